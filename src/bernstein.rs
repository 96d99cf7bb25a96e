//! The Bernstein basis `B_{i,n}(t) = C(n, i) tⁱ (1 − t)^{n−i}`, generic over
//! the scalar, and the change to the power basis `1, t, …, tⁿ` and back.
//!
//! Reference: source 001 (lecture), "定义" and "伯恩斯坦多项式的性质".

use crate::algebra::scalar::{binomial_scalar, Field, Scalar};

/// `B_{i,n}(t) = C(n, i) tⁱ (1 − t)^{n−i}` (0 when `i > n`).
///
/// # Examples
///
/// ```
/// use exact_bezier::{bernstein::bernstein, ratio};
/// use exact_bezier::BigRational;
/// let b: BigRational = bernstein(1, 3, &ratio(1, 2));
/// assert_eq!(b, ratio(3, 8));
/// ```
pub fn bernstein<T: Scalar>(i: usize, n: usize, t: &T) -> T {
    if i > n {
        return T::zero();
    }
    let s = T::one() - t;
    binomial_scalar::<T>(n, i) * t.pow_u32(i as u32) * s.pow_u32((n - i) as u32)
}

/// All `n + 1` values `B_{0,n}(t), …, B_{n,n}(t)`, computed by the recursion
/// `B_{i,n} = (1 − t) B_{i,n−1} + t B_{i−1,n−1}` (no binomials, no powers).
///
/// ```
/// use exact_bezier::{bernstein::bernstein_all, ratio};
/// use exact_bezier::BigRational;
/// let b: Vec<BigRational> = bernstein_all(2, &ratio(1, 3));
/// assert_eq!(b, vec![ratio(4, 9), ratio(4, 9), ratio(1, 9)]);
/// ```
pub fn bernstein_all<T: Scalar>(n: usize, t: &T) -> Vec<T> {
    let mut b = vec![T::zero(); n + 1];
    bernstein_all_into(t, &mut b);
    b
}

/// [`bernstein_all`] into `b`, without allocating: `b[i] = B_{i,n}(t)`,
/// `n + 1 = b.len()`, by the same recursion, each row overwriting the
/// last from its high end. An empty `b` is left empty.
///
/// ```
/// use exact_bezier::bernstein::bernstein_all_into;
/// let mut b = [0.0; 4];
/// bernstein_all_into(&0.5, &mut b);
/// assert_eq!(b, [0.125, 0.375, 0.375, 0.125]);
/// ```
pub fn bernstein_all_into<T: Scalar>(t: &T, b: &mut [T]) {
    bernstein_stages_into(t, b, |_, _| {});
}

/// [`bernstein_all_into`], handing each stage of the recursion to `stage`
/// as it is done: `stage(r, &b[..=r])` with the basis of degree `r`
/// (`r = 0..b.len()`), bit for bit what [`bernstein_all_into`] gives for
/// that degree. One recursion serves every degree up to `b.len() − 1`.
///
/// ```
/// use exact_bezier::bernstein::bernstein_stages_into;
/// let mut b = [0.0; 3];
/// let mut linear = Vec::new();
/// bernstein_stages_into(&0.25, &mut b, |r, basis| if r == 1 { linear = basis.to_vec() });
/// assert_eq!(linear, [0.75, 0.25]);
/// assert_eq!(b, [0.5625, 0.375, 0.0625]);
/// ```
pub fn bernstein_stages_into<T: Scalar>(t: &T, b: &mut [T], mut stage: impl FnMut(usize, &[T])) {
    let Some(first) = b.first_mut() else {
        return;
    };
    *first = T::one();
    stage(0, &b[..1]);
    let s = T::one() - t;
    for r in 1..b.len() {
        b[r] = b[r - 1].clone() * t;
        for i in (1..r).rev() {
            b[i] = b[i].clone() * &s + &(b[i - 1].clone() * t);
        }
        b[0] = b[0].clone() * &s;
        stage(r, &b[..=r]);
    }
}

/// The power-basis coefficients `a_0 … a_n` of `Σ_i b_i B_{i,n}(t)`
/// (`n + 1 = b.len()`): `Σ_i b_i B_{i,n}(t) = Σ_k a_k tᵏ` with
///
/// ```text
/// a_k = Σ_{i≤k} C(n, k) C(k, i) (−1)^{k−i} b_i
/// ```
///
/// (expand `(1 − t)^{n−i}` in `B_{i,n}` and collect `tᵏ`; `C(n,i)·C(n−i,k−i)
/// = C(n,k)·C(k,i)`). The inverse is [`power_to_bernstein`].
///
/// ```
/// use exact_bezier::{bernstein::bernstein_to_power, ratio};
/// use exact_bezier::BigRational;
/// let q = |n: i64| ratio::<BigRational>(n, 1);
/// // (1 − t)² + 2·2t(1 − t) + 4t² = 1 + 2t + t²:
/// // a_0 = b_0 = 1, a_1 = 2(b_1 − b_0) = 2, a_2 = b_0 − 2b_1 + b_2 = 1.
/// assert_eq!(bernstein_to_power(&[q(1), q(2), q(4)]), vec![q(1), q(2), q(1)]);
/// ```
pub fn bernstein_to_power<T: Scalar>(b: &[T]) -> Vec<T> {
    bernstein_to_power_with(b, &binomial_rows(b.len().saturating_sub(1)))
}

/// [`bernstein_to_power`] with Pascal's triangle of its degree given
/// (`c = binomial_rows(b.len() − 1)`), for callers that convert many
/// sequences of one length.
pub(crate) fn bernstein_to_power_with<T: Scalar>(b: &[T], c: &[Vec<T>]) -> Vec<T> {
    let mut out = Vec::with_capacity(b.len());
    bernstein_to_power_into(b, c, &mut out);
    out
}

/// [`bernstein_to_power_with`] written into `out` (cleared first), so that
/// a caller converting many sequences reuses one buffer.
pub(crate) fn bernstein_to_power_into<T: Scalar>(b: &[T], c: &[Vec<T>], out: &mut Vec<T>) {
    let n = b.len().saturating_sub(1);
    out.clear();
    out.extend((0..b.len()).map(|k| {
        let sum = (0..=k).fold(T::zero(), |acc, i| {
            let term = c[k][i].clone() * &b[i];
            if (k - i) % 2 == 0 {
                acc + term
            } else {
                acc - term
            }
        });
        c[n][k].clone() * &sum
    }));
}

/// Pascal's triangle `C(k, i)` for `k ≤ n` as scalars: `O(n²)` integer
/// additions (`C(k, i) = C(k−1, i−1) + C(k−1, i)`) for a whole change of
/// basis, instead of a product and a division per coefficient. The values
/// are those of [`binomial_scalar`] (exact integers, each converted once).
pub(crate) fn binomial_rows<T: Scalar>(n: usize) -> Vec<Vec<T>> {
    let mut ints: Vec<Vec<Option<u128>>> = vec![vec![Some(1)]];
    for k in 1..=n {
        let prev = &ints[k - 1];
        let row = (0..=k)
            .map(|i| {
                let left = i.checked_sub(1).map_or(Some(0), |j| prev[j]);
                let right = prev.get(i).copied().unwrap_or(Some(0));
                left?.checked_add(right?)
            })
            .collect();
        ints.push(row);
    }
    ints.iter()
        .enumerate()
        .map(|(k, row)| {
            row.iter()
                .enumerate()
                .map(|(i, c)| match c.and_then(|c| i64::try_from(c).ok()) {
                    Some(c) => T::from_i64(c),
                    None => binomial_scalar(k, i),
                })
                .collect()
        })
        .collect()
}

/// The Bernstein coefficients `b_0 … b_n` of degree `n` of `Σ_k a_k tᵏ`
/// (needs `a.len() ≤ n + 1`), the inverse of [`bernstein_to_power`]:
///
/// ```text
/// b_i = Σ_{k≤i} C(i, k) / C(n, k) · a_k
/// ```
///
/// (`tᵏ = Σ_{i≥k} C(i,k)/C(n,k) B_{i,n}(t)`). A degree `n` above the
/// polynomial's gives its degree-elevated coefficients.
///
/// ```
/// use exact_bezier::{bernstein::power_to_bernstein, ratio};
/// use exact_bezier::BigRational;
/// let q = |n: i64, d: i64| ratio::<BigRational>(n, d);
/// // 1 + 2t + t²: b_0 = 1, b_1 = 1 + 2/2 = 2, b_2 = 1 + 2 + 1 = 4 in degree 2;
/// assert_eq!(power_to_bernstein(&[q(1, 1), q(2, 1), q(1, 1)], 2), vec![q(1, 1), q(2, 1), q(4, 1)]);
/// // in degree 3: b_1 = 1 + 2/3, b_2 = 1 + 2·2/3 + 1/3, b_3 = 4.
/// assert_eq!(
///     power_to_bernstein(&[q(1, 1), q(2, 1), q(1, 1)], 3),
///     vec![q(1, 1), q(5, 3), q(8, 3), q(4, 1)]
/// );
/// ```
pub fn power_to_bernstein<T: Field>(a: &[T], n: usize) -> Vec<T> {
    let c = binomial_rows::<T>(n);
    (0..=n)
        .map(|i| {
            (0..=i.min(a.len().saturating_sub(1)))
                .filter(|&k| k < a.len())
                .fold(T::zero(), |acc, k| acc + c[i][k].clone() * &a[k] / &c[n][k])
        })
        .collect()
}

/// The coefficients `p_0 … p_k` of degree `k` whose degree elevation to
/// `n = b.len() − 1` is `b`, or `None` if `b` is not such an elevation: the
/// exact inverse of elevation, in one pass of `O(n·k)` operations.
///
/// Elevation from `k` to `n` multiplies `Σ_j p_j B_{j,k}(t)` by
/// `1 = ((1 − t) + t)^{n−k}`, so
///
/// ```text
/// C(n, i) b_i = Σ_j C(k, j) C(n − k, i − j) p_j      (i = 0 … n)
/// ```
///
/// The equations `i = 0 … k` are triangular with diagonal `C(k, i) ≠ 0`:
/// `p_i = (C(n, i) b_i − Σ_{j<i} C(k, j) C(n−k, i−j) p_j) / C(k, i)`. The
/// others, `i = k+1 … n`, are then checked exactly; the first that fails
/// ends the check.
///
/// ```
/// use exact_bezier::{bernstein::{power_to_bernstein, reduce_elevated}, ratio};
/// use exact_bezier::BigRational;
/// let q = |n: i64| ratio::<BigRational>(n, 1);
/// // 1 + 2t + t² written in degree 5, then reduced back to degree 2:
/// let b5 = power_to_bernstein(&[q(1), q(2), q(1)], 5);
/// assert_eq!(reduce_elevated(&b5, 2), Some(vec![q(1), q(2), q(4)]));
/// assert_eq!(reduce_elevated(&b5, 1), None);
/// ```
pub fn reduce_elevated<T: Field>(b: &[T], k: usize) -> Option<Vec<T>> {
    let n = b.len().checked_sub(1)?;
    if k > n {
        return None;
    }
    let c = binomial_rows::<T>(n);
    let elevated_sum = |p: &[T], i: usize, upto: usize| {
        (i.saturating_sub(n - k)..=i.min(upto)).fold(T::zero(), |acc, j| {
            acc + c[k][j].clone() * &c[n - k][i - j] * &p[j]
        })
    };
    let mut p: Vec<T> = Vec::with_capacity(k + 1);
    for i in 0..=k {
        let below = if i == 0 {
            T::zero()
        } else {
            elevated_sum(&p, i, i - 1)
        };
        p.push((c[n][i].clone() * &b[i] - below) / &c[k][i]);
    }
    let matches = (k + 1..=n).all(|i| elevated_sum(&p, i, k) == c[n][i].clone() * &b[i]);
    matches.then_some(p)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    use num_rational::BigRational;

    #[test]
    fn pascal_rows_are_binomials() {
        let rows = binomial_rows::<BigRational>(70);
        for (k, row) in rows.iter().enumerate() {
            for (i, c) in row.iter().enumerate() {
                assert_eq!(*c, binomial_scalar::<BigRational>(k, i));
            }
        }
    }

    /// Elevation by `(1 − t + t)^r` and its exact inverse, against the
    /// power basis (a second route): reducing the degree-`n` form of a
    /// degree-`k` polynomial gives back its degree-`k` coefficients, and no
    /// lower degree works.
    #[test]
    fn reduce_elevated_inverts_elevation() {
        let q = |a: i64, b: i64| ratio::<BigRational>(a, b);
        let power = [q(3, 2), q(-1, 1), q(0, 1), q(5, 7)];
        let own = power_to_bernstein(&power, 3);
        for n in 3..20 {
            let high = power_to_bernstein(&power, n);
            assert_eq!(reduce_elevated(&high, 3), Some(own.clone()));
            assert_eq!(reduce_elevated(&high, 2), None);
            assert_eq!(reduce_elevated(&high, n), Some(high.clone()));
        }
    }

    #[test]
    fn recursion_matches_closed_form() {
        let t: BigRational = ratio(2, 7);
        for n in 0..8 {
            let all = bernstein_all(n, &t);
            for (i, v) in all.iter().enumerate() {
                assert_eq!(*v, bernstein(i, n, &t));
            }
        }
    }
}
