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

use crate::algebra::int::common_denominator;
use crate::algebra::upoly::UPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// A univariate polynomial over Q.
pub(crate) type QPoly = UPoly<BigRational>;

/// The polynomial `Σ c_i xⁱ` with integer coefficients, for tests.
#[cfg(test)]
pub(crate) fn int_poly(c: &[i64]) -> QPoly {
    UPoly::new(c.iter().map(|&v| crate::ratio(v, 1)).collect())
}

fn q(n: i64) -> BigRational {
    BigRational::from_integer(n.into())
}

/// The most bits (numerator + denominator) of a coefficient of `p`.
pub(crate) fn poly_bits(p: &QPoly) -> u64 {
    p.coeffs()
        .iter()
        .map(crate::limits::bits)
        .max()
        .unwrap_or(0)
}

/// Record `ops` coefficient operations on the coefficients of `polys` in
/// the actual-work meter ([`crate::limits::meter`]).
pub(crate) fn meter(ops: usize, polys: &[&QPoly]) {
    let bits = polys.iter().map(|p| poly_bits(p)).max().unwrap_or(0);
    crate::limits::meter(ops as u64, bits);
}

/// `p'` ([`UPoly::derivative`]).
pub(crate) fn derivative(p: &QPoly) -> QPoly {
    p.derivative()
}

/// A square-free polynomial prepared (once) to isolate several of its
/// roots: the monic square-free part of a non-zero `p`, and the same as an
/// integer polynomial for sign evaluations and Descartes counts.
#[derive(Clone, Debug)]
pub(crate) struct Isolator {
    /// The monic square-free part.
    pub sf: QPoly,
    /// `sf` scaled to primitive integers.
    pub sign: SignPoly,
}

impl Isolator {
    /// Prepare `p ≠ 0`.
    pub(crate) fn new(p: &QPoly) -> Self {
        let sf = square_free_part(p);
        let sign = SignPoly::new(&sf);
        Isolator { sf, sign }
    }
}

/// The monic square-free part `p / gcd(p, p')` of `p ≠ 0`; `p` itself
/// (made monic) when reduction modulo a prime certifies that it is
/// square-free ([`super::modular`]), the generic case.
pub(crate) fn square_free_part(p: &QPoly) -> QPoly {
    if super::modular::certainly_square_free(p) {
        return monic(p);
    }
    let g = gcd(p, &derivative(p));
    monic(&p.div_exact(&g).expect("the gcd divides"))
}

/// `p / lc(p)` (zero for zero): [`UPoly::monic`] with each quotient
/// reduced by Lehmer's gcd ([`crate::algebra::gcd::product`]) instead of
/// num-rational's binary gcd, which is quadratic in the size of the
/// coefficients (and of the leading one) of value polynomials.
pub(crate) fn monic(p: &QPoly) -> QPoly {
    let Some(inverse) = p.lead().map(|l| l.recip()) else {
        return UPoly::zero();
    };
    UPoly::new(
        p.coeffs()
            .iter()
            .map(|c| crate::algebra::gcd::product(c, &inverse))
            .collect(),
    )
}

/// The non-negative gcd of `ints` (zero when all are zero), by Lehmer's
/// gcd ([`crate::algebra::gcd::gcd`]), stopping at 1.
fn content(ints: &[BigInt]) -> BigInt {
    let mut g = num_bigint::BigUint::zero();
    for c in ints {
        if g.is_one() {
            break;
        }
        g = crate::algebra::gcd::gcd(&g, c.magnitude());
    }
    BigInt::from(g)
}

/// The monic `gcd(a, b)` over Q (zero when both are zero), by a primitive
/// remainder sequence over Z: Gauss's lemma makes the primitive part of
/// the last non-zero remainder the gcd up to a constant, and the integers
/// stay content-free without a gcd per coefficient operation. Coprime
/// pairs, the generic case, are first recognised modulo a prime
/// ([`super::modular::certainly_coprime`]) and skip the sequence.
pub(crate) fn gcd(a: &QPoly, b: &QPoly) -> QPoly {
    if super::modular::certainly_coprime(a, b) || super::modular::certainly_coprime(b, a) {
        return UPoly::constant(q(1));
    }
    let (mut x, mut y) = (SignPoly::new(a), SignPoly::new(b));
    if x.0.len() < y.0.len() {
        std::mem::swap(&mut x, &mut y);
    }
    while !y.0.is_empty() {
        let r = x.negated_remainder(&y);
        x = y;
        y = r;
    }
    if x.0.is_empty() {
        return UPoly::zero();
    }
    monic(&x.to_qpoly())
}

/// `p` scaled to integer coefficients with gcd 1 and a positive leading
/// coefficient.
pub(crate) fn primitive_integer(p: &QPoly) -> Vec<BigInt> {
    let (ints, _): (Vec<BigInt>, _) = common_denominator(p.coeffs());
    let g = content(&ints);
    let sign = if p.lead().is_some_and(|l| l.is_negative()) {
        -BigInt::one()
    } else {
        BigInt::one()
    };
    ints.into_iter().map(|c| c / &g * &sign).collect()
}

/// A positive integer multiple of a polynomial over Q, for exact sign
/// evaluation at rationals without a gcd per operation:
///
/// ```text
/// x = a/b (b > 0):   b^d p(a/b) = Σ c_i a^i b^{d−i}   (homogeneous Horner)
/// ```
///
/// has the sign of `p(a/b)`.
#[derive(Clone, Debug)]
pub(crate) struct SignPoly(Vec<BigInt>);

impl SignPoly {
    /// `p` times the positive lcm of its denominators, divided by the
    /// positive gcd of the resulting integers.
    pub(crate) fn new(p: &QPoly) -> Self {
        let (ints, _): (Vec<BigInt>, _) = common_denominator(p.coeffs());
        let g = content(&ints);
        if g.is_zero() {
            return SignPoly(Vec::new());
        }
        SignPoly(ints.into_iter().map(|c| c / &g).collect())
    }

    /// The integer coefficients, lowest power first.
    pub(crate) fn coeffs(&self) -> &[BigInt] {
        &self.0
    }

    /// The polynomial over Q with these coefficients.
    pub(crate) fn to_qpoly(&self) -> QPoly {
        UPoly::new(
            self.0
                .iter()
                .map(|c| BigRational::from_integer(c.clone()))
                .collect(),
        )
    }

    /// A positive multiple of `−(self mod other)`, primitive (empty for a
    /// zero remainder): `lc^k self = q · other + r` with `lc = lc(other)`
    /// after `k` reduction steps, so `r` is `−(self mod other)` times
    /// `−lc^k`, whose sign is corrected.
    fn negated_remainder(&self, other: &SignPoly) -> SignPoly {
        let lc = other.0.last().expect("non-zero divisor");
        let n = other.0.len();
        let coeff_bits = self.0.iter().chain(&other.0).map(BigInt::bits).max();
        let steps_bound = self.0.len().saturating_sub(n) + 1;
        crate::limits::meter(
            (steps_bound * self.0.len()) as u64,
            coeff_bits.unwrap_or(0) + steps_bound as u64 * lc.bits(),
        );
        let mut r = self.0.clone();
        let mut steps = 0;
        while r.len() >= n {
            let lead = r.pop().expect("non-empty");
            let shift = r.len() + 1 - n;
            for c in r.iter_mut() {
                *c *= lc;
            }
            for (k, b) in other.0[..n - 1].iter().enumerate() {
                r[k + shift] -= &lead * b;
            }
            while r.last().is_some_and(Zero::is_zero) {
                r.pop();
            }
            steps += 1;
        }
        let flip = !(lc.is_negative() && steps % 2 == 1);
        let g = content(&r);
        SignPoly(
            r.into_iter()
                .map(|c| if flip { -(c / &g) } else { c / &g })
                .collect(),
        )
    }

    /// A power of two `B` with every root (complex too) in `|z| < B`, by
    /// Fujiwara's bound `|z| ≤ 2 max_i |c_{d−i}/c_d|^{1/i}` on bit lengths
    /// (`|c_{d−i}/c_d| < 2^{e_i}`, `e_i = bits c_{d−i} − bits c_d + 1`): far
    /// below Cauchy's `1 + max |c_i/c_d|` when the coefficients are large,
    /// so isolation from `−B` starts near the roots.
    ///
    /// Reference: Fujiwara, *Über die obere Schranke des absoluten Betrages
    /// der Wurzeln einer algebraischen Gleichung*, Tôhoku Math. J. 10
    /// (1916) 167–171.
    pub(crate) fn root_bound(&self) -> BigInt {
        let d = self.0.len().saturating_sub(1);
        let lead_bits = self.0.last().map_or(0, BigInt::bits) as i64;
        let e = (1..=d)
            .filter(|&i| !self.0[d - i].is_zero())
            .map(|i| {
                let x = self.0[d - i].bits() as i64 - lead_bits + 1;
                -((-x).div_euclid(i as i64)) // ⌈x / i⌉
            })
            .max()
            .unwrap_or(0);
        BigInt::one() << (e + 2).max(0) as usize
    }

    /// The sign of `p(x)`: −1, 0 or 1.
    pub(crate) fn sign_at(&self, x: &BigRational) -> i32 {
        let (a, b) = (x.numer(), x.denom());
        let mut coeffs = self.0.iter().rev();
        let Some(lead) = coeffs.next() else {
            return 0;
        };
        let degree = self.0.len() as u64;
        let coeff_bits = self.0.iter().map(BigInt::bits).max().unwrap_or(0);
        crate::limits::meter(2 * degree, coeff_bits + degree * crate::limits::bits(x));
        let mut acc = lead.clone();
        let mut bpow = BigInt::one();
        for c in coeffs {
            bpow *= b;
            acc = acc * a + c * &bpow;
        }
        signum(&acc)
    }
}

fn signum(x: &BigInt) -> i32 {
    if x.is_positive() {
        1
    } else if x.is_negative() {
        -1
    } else {
        0
    }
}

/// The Sturm sequence `p, p', −rem(p, p'), …` of `p ≠ 0` (for a `p` that is
/// not square-free it ends in `gcd(p, p')`), each term a positive multiple
/// of the one over Q: a primitive pseudo-remainder sequence over Z, so no
/// gcd runs per coefficient operation.
pub(crate) fn sturm_sequence(p: &QPoly) -> Vec<SignPoly> {
    let mut seq = vec![SignPoly::new(p)];
    let dp = derivative(p);
    if dp.is_zero() {
        return seq;
    }
    seq.push(SignPoly::new(&dp));
    loop {
        let next = seq[seq.len() - 2].negated_remainder(&seq[seq.len() - 1]);
        if next.0.is_empty() {
            return seq;
        }
        seq.push(next);
    }
}

fn sign_changes(seq: &[SignPoly], x: &BigRational) -> usize {
    let signs: Vec<i32> = seq
        .iter()
        .map(|s| s.sign_at(x))
        .filter(|&v| v != 0)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// The number of distinct real roots in the open interval `(a, b)`, `a < b`
/// not roots themselves (Sturm's theorem).
pub(crate) fn count_roots(seq: &[SignPoly], a: &BigRational, b: &BigRational) -> usize {
    sign_changes(seq, a).saturating_sub(sign_changes(seq, b))
}

/// Can the integer polynomial `c` have a rational root? A root `k/L`
/// (`L` | leading coefficient) reduces to a root modulo every prime `p ∤ L`;
/// so `false` as soon as one small prime gives a polynomial without roots
/// in `F_p` (for an irreducible factor of degree `d ≥ 2` a prime does so
/// with probability about `1/e`, so a few dozen primes settle almost every
/// irrational case). `true` means "not excluded", not "has one".
pub(crate) fn may_have_rational_root(c: &[BigInt]) -> bool {
    const PRIMES: [u64; 24] = [
        101, 103, 107, 109, 113, 127, 131, 137, 139, 149, 151, 157, 163, 167, 173, 179, 181, 191,
        193, 197, 199, 211, 223, 227,
    ];
    if c.len() <= 2 {
        return true;
    }
    !PRIMES.iter().any(|&p| {
        let big = BigInt::from(p);
        let reduced: Vec<u64> = c
            .iter()
            .map(|x| {
                let r = x.mod_floor(&big);
                u64::try_from(r).expect("reduced below p")
            })
            .collect();
        if reduced.last() == Some(&0) {
            return false; // p divides the leading coefficient: no information
        }
        (0..p).all(|x| reduced.iter().rev().fold(0, |acc, &k| (acc * x + k) % p) != 0)
    })
}

/// Rational bounds `(lo, hi)` on `p(x)` for every `x ∈ [a, b]` (Horner in
/// interval arithmetic; exact rationals, so the enclosure is rigorous).
///
/// Run in integers over one denominator: with `p = Σ C_i xⁱ / L` and
/// `a = A/D`, `b = B/D`, the bounds after `k + 1` Horner steps are
/// numerators over `L·Dᵏ`; the four products of a step share their
/// denominator, so they order as their numerators, and the next
/// coefficient enters as `C_i·Dᵏ⁺¹`. Only the two results are reduced
/// (every rational product reduced by a gcd, the old way, was most of
/// the cost on dyadic enclosures).
pub(crate) fn eval_on_interval(
    p: &QPoly,
    a: &BigRational,
    b: &BigRational,
) -> (BigRational, BigRational) {
    let end_bits = crate::limits::bits(a).max(crate::limits::bits(b));
    let degree = p.coeffs().len() as u64;
    crate::limits::meter(4 * degree, poly_bits(p) + degree * end_bits);
    if p.is_zero() {
        return (q(0), q(0));
    }
    let (coeffs, l): (Vec<BigInt>, BigInt) = common_denominator(p.coeffs());
    let d = a.denom().lcm(b.denom());
    let (na, nb) = (a.numer() * (&d / a.denom()), b.numer() * (&d / b.denom()));
    let (mut lo, mut hi, mut scale) = (BigInt::zero(), BigInt::zero(), BigInt::one());
    for c in coeffs.iter().rev() {
        let products = [&lo * &na, &lo * &nb, &hi * &na, &hi * &nb];
        let min = products.iter().min().expect("four");
        let max = products.iter().max().expect("four");
        let c = c * &scale;
        (lo, hi) = (min + &c, max + c);
        scale *= &d;
    }
    let den = l * (scale / &d);
    // Reduced by Lehmer's gcd: the binary gcd is quadratic on these.
    let reduce = crate::algebra::gcd::fraction;
    (reduce(lo, den.clone()), reduce(hi, den))
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

/// A point of `(lo, hi)` near the middle that is not a root of `p`.
pub(crate) fn split_point(p: &SignPoly, lo: &BigRational, hi: &BigRational) -> BigRational {
    let mut mid = (lo + hi) / q(2);
    while p.sign_at(&mid) == 0 {
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
    meter((m + 1).saturating_sub(n).max(1) * n, &[a, b]);
    let (_, r) = a.div_rem(b).expect("non-zero divisor");
    let Some(k) = r.degree() else {
        return BigRational::zero();
    };
    let sign = if (m * n) % 2 == 1 { q(-1) } else { q(1) };
    sign * b.lead().expect("non-zero").pow((m - k) as i32) * resultant(b, &r)
}

/// The norm `∏_{p(α) = 0} H(α)` (roots with multiplicity, over C) of the
/// integer polynomial `H` modulo the integer polynomial `P` of degree `d`
/// with leading coefficient `L` (coefficients lowest power first), which is
/// `Res(P, H) / L^k` for `k = deg H` (Poisson's formula). With the
/// pseudo-remainder `R = lc(H)^{d−k+1}·P − Q·H` (equal to
/// `lc(H)^{d−k+1}·P(β)` at each root `β` of `H`):
///
/// ```text
/// Res(H, R) = lc(H)^{deg R + k(d−k+1)} ∏_β P(β),   Res(P, H) = (−1)^{dk} lc(H)^d ∏_β P(β)
/// ```
///
/// so only one pseudo-division of `P` by the (low-degree) `H` and a
/// Sylvester determinant of size below `2k` are needed, not one of size
/// `d + k`.
pub(crate) fn norm(p: &[BigInt], h: &[BigInt]) -> BigRational {
    let d = p.len() - 1;
    let Some(k) = h.iter().rposition(|c| !c.is_zero()) else {
        return BigRational::zero();
    };
    let lc = &h[k];
    let lead = &p[d];
    if k == 0 {
        return BigRational::from_integer(lc.pow(d as u32));
    }
    let bits = p.iter().chain(h).map(BigInt::bits).max().unwrap_or(0);
    crate::limits::meter(((d + 1).saturating_sub(k) * (k + 1)) as u64, bits);
    let mut r = p.to_vec();
    for top in (k..=d).rev() {
        let lead = std::mem::take(&mut r[top]);
        for c in r[..top].iter_mut() {
            *c *= lc;
        }
        for (j, b) in h[..k].iter().enumerate() {
            r[top - k + j] -= &lead * b;
        }
    }
    r.truncate(k.min(d + 1));
    while r.last().is_some_and(Zero::is_zero) {
        r.pop();
    }
    let Some(deg_r) = r.len().checked_sub(1) else {
        return BigRational::zero();
    };
    let res_hr = crate::algebra::sylvester::integer_determinant(
        crate::algebra::sylvester::sylvester_rows(&h[..=k], &r),
    );
    let steps = (d + 1).saturating_sub(k);
    let lc_pow = d as i64 - deg_r as i64 - (k * steps) as i64;
    let numer = if (d * k) % 2 == 1 { -res_hr } else { res_hr };
    let lc_part = lc.pow(lc_pow.unsigned_abs() as u32);
    let lead_part = lead.pow(k as u32);
    // One reduction by Lehmer's gcd, not one binary gcd per product.
    match lc_pow >= 0 {
        true => crate::algebra::gcd::fraction(numer * lc_part, lead_part),
        false => crate::algebra::gcd::fraction(numer, lc_part * lead_part),
    }
}

/// The polynomial of degree ≤ `D = values.len() − 1` through
/// `(k, values[k])`, `k = 0 … D` (Newton's forward differences), in
/// integers: with `L` the lcm of the denominators and `Δ^k` the forward
/// differences of `L·values`,
///
/// ```text
/// D!·L·P(x) = Σ_k Δ^k · (D!/k!) · x(x − 1)…(x − k + 1)      (Horner in the Newton basis)
/// ```
///
/// so the only divisions are the final `D + 1`.
pub(crate) fn interpolate(values: &[BigRational]) -> QPoly {
    let Some(deg) = values.len().checked_sub(1) else {
        return UPoly::zero();
    };
    let value_bits = values.iter().map(crate::limits::bits).max().unwrap_or(0);
    crate::limits::meter(2 * (deg as u64 + 1).pow(2), value_bits);
    let (mut diff, l): (Vec<BigInt>, _) = common_denominator(values);
    for level in 1..=deg {
        for k in (level..=deg).rev() {
            diff[k] = &diff[k] - &diff[k - 1];
        }
    }
    // weight[k] = D!/k!
    let mut weight = vec![BigInt::one(); deg + 1];
    for k in (0..deg).rev() {
        weight[k] = &weight[k + 1] * BigInt::from(k + 1);
    }
    let mut acc = vec![&diff[deg] * &weight[deg]];
    for k in (0..deg).rev() {
        // acc ← acc · (x − k) + Δ^k · D!/k!
        let mut next = vec![BigInt::zero(); acc.len() + 1];
        for (i, a) in acc.iter().enumerate() {
            next[i + 1] += a;
            next[i] -= a * BigInt::from(k);
        }
        next[0] += &diff[k] * &weight[k];
        acc = next;
    }
    let scale = l * &weight[0];
    UPoly::new(
        acc.into_iter()
            .map(|c| crate::algebra::gcd::fraction(c, scale.clone()))
            .collect(),
    )
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

/// The sign of a non-zero number from enclosures `enclose(prec)` that
/// shrink to it: `prec` doubles from `start` until the enclosure excludes
/// 0 (it must, the value being non-zero).
pub(crate) fn sign_by_refinement(
    start: u32,
    enclose: impl Fn(u32) -> (BigRational, BigRational),
) -> i32 {
    let mut prec = start;
    loop {
        let (lo, hi) = enclose(prec);
        if lo.is_positive() {
            return 1;
        }
        if hi.is_negative() {
            return -1;
        }
        prec *= 2;
    }
}

/// The root of the square-free polynomial `p` (as integers) that the
/// enclosures `enclose(prec)` shrink to: `prec` doubles from 16 until an
/// enclosure, rounded outward to multiples of `2^{−prec−2}` (short
/// numbers for the count), holds exactly one root (endpoints not roots,
/// one Descartes sign variation: [`super::descartes`]), `Ok(lo, hi)`;
/// `Err(q)` when an enclosure collapses to the rational point `q`.
pub(crate) fn isolate_by_enclosures(
    p: &SignPoly,
    enclose: impl Fn(u32) -> (BigRational, BigRational),
) -> Result<(BigRational, BigRational), BigRational> {
    let mut prec = 16;
    loop {
        let (lo, hi) = enclose(prec);
        if lo == hi {
            return Err(lo);
        }
        let unit = BigRational::from_integer(BigInt::one() << (prec as usize + 2));
        let (lo, hi) = ((&lo * &unit).floor() / &unit, (&hi * &unit).ceil() / &unit);
        if lo < hi
            && p.sign_at(&lo) != 0
            && p.sign_at(&hi) != 0
            && super::descartes::variations(p.coeffs(), &lo, &hi) == 1
        {
            return Ok((lo, hi));
        }
        prec *= 2;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(v: &[i64]) -> QPoly {
        UPoly::new(v.iter().map(|&x| q(x)).collect())
    }

    #[test]
    fn norm_is_the_product_over_the_roots() {
        // P = 2(x − 1)(x − 2)(x + 3), H = 2x² − x + 5 and H = 2x − 3.
        let ints = |v: &[i64]| v.iter().map(|&x| BigInt::from(x)).collect::<Vec<_>>();
        let p = ints(&[12, -14, 0, 2]);
        for h in [ints(&[5, -1, 2]), ints(&[-3, 2])] {
            let want = [1, 2, -3].iter().fold(BigInt::one(), |acc, &a| {
                acc * h.iter().rev().fold(BigInt::zero(), |v, c| v * a + c)
            });
            assert_eq!(norm(&p, &h), BigRational::from_integer(want));
        }
        // A modulus of lower degree than H, a constant H, a common root.
        assert_eq!(norm(&ints(&[-2, 1]), &ints(&[1, 0, 0, 1])), q(9));
        assert_eq!(norm(&p, &ints(&[3])), q(27));
        assert_eq!(norm(&p, &ints(&[-2, 1])), q(0));
    }

    #[test]
    fn sum_of_square_roots() {
        // √2 + √3 is a root of x⁴ − 10x² + 1.
        let s = sum_poly(&poly(&[-2, 0, 1]), &poly(&[-3, 0, 1]));
        assert_eq!(s.monic(), poly(&[1, 0, -10, 0, 1]));
        let p = product_poly(&poly(&[-2, 0, 1]), &poly(&[-3, 0, 1]));
        assert_eq!(p.monic(), poly(&[36, 0, -12, 0, 1]));
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// The integer Horner of `eval_on_interval` gives exactly the
        /// bounds of interval Horner in reduced rationals (the formula it
        /// replaces), on rational coefficients and ends.
        #[test]
        fn interval_horner_in_integers_matches_rationals(
            c in proptest::collection::vec((-99i64..=99, 1i64..=12), 0..=9),
            ends in (-50i64..=50, 1i64..=64, 0i64..=50, 1i64..=64),
        ) {
            let p = UPoly::new(c.iter().map(|&(n, d)| BigRational::new(n.into(), d.into())).collect());
            let a = BigRational::new(ends.0.into(), ends.1.into());
            let b = &a + BigRational::new(ends.2.into(), ends.3.into());
            let want = p.coeffs().iter().rev().fold((q(0), q(0)), |(lo, hi), c| {
                let products = [&lo * &a, &lo * &b, &hi * &a, &hi * &b];
                let min = products.iter().min().unwrap().clone();
                let max = products.iter().max().unwrap().clone();
                (min + c, max + c)
            });
            proptest::prop_assert_eq!(eval_on_interval(&p, &a, &b), want);
        }

        /// `monic` (Lehmer-reduced quotients) gives the coefficients of
        /// `UPoly::monic` (num-rational's reduction), in the same lowest
        /// terms.
        #[test]
        fn monic_matches_upoly_monic(
            c in proptest::collection::vec((-(1i64 << 40)..=(1i64 << 40), 1i64..=(1i64 << 40)), 0..=9),
        ) {
            let p = UPoly::new(c.iter().map(|&(n, d)| BigRational::new(n.into(), d.into())).collect());
            let (got, want) = (monic(&p), p.monic());
            proptest::prop_assert_eq!(got.coeffs().len(), want.coeffs().len());
            for (g, w) in got.coeffs().iter().zip(want.coeffs()) {
                proptest::prop_assert_eq!((g.numer(), g.denom()), (w.numer(), w.denom()));
            }
        }

        /// The norm by pseudo-division equals the Sylvester determinant of
        /// the monic modulus and `h` (the formula it replaces).
        #[test]
        fn norm_matches_the_sylvester_resultant(
            p in proptest::collection::vec(-9i64..=9, 2..=10),
            h in proptest::collection::vec(-9i64..=9, 1..=5),
        ) {
            let (pq, hq) = (poly(&p), poly(&h));
            proptest::prop_assume!(pq.degree().unwrap_or(0) > 0 && !hq.is_zero());
            let monic = pq.monic();
            let mut hc = hq.coeffs().to_vec();
            if hc.len() == 1 {
                hc.push(q(0)); // formal degree 1: Res(p, c) = c^d for monic p
            }
            let want = crate::algebra::sylvester::resultant(monic.coeffs(), &hc);
            let ints = |v: &QPoly| v.coeffs().iter().map(|c| c.to_integer()).collect::<Vec<_>>();
            let got = norm(&ints(&pq), &ints(&hq));
            proptest::prop_assert_eq!(got, want);
        }
    }
}
