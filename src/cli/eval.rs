//! `eval FILE --at U[,V] [--scalar f64]`.

use super::{check_domain, parse_list, read_input, run_each, PatchOp, ScalarKind};
use crate::algebra::scalar::Ordered;
use crate::error::Error;
use crate::io::{point_to_json, read_patches, JsonScalar, Patch};
use serde_json::{json, Value};

/// Arguments of `eval`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// Parameter(s): t for a curve, u,v for a rect or tri patch (exact text: 1/3, 0.25).
    /// Trig patches: tau=1/3[,tau=1/2] (exact, τ = tan(t/2)) or angles in radians (f64).
    #[arg(long, allow_hyphen_values = true)]
    at: String,
    /// Scalar to compute with.
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
    /// Allow parameters outside the patch's domain ([0,1], [0,1]², or the
    /// triangle u, v ≥ 0, u + v ≤ 1): the polynomial continued beyond it.
    #[arg(long)]
    extrapolate: bool,
}

pub fn run(a: &Args) -> Result<Value, Error> {
    let text = read_input(&a.file)?;
    if let Some(trig) = crate::io::trig::read_trig_patches(&text)? {
        return super::eval_trig::run(&trig, &a.at, a.scalar);
    }
    let params = parse_list(&a.at)?;
    let patches = read_patches(&text)?;
    if patches.is_empty() {
        return Err(Error::Shape(format!(
            "{:?} holds an empty array: no curve or patch to evaluate",
            a.file
        )));
    }
    if !a.extrapolate {
        for p in &patches {
            check_domain(p, &params)?;
        }
    }
    run_each(&patches, &params, a.scalar, &Eval)
}

/// The point of a curve at `t` or of a patch at `(u, v)`.
struct Eval;

impl PatchOp for Eval {
    const NAME: &'static str = "eval";

    fn apply<T: JsonScalar + Ordered>(&self, p: &Patch<T>, params: &[T]) -> Result<Value, Error> {
        eval_with(p, params)
    }
}

fn eval_with<T: JsonScalar + Ordered>(p: &Patch<T>, params: &[T]) -> Result<Value, Error> {
    let want = if matches!(p, Patch::Curve(_)) { 1 } else { 2 };
    if params.len() != want {
        return Err(Error::Shape(format!(
            "a {} takes {want} parameter(s) in --at, not {}",
            p.kind(),
            params.len()
        )));
    }
    let point = match p {
        Patch::Curve(c) => c.eval(&params[0])?,
        Patch::Rect(r) => r.eval(&params[0], &params[1])?,
        Patch::Tri(t) => t.eval(&params[0], &params[1])?,
    };
    Ok(json!({ "point": point_to_json(&point) }))
}
