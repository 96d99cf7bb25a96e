//! Curve evaluation, f64 vs exact `BigRational`: rational curves of degree 3
//! and 10 with rational weights, evaluated by de Casteljau (`eval`, one
//! division at the end). Run with
//! `cargo bench --bench curve -- --warm-up-time 1 --measurement-time 3`;
//! the exact/f64 ratio is the ratio of the reported times.
//!
//! A third variant shows the fraction-free path (README, "Speed") with the
//! generic API only: the homogeneous control points are scaled to integers
//! ([`RationalCurve::scale_weights`] by the lcm of the denominators, which
//! keeps every point), `t = p/q` becomes the homogeneous parameter
//! `(q − p : p)` ([`RationalCurve::eval_hom_param`]), and the one division
//! happens in `project`. A fourth runs a batch of 100 parameters through
//! [`Evaluator`] (`f64` and exact): since issue 12 `eval` itself is the
//! Horner–Bernstein kernel, fraction-free on machine integers for
//! `BigRational`; the per-point time is the batch time / 100.
//!
//! The group `elevate` raises the same curves by 1 and by 5 degrees
//! ([`RationalCurve::elevate`]), `f64` and exact.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::{algebra::rational_to_f64, eval::Evaluator, ratio, RationalCurve};
use num_integer::Integer;
use num_rational::BigRational;

/// A planar rational curve of degree `n` with small rational coordinates
/// and weights (denominators up to 7).
fn sample(n: usize) -> RationalCurve<BigRational> {
    let pts = (0..=n as i64)
        .map(|i| vec![ratio(i * 3 + 1, 2), ratio((i * i) % 7 - 3, 3)])
        .collect();
    let weights = (0..=n as i64)
        .map(|i| ratio(i % 4 + 1, i % 3 + 2))
        .collect();
    RationalCurve::new(pts, weights).expect("well-formed sample")
}

/// The curve with integer homogeneous coordinates (weights scaled by the
/// lcm of all denominators).
fn integral(c: &RationalCurve<BigRational>) -> RationalCurve<BigRational> {
    let lcm = c
        .ctrl()
        .iter()
        .flat_map(|h| h.coords.iter())
        .fold(num_bigint::BigInt::from(1), |acc, x| acc.lcm(x.denom()));
    c.scale_weights(&BigRational::from_integer(lcm))
}

fn eval(c: &mut Criterion) {
    let t = ratio::<BigRational>(2, 7);
    let tf = rational_to_f64(&t);
    for n in [3usize, 10] {
        let exact = sample(n);
        let float = exact.map(rational_to_f64);
        c.bench_function(&format!("eval degree {n} f64"), |b| {
            b.iter(|| black_box(&float).eval(black_box(&tf)))
        });
        c.bench_function(&format!("eval degree {n} exact"), |b| {
            b.iter(|| black_box(&exact).eval(black_box(&t)))
        });
        let ints = integral(&exact);
        let (p, q) = (ratio::<BigRational>(2, 1), ratio::<BigRational>(7, 1));
        let a = q.clone() - &p;
        assert_eq!(
            ints.eval_hom_param(&a, &p).project().unwrap(),
            exact.eval(&t).unwrap()
        );
        c.bench_function(&format!("eval degree {n} exact fraction-free"), |b| {
            b.iter(|| {
                black_box(&ints)
                    .eval_hom_param(black_box(&a), black_box(&p))
                    .project()
            })
        });
        let ts: Vec<BigRational> = (0..100).map(|k| ratio(k, 100)).collect();
        let mut ev = Evaluator::curve(&exact);
        let mut out = vec![ratio(0, 1); 2 * ts.len()];
        c.bench_function(&format!("eval degree {n} exact batch of 100"), |b| {
            b.iter(|| ev.eval_batch(black_box(&ts), &mut out))
        });
        let tfs: Vec<f64> = ts.iter().map(rational_to_f64).collect();
        let mut evf = Evaluator::curve(&float);
        let mut outf = vec![0.0; 2 * ts.len()];
        c.bench_function(&format!("eval degree {n} f64 batch of 100"), |b| {
            b.iter(|| evf.eval_batch(black_box(&tfs), &mut outf))
        });
    }
}

fn elevate(c: &mut Criterion) {
    let mut g = c.benchmark_group("elevate");
    for n in [3usize, 10] {
        let exact = sample(n);
        let float = exact.map(rational_to_f64);
        for r in [1usize, 5] {
            g.bench_function(format!("degree {n} by {r} f64"), |b| {
                b.iter(|| black_box(&float).elevate(black_box(r)))
            });
            g.bench_function(format!("degree {n} by {r} exact"), |b| {
                b.iter(|| black_box(&exact).elevate(black_box(r)))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, eval, elevate);
criterion_main!(benches);
