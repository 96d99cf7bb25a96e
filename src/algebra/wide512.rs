//! [`Wide512`]: a 512-bit signed integer on the stack, the tier of
//! fraction-free exact evaluation ([`crate::eval`]) between the 256-bit
//! [`Wide`](crate::algebra::Wide) and the growing [`Int`](crate::algebra::Int).
//!
//! Eight little-endian 64-bit limbs in two's complement. Sums are one carry
//! chain over the limbs; a product multiplies the magnitudes' significant
//! limbs only (schoolbook, Knuth, *TAOCP* vol. 2, §4.3.1, Algorithm M,
//! truncated to 512 bits) — in the Horner–Bernstein kernel one factor is
//! usually a parameter of one limb, so a product costs a few machine
//! multiplications, and nothing allocates.

use num_bigint::{BigInt, BigUint, Sign};
use num_traits::{One, Zero};
use std::ops::{Add, Mul, Neg, Sub};

/// Limbs of a [`Wide512`].
const LIMBS: usize = 8;

/// A 512-bit signed integer. Overflow wraps silently, so it is used only
/// where a bound proves that values fit (`|x| < 2⁵¹¹`).
///
/// ```
/// use exact_bezier::algebra::Wide512;
/// let big = Wide512::from(i128::MAX) * &Wide512::from(i128::MIN) * &Wide512::from(-3);
/// assert_eq!(big.to_bigint(), exact_bezier::BigInt::from(i128::MAX) * i128::MIN * -3);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Wide512([u64; LIMBS]);

impl Wide512 {
    /// Bits of magnitude a `Wide512` holds: every `|x| < 2⁵¹¹`.
    pub const BITS: u64 = 511;

    /// Is `self < 0`?
    pub fn is_negative(&self) -> bool {
        (self.0[LIMBS - 1] as i64) < 0
    }

    /// `|self|` as little-endian limbs (correct for every `|x| < 2⁵¹¹`).
    pub(crate) fn magnitude(&self) -> [u64; LIMBS] {
        if self.is_negative() {
            (-*self).0
        } else {
            self.0
        }
    }

    /// `±magnitude`.
    fn signed(negative: bool, magnitude: [u64; LIMBS]) -> Wide512 {
        let x = Wide512(magnitude);
        if negative {
            -x
        } else {
            x
        }
    }

    /// The value as a big integer.
    pub fn to_bigint(&self) -> BigInt {
        let sign = if self.is_negative() {
            Sign::Minus
        } else {
            Sign::Plus
        };
        BigInt::from_biguint(sign, limbs_to_biguint(&self.magnitude()))
    }

    /// The big integer `n`, or `None` if `|n| ≥ 2⁵¹¹`.
    pub fn from_bigint(n: &BigInt) -> Option<Wide512> {
        if n.bits() > Self::BITS {
            return None;
        }
        let mut limbs = [0u64; LIMBS];
        for (l, d) in limbs.iter_mut().zip(n.magnitude().iter_u64_digits()) {
            *l = d;
        }
        Some(Wide512::signed(n.sign() == Sign::Minus, limbs))
    }

    /// The number of bits of `|self|` (0 for zero).
    pub fn bits(&self) -> u64 {
        let m = self.magnitude();
        let used = significant(&m);
        used.checked_sub(1).map_or(0, |top| {
            64 * used as u64 - u64::from(m[top].leading_zeros())
        })
    }
}

/// The number of limbs up to the most significant non-zero one.
fn significant(m: &[u64; LIMBS]) -> usize {
    m.iter().rposition(|&d| d != 0).map_or(0, |top| top + 1)
}

/// The unsigned big integer of little-endian 64-bit limbs.
fn limbs_to_biguint(limbs: &[u64]) -> BigUint {
    BigUint::from_slice(
        &limbs
            .iter()
            .flat_map(|&d| [d as u32, (d >> 32) as u32])
            .collect::<Vec<u32>>(),
    )
}

impl From<i128> for Wide512 {
    fn from(n: i128) -> Wide512 {
        // Sign extension of the two low limbs.
        let fill = if n < 0 { u64::MAX } else { 0 };
        let mut limbs = [fill; LIMBS];
        limbs[0] = n as u64;
        limbs[1] = (n >> 64) as u64;
        Wide512(limbs)
    }
}

impl<'a> Add<&'a Wide512> for Wide512 {
    type Output = Wide512;
    /// One carry chain (wrapping at 2⁵¹²).
    fn add(self, rhs: &'a Wide512) -> Wide512 {
        let mut out = [0u64; LIMBS];
        let mut carry = false;
        for ((o, &x), &y) in out.iter_mut().zip(&self.0).zip(&rhs.0) {
            let (s, c1) = x.overflowing_add(y);
            let (s, c2) = s.overflowing_add(u64::from(carry));
            *o = s;
            carry = c1 || c2;
        }
        Wide512(out)
    }
}

impl<'a> Sub<&'a Wide512> for Wide512 {
    type Output = Wide512;
    fn sub(self, rhs: &'a Wide512) -> Wide512 {
        self + (-*rhs)
    }
}

impl<'a> Mul<&'a Wide512> for Wide512 {
    type Output = Wide512;
    /// The product of the magnitudes' significant limbs, truncated to
    /// 512 bits, with the sign of the product.
    fn mul(self, rhs: &'a Wide512) -> Wide512 {
        let (a, b) = (self.magnitude(), rhs.magnitude());
        let (la, lb) = (significant(&a), significant(&b));
        let mut out = [0u64; LIMBS];
        for (i, &x) in a[..la].iter().enumerate() {
            let mut carry = 0u128;
            for (j, &y) in b[..lb.min(LIMBS - i)].iter().enumerate() {
                // (2⁶⁴ − 1)² + 2·(2⁶⁴ − 1) = 2¹²⁸ − 1: no overflow.
                let t = u128::from(x) * u128::from(y) + u128::from(out[i + j]) + carry;
                out[i + j] = t as u64;
                carry = t >> 64;
            }
            if let Some(o) = out.get_mut(i + lb) {
                *o = carry as u64;
            }
        }
        Wide512::signed(self.is_negative() != rhs.is_negative(), out)
    }
}

/// The by-value forms, through the by-reference ones.
macro_rules! by_value {
    ($Trait:ident, $method:ident) => {
        impl $Trait for Wide512 {
            type Output = Wide512;
            fn $method(self, rhs: Wide512) -> Wide512 {
                self.$method(&rhs)
            }
        }
    };
}

by_value!(Add, add);
by_value!(Sub, sub);
by_value!(Mul, mul);

impl Neg for Wide512 {
    type Output = Wide512;
    /// Two's complement: `!x + 1`.
    fn neg(self) -> Wide512 {
        let mut out = self.0.map(|d| !d);
        for d in &mut out {
            let (s, carry) = d.overflowing_add(1);
            *d = s;
            if !carry {
                break;
            }
        }
        Wide512(out)
    }
}

impl crate::algebra::scalar::MulAcc for Wide512 {}

impl Zero for Wide512 {
    fn zero() -> Wide512 {
        Wide512([0; LIMBS])
    }
    fn is_zero(&self) -> bool {
        self.0 == [0; LIMBS]
    }
}

impl One for Wide512 {
    fn one() -> Wide512 {
        Wide512::from(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A big integer of up to `limbs` random 64-bit digits, signed.
    fn big(digits: &[u64], negative: bool) -> BigInt {
        let n = BigInt::from(limbs_to_biguint(digits));
        if negative {
            -n
        } else {
            n
        }
    }

    proptest! {
        /// `Wide512` arithmetic agrees with big integers on operands whose
        /// results stay below 2⁵¹¹, and the conversions round-trip.
        #[test]
        fn agrees_with_bigint(
            a in prop::collection::vec(any::<u64>(), 0..4), an in any::<bool>(),
            b in prop::collection::vec(any::<u64>(), 0..4), bn in any::<bool>(),
            c in prop::collection::vec(any::<u64>(), 0..8), cn in any::<bool>(),
        ) {
            let (ba, bb) = (big(&a, an), big(&b, bn));
            // c below 2⁵⁰⁹, so that c ± a·b stays below 2⁵¹¹.
            let bc = big(&c, cn) >> 3;
            let w = |n: &BigInt| Wide512::from_bigint(n).expect("fits");
            let (wa, wb, wc) = (w(&ba), w(&bb), w(&bc));
            prop_assert_eq!((wa * wb).to_bigint(), &ba * &bb);
            prop_assert_eq!((wc + wa * wb).to_bigint(), &bc + &ba * &bb);
            prop_assert_eq!((wc - wa * wb).to_bigint(), &bc - &ba * &bb);
            prop_assert_eq!((-wc).to_bigint(), -&bc);
            prop_assert_eq!(wc.bits(), bc.bits());
        }
    }

    #[test]
    fn range_ends() {
        let top = (BigInt::from(1) << 511) - 1;
        let w = Wide512::from_bigint(&top).expect("2⁵¹¹ − 1 fits");
        assert_eq!(w.to_bigint(), top);
        assert_eq!((-w).to_bigint(), -&top);
        assert_eq!(Wide512::from_bigint(&(top + 1)), None);
        assert_eq!(
            Wide512::from(i128::MIN).to_bigint(),
            BigInt::from(i128::MIN)
        );
        assert_eq!(Wide512::zero().bits(), 0);
    }
}
