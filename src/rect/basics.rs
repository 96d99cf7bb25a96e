//! Construction, access and evaluation of [`RectPatch`]: the first methods
//! of its page (a module of its own because rustdoc lists the impl blocks
//! of submodules before those of the parent).

use super::RectPatch;
use crate::algebra::scalar::{Field, Scalar};
use crate::error::Error;
use crate::hpoint::{check_same_dimension, de_casteljau, hom_rows, HPoint};

/// # Construction and access
impl<T: Scalar> RectPatch<T> {
    /// The patch with control points `points[i][j]` and weights `weights[i][j]`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the grids are empty, ragged or of different sizes,
    /// or the points differ in dimension; [`Error::Weight`] if a weight is 0.
    pub fn new(points: Vec<Vec<Vec<T>>>, weights: Vec<Vec<T>>) -> Result<Self, Error> {
        Self::from_hom(hom_rows(&points, &weights, "grid", |i, j| {
            format!("{{{i},{j}}}")
        })?)
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
        check_same_dimension(&ctrl, |i, j, dim, first| {
            format!("control point P_{{{i},{j}}} has dimension {dim}, P_{{0,0}} has {first}")
        })?;
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

    /// The homogeneous control net as its vector of rows (what the
    /// coincidence tests read, borrowed rather than copied).
    pub(crate) fn ctrl_rows(&self) -> &Vec<Vec<HPoint<T>>> {
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

/// # Evaluation to Cartesian points
impl<T: Field> RectPatch<T> {
    /// The Cartesian point `X(u, v)`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes there.
    ///
    /// Computed by the Horner–Bernstein kernel of [`crate::eval`]; exact
    /// types take their fast path (fraction-free for `BigRational`).
    pub fn eval(&self, u: &T, v: &T) -> Result<Vec<T>, Error> {
        self.eval_many(&[u.clone(), v.clone()])
    }

    /// The points at the parameter pairs `uv = [u₀, v₀, u₁, v₁, …]`, `dim`
    /// coordinates each, back to back (the batch form of
    /// [`RectPatch::eval`]).
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes at a pair;
    /// [`Error::Shape`] if `uv` has odd length.
    pub fn eval_many(&self, uv: &[T]) -> Result<Vec<T>, Error> {
        crate::eval::eval_points(crate::eval::Net::from_rect(self), uv)
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

/// # Homogeneous evaluation
impl<T: Scalar> RectPatch<T> {
    /// The homogeneous point at `(u, v)`: de Casteljau in v on each row
    /// `i`, then in u on the results (the lecture's second order; the two
    /// orders agree, see the surfaces proofs). Exact for exact `T`.
    pub fn eval_hom(&self, u: &T, v: &T) -> HPoint<T> {
        let col: Vec<HPoint<T>> = self.ctrl.iter().map(|row| de_casteljau(row, v)).collect();
        de_casteljau(&col, u)
    }
}
