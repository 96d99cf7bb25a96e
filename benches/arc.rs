//! Arc construction (source 004 eq. 1) and the exact circle test, exact vs f64.
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::{arc::QuadArc, curve::circle_of, ratio, Tolerance};
use num_rational::BigRational;

fn arcs(c: &mut Criterion) {
    let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    // θ/2 with cos 3/5, sin 4/5; λ chosen from σ = 2/3, so σ³ = 8/27 is a perfect cube.
    let arc = QuadArc::from_ends(
        &p(1, 3),
        &p(-4, 7),
        &ratio(3, 5),
        &ratio(4, 5),
        Tolerance::EXACT,
    )
    .unwrap();
    let sigma = ratio::<BigRational>(2, 3);
    let lambda = exact_bezier::arc::lambda_of_sigma_cubed(arc.cos_half(), &ratio(8, 27)).unwrap();
    let arc_f = arc.map(exact_bezier::Ordered::to_f64);
    let lambda_f = exact_bezier::Ordered::to_f64(&lambda);
    c.bench_function("arc cubic from lambda, exact (cube root decided)", |b| {
        b.iter(|| {
            black_box(&arc)
                .cubic_for_lambda(black_box(&lambda))
                .unwrap()
        })
    });
    c.bench_function("arc cubic from lambda, f64", |b| {
        b.iter(|| {
            let s =
                exact_bezier::arc::sigma_of_lambda(arc_f.cos_half(), black_box(&lambda_f)).unwrap();
            black_box(&arc_f).standard_cubic(&s).unwrap()
        })
    });
    let cubic = arc.standard_cubic(&sigma).unwrap();
    let cubic_f = cubic.map(exact_bezier::Ordered::to_f64);
    c.bench_function("circle test, exact cubic", |b| {
        b.iter(|| circle_of(black_box(&cubic), Tolerance::EXACT).unwrap())
    });
    let scaled = exact_bezier::curve::integer_coords(&cubic);
    c.bench_function(
        "circle test, exact cubic, integer homogeneous coords",
        |b| {
            b.iter(|| {
                circle_of(
                    &exact_bezier::curve::integer_coords(black_box(&cubic)),
                    Tolerance::EXACT,
                )
                .unwrap()
            })
        },
    );
    assert_eq!(
        circle_of(&scaled, Tolerance::EXACT),
        circle_of(&cubic, Tolerance::EXACT)
    );
    c.bench_function("circle test, f64 cubic (tol 1e-9)", |b| {
        b.iter(|| circle_of(black_box(&cubic_f), Tolerance(1e-9)).unwrap())
    });
    let sextic = cubic.elevate(3);
    c.bench_function("circle test, exact degree 6", |b| {
        b.iter(|| circle_of(black_box(&sextic), Tolerance::EXACT).unwrap())
    });
}

criterion_group!(benches, arcs);
criterion_main!(benches);
