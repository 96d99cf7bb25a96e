//! `curvature FILE --at T [--scalar f64]`: `{"curvature_squared": κ²,
//! "curvature": κ, "curvature_approx": κ as f64}` — exact by default: κ² is
//! rational (algebraic for a curve with algebraic numbers) and κ = √κ² a
//! real algebraic number (a rational when κ² is a square, `sqrt(q)`-style
//! text otherwise); with `--scalar f64` both are numbers and there is no
//! `curvature_approx`.

use super::deriv::{curve_of, single_parameter};
use super::{
    charge_each, load_exact, on_exact, one_or_many, run_each, ExactScalar, PatchOp, ScalarKind,
};
use exact_bezier::algebra::{Ordered, Roots, Scalar};
use exact_bezier::io::JsonScalar;
use exact_bezier::limits::{self, Size};
use exact_bezier::patch::Patch;
use exact_bezier::Error;
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
    on_exact!(load_exact(&a.file)?, patches => {
        let at = [Scalar::from_rational(&t)];
        match a.scalar {
            ScalarKind::F64 => run_each(&patches, &at, a.scalar, &Curvature),
            ScalarKind::Exact => exact_each(&patches, &at[0]),
        }
    })
}

/// The exact result on every patch: κ² over `T` and κ = √κ² as a real
/// algebraic number, with κ as `f64` in `curvature_approx` (left out when
/// it overflows). The work is charged first, the square root's extension
/// of the numbers' field included (refused when it would pass the field
/// degree limit).
fn exact_each<T: ExactScalar>(patches: &[Patch<T>], t: &T) -> Result<Value, Error> {
    charge_each("curvature", patches, ScalarKind::Exact, |s| {
        Curvature.cost(s, t.bits())
    })?;
    for p in patches {
        let s = p.size();
        let (_, bits) = Curvature.cost(&s, t.bits());
        limits::charge_extension("curvature's κ = √κ²", s.field_degree, 2, bits)?;
        // Building that extension: the primitive element of κ's field and
        // its minimal polynomial, `D'³` operations in degree D' = 2D
        // (metered: 4·10⁶ units for κ of a cubic over Q(√11), twice what
        // `D'²` charged for it).
        let (d, field) = (s.field_degree, s.field);
        if d > 1 {
            let extended = 2 * d;
            let ops = extended.pow(3);
            limits::charge(
                "curvature's κ = √κ² (its field)",
                limits::exact_work(ops, bits).saturating_mul(limits::field_op_cost(extended, true)),
            )?;
        }
        // κ² written in the numbers' field, κ in its quadratic extension.
        limits::charge_writes("curvature (writing κ²)", 1, d, field, bits)?;
        limits::charge_writes("curvature (writing κ)", 1, 2 * d, d > 1, bits)?;
    }
    let values = patches
        .iter()
        .map(|p| {
            let k2 = curve_of(p, "curvature")?.curvature_sq(t)?;
            let kappa = k2
                .to_algebraic()
                .nth_root(2)
                .ok_or_else(|| Error::Domain(format!("κ² = {k2} is negative")))?;
            let mut v = json!({ "curvature_squared": k2.to_json(), "curvature": kappa.to_json() });
            let approx = kappa.to_f64();
            if approx.is_finite() {
                v["curvature_approx"] = approx.into();
            }
            Ok(v)
        })
        .collect::<Result<Vec<_>, Error>>()?;
    Ok(one_or_many(values))
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
