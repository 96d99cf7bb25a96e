//! A small streaming reader of the ISO 10303-21 exchange structure: the DATA
//! section's entity instances, one statement at a time, without holding the
//! file in memory.
//!
//! ```text
//! #12 = CARTESIAN_POINT('', (0., 1.5, -2.E-1));            simple instance
//! #13 = (BOUNDED_SURFACE() B_SPLINE_SURFACE(2, 2, …) …);     complex instance
//! ```
//!
//! Parameters: numbers (kept as their text, read exactly on demand),
//! strings `'…'` (`''` is a quote), enumerations `.T.`, references `#7`,
//! `$` (unset), `*` (derived), lists `( … )` and typed values `NAME( … )`.
//! Comments `/* … */` are skipped anywhere outside strings. Reference:
//! ISO 10303-21:2016 §6–§11 (the exchange structure's grammar).

use crate::error::Error;
use crate::limits::{MAX_STEP_DEPTH as MAX_DEPTH, MAX_STEP_STATEMENT as MAX_STATEMENT};
use std::io::BufRead;

/// One parameter of an entity instance.
#[derive(Clone, Debug, PartialEq)]
pub enum Param {
    /// An integer or real, as written (`2`, `-1.5E-3`, `0.`).
    Number(String),
    /// A string (quotes removed, `''` unescaped).
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

    /// The next statement's text (comments removed, strings kept), or
    /// `None` at the end of input.
    fn statement(&mut self) -> Result<Option<String>, Error> {
        let mut out: Vec<u8> = Vec::new();
        let mut in_str = false;
        let mut comment = false;
        let mut prev = 0u8;
        loop {
            let buf = self
                .input
                .fill_buf()
                .map_err(|e| Error::Io(format!("cannot read the STEP file: {e}")))?;
            if buf.is_empty() {
                let rest = String::from_utf8_lossy(&out).trim().to_owned();
                return if rest.is_empty() {
                    Ok(None)
                } else {
                    Err(self.err("the file ends inside a statement (missing ';')"))
                };
            }
            let mut used = 0;
            let mut finished = false;
            for &b in buf {
                used += 1;
                if b == b'\n' {
                    self.line += 1;
                }
                if comment {
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
                if !in_str && b == b';' {
                    finished = true;
                    break;
                }
                out.push(b);
                prev = b;
            }
            self.input.consume(used);
            if out.len() > MAX_STATEMENT {
                return Err(self.err(&format!("a statement longer than {MAX_STATEMENT} bytes")));
            }
            if finished {
                return String::from_utf8(out)
                    .map(Some)
                    .map_err(|_| self.err("a statement is not UTF-8 text"));
            }
        }
    }

    fn err(&self, what: &str) -> Error {
        Error::Format(format!("STEP line {}: {what}", self.line))
    }

    /// The next entity instance of the DATA section, `None` after its end.
    ///
    /// # Errors
    ///
    /// [`Error::Format`] with the line number for malformed syntax.
    pub fn next_instance(&mut self) -> Result<Option<Instance>, Error> {
        while !self.done {
            let Some(text) = self.statement()? else {
                self.done = true;
                break;
            };
            let t = text.trim();
            if !self.in_data {
                if t == "DATA" || t.starts_with("DATA(") || t.starts_with("DATA (") {
                    self.in_data = true;
                }
                continue;
            }
            if t == "ENDSEC" {
                self.in_data = false;
                continue;
            }
            if t.starts_with('#') {
                return parse_instance(t).map(Some).map_err(|e| self.err(&e));
            }
            if t.starts_with("END-ISO-10303-21") {
                self.done = true;
            }
        }
        Ok(None)
    }
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
        let mut out = Vec::new();
        loop {
            match self.s.get(self.pos) {
                None => return Err("unterminated string".into()),
                Some(b'\'') if self.s.get(self.pos + 1) == Some(&b'\'') => {
                    out.push(b'\'');
                    self.pos += 2;
                }
                Some(b'\'') => {
                    self.pos += 1;
                    return Ok(Param::Str(String::from_utf8_lossy(&out).into_owned()));
                }
                Some(&b) => {
                    out.push(b);
                    self.pos += 1;
                }
            }
        }
    }
}

/// Parse `#id = NAME(…)` or `#id = (NAME(…) NAME(…) …)`.
fn parse_instance(text: &str) -> Result<Instance, String> {
    let mut c = Cursor {
        s: text.as_bytes(),
        pos: 0,
    };
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

    #[test]
    fn malformed_input_names_the_line() {
        let e = all("DATA;\n#1 = FOO(1,;\n").unwrap_err();
        assert!(e.to_string().contains("STEP line 2"), "{e}");
        let e = all("DATA;\n#1 = FOO(1").unwrap_err();
        assert!(e.to_string().contains("missing ';'"), "{e}");
        let deep = format!("DATA;\n#1 = FOO({}1{});", "(".repeat(100), ")".repeat(100));
        assert!(all(&deep).unwrap_err().to_string().contains("nested"));
    }
}
