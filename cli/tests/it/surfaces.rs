//! Property tests of rect patches on random exact inputs: reparameterizations
//! keep points at the mapped parameters, elevation and subdivision keep
//! points, standard forms have unit corners, joins are detected.

use crate::common::cli_json as cli;
use exact_bezier::strategy::*;
use exact_bezier::{algebra::*, curve::*, hpoint::*, prelude::*, rect::*, reparam::*};
use num_rational::BigRational;
use proptest::prelude::*;

type Q = BigRational;

fn q(p: i64, d: i64) -> Q {
    ratio(p, d)
}

fn one() -> Q {
    q(1, 1)
}

/// A random bidegree (1..=3, 1..=3) 3D patch.
fn any_rect() -> impl Strategy<Value = RectPatch<Q>> {
    (1usize..=3, 1usize..=3).prop_flat_map(|(m, n)| rect(m, n, 3))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn de_casteljau_orders_agree(p in any_rect(), u in unit_parameter(), v in unit_parameter()) {
        prop_assert_eq!(p.eval_hom_u_first(&u, &v), p.eval_hom(&u, &v));
    }

    #[test]
    fn mobius_keeps_points(p in any_rect(), a in open_unit_parameter(), b in open_unit_parameter(),
                           s in unit_parameter(), t in unit_parameter()) {
        let moved = p.mobius_u(&a).mobius_v(&b);
        let u = RationalCurve::mobius_param(&a, &s).unwrap();
        let v = RationalCurve::mobius_param(&b, &t).unwrap();
        prop_assert_eq!(moved.eval(&s, &t).unwrap(), p.eval(&u, &v).unwrap());
    }

    #[test]
    fn quadratic_reparam_keeps_points(p in any_rect(),
                                      a1 in open_unit_parameter(), a2 in open_unit_parameter(),
                                      b1 in open_unit_parameter(), b2 in open_unit_parameter(),
                                      s in unit_parameter(), t in unit_parameter()) {
        let map = Quadratic { alpha1: a1, alpha2: a2, beta1: b1, beta2: b2 };
        let r = p.quadratic_reparam(&map);
        let (m, n) = p.degree();
        prop_assert_eq!(r.degree(), (m + n, m + n));
        let (u, v) = map.param(&s, &t).unwrap();
        prop_assert!((Q::from_integer(0.into())..=one()).contains(&u));
        prop_assert!((Q::from_integer(0.into())..=one()).contains(&v));
        prop_assert_eq!(r.eval(&s, &t).unwrap(), p.eval(&u, &v).unwrap());
        prop_assert!(r.check_positive_weights().is_ok());
    }

    #[test]
    fn elevation_keeps_points(p in any_rect(), r in 0usize..=2, s in 0usize..=2,
                              u in unit_parameter(), v in unit_parameter()) {
        let e = p.elevate(r, s);
        let (m, n) = p.degree();
        prop_assert_eq!(e.degree(), (m + r, n + s));
        prop_assert_eq!(e.eval(&u, &v).unwrap(), p.eval(&u, &v).unwrap());
    }

    #[test]
    fn subdivision_keeps_points(p in any_rect(), c in open_unit_parameter(),
                                s in unit_parameter(), t in unit_parameter()) {
        let (lu, ru) = p.subdivide_u(&c);
        let (lv, rv) = p.subdivide_v(&c);
        let right = |x: &Q| c.clone() + x.clone() * (one() - &c);
        prop_assert_eq!(lu.eval(&s, &t).unwrap(), p.eval(&(s.clone() * &c), &t).unwrap());
        prop_assert_eq!(ru.eval(&s, &t).unwrap(), p.eval(&right(&s), &t).unwrap());
        prop_assert_eq!(lv.eval(&s, &t).unwrap(), p.eval(&s, &(t.clone() * &c)).unwrap());
        prop_assert_eq!(rv.eval(&s, &t).unwrap(), p.eval(&s, &right(&t)).unwrap());
    }

    #[test]
    fn subpatch_keeps_points(p in any_rect(), u0 in unit_parameter(), u1 in unit_parameter(),
                             v0 in unit_parameter(), v1 in unit_parameter(),
                             s in unit_parameter(), t in unit_parameter()) {
        let sub = p.subpatch(&u0, &u1, &v0, &v1);
        let u = u0.clone() + s.clone() * (u1.clone() - &u0);
        let v = v0.clone() + t.clone() * (v1.clone() - &v0);
        prop_assert_eq!(sub.eval(&s, &t).unwrap(), p.eval(&u, &v).unwrap());
    }

    #[test]
    fn iso_curves_and_boundaries(p in any_rect(), u in unit_parameter(), v in unit_parameter()) {
        prop_assert_eq!(p.iso_u(&u).eval(&v).unwrap(), p.eval(&u, &v).unwrap());
        prop_assert_eq!(p.iso_v(&v).eval(&u).unwrap(), p.eval(&u, &v).unwrap());
        prop_assert_eq!(p.boundary(Side::U1), p.iso_u(&one()));
        prop_assert_eq!(p.boundary(Side::V0), p.iso_v(&q(0, 1)));
    }

    #[test]
    fn normal_is_orthogonal_to_tangents(p in any_rect(), u in unit_parameter(), v in unit_parameter()) {
        let nrm = p.normal_hom(&u, &v).unwrap();
        let d = p.derivatives(1, 1, &u, &v).unwrap();
        for tangent in [&d[1][0], &d[0][1]] {
            let dot: Q = nrm.iter().zip(tangent.iter()).fold(q(0, 1), |a, (x, y)| a + x.clone() * y);
            prop_assert_eq!(dot, q(0, 1));
        }
    }

    /// Second derivatives against the closed form of the quotient rule:
    /// X'' = (N''D² − 2N'D'D − N D''D + 2N D'²)/D³ along u.
    #[test]
    fn second_derivative_closed_form(p in any_rect(), u in unit_parameter(), v in unit_parameter()) {
        let d = p.derivatives(2, 0, &u, &v).unwrap();
        let h: Vec<HPoint<Q>> = (0..=2).map(|a| p.derivative_hom(a, 0, &u, &v)).collect();
        let w: Vec<Q> = h.iter().map(|x| x.weight().clone()).collect();
        for (k, got) in d[2][0].iter().enumerate() {
            let n: Vec<Q> = h.iter().map(|x| x.coords[k].clone()).collect();
            let num = n[2].clone() * &w[0] * &w[0] - q(2, 1) * &n[1] * &w[1] * &w[0]
                - n[0].clone() * &w[2] * &w[0] + q(2, 1) * &n[0] * &w[1] * &w[1];
            prop_assert_eq!(got.clone(), num / (w[0].clone() * &w[0] * &w[0]));
        }
    }

    /// A standard form (corners 1) moved by random Möbius maps and a scale
    /// is standardized exactly back to unit corners, and its points are kept.
    #[test]
    fn linear_standardization_is_exact_and_unit(p in any_rect(), a in open_unit_parameter(),
                                                b in open_unit_parameter(), k in positive_weight(),
                                                s in unit_parameter(), t in unit_parameter()) {
        // Unit corners: Theorem 1 holds, and after the maps all roots are rational.
        let (m, n) = p.degree();
        let mut w = p.weights();
        for (i, j) in [(0, 0), (m, 0), (0, n), (m, n)] {
            w[i][j] = one();
        }
        let base = RectPatch::new(p.points().unwrap(), w).unwrap();
        let moved = base.mobius_u(&a).mobius_v(&b).scale_weights(&k);
        let st = standardize(&moved, Options { method: Method::Mobius, ..Options::default() }).unwrap();
        prop_assert_eq!(corner_weights(&st.patch), [one(), one(), one(), one()]);
        let StandardMap::Mobius { alpha, beta: Some(beta), .. } = st.map else { panic!("linear") };
        let u = RationalCurve::mobius_param(&alpha, &s).unwrap();
        let v = RationalCurve::mobius_param(&beta, &t).unwrap();
        prop_assert_eq!(st.patch.eval(&s, &t).unwrap(), moved.eval(&u, &v).unwrap());
    }

    /// Corner weights with rational (19) roots (the parametrization of the
    /// proofs): the quadratic standard form is exact with unit corners and
    /// keeps points at the mapped parameters.
    #[test]
    fn quadratic_standardization_is_exact_and_unit(p in any_rect(), a1 in open_unit_parameter(),
                                                   a2 in open_unit_parameter(), b in open_unit_parameter(),
                                                   z in positive_weight(), s in unit_parameter(),
                                                   t in unit_parameter()) {
        let (m, n) = p.degree();
        let (mu, nu) = (m as u32, n as u32);
        let c = |x: &Q| one() - x;
        let x = a1.pow_u32(mu) * &c(&a1).pow_u32(mu) * &c(&b).pow_u32(nu) * &z;
        let y = a2.pow_u32(mu) * &c(&a2).pow_u32(mu) * &b.pow_u32(nu) * &z;
        let corners = [c(&a2).pow_u32(mu) * &x, a2.pow_u32(mu) * &x, c(&a1).pow_u32(mu) * &y, a1.pow_u32(mu) * &y];
        let pts = p.points().unwrap();
        let mut w = p.weights();
        for (k, (i, j)) in [(0, 0), (m, 0), (0, n), (m, n)].into_iter().enumerate() {
            w[i][j] = corners[k].clone();
        }
        let patch = RectPatch::new(pts, w).unwrap();
        prop_assume!(!theorem1_holds(&patch, Tolerance::EXACT));
        let st = standardize(&patch, Options::default()).expect("all roots are rational by construction");
        prop_assert_eq!(corner_weights(&st.patch), [one(), one(), one(), one()]);
        let StandardMap::Quadratic { map, .. } = st.map else { panic!("quadratic") };
        prop_assert_eq!((&map.alpha1, &map.alpha2, &map.beta1), (&a1, &a2, &b));
        let (u, v) = map.param(&s, &t).unwrap();
        prop_assert_eq!(st.patch.eval(&s, &t).unwrap(), patch.eval(&u, &v).unwrap());
    }

    /// Any positive weights: exact, or (an irrational root) in f64 by the
    /// method the exact input selects, the corners come out 1.
    #[test]
    fn standardization_gives_unit_corners(p in any_rect()) {
        match standardize(&p, Options::default()) {
            Ok(st) => prop_assert_eq!(corner_weights(&st.patch), [one(), one(), one(), one()]),
            Err(Error::NotRational(_)) => {
                let method = if Options::default().linear(&p) { Method::Mobius } else { Method::Quadratic };
                let st = standardize(&p.map(Ordered::to_f64), Options { method, ..Options::default() }).unwrap();
                for w in corner_weights(&st.patch) {
                    prop_assert!((w - 1.0).abs() < 1e-9);
                }
            }
            Err(e) => panic!("{e}"),
        }
    }

    #[test]
    fn curve_standard_form_has_unit_ends(c in (1usize..=4).prop_flat_map(|n| curve(n, 2)),
                                         a in open_unit_parameter(), k in positive_weight()) {
        // Exact when built from a standard form by a rational Möbius map.
        let n = c.degree();
        if let Ok(st) = standardize(&c, Options::default()) {
            let w = st.patch.weights();
            prop_assert_eq!((&w[0], &w[n]), (&one(), &one()));
            let again = standardize(&st.patch.mobius(&a).scale_weights(&k), Options::default()).unwrap();
            prop_assert_eq!(again.patch, st.patch);
        } else {
            let st = standardize(&c.map(Ordered::to_f64), Options::default()).unwrap();
            let w = st.patch.weights();
            prop_assert!((w[0] - 1.0).abs() < 1e-9 && (w[n] - 1.0).abs() < 1e-9);
        }
    }

    /// Q continues P across u = 1 with Q_{1,j} = P_{m,j} + λ (P_{m,j} − P_{m−1,j}):
    /// a G¹ join; lifting one interior point of Q's first inner row off the
    /// tangent plane breaks it.
    #[test]
    fn g1_construction_is_detected(p in (1usize..=3, 1usize..=3).prop_flat_map(|(m, n)| rect(m, n, 3)),
                                   lambda in positive_weight(), rest in point(3)) {
        let (m, n) = p.degree();
        let pts = p.points().unwrap();
        let mut qp = vec![pts[m].clone()];
        qp.push((0..=n).map(|j| (0..3).map(|k| pts[m][j][k].clone() + lambda.clone() * (pts[m][j][k].clone() - &pts[m - 1][j][k])).collect()).collect());
        qp.push((0..=n).map(|_| rest.clone()).collect());
        let poly = RectPatch::polynomial(pts.clone()).unwrap();
        let partner = RectPatch::polynomial(qp.clone()).unwrap();
        prop_assert!(g0_join(&poly, &partner, Tolerance::EXACT));
        prop_assert!(g1_join(&poly, &partner, Tolerance::EXACT).unwrap());
        // Off the tangent plane: move Q_{1,0} along the normal at (1, 0).
        let nrm = poly.normal_hom(&one(), &q(0, 1)).unwrap();
        prop_assume!(nrm.iter().any(|x| *x != q(0, 1)));
        let mut bent = qp;
        for (x, dx) in bent[1][0].iter_mut().zip(&nrm) {
            *x = x.clone() + dx;
        }
        let bent = RectPatch::polynomial(bent).unwrap();
        prop_assert!(!g1_join(&poly, &bent, Tolerance::EXACT).unwrap());
    }
}

#[test]
fn g0_fails_for_a_different_boundary_and_dimensions_are_checked() {
    let p = |x: i64, y: i64| vec![q(x, 1), q(y, 1)];
    let a = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 1)], vec![p(1, 0), p(1, 1)]]).unwrap();
    let b = RectPatch::polynomial(vec![vec![p(1, 0), p(1, 2)], vec![p(2, 0), p(2, 1)]]).unwrap();
    assert!(!g0_join(&a, &b, Tolerance::EXACT));
    assert!(matches!(
        g1_join(&a, &a, Tolerance::EXACT),
        Err(Error::Shape(_))
    ));
    assert!(matches!(
        a.normal_hom(&q(0, 1), &q(0, 1)),
        Err(Error::Shape(_))
    ));
}

#[test]
fn g0_holds_for_a_reweighted_boundary() {
    // Same boundary curve with weights scaled by 2 on Q: equal as curves.
    let p = |x: i64, y: i64| vec![q(x, 1), q(y, 1)];
    let a = RectPatch::new(
        vec![vec![p(0, 0), p(0, 1)], vec![p(1, 0), p(1, 1)]],
        vec![vec![one(), one()], vec![q(1, 2), q(3, 1)]],
    )
    .unwrap();
    let b = RectPatch::new(
        vec![vec![p(1, 0), p(1, 1)], vec![p(2, 0), p(2, 1)]],
        vec![vec![one(), q(6, 1)], vec![one(), one()]],
    )
    .unwrap();
    assert!(g0_join(&a, &b, Tolerance::EXACT));
}

#[test]
fn theorem1_failure_names_the_condition() {
    let p = |x: i64| vec![q(x, 1)];
    let w = vec![vec![q(1, 1), q(2, 1)], vec![q(3, 1), q(5, 1)]];
    let patch = RectPatch::new(vec![vec![p(0), p(1)], vec![p(2), p(3)]], w).unwrap();
    let err = standardize(
        &patch,
        Options {
            method: Method::Mobius,
            ..Options::default()
        },
    )
    .unwrap_err();
    assert!(err.to_string().contains("Theorem 1 fails"), "{err}");
    let neg = RectPatch::new(
        vec![vec![p(0), p(1)], vec![p(2), p(3)]],
        vec![vec![q(1, 1), q(-2, 1)], vec![q(3, 1), q(5, 1)]],
    )
    .unwrap();
    assert!(matches!(
        standardize(&neg, Options::default()),
        Err(Error::Weight { .. })
    ));
}

#[test]
fn cli_standardize_example3_is_exact() {
    let (code, v) = cli(&["standardize", "tests/fixtures/yang_yong_example3.json"]);
    assert_eq!(code, 0);
    assert_eq!(v["exact"], true);
    let r = &v["reparameterization"];
    assert_eq!(
        (r["kind"].as_str(), r["alpha"].as_str(), r["beta"].as_str()),
        (Some("mobius"), Some("3/5"), Some("7/10"))
    );
    // k = 1/(1.44 · 0.6² · 0.7²) = 1/0.254016 = 15625/3969 (by hand).
    assert_eq!(r["k"].as_str(), Some("15625/3969"));
    // Standardized ω10 = 0.885 · 0.4/(1.44 · 0.6) = 59/144 (by hand).
    assert_eq!(v["patch"]["weights"][1][0].as_str(), Some("59/144"));
}

#[test]
fn cli_standardize_example2_is_quadratic_and_exact() {
    // The exact (6, 6) form needs radicals of one cubic field; it runs
    // under the default limits (issue 32: the sources' examples are never
    // refused).
    let f = "tests/fixtures/yang_yong_example2.json";
    let (code, v) = cli(&["standardize", f]);
    assert_eq!(code, 0);
    assert_eq!(v["exact"], true);
    assert_eq!(v["reparameterization"]["kind"], "quadratic");
    assert_eq!(v["patch"]["degree"], serde_json::json!([6, 6]));
    assert_eq!(v["patch"]["weights"][6][6], 1);
    let (code, v) = cli(&["standardize", "--compact", f]);
    assert_eq!(code, 0);
    assert_eq!(v["patch"]["degree"], serde_json::json!([3, 6]));
}

#[test]
fn cli_reparam_and_elevate_rects() {
    let f = "tests/fixtures/yang_yong_example1.json";
    let (code, v) = cli(&["reparam", f, "--quadratic", "1/2,1/3,1/4,1/5"]);
    assert_eq!(code, 0);
    assert_eq!(v["degree"], serde_json::json!([4, 4]));
    let (code, v) = cli(&["elevate", f, "--by", "1,2"]);
    assert_eq!(code, 0);
    assert_eq!(v["degree"], serde_json::json!([3, 4]));
    let (code, v) = cli(&["reparam", f, "--mobius", "1/2,1/3"]);
    assert_eq!(code, 0);
    // ω00 · α² β² = 8 · 1/4 · 1/9 = 2/9.
    assert_eq!(v["weights"][0][0].as_str(), Some("2/9"));
    assert_eq!(cli(&["reparam", f, "--quadratic", "1/2,1/3,1/4"]).0, 2);
    assert_eq!(cli(&["reparam", f, "--quadratic", "1/2,1/3,1/4,1"]).0, 2);
    assert_eq!(cli(&["reparam", f]).0, 2);
}
