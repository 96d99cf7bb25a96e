//! Printed decimals of the sources compared with our exact values, exactly:
//! a printed `v` with `d` digits after the point is reproduced iff
//!
//! ```text
//! v − h ≤ x ≤ v + h,   h = 10^{−d}/2
//! ```
//!
//! decided by the exact comparison of [`RealAlgebraic`] with the rational
//! bounds `v ± h` (no `f64`, no tolerance). Used by the families
//! `hang_li_tables` and `yang_yong_examples`.

use super::{Claim, Verdict};
use exact_bezier::algebra::parse_rational;
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::algebra::{ratio, Scalar};
use exact_bezier::Error;
use num_rational::BigRational;

/// The exact scalar of printed comparisons.
type R = RealAlgebraic;

/// The number of decimal digits printed after the point.
pub(crate) fn digits(text: &str) -> usize {
    text.split_once('.').map_or(0, |(_, f)| f.len())
}

/// Does `x` round to the printed decimal `text`? Exactly:
/// `v − h ≤ x ≤ v + h` with `h` half a unit of the last printed digit.
pub(crate) fn rounds_to(x: &R, text: &str) -> bool {
    let v = parse_rational(text).expect("printed decimals parse");
    let exponent = u32::try_from(digits(text)).expect("few digits");
    let h = ratio::<BigRational>(1, 2) / BigRational::from_i64(10).pow_u32(exponent);
    let (lo, hi) = (
        R::from_rational(&(v.clone() - &h)),
        R::from_rational(&(v + h)),
    );
    lo <= *x && *x <= hi
}

/// Our exact value as text and its decimal expansion to three digits more
/// than `text` prints.
pub(crate) fn shown(x: &R, text: &str) -> String {
    format!("{x} ≈ {}", x.to_decimal(digits(text) + 3))
}

/// The claim that the printed decimal `text` is our value rounded; `note`
/// adds to the detail. `Broken` if the computation of our value failed.
pub(crate) fn decimal(
    claim: &str,
    source: &str,
    expected: Verdict,
    ours: &Result<R, Error>,
    text: &str,
    note: impl FnOnce(&R) -> String,
) -> Claim {
    match ours {
        Ok(x) => Claim::compare(
            claim,
            source,
            expected,
            rounds_to(x, text),
            text,
            &format!("{}{}", shown(x, text), note(x)),
        ),
        Err(e) => Claim::compare(claim, source, expected, false, text, "nothing")
            .given(false, &format!("the computation failed: {e}")),
    }
}
