//! The audit over the real algebraic numbers: hand-built seams rotated by
//! 45° about the z axis (coordinates with `√2/2`), verdicts derived by hand.

use super::*;
use crate::algebra::{RealAlgebraic, Scalar};
use crate::ratio;

/// A grid of control points `(x, y, z)` in halves, weights 1.
type Grid = &'static [&'static [[i64; 3]]];

/// The rect patch of `grid` with each point mapped by `place`.
fn rect<T: SeamScalar>(grid: Grid, place: &dyn Fn([Q; 3]) -> Vec<T>) -> RectPatch<T> {
    let p: Vec<Vec<Vec<T>>> = grid
        .iter()
        .map(|row| {
            row.iter()
                .map(|xyz| place(xyz.map(|c| ratio(c, 2))))
                .collect()
        })
        .collect();
    let w = p.iter().map(|row| vec![T::one(); row.len()]).collect();
    RectPatch::new(p, w).unwrap()
}

/// `A`: the flat square x ∈ [−1, 0], y ∈ [0, 1], its edge `u = 1` on x = 0.
const FLAT_LEFT: Grid = &[&[[-2, 0, 0], [-2, 2, 0]], &[[0, 0, 0], [0, 2, 0]]];

fn model_of<T: SeamScalar>(grids: &[Grid], place: &dyn Fn([Q; 3]) -> Vec<T>) -> Model<T> {
    Model {
        pieces: grids
            .iter()
            .map(|g| Piece {
                patch: Patch::Rect(rect(g, place)),
                origin: Origin::default(),
            })
            .collect(),
        ..Model::default()
    }
}

/// The verdict of the one seam of the patches as given (over Q) and
/// turned by 45° about z, `(x, y) ↦ (c x − c y, c x + c y)` with
/// `c = √2/2` (over the real algebraic numbers): both must agree, with six
/// open edges.
fn seam_verdict(grids: &[Grid]) -> Option<Continuity> {
    let c: RealAlgebraic = "sqrt(2)/2".parse().unwrap();
    let turn = |[x, y, z]: [Q; 3]| {
        let [x, y, z] = [x, y, z].map(|v| RealAlgebraic::from_rational(&v));
        vec![
            c.clone() * &x - c.clone() * &y,
            c.clone() * &x + c.clone() * &y,
            z,
        ]
    };
    let rational = audit(&model_of(grids, &|p: [Q; 3]| p.to_vec())).unwrap();
    let algebraic = audit(&model_of(grids, &turn)).unwrap();
    for a in [rational.summary(), algebraic.summary()] {
        assert!(
            a.contains("1 shared edges") && a.contains("6 open edges"),
            "{a}"
        );
    }
    let v = rational.seams[0].verdict.continuity;
    assert_eq!(algebraic.seams[0].verdict.continuity, v);
    v
}

/// Coplanar squares on either side of x = 0: every normal curvature is 0 on
/// both sides, so G2.
#[test]
fn coplanar_squares_are_g2_turned_or_not() {
    let right: Grid = &[&[[0, 0, 0], [0, 2, 0]], &[[2, 0, 0], [2, 2, 0]]];
    assert_eq!(seam_verdict(&[FLAT_LEFT, right]), Some(Continuity::G2));
}

/// `z = x²` for x ∈ [0, 1] (control heights 0, 0, 1 at x = 0, ½, 1): its
/// tangent plane at x = 0 is z = 0 (G1) but its normal curvature across the
/// seam is 2, the flat side's 0: not G2.
#[test]
fn a_parabolic_sheet_on_a_plane_is_g1_turned_or_not() {
    let right: Grid = &[
        &[[0, 0, 0], [0, 2, 0]],
        &[[1, 0, 0], [1, 2, 0]],
        &[[2, 0, 2], [2, 2, 2]],
    ];
    assert_eq!(seam_verdict(&[FLAT_LEFT, right]), Some(Continuity::G1));
}

/// A wall standing on the seam (x = 0, z ∈ [0, 1]): tangent planes z = 0
/// and x = 0 differ, G0.
#[test]
fn a_wall_on_a_plane_is_g0_turned_or_not() {
    let wall: Grid = &[&[[0, 0, 0], [0, 2, 0]], &[[0, 0, 2], [0, 2, 2]]];
    assert_eq!(seam_verdict(&[FLAT_LEFT, wall]), Some(Continuity::G0));
}
