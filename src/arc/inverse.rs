//! The inverse problems of source 004 §3 and the change of λ (eq. 6).
//!
//! A point `p` of the arc has quadratic parameter `s` (weights 1, c, 1)
//! with `s/(1 − s) = √μ`, where `μ = |b̄₀m|/|mb̄₂|` and `m` is where the line
//! through `b̄₁` and `p` (for θ = π: through `p` along `b`) meets the chord.
//! On the cubic with weight ratio `σ` the same point has parameter `ū` with
//! `σ·ū/(1 − ū) = √μ`. Everything below follows from that.

use super::{lambda_of_sigma_cubed, LambdaFactors, QuadArc};
use crate::algebra::scalar::Roots;
use crate::algebra::scalar::{Field, Ordered};
use crate::error::Error;

/// # Inverse problems (source 004 §3)
impl<T: Roots> QuadArc<T> {
    /// `μ = |b̄₀m|/|mb̄₂|` for a point `p` of the arc (source 004 §3.1, fig. 5):
    /// `m = b̄₀ + t(b̄₂ − b̄₀)` on the line through `p` with direction
    /// `d = x(A₁) − w(A₁)·p` (towards `b̄₁`, or along `b` for θ = π), solved by
    /// the normal equations in any dimension, and `μ = t/(1 − t)`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] for a point of the wrong dimension; [`Error::Domain`]
    /// if the line is parallel to the chord or `m` is not strictly between
    /// `b̄₀` and `b̄₂` (then `p` is not an inner point of the arc).
    ///
    /// ```
    /// use exact_bezier::{arc::QuadArc, ratio, Tolerance};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// // Source 004 §4: the semicircle on (0,0), (2,0) and its top point (1, 1).
    /// let arc = QuadArc::semicircle(&p(0, 0), &p(2, 0), &p(0, 1), Tolerance::EXACT).unwrap();
    /// assert_eq!(arc.mu_of_point(&p(1, 1)).unwrap(), ratio(1, 1));
    /// ```
    pub fn mu_of_point(&self, p: &[T]) -> Result<T, Error> {
        let [a0, a1, a2] = self.ctrl();
        let b0 = a0.project()?;
        let b2 = a2.project()?;
        if p.len() != b0.len() {
            return Err(Error::Shape(format!(
                "the point has dimension {}, the arc {}",
                p.len(),
                b0.len()
            )));
        }
        let w1 = a1.weight();
        let d: Vec<T> = a1
            .weighted()
            .iter()
            .zip(p)
            .map(|(x, y)| x.clone() - &(w1.clone() * y))
            .collect();
        let e = super::sub(&b2, &b0);
        let f = super::sub(p, &b0);
        let (ee, dd, ed) = (super::dot(&e, &e), super::dot(&d, &d), super::dot(&e, &d));
        let det = ee * &dd - &(ed.clone() * &ed);
        if det.is_zero() {
            return Err(Error::Domain(
                "the line through b̄₁ and the point is parallel to the chord".into(),
            ));
        }
        let t = (super::dot(&e, &f) * &dd - &(ed * &super::dot(&d, &f))) / &det;
        let zero = T::zero();
        if !(t > zero && t < T::one()) {
            return Err(Error::Domain(format!(
                "the point is not an inner point of the arc (m at chord parameter {})",
                t.to_f64()
            )));
        }
        Ok(t.clone() / &(T::one() - &t))
    }

    /// The weight ratio `σ = √μ·(1 − ū)/ū` that puts `p` at parameter `ū`.
    ///
    /// # Errors
    ///
    /// As [`QuadArc::mu_of_point`]; [`Error::Domain`] unless `0 < ū < 1`;
    /// [`Error::NotRational`] if `√μ` is irrational (exact scalars).
    pub fn sigma_for_point(&self, p: &[T], u_bar: &T) -> Result<T, Error> {
        check_open_unit(u_bar)?;
        let mu = self.mu_of_point(p)?;
        let root = mu
            .nth_root(2)
            .ok_or_else(|| Error::NotRational(format!("√μ = √{} is irrational", mu.to_f64())))?;
        Ok(root * &(T::one() - u_bar) / u_bar)
    }

    /// The λ that puts the arc point `p` at parameter `ū` (source 004
    /// eq. 7; eq. 8 for θ = π, eq. 9 for ū = 1/2):
    ///
    /// ```text
    /// λ* = (1 − M)/((1 + 2c)(1 + 2cM)),   M = μ√μ(1/ū − 1)³ = σ³
    /// ```
    ///
    /// # Errors
    ///
    /// As [`QuadArc::sigma_for_point`]; [`Error::Domain`] if λ* is infinite.
    ///
    /// ```
    /// use exact_bezier::{arc::QuadArc, ratio, Tolerance};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let arc = QuadArc::semicircle(&p(0, 0), &p(2, 0), &p(0, 1), Tolerance::EXACT).unwrap();
    /// // (1, 1) at ū = 1/3: σ = 2, λ* = 1 − 8 = −7 (eq. 8).
    /// assert_eq!(arc.lambda_for_point(&p(1, 1), &ratio(1, 3)).unwrap(), ratio(-7, 1));
    /// ```
    pub fn lambda_for_point(&self, p: &[T], u_bar: &T) -> Result<T, Error> {
        let sigma = self.sigma_for_point(p, u_bar)?;
        lambda_of_sigma_cubed(self.cos_half(), &sigma.pow_u32(3))
    }

    /// The parameter `ū` of the arc point `p` on the standard cubic for λ
    /// (source 004 eq. 10; eq. 11 for θ = π), read as
    ///
    /// ```text
    /// ū = 1/(ρ + 1),   ρ = σ/√μ = ∛(N/(D·μ√μ)),   ρ⁶ = N²/(D²μ³)
    /// ```
    ///
    /// Exact when `ρ` is rational (decided from `ρ⁶`).
    ///
    /// # Errors
    ///
    /// As [`QuadArc::mu_of_point`] and [`check_lambda`](super::check_lambda);
    /// [`Error::NotRational`] if `ρ` is irrational (exact scalars).
    ///
    /// ```
    /// use exact_bezier::{arc::QuadArc, ratio, Tolerance};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let arc = QuadArc::semicircle(&p(0, 0), &p(2, 0), &p(0, 1), Tolerance::EXACT).unwrap();
    /// assert_eq!(arc.param_of_point(&p(1, 1), &ratio(-7, 1)).unwrap(), ratio(1, 3));
    /// ```
    pub fn param_of_point(&self, p: &[T], lambda: &T) -> Result<T, Error> {
        super::check_lambda(self.cos_half(), lambda)?;
        let mu = self.mu_of_point(p)?;
        let f = LambdaFactors::new(self.cos_half(), lambda);
        let rho6 = f.n.clone() * &f.n / &(f.d.clone() * &f.d * &mu.pow_u32(3));
        let rho = rho6.nth_root(6).ok_or_else(|| {
            Error::NotRational(format!("ρ = σ/√μ = ⁶√{} is irrational", rho6.to_f64()))
        })?;
        Ok((rho + &T::one()).recip())
    }
}

/// `0 < u < 1`, else [`Error::Domain`].
fn check_open_unit<T: Ordered>(u: &T) -> Result<(), Error> {
    if *u > T::zero() && *u < T::one() {
        Ok(())
    } else {
        Err(Error::Domain(format!(
            "the parameter {} must lie strictly between 0 and 1",
            u.to_f64()
        )))
    }
}

/// `Δ = σ₁/σ₂ = ∛(N₁D₂/(D₁N₂))` of the change from λ₁ to λ₂ (source 004
/// eq. 6); also for θ = π.
///
/// # Errors
///
/// As [`check_lambda`](super::check_lambda) for either λ; [`Error::NotRational`] if `Δ` is
/// irrational (exact scalars; decided from `Δ³`).
///
/// ```
/// use exact_bezier::{arc::lambda_change_delta, ratio};
/// use exact_bezier::BigRational;
/// let c = ratio::<BigRational>(0, 1);
/// assert_eq!(lambda_change_delta(&c, &ratio(-7, 1), &ratio(0, 1)).unwrap(), ratio(2, 1));
/// ```
pub fn lambda_change_delta<T: Roots>(c: &T, lambda1: &T, lambda2: &T) -> Result<T, Error> {
    for l in [lambda1, lambda2] {
        super::check_lambda(c, l)?;
    }
    let (f1, f2) = (
        LambdaFactors::new(c, lambda1),
        LambdaFactors::new(c, lambda2),
    );
    let cube = f1.n * &f2.d / &(f1.d * &f2.n);
    cube.nth_root(3)
        .ok_or_else(|| Error::NotRational(format!("Δ = ∛{} is irrational", cube.to_f64())))
}

/// The parameter `u = ū/(Δ(1 − ū) + ū)` on the cubic for λ₁ of the point
/// at `ū` on the cubic for λ₂ (source 004 eq. 6), `Δ` from
/// [`lambda_change_delta`]. It is the Möbius map
/// [`RationalCurve::mobius_param`](crate::RationalCurve::mobius_param) with
/// `α = Δ/(1 + Δ)`.
///
/// # Errors
///
/// [`Error::Domain`] when `Δ(1 − ū) + ū = 0` (never for `Δ > 0`,
/// `0 ≤ ū ≤ 1`).
///
/// ```
/// use exact_bezier::{arc::lambda_change_param, ratio};
/// use exact_bezier::BigRational;
/// assert_eq!(lambda_change_param(&ratio::<BigRational>(2, 1), &ratio(1, 3)).unwrap(), ratio(1, 5));
/// ```
pub fn lambda_change_param<T: Field>(delta: &T, u_bar: &T) -> Result<T, Error> {
    let den = delta.clone() * &(T::one() - u_bar) + u_bar;
    if den.is_zero() {
        return Err(Error::Domain(
            "Δ(1 − ū) + ū = 0: the map has a pole there".into(),
        ));
    }
    Ok(u_bar.clone() / &den)
}
