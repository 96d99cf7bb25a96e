//! The root step of exact intersections against GMP: our
//! [`RealAlgebraic::real_roots_in`] on `(0, 1)` (the call with which
//! `intersect` isolates the parameters of the crossings) next to the
//! Vincent–Collins–Akritas bisection written on rug's `Integer` (GMP 6):
//! Descartes' rule on `(x + 1)^d P(1/(x + 1))`, halving by
//! `P ↦ 2^d P(x/2)` and `P ↦ 2^d P((x + 1)/2)` (Taylor shifts, additions
//! only), dyadic intervals.
//!
//! The inputs are square-free integer polynomials with no root at a
//! dyadic number: random ones with 10-digit coefficients (like the
//! eliminants of intersections: few roots in `(0, 1)`, and no rational
//! root, which a test modulo small primes shows at once), and products of
//! `a x² − b` with `b/a` in `(0, 1)` and not a square (one root in
//! `(0, 1)` each; a root modulo every small prime, so that the
//! rational-root test of each root has to refine it). The GMP side is told
//! so; ours still computes the square-free part (a check modulo p) and
//! tests each root for a rational value, as `intersect` needs. The check:
//! the same number of roots, and the k-th intervals of both sides meet
//! (each isolates the k-th root).

use crate::{interleaved, record, Lcg};
use exact_bezier::algebra::{RealAlgebraic, UPoly};
use exact_bezier::Ordered;
use num_rational::BigRational;
use rug::{Integer, Rational};
use serde_json::{Map, Value};

/// `a ← a(x + 1)`, coefficients lowest first.
fn taylor_shift(a: &mut [Integer]) {
    let d = a.len() - 1;
    for i in 0..d {
        for k in (i..d).rev() {
            let (low, high) = a.split_at_mut(k + 1);
            low[k] += &high[0];
        }
    }
}

/// Descartes' bound on the roots of `p` in `(0, 1)`: the sign variations
/// of `(x + 1)^d p(1/(x + 1))`.
fn variations(p: &[Integer]) -> usize {
    let mut q: Vec<Integer> = p.iter().rev().cloned().collect();
    taylor_shift(&mut q);
    let signs: Vec<bool> = q.iter().filter(|c| **c != 0).map(|c| *c > 0).collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// Isolating intervals `(c/2^k, (c + 1)/2^k)` of the roots in `(0, 1)` of
/// a square-free `p` with no dyadic root, increasing.
fn isolate(p: Vec<Integer>) -> Vec<(Rational, Rational)> {
    let d = p.len() - 1;
    let mut out = Vec::new();
    let mut stack = vec![(p, Integer::from(0), 0u32)];
    while let Some((p, c, k)) = stack.pop() {
        assert!(k < 400, "no isolation: the polynomial is not square-free");
        match variations(&p) {
            0 => {}
            1 => {
                let scale = Integer::from(1) << k;
                out.push((
                    Rational::from((c.clone(), scale.clone())),
                    Rational::from((c + 1, scale)),
                ));
            }
            _ => {
                let left: Vec<Integer> = p
                    .iter()
                    .enumerate()
                    .map(|(i, x)| Integer::from(x << (d - i) as u32))
                    .collect();
                let mut right = left.clone();
                taylor_shift(&mut right);
                let c2 = Integer::from(&c << 1);
                stack.push((right, Integer::from(&c2 + 1), k + 1));
                stack.push((left, c2, k + 1));
            }
        }
    }
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// `Π (a_i x² − b_i)`, coefficients lowest first.
fn product(factors: &[(i64, i64)]) -> Vec<Integer> {
    factors.iter().fold(vec![Integer::from(1)], |p, &(a, b)| {
        let mut q = vec![Integer::new(); p.len() + 2];
        for (i, c) in p.iter().enumerate() {
            q[i] -= Integer::from(c * b);
            q[i + 2] += Integer::from(c * a);
        }
        q
    })
}

/// `m` factors `a x² − b`, `b < a` of 3 digits, `b/a` not a square.
fn factors(m: usize, rng: &mut Lcg) -> Vec<(i64, i64)> {
    let mut out = Vec::new();
    while out.len() < m {
        let a = 100 + (rng.next() % 900) as i64;
        let b = 1 + (rng.next() % (a as u64 - 1)) as i64;
        let square = |n: i64| (n as f64).sqrt().round() as i64;
        let is_square = square(a * b).pow(2) == a * b;
        let root = (b as f64 / a as f64).sqrt();
        let apart = out
            .iter()
            .all(|&(c, e): &(i64, i64)| ((e as f64 / c as f64).sqrt() - root).abs() > 1e-9);
        if !is_square && apart {
            out.push((a, b));
        }
    }
    out
}

/// A polynomial of degree `d` with random 10-digit coefficients.
fn random(d: usize, rng: &mut Lcg) -> Vec<Integer> {
    (0..=d)
        .map(|_| {
            let sign = if rng.next() % 2 == 0 { "" } else { "-" };
            format!("{sign}{}", rng.digits(10))
                .parse()
                .expect("an integer")
        })
        .collect()
}

/// The root rows, 64 polynomials each, those whose name contains `only`:
/// ns per polynomial.
pub fn root_cases(repeat: usize, only: Option<&str>, rng: &mut Lcg) -> Map<String, Value> {
    let mut out = Map::new();
    type Make = fn(&mut Lcg) -> Vec<Integer>;
    let cases: [(&str, Make); 4] = [
        ("degree 9, random 10-digit coefficients", |rng| {
            random(9, rng)
        }),
        ("degree 18, random 10-digit coefficients", |rng| {
            random(18, rng)
        }),
        ("degree 8, 4 quadratic factors", |rng| {
            product(&factors(4, rng))
        }),
        ("degree 18, 9 quadratic factors", |rng| {
            product(&factors(9, rng))
        }),
    ];
    for (what, make) in cases {
        let name = format!("roots in (0, 1), {what}");
        if only.is_some_and(|o| !name.contains(o)) {
            continue;
        }
        let polys: Vec<Vec<Integer>> = (0..64).map(|_| make(rng)).collect();
        let ours_in: Vec<UPoly<BigRational>> = polys
            .iter()
            .map(|p| {
                UPoly::new(
                    p.iter()
                        .map(|c| {
                            BigRational::from_integer(c.to_string().parse().expect("an integer"))
                        })
                        .collect(),
                )
            })
            .collect();
        let (zero, one) = (
            BigRational::from_integer(0.into()),
            BigRational::from_integer(1.into()),
        );
        let (mut ours, mut theirs) = (Vec::new(), Vec::new());
        let (a, b) = interleaved(
            repeat,
            polys.len(),
            || {
                ours = ours_in
                    .iter()
                    .map(|p| RealAlgebraic::real_roots_in(p, &zero, &one))
                    .collect()
            },
            || theirs = polys.iter().map(|p| isolate(p.clone())).collect(),
        );
        for (k, (o, t)) in ours.iter().zip(&theirs).enumerate() {
            assert_eq!(
                o.len(),
                t.len(),
                "{name}: polynomial {k}: root counts differ"
            );
            for (x, (lo, hi)) in o.iter().zip(t) {
                let (xlo, xhi) = x.rational_bounds().unwrap_or_else(|| {
                    let q = x.as_rational().expect("bounds or a rational");
                    (q.clone(), q)
                });
                let rational = |q: &BigRational| {
                    Rational::from((
                        q.numer().to_string().parse::<Integer>().unwrap(),
                        q.denom().to_string().parse::<Integer>().unwrap(),
                    ))
                };
                assert!(
                    rational(&xlo) <= *hi && *lo <= rational(&xhi),
                    "{name}: polynomial {k}: the intervals of a root do not meet"
                );
            }
        }
        record(&mut out, name, (a, b));
    }
    out
}
