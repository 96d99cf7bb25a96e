//! The feet of an edge's points near a curve fitted in a face's
//! parameters, enclosed by Krawczyk's operator: a tube of parameter boxes
//! `p(t) + E` around the fitted curve `p`, each proved to hold exactly one
//! foot point of the edge point `C(t)`.
//!
//! **Why.** A B-spline face's normal along an edge is taken along a curve
//! `p` fitted to the edge's feet ([`super::spline::SplineField::normal_over`]);
//! how far the true foot `q(t)` may be from `p(t)` decides the slack of
//! the angle. A bound from the distance alone (the nearest point is no
//! farther than `S(p(t))`, so `|q − p| ≤ 2g/σ` with `g` the bound of
//! `|C − S∘p|` and `σ` the least stretch of `(S_u S_v)`) does not shrink
//! with the piece where the edge is really off the face: 10⁻³ mm off a
//! face of radius 20 mm it stays near 10⁻⁴ rad, a hundred times the
//! angular tolerance. The foot-point system's residual along `p` vanishes
//! wherever `p` passes through the feet, whatever the gap, so the bound
//! below shrinks with the fitting error of `p`.
//!
//! **The residual along `p`.** With the foot-point system
//! `F(σ; P) = ((S(σ) − P)·S_u, (S(σ) − P)·S_v)` ([`super::krawczyk`]),
//! the patch `H = (X, W)`, its derivative `H_u = (X_u, W_u)` and the edge
//! `C = (X_C, w_C)`, all composed with `p` (polynomials in the part's
//! parameter `s ∈ [0, 1]`, [`super::compose::compose`]),
//! `S_u = (W X_u − W_u X)/W²` and `S − C = −D/(W w_C)`, so
//!
//! ```text
//! F_u(p(s); C(s)) = −N_u / (W³ w_C),   N_u = (W X_u − W_u X)·D,   D = X_C W − X w_C,
//! ```
//!
//! likewise in `v`. For a patch of degree `(m, n)`, `p` of degree `k` and
//! `C` of degree `n_C`, `N_u` has degree `(3(m + n) − 1)k + n_C`, the
//! denominator `k` more; raised to it (times `((1 − s) + s)^k`), and where
//! every Bernstein coefficient `e_l` of `W³ w_C` is positive,
//! `|F_u| ≤ max_l |N_{u,l}|/e_l` over the part (the rational convex hull
//! property, as in [`super::compose::distance_bound`]).
//!
//! **The tube.** With `R` those bounds, `E = [−e_u, e_u] × [−e_v, e_v]`
//! and `Q` a box holding `p(s) + E` for the `s` of a sub-range `S'`, and
//! `J(Q; C(S'))` the Jacobian of `F` enclosed over it: for each `s ∈ S'`,
//! Krawczyk's operator on the box `B(s) = p(s) + E` about its centre is
//!
//! ```text
//! K(B(s)) = p(s) − Y F(p(s); C(s)) + (I − Y J(B(s); C(s)))·E
//!         ⊆ p(s) + (−Y [−R, R] + (I − Y J(Q; C(S')))·E)
//! ```
//!
//! by inclusion isotonicity (`B(s) ⊆ Q`). If the right-hand box lies in
//! the interior of `p(s) + E`, `F(·; C(s))` has exactly one zero in `B(s)`
//! (Krawczyk 1969; Moore, Kearfott & Cloud, *Introduction to Interval
//! Analysis*, SIAM 2009, §8.2): a foot point of `C(s)` within `e_u`, `e_v`
//! of `p(s)`, for every `s` of `S'` at once ([`holds`]).

use super::bezier::PatchJet;
use super::krawczyk::{operator, system};
use crate::algebra::interval_bernstein::{binomials, mul, unscale, Scaled};
use crate::algebra::Interval;

/// `a − b` for scaled forms of one degree.
fn difference(a: &[Interval], b: &[Interval]) -> Scaled {
    a.iter().zip(b).map(|(x, y)| x.sub(y)).collect()
}

/// `a + b` for scaled forms of one degree.
fn sum(a: Scaled, b: Scaled) -> Scaled {
    a.iter().zip(&b).map(|(x, y)| x.add(y)).collect()
}

/// Proved bounds of `|F_u|` and `|F_v|`, the foot-point system's residual
/// along a fitted curve `p` (see the module documentation), in the
/// parameters of `H`'s derivatives: `c` the edge's homogeneous coordinates
/// over the part, `h`, `hu`, `hv` those of `H`, `H_u`, `H_v` composed with
/// `p`, all in scaled form. `None` when a coefficient of the denominator
/// `W³ w_C` is not proved positive.
pub fn residual(c: &[Scaled], h: &[Scaled], hu: &[Scaled], hv: &[Scaled]) -> Option<[f64; 2]> {
    let w = &h[3];
    let d: Vec<Scaled> = (0..3)
        .map(|j| difference(&mul(&c[j], w), &mul(&h[j], &c[3])))
        .collect();
    let den = unscale(&mul(&mul(&mul(w, w), w), &c[3]))?;
    if !den.iter().all(|e| e.lo > 0.0) {
        return None;
    }
    let bound = |hk: &[Scaled]| -> Option<f64> {
        let n = (0..3)
            .map(|j| mul(&difference(&mul(w, &hk[j]), &mul(&hk[3], &h[j])), &d[j]))
            .reduce(sum)?;
        let raise = den.len().checked_sub(n.len())?;
        let n = unscale(&mul(&n, &binomials(raise)))?;
        n.iter().zip(&den).try_fold(0.0_f64, |most, (x, e)| {
            let ratio = Interval::point(x.mag()).div(&Interval::point(e.lo))?;
            Some(most.max(ratio.hi))
        })
    };
    let r = [bound(hu)?, bound(hv)?];
    r.iter().all(|x| x.is_finite()).then_some(r)
}

/// Does the tube of radii `radius` hold one foot for each edge point of
/// the box `points` whose fitted parameter `p(s)` keeps `p(s) + E` within
/// the box of `jet`: is `−Y [−R, R] + (I − Y J)·E`, with `R` =
/// `residual` (in the jet's parameters) and `J` the foot-point system's
/// Jacobian over `jet` and `points`, inside the interior of `E` (see the
/// module documentation)?
pub fn holds(jet: &PatchJet, points: &[Interval], residual: [f64; 2], radius: [f64; 2]) -> bool {
    let (_, j) = system(jet, points);
    let around = |x: f64| Interval { lo: -x, hi: x };
    let zero = Interval::point(0.0);
    let Some(k) = operator([zero; 2], residual.map(around), &j, radius.map(around)) else {
        return false;
    };
    (0..2).all(|i| around(radius[i]).interior_contains(&k[i]))
}

/// The radii `e` the tube needs over the box of `jet` for the edge's
/// points `points` and the residual's bounds `residual`, in `f64` (an
/// estimate: [`holds`] proves a choice): with `M = |I − Y J|` and
/// `b = |Y| R` (magnitudes), the box `−Y [−R, R] + (I − Y J)·E` is within
/// `E` when `b + M e ≤ e`, whose least solution is `e = (I − M)⁻¹ b`;
/// `None` unless `I − M` has a positive diagonal and determinant (then
/// `(I − M)⁻¹ ≥ 0`, the contraction's condition).
pub fn radius(jet: &PatchJet, points: &[Interval], residual: [f64; 2]) -> Option<[f64; 2]> {
    let (_, j) = system(jet, points);
    let around = |x: f64| Interval { lo: -x, hi: x };
    let zero = Interval::point(0.0);
    let unit = |k: usize| [0, 1].map(|i| Interval::point(if i == k { 1.0 } else { 0.0 }));
    let b = operator([zero; 2], residual.map(around), &j, [zero; 2])?.map(|x| x.mag());
    let columns = [0, 1].map(|k| operator([zero; 2], [zero; 2], &j, unit(k)));
    let [Some(c0), Some(c1)] = columns else {
        return None;
    };
    let m = [[c0[0].mag(), c1[0].mag()], [c0[1].mag(), c1[1].mag()]];
    let (a, d) = (1.0 - m[0][0], 1.0 - m[1][1]);
    let det = a * d - m[0][1] * m[1][0];
    if !(a > 0.0 && d > 0.0 && det > 0.0) {
        return None;
    }
    let e = [
        (d * b[0] + m[0][1] * b[1]) / det,
        (m[1][0] * b[0] + a * b[1]) / det,
    ];
    e.iter().all(|x| x.is_finite()).then_some(e)
}

#[cfg(test)]
mod tests;
