//! `curvature FILE --at T [--scalar f64]`: `{"curvature_squared": κ²,
//! "curvature": κ}` — κ² exact by default, κ always as `f64` (κ is
//! irrational in general).

use super::deriv::{curve_of, single_parameter};
use super::{load, one_or_many, ScalarKind};
use crate::error::Error;
use crate::io::{JsonScalar, Patch};
use crate::scalar::Ordered;
use serde_json::{json, Value};

/// Arguments of `curvature`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// Parameter t (exact text: 1/3, 0.25).
    #[arg(long, allow_hyphen_values = true)]
    at: String,
    /// Scalar to compute with.
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
}

pub fn run(a: &Args) -> Result<Value, Error> {
    let t = single_parameter(&a.at)?;
    let values = load(&a.file)?
        .iter()
        .map(|p| match a.scalar {
            ScalarKind::Exact => curvature_with(p, &t),
            ScalarKind::F64 => curvature_with(&p.to_f64(), &t.to_f64()),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(values))
}

fn curvature_with<T: JsonScalar + Ordered>(p: &Patch<T>, t: &T) -> Result<Value, Error> {
    let k2 = curve_of(p, "curvature")?.curvature_sq(t)?;
    Ok(json!({ "curvature_squared": k2.to_json(), "curvature": k2.to_f64().sqrt() }))
}
