//! `audit FILE [--summary]`: the audit of a STEP B-rep from its topology
//! (edges classified shared / seam / open / non-manifold / degenerate,
//! faces by surface type, tolerances), or the exact audit of a patch model
//! without topology (JSON patches, NURBS JSON, geomdl JSON, STEP surfaces
//! without edges): shared edges with their G0/G1/G2 verdicts, open and
//! degenerate edges, duplicates, pieces of one surface. See `docs/audit.md`.

use super::open_input;
use exact_bezier::algebra::parse_rational;
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::audit::brep::{
    audit_brep, default_angle_tolerance, BrepAudit, EdgeClass, Grade, Measured, ToleranceRequest,
};
use exact_bezier::audit::{audit, Audit, Continuity, ExactModel, Model, PatchEdge, SeamScalar};
use exact_bezier::coincide::boundary_curve;
use exact_bezier::io::{audit_to_json, brep_audit_to_json, is_step, read_exact_model, JsonScalar};
use exact_bezier::limits::{self, Cost, Size};
use exact_bezier::patch::Patch;
use exact_bezier::render::plot::{plot_colored_png, PlotOptions};
use exact_bezier::step::brep::Geometry;
use exact_bezier::step::{read_brep, BrepModel};
use exact_bezier::{Error, Scalar};
use num_rational::BigRational;
use serde_json::{json, Value};

/// Arguments of `audit`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON or STEP), or - for standard input.
    file: String,
    /// Print only the summary and the counts.
    #[arg(long)]
    summary: bool,
    /// Draw the model to OUT.png with seams coloured by verdict: G2 green,
    /// G1 blue, G0 red, undecided orange, open edges purple; patches brown.
    #[arg(long)]
    plot: Option<String>,
    /// Length tolerance for a STEP B-rep, an exact number in the model's
    /// length unit (default: the model's UNCERTAINTY_MEASURE_WITH_UNIT).
    #[arg(long)]
    tol: Option<String>,
    /// Angular tolerance for a STEP B-rep, in radians (default 1e-6).
    #[arg(long = "angle-tol")]
    angle_tol: Option<String>,
    /// Curvature tolerance for a STEP B-rep: the largest difference of
    /// normal curvatures across a G2 edge, per model length unit (default
    /// 1 per metre: 1e-3 per millimetre).
    #[arg(long = "curvature-tol")]
    curvature_tol: Option<String>,
}

/// A tolerance option: an exact non-negative number.
fn tolerance(text: &str, what: &str) -> Result<BigRational, Error> {
    let t = parse_rational(text)?;
    if t < BigRational::from_integer(0.into()) {
        return Err(Error::Format(format!(
            "{what} must not be negative, found {text}"
        )));
    }
    Ok(t)
}

pub fn run(a: &Args) -> Result<Value, Error> {
    let mut input = open_input(&a.file)?;
    if is_step(&mut input)? {
        let brep = read_brep(input)?;
        if !brep.edges.is_empty() {
            if let Some(out) = &a.plot {
                check_png_name(out)?;
            }
            let given = |t: &Option<String>, what| t.as_deref().map(|t| tolerance(t, what));
            let asked = ToleranceRequest {
                length: given(&a.tol, "--tol").transpose()?,
                angle: given(&a.angle_tol, "--angle-tol")
                    .unwrap_or_else(|| Ok(default_angle_tolerance()))?,
                curvature: given(&a.curvature_tol, "--curvature-tol").transpose()?,
            };
            let report = audit_brep(&brep, &asked);
            if let Some(out) = &a.plot {
                plot_brep(&brep, &report, out)?;
            }
            return Ok(brep_audit_to_json(&report, !a.summary));
        }
        return run_on(&Model::from_step(brep.geometry), a);
    }
    if a.tol.is_some() || a.angle_tol.is_some() || a.curvature_tol.is_some() {
        return Err(Error::Format(
            "--tol, --angle-tol and --curvature-tol apply to STEP B-rep input; patch models are audited exactly"
                .into(),
        ));
    }
    match read_exact_model(input)? {
        ExactModel::Rational(m) => run_on(&m, a),
        ExactModel::Algebraic(m) => run_on(&m, a),
    }
}

/// The audit of a model over either exact scalar, its work charged first.
fn run_on<T: SeamScalar + JsonScalar + Cost>(model: &Model<T>, a: &Args) -> Result<Value, Error> {
    let sizes = model.pieces.iter().map(|p| p.patch.size());
    limits::charge_sizes("audit", sizes, true, audit_cost)?;
    let report = audit(model)?;
    if let Some(out) = &a.plot {
        plot(model, &report, out)?;
    }
    if a.summary {
        let [g0, g1, g2, u] = report.counts();
        return Ok(
            json!({"summary": report.summary(), "counts": {"G0": g0, "G1": g1, "G2": g2, "undecided": u}}),
        );
    }
    Ok(audit_to_json(&report, model))
}

/// Estimated `(operations, bits)` of auditing one piece of a patch model:
/// its edges' jets, the matching of edges and the exact seam verdicts,
/// `16(N+1)³(d+1)` operations on its own numbers (calibrated,
/// `cli/benches/cost_model.rs`: the 32 bicubics of the teapot take about
/// 50 ms). The certified measures of an audit charge their own pieces as
/// they go (`docs/audit.md`).
fn audit_cost(s: &Size) -> (u64, u64) {
    let n1 = s.total_degree() + 1;
    (16 * n1.pow(3) * (s.dim as u64 + 1), s.bits)
}

/// Palette indices (see [`plot_colored_png`]).
const BROWN: usize = 6;
const PURPLE: usize = 3;

fn verdict_colour(c: Option<Continuity>) -> usize {
    match c {
        Some(Continuity::G2) => 2,
        Some(Continuity::G1) => 0,
        Some(Continuity::G0) => 1,
        None => 4,
    }
}

/// The model's patches (3 iso-lines each) and its seams and open edges.
fn plot<T: SeamScalar + Cost>(model: &Model<T>, report: &Audit<T>, out: &str) -> Result<(), Error> {
    check_png_name(out)?;
    let edge = |e: &PatchEdge| -> Patch<T> {
        match &model.pieces[e.patch].patch {
            Patch::Rect(r) => Patch::Curve(boundary_curve(r, e.edge)),
            other => other.clone(),
        }
    };
    let mut items: Vec<(Patch<T>, usize)> = model
        .pieces
        .iter()
        .filter(|p| matches!(p.patch, Patch::Rect(_)))
        .map(|p| (p.patch.clone(), BROWN))
        .collect();
    items.extend(report.open_edges.iter().map(|e| (edge(e), PURPLE)));
    items.extend(
        report
            .seams
            .iter()
            .map(|s| (edge(&s.a), verdict_colour(s.verdict.continuity))),
    );
    write_png(&items, report.summary(), out)
}

/// `--plot` writes PNG only.
fn check_png_name(out: &str) -> Result<(), Error> {
    if out.ends_with(".png") {
        Ok(())
    } else {
        Err(Error::Format(format!(
            "--plot writes PNG: {out} should end in .png"
        )))
    }
}

/// Draw `items` (3 iso-lines a patch, 24 samples a line) under the title
/// `summary` into the PNG `out`, charging the sampling and the pixels
/// first.
fn write_png<T: exact_bezier::Ordered + std::fmt::Display + Cost>(
    items: &[(Patch<T>, usize)],
    summary: String,
    out: &str,
) -> Result<(), Error> {
    let opts = PlotOptions {
        iso: 3,
        samples: 24,
        net: false,
        title: format!("exact-bezier audit: {summary}"),
        ..PlotOptions::default()
    };
    let samples: u64 = items
        .iter()
        .map(|(p, _)| p.size().eval_ops().saturating_mul(216))
        .sum();
    let pixels = u64::from(opts.width) * u64::from(opts.height);
    limits::charge(
        "audit --plot",
        limits::f64_work(samples)
            .saturating_add(pixels.saturating_mul(crate::plot::PNG_UNITS_PER_PIXEL)),
    )?;
    let png = plot_colored_png(items, &opts)?;
    std::fs::write(out, png).map_err(|e| Error::Format(format!("cannot write {out}: {e}")))
}

/// A B-rep's faces (their surfaces' pieces, brown) and its edges coloured
/// by what the audit found: shared and seam edges by their continuity
/// grade (G2 green, G1 blue, G0 red, G0 failing pink, undecided orange, not
/// measured cyan), open edges purple; other edges are not drawn.
fn plot_brep(m: &BrepModel, report: &BrepAudit, out: &str) -> Result<(), Error> {
    let lift = |p: &Patch<BigRational>| p.map(RealAlgebraic::from_rational);
    let pieces = |g: &Geometry| -> Vec<Patch<RealAlgebraic>> {
        match g {
            Geometry::BSpline(b) => b.pieces().iter().map(|s| lift(&s.patch)).collect(),
            Geometry::Analytic(a) => a.pieces.clone(),
            Geometry::NotConverted | Geometry::Invalid(_) => Vec::new(),
        }
    };
    let mut items: Vec<(Patch<RealAlgebraic>, usize)> = m
        .faces
        .values()
        .flat_map(|f| pieces(&f.surface.geometry))
        .map(|p| (p, BROWN))
        .collect();
    for e in &report.edges {
        let colour = match (&e.measured, e.class) {
            (Measured::Measured(j), _) => match Grade::of(j).0 {
                Grade::G2 => 2,
                Grade::G1 => 0,
                Grade::G0 => 1,
                Grade::Fails => 7,
                Grade::Undecided => 4,
            },
            (Measured::NotMeasured(_), _) => 5,
            (Measured::NotApplicable, EdgeClass::Open) => PURPLE,
            (Measured::NotApplicable, _) => continue,
        };
        if let Some(edge) = m.edges.get(&e.id) {
            items.extend(
                pieces(&edge.curve.geometry)
                    .into_iter()
                    .map(|p| (p, colour)),
            );
        }
    }
    write_png(&items, report.summary(), out)
}
