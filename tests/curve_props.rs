//! Property tests of the curve core on random exact curves.

use exact_bezier::hpoint::HPoint;
use exact_bezier::strategy::{curve, open_unit_parameter, rect, tri, unit_parameter};
use exact_bezier::{ratio, RationalCurve};
use num_rational::BigRational;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn mobius_keeps_points(c in curve(4, 2), alpha in open_unit_parameter(), s in unit_parameter()) {
        let u = RationalCurve::mobius_param(&alpha, &s).unwrap();
        prop_assert_eq!(c.mobius(&alpha).eval(&s).unwrap(), c.eval(&u).unwrap());
    }

    #[test]
    fn elevation_keeps_points(c in curve(3, 3), r in 0usize..4, t in unit_parameter()) {
        prop_assert_eq!(c.elevate(r).eval(&t).unwrap(), c.eval(&t).unwrap());
    }

    /// `elevate(r)` (all `r` steps in one sum each) gives the control
    /// points of source 001's single step
    /// `P*_i = (i/(n+1)) P_{i−1} + (1 − i/(n+1)) P_i`, written out here,
    /// applied `r` times.
    #[test]
    fn elevation_is_the_single_step_repeated(c in curve(5, 3), r in 0usize..6) {
        let step = |p: Vec<HPoint<BigRational>>| -> Vec<HPoint<BigRational>> {
            let n = p.len() - 1;
            (0..=n + 1)
                .map(|i| {
                    let a = ratio::<BigRational>(i as i64, n as i64 + 1);
                    let b = ratio::<BigRational>(1, 1) - &a;
                    let (left, right) = (&p[i.saturating_sub(1)], &p[i.min(n)]);
                    HPoint {
                        coords: left.coords.iter().zip(&right.coords).map(|(x, y)| x * &a + y * &b).collect(),
                    }
                })
                .collect()
        };
        let repeated = (0..r).fold(c.ctrl().to_vec(), |p, _| step(p));
        let elevated = c.elevate(r);
        prop_assert_eq!(elevated.ctrl(), &repeated[..]);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// `eval` (Horner–Bernstein, fraction-free on integers for
    /// `BigRational`) agrees exactly with de Casteljau on rationals (a
    /// second method), for curves and patches.
    #[test]
    fn fast_evaluation_is_exact(c in curve(5, 3), r in rect(3, 2, 3), s in tri(4, 3), t in unit_parameter(), u in unit_parameter()) {
        prop_assert_eq!(c.eval(&t).unwrap(), c.eval_hom(&t).project().unwrap());
        prop_assert_eq!(r.eval(&t, &u).unwrap(), r.eval_hom(&t, &u).project().unwrap());
        // Any (u, v), inside the triangle or not: both sides are the same polynomial map.
        prop_assert_eq!(s.eval(&t, &u), s.eval_hom(&t, &u).project());
    }
}
