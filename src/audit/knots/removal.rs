//! Exact knot removal on one B-spline curve, near one knot.
//!
//! Removing one copy of a knot `k` of multiplicity `s ≤ p` (its last copy
//! at `u_r`) undoes a knot insertion (Boehm): the curve with points `Q`
//! and one copy fewer gives back the points `P` by
//!
//! ```text
//! P_i = α_i Q_i + (1 − α_i) Q_{i−1},  α_i = (k − u_i)/(u_{i+p+1} − u_i),  r − p ≤ i ≤ r − s,
//! ```
//!
//! with `Q_{r−p−1} = P_{r−p−1}` and `Q_{r−s} = P_{r−s+1}` fixed (the other
//! points are `P`'s, shifted by one after the knot). These are `p − s + 1`
//! equations for `p − s` unknowns: solve the first ones upwards
//! (`α_i ≠ 0`), the last ones downwards (`α_i ≠ 1`), meeting in the middle
//! so that each chain of divisions is half as long, and the knot is
//! removable iff the equation left over holds. In exact arithmetic that is
//! an equality, and it holds iff the curve is `C^{p−s+1}` at `k`; removing
//! again from the new points tests the next order. Reference: Piegl &
//! Tiller, *The NURBS Book* (2nd ed., 1997), §5.4, algorithm A5.8 (with
//! tolerance zero).

use crate::algebra::gcd::{product, sum};
use crate::hpoint::HPoint;
use crate::nurbs::Knots;
use num_rational::BigRational;
use num_traits::One;

type Q = BigRational;

/// The part of a degree-`p` B-spline curve that removing a knot touches:
/// the points `P_{first−1−p} ..= P_{last}` and their knots, the knot's
/// copies being at `last − mult + 1 ..= last` (`last = mult + p` here).
pub(super) struct Near {
    degree: usize,
    knots: Vec<Q>,
    points: Vec<HPoint<Q>>,
    last: usize,
    mult: usize,
}

impl Near {
    /// The window of the curve with points `point(i)` around the knot
    /// copies `first..=last` of `knots` (`first ≥ p + 1`, an interior knot).
    pub(super) fn around<'a>(
        knots: &Knots,
        first: usize,
        last: usize,
        point: impl Fn(usize) -> &'a HPoint<Q>,
    ) -> Near {
        let p = knots.degree();
        let start = first - 1 - p;
        Near {
            degree: p,
            knots: knots.knots()[start..=last + p + 1].to_vec(),
            points: (start..=last).map(|i| point(i).clone()).collect(),
            last: last - start,
            mult: last + 1 - first,
        }
    }

    /// For a knot of multiplicity ≥ p + 1 whose two sides meet once the
    /// points before it are scaled by `scale`: the scaled curve with the
    /// knot at multiplicity `p` (`C⁰`). The two sides' shared point is kept
    /// once, and the points between (whose basis functions vanish on the
    /// domain when the multiplicity is over p + 1) are dropped.
    pub(super) fn joined(&self, scale: &Q) -> Near {
        let p = self.degree;
        let left = self.points[..=p].iter().map(|x| x.scale(scale));
        let right = self.points[self.points.len() - p..].iter().cloned();
        let kept = |i: usize| i <= p || i > p + self.mult - p;
        Near {
            degree: p,
            knots: (0..self.knots.len())
                .filter(|&i| kept(i))
                .map(|i| self.knots[i].clone())
                .collect(),
            points: left.chain(right).collect(),
            last: 2 * p,
            mult: p,
        }
    }

    /// The order of continuity at the knot: `p − μ + t` after `t`
    /// successful removals, `None` when all μ copies come out.
    pub(super) fn order(self) -> Option<usize> {
        let (p, mult) = (self.degree, self.mult);
        let mut near = self;
        let mut removed = 0;
        while near.mult > 0 {
            match near.remove_once() {
                Some(next) => near = next,
                None => break,
            }
            removed += 1;
        }
        (removed < mult).then(|| p - mult + removed)
    }

    /// The curve with one copy of the knot fewer, if it is the same curve
    /// (see the module docs); needs `1 ≤ mult ≤ p`.
    fn remove_once(&self) -> Option<Near> {
        let (p, r, s) = (self.degree, self.last, self.mult);
        let (lo, hi) = (r - p, r - s);
        let alpha = |i: usize| {
            let u = &self.knots;
            (&u[r] - &u[i]) / (&u[i + p + 1] - &u[i])
        };
        let middle = lo + (hi - lo) / 2;
        // Upwards: Q_i = (P_i − (1 − α_i) Q_{i−1}) / α_i, Q_{lo−1} … Q_{middle−1}.
        let mut below = vec![self.points[lo - 1].clone()];
        for i in lo..middle {
            let a = alpha(i);
            let q = affine(
                &self.points[i],
                &a.recip(),
                &below[below.len() - 1],
                &(-(Q::one() - &a) / &a),
            );
            below.push(q);
        }
        // Downwards: Q_{i−1} = (P_i − α_i Q_i) / (1 − α_i), Q_hi … Q_middle.
        let mut above = vec![self.points[hi + 1].clone()];
        for i in (middle + 1..=hi).rev() {
            let a = alpha(i);
            let b = Q::one() - &a;
            let q = affine(
                &self.points[i],
                &b.recip(),
                &above[above.len() - 1],
                &(-&a / &b),
            );
            above.push(q);
        }
        let a = alpha(middle);
        let (q_mid, q_before) = (&above[above.len() - 1], &below[below.len() - 1]);
        if affine(q_mid, &a, q_before, &(Q::one() - &a)) != self.points[middle] {
            return None;
        }
        let mut points = self.points[..lo - 1].to_vec();
        points.extend(below);
        points.extend(above.into_iter().rev());
        points.extend_from_slice(&self.points[hi + 2..]);
        let mut knots = self.knots.clone();
        knots.remove(r);
        Some(Near {
            degree: p,
            knots,
            points,
            last: r - 1,
            mult: s - 1,
        })
    }
}

/// `a·x + b·y`, coordinate by coordinate, reduced by Lehmer's gcd: what
/// [`HPoint::combine`] computes, without num-rational's binary gcd (with
/// `combine` the audit of `tail_section_asm.stp` took about 1 s more CPU,
/// 16.0 s against 15.0 s). Moving this reduction into the scalar trait,
/// so that `combine` itself uses it, is the general fix.
fn affine(x: &HPoint<Q>, a: &Q, y: &HPoint<Q>, b: &Q) -> HPoint<Q> {
    HPoint {
        coords: x
            .coords
            .iter()
            .zip(&y.coords)
            .map(|(xi, yi)| sum(&product(a, xi), &product(b, yi)))
            .collect(),
    }
}
