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
//!
//! The modules: `args` (the clap definitions and the dispatch), `session`
//! (one run: standard input and output, exit codes, one-line errors),
//! `input` (files, patches over the exact scalar their numbers need,
//! parameter lists), `patch_ops` (a command over every input patch, its
//! cost charged first), and one module per subcommand.

mod arc;
mod args;
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
mod input;
mod intersect;
mod is_circle;
mod join;
mod key;
mod mesh;
mod patch_ops;
mod plot;
mod prove;
mod recent;
mod reduce;
mod session;
mod standardize;
mod transform;

pub use args::{Cli, ScalarKind};
pub(crate) use input::on_exact;
pub(crate) use input::{
    check_tol, load, load_all_exact, load_exact, load_one, open_input, parse_algebraic_list,
    parse_list, read_input, ExactPatches, ExactScalar,
};
pub(crate) use patch_ops::{charge_each, check_domain, one_or_many, patch_f64, run_each, PatchOp};
pub(crate) use session::{
    check_finite, emit, emit_raw, json_text, mark_outside_domain, stdin_reader,
};
pub use session::{main, one_line, run_with, Outcome, Stdin, EXIT_OUTSIDE_DOMAIN, MAX_ERROR_CHARS};
