//! Polynomial tools for real algebraic numbers over Q: square-free part,
//! Sturm sequences and root counting, real root isolation, and the
//! resultants that give defining polynomials of sums and products.
//!
//! ```text
//! square-free part   p / gcd(p, p')                         (Yun's first step)
//! Sturm sequence     s₀ = p, s₁ = p', s_{i+1} = −rem(s_{i−1}, s_i)
//! root count         #roots in (a, b) = V(a) − V(b)    (a, b not roots; V = sign changes)
//! sum                Res_z(p(z), q(t − z))       has the root α + β
//! product            Res_z(p(z), z^{deg q} q(t/z)) has the root α·β   (q(0) ≠ 0)
//! Cauchy bound       every root |x| < 1 + max |a_i / a_d|
//! ```
//!
//! The bivariate resultants are evaluated at the integers `t = 0 … deg p·deg q`
//! (each a univariate resultant by the Euclidean algorithm over Q) and
//! interpolated (Newton's divided differences): `O(D)` univariate resultants
//! of cost `O(d²)` for output degree `D = deg p·deg q`.
//!
//! Reference: Cohen, *A Course in Computational Algebraic Number Theory*,
//! §3.3 (resultants), §4.1–4.2 (Sturm, Cauchy bound); Yap, *Fundamental
//! Problems of Algorithmic Algebra*, ch. 7.

use crate::algebra::upoly::UPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// A univariate polynomial over Q.
pub(crate) type QPoly = UPoly<BigRational>;

fn q(n: i64) -> BigRational {
    BigRational::from_integer(n.into())
}

/// `p'`.
pub(crate) fn derivative(p: &QPoly) -> QPoly {
    UPoly::new(
        p.coeffs()
            .iter()
            .enumerate()
            .skip(1)
            .map(|(k, c)| c * q(k as i64))
            .collect(),
    )
}

/// The monic square-free part `p / gcd(p, p')` (`p ≠ 0`).
pub(crate) fn square_free(p: &QPoly) -> QPoly {
    let g = p.gcd(&derivative(p));
    p.div_exact(&g).expect("gcd divides").monic()
}

/// `p` scaled to integer coefficients with gcd 1 and a positive leading
/// coefficient.
pub(crate) fn primitive_integer(p: &QPoly) -> Vec<BigInt> {
    let den = p
        .coeffs()
        .iter()
        .fold(BigInt::one(), |acc, c| acc.lcm(c.denom()));
    let ints: Vec<BigInt> = p
        .coeffs()
        .iter()
        .map(|c| (c * BigRational::from_integer(den.clone())).to_integer())
        .collect();
    let g = ints.iter().fold(BigInt::zero(), |acc, c| acc.gcd(c));
    let sign = if p.lead().is_some_and(|l| l.is_negative()) {
        -BigInt::one()
    } else {
        BigInt::one()
    };
    ints.into_iter().map(|c| c / &g * &sign).collect()
}

/// The Sturm sequence of a square-free `p`.
pub(crate) fn sturm_sequence(p: &QPoly) -> Vec<QPoly> {
    let mut seq = vec![p.clone(), derivative(p)];
    while let Some(last) = seq.last().filter(|s| !s.is_zero()) {
        let prev = &seq[seq.len() - 2];
        let (_, r) = prev.div_rem(last).expect("non-zero divisor");
        let next = r.scale(&q(-1));
        if next.is_zero() {
            break;
        }
        seq.push(next);
    }
    seq.retain(|s| !s.is_zero());
    seq
}

fn sign_changes(seq: &[QPoly], x: &BigRational) -> usize {
    let signs: Vec<bool> = seq
        .iter()
        .map(|s| s.eval(x))
        .filter(|v| !v.is_zero())
        .map(|v| v.is_positive())
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// The number of distinct real roots in the open interval `(a, b)`, `a < b`
/// not roots themselves (Sturm's theorem).
pub(crate) fn count_roots(seq: &[QPoly], a: &BigRational, b: &BigRational) -> usize {
    sign_changes(seq, a).saturating_sub(sign_changes(seq, b))
}

/// Rational bounds `(lo, hi)` on `p(x)` for every `x ∈ [a, b]` (Horner in
/// interval arithmetic; exact rationals, so the enclosure is rigorous).
pub(crate) fn eval_on_interval(
    p: &QPoly,
    a: &BigRational,
    b: &BigRational,
) -> (BigRational, BigRational) {
    p.coeffs().iter().rev().fold((q(0), q(0)), |(lo, hi), c| {
        let products = [&lo * a, &lo * b, &hi * a, &hi * b];
        let min = products.iter().min().expect("four").clone();
        let max = products.iter().max().expect("four").clone();
        (min + c, max + c)
    })
}

/// A bound `B` with every real root in `(−B, B)`.
pub(crate) fn cauchy_bound(p: &QPoly) -> BigRational {
    let lead = p.lead().expect("non-zero").abs();
    let max = p
        .coeffs()
        .iter()
        .map(|c| c.abs() / &lead)
        .fold(BigRational::zero(), |a, b| if b > a { b } else { a });
    max + q(1)
}

/// Isolating intervals `(lo, hi)` (open, endpoints not roots, one root
/// each, increasing) of the real roots of a square-free `p` in `(a, b)`,
/// where `a < b` are not roots; by bisection with Sturm counts.
pub(crate) fn isolate(
    p: &QPoly,
    a: &BigRational,
    b: &BigRational,
) -> Vec<(BigRational, BigRational)> {
    let seq = sturm_sequence(p);
    let mut out = Vec::new();
    let mut stack = vec![(a.clone(), b.clone())];
    while let Some((lo, hi)) = stack.pop() {
        match count_roots(&seq, &lo, &hi) {
            0 => {}
            1 => out.push((lo, hi)),
            _ => {
                let mid = split_point(p, &lo, &hi);
                stack.push((mid.clone(), hi));
                stack.push((lo, mid));
            }
        }
    }
    out.sort_by(|x, y| x.0.cmp(&y.0));
    out
}

/// A point of `(lo, hi)` near the middle that is not a root of `p`.
pub(crate) fn split_point(p: &QPoly, lo: &BigRational, hi: &BigRational) -> BigRational {
    let mut mid = (lo + hi) / q(2);
    while p.eval(&mid).is_zero() {
        mid = (mid + hi) / q(2);
    }
    mid
}

/// The univariate resultant `Res(a, b)` over Q by the Euclidean algorithm:
/// `Res(a, b) = (−1)^{mn} lc(b)^{m − deg r} Res(b, r)` with `r = a mod b`.
pub(crate) fn resultant(a: &QPoly, b: &QPoly) -> BigRational {
    let (Some(m), Some(n)) = (a.degree(), b.degree()) else {
        return BigRational::zero();
    };
    if n == 0 {
        return b.lead().expect("non-zero").pow(m as i32);
    }
    let (_, r) = a.div_rem(b).expect("non-zero divisor");
    let Some(k) = r.degree() else {
        return BigRational::zero();
    };
    let sign = if (m * n) % 2 == 1 { q(-1) } else { q(1) };
    sign * b.lead().expect("non-zero").pow((m - k) as i32) * resultant(b, &r)
}

/// The polynomial of degree ≤ `values.len() − 1` through `(k, values[k])`,
/// `k = 0, 1, …` (Newton's divided differences).
pub(crate) fn interpolate(values: &[BigRational]) -> QPoly {
    let n = values.len();
    let mut dd = values.to_vec();
    for level in 1..n {
        for k in (level..n).rev() {
            dd[k] = (&dd[k] - &dd[k - 1]) / q(level as i64);
        }
    }
    // Horner in the Newton basis: c_0 + (x − 0)(c_1 + (x − 1)(c_2 + …)).
    let mut acc = UPoly::constant(dd[n - 1].clone());
    for k in (0..n - 1).rev() {
        let factor = UPoly::new(vec![q(-(k as i64)), q(1)]);
        acc = acc.mul(&factor).add(&UPoly::constant(dd[k].clone()));
    }
    acc
}

/// `Res_z(p(z), g_t(z))` as a polynomial in `t` of degree ≤ `deg`, where
/// `g(t)` builds `g_t` for each integer `t` (its degree in `z` must not
/// depend on `t`).
fn resultant_in_t(p: &QPoly, g: impl Fn(&BigRational) -> QPoly, deg: usize) -> QPoly {
    let values: Vec<BigRational> = (0..=deg as i64).map(|t| resultant(p, &g(&q(t)))).collect();
    interpolate(&values)
}

/// `q(t − z)` as a polynomial in `z` for a fixed `t`.
fn shifted_reflection(qp: &QPoly, t: &BigRational) -> QPoly {
    // Horner: q(t − z) = (…(q_d (t − z) + q_{d−1})(t − z) + …).
    let lin = UPoly::new(vec![t.clone(), q(-1)]);
    qp.coeffs().iter().rev().fold(UPoly::zero(), |acc, c| {
        acc.mul(&lin).add(&UPoly::constant(c.clone()))
    })
}

/// A polynomial whose roots include every `α + β` (`p(α) = 0`, `q(β) = 0`).
pub(crate) fn sum_poly(p: &QPoly, qp: &QPoly) -> QPoly {
    let deg = p.degree().unwrap_or(0) * qp.degree().unwrap_or(0);
    resultant_in_t(p, |t| shifted_reflection(qp, t), deg)
}

/// A polynomial whose roots include every `α·β` (`p(α) = 0`, `q(β) = 0`,
/// `q(0) ≠ 0`).
pub(crate) fn product_poly(p: &QPoly, qp: &QPoly) -> QPoly {
    let dq = qp.degree().unwrap_or(0);
    let deg = p.degree().unwrap_or(0) * dq;
    resultant_in_t(
        p,
        |t| {
            // z^{dq} q(t/z) = Σ q_i t^i z^{dq − i}.
            let mut c = vec![BigRational::zero(); dq + 1];
            let mut tp = q(1);
            for (i, qi) in qp.coeffs().iter().enumerate() {
                c[dq - i] = qi * &tp;
                tp *= t;
            }
            UPoly::new(c)
        },
        deg,
    )
}

/// `p(−x)`.
pub(crate) fn reflect(p: &QPoly) -> QPoly {
    UPoly::new(
        p.coeffs()
            .iter()
            .enumerate()
            .map(|(k, c)| if k % 2 == 1 { -c } else { c.clone() })
            .collect(),
    )
}

/// `x^d p(1/x)`.
pub(crate) fn reverse(p: &QPoly) -> QPoly {
    UPoly::new(p.coeffs().iter().rev().cloned().collect())
}

/// `p(x − c)` (roots shifted by `+c`).
pub(crate) fn shift(p: &QPoly, c: &BigRational) -> QPoly {
    let lin = UPoly::new(vec![-c.clone(), q(1)]);
    p.coeffs().iter().rev().fold(UPoly::zero(), |acc, k| {
        acc.mul(&lin).add(&UPoly::constant(k.clone()))
    })
}

/// `p(x / c)` up to a constant factor (roots scaled by `c ≠ 0`):
/// `Σ p_k c^{d−k} x^k`.
pub(crate) fn scale_roots(p: &QPoly, c: &BigRational) -> QPoly {
    let d = p.degree().unwrap_or(0);
    UPoly::new(
        p.coeffs()
            .iter()
            .enumerate()
            .map(|(k, a)| a * c.pow((d - k) as i32))
            .collect(),
    )
}

/// `p(x^n)`.
pub(crate) fn compose_power(p: &QPoly, n: u32) -> QPoly {
    let mut c = vec![BigRational::zero(); p.degree().unwrap_or(0) * n as usize + 1];
    for (k, a) in p.coeffs().iter().enumerate() {
        c[k * n as usize] = a.clone();
    }
    UPoly::new(c)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(v: &[i64]) -> QPoly {
        UPoly::new(v.iter().map(|&x| q(x)).collect())
    }

    #[test]
    fn sum_of_square_roots() {
        // √2 + √3 is a root of x⁴ − 10x² + 1.
        let s = sum_poly(&poly(&[-2, 0, 1]), &poly(&[-3, 0, 1]));
        assert_eq!(s.monic(), poly(&[1, 0, -10, 0, 1]));
        let p = product_poly(&poly(&[-2, 0, 1]), &poly(&[-3, 0, 1]));
        assert_eq!(p.monic(), poly(&[36, 0, -12, 0, 1]));
    }

    #[test]
    fn isolation_finds_every_root() {
        // (x − 1)(x − 2)(x + 3)(x² − 2): five real roots, two at interval ends.
        let p = poly(&[-1, 1])
            .mul(&poly(&[-2, 1]))
            .mul(&poly(&[3, 1]))
            .mul(&poly(&[-2, 0, 1]));
        let b = cauchy_bound(&p);
        let roots = isolate(&p, &-b.clone(), &b);
        assert_eq!(roots.len(), 5);
    }
}
