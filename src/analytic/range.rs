//! [`covering_range`]: the range of a surface's unbounded parameter(s) that
//! covers a face, from points whose convex hull contains the face's edges.
//!
//! A face's bounding edges are rational curves with positive weights, so
//! each lies in the convex hull of its control points. Every unbounded
//! parameter below is an affine function of the surface point (or bounded
//! by affine functions of it), so its extreme values over that hull are
//! attained at the given points: the exact min/max of the projections
//! (in `T`, no rounding) covers the face. No margin is added; only when
//! the points project to a single value (no face has zero extent) is the
//! range widened to `[x − 1, x + 1]` so the pieces are not degenerate.

use super::frame::Frame;
use super::{dot, sub};
use crate::algebra::scalar::{Field, Ordered};
use crate::curve::RationalCurve;
use crate::error::Error;

/// A surface with unbounded parameter directions.
#[derive(Clone, Debug)]
pub enum Unbounded<'a, T> {
    /// A plane: both `u = (P − C)·x̂` and `v = (P − C)·ŷ`.
    Plane(&'a Frame<T>),
    /// A cylinder or cone: `v = (P − C)·ẑ`.
    Axial(&'a Frame<T>),
    /// An extrusion `λ(u) + v V`: `v = (P·V − λ(u)·V)/|V|²`, bounded by the
    /// projections of the points and of the curve's control points.
    Extrusion {
        /// The swept curve's pieces.
        curve: &'a [RationalCurve<T>],
        /// `V`.
        vector: &'a [T],
    },
    /// The revolution of the line `L + v D` about the axis through `A` with
    /// unit direction `â`: `v = ((P − A)·â − (L − A)·â)/(D·â)` (the
    /// rotation keeps the axial coordinate); needs `D·â ≠ 0`.
    RevolvedLine {
        /// `L`.
        point: &'a [T],
        /// `D`.
        direction: &'a [T],
        /// `A`.
        origin: &'a [T],
        /// `â`.
        axis: &'a [T],
    },
}

/// The ranges `[lo, hi]` of the unbounded parameters of `surface` that
/// cover `points` (two ranges, u then v, for a plane; one, v, otherwise).
/// Exact for exact `T`.
///
/// # Errors
///
/// [`Error::Domain`] with no points, or for a line revolved in a plane
/// perpendicular to the axis (`D·â = 0`: its parameter is a radius, not
/// an affine function); [`Error::PointAtInfinity`] for a zero weight.
///
/// ```
/// use exact_bezier::{analytic::{covering_range, Frame, Unbounded}, ratio, BigRational};
/// let q = |n: i64| ratio::<BigRational>(n, 1);
/// let f = Frame::from_axes(vec![q(0), q(0), q(1)], vec![q(1), q(0), q(0)], vec![q(0), q(0), q(1)]);
/// let pts = vec![vec![q(1), q(0), q(5)], vec![q(0), q(1), q(-2)]];
/// assert_eq!(covering_range(&Unbounded::Axial(&f), &pts).unwrap(), vec![[q(-3), q(4)]]);
/// ```
pub fn covering_range<T: Field + Ordered>(
    surface: &Unbounded<'_, T>,
    points: &[Vec<T>],
) -> Result<Vec<[T; 2]>, Error> {
    if points.is_empty() {
        return Err(Error::Domain("no points to cover".into()));
    }
    let along = |p: &[T], origin: &[T], d: &[T]| dot(&sub(p, origin), d);
    let range = |f: &dyn Fn(&[T]) -> T| widen(extremes(points.iter().map(|p| f(p))));
    Ok(match surface {
        Unbounded::Plane(fr) => vec![
            range(&|p| along(p, &fr.origin, &fr.x)),
            range(&|p| along(p, &fr.origin, &fr.y)),
        ],
        Unbounded::Axial(fr) => vec![range(&|p| along(p, &fr.origin, &fr.z))],
        Unbounded::Extrusion { curve, vector } => {
            if curve.is_empty() {
                return Err(Error::Domain("an extrusion of no curve pieces".into()));
            }
            let vv = dot(vector, vector);
            let [p_lo, p_hi] = extremes(points.iter().map(|p| dot(p, vector)));
            let mut ctrl = Vec::new();
            for c in curve.iter() {
                ctrl.extend(c.points()?);
            }
            let [c_lo, c_hi] = extremes(ctrl.iter().map(|p| dot(p, vector)));
            vec![widen([(p_lo - &c_hi) / &vv, (p_hi - &c_lo) / &vv])]
        }
        Unbounded::RevolvedLine {
            point,
            direction,
            origin,
            axis,
        } => {
            let da = dot(direction, axis);
            if da.is_zero() {
                return Err(Error::Domain(
                    "a line revolved in a plane perpendicular to the axis".into(),
                ));
            }
            let base = along(point, origin, axis);
            let [lo, hi] = extremes(
                points
                    .iter()
                    .map(|p| (along(p, origin, axis) - &base) / &da),
            );
            vec![widen([lo, hi])]
        }
    })
}

/// The min and max of a non-empty sequence.
fn extremes<T: Ordered>(mut xs: impl Iterator<Item = T>) -> [T; 2] {
    let first = xs.next().expect("a non-empty sequence");
    xs.fold([first.clone(), first], |[lo, hi], x| {
        let lo = if x < lo { x.clone() } else { lo };
        let hi = if x > hi { x } else { hi };
        [lo, hi]
    })
}

/// `[lo, hi]`, ordered, and widened by 1 each way when `lo = hi`.
fn widen<T: Ordered>([a, b]: [T; 2]) -> [T; 2] {
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    if lo == hi {
        return [lo - &T::one(), hi + &T::one()];
    }
    [lo, hi]
}
