//! G⁰ and G¹ joins of two rect patches along a shared boundary, decided
//! exactly for exact scalars.
//!
//! Convention (the lecture's): patch `P` is joined at its side `u = 1` to
//! patch `Q`'s side `u = 0`; the bidegrees may differ.
//!
//! - G⁰: `P(1, v) = Q(0, v)` for all v. The lecture prints the control-point
//!   form as `P_{ni} = Q_{0i}, i = 0…m`; with `P_{ij}`, `i = 0…m` the u
//!   index, the boundary `u = 1` is `P_{m,j}`, so it must read
//!   `P_{mj} = Q_{0j}, j = 0…n` (proofs family `surfaces`). For rational
//!   patches equal control points are sufficient, not necessary (a common
//!   weight factor, or a different degree, gives the same curve), so the
//!   predicate compares the curves themselves.
//! - G¹: `Q_u(0, v) = α(v) P_u(1, v) + β(v) P_v(1, v)` for some functions α,
//!   β: the three tangent vectors are linearly dependent for every v.
//!
//! Both are polynomial identities in v, decided by evaluating a polynomial of
//! known degree d at d + 1 distinct parameters (a non-zero polynomial of
//! degree ≤ d has at most d roots): exact for exact `T`, within the caller's
//! [`Tolerance`] for `f64`.
//!
//! Reference: source 001 (lecture), "几何连续性" for surfaces.

use crate::algebra::scalar::{ratio, Scalar, Tolerance};
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::rect::{RectPatch, Side};

/// Is there a G⁰ join: `P(1, v) = Q(0, v)` for every v?
///
/// Decided on homogeneous points: `H_P(1, v) ∧ H_Q(0, v) = 0` (cross
/// multiplication, no division) is a polynomial of degree `n_P + n_Q` in v,
/// checked at `n_P + n_Q + 1` parameters.
///
/// # Examples
///
/// ```
/// use exact_bezier::{RectPatch, rect::g0_join, ratio, Tolerance};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let a = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 1)], vec![p(1, 0), p(1, 1)]]).unwrap();
/// let b = RectPatch::polynomial(vec![vec![p(1, 0), p(1, 1)], vec![p(2, 0), p(2, 1)]]).unwrap();
/// assert!(g0_join(&a, &b, Tolerance::EXACT));
/// assert!(!g0_join(&b, &a, Tolerance::EXACT));
/// ```
pub fn g0_join<T: Scalar>(p: &RectPatch<T>, q: &RectPatch<T>, tol: Tolerance) -> bool {
    if p.dim() != q.dim() {
        return false;
    }
    let (cp, cq) = (p.boundary(Side::U1), q.boundary(Side::U0));
    let d = cp.degree() + cq.degree();
    samples::<T>(d)
        .iter()
        .all(|v| cp.eval_hom(v).same_projective_point(&cq.eval_hom(v), tol))
}

/// Is there a G¹ join (lecture): G⁰, and `Q_u(0, v)`, `P_u(1, v)`,
/// `P_v(1, v)` linearly dependent for every v?
///
/// With `H = w(X, 1)` the 4×4 determinant `det[H, H_u, H_v, H'_u]` equals
/// `± w⁴ w' det₃[X_u, X_v, X'_u]` (subtract multiples of the first row), so
/// the test is `det[H_P, ∂_u H_P, ∂_v H_P, ∂_u H_Q] = 0` at `(1, v)` / `(0, v)`:
/// ring operations only, a polynomial of degree ≤ `3 n_P + n_Q` in v.
///
/// # Errors
///
/// [`Error::Shape`] unless both patches are 3D.
///
/// # Examples
///
/// ```
/// use exact_bezier::{RectPatch, rect::g1_join, ratio, Tolerance};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64, z: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1), ratio(z, 1)];
/// let a = RectPatch::polynomial(vec![vec![p(0, 0, 0), p(0, 1, 0)], vec![p(1, 0, 0), p(1, 1, 0)]]).unwrap();
/// let flat = RectPatch::polynomial(vec![vec![p(1, 0, 0), p(1, 1, 0)], vec![p(3, 0, 0), p(3, 1, 0)]]).unwrap();
/// let bent = RectPatch::polynomial(vec![vec![p(1, 0, 0), p(1, 1, 0)], vec![p(2, 0, 1), p(2, 1, 1)]]).unwrap();
/// assert!(g1_join(&a, &flat, Tolerance::EXACT).unwrap());
/// assert!(!g1_join(&a, &bent, Tolerance::EXACT).unwrap());
/// ```
pub fn g1_join<T: Scalar>(
    p: &RectPatch<T>,
    q: &RectPatch<T>,
    tol: Tolerance,
) -> Result<bool, Error> {
    if p.dim() != 3 || q.dim() != 3 {
        return Err(Error::Shape(format!(
            "a G¹ join needs 3D patches, not {}D and {}D",
            p.dim(),
            q.dim()
        )));
    }
    if !g0_join(p, q, tol) {
        return Ok(false);
    }
    let (one, zero) = (T::one(), T::zero());
    let d = 3 * p.degree().1 + q.degree().1;
    Ok(samples::<T>(d).iter().all(|v| {
        let rows = [
            p.eval_hom(&one, v),
            p.derivative_hom(1, 0, &one, v),
            p.derivative_hom(0, 1, &one, v),
            q.derivative_hom(1, 0, &zero, v),
        ];
        det4(&rows).is_zero_within(tol)
    }))
}

/// `d + 1` distinct parameters `k/d` in `[0, 1]` (just `0` when `d = 0`).
fn samples<T: Scalar>(d: usize) -> Vec<T> {
    if d == 0 {
        return vec![T::zero()];
    }
    (0..=d).map(|k| ratio::<T>(k as i64, d as i64)).collect()
}

/// The determinant of four homogeneous 3D points (4×4), by Laplace expansion
/// along the first row.
pub(crate) fn det4<T: Scalar>(rows: &[HPoint<T>; 4]) -> T {
    let m: Vec<&[T]> = rows.iter().map(|r| r.coords.as_slice()).collect();
    let det3 = |c: [usize; 3]| -> T {
        let e = |r: usize, k: usize| m[r][c[k]].clone();
        e(1, 0) * &(e(2, 1) * &e(3, 2) - &(e(2, 2) * &e(3, 1)))
            - &(e(1, 1) * &(e(2, 0) * &e(3, 2) - &(e(2, 2) * &e(3, 0))))
            + &(e(1, 2) * &(e(2, 0) * &e(3, 1) - &(e(2, 1) * &e(3, 0))))
    };
    let minors = [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]];
    minors.iter().enumerate().fold(T::zero(), |acc, (k, c)| {
        let term = m[0][k].clone() * &det3(*c);
        if k % 2 == 0 {
            acc + term
        } else {
            acc - term
        }
    })
}
