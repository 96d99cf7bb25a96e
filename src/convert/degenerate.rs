//! Triangle → one degenerate rectangle (source 001, Hu 2001).
//!
//! Substituting `u = s`, `v = (1 − s)t`, `w = (1 − s)(1 − t)` gives
//! `B^n_{ijk}(u, v, w) = B^n_i(s) · B^{n−i}_j(t)`, so row `i` of the
//! rectangle (s-index i) is the degree n − i curve `T_{i0}, …, T_{i,n−i}`
//! (`T_{ij} = Q_{i,j,n−i−j}`) raised to degree n:
//! `(P_{i0}, …, P_{in})ᵀ = A₁ A₂ ⋯ A_i (T_{i0}, …, T_{i,n−i})ᵀ`.

use crate::algebra::scalar::{ratio, Scalar};
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;
use crate::tri::TriPatch;

/// The degree-raising operator `A_k` (1 ≤ k ≤ n) of source 001 (Hu 2001),
/// corrected: it raises a curve from degree n − k to n − k + 1, so it is
/// `(n − k + 2) × (n − k + 1)`, with row `r` holding `r/(n−k+1)` in column
/// `r − 1` and `1 − r/(n−k+1)` in column `r`:
///
/// ```text
///        ⎡ 1                                   ⎤
///        ⎢ 1/(n+1−k)  (n−k)/(n+1−k)            ⎥
/// A_k =  ⎢            2/(n+1−k)  (n−k−1)/(n+1−k)⎥
///        ⎢                  ⋱          ⋱        ⎥
///        ⎢            (n−k)/(n+1−k)  1/(n+1−k)  ⎥
///        ⎣                                  1  ⎦
/// ```
///
/// The lecture prints a `(k+1) × k` matrix with a spurious second row
/// `(1, (n−k)/(n+1−k), 0, …)`; see `proofs/src/conversions.rs` (refuted).
///
/// # Errors
///
/// [`Error::Domain`] unless `1 ≤ k ≤ n`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{convert::degree_raising_matrix, ratio};
/// use exact_bezier::BigRational;
/// let a = degree_raising_matrix::<BigRational>(2, 1).unwrap();
/// let z: BigRational = ratio(0, 1);
/// assert_eq!(a, vec![vec![ratio(1, 1), z.clone()], vec![ratio(1, 2), ratio(1, 2)], vec![z, ratio(1, 1)]]);
/// ```
pub fn degree_raising_matrix<T: Scalar>(n: usize, k: usize) -> Result<Vec<Vec<T>>, Error> {
    if k == 0 || k > n {
        return Err(Error::Domain(format!(
            "the degree-raising operator A_k needs 1 ≤ k ≤ n = {n}, not k = {k}"
        )));
    }
    let d = (n - k + 1) as i64; // the raised degree
    Ok((0..=d)
        .map(|r| {
            (0..d)
                .map(|c| match r - c {
                    1 => ratio(r, d),
                    0 => ratio(d - r, d),
                    _ => T::zero(),
                })
                .collect()
        })
        .collect())
}

/// `A · x` for a matrix of scalars and a column of homogeneous points.
fn apply<T: Scalar>(a: &[Vec<T>], x: &[HPoint<T>]) -> Vec<HPoint<T>> {
    a.iter()
        .map(|row| {
            row.iter()
                .zip(x)
                .fold(HPoint::zero(x[0].dim()), |acc, (c, p)| acc.add(&p.scale(c)))
        })
        .collect()
}

/// The triangle as one degenerate rectangle of bidegree (n, n) (source 001,
/// Hu 2001): row `i` is `A₁ ⋯ A_i (T_{i0}, …, T_{i,n−i})ᵀ` with the corrected
/// [`degree_raising_matrix`]. The rectangle at `(s, t)` is the triangle at
/// `(s, (1 − s)t, (1 − s)(1 − t))`; its edge `s = 1` collapses to T1.
///
/// # Examples
///
/// ```
/// use exact_bezier::{convert::tri_to_degenerate_rect, TriPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let t = TriPatch::polynomial(vec![vec![p(0, 0), p(1, 0)], vec![p(0, 1)]]).unwrap();
/// let r = tri_to_degenerate_rect(&t);
/// // (s, t) = (1/2, 1/2) ↦ (u, v) = (1/2, 1/4)
/// assert_eq!(r.eval(&ratio(1, 2), &ratio(1, 2)).unwrap(), vec![ratio(1, 2), ratio(1, 4)]);
/// ```
pub fn tri_to_degenerate_rect<T: Scalar>(tri: &TriPatch<T>) -> RectPatch<T> {
    let n = tri.degree();
    let ctrl = (0..=n)
        .map(|i| {
            let mut row: Vec<HPoint<T>> = (0..=n - i).map(|j| tri.get(i, j).clone()).collect();
            for k in (1..=i).rev() {
                let a = degree_raising_matrix::<T>(n, k).expect("1 ≤ k ≤ i ≤ n");
                row = apply(&a, &row);
            }
            row
        })
        .collect();
    RectPatch::from_hom(ctrl).expect("a non-empty square net of equal-length points")
}
