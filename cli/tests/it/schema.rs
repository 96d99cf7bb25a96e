//! Every fixture and the output of every command validate against the JSON
//! Schema of the format (docs/exact-bezier.schema.json, described in
//! docs/FORMAT.md), and the schema rejects what the reader rejects.

use crate::common::cli;
use boon::{Compiler, SchemaIndex, Schemas};
use serde_json::Value;

const SCHEMA: &str = "file:///exact-bezier.schema.json";

/// The schema compiled at the definition `def` (e.g. `curve`, `evalOutput`).
fn schema(def: &str) -> (Schemas, SchemaIndex) {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/..",
        "/docs/exact-bezier.schema.json"
    );
    let text = crate::common::read_to_string(path).expect("the schema file exists");
    let value: Value = serde_json::from_str(&text).expect("the schema is JSON");
    let mut compiler = Compiler::new();
    compiler.add_resource(SCHEMA, value).expect("a resource");
    let mut schemas = Schemas::new();
    let index = compiler
        .compile(&format!("{SCHEMA}#/$defs/{def}"), &mut schemas)
        .expect("the schema compiles");
    (schemas, index)
}

fn assert_valid(def: &str, what: &str, instance: &Value) {
    let (schemas, index) = schema(def);
    if let Err(e) = schemas.validate(instance, index) {
        panic!("{what} does not match #/$defs/{def}: {e}\n{instance}");
    }
}

fn assert_invalid(def: &str, what: &str, instance: &Value) {
    let (schemas, index) = schema(def);
    assert!(
        schemas.validate(instance, index).is_err(),
        "{what} should not match #/$defs/{def}: {instance}"
    );
}

/// The JSON printed by `exact-bezier args…` (exit code 0).
fn output(args: &[&str]) -> Value {
    let (code, out, err) = cli(args);
    assert_eq!(code, 0, "exact-bezier {args:?} failed: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{args:?} printed non-JSON ({e}): {out}"))
}

fn fixtures() -> Vec<std::path::PathBuf> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/..", "/tests/fixtures");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("the fixtures folder exists")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_fixture_is_valid_input() {
    let files = fixtures();
    assert!(files.len() >= 8, "fixtures found: {files:?}");
    for f in files {
        let text = crate::common::read_to_string(&f).expect("readable");
        let v: Value = serde_json::from_str(&text).expect("JSON");
        assert_valid("input", &f.display().to_string(), &v);
    }
}

#[test]
fn the_schema_rejects_what_the_reader_rejects() {
    let bad = [
        r#"{"kind": "curve", "points": [[0], [1]], "weights": [1, 1], "colour": "red"}"#,
        r#"{"kind": "curve", "points": [[0], [1]], "weights": [1, 0]}"#,
        r#"{"kind": "curve", "points": [[0], ["NaN"]]}"#,
        r#"{"kind": "curve", "points": [[0], ["1/3x"]]}"#,
        r#"{"kind": "surface", "points": [[0]]}"#,
        r#"{"kind": "curve", "points": []}"#,
    ];
    for text in bad {
        let v: Value = serde_json::from_str(text).expect("JSON");
        assert_invalid("input", text, &v);
        assert!(
            exact_bezier::io::read_patches(text).is_err(),
            "the reader accepts {text}"
        );
    }
}

#[test]
fn command_outputs_match_the_schema() {
    let ex1 = "tests/fixtures/yang_yong_example1.json";
    let ex3 = "tests/fixtures/yang_yong_example3.json";
    let tri = "tests/fixtures/zcf_4_2_tri.json";
    assert_valid(
        "evalOutput",
        "eval rect",
        &output(&["eval", ex1, "--at", "1/3,1/2"]),
    );
    assert_valid(
        "evalOutput",
        "eval rect f64",
        &output(&["eval", ex1, "--at", "0.25,0.5", "--scalar", "f64"]),
    );
    assert_valid(
        "evalOutput",
        "eval tri",
        &output(&["eval", tri, "--at", "1/4,1/4"]),
    );
    assert_valid(
        "evalPointsOutput",
        "eval --grid",
        &output(&["eval", tri, "--grid", "2"]),
    );
    assert_valid(
        "evalPointsOutput",
        "eval repeated --at f64",
        &output(&[
            "eval", ex1, "--at", "0,0", "--at", "1/3,1/2", "--scalar", "f64",
        ]),
    );
    let (_, lines, _) = cli(&[
        "eval",
        "tests/fixtures/zcf_4_2_rects.json",
        "--grid",
        "1",
        "--jsonl",
    ]);
    for line in lines.lines() {
        assert_valid(
            "evalPoint",
            "eval --jsonl line",
            &serde_json::from_str(line).unwrap(),
        );
    }
    assert_valid(
        "patch",
        "reparam",
        &output(&["reparam", ex1, "--mobius", "3/5,7/10"]),
    );
    assert_valid(
        "patch",
        "elevate",
        &output(&["elevate", ex1, "--by", "1,2"]),
    );
    assert_valid(
        "patches",
        "convert",
        &output(&["convert", ex1, "--to", "tri"]),
    );
    assert_valid(
        "patches",
        "convert back",
        &output(&["convert", tri, "--to", "rect"]),
    );
    assert_valid(
        "standardizeOutput",
        "standardize",
        &output(&["standardize", ex3]),
    );
    assert_valid(
        "standardizeOutput",
        "standardize f64",
        &output(&["standardize", ex1]),
    );
    assert_valid(
        "coincideOutput",
        "coincide",
        &output(&["coincide", ex1, ex3]),
    );
    let (curve, line, looped) = (
        "docs/examples/curve.json",
        "docs/examples/line.json",
        "docs/examples/loop.json",
    );
    for args in [
        vec!["intersect", curve, line],
        vec!["intersect", curve, curve, "--filtered"],
        vec!["intersect", curve, curve],
        vec!["intersect", looped],
    ] {
        assert_valid("intersectOutput", &args.join(" "), &output(&args));
    }
    assert_valid(
        "intersectCertifiedOutput",
        "intersect --filtered",
        &output(&["intersect", curve, line, "--filtered"]),
    );
    assert_valid(
        "intersectF64Output",
        "intersect f64",
        &output(&["intersect", curve, line, "--scalar", "f64"]),
    );
    let teapot = "tests/fixtures/teapot.json";
    assert_valid(
        "auditSummary",
        "audit",
        &output(&["audit", teapot, "--summary"]),
    );
    assert_valid(
        "brepAuditSummary",
        "audit STEP B-rep",
        &output(&["audit", "tests/fixtures/step/sg1-c5-214.stp", "--summary"]),
    );
    assert_valid(
        "patches",
        "convert --to bezier",
        &output(&["convert", "tests/fixtures/cylinder.json", "--to", "bezier"]),
    );
    let curves = "docs/examples/three_curves.jsonl";
    for (cmd, def) in [("dedup", "dedupLine"), ("key", "keyLine")] {
        let (code, out, err) = cli(&[cmd, curves]);
        assert_eq!(code, 0, "{cmd}: {err}");
        for line in out.lines() {
            let v: Value = serde_json::from_str(line).expect("a JSON line");
            assert_valid(def, cmd, &v);
        }
    }
}

/// Outputs on inputs with algebraic numbers (`"sqrt(6)/6"`) match too.
#[test]
fn algebraic_outputs_match_the_schema() {
    let ex1 = "tests/fixtures/yang_yong_example1.json";
    let std1 = "tests/fixtures/yang_yong_example1_standard.json";
    let quarter = "tests/fixtures/quarter_circle.json";
    for (def, args) in [
        ("coincideOutput", vec!["coincide", ex1, std1]),
        ("coincideOutput", vec!["coincide", std1, ex1, "--filtered"]),
        ("patch", vec!["reparam", std1, "--mobius", "1/3,sqrt(2)/2"]),
        ("patch", vec!["elevate", std1, "--by", "1,0"]),
        ("patches", vec!["convert", std1, "--to", "tri"]),
        ("evalOutput", vec!["eval", quarter, "--at", "1/3"]),
        ("derivOutput", vec!["deriv", quarter, "--at", "1/3"]),
    ] {
        assert_valid(def, &args.join(" "), &output(&args));
    }
    let v = output(&["curvature", quarter, "--at", "1/3"]);
    assert_valid("number", "curvature", &v["curvature"]);
    assert_valid("number", "curvature_squared", &v["curvature_squared"]);
    for (cmd, def) in [("dedup", "dedupLine"), ("key", "keyLine")] {
        let (code, out, err) = cli(&[cmd, std1]);
        assert_eq!(code, 0, "{cmd}: {err}");
        for line in out.lines() {
            assert_valid(def, cmd, &serde_json::from_str(line).expect("a JSON line"));
        }
    }
}

#[test]
fn an_assemblys_occurrences_match_the_schema() {
    let out = output(&[
        "convert",
        "tests/fixtures/step/as1-oc-214.stp",
        "--to",
        "bezier",
    ]);
    assert_valid("brep", "convert an assembly --to bezier", &out);
    let occurrences = out["occurrences"].as_array().unwrap();
    assert_eq!(occurrences.len(), 18);
    assert_eq!(out["summary"]["occurrences"], 18);
    // Every placement is rigid and in the root's context: the linear
    // part's rows are exact unit vectors here (the file's directions are).
    for o in occurrences {
        assert_eq!(o["root"], "#10");
        assert_eq!(o["context"], "#31");
        for row in o["linear"].as_array().unwrap() {
            let norm: i64 = row
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_i64().unwrap().pow(2))
                .sum();
            assert_eq!(norm, 1, "{o}");
        }
    }
}

#[test]
fn the_step_brep_output_matches_the_schema_and_reads_back() {
    let stp = "tests/fixtures/step/nist_ftc_06_asme1_rd.stp";
    assert_valid(
        "brep",
        "convert STEP --to bezier",
        &output(&["convert", stp, "--to", "bezier"]),
    );
    let (code, out, err) = cli(&["convert", stp, "--to", "bezier", "--jsonl"]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).expect("one JSON value a line"))
        .collect();
    // 144 faces, 310 edges and 227 vertices (counted in the text), then the model.
    assert_eq!(lines.len(), 144 + 310 + 227 + 1);
    for line in &lines[..144] {
        assert_valid("brepFace", "a face line", line);
    }
    assert_valid("brepEdge", "an edge line", &lines[144]);
    assert_valid("brepVertex", "a vertex line", &lines[454]);
    assert_valid("brepModel", "the model line", &lines[681]);
    // A piece with its origin is a patch every reader takes.
    let piece = r##"[{"kind":"curve","points":[[0,0],[1,1]],"origin":{"entity":"#4","faces":["#5"],"span_u":[0,"1/2"]}}]"##;
    assert_valid("input", "a piece", &serde_json::from_str(piece).unwrap());
    assert!(exact_bezier::io::read_patches(piece).is_ok());
}
