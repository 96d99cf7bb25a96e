//! Triangle evaluation and the rect ↔ tri conversions, f64 and exact, at
//! degrees 3 and 6 (rect bidegree (3, 3) and (6, 6)).
//!
//! `cargo bench --bench tri -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::{
    convert::rect_to_tris, convert::tri_to_degenerate_rect, convert::tri_to_rects, convert::Split,
    eval::Evaluator, ratio, Field, Ordered, RectPatch, TriPatch,
};
use num_rational::BigRational;

fn tri_patch<T: Field>(n: usize) -> TriPatch<T> {
    let pts = (0..=n)
        .map(|j| {
            (0..=n - j)
                .map(|i| {
                    vec![
                        ratio(i as i64, 3),
                        ratio(j as i64 * 2, 5),
                        ratio((i * j) as i64 + 1, 7),
                    ]
                })
                .collect()
        })
        .collect::<Vec<Vec<Vec<T>>>>();
    let ws = (0..=n)
        .map(|j| {
            (0..=n - j)
                .map(|i| ratio((i + 2 * j) as i64 % 5 + 1, 3))
                .collect()
        })
        .collect();
    TriPatch::new(pts, ws).unwrap()
}

fn rect_patch<T: Field>(n: usize) -> RectPatch<T> {
    let pts = (0..=n)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    vec![
                        ratio(i as i64, 3),
                        ratio(j as i64, 4),
                        ratio((i * j) as i64 % 5, 7),
                    ]
                })
                .collect()
        })
        .collect::<Vec<Vec<Vec<T>>>>();
    let ws = (0..=n)
        .map(|i| {
            (0..=n)
                .map(|j| ratio((i + 3 * j) as i64 % 4 + 1, 2))
                .collect()
        })
        .collect();
    RectPatch::new(pts, ws).unwrap()
}

fn run<T: Field>(c: &mut Criterion, label: &str) {
    let (u, v) = (ratio::<T>(2, 7), ratio::<T>(3, 11));
    let split = Split::new_unchecked(
        Split::<BigRational>::standard()
            .params()
            .clone()
            .map(|x| T::from_rational(&x)),
    );
    for n in [3usize, 6] {
        let t = tri_patch::<T>(n);
        let r = rect_patch::<T>(n);
        c.bench_function(&format!("tri eval n={n} {label}"), |b| {
            b.iter(|| black_box(&t).eval(black_box(&u), black_box(&v)))
        });
        c.bench_function(&format!("rect->2 tris ({n},{n}) {label}"), |b| {
            b.iter(|| rect_to_tris(black_box(&r)))
        });
        c.bench_function(&format!("tri->3 rects n={n} {label}"), |b| {
            b.iter(|| tri_to_rects(black_box(&t), black_box(&split)))
        });
        c.bench_function(&format!("tri->degenerate rect n={n} {label}"), |b| {
            b.iter(|| tri_to_degenerate_rect(black_box(&t)))
        });
    }
}

/// Batches of 100 points through [`Evaluator`], exact (fraction-free) and
/// f64; the per-point time is the batch time / 100.
fn batch(c: &mut Criterion) {
    let uv: Vec<BigRational> = (0..100)
        .flat_map(|k| {
            [
                ratio(k % 10, 10),
                ratio::<BigRational>(k / 10, 10) * ratio::<BigRational>(10 - k % 10, 10),
            ]
        })
        .collect();
    let uvf: Vec<f64> = uv.iter().map(Ordered::to_f64).collect();
    for n in [3usize, 6] {
        let t = tri_patch::<BigRational>(n);
        let mut ev = Evaluator::tri(&t);
        let mut out = vec![ratio(0, 1); 3 * 100];
        c.bench_function(&format!("tri eval n={n} exact batch of 100"), |b| {
            b.iter(|| ev.eval_batch(black_box(&uv), &mut out))
        });
        let mut evf = Evaluator::tri(&tri_patch::<f64>(n));
        let mut outf = vec![0.0; 3 * 100];
        c.bench_function(&format!("tri eval n={n} f64 batch of 100"), |b| {
            b.iter(|| evf.eval_batch(black_box(&uvf), &mut outf))
        });
    }
}

fn benches(c: &mut Criterion) {
    run::<f64>(c, "f64");
    run::<BigRational>(c, "exact");
    batch(c);
}

criterion_group!(tri, benches);
criterion_main!(tri);
