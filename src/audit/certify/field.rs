//! A face as a **distance field**: what the certified measures of an edge
//! need from a face's surface, whatever its kind, over a box of points.
//!
//! With `s(P)` the signed distance of a point `P` from the surface (positive
//! on the side of the surface's own normal) and `σ(P)` its foot point,
//!
//! - `n̂ = ∇s` is the unit normal at the foot point (constant along the
//!   normal line), so along a curve `P(t)`: `d s(P(t))/dt = n̂·P'(t)`;
//! - `J = ∂n̂/∂P` (the Hessian of `s`, symmetric, `J n̂ = 0`) gives the
//!   normal's derivative along the curve, `d n̂(P(t))/dt = J P'(t)`;
//! - at a point **on** the surface, `J` restricted to the tangent plane is
//!   the derivative of the unit normal, the Weingarten map with its sign
//!   reversed (do Carmo, *Differential Geometry of Curves and Surfaces*,
//!   1976, §3-2: `II(w, w) = −⟨dN(w), w⟩`), so the normal curvature in a
//!   tangent direction `w`, relative to `n̂`, is `κ = −wᵀ J w / |w|²`.
//!
//! Closed forms implement it for the elementary surfaces
//! ([`super::closed_form::ISurface`]), certified foot points for B-spline
//! surfaces ([`super::spline::SplineField`]).

use super::closed_form::Distance;
use super::ivec::{scale, sub, IVec};
use crate::algebra::Interval;

/// A 3×3 matrix of intervals (rows).
pub type IMat3 = [[Interval; 3]; 3];

/// A surface seen from the points around it.
pub trait DistanceField {
    /// `s` and `n̂` enclosed for every point of the box `p`; `None` where
    /// not proved (the box reaches the axis, a singular point, or the foot
    /// point is not unique).
    fn distance(&self, p: &[Interval]) -> Option<Distance>;

    /// `J = ∂n̂/∂P` enclosed for every point of the box `p`; `None` where
    /// not proved.
    fn normal_jacobian(&self, p: &[Interval]) -> Option<IMat3>;

    /// `J` at the foot points `P − s n̂` of the points `p` whose normal
    /// and signed distance are enclosed by `normal` and `signed` (the
    /// surface's own points, where `J` gives its curvatures). The default
    /// takes [`DistanceField::normal_jacobian`] of that box.
    fn normal_jacobian_at_foot(
        &self,
        p: &[Interval],
        normal: &[Interval],
        signed: &Interval,
    ) -> Option<IMat3> {
        self.normal_jacobian(&sub(p, &scale(normal, signed)))
    }
}

/// `J v`.
pub fn apply(j: &IMat3, v: &[Interval]) -> IVec {
    j.iter()
        .map(|row| {
            row.iter()
                .zip(v)
                .fold(Interval::point(0.0), |acc, (a, b)| acc.add(&a.mul(b)))
        })
        .collect()
}

/// The normal curvature `κ = −wᵀ J w / |w|²` relative to `n̂` in the
/// tangent direction `w`, for `J` taken at points of the surface; `None`
/// when `|w|²`'s enclosure holds 0.
pub fn normal_curvature(j: &IMat3, w: &[Interval]) -> Option<Interval> {
    let jw = apply(j, w);
    let quad = super::ivec::dot(w, &jw);
    quad.neg().div(&super::ivec::norm2(w))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curvature_of_a_projector_is_minus_its_scale() {
        // J = (I − n nᵀ)/2 with n = e_z, the sphere of radius 2 seen
        // outward: κ = −1/2 in every tangent direction.
        let (z, h) = (Interval::point(0.0), Interval::point(0.5));
        let j = [[h, z, z], [z, h, z], [z, z, z]];
        let w = [1.0, 3.0, 0.0].map(Interval::point);
        let k = normal_curvature(&j, &w).unwrap();
        assert!(k.lo <= -0.5 && -0.5 <= k.hi && k.width() < 1e-14, "{k:?}");
        assert!(normal_curvature(&j, &[z, z, z]).is_none());
    }
}
