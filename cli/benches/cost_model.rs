//! The calibration of the cost model (docs/limits.md, "The cost model";
//! issue 32): runs 40-odd commands in-process through
//! [`exact_bezier_cli::run_with`] — every command that charges work, every
//! shape (curves, rect and tri patches of degree 1–64), rational and
//! algebraic numbers, `standardize` with Möbius and quadratic maps,
//! `coincide`, `dedup`, `key`, `intersect` exact and filtered, `audit`
//! and STEP reading — and prints the work units each is charged against
//! its measured time.
//!
//! Run it on the release build (`cargo bench` builds with the `bench`
//! profile, which inherits `release`):
//!
//! ```text
//! cargo bench -p exact-bezier-cli --bench cost_model
//! ```
//!
//! Time is the least CPU time (all threads) of several runs (the machine
//! is shared: CPU time is stretched less than wall time by neighbours, and
//! the least run is the one least disturbed). Each row prints `ns/unit`; the
//! summary gives the geometric mean of `ns/unit` over the rows and each
//! row's factor from it, and says whether every row is within a factor of
//! 4 — the promise of docs/limits.md. The process exits 1 when a row is
//! not, so the benchmark is also a check (never a timed test of CI).

use exact_bezier_cli::{run_with, Outcome, Stdin};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The factor every row must keep from the geometric mean (docs/limits.md).
const FACTOR: f64 = 4.0;

/// A budget no row reaches: nothing is refused while measuring.
const NO_LIMIT: &str = "1000000000000000000";

/// Measuring one row stops after this much time spent on it (at least
/// [`MIN_RUNS`] runs, at most [`MAX_RUNS`]).
const TIME_PER_ROW: Duration = Duration::from_millis(1500);
const MIN_RUNS: usize = 2;
const MAX_RUNS: usize = 7;

/// A small deterministic generator (a linear congruential sequence): the
/// nets are the same on every run.
struct Numbers(u64);

impl Numbers {
    /// An integer in `lo..=hi`.
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        lo + ((self.0 >> 33) % (hi - lo + 1) as u64) as i64
    }

    /// A point of `dim` integer coordinates in -9..=9, as JSON.
    fn point(&mut self, dim: usize) -> String {
        let c: Vec<String> = (0..dim).map(|_| self.int(-9, 9).to_string()).collect();
        format!("[{}]", c.join(","))
    }

    /// A weight: an integer 1..=5, or (every third, when `algebraic`) one
    /// of a few square and cube roots.
    fn weight(&mut self, algebraic: bool) -> String {
        const ROOTS: [&str; 4] = [
            "\"sqrt(2)\"",
            "\"cbrt(3)\"",
            "\"1+sqrt(5)\"",
            "\"sqrt(3)/2\"",
        ];
        let k = self.int(1, 5);
        if algebraic && k % 3 == 0 {
            ROOTS[self.int(0, 3) as usize].to_string()
        } else {
            k.to_string()
        }
    }
}

/// The JSON array of arrays of `rows` (each a list of JSON texts).
fn rows_json(rows: &[Vec<String>]) -> String {
    let inner: Vec<String> = rows.iter().map(|r| format!("[{}]", r.join(","))).collect();
    format!("[{}]", inner.join(","))
}

/// A curve of degree `n` in dimension `dim`.
fn curve(g: &mut Numbers, n: usize, dim: usize, algebraic: bool) -> String {
    let points: Vec<String> = (0..=n).map(|_| g.point(dim)).collect();
    let weights: Vec<String> = (0..=n).map(|_| g.weight(algebraic)).collect();
    format!(
        "{{\"kind\":\"curve\",\"degree\":{n},\"points\":[{}],\"weights\":[{}]}}",
        points.join(","),
        weights.join(",")
    )
}

/// A rect patch of bidegree `(m, n)` in dimension 3.
fn rect(g: &mut Numbers, m: usize, n: usize, algebraic: bool) -> String {
    rect_weighted(g, m, n, |g, _, _| g.weight(algebraic))
}

/// A rect patch of bidegree `(m, n)` in dimension 3 whose weight `(i, j)`
/// is `weight(g, i, j)` (JSON text).
fn rect_weighted(
    g: &mut Numbers,
    m: usize,
    n: usize,
    mut weight: impl FnMut(&mut Numbers, usize, usize) -> String,
) -> String {
    let points = (0..=m)
        .map(|_| (0..=n).map(|_| g.point(3)).collect())
        .collect();
    let weights = (0..=m)
        .map(|i| (0..=n).map(|j| weight(g, i, j)).collect())
        .collect();
    net("rect", &format!("[{m},{n}]"), points, weights)
}

/// A bicubic whose weights are those of a random integer bicubic moved by
/// Möbius maps `A/10`, `B/10` and scaled by `k`, as
/// `benches/make_dedup_input.py` writes its copies:
/// `w k (10−A)^i A^(3−i) (10−B)^j B^(3−j) / 10⁶` (numbers of up to 48 bits
/// that the key reduces: its machine path, near its top).
fn moved_bicubic(g: &mut Numbers) -> String {
    let (a, b, k) = (g.int(1, 9), g.int(1, 9), g.int(1, 5));
    rect_weighted(g, 3, 3, |g, i, j| {
        let pow = |x: i64, e: usize| x.pow(e as u32);
        let w = g.int(1, 9) * k * pow(10 - a, i) * pow(a, 3 - i) * pow(10 - b, j) * pow(b, 3 - j);
        format!("\"{w}/1000000\"")
    })
}

/// A tri patch of degree `n` in dimension 3 (row `i` has `n + 1 − i`
/// entries).
fn tri(g: &mut Numbers, n: usize) -> String {
    let points = (0..=n)
        .map(|i| (0..=n - i).map(|_| g.point(3)).collect())
        .collect();
    let weights = (0..=n)
        .map(|i| (0..=n - i).map(|_| g.weight(false)).collect())
        .collect();
    net("tri", &n.to_string(), points, weights)
}

/// A patch object of `kind` from its rows of points and weights.
fn net(kind: &str, degree: &str, points: Vec<Vec<String>>, weights: Vec<Vec<String>>) -> String {
    let (p, w) = (rows_json(&points), rows_json(&weights));
    format!("{{\"kind\":\"{kind}\",\"degree\":{degree},\"points\":{p},\"weights\":{w}}}")
}

/// One measured row.
struct Row {
    command: String,
    input: String,
    units: u64,
    seconds: f64,
}

impl Row {
    fn ns_per_unit(&self) -> f64 {
        self.seconds * 1e9 / self.units.max(1) as f64
    }
}

/// The benchmark's files and results.
struct Bench {
    dir: PathBuf,
    fixtures: PathBuf,
    rows: Vec<Row>,
}

impl Bench {
    /// Write `text` to the scratch file `name`; its path.
    fn file(&self, name: &str, text: &str) -> String {
        let path = self.dir.join(name);
        std::fs::write(&path, text).expect("the scratch directory is writable");
        path.display().to_string()
    }

    /// The path of a repository fixture (`tests/fixtures/…`).
    fn fixture(&self, name: &str) -> String {
        self.fixtures.join(name).display().to_string()
    }

    /// Run `args` (without the program name) until [`TIME_PER_ROW`] is
    /// spent, keep the least time, and record the row.
    fn row(&mut self, command: &str, input: &str, args: &[&str]) {
        let mut full = vec![
            "exact-bezier".to_string(),
            "--max-work".into(),
            NO_LIMIT.into(),
        ];
        full.extend(args.iter().map(|a| a.to_string()));
        let mut best = f64::INFINITY;
        let mut units = 0;
        let mut out_bytes = 0;
        let started = Instant::now();
        for run in 0..MAX_RUNS {
            let t = cpu_seconds();
            let out: Outcome = run_with(full.clone(), Stdin::Bytes(Vec::new()));
            let seconds = cpu_seconds() - t;
            assert!(
                out.code == 0 || out.code == 3,
                "{command} {input}: exit {} {}",
                out.code,
                out.stderr
            );
            std::hint::black_box(&out.stdout);
            best = best.min(seconds);
            units = out.work;
            out_bytes = out.stdout.len();
            if run + 1 >= MIN_RUNS && started.elapsed() > TIME_PER_ROW {
                break;
            }
        }
        let row = Row {
            command: command.into(),
            input: input.into(),
            units,
            seconds: best,
        };
        eprintln!(
            "{:<28} {:<44} {:>9} B in {:>9} B out {:>10.3e} units {:>10.4} s {:>8.3} ns/unit",
            row.command,
            row.input,
            args.iter()
                .filter_map(|a| std::fs::metadata(a).ok())
                .map(|m| m.len())
                .sum::<u64>(),
            out_bytes,
            row.units as f64,
            row.seconds,
            row.ns_per_unit()
        );
        self.rows.push(row);
    }
}

/// The CPU time of this process so far, all its threads (the rayon pool
/// of the bulk commands included), in seconds: `CLOCK_PROCESS_CPUTIME_ID`.
/// CPU time, not wall time: the machine is shared, and a busy neighbour
/// stretches the wall time of a run much more than its CPU time.
fn cpu_seconds() -> f64 {
    let mut t = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: `t` is a valid, writable timespec for the call's duration.
    let status = unsafe { libc::clock_gettime(libc::CLOCK_PROCESS_CPUTIME_ID, &mut t) };
    assert_eq!(status, 0, "the process CPU clock is readable");
    t.tv_sec as f64 + t.tv_nsec as f64 * 1e-9
}

/// The load averages of the machine (`/proc/loadavg`), for the report.
fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "unknown".into())
}

fn main() {
    let dir = std::env::temp_dir().join(format!("exact-bezier-cost-model-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    let fixtures = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/fixtures");
    let mut b = Bench {
        dir,
        fixtures,
        rows: Vec::new(),
    };
    let load_before = load_average();
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    measure(&mut b);
    report(&b, threads, &load_before);
    let _ = std::fs::remove_dir_all(&b.dir);
    let worst = b
        .rows
        .iter()
        .map(|r| spread(&b.rows, r))
        .fold(1.0, f64::max);
    if worst > FACTOR {
        std::process::exit(1);
    }
}

/// Every row of the calibration.
fn measure(b: &mut Bench) {
    let g = &mut Numbers(32);
    let out_obj = b.dir.join("mesh.obj").display().to_string();

    // Curves: evaluation, derivatives, curvature, maps, elevation.
    let c1 = b.file("c1.json", &curve(g, 1, 3, false));
    let c3 = b.file("c3.json", &curve(g, 3, 2, false));
    let c8 = b.file("c8.json", &curve(g, 8, 3, false));
    let c32 = b.file("c32.json", &curve(g, 32, 3, false));
    let c64 = b.file("c64.json", &curve(g, 64, 3, false));
    let c3a = b.file("c3a.json", &curve(g, 3, 3, true));
    let c8a = b.file("c8a.json", &curve(g, 8, 3, true));
    b.row("eval", "curve n=1, d=3", &["eval", &c1, "--at", "1/3"]);
    b.row("eval", "curve n=8, d=3", &["eval", &c8, "--at", "1/3"]);
    b.row("eval", "curve n=64, d=3", &["eval", &c64, "--at", "1/3"]);
    b.row(
        "eval --grid 1000",
        "curve n=32, d=3",
        &["eval", &c32, "--grid", "1000"],
    );
    b.row(
        "eval",
        "curve n=3, sqrt/cbrt weights",
        &["eval", &c3a, "--at", "1/3"],
    );
    b.row(
        "eval",
        "curve n=8, sqrt/cbrt weights",
        &["eval", &c8a, "--at", "1/3"],
    );
    b.row(
        "eval --scalar f64",
        "curve n=64, d=3",
        &["eval", &c64, "--at", "1/3", "--scalar", "f64"],
    );
    b.row(
        "deriv --order 3",
        "curve n=32, d=3",
        &["deriv", &c32, "--order", "3", "--at", "1/3"],
    );
    b.row(
        "curvature",
        "curve n=32, d=3",
        &["curvature", &c32, "--at", "1/3"],
    );
    b.row(
        "reparam --mobius",
        "curve n=32, d=3",
        &["reparam", &c32, "--mobius", "1/3"],
    );
    b.row(
        "elevate --by 32",
        "curve n=32, d=3",
        &["elevate", &c32, "--by", "32"],
    );
    b.row("reduce", "curve n=32, d=3", &["reduce", &c32]);
    b.row("join", "curves n=32, n=64", &["join", &c32, &c64]);
    let arc = b.file(
        "arc.json",
        r#"{"kind":"curve","degree":2,"points":[["3/5","-4/5"],["5/3",0],["3/5","4/5"]],"weights":[1,"3/5",1]}"#,
    );
    b.row(
        "is-circle",
        "circular arc, cos θ = 3/5",
        &["is-circle", &arc],
    );
    b.row("is-circle", "curve n=32, d=3", &["is-circle", &c32]);

    // Rect patches.
    let r1 = b.file("r1.json", &rect(g, 1, 1, false));
    let r4 = b.file("r4.json", &rect(g, 4, 4, false));
    let r8 = b.file("r8.json", &rect(g, 8, 8, false));
    let r16 = b.file("r16.json", &rect(g, 16, 16, false));
    let r32 = b.file("r32.json", &rect(g, 32, 32, false));
    let r64 = b.file("r64.json", &rect(g, 64, 64, false));
    let r3a = b.file("r3a.json", &rect(g, 3, 3, true));
    b.row("eval", "rect (1,1)", &["eval", &r1, "--at", "1/3,2/7"]);
    b.row("eval", "rect (8,8)", &["eval", &r8, "--at", "1/3,2/7"]);
    b.row("eval", "rect (32,32)", &["eval", &r32, "--at", "1/3,2/7"]);
    b.row("eval", "rect (64,64)", &["eval", &r64, "--at", "1/3,2/7"]);
    b.row(
        "eval",
        "rect (3,3), sqrt/cbrt weights",
        &["eval", &r3a, "--at", "1/3,2/7"],
    );
    b.row(
        "reparam --mobius",
        "rect (16,16)",
        &["reparam", &r16, "--mobius", "1/3,2/5"],
    );
    b.row(
        "reparam --quadratic",
        "rect (8,8)",
        &["reparam", &r8, "--quadratic", "1/3,2/5,1/4,3/4"],
    );
    b.row(
        "elevate --by 16,16",
        "rect (16,16)",
        &["elevate", &r16, "--by", "16,16"],
    );
    b.row(
        "convert --to tri",
        "rect (8,8)",
        &["convert", &r8, "--to", "tri"],
    );
    b.row(
        "mesh --density 32",
        "rect (4,4), exact",
        &[
            "mesh",
            &r4,
            "-o",
            &out_obj,
            "--density",
            "32",
            "--scalar",
            "exact",
        ],
    );
    b.row(
        "mesh --density 256",
        "rect (8,8), f64",
        &["mesh", &r8, "-o", &out_obj, "--density", "256"],
    );
    let out_svg = b.dir.join("plot.svg").display().to_string();
    let out_png = b.dir.join("plot.png").display().to_string();
    b.row("plot (SVG)", "rect (8,8)", &["plot", &r8, "-o", &out_svg]);
    b.row("plot (PNG)", "rect (8,8)", &["plot", &r8, "-o", &out_png]);
    b.row(
        "plot (SVG)",
        "curve n=64, d=3",
        &["plot", &c64, "-o", &out_svg],
    );

    // Tri patches.
    let t1 = b.file("t1.json", &tri(g, 1));
    let t8 = b.file("t8.json", &tri(g, 8));
    let t64 = b.file("t64.json", &tri(g, 64));
    b.row("eval", "tri n=1", &["eval", &t1, "--at", "1/3,1/5"]);
    b.row("eval", "tri n=64", &["eval", &t64, "--at", "1/3,1/5"]);
    b.row(
        "convert --to rect",
        "tri n=8",
        &["convert", &t8, "--to", "rect"],
    );

    // standardize: Möbius maps (curves, rects of Theorem 1) and the
    // quadratic map (source 000's examples).
    let c4 = b.file("c4.json", &curve(g, 4, 3, false));
    let r2 = b.file("r2.json", &rect(g, 2, 2, false));
    b.row(
        "standardize (Möbius)",
        "curve n=4, d=3",
        &["standardize", &c4],
    );
    b.row(
        "standardize (Möbius)",
        "curve n=8, d=3",
        &["standardize", &c8],
    );
    b.row(
        "standardize",
        "rect (2,2) random weights",
        &["standardize", &r2],
    );
    for k in 1..=3 {
        let name = format!("yang_yong_example{k}.json");
        let label = format!("source 000 Example {k}");
        b.row("standardize", &label, &["standardize", &b.fixture(&name)]);
    }

    // Trigonometric patches (source 002) and circular arcs (source 004).
    let bowl = b.fixture("bowl.json");
    b.row(
        "eval (trig)",
        "bowl.json, 4 trig-rects",
        &["eval", &bowl, "--at", "1/3,1/5"],
    );
    b.row(
        "convert --to rational",
        "bowl.json, 4 trig-rects",
        &["convert", &bowl, "--to", "rational"],
    );
    b.row(
        "arc",
        "cos θ/2 = 3/5, λ = 0",
        &[
            "arc",
            "--cos-half",
            "3/5",
            "--lambda",
            "0",
            "--points",
            "1,0;1,4/3;-7/25,24/25",
        ],
    );
    b.row(
        "arc",
        "cos θ/2 = √2/2, λ = 1/10",
        &[
            "arc",
            "--cos-half",
            "sqrt(2)/2",
            "--lambda",
            "1/10",
            "--points",
            "1,0;1,1;0,1",
        ],
    );

    // Coincidence, canonical keys, bulk.
    let r16e = elevated_copy(b, &r8, "r8e.json");
    b.row(
        "coincide",
        "rect (8,8) vs its (16,16) copy",
        &["coincide", &r8, &r16e],
    );
    b.row(
        "coincide --filtered",
        "rect (8,8) vs rect (8,8)",
        &["coincide", &r8, &r8, "--filtered"],
    );
    b.row(
        "coincide",
        "curve n=3 sqrt/cbrt vs itself",
        &["coincide", &c3a, &c3a],
    );
    let bulk: Vec<String> = (0..2000).map(|_| rect(g, 3, 3, false)).collect();
    let bulk_file = b.file("bulk.jsonl", &(bulk.join("\n") + "\n"));
    b.row("key", "2000 random rects (3,3)", &["key", &bulk_file]);
    b.row("dedup", "2000 random rects (3,3)", &["dedup", &bulk_file]);
    let moved: Vec<String> = (0..2000).map(|_| moved_bicubic(g)).collect();
    let moved_file = b.file("moved.jsonl", &(moved.join("\n") + "\n"));
    b.row(
        "key",
        "2000 moved rects (3,3), p/10⁶",
        &["key", &moved_file],
    );
    // Weights of 40 bits: the invariants leave i128, the key is over BigRational.
    let wide: Vec<String> = (0..300)
        .map(|_| rect_weighted(g, 3, 3, |g, _, _| g.int(1, 1 << 40).to_string()))
        .collect();
    let wide_file = b.file("wide.jsonl", &(wide.join("\n") + "\n"));
    b.row(
        "key",
        "300 rects (3,3), 40-bit weights",
        &["key", &wide_file],
    );
    // Weights of 60 digits: beyond i128, read by the general reader.
    let huge: Vec<String> = (0..100)
        .map(|_| {
            rect_weighted(g, 3, 3, |g, _, _| {
                let digits: String = (0..6)
                    .map(|_| g.int(1_000_000_000, 9_999_999_999).to_string())
                    .collect();
                format!("\"{digits}\"")
            })
        })
        .collect();
    let huge_file = b.file("huge.jsonl", &(huge.join("\n") + "\n"));
    b.row(
        "key",
        "100 rects (3,3), 60-digit weights",
        &["key", &huge_file],
    );
    let copies: Vec<String> = (0..200)
        .map(|_| std::fs::read_to_string(&r16e).expect("written"))
        .map(|s| s.replace('\n', ""))
        .collect();
    let copies_file = b.file("copies.jsonl", &(copies.join("\n") + "\n"));
    b.row(
        "dedup",
        "200 copies of an elevated (16,16)",
        &["dedup", &copies_file],
    );
    let few_copies = b.file("copies20.jsonl", &(copies[..20].join("\n") + "\n"));
    b.row(
        "dedup --witness",
        "20 copies of an elevated (16,16)",
        &["dedup", &few_copies, "--witness"],
    );
    let alg: Vec<String> = (0..50).map(|_| rect(g, 2, 2, true)).collect();
    let alg_file = b.file("alg.jsonl", &(alg.join("\n") + "\n"));
    b.row(
        "dedup",
        "50 rects (2,2), sqrt/cbrt weights",
        &["dedup", &alg_file],
    );

    // Intersections.
    let c6 = b.file("c6.json", &curve(g, 6, 2, false));
    let c6b = b.file("c6b.json", &curve(g, 6, 2, false));
    let c3b = b.file("c3b.json", &curve(g, 3, 2, false));
    b.row("intersect", "two planar cubics", &["intersect", &c3, &c3b]);
    b.row(
        "intersect",
        "two planar curves n=6",
        &["intersect", &c6, &c6b],
    );
    b.row(
        "intersect --filtered",
        "two planar curves n=6",
        &["intersect", &c6, &c6b, "--filtered"],
    );
    b.row(
        "intersect --scalar f64",
        "two planar curves n=6",
        &["intersect", &c6, &c6b, "--scalar", "f64"],
    );

    // STEP reading and audit.
    for step in ["wavy-cube.stp", "red_cube_blue_cylinder.step", "ANC101.stp"] {
        let path = b.fixture(&format!("step/{step}"));
        b.row(
            "convert --to bezier",
            &format!("STEP {step}"),
            &["convert", &path, "--to", "bezier"],
        );
        b.row(
            "audit",
            &format!("STEP {step}"),
            &["audit", &path, "--summary"],
        );
    }
    b.row(
        "audit",
        "teapot.json (patch model)",
        &["audit", &b.fixture("teapot.json"), "--summary"],
    );
}

/// `elevate --by 8,8` of the rect in `path`, written to `name`.
fn elevated_copy(b: &Bench, path: &str, name: &str) -> String {
    let args = ["exact-bezier", "elevate", path, "--by", "8,8"]
        .map(String::from)
        .to_vec();
    let out = run_with(args, Stdin::Bytes(Vec::new()));
    assert_eq!(out.code, 0, "{}", out.stderr);
    b.file(name, &out.stdout)
}

/// Row `r`'s factor from the geometric mean of `ns/unit` over `rows`
/// (≥ 1 either way).
fn spread(rows: &[Row], r: &Row) -> f64 {
    let mean = geometric_mean(rows);
    let f = r.ns_per_unit() / mean;
    f.max(1.0 / f)
}

fn geometric_mean(rows: &[Row]) -> f64 {
    let logs: f64 = rows.iter().map(|r| r.ns_per_unit().ln()).sum();
    (logs / rows.len() as f64).exp()
}

/// The table (Markdown, as docs/limits.md carries it) and the summary.
fn report(b: &Bench, threads: usize, load_before: &str) {
    let mean = geometric_mean(&b.rows);
    let mut t = String::new();
    let _ = writeln!(t, "| command | input | units | time | ns/unit | factor |");
    let _ = writeln!(t, "| --- | --- | ---: | ---: | ---: | ---: |");
    for r in &b.rows {
        let f = r.ns_per_unit() / mean;
        let _ = writeln!(
            t,
            "| `{}` | {} | {:.2e} | {} | {:.2} | {}{:.2} |",
            r.command,
            r.input,
            r.units as f64,
            seconds(r.seconds),
            r.ns_per_unit(),
            if f >= 1.0 { "×" } else { "÷" },
            f.max(1.0 / f)
        );
    }
    let worst = b
        .rows
        .iter()
        .map(|r| spread(&b.rows, r))
        .fold(1.0, f64::max);
    let (lo, hi) = b
        .rows
        .iter()
        .map(Row::ns_per_unit)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
    print!("{t}");
    println!();
    println!(
        "{} rows; {threads} threads; load average {load_before} before, {} after",
        b.rows.len(),
        load_average()
    );
    println!(
        "geometric mean {mean:.3} ns/unit; spread max/min {:.1}; the worst row is {worst:.2}× off the mean: {}",
        hi / lo,
        if worst <= FACTOR {
            "every row within a factor of 4"
        } else {
            "NOT every row within a factor of 4"
        }
    );
}

/// A time as `12.3 ms` or `1.23 s`.
fn seconds(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.0} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.1} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}
