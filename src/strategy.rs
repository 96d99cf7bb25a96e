//! proptest strategies for exact inputs (feature `proptest`): small
//! rationals (numerator and denominator within ±1000), positive weights, and
//! random curves and patches. Used by the property tests in `tests/`.

use crate::curve::RationalCurve;
use crate::rect::RectPatch;
use crate::tri::TriPatch;
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::collection::vec;
use proptest::prelude::*;

/// A rational `p/q` with `|p| ≤ 1000`, `1 ≤ q ≤ 1000`.
pub fn small_rational() -> impl Strategy<Value = BigRational> {
    (-1000i64..=1000, 1i64..=1000)
        .prop_map(|(p, q)| BigRational::new(BigInt::from(p), BigInt::from(q)))
}

/// A rational in `[lo/den, hi/den]`, for parameters like `t ∈ [0, 1]`.
pub fn rational_in(lo: i64, hi: i64, den: i64) -> impl Strategy<Value = BigRational> {
    (lo..=hi).prop_map(move |p| BigRational::new(BigInt::from(p), BigInt::from(den)))
}

/// A parameter in `[0, 1]` with denominator up to 1000.
pub fn unit_parameter() -> impl Strategy<Value = BigRational> {
    (1i64..=1000).prop_flat_map(|q| (0..=q).prop_map(move |p| BigRational::new(p.into(), q.into())))
}

/// A parameter strictly inside `(0, 1)`, e.g. a Möbius α.
pub fn open_unit_parameter() -> impl Strategy<Value = BigRational> {
    (2i64..=1000).prop_flat_map(|q| (1..q).prop_map(move |p| BigRational::new(p.into(), q.into())))
}

/// A positive weight `p/q` with `1 ≤ p, q ≤ 1000`.
pub fn positive_weight() -> impl Strategy<Value = BigRational> + Clone {
    (1i64..=1000, 1i64..=1000).prop_map(|(p, q)| BigRational::new(p.into(), q.into()))
}

/// A point of dimension `dim` with small rational coordinates.
pub fn point(dim: usize) -> impl Strategy<Value = Vec<BigRational>> {
    vec(small_rational(), dim)
}

/// A rational curve of the given degree and dimension, positive weights.
pub fn curve(degree: usize, dim: usize) -> impl Strategy<Value = RationalCurve<BigRational>> {
    (
        vec(point(dim), degree + 1),
        vec(positive_weight(), degree + 1),
    )
        .prop_map(|(p, w)| RationalCurve::new(p, w).expect("shapes match"))
}

/// A rational tensor-product patch of bidegree `(m, n)`, positive weights.
pub fn rect(m: usize, n: usize, dim: usize) -> impl Strategy<Value = RectPatch<BigRational>> {
    rect_weighted(m, n, dim, positive_weight())
}

/// [`rect`] with its weights drawn from `weight` (e.g. a narrower range,
/// for tests of the `f64` path whose round-off grows with the weights'
/// spread).
pub fn rect_weighted<W: Strategy<Value = BigRational> + Clone>(
    m: usize,
    n: usize,
    dim: usize,
    weight: W,
) -> impl Strategy<Value = RectPatch<BigRational>> {
    (
        vec(vec(point(dim), n + 1), m + 1),
        vec(vec(weight, n + 1), m + 1),
    )
        .prop_map(|(p, w)| RectPatch::new(p, w).expect("shapes match"))
}

/// A rational triangular patch of degree `n`, positive weights.
pub fn tri(n: usize, dim: usize) -> impl Strategy<Value = TriPatch<BigRational>> {
    let rows: Vec<usize> = (0..=n).map(|j| n - j + 1).collect();
    let pts = rows
        .iter()
        .map(|&len| vec(point(dim), len))
        .collect::<Vec<_>>();
    let ws = rows
        .iter()
        .map(|&len| vec(positive_weight(), len))
        .collect::<Vec<_>>();
    (pts, ws).prop_map(|(p, w)| TriPatch::new(p, w).expect("shapes match"))
}
