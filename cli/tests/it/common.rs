//! Helpers shared by the integration tests: running the `exact-bezier`
//! binary. Each test crate uses its own subset.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

/// The `exact-bezier` binary, run from the crate root (fixture paths in the
/// tests are relative to it).
pub fn bin() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_exact-bezier"));
    c.current_dir(root());
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

/// The workspace root, where the fixture paths of the tests (and of the
/// documented examples) are relative to.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the cli crate is inside the workspace")
        .to_path_buf()
}

/// `std::fs::read_to_string` of a path relative to the workspace root (an
/// absolute path is taken as it is).
pub fn read_to_string(path: impl AsRef<Path>) -> std::io::Result<String> {
    std::fs::read_to_string(root().join(path))
}

/// `std::fs::File::open` of a path relative to the workspace root.
pub fn open(path: impl AsRef<Path>) -> std::io::Result<std::fs::File> {
    std::fs::File::open(root().join(path))
}

/// Metered work may be at most this many times the charged work, the
/// factor within which the cost model is calibrated against time
/// (docs/limits.md) … (no ratio above 2 in 100 generated algebraic cases
/// since writing a number-field element is charged, `limits::write_ops`;
/// the ratio was 17 for `reparam --mobius sqrt(2)/2` of a quadratic over a
/// degree-8 field, whose nine written numbers cost 150 products each).
pub const METER_FACTOR: u64 = 4;

/// … plus this many units (a few hundred operations on small numbers:
/// comparisons and signs that no model counts one by one).
pub const METER_SLACK: u64 = 20_000;

/// An in-process run that answered (`out.code == 0`) did at most
/// [`METER_FACTOR`] times the work it was charged (+ [`METER_SLACK`]),
/// counted by the actual-work meter, and every number it wrote reads back.
pub fn answered_within_charge(out: &exact_bezier_cli::Outcome, args: &[&str]) {
    assert_eq!(out.code, 0, "{args:?}: {}", out.stderr);
    assert!(
        out.metered <= METER_FACTOR * out.work + METER_SLACK,
        "{args:?}: metered {} for {} charged",
        out.metered,
        out.work
    );
    written_numbers_read_back(&out.stdout, args);
}

/// Every number a JSON answer writes (a string of the numbers' grammar,
/// docs/algebraic_numbers.md) is read back by the algebraic reader under
/// the default limits; `args` names the command in the failure. Returns
/// how many numbers were checked.
pub fn written_numbers_read_back(stdout: &str, args: &[&str]) -> usize {
    use exact_bezier::algebra::{ExactNumber, RealAlgebraic};
    let v: serde_json::Value = serde_json::from_str(stdout).expect("JSON");
    let mut strings = Vec::new();
    collect_strings(&v, &mut strings);
    let numbers: Vec<&String> = strings.iter().filter(|s| is_number_text(s)).collect();
    for s in &numbers {
        assert!(
            RealAlgebraic::from_text(s).is_ok(),
            "{args:?} wrote {s:.200}, which the reader refuses"
        );
    }
    numbers.len()
}

fn collect_strings(v: &serde_json::Value, out: &mut Vec<String>) {
    match v {
        serde_json::Value::String(s) => out.push(s.clone()),
        serde_json::Value::Array(a) => a.iter().for_each(|x| collect_strings(x, out)),
        serde_json::Value::Object(m) => m.values().for_each(|x| collect_strings(x, out)),
        _ => {}
    }
}

/// A string with a digit whose words are all names of the number grammar.
fn is_number_text(s: &str) -> bool {
    s.contains(|c: char| c.is_ascii_digit())
        && s.split(|c: char| !c.is_ascii_alphabetic())
            .all(|w| w.is_empty() || ["sqrt", "cbrt", "root", "CRootOf", "x"].contains(&w))
}
