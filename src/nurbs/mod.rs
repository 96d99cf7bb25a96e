//! NURBS → rational Bézier, exactly: B-spline and rational B-spline curves
//! and tensor-product surfaces split into their Bézier pieces, each with the
//! knot span it came from.
//!
//! Conventions (Piegl & Tiller, *The NURBS Book*, ch. 2–5): degree `p`,
//! control points `P_0 … P_n` with weights `w_i`, knots `u_0 ≤ … ≤ u_{n+p+1}`;
//! the curve lives on `[u_p, u_{n+1}]` and is
//!
//! ```text
//! C(u) = Σ N_{i,p}(u) w_i P_i / Σ N_{i,p}(u) w_i
//! ```
//!
//! Clamped or not, uniform or not: only the knots in `u_0 … u_{n+p+1}` and the
//! domain `[u_p, u_{n+1}]` matter.
//!
//! **Decomposition.** On a non-empty span `[u_k, u_{k+1})` the curve is a
//! polynomial (homogeneously) whose blossom `f(t_1, …, t_p)` is computed by
//! de Boor's recursion with a different argument at each level (Ramshaw's
//! blossoming principle; The NURBS Book §5.2): its Bézier control points on
//! the span are `f(u_k^{p−j}, u_{k+1}^j)`, `j = 0 … p` — exactly the points
//! knot insertion (Boehm) produces when `u_k` and `u_{k+1}` are raised to
//! multiplicity `p`. The recursion's coefficients
//! `(t_r − u_i)/(u_{i+p+1−r} − u_i)` divide only by knot differences that
//! contain the span, so they are never zero.
//!
//! **Scalars.** Knots are exact rationals ([`BigRational`]); control points
//! and weights are any [`Scalar`] — `BigRational` for exact pieces, `f64`, or
//! the symbolic [`Poly`](crate::Poly) (the coefficients enter through
//! [`Scalar::from_rational`], so no division in the scalar is needed; see
//! `proofs/src/nurbs.rs`). Everything is homogeneous: `(w_i P_i, w_i)`.

pub use invert::nearest_parameters;
pub use spanned::{Nurbs, SpannedPatch};

use crate::algebra::gcd::{product, sum};
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::limits::check_degree;
use crate::{RationalCurve, RectPatch, Scalar};
use num_rational::BigRational;
use num_traits::{One, Zero};

mod invert;
mod spanned;

/// A knot vector with its degree: validated once, used by curves and both
/// directions of surfaces.
#[derive(Clone, Debug, PartialEq)]
pub struct Knots {
    degree: usize,
    knots: Vec<BigRational>,
}

impl Knots {
    /// The knots `u_0 … u_{n+p+1}` of a degree-`p` B-spline with `count`
    /// (`= n + 1`) control points.
    ///
    /// # Errors
    ///
    /// [`Error::DegreeTooHigh`] over [`MAX_DEGREE`](crate::limits::MAX_DEGREE); [`Error::Shape`] for a
    /// degree of 0, a wrong knot count, fewer than `p + 1` control points,
    /// decreasing knots, or an empty domain `u_p = u_{n+1}`.
    pub fn new(degree: usize, knots: Vec<BigRational>, count: usize) -> Result<Self, Error> {
        check_degree(degree)?;
        if degree == 0 {
            return Err(Error::Shape("a B-spline needs degree ≥ 1".into()));
        }
        if count < degree + 1 {
            return Err(Error::Shape(format!(
                "a degree {degree} B-spline needs at least {} control points, not {count}",
                degree + 1
            )));
        }
        if knots.len() != count + degree + 1 {
            return Err(Error::Shape(format!(
                "a degree {degree} B-spline with {count} control points needs {} knots, not {}",
                count + degree + 1,
                knots.len()
            )));
        }
        if let Some(i) = knots.windows(2).position(|w| w[1] < w[0]) {
            return Err(Error::Shape(format!(
                "knots must not decrease: u_{} = {} > u_{} = {}",
                i,
                knots[i],
                i + 1,
                knots[i + 1]
            )));
        }
        if knots[degree] == knots[count] {
            return Err(Error::Shape(format!(
                "the domain [u_{degree}, u_{count}] is empty"
            )));
        }
        Ok(Knots { degree, knots })
    }

    /// Knots from distinct values and their multiplicities (the STEP form).
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the lists differ in length or a multiplicity is 0;
    /// then as [`Knots::new`].
    pub fn from_multiplicities(
        degree: usize,
        values: &[BigRational],
        mults: &[usize],
        count: usize,
    ) -> Result<Self, Error> {
        if values.len() != mults.len() || mults.contains(&0) {
            return Err(Error::Shape(format!(
                "{} knot values with {} positive multiplicities",
                values.len(),
                mults.len()
            )));
        }
        let total: usize = mults.iter().sum();
        if total != count + degree + 1 {
            return Err(Error::Shape(format!(
                "a degree {degree} B-spline with {count} control points needs {} knots, the multiplicities sum to {total}",
                count + degree + 1
            )));
        }
        let knots = values
            .iter()
            .zip(mults)
            .flat_map(|(v, &m)| std::iter::repeat_n(v.clone(), m))
            .collect();
        Self::new(degree, knots, count)
    }

    /// The clamped single-span knots `0^{p+1} 1^{p+1}` of a Bézier curve.
    pub fn bezier(degree: usize) -> Result<Self, Error> {
        let zero = BigRational::from_integer(0.into());
        let one = BigRational::from_integer(1.into());
        let mut k = vec![zero; degree + 1];
        k.extend(std::iter::repeat_n(one, degree + 1));
        Self::new(degree, k, degree + 1)
    }

    /// The degree `p`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Are the end knots of multiplicity `p + 1` (`u_0 = … = u_p`, and
    /// alike at the end), so that the first and last control points are
    /// the ends of the curve?
    ///
    /// ```
    /// use exact_bezier::nurbs::Knots;
    /// use exact_bezier::{ratio, BigRational};
    /// let q = |n: i64| ratio::<BigRational>(n, 1);
    /// let k = Knots::from_multiplicities(1, &[q(0), q(1), q(2)], &[2, 1, 2], 3).unwrap();
    /// assert!(k.is_clamped());
    /// ```
    pub fn is_clamped(&self) -> bool {
        let (k, p) = (&self.knots, self.degree);
        k.len() > 2 * p + 1
            && k[..=p].iter().all(|x| *x == k[0])
            && k[k.len() - 1 - p..].iter().all(|x| *x == k[k.len() - 1])
    }

    /// The knots `u_0 … u_{n+p+1}`.
    pub fn knots(&self) -> &[BigRational] {
        &self.knots
    }

    /// The number of control points `n + 1`.
    pub fn count(&self) -> usize {
        self.knots.len() - self.degree - 1
    }

    /// The non-empty spans `k` (`u_k < u_{k+1}`, `p ≤ k ≤ n`) in order.
    pub fn spans(&self) -> Vec<usize> {
        (self.degree..self.count())
            .filter(|&k| self.knots[k] < self.knots[k + 1])
            .collect()
    }

    /// The blossom of span `k` at `args` (`p` values) from the local
    /// homogeneous points `P_{k−p} … P_k`, by de Boor's recursion with
    /// argument `args[r−1]` at level `r`:
    ///
    /// ```text
    /// d_i^r = (1 − a) d_{i−1}^{r−1} + a d_i^{r−1},  a = (t_r − u_i)/(u_{i+p+1−r} − u_i)
    /// ```
    ///
    /// The weight `a` is built by `coeff(t_r, u_i, u_{i+p+1−r})` so that a
    /// symbolic argument can be used (see [`Knots::de_boor`]).
    fn blossom_with<T: Scalar, A>(
        &self,
        k: usize,
        local: &[HPoint<T>],
        args: &[A],
        coeff: impl Fn(&A, &BigRational, &BigRational) -> Step<T>,
    ) -> HPoint<T> {
        let p = self.degree;
        let mut d: Vec<HPoint<T>> = local.to_vec();
        for r in 1..=p {
            // d[j] holds d_{k−p+j}; update from the top so d[j−1] is still level r−1.
            for j in (r..=p).rev() {
                let i = k - p + j;
                match coeff(&args[r - 1], &self.knots[i], &self.knots[i + p + 1 - r]) {
                    Step::Zero => d[j] = d[j - 1].clone(),
                    Step::One => {}
                    Step::Mix(a) => {
                        let one_minus = T::one() - &a;
                        d[j] = d[j - 1].combine(&one_minus, &d[j], &a);
                    }
                }
            }
        }
        d.swap_remove(p)
    }

    /// The Bézier control points of span `k` from the local points
    /// `P_{k−p} … P_k`: the blossom values `f(u_k^{p−j}, u_{k+1}^j)`.
    fn bezier_points<T: Scalar>(&self, k: usize, local: &[HPoint<T>]) -> Vec<HPoint<T>> {
        let p = self.degree;
        let (a, b) = (&self.knots[k], &self.knots[k + 1]);
        // Lehmer's gcd for the knot arithmetic: `Ratio`'s own `-` and `/`
        // reduce by num-integer's binary gcd, and STEP knots are decimals
        // with long denominators.
        let coeff = |t: &BigRational, lo: &BigRational, hi: &BigRational| {
            let a = product(&sum(t, &-lo), &sum(hi, &-lo).recip());
            if a.is_zero() {
                Step::Zero
            } else if a.is_one() {
                Step::One
            } else {
                Step::Mix(T::from_rational(&a))
            }
        };
        (0..=p)
            .map(|j| {
                let args: Vec<BigRational> = (0..p)
                    .map(|r| if r < p - j { a.clone() } else { b.clone() })
                    .collect();
                self.blossom_with(k, local, &args, coeff)
            })
            .collect()
    }

    /// De Boor's evaluation of span `k` at a parameter `t` of any scalar
    /// (symbolic too): `C(t) = f(t, …, t)`, the recursion's weights
    /// `(t − u_i) · (1/(u_{i+p+1−r} − u_i))` needing no division in `T`.
    pub fn de_boor<T: Scalar>(&self, k: usize, local: &[HPoint<T>], t: &T) -> HPoint<T> {
        let args = vec![t.clone(); self.degree];
        self.blossom_with(k, local, &args, |t: &T, lo, hi| {
            let inv = BigRational::from_integer(1.into()) / (hi - lo);
            Step::Mix((t.clone() - T::from_rational(lo)) * T::from_rational(&inv))
        })
    }

    /// The local control point indices `k − p … k` of span `k`.
    fn local_range(&self, k: usize) -> std::ops::Range<usize> {
        k - self.degree..k + 1
    }

    /// The span `[u_k, u_{k+1}]`.
    pub fn interval(&self, k: usize) -> [BigRational; 2] {
        [self.knots[k].clone(), self.knots[k + 1].clone()]
    }
}

/// One weight `a` of the blossom recursion `(1 − a) d_{i−1} + a d_i`; the
/// exact values 0 and 1 (knots of full multiplicity, e.g. a Bézier entity)
/// copy a point instead of computing with it.
enum Step<T> {
    Zero,
    One,
    Mix(T),
}

/// A (rational) B-spline curve in homogeneous form.
///
/// # Examples
///
/// A uniform quadratic B-spline with three pieces; the middle piece is the
/// Bézier curve with the midpoints of the legs as its ends.
///
/// ```
/// use exact_bezier::{nurbs::NurbsCurve, nurbs::Knots, hpoint::HPoint, ratio};
/// use exact_bezier::BigRational;
/// let k = |x: i64| ratio::<BigRational>(x, 1);
/// let pts: Vec<HPoint<BigRational>> = [0, 2, 4, 8, 16].iter().map(|&x| HPoint::from_cartesian(&[k(x)])).collect();
/// let knots = Knots::new(2, (0..8).map(k).collect(), 5).unwrap();
/// let c = NurbsCurve::new(knots, pts).unwrap();
/// let pieces = c.bezier_pieces();
/// assert_eq!(pieces.len(), 3);
/// assert_eq!(pieces[1].curve.points().unwrap(), vec![vec![k(3)], vec![k(4)], vec![k(6)]]);
/// assert_eq!(pieces[1].span, [k(3), k(4)]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurve<T> {
    knots: Knots,
    ctrl: Vec<HPoint<T>>,
}

/// One Bézier piece of a B-spline curve: the curve on `[0, 1]` is the
/// B-spline on `span` mapped affinely (`u = a + (b − a) t`).
#[derive(Clone, Debug, PartialEq)]
pub struct CurvePiece<T> {
    /// The knot span `[a, b]`.
    pub span: [BigRational; 2],
    /// The rational Bézier piece.
    pub curve: RationalCurve<T>,
}

/// One Bézier patch of a B-spline surface on the knot spans `u` × `v`.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfacePiece<T> {
    /// The knot span in u.
    pub u: [BigRational; 2],
    /// The knot span in v.
    pub v: [BigRational; 2],
    /// The rational Bézier patch (`points[i][j]`, i along u).
    pub patch: RectPatch<T>,
}

impl<T: Scalar> NurbsCurve<T> {
    /// The homogeneous control points `(w·P, w)`.
    pub fn control_points(&self) -> &[HPoint<T>] {
        &self.ctrl
    }

    /// The curve with knots `knots` and homogeneous control points.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the count of points differs from the knots' or
    /// the points are not all of one dimension ≥ 1.
    pub fn new(knots: Knots, ctrl: Vec<HPoint<T>>) -> Result<Self, Error> {
        if ctrl.len() != knots.count() {
            return Err(Error::Shape(format!(
                "the knots need {} control points, not {}",
                knots.count(),
                ctrl.len()
            )));
        }
        RationalCurve::from_hom(ctrl.clone())?;
        Ok(NurbsCurve { knots, ctrl })
    }

    /// The knots.
    pub fn knots(&self) -> &Knots {
        &self.knots
    }

    /// The rational Bézier pieces, one per non-empty span, in order.
    pub fn bezier_pieces(&self) -> Vec<CurvePiece<T>> {
        self.knots
            .spans()
            .into_iter()
            .map(|k| CurvePiece {
                span: self.knots.interval(k),
                curve: RationalCurve::from_ctrl(
                    self.knots
                        .bezier_points(k, &self.ctrl[self.knots.local_range(k)]),
                ),
            })
            .collect()
    }

    /// The homogeneous point at `t` of span `k` by de Boor's algorithm (the
    /// independent evaluation the pieces are checked against).
    pub fn eval_hom_in_span(&self, k: usize, t: &T) -> HPoint<T> {
        self.knots
            .de_boor(k, &self.ctrl[self.knots.local_range(k)], t)
    }
}

/// A (rational) tensor-product B-spline surface in homogeneous form:
/// `ctrl[i][j]`, `i` along u (knots `u`), `j` along v (knots `v`).
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsSurface<T> {
    u: Knots,
    v: Knots,
    ctrl: Vec<Vec<HPoint<T>>>,
}

impl<T: Scalar> NurbsSurface<T> {
    /// The homogeneous control net `ctrl[i][j]` (`i` along u).
    pub fn control_points(&self) -> &[Vec<HPoint<T>>] {
        &self.ctrl
    }

    /// The surface with knots `u`, `v` and the homogeneous net `ctrl[i][j]`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the net is not `count_u × count_v` or ragged in
    /// dimension.
    pub fn new(u: Knots, v: Knots, ctrl: Vec<Vec<HPoint<T>>>) -> Result<Self, Error> {
        if ctrl.len() != u.count() || ctrl.iter().any(|r| r.len() != v.count()) {
            return Err(Error::Shape(format!(
                "the knots need a {}×{} control net",
                u.count(),
                v.count()
            )));
        }
        RectPatch::from_hom(ctrl.clone())?;
        Ok(NurbsSurface { u, v, ctrl })
    }

    /// The knots in u and in v.
    pub fn knots(&self) -> (&Knots, &Knots) {
        (&self.u, &self.v)
    }

    /// The rational Bézier patches, one per pair of non-empty spans, u-span
    /// major. Rows (fixed i) are split in v first, then the columns of each
    /// v-piece in u: the tensor product of the two curve decompositions.
    pub fn bezier_pieces(&self) -> Vec<SurfacePiece<T>> {
        let (p, q) = (self.u.degree, self.v.degree);
        let v_spans = self.v.spans();
        // rows_v[s][i] = the Bézier points of row i on v-span s.
        let rows_v: Vec<Vec<Vec<HPoint<T>>>> = v_spans
            .iter()
            .map(|&l| {
                self.ctrl
                    .iter()
                    .map(|row| self.v.bezier_points(l, &row[self.v.local_range(l)]))
                    .collect()
            })
            .collect();
        let mut out = Vec::new();
        for k in self.u.spans() {
            for (s, &l) in v_spans.iter().enumerate() {
                let cols: Vec<Vec<HPoint<T>>> = (0..=q)
                    .map(|j| {
                        let col: Vec<HPoint<T>> = rows_v[s][self.u.local_range(k)]
                            .iter()
                            .map(|r| r[j].clone())
                            .collect();
                        self.u.bezier_points(k, &col)
                    })
                    .collect();
                let net = (0..=p)
                    .map(|i| (0..=q).map(|j| cols[j][i].clone()).collect())
                    .collect();
                out.push(SurfacePiece {
                    u: self.u.interval(k),
                    v: self.v.interval(l),
                    patch: RectPatch::from_hom(net).expect("pieces of a valid net are valid"),
                });
            }
        }
        out
    }

    /// The homogeneous point at `(s, t)` of spans `(k, l)` by de Boor in v on
    /// each local row, then in u (independent of [`Self::bezier_pieces`]).
    pub fn eval_hom_in_span(&self, (k, l): (usize, usize), s: &T, t: &T) -> HPoint<T> {
        let col: Vec<HPoint<T>> = self.ctrl[self.u.local_range(k)]
            .iter()
            .map(|row| self.v.de_boor(l, &row[self.v.local_range(l)], t))
            .collect();
        self.u.de_boor(k, &col, s)
    }
}

#[cfg(test)]
mod tests;
