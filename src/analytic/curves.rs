//! Curves of ISO 10303-42 §4.4 as exact rational Bézier pieces: `line`
//! (a segment of it), `circle`, `ellipse`, `polyline`.
//!
//! ```text
//! line      λ(u) = P + u·V                          (V = the VECTOR, with magnitude)
//! circle    λ(u) = C + R (cos u · x̂ + sin u · ŷ)
//! ellipse   λ(u) = C + a cos u · x̂ + b sin u · ŷ
//! polyline  λ(u) = P_k + (u − k)(P_{k+1} − P_k),  k ≤ u ≤ k + 1 (0-based)
//! ```
//!
//! Circles and ellipses are four quarter arcs (see the module
//! [`analytic`](super) for the half-angle parameter `t = tan((u − k·90°)/2)`).

use super::frame::Frame;
use super::{add, scale, sub};
use crate::algebra::scalar::Scalar;
use crate::curve::RationalCurve;
use crate::hpoint::HPoint;

/// The four quarter arcs of the unit circle in `(cos, sin)` coordinates:
/// for arc `k`, three control points `(c, s)` with weights `1, 1, 2`
/// (arc 0: `(1,0), (1,1), (0,1)`; arc `k` turned by `k·90°`). Arc `k` at
/// `t` is `(cos φ, sin φ)`, `φ = k·90° + 2·atan t`.
pub fn quarter_arcs<T: Scalar>() -> Vec<Vec<([T; 2], T)>> {
    let base = [(1, 0, 1), (1, 1, 1), (0, 1, 2)];
    // Turning by 90°: (c, s) ↦ (−s, c).
    let turn = |(c, s): (i64, i64), k: usize| (0..k).fold((c, s), |(c, s), _| (-s, c));
    (0..4)
        .map(|k| {
            base.iter()
                .map(|&(c, s, w)| {
                    let (c, s) = turn((c, s), k);
                    ([T::from_i64(c), T::from_i64(s)], T::from_i64(w))
                })
                .collect()
        })
        .collect()
}

/// The four quarter arcs of `C + a·cos φ·x̂ + b·sin φ·ŷ` (an ellipse of
/// semi-axes `a` along `x̂` and `b` along `ŷ`; a circle of radius `R` when
/// `a = b = R`): the unit arcs of [`quarter_arcs`] under the affine map
/// `(c, s) ↦ C + a·c·x̂ + b·s·ŷ` (rational curves are affinely invariant).
/// Piece `k` covers `φ ∈ [k·90°, (k+1)·90°]` with `t = tan((φ − k·90°)/2)`.
/// Exact for exact `T`; ring operations only.
///
/// ```
/// use exact_bezier::{analytic::{ellipse, Frame}, ratio, BigRational};
/// let q = |n: i64| ratio::<BigRational>(n, 1);
/// let f = Frame::from_axes(vec![q(0), q(0), q(0)], vec![q(1), q(0), q(0)], vec![q(0), q(0), q(1)]);
/// let arcs = ellipse(&f, &q(3), &q(2));
/// // φ = 90° + 2·atan(1/2): cos φ = −4/5, sin φ = 3/5.
/// assert_eq!(arcs[1].eval(&ratio(1, 2)).unwrap(), vec![ratio(-12, 5), ratio(6, 5), q(0)]);
/// ```
pub fn ellipse<T: Scalar>(frame: &Frame<T>, a: &T, b: &T) -> Vec<RationalCurve<T>> {
    quarter_arcs::<T>()
        .iter()
        .map(|arc| {
            let ctrl = arc
                .iter()
                .map(|([c, s], w)| {
                    HPoint::from_point(
                        &frame.point(&(a.clone() * c), &(b.clone() * s), &T::zero()),
                        w,
                    )
                })
                .collect();
            RationalCurve::from_ctrl(ctrl)
        })
        .collect()
}

/// The circle `C + R (cos φ · x̂ + sin φ · ŷ)` as four quarter arcs:
/// [`ellipse`] with `a = b = R`.
pub fn circle<T: Scalar>(frame: &Frame<T>, radius: &T) -> Vec<RationalCurve<T>> {
    ellipse(frame, radius, radius)
}

/// The segment of the line `P + u·V` for `u ∈ [u0, u1]`: one linear piece
/// `(P + u0·V, P + u1·V)`, piece parameter `t = (u − u0)/(u1 − u0)`.
pub fn line_segment<T: Scalar>(point: &[T], vector: &[T], u0: &T, u1: &T) -> RationalCurve<T> {
    let end = |u: &T| HPoint::from_cartesian(&add(point, &scale(vector, u)));
    RationalCurve::from_ctrl(vec![end(u0), end(u1)])
}

/// A polyline through `points`: one linear piece per consecutive pair,
/// piece `k` at `t` being ISO's `λ(k + t)` (0-based). Empty for fewer than
/// two points.
pub fn polyline<T: Scalar>(points: &[Vec<T>]) -> Vec<RationalCurve<T>> {
    points
        .windows(2)
        .map(|w| line_segment(&w[0], &sub(&w[1], &w[0]), &T::zero(), &T::one()))
        .collect()
}
