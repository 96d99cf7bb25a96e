//! Vectors of [`Interval`]s: the few operations of 3D geometry, each
//! enclosing the exact result for every choice of the vectors' points
//! (inclusion isotonicity of interval arithmetic: Moore, Kearfott & Cloud,
//! *Introduction to Interval Analysis*, SIAM 2009, Thm. 5.1).

use crate::algebra::Interval;

/// A vector of intervals (a box in space).
pub type IVec = Vec<Interval>;

/// `a + b`.
pub fn add(a: &[Interval], b: &[Interval]) -> IVec {
    a.iter().zip(b).map(|(x, y)| x.add(y)).collect()
}

/// `a − b`.
pub fn sub(a: &[Interval], b: &[Interval]) -> IVec {
    a.iter().zip(b).map(|(x, y)| x.sub(y)).collect()
}

/// `k · a`.
pub fn scale(a: &[Interval], k: &Interval) -> IVec {
    a.iter().map(|x| x.mul(k)).collect()
}

/// `a · b`.
pub fn dot(a: &[Interval], b: &[Interval]) -> Interval {
    a.iter()
        .zip(b)
        .fold(Interval::point(0.0), |acc, (x, y)| acc.add(&x.mul(y)))
}

/// `|a|²`, each square taken with [`Interval::sqr`] (never below 0).
pub fn norm2(a: &[Interval]) -> Interval {
    a.iter()
        .fold(Interval::point(0.0), |acc, x| acc.add(&x.sqr()))
}

/// `a × b` (3D).
pub fn cross(a: &[Interval], b: &[Interval]) -> IVec {
    let m = |i: usize, j: usize| a[i].mul(&b[j]).sub(&a[j].mul(&b[i]));
    vec![m(1, 2), m(2, 0), m(0, 1)]
}
