//! [`Wide`]: a 256-bit signed integer on the stack, the middle tier of
//! fraction-free exact evaluation ([`crate::eval`]).
//!
//! Exact evaluation picks, point by point, the narrowest integer type that
//! provably holds every value of the Horner–Bernstein kernel: `i128`, then
//! `Wide`, then the growing [`Int`](crate::algebra::Int). A value of up to
//! 255 bits then costs no heap allocation and no overflow test; the bound
//! that makes this safe is in `eval::fraction_free`.
//!
//! The arithmetic is `ethnum`'s `I256` (two's complement on two `u128`
//! words); `Wide` adds the `num-traits` identities that make it a
//! [`Ring`](crate::Ring).

use ethnum::{I256, U256};
use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{One, Zero};
use std::ops::{Add, Mul, Neg, Sub};

/// A 256-bit signed integer. Overflow is a bug of the caller (it panics
/// where `overflow-checks` are on and wraps elsewhere), so it is used only
/// where a bound proves that values fit.
///
/// ```
/// use exact_bezier::algebra::Wide;
/// let big = Wide::from(i128::MAX) * &Wide::from(4);
/// assert_eq!(big.to_bigint(), exact_bezier::BigInt::from(i128::MAX) * 4);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Wide(I256);

impl Wide {
    /// Bits of magnitude a `Wide` holds: every `|x| < 2²⁵⁵`.
    pub const BITS: u64 = 255;

    /// The value as a big integer (its magnitude's 32-bit digits, one
    /// allocation).
    pub fn to_bigint(&self) -> BigInt {
        let sign = if self.0 < I256::ZERO {
            Sign::Minus
        } else {
            Sign::Plus
        };
        let (hi, lo) = self.0.unsigned_abs().into_words();
        let digits: [u32; 8] = std::array::from_fn(|k| {
            let word = if k < 4 { lo } else { hi };
            (word >> (32 * (k % 4))) as u32
        });
        BigInt::from_biguint(sign, BigUint::from_slice(&digits))
    }

    /// `|self|` as four little-endian 64-bit limbs.
    pub(crate) fn magnitude_limbs(&self) -> [u64; 4] {
        let (hi, lo) = self.0.unsigned_abs().into_words();
        [lo as u64, (lo >> 64) as u64, hi as u64, (hi >> 64) as u64]
    }

    /// `gcd(|self|, |other|)` by Lehmer's algorithm on the four 64-bit limbs
    /// ([`gcd`](crate::algebra::gcd::gcd)), with no big integer.
    ///
    /// ```
    /// use exact_bezier::algebra::Wide;
    /// let a = Wide::from(i128::MAX) * &Wide::from(6);
    /// let b = Wide::from(i128::MAX) * &Wide::from(-4);
    /// assert_eq!(a.gcd(&b), Wide::from(i128::MAX) * &Wide::from(2));
    /// ```
    pub fn gcd(&self, other: &Wide) -> Wide {
        let (a, b) = (self.0.unsigned_abs(), other.0.unsigned_abs());
        let (a, b) = if a < b { (b, a) } else { (a, b) };
        if b == U256::ZERO {
            return Wide(a.as_i256());
        }
        // One remainder in 256 bits first: the quotient of a coordinate by
        // the weight is usually far beyond what Lehmer's leading words
        // certify, and would cost a big-integer division there.
        let limbs = |x: U256| {
            let (hi, lo) = x.into_words();
            vec![lo as u64, (lo >> 64) as u64, hi as u64, (hi >> 64) as u64]
        };
        let g = crate::algebra::gcd::gcd_limbs(limbs(b), limbs(a % b));
        let word = |k: usize| u128::from(g.get(k).copied().unwrap_or(0));
        Wide(I256::from_words(
            (word(2) | word(3) << 64) as i128,
            (word(0) | word(1) << 64) as i128,
        ))
    }

    /// Is `self < 0`?
    pub fn is_negative(&self) -> bool {
        self.0 < I256::ZERO
    }

    /// `self / d` for a divisor `d ≠ 0` of `self`.
    pub fn div_exact(&self, d: &Wide) -> Wide {
        Wide(self.0 / d.0)
    }

    /// The number of bits of `|self|` (0 for zero).
    pub fn bits(&self) -> u64 {
        u64::from(256 - self.0.unsigned_abs().leading_zeros())
    }

    /// The big integer `n`, or `None` if `|n| ≥ 2²⁵⁵`.
    pub fn from_bigint(n: &BigInt) -> Option<Wide> {
        if n.bits() > Self::BITS {
            return None;
        }
        let low_mask = (BigInt::from(1) << 128) - 1;
        let lo = u128::try_from(n & &low_mask).ok()?;
        let hi = i128::try_from(n >> 128).ok()?;
        Some(Wide(I256::from_words(hi, lo as i128)))
    }
}

impl From<i128> for Wide {
    fn from(n: i128) -> Wide {
        Wide(I256::from(n))
    }
}

/// `+`, `−`, `×` by value and by reference, as `I256`'s.
macro_rules! wide_binary_op {
    ($Trait:ident, $method:ident) => {
        impl<'a> $Trait<&'a Wide> for Wide {
            type Output = Wide;
            fn $method(self, rhs: &'a Wide) -> Wide {
                Wide(self.0.$method(rhs.0))
            }
        }
        impl $Trait for Wide {
            type Output = Wide;
            fn $method(self, rhs: Wide) -> Wide {
                Wide(self.0.$method(rhs.0))
            }
        }
    };
}

wide_binary_op!(Add, add);
wide_binary_op!(Sub, sub);
wide_binary_op!(Mul, mul);

impl Neg for Wide {
    type Output = Wide;
    fn neg(self) -> Wide {
        Wide(-self.0)
    }
}

/// `acc·a + c·x`, each product by a machine word where the factor is one
/// (in Horner's sums `a` and `c` are the parameter and its powers, mostly
/// words): four limb products instead of a full 256-bit product.
impl crate::algebra::scalar::MulAcc for Wide {
    fn mul_acc(acc: &mut Wide, a: &Wide, c: &Wide, x: &Wide) {
        *acc = acc.times(a) + c.word().map_or_else(|| *c * x, |k| x.times_word(k));
    }
}

impl Wide {
    /// `self · k`, by a word when `k` is one.
    fn times(self, k: &Wide) -> Wide {
        k.word().map_or_else(|| self * k, |k| self.times_word(k))
    }

    /// The value as an `i64`, if it is one.
    fn word(&self) -> Option<i64> {
        let (hi, lo) = self.0.into_words();
        (hi == lo >> 127 && lo == i128::from(lo as i64)).then_some(lo as i64)
    }

    /// `self · k` modulo 2²⁵⁶ (exact where the product fits, as the
    /// callers' bounds prove): the two's-complement limbs times `|k|` with
    /// carries, negated for `k < 0`.
    fn times_word(self, k: i64) -> Wide {
        let (hi, lo) = self.0.as_u256().into_words();
        let s = u128::from(k.unsigned_abs());
        let p0 = (lo as u64 as u128) * s;
        let p1 = (lo >> 64) * s + (p0 >> 64);
        let p2 = (hi as u64 as u128) * s + (p1 >> 64);
        let p3 = (hi >> 64).wrapping_mul(s).wrapping_add(p2 >> 64);
        let product = U256::from_words(
            (p2 as u64 as u128) | (p3 << 64),
            (p0 as u64 as u128) | (p1 << 64),
        )
        .as_i256();
        Wide(if k < 0 {
            product.wrapping_neg()
        } else {
            product
        })
    }
}

impl Zero for Wide {
    fn zero() -> Wide {
        Wide(I256::ZERO)
    }
    fn is_zero(&self) -> bool {
        self.0 == I256::ZERO
    }
}

impl One for Wide {
    fn one() -> Wide {
        Wide(I256::ONE)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// `Wide` arithmetic agrees with big integers on values whose
        /// results stay below 2²⁵⁵, and the conversions round-trip.
        #[test]
        fn agrees_with_bigint(a in any::<i128>(), b in any::<i128>(), c in any::<i64>()) {
            let (wa, wb, wc) = (Wide::from(a), Wide::from(b), Wide::from(i128::from(c)));
            let (ba, bb, bc) = (BigInt::from(a), BigInt::from(b), BigInt::from(c));
            let w = wa * wb - wc * wc + wa;
            let n = &ba * &bb - &bc * &bc + &ba;
            prop_assert_eq!(w.to_bigint(), n.clone());
            prop_assert_eq!(Wide::from_bigint(&n), Some(w));
        }

        /// `gcd` and `div_exact` agree with big integers, on operands of
        /// very different sizes (a coordinate and its weight) and with a
        /// planted common factor.
        #[test]
        fn gcd_agrees_with_bigint(a in any::<i128>(), b in any::<i128>(), c in any::<i64>(), f in 1..u64::MAX) {
            use num_integer::Integer;
            let (x, y) = (Wide::from(a) * Wide::from(i128::from(f)), Wide::from(i128::from(c)) * Wide::from(b));
            let g = x.gcd(&y);
            prop_assert_eq!(g.to_bigint(), x.to_bigint().gcd(&y.to_bigint()));
            if !g.is_zero() {
                prop_assert_eq!(x.div_exact(&g).to_bigint(), x.to_bigint() / g.to_bigint());
            }
        }
    }

    proptest! {
        /// The word path of `mul_acc` is the full product's: word factors
        /// against a 187-bit `x`, and 126-bit factors (the full path)
        /// against a 126-bit one, so that every value stays below 2²⁵⁵.
        #[test]
        fn mul_acc_by_words_is_the_product(
            x in any::<i128>(), acc in any::<i128>(), a in any::<i64>(), c in any::<i64>(),
            big_a in any::<i128>(), big_c in any::<i128>(),
        ) {
            let w = Wide::from;
            let check = |acc: Wide, a: Wide, c: Wide, x: Wide| {
                let mut got = acc;
                crate::algebra::scalar::MulAcc::mul_acc(&mut got, &a, &c, &x);
                let want = acc.to_bigint() * a.to_bigint() + c.to_bigint() * x.to_bigint();
                (got.to_bigint(), want)
            };
            let (got, want) = check(w(acc), w(a.into()), w(c.into()), w(x) * w(1 << 60));
            prop_assert_eq!(got, want);
            let (got, want) = check(w(acc >> 1), w(big_a >> 1), w(big_c >> 1), w(x >> 1));
            prop_assert_eq!(got, want);
        }
    }

    #[test]
    fn range_ends() {
        let top = (BigInt::from(1) << 255) - 1;
        assert_eq!(Wide::from_bigint(&top).unwrap().to_bigint(), top);
        assert_eq!(Wide::from_bigint(&-&top).unwrap().to_bigint(), -&top);
        assert_eq!(Wide::from_bigint(&(top + 1)), None);
    }
}
