//! `dedup FILE`: group curves and rect patches (JSON Lines or a JSON array,
//! streamed) into coincidence classes by their canonical keys, computed on
//! all cores; one JSON line per class, classes by first member:
//!
//! ```text
//! {"class": 0, "representative": 0, "members": [0, 5, 9]}
//! ```
//!
//! Memory: per input a 4-byte class id, per class a 32-byte key digest —
//! never the patches. Patches with algebraic numbers (`"sqrt(6)/6"`) are
//! keyed over the real algebraic numbers: a key whose numbers are all
//! rational is the digest of their copies over Q; an irrational key is kept
//! whole and compared exactly with the kept keys of its skeleton
//! ([`Deduper::insert_algebraic`]). With `--witness` each member also gets the exact
//! witness of `coincide` against its class's representative (in parallel),
//! which re-checks every grouping exactly; it keeps each representative's
//! text and each witness until the end.

use super::bulk::{for_each_chunk_ahead, key_chunk, BulkArgs, MachineKey, Member, Out, Progress};
use crate::recent::{RecentKeys, RECENT_SLOTS_LOG2};
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::coincide::canonical::{
    canonical_key, key_digest, CanonicalKey, Deduper, KeyDigest,
};
use exact_bezier::coincide::{coincide, Coincidence, Options};
use exact_bezier::io::coincidence_to_json;
use exact_bezier::io::{JsonScalar, Record};
use exact_bezier::limits;
use exact_bezier::Error;
use rayon::prelude::*;
use serde_json::json;

/// Arguments of `dedup`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    bulk: BulkArgs,
    /// Give every member the exact witness mapping the representative to it.
    #[arg(long)]
    witness: bool,
}

/// Run `dedup`; its lines are written as they are ready.
pub fn run(a: &Args) -> Result<(), Error> {
    dedup(a)
}

/// The witnesses of `--witness`: each representative's text (per class)
/// and each member's witness (per input; `None` for a representative).
#[derive(Default)]
struct Witnesses {
    reps: Vec<Box<str>>,
    of: Vec<Option<Box<str>>>,
}

impl Witnesses {
    /// The witnesses of one keyed chunk whose class ids are `ids`; each
    /// member that is not a representative is charged the work of
    /// `coincide` with its representative first (both sides, at the
    /// degree of their common canonical form, [`super::bulk::least_degree`]).
    fn add_chunk(
        &mut self,
        d: &Deduper,
        first: usize,
        records: &[Record],
        ids: &[usize],
    ) -> Result<(), Error> {
        for (k, (r, &id)) in records.iter().zip(ids).enumerate() {
            if d.representative(id) == first + k {
                self.reps.push(r.text().into_owned().into_boxed_str());
            }
        }
        // Read under the command's limits (a worker's own are the defaults).
        let command_limits = limits::current();
        let read: Vec<Result<Member, Error>> = records
            .par_iter()
            .map(|r| limits::with_limits(command_limits, || Member::read(r)))
            .collect();
        let mut patches = Vec::with_capacity(read.len());
        for (k, (p, &id)) in read.into_iter().zip(ids).enumerate() {
            let p = p?;
            if d.representative(id) != first + k {
                // Member and representative share a key, so a least degree:
                // `coincide`'s charge at that degree.
                let (s, low) = super::bulk::least_degree(&p)?;
                let (ops, bits) = super::coincide::pair_cost(&s, low);
                limits::charge(
                    &format!("dedup --witness (through record {})", first + k),
                    s.exact_units(ops, bits).saturating_mul(2),
                )?;
            }
            patches.push(p);
        }
        let reps = &self.reps;
        let done: Vec<Result<Option<Box<str>>, Error>> = patches
            .par_iter()
            .zip(ids)
            .enumerate()
            .map(|(k, (p, &id))| {
                let rep = d.representative(id);
                if rep == first + k {
                    return Ok(None);
                }
                let rep_record = Record::Line(rep + 1, reps[id].to_string());
                let a = limits::with_limits(command_limits, || Member::read(&rep_record))?;
                let (coincident, reason, witness) = match (&a, p) {
                    (Member::Rational(a), Member::Rational(p)) => {
                        summary(coincide(a, p, Options::default())?)
                    }
                    (a, p) => summary(coincide(
                        &a.algebraic()?,
                        &p.algebraic()?,
                        Options::default(),
                    )?),
                };
                if !coincident {
                    return Err(Error::Format(format!(
                        "inputs {rep} and {} have equal keys but do not coincide: {reason}",
                        first + k,
                    )));
                }
                Ok(Some(witness.into_boxed_str()))
            })
            .collect();
        for w in done {
            self.of.push(w?);
        }
        Ok(())
    }
}

/// Whether they coincide, why, and the witness's JSON text.
fn summary<T: JsonScalar>(c: Coincidence<T>) -> (bool, String, String) {
    let witness = coincidence_to_json(&c)["witness"].to_string();
    (c.coincident, c.reason, witness)
}

/// A record's key: a digest, or (over the real algebraic numbers) the key.
#[derive(Clone)]
enum Keyed {
    Digest(KeyDigest),
    Algebraic(CanonicalKey<RealAlgebraic>),
}

impl From<MachineKey> for Keyed {
    fn from(k: MachineKey) -> Keyed {
        Keyed::Digest(k.digest)
    }
}

fn dedup(a: &Args) -> Result<(), Error> {
    let (reader, input) = a.bulk.open()?;
    let progress = Progress::new(&a.bulk, &input);
    let mut d = Deduper::default();
    let mut witnesses = a.witness.then(Witnesses::default);
    let mut recent = RecentKeys::new(RECENT_SLOTS_LOG2);
    for_each_chunk_ahead(reader, |first, records| {
        let keyed = key_chunk("dedup", false, first, &records, &mut recent, |p| {
            Ok(match &p {
                Member::Rational(q) => Keyed::Digest(key_digest(q)?),
                Member::Algebraic(q) => Keyed::Algebraic(canonical_key(q)?),
            })
        })?;
        let mut ids = Vec::with_capacity(keyed.len());
        for key in keyed {
            ids.push(match key {
                Keyed::Digest(k) => d.insert_digest(k)?,
                Keyed::Algebraic(k) => d.insert_algebraic(k)?,
            });
        }
        if let Some(w) = &mut witnesses {
            w.add_chunk(&d, first, &records, &ids)?;
        }
        progress.update(&input, d.len());
        Ok(())
    })?;
    let (n, count) = (d.len(), d.class_count());
    let mut out = Out::new();
    for (id, members) in d.into_classes().iter().enumerate() {
        let mut line =
            json!({"class": id, "representative": members[0], "members": members}).to_string();
        if let Some(w) = &witnesses {
            let list: Vec<&str> = members
                .iter()
                .map(|&k| w.of[k as usize].as_deref().unwrap_or("null"))
                .collect();
            line.pop();
            line.push_str(&format!(",\"witnesses\":[{}]}}", list.join(",")));
        }
        out.line(&line);
    }
    out.flush();
    progress.finish(&format!("{n} patches, {count} classes"));
    Ok(())
}
