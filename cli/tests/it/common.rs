//! Helpers shared by the integration tests: running the `exact-bezier`
//! binary. Each test crate uses its own subset.
#![allow(dead_code)]

use std::process::Command;

/// The `exact-bezier` binary, run from the crate root (fixture paths in the
/// tests are relative to it).
pub fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_exact-bezier"));
    c.current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    c
}

/// Run the binary: (exit code, −1 if it has none; standard output; standard
/// error).
pub fn cli(args: &[&str]) -> (i32, String, String) {
    let out = bin().args(args).output().expect("the binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Run the binary: (exit code, standard output as JSON, `Null` if it is not
/// JSON).
pub fn cli_json(args: &[&str]) -> (i32, serde_json::Value) {
    let (code, out, _) = cli(args);
    (
        code,
        serde_json::from_str(&out).unwrap_or(serde_json::Value::Null),
    )
}
