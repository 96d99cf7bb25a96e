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

/// The determinant of a square matrix over Q, fraction-free: each row is
/// scaled to integers by the lcm of its denominators, then Bareiss's
/// elimination keeps every entry an integer (each division is exact):
///
/// ```text
/// a_ij ← (a_ij a_kk − a_ik a_kj) / a_{k−1,k−1}      det = a_{n−1,n−1} / ∏ row scales
/// ```
///
/// No gcd per operation, unlike Gaussian elimination over `BigRational`.
///
/// Reference: Bareiss, *Sylvester's identity and multistep
/// integer-preserving Gaussian elimination*, Math. Comp. 22 (1968) 565–578.
pub(crate) fn rational_determinant(m: Vec<Vec<BigRational>>) -> BigRational {
    let n = m.len();
    if n == 0 {
        return BigRational::one();
    }
    let mut scale = BigInt::one();
    let mut a: Vec<Vec<BigInt>> = m
        .iter()
        .map(|row| {
            let (ints, l) = common_denominator(row);
            scale *= l;
            ints
        })
        .collect();
    let mut negate = false;
    let mut prev = BigInt::one();
    for k in 0..n {
        let Some(p) = (k..n).find(|&r| !a[r][k].is_zero()) else {
            return BigRational::zero();
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
    let det = BigRational::new(prev, scale);
    if negate {
        -det
    } else {
        det
    }
}

/// The rows of the `j`-th subresultant matrix of `f`, `g` (coefficient
/// slices, lowest power first, formal degrees `len − 1`), highest power
/// first in each row.
fn subresultant_rows<T: Field>(f: &[T], g: &[T], j: usize) -> Vec<Vec<T>> {
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
pub fn resultant<T: Field>(f: &[T], g: &[T]) -> T {
    determinant(subresultant_rows(f, g, 0))
}

/// [`resultant`] over Q by the fraction-free [`rational_determinant`].
pub(crate) fn rational_resultant(f: &[BigRational], g: &[BigRational]) -> BigRational {
    rational_determinant(subresultant_rows(f, g, 0))
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
fn linear_eliminant_by<T: Field>(f: &[T], g: &[T], det: fn(Vec<Vec<T>>) -> T) -> (T, T) {
    let (m, n) = (f.len() - 1, g.len() - 1);
    if n == 1 {
        return (g[1].clone(), g[0].clone());
    }
    if m == 1 {
        return (f[1].clone(), f[0].clone());
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
    (det(square(width - 2)), det(square(width - 1)))
}

/// A polynomial in `t` whose coefficients are polynomials in `s`:
/// `Σ_k a_k(s) t^k` (a [`BPoly`] with `u = t`, `v = s`), with its formal
/// degree in `t` and its degree in `s`.
fn shape(p: &BPoly<BigRational>) -> (usize, usize) {
    let deg_s = p
        .coeffs()
        .iter()
        .filter_map(UPoly::degree)
        .max()
        .unwrap_or(0);
    (p.deg_u().unwrap_or(0), deg_s)
}

/// The coefficients in `t` of `p` at the parameter value `s`, formal degree
/// `deg_t`.
fn at_s(p: &BPoly<BigRational>, deg_t: usize, s: &BigRational) -> Vec<BigRational> {
    (0..=deg_t)
        .map(|k| {
            p.coeffs()
                .get(k)
                .map_or_else(BigRational::default, |a| a.eval(s))
        })
        .collect()
}

/// `values(s)` at `s = 0 … degree`, interpolated.
fn interpolated(degree: usize, values: impl Fn(&BigRational) -> BigRational) -> UPoly<BigRational> {
    let samples: Vec<BigRational> = (0..=degree)
        .map(|k| values(&BigRational::from_integer(k.into())))
        .collect();
    interpolate(&samples)
}

/// `Res_t(F, G)` as a polynomial in `s`, for `F = Σ a_k(s) t^k`,
/// `G = Σ b_k(s) t^k` with `t`-degrees at least 1 (formal degrees: the
/// actual `t`-degrees of `F` and `G`).
///
/// Degree bound: `deg_s F · deg_t G + deg_s G · deg_t F`.
pub fn resultant_in_t(f: &BPoly<BigRational>, g: &BPoly<BigRational>) -> UPoly<BigRational> {
    let ((mf, df), (mg, dg)) = (shape(f), shape(g));
    interpolated(df * mg + dg * mf, |s| {
        rational_resultant(&at_s(f, mf, s), &at_s(g, mg, s))
    })
}

/// [`linear_eliminant`] of `F` and `G` in `t`, as two polynomials in `s`:
/// at every `s` where `F(s, ·)` and `G(s, ·)` have exactly one common root
/// `t`, it is `−e_0(s) / e_1(s)` with `e_1(s) ≠ 0`.
pub fn linear_eliminant_in_t(
    f: &BPoly<BigRational>,
    g: &BPoly<BigRational>,
) -> (UPoly<BigRational>, UPoly<BigRational>) {
    let ((mf, df), (mg, dg)) = (shape(f), shape(g));
    // Rows: mg − 1 of F and mf − 1 of G (or one polynomial itself).
    let degree = match (mf, mg) {
        (_, 1) => dg,
        (1, _) => df,
        _ => df * (mg - 1) + dg * (mf - 1),
    };
    let pair = |s: &BigRational| {
        linear_eliminant_by(&at_s(f, mf, s), &at_s(g, mg, s), rational_determinant)
    };
    (
        interpolated(degree, |s| pair(s).0),
        interpolated(degree, |s| pair(s).1),
    )
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
        let r = |n: i64, d: i64| ratio::<BigRational>(n, d);
        let m = vec![
            vec![r(0, 1), r(2, 3), r(-1, 5), r(7, 2)],
            vec![r(3, 4), r(0, 1), r(5, 1), r(-2, 9)],
            vec![r(1, 7), r(-4, 3), r(0, 1), r(1, 1)],
            vec![r(6, 1), r(1, 2), r(-3, 8), r(0, 1)],
        ];
        assert_eq!(rational_determinant(m.clone()), determinant(m.clone()));
        // A singular matrix: the last row is the sum of the first two.
        let mut s = m[..3].to_vec();
        s.push(m[0].iter().zip(&m[1]).map(|(a, b)| a + b).collect());
        assert_eq!(rational_determinant(s), r(0, 1));
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
