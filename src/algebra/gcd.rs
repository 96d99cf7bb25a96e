//! Lehmer's gcd of big integers, and exact fractions normalized with it.
//!
//! `num-bigint`'s gcd is Stein's binary algorithm: one shift and one
//! subtraction of the whole number per bit, quadratic in the size with a
//! large constant. Lehmer's algorithm runs Euclid on the leading 64 bits
//! of both numbers, collects the quotients in a 2 × 2 matrix while they are
//! certain to be those of the full numbers (Collins' test below), and
//! applies the matrix to the big numbers once per about 30 quotients.
//!
//! ```text
//! x, y = leading 64 bits of a, b (same shift);  (A B; C D) = identity
//! while y + C ≠ 0, y + D ≠ 0 and q = ⌊(x + A)/(y + C)⌋ = ⌊(x + B)/(y + D)⌋:
//!     (A, B, C, D) ← (C, D, A − qC, B − qD);  (x, y) ← (y, x − qy)
//! (a, b) ← (A a + B b, C a + D b), or one full Euclid step if B = 0
//! ```
//!
//! Reference: D. E. Knuth, *The Art of Computer Programming*, vol. 2,
//! 3rd ed., §4.5.2, Algorithm L.

use super::limbs;
use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use std::borrow::Cow;

/// `gcd(a, b)` by Lehmer's algorithm (`gcd(0, 0) = 0`).
///
/// ```
/// use exact_bezier::algebra::gcd::gcd;
/// use exact_bezier::BigUint;
/// let a: BigUint = "123456789012345678901234567890123456789012345678901234567890".parse().unwrap();
/// let b: BigUint = "987654321098765432109876543210987654321098765432109876543210".parse().unwrap();
/// // Euclid's algorithm, one remainder at a time, gives the same answer.
/// let (mut x, mut y) = (a.clone(), b.clone());
/// while y != BigUint::from(0u32) {
///     let r = &x % &y;
///     (x, y) = (y, r);
/// }
/// assert_eq!(gcd(&a, &b), x);
/// ```
pub fn gcd(a: &BigUint, b: &BigUint) -> BigUint {
    if let (Some(x), Some(y)) = (a.to_u128(), b.to_u128()) {
        // Machine words: no limb vectors.
        return BigUint::from(gcd_u128(x, y));
    }
    from_limbs(&gcd_limbs(a.to_u64_digits(), b.to_u64_digits()))
}

/// [`gcd`] on little-endian 64-bit limbs (the form a fixed-size integer
/// such as [`Wide`](crate::algebra::Wide) has without a big integer).
pub(crate) fn gcd_limbs(mut a: Vec<u64>, mut b: Vec<u64>) -> Vec<u64> {
    if a.len() < b.len() || (a.len() == b.len() && a.iter().rev().lt(b.iter().rev())) {
        std::mem::swap(&mut a, &mut b);
    }
    b.resize(a.len(), 0);
    loop {
        trim(&mut a, &mut b);
        if b.is_empty() {
            return a;
        }
        if a.len() <= 2 {
            let g = gcd_u128(to_u128(&a), to_u128(&b));
            return vec![g as u64, (g >> 64) as u64];
        }
        let shift = bits(&a) - LEAD_BITS;
        let cofactors = cosequence(leading(&a, shift), leading(&b, shift));
        if cofactors[1] == 0 {
            // One quotient too large for the leading parts: a full step.
            let r = from_limbs(&a) % from_limbs(&b);
            a = std::mem::take(&mut b);
            b = r.to_u64_digits();
            b.resize(a.len(), 0);
        } else {
            combine(&mut a, &mut b, cofactors);
        }
    }
}

/// `(a, b) ← (A a + B b, C a + D b)` in place, limb by limb with signed
/// 128-bit carries. Each row of Lehmer's cofactors has entries of opposite
/// signs (or a zero), below 2⁶² in size: a row is `±(|A| a − |B| b)`, two
/// single-word products per limb; both results stay in `[0, a]`, so the
/// last carries are zero.
fn combine(a: &mut [u64], b: &mut [u64], [m00, m01, m10, m11]: [i64; 4]) {
    let row = |p: i64, q: i64| {
        let (p_abs, q_abs) = (p.unsigned_abs(), q.unsigned_abs());
        let sign: i128 = if p >= 0 && q <= 0 { 1 } else { -1 };
        move |x: u64, y: u64| {
            let px = u128::from(p_abs) * u128::from(x);
            let qy = u128::from(q_abs) * u128::from(y);
            sign * (px as i128 - qy as i128)
        }
    };
    let (row_a, row_b) = (row(m00, m01), row(m10, m11));
    let (mut carry_a, mut carry_b) = (0i128, 0i128);
    for (x, y) in a.iter_mut().zip(b.iter_mut()) {
        let na = row_a(*x, *y) + carry_a;
        let nb = row_b(*x, *y) + carry_b;
        (*x, *y) = (na as u64, nb as u64);
        (carry_a, carry_b) = (na >> 64, nb >> 64);
    }
    debug_assert!(
        carry_a == 0 && carry_b == 0,
        "Lehmer's cofactors keep 0 ≤ b ≤ a"
    );
}

/// Drop the leading zero limbs of `a`, and of `b` down to `a`'s length (the
/// two stay equally long, `b ≤ a`); `b` empties when it is zero.
fn trim(a: &mut Vec<u64>, b: &mut Vec<u64>) {
    while a.last() == Some(&0) {
        a.pop();
    }
    b.truncate(a.len());
    if b.iter().all(|&d| d == 0) {
        b.clear();
    }
}

/// The number of significant bits of a trimmed limb vector.
fn bits(n: &[u64]) -> u64 {
    n.last().map_or(0, |top| {
        64 * n.len() as u64 - u64::from(top.leading_zeros())
    })
}

/// The value of at most two limbs.
fn to_u128(n: &[u64]) -> u128 {
    n.iter()
        .rev()
        .fold(0, |acc, &d| (acc << 64) | u128::from(d))
}

/// The big integer of little-endian 64-bit limbs (up to 16 limbs, its
/// 32-bit digits on the stack, so that the result's is the one
/// allocation).
pub(crate) fn from_limbs(n: &[u64]) -> BigUint {
    const STACK: usize = 16;
    let mut stack = [0u32; 2 * STACK];
    let mut heap = Vec::new();
    let digits = if n.len() <= STACK {
        &mut stack[..2 * n.len()]
    } else {
        heap.resize(2 * n.len(), 0);
        &mut heap[..]
    };
    for (pair, &d) in digits.chunks_exact_mut(2).zip(n) {
        pair.copy_from_slice(&[d as u32, (d >> 32) as u32]);
    }
    let mut big = BigUint::zero();
    big.assign_from_slice(digits);
    big
}

/// Bits of the leading parts Lehmer's inner loop runs on: 62, so that the
/// parts, the cofactors (bounded by the parts) and their sums fit `i64`
/// and every quotient is one machine division.
const LEAD_BITS: u64 = 62;

/// `⌊n / 2^shift⌋` for a shift that leaves at most 64 bits, read from the
/// two limbs it spans (no shifted copy of `n`).
fn leading(n: &[u64], shift: u64) -> u64 {
    let (word, bit) = ((shift / 64) as usize, (shift % 64) as u32);
    let low = n.get(word).copied().unwrap_or(0);
    let high = n.get(word + 1).copied().unwrap_or(0);
    let wide = (u128::from(high) << 64) | u128::from(low);
    (wide >> bit) as u64
}

/// The matrix `(A, B, C, D)` of the quotients of Euclid on `(x, y)` that
/// are certain to be those of the full numbers (Knuth's Algorithm L);
/// `x, y < 2⁶²`, so every entry and sum fits `i64`.
fn cosequence(x: u64, y: u64) -> [i64; 4] {
    let (mut x, mut y) = (x as i64, y as i64);
    let (mut a, mut b, mut c, mut d) = (1i64, 0i64, 0i64, 1i64);
    while y + c != 0 && y + d != 0 {
        let q = (x + a) / (y + c);
        if q != (x + b) / (y + d) {
            break;
        }
        (a, c) = (c, a - q * c);
        (b, d) = (d, b - q * d);
        (x, y) = (y, x - q * y);
    }
    [a, b, c, d]
}

/// `gcd(x, y)` on machine words, by Stein's binary algorithm (shifts and
/// subtractions), on 64-bit words when both fit (the common case, several
/// times faster). Where they do not, one remainder first: a coordinate is
/// often far larger than its weight, and the binary algorithm would
/// spend a subtraction per bit of the difference.
pub(crate) fn gcd_u128(x: u128, y: u128) -> u128 {
    if let (Ok(a), Ok(b)) = (u64::try_from(x), u64::try_from(y)) {
        return u128::from(gcd_u64(a, b));
    }
    if x == 0 || y == 0 {
        return x | y;
    }
    if x == 1 || y == 1 {
        // An integer denominator.
        return 1;
    }
    let (big, small) = if x < y { (y, x) } else { (x, y) };
    let rest = big % small;
    if rest == 0 {
        return small;
    }
    match u64::try_from(small) {
        Ok(s) => u128::from(binary_gcd(s, rest as u64)),
        Err(_) => binary_gcd_wide(small, rest),
    }
}

/// `gcd(x, y)` of 64-bit words, by [`binary_gcd`].
#[inline]
pub(crate) fn gcd_u64(x: u64, y: u64) -> u64 {
    if x == 0 || y == 0 {
        return x | y;
    }
    if x == 1 || y == 1 {
        // An integer denominator: the binary algorithm would take a step per bit.
        return 1;
    }
    binary_gcd(x, y)
}

/// [`binary_gcd`] on 128-bit words that moves to 64-bit words as soon as
/// both operands fit one (each 64-bit step is about twice as fast), with
/// the same branch-free step: the odd part of `|x − y|` and `min(x, y)`.
fn binary_gcd_wide(x: u128, y: u128) -> u128 {
    let twos = (x | y).trailing_zeros();
    let (mut x, mut y) = (x >> x.trailing_zeros(), y >> y.trailing_zeros());
    while (x | y) >> 64 != 0 {
        if x == y {
            return x << twos;
        }
        let zeros = x.wrapping_sub(y).trailing_zeros();
        (x, y) = (x.abs_diff(y) >> zeros, x.min(y));
    }
    u128::from(binary_gcd(x as u64, y as u64)) << twos
}

/// Stein's binary gcd of non-zero words: strip the common factor 2, make
/// both odd, then replace the larger by the odd part of the difference.
/// The difference's trailing zeros are counted on `x − y` (wrapping: a
/// number and its negation have the same), in parallel with the minimum
/// and `|x − y|`, so one step's chain is a subtraction, a count and a
/// shift.
fn binary_gcd(x: u64, y: u64) -> u64 {
    let twos = (x | y).trailing_zeros();
    let (mut x, mut y) = (x >> x.trailing_zeros(), y >> y.trailing_zeros());
    while x != y {
        let zeros = x.wrapping_sub(y).trailing_zeros();
        (x, y) = (x.abs_diff(y) >> zeros, x.min(y));
    }
    x << twos
}

/// `lcm(a, b)` of positive integers, by [`gcd`].
///
/// ```
/// use exact_bezier::algebra::gcd::lcm;
/// use exact_bezier::BigInt;
/// assert_eq!(lcm(&BigInt::from(600), &BigInt::from(678)), BigInt::from(67800));
/// ```
pub fn lcm(a: &BigInt, b: &BigInt) -> BigInt {
    let g = gcd(a.magnitude(), b.magnitude());
    if g.is_one() {
        a * b
    } else {
        a / BigInt::from(g) * b
    }
}

/// The fraction `numer/denom` in lowest terms with a positive denominator,
/// reduced by [`gcd`].
///
/// **Panics if `denom` is zero.**
///
/// ```
/// use exact_bezier::algebra::gcd::fraction;
/// use exact_bezier::BigRational;
/// assert_eq!(fraction(6.into(), (-4).into()), BigRational::new((-3).into(), 2.into()));
/// ```
pub fn fraction(numer: BigInt, denom: BigInt) -> BigRational {
    assert!(!denom.is_zero(), "a fraction needs a nonzero denominator");
    let g = gcd(numer.magnitude(), denom.magnitude());
    let (n, d) = if g.is_one() {
        (numer, denom)
    } else {
        let g = BigInt::from(g);
        (numer / &g, denom / &g)
    };
    if d.sign() == Sign::Minus {
        BigRational::new_raw(-n, -d)
    } else {
        BigRational::new_raw(n, d)
    }
}

/// The fractions `numers[i] / denom` in lowest terms with positive
/// denominators, written to `out`, with one gcd of `denom`'s size for all
/// of them instead of one each:
///
/// ```text
/// g = gcd(w, ∏_{xᵢ ≠ 0} |xᵢ| mod w)        (w = |denom|)
/// gcd(xᵢ, w) = gcd(xᵢ mod g, g)
/// ```
///
/// since `gcd(xᵢ, w)` divides `w` and the product, hence `g`. The rest is
/// a product and a remainder of the numbers' size, and a gcd against `g`
/// per coordinate, which is mostly 1 (then the fractions need no division
/// at all) or a machine word. The coordinates of a rational point over its
/// weight are the case this serves: the point's cost falls from `d` big
/// gcds to one.
///
/// **Panics if `denom` is zero or `out` is shorter than `numers`.**
///
/// ```
/// use exact_bezier::algebra::gcd::fractions_over;
/// use exact_bezier::{BigInt, BigRational};
/// let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
/// let mut out = vec![q(0, 1); 3];
/// fractions_over(vec![6.into(), (-35).into(), 0.into()], (-210).into(), &mut out);
/// assert_eq!(out, [q(-1, 35), q(1, 6), q(0, 1)]);
/// ```
pub fn fractions_over(numers: Vec<BigInt>, denom: BigInt, out: &mut [BigRational]) {
    let signed = |n: &BigInt| SignedLimbs {
        negative: n.sign() == Sign::Minus,
        limbs: n.magnitude().iter_u64_digits().collect(),
    };
    let mut numers: Vec<SignedLimbs> = numers.iter().map(signed).collect();
    fractions_over_limbs(
        &mut numers,
        &mut signed(&denom),
        out,
        &mut Scratch::default(),
    );
}

/// An integer as its sign and the little-endian 64-bit limbs of its
/// magnitude (leading zero limbs allowed), the form in which
/// [`fractions_over_limbs`] takes the fixed-width integers of exact
/// evaluation without making big integers of them first.
#[derive(Clone, Debug, Default)]
pub(crate) struct SignedLimbs {
    pub negative: bool,
    pub limbs: Vec<u64>,
}

/// The product buffers of [`fractions_over_limbs`], kept from call to call.
#[derive(Clone, Debug, Default)]
pub(crate) struct Scratch {
    product: Vec<u64>,
    next: Vec<u64>,
}

/// [`fractions_over`] on limbs: the numerators' limbs are overwritten
/// (divided by their gcds), the denominator's trimmed, and only the
/// fractions written to `out` are big integers.
///
/// **Panics if `denom` is zero or `out` is shorter than `numers`.**
pub(crate) fn fractions_over_limbs(
    numers: &mut [SignedLimbs],
    denom: &mut SignedLimbs,
    out: &mut [BigRational],
    scratch: &mut Scratch,
) {
    limbs::trim(&mut denom.limbs);
    let w = &denom.limbs;
    assert!(!w.is_empty(), "a fraction needs a nonzero denominator");
    let shared = shared_gcd(numers, w, scratch);
    let den = from_limbs(w);
    let word_divisor = match shared.as_slice() {
        &[word] if word != 1 => Some(limbs::WordDivisor::new(word)),
        _ => None,
    };
    // The denominator divided by the last word gcd, and that gcd's
    // divisor, kept for the next coordinate with the same one.
    let mut reduced: Option<(u64, limbs::WordDivisor, BigUint)> = None;
    for (o, x) in out[..numers.len()].iter_mut().zip(numers.iter_mut()) {
        limbs::trim(&mut x.limbs);
        let negative = x.negative != denom.negative;
        let (n, d) = match (shared.as_slice(), word_divisor) {
            _ if x.limbs.is_empty() => {
                *o = BigRational::zero();
                continue;
            }
            ([1], _) => (from_limbs(&x.limbs), den.clone()),
            (&[word], Some(divisor)) => {
                let g = gcd_u64(divisor.rem(&x.limbs), word);
                if g == 1 {
                    (from_limbs(&x.limbs), den.clone())
                } else {
                    let (divisor, d) = match &reduced {
                        Some((last, divisor, d)) if *last == g => (*divisor, d.clone()),
                        _ => {
                            let (divisor, mut q) = (limbs::WordDivisor::new(g), w.to_vec());
                            divisor.div_in_place(&mut q);
                            let (_, divisor, d) = reduced.insert((g, divisor, from_limbs(&q)));
                            (*divisor, d.clone())
                        }
                    };
                    divisor.div_in_place(&mut x.limbs);
                    (from_limbs(&x.limbs), d)
                }
            }
            _ => {
                let (x, shared) = (from_limbs(&x.limbs), from_limbs(&shared));
                let g = gcd(&(&x % &shared), &shared);
                (x / &g, &den / &g)
            }
        };
        let sign = if negative { Sign::Minus } else { Sign::Plus };
        *o = BigRational::new_raw(BigInt::from_biguint(sign, n), BigInt::from(d));
    }
}

/// Limbs of the weight up to which [`shared_gcd`] multiplies and divides
/// on limbs ([`limbs`], quadratic, without allocation); above, by
/// num-bigint (Karatsuba from 32 limbs). On 100 000-digit coordinates the
/// quadratic product made the shared gcd slower than three gcds.
const LONG_LIMBS: usize = 16;

/// `gcd(w, ∏_{xᵢ ≠ 0} |xᵢ| mod w)`, which every `gcd(xᵢ, w)` divides, as
/// trimmed limbs: the product and the remainder on the limbs
/// ([`limbs`]), then Lehmer's gcd.
fn shared_gcd(numers: &[SignedLimbs], w: &[u64], scratch: &mut Scratch) -> Vec<u64> {
    if w == [1] {
        return w.to_vec();
    }
    let Scratch { product, next } = scratch;
    let factors = numers.iter().filter(|x| x.limbs.iter().any(|&l| l != 0));
    if w.len() <= LONG_LIMBS {
        product.clear();
        product.push(1);
        for x in factors {
            limbs::mul_into(product, &x.limbs, next);
            std::mem::swap(product, next);
        }
        limbs::rem_in_place(product, w);
    } else {
        // Long numbers: num-bigint's subquadratic product and division.
        let p = factors.fold(BigUint::one(), |p, x| p * from_limbs(&x.limbs));
        *product = (p % from_limbs(w)).to_u64_digits();
    }
    let mut g = if w.len() <= 2 {
        let g = gcd_u128(to_u128(w), to_u128(product));
        vec![g as u64, (g >> 64) as u64]
    } else {
        gcd_limbs(w.to_vec(), product.clone())
    };
    limbs::trim(&mut g);
    g
}

/// `a · b` in lowest terms (both in lowest terms, as every `BigRational`
/// is), by Knuth's cross reduction: with `g₁ = gcd(n₁, d₂)` and
/// `g₂ = gcd(n₂, d₁)`,
///
/// ```text
/// (n₁/d₁)·(n₂/d₂) = ((n₁/g₁)(n₂/g₂)) / ((d₁/g₂)(d₂/g₁)),  already reduced,
/// ```
///
/// two gcds of the factors' sizes instead of one of the product's (gcds
/// cost the square of the size; one against a small or unit denominator is
/// a single remainder, or nothing). num-rational's own product reduces
/// the product by the binary gcd. Reference: D. E. Knuth, *The Art of
/// Computer Programming*, vol. 2, 3rd ed., §4.5.1.
///
/// ```
/// use exact_bezier::algebra::gcd::product;
/// use exact_bezier::BigRational;
/// let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
/// assert_eq!(product(&q(6, 35), &q(-14, 9)), q(-4, 15));
/// assert_eq!(product(&q(0, 1), &q(-14, 9)), q(0, 1));
/// ```
pub fn product(a: &BigRational, b: &BigRational) -> BigRational {
    if a.is_zero() || b.is_zero() {
        return BigRational::zero();
    }
    let (n1, d2) = cancel(a.numer(), b.denom());
    let (n2, d1) = cancel(b.numer(), a.denom());
    BigRational::new_raw(&*n1 * &*n2, &*d1 * &*d2)
}

/// `(n/g, d/g)` with `g = gcd(n, d)`, borrowed where `g = 1`.
fn cancel<'a>(n: &'a BigInt, d: &'a BigInt) -> (Cow<'a, BigInt>, Cow<'a, BigInt>) {
    let g = if d.is_one() {
        BigUint::one()
    } else {
        gcd(n.magnitude(), d.magnitude())
    };
    if g.is_one() {
        (Cow::Borrowed(n), Cow::Borrowed(d))
    } else {
        let g = BigInt::from(g);
        (Cow::Owned(n / &g), Cow::Owned(d / &g))
    }
}

/// `a + b` in lowest terms (both in lowest terms), by Knuth's method: with
/// `d = gcd(d₁, d₂)`,
///
/// ```text
/// t = n₁·(d₂/d) + n₂·(d₁/d),  e = gcd(t, d),  a + b = (t/e) / ((d₁/d)·(d₂/e)),
/// ```
///
/// gcds of the denominators' size instead of one of the cross product's
/// (for `d = 1` none more: the sum is already reduced). Reference: Knuth,
/// *The Art of Computer Programming*, vol. 2, §4.5.1.
///
/// ```
/// use exact_bezier::algebra::gcd::sum;
/// use exact_bezier::BigRational;
/// let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
/// assert_eq!(sum(&q(1, 6), &q(3, 10)), q(7, 15));
/// assert_eq!(sum(&q(1, 6), &q(-1, 6)), q(0, 1));
/// assert_eq!(sum(&q(1, 6), &q(1, 35)), q(41, 210));
/// ```
pub fn sum(a: &BigRational, b: &BigRational) -> BigRational {
    let (d1, d2) = (a.denom(), b.denom());
    let d = BigInt::from(gcd(d1.magnitude(), d2.magnitude()));
    if d.is_one() {
        return BigRational::new_raw(a.numer() * d2 + b.numer() * d1, d1 * d2);
    }
    let (r1, r2) = (d1 / &d, d2 / &d);
    let t = a.numer() * &r2 + b.numer() * &r1;
    if t.is_zero() {
        return BigRational::zero();
    }
    let e = BigInt::from(gcd(t.magnitude(), d.magnitude()));
    if e.is_one() {
        BigRational::new_raw(t, r1 * d2)
    } else {
        BigRational::new_raw(t / &e, r1 * (d2 / e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;
    use proptest::prelude::*;

    use super::from_limbs as big;

    proptest! {
        /// Lehmer's gcd equals the binary gcd of `num-integer`, on numbers
        /// with a planted common factor and on random ones.
        #[test]
        fn lehmer_equals_binary_gcd(
            a in prop::collection::vec(any::<u64>(), 0..12),
            b in prop::collection::vec(any::<u64>(), 0..12),
            f in prop::collection::vec(any::<u64>(), 0..4),
        ) {
            let (a, b, f) = (big(&a), big(&b), big(&f));
            prop_assert_eq!(gcd(&a, &b), a.gcd(&b));
            let (fa, fb) = (&a * &f, &b * &f);
            prop_assert_eq!(gcd(&fa, &fb), fa.gcd(&fb));
        }

        /// The word gcd equals `num-integer`'s, on words of any sizes (one
        /// far larger than the other takes the remainder first).
        #[test]
        fn word_gcd_equals_binary_gcd(x in any::<u128>(), y in any::<u64>(), shift in 0u32..64, f in 1..u32::MAX) {
            let (x, y) = (x.saturating_mul(u128::from(f)), u128::from(y) << shift);
            prop_assert_eq!(gcd_u128(x, y), x.gcd(&y));
            prop_assert_eq!(gcd_u128(y, x), x.gcd(&y));
        }

        /// Knuth's reduced product and sum equal num-rational's operators
        /// (which reduce the whole result), on fractions of one to four
        /// words with planted common factors (so that the cross gcds and
        /// the denominators' gcd are not 1), equal denominators and zero.
        #[test]
        fn reduced_product_and_sum_are_the_field_operations(
            n in prop::collection::vec(any::<u64>(), 0..4),
            d in prop::collection::vec(any::<u64>(), 1..4),
            m in prop::collection::vec(any::<u64>(), 0..4),
            e in prop::collection::vec(any::<u64>(), 1..4),
            f in 1u64..1 << 40,
            negative in any::<bool>(),
            same_denominator in any::<bool>(),
        ) {
            let int = |l: &[u64], sign: bool| {
                let x = BigInt::from(big(l));
                if sign { -x } else { x }
            };
            let f = BigInt::from(f);
            let den = |l: &[u64]| int(l, false) * &f + 1u32;
            let a = BigRational::new(int(&n, negative) * &f, den(&d));
            let b = if same_denominator {
                BigRational::new(int(&m, false), a.denom().clone())
            } else {
                BigRational::new(int(&m, false) * &f, den(&e) * &f)
            };
            // Numerator and denominator compared, not the values: a
            // `Ratio` compares equal to its unreduced forms.
            let parts = |x: BigRational| x.into_raw();
            prop_assert_eq!(parts(product(&a, &b)), parts(&a * &b));
            prop_assert_eq!(parts(product(&b, &a)), parts(&a * &b));
            prop_assert_eq!(parts(sum(&a, &b)), parts(&a + &b));
            prop_assert_eq!(parts(sum(&a, &-&a)), parts(BigRational::zero()));
        }

        /// The shared gcd gives every coordinate num-rational's reduced
        /// fraction: numerators and a denominator of one to 23 words (on
        /// limbs up to `LONG_LIMBS`, by num-bigint above) with a planted
        /// common factor (so that the shared gcd is 1, a word or several),
        /// zero and negative numerators, negative denominators.
        #[test]
        fn fractions_over_one_gcd_are_the_reduced_fractions(
            numers in prop::collection::vec((prop::collection::vec(any::<u64>(), 0..24), any::<bool>()), 1..5),
            denom in prop::collection::vec(any::<u64>(), 1..24),
            negative in any::<bool>(),
            f in prop::collection::vec(any::<u64>(), 0..3),
        ) {
            let f = big(&f) + 1u32;
            let signed = |m: BigUint, neg: bool| if neg { -BigInt::from(m) } else { BigInt::from(m) };
            let numers: Vec<BigInt> = numers.iter().map(|(m, neg)| signed(big(m) * &f, *neg)).collect();
            let denom = signed(big(&denom) * &f, negative);
            prop_assume!(!denom.is_zero());
            let mut out = vec![BigRational::zero(); numers.len()];
            fractions_over(numers.clone(), denom.clone(), &mut out);
            for (x, o) in numers.into_iter().zip(out) {
                prop_assert_eq!(o.into_raw(), BigRational::new(x, denom.clone()).into_raw());
            }
        }

        /// On 64-bit words with a common factor (the binary loop alone).
        #[test]
        fn binary_gcd_of_words_is_the_gcd(x in 1..u64::MAX >> 20, y in 1..u64::MAX >> 20, f in 1u64..1 << 20) {
            let (x, y) = (x * f, y * f);
            prop_assert_eq!(binary_gcd(x, y), x.gcd(&y));
        }
    }

    /// `F_k`, the Fibonacci numbers: every Euclidean quotient is 1, the
    /// longest cosequence per bit.
    fn fibonacci(k: usize) -> BigUint {
        let (mut a, mut b) = (BigUint::zero(), BigUint::one());
        for _ in 0..k {
            (a, b) = (b.clone(), a + b);
        }
        a
    }

    proptest! {
        /// Numbers close to each other (agreeing in many leading bits),
        /// far apart in size (quotients beyond a step), and Fibonacci
        /// neighbours times a factor: the edges of Lehmer's step (a full
        /// Euclid step when a quotient is too large).
        #[test]
        fn lehmer_equals_binary_gcd_at_the_edges(
            a in prop::collection::vec(any::<u64>(), 1..10),
            delta in prop::collection::vec(any::<u64>(), 0..3),
            shift in 0u32..700,
            k in 90usize..1500,
            f in any::<u64>(),
        ) {
            let (a, delta, f) = (big(&a), big(&delta), BigUint::from(f));
            let close = &a + &delta;
            prop_assert_eq!(gcd(&close, &a), close.gcd(&a));
            let far = (&a << shift) + &delta;
            prop_assert_eq!(gcd(&far, &a), far.gcd(&a));
            prop_assert_eq!(gcd(&a, &far), far.gcd(&a));
            let (x, y) = (fibonacci(k + 1) * &f, fibonacci(k) * &f);
            prop_assert_eq!(gcd(&x, &y), x.gcd(&y));
        }
    }

    #[test]
    fn edge_cases() {
        let two = BigUint::from(2u32);
        let p = two.pow(300u32);
        assert_eq!(gcd(&p, &BigUint::zero()), p);
        assert_eq!(gcd(&BigUint::zero(), &BigUint::zero()), BigUint::zero());
        assert_eq!(gcd(&p, &two.pow(200u32)), two.pow(200u32));
        assert_eq!(gcd(&p, &(&p + 1u32)), BigUint::from(1u32));
        assert_eq!(
            fraction((-10).into(), (-4).into()),
            BigRational::new(5.into(), 2.into())
        );
    }
}
