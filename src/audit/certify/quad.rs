//! Four intervals side by side — the homogeneous coordinates `x, y, z, w`
//! of one control point — with the interval operations of de Casteljau's
//! algorithm. Each lane is bit for bit the [`Interval`] operation (the unit
//! tests compare them); the lower and the upper ends are stored as two
//! arrays, so that the compiler runs the four lanes as one vector
//! operation (the patch enclosures of `audit` spend most of their time in
//! these steps).

use crate::algebra::interval::{next_down, next_up};
use crate::algebra::Interval;

/// The intervals `[lo[k], hi[k]]`, `k = 0..4`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quad {
    /// Lower ends.
    pub lo: [f64; 4],
    /// Upper ends.
    pub hi: [f64; 4],
}

impl Quad {
    /// The lanes `x[0..4]`.
    pub fn new(x: [Interval; 4]) -> Quad {
        Quad {
            lo: x.map(|i| i.lo),
            hi: x.map(|i| i.hi),
        }
    }

    /// Lane `k`.
    pub fn lane(&self, k: usize) -> Interval {
        Interval {
            lo: self.lo[k],
            hi: self.hi[k],
        }
    }

    /// The four lanes.
    pub fn lanes(&self) -> [Interval; 4] {
        [0, 1, 2, 3].map(|k| self.lane(k))
    }

    /// Every lane's midpoint ([`Interval::mid`]).
    pub fn mids(&self) -> [f64; 4] {
        self.lanes().map(|x| x.mid())
    }

    /// `self + o`, lane by lane ([`Interval::add`]).
    #[inline(always)]
    pub fn add(&self, o: &Quad) -> Quad {
        let mut out = *self;
        for k in 0..4 {
            out.lo[k] = next_down(self.lo[k] + o.lo[k]);
            out.hi[k] = next_up(self.hi[k] + o.hi[k]);
        }
        out
    }

    /// Every lane times `t` ([`Interval::mul_nonneg`], which falls back to
    /// [`Interval::mul`] when `t` reaches below 0).
    #[inline(always)]
    pub fn scale(&self, t: &Interval) -> Quad {
        let mut out = *self;
        if t.lo < 0.0 {
            for k in 0..4 {
                out.set(k, self.lane(k).mul(t));
            }
            return out;
        }
        for k in 0..4 {
            let (a, b) = (self.lo[k], self.hi[k]);
            out.lo[k] = next_down(a * if a >= 0.0 { t.lo } else { t.hi });
            out.hi[k] = next_up(b * if b >= 0.0 { t.hi } else { t.lo });
        }
        out
    }

    /// Every lane times `t` ([`Interval::mul`]: the least and greatest of
    /// the four products of the ends, NaNs ignored).
    #[inline(always)]
    pub fn mul(&self, t: &Interval) -> Quad {
        let mut out = *self;
        for k in 0..4 {
            let (a, b) = (self.lo[k], self.hi[k]);
            let p = [a * t.lo, a * t.hi, b * t.lo, b * t.hi];
            out.lo[k] = next_down(p.iter().fold(f64::INFINITY, |m, x| m.min(*x)));
            out.hi[k] = next_up(p.iter().fold(f64::NEG_INFINITY, |m, x| m.max(*x)));
        }
        out
    }

    /// The smallest box holding both, lane by lane ([`Interval::hull`]).
    #[inline(always)]
    pub fn hull(&self, o: &Quad) -> Quad {
        let mut out = *self;
        for k in 0..4 {
            out.lo[k] = self.lo[k].min(o.lo[k]);
            out.hi[k] = self.hi[k].max(o.hi[k]);
        }
        out
    }

    /// Every lane `[0, 0]`.
    pub fn zero() -> Quad {
        Quad {
            lo: [0.0; 4],
            hi: [0.0; 4],
        }
    }

    /// Make lane `k` the interval `x`.
    pub fn set(&mut self, k: usize, x: Interval) {
        self.lo[k] = x.lo;
        self.hi[k] = x.hi;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Intervals from ends of every sign and size, zeros of both signs and
    /// infinities among them.
    fn interval() -> impl Strategy<Value = Interval> {
        let end = prop_oneof![
            Just(0.0),
            Just(-0.0),
            Just(f64::INFINITY),
            Just(f64::NEG_INFINITY),
            -1e6f64..1e6,
            -1e-300f64..1e-300,
        ];
        (end.clone(), end).prop_map(|(a, b)| Interval {
            lo: a.min(b),
            hi: a.max(b),
        })
    }

    fn quad() -> impl Strategy<Value = Quad> {
        proptest::array::uniform4(interval()).prop_map(Quad::new)
    }

    /// The same bits, or NaN both (`∞ · 0`: the sign of a NaN depends on
    /// the order of the operands the compiler picks).
    fn same(a: Interval, b: Interval) -> bool {
        let end = |x: f64, y: f64| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
        end(a.lo, b.lo) && end(a.hi, b.hi)
    }

    proptest! {
        #[test]
        fn lanes_are_the_interval_operations(a in quad(), b in quad(), t in interval()) {
            for k in 0..4 {
                let (x, y) = (a.lane(k), b.lane(k));
                prop_assert!(same(a.add(&b).lane(k), x.add(&y)));
                prop_assert!(same(a.scale(&t).lane(k), x.mul_nonneg(&t)));
                prop_assert!(same(a.mul(&t).lane(k), x.mul(&t)));
                prop_assert!(same(a.mul(&t).lane(k), t.mul(&x)));
                prop_assert!(same(a.hull(&b).lane(k), x.hull(&y)));
            }
        }
    }
}
