//! Identities of Bernstein bases proved for **every** degree, with the
//! degree `n` and the indices `i, j` as symbols of [`Poly`] — the
//! general-degree counterparts of claims the families `bernstein`,
//! `triangles` and `yang_yong` check degree by degree up to a bound.
//!
//! Method. Every Bernstein polynomial of an identity is a hypergeometric
//! multiple of one base term `B = B_{i,n}(t) = C(n,i) tⁱ (1−t)^{n−i}` (or
//! `n!/(i! j! k!) uⁱ vʲ wᵏ` on a triangle, `k = n − i − j`), with a ratio
//! that is a rational function of the symbols:
//!
//! ```text
//! B_{i+a, n+b}(t) / B_{i,n}(t) = [C(n+b, i+a) / C(n, i)] · tᵃ (1−t)^{b−a}
//! C(n+b, i+a) / C(n, i) = [(n+b)!/n!] · [i!/(i+a)!] · [(n−i)!/(n−i+b−a)!]
//! (x + k)!/x! = (x+1)(x+2)…(x+k),   x!/(x − k)! = x(x−1)…(x−k+1)
//! ```
//!
//! — the only facts used about factorials are `x! = x·(x−1)!`, applied a
//! constant number of times, which is why the exponents and indices may be
//! symbols. Dividing the identity by `B` leaves an identity between
//! rational functions of `n, i, t, …`; it is decided by clearing the
//! denominators and expanding with [`Poly`]. The denominators are products
//! of `t`, `1 − t`, `n`, `n + 1`, `i + 1`, `n + 1 − i` and the like: non-zero
//! for `0 < t < 1` and indices in range (`0 ≤ i ≤ n`, `n ≥ 1`), the domain
//! each claim states; the identities of polynomials in `t` then extend to
//! every `t` by continuity.

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use num_traits::{One, Zero};

const LECTURE: &str = "001 lecture, Bernstein properties (general degree: ours)";
const TRIANGLES: &str = "001 lecture, triangular patches (general degree: ours)";

/// A rational function `num / den` of the symbols.
#[derive(Clone, Debug)]
struct Ratio {
    num: Poly,
    den: Poly,
}

impl Ratio {
    fn poly(p: Poly) -> Ratio {
        Ratio {
            num: p,
            den: Poly::one(),
        }
    }

    fn over(num: Poly, den: Poly) -> Ratio {
        Ratio { num, den }
    }

    fn mul(&self, o: &Ratio) -> Ratio {
        Ratio::over(self.num.clone() * &o.num, self.den.clone() * &o.den)
    }

    fn add(&self, o: &Ratio) -> Ratio {
        Ratio::over(
            self.num.clone() * &o.den + &(o.num.clone() * &self.den),
            self.den.clone() * &o.den,
        )
    }

    fn sub(&self, o: &Ratio) -> Ratio {
        self.add(&Ratio::over(-o.num.clone(), o.den.clone()))
    }

    /// `self^e` for an integer exponent (negative: the reciprocal).
    fn powi(&self, e: i64) -> Ratio {
        let (n, d) = (
            self.num.pow(e.unsigned_abs() as u32),
            self.den.pow(e.unsigned_abs() as u32),
        );
        if e >= 0 {
            Ratio::over(n, d)
        } else {
            Ratio::over(d, n)
        }
    }

    /// Are the two rational functions equal (cross-multiplied)?
    fn equals(&self, o: &Ratio) -> bool {
        (self.num.clone() * &o.den - &(o.num.clone() * &self.den)).is_zero()
    }
}

fn var(name: &str) -> Poly {
    Poly::var(name)
}

fn int(k: i64) -> Poly {
    Poly::from_int(k)
}

/// `(x + k)!/x!` for an integer shift `k` (a product of `|k|` factors, or
/// its reciprocal): the factorial recurrence applied `|k|` times.
fn factorial_shift(x: &Poly, k: i64) -> Ratio {
    let factors =
        |from: i64, to: i64| (from..=to).fold(Poly::one(), |acc, r| acc * &(x.clone() + &int(r)));
    if k >= 0 {
        Ratio::poly(factors(1, k))
    } else {
        Ratio::over(Poly::one(), factors(k + 1, 0))
    }
}

/// `C(n+b, i+a) / C(n, i)` as a rational function of `n, i`.
fn binomial_ratio(n: &Poly, i: &Poly, a: i64, b: i64) -> Ratio {
    let n_minus_i = n.clone() - i;
    factorial_shift(n, b)
        .mul(&factorial_shift(i, a).powi(-1))
        .mul(&factorial_shift(&n_minus_i, b - a).powi(-1))
}

/// `B_{i+a, n+b}(t) / B_{i,n}(t)`.
fn bernstein_ratio(a: i64, b: i64) -> Ratio {
    let (n, i, t) = (var("n"), var("i"), Ratio::poly(var("t")));
    let one_minus_t = Ratio::poly(Poly::one() - &var("t"));
    binomial_ratio(&n, &i, a, b)
        .mul(&t.powi(a))
        .mul(&one_minus_t.powi(b - a))
}

/// `B_{i+a, j+b, k+c; n+a+b+c}(u, v, w) / B_{i,j,k; n}` (`k = n − i − j`,
/// `w = 1 − u − v`): the trinomial ratio times `uᵃ vᵇ w^c`.
fn triangle_ratio(a: i64, b: i64, c: i64) -> Ratio {
    let (n, i, j) = (var("n"), var("i"), var("j"));
    let k = n.clone() - &i - &j;
    let w = Poly::one() - &var("u") - &var("v");
    factorial_shift(&n, a + b + c)
        .mul(&factorial_shift(&i, a).powi(-1))
        .mul(&factorial_shift(&j, b).powi(-1))
        .mul(&factorial_shift(&k, c).powi(-1))
        .mul(&Ratio::poly(var("u")).powi(a))
        .mul(&Ratio::poly(var("v")).powi(b))
        .mul(&Ratio::poly(w).powi(c))
}

/// `Σ coefficient · ratio` over the terms of one side.
fn combine(terms: &[(Ratio, Ratio)]) -> Ratio {
    terms
        .iter()
        .fold(Ratio::poly(Poly::zero()), |acc, (c, r)| acc.add(&c.mul(r)))
}

/// The claim that `lhs = rhs` as rational functions, with the method.
fn identity(claim: &str, source: &str, lhs: &Ratio, rhs: &Ratio, how: &str) -> Claim {
    let holds = lhs.equals(rhs);
    let detail = if holds {
        format!(
            "{how}; both sides divided by the base term agree as rational functions of the symbols"
        )
    } else {
        let diff = lhs.sub(rhs);
        format!(
            "{how}; the difference over the base term is ({}) / ({})",
            diff.num, diff.den
        )
    };
    Claim::check(claim, source, Verdict::Proved, holds, detail).with_bound("every n")
}

/// `p / q` with integer polynomials.
fn frac(p: Poly, q: Poly) -> Ratio {
    Ratio::over(p, q)
}

/// The degree-elevation identity with its coefficients as parameters (the
/// discrimination test feeds wrong ones).
fn elevation_with(c0: Ratio, c1: Ratio) -> Claim {
    let rhs = combine(&[(c0, bernstein_ratio(0, 1)), (c1, bernstein_ratio(1, 1))]);
    identity(
        "degree elevation B_{i,n} = ((n+1−i)/(n+1)) B_{i,n+1} + ((i+1)/(n+1)) B_{i+1,n+1} for every n ≥ 0 and 0 ≤ i ≤ n",
        LECTURE,
        &Ratio::poly(Poly::one()),
        &rhs,
        "ratios C(n+1,i)/C(n,i) = (n+1)/(n+1−i), C(n+1,i+1)/C(n,i) = (n+1)/(i+1)",
    )
}

fn elevation() -> Claim {
    let (n, i) = (var("n"), var("i"));
    let n1 = n.clone() + &int(1);
    elevation_with(frac(n1.clone() - &i, n1.clone()), frac(i + &int(1), n1))
}

fn recurrence() -> Claim {
    let rhs = combine(&[
        (Ratio::poly(Poly::one() - &var("t")), bernstein_ratio(0, -1)),
        (Ratio::poly(var("t")), bernstein_ratio(-1, -1)),
    ]);
    identity(
        "recurrence B_{i,n} = (1−t) B_{i,n−1} + t B_{i−1,n−1} for every n ≥ 1 and 0 ≤ i ≤ n",
        LECTURE,
        &Ratio::poly(Poly::one()),
        &rhs,
        "ratios C(n−1,i)/C(n,i) = (n−i)/n, C(n−1,i−1)/C(n,i) = i/n (the term with index −1 or n is 0 and so is its coefficient)",
    )
}

/// `d/dt B_{i,n} = n (B_{i−1,n−1} − B_{i,n−1})`; the left side over the
/// base term is the logarithmic derivative `i/t − (n−i)/(1−t)`.
fn derivative() -> Claim {
    let (n, i, t) = (var("n"), var("i"), var("t"));
    let lhs = frac(i.clone(), t.clone()).sub(&frac(n.clone() - &i, Poly::one() - &t));
    let rhs = Ratio::poly(n).mul(&bernstein_ratio(-1, -1).sub(&bernstein_ratio(0, -1)));
    identity(
        "derivative d/dt B_{i,n} = n (B_{i−1,n−1} − B_{i,n−1}) for every n ≥ 1 and 0 ≤ i ≤ n",
        LECTURE,
        &lhs,
        &rhs,
        "(d/dt B)/B = i/t − (n−i)/(1−t) by the product rule on tⁱ(1−t)^{n−i}",
    )
}

/// Source 000 eqs. (2)–(4): under `u = (α−1)s/(2αs − s − α)`,
/// `B_{i,n}(u) = αⁿ ρⁱ B_{i,n}(s) / Eⁿ` with `ρ = (1−α)/α`,
/// `E = α(1−s) + (1−α)s`. Over the base term `B_{i,n}(s)` both sides are
/// `X^i Y^{n−i}` for `X = u/s`, `Y = (1−u)/(1−s)` on the left and
/// `X = (1−α)/E`, `Y = α/E` on the right: equal for all `n, i` exactly when
/// the two bases agree, which is what is decided.
fn mobius() -> Claim {
    let (s, alpha) = (var("s"), var("alpha"));
    let one = Poly::one();
    let u = frac(
        (alpha.clone() - &one) * &s,
        int(2) * &alpha * &s - &s - &alpha,
    );
    let e = alpha.clone() * &(one.clone() - &s) + &((one.clone() - &alpha) * &s);
    let u_over_s = u.mul(&frac(one.clone(), s.clone()));
    let rest_ratio = Ratio::poly(one.clone())
        .sub(&u)
        .mul(&frac(one.clone(), one.clone() - &s));
    let holds = u_over_s.equals(&frac(one.clone() - &alpha, e.clone()))
        && rest_ratio.equals(&frac(alpha.clone(), e));
    Claim::check(
        "Möbius weight rule: B_{i,n}(u(s)) = αⁿ ρⁱ B_{i,n}(s) / (α(1−s) + (1−α)s)ⁿ, ρ = (1−α)/α, for every n and 0 ≤ i ≤ n (so ω_i ↦ ω_i ρⁱ)",
        "000 eqs. (2)–(4)",
        Verdict::Proved,
        holds,
        "u/s = (1−α)/E and (1−u)/(1−s) = α/E with E = α(1−s) + (1−α)s, as rational functions; then (u/s)ⁱ((1−u)/(1−s))^{n−i} = αⁿρⁱ/Eⁿ for symbolic n, i by the exponent laws".into(),
    )
    .with_bound("every n")
}

fn triangle_recurrence() -> Claim {
    let w = Poly::one() - &var("u") - &var("v");
    let rhs = combine(&[
        (Ratio::poly(var("u")), triangle_ratio(-1, 0, 0)),
        (Ratio::poly(var("v")), triangle_ratio(0, -1, 0)),
        (Ratio::poly(w), triangle_ratio(0, 0, -1)),
    ]);
    identity(
        "triangular recurrence B_{ijk}^n = u B_{i−1,j,k}^{n−1} + v B_{i,j−1,k}^{n−1} + w B_{i,j,k−1}^{n−1} for every n ≥ 1 and i + j + k = n",
        TRIANGLES,
        &Ratio::poly(Poly::one()),
        &rhs,
        "trinomial ratios (n−1)!/((i−1)! j! k!) ÷ n!/(i! j! k!) = i/n (likewise j/n, k/n), k = n − i − j, w = 1 − u − v",
    )
}

fn triangle_elevation() -> Claim {
    let (n, i, j) = (var("n"), var("i"), var("j"));
    let n1 = n.clone() + &int(1);
    let k = n - &i - &j;
    let rhs = combine(&[
        (frac(i + &int(1), n1.clone()), triangle_ratio(1, 0, 0)),
        (frac(j + &int(1), n1.clone()), triangle_ratio(0, 1, 0)),
        (frac(k + &int(1), n1), triangle_ratio(0, 0, 1)),
    ]);
    identity(
        "triangular degree elevation B_{ijk}^n = ((i+1)/(n+1)) B_{i+1,j,k}^{n+1} + ((j+1)/(n+1)) B_{i,j+1,k}^{n+1} + ((k+1)/(n+1)) B_{i,j,k+1}^{n+1} for every n ≥ 0",
        TRIANGLES,
        &Ratio::poly(Poly::one()),
        &rhs,
        "trinomial ratio (n+1)!/((i+1)! j! k!) ÷ n!/(i! j! k!) = (n+1)/(i+1) (likewise), then u + v + w = 1",
    )
}

/// Every claim of this family.
pub fn claims() -> Vec<Claim> {
    vec![
        recurrence(),
        elevation(),
        derivative(),
        mobius(),
        triangle_recurrence(),
        triangle_elevation(),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn all_proved() {
        for c in claims() {
            assert_eq!(c.verdict, Verdict::Proved, "{}: {}", c.claim, c.detail);
        }
    }

    /// The verdicts discriminate: an index shifted in a coefficient, or a
    /// sign flipped, refutes the elevation identity.
    #[test]
    fn wrong_elevation_coefficients_are_refuted() {
        let (n, i) = (var("n"), var("i"));
        let n1 = n.clone() + &int(1);
        let shifted = elevation_with(
            frac(n.clone() - &i, n1.clone()),
            frac(i.clone() + &int(1), n1.clone()),
        );
        assert_eq!(shifted.verdict, Verdict::Refuted);
        let flipped = elevation_with(frac(n1.clone() - &i, n1.clone()), frac(-(i + &int(1)), n1));
        assert_eq!(flipped.verdict, Verdict::Refuted);
    }

    /// The ratio machinery itself: C(n+1, i)/C(n, i) at n = 5, i = 2 is
    /// C(6,2)/C(5,2) = 15/10.
    #[test]
    fn binomial_ratio_matches_numbers() {
        let r = binomial_ratio(&var("n"), &var("i"), 0, 1);
        let at = |p: &Poly| {
            p.eval(&[
                ("n", exact_bezier::algebra::ratio(5, 1)),
                ("i", exact_bezier::algebra::ratio(2, 1)),
            ])
            .unwrap()
        };
        assert_eq!(
            at(&r.num) / at(&r.den),
            exact_bezier::algebra::ratio(15, 10)
        );
    }
}
