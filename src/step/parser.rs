//! A small streaming reader of the ISO 10303-21 exchange structure: the DATA
//! section's entity instances, one statement at a time or a batch at a time
//! (parsed on all cores), without holding the file in memory.
//!
//! ```text
//! #12 = CARTESIAN_POINT('', (0., 1.5, -2.E-1));            simple instance
//! #13 = (BOUNDED_SURFACE() B_SPLINE_SURFACE(2, 2, …) …);     complex instance
//! ```
//!
//! Parameters: numbers (kept as their text, read exactly on demand),
//! strings `'…'` (decoded by [`decode_string`]), enumerations `.T.`,
//! references `#7`, `$` (unset), `*` (derived), lists `( … )` and typed
//! values `NAME( … )`. Comments `/* … */` are skipped anywhere outside
//! strings. Reference: ISO 10303-21:2016 §6–§11 (the exchange structure's
//! grammar), §6.4.3 (strings).
//!
//! Bytes outside ASCII are tolerated inside strings (CAD systems write raw
//! Latin-1 or UTF-8 in author names; strings are never geometry); outside a
//! string they are an error naming the line of the byte.

use crate::error::Error;
use crate::limits::{MAX_STEP_DEPTH as MAX_DEPTH, MAX_STEP_STATEMENT as MAX_STATEMENT};
use std::io::BufRead;

/// One parameter of an entity instance.
#[derive(Clone, Debug, PartialEq)]
pub enum Param {
    /// An integer or real, as written (`2`, `-1.5E-3`, `0.`).
    Number(String),
    /// A string, decoded ([`decode_string`]).
    Str(String),
    /// An enumeration `.NAME.` (dots removed).
    Enum(String),
    /// A reference `#id`.
    Ref(u64),
    /// `$`: no value.
    Unset,
    /// `*`: derived.
    Derived,
    /// `( … )`.
    List(Vec<Param>),
    /// `NAME( … )`, e.g. `LENGTH_MEASURE(1.)`.
    Typed(String, Vec<Param>),
}

/// One record `NAME(params)`; a complex instance has several.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// The entity name, upper case as written.
    pub name: String,
    /// Its parameters.
    pub params: Vec<Param>,
}

/// An entity instance `#id = …;` of the DATA section.
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    /// The instance id.
    pub id: u64,
    /// One record (simple instance) or several (complex instance).
    pub records: Vec<Record>,
    /// Was it written as a complex instance `( … )`?
    pub complex: bool,
}

impl Instance {
    /// Its record names joined by spaces, in the order written
    /// (`"BOUNDED_CURVE B_SPLINE_CURVE …"`; the one name of a simple
    /// instance).
    pub fn record_names(&self) -> String {
        let names: Vec<&str> = self.records.iter().map(|r| r.name.as_str()).collect();
        names.join(" ")
    }
}

/// Reads statements from a byte stream and yields the DATA section's
/// instances in order.
pub struct Reader<R> {
    input: R,
    line: usize,
    in_data: bool,
    done: bool,
}

impl<R: BufRead> Reader<R> {
    /// A reader over `input`.
    pub fn new(input: R) -> Self {
        Reader {
            input,
            line: 1,
            in_data: false,
            done: false,
        }
    }

    /// Append the next statement's bytes (comments removed, strings kept)
    /// to `out`; `false` (and `out` unchanged) at the end of input.
    fn statement(&mut self, out: &mut Vec<u8>) -> Result<bool, Error> {
        let start = out.len();
        let mut in_str = false;
        let mut comment = false;
        let mut prev = 0u8;
        loop {
            let buf = self
                .input
                .fill_buf()
                .map_err(|e| Error::Io(format!("cannot read the STEP file: {e}")))?;
            if buf.is_empty() {
                let rest = out[start..].trim_ascii().is_empty();
                out.truncate(start);
                return if rest {
                    Ok(false)
                } else {
                    Err(self.err("the file ends inside a statement (missing ';')"))
                };
            }
            let mut used = 0;
            let mut finished = false;
            while used < buf.len() {
                // A run of bytes that change no state is copied (or, in a
                // comment, skipped) at once.
                let run = quiet_run(&buf[used..], in_str, comment);
                if run > 0 {
                    if !comment {
                        out.extend_from_slice(&buf[used..used + run]);
                    }
                    prev = buf[used + run - 1];
                    used += run;
                    continue;
                }
                let b = buf[used];
                used += 1;
                if b == b'\n' {
                    self.line += 1;
                }
                if comment {
                    if b == b'\n' {
                        out.push(b);
                    }
                    if prev == b'*' && b == b'/' {
                        comment = false;
                        prev = 0;
                    } else {
                        prev = b;
                    }
                    continue;
                }
                if !in_str && prev == b'/' && b == b'*' {
                    out.pop();
                    comment = true;
                    prev = 0;
                    continue;
                }
                if b == b'\'' {
                    in_str = !in_str;
                }
                if !in_str && !b.is_ascii() {
                    self.input.consume(used);
                    return Err(self.err(&format!(
                        "the byte 0x{b:02X} outside a string (only ASCII is allowed there)"
                    )));
                }
                if !in_str && b == b';' {
                    finished = true;
                    break;
                }
                out.push(b);
                prev = b;
            }
            self.input.consume(used);
            if out.len() - start > MAX_STATEMENT {
                return Err(self.err(&format!("a statement longer than {MAX_STATEMENT} bytes")));
            }
            if finished {
                return Ok(true);
            }
        }
    }

    fn err(&self, what: &str) -> Error {
        Error::Format(format!("STEP line {}: {what}", self.line))
    }

    /// Append the next instance statement of the DATA section to `out`
    /// and give the line where it ends; `None` after the section's end.
    fn next_statement(&mut self, out: &mut Vec<u8>) -> Result<Option<usize>, Error> {
        while !self.done {
            let start = out.len();
            if !self.statement(out)? {
                self.done = true;
                break;
            }
            let t = out[start..].trim_ascii();
            if !self.in_data {
                if t == b"DATA" || t.starts_with(b"DATA(") || t.starts_with(b"DATA (") {
                    self.in_data = true;
                }
            } else if t == b"ENDSEC" {
                self.in_data = false;
            } else if t.starts_with(b"#") {
                return Ok(Some(self.line));
            } else if t.starts_with(b"END-ISO-10303-21") {
                self.done = true;
            }
            out.truncate(start);
        }
        Ok(None)
    }

    /// The next entity instance of the DATA section, `None` after its end.
    ///
    /// # Errors
    ///
    /// [`Error::Format`] with the line number for malformed syntax.
    pub fn next_instance(&mut self) -> Result<Option<Instance>, Error> {
        let mut text = Vec::new();
        self.next_statement(&mut text)?
            .map(|end_line| parse_statement(&text, end_line))
            .transpose()
    }

    /// The next instance statements of the DATA section, split from the
    /// stream but not parsed: up to `max` of them and up to [`BATCH_BYTES`]
    /// of text (or one longer statement). Empty after the section's end; a
    /// syntax error the splitter finds ends the batch and the reading.
    pub fn split_batch(&mut self, max: usize) -> Statements {
        let mut batch = Statements::default();
        while batch.spans.len() < max && batch.text.len() < BATCH_BYTES {
            let start = batch.text.len();
            match self.next_statement(&mut batch.text) {
                Ok(Some(end_line)) => batch.spans.push((start, batch.text.len(), end_line)),
                Ok(None) => break,
                Err(e) => {
                    batch.text.truncate(start);
                    batch.stop = Some(e);
                    self.done = true;
                    break;
                }
            }
        }
        batch
    }

    /// The next instances of the DATA section, in order: a
    /// [`split_batch`](Reader::split_batch), [parsed](Statements::parse)
    /// on all cores. Empty after the section's end.
    ///
    /// # Errors
    ///
    /// As [`Reader::next_instance`]: the first malformed statement in the
    /// file's order.
    pub fn next_batch(&mut self, max: usize) -> Result<Vec<Instance>, Error> {
        self.split_batch(max).parse()
    }
}

/// Instance statements split from the stream and not yet parsed
/// ([`Reader::split_batch`]): their text in one buffer, where each ends
/// (byte range and line), and the splitter's error that ended them, if any.
#[derive(Debug, Default)]
pub struct Statements {
    text: Vec<u8>,
    spans: Vec<(usize, usize, usize)>,
    stop: Option<Error>,
}

impl Statements {
    /// No statement and no error: the stream is read.
    pub fn is_empty(&self) -> bool {
        self.spans.is_empty() && self.stop.is_none()
    }

    /// The instances, parsed on all cores, in order.
    ///
    /// # Errors
    ///
    /// The first malformed statement in the file's order: a statement that
    /// does not parse, else the splitter's error after the last statement.
    pub fn parse(self) -> Result<Vec<Instance>, Error> {
        use rayon::prelude::*;
        let parsed: Vec<Result<Instance, Error>> = self
            .spans
            .par_iter()
            .map(|&(start, end, end_line)| parse_statement(&self.text[start..end], end_line))
            .collect();
        let instances = parsed.into_iter().collect::<Result<Vec<_>, _>>()?;
        match self.stop {
            Some(e) => Err(e),
            None => Ok(instances),
        }
    }
}

/// The text a batch of [`Reader::split_batch`] holds at most before it is
/// parsed (a longer single statement is still read whole, up to the
/// statement limit).
pub const BATCH_BYTES: usize = 1 << 22;

/// Parse one instance statement that ends on line `end_line`; an error
/// names the line where it was found.
fn parse_statement(bytes: &[u8], end_line: usize) -> Result<Instance, Error> {
    let t = bytes.trim_ascii();
    parse_instance(t).map_err(|(pos, e)| {
        let after = t[pos.min(t.len())..].iter().filter(|&&b| b == b'\n');
        let line = end_line - after.count();
        Error::Format(format!("STEP line {line}: {e}"))
    })
}

/// How many leading bytes of `buf` change no state of the splitter: in a
/// comment, anything but `*`, `/` and a newline; in a string, anything but
/// a quote and a newline; elsewhere printable ASCII but the quote, `/`,
/// `*` and `;`.
fn quiet_run(buf: &[u8], in_str: bool, comment: bool) -> usize {
    let quiet = |b: &u8| match (comment, in_str) {
        (true, _) => !matches!(b, b'*' | b'/' | b'\n'),
        (false, true) => !matches!(b, b'\'' | b'\n'),
        (false, false) => matches!(b, 0x20..=0x7e) && !matches!(b, b'\'' | b'/' | b'*' | b';'),
    };
    buf.iter().position(|b| !quiet(b)).unwrap_or(buf.len())
}

/// A cursor over one statement.
struct Cursor<'a> {
    s: &'a [u8],
    pos: usize,
}

impl Cursor<'_> {
    fn skip_ws(&mut self) {
        while self.pos < self.s.len() && self.s[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip_ws();
        self.s.get(self.pos).copied()
    }

    fn expect(&mut self, c: u8) -> Result<(), String> {
        if self.peek() == Some(c) {
            self.pos += 1;
            Ok(())
        } else {
            Err(format!("expected '{}' at byte {}", c as char, self.pos))
        }
    }

    fn take_while(&mut self, f: impl Fn(u8) -> bool) -> &str {
        let start = self.pos;
        while self.pos < self.s.len() && f(self.s[self.pos]) {
            self.pos += 1;
        }
        std::str::from_utf8(&self.s[start..self.pos]).unwrap_or("")
    }

    fn keyword(&mut self) -> Result<String, String> {
        self.skip_ws();
        let k = self.take_while(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'-');
        if k.is_empty() {
            return Err(format!("expected an entity name at byte {}", self.pos));
        }
        Ok(k.to_ascii_uppercase())
    }

    fn id(&mut self) -> Result<u64, String> {
        self.expect(b'#')?;
        self.take_while(|b| b.is_ascii_digit())
            .parse()
            .map_err(|_| format!("bad instance id at byte {}", self.pos))
    }

    fn params(&mut self, depth: usize) -> Result<Vec<Param>, String> {
        if depth > MAX_DEPTH {
            return Err(format!("lists nested deeper than {MAX_DEPTH}"));
        }
        self.expect(b'(')?;
        let mut out = Vec::new();
        if self.peek() == Some(b')') {
            self.pos += 1;
            return Ok(out);
        }
        loop {
            out.push(self.param(depth)?);
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b')') => {
                    self.pos += 1;
                    return Ok(out);
                }
                _ => return Err(format!("expected ',' or ')' at byte {}", self.pos)),
            }
        }
    }

    fn param(&mut self, depth: usize) -> Result<Param, String> {
        match self.peek() {
            Some(b'(') => Ok(Param::List(self.params(depth + 1)?)),
            Some(b'#') => Ok(Param::Ref(self.id()?)),
            Some(b'$') => {
                self.pos += 1;
                Ok(Param::Unset)
            }
            Some(b'*') => {
                self.pos += 1;
                Ok(Param::Derived)
            }
            Some(b'\'') => self.string(),
            Some(b'.') => {
                self.pos += 1;
                let e = self.take_while(|b| b != b'.').to_owned();
                self.expect(b'.')?;
                Ok(Param::Enum(e))
            }
            Some(b'"') => {
                self.pos += 1;
                let e = self.take_while(|b| b != b'"').to_owned();
                self.expect(b'"')?;
                Ok(Param::Str(e))
            }
            Some(b) if b == b'-' || b == b'+' || b.is_ascii_digit() => Ok(Param::Number(
                self.take_while(|b| b.is_ascii_digit() || b"+-.eE".contains(&b))
                    .to_owned(),
            )),
            Some(b) if b.is_ascii_alphabetic() => {
                let name = self.keyword()?;
                Ok(Param::Typed(name, self.params(depth + 1)?))
            }
            _ => Err(format!("unexpected input at byte {}", self.pos)),
        }
    }

    fn string(&mut self) -> Result<Param, String> {
        self.pos += 1;
        let start = self.pos;
        loop {
            match self.s.get(self.pos) {
                None => return Err("unterminated string".into()),
                Some(b'\'') if self.s.get(self.pos + 1) == Some(&b'\'') => self.pos += 2,
                Some(b'\'') => {
                    self.pos += 1;
                    return decode_string(&self.s[start..self.pos - 1]).map(Param::Str);
                }
                Some(_) => self.pos += 1,
            }
        }
    }
}

/// Decode the body of a string (between its quotes) per ISO 10303-21
/// §6.4.3: `''` is a quote, `\\` a backslash, `\S\c` the character
/// `c` + 128 of the current ISO 8859 page (`\PA\` … `\PI\` choose it;
/// only part 1, Latin-1, is mapped, other pages give U+FFFD), `\X\hh` the
/// Latin-1 character `hh`, `\X2\hhhh…\X0\` UTF-16 code units and
/// `\X4\hhhhhhhh…\X0\` UCS-4 characters. Raw bytes outside ASCII are
/// kept as UTF-8 where they form it, else read as Latin-1.
///
/// # Errors
///
/// A malformed escape (bad hex digits, a missing `\X0\`), described.
///
/// ```
/// use exact_bezier::step::parser::decode_string;
/// assert_eq!(decode_string(br"K\X\F6ln \X2\00E9\X0\t\S\) it''s").unwrap(), "Köln ét© it's");
/// ```
pub fn decode_string(raw: &[u8]) -> Result<String, String> {
    let mut out = String::with_capacity(raw.len());
    let mut page = b'A';
    let mut i = 0;
    while i < raw.len() {
        let rest = &raw[i..];
        if rest.starts_with(b"''") {
            out.push('\'');
            i += 2;
        } else if rest.starts_with(b"\\\\") {
            out.push('\\');
            i += 2;
        } else if rest.starts_with(b"\\S\\") && rest.len() > 3 {
            let c = u32::from(rest[3]) + 128;
            out.push(if page == b'A' {
                char::from_u32(c).unwrap_or(char::REPLACEMENT_CHARACTER)
            } else {
                char::REPLACEMENT_CHARACTER
            });
            i += 4;
        } else if rest.starts_with(b"\\P") && rest.len() > 3 && rest.get(3) == Some(&b'\\') {
            page = rest[2];
            i += 4;
        } else if rest.starts_with(b"\\X\\") {
            out.push(char::from(hex(rest.get(3..5), "\\X\\")? as u8));
            i += 5;
        } else if rest.starts_with(b"\\X2\\") || rest.starts_with(b"\\X4\\") {
            i += 4 + wide(&rest[4..], rest[2] == b'4', &mut out)?;
        } else if rest[0].is_ascii() {
            out.push(char::from(rest[0]));
            i += 1;
        } else {
            let n = rest.iter().take_while(|b| !b.is_ascii()).count();
            match std::str::from_utf8(&rest[..n]) {
                Ok(t) => out.push_str(t),
                Err(_) => out.extend(rest[..n].iter().map(|&b| char::from(b))),
            }
            i += n;
        }
    }
    Ok(out)
}

/// The value of the hex digits `digits`.
fn hex(digits: Option<&[u8]>, what: &str) -> Result<u32, String> {
    digits
        .and_then(|d| std::str::from_utf8(d).ok())
        .and_then(|d| u32::from_str_radix(d, 16).ok())
        .ok_or_else(|| format!("a malformed {what} escape in a string"))
}

/// Decode the characters of a `\X2\` (UTF-16, `ucs4` false) or `\X4\`
/// (UCS-4) escape up to its `\X0\`; returns the bytes used.
fn wide(s: &[u8], ucs4: bool, out: &mut String) -> Result<usize, String> {
    let what = if ucs4 { "\\X4\\" } else { "\\X2\\" };
    let end = s
        .windows(4)
        .position(|w| w == b"\\X0\\")
        .ok_or_else(|| format!("a {what} escape without its \\X0\\ in a string"))?;
    let width = if ucs4 { 8 } else { 4 };
    if end % width != 0 {
        return Err(format!("a malformed {what} escape in a string"));
    }
    let units = (0..end / width)
        .map(|k| hex(s.get(k * width..(k + 1) * width), what))
        .collect::<Result<Vec<u32>, _>>()?;
    if ucs4 {
        out.extend(
            units
                .iter()
                .map(|&u| char::from_u32(u).unwrap_or(char::REPLACEMENT_CHARACTER)),
        );
    } else {
        let units16 = units.iter().map(|&u| u as u16);
        out.extend(char::decode_utf16(units16).map(|c| c.unwrap_or(char::REPLACEMENT_CHARACTER)));
    }
    Ok(end + 4)
}

/// Parse `#id = NAME(…)` or `#id = (NAME(…) NAME(…) …)`; an error comes
/// with the byte position where it was found.
fn parse_instance(text: &[u8]) -> Result<Instance, (usize, String)> {
    let mut c = Cursor { s: text, pos: 0 };
    instance(&mut c).map_err(|e| (c.pos, e))
}

fn instance(c: &mut Cursor) -> Result<Instance, String> {
    let id = c.id()?;
    c.expect(b'=')?;
    let complex = c.peek() == Some(b'(');
    let mut records = Vec::new();
    if complex {
        c.pos += 1;
        while c.peek() != Some(b')') {
            let name = c.keyword()?;
            records.push(Record {
                name,
                params: c.params(1)?,
            });
        }
        c.pos += 1;
    } else {
        let name = c.keyword()?;
        records.push(Record {
            name,
            params: c.params(1)?,
        });
    }
    if records.is_empty() {
        return Err(format!("instance #{id} has no record"));
    }
    if c.peek().is_some() {
        return Err(format!("trailing text after instance #{id}"));
    }
    Ok(Instance {
        id,
        records,
        complex,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(text: &str) -> Result<Vec<Instance>, Error> {
        let mut r = Reader::new(text.as_bytes());
        let mut out = Vec::new();
        while let Some(i) = r.next_instance()? {
            out.push(i);
        }
        Ok(out)
    }

    const FILE: &str =
        "ISO-10303-21;\nHEADER;\nFILE_NAME('a;b.stp','',(''),(''),'','','');\nENDSEC;\nDATA;\n\
        #1 = CARTESIAN_POINT('it''s /* not a comment */', (0., -1.5E-1, 2));\n\
        /* a comment; with a semicolon */\n\
        #2=(BOUNDED_SURFACE()B_SPLINE_SURFACE(1,1,((#1,#1),(#1,#1)),.UNSPECIFIED.,.F.,.F.,.F.)\n\
        REPRESENTATION_ITEM(''));\n\
        #3 = MEASURE_WITH_UNIT(LENGTH_MEASURE(1.),$,*);\nENDSEC;\nEND-ISO-10303-21;\n";

    #[test]
    fn reads_simple_complex_strings_comments_and_typed_values() {
        let v = all(FILE).unwrap();
        assert_eq!(v.len(), 3);
        assert_eq!(v[0].records[0].name, "CARTESIAN_POINT");
        assert_eq!(
            v[0].records[0].params,
            vec![
                Param::Str("it's /* not a comment */".into()),
                Param::List(vec![
                    Param::Number("0.".into()),
                    Param::Number("-1.5E-1".into()),
                    Param::Number("2".into())
                ])
            ]
        );
        assert!(v[1].complex);
        let names: Vec<&str> = v[1].records.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(
            names,
            ["BOUNDED_SURFACE", "B_SPLINE_SURFACE", "REPRESENTATION_ITEM"]
        );
        assert_eq!(v[1].records[1].params[4], Param::Enum("F".into()));
        assert_eq!(
            v[2].records[0].params,
            vec![
                Param::Typed("LENGTH_MEASURE".into(), vec![Param::Number("1.".into())]),
                Param::Unset,
                Param::Derived
            ]
        );
    }

    /// Every instance of `text`, read `max` statements at a time.
    fn batched(text: &str, max: usize) -> Result<Vec<Instance>, Error> {
        let mut r = Reader::new(text.as_bytes());
        let mut out = Vec::new();
        loop {
            let batch = r.next_batch(max)?;
            if batch.is_empty() {
                return Ok(out);
            }
            out.extend(batch);
        }
    }

    #[test]
    fn batches_read_what_single_statements_read() {
        let one_by_one = all(FILE).unwrap();
        assert_eq!(one_by_one.len(), 3);
        for max in [1, 2, 3, 100] {
            assert_eq!(batched(FILE, max).unwrap(), one_by_one, "batches of {max}");
        }
    }

    #[test]
    fn a_batch_reports_the_first_error_in_file_order() {
        // Line 3 does not parse; line 5 has a byte the splitter refuses.
        let text = "DATA;\n#1 = A(1.);\n#2 = B(1,;\n#3 = C(2.);\n#4 = D(\u{e9});\n";
        for max in [1, 2, 10] {
            let e = batched(text, max).unwrap_err().to_string();
            assert!(e.contains("STEP line 3"), "batches of {max}: {e}");
        }
        let later = "DATA;\n#1 = A(1.);\n#2 = D(\u{e9});\n#3 = B(1,;\n";
        let e = batched(later, 10).unwrap_err().to_string();
        assert!(
            e.contains("STEP line 3") && e.contains("outside a string"),
            "{e}"
        );
    }

    #[test]
    fn malformed_input_names_the_line() {
        let e = all("DATA;\n#1 = FOO(1,;\n").unwrap_err();
        assert!(e.to_string().contains("STEP line 2"), "{e}");
        let e = all("DATA;\n#1 = FOO(1").unwrap_err();
        assert!(e.to_string().contains("missing ';'"), "{e}");
        let deep = format!("DATA;\n#1 = FOO({}1{});", "(".repeat(100), ")".repeat(100));
        assert!(all(&deep).unwrap_err().to_string().contains("nested"));
    }

    #[test]
    fn strings_are_decoded_per_part_21() {
        let cases: [(&[u8], &str); 7] = [
            (br"it''s", "it's"),
            (br"a\\b", r"a\b"),
            (br"\X\E9t\X\E9", "été"),
            (br"\X2\03B103B2\X0\!", "αβ!"),
            (br"\X4\0001F600\X0\", "😀"),
            (br"\PA\\S\i", "é"),
            (b"Jos\xe9 M\xc3\xbcller", "José Müller"),
        ];
        for (raw, want) in cases {
            assert_eq!(decode_string(raw).unwrap(), want, "{raw:?}");
        }
        // U+1F600 as a UTF-16 surrogate pair.
        assert_eq!(decode_string(br"\X2\D83DDE00\X0\").unwrap(), "😀");
        assert!(decode_string(br"\X2\00E9").unwrap_err().contains(r"\X0\"));
        assert!(decode_string(br"\X\G1").is_err());
    }

    #[test]
    fn raw_bytes_in_strings_are_read_and_outside_strings_name_their_line() {
        // A SolidWorks-style header and data string with Latin-1 bytes.
        let mut text = b"ISO-10303-21;\nHEADER;\nFILE_NAME('x','',('Ren\xe9'),(''),'','','');\nENDSEC;\nDATA;\n".to_vec();
        text.extend_from_slice(
            b"#1=PERSON('M\xfcller',\n'x',$,$,$,$);\n#2=CARTESIAN_POINT('',(1.,2.,3.));\nENDSEC;\n",
        );
        let mut r = Reader::new(&text[..]);
        let p = r.next_instance().unwrap().unwrap();
        assert_eq!(p.records[0].params[0], Param::Str("Müller".into()));
        assert_eq!(r.next_instance().unwrap().unwrap().id, 2);
        let bad = b"DATA;\n#1=FOO(1,\n2\xe9,\n3);\n";
        let e = Reader::new(&bad[..]).next_instance().unwrap_err();
        assert!(e.to_string().contains("STEP line 3"), "{e}");
        assert!(e.to_string().contains("0xE9"), "{e}");
    }

    #[test]
    fn a_syntax_error_names_the_line_where_it_is() {
        let e = all("DATA;\n#1 = FOO(1,\n2,\n3 4,\n5);\n").unwrap_err();
        assert!(e.to_string().contains("STEP line 4"), "{e}");
        assert!(all("DATA;\n#1 = ();\n")
            .unwrap_err()
            .to_string()
            .contains("no record"));
    }
}
