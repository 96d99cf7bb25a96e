//! Our side of the arithmetic peer benchmark `benches/peers/arith` (issue
//! 30): reads the polynomial cases that `benches/peers/peer_arith.py`
//! wrote, raises each polynomial to its power with [`Poly::pow`] and prints
//! one JSON object: per case the median nanoseconds of `--repeat` runs and
//! the expanded result (exponent vectors and exact coefficients), which the
//! script compares term by term with FLINT's.
//!
//! ```text
//! cargo bench --bench peer_arith -- CASES.json [--repeat 9]
//! ```
//!
//! Each case is `{"name", "vars": n, "terms": [[[e_0, …, e_{n−1}], "p/q"], …],
//! "power": k}` in the variables `x0 … x{n−1}`.

use exact_bezier::algebra::parse_rational;
use exact_bezier::Poly;
use serde_json::{json, Map, Value};
use std::time::Instant;

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
        let n = case["vars"].as_u64().expect("vars") as usize;
        let k = case["power"].as_u64().expect("power") as u32;
        let p = read_poly(&case["terms"], n);
        let mut times = Vec::with_capacity(repeat);
        let mut result = Poly::default();
        for _ in 0..repeat {
            let start = Instant::now();
            result = std::hint::black_box(&p).pow(k);
            times.push(start.elapsed().as_nanos() as u64);
        }
        times.sort_unstable();
        out.insert(
            name.to_string(),
            json!({"ns": times[times.len() / 2], "terms": write_poly(&result, n)}),
        );
    }
    println!("{}", Value::Object(out));
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
