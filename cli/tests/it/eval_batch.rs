//! `eval --grid N`, repeated `--at` and `--jsonl` (issue 12): every point
//! equals de Casteljau (`eval_hom(..).project()`, a second method) on the
//! library side; the grids have the documented points; limits and errors.

use crate::common::{cli, cli_json};
use exact_bezier::algebra::parse_rational;
use exact_bezier::io::read_patches;
use exact_bezier::{ratio, Patch};
use num_rational::BigRational;
use serde_json::Value;

const EX1: &str = "tests/fixtures/yang_yong_example1.json";
const TRI: &str = "tests/fixtures/zcf_4_2_tri.json";

fn patch(path: &str) -> Patch<BigRational> {
    let text = crate::common::read_to_string(path).unwrap();
    read_patches(&text).unwrap().swap_remove(0)
}

fn exact(v: &Value) -> Vec<BigRational> {
    let text = |x: &Value| match x {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    };
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| parse_rational(&text(x)).unwrap())
        .collect()
}

/// The point at `at` by de Casteljau.
fn de_casteljau(p: &Patch<BigRational>, at: &[BigRational]) -> Vec<BigRational> {
    match p {
        Patch::Curve(c) => c.eval_hom(&at[0]).project().unwrap(),
        Patch::Rect(r) => r.eval_hom(&at[0], &at[1]).project().unwrap(),
        Patch::Tri(t) => t.eval_hom(&at[0], &at[1]).project().unwrap(),
    }
}

fn jsonl(args: &[&str]) -> Vec<Value> {
    let (code, out, err) = cli(args);
    assert_eq!(code, 0, "{err}");
    out.lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

#[test]
fn rect_grid_lines_are_de_casteljau_points() {
    let p = patch(EX1);
    let lines = jsonl(&["eval", EX1, "--grid", "4", "--jsonl"]);
    assert_eq!(lines.len(), 25);
    for (k, line) in lines.iter().enumerate() {
        let at = exact(&line["at"]);
        assert_eq!(at, vec![ratio(k as i64 / 5, 4), ratio(k as i64 % 5, 4)]);
        assert_eq!(exact(&line["point"]), de_casteljau(&p, &at));
    }
}

#[test]
fn tri_grid_covers_the_triangle_once() {
    let p = patch(TRI);
    let lines = jsonl(&["eval", TRI, "--grid", "3", "--jsonl"]);
    assert_eq!(lines.len(), 10);
    let mut seen = std::collections::BTreeSet::new();
    for line in &lines {
        let at = exact(&line["at"]);
        assert!(at[0].clone() + &at[1] <= ratio(1, 1));
        assert!(seen.insert((at[0].clone(), at[1].clone())));
        assert_eq!(exact(&line["point"]), de_casteljau(&p, &at));
    }
}

#[test]
fn repeated_at_matches_single_at_and_f64_is_close() {
    let (code, many) = cli_json(&["eval", EX1, "--at", "1/3,1/2", "--at", "123/457,0.99"]);
    assert_eq!(code, 0);
    let points = many["points"].as_array().unwrap();
    assert_eq!(points.len(), 2);
    for (point, at) in points.iter().zip(["1/3,1/2", "123/457,0.99"]) {
        let (_, one) = cli_json(&["eval", EX1, "--at", at]);
        assert_eq!(point["point"], one["point"]);
    }
    let (_, float) = cli_json(&["eval", EX1, "--grid", "3", "--scalar", "f64"]);
    let (_, exact_grid) = cli_json(&["eval", EX1, "--grid", "3"]);
    for (f, e) in float["points"]
        .as_array()
        .unwrap()
        .iter()
        .zip(exact_grid["points"].as_array().unwrap())
    {
        for (x, y) in f["point"]
            .as_array()
            .unwrap()
            .iter()
            .zip(exact(&e["point"]))
        {
            let y = exact_bezier::Ordered::to_f64(&y);
            assert!((x.as_f64().unwrap() - y).abs() <= 1e-12 * (1.0 + y.abs()));
        }
    }
}

#[test]
fn several_patches_are_tagged_in_jsonl() {
    let lines = jsonl(&[
        "eval",
        "tests/fixtures/zcf_4_2_rects.json",
        "--grid",
        "1",
        "--jsonl",
    ]);
    let tags: Vec<u64> = lines.iter().map(|l| l["patch"].as_u64().unwrap()).collect();
    assert_eq!(tags, vec![0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2]);
}

#[test]
fn bad_grids_and_points_are_one_line_errors() {
    for (args, needle) in [
        (vec!["eval", EX1, "--grid", "0"], "N ≥ 1"),
        (vec!["eval", EX1, "--grid", "2000"], "--jsonl"),
        (
            vec!["eval", EX1, "--at", "1/2,1/2", "--at", "1/2"],
            "takes 2 parameter",
        ),
        (
            vec!["eval", EX1, "--at", "1/2,1/2", "--at", "2,0"],
            "outside the domain",
        ),
        (
            vec!["eval", "tests/fixtures/bowl.json", "--grid", "2"],
            "one --at at a time",
        ),
        (
            vec!["eval", EX1, "--grid", "2", "--at", "0,0"],
            "cannot be used with",
        ),
    ] {
        let (code, out, err) = cli(&args);
        assert_eq!(code, 2, "{args:?}: {out}");
        assert!(err.contains(needle), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
}
