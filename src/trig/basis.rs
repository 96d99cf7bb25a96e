//! The cubic trigonometric basis with a shape parameter α (source 002,
//! Definition 1, eq. (1)) and exact trigonometric arithmetic.
//!
//! A parameter `t ∈ [0, π/2]` is carried as the pair `(s, c) = (sin t, cos t)`
//! ([`TrigParam`]): `f64` callers pass the sine and cosine of an angle, exact
//! callers pass the rational point of the unit circle at `τ = tan(t/2)`
//! (`s = 2τ/(1+τ²)`, `c = (1−τ²)/(1+τ²)`), and symbolic callers pass two
//! [`Poly`] variables and reduce the result with [`circle_normal_form`].
//!
//! A function of `t` is a [`TrigFn`]: coefficients on `1, s, c, s², s·c`.
//! That span is closed under `d/dt` (`s' = c`, `c' = −s`, and `c² = 1 − s²`),
//! so derivatives of every order stay in it and are exact.
//!
//! ```text
//! X₀ = 1 − α s + (α−1) s² = (1−s)(1 + (1−α) s)
//! X₁ = α s − α s²         = α s (1−s)
//! X₂ = −α + α c + α s²    = α c (1−c)           (mod s² + c² = 1)
//! X₃ = α − α c + (1−α) s² = (1−c)(1 + (1−α) c)  (mod s² + c² = 1)
//! ```
//!
//! Reference: source 002 eq. (1).

use crate::algebra::poly::Poly;
use crate::algebra::scalar::{Field, Scalar};

/// A parameter `t ∈ [0, π/2]` as the pair `(sin t, cos t)`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{ratio, trig::TrigParam};
/// use exact_bezier::BigRational;
/// // τ = tan(t/2) = 1/2: sin t = 4/5, cos t = 3/5, exactly.
/// let p = TrigParam::from_tau(&ratio::<BigRational>(1, 2));
/// assert_eq!((p.sin.clone(), p.cos.clone()), (ratio(4, 5), ratio(3, 5)));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TrigParam<T> {
    /// `sin t`.
    pub sin: T,
    /// `cos t`.
    pub cos: T,
}

impl<T: Scalar> TrigParam<T> {
    /// The pair `(sin t, cos t)` as given (symbolic callers pass variables).
    pub fn new(sin: T, cos: T) -> Self {
        TrigParam { sin, cos }
    }

    /// `t = 0`: `(sin, cos) = (0, 1)`.
    pub fn start() -> Self {
        TrigParam::new(T::zero(), T::one())
    }

    /// `t = π/2`: `(sin, cos) = (1, 0)`.
    pub fn end() -> Self {
        TrigParam::new(T::one(), T::zero())
    }

    /// The parameter `π/2 − t`: sine and cosine swap.
    pub fn reflect(&self) -> Self {
        TrigParam::new(self.cos.clone(), self.sin.clone())
    }
}

impl<T: Field> TrigParam<T> {
    /// The rational point of the unit circle at `τ = tan(t/2)`:
    /// `sin t = 2τ/(1+τ²)`, `cos t = (1−τ²)/(1+τ²)`; `τ ∈ [0, 1]` gives
    /// `t ∈ [0, π/2]`.
    ///
    /// Reference: the half-angle substitution, the rational parameterization
    /// of the unit circle.
    pub fn from_tau(tau: &T) -> Self {
        let tt = tau.clone() * tau;
        let den = T::one() + &tt;
        TrigParam::new((tau.clone() + tau) / &den, (T::one() - tt) / den)
    }
}

impl TrigParam<f64> {
    /// `(sin t, cos t)` of an angle `t` in radians.
    ///
    /// ```
    /// use exact_bezier::trig::TrigParam;
    /// let p = TrigParam::from_angle(std::f64::consts::FRAC_PI_2);
    /// assert!((p.sin - 1.0).abs() < 1e-15 && p.cos.abs() < 1e-15);
    /// ```
    pub fn from_angle(t: f64) -> Self {
        TrigParam::new(t.sin(), t.cos())
    }
}

/// The normal form of `p` in `Q[…, s, c]/(s² + c² − 1)`: every `c²` is
/// rewritten as `1 − s²`, so the result has degree ≤ 1 in `c`. Two
/// polynomials in `sin t, cos t` agree for every `t` iff their normal forms
/// are equal.
///
/// ```
/// use exact_bezier::{trig::circle_normal_form, Poly};
/// let (s, c) = (Poly::var("s"), Poly::var("c"));
/// assert_eq!(circle_normal_form(&(s.pow(2) + c.pow(2)), "s", "c"), Poly::from_int(1));
/// ```
pub fn circle_normal_form(p: &Poly, s: &str, c: &str) -> Poly {
    p.reduce_power(c, 2, &(Poly::from_int(1) - Poly::var(s).pow(2)))
}

/// A function `a₀ + a₁ s + a₂ c + a₃ s² + a₄ s c` of `t`, with
/// `s = sin t`, `c = cos t`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{ratio, trig::TrigFn, trig::TrigParam};
/// use exact_bezier::BigRational;
/// let sin = TrigFn::<BigRational>::new([0, 1, 0, 0, 0].map(|k| ratio(k, 1)));
/// // d/dt sin = cos, d²/dt² sin = −sin.
/// assert_eq!(sin.derivative().coeffs()[2], ratio(1, 1));
/// assert_eq!(sin.derivative_n(2), sin.scale(&ratio(-1, 1)));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TrigFn<T> {
    coeffs: [T; 5],
}

impl<T: Scalar> TrigFn<T> {
    /// The function with coefficients `[a₀, a₁, a₂, a₃, a₄]` on
    /// `1, s, c, s², s c`.
    pub fn new(coeffs: [T; 5]) -> Self {
        TrigFn { coeffs }
    }

    /// The coefficients on `1, s, c, s², s c`.
    pub fn coeffs(&self) -> &[T; 5] {
        &self.coeffs
    }

    /// The four basis functions `X₀…X₃` of eq. (1) for the shape parameter α.
    ///
    /// Reference: source 002 eq. (1).
    ///
    /// ```
    /// use exact_bezier::{ratio, trig::TrigFn, trig::TrigParam};
    /// use exact_bezier::BigRational;
    /// let x = TrigFn::basis(&ratio::<BigRational>(1, 1));
    /// let at = TrigParam::from_tau(&ratio(1, 2)); // s = 4/5, c = 3/5
    /// // X₁ = α s (1 − s) = 4/25.
    /// assert_eq!(x[1].eval(&at), ratio(4, 25));
    /// ```
    pub fn basis(alpha: &T) -> [TrigFn<T>; 4] {
        let (z, one, a) = (T::zero(), T::one(), alpha.clone());
        [
            [
                one.clone(),
                -a.clone(),
                z.clone(),
                a.clone() - &one,
                z.clone(),
            ],
            [z.clone(), a.clone(), z.clone(), -a.clone(), z.clone()],
            [-a.clone(), z.clone(), a.clone(), a.clone(), z.clone()],
            [a.clone(), z.clone(), -a.clone(), one - &a, z],
        ]
        .map(TrigFn::new)
    }

    /// `d/dt`: with `s' = c`, `c' = −s` and `c² = 1 − s²`,
    /// `(a₀, a₁, a₂, a₃, a₄) ↦ (a₄, −a₂, a₁, −2a₄, 2a₃)`.
    pub fn derivative(&self) -> Self {
        let [_, a1, a2, a3, a4] = &self.coeffs;
        let two = T::from_i64(2);
        TrigFn::new([
            a4.clone(),
            -a2.clone(),
            a1.clone(),
            -(a4.clone() * &two),
            a3.clone() * &two,
        ])
    }

    /// The `k`-th derivative `dᵏ/dtᵏ` (`k = 0` is the function itself).
    pub fn derivative_n(&self, k: usize) -> Self {
        (0..k).fold(self.clone(), |f, _| f.derivative())
    }

    /// `k · f`.
    pub fn scale(&self, k: &T) -> Self {
        TrigFn::new(self.coeffs.clone().map(|a| a * k))
    }

    /// The value at `(s, c)`: `a₀ + s (a₁ + a₃ s) + c (a₂ + a₄ s)`.
    pub fn eval(&self, at: &TrigParam<T>) -> T {
        let [a0, a1, a2, a3, a4] = &self.coeffs;
        let s = &at.sin;
        let in_s = a1.clone() + &(a3.clone() * s);
        let in_c = a2.clone() + &(a4.clone() * s);
        a0.clone() + &(in_s * s) + &(in_c * &at.cos)
    }
}

/// The four values `X₀⁽ᵏ⁾(t) … X₃⁽ᵏ⁾(t)` of the `k`-th derivatives of the
/// basis (1) at `at`.
///
/// ```
/// use exact_bezier::{ratio, trig::trig_basis_values, trig::TrigParam};
/// use exact_bezier::BigRational;
/// let a = ratio::<BigRational>(3, 2);
/// // End derivatives: X'(0) = (−α, α, 0, 0).
/// let d0 = trig_basis_values(&a, 1, &TrigParam::start());
/// assert_eq!(d0, [ratio(-3, 2), ratio(3, 2), ratio(0, 1), ratio(0, 1)]);
/// ```
pub fn trig_basis_values<T: Scalar>(alpha: &T, k: usize, at: &TrigParam<T>) -> [T; 4] {
    TrigFn::basis(alpha).map(|x| x.derivative_n(k).eval(at))
}

/// `Σᵢ wᵢ · Pᵢ` for points of one dimension (`Pᵢ` non-empty slice list).
pub(crate) fn combine<T: Scalar>(weights: &[T], points: &[Vec<T>]) -> Vec<T> {
    let dim = points.first().map_or(0, Vec::len);
    (0..dim)
        .map(|d| {
            weights
                .iter()
                .zip(points)
                .fold(T::zero(), |acc, (w, p)| acc + &(w.clone() * &p[d]))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    use num_rational::BigRational;

    #[test]
    fn tau_points_lie_on_the_circle() {
        for (p, q) in [(0, 1), (1, 3), (1, 2), (1, 1), (7, 9)] {
            let at = TrigParam::from_tau(&ratio::<BigRational>(p, q));
            assert_eq!(
                at.sin.clone() * &at.sin + at.cos.clone() * &at.cos,
                ratio(1, 1)
            );
        }
    }

    #[test]
    fn derivative_matches_finite_differences() {
        // Second method: central differences of the f64 evaluation.
        let a = 1.3;
        let h = 1e-5;
        for x in TrigFn::basis(&a) {
            for t in [0.2, 0.7, 1.3] {
                let f = |t: f64| x.eval(&TrigParam::from_angle(t));
                let fd = (f(t + h) - f(t - h)) / (2.0 * h);
                assert!((x.derivative().eval(&TrigParam::from_angle(t)) - fd).abs() < 1e-8);
            }
        }
    }
}
