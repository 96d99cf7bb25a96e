//! `join A B [--scalar f64 --tol T]`: G⁰/G¹/G² verdicts for the join of the
//! end of curve A to the start of curve B, `{"g0", "g1", "g2", "alpha",
//! "beta", "reason"}`. Exact by default (no tolerance); `--tol` applies to
//! `f64` only.

use super::deriv::curve_of;
use super::{charge_each, check_tol, load_one, patch_f64, ScalarKind};
use exact_bezier::algebra::{Ordered, Tolerance};
use exact_bezier::curve::join::join;
use exact_bezier::io::JsonScalar;
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use num_rational::BigRational;
use serde_json::{json, Value};

/// Arguments of `join`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The first curve (its end, t = 1), JSON file or - for standard input.
    first: String,
    /// The second curve (its start, t = 0).
    second: String,
    /// Scalar to compute with.
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
    /// Absolute tolerance for f64 comparisons (ignored by exact arithmetic).
    #[arg(long, default_value_t = 1e-9)]
    tol: f64,
}

fn one_curve(path: &str) -> Result<Patch<BigRational>, Error> {
    load_one(path, |n| {
        format!("{path} holds {n} objects; join takes one curve per file")
    })
}

pub fn run(a: &Args) -> Result<Value, Error> {
    check_tol(a.tol)?;
    let (p, q) = (one_curve(&a.first)?, one_curve(&a.second)?);
    // End derivatives up to order 2 and a few products of them: 3
    // evaluations' operations, 16 each as for `deriv` (calibrated,
    // `cli/benches/cost_model.rs`).
    charge_each("join", &[p.clone(), q.clone()], a.scalar, |s| {
        (48 * s.eval_ops(), s.bits.saturating_mul(8))
    })?;
    match a.scalar {
        ScalarKind::Exact => join_with(&p, &q, Tolerance::EXACT),
        ScalarKind::F64 => join_with(&patch_f64(&p)?, &patch_f64(&q)?, Tolerance(a.tol)),
    }
}

fn join_with<T: JsonScalar + Ordered>(
    p: &Patch<T>,
    q: &Patch<T>,
    tol: Tolerance,
) -> Result<Value, Error> {
    let j = join(curve_of(p, "join")?, curve_of(q, "join")?, tol)?;
    Ok(json!({
        "g0": j.g0,
        "g1": j.g1,
        "g2": j.g2,
        "alpha": j.alpha.as_ref().map(JsonScalar::to_json),
        "beta": j.beta.as_ref().map(JsonScalar::to_json),
        "reason": j.reason,
    }))
}
