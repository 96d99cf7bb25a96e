//! Running a command over every input patch: the cost charged first, the
//! computation written once for every exact scalar, `f64` copies, domain
//! checks and the shape of the JSON answer.

use crate::args::ScalarKind;
use crate::input::ExactScalar;
use exact_bezier::algebra::Ordered;
use exact_bezier::io::JsonScalar;
use exact_bezier::limits::{self, Size};
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use num_rational::BigRational;
use num_traits::{One, Zero};
use serde_json::Value;
/// A command's computation on one patch with exact parameters, written once
/// for every scalar (see [`run_each`]).
pub(crate) trait PatchOp {
    /// The command's name, for the limit message.
    const NAME: &'static str;

    /// The JSON result for `p` at `params` (converted to the patch's scalar).
    fn apply<T: JsonScalar + Ordered>(&self, p: &Patch<T>, params: &[T]) -> Result<Value, Error>;

    /// Estimated `(operations, bits)` of [`PatchOp::apply`] on a patch of
    /// size `s` at parameters of `param_bits` bits (the cost model of
    /// [`exact_bezier::limits`]); by default one evaluation and one point
    /// written.
    fn cost(&self, s: &Size, param_bits: u64) -> (u64, u64) {
        (
            s.eval_ops() + s.write_ops(s.dim as u64),
            s.grown_bits(s.total_degree(), param_bits),
        )
    }
}

/// Charge `what`'s estimated work on each patch before computing
/// ([`limits::charge_sizes`]: `cost` gives `(operations, bits)`; an `f64`
/// run counts the operations only).
pub(crate) fn charge_each<T: ExactScalar>(
    what: &str,
    patches: &[Patch<T>],
    scalar: ScalarKind,
    cost: impl Fn(&Size) -> (u64, u64),
) -> Result<(), Error> {
    let sizes = patches.iter().map(Patch::size);
    limits::charge_sizes(what, sizes, scalar == ScalarKind::Exact, cost)
}

/// Convert an exact patch to `f64`, refusing numbers that overflow.
///
/// # Errors
///
/// [`Error::NotFinite`] naming the first such number.
pub(crate) fn patch_f64<T: Ordered>(p: &Patch<T>) -> Result<Patch<f64>, Error> {
    let bad = std::cell::Cell::new(false);
    let f = p.map(|x| {
        let y = x.to_f64();
        if !y.is_finite() {
            bad.set(true);
        }
        y
    });
    if bad.get() {
        return Err(Error::NotFinite(
            "a coordinate or weight is too large for f64; use --scalar exact".into(),
        ));
    }
    Ok(f)
}

/// Apply `op` to every patch with the chosen scalar: exactly, or on the
/// nearest `f64` patch and parameters. One value for a single patch, an
/// array for several. The estimated work is charged first.
///
/// # Errors
///
/// [`Error::Limit`] over the work budget; the first error of `op`.
pub(crate) fn run_each<Op: PatchOp, T: ExactScalar>(
    patches: &[Patch<T>],
    params: &[T],
    scalar: ScalarKind,
    op: &Op,
) -> Result<Value, Error> {
    let param_bits = params.iter().map(T::bits).max().unwrap_or(0);
    let sizes = patches.iter().map(|p| p.size_with(params));
    let exact = scalar == ScalarKind::Exact;
    limits::charge_sizes(Op::NAME, sizes, exact, |s| op.cost(s, param_bits))?;
    let values = patches
        .iter()
        .map(|p| match scalar {
            ScalarKind::Exact => op.apply(p, params),
            ScalarKind::F64 => op.apply(
                &patch_f64(p)?,
                &params.iter().map(Ordered::to_f64).collect::<Vec<_>>(),
            ),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(values))
}

/// Refuse parameters outside the domain of `p` (policy: extrapolation only
/// with `--extrapolate`): `t ∈ [0, 1]` for a curve, `(u, v) ∈ [0, 1]²` for
/// a rect, `u, v ≥ 0, u + v ≤ 1` for a tri patch. A parameter count that
/// does not fit is left to the command's own message.
///
/// # Errors
///
/// [`Error::Domain`] naming the parameter and the flag.
pub(crate) fn check_domain<T: exact_bezier::Scalar>(
    p: &Patch<T>,
    params: &[BigRational],
) -> Result<(), Error> {
    let (zero, one) = (BigRational::zero(), BigRational::one());
    let unit = |x: &BigRational| *x >= zero && *x <= one;
    let inside = match (p, params) {
        (Patch::Curve(_), [t]) => unit(t),
        (Patch::Rect(_), [u, v]) => unit(u) && unit(v),
        (Patch::Tri(_), [u, v]) => u >= &zero && v >= &zero && (u + v) <= one,
        _ => true,
    };
    if inside {
        return Ok(());
    }
    let shown: Vec<String> = params.iter().map(ToString::to_string).collect();
    Err(Error::Domain(format!(
        "--at {} is outside the domain of the {} (give --extrapolate to evaluate the polynomial beyond it)",
        shown.join(","),
        p.kind()
    )))
}

/// One value for a single patch, an array for several.
pub(crate) fn one_or_many(mut values: Vec<Value>) -> Value {
    if values.len() == 1 {
        values.swap_remove(0)
    } else {
        Value::Array(values)
    }
}
