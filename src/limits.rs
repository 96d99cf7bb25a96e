//! Resource limits: every input's cost is bounded **before** the work starts
//! (`docs/limits.md`). No watchdog, no timeout: a request whose estimated
//! cost is over a limit is refused with an [`Error::Limit`] that names the
//! limit and, where it can be raised, the flag that raises it.
//!
//! Three kinds of limit:
//!
//! - **Input size**: bytes of one input ([`Limits::max_input_bytes`]),
//!   decimal digits per number ([`Limits::max_digits`], exponents count as
//!   digits: `1e400` has 401), dimension ([`MAX_DIMENSION`]), degree
//!   ([`MAX_DEGREE`], also for every patch a command writes), and the
//!   parsers' caps ([`MAX_STEP_STATEMENT`], [`MAX_STEP_DEPTH`],
//!   [`MAX_ALGEBRAIC_TEXT`], [`MAX_ALGEBRAIC_DEPTH`],
//!   [`MAX_ALGEBRAIC_EXPONENT`]).
//! - **Exact work**: a cost model, [`exact_work`]: `ops × (2 + S/64)²`
//!   units for `ops` rational operations on numbers of `S` bits (a
//!   rational `+`/`×` reduces by a gcd, quadratic in the size). Each command
//!   estimates `ops` and `S` from the degree, the dimension and the bit size
//!   of its numbers and parameters, and [`charge`]s it against
//!   [`Limits::max_work`] before computing, besides a fixed
//!   [`COMMAND_WORK`] and its input's bytes ([`charge_input`]). The
//!   commands' constant factors are calibrated by
//!   `cli/benches/cost_model.rs` so that a unit is about the same time for
//!   every command (about 8 ns in a release build on the reference
//!   machine).
//! - **f64 work and output size**: sample and vertex counts of `plot` and
//!   `mesh` ([`MAX_PLOT_POINTS`], [`MAX_PIXELS`], [`MAX_MESH_VERTICES`],
//!   [`MAX_DENSITY`], [`MAX_DOCUMENT_POINTS`]), charged by the same counter
//!   ([`f64_work`]).
//!
//! The limits are per thread ([`with_limits`]): the command line sets them
//! from `--max-digits`, `--max-input-bytes` and `--max-work`; work spread
//! over threads runs [`detached`] under a share of what is left, and is
//! [`absorb`]ed back. No limit turns
//! an exact answer into an approximate one: an exact request over a limit is
//! refused, never rounded.

use crate::error::Error;
use num_rational::BigRational;
use std::cell::Cell;

/// The largest degree (per parameter) accepted from input and written: 64.
pub const MAX_DEGREE: usize = 64;

/// The largest dimension (coordinates per point) accepted from input.
pub const MAX_DIMENSION: usize = 64;

/// The largest mesh density accepted: 1024 steps per parameter.
pub const MAX_DENSITY: usize = 1024;

/// The most points one `eval` document (without `--jsonl`) may hold.
pub const MAX_DOCUMENT_POINTS: u64 = 1_000_000;

/// The longest STEP statement accepted (bytes): a bound on hostile input.
pub const MAX_STEP_STATEMENT: usize = 64 << 20;

/// The deepest nesting of STEP parameter lists accepted.
pub const MAX_STEP_DEPTH: usize = 64;

/// The longest text of one algebraic number accepted, per decimal digit of
/// [`Limits::max_digits`] (bytes): [`max_algebraic_text`].
pub const ALGEBRAIC_TEXT_PER_DIGIT: u64 = 64;

/// The least bound of [`max_algebraic_text`] (bytes), whatever the digits.
pub const MAX_ALGEBRAIC_TEXT: usize = 10_000;

/// The deepest nesting of an algebraic number's text: brackets, function
/// calls and power exponents each count one level.
pub const MAX_ALGEBRAIC_DEPTH: usize = 64;

/// The largest `|exponent|` of a power in an algebraic number's text.
pub const MAX_ALGEBRAIC_EXPONENT: i64 = 64;

/// The largest degree over Q of a number field that exact algebraic
/// arithmetic builds (`src/algebra/real_algebraic/field.rs`): combining two
/// fields of degrees `d₁`, `d₂` needs `d₁·d₂`, an `n`-th root `n·d`, known
/// before the work. An input whose numbers span a larger field (a `CRootOf`
/// or a root of a sum among them) is refused as it is read
/// ([`check_field_degree`]), and so is a command whose numbers and
/// parameters together would span one ([`charge_sizes`]) or whose roots
/// would extend the field past it ([`charge_extension`]); the library's
/// arithmetic, called directly, falls back to resultants there. 32: a tower of square roots `√(1 + √(1 + …))` of
/// degree 16 is read in 0.6 s, of degree 32 in about a minute (debug
/// builds), of degree 64 in minutes.
pub const MAX_FIELD_DEGREE: usize = 32;

/// The largest root index of a radical (`b^{1/n}`, nested roots multiply
/// their indices: `sqrt` nested 30 times is `b^{1/2³⁰}`) accepted from input:
/// 2³⁰. Radicals of any index cost a few integer roots of word-sized index
/// each; the bound keeps exponents in machine words.
pub const MAX_RADICAL_INDEX: u64 = 1 << 30;

/// The most sample points one `plot` may draw (all curves and iso-lines).
pub const MAX_PLOT_POINTS: u64 = 1 << 20;

/// The most pixels of a `plot` picture (4096 × 4096).
pub const MAX_PIXELS: u64 = 1 << 24;

/// The most vertices one `mesh` may write.
pub const MAX_MESH_VERTICES: u64 = 1 << 22;

/// The limits in force on this thread.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Decimal digits per input number, counting both sides of `p/q` and the
    /// magnitude of an exponent (`--max-digits`).
    pub max_digits: u64,
    /// Bytes of one input file or of standard input (`--max-input-bytes`).
    pub max_input_bytes: u64,
    /// Estimated work units per command, see [`exact_work`] (`--max-work`).
    pub max_work: u64,
}

impl Limits {
    /// The defaults: 1 000 digits, 64 MiB, 10¹⁰ work units — about a
    /// minute in a release build on the reference machine (a unit is about
    /// 8 ns of CPU time there; `docs/limits.md` has the calibration).
    pub const DEFAULT: Limits = Limits {
        max_digits: 1_000,
        max_input_bytes: 64 << 20,
        max_work: 10_000_000_000,
    };
}

impl Default for Limits {
    fn default() -> Self {
        Limits::DEFAULT
    }
}

thread_local! {
    static CURRENT: Cell<Limits> = const { Cell::new(Limits::DEFAULT) };
    static CHARGED: Cell<u64> = const { Cell::new(0) };
    static METERED: Cell<u64> = const { Cell::new(0) };
}

/// The limits in force on this thread.
pub fn current() -> Limits {
    CURRENT.with(Cell::get)
}

/// Run `f` under `limits` with a fresh work counter and a fresh
/// actual-work meter ([`metered`]); the previous limits, counter and meter
/// are restored afterwards.
pub fn with_limits<R>(limits: Limits, f: impl FnOnce() -> R) -> R {
    let old = CURRENT.with(|c| c.replace(limits));
    let old_charged = CHARGED.with(|c| c.replace(0));
    let old_metered = METERED.with(|c| c.replace(0));
    let r = f();
    CURRENT.with(|c| c.set(old));
    CHARGED.with(|c| c.set(old_charged));
    METERED.with(|c| c.set(old_metered));
    r
}

/// Work done on another thread for this one: the result of [`detached`],
/// the work it was charged and the work it metered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Detached<R> {
    /// What the work returned.
    pub result: R,
    /// The work [`charge`]d while it ran.
    pub charged: u64,
    /// The work [`meter`]ed while it ran.
    pub metered: u64,
}

/// Run `f` under `limits` with fresh counters, on any thread (a parallel
/// worker's limits are not the spawning thread's): its result and the work
/// it was charged and metered, for the spawning thread to [`absorb`].
pub fn detached<R>(limits: Limits, f: impl FnOnce() -> R) -> Detached<R> {
    with_limits(limits, || {
        let result = f();
        Detached {
            result,
            charged: charged(),
            metered: metered(),
        }
    })
}

/// Add the work of a [`detached`] run to this thread's counters. The caller
/// gave each run a share of what was left of [`Limits::max_work`], so that
/// their sum stays within it; the total saturates rather than fails.
pub fn absorb<R>(run: &Detached<R>) {
    CHARGED.with(|c| c.set(c.get().saturating_add(run.charged)));
    METERED.with(|c| c.set(c.get().saturating_add(run.metered)));
}

/// Record `ops` coefficient operations actually done on rationals of up to
/// `bits` bits, in the units of [`exact_work`]: the **actual-work meter**.
/// It never fails and limits nothing; the exact algebraic arithmetic
/// (`algebra::real_algebraic`: number-field operations, radical sums,
/// Sturm sequences, resultants) feeds it, so that tests can compare the
/// work a command really did with the work it was [`charge`]d
/// (`cli/tests/it/algebraic_budget.rs`).
pub fn meter(ops: u64, bits: u64) {
    let units = exact_work(ops, bits);
    METERED.with(|c| c.set(c.get().saturating_add(units)));
}

/// The work recorded by [`meter`] on this thread since [`with_limits`]
/// began.
pub fn metered() -> u64 {
    METERED.with(Cell::get)
}

/// The work charged on this thread since [`with_limits`] began.
pub fn charged() -> u64 {
    CHARGED.with(Cell::get)
}

/// Add `units` of estimated work for `what`.
///
/// # Errors
///
/// [`Error::Limit`] when the total would pass [`Limits::max_work`]; nothing
/// is charged then.
pub fn charge(what: &str, units: u64) -> Result<(), Error> {
    let total = charged().saturating_add(units);
    let max = current().max_work;
    if total > max {
        return Err(Error::Limit(format!(
            "{what} needs an estimated {} work units, over the budget of {} (raise it with --max-work)",
            sci(total),
            sci(max)
        )));
    }
    CHARGED.with(|c| c.set(total));
    Ok(())
}

/// `x` as `d.dde±k` text for messages.
fn sci(x: u64) -> String {
    format!("{:.2e}", x as f64)
}

/// The fixed work of one command, whatever its input: parsing the
/// arguments, opening and writing (about 0.25 ms in a release build,
/// `cli/benches/cost_model.rs`).
pub const COMMAND_WORK: u64 = 25_000;

/// Work units per byte of a JSON input read whole, white space not counted
/// (the exact numbers parsed from their text: about 0.5 µs a byte in a
/// release build; the indentation of a pretty-printed file costs next to
/// nothing).
pub const JSON_BYTE_WORK: u64 = 64;

/// Work units per byte of an input read as a stream (STEP, the models of
/// `audit` and `convert --to bezier`: entities resolved and converted,
/// about 1–3 µs a byte).
pub const STREAM_BYTE_WORK: u64 = 200;

/// `f64` operations per work unit: a command run with `--scalar f64`, and
/// the sampling of `plot` and `mesh`, is charged its operation count over
/// this (an `f64` operation takes well under a nanosecond).
pub const F64_OPS_PER_UNIT: u64 = 128;

/// Work units of `ops` operations in `f64`: `⌈ops / 128⌉`
/// ([`F64_OPS_PER_UNIT`]).
pub fn f64_work(ops: u64) -> u64 {
    ops.div_ceil(F64_OPS_PER_UNIT)
}

/// Charge the reading of an input of `bytes` bytes at `per_byte` units a
/// byte ([`JSON_BYTE_WORK`], [`STREAM_BYTE_WORK`]).
///
/// # Errors
///
/// [`Error::Limit`] as [`charge`].
pub fn charge_input(bytes: u64, per_byte: u64) -> Result<(), Error> {
    charge("reading the input", bytes.saturating_mul(per_byte))
}

/// Work units of `ops` exact rational operations on numbers of `bits` bits:
/// `ops × (2 + bits/64)²` (saturating). The square is the cost of the gcd
/// that normalizes every rational result; the `2` the fixed cost of an
/// operation on small numbers (allocation, sign, length).
pub fn exact_work(ops: u64, bits: u64) -> u64 {
    let words = 2 + bits / 64;
    ops.saturating_mul(words.saturating_mul(words))
}

/// Charge `what`'s estimated work on patches of `sizes` before computing:
/// `cost` gives `(operations, bits)` per patch, and `exact` runs are
/// charged [`Size::exact_units`] (the operations times the cost of one
/// operation in the patch's number field, [`field_op_cost`]); an `f64` run
/// is charged [`f64_work`] of the operations. An exact run whose numbers
/// (with the command's parameters) would build a field over
/// [`MAX_FIELD_DEGREE`] is refused first: its arithmetic would leave the
/// bounded field path.
///
/// # Errors
///
/// [`Error::Limit`] as [`charge`] and [`check_field_degree`].
pub fn charge_sizes(
    what: &str,
    sizes: impl IntoIterator<Item = Size>,
    exact: bool,
    cost: impl Fn(&Size) -> (u64, u64),
) -> Result<(), Error> {
    for size in sizes {
        if exact && size.field {
            check_field_degree(size.field_degree, false, what)?;
        }
        let (ops, bits) = cost(&size);
        let units = if exact {
            size.exact_units(ops, bits)
        } else {
            f64_work(ops)
        };
        charge(what, units)?;
    }
    Ok(())
}

/// The cost of one operation on numbers that span a field of degree `D =
/// degree` over Q, in rational operations on numbers of the elements'
/// (input) size: `FIELD_OP_FACTOR · D⁴` in a number field (`field`), for
/// `D ≥ 2`. An element has `D` coefficients, a product takes `D²`
/// coefficient products and as many for its reduction modulo the field's
/// polynomial, and the coefficients in the field's basis grow with `D`
/// (their size, squared in the cost of a rational operation, gives the
/// other `D²`). Radical sums alone (`!field`) multiply term by term
/// without that growth: `FIELD_OP_FACTOR · D²`. 1 over Q (`D = 1`).
/// Saturating.
///
/// Fitted on the release build (docs/limits.md, "Algebraic work"):
/// `eval` of a cubic over `Q(θ)`, θ a root of `x^D − x − 1`, takes 0.03,
/// 0.76 and 27 s for D = 6, 12, 24 (the machine shared), 10–13 ns a unit
/// with `D⁴`, where `D²` left 0.1–1.8 µs a unit.
pub fn field_op_cost(degree: u64, field: bool) -> u64 {
    if degree <= 1 {
        return 1;
    }
    let square = degree.saturating_mul(degree);
    let growth = if field { square } else { 1 };
    FIELD_OP_FACTOR
        .saturating_mul(square)
        .saturating_mul(growth)
}

/// The constant of [`field_op_cost`] (see there for the fit).
pub const FIELD_OP_FACTOR: u64 = 4;

/// Field operations (each costing [`field_op_cost`]) of writing one number
/// of a field of degree `D = degree` as text: `WRITE_OPS_PER_DEGREE · D`
/// for `D ≥ 2` in a number field (`field`), 0 otherwise. Writing an
/// element needs its minimal polynomial (the characteristic polynomial of
/// the `D × D` matrix of multiplication by it, divided down to the
/// irreducible factor it annuls) and an interval isolating it among that
/// polynomial's roots; sums of radicals and rationals are written term by
/// term, at no cost beyond the operation count of the command.
///
/// Measured with the actual-work [`meter`] (`examples/write_cost.rs`):
/// about `25·D⁵` units a number for D = 4…10; `2·D` operations of
/// `4·D⁴` each on numbers of at most two words ([`exact_work`]: 4 units an
/// operation) charge `32·D⁵`.
pub fn write_ops(degree: u64, field: bool) -> u64 {
    if field && degree >= 2 {
        WRITE_OPS_PER_DEGREE.saturating_mul(degree)
    } else {
        0
    }
}

/// Charge `what`: writing `count` numbers of `bits` bits that lie in a
/// field of degree `degree` ([`write_ops`] operations each, at
/// [`field_op_cost`]); nothing for rationals and radical sums (`field`
/// false).
///
/// # Errors
///
/// [`Error::Limit`] as [`charge`].
pub fn charge_writes(
    what: &str,
    count: u64,
    degree: u64,
    field: bool,
    bits: u64,
) -> Result<(), Error> {
    let ops = count.saturating_mul(write_ops(degree, field));
    charge(
        what,
        exact_work(ops, bits).saturating_mul(field_op_cost(degree, true)),
    )
}

/// The constant of [`write_ops`].
pub const WRITE_OPS_PER_DEGREE: u64 = 2;

/// Charge, before the work, a computation that extends the field of its
/// numbers (degree `degree`, from [`Cost::field_degree`], numbers of up to
/// `bits` bits) by an `n`-th root, and refuse it when the extension
/// `D = n · degree` would be over [`MAX_FIELD_DEGREE`] (`what` names the
/// computation). Building the extension (a primitive element: `D + 1`
/// powers and a `D × D` elimination) and writing its numbers (a minimal
/// polynomial each, and the isolation of its root) cost about `D²`
/// operations in it: `exact_work(D², bits) · field_op_cost(D)`. Rational numbers (`degree` 1) extend nothing the
/// limit counts: the root of a rational is a radical, bounded by
/// [`MAX_RADICAL_INDEX`] instead.
///
/// # Errors
///
/// [`Error::Limit`] naming the degree and the field degree limit, or the
/// budget as [`charge`].
pub fn charge_extension(what: &str, degree: u64, n: u64, bits: u64) -> Result<(), Error> {
    if degree <= 1 {
        return Ok(());
    }
    let extended = degree.saturating_mul(n);
    check_field_degree(extended, false, what)?;
    charge(
        what,
        exact_work(extended.saturating_mul(extended), bits)
            .saturating_mul(field_op_cost(extended, true)),
    )
}

/// Check the text of one number before it is parsed: at most
/// [`Limits::max_digits`] digits, an exponent's magnitude counted as digits.
///
/// # Errors
///
/// [`Error::Limit`] naming the count and `--max-digits`.
pub fn check_number_text(text: &str) -> Result<(), Error> {
    let max = current().max_digits;
    let mut digits: u64 = 0;
    let mut exponent: u64 = 0;
    for part in text.split('/') {
        let (mantissa, exp) = match part.find(['e', 'E']) {
            Some(k) => (&part[..k], Some(&part[k + 1..])),
            None => (part, None),
        };
        digits += mantissa.bytes().filter(u8::is_ascii_digit).count() as u64;
        if let Some(e) = exp {
            let e = e
                .trim()
                .trim_start_matches(['+', '-'])
                .trim_start_matches('0');
            exponent = exponent.saturating_add(if e.len() > 18 {
                u64::MAX
            } else {
                e.parse::<u64>().unwrap_or(0)
            });
        }
    }
    let total = digits.saturating_add(exponent);
    if total > max {
        return Err(Error::Limit(format!(
            "a number of {} digits{} is over the limit of {max} digits (raise it with --max-digits)",
            if total == u64::MAX { "≥ 10¹⁸".to_string() } else { total.to_string() },
            if exponent > 0 { " (exponent included)" } else { "" }
        )));
    }
    Ok(())
}

/// The longest text of one algebraic number the reader takes under the
/// current limits: `max(10 000, 64 × max_digits)` bytes (64 000 by
/// default), so that raising `--max-digits` raises it too. What a command
/// writes is checked against the same bound ([`check_written_number`]).
pub fn max_algebraic_text() -> usize {
    let per_digit = current()
        .max_digits
        .saturating_mul(ALGEBRAIC_TEXT_PER_DIGIT);
    usize::try_from(per_digit)
        .unwrap_or(usize::MAX)
        .max(MAX_ALGEBRAIC_TEXT)
}

/// Check that a number a command is about to write will be read back under
/// the same limits (what we write, we read): an integer or `p/q` within
/// [`Limits::max_digits`] (both sides counted), and the text of an
/// algebraic number within [`max_algebraic_text`] with every integer in it
/// within the digit limit. Text outside the number grammar's alphabet
/// (digits, `+ - * / ( ) , .`, spaces and the words `sqrt`, `cbrt`, `root`,
/// `Rational`, `CRootOf`, `x`) is not a number and passes.
///
/// # Errors
///
/// [`Error::Limit`] naming the size and `--max-digits`.
pub fn check_written_number(text: &str) -> Result<(), Error> {
    if !is_number_text(text) {
        return Ok(());
    }
    let over = |what: String| {
        Error::Limit(format!(
            "the result has {what}, more than the reader takes under the same limits (raise them with --max-digits)"
        ))
    };
    if !text.contains(|c: char| c.is_ascii_alphabetic()) {
        return check_number_text(text)
            .map_err(|_| over(format!("a number of {} characters", text.len())));
    }
    if text.len() > max_algebraic_text() {
        return Err(over(format!(
            "an algebraic number of {} characters (at most {})",
            text.len(),
            max_algebraic_text()
        )));
    }
    let max = current().max_digits as usize;
    match text
        .split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
    {
        Some(longest) if longest > max => Err(over(format!(
            "an algebraic number with an integer of {longest} digits"
        ))),
        _ => Ok(()),
    }
}

/// Is `text` in the alphabet of the number grammars, with a digit?
fn is_number_text(text: &str) -> bool {
    const WORDS: [&str; 6] = ["sqrt", "cbrt", "root", "Rational", "CRootOf", "x"];
    text.contains(|c: char| c.is_ascii_digit())
        && text
            .split(|c: char| !c.is_ascii_alphabetic())
            .all(|w| w.is_empty() || WORDS.contains(&w))
        && text
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || " +-*/(),.".contains(c))
}

/// Check the size of one input before it is read or parsed.
///
/// # Errors
///
/// [`Error::Limit`] naming the size and `--max-input-bytes`.
pub fn check_input_bytes(len: u64) -> Result<(), Error> {
    let max = current().max_input_bytes;
    if len > max {
        return Err(Error::Limit(format!(
            "an input of {len} bytes is over the limit of {max} bytes (raise it with --max-input-bytes)"
        )));
    }
    Ok(())
}

/// Check a point's dimension against [`MAX_DIMENSION`].
///
/// # Errors
///
/// [`Error::Limit`] naming the dimension.
pub fn check_dimension(dim: usize) -> Result<(), Error> {
    if dim > MAX_DIMENSION {
        return Err(Error::Limit(format!(
            "points of dimension {dim} are over the limit of {MAX_DIMENSION}"
        )));
    }
    Ok(())
}

/// Check the degree over Q of the field an input's algebraic numbers span
/// (`what` names them) against [`MAX_FIELD_DEGREE`], and a radical's root
/// index against [`MAX_RADICAL_INDEX`] (`radical`), before any arithmetic.
///
/// # Errors
///
/// [`Error::Limit`] naming the degree and the limit. Neither limit has a
/// flag: the work of field arithmetic grows as the cube of the degree, so
/// the way under the limit is fewer independent generators (one `CRootOf`
/// and rationals, or the numbers of one field).
pub fn check_field_degree(degree: u64, radical: bool, what: &str) -> Result<(), Error> {
    let (limit, name) = if radical {
        (MAX_RADICAL_INDEX, "radical index limit")
    } else {
        (MAX_FIELD_DEGREE as u64, "field degree limit")
    };
    if degree > limit {
        return Err(Error::Limit(format!(
            "{what} needs a number field of degree {degree} over Q, over the {name} of {limit} \
             (a fixed limit, no flag raises it: write the numbers with fewer independent roots)"
        )));
    }
    Ok(())
}

/// Check a degree against [`MAX_DEGREE`]: of an input as it is read, of a
/// patch a command is about to write before computing it (what we write,
/// we read).
///
/// # Errors
///
/// [`Error::DegreeTooHigh`] naming the degree and the limit.
pub fn check_degree(degree: usize) -> Result<(), Error> {
    if degree > MAX_DEGREE {
        return Err(Error::DegreeTooHigh {
            degree,
            limit: MAX_DEGREE,
        });
    }
    Ok(())
}

/// Bits of a rational: numerator plus denominator.
pub fn bits(x: &BigRational) -> u64 {
    x.numer().bits() + x.denom().bits()
}

/// The most bits of any of `xs` (0 for none).
pub fn max_bits<'a>(xs: impl IntoIterator<Item = &'a BigRational>) -> u64 {
    xs.into_iter().map(bits).max().unwrap_or(0)
}

/// What the cost model needs to know of numbers (implemented for the
/// exact scalars in `algebra`), known without arithmetic on them.
pub trait Cost: Sized {
    /// The size of the number in bits (of its largest rational
    /// coefficient).
    fn bits(&self) -> u64;
    /// The degree over Q of the number field the numbers `xs` span, as the
    /// exact arithmetic represents it (1 for rationals): every operation on
    /// them costs [`field_op_cost`] of it; and whether their arithmetic
    /// builds that field (false for rationals and for radicals alone, whose
    /// sums and products stay sums of radicals).
    fn field_degree<'a>(xs: impl IntoIterator<Item = &'a Self>) -> (u64, bool)
    where
        Self: 'a;
}

/// What the cost model needs to know of a patch (built by the patch's
/// `size` method).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    /// Degree: `(n, 0)` for a curve or tri patch, `(m, n)` for a rect.
    pub degree: (usize, usize),
    /// True for a tri patch.
    pub tri: bool,
    /// Coordinates per point (Cartesian).
    pub dim: usize,
    /// The most bits of a stored (homogeneous) number.
    pub bits: u64,
    /// The degree over Q of the number field the stored numbers (and the
    /// command's parameters) span ([`Cost::field_degree`]; 1 over Q).
    pub field_degree: u64,
    /// Whether the arithmetic on them builds that field (an isolated root
    /// or a field element among them), so [`MAX_FIELD_DEGREE`] applies.
    pub field: bool,
}

impl Size {
    /// The size of a patch of `degree` (`tri` for a tri patch) in dimension
    /// `dim` whose stored numbers are `numbers`, computed with numbers
    /// `with` (a command's parameters: they count in the field degree, not
    /// in the bits).
    pub fn measure<'a, T: Cost + 'a>(
        degree: (usize, usize),
        tri: bool,
        dim: usize,
        numbers: impl IntoIterator<Item = &'a T>,
        with: impl IntoIterator<Item = &'a T>,
    ) -> Size {
        let numbers: Vec<&T> = numbers.into_iter().collect();
        let bits = numbers.iter().map(|x| x.bits()).max().unwrap_or(0);
        let (field_degree, field) = T::field_degree(numbers.into_iter().chain(with));
        Size {
            degree,
            tri,
            dim,
            bits,
            field_degree,
            field,
        }
    }

    /// The cost of one operation on this patch's numbers, in rational
    /// operations ([`field_op_cost`] of [`Size::field_degree`]).
    pub fn op_cost(&self) -> u64 {
        field_op_cost(self.field_degree, self.field)
    }

    /// Work units of `ops` operations on numbers of `bits` bits made of
    /// this patch's numbers: [`exact_work`] times [`Size::op_cost`].
    pub fn exact_units(&self, ops: u64, bits: u64) -> u64 {
        exact_work(ops, bits).saturating_mul(self.op_cost())
    }

    /// Operations of writing `count` numbers made of this patch's numbers
    /// as text ([`write_ops`] each), to add to a command's operation count.
    pub fn write_ops(&self, count: u64) -> u64 {
        count.saturating_mul(write_ops(self.field_degree, self.field))
    }

    /// The numbers of the patch as stored: its control points in
    /// homogeneous coordinates (`dim + 1` a point).
    pub fn stored_numbers(&self) -> u64 {
        let (m, n) = (self.degree.0 as u64, self.degree.1 as u64);
        let points = if self.tri {
            (m + 1) * (m + 2) / 2
        } else {
            (m + 1) * (n + 1)
        };
        points.saturating_mul(self.dim as u64 + 1)
    }

    /// The total degree `m + n` (`n` for a curve or tri patch).
    pub fn total_degree(&self) -> u64 {
        (self.degree.0 + self.degree.1) as u64
    }

    /// Rational operations of one de Casteljau evaluation:
    /// `(n+1)²(d+1)` for a curve, `(m+1)(n+1)(m+n+2)(d+1)` for a rect,
    /// `(n+1)³(d+1)` for a tri patch.
    pub fn eval_ops(&self) -> u64 {
        let (m, n) = (self.degree.0 as u64, self.degree.1 as u64);
        let d1 = self.dim as u64 + 1;
        if self.tri {
            (m + 1).pow(3) * d1
        } else if n == 0 {
            (m + 1).pow(2) * d1
        } else {
            (m + 1) * (n + 1) * (m + n + 2) * d1
        }
    }

    /// Bits of the numbers of a computation that multiplies the stored
    /// numbers by `depth` factors of `param_bits` bits each (de Casteljau at
    /// a parameter of that size: `depth` is the total degree).
    pub fn grown_bits(&self, depth: u64, param_bits: u64) -> u64 {
        self.bits
            .saturating_add(depth.saturating_mul(param_bits.saturating_add(1)))
    }

    /// Exact work of one evaluation at parameters of `param_bits` bits.
    pub fn eval_work(&self, param_bits: u64) -> u64 {
        exact_work(
            self.eval_ops(),
            self.grown_bits(self.total_degree(), param_bits),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn digits_count_exponents_and_both_sides() {
        with_limits(
            Limits {
                max_digits: 10,
                ..Limits::DEFAULT
            },
            || {
                assert!(check_number_text("12345/12345").is_ok());
                assert!(check_number_text("123456/12345").is_err());
                assert!(check_number_text("1e9").is_ok());
                assert!(check_number_text("1e10").is_err());
                assert!(check_number_text("1e-10").is_err());
                assert!(check_number_text("1e000000000000000000000000000009").is_ok());
                assert!(check_number_text("1e99999999999999999999999").is_err());
            },
        );
    }

    #[test]
    fn charges_add_up_and_stop_at_the_budget() {
        with_limits(
            Limits {
                max_work: 100,
                ..Limits::DEFAULT
            },
            || {
                assert!(charge("a", 60).is_ok());
                assert!(matches!(charge("b", 60), Err(Error::Limit(_))));
                assert_eq!(charged(), 60);
                assert!(charge("c", 40).is_ok());
            },
        );
        assert_eq!(charged(), 0);
    }

    #[test]
    fn the_meter_counts_without_failing_and_starts_fresh() {
        with_limits(
            Limits {
                max_work: 1,
                ..Limits::DEFAULT
            },
            || {
                meter(10, 0);
                meter(u64::MAX, 64);
                assert_eq!(metered(), u64::MAX);
                with_limits(Limits::DEFAULT, || assert_eq!(metered(), 0));
                assert_eq!(metered(), u64::MAX);
            },
        );
        assert_eq!(metered(), 0);
    }

    #[test]
    fn a_field_operation_costs_the_fourth_power_of_the_degree() {
        assert_eq!(field_op_cost(1, true), 1);
        assert_eq!(field_op_cost(3, true), FIELD_OP_FACTOR * 81);
        assert_eq!(field_op_cost(6, true), 16 * field_op_cost(3, true));
        assert_eq!(field_op_cost(6, false), 4 * field_op_cost(3, false));
        assert_eq!(field_op_cost(u64::MAX, true), u64::MAX);
    }

    #[test]
    fn extensions_past_the_field_degree_limit_are_refused() {
        with_limits(Limits::DEFAULT, || {
            assert!(charge_extension("κ", 1, 2, 0).is_ok());
            assert_eq!(charged(), 0, "a rational root extends nothing");
            assert!(charge_extension("κ", 8, 2, 0).is_ok());
            assert_eq!(charged(), exact_work(16 * 16, 0) * field_op_cost(16, true));
            let e = charge_extension("κ", 17, 2, 0).unwrap_err().to_string();
            assert!(
                e.contains("degree 34") && e.contains("field degree limit of 32"),
                "{e}"
            );
        });
    }

    #[test]
    fn work_grows_with_the_square_of_the_words() {
        assert_eq!(exact_work(10, 0), 40);
        assert_eq!(exact_work(10, 128), 160);
        assert_eq!(exact_work(u64::MAX, 1 << 40), u64::MAX);
    }
}
