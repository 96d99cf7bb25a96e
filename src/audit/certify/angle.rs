//! The angle between the two faces' oriented normals along an edge: 0 where
//! the faces meet tangent-plane continuously, π at a fold.
//!
//! With `N = ±(S_u × S_v)` (the sign making it point out of the solid),
//! `V = N₁ × N₂` and `c = N₁·N₂`, the angle is `θ = atan2(|V|, c)`
//! (`sin θ = |V|/(|N₁||N₂|)`, `cos θ = c/(|N₁||N₂|)`; no normalization or
//! square root of a difference is needed, so small angles are enclosed
//! with small absolute error). Along the edge `N' = N_u σ_u' + N_v σ_v'`
//! with `N_u = S_uu × S_v + S_u × S_uv`, `N_v = S_uv × S_v + S_u × S_vv`,
//! and on a piece `T`: `V(T) ⊆ V(t_m) + (N₁' × N₂ + N₁ × N₂')(T)·(T − t_m)`,
//! likewise `c`.
//!
//! **From `(|V|, c)` to radians.** Over a box of `(y, x) = (|V|, c)` with
//! `y ≥ 0` not holding the origin, the polar angle is extreme at the
//! corners; `f64::atan2` (correctly rounded to within an ulp in the usual
//! libm) is widened by a relative `2⁻⁴⁰`, far beyond its error.

use super::foot::Foot;
use super::ivec::{add, cross, dot, norm2, scale, IVec};
use super::local::{Face, Local};
use super::maximize::Bound;
use crate::algebra::Interval;

/// The oriented normal and its derivative along the edge.
fn normal(f: &Foot, sign: &Interval) -> (IVec, IVec) {
    let j = &f.jet;
    let n = scale(&cross(&j.xu, &j.xv), sign);
    let nu = add(&cross(&j.xuu, &j.xv), &cross(&j.xu, &j.xuv));
    let nv = add(&cross(&j.xuv, &j.xv), &cross(&j.xu, &j.xvv));
    let dn = scale(
        &add(&scale(&nu, &f.dsigma[0]), &scale(&nv, &f.dsigma[1])),
        sign,
    );
    (n, dn)
}

/// The angle `atan2(y, x)` over `y ≥ 0`, `x` in the intervals.
pub fn polar_angle(y: &Interval, x: &Interval) -> Interval {
    let y0 = y.lo.max(0.0);
    if y0 == 0.0 && x.lo <= 0.0 && x.hi >= 0.0 {
        return Interval {
            lo: 0.0,
            hi: std::f64::consts::PI * (1.0 + 1e-12),
        };
    }
    let corners = [
        y0.atan2(x.lo),
        y0.atan2(x.hi),
        y.hi.atan2(x.lo),
        y.hi.atan2(x.hi),
    ];
    let lo = corners.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = corners.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let slack = |a: f64| a.abs() * 2f64.powi(-40) + f64::MIN_POSITIVE;
    Interval {
        lo: (lo - slack(lo)).max(0.0),
        hi: hi + slack(hi),
    }
}

/// The angle between the faces on one piece.
pub fn angle(l: &Local, faces: &[Face; 2]) -> Bound {
    let signs = [faces[0].sign(), faces[1].sign()];
    let (n1m, _) = normal(&l.mid[0], &signs[0]);
    let (n2m, _) = normal(&l.mid[1], &signs[1]);
    let (n1, d1) = normal(&l.over[0], &signs[0]);
    let (n2, d2) = normal(&l.over[1], &signs[1]);
    let (v_mid, c_mid) = (cross(&n1m, &n2m), dot(&n1m, &n2m));
    let dv = add(&cross(&d1, &n2), &cross(&n1, &d2));
    let dc = dot(&d1, &n2).add(&dot(&n1, &d2));
    let v = add(&v_mid, &scale(&dv, &l.dt));
    let c = c_mid.add(&dc.mul(&l.dt));
    let len = |v: &[Interval]| norm2(v).sqrt().expect("a sum of squares is never negative");
    Bound {
        upper: polar_angle(&len(&v), &c).hi,
        lower: polar_angle(&len(&v_mid), &c_mid).lo,
    }
}
