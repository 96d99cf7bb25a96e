//! The rigorous interval filter in front of the exact intersection.
//!
//! The control polygons are subdivided at `1/2` in interval arithmetic
//! with outward rounding ([`Interval`]); by the convex hull property
//! (positive weights), each piece lies in the box of its projected control
//! points. The subdivision runs level by level (module `pieces`, shared
//! with the `f64` path): each piece of a level is halved once, whatever the number of pairs it is in, and its bounding
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
use super::pieces::{subdivide, Pieces, Policy, Stop};
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

/// The whole curve's control points enclosed, as one [`Pieces`]; a curve
/// with equal weights is divided by them exactly first (`W ≡ 1`).
fn whole(c: &RationalCurve<BigRational>) -> Pieces<Interval> {
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
    Pieces::whole(ctrl, dim + usize::from(weighted), weighted)
}

/// The control boxes of piece `i`, flat.
fn net(p: &Pieces<Interval>, i: usize) -> Net<'_> {
    Net {
        ctrl: p.piece(i),
        stride: p.stride,
        weighted: p.weighted,
    }
}

/// Enclosures of a planar piece's point at the middle of its range and of
/// its velocity over the range (`None` when a weight box contains 0).
type PieceFacts = Option<([Interval; 2], [Interval; 2])>;

/// The midpoint and velocity enclosures of the planar pieces `p`, `halves`
/// being `p.halves()` (the midpoint is where the halves meet).
fn planar_facts(p: &Pieces<Interval>, halves: &Pieces<Interval>) -> Vec<PieceFacts> {
    (0..p.range.len())
        .map(|i| {
            let width = p.range[i].hi - p.range[i].lo;
            let mid = net(halves, 2 * i + 1).projected(0);
            mid.zip(net(p, i).velocity_hull(width))
        })
        .collect()
}

/// A planar control point's boxes `[x, y, w]` (homogeneous).
type PlanarPoint = [Interval; 3];

/// The whole planar curve's control boxes.
fn planar(p: &Pieces<Interval>) -> Vec<PlanarPoint> {
    let n = net(p, 0);
    (0..p.len).map(|i| n.homogeneous(i)).collect()
}

/// The filter's [`Policy`]: pairs with disjoint boxes are dropped; in the
/// plane, a pair is settled when the Krawczyk test certifies a unique
/// crossing in its parameter box (recorded) or excludes one.
struct Decide {
    dim: usize,
    /// The whole planar curves (for the crossings' boxes), `None` off the plane.
    curves: Option<(Vec<PlanarPoint>, Vec<PlanarPoint>)>,
    /// The planar facts of the level's pieces.
    facts: (Vec<PieceFacts>, Vec<PieceFacts>),
    found: Vec<CertifiedCrossing>,
}

impl Policy<Interval> for Decide {
    fn sift(
        &mut self,
        a: &Pieces<Interval>,
        b: &Pieces<Interval>,
        pairs: &mut Vec<(usize, usize)>,
    ) -> Result<(), Stop> {
        let dim = self.dim;
        let (ba, bb) = (a.bounding_boxes(), b.bounding_boxes());
        let (Some(ba), Some(bb)) = (ba, bb) else {
            return Err(Stop::Refused);
        };
        pairs.retain(|&(i, j)| {
            let (x, y) = (&ba[i * dim..(i + 1) * dim], &bb[j * dim..(j + 1) * dim]);
            !x.iter().zip(y).any(|(u, v)| u.disjoint(v))
        });
        Ok(())
    }

    /// The planar facts of the level's pieces.
    fn prepare(&mut self, [a, b, ha, hb]: [&Pieces<Interval>; 4]) -> Result<(), Stop> {
        if self.curves.is_some() {
            self.facts = (planar_facts(a, ha), planar_facts(b, hb));
        }
        Ok(())
    }

    fn settle(
        &mut self,
        a: &Pieces<Interval>,
        b: &Pieces<Interval>,
        (i, j): (usize, usize),
    ) -> Result<bool, Stop> {
        let Some((ca, cb)) = &self.curves else {
            return Ok(false);
        };
        let x = [a.range[i], b.range[j]];
        match krawczyk_pair(x, self.facts.0[i], self.facts.1[j]) {
            Krawczyk::Unique(_) => {
                let found = crossing(ca, cb, contract(ca, cb, x)).ok_or(Stop::Refused)?;
                self.found.push(found);
                Ok(true)
            }
            Krawczyk::None => Ok(true),
            Krawczyk::Unknown => Ok(false),
        }
    }
}

/// The certified crossings when interval arithmetic decides every box
/// pair of a subdivision (separated hulls, or a Krawczyk verdict in the
/// plane) within 16 levels of 1024 pairs, `None` when some pair stays
/// undecided.
fn decide(
    a: &RationalCurve<BigRational>,
    b: &RationalCurve<BigRational>,
) -> Option<Vec<CertifiedCrossing>> {
    let (pa, pb) = (whole(a), whole(b));
    let mut policy = Decide {
        dim: pa.dim(),
        curves: (pa.dim() == 2).then(|| (planar(&pa), planar(&pb))),
        facts: (Vec::new(), Vec::new()),
        found: Vec::new(),
    };
    subdivide(pa, pb, &mut policy, FILTER_DEPTH, FILTER_PAIRS).ok()?;
    Some(policy.found)
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
