//! Our side of the intersection peer comparison `benches/peers/intersect`
//! (issue 18): reads the curve pairs that `benches/peers/peer_intersect.py`
//! generated, intersects each pair exactly, through the filter and in
//! `f64`, and prints one JSON object per pair: the exact answers as `f64`
//! pairs `(s, t)` (for the agreement check against the peer), the `f64`
//! path's answers (tolerance `1e-12`, checked against the exact ones) and the best
//! time of each path over `--repeat` runs, in microseconds.
//!
//! ```text
//! cargo bench --bench peer_intersect -- PAIRS.json [--repeat 5]
//! ```
//!
//! Each pair is `{"a": curve, "b": curve}` in our JSON format.

use exact_bezier::algebra::{Interval, RealAlgebraic};
use exact_bezier::intersect::{intersect, Filter, Found, Intersections, Options};
use exact_bezier::io::read_patches;
use exact_bezier::{Ordered, Patch, RationalCurve, Tolerance};
use num_rational::BigRational;
use serde_json::{json, Value};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    // `cargo bench` appends `--bench`; with no pairs file there is nothing to time.
    let Some(path) = args.get(1).filter(|a| !a.starts_with("--")) else {
        eprintln!("usage: cargo bench --bench peer_intersect -- PAIRS.json [--repeat N]");
        return;
    };
    let repeat = match args.iter().position(|a| a == "--repeat") {
        Some(i) => args[i + 1].parse().expect("--repeat takes a count"),
        None => 5,
    };
    let text = std::fs::read_to_string(path).expect("readable pairs file");
    let pairs: Vec<Value> = serde_json::from_str(&text).expect("a JSON array of pairs");
    let out: Vec<Value> = pairs
        .iter()
        .map(|p| run_pair(&curve(&p["a"]), &curve(&p["b"]), repeat))
        .collect();
    println!("{}", Value::Array(out));
}

fn curve(v: &Value) -> RationalCurve<BigRational> {
    match read_patches(&v.to_string())
        .expect("a valid curve")
        .remove(0)
    {
        Patch::Curve(c) => c,
        _ => panic!("the pairs hold curves"),
    }
}

/// Microseconds of the best of `repeat` runs of `f`.
fn best_us(repeat: usize, mut f: impl FnMut()) -> f64 {
    (0..repeat.max(1))
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64() * 1e6
        })
        .fold(f64::INFINITY, f64::min)
}

/// Do the certified boxes hold the exact crossings, one each (or is the
/// filtered answer the exact one)?
fn filtered_agrees(exact: &Intersections, filtered: &Found) -> bool {
    let Found::Certified(boxes) = filtered else {
        return true;
    };
    let inside = |x: &RealAlgebraic, i: &Interval| {
        let (lo, hi) = x.enclosure(64);
        let (Some(a), Some(b)) = (BigRational::from_float(i.lo), BigRational::from_float(i.hi))
        else {
            return false;
        };
        a <= lo && hi <= b
    };
    exact.overlaps.is_empty()
        && boxes.len() == exact.points.len()
        && exact.points.iter().all(|p| {
            boxes
                .iter()
                .filter(|k| inside(&p.s, &k.s) && inside(&p.t, &k.t))
                .count()
                == 1
        })
}

fn run_pair(
    a: &RationalCurve<BigRational>,
    b: &RationalCurve<BigRational>,
    repeat: usize,
) -> Value {
    let exact = || intersect(a, Some(b), Options::default()).map(|x| x.exact().expect("exact"));
    let filtered = || {
        let options = Options {
            filter: Filter::First,
            ..Options::default()
        };
        intersect(a, Some(b), options).expect("the filtered path runs")
    };
    let x = match exact() {
        Ok(x) => x,
        Err(e) => return json!({"error": e.to_string()}),
    };
    let (a64, b64) = (a.map(Ordered::to_f64), b.map(Ordered::to_f64));
    let found = filtered();
    let decided_by = format!("{:?}", found.decided_by().expect("First decides")).to_lowercase();
    let t_filtered = best_us(repeat, || {
        filtered();
    });
    let t_exact = best_us(repeat, || {
        exact().expect("the exact path runs");
    });
    let approx = Options {
        tol: Tolerance(1e-12),
        ..Options::default()
    };
    let approx_points = intersect(&a64, Some(&b64), approx).expect("the f64 path runs");
    let t_f64 = best_us(repeat, || {
        intersect(&a64, Some(&b64), approx).expect("the f64 path runs");
    });
    json!({
        "points": x.points.iter().map(|p| [p.s.to_f64(), p.t.to_f64()]).collect::<Vec<_>>(),
        "overlaps": x.overlaps.len(),
        "f64_points": approx_points.iter().map(|p| [p.s, p.t]).collect::<Vec<_>>(),
        "f64_overlaps": approx_points.iter().filter(|p| p.overlap.is_some()).count(),
        "decided_by": decided_by,
        "filtered_agrees": filtered_agrees(&x, &found),
        "us": {"exact": t_exact, "filtered": t_filtered, "f64": t_f64},
    })
}
