//! Certified measures on pairs of faces whose true deviations are known in
//! closed form, checked against those values and against exact sampling.

use super::*;
use crate::error::Error;
use crate::limits::{with_limits, Limits};
use crate::{ratio, RationalCurve, RectPatch};
use num_rational::BigRational;
use num_traits::{FromPrimitive, Zero};
use proptest::prelude::*;
use std::time::Instant;

type Q = BigRational;

fn q(n: i64, d: i64) -> Q {
    ratio(n, d)
}

fn pt(x: Q, y: Q, z: Q) -> Vec<Q> {
    vec![x, y, z]
}

/// Does the enclosure hold every value of `[lo, hi]` (true bounds)?
fn holds(e: &Enclosure, lo: f64, hi: f64) -> bool {
    e.lo <= lo && hi <= e.hi
}

/// Is the enclosure as tight as `p` asks, for a quantity of width `abs`?
fn tight(e: &Enclosure, rel: f64, abs: f64) -> bool {
    e.tight && e.hi - e.lo <= rel * e.hi + abs
}

const G: i64 = 10_000_000; // the gap is 1/G = 10⁻⁷
const K: i64 = 100_000; // the kink's slope is 1/K = 10⁻⁵

/// The floor `z = 0` over `0 ≤ x ≤ 1, −1 ≤ y ≤ 0` (normal `−z`, so
/// outward is `+z` with `outward: false`) and the plane `z = y/K` over
/// `0 ≤ y ≤ 1` (normal `(0, −1/K, 1)`): a kink of `atan(1/K)` along the
/// x axis.
fn planes() -> [Face; 2] {
    let floor = RectPatch::polynomial(vec![
        vec![
            pt(q(0, 1), q(0, 1), q(0, 1)),
            pt(q(0, 1), q(-1, 1), q(0, 1)),
        ],
        vec![
            pt(q(1, 1), q(0, 1), q(0, 1)),
            pt(q(1, 1), q(-1, 1), q(0, 1)),
        ],
    ])
    .unwrap();
    let tilted = RectPatch::polynomial(vec![
        vec![pt(q(0, 1), q(0, 1), q(0, 1)), pt(q(0, 1), q(1, 1), q(1, K))],
        vec![pt(q(1, 1), q(0, 1), q(0, 1)), pt(q(1, 1), q(1, 1), q(1, K))],
    ])
    .unwrap();
    [
        Face {
            patch: IPatch::new(&floor).unwrap(),
            outward: false,
        },
        Face {
            patch: IPatch::new(&tilted).unwrap(),
            outward: true,
        },
    ]
}

fn timed(name: &str, edge: &[ICurve], faces: &[Face; 2], p: &Precision) -> EdgeMeasures {
    let start = Instant::now();
    let m = measure_edge(edge, faces, p).unwrap().measures;
    eprintln!("certify timing: {name}: {:?}", start.elapsed());
    m
}

#[test]
fn planes_with_gap_and_kink_are_measured_right() {
    // The edge runs 10⁻⁷ above the x axis: its distance to the floor is
    // g = 10⁻⁷, to the tilted plane g/√(1+k²), and the feet are g·k/√(1+k²)
    // apart (k = 10⁻⁵); the angle is atan k. Brackets from the alternating
    // series: 1/√(1+k²) ∈ [1 − k²/2, 1 − k²/2 + 3k⁴/8],
    // atan k ∈ [k − k³/3, k − k³/3 + k⁵/5]; the f64 rounding of the bracket
    // ends is covered by a relative 10⁻¹⁵.
    let edge = RationalCurve::polynomial(vec![
        pt(q(0, 1), q(0, 1), q(1, G)),
        pt(q(1, 1), q(0, 1), q(1, G)),
    ])
    .unwrap();
    let p = Precision {
        length: 1e-10,
        angle: 1e-10,
        ..Precision::default()
    };
    let m = timed("planes", &[ICurve::new(&edge).unwrap()], &planes(), &p);
    let (g, k): (f64, f64) = (1e-7, 1e-5);
    let (down, up) = (1.0 - 1e-15, 1.0 + 1e-15);
    let inv_root = [1.0 - k * k / 2.0, 1.0 - k * k / 2.0 + 3.0 * k.powi(4) / 8.0];
    let atan = [k - k.powi(3) / 3.0, k - k.powi(3) / 3.0 + k.powi(5) / 5.0];
    assert!(holds(&m.gap[0], g * down, g * up), "{:?}", m.gap[0]);
    assert!(
        holds(&m.gap[1], g * inv_root[0] * down, g * inv_root[1] * up),
        "{:?}",
        m.gap[1]
    );
    let feet = [g * k * inv_root[0] * down, g * k * inv_root[1] * up];
    assert!(holds(&m.face_gap, feet[0], feet[1]), "{:?}", m.face_gap);
    assert!(
        holds(&m.angle, atan[0] * down, atan[1] * up),
        "{:?}",
        m.angle
    );
    assert!(m.angle.hi - m.angle.lo < 1e-15, "{:?}", m.angle);
    assert!(holds(&m.curvature, 0.0, 0.0), "{:?}", m.curvature);
    for e in [m.gap[0], m.gap[1], m.face_gap] {
        assert!(tight(&e, p.rel, p.length), "{e:?}");
    }
    assert!(tight(&m.angle, p.rel, p.angle), "{:?}", m.angle);
    assert!(tight(&m.curvature, p.rel, p.curvature), "{:?}", m.curvature);

    let above = Tolerances {
        length: 1.01e-7,
        angle: 1.01e-5,
        curvature: 1e-3,
    };
    let v = verdicts(&m, &above, None);
    assert_eq!(
        (v.g0, v.g1, v.g2),
        (
            Verdict::WithinTolerance,
            Verdict::WithinTolerance,
            Verdict::WithinTolerance
        )
    );
    let below = Tolerances {
        length: 0.99e-7,
        angle: 0.99e-5,
        curvature: 1e-3,
    };
    let v = verdicts(&m, &below, None);
    assert!(matches!(v.g0, Verdict::Fails { magnitude } if magnitude.lo > 0.99e-7));
    assert!(matches!(v.g1, Verdict::Fails { magnitude } if magnitude.lo > 0.99e-5));
    // An exact seam test's answer overrides the measures up to its order.
    let v = verdicts(&m, &below, Some(crate::audit::Continuity::G0));
    assert_eq!(v.g0, Verdict::Exact);
    assert!(matches!(v.g1, Verdict::Fails { .. }));
}

/// A rational quadratic arc of the unit circle in the (x, z) plane over an
/// angle of 2·acos(3/5) from `(1, 0)`, turned by `turns` times that angle
/// (rotation by (cos, sin) = (−7/25, 24/25)), extruded along y ∈ [0, 1].
fn cylinder(turns: usize) -> RectPatch<Q> {
    let mut arc = [
        [q(1, 1), q(0, 1)],
        [q(1, 1), q(4, 3)],
        [q(-7, 25), q(24, 25)],
    ];
    for _ in 0..turns {
        arc = arc.map(|[x, z]| {
            [
                q(-7, 25) * &x - q(24, 25) * &z,
                q(24, 25) * x + q(-7, 25) * z,
            ]
        });
    }
    let points = arc
        .iter()
        .map(|[x, z]| {
            vec![
                pt(x.clone(), q(0, 1), z.clone()),
                pt(x.clone(), q(1, 1), z.clone()),
            ]
        })
        .collect();
    let weights = [q(1, 1), q(3, 5), q(1, 1)]
        .map(|w| vec![w.clone(), w])
        .to_vec();
    RectPatch::new(points, weights).unwrap()
}

/// The plane tangent to the unit cylinder along the line x = −7/25,
/// z = 24/25, continuing the turn of the first piece.
fn tangent_plane() -> RectPatch<Q> {
    RectPatch::polynomial(vec![
        vec![
            pt(q(-7, 25), q(0, 1), q(24, 25)),
            pt(q(-7, 25), q(1, 1), q(24, 25)),
        ],
        vec![
            pt(q(-31, 25), q(0, 1), q(17, 25)),
            pt(q(-31, 25), q(1, 1), q(17, 25)),
        ],
    ])
    .unwrap()
}

/// A straightforward rational evaluator of a rational patch: the
/// Bernstein sums of `w·P` and `w`, divided.
fn eval_direct(r: &RectPatch<Q>, u: &Q, v: &Q) -> Vec<Q> {
    let (m, n) = r.degree();
    let bern = |deg: usize, i: usize, t: &Q| {
        let c = (0..i).fold(Q::from_integer(1.into()), |a, k| {
            a * q((deg - k) as i64, (k + 1) as i64)
        });
        c * num_traits::pow(t.clone(), i) * num_traits::pow(Q::from_integer(1.into()) - t, deg - i)
    };
    let mut acc = vec![Q::zero(); 4];
    for i in 0..=m {
        for j in 0..=n {
            let b = bern(m, i, u) * bern(n, j, v);
            for (a, c) in acc.iter_mut().zip(&r.ctrl()[i][j].coords) {
                *a += &b * c;
            }
        }
    }
    let w = acc[3].clone();
    acc[..3].iter().map(|x| x / &w).collect()
}

#[test]
fn cylinder_pieces_are_g2_and_a_tangent_plane_fails_g2() {
    let (a, b, plane) = (cylinder(0), cylinder(1), tangent_plane());
    // The construction, checked by an independent evaluator at 21 points
    // of the seam: a's u = 1 and b's u = 0 are the line (−7/25, y, 24/25),
    // and the pieces lie on x² + z² = 1.
    for k in 0..=20 {
        let y = q(k, 20);
        let line = pt(q(-7, 25), y.clone(), q(24, 25));
        assert_eq!(eval_direct(&a, &q(1, 1), &y), line);
        assert_eq!(eval_direct(&b, &q(0, 1), &y), line);
        assert_eq!(eval_direct(&plane, &q(0, 1), &y), line);
        let x = eval_direct(&b, &q(k, 20), &y);
        assert_eq!(&x[0] * &x[0] + &x[2] * &x[2], q(1, 1));
    }
    let edge = RationalCurve::polynomial(vec![
        pt(q(-7, 25), q(0, 1), q(24, 25)),
        pt(q(-7, 25), q(1, 1), q(24, 25)),
    ])
    .unwrap();
    let edge = [ICurve::new(&edge).unwrap()];
    // Both pieces have S_u × S_v pointing to the axis: inward.
    let face = |r: &RectPatch<Q>| Face {
        patch: IPatch::new(r).unwrap(),
        outward: false,
    };
    let p = Precision {
        rel: 1e-3,
        length: 1e-6,
        angle: 1e-6,
        curvature: 1e-2,
    };
    let tol = Tolerances {
        length: 1e-5,
        angle: 1e-5,
        curvature: 1e-1,
    };

    // Same cylinder: every deviation is 0.
    let m = timed("cylinder-cylinder", &edge, &[face(&a), face(&b)], &p);
    for e in [m.gap[0], m.gap[1], m.face_gap, m.angle, m.curvature] {
        assert!(holds(&e, 0.0, 0.0), "{e:?}");
    }
    assert!(
        m.angle.hi < 2e-6 && m.gap[0].hi < 2e-6 && m.curvature.hi < 2e-2,
        "{m:?}"
    );
    let v = verdicts(&m, &tol, None);
    assert_eq!(
        (v.g0, v.g1),
        (Verdict::WithinTolerance, Verdict::WithinTolerance)
    );

    // Cylinder of radius 1 against its tangent plane: G1, and the normal
    // curvatures across the edge are 1 and 0.
    let m = timed("cylinder-plane", &edge, &[face(&a), face(&plane)], &p);
    assert!(
        holds(&m.angle, 0.0, 0.0) && m.angle.hi < 2e-6,
        "{:?}",
        m.angle
    );
    assert!(holds(&m.curvature, 1.0, 1.0), "{:?}", m.curvature);
    assert!(tight(&m.curvature, p.rel, p.curvature), "{:?}", m.curvature);
    let v = verdicts(&m, &tol, None);
    assert_eq!(v.g1, Verdict::WithinTolerance);
    assert!(matches!(v.g2, Verdict::Fails { magnitude } if magnitude.lo > 0.99));
}

/// z = c·τ(1−τ)(1−2τ)² = c(τ − 5τ² + 8τ³ − 4τ⁴), the monomial form.
fn bump(c: &Q, t: &Q) -> Q {
    let coef = [0, 1, -5, 8, -4];
    coef.iter()
        .rev()
        .fold(Q::zero(), |acc, &a| acc * t + q(a, 1))
        * c
}

#[test]
fn the_certified_gap_catches_a_maximum_that_sampling_misses() {
    // The edge (τ, 0, c·τ(1−τ)(1−2τ)²) over the floor z = 0: zero at its
    // ends and midpoint, the samples of a sampling checker, and largest,
    // c/16, at τ = 1/2 ± 1/(2√2). With c = 16·10⁻⁷ the gap is 10⁻⁷.
    let c = q(16, G);
    // Bernstein coefficients of τ − 5τ² + 8τ³ − 4τ⁴ (degree 4):
    // b_i = Σ_j C(i,j)/C(4,j) a_j = 0, 1/4, −1/3, 1/4, 0.
    let b = [q(0, 1), q(1, 4), q(-1, 3), q(1, 4), q(0, 1)];
    let points = (0..5)
        .map(|i| pt(q(i, 4), q(0, 1), &c * &b[i as usize]))
        .collect();
    let curve = RationalCurve::polynomial(points).unwrap();
    for k in 0..=16 {
        let t = q(k, 16);
        assert_eq!(curve.eval(&t).unwrap()[2], bump(&c, &t));
    }
    for t in [q(0, 1), q(1, 2), q(1, 1)] {
        assert!(bump(&c, &t).is_zero(), "a sampling checker sees no gap");
    }
    let m = timed(
        "bump",
        &[ICurve::new(&curve).unwrap()],
        &planes(),
        &Precision {
            length: 1e-10,
            ..Precision::default()
        },
    );
    assert!(
        holds(&m.gap[0], 1e-7 * (1.0 - 1e-15), 1e-7 * (1.0 + 1e-15)),
        "{:?}",
        m.gap[0]
    );
    assert!(tight(&m.gap[0], 1e-3, 1e-10));
    let roots = [0.5 - 0.5 / 2f64.sqrt(), 0.5 + 0.5 / 2f64.sqrt()];
    assert!(
        roots
            .iter()
            .any(|r| m.gap[0].at.lo <= *r && *r <= m.gap[0].at.hi),
        "{:?}",
        m.gap[0].at
    );
    let v = verdicts(
        &m,
        &Tolerances {
            length: 0.9e-7,
            ..Tolerances::default()
        },
        None,
    );
    assert!(matches!(v.g0, Verdict::Fails { .. }));
}

#[test]
fn the_work_budget_is_charged() {
    let points = (0..4)
        .map(|i| pt(q(i, 3), q(0, 1), q(i * (3 - i), G)))
        .collect();
    let edge = [ICurve::new(&RationalCurve::polynomial(points).unwrap()).unwrap()];
    let small = Limits {
        max_work: 10 * maximize::WORK_PER_PIECE,
        ..Limits::DEFAULT
    };
    let r = with_limits(small, || {
        measure_edge(
            &edge,
            &planes(),
            &Precision {
                rel: 1e-12,
                ..Precision::default()
            },
        )
    });
    assert!(matches!(r, Err(Error::Limit(_))), "{r:?}");
}

#[test]
fn non_3d_and_non_positive_weights_are_refused() {
    let flat =
        RationalCurve::polynomial(vec![vec![q(0, 1), q(0, 1)], vec![q(1, 1), q(0, 1)]]).unwrap();
    assert!(matches!(ICurve::new(&flat), Err(Error::Shape(_))));
    let hom = vec![
        crate::hpoint::HPoint {
            coords: vec![q(0, 1), q(0, 1), q(0, 1), q(1, 1)],
        },
        crate::hpoint::HPoint {
            coords: vec![q(0, 1), q(0, 1), q(0, 1), q(-1, 1)],
        },
    ];
    if let Ok(c) = RationalCurve::from_hom(hom) {
        assert!(matches!(ICurve::new(&c), Err(Error::Weight { .. })));
    }
}

/// `z` and `y` of the cubic with these control points at `t`, exactly (de
/// Casteljau in rationals, written out here).
fn cubic(ctrl: &[Q; 4], t: &Q) -> Q {
    let mut v = ctrl.to_vec();
    while v.len() > 1 {
        v = v.windows(2).map(|w| &w[0] + (&w[1] - &w[0]) * t).collect();
    }
    v.remove(0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// An edge cubic from (0,0,0) to (1,0,0) with its inner control points
    /// moved by up to 10⁻⁵ in y and z: the certified gaps to the floor and
    /// the tilted plane are at least the largest of 65 exact samples of the
    /// (closed-form) distances to the planes.
    #[test]
    fn gap_encloses_sampled_distances(d in proptest::collection::vec(-1000i64..=1000, 4)) {
        let e = |k: usize| q(d[k], 100_000_000);
        let ys = [q(0, 1), e(0), e(1), q(0, 1)];
        let zs = [q(0, 1), e(2), e(3), q(0, 1)];
        let points = (0..4).map(|i| pt(q(i as i64, 3), ys[i].clone(), zs[i].clone())).collect();
        let curve = RationalCurve::polynomial(points).unwrap();
        let m = measure_edge(&[ICurve::new(&curve).unwrap()], &planes(), &Precision::default()).unwrap().measures;
        let k = q(1, K);
        let one_plus_k2 = q(1, 1) + &k * &k;
        let (mut floor, mut tilted) = (Q::zero(), Q::zero());
        for i in 0..=64 {
            let t = q(i, 64);
            let (y, z) = (cubic(&ys, &t), cubic(&zs, &t));
            floor = floor.max(&z * &z);
            let s = &k * &y - &z;
            tilted = tilted.max(&s * &s / &one_plus_k2);
        }
        let sq = |x: f64| Q::from_f64(x).unwrap().pow(2);
        prop_assert!(floor <= sq(m.gap[0].hi), "{:?}", m.gap[0]);
        prop_assert!(tilted <= sq(m.gap[1].hi), "{:?}", m.gap[1]);
        prop_assert!(m.gap[0].lo <= m.gap[0].hi && m.gap[1].lo <= m.gap[1].hi);
    }
}
