//! A filtered exact coincidence predicate: decide with `f64` interval
//! bounds first, fall back to exact arithmetic only when they cannot.
//!
//! [`Interval`] is closed interval arithmetic on `f64` with outward rounding
//! (each result widened by one ulp on each side, which contains the
//! correctly rounded result's error), so an interval always encloses the
//! exact value of the rational expression it stands for. Two quantities
//! whose intervals are disjoint are certainly different — that is an exact
//! conclusion. Equality can never be certified by intervals; it goes to the
//! exact path.
//!
//! [`filtered`] stages:
//! 1. corner points (intrinsic to the parametric map, so valid before any
//!    reduction) under every symmetry;
//! 2. if both nets are certified minimal modulo p (exact, cheap), control
//!    points and weight invariants under every admissible symmetry;
//! 3. otherwise, or when a symmetry survives, the exact decision.
//!
//! Reference: the filtered-predicate design of CGAL (Brönnimann, Burnikel,
//! Pion, "Interval arithmetic yields efficient dynamic filters for
//! computational geometry", 2001).

use crate::algebra::interval::Interval;
use crate::coincide::minimal::{certified_minimal, Net};
use crate::coincide::{exact_nets, Coincidence, DecidedBy, ReductionInfo, Symmetry};
use crate::hpoint::HPoint;
use num_rational::BigRational;

/// Interval images of one row of a net: Cartesian points and weights.
type RowBounds = (Vec<Option<Vec<Interval>>>, Vec<Interval>);

/// Interval images of a net: Cartesian points `P_{i,j}` and weights.
struct Bounds {
    points: Vec<Vec<Option<Vec<Interval>>>>,
    weights: Vec<Vec<Interval>>,
}

fn cartesian(h: &HPoint<BigRational>) -> (Option<Vec<Interval>>, Interval) {
    let w = Interval::enclose(h.weight());
    let p = h
        .weighted()
        .iter()
        .map(|x| Interval::enclose(x).div(&w))
        .collect();
    (p, w)
}

impl Bounds {
    fn new(net: &Net<BigRational>) -> Bounds {
        let rows: Vec<RowBounds> = net
            .iter()
            .map(|row| row.iter().map(cartesian).unzip())
            .collect();
        let (points, weights) = rows.into_iter().unzip();
        Bounds { points, weights }
    }

    fn dims(&self) -> (usize, usize) {
        (self.points.len() - 1, self.points[0].len() - 1)
    }

    /// Original position of position (i, j) of `sym` applied to this net.
    fn src(&self, sym: Symmetry, i: usize, j: usize) -> (usize, usize) {
        let (m, n) = self.dims();
        let (tm, tn) = if sym.swap { (n, m) } else { (m, n) };
        let i1 = if sym.reverse_u { tm - i } else { i };
        let j1 = if sym.reverse_v { tn - j } else { j };
        if sym.swap {
            (j1, i1)
        } else {
            (i1, j1)
        }
    }

    fn point(&self, sym: Symmetry, i: usize, j: usize) -> Option<&Vec<Interval>> {
        let (a, b) = self.src(sym, i, j);
        self.points[a][b].as_ref()
    }

    /// `I_{i,j} = ω_{i,j} ω_{0,0}^{i+j−1} / (ω_{1,0}^i ω_{0,1}^j)` of the
    /// transformed net (positive weights).
    fn invariant(&self, sym: Symmetry, i: usize, j: usize) -> Option<Interval> {
        let w = |i: usize, j: usize| {
            let (a, b) = self.src(sym, i, j);
            self.weights[a][b]
        };
        let e = i + j;
        let num = w(i, j).mul(&w(0, 0).pow(e as u32));
        let den = w(0, 0)
            .mul(&w(1.min(self.tdims(sym).0), 0).pow(i as u32))
            .mul(&w(0, 1.min(self.tdims(sym).1)).pow(j as u32));
        num.div(&den)
    }

    fn tdims(&self, sym: Symmetry) -> (usize, usize) {
        let (m, n) = self.dims();
        if sym.swap {
            (n, m)
        } else {
            (m, n)
        }
    }
}

fn points_disjoint(p: Option<&Vec<Interval>>, q: Option<&Vec<Interval>>) -> bool {
    match (p, q) {
        (Some(p), Some(q)) => p.iter().zip(q).any(|(x, y)| x.disjoint(y)),
        _ => false,
    }
}

/// Stage 1: under `sym`, do the corner points of a and b certainly differ?
fn corners_differ(a: &Bounds, b: &Bounds, sym: Symmetry) -> bool {
    let (am, an) = a.tdims(sym);
    let (bm, bn) = b.dims();
    [(0, 0), (1, 0), (0, 1), (1, 1)].iter().any(|&(cu, cv)| {
        points_disjoint(
            a.point(sym, cu * am, cv * an),
            b.point(Symmetry::IDENTITY, cu * bm, cv * bn),
        )
    })
}

/// Stage 2: under `sym` (same shape), does a control point or an invariant
/// certainly differ? Returns the first such difference.
fn net_differs(a: &Bounds, b: &Bounds, sym: Symmetry) -> Option<String> {
    let (m, n) = b.dims();
    let id = Symmetry::IDENTITY;
    let positions = || (0..=m).flat_map(move |i| (0..=n).map(move |j| (i, j)));
    if let Some((i, j)) =
        positions().find(|&(i, j)| points_disjoint(a.point(sym, i, j), b.point(id, i, j)))
    {
        return Some(format!("control point P_{{{i},{j}}} differs"));
    }
    positions()
        .find(
            |&(i, j)| match (a.invariant(sym, i, j), b.invariant(id, i, j)) {
                (Some(x), Some(y)) => x.disjoint(&y),
                _ => false,
            },
        )
        .map(|(i, j)| format!("weight invariant I_{{{i},{j}}} differs"))
}

fn not_coincident(
    reason: String,
    a: &Net<BigRational>,
    b: &Net<BigRational>,
    decided_by: DecidedBy,
) -> Coincidence<BigRational> {
    let info = |n: &Net<BigRational>| ReductionInfo {
        from: (n.len() - 1, n[0].len() - 1),
        to: (n.len() - 1, n[0].len() - 1),
        common_factor: "1".into(),
    };
    Coincidence {
        coincident: false,
        reason,
        witness: None,
        reductions: [info(a), info(b)],
        decided_by,
    }
}

/// The exact coincidence decision for two nets of one kind, filtered:
/// the same answer, decided by `f64` interval bounds when they can (only
/// "not coincident" can be certified that way), by exact arithmetic
/// otherwise. The reductions reported when an interval stage decides are
/// those known at that point (none before stage 2).
pub(crate) fn filtered(
    na: &Net<BigRational>,
    nb: &Net<BigRational>,
    curve: bool,
) -> Coincidence<BigRational> {
    let (ba, bb) = (Bounds::new(na), Bounds::new(nb));
    let syms: Vec<Symmetry> = Symmetry::all()
        .filter(|s| !curve || (!s.swap && !s.reverse_v))
        .collect();
    if syms.iter().all(|&s| corners_differ(&ba, &bb, s)) {
        let reason = format!(
            "corner points differ under all {} symmetries (interval bounds)",
            syms.len()
        );
        return not_coincident(reason, na, nb, DecidedBy::Corners);
    }
    if certified_minimal(na) && certified_minimal(nb) {
        let admissible: Vec<Symmetry> = Symmetry::admissible(curve, ba.dims(), bb.dims()).collect();
        let reasons: Vec<Option<String>> = admissible
            .iter()
            .map(|&s| net_differs(&ba, &bb, s))
            .collect();
        if reasons.iter().all(Option::is_some) {
            let reason = match reasons.into_iter().next() {
                Some(Some(r)) => format!(
                    "{r} (interval bounds, best of {} symmetries)",
                    admissible.len()
                ),
                _ => format!(
                    "minimal (bi)degrees differ: {:?} vs {:?}",
                    ba.dims(),
                    bb.dims()
                ),
            };
            return not_coincident(reason, na, nb, DecidedBy::Intervals);
        }
    }
    exact_nets(na, nb, curve)
}
