use super::*;
use crate::algebra::Ordered;
use crate::{ratio, Error};
use proptest::prelude::*;

type Q = BigRational;

fn q(n: i64, d: i64) -> Q {
    ratio(n, d)
}

fn hp(x: i64, y: i64, w: Q) -> HPoint<Q> {
    HPoint::from_point(&[q(x, 1), q(y, 1)], &w)
}

/// Every piece at local t equals de Boor at u = a + (b − a)t, projectively
/// (both are homogeneous; the piece's weights come from the same net, so the
/// homogeneous points are equal, not merely proportional).
fn check_curve(c: &NurbsCurve<Q>) {
    let spans = c.knots().spans();
    let pieces = c.bezier_pieces();
    assert_eq!(pieces.len(), spans.len());
    for (k, piece) in spans.into_iter().zip(&pieces) {
        let [a, b] = &piece.span;
        for t in [q(0, 1), q(1, 3), q(1, 2), q(5, 7), q(1, 1)] {
            let u = a + (b - a) * &t;
            assert_eq!(piece.curve.eval_hom(&t), c.eval_hom_in_span(k, &u));
        }
    }
}

#[test]
fn clamped_nonuniform_rational_cubic_with_a_double_knot() {
    let k: Vec<Q> = [0, 0, 0, 0, 1, 3, 3, 4, 4, 4, 4]
        .iter()
        .map(|&x| q(x, 1))
        .collect();
    let w = [1, 2, 1, 3, 1, 1, 2];
    let pts = (0..7)
        .map(|i| hp(i, (i * i) % 5, q(w[i as usize], 1)))
        .collect();
    let c = NurbsCurve::new(Knots::new(3, k, 7).unwrap(), pts).unwrap();
    assert_eq!(c.knots().spans(), vec![3, 4, 6]);
    check_curve(&c);
}

#[test]
fn unclamped_uniform_quadratic() {
    let k: Vec<Q> = (0..9).map(|x| q(x, 2)).collect();
    let pts = (0..6).map(|i| hp(i, 3 - i, q(i + 1, 3))).collect();
    let c = NurbsCurve::new(Knots::new(2, k, 6).unwrap(), pts).unwrap();
    check_curve(&c);
    // Uniform quadratic B-spline: the piece's ends are the leg midpoints.
    let first = &c.bezier_pieces()[0].curve;
    assert_eq!(first.degree(), 2);
}

#[test]
fn a_bezier_curve_is_its_own_single_piece() {
    let pts: Vec<HPoint<Q>> = (0..4).map(|i| hp(i, i * i, q(i + 1, 2))).collect();
    let c = NurbsCurve::new(Knots::bezier(3).unwrap(), pts.clone()).unwrap();
    let p = c.bezier_pieces();
    assert_eq!(p.len(), 1);
    assert_eq!(p[0].curve.ctrl(), &pts[..]);
}

#[test]
fn pieces_meet_c2_across_a_simple_knot_of_a_cubic() {
    // Consecutive pieces of a cubic with simple knots are C²: the second
    // differences at the join match (uniform spans of equal length).
    let k: Vec<Q> = [0, 0, 0, 0, 1, 2, 2, 2, 2]
        .iter()
        .map(|&x| q(x, 1))
        .collect();
    let pts = (0..5).map(|i| hp(i * 3, (i * 7) % 4, q(1, 1))).collect();
    let c = NurbsCurve::new(Knots::new(3, k, 5).unwrap(), pts).unwrap();
    let p = c.bezier_pieces();
    let (l, r) = (p[0].curve.points().unwrap(), p[1].curve.points().unwrap());
    let d = |a: &[Q], b: &[Q]| a.iter().zip(b).map(|(x, y)| x - y).collect::<Vec<_>>();
    assert_eq!(l[3], r[0]);
    assert_eq!(d(&l[3], &l[2]), d(&r[1], &r[0]));
    let second = |a: &[Vec<Q>], i: usize| d(&d(&a[i + 2], &a[i + 1]), &d(&a[i + 1], &a[i]));
    assert_eq!(second(&l, 1), second(&r, 0));
}

#[test]
fn surface_pieces_reproduce_de_boor() {
    let s = wavy();
    let pieces = s.bezier_pieces();
    assert_eq!(pieces.len(), 2 * 3);
    let (u, v) = s.knots();
    let spans: Vec<(usize, usize)> = u
        .spans()
        .into_iter()
        .flat_map(|k| v.spans().into_iter().map(move |l| (k, l)))
        .collect();
    for (piece, kl) in pieces.iter().zip(spans) {
        for (a, b) in [(q(0, 1), q(1, 1)), (q(1, 3), q(2, 5)), (q(1, 1), q(1, 2))] {
            let uu = &piece.u[0] + (&piece.u[1] - &piece.u[0]) * &a;
            let vv = &piece.v[0] + (&piece.v[1] - &piece.v[0]) * &b;
            assert_eq!(
                piece.patch.eval_hom(&a, &b),
                s.eval_hom_in_span(kl, &uu, &vv)
            );
        }
    }
}

/// A wavy rational biquadratic: knots (0, 0, 0, 1, 2, 2, 2) × (0, …, 7),
/// points `(i, j, ij mod 3)`, weights 1 and 2 alternating.
fn wavy() -> NurbsSurface<Q> {
    let ku: Vec<Q> = [0, 0, 0, 1, 2, 2, 2].iter().map(|&x| q(x, 1)).collect();
    let kv: Vec<Q> = (0..8).map(|x| q(x, 1)).collect();
    let net = (0..4)
        .map(|i| {
            (0..5)
                .map(|j| {
                    HPoint::from_point(&[q(i, 1), q(j, 1), q(i * j % 3, 1)], &q(1 + (i + j) % 2, 1))
                })
                .collect()
        })
        .collect();
    NurbsSurface::new(
        Knots::new(2, ku, 4).unwrap(),
        Knots::new(2, kv, 5).unwrap(),
        net,
    )
    .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    /// Point inversion finds the knot parameters of a point of the surface
    /// (evaluated exactly by de Boor in its span) to 10⁻⁹.
    #[test]
    fn inversion_finds_the_parameters_of_a_surface_point(a in 0i64..=40, b in 0i64..=60) {
        let s = wavy();
        let (u, v) = (q(a, 20), q(2, 1) + q(b, 20));
        let (ku, kv) = s.knots();
        let span = |k: &Knots, x: &Q| k.spans().into_iter().find(|&i| &k.knots()[i + 1] >= x).unwrap();
        let p = s.eval_hom_in_span((span(ku, &u), span(kv, &v)), &u, &v).project().unwrap();
        let p: Vec<f64> = p.iter().map(Ordered::to_f64).collect();
        let (uv, d) = nearest_parameters(&Nurbs::Surface(s).pieces(), &p).unwrap();
        prop_assert!(d < 1e-9, "{d}");
        prop_assert!((uv[0] - Ordered::to_f64(&u)).abs() < 1e-7 && (uv[1] - Ordered::to_f64(&v)).abs() < 1e-7, "{uv:?}");
    }
}

#[test]
fn bad_knots_are_typed_errors() {
    let k = |v: &[i64]| v.iter().map(|&x| q(x, 1)).collect::<Vec<Q>>();
    assert!(matches!(
        Knots::new(2, k(&[0, 0, 0, 1, 1]), 3),
        Err(Error::Shape(_))
    ));
    assert!(matches!(
        Knots::new(2, k(&[0, 0, 1, 0, 1, 1]), 3),
        Err(Error::Shape(_))
    ));
    assert!(matches!(
        Knots::new(2, k(&[0, 0, 0, 0, 0, 0]), 3),
        Err(Error::Shape(_))
    ));
    assert!(matches!(Knots::new(0, k(&[0, 1]), 1), Err(Error::Shape(_))));
    assert!(matches!(
        Knots::new(99, k(&[0, 1]), 1),
        Err(Error::DegreeTooHigh { .. })
    ));
    assert!(Knots::from_multiplicities(2, &k(&[0, 1]), &[3, 2], 3).is_err());
    assert_eq!(
        Knots::from_multiplicities(2, &k(&[0, 1]), &[3, 3], 3).unwrap(),
        Knots::bezier(2).unwrap()
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]
    /// Random degree, knot gaps (zero gaps give multiplicities), points and
    /// weights: every piece agrees with de Boor.
    #[test]
    fn pieces_agree_with_de_boor(p in 1usize..4, extra in 0usize..4,
                                 gaps in proptest::collection::vec(0i64..3, 12),
                                 coords in proptest::collection::vec(-9i64..10, 8),
                                 ws in proptest::collection::vec(1i64..5, 8)) {
        let count = p + 1 + extra;
        let mut knots = vec![q(0, 1)];
        for g in gaps.iter().take(count + p) {
            let last = knots[knots.len() - 1].clone();
            knots.push(last + q(*g, 2));
        }
        prop_assume!(knots[p] < knots[count]);
        let pts = (0..count).map(|i| hp(coords[i], coords[(i + 3) % 8], q(ws[i], 1))).collect();
        let c = NurbsCurve::new(Knots::new(p, knots, count).unwrap(), pts).unwrap();
        check_curve(&c);
    }
}
