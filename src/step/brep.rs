//! The boundary representation of a STEP file, read whole: solids, shells,
//! faces, loops, edges and vertices (ISO 10303-42 §5, topology), the
//! geometry of each face and edge, the units and tolerance of each
//! representation context (ISO 10303-41 §4, measures), and a summary.
//!
//! ```text
//! ADVANCED_BREP_SHAPE_REPRESENTATION('',(#solid,…),#context)
//! MANIFOLD_SOLID_BREP('',#shell)         BREP_WITH_VOIDS('',#shell,(#oriented_closed_shell,…))
//! SHELL_BASED_SURFACE_MODEL('',(#shell,…))
//! CLOSED_SHELL('',(#face,…))             OPEN_SHELL('',(#face,…))
//! ADVANCED_FACE('',(#bound,…),#surface,same_sense)          (FACE_SURFACE alike)
//! FACE_OUTER_BOUND('',#loop,orientation)  FACE_BOUND('',#loop,orientation)
//! EDGE_LOOP('',(#oriented_edge,…))  VERTEX_LOOP('',#vertex)  POLY_LOOP('',(#point,…))
//! ORIENTED_EDGE('',*,*,#edge_curve,orientation)
//! EDGE_CURVE('',#start,#end,#curve,same_sense)   VERTEX_POINT('',#point)
//! SURFACE_CURVE('',#curve_3d,(#pcurve_or_surface,…),master)  (SEAM_CURVE alike)
//! PCURVE('',#surface,#definitional_representation)
//! ```
//!
//! Geometry is produced by `surface_geometry` and `curve_geometry`, one
//! `match` on the entity type each: B-spline entities are kept as read,
//! their exact Bézier pieces ([`super::read_step`]'s conversion) computed
//! at their first use ([`BSpline`]); every other type is kept as
//! [`Geometry::NotConverted`] with its name, counted in the summary, never
//! dropped. Anything of the topology that cannot be read (a dangling
//! reference, a wrong type) is listed in [`Summary::invalid`] with its id.

use super::parser::{Instance, Param, Reader, Record};
use super::{cartesian, Collector, StepModel};
use crate::algebra::{parse_rational, RealAlgebraic};
use crate::analytic::ClosedForm;
use crate::error::Error;
use crate::nurbs::{Nurbs, SpannedPatch};
use crate::patch::Patch;
use num_rational::BigRational;
use num_traits::{One, Zero};
use rayon::prelude::*;
use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::io::BufRead;
use std::sync::OnceLock;

/// The exact geometry of a face's surface or an edge's curve.
#[derive(Clone, Debug)]
pub enum Geometry {
    /// A B-spline entity, with its exact rational Bézier pieces.
    BSpline(BSpline),
    /// Exact pieces of an analytic curve or surface, over the real
    /// algebraic numbers (see [`AnalyticPieces`]).
    Analytic(AnalyticPieces),
    /// A type this reader does not convert: kept with its name.
    NotConverted,
    /// The entity could not be read: why.
    Invalid(String),
}

/// A B-spline curve or surface as read, and its exact rational Bézier
/// pieces with their knot spans ([`Nurbs::pieces`]), converted at the
/// first call of [`BSpline::pieces`] and kept. A reader that needs only
/// the B-spline's own data (the audit's knot lines and enclosures) never
/// pays for the conversion, the costliest step of most models.
///
/// ```
/// use exact_bezier::nurbs::{Knots, Nurbs, NurbsCurve};
/// use exact_bezier::hpoint::HPoint;
/// use exact_bezier::step::brep::BSpline;
/// use exact_bezier::{ratio, BigRational};
/// let q = |n: i64| ratio::<BigRational>(n, 1);
/// let knots = Knots::from_multiplicities(1, &[q(0), q(1), q(2)], &[2, 1, 2], 3).unwrap();
/// let points = [0, 1, 0].map(|y| HPoint::from_cartesian(&[q(y), q(0)]));
/// let b = BSpline::new(Nurbs::Curve(NurbsCurve::new(knots, points.to_vec()).unwrap()));
/// assert_eq!(b.pieces().len(), 2);
/// assert_eq!(b.pieces()[1].u, [q(1), q(2)]);
/// ```
#[derive(Debug)]
pub struct BSpline {
    nurbs: Nurbs,
    pieces: OnceLock<Vec<SpannedPatch>>,
}

impl BSpline {
    /// The entity `nurbs`, not converted yet.
    pub fn new(nurbs: Nurbs) -> BSpline {
        BSpline {
            nurbs,
            pieces: OnceLock::new(),
        }
    }

    /// The B-spline as read.
    pub fn nurbs(&self) -> &Nurbs {
        &self.nurbs
    }

    /// Its exact Bézier pieces with their knot spans, converted on the
    /// first call.
    pub fn pieces(&self) -> &[SpannedPatch] {
        self.pieces.get_or_init(|| self.nurbs.pieces())
    }
}

impl Clone for BSpline {
    /// A copy, with the pieces if they are converted already.
    fn clone(&self) -> BSpline {
        BSpline {
            nurbs: self.nurbs.clone(),
            pieces: self.pieces.clone(),
        }
    }
}

/// The exact pieces of an analytic face surface or edge curve
/// ([`crate::analytic`], read by [`super::geometry`]): a face's surface
/// covers the face (its bounding edges' control points), an edge's curve
/// runs from the edge's start vertex to its end vertex.
#[derive(Clone, Debug)]
pub struct AnalyticPieces {
    /// The pieces (curves for edges, rect patches for faces). Coordinates
    /// are rational where the frame's unit vectors are, else radicals.
    pub pieces: Vec<Patch<RealAlgebraic>>,
    /// Why the pieces are not exactly the entity, when they are not (a
    /// cone's slope that is not a multiple of 15°, an angle trim).
    pub approximate: Option<String>,
    /// For an edge: `|start vertex − first point|²` and `|end vertex −
    /// last point|²`, exact (the vertices are rounded decimals; the pieces
    /// end exactly on the curve at rational parameters nearest to them).
    pub vertex_distance_sq: Option<[RealAlgebraic; 2]>,
    /// For a face: the closed form of its surface, when it is an
    /// elementary one ([`crate::analytic::ClosedForm`]: exact, or a cone
    /// whose slope is known within a bound).
    pub closed_form: Option<Box<ClosedForm<RealAlgebraic>>>,
}

/// A referenced geometric entity: its id, type name and geometry.
#[derive(Clone, Debug)]
pub struct GeometryRef {
    /// The entity id.
    pub entity: u64,
    /// Its type name (the leaf type of a complex B-spline instance).
    pub kind: String,
    /// Its exact pieces, or why there are none.
    pub geometry: Geometry,
}

/// One oriented use of an edge in an edge loop.
#[derive(Clone, Debug, PartialEq)]
pub struct OrientedEdge {
    /// The `ORIENTED_EDGE` id.
    pub id: u64,
    /// The `EDGE_CURVE` it uses.
    pub edge: u64,
    /// True when the loop runs from the edge's start to its end.
    pub orientation: bool,
}

/// A loop bounding a face.
#[derive(Clone, Debug, PartialEq)]
pub enum Loop {
    /// `EDGE_LOOP`: oriented edges, head to tail.
    Edges(Vec<OrientedEdge>),
    /// `VERTEX_LOOP`: one vertex (e.g. the apex of a cone).
    Vertex(u64),
    /// `POLY_LOOP`: a closed polygon of exact points.
    Poly(Vec<Vec<BigRational>>),
}

/// A bound of a face: `FACE_OUTER_BOUND` or `FACE_BOUND`.
#[derive(Clone, Debug, PartialEq)]
pub struct Bound {
    /// The bound's id.
    pub id: u64,
    /// The loop's id.
    pub loop_id: u64,
    /// Written as `FACE_OUTER_BOUND`?
    pub outer: bool,
    /// False when the loop is used reversed.
    pub orientation: bool,
    /// The loop.
    pub edges: Loop,
}

/// A face: a region of a surface bounded by loops.
#[derive(Clone, Debug)]
pub struct Face {
    /// The `ADVANCED_FACE`/`FACE_SURFACE` id.
    pub id: u64,
    /// Its surface (for a `RECTANGULAR_TRIMMED_SURFACE`, its basis: the
    /// face's bounds trim it).
    pub surface: GeometryRef,
    /// The `RECTANGULAR_TRIMMED_SURFACE` the surface came through, if any.
    pub trimmed: Option<u64>,
    /// True when the face normal is the normal of `surface` (the file's
    /// `same_sense`, reversed when a rectangular trim reverses exactly one
    /// parameter direction of its basis).
    pub same_sense: bool,
    /// Outer and inner bounds, as written.
    pub bounds: Vec<Bound>,
}

/// A curve in a surface's parameter plane (`PCURVE`).
#[derive(Clone, Debug)]
pub struct Pcurve {
    /// The `PCURVE` id.
    pub id: u64,
    /// The surface whose (u, v) plane it lies in.
    pub surface: u64,
    /// The 2D curve (through its `DEFINITIONAL_REPRESENTATION`).
    pub curve: GeometryRef,
}

/// An edge: a curve between two vertices.
#[derive(Clone, Debug)]
pub struct Edge {
    /// The `EDGE_CURVE` id.
    pub id: u64,
    /// The 3D curve (the `curve_3d` of a `SURFACE_CURVE`/`SEAM_CURVE`).
    pub curve: GeometryRef,
    /// `SURFACE_CURVE` or `SEAM_CURVE` when the curve came through one.
    pub via: Option<String>,
    /// Start and end `VERTEX_POINT` ids.
    pub start: u64,
    /// See `start`.
    pub end: u64,
    /// True when the edge runs along the curve's parameterization.
    pub same_sense: bool,
    /// The curve in the parameter plane of each surface, where given.
    pub pcurves: Vec<Pcurve>,
    /// The faces using the edge, once per oriented use (a face twice: a seam).
    pub used_by: Vec<u64>,
}

/// How an edge is used by the faces of the model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum EdgeUse {
    /// No loop uses it.
    Unused,
    /// One use: an open (boundary) edge.
    Open,
    /// Two uses by two faces: a manifold edge.
    Shared,
    /// Two uses by one face: a seam (e.g. of a cylinder).
    Seam,
    /// More than two uses: non-manifold.
    NonManifold,
}

impl Edge {
    /// How the edge is used (from the loops, counting oriented uses).
    pub fn usage(&self) -> EdgeUse {
        match self.used_by.as_slice() {
            [] => EdgeUse::Unused,
            [_] => EdgeUse::Open,
            [a, b] if a == b => EdgeUse::Seam,
            [_, _] => EdgeUse::Shared,
            _ => EdgeUse::NonManifold,
        }
    }
}

/// A shell: faces, closed (bounding a volume) or open.
#[derive(Clone, Debug, PartialEq)]
pub struct Shell {
    /// The shell id.
    pub id: u64,
    /// `CLOSED_SHELL`?
    pub closed: bool,
    /// False for a void used reversed (`ORIENTED_CLOSED_SHELL` … `.F.`).
    pub orientation: bool,
    /// Its faces' ids.
    pub faces: Vec<u64>,
}

/// A solid (or surface model): its shells, the first the outer one.
#[derive(Clone, Debug, PartialEq)]
pub struct Solid {
    /// The id.
    pub id: u64,
    /// `MANIFOLD_SOLID_BREP`, `BREP_WITH_VOIDS` or `SHELL_BASED_SURFACE_MODEL`.
    pub kind: String,
    /// The outer shell then the voids (solids); all shells (surface models).
    pub shells: Vec<Shell>,
}

/// A length unit: its name and how many metres it is, exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct LengthUnit {
    /// `MILLI METRE`, `INCH`, … as written.
    pub name: String,
    /// Metres per unit (`SI_UNIT` prefixes are powers of ten; a
    /// `CONVERSION_BASED_UNIT` multiplies its written factor, `25.4` mm for
    /// the inch, exactly).
    pub metres: BigRational,
}

/// A plane angle unit (the geometry readers' type).
pub use crate::analytic::AngleUnit;

/// The units and tolerance of a representation context.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Context {
    /// The context id.
    pub id: u64,
    /// Its length unit.
    pub length: Option<LengthUnit>,
    /// Its plane angle unit.
    pub angle: Option<AngleUnit>,
    /// The declared distance tolerance (`UNCERTAINTY_MEASURE_WITH_UNIT`),
    /// in the context's length unit, exactly.
    pub tolerance: Option<BigRational>,
}

/// A shape representation holding solids: one body of the model.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// The representation id.
    pub id: u64,
    /// Its type (`ADVANCED_BREP_SHAPE_REPRESENTATION`, …) and name.
    pub kind: String,
    /// Its name as written.
    pub name: String,
    /// The solids (and surface models) it holds.
    pub solids: Vec<u64>,
    /// Its context (units, tolerance).
    pub context: Option<u64>,
}

/// What was read, counted.
#[derive(Clone, Debug, Default)]
pub struct Summary {
    /// Faces by the type of surface they name (`RECTANGULAR_TRIMMED_SURFACE`
    /// for a trim, whatever its basis).
    pub faces_by_surface: BTreeMap<String, usize>,
    /// Edges by (3D) curve type.
    pub edges_by_curve: BTreeMap<String, usize>,
    /// Surfaces of faces and curves of edges whose type is not converted
    /// (not rational, e.g. `OFFSET_SURFACE`), by type.
    pub not_converted: BTreeMap<String, usize>,
    /// Pcurves whose 2D curve is not converted (analytic pcurves: see
    /// `analytic`), by type.
    pub pcurves_not_converted: BTreeMap<String, usize>,
    /// Faces and edges whose pieces are not exactly their entity (see
    /// [`AnalyticPieces::approximate`]), by type.
    pub approximate: BTreeMap<String, usize>,
    /// Edges by use.
    pub edge_uses: BTreeMap<EdgeUse, usize>,
    /// Placements read but applied to no body (e.g. the `MAPPED_ITEM`s of
    /// a drawing), by type.
    pub not_applied: BTreeMap<String, usize>,
    /// Entities that could not be read: `(id, reason)`.
    pub invalid: Vec<(u64, String)>,
}

/// The whole B-rep of a STEP file.
#[derive(Clone, Debug, Default)]
pub struct BrepModel {
    /// One body per shape representation holding solids.
    pub bodies: Vec<Body>,
    /// Solids and surface models by id.
    pub solids: BTreeMap<u64, Solid>,
    /// Faces by id.
    pub faces: BTreeMap<u64, Face>,
    /// Edges by id.
    pub edges: BTreeMap<u64, Edge>,
    /// Vertices by id: exact points.
    pub vertices: BTreeMap<u64, Vec<BigRational>>,
    /// Shells held by no solid (read for their faces), by id.
    pub loose_shells: Vec<Shell>,
    /// Where the bodies sit: one occurrence per placement of a body in
    /// the assembly (a body placed nowhere is one occurrence, unmoved);
    /// see [`Occurrence`].
    pub occurrences: Vec<Occurrence>,
    /// Representation contexts with units, by id.
    pub contexts: BTreeMap<u64, Context>,
    /// The counts.
    pub summary: Summary,
    /// The B-spline geometry and the skipped entity counts, as
    /// [`super::read_step`] reads them.
    pub geometry: StepModel,
}

impl BrepModel {
    /// The faces of `body`: those of its solids' shells, in order.
    pub fn body_faces(&self, body: &Body) -> Vec<u64> {
        body.solids
            .iter()
            .filter_map(|s| self.solids.get(s))
            .flat_map(|s| &s.shells)
            .flat_map(|sh| sh.faces.iter().copied())
            .collect()
    }

    /// The vertices bounding `faces`: the ends of their loops' edges and
    /// the vertices of their vertex loops, each once.
    pub fn face_vertices(&self, faces: &[u64]) -> BTreeSet<u64> {
        let mut out = BTreeSet::new();
        let bounds = faces
            .iter()
            .filter_map(|f| self.faces.get(f))
            .flat_map(|f| &f.bounds);
        for b in bounds {
            match &b.edges {
                Loop::Edges(es) => {
                    let edges = es.iter().filter_map(|e| self.edges.get(&e.edge));
                    out.extend(edges.flat_map(|e| [e.start, e.end]));
                }
                Loop::Vertex(v) => {
                    out.insert(*v);
                }
                Loop::Poly(_) => {}
            }
        }
        out
    }

    /// Convert every face's and edge's B-spline to its Bézier pieces now,
    /// on all cores ([`BSpline::pieces`] then returns them at once): for
    /// writers that need them all.
    pub fn convert_pieces(&self) {
        let geometries: Vec<&Geometry> = self
            .faces
            .values()
            .map(|f| &f.surface.geometry)
            .chain(self.edges.values().map(|e| &e.curve.geometry))
            .collect();
        geometries.par_iter().for_each(|g| {
            if let Geometry::BSpline(b) = g {
                b.pieces();
            }
        });
    }
}

/// The instances of a file by id.
type Store = super::geometry::Table;

/// The record `name` of instance `id` (simple or part of a complex one).
fn record<'a>(store: &'a Store, id: u64, name: &str) -> Option<&'a Record> {
    store.get(&id)?.records.iter().find(|r| r.name == name)
}

/// The type name of instance `id`: its record's name, the leaf of a
/// complex B-spline (its knot part), or `(A B …)` for another complex
/// instance.
fn type_name(store: &Store, id: u64) -> String {
    let Some(inst) = store.get(&id) else {
        return "missing".into();
    };
    if !inst.complex {
        return inst.records[0].name.clone();
    }
    let names = || inst.records.iter().map(|r| r.name.as_str());
    [super::SURFACE, super::CURVE]
        .into_iter()
        .find(|b| names().any(|n| n == *b))
        .and_then(|b| super::knot_part(b, names()))
        .map_or_else(|| format!("({})", inst.record_names()), str::to_owned)
}

fn reference(p: Option<&Param>, what: &str) -> Result<u64, String> {
    match p {
        Some(Param::Ref(id)) => Ok(*id),
        _ => Err(format!("{what} should be a reference #id")),
    }
}

fn references(p: Option<&Param>, what: &str) -> Result<Vec<u64>, String> {
    match p {
        Some(Param::List(items)) => items.iter().map(|x| reference(Some(x), what)).collect(),
        _ => Err(format!("{what} should be a list of references")),
    }
}

fn boolean(p: Option<&Param>, what: &str) -> Result<bool, String> {
    match p {
        Some(Param::Enum(e)) if e == "T" => Ok(true),
        Some(Param::Enum(e)) if e == "F" => Ok(false),
        _ => Err(format!("{what} should be .T. or .F.")),
    }
}

/// The basis of surface `id` through any `RECTANGULAR_TRIMMED_SURFACE`s
/// (`(name, basis_surface, u1, u2, v1, v2, usense, vsense)`, ISO 10303-42
/// §4.4.43: the basis's own parameters, restricted to `[u1, u2] × [v1,
/// v2]`), and whether the trims reverse its normal: `S_u × S_v` changes
/// sign when exactly one of `usense`, `vsense` is false. The face's
/// bounds lie inside the rectangle, so the basis's pieces (which cover the
/// bounds) hold the face; `id` itself when it is no trim.
fn untrimmed(store: &Store, mut id: u64) -> Result<(u64, bool), String> {
    let mut flipped = false;
    for _ in 0..MAX_TRIMS {
        let Some(r) = record(store, id, "RECTANGULAR_TRIMMED_SURFACE") else {
            return Ok((id, flipped));
        };
        let usense = boolean(r.params.get(6), "usense")?;
        let vsense = boolean(r.params.get(7), "vsense")?;
        flipped ^= usense != vsense;
        id = reference(r.params.get(1), "basis_surface")?;
    }
    Err(format!(
        "#{id}: rectangular trims nested over {MAX_TRIMS} deep"
    ))
}

/// How deep [`untrimmed`] follows trims of trims (a cycle ends there).
const MAX_TRIMS: usize = 8;

/// The record of `id` among `names`, or why not.
fn one_of<'a>(store: &'a Store, id: u64, names: &[&str]) -> Result<&'a Record, String> {
    names
        .iter()
        .find_map(|n| record(store, id, n))
        .ok_or_else(|| {
            format!(
                "#{id} is a {}, not {}",
                type_name(store, id),
                names.join(" or ")
            )
        })
}

/// The B-spline geometry of the file, and the entities found invalid.
struct Converted<'a> {
    nurbs: HashMap<u64, &'a Nurbs>,
    invalid: HashMap<u64, &'a str>,
}

impl<'a> Converted<'a> {
    fn new(geometry: &'a StepModel) -> Converted<'a> {
        Converted {
            nurbs: geometry.entities.iter().map(|e| (e.id, &e.nurbs)).collect(),
            invalid: geometry
                .invalid
                .iter()
                .map(|(id, why)| (*id, why.as_str()))
                .collect(),
        }
    }

    /// Entity `id` as a [`BSpline`], its pieces converted when first
    /// asked for (on whichever core asks: the reader reads faces and
    /// edges on all cores).
    fn bspline(&self, id: u64) -> Geometry {
        match (self.nurbs.get(&id), self.invalid.get(&id)) {
            (Some(n), _) => Geometry::BSpline(BSpline::new((*n).clone())),
            (None, Some(why)) => Geometry::Invalid((*why).to_owned()),
            (None, None) => Geometry::Invalid(format!("#{id} was not read")),
        }
    }
}

/// The exact geometry of surface `id` of type `kind`: B-spline surfaces
/// ([`BSpline`]); every other type not converted (yet).
fn surface_geometry(kind: &str, id: u64, conv: &Converted) -> Geometry {
    match kind {
        "B_SPLINE_SURFACE_WITH_KNOTS"
        | "BEZIER_SURFACE"
        | "UNIFORM_SURFACE"
        | "QUASI_UNIFORM_SURFACE" => conv.bspline(id),
        _ => Geometry::NotConverted,
    }
}

/// The exact geometry of curve `id` of type `kind` (3D or 2D): B-spline
/// curves ([`BSpline`]); every other type not converted (yet).
fn curve_geometry(kind: &str, id: u64, conv: &Converted) -> Geometry {
    match kind {
        "B_SPLINE_CURVE_WITH_KNOTS" | "BEZIER_CURVE" | "UNIFORM_CURVE" | "QUASI_UNIFORM_CURVE" => {
            conv.bspline(id)
        }
        _ => Geometry::NotConverted,
    }
}

/// An edge whose curve is still to be read ([`Builder::read_geometry`]).
struct PendingEdge {
    edge: u64,
    curve: u64,
    /// Its start and end vertices.
    ends: (u64, u64),
    same_sense: bool,
    /// The units of its body.
    units: analytic::Units,
}

/// Reads the topology out of the store.
struct Builder<'a> {
    store: &'a Store,
    conv: Converted<'a>,
    model: BrepModel,
    /// Convert analytic faces and edges ([`BrepOptions::analytic`])?
    analytic: bool,
    /// The units of the body being read ([`analytic::Units`]).
    units: analytic::Units,
    /// Edges whose curve is read after the topology, on all cores.
    pending_edges: Vec<PendingEdge>,
    /// Faces whose surface is read after their edges' curves: the face,
    /// its surface, the units of its body.
    pending_faces: Vec<(u64, u64, analytic::Units)>,
}

impl Builder<'_> {
    fn geometry(&self, id: u64, surface: bool) -> GeometryRef {
        let kind = type_name(self.store, id);
        let geometry = if surface {
            surface_geometry(&kind, id, &self.conv)
        } else {
            curve_geometry(&kind, id, &self.conv)
        };
        GeometryRef {
            entity: id,
            kind,
            geometry,
        }
    }

    /// Entity `id` with its geometry still to be read
    /// ([`Builder::read_geometry`]).
    fn placeholder(&self, id: u64) -> GeometryRef {
        GeometryRef {
            entity: id,
            kind: type_name(self.store, id),
            geometry: Geometry::NotConverted,
        }
    }

    /// Read the curves of the edges, then the surfaces of the faces (whose
    /// analytic pieces cover their edges' curves), each on all cores.
    fn read_geometry(&mut self) {
        let edges = std::mem::take(&mut self.pending_edges);
        let curves: Vec<(u64, GeometryRef, Vec<GeometryRef>)> = edges
            .par_iter()
            .map(|p| {
                let curve = self.edge_curve(&p.units, p.curve, p.ends, p.same_sense);
                let pcurves = self.model.edges.get(&p.edge).map_or_else(Vec::new, |e| {
                    e.pcurves
                        .iter()
                        .map(|pc| self.pcurve_geometry(&p.units, pc, p.ends, p.same_sense))
                        .collect()
                });
                (p.edge, curve, pcurves)
            })
            .collect();
        for (edge, curve, pcurves) in curves {
            if let Some(e) = self.model.edges.get_mut(&edge) {
                e.curve = curve;
                for (pc, geometry) in e.pcurves.iter_mut().zip(pcurves) {
                    pc.curve = geometry;
                }
            }
        }
        let faces = std::mem::take(&mut self.pending_faces);
        let surfaces: Vec<(u64, GeometryRef)> = faces
            .par_iter()
            .filter_map(|(face, surface, units)| {
                let bounds = &self.model.faces.get(face)?.bounds;
                Some((*face, self.face_surface(units, *surface, bounds)))
            })
            .collect();
        for (face, surface) in surfaces {
            if let Some(f) = self.model.faces.get_mut(&face) {
                f.surface = surface;
            }
        }
    }

    fn invalid(&mut self, id: u64, why: String) {
        self.model.summary.invalid.push((id, why));
    }

    fn point(&self, id: u64) -> Result<Vec<BigRational>, String> {
        let r = one_of(self.store, id, &["CARTESIAN_POINT"])?;
        cartesian(r).map_err(|e| e.to_string())
    }

    fn vertex(&mut self, id: u64) -> Result<u64, String> {
        if !self.model.vertices.contains_key(&id) {
            let r = one_of(self.store, id, &["VERTEX_POINT"])?;
            let p = self.point(reference(r.params.get(1), "vertex_geometry")?)?;
            self.model.vertices.insert(id, p);
        }
        Ok(id)
    }

    fn pcurve(&self, id: u64) -> Result<Pcurve, String> {
        let r = one_of(self.store, id, &["PCURVE"])?;
        // A rectangular trim keeps its basis's parameters.
        let (surface, _) = untrimmed(self.store, reference(r.params.get(1), "basis_surface")?)?;
        let rep = reference(r.params.get(2), "reference_to_curve")?;
        let d = one_of(self.store, rep, &["DEFINITIONAL_REPRESENTATION"])?;
        let items = references(d.params.get(1), "items")?;
        let curve = *items
            .first()
            .ok_or_else(|| format!("#{rep} holds no curve"))?;
        Ok(Pcurve {
            id,
            surface,
            curve: self.geometry(curve, false),
        })
    }

    /// Read edge `id` once; later calls only record the use by `face`.
    fn edge(&mut self, id: u64, face: u64) -> Result<(), String> {
        if let Some(e) = self.model.edges.get_mut(&id) {
            e.used_by.push(face);
            return Ok(());
        }
        let r = one_of(self.store, id, &["EDGE_CURVE"])?;
        let start = self.vertex(reference(r.params.get(1), "edge_start")?)?;
        let end = self.vertex(reference(r.params.get(2), "edge_end")?)?;
        let mut curve = reference(r.params.get(3), "edge_geometry")?;
        let same_sense = boolean(r.params.get(4), "same_sense")?;
        let mut via = None;
        let mut pcurves = Vec::new();
        if let Ok(sc) = one_of(self.store, curve, &["SURFACE_CURVE", "SEAM_CURVE"]) {
            via = Some(sc.name.clone());
            for g in references(sc.params.get(2), "associated_geometry")? {
                if record(self.store, g, "PCURVE").is_some() {
                    pcurves.push(self.pcurve(g)?);
                }
            }
            curve = reference(sc.params.get(1), "curve_3d")?;
        }
        self.pending_edges.push(PendingEdge {
            edge: id,
            curve,
            ends: (start, end),
            same_sense,
            units: self.units.clone(),
        });
        let curve = self.placeholder(curve);
        self.model.edges.insert(
            id,
            Edge {
                id,
                curve,
                via,
                start,
                end,
                same_sense,
                pcurves,
                used_by: vec![face],
            },
        );
        Ok(())
    }

    fn edge_loop(&mut self, id: u64, face: u64) -> Result<Loop, String> {
        let r = one_of(self.store, id, &["EDGE_LOOP", "VERTEX_LOOP", "POLY_LOOP"])?;
        match r.name.as_str() {
            "VERTEX_LOOP" => Ok(Loop::Vertex(
                self.vertex(reference(r.params.get(1), "loop_vertex")?)?,
            )),
            "POLY_LOOP" => references(r.params.get(1), "polygon")?
                .into_iter()
                .map(|p| self.point(p))
                .collect::<Result<_, _>>()
                .map(Loop::Poly),
            _ => {
                let mut out = Vec::new();
                for oe in references(r.params.get(1), "edge_list")? {
                    let o = one_of(self.store, oe, &["ORIENTED_EDGE"])?;
                    let edge = reference(o.params.get(3), "edge_element")?;
                    self.edge(edge, face)
                        .map_err(|e| format!("edge #{edge}: {e}"))?;
                    out.push(OrientedEdge {
                        id: oe,
                        edge,
                        orientation: boolean(o.params.get(4), "orientation")?,
                    });
                }
                Ok(Loop::Edges(out))
            }
        }
    }

    fn face(&mut self, id: u64) -> Result<(), String> {
        if self.model.faces.contains_key(&id) {
            return Ok(());
        }
        let r = one_of(self.store, id, &["ADVANCED_FACE", "FACE_SURFACE"])?;
        let written = reference(r.params.get(2), "face_geometry")?;
        let (surface_id, flipped) = untrimmed(self.store, written)?;
        let same_sense = boolean(r.params.get(3), "same_sense")? != flipped;
        let mut bounds = Vec::new();
        for b in references(r.params.get(1), "bounds")? {
            let br = one_of(self.store, b, &["FACE_OUTER_BOUND", "FACE_BOUND"])?;
            let loop_id = reference(br.params.get(1), "bound")?;
            bounds.push(Bound {
                id: b,
                loop_id,
                outer: br.name == "FACE_OUTER_BOUND",
                orientation: boolean(br.params.get(2), "orientation")?,
                edges: self.edge_loop(loop_id, id)?,
            });
        }
        self.pending_faces
            .push((id, surface_id, self.units.clone()));
        let surface = self.placeholder(surface_id);
        self.model.faces.insert(
            id,
            Face {
                id,
                surface,
                trimmed: (written != surface_id).then_some(written),
                same_sense,
                bounds,
            },
        );
        Ok(())
    }

    /// A shell and its faces; `orientation` false for a reversed void.
    fn shell(&mut self, id: u64) -> Result<Shell, String> {
        let (id, orientation) = match record(self.store, id, "ORIENTED_CLOSED_SHELL") {
            Some(o) => (
                reference(o.params.get(2), "closed_shell_element")?,
                boolean(o.params.get(3), "orientation")?,
            ),
            None => (id, true),
        };
        let r = one_of(self.store, id, &["CLOSED_SHELL", "OPEN_SHELL"])?;
        let faces = references(r.params.get(1), "cfs_faces")?;
        let mut kept = Vec::new();
        for f in faces {
            match self.face(f) {
                Ok(()) => kept.push(f),
                Err(e) => self.invalid(f, e),
            }
        }
        Ok(Shell {
            id,
            closed: r.name == "CLOSED_SHELL",
            orientation,
            faces: kept,
        })
    }

    fn solid(&mut self, id: u64) -> Result<(), String> {
        if self.model.solids.contains_key(&id) {
            return Ok(());
        }
        let r = one_of(
            self.store,
            id,
            &[
                "MANIFOLD_SOLID_BREP",
                "BREP_WITH_VOIDS",
                "SHELL_BASED_SURFACE_MODEL",
            ],
        )?;
        let shell_ids = match r.name.as_str() {
            "SHELL_BASED_SURFACE_MODEL" => references(r.params.get(1), "sbsm_boundary")?,
            _ => {
                let mut v = vec![reference(r.params.get(1), "outer")?];
                if let Some(voids) = record(self.store, id, "BREP_WITH_VOIDS") {
                    v.extend(references(voids.params.last(), "voids")?);
                }
                v
            }
        };
        let kind = if record(self.store, id, "BREP_WITH_VOIDS").is_some() {
            "BREP_WITH_VOIDS".to_owned()
        } else {
            r.name.clone()
        };
        let shells = shell_ids
            .into_iter()
            .map(|s| self.shell(s))
            .collect::<Result<_, _>>()?;
        self.model.solids.insert(id, Solid { id, kind, shells });
        Ok(())
    }

    /// Every representation holding solids becomes a body.
    fn bodies(&mut self, ids: &[u64]) {
        for &id in ids {
            let inst = &self.store[&id];
            for r in &inst.records {
                let (Some(Param::List(items)), Some(ctx)) = (r.params.get(1), r.params.get(2))
                else {
                    continue;
                };
                let solids: Vec<u64> = items
                    .iter()
                    .filter_map(|p| match p {
                        Param::Ref(s) if is_solid(self.store, *s) => Some(*s),
                        _ => None,
                    })
                    .collect();
                if solids.is_empty() {
                    continue;
                }
                let context = reference(Some(ctx), "context").ok();
                if let Some(c) = context {
                    self.context(c);
                }
                self.units = analytic::Units::of(context.and_then(|c| self.model.contexts.get(&c)));
                for &s in &solids {
                    if let Err(e) = self.solid(s) {
                        self.invalid(s, e);
                    }
                }
                self.model.bodies.push(Body {
                    id,
                    kind: r.name.clone(),
                    name: match r.params.first() {
                        Some(Param::Str(s)) => s.clone(),
                        _ => String::new(),
                    },
                    solids,
                    context,
                });
            }
        }
    }

    /// Read the shells and faces no solid holds (in file order), and
    /// return the entities found invalid among them, in that order.
    fn loose_shells_and_faces(&mut self, order: &[u64]) -> Vec<(u64, String)> {
        let mark = self.model.summary.invalid.len();
        for &id in order {
            let name = &self.store[&id].records[0].name;
            let read = match name.as_str() {
                "CLOSED_SHELL" | "OPEN_SHELL" => self
                    .model
                    .solids
                    .values()
                    .flat_map(|s| &s.shells)
                    .any(|sh| sh.id == id),
                "ADVANCED_FACE" | "FACE_SURFACE" => self.model.faces.contains_key(&id),
                _ => continue,
            };
            if read {
                continue;
            }
            let r = if name.ends_with("SHELL") {
                self.shell(id).map(|s| self.model.loose_shells.push(s))
            } else {
                self.face(id)
            };
            if let Err(e) = r {
                self.invalid(id, e);
            }
        }
        self.model.summary.invalid.split_off(mark)
    }

    fn context(&mut self, id: u64) {
        if self.model.contexts.contains_key(&id) {
            return;
        }
        match context(self.store, id) {
            Ok(c) => {
                self.model.contexts.insert(id, c);
            }
            Err(e) => self.invalid(id, e),
        }
    }
}

fn is_solid(store: &Store, id: u64) -> bool {
    store.get(&id).is_some_and(|i| {
        i.records.iter().any(|r| {
            matches!(
                r.name.as_str(),
                "MANIFOLD_SOLID_BREP" | "BREP_WITH_VOIDS" | "SHELL_BASED_SURFACE_MODEL"
            )
        })
    })
}

/// `10^k` for an SI prefix (ISO 10303-41 `si_prefix`), 1 for `$`.
fn si_prefix(p: Option<&Param>) -> Result<BigRational, String> {
    let k: i32 = match p {
        None | Some(Param::Unset) => 0,
        Some(Param::Enum(e)) => match e.as_str() {
            "EXA" => 18,
            "PETA" => 15,
            "TERA" => 12,
            "GIGA" => 9,
            "MEGA" => 6,
            "KILO" => 3,
            "HECTO" => 2,
            "DECA" => 1,
            "DECI" => -1,
            "CENTI" => -2,
            "MILLI" => -3,
            "MICRO" => -6,
            "NANO" => -9,
            "PICO" => -12,
            "FEMTO" => -15,
            "ATTO" => -18,
            other => return Err(format!("unknown SI prefix .{other}.")),
        },
        _ => return Err("an SI prefix should be an enumeration".into()),
    };
    let ten = BigRational::from_integer(10.into());
    Ok(num_traits::pow::Pow::pow(&ten, k))
}

/// A unit's name and its factor to the SI base unit (metre, radian),
/// exactly: the SI prefix, or the written factor of a conversion-based
/// unit times its base unit's factor.
fn unit_factor(store: &Store, id: u64, depth: usize) -> Result<(String, BigRational), String> {
    if depth > 8 {
        return Err(format!("unit #{id}: conversions nested too deep"));
    }
    if let Some(si) = record(store, id, "SI_UNIT") {
        let name = match si.params.get(1) {
            Some(Param::Enum(n)) => n.clone(),
            _ => return Err(format!("SI_UNIT #{id} without a name")),
        };
        let prefix = match si.params.first() {
            Some(Param::Enum(p)) => format!("{p} "),
            _ => String::new(),
        };
        return Ok((format!("{prefix}{name}"), si_prefix(si.params.first())?));
    }
    let c = record(store, id, "CONVERSION_BASED_UNIT")
        .ok_or_else(|| format!("unit #{id} is a {}", type_name(store, id)))?;
    let name = match c.params.first() {
        Some(Param::Str(s)) => s.clone(),
        _ => String::new(),
    };
    let m = reference(c.params.get(1), "conversion_factor")?;
    let (value, base) = measure(store, m)?;
    let (_, f) = unit_factor(store, base, depth + 1)?;
    Ok((name, value * f))
}

/// A `…MEASURE_WITH_UNIT(TYPED_MEASURE(value), #unit, …)`: value and unit.
fn measure(store: &Store, id: u64) -> Result<(BigRational, u64), String> {
    let r = store
        .get(&id)
        .and_then(|i| {
            i.records
                .iter()
                .find(|r| r.name.ends_with("MEASURE_WITH_UNIT"))
        })
        .ok_or_else(|| format!("#{id} is not a measure with unit"))?;
    let value = match r.params.first() {
        Some(Param::Typed(_, v)) | Some(Param::List(v)) if v.len() == 1 => &v[0],
        other => other.ok_or_else(|| format!("#{id} has no value"))?,
    };
    let Param::Number(t) = value else {
        return Err(format!("#{id}: the value should be a number"));
    };
    let v = parse_rational(t).map_err(|e| e.to_string())?;
    Ok((v, reference(r.params.get(1), "unit_component")?))
}

/// The units and tolerance of context `id` (`GLOBAL_UNIT_ASSIGNED_CONTEXT`,
/// `GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT`).
fn context(store: &Store, id: u64) -> Result<Context, String> {
    let mut c = Context {
        id,
        ..Context::default()
    };
    if let Some(units) = record(store, id, "GLOBAL_UNIT_ASSIGNED_CONTEXT") {
        for u in references(units.params.first(), "units")? {
            let is = |n: &str| record(store, u, n).is_some();
            if is("LENGTH_UNIT") {
                let (name, metres) = unit_factor(store, u, 0)?;
                c.length = Some(LengthUnit { name, metres });
            } else if is("PLANE_ANGLE_UNIT") {
                let (name, f) = unit_factor(store, u, 0)?;
                c.angle = Some(if is("SI_UNIT") {
                    AngleUnit::Radian(f)
                } else if name.to_ascii_uppercase().starts_with("DEG") {
                    AngleUnit::Degree
                } else {
                    AngleUnit::Other(name, f)
                });
            }
        }
    }
    if let Some(unc) = record(store, id, "GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT") {
        for u in references(unc.params.first(), "uncertainty")? {
            let (value, unit) = measure(store, u)?;
            if record(store, unit, "LENGTH_UNIT").is_none() {
                continue;
            }
            let (_, metres) = unit_factor(store, unit, 0)?;
            let own = c
                .length
                .as_ref()
                .map_or_else(BigRational::one, |l| l.metres.clone());
            if own.is_zero() {
                return Err(format!("context #{id}: a length unit of zero metres"));
            }
            c.tolerance = Some(value * metres / own);
        }
    }
    Ok(c)
}

/// Placements, counted under [`Summary::not_applied`] when they place no
/// body.
const PLACEMENTS: [&str; 2] = ["ITEM_DEFINED_TRANSFORMATION", "MAPPED_ITEM"];

/// Read the whole B-rep of a STEP file.
///
/// The file is held in memory as parsed instances (topology refers forward
/// and backward). Solids are found through the representations that hold
/// them; faces of shells not held by any representation are read too.
///
/// # Errors
///
/// [`Error::Format`] for malformed exchange syntax (with its line); bad
/// topology is reported in [`Summary::invalid`], not an error.
///
/// ```
/// let step = "ISO-10303-21;\nDATA;\n#1=CARTESIAN_POINT('',(0.,0.,0.));\n\
///             #2=VERTEX_POINT('',#1);\n#3=VERTEX_LOOP('',#2);\n#4=OFFSET_SURFACE('',#9,1.,.F.);\n\
///             #5=FACE_OUTER_BOUND('',#3,.T.);\n#6=ADVANCED_FACE('',(#5),#4,.T.);\n\
///             #7=OPEN_SHELL('',(#6));\nENDSEC;\nEND-ISO-10303-21;\n";
/// let m = exact_bezier::step::read_brep(step.as_bytes()).unwrap();
/// assert_eq!(m.summary.faces_by_surface["OFFSET_SURFACE"], 1);
/// // Not rational: kept, named and counted, never dropped.
/// assert_eq!(m.summary.not_converted["OFFSET_SURFACE"], 1);
/// ```
pub fn read_brep(input: impl BufRead) -> Result<BrepModel, Error> {
    read_brep_with(input, BrepOptions::default())
}

/// What [`read_brep_with`] converts.
#[derive(Clone, Copy, Debug)]
pub struct BrepOptions {
    /// Convert analytic surfaces and curves to exact pieces (the default);
    /// `false` reads the topology and the B-spline geometry only, much
    /// faster (analytic geometry is then "not converted").
    pub analytic: bool,
}

impl Default for BrepOptions {
    fn default() -> Self {
        BrepOptions { analytic: true }
    }
}

/// The statements parsed on all cores at a time (see [`Reader::split_batch`]).
const PARSE_BATCH: usize = 4096;

/// [`read_brep`] with [`BrepOptions`].
///
/// # Errors
///
/// As [`read_brep`].
pub fn read_brep_with(input: impl BufRead, options: BrepOptions) -> Result<BrepModel, Error> {
    let mut reader = Reader::new(input);
    let mut collector = Collector::default();
    let mut store = Store::default();
    let mut order = Vec::new();
    // Each batch is parsed on the pool while this thread splits the next.
    let mut batch = reader.split_batch(PARSE_BATCH);
    while !batch.is_empty() {
        let current = std::mem::take(&mut batch);
        let mut parsed = None;
        let slot = &mut parsed;
        batch = rayon::in_place_scope(|s| {
            s.spawn(move |_| *slot = Some(current.parse()));
            reader.split_batch(PARSE_BATCH)
        });
        for inst in parsed.unwrap_or_else(|| Ok(Vec::new()))? {
            order.push(inst.id);
            store.insert(inst.id, inst);
        }
    }
    let instances: Vec<&Instance> = order.iter().filter_map(|id| store.get(id)).collect();
    collector.add_all(&instances);
    let geometry = collector.finish();
    let conv = Converted::new(&geometry);
    let mut b = Builder {
        store: &store,
        conv,
        model: BrepModel::default(),
        analytic: options.analytic,
        units: analytic::Units::of(None),
        pending_edges: Vec::new(),
        pending_faces: Vec::new(),
    };
    b.bodies(&order);
    let loose_invalid = b.loose_shells_and_faces(&order);
    // The placements of the bodies do not depend on the geometry: they are
    // found while it is converted.
    let bodies = std::mem::take(&mut b.model.bodies);
    let (placed, ()) = rayon::join(
        || assembly::occurrences(&store, &order, &bodies),
        || b.read_geometry(),
    );
    b.model.bodies = bodies;
    for c in placed.occurrences.iter().filter_map(|o| o.context) {
        b.context(c);
    }
    b.model.occurrences = placed.occurrences;
    b.model.summary.invalid.extend(placed.invalid);
    b.model.summary.invalid.extend(loose_invalid);
    let mut summary_extra = BTreeMap::new();
    for &id in &order {
        let name = &store[&id].records[0].name;
        if PLACEMENTS.contains(&name.as_str()) && !placed.applied.contains(&id) {
            *summary_extra.entry(name.clone()).or_insert(0) += 1;
        }
    }
    let mut model = b.model;
    model.summary.not_applied = summary_extra;
    model.geometry = geometry;
    summarize(&mut model);
    // The instances are not needed any more: freed on a worker thread.
    rayon::spawn(move || drop(store));
    Ok(model)
}

/// Fill the counts of the summary from the model.
fn summarize(m: &mut BrepModel) {
    let s = &mut m.summary;
    let mut not_converted = |g: &GeometryRef, pcurve: bool| {
        let missing = if pcurve {
            &mut s.pcurves_not_converted
        } else {
            &mut s.not_converted
        };
        match &g.geometry {
            Geometry::NotConverted => *missing.entry(g.kind.clone()).or_insert(0) += 1,
            Geometry::Analytic(a) if a.approximate.is_some() => {
                *s.approximate.entry(g.kind.clone()).or_insert(0) += 1;
            }
            _ => {}
        }
    };
    for f in m.faces.values() {
        not_converted(&f.surface, false);
    }
    for e in m.edges.values() {
        not_converted(&e.curve, false);
        for p in &e.pcurves {
            not_converted(&p.curve, true);
        }
    }
    for f in m.faces.values() {
        let written = match f.trimmed {
            Some(_) => "RECTANGULAR_TRIMMED_SURFACE",
            None => &f.surface.kind,
        };
        *s.faces_by_surface.entry(written.to_owned()).or_insert(0) += 1;
    }
    for e in m.edges.values() {
        *s.edges_by_curve.entry(e.curve.kind.clone()).or_insert(0) += 1;
        *s.edge_uses.entry(e.usage()).or_insert(0) += 1;
    }
}

impl Shell {
    /// How many oriented uses each edge has within this shell's faces (a
    /// closed manifold shell uses every edge exactly twice).
    pub fn edge_uses(&self, model: &BrepModel) -> BTreeMap<u64, usize> {
        let mut uses = BTreeMap::new();
        for f in &self.faces {
            for b in model.faces.get(f).map_or(&[][..], |f| &f.bounds) {
                if let Loop::Edges(es) = &b.edges {
                    for e in es {
                        *uses.entry(e.edge).or_insert(0) += 1;
                    }
                }
            }
        }
        uses
    }
}

mod analytic;
mod assembly;
mod pcurve;
pub use assembly::{Occurrence, Placement, MAX_OCCURRENCES};
#[cfg(test)]
mod tests;
