//! [`HPoint`]: a homogeneous (weighted) control point `(w·P, w)`.
//!
//! Storing `w·P` and `w` side by side turns every rational Bézier algorithm
//! into a polynomial one: de Casteljau, blossoms, elevation and subdivision
//! act on the `dim + 1` coordinates alike and need only ring operations.
//! Division happens once, in [`HPoint::project`].

use crate::algebra::scalar::{Field, MulAcc, Ordered, Ring, Scalar, Tolerance};
use crate::error::Error;

/// A homogeneous point: `coords = [w·x₁, …, w·x_d, w]` (weight last).
///
/// # Examples
///
/// ```
/// use exact_bezier::{hpoint::HPoint, ratio};
/// use exact_bezier::BigRational;
/// let p: HPoint<BigRational> = HPoint::from_point(&[ratio(1, 2), ratio(3, 1)], &ratio(2, 1));
/// assert_eq!(p.coords, vec![ratio(1, 1), ratio(6, 1), ratio(2, 1)]);
/// assert_eq!(p.project().unwrap(), vec![ratio(1, 2), ratio(3, 1)]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HPoint<T> {
    /// `[w·x₁, …, w·x_d, w]`.
    pub coords: Vec<T>,
}

impl<T: Ring> HPoint<T> {
    /// The point `P` with weight 1: `(P, 1)`.
    pub fn from_cartesian(point: &[T]) -> Self {
        let mut coords = point.to_vec();
        coords.push(T::one());
        HPoint { coords }
    }

    /// Spatial dimension `d` (the number of coordinates less the weight).
    pub fn dim(&self) -> usize {
        self.coords.len() - 1
    }

    /// The weight `w`.
    pub fn weight(&self) -> &T {
        &self.coords[self.coords.len() - 1]
    }

    /// The weighted coordinates `w·P`.
    pub fn weighted(&self) -> &[T] {
        &self.coords[..self.coords.len() - 1]
    }

    /// The zero vector of `d + 1` coordinates.
    pub fn zero(dim: usize) -> Self {
        HPoint {
            coords: vec![T::zero(); dim + 1],
        }
    }

    /// `k·self`.
    pub fn scale(&self, k: &T) -> Self {
        HPoint {
            coords: self.coords.iter().map(|x| x.clone() * k).collect(),
        }
    }

    /// `self + other`.
    pub fn add(&self, other: &Self) -> Self {
        HPoint {
            coords: self
                .coords
                .iter()
                .zip(&other.coords)
                .map(|(x, y)| x.clone() + y)
                .collect(),
        }
    }

    /// `self − other`.
    pub fn sub(&self, other: &Self) -> Self {
        HPoint {
            coords: self
                .coords
                .iter()
                .zip(&other.coords)
                .map(|(x, y)| x.clone() - y)
                .collect(),
        }
    }
}

/// # The de Casteljau step
impl<T: MulAcc> HPoint<T> {
    /// `(1 − t)·self + t·other`, the de Casteljau step.
    pub fn lerp(&self, other: &Self, t: &T) -> Self {
        let s = T::one() - t;
        self.combine(&s, other, t)
    }

    /// `a·self + b·other`.
    pub fn combine(&self, a: &T, other: &Self, b: &T) -> Self {
        let mut out = self.clone();
        out.combine_assign(a, other, b);
        out
    }

    /// `self ← a·self + b·other` in place, one [`MulAcc::mul_acc`] per
    /// coordinate (a scalar type may do each in one pass: `Poly` merges
    /// the four streams of a step by binomials at once).
    pub fn combine_assign(&mut self, a: &T, other: &Self, b: &T) {
        for (x, y) in self.coords.iter_mut().zip(&other.coords) {
            T::mul_acc(x, a, b, y);
        }
    }
}

/// One de Casteljau step on `row[i]`: `row[i] ← a·row[i] + b·row[i + 1]`.
pub(crate) fn step_in_place<T: MulAcc>(row: &mut [HPoint<T>], i: usize, a: &T, b: &T) {
    let (head, tail) = row.split_at_mut(i + 1);
    head[i].combine_assign(a, &tail[0], b);
}

/// # Comparisons
impl<T: Scalar> HPoint<T> {
    /// `(w·P, w)` from a Cartesian point `P` and weight `w`.
    pub fn from_point(point: &[T], weight: &T) -> Self {
        let mut coords: Vec<T> = point.iter().map(|x| x.mul_scalar(weight)).collect();
        coords.push(weight.clone());
        HPoint { coords }
    }

    /// Are all coordinates zero (within `tol` for `f64`)?
    pub fn is_zero_within(&self, tol: Tolerance) -> bool {
        self.coords.iter().all(|x| x.is_zero_within(tol))
    }

    /// Do `self` and `other` represent the same projective point, i.e. is
    /// `self.coords[i]·other.w = other.coords[i]·self.w` for all i? (Cross
    /// multiplication: no division, valid for every scalar.)
    pub fn same_projective_point(&self, other: &Self, tol: Tolerance) -> bool {
        let (w1, w2) = (self.weight(), other.weight());
        self.coords
            .iter()
            .zip(&other.coords)
            .all(|(a, b)| (a.clone() * w2 - &(b.clone() * w1)).is_zero_within(tol))
    }
}

impl<T> HPoint<T> {
    /// Apply `f` to every coordinate (e.g. to change the scalar type).
    pub fn map<U>(&self, f: &impl Fn(&T) -> U) -> HPoint<U> {
        HPoint {
            coords: self.coords.iter().map(f).collect(),
        }
    }

    /// Apply `f` to every coordinate, `None` if it fails on any (e.g. a
    /// real algebraic point to a rational one).
    ///
    /// ```
    /// use exact_bezier::{hpoint::HPoint, ratio, BigRational};
    /// let p: HPoint<i64> = HPoint { coords: vec![1, 2, 4] };
    /// let halves = p.try_map(&|x| (x % 2 == 0).then(|| ratio::<BigRational>(*x, 2)));
    /// assert!(halves.is_none());
    /// let q = HPoint { coords: vec![2, 4] }.try_map(&|x| Some(*x / 2));
    /// assert_eq!(q.unwrap().coords, vec![1, 2]);
    /// ```
    pub fn try_map<U>(&self, f: &impl Fn(&T) -> Option<U>) -> Option<HPoint<U>> {
        Some(HPoint {
            coords: self.coords.iter().map(f).collect::<Option<_>>()?,
        })
    }
}

impl<T: Field> HPoint<T> {
    /// The Cartesian point `w·P / w`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] when the weight is zero.
    pub fn project(&self) -> Result<Vec<T>, Error> {
        let w = self.weight();
        if w.is_zero() {
            return Err(Error::PointAtInfinity);
        }
        Ok(self.weighted().iter().map(|x| x.clone() / w).collect())
    }
}

/// One de Casteljau pass over a row of homogeneous points:
/// `b_i^{k} = (1 − t)·b_i^{k−1} + t·b_{i+1}^{k−1}`; returns `b_0^n`.
///
/// **Panics if `points` is empty.**
///
/// Reference: source 001 (lecture), "de Casteljau算法", P_i^k recursion.
pub fn de_casteljau<T: Scalar>(points: &[HPoint<T>], t: &T) -> HPoint<T> {
    de_casteljau_hom(points, &(T::one() - t), t)
}

/// de Casteljau at the homogeneous parameter `(a : b)`:
/// `b_i^{k} = a·b_i^{k−1} + b·b_{i+1}^{k−1}`, which is `(a + b)ⁿ` times the
/// value at `t = b/(a + b)`. Ring operations only: with integer control
/// points and `t = p/q`, `(a, b) = (q − p, p)` keeps every step integral
/// (fraction-free evaluation).
///
/// **Panics if `points` is empty.**
///
/// ```
/// use exact_bezier::{hpoint::de_casteljau, hpoint::de_casteljau_hom, hpoint::HPoint, ratio};
/// use exact_bezier::BigRational;
/// let pts: Vec<HPoint<BigRational>> = (0..4).map(|i| HPoint::from_cartesian(&[ratio(i * i, 1)])).collect();
/// let t = ratio(1, 3);
/// let scaled = de_casteljau_hom(&pts, &ratio(2, 1), &ratio(1, 1)); // (2 : 1) is t = 1/3, times 3³
/// assert_eq!(scaled, de_casteljau(&pts, &t).scale(&ratio(27, 1)));
/// ```
pub fn de_casteljau_hom<T: MulAcc>(points: &[HPoint<T>], a: &T, b: &T) -> HPoint<T> {
    let mut row: Vec<HPoint<T>> = points.to_vec();
    for k in (1..row.len()).rev() {
        for i in 0..k {
            step_in_place(&mut row, i, a, b);
        }
    }
    row.swap_remove(0)
}

/// Rows of homogeneous points `(w_ab·P_ab, w_ab)` from rows of Cartesian
/// points and of weights of the same shape (a rect grid or the rows of a
/// triangle). `layout` names the shape in the error ("grid", "rows");
/// `label(a, b)` names the weight in row `a`, position `b` (`"{0,2}"`).
///
/// # Errors
///
/// [`Error::Shape`] if the weights do not have the shape of the points;
/// [`Error::Weight`] for the first zero weight.
pub(crate) fn hom_rows<T: Scalar>(
    points: &[Vec<Vec<T>>],
    weights: &[Vec<T>],
    layout: &str,
    label: impl Fn(usize, usize) -> String,
) -> Result<Vec<Vec<HPoint<T>>>, Error> {
    if points.len() != weights.len() || points.iter().zip(weights).any(|(p, w)| p.len() != w.len())
    {
        return Err(Error::Shape(format!(
            "the weight {layout} must have the same shape as the point {layout}"
        )));
    }
    for (a, row) in weights.iter().enumerate() {
        if let Some(b) = row.iter().position(|w| w.is_zero()) {
            return Err(Error::Weight {
                index: format!("w_{}", label(a, b)),
                value: "0".into(),
            });
        }
    }
    Ok(points
        .iter()
        .zip(weights)
        .map(|(pr, wr)| {
            pr.iter()
                .zip(wr)
                .map(|(p, w)| HPoint::from_point(p, w))
                .collect()
        })
        .collect())
}

/// Checks that every point of `rows` has the length of `rows[0][0]`, at
/// least 2 (one coordinate and the weight). `mismatch(a, b, dim, expected)`
/// words the error for the point in row `a`, position `b`, of dimension
/// `dim` where `expected` was wanted.
///
/// **Panics if `rows` or `rows[0]` is empty.**
///
/// # Errors
///
/// [`Error::Shape`] for points without coordinates or of mixed dimension.
pub(crate) fn check_same_dimension<T>(
    rows: &[Vec<HPoint<T>>],
    mismatch: impl Fn(usize, usize, usize, usize) -> String,
) -> Result<(), Error> {
    let len = rows[0][0].coords.len();
    if len < 2 {
        return Err(Error::Shape(
            "control points need at least one coordinate".into(),
        ));
    }
    for (a, row) in rows.iter().enumerate() {
        if let Some(b) = row.iter().position(|p| p.coords.len() != len) {
            let dim = row[b].coords.len() - 1;
            return Err(Error::Shape(mismatch(a, b, dim, len - 1)));
        }
    }
    Ok(())
}

/// Checks that every weight in `rows` is positive (exactly for exact `T`).
/// `label(a, b)` names the weight in row `a`, position `b` (`"{0,2}"`).
///
/// # Errors
///
/// [`Error::Weight`] naming the first non-positive weight, row by row.
pub(crate) fn check_positive_weights<T: Ordered>(
    rows: &[Vec<HPoint<T>>],
    label: impl Fn(usize, usize) -> String,
) -> Result<(), Error> {
    for (a, row) in rows.iter().enumerate() {
        let bad = row
            .iter()
            .position(|p| !p.weight().is_positive_within(Tolerance::EXACT));
        if let Some(b) = bad {
            return Err(Error::Weight {
                index: format!("w_{}", label(a, b)),
                value: format!("{}", row[b].weight().to_f64()),
            });
        }
    }
    Ok(())
}
