//! `reduce FILE [--method forrest|farin|lsq|exact] [--scalar f64 --tol T]`:
//! lower the degree of a curve by one, `{"method": ..., "curve": {...}}`.
//! `exact` adds `"reducible": true|false` and gives `"curve": null` when the
//! curve is not of lower degree (exit 0 either way). A Forrest or Farin
//! reduction can leave the domain (a weight ≤ 0): the curve is still
//! written, with `"valid": false` and `"problem"`, and the exit code is 3.

use super::deriv::curve_of;
use super::{charge_each, check_tol, load, one_or_many, patch_f64, ScalarKind};
use clap::ValueEnum;
use exact_bezier::algebra::{Ordered, Tolerance};
use exact_bezier::curve::reduction::Reduction;
use exact_bezier::io::{patch_to_json, JsonScalar};
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use serde_json::{json, Value};

/// The reduction method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum, Default)]
pub enum Method {
    /// Forrest (1972): forward recursion for the first half, backward after.
    Forrest,
    /// Farin (1983): blend of the two recursions.
    #[default]
    Farin,
    /// Constrained least squares: minimal perturbation, then exact.
    Lsq,
    /// Exact: only when the curve truly is of lower degree.
    Exact,
}

/// Arguments of `reduce`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// Reduction method.
    #[arg(long, value_enum, default_value_t)]
    method: Method,
    /// Scalar to compute with.
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
    /// Absolute tolerance of the f64 degeneracy test of `exact`.
    #[arg(long, default_value_t = 1e-9)]
    tol: f64,
}

pub fn run(a: &Args) -> Result<Value, Error> {
    check_tol(a.tol)?;
    let patches = load(&a.file)?;
    // Recursions over the net (least squares: a dense (n+1)² system),
    // mostly on small numbers: (n+1)³(d+1)/32 operations (calibrated,
    // `cli/benches/cost_model.rs`).
    charge_each("reduce", &patches, a.scalar, |s| {
        let n1 = s.total_degree() + 1;
        (
            (n1 * n1 * n1 * (s.dim as u64 + 1)).div_ceil(32),
            s.grown_bits(2 * n1, s.bits),
        )
    })?;
    let values = patches
        .iter()
        .map(|p| match a.scalar {
            ScalarKind::Exact => reduce_with(p, a.method, Tolerance::EXACT),
            ScalarKind::F64 => reduce_with(&patch_f64(p)?, a.method, Tolerance(a.tol)),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(values))
}

fn reduce_with<T: JsonScalar + Ordered>(
    p: &Patch<T>,
    method: Method,
    tol: Tolerance,
) -> Result<Value, Error> {
    let c = curve_of(p, "reduce")?;
    let scheme = match method {
        Method::Forrest => Reduction::Forrest,
        Method::Farin => Reduction::Farin,
        Method::Lsq => Reduction::LeastSquares,
        Method::Exact => {
            let reduced = c
                .reduce_exact(tol)
                .map(|r| patch_to_json(&Patch::Curve(r)))
                .transpose()?;
            return Ok(json!({
                "method": "exact",
                "reducible": reduced.is_some(),
                "curve": reduced,
            }));
        }
    };
    let name = format!("{method:?}").to_lowercase();
    let reduced = c.reduce(scheme)?;
    let mut v = json!({ "method": name, "curve": patch_to_json(&Patch::Curve(reduced.clone()))? });
    if let Some(i) = reduced
        .weights()
        .iter()
        .position(|w| !w.is_positive_within(tol))
    {
        // Outside the valid domain: written, flagged, exit 3 (module docs).
        v["valid"] = false.into();
        v["problem"] = format!(
            "weight w_{i} of the reduced curve is not positive: the {name} reduction left the domain of rational Bézier curves"
        )
        .into();
        super::mark_outside_domain();
    }
    Ok(v)
}
