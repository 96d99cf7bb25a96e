//! The exact circle test: does a rational curve of any degree, in the plane
//! or in space, lie on a circle?
//!
//! With `X(t)` the weighted coordinates and `w(t)` the weight, the curve lies
//! on the circle with centre `C` and radius² `R²` iff
//!
//! ```text
//! |X − C·w|² − R²·w² ≡ 0   (as a polynomial in t)
//! ```
//!
//! and the curve is planar (the circle's plane). Writing `Y = X − P₀·w`
//! for a finite control point `P₀` and `C = P₀ + αu + βv` with `u, v`
//! spanning the curve's plane, the identity reads
//!
//! ```text
//! |Y|² − 2α(u·Y)w − 2β(v·Y)w + K·w² ≡ 0,   K = |αu + βv|² − R²
//! ```
//!
//! — linear in `α, β, K`. Its `2n + 1` coefficients (on the basis
//! `tⁱ(1 − t)^{2n−i}`) give an overdetermined linear system over the scalar,
//! solved exactly for exact scalars. Reference: source 004 (circular arcs as
//! rational cubics); the method is ours.

use crate::algebra::int::common_denominator;
use crate::algebra::scalar::{binomial_scalar, Field, Scalar, Tolerance};
use crate::curve::RationalCurve;
use num_bigint::BigInt;
use num_rational::BigRational;
use std::fmt;

/// A circle: centre and squared radius (exact for exact scalars).
#[derive(Clone, Debug, PartialEq)]
pub struct Circle<T> {
    /// The centre `C`.
    pub center: Vec<T>,
    /// The squared radius `R²`.
    pub radius_squared: T,
}

/// Why a curve does not lie on a circle.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NotCircle {
    /// Every weight is zero: no finite point.
    AtInfinity,
    /// All control points coincide: the curve is a point.
    Point,
    /// The curve lies on a straight line.
    Line,
    /// The control points span three or more dimensions.
    NotPlanar,
    /// The curve is planar but on no circle: the circle determined by the
    /// first independent coefficient equations leaves a non-zero
    /// coefficient of `t^index (1 − t)^(degree − index)`.
    OffCircle {
        /// Index `i` of the failing coefficient.
        index: usize,
        /// Degree `2n` of the identity.
        degree: usize,
    },
}

impl fmt::Display for NotCircle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NotCircle::AtInfinity => f.write_str("every weight is zero: the curve has no finite point"),
            NotCircle::Point => f.write_str("the curve is a single point"),
            NotCircle::Line => f.write_str("the curve lies on a straight line"),
            NotCircle::NotPlanar => f.write_str("the curve is not planar"),
            NotCircle::OffCircle { index, degree } => write!(
                f,
                "the curve is planar but on no circle: |X − C·w|² − R²·w² keeps a non-zero coefficient of t^{index}(1−t)^{}",
                degree - index
            ),
        }
    }
}

/// Decide whether `curve` lies on a circle; return the circle or the reason
/// it does not (see the module docs for the method). Exact for exact `T`
/// (`tol` is ignored); `f64` treats `|x| ≤ tol` as zero.
///
/// # Errors
///
/// The [`NotCircle`] reason.
///
/// # Examples
///
/// ```
/// use exact_bezier::{curve::circle_of, ratio, RationalCurve, Tolerance};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// // The quarter circle (1,0), (1,1), (0,1) needs weight √2/2; the
/// // semicircle with its direction at infinity is rational:
/// let half = RationalCurve::from_hom(vec![
///     exact_bezier::hpoint::HPoint::from_cartesian(&p(0, 0)),
///     exact_bezier::hpoint::HPoint { coords: vec![ratio(0, 1), ratio(1, 1), ratio(0, 1)] },
///     exact_bezier::hpoint::HPoint::from_cartesian(&p(2, 0)),
/// ]).unwrap();
/// let circle = circle_of(&half, Tolerance::EXACT).unwrap();
/// assert_eq!(circle.center, p(1, 0));
/// assert_eq!(circle.radius_squared, ratio(1, 1));
/// let parabola = RationalCurve::polynomial(vec![p(0, 0), p(1, 2), p(2, 0)]).unwrap();
/// assert!(circle_of(&parabola, Tolerance::EXACT).is_err());
/// ```
pub fn circle_of<T: Field>(
    curve: &RationalCurve<T>,
    tol: Tolerance,
) -> Result<Circle<T>, NotCircle> {
    let ctrl = curve.ctrl();
    let origin = ctrl
        .iter()
        .find(|h| !h.weight().is_zero_within(tol))
        .ok_or(NotCircle::AtInfinity)?
        .project()
        .map_err(|_| NotCircle::AtInfinity)?;
    // D_i = x_i − w_i·P₀: the homogeneous control points seen from P₀.
    let dirs: Vec<Vec<T>> = ctrl
        .iter()
        .map(|h| {
            h.weighted()
                .iter()
                .zip(&origin)
                .map(|(x, o)| x.clone() - &(h.weight().clone() * o))
                .collect()
        })
        .collect();
    let (u, v) = plane_basis(&dirs, tol)?;
    let w: Vec<T> = curve.weights();
    let along = |b: &[T]| -> Vec<T> { dirs.iter().map(|d| dot(b, d)).collect() };
    let n = curve.degree();
    let mut sq = vec![T::zero(); 2 * n + 1];
    for k in 0..origin.len() {
        let yk: Vec<T> = dirs.iter().map(|d| d[k].clone()).collect();
        for (acc, x) in sq.iter_mut().zip(product(&yk, &yk)) {
            *acc = acc.clone() + &x;
        }
    }
    let (a, b, ww) = (
        product(&along(&u), &w),
        product(&along(&v), &w),
        product(&w, &w),
    );
    let minus_two = T::from_i64(-2);
    // Row m: −2α·a_m − 2β·b_m + K·ww_m = −sq_m.
    let rows: Vec<[T; 4]> = (0..=2 * n)
        .map(|m| {
            [
                minus_two.clone() * &a[m],
                minus_two.clone() * &b[m],
                ww[m].clone(),
                -sq[m].clone(),
            ]
        })
        .collect();
    let [alpha, beta, k] = solve3(&rows, tol).ok_or(NotCircle::Line)?;
    if let Some(index) = rows.iter().position(|r| {
        !(r[0].clone() * &alpha + &(r[1].clone() * &beta) + &(r[2].clone() * &k) - &r[3])
            .is_zero_within(tol)
    }) {
        return Err(NotCircle::OffCircle {
            index,
            degree: 2 * n,
        });
    }
    let g: Vec<T> = u
        .iter()
        .zip(&v)
        .map(|(x, y)| alpha.clone() * x + &(beta.clone() * y))
        .collect();
    Ok(Circle {
        center: origin.iter().zip(&g).map(|(o, x)| o.clone() + x).collect(),
        radius_squared: dot(&g, &g) - &k,
    })
}

/// The same curve with integer homogeneous coordinates: every `(w·P, w)`
/// multiplied by the least common multiple of all denominators (the curve is
/// unchanged, source 000 eq. 5). Exact rationals with denominator 1 skip
/// some gcd work in [`circle_of`] (≈25% faster on the bench cubic).
///
/// ```
/// use exact_bezier::{curve::integer_coords, ratio, RationalCurve};
/// use exact_bezier::BigRational;
/// let c = RationalCurve::new(vec![vec![ratio::<BigRational>(1, 2)], vec![ratio(1, 3)]], vec![ratio(1, 1), ratio(3, 4)]).unwrap();
/// let i = integer_coords(&c);
/// assert_eq!(i.ctrl()[1].coords, vec![ratio(1, 1), ratio(3, 1)]);
/// assert_eq!(i.eval(&ratio(1, 5)).unwrap(), c.eval(&ratio(1, 5)).unwrap());
/// ```
pub fn integer_coords(curve: &RationalCurve<BigRational>) -> RationalCurve<BigRational> {
    let (_, lcm) = common_denominator::<BigInt>(curve.ctrl().iter().flat_map(|h| h.coords.iter()));
    curve.scale_weights(&BigRational::from_integer(lcm))
}

/// Two directions spanning the span of `dirs`, or why there are not
/// exactly two: Gram determinants decide independence.
fn plane_basis<T: Field>(dirs: &[Vec<T>], tol: Tolerance) -> Result<(Vec<T>, Vec<T>), NotCircle> {
    let u = dirs
        .iter()
        .find(|d| !dot(d, d).is_zero_within(tol))
        .ok_or(NotCircle::Point)?;
    let v = dirs
        .iter()
        .find(|d| !gram(&[u, d]).is_zero_within(tol))
        .ok_or(NotCircle::Line)?;
    if dirs.iter().any(|d| !gram(&[u, v, d]).is_zero_within(tol)) {
        return Err(NotCircle::NotPlanar);
    }
    Ok((u.clone(), v.clone()))
}

/// The Gram determinant `det(vᵢ·vⱼ)` of two or three vectors (zero iff
/// they are linearly dependent).
fn gram<T: Scalar>(vs: &[&Vec<T>]) -> T {
    let g: Vec<Vec<T>> = vs
        .iter()
        .map(|a| vs.iter().map(|b| dot(a, b)).collect())
        .collect();
    if g.len() == 2 {
        return g[0][0].clone() * &g[1][1] - &(g[0][1].clone() * &g[1][0]);
    }
    let minor = |i: usize, j: usize, k: usize, l: usize| {
        g[1][i].clone() * &g[2][j] - &(g[1][k].clone() * &g[2][l])
    };
    g[0][0].clone() * &minor(1, 2, 2, 1) - &(g[0][1].clone() * &minor(0, 2, 2, 0))
        + &(g[0][2].clone() * &minor(0, 1, 1, 0))
}

/// The dot product.
fn dot<T: Scalar>(a: &[T], b: &[T]) -> T {
    a.iter()
        .zip(b)
        .fold(T::zero(), |acc, (x, y)| acc + &(x.clone() * y))
}

/// Product of two degree-n Bernstein polynomials `Σ fᵢ B_{i,n}`, as the
/// coefficients of `t^m (1 − t)^{2n−m}`: `Σ_{i+j=m} C(n,i)C(n,j) fᵢ gⱼ`.
fn product<T: Scalar>(f: &[T], g: &[T]) -> Vec<T> {
    let n = f.len() - 1;
    let scaled = |h: &[T]| -> Vec<T> {
        h.iter()
            .enumerate()
            .map(|(i, x)| binomial_scalar::<T>(n, i) * x)
            .collect()
    };
    let (fs, gs) = (scaled(f), scaled(g));
    let mut out = vec![T::zero(); 2 * n + 1];
    for (i, x) in fs.iter().enumerate() {
        for (j, y) in gs.iter().enumerate() {
            out[i + j] = out[i + j].clone() + &(x.clone() * y);
        }
    }
    out
}

/// Solve `a·x + b·y + c·z = r` from the first three independent rows
/// `[a, b, c, r]` (an echelon basis grown row by row; later rows are left
/// for the caller's residual check); `None` if the rank is below 3.
fn solve3<T: Field>(rows: &[[T; 4]], tol: Tolerance) -> Option<[T; 3]> {
    let mut basis: Vec<(usize, [T; 4])> = Vec::with_capacity(3);
    for r in rows {
        let mut row = r.clone();
        for (col, b) in &basis {
            if !row[*col].is_zero_within(tol) {
                let f = row[*col].clone() / &b[*col];
                for j in 0..4 {
                    row[j] = row[j].clone() - &(f.clone() * &b[j]);
                }
            }
        }
        if let Some(col) = (0..3).find(|&j| !row[j].is_zero_within(tol)) {
            basis.push((col, row));
            if basis.len() == 3 {
                break;
            }
        }
    }
    if basis.len() < 3 {
        return None;
    }
    // Row i is zero in the pivot columns of rows before it: back-substitute.
    let mut x = [T::zero(), T::zero(), T::zero()];
    for i in (0..3).rev() {
        let (col, row) = &basis[i];
        let mut acc = row[3].clone();
        for (c, _) in &basis[i + 1..] {
            acc = acc - &(row[*c].clone() * &x[*c]);
        }
        x[*col] = acc / &row[*col];
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    use crate::hpoint::HPoint;
    use num_rational::BigRational;

    fn p(v: &[i64]) -> Vec<BigRational> {
        v.iter().map(|&x| ratio(x, 1)).collect()
    }

    #[test]
    fn space_circle_and_failures() {
        // A semicircle in the plane 4y = 3z: direction (0, 3/5, 4/5) at infinity.
        let half = RationalCurve::from_hom(vec![
            HPoint::from_cartesian(&p(&[0, 0, 0])),
            HPoint {
                coords: vec![ratio(0, 1), ratio(3, 5), ratio(4, 5), ratio(0, 1)],
            },
            HPoint::from_cartesian(&p(&[2, 0, 0])),
        ])
        .unwrap();
        let c = circle_of(&half, Tolerance::EXACT).unwrap();
        assert_eq!(c.center, p(&[1, 0, 0]));
        assert_eq!(c.radius_squared, ratio(1, 1));
        let twisted = RationalCurve::polynomial(vec![
            p(&[0, 0, 0]),
            p(&[1, 0, 0]),
            p(&[0, 1, 0]),
            p(&[0, 0, 1]),
        ])
        .unwrap();
        assert_eq!(
            circle_of(&twisted, Tolerance::EXACT),
            Err(NotCircle::NotPlanar)
        );
        let line = RationalCurve::polynomial(vec![p(&[0, 0]), p(&[1, 1]), p(&[3, 3])]).unwrap();
        assert_eq!(circle_of(&line, Tolerance::EXACT), Err(NotCircle::Line));
        let dot = RationalCurve::polynomial(vec![p(&[2, 1]), p(&[2, 1])]).unwrap();
        assert_eq!(circle_of(&dot, Tolerance::EXACT), Err(NotCircle::Point));
        let parabola = RationalCurve::polynomial(vec![p(&[0, 0]), p(&[1, 2]), p(&[2, 0])]).unwrap();
        assert!(matches!(
            circle_of(&parabola, Tolerance::EXACT),
            Err(NotCircle::OffCircle { degree: 4, .. })
        ));
    }
}
