//! `curvature FILE --at T [--scalar f64]`: `{"curvature_squared": κ²,
//! "curvature": κ, "curvature_approx": κ as f64}` — exact by default: κ² is
//! rational and κ = √κ² a real algebraic number (a rational when κ² is a
//! square, `sqrt(q)`-style text otherwise); with `--scalar f64` both are
//! numbers and there is no `curvature_approx`.

use super::deriv::{curve_of, single_parameter};
use super::{load, run_each, PatchOp, ScalarKind};
use crate::algebra::scalar::{Ordered, Roots, Scalar};
use crate::algebra::RealAlgebraic;
use crate::error::Error;
use crate::io::parse_own_rational;
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
    let mut v = run_each(&load(&a.file)?, &[t], a.scalar, &Curvature)?;
    if a.scalar == ScalarKind::Exact {
        match &mut v {
            Value::Array(items) => items.iter_mut().try_for_each(exact_kappa)?,
            one => exact_kappa(one)?,
        }
    }
    Ok(v)
}

/// Replace the `f64` κ of an exact result by κ = √κ², exactly (the `f64`
/// value moves to `curvature_approx`). κ² is read back from the result's
/// own exact text.
fn exact_kappa(v: &mut Value) -> Result<(), Error> {
    let text = match &v["curvature_squared"] {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    };
    let k2 = RealAlgebraic::from_rational(&parse_own_rational(&text)?);
    let kappa = k2
        .nth_root(2)
        .ok_or_else(|| Error::Domain(format!("κ² = {text} is negative")))?;
    let approx = v["curvature"].take();
    v["curvature"] = kappa.to_json();
    if !approx.is_null() {
        v["curvature_approx"] = approx;
    }
    Ok(())
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
