//! Small exact curves and patches shared by unit tests and proof claims, so
//! that one fixture is written in one place.

use crate::algebra::scalar::ratio;
use crate::rect::RectPatch;
use num_rational::BigRational;

type Q = BigRational;

/// The integer point `(x, y)`.
#[cfg(test)]
pub(crate) fn p2(x: i64, y: i64) -> Vec<Q> {
    vec![ratio(x, 1), ratio(y, 1)]
}

/// The integer point `(x, y, z)`.
fn p3(x: i64, y: i64, z: i64) -> Vec<Q> {
    vec![ratio(x, 1), ratio(y, 1), ratio(z, 1)]
}

/// A planar rational cubic: points (0,0), (1,3), (4,3), (5,−1) with weights
/// 1, 2, 1/3, 3/2.
#[cfg(test)]
pub(crate) fn cubic() -> crate::curve::RationalCurve<Q> {
    crate::curve::RationalCurve::new(
        vec![p2(0, 0), p2(1, 3), p2(4, 3), p2(5, -1)],
        vec![ratio(1, 1), ratio(2, 1), ratio(1, 3), ratio(3, 2)],
    )
    .expect("valid curve")
}

/// The control points of [`rect_1x2`]: rows (0,0,0), (0,1,2), (0,3,1) and
/// (2,0,1), (2,2,5), (1,3,0).
pub(crate) fn rect_1x2_points() -> Vec<Vec<Vec<Q>>> {
    vec![
        vec![p3(0, 0, 0), p3(0, 1, 2), p3(0, 3, 1)],
        vec![p3(2, 0, 1), p3(2, 2, 5), p3(1, 3, 0)],
    ]
}

/// A rational patch of bidegree (1, 2) in space: [`rect_1x2_points`] with
/// weights 1, 2, 1/2 and 3, 1, 1.
pub(crate) fn rect_1x2() -> RectPatch<Q> {
    RectPatch::new(
        rect_1x2_points(),
        vec![
            vec![ratio(1, 1), ratio(2, 1), ratio(1, 2)],
            vec![ratio(3, 1), ratio(1, 1), ratio(1, 1)],
        ],
    )
    .expect("valid patch")
}
