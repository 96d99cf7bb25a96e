//! The command line (DESIGN §5): subcommands read the JSON interchange
//! format (a path, or `-` for standard input) and write JSON to standard
//! output. Exit codes: 0 success, 1 a `prove` claim off its expected
//! verdict, 2 bad input (one line on standard error). Never a panic.
//!
//! Exact arithmetic is the default; `--scalar f64` selects floats.

use crate::error::Error;
use crate::io::{read_patches, JsonScalar, Patch};
use crate::scalar::Ordered;
use clap::{Parser, Subcommand, ValueEnum};
use num_rational::BigRational;
use serde_json::Value;
use std::io::Read;

mod arc;
mod audit;
mod coincide;
mod convert;
mod curvature;
mod dedup;
mod deriv;
mod eval;
mod eval_trig;
mod figures;
mod is_circle;
mod join;
mod mesh;
mod plot;
mod prove;
mod reduce;
mod standardize;
mod transform;

/// Rational Bézier curves and patches, exactly.
#[derive(Parser, Debug)]
#[command(name = "exact-bezier", version, about)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// Which scalar a command computes with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum, Default)]
pub enum ScalarKind {
    /// Exact rationals (default).
    #[default]
    Exact,
    /// IEEE double precision.
    F64,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Evaluate a curve or patch: {"point": [...]}.
    Eval(eval::Args),
    /// Reparameterize: linear Möbius map (--mobius ALPHA[,BETA]) or quadratic map of a rect (--quadratic A1,A2,B1,B2).
    Reparam(transform::ReparamArgs),
    /// Standard form: end weights 1 (curve) or corner weights 1 (rect).
    Standardize(standardize::Args),
    /// Raise the degree (--by R[,S]).
    Elevate(transform::ElevateArgs),
    /// Convert rect ↔ tri (--to tri | --to rect [--split a,b,c,d,e,f] [--degenerate]).
    Convert(convert::Args),
    /// Run every proof in proofs/ and print one line per claim.
    Prove(prove::Args),
    /// Draw curves and patches as SVG or PNG (-o OUT.svg|OUT.png).
    Plot(plot::Args),
    /// Triangulate patches with normals as OBJ, STL or PLY (-o OUT.obj).
    Mesh(mesh::Args),
    /// Regenerate the figure gallery (docs/figures/gallery.json).
    Figures(figures::Args),
    /// Derivative of a curve: {"order": K, "derivative": [...]}.
    Deriv(deriv::Args),
    /// Curvature of a curve: {"curvature_squared": κ² (exact), "curvature": κ (f64)}.
    Curvature(curvature::Args),
    /// G0/G1/G2 verdicts for the join of curve A's end to curve B's start.
    Join(join::Args),
    /// Lower the degree of a curve by one (--method forrest|farin|lsq|exact).
    Reduce(reduce::Args),
    /// A circular arc as a standard-form rational cubic (source 004 eq. 1).
    Arc(arc::Args),
    /// Does a curve lie on a circle? Exact centre and radius², or the reason.
    IsCircle(is_circle::Args),
    /// Are two curves or rect patches the same up to reparameterization?
    Coincide(coincide::Args),
    /// Group a JSON array of curves/rect patches into coincidence classes.
    Dedup(dedup::Args),
    /// Exact audit of a model (JSON, NURBS or STEP): shared edges G0/G1/G2, open/degenerate edges, duplicates.
    Audit(audit::Args),
}

/// Run the command line; returns the process exit code.
pub fn main() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            let _ = e.print();
            return if e.use_stderr() { 2 } else { 0 };
        }
    };
    let result = match cli.command {
        Command::Eval(a) => eval::run(&a),
        Command::Reparam(a) => transform::reparam(&a),
        Command::Elevate(a) => transform::elevate(&a),
        Command::Standardize(a) => standardize::run(&a),
        Command::Convert(a) => convert::run(&a),
        Command::Prove(a) => return prove::run(&a),
        Command::Plot(a) => plot::run(&a),
        Command::Mesh(a) => mesh::run(&a),
        Command::Figures(a) => figures::run(&a),
        Command::Deriv(a) => deriv::run(&a),
        Command::Curvature(a) => curvature::run(&a),
        Command::Join(a) => join::run(&a),
        Command::Reduce(a) => reduce::run(&a),
        Command::Arc(a) => arc::run(&a),
        Command::IsCircle(a) => is_circle::run(&a),
        Command::Coincide(a) => coincide::run(&a),
        Command::Dedup(a) => dedup::run(&a),
        Command::Audit(a) => audit::run(&a),
    };
    match result {
        Ok(v) => {
            emit(&serde_json::to_string_pretty(&v).unwrap_or_default());
            0
        }
        Err(e) => {
            eprintln!("error: {e}");
            2
        }
    }
}

/// Write `text` and a newline to standard output. A closed pipe (e.g.
/// `exact-bezier prove | head`) is not an error: the reader has what it
/// wanted, so write errors are ignored rather than panicking as `println!`
/// would.
pub(crate) fn emit(text: &str) {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    let _ = writeln!(out, "{text}").and_then(|()| out.flush());
}

/// Read the text of `path` (`-` for standard input).
pub(crate) fn read_input(path: &str) -> Result<String, Error> {
    if path == "-" {
        let mut s = String::new();
        std::io::stdin()
            .read_to_string(&mut s)
            .map_err(|e| Error::Format(format!("cannot read standard input: {e}")))?;
        Ok(s)
    } else {
        std::fs::read_to_string(path).map_err(|e| Error::Format(format!("cannot read {path}: {e}")))
    }
}

/// A buffered stream over `path` (`-` for standard input), for readers
/// that stream (STEP).
pub(crate) fn open_input(path: &str) -> Result<Box<dyn std::io::BufRead>, Error> {
    if path == "-" {
        return Ok(Box::new(std::io::BufReader::new(std::io::stdin())));
    }
    let f =
        std::fs::File::open(path).map_err(|e| Error::Format(format!("cannot read {path}: {e}")))?;
    Ok(Box::new(std::io::BufReader::with_capacity(1 << 16, f)))
}

/// Read the patches of `path`.
pub(crate) fn load(path: &str) -> Result<Vec<Patch<BigRational>>, Error> {
    read_patches(&read_input(path)?)
}

/// The single curve or patch of `path`; `count_error(n)` words the error
/// when it holds `n ≠ 1`.
pub(crate) fn load_one(
    path: &str,
    count_error: impl Fn(usize) -> String,
) -> Result<Patch<BigRational>, Error> {
    let mut patches = load(path)?;
    if patches.len() != 1 {
        return Err(Error::Shape(count_error(patches.len())));
    }
    Ok(patches.swap_remove(0))
}

/// Check the `--tol` of an f64 comparison: finite and ≥ 0.
///
/// # Errors
///
/// [`Error::NotFinite`] naming the value otherwise.
pub(crate) fn check_tol(tol: f64) -> Result<(), Error> {
    if !(tol.is_finite() && tol >= 0.0) {
        return Err(Error::NotFinite(format!(
            "--tol {tol} must be finite and ≥ 0"
        )));
    }
    Ok(())
}

/// Parse a comma-separated list of exact numbers (`1/3,0.25`).
pub(crate) fn parse_list(text: &str) -> Result<Vec<BigRational>, Error> {
    text.split(',').map(crate::io::parse_rational).collect()
}

/// A command's computation on one patch with exact parameters, written once
/// for every scalar (see [`run_each`]).
pub(crate) trait PatchOp {
    /// The JSON result for `p` at `params` (converted to the patch's scalar).
    fn apply<T: JsonScalar + Ordered>(&self, p: &Patch<T>, params: &[T]) -> Result<Value, Error>;
}

/// Apply `op` to every patch with the chosen scalar: exactly, or on the
/// nearest `f64` patch and parameters. One value for a single patch, an
/// array for several.
///
/// # Errors
///
/// The first error of `op`.
pub(crate) fn run_each(
    patches: &[Patch<BigRational>],
    params: &[BigRational],
    scalar: ScalarKind,
    op: &impl PatchOp,
) -> Result<Value, Error> {
    let values = patches
        .iter()
        .map(|p| match scalar {
            ScalarKind::Exact => op.apply(p, params),
            ScalarKind::F64 => op.apply(
                &p.to_f64(),
                &params.iter().map(Ordered::to_f64).collect::<Vec<_>>(),
            ),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(values))
}

/// One value for a single patch, an array for several.
pub(crate) fn one_or_many(mut values: Vec<Value>) -> Value {
    if values.len() == 1 {
        values.swap_remove(0)
    } else {
        Value::Array(values)
    }
}
