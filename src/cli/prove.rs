//! `prove [--json]`: run every family in `proofs/`.

use crate::proofs::run_all;
use serde_json::Value;

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
        println!("{}", serde_json::to_string_pretty(&arr).unwrap_or_default());
    } else {
        for (family, cs) in &families {
            println!("== {family}");
            for c in cs {
                let mark = if c.as_expected() { "ok " } else { "BAD" };
                println!(
                    "{mark} {:<10} {}  [{}]",
                    c.verdict.to_string(),
                    c.claim,
                    c.source
                );
                if !c.detail.is_empty() {
                    println!("               {}", c.detail);
                }
            }
        }
        let count = |v: crate::proofs::Verdict| claims.iter().filter(|c| c.verdict == v).count();
        use crate::proofs::Verdict::*;
        println!(
            "{} claims: {} proved, {} refuted, {} reproduced, {} mismatch; {} off their expected verdict",
            claims.len(),
            count(Proved),
            count(Refuted),
            count(Reproduced),
            count(Mismatch),
            off.len()
        );
    }
    if off.is_empty() {
        0
    } else {
        1
    }
}
