//! A rational patch composed with a polynomial curve in its parameters,
//! and a proved bound on the distance from an edge curve to it.
//!
//! **Why.** The distance from a point `C(t)` of an edge to a face is at most
//! `|C(t) − S(p(t))|` for *any* curve `p` in the face's parameter domain.
//! With `p` a polynomial close to the edge's foot points, `S∘p` is a
//! rational Bézier curve, and the convex hull property bounds
//! `|C − S∘p|` over a whole piece of the edge at once, with an error that
//! shrinks like a power of the piece's length set by `p`'s degree — where a
//! mean-value form over the piece only shrinks like its square. `p` is any
//! curve: fitting it in `f64` costs no rigour, only tightness; clamping its
//! control points into the domain keeps it on the face (the Bézier curve
//! stays in the hull of its control points), which also holds an edge
//! along the face's border on the face rather than on its continuation.
//!
//! **Scaled Bernstein form.** A polynomial of degree `n` is held by
//! `c̃_i = C(n, i) c_i`, its coefficients in the basis `tⁱ(1 − t)^{n−i}`,
//! so that a product is a convolution: `(fg)~_l = Σ_{i+j=l} f̃_i g̃_j`
//! (Farin, *Curves and Surfaces for CAGD*, §5.5, products of Bernstein
//! polynomials). With `H_{ij}` the homogeneous control points of a patch
//! of degree `(m, n)` and `p = (u, v)` of degree `k`,
//!
//! ```text
//! H(u(t), v(t)) = Σ_i C(m,i) uⁱ(1 − u)^{m−i} Σ_j C(n,j) vʲ(1 − v)^{n−j} H_ij
//! ```
//!
//! of degree `(m + n)k`, where `1 − u` has the Bernstein coefficients
//! `1 − u_i`. All of it runs in outward-rounded interval arithmetic, so the
//! exact coefficients of the exact composition lie in the result.
//!
//! **The bound.** With `C = (P_C, w_C)` and `S∘p = (P_S, w_S)` homogeneous,
//! `C − S∘p = D / e` for `D = P_C w_S − P_S w_C` and `e = w_C w_S`, and
//! `|C − S∘p| ≤ max_l |D_l| / e_l` over their Bernstein coefficients
//! (the rational convex hull property, [`distance_bound`]).

use super::quad::Quad;
use crate::algebra::interval_bernstein::{binomials, mul, scale, unscale, Scaled};
use crate::algebra::Interval;
use crate::widest::Job;

/// `Σ c_k f_k` of scaled forms of one degree, for the four homogeneous
/// coordinates of the points `c_k` at once, each term added in turn.
#[inline(always)]
fn combination<'f>(terms: impl Iterator<Item = (Quad, &'f Scaled)>, len: usize) -> Vec<Quad> {
    let mut out = vec![Quad::zero(); len];
    for (c, f) in terms {
        for (o, x) in out.iter_mut().zip(f) {
            *o = o.add(&c.mul(x));
        }
    }
    out
}

/// The product `a · b` of a scaled form and four (`b`, lane by lane): the
/// convolution `out_l = Σ_{i+j=l} a_i b_j` accumulated in the order of
/// `i`, as [`mul`] does for each lane (the same bits: an interval product
/// does not depend on the order of its factors once rounded outward).
#[inline(always)]
fn convolve(a: &[Interval], b: &[Quad]) -> Vec<Quad> {
    let mut out = vec![Quad::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (o, y) in out[i..].iter_mut().zip(b) {
            *o = o.add(&y.mul(x));
        }
    }
    out
}

/// `C(d, i) xⁱ (1 − x)^{d−i}` for `i = 0..=d`, in scaled form, for the
/// polynomial `x` with Bernstein coefficients `x` (degree `k`): the
/// Bernstein basis of degree `d` composed with `x`.
fn basis_of(x: &[f64], d: usize) -> Vec<Scaled> {
    let ones = Interval::point(1.0);
    let xs = scale(&x.iter().map(|&c| Interval::point(c)).collect::<Vec<_>>());
    let rest = scale(
        &x.iter()
            .map(|&c| ones.sub(&Interval::point(c)))
            .collect::<Vec<_>>(),
    );
    let powers = |f: &Scaled| {
        let mut p = vec![vec![ones]];
        for i in 0..d {
            let next = mul(&p[i], f);
            p.push(next);
        }
        p
    };
    let (xp, rp) = (powers(&xs), powers(&rest));
    let b = binomials(d);
    (0..=d)
        .map(|i| {
            mul(&xp[i], &rp[d - i])
                .iter()
                .map(|c| c.mul(&b[i]))
                .collect()
        })
        .collect()
}

/// A tensor-product net of homogeneous control points in 3D (four
/// coordinates): `rows × cols` points, coordinate `d` of point `(i, j)` at
/// `coords[d][i·cols + j]` (rows along the first parameter).
pub struct NetRef<'a> {
    /// Points along the first parameter.
    pub rows: usize,
    /// Points along the second parameter.
    pub cols: usize,
    /// The coordinates, homogeneous (the weight last).
    pub coords: &'a [Vec<Interval>],
}

/// `H(u(t), v(t))`, each homogeneous coordinate in scaled form of degree
/// `(m + n)k`, for `p = (u, v)` given by Bernstein coefficients of degree
/// `k` (see the module documentation).
pub fn compose(net: &NetRef<'_>, u: &[f64], v: &[f64]) -> Vec<Scaled> {
    let (bu, bv) = (basis_of(u, net.rows - 1), basis_of(v, net.cols - 1));
    let out = crate::widest::run(Composition {
        net,
        bu: &bu,
        bv: &bv,
    });
    (0..4)
        .map(|d| out.iter().map(|q| q.lane(d)).collect())
        .collect()
}

/// The sums of [`compose`], run on the widest vector instructions the
/// processor has ([`crate::widest`]), the four homogeneous coordinates
/// side by side ([`Quad`]): `Σ_i B_i(u) Σ_j B_j(v) H_ij` with the bases
/// composed with `u` and `v` in `bu` and `bv`.
struct Composition<'a> {
    net: &'a NetRef<'a>,
    bu: &'a [Scaled],
    bv: &'a [Scaled],
}

impl Job for Composition<'_> {
    type Output = Vec<Quad>;

    #[inline(always)]
    fn run(self) -> Vec<Quad> {
        let (net, bu, bv) = (self.net, self.bu, self.bv);
        let point = |k: usize| Quad::new([0, 1, 2, 3].map(|d| net.coords[d][k]));
        let len_v = bv[0].len();
        let mut out = vec![Quad::zero(); bu[0].len() + len_v - 1];
        for (i, b) in bu.iter().enumerate() {
            let terms = (0..net.cols).map(|j| (point(i * net.cols + j), &bv[j]));
            let row = combination(terms, len_v);
            for (o, x) in out.iter_mut().zip(convolve(b, &row)) {
                *o = o.add(&x);
            }
        }
        out
    }
}

/// A proved upper bound of `|C(t) − S(t)|` over `t ∈ [0, 1]` for two
/// rational curves in 3D given by the scaled forms of their homogeneous
/// coordinates (`x, y, z, w`); `None` when the denominator's coefficients
/// are not proved positive. With `D = P_C w_S − P_S w_C` and
/// `e = w_C w_S = Σ e_l B_l`, `e_l > 0`, the difference
/// `D/e = Σ (e_l B_l / e)(D_l / e_l)` is a convex combination, so
/// `|C − S| ≤ max_l |D_l| / e_l`.
pub fn distance_bound(c: &[Scaled], s: &[Scaled]) -> Option<f64> {
    let (cw, sw) = (&c[3], &s[3]);
    let den = unscale(&mul(cw, sw))?;
    let diff: Vec<Vec<Interval>> = (0..3)
        .map(|d| {
            let a = mul(&c[d], sw);
            let b = mul(&s[d], cw);
            unscale(&a.iter().zip(&b).map(|(x, y)| x.sub(y)).collect::<Vec<_>>())
        })
        .collect::<Option<_>>()?;
    let mut bound = 0.0_f64;
    for (l, e) in den.iter().enumerate() {
        if e.lo.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let sq = diff
            .iter()
            .fold(Interval::point(0.0), |a, d| a.add(&d[l].sqr()));
        let ratio = sq.sqrt()?.div(&Interval::point(e.lo))?;
        bound = bound.max(ratio.hi);
    }
    bound.is_finite().then_some(bound)
}

/// The Bernstein coefficients of degree `values.len() − 1` of the
/// polynomial through `values` at equally spaced `t_j = j/k`, in `f64`
/// (Gaussian elimination with partial pivoting); `None` if singular,
/// which equally spaced nodes never are.
pub fn interpolate(values: &[f64]) -> Option<Vec<f64>> {
    let k = values.len() - 1;
    let basis = |i: usize, t: f64| -> f64 {
        let b: f64 = (0..i).map(|r| (k - r) as f64 / (r + 1) as f64).product();
        b * t.powi(i as i32) * (1.0 - t).powi((k - i) as i32)
    };
    let mut a: Vec<Vec<f64>> = (0..=k)
        .map(|j| {
            let t = if k == 0 { 0.0 } else { j as f64 / k as f64 };
            let mut row: Vec<f64> = (0..=k).map(|i| basis(i, t)).collect();
            row.push(values[j]);
            row
        })
        .collect();
    for col in 0..=k {
        let pivot = (col..=k).max_by(|&x, &y| a[x][col].abs().total_cmp(&a[y][col].abs()))?;
        a.swap(col, pivot);
        if a[col][col] == 0.0 {
            return None;
        }
        let pivot_row = a[col].clone();
        for (r, row) in a.iter_mut().enumerate() {
            if r != col {
                let f = row[col] / pivot_row[col];
                for (x, p) in row[col..].iter_mut().zip(&pivot_row[col..]) {
                    *x -= f * p;
                }
            }
        }
    }
    let out: Vec<f64> = (0..=k).map(|i| a[i][k + 1] / a[i][i]).collect();
    out.iter().all(|x| x.is_finite()).then_some(out)
}

#[cfg(test)]
mod tests;
