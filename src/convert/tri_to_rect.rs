//! Triangle of degree n → rectangles (n, n) (source 003 §3; source 001,
//! Hu 1996).
//!
//! The split of the domain triangle (source 003 Fig. 1, eq. 19), in
//! `(u, v)` = the first two barycentric coordinates:
//!
//! ```text
//! p1 = T3 = (0, 0),  p2 = (b, 0),  p3 = (a, c),  p4 = (0, d),  p5 = (e, f)  (e + f = 1)
//! D1 = [p1, p2, p3, p4],  D2 = [p2, T1, p5, p3],  D3 = [p4, p3, p5, T2]
//! ```
//!
//! each quadrilateral listed as the bilinear corners `[L(0,0), L(1,0),
//! L(1,1), L(0,1)]` (read off eqs. 23, 24, 25). The default split
//! ([`Split::standard`]) is the centroid and the edge midpoints:
//! `a = c = 1/3`, `b = d = e = f = 1/2`.

use super::recip_binomial;
use crate::algebra::scalar::{binomial, ratio, Ordered, Scalar};
use crate::bernstein::binomial_rows;
use crate::blossom::ShiftOp;
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;
use crate::tri::{casteljau_level, Bary, TriPatch};
use num_rational::BigRational;

/// The split parameters `a, b, c, d, e, f` of source 003 eq. (19).
#[derive(Clone, Debug, PartialEq)]
pub struct Split<T> {
    params: [T; 6],
}

impl<T: Scalar> Split<T> {
    /// The split `[a, b, c, d, e, f]` without validation (for symbolic
    /// parameters); see [`Split::new`].
    pub fn new_unchecked(params: [T; 6]) -> Self {
        Split { params }
    }

    /// The default split: centroid and edge midpoints,
    /// `a = c = 1/3`, `b = d = e = f = 1/2`.
    pub fn standard() -> Self {
        let h = ratio::<T>(1, 2);
        let third = ratio::<T>(1, 3);
        Split {
            params: [third.clone(), h.clone(), third, h.clone(), h.clone(), h],
        }
    }

    /// `[a, b, c, d, e, f]`.
    pub fn params(&self) -> &[T; 6] {
        &self.params
    }

    /// The points `p1 … p5` in barycentric coordinates (eq. 19):
    /// `p1 = T3`, `p2 = bT1 + (1−b)T3`, `p3 = aT1 + cT2 + (1−a−c)T3`,
    /// `p4 = dT2 + (1−d)T3`, `p5 = eT1 + fT2`.
    pub fn points(&self) -> [Bary<T>; 5] {
        let [a, b, c, d, e, f] = self.params.clone();
        let z = T::zero;
        let one = T::one();
        [
            [z(), z(), one.clone()],
            [b.clone(), z(), one.clone() - &b],
            [a.clone(), c.clone(), one.clone() - &a - &c],
            [z(), d.clone(), one - &d],
            [e, f, z()],
        ]
    }

    /// The corners `[L(0,0), L(1,0), L(1,1), L(0,1)]` of quadrilateral
    /// `D_{piece+1}` (piece 0, 1 or 2).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] if `piece > 2`.
    pub fn quad(&self, piece: usize) -> Result<[Bary<T>; 4], Error> {
        let [p1, p2, p3, p4, p5] = self.points();
        let t1 = [T::one(), T::zero(), T::zero()];
        let t2 = [T::zero(), T::one(), T::zero()];
        match piece {
            0 => Ok([p1, p2, p3, p4]),
            1 => Ok([p2, t1, p5, p3]),
            2 => Ok([p4, p3, p5, t2]),
            _ => Err(Error::Domain(format!(
                "the split has pieces 0, 1, 2 (D1, D2, D3), not {piece}"
            ))),
        }
    }
}

impl<T: Ordered> Split<T> {
    /// A validated split: `p2, p4, p5` strictly inside their edges
    /// (`0 < b < 1`, `0 < d < 1`, `e, f > 0`, `e + f = 1`), `p3` strictly
    /// inside the triangle (`a, c > 0`, `a + c < 1`), and each quadrilateral
    /// strictly convex and counter-clockwise (so its bilinear map is
    /// one-to-one and the three cover the triangle without overlap).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] naming the first violated condition.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{convert::Split, ratio};
    /// use exact_bezier::BigRational;
    /// let ok = Split::<BigRational>::new([ratio(3, 10), ratio(1, 2), ratio(3, 10), ratio(1, 2), ratio(1, 2), ratio(1, 2)]);
    /// assert!(ok.is_ok());
    /// let bad = Split::<BigRational>::new([ratio(3, 10), ratio(1, 2), ratio(3, 10), ratio(1, 2), ratio(1, 2), ratio(1, 3)]);
    /// assert!(bad.unwrap_err().to_string().contains("e + f = 1"));
    /// ```
    pub fn new(params: [T; 6]) -> Result<Self, Error> {
        let [a, b, c, d, e, f] = &params;
        let (zero, one) = (T::zero(), T::one());
        let shown = params
            .iter()
            .map(|x| format!("{}", x.to_f64()))
            .collect::<Vec<_>>()
            .join(",");
        let fail = |what: &str| {
            Err(Error::Domain(format!(
                "split a,b,c,d,e,f = {shown}: {what}"
            )))
        };
        let inside = |x: &T| *x > zero && *x < one;
        if !inside(b) || !inside(d) {
            return fail("p2 = (b, 0) and p4 = (0, d) need 0 < b < 1 and 0 < d < 1");
        }
        if !(*e > zero && *f > zero) || e.clone() + f != one {
            return fail("p5 = (e, f) must lie inside the edge T1T2: e, f > 0 and e + f = 1");
        }
        if !(*a > zero && *c > zero) || a.clone() + c >= one {
            return fail("p3 = (a, c) must lie inside the triangle: a, c > 0 and a + c < 1");
        }
        let split = Split {
            params: params.clone(),
        };
        for piece in 0..3 {
            let q = split.quad(piece)?;
            if !strictly_convex(&q) {
                return fail(&format!(
                    "quadrilateral D{} is not strictly convex, so its bilinear map folds",
                    piece + 1
                ));
            }
        }
        Ok(split)
    }
}

/// Are the corners (in `(u, v)`, taken in the order L00, L10, L11, L01) a
/// strictly convex counter-clockwise quadrilateral? (All four turns left.)
fn strictly_convex<T: Ordered>(q: &[Bary<T>; 4]) -> bool {
    (0..4).all(|k| {
        let (p, c, n) = (&q[k], &q[(k + 1) % 4], &q[(k + 2) % 4]);
        let (x1, y1) = (c[0].clone() - &p[0], c[1].clone() - &p[1]);
        let (x2, y2) = (n[0].clone() - &c[0], n[1].clone() - &c[1]);
        x1 * &y2 - &(y1 * &x2) > T::zero()
    })
}

/// The bilinear map of source 003 eq. (20) for corners
/// `[c₀₀, c₁₀, c₁₁, c₀₁]`:
/// `L(s, t) = (1−s)(1−t) c₀₀ + s(1−t) c₁₀ + s t c₁₁ + (1−s) t c₀₁`.
pub fn bilinear<T: Scalar>(corners: &[Bary<T>; 4], s: &T, t: &T) -> Bary<T> {
    let (s1, t1) = (T::one() - s, T::one() - t);
    let f = [s1.clone() * &t1, s.clone() * &t1, s.clone() * t, s1 * t];
    std::array::from_fn(|c| (0..4).fold(T::zero(), |acc, k| acc + &(f[k].clone() * &corners[k][c])))
}

/// The hypergeometric weights `C(i, k) C(n − i, j − k) / C(n, j)` of eq.
/// (22) — the share of pairings of `(0^{n−i}, 1^i)` with `(0^{n−j}, 1^j)`
/// that have `k` pairs `(1, 1)` — as `weights(i, j, k)` for `k` in [`k_range`].
fn pairing_weights<T: Scalar>(n: usize) -> impl Fn(usize, usize, usize) -> T {
    let c = binomial_rows::<T>(n);
    let inv: Vec<T> = (0..=n).map(|j| recip_binomial::<T>(n, j)).collect();
    move |i, j, k| c[i][k].clone() * &c[n - i][j - k] * &inv[j]
}

/// The range of `k` in eq. (22) for `(i, j)`: `max(0, i + j − n) ≤ k ≤ min(i, j)`.
fn k_range(n: usize, i: usize, j: usize) -> std::ops::RangeInclusive<usize> {
    (i + j).saturating_sub(n)..=i.min(j)
}

/// The triangle restricted to the bilinear quadrilateral with corners
/// `[c₀₀, c₁₀, c₁₁, c₀₁]` (barycentric; anywhere in the plane), as a
/// rectangle of bidegree (n, n) over `[0, 1]²` (source 003 eq. 22, values by
/// the blossoming algorithm eq. 26):
///
/// ```text
/// P̂_{ij} = Σ_k C(i,k) C(n−i,j−k)/C(n,j) · b[c₀₀^{n−i−j+k}, c₁₀^{i−k}, c₁₁^k, c₀₁^{j−k}]
/// ```
///
/// The rectangle at `(s, t)` equals the triangle at [`bilinear`]`(corners, s, t)`,
/// homogeneously.
///
/// # Examples
///
/// ```
/// use exact_bezier::{convert::bilinear, convert::tri_to_rect_on_quad, convert::Split, TriPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let t = TriPatch::polynomial(vec![vec![p(0, 0), p(1, 0)], vec![p(0, 1)]]).unwrap();
/// let q = Split::standard().quad(0).unwrap();
/// let r = tri_to_rect_on_quad(&t, &q);
/// let (s, tt) = (ratio(1, 3), ratio(3, 4));
/// let x = bilinear(&q, &s, &tt);
/// assert_eq!(r.eval(&s, &tt).unwrap(), t.eval(&x[0], &x[1]).unwrap());
/// ```
pub fn tri_to_rect_on_quad<T: Scalar>(tri: &TriPatch<T>, corners: &[Bary<T>; 4]) -> RectPatch<T> {
    let n = tri.degree();
    let weight = pairing_weights::<T>(n);
    let table = quad_blossoms(tri, corners);
    let ctrl = (0..=n)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    k_range(n, i, j).fold(HPoint::zero(tri.dim()), |acc, k| {
                        acc.add(&table[j - k][k][i - k].scale(&weight(i, j, k)))
                    })
                })
                .collect()
        })
        .collect();
    RectPatch::from_hom(ctrl).expect("a non-empty square net of equal-length points")
}

/// Every blossom value `b[c₀₀^{n−x−y−z}, c₁₀^x, c₁₁^y, c₀₁^z]`
/// (`x + y + z ≤ n`) as `table[z][y][x]`, by the blossoming algorithm (26)
/// with the levels for common leading arguments computed once.
fn quad_blossoms<T: Scalar>(tri: &TriPatch<T>, corners: &[Bary<T>; 4]) -> Vec<Vec<Vec<HPoint<T>>>> {
    let n = tri.degree();
    let [c00, c10, c11, c01] = corners;
    let mut table = Vec::with_capacity(n + 1);
    let mut after_z = tri.rows().to_vec();
    for z in 0..=n {
        if z > 0 {
            after_z = casteljau_level(&after_z, c01);
        }
        let mut by_y = Vec::with_capacity(n - z + 1);
        let mut after_y = after_z.clone();
        for y in 0..=n - z {
            if y > 0 {
                after_y = casteljau_level(&after_y, c11);
            }
            let mut by_x = Vec::with_capacity(n - z - y + 1);
            let mut after_x = after_y.clone();
            for x in 0..=n - z - y {
                if x > 0 {
                    after_x = casteljau_level(&after_x, c10);
                }
                let mut rest = after_x.clone();
                for _ in 0..n - z - y - x {
                    rest = casteljau_level(&rest, c00);
                }
                by_x.push(rest.swap_remove(0).swap_remove(0));
            }
            by_y.push(by_x);
        }
        table.push(by_y);
    }
    table
}

/// The triangle as three rectangles of bidegree (n, n) over the split
/// `D1, D2, D3` (source 003 Theorem 3.2), by [`tri_to_rect_on_quad`]. Piece
/// `d` at `(s, t)` is the triangle at `bilinear(split.quad(d), s, t)`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{convert::tri_to_rects, convert::Split, TriPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let t = TriPatch::polynomial(vec![vec![p(0, 0), p(1, 0)], vec![p(0, 1)]]).unwrap();
/// let [d1, _, _] = tri_to_rects(&t, &Split::standard());
/// // D1's corner L(1, 1) is the centroid p3 = (1/3, 1/3).
/// assert_eq!(d1.eval(&ratio(1, 1), &ratio(1, 1)).unwrap(), vec![ratio(1, 3), ratio(1, 3)]);
/// ```
pub fn tri_to_rects<T: Scalar>(tri: &TriPatch<T>, split: &Split<T>) -> [RectPatch<T>; 3] {
    std::array::from_fn(|d| {
        let q = split.quad(d).expect("pieces 0, 1, 2 exist");
        tri_to_rect_on_quad(tri, &q)
    })
}

/// The three rectangles by the operator formulas as printed in source 003:
///
/// ```text
/// (23) P̂_{ij,D1} = Σ_{k=0}^i C(i,k)C(n−i,j−k)/C(n,j) (aE₁+cE₂+(1−a−c)E₃)^k (bE₁+(1−b)E₃)^{i−k} (dE₂+(1−d)E₃)^{j−k} E₃^{n−i−j+k} Q̂_{000}
/// (24) P̂_{ij,D2} = Σ_{k=0}^i … (eE₁+fE₂)^k (bE₁+(1−b)E₃)^{n−i−j+k} (aE₁+cE₂+(1−a−c)E₃)^{j−k} E₁^{i−k} Q̂_{000}
/// (25) P̂_{ij,D3} = Σ_{k=0}^i … (eE₁+fE₂)^k (dE₂+(1−d)E₃)^{n−i−j+k} (aE₁+cE₂+(1−a−c)E₃)^{i−k} E₂^{j−k} Q̂_{000}
/// ```
///
/// with the binomial convention `C(m, l) = 0` for `l < 0` or `l > m`. The
/// operator polynomials are expanded by [`ShiftOp`]; shown equal to
/// [`tri_to_rects`] in `proofs/src/conversions.rs`.
pub fn tri_to_rects_operators<T: Scalar>(tri: &TriPatch<T>, split: &Split<T>) -> [RectPatch<T>; 3] {
    let [p1, p2, p3, p4, p5] = split.points().map(|p| ShiftOp::linear(&p));
    let e1 = ShiftOp::linear(&[T::one(), T::zero(), T::zero()]);
    let e2 = ShiftOp::linear(&[T::zero(), T::one(), T::zero()]);
    // Operators raised to the counts [k, i−k, j−k, n−i−j+k], as printed.
    let printed = [
        [p3.clone(), p2.clone(), p4.clone(), p1],
        [p5.clone(), e1, p3.clone(), p2],
        [p5, p3, e2, p4],
    ];
    std::array::from_fn(|d| {
        let [op_k, op_ik, op_jk, op_rest] = &printed[d];
        operator_rect(tri, |n, i, j, k| {
            op_k.pow(k)
                .mul(&op_ik.pow(i - k))
                .mul(&op_jk.pow(j - k))
                .mul(&op_rest.pow(n + k - i - j))
        })
    })
}

/// `P̂_{ij} = Σ_{k ∈ k_range} pairing weight · op(n, i, j, k) Q̂_{000}`.
fn operator_rect<T: Scalar>(
    tri: &TriPatch<T>,
    op: impl Fn(usize, usize, usize, usize) -> ShiftOp<T>,
) -> RectPatch<T> {
    let n = tri.degree();
    let weight = pairing_weights::<T>(n);
    let ctrl = (0..=n)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    k_range(n, i, j).fold(HPoint::zero(tri.dim()), |acc, k| {
                        let w = weight(i, j, k);
                        let q = op(n, i, j, k).apply(tri).expect("operator degree n");
                        acc.add(&q.scale(&w))
                    })
                })
                .collect()
        })
        .collect();
    RectPatch::from_hom(ctrl).expect("a non-empty square net of equal-length points")
}

/// The rectangle on D1 by the lecture's shift-operator formula (source 001,
/// Hu 1996 eqs. 5, 6), in two-index notation `T_{ij} = Q_{i,j,n−i−j}` with
/// `I` the identity:
///
/// ```text
/// (5) P_{ij} = Σ_{k=0}^{i} Σ_{l=0}^{n−i} [k + l = j] C(i,k) C(n−i,l)/C(n,j) Q^{(i)}_{kl},   0 ≤ i, j ≤ n
/// (6) Q^{(i)}_{kl} = (aE₁ + cE₂ + (1−a−c)I)^k (bE₁ + (1−b)I)^{i−k} (dE₂ + (1−d)I)^l T_{00}
/// ```
///
/// Both sums run over their full printed ranges; the pair `(k, l)` is kept
/// only when `k + l = j`. Homogeneous points make it rational. Shown equal
/// to piece D1 of [`tri_to_rects`] in `proofs/src/conversions.rs`.
pub fn tri_to_rect_hu<T: Scalar>(tri: &TriPatch<T>, split: &Split<T>) -> RectPatch<T> {
    let n = tri.degree();
    let [_, p2, p3, p4, _] = split.points().map(|p| ShiftOp::linear(&p));
    let ctrl = (0..=n)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    let mut acc = HPoint::zero(tri.dim());
                    for k in 0..=i {
                        for l in (0..=n - i).filter(|l| k + l == j) {
                            let w = BigRational::new(
                                binomial(i, k) * binomial(n - i, l),
                                binomial(n, j),
                            );
                            let q = p3.pow(k).mul(&p2.pow(i - k)).mul(&p4.pow(l));
                            let q = q.apply(tri).expect("operator degree i + l ≤ n");
                            acc = acc.add(&q.scale(&T::from_rational(&w)));
                        }
                    }
                    acc
                })
                .collect()
        })
        .collect();
    RectPatch::from_hom(ctrl).expect("a non-empty square net of equal-length points")
}
