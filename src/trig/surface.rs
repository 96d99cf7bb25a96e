//! [`TrigRect`]: the tensor-product trigonometric surface with shape
//! parameters (α₁, α₂) (source 002, Definition 3, eq. (3)):
//!
//! ```text
//! S(u, v; α₁, α₂) = Σᵢ Σⱼ Xᵢ(u; α₁) Xⱼ(v; α₂) Pᵢⱼ,   u, v ∈ [0, π/2]
//! ```
//!
//! `points[i][j] = Pᵢⱼ`, `i` the u index. α₁ shapes the u direction, α₂ the v
//! direction.
//!
//! Reference: source 002 eq. (3) and its properties 1)–5).

use super::basis::{combine, trig_basis_values, TrigParam};
use super::curve::{check_points, TrigCurve};
use crate::algebra::scalar::Scalar;
use crate::error::Error;

/// A bicubic trigonometric surface with shape parameters (α₁, α₂).
///
/// # Examples
///
/// ```
/// use exact_bezier::{ratio, trig::TrigParam, trig::TrigRect};
/// use exact_bezier::BigRational;
/// let net: Vec<Vec<Vec<BigRational>>> = (0..4)
///     .map(|i| (0..4).map(|j| vec![ratio(i, 1), ratio(j, 1), ratio(i * j, 1)]).collect())
///     .collect();
/// let s = TrigRect::new(net, [ratio(1, 1), ratio(1, 2)]).unwrap();
/// let (o, e) = (TrigParam::start(), TrigParam::end());
/// assert_eq!(s.eval(&e, &o), vec![ratio(3, 1), ratio(0, 1), ratio(0, 1)]); // S(π/2, 0) = P₃₀
/// // ∂S/∂v(0, 0) = α₂ (P₀₁ − P₀₀).
/// assert_eq!(s.partial(0, 1, &o, &o), vec![ratio(0, 1), ratio(1, 2), ratio(0, 1)]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TrigRect<T> {
    points: Vec<Vec<Vec<T>>>,
    alpha: [T; 2],
}

impl<T: Scalar> TrigRect<T> {
    /// The surface with the 4 × 4 net `points[i][j] = Pᵢⱼ` and shape
    /// parameters `[α₁, α₂]`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless the net is 4 × 4 points of one non-zero
    /// dimension.
    pub fn new(points: Vec<Vec<Vec<T>>>, alpha: [T; 2]) -> Result<Self, Error> {
        if points.len() != 4 {
            return Err(Error::Shape(format!(
                "a trig-rect needs 4 rows of control points, not {}",
                points.len()
            )));
        }
        for row in &points {
            check_points(row, "each row of a trig-rect")?;
        }
        if points.iter().any(|r| r[0].len() != points[0][0].len()) {
            return Err(Error::Shape(
                "the control points of a trig-rect must have one dimension".into(),
            ));
        }
        Ok(TrigRect { points, alpha })
    }

    /// The net `Pᵢⱼ` (`[i][j]`, `i` the u index).
    pub fn points(&self) -> &[Vec<Vec<T>>] {
        &self.points
    }

    /// The shape parameters `[α₁, α₂]`.
    pub fn alpha(&self) -> &[T; 2] {
        &self.alpha
    }

    /// `S(u, v) = Σᵢ Σⱼ Xᵢ(u; α₁) Xⱼ(v; α₂) Pᵢⱼ`.
    pub fn eval(&self, u: &TrigParam<T>, v: &TrigParam<T>) -> Vec<T> {
        self.partial(0, 0, u, v)
    }

    /// The partial derivative `∂^{ku+kv} S / ∂u^{ku} ∂v^{kv}` at `(u, v)`:
    /// `Σᵢ Σⱼ Xᵢ⁽ᵏᵘ⁾(u; α₁) Xⱼ⁽ᵏᵛ⁾(v; α₂) Pᵢⱼ`.
    pub fn partial(&self, ku: usize, kv: usize, u: &TrigParam<T>, v: &TrigParam<T>) -> Vec<T> {
        self.u_curve(kv, v).derivative(ku, u)
    }

    /// The curve `u ↦ ∂^{kv} S/∂v^{kv}(u, v)` at a fixed `v`: a trig curve
    /// with shape parameter α₁ and control points `Σⱼ Xⱼ⁽ᵏᵛ⁾(v; α₂) Pᵢⱼ`.
    /// With `kv = 0` and `v = 0` or `π/2` it is a boundary curve; with
    /// `kv = 1` a cross-boundary derivative.
    pub fn u_curve(&self, kv: usize, v: &TrigParam<T>) -> TrigCurve<T> {
        let w = trig_basis_values(&self.alpha[1], kv, v);
        TrigCurve::new(
            self.points.iter().map(|row| combine(&w, row)).collect(),
            self.alpha[0].clone(),
        )
        .expect("a 4 × 4 net gives four points")
    }

    /// The curve `v ↦ ∂^{ku} S/∂u^{ku}(u, v)` at a fixed `u` (shape α₂).
    pub fn v_curve(&self, ku: usize, u: &TrigParam<T>) -> TrigCurve<T> {
        self.swap_uv().u_curve(ku, u)
    }

    /// The surface with u and v exchanged: `Pᵢⱼ ↦ Pⱼᵢ`, `(α₁, α₂) ↦ (α₂, α₁)`.
    pub fn swap_uv(&self) -> Self {
        let points = (0..4)
            .map(|j| (0..4).map(|i| self.points[i][j].clone()).collect())
            .collect();
        let [a1, a2] = self.alpha.clone();
        TrigRect {
            points,
            alpha: [a2, a1],
        }
    }

    /// The surface with v reversed, `v ↦ π/2 − v` (columns `j ↦ 3 − j`).
    pub fn reverse_v(&self) -> Self {
        let mut points = self.points.clone();
        points.iter_mut().for_each(|row| row.reverse());
        TrigRect {
            points,
            alpha: self.alpha.clone(),
        }
    }

    /// Apply `f` to every coordinate and both shape parameters.
    pub fn map<U: Scalar>(&self, f: impl Fn(&T) -> U) -> TrigRect<U> {
        TrigRect {
            points: self
                .points
                .iter()
                .map(|row| row.iter().map(|p| p.iter().map(&f).collect()).collect())
                .collect(),
            alpha: [f(&self.alpha[0]), f(&self.alpha[1])],
        }
    }
}
