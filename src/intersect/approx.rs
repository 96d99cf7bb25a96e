//! The approximate `f64` intersection with a caller's tolerance: the
//! control polygons are subdivided in plain `f64` down to pieces whose
//! boxes are below the tolerance, Newton steps on `A(s) − B(t)` run from
//! each surviving cluster of piece pairs, and the results are clustered in
//! `(s, t)`.

use crate::curve::RationalCurve;
use crate::error::Error;

/// An approximate intersection: the `f64` answer of [`intersect`](super::intersect).
#[derive(Clone, Debug, PartialEq)]
pub struct ApproxIntersection {
    /// Parameter on the first curve (for an overlap, its start).
    pub s: f64,
    /// Parameter on the second curve (for an overlap, its start).
    pub t: f64,
    /// `A(s)`.
    pub point: Vec<f64>,
    /// `|A(s) − B(t)|` after refinement (≤ the tolerance).
    pub distance: f64,
    /// For a suspected overlap, the parameter ranges `(s0, s1, t0, t1)` of
    /// the cluster of close pieces; `None` for an isolated point.
    pub overlap: Option<[f64; 4]>,
}

/// A curve piece in `f64`: its homogeneous control points and parameter
/// range.
#[derive(Clone)]
struct Piece {
    ctrl: Vec<Vec<f64>>,
    lo: f64,
    hi: f64,
}

impl Piece {
    fn halves(&self) -> (Piece, Piece) {
        let mut rows = self.ctrl.clone();
        let (mut left, mut right) = (vec![rows[0].clone()], vec![rows[rows.len() - 1].clone()]);
        while rows.len() > 1 {
            rows = rows
                .windows(2)
                .map(|w| w[0].iter().zip(&w[1]).map(|(a, b)| 0.5 * (a + b)).collect())
                .collect();
            left.push(rows[0].clone());
            right.push(rows[rows.len() - 1].clone());
        }
        right.reverse();
        let mid = 0.5 * (self.lo + self.hi);
        (
            Piece {
                ctrl: left,
                lo: self.lo,
                hi: mid,
            },
            Piece {
                ctrl: right,
                lo: mid,
                hi: self.hi,
            },
        )
    }

    /// `(min, max)` per coordinate of the projected control points.
    fn bounds(&self) -> Vec<(f64, f64)> {
        let dim = self.ctrl[0].len() - 1;
        (0..dim)
            .map(|k| {
                self.ctrl
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), h| {
                        let x = h[k] / h[dim];
                        (lo.min(x), hi.max(x))
                    })
            })
            .collect()
    }
}

fn piece(c: &RationalCurve<f64>) -> Piece {
    Piece {
        ctrl: c.ctrl().iter().map(|h| h.coords.clone()).collect(),
        lo: 0.0,
        hi: 1.0,
    }
}

/// Newton steps (least squares in 3D and above) on `A(s) − B(t) = 0`.
fn refine(a: &RationalCurve<f64>, b: &RationalCurve<f64>, mut s: f64, mut t: f64) -> (f64, f64) {
    for _ in 0..20 {
        let (Ok(da), Ok(db)) = (a.derivs(&s, 1), b.derivs(&t, 1)) else {
            break;
        };
        let r: Vec<f64> = da[0].iter().zip(&db[0]).map(|(x, y)| x - y).collect();
        // J = [A'(s), −B'(t)]; normal equations JᵀJ δ = −Jᵀr.
        let dot = |u: &[f64], v: &[f64]| u.iter().zip(v).map(|(x, y)| x * y).sum::<f64>();
        let (aa, ab, bb) = (
            dot(&da[1], &da[1]),
            -dot(&da[1], &db[1]),
            dot(&db[1], &db[1]),
        );
        let (ra, rb) = (-dot(&da[1], &r), dot(&db[1], &r));
        let det = aa * bb - ab * ab;
        if det.abs() <= f64::EPSILON * aa * bb || !det.is_finite() {
            break;
        }
        let (ds, dt) = ((ra * bb - ab * rb) / det, (aa * rb - ab * ra) / det);
        s = (s + ds).clamp(0.0, 1.0);
        t = (t + dt).clamp(0.0, 1.0);
        if ds.abs() + dt.abs() < 1e-16 {
            break;
        }
    }
    (s, t)
}

/// The most leaf pairs the approximate path keeps before refusing.
const APPROX_PAIRS: usize = 100_000;
/// A cluster of more leaves than this is reported as a suspected overlap.
const OVERLAP_LEAVES: usize = 64;

/// Intersections in `f64` within the tolerance `tol` (absolute, in model
/// units): subdivision to pieces of size `L = max(tol, √(tol·D))` (`D` the
/// diameter of both curves' boxes), Newton refinement from each cluster of
/// touching piece pairs, kept when `|A(s) − B(t)| ≤ tol`. A cluster of more
/// than 64 piece pairs is reported as a suspected overlap with its
/// parameter ranges (a heuristic: the exact path decides overlaps).
///
/// # Errors
///
/// [`Error::Domain`] for a tolerance that is not finite and positive,
/// [`Error::Shape`] for different dimensions, [`Error::Weight`] for
/// non-positive weights, [`Error::Limit`] when more than 100 000 piece
/// pairs stay close.
pub(crate) fn intersect_approx(
    a: &RationalCurve<f64>,
    b: &RationalCurve<f64>,
    tol: f64,
) -> Result<Vec<ApproxIntersection>, Error> {
    if !(tol.is_finite() && tol > 0.0) {
        return Err(Error::Domain(format!(
            "the tolerance {tol} must be finite and > 0"
        )));
    }
    if a.dim() != b.dim() {
        return Err(Error::Shape(format!(
            "the curves have dimensions {} and {}",
            a.dim(),
            b.dim()
        )));
    }
    a.check_positive_weights()?;
    b.check_positive_weights()?;
    let (pa, pb) = (piece(a), piece(b));
    let diameter = pa
        .bounds()
        .iter()
        .zip(pb.bounds())
        .map(|(x, y)| (x.1.max(y.1) - x.0.min(y.0)).powi(2))
        .sum::<f64>()
        .sqrt();
    let leaf = tol.max((tol * diameter).sqrt());
    let leaves = close_leaves(pa, pb, tol, leaf)?;
    let found = clusters(&leaves)
        .into_iter()
        .filter_map(|c| cluster_result(a, b, &c, tol).map(|x| (x, c.range)))
        .collect();
    Ok(distinct(found))
}

/// Drop an intersection that Newton refined onto the root of an earlier
/// one — two clusters that do not touch can still converge to one root —
/// judged in parameters, at the resolution of the search: `s` and `t`
/// each within the wider of the two clusters' extents. Overlaps are kept.
fn distinct(found: Vec<(ApproxIntersection, [f64; 4])>) -> Vec<ApproxIntersection> {
    let mut kept: Vec<(ApproxIntersection, [f64; 4])> = Vec::new();
    for (x, r) in found {
        let same = |(y, q): &(ApproxIntersection, [f64; 4])| {
            let near = |d: f64, w: f64| d.abs() <= w;
            x.overlap.is_none()
                && y.overlap.is_none()
                && near(x.s - y.s, (r[1] - r[0]).max(q[1] - q[0]))
                && near(x.t - y.t, (r[3] - r[2]).max(q[3] - q[2]))
        };
        if !kept.iter().any(same) {
            kept.push((x, r));
        }
    }
    kept.into_iter().map(|(x, _)| x).collect()
}

/// Leaf pairs `(s0, s1, t0, t1)` whose boxes stay within `tol` of each
/// other, subdivided to box diagonals of at most `leaf`.
fn close_leaves(a: Piece, b: Piece, tol: f64, leaf: f64) -> Result<Vec<[f64; 4]>, Error> {
    let near = |x: &[(f64, f64)], y: &[(f64, f64)]| {
        x.iter()
            .zip(y)
            .all(|(p, q)| p.0 <= q.1 + tol && q.0 <= p.1 + tol)
    };
    let small = |x: &[(f64, f64)]| {
        x.iter()
            .map(|(lo, hi)| (hi - lo).powi(2))
            .sum::<f64>()
            .sqrt()
            <= leaf
    };
    let mut stack = vec![(a, b)];
    let mut leaves = Vec::new();
    while let Some((pa, pb)) = stack.pop() {
        let (ba, bb) = (pa.bounds(), pb.bounds());
        if !near(&ba, &bb) {
            continue;
        }
        let splittable = pa.hi - pa.lo > f64::EPSILON && pb.hi - pb.lo > f64::EPSILON;
        if (small(&ba) && small(&bb)) || !splittable {
            leaves.push([pa.lo, pa.hi, pb.lo, pb.hi]);
            if leaves.len() > APPROX_PAIRS {
                return Err(Error::Limit(format!(
                    "over {APPROX_PAIRS} piece pairs within {tol} of each other: use the exact path"
                )));
            }
            continue;
        }
        let (a0, a1) = pa.halves();
        let (b0, b1) = pb.halves();
        stack.extend([
            (a0.clone(), b0.clone()),
            (a0, b1.clone()),
            (a1.clone(), b0),
            (a1, b1),
        ]);
    }
    Ok(leaves)
}

/// A group of touching leaves: its parameter rectangle and leaf count.
struct Cluster {
    range: [f64; 4],
    leaves: usize,
}

/// Group leaves whose parameter rectangles touch (merging as they come).
fn clusters(leaves: &[[f64; 4]]) -> Vec<Cluster> {
    let touch =
        |x: &[f64; 4], y: &[f64; 4]| x[0] <= y[1] && y[0] <= x[1] && x[2] <= y[3] && y[2] <= x[3];
    let mut groups: Vec<Cluster> = Vec::new();
    for leaf in leaves {
        let mut merged = Cluster {
            range: *leaf,
            leaves: 1,
        };
        groups.retain(|g| {
            if touch(&g.range, &merged.range) {
                let (x, y) = (&g.range, &merged.range);
                merged.range = [
                    x[0].min(y[0]),
                    x[1].max(y[1]),
                    x[2].min(y[2]),
                    x[3].max(y[3]),
                ];
                merged.leaves += g.leaves;
                false
            } else {
                true
            }
        });
        groups.push(merged);
    }
    groups
}

/// A cluster as an intersection (refined from its centre), or as a
/// suspected overlap when it has many leaves.
fn cluster_result(
    a: &RationalCurve<f64>,
    b: &RationalCurve<f64>,
    c: &Cluster,
    tol: f64,
) -> Option<ApproxIntersection> {
    let r = &c.range;
    if c.leaves > OVERLAP_LEAVES {
        let (pa, pb) = (a.eval(&r[0]).ok()?, b.eval(&r[2]).ok()?);
        return Some(ApproxIntersection {
            s: r[0],
            t: r[2],
            distance: distance(&pa, &pb),
            point: pa,
            overlap: Some(*r),
        });
    }
    let (s, t) = refine(a, b, 0.5 * (r[0] + r[1]), 0.5 * (r[2] + r[3]));
    let (pa, pb) = (a.eval(&s).ok()?, b.eval(&t).ok()?);
    let d = distance(&pa, &pb);
    (d <= tol).then_some(ApproxIntersection {
        s,
        t,
        point: pa,
        distance: d,
        overlap: None,
    })
}

fn distance(p: &[f64], q: &[f64]) -> f64 {
    p.iter()
        .zip(q)
        .map(|(x, y)| (x - y).powi(2))
        .sum::<f64>()
        .sqrt()
}
