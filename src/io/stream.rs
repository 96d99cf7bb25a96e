//! Streaming input for bulk commands (`key`, `dedup`): JSON Lines (one
//! curve or patch per line; blank lines skipped) or one JSON array, read in
//! chunks of records so that memory holds one chunk, never the document.
//!
//! The format is told by the first non-blank byte: `[` starts an array
//! (streamed element by element through a serde `SeqAccess` visitor),
//! anything else is JSON Lines — unless the first record line is an
//! incomplete JSON value, as in a pretty-printed object: then the input is
//! read as a sequence of JSON values (parsed on one thread). Records are parsed to patches by the
//! caller, in parallel, with [`patch_from_value`](crate::io::patch_from_value).

use crate::algebra::ExactNumber;
use crate::coincide::canonical::SmallPatch;
use crate::error::Error;
use crate::io::{parse_json, patch_from_value, patch_from_value_as, read_small_patch};
use crate::patch::Patch;
use num_rational::BigRational;
use serde::de::{DeserializeSeed, Error as _, SeqAccess, Visitor};
use serde_json::Value;
use std::borrow::Cow;
use std::cell::RefCell;
use std::fmt;
use std::io::{BufRead, Read};

/// One input record, not yet parsed into a patch.
#[derive(Clone, Debug)]
pub enum Record {
    /// A line of a JSON Lines file (1-based line number, text).
    Line(usize, String),
    /// An element of a JSON array (0-based position, value).
    Element(usize, Value),
}

impl Record {
    /// The patch of this record.
    ///
    /// # Errors
    ///
    /// As [`patch_from_value`], prefixed with the line or element.
    pub fn patch(&self) -> Result<Patch<BigRational>, Error> {
        let parsed = match self {
            Record::Line(_, text) => parse_json(text).and_then(|v| patch_from_value(&v)),
            Record::Element(_, v) => patch_from_value(v),
        };
        parsed.map_err(|e| self.locate(e))
    }

    /// The patch of this record over any exact number type (e.g.
    /// `RealAlgebraic` for algebraic weights; no NURBS objects).
    ///
    /// # Errors
    ///
    /// As [`patch_from_value_as`], prefixed with the line or element.
    pub fn patch_as<T: ExactNumber>(&self) -> Result<Patch<T>, Error> {
        let parsed = match self {
            Record::Line(_, text) => parse_json(text).and_then(|v| patch_from_value_as(&v)),
            Record::Element(_, v) => patch_from_value_as(v),
        };
        parsed.map_err(|e| self.locate(e))
    }

    /// The patch of this record by the fast reader
    /// ([`read_small_patch`](crate::io::read_small_patch)) when it is a
    /// line of the plain shape; `None` sends it to [`patch`](Record::patch).
    pub fn small_patch(&self) -> Option<SmallPatch> {
        match self {
            Record::Line(_, text) => read_small_patch(text),
            Record::Element(..) => None,
        }
    }

    /// `e` prefixed with where this record is (`line 7: …`, `element 6: …`).
    pub fn locate(&self, e: Error) -> Error {
        match self {
            Record::Line(n, _) => Error::Format(format!("line {n}: {e}")),
            Record::Element(k, _) => Error::Format(format!("element {k}: {e}")),
        }
    }

    /// The record as compact JSON text (a line as it was read, borrowed).
    pub fn text(&self) -> Cow<'_, str> {
        match self {
            Record::Line(_, text) => Cow::Borrowed(text),
            Record::Element(_, v) => Cow::Owned(v.to_string()),
        }
    }
}

/// Read `input` (JSON Lines or a JSON array) and hand its records to `f`
/// in chunks of at most `chunk` (≥ 1), in input order, with the index of
/// each chunk's first record among all records. Returns the record count.
///
/// # Errors
///
/// A read or JSON syntax error (with its line), or the first error of `f`.
///
/// ```
/// use exact_bezier::io::for_each_chunk;
/// let text = "{\"kind\": \"curve\", \"points\": [[0], [1]]}\n\n{\"kind\": \"curve\", \"points\": [[2], [3]]}\n";
/// let mut seen = Vec::new();
/// let n = for_each_chunk(text.as_bytes(), 1, |first, recs| {
///     seen.push((first, recs.len()));
///     Ok(())
/// })
/// .unwrap();
/// assert_eq!((n, seen), (2, vec![(0, 1), (1, 1)]));
/// ```
pub fn for_each_chunk<R: BufRead>(
    mut input: R,
    chunk: usize,
    mut f: impl FnMut(usize, Vec<Record>) -> Result<(), Error>,
) -> Result<usize, Error> {
    let chunk = chunk.max(1);
    if first_byte(&mut input)? == Some(b'[') {
        read_array(input, chunk, &mut f)
    } else {
        read_lines(input, chunk, &mut f)
    }
}

fn read_error(e: std::io::Error) -> Error {
    Error::Io(format!("cannot read the input: {e}"))
}

/// The error `BufRead::read_line` gives for bytes that are not UTF-8.
fn invalid_utf8() -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::InvalidData,
        "stream did not contain valid UTF-8",
    )
}

/// Skip leading whitespace; the first other byte, left unread.
fn first_byte<R: BufRead>(input: &mut R) -> Result<Option<u8>, Error> {
    loop {
        let buf = input.fill_buf().map_err(read_error)?;
        if buf.is_empty() {
            return Ok(None);
        }
        match buf.iter().position(|b| !b.is_ascii_whitespace()) {
            Some(k) => {
                let b = buf[k];
                input.consume(k);
                return Ok(Some(b));
            }
            None => {
                let len = buf.len();
                input.consume(len);
            }
        }
    }
}

type Sink<'a> = &'a mut dyn FnMut(usize, Vec<Record>) -> Result<(), Error>;

/// Collects records and hands them on every `chunk`, with the index of
/// each chunk's first record.
struct Chunker<'a> {
    chunk: usize,
    count: usize,
    first: usize,
    buf: Vec<Record>,
    f: Sink<'a>,
}

impl<'a> Chunker<'a> {
    fn new(chunk: usize, f: Sink<'a>) -> Self {
        Chunker {
            chunk,
            count: 0,
            first: 0,
            buf: Vec::with_capacity(chunk),
            f,
        }
    }

    /// Add the record built from its index.
    fn push(&mut self, record: impl FnOnce(usize) -> Record) -> Result<(), Error> {
        self.buf.push(record(self.count));
        self.count += 1;
        if self.buf.len() == self.chunk {
            (self.f)(self.first, std::mem::take(&mut self.buf))?;
            self.first = self.count;
        }
        Ok(())
    }

    /// Hand on the last records; the record count.
    fn finish(mut self) -> Result<usize, Error> {
        if !self.buf.is_empty() {
            (self.f)(self.first, std::mem::take(&mut self.buf))?;
        }
        Ok(self.count)
    }
}

fn read_lines<R: BufRead>(mut input: R, chunk: usize, f: Sink<'_>) -> Result<usize, Error> {
    let mut line_no = 0;
    let mut out = Chunker::new(chunk, f);
    // One buffer for the bytes of every line; each line then gets one
    // allocation of its own length (not a doubling per line).
    let mut bytes = Vec::new();
    loop {
        bytes.clear();
        if input.read_until(b'\n', &mut bytes).map_err(read_error)? == 0 {
            break;
        }
        let line = std::str::from_utf8(&bytes)
            .map_err(|_| read_error(invalid_utf8()))?
            .to_owned();
        line_no += 1;
        if line.trim().is_empty() {
            continue;
        }
        if out.count == 0 && is_incomplete(&line) {
            let rest = std::io::Cursor::new(line).chain(input);
            return read_values(rest, out);
        }
        out.push(|_| Record::Line(line_no, line))?;
    }
    out.finish()
}

/// Is `line` the start of a longer JSON value (not a syntax error)?
fn is_incomplete(line: &str) -> bool {
    serde_json::from_str::<serde::de::IgnoredAny>(line).is_err_and(|e| e.is_eof())
}

/// A sequence of JSON values (whitespace-separated, any layout).
fn read_values<R: Read>(input: R, mut out: Chunker<'_>) -> Result<usize, Error> {
    for v in serde_json::Deserializer::from_reader(input).into_iter::<Value>() {
        let v = v.map_err(|e| Error::Format(e.to_string()))?;
        out.push(|k| Record::Element(k, v))?;
    }
    out.finish()
}

fn read_array<R: BufRead>(input: R, chunk: usize, f: Sink<'_>) -> Result<usize, Error> {
    let failure = RefCell::new(None);
    let mut de = serde_json::Deserializer::from_reader(input);
    let visitor = Chunks {
        out: Chunker::new(chunk, f),
        failure: &failure,
    };
    let counted = visitor
        .deserialize(&mut de)
        .and_then(|n| de.end().map(|()| n));
    match (counted, failure.into_inner()) {
        (_, Some(e)) => Err(e),
        (Ok(n), None) => Ok(n),
        (Err(e), None) => Err(Error::Format(e.to_string())),
    }
}

/// A visitor over the array's elements that flushes every `chunk`; an
/// error of `f` is kept in `failure` (typed) and stops the parse.
struct Chunks<'a> {
    out: Chunker<'a>,
    failure: &'a RefCell<Option<Error>>,
}

impl<'de> DeserializeSeed<'de> for Chunks<'_> {
    type Value = usize;
    fn deserialize<D: serde::Deserializer<'de>>(self, d: D) -> Result<usize, D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for Chunks<'_> {
    type Value = usize;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an array of curves and patches")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<usize, A::Error> {
        let Chunks { mut out, failure } = self;
        let stop = |e: Error| {
            *failure.borrow_mut() = Some(e);
            A::Error::custom("stopped")
        };
        while let Some(v) = seq.next_element::<Value>()? {
            out.push(|k| Record::Element(k, v)).map_err(stop)?;
        }
        out.finish().map_err(stop)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chunks(text: &str) -> (usize, Vec<(usize, Vec<String>)>) {
        let mut seen = Vec::new();
        let n = for_each_chunk(text.as_bytes(), 2, |first, recs| {
            let names = recs.iter().map(|r| r.patch().unwrap().kind().to_string());
            seen.push((first, names.collect()));
            Ok(())
        })
        .unwrap();
        (n, seen)
    }

    #[test]
    fn every_layout_gives_the_same_chunks() {
        let c = r#"{"kind": "curve", "points": [[0], [1]]}"#;
        let r = r#"{"kind": "rect", "points": [[[0], [1]]]}"#;
        let items = [c, r, c, c, r];
        let want = (
            5,
            vec![
                (0, vec!["curve".to_string(), "rect".into()]),
                (2, vec!["curve".into(), "curve".into()]),
                (4, vec!["rect".into()]),
            ],
        );
        assert_eq!(chunks(&items.join("\n")), want);
        assert_eq!(chunks(&format!(" [{}]", items.join(",\n"))), want);
        let pretty = items.map(|t| t.replace(", ", ",\n  ")).join("\n");
        assert_eq!(chunks(&pretty), want);
        assert_eq!(chunks("  \n"), (0, vec![]));
    }

    #[test]
    fn an_error_of_the_consumer_stops_an_array_and_keeps_its_type() {
        let c = r#"{"kind": "curve", "points": [[0], [1]]}"#;
        let text = format!("[{c}, {c}, {c}]");
        let e = for_each_chunk(text.as_bytes(), 1, |first, _| {
            if first == 1 {
                Err(Error::Domain("stop here".into()))
            } else {
                Ok(())
            }
        });
        assert!(matches!(e, Err(Error::Domain(m)) if m == "stop here"));
    }
}
