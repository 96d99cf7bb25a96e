//! `audit FILE [--summary]`: the exact audit of a patch model (JSON patches,
//! NURBS JSON, geomdl JSON or STEP): shared edges with their G0/G1/G2
//! verdicts, open and degenerate edges, duplicates, pieces of one surface.
//! See `docs/audit.md`.

use super::open_input;
use crate::audit::{audit, read_model};
use crate::error::Error;
use serde_json::{json, Value};

/// Arguments of `audit`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON or STEP), or - for standard input.
    file: String,
    /// Print only the summary and the counts.
    #[arg(long)]
    summary: bool,
}

pub fn run(a: &Args) -> Result<Value, Error> {
    let model = read_model(open_input(&a.file)?)?;
    let report = audit(&model)?;
    if a.summary {
        let [g0, g1, g2, u] = report.counts();
        return Ok(json!({"summary": report.summary(), "counts": {"G0": g0, "G1": g1, "G2": g2, "undecided": u}}));
    }
    Ok(report.to_json(&model))
}
