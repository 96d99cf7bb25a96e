//! `prove [--json]`: run every family in `proofs/`.

use super::emit;
use crate::proofs::{run_all, Claim, Verdict};
use serde_json::Value;
use std::fmt::Write;

/// Arguments of `prove`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Print a JSON array (one object per claim) instead of the table.
    #[arg(long)]
    json: bool,
}

/// Print the report; exit 0 iff every claim has its expected verdict.
pub fn run(a: &Args) -> i32 {
    let families = run_all();
    let claims: Vec<_> = families.iter().flat_map(|(_, c)| c.iter()).collect();
    let off: Vec<_> = claims.iter().filter(|c| !c.as_expected()).collect();
    if a.json {
        let arr = Value::Array(claims.iter().map(|c| c.to_json()).collect());
        emit(&serde_json::to_string_pretty(&arr).unwrap_or_default());
    } else {
        emit(&table(&families, off.len()));
    }
    if off.is_empty() {
        0
    } else {
        1
    }
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
    let count = |v: Verdict| claims.iter().filter(|c| c.verdict == v).count();
    let _ = write!(
        out,
        "{} claims: {} proved, {} refuted, {} reproduced, {} mismatch; {off} off their expected verdict",
        claims.len(),
        count(Verdict::Proved),
        count(Verdict::Refuted),
        count(Verdict::Reproduced),
        count(Verdict::Mismatch),
    );
    out
}
