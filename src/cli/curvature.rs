//! `curvature FILE --at T [--scalar f64]`: `{"curvature_squared": κ²,
//! "curvature": κ}` — κ² exact by default, κ always as `f64` (κ is
//! irrational in general).

use super::deriv::{curve_of, single_parameter};
use super::{load, run_each, PatchOp, ScalarKind};
use crate::algebra::scalar::Ordered;
use crate::error::Error;
use crate::io::{JsonScalar, Patch};
use crate::limits::Size;
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
    /// Allow t outside [0, 1] (the polynomial continued beyond the curve).
    #[arg(long)]
    extrapolate: bool,
}

pub fn run(a: &Args) -> Result<Value, Error> {
    let t = single_parameter(&a.at, a.extrapolate)?;
    run_each(&load(&a.file)?, &[t], a.scalar, &Curvature)
}

/// κ² (exact for exact `T`) and κ of a curve at `params[0]`.
struct Curvature;

impl PatchOp for Curvature {
    const NAME: &'static str = "curvature";

    /// κ² from the first two derivatives: three evaluations, then a few
    /// products (numbers up to 8× the evaluation's size).
    fn cost(&self, s: &Size, param_bits: u64) -> (u64, u64) {
        let bits = s.grown_bits(s.total_degree() + 2, param_bits);
        (3 * s.eval_ops(), bits.saturating_mul(8))
    }

    /// κ as `f64` is left out when it overflows (κ² is exact and always
    /// given); with `--scalar f64` an overflowed κ² is an error.
    fn apply<T: JsonScalar + Ordered>(&self, p: &Patch<T>, params: &[T]) -> Result<Value, Error> {
        let k2 = curve_of(p, "curvature")?.curvature_sq(&params[0])?;
        let kappa = k2.to_f64().sqrt();
        let mut v = json!({ "curvature_squared": k2.to_json() });
        if kappa.is_finite() {
            v["curvature"] = kappa.into();
        }
        Ok(v)
    }
}
