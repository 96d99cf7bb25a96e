//! Rectangle (m, n) → two triangles of degree m + n (source 003 §2).

use super::recip_binomial;
use crate::algebra::scalar::Scalar;
use crate::bernstein::binomial_rows;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;
use crate::tri::{Bary, TriPatch};

/// Which half of the unit square a triangle covers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Half {
    /// Δ1 = {u + v ≤ 1}: the triangle at `(u, v, w)` is the rectangle at
    /// `(u, v)` (T1 = (1, 0), T2 = (0, 1), T3 = (0, 0)).
    Lower,
    /// Δ2 = {u + v ≥ 1}: the triangle at `(u, v, w)` is the rectangle at
    /// `(1 − u, 1 − v)` (T1 = (0, 1), T2 = (1, 0), T3 = (1, 1)).
    Upper,
}

impl Half {
    /// The rectangle parameters `(s, t)` of the triangle point `(u, v, w)`.
    pub fn rect_param<T: Scalar>(self, u: &T, v: &T) -> (T, T) {
        match self {
            Half::Lower => (u.clone(), v.clone()),
            Half::Upper => (T::one() - u, T::one() - v),
        }
    }
}

/// The rectangle restricted to one half of the unit square, as a triangle
/// of degree m + n (source 003 Theorem 2.3):
///
/// ```text
/// Q̂_{rst} = Σ_{i=0}^{min(m,r)} Σ_{j=max(0,s+i−m)}^{min(s,n−r+i)} P̂_{ij} C(r,i) C(s,j) C(t,n−j−r+i) / C(m+n,m)   (14)
/// ```
///
/// on Δ1, and the same with `P̂_{m−i,n−j}` on Δ2 (eq. 16). Homogeneous
/// points, so rational patches convert exactly; see [`Half`] for the
/// parameter maps (proved in `proofs/src/conversions.rs` for m, n ≤ 5).
///
/// # Examples
///
/// ```
/// use exact_bezier::{convert::rect_to_tri, convert::Half, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let r = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 1)], vec![p(1, 0), p(1, 1)]]).unwrap();
/// let t = rect_to_tri(&r, Half::Upper);
/// let (u, v) = (ratio(1, 4), ratio(1, 2));
/// assert_eq!(t.eval(&u, &v).unwrap(), vec![ratio(3, 4), ratio(1, 2)]);
/// ```
pub fn rect_to_tri<T: Scalar>(r: &RectPatch<T>, half: Half) -> TriPatch<T> {
    let (m, n) = r.degree();
    let ctrl = r.ctrl();
    let net = |i: usize, j: usize| match half {
        Half::Lower => &ctrl[i][j],
        Half::Upper => &ctrl[m - i][n - j],
    };
    let c = binomial_rows::<T>(m + n);
    let inv = recip_binomial::<T>(m + n, m);
    TriPatch::from_fn(m + n, |rr, s, t| {
        let mut acc = HPoint::zero(r.dim());
        for i in 0..=m.min(rr) {
            let lo = (s + i).saturating_sub(m);
            let hi = s.min((n + i).saturating_sub(rr));
            for j in lo..=hi {
                // n − j − r + i of the T3 arguments go to the v-blossom (eq. 14).
                let Some(k) = (n + i).checked_sub(j + rr) else {
                    continue;
                };
                if k > t {
                    continue;
                }
                let w = c[rr][i].clone() * &c[s][j] * &c[t][k] * &inv;
                acc = acc.add(&net(i, j).scale(&w));
            }
        }
        acc
    })
}

/// Both triangles, `[on Δ1, on Δ2]` (source 003 eqs. 14, 16).
pub fn rect_to_tris<T: Scalar>(r: &RectPatch<T>) -> [TriPatch<T>; 2] {
    [rect_to_tri(r, Half::Lower), rect_to_tri(r, Half::Upper)]
}

/// The corners `[c₀₀, c₁₀, c₁₁, c₀₁]` of the unit square in the barycentric
/// coordinates of the triangle on `half`, for [`tri_to_rect_on_quad`](crate::convert::tri_to_rect_on_quad):
/// converting that triangle back over the whole square gives the original
/// rectangle degree-elevated to (m + n, m + n), exactly.
pub fn square_corners<T: Scalar>(half: Half) -> [Bary<T>; 4] {
    let b = |u: i64, v: i64| [T::from_i64(u), T::from_i64(v), T::from_i64(1 - u - v)];
    match half {
        Half::Lower => [b(0, 0), b(1, 0), b(1, 1), b(0, 1)],
        // (s, t) ↦ (u, v) = (1 − s, 1 − t)
        Half::Upper => [b(1, 1), b(0, 1), b(0, 0), b(1, 0)],
    }
}
