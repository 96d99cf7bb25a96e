//! [`TrigCurve`]: the cubic trigonometric curve with shape parameter α,
//! `p(t) = Σᵢ Xᵢ(t; α) Pᵢ`, `t ∈ [0, π/2]` (source 002, Definition 2).
//!
//! Reference: source 002 Definition 2 and its properties 1)–6).

use super::basis::{combine, trig_basis_values, TrigFn, TrigParam};
use crate::algebra::scalar::Scalar;
use crate::error::Error;

/// A cubic trigonometric curve: four control points and a shape parameter α.
///
/// # Examples
///
/// ```
/// use exact_bezier::{ratio, trig::TrigCurve, trig::TrigParam};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let c = TrigCurve::new(vec![p(0, 0), p(1, 2), p(3, 2), p(4, 0)], ratio(1, 1)).unwrap();
/// assert_eq!(c.eval(&TrigParam::end()), p(4, 0));
/// // p'(0) = α (P₁ − P₀).
/// assert_eq!(c.derivative(1, &TrigParam::start()), p(1, 2));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TrigCurve<T> {
    points: Vec<Vec<T>>,
    alpha: T,
}

impl<T: Scalar> TrigCurve<T> {
    /// The curve with control points `P₀…P₃` and shape parameter α.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless there are exactly four points of one non-zero
    /// dimension.
    pub fn new(points: Vec<Vec<T>>, alpha: T) -> Result<Self, Error> {
        check_points(&points, "a trig curve")?;
        Ok(TrigCurve { points, alpha })
    }

    /// The control points `P₀…P₃`.
    pub fn points(&self) -> &[Vec<T>] {
        &self.points
    }

    /// The shape parameter α.
    pub fn alpha(&self) -> &T {
        &self.alpha
    }

    /// `p(t) = Σᵢ Xᵢ(t; α) Pᵢ`.
    pub fn eval(&self, at: &TrigParam<T>) -> Vec<T> {
        self.derivative(0, at)
    }

    /// `p⁽ᵏ⁾(t) = Σᵢ Xᵢ⁽ᵏ⁾(t; α) Pᵢ`, exact in the `(s, c)` representation.
    pub fn derivative(&self, k: usize, at: &TrigParam<T>) -> Vec<T> {
        combine(&trig_basis_values(&self.alpha, k, at), &self.points)
    }

    /// The curve as one function per coordinate: coefficients on
    /// `1, s, c, s², s c`. Two curves are the same map `t ↦ p(t)` iff these
    /// agree (the five functions are linearly independent on `[0, π/2]`).
    pub fn functions(&self) -> Vec<TrigFn<T>> {
        let basis = TrigFn::basis(&self.alpha);
        (0..self.points[0].len())
            .map(|d| {
                let coeffs = std::array::from_fn(|k| {
                    basis
                        .iter()
                        .zip(&self.points)
                        .fold(T::zero(), |acc, (x, p)| {
                            acc + &(x.coeffs()[k].clone() * &p[d])
                        })
                });
                TrigFn::new(coeffs)
            })
            .collect()
    }

    /// The same curve traversed backwards, `t ↦ π/2 − t`: the control
    /// points in reverse order (since `Xᵢ(π/2 − t) = X₃₋ᵢ(t)`).
    pub fn reverse(&self) -> Self {
        let mut points = self.points.clone();
        points.reverse();
        TrigCurve {
            points,
            alpha: self.alpha.clone(),
        }
    }

    /// Apply `f` to every coordinate and to α (e.g. exact → `f64`).
    pub fn map<U: Scalar>(&self, f: impl Fn(&T) -> U) -> TrigCurve<U> {
        TrigCurve {
            points: self
                .points
                .iter()
                .map(|p| p.iter().map(&f).collect())
                .collect(),
            alpha: f(&self.alpha),
        }
    }
}

/// Four points of one non-zero dimension.
pub(crate) fn check_points<T>(points: &[Vec<T>], what: &str) -> Result<(), Error> {
    if points.len() != 4 {
        return Err(Error::Shape(format!(
            "{what} needs 4 control points, not {}",
            points.len()
        )));
    }
    let dim = points[0].len();
    if dim == 0 || points.iter().any(|p| p.len() != dim) {
        return Err(Error::Shape(format!(
            "the control points of {what} must have one non-zero dimension"
        )));
    }
    Ok(())
}
