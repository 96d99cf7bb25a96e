//! Products of interval Bernstein polynomials in scaled form
//! (`interval_bernstein::mul`, the audit's inner operation), at the sizes
//! the audit multiplies: from 1 × 4 coefficients to 40 × 40 (the most
//! frequent in the audit of `tail_section_asm.stp`, 2026-11-29: 7 × 10,
//! 16 × 19, 10 × 10, 4 × 7, 4 × 4 and 1 × 4, 0.7 to 1.5 million each).
//!
//! Two inputs of each size: finite end points (the vectorised convolution
//! from `FINITE_FROM` = 100 term products on, the plain one below) and the
//! same operands with one end point at −∞ (always the plain convolution).
//! The pair shows where the vectorised kernel starts to pay, which is how
//! `FINITE_FROM` was chosen.
//!
//! Run: `cargo bench --bench interval_mul -- --warm-up-time 1 --measurement-time 2`

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use exact_bezier::algebra::interval_bernstein::mul;
use exact_bezier::algebra::Interval;

/// `len` intervals of width about 1e-12 around values of both signs
/// (the audit's operands straddle zero as often as not).
fn operand(len: usize, seed: u64) -> Vec<Interval> {
    (0..len as u64)
        .map(|i| {
            let x = ((i * 7919 + seed * 104_729) % 2001) as f64 / 1000.0 - 1.0;
            Interval {
                lo: x - 1e-12,
                hi: x + 1e-12,
            }
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("interval_bernstein::mul");
    for (m, n) in [
        (1, 4),
        (2, 4),
        (4, 4),
        (4, 7),
        (7, 7),
        (7, 10),
        (4, 13),
        (10, 10),
        (13, 13),
        (16, 19),
        (20, 20),
        (40, 40),
    ] {
        let (a, b) = (operand(m, 1), operand(n, 2));
        let mut unbounded = a.clone();
        unbounded[0].lo = f64::NEG_INFINITY;
        let size = format!("{m}x{n}");
        g.bench_with_input(
            BenchmarkId::new("finite", &size),
            &(&a, &b),
            |bn, (a, b)| bn.iter(|| mul(black_box(a), black_box(b))),
        );
        g.bench_with_input(
            BenchmarkId::new("one end infinite (plain)", &size),
            &(&unbounded, &b),
            |bn, (a, b)| bn.iter(|| mul(black_box(a), black_box(b))),
        );
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
