//! The command line (README, "A short tour"): subcommands read the JSON
//! interchange format (a path, or `-` for standard input) and write JSON to
//! standard output. Exit codes: 0 success, 1 a `prove` claim off its expected
//! verdict, 2 bad input or a limit (one line on standard error, argument
//! errors included), 3 a result written but outside the valid domain (e.g.
//! `reduce` giving a non-positive weight; the output says which). Never a
//! panic, never `inf`/`NaN` in the output.
//!
//! Every command runs in-process through [`run_with`] (argument vector and
//! standard-input bytes in, [`Outcome`] out); the binary's `main` is a thin
//! wrapper, so the fuzz suite (`tests/fuzz.rs`) drives exactly what users
//! run. Errors of every subcommand, present and future, pass through
//! [`one_line`]; resource limits ([`exact_bezier::limits`]) are set from the global
//! flags `--max-digits`, `--max-input-bytes` and `--max-work`.
//!
//! Exact arithmetic is the default; `--scalar f64` selects floats.

use clap::{Parser, Subcommand, ValueEnum};
use exact_bezier::algebra::Ordered;
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::algebra::Scalar;
use exact_bezier::coincide::{CoincideScalar, Reducible};
use exact_bezier::io::{read_patches, read_patches_as, JsonScalar};
use exact_bezier::limits::{self, Cost, Limits, Size};
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use num_rational::BigRational;
use num_traits::{One, Zero};
use serde_json::Value;
use std::cell::RefCell;
use std::io::Read;

mod arc;
mod audit;
mod bulk;
mod coincide;
mod convert;
mod curvature;
mod dedup;
mod deriv;
mod eval;
mod eval_trig;
mod figures;
mod intersect;
mod is_circle;
mod join;
mod key;
mod mesh;
mod plot;
mod prove;
mod reduce;
mod standardize;
mod transform;

/// Rational Bézier curves and patches, exactly.
#[derive(Parser, Debug)]
#[command(name = "exact-bezier", version, about)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Most decimal digits per input number, exponent included (docs/limits.md).
    #[arg(long, global = true, value_name = "N")]
    max_digits: Option<u64>,
    /// Most bytes of one input file or of standard input.
    #[arg(long, global = true, value_name = "BYTES")]
    max_input_bytes: Option<u64>,
    /// Most estimated work units of one command (docs/limits.md).
    #[arg(long, global = true, value_name = "UNITS")]
    max_work: Option<u64>,
    /// Print JSON results over several indented lines (default: one line).
    #[arg(long, global = true)]
    pretty: bool,
}

impl Cli {
    /// The limits asked for by the global flags (defaults otherwise).
    fn limits(&self) -> Limits {
        let d = Limits::DEFAULT;
        Limits {
            max_digits: self.max_digits.unwrap_or(d.max_digits),
            max_input_bytes: self.max_input_bytes.unwrap_or(d.max_input_bytes),
            max_work: self.max_work.unwrap_or(d.max_work),
        }
    }

    fn sets_limits(&self) -> bool {
        self.max_digits.is_some() || self.max_input_bytes.is_some() || self.max_work.is_some()
    }
}

/// Which scalar a command computes with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum, Default)]
pub enum ScalarKind {
    /// Exact rationals.
    #[default]
    Exact,
    /// IEEE double precision.
    F64,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Evaluate a curve or patch: {"point": [...]}.
    #[command(
        after_help = "Parameters are exact text (1/3, 0.25). A curve takes t in [0, 1]; a rect takes u,v in [0, 1]²; a tri takes barycentric u,v with u, v ≥ 0 and u + v ≤ 1 (w = 1 − u − v; u = 1 is the vertex points[0][n], v = 1 is points[n][0], w = 1 is points[0][0]). A trig patch takes tau=T (τ = tan(t/2)). Outside the domain needs --extrapolate.\n\nExample: exact-bezier eval tests/fixtures/yang_yong_example1.json --at 1/3,1/2"
    )]
    Eval(eval::Args),
    /// Reparameterize: linear Möbius map (--mobius ALPHA[,BETA]) or quadratic map of a rect (--quadratic A1,A2,B1,B2).
    #[command(
        after_help = "The linear Möbius map u = (α − 1)s / (2αs − s − α) with 0 < α < 1 (α = 1/2 is the identity) keeps every point of the patch and changes only its weights (source 000, eqs. 2–4). The quadratic map of source 000, eqs. 9–10, raises a rect (m, n) to (m + n, m + n).\n\nExample: exact-bezier reparam tests/fixtures/yang_yong_example1.json --mobius 3/5,7/10"
    )]
    Reparam(transform::ReparamArgs),
    /// Standard form: end weights 1 (curve) or corner weights 1 (rect).
    #[command(
        after_help = "Finds the reparameterization that makes the end weights (curve) or the corner weights (rect) equal to 1, exactly, with real algebraic numbers where roots are needed (sqrt, cbrt: docs/algebraic_numbers.md). A rect whose corner weights satisfy ω_m0·ω_0n = ω_00·ω_mn takes a linear Möbius map (source 000, Theorem 1); any other takes the quadratic map of eqs. 9–19.\n\nExample: exact-bezier standardize tests/fixtures/yang_yong_example3.json"
    )]
    Standardize(standardize::Args),
    /// Raise the degree (--by R[,S]).
    #[command(
        after_help = "The same curve or patch with its degree raised by R (and by S in v for a rect); the points do not change.\n\nExample: exact-bezier elevate tests/fixtures/yang_yong_example1.json --by 1,2"
    )]
    Elevate(transform::ElevateArgs),
    /// Convert rect ↔ tri (--to tri | --to rect [--split a,b,c,d,e,f] [--degenerate]).
    #[command(
        after_help = "--to tri: a rect (m, n) becomes two tris of degree m + n, on u + v ≤ 1 and on its complement. --to rect: a tri of degree n becomes three rects (n, n) over a split of the triangle (see --split), or one degenerate rect. --to rational: a trig patch becomes its exact rational Bézier form. --to bezier: NURBS or STEP input becomes its rational Bézier pieces.\n\nExample: exact-bezier convert tests/fixtures/zcf_4_2_tri.json --to rect --split 1/3,1/2,1/3,1/2,1/2,1/2"
    )]
    Convert(convert::Args),
    /// Run every proof in proofs/ and print one line per claim.
    #[command(
        after_help = "Each claim gets a verdict: proved, checked, refuted, reproduced, mismatch or broken (see the README). Exit 0 iff every claim has its expected verdict.\n\nExample: exact-bezier prove --family bernstein"
    )]
    Prove(prove::Args),
    /// Draw curves and patches as SVG or PNG (-o OUT.svg|OUT.png).
    #[command(
        after_help = "Example: exact-bezier plot tests/fixtures/yang_yong_example1.json -o example1.png"
    )]
    Plot(plot::Args),
    /// Triangulate patches with normals as OBJ, STL or PLY (-o OUT.obj).
    #[command(
        after_help = "Example: exact-bezier mesh tests/fixtures/yang_yong_example1.json -o example1.obj --density 16"
    )]
    Mesh(mesh::Args),
    /// Regenerate the figure gallery (docs/figures/gallery.json).
    #[command(after_help = "Example: exact-bezier figures --only 000-fig3a-example1")]
    Figures(figures::Args),
    /// Derivative of a curve: {"order": K, "derivative": [...]}.
    #[command(
        after_help = "Example: exact-bezier deriv docs/examples/curve.json --at 1/2 --order 2"
    )]
    Deriv(deriv::Args),
    /// Curvature of a curve: {"curvature_squared": κ², "curvature": κ, "curvature_approx": κ as f64}, exact (κ = √κ², algebraic).
    #[command(after_help = "Example: exact-bezier curvature docs/examples/curve.json --at 1/2")]
    Curvature(curvature::Args),
    /// G0/G1/G2 verdicts for the join of curve A's end to curve B's start.
    #[command(
        after_help = "G0: B starts where A ends. G1: also the same tangent direction, Q1 − Q0 = (nα/m)(Pn − Pn−1) with α > 0 (the corrected form of source 001). G2: also the same curvature vector.\n\nExample: exact-bezier join docs/examples/curve.json docs/examples/curve.json"
    )]
    Join(join::Args),
    /// Lower the degree of a curve by one (--method forrest|farin|lsq|exact).
    #[command(
        after_help = "forrest and farin may give non-positive weights: the result is then written with valid: false, and the exit code is 3. exact succeeds only when the curve truly has a lower degree.\n\nExample: exact-bezier reduce docs/examples/curve.json --method lsq"
    )]
    Reduce(reduce::Args),
    /// A circular arc as a standard-form rational cubic (source 004 eq. 1).
    #[command(
        after_help = "λ picks one member of the family of standard-form cubics of the same arc. It is admissible (all weights positive) iff 1 − λk > 0, 1 + 2λck > 0 and 1 − λ(1 − 4c²) > 0, with c = cos(θ/2) and k = 1 + 2c: λ in (−1/(2ck), 1/k) for 0 < θ < π, and λ < 1/(1 − 4c²) for π ≤ θ < 4π/3.\n\nExample: exact-bezier arc --cos-half 'sqrt(2)/2' --lambda 0 --points '1,0;1,1;0,1'"
    )]
    Arc(arc::Args),
    /// Does a curve lie on a circle? Exact centre and radius², or the reason.
    #[command(after_help = "Example: exact-bezier is-circle docs/examples/arc.json")]
    IsCircle(is_circle::Args),
    /// Are two curves or rect patches the same up to reparameterization?
    #[command(
        after_help = "Same up to Möbius maps of each parameter, reversal, swapping u and v, degree elevation, common factors and weight scaling, decided exactly (no roots, no tolerance). The witness gives the map. Exit 0 either way.\n\nExample: exact-bezier coincide tests/fixtures/yang_yong_example1.json tests/fixtures/yang_yong_example3.json"
    )]
    Coincide(coincide::Args),
    /// Exact intersections of two curves (or self-intersections of one): points, contacts, overlaps.
    #[command(
        after_help = "Parameters and points are exact real algebraic numbers (sqrt(...), CRootOf(...)) with f64 approximations; an overlap gives the parameter intervals on both curves and the Möbius map s = (a t + b)/(c t + d) between them. Without B: loops (s < t) and cusps of A.\n\nExample: exact-bezier intersect docs/examples/curve.json docs/examples/line.json"
    )]
    Intersect(intersect::Args),
    /// Group curves/rect patches (JSON Lines or array) into coincidence classes, one JSON line each.
    #[command(after_help = "Example: exact-bezier dedup patches.jsonl --witness")]
    Dedup(dedup::Args),
    /// One canonical coincidence key per curve/rect patch, one JSON line each.
    #[command(after_help = "Example: exact-bezier key patches.jsonl")]
    Key(key::Args),
    /// Exact audit of a model (JSON, NURBS or STEP): shared edges G0/G1/G2, open/degenerate edges, duplicates.
    #[command(after_help = "Example: exact-bezier audit tests/fixtures/teapot.json --summary")]
    Audit(audit::Args),
}

/// Exit code of a result written but outside the valid domain (module docs).
pub const EXIT_OUTSIDE_DOMAIN: i32 = 3;

/// Run one command: its JSON result, or its exit code when the command
/// prints for itself (`prove`).
fn dispatch(command: Command) -> Result<Result<Value, i32>, Error> {
    let value = match command {
        Command::Eval(a) => return eval::run(&a),
        Command::Reparam(a) => transform::reparam(&a),
        Command::Elevate(a) => transform::elevate(&a),
        Command::Standardize(a) => standardize::run(&a),
        Command::Convert(a) => convert::run(&a),
        Command::Prove(a) => return prove::run(&a).map(Err),
        Command::Plot(a) => plot::run(&a),
        Command::Mesh(a) => mesh::run(&a),
        Command::Figures(a) => figures::run(&a),
        Command::Deriv(a) => deriv::run(&a),
        Command::Curvature(a) => curvature::run(&a),
        Command::Join(a) => join::run(&a),
        Command::Reduce(a) => reduce::run(&a),
        Command::Arc(a) => arc::run(&a),
        Command::IsCircle(a) => is_circle::run(&a),
        Command::Coincide(a) => coincide::run(&a),
        Command::Intersect(a) => intersect::run(&a),
        Command::Dedup(a) => return dedup::run(&a).map(|()| Err(0)),
        Command::Key(a) => return key::run(&a).map(|()| Err(0)),
        Command::Audit(a) => audit::run(&a),
    }?;
    Ok(Ok(value))
}

/// Where a run's standard input comes from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Stdin {
    /// The process's standard input (the binary).
    Process,
    /// These bytes (in-process runs: tests, nested `figures` inputs).
    Bytes(Vec<u8>),
}

/// What one run of the command line did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// The exit code (module docs).
    pub code: i32,
    /// Standard output.
    pub stdout: String,
    /// Standard error: empty, or one line.
    pub stderr: String,
    /// Work units charged by the cost model ([`exact_bezier::limits::charged`]).
    pub work: u64,
}

/// The state of the run in progress on this thread.
struct Session {
    stdin: Stdin,
    stdout: String,
    exit: i32,
    /// Write standard output straight to the process's (the binary's
    /// top-level run), so that long outputs stream; otherwise buffer it.
    direct: bool,
}

thread_local! {
    static SESSION: RefCell<Vec<Session>> = const { RefCell::new(Vec::new()) };
}

/// Run the command line `args` (with the program name first) in-process,
/// with `stdin` as standard input. A run inside a run (a `figures` input)
/// shares the outer run's limits and work counter.
pub fn run_with(args: Vec<String>, stdin: Stdin) -> Outcome {
    run_session(args, stdin, false)
}

/// [`run_with`], writing standard output to the process's as it comes when
/// `direct` (then [`Outcome::stdout`] is empty).
fn run_session(args: Vec<String>, stdin: Stdin, direct: bool) -> Outcome {
    let nested = SESSION.with(|s| !s.borrow().is_empty());
    SESSION.with(|s| {
        s.borrow_mut().push(Session {
            stdin,
            stdout: String::new(),
            exit: 0,
            direct,
        })
    });
    let (code, stderr, work) = parse_and_run(args, nested);
    let session = SESSION.with(|s| s.borrow_mut().pop().expect("the session pushed above"));
    Outcome {
        code: if code == 0 { session.exit } else { code },
        stdout: session.stdout,
        stderr: stderr.map_or_else(String::new, |e| format!("error: {}\n", one_line(&e))),
        work,
    }
}

/// Parse and run; the exit code, the error message if any, and the work
/// charged.
fn parse_and_run(args: Vec<String>, nested: bool) -> (i32, Option<String>, u64) {
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => {
            let (code, err) = clap_outcome(&e);
            return (code, err, 0);
        }
    };
    let pretty = cli.pretty;
    let run = |command| {
        let before = limits::charged();
        let result = dispatch(command).and_then(|r| match r {
            Ok(v) => check_finite(&v).map(|()| Ok(v)),
            Err(code) => Ok(Err(code)),
        });
        (result, limits::charged() - before)
    };
    let (result, work) = if nested {
        if cli.sets_limits() {
            let e = "limit flags belong to the outer command line".to_string();
            return (2, Some(e), 0);
        }
        run(cli.command)
    } else {
        let limits = cli.limits();
        limits::with_limits(limits, || run(cli.command))
    };
    match result {
        Ok(Ok(v)) => {
            emit(&json_text(&v, pretty));
            (0, None, work)
        }
        Ok(Err(code)) => (code, None, work),
        Err(e) => (2, Some(e.to_string()), work),
    }
}

/// `v` as JSON text: one line, or indented over several with `pretty`.
pub(crate) fn json_text(v: &Value, pretty: bool) -> String {
    let text = if pretty {
        serde_json::to_string_pretty(v)
    } else {
        serde_json::to_string(v)
    };
    text.unwrap_or_default()
}

/// Help and version go to standard output (exit 0); every other argument
/// error becomes one line: the message, clap's tip and the usage.
fn clap_outcome(e: &clap::Error) -> (i32, Option<String>) {
    use clap::error::ErrorKind;
    let text = e.render().to_string();
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            emit(text.trim_end());
            return (0, None);
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            return (
                2,
                Some("a subcommand is required; usage: exact-bezier [OPTIONS] <COMMAND>; try '--help'".into()),
            );
        }
        _ => {}
    }
    let mut parts = Vec::new();
    for line in text.lines().map(str::trim).filter(|l| !l.is_empty()) {
        let line = line.strip_prefix("error: ").unwrap_or(line);
        if let Some(u) = line.strip_prefix("Usage: ") {
            parts.push(format!("usage: {u}"));
        } else if line.starts_with("For more information") {
            parts.push("try '--help'".into());
        } else {
            parts.push(line.to_string());
        }
    }
    (2, Some(parts.join("; ")))
}

/// The most characters of an error line.
pub const MAX_ERROR_CHARS: usize = 300;

/// `message` as one line of at most [`MAX_ERROR_CHARS`] characters:
/// control characters escaped (`\n`), the middle elided when too long.
pub fn one_line(message: &str) -> String {
    let flat: String = message
        .chars()
        .flat_map(|c| {
            let escaped: Vec<char> = if c.is_control() {
                c.escape_default().collect()
            } else {
                vec![c]
            };
            escaped
        })
        .collect();
    let n = flat.chars().count();
    if n <= MAX_ERROR_CHARS {
        return flat;
    }
    // Head + tail + the marker (at most 36 characters) stay within the limit.
    let (keep_head, keep_tail) = (MAX_ERROR_CHARS - 100, 60);
    let head: String = flat.chars().take(keep_head).collect();
    let tail: String = flat.chars().skip(n - keep_tail).collect();
    format!(
        "{head} …[{} characters elided]… {tail}",
        n - keep_head - keep_tail
    )
}

/// Refuse output with a non-finite number: an `f64` result that overflowed
/// is written as the text `inf`, `-inf` or `NaN` by
/// [`JsonScalar`](exact_bezier::io::JsonScalar), and caught here for every command.
pub(crate) fn check_finite(v: &Value) -> Result<(), Error> {
    match v {
        Value::String(s) if matches!(s.as_str(), "inf" | "-inf" | "NaN") => Err(Error::NotFinite(
            "an f64 result overflowed (inf or NaN); use --scalar exact or smaller numbers".into(),
        )),
        Value::Array(items) => items.iter().try_for_each(check_finite),
        Value::Object(map) => map.values().try_for_each(check_finite),
        _ => Ok(()),
    }
}

/// Mark this run's result as outside the valid domain: the output is still
/// written, and the exit code is [`EXIT_OUTSIDE_DOMAIN`].
pub(crate) fn mark_outside_domain() {
    SESSION.with(|s| {
        if let Some(top) = s.borrow_mut().last_mut() {
            top.exit = EXIT_OUTSIDE_DOMAIN;
        }
    });
}

/// Run the command line of this process; returns the exit code.
pub fn main() -> i32 {
    let out = run_session(std::env::args().collect(), Stdin::Process, true);
    use std::io::Write;
    let _ = std::io::stderr().write_all(out.stderr.as_bytes());
    // A closed pipe (e.g. `exact-bezier prove | head`) is not an error: the
    // reader has what it wanted.
    let mut stdout = std::io::stdout().lock();
    let _ = stdout
        .write_all(out.stdout.as_bytes())
        .and_then(|()| stdout.flush());
    out.code
}

/// Append `text` and a newline to this run's standard output.
pub(crate) fn emit(text: &str) {
    emit_raw(text);
    emit_raw("\n");
}

/// Append `text` to this run's standard output: the buffer of an
/// in-process run, or the process's standard output for the binary. A
/// closed pipe (e.g. `exact-bezier prove | head`) is not an error: the
/// reader has what it wanted, so write errors are ignored.
pub(crate) fn emit_raw(text: &str) {
    use std::io::Write;
    SESSION.with(|s| {
        if let Some(top) = s.borrow_mut().last_mut() {
            if top.direct {
                let _ = std::io::stdout().lock().write_all(text.as_bytes());
            } else {
                top.stdout.push_str(text);
            }
        }
    });
}

/// This run's standard input as a reader: the given bytes of an in-process
/// run, or the process's standard input.
pub(crate) fn stdin_reader() -> Box<dyn Read> {
    let given = SESSION.with(|s| {
        s.borrow_mut()
            .last_mut()
            .and_then(|top| match &mut top.stdin {
                Stdin::Bytes(b) => Some(std::mem::take(b)),
                Stdin::Process => None,
            })
    });
    match given {
        Some(bytes) => Box::new(std::io::Cursor::new(bytes)),
        None => Box::new(std::io::stdin()),
    }
}

/// Read all of `r`, refusing more than the input limit.
fn read_limited(r: impl Read, what: &str) -> Result<String, Error> {
    let max = limits::current().max_input_bytes;
    let mut bytes = Vec::new();
    r.take(max.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| Error::Io(format!("cannot read {what}: {e}")))?;
    limits::check_input_bytes(bytes.len() as u64)?;
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
/// inputs read as a stream (STEP files).
pub(crate) fn open_input(path: &str) -> Result<Box<dyn std::io::BufRead>, Error> {
    if path == "-" {
        return Ok(Box::new(std::io::BufReader::new(stdin_reader())));
    }
    let f =
        std::fs::File::open(path).map_err(|e| Error::Io(format!("cannot read {path:?}: {e}")))?;
    Ok(Box::new(std::io::BufReader::with_capacity(1 << 16, f)))
}

/// Read the patches of `path`.
///
/// An empty array is refused (docs/limits.md, policies): every command
/// needs at least one patch.
pub(crate) fn load(path: &str) -> Result<Vec<Patch<BigRational>>, Error> {
    let patches = read_patches(&read_input(path)?)?;
    if patches.is_empty() {
        return Err(empty_input(path));
    }
    Ok(patches)
}

/// The error for a file that holds an empty array.
fn empty_input(path: &str) -> Error {
    Error::Shape(format!(
        "{path:?} holds an empty array: no curve or patch to work on"
    ))
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
    /// text neither reader accepts gets the rational reader's error.
    pub(crate) fn parse(text: &str) -> Result<Self, Error> {
        match read_patches(text) {
            Ok(p) => Ok(ExactPatches::Rational(p)),
            Err(rational) => match read_patches_as::<RealAlgebraic>(text) {
                Ok(p) => Ok(ExactPatches::Algebraic(p)),
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
/// array is refused as by [`load`].
pub(crate) fn load_exact(path: &str) -> Result<ExactPatches, Error> {
    let patches = ExactPatches::parse(&read_input(path)?)?;
    if patches.len() == 0 {
        return Err(empty_input(path));
    }
    Ok(patches)
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
    items
        .into_iter()
        .map(|t| RealAlgebraic::from_text(t.trim()))
        .collect()
}

/// Parse a comma-separated list of exact numbers (`1/3,0.25`).
pub(crate) fn parse_list(text: &str) -> Result<Vec<BigRational>, Error> {
    text.split(',')
        .map(exact_bezier::algebra::parse_rational)
        .collect()
}

/// A command's computation on one patch with exact parameters, written once
/// for every scalar (see [`run_each`]).
pub(crate) trait PatchOp {
    /// The command's name, for the limit message.
    const NAME: &'static str;

    /// The JSON result for `p` at `params` (converted to the patch's scalar).
    fn apply<T: JsonScalar + Ordered>(&self, p: &Patch<T>, params: &[T]) -> Result<Value, Error>;

    /// Estimated `(operations, bits)` of [`PatchOp::apply`] on a patch of
    /// size `s` at parameters of `param_bits` bits (the cost model of
    /// [`exact_bezier::limits`]); by default one evaluation.
    fn cost(&self, s: &Size, param_bits: u64) -> (u64, u64) {
        (s.eval_ops(), s.grown_bits(s.total_degree(), param_bits))
    }
}

/// Charge `what`'s estimated work on each patch before computing
/// ([`limits::charge_sizes`]: `cost` gives `(operations, bits)`; an `f64`
/// run counts the operations only).
pub(crate) fn charge_each<T: ExactScalar>(
    what: &str,
    patches: &[Patch<T>],
    scalar: ScalarKind,
    cost: impl Fn(&Size) -> (u64, u64),
) -> Result<(), Error> {
    let sizes = patches.iter().map(Patch::size);
    limits::charge_sizes(what, sizes, scalar == ScalarKind::Exact, 1, cost)
}

/// Convert an exact patch to `f64`, refusing numbers that overflow.
///
/// # Errors
///
/// [`Error::NotFinite`] naming the first such number.
pub(crate) fn patch_f64<T: Ordered>(p: &Patch<T>) -> Result<Patch<f64>, Error> {
    let bad = std::cell::Cell::new(false);
    let f = p.map(|x| {
        let y = x.to_f64();
        if !y.is_finite() {
            bad.set(true);
        }
        y
    });
    if bad.get() {
        return Err(Error::NotFinite(
            "a coordinate or weight is too large for f64; use --scalar exact".into(),
        ));
    }
    Ok(f)
}

/// Apply `op` to every patch with the chosen scalar: exactly, or on the
/// nearest `f64` patch and parameters. One value for a single patch, an
/// array for several. The estimated work is charged first.
///
/// # Errors
///
/// [`Error::Limit`] over the work budget; the first error of `op`.
pub(crate) fn run_each<Op: PatchOp, T: ExactScalar>(
    patches: &[Patch<T>],
    params: &[T],
    scalar: ScalarKind,
    op: &Op,
) -> Result<Value, Error> {
    let param_bits = params.iter().map(T::bits).max().unwrap_or(0);
    let param_degree = params.iter().map(T::root_degree).max().unwrap_or(1);
    let sizes = patches.iter().map(Patch::size);
    let exact = scalar == ScalarKind::Exact;
    limits::charge_sizes(Op::NAME, sizes, exact, param_degree, |s| {
        op.cost(s, param_bits)
    })?;
    let values = patches
        .iter()
        .map(|p| match scalar {
            ScalarKind::Exact => op.apply(p, params),
            ScalarKind::F64 => op.apply(
                &patch_f64(p)?,
                &params.iter().map(Ordered::to_f64).collect::<Vec<_>>(),
            ),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(one_or_many(values))
}

/// Refuse parameters outside the domain of `p` (policy: extrapolation only
/// with `--extrapolate`): `t ∈ [0, 1]` for a curve, `(u, v) ∈ [0, 1]²` for
/// a rect, `u, v ≥ 0, u + v ≤ 1` for a tri patch. A parameter count that
/// does not fit is left to the command's own message.
///
/// # Errors
///
/// [`Error::Domain`] naming the parameter and the flag.
pub(crate) fn check_domain<T: exact_bezier::Scalar>(
    p: &Patch<T>,
    params: &[BigRational],
) -> Result<(), Error> {
    let (zero, one) = (BigRational::zero(), BigRational::one());
    let unit = |x: &BigRational| *x >= zero && *x <= one;
    let inside = match (p, params) {
        (Patch::Curve(_), [t]) => unit(t),
        (Patch::Rect(_), [u, v]) => unit(u) && unit(v),
        (Patch::Tri(_), [u, v]) => u >= &zero && v >= &zero && (u + v) <= one,
        _ => true,
    };
    if inside {
        return Ok(());
    }
    let shown: Vec<String> = params.iter().map(ToString::to_string).collect();
    Err(Error::Domain(format!(
        "--at {} is outside the domain of the {} (give --extrapolate to evaluate the polynomial beyond it)",
        shown.join(","),
        p.kind()
    )))
}

/// One value for a single patch, an array for several.
pub(crate) fn one_or_many(mut values: Vec<Value>) -> Value {
    if values.len() == 1 {
        values.swap_remove(0)
    } else {
        Value::Array(values)
    }
}
