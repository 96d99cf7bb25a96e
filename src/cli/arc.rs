//! `arc --cos-half C --lambda L --points B0;B1;B2 [--direction B]`: the
//! standard-form rational cubic of source 004 eq. (1) (eq. (2) for θ = π).

use super::parse_list;
use crate::algebra::scalar::{Field, Tolerance};
use crate::arc::{ArcCubic, QuadArc};
use crate::error::Error;
use crate::io::{parse_rational, patch_to_json, JsonScalar, Patch};
use num_rational::BigRational;
use serde_json::Value;

/// Arguments of `arc`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// c = cos(θ/2) of the centre angle θ, exact text (1/2, 0.6); −1/2 < c < 1.
    #[arg(long = "cos-half", alias = "theta-cos", allow_hyphen_values = true)]
    cos_half: String,
    /// The family parameter λ, exact text; must lie in the admissible interval.
    #[arg(long, allow_hyphen_values = true)]
    lambda: String,
    /// Control points of the quadratic arc, `x,y;x,y;x,y` (b̄₀; b̄₁; b̄₂), or
    /// `x,y;x,y` (b̄₀; b̄₂) with --direction when c = 0 (θ = π).
    #[arg(long, allow_hyphen_values = true)]
    points: String,
    /// θ = π only: the direction b ⟂ b̄₂ − b̄₀ with |b| = radius, `x,y`.
    #[arg(long, allow_hyphen_values = true)]
    direction: Option<String>,
}

/// Build the arc, then the cubic; `exact` says whether it is exact.
pub fn run(a: &Args) -> Result<Value, Error> {
    let c = parse_rational(&a.cos_half)?;
    let lambda = parse_rational(&a.lambda)?;
    let pts = a
        .points
        .split(';')
        .map(parse_list)
        .collect::<Result<Vec<_>, _>>()?;
    let arc = match (pts.as_slice(), &a.direction) {
        ([b0, b1, b2], None) => QuadArc::from_control(b0, b1, b2, &c, Tolerance::EXACT)?,
        ([b0, b2], Some(d)) if c == BigRational::from_integer(0.into()) => {
            QuadArc::semicircle(b0, b2, &parse_list(d)?, Tolerance::EXACT)?
        }
        _ => {
            return Err(Error::Shape(
                "--points takes three points b̄₀;b̄₁;b̄₂, or two points b̄₀;b̄₂ with --direction when cos(θ/2) = 0".into(),
            ))
        }
    };
    let cubic = arc.cubic_for_lambda(&lambda)?;
    let exact = cubic.is_exact();
    let mut out = match cubic {
        ArcCubic::Exact(c) => curve_json(c)?,
        ArcCubic::Approx(c) => curve_json(c)?,
    };
    if let Value::Object(map) = &mut out {
        map.insert("exact".into(), exact.into());
        map.insert("cos_half".into(), c.to_json());
        map.insert("lambda".into(), lambda.to_json());
    }
    Ok(out)
}

fn curve_json<T: JsonScalar + Field>(c: crate::curve::RationalCurve<T>) -> Result<Value, Error> {
    patch_to_json(&Patch::Curve(c))
}
