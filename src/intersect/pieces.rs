//! The subdivision of two curves against each other that both the interval
//! filter (module `filter`) and the `f64` path (module `approx`) run, each
//! with its own [`Policy`] and coordinate type ([`Coord`]).
//!
//! The control polygons are halved at `1/2` (de Casteljau) level by level,
//! each curve's pieces of a level side by side in one buffer
//! ([`Pieces`]): each piece is halved once, whatever the number of pairs
//! it is in. At each level the policy drops the pairs whose pieces cannot
//! meet (by the convex hull property, a piece lies in the box of its
//! projected control points when its weights are positive), settles the
//! pairs it can decide, and the others are split into their four pairs of
//! halves; only the pieces still in a pair are carried to the next level.

use crate::algebra::Interval;

/// A coordinate of a control point: `f64` (rounded to nearest) or an
/// [`Interval`] (rounded outward, enclosing the exact value).
pub(super) trait Coord: Copy {
    /// `(a + b) / 2`.
    fn mid(a: Self, b: Self) -> Self;
    /// A box holding `x / w`, `None` when `w` may be 0.
    fn ratio(x: Self, w: Self) -> Option<Interval>;
    /// A box holding `x`.
    fn boxed(x: Self) -> Interval;
}

impl Coord for f64 {
    fn mid(a: f64, b: f64) -> f64 {
        0.5 * (a + b)
    }

    fn ratio(x: f64, w: f64) -> Option<Interval> {
        Some(Interval::point(x / w))
    }

    fn boxed(x: f64) -> Interval {
        Interval::point(x)
    }
}

impl Coord for Interval {
    /// Halving is exact in `f64`; the sum is rounded outward.
    fn mid(a: Interval, b: Interval) -> Interval {
        a.add(&b).mul_nonneg(&Interval::point(0.5))
    }

    fn ratio(x: Interval, w: Interval) -> Option<Interval> {
        x.div(&w)
    }

    fn boxed(x: Interval) -> Interval {
        x
    }
}

/// One curve's pieces at one level of the subdivision, side by side in one
/// buffer: piece `i` holds the control points `i·len … (i+1)·len − 1`,
/// each `stride` coordinates (the Cartesian coordinates times the weight,
/// then the weight; without the weight for a polynomial curve, whose
/// weight is 1), and has the exact (dyadic) parameter range `range[i]`.
pub(super) struct Pieces<C> {
    /// Control points per piece.
    pub len: usize,
    /// Coordinates per control point.
    pub stride: usize,
    /// Whether the last coordinate of a point is its weight.
    pub weighted: bool,
    /// The coordinates, piece after piece, point after point.
    pub ctrl: Vec<C>,
    /// The parameter range of each piece.
    pub range: Vec<Interval>,
}

impl<C: Coord> Pieces<C> {
    /// The whole curve `[0, 1]` from its control points, flat (`stride`
    /// coordinates each, the weight last when `weighted`).
    pub fn whole(ctrl: Vec<C>, stride: usize, weighted: bool) -> Pieces<C> {
        Pieces {
            len: ctrl.len() / stride,
            stride,
            weighted,
            ctrl,
            range: vec![Interval { lo: 0.0, hi: 1.0 }],
        }
    }

    /// The number of Cartesian coordinates.
    pub fn dim(&self) -> usize {
        self.stride - usize::from(self.weighted)
    }

    /// The coordinates of piece `i`, flat.
    pub fn piece(&self, i: usize) -> &[C] {
        let n = self.len * self.stride;
        &self.ctrl[i * n..(i + 1) * n]
    }

    /// Both halves of every piece (de Casteljau at `1/2`): piece `i`
    /// becomes pieces `2i` (left) and `2i + 1` (right).
    pub fn halves(&self) -> Pieces<C> {
        let (len, stride) = (self.len, self.stride);
        let n = len * stride;
        let mut ctrl = self.ctrl.repeat(2);
        let mut row = Vec::with_capacity(n);
        for (piece, out) in self.ctrl.chunks_exact(n).zip(ctrl.chunks_exact_mut(2 * n)) {
            row.clear();
            row.extend_from_slice(piece);
            let (left, right) = out.split_at_mut(n);
            for r in 0..len {
                if r > 0 {
                    for j in 0..(len - r) * stride {
                        row[j] = C::mid(row[j], row[j + stride]);
                    }
                }
                let (first, last) = (0..stride, (len - 1 - r) * stride..(len - r) * stride);
                left[r * stride..(r + 1) * stride].copy_from_slice(&row[first]);
                right[(len - 1 - r) * stride..(len - r) * stride].copy_from_slice(&row[last]);
            }
        }
        let range = self
            .range
            .iter()
            .flat_map(|r| {
                let m = 0.5 * (r.lo + r.hi);
                [Interval { lo: r.lo, hi: m }, Interval { lo: m, hi: r.hi }]
            })
            .collect();
        Pieces {
            ctrl,
            range,
            ..*self
        }
    }

    /// The pieces `keep` (increasing), renumbered `0, 1, …`.
    fn select(&self, keep: &[usize]) -> Pieces<C> {
        Pieces {
            ctrl: keep.iter().flat_map(|&i| self.piece(i)).copied().collect(),
            range: keep.iter().map(|&i| self.range[i]).collect(),
            ..*self
        }
    }

    /// The boxes of the pieces' projected control points (`dim` intervals
    /// each, side by side), `None` when a weight may be 0.
    pub fn bounding_boxes(&self) -> Option<Vec<Interval>> {
        let (dim, stride) = (self.dim(), self.stride);
        let mut boxes = Vec::with_capacity(self.range.len() * dim);
        for piece in self.ctrl.chunks_exact(self.len * stride) {
            for k in 0..dim {
                let mut points = piece.chunks_exact(stride).map(|p| match self.weighted {
                    true => C::ratio(p[k], p[dim]),
                    false => Some(C::boxed(p[k])),
                });
                let first = points.next()??;
                boxes.push(points.try_fold(first, |b, x| Some(b.hull(&x?)))?);
            }
        }
        Some(boxes)
    }
}

/// Why a subdivision stopped without settling every pair.
#[derive(Debug, PartialEq)]
pub(super) enum Stop {
    /// The policy gave up (e.g. a weight box containing 0).
    Refused,
    /// More pairs at one level than the limit.
    TooMany,
    /// Pairs left at the deepest level.
    TooDeep,
}

/// What a subdivision does with the pairs of a level: piece `i` of the
/// first curve against piece `j` of the second.
pub(super) trait Policy<C> {
    /// Drop the pairs whose pieces cannot meet.
    fn sift(
        &mut self,
        a: &Pieces<C>,
        b: &Pieces<C>,
        pairs: &mut Vec<(usize, usize)>,
    ) -> Result<(), Stop>;

    /// Ready the level for [`Policy::settle`], given its pieces and their
    /// halves (called only when some pair is left after the sift).
    fn prepare(&mut self, level: [&Pieces<C>; 4]) -> Result<(), Stop>;

    /// Whether the pair is settled (recorded by the policy, its halves not
    /// looked at).
    fn settle(&mut self, a: &Pieces<C>, b: &Pieces<C>, pair: (usize, usize)) -> Result<bool, Stop>;
}

/// Run the subdivision of `a` against `b` (both whole curves) under
/// `policy` until every pair is dropped or settled, for at most `depth`
/// levels of at most `max_pairs` pairs each.
pub(super) fn subdivide<C: Coord>(
    a: Pieces<C>,
    b: Pieces<C>,
    policy: &mut impl Policy<C>,
    depth: usize,
    max_pairs: usize,
) -> Result<(), Stop> {
    let (mut a, mut b, mut pairs) = (a, b, vec![(0, 0)]);
    for _ in 0..depth {
        policy.sift(&a, &b, &mut pairs)?;
        if pairs.is_empty() {
            return Ok(());
        }
        let (ha, hb) = (a.halves(), b.halves());
        policy.prepare([&a, &b, &ha, &hb])?;
        let mut next = Vec::with_capacity(4 * pairs.len());
        for &(i, j) in &pairs {
            if !policy.settle(&a, &b, (i, j))? {
                next.extend([(2 * i, 2 * j), (2 * i, 2 * j + 1)]);
                next.extend([(2 * i + 1, 2 * j), (2 * i + 1, 2 * j + 1)]);
            }
        }
        if next.is_empty() {
            return Ok(());
        }
        if next.len() > max_pairs {
            return Err(Stop::TooMany);
        }
        let (keep_a, keep_b) = (renumber(&mut next, 0), renumber(&mut next, 1));
        (a, b, pairs) = (ha.select(&keep_a), hb.select(&keep_b), next);
    }
    Err(Stop::TooDeep)
}

/// The distinct piece numbers in position `side` of the pairs, increasing;
/// the pairs are rewritten to their ranks in that list.
fn renumber(pairs: &mut [(usize, usize)], side: usize) -> Vec<usize> {
    let get = |p: &(usize, usize)| if side == 0 { p.0 } else { p.1 };
    let mut keep: Vec<usize> = pairs.iter().map(get).collect();
    keep.sort_unstable();
    keep.dedup();
    for p in pairs.iter_mut() {
        let rank = keep.binary_search(&get(p)).expect("listed");
        *(if side == 0 { &mut p.0 } else { &mut p.1 }) = rank;
    }
    keep
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A planar cubic's control points, flat, no weights.
    const CUBIC: [f64; 8] = [0.2, 0.78, 0.94, 0.83, 0.54, 0.0, 0.65, 0.71];

    /// The halves of the interval pieces enclose the `f64` halves, which
    /// meet at the curve's point at `1/2` (`(P0 + 3P1 + 3P2 + P3)/8`), and
    /// the halves' boxes lie in the whole curve's box.
    #[test]
    fn interval_halves_enclose_the_f64_halves() {
        let exact = Pieces::whole(CUBIC.to_vec(), 2, false).halves();
        let boxes = Pieces::whole(CUBIC.map(Interval::point).to_vec(), 2, false).halves();
        for (x, b) in exact.ctrl.iter().zip(&boxes.ctrl) {
            assert!(b.lo <= *x && *x <= b.hi && b.hi - b.lo < 1e-14);
        }
        for k in 0..2 {
            let mid = (CUBIC[k] + 3.0 * CUBIC[2 + k] + 3.0 * CUBIC[4 + k] + CUBIC[6 + k]) / 8.0;
            assert!((exact.piece(1)[k] - mid).abs() < 1e-15);
            assert_eq!(exact.piece(0)[6 + k], exact.piece(1)[k]);
        }
        assert_eq!(exact.range[1], Interval { lo: 0.5, hi: 1.0 });
        let whole = Pieces::whole(CUBIC.to_vec(), 2, false)
            .bounding_boxes()
            .unwrap();
        for b in exact.bounding_boxes().unwrap().chunks_exact(2) {
            for (h, w) in b.iter().zip(&whole) {
                assert!(w.lo <= h.lo && h.hi <= w.hi);
            }
        }
    }

    /// Settles nothing and drops nothing.
    struct Never;

    impl Policy<f64> for Never {
        fn sift(
            &mut self,
            _: &Pieces<f64>,
            _: &Pieces<f64>,
            _: &mut Vec<(usize, usize)>,
        ) -> Result<(), Stop> {
            Ok(())
        }

        fn prepare(&mut self, _: [&Pieces<f64>; 4]) -> Result<(), Stop> {
            Ok(())
        }

        fn settle(
            &mut self,
            _: &Pieces<f64>,
            _: &Pieces<f64>,
            _: (usize, usize),
        ) -> Result<bool, Stop> {
            Ok(false)
        }
    }

    /// The limits hold: `4^k` pairs at level `k`, so 3 levels of at most
    /// 64 pairs run out of depth and 2 levels of at most 15 out of pairs.
    #[test]
    fn the_subdivision_stops_at_its_limits() {
        let whole = || Pieces::whole(CUBIC.to_vec(), 2, false);
        assert_eq!(
            subdivide(whole(), whole(), &mut Never, 3, 64),
            Err(Stop::TooDeep)
        );
        assert_eq!(
            subdivide(whole(), whole(), &mut Never, 3, 15),
            Err(Stop::TooMany)
        );
    }
}
