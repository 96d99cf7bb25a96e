//! The approximate `f64` intersection with a caller's tolerance: the
//! control polygons are subdivided in plain `f64` (module `pieces`, the
//! filter's level-by-level subdivision) down to pieces whose boxes are
//! below the leaf size, Newton steps on `A(s) − B(t)` run from
//! each surviving cluster of piece pairs, and the results are clustered in
//! `(s, t)`.

use super::pieces::{subdivide, Pieces, Policy, Stop};
use crate::algebra::Interval;
use crate::curve::RationalCurve;
use crate::error::Error;
use smallvec::SmallVec;

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

/// The whole curve's homogeneous control points as one [`Pieces`]; a curve
/// with equal weights is divided by them first (a polynomial curve,
/// `W ≡ 1`).
fn whole(c: &RationalCurve<f64>) -> Pieces<f64> {
    let dim = c.dim();
    let w0 = c.ctrl()[0].coords[dim];
    let weighted = c.ctrl().iter().any(|h| h.coords[dim] != w0);
    let ctrl = c
        .ctrl()
        .iter()
        .flat_map(|h| match weighted {
            true => h.coords.clone(),
            false => h.coords[..dim].iter().map(|x| x / w0).collect(),
        })
        .collect();
    Pieces::whole(ctrl, dim + usize::from(weighted), weighted)
}

/// A vector of a few `f64` coordinates (a point or a velocity).
type Coords = SmallVec<[f64; 4]>;

/// A curve's homogeneous control points in `f64`, flat (`dim + 1`
/// coordinates each, the weight last), for the Newton steps.
struct Jet {
    ctrl: Vec<f64>,
    stride: usize,
}

impl Jet {
    fn new(c: &RationalCurve<f64>) -> Jet {
        Jet {
            ctrl: c
                .ctrl()
                .iter()
                .flat_map(|h| h.coords.iter().copied())
                .collect(),
            stride: c.dim() + 1,
        }
    }

    /// `A(s)` and `A'(s)` from one de Casteljau triangle: its last two
    /// points `P`, `Q` give, in homogeneous coordinates, `H = (1 − s)P + sQ`
    /// and `H' = n(Q − P)` (Farin, *Curves and Surfaces for CAGD*, §5.3);
    /// then `x = X/W` and `x' = (X'W − XW')/W²`.
    fn point_and_velocity(&self, s: f64) -> (Coords, Coords) {
        let stride = self.stride;
        let n = self.ctrl.len() / stride - 1;
        let mut row: SmallVec<[f64; 24]> = SmallVec::from_slice(&self.ctrl);
        for r in 1..n {
            for j in 0..(n + 1 - r) * stride {
                row[j] = (1.0 - s) * row[j] + s * row[j + stride];
            }
        }
        let (p, q) = (&row[..stride], &row[stride.min(n * stride)..][..stride]);
        let h: Coords = p
            .iter()
            .zip(q)
            .map(|(x, y)| (1.0 - s) * x + s * y)
            .collect();
        let dh: Coords = p.iter().zip(q).map(|(x, y)| n as f64 * (y - x)).collect();
        let (w, dw) = (h[stride - 1], dh[stride - 1]);
        let point = h[..stride - 1].iter().map(|x| x / w).collect();
        let velocity = h[..stride - 1]
            .iter()
            .zip(&dh)
            .map(|(x, dx)| (dx * w - x * dw) / (w * w))
            .collect();
        (point, velocity)
    }
}

/// Newton steps (least squares in 3D and above) on `A(s) − B(t) = 0`.
fn refine(a: &Jet, b: &Jet, mut s: f64, mut t: f64) -> (f64, f64) {
    for _ in 0..20 {
        let ((pa, va), (pb, vb)) = (a.point_and_velocity(s), b.point_and_velocity(t));
        let r: Coords = pa.iter().zip(&pb).map(|(x, y)| x - y).collect();
        // J = [A'(s), −B'(t)]; normal equations JᵀJ δ = −Jᵀr.
        let dot = |u: &[f64], v: &[f64]| u.iter().zip(v).map(|(x, y)| x * y).sum::<f64>();
        let (aa, ab, bb) = (dot(&va, &va), -dot(&va, &vb), dot(&vb, &vb));
        let (ra, rb) = (-dot(&va, &r), dot(&vb, &r));
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

/// The most piece pairs the approximate path keeps, as leaves or at one
/// level, before refusing.
const APPROX_PAIRS: usize = 100_000;
/// Levels of the subdivision: a parameter range stops halving below
/// `f64::EPSILON = 2⁻⁵²`, so pairs settle by level 53.
const APPROX_DEPTH: usize = 64;
/// A cluster of more leaves than this is reported as a suspected overlap.
const OVERLAP_LEAVES: usize = 64;

/// Intersections in `f64` within the tolerance `tol` (absolute, in model
/// units): subdivision to pieces of size `L = max(tol, √(tol·D))` (`D` the
/// diameter of both curves' boxes), Newton refinement from each cluster of
/// touching piece pairs, kept when `|A(s) − B(t)| ≤ tol`. A cluster of more
/// than 64 piece pairs is reported as a suspected overlap with its
/// parameter ranges unless Newton ends there on a transversal crossing
/// (tangents at a sine over 10⁻⁶): a heuristic, the exact path decides
/// overlaps.
///
/// # Errors
///
/// [`Error::Domain`] for a tolerance that is not finite and positive,
/// [`Error::Shape`] for different dimensions, [`Error::Weight`] for
/// non-positive weights, [`Error::Limit`] when more than 100 000 piece
/// pairs stay close (as leaves, or at one level of the subdivision).
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
    let (pa, pb) = (whole(a), whole(b));
    let (Some(ba), Some(bb)) = (pa.bounding_boxes(), pb.bounding_boxes()) else {
        return Ok(Vec::new());
    };
    let diameter = ba
        .iter()
        .zip(&bb)
        .map(|(x, y)| (x.hi.max(y.hi) - x.lo.min(y.lo)).powi(2))
        .sum::<f64>()
        .sqrt();
    let leaf = tol.max((tol * diameter).sqrt());
    let leaves = close_leaves(pa, pb, tol, leaf)?;
    let (ja, jb) = (Jet::new(a), Jet::new(b));
    let found = clusters(&leaves)
        .into_iter()
        .filter_map(|c| cluster_result(&ja, &jb, &c, tol).map(|x| (x, c.range)))
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

/// The `f64` path's [`Policy`]: pairs of pieces whose boxes are more than
/// `tol` apart are dropped; a pair is settled as a leaf when both boxes
/// have diagonals of at most `leaf` or a parameter range cannot be halved
/// further.
struct Leaves {
    tol: f64,
    leaf: f64,
    /// Whether each piece of the level is small enough, per curve.
    small: (Vec<bool>, Vec<bool>),
    /// The leaf pairs `(s0, s1, t0, t1)`.
    found: Vec<[f64; 4]>,
}

impl Leaves {
    /// Whether each piece's box (`dim` intervals each) has a diagonal of at
    /// most `leaf`.
    fn small(&self, boxes: &[Interval], dim: usize) -> Vec<bool> {
        boxes
            .chunks_exact(dim)
            .map(|b| b.iter().map(|x| (x.hi - x.lo).powi(2)).sum::<f64>().sqrt() <= self.leaf)
            .collect()
    }
}

impl Policy<f64> for Leaves {
    fn sift(
        &mut self,
        a: &Pieces<f64>,
        b: &Pieces<f64>,
        pairs: &mut Vec<(usize, usize)>,
    ) -> Result<(), Stop> {
        let dim = a.dim();
        let (Some(ba), Some(bb)) = (a.bounding_boxes(), b.bounding_boxes()) else {
            return Err(Stop::Refused);
        };
        let tol = self.tol;
        pairs.retain(|&(i, j)| {
            let (x, y) = (&ba[i * dim..(i + 1) * dim], &bb[j * dim..(j + 1) * dim]);
            x.iter()
                .zip(y)
                .all(|(p, q)| p.lo <= q.hi + tol && q.lo <= p.hi + tol)
        });
        self.small = (self.small(&ba, dim), self.small(&bb, dim));
        Ok(())
    }

    fn prepare(&mut self, _: [&Pieces<f64>; 4]) -> Result<(), Stop> {
        Ok(())
    }

    fn settle(
        &mut self,
        a: &Pieces<f64>,
        b: &Pieces<f64>,
        (i, j): (usize, usize),
    ) -> Result<bool, Stop> {
        let (ra, rb) = (a.range[i], b.range[j]);
        let splittable = ra.hi - ra.lo > f64::EPSILON && rb.hi - rb.lo > f64::EPSILON;
        if (self.small.0[i] && self.small.1[j]) || !splittable {
            self.found.push([ra.lo, ra.hi, rb.lo, rb.hi]);
            if self.found.len() > APPROX_PAIRS {
                return Err(Stop::TooMany);
            }
            return Ok(true);
        }
        Ok(false)
    }
}

/// Leaf pairs `(s0, s1, t0, t1)` whose boxes stay within `tol` of each
/// other, subdivided to box diagonals of at most `leaf`.
fn close_leaves(
    a: Pieces<f64>,
    b: Pieces<f64>,
    tol: f64,
    leaf: f64,
) -> Result<Vec<[f64; 4]>, Error> {
    let mut policy = Leaves {
        tol,
        leaf,
        small: (Vec::new(), Vec::new()),
        found: Vec::new(),
    };
    match subdivide(a, b, &mut policy, APPROX_DEPTH, APPROX_PAIRS) {
        Ok(()) => Ok(policy.found),
        Err(_) => Err(Error::Limit(format!(
            "over {APPROX_PAIRS} piece pairs within {tol} of each other: use the exact path"
        ))),
    }
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
/// suspected overlap when it has many leaves and Newton's point is not a
/// transversal crossing. (A shallow crossing also makes a cluster of many
/// leaves — the curves stay within `tol` of each other along a stretch of
/// about `tol/sin θ` — and a cluster merged in one pass can hold part of a
/// crossing another cluster holds too: Newton's point decides.)
fn cluster_result(a: &Jet, b: &Jet, c: &Cluster, tol: f64) -> Option<ApproxIntersection> {
    let r = &c.range;
    let (s, t) = refine(a, b, 0.5 * (r[0] + r[1]), 0.5 * (r[2] + r[3]));
    let ((pa, va), (pb, vb)) = (a.point_and_velocity(s), b.point_and_velocity(t));
    let d = distance(&pa, &pb);
    if d <= tol && (c.leaves <= OVERLAP_LEAVES || crossing_sine(&va, &vb) > TRANSVERSAL) {
        return Some(ApproxIntersection {
            s,
            t,
            point: pa.to_vec(),
            distance: d,
            overlap: None,
        });
    }
    (c.leaves > OVERLAP_LEAVES).then(|| {
        let (pa, pb) = (a.point_and_velocity(r[0]).0, b.point_and_velocity(r[2]).0);
        ApproxIntersection {
            s: r[0],
            t: r[2],
            distance: distance(&pa, &pb),
            point: pa.to_vec(),
            overlap: Some(*r),
        }
    })
}

/// Below this sine of the angle between the two tangents, a point where a
/// large cluster's Newton steps end is not taken as a crossing (the
/// cluster is a suspected overlap).
const TRANSVERSAL: f64 = 1e-6;

/// `sin θ` of the angle between `u` and `v`, by Lagrange's identity
/// `|u|²|v|² − (u·v)² = |u|²|v|² sin²θ` (any dimension); 0 for a zero
/// vector.
fn crossing_sine(u: &[f64], v: &[f64]) -> f64 {
    let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(p, q)| p * q).sum::<f64>();
    let (uu, vv, uv) = (dot(u, u), dot(v, v), dot(u, v));
    if uu == 0.0 || vv == 0.0 {
        return 0.0;
    }
    ((uu * vv - uv * uv).max(0.0) / (uu * vv)).sqrt()
}

fn distance(p: &[f64], q: &[f64]) -> f64 {
    p.iter()
        .zip(q)
        .map(|(x, y)| (x - y).powi(2))
        .sum::<f64>()
        .sqrt()
}
