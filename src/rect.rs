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

use crate::curve::{elevate_once, mobius_factors};
use crate::error::Error;
use crate::hpoint::{de_casteljau, HPoint};
use crate::scalar::{Field, Ordered, Scalar, Tolerance};

/// A rational tensor-product Bézier patch of bidegree (m, n).
///
/// # Examples
///
/// A bilinear patch evaluated at its centre:
///
/// ```
/// use exact_bezier::{RectPatch, ratio};
/// use num_rational::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let s = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 2)], vec![p(2, 0), p(4, 4)]]).unwrap();
/// // The average of the four corners: (6/4, 6/4).
/// assert_eq!(s.eval(&ratio(1, 2), &ratio(1, 2)).unwrap(), vec![ratio(3, 2), ratio(3, 2)]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RectPatch<T> {
    ctrl: Vec<Vec<HPoint<T>>>,
}

/// # Construction and access
impl<T: Scalar> RectPatch<T> {
    /// The patch with control points `points[i][j]` and weights `weights[i][j]`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the grids are empty, ragged or of different sizes,
    /// or the points differ in dimension; [`Error::Weight`] if a weight is 0.
    pub fn new(points: Vec<Vec<Vec<T>>>, weights: Vec<Vec<T>>) -> Result<Self, Error> {
        if points.len() != weights.len()
            || points.iter().zip(&weights).any(|(p, w)| p.len() != w.len())
        {
            return Err(Error::Shape(
                "the weight grid must have the same shape as the point grid".into(),
            ));
        }
        for (i, row) in weights.iter().enumerate() {
            if let Some(j) = row.iter().position(|w| w.is_zero()) {
                return Err(Error::Weight {
                    index: format!("w_{{{i},{j}}}"),
                    value: "0".into(),
                });
            }
        }
        let ctrl = points
            .iter()
            .zip(&weights)
            .map(|(pr, wr)| {
                pr.iter()
                    .zip(wr)
                    .map(|(p, w)| HPoint::from_point(p, w))
                    .collect()
            })
            .collect();
        Self::from_hom(ctrl)
    }

    /// The polynomial patch (all weights 1) with control points `points[i][j]`.
    ///
    /// # Errors
    ///
    /// As [`RectPatch::new`].
    pub fn polynomial(points: Vec<Vec<Vec<T>>>) -> Result<Self, Error> {
        let weights = points.iter().map(|r| vec![T::one(); r.len()]).collect();
        Self::new(points, weights)
    }

    /// The patch with homogeneous control points `ctrl[i][j]`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the grid is empty or ragged or the points differ in
    /// length.
    pub fn from_hom(ctrl: Vec<Vec<HPoint<T>>>) -> Result<Self, Error> {
        let rows = ctrl.len();
        let cols = ctrl.first().map_or(0, Vec::len);
        if rows == 0 || cols == 0 {
            return Err(Error::Shape(
                "a patch needs at least one control point".into(),
            ));
        }
        if let Some(i) = ctrl.iter().position(|r| r.len() != cols) {
            return Err(Error::Shape(format!(
                "row {i} of the control net has {} points, row 0 has {cols}",
                ctrl[i].len()
            )));
        }
        let len = ctrl[0][0].coords.len();
        if len < 2 {
            return Err(Error::Shape(
                "control points need at least one coordinate".into(),
            ));
        }
        for (i, row) in ctrl.iter().enumerate() {
            if let Some(j) = row.iter().position(|p| p.coords.len() != len) {
                return Err(Error::Shape(format!(
                    "control point P_{{{i},{j}}} has dimension {}, P_{{0,0}} has {}",
                    row[j].coords.len() - 1,
                    len - 1
                )));
            }
        }
        Ok(RectPatch { ctrl })
    }

    /// The same patch over another scalar type, coordinate by coordinate.
    pub fn map<U: Scalar>(&self, f: impl Fn(&T) -> U) -> RectPatch<U> {
        RectPatch {
            ctrl: self
                .ctrl
                .iter()
                .map(|r| r.iter().map(|p| p.map(&f)).collect())
                .collect(),
        }
    }

    /// The bidegree `(m, n)`.
    pub fn degree(&self) -> (usize, usize) {
        (self.ctrl.len() - 1, self.ctrl[0].len() - 1)
    }

    /// The spatial dimension of the control points.
    pub fn dim(&self) -> usize {
        self.ctrl[0][0].dim()
    }

    /// The homogeneous control net, `ctrl()[i][j]`.
    pub fn ctrl(&self) -> &[Vec<HPoint<T>>] {
        &self.ctrl
    }

    /// The weights `ω_{i,j}`.
    pub fn weights(&self) -> Vec<Vec<T>> {
        self.ctrl
            .iter()
            .map(|r| r.iter().map(|p| p.weight().clone()).collect())
            .collect()
    }
}

/// # Evaluation and reparameterization
impl<T: Scalar> RectPatch<T> {
    /// The homogeneous point at `(u, v)`: de Casteljau in v on each row
    /// `i`, then in u on the results (the lecture's second order; the two
    /// orders agree, see the surfaces proofs). Exact for exact `T`.
    pub fn eval_hom(&self, u: &T, v: &T) -> HPoint<T> {
        let col: Vec<HPoint<T>> = self.ctrl.iter().map(|row| de_casteljau(row, v)).collect();
        de_casteljau(&col, u)
    }

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
        let rows: Vec<Vec<HPoint<T>>> = self.ctrl.iter().map(|row| elevate_row(row, s)).collect();
        let swapped = RectPatch { ctrl: rows }.swap_uv();
        let cols: Vec<Vec<HPoint<T>>> = swapped.ctrl.iter().map(|c| elevate_row(c, r)).collect();
        RectPatch { ctrl: cols }.swap_uv()
    }
}

fn elevate_row<T: Scalar>(row: &[HPoint<T>], times: usize) -> Vec<HPoint<T>> {
    (0..times).fold(row.to_vec(), |acc, _| elevate_once(&acc))
}

/// # Cartesian results
impl<T: Field> RectPatch<T> {
    /// The Cartesian point `X(u, v)`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes there.
    pub fn eval(&self, u: &T, v: &T) -> Result<Vec<T>, Error> {
        self.eval_hom(u, v).project()
    }

    /// The Cartesian control points `P_{i,j}`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if a weight is zero.
    pub fn points(&self) -> Result<Vec<Vec<Vec<T>>>, Error> {
        self.ctrl
            .iter()
            .map(|r| r.iter().map(HPoint::project).collect())
            .collect()
    }
}

/// # Validation of weights
impl<T: Ordered> RectPatch<T> {
    /// Check that every weight is positive.
    ///
    /// # Errors
    ///
    /// [`Error::Weight`] naming the first non-positive weight.
    pub fn check_positive_weights(&self) -> Result<(), Error> {
        for (i, row) in self.ctrl.iter().enumerate() {
            for (j, p) in row.iter().enumerate() {
                if !p.weight().is_positive_within(Tolerance::EXACT) {
                    return Err(Error::Weight {
                        index: format!("w_{{{i},{j}}}"),
                        value: format!("{}", p.weight().to_f64()),
                    });
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::ratio;
    use num_rational::BigRational;
    type Q = BigRational;

    #[test]
    fn corners_interpolate_and_mobius_keeps_points() {
        let p = |x: i64, y: i64, z: i64| vec![ratio::<Q>(x, 1), ratio(y, 1), ratio(z, 1)];
        let pts = vec![
            vec![p(0, 0, 0), p(0, 1, 2), p(0, 3, 1)],
            vec![p(2, 0, 1), p(2, 2, 5), p(1, 3, 0)],
        ];
        let w = vec![
            vec![ratio(1, 1), ratio(2, 1), ratio(1, 2)],
            vec![ratio(3, 1), ratio(1, 1), ratio(1, 1)],
        ];
        let s = RectPatch::new(pts.clone(), w).unwrap();
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
