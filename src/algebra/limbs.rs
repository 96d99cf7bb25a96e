//! Products and remainders of natural numbers as little-endian 64-bit
//! limbs, without allocation beyond the caller's buffers: what
//! [`fractions_over`](crate::algebra::gcd::fractions_over) needs for
//! `∏ xᵢ mod w` on numbers of a few limbs, where `num-bigint`'s operators
//! spent much of their time allocating and normalizing (a profile of the
//! GMP harness's 30-digit curve row).
//!
//! ```text
//! product:    schoolbook, one row a·b_j per limb of b        (Knuth, Algorithm M)
//! remainder:  shift so that den's top bit is set, then per limb of the quotient
//!             q̂ = ⌊(u_top·2⁶⁴ + u_next) / v_top⌋, corrected by v_next (at most twice),
//!             u ← u − q̂·v·2^{64j}, adding v back once if that went negative
//!                                                               (Knuth, Algorithm D)
//! by a word:  the same, one limb of the quotient per limb of n, each a division of
//!             two words by the normalized word through its reciprocal
//!                                                               (Möller–Granlund)
//! ```
//!
//! The product is quadratic (no Karatsuba), so the shared gcd takes these
//! for weights of up to 16 limbs and num-bigint's operators above.
//!
//! Reference: D. E. Knuth, *The Art of Computer Programming*, vol. 2, 3rd
//! ed., §4.3.1.

/// `a · b` written to `out` (resized to `a.len() + b.len()` limbs, with
/// leading zeros removed).
pub(crate) fn mul_into(a: &[u64], b: &[u64], out: &mut Vec<u64>) {
    out.clear();
    out.resize(a.len() + b.len(), 0);
    for (j, &bj) in b.iter().enumerate() {
        let mut carry = 0u128;
        for (i, &ai) in a.iter().enumerate() {
            let t = u128::from(ai) * u128::from(bj) + u128::from(out[i + j]) + carry;
            out[i + j] = t as u64;
            carry = t >> 64;
        }
        out[j + a.len()] = carry as u64;
    }
    trim(out);
}

/// `u mod v` (`v` non-zero, without leading zero limbs), written over `u`,
/// which keeps the remainder's limbs, leading zeros removed.
pub(crate) fn rem_in_place(u: &mut Vec<u64>, v: &[u64]) {
    let n = v.len();
    assert!(
        v.last().is_some_and(|&top| top != 0),
        "a trimmed non-zero divisor"
    );
    trim(u);
    if u.len() < n {
        return;
    }
    if n == 1 {
        let r = WordDivisor::new(v[0]).rem(u);
        u.clear();
        u.push(r);
        trim(u);
        return;
    }
    // Normalize: the divisor's top bit set, the dividend one limb longer.
    let shift = v[n - 1].leading_zeros();
    let (mut stack, mut heap) = ([0u64; 8], Vec::new());
    let v = if n <= stack.len() {
        stack[..n].copy_from_slice(v);
        &mut stack[..n]
    } else {
        heap.extend_from_slice(v);
        &mut heap[..]
    };
    shift_left(v, shift);
    let v = &*v;
    let top_divisor = Divisor::new(v[n - 1]);
    u.push(0);
    shift_left(u, shift);
    for j in (0..u.len() - n).rev() {
        let q = quotient_digit(&u[j..=j + n], v, top_divisor);
        if q != 0 && subtract_multiple(&mut u[j..=j + n], v, q) {
            add_back(&mut u[j..=j + n], v);
        }
    }
    u.truncate(n);
    shift_right(u, shift);
    trim(u);
}

/// Division by one limb `d ≠ 0`: the limbs of `n·2^s` (`2^s·d`
/// normalized) from the top through [`Divisor::div`]. Built once per
/// divisor, so that its reciprocal serves every number divided by it.
#[derive(Clone, Copy)]
pub(crate) struct WordDivisor {
    shift: u32,
    normalized: Divisor,
}

impl WordDivisor {
    /// The divisor `d ≠ 0`.
    pub(crate) fn new(d: u64) -> WordDivisor {
        let shift = d.leading_zeros();
        WordDivisor {
            shift,
            normalized: Divisor::new(d << shift),
        }
    }

    /// `n mod d`.
    pub(crate) fn rem(self, n: &[u64]) -> u64 {
        let r = (0..n.len()).rev().fold(shifted_top(n, self.shift), |r, i| {
            self.normalized.div(r, shifted_limb(n, i, self.shift)).1
        });
        r >> self.shift
    }

    /// `n ← ⌊n / d⌋`, returning `n mod d`; each quotient limb written
    /// over the limb it came from (the next one down, which it also reads,
    /// is still unchanged).
    pub(crate) fn div_in_place(self, n: &mut Vec<u64>) -> u64 {
        let mut r = shifted_top(n, self.shift);
        for i in (0..n.len()).rev() {
            (n[i], r) = self.normalized.div(r, shifted_limb(n, i, self.shift));
        }
        trim(n);
        r >> self.shift
    }
}

/// `10¹⁹`, the largest power of ten in a limb.
const TEN_19: u64 = 10_000_000_000_000_000_000;

/// Append the integer of magnitude `n` (little-endian limbs, consumed)
/// in decimal, with a `-` if `negative` and non-zero: the top limb's
/// digits, then blocks of 19 digits, the remainders of divisions by `10¹⁹`
/// (one reciprocal for all of them: [`WordDivisor`]).
pub(crate) fn push_decimal(out: &mut String, negative: bool, mut n: Vec<u64>) {
    trim(&mut n);
    if negative && !n.is_empty() {
        out.push('-');
    }
    let ten_19 = WordDivisor::new(TEN_19);
    let mut blocks = Vec::new();
    while n.len() > 1 {
        blocks.push(ten_19.div_in_place(&mut n));
    }
    push_word(out, n.first().copied().unwrap_or(0));
    for &block in blocks.iter().rev() {
        push_digits(out, block, 19);
    }
}

/// Append the word `u` in decimal.
pub(crate) fn push_word(out: &mut String, u: u64) {
    push_digits(out, u, 1);
}

/// Append the word `u` in decimal, with leading zeros to `width ≤ 20`
/// digits.
fn push_digits(out: &mut String, mut u: u64, width: usize) {
    let mut digits = [b'0'; 20];
    let mut at = digits.len();
    loop {
        at -= 1;
        digits[at] = b'0' + (u % 10) as u8;
        u /= 10;
        if u == 0 {
            break;
        }
    }
    let at = at.min(digits.len() - width);
    // ASCII digits: always UTF-8, appended as one slice.
    if let Ok(text) = std::str::from_utf8(&digits[at..]) {
        out.push_str(text);
    }
}

/// Limb `i` of `n·2^shift` (`shift < 64`).
fn shifted_limb(n: &[u64], i: usize, shift: u32) -> u64 {
    match (shift, i) {
        (0, _) => n[i],
        (_, 0) => n[0] << shift,
        _ => (n[i] << shift) | (n[i - 1] >> (64 - shift)),
    }
}

/// The limb of `n·2^shift` above `n`'s top limb (below `2^shift`).
fn shifted_top(n: &[u64], shift: u32) -> u64 {
    match (shift, n.last()) {
        (0, _) | (_, None) => 0,
        (_, Some(&top)) => top >> (64 - shift),
    }
}

/// A normalized divisor word `d` (top bit set) with its reciprocal
/// `v = ⌊(2¹²⁸ − 1)/d⌋ − 2⁶⁴`, which turns each division of two words by
/// `d` into two products (N. Möller and T. Granlund, "Improved division by
/// invariant integers", *IEEE Trans. Computers* 60, 2011, Algorithm 4):
///
/// ```text
/// (q₁, q₀) = v·u₁ + (u₁, u₀);  q₁ ← q₁ + 1;  r = u₀ − q₁·d  (mod 2⁶⁴)
/// if r > q₀: q₁ ← q₁ − 1, r ← r + d;   if r ≥ d: q₁ ← q₁ + 1, r ← r − d
/// ```
#[derive(Clone, Copy)]
struct Divisor {
    d: u64,
    reciprocal: u64,
}

impl Divisor {
    fn new(d: u64) -> Divisor {
        debug_assert!(d >> 63 == 1, "a normalized divisor");
        Divisor {
            d,
            reciprocal: (u128::MAX / u128::from(d) - (1u128 << 64)) as u64,
        }
    }

    /// `(⌊(u₁·2⁶⁴ + u₀)/d⌋, (u₁·2⁶⁴ + u₀) mod d)` for `u₁ < d`.
    fn div(self, u1: u64, u0: u64) -> (u64, u64) {
        debug_assert!(u1 < self.d, "the quotient fits a word");
        let q = (u128::from(self.reciprocal) * u128::from(u1))
            .wrapping_add((u128::from(u1) << 64) | u128::from(u0));
        let (mut q1, q0) = (((q >> 64) as u64).wrapping_add(1), q as u64);
        let mut r = u0.wrapping_sub(q1.wrapping_mul(self.d));
        if r > q0 {
            q1 = q1.wrapping_sub(1);
            r = r.wrapping_add(self.d);
        }
        if r >= self.d {
            q1 += 1;
            r -= self.d;
        }
        (q1, r)
    }
}

/// Knuth's estimate `q̂` of the quotient limb of the window `u` (`n + 1`
/// limbs) by the normalized `v` (`n ≥ 2` limbs), corrected by the second
/// limb of `v` until it is at most one too large.
fn quotient_digit(u: &[u64], v: &[u64], top_divisor: Divisor) -> u64 {
    let n = v.len();
    let (v1, v2) = (u128::from(v[n - 1]), u128::from(v[n - 2]));
    let (mut q, mut r) = if u[n] < v[n - 1] {
        let (q, r) = top_divisor.div(u[n], u[n - 1]);
        (u128::from(q), u128::from(r))
    } else {
        // The window's top limb equals v's (it is never larger): q̂ = 2⁶⁴ − 1.
        let q = u128::from(u64::MAX);
        (
            q,
            ((u128::from(u[n]) << 64) | u128::from(u[n - 1])) - q * v1,
        )
    };
    while r >> 64 == 0 && q * v2 > ((r << 64) | u128::from(u[n - 2])) {
        q -= 1;
        r += v1;
    }
    q as u64
}

/// `u ← u − q·v` over the window (`v.len() + 1` limbs); true if the
/// result went negative (then it is held in two's complement).
fn subtract_multiple(u: &mut [u64], v: &[u64], q: u64) -> bool {
    let (mut carry, mut borrow) = (0u128, 0u64);
    for (ui, &vi) in u.iter_mut().zip(v) {
        let p = u128::from(vi) * u128::from(q) + carry;
        carry = p >> 64;
        let (d1, b1) = ui.overflowing_sub(p as u64);
        let (d2, b2) = d1.overflowing_sub(borrow);
        *ui = d2;
        borrow = u64::from(b1) + u64::from(b2);
    }
    let top = u.last_mut().expect("the window has v.len() + 1 limbs");
    let (d1, b1) = top.overflowing_sub(carry as u64);
    let (d2, b2) = d1.overflowing_sub(borrow);
    *top = d2;
    b1 || b2
}

/// `u ← u + v` over the window, the carry out of the top limb dropped (it
/// cancels the borrow of [`subtract_multiple`]).
fn add_back(u: &mut [u64], v: &[u64]) {
    let mut carry = false;
    for (i, ui) in u.iter_mut().enumerate() {
        let vi = v.get(i).copied().unwrap_or(0);
        let (s1, c1) = ui.overflowing_add(vi);
        let (s2, c2) = s1.overflowing_add(u64::from(carry));
        *ui = s2;
        carry = c1 || c2;
    }
}

/// `n ← n · 2^shift` (`shift < 64`), the bits shifted out of the top limb
/// dropped (the callers leave a zero top limb or none to lose).
fn shift_left(n: &mut [u64], shift: u32) {
    if shift == 0 {
        return;
    }
    for i in (0..n.len()).rev() {
        let low = if i == 0 { 0 } else { n[i - 1] >> (64 - shift) };
        n[i] = (n[i] << shift) | low;
    }
}

/// `n ← ⌊n / 2^shift⌋` (`shift < 64`).
fn shift_right(n: &mut [u64], shift: u32) {
    if shift == 0 {
        return;
    }
    for i in 0..n.len() {
        let high = n.get(i + 1).map_or(0, |h| h << (64 - shift));
        n[i] = (n[i] >> shift) | high;
    }
}

/// Remove leading zero limbs.
pub(crate) fn trim(n: &mut Vec<u64>) {
    while n.last() == Some(&0) {
        n.pop();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    use crate::algebra::gcd::from_limbs as big;

    /// Limbs drawn to reach the rare branches of Algorithm D: all-ones and
    /// top-bit words make `q̂` too large and the add-back happen.
    fn limb() -> impl Strategy<Value = u64> {
        prop_oneof![
            any::<u64>(),
            Just(u64::MAX),
            Just(1u64 << 63),
            Just(0u64),
            Just(1u64)
        ]
    }

    proptest! {
        /// The decimal text is num-bigint's, for numbers of up to 8 limbs
        /// (blocks of 19 digits with leading zeros), zero and both signs.
        #[test]
        fn decimal_text_is_num_bigint_text(
            n in prop::collection::vec(prop_oneof![limb(), Just(TEN_19), Just(TEN_19 - 1)], 0..8),
            negative in any::<bool>(),
        ) {
            let magnitude = num_bigint::BigInt::from(big(&n));
            let want = if negative { -magnitude } else { magnitude };
            let mut got = String::from("x");
            push_decimal(&mut got, negative, n);
            prop_assert_eq!(got, format!("x{want}"));
        }

        /// Division by the reciprocal equals the machine's 128-bit division.
        #[test]
        fn reciprocal_division_is_division(d in limb(), u1 in limb(), u0 in limb()) {
            let d = d | 1 << 63;
            let u1 = u1 % d;
            let u = (u128::from(u1) << 64) | u128::from(u0);
            let want = ((u / u128::from(d)) as u64, (u % u128::from(d)) as u64);
            prop_assert_eq!(Divisor::new(d).div(u1, u0), want);
        }

        /// The product and the remainder equal num-bigint's.
        #[test]
        fn product_and_remainder_equal_num_bigint(
            a in prop::collection::vec(limb(), 0..8),
            b in prop::collection::vec(limb(), 0..8),
            mut v in prop::collection::vec(limb(), 1..6),
        ) {
            let mut product = Vec::new();
            mul_into(&a, &b, &mut product);
            prop_assert_eq!(big(&product), big(&a) * big(&b));
            trim(&mut v);
            prop_assume!(!v.is_empty());
            let mut u = product.clone();
            rem_in_place(&mut u, &v);
            prop_assert_eq!(big(&u), big(&product) % big(&v));
            prop_assert!(u.last() != Some(&0));
            let mut q = product.clone();
            WordDivisor::new(v[0].max(1)).div_in_place(&mut q);
            prop_assert_eq!(big(&q), big(&product) / big(&[v[0].max(1)]));
            prop_assert!(q.last() != Some(&0));
        }
    }

    /// Operands of extreme limbs, where `q̂` overshoots: every remainder
    /// is num-bigint's, and the add-back step (rare on random limbs) runs.
    #[test]
    fn extreme_limbs_reach_the_add_back_step() {
        let words = [0, 1, 2, (1u64 << 63) - 1, 1 << 63, u64::MAX - 1, u64::MAX];
        let mut add_backs = 0;
        // Three-limb divisors: with two, the correction by `v`'s second
        // limb already makes `q̂` exact.
        for &u3 in &words {
            for &u2 in &words {
                for &u1 in &words {
                    let divisors = words[4..]
                        .iter()
                        .flat_map(|&a| words.map(|b| (a, b)))
                        .flat_map(|(a, b)| words.map(|c| [c, b, a]));
                    for v in divisors {
                        let u = [u64::MAX, u1, u2, u3];
                        if big(&u[1..]) >= big(&v) {
                            continue; // not a window of Algorithm D
                        }
                        let q = quotient_digit(&u, &v, Divisor::new(v[2]));
                        add_backs += usize::from(subtract_multiple(&mut u.clone(), &v, q));
                        let mut r = u.to_vec();
                        rem_in_place(&mut r, &v);
                        assert_eq!(big(&r), big(&u) % big(&v));
                    }
                }
            }
        }
        assert!(add_backs > 0, "no operand reached the add-back step");
    }
}
