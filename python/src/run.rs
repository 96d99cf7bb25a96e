//! The command line in-process, and the limits a Python thread sets.
//!
//! [`run`] is `exact-bezier ARGS…` with standard input from Python: the
//! command line's own [`exact_bezier_cli::run_with`], so every subcommand,
//! option, output and one-line error is the binary's. The package's
//! functions (`exact_bezier.evaluate`, `standardize`, `intersect`, `audit`,
//! `prove`, …) build the arguments and read the JSON it writes.
//!
//! The limits ([`exact_bezier::limits`]) are per Python thread: the
//! `exact_bezier.limits(...)` context sets them here ([`set_limits`]); the
//! native calls run under them ([`current`]) and [`run`] passes them to the
//! command line as its global flags.

use exact_bezier::limits::Limits;
use exact_bezier_cli::{run_with, Stdin};
use pyo3::prelude::*;
use std::cell::Cell;
use std::panic::{catch_unwind, AssertUnwindSafe};

thread_local! {
    /// The limits of the Python thread running on this OS thread.
    static LIMITS: Cell<Limits> = const { Cell::new(Limits::DEFAULT) };
}

/// The limits in force for native calls on this thread.
pub fn current() -> Limits {
    LIMITS.with(Cell::get)
}

/// Set this thread's limits (`max_digits`, `max_input_bytes`, `max_work`);
/// `exact_bezier.limits` restores the previous ones on exit.
#[pyfunction]
pub fn set_limits(max_digits: u64, max_input_bytes: u64, max_work: u64) {
    LIMITS.with(|c| {
        c.set(Limits {
            max_digits,
            max_input_bytes,
            max_work,
        })
    });
}

/// This thread's limits as `(max_digits, max_input_bytes, max_work)`.
#[pyfunction]
pub fn get_limits() -> (u64, u64, u64) {
    let l = current();
    (l.max_digits, l.max_input_bytes, l.max_work)
}

/// Run `exact-bezier ARGS…` in-process with `stdin` as standard input,
/// under this thread's limits (as the global flags `--max-digits`,
/// `--max-input-bytes`, `--max-work`), the GIL released. Returns `(exit
/// code, standard output, standard error, work units charged)`; a panic
/// (a bug) comes back as exit code 70 with its message on standard error.
#[pyfunction]
#[pyo3(signature = (args, stdin = Vec::new()))]
pub fn run(py: Python<'_>, args: Vec<String>, stdin: Vec<u8>) -> (i32, String, String, u64) {
    let l = current();
    let mut argv = vec!["exact-bezier".to_string()];
    argv.extend([
        format!("--max-digits={}", l.max_digits),
        format!("--max-input-bytes={}", l.max_input_bytes),
        format!("--max-work={}", l.max_work),
    ]);
    argv.extend(args);
    py.detach(move || {
        match catch_unwind(AssertUnwindSafe(|| run_with(argv, Stdin::Bytes(stdin)))) {
            Ok(o) => (o.code, o.stdout, o.stderr, o.work),
            Err(p) => (
                70,
                String::new(),
                format!(
                    "error: internal error (a bug in exact-bezier, please report it): {}",
                    crate::panic_text(p.as_ref())
                ),
                0,
            ),
        }
    })
}
