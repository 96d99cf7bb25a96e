//! Operations on [`RectPatch`]: partial derivatives of any order (homogeneous
//! and Cartesian), normal vectors, the lecture's corner tangent planes,
//! subdivision in u and v, and sub-patch extraction.
//!
//! Conventions as in [`RectPatch`]: `H(u, v) = Σ Σ ω_{i,j}(P_{i,j}, 1)
//! B_{i,m}(u) B_{j,n}(v)` is the homogeneous surface (weight last) and
//! `X = H_{1…d} / H_{d+1}` the Cartesian one.
//!
//! Reference: source 001 (lecture), "矩形域曲面" (tensor product, corner
//! tangent planes) and the curve derivative formula applied per direction.

use crate::algebra::scalar::{binomial_scalar, Field, Scalar};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;

/// # Derivatives and normals (homogeneous: ring operations only)
impl<T: Scalar> RectPatch<T> {
    /// The patch of `∂^{a+b}H/∂u^a∂v^b`: bidegree `(m − a, n − b)`, control
    /// points `m!/(m−a)! · n!/(n−b)! · Δ^{a,b} ω_{i,j}(P_{i,j}, 1)` (forward
    /// differences in both indices). `None` when `a > m` or `b > n` (the
    /// derivative is identically zero).
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// // H = (x(u, v), 1) with x = 4uv: the mixed derivative is 4 everywhere.
    /// let s = RectPatch::polynomial(vec![vec![p(0), p(0)], vec![p(0), p(4)]]).unwrap();
    /// let d = s.derivative_patch(1, 1).unwrap();
    /// assert_eq!(d.ctrl()[0][0].coords, vec![ratio(4, 1), ratio(0, 1)]);
    /// assert!(s.derivative_patch(2, 0).is_none());
    /// ```
    pub fn derivative_patch(&self, a: usize, b: usize) -> Option<RectPatch<T>> {
        let (m, n) = self.degree();
        if a > m || b > n {
            return None;
        }
        let diff = |row: &[HPoint<T>], times: usize| -> Vec<HPoint<T>> {
            let deg = row.len() - 1;
            let mut out = row.to_vec();
            for _ in 0..times {
                out = out.windows(2).map(|w| w[1].sub(&w[0])).collect();
            }
            let factor = falling_factorial::<T>(deg, times);
            out.iter().map(|p| p.scale(&factor)).collect()
        };
        Some(self.map_rows(|r| diff(r, b)).map_columns(|c| diff(c, a)))
    }

    /// `∂^{a+b}H/∂u^a∂v^b` at `(u, v)`, the homogeneous derivative (the
    /// zero vector when `a > m` or `b > n`). Exact for exact `T`.
    pub fn derivative_hom(&self, a: usize, b: usize, u: &T, v: &T) -> HPoint<T> {
        match self.derivative_patch(a, b) {
            Some(d) => d.eval_hom(u, v),
            None => HPoint::zero(self.dim()),
        }
    }

    /// A normal vector at `(u, v)` of a 3D patch, without division:
    /// `N = (w P_u − w_u P) × (w P_v − w_v P) = w⁴ · (X_u × X_v)`, where
    /// `(P, w) = H(u, v)` and `(P_u, w_u) = H_u(u, v)` etc. It is zero where
    /// the patch is singular (e.g. at a degenerate corner).
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless the control points are 3D.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1), ratio(0, 1)];
    /// // The unit square in the plane z = 0: normal along +z.
    /// let s = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 1)], vec![p(1, 0), p(1, 1)]]).unwrap();
    /// let n = s.normal_hom(&ratio(1, 2), &ratio(1, 2)).unwrap();
    /// assert_eq!(n, vec![ratio(0, 1), ratio(0, 1), ratio(1, 1)]);
    /// ```
    pub fn normal_hom(&self, u: &T, v: &T) -> Result<Vec<T>, Error> {
        if self.dim() != 3 {
            return Err(Error::Shape(format!(
                "a normal vector needs 3D control points, not {}D",
                self.dim()
            )));
        }
        let h = self.eval_hom(u, v);
        let tangent = |d: &HPoint<T>| -> Vec<T> {
            (0..3)
                .map(|k| h.weight().clone() * &d.coords[k] - &(d.weight().clone() * &h.coords[k]))
                .collect()
        };
        let tu = tangent(&self.derivative_hom(1, 0, u, v));
        let tv = tangent(&self.derivative_hom(0, 1, u, v));
        Ok(cross(&tu, &tv))
    }

    /// The lecture's corner tangent triangle at `corner`: the indices of
    /// three control points spanning the tangent plane there, as printed:
    /// `P00 P10 P01`, `P0n P1n P0,n−1`, `Pmn Pm,n−1 Pm−1,n`, `Pm0 Pm−1,0 Pm1`
    /// (corner first). The lecture's list is correct (proofs family
    /// `surfaces`: the normal at each corner is parallel to the triangle's).
    ///
    /// Reference: source 001 (lecture), "以下三角形指定了四个角处的切平面".
    ///
    /// ```
    /// use exact_bezier::{RectPatch, rect::Corner, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let s = RectPatch::polynomial(vec![vec![p(0); 4]; 3]).unwrap(); // (m, n) = (2, 3)
    /// assert_eq!(s.corner_triangle(Corner::Uv10), [(2, 0), (1, 0), (2, 1)]);
    /// ```
    pub fn corner_triangle(&self, corner: Corner) -> [(usize, usize); 3] {
        let (m, n) = self.degree();
        match corner {
            Corner::Uv00 => [(0, 0), (1.min(m), 0), (0, 1.min(n))],
            Corner::Uv01 => [(0, n), (1.min(m), n), (0, n.saturating_sub(1))],
            Corner::Uv11 => [(m, n), (m, n.saturating_sub(1)), (m.saturating_sub(1), n)],
            Corner::Uv10 => [(m, 0), (m.saturating_sub(1), 0), (m, 1.min(n))],
        }
    }
}

/// A corner of the parameter square, named by its `(u, v)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Corner {
    /// `(u, v) = (0, 0)`, control point `P_{0,0}`.
    Uv00,
    /// `(0, 1)`, control point `P_{0,n}`.
    Uv01,
    /// `(1, 1)`, control point `P_{m,n}`.
    Uv11,
    /// `(1, 0)`, control point `P_{m,0}`.
    Uv10,
}

impl Corner {
    /// All four corners.
    pub const ALL: [Corner; 4] = [Corner::Uv00, Corner::Uv01, Corner::Uv11, Corner::Uv10];

    /// The parameters `(u, v)` of the corner as 0/1 scalars.
    pub fn params<T: Scalar>(self) -> (T, T) {
        let b = |x: bool| if x { T::one() } else { T::zero() };
        match self {
            Corner::Uv00 => (b(false), b(false)),
            Corner::Uv01 => (b(false), b(true)),
            Corner::Uv11 => (b(true), b(true)),
            Corner::Uv10 => (b(true), b(false)),
        }
    }
}

/// The cross product of two 3-vectors.
pub fn cross<T: Scalar>(a: &[T], b: &[T]) -> Vec<T> {
    vec![
        a[1].clone() * &b[2] - &(a[2].clone() * &b[1]),
        a[2].clone() * &b[0] - &(a[0].clone() * &b[2]),
        a[0].clone() * &b[1] - &(a[1].clone() * &b[0]),
    ]
}

/// `n!/(n−k)!` as a scalar.
fn falling_factorial<T: Scalar>(n: usize, k: usize) -> T {
    (0..k).fold(T::one(), |acc, i| acc * T::from_i64((n - i) as i64))
}

/// # Cartesian derivatives (exact quotient rule)
impl<T: Field> RectPatch<T> {
    /// All Cartesian partial derivatives `∂^{i+j}X/∂u^i∂v^j` for `i ≤ a`,
    /// `j ≤ b` at `(u, v)`, as `table[i][j]`, by the exact quotient rule:
    /// from `P = w·X` (Leibniz),
    ///
    /// ```text
    /// X^{(i,j)} = ( P^{(i,j)} − Σ_{(k,l) ≤ (i,j), (k,l) ≠ (0,0)} C(i,k) C(j,l) w^{(k,l)} X^{(i−k,j−l)} ) / w
    /// ```
    ///
    /// where `(P, w) = H`. Exact for exact `T` (one division per entry, by
    /// `w`).
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if `w(u, v) = 0`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// // x(u, v) = u with weights 1 + u (linear in u): X = u exactly, X_u = 1, X_uu = 0.
    /// let s = RectPatch::new(vec![vec![p(0)], vec![p(1)]], vec![vec![ratio(1, 1)], vec![ratio(2, 1)]]).unwrap();
    /// let d = s.derivatives(2, 0, &ratio(1, 3), &ratio(0, 1)).unwrap();
    /// // X = 2u/(1 + u): X' = 2/(1+u)², X'' = −4/(1+u)³ at u = 1/3.
    /// assert_eq!(d[1][0], vec![ratio(9, 8)]);
    /// assert_eq!(d[2][0], vec![ratio(-27, 16)]);
    /// ```
    pub fn derivatives(&self, a: usize, b: usize, u: &T, v: &T) -> Result<Vec<Vec<Vec<T>>>, Error> {
        let h: Vec<Vec<HPoint<T>>> = (0..=a)
            .map(|i| (0..=b).map(|j| self.derivative_hom(i, j, u, v)).collect())
            .collect();
        let w = h[0][0].weight().clone();
        if w.is_zero() {
            return Err(Error::PointAtInfinity);
        }
        let d = self.dim();
        let mut x: Vec<Vec<Vec<T>>> = vec![vec![Vec::new(); b + 1]; a + 1];
        for i in 0..=a {
            for j in 0..=b {
                let mut acc: Vec<T> = h[i][j].weighted().to_vec();
                for k in 0..=i {
                    for l in 0..=j {
                        if k == 0 && l == 0 {
                            continue;
                        }
                        let c = binomial_scalar::<T>(i, k)
                            * binomial_scalar::<T>(j, l)
                            * h[k][l].weight();
                        for (q, xq) in acc.iter_mut().zip(&x[i - k][j - l]) {
                            *q = q.clone() - &(c.clone() * xq);
                        }
                    }
                }
                x[i][j] = acc.into_iter().map(|q| q / &w).collect();
                debug_assert_eq!(x[i][j].len(), d);
            }
        }
        Ok(x)
    }
}

/// # Subdivision and sub-patches
impl<T: Scalar> RectPatch<T> {
    /// Split at `u = t` into the pieces over `[0, t]` and `[t, 1]` in u, each
    /// reparameterized to `[0, 1]` (curve subdivision on every column).
    /// Exact for exact `T`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let s = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 2)], vec![p(2, 0), p(4, 4)]]).unwrap();
    /// let (left, _) = s.subdivide_u(&ratio(1, 2));
    /// assert_eq!(left.eval(&ratio(1, 1), &ratio(1, 3)).unwrap(), s.eval(&ratio(1, 2), &ratio(1, 3)).unwrap());
    /// ```
    pub fn subdivide_u(&self, t: &T) -> (Self, Self) {
        let left = self.map_columns(|c| curve_of(c).subdivide(t).0.ctrl().to_vec());
        let right = self.map_columns(|c| curve_of(c).subdivide(t).1.ctrl().to_vec());
        (left, right)
    }

    /// Split at `v = t` into the pieces over `[0, t]` and `[t, 1]` in v.
    pub fn subdivide_v(&self, t: &T) -> (Self, Self) {
        let left = self.map_rows(|r| curve_of(r).subdivide(t).0.ctrl().to_vec());
        let right = self.map_rows(|r| curve_of(r).subdivide(t).1.ctrl().to_vec());
        (left, right)
    }

    /// The sub-patch over `[u0, u1] × [v0, v1]`, reparameterized to
    /// `[0, 1]²` (blossom-based curve subsegments on columns, then rows):
    /// the new patch at `(s, t)` is the old at `(u0 + s(u1 − u0), v0 + t(v1 − v0))`.
    /// Reversed intervals give reversed pieces. Exact for exact `T`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let s = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 2)], vec![p(2, 0), p(4, 4)]]).unwrap();
    /// let sub = s.subpatch(&ratio(1, 4), &ratio(3, 4), &ratio(0, 1), &ratio(1, 2));
    /// assert_eq!(sub.eval(&ratio(0, 1), &ratio(1, 1)).unwrap(), s.eval(&ratio(1, 4), &ratio(1, 2)).unwrap());
    /// ```
    pub fn subpatch(&self, u0: &T, u1: &T, v0: &T, v1: &T) -> Self {
        self.map_columns(|c| curve_of(c).subsegment(u0, u1).ctrl().to_vec())
            .map_rows(|r| curve_of(r).subsegment(v0, v1).ctrl().to_vec())
    }
}

/// A row or column of a patch as a curve (never empty, same lengths).
fn curve_of<T: Scalar>(ctrl: &[HPoint<T>]) -> RationalCurve<T> {
    RationalCurve::from_hom(ctrl.to_vec()).expect("rows and columns of a patch are valid curves")
}

#[cfg(test)]
mod tests {
    use crate::algebra::scalar::ratio;
    use crate::samples::rect_1x2 as sample;
    use num_rational::BigRational;
    type Q = BigRational;

    #[test]
    fn derivatives_match_difference_quotients_of_the_exact_function() {
        // X_u against the quotient rule (N'D − N D')/D² of the homogeneous form.
        let s = sample();
        let (u, v) = (ratio::<Q>(1, 3), ratio::<Q>(2, 5));
        let d = s.derivatives(1, 1, &u, &v).unwrap();
        let h = s.eval_hom(&u, &v);
        let hu = s.derivative_hom(1, 0, &u, &v);
        let w = h.weight().clone();
        for (k, got) in d[1][0].iter().enumerate() {
            let expect =
                (hu.coords[k].clone() * &w - h.coords[k].clone() * hu.weight()) / (w.clone() * &w);
            assert_eq!(*got, expect);
        }
        assert_eq!(d[0][0], s.eval(&u, &v).unwrap());
    }

    #[test]
    fn subpatch_and_subdivision_agree() {
        let s = sample();
        let t = ratio::<Q>(1, 3);
        let (_, right) = s.subdivide_v(&t);
        let sub = s.subpatch(&ratio(0, 1), &ratio(1, 1), &t, &ratio(1, 1));
        let (a, b) = (ratio::<Q>(2, 7), ratio::<Q>(5, 6));
        assert_eq!(right.eval(&a, &b).unwrap(), sub.eval(&a, &b).unwrap());
    }
}
