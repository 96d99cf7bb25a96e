//! `audit FILE [--summary]`: the exact audit of a patch model (JSON patches,
//! NURBS JSON, geomdl JSON or STEP): shared edges with their G0/G1/G2
//! verdicts, open and degenerate edges, duplicates, pieces of one surface.
//! See `docs/audit.md`.

use super::open_input;
use exact_bezier::audit::{audit, Audit, Continuity, ExactModel, Model, PatchEdge, SeamScalar};
use exact_bezier::coincide::boundary_curve;
use exact_bezier::io::{audit_to_json, read_exact_model, JsonScalar};
use exact_bezier::patch::Patch;
use exact_bezier::render::plot::{plot_colored_png, PlotOptions};
use exact_bezier::Error;
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
}

pub fn run(a: &Args) -> Result<Value, Error> {
    match read_exact_model(open_input(&a.file)?)? {
        ExactModel::Rational(m) => run_on(&m, a),
        ExactModel::Algebraic(m) => run_on(&m, a),
    }
}

/// The audit of a model over either exact scalar.
fn run_on<T: SeamScalar + JsonScalar>(model: &Model<T>, a: &Args) -> Result<Value, Error> {
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
fn plot<T: SeamScalar>(model: &Model<T>, report: &Audit<T>, out: &str) -> Result<(), Error> {
    if !out.ends_with(".png") {
        return Err(Error::Format(format!(
            "--plot writes PNG: {out} should end in .png"
        )));
    }
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
    let opts = PlotOptions {
        iso: 3,
        samples: 24,
        net: false,
        title: format!("exact-bezier audit: {}", report.summary()),
        ..PlotOptions::default()
    };
    let png = plot_colored_png(&items, &opts)?;
    std::fs::write(out, png).map_err(|e| Error::Format(format!("cannot write {out}: {e}")))
}
