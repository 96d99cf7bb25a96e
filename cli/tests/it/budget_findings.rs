//! The fuzzing findings that opened issue 32, each run as the issue ran it,
//! in-process under the **default** limits: every one now answers with
//! work bounded by its charge (the actual-work meter, not wall time), or is
//! refused at once naming the limit, and every number it writes reads back.
//! Before the number-field arithmetic, each ran from 20 s to 14 minutes.

use exact_bezier::algebra::{ExactNumber, RealAlgebraic};
use exact_bezier_cli::{run_with, Outcome, Stdin};
use serde_json::Value;

/// The issue's 149-byte quadratic: one weight and one coordinate a root of
/// `x³ − x − 1`.
const QUADRATIC: &str = r#"{"kind":"curve","degree":2,"points":[[1,"7/2"],["-8/3","-17/2"],["5/6","CRootOf(x**3 - x - 1, 0)"]],"weights":[6,"CRootOf(x**3 - x - 1, 0)","13/5"]}"#;

/// A degree-1 curve with that root.
const LINE: &str = r#"{"kind":"curve","degree":1,"points":[[1,"7/2"],["5/6","CRootOf(x**3 - x - 1, 0)"]],"weights":[6,"CRootOf(x**3 - x - 1, 0)"]}"#;

/// A cubic with that root.
const CUBIC: &str = r#"{"kind":"curve","degree":3,"points":[[1,"7/2"],["-8/3","-17/2"],[2,1],["5/6","CRootOf(x**3 - x - 1, 0)"]],"weights":[6,"CRootOf(x**3 - x - 1, 0)",1,"13/5"]}"#;

/// `sqrt(` nested `depth` times around `inner`.
fn nested_sqrt(inner: &str, depth: usize) -> String {
    (0..depth).fold(inner.to_string(), |acc, _| format!("sqrt({acc})"))
}

/// A degree-1 curve from (0, `y`) to (1, 2).
fn segment_to(y: &str) -> String {
    format!(r#"{{"kind":"curve","degree":1,"points":[[0,"{y}"],[1,2]]}}"#)
}

/// Run `args` with `input` on standard input (`-`) under the default limits.
fn run(args: &[&str], input: &str) -> Outcome {
    let argv = std::iter::once("exact-bezier")
        .chain(args.iter().copied())
        .map(String::from)
        .collect();
    run_with(argv, Stdin::Bytes(input.as_bytes().to_vec()))
}

/// `run`, which must answer within its charged work, writing only numbers
/// that read back; the JSON answer.
fn answers(args: &[&str], input: &str) -> Value {
    let out = run(args, input);
    crate::common::answered_within_charge(&out, args);
    serde_json::from_str(&out.stdout).expect("JSON")
}

/// "`curvature --at 1/2`, `curvature --at 0` and `elevate --by 2` run for
/// more than two minutes; `eval --at 7/8` of a degree-1 curve more than a
/// minute; `deriv` of a cubic 14 minutes."
#[test]
fn the_cubic_root_curves_answer_within_their_charge() {
    let k = answers(&["curvature", "-", "--at", "1/2"], QUADRATIC);
    // κ² > 0 and κ = √κ², exactly: κ·κ = κ².
    let k2 = RealAlgebraic::from_text(k["curvature_squared"].as_str().unwrap()).unwrap();
    let kappa = RealAlgebraic::from_text(k["curvature"].as_str().unwrap()).unwrap();
    assert_eq!(kappa.clone() * &kappa, k2);
    answers(&["curvature", "-", "--at", "0"], QUADRATIC);
    let raised = answers(&["elevate", "-", "--by", "2"], QUADRATIC);
    // Elevation keeps the end points: the last weight is still 13/5.
    assert_eq!(raised["weights"][4], "13/5");
    let p = answers(&["eval", "-", "--at", "7/8"], LINE);
    // Independently: (1−t)·w₀·P₀ + t·w₁·P₁ over (1−t)·w₀ + t·w₁ at t = 7/8,
    // with w₁ = α: x = (6/8 + 7/8·α·5/6)/(6/8 + 7/8·α).
    let alpha = RealAlgebraic::from_text("CRootOf(x**3 - x - 1, 0)").unwrap();
    let q = |s: &str| RealAlgebraic::from_text(s).unwrap();
    let den = q("3/4") + &(q("7/8") * &alpha);
    let x = (q("3/4") + &(q("35/48") * &alpha)) / &den;
    assert_eq!(q(p["point"][0].as_str().unwrap()), x);
    answers(&["deriv", "-", "--at", "1/2"], CUBIC);
    // "eval of a cubic with that CRootOf at 2/3 writes a 10 092-character
    // number (the reader takes ≤ 10 000)".
    answers(&["eval", "-", "--at", "2/3"], CUBIC);
}

/// "a 56-character number, `sqrt(` nested 15 times around 3, makes `eval`
/// run more than 20 s"; "`sqrt` nested 7 times around 2 is written as
/// `root(2, 128)`, which the reader refuses".
#[test]
fn nested_square_roots_answer_and_read_back() {
    let deep = nested_sqrt("3", 15);
    let v = answers(&["eval", "-", "--at", "0"], &segment_to(&deep));
    assert_eq!(
        RealAlgebraic::from_text(v["point"][1].as_str().unwrap()).unwrap(),
        RealAlgebraic::from_text(&deep).unwrap()
    );
    let seven = nested_sqrt("2", 7);
    let v = answers(&["eval", "-", "--at", "0"], &segment_to(&seven));
    let written = RealAlgebraic::from_text(v["point"][1].as_str().unwrap()).unwrap();
    // 2^(1/128), independently: its 128th power is 2.
    let power = (0..7).fold(written, |x, _| x.clone() * &x);
    assert_eq!(power, RealAlgebraic::from_text("2").unwrap());
}

/// "`curvature --at 1e999 --extrapolate` writes κ with 63 940 characters":
/// now refused before the work, naming the budget and the flag.
#[test]
fn curvature_far_outside_is_refused_at_once() {
    let out = run(
        &["curvature", "-", "--at", "1e999", "--extrapolate"],
        QUADRATIC,
    );
    assert_eq!(out.code, 2, "{}", out.stdout);
    assert!(
        out.stderr.contains("over a limit") && out.stderr.contains("--max-work"),
        "{}",
        out.stderr
    );
    assert!(
        out.metered <= crate::common::METER_SLACK,
        "metered {} before refusing",
        out.metered
    );
}

/// A scrambled small integer from `seed` (a net of such numbers is of
/// full bidegree and coprime: certified minimal).
fn scrambled(seed: usize, modulus: usize) -> usize {
    seed.wrapping_mul(2_654_435_761).rotate_left(13) % modulus
}

/// A bicubic line for the bulk commands: scrambled coordinates from `k`,
/// weight `(i, j)` the JSON text `weight(i, j)`.
fn bicubic(k: usize, weight: impl Fn(usize, usize) -> String) -> String {
    let rows: Vec<String> = (0..4)
        .map(|i| {
            let p: Vec<String> = (0..4)
                .map(|j| {
                    let c = |axis: usize| scrambled(((k * 4 + i) * 4 + j) * 3 + axis, 19);
                    format!("[{},{},{}]", c(0), c(1), c(2))
                })
                .collect();
            format!("[{}]", p.join(","))
        })
        .collect();
    let weights: Vec<String> = (0..4)
        .map(|i| {
            format!(
                "[{}]",
                (0..4).map(|j| weight(i, j)).collect::<Vec<_>>().join(",")
            )
        })
        .collect();
    format!(
        r#"{{"kind":"rect","degree":[3,3],"points":[{}],"weights":[{}]}}"#,
        rows.join(","),
        weights.join(",")
    )
}

/// Issue 31: a record whose key stays in machine integers is charged that
/// path's cost whatever its bits (small weights and the `p/10⁶` weights of
/// a moved copy alike); one whose key leaves them (40-bit weights) or whose
/// numbers are beyond `i128` (60 digits) is charged the `BigRational` key
/// on top, so a stream of them is still refused, naming the record.
#[test]
fn bulk_records_are_charged_by_the_path_their_key_takes() {
    let weight = |k: usize, i: usize, j: usize| 1 + scrambled((k * 4 + i) * 4 + j, 5) as u64;
    let small = |k| bicubic(k, |i, j| weight(k, i, j).to_string());
    // `small(k)` moved by the Möbius maps 3/10 in u and 6/10 in v.
    let moved = |k| {
        bicubic(k, |i, j| {
            let mobius = 7u64.pow(i as u32)
                * 3u64.pow(3 - i as u32)
                * 4u64.pow(j as u32)
                * 6u64.pow(3 - j as u32);
            format!("\"{}/1000000\"", weight(k, i, j) * mobius)
        })
    };
    let wide = |k| {
        bicubic(k, |i, j| {
            ((1u64 << 40) - scrambled((k * 4 + i) * 4 + j, 1 << 30) as u64).to_string()
        })
    };
    let huge = |k| {
        bicubic(k, |i, j| {
            format!("\"{}{:050}\"", 1 + scrambled((k * 4 + i) * 4 + j, 9), k)
        })
    };
    let charge = |line: String| {
        let out = run(&["key", "-"], &(line + "\n"));
        assert_eq!(out.code, 0, "{}", out.stderr);
        out.work
    };
    let (s, m, w, h) = (
        charge(small(1)),
        charge(moved(1)),
        charge(wide(1)),
        charge(huge(1)),
    );
    assert_eq!(s, m, "machine keys cost the same whatever their bits");
    assert!(
        w > s + 5 * (s - exact_bezier::limits::COMMAND_WORK),
        "{w} against {s}"
    );
    assert!(h > 5 * w, "{h} against {w}");
    // A budget of about 100 huge records refuses a stream of 300 of them,
    // naming the record, and answers for 300 small ones.
    let budget = (100 * (h - exact_bezier::limits::COMMAND_WORK)).to_string();
    let lines = |f: &dyn Fn(usize) -> String| (0..300).map(f).collect::<Vec<_>>().join("\n");
    let out = run(&["--max-work", &budget, "key", "-"], &lines(&huge));
    assert_eq!(out.code, 2, "{}", out.stdout);
    assert!(
        out.stderr.contains("key (through record 9"),
        "{}",
        out.stderr
    );
    let out = run(&["--max-work", &budget, "key", "-"], &lines(&small));
    assert_eq!(out.code, 0, "{}", out.stderr);
}

/// "`dedup --max-work 1` still answers (while `coincide --max-work 1`
/// refuses)": both bulk commands now charge every record.
#[test]
fn bulk_commands_honour_the_work_budget() {
    let records = format!("{QUADRATIC}\n{LINE}\n");
    for command in ["dedup", "key"] {
        let out = run(&["--max-work", "1", command, "-"], &records);
        assert_eq!(out.code, 2, "{command}: {}", out.stdout);
        assert!(out.stderr.contains("over a limit"), "{}", out.stderr);
    }
}
