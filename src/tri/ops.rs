//! Operations on triangular patches: the barycentric Bernstein basis,
//! degree elevation, symmetries, the projective reparameterization,
//! sub-patches over any triangle (subdivision), boundary curves and
//! directional derivatives.
//!
//! Barycentric points are [`Bary`] = `[u, v, w]`; the vertices are
//! `T1 = [1, 0, 0]` (u = 1), `T2 = [0, 1, 0]` (v = 1), `T3 = [0, 0, 1]`
//! (w = 1). All operations are exact ring computations on the homogeneous
//! control points.
//!
//! Reference: source 001 (lecture), "三角域Bézier曲面"; source 003 §1 (eq. 2–4).

use super::TriPatch;
use crate::algebra::scalar::{binomial_scalar, ratio, Field, Scalar};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;

/// A barycentric point `[u, v, w]` (a triangle point when `u + v + w = 1`).
pub type Bary<T> = [T; 3];

/// The six symmetries of the triangle as permutations `σ` for
/// [`TriPatch::permute`]: the identity, the three transpositions and the two
/// rotations.
pub const SYMMETRIES: [[usize; 3]; 6] = [
    [0, 1, 2],
    [1, 0, 2],
    [2, 1, 0],
    [0, 2, 1],
    [1, 2, 0],
    [2, 0, 1],
];

/// The barycentric Bernstein polynomial
/// `B^n_{ijk}(u, v, w) = n!/(i! j! k!) uⁱ vʲ wᵏ` with `k = n − i − j`
/// (0 when `i + j > n`).
///
/// ```text
/// Laws (proved in proofs/src/triangles.rs for n ≤ 6):
///   B^n_{ijk} ≥ 0 on the triangle,   Σ_{i+j+k=n} B^n_{ijk} = (u + v + w)ⁿ = 1,
///   B^n_{ijk} = u B^{n−1}_{i−1,j,k} + v B^{n−1}_{i,j−1,k} + w B^{n−1}_{i,j,k−1}
/// ```
///
/// Reference: source 001 (lecture), "Bernstein基函数"; source 003 eq. (1).
///
/// # Examples
///
/// ```
/// use exact_bezier::{tri::tri_bernstein, ratio};
/// use exact_bezier::BigRational;
/// let b = [ratio::<BigRational>(1, 2), ratio(1, 4), ratio(1, 4)];
/// // 2!/(1! 1! 0!) · (1/2)(1/4) = 1/4
/// assert_eq!(tri_bernstein(2, 1, 1, &b), ratio(1, 4));
/// ```
pub fn tri_bernstein<T: Scalar>(n: usize, i: usize, j: usize, b: &Bary<T>) -> T {
    if i + j > n {
        return T::zero();
    }
    let k = n - i - j;
    // n!/(i! j! k!) = C(n, i) · C(n − i, j)
    binomial_scalar::<T>(n, i)
        * binomial_scalar::<T>(n - i, j)
        * b[0].pow_u32(i as u32)
        * b[1].pow_u32(j as u32)
        * b[2].pow_u32(k as u32)
}

/// The vertex `T_{index+1}` as a barycentric point (index 0, 1 or 2).
pub(crate) fn vertex<T: Scalar>(index: usize) -> Bary<T> {
    let mut b = [T::zero(), T::zero(), T::zero()];
    b[index] = T::one();
    b
}

/// `Σ_a x_a · verts[a]`: the point with barycentric coordinates `x` relative
/// to the triangle `verts` (the parameter map of [`TriPatch::subpatch`]).
///
/// ```
/// use exact_bezier::{tri::affine_combination, ratio};
/// use exact_bezier::BigRational;
/// let v = |a: i64, b: i64, c: i64| [ratio::<BigRational>(a, 1), ratio(b, 1), ratio(c, 1)];
/// let x = [ratio(1, 2), ratio(1, 2), ratio(0, 1)];
/// assert_eq!(affine_combination(&x, &[v(1, 0, 0), v(0, 0, 1), v(0, 1, 0)]), [ratio(1, 2), ratio(0, 1), ratio(1, 2)]);
/// ```
pub fn affine_combination<T: Scalar>(x: &Bary<T>, verts: &[Bary<T>; 3]) -> Bary<T> {
    std::array::from_fn(|c| (0..3).fold(T::zero(), |acc, a| acc + &(x[a].clone() * &verts[a][c])))
}

/// # Construction helpers, elevation, symmetries, weights
impl<T: Scalar> TriPatch<T> {
    /// The degree-`n` patch with control points `f(i, j, k)`, `i + j + k = n`.
    pub(crate) fn from_fn(n: usize, f: impl Fn(usize, usize, usize) -> HPoint<T>) -> Self {
        let rows = (0..=n)
            .map(|j| (0..=n - j).map(|i| f(i, j, n - i - j)).collect())
            .collect();
        TriPatch { n, rows }
    }

    /// The homogeneous control point with exponents `(i, j, k)`.
    fn at(&self, i: usize, j: usize) -> &HPoint<T> {
        &self.rows[j][i]
    }

    /// Raise the degree by one, keeping every point:
    /// `P*_{ijk} = (i P_{i−1,j,k} + j P_{i,j−1,k} + k P_{i,j,k−1}) / (n + 1)`
    /// on the homogeneous points.
    ///
    /// Reference: the triangular analogue of source 001 "升阶"; proved in
    /// `proofs/src/triangles.rs`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{TriPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let t = TriPatch::polynomial(vec![vec![p(0), p(3)], vec![p(6)]]).unwrap();
    /// let e = t.elevate();
    /// assert_eq!(e.degree(), 2);
    /// assert_eq!(e.eval(&ratio(1, 3), &ratio(1, 5)).unwrap(), t.eval(&ratio(1, 3), &ratio(1, 5)).unwrap());
    /// ```
    pub fn elevate(&self) -> Self {
        let n = self.n;
        let dim = self.dim();
        Self::from_fn(n + 1, |i, j, k| {
            let mut acc = HPoint::zero(dim);
            if i > 0 {
                acc = acc.add(&self.at(i - 1, j).scale(&ratio(i as i64, n as i64 + 1)));
            }
            if j > 0 {
                acc = acc.add(&self.at(i, j - 1).scale(&ratio(j as i64, n as i64 + 1)));
            }
            if k > 0 {
                acc = acc.add(&self.at(i, j).scale(&ratio(k as i64, n as i64 + 1)));
            }
            acc
        })
    }

    /// A symmetry of the triangle: the new patch at barycentric `x` is the
    /// old one at `y` with `y[σ[a]] = x[a]`; control points
    /// `P̃_e = P_f` with `f[σ[a]] = e[a]`. [`SYMMETRIES`] lists all six.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] if `sigma` is not a permutation of `{0, 1, 2}`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{TriPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let t = TriPatch::polynomial(vec![vec![p(0, 0), p(1, 0)], vec![p(0, 1)]]).unwrap();
    /// // swap u and v: the identity map becomes (u, v) ↦ (v, u)
    /// let s = t.permute([1, 0, 2]).unwrap();
    /// assert_eq!(s.eval(&ratio(1, 5), &ratio(2, 5)).unwrap(), vec![ratio(2, 5), ratio(1, 5)]);
    /// ```
    pub fn permute(&self, sigma: [usize; 3]) -> Result<Self, Error> {
        let mut seen = [false; 3];
        for &s in &sigma {
            if s > 2 || seen[s] {
                return Err(Error::Domain(format!(
                    "{sigma:?} is not a permutation of [0, 1, 2]"
                )));
            }
            seen[s] = true;
        }
        Ok(Self::from_fn(self.n, |i, j, k| {
            let e = [i, j, k];
            let mut f = [0; 3];
            for a in 0..3 {
                f[sigma[a]] = e[a];
            }
            self.at(f[0], f[1]).clone()
        }))
    }

    /// The projective reparameterization `(u : v : w) ↦ (a·u : b·v : c·w)`:
    /// control points unchanged, weights `ω̃_{ijk} = ω_{ijk} aⁱ bʲ cᵏ`. The
    /// new patch at `(u, v, w)` is the old one at
    /// `(a u, b v, c w) / (a u + b v + c w)` (homogeneously: the same point
    /// without the division), the triangle analogue of the Möbius map
    /// (source 000 eq. 4). Positive `a, b, c` keep the weights positive and
    /// map the triangle onto itself. Proved in `proofs/src/triangles.rs`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{TriPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let t = TriPatch::polynomial(vec![vec![p(0, 0), p(1, 0)], vec![p(0, 1)]]).unwrap();
    /// let r = t.reparam(&ratio(2, 1), &ratio(1, 1), &ratio(1, 1));
    /// // (1/2, 0, 1/2) ↦ (1, 0, 1/2)/(3/2) = (2/3, 0, 1/3)
    /// assert_eq!(r.eval(&ratio(1, 2), &ratio(0, 1)).unwrap(), vec![ratio(2, 3), ratio(0, 1)]);
    /// ```
    pub fn reparam(&self, a: &T, b: &T, c: &T) -> Self {
        Self::from_fn(self.n, |i, j, k| {
            let f = a.pow_u32(i as u32) * b.pow_u32(j as u32) * c.pow_u32(k as u32);
            self.at(i, j).scale(&f)
        })
    }

    /// Multiply every weight by `k` (the patch is unchanged), e.g. to
    /// normalize the weights to sum 1.
    pub fn scale_weights(&self, k: &T) -> Self {
        Self::from_fn(self.n, |i, j, _| self.at(i, j).scale(k))
    }

    /// The sum of all weights `Σ ω_{ijk}`.
    pub fn weight_sum(&self) -> T {
        self.rows
            .iter()
            .flatten()
            .fold(T::zero(), |acc, p| acc + p.weight())
    }
}

/// # Sub-patches, subdivision, boundary curves, derivatives
impl<T: Scalar> TriPatch<T> {
    /// The patch restricted to the triangle with barycentric vertices
    /// `verts = [V1, V2, V3]`, as a patch over the standard triangle:
    /// `Q_{ijk} = b[V1^i, V2^j, V3^k]` (blossom, source 003 eq. 4 and 26).
    /// The new patch at `x` equals the old at `x₀V1 + x₁V2 + x₂V3`,
    /// homogeneously. The vertices may lie anywhere (the polynomial extends).
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{TriPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let t = TriPatch::polynomial(vec![vec![p(0, 0), p(1, 0)], vec![p(0, 1)]]).unwrap();
    /// let h = ratio::<BigRational>(1, 2);
    /// let z = ratio::<BigRational>(0, 1);
    /// let one = ratio::<BigRational>(1, 1);
    /// let sub = t.subpatch(&[[h.clone(), z.clone(), h.clone()], [z.clone(), one.clone(), z.clone()], [z.clone(), z.clone(), one.clone()]]);
    /// assert_eq!(sub.eval(&one, &z).unwrap(), vec![h, z]);
    /// ```
    pub fn subpatch(&self, verts: &[Bary<T>; 3]) -> Self {
        let n = self.n;
        Self::from_fn(n, |i, j, k| {
            let mut args = Vec::with_capacity(n);
            args.extend(std::iter::repeat_n(verts[0].clone(), i));
            args.extend(std::iter::repeat_n(verts[1].clone(), j));
            args.extend(std::iter::repeat_n(verts[2].clone(), k));
            self.blossom_unchecked(&args)
        })
    }

    /// Subdivide at the point `p` (barycentric, normally interior) into three
    /// patches over the triangles `(p, T2, T3)`, `(T1, p, T3)`, `(T1, T2, p)`:
    /// piece `a` is the old patch on the triangle with vertex `a` replaced by
    /// `p`, reparameterized over the standard triangle (see
    /// [`TriPatch::subpatch`]).
    pub fn subdivide_at(&self, p: &Bary<T>) -> [Self; 3] {
        std::array::from_fn(|a| {
            let mut verts: [Bary<T>; 3] = std::array::from_fn(vertex);
            verts[a] = p.clone();
            self.subpatch(&verts)
        })
    }

    /// Split along edge `edge` at parameter `t` into two patches. Edge 0
    /// runs from T3 to T1 (v = 0), edge 1 from T1 to T2 (w = 0), edge 2
    /// from T2 to T3 (u = 0), matching [`TriPatch::boundary`]. With
    /// `q = (1 − t)·start + t·end`, the first piece replaces the end vertex
    /// by `q`, the second the start vertex.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] if `edge > 2`.
    pub fn split_edge(&self, edge: usize, t: &T) -> Result<[Self; 2], Error> {
        let (start, end) = edge_vertices(edge)?;
        let (vs, ve): (Bary<T>, Bary<T>) = (vertex(start), vertex(end));
        let s = T::one() - t;
        let q: Bary<T> = std::array::from_fn(|c| vs[c].clone() * &s + &(ve[c].clone() * t));
        let base: [Bary<T>; 3] = std::array::from_fn(vertex);
        let mut first = base.clone();
        first[end] = q.clone();
        let mut second = base;
        second[start] = q;
        Ok([self.subpatch(&first), self.subpatch(&second)])
    }

    /// The boundary curve along edge `edge` (0: T3→T1, v = 0, parameter u;
    /// 1: T1→T2, w = 0, parameter v; 2: T2→T3, u = 0, parameter w), as a
    /// rational curve of degree n: edge 0 has control points `P_{i,0,n−i}`,
    /// edge 1 `P_{n−i,i,0}`, edge 2 `P_{0,n−i,i}`, `i = 0…n`.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] if `edge > 2`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{TriPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let t = TriPatch::polynomial(vec![vec![p(0, 0), p(1, 0)], vec![p(0, 1)]]).unwrap();
    /// let c = t.boundary(1).unwrap();
    /// assert_eq!(c.eval(&ratio(1, 4)).unwrap(), vec![ratio(3, 4), ratio(1, 4)]);
    /// ```
    pub fn boundary(&self, edge: usize) -> Result<RationalCurve<T>, Error> {
        let n = self.n;
        let ctrl = (0..=n)
            .map(|i| match edge {
                0 => Ok(self.at(i, 0).clone()),
                1 => Ok(self.at(n - i, i).clone()),
                2 => Ok(self.at(0, n - i).clone()),
                _ => Err(Error::Domain(format!(
                    "a triangle has edges 0, 1, 2, not {edge}"
                ))),
            })
            .collect::<Result<Vec<_>, _>>()?;
        RationalCurve::from_hom(ctrl)
    }

    /// The homogeneous derivative in the barycentric direction `d`
    /// (`d₀ + d₁ + d₂ = 0` for a true direction; ∂/∂u in `(u, v)` is
    /// `[1, 0, −1]`): the degree n − 1 patch
    /// `n Σ (d₀ P_{i+1,j,k} + d₁ P_{i,j+1,k} + d₂ P_{i,j,k+1}) B^{n−1}_{ijk}`,
    /// i.e. `n · b[d, x^{n−1}]` (blossom). A degree-0 patch gives the zero
    /// patch of degree 0.
    pub fn deriv_hom(&self, d: &Bary<T>) -> Self {
        if self.n == 0 {
            return Self::from_fn(0, |_, _, _| HPoint::zero(self.dim()));
        }
        let level = super::casteljau_level(&self.rows, d);
        let n = T::from_i64(self.n as i64);
        let rows = level
            .iter()
            .map(|r| r.iter().map(|p| p.scale(&n)).collect())
            .collect();
        TriPatch {
            n: self.n - 1,
            rows,
        }
    }
}

/// The (start, end) vertex indices of edge `edge`.
fn edge_vertices(edge: usize) -> Result<(usize, usize), Error> {
    match edge {
        0 => Ok((2, 0)),
        1 => Ok((0, 1)),
        2 => Ok((1, 2)),
        _ => Err(Error::Domain(format!(
            "a triangle has edges 0, 1, 2, not {edge}"
        ))),
    }
}

/// # Cartesian derivatives
impl<T: Field> TriPatch<T> {
    /// The directional derivative of the Cartesian patch at `(u, v)` in the
    /// barycentric direction `d` (see [`TriPatch::deriv_hom`]), by the
    /// quotient rule `(Ĥ′ ω − Ĥ ω′) / ω²` on the homogeneous point `(Ĥ, ω)`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes at `(u, v)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{TriPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let t = TriPatch::polynomial(vec![vec![p(0, 0), p(1, 0)], vec![p(0, 1)]]).unwrap();
    /// let du = [ratio(1, 1), ratio(0, 1), ratio(-1, 1)];
    /// assert_eq!(t.directional_derivative(&ratio(1, 3), &ratio(1, 3), &du).unwrap(), vec![ratio(1, 1), ratio(0, 1)]);
    /// ```
    pub fn directional_derivative(&self, u: &T, v: &T, d: &Bary<T>) -> Result<Vec<T>, Error> {
        let h = self.eval_hom(u, v);
        let dh = self.deriv_hom(d).eval_hom(u, v);
        let w = h.weight().clone();
        if w.is_zero() {
            return Err(Error::PointAtInfinity);
        }
        let dw = dh.weight().clone();
        let w2 = w.clone() * &w;
        Ok(h.weighted()
            .iter()
            .zip(dh.weighted())
            .map(|(x, dx)| (dx.clone() * &w - &(x.clone() * &dw)) / &w2)
            .collect())
    }
}
