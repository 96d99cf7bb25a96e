//! Plane angles of STEP ([`AngleUnit`]) and the slope `tan α` of a cone's
//! `semi_angle` ([`cone_slope`]), exact where it can be.
//!
//! `tan α` of a decimal angle is transcendental in general. The rule:
//!
//! 1. **Exact** when the decimal is the rounding, to its printed digits, of
//!    a multiple `k·15°` (`k = 1…5`; `kπ/12` in radians): then `α` is taken
//!    as that multiple and `tan α ∈ Q(√3)` exactly (`2 − √3, √3/3, 1, √3,
//!    2 + √3`). "Is the rounding" is decided rigorously: `|d − k·15°| ≤ ½`
//!    unit of the last printed digit, with π enclosed in
//!    `[3.14159…841971, +10⁻⁴⁰]` (40 correct decimals), and the match is
//!    accepted only if the whole enclosure is within the half unit.
//! 2. **Approximate** otherwise (or when `T` has no `√3`, e.g.
//!    `BigRational`): `tan α` is enclosed rigorously (alternating Taylor
//!    partial sums bracket `sin` and `cos` for `0 < α < π/2`), and the slope
//!    is the dyadic rational with 64 fractional bits nearest the middle; the
//!    result carries an exact bound `error ≥ |slope − tan α|` and
//!    `exact = false`. Nothing is approximated silently.
//!
//! Both steps depend only on the decimal and the unit, and a model repeats
//! the same few semi-angles on many cones (NIST CTC 02: 82 cones, two
//! angles), so their rational results are remembered per thread
//! (`SLOPES`); the Taylor enclosure was a tenth of reading that model.

use crate::algebra::gcd;
use crate::algebra::parse_rational;
use crate::algebra::scalar::{Field, Ordered, Roots};
use crate::error::Error;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cell::RefCell;
use std::collections::HashMap;

/// The plane angle unit of a STEP representation context (one type for
/// the B-rep's contexts and the geometry readers).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum AngleUnit {
    /// `SI_UNIT(prefix, .RADIAN.)`: the radian times its SI prefix factor
    /// (1 unprefixed).
    Radian(BigRational),
    /// A conversion-based unit named degree: exactly π/180 radian (the
    /// file's decimal factor approximates it and is not used).
    Degree,
    /// Another conversion-based unit: its name and written factor in
    /// radians.
    Other(String, BigRational),
}

impl AngleUnit {
    /// The unprefixed radian.
    pub fn radian() -> Self {
        AngleUnit::Radian(BigRational::one())
    }

    /// The factor of a unit written as a number of radians (`None` for the
    /// degree, whose factor π/180 is not rational).
    pub fn radians(&self) -> Option<&BigRational> {
        match self {
            AngleUnit::Radian(f) | AngleUnit::Other(_, f) => Some(f),
            AngleUnit::Degree => None,
        }
    }

    /// An angle written `a` in this unit, in radians, as an `f64`.
    pub fn to_radians_f64(&self, a: f64) -> f64 {
        match self.radians() {
            Some(f) => a * num_traits::ToPrimitive::to_f64(f).unwrap_or(f64::NAN),
            None => a.to_radians(),
        }
    }
}

/// The slope `tan α` of a cone, with how it was obtained.
#[derive(Clone, Debug, PartialEq)]
pub struct Slope<T> {
    /// `tan α`, exact when `exact`, else within `error` of it.
    pub tan: T,
    /// Was `α` recognised as a multiple of 15° (see the module docs)?
    pub exact: bool,
    /// An exact upper bound of `|tan − tan α|` (0 when `exact`).
    pub error: BigRational,
}

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// π ∈ [lo, hi], from its first 40 decimals.
fn pi_enclosure() -> (BigRational, BigRational) {
    let lo = parse_rational("3.1415926535897932384626433832795028841971").expect("a decimal");
    let hi = lo.clone() + BigRational::new(BigInt::one(), BigInt::from(10).pow(40));
    (lo, hi)
}

/// Half a unit of the last printed digit of a decimal `[-]m[.f][E e]`.
fn half_ulp(text: &str) -> Result<BigRational, Error> {
    let t = text.trim().trim_start_matches(['+', '-']);
    let (mantissa, exp) = match t.find(['e', 'E']) {
        Some(k) => (&t[..k], t[k + 1..].parse::<i32>().map_err(|_| bad(text))?),
        None => (t, 0),
    };
    let frac = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    let p = exp - frac;
    let ten = BigRational::from_integer(BigInt::from(10));
    let ulp = if p >= 0 {
        ten.pow(p)
    } else {
        ten.pow(-p).recip()
    };
    Ok(ulp / BigRational::from_integer(BigInt::from(2)))
}

fn bad(text: &str) -> Error {
    Error::BadNumber(format!("{text:?} is not a decimal angle"))
}

/// The slope `tan α` of the cone `semi_angle` written as `text` in `unit`
/// (see the module docs for the exact/approximate rule).
///
/// # Errors
///
/// [`Error::BadNumber`] if `text` is not a decimal; [`Error::Domain`]
/// unless `0 < α < 90°`.
///
/// ```
/// use exact_bezier::{analytic::{cone_slope, AngleUnit}, algebra::RealAlgebraic, Scalar};
/// let s = cone_slope::<RealAlgebraic>("0.523598775598299", &AngleUnit::radian()).unwrap();
/// assert!(s.exact); // π/6 to 15 decimals: tan = √3/3
/// assert_eq!(s.tan.clone() * &s.tan, RealAlgebraic::from_i64(1) / RealAlgebraic::from_i64(3));
/// let t = cone_slope::<RealAlgebraic>("59.", &AngleUnit::Degree).unwrap();
/// assert!(!t.exact);
/// assert!(t.error < exact_bezier::ratio(1, 1i64 << 60));
/// ```
pub fn cone_slope<T: Field + Ordered + Roots>(
    text: &str,
    unit: &AngleUnit,
) -> Result<Slope<T>, Error> {
    let angle = remembered_semi_angle(text, unit)?;
    if let Some(tan) = angle.multiple.and_then(tan_15::<T>) {
        return Ok(Slope {
            tan,
            exact: true,
            error: BigRational::zero(),
        });
    }
    Ok(Slope {
        tan: T::from_rational(&angle.tan),
        exact: false,
        error: angle.error,
    })
}

/// What the slope of a decimal semi-angle is before it becomes a `T`: the
/// multiple `k·15°` it is the rounding of, if any, and the dyadic slope
/// with its error bound (rule 2 of the module docs, used when there is no
/// such `k` or `T` has no `√3`).
#[derive(Clone, Debug)]
struct SemiAngle {
    multiple: Option<i64>,
    tan: BigRational,
    error: BigRational,
}

/// The most semi-angles [`SLOPES`] keeps before it is cleared, and the
/// longest text it keeps one for (longer ones are computed every time).
const SLOPES_KEPT: usize = 256;
const SLOPE_TEXT_KEPT: usize = 64;

thread_local! {
    /// [`semi_angle`]'s answers on this thread, by text and unit.
    static SLOPES: RefCell<HashMap<(String, AngleUnit), SemiAngle>> = RefCell::new(HashMap::new());
}

/// [`semi_angle`], remembered in [`SLOPES`] (errors are not kept).
fn remembered_semi_angle(text: &str, unit: &AngleUnit) -> Result<SemiAngle, Error> {
    if text.len() > SLOPE_TEXT_KEPT {
        return semi_angle(text, unit);
    }
    let key = (text.to_string(), unit.clone());
    if let Some(known) = SLOPES.with(|t| t.borrow().get(&key).cloned()) {
        return Ok(known);
    }
    let angle = semi_angle(text, unit)?;
    SLOPES.with(|t| {
        let mut t = t.borrow_mut();
        if t.len() >= SLOPES_KEPT {
            t.clear();
        }
        t.insert(key, angle.clone());
    });
    Ok(angle)
}

/// The semi-angle `text` in `unit`: the multiple of 15° it rounds (rule 1
/// of the module docs) and its approximate slope (rule 2).
fn semi_angle(text: &str, unit: &AngleUnit) -> Result<SemiAngle, Error> {
    let d = parse_rational(text)?;
    let half = half_ulp(text)?;
    let (pi_lo, pi_hi) = pi_enclosure();
    // α in radians is in [lo, hi] (a radian factor f scales the decimal
    // and its half unit alike).
    let (lo, hi, half) = match unit.radians() {
        Some(f) => (d.clone() * f, d.clone() * f, half * f),
        None => (
            d.clone() * &pi_lo / q(180, 1),
            d.clone() * &pi_hi / q(180, 1),
            half,
        ),
    };
    let d = match unit.radians() {
        Some(f) => d * f,
        None => d,
    };
    if !lo.is_positive() || hi >= pi_lo.clone() / q(2, 1) {
        return Err(Error::Domain(format!(
            "a cone's semi_angle must lie strictly between 0 and 90°, not {text}"
        )));
    }
    let multiple = (1..=5i64).find(|&k| {
        let (a, b) = match unit {
            AngleUnit::Degree => (q(15 * k, 1), q(15 * k, 1)),
            _ => (pi_lo.clone() * q(k, 12), pi_hi.clone() * q(k, 12)),
        };
        (a - &d).abs() <= half && (b - &d).abs() <= half
    });
    let (tan, error) = approximate(&lo, &hi)?;
    Ok(SemiAngle {
        multiple,
        tan,
        error,
    })
}

/// `tan(k·15°)` for `k = 1…5`, or `None` without `√3` in `T`.
fn tan_15<T: Field + Roots>(k: i64) -> Option<T> {
    if k == 3 {
        return Some(T::one());
    }
    let r3 = T::from_i64(3).nth_root(2)?;
    let two = T::from_i64(2);
    Some(match k {
        1 => two - &r3,
        2 => r3 / &T::from_i64(3),
        4 => r3,
        _ => two + &r3,
    })
}

/// `sin x` and `cos x` of the dyadic `x = X/2^f` bracketed by consecutive
/// alternating partial sums (valid for `0 < x < √6`, where the terms
/// decrease), stopped at the first term below `2^{−80}`.
///
/// The partial sums are kept as integers over their common denominator
/// `2^{f(2k+1)}·(2k+1)!` (`2^{2fk}·(2k)!` for the cosine), so no fraction
/// is reduced until the two returned bounds; the values are those of the
/// reduced-fraction recurrence `t ← −t·x²/((n+1)(n+2))`.
fn bracket(x: &BigInt, f: usize, odd: bool) -> (BigRational, BigRational) {
    let x2 = x * x;
    let (mut term, mut denom, mut n) = if odd {
        (x.clone(), BigInt::one() << f, 1i64)
    } else {
        (BigInt::one(), BigInt::one(), 0i64)
    };
    let mut sum = term.clone();
    loop {
        let step = BigInt::from((n + 1) * (n + 2)) << (2 * f);
        term = -(term * &x2);
        let next_denom = &denom * &step;
        let next = &sum * &step + &term;
        n += 2;
        if (term.abs() << 80usize) < next_denom {
            let a = gcd::fraction(sum, denom);
            let b = gcd::fraction(next, next_denom);
            return if a < b { (a, b) } else { (b, a) };
        }
        (sum, denom) = (next, next_denom);
    }
}

/// The 64-bit dyadic slope nearest the middle of a rigorous enclosure of
/// `tan α` for `α ∈ [lo, hi] ⊂ (0, π/2)`, and a bound of its error.
fn approximate(lo: &BigRational, hi: &BigRational) -> Result<(BigRational, BigRational), Error> {
    // Widen [lo, hi] outward to 96-bit dyadics: the enclosure stays
    // rigorous, and the Taylor terms stay short (the 40-digit π of a degree
    // angle would otherwise make every power of x a long fraction).
    const GRID: usize = 96;
    let grid = BigRational::from_integer(BigInt::one() << GRID);
    let lo = &(lo.clone() * &grid).floor().to_integer();
    let hi = &(hi.clone() * &grid).ceil().to_integer();
    let (s_lo, _) = bracket(lo, GRID, true);
    let (_, c_hi) = bracket(lo, GRID, false);
    let (_, s_hi) = bracket(hi, GRID, true);
    let (c_lo, _) = bracket(hi, GRID, false);
    if !s_lo.is_positive() || !c_lo.is_positive() {
        return Err(Error::Domain(
            "a cone's semi_angle too close to 0 or 90° to bound its tangent".into(),
        ));
    }
    // tan is increasing on (0, π/2).
    let (t_lo, t_hi) = (s_lo / c_hi, s_hi / c_lo);
    let scale = BigRational::from_integer(BigInt::one() << 64);
    let mid = (t_lo.clone() + &t_hi) / q(2, 1);
    let tan = (mid * &scale).round() / &scale;
    let error = (tan.clone() - t_lo).max(t_hi - &tan);
    Ok((tan, error))
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::ToPrimitive;
    use proptest::prelude::*;

    /// The recurrence on reduced fractions, term by term (the reference).
    fn reduced_bracket(x: &BigRational, odd: bool) -> (BigRational, BigRational) {
        let eps = BigRational::new(BigInt::one(), BigInt::one() << 80);
        let x2 = x.clone() * x;
        let (mut term, mut n) = if odd {
            (x.clone(), 1i64)
        } else {
            (BigRational::one(), 0i64)
        };
        let mut sum = term.clone();
        loop {
            term = -term * &x2 / q((n + 1) * (n + 2), 1);
            n += 2;
            let next = sum.clone() + &term;
            if term.abs() < eps {
                return if sum < next { (sum, next) } else { (next, sum) };
            }
            sum = next;
        }
    }

    proptest! {
        /// The integer recurrence gives the reduced recurrence's bounds, and
        /// they bracket `f64`'s sin or cos up to its rounding (`1e-15`).
        #[test]
        fn the_integer_bracket_is_the_reduced_one(x in 1u64..(1u64 << 50), odd: bool) {
            // x / 2^50 ∈ (0, 1): a dyadic on a grid of 96 bits.
            let big = BigInt::from(x) << 46usize;
            let exact = BigRational::new(BigInt::from(x), BigInt::one() << 50usize);
            let (lo, hi) = bracket(&big, 96, odd);
            prop_assert_eq!((lo.clone(), hi.clone()), reduced_bracket(&exact, odd));
            let v = ToPrimitive::to_f64(&exact).unwrap();
            let f = if odd { v.sin() } else { v.cos() };
            prop_assert!(ToPrimitive::to_f64(&lo).unwrap() <= f + 1e-15 && f - 1e-15 <= ToPrimitive::to_f64(&hi).unwrap());
        }
    }
}
