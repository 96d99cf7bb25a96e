//! Property tests of the curve core on random exact curves.

use exact_bezier::strategy::{curve, open_unit_parameter, unit_parameter};
use exact_bezier::RationalCurve;
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
}
