//! Curve evaluation, f64 vs exact (placeholder until the foundation benches land).
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::{ratio, RationalCurve};
use num_rational::BigRational;

fn eval(c: &mut Criterion) {
    let pts: Vec<Vec<BigRational>> = (0..4).map(|i| vec![ratio(i, 1), ratio(i * i, 3)]).collect();
    let curve = RationalCurve::polynomial(pts).unwrap();
    let t = ratio::<BigRational>(1, 3);
    c.bench_function("cubic eval exact", |b| {
        b.iter(|| black_box(&curve).eval(black_box(&t)))
    });
}

criterion_group!(benches, eval);
criterion_main!(benches);
