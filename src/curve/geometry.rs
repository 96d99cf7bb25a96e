//! Geometry of rational Bézier curves: curvature (exact κ², and κ through
//! `f64`), the lecture's end-point curvature, affine maps of the control
//! points, the Möbius invariants of the weights and the conic type of a
//! rational quadratic.
//!
//! Conventions as in [`RationalCurve`]: `c_i = (w_i P_i, w_i)`,
//! `X(t) = H(t)/w(t)`. Curvature in any dimension uses the Lagrange identity
//! `|a × b|² = |a|²|b|² − (a·b)²`, so no square root and no cross product of
//! a fixed dimension are needed:
//!
//! ```text
//! κ² = |X' × X''|² / |X'|⁶
//! ```

use crate::algebra::scalar::{Field, Ordered, Scalar};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;

/// `a·b`.
fn dot<T: Scalar>(a: &[T], b: &[T]) -> T {
    a.iter()
        .zip(b)
        .fold(T::zero(), |acc, (x, y)| acc + &(x.clone() * y))
}

/// `|a × b|² = |a|²|b|² − (a·b)²` (Lagrange's identity, any dimension).
///
/// ```
/// use exact_bezier::{curve::cross_norm_sq, ratio};
/// use exact_bezier::BigRational;
/// let a = [ratio::<BigRational>(1, 1), ratio(0, 1), ratio(0, 1)];
/// let b = [ratio::<BigRational>(1, 1), ratio(2, 1), ratio(0, 1)];
/// assert_eq!(cross_norm_sq(&a, &b), ratio(4, 1)); // a × b = (0, 0, 2)
/// ```
pub fn cross_norm_sq<T: Scalar>(a: &[T], b: &[T]) -> T {
    let ab = dot(a, b);
    dot(a, a) * &dot(b, b) - &(ab.clone() * &ab)
}

/// Which end of a curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CurveEnd {
    /// `t = 0`.
    Start,
    /// `t = 1`.
    Finish,
}

/// The type of the conic carried by a rational quadratic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConicType {
    /// `w1² < w0·w2`: the weight function has no real root.
    Ellipse,
    /// `w1² = w0·w2`: one double root (a polynomial curve after Möbius).
    Parabola,
    /// `w1² > w0·w2`: two real roots (points at infinity).
    Hyperbola,
    /// The three control points are collinear: a segment of a line, not a
    /// proper conic.
    Degenerate,
}

/// # Curvature, invariants and affine maps (ring operations only)
impl<T: Scalar> RationalCurve<T> {
    /// The squared curvature at `t` as a fraction `(num, den)`,
    /// `κ²(t) = num/den`:
    ///
    /// ```text
    /// num = |M_1 × M_2|² w²,   den = |M_1|⁶
    /// ```
    ///
    /// where `X' = M_1/w²`, `X'' = M_2/w³` ([`RationalCurve::derivs_hom`]).
    /// Ring operations only (runs on symbols); `den = 0` where `X'(t) = 0`.
    ///
    /// Reference: ours (curvature formula in homogeneous form).
    pub fn curvature_sq_frac(&self, t: &T) -> (T, T) {
        let d = self.derivs_hom(t, 2);
        let (m1, m2) = (d[1].weighted(), d[2].weighted());
        let w = d[0].weight();
        let m1sq = dot(m1, m1);
        (cross_norm_sq(m1, m2) * w * w, m1sq.clone() * &m1sq * &m1sq)
    }

    /// The lecture's end-point curvature, extended to rational curves, as a
    /// fraction `(num, den)` of κ²: with `a = P_1 − P_0`, `b = P_2 − P_1`,
    ///
    /// ```text
    /// κ(0) = (n−1)/n · (w_0 w_2 / w_1²) · |a × b| / |a|³
    /// ```
    ///
    /// in homogeneous form (`â = w_0 c_1 − w_1 c_0 = w_0 w_1 a`,
    /// `b̂ = w_1 c_2 − w_2 c_1 = w_1 w_2 b`, spatial parts):
    /// `num = (n−1)² w_0⁶ |â × b̂|²`, `den = n² w_1² |â|⁶`. For `Finish` the
    /// same at the reversed curve. For unit weights this is the lecture's
    /// `k(0) = (n−1)/n |(P_1 − P_0) × (P_2 − P_1)| / |P_1 − P_0|³`; a curve of
    /// degree < 2 has κ = 0 (`(0, 1)`).
    ///
    /// Reference: source 001 (lecture), "二阶导数" (k(0), k(1)); the rational
    /// factor is ours. Both proved in `proofs/src/curves.rs`.
    pub fn end_curvature_sq_frac(&self, end: CurveEnd) -> (T, T) {
        let n = self.degree();
        if n < 2 {
            return (T::zero(), T::one());
        }
        let c = self.ctrl();
        let idx: [usize; 3] = match end {
            CurveEnd::Start => [0, 1, 2],
            CurveEnd::Finish => [n, n - 1, n - 2],
        };
        let [c0, c1, c2] = idx.map(|i| &c[i]);
        let (w0, w1, w2) = (c0.weight(), c1.weight(), c2.weight());
        let a = c1.scale(w0).sub(&c0.scale(w1));
        let b = c2.scale(w1).sub(&c1.scale(w2));
        let (a, b) = (a.weighted(), b.weighted());
        let asq = dot(a, a);
        let nm1 = T::from_i64(n as i64 - 1);
        let num = nm1.clone() * &nm1 * &w0.pow_u32(6) * &cross_norm_sq(a, b);
        let den = T::from_i64((n * n) as i64) * w1 * w1 * &asq.pow_u32(3);
        (num, den)
    }

    /// The image of the curve under the affine map `x ↦ A x + b`, applied to
    /// the homogeneous control points: `(w P, w) ↦ (A (w P) + w b, w)`. The
    /// weights are unchanged, and `X̃(t) = A X(t) + b` (affine invariance,
    /// source 001 "几何不变性"). `A` is `e × d` (rows), `b` has `e` entries.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if a row of `A` does not have `d` entries or `b` does
    /// not have one entry per row.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let q = |x: i64| ratio::<BigRational>(x, 1);
    /// let c = RationalCurve::new(vec![vec![q(0), q(0)], vec![q(1), q(0)]], vec![q(1), q(3)]).unwrap();
    /// let rot = vec![vec![q(0), q(-1)], vec![q(1), q(0)]]; // a quarter turn
    /// let m = c.affine(&rot, &[q(5), q(0)]).unwrap();
    /// assert_eq!(m.eval(&ratio(1, 2)).unwrap(), vec![q(5), ratio(3, 4)]);
    /// ```
    pub fn affine(&self, matrix: &[Vec<T>], translation: &[T]) -> Result<Self, Error> {
        let d = self.dim();
        if matrix.len() != translation.len() || matrix.iter().any(|row| row.len() != d) {
            return Err(Error::Shape(format!(
                "an affine map of {d}-dimensional points needs an e × {d} matrix and e translation entries; got {} rows and {} entries",
                matrix.len(),
                translation.len()
            )));
        }
        let ctrl = self
            .ctrl()
            .iter()
            .map(|p| {
                let w = p.weight();
                let mut coords: Vec<T> = matrix
                    .iter()
                    .zip(translation)
                    .map(|(row, b)| dot(row, p.weighted()) + &(b.clone() * w))
                    .collect();
                coords.push(w.clone());
                HPoint { coords }
            })
            .collect();
        RationalCurve::from_hom(ctrl)
    }

    /// The Möbius invariants of the weights as fractions `(num, den)`,
    /// `i = 1 … n−1`:
    ///
    /// ```text
    /// I_i = w_iⁿ / (w_0^{n−i} w_nⁱ)
    /// ```
    ///
    /// Unchanged by [`RationalCurve::mobius`] (`w_i ↦ w_i (1−α)ⁱ α^{n−i}`)
    /// and by [`RationalCurve::scale_weights`]; two curves with the same
    /// control points are Möbius-equivalent iff their invariants agree.
    ///
    /// Reference: ours, from source 000 eq. (4); proved in `proofs/src/curves.rs`.
    pub fn mobius_invariants_frac(&self) -> Vec<(T, T)> {
        let w = self.weights();
        let n = self.degree();
        (1..n)
            .map(|i| {
                (
                    w[i].pow_u32(n as u32),
                    w[0].pow_u32((n - i) as u32) * &w[n].pow_u32(i as u32),
                )
            })
            .collect()
    }

    /// The local Möbius invariants as fractions `(num, den)`,
    /// `i = 1 … n−1`:
    ///
    /// ```text
    /// J_i = w_{i−1} w_{i+1} / w_i²
    /// ```
    ///
    /// (for a quadratic, `J_1 = w_0 w_2 / w_1²` decides the conic type).
    ///
    /// Reference: ours, from source 000 eq. (4); proved in `proofs/src/curves.rs`.
    pub fn local_invariants_frac(&self) -> Vec<(T, T)> {
        let w = self.weights();
        (1..self.degree())
            .map(|i| (w[i - 1].clone() * &w[i + 1], w[i].clone() * &w[i]))
            .collect()
    }
}

/// Divide each fraction; `Error::Domain` on a zero denominator.
fn divide_all<T: Field>(fracs: Vec<(T, T)>, what: &str) -> Result<Vec<T>, Error> {
    fracs
        .into_iter()
        .map(|(n, d)| {
            if d.is_zero() {
                Err(Error::Domain(format!("{what}: zero denominator")))
            } else {
                Ok(n / d)
            }
        })
        .collect()
}

/// # Cartesian values (division at the end)
impl<T: Field> RationalCurve<T> {
    /// The squared curvature `κ²(t) = |X' × X''|² / |X'|⁶`, exact for exact
    /// `T` (see [`RationalCurve::curvature_sq_frac`]).
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight vanishes at `t`;
    /// [`Error::Domain`] if `X'(t) = 0` (curvature undefined).
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// // The unit quarter circle has κ = 1 everywhere.
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let c = RationalCurve::new(vec![p(1, 0), p(1, 1), p(0, 1)], vec![ratio(1, 1), ratio(1, 1), ratio(2, 1)]).unwrap();
    /// assert_eq!(c.curvature_sq(&ratio(2, 7)).unwrap(), ratio(1, 1));
    /// ```
    pub fn curvature_sq(&self, t: &T) -> Result<T, Error> {
        if self.eval_hom(t).weight().is_zero() {
            return Err(Error::PointAtInfinity);
        }
        let (num, den) = self.curvature_sq_frac(t);
        divide_all(vec![(num, den)], "curvature where X'(t) = 0").map(|mut v| v.swap_remove(0))
    }

    /// The lecture's end-point curvature squared (see
    /// [`RationalCurve::end_curvature_sq_frac`]).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] if `P_1 = P_0` (resp. `P_{n−1} = P_n`): the formula
    /// needs a non-degenerate end leg.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{curve::CurveEnd, RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let c = RationalCurve::polynomial(vec![p(0, 0), p(1, 0), p(1, 1)]).unwrap();
    /// // k(0) = (1/2)·|(1,0) × (0,1)| / 1 = 1/2, so κ² = 1/4.
    /// assert_eq!(c.end_curvature_sq(CurveEnd::Start).unwrap(), ratio(1, 4));
    /// ```
    pub fn end_curvature_sq(&self, end: CurveEnd) -> Result<T, Error> {
        let (num, den) = self.end_curvature_sq_frac(end);
        divide_all(vec![(num, den)], "end curvature with a zero end leg")
            .map(|mut v| v.swap_remove(0))
    }

    /// The Möbius invariants `w_iⁿ / (w_0^{n−i} w_nⁱ)`, `i = 1 … n−1` (see
    /// [`RationalCurve::mobius_invariants_frac`]).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] if an end weight is zero.
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let c = RationalCurve::new(vec![p(0), p(1), p(2)], vec![ratio(1, 1), ratio(2, 1), ratio(4, 1)]).unwrap();
    /// assert_eq!(c.mobius_invariants().unwrap(), vec![ratio(1, 1)]);
    /// assert_eq!(c.mobius(&ratio(1, 3)).mobius_invariants().unwrap(), vec![ratio(1, 1)]);
    /// ```
    pub fn mobius_invariants(&self) -> Result<Vec<T>, Error> {
        divide_all(self.mobius_invariants_frac(), "Möbius invariant")
    }

    /// The local invariants `w_{i−1} w_{i+1} / w_i²`, `i = 1 … n−1`.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] if an inner weight is zero.
    ///
    /// ```
    /// use exact_bezier::{RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let w = vec![ratio(1, 1), ratio(2, 1), ratio(3, 1), ratio(1, 1)];
    /// let c = RationalCurve::new(vec![p(0), p(1), p(2), p(3)], w).unwrap();
    /// assert_eq!(c.local_invariants().unwrap(), vec![ratio(3, 4), ratio(2, 9)]);
    /// ```
    pub fn local_invariants(&self) -> Result<Vec<T>, Error> {
        divide_all(self.local_invariants_frac(), "local invariant")
    }
}

/// # Decisions (exact for exact scalars)
impl<T: Ordered> RationalCurve<T> {
    /// The curvature `κ(t)` as `f64` (square root of [`RationalCurve::curvature_sq`]).
    ///
    /// # Errors
    ///
    /// As [`RationalCurve::curvature_sq`].
    pub fn curvature_f64(&self, t: &T) -> Result<f64, Error> {
        Ok(self.curvature_sq(t)?.to_f64().sqrt())
    }

    /// The conic type of a rational quadratic, decided exactly by the sign
    /// of `w_1² − w_0 w_2` (the discriminant of the weight function in
    /// `(1 − t : t)`; equivalently `w_0 w_2 / w_1²` against 1, a Möbius and
    /// scaling invariant): ellipse if `w_0 w_2 / w_1² > 1`, parabola if `= 1`,
    /// hyperbola if `< 1`; [`ConicType::Degenerate`] if the control points
    /// are collinear. Exact for exact `T`; `f64` compares with zero exactly.
    ///
    /// Reference: source 000 (Yang & Yong), conic type of a standardized
    /// quadratic boundary; the invariant form is ours.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless the degree is 2; [`Error::PointAtInfinity`]
    /// if a weight is zero.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{curve::ConicType, RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let pts = vec![p(1, 0), p(1, 1), p(0, 1)];
    /// let w = |a, b, c| vec![ratio(a, 1), ratio(b, 1), ratio(c, 1)];
    /// let conic = |ws| RationalCurve::new(pts.clone(), ws).unwrap().conic_type().unwrap();
    /// assert_eq!(conic(w(1, 1, 2)), ConicType::Ellipse);
    /// assert_eq!(conic(w(1, 2, 4)), ConicType::Parabola);
    /// assert_eq!(conic(w(1, 3, 1)), ConicType::Hyperbola);
    /// ```
    pub fn conic_type(&self) -> Result<ConicType, Error> {
        if self.degree() != 2 {
            return Err(Error::Shape(format!(
                "the conic type needs a rational quadratic, not degree {}",
                self.degree()
            )));
        }
        let p = self.points()?;
        let a: Vec<T> = p[1].iter().zip(&p[0]).map(|(x, y)| x.clone() - y).collect();
        let b: Vec<T> = p[2].iter().zip(&p[1]).map(|(x, y)| x.clone() - y).collect();
        if cross_norm_sq(&a, &b).is_zero() {
            return Ok(ConicType::Degenerate);
        }
        let w = self.weights();
        let disc = w[1].clone() * &w[1] - &(w[0].clone() * &w[2]);
        Ok(if disc.is_zero() {
            ConicType::Parabola
        } else if disc > T::zero() {
            ConicType::Hyperbola
        } else {
            ConicType::Ellipse
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    use crate::samples::p2 as p;

    #[test]
    fn end_curvature_agrees_with_derivatives() {
        let c = RationalCurve::new(
            vec![p(0, 0), p(2, 1), p(3, 4), p(6, 2)],
            vec![ratio(1, 1), ratio(3, 2), ratio(1, 2), ratio(2, 1)],
        )
        .unwrap();
        for (end, t) in [(CurveEnd::Start, 0), (CurveEnd::Finish, 1)] {
            assert_eq!(
                c.end_curvature_sq(end).unwrap(),
                c.curvature_sq(&ratio(t, 1)).unwrap()
            );
        }
    }

    #[test]
    fn lecture_end_curvature_by_hand() {
        // n = 3, P0 = (0,0), P1 = (2,0), P2 = (2,1): k(0) = (2/3)·2/8 = 1/6.
        let c = RationalCurve::polynomial(vec![p(0, 0), p(2, 0), p(2, 1), p(5, 5)]).unwrap();
        assert_eq!(c.end_curvature_sq(CurveEnd::Start).unwrap(), ratio(1, 36));
        assert!((c.curvature_f64(&ratio(0, 1)).unwrap() - 1.0 / 6.0).abs() < 1e-15);
    }

    #[test]
    fn degenerate_and_shape_errors() {
        let line = RationalCurve::polynomial(vec![p(0, 0), p(1, 1), p(3, 3)]).unwrap();
        assert_eq!(line.conic_type().unwrap(), ConicType::Degenerate);
        let cubic = RationalCurve::polynomial(vec![p(0, 0), p(1, 1), p(3, 3), p(4, 0)]).unwrap();
        assert!(matches!(cubic.conic_type(), Err(Error::Shape(_))));
        let stuck = RationalCurve::polynomial(vec![p(0, 0), p(0, 0), p(3, 3)]).unwrap();
        assert!(matches!(
            stuck.curvature_sq(&ratio(0, 1)),
            Err(Error::Domain(_))
        ));
        assert!(matches!(
            line.affine(&[vec![ratio(1, 1)]], &[]),
            Err(Error::Shape(_))
        ));
    }
}
