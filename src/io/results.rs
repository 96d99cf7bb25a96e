//! JSON of the results of domain operations: a coincidence decision with
//! its witness ([`coincidence_to_json`]) and a standard form with its map
//! ([`standard_to_json`]), as the command line writes them (docs/FORMAT.md).

use crate::algebra::scalar::Field;
use crate::coincide::{Coincidence, MobiusParam, ReductionInfo};
use crate::error::Error;
use crate::io::{patch_to_json, JsonScalar};
use crate::reparam::{Standard, StandardMap};
use crate::Patch;
use serde_json::{json, Value};

/// `{"rho", "alpha"}` in u, `{"sigma", "beta"}` in v (the paper's names).
fn param_json<T: JsonScalar>(p: &MobiusParam<T>, (ratio, param): (&str, &str)) -> Value {
    match p {
        MobiusParam::None => Value::Null,
        MobiusParam::Value { rho, alpha } => json!({ratio: rho.to_json(), param: alpha.to_json()}),
        MobiusParam::Power { exponent, power } => {
            json!({format!("{ratio}_power"): {"exponent": exponent, "value": power.to_json()}})
        }
    }
}

/// `{"from": [m, n], "to": [m', n'], "common_factor"}`.
fn reduction_json(r: &ReductionInfo) -> Value {
    json!({"from": [r.from.0, r.from.1], "to": [r.to.0, r.to.1], "common_factor": r.common_factor})
}

/// The `coincide` command's object `{"coincident", "reason", "witness",
/// "reductions"}`; the witness `{"symmetry", "u", "v", "k",
/// "corner_weight_ratio"}` or `null`.
pub fn coincidence_to_json<T: JsonScalar>(c: &Coincidence<T>) -> Value {
    let witness = c.witness.as_ref().map_or(Value::Null, |w| {
        json!({
            "symmetry": w.symmetry.to_string(),
            "u": param_json(&w.u, ("rho", "alpha")),
            "v": param_json(&w.v, ("sigma", "beta")),
            "k": w.k.as_ref().map_or(Value::Null, JsonScalar::to_json),
            "corner_weight_ratio": w.corner_ratio.to_json(),
        })
    });
    json!({
        "coincident": c.coincident,
        "reason": c.reason,
        "witness": witness,
        "reductions": [reduction_json(&c.reductions[0]), reduction_json(&c.reductions[1])],
    })
}

/// The `reparameterization` object of `standardize`'s output:
/// `{"kind": "mobius", "alpha", "beta"?, "k"}` or `{"kind": "quadratic",
/// "alpha1", "alpha2", "beta1", "beta2", "k"}` (docs/FORMAT.md).
fn standard_map_json<T: JsonScalar>(map: &StandardMap<T>) -> Value {
    let j = |x: &T| x.to_json();
    match map {
        StandardMap::Mobius { alpha, beta, k } => match beta {
            Some(b) => json!({"kind": "mobius", "alpha": j(alpha), "beta": j(b), "k": j(k)}),
            None => json!({"kind": "mobius", "alpha": j(alpha), "k": j(k)}),
        },
        StandardMap::Quadratic { map, k } => json!({
            "kind": "quadratic",
            "alpha1": j(&map.alpha1), "alpha2": j(&map.alpha2),
            "beta1": j(&map.beta1), "beta2": j(&map.beta2), "k": j(k)
        }),
    }
}

/// The `standardize` command's object: `{"exact": true,
/// "reparameterization": {...}, "patch": {...}}` (docs/FORMAT.md).
///
/// # Errors
///
/// As [`patch_to_json`] (a weight that is not positive).
pub fn standard_to_json<P: Clone + Into<Patch<T>>, T: JsonScalar + Field>(
    s: &Standard<P, T>,
) -> Result<Value, Error> {
    Ok(json!({
        "exact": true,
        "reparameterization": standard_map_json(&s.map),
        "patch": patch_to_json(&s.patch.clone().into())?,
    }))
}
