//! `audit` of a model: the Bézier pieces of one uniform bicubic B-spline
//! surface with N × N spans (all 2N(N−1) interior seams G2, the most work
//! per seam), and the STEP reader on the same pieces written as STEP text.
//! For the 10 000-surface STEP file, see `benches/make_step_model.py`.
//!
//! The certified measures' kernels (group `certify`), on a rational
//! bicubic piece as a B-spline face gives them (derivative nets formed in
//! interval arithmetic): the jet enclosed over a box 1/64 wide, the `f64`
//! jet Newton's guesses take, and the patch composed with a cubic in its
//! parameters.
//!
//! Run: `cargo bench --bench audit -- --warm-up-time 1 --measurement-time 2`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::audit::certify::{bezier::IPatch, compose::compose};
use exact_bezier::{algebra::Interval, RectPatch};
use exact_bezier::{
    audit::audit, audit::Model, audit::Piece, hpoint::HPoint, io::read_model, nurbs::Knots,
    nurbs::NurbsSurface, Patch,
};
use num_rational::BigRational;

type Q = BigRational;

fn q(n: i64) -> Q {
    Q::from_integer(n.into())
}

/// The pieces of a uniform bicubic B-spline surface with `n × n` spans.
fn model(n: i64) -> Model {
    let h = |i: i64, j: i64| ((i * 7 + j * 13) % 11) - 5 + ((i * j) % 3);
    let net = (0..n + 3)
        .map(|i| {
            (0..n + 3)
                .map(|j| HPoint::from_cartesian(&[q(i), q(j), q(h(i, j))]))
                .collect()
        })
        .collect();
    let knots = || Knots::new(3, (0..n + 7).map(q).collect(), (n + 3) as usize).expect("valid");
    let s = NurbsSurface::new(knots(), knots(), net).expect("valid");
    let pieces = s
        .bezier_pieces()
        .into_iter()
        .map(|p| Piece {
            patch: Patch::Rect(p.patch),
            origin: Default::default(),
        })
        .collect();
    Model {
        pieces,
        ..Model::default()
    }
}

/// The same surface as one STEP B_SPLINE_SURFACE_WITH_KNOTS.
fn step_text(n: i64) -> String {
    let mut s = String::from("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n");
    let mut rows = Vec::new();
    let mut id = 1;
    for i in 0..n + 3 {
        let mut row = Vec::new();
        for j in 0..n + 3 {
            s += &format!(
                "#{id}=CARTESIAN_POINT('',({i}.,{j}.,{}.));\n",
                ((i * 7 + j * 13) % 11) - 5 + ((i * j) % 3)
            );
            row.push(format!("#{id}"));
            id += 1;
        }
        rows.push(format!("({})", row.join(",")));
    }
    let mults = format!("({})", vec!["1"; (n + 7) as usize].join(","));
    let knots = format!(
        "({})",
        (0..n + 7)
            .map(|k| format!("{k}."))
            .collect::<Vec<_>>()
            .join(",")
    );
    s += &format!(
        "#{id}=B_SPLINE_SURFACE_WITH_KNOTS('',3,3,({}),.UNSPECIFIED.,.F.,.F.,.F.,{mults},{mults},{knots},{knots},.UNSPECIFIED.);\nENDSEC;\nEND-ISO-10303-21;\n",
        rows.join(",")
    );
    s
}

fn bench(c: &mut Criterion) {
    let m = model(10);
    c.bench_function("audit 100 bicubic pieces (180 G2 seams)", |b| {
        b.iter(|| audit(black_box(&m)).unwrap())
    });
    let text = step_text(10);
    c.bench_function("read STEP B-spline 13x13 net to 100 pieces", |b| {
        b.iter(|| read_model(black_box(text.as_bytes())).unwrap())
    });
}

/// A rational bicubic patch with coordinates in the tens, weights 1 to 2.
fn bicubic() -> IPatch {
    let r = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    let points = (0..4i64)
        .map(|i| {
            (0..4i64)
                .map(|j| vec![r(10 * i + j, 3), r(7 * j - i, 2), r((i * j) % 5 + 20, 1)])
                .collect()
        })
        .collect();
    let weights = (0..4i64)
        .map(|i| (0..4i64).map(|j| r(4 + (i + 2 * j) % 4, 4)).collect())
        .collect();
    let patch = RectPatch::new(points, weights).expect("positive weights");
    IPatch::with_enclosed_derivatives(&patch).expect("3D, positive weights")
}

fn certify(c: &mut Criterion) {
    let p = bicubic();
    let mut g = c.benchmark_group("certify");
    let (u, v) = (
        Interval {
            lo: 0.3,
            hi: 0.3 + 1.0 / 64.0,
        },
        Interval {
            lo: 0.55,
            hi: 0.55 + 1.0 / 64.0,
        },
    );
    g.bench_function("bicubic jet over a box", |b| {
        b.iter(|| p.jet(black_box(u), black_box(v)).unwrap())
    });
    g.bench_function("bicubic f64 jet", |b| {
        b.iter(|| p.approximate_jet(black_box(0.3), black_box(0.55)).unwrap())
    });
    let (cu, cv) = ([0.2, 0.3, 0.45, 0.5], [0.6, 0.55, 0.5, 0.52]);
    g.bench_function("bicubic composed with a cubic", |b| {
        b.iter(|| compose(&p.homogeneous(), black_box(&cu), black_box(&cv)))
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_group!(kernels, certify);
criterion_main!(benches, kernels);
