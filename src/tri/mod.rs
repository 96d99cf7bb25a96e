//! [`TriPatch`]: rational triangular Bézier patches of degree n, in
//! homogeneous form, generic over the scalar.
//!
//! Conventions (DESIGN §4): barycentric coordinates `(u, v, w)`,
//! `w = 1 − u − v`; the control point `P_{i,j,k}` (`i + j + k = n`) carries
//! the exponents of `u`, `v`, `w`:
//!
//! ```text
//! X(u, v, w) = Σ ω_{ijk} P_{ijk} B^n_{ijk}(u, v, w) / Σ ω_{ijk} B^n_{ijk}(u, v, w),
//! B^n_{ijk} = n!/(i! j! k!) uⁱ vʲ wᵏ
//! ```
//!
//! Storage follows the JSON rows: row `j` holds the `n − j + 1` points with
//! v-exponent `j`, ordered by `i`.
//!
//! Reference: source 001 (lecture), "三角域Bézier曲面".

use crate::algebra::scalar::{Field, Ordered, Ring, Scalar};
use crate::error::Error;
use crate::eval::{eval_points, Evaluator, Jets, Net, Shape};
use crate::hpoint::{check_positive_weights, check_same_dimension, hom_rows, HPoint};

pub mod ops;
pub use ops::{affine_combination, tri_bernstein, Bary, SYMMETRIES};

/// One level of triangular de Casteljau with barycentric `b = (u, v, w)`:
/// from the rows of level r (entries `(i, j)`, `i + j ≤ r`) to level r − 1,
/// `P'_{i,j} = u P_{i+1,j} + v P_{i,j+1} + w P_{i,j}` (k implicit).
/// **Panics if `rows` has a single row (level 0).**
pub(crate) fn casteljau_level<T: Ring>(
    rows: &[Vec<HPoint<T>>],
    b: &Bary<T>,
) -> Vec<Vec<HPoint<T>>> {
    let r = rows.len() - 1;
    (0..r)
        .map(|j| {
            (0..r - j)
                .map(|i| {
                    rows[j][i + 1]
                        .scale(&b[0])
                        .add(&rows[j + 1][i].scale(&b[1]))
                        .add(&rows[j][i].scale(&b[2]))
                })
                .collect()
        })
        .collect()
}

/// A rational triangular Bézier patch of degree n.
///
/// # Examples
///
/// The linear patch with vertices (1,0) at u=1, (0,1) at v=1 and (0,0) at
/// w=1 is the identity map on the triangle:
///
/// ```
/// use exact_bezier::{TriPatch, ratio};
/// use num_rational::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// // rows by j: [P_{0,0,1}, P_{1,0,0}], [P_{0,1,0}]
/// let t = TriPatch::polynomial(vec![vec![p(0, 0), p(1, 0)], vec![p(0, 1)]]).unwrap();
/// let (u, v) = (ratio(1, 5), ratio(2, 5));
/// assert_eq!(t.eval(&u, &v).unwrap(), vec![u, v]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TriPatch<T> {
    n: usize,
    /// `rows[j][i]` = homogeneous `P_{i,j,n−i−j}`.
    rows: Vec<Vec<HPoint<T>>>,
}

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

/// # Cartesian results
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
        eval_points(Net::from_tri(self), uv)
    }
}

/// # Validation of weights
impl<T: Ordered> TriPatch<T> {
    /// Check that every weight is positive.
    ///
    /// # Errors
    ///
    /// [`Error::Weight`] naming the first non-positive weight.
    pub fn check_positive_weights(&self) -> Result<(), Error> {
        check_positive_weights(&self.rows, |j, i| format!("{{{i},{j},{}}}", self.n - i - j))
    }
}

/// # Batch evaluation (the nets of [`crate::eval`])
impl<T: Scalar> Net<T> {
    /// The net of a tri patch.
    pub fn from_tri(t: &TriPatch<T>) -> Self {
        Net::from_points(t.rows().iter().flatten(), Shape::Tri(t.degree()))
            .expect("a validated patch has a consistent net")
    }
}

impl<T: Field> Evaluator<T> {
    /// An evaluator of a tri patch.
    pub fn tri(t: &TriPatch<T>) -> Self {
        Self::new(Net::from_tri(t))
    }
}

impl<T: Scalar> Jets<T> {
    /// The jets of a tri patch: `H`, `H_u`, `H_v` (`w = 1 − u − v`).
    pub fn tri(t: &TriPatch<T>) -> Self {
        Self::new(Net::from_tri(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::{binomial_scalar, ratio};
    use num_rational::BigRational;
    type Q = BigRational;

    #[test]
    fn de_casteljau_matches_bernstein_sum() {
        // Quadratic with P_{ijk} = (i, j, i*j + k).
        let n = 2;
        let rows: Vec<Vec<Vec<Q>>> = (0..=n)
            .map(|j| {
                (0..=n - j)
                    .map(|i| {
                        let k = n - i - j;
                        vec![
                            ratio(i as i64, 1),
                            ratio(j as i64, 1),
                            ratio((i * j + k) as i64, 1),
                        ]
                    })
                    .collect()
            })
            .collect();
        let t = TriPatch::polynomial(rows.clone()).unwrap();
        let (u, v) = (ratio::<Q>(1, 3), ratio::<Q>(1, 4));
        let w = ratio::<Q>(1, 1) - &u - &v;
        let mut sum = vec![ratio::<Q>(0, 1); 3];
        for (j, row) in rows.iter().enumerate() {
            for (i, p) in row.iter().enumerate() {
                let k = n - i - j;
                // n!/(i!j!k!) = C(n, i) C(n − i, j)
                let b = binomial_scalar::<Q>(n, i)
                    * binomial_scalar::<Q>(n - i, j)
                    * u.pow_u32(i as u32)
                    * v.pow_u32(j as u32)
                    * w.pow_u32(k as u32);
                for d in 0..3 {
                    sum[d] = sum[d].clone() + p[d].clone() * &b;
                }
            }
        }
        assert_eq!(t.eval(&u, &v).unwrap(), sum);
    }
}
