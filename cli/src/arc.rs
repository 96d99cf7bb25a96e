//! `arc --cos-half C --lambda L --points B0;B1;B2 [--direction B]`: the
//! standard-form rational cubic of source 004 eq. (1) (eq. (2) for θ = π).

use super::parse_algebraic_list;
use exact_bezier::algebra::ExactNumber;
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::algebra::Tolerance;
use exact_bezier::arc::QuadArc;
use exact_bezier::io::{patch_to_json, JsonScalar};
use exact_bezier::limits::{self, Cost};
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use num_traits::Zero;
use serde_json::Value;

/// Arguments of `arc`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// c = cos(θ/2) of the centre angle θ, exact text (1/2, 0.6, sqrt(2)/2); −1/2 < c < 1.
    #[arg(long = "cos-half", alias = "theta-cos", allow_hyphen_values = true)]
    cos_half: String,
    /// The family parameter λ, exact text (rational or algebraic); must lie in the admissible interval.
    #[arg(long, allow_hyphen_values = true)]
    lambda: String,
    /// Control points of the quadratic arc, `x,y;x,y;x,y` (b̄₀; b̄₁; b̄₂), or
    /// `x,y;x,y` (b̄₀; b̄₂) with --direction when c = 0 (θ = π).
    #[arg(long, allow_hyphen_values = true)]
    points: String,
    /// θ = π only: the direction b ⟂ b̄₂ − b̄₀ with |b| = radius, `x,y`.
    #[arg(long, allow_hyphen_values = true)]
    direction: Option<String>,
}

/// Build the arc, then the cubic, over the real algebraic numbers: exact
/// for every admissible λ (`"exact": true`; numbers that need roots are
/// written in the algebraic grammar of docs/FORMAT.md). Every input may be
/// algebraic text too, e.g. `--points '1,0;1,sqrt(3);-1/2,sqrt(3)/2'`.
pub fn run(a: &Args) -> Result<Value, Error> {
    let c = number(&a.cos_half)?;
    let lambda = number(&a.lambda)?;
    let pts = a
        .points
        .split(';')
        .map(parse_algebraic_list)
        .collect::<Result<Vec<_>, _>>()?;
    let all: Vec<RealAlgebraic> = [c.clone(), lambda.clone()]
        .into_iter()
        .chain(pts.iter().flatten().cloned())
        .collect();
    crate::input::check_numbers(&all, "the arc's numbers")?;
    charge_arc(&all, pts.iter().map(Vec::len).max().unwrap_or(0))?;
    let arc = match (pts.as_slice(), &a.direction) {
        ([b0, b1, b2], None) => QuadArc::from_control(b0, b1, b2, &c, Tolerance::EXACT)?,
        ([b0, b2], Some(d)) if c.is_zero() => {
            QuadArc::semicircle(b0, b2, &parse_algebraic_list(d)?, Tolerance::EXACT)?
        }
        _ => {
            return Err(Error::Shape(
                "--points takes three points b̄₀;b̄₁;b̄₂, or two points b̄₀;b̄₂ with --direction when cos(θ/2) = 0".into(),
            ))
        }
    };
    let cubic = arc.cubic_for_lambda(&lambda)?;
    let mut out = patch_to_json(&Patch::Curve(cubic))?;
    if let Value::Object(map) = &mut out {
        map.insert("exact".into(), true.into());
        map.insert("cos_half".into(), c.to_json());
        map.insert("lambda".into(), lambda.to_json());
    }
    Ok(out)
}

/// Charge the arc's work before it starts: a fixed number of operations
/// per coordinate (the triangle's dot products, `A₁`, the cubic's points:
/// [`ARC_OPS_PER_COORDINATE`]) in the field of degree `D` that the numbers
/// span, then σ = ∛(N/D), which extends that field to degree `3D`
/// ([`limits::charge_extension`], refused over the field degree limit),
/// and the cubic's numbers written in that extension
/// ([`limits::write_ops`]; calibrated by `cli/benches/cost_model.rs`).
fn charge_arc(numbers: &[RealAlgebraic], dim: usize) -> Result<(), Error> {
    let (degree, field) = RealAlgebraic::field_degree(numbers);
    let bits = numbers.iter().map(Cost::bits).max().unwrap_or(0);
    let ops = ARC_OPS_PER_COORDINATE.saturating_mul(dim as u64 + 1);
    let units = limits::exact_work(ops, bits).saturating_mul(limits::field_op_cost(degree, field));
    limits::charge("arc", units)?;
    limits::charge_extension("arc's σ = ∛(N/D)", degree, 3, bits)?;
    // The cubic's four points and weights, written in that extension.
    let count = 4 * (dim as u64 + 1);
    limits::charge_writes(
        "arc (writing the cubic)",
        count,
        3 * degree,
        degree > 1,
        bits,
    )
}

/// Operations of `arc` per coordinate of its points (about 30 products and
/// sums: the control triangle's checks, `A₁`, the cubic's four points).
const ARC_OPS_PER_COORDINATE: u64 = 32;

/// One exact number: rational or algebraic text.
fn number(text: &str) -> Result<RealAlgebraic, Error> {
    RealAlgebraic::from_text(text.trim())
}
