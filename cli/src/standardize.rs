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
        if let MapField::General(degree) = map_field(p) {
            limits::check_field_degree(degree, false, "standardize's β1 = β2 (eq. 19)")?;
        }
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
    let map = map_field(p);
    let quadratic = !matches!(map, MapField::Mobius(_));
    let big = if quadratic { m + n + 1 } else { m.max(n) + 1 };
    let ops = big * big * (m + 1) * (n + 1) * (s.dim as u64 + 1);
    let ops = match map {
        MapField::Mobius(field) | MapField::Radical(field) => {
            ops.saturating_mul(field.saturating_pow(3))
        }
        MapField::General(field) => ops.saturating_mul(field.saturating_pow(8)),
    };
    limits::exact_work(ops, s.grown_bits(2 * (m + n), s.bits)) / 10
}

/// The field of the map's parameters, of degree `D` (a bound): `m·n` for
/// a Möbius map (`n` for a curve), `m²·n` for the quadratic map (two m-th
/// roots and an n-th root).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum MapField {
    /// A Möbius map: roots of rationals, sums of radicals.
    Mobius(u64),
    /// The quadratic map with β = ((α₂/α₁)^{m/g})^{g/n}·(ω₀₀/ω₀ₙ)^{1/n},
    /// g = gcd(m, n), a sum of radicals: n divides m (or the α are
    /// rational, m = 1).
    Radical(u64),
    /// The quadratic map with β a root of an element of the α's field,
    /// which builds a number field of that degree (refused over
    /// `MAX_FIELD_DEGREE`); charged as `D⁸`, the isolation's growth.
    General(u64),
}

/// The [`MapField`] of standardizing `p`.
fn map_field(p: &Patch<BigRational>) -> MapField {
    let (m, n) = match p {
        Patch::Rect(r) => (r.degree().0.max(1) as u64, r.degree().1.max(1) as u64),
        Patch::Curve(c) => (c.degree().max(1) as u64, 1),
        Patch::Tri(t) => (t.degree().max(1) as u64, 1),
    };
    match p {
        Patch::Rect(r) if !Options::default().linear(r) => {
            if m >= 2 && m % n != 0 {
                MapField::General(m * m * n)
            } else {
                MapField::Radical(m * m * n)
            }
        }
        _ => MapField::Mobius(m * n),
    }
}
