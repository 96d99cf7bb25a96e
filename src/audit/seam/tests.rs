use super::*;
use crate::nurbs::{Knots, NurbsSurface};
use crate::ratio;

fn q(n: i64, d: i64) -> Q {
    ratio(n, d)
}

/// The two Bézier pieces of a bicubic (rational if `rational`) B-spline
/// surface with an inner knot 1 of multiplicity `mult` in u.
fn split(mult: usize, rational: bool) -> (RectPatch<Q>, RectPatch<Q>) {
    let mut ku = vec![q(0, 1); 4];
    ku.extend(std::iter::repeat_n(q(1, 1), mult));
    ku.extend(vec![q(2, 1); 4]);
    let cu = 4 + mult;
    let net = (0..cu as i64)
        .map(|i| {
            (0..4)
                .map(|j| {
                    let z = q((i * 7 + j * 3) % 5 - 2, 3);
                    let w = if rational {
                        q(1 + (i + 2 * j) % 3, 2)
                    } else {
                        q(1, 1)
                    };
                    HPoint::from_point(&[q(i, 1), q(j, 1), z], &w)
                })
                .collect()
        })
        .collect();
    let s = NurbsSurface::new(
        Knots::new(3, ku, cu).unwrap(),
        Knots::bezier(3).unwrap(),
        net,
    )
    .unwrap();
    let mut p = s.bezier_pieces().into_iter().map(|p| p.patch);
    (p.next().unwrap(), p.next().unwrap())
}

#[test]
fn a_simple_inner_knot_is_g2_polynomial_and_rational() {
    for rational in [false, true] {
        let (a, b) = split(1, rational);
        let v = seam_continuity(&a, Edge::U1, &b, Edge::U0).unwrap();
        assert_eq!(v.continuity, Some(Continuity::G2), "{}", v.reason);
        assert!(!v.reversed && !v.reparameterized);
    }
}

#[test]
fn a_double_knot_is_g1_and_a_triple_knot_g0_with_exact_witnesses() {
    let (a, b) = split(2, true);
    let v = seam_continuity(&a, Edge::U1, &b, Edge::U0).unwrap();
    assert_eq!(v.continuity, Some(Continuity::G1), "{}", v.reason);
    assert!(
        v.reason.contains("normal curvature across the seam"),
        "{}",
        v.reason
    );
    let (a, b) = split(3, true);
    let v = seam_continuity(&a, Edge::U1, &b, Edge::U0).unwrap();
    assert_eq!(v.continuity, Some(Continuity::G0), "{}", v.reason);
    assert!(
        v.reason
            .starts_with("tangent planes differ at a at (u, v) = (1, "),
        "{}",
        v.reason
    );
}

#[test]
fn reversal_mobius_and_elevation_of_the_neighbour_keep_g2() {
    let (a, b) = split(1, true);
    // b's shared edge u = 0 runs in v: reparameterize and reverse v, elevate.
    let b2 = b.mobius_v(&q(2, 7)).reverse_v().elevate(1, 2).swap_uv();
    let v = seam_continuity(&a, Edge::U1, &b2, Edge::V0).unwrap();
    assert_eq!(v.continuity, Some(Continuity::G2), "{}", v.reason);
    assert!(v.reversed && v.reparameterized, "{v:?}");
    // Seen from b's side the verdict is the same.
    let w = seam_continuity(&b2, Edge::V0, &a, Edge::U1).unwrap();
    assert_eq!(w.continuity, Some(Continuity::G2), "{}", w.reason);
}

#[test]
fn a_patch_folded_back_onto_itself_is_a_fold() {
    let (a, _) = split(1, false);
    // a.reverse_u() lies on a, across a's edge u = 1 from itself.
    let v = seam_continuity(&a, Edge::U1, &a.reverse_u(), Edge::U0).unwrap();
    assert_eq!(v.continuity, Some(Continuity::G0));
    assert!(v.reason.contains("fold"), "{}", v.reason);
}

#[test]
fn edges_that_differ_are_not_judged() {
    let (a, b) = split(1, false);
    let v = seam_continuity(&a, Edge::U0, &b, Edge::U0).unwrap();
    assert_eq!(v.continuity, None);
    assert!(v.reason.contains("differ"), "{}", v.reason);
}
