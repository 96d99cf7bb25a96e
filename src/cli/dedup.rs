//! `dedup FILE`: group curves and rect patches (JSON Lines or a JSON array,
//! streamed) into coincidence classes by their canonical keys, computed on
//! all cores; one JSON line per class, classes by first member:
//!
//! ```text
//! {"class": 0, "representative": 0, "members": [0, 5, 9]}
//! ```
//!
//! Memory: per input a 4-byte class id, per class a 32-byte key digest —
//! never the patches. With `--witness` each member also gets the exact
//! witness of `coincide` against its class's representative (in parallel),
//! which re-checks every grouping exactly; it keeps each representative's
//! text and each witness until the end.

use super::bulk::{map_chunk, BulkArgs, Out, Progress, CHUNK};
use crate::coincide::canonical::{key_digest, Deduper};
use crate::coincide::coincide;
use crate::error::Error;
use crate::io::{for_each_chunk, parse_json, patch_from_value, Patch, Record};
use num_rational::BigRational;
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
    /// The witnesses of one keyed chunk whose class ids are `ids`.
    fn add_chunk(
        &mut self,
        d: &Deduper,
        first: usize,
        records: &[Record],
        patches: Vec<Patch<BigRational>>,
        ids: &[usize],
    ) -> Result<(), Error> {
        for (k, (r, &id)) in records.iter().zip(ids).enumerate() {
            if d.representative(id) == first + k {
                self.reps.push(r.text().into_boxed_str());
            }
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
                let a = patch_from_value(&parse_json(&reps[id])?)?;
                let c = coincide(&a, p)?;
                if !c.coincident {
                    return Err(Error::Format(format!(
                        "inputs {rep} and {} have equal keys but do not coincide: {}",
                        first + k,
                        c.reason
                    )));
                }
                Ok(Some(c.to_json()["witness"].to_string().into_boxed_str()))
            })
            .collect();
        for w in done {
            self.of.push(w?);
        }
        Ok(())
    }
}

fn dedup(a: &Args) -> Result<(), Error> {
    let (reader, input) = a.bulk.open()?;
    let progress = Progress::new(&a.bulk, &input);
    let mut d = Deduper::default();
    let mut witnesses = a.witness.then(Witnesses::default);
    for_each_chunk(reader, CHUNK, |first, records| {
        let keyed = map_chunk(&records, |p| {
            let key = key_digest(&p)?;
            Ok((key, a.witness.then_some(p)))
        })?;
        let mut ids = Vec::with_capacity(keyed.len());
        let mut patches = Vec::new();
        for (key, p) in keyed {
            ids.push(d.insert_digest(key)?);
            patches.extend(p);
        }
        if let Some(w) = &mut witnesses {
            w.add_chunk(&d, first, &records, patches, &ids)?;
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
