//! Every example, table and figure input of the five sources that the
//! repository holds runs under the **default** limits (issue 32: limits
//! are chosen so that no legitimate use meets them). No `--max-*` flag is
//! passed anywhere here; each command must succeed (exit 0) with JSON out.
//! The README's and docs' shell examples run with the defaults too
//! (`cli/tests/readme.rs`).

use super::common::{cli, read_to_string};

/// The source examples kept as fixtures, with the commands the sources
/// apply to them (source 000: standard forms and reparameterizations of
/// Examples 1–3; Zhang–Chen–Feng §4.1 and §4.2: the conversions).
const SOURCE_RUNS: &[&[&str]] = &[
    &["standardize", "tests/fixtures/yang_yong_example1.json"],
    &["standardize", "tests/fixtures/yang_yong_example2.json"],
    &[
        "standardize",
        "tests/fixtures/yang_yong_example2.json",
        "--compact",
    ],
    &["standardize", "tests/fixtures/yang_yong_example3.json"],
    &[
        "reparam",
        "tests/fixtures/yang_yong_example1.json",
        "--mobius",
        "3/5,7/10",
    ],
    &[
        "reparam",
        "tests/fixtures/yang_yong_example3.json",
        "--mobius",
        "1/3,1/2",
    ],
    &[
        "reparam",
        "tests/fixtures/yang_yong_example2.json",
        "--quadratic",
        "0.5391,0.4663,0.5782,0.5782",
    ],
    &[
        "coincide",
        "tests/fixtures/yang_yong_example1.json",
        "tests/fixtures/yang_yong_example1_standard.json",
    ],
    &[
        "coincide",
        "tests/fixtures/yang_yong_example1.json",
        "tests/fixtures/yang_yong_example3.json",
    ],
    &[
        "convert",
        "tests/fixtures/zcf_4_1_rect.json",
        "--to",
        "tri",
        "--normalize",
    ],
    &[
        "convert",
        "tests/fixtures/zcf_4_2_tri.json",
        "--to",
        "rect",
        "--split",
        "0.3,0.5,0.3,0.5,0.5,0.5",
        "--normalize",
    ],
    &[
        "arc",
        "--cos-half",
        "3/5",
        "--lambda",
        "0",
        "--points",
        "1,0;1,4/3;-7/25,24/25",
    ],
    &["convert", "tests/fixtures/bowl.json", "--to", "rational"],
    &[
        "intersect",
        "docs/examples/curve.json",
        "docs/examples/line.json",
    ],
    &["intersect", "docs/examples/loop.json"],
];

fn assert_runs(args: &[&str]) {
    let (code, out, err) = cli(args);
    assert_eq!(code, 0, "{args:?} under the default limits: {err}");
    assert!(
        serde_json::from_str::<serde_json::Value>(&out).is_ok(),
        "{args:?} wrote no JSON: {out:.200}"
    );
}

#[test]
fn source_examples_run_under_the_default_limits() {
    for args in SOURCE_RUNS {
        assert_runs(args);
    }
}

/// Every derived input of the figure gallery (`{"run": [...]}` in
/// docs/figures/gallery.json: the sources' figures, arcs and trigonometric
/// patches included) runs under the default limits.
#[test]
fn gallery_inputs_run_under_the_default_limits() {
    let text = read_to_string("docs/figures/gallery.json").expect("the gallery list");
    let gallery: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let mut runs = 0;
    for entry in gallery.as_array().expect("an array") {
        for input in entry["inputs"].as_array().expect("inputs") {
            if let Some(run) = input.get("run").and_then(|r| r.as_array()) {
                let args: Vec<&str> = run.iter().map(|a| a.as_str().expect("text")).collect();
                assert_runs(&args);
                runs += 1;
            }
        }
    }
    assert!(runs >= 10, "the gallery lost its derived inputs ({runs})");
}

/// Every string a command writes in the numbers' alphabet is read back by
/// the reader under the default limits (issue 32): the standard forms of
/// Examples 1 and 2 (radicals in cubic fields), an exact curvature (κ =
/// √κ²), and a point whose coordinate is `2^(1/128)` (once written
/// `root(2, 128)`, which the reader refused).
#[test]
fn what_commands_write_the_reader_takes() {
    let seventh = (0..7).fold("2".to_string(), |acc, _| format!("sqrt({acc})"));
    let line =
        format!(r#"{{"kind": "curve", "points": [["{seventh}", 0], [1, 1]], "weights": [1, 1]}}"#);
    let dir = std::env::temp_dir().join(format!("eb-sources-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let root_curve = dir.join("root128.json");
    std::fs::write(&root_curve, line).unwrap();
    let root_curve = root_curve.to_str().unwrap().to_string();
    let runs: Vec<Vec<&str>> = vec![
        vec!["standardize", "tests/fixtures/yang_yong_example1.json"],
        vec!["standardize", "tests/fixtures/yang_yong_example2.json"],
        vec!["curvature", "docs/examples/curve.json", "--at", "1/3"],
        vec!["eval", &root_curve, "--at", "0"],
    ];
    let mut numbers = 0;
    for args in &runs {
        let (code, out, err) = cli(args);
        assert_eq!(code, 0, "{args:?}: {err}");
        numbers += crate::common::written_numbers_read_back(&out, args);
    }
    let (_, out, _) = cli(&["eval", &root_curve, "--at", "0"]);
    assert!(out.contains("root(sqrt(2), 64)"), "{out}");
    assert!(numbers > 50, "only {numbers} numbers checked");
    std::fs::remove_dir_all(&dir).ok();
}
