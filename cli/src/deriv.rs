//! `deriv FILE --at T [--order K] [--scalar f64]`: the K-th derivative of a
//! curve at T, `{"order": K, "derivative": [...]}` (exact by default).

use super::{load_exact, on_exact, parse_list, run_each, PatchOp, ScalarKind};
use exact_bezier::algebra::Ordered;
use exact_bezier::algebra::Scalar;
use exact_bezier::curve::RationalCurve;
use exact_bezier::error::Error;
use exact_bezier::io::{point_to_json, JsonScalar};
use exact_bezier::limits::Size;
use exact_bezier::limits::MAX_DEGREE;
use exact_bezier::patch::Patch;
use num_rational::BigRational;
use num_traits::{One, Zero};
use serde_json::{json, Value};

/// Arguments of `deriv`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// Parameter t (exact text: 1/3, 0.25).
    #[arg(long, allow_hyphen_values = true)]
    at: String,
    /// Order of the derivative (0 is the point itself).
    #[arg(long, default_value_t = 1)]
    order: usize,
    /// Scalar to compute with.
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
    /// Allow t outside [0, 1] (the polynomial continued beyond the curve).
    #[arg(long)]
    extrapolate: bool,
}

/// The curve inside `p`, or a typed error naming the command.
pub(super) fn curve_of<'a, T: exact_bezier::algebra::Scalar>(
    p: &'a Patch<T>,
    command: &str,
) -> Result<&'a RationalCurve<T>, Error> {
    match p {
        Patch::Curve(c) => Ok(c),
        other => Err(Error::Shape(format!(
            "{command} takes a curve, not a {}",
            other.kind()
        ))),
    }
}

/// The single parameter of `--at`, in `[0, 1]` unless `extrapolate`.
pub(super) fn single_parameter(text: &str, extrapolate: bool) -> Result<BigRational, Error> {
    let mut values = parse_list(text)?;
    if values.len() != 1 {
        return Err(Error::Shape(format!(
            "--at takes one parameter t for a curve, not {}",
            values.len()
        )));
    }
    let t = values.swap_remove(0);
    if !extrapolate && (t < BigRational::zero() || t > BigRational::one()) {
        return Err(Error::Domain(format!(
            "--at {t} is outside [0, 1] (give --extrapolate to evaluate the polynomial beyond the curve)"
        )));
    }
    Ok(t)
}

pub fn run(a: &Args) -> Result<Value, Error> {
    if a.order > MAX_DEGREE + 1 {
        return Err(Error::Domain(format!(
            "--order {} is over the limit of {}",
            a.order,
            MAX_DEGREE + 1
        )));
    }
    let t = single_parameter(&a.at, a.extrapolate)?;
    on_exact!(load_exact(&a.file)?, patches => {
        run_each(&patches, &[Scalar::from_rational(&t)], a.scalar, &Deriv(a.order))
    })
}

/// The derivative of the given order of a curve at `params[0]`.
struct Deriv(usize);

impl PatchOp for Deriv {
    const NAME: &'static str = "deriv";

    /// `16(k+1)` evaluations' operations: the derivative of a rational
    /// curve builds the hodographs of its homogeneous net exactly, every
    /// number a fresh fraction (calibrated, `cli/benches/cost_model.rs`).
    fn cost(&self, s: &Size, param_bits: u64) -> (u64, u64) {
        let k = self.0 as u64 + 1;
        (
            16 * k * s.eval_ops(),
            s.grown_bits(s.total_degree() + k, param_bits),
        )
    }

    fn apply<T: JsonScalar + Ordered>(&self, p: &Patch<T>, params: &[T]) -> Result<Value, Error> {
        let d = curve_of(p, "deriv")?.deriv(&params[0], self.0)?;
        Ok(json!({ "order": self.0, "derivative": point_to_json(&d) }))
    }
}
