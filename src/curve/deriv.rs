//! Derivatives of any order of rational Bézier curves: the hodograph of the
//! homogeneous curve (forward differences), and exact derivatives of the
//! projected (Cartesian) curve by the Leibniz rule in fraction-free form.
//!
//! Conventions: `H(t) = Σ c_i B_{i,n}(t)` is the homogeneous curve with
//! `c_i = (w_i P_i, w_i)`, `w(t)` its last coordinate, `X(t) = H(t)/w(t)` the
//! projected curve. For a polynomial curve (all weights 1) `w ≡ 1` and the
//! hodograph is the lecture's forward-difference formula.
//!
//! Reference: source 001 (lecture), "k 阶导数的差分形式":
//! `P⁽ᵏ⁾(t) = n!/(n−k)! Σ_{i=0}^{n−k} Δᵏ P_i B_{i,n−k}(t)`, with
//! `Δ⁰ P_i = P_i`, `Δᵏ P_i = Δᵏ⁻¹ P_{i+1} − Δᵏ⁻¹ P_i`.

use crate::algebra::scalar::{binomial_scalar, Field, Scalar};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::{de_casteljau, HPoint};
use num_bigint::BigInt;

/// The k-th forward differences `Δᵏ c_i`, `i = 0 … len − 1 − k` (empty when
/// `k ≥ len`).
///
/// ```text
/// Δ⁰ c_i = c_i,   Δᵏ c_i = Δᵏ⁻¹ c_{i+1} − Δᵏ⁻¹ c_i
/// ```
///
/// Reference: source 001 (lecture), "k 阶导数的差分形式".
///
/// # Examples
///
/// ```
/// use exact_bezier::{curve::forward_differences, hpoint::HPoint, ratio};
/// use exact_bezier::BigRational;
/// let c: Vec<HPoint<BigRational>> =
///     [0, 1, 4, 9].iter().map(|&x| HPoint::from_cartesian(&[ratio(x, 1)])).collect();
/// // Second differences of squares are 2; the weights (all 1) difference to 0.
/// let d2 = forward_differences(&c, 2);
/// assert_eq!(d2, vec![HPoint { coords: vec![ratio(2, 1), ratio(0, 1)] }; 2]);
/// ```
pub fn forward_differences<T: Scalar>(ctrl: &[HPoint<T>], k: usize) -> Vec<HPoint<T>> {
    let mut row = ctrl.to_vec();
    for _ in 0..k {
        if row.is_empty() {
            break;
        }
        row = row.windows(2).map(|w| w[1].sub(&w[0])).collect();
    }
    row
}

/// The falling factorial `n!/(n−k)! = n (n−1) ⋯ (n−k+1)` as a scalar (0 when
/// `k > n`).
fn falling_factorial<T: Scalar>(n: usize, k: usize) -> T {
    if k > n {
        return T::zero();
    }
    let product: BigInt = (n - k + 1..=n).map(BigInt::from).product();
    T::from_bigint(&product)
}

/// # Derivatives of the homogeneous curve (ring operations only)
impl<T: Scalar> RationalCurve<T> {
    /// The Bernstein coefficients (degree `n − k`) of the k-th derivative of
    /// the homogeneous curve `H(t)`:
    ///
    /// ```text
    /// H⁽ᵏ⁾(t) = n!/(n−k)! Σ_{i=0}^{n−k} Δᵏ c_i B_{i,n−k}(t)
    /// ```
    ///
    /// For a polynomial curve (unit weights) the first `d` coordinates are
    /// the lecture's `n!/(n−k)! Δᵏ P_i` and the weight coordinate is 0. Empty
    /// when `k > n` (the derivative is zero). Exact for exact `T`.
    ///
    /// Reference: source 001 (lecture), "k 阶导数的差分形式" and "切向量".
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let c = RationalCurve::polynomial(vec![p(0, 0), p(1, 2), p(3, 2), p(4, 0)]).unwrap();
    /// // P'(0) = n (P1 − P0) = 3·(1, 2).
    /// let h = c.hodograph(1);
    /// assert_eq!(h[0].coords, vec![ratio(3, 1), ratio(6, 1), ratio(0, 1)]);
    /// ```
    pub fn hodograph(&self, k: usize) -> Vec<HPoint<T>> {
        let factor = falling_factorial::<T>(self.degree(), k);
        forward_differences(self.ctrl(), k)
            .iter()
            .map(|d| d.scale(&factor))
            .collect()
    }

    /// `[H(t), H'(t), …, H⁽ᵏ⁾(t)]`: the homogeneous curve and its first `k`
    /// derivatives at `t`, each by de Casteljau on [`RationalCurve::hodograph`].
    /// Exact for exact `T`.
    pub fn hom_derivs_at(&self, t: &T, k: usize) -> Vec<HPoint<T>> {
        (0..=k)
            .map(|j| {
                let h = self.hodograph(j);
                if h.is_empty() {
                    HPoint::zero(self.dim())
                } else {
                    de_casteljau(&h, t)
                }
            })
            .collect()
    }

    /// The derivatives `X⁽ʲ⁾(t)`, `j = 0 … k`, of the projected curve in
    /// fraction-free homogeneous form: entry `j` is `(M_j, w^{j+1})` with
    /// `X⁽ʲ⁾(t) = M_j / w(t)^{j+1}`, where (Leibniz rule for `w·X = H`)
    ///
    /// ```text
    /// M_0 = H,   M_k = wᵏ H⁽ᵏ⁾ − Σ_{j=1}^{k} C(k, j) w⁽ʲ⁾ w^{j−1} M_{k−j}
    /// ```
    ///
    /// (`H`, `M` the spatial parts, `w⁽ʲ⁾` the weight part of `H⁽ʲ⁾` at `t`).
    /// Ring operations only, so it runs on symbols; [`HPoint::project`] of
    /// entry `j` is `X⁽ʲ⁾(t)`.
    ///
    /// Reference: ours (quotient rule in homogeneous form); proved in
    /// `proofs/src/curves.rs`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// // x(t) = t/(1 + t) (weights 1, 2; points 0, 1/2): x' = 1/(1 + t)².
    /// let c = RationalCurve::new(vec![vec![ratio::<BigRational>(0, 1)], vec![ratio(1, 2)]],
    ///                            vec![ratio(1, 1), ratio(2, 1)]).unwrap();
    /// let d = c.derivs_hom(&ratio(1, 1), 1);
    /// // At t = 1: w = 2, so entry 1 is (M_1, w²) = (1, 4), i.e. x'(1) = 1/4.
    /// assert_eq!(d[1].coords, vec![ratio(1, 1), ratio(4, 1)]);
    /// ```
    pub fn derivs_hom(&self, t: &T, k: usize) -> Vec<HPoint<T>> {
        let h = self.hom_derivs_at(t, k);
        let w: Vec<T> = h.iter().map(|p| p.weight().clone()).collect();
        let w_pows: Vec<T> = (0..=k + 1).map(|e| w[0].pow_u32(e as u32)).collect();
        let mut m: Vec<Vec<T>> = Vec::with_capacity(k + 1);
        for order in 0..=k {
            let mut cur: Vec<T> = h[order]
                .weighted()
                .iter()
                .map(|x| x.clone() * &w_pows[order])
                .collect();
            for j in 1..=order {
                let f = binomial_scalar::<T>(order, j) * &w[j] * &w_pows[j - 1];
                for (c, x) in cur.iter_mut().zip(&m[order - j]) {
                    *c = c.clone() - &(f.clone() * x);
                }
            }
            m.push(cur);
        }
        m.into_iter()
            .enumerate()
            .map(|(j, mut coords)| {
                coords.push(w_pows[j + 1].clone());
                HPoint { coords }
            })
            .collect()
    }
}

/// # Derivatives of the projected curve
impl<T: Field> RationalCurve<T> {
    /// `[X(t), X'(t), …, X⁽ᵏ⁾(t)]`, the projected curve and its derivatives,
    /// from [`RationalCurve::derivs_hom`] with one division each. Exact for
    /// exact `T`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes at `t`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// // The quarter circle (1,0),(1,1),(0,1) with weights 1, 1, 2:
    /// // X(t) = ((1 − t²), 2t)/(1 + t²); X'(0) = (0, 2), X''(0) = (−4, 0).
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let c = RationalCurve::new(vec![p(1, 0), p(1, 1), p(0, 1)], vec![ratio(1, 1), ratio(1, 1), ratio(2, 1)]).unwrap();
    /// let d = c.derivs(&ratio(0, 1), 2).unwrap();
    /// assert_eq!(d[1], p(0, 2));
    /// assert_eq!(d[2], p(-4, 0));
    /// ```
    pub fn derivs(&self, t: &T, k: usize) -> Result<Vec<Vec<T>>, Error> {
        self.derivs_hom(t, k).iter().map(HPoint::project).collect()
    }

    /// The k-th derivative `X⁽ᵏ⁾(t)` of the projected curve (see
    /// [`RationalCurve::derivs`]).
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes at `t`.
    pub fn deriv(&self, t: &T, k: usize) -> Result<Vec<T>, Error> {
        let mut all = self.derivs(t, k)?;
        Ok(all.swap_remove(k))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    use num_rational::BigRational;

    type Q = BigRational;

    fn quarter_circle() -> RationalCurve<Q> {
        let p = |x: i64, y: i64| vec![ratio::<Q>(x, 1), ratio(y, 1)];
        RationalCurve::new(
            vec![p(1, 0), p(1, 1), p(0, 1)],
            vec![ratio(1, 1), ratio(1, 1), ratio(2, 1)],
        )
        .unwrap()
    }

    #[test]
    fn rational_derivatives_match_closed_form() {
        // X(t) = (1 − t², 2t)/(1 + t²); by hand at t = 1/2:
        // X' = (−4t, 2 − 2t²)/(1 + t²)² = (−2, 3/2)/(25/16) = (−32/25, 24/25).
        let d = quarter_circle().derivs(&ratio(1, 2), 1).unwrap();
        assert_eq!(d[0], vec![ratio::<Q>(3, 5), ratio(4, 5)]);
        assert_eq!(d[1], vec![ratio::<Q>(-32, 25), ratio(24, 25)]);
    }

    #[test]
    fn high_orders_vanish_for_polynomials() {
        let p = |x: i64| vec![ratio::<Q>(x, 1)];
        let c = RationalCurve::polynomial(vec![p(0), p(1), p(5)]).unwrap();
        // x(t) = 2t + 3t², so x'' = 6, x''' = 0.
        let d = c.derivs(&ratio(1, 3), 4).unwrap();
        assert_eq!(d[2], p(6));
        assert_eq!(d[3], p(0));
        assert_eq!(d[4], p(0));
        assert!(c.hodograph(3).is_empty());
    }

    #[test]
    fn pole_is_an_error() {
        let p = |x: i64| vec![ratio::<Q>(x, 1)];
        let c = RationalCurve::new(vec![p(0), p(1)], vec![ratio(1, 1), ratio(-1, 1)]).unwrap();
        assert_eq!(c.derivs(&ratio(1, 2), 1), Err(Error::PointAtInfinity));
    }
}
