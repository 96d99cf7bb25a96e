//! Algebraic input under the work budget (issue 32), generated: curves,
//! rect and tri patches whose points and weights mix rationals with square
//! and cube roots, nested radicals and `CRootOf` roots of degree ≤ 5, and
//! `arc` arguments of the same kinds, through every command that reads
//! them, in-process (`exact_bezier_cli::run_with`) with a modest
//! `--max-work`. Every run must
//!
//! - exit 0, or refuse with one line (exit 2);
//! - be charged at most `--max-work`;
//! - when it answers, have done at most `common::METER_FACTOR` times the
//!   work it was charged, counted by the actual-work meter of the exact
//!   algebraic arithmetic (`exact_bezier::limits::meter`;
//!   [`Outcome::metered`]), plus `common::METER_SLACK` for the fixed cost
//!   of small numbers;
//! - write only numbers the reader takes back under the default limits,
//!   and, where an independent value is cheap (a patch's value at a corner
//!   is its corner control point), the right one.

use exact_bezier::algebra::{ExactNumber, RealAlgebraic};
use exact_bezier_cli::{run_with, Outcome, Stdin};
use proptest::prelude::*;
use serde_json::{json, Value};

/// The work budget of every generated run.
const CASE_WORK: u64 = 2_000_000;

/// Generated cases (each runs about a dozen commands).
const CASES: u32 = 8;

/// Polynomials with their number of real roots, for `CRootOf(p, k)`.
const POLYS: [(&str, usize); 6] = [
    ("x**2 - 3", 2),
    ("x**3 - x - 1", 1),
    ("x**3 - 3*x + 1", 3),
    ("x**4 - 10*x**2 + 1", 4),
    ("x**5 - x - 1", 1),
    ("x**5 - 4*x + 2", 3),
];

/// An irrational atom: a square or cube root, a nested radical of up to
/// three levels, or a `CRootOf` of degree ≤ 5. Every atom is positive.
fn atom() -> impl Strategy<Value = String> {
    let small = 2u32..12;
    prop_oneof![
        small.clone().prop_map(|k| format!("sqrt({k})")),
        small.clone().prop_map(|k| format!("cbrt({k})")),
        (small.clone(), 1u32..4, 1u32..4).prop_map(|(k, a, levels)| {
            (0..levels).fold(format!("{k}"), |acc, _| format!("sqrt({a} + {acc})"))
        }),
        (0..POLYS.len(), 0usize..5).prop_map(|(i, k)| {
            let (p, count) = POLYS[i];
            // The largest real root of each polynomial is positive.
            format!("CRootOf({p}, {})", count - 1 - k % count)
        }),
    ]
}

/// A small positive rational.
fn positive_rational() -> impl Strategy<Value = String> {
    (1i64..9, 1i64..5).prop_map(|(p, q)| format!("{p}/{q}"))
}

/// A number over the case's atoms: rational, `q·atom` or `q + atom`, with
/// a sign when `signed`.
fn number(atoms: Vec<String>, signed: bool) -> impl Strategy<Value = String> {
    let n = atoms.len();
    (0..4usize, 0..n, positive_rational(), any::<bool>()).prop_map(move |(form, i, q, negative)| {
        let a = &atoms[i];
        let text = match form {
            0 => q,
            1 => format!("{q}*{a}"),
            _ => format!("{q} + {a}"),
        };
        if signed && negative {
            format!("-({text})")
        } else {
            text
        }
    })
}

/// The shape of a generated patch.
#[derive(Clone, Copy, Debug)]
enum Shape {
    Curve(usize),
    Rect(usize, usize),
    Tri(usize),
}

impl Shape {
    fn points(self) -> usize {
        match self {
            Shape::Curve(n) => n + 1,
            Shape::Rect(m, n) => (m + 1) * (n + 1),
            Shape::Tri(n) => (n + 1) * (n + 2) / 2,
        }
    }
}

fn shape() -> impl Strategy<Value = Shape> {
    prop_oneof![
        3 => (1usize..4).prop_map(Shape::Curve),
        2 => (1usize..3, 1usize..3).prop_map(|(m, n)| Shape::Rect(m, n)),
        1 => (1usize..3).prop_map(Shape::Tri),
    ]
}

/// A patch: its JSON and its first control point (Cartesian coordinates,
/// text): the value at `t = 0` (curve), `(u, v) = (0, 0)` (rect, tri).
#[derive(Clone, Debug)]
struct Case {
    json: Value,
    shape: Shape,
    first: Vec<String>,
}

fn case() -> impl Strategy<Value = Case> {
    (proptest::collection::vec(atom(), 1..3), shape(), 2usize..4).prop_flat_map(
        |(atoms, shape, dim)| {
            let count = shape.points();
            (
                proptest::collection::vec(
                    proptest::collection::vec(number(atoms.clone(), true), dim),
                    count,
                ),
                proptest::collection::vec(number(atoms, false), count),
            )
                .prop_map(move |(points, weights)| {
                    let first = points[0].clone();
                    let json = match shape {
                        Shape::Curve(n) => json!({
                            "kind": "curve", "degree": n, "points": points, "weights": weights,
                        }),
                        Shape::Rect(m, n) => json!({
                            "kind": "rect", "degree": [m, n],
                            "points": grid(&points, n), "weights": grid(&weights, n),
                        }),
                        Shape::Tri(n) => json!({
                            "kind": "tri", "degree": n,
                            "points": tri_rows(&points, n), "weights": tri_rows(&weights, n),
                        }),
                    };
                    Case { json, shape, first }
                })
        },
    )
}

/// Rows of `n + 1` entries (a rect's `points[i][j]`).
fn grid<T: Clone>(v: &[T], n: usize) -> Vec<Vec<T>> {
    v.chunks(n + 1).map(<[T]>::to_vec).collect()
}

/// A tri patch's rows: row `j` holds `n − j + 1` entries.
fn tri_rows<T: Clone>(v: &[T], n: usize) -> Vec<Vec<T>> {
    let mut rest = v;
    (0..=n)
        .map(|j| {
            let (row, tail) = rest.split_at(n - j + 1);
            rest = tail;
            row.to_vec()
        })
        .collect()
}

/// Run `args` in-process with `--max-work CASE_WORK` and check the
/// budget's promises; the outcome.
fn run(args: &[&str]) -> Outcome {
    let work = CASE_WORK.to_string();
    let argv = ["exact-bezier", "--max-work", &work]
        .iter()
        .chain(args)
        .map(ToString::to_string)
        .collect();
    let out = run_with(argv, Stdin::Bytes(Vec::new()));
    assert!(
        out.code == 0 || (out.code == 2 && out.stderr.lines().count() == 1),
        "{args:?}: exit {} {}",
        out.code,
        out.stderr
    );
    assert!(out.work <= CASE_WORK, "{args:?}: charged {}", out.work);
    if out.code == 0 {
        crate::common::answered_within_charge(&out, args);
    }
    out
}

/// The exact value of a written number (JSON number or string).
fn value(v: &Value) -> RealAlgebraic {
    match v {
        Value::String(s) => RealAlgebraic::from_text(s).expect("read back"),
        other => RealAlgebraic::from_text(&other.to_string()).expect("a number"),
    }
}

/// The commands that take `case`'s patch (in file `path`), with the
/// parameters its kind needs.
fn commands(case: &Case, path: &str) -> Vec<Vec<String>> {
    let s = |v: &[&str]| v.iter().map(ToString::to_string).collect::<Vec<_>>();
    let mut out = vec![
        s(&["key", path]),
        s(&["dedup", path]),
        s(&["coincide", path, path]),
    ];
    match case.shape {
        Shape::Curve(_) => out.extend([
            s(&["eval", path, "--at", "1/3"]),
            s(&["deriv", path, "--at", "1/2"]),
            s(&["curvature", path, "--at", "1/2"]),
            s(&["elevate", path, "--by", "1"]),
            s(&["reparam", path, "--mobius", "1/3"]),
            s(&["reparam", path, "--mobius", "sqrt(2)/2"]),
            s(&["reparam", path, "--quadratic", "1/3,1/2,1/4"]),
            s(&["standardize", path]),
            s(&["is-circle", path]),
            s(&["reduce", path]),
            s(&["join", path, path]),
        ]),
        Shape::Rect(..) => out.extend([
            s(&["eval", path, "--at", "1/3,1/2"]),
            s(&["deriv", path, "--at", "1/2,1/3"]),
            s(&["elevate", path, "--by", "1,0"]),
            s(&[
                "reparam",
                path,
                "--mobius",
                "1/3,CRootOf(x**3 - x - 1, 0)/2",
            ]),
            s(&["convert", path, "--to", "tri"]),
            s(&["standardize", path]),
        ]),
        Shape::Tri(_) => out.extend([
            s(&["eval", path, "--at", "1/4,1/4"]),
            s(&["elevate", path, "--by", "1"]),
            s(&["convert", path, "--to", "rect"]),
        ]),
    }
    out
}

/// The value at the corner of the first control point: `eval` there gives
/// that point, exactly (checked when the command answers).
fn corner_is_first_point(case: &Case, path: &str) {
    // `points[0][0]` sits at (u, v) = (0, 0) for a rect and a tri patch.
    let at = match case.shape {
        Shape::Curve(_) => "0",
        Shape::Rect(..) | Shape::Tri(_) => "0,0",
    };
    let out = run(&["eval", path, "--at", at]);
    if out.code != 0 {
        return;
    }
    let v: Value = serde_json::from_str(&out.stdout).unwrap();
    let point = v["point"].as_array().expect("a point");
    let want: Vec<RealAlgebraic> = case
        .first
        .iter()
        .map(|t| RealAlgebraic::from_text(t).unwrap())
        .collect();
    let got: Vec<RealAlgebraic> = point.iter().map(value).collect();
    assert_eq!(got, want, "eval {path} --at {at}");
}

/// `arc` arguments: a centre angle with a known control triangle (points
/// scaled by a generated positive number) and a λ near 0.
fn arc_args() -> impl Strategy<Value = [String; 3]> {
    let triangles = [
        ("1/2", "1,0;1,sqrt(3);-1/2,sqrt(3)/2"),
        ("sqrt(2)/2", "1,0;1,1;0,1"),
        ("sqrt(3)/2", "1,0;1,sqrt(3)/3;1/2,sqrt(3)/2"),
    ];
    (
        0..triangles.len(),
        proptest::collection::vec(atom(), 1..2),
        any::<bool>(),
        (1i64..5, 10i64..40),
    )
        .prop_flat_map(move |(i, atoms, scale, (p, q))| {
            let (c, pts) = triangles[i];
            (
                number(atoms.clone(), false),
                number(atoms, true),
                Just((c, pts, scale, p, q)),
            )
        })
        .prop_map(|(factor, lambda_atom, (c, pts, scale, p, q))| {
            let points = if scale {
                pts.split(';')
                    .map(|pt| {
                        pt.split(',')
                            .map(|x| format!("({x})*({factor})"))
                            .collect::<Vec<_>>()
                            .join(",")
                    })
                    .collect::<Vec<_>>()
                    .join(";")
            } else {
                pts.to_string()
            };
            let lambda = format!("({lambda_atom})*{p}/{}", q * 10);
            [c.to_string(), lambda, points]
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// Every command on a generated algebraic patch answers or refuses in
    /// one line, within its charged budget counted by work.
    #[test]
    fn algebraic_patches_stay_within_their_charged_work(case in case()) {
        let dir = std::env::temp_dir().join(format!("eb-alg-budget-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join(format!("{:x}.json", fxhash(&case.json.to_string())));
        std::fs::write(&file, case.json.to_string()).unwrap();
        let path = file.to_str().unwrap();
        for args in commands(&case, path) {
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            run(&args);
        }
        corner_is_first_point(&case, path);
        std::fs::remove_file(&file).ok();
    }

    /// `arc` with generated algebraic arguments: answers or refuses in one
    /// line within its charged work; what it writes reads back.
    #[test]
    fn algebraic_arcs_stay_within_their_charged_work(args in arc_args()) {
        let [c, lambda, points] = args;
        let (c, lambda, points) = (
            format!("--cos-half={c}"),
            format!("--lambda={lambda}"),
            format!("--points={points}"),
        );
        run(&["arc", &c, &lambda, &points]);
    }
}

/// A file name for a case (FNV-1a of its text).
fn fxhash(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}
