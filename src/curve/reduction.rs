//! Degree reduction `n → n − 1` of (rational) Bézier curves: the two
//! recursions that invert degree elevation, the Forrest and Farin schemes
//! built from them, the constrained least-squares perturbation, and exact
//! reduction of curves that truly are of lower degree.
//!
//! Everything acts on the homogeneous control points `c_i = (w_i P_i, w_i)`,
//! so it serves rational curves too (for a polynomial curve the weights stay
//! 1). If `c_i` is the elevation of `c*_i` (degree `n − 1`),
//!
//! ```text
//! c_i = (i/n) c*_{i−1} + ((n−i)/n) c*_i,          i = 0 … n
//! c#_i = (n c_i − i c#_{i−1}) / (n − i),           i = 0 … n−1   (forward)
//! c*_{i−1} = (n c_i − (n−i) c*_i) / i,              i = n … 1     (backward)
//! ```
//!
//! and both recursions return `c*` exactly; on other curves they differ and
//! the schemes blend them. The recursions and schemes are as printed in the
//! lecture (checked in `proofs/src/reduction.rs`).
//!
//! Reference: source 001 (lecture), "降阶".

use crate::algebra::scalar::{binomial, ratio, recip_int, Scalar, Tolerance};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;

/// A degree-reduction scheme.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reduction {
    /// Forrest (1972): `c#_i` for `i ≤ ⌊(n−1)/2⌋`, `c*_i` after.
    Forrest,
    /// Farin (1983): `(1 − i/(n−1)) c#_i + (i/(n−1)) c*_i`.
    Farin,
    /// Minimal perturbation making the curve of degree `n − 1`, then exact.
    LeastSquares,
}

/// # Degree reduction (ring operations only; exact for exact scalars)
impl<T: Scalar> RationalCurve<T> {
    fn require_reducible(&self, min: usize) -> Result<usize, Error> {
        let n = self.degree();
        if n < min {
            return Err(Error::Domain(format!(
                "degree reduction needs degree ≥ {min}, not {n}"
            )));
        }
        Ok(n)
    }

    /// The forward recursion `c#_i = (n c_i − i c#_{i−1}) / (n − i)`,
    /// `i = 0 … n−1` (exact inverse of elevation, accumulating error
    /// towards the end).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] for degree 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let c = RationalCurve::polynomial(vec![p(0), p(3), p(6)]).unwrap().elevate(1);
    /// let back = c.reduce_forward().unwrap();
    /// assert_eq!(back, RationalCurve::polynomial(vec![p(0), p(3), p(6)]).unwrap().ctrl());
    /// ```
    pub fn reduce_forward(&self) -> Result<Vec<HPoint<T>>, Error> {
        let n = self.require_reducible(1)?;
        let c = self.ctrl();
        let mut out: Vec<HPoint<T>> = Vec::with_capacity(n);
        for (i, ci) in c.iter().take(n).enumerate() {
            let nc = ci.scale(&T::from_i64(n as i64));
            let prev = match out.last() {
                Some(p) => nc.sub(&p.scale(&T::from_i64(i as i64))),
                None => nc,
            };
            out.push(prev.scale(&ratio(1, (n - i) as i64)));
        }
        Ok(out)
    }

    /// The backward recursion `c*_{i−1} = (n c_i − (n−i) c*_i) / i`,
    /// `i = n … 1` (exact inverse of elevation, accumulating error towards
    /// the start).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] for degree 0.
    pub fn reduce_backward(&self) -> Result<Vec<HPoint<T>>, Error> {
        let n = self.require_reducible(1)?;
        let c = self.ctrl();
        let mut out: Vec<HPoint<T>> = vec![HPoint::zero(self.dim()); n];
        out[n - 1] = c[n].clone();
        for i in (1..n).rev() {
            let v = c[i]
                .scale(&T::from_i64(n as i64))
                .sub(&out[i].scale(&T::from_i64((n - i) as i64)));
            out[i - 1] = v.scale(&ratio(1, i as i64));
        }
        Ok(out)
    }

    /// Reduce the degree by one with `scheme`.
    ///
    /// On a curve that is an elevation, every scheme returns the original
    /// exactly. Forrest and Farin interpolate the end points.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] for degree 0, and for Farin's scheme at degree 1
    /// (its weights `i/(n−1)` are undefined).
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, curve::Reduction, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let c = RationalCurve::polynomial(vec![p(0, 0), p(1, 3), p(4, 3), p(5, 0)]).unwrap();
    /// for s in [Reduction::Forrest, Reduction::Farin, Reduction::LeastSquares] {
    ///     assert_eq!(c.elevate(1).reduce(s).unwrap(), c);
    /// }
    /// ```
    pub fn reduce(&self, scheme: Reduction) -> Result<Self, Error> {
        let ctrl = match scheme {
            Reduction::Forrest => {
                let (fwd, bwd) = (self.reduce_forward()?, self.reduce_backward()?);
                let half = (self.degree() - 1) / 2;
                fwd.into_iter()
                    .zip(bwd)
                    .enumerate()
                    .map(|(i, (f, b))| if i <= half { f } else { b })
                    .collect()
            }
            Reduction::Farin => {
                let n = self.require_reducible(2)?;
                let (fwd, bwd) = (self.reduce_forward()?, self.reduce_backward()?);
                fwd.iter()
                    .zip(&bwd)
                    .enumerate()
                    .map(|(i, (f, b))| {
                        let s = ratio::<T>(i as i64, n as i64 - 1);
                        f.lerp(b, &s)
                    })
                    .collect()
            }
            Reduction::LeastSquares => {
                let eps = self.lsq_perturbation()?;
                let moved: Vec<HPoint<T>> = self
                    .ctrl()
                    .iter()
                    .zip(&eps)
                    .map(|(c, e)| c.add(e))
                    .collect();
                RationalCurve::from_ctrl(moved).reduce_forward()?
            }
        };
        Ok(RationalCurve::from_ctrl(ctrl))
    }

    /// The degeneracy form `D = Σ_i (−1)ⁱ C(n, i) c_i` (`= (−1)ⁿ Δⁿ c_0`,
    /// `n!`⁻¹ times the leading power coefficient up to sign): zero iff the
    /// homogeneous curve has degree < n.
    ///
    /// Reference: source 001 (lecture), "约束优化方法".
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// // 0, 1, 2 lie on a line (degree 1): D = 0 − 2·1 + 2 = 0.
    /// let line = RationalCurve::polynomial(vec![p(0), p(1), p(2)]).unwrap();
    /// assert_eq!(line.degeneracy().coords, vec![ratio(0, 1), ratio(0, 1)]);
    /// ```
    pub fn degeneracy(&self) -> HPoint<T> {
        self.ctrl()
            .iter()
            .enumerate()
            .fold(HPoint::zero(self.dim()), |acc, (i, c)| {
                acc.add(&c.scale(&alternating_binomial::<T>(self.degree(), i)))
            })
    }

    /// The perturbation `ε_i` of least `Σ |ε_i|²` with
    /// `Σ (−1)ⁱ C(n, i)(c_i + ε_i) = 0`, in closed form (Lagrange
    /// multiplier; `Σ_i C(n, i)² = C(2n, n)`):
    ///
    /// ```text
    /// ε_i = −(−1)ⁱ C(n, i) D / C(2n, n),   D = Σ_j (−1)ʲ C(n, j) c_j
    /// ```
    ///
    /// applied to every homogeneous coordinate (for a polynomial curve the
    /// weights' `D` is 0, so only the points move: the lecture's problem).
    /// Exact over Q. Optimality (orthogonality to the constraint's null
    /// space) is proved in `proofs/src/reduction.rs`.
    ///
    /// Reference: source 001 (lecture), "约束优化方法"; the closed form is ours.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] for degree 0.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// // x: 0, 1, 0 has D = 0 − 2 + 0 = −2; C(4, 2) = 6; ε = (1/3, −2/3, 1/3).
    /// let c = RationalCurve::polynomial(vec![p(0), p(1), p(0)]).unwrap();
    /// let eps = c.lsq_perturbation().unwrap();
    /// assert_eq!(eps[1].coords, vec![ratio(-2, 3), ratio(0, 1)]);
    /// ```
    pub fn lsq_perturbation(&self) -> Result<Vec<HPoint<T>>, Error> {
        let n = self.require_reducible(1)?;
        let d = self.degeneracy();
        let inv_norm = recip_int::<T>(&binomial(2 * n, n));
        Ok((0..=n)
            .map(|i| d.scale(&(-alternating_binomial::<T>(n, i) * &inv_norm)))
            .collect())
    }

    /// Exact reduction: `Some` curve of degree `n − 1` with the same
    /// homogeneous points iff the degeneracy form
    /// [`RationalCurve::degeneracy`] vanishes (within `tol` for `f64`;
    /// exactly for exact scalars), else `None`. For a rational curve this is
    /// degree reduction of its homogeneous form; a common factor of the
    /// coordinates and the weight (cancellation) is not detected.
    ///
    /// Reference: source 001 (lecture), "退化的曲线，可以精确降阶".
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, Tolerance, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let c = RationalCurve::polynomial(vec![p(0, 0), p(1, 3), p(5, 0)]).unwrap();
    /// assert_eq!(c.elevate(2).reduce_exact(Tolerance::EXACT).unwrap().reduce_exact(Tolerance::EXACT), Some(c.clone()));
    /// assert_eq!(c.reduce_exact(Tolerance::EXACT), None);
    /// ```
    pub fn reduce_exact(&self, tol: Tolerance) -> Option<Self> {
        if self.degree() == 0 || !self.degeneracy().is_zero_within(tol) {
            return None;
        }
        self.reduce_forward().ok().map(RationalCurve::from_ctrl)
    }

    /// Reduce exactly as far as possible ([`RationalCurve::reduce_exact`]
    /// repeated): the same homogeneous curve at its true polynomial degree.
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, Tolerance, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let seg = RationalCurve::polynomial(vec![p(2), p(5)]).unwrap();
    /// assert_eq!(seg.elevate(4).reduce_exact_fully(Tolerance::EXACT), seg);
    /// ```
    pub fn reduce_exact_fully(&self, tol: Tolerance) -> Self {
        let mut cur = self.clone();
        while let Some(lower) = cur.reduce_exact(tol) {
            cur = lower;
        }
        cur
    }
}

/// `(−1)ⁱ C(n, i)` as a scalar.
fn alternating_binomial<T: Scalar>(n: usize, i: usize) -> T {
    let b = binomial(n, i);
    T::from_bigint(&if i % 2 == 1 { -b } else { b })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::samples::p2 as p;
    use num_rational::BigRational;

    type Q = BigRational;

    #[test]
    fn schemes_interpolate_ends_and_differ_inside() {
        let c =
            RationalCurve::polynomial(vec![p(0, 0), p(1, 4), p(2, -3), p(5, 2), p(6, 0)]).unwrap();
        let fo = c.reduce(Reduction::Forrest).unwrap();
        let fa = c.reduce(Reduction::Farin).unwrap();
        for r in [&fo, &fa] {
            assert_eq!(r.ctrl()[0], c.ctrl()[0]);
            assert_eq!(r.ctrl()[3], c.ctrl()[4]);
        }
        assert_ne!(fo, fa);
    }

    #[test]
    fn lsq_makes_curve_degenerate_with_least_cost() {
        let c = RationalCurve::polynomial(vec![p(0, 0), p(1, 4), p(2, -3), p(5, 2)]).unwrap();
        let eps = c.lsq_perturbation().unwrap();
        let moved: Vec<HPoint<Q>> = c.ctrl().iter().zip(&eps).map(|(a, e)| a.add(e)).collect();
        let moved = RationalCurve::from_ctrl(moved);
        assert!(moved.degeneracy().is_zero_within(Tolerance::EXACT));
        // Moving only the last point also satisfies the constraint, at a higher cost.
        let d = c.degeneracy();
        let cost = |e: &[HPoint<Q>]| {
            e.iter()
                .flat_map(|h| h.coords.iter().map(|x| x.clone() * x))
                .fold(Q::from_integer(0.into()), |a, b| a + b)
        };
        let mut last_only = vec![HPoint::zero(2); 4];
        last_only[3] = d.scale(&ratio(1, 1)); // a_3 = −1, so ε_3 = D moves D to 0.
        let moved2: Vec<HPoint<Q>> = c
            .ctrl()
            .iter()
            .zip(&last_only)
            .map(|(a, e)| a.add(e))
            .collect();
        assert!(RationalCurve::from_ctrl(moved2)
            .degeneracy()
            .is_zero_within(Tolerance::EXACT));
        assert!(cost(&eps) < cost(&last_only));
        assert_eq!(c.reduce(Reduction::LeastSquares).unwrap().degree(), 2);
    }

    #[test]
    fn degree_limits() {
        let point = RationalCurve::polynomial(vec![p(1, 1)]).unwrap();
        assert!(matches!(
            point.reduce(Reduction::Forrest),
            Err(Error::Domain(_))
        ));
        assert_eq!(point.reduce_exact(Tolerance::EXACT), None);
        let seg = RationalCurve::polynomial(vec![p(1, 1), p(1, 1)]).unwrap();
        assert!(matches!(
            seg.reduce(Reduction::Farin),
            Err(Error::Domain(_))
        ));
        assert_eq!(seg.reduce_exact_fully(Tolerance::EXACT).degree(), 0);
    }
}
