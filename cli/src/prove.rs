//! `prove [--json] [--family NAME] [--deep]`: run the families in `proofs/`.

use super::emit;
use exact_bezier::Error;
use exact_bezier_proofs::{family, run_all, run_families, Claim, Verdict, FAMILIES};
use serde_json::Value;
use std::fmt::Write;

/// Arguments of `prove`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Print a JSON array (one object per claim, with its family, degree
    /// bound and elapsed milliseconds) instead of the table.
    #[arg(long)]
    json: bool,
    /// Run only this family (a file name in proofs/ without `.rs`).
    #[arg(long, value_name = "NAME")]
    family: Option<String>,
    /// Check the costly bounded claims to their deep bounds (yang_yong's
    /// Möbius and scaling point identities and quadratic-map claims to
    /// m, n ≤ 10 instead of 5): seconds, not one.
    #[arg(long)]
    deep: bool,
}

/// Print the report; exit 0 iff every claim has its expected verdict.
///
/// # Errors
///
/// [`Error::Domain`] for an unknown family, naming the families.
pub fn run(a: &Args) -> Result<i32, Error> {
    exact_bezier_proofs::set_deep(a.deep);
    let families = match &a.family {
        None => run_all(),
        Some(name) => match family(name) {
            Some(f) => run_families(&[f]),
            None => {
                let names: Vec<&str> = FAMILIES.iter().map(|f| f.name).collect();
                return Err(Error::Domain(format!(
                    "no proof family {name:?}; families: {}",
                    names.join(", ")
                )));
            }
        },
    };
    let off = families
        .iter()
        .flat_map(|(_, c)| c.iter())
        .filter(|c| !c.as_expected())
        .count();
    if a.json {
        let arr = families
            .iter()
            .flat_map(|(name, cs)| cs.iter().map(|c| c.to_json(name)))
            .collect();
        emit(&serde_json::to_string_pretty(&Value::Array(arr)).unwrap_or_default());
    } else {
        emit(&table(&families, off));
    }
    Ok(if off == 0 { 0 } else { 1 })
}

/// The human-readable report: one line per claim (with its detail below),
/// grouped by family, and a closing count.
fn table(families: &[(&str, Vec<Claim>)], off: usize) -> String {
    let mut out = String::new();
    let claims: Vec<&Claim> = families.iter().flat_map(|(_, c)| c.iter()).collect();
    for (family, cs) in families {
        let _ = writeln!(out, "== {family}");
        for c in cs {
            let mark = if c.as_expected() { "ok " } else { "BAD" };
            let verdict = c.verdict.to_string();
            let _ = writeln!(out, "{mark} {verdict:<10} {}  [{}]", c.claim, c.source);
            if !c.detail.is_empty() {
                let _ = writeln!(out, "               {}", c.detail);
            }
        }
    }
    let counts: Vec<String> = Verdict::ALL
        .iter()
        .map(|v| format!("{} {v}", claims.iter().filter(|c| c.verdict == *v).count()))
        .collect();
    let _ = write!(
        out,
        "{} claims: {}; {off} off their expected verdict",
        claims.len(),
        counts.join(", "),
    );
    out
}
