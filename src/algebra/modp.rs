//! [`Fp`]: the prime field `Z/pZ`, `p = 2⁶¹ − 1`, as an exact [`Field`].
//!
//! Used as a cheap exact filter: a property proved for the image of a
//! rational patch modulo `p` (e.g. "the homogeneous components are coprime")
//! transfers to the rationals under conditions stated where it is used.
//! Every operation is exact (no rounding): this is not a floating-point path.
//!
//! Reference: Mersenne prime reduction, Knuth, TAOCP vol. 2, §4.3.2.

use crate::algebra::scalar::{Field, Scalar};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The modulus `p = 2⁶¹ − 1` (a Mersenne prime).
pub const MODULUS: u64 = (1 << 61) - 1;

/// An element of `Z/pZ`, `p = 2⁶¹ − 1`, stored as its representative in `[0, p)`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{algebra::Fp, ratio};
/// let third = Fp::from_rational_checked(&ratio(1, 3)).unwrap();
/// assert_eq!(third * Fp::new(3), Fp::new(1));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Fp(u64);

impl Fp {
    /// `x mod p`.
    pub fn new(x: u64) -> Fp {
        Fp(x % MODULUS)
    }

    /// `x mod p`, by folding: `2⁶¹ ≡ 1 (mod p)`, so the bits above 61 are
    /// added onto the low ones (no division).
    pub fn from_i128(x: i128) -> Fp {
        let fold = |v: u128| (v & u128::from(MODULUS)) + (v >> 61);
        let a = x.unsigned_abs();
        let r = if a < u128::from(MODULUS) {
            // Already reduced (the common case: small numbers).
            a as u64
        } else {
            // |x| < 2¹²⁷ → below 2⁶⁷ → below 2⁶² after two folds.
            let mut r = fold(fold(a)) as u64;
            while r >= MODULUS {
                r -= MODULUS;
            }
            r
        };
        if x < 0 {
            -Fp(r)
        } else {
            Fp(r)
        }
    }

    /// The representative in `[0, p)`.
    pub fn value(self) -> u64 {
        self.0
    }

    /// The image of a rational `a/b` (`a·b⁻¹ mod p`), or `None` when `p`
    /// divides the denominator.
    pub fn from_rational_checked(q: &BigRational) -> Option<Fp> {
        let num = reduce(q.numer());
        if q.denom().is_one() {
            return Some(num);
        }
        let den = reduce(q.denom());
        if den.is_zero() {
            return None;
        }
        Some(num / den)
    }

    /// The images of rationals, as [`from_rational_checked`](Fp::from_rational_checked)
    /// gives them one by one (`None` when `p` divides a denominator), with
    /// one inversion for all (Montgomery's trick: the prefix products
    /// `D_k = d_0⋯d_k` of the denominators, `D_last⁻¹`, then
    /// `d_k⁻¹ = D_k⁻¹ D_{k−1}` and `D_{k−1}⁻¹ = D_k⁻¹ d_k` from the back).
    pub fn from_rationals_checked(qs: &[&BigRational]) -> Option<Vec<Fp>> {
        let mut out: Vec<Fp> = qs.iter().map(|q| reduce(q.numer())).collect();
        let dens: Vec<Fp> = qs
            .iter()
            .map(|q| match q.denom().is_one() {
                true => Fp::new(1),
                false => reduce(q.denom()),
            })
            .collect();
        let mut prefix = Vec::with_capacity(qs.len());
        let mut product = Fp::new(1);
        for &d in &dens {
            product = product * d;
            prefix.push(product);
        }
        let mut inverse = product.inverse()?;
        for k in (0..qs.len()).rev() {
            let before = if k == 0 { Fp::new(1) } else { prefix[k - 1] };
            out[k] = out[k] * inverse * before;
            inverse = inverse * dens[k];
        }
        Some(out)
    }

    /// `self⁻¹` by the extended Euclidean algorithm (`None` for 0), on
    /// 64-bit words: the remainders stay below `p < 2⁶¹` and the cofactors
    /// `|t| ≤ p` (Knuth, TAOCP vol. 2, §4.5.2), so nothing overflows `i64`.
    fn inverse(self) -> Option<Fp> {
        let (mut r0, mut r1) = (MODULUS as i64, self.0 as i64);
        let (mut t0, mut t1) = (0i64, 1i64);
        while r1 != 0 {
            let q = r0 / r1;
            (r0, r1) = (r1, r0 - q * r1);
            (t0, t1) = (t1, t0 - q * t1);
        }
        (r0 == 1).then(|| Fp(t0.rem_euclid(MODULUS as i64) as u64))
    }
}

/// `n mod p` by Horner's rule on its 64-bit limbs, most significant
/// first: `2⁶⁴ ≡ 2³ (mod 2⁶¹ − 1)`, so each step is `r ← 8r + limb`.
fn reduce(n: &BigInt) -> Fp {
    if let Some(small) = n.to_i128() {
        return Fp::from_i128(small);
    }
    let eight = Fp::new(8);
    let r = n
        .magnitude()
        .iter_u64_digits()
        .rev()
        .fold(Fp::new(0), |r, limb| {
            r * eight + Fp::from_i128(i128::from(limb))
        });
    if n.sign() == num_bigint::Sign::Minus {
        -r
    } else {
        r
    }
}

impl Add for Fp {
    type Output = Fp;
    fn add(self, o: Fp) -> Fp {
        let s = self.0 + o.0;
        Fp(if s >= MODULUS { s - MODULUS } else { s })
    }
}
impl Sub for Fp {
    type Output = Fp;
    fn sub(self, o: Fp) -> Fp {
        Fp(if self.0 >= o.0 {
            self.0 - o.0
        } else {
            self.0 + MODULUS - o.0
        })
    }
}
impl Mul for Fp {
    type Output = Fp;
    fn mul(self, o: Fp) -> Fp {
        let x = self.0 as u128 * o.0 as u128;
        // 2⁶¹ ≡ 1 (mod p): fold the high bits onto the low ones.
        let mut s = (x & MODULUS as u128) as u64 + (x >> 61) as u64;
        while s >= MODULUS {
            s -= MODULUS;
        }
        Fp(s)
    }
}
impl Neg for Fp {
    type Output = Fp;
    fn neg(self) -> Fp {
        Fp::zero() - self
    }
}
impl Div for Fp {
    type Output = Fp;
    /// **Panics if `o` is zero.**
    fn div(self, o: Fp) -> Fp {
        let inv = o.inverse().expect("division by zero in Z/pZ");
        Fp::mul(self, inv)
    }
}
impl Add<&Fp> for Fp {
    type Output = Fp;
    fn add(self, o: &Fp) -> Fp {
        self + *o
    }
}
impl Sub<&Fp> for Fp {
    type Output = Fp;
    fn sub(self, o: &Fp) -> Fp {
        self - *o
    }
}
impl Mul<&Fp> for Fp {
    type Output = Fp;
    fn mul(self, o: &Fp) -> Fp {
        self * *o
    }
}
impl Div<&Fp> for Fp {
    type Output = Fp;
    fn div(self, o: &Fp) -> Fp {
        self / *o
    }
}
impl Zero for Fp {
    fn zero() -> Fp {
        Fp(0)
    }
    fn is_zero(&self) -> bool {
        self.0 == 0
    }
}
impl One for Fp {
    fn one() -> Fp {
        Fp(1)
    }
}

impl crate::algebra::scalar::MulAcc for Fp {}

impl Scalar for Fp {
    fn from_i64(n: i64) -> Self {
        Fp(n.rem_euclid(MODULUS as i64) as u64)
    }
    fn from_bigint(n: &BigInt) -> Self {
        reduce(n)
    }
    /// **Panics if `p` divides the denominator** (use
    /// [`Fp::from_rational_checked`] on data).
    fn from_rational(q: &BigRational) -> Self {
        Fp::from_rational_checked(q).expect("denominator invertible modulo p")
    }
}
impl Field for Fp {}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;

    #[test]
    fn field_laws_on_samples() {
        let a = Fp::from_rational(&ratio(-7, 5));
        let b = Fp::new(MODULUS - 3);
        assert_eq!((a + b) - b, a);
        assert_eq!((a / b) * b, a);
        assert_eq!(a * Fp::from_i64(5), Fp::from_i64(-7));
        assert_eq!(-Fp::new(0), Fp::new(0));
        let big = BigRational::from_integer(BigInt::from(MODULUS) * 4);
        assert_eq!(Fp::from_rational_checked(&big.recip()), None);
    }

    #[test]
    fn inverses_and_folded_residues_agree_with_division() {
        let p = i128::from(MODULUS);
        let mut x: i128 = 0x1234_5678_9abc_def0_1122_3344;
        for k in 0..2000i128 {
            // A walk over all magnitudes, both signs, and the edges.
            x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(k) >> (k % 120);
            for v in [x, -x, p * k, p * k - 1, i128::MAX - k, i128::MIN + 1 + k] {
                assert_eq!(Fp::from_i128(v).value() as i128, v.rem_euclid(p), "{v}");
            }
            let a = Fp::from_i128(x);
            match a.inverse() {
                None => assert!(a.is_zero()),
                Some(inv) => assert_eq!(a * inv, Fp::new(1), "{x}"),
            }
        }
        assert_eq!(Fp::new(MODULUS - 1).inverse(), Some(Fp::new(MODULUS - 1)));
    }

    #[test]
    fn one_inversion_gives_the_images_one_by_one() {
        let p = i64::try_from(MODULUS).unwrap();
        let qs: Vec<BigRational> = vec![
            ratio(-7, 5),
            ratio(3, 1),
            ratio(1, 9),
            ratio(0, 1),
            ratio(p + 2, p - 1),
        ];
        let refs: Vec<&BigRational> = qs.iter().collect();
        let one_by_one: Option<Vec<Fp>> = qs.iter().map(Fp::from_rational_checked).collect();
        assert_eq!(Fp::from_rationals_checked(&refs), one_by_one);
        assert_eq!(Fp::from_rationals_checked(&[]), Some(vec![]));
        let divisible = ratio(1, 2 * p);
        assert_eq!(
            Fp::from_rationals_checked(&[&qs[0], &divisible, &qs[1]]),
            None
        );
    }

    proptest::proptest! {
        /// The residue of a big integer by Horner's rule on limbs is its
        /// floor remainder by num-integer, for extreme limbs, multiples of
        /// p and both signs.
        #[test]
        fn limb_residues_are_remainders(
            limbs in proptest::collection::vec(
                proptest::prop_oneof![proptest::num::u64::ANY, proptest::strategy::Just(u64::MAX), proptest::strategy::Just(MODULUS)],
                0..9,
            ),
            times_p in proptest::bool::ANY,
            negative in proptest::bool::ANY,
        ) {
            use num_integer::Integer;
            let mut n = BigInt::from(num_bigint::BigUint::new(
                limbs.iter().flat_map(|l| [*l as u32, (l >> 32) as u32]).collect(),
            ));
            if times_p {
                n *= MODULUS;
            }
            if negative {
                n = -n;
            }
            let want = n.mod_floor(&BigInt::from(MODULUS));
            proptest::prop_assert_eq!(BigInt::from(reduce(&n).value()), want);
        }
    }
}
