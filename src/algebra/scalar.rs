//! The scalar tower: [`Scalar`] (a commutative ring containing Q), [`Field`]
//! (adds division) and [`Ordered`] (adds a sign).
//!
//! Three instantiations are provided:
//!
//! | type | level | use |
//! | --- | --- | --- |
//! | `f64` | [`Ordered`] | speed; comparisons through an explicit [`Tolerance`] |
//! | [`BigRational`] | [`Ordered`] | exact numbers: equality is equality |
//! | [`Poly`](crate::Poly) | [`Scalar`] only | proofs: an identity that comes out `== 0` holds for all symbol values |
//!
//! Every algorithm in this crate is written in homogeneous (weighted) form, so
//! that ring operations suffice; division happens only where a Cartesian answer
//! is asked for, and is then bounded by [`Field`].
//!
//! Reference: the split follows CGAL's RingNumberType /
//! FieldNumberType and num-traits' `NumOps` / `NumRef`.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An absolute tolerance for `f64` comparisons, visible at every call site.
///
/// Exact scalars ([`BigRational`], [`Poly`](crate::Poly)) ignore it and decide
/// exactly; `f64` treats `|x| <= tol` as zero. [`Tolerance::EXACT`] (0) asks
/// `f64` for bitwise-exact zero tests too.
///
/// # Examples
///
/// ```
/// use exact_bezier::{Scalar, Tolerance};
/// assert!((1e-12_f64).is_zero_within(Tolerance(1e-9)));
/// assert!(!(1e-12_f64).is_zero_within(Tolerance::EXACT));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Tolerance(pub f64);

impl Tolerance {
    /// Zero tolerance: exact decisions for every scalar.
    pub const EXACT: Tolerance = Tolerance(0.0);
}

impl Default for Tolerance {
    /// `1e-9`, a tolerance suited to `f64` geometry of unit size.
    fn default() -> Self {
        Tolerance(1e-9)
    }
}

/// A commutative ring with exact `==`: `+ − ×`, negation, zero and one,
/// by value and by reference. Every [`Scalar`] is a `Ring`; so is the
/// machine-or-big integer [`Int`](crate::algebra::Int) of the fraction-free fast
/// paths, which contains no 1/2 and so is no `Scalar`. Algorithms that need
/// only these operations (homogeneous de Casteljau with a homogeneous
/// parameter) are bounded by `Ring`.
///
/// The trait is implemented for every type with these operations (and
/// `'static`, so that the evaluation kernel can recognise the types it has
/// a faster exact path for): a type outside this crate is a `Ring` by
/// implementing the `std::ops` traits and num-traits' [`Zero`] and
/// [`One`].
pub trait Ring:
    'static
    + Clone
    + PartialEq
    + Debug
    + Send
    + Sync
    + Zero
    + One
    + Neg<Output = Self>
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
{
}

impl<T> Ring for T where
    T: 'static
        + Clone
        + PartialEq
        + Debug
        + Send
        + Sync
        + Zero
        + One
        + Neg<Output = T>
        + Add<Output = T>
        + Sub<Output = T>
        + Mul<Output = T>
        + for<'a> Add<&'a T, Output = T>
        + for<'a> Sub<&'a T, Output = T>
        + for<'a> Mul<&'a T, Output = T>
{
}

/// `x^e` by repeated squaring (`x^0 = 1`), in any ring.
pub(crate) fn pow<T: Ring>(x: &T, e: u32) -> T {
    let mut result = T::one();
    let mut base = x.clone();
    let mut e = e;
    while e > 0 {
        if e & 1 == 1 {
            result = result * &base;
        }
        e >>= 1;
        if e > 0 {
            base = base.clone() * &base;
        }
    }
    result
}

/// The multiply-accumulate step of the Horner–Bernstein kernel
/// ([`crate::eval`]) and of de Casteljau ([`HPoint::combine`](crate::hpoint::HPoint::combine)):
/// `acc ← acc·a + c·x`. The default is those ring operations; a type may
/// override it with a faster route to the same value (`f64` fuses the two
/// products, the big-integer [`Int`](crate::algebra::Int) multiplies `c·x`
/// without copying an operand, [`Poly`](crate::Poly) merges both products
/// by binomials into one output). Every [`Scalar`] is a `MulAcc`; a scalar type of your own takes
/// the default with an empty `impl MulAcc for MyScalar {}`.
pub trait MulAcc: Ring {
    /// `*acc = acc·a + c·x`.
    fn mul_acc(acc: &mut Self, a: &Self, c: &Self, x: &Self) {
        let prev = std::mem::replace(acc, Self::zero());
        *acc = prev * a + &(c.clone() * x);
    }
}

impl MulAcc for f64 {
    fn mul_acc(acc: &mut f64, a: &f64, c: &f64, x: &f64) {
        *acc = *acc * a + c * x;
    }
}
impl MulAcc for i128 {}
/// `acc·a + c·x` with Lehmer's gcd ([`crate::algebra::gcd::product`] and
/// [`sum`](crate::algebra::gcd::sum)): `Ratio`'s operators reduce by the
/// binary gcd of `num-integer`, which shifts whole big integers per step.
impl MulAcc for BigRational {
    fn mul_acc(acc: &mut Self, a: &Self, c: &Self, x: &Self) {
        use crate::algebra::gcd::{product, sum};
        *acc = sum(&product(acc, a), &product(c, x));
    }
}

/// A commutative ring that contains Q (a Q-algebra): `+ − ×`, negation, zero,
/// one, integer and rational constants, and an exact zero test.
///
/// This is all that homogeneous Bézier algorithms need (de Casteljau on
/// `(w·P, w)`, blossoms, elevation, subdivision, Möbius substitution,
/// rectangle↔triangle conversion).
///
/// ```text
/// Laws (exact for BigRational and Poly, up to rounding for f64):
///   a + b = b + a,  a·b = b·a,  (a + b)·c = a·c + b·c,
///   0 + a = a,      1·a = a,    a + (−a) = 0,
///   from_rational(p/q)·from_i64(q) = from_i64(p)
/// ```
pub trait Scalar: Ring + MulAcc {
    /// The integer `n` as a scalar.
    fn from_i64(n: i64) -> Self;

    /// The rational constant `q` as a scalar (rounded to nearest for `f64`).
    fn from_rational(q: &BigRational) -> Self;

    /// The big integer `n` as a scalar (rounded for `f64`).
    fn from_bigint(n: &BigInt) -> Self {
        Self::from_rational(&BigRational::from_integer(n.clone()))
    }

    /// Is `self` zero? Exact scalars answer exactly and ignore `tol`; `f64`
    /// answers `|self| <= tol.0`.
    fn is_zero_within(&self, tol: Tolerance) -> bool {
        let _ = tol;
        self.is_zero()
    }

    /// `self · other`. The same as `*`; an exact type may take a shortcut
    /// (`BigRational`: two integers multiply without the gcds of its `*`).
    fn mul_scalar(&self, other: &Self) -> Self {
        self.clone() * other
    }

    /// `self^e` by repeated squaring (the ring power `pow` of this module).
    fn pow_u32(&self, e: u32) -> Self {
        pow(self, e)
    }

    /// The sum of `parts` (`0` for none). The default adds them left to
    /// right, `((0 + p₀) + p₁) + …` (so `f64` rounds as a loop would); an
    /// exact type may take a faster route to the same value (`Poly` merges
    /// all the parts at once).
    fn sum_of(parts: Vec<Self>) -> Self {
        parts.into_iter().fold(Self::zero(), |acc, x| acc + x)
    }

    /// Whether [`Scalar::sum_of`] adds many parts more cheaply than as many
    /// steps of two (`Poly`: one merge and one normalization for all of
    /// them). Algorithms that can take either route — degree elevation by
    /// `r` as one sum per point or as `r` single steps — take the sum only
    /// then: for `f64` and `BigRational` the single steps are 1.3–4 times
    /// faster (criterion `curve` group `elevate`, 2026-11-29).
    const SUMS_AT_ONCE: bool = false;
}

/// A [`Scalar`] with division: exact rationals and `f64`.
///
/// Needed to project homogeneous points to Cartesian ones and to solve for
/// parameters. Callers test the divisor with [`Scalar::is_zero_within`] first;
/// dividing by zero is a precondition violation (`BigRational` panics, `f64`
/// gives ±∞ or NaN).
pub trait Field: Scalar + Div<Output = Self> + for<'a> Div<&'a Self, Output = Self> {
    /// `1 / self`. **Panics for `BigRational` if `self` is zero.**
    fn recip(&self) -> Self {
        Self::one() / self
    }

    /// `x / den` for each `x` of `nums` (a homogeneous point's coordinates
    /// over its weight). The default multiplies by `1/den`; `BigRational`
    /// puts the numbers on one denominator and reduces them by one shared
    /// gcd ([`fractions_over`](crate::algebra::gcd::fractions_over)).
    /// **Panics for `BigRational` if `den` is zero.**
    ///
    /// ```
    /// use exact_bezier::{ratio, BigRational, Field};
    /// let q = |n: i64, d: i64| ratio::<BigRational>(n, d);
    /// assert_eq!(BigRational::divide_each(&[q(3, 4), q(-5, 6), q(0, 1)], &q(-15, 2)), [q(-1, 10), q(1, 9), q(0, 1)]);
    /// ```
    fn divide_each(nums: &[Self], den: &Self) -> Vec<Self> {
        let inv = den.recip();
        nums.iter().map(|x| x.mul_scalar(&inv)).collect()
    }
}

/// A [`Field`] with a sign and an `f64` approximation: exact rationals and
/// `f64`. The symbolic polynomial type has no sign.
pub trait Ordered: Field + PartialOrd {
    /// The nearest `f64` (exact types) or the value itself (`f64`).
    fn to_f64(&self) -> f64;

    /// Rational bounds `lo ≤ self ≤ hi`, about 64 bits wide or narrower,
    /// for types whose exact comparisons are costly (real algebraic
    /// numbers); `None` (the default) where comparing the values is as
    /// cheap (`f64`, rationals). Callers use them to skip exact work whose
    /// outcome the bounds already decide, never in place of an answer.
    ///
    /// ```
    /// use exact_bezier::{algebra::RealAlgebraic, Ordered, Roots, Scalar};
    /// let r2 = RealAlgebraic::from_i64(2).nth_root(2).unwrap();
    /// let (lo, hi) = r2.rational_bounds().unwrap();
    /// // lo ≤ √2 ≤ hi, checked on the squares of the (positive) bounds.
    /// let two = exact_bezier::ratio(2, 1);
    /// assert!(lo.clone() * &lo <= two && two <= hi.clone() * &hi);
    /// assert!(hi - lo < exact_bezier::ratio(1, 1i64 << 60));
    /// assert_eq!(2.5f64.rational_bounds(), None);
    /// ```
    fn rational_bounds(&self) -> Option<(BigRational, BigRational)> {
        None
    }

    /// The sign of `self`: its order against zero (`Equal` for NaN).
    /// `BigRational` reads its numerator's sign (its `<` against zero
    /// runs a floor division of numerator by denominator).
    ///
    /// ```
    /// use exact_bezier::{ratio, BigRational, Ordered};
    /// use std::cmp::Ordering;
    /// assert_eq!(ratio::<BigRational>(-3, 7).sign_order(), Ordering::Less);
    /// assert_eq!(f64::NAN.sign_order(), Ordering::Equal);
    /// ```
    fn sign_order(&self) -> Ordering {
        self.partial_cmp(&Self::zero()).unwrap_or(Ordering::Equal)
    }

    /// `|self|`.
    fn abs_val(&self) -> Self {
        if self.sign_order().is_lt() {
            -self.clone()
        } else {
            self.clone()
        }
    }

    /// Is `self` strictly positive, beyond `tol` for `f64`?
    fn is_positive_within(&self, tol: Tolerance) -> bool {
        !self.is_zero_within(tol) && self.sign_order().is_gt()
    }
}

impl Scalar for f64 {
    fn from_i64(n: i64) -> Self {
        n as f64
    }
    fn from_rational(q: &BigRational) -> Self {
        rational_to_f64(q)
    }
    fn from_bigint(n: &BigInt) -> Self {
        n.to_f64().unwrap_or(f64::NAN)
    }
    fn is_zero_within(&self, tol: Tolerance) -> bool {
        self.abs() <= tol.0
    }
}
impl Field for f64 {}
impl Ordered for f64 {
    fn to_f64(&self) -> f64 {
        *self
    }
}

impl Scalar for BigRational {
    fn from_i64(n: i64) -> Self {
        BigRational::from_integer(BigInt::from(n))
    }
    fn from_rational(q: &BigRational) -> Self {
        q.clone()
    }
    fn from_bigint(n: &BigInt) -> Self {
        BigRational::from_integer(n.clone())
    }
    fn mul_scalar(&self, other: &Self) -> Self {
        // `Ratio`'s `*` reduces by gcd(numer, other denom) and the converse
        // with the binary gcd (work even when both denominators are 1);
        // Lehmer's gcd reduces the product once.
        if self.is_integer() && other.is_integer() {
            BigRational::from_integer(self.numer() * other.numer())
        } else {
            crate::algebra::gcd::product(self, other)
        }
    }
}
/// `recip` swaps numerator and denominator (no gcd: the default `1 / x`
/// runs `Ratio`'s binary gcd).
impl Field for BigRational {
    fn recip(&self) -> Self {
        num_rational::Ratio::recip(self)
    }

    /// With `L` the lcm of the numbers' denominators and `den = c/d`:
    /// `x_k / den = (x_k L d) / (L c)`, integers over one denominator.
    fn divide_each(nums: &[Self], den: &Self) -> Vec<Self> {
        use crate::algebra::gcd::{fractions_over, lcm};
        let common = nums.iter().fold(BigInt::one(), |l, x| lcm(&l, x.denom()));
        let numers = nums
            .iter()
            .map(|x| x.numer() * (&common / x.denom()) * den.denom())
            .collect();
        let mut out = vec![BigRational::zero(); nums.len()];
        fractions_over(numers, common * den.numer(), &mut out);
        out
    }
}
impl Ordered for BigRational {
    fn to_f64(&self) -> f64 {
        rational_to_f64(self)
    }
    fn abs_val(&self) -> Self {
        self.abs()
    }
    fn sign_order(&self) -> Ordering {
        self.numer().sign().cmp(&num_bigint::Sign::NoSign)
    }
}

/// Nearest `f64` to a rational, correct even when numerator and denominator
/// overflow `f64` on their own (scales by powers of two first).
pub fn rational_to_f64(q: &BigRational) -> f64 {
    if let (Some(n), Some(d)) = (q.numer().to_f64(), q.denom().to_f64())
        && n.is_finite()
        && d.is_finite()
        && d != 0.0
    {
        return n / d;
    }
    let nb = q.numer().bits() as i64;
    let db = q.denom().bits() as i64;
    let shift = nb - db - 60;
    let (n, d) = if shift > 0 {
        (q.numer().clone(), q.denom().clone() << shift as usize)
    } else {
        (q.numer().clone() << (-shift) as usize, q.denom().clone())
    };
    let mantissa = (n / d).to_f64().unwrap_or(f64::NAN);
    mantissa * 2f64.powi(shift as i32)
}

/// The binomial coefficient C(n, k) as an exact big integer (0 when k > n).
///
/// # Examples
///
/// ```
/// use exact_bezier::algebra::binomial;
/// assert_eq!(binomial(6, 3), 20.into());
/// assert_eq!(binomial(3, 5), 0.into());
/// ```
pub fn binomial(n: usize, k: usize) -> BigInt {
    if k > n {
        return BigInt::zero();
    }
    let k = k.min(n - k);
    let mut acc = BigInt::one();
    for i in 0..k {
        acc = acc * BigInt::from(n - i) / BigInt::from(i + 1);
    }
    acc
}

/// The binomial coefficient C(n, k) as a scalar (0 when k > n).
///
/// Built from machine integers while C(n, k) fits in `i64` (every n ≤ 66),
/// else from the big integer [`binomial`]; the value is the same either way
/// (an integer below 2⁶⁴ converts to `f64` with one rounding).
///
/// # Examples
///
/// ```
/// use exact_bezier::{algebra::binomial_scalar, ratio};
/// use exact_bezier::BigRational;
/// assert_eq!(binomial_scalar::<BigRational>(6, 3), ratio(20, 1));
/// assert_eq!(binomial_scalar::<f64>(70, 35), 112186277816662845432.0);
/// ```
pub fn binomial_scalar<T: Scalar>(n: usize, k: usize) -> T {
    if k > n {
        return T::from_bigint(&BigInt::zero());
    }
    let mut acc: u128 = 1;
    for i in 0..k.min(n - k) {
        acc = acc * (n - i) as u128 / (i + 1) as u128;
        if acc > i64::MAX as u128 {
            return T::from_bigint(&binomial(n, k));
        }
    }
    T::from_i64(acc as i64)
}

/// The reciprocal `1/k` of an integer as a scalar (exact for exact `T`).
///
/// **Panics if `k` is zero.**
pub fn recip_int<T: Scalar>(k: &BigInt) -> T {
    T::from_rational(&BigRational::new(BigInt::one(), k.clone()))
}

/// The rational `p/q` (q ≠ 0) as a scalar. **Panics if `q` is zero.**
///
/// ```
/// use exact_bezier::ratio;
/// use exact_bezier::BigRational;
/// let third: BigRational = ratio(1, 3);
/// assert_eq!(third * BigRational::from_integer(3.into()), BigRational::from_integer(1.into()));
/// ```
pub fn ratio<T: Scalar>(p: i64, q: i64) -> T {
    T::from_rational(&BigRational::new(BigInt::from(p), BigInt::from(q)))
}

/// Real n-th roots, exact where they exist: `BigRational` answers `Some`
/// only when the root is rational (decided exactly by [`rational_root`]);
/// `f64` always answers, rounded.
///
/// ```text
/// nth_root(x, n) = r  with  rⁿ = x;  r ≥ 0 for even n (x ≥ 0 required),
///                  the real root (sign of x) for odd n;  None for n = 0
/// ```
///
/// ```
/// use exact_bezier::{ratio, Roots};
/// use exact_bezier::BigRational;
/// assert_eq!(ratio::<BigRational>(-8, 27).nth_root(3), Some(ratio(-2, 3)));
/// assert_eq!(ratio::<BigRational>(2, 1).nth_root(2), None);
/// assert_eq!(ratio::<BigRational>(-4, 1).nth_root(2), None);
/// assert!((2.0_f64.nth_root(2).unwrap() - 2f64.sqrt()).abs() < 1e-15);
/// ```
pub trait Roots: Ordered {
    /// The real n-th root of `self`, if it exists and is representable.
    fn nth_root(&self, n: u32) -> Option<Self>;

    /// [`Roots::nth_root`] when the root stays inside the limits of exact
    /// arithmetic (for real algebraic numbers: a number field of degree at
    /// most [`MAX_FIELD_DEGREE`](crate::limits::MAX_FIELD_DEGREE)), else
    /// `None`: for callers that have an exact answer without the root.
    fn bounded_root(&self, n: u32) -> Option<Self> {
        self.nth_root(n)
    }
}

impl Roots for BigRational {
    fn nth_root(&self, n: u32) -> Option<Self> {
        if self.is_negative() && n % 2 == 1 {
            return rational_root(&-self.clone(), n).map(|r| -r);
        }
        rational_root(self, n)
    }
}

impl Roots for f64 {
    fn nth_root(&self, n: u32) -> Option<Self> {
        match (n, *self < 0.0) {
            (0, _) | (_, true) if n.is_multiple_of(2) => None,
            (_, true) => Some(-(-self).powf(1.0 / f64::from(n))),
            _ => Some(self.powf(1.0 / f64::from(n))),
        }
    }
}

/// The exact n-th root of a non-negative rational, if it is rational:
/// `Some(r)` with `r ≥ 0` and `rⁿ = q`, else `None` (also for `q < 0` or
/// `n = 0`). Decided exactly with integer roots of numerator and denominator
/// (a reduced fraction is an n-th power iff both parts are).
///
/// ```
/// use exact_bezier::{algebra::rational_root, ratio};
/// assert_eq!(rational_root(&ratio(8, 27), 3), Some(ratio(2, 3)));
/// assert_eq!(rational_root(&ratio(2, 1), 2), None);
/// ```
pub fn rational_root(q: &BigRational, n: u32) -> Option<BigRational> {
    if n == 0 || q.is_negative() {
        return None;
    }
    let exact = |x: &BigInt| {
        let r = x.nth_root(n);
        (num_traits::pow(r.clone(), n as usize) == *x).then_some(r)
    };
    Some(BigRational::new(exact(q.numer())?, exact(q.denom())?))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A rational with numerator and denominator of up to 200 bits.
    fn rational() -> impl Strategy<Value = BigRational> {
        (
            any::<[u64; 3]>(),
            any::<[u64; 3]>(),
            1u32..200,
            1u32..200,
            any::<bool>(),
        )
            .prop_map(|(n, d, nb, db, neg)| {
                let big = |w: [u64; 3], bits: u32| {
                    let x = BigInt::from_slice(
                        num_bigint::Sign::Plus,
                        &w.iter()
                            .flat_map(|v| [*v as u32, (v >> 32) as u32])
                            .collect::<Vec<_>>(),
                    );
                    x % (BigInt::one() << bits)
                };
                let r = BigRational::new(big(n, nb), big(d, db) + 1);
                if neg {
                    -r
                } else {
                    r
                }
            })
    }

    proptest! {
        /// `mul_acc` on rationals is `acc·a + c·x` by `Ratio`'s own
        /// operators, in lowest terms.
        #[test]
        fn rational_mul_acc_is_the_ring_value(acc in rational(), a in rational(), c in rational(), x in rational()) {
            let mut got = acc.clone();
            BigRational::mul_acc(&mut got, &a, &c, &x);
            let want = acc * &a + c * &x;
            prop_assert_eq!(got.numer(), want.numer());
            prop_assert_eq!(got.denom(), want.denom());
        }

        /// `divide_each` on rationals is `Ratio`'s division, in lowest
        /// terms, zero and negative numbers included; so are `recip` and
        /// `sign_order` (against `Ratio`'s `cmp` with zero).
        #[test]
        fn rational_division_of_a_point(
            nums in prop::collection::vec(prop_oneof![rational(), Just(BigRational::zero())], 1..5),
            den in rational(),
        ) {
            prop_assume!(!den.is_zero());
            let got = BigRational::divide_each(&nums, &den);
            for (g, x) in got.iter().zip(&nums) {
                let want = x / &den;
                prop_assert_eq!(g.numer(), want.numer());
                prop_assert_eq!(g.denom(), want.denom());
            }
            prop_assert_eq!(Field::recip(&den), BigRational::one() / &den);
            prop_assert_eq!(den.sign_order(), den.cmp(&BigRational::zero()));
        }
    }

    #[test]
    fn binomials_match_pascal() {
        for n in 1..30 {
            for k in 1..n {
                assert_eq!(binomial(n, k), binomial(n - 1, k - 1) + binomial(n - 1, k));
            }
        }
    }

    #[test]
    fn huge_rationals_convert_to_f64() {
        let big = BigInt::from(10).pow(400);
        let q = BigRational::new(big.clone() * 3, big);
        assert!((rational_to_f64(&q) - 3.0).abs() < 1e-15);
    }

    #[test]
    fn pow_by_squaring() {
        assert_eq!(3.0_f64.pow_u32(5), 243.0);
        assert_eq!(ratio::<BigRational>(2, 3).pow_u32(3), ratio(8, 27));
        assert_eq!(ratio::<BigRational>(2, 3).pow_u32(0), ratio(1, 1));
    }

    #[test]
    fn default_sum_adds_left_to_right() {
        // (1e16 + 1) rounds back to 1e16 in f64, so the left fold gives 0;
        // any other order (1e16 − 1e16 first) would give 1.
        assert_eq!(f64::sum_of(vec![1e16, 1.0, -1e16]), 0.0);
        assert_eq!(f64::sum_of(Vec::new()), 0.0);
        let parts = vec![ratio::<BigRational>(1, 2), ratio(1, 3), ratio(1, 6)];
        assert_eq!(BigRational::sum_of(parts), ratio(1, 1));
    }
}
