//! `reparam` and `elevate`: transformations that return patches.

use super::{
    charge_each, load_exact, on_exact, one_or_many, parse_algebraic_list, parse_list, run_each,
    ExactPatches, ExactScalar, PatchOp, ScalarKind,
};
use exact_bezier::algebra::Ordered;
use exact_bezier::io::{patch_to_json, JsonScalar};
use exact_bezier::limits::{check_degree, Size};
use exact_bezier::patch::Patch;
use exact_bezier::reparam::Quadratic;
use exact_bezier::Error;
use serde_json::Value;

/// Arguments of `reparam`.
#[derive(clap::Args, Debug)]
#[command(group(clap::ArgGroup::new("map").required(true).args(["mobius", "quadratic"])))]
pub struct ReparamArgs {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// Linear Möbius map u = (α−1)s/(2αs−s−α): ALPHA for a curve, ALPHA,BETA
    /// for a rect patch; each strictly between 0 and 1.
    #[arg(long, group = "map")]
    mobius: Option<String>,
    /// Quadratic map of a rect patch (source 000, eqs 9-17), the paper's
    /// convention: α(t) = α1·t + α2·(1−t) in u(s,t), β(s) = β1·s + β2·(1−s)
    /// in v(s,t); A1,A2,B1,B2 each strictly between 0 and 1. The result has
    /// bidegree (m+n, m+n).
    #[arg(long, group = "map")]
    quadratic: Option<String>,
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
    let (text, quadratic) = match (&a.mobius, &a.quadratic) {
        (Some(m), None) => (m, false),
        (None, Some(q)) => (q, true),
        _ => {
            return Err(Error::Domain(
                "give exactly one of --mobius and --quadratic".into(),
            ))
        }
    };
    let op = Reparam { quadratic };
    match (load_exact(&a.file)?, parse_list(text)) {
        (ExactPatches::Rational(patches), Ok(params)) => op.run(&patches, &params, a.scalar),
        (patches, rational) => {
            let params = parse_algebraic_list(text)
                .map_err(|algebraic| rational.err().unwrap_or(algebraic))?;
            op.run(&patches.into_algebraic(), &params, a.scalar)
        }
    }
}

impl Reparam {
    /// Check the parameters and the result's degree, then map every patch.
    fn run<T: ExactScalar>(
        &self,
        patches: &[Patch<T>],
        params: &[T],
        scalar: ScalarKind,
    ) -> Result<Value, Error> {
        for p in params {
            if !(p > &T::zero() && p < &T::one()) {
                return Err(Error::Domain(format!(
                    "reparameterization parameter {p} must lie strictly between 0 and 1 (weights stay positive and [0,1] maps onto itself)"
                )));
            }
        }
        if self.quadratic {
            for p in patches {
                if let Patch::Rect(r) = p {
                    let (m, n) = r.degree();
                    check_degree(m + n)?;
                }
            }
        }
        run_each(patches, params, scalar, self)
    }
}

/// A Möbius map (or, if `quadratic`, the quadratic map of a rect patch).
struct Reparam {
    quadratic: bool,
}

impl PatchOp for Reparam {
    const NAME: &'static str = "reparam";

    /// Möbius: one evaluation's work and the net written. Quadratic: every
    /// coefficient of the (N, N) result (N = m + n) sums over the whole
    /// net, on numbers grown by 2N parameter factors, 8 operations a term
    /// (calibrated, `cli/benches/cost_model.rs`), and the result written.
    fn cost(&self, s: &Size, param_bits: u64) -> (u64, u64) {
        if !self.quadratic {
            return (
                s.eval_ops() + s.write_ops(s.stored_numbers()),
                s.grown_bits(s.total_degree(), param_bits),
            );
        }
        let (m, n) = (s.degree.0 as u64, s.degree.1 as u64);
        let big = m + n + 1;
        let d1 = s.dim as u64 + 1;
        let ops = 8 * big * big * (m + 1) * (n + 1) * d1 + s.write_ops(big * big * d1);
        (ops, s.grown_bits(2 * (m + n), param_bits))
    }

    fn apply<T: JsonScalar + Ordered>(&self, p: &Patch<T>, params: &[T]) -> Result<Value, Error> {
        reparam_with(p, params, self.quadratic)
    }
}

fn reparam_with<T: JsonScalar + Ordered>(
    p: &Patch<T>,
    params: &[T],
    quadratic: bool,
) -> Result<Value, Error> {
    if quadratic {
        return match (p, params) {
            (Patch::Rect(r), [a1, a2, b1, b2]) => {
                patch_to_json(&Patch::Rect(r.quadratic_reparam(&Quadratic {
                    alpha1: a1.clone(),
                    alpha2: a2.clone(),
                    beta1: b1.clone(),
                    beta2: b2.clone(),
                })))
            }
            (Patch::Rect(_), _) => Err(Error::Shape(format!(
                "--quadratic takes 4 values A1,A2,B1,B2, not {}",
                params.len()
            ))),
            _ => Err(Error::Shape(format!(
                "--quadratic applies to a rect patch, not a {}",
                p.kind()
            ))),
        };
    }
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
                    .filter(|r| *r <= exact_bezier::MAX_DEGREE)
                    .ok_or_else(|| {
                        Error::Domain(format!(
                            "--by {s:?} is not an integer from 0 to {}",
                            exact_bezier::MAX_DEGREE
                        ))
                    })
            })
            .collect::<Result<_, _>>()?;
    on_exact!(load_exact(&a.file)?, patches => elevate_each(&patches, &by, &a.by))
}

/// `elevate` on exact patches over `T`; `text` is the `--by` argument.
fn elevate_each<T: ExactScalar>(
    patches: &[Patch<T>],
    by: &[usize],
    text: &str,
) -> Result<Value, Error> {
    for p in patches {
        let (m, n) = match p {
            Patch::Curve(c) => (c.degree(), 0),
            Patch::Rect(q) => q.degree(),
            Patch::Tri(t) => (t.degree(), 0),
        };
        check_degree(m + by[0])?;
        check_degree(n + by.get(1).copied().unwrap_or(0))?;
    }
    charge_each("elevate", patches, ScalarKind::Exact, |s| {
        let (r, t) = (by[0], by.get(1).copied().unwrap_or(0));
        let (m, n) = (s.degree.0 + r, s.degree.1 + t);
        // Every new coefficient a fresh fraction with binomial
        // denominators, written out: 16 operations a term (calibrated,
        // `cli/benches/cost_model.rs`).
        let ops = 16 * ((m + 1) * (n + 1) * (m + n + 2) * (s.dim + 1)) as u64
            + s.write_ops(((m + 1) * (n + 1) * (s.dim + 1)) as u64);
        (ops, s.bits + 2 * (m + n) as u64)
    })?;
    let out = patches
        .iter()
        .map(|p| {
            let raised = match (p, by) {
                (Patch::Curve(c), [r]) => Patch::Curve(c.elevate(*r)),
                (Patch::Rect(q), [r, s]) => Patch::Rect(q.elevate(*r, *s)),
                _ => {
                    return Err(Error::Shape(format!(
                        "--by {text} does not apply to a {}",
                        p.kind()
                    )))
                }
            };
            patch_to_json(&raised)
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(out))
}
