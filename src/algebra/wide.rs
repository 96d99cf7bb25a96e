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

impl crate::algebra::scalar::MulAcc for Wide {}

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

    #[test]
    fn range_ends() {
        let top = (BigInt::from(1) << 255) - 1;
        assert_eq!(Wide::from_bigint(&top).unwrap().to_bigint(), top);
        assert_eq!(Wide::from_bigint(&-&top).unwrap().to_bigint(), -&top);
        assert_eq!(Wide::from_bigint(&(top + 1)), None);
    }
}
