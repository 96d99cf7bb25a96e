//! Our side of the peer benchmark `benches/peers/run` (issue 12): reads the
//! cases that `benches/peers/peer_eval.py` generated, evaluates each one
//! with the batch API ([`Evaluator`]) and prints one JSON object of
//! nanoseconds per point (the best of `--repeat` passes).
//!
//! ```text
//! cargo bench --bench peer_eval -- CASES.json [--repeat 5]
//! cargo bench --bench peer_eval -- --peak
//! ```
//!
//! `--peak` prints the machine's peak instead ([`peak::peak`]: FMA
//! GFLOP/s and divides a nanosecond, 4- and 8-wide), from which
//! `peer_eval.py` computes the bound of each case.
//!
//! Each case is `{"name", "patch" (our JSON format), "params": [...],
//! "exact": bool}`; `params` holds one value per point for a curve and
//! two for a patch, read exactly from their text. The `f64` cases also run
//! a hand-written fixed-size kernel of the same Horner–Bernstein scheme,
//! eight parameters at a time in fixed-size arrays that the compiler
//! vectorises (`<name>_reference`), where one is written below: the
//! yardstick of the library's lane kernels (`src/eval/lanes.rs`). Batches
//! are multiples of eight points.

use exact_bezier::algebra::parse_rational;
use exact_bezier::eval::Evaluator;
use exact_bezier::io::read_patches;
use exact_bezier::{Field, Ordered, Patch};
use num_rational::BigRational;
use serde_json::{Map, Value};
use std::time::Instant;

mod peak;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.iter().any(|a| a == "--peak") {
        println!("{}", peak::peak());
        return;
    }
    // `cargo bench` appends `--bench`; with no cases file there is nothing to time.
    let Some(path) = args.get(1).filter(|a| !a.starts_with("--")) else {
        eprintln!("usage: cargo bench --bench peer_eval -- CASES.json [--repeat N] | --peak");
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
/// rational bicubic in space, [`L`] parameters at a time in arrays of
/// fixed size (the lane-major form the compiler vectorises), the yardstick
/// of the library's lane kernels.
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
            let h: [[Lane; 3]; 4] =
                std::array::from_fn(|i| std::array::from_fn(|k| [net[3 * i + k]; L]));
            let mut out = vec![0.0; params.len() * 2];
            Some(best_of(repeat, params.len(), || {
                for (t, o) in params.chunks_exact(L).zip(out.chunks_exact_mut(2 * L)) {
                    let x = cubic(&h, t.try_into().expect("L values"));
                    for (l, o) in o.chunks_exact_mut(2).enumerate() {
                        o.copy_from_slice(&[x[0][l] / x[2][l], x[1][l] / x[2][l]]);
                    }
                }
                std::hint::black_box(&out);
            }))
        }
        "f64_bicubic" => {
            let h: [[[Lane; 4]; 4]; 4] = std::array::from_fn(|i| {
                std::array::from_fn(|j| std::array::from_fn(|k| [net[16 * i + 4 * j + k]; L]))
            });
            let mut out = vec![0.0; params.len() / 2 * 3];
            Some(best_of(repeat, params.len() / 2, || {
                for (uv, o) in params.chunks_exact(2 * L).zip(out.chunks_exact_mut(3 * L)) {
                    let (u, v): (Lane, Lane) = (
                        std::array::from_fn(|l| uv[2 * l]),
                        std::array::from_fn(|l| uv[2 * l + 1]),
                    );
                    let rows: [[Lane; 4]; 4] = std::array::from_fn(|i| cubic(&h[i], &v));
                    let x = cubic(&rows, &u);
                    for (l, o) in o.chunks_exact_mut(3).enumerate() {
                        o.copy_from_slice(&[
                            x[0][l] / x[3][l],
                            x[1][l] / x[3][l],
                            x[2][l] / x[3][l],
                        ]);
                    }
                }
                std::hint::black_box(&out);
            }))
        }
        _ => None,
    }
}

/// Parameters per group of the reference kernels.
const L: usize = 8;

/// One value per parameter of a group.
type Lane = [f64; L];

/// `Σ C(3,i) (1−t)^{3−i} tⁱ H_i` by Horner, fixed size, in every lane.
#[inline(always)]
fn cubic<const S: usize>(h: &[[Lane; S]; 4], t: &Lane) -> [Lane; S] {
    let s = lane(|l| 1.0 - t[l]);
    let (c1, c2, c3) = (
        lane(|l| 3.0 * t[l]),
        lane(|l| 3.0 * t[l] * t[l]),
        lane(|l| t[l] * t[l] * t[l]),
    );
    std::array::from_fn(|k| {
        lane(|l| {
            ((h[0][k][l] * s[l] + c1[l] * h[1][k][l]) * s[l] + c2[l] * h[2][k][l]) * s[l]
                + c3[l] * h[3][k][l]
        })
    })
}

/// The lane of values `f(l)`.
#[inline(always)]
fn lane(f: impl Fn(usize) -> f64) -> Lane {
    std::array::from_fn(f)
}
