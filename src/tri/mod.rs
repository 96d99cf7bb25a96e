//! [`TriPatch`]: rational triangular Bézier patches of degree n, in
//! homogeneous form, generic over the scalar.
//!
//! Conventions (those of docs/FORMAT.md): barycentric coordinates `(u, v, w)`,
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
use crate::eval::{Evaluator, Jets, Net, Shape};
use crate::hpoint::{check_positive_weights, HPoint};

mod basics;
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
/// use exact_bezier::BigRational;
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
    use crate::algebra::scalar::{binomial_scalar, ratio, Scalar};
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
