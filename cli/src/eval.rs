//! `eval FILE --at U[,V] [--at …] | --grid N [--jsonl] [--scalar f64]`.
//!
//! One `--at`: `{"point": [...]}`. Several `--at`, or `--grid N`:
//! `{"points": [{"at": [...], "point": [...]}, …]}`, or with `--jsonl` one
//! such object per line, streamed (with `"patch": k` when the file holds
//! several patches). Grids: a curve at `t = i/N`; a rect at `(i/N, j/N)`,
//! `i` outer; a tri at `(i/N, j/N)` with `i + j ≤ N`, `i` outer.
//! Control points and weights may be algebraic numbers (the text grammar
//! of docs/FORMAT.md); the points then come out in that grammar.

use super::{
    check_domain, check_finite, emit, json_text, on_exact, one_or_many, parse_list, patch_f64,
    read_input, ExactPatches, ExactScalar, ScalarKind,
};
use exact_bezier::algebra::{Field, Scalar};
use exact_bezier::eval::Evaluator;
use exact_bezier::io::{point_to_json, JsonScalar};
use exact_bezier::limits::MAX_DOCUMENT_POINTS;
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use num_rational::BigRational;
use serde_json::{json, Value};

/// Points evaluated per batch (bounds memory when streaming).
const CHUNK: usize = 4096;

/// Arguments of `eval`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// Parameter point: t for a curve, u,v for a rect or tri patch (exact text: 1/3, 0.25).
    /// Repeat --at for several points. Trig patches: tau=1/3[,tau=1/2] (exact, τ = tan(t/2)),
    /// angle=pi/3[,angle=pi/4] (exact, multiples of π/12) or angles in radians (f64).
    #[arg(long, allow_hyphen_values = true, required_unless_present = "grid")]
    at: Vec<String>,
    /// Evaluate on a grid instead: curve t = i/N; rect (i/N, j/N); tri (i/N, j/N) with i + j ≤ N.
    #[arg(long, value_name = "N", conflicts_with = "at")]
    grid: Option<u64>,
    /// Write one JSON line per point ({"at", "point"}), streamed, instead of one document.
    #[arg(long)]
    jsonl: bool,
    /// Scalar to compute with.
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
    /// Allow parameters outside the patch's domain ([0,1], [0,1]², or the
    /// triangle u, v ≥ 0, u + v ≤ 1): the polynomial continued beyond it.
    #[arg(long)]
    extrapolate: bool,
}

/// The JSON result, or (with `--jsonl`) `Err(0)`: the lines are written.
///
/// Patches whose numbers are all rational run on `BigRational`; a file
/// with algebraic numbers (`"sqrt(6)/6"`, as `standardize` writes them)
/// runs the same code on [`RealAlgebraic`](exact_bezier::algebra::RealAlgebraic).
pub fn run(a: &Args) -> Result<Result<Value, i32>, Error> {
    let text = read_input(&a.file)?;
    if let Some(trig) = exact_bezier::io::trig::read_trig_patches(&text)? {
        if !is_single(a) {
            return Err(Error::Shape(
                "trig patches take one --at at a time (no --grid, --jsonl or repeated --at)".into(),
            ));
        }
        return super::eval_trig::run(&trig, &a.at[0], a.scalar).map(Ok);
    }
    on_exact!(ExactPatches::parse(&text)?, patches => run_patches(a, &patches))
}

/// The model's exact operations per work unit of `eval`: 128. Exact
/// evaluation is fraction-free (integer de Casteljau over a common
/// denominator, word-sized and 256-bit tiers first), so it costs about
/// 1/128 of the rational operations the model counts (rationals and sums
/// of radicals; number-field elements are charged in full); the parsing of the
/// input, charged apart, is most of an evaluation's time (calibrated,
/// `cli/benches/cost_model.rs`).
const EVAL_OPS_PER_UNIT: u64 = 128;

/// One point, written as `{"point": …}`.
fn is_single(a: &Args) -> bool {
    a.at.len() == 1 && a.grid.is_none() && !a.jsonl
}

/// `eval` on patches of exact numbers `T`: exactly, or on their nearest
/// `f64` patches. The work is charged first: [`Size::op_cost`](exact_bezier::limits::Size::op_cost)
/// times the exact model for one operation, over [`EVAL_OPS_PER_UNIT`]
/// (or [`f64_work`](exact_bezier::limits::f64_work) in `f64`).
fn run_patches<T: ExactScalar>(
    a: &Args,
    patches: &[Patch<T>],
) -> Result<Result<Value, i32>, Error> {
    let lists: Vec<Vec<BigRational>> =
        a.at.iter()
            .map(|s| parse_list(s))
            .collect::<Result<_, _>>()?;
    let mut values = Vec::with_capacity(patches.len());
    for (k, p) in patches.iter().enumerate() {
        let at = match a.grid {
            Some(n) => grid(p, n, a.jsonl)?,
            None => lists.clone(),
        };
        check_points(p, &at, a.extrapolate)?;
        let size = p.size();
        let points = at.len() as u64;
        let ops = size.eval_ops().saturating_mul(points) + size.write_ops(points * size.dim as u64);
        let units = match a.scalar {
            ScalarKind::Exact => {
                let bits = size.grown_bits(
                    size.total_degree(),
                    exact_bezier::limits::max_bits(at.iter().flatten()),
                );
                // Number-field arithmetic has no fraction-free shortcut.
                let per_unit = if size.field { 1 } else { EVAL_OPS_PER_UNIT };
                size.exact_units(ops, bits).div_ceil(per_unit)
            }
            ScalarKind::F64 => exact_bezier::limits::f64_work(ops),
        };
        exact_bezier::limits::charge("eval", units)?;
        let tag = a.jsonl.then(|| (patches.len() > 1).then_some(k));
        values.push(match a.scalar {
            ScalarKind::Exact => evaluate(p, &at, is_single(a), tag)?,
            ScalarKind::F64 => evaluate(&patch_f64(p)?, &at, is_single(a), tag)?,
        });
    }
    if a.jsonl {
        return Ok(Err(0));
    }
    Ok(Ok(one_or_many(values)))
}

/// `{"point": …}` for a single point, else `{"points": […]}` (or, with
/// `tag`, the lines written).
fn evaluate<U: JsonScalar + Field>(
    p: &Patch<U>,
    at: &[Vec<BigRational>],
    single: bool,
    tag: Option<Option<usize>>,
) -> Result<Value, Error> {
    if single {
        let params: Vec<U> = at[0].iter().map(U::from_rational).collect();
        let point = match p {
            Patch::Curve(c) => c.eval(&params[0])?,
            Patch::Rect(r) => r.eval(&params[0], &params[1])?,
            Patch::Tri(t) => t.eval(&params[0], &params[1])?,
        };
        return Ok(json!({ "point": point_to_json(&point) }));
    }
    Ok(json!({ "points": eval_points(p, at, tag)? }))
}

/// The grid parameter points of `p` (module docs), refusing grids too
/// large for one document.
fn grid<T: Scalar>(p: &Patch<T>, n: u64, jsonl: bool) -> Result<Vec<Vec<BigRational>>, Error> {
    if n == 0 {
        return Err(Error::Domain("--grid takes N ≥ 1".into()));
    }
    let count = match p {
        Patch::Curve(_) => n + 1,
        Patch::Rect(_) => (n + 1).saturating_mul(n + 1),
        Patch::Tri(_) => (n + 1).saturating_mul(n + 2) / 2,
    };
    if !jsonl && count > MAX_DOCUMENT_POINTS {
        return Err(Error::Limit(format!(
            "--grid {n} gives {count} points, more than {MAX_DOCUMENT_POINTS} in one document; add --jsonl to stream them"
        )));
    }
    exact_bezier::limits::charge("eval --grid", count)?;
    let q = |i: u64| BigRational::new((i as i64).into(), (n as i64).into());
    Ok(match p {
        Patch::Curve(_) => (0..=n).map(|i| vec![q(i)]).collect(),
        Patch::Rect(_) => (0..=n)
            .flat_map(|i| (0..=n).map(move |j| (i, j)))
            .map(|(i, j)| vec![q(i), q(j)])
            .collect(),
        Patch::Tri(_) => (0..=n)
            .flat_map(|i| (0..=n - i).map(move |j| (i, j)))
            .map(|(i, j)| vec![q(i), q(j)])
            .collect(),
    })
}

/// Each point has the parameter count of `p` and, unless extrapolating,
/// lies in its domain.
fn check_points<T: Scalar>(
    p: &Patch<T>,
    at: &[Vec<BigRational>],
    extrapolate: bool,
) -> Result<(), Error> {
    let want = if matches!(p, Patch::Curve(_)) { 1 } else { 2 };
    for params in at {
        if params.len() != want {
            return Err(Error::Shape(format!(
                "a {} takes {want} parameter(s) in --at, not {}",
                p.kind(),
                params.len()
            )));
        }
        if !extrapolate {
            check_domain(p, params)?;
        }
    }
    Ok(())
}

/// Evaluate `p` at every point of `at` in batches of [`CHUNK`]: the
/// `{"at", "point"}` objects, or (with `tag`, for `--jsonl`) each written
/// as a line at once and none kept.
fn eval_points<T: JsonScalar + Field>(
    p: &Patch<T>,
    at: &[Vec<BigRational>],
    tag: Option<Option<usize>>,
) -> Result<Vec<Value>, Error> {
    let mut ev = match p {
        Patch::Curve(c) => Evaluator::curve(c),
        Patch::Rect(r) => Evaluator::rect(r),
        Patch::Tri(t) => Evaluator::tri(t),
    };
    let d = ev.net().dim();
    let mut kept = Vec::new();
    for chunk in at.chunks(CHUNK) {
        let params: Vec<T> = chunk.iter().flatten().map(T::from_rational).collect();
        let mut out = vec![T::zero(); chunk.len() * d];
        ev.eval_batch(&params, &mut out)?;
        for (at, x) in chunk.iter().zip(out.chunks(d)) {
            let mut v = json!({ "at": point_to_json(at), "point": point_to_json(x) });
            match tag {
                Some(patch) => {
                    if let Some(k) = patch {
                        v["patch"] = json!(k);
                    }
                    check_finite(&v)?;
                    emit(&json_text(&v, false));
                }
                None => kept.push(v),
            }
        }
    }
    Ok(kept)
}
