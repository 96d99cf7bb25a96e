//! [`Interval`]: closed interval arithmetic on `f64` with outward rounding
//! (each result widened by one ulp on each side), so an interval always
//! encloses the exact value of the rational expression it stands for.
//! Used by the filtered predicates (`coincide::coincide` with `Options::filtered`).

use crate::algebra::scalar::rational_to_f64;
use num_rational::BigRational;

/// A closed interval `[lo, hi]` of reals with `f64` end points.
///
/// # Examples
///
/// ```
/// use exact_bezier::{algebra::Interval, ratio};
/// let third = Interval::enclose(&ratio(1, 3));
/// assert!(third.lo < 1.0 / 3.0 + 1e-15 && third.hi > 1.0 / 3.0 - 1e-15);
/// let sum = third.add(&third).add(&third);
/// assert!(sum.lo <= 1.0 && 1.0 <= sum.hi);
/// assert!(sum.disjoint(&Interval::enclose(&ratio(11, 10))));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

/// `x.next_up()` (the least `f64` above `x`; `x` itself for `+∞` and NaN),
/// without the standard library's branches: bit for bit the same value
/// for every input.
///
/// ```text
/// y = x + 0            (−0 becomes +0; every other x is unchanged)
/// b = bits(y)
/// up(x) = bits⁻¹(b + 1 − 2·sign(b))   for x < +∞,   x otherwise
/// ```
///
/// For `y ≥ 0` the next float up has the bit pattern one higher (IEEE 754
/// orders non-negative floats as their bit patterns; `+0` gives the least
/// subnormal, `f64::MAX` gives `+∞`); for `y < 0`, one lower (the
/// magnitude shrinks; the least negative subnormal gives `−0`, `−∞` gives
/// `−f64::MAX`); `+∞` and NaN (where `x < +∞` is false) are returned as
/// they are, as by `f64::next_up`. The unit tests compare the two on every
/// special value and on random bit patterns. Written as a select the
/// compiler makes branch-free, and so vectorises in loops.
#[inline(always)]
pub(crate) fn next_up(x: f64) -> f64 {
    let b = (x + 0.0).to_bits();
    let up = f64::from_bits(b.wrapping_add(1).wrapping_sub((b >> 63) << 1));
    if x < f64::INFINITY {
        up
    } else {
        x
    }
}

/// `x.next_down()`, as `−next_up(−x)` ([`next_up`]; negation is exact and
/// maps the floats above `−x` onto those below `x`): bit for bit the same
/// value for every input.
#[inline(always)]
pub(crate) fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// The least of four values, NaNs ignored (`+∞` when all are NaN).
fn min4(p: [f64; 4]) -> f64 {
    f64::INFINITY.min(p[0]).min(p[1]).min(p[2]).min(p[3])
}

/// The greatest of four values, NaNs ignored (`−∞` when all are NaN).
fn max4(p: [f64; 4]) -> f64 {
    f64::NEG_INFINITY.max(p[0]).max(p[1]).max(p[2]).max(p[3])
}

impl Interval {
    /// `[lo, hi]` widened outward by one ulp (the rounding of one operation).
    fn rounded(lo: f64, hi: f64) -> Interval {
        Interval {
            lo: next_down(lo),
            hi: next_up(hi),
        }
    }

    /// An interval certainly containing the rational `q`: its nearest `f64`
    /// widened by a relative `2⁻⁵⁰` (the conversion is accurate to a few
    /// ulps) and one ulp.
    pub fn enclose(q: &BigRational) -> Interval {
        let f = rational_to_f64(q);
        let slack = f.abs() * f64::EPSILON * 4.0 + f64::MIN_POSITIVE;
        Interval::rounded(f - slack, f + slack)
    }

    /// `self + o`.
    pub fn add(&self, o: &Interval) -> Interval {
        Interval::rounded(self.lo + o.lo, self.hi + o.hi)
    }

    /// `self − o`.
    pub fn sub(&self, o: &Interval) -> Interval {
        Interval::rounded(self.lo - o.hi, self.hi - o.lo)
    }

    /// `self · o`.
    pub fn mul(&self, o: &Interval) -> Interval {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        Interval::rounded(min4(p), max4(p))
    }

    /// `self · o` for a non-negative `o` (`o.lo ≥ 0`, checked): two
    /// products instead of four (`min = a·c` or `a·d` by the sign of `a`,
    /// `max = b·d` or `b·c` by the sign of `b`, for `[a, b]·[c, d]`).
    pub fn mul_nonneg(&self, o: &Interval) -> Interval {
        if o.lo < 0.0 {
            return self.mul(o);
        }
        // Selects rather than branches: the signs of control points
        // are not predictable.
        let lo = self.lo * if self.lo >= 0.0 { o.lo } else { o.hi };
        let hi = self.hi * if self.hi >= 0.0 { o.hi } else { o.lo };
        Interval::rounded(lo, hi)
    }

    /// `self / o`, or `None` when `o` contains 0.
    pub fn div(&self, o: &Interval) -> Option<Interval> {
        if o.lo <= 0.0 && o.hi >= 0.0 {
            return None;
        }
        let p = [
            self.lo / o.lo,
            self.lo / o.hi,
            self.hi / o.lo,
            self.hi / o.hi,
        ];
        Some(Interval::rounded(min4(p), max4(p)))
    }

    /// `self^e` by repeated multiplication (`[1, 1]` for e = 0).
    pub fn pow(&self, e: u32) -> Interval {
        (0..e).fold(Interval { lo: 1.0, hi: 1.0 }, |acc, _| acc.mul(self))
    }

    /// The degenerate interval `[x, x]` (an `f64` is an exact rational).
    pub fn point(x: f64) -> Interval {
        Interval { lo: x, hi: x }
    }

    /// The smallest interval containing both.
    pub fn hull(&self, o: &Interval) -> Interval {
        Interval {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }

    /// `−self` (exact: negation does not round).
    pub fn neg(&self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }

    /// `self²`: `[0, max²]` when `self` contains 0, tighter than `self · self`.
    pub fn sqr(&self) -> Interval {
        let (a, b) = (self.lo.abs(), self.hi.abs());
        if self.lo <= 0.0 && self.hi >= 0.0 {
            return Interval {
                lo: 0.0,
                hi: next_up(a.max(b) * a.max(b)),
            };
        }
        Interval::rounded(a.min(b) * a.min(b), a.max(b) * a.max(b))
    }

    /// `√self` over the non-negative part of `self` (IEEE `sqrt` is
    /// correctly rounded, so one ulp outward encloses it); `None` when
    /// `self` is entirely negative.
    pub fn sqrt(&self) -> Option<Interval> {
        if self.hi < 0.0 {
            return None;
        }
        let lo = next_down(self.lo.max(0.0).sqrt()).max(0.0);
        Some(Interval {
            lo,
            hi: next_up(self.hi.sqrt()),
        })
    }

    /// `max(|x|)` over the interval.
    pub fn mag(&self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    /// `hi − lo`, rounded up.
    pub fn width(&self) -> f64 {
        next_up(self.hi - self.lo)
    }

    /// The midpoint (an `f64` inside the interval).
    pub fn mid(&self) -> f64 {
        (0.5 * self.lo + 0.5 * self.hi).clamp(self.lo, self.hi)
    }

    /// Is `o` inside the interior of `self`?
    pub fn interior_contains(&self, o: &Interval) -> bool {
        self.lo < o.lo && o.hi < self.hi
    }

    /// The common part, `None` when disjoint.
    pub fn intersect(&self, o: &Interval) -> Option<Interval> {
        (!self.disjoint(o)).then(|| Interval {
            lo: self.lo.max(o.lo),
            hi: self.hi.min(o.hi),
        })
    }

    /// Do the intervals have no point in common (so the exact values differ)?
    pub fn disjoint(&self, o: &Interval) -> bool {
        self.hi < o.lo || o.hi < self.lo
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn interval(a: f64, b: f64) -> Interval {
        Interval {
            lo: a.min(b),
            hi: a.max(b),
        }
    }

    /// `next_up`/`next_down` against the standard library's, bit for bit.
    fn same_as_std(x: f64) {
        assert_eq!(
            next_up(x).to_bits(),
            x.next_up().to_bits(),
            "next_up({x:e})"
        );
        assert_eq!(
            next_down(x).to_bits(),
            x.next_down().to_bits(),
            "next_down({x:e})"
        );
    }

    #[test]
    fn rounding_steps_match_std_on_special_values() {
        let tiny = f64::from_bits(1);
        for x in [
            0.0,
            -0.0,
            tiny,
            -tiny,
            f64::MIN_POSITIVE,
            -f64::MIN_POSITIVE,
            1.0,
            -1.0,
            f64::MAX,
            -f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            -f64::NAN,
        ] {
            same_as_std(x);
        }
    }

    proptest! {
        /// On any bit pattern (NaNs of every payload included).
        #[test]
        fn rounding_steps_match_std_on_any_bits(bits in any::<u64>()) {
            same_as_std(f64::from_bits(bits));
        }


        /// With a non-negative factor, the two-product form picks the same
        /// extreme products as the four-product one.
        #[test]
        fn mul_nonneg_is_mul_for_non_negative_factors(
            x in (-1e6f64..1e6, -1e6f64..1e6),
            y in (0f64..1e6, 0f64..1e6),
        ) {
            let (a, o) = (interval(x.0, x.1), interval(y.0, y.1));
            prop_assert_eq!(a.mul_nonneg(&o), a.mul(&o));
        }
    }
}
