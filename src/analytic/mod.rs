//! The analytic curves and surfaces of ISO 10303-42 (STEP) as exact rational
//! Bézier pieces: lines, circles, ellipses, polylines; planes, cylinders,
//! cones, spheres, tori, surfaces of linear extrusion and of revolution.
//!
//! Conventions (every constructor states its own relation to the ISO
//! parameter):
//!
//! - A full turn is four quarter arcs. Quarter arc `k` (`k = 0…3`) covers
//!   the ISO angle `φ ∈ [k·90°, (k+1)·90°]`; its parameter is the half-angle
//!   tangent `t = tan((φ − k·90°)/2) ∈ [0, 1]`. In the frame's `(cos, sin)`
//!   coordinates the arc `k = 0` has control points `(1, 0), (1, 1), (0, 1)`
//!   and weights `(1, 1, 2)`:
//!
//!   ```text
//!   X(t) = ((1 − t²)/(1 + t²), 2t/(1 + t²))     (weight function 1 + t²)
//!   ```
//!
//!   the rational parameterization of the circle by `t = tan(φ/2)`. It is a
//!   Möbius reparameterization of the usual arc with weights `(1, √2/2, 1)`
//!   (the invariant `w₀w₂/w₁² = 2` is the same), and it keeps every weight
//!   rational: the arithmetic stays in Q when the frame is rational. Arc `k`
//!   is arc 0 turned by `k·90°`. Reference: Piegl–Tiller, *The NURBS Book*,
//!   §7.3 (conics as rational quadratics), §7.5 (full circles), §1.4 (the
//!   tan-half-angle parameterization); Farin, *Curves and Surfaces for CAGD*,
//!   §12 (conics, Möbius/weight invariants).
//! - Surfaces are tensor products of such arcs and segments: a surface
//!   `S(a, b)` affine in each of its two arguments (bi-affine) becomes the
//!   patch with control points `S(a_i, b_j)` and weights `w_i·w'_j` from the
//!   control points `(a_i, w_i)`, `(b_j, w'_j)` of the two parameter curves
//!   (Piegl–Tiller §8.2–§8.5). The first index (`u`) is ISO's `u`.
//! - Scalars: construction from an orthonormal [`Frame`] needs ring
//!   operations only ([`Scalar`], so the symbolic ring proves the implicit
//!   equations in `proofs/`); turning STEP's decimal directions into an
//!   orthonormal frame needs square roots ([`Roots`](crate::Roots): exact radicals with
//!   [`RealAlgebraic`](crate::algebra::RealAlgebraic)).
//!
//! Reference: ISO 10303-42 §4.4 (geometry schema: placements, conics,
//! elementary surfaces, swept surfaces).

pub mod angle;
pub mod curves;
pub mod frame;
pub mod implicit;
pub mod range;
pub mod surfaces;
pub mod trim;

pub use angle::{cone_slope, AngleUnit, Slope};
pub use curves::{circle, ellipse, line_segment, polyline, quarter_arcs};
pub use frame::{Frame, Frame2};
pub use implicit::{ClosedForm, Implicit};
pub use range::{covering_range, Unbounded};
pub use surfaces::{cone, cylinder, extrusion, plane, revolution, sphere, torus};
pub use trim::{locate_vertex, split_between, trim_between, Trimmed};

use crate::algebra::scalar::Scalar;

/// `a + b`, coordinate by coordinate.
pub(crate) fn add<T: Scalar>(a: &[T], b: &[T]) -> Vec<T> {
    a.iter().zip(b).map(|(x, y)| x.clone() + y).collect()
}

/// `a − b`, coordinate by coordinate.
pub(crate) fn sub<T: Scalar>(a: &[T], b: &[T]) -> Vec<T> {
    a.iter().zip(b).map(|(x, y)| x.clone() - y).collect()
}

/// `k·a`.
pub(crate) fn scale<T: Scalar>(a: &[T], k: &T) -> Vec<T> {
    a.iter().map(|x| x.clone() * k).collect()
}

/// `a · b`.
pub(crate) fn dot<T: Scalar>(a: &[T], b: &[T]) -> T {
    a.iter()
        .zip(b)
        .fold(T::zero(), |acc, (x, y)| acc + &(x.clone() * y))
}

/// `a × b` in 3D.
pub(crate) fn cross<T: Scalar>(a: &[T], b: &[T]) -> Vec<T> {
    vec![
        a[1].clone() * &b[2] - &(a[2].clone() * &b[1]),
        a[2].clone() * &b[0] - &(a[0].clone() * &b[2]),
        a[0].clone() * &b[1] - &(a[1].clone() * &b[0]),
    ]
}

#[cfg(test)]
mod tests;
