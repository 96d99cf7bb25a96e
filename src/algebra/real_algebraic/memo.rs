//! Per-thread memo tables for the radical fast path ([`super::radical`]):
//! the gcd of two bases and the fixed-point enclosure of a power.
//!
//! A model read from STEP places thousands of points in a few hundred
//! frames, and every coordinate is a radical sum over the same few bases
//! (`√|z|²`, `√|x⊥|²` of each frame). Adding, multiplying and comparing
//! them asks again and again whether two bases are coprime (a gcd of
//! 100–300-bit integers) and for the same enclosure of `√b` at the same
//! precision (an integer square root, Newton's method on big integers).
//! Both are pure functions of their arguments, so they are kept here and
//! looked up; the answers are the ones computed without the tables, bit
//! for bit. Each table is cleared when it reaches [`CAPACITY`] entries,
//! which bounds the memory at a few megabytes per thread.

use num_bigint::BigInt;
use std::cell::RefCell;
use std::collections::HashMap;

/// The most entries a table keeps before it is cleared.
pub(crate) const CAPACITY: usize = 4096;

/// The longest integer (in bits) whose gcds and enclosures are kept: with
/// [`CAPACITY`] entries a table then holds at most a few megabytes, even
/// when hostile input brings bases of thousands of digits (those are
/// computed every time).
pub(crate) const MAX_KEPT_BITS: u64 = 1024;

type GcdKey = (BigInt, BigInt);
type EnclosureKey = (BigInt, i64, i64, usize);

thread_local! {
    static GCDS: RefCell<HashMap<GcdKey, BigInt>> = RefCell::new(HashMap::new());
    static ENCLOSURES: RefCell<HashMap<EnclosureKey, (BigInt, BigInt)>> =
        RefCell::new(HashMap::new());
}

/// `gcd(a, b)` of two positive integers, by Lehmer's algorithm
/// ([`crate::algebra::gcd::gcd`]), remembered on this thread (the key is
/// the ordered pair, so `gcd(b, a)` is the same entry) unless one is
/// longer than [`MAX_KEPT_BITS`].
pub(crate) fn base_gcd(a: &BigInt, b: &BigInt) -> BigInt {
    let compute = || BigInt::from(crate::algebra::gcd::gcd(a.magnitude(), b.magnitude()));
    if a.bits().max(b.bits()) > MAX_KEPT_BITS {
        return compute();
    }
    let key = if a <= b {
        (a.clone(), b.clone())
    } else {
        (b.clone(), a.clone())
    };
    if let Some(g) = GCDS.with(|t| t.borrow().get(&key).cloned()) {
        return g;
    }
    let g = compute();
    remember(&GCDS, key, g.clone());
    g
}

/// The enclosure `compute()` of `b^(num/den)` at `w` fractional bits,
/// remembered on this thread under `(b, num, den, w)` unless `b` or `w` is
/// over [`MAX_KEPT_BITS`].
pub(crate) fn power_enclosure(
    b: &BigInt,
    (num, den): (i64, i64),
    w: usize,
    compute: impl FnOnce() -> (BigInt, BigInt),
) -> (BigInt, BigInt) {
    if b.bits() > MAX_KEPT_BITS || w as u64 > MAX_KEPT_BITS {
        return compute();
    }
    let key = (b.clone(), num, den, w);
    if let Some(e) = ENCLOSURES.with(|t| t.borrow().get(&key).cloned()) {
        return e;
    }
    let e = compute();
    remember(&ENCLOSURES, key, e.clone());
    e
}

fn remember<K: std::hash::Hash + Eq, V>(
    table: &'static std::thread::LocalKey<RefCell<HashMap<K, V>>>,
    key: K,
    value: V,
) {
    table.with(|t| {
        let mut t = t.borrow_mut();
        if t.len() >= CAPACITY {
            t.clear();
        }
        t.insert(key, value);
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;
    use proptest::prelude::*;

    proptest! {
        /// The remembered gcd is the gcd, asked either way round and twice.
        #[test]
        fn a_remembered_gcd_is_the_gcd(a in 1u128.., b in 1u128.., k in 1u64..) {
            let (a, b) = (BigInt::from(a) * k, BigInt::from(b) * k);
            let expected = a.gcd(&b);
            prop_assert_eq!(base_gcd(&a, &b), expected.clone());
            prop_assert_eq!(base_gcd(&b, &a), expected);
        }
    }

    #[test]
    fn a_remembered_enclosure_is_computed_once_per_key() {
        let b = BigInt::from(1_000_003);
        let mut calls = 0;
        for _ in 0..3 {
            let e = power_enclosure(&b, (1, 2), 40, || {
                calls += 1;
                (BigInt::from(1), BigInt::from(2))
            });
            assert_eq!(e, (BigInt::from(1), BigInt::from(2)));
        }
        assert_eq!(calls, 1);
        // Another precision is another entry.
        power_enclosure(&b, (1, 2), 41, || {
            calls += 1;
            (BigInt::from(1), BigInt::from(2))
        });
        assert_eq!(calls, 2);
    }

    #[test]
    fn a_long_base_is_computed_every_time() {
        let b = BigInt::from(3) << 2000usize;
        let mut calls = 0;
        for _ in 0..2 {
            power_enclosure(&b, (1, 2), 40, || {
                calls += 1;
                (BigInt::from(1), BigInt::from(2))
            });
        }
        assert_eq!(calls, 2);
        assert_eq!(base_gcd(&b, &BigInt::from(6)), BigInt::from(6));
        assert_eq!(GCDS.with(|t| t.borrow().len()), 0);
    }

    #[test]
    fn a_full_table_is_cleared_not_grown() {
        for i in 0..(CAPACITY as i64 + 10) {
            base_gcd(&BigInt::from(6), &BigInt::from(10 + i));
        }
        assert!(GCDS.with(|t| t.borrow().len()) <= CAPACITY);
    }
}
