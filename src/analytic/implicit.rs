//! The closed forms of the elementary surfaces of ISO 10303-42 §4.4: each
//! kept beside its exact pieces, so that a point or a curve can be tested
//! against the surface itself, exactly, and measured against it cheaply.
//!
//! In the frame coordinates `(a, b, h) = ((P − C)·x̂, (P − C)·ŷ, (P − C)·ẑ)`
//! ([`Frame::coords`]), with `ρ² = a² + b²`, the surfaces are the zero sets
//!
//! ```text
//! plane      F = h
//! cylinder   F = ρ² − R²
//! cone       F = ρ² − (R + k h)²                      (k = tan α, the slope)
//! sphere     F = ρ² + h² − R²
//! torus      F = (ρ² + h² + R² − r²)² − 4R² ρ²         (major R, minor r)
//! ```
//!
//! (Each follows from the parameterization in [`super::surfaces`] by
//! eliminating `cos u, sin u` with `cos² + sin² = 1`, and `cos v, sin v`
//! likewise for the sphere and torus. The cone's zero set is the double
//! cone, which is ISO's cone for all `v`.) [`Implicit::gradient`] is a
//! positive multiple of `∇F`, and it points the way of ISO's surface normal
//! `σ_u × σ_v` wherever that is not zero: for the plane `x̂ × ŷ = ẑ`; for
//! the cylinder, cone and torus `σ_u × σ_v` is the radial factor `R + k v`
//! (resp. `R + r cos v`) times the same vector as `∇F/2` (resp. `∇F/4`)
//! divided by that factor, with the same sign; for the sphere
//! `σ_u × σ_v = R cos v · (P − C)`.

use super::frame::Frame;
use super::{add, scale};
use crate::algebra::scalar::Scalar;
use num_rational::BigRational;

/// An elementary surface by its closed form.
#[derive(Clone, Debug, PartialEq)]
pub enum Implicit<T> {
    /// `h = 0`.
    Plane {
        /// The placement.
        frame: Frame<T>,
    },
    /// `ρ = R`.
    Cylinder {
        /// The placement.
        frame: Frame<T>,
        /// `R`.
        radius: T,
    },
    /// `ρ = |R + k h|`.
    Cone {
        /// The placement.
        frame: Frame<T>,
        /// `R`, the radius at `h = 0`.
        radius: T,
        /// `k = tan α`.
        slope: T,
    },
    /// `ρ² + h² = R²`.
    Sphere {
        /// The placement.
        frame: Frame<T>,
        /// `R`.
        radius: T,
    },
    /// `(ρ − R)² + h² = r²` (for `ρ ≥ 0`).
    Torus {
        /// The placement.
        frame: Frame<T>,
        /// `R`.
        major: T,
        /// `r`.
        minor: T,
    },
}

impl<T: Scalar> Implicit<T> {
    /// The placement.
    pub fn frame(&self) -> &Frame<T> {
        match self {
            Implicit::Plane { frame }
            | Implicit::Cylinder { frame, .. }
            | Implicit::Cone { frame, .. }
            | Implicit::Sphere { frame, .. }
            | Implicit::Torus { frame, .. } => frame,
        }
    }

    /// The degree of `F` in the point's coordinates: 1, 2 or 4.
    pub fn degree(&self) -> usize {
        match self {
            Implicit::Plane { .. } => 1,
            Implicit::Torus { .. } => 4,
            _ => 2,
        }
    }

    /// The degree of [`Implicit::gradient`] in the point's coordinates.
    pub fn gradient_degree(&self) -> usize {
        self.degree() - 1
    }

    /// `F(p)`: zero exactly on the surface.
    ///
    /// ```
    /// use exact_bezier::{analytic::{Frame, Implicit}, ratio, BigRational};
    /// let q = |n: i64| ratio::<BigRational>(n, 1);
    /// let frame = Frame::from_axes(vec![q(0), q(0), q(0)], vec![q(1), q(0), q(0)], vec![q(0), q(0), q(1)]);
    /// let cylinder = Implicit::Cylinder { frame, radius: q(5) };
    /// assert_eq!(cylinder.value(&[q(3), q(4), q(7)]), q(0));
    /// assert_eq!(cylinder.value(&[q(3), q(3), q(7)]), q(-7));
    /// ```
    pub fn value(&self, p: &[T]) -> T {
        let [a, b, h] = self.frame().coords(p);
        let rho2 = a.clone() * &a + &(b.clone() * &b);
        match self {
            Implicit::Plane { .. } => h,
            Implicit::Cylinder { radius, .. } => rho2 - &(radius.clone() * radius),
            Implicit::Cone { radius, slope, .. } => {
                let r = radius.clone() + &(slope.clone() * &h);
                rho2 - &(r.clone() * &r)
            }
            Implicit::Sphere { radius, .. } => {
                rho2 + &(h.clone() * &h) - &(radius.clone() * radius)
            }
            Implicit::Torus { major, minor, .. } => {
                let big = major.clone() * major;
                let s = rho2.clone() + &(h.clone() * &h) + &big - &(minor.clone() * minor);
                s.clone() * &s - &(T::from_i64(4) * &big * &rho2)
            }
        }
    }

    /// A positive multiple of `∇F(p)` (`∇F/2`, or `∇F/4` for the torus),
    /// in world coordinates: the direction of ISO's surface normal on the
    /// surface (module docs).
    pub fn gradient(&self, p: &[T]) -> Vec<T> {
        let f = self.frame();
        let [a, b, h] = f.coords(p);
        let [ga, gb, gh] = match self {
            Implicit::Plane { .. } => [T::zero(), T::zero(), T::one()],
            Implicit::Cylinder { .. } => [a, b, T::zero()],
            Implicit::Cone { radius, slope, .. } => {
                let r = radius.clone() + &(slope.clone() * &h);
                [a, b, -(slope.clone() * &r)]
            }
            Implicit::Sphere { .. } => [a, b, h],
            Implicit::Torus { major, minor, .. } => {
                let big = major.clone() * major;
                let rho2 = a.clone() * &a + &(b.clone() * &b);
                let s = rho2 + &(h.clone() * &h) + &big - &(minor.clone() * minor);
                let radial = s.clone() - &(T::from_i64(2) * &big);
                [radial.clone() * &a, radial * &b, s * &h]
            }
        };
        add(
            &add(&scale(&f.x, &ga), &scale(&f.y, &gb)),
            &scale(&f.z, &gh),
        )
    }
}

/// The closed form of a surface entity as far as it is known: exactly, or
/// (a cone whose `semi_angle` is not a multiple of 15°, [`cone_slope`])
/// with its slope known within a bound; and how the entity's normal
/// `σ_u × σ_v` relates to [`Implicit::gradient`].
///
/// [`cone_slope`]: super::cone_slope
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedForm<T> {
    /// The surface: exactly it when `slope_error` is `None`; else a cone
    /// whose slope is a rational within `slope_error` of `tan α`.
    pub implicit: Implicit<T>,
    /// An exact bound `≥ |slope − tan α|` ([`Slope::error`]) for a cone
    /// whose slope is not exact; `None` when `implicit` is exact.
    ///
    /// [`Slope::error`]: super::Slope::error
    pub slope_error: Option<BigRational>,
    /// Does the entity's normal point against [`Implicit::gradient`]?
    /// False for the elementary surfaces (module docs); a surface of
    /// extrusion or revolution recognised as one may be reversed.
    pub reversed: bool,
}

impl<T> ClosedForm<T> {
    /// An elementary surface known exactly, with ISO's normal.
    pub fn exact(implicit: Implicit<T>) -> Self {
        ClosedForm {
            implicit,
            slope_error: None,
            reversed: false,
        }
    }

    /// The closed form when it is exactly the surface.
    pub fn exact_implicit(&self) -> Option<&Implicit<T>> {
        self.slope_error.is_none().then_some(&self.implicit)
    }
}
