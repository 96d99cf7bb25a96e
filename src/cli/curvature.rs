//! `curvature FILE --at T [--scalar f64]`: `{"curvature_squared": κ²,
//! "curvature": κ}` — κ² exact by default, κ always as `f64` (κ is
//! irrational in general).

use super::deriv::{curve_of, single_parameter};
use super::{load, run_each, PatchOp, ScalarKind};
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
    run_each(&load(&a.file)?, &[t], a.scalar, &Curvature)
}

/// κ² (exact for exact `T`) and κ of a curve at `params[0]`.
struct Curvature;

impl PatchOp for Curvature {
    fn apply<T: JsonScalar + Ordered>(&self, p: &Patch<T>, params: &[T]) -> Result<Value, Error> {
        let k2 = curve_of(p, "curvature")?.curvature_sq(&params[0])?;
        Ok(json!({ "curvature_squared": k2.to_json(), "curvature": k2.to_f64().sqrt() }))
    }
}
