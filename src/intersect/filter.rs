//! The rigorous interval filter in front of the exact intersection.
//!
//! The control polygons are subdivided at `1/2` in interval arithmetic
//! with outward rounding ([`Interval`]); by the convex hull property
//! (positive weights), each piece lies in the box of its projected control
//! points. The subdivision runs level by level: each piece of a level is
//! halved once, whatever the number of pairs it is in, and its bounding
//! box, its midpoint (the point the halving shares between the halves)
//! and, in the plane, its velocity hull are computed once. Pairs of pieces
//! with disjoint boxes are dropped; in the plane, the Krawczyk test
//! (module `certify`) certifies a unique transversal crossing in a pair's
//! parameter box or excludes one. When every pair is decided by some
//! depth, the answer is certified without the exact path.
//!
//! A curve whose weights are all equal is a polynomial curve: its pieces
//! carry no weight (`W ≡ 1` exactly after dividing by it), which makes
//! the boxes and velocities cheaper and tighter.

use super::certify::{
    contract, jacobian, krawczyk, point_and_velocity, Krawczyk, Net, PlanarBoxes,
};
use crate::algebra::Interval;
use crate::curve::RationalCurve;
use crate::error::Error;
use num_rational::BigRational;
use num_traits::One;

/// A transversal crossing of two planar curves certified by interval
/// arithmetic: exactly one intersection has its parameters in `s × t`.
#[derive(Clone, Debug, PartialEq)]
pub struct CertifiedCrossing {
    /// An interval holding the parameter on the first curve.
    pub s: Interval,
    /// An interval holding the parameter on the second curve.
    pub t: Interval,
    /// A box holding the common point.
    pub point: Vec<Interval>,
}

/// Depth of the interval subdivision: parameter boxes down to `2⁻¹⁶`.
const FILTER_DEPTH: usize = 16;
/// The most box pairs kept at one depth before the filter gives up (high
/// degrees need many: two random degree-20 curves with 8 crossings are
/// not decided within 64).
const FILTER_PAIRS: usize = 1024;

/// One curve's pieces at one level of the subdivision, side by side in one
/// buffer: piece `i` holds the control points `i·len … (i+1)·len − 1`,
/// each `stride` boxes (the Cartesian coordinates times the weight, then
/// the weight; without the weight for a polynomial curve), and has the
/// exact (dyadic) parameter range `range[i]`.
struct Pieces {
    len: usize,
    stride: usize,
    weighted: bool,
    ctrl: Vec<Interval>,
    range: Vec<Interval>,
}

impl Pieces {
    /// The whole curve, its control points enclosed; a curve with equal
    /// weights is divided by them exactly first (`W ≡ 1`).
    fn whole(c: &RationalCurve<BigRational>) -> Pieces {
        let dim = c.dim();
        let w0 = &c.ctrl()[0].coords[dim];
        let weighted = c.ctrl().iter().any(|h| h.coords[dim] != *w0);
        let ctrl = c
            .ctrl()
            .iter()
            .flat_map(|h| {
                let coords = if weighted {
                    &h.coords[..]
                } else {
                    &h.coords[..dim]
                };
                coords.iter().map(move |x| match weighted || w0.is_one() {
                    true => Interval::enclose(x),
                    false => Interval::enclose(&(x / w0)),
                })
            })
            .collect();
        Pieces {
            len: c.ctrl().len(),
            stride: dim + usize::from(weighted),
            weighted,
            ctrl,
            range: vec![Interval { lo: 0.0, hi: 1.0 }],
        }
    }

    /// The number of Cartesian coordinates.
    fn dim(&self) -> usize {
        self.stride - usize::from(self.weighted)
    }

    /// The control boxes of piece `i`, flat.
    fn net(&self, i: usize) -> Net<'_> {
        let n = self.len * self.stride;
        Net {
            ctrl: &self.ctrl[i * n..(i + 1) * n],
            stride: self.stride,
            weighted: self.weighted,
        }
    }

    /// Both halves of every piece (de Casteljau at `1/2`; halving is exact
    /// in `f64`, the sums are rounded outward): piece `i` becomes pieces
    /// `2i` (left) and `2i + 1` (right).
    fn halves(&self) -> Pieces {
        let (len, stride) = (self.len, self.stride);
        let half = Interval::point(0.5);
        let mut ctrl = vec![Interval::point(0.0); 2 * self.ctrl.len()];
        let mut row = vec![Interval::point(0.0); len * stride];
        for (i, out) in ctrl.chunks_exact_mut(2 * len * stride).enumerate() {
            row.copy_from_slice(self.net(i).ctrl);
            let (left, right) = out.split_at_mut(len * stride);
            for r in 0..len {
                if r > 0 {
                    for j in 0..(len - r) * stride {
                        row[j] = row[j].add(&row[j + stride]).mul_nonneg(&half);
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
    fn select(&self, keep: &[usize]) -> Pieces {
        Pieces {
            ctrl: keep
                .iter()
                .flat_map(|&i| self.net(i).ctrl)
                .copied()
                .collect(),
            range: keep.iter().map(|&i| self.range[i]).collect(),
            ..*self
        }
    }
}

/// Enclosures of a planar piece's point at the middle of its range and of
/// its velocity over the range (`None` when a weight box contains 0).
type PieceFacts = Option<([Interval; 2], [Interval; 2])>;

impl Pieces {
    /// The bounding boxes of the pieces (`dim` intervals each, side by
    /// side), `None` when a weight box contains 0.
    fn bounding_boxes(&self) -> Option<Vec<Interval>> {
        let mut boxes = Vec::with_capacity(self.range.len() * self.dim());
        for i in 0..self.range.len() {
            self.net(i).bounding_box(self.dim(), &mut boxes)?;
        }
        Some(boxes)
    }

    /// The midpoint and velocity enclosures of planar pieces, `halves`
    /// being `self.halves()` (the midpoint is where the halves meet).
    fn planar_facts(&self, halves: &Pieces) -> Vec<PieceFacts> {
        (0..self.range.len())
            .map(|i| {
                let width = self.range[i].hi - self.range[i].lo;
                let mid = halves.net(2 * i + 1).projected(0);
                mid.zip(self.net(i).velocity_hull(width))
            })
            .collect()
    }

    /// The whole planar curve's control boxes as `[x, y, w]`.
    fn planar(&self) -> Vec<[Interval; 3]> {
        let net = self.net(0);
        (0..self.len).map(|i| net.homogeneous(i)).collect()
    }
}

/// The certified crossings when interval arithmetic decides every box
/// pair of a subdivision (separated hulls, or a Krawczyk verdict in the
/// plane), `None` when some pair stays undecided. The halves and the
/// planar facts of a level are computed only when a pair survives the
/// boxes.
fn decide(
    a: &RationalCurve<BigRational>,
    b: &RationalCurve<BigRational>,
) -> Option<Vec<CertifiedCrossing>> {
    let (mut pa, mut pb) = (Pieces::whole(a), Pieces::whole(b));
    let dim = pa.dim();
    let curves = (dim == 2).then(|| (pa.planar(), pb.planar()));
    let mut pairs = vec![(0, 0)];
    let mut found = Vec::new();
    for _ in 0..FILTER_DEPTH {
        let (ba, bb) = (pa.bounding_boxes()?, pb.bounding_boxes()?);
        pairs.retain(|&(i, j)| {
            let (x, y) = (&ba[i * dim..(i + 1) * dim], &bb[j * dim..(j + 1) * dim]);
            !x.iter().zip(y).any(|(u, v)| u.disjoint(v))
        });
        if pairs.is_empty() {
            return Some(found);
        }
        let (ha, hb) = (pa.halves(), pb.halves());
        let facts = curves
            .as_ref()
            .map(|_| (pa.planar_facts(&ha), pb.planar_facts(&hb)));
        let mut next = Vec::with_capacity(4 * pairs.len());
        for &(i, j) in &pairs {
            if let (Some((ca, cb)), Some((fa, fb))) = (&curves, &facts) {
                let x = [pa.range[i], pb.range[j]];
                match krawczyk_pair(x, fa[i], fb[j]) {
                    Krawczyk::Unique(_) => {
                        found.push(crossing(ca, cb, contract(ca, cb, x))?);
                        continue;
                    }
                    Krawczyk::None => continue,
                    Krawczyk::Unknown => {}
                }
            }
            next.extend([(2 * i, 2 * j), (2 * i, 2 * j + 1)]);
            next.extend([(2 * i + 1, 2 * j), (2 * i + 1, 2 * j + 1)]);
        }
        if next.is_empty() {
            return Some(found);
        }
        if next.len() > FILTER_PAIRS {
            return None;
        }
        let (keep_a, keep_b) = (renumber(&mut next, 0), renumber(&mut next, 1));
        (pa, pb, pairs) = (ha.select(&keep_a), hb.select(&keep_b), next);
    }
    None
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

/// The Krawczyk test on the parameter box `x` of two pieces, from their
/// midpoint and velocity enclosures ([`Facts`]).
fn krawczyk_pair(x: [Interval; 2], a: PieceFacts, b: PieceFacts) -> Krawczyk {
    let (Some((ma, va)), Some((mb, vb))) = (a, b) else {
        return Krawczyk::Unknown;
    };
    let c = x.map(|r| 0.5 * (r.lo + r.hi));
    let f = [ma[0].sub(&mb[0]), ma[1].sub(&mb[1])];
    krawczyk(x, c, f, jacobian(va, vb))
}

/// The crossing in the certified box `x`, with the point box `A(S) ∩ B(T)`.
fn crossing(a: &PlanarBoxes, b: &PlanarBoxes, x: [Interval; 2]) -> Option<CertifiedCrossing> {
    let (pa, _) = point_and_velocity(a, x[0])?;
    let (pb, _) = point_and_velocity(b, x[1])?;
    Some(CertifiedCrossing {
        s: x[0],
        t: x[1],
        point: pa
            .iter()
            .zip(&pb)
            .map(|(u, v)| Interval {
                lo: u.lo.max(v.lo),
                hi: u.hi.min(v.hi),
            })
            .collect(),
    })
}

/// The interval stage of [`intersect`](super::intersect) (`Filter::First`,
/// `Filter::Only`): `Some(crossings)` when `f64` interval arithmetic decides
/// the pair — curves separated by hulls of subdivided control polygons
/// (empty), or, in the plane, transversal crossings certified by the
/// Krawczyk test (module `certify`) and no other common point — `None`
/// when the exact elimination is needed (tangencies, overlaps,
/// intersections at curve ends or on a dyadic split line, curves in 3D
/// that come close, or curves not of one dimension ≥ 2). Its cost is
/// bounded whatever the degrees: at most 16 levels of 1024 piece pairs,
/// each piece of a level split once by interval de Casteljau.
pub(crate) fn certify_crossings(
    a: &RationalCurve<BigRational>,
    b: &RationalCurve<BigRational>,
) -> Result<Option<Vec<CertifiedCrossing>>, Error> {
    if a.dim() != b.dim() || a.dim() < 2 {
        return Ok(None);
    }
    a.check_positive_weights()?;
    b.check_positive_weights()?;
    Ok(decide(a, b))
}
