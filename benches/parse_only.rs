//! The yardstick of `exact-bezier key`/`dedup` throughput: stream the same
//! input and merely parse every record into a patch (exactly, on all
//! cores, as they do), computing no key.
//!
//! ```sh
//! /usr/bin/time -v cargo bench --bench parse_only -- /tmp/p200k.jsonl
//! ```
//!
//! (`docs/bulk_dedup.md` makes the input.) Without a file it prints its
//! usage and exits, so that `cargo bench` passes over it.

use exact_bezier::{io::for_each_chunk, Error};
use rayon::prelude::*;
use std::io::BufReader;

fn main() -> Result<(), Error> {
    // `cargo bench` appends `--bench`; with no input file there is nothing to time.
    let Some(path) = std::env::args().nth(1).filter(|a| !a.starts_with("--")) else {
        eprintln!("usage: cargo bench --bench parse_only -- FILE");
        return Ok(());
    };
    let file = std::fs::File::open(&path).map_err(|e| Error::Format(e.to_string()))?;
    let mut parsed = 0usize;
    let n = for_each_chunk(
        BufReader::with_capacity(1 << 16, file),
        4096,
        |_, records| {
            let ok: Vec<Result<usize, Error>> = records
                .par_iter()
                .map(|r| r.patch().map(|p| p.kind().len()))
                .collect();
            for r in ok {
                r?;
                parsed += 1;
            }
            Ok(())
        },
    )?;
    println!("{n} records, {parsed} patches");
    Ok(())
}
