//! Geometric continuity G⁰/G¹/G² of the join of two curves: `P` (degree
//! `n`) ends where `Q` (degree `m`) starts.
//!
//! ```text
//! G⁰:  P(1) = Q(0)
//! G¹:  G⁰ and Q'(0) = α P'(1) with α > 0
//! G²:  G¹ and Q''(0) = α² P''(1) + β P'(1) for some β
//! ```
//!
//! The predicates work on the projected curves (so rational curves are
//! judged by their shape, not their homogeneous coefficients) with exact
//! derivatives ([`RationalCurve::derivs`]); they are exact for exact scalars
//! and use the caller's [`Tolerance`] for `f64`.
//!
//! The lecture's control-point form of G¹ has the wrong sign; the G² formula
//! holds as printed only when `m = n`. [`g2_leading_points`] is the corrected
//! general form. Reference: source 001 (lecture), "Gⁿ 几何连续性"; checked in
//! `proofs/src/lecture_joins.rs`.

use crate::algebra::scalar::{ratio, Ordered, Scalar, Tolerance};
use crate::curve::RationalCurve;
use crate::error::Error;

/// The verdict on a join of `P` (at `t = 1`) to `Q` (at `t = 0`).
#[derive(Clone, Debug, PartialEq)]
pub struct Join<T> {
    /// `P(1) = Q(0)`.
    pub g0: bool,
    /// G⁰ and the tangents agree in direction: `Q'(0) = α P'(1)`, `α > 0`.
    pub g1: bool,
    /// G¹ and `Q''(0) − α² P''(1)` is parallel to `P'(1)`.
    pub g2: bool,
    /// `α = Q'(0)·P'(1) / |P'(1)|²` when G⁰ holds and `P'(1) ≠ 0`.
    pub alpha: Option<T>,
    /// `β = (Q''(0) − α² P''(1))·P'(1) / |P'(1)|²` when G¹ holds.
    pub beta: Option<T>,
    /// Why the highest failing order fails (empty when G² holds).
    pub reason: String,
}

fn dot<T: Scalar>(a: &[T], b: &[T]) -> T {
    a.iter()
        .zip(b)
        .fold(T::zero(), |acc, (x, y)| acc + &(x.clone() * y))
}

/// `a − k·b`.
fn minus_scaled<T: Scalar>(a: &[T], k: &T, b: &[T]) -> Vec<T> {
    a.iter()
        .zip(b)
        .map(|(x, y)| x.clone() - &(k.clone() * y))
        .collect()
}

fn is_zero_vec<T: Scalar>(v: &[T], tol: Tolerance) -> bool {
    v.iter().all(|x| x.is_zero_within(tol))
}

/// Judge the join of `p` (end, `t = 1`) to `q` (start, `t = 0`).
///
/// `α` is the least-squares ratio of the tangents and the G¹ test requires
/// the residual `Q'(0) − α P'(1)` to vanish (componentwise within `tol` for
/// `f64`; exactly for exact scalars) and `α > 0`; likewise G² with
/// `Q''(0) − α² P''(1) − β P'(1)`. A zero end tangent `P'(1) = 0` or
/// `Q'(0) = 0` leaves G¹ undecided by this test and is reported as not G¹,
/// with the reason.
///
/// Reference: source 001 (lecture), "Gⁿ 几何连续性", with the corrected sign
/// of G¹ (see `proofs/src/lecture_joins.rs`).
///
/// # Errors
///
/// [`Error::Shape`] if the dimensions differ; [`Error::PointAtInfinity`] if
/// an end weight is zero.
///
/// # Examples
///
/// ```
/// use exact_bezier::{curve::join, RationalCurve, Tolerance, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let a = RationalCurve::polynomial(vec![p(0, 0), p(1, 1), p(2, 1)]).unwrap();
/// // P'(1) = 2·(1, 0) and Q'(0) = 3·(2, 0) = 3 P'(1): G¹ with α = 3.
/// let b = RationalCurve::polynomial(vec![p(2, 1), p(4, 1), p(5, 3), p(6, 0)]).unwrap();
/// let j = join(&a, &b, Tolerance::EXACT).unwrap();
/// assert!(j.g0 && j.g1);
/// assert_eq!(j.alpha, Some(ratio(3, 1)));
/// ```
pub fn join<T: Ordered>(
    p: &RationalCurve<T>,
    q: &RationalCurve<T>,
    tol: Tolerance,
) -> Result<Join<T>, Error> {
    if p.dim() != q.dim() {
        return Err(Error::Shape(format!(
            "cannot join a {}-dimensional curve to a {}-dimensional one",
            p.dim(),
            q.dim()
        )));
    }
    let dp = p.derivs(&T::one(), 2)?;
    let dq = q.derivs(&T::zero(), 2)?;
    let mut out = Join {
        g0: false,
        g1: false,
        g2: false,
        alpha: None,
        beta: None,
        reason: String::new(),
    };
    if !is_zero_vec(&minus_scaled(&dq[0], &T::one(), &dp[0]), tol) {
        out.reason = "G0 fails: P(1) ≠ Q(0)".into();
        return Ok(out);
    }
    out.g0 = true;
    let pp = dot(&dp[1], &dp[1]);
    if pp.is_zero_within(tol) || is_zero_vec(&dq[1], tol) {
        out.reason = "G1 undecided: an end tangent P'(1) or Q'(0) is zero".into();
        return Ok(out);
    }
    let alpha = dot(&dq[1], &dp[1]) / &pp;
    out.alpha = Some(alpha.clone());
    if !is_zero_vec(&minus_scaled(&dq[1], &alpha, &dp[1]), tol) {
        out.reason = "G1 fails: Q'(0) is not parallel to P'(1)".into();
        return Ok(out);
    }
    if !alpha.is_positive_within(tol) {
        out.reason = "G1 fails: Q'(0) points against P'(1) (a cusp)".into();
        return Ok(out);
    }
    out.g1 = true;
    let r2 = minus_scaled(&dq[2], &(alpha.clone() * &alpha), &dp[2]);
    let beta = dot(&r2, &dp[1]) / &pp;
    out.beta = Some(beta.clone());
    if !is_zero_vec(&minus_scaled(&r2, &beta, &dp[1]), tol) {
        out.reason = "G2 fails: Q''(0) − α² P''(1) is not parallel to P'(1)".into();
        return Ok(out);
    }
    out.g2 = true;
    Ok(out)
}

/// The first three control points `Q_0, Q_1, Q_2` of a polynomial curve of
/// degree `m` that joins the polynomial curve with control points `p`
/// (degree `n`) with `Q'(0) = α P'(1)` and `Q''(0) = α² P''(1) + β P'(1)`:
///
/// ```text
/// Q_0 = P_n
/// Q_1 = P_n + (nα/m)(P_n − P_{n−1})
/// Q_2 = (1 + 2nα/m + (n(n−1)α² + nβ)/(m(m−1))) P_n
///     − (2nα/m + (2n(n−1)α² + nβ)/(m(m−1))) P_{n−1}
///     + (n(n−1)α²/(m(m−1))) P_{n−2}
/// ```
///
/// For `m = n` this is the lecture's
/// `Q_2 = (α² + 2α + β/(n−1) + 1) P_n − (2α² + 2α + β/(n−1)) P_{n−1} + α² P_{n−2}`.
/// Ring operations only (runs on symbols).
///
/// Reference: source 001 (lecture), "Gⁿ 几何连续性", generalized to `m ≠ n`;
/// proved in `proofs/src/lecture_joins.rs`.
///
/// # Errors
///
/// [`Error::Shape`] if `p` has fewer than 3 points or `m < 2`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{curve::g2_leading_points, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// // n = m = 2, α = 1, β = 0: x(t) = t² continues as (1 + t)² (C²).
/// let q = g2_leading_points(&[p(0), p(0), p(1)], 2, &ratio(1, 1), &ratio(0, 1)).unwrap();
/// assert_eq!(q, [p(1), p(2), p(4)]);
/// ```
pub fn g2_leading_points<T: Scalar>(
    p: &[Vec<T>],
    m: usize,
    alpha: &T,
    beta: &T,
) -> Result<[Vec<T>; 3], Error> {
    let n = p.len().wrapping_sub(1);
    if p.len() < 3 || m < 2 {
        return Err(Error::Shape(format!(
            "a G2 join needs degrees n, m ≥ 2 (got n = {}, m = {m})",
            p.len() as i64 - 1
        )));
    }
    let (pn, pn1, pn2) = (&p[n], &p[n - 1], &p[n - 2]);
    let r = ratio::<T>(n as i64, m as i64) * alpha;
    let s = ratio::<T>(n as i64, (m * (m - 1)) as i64);
    let a2 = T::from_i64(n as i64 - 1) * alpha * alpha;
    let two = T::from_i64(2);
    let c_pn = T::one() + &(two.clone() * &r) + &(s.clone() * &(a2.clone() + beta));
    let c_pn1 = two.clone() * &r + &(s.clone() * &(two * &a2 + beta));
    let c_pn2 = s * &a2;
    let combo = |cs: [&T; 3]| -> Vec<T> {
        (0..pn.len())
            .map(|k| {
                cs[0].clone() * &pn[k] + &(cs[1].clone() * &pn1[k]) + &(cs[2].clone() * &pn2[k])
            })
            .collect()
    };
    let q1 = combo([&(T::one() + &r), &(-r.clone()), &T::zero()]);
    let q2 = combo([&c_pn, &(-c_pn1), &c_pn2]);
    Ok([pn.clone(), q1, q2])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samples::p2 as p;
    use num_rational::BigRational;

    type Q = BigRational;

    #[test]
    fn straight_continuation_is_g2_cusp_is_not_g1() {
        let a = RationalCurve::polynomial(vec![p(0, 0), p(1, 0)]).unwrap();
        let on = RationalCurve::polynomial(vec![p(1, 0), p(2, 0)]).unwrap();
        let back = RationalCurve::polynomial(vec![p(1, 0), p(0, 0)]).unwrap();
        let j = join(&a, &on, Tolerance::EXACT).unwrap();
        assert!(j.g2 && j.alpha == Some(ratio(1, 1)));
        let k = join(&a, &back, Tolerance::EXACT).unwrap();
        assert!(k.g0 && !k.g1 && k.alpha == Some(ratio(-1, 1)));
    }

    #[test]
    fn gap_and_kink_fail() {
        let a = RationalCurve::polynomial(vec![p(0, 0), p(1, 0)]).unwrap();
        let gap = RationalCurve::polynomial(vec![p(2, 0), p(3, 0)]).unwrap();
        let kink = RationalCurve::polynomial(vec![p(1, 0), p(1, 1)]).unwrap();
        assert!(!join(&a, &gap, Tolerance::EXACT).unwrap().g0);
        let j = join(&a, &kink, Tolerance::EXACT).unwrap();
        assert!(j.g0 && !j.g1);
        let three = RationalCurve::polynomial(vec![vec![ratio(1, 1), ratio(0, 1), ratio(0, 1)]; 2])
            .unwrap();
        assert!(matches!(
            join(&a, &three, Tolerance::EXACT),
            Err(Error::Shape(_))
        ));
    }

    #[test]
    fn circle_arcs_join_g2_but_not_c1() {
        // Two quarter circles (1,0)→(0,1)→(−1,0), the second at another speed.
        let w = |a, b, c| vec![ratio::<Q>(a, 1), ratio(b, 1), ratio(c, 1)];
        let a = RationalCurve::new(vec![p(1, 0), p(1, 1), p(0, 1)], w(1, 1, 2)).unwrap();
        let b = RationalCurve::new(vec![p(0, 1), p(-1, 1), p(-1, 0)], w(1, 2, 8)).unwrap();
        let j = join(&a, &b, Tolerance::EXACT).unwrap();
        assert!(j.g2, "{}", j.reason);
        assert_ne!(j.alpha, Some(ratio(1, 1)));
        let f = join(
            &a.map(|x| x.to_f64()),
            &b.map(|x| x.to_f64()),
            Tolerance(1e-12),
        )
        .unwrap();
        assert!(f.g2);
    }
}
