//! Construction, access and evaluation of [`RationalCurve`]: the first
//! methods of its page (a module of its own because rustdoc lists the impl
//! blocks of submodules before those of the parent).

use super::RationalCurve;
use crate::algebra::scalar::{Field, Scalar, Tolerance};
use crate::error::Error;
use crate::hpoint::{de_casteljau, de_casteljau_hom, HPoint};

/// # Construction and access
impl<T: Scalar> RationalCurve<T> {
    /// The curve with control points `points` and weights `weights`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if there are no points, the counts differ, or the
    /// points differ in dimension; [`Error::Weight`] if a weight is zero.
    pub fn new(points: Vec<Vec<T>>, weights: Vec<T>) -> Result<Self, Error> {
        if points.len() != weights.len() {
            return Err(Error::Shape(format!(
                "a degree {} curve needs {} weights, not {}",
                points.len().saturating_sub(1),
                points.len(),
                weights.len()
            )));
        }
        if let Some(i) = weights.iter().position(|w| w.is_zero()) {
            return Err(Error::Weight {
                index: format!("w_{i}"),
                value: "0".into(),
            });
        }
        let ctrl = points
            .iter()
            .zip(&weights)
            .map(|(p, w)| HPoint::from_point(p, w))
            .collect();
        Self::from_hom(ctrl)
    }

    /// The polynomial curve (all weights 1) with control points `points`.
    ///
    /// # Errors
    ///
    /// As [`RationalCurve::new`].
    pub fn polynomial(points: Vec<Vec<T>>) -> Result<Self, Error> {
        let weights = vec![T::one(); points.len()];
        Self::new(points, weights)
    }

    /// The curve with homogeneous control points `(w_i·P_i, w_i)`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if there are no points or they differ in length.
    pub fn from_hom(ctrl: Vec<HPoint<T>>) -> Result<Self, Error> {
        let Some(first) = ctrl.first() else {
            return Err(Error::Shape(
                "a curve needs at least one control point".into(),
            ));
        };
        let len = first.coords.len();
        if len < 2 {
            return Err(Error::Shape(
                "control points need at least one coordinate".into(),
            ));
        }
        if let Some(i) = ctrl.iter().position(|p| p.coords.len() != len) {
            return Err(Error::Shape(format!(
                "control point P_{i} has dimension {}, P_0 has {}",
                ctrl[i].coords.len() - 1,
                len - 1
            )));
        }
        Ok(RationalCurve { ctrl })
    }

    /// The curve with homogeneous control points known to be well formed
    /// (non-empty, equal lengths ≥ 2): the crate's algorithms build these.
    pub(crate) fn from_ctrl(ctrl: Vec<HPoint<T>>) -> Self {
        debug_assert!(
            !ctrl.is_empty() && ctrl.iter().all(|p| p.coords.len() == ctrl[0].coords.len())
        );
        RationalCurve { ctrl }
    }

    /// The same curve over another scalar type, coordinate by coordinate
    /// (e.g. `BigRational` → `f64` with [`Ordered::to_f64`](crate::algebra::Ordered::to_f64), or → `Poly`).
    pub fn map<U: Scalar>(&self, f: impl Fn(&T) -> U) -> RationalCurve<U> {
        RationalCurve {
            ctrl: self.ctrl.iter().map(|p| p.map(&f)).collect(),
        }
    }

    /// The degree `n` (number of control points less one).
    pub fn degree(&self) -> usize {
        self.ctrl.len() - 1
    }

    /// The spatial dimension of the control points.
    pub fn dim(&self) -> usize {
        self.ctrl[0].dim()
    }

    /// The homogeneous control points `(w_i·P_i, w_i)`.
    pub fn ctrl(&self) -> &[HPoint<T>] {
        &self.ctrl
    }

    /// The weights `w_0 … w_n`.
    pub fn weights(&self) -> Vec<T> {
        self.ctrl.iter().map(|p| p.weight().clone()).collect()
    }

    /// Are all weights equal (a polynomial curve up to uniform scaling)?
    pub fn is_polynomial(&self, tol: Tolerance) -> bool {
        let w0 = self.ctrl[0].weight();
        self.ctrl
            .iter()
            .all(|p| (p.weight().clone() - w0).is_zero_within(tol))
    }
}

/// # Evaluation to Cartesian points (division at the end)
impl<T: Field> RationalCurve<T> {
    /// The Cartesian point `X(t)`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes at `t`.
    ///
    /// Computed by the Horner–Bernstein kernel of [`crate::eval`]; exact
    /// types take their fast path (fraction-free for `BigRational`).
    pub fn eval(&self, t: &T) -> Result<Vec<T>, Error> {
        self.eval_many(std::slice::from_ref(t))
    }

    /// The points `X(t)` at every `t` of `ts`, `dim` coordinates each, back
    /// to back (the batch form of [`RationalCurve::eval`]; for repeated
    /// batches without allocation use [`crate::eval::Evaluator`]).
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let c = RationalCurve::polynomial(vec![p(10, 0), p(30, 60), p(130, 60), p(190, 0)]).unwrap();
    /// let xs = c.eval_many(&[ratio(0, 1), ratio(1, 2)]).unwrap();
    /// assert_eq!(xs, vec![ratio(10, 1), ratio(0, 1), ratio(85, 1), ratio(45, 1)]);
    /// ```
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes at some `t`.
    pub fn eval_many(&self, ts: &[T]) -> Result<Vec<T>, Error> {
        crate::eval::eval_points(crate::eval::Net::from_curve(self), ts)
    }

    /// The Cartesian control points `P_i`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if a weight is zero.
    pub fn points(&self) -> Result<Vec<Vec<T>>, Error> {
        self.ctrl.iter().map(HPoint::project).collect()
    }

    /// The Möbius parameter map `u(s) = (α − 1)s / (2αs − s − α)` of
    /// source 000 eq. (2).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] when the denominator `2αs − s − α` is zero.
    pub fn mobius_param(alpha: &T, s: &T) -> Result<T, Error> {
        let one = T::one();
        let two = T::from_i64(2);
        let den = two * alpha * s - s - alpha;
        if den.is_zero() {
            return Err(Error::Domain(format!(
                "Möbius map with α = {alpha:?} has a pole at s = {s:?}"
            )));
        }
        Ok((alpha.clone() - &one) * s / &den)
    }
}

/// # Homogeneous evaluation
impl<T: Scalar> RationalCurve<T> {
    /// The homogeneous point `(Σ w_i P_i B_{i,n}(t), Σ w_i B_{i,n}(t))` by de
    /// Casteljau's algorithm. Exact for exact `T`; ring operations only.
    pub fn eval_hom(&self, t: &T) -> HPoint<T> {
        de_casteljau(&self.ctrl, t)
    }

    /// The homogeneous point at the homogeneous parameter `(a : b)`:
    ///
    /// ```text
    /// Σ_i c_i C(n, i) a^{n−i} bⁱ = (a + b)ⁿ · H(b / (a + b))
    /// ```
    ///
    /// where `c_i = (w_i P_i, w_i)` and `H` is [`RationalCurve::eval_hom`]
    /// (`a = 1 − t, b = t` gives `H(t)`). de Casteljau with the step
    /// `a·c_i + b·c_{i+1}`: ring operations only, no division, so a
    /// parameter `u = N/D` is evaluated as `(D − N : N)` without fractions.
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let c = RationalCurve::polynomial(vec![p(0), p(3), p(9)]).unwrap();
    /// // (2 : 1) is t = 1/3, scaled by (2 + 1)² = 9.
    /// let h = c.eval_hom_param(&ratio(2, 1), &ratio(1, 1));
    /// assert_eq!(h, c.eval_hom(&ratio(1, 3)).scale(&ratio(9, 1)));
    /// ```
    pub fn eval_hom_param(&self, a: &T, b: &T) -> HPoint<T> {
        de_casteljau_hom(&self.ctrl, a, b)
    }
}
