//! [`Frame`] and [`Frame2`]: ISO 10303-42 placements (`axis2_placement_3d`,
//! `axis2_placement_2d`, `axis1_placement`) as exact orthonormal frames.
//!
//! STEP writes the directions as decimals, not unit vectors, and
//! `ref_direction` need not be perpendicular to `axis`. ISO 10303-42 §4.4
//! (`build_axes`, `first_proj_axis`) defines the frame as
//!
//! ```text
//! ẑ = z/|z|,   x̂ = (x − (x·ẑ)ẑ)/|x − (x·ẑ)ẑ|,   ŷ = ẑ × x̂
//! ```
//!
//! with `z = (0,0,1)` when `axis` is omitted and, when `ref_direction` is
//! omitted, `x = (1,0,0)` unless `z` is parallel to it, then `x = (0,1,0)`.
//! `x − (x·ẑ)ẑ = x − ((x·z)/|z|²) z` is rational for rational input, so the
//! only irrationals are the two square roots `|z|` and `|x⊥|`: exact
//! radicals with [`RealAlgebraic`](crate::algebra::RealAlgebraic).

use super::{add, cross, dot, scale, sub};
use crate::algebra::scalar::{Field, Ordered, Roots, Scalar};
use crate::error::Error;

/// An orthonormal frame: `origin`, and unit axes `x`, `y`, `z` with
/// `y = z × x` (right-handed).
#[derive(Clone, Debug, PartialEq)]
pub struct Frame<T> {
    /// The location `C`.
    pub origin: Vec<T>,
    /// `x̂` (ISO's `p[1]`).
    pub x: Vec<T>,
    /// `ŷ = ẑ × x̂` (ISO's `p[2]`).
    pub y: Vec<T>,
    /// `ẑ` (ISO's `p[3]`, the axis).
    pub z: Vec<T>,
}

/// # Construction from orthonormal axes and use
impl<T: Scalar> Frame<T> {
    /// The frame with the given axes, taken as orthonormal without a check
    /// (for axes known to be so, e.g. symbolic or rational Pythagorean ones;
    /// [`Frame::from_placement`] builds them from STEP data).
    pub fn from_axes(origin: Vec<T>, x: Vec<T>, z: Vec<T>) -> Self {
        let y = cross(&z, &x);
        Frame { origin, x, y, z }
    }

    /// The point `C + a·x̂ + b·ŷ + c·ẑ` (zero coordinates skipped).
    pub fn point(&self, a: &T, b: &T, c: &T) -> Vec<T> {
        [(a, &self.x), (b, &self.y), (c, &self.z)]
            .into_iter()
            .filter(|(k, _)| !k.is_zero())
            .fold(self.origin.clone(), |p, (k, axis)| add(&p, &scale(axis, k)))
    }

    /// The frame coordinates `((P − C)·x̂, (P − C)·ŷ, (P − C)·ẑ)` of `p`.
    pub fn coords(&self, p: &[T]) -> [T; 3] {
        let d = sub(p, &self.origin);
        [dot(&d, &self.x), dot(&d, &self.y), dot(&d, &self.z)]
    }
}

/// # Construction from a STEP placement
impl<T: Field + Ordered + Roots> Frame<T> {
    /// The frame of an `axis2_placement_3d(location, axis, ref_direction)`
    /// (ISO 10303-42 §4.4.12 and the functions `build_axes`,
    /// `first_proj_axis`), `None` for an omitted (`$`) direction. Exact for
    /// exact `T` with exact square roots.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless the vectors are 3D; [`Error::Domain`] for a
    /// zero axis or a `ref_direction` parallel to the axis;
    /// [`Error::NotRational`] when `T` has no square root of a length
    /// (`BigRational` with an irrational norm).
    ///
    /// ```
    /// use exact_bezier::{analytic::Frame, ratio, BigRational};
    /// let q = |n: i64, d: i64| ratio::<BigRational>(n, d);
    /// let f = Frame::from_placement(
    ///     &[q(0, 1), q(0, 1), q(0, 1)],
    ///     Some(&[q(0, 1), q(0, 1), q(2, 1)]),
    ///     Some(&[q(3, 1), q(4, 1), q(7, 1)]),
    /// ).unwrap();
    /// assert_eq!(f.x, vec![q(3, 5), q(4, 5), q(0, 1)]);
    /// assert_eq!(f.y, vec![q(-4, 5), q(3, 5), q(0, 1)]);
    /// ```
    pub fn from_placement(
        location: &[T],
        axis: Option<&[T]>,
        ref_direction: Option<&[T]>,
    ) -> Result<Self, Error> {
        let unit = |k: usize| -> Vec<T> {
            (0..3)
                .map(|i| if i == k { T::one() } else { T::zero() })
                .collect()
        };
        let z = axis.map_or_else(|| unit(2), <[T]>::to_vec);
        for v in [location, &z[..]].into_iter().chain(ref_direction) {
            if v.len() != 3 {
                return Err(Error::Shape(format!(
                    "an axis2_placement_3d needs 3D points and directions, not {}D",
                    v.len()
                )));
            }
        }
        let x = match ref_direction {
            Some(r) => r.to_vec(),
            None if z[1].is_zero() && z[2].is_zero() => unit(1),
            None => unit(0),
        };
        let zz = dot(&z, &z);
        if zz.is_zero() {
            return Err(Error::Domain("an axis of length zero".into()));
        }
        // |z|² x⊥ = |z|² x − (x·z) z, x⊥ = x − ((x·z)/|z|²) z: the positive
        // multiple normalises to the same x̂, and stays integral for integral
        // input (no denominator |z|² to carry into the root).
        let x_perp = sub(&scale(&x, &zz), &scale(&z, &dot(&x, &z)));
        let xx = dot(&x_perp, &x_perp);
        if xx.is_zero() {
            return Err(Error::Domain(
                "the ref_direction is parallel to the axis".into(),
            ));
        }
        // |x⊥|² = |z|²·w with w = |z|²|x|² − (x·z)²: dividing by √w and
        // √|z|² separately keeps the two radicands apart, where √(|z|²w)
        // would share the factor |z|² with ẑ's root, and every sum of
        // x̂- and ẑ-terms would first refine the two into a common basis.
        let w = xx / &zz;
        Ok(Frame::from_axes(
            location.to_vec(),
            normalize(&normalize(&x_perp, &w)?, &zz)?,
            normalize(&z, &zz)?,
        ))
    }
}

/// `v/√(v·v)` given `vv = v·v > 0`, with an exact root.
fn normalize<T: Field + Roots>(v: &[T], vv: &T) -> Result<Vec<T>, Error> {
    let len = vv
        .nth_root(2)
        .ok_or_else(|| Error::NotRational(format!("√{vv:?} is not in this scalar type")))?;
    // 1/√vv = √vv/vv: a division by the rational-valued vv, not by a root.
    let inv = len / vv;
    Ok(v.iter().map(|c| c.clone() * &inv).collect())
}

/// A 2D orthonormal frame: an `axis2_placement_2d(location, ref_direction)`
/// with `x̂ = x/|x|` and `ŷ = x̂` turned by +90° (ISO 10303-42 §4.4.11;
/// `x = (1, 0)` when omitted).
#[derive(Clone, Debug, PartialEq)]
pub struct Frame2<T> {
    /// The location.
    pub origin: Vec<T>,
    /// `x̂`.
    pub x: Vec<T>,
    /// `ŷ = (−x̂₂, x̂₁)`.
    pub y: Vec<T>,
}

impl<T: Field + Ordered + Roots> Frame2<T> {
    /// The frame of an `axis2_placement_2d`, exact for exact `T` with exact
    /// square roots.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless 2D; [`Error::Domain`] for a zero direction;
    /// [`Error::NotRational`] as [`Frame::from_placement`].
    pub fn from_placement(location: &[T], ref_direction: Option<&[T]>) -> Result<Self, Error> {
        let x = ref_direction.map_or_else(|| vec![T::one(), T::zero()], <[T]>::to_vec);
        if location.len() != 2 || x.len() != 2 {
            return Err(Error::Shape(
                "an axis2_placement_2d needs 2D points and directions".into(),
            ));
        }
        let xx = dot(&x, &x);
        if xx.is_zero() {
            return Err(Error::Domain("a ref_direction of length zero".into()));
        }
        let x = normalize(&x, &xx)?;
        let y = vec![-x[1].clone(), x[0].clone()];
        Ok(Frame2 {
            origin: location.to_vec(),
            x,
            y,
        })
    }
}
