//! The bulk commands' fast reader: a JSON line holding a curve or rect
//! patch of the plain shape read straight from its bytes into a
//! [`SmallPatch`] (machine fractions), without a JSON value in between.
//!
//! The plain shape: one object with the fields `"kind"` (`"curve"` or
//! `"rect"`), `"points"`, and optionally `"degree"` and `"weights"`, each
//! once, in any order; numbers as JSON numbers `-?(0|[1-9]d*)(.d+)?` or
//! strings `"-?d+(.d+)?(/d+)?"` that fit `i128`. Anything else — another
//! field, an exponent, an escape, a big number, a shape error, a
//! non-positive weight, a number over `--max-digits` — gives `None`, and
//! the caller reads the line with the general reader
//! ([`patch_from_value`](crate::io::patch_from_value)), which accepts or
//! refuses it as it always did. So what this reader accepts is valid JSON
//! that the general reader turns into the same patch (tested against it).

use crate::coincide::canonical::SmallPatch;
use crate::limits::{self, MAX_DEGREE, MAX_DIMENSION};
use std::cell::RefCell;

thread_local! {
    /// The grids of the points and of the weights of the line being read,
    /// reused across the lines a thread reads (no allocation per line).
    static GRIDS: RefCell<Grids> = RefCell::default();
}

/// The patch of one JSON line of the plain shape, or `None` (then the
/// general reader decides).
///
/// ```
/// use exact_bezier::io::{parse_json, patch_from_value, read_small_patch};
/// let line = r#"{"kind": "curve", "points": [[0, 0], ["1/2", 1.5], [3, 0]], "weights": [1, "2", 1]}"#;
/// let fast = read_small_patch(line).unwrap().to_patch().unwrap();
/// assert_eq!(fast, patch_from_value(&parse_json(line).unwrap()).unwrap());
/// assert!(read_small_patch(r#"{"kind": "curve", "points": [[1e3]]}"#).is_none());
/// ```
pub fn read_small_patch(line: &str) -> Option<SmallPatch> {
    GRIDS.with(|kept| match kept.try_borrow_mut() {
        Ok(mut grids) => read_with(line, &mut grids),
        // Not reached (reading does not read again), but never a panic.
        Err(_) => read_with(line, &mut Grids::default()),
    })
}

/// [`read_small_patch`] with `grids` to read the numbers into.
fn read_with(line: &str, grids: &mut Grids) -> Option<SmallPatch> {
    let mut c = Cursor {
        bytes: line.as_bytes(),
        at: 0,
        max_digits: limits::current().max_digits,
    };
    let fields = c.object(grids)?;
    c.skip_space();
    if c.at != c.bytes.len() {
        return None;
    }
    fields.patch(grids)
}

/// The points' and the weights' grids of one line.
#[derive(Default)]
struct Grids {
    points: Grid,
    weights: Grid,
}

/// Nested arrays of numbers as read: the numbers in order and the length
/// of every array, innermost level first.
#[derive(Default)]
struct Grid {
    numbers: Vec<(i128, i128)>,
    /// `lens[k]`: the common length of the arrays at depth `k` from the
    /// innermost (`None` until one is read).
    lens: Vec<Option<usize>>,
}

/// What the declared `"degree"` was: a count or a pair of counts.
enum Degree {
    One(usize),
    Two(usize, usize),
}

/// The fields of the object; whether the points and the weights were
/// read (into [`Grids`]).
#[derive(Default)]
struct Fields {
    curve: Option<bool>,
    degree: Option<Degree>,
    points: bool,
    weights: bool,
}

impl Fields {
    /// The patch the fields describe (their numbers in `grids`), if they
    /// are consistent.
    fn patch(self, grids: &mut Grids) -> Option<SmallPatch> {
        let curve = self.curve?;
        if !self.points {
            return None;
        }
        let points = &grids.points;
        let depth = if curve { 2 } else { 3 };
        if points.lens.len() != depth {
            return None;
        }
        let dim = points.lens[0]?;
        let shape = if curve {
            (points.lens[1]? - 1, 0)
        } else {
            (points.lens[2]? - 1, points.lens[1]? - 1)
        };
        if dim > MAX_DIMENSION || shape.0 > MAX_DEGREE || shape.1 > MAX_DEGREE {
            return None;
        }
        let declared_ok = match (self.degree, curve) {
            (None, _) => true,
            (Some(Degree::One(n)), true) => n == shape.0,
            (Some(Degree::Two(m, n)), false) => (m, n) == shape,
            _ => false,
        };
        let weights = &mut grids.weights;
        if self.weights {
            let shape_of_weights: &[Option<usize>] = if curve {
                &[Some(shape.0 + 1)]
            } else {
                &[Some(shape.1 + 1), Some(shape.0 + 1)]
            };
            if weights.lens != shape_of_weights {
                return None;
            }
        } else {
            weights.numbers.clear();
            let count = (shape.0 + 1) * (shape.1 + 1);
            weights.numbers.resize(count, (1, 1));
        }
        if !declared_ok {
            return None;
        }
        SmallPatch::new(curve, shape, dim, &points.numbers, &weights.numbers)
    }
}

/// A position in the line's bytes.
struct Cursor<'a> {
    bytes: &'a [u8],
    at: usize,
    max_digits: u64,
}

impl Cursor<'_> {
    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.at).copied()
    }

    /// Skip JSON whitespace.
    fn skip_space(&mut self) {
        while let Some(b' ' | b'\t' | b'\n' | b'\r') = self.peek() {
            self.at += 1;
        }
    }

    /// Skip whitespace and take `b`.
    fn expect(&mut self, b: u8) -> Option<()> {
        self.skip_space();
        (self.peek() == Some(b)).then(|| self.at += 1)
    }

    /// Skip whitespace and take `b` if it is next.
    fn take(&mut self, b: u8) -> bool {
        self.expect(b).is_some()
    }

    /// A string without escapes, as bytes.
    fn string(&mut self) -> Option<&[u8]> {
        self.expect(b'"')?;
        let start = self.at;
        loop {
            match self.peek()? {
                b'"' => break,
                b'\\' | 0..=0x1f => return None,
                _ => self.at += 1,
            }
        }
        self.at += 1;
        Some(&self.bytes[start..self.at - 1])
    }

    /// The object's fields, their numbers read into `grids`; `None` on
    /// another or a repeated field.
    fn object(&mut self, grids: &mut Grids) -> Option<Fields> {
        self.expect(b'{')?;
        let mut f = Fields::default();
        loop {
            let repeated = match self.string()? {
                b"kind" => {
                    let kind = match self.colon()?.string()? {
                        b"curve" => true,
                        b"rect" => false,
                        _ => return None,
                    };
                    f.curve.replace(kind).is_some()
                }
                b"degree" => {
                    let d = self.colon()?.degree()?;
                    f.degree.replace(d).is_some()
                }
                b"points" => {
                    self.colon()?.grid(&mut grids.points)?;
                    std::mem::replace(&mut f.points, true)
                }
                b"weights" => {
                    self.colon()?.grid(&mut grids.weights)?;
                    std::mem::replace(&mut f.weights, true)
                }
                _ => return None,
            };
            if repeated {
                return None;
            }
            if !self.take(b',') {
                break;
            }
        }
        self.expect(b'}')?;
        Some(f)
    }

    fn colon(&mut self) -> Option<&mut Self> {
        self.expect(b':')?;
        Some(self)
    }

    /// `n` or `[m, n]`, counts written as JSON integers without sign.
    fn degree(&mut self) -> Option<Degree> {
        if !self.take(b'[') {
            return self.count().map(Degree::One);
        }
        let m = self.count()?;
        self.expect(b',')?;
        let n = self.count()?;
        self.expect(b']')?;
        Some(Degree::Two(m, n))
    }

    /// A JSON integer `0|[1-9]d*` of at most 6 digits.
    fn count(&mut self) -> Option<usize> {
        self.skip_space();
        let start = self.at;
        let digits = self.digits();
        let text = &self.bytes[start..self.at];
        let canonical = (1..=6).contains(&digits) && (digits == 1 || text[0] != b'0');
        canonical.then(|| text.iter().fold(0, |n, d| 10 * n + usize::from(d - b'0')))
    }

    /// Skip ASCII digits; how many.
    fn digits(&mut self) -> usize {
        let start = self.at;
        while self.peek().is_some_and(|b| b.is_ascii_digit()) {
            self.at += 1;
        }
        self.at - start
    }

    /// Nested non-empty arrays of numbers, every array at one depth of the
    /// same length, at most 3 deep, read into `g` (emptied first).
    fn grid(&mut self, g: &mut Grid) -> Option<()> {
        g.numbers.clear();
        g.lens.clear();
        self.array(g, 0).map(|_| ())
    }

    /// One array at nesting `level` (0 outermost) into `g`; the depth of
    /// the arrays below and including it.
    fn array(&mut self, g: &mut Grid, level: usize) -> Option<usize> {
        self.expect(b'[')?;
        self.skip_space();
        let nested = self.peek() == Some(b'[');
        if nested && level == 2 {
            return None;
        }
        let (mut len, mut below) = (0, 0);
        loop {
            if nested {
                let d = self.array(g, level + 1)?;
                if len > 0 && d != below {
                    return None;
                }
                below = d;
            } else {
                let x = self.number()?;
                g.numbers.push(x);
            }
            len += 1;
            if !self.take(b',') {
                break;
            }
        }
        self.expect(b']')?;
        if below >= g.lens.len() {
            g.lens.push(None);
        }
        match g.lens[below] {
            Some(l) if l != len => None,
            _ => {
                g.lens[below] = Some(len);
                Some(below + 1)
            }
        }
    }

    /// A number: a JSON number without exponent, or a string
    /// `-?d+(.d+)?(/d+)?`; as `(p, q)` with `q > 0`.
    fn number(&mut self) -> Option<(i128, i128)> {
        self.skip_space();
        let quoted = self.peek() == Some(b'"');
        if quoted {
            self.at += 1;
        }
        let ((p, q), mut digits) = self.decimal(quoted)?;
        let (p, q) = if quoted && self.peek() == Some(b'/') {
            self.at += 1;
            let ((d, e), more) = self.decimal(true)?;
            if d <= 0 {
                return None;
            }
            digits += more;
            (p.checked_mul(e)?, q.checked_mul(d)?)
        } else {
            (p, q)
        };
        if digits as u64 > self.max_digits {
            return None;
        }
        if quoted {
            self.expect_now(b'"')?;
        }
        Some((p, q))
    }

    /// Take `b` with no whitespace before it.
    fn expect_now(&mut self, b: u8) -> Option<()> {
        (self.peek() == Some(b)).then(|| self.at += 1)
    }

    /// `-?d+(.d+)?` as `(mantissa, 10^fraction digits)` and its count of
    /// digits, in one pass over its bytes; a JSON number (`loose = false`)
    /// has no leading zero. `None` when the mantissa leaves `i128`.
    /// Inlined: its result, returned through the stack, stalled the load
    /// of its tag (as the machine fractions' products did).
    #[inline(always)]
    fn decimal(&mut self, loose: bool) -> Option<((i128, i128), usize)> {
        let negative = self.peek() == Some(b'-');
        if negative {
            self.at += 1;
        }
        let start = self.at;
        let mut mantissa = Mantissa::default();
        let whole = self.digits_into(&mut mantissa)?;
        if whole == 0 || (!loose && whole > 1 && self.bytes[start] == b'0') {
            return None;
        }
        let mut frac = 0;
        if self.peek() == Some(b'.') {
            self.at += 1;
            frac = self.digits_into(&mut mantissa)?;
            if frac == 0 {
                return None;
            }
        }
        let scale = 10i128.checked_pow(u32::try_from(frac).ok()?)?;
        let value = mantissa.value();
        Some(((if negative { -value } else { value }, scale), whole + frac))
    }

    /// Take ASCII digits into `m`; how many (`None` when `m` leaves `i128`).
    /// Eight bytes at a time ([`leading_digits`]) while the word of `m`
    /// has room for eight more digits, then one at a time.
    #[inline(always)]
    fn digits_into(&mut self, m: &mut Mantissa) -> Option<usize> {
        let start = self.at;
        while m.len <= Mantissa::WORD_DIGITS - 8 {
            let Some(Ok(eight)) = self
                .bytes
                .get(self.at..self.at + 8)
                .map(<[u8; 8]>::try_from)
            else {
                break;
            };
            let (value, count) = leading_digits(u64::from_le_bytes(eight));
            m.push_run(value, count);
            self.at += count;
            if count < 8 {
                return Some(self.at - start);
            }
        }
        while let Some(&b) = self.bytes.get(self.at) {
            if !b.is_ascii_digit() {
                break;
            }
            m.push(b - b'0')?;
            self.at += 1;
        }
        Some(self.at - start)
    }
}

/// The leading ASCII digits of eight bytes read as a little-endian word
/// `w` (the first byte lowest): their value and count, without a branch
/// per byte (SWAR). A byte `b` is a digit when neither `b − '0'` nor
/// `b + 0x46` sets its high bit; a borrow or carry only moves to the bytes
/// after a non-digit, which are not read. The digits, moved to the top
/// bytes (the zeros below them are leading zeros), are combined in pairs,
/// fours and eights by three multiplications.
#[inline(always)]
fn leading_digits(w: u64) -> (u64, usize) {
    const LOW: u64 = 0x0101_0101_0101_0101;
    let d = w.wrapping_sub(0x30 * LOW);
    let not_digit = (d | w.wrapping_add(0x46 * LOW)) & (0x80 * LOW);
    let count = (not_digit.trailing_zeros() / 8) as usize;
    if count == 0 {
        return (0, 0);
    }
    let d = d << (8 * (8 - count));
    let pairs = (d * 10 + (d >> 8)) & 0x00FF_00FF_00FF_00FF;
    let fours = (pairs * 100 + (pairs >> 16)) & 0x0000_FFFF_0000_FFFF;
    ((fours * 10_000 + (fours >> 32)) & 0xFFFF_FFFF, count)
}

/// The digits of a decimal's mantissa as read: the first 18 on a 64-bit
/// word (below 10¹⁸ < 2⁶³), the rest, if any, on 128 bits with overflow
/// checks.
#[derive(Default)]
struct Mantissa {
    word: u64,
    len: usize,
    wide: i128,
}

impl Mantissa {
    /// The digits kept on the 64-bit word.
    const WORD_DIGITS: usize = 18;

    /// Append the `count ≤ 8` digits of value `v` to a mantissa of at most
    /// [`WORD_DIGITS`](Mantissa::WORD_DIGITS)` − 8` digits (on the word).
    #[inline(always)]
    fn push_run(&mut self, v: u64, count: usize) {
        const TENS: [u64; 9] = [
            1,
            10,
            100,
            1_000,
            10_000,
            100_000,
            1_000_000,
            10_000_000,
            100_000_000,
        ];
        self.word = self.word * TENS[count] + v;
        self.len += count;
    }

    /// Append the digit `d`; `None` when the value leaves `i128`.
    #[inline(always)]
    fn push(&mut self, d: u8) -> Option<()> {
        if self.len < Self::WORD_DIGITS {
            self.word = 10 * self.word + u64::from(d);
        } else {
            if self.len == Self::WORD_DIGITS {
                self.wide = i128::from(self.word);
            }
            self.wide = self.wide.checked_mul(10)?.checked_add(i128::from(d))?;
        }
        self.len += 1;
        Some(())
    }

    #[inline(always)]
    fn value(&self) -> i128 {
        if self.len <= Self::WORD_DIGITS {
            i128::from(self.word)
        } else {
            self.wide
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coincide::canonical::canonical_text;
    use crate::io::{parse_json, patch_from_value};
    use crate::limits::{with_limits, Limits};
    use proptest::prelude::*;

    /// The general reader's patch of `line`.
    fn general(line: &str) -> Result<crate::Patch<num_rational::BigRational>, crate::Error> {
        parse_json(line).and_then(|v| patch_from_value(&v))
    }

    /// Whatever the fast reader accepts, the general reader reads as the
    /// same patch, and the fast key text is the general one.
    fn agrees(line: &str) -> bool {
        let Some(mut fast) = read_small_patch(line) else {
            return false;
        };
        let want = general(line).unwrap_or_else(|e| panic!("{line}: fast accepts, general: {e}"));
        assert_eq!(fast.to_patch().unwrap(), want, "{line}");
        fast.certify();
        assert_eq!(
            fast.key_text().unwrap(),
            canonical_text(&want).unwrap(),
            "{line}"
        );
        true
    }

    /// A number written in form `form` from `a`, `b` (`b ≥ 1`); whether
    /// the fast reader should take it.
    fn number(form: u8, a: i64, b: i64) -> (String, bool) {
        match form % 8 {
            0 => (a.to_string(), true),
            1 => (format!("\"{a}/{b}\""), true),
            2 => (format!("{a}.{:03}", b % 1000), true),
            3 => (format!("\"{a}.{b}\""), true),
            4 => (format!("\"{a}.5/{b}.25\""), true),
            5 => (format!("\"{}\"", b), true),
            6 => (format!("{a}e2"), false),
            // A non-zero lead and 40 more digits: at least 10^40 > i128::MAX.
            _ => (format!("\"{}{:040}\"", a.abs() % 9 + 1, b), false),
        }
    }

    /// A curve or rect record with numbers in the given forms, fields in
    /// a rotated order, with or without degree and weights.
    fn record(
        rect: bool,
        (m, n, dim): (usize, usize, usize),
        forms: &[(u8, i64, i64)],
        rotate: usize,
        with_degree: bool,
        with_weights: bool,
    ) -> (String, bool) {
        let mut it = forms.iter().cycle();
        // Whether the points, and the weights, are all of plain forms.
        let mut plain = [true, true];
        let mut num = |weight: bool| {
            let &(f, a, b) = it.next().unwrap();
            let a = if weight { a.abs() + 1 } else { a };
            let (text, ok) = number(f, a, b);
            plain[usize::from(weight)] &= ok;
            text
        };
        let point = |num: &mut dyn FnMut(bool) -> String| {
            format!(
                "[{}]",
                (0..dim).map(|_| num(false)).collect::<Vec<_>>().join(", ")
            )
        };
        let list = |items: Vec<String>| format!("[{}]", items.join(","));
        let (points, weights, degree) = if rect {
            let pts = (0..=m)
                .map(|_| list((0..=n).map(|_| point(&mut num)).collect()))
                .collect();
            let ws = (0..=m)
                .map(|_| list((0..=n).map(|_| num(true)).collect()))
                .collect();
            (list(pts), list(ws), format!("[{m}, {n}]"))
        } else {
            let pts = (0..=m).map(|_| point(&mut num)).collect();
            let ws = (0..=m).map(|_| num(true)).collect();
            (list(pts), list(ws), m.to_string())
        };
        let plain = plain[0] && (plain[1] || !with_weights);
        let kind = if rect { "rect" } else { "curve" };
        let mut fields = vec![
            format!("\"kind\": \"{kind}\""),
            format!("\"points\":{points}"),
        ];
        if with_degree {
            fields.push(format!("\"degree\" : {degree}"));
        }
        if with_weights {
            fields.push(format!("\"weights\": {weights}"));
        }
        let k = rotate % fields.len();
        fields.rotate_left(k);
        (format!(" {{{}}}\n", fields.join(", ")), plain)
    }

    fn records() -> impl Strategy<Value = (String, bool)> {
        (
            any::<bool>(),
            (0usize..4, 0usize..4, 1usize..4),
            prop::collection::vec((0u8..8, -60i64..60, 1i64..40), 1..12),
            0usize..4,
            any::<bool>(),
            any::<bool>(),
        )
            .prop_map(|(rect, shape, forms, rotate, d, w)| {
                let shape = if rect { shape } else { (shape.0, 0, shape.2) };
                record(rect, shape, &forms, rotate, d, w)
            })
    }

    proptest! {
        #[test]
        fn plain_records_are_read_as_the_general_reader_reads_them((line, plain) in records()) {
            prop_assert_eq!(agrees(&line), plain, "{}", line);
        }

        #[test]
        fn a_damaged_record_is_refused_or_read_as_the_general_reader_reads_it(
            (line, _) in records(),
            at in any::<prop::sample::Index>(),
            edit in 0usize..20,
        ) {
            const BYTES: &[u8] = b"[]{},:\"-./0159e x\\";
            let mut bytes = line.into_bytes();
            let k = at.index(bytes.len());
            match BYTES.get(edit) {
                Some(&b) => bytes[k] = b,
                None => {
                    bytes.remove(k);
                }
            }
            if let Ok(line) = String::from_utf8(bytes) {
                agrees(&line);
            }
        }
    }

    proptest! {
        #[test]
        fn eight_bytes_at_once_read_the_digits_one_at_a_time_reads(
            bytes in prop::array::uniform8(prop_oneof![b'0'..=b'9', any::<u8>()]),
        ) {
            let count = bytes.iter().take_while(|b| b.is_ascii_digit()).count();
            let value = bytes[..count].iter().fold(0, |v, &b| 10 * v + u64::from(b - b'0'));
            prop_assert_eq!(leading_digits(u64::from_le_bytes(bytes)), (value, count));
        }

        #[test]
        fn long_decimals_are_read_exactly_or_refused(
            whole in "[1-9][0-9]{0,44}",
            frac in "[0-9]{1,20}",
            tail in "[,\\]\"/ x]{0,9}",
        ) {
            for text in [whole.clone(), format!("{whole}.{frac}")] {
                let line = format!("{text}{tail}");
                let mut c = Cursor { bytes: line.as_bytes(), at: 0, max_digits: u64::MAX };
                let digits = text.replace('.', "");
                let frac_digits = text.len() - whole.len() - usize::from(text.contains('.'));
                let want = digits.parse::<i128>().ok().and_then(|p| {
                    Some(((p, 10i128.checked_pow(frac_digits as u32)?), digits.len()))
                });
                prop_assert_eq!(c.decimal(false), want);
                if want.is_some() {
                    prop_assert_eq!(c.at, text.len());
                }
            }
        }
    }

    #[test]
    fn the_corpus_patches_are_keyed_as_by_the_general_path() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures");
        let mut fast = 0;
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_none_or(|e| e != "json") {
                continue;
            }
            let v: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
            let items = match v {
                serde_json::Value::Array(items) => items,
                v => vec![v],
            };
            for item in items {
                let line = item.to_string();
                if general(&line).is_ok() && agrees(&line) {
                    fast += 1;
                }
            }
        }
        // The teapot's 32 patches alone are of the plain shape.
        assert!(fast >= 32, "{fast}");
    }

    #[test]
    fn unusual_records_go_to_the_general_reader() {
        let ok = r#"{"kind": "curve", "points": [[0], [1]]}"#;
        assert!(agrees(ok));
        for line in [
            r#"{"kind": "curve", "points": [[0], [1]], "origin": {}}"#,
            r#"{"kind": "curve", "points": [[0], [1]], "kind": "curve"}"#,
            r#"{"kind": "cur\u0076e", "points": [[0], [1]]}"#,
            r#"{"kind": "tri", "points": [[[0], [1]], [[2]]]}"#,
            r#"{"kind": "curve", "points": [[0], [1e0]]}"#,
            r#"{"kind": "curve", "points": [[0], ["+1"]]}"#,
            r#"{"kind": "curve", "points": [[0], [" 1"]]}"#,
            r#"{"kind": "curve", "points": [[0], ["1/-3"]]}"#,
            r#"{"kind": "curve", "points": [[0], [01]]}"#,
            r#"{"kind": "curve", "points": [[0], [1]], "weights": [1, 0]}"#,
            r#"{"kind": "curve", "points": [[0], [1]], "degree": 1.0}"#,
            r#"{"kind": "curve", "points": [[0], [1, 2]]}"#,
            r#"{"kind": "curve", "points": [[0], [1]]} x"#,
            r#"{"kind": "curve", "points": [[0], [170141183460469231731687303715884105728]]}"#,
        ] {
            assert!(read_small_patch(line).is_none(), "{line}");
        }
        let few_digits = Limits {
            max_digits: 3,
            ..Limits::default()
        };
        let long = r#"{"kind": "curve", "points": [[0], ["1/1000"]]}"#;
        assert!(read_small_patch(long).is_some());
        assert!(with_limits(few_digits, || read_small_patch(long)).is_none());
    }
}
