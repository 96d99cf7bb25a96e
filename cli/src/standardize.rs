//! `standardize FILE`: the standard form of a curve (end weights 1) or a
//! rect patch (corner weights 1), source 000. The JSON says whether the
//! result is exact (always, over the real algebraic numbers) and names the
//! reparameterization with its parameters.

use super::{load, one_or_many};
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::io::standard_to_json;
use exact_bezier::limits;
use exact_bezier::patch::Patch;
use exact_bezier::reparam::{standardize, Options};
use exact_bezier::Error;
use exact_bezier::Scalar;
use num_rational::BigRational;
use serde_json::Value;

/// Arguments of `standardize`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// For a rect patch that needs the quadratic map: write the standard
    /// form in bidegree (m, m+n) instead of the paper's (m+n, m+n) (the same
    /// surface: the latter is the former degree-elevated n times in u).
    #[arg(long)]
    compact: bool,
}

/// The subcommand: `{"exact": true, "reparameterization": {...}, "patch": {...}}` per input;
/// every number is exact, irrational ones in the text grammar of
/// `docs/algebraic_numbers.md` (`"sqrt(6)/6"`).
pub fn run(a: &Args) -> Result<Value, Error> {
    let patches = load(&a.file)?;
    for p in &patches {
        limits::charge("standardize", standardize_cost(p))?;
    }
    let options = Options {
        compact: a.compact,
        ..Options::default()
    };
    let lift = RealAlgebraic::from_rational;
    let out = patches
        .iter()
        .map(|p| match p {
            Patch::Curve(c) => standard_to_json(&standardize(&c.map(lift), options)?),
            Patch::Rect(r) => standard_to_json(&standardize(&r.map(lift), options)?),
            Patch::Tri(_) => Err(Error::Shape(
                "standardize applies to a curve or a rect patch, not a tri patch".into(),
            )),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(out))
}

/// The estimated work of standardizing `p` exactly (docs/limits.md).
///
/// A curve, or a rect that satisfies Theorem 1, takes a Möbius map: the
/// weights times powers of one root per parameter, in a field of degree
/// `D = m·n` (`n` for a curve). Any other rect takes the quadratic map:
/// the (m+n, m+n) patch is evaluated at parameters in a field of degree up
/// to `D = m²·n` (two m-th roots and an n-th root). An element of such a
/// field has up to `D` terms and a product costs up to `D²` term products;
/// with the growth of the terms' coefficients the work is taken as
/// `ops · D³ / 10` on numbers of the input's size (`D⁸` when β needs the
/// general root isolation, below, whose resultant degrees multiply).
/// Calibrated with the other commands (`cli/benches/cost_model.rs`):
/// Example 2 of source 000 (bicubic, quadratic map, D = 27) is charged
/// 1.5·10⁸ units for about 2 s of CPU time in a release build — well under
/// the default budget, as every source example must be.
fn standardize_cost(p: &Patch<BigRational>) -> u64 {
    let s = p.size();
    let (m, n) = (s.degree.0.max(1) as u64, s.degree.1.max(1) as u64);
    let quadratic = matches!(p, Patch::Rect(r) if !Options::default().linear(r));
    let big = if quadratic { m + n + 1 } else { m.max(n) + 1 };
    let ops = big * big * (m + 1) * (n + 1) * (s.dim as u64 + 1);
    let field = if quadratic { m * m * n } else { m * n };
    // β = ((α₂/α₁)^{m/g})^{g/n}·(ω₀₀/ω₀ₙ)^{1/n}, g = gcd(m, n), stays a sum
    // of radicals when n divides m (or the α are rational, m = 1); otherwise
    // it is a root of an element of the α's field, isolated by resultants,
    // whose degrees multiply: charged as D⁸.
    let general = quadratic && m >= 2 && m % n != 0;
    let ops = ops.saturating_mul(field.saturating_pow(if general { 8 } else { 3 }));
    limits::exact_work(ops, s.grown_bits(2 * (m + n), s.bits)) / 10
}
