//! Exact numbers from text: decimal and `p/q` text as a [`BigRational`]
//! ([`parse_rational`]), and the [`ExactNumber`] capability of the number
//! types the readers produce (`BigRational`, [`RealAlgebraic`], which also
//! reads the grammar of docs/algebraic_numbers.md), and their [`Cost`] in
//! the cost model of `limits`.

use crate::algebra::{parse_algebraic, Ordered, RealAlgebraic, Scalar};
use crate::error::Error;
use crate::limits::Cost;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

/// Read a rational exactly from decimal or fraction text: `"3"`, `"-0.885"`,
/// `"1.5e-3"`, `"1/3"`, `"-2/4"`.
///
/// # Errors
///
/// [`Error::BadNumber`] for anything else (including `NaN`, `inf`, a zero
/// denominator).
///
/// # Examples
///
/// ```
/// use exact_bezier::{algebra::parse_rational, ratio};
/// assert_eq!(parse_rational("0.885").unwrap(), ratio(885, 1000));
/// assert_eq!(parse_rational("1/3").unwrap(), ratio(1, 3));
/// assert_eq!(parse_rational("-2.5e-1").unwrap(), ratio(-1, 4));
/// assert!(parse_rational("NaN").is_err());
/// ```
pub fn parse_rational(text: &str) -> Result<BigRational, Error> {
    crate::limits::check_number_text(text)?;
    let t = text.trim();
    let bad = || Error::BadNumber(format!("{text:?}"));
    if let Some((n, d)) = t.split_once('/') {
        let n = parse_decimal(n.trim()).ok_or_else(bad)?;
        let d = parse_decimal(d.trim()).ok_or_else(bad)?;
        if d.is_zero() {
            return Err(Error::BadNumber(format!("{text:?} has a zero denominator")));
        }
        return Ok(n / d);
    }
    parse_decimal(t).ok_or_else(bad)
}

/// `[-+]digits[.digits][(e|E)[-+]digits]` as an exact rational.
fn parse_decimal(t: &str) -> Option<BigRational> {
    let (mantissa, exp) = match t.find(['e', 'E']) {
        Some(k) => (&t[..k], t[k + 1..].parse::<i32>().ok()?),
        None => (t, 0),
    };
    let (neg, digits) = match mantissa.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int_part, frac_part) = digits.split_once('.').unwrap_or((digits, ""));
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    if !int_part
        .chars()
        .chain(frac_part.chars())
        .all(|c| c.is_ascii_digit())
    {
        return None;
    }
    if exp.unsigned_abs() > 10_000 {
        return None;
    }
    let n = digits_value(int_part, frac_part)?;
    let scale = exp - frac_part.len() as i32;
    let ten = BigInt::from(10);
    let q = if scale >= 0 {
        BigRational::from_integer(n * num_traits::pow(ten, scale as usize))
    } else {
        crate::algebra::gcd::fraction(n, num_traits::pow(ten, (-scale) as usize))
    };
    Some(if neg { -q } else { q })
}

/// The integer written by the ASCII digits `int_part` then `frac_part`
/// (0 for none): in a machine word when there are at most 38 of them.
fn digits_value(int_part: &str, frac_part: &str) -> Option<BigInt> {
    let len = int_part.len() + frac_part.len();
    if len <= 38 {
        let n = int_part
            .bytes()
            .chain(frac_part.bytes())
            .fold(0u128, |acc, b| acc * 10 + u128::from(b - b'0'));
        return Some(BigInt::from(n));
    }
    format!("{int_part}{frac_part}").parse().ok()
}

/// Exact number types the reader produces: `BigRational` from decimal and
/// `p/q` text, and `RealAlgebraic`, which also reads the algebraic grammar
/// of docs/algebraic_numbers.md (`"sqrt(6)/6"`).
pub trait ExactNumber: Ordered + std::fmt::Display {
    /// The number written as `text`.
    ///
    /// # Errors
    ///
    /// [`Error::BadNumber`] for text that is not a number of this type.
    fn from_text(text: &str) -> Result<Self, Error>;
}

impl ExactNumber for BigRational {
    fn from_text(text: &str) -> Result<Self, Error> {
        parse_rational(text)
    }
}

impl ExactNumber for RealAlgebraic {
    fn from_text(text: &str) -> Result<Self, Error> {
        match parse_rational(text) {
            Ok(q) => Ok(RealAlgebraic::from_rational(&q)),
            Err(_) => parse_algebraic(text),
        }
    }
}

/// Exact rationals: `bits` of numerator and denominator, field degree 1.
impl Cost for BigRational {
    fn bits(&self) -> u64 {
        crate::limits::bits(self)
    }
    fn field_degree<'a>(_: impl IntoIterator<Item = &'a Self>) -> (u64, bool) {
        (1, false)
    }
}

/// Real algebraic numbers: the bits of the largest rational in their
/// representation ([`RealAlgebraic::coefficient_bits`]) and the degree `D`
/// of the field they span ([`RealAlgebraic::span_degree`]: radicals count
/// the degree of the radicals they use, every other number the degree of
/// its field, distinct fields multiplying). Both are read off the numbers
/// without arithmetic, so a command charges one operation on them as
/// [`field_op_cost`](crate::limits::field_op_cost)`(D, field)` rational operations
/// before it starts.
impl Cost for RealAlgebraic {
    fn bits(&self) -> u64 {
        self.coefficient_bits()
    }
    fn field_degree<'a>(xs: impl IntoIterator<Item = &'a Self>) -> (u64, bool) {
        let (degree, radicals) = RealAlgebraic::span_degree(xs);
        (degree, !radicals)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// A decimal is read as its digits over a power of ten, in lowest
        /// terms (the reference: num-rational's `Ratio::new`, which reduces),
        /// with up to 60 digits on either side of the point.
        #[test]
        fn a_decimal_is_its_digits_over_a_power_of_ten(
            int_part in "[0-9]{0,30}",
            frac_part in "[0-9]{1,30}",
            neg: bool,
        ) {
            let text = format!("{}{int_part}.{frac_part}", if neg { "-" } else { "" });
            let digits: BigInt = format!("{int_part}{frac_part}").parse().unwrap();
            let ten_k = num_traits::pow(BigInt::from(10), frac_part.len());
            let expected = BigRational::new(if neg { -digits } else { digits }, ten_k);
            prop_assert_eq!(parse_decimal(&text), Some(expected));
        }
    }
}
