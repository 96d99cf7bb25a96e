//! Construction, access and evaluation of [`TriPatch`]: the first methods
//! of its page (a module of its own because rustdoc lists the impl blocks
//! of submodules before those of the parent).

use super::{casteljau_level, TriPatch};
use crate::algebra::scalar::{Field, Scalar};
use crate::error::Error;
use crate::hpoint::{check_same_dimension, hom_rows, HPoint};

/// # Construction and access
impl<T: Scalar> TriPatch<T> {
    /// The patch with control points `points[j][i] = P_{i,j,n−i−j}` and
    /// weights in the same layout.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if row `j` does not hold `n − j + 1` entries, or the
    /// points differ in dimension; [`Error::Weight`] if a weight is zero.
    pub fn new(points: Vec<Vec<Vec<T>>>, weights: Vec<Vec<T>>) -> Result<Self, Error> {
        Self::from_hom(hom_rows(&points, &weights, "rows", |j, i| {
            format!("{{{i},{j}}}")
        })?)
    }

    /// The polynomial patch (all weights 1).
    ///
    /// # Errors
    ///
    /// As [`TriPatch::new`].
    pub fn polynomial(points: Vec<Vec<Vec<T>>>) -> Result<Self, Error> {
        let weights = points.iter().map(|r| vec![T::one(); r.len()]).collect();
        Self::new(points, weights)
    }

    /// The patch with homogeneous rows `rows[j][i] = (ω P, ω)_{i,j,n−i−j}`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] on a wrong triangular layout or mixed dimensions.
    pub fn from_hom(rows: Vec<Vec<HPoint<T>>>) -> Result<Self, Error> {
        if rows.is_empty() {
            return Err(Error::Shape(
                "a triangular patch needs at least one row".into(),
            ));
        }
        let n = rows.len() - 1;
        for (j, row) in rows.iter().enumerate() {
            if row.len() != n - j + 1 {
                return Err(Error::Shape(format!(
                    "row {j} of a degree {n} triangular patch needs {} points, not {}",
                    n - j + 1,
                    row.len()
                )));
            }
        }
        check_same_dimension(&rows, |j, i, dim, first| {
            format!(
                "control point P_{{{i},{j},{}}} has dimension {dim}, expected {first}",
                n - i - j
            )
        })?;
        Ok(TriPatch { n, rows })
    }

    /// The same patch over another scalar type, coordinate by coordinate.
    pub fn map<U: Scalar>(&self, f: impl Fn(&T) -> U) -> TriPatch<U> {
        TriPatch {
            n: self.n,
            rows: self
                .rows
                .iter()
                .map(|r| r.iter().map(|p| p.map(&f)).collect())
                .collect(),
        }
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.n
    }

    /// The spatial dimension of the control points.
    pub fn dim(&self) -> usize {
        self.rows[0][0].dim()
    }

    /// The homogeneous control point `P_{i,j,n−i−j}`. **Panics if `i + j > n`.**
    pub fn get(&self, i: usize, j: usize) -> &HPoint<T> {
        &self.rows[j][i]
    }

    /// The homogeneous rows, `rows()[j][i]`.
    pub fn rows(&self) -> &[Vec<HPoint<T>>] {
        &self.rows
    }

    /// The weights in row layout.
    pub fn weights(&self) -> Vec<Vec<T>> {
        self.rows
            .iter()
            .map(|r| r.iter().map(|p| p.weight().clone()).collect())
            .collect()
    }

    /// The homogeneous point at barycentric `(u, v, w)` by triangular de
    /// Casteljau: `P^r_{ijk} = u P^{r−1}_{i+1,j,k} + v P^{r−1}_{i,j+1,k} +
    /// w P^{r−1}_{i,j,k+1}` (source 001). `u + v + w = 1` is not required:
    /// other triples give the homogeneous extension.
    pub fn eval_hom_bary(&self, u: &T, v: &T, w: &T) -> HPoint<T> {
        let b = [u.clone(), v.clone(), w.clone()];
        let mut rows = self.rows.clone();
        for _ in 0..self.n {
            rows = casteljau_level(&rows, &b);
        }
        rows.swap_remove(0).swap_remove(0)
    }

    /// The homogeneous point at `(u, v)` with `w = 1 − u − v`.
    pub fn eval_hom(&self, u: &T, v: &T) -> HPoint<T> {
        let w = T::one() - u - v;
        self.eval_hom_bary(u, v, &w)
    }
}

/// # Evaluation to Cartesian points
impl<T: Field> TriPatch<T> {
    /// The Cartesian point at `(u, v, 1 − u − v)`.
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

    /// The points at the parameter pairs `uv = [u₀, v₀, u₁, v₁, …]`
    /// (`w = 1 − u − v`), `dim` coordinates each, back to back (the batch
    /// form of [`TriPatch::eval`]).
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes at a pair;
    /// [`Error::Shape`] if `uv` has odd length.
    pub fn eval_many(&self, uv: &[T]) -> Result<Vec<T>, Error> {
        crate::eval::eval_points(crate::eval::Net::from_tri(self), uv)
    }
}
