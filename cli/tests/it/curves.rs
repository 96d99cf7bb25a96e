//! Property tests of curve derivatives, geometry, joins and degree
//! reduction on random exact curves (positive rational weights).

use exact_bezier::strategy::{
    curve, open_unit_parameter, positive_weight, small_rational, unit_parameter,
};
use exact_bezier::{
    curve::g2_leading_points, curve::join, curve::ConicType, curve::CurveEnd, curve::Reduction,
    RationalCurve, Tolerance,
};
use num_rational::BigRational;
use num_traits::{One, Zero};
use proptest::prelude::*;

type Q = BigRational;

/// A random curve of degree 1…5 in 2D.
fn any_curve() -> impl Strategy<Value = RationalCurve<Q>> {
    (1usize..=5).prop_flat_map(|n| curve(n, 2))
}

fn close(a: &[f64], b: &[Q], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| {
        let y = exact_bezier::algebra::rational_to_f64(y);
        (x - y).abs() <= tol * (1.0 + y.abs())
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn mobius_keeps_points_at_mapped_parameters(c in any_curve(), alpha in open_unit_parameter(), s in unit_parameter()) {
        let u = RationalCurve::mobius_param(&alpha, &s).unwrap();
        prop_assert_eq!(c.mobius(&alpha).eval(&s).unwrap(), c.eval(&u).unwrap());
    }

    #[test]
    fn subdivision_keeps_points(c in any_curve(), tau in open_unit_parameter(), s in unit_parameter()) {
        let (l, r) = c.subdivide(&tau);
        prop_assert_eq!(l.eval(&s).unwrap(), c.eval(&(tau.clone() * &s)).unwrap());
        let u = tau.clone() + s.clone() * (Q::one() - &tau);
        prop_assert_eq!(r.eval(&s).unwrap(), c.eval(&u).unwrap());
    }

    #[test]
    fn elevation_keeps_points_and_derivatives(c in any_curve(), r in 1usize..3, t in unit_parameter()) {
        let e = c.elevate(r);
        prop_assert_eq!(e.derivs(&t, 2).unwrap(), c.derivs(&t, 2).unwrap());
    }

    #[test]
    fn invariants_unchanged(c in (2usize..=6).prop_flat_map(|n| curve(n, 2)), alpha in open_unit_parameter(), k in positive_weight()) {
        let inv = c.mobius_invariants().unwrap();
        let loc = c.local_invariants().unwrap();
        for moved in [c.mobius(&alpha), c.scale_weights(&k)] {
            prop_assert_eq!(moved.mobius_invariants().unwrap(), inv.clone());
            prop_assert_eq!(moved.local_invariants().unwrap(), loc.clone());
        }
    }

    #[test]
    fn conic_type_is_mobius_invariant(c in curve(2, 2), alpha in open_unit_parameter()) {
        prop_assert_eq!(c.mobius(&alpha).conic_type().unwrap(), c.conic_type().unwrap());
    }

    #[test]
    fn chain_rule_on_subdivided_piece(c in any_curve(), tau in open_unit_parameter(), s in unit_parameter()) {
        // left(s) = X(τ s), so left'(s) = τ X'(τ s) and left''(s) = τ² X''(τ s).
        let (l, _) = c.subdivide(&tau);
        let dl = l.derivs(&s, 2).unwrap();
        let dx = c.derivs(&(tau.clone() * &s), 2).unwrap();
        let scaled = |v: &[Q], k: &Q| v.iter().map(|x| x.clone() * k).collect::<Vec<_>>();
        prop_assert_eq!(&dl[1], &scaled(&dx[1], &tau));
        prop_assert_eq!(&dl[2], &scaled(&dx[2], &(tau.clone() * &tau)));
    }

    #[test]
    fn end_curvature_matches_derivatives(c in (2usize..=5).prop_flat_map(|n| curve(n, 3))) {
        for (end, t) in [(CurveEnd::Start, Q::zero()), (CurveEnd::Finish, Q::one())] {
            match (c.end_curvature_sq(end), c.curvature_sq(&t)) {
                (Ok(a), Ok(b)) => prop_assert_eq!(a, b),
                (a, b) => prop_assert!(a.is_err() && b.is_err()),
            }
        }
    }

    #[test]
    fn f64_agrees_with_exact(c in any_curve(), t in unit_parameter()) {
        let f = c.map(exact_bezier::algebra::rational_to_f64);
        let tf = exact_bezier::algebra::rational_to_f64(&t);
        let (de, df) = (c.derivs(&t, 2).unwrap(), f.derivs(&tf, 2).unwrap());
        for (a, b) in df.iter().zip(&de) {
            prop_assert!(close(a, b, 1e-6), "{:?} vs {:?}", a, b);
        }
        if let (Ok(ke), Ok(kf)) = (c.curvature_sq(&t), f.curvature_sq(&tf)) {
            prop_assert!(close(&[kf], &[ke], 1e-6));
        }
    }

    #[test]
    fn reduction_inverts_elevation(c in any_curve()) {
        let e = c.elevate(1);
        prop_assert_eq!(e.reduce(Reduction::Forrest).unwrap(), c.clone());
        prop_assert_eq!(e.reduce(Reduction::LeastSquares).unwrap(), c.clone());
        prop_assert_eq!(e.reduce_exact(Tolerance::EXACT), Some(c.clone()));
        prop_assert_eq!(e.elevate(2).reduce_exact_fully(Tolerance::EXACT), c.reduce_exact_fully(Tolerance::EXACT));
        if e.degree() >= 2 {
            prop_assert_eq!(e.reduce(Reduction::Farin).unwrap(), c);
        }
    }

    #[test]
    fn least_squares_beats_any_feasible_perturbation(c in (1usize..=5).prop_flat_map(|n| curve(n, 2)), j in 0usize..6, k in small_rational()) {
        // A feasible competitor: move all of D onto one control point j,
        // plus a null-space change along e_0·a_1 − e_1·a_0 scaled by k.
        let n = c.degree();
        let j = j % (n + 1);
        let eps = c.lsq_perturbation().unwrap();
        let d = c.degeneracy();
        let a = |i: usize| {
            let b = Q::from_integer(exact_bezier::algebra::binomial(n, i));
            if i % 2 == 1 { -b } else { b }
        };
        let mut other: Vec<_> = (0..=n).map(|_| exact_bezier::hpoint::HPoint::<Q>::zero(2)).collect();
        other[j] = d.scale(&(-a(j).recip()));
        let tweak = exact_bezier::hpoint::HPoint { coords: vec![k.clone(), Q::zero(), Q::zero()] };
        other[0] = other[0].add(&tweak.scale(&a(1)));
        other[1] = other[1].sub(&tweak.scale(&a(0)));
        let cost = |e: &[exact_bezier::hpoint::HPoint<Q>]| e.iter().flat_map(|h| h.coords.iter().map(|x| x.clone() * x)).fold(Q::zero(), |s, x| s + x);
        let moved: Vec<_> = c.ctrl().iter().zip(&other).map(|(p, e)| p.add(e)).collect();
        prop_assert!(RationalCurve::from_hom(moved).unwrap().degeneracy().is_zero_within(Tolerance::EXACT));
        prop_assert!(cost(&eps) <= cost(&other));
    }

    #[test]
    fn corrected_g2_points_join_g2(p in (2usize..=4).prop_flat_map(|n| curve(n, 2)), m in 2usize..=4, alpha in positive_weight(), beta in small_rational(), rest in proptest::collection::vec(exact_bezier::strategy::point(2), 3)) {
        let poly = RationalCurve::polynomial(p.points().unwrap()).unwrap();
        let pts = poly.points().unwrap();
        let [q0, q1, q2] = g2_leading_points(&pts, m, &alpha, &beta).unwrap();
        let mut q = vec![q0, q1, q2];
        q.extend(rest.into_iter().take(m - 2));
        let qc = RationalCurve::polynomial(q).unwrap();
        let j = join(&poly, &qc, Tolerance::EXACT).unwrap();
        if j.alpha.is_some() {
            prop_assert!(j.g2, "{}", j.reason);
            prop_assert_eq!(j.alpha, Some(alpha));
            prop_assert_eq!(j.beta, Some(beta));
        }
    }

    #[test]
    fn affine_image_of_points(c in any_curve(), t in unit_parameter(), m in proptest::collection::vec(small_rational(), 6)) {
        let a = vec![vec![m[0].clone(), m[1].clone()], vec![m[2].clone(), m[3].clone()]];
        let b = vec![m[4].clone(), m[5].clone()];
        let x = c.eval(&t).unwrap();
        let want: Vec<Q> = (0..2).map(|r| a[r][0].clone() * &x[0] + a[r][1].clone() * &x[1] + &b[r]).collect();
        prop_assert_eq!(c.affine(&a, &b).unwrap().eval(&t).unwrap(), want);
    }
}

#[test]
fn conic_types_of_known_arcs() {
    let q = |x: i64| Q::from_integer(x.into());
    let pts = vec![vec![q(1), q(0)], vec![q(1), q(1)], vec![q(0), q(1)]];
    let conic = |w: [i64; 3]| {
        RationalCurve::new(pts.clone(), w.iter().map(|&x| q(x)).collect())
            .unwrap()
            .conic_type()
            .unwrap()
    };
    // w1²/(w0 w2) = 1/2 is the circle, 1 the parabola, 2 a hyperbola.
    assert_eq!(conic([1, 1, 2]), ConicType::Ellipse);
    assert_eq!(conic([1, 1, 1]), ConicType::Parabola);
    assert_eq!(conic([1, 2, 2]), ConicType::Hyperbola);
}

/// `curvature` is exact (issue 14): on an arc of a circle of radius 5/3
/// (control points (5/3)·(1, 0), (5/3)·(1, 1), (5/3)·(0, 1), weights 1, 1,
/// 2, which is the quarter circle since w₁/√(w₀w₂) = cos 45°) κ is 3/5 at
/// every t; elsewhere κ is irrational and its text squares to κ².
#[test]
fn curvature_is_exact() {
    use crate::common::cli_json;
    use exact_bezier::algebra::{parse_algebraic, RealAlgebraic};
    let dir = std::env::temp_dir().join(format!("exact-bezier-kappa-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let arc = dir.join("arc.json");
    std::fs::write(
        &arc,
        r#"{"kind":"curve","degree":2,"points":[["5/3",0],["5/3","5/3"],[0,"5/3"]],"weights":[1,1,2]}"#,
    )
    .unwrap();
    for t in ["0", "1/7", "1/2", "0.9", "1"] {
        let (code, v) = cli_json(&["curvature", arc.to_str().unwrap(), "--at", t]);
        assert_eq!(code, 0);
        assert_eq!(v["curvature"], "3/5", "t = {t}");
        assert_eq!(v["curvature_squared"], "9/25");
    }
    let (code, v) = cli_json(&["curvature", "docs/examples/curve.json", "--at", "1/3"]);
    assert_eq!(code, 0);
    let kappa: RealAlgebraic = parse_algebraic(v["curvature"].as_str().unwrap()).unwrap();
    assert!(kappa.as_rational().is_none(), "κ is irrational here");
    let k2: RealAlgebraic = parse_algebraic(v["curvature_squared"].as_str().unwrap()).unwrap();
    assert_eq!(kappa.clone() * &kappa, k2);
    assert!(kappa > <RealAlgebraic as exact_bezier::Scalar>::from_i64(0));
    let approx = v["curvature_approx"].as_f64().unwrap();
    assert!((approx - exact_bezier::Ordered::to_f64(&kappa)).abs() < 1e-12);
    let _ = std::fs::remove_dir_all(&dir);
}
