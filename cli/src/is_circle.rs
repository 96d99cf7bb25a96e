//! `is-circle FILE`: does a curve lie on a circle? Exact.

use super::{charge_each, load, one_or_many, ScalarKind};
use exact_bezier::algebra::Tolerance;
use exact_bezier::curve::circle::{circle_of, integer_coords};
use exact_bezier::io::{point_to_json, JsonScalar};
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use serde_json::{json, Value};

/// Arguments of `is-circle`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON curve, or an array of curves), or - for standard input.
    file: String,
}

/// `{"circle": true, "center": [...], "radius_squared": ...}` or
/// `{"circle": false, "reason": "..."}` per curve.
pub fn run(a: &Args) -> Result<Value, Error> {
    let patches = load(&a.file)?;
    charge_each("is-circle", &patches, ScalarKind::Exact, |s| {
        let n1 = s.total_degree() + 1;
        let d1 = s.dim as u64 + 1;
        // Cleared denominators: up to one factor per stored number.
        let cleared = s.bits.saturating_mul(n1 * d1);
        // Integer arithmetic on the cleared net, most of it on the small
        // coefficients: (n+1)²(d+1)/64 operations (calibrated,
        // `cli/benches/cost_model.rs`).
        ((n1 * n1 * d1).div_ceil(64), cleared.saturating_mul(2))
    })?;
    let values = patches
        .iter()
        .map(|p| match p {
            Patch::Curve(c) => Ok(match circle_of(&integer_coords(c), Tolerance::EXACT) {
                Ok(circle) => json!({
                    "circle": true,
                    "center": point_to_json(&circle.center),
                    "radius_squared": circle.radius_squared.to_json(),
                }),
                Err(reason) => json!({ "circle": false, "reason": reason.to_string() }),
            }),
            other => Err(Error::Shape(format!(
                "is-circle takes curves, not a {}",
                other.kind()
            ))),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(values))
}
