//! Calculus on [`Poly`] in one named variable, for the proof families:
//! repeated derivatives (from [`Poly::derivative`], `d/dt tᵏ = k tᵏ⁻¹`) and
//! the definite integral over `[0, 1]` (`∫₀¹ tᵏ dt = 1/(k+1)`), computed
//! coefficient by coefficient, independently of the Bézier code they check.

use exact_bezier::algebra::ratio;
use exact_bezier::algebra::Poly;
use num_traits::Zero;

/// The `k`-th derivative `dᵏ/d varᵏ` of `p`.
pub fn nth_derivative(p: &Poly, var: &str, k: usize) -> Poly {
    (0..k).fold(p.clone(), |acc, _| acc.derivative(var))
}

/// The antiderivative `F = Σ c_k tᵏ⁺¹/(k+1)` of `p = Σ c_k tᵏ` (`F(0) = 0`).
pub fn antiderivative(p: &Poly, var: &str) -> Poly {
    let t = Poly::var(var);
    (0..=p.degree_in(var)).fold(Poly::zero(), |acc, k| {
        acc + p.coeff_of(var, k) * ratio::<Poly>(1, k as i64 + 1) * t.pow(k + 1)
    })
}

/// `∫₀¹ p d var = F(1) − F(0)` with `F` = [`antiderivative`].
pub fn integral_0_1(p: &Poly, var: &str) -> Poly {
    let f = antiderivative(p, var);
    f.subst(var, &Poly::from_int(1)) - f.subst(var, &Poly::zero())
}
