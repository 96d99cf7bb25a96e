//! `standardize FILE`: the standard form of a curve (end weights 1) or a
//! rect patch (corner weights 1), source 000. The JSON says whether the
//! result is exact (always, over the real algebraic numbers) and names the
//! reparameterization with its parameters.

use super::{charge_each, load, one_or_many, ScalarKind};
use crate::error::Error;
use crate::io::{patch_to_json, JsonScalar, Patch};
use crate::scalar::Ordered;
use crate::standard::{standardize_curve_algebraic, standardize_rect_algebraic, StandardMap};
use serde_json::{json, Value};

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
    // A Möbius map with α of about bits/n bits (a root of w₀/wₙ), or for a
    // rect the quadratic map, bidegree (m+n, m+n), with parameters as large
    // as the weights.
    charge_each("standardize", &patches, ScalarKind::Exact, |s| {
        let (m, n) = (s.degree.0 as u64, s.degree.1 as u64);
        let big = m + n + 1;
        let ops = big * big * (m + 1) * (n + 1) * (s.dim as u64 + 1);
        (ops, s.grown_bits(2 * (m + n), s.bits))
    })?;
    let out = patches
        .iter()
        .map(|p| match p {
            Patch::Curve(c) => {
                let s = standardize_curve_algebraic(c)?;
                describe(&Patch::Curve(s.patch), &s.map)
            }
            Patch::Rect(r) => {
                let s = standardize_rect_algebraic(r, a.compact)?;
                describe(&Patch::Rect(s.patch), &s.map)
            }
            Patch::Tri(_) => Err(Error::Shape(
                "standardize applies to a curve or a rect patch, not a tri patch".into(),
            )),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(out))
}

fn describe<T: JsonScalar + Ordered>(
    patch: &Patch<T>,
    map: &StandardMap<T>,
) -> Result<Value, Error> {
    let j = |x: &T| x.to_json();
    let reparam = match map {
        StandardMap::Mobius { alpha, beta, k } => match beta {
            Some(b) => json!({"kind": "mobius", "alpha": j(alpha), "beta": j(b), "k": j(k)}),
            None => json!({"kind": "mobius", "alpha": j(alpha), "k": j(k)}),
        },
        StandardMap::Quadratic { map, k } => json!({
            "kind": "quadratic",
            "alpha1": j(&map.alpha1), "alpha2": j(&map.alpha2),
            "beta1": j(&map.beta1), "beta2": j(&map.beta2), "k": j(k)
        }),
    };
    Ok(json!({"exact": true, "reparameterization": reparam, "patch": patch_to_json(patch)?}))
}
