//! `deriv FILE --at T [--order K] [--scalar f64]`: the K-th derivative of a
//! curve at T, `{"order": K, "derivative": [...]}` (exact by default).

use super::{load, one_or_many, parse_list, ScalarKind};
use crate::curve::RationalCurve;
use crate::error::{Error, MAX_DEGREE};
use crate::io::{point_to_json, JsonScalar, Patch};
use crate::scalar::Ordered;
use num_rational::BigRational;
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
}

/// The curve inside `p`, or a typed error naming the command.
pub(super) fn curve_of<'a, T: crate::scalar::Scalar>(
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

/// The single parameter of `--at`.
pub(super) fn single_parameter(text: &str) -> Result<BigRational, Error> {
    let mut values = parse_list(text)?;
    if values.len() != 1 {
        return Err(Error::Shape(format!(
            "--at takes one parameter t for a curve, not {}",
            values.len()
        )));
    }
    Ok(values.swap_remove(0))
}

pub fn run(a: &Args) -> Result<Value, Error> {
    if a.order > MAX_DEGREE + 1 {
        return Err(Error::Domain(format!(
            "--order {} is over the limit of {}",
            a.order,
            MAX_DEGREE + 1
        )));
    }
    let t = single_parameter(&a.at)?;
    let values = load(&a.file)?
        .iter()
        .map(|p| match a.scalar {
            ScalarKind::Exact => deriv_with(p, &t, a.order),
            ScalarKind::F64 => deriv_with(&p.to_f64(), &t.to_f64(), a.order),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(values))
}

fn deriv_with<T: JsonScalar + Ordered>(p: &Patch<T>, t: &T, order: usize) -> Result<Value, Error> {
    let d = curve_of(p, "deriv")?.deriv(t, order)?;
    Ok(json!({ "order": order, "derivative": point_to_json(&d) }))
}
