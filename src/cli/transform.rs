//! `reparam` and `elevate`: transformations that return patches.

use super::{load, one_or_many, parse_list, ScalarKind};
use crate::error::Error;
use crate::io::{patch_to_json, JsonScalar, Patch};
use crate::scalar::Ordered;
use num_rational::BigRational;
use serde_json::Value;

/// Arguments of `reparam`.
#[derive(clap::Args, Debug)]
pub struct ReparamArgs {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// Linear Möbius map u = (α−1)s/(2αs−s−α): ALPHA for a curve, ALPHA,BETA
    /// for a rect patch; each strictly between 0 and 1.
    #[arg(long)]
    mobius: String,
    /// Scalar to compute with.
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
}

/// Arguments of `elevate`.
#[derive(clap::Args, Debug)]
pub struct ElevateArgs {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// Degree increase: R for a curve, R,S for a rect patch (non-negative integers).
    #[arg(long, default_value = "1")]
    by: String,
}

pub fn reparam(a: &ReparamArgs) -> Result<Value, Error> {
    let params = parse_list(&a.mobius)?;
    for p in &params {
        if !(p > &BigRational::from_integer(0.into()) && p < &BigRational::from_integer(1.into())) {
            return Err(Error::Domain(format!(
                "Möbius parameter {p} must lie strictly between 0 and 1 (weights stay positive and [0,1] maps onto itself)"
            )));
        }
    }
    let out = load(&a.file)?
        .iter()
        .map(|p| match a.scalar {
            ScalarKind::Exact => mobius_with(p, &params),
            ScalarKind::F64 => mobius_with(
                &p.to_f64(),
                &params.iter().map(Ordered::to_f64).collect::<Vec<_>>(),
            ),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(out))
}

fn mobius_with<T: JsonScalar + Ordered>(p: &Patch<T>, params: &[T]) -> Result<Value, Error> {
    let moved = match (p, params) {
        (Patch::Curve(c), [alpha]) => Patch::Curve(c.mobius(alpha)),
        (Patch::Rect(r), [alpha, beta]) => Patch::Rect(r.mobius_u(alpha).mobius_v(beta)),
        (Patch::Tri(_), _) => {
            return Err(Error::Shape(
                "a Möbius map in one parameter does not apply to a tri patch".into(),
            ))
        }
        _ => {
            return Err(Error::Shape(format!(
                "--mobius takes {} value(s) for a {}, not {}",
                if matches!(p, Patch::Curve(_)) { 1 } else { 2 },
                p.kind(),
                params.len()
            )))
        }
    };
    patch_to_json(&moved)
}

pub fn elevate(a: &ElevateArgs) -> Result<Value, Error> {
    let by: Vec<usize> =
        a.by.split(',')
            .map(|s| {
                s.trim()
                    .parse::<usize>()
                    .ok()
                    .filter(|r| *r <= crate::error::MAX_DEGREE)
                    .ok_or_else(|| {
                        Error::Domain(format!(
                            "--by {s:?} is not an integer from 0 to {}",
                            crate::error::MAX_DEGREE
                        ))
                    })
            })
            .collect::<Result<_, _>>()?;
    let out = load(&a.file)?
        .iter()
        .map(|p| {
            let raised = match (p, by.as_slice()) {
                (Patch::Curve(c), [r]) => Patch::Curve(c.elevate(*r)),
                _ => {
                    return Err(Error::Shape(format!(
                        "--by {} does not apply to a {}",
                        a.by,
                        p.kind()
                    )))
                }
            };
            patch_to_json(&raised)
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(out))
}
