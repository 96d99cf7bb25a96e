//! Rect patches: bicubic evaluation (f64 vs exact) and the exact quadratic
//! reparameterization of a bicubic (source 000, eqs 9-17), on Example 2 of
//! source 000 (read exactly from its fixture); exact evaluation also by the
//! batch [`Evaluator`] (fraction-free for exact input).
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::{
    eval::Evaluator, io::read_patches, ratio, reparam::Quadratic, Ordered, Patch, RectPatch,
};
use num_rational::BigRational;

fn example2() -> RectPatch<BigRational> {
    let text = include_str!("../tests/fixtures/yang_yong_example2.json");
    match read_patches(text).expect("fixture").remove(0) {
        Patch::Rect(r) => r,
        _ => unreachable!("the fixture is a rect patch"),
    }
}

fn eval(c: &mut Criterion) {
    let exact = example2();
    let float = exact.map(Ordered::to_f64);
    let (u, v) = (ratio::<BigRational>(1, 3), ratio::<BigRational>(2, 7));
    let (uf, vf) = (u.to_f64(), v.to_f64());
    c.bench_function("bicubic eval f64", |b| {
        b.iter(|| black_box(&float).eval(black_box(&uf), black_box(&vf)))
    });
    c.bench_function("bicubic eval exact", |b| {
        b.iter(|| black_box(&exact).eval(black_box(&u), black_box(&v)))
    });
    let uv: Vec<BigRational> = (0..100)
        .flat_map(|k| [ratio(k, 100), ratio(99 - k, 100)])
        .collect();
    let mut ev = Evaluator::rect(&exact);
    let mut out = vec![ratio(0, 1); 3 * 100];
    c.bench_function("bicubic eval exact batch of 100", |b| {
        b.iter(|| ev.eval_batch(black_box(&uv), &mut out))
    });
    let uvf: Vec<f64> = uv.iter().map(Ordered::to_f64).collect();
    let mut evf = Evaluator::rect(&float);
    let mut outf = vec![0.0; 3 * 100];
    c.bench_function("bicubic eval f64 batch of 100", |b| {
        b.iter(|| evf.eval_batch(black_box(&uvf), &mut outf))
    });
}

fn quadratic(c: &mut Criterion) {
    let exact = example2();
    let map = Quadratic {
        alpha1: ratio(1, 2),
        alpha2: ratio(7, 15),
        beta1: ratio(4, 7),
        beta2: ratio(4, 7),
    };
    c.bench_function("bicubic quadratic reparam exact", |b| {
        b.iter(|| black_box(&exact).quadratic_reparam(black_box(&map)))
    });
    let float = exact.map(Ordered::to_f64);
    let mapf = Quadratic {
        alpha1: 0.5,
        alpha2: 7.0 / 15.0,
        beta1: 4.0 / 7.0,
        beta2: 4.0 / 7.0,
    };
    c.bench_function("bicubic quadratic reparam f64", |b| {
        b.iter(|| black_box(&float).quadratic_reparam(black_box(&mapf)))
    });
}

criterion_group!(benches, eval, quadratic);
criterion_main!(benches);
