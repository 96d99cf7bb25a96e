//! Unit tests of the analytic module: placement defaults and errors,
//! polylines, extrusion ranges, trimming errors.

use super::*;
use crate::algebra::RealAlgebraic;
use crate::error::Error;
use crate::ratio;
use num_rational::BigRational;

type Q = BigRational;

fn q(n: i64) -> Q {
    ratio(n, 1)
}

#[test]
fn placement_defaults_follow_iso() {
    let o = [q(0), q(0), q(0)];
    // No axis: z = (0, 0, 1); no ref_direction: x = (1, 0, 0).
    let f = Frame::from_placement(&o, None, None).unwrap();
    assert_eq!(
        (f.x.clone(), f.z.clone()),
        (vec![q(1), q(0), q(0)], vec![q(0), q(0), q(1)])
    );
    // An axis along x: the default ref_direction is (0, 1, 0).
    let f = Frame::from_placement(&o, Some(&[q(-2), q(0), q(0)]), None).unwrap();
    assert_eq!(f.x, vec![q(0), q(1), q(0)]);
    assert_eq!(f.z, vec![q(-1), q(0), q(0)]);
    assert_eq!(f.y, vec![q(0), q(0), q(-1)]);
}

#[test]
fn bad_placements_are_typed_errors() {
    let o = [q(0), q(0), q(0)];
    let z = [q(0), q(0), q(3)];
    assert!(matches!(
        Frame::from_placement(&o, Some(&z), Some(&[q(0), q(0), q(-1)])),
        Err(Error::Domain(_))
    ));
    assert!(matches!(
        Frame::from_placement(&o, Some(&[q(0), q(0), q(0)]), None),
        Err(Error::Domain(_))
    ));
    assert!(matches!(
        Frame::from_placement(&o, Some(&[q(1), q(1), q(0)]), None),
        Err(Error::NotRational(_))
    ));
    assert!(matches!(
        Frame::from_placement(&o[..2], None, None),
        Err(Error::Shape(_))
    ));
    // The same irrational axis is exact over the real algebraic numbers.
    let r = |n: i64| RealAlgebraic::from_i64(n);
    let f = Frame::from_placement(&[r(0), r(0), r(0)], Some(&[r(1), r(1), r(0)]), None).unwrap();
    assert_eq!(f.z[0].clone() * &f.z[0], RealAlgebraic::from_i64(1) / r(2));
}

#[test]
fn polyline_piece_k_at_t_is_u_k_plus_t() {
    let pts = vec![vec![q(0), q(0)], vec![q(2), q(0)], vec![q(2), q(4)]];
    let c = polyline(&pts);
    assert_eq!(c.len(), 2);
    assert_eq!(c[1].eval(&ratio(1, 4)).unwrap(), vec![q(2), q(1)]);
    assert!(polyline(&pts[..1]).is_empty());
}

#[test]
fn extrusion_range_covers_offset_points() {
    // The segment (0,0,0)–(1,0,0) extruded along V = (0, 0, 2): a point at
    // height 5 is at v = 5/2, whatever its x.
    let seg = vec![line_segment(
        &[q(0), q(0), q(0)],
        &[q(1), q(0), q(0)],
        &q(0),
        &q(1),
    )];
    let v = [q(0), q(0), q(2)];
    let pts = vec![vec![ratio(1, 2), q(0), q(5)], vec![q(1), q(0), q(-1)]];
    let r = covering_range(
        &Unbounded::Extrusion {
            curve: &seg,
            vector: &v,
        },
        &pts,
    )
    .unwrap();
    assert_eq!(r, vec![[ratio(-1, 2), ratio(5, 2)]]);
    let s = extrusion(&seg, &v, [&r[0][0], &r[0][1]]).unwrap();
    assert_eq!(s[0].eval(&ratio(1, 2), &q(1)).unwrap(), pts[0]);
}

#[test]
fn trimming_an_open_curve_backwards_is_refused() {
    let pts = vec![vec![q(0), q(0)], vec![q(2), q(0)], vec![q(2), q(4)]];
    let c = polyline(&pts);
    let e = trim_between(&c, &pts[2], &pts[0], true, 0.0);
    assert!(matches!(e, Err(Error::Domain(_))));
    // Against the curve's sense it is the polyline reversed.
    let t = trim_between(&c, &pts[2], &pts[0], false, 0.0).unwrap();
    assert_eq!(t.pieces, vec![c[1].reverse(), c[0].reverse()]);
    assert!(matches!(
        trim_between::<Q>(&[], &pts[0], &pts[1], true, 0.0),
        Err(Error::Shape(_))
    ));
}

#[test]
fn degree_decimals_in_exponent_form_are_recognised() {
    let s = cone_slope::<RealAlgebraic>("4.5E1", &AngleUnit::Degree).unwrap();
    assert!(s.exact);
    // 59° is no multiple of 15°.
    assert!(
        !cone_slope::<RealAlgebraic>("59.", &AngleUnit::Degree)
            .unwrap()
            .exact
    );
    // Over Q there is no √3: 30° is approximate there, and says so.
    let s = cone_slope::<Q>("30.", &AngleUnit::Degree).unwrap();
    assert!(!s.exact && s.error > q(0));
}

#[test]
fn a_prefixed_radian_scales_the_semi_angle_and_its_rounding() {
    // 523.598775598299 mrad is π/6 to the printed digits: tan = √3/3.
    let milli = AngleUnit::Radian(q(1) / q(1000));
    let s = cone_slope::<RealAlgebraic>("523.598775598299", &milli).unwrap();
    assert!(s.exact);
    let three = RealAlgebraic::from_i64(3);
    assert_eq!(s.tan.clone() * &s.tan * &three, RealAlgebraic::from_i64(1));
    // 0.5000 rad is not π/6 to its digits (|π/6 − 0.5| > 5·10⁻⁵): taken
    // as written, enclosed, approximate.
    let s = cone_slope::<RealAlgebraic>("0.5000", &AngleUnit::radian()).unwrap();
    assert!(!s.exact);
    // A unit of 2 rad (Other): 0.25 units are 0.5 rad; tan 0.5 = 0.5463…
    let s = cone_slope::<Q>("0.25", &AngleUnit::Other("HALF_TURNISH".into(), q(2))).unwrap();
    assert!(!s.exact);
    assert!((crate::Ordered::to_f64(&s.tan) - 0.5f64.tan()).abs() < 1e-15);
}

#[test]
fn a_remembered_semi_angle_keeps_each_scalars_rule() {
    // 30° asked over Q(√3)'s real algebraic numbers, then over Q, then
    // again: the remembered answer is exact where √3 exists and an
    // enclosure of tan 30° = √3/3 where it does not, every time.
    for _ in 0..2 {
        let s = cone_slope::<RealAlgebraic>("30.", &AngleUnit::Degree).unwrap();
        assert!(s.exact);
        let three = RealAlgebraic::from_i64(3);
        assert_eq!(s.tan.clone() * &s.tan * &three, RealAlgebraic::from_i64(1));
        let a = cone_slope::<Q>("30.", &AngleUnit::Degree).unwrap();
        assert!(!a.exact && a.error > q(0) && a.error < q(1) / q(1 << 60));
        let (lo, hi) = (a.tan.clone() - &a.error, a.tan.clone() + &a.error);
        assert!(lo.clone() * &lo * q(3) <= q(1) && q(1) <= hi.clone() * &hi * q(3));
    }
    // An angle out of range is refused each time it is asked (errors are
    // not remembered as answers).
    for _ in 0..2 {
        assert!(matches!(
            cone_slope::<Q>("90.", &AngleUnit::Degree),
            Err(Error::Domain(_))
        ));
    }
}

mod covering_range_filter {
    use super::*;
    use crate::algebra::scalar::{Roots, Scalar};
    use proptest::prelude::*;

    /// `a + b·√2 + c·√3` from small integers (ties come often).
    fn radical(a: i64, b: i64, c: i64) -> RealAlgebraic {
        let r = |n: i64| RealAlgebraic::from_i64(n).nth_root(2).unwrap();
        RealAlgebraic::from_i64(a)
            + &(RealAlgebraic::from_i64(b) * &r(2))
            + &(RealAlgebraic::from_i64(c) * &r(3))
    }

    /// The exact min and max over every point, compared one by one.
    fn every_point(points: &[Vec<RealAlgebraic>], f: &Frame<RealAlgebraic>) -> [RealAlgebraic; 2] {
        let v: Vec<RealAlgebraic> = points.iter().map(|p| f.coords(p)[2].clone()).collect();
        let mut lo = v[0].clone();
        let mut hi = v[0].clone();
        for x in &v {
            if *x < lo {
                lo = x.clone();
            }
            if *x > hi {
                hi = x.clone();
            }
        }
        [lo, hi]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// The range found by enclosing the projections first is the exact
        /// range over every point, on a frame whose axes are radicals.
        #[test]
        fn the_filtered_range_is_the_exact_range(
            coords in proptest::collection::vec((-3i64..4, -2i64..3, -2i64..3), 3..24),
            axis in (1i64..4, -2i64..3, 1i64..3),
        ) {
            let points: Vec<Vec<RealAlgebraic>> = coords
                .chunks(3)
                .filter(|c| c.len() == 3)
                .map(|c| c.iter().map(|&(a, b, k)| radical(a, b, k)).collect())
                .collect();
            prop_assume!(!points.is_empty());
            let z: Vec<RealAlgebraic> = [axis.0, axis.1, axis.2].iter().map(|&n| RealAlgebraic::from_i64(n)).collect();
            let o = vec![radical(1, 1, 0), RealAlgebraic::from_i64(0), radical(0, 0, 1)];
            let f = Frame::from_placement(&o, Some(&z), None).unwrap();
            let [lo, hi] = every_point(&points, &f);
            let r = covering_range(&Unbounded::Axial(&f), &points).unwrap();
            if lo == hi {
                prop_assert_eq!(&r[0][0], &(lo.clone() - &RealAlgebraic::from_i64(1)));
                prop_assert_eq!(&r[0][1], &(hi + &RealAlgebraic::from_i64(1)));
            } else {
                prop_assert_eq!(&r[0][0], &lo);
                prop_assert_eq!(&r[0][1], &hi);
            }
        }
    }
}
