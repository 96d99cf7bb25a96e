//! Our side of the peer benchmark `benches/peers/run` (issue 12): reads the
//! cases that `benches/peers/peer_eval.py` generated, evaluates each one
//! with the batch API ([`Evaluator`]) and prints one JSON object of
//! nanoseconds per point (the best of `--repeat` passes).
//!
//! ```text
//! cargo bench --bench peer_eval -- CASES.json [--repeat 5]
//! ```
//!
//! Each case is `{"name", "patch" (our JSON format), "params": [...],
//! "exact": bool}`; `params` holds one value per point for a curve and
//! two for a patch, read exactly from their text. The `f64` cases also run
//! a hand-written fixed-size kernel of the same Horner–Bernstein scheme
//! (`<name>_reference`) where one is written below: the yardstick of
//! "within 2× of a fixed-size kernel".

use exact_bezier::algebra::parse_rational;
use exact_bezier::eval::Evaluator;
use exact_bezier::io::read_patches;
use exact_bezier::{Field, Ordered, Patch};
use num_rational::BigRational;
use serde_json::{Map, Value};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    // `cargo bench` appends `--bench`; with no cases file there is nothing to time.
    let Some(path) = args.get(1).filter(|a| !a.starts_with("--")) else {
        eprintln!("usage: cargo bench --bench peer_eval -- CASES.json [--repeat N]");
        return;
    };
    let repeat = match args.iter().position(|a| a == "--repeat") {
        Some(i) => args[i + 1].parse().expect("--repeat takes a count"),
        None => 5,
    };
    let text = std::fs::read_to_string(path).expect("readable cases file");
    let cases: Vec<Value> = serde_json::from_str(&text).expect("a JSON array of cases");
    let mut result = Map::new();
    for case in &cases {
        let name = case["name"].as_str().expect("a case name");
        let patch = read_patches(&case["patch"].to_string()).expect("a valid patch");
        let params: Vec<BigRational> = case["params"]
            .as_array()
            .expect("params")
            .iter()
            .map(|v| parse_rational(&number_text(v)).expect("an exact parameter"))
            .collect();
        let exact = case["exact"].as_bool().unwrap_or(false);
        let ns = if exact {
            time_batch(&patch[0], &params, repeat)
        } else {
            let p64 = patch[0].map(Ordered::to_f64);
            let f: Vec<f64> = params.iter().map(Ordered::to_f64).collect();
            if let Some(ns) = reference(name, &p64, &f, repeat) {
                result.insert(format!("{name}_reference"), ns.into());
            }
            time_batch(&p64, &f, repeat)
        };
        result.insert(name.to_string(), ns.into());
    }
    println!("{}", Value::Object(result));
}

/// The text of a JSON number or string, for the exact reader.
fn number_text(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// An evaluator of any Bézier patch.
fn evaluator<T: Field>(p: &Patch<T>) -> Evaluator<T> {
    match p {
        Patch::Curve(c) => Evaluator::curve(c),
        Patch::Rect(r) => Evaluator::rect(r),
        Patch::Tri(t) => Evaluator::tri(t),
    }
}

/// Nanoseconds per point of the best of `repeat` batch evaluations.
fn time_batch<T: Field>(p: &Patch<T>, params: &[T], repeat: usize) -> f64 {
    let mut ev = evaluator(p);
    let per_point = if matches!(p, Patch::Curve(_)) { 1 } else { 2 };
    let points = params.len() / per_point;
    let mut out = vec![T::zero(); points * ev.net().dim()];
    best_of(repeat, points, || {
        ev.eval_batch(params, &mut out).expect("finite points")
    })
}

/// Nanoseconds per point of the fastest of `repeat` runs of `f`.
fn best_of(repeat: usize, points: usize, mut f: impl FnMut()) -> f64 {
    (0..repeat)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_nanos() as f64 / points as f64
        })
        .fold(f64::INFINITY, f64::min)
}

/// The fixed-size reference kernels: the cubic planar curve and the
/// rational bicubic in space.
fn reference(name: &str, p: &Patch<f64>, params: &[f64], repeat: usize) -> Option<f64> {
    let net: Vec<f64> = match p {
        Patch::Curve(c) => c.ctrl().iter().flat_map(|h| h.coords.clone()).collect(),
        Patch::Rect(r) => r
            .ctrl()
            .iter()
            .flatten()
            .flat_map(|h| h.coords.clone())
            .collect(),
        Patch::Tri(_) => return None,
    };
    match name {
        "f64_curve3" => {
            let h: [[f64; 3]; 4] = std::array::from_fn(|i| std::array::from_fn(|k| net[3 * i + k]));
            let mut out = vec![0.0; params.len() * 2];
            Some(best_of(repeat, params.len(), || {
                for (t, o) in params.iter().zip(out.chunks_mut(2)) {
                    let x = cubic(&h, *t);
                    o.copy_from_slice(&[x[0] / x[2], x[1] / x[2]]);
                }
                std::hint::black_box(&out);
            }))
        }
        "f64_bicubic" => {
            let h: [[[f64; 4]; 4]; 4] = std::array::from_fn(|i| {
                std::array::from_fn(|j| std::array::from_fn(|k| net[16 * i + 4 * j + k]))
            });
            let mut out = vec![0.0; params.len() / 2 * 3];
            Some(best_of(repeat, params.len() / 2, || {
                for (uv, o) in params.chunks(2).zip(out.chunks_mut(3)) {
                    let rows: [[f64; 4]; 4] = std::array::from_fn(|i| cubic(&h[i], uv[1]));
                    let x = cubic(&rows, uv[0]);
                    o.copy_from_slice(&[x[0] / x[3], x[1] / x[3], x[2] / x[3]]);
                }
                std::hint::black_box(&out);
            }))
        }
        _ => None,
    }
}

/// `Σ C(3,i) (1−t)^{3−i} tⁱ H_i` by Horner, fixed size.
fn cubic<const S: usize>(h: &[[f64; S]; 4], t: f64) -> [f64; S] {
    let s = 1.0 - t;
    let (c1, c2, c3) = (3.0 * t, 3.0 * t * t, t * t * t);
    std::array::from_fn(|k| ((h[0][k] * s + c1 * h[1][k]) * s + c2 * h[2][k]) * s + c3 * h[3][k])
}
