//! One run of the command line: standard input and output of the run in
//! progress (in-process runs nest and buffer), exit codes, and the
//! one-line error contract.

use crate::args::{dispatch, Cli};
use clap::Parser;
use exact_bezier::limits;
use exact_bezier::Error;
use serde_json::Value;
use std::cell::RefCell;
use std::io::Read;

/// Exit code of a result written but outside the valid domain (module docs).
pub const EXIT_OUTSIDE_DOMAIN: i32 = 3;

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
    /// Work units the exact algebraic arithmetic actually did, in the same
    /// units ([`exact_bezier::limits::metered`]): tests compare it with
    /// [`Outcome::work`].
    pub metered: u64,
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
    let (code, stderr, (work, metered)) = parse_and_run(args, nested);
    let session = SESSION.with(|s| s.borrow_mut().pop().expect("the session pushed above"));
    Outcome {
        code: if code == 0 { session.exit } else { code },
        stdout: session.stdout,
        stderr: stderr.map_or_else(String::new, |e| format!("error: {}\n", one_line(&e))),
        work,
        metered,
    }
}

/// Parse and run; the exit code, the error message if any, and the work
/// charged and metered.
fn parse_and_run(args: Vec<String>, nested: bool) -> (i32, Option<String>, (u64, u64)) {
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => {
            let (code, err) = clap_outcome(&e);
            return (code, err, (0, 0));
        }
    };
    let pretty = cli.pretty;
    let run = |command| {
        let before = (limits::charged(), limits::metered());
        let result = limits::charge("the command", limits::COMMAND_WORK);
        let result = result
            .and_then(|()| dispatch(command))
            .and_then(|r| match r {
                Ok(v) => check_finite(&v).map(|()| Ok(v)),
                Err(code) => Ok(Err(code)),
            });
        let work = (
            limits::charged() - before.0,
            limits::metered().saturating_sub(before.1),
        );
        (result, work)
    };
    let (result, work) = if nested {
        if cli.sets_limits() {
            let e = "limit flags belong to the outer command line".to_string();
            return (2, Some(e), (0, 0));
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
/// Refuse too an exact number the reader would not take back under the
/// same limits ([`limits::check_written_number`]: what we write, we read).
pub(crate) fn check_finite(v: &Value) -> Result<(), Error> {
    match v {
        Value::String(s) if matches!(s.as_str(), "inf" | "-inf" | "NaN") => Err(Error::NotFinite(
            "an f64 result overflowed (inf or NaN); use --scalar exact or smaller numbers".into(),
        )),
        Value::String(s) => limits::check_written_number(s),
        // Exact integers are written as JSON numbers; f64 results (with a
        // point or an exponent) are not exact input and are not checked.
        Value::Number(n) => {
            let text = n.to_string();
            if text.contains(['.', 'e', 'E']) {
                Ok(())
            } else {
                limits::check_written_number(&text)
            }
        }
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
pub(crate) fn stdin_reader() -> Box<dyn Read + Send> {
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
