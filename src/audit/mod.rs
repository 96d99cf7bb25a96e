//! The exact audit of a patch model: which patches share a boundary curve
//! (any orientation, Möbius reparameterization or degree elevation), with
//! what continuity; duplicates; pieces of one surface; degenerate and open
//! edges. See `docs/audit.md` for what each verdict means.
//!
//! **Finding shared edges.** Every boundary curve gets its canonical key
//! ([`canonical_key`]: an exact normal form of its class under reversal,
//! Möbius maps, elevation and weight scaling); two edges are the same
//! curve iff their keys are equal, so all shared edges are found by one
//! hash pass — O(edges), not O(patches²). A boundary whose control points
//! are all one point is *degenerate* (collapsed) and is not matched.
//!
//! **Continuity** of each shared edge: [`seam_continuity`].

use crate::coincide::canonical::{canonical_key, CanonicalKey};
use crate::coincide::{boundary_curve, Edge};
use crate::error::Error;
use crate::patch::Patch;
use crate::{RectPatch, Tolerance};
use num_rational::BigRational;
use std::cmp::Ordering;

pub mod brep;
pub mod certify;
pub mod joint;
pub mod knots;
pub mod model;
pub mod seam;
pub mod swept;

pub use model::{nurbs_pieces, ExactModel, Model, Origin, Piece};
pub use seam::{seam_continuity, Continuity, SeamScalar, SeamVerdict};

type Q = BigRational;

/// One edge of one patch of the model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct PatchEdge {
    /// Index of the patch in the model's pieces.
    pub patch: usize,
    /// Which edge.
    pub edge: Edge,
}

/// Two patch edges on the same curve, with their continuity.
#[derive(Clone, Debug, PartialEq)]
pub struct Seam {
    /// The first patch's edge.
    pub a: PatchEdge,
    /// The second patch's edge.
    pub b: PatchEdge,
    /// The verdict.
    pub verdict: SeamVerdict,
    /// More than two patch edges lie on this curve.
    pub non_manifold: bool,
}

/// The audit's findings (points over the model's scalar `T`).
#[derive(Clone, Debug)]
pub struct Audit<T = Q> {
    /// Pieces audited (rect patches).
    pub patches: usize,
    /// Pieces not audited (curves, tri patches), with their indices.
    pub not_rect: Vec<usize>,
    /// Shared boundaries.
    pub seams: Vec<Seam>,
    /// Edges no other patch shares.
    pub open_edges: Vec<PatchEdge>,
    /// Collapsed edges and the point they collapse to.
    pub degenerate_edges: Vec<(PatchEdge, Vec<T>)>,
    /// Classes of coincident patches (same surface piece up to
    /// reparameterization), two or more each.
    pub duplicates: Vec<Vec<usize>>,
}

impl<T> Default for Audit<T> {
    fn default() -> Self {
        Audit {
            patches: 0,
            not_rect: Vec::new(),
            seams: Vec::new(),
            open_edges: Vec::new(),
            degenerate_edges: Vec::new(),
            duplicates: Vec::new(),
        }
    }
}

fn rects<T: SeamScalar>(model: &Model<T>) -> (Vec<(usize, &RectPatch<T>)>, Vec<usize>) {
    let mut out = Vec::new();
    let mut other = Vec::new();
    for (k, p) in model.pieces.iter().enumerate() {
        match &p.patch {
            Patch::Rect(r) => out.push((k, r)),
            _ => other.push(k),
        }
    }
    (out, other)
}

/// The collapse point of a boundary curve whose control points all project
/// to one point, if it is one.
fn collapsed<T: SeamScalar>(r: &RectPatch<T>, e: Edge) -> Option<Vec<T>> {
    let c = boundary_curve(r, e);
    let first = &c.ctrl()[0];
    c.ctrl()
        .iter()
        .all(|p| p.same_projective_point(first, Tolerance::EXACT))
        .then(|| first.project().unwrap_or_default())
}

/// Run `f` on every item, in parallel on the available cores, keeping order.
fn par_map<I: Sync, O: Send>(items: &[I], f: impl Fn(&I) -> O + Sync) -> Vec<O> {
    let threads = std::thread::available_parallelism()
        .map_or(1, usize::from)
        .min(8);
    let chunk = items.len().div_ceil(threads).max(1);
    std::thread::scope(|s| {
        let handles: Vec<_> = items
            .chunks(chunk)
            .map(|c| s.spawn(|| c.iter().map(&f).collect::<Vec<O>>()))
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().expect("audit worker panicked"))
            .collect()
    })
}

/// The edges' canonical keys (or collapse points).
type EdgeKey<T> = Result<Result<CanonicalKey<T>, Vec<T>>, Error>;

/// The classes of equal keys, each with its items in input order, the
/// classes in key order: one sort (keys over the real algebraic numbers
/// are ordered exactly but not hashable).
fn classes_of<K: PartialOrd, I>(mut keyed: Vec<(K, I)>) -> Vec<Vec<I>> {
    keyed.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(Ordering::Equal));
    let mut out: Vec<Vec<I>> = Vec::new();
    let mut last: Option<K> = None;
    for (k, item) in keyed {
        match &last {
            Some(l) if *l == k => out.last_mut().expect("a class is open").push(item),
            _ => {
                out.push(vec![item]);
                last = Some(k);
            }
        }
    }
    out
}

/// Audit the rect patches of `model`.
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight; [`Error::Shape`] for
/// patches of dimension other than 2 or 3 that share an edge.
pub fn audit<T: SeamScalar>(model: &Model<T>) -> Result<Audit<T>, Error> {
    let (rects, not_rect) = rects(model);
    let edges: Vec<(PatchEdge, &RectPatch<T>)> = rects
        .iter()
        .flat_map(|&(k, r)| Edge::ALL.map(|edge| (PatchEdge { patch: k, edge }, r)))
        .collect();
    let keys: Vec<EdgeKey<T>> = par_map(&edges, |(pe, r)| match collapsed(r, pe.edge) {
        Some(point) => Ok(Err(point)),
        None => canonical_key(&Patch::Curve(boundary_curve(r, pe.edge))).map(Ok),
    });
    let mut out = Audit {
        patches: rects.len(),
        not_rect,
        ..Audit::default()
    };
    let mut keyed = Vec::new();
    for ((pe, _), key) in edges.iter().zip(keys) {
        match key? {
            Err(point) => out.degenerate_edges.push((*pe, point)),
            Ok(k) => keyed.push((k, *pe)),
        }
    }
    let mut groups = classes_of(keyed);
    groups.sort();
    let mut pairs = Vec::new();
    for g in &groups {
        if g.len() == 1 {
            out.open_edges.push(g[0]);
        }
        for (i, a) in g.iter().enumerate() {
            for b in &g[i + 1..] {
                pairs.push((*a, *b, g.len() > 2));
            }
        }
    }
    out.open_edges.sort();
    let rect_of = |k: usize| match &model.pieces[k].patch {
        Patch::Rect(r) => r,
        _ => unreachable!("only rect edges are grouped"),
    };
    let verdicts = par_map(&pairs, |(a, b, _)| {
        seam_continuity(rect_of(a.patch), a.edge, rect_of(b.patch), b.edge)
    });
    for ((a, b, non_manifold), v) in pairs.into_iter().zip(verdicts) {
        out.seams.push(Seam {
            a,
            b,
            verdict: v?,
            non_manifold,
        });
    }
    let patch_keys = par_map(&rects, |(_, r)| canonical_key(&Patch::Rect((*r).clone())));
    let mut keyed = Vec::new();
    for ((k, _), key) in rects.iter().zip(patch_keys) {
        keyed.push((key?, *k));
    }
    out.duplicates = classes_of(keyed)
        .into_iter()
        .filter(|c| c.len() > 1)
        .collect();
    out.duplicates.sort();
    Ok(out)
}

impl<T> Audit<T> {
    /// Seams by verdict: `(G0, G1, G2, undecided)`.
    pub fn counts(&self) -> [usize; 4] {
        let mut c = [0; 4];
        for s in &self.seams {
            c[s.verdict.continuity.map_or(3, |v| v as usize)] += 1;
        }
        c
    }

    /// The one-line summary.
    pub fn summary(&self) -> String {
        let [g0, g1, g2, u] = self.counts();
        format!(
            "{} patches: {} shared edges (G2 {g2}, G1 {g1}, G0 {g0}, undecided {u}), {} open edges, {} degenerate edges, {} duplicate classes",
            self.patches,
            self.seams.len(),
            self.open_edges.len(),
            self.degenerate_edges.len(),
            self.duplicates.len()
        )
    }
}

#[cfg(test)]
mod tests;
