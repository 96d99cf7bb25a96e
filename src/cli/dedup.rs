//! `dedup FILE`: group a JSON array of curves and rect patches into
//! coincidence classes by exact canonical keys (O(N) expected), with the
//! witness mapping each class's first member to every other member.

use super::{charge_each, load, ScalarKind};
use crate::canonical::dedup;
use crate::coincide::coincide;
use crate::error::Error;
use serde_json::{json, Value};

/// Arguments of `dedup`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (a JSON array of curves and rect patches), or - for standard input.
    file: String,
}

pub fn run(a: &Args) -> Result<Value, Error> {
    let patches = load(&a.file)?;
    // A canonical key per patch, and a witness per class member.
    charge_each("dedup", &patches, ScalarKind::Exact, |s| {
        let (ops, bits) = super::coincide::coincide_cost(s);
        (2 * ops, bits)
    })?;
    let classes = dedup(&patches)?;
    let out = classes
        .iter()
        .map(|members| {
            let first = &patches[members[0]];
            let listed = members
                .iter()
                .map(|&k| {
                    if k == members[0] {
                        return Ok(json!({"index": k, "witness": Value::Null}));
                    }
                    let c = coincide(first, &patches[k])?;
                    Ok(json!({"index": k, "witness": c.to_json()["witness"].clone()}))
                })
                .collect::<Result<Vec<_>, Error>>()?;
            Ok(json!({"representative": members[0], "members": listed}))
        })
        .collect::<Result<Vec<_>, Error>>()?;
    Ok(json!({"patches": patches.len(), "classes": out.len(), "groups": out}))
}
