//! The audit of a STEP B-rep from its own topology: every `EDGE_CURVE` of
//! the model classified by how the faces' loops use it, faces of every
//! surface type counted, and the tolerances the verdicts are taken against.
//!
//! An edge is
//! - **degenerate** when its 3D curve is converted and every piece is one
//!   point (all control points equal, exactly): a zero-length edge;
//! - otherwise by its oriented uses in the loops ([`Edge::usage`]):
//!   **shared** (two uses by two faces), **seam** (two uses by one face, a
//!   cylinder's seam line), **open** (one use: a hole in a solid, the
//!   border of a surface model), **non-manifold** (more than two uses), or
//!   **unused** (no loop uses it).
//!
//! Every shared and seam edge is measured ([`super::joint`]): certified
//! gaps, angle and curvature difference with G0/G1/G2 verdicts against the
//! tolerances, where both faces have a closed form (elementary surfaces, a
//! cone's slope exact or enclosed, and extrusions of a line or of a circle
//! along its axis: [`crate::analytic::ClosedForm`]); other edges are *not
//! measured*, with the reason counted.
//!
//! The length tolerance is `--tol` when given, else the declared
//! `UNCERTAINTY_MEASURE_WITH_UNIT` of the model's representation contexts
//! (the largest when they differ), in the model's length unit.

use super::certify::closed_form::ISurface;
use super::certify::spline::{SplineField, SplineSurface};
use super::certify::Verdict;
use super::joint::{
    measure_joint, JointFace, JointMeasures, JointSurface, JointTolerances, EDGE_WORK,
};
use super::knots::{surface_knot_lines, KnotLine};
use super::swept::{swept_grid, SweptGrid};
use crate::algebra::{Interval, Ordered, RealAlgebraic, Scalar};
use crate::curve::RationalCurve;
use crate::limits::{self, Limits};
use crate::nurbs::Nurbs;
use crate::patch::Patch;
use crate::step::brep::{Edge, EdgeUse, Face, Geometry};
use crate::step::BrepModel;
use crate::Tolerance;
use num_rational::BigRational;
use rayon::prelude::*;
use std::collections::{BTreeMap, HashMap};

type Q = BigRational;

/// The default angular tolerance, in radians: `1e-6` (tangent planes of a
/// G1 edge may differ by up to a micro-radian, well above the rounding of
/// decimals written with 15 significant digits, ~1e-14).
pub fn default_angle_tolerance() -> Q {
    Q::new(1.into(), 1_000_000.into())
}

/// The default curvature tolerance: 1 per metre in the model's length
/// unit (`10⁻³` per millimetre, `0.0254` per inch), `10⁻³` per unit when
/// the model declares no unit — two faces whose normal curvatures across
/// an edge differ by less are G2 (radii of curvature above a metre agree
/// with a plane).
pub fn default_curvature_tolerance(metres_per_unit: Option<&Q>) -> Q {
    metres_per_unit
        .cloned()
        .unwrap_or_else(|| Q::new(1.into(), 1000.into()))
}

/// The tolerances asked for: `None` length takes the model's declared one,
/// `None` curvature the default for the model's unit.
#[derive(Clone, Debug, PartialEq)]
pub struct ToleranceRequest {
    /// Length (`--tol`), in the model's unit.
    pub length: Option<Q>,
    /// Angle (`--angle-tol`), radians.
    pub angle: Q,
    /// Difference of normal curvatures (`--curvature-tol`), per model
    /// length unit.
    pub curvature: Option<Q>,
}

impl Default for ToleranceRequest {
    /// The model's length tolerance, [`default_angle_tolerance`],
    /// [`default_curvature_tolerance`].
    fn default() -> Self {
        ToleranceRequest {
            length: None,
            angle: default_angle_tolerance(),
            curvature: None,
        }
    }
}

/// How an edge of the B-rep is used.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum EdgeClass {
    /// Two uses by two faces.
    Shared,
    /// Two uses by one face.
    Seam,
    /// One use.
    Open,
    /// More than two uses.
    NonManifold,
    /// Zero length: every piece of its curve is one point.
    Degenerate,
    /// No loop uses it.
    Unused,
}

impl EdgeClass {
    /// The name used in the JSON output.
    pub fn name(self) -> &'static str {
        match self {
            EdgeClass::Shared => "shared",
            EdgeClass::Seam => "seam",
            EdgeClass::Open => "open",
            EdgeClass::NonManifold => "non_manifold",
            EdgeClass::Degenerate => "degenerate",
            EdgeClass::Unused => "unused",
        }
    }

    /// Every class, in output order.
    pub const ALL: [EdgeClass; 6] = [
        EdgeClass::Shared,
        EdgeClass::Seam,
        EdgeClass::Open,
        EdgeClass::NonManifold,
        EdgeClass::Degenerate,
        EdgeClass::Unused,
    ];
}

/// One edge of the B-rep with its class.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepEdge {
    /// The `EDGE_CURVE` id.
    pub id: u64,
    /// Its 3D curve's type.
    pub curve: String,
    /// The faces using it, once per use.
    pub faces: Vec<u64>,
    /// Its class.
    pub class: EdgeClass,
    /// Its measures (shared and seam edges).
    pub measured: Measured,
}

/// The continuity measures of an edge.
#[derive(Clone, Debug, PartialEq)]
pub enum Measured {
    /// Not a shared or seam edge: nothing to measure.
    NotApplicable,
    /// Not measured: why.
    NotMeasured(String),
    /// Measured.
    Measured(Box<JointMeasures>),
}

/// The continuity an edge is counted under: the highest order whose
/// verdict holds (exact or within tolerance), unless an undecided order
/// comes first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Grade {
    /// G0, G1 and G2 hold.
    G2,
    /// G0 and G1 hold, G2 fails.
    G1,
    /// G0 holds, G1 fails (a crease).
    G0,
    /// G0 fails (a gap over the tolerance).
    Fails,
    /// The first order that does not hold is undecided.
    Undecided,
}

impl Grade {
    /// The name used in the JSON output.
    pub fn name(self) -> &'static str {
        match self {
            Grade::G2 => "G2",
            Grade::G1 => "G1",
            Grade::G0 => "G0",
            Grade::Fails => "fails",
            Grade::Undecided => "undecided",
        }
    }

    /// The grade of measured verdicts, and whether the orders it counts
    /// hold exactly (deviation proved 0).
    pub fn of(m: &JointMeasures) -> (Grade, bool) {
        let exact = |v: &Verdict| *v == Verdict::Exact;
        match (&m.g0, &m.g1, &m.g2) {
            (Verdict::Undecided, _, _) => (Grade::Undecided, false),
            (Verdict::Fails { .. }, _, _) => (Grade::Fails, false),
            (_, Verdict::Undecided, _) => (Grade::Undecided, false),
            (g0, Verdict::Fails { .. }, _) => (Grade::G0, exact(g0)),
            (_, _, Some(Verdict::Undecided) | None) => (Grade::Undecided, false),
            (g0, g1, Some(Verdict::Fails { .. })) => (Grade::G1, exact(g0) && exact(g1)),
            (g0, g1, Some(g2)) => (Grade::G2, exact(g0) && exact(g1) && exact(g2)),
        }
    }
}

/// Where the length tolerance came from.
#[derive(Clone, Debug, PartialEq)]
pub enum ToleranceSource {
    /// `--tol`.
    Given,
    /// The model's `UNCERTAINTY_MEASURE_WITH_UNIT`.
    Declared,
    /// Neither: no length tolerance (only exact verdicts).
    None,
}

/// The tolerances verdicts are taken against.
#[derive(Clone, Debug, PartialEq)]
pub struct Tolerances {
    /// Length, in the model's length unit.
    pub length: Option<Q>,
    /// The length unit's name, when the model declares one.
    pub unit: Option<String>,
    /// Angle, in radians.
    pub angle: Q,
    /// Difference of normal curvatures, per length unit.
    pub curvature: Q,
    /// Where `length` came from.
    pub source: ToleranceSource,
}

/// The B-rep audit's findings.
#[derive(Clone, Debug)]
pub struct BrepAudit {
    /// Faces by surface type (all faces, converted or not).
    pub faces_by_surface: BTreeMap<String, usize>,
    /// Every edge, by id.
    pub edges: Vec<BrepEdge>,
    /// The tolerances.
    pub tolerance: Tolerances,
    /// Faces and edges whose geometry is not converted, by type.
    pub not_converted: BTreeMap<String, usize>,
    /// The interior knot lines of every B-spline face, by face id (faces
    /// without any are left out): the continuity of the face's own
    /// surface, not a seam ([`super::knots`]).
    pub knot_lines: BTreeMap<u64, Vec<KnotLine>>,
    /// Entities that could not be read.
    pub invalid: usize,
}

/// Does a B-spline curve visibly run between two points: clamped ends
/// (its first and last control points are its ends) that are not the
/// same projective point? (No conversion to pieces needed.)
fn distinct_ends(n: &Nurbs) -> bool {
    let Nurbs::Curve(c) = n else {
        return false;
    };
    match (c.control_points().first(), c.control_points().last()) {
        (Some(a), Some(b)) if c.knots().is_clamped() => {
            !a.same_projective_point(b, Tolerance::EXACT)
        }
        _ => false,
    }
}

/// Do all pieces of `g` collapse to one point?
fn zero_length(g: &Geometry) -> bool {
    fn one_point<'a, T: Ordered>(mut pieces: impl Iterator<Item = &'a Patch<T>>) -> bool {
        let mut first = None;
        pieces.all(|p| match p {
            Patch::Curve(c) => c.ctrl().iter().all(|x| {
                let f = first.get_or_insert_with(|| x.clone());
                x.same_projective_point(f, Tolerance::EXACT)
            }),
            _ => false,
        }) && first.is_some()
    }
    match g {
        Geometry::BSpline(b) if distinct_ends(b.nurbs()) => false,
        Geometry::BSpline(b) => one_point(b.pieces().iter().map(|s| &s.patch)),
        Geometry::Analytic(a) => one_point(a.pieces.iter()),
        Geometry::NotConverted | Geometry::Invalid(_) => false,
    }
}

/// The class of edge `e`.
pub fn classify(e: &Edge) -> EdgeClass {
    if zero_length(&e.curve.geometry) {
        return EdgeClass::Degenerate;
    }
    match e.usage() {
        EdgeUse::Unused => EdgeClass::Unused,
        EdgeUse::Open => EdgeClass::Open,
        EdgeUse::Shared => EdgeClass::Shared,
        EdgeUse::Seam => EdgeClass::Seam,
        EdgeUse::NonManifold => EdgeClass::NonManifold,
    }
}

/// The edge's curve as Bézier pieces over the real algebraic numbers, or
/// why not.
fn edge_pieces(e: &Edge) -> Result<Vec<RationalCurve<RealAlgebraic>>, String> {
    let curves = |ps: Vec<Patch<RealAlgebraic>>| {
        ps.into_iter()
            .map(|p| match p {
                Patch::Curve(c) => Ok(c),
                _ => Err("the edge curve's pieces are not curves".to_string()),
            })
            .collect()
    };
    match &e.curve.geometry {
        Geometry::Analytic(a) if a.approximate.is_some() => {
            Err(format!("{} edge converted approximately", e.curve.kind))
        }
        Geometry::Analytic(a) => curves(a.pieces.clone()),
        Geometry::BSpline(b) => curves(
            b.pieces()
                .iter()
                .map(|p| p.patch.map(RealAlgebraic::from_rational))
                .collect(),
        ),
        Geometry::NotConverted | Geometry::Invalid(_) => {
            Err(format!("{} edge curve not converted", e.curve.kind))
        }
    }
}

/// The face as a [`JointFace`], or why not.
fn joint_face<'a>(f: &'a Face, splines: &'a Splines<'a>) -> Result<JointFace<'a>, String> {
    match &f.surface.geometry {
        Geometry::Analytic(a) => match &a.closed_form {
            Some(c) => {
                let surface = match c.exact_implicit() {
                    Some(s) => JointSurface::Exact(s),
                    None => JointSurface::Enclosed(ISurface::enclosing(c).ok_or_else(|| {
                        format!(
                            "{} face: a torus whose major radius is negative",
                            f.surface.kind
                        )
                    })?),
                };
                Ok(JointFace {
                    surface,
                    same_sense: f.same_sense != c.reversed,
                })
            }
            None => spline_face(f, splines),
        },
        Geometry::BSpline(_) => spline_face(f, splines),
        Geometry::NotConverted | Geometry::Invalid(_) => {
            Err(format!("{} face not converted", f.surface.kind))
        }
    }
}

/// A face measured through its Bézier pieces: a B-spline face, or a swept
/// one with no closed form ([`super::swept`]).
fn spline_face<'a>(f: &'a Face, splines: &'a Splines<'a>) -> Result<JointFace<'a>, String> {
    match splines.get(&f.id) {
        Some(Ok(s)) => Ok(JointFace {
            surface: JointSurface::Spline(Box::new(SplineField::new(s))),
            same_sense: f.same_sense,
        }),
        Some(Err(why)) => Err(format!("{} face: {why}", f.surface.kind)),
        None => Err(format!("{} face not read", f.surface.kind)),
    }
}

/// The surfaces of the faces measured through their pieces, by face id,
/// or why not.
type Splines<'a> = HashMap<u64, Result<SplineSurface<'a>, String>>;

/// The grids of the swept faces with no closed form, by face id, or why
/// not.
type SweptGrids = HashMap<u64, Result<SweptGrid, String>>;

fn swept_grids(m: &BrepModel) -> SweptGrids {
    m.faces
        .values()
        .filter_map(|f| Some((f.id, swept_grid(f)?)))
        .collect()
}

/// The surface of every B-spline face of `m` and of every swept face of
/// `swept`, its pieces enclosed at first use by any of its edges.
fn spline_surfaces<'a>(m: &'a BrepModel, swept: &'a SweptGrids) -> Splines<'a> {
    let splines = m.faces.values().filter_map(|f| match &f.surface.geometry {
        Geometry::BSpline(b) => Some((
            f.id,
            match b.nurbs() {
                Nurbs::Surface(s) => SplineSurface::new(s, b.pieces()).map_err(|e| e.to_string()),
                Nurbs::Curve(_) => Err("its geometry is a curve".into()),
            },
        )),
        _ => None,
    });
    let swept = swept.iter().map(|(id, g)| {
        let surface = g.as_ref().map_err(Clone::clone).and_then(|g| {
            let [su, sv] = &g.smooth;
            SplineSurface::from_pieces(&g.pieces, |b| su.contains(b), |b| sv.contains(b))
                .map_err(|e| e.to_string())
        });
        (*id, surface)
    });
    splines.chain(swept).collect()
}

/// Measure a shared or seam edge.
fn measure(m: &BrepModel, splines: &Splines<'_>, e: &Edge, tol: &JointTolerances) -> Measured {
    let faces = || -> Result<[JointFace<'_>; 2], String> {
        let face = |id: &u64| {
            m.faces
                .get(id)
                .ok_or_else(|| format!("face #{id} not read"))
                .and_then(|f| joint_face(f, splines))
        };
        Ok([face(&e.used_by[0])?, face(&e.used_by[1])?])
    };
    let run = || -> Result<JointMeasures, String> {
        let pieces = edge_pieces(e)?;
        measure_joint(&pieces, &faces()?, tol).map_err(|x| format!("not measurable: {x}"))
    };
    match run() {
        Ok(j) => Measured::Measured(Box::new(j)),
        Err(why) => Measured::NotMeasured(why),
    }
}

/// Edges measured together, on all cores. Each gets a work cap fixed when
/// its batch starts: [`EDGE_WORK`], or an equal share of what is left of the
/// budget when that is less. The verdicts do not depend on the number of
/// threads, and the batches' work stays within the budget.
const EDGE_BATCH: usize = 64;

/// [`measure`] every edge of `edges`, in order, in parallel batches.
fn measure_all(m: &BrepModel, edges: &[&Edge], tol: &JointTolerances) -> Vec<Measured> {
    // The B-spline faces' exact pieces, converted on all cores before the
    // surfaces below take them one by one.
    m.convert_pieces();
    let swept = swept_grids(m);
    let splines = spline_surfaces(m, &swept);
    let outer = limits::current();
    let mut out = Vec::with_capacity(edges.len());
    for batch in edges.chunks(EDGE_BATCH) {
        let left = outer.max_work.saturating_sub(limits::charged());
        let cap = Limits {
            max_work: EDGE_WORK.min(left / batch.len() as u64),
            ..outer
        };
        let runs: Vec<_> = batch
            .par_iter()
            .map(|e| limits::detached(cap, || measure(m, &splines, e, tol)))
            .collect();
        for run in runs {
            limits::absorb(&run);
            out.push(run.result);
        }
    }
    out
}

/// The length tolerance: `given`, else the largest declared one; the
/// curvature tolerance: `given`, else the default for the model's unit.
fn tolerances(m: &BrepModel, asked: &ToleranceRequest) -> Tolerances {
    let length_unit = m.contexts.values().find_map(|c| c.length.as_ref());
    let unit = length_unit.map(|u| u.name.clone());
    let curvature = asked
        .curvature
        .clone()
        .unwrap_or_else(|| default_curvature_tolerance(length_unit.map(|u| &u.metres)));
    let declared = m
        .contexts
        .values()
        .filter_map(|c| c.tolerance.clone())
        .max();
    let (length, source) = match (asked.length.clone(), declared) {
        (Some(t), _) => (Some(t), ToleranceSource::Given),
        (None, Some(t)) => (Some(t), ToleranceSource::Declared),
        (None, None) => (None, ToleranceSource::None),
    };
    Tolerances {
        length,
        unit,
        angle: asked.angle.clone(),
        curvature,
        source,
    }
}

/// Audit the B-rep `m`: its edges classified, its faces counted, every
/// shared and seam edge measured against the tolerances `asked`.
///
/// ```
/// use exact_bezier::audit::brep::{audit_brep, EdgeClass, ToleranceRequest};
/// let m = exact_bezier::step::read_brep(std::fs::File::open(
///     "tests/fixtures/step/red_cube_blue_cylinder.step").map(std::io::BufReader::new).unwrap()).unwrap();
/// let a = audit_brep(&m, &ToleranceRequest::default());
/// assert_eq!(a.count(EdgeClass::Open), 0);
/// ```
pub fn audit_brep(m: &BrepModel, asked: &ToleranceRequest) -> BrepAudit {
    audit_with(m, asked, true)
}

/// [`audit_brep`] without the measures (every edge
/// [`Measured::NotApplicable`]): the topology, faces and tolerances only.
pub fn audit_brep_topology(m: &BrepModel, asked: &ToleranceRequest) -> BrepAudit {
    audit_with(m, asked, false)
}

fn audit_with(m: &BrepModel, asked: &ToleranceRequest, measured: bool) -> BrepAudit {
    let tolerance = tolerances(m, asked);
    let joint = JointTolerances {
        length: tolerance.length.as_ref().map(Interval::enclose),
        angle: Interval::enclose(&tolerance.angle),
        curvature: Interval::enclose(&tolerance.curvature),
    };
    let edges: Vec<&Edge> = m.edges.values().collect();
    let classes: Vec<EdgeClass> = edges.iter().map(|e| classify(e)).collect();
    let to_measure: Vec<&Edge> = edges
        .iter()
        .zip(&classes)
        .filter(|(_, c)| measured && matches!(c, EdgeClass::Shared | EdgeClass::Seam))
        .map(|(e, _)| *e)
        .collect();
    let mut results = measure_all(m, &to_measure, &joint).into_iter();
    let edges = edges
        .into_iter()
        .zip(classes)
        .map(|(e, class)| BrepEdge {
            id: e.id,
            curve: e.curve.kind.clone(),
            faces: e.used_by.clone(),
            measured: match class {
                EdgeClass::Shared | EdgeClass::Seam if measured => {
                    results.next().expect("one result per edge measured")
                }
                _ => Measured::NotApplicable,
            },
            class,
        })
        .collect();
    let knot_lines = m
        .faces
        .values()
        .collect::<Vec<_>>()
        .par_iter()
        .filter_map(|f| match &f.surface.geometry {
            Geometry::BSpline(b) => match b.nurbs() {
                Nurbs::Surface(s) => Some((f.id, surface_knot_lines(s))),
                Nurbs::Curve(_) => None,
            },
            _ => None,
        })
        .filter(|(_, lines)| !lines.is_empty())
        .collect::<Vec<_>>()
        .into_iter()
        .collect();
    BrepAudit {
        faces_by_surface: m.summary.faces_by_surface.clone(),
        edges,
        tolerance,
        not_converted: m.summary.not_converted.clone(),
        knot_lines,
        invalid: m.summary.invalid.len(),
    }
}

impl BrepAudit {
    /// How many edges are of class `c`.
    pub fn count(&self, c: EdgeClass) -> usize {
        self.edges.iter().filter(|e| e.class == c).count()
    }

    /// All faces.
    pub fn faces(&self) -> usize {
        self.faces_by_surface.values().sum()
    }

    /// Measured edges by [`Grade`], and how many of each hold exactly.
    pub fn grades(&self) -> BTreeMap<Grade, [usize; 2]> {
        let mut out = BTreeMap::new();
        for e in &self.edges {
            if let Measured::Measured(j) = &e.measured {
                let (g, exact) = Grade::of(j);
                let c: &mut [usize; 2] = out.entry(g).or_default();
                c[0] += 1;
                c[1] += usize::from(exact);
            }
        }
        out
    }

    /// Edges not measured, by reason.
    pub fn not_measured(&self) -> BTreeMap<String, usize> {
        let mut out = BTreeMap::new();
        for e in &self.edges {
            if let Measured::NotMeasured(why) = &e.measured {
                *out.entry(why.clone()).or_default() += 1;
            }
        }
        out
    }

    /// The knot lines of all faces by continuity: `"C0"`, `"C1"`, … and
    /// `"removable"` (one polynomial across the knot).
    pub fn knot_line_counts(&self) -> BTreeMap<String, usize> {
        let mut out = BTreeMap::new();
        for line in self.knot_lines.values().flatten() {
            let key = line
                .continuity
                .map_or_else(|| "removable".to_string(), |r| format!("C{r}"));
            *out.entry(key).or_default() += 1;
        }
        out
    }

    /// The one-line summary, naming what was not done.
    pub fn summary(&self) -> String {
        let n = |c| self.count(c);
        let skipped: usize = self.not_converted.values().sum();
        let grades = self.grades();
        let g = |k| grades.get(&k).map_or(0, |c| c[0]);
        let exact: usize = grades.values().map(|c| c[1]).sum();
        let not_measured = self.not_measured();
        let knot_counts = self.knot_line_counts();
        let knots = if knot_counts.is_empty() {
            "none".to_string()
        } else {
            let list: Vec<String> = knot_counts
                .iter()
                .map(|(c, k)| format!("{k} {c}"))
                .collect();
            list.join(", ")
        };
        let why = if not_measured.is_empty() {
            String::new()
        } else {
            let list: Vec<String> = not_measured
                .iter()
                .map(|(w, k)| format!("{k} {w}"))
                .collect();
            format!(" ({})", list.join("; "))
        };
        format!(
            "{} faces, {} edges: {} shared, {} seam, {} open, {} non-manifold, {} degenerate, {} unused; \
             continuity of the {} shared and seam edges: {} G2, {} G1, {} G0, {} fail G0, {} undecided ({} exact), \
             {} not measured{why}; \
             knot lines inside {} B-spline faces: {knots}; \
             {skipped} faces or edges with geometry not converted, {} entities unreadable",
            self.faces(),
            self.edges.len(),
            n(EdgeClass::Shared),
            n(EdgeClass::Seam),
            n(EdgeClass::Open),
            n(EdgeClass::NonManifold),
            n(EdgeClass::Degenerate),
            n(EdgeClass::Unused),
            n(EdgeClass::Shared) + n(EdgeClass::Seam),
            g(Grade::G2),
            g(Grade::G1),
            g(Grade::G0),
            g(Grade::Fails),
            g(Grade::Undecided),
            exact,
            not_measured.values().sum::<usize>(),
            self.knot_lines.len(),
            self.invalid,
        )
    }
}
