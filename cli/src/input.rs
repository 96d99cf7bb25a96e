//! Reading the commands' inputs: files or standard input within the input
//! limit, patches over the exact scalar their numbers need, and the
//! comma-separated parameter lists of the flags.

use crate::session::stdin_reader;
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::algebra::Scalar;
use exact_bezier::coincide::{CoincideScalar, Reducible};
use exact_bezier::io::{read_patches, read_patches_as, JsonScalar};
use exact_bezier::limits::{self, Cost};
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use num_rational::BigRational;
use std::io::Read;
/// Read all of `r`, refusing more than the input limit.
fn read_limited(r: impl Read, what: &str) -> Result<String, Error> {
    let max = limits::current().max_input_bytes;
    let mut bytes = Vec::new();
    r.take(max.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| Error::Io(format!("cannot read {what}: {e}")))?;
    limits::check_input_bytes(bytes.len() as u64)?;
    let significant = bytes.iter().filter(|b| !b.is_ascii_whitespace()).count();
    limits::charge_input(significant as u64, limits::JSON_BYTE_WORK)?;
    String::from_utf8(bytes).map_err(|_| Error::Format(format!("{what} is not UTF-8 text")))
}

/// Read the text of `path` (`-` for standard input), within
/// [`Limits::max_input_bytes`].
pub(crate) fn read_input(path: &str) -> Result<String, Error> {
    if path == "-" {
        read_limited(stdin_reader(), "standard input")
    } else {
        let what = format!("{path:?}");
        let file =
            std::fs::File::open(path).map_err(|e| Error::Io(format!("cannot read {what}: {e}")))?;
        read_limited(file, &what)
    }
}

/// A buffered reader of `path` (`-` for this run's standard input), for
/// inputs read as a stream (STEP files, the models of `audit` and
/// `convert --to bezier`); every byte read is charged
/// [`limits::STREAM_BYTE_WORK`] ([`Charged`]).
pub(crate) fn open_input(path: &str) -> Result<Box<dyn std::io::BufRead>, Error> {
    let inner: Box<dyn Read> = if path == "-" {
        stdin_reader()
    } else {
        Box::new(
            std::fs::File::open(path)
                .map_err(|e| Error::Io(format!("cannot read {path:?}: {e}")))?,
        )
    };
    Ok(Box::new(std::io::BufReader::with_capacity(
        1 << 16,
        Charged(inner),
    )))
}

/// A reader that charges the work of what is read from it as it comes:
/// [`limits::STREAM_BYTE_WORK`] a byte. Over the budget, the read fails
/// with the limit's message (an `io::Error` of kind `Other` carrying it).
struct Charged<R>(R);

impl<R: Read> Read for Charged<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.0.read(buf)?;
        limits::charge_input(n as u64, limits::STREAM_BYTE_WORK)
            .map_err(|e| std::io::Error::other(e.to_string()))?;
        Ok(n)
    }
}

/// Read the patches of `path`. An empty array is an empty model
/// (docs/limits.md, policies): commands that work patch by patch answer
/// with an empty list.
pub(crate) fn load(path: &str) -> Result<Vec<Patch<BigRational>>, Error> {
    read_patches(&read_input(path)?)
}

/// The single curve or patch of `path`; `count_error(n)` words the error
/// when it holds `n ≠ 1`.
pub(crate) fn load_one(
    path: &str,
    count_error: impl Fn(usize) -> String,
) -> Result<Patch<BigRational>, Error> {
    let mut patches = load(path)?;
    if patches.len() != 1 {
        return Err(Error::Shape(count_error(patches.len())));
    }
    Ok(patches.swap_remove(0))
}

/// An exact scalar a command runs on: written as JSON, decided by
/// `coincide`, measured by the cost model ([`Cost`], implemented in
/// `exact_bezier::algebra`), and lifted to the real algebraic numbers.
pub(crate) trait ExactScalar: JsonScalar + Reducible + CoincideScalar + Cost {
    /// The same number as a real algebraic number.
    fn to_algebraic(&self) -> RealAlgebraic;
}

impl ExactScalar for BigRational {
    fn to_algebraic(&self) -> RealAlgebraic {
        RealAlgebraic::from_rational(self)
    }
}

impl ExactScalar for RealAlgebraic {
    fn to_algebraic(&self) -> RealAlgebraic {
        self.clone()
    }
}

/// Exact patches as read: over Q when every number of the file is
/// rational, else over the real algebraic numbers (`"sqrt(6)/6"`, the
/// grammar of docs/algebraic_numbers.md, as `standardize` writes them).
pub(crate) enum ExactPatches {
    /// Every number rational (also every NURBS input).
    Rational(Vec<Patch<BigRational>>),
    /// Some number algebraic and irrational.
    Algebraic(Vec<Patch<RealAlgebraic>>),
}

/// Run `$body` with `$p` bound to the patches of an [`ExactPatches`],
/// whichever scalar they have: one generic body, two instantiations.
macro_rules! on_exact {
    ($patches:expr, $p:ident => $body:expr) => {
        match $patches {
            $crate::ExactPatches::Rational($p) => $body,
            $crate::ExactPatches::Algebraic($p) => $body,
        }
    };
}
pub(crate) use on_exact;

impl ExactPatches {
    /// The patches of `text`: rational if they all are, else algebraic; a
    /// text neither reader accepts gets the rational reader's error, unless
    /// the algebraic reader stopped at a limit (that error, naming it).
    pub(crate) fn parse(text: &str) -> Result<Self, Error> {
        match read_patches(text) {
            Ok(p) => Ok(ExactPatches::Rational(p)),
            Err(rational) => match read_patches_as::<RealAlgebraic>(text) {
                Ok(p) => {
                    check_field_degree(&p)?;
                    Ok(ExactPatches::Algebraic(p))
                }
                // A limit the algebraic reader met is the reason to give.
                Err(e @ Error::Limit(_)) => Err(e),
                Err(_) => Err(rational),
            },
        }
    }

    /// The patches over the real algebraic numbers (rationals lifted).
    pub(crate) fn into_algebraic(self) -> Vec<Patch<RealAlgebraic>> {
        match self {
            ExactPatches::Rational(p) => p
                .iter()
                .map(|p| p.map(RealAlgebraic::from_rational))
                .collect(),
            ExactPatches::Algebraic(p) => p,
        }
    }

    /// How many patches.
    pub(crate) fn len(&self) -> usize {
        on_exact!(self, p => p.len())
    }
}

/// Refuse patches whose numbers span a number field over the limit
/// ([`limits::check_field_degree`]) before any work on them.
fn check_field_degree(patches: &[Patch<RealAlgebraic>]) -> Result<(), Error> {
    let numbers = std::cell::RefCell::new(Vec::new());
    for p in patches {
        p.map(|x| {
            numbers.borrow_mut().push(x.clone());
            0.0
        });
    }
    check_numbers(&numbers.into_inner(), "reading the input")
}

/// Refuse numbers that span a number field over the limit
/// ([`RealAlgebraic::span_degree`]; radicals alone need no field), and
/// charge the work of having read them: a number that is an isolated root
/// or a field element of degree `D` was built as one (a Sturm sequence and
/// its isolation, or a primitive element: about `D` operations in degree
/// `D`, `exact_work(D, bits) · field_op_cost(D, true)`). The text limits bound
/// that work before it is done; the charge keeps the counted work whole.
pub(crate) fn check_numbers(numbers: &[RealAlgebraic], what: &str) -> Result<(), Error> {
    let (degree, radical) = RealAlgebraic::span_degree(numbers);
    if radical {
        return Ok(());
    }
    limits::check_field_degree(degree, false, what)?;
    let read = numbers.iter().fold(0u64, |acc, x| {
        let (d, field) = RealAlgebraic::field_degree([x]);
        let units = if field {
            limits::exact_work(d, x.bits()).saturating_mul(limits::field_op_cost(d, true))
        } else {
            0
        };
        acc.saturating_add(units)
    });
    limits::charge(what, read)
}

/// The patches of every file of `paths`, in order: rational if they all
/// are, else all lifted to the real algebraic numbers.
pub(crate) fn load_all_exact(paths: &[String]) -> Result<ExactPatches, Error> {
    let files = paths
        .iter()
        .map(|p| load_exact(p))
        .collect::<Result<Vec<_>, _>>()?;
    if files.iter().all(|f| matches!(f, ExactPatches::Rational(_))) {
        let all = files.into_iter().flat_map(|f| match f {
            ExactPatches::Rational(p) => p,
            ExactPatches::Algebraic(_) => Vec::new(),
        });
        return Ok(ExactPatches::Rational(all.collect()));
    }
    let all = files.into_iter().flat_map(ExactPatches::into_algebraic);
    Ok(ExactPatches::Algebraic(all.collect()))
}

/// Read the exact patches of `path` (see [`ExactPatches::parse`]); an empty
/// array is an empty model, as for [`load`].
pub(crate) fn load_exact(path: &str) -> Result<ExactPatches, Error> {
    ExactPatches::parse(&read_input(path)?)
}

/// Check the `--tol` of an f64 comparison: finite and ≥ 0.
///
/// # Errors
///
/// [`Error::NotFinite`] naming the value otherwise.
pub(crate) fn check_tol(tol: f64) -> Result<(), Error> {
    if !(tol.is_finite() && tol >= 0.0) {
        return Err(Error::NotFinite(format!(
            "--tol {tol} must be finite and ≥ 0"
        )));
    }
    Ok(())
}

/// Parse a comma-separated list of exact real algebraic numbers
/// (`1/3,sqrt(2)/2,CRootOf(x**3 - x - 1, 0)`): commas inside parentheses
/// belong to the number.
pub(crate) fn parse_algebraic_list(text: &str) -> Result<Vec<RealAlgebraic>, Error> {
    use exact_bezier::algebra::ExactNumber;
    let mut items = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (k, ch) in text.char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                items.push(&text[start..k]);
                start = k + 1;
            }
            _ => {}
        }
    }
    items.push(&text[start..]);
    let numbers = items
        .into_iter()
        .map(|t| RealAlgebraic::from_text(t.trim()))
        .collect::<Result<Vec<_>, _>>()?;
    check_numbers(&numbers, &format!("reading {text:?}"))?;
    Ok(numbers)
}

/// Parse a comma-separated list of exact numbers (`1/3,0.25`).
pub(crate) fn parse_list(text: &str) -> Result<Vec<BigRational>, Error> {
    text.split(',')
        .map(exact_bezier::algebra::parse_rational)
        .collect()
}
