//! `eval FILE --at U[,V] [--at …] | --grid N [--jsonl] [--scalar f64]`.
//!
//! One `--at`: `{"point": [...]}`. Several `--at`, or `--grid N`:
//! `{"points": [{"at": [...], "point": [...]}, …]}`, or with `--jsonl` one
//! such object per line, streamed (with `"patch": k` when the file holds
//! several patches). Grids: a curve at `t = i/N`; a rect at `(i/N, j/N)`,
//! `i` outer; a tri at `(i/N, j/N)` with `i + j ≤ N`, `i` outer.

use super::{
    charge_each, check_domain, check_finite, emit, json_text, one_or_many, parse_list, patch_f64,
    read_input, run_each, PatchOp, ScalarKind,
};
use crate::algebra::scalar::{Field, Ordered};
use crate::error::Error;
use crate::eval::Evaluator;
use crate::io::{point_to_json, read_patches, JsonScalar, Patch};
use num_rational::BigRational;
use serde_json::{json, Value};

/// Points evaluated per batch (bounds memory when streaming).
const CHUNK: usize = 4096;

/// Points a document (without `--jsonl`) may hold.
const MAX_DOCUMENT_POINTS: u64 = 1_000_000;

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
pub fn run(a: &Args) -> Result<Result<Value, i32>, Error> {
    let text = read_input(&a.file)?;
    let single = a.at.len() == 1 && a.grid.is_none() && !a.jsonl;
    if let Some(trig) = crate::io::trig::read_trig_patches(&text)? {
        if !single {
            return Err(Error::Shape(
                "trig patches take one --at at a time (no --grid, --jsonl or repeated --at)".into(),
            ));
        }
        return super::eval_trig::run(&trig, &a.at[0], a.scalar).map(Ok);
    }
    let patches = read_patches(&text)?;
    if patches.is_empty() {
        return Err(Error::Shape(format!(
            "{:?} holds an empty array: no curve or patch to evaluate",
            a.file
        )));
    }
    if single {
        let params = parse_list(&a.at[0])?;
        if !a.extrapolate {
            for p in &patches {
                check_domain(p, &params)?;
            }
        }
        return run_each(&patches, &params, a.scalar, &Eval).map(Ok);
    }
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
        let param_bits = crate::limits::max_bits(at.iter().flatten());
        charge_each("eval", std::slice::from_ref(p), a.scalar, |s| {
            let ops = s.eval_ops().saturating_mul(at.len() as u64);
            (ops, s.grown_bits(s.total_degree(), param_bits))
        })?;
        let tag = a.jsonl.then(|| (patches.len() > 1).then_some(k));
        let points = match a.scalar {
            ScalarKind::Exact => eval_points(p, &at, tag)?,
            ScalarKind::F64 => eval_points(&patch_f64(p)?, &at, tag)?,
        };
        values.push(json!({ "points": points }));
    }
    if a.jsonl {
        return Ok(Err(0));
    }
    Ok(Ok(one_or_many(values)))
}

/// The grid parameter points of `p` (module docs), refusing grids too
/// large for one document.
fn grid(p: &Patch<BigRational>, n: u64, jsonl: bool) -> Result<Vec<Vec<BigRational>>, Error> {
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
    crate::limits::charge("eval --grid", count)?;
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
fn check_points(
    p: &Patch<BigRational>,
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
