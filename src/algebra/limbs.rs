//! Products and remainders of natural numbers as little-endian 64-bit
//! limbs, without allocation beyond the caller's buffers: what
//! [`fractions_over`](crate::algebra::gcd::fractions_over) needs for
//! `∏ xᵢ mod w` on numbers of a few limbs, where `num-bigint`'s operators
//! spend most of their time allocating and normalizing.
//!
//! ```text
//! product:    schoolbook, one row a·b_j per limb of b        (Knuth, Algorithm M)
//! remainder:  shift so that den's top bit is set, then per limb of the quotient
//!             q̂ = ⌊(u_top·2⁶⁴ + u_next) / v_top⌋, corrected by v_next (at most twice),
//!             u ← u − q̂·v·2^{64j}, adding v back once if that went negative
//!                                                               (Knuth, Algorithm D)
//! ```
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
    assert!(v.last().is_some_and(|&top| top != 0), "a trimmed non-zero divisor");
    trim(u);
    if u.len() < n {
        return;
    }
    if n == 1 {
        let r = rem_word(u, v[0]);
        u.clear();
        u.push(r);
        trim(u);
        return;
    }
    // Normalize: the divisor's top bit set, the dividend one limb longer.
    let shift = v[n - 1].leading_zeros();
    let v = shifted(v, shift);
    u.push(0);
    shift_left(u, shift);
    for j in (0..u.len() - n).rev() {
        let q = quotient_digit(&u[j..=j + n], &v);
        if q != 0 && subtract_multiple(&mut u[j..=j + n], &v, q) {
            add_back(&mut u[j..=j + n], &v);
        }
    }
    u.truncate(n);
    shift_right(u, shift);
    trim(u);
}

/// `n mod d` for one limb `d ≠ 0`.
pub(crate) fn rem_word(n: &[u64], d: u64) -> u64 {
    n.iter().rev().fold(0u64, |r, &limb| {
        (((u128::from(r) << 64) | u128::from(limb)) % u128::from(d)) as u64
    })
}

/// Knuth's estimate `q̂` of the quotient limb of the window `u` (`n + 1`
/// limbs) by the normalized `v` (`n ≥ 2` limbs), corrected by the second
/// limb of `v` until it is at most one too large.
fn quotient_digit(u: &[u64], v: &[u64]) -> u64 {
    let n = v.len();
    let (top, v1, v2) = (u128::from(u[n]), u128::from(v[n - 1]), u128::from(v[n - 2]));
    let numerator = (top << 64) | u128::from(u[n - 1]);
    let mut q = (numerator / v1).min(u128::from(u64::MAX));
    let mut r = numerator - q * v1;
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

/// `v · 2^shift` for `shift < 64` that does not carry out of the top limb.
fn shifted(v: &[u64], shift: u32) -> Vec<u64> {
    let mut out = v.to_vec();
    shift_left(&mut out, shift);
    out
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
fn trim(n: &mut Vec<u64>) {
    while n.last() == Some(&0) {
        n.pop();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigUint;
    use proptest::prelude::*;

    fn big(limbs: &[u64]) -> BigUint {
        BigUint::from_slice(
            &limbs
                .iter()
                .flat_map(|l| [*l as u32, (*l >> 32) as u32])
                .collect::<Vec<_>>(),
        )
    }

    /// Limbs drawn to reach the rare branches of Algorithm D: all-ones and
    /// top-bit words make `q̂` too large and the add-back happen.
    fn limb() -> impl Strategy<Value = u64> {
        prop_oneof![any::<u64>(), Just(u64::MAX), Just(1u64 << 63), Just(0u64), Just(1u64)]
    }

    proptest! {
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
                        let q = quotient_digit(&u, &v);
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
