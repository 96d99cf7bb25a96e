//! `key FILE`: the canonical key of every curve or rect patch, one JSON
//! line each — `{"index": K, "key": "eb1:…"}` — computed on all cores and
//! written in input order. Grouping these lines by `key` (in any engine:
//! DuckDB, Spark, `sort`) gives the classes of `dedup`; see
//! `docs/bulk_dedup.md`.

use super::bulk::{for_each_chunk_ahead, key_chunk, BulkArgs, MachineKey, Member, Out, Progress};
use crate::recent::{RecentKeys, RECENT_SLOTS_LOG2};
use exact_bezier::coincide::canonical::{canonical_key, canonical_text, KeyDigest};
use exact_bezier::Error;
use serde_json::json;

/// Arguments of `key`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    bulk: BulkArgs,
    /// The index of the first record (for a shard of a larger input).
    #[arg(long, default_value_t = 0)]
    first_index: u64,
    /// Also print the key text the digest is taken of ("text").
    #[arg(long)]
    text: bool,
}

/// Run `key`; its lines are written as they are ready.
pub fn run(a: &Args) -> Result<(), Error> {
    keys(a)
}

/// The key text of a record: a patch over the real algebraic numbers has
/// one when its key is rational (then it is the key of its copies over Q).
///
/// # Errors
///
/// [`Error::Domain`] for an irrational key (no canonical text: use
/// `dedup`, which compares such keys exactly).
fn member_text(p: Member) -> Result<String, Error> {
    match p {
        Member::Rational(p) => canonical_text(&p),
        Member::Algebraic(p) => algebraic_text(&p),
    }
}

/// The key text of a patch over the real algebraic numbers (see
/// [`member_text`]).
fn algebraic_text(
    p: &exact_bezier::patch::Patch<exact_bezier::algebra::RealAlgebraic>,
) -> Result<String, Error> {
    canonical_key(p)?
            .to_rational()
            .map(|k| k.text())
            .ok_or_else(|| {
                Error::Domain(
                    "this patch's key has irrational algebraic numbers, which have no canonical text; dedup compares such keys exactly".into(),
                )
            })
}

fn keys(a: &Args) -> Result<(), Error> {
    let (reader, input) = a.bulk.open()?;
    let progress = Progress::new(&a.bulk, &input);
    let mut out = Out::new();
    let mut done = 0;
    let mut recent = RecentKeys::new(RECENT_SLOTS_LOG2);
    let n = for_each_chunk_ahead(reader, |first, records| {
        let lines = key_chunk("key", a.text, first, &records, &mut recent, |p| {
            let text = member_text(p)?;
            Ok(MachineKey {
                digest: KeyDigest::of_text(&text),
                text: a.text.then_some(text),
            })
        })?;
        for (k, MachineKey { digest, text }) in lines.into_iter().enumerate() {
            let index = a.first_index + (first + k) as u64;
            match text {
                None => out.line_args(format_args!("{{\"index\":{index},\"key\":\"{digest}\"}}")),
                Some(t) => out.line(
                    &json!({"index": index, "key": digest.to_string(), "text": t}).to_string(),
                ),
            }
        }
        done += records.len();
        progress.update(&input, done);
        Ok(())
    })?;
    out.flush();
    progress.finish(&format!("{n} keys"));
    Ok(())
}
