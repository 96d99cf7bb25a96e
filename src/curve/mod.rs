//! [`RationalCurve`]: rational Bézier curves of any degree and dimension, in
//! homogeneous form, generic over the scalar.
//!
//! Conventions: parameter `t ∈ [0, 1]`; control points `P_0 … P_n` with
//! weights `w_0 … w_n`, stored as homogeneous points `(w_i·P_i, w_i)`;
//!
//! ```text
//! X(t) = Σ w_i P_i B_{i,n}(t) / Σ w_i B_{i,n}(t)
//! ```
//!
//! A polynomial curve is the case of all weights 1.
//!
//! Reference: source 001 (lecture) for the Bézier curve and its algorithms;
//! source 000 (Yang & Yong) eqs (2)–(5) for the Möbius map and weight scaling.

mod basics;
pub mod circle;
pub mod deriv;
pub mod geometry;
pub mod join;
pub mod reduction;

pub use circle::{circle_of, integer_coords, Circle, NotCircle};
pub use deriv::forward_differences;
pub use geometry::{cross_norm_sq, ConicType, CurveEnd};
pub use join::{g2_leading_points, join, Join};
pub use reduction::Reduction;

use crate::algebra::scalar::{binomial, ratio, Field, Ordered, Scalar};
use crate::error::Error;
use crate::eval::{Evaluator, Jets, Net, Shape};
use crate::hpoint::{check_positive_weights, HPoint};
use num_bigint::BigInt;
use num_rational::BigRational;

/// A rational Bézier curve `X(t) = Σ w_i P_i B_{i,n}(t) / Σ w_i B_{i,n}(t)`.
///
/// # Examples
///
/// The lecture's quiz (source 001): the cubic with control points (10,0),
/// (30,60), (130,60), (190,0) at t = 1/2 is (85, 45).
///
/// ```
/// use exact_bezier::{RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let c = RationalCurve::polynomial(vec![p(10, 0), p(30, 60), p(130, 60), p(190, 0)]).unwrap();
/// assert_eq!(c.eval(&ratio(1, 2)).unwrap(), p(85, 45));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RationalCurve<T> {
    ctrl: Vec<HPoint<T>>,
}

/// # Blossom, subdivision, elevation, Möbius maps
impl<T: Scalar> RationalCurve<T> {
    /// The blossom (polar form) `b[t_1, …, t_n]`: symmetric, affine in each
    /// argument, and `b[t, …, t] = X(t)` (homogeneously); the control points
    /// are `b[0^{n−i}, 1^i]` (dual functional property).
    ///
    /// Computed by de Casteljau with a different parameter at each level.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless exactly `n` arguments are given.
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let c = RationalCurve::polynomial(vec![p(0), p(3), p(9)]).unwrap();
    /// // b[0, 1] is the middle control point.
    /// assert_eq!(c.blossom(&[ratio(0, 1), ratio(1, 1)]).unwrap(), c.ctrl()[1]);
    /// ```
    pub fn blossom(&self, args: &[T]) -> Result<HPoint<T>, Error> {
        if args.len() != self.degree() {
            return Err(Error::Shape(format!(
                "the blossom of a degree {} curve takes {} arguments, not {}",
                self.degree(),
                self.degree(),
                args.len()
            )));
        }
        let mut row = self.ctrl.clone();
        for (level, t) in args.iter().enumerate() {
            for i in 0..self.degree() - level {
                row[i] = row[i].lerp(&row[i + 1], t);
            }
        }
        Ok(row.swap_remove(0))
    }

    /// Split at `t` into the pieces over `[0, t]` and `[t, 1]`, each
    /// reparameterized to `[0, 1]`, from the two edges of de Casteljau's
    /// triangle. Exact for exact `T`.
    pub fn subdivide(&self, t: &T) -> (Self, Self) {
        let n = self.degree();
        let mut row = self.ctrl.clone();
        let mut left = Vec::with_capacity(n + 1);
        let mut right = Vec::with_capacity(n + 1);
        left.push(row[0].clone());
        right.push(row[n].clone());
        for k in (1..=n).rev() {
            for i in 0..k {
                row[i] = row[i].lerp(&row[i + 1], t);
            }
            left.push(row[0].clone());
            right.push(row[k - 1].clone());
        }
        right.reverse();
        (RationalCurve { ctrl: left }, RationalCurve { ctrl: right })
    }

    /// The piece over `[a, b]` reparameterized to `[0, 1]` (`a > b` gives the
    /// reversed piece): control points `b[a^{n−i}, b^i]` from the blossom.
    pub fn subsegment(&self, a: &T, b: &T) -> Self {
        let n = self.degree();
        let ctrl = (0..=n)
            .map(|i| {
                let mut args = vec![a.clone(); n - i];
                args.extend(std::iter::repeat_n(b.clone(), i));
                self.blossom(&args).expect("n arguments")
            })
            .collect();
        RationalCurve { ctrl }
    }

    /// Raise the degree by `r`, keeping every point: source 001's elevation
    /// ("升阶", `P*_i = (i/(n+1)) P_{i−1} + (1 − i/(n+1)) P_i`) applied `r`
    /// times to the homogeneous points, or all `r` at once where the scalar
    /// sums many parts cheaply (`elevate_by`).
    pub fn elevate(&self, r: usize) -> Self {
        RationalCurve {
            ctrl: elevate_by(&self.ctrl, r),
        }
    }

    /// The same curve traversed backwards: `P*_i = P_{n−i}`, `X*(t) = X(1 − t)`.
    pub fn reverse(&self) -> Self {
        let mut ctrl = self.ctrl.clone();
        ctrl.reverse();
        RationalCurve { ctrl }
    }

    /// Linear Möbius reparameterization `u = (α − 1)s / (2αs − s − α)`
    /// (source 000, eq. 2): control points unchanged, weights
    /// `w̃_i = w_i (1 − α)^i α^{n−i}` (eq. 4, curve case). The new curve at
    /// `s` is the old one at `u(s)` (see [`RationalCurve::mobius_param`]).
    /// For a symbolic `α` the result is exact for all α.
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let c = RationalCurve::new(vec![p(0, 0), p(1, 2), p(3, 0)], vec![ratio(1, 1), ratio(2, 1), ratio(1, 1)]).unwrap();
    /// let alpha = ratio(1, 3);
    /// let m = c.mobius(&alpha);
    /// let s = ratio(1, 4);
    /// let u = RationalCurve::mobius_param(&alpha, &s).unwrap();
    /// assert_eq!(m.eval(&s).unwrap(), c.eval(&u).unwrap());
    /// ```
    pub fn mobius(&self, alpha: &T) -> Self {
        let beta = T::one() - alpha;
        let ctrl = mobius_factors(alpha, &beta, self.degree())
            .iter()
            .zip(&self.ctrl)
            .map(|(f, p)| p.scale(f))
            .collect();
        RationalCurve { ctrl }
    }

    /// Multiply every weight by `k` (source 000, eq. 5): the curve is unchanged.
    pub fn scale_weights(&self, k: &T) -> Self {
        RationalCurve {
            ctrl: self.ctrl.iter().map(|p| p.scale(k)).collect(),
        }
    }
}

/// The Möbius weight factors `(1 − α)^i α^{n−i}`, `i = 0…n` (source 000, eq. 4),
/// given `alpha` and `one_minus_alpha`.
pub fn mobius_factors<T: Scalar>(alpha: &T, one_minus_alpha: &T, n: usize) -> Vec<T> {
    (0..=n)
        .map(|i| one_minus_alpha.pow_u32(i as u32) * alpha.pow_u32((n - i) as u32))
        .collect()
}

/// `r` degree elevations of a row of homogeneous points: by
/// [`elevate_at_once`] where the scalar sums many parts at once
/// ([`Scalar::SUMS_AT_ONCE`], `Poly`: the compact-form claim of `prove
/// --deep` at (10, 10), 0.44 → 0.09 s), else by [`elevate_once`] `r` times.
/// The two give the same points for exact scalars (property test).
pub(crate) fn elevate_by<T: Scalar>(ctrl: &[HPoint<T>], r: usize) -> Vec<HPoint<T>> {
    if T::SUMS_AT_ONCE && r > 1 {
        elevate_at_once(ctrl, r)
    } else {
        (0..r).fold(ctrl.to_vec(), |acc, _| elevate_once(&acc))
    }
}

/// One degree elevation of a row of homogeneous points (source 001,
/// "升阶"): `P*_i = (i/(n+1)) P_{i−1} + (1 − i/(n+1)) P_i`, `i = 0…n+1`.
pub(crate) fn elevate_once<T: Scalar>(ctrl: &[HPoint<T>]) -> Vec<HPoint<T>> {
    let n = ctrl.len() - 1;
    let mut out = Vec::with_capacity(n + 2);
    out.push(ctrl[0].clone());
    for i in 1..=n {
        let a = ratio::<T>(i as i64, n as i64 + 1);
        let b = T::one() - &a;
        out.push(ctrl[i - 1].combine(&a, &ctrl[i], &b));
    }
    out.push(ctrl[n].clone());
    out
}

/// `r` degree elevations at once:
/// `P*_k = Σ_i C(n,i)·C(r,k−i)/C(n+r,k) · P_i` over
/// `max(0, k−r) ≤ i ≤ min(n, k)`, `k = 0…n+r` (the product of
/// `Σ P_i B_{i,n}` with `1 = Σ_j B_{j,r}`, by
/// `B_{i,n}·B_{j,r} = C(n,i)C(r,j)/C(n+r,i+j)·B_{i+j,n+r}`; Farin, *Curves
/// and Surfaces for CAGD*, §6.1): each point one [`Scalar::sum_of`] of at
/// most `n + 1` terms, where [`elevate_once`] builds it through `r` rounds
/// of intermediate points.
pub(crate) fn elevate_at_once<T: Scalar>(ctrl: &[HPoint<T>], r: usize) -> Vec<HPoint<T>> {
    let n = ctrl.len() - 1;
    let row = |m: usize| -> Vec<BigInt> { (0..=m).map(|i| binomial(m, i)).collect() };
    let (cn, cr, cnr) = (row(n), row(r), row(n + r));
    (0..=n + r)
        .map(|k| {
            let terms: Vec<(usize, T)> = (k.saturating_sub(r)..=k.min(n))
                .map(|i| {
                    let w = BigRational::new(&cn[i] * &cr[k - i], cnr[k].clone());
                    (i, T::from_rational(&w))
                })
                .collect();
            let coords = (0..ctrl[0].coords.len())
                .map(|c| {
                    T::sum_of(
                        terms
                            .iter()
                            .map(|(i, w)| ctrl[*i].coords[c].clone() * w)
                            .collect(),
                    )
                })
                .collect();
            HPoint { coords }
        })
        .collect()
}

/// # Validation of weights
impl<T: Ordered> RationalCurve<T> {
    /// Check that every weight is positive (the CAD convention; negative
    /// weights put poles inside the parameter interval).
    ///
    /// # Errors
    ///
    /// [`Error::Weight`] naming the first non-positive weight.
    pub fn check_positive_weights(&self) -> Result<(), Error> {
        check_positive_weights(std::slice::from_ref(&self.ctrl), |_, i| i.to_string())
    }
}

/// # Batch evaluation (the nets of [`crate::eval`])
impl<T: Scalar> Net<T> {
    /// The net of a curve.
    pub fn from_curve(c: &RationalCurve<T>) -> Self {
        Net::from_points(c.ctrl(), Shape::Curve(c.degree()))
            .expect("a validated curve has a consistent net")
    }
}

impl<T: Field> Evaluator<T> {
    /// An evaluator of a curve.
    pub fn curve(c: &RationalCurve<T>) -> Self {
        Self::new(Net::from_curve(c))
    }
}

impl<T: Scalar> Jets<T> {
    /// The jets of a curve: `H` and `H'`.
    ///
    /// ```
    /// use exact_bezier::{eval::Jets, RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// // The parabola X(t) = (t, t²): X'(t) = (1, 2t), weight 1 (w' = 0).
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 2), ratio(y, 1)];
    /// let c = RationalCurve::polynomial(vec![p(0, 0), p(1, 0), p(2, 1)]).unwrap();
    /// let mut out = vec![ratio(0, 1); 6];
    /// Jets::curve(&c).eval_batch(&[ratio(1, 3)], &mut out).unwrap();
    /// assert_eq!(out[3..], [ratio(1, 1), ratio(2, 3), ratio(0, 1)]);
    /// ```
    pub fn curve(c: &RationalCurve<T>) -> Self {
        Self::new(Net::from_curve(c))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samples::cubic as sample;
    use crate::strategy::curve;
    use proptest::prelude::*;

    type Q = BigRational;

    #[test]
    fn subdivision_keeps_points() {
        let c = sample();
        let t = ratio::<Q>(2, 5);
        let (l, r) = c.subdivide(&t);
        for k in 0..=6 {
            let s = ratio::<Q>(k, 6);
            assert_eq!(l.eval(&s).unwrap(), c.eval(&(s.clone() * &t)).unwrap());
            let u = t.clone() + s.clone() * (ratio::<Q>(1, 1) - &t);
            assert_eq!(r.eval(&s).unwrap(), c.eval(&u).unwrap());
        }
    }

    #[test]
    fn elevation_and_reversal_keep_points() {
        let c = sample();
        let e = c.elevate(3);
        assert_eq!(e.degree(), 6);
        let rv = c.reverse();
        for k in 0..=5 {
            let s = ratio::<Q>(k, 5);
            assert_eq!(e.eval(&s).unwrap(), c.eval(&s).unwrap());
            assert_eq!(
                rv.eval(&s).unwrap(),
                c.eval(&(ratio::<Q>(1, 1) - &s)).unwrap()
            );
        }
    }

    proptest! {
        /// All `r` elevations at once (the route of `Poly`) give the points
        /// of `r` single steps (the route of `BigRational`).
        #[test]
        fn elevation_at_once_is_the_single_steps(c in curve(5, 3), r in 0usize..6) {
            let steps = (0..r).fold(c.ctrl().to_vec(), |p, _| elevate_once(&p));
            prop_assert_eq!(elevate_at_once(c.ctrl(), r), steps);
        }
    }

    #[test]
    fn subsegment_matches_blossom_ends() {
        let c = sample();
        let (a, b) = (ratio::<Q>(1, 4), ratio::<Q>(3, 4));
        let seg = c.subsegment(&a, &b);
        assert_eq!(seg.eval(&ratio(0, 1)).unwrap(), c.eval(&a).unwrap());
        assert_eq!(
            seg.eval(&ratio(1, 2)).unwrap(),
            c.eval(&ratio(1, 2)).unwrap()
        );
        assert_eq!(seg.eval(&ratio(1, 1)).unwrap(), c.eval(&b).unwrap());
    }

    #[test]
    fn shape_errors_are_typed() {
        let p = vec![vec![ratio::<Q>(0, 1)], vec![ratio(1, 1), ratio(2, 1)]];
        assert!(matches!(RationalCurve::polynomial(p), Err(Error::Shape(_))));
        assert!(matches!(
            RationalCurve::<Q>::new(vec![vec![ratio(0, 1)]], vec![ratio(0, 1)]),
            Err(Error::Weight { .. })
        ));
        assert!(RationalCurve::<Q>::polynomial(vec![]).is_err());
    }
}
