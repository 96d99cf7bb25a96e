//! The GMP side of `benches/peers/arith` (issue 30): exact evaluation of the
//! same rational Bézier nets at the same parameters by exact-bezier's exact
//! kernel ([`Evaluator`] on `BigRational`) and by a fraction-free
//! Horner–Bernstein scheme on rug's `Integer` (GMP 6): every homogeneous
//! coordinate on one integer denominator per net (set up once, like ours),
//! per point an integer homogeneous Horner sum in the parameter's numerator
//! and denominator, then one `Rational` (one gcd) per coordinate. Every
//! result is checked identical to ours as text; a mismatch aborts.
//!
//! ```text
//! cargo run --release --manifest-path benches/peers/gmp/Cargo.toml -- [--points 256] [--repeat 7] [--only TEXT]
//! ```
//!
//! Then our Lehmer gcd against `mpz_gcd` on operands of 64 to 1 024 bits,
//! the coincidence key ([`key`]) of cubic curves and bicubics, and the
//! root isolation step of intersections ([`roots`]).
//! Prints a table on standard error and one JSON line on standard output:
//! `{"exact_vs_gmp": worst ours/GMP, "cases": {name: {"ours_ns", "gmp_ns", "ratio"}},
//! "gcd_vs_gmp": worst, "gcd": {…}, "key_vs_gmp": worst, "key": {…},
//! "roots_vs_gmp": worst, "roots": {…}}`, nanoseconds per point (per gcd,
//! per key, per polynomial), the best of `--repeat` passes
//! over the batch (the two sides alternately).
//! `--only TEXT` runs the evaluation, key and root cases whose name
//! contains `TEXT` (the gcd rows always run).

use exact_bezier::algebra::parse_rational;
use exact_bezier::eval::Evaluator;
use exact_bezier::io::read_patches;
use exact_bezier::Patch;
use num_bigint::BigUint;
use num_rational::BigRational;
use rug::{Integer, Rational};
use serde_json::{json, Map, Value};
use std::time::Instant;

mod key;
mod roots;

/// A 64-bit linear congruential generator: the same inputs on every run.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }

    /// `n` decimal digits, the first non-zero.
    fn digits(&mut self, n: usize) -> String {
        (0..n)
            .map(|k| {
                let d = (self.next() % 10) as u8;
                char::from(b'0' + if k == 0 { d % 9 + 1 } else { d })
            })
            .collect()
    }

    /// A signed decimal of `n` significant digits, four after the point.
    fn coordinate(&mut self, n: usize) -> String {
        let sign = if self.next().is_multiple_of(2) {
            ""
        } else {
            "-"
        };
        format!("{sign}{}/10000", self.digits(n))
    }

    /// A positive weight: a ratio of two 4-digit integers.
    fn weight(&mut self) -> String {
        format!("{}/{}", self.digits(4), self.digits(4))
    }

    /// A parameter in (0, 1/2]: `k/1000` or a 60-digit decimal.
    fn parameter(&mut self, long: bool) -> String {
        if long {
            format!("{}/2{}", self.digits(60), "0".repeat(60))
        } else {
            format!("{}/1000", 1 + self.next() % 500)
        }
    }
}

/// The three shapes of the benchmark, all cubic, rational, in space.
#[derive(Clone, Copy)]
enum Shape {
    Curve,
    Rect,
    Tri,
}

/// One case: a patch in our JSON format and its parameters as exact text.
struct Case {
    name: String,
    shape: Shape,
    /// Homogeneous-free input: `(x, y, z, weight)` per control point, in
    /// the order of the JSON (curve: i; rect: i then j; tri: row j, then i).
    points: Vec<[String; 4]>,
    /// One value per point (curve) or two (rect, tri).
    params: Vec<String>,
}

const DEGREE: usize = 3;

impl Case {
    fn new(shape: Shape, digits: usize, long: bool, points: usize, rng: &mut Lcg) -> Case {
        let count = match shape {
            Shape::Curve => DEGREE + 1,
            Shape::Rect => (DEGREE + 1) * (DEGREE + 1),
            Shape::Tri => (DEGREE + 1) * (DEGREE + 2) / 2,
        };
        let net = (0..count)
            .map(|_| {
                [
                    rng.coordinate(digits),
                    rng.coordinate(digits),
                    rng.coordinate(digits),
                    rng.weight(),
                ]
            })
            .collect();
        let per_point = if matches!(shape, Shape::Curve) { 1 } else { 2 };
        let params = (0..points * per_point)
            .map(|_| rng.parameter(long))
            .collect();
        let kind = match shape {
            Shape::Curve => "curve",
            Shape::Rect => "bicubic",
            Shape::Tri => "triangle",
        };
        let param = if long { "60-digit" } else { "k/1000" };
        Case {
            name: format!("{kind}, {digits}-digit points, {param}"),
            shape,
            points: net,
            params,
        }
    }

    /// The patch in our JSON format.
    fn json(&self) -> String {
        let point = |p: &[String; 4]| json!([p[0], p[1], p[2]]);
        let (kind, degree, points, weights) = match self.shape {
            Shape::Curve => (
                "curve",
                json!(DEGREE),
                json!(self.points.iter().map(point).collect::<Vec<_>>()),
                json!(self.points.iter().map(|p| &p[3]).collect::<Vec<_>>()),
            ),
            Shape::Rect => {
                let rows = |f: &dyn Fn(&[String; 4]) -> Value| {
                    json!(self
                        .points
                        .chunks(DEGREE + 1)
                        .map(|r| r.iter().map(f).collect::<Vec<_>>())
                        .collect::<Vec<_>>())
                };
                (
                    "rect",
                    json!([DEGREE, DEGREE]),
                    rows(&point),
                    rows(&|p| json!(p[3])),
                )
            }
            Shape::Tri => {
                let rows = |f: &dyn Fn(&[String; 4]) -> Value| {
                    let mut out = Vec::new();
                    let mut rest = self.points.as_slice();
                    for i in 0..=DEGREE {
                        let (row, tail) = rest.split_at(DEGREE + 1 - i);
                        out.push(row.iter().map(f).collect::<Vec<_>>());
                        rest = tail;
                    }
                    json!(out)
                };
                ("tri", json!(DEGREE), rows(&point), rows(&|p| json!(p[3])))
            }
        };
        json!({"kind": kind, "degree": degree, "points": points, "weights": weights}).to_string()
    }
}

/// The GMP net: homogeneous coordinates `(w·x, w·y, w·z, w)` times the
/// Bernstein coefficient's binomial factor, all on one integer denominator.
struct GmpNet {
    shape: Shape,
    coords: Vec<[Integer; 4]>,
}

impl GmpNet {
    fn new(case: &Case) -> GmpNet {
        let factorial = |k: usize| (1..=k as u64).product::<u64>();
        let factors: Vec<u64> = match case.shape {
            Shape::Curve => (0..=DEGREE).map(|i| binomial(DEGREE, i)).collect(),
            Shape::Rect => (0..=DEGREE)
                .flat_map(|i| (0..=DEGREE).map(move |j| binomial(DEGREE, i) * binomial(DEGREE, j)))
                .collect(),
            Shape::Tri => (0..=DEGREE)
                .flat_map(|i| (0..=DEGREE - i).map(move |j| (i, j)))
                .map(|(i, j)| {
                    factorial(DEGREE) / (factorial(i) * factorial(j) * factorial(DEGREE - i - j))
                })
                .collect(),
        };
        let hom: Vec<[Rational; 4]> = case
            .points
            .iter()
            .zip(&factors)
            .map(|(p, f)| {
                let w = rational(&p[3]);
                let scaled = |x: &str| rational(x) * &w * Integer::from(*f);
                [
                    scaled(&p[0]),
                    scaled(&p[1]),
                    scaled(&p[2]),
                    w.clone() * Integer::from(*f),
                ]
            })
            .collect();
        let lcm = hom
            .iter()
            .flatten()
            .fold(Integer::from(1), |l, q| l.lcm(q.denom()));
        let coords = hom
            .iter()
            .map(|h| std::array::from_fn(|k| h[k].numer() * Integer::from(&lcm / h[k].denom())))
            .collect();
        GmpNet {
            shape: case.shape,
            coords,
        }
    }

    /// The homogeneous Horner sum `Σ_i c_i x^i y^(n−i)` of four coordinates.
    fn horner(c: &[&[Integer; 4]], x: &Integer, y: &Integer) -> [Integer; 4] {
        let mut acc = c[0].clone();
        let mut power = Integer::from(1);
        for ci in &c[1..] {
            power *= x;
            for (a, cik) in acc.iter_mut().zip(ci.iter()) {
                *a *= y;
                *a += Integer::from(cik * &power);
            }
        }
        acc
    }

    /// The point at parameters `t` (one for a curve, two otherwise).
    fn eval(&self, t: &[Rational]) -> [Rational; 3] {
        let h = match self.shape {
            Shape::Curve => {
                let (a, b) = (t[0].numer(), t[0].denom());
                let c: Vec<&[Integer; 4]> = self.coords.iter().collect();
                Self::horner(&c, a, &Integer::from(b - a))
            }
            Shape::Rect => {
                let (a, b) = (t[1].numer(), t[1].denom());
                let bma = Integer::from(b - a);
                let rows: Vec<[Integer; 4]> = self
                    .coords
                    .chunks(DEGREE + 1)
                    .map(|r| Self::horner(&r.iter().collect::<Vec<_>>(), a, &bma))
                    .collect();
                let (a, b) = (t[0].numer(), t[0].denom());
                Self::horner(&rows.iter().collect::<Vec<_>>(), a, &Integer::from(b - a))
            }
            Shape::Tri => {
                let d = Integer::from(t[0].denom().lcm_ref(t[1].denom()));
                let u = t[0].numer() * Integer::from(&d / t[0].denom());
                let v = t[1].numer() * Integer::from(&d / t[1].denom());
                let w = Integer::from(&d - &u) - &v;
                // Row j holds the points of v-exponent j, by u-exponent i:
                // Σ_j v^j·Σ_i u^i w^(n−i−j) c_ij.
                let mut rest = self.coords.as_slice();
                let mut inner = Vec::new();
                for i in 0..=DEGREE {
                    let (row, tail) = rest.split_at(DEGREE + 1 - i);
                    inner.push(Self::horner(&row.iter().collect::<Vec<_>>(), &u, &w));
                    rest = tail;
                }
                let mut acc = inner.pop().expect("n + 1 rows");
                for row in inner.iter().rev() {
                    for (a, r) in acc.iter_mut().zip(row) {
                        *a *= &v;
                        *a += r;
                    }
                }
                acc
            }
        };
        let [x, y, z, w] = h;
        [
            Rational::from((x, &w)),
            Rational::from((y, &w)),
            Rational::from((z, w)),
        ]
    }
}

fn binomial(n: usize, k: usize) -> u64 {
    (0..k as u64).fold(1, |acc, i| acc * (n as u64 - i) / (i + 1))
}

fn rational(text: &str) -> Rational {
    Rational::from(Rational::parse(text).expect("an exact fraction"))
}

/// Nanoseconds per point of the fastest of `repeat` runs of `ours` and of
/// `theirs`, run alternately so that a change of machine speed during the
/// measurement falls on both sides.
fn interleaved(
    repeat: usize,
    points: usize,
    mut ours: impl FnMut(),
    mut theirs: impl FnMut(),
) -> (f64, f64) {
    let time = |f: &mut dyn FnMut()| {
        let start = Instant::now();
        f();
        start.elapsed().as_nanos() as f64 / points as f64
    };
    (0..repeat).fold((f64::INFINITY, f64::INFINITY), |(a, b), _| {
        (a.min(time(&mut ours)), b.min(time(&mut theirs)))
    })
}

fn arg(args: &[String], name: &str, default: usize) -> usize {
    args.iter()
        .position(|a| a == name)
        .map_or(default, |i| args[i + 1].parse().expect("a count"))
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (points, repeat) = (arg(&args, "--points", 256), arg(&args, "--repeat", 7));
    let only = args
        .iter()
        .position(|a| a == "--only")
        .map(|i| args[i + 1].clone());
    let mut rng = Lcg(30);
    let mut cases = Map::new();
    let mut worst = 0.0f64;
    for shape in [Shape::Curve, Shape::Rect, Shape::Tri] {
        for digits in [10, 30] {
            for long in [false, true] {
                let case = Case::new(shape, digits, long, points, &mut rng);
                if only
                    .as_ref()
                    .is_some_and(|o| !case.name.contains(o.as_str()))
                {
                    continue;
                }
                let (ours, gmp) = run(&case, points, repeat);
                worst = worst.max(ours / gmp);
                record(&mut cases, case.name, (ours, gmp));
            }
        }
    }
    let gcds = gcd_cases(repeat, &mut rng);
    let keys = key::key_cases(points, repeat, only.as_deref(), &mut rng);
    let roots = roots::root_cases(repeat, only.as_deref(), &mut rng);
    println!(
        "{}",
        json!({"exact_vs_gmp": round3(worst), "cases": cases, "gcd_vs_gmp": worst_of(&gcds), "gcd": gcds,
               "key_vs_gmp": worst_of(&keys), "key": keys, "roots_vs_gmp": worst_of(&roots), "roots": roots})
    );
}

/// The largest ratio of a set of rows (0 for none).
fn worst_of(rows: &Map<String, Value>) -> f64 {
    rows.values()
        .filter_map(|c| c["ratio"].as_f64())
        .fold(0.0, f64::max)
}

fn round3(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}

/// Our Lehmer gcd ([`exact_bezier::algebra::gcd::gcd`]) against GMP's
/// `mpz_gcd` on 2 000 pairs of random operands of 64 to 1 024 bits with a
/// planted common factor of 20 bits, results checked equal: ns per gcd.
fn gcd_cases(repeat: usize, rng: &mut Lcg) -> Map<String, Value> {
    let mut out = Map::new();
    for bits in [64, 128, 256, 512, 1024] {
        let number = |rng: &mut Lcg| rng.digits(bits * 3 / 10 - 6);
        let pairs: Vec<(String, String)> = (0..2000)
            .map(|_| {
                let f = rng.digits(6);
                (format!("{}{f}", number(rng)), format!("{}{f}", number(rng)))
            })
            .collect();
        let ours: Vec<(BigUint, BigUint)> = pairs
            .iter()
            .map(|(a, b)| (a.parse().unwrap(), b.parse().unwrap()))
            .collect();
        let theirs: Vec<(Integer, Integer)> = pairs
            .iter()
            .map(|(a, b)| (a.parse().unwrap(), b.parse().unwrap()))
            .collect();
        let (mut g_ours, mut g_gmp) = (Vec::new(), Vec::new());
        let (a, b) = interleaved(
            repeat,
            pairs.len(),
            || {
                g_ours = ours
                    .iter()
                    .map(|(a, b)| exact_bezier::algebra::gcd::gcd(a, b))
                    .collect()
            },
            || {
                g_gmp = theirs
                    .iter()
                    .map(|(a, b)| Integer::from(a.gcd_ref(b)))
                    .collect()
            },
        );
        for (x, y) in g_ours.iter().zip(&g_gmp) {
            assert_eq!(x.to_string(), y.to_string(), "gcds differ");
        }
        record(&mut out, format!("gcd, {bits}-bit operands"), (a, b));
    }
    out
}

/// Print a row of the table and enter it into `rows`: ours and GMP's time
/// in ns and their ratio.
fn record(rows: &mut Map<String, Value>, name: String, (ours, gmp): (f64, f64)) {
    eprintln!(
        "{name:<44} ours {ours:>9.0} ns  GMP {gmp:>9.0} ns  ours/GMP {:.2}",
        ours / gmp
    );
    rows.insert(
        name,
        json!({"ours_ns": ours.round(), "gmp_ns": gmp.round(), "ratio": round3(ours / gmp)}),
    );
}

/// Both sides on one case, results checked identical: (ours, GMP) in ns per point.
fn run(case: &Case, points: usize, repeat: usize) -> (f64, f64) {
    let patch = read_patches(&case.json()).expect("a valid patch").remove(0);
    let mut ev = match &patch {
        Patch::Curve(c) => Evaluator::curve(c),
        Patch::Rect(r) => Evaluator::rect(r),
        Patch::Tri(t) => Evaluator::tri(t),
    };
    let params: Vec<BigRational> = case
        .params
        .iter()
        .map(|p| parse_rational(p).expect("exact"))
        .collect();
    let mut out = vec![BigRational::from_integer(0.into()); points * 3];
    let net = GmpNet::new(case);
    let gmp_params: Vec<Rational> = case.params.iter().map(|p| rational(p)).collect();
    let per_point = gmp_params.len() / points;
    let mut theirs = Vec::with_capacity(points);
    let (ours, gmp) = interleaved(
        repeat,
        points,
        || ev.eval_batch(&params, &mut out).expect("finite points"),
        || theirs = gmp_params.chunks(per_point).map(|t| net.eval(t)).collect(),
    );
    for (k, (o, g)) in out.chunks(3).zip(&theirs).enumerate() {
        for (x, y) in o.iter().zip(g) {
            assert_eq!(
                x.to_string(),
                y.to_string(),
                "{}: point {k} differs",
                case.name
            );
        }
    }
    (ours, gmp)
}
