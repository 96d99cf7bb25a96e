//! The Bernstein basis `B_{i,n}(t) = C(n, i) tⁱ (1 − t)^{n−i}`, generic over
//! the scalar.
//!
//! Reference: source 001 (lecture), "定义" and "伯恩斯坦多项式的性质".

use crate::algebra::scalar::{binomial_scalar, Scalar};

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
    let s = T::one() - t;
    let mut b = vec![T::one()];
    for _ in 0..n {
        let mut next = vec![T::zero(); b.len() + 1];
        for (i, bi) in b.iter().enumerate() {
            next[i] = next[i].clone() + &(bi.clone() * &s);
            next[i + 1] = next[i + 1].clone() + &(bi.clone() * t);
        }
        b = next;
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    use num_rational::BigRational;

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
