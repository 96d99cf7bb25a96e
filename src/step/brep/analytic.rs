//! The analytic geometry of a B-rep's faces and edges: every face surface
//! and edge curve that is not a B-spline becomes exact pieces through
//! [`crate::step::geometry`] (placements, conics and quadrics of
//! [`crate::analytic`]), over the real algebraic numbers.
//!
//! - An **edge** curve is trimmed to the edge ([`trim_between`]): from the
//!   start vertex to the end vertex, along the curve when the edge's
//!   `same_sense` is true and against it otherwise, so the pieces always
//!   run from `edge_start` to `edge_end`. The vertices are rounded decimals
//!   that lie on the curve only within the model's tolerance: each is
//!   located at the nearest dyadic parameter, the pieces end exactly on the
//!   curve there, and the exact squared distances are kept
//!   ([`AnalyticPieces::vertex_distance_sq`]). Unbounded curves (`LINE`)
//!   are first cut to cover both vertices.
//! - A **face** surface is cut to cover the face in its unbounded
//!   directions (plane, cylinder, cone, extrusion): the range spanned by the
//!   control points of its bounding edges' pieces, the vertices of vertex
//!   loops and the points of poly loops ([`covering_range`](crate::analytic::covering_range)).
//!   Closed directions (angles) are whole turns.
//! - `PCURVE`s (curves in a surface's parameter plane) are converted when
//!   they are B-splines, and trimmed to their edge when they are analytic
//!   ([`pcurve`](super::pcurve)).

use super::BSpline;
use super::{
    curve_geometry, surface_geometry, type_name, AnalyticPieces, AngleUnit, Bound, Builder,
    Context, Geometry, GeometryRef, Loop,
};
use crate::algebra::{Ordered, RealAlgebraic, Scalar};
use crate::analytic::{trim_between, Trimmed};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::nurbs::{Nurbs, SpannedPatch};
use crate::patch::Patch;
use crate::step::geometry::{curve_pieces, surface_pieces, Context as Readers, Curve, Surface};
use num_rational::BigRational;

/// The units the geometry readers need, from a representation context.
#[derive(Clone, Debug)]
pub(super) struct Units {
    /// The plane angle unit (cone semi-angles, angle trims).
    pub(super) angle: AngleUnit,
    /// The declared tolerance, or 10⁻⁷ without one (an `f64` distance in
    /// the model's length unit): how near a B-spline edge's ends must be
    /// to its vertices for it to keep its whole curve, and the scale of
    /// the p-curves' checks; trimming takes a vertex at a piece's end only
    /// within [`Units::end_snap`]. A search heuristic only: the trimmed
    /// pieces and the distances kept are exact.
    pub(super) snap: f64,
}

impl Units {
    /// The units of `context` (radians and a 10⁻⁷ snap when absent).
    pub(super) fn of(context: Option<&Context>) -> Self {
        let angle = context
            .and_then(|c| c.angle.clone())
            .unwrap_or_else(AngleUnit::radian);
        let snap = context
            .and_then(|c| c.tolerance.as_ref())
            .map_or(1e-7, crate::algebra::scalar::Ordered::to_f64);
        Units { angle, snap }
    }

    /// How much farther from a vertex than the curve point nearest it a
    /// piece's end may be and still be taken for the vertex when an edge
    /// is trimmed ([`trim_between`]'s `snap`): [`END_SNAP`], or the
    /// declared tolerance where smaller. Snapping by the whole tolerance
    /// moved `nist_ctc_02 #6261`'s start 0.0164 mm (0.094° of its circle)
    /// along the curve to its arc's end, past the corner of its B-spline
    /// face (tolerance 0.0508 mm), so the audit measured a curve that left
    /// the face.
    fn end_snap(&self) -> f64 {
        self.snap.min(END_SNAP)
    }
}

/// A vertex at a piece's end up to the rounding of a file's decimals (and
/// of the `f64` search that locates it) is taken at the end, so that no
/// sliver piece appears: 10⁻⁷ model units, far above the ~10⁻¹² of
/// 15-digit coordinates, far below any real edge's length.
const END_SNAP: f64 = 1e-7;

pub(super) fn lift(p: &[BigRational]) -> Vec<RealAlgebraic> {
    p.iter().map(RealAlgebraic::from_rational).collect()
}

/// The Bézier curve pieces of a B-spline curve entity, lifted.
fn bspline_pieces(nurbs: &Nurbs) -> Vec<RationalCurve<RealAlgebraic>> {
    lifted(&nurbs.pieces())
}

/// The curves among spanned pieces, lifted to the real algebraic numbers.
fn lifted(pieces: &[SpannedPatch]) -> Vec<RationalCurve<RealAlgebraic>> {
    pieces
        .iter()
        .filter_map(|p| match &p.patch {
            Patch::Curve(c) => Some(c.map(RealAlgebraic::from_rational)),
            _ => None,
        })
        .collect()
}

/// A trimmed edge curve as geometry.
fn trimmed(t: Trimmed<RealAlgebraic>, approximate: Option<String>) -> Geometry {
    Geometry::Analytic(AnalyticPieces {
        pieces: t.pieces.into_iter().map(Patch::Curve).collect(),
        approximate,
        vertex_distance_sq: Some([t.start_distance_sq, t.end_distance_sq]),
        closed_form: None,
    })
}

/// Does the B-spline curve `s` run from vertex `a` to vertex `b` (from
/// `b` to `a` when not `same_sense`): are its ends within the snap
/// distance of them? Real files write B-spline edges so (every corpus
/// file does); such an edge keeps its whole curve, and any other is
/// trimmed between its vertices like an analytic one. A decision in `f64`
/// (a choice of representation only: both are exact). The ends of a
/// clamped curve are its end control points; another is converted.
fn runs_between(
    s: &BSpline,
    a: &[BigRational],
    b: &[BigRational],
    same_sense: bool,
    units: &Units,
) -> bool {
    let Some([first, last]) = spline_ends(s) else {
        return false;
    };
    let near = |p: &[f64], v: &[BigRational]| {
        p.len() == v.len()
            && p.iter()
                .zip(v)
                .map(|(x, y)| (x - y.to_f64()).powi(2))
                .sum::<f64>()
                .sqrt()
                <= units.snap
    };
    let (from, to) = if same_sense { (a, b) } else { (b, a) };
    near(&first, from) && near(&last, to)
}

/// The first and last points of a B-spline curve, in `f64`.
fn spline_ends(s: &BSpline) -> Option<[Vec<f64>; 2]> {
    let Nurbs::Curve(c) = s.nurbs() else {
        return None;
    };
    let project = |h: &HPoint<BigRational>| -> Option<Vec<f64>> {
        Some(h.project().ok()?.iter().map(Ordered::to_f64).collect())
    };
    if c.knots().is_clamped() {
        let ctrl = c.control_points();
        return Some([project(ctrl.first()?)?, project(ctrl.last()?)?]);
    }
    let pieces = lifted(s.pieces());
    let end = |c: &RationalCurve<RealAlgebraic>, t: i64| -> Option<Vec<f64>> {
        let p = c.eval(&RealAlgebraic::from_i64(t)).ok()?;
        Some(p.iter().map(Ordered::to_f64).collect())
    };
    Some([end(pieces.first()?, 0)?, end(pieces.last()?, 1)?])
}

/// The Cartesian control points of pieces (positive weights: their hull
/// contains the pieces).
fn control_points(pieces: &[Patch<RealAlgebraic>]) -> Vec<Vec<RealAlgebraic>> {
    pieces
        .iter()
        .flat_map(|p| match p {
            Patch::Curve(c) => c.ctrl().to_vec(),
            Patch::Rect(r) => r.ctrl().iter().flatten().cloned().collect(),
            Patch::Tri(t) => t.rows().iter().flatten().cloned().collect(),
        })
        .filter_map(|h| h.project().ok())
        .collect()
}

impl Builder<'_> {
    /// The geometry readers over this file, in `units`.
    pub(super) fn with_readers<R>(
        &self,
        units: &Units,
        f: impl FnOnce(&Readers<'_, RealAlgebraic>) -> R,
    ) -> R {
        let bspline = |id: u64| -> Result<Vec<RationalCurve<RealAlgebraic>>, Error> {
            match self.conv.nurbs.get(&id) {
                Some(n) => Ok(bspline_pieces(n)),
                None => Err(Error::Format(format!("#{id} is not a B-spline curve read"))),
            }
        };
        f(&Readers {
            table: self.store,
            angle_unit: units.angle.clone(),
            bspline_curve: Some(&bspline),
        })
    }

    /// The curve of an edge, trimmed from its start to its end vertex.
    pub(super) fn edge_curve(
        &self,
        units: &Units,
        id: u64,
        (start, end): (u64, u64),
        same_sense: bool,
    ) -> GeometryRef {
        let kind = type_name(self.store, id);
        let (a, b) = (&self.model.vertices[&start], &self.model.vertices[&end]);
        let geometry = match curve_geometry(&kind, id, &self.conv) {
            Geometry::NotConverted if self.analytic => self
                .trimmed_curve(units, id, &lift(a), &lift(b), same_sense)
                .unwrap_or_else(|e| Geometry::Invalid(e.to_string())),
            Geometry::BSpline(s) if self.analytic && !runs_between(&s, a, b, same_sense, units) => {
                let t = trim_between(
                    &lifted(s.pieces()),
                    &lift(a),
                    &lift(b),
                    same_sense,
                    units.end_snap(),
                );
                t.map_or_else(|e| Geometry::Invalid(e.to_string()), |t| trimmed(t, None))
            }
            g => g,
        };
        GeometryRef {
            entity: id,
            kind,
            geometry,
        }
    }

    pub(super) fn trimmed_curve(
        &self,
        units: &Units,
        id: u64,
        start: &[RealAlgebraic],
        end: &[RealAlgebraic],
        same_sense: bool,
    ) -> Result<Geometry, Error> {
        let cover = [start.to_vec(), end.to_vec()];
        let curve = self.with_readers(units, |r| curve_pieces(r, id, &cover))?;
        let Curve::Pieces(c) = curve else {
            return Ok(Geometry::NotConverted);
        };
        let t = trim_between(&c.pieces, start, end, same_sense, units.end_snap())?;
        Ok(trimmed(t, c.approximate))
    }

    /// The surface of a face, covering its bounds.
    pub(super) fn face_surface(&self, units: &Units, id: u64, bounds: &[Bound]) -> GeometryRef {
        let kind = type_name(self.store, id);
        let geometry = match surface_geometry(&kind, id, &self.conv) {
            Geometry::NotConverted if self.analytic => {
                let (boundary, unconverted) = self.boundary_points(bounds);
                match self.with_readers(units, |r| surface_pieces(r, id, &boundary)) {
                    Ok(Surface::Pieces(s)) => Geometry::Analytic(AnalyticPieces {
                        pieces: s.patches.into_iter().map(Patch::Rect).collect(),
                        approximate: s.approximate.or(unconverted.map(|e| {
                            format!("the pieces cover the vertices of edge #{e}, whose curve is not converted, not the curve")
                        })),
                        vertex_distance_sq: None,
                        closed_form: s.closed_form,
                    }),
                    Ok(Surface::BSpline(_) | Surface::Unsupported { .. }) => Geometry::NotConverted,
                    Err(e) => Geometry::Invalid(e.to_string()),
                }
            }
            g => g,
        };
        GeometryRef {
            entity: id,
            kind,
            geometry,
        }
    }

    /// Points whose convex hull contains a face's bounds: its edges'
    /// control points, its loop vertices and polygon points; and an edge
    /// whose curve is not converted (only its vertices are taken), if any.
    fn boundary_points(&self, bounds: &[Bound]) -> (Vec<Vec<RealAlgebraic>>, Option<u64>) {
        let mut points = Vec::new();
        let mut unconverted = None;
        for b in bounds {
            match &b.edges {
                Loop::Edges(es) => {
                    for e in es {
                        let Some(edge) = self.model.edges.get(&e.edge) else {
                            continue;
                        };
                        match &edge.curve.geometry {
                            Geometry::Analytic(a) => points.extend(control_points(&a.pieces)),
                            Geometry::BSpline(b) => points.extend(control_points(
                                &b.pieces()
                                    .iter()
                                    .map(|p| p.patch.map(RealAlgebraic::from_rational))
                                    .collect::<Vec<_>>(),
                            )),
                            Geometry::NotConverted | Geometry::Invalid(_) => {
                                unconverted = unconverted.or(Some(edge.id));
                                for v in [edge.start, edge.end] {
                                    points.extend(self.model.vertices.get(&v).map(|p| lift(p)));
                                }
                            }
                        }
                    }
                }
                Loop::Vertex(v) => points.extend(self.model.vertices.get(v).map(|p| lift(p))),
                Loop::Poly(ps) => points.extend(ps.iter().map(|p| lift(p))),
            }
        }
        (points, unconverted)
    }
}
