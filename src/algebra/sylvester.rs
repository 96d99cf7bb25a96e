//! Sylvester resultants and the first subresultant with **formal** degrees,
//! univariate and (by evaluation and interpolation) in one parameter.
//!
//! For `f = Σ_{k≤m} f_k x^k` and `g = Σ_{k≤n} g_k x^k` with formal degrees
//! `m, n` (the leading coefficients may vanish), the `j`-th subresultant
//! matrix has the `n − j` rows of `x^i f` (`i = n−j−1 … 0`) and the `m − j`
//! rows of `x^i g` (`i = m−j−1 … 0`), written in the powers
//! `x^{m+n−j−1} … x^0`:
//!
//! ```text
//! S_j(x) = Σ_{i≤j} det(M_j^{(i)}) x^i      M_j^{(i)}: the first m+n−2j−1 columns and the column of x^i
//! Res(f, g) = S_0 = det(Sylvester matrix)
//! ```
//!
//! What the intersection code uses: `Res(f, g) = 0` iff `f, g` have a common
//! root or both leading coefficients vanish; if `Res = 0` and the
//! coefficient of `x` in `S_1` is non-zero, the common root is unique and
//! equals `−S_{1,0} / S_{1,1}` (the gcd of `f` and `g` is then `S_1`).
//!
//! With coefficients polynomial in a parameter `s`, each determinant is a
//! polynomial in `s` whose degree is bounded by the entries' degrees; it is
//! evaluated at `s = 0, 1, …, D` and interpolated (Newton's divided
//! differences), so that no determinant over `Q[s]` is ever expanded.
//! Formal degrees keep the specializations consistent: at a value of `s`
//! where a leading coefficient vanishes the matrix keeps its shape.
//!
//! Cost: one `(m+n)`-square elimination over Q per sample, `O((m+n)³)`
//! operations, `D + 1` samples.
//!
//! Reference: Basu, Pollack & Roy, *Algorithms in Real Algebraic Geometry*
//! (2006), §4.2 (subresultants, Prop. 4.25: the first non-vanishing
//! subresultant is the gcd); Cohen, *A Course in Computational Algebraic
//! Number Theory* (1993), §3.3.

use crate::algebra::int::common_denominator;
use crate::algebra::real_algebraic::polys::interpolate;
use crate::algebra::scalar::Field;
use crate::algebra::upoly::{BPoly, UPoly};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::any::Any;

/// The determinant of a square matrix over a field, by Gaussian
/// elimination with the first non-zero pivot (exact fields only).
pub(crate) fn determinant<T: Field>(mut m: Vec<Vec<T>>) -> T {
    let n = m.len();
    let mut det = T::one();
    for col in 0..n {
        let Some(p) = (col..n).find(|&r| !m[r][col].is_zero()) else {
            return T::zero();
        };
        if p != col {
            m.swap(p, col);
            det = -det;
        }
        let pivot = m[col][col].clone();
        det = det * &pivot;
        let inv = pivot.recip();
        let (upper, lower) = m.split_at_mut(col + 1);
        let pivot_row = &upper[col];
        for row in lower.iter_mut().filter(|row| !row[col].is_zero()) {
            let factor = row[col].clone() * &inv;
            for (entry, p) in row[col..].iter_mut().zip(&pivot_row[col..]) {
                let d = factor.clone() * p;
                *entry = entry.clone() - &d;
            }
        }
    }
    det
}

/// The determinant of a square integer matrix by Bareiss's fraction-free
/// elimination: every entry stays an integer (each division is exact),
/// no gcd per operation unlike Gaussian elimination over `BigRational`:
///
/// ```text
/// a_ij ← (a_ij a_kk − a_ik a_kj) / a_{k−1,k−1}      det = a_{n−1,n−1}
/// ```
///
/// Reference: Bareiss, *Sylvester's identity and multistep
/// integer-preserving Gaussian elimination*, Math. Comp. 22 (1968) 565–578.
pub(crate) fn integer_determinant(mut a: Vec<Vec<BigInt>>) -> BigInt {
    let n = a.len();
    let mut negate = false;
    let mut prev = BigInt::one();
    for k in 0..n {
        let Some(p) = (k..n).find(|&r| !a[r][k].is_zero()) else {
            return BigInt::zero();
        };
        if p != k {
            a.swap(p, k);
            negate = !negate;
        }
        let (upper, lower) = a.split_at_mut(k + 1);
        let pivot_row = &upper[k];
        for row in lower.iter_mut() {
            for j in k + 1..n {
                row[j] = (&row[j] * &pivot_row[k] - &row[k] * &pivot_row[j]) / &prev;
            }
        }
        prev = a[k][k].clone();
    }
    if negate {
        -prev
    } else {
        prev
    }
}

/// The Sylvester matrix of `f`, `g` (formal degrees `len − 1`).
pub(crate) fn sylvester_rows<T: Clone + Zero>(f: &[T], g: &[T]) -> Vec<Vec<T>> {
    subresultant_rows(f, g, 0)
}

/// The rows of the `j`-th subresultant matrix of `f`, `g` (coefficient
/// slices, lowest power first, formal degrees `len − 1`), highest power
/// first in each row.
fn subresultant_rows<T: Clone + Zero>(f: &[T], g: &[T], j: usize) -> Vec<Vec<T>> {
    let (m, n) = (f.len() - 1, g.len() - 1);
    let width = m + n - j;
    let shifted = |p: &[T], i: usize| {
        let mut row = vec![T::zero(); width];
        for (k, c) in p.iter().enumerate() {
            row[width - 1 - (k + i)] = c.clone();
        }
        row
    };
    let mut rows: Vec<Vec<T>> = (0..n - j).rev().map(|i| shifted(f, i)).collect();
    rows.extend((0..m - j).rev().map(|i| shifted(g, i)));
    rows
}

/// The Sylvester resultant of `f` and `g` with formal degrees
/// `f.len() − 1`, `g.len() − 1` (both at least 1).
///
/// ```
/// use exact_bezier::{algebra::resultant, ratio};
/// use exact_bezier::BigRational;
/// let q = |v: i64| ratio::<BigRational>(v, 1);
/// // Res(x − 2, x² − 4) = (2)² − 4 = 0; Res(x − 1, x² − 4) = 1 − 4 = −3.
/// assert_eq!(resultant(&[q(-2), q(1)], &[q(-4), q(0), q(1)]), q(0));
/// assert_eq!(resultant(&[q(-1), q(1)], &[q(-4), q(0), q(1)]), q(-3));
/// ```
///
/// Rational inputs (`T` = `BigRational`) take the integer path of
/// `rational_resultant`; other fields Gaussian elimination.
pub fn resultant<T: Field>(f: &[T], g: &[T]) -> T {
    match (rationals(f), rationals(g)) {
        (Some(f), Some(g)) => T::from_rational(&rational_resultant(&f, &g)),
        _ => determinant(subresultant_rows(f, g, 0)),
    }
}

/// `xs` as rationals, if `T` is `BigRational` (recognised by its type id).
fn rationals<T: Field>(xs: &[T]) -> Option<Vec<BigRational>> {
    xs.iter()
        .map(|x| (x as &dyn Any).downcast_ref::<BigRational>().cloned())
        .collect()
}

/// [`resultant`] of rational polynomials without a gcd per operation: with
/// `a`, `b` the common denominators of `f` and `g` (formal degrees `m`,
/// `n`), the integer Sylvester determinant of `a·f`, `b·g` by Bareiss's
/// elimination ([`integer_determinant`]), then one division,
///
/// ```text
/// Res(f, g) = Res(a·f, b·g) / (aⁿ·bᵐ)
/// ```
///
/// (each of the n rows of f's coefficients scaled by a, each of the m rows
/// of g's by b). Gaussian elimination over `BigRational` reduced every
/// entry by a gcd: 106–1 349 times FLINT's `fmpz_poly_resultant` on
/// degrees 3–12 with 10- and 30-digit coefficients, this path 4.6–32 times
/// (`benches/peers/arith`, 2026-11-29, AMD Zen 5).
fn rational_resultant(f: &[BigRational], g: &[BigRational]) -> BigRational {
    let (fi, a) = common_denominator::<BigInt>(f);
    let (gi, b) = common_denominator::<BigInt>(g);
    let (m, n) = (f.len() - 1, g.len() - 1);
    let det = integer_determinant(subresultant_rows(&fi, &gi, 0));
    BigRational::new(det, num_traits::pow(a, n) * num_traits::pow(b, m))
}

/// The coefficients `(S_{1,1}, S_{1,0})` of a linear polynomial that every
/// common root of `f` and `g` satisfies, with `S_{1,1} ≠ 0` exactly when
/// that root is unique: the first subresultant when both formal degrees
/// are at least 2, else the linear one of `f`, `g` itself.
///
/// ```
/// use exact_bezier::{algebra::linear_eliminant, ratio};
/// use exact_bezier::BigRational;
/// let q = |v: i64| ratio::<BigRational>(v, 1);
/// // (x − 1)(x − 2) and (x − 1)(x + 3) share x = 1: S_1 ∝ x − 1.
/// let (a, b) = linear_eliminant(&[q(2), q(-3), q(1)], &[q(-3), q(2), q(1)]);
/// assert_eq!(-b / a, q(1));
/// ```
pub fn linear_eliminant<T: Field>(f: &[T], g: &[T]) -> (T, T) {
    linear_eliminant_by(f, g, determinant)
}

/// [`linear_eliminant`] with the determinant `det`.
fn linear_eliminant_by<T: Clone + Zero>(f: &[T], g: &[T], det: fn(Vec<Vec<T>>) -> T) -> (T, T) {
    match eliminant_matrices(f, g) {
        Ok((one, zero)) => (det(one), det(zero)),
        Err(line) => line,
    }
}

/// The two square matrices of the first subresultant of `f`, `g` (its
/// coefficients of `x` and of 1), or `Err` with the linear polynomial
/// itself when a formal degree is 1.
#[allow(clippy::type_complexity)]
fn eliminant_matrices<T: Clone + Zero>(
    f: &[T],
    g: &[T],
) -> Result<(Vec<Vec<T>>, Vec<Vec<T>>), (T, T)> {
    let (m, n) = (f.len() - 1, g.len() - 1);
    if n == 1 {
        return Err((g[1].clone(), g[0].clone()));
    }
    if m == 1 {
        return Err((f[1].clone(), f[0].clone()));
    }
    let rows = subresultant_rows(f, g, 1);
    let square = |last: usize| {
        let size = rows.len();
        rows.iter()
            .map(|r| {
                let mut row = r[..size - 1].to_vec();
                row.push(r[last].clone());
                row
            })
            .collect::<Vec<_>>()
    };
    let width = m + n - 1;
    Ok((square(width - 2), square(width - 1)))
}

/// A polynomial in `t` whose coefficients are polynomials in `s`,
/// `Σ_k a_k(s) t^k` (a [`BPoly`] with `u = t`, `v = s`), times the lcm of
/// its denominators: the integer coefficients of each `a_k`, lowest power
/// first. The scale changes neither the roots of a resultant nor the
/// ratio `e_0/e_1` of [`linear_eliminant_in_t`] (both determinants of one
/// matrix take the same factor).
fn integer_grid(p: &BPoly<BigRational>) -> Vec<Vec<BigInt>> {
    let all = p.coeffs().iter().flat_map(|a| a.coeffs());
    let (ints, _): (Vec<BigInt>, _) = common_denominator(all);
    let mut ints = ints.into_iter();
    p.coeffs()
        .iter()
        .map(|a| ints.by_ref().take(a.coeffs().len()).collect())
        .collect()
}

/// The coefficients in `t` at the integer `s` (Horner), formal degree
/// `grid.len() − 1`.
fn at_s(grid: &[Vec<BigInt>], s: &BigInt) -> Vec<BigInt> {
    grid.iter()
        .map(|a| a.iter().rev().fold(BigInt::zero(), |acc, c| acc * s + c))
        .collect()
}

/// The weight of each coefficient: `1 + deg_s a_k`, 0 for `a_k = 0`.
fn weights(grid: &[Vec<BigInt>]) -> Vec<usize> {
    grid.iter().map(Vec::len).collect()
}

/// A bound on the `s`-degree of the determinant of a matrix whose entries
/// have the weights `w` (`1 + degree`, 0 for a zero entry): by the
/// Leibniz expansion, at most the sum over the rows of their largest
/// degree, and over the columns likewise (0 when a row or column is zero).
fn degree_bound(w: &[Vec<usize>]) -> usize {
    let sum = |maxes: Vec<usize>| -> usize {
        if maxes.contains(&0) {
            0
        } else {
            maxes.iter().map(|m| m - 1).sum()
        }
    };
    let rows = w
        .iter()
        .map(|r| r.iter().copied().max().unwrap_or(0))
        .collect();
    let width = w.first().map_or(0, Vec::len);
    let cols = (0..width)
        .map(|c| w.iter().map(|r| r[c]).max().unwrap_or(0))
        .collect();
    sum(rows).min(sum(cols))
}

/// `values(s)` at `s = 0 … degree`, interpolated.
fn interpolated(values: &[BigInt]) -> UPoly<BigRational> {
    let samples: Vec<BigRational> = values
        .iter()
        .map(|v| BigRational::from_integer(v.clone()))
        .collect();
    interpolate(&samples)
}

/// `Res_t(F, G)` as a polynomial in `s`, for `F = Σ a_k(s) t^k`,
/// `G = Σ b_k(s) t^k` with `t`-degrees at least 1 (formal degrees: the
/// actual `t`-degrees of `F` and `G`), up to a non-zero constant factor:
/// integer determinants at `s = 0 … D` with `D` the row and column bound
/// of `degree_bound` on the Sylvester matrix (at most `deg_s F · deg_t G
/// + deg_s G · deg_t F`; `mn` rather than `2mn` for two polynomial curves,
/// whose `E_k` have constant coefficients beside `t⁰`).
pub fn resultant_in_t(f: &BPoly<BigRational>, g: &BPoly<BigRational>) -> UPoly<BigRational> {
    let (fi, gi) = (integer_grid(f), integer_grid(g));
    let degree = degree_bound(&subresultant_rows(&weights(&fi), &weights(&gi), 0));
    let values: Vec<BigInt> = (0..=degree)
        .map(|s| {
            let s = BigInt::from(s);
            integer_determinant(subresultant_rows(&at_s(&fi, &s), &at_s(&gi, &s), 0))
        })
        .collect();
    interpolated(&values)
}

/// [`linear_eliminant`] of `F` and `G` in `t`, as two polynomials in `s`
/// (each up to one common non-zero constant factor): at every `s` where
/// `F(s, ·)` and `G(s, ·)` have exactly one common root `t`, it is
/// `−e_0(s) / e_1(s)` with `e_1(s) ≠ 0`. Sampled at as many integers as the
/// larger `degree_bound` of the two matrices asks, both determinants
/// from one specialization.
pub fn linear_eliminant_in_t(
    f: &BPoly<BigRational>,
    g: &BPoly<BigRational>,
) -> (UPoly<BigRational>, UPoly<BigRational>) {
    let (fi, gi) = (integer_grid(f), integer_grid(g));
    let degree = match eliminant_matrices(&weights(&fi), &weights(&gi)) {
        Ok((one, zero)) => degree_bound(&one).max(degree_bound(&zero)),
        Err((one, zero)) => one.max(zero).saturating_sub(1),
    };
    let (ones, zeros): (Vec<BigInt>, Vec<BigInt>) = (0..=degree)
        .map(|s| {
            let s = BigInt::from(s);
            linear_eliminant_by(&at_s(&fi, &s), &at_s(&gi, &s), integer_determinant)
        })
        .unzip();
    (interpolated(&ones), interpolated(&zeros))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ratio;

    fn q(v: i64) -> BigRational {
        ratio(v, 1)
    }

    #[test]
    fn formal_degree_keeps_a_vanishing_leading_coefficient() {
        // f = 0·x² + x − 1 (formal degree 2), g = x − 1: the formal
        // resultant is lc(g)^... · 0 … — with a vanishing leading coefficient
        // of f the Sylvester determinant is lc(g)·Res(x − 1, x − 1) = 0.
        assert_eq!(resultant(&[q(-1), q(1), q(0)], &[q(-1), q(1)]), q(0));
        // f = 0·x² + x − 2: Res = lc(g)^{2−1}·Res(x − 2, x − 1) ≠ 0.
        assert_ne!(resultant(&[q(-2), q(1), q(0)], &[q(-1), q(1)]), q(0));
    }

    proptest::proptest! {
        /// The integer path of rational inputs gives Gaussian elimination's
        /// value over the rationals.
        #[test]
        fn rational_resultant_is_the_sylvester_determinant(
            f in proptest::collection::vec((-50i64..50, 1i64..9), 2..7),
            g in proptest::collection::vec((-50i64..50, 1i64..9), 2..7),
        ) {
            let q = |c: &[(i64, i64)]| -> Vec<BigRational> { c.iter().map(|&(n, d)| ratio(n, d)).collect() };
            let (f, g) = (q(&f), q(&g));
            proptest::prop_assert_eq!(resultant(&f, &g), determinant(subresultant_rows(&f, &g, 0)));
        }
    }

    #[test]
    fn resultant_in_t_matches_pointwise_resultants() {
        // F = t² − s, G = t − s + 1: Res_t = (s − 1)² − s.
        let f = BPoly::new(vec![
            UPoly::new(vec![q(0), q(-1)]),
            UPoly::zero(),
            UPoly::constant(q(1)),
        ]);
        let g = BPoly::new(vec![UPoly::new(vec![q(1), q(-1)]), UPoly::constant(q(1))]);
        let r = resultant_in_t(&f, &g);
        let want = UPoly::new(vec![q(1), q(-3), q(1)]);
        assert_eq!(r.monic(), want);
        // The common root at s is t = s − 1 (from G itself).
        let (e1, e0) = linear_eliminant_in_t(&f, &g);
        assert_eq!(e0.eval(&q(5)) / e1.eval(&q(5)), q(-4));
    }

    #[test]
    fn bareiss_agrees_with_gaussian_elimination() {
        let m: Vec<Vec<i64>> = vec![
            vec![0, 2, -1, 7],
            vec![3, 0, 5, -2],
            vec![1, -4, 0, 1],
            vec![6, 1, -3, 0],
        ];
        let ints = |m: &[Vec<i64>]| -> Vec<Vec<BigInt>> {
            m.iter()
                .map(|r| r.iter().map(|&x| x.into()).collect())
                .collect()
        };
        let rats = |m: &[Vec<i64>]| -> Vec<Vec<BigRational>> {
            m.iter()
                .map(|r| r.iter().map(|&x| q(x)).collect())
                .collect()
        };
        let det = integer_determinant(ints(&m));
        assert_eq!(BigRational::from_integer(det), determinant(rats(&m)));
        // A singular matrix: the last row is the sum of the first two.
        let mut s = m[..3].to_vec();
        s.push(m[0].iter().zip(&m[1]).map(|(a, b)| a + b).collect());
        assert!(integer_determinant(ints(&s)).is_zero());
    }

    #[test]
    fn column_bound_of_polynomial_curves_is_mn() {
        // E = X_A(s) − X_B(t) for cubics: only t⁰ depends on s (degree 3).
        let f = BPoly::new(vec![
            UPoly::new(vec![q(1), q(2), q(0), q(5)]),
            UPoly::constant(q(-3)),
            UPoly::constant(q(2)),
            UPoly::constant(q(1)),
        ]);
        let g = BPoly::new(vec![
            UPoly::new(vec![q(0), q(1), q(-4), q(1)]),
            UPoly::constant(q(1)),
            UPoly::constant(q(-1)),
            UPoly::constant(q(3)),
        ]);
        let (fi, gi) = (integer_grid(&f), integer_grid(&g));
        let bound = degree_bound(&subresultant_rows(&weights(&fi), &weights(&gi), 0));
        assert_eq!(bound, 9);
        // The interpolated resultant is the pointwise one times one constant.
        let r = resultant_in_t(&f, &g);
        for s in [BigRational::new(1.into(), 2.into()), q(7)] {
            let want = resultant(&at_s_q(&f, &s), &at_s_q(&g, &s));
            let lead_ratio = r.eval(&s) / want;
            let at_zero = r.eval(&q(0)) / resultant(&at_s_q(&f, &q(0)), &at_s_q(&g, &q(0)));
            assert_eq!(lead_ratio, at_zero);
        }
    }

    fn at_s_q(p: &BPoly<BigRational>, s: &BigRational) -> Vec<BigRational> {
        p.coeffs().iter().map(|a| a.eval(s)).collect()
    }

    #[test]
    fn first_subresultant_gives_the_common_root() {
        // f = (x − 3)(x² + 1), g = (x − 3)(x + 5): S_1 ∝ x − 3.
        let f = [q(-3), q(1), q(-3), q(1)];
        let g = [q(-15), q(2), q(1)];
        assert_eq!(resultant(&f, &g), q(0));
        let (a, b) = linear_eliminant(&f, &g);
        assert_eq!(-b / a, q(3));
    }
}
