//! [`Int`]: an exact integer that computes in `i128` while it fits and
//! moves to a big integer on overflow (checked arithmetic, never wrapping).
//!
//! It is a [`Ring`](crate::Ring) but not a [`Scalar`](crate::Scalar) (it has
//! no 1/2): exact evaluation ([`crate::eval`]) clears denominators once and
//! then runs the Horner–Bernstein kernel at a homogeneous parameter on
//! `Int`, so that typical inputs never allocate and never take a gcd until
//! the final division.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use std::ops::{Add, Mul, Neg, Sub};

/// An exact integer: `Small` while it fits `i128`, `Big` otherwise.
///
/// ```
/// use exact_bezier::algebra::Int;
/// let big = Int::from(i128::MAX) + &Int::from(1);
/// assert_eq!(big.to_bigint(), exact_bezier::BigInt::from(i128::MAX) + 1);
/// assert_eq!(big - &Int::from(1), Int::from(i128::MAX)); // back to i128
/// ```
#[derive(Debug)]
pub enum Int {
    /// A machine integer.
    Small(i128),
    /// A big integer outside the `i128` range.
    Big(BigInt),
}

impl Int {
    /// The value as a big integer.
    pub fn to_bigint(&self) -> BigInt {
        match self {
            Int::Small(a) => BigInt::from(*a),
            Int::Big(a) => a.clone(),
        }
    }

    /// `Small` when `n` fits `i128`, else `Big` (the representation is
    /// canonical: equal values have equal variants).
    pub fn from_bigint(n: BigInt) -> Int {
        // `bits()` is O(1); only a number of at most 128 bits can fit.
        if n.bits() > 128 {
            return Int::Big(n);
        }
        n.to_i128().map_or(Int::Big(n), Int::Small)
    }
}

/// # Number theory
impl Int {
    /// The big integer `n` as an `Int`, copying it only when it is big.
    pub fn from_ref(n: &BigInt) -> Int {
        if n.bits() <= 127
            && let Some(small) = n.to_i128()
        {
            return Int::Small(small);
        }
        Int::Big(n.clone())
    }

    /// The number of bits of `|self|` (0 for zero).
    pub fn bits(&self) -> u64 {
        match self {
            Int::Small(a) => u64::from(128 - a.unsigned_abs().leading_zeros()),
            Int::Big(a) => a.bits(),
        }
    }

    /// `gcd(|self|, |other|) ≥ 0`: Euclid on machine words while both are
    /// small, Lehmer's algorithm ([`crate::algebra::gcd`]) otherwise.
    pub fn gcd(&self, other: &Int) -> Int {
        if let (Int::Small(x), Int::Small(y)) = (self, other) {
            // Binary gcd: no 128-bit division (the bulk of a normalization).
            let g = crate::algebra::gcd::gcd_u128(x.unsigned_abs(), y.unsigned_abs());
            if let Ok(g) = i128::try_from(g) {
                return Int::Small(g);
            }
        }
        let (a, b) = (self.to_bigint(), other.to_bigint());
        Int::from_bigint(BigInt::from(crate::algebra::gcd::gcd(
            a.magnitude(),
            b.magnitude(),
        )))
    }

    /// `self / d` for a divisor `d ≠ 0` of `self`.
    pub fn div_exact(&self, d: &Int) -> Int {
        if let (Int::Small(x), Int::Small(y)) = (self, d)
            && let Some(q) = x.checked_div(*y)
        {
            return Int::Small(q);
        }
        Int::from_bigint(self.to_bigint() / d.to_bigint())
    }
}

impl Clone for Int {
    fn clone(&self) -> Int {
        match self {
            Int::Small(a) => Int::Small(*a),
            Int::Big(a) => Int::Big(a.clone()),
        }
    }

    /// Reuses the digits of a big `self` for a big `source`, so that
    /// refilling a buffer of big numbers (the kernel's lanes) allocates
    /// nothing once it has grown.
    fn clone_from(&mut self, source: &Int) {
        match (self, source) {
            (Int::Big(a), Int::Big(b)) => a.clone_from(b),
            (this, _) => *this = source.clone(),
        }
    }
}

impl From<BigInt> for Int {
    /// [`Int::from_bigint`].
    fn from(n: BigInt) -> Int {
        Int::from_bigint(n)
    }
}

impl From<i128> for Int {
    fn from(n: i128) -> Int {
        Int::Small(n)
    }
}

impl PartialEq for Int {
    fn eq(&self, other: &Int) -> bool {
        match (self, other) {
            (Int::Small(a), Int::Small(b)) => a == b,
            (Int::Big(a), Int::Big(b)) => a == b,
            // The representation is canonical: a small value is never big.
            _ => false,
        }
    }
}

/// `+` and `−` with an `i128` fast path and a big-integer fallback.
///
/// A big operand is updated in place where `num-bigint` allows it (a big
/// number plus a machine word or a big number; `×` below): the Horner
/// loops of exact evaluation and the coefficient arithmetic of `Poly` then
/// allocate only for a product of two big numbers or a small times a
/// borrowed big one.
macro_rules! int_binary_op {
    ($Trait:ident, $method:ident, $checked:ident, $small_big:expr) => {
        impl<'a> $Trait<&'a Int> for Int {
            type Output = Int;
            fn $method(self, rhs: &'a Int) -> Int {
                // The machine-word case inline; the rest out of line, so
                // that loops over small coefficients stay small.
                #[inline(never)]
                fn wide(x: Int, y: &Int) -> Int {
                    match (x, y) {
                        (Int::Small(a), Int::Small(b)) => Int::Big(BigInt::from(a).$method(*b)),
                        (Int::Big(a), Int::Small(b)) => Int::from_bigint(a.$method(*b)),
                        (Int::Small(a), Int::Big(b)) => Int::from_bigint($small_big(a, b)),
                        (Int::Big(a), Int::Big(b)) => Int::from_bigint(a.$method(b)),
                    }
                }
                if let (Int::Small(a), Int::Small(b)) = (&self, rhs) {
                    if let Some(r) = a.$checked(*b) {
                        return Int::Small(r);
                    }
                }
                wide(self, rhs)
            }
        }
        impl $Trait for Int {
            type Output = Int;
            fn $method(self, rhs: Int) -> Int {
                self.$method(&rhs)
            }
        }
    };
}

int_binary_op!(Add, add, checked_add, |a: i128, b: &BigInt| b + a);
int_binary_op!(Sub, sub, checked_sub, |a: i128, b: &BigInt| -(b - a));

impl<'a> Mul<&'a Int> for Int {
    type Output = Int;
    /// A big factor has `|x| ≥ 2¹²⁷`: its product with another big one, or
    /// with a small one of `|s| ≥ 2`, is big again without a range test.
    fn mul(self, rhs: &'a Int) -> Int {
        // The machine-word case inline; the rest out of line, so that
        // loops over small coefficients stay small.
        #[inline(never)]
        fn wide(x: Int, y: &Int) -> Int {
            match (x, y) {
                (Int::Small(a), Int::Small(b)) => Int::Big(BigInt::from(a) * *b),
                (Int::Big(a), Int::Small(b)) => big_times(a * *b, *b),
                (Int::Small(a), Int::Big(b)) => big_times(b * a, a),
                (Int::Big(a), Int::Big(b)) => Int::Big(a * b),
            }
        }
        if let (Int::Small(a), Int::Small(b)) = (&self, rhs)
            && let Some(r) = a.checked_mul(*b)
        {
            return Int::Small(r);
        }
        wide(self, rhs)
    }
}

impl Mul for Int {
    type Output = Int;
    fn mul(self, rhs: Int) -> Int {
        self * &rhs
    }
}

/// `big·s` for a big `|big| ≥ 2¹²⁷`: big again without a range test when
/// `|s| ≥ 2`.
fn big_times(product: BigInt, s: i128) -> Int {
    if s.unsigned_abs() >= 2 {
        Int::Big(product)
    } else {
        Int::from_bigint(product)
    }
}

/// `a·b` of borrowed operands: two big operands multiply without a copy.
fn product(a: &Int, b: &Int) -> Int {
    match (a, b) {
        (Int::Big(x), Int::Big(y)) => Int::Big(x * y),
        (Int::Big(_), Int::Small(_)) => a.clone() * b,
        (Int::Small(_), _) => b.clone() * a,
    }
}

impl crate::algebra::scalar::MulAcc for Int {
    /// `acc·a` in place (a machine-word `a` scales the big number's
    /// digits), then `+ c·x`, with `c·x` formed from borrowed operands,
    /// added in place.
    fn mul_acc(acc: &mut Int, a: &Int, c: &Int, x: &Int) {
        let prev = std::mem::replace(acc, Int::Small(0));
        *acc = prev * a + &product(c, x);
    }
}

impl Neg for Int {
    type Output = Int;
    fn neg(self) -> Int {
        match self {
            Int::Small(a) => a
                .checked_neg()
                .map_or_else(|| Int::Big(-BigInt::from(a)), Int::Small),
            Int::Big(a) => Int::from_bigint(-a),
        }
    }
}

impl Zero for Int {
    fn zero() -> Int {
        Int::Small(0)
    }
    fn is_zero(&self) -> bool {
        matches!(self, Int::Small(0))
    }
}

impl One for Int {
    fn one() -> Int {
        Int::Small(1)
    }
}

/// Integer numerators over one common denominator: `(nums, den)` with
/// `den > 0` the lcm of the denominators of `values` and
/// `nums[i] = den·values[i]`, as big integers or as [`Int`]s.
///
/// ```text
/// den = lcm_i d_i,   nums[i] = n_i · (den / d_i)     (values[i] = n_i / d_i)
/// ```
pub(crate) fn common_denominator<'a, N: From<BigInt>>(
    values: impl IntoIterator<Item = &'a BigRational> + Clone,
) -> (Vec<N>, BigInt) {
    let den = values.clone().into_iter().fold(BigInt::one(), |l, q| {
        crate::algebra::gcd::lcm(&l, q.denom())
    });
    let nums = values
        .into_iter()
        .map(|q| N::from(q.numer() * (&den / q.denom())))
        .collect();
    (nums, den)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overflow_moves_to_big_and_back() {
        let m = Int::from(i128::MAX);
        let sq = m.clone() * &m;
        assert!(matches!(sq, Int::Big(_)));
        assert_eq!(
            sq.to_bigint(),
            BigInt::from(i128::MAX) * BigInt::from(i128::MAX)
        );
        assert_eq!(-Int::from(i128::MIN) - &Int::from(1), Int::from(i128::MAX));
        assert!((Int::from(3) - &Int::from(3)).is_zero());
    }
}
