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
//! `V / c = Σ (c_l B_l / c)(V_l / c_l)` is a convex combination of the
//! vectors `V_l / c_l` (the rational convex hull property), so
//! `tan θ = |V/c| ≤ max_l |V_l|/c_l` ([`angle_between`]).
//! Elsewhere (a crease near a right angle or beyond, where `c` changes
//! sign) the Bernstein hulls of `c`, `|n₁|²` and `|n₂|²` bound
//! `cos θ = c/(|n₁||n₂|)` from below over the piece.

use super::angle::polar_angle;
use super::ivec::{cross as cross3, dot as dot3, norm2, IVec};
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

/// The normal `W (X_u × X_v) + W_v (X × X_u) + W_u (X_v × X)` along a
/// curve `p` in a patch's parameters, from `H`, `H_u` and `H_v` composed
/// with `p` (`h`, `hu`, `hv`: Bernstein coefficients of one degree per
/// composition, [`super::compose::compose`]; see the module documentation).
pub fn patch_normal(h: &[Scaled], hu: &[Scaled], hv: &[Scaled]) -> ScaledVec {
    let ((x, w), (xu, wu), (xv, wv)) = (split(h), split(hu), split(hv));
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
/// bound of its maximum, and its enclosure at `t = 1/2`. Where every
/// Bernstein coefficient of `n₁·n₂` is proved positive the bound is that
/// of the tangent (`tangent_bound`, tight like the square of the
/// piece's length); elsewhere (a crease near or beyond a right angle)
/// that of the cosine (`cosine_bound`, tight like its length). `None`
/// when a normal's length is not proved positive.
pub fn angle_between(n1: &ScaledVec, n2: &ScaledVec) -> Option<(f64, Interval)> {
    let v = cross(n1, n2);
    let c = dot(n1, n2);
    let mid = polar_angle(
        &[0, 1, 2]
            .map(|k| at_half(&v[k]).sqr())
            .iter()
            .fold(Interval::point(0.0), |a, x| a.add(x))
            .sqrt()?,
        &at_half(&c),
    );
    let c = unscale(&c)?;
    let positive = c
        .iter()
        .all(|x| x.lo.partial_cmp(&0.0) == Some(std::cmp::Ordering::Greater));
    let upper = if positive {
        tangent_bound(&v, &c)?
    } else {
        cosine_bound(n1, n2, &c)?
    };
    upper.is_finite().then_some((upper, mid))
}

/// The angle between two normal paths at the ends `t = 0` and `t = 1` of
/// the piece, enclosed: there the paths are their first and last
/// Bernstein coefficients (a scaled form's ends are unscaled). With the
/// value at the middle ([`angle_between`]) they make the lower bound of the
/// angle over the piece: where the angle grows along the whole edge (a
/// crease between faces that open up), its maximum is at an end of the
/// edge, which no piece's middle reaches.
pub fn angle_at_ends(n1: &ScaledVec, n2: &ScaledVec) -> [Interval; 2] {
    let end = |last: bool| {
        let at = |n: &ScaledVec| -> IVec {
            n.iter()
                .map(|f| if last { f[f.len() - 1] } else { f[0] })
                .collect()
        };
        let (a, b) = (at(n1), at(n2));
        let v = cross3(&a, &b);
        let c = dot3(&a, &b);
        match norm2(&v).sqrt() {
            Some(length) => polar_angle(&length, &c),
            None => Interval {
                lo: 0.0,
                hi: std::f64::consts::PI,
            },
        }
    };
    [end(false), end(true)]
}

/// `n₁·n₂` in scaled form.
fn dot(n1: &ScaledVec, n2: &ScaledVec) -> Scaled {
    let [x, y, z] = [0, 1, 2].map(|k| mul(&n1[k], &n2[k]));
    add(&add(&x, &y), &z)
}

/// `atan max_l |V_l|/c_l` for the Bernstein coefficients `c` of `n₁·n₂`,
/// all positive, and `V = n₁ × n₂` in scaled form, `|V_l|` the length of
/// its `l`-th coefficient vector: `V/c = Σ_l λ_l (V_l/c_l)` with weights
/// `λ_l = c_l B_l / c ≥ 0` of sum 1 (the rational convex hull property),
/// so `|V/c| ≤ Σ_l λ_l |V_l/c_l|` (the triangle inequality). The vectors
/// `V_l/c_l` approach the curve `V/c` like the square of the piece's
/// length, whatever way `V` turns along it (bounding each component's
/// largest `|V_{k,l}/c_l|` on its own, as until 2026-11-29, is tight only
/// like its length where `V` turns: a crease along a curved edge).
fn tangent_bound(v: &ScaledVec, c: &[Interval]) -> Option<f64> {
    let [x, y, z] = [0, 1, 2].map(|k| unscale(&v[k]));
    let (x, y, z) = (x?, y?, z?);
    let mut most = 0.0_f64;
    for (l, cl) in c.iter().enumerate() {
        let length = x[l].sqr().add(&y[l].sqr()).add(&z[l].sqr()).sqrt()?;
        most = most.max(length.div(&Interval::point(cl.lo))?.hi);
    }
    Some(polar_angle(&Interval::point(most), &Interval::point(1.0)).hi)
}

/// `acos` of a lower bound of `cos θ = n₁·n₂/(|n₁||n₂|)` over the piece:
/// `m = min_l c_l` over the Bernstein coefficients `c` of `n₁·n₂` bounds
/// the numerator below, and the hulls of the coefficients of `|n₁|²` and
/// `|n₂|²` bound the denominator, so `cos θ ≥ m/max(|n₁||n₂|)` where
/// `m ≥ 0` and `≥ m/min(|n₁||n₂|)` where `m < 0`. `None` unless both
/// lengths are proved positive.
fn cosine_bound(n1: &ScaledVec, n2: &ScaledVec, c: &[Interval]) -> Option<f64> {
    let least = c.iter().map(|x| x.lo).fold(f64::INFINITY, f64::min);
    let hull = |n: &ScaledVec| -> Option<Interval> {
        let coefficients = unscale(&dot(n, n))?;
        let lo = coefficients
            .iter()
            .map(|x| x.lo)
            .fold(f64::INFINITY, f64::min);
        let hi = coefficients.iter().map(|x| x.hi).fold(0.0, f64::max);
        (lo > 0.0).then_some(Interval { lo, hi })
    };
    let lengths = hull(n1)?.mul(&hull(n2)?).sqrt()?;
    let by = if least >= 0.0 { lengths.hi } else { lengths.lo };
    let cos = Interval::point(least)
        .div(&Interval::point(by))?
        .lo
        .max(-1.0);
    let sin = Interval::point(1.0).sub(&Interval::point(cos).sqr());
    let sin = Interval {
        lo: sin.lo.max(0.0),
        hi: sin.hi.max(0.0),
    }
    .sqrt()?;
    Some(polar_angle(&sin, &Interval::point(cos)).hi)
}

/// `−n`: the normal of a face whose orientation is reversed.
pub fn reversed(n: &ScaledVec) -> ScaledVec {
    n.each_ref().map(|f| f.iter().map(Interval::neg).collect())
}

#[cfg(test)]
mod tests;
