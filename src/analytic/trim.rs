//! [`trim_between`]: the part of a curve (exact rational Bézier pieces)
//! between two vertices of a STEP edge, split exactly.
//!
//! A vertex's coordinates are decimals rounded by the CAD system: they lie
//! on the curve only within the model's tolerance. Each vertex is located
//! on the pieces by an `f64` search (a heuristic only: 33 samples per piece,
//! then 60 halvings of a local step); the parameter found is replaced by
//! the nearest dyadic rational `m/2⁴⁰`, and everything after is exact: the
//! pieces are split there by the blossom ([`RationalCurve::subsegment`],
//! no new roots), and the squared distance between the vertex and the
//! chosen curve point is computed in `T`, for the caller to compare with
//! the tolerance exactly.

use super::{dot, sub};
use crate::algebra::scalar::{Field, Ordered};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::eval::Evaluator;
use crate::hpoint::HPoint;
use crate::Tolerance;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;

/// The trimmed edge: sub-pieces in the edge's direction and, for each
/// vertex, where it was located and how far it is from the curve point
/// chosen.
#[derive(Clone, Debug, PartialEq)]
pub struct Trimmed<T> {
    /// The exact sub-pieces, from the start vertex to the end vertex.
    pub pieces: Vec<RationalCurve<T>>,
    /// The curve point taken for the start vertex (the first piece's start).
    pub start: Vec<T>,
    /// The curve point taken for the end vertex (the last piece's end).
    pub end: Vec<T>,
    /// `|start vertex − start|²`, exact.
    pub start_distance_sq: T,
    /// `|end vertex − end|²`, exact.
    pub end_distance_sq: T,
    /// `(piece, t)` of the start in the pieces in edge direction (the
    /// given pieces, or their reversal when `same_sense` is false).
    pub start_at: (usize, T),
    /// `(piece, t)` of the end, likewise.
    pub end_at: (usize, T),
}

/// The part of the curve `pieces` (consecutive, each on `[0, 1]`) from the
/// vertex `start` to the vertex `end`, following the curve when
/// `same_sense` and against it otherwise. `start == end` (exactly) is a
/// closed edge: the whole curve, starting at the vertex. When the end comes
/// before the start, the path wraps through the curve's end (a closed
/// curve). `snap` (an `f64` distance, visible here) takes a vertex at a
/// piece's end point when that end is within `snap` of the best point found,
/// so that no sliver piece appears.
///
/// # Errors
///
/// [`Error::Shape`] for no pieces or points of another dimension;
/// [`Error::Domain`] when the path must wrap but the curve is not closed
/// (its last point is not exactly its first); [`Error::PointAtInfinity`]
/// for a zero weight where a point is evaluated.
///
/// ```
/// use exact_bezier::{analytic::{circle, trim_between, Frame}, ratio, BigRational};
/// let q = |n: i64, d: i64| ratio::<BigRational>(n, d);
/// let f = Frame::from_axes(vec![q(0, 1); 3], vec![q(1, 1), q(0, 1), q(0, 1)], vec![q(0, 1), q(0, 1), q(1, 1)]);
/// let arcs = circle(&f, &q(1, 1));
/// // From (1, 0, 0) to (0, 1, 0): the first quarter arc.
/// let t = trim_between(&arcs, &[q(1, 1), q(0, 1), q(0, 1)], &[q(0, 1), q(1, 1), q(0, 1)], true, 1e-9).unwrap();
/// assert_eq!(t.pieces, vec![arcs[0].clone()]);
/// assert_eq!(t.end_distance_sq, q(0, 1));
/// ```
pub fn trim_between<T: Field + Ordered>(
    pieces: &[RationalCurve<T>],
    start: &[T],
    end: &[T],
    same_sense: bool,
    snap: f64,
) -> Result<Trimmed<T>, Error> {
    if pieces.is_empty() {
        return Err(Error::Shape("no curve pieces to trim".into()));
    }
    let dim = pieces[0].dim();
    if start.len() != dim || end.len() != dim || pieces.iter().any(|c| c.dim() != dim) {
        return Err(Error::Shape(format!(
            "vertices and pieces must all be {dim}D"
        )));
    }
    let work: Vec<RationalCurve<T>> = if same_sense {
        pieces.to_vec()
    } else {
        pieces.iter().rev().map(RationalCurve::reverse).collect()
    };
    let mut approx = to_f64_pieces(&work);
    let (ks, ts) = locate_in(&mut approx, start, snap);
    let (ke, te) = if start == end {
        (ks, ts.clone())
    } else {
        locate_in(&mut approx, end, snap)
    };
    let out = split_between(&work, (ks, &ts), (ke, &te), start == end)?;
    let start_pt = point_at(&work[ks], &ts, out.first().map(|c| &c.ctrl()[0]))?;
    let end_pt = point_at(&work[ke], &te, out.last().and_then(|c| c.ctrl().last()))?;
    Ok(Trimmed {
        pieces: out,
        start_distance_sq: dist_sq(start, &start_pt),
        end_distance_sq: dist_sq(end, &end_pt),
        start: start_pt,
        end: end_pt,
        start_at: (ks, ts),
        end_at: (ke, te),
    })
}

/// The point of `piece` at `t`: an end control point for `t` = 0 or 1,
/// else `cut`, the end of the sub-piece [`split_between`] cut at `t` (the
/// blossom `b(t, …, t)`, the same exact point), or by evaluation without one.
fn point_at<T: Field>(
    piece: &RationalCurve<T>,
    t: &T,
    cut: Option<&HPoint<T>>,
) -> Result<Vec<T>, Error> {
    let ctrl = piece.ctrl();
    let end = if t.is_zero() {
        ctrl.first()
    } else if t.is_one() {
        ctrl.last()
    } else {
        cut
    };
    match end {
        Some(h) => h.project(),
        None => piece.eval(t),
    }
}

fn dist_sq<T: Field>(a: &[T], b: &[T]) -> T {
    let d = sub(a, b);
    dot(&d, &d)
}

/// The exact sub-pieces of `pieces` from the position `from = (piece, t)`
/// to `to`, following the pieces' order; when `to` comes before `from`, or
/// `whole` (a closed edge from a vertex back to it), the path wraps through
/// the end of the last piece to the start of the first. Each sub-piece is
/// [`RationalCurve::subsegment`] (exact, the blossom at rational
/// parameters); zero-length spans are dropped.
///
/// # Errors
///
/// [`Error::Domain`] when the path must wrap but the curve is not closed
/// (its last point is not exactly its first), or a position is out of range.
pub fn split_between<T: Field + Ordered>(
    pieces: &[RationalCurve<T>],
    from: (usize, &T),
    to: (usize, &T),
    whole: bool,
) -> Result<Vec<RationalCurve<T>>, Error> {
    let ((ks, ts), (ke, te)) = (from, to);
    let n = pieces.len();
    let (zero, one) = (T::zero(), T::one());
    let inside = |t: &T| *t >= zero && *t <= one;
    if ks >= n || ke >= n || !inside(ts) || !inside(te) {
        return Err(Error::Domain(format!(
            "a position outside the {n} pieces and [0, 1]"
        )));
    }
    let forward = !whole && (ks < ke || (ks == ke && ts <= te));
    let mut spans: Vec<(usize, T, T)> = Vec::new();
    if forward && ks == ke {
        spans.push((ks, ts.clone(), te.clone()));
    } else {
        if !forward && !is_closed(pieces) {
            return Err(Error::Domain(
                "the end comes before the start on an open curve".into(),
            ));
        }
        spans.push((ks, ts.clone(), one.clone()));
        let middle: Vec<usize> = if forward {
            (ks + 1..ke).collect()
        } else {
            (ks + 1..n).chain(0..ke).collect()
        };
        spans.extend(middle.into_iter().map(|k| (k, zero.clone(), one.clone())));
        spans.push((ke, zero.clone(), te.clone()));
    }
    Ok(spans
        .into_iter()
        .filter(|(_, a, b)| a != b)
        .map(|(k, a, b)| {
            if a == zero && b == one {
                pieces[k].clone()
            } else {
                pieces[k].subsegment(&a, &b)
            }
        })
        .collect())
}

/// Does the last piece end exactly where the first begins?
fn is_closed<T: Field>(pieces: &[RationalCurve<T>]) -> bool {
    let first: &HPoint<T> = &pieces[0].ctrl()[0];
    let last = pieces[pieces.len() - 1]
        .ctrl()
        .last()
        .expect("a piece has points");
    first.same_projective_point(last, Tolerance::EXACT)
}

/// `(piece, t)` of the point of `pieces` nearest `p` by an `f64` search
/// (a heuristic: 33 samples per piece, then a halving local search), with
/// `t` the dyadic rational `m/2⁴⁰` nearest the parameter found; a piece end
/// within `snap` of the best point found is preferred (no sliver pieces).
pub fn locate_vertex<T: Field + Ordered>(
    pieces: &[RationalCurve<T>],
    p: &[T],
    snap: f64,
) -> (usize, T) {
    locate_in(&mut to_f64_pieces(pieces), p, snap)
}

/// The pieces rounded to `f64`, as evaluators for [`locate_in`]'s search
/// (which evaluates each piece about 150 times: one evaluator each, no
/// allocation per point).
fn to_f64_pieces<T: Ordered>(pieces: &[RationalCurve<T>]) -> Vec<Evaluator<f64>> {
    pieces
        .iter()
        .map(|c| Evaluator::curve(&c.map(Ordered::to_f64)))
        .collect()
}

/// [`locate_vertex`] on the pieces already rounded to `f64` (a trimmed
/// edge locates both its vertices on one rounding).
fn locate_in<T: Field + Ordered>(approx: &mut [Evaluator<f64>], p: &[T], snap: f64) -> (usize, T) {
    let pf: Vec<f64> = p.iter().map(Ordered::to_f64).collect();
    let mut x = vec![0.0; pf.len()];
    let mut best = (0, 0.0, f64::INFINITY);
    let mut ends = Vec::new();
    for (k, ev) in approx.iter_mut().enumerate() {
        let mut d = |t: f64| match ev.eval_into(&[t], &mut x) {
            Ok(()) => dist2(&x, &pf),
            Err(_) => f64::INFINITY,
        };
        let (t, dt) = nearest(&mut d);
        if dt < best.2 {
            best = (k, t, dt);
        }
        ends.push((k, 0.0, d(0.0)));
        ends.push((k, 1.0, d(1.0)));
    }
    let reach = (best.2.sqrt() + snap).powi(2);
    let (k, t) = ends
        .into_iter()
        .filter(|e| e.2 <= reach)
        .min_by(|a, b| a.2.total_cmp(&b.2))
        .map_or((best.0, best.1), |e| (e.0, e.1));
    (k, T::from_rational(&dyadic(t)))
}

/// The minimum of `d` on `[0, 1]`: the best of 33 samples, then 60 steps
/// of a halving local search.
fn nearest(d: &mut dyn FnMut(f64) -> f64) -> (f64, f64) {
    let mut best = (0..=32)
        .map(|i| f64::from(i) / 32.0)
        .map(|t| (t, d(t)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("33 samples");
    let mut h = 1.0 / 32.0;
    for _ in 0..60 {
        for t in [best.0 - h, best.0 + h] {
            let t = t.clamp(0.0, 1.0);
            let dt = d(t);
            if dt < best.1 {
                best = (t, dt);
            }
        }
        h /= 2.0;
    }
    best
}

fn dist2(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y) * (x - y)).sum()
}

/// The dyadic rational `round(t·2⁴⁰)/2⁴⁰` (t in [0, 1]).
pub(crate) fn dyadic(t: f64) -> BigRational {
    let scale = (1u64 << 40) as f64;
    let m = (t.clamp(0.0, 1.0) * scale).round() as i64;
    BigRational::new(BigInt::from(m), BigInt::one() << 40)
}
