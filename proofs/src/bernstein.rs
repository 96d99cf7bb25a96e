//! The Bernstein basis properties listed in the lecture (source 001,
//! "伯恩斯坦多项式的性质"), each established as an identity of polynomials in
//! `t` for **every** degree `n ≤ 10` and every index `i`.
//!
//! `B_{i,n}(t)` is built by [`bernstein`] on the symbol `t` (so the basis is
//! expanded into powers of `t` by the crate's own code) and each property is
//! checked against an independently written right-hand side.

use super::calculus::{antiderivative, integral_0_1};
use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::algebra::{binomial, binomial_scalar, ratio};
use exact_bezier::bernstein::bernstein;
use num_traits::{One, Zero};

/// Degree bound of the family.
const MAX_N: usize = 10;
const SOURCE: &str = "001 lecture, 伯恩斯坦多项式的性质";

fn t() -> Poly {
    Poly::var("t")
}

fn b(i: i64, n: i64) -> Poly {
    if i < 0 || n < 0 {
        return Poly::zero();
    }
    bernstein(i as usize, n as usize, &t())
}

/// Check `check(n, i)` for `n ∈ degrees`, `i = 0 … n`; the first failure
/// (if any) becomes the detail.
fn for_all(
    claim: &str,
    degrees: std::ops::RangeInclusive<usize>,
    how: &str,
    check: impl Fn(usize, usize) -> Result<(), String>,
) -> Claim {
    let (lo, hi) = (*degrees.start(), *degrees.end());
    let failure = degrees
        .flat_map(|n| (0..=n).map(move |i| (n, i)))
        .find_map(|(n, i)| check(n, i).err().map(|e| format!("n = {n}, i = {i}: {e}")));
    let detail = match &failure {
        None => format!("{how}; each n, i an identity"),
        Some(f) => f.clone(),
    };
    let range = format!("{lo} ≤ n ≤ {hi}, 0 ≤ i ≤ n");
    let claim = format!("{claim} — checked for every {range}");
    Claim::check(&claim, SOURCE, Verdict::Proved, failure.is_none(), detail).with_bound(range)
}

fn equal(lhs: &Poly, rhs: &Poly) -> Result<(), String> {
    if lhs == rhs {
        Ok(())
    } else {
        Err(format!("lhs − rhs = {}", lhs.clone() - rhs))
    }
}

/// `(a + b)ⁿ B_{i,n}(a/(a+b))`, computed from the power-basis expansion
/// `Σ c_k tᵏ` of `B_{i,n}` as `Σ c_k aᵏ (a+b)^{n−k}`.
fn homogenized(i: usize, n: usize) -> Poly {
    let (a, s) = (Poly::var("a"), Poly::var("a") + Poly::var("b"));
    let p = b(i as i64, n as i64);
    (0..=n as u32).fold(Poly::zero(), |acc, k| {
        acc + p.coeff_of("t", k) * a.pow(k) * s.pow(n as u32 - k)
    })
}

/// The recursion's right side `(1 − t) B_{i,n−1} + t B_{i−1,n−1}`.
fn recursion_rhs(n: i64, i: i64) -> Poly {
    (Poly::one() - t()) * b(i, n - 1) + t() * b(i - 1, n - 1)
}

/// `lhs(n, i) = rhs(n, i)` for `1 ≤ n ≤ MAX_N`, `0 ≤ i ≤ n` (the tests feed
/// wrong right sides through the same code).
fn formula_claim(
    claim: &str,
    how: &str,
    lhs: impl Fn(i64, i64) -> Poly,
    rhs: impl Fn(i64, i64) -> Poly,
) -> Claim {
    for_all(claim, 1..=MAX_N, how, |n, i| {
        let (i, n) = (i as i64, n as i64);
        equal(&lhs(n, i), &rhs(n, i))
    })
}

/// The recursion `B_{i,n} = rhs(n, i)`.
fn recursion_claim(rhs: impl Fn(i64, i64) -> Poly) -> Claim {
    formula_claim(
        "recursion: B_{i,n} = (1 − t) B_{i,n−1} + t B_{i−1,n−1}, i = 0…n",
        "expansion (B_{−1,n−1} = B_{n,n−1} = 0)",
        |n, i| b(i, n),
        rhs,
    )
}

/// The derivative's right side `n [B_{i−1,n−1} − B_{i,n−1}]`.
fn derivative_rhs(n: i64, i: i64) -> Poly {
    Poly::from_int(n) * (b(i - 1, n - 1) - b(i, n - 1))
}

/// The derivative formula `B'_{i,n} = rhs(n, i)`.
fn derivative_claim(rhs: impl Fn(i64, i64) -> Poly) -> Claim {
    formula_claim(
        "derivative: B'_{i,n}(t) = n [B_{i−1,n−1}(t) − B_{i,n−1}(t)], i = 0…n",
        "term-by-term derivative of the expanded polynomial",
        |n, i| b(i, n).derivative("t"),
        rhs,
    )
}

/// The middle step of the lecture's symmetry proof,
/// `B_{n−i,n}(t) = C(n,n−i) [1 − (1−t)]^{n−(n−i)} (1−t)^{n−i}`, whose right
/// side is `C(n,i) tⁱ (1−t)^{n−i} = B_{i,n}(t)`: the exponents are swapped
/// (the statement itself, proved above, is right).
fn printed_symmetry_step() -> Claim {
    let s = Poly::one() - t();
    let failure = (1..=MAX_N)
        .flat_map(|n| (0..=n).map(move |i| (n, i)))
        .find(|&(n, i)| {
            let rhs = binomial_scalar::<Poly>(n, n - i)
                * (Poly::one() - &s).pow((n - (n - i)) as u32)
                * s.pow((n - i) as u32);
            b((n - i) as i64, n as i64) != rhs
        });
    Claim::check(
        "symmetry proof step: B_{n−i,n}(t) = C(n,n−i)[1 − (1−t)]^{n−(n−i)}(1−t)^{n−i} = C(n,i)tⁱ(1−t)^{n−i} = B_{i,n}(1−t)",
        SOURCE,
        Verdict::Refuted,
        failure.is_none(),
        match failure {
            Some((n, i)) => format!(
                "n = {n}, i = {i}: B_{{{},{n}}}(t) = {} but the printed middle expression is {}; correct: B_{{n−i,n}}(t) = C(n,n−i)[1 − (1−t)]^{{n−i}}(1−t)^{{i}} = B_{{i,n}}(1−t)",
                n - i,
                b((n - i) as i64, n as i64),
                binomial_scalar::<Poly>(n, i) * t().pow(i as u32) * s.pow((n - i) as u32)
            ),
            None => "printed step holds".into(),
        },
    )
}

/// The family's claims.
pub fn claims() -> Vec<Claim> {
    let one = Poly::one();
    let s = one.clone() - t();
    vec![
        for_all(
            "non-negativity: B_{i,n}(t) ≥ 0 on [0,1], > 0 on (0,1); = 0 at t = 0 and 1 for i = 1…n−1",
            0..=MAX_N,
            "substitution t = a/(a+b) (a, b ≥ 0, a+b > 0 covers [0,1]) turns the expanded power form into (a+b)ⁿB_{i,n} = C(n,i)aⁱb^{n−i}, one monomial with a positive coefficient: ≥ 0, and > 0 for a, b > 0; zeros at a = 0 (t = 0) iff i > 0 and at b = 0 (t = 1) iff i < n",
            |n, i| {
                let mono = binomial_scalar::<Poly>(n, i)
                    * Poly::var("a").pow(i as u32)
                    * Poly::var("b").pow((n - i) as u32);
                equal(&homogenized(i, n), &mono)?;
                let at = |v: i64| b(i as i64, n as i64).subst("t", &Poly::from_int(v));
                if 0 < i && i < n && !(at(0).is_zero() && at(1).is_zero()) {
                    return Err("not zero at an end".into());
                }
                Ok(())
            },
        ),
        for_all(
            "end values: B_{i,n}(0) = [i = 0], B_{i,n}(1) = [i = n]",
            0..=MAX_N,
            "substitution t = 0 and t = 1",
            |n, i| {
                let at = |v: i64| b(i as i64, n as i64).subst("t", &Poly::from_int(v));
                let ind = |c: bool| if c { Poly::one() } else { Poly::zero() };
                equal(&at(0), &ind(i == 0))?;
                equal(&at(1), &ind(i == n))
            },
        ),
        for_all(
            "partition of unity: Σ_i B_{i,n}(t) = 1",
            0..=MAX_N,
            "sum of the expanded polynomials",
            |n, i| {
                if i > 0 {
                    return Ok(());
                }
                let sum = (0..=n).fold(Poly::zero(), |a, k| a + b(k as i64, n as i64));
                equal(&sum, &Poly::one())
            },
        ),
        for_all(
            "symmetry: B_{i,n}(1 − t) = B_{n−i,n}(t)",
            0..=MAX_N,
            "substitution t ↦ 1 − t",
            |n, i| {
                equal(
                    &b(i as i64, n as i64).subst("t", &s),
                    &b((n - i) as i64, n as i64),
                )
            },
        ),
        printed_symmetry_step(),
        recursion_claim(recursion_rhs),
        derivative_claim(derivative_rhs),
        for_all(
            "degree raising: (1 − t) B_{i,n} = (1 − i/(n+1)) B_{i,n+1}",
            0..=MAX_N,
            "expansion",
            |n, i| {
                let (i, n) = (i as i64, n as i64);
                let k = Poly::one() - ratio::<Poly>(i, n + 1);
                equal(&(s.clone() * b(i, n)), &(k * b(i, n + 1)))
            },
        ),
        for_all(
            "degree raising: t B_{i,n} = ((i+1)/(n+1)) B_{i+1,n+1}",
            0..=MAX_N,
            "expansion",
            |n, i| {
                let (i, n) = (i as i64, n as i64);
                equal(&(t() * b(i, n)), &(ratio::<Poly>(i + 1, n + 1) * b(i + 1, n + 1)))
            },
        ),
        for_all(
            "degree raising: B_{i,n} = (1 − i/(n+1)) B_{i,n+1} + ((i+1)/(n+1)) B_{i+1,n+1}",
            0..=MAX_N,
            "expansion",
            |n, i| {
                let (i, n) = (i as i64, n as i64);
                let rhs = (Poly::one() - ratio::<Poly>(i, n + 1)) * b(i, n + 1)
                    + ratio::<Poly>(i + 1, n + 1) * b(i + 1, n + 1);
                equal(&b(i, n), &rhs)
            },
        ),
        for_all(
            "integral: ∫₀¹ B_{i,n}(t) dt = 1/(n+1)",
            0..=MAX_N,
            "exact antiderivative F (checked F' = B_{i,n}), F(1) − F(0)",
            |n, i| {
                let p = b(i as i64, n as i64);
                equal(&antiderivative(&p, "t").derivative("t"), &p)?;
                equal(&integral_0_1(&p, "t"), &ratio::<Poly>(1, n as i64 + 1))
            },
        ),
        for_all(
            "maximum: B_{i,n} has its unique maximum on [0,1] at t = i/n (n ≥ 1)",
            1..=MAX_N,
            "B'_{i,n} = C(n,i) t^{i−1}(1−t)^{n−i−1}(i − n t) for 0 < i < n: the first factors are > 0 on (0,1), the last changes sign from + to − exactly at t = i/n; B'_{0,n} = −n(1−t)^{n−1} < 0 and B'_{n,n} = n t^{n−1} > 0 on (0,1) put the maxima at t = 0 and t = 1",
            |n, i| {
                let (ii, nn) = (i as u32, n as u32);
                let d = b(i as i64, n as i64).derivative("t");
                let rhs = if i == 0 {
                    -Poly::from_int(n as i64) * s.pow(nn - 1)
                } else if i == n {
                    Poly::from_int(n as i64) * t().pow(nn - 1)
                } else {
                    Poly::constant(binomial(n, i).into())
                        * t().pow(ii - 1)
                        * s.pow(nn - ii - 1)
                        * (Poly::from_int(i as i64) - Poly::from_int(n as i64) * t())
                };
                equal(&d, &rhs)
            },
        ),
    ]
}

#[cfg(test)]
mod tests {
    //! The verdicts discriminate: a wrong formula fed through the same
    //! claim code is refuted.
    use super::*;

    #[test]
    fn wrong_formulas_are_refuted() {
        assert_eq!(recursion_claim(recursion_rhs).verdict, Verdict::Proved);
        // Index shifted: t·B_{i,n−1} instead of t·B_{i−1,n−1}.
        let shifted = |n: i64, i: i64| (Poly::one() - t()) * b(i, n - 1) + t() * b(i, n - 1);
        assert_eq!(recursion_claim(shifted).verdict, Verdict::Refuted);
        assert_eq!(derivative_claim(derivative_rhs).verdict, Verdict::Proved);
        // Sign flipped.
        let flipped = |n: i64, i: i64| -derivative_rhs(n, i);
        assert_eq!(derivative_claim(flipped).verdict, Verdict::Refuted);
    }
}
