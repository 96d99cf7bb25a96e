//! A face's normal along a piece of an edge as a polynomial in the edge's
//! parameter, and the angle between two faces bounded from their normals
//! over the whole piece at once.
//!
//! **Why.** The angle between two faces' normals evaluated over a piece `T`
//! of an edge with boxes (a mean-value form) loses the cancellation of a
//! smooth joint: `N₁ × N₂` vanishes all along a G1 edge, but its box over
//! `T` is as wide as `|T|²` times the normals' rates of turn, so a tolerance
//! of 10⁻⁶ rad needs pieces of hundredths of a millimetre. Here each normal
//! is a polynomial `n(t)` with interval Bernstein coefficients (scaled form,
//! [`crate::algebra::interval_bernstein`]), so `V = n₁ × n₂` and
//! `c = n₁·n₂` are polynomials too, formed by exact algebra in
//! outward-rounded arithmetic: their coefficients are as small as the
//! angle itself, up to rounding.
//!
//! **A rational patch's normal.** With homogeneous coordinates
//! `H = (X, W)` and `P = X/W`, `P_u = (W X_u − W_u X)/W²`, and expanding the
//! cross product (the `X × X` term vanishes),
//!
//! ```text
//! W³ (P_u × P_v) = W (X_u × X_v) + W_v (X × X_u) + W_u (X_v × X),
//! ```
//!
//! a positive multiple of the surface's own normal (ISO 10303-42:
//! `S_u × S_v`) where the weights are positive. Composed with a curve
//! `p(t)` in the patch's parameters ([`super::compose::compose`] of `H`,
//! `H_u`, `H_v`), each term has degree `(3(m + n) − 2)k` for a patch of
//! degree `(m, n)` and `p` of degree `k`.
//!
//! **The angle.** For `t ∈ [0, 1]`, `θ(t) = atan2(|V(t)|, c(t))`. Where
//! the Bernstein coefficients `c_l` of `c` are all positive,
//! `V_k / c = Σ (c_l B_l / c)(V_{k,l} / c_l)` is a convex combination
//! (the rational convex hull property), so
//! `tan θ ≤ √(Σ_k max_l (V_{k,l}/c_l)²)` ([`angle_between`]).

use super::angle::polar_angle;
use super::compose::{compose, NetRef};
use crate::algebra::interval_bernstein::{mul, unscale, Scaled};
use crate::algebra::Interval;

/// A 3-vector of polynomials in scaled Bernstein form.
pub type ScaledVec = [Scaled; 3];

/// `a + b` for scaled forms of one degree.
fn add(a: &[Interval], b: &[Interval]) -> Scaled {
    a.iter().zip(b).map(|(x, y)| x.add(y)).collect()
}

/// `a × b`, componentwise products of scaled forms.
fn cross(a: &ScaledVec, b: &ScaledVec) -> ScaledVec {
    let term = |i: usize, j: usize| {
        let (p, q) = (mul(&a[i], &b[j]), mul(&a[j], &b[i]));
        p.iter().zip(&q).map(|(x, y)| x.sub(y)).collect::<Scaled>()
    };
    [term(1, 2), term(2, 0), term(0, 1)]
}

/// `f · a` for a scalar polynomial `f`.
fn times(f: &[Interval], a: &ScaledVec) -> ScaledVec {
    [0, 1, 2].map(|k| mul(f, &a[k]))
}

/// The Cartesian part `X` and the weight `W` of composed homogeneous
/// coordinates.
fn split(h: &[Scaled]) -> (ScaledVec, &Scaled) {
    ([h[0].clone(), h[1].clone(), h[2].clone()], &h[3])
}

/// The normal `W (X_u × X_v) + W_v (X × X_u) + W_u (X_v × X)` along
/// `p = (u, v)` (Bernstein coefficients of one degree), given `H∘p` and
/// the homogeneous nets `[H_u, H_v]` of a patch (see the module
/// documentation).
pub fn patch_normal(h: &[Scaled], nets: &[NetRef<'_>; 2], u: &[f64], v: &[f64]) -> ScaledVec {
    let [hu, hv] = nets.each_ref().map(|n| compose(n, u, v));
    let ((x, w), (xu, wu), (xv, wv)) = (split(h), split(&hu), split(&hv));
    let n = [
        times(w, &cross(&xu, &xv)),
        times(wv, &cross(&x, &xu)),
        times(wu, &cross(&xv, &x)),
    ];
    [0, 1, 2].map(|k| add(&add(&n[0][k], &n[1][k]), &n[2][k]))
}

/// The value at `t = 1/2` of a scaled form of degree `d`: `Σ c̃_i / 2^d`.
fn at_half(f: &[Interval]) -> Interval {
    let sum = f.iter().fold(Interval::point(0.0), |a, x| a.add(x));
    sum.mul(&Interval::point(0.5f64.powi(f.len() as i32 - 1)))
}

/// The angle between two normal paths over `t ∈ [0, 1]`: a proved upper
/// bound of its maximum, and its enclosure at `t = 1/2`; `None` unless
/// every Bernstein coefficient of `n₁·n₂` is proved positive (the normals
/// are not proved to be within a right angle of each other).
pub fn angle_between(n1: &ScaledVec, n2: &ScaledVec) -> Option<(f64, Interval)> {
    let v = cross(n1, n2);
    let c = [0, 1, 2]
        .map(|k| mul(&n1[k], &n2[k]))
        .iter()
        .fold(None::<Scaled>, |s, f| {
            Some(s.map_or(f.clone(), |s| add(&s, f)))
        })?;
    let mid = polar_angle(
        &[0, 1, 2]
            .map(|k| at_half(&v[k]).sqr())
            .iter()
            .fold(Interval::point(0.0), |a, x| a.add(x))
            .sqrt()?,
        &at_half(&c),
    );
    let c = unscale(&c)?;
    if c.iter()
        .any(|x| x.lo.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater))
    {
        return None;
    }
    let mut tan2 = Interval::point(0.0);
    for vk in &v {
        let most = unscale(vk)?
            .iter()
            .zip(&c)
            .map(|(x, cl)| x.div(&Interval::point(cl.lo)).map(|r| r.mag()))
            .try_fold(0.0_f64, |m, r| r.map(|r| m.max(r)))?;
        tan2 = tan2.add(&Interval::point(most).sqr());
    }
    let upper = polar_angle(&tan2.sqrt()?, &Interval::point(1.0)).hi;
    upper.is_finite().then_some((upper, mid))
}

/// `−n`: the normal of a face whose orientation is reversed.
pub fn reversed(n: &ScaledVec) -> ScaledVec {
    n.each_ref().map(|f| f.iter().map(Interval::neg).collect())
}

#[cfg(test)]
mod tests;
