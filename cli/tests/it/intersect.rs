//! The `intersect` command on the documented examples, against values
//! derived by hand (below), and its typed errors.
//!
//! `docs/examples/curve.json` is the rational cubic with points (0,0),
//! (1,2), (3,2), (4,0) and weights 1, 1/3, 1/3, 1. Its weight sum is
//! W = 1 − 2s + 2s² and y(s) = 2s(1 − s)/W, so y = 1/2 at 6s² − 6s + 1 = 0,
//! s = 1/2 ∓ √3/6. There s² = s − 1/6, W = 2/3 and the x numerator
//! s + s² + 2s³ reduces to 11s/3 − 1/2, so x = 11s/2 − 3/4 = 2 ∓ 11√3/12;
//! on the line from (0, 1/2) to (4, 1/2), t = x/4 = 1/2 ∓ 11√3/48.
//!
//! `docs/examples/loop.json` is the cubic (0,0), (3,3), (−1,3), (2,0):
//! x = 9s − 21s² + 14s³, y = 9s(1 − s). Equal y forces t = 1 − s; with
//! u = s − 1/2 the odd part of x is −3u/2 + 14u³, zero at u² = 3/28, so
//! s = 1/2 − √21/14, t = 1/2 + √21/14, and the point is
//! (x(1/2), 9(1/4 − 3/28)) = (1, 9/7).

use crate::common::{cli, cli_json};
use serde_json::{json, Value};

const CURVE: &str = "docs/examples/curve.json";
const LINE: &str = "docs/examples/line.json";
const LOOP: &str = "docs/examples/loop.json";

fn exact_points(v: &Value) -> Vec<(Value, Value, Value)> {
    v["intersections"]
        .as_array()
        .expect("an intersections array")
        .iter()
        .map(|p| (p["s"].clone(), p["t"].clone(), p["point"].clone()))
        .collect()
}

#[test]
fn rational_cubic_meets_a_line_at_radicals() {
    let (code, v) = cli_json(&["intersect", CURVE, LINE]);
    assert_eq!(code, 0);
    assert_eq!(
        exact_points(&v),
        vec![
            (
                json!("1/2 - sqrt(3)/6"),
                json!("1/2 - 11*sqrt(3)/48"),
                json!(["2 - 11*sqrt(3)/12", "1/2"])
            ),
            (
                json!("1/2 + sqrt(3)/6"),
                json!("1/2 + 11*sqrt(3)/48"),
                json!(["2 + 11*sqrt(3)/12", "1/2"])
            ),
        ]
    );
    for p in v["intersections"].as_array().unwrap() {
        assert_eq!(p["contact"], "transversal");
        assert_eq!(p["multiplicity"], 1);
    }
    assert_eq!(v["overlaps"], json!([]));
}

#[test]
fn filtered_answer_certifies_crossings_or_is_the_exact_one() {
    let (_, exact) = cli_json(&["intersect", CURVE, LINE]);
    let (code, filtered) = cli_json(&["intersect", CURVE, LINE, "--filtered"]);
    assert_eq!(code, 0);
    // Two transversal crossings in the plane: interval arithmetic decides,
    // each box holding one exact crossing (s = 1/2 ∓ √3/6, t = 1/2 ∓ 11√3/48).
    assert_eq!(filtered["decided_by"], "intervals");
    let boxes = filtered["crossings"].as_array().unwrap();
    let r3 = 3f64.sqrt();
    let want = [
        (0.5 - r3 / 6.0, 0.5 - 11.0 * r3 / 48.0),
        (0.5 + r3 / 6.0, 0.5 + 11.0 * r3 / 48.0),
    ];
    assert_eq!(boxes.len(), want.len());
    assert_eq!(exact["intersections"].as_array().unwrap().len(), want.len());
    let holds = |b: &Value, x: f64| {
        let (lo, hi) = (b[0].as_f64().unwrap(), b[1].as_f64().unwrap());
        lo <= x + 1e-15 && x - 1e-15 <= hi && hi - lo < 1e-12
    };
    for (s, t) in want {
        let n = boxes
            .iter()
            .filter(|b| holds(&b["s"], s) && holds(&b["t"], t))
            .count();
        assert_eq!(n, 1, "one certified box holds ({s}, {t})");
    }
    // An overlap is left to the exact path: the exact answer, plus who decided.
    let (_, exact) = cli_json(&["intersect", CURVE, CURVE]);
    let (_, mut filtered) = cli_json(&["intersect", CURVE, CURVE, "--filtered"]);
    assert_eq!(filtered["decided_by"], "exact");
    filtered.as_object_mut().unwrap().remove("decided_by");
    assert_eq!(filtered, exact);
}

#[test]
fn f64_answer_lies_within_its_tolerance_of_the_exact_one() {
    let (code, v) = cli_json(&[
        "intersect",
        CURVE,
        LINE,
        "--scalar",
        "f64",
        "--tol",
        "1e-10",
    ]);
    assert_eq!(code, 0);
    assert_eq!(v["tolerance"], 1e-10);
    let mut s: Vec<f64> = v["intersections"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["s"].as_f64().unwrap())
        .collect();
    s.sort_by(f64::total_cmp);
    let r3 = 3f64.sqrt() / 6.0;
    assert_eq!(s.len(), 2);
    assert!((s[0] - (0.5 - r3)).abs() < 1e-9 && (s[1] - (0.5 + r3)).abs() < 1e-9);
}

#[test]
fn the_loop_crosses_itself_once() {
    let (code, v) = cli_json(&["intersect", LOOP]);
    assert_eq!(code, 0);
    assert_eq!(
        exact_points(&v),
        vec![(
            json!("1/2 - sqrt(21)/14"),
            json!("1/2 + sqrt(21)/14"),
            json!([1, "9/7"])
        )]
    );
}

#[test]
fn a_curve_with_itself_is_one_identity_overlap() {
    let (code, v) = cli_json(&["intersect", CURVE, CURVE]);
    assert_eq!(code, 0);
    assert_eq!(v["intersections"], json!([]));
    let o = &v["overlaps"][0];
    assert_eq!((&o["s"], &o["t"]), (&json!([0, 1]), &json!([0, 1])));
    assert_eq!(o["mobius"], json!([1, 0, 0, 1]));
}

#[test]
fn misuse_is_a_typed_error() {
    for (args, says) in [
        (
            vec![LOOP, "--scalar", "f64"],
            "self-intersections are exact only",
        ),
        (
            vec![CURVE, LINE, "--tol", "1e-3"],
            "--tol applies to --scalar f64",
        ),
        (vec![LOOP, "--filtered"], "needs a second curve"),
        (
            vec!["docs/examples/bilinear.json"],
            "intersect takes a curve",
        ),
        (vec![CURVE, "no/such/file.json"], "no/such/file.json"),
    ] {
        let mut all = vec!["intersect"];
        all.extend(args);
        let (code, out, err) = cli(&all);
        assert_eq!(code, 2, "{all:?}: {err}");
        assert!(out.is_empty() && err.contains(says), "{all:?}: {err}");
    }
}

/// Two degree-12 curves: the exact path is over the default work budget,
/// but `--filtered` charges only its bounded interval stage first and
/// decides them there. Checked against the independent `f64` search
/// (subdivision and Newton): as many crossings, each `f64` root inside
/// exactly one certified box (widened by the `f64` search's own 10⁻⁹).
#[test]
fn filtered_decides_high_degree_pairs_within_the_default_budget() {
    let (a, b) = (
        "tests/fixtures/degree12_a.json",
        "tests/fixtures/degree12_b.json",
    );
    let (code, _, err) = cli(&["intersect", a, b]);
    assert_eq!(code, 2, "the exact path should be over the budget");
    assert!(err.contains("--max-work"), "{err}");
    let (code, v) = cli_json(&["intersect", a, b, "--filtered"]);
    assert_eq!(code, 0, "{v}");
    assert_eq!(v["decided_by"], "intervals");
    let boxes = v["crossings"].as_array().unwrap();
    let (code, f) = cli_json(&["intersect", a, b, "--scalar", "f64"]);
    assert_eq!(code, 0, "{f}");
    let roots = f["intersections"].as_array().unwrap();
    assert_eq!(boxes.len(), roots.len());
    assert!(boxes.len() >= 2, "the fixture crosses several times");
    let within = |r: &Value, iv: &Value| {
        let (x, lo, hi) = (
            r.as_f64().unwrap(),
            iv[0].as_f64().unwrap(),
            iv[1].as_f64().unwrap(),
        );
        lo - 1e-9 <= x && x <= hi + 1e-9
    };
    for r in roots {
        let hits = boxes
            .iter()
            .filter(|bx| within(&r["s"], &bx["s"]) && within(&r["t"], &bx["t"]))
            .count();
        assert_eq!(hits, 1, "root {r} in {hits} boxes");
    }
}

/// The `f64` search reports each crossing once: on two degree-20 curves two
/// clusters of close pieces that do not touch converged by Newton to one
/// root and came out twice; now its roots are pairwise distinct and as many
/// as the certified boxes of `--filtered`.
#[test]
fn the_f64_search_reports_each_crossing_once() {
    let (a, b) = (
        "tests/fixtures/degree20_a.json",
        "tests/fixtures/degree20_b.json",
    );
    let (_, v) = cli_json(&["intersect", a, b, "--filtered"]);
    let (_, f) = cli_json(&["intersect", a, b, "--scalar", "f64"]);
    let roots = f["intersections"].as_array().unwrap();
    assert_eq!(roots.len(), v["crossings"].as_array().unwrap().len());
    let st = |r: &Value| (r["s"].as_f64().unwrap(), r["t"].as_f64().unwrap());
    for (k, x) in roots.iter().enumerate() {
        for y in &roots[..k] {
            let ((s1, t1), (s2, t2)) = (st(x), st(y));
            assert!((s1 - s2).abs() + (t1 - t2).abs() > 1e-6, "{x} repeats {y}");
        }
    }
}
