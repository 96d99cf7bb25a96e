//! Trigonometric surface evaluation (source 002): the bowl's S₁ at one point
//! and on an 8 × 8 grid, f64 (angles) against exact (rational τ).
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::{ratio, trig::trig_bowl, trig::TrigParam, trig::TrigRect, Ordered};
use num_rational::BigRational;

fn surface() -> TrigRect<BigRational> {
    let r = |k: i64| ratio::<BigRational>(k, 100);
    trig_bowl(&r(120), &[r(130), r(110), r(110), r(130)], None).unwrap()[0].clone()
}

fn eval(c: &mut Criterion) {
    let exact = surface();
    let float = exact.map(Ordered::to_f64);
    let (tu, tv) = (ratio::<BigRational>(1, 3), ratio::<BigRational>(2, 7));
    let (eu, ev) = (TrigParam::from_tau(&tu), TrigParam::from_tau(&tv));
    let angle = |t: &BigRational| TrigParam::from_angle(2.0 * t.to_f64().atan());
    let (fu, fv) = (angle(&tu), angle(&tv));
    c.bench_function("trig-rect eval f64", |b| {
        b.iter(|| black_box(&float).eval(black_box(&fu), black_box(&fv)))
    });
    c.bench_function("trig-rect eval exact", |b| {
        b.iter(|| black_box(&exact).eval(black_box(&eu), black_box(&ev)))
    });
    c.bench_function("trig-rect normal-direction partials exact", |b| {
        b.iter(|| {
            let e = black_box(&exact);
            (e.partial(1, 0, &eu, &ev), e.partial(0, 1, &eu, &ev))
        })
    });
    let taus: Vec<BigRational> = (0..8).map(|k| ratio(k, 7)).collect();
    let exact_grid: Vec<_> = taus.iter().map(TrigParam::from_tau).collect();
    let float_grid: Vec<_> = taus.iter().map(angle).collect();
    c.bench_function("trig-rect 8x8 grid f64", |b| {
        b.iter(|| {
            for u in &float_grid {
                for v in &float_grid {
                    black_box(float.eval(u, v));
                }
            }
        })
    });
    c.bench_function("trig-rect 8x8 grid exact", |b| {
        b.iter(|| {
            for u in &exact_grid {
                for v in &exact_grid {
                    black_box(exact.eval(u, v));
                }
            }
        })
    });
}

criterion_group!(benches, eval);
criterion_main!(benches);
