//! Our side of the arithmetic peer benchmark `benches/peers/arith` (issue
//! 30): reads the cases that `benches/peers/peer_arith.py` wrote, runs
//! each and prints one JSON object: per case the median nanoseconds of
//! `--repeat` runs and the expanded result (exponent vectors and exact
//! coefficients), which the script compares term by term with FLINT's.
//!
//! ```text
//! cargo bench -p exact-bezier-proofs --bench peer_arith -- CASES.json [--repeat 9]
//! ```
//!
//! A case is either a power, `{"name", "vars": n, "terms": [[[e_0, …,
//! e_{n−1}], "p/q"], …], "power": k}` in the variables `x0 … x{n−1}`,
//! raised with [`Poly::pow`]; or the Möbius identity of `proofs/`,
//! `{"name", "mobius": m}`: both sides of the maps (2)(3) on the fully
//! symbolic (m, m) net ([`mobius_uv_sides`]), checked equal, the result
//! being the new side's weight coordinate, with variables by name; or the
//! quadratic map's point identity, `{"name", "quadratic": m}`
//! ([`quadratic_identity`] at (m, m)), the result being the map's weight
//! (m, m) on the net of symbolic weights ([`quadratic_weights`]); or the
//! Sylvester resultant of two integer polynomials, `{"name", "resultant":
//! [[c_0, …], [c_0, …]]}` (coefficients as text, lowest degree first), by
//! [`resultant`] (the elimination step of exact intersections), the result
//! being the resultant as one constant term; or the resultant in `t` of
//! two polynomials in `s` and `t` (the elimination step of exact curve
//! intersections), `{"name", "resultant_t": [F, G]}` with `F` the rows of
//! coefficients in `s` of `t⁰, t¹, …`, by [`resultant_in_t`], the result
//! being that polynomial in `s` made monic (ours is defined up to a
//! constant factor).

use exact_bezier::algebra::sylvester::resultant_in_t;
use exact_bezier::algebra::{parse_rational, resultant, BPoly, UPoly};
use exact_bezier::Poly;
use exact_bezier_proofs::yang_yong::{mobius_uv_sides, quadratic_identity, quadratic_weights};
use num_rational::BigRational;
use num_traits::Zero;
use serde_json::{json, Map, Value};
use std::hint::black_box;
use std::time::Instant;

/// The allocator of the `exact-bezier` command line (mimalloc, without
/// transparent huge pages), so that the engine is timed as `prove` runs
/// it: with the C library's malloc the Möbius identity at (6, 6) took
/// 14.0–14.4 ms, with mimalloc 10.5–10.8 (2026-11-29, Zen 5).
/// `benches/peers/arith` preloads mimalloc for FLINT too where the machine
/// has it, and names the allocators in its JSON line.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    // `cargo bench` appends `--bench`; with no cases file there is nothing to time.
    let Some(path) = args.get(1).filter(|a| !a.starts_with("--")) else {
        eprintln!("usage: cargo bench --bench peer_arith -- CASES.json [--repeat N]");
        return;
    };
    let repeat: usize = match args.iter().position(|a| a == "--repeat") {
        Some(i) => args[i + 1].parse().expect("--repeat takes a count"),
        None => 9,
    };
    let text = std::fs::read_to_string(path).expect("readable cases file");
    let cases: Vec<Value> = serde_json::from_str(&text).expect("a JSON array of cases");
    let mut out = Map::new();
    for case in &cases {
        let name = case["name"].as_str().expect("a case name");
        let (ns, terms) = match (case["mobius"].as_u64(), case["quadratic"].as_u64()) {
            _ if case.get("resultant_t").is_some() => {
                let [f, g] = [0, 1].map(|k| read_bivariate(&case["resultant_t"][k]));
                let (ns, r) = median_time(repeat, || resultant_in_t(black_box(&f), black_box(&g)));
                (ns, write_univariate(&r.monic()))
            }
            _ if case.get("resultant").is_some() => {
                let [f, g] = [0, 1].map(|k| read_integers(&case["resultant"][k]));
                let (ns, r) = median_time(repeat, || resultant(black_box(&f), black_box(&g)));
                (ns, json!([[[], r.to_string()]]))
            }
            (_, Some(m)) => {
                let m = m as usize;
                let (ns, failure) = median_time(repeat, || quadratic_identity(m, m));
                assert_eq!(failure, None, "the quadratic identity fails at m = {m}");
                (ns, write_named(&quadratic_weights(m, m)[m][m]))
            }
            (Some(m), None) => {
                let identity = || {
                    let (new, old) = mobius_uv_sides(m as usize, m as usize);
                    assert_eq!(new, old, "the Möbius identity fails at m = {m}");
                    new.coords[1].clone()
                };
                let (ns, weight) = median_time(repeat, identity);
                (ns, write_named(&weight))
            }
            (None, None) => {
                let n = case["vars"].as_u64().expect("vars") as usize;
                let k = case["power"].as_u64().expect("power") as u32;
                let p = read_poly(&case["terms"], n);
                let (ns, result) = median_time(repeat, || black_box(&p).pow(k));
                (ns, write_poly(&result, n))
            }
        };
        out.insert(name.to_string(), json!({"ns": ns, "terms": terms}));
    }
    println!("{}", Value::Object(out));
}

/// The coefficients `["c_0", …, "c_n"]` (integers as text, lowest degree
/// first) as exact rationals.
fn read_integers(coeffs: &Value) -> Vec<BigRational> {
    coeffs
        .as_array()
        .expect("a coefficient list")
        .iter()
        .map(|c| parse_rational(c.as_str().expect("an integer as text")).expect("exact"))
        .collect()
}

/// `Σ_k a_k(s) t^k` from `[[a_k's coefficients, lowest power of s first], …]`
/// (integers as text, lowest power of t first).
fn read_bivariate(rows: &Value) -> BPoly<BigRational> {
    let rows = rows.as_array().expect("rows, one a power of t");
    BPoly::new(rows.iter().map(|r| UPoly::new(read_integers(r))).collect())
}

/// The terms of a polynomial in one variable as `[[exponent], "p/q"]` pairs.
fn write_univariate(p: &UPoly<BigRational>) -> Value {
    let terms: Vec<Value> = p
        .coeffs()
        .iter()
        .enumerate()
        .filter(|(_, c)| !c.is_zero())
        .map(|(k, c)| json!([[k], c.to_string()]))
        .collect();
    Value::Array(terms)
}

/// The median nanoseconds of `repeat` runs of `f`, and its last result.
fn median_time<R>(repeat: usize, mut f: impl FnMut() -> R) -> (u64, R) {
    let mut times = Vec::with_capacity(repeat);
    let mut result = None;
    for _ in 0..repeat.max(1) {
        let start = Instant::now();
        result = Some(f());
        times.push(start.elapsed().as_nanos() as u64);
    }
    times.sort_unstable();
    (times[times.len() / 2], result.expect("one run at least"))
}

/// The terms as `[[[name, exponent], …], "p/q"]` (variables by name).
fn write_named(p: &Poly) -> Value {
    Value::Array(
        p.terms()
            .map(|(vars, c)| json!([vars, c.to_string()]))
            .collect(),
    )
}

/// The polynomial `Σ c·x0^e0⋯` from `[[exponents], "p/q"]` pairs.
fn read_poly(terms: &Value, n: usize) -> Poly {
    let x = Poly::vars("x", n);
    terms
        .as_array()
        .expect("a term list")
        .iter()
        .map(|t| {
            let c = parse_rational(t[1].as_str().expect("a coefficient")).expect("exact");
            let exps = t[0].as_array().expect("exponents");
            exps.iter().zip(&x).fold(Poly::constant(c), |m, (e, v)| {
                m * v.pow(e.as_u64().expect("an exponent") as u32)
            })
        })
        .sum()
}

/// The terms as `[[exponents], "p/q"]` pairs (coefficients in lowest terms).
fn write_poly(p: &Poly, n: usize) -> Value {
    let terms: Vec<Value> = p
        .terms()
        .map(|(vars, c)| {
            let mut exps = vec![0u32; n];
            for (v, e) in vars {
                let i: usize = v[1..].parse().expect("a variable x<i>");
                exps[i] = e;
            }
            json!([exps, c.to_string()])
        })
        .collect();
    Value::Array(terms)
}
