//! [`RectPatch`]: rational tensor-product Bézier patches of bidegree (m, n),
//! in homogeneous form, generic over the scalar.
//!
//! Conventions: parameters `(u, v) ∈ [0, 1]²`; `ctrl[i][j]` is the
//! homogeneous point `(ω_{i,j} P_{i,j}, ω_{i,j})`, `i = 0…m` the u index and
//! `j = 0…n` the v index;
//!
//! ```text
//! X(u, v) = Σ_i Σ_j ω_{i,j} P_{i,j} B_{i,m}(u) B_{j,n}(v) / Σ_i Σ_j ω_{i,j} B_{i,m}(u) B_{j,n}(v)
//! ```
//!
//! Reference: source 001 (lecture), "矩形域曲面"; source 000 eq. (1).

mod basics;
pub mod join;
pub mod ops;

pub use join::{g0_join, g1_join};
pub use ops::Corner;

use crate::algebra::scalar::{Field, Ordered, Scalar};
use crate::curve::{elevate_by, mobius_factors, RationalCurve};
use crate::error::Error;
use crate::eval::{Evaluator, Jets, Net, Shape};
use crate::hpoint::{check_positive_weights, de_casteljau, HPoint};

/// A rational tensor-product Bézier patch of bidegree (m, n).
///
/// # Examples
///
/// A bilinear patch evaluated at its centre:
///
/// ```
/// use exact_bezier::{RectPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let s = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 2)], vec![p(2, 0), p(4, 4)]]).unwrap();
/// // The average of the four corners: (6/4, 6/4).
/// assert_eq!(s.eval(&ratio(1, 2), &ratio(1, 2)).unwrap(), vec![ratio(3, 2), ratio(3, 2)]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RectPatch<T> {
    ctrl: Vec<Vec<HPoint<T>>>,
}

/// # Möbius maps and weight scaling
impl<T: Scalar> RectPatch<T> {
    /// Linear Möbius map in u (source 000, eq. 2): weights
    /// `ω̃_{i,j} = ω_{i,j} (1 − α)^i α^{m−i}` (eq. 4), points unchanged.
    pub fn mobius_u(&self, alpha: &T) -> Self {
        let f = mobius_factors(alpha, &(T::one() - alpha), self.degree().0);
        let ctrl = self
            .ctrl
            .iter()
            .zip(&f)
            .map(|(row, fi)| row.iter().map(|p| p.scale(fi)).collect())
            .collect();
        RectPatch { ctrl }
    }

    /// Linear Möbius map in v (source 000, eq. 3): weights
    /// `ω̃_{i,j} = ω_{i,j} (1 − β)^j β^{n−j}` (eq. 4), points unchanged.
    pub fn mobius_v(&self, beta: &T) -> Self {
        let f = mobius_factors(beta, &(T::one() - beta), self.degree().1);
        let ctrl = self
            .ctrl
            .iter()
            .map(|row| row.iter().zip(&f).map(|(p, fj)| p.scale(fj)).collect())
            .collect();
        RectPatch { ctrl }
    }

    /// Multiply every weight by `k` (source 000, eq. 5).
    pub fn scale_weights(&self, k: &T) -> Self {
        RectPatch {
            ctrl: self
                .ctrl
                .iter()
                .map(|row| row.iter().map(|p| p.scale(k)).collect())
                .collect(),
        }
    }
}

/// # Symmetries and degree elevation
impl<T: Scalar> RectPatch<T> {
    /// Swap the parameters: the new patch at `(u, v)` is the old at `(v, u)`;
    /// `P̃_{j,i} = P_{i,j}`.
    pub fn swap_uv(&self) -> Self {
        let (m, n) = self.degree();
        let ctrl = (0..=n)
            .map(|j| (0..=m).map(|i| self.ctrl[i][j].clone()).collect())
            .collect();
        RectPatch { ctrl }
    }

    /// Reverse u: the new patch at `(u, v)` is the old at `(1 − u, v)`.
    pub fn reverse_u(&self) -> Self {
        let mut ctrl = self.ctrl.clone();
        ctrl.reverse();
        RectPatch { ctrl }
    }

    /// Reverse v: the new patch at `(u, v)` is the old at `(u, 1 − v)`.
    pub fn reverse_v(&self) -> Self {
        let ctrl = self
            .ctrl
            .iter()
            .map(|r| r.iter().rev().cloned().collect())
            .collect();
        RectPatch { ctrl }
    }

    /// Raise the bidegree by `(r, s)`, keeping every point: curve elevation
    /// (source 001, "升阶") on every column (u) and every row (v).
    pub fn elevate(&self, r: usize, s: usize) -> Self {
        let rows: Vec<Vec<HPoint<T>>> = self.ctrl.iter().map(|row| elevate_by(row, s)).collect();
        let swapped = RectPatch { ctrl: rows }.swap_uv();
        let cols: Vec<Vec<HPoint<T>>> = swapped.ctrl.iter().map(|c| elevate_by(c, r)).collect();
        RectPatch { ctrl: cols }.swap_uv()
    }
}

/// # The lecture's two de Casteljau orders, and homogeneous parameters
impl<T: Scalar> RectPatch<T> {
    /// The homogeneous point at `(u, v)` by the lecture's **first** order:
    /// `P^{k,0}_{i,j} = (1 − u) P^{k−1,0}_{i,j} + u P^{k−1,0}_{i+1,j}` for
    /// `k = 1…m` (every column reduced in u), then
    /// `P^{m,l}_{0,j} = (1 − v) P^{m,l−1}_{0,j} + v P^{m,l−1}_{0,j+1}` for
    /// `l = 1…n`. [`RectPatch::eval_hom`] is the second order (v first); the
    /// two agree for every (u, v) (proofs family `surfaces`).
    ///
    /// Reference: source 001 (lecture), "de Casteljau算法" for surfaces.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let s = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 2)], vec![p(2, 0), p(4, 4)]]).unwrap();
    /// let (u, v) = (ratio(1, 3), ratio(3, 4));
    /// assert_eq!(s.eval_hom_u_first(&u, &v), s.eval_hom(&u, &v));
    /// ```
    pub fn eval_hom_u_first(&self, u: &T, v: &T) -> HPoint<T> {
        let (_, n) = self.degree();
        let row: Vec<HPoint<T>> = (0..=n)
            .map(|j| {
                let col: Vec<HPoint<T>> = self.ctrl.iter().map(|r| r[j].clone()).collect();
                de_casteljau(&col, u)
            })
            .collect();
        de_casteljau(&row, v)
    }

    /// Evaluation at homogeneous parameters: `Σ_i Σ_j C(m,i) C(n,j)
    /// u₁^i u₀^{m−i} v₁^j v₀^{n−j} ω_{i,j}(P_{i,j}, 1)`, which is
    /// `(u₀ + u₁)^m (v₀ + v₁)^n` times the homogeneous point at
    /// `(u₁/(u₀+u₁), v₁/(v₀+v₁))`. With `(u₀, u₁) = (1 − u, u)` it is
    /// [`RectPatch::eval_hom`]. Ring operations only, so a rational parameter
    /// map such as a Möbius map can be substituted without division.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let s = RectPatch::polynomial(vec![vec![p(0), p(1)], vec![p(2), p(5)]]).unwrap();
    /// // (u₀, u₁) = (2, 2) is u = 1/2 scaled by 4; (v₀, v₁) = (1, 0) is v = 0.
    /// let h = s.eval_hom_projective(&[ratio(2, 1), ratio(2, 1)], &[ratio(1, 1), ratio(0, 1)]);
    /// assert_eq!(h, s.eval_hom(&ratio(1, 2), &ratio(0, 1)).scale(&ratio(4, 1)));
    /// ```
    pub fn eval_hom_projective(&self, u: &[T; 2], v: &[T; 2]) -> HPoint<T> {
        let col: Vec<HPoint<T>> = self
            .ctrl
            .iter()
            .map(|row| de_casteljau_projective(row, v))
            .collect();
        de_casteljau_projective(&col, u)
    }
}

/// de Casteljau with homogeneous parameter `(a, b)`: `b_i ← a·b_i + b·b_{i+1}`.
fn de_casteljau_projective<T: Scalar>(points: &[HPoint<T>], ab: &[T; 2]) -> HPoint<T> {
    crate::hpoint::de_casteljau_hom(points, &ab[0], &ab[1])
}

/// # Rows, columns, iso-parameter and boundary curves
impl<T: Scalar> RectPatch<T> {
    /// Column `j` (fixed v index): the homogeneous points `ctrl[0..=m][j]`.
    pub fn column(&self, j: usize) -> Vec<HPoint<T>> {
        self.ctrl.iter().map(|r| r[j].clone()).collect()
    }

    /// Apply a curve operation to every column (the u direction): column `j`
    /// becomes `f(column j)`; all results must have the same length.
    pub(crate) fn map_columns(&self, f: impl Fn(&[HPoint<T>]) -> Vec<HPoint<T>>) -> Self {
        let cols: Vec<Vec<HPoint<T>>> = (0..=self.degree().1).map(|j| f(&self.column(j))).collect();
        RectPatch { ctrl: cols }.swap_uv()
    }

    /// Apply a curve operation to every row (the v direction).
    pub(crate) fn map_rows(&self, f: impl Fn(&[HPoint<T>]) -> Vec<HPoint<T>>) -> Self {
        RectPatch {
            ctrl: self.ctrl.iter().map(|r| f(r)).collect(),
        }
    }

    /// The iso-parameter curve `v ↦ X(u₀, v)`, a rational curve of degree n:
    /// control points `Σ_i B_{i,m}(u₀) ω_{i,j}(P_{i,j}, 1)` (de Casteljau in u
    /// on every column). Exact for exact `T`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let s = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 2)], vec![p(2, 0), p(4, 4)]]).unwrap();
    /// let c = s.iso_u(&ratio(1, 2));
    /// assert_eq!(c.eval(&ratio(1, 3)).unwrap(), s.eval(&ratio(1, 2), &ratio(1, 3)).unwrap());
    /// ```
    pub fn iso_u(&self, u0: &T) -> RationalCurve<T> {
        let ctrl = (0..=self.degree().1)
            .map(|j| de_casteljau(&self.column(j), u0))
            .collect();
        RationalCurve::from_hom(ctrl).expect("a patch has at least one column")
    }

    /// The iso-parameter curve `u ↦ X(u, v₀)`, a rational curve of degree m.
    /// Exact for exact `T`.
    pub fn iso_v(&self, v0: &T) -> RationalCurve<T> {
        let ctrl = self.ctrl.iter().map(|r| de_casteljau(r, v0)).collect();
        RationalCurve::from_hom(ctrl).expect("a patch has at least one row")
    }

    /// A boundary curve, read off the control net (no arithmetic):
    /// `X(u, 0)` is row `j = 0` of the net, `X(1, v)` is `P_{m,0…n}`, etc.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, rect::Side, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let s = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 2)], vec![p(2, 0), p(4, 4)]]).unwrap();
    /// assert_eq!(s.boundary(Side::U1).points().unwrap(), vec![p(2, 0), p(4, 4)]);
    /// ```
    pub fn boundary(&self, side: Side) -> RationalCurve<T> {
        let (m, n) = self.degree();
        let ctrl = match side {
            Side::U0 => self.ctrl[0].clone(),
            Side::U1 => self.ctrl[m].clone(),
            Side::V0 => self.column(0),
            Side::V1 => self.column(n),
        };
        RationalCurve::from_hom(ctrl).expect("a patch has at least one control point")
    }
}

/// A side of the parameter square `[0, 1]²`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// `u = 0`: the curve `v ↦ X(0, v)`.
    U0,
    /// `u = 1`: the curve `v ↦ X(1, v)`.
    U1,
    /// `v = 0`: the curve `u ↦ X(u, 0)`.
    V0,
    /// `v = 1`: the curve `u ↦ X(u, 1)`.
    V1,
}

/// # Validation of weights
impl<T: Ordered> RectPatch<T> {
    /// Check that every weight is positive.
    ///
    /// # Errors
    ///
    /// [`Error::Weight`] naming the first non-positive weight.
    pub fn check_positive_weights(&self) -> Result<(), Error> {
        check_positive_weights(&self.ctrl, |i, j| format!("{{{i},{j}}}"))
    }
}

/// # Batch evaluation (the nets of [`crate::eval`])
impl<T: Scalar> Net<T> {
    /// The net of a rect patch.
    pub fn from_rect(r: &RectPatch<T>) -> Self {
        let (m, n) = r.degree();
        Net::from_points(r.ctrl().iter().flatten(), Shape::Rect(m, n))
            .expect("a validated patch has a consistent net")
    }
}

impl<T: Field> Evaluator<T> {
    /// An evaluator of a rect patch.
    pub fn rect(r: &RectPatch<T>) -> Self {
        Self::new(Net::from_rect(r))
    }
}

impl<T: Scalar> Jets<T> {
    /// The jets of a rect patch: `H`, `H_u`, `H_v`.
    pub fn rect(r: &RectPatch<T>) -> Self {
        Self::new(Net::from_rect(r))
    }
}

#[cfg(test)]
mod tests {
    use crate::algebra::scalar::ratio;
    use crate::samples::{rect_1x2, rect_1x2_points};
    use num_rational::BigRational;
    type Q = BigRational;

    #[test]
    fn corners_interpolate_and_mobius_keeps_points() {
        let (pts, s) = (rect_1x2_points(), rect_1x2());
        assert_eq!(s.degree(), (1, 2));
        assert_eq!(s.eval(&ratio(1, 1), &ratio(1, 1)).unwrap(), pts[1][2]);
        let (a, b) = (ratio::<Q>(1, 3), ratio::<Q>(3, 5));
        let m = s.mobius_u(&a).mobius_v(&b);
        let (ss, tt) = (ratio::<Q>(2, 7), ratio::<Q>(5, 9));
        let u = crate::RationalCurve::mobius_param(&a, &ss).unwrap();
        let v = crate::RationalCurve::mobius_param(&b, &tt).unwrap();
        assert_eq!(m.eval(&ss, &tt).unwrap(), s.eval(&u, &v).unwrap());
        let one = ratio::<Q>(1, 1);
        let e = s.elevate(2, 1);
        assert_eq!(e.degree(), (3, 3));
        assert_eq!(e.eval(&ss, &tt).unwrap(), s.eval(&ss, &tt).unwrap());
        assert_eq!(
            s.swap_uv().eval(&tt, &ss).unwrap(),
            s.eval(&ss, &tt).unwrap()
        );
        let back = s.reverse_u().reverse_v();
        assert_eq!(
            back.eval(&(one.clone() - &ss), &(one - &tt)).unwrap(),
            s.eval(&ss, &tt).unwrap()
        );
    }
}
