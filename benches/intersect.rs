//! Intersections of two planar cubics that cross three times (control
//! points k/100, the kind of input the peer comparison
//! `benches/peers/intersect` draws): the exact path, the filtered path
//! (certified boxes) and the `f64` path with tolerance 1e-12; plus a pair
//! that does not meet (the filter separates it).
//!
//! Run: `cargo bench --bench intersect -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::intersect::{intersect, Filter, Options};
use exact_bezier::Tolerance;

/// The filtered exact path.
const FILTERED: Options = Options {
    filter: Filter::First,
    tol: Tolerance(1e-9),
};
use exact_bezier::{ratio, Ordered, RationalCurve};
use num_rational::BigRational;

fn cubic(points: [(i64, i64); 4]) -> RationalCurve<BigRational> {
    RationalCurve::polynomial(
        points
            .iter()
            .map(|&(x, y)| vec![ratio(x, 100), ratio(y, 100)])
            .collect(),
    )
    .expect("a valid cubic")
}

fn bench(c: &mut Criterion) {
    let a = cubic([(20, 78), (94, 83), (54, 0), (65, 71)]);
    let b = cubic([(71, 58), (70, 12), (1, 98), (77, 98)]);
    let far = cubic([(200, 200), (230, 260), (260, 200), (290, 260)]);
    let (a64, b64) = (a.map(Ordered::to_f64), b.map(Ordered::to_f64));
    let mut g = c.benchmark_group("intersect cubic × cubic, 3 crossings");
    g.bench_function("exact", |bn| {
        bn.iter(|| intersect(black_box(&a), Some(&b), Options::default()))
    });
    g.bench_function("filtered", |bn| {
        bn.iter(|| intersect(black_box(&a), Some(&b), FILTERED))
    });
    g.bench_function("f64 tol 1e-12", |bn| {
        bn.iter(|| {
            intersect(
                black_box(&a64),
                Some(&b64),
                Options {
                    tol: Tolerance(1e-12),
                    ..Options::default()
                },
            )
        })
    });
    g.finish();
    let mut g = c.benchmark_group("intersect cubic × cubic, apart");
    g.bench_function("exact", |bn| {
        bn.iter(|| intersect(black_box(&a), Some(&far), Options::default()))
    });
    g.bench_function("filtered", |bn| {
        bn.iter(|| intersect(black_box(&a), Some(&far), FILTERED))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
