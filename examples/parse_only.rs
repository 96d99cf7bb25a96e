//! The yardstick of `exact-bezier key`/`dedup` throughput: stream the same
//! input and merely parse every record into a patch (exactly, on all
//! cores, as they do), computing no key.
//!
//! ```sh
//! cargo build --release --example parse_only
//! /usr/bin/time -v target/release/examples/parse_only /tmp/p200k.jsonl
//! ```

use exact_bezier::{io::for_each_chunk, Error};
use rayon::prelude::*;
use std::io::BufReader;

fn main() -> Result<(), Error> {
    let path = std::env::args().nth(1).expect("usage: parse_only FILE");
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
