//! An interval certificate that bivariate polynomials with real algebraic
//! coefficients have no common factor of positive degree: what lets
//! [`minimal_rect`](crate::coincide::minimal_rect) skip the exact gcd over
//! a number field, whose coefficients grow without bound in Euclid's
//! algorithm (a bicubic with weights `a + √p` for four primes ran for
//! minutes).
//!
//! ```text
//! F_c(u, v) = Σ_p Σ_q a_{c,p,q} uᵖ v^q,   deg_u = m
//! v = v₀ ∈ Q:  A(u) = F_a(u, v₀) with lc_u A ≠ 0 (its interval excludes 0)
//! Res_u(A, B) ≠ 0 for every other component B  (formal degree m)
//!   ⇒ no common factor g with deg_u g ≥ 1
//! ```
//!
//! Why: if `g` divides every `F_c`, then `lc_u(g)(v₀) · lc_u(A/g)(v₀) =
//! lc_u(A)(v₀) ≠ 0`, so `g(u, v₀)` keeps its u-degree and divides `A(u)`
//! and `B(u)`; a non-zero resultant leaves it no root. The resultant is the
//! determinant of the Sylvester matrix, shown non-zero by interval Gaussian
//! elimination: when no pivot interval contains 0, every real matrix in
//! the interval matrix is regular (exact elimination with the same pivot
//! order has each pivot inside its interval). Coefficients enter as `f64`
//! intervals around exact enclosures ([`RealAlgebraic::enclosure`]); the
//! same in v with `u = u₀`. A failure only means "not certified".

use crate::algebra::{Interval, RealAlgebraic};
use num_rational::BigRational;

/// Specialization points tried in each direction.
const PROBES: [(i64, i64); 3] = [(1, 3), (5, 7), (2, 11)];

/// Bits of the exact enclosure of each coefficient (far below `f64`'s
/// precision loss in the elimination).
const ENCLOSURE_BITS: u32 = 64;

/// Do the polynomials with power grids `comps[c][p][q]` (coefficient of
/// `uᵖ v^q`, all of bidegree ≤ `(m, n)`) certainly have no common factor of
/// positive degree? `false` only means "not certified".
pub(crate) fn coprime_by_intervals(
    comps: &[Vec<Vec<RealAlgebraic>>],
    (m, n): (usize, usize),
) -> bool {
    let Some(grids) = comps
        .iter()
        .map(|g| interval_grid(g, (m, n)))
        .collect::<Option<Vec<_>>>()
    else {
        return false;
    };
    let transposed: Vec<Vec<Vec<Interval>>> = grids.iter().map(|g| transpose(g)).collect();
    no_factor_in(&grids, m) && no_factor_in(&transposed, n)
}

/// The grid as `f64` intervals, padded to `(m + 1) × (n + 1)`; `None` if a
/// coefficient does not fit `f64`.
fn interval_grid(g: &[Vec<RealAlgebraic>], (m, n): (usize, usize)) -> Option<Vec<Vec<Interval>>> {
    let zero = Interval { lo: 0.0, hi: 0.0 };
    let mut out = vec![vec![zero; n + 1]; m + 1];
    for (p, row) in g.iter().enumerate() {
        for (q, x) in row.iter().enumerate() {
            let (lo, hi) = x.enclosure(ENCLOSURE_BITS);
            let iv = Interval {
                lo: Interval::enclose(&lo).lo,
                hi: Interval::enclose(&hi).hi,
            };
            if !(iv.lo.is_finite() && iv.hi.is_finite()) {
                return None;
            }
            *out.get_mut(p)?.get_mut(q)? = iv;
        }
    }
    Some(out)
}

fn transpose(g: &[Vec<Interval>]) -> Vec<Vec<Interval>> {
    (0..g[0].len())
        .map(|q| g.iter().map(|row| row[q]).collect())
        .collect()
}

/// No common factor of positive degree in the first variable (degree
/// `m`), certified at one of the [`PROBES`] of the second.
fn no_factor_in(grids: &[Vec<Vec<Interval>>], m: usize) -> bool {
    m == 0
        || PROBES.iter().any(|&(p, q)| {
            let at = Interval::enclose(&BigRational::new(p.into(), q.into()));
            let polys: Vec<Vec<Interval>> = grids.iter().map(|g| specialize(g, &at)).collect();
            let Some(a) = polys.iter().position(|f| excludes_zero(&f[m])) else {
                return false;
            };
            polys
                .iter()
                .enumerate()
                .filter(|&(b, _)| b != a)
                .any(|(_, f)| regular(sylvester(&polys[a], f)))
        })
}

/// `Σ_q g[p][q] v^q` for each `p`: the coefficients in the first variable.
fn specialize(g: &[Vec<Interval>], v: &Interval) -> Vec<Interval> {
    g.iter()
        .map(|row| {
            row.iter()
                .rev()
                .fold(Interval { lo: 0.0, hi: 0.0 }, |acc, c| acc.mul(v).add(c))
        })
        .collect()
}

fn excludes_zero(x: &Interval) -> bool {
    x.lo > 0.0 || x.hi < 0.0
}

/// The Sylvester matrix of two polynomials of formal degree `m` (ascending
/// coefficients), `2m × 2m`.
fn sylvester(a: &[Interval], b: &[Interval]) -> Vec<Vec<Interval>> {
    let m = a.len() - 1;
    let zero = Interval { lo: 0.0, hi: 0.0 };
    let row = |f: &[Interval], shift: usize| {
        let mut r = vec![zero; 2 * m];
        for (k, c) in f.iter().rev().enumerate() {
            r[shift + k] = *c;
        }
        r
    };
    (0..m)
        .map(|s| row(a, s))
        .chain((0..m).map(|s| row(b, s)))
        .collect()
}

/// Interval Gaussian elimination with pivots of largest magnitude: `true`
/// when no pivot interval contains 0 (every matrix in the box is regular).
fn regular(mut rows: Vec<Vec<Interval>>) -> bool {
    let size = rows.len();
    for k in 0..size {
        let mig = |x: &Interval| {
            if excludes_zero(x) {
                x.lo.abs().min(x.hi.abs())
            } else {
                0.0
            }
        };
        let Some(pivot) = (k..size).max_by(|&i, &j| mig(&rows[i][k]).total_cmp(&mig(&rows[j][k])))
        else {
            return false;
        };
        if !excludes_zero(&rows[pivot][k]) || !rows[pivot][k].lo.is_finite() {
            return false;
        }
        rows.swap(k, pivot);
        let (top, rest) = rows.split_at_mut(k + 1);
        let p = &top[k];
        for r in rest {
            let Some(f) = r[k].div(&p[k]) else {
                return false;
            };
            for c in k..size {
                r[c] = r[c].sub(&f.mul(&p[c]));
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::Scalar;

    fn a(s: &str) -> RealAlgebraic {
        s.parse().unwrap()
    }

    /// Grids of `(u + √2)(v + 1)` times `u − 1` and times `u + v`: the
    /// common factor `u + √2` (and `v + 1`) is not certified away; without
    /// it they are coprime.
    #[test]
    fn a_common_factor_is_never_certified_away() {
        let (s2, one, zero) = (
            a("sqrt(2)"),
            RealAlgebraic::from_i64(1),
            RealAlgebraic::from_i64(0),
        );
        // (u + √2)(u − 1) = u² + (√2 − 1)u − √2 and (u + √2)(u + v) = u² + √2 u + uv + √2 v.
        let f = vec![
            vec![-s2.clone(), zero.clone()],
            vec![s2.clone() - &one, zero.clone()],
            vec![one.clone(), zero.clone()],
        ];
        let g = vec![
            vec![zero.clone(), s2.clone()],
            vec![s2.clone(), one.clone()],
            vec![one.clone(), zero.clone()],
        ];
        assert!(!coprime_by_intervals(&[f.clone(), g], (2, 1)));
        // u² + √3 u + uv is coprime to f.
        let h = vec![
            vec![zero.clone(), zero.clone()],
            vec![a("sqrt(3)"), one.clone()],
            vec![one, zero],
        ];
        assert!(coprime_by_intervals(&[f, h], (2, 1)));
    }
}
