//! The gaps along an edge: from the edge curve to each face, and between
//! the two faces' foot points.
//!
//! **Edge to face.** With `σ(t)` the foot point of `C(t)` on the face
//! (`S(σ) − C` normal to the face), `n̂` the unit normal there and
//! `h(t) = (C(t) − S(σ(t)))·n̂(σ(t))` the signed distance, `|h|` is the
//! gap and, because `C − S(σ) = h n̂` and `n̂·n̂' = 0`,
//! `h'(t) = C'(t)·n̂(σ(t))`: no derivative of `σ` is needed. By the mean
//! value theorem, on a piece `T` with midpoint `t_m`,
//! `|h(t)| ≤ |h(t_m)| + max |C'(T)·n̂(σ(T))| · |T − t_m|`, whose error
//! shrinks like `|T|²` where the edge runs parallel to the face.
//!
//! **Face to face.** `E(t) = S₁(σ₁(t)) − S₂(σ₂(t))`, with
//! `E' = S₁,u σ₁,u' + S₁,v σ₁,v' − S₂,u σ₂,u' − S₂,v σ₂,v'` and
//! `E(T) ⊆ E(t_m) + E'(T)(T − t_m)`.

use super::foot::Foot;
use super::ivec::{add, cross, dot, norm2, scale, sub};
use super::local::Local;
use super::maximize::Bound;
use crate::algebra::Interval;

fn sqrt(x: &Interval) -> Interval {
    x.sqrt().expect("a sum of squares is never negative")
}

/// `|x|`'s lower end: 0 if `x` holds 0.
pub fn abs_lower(x: &Interval) -> f64 {
    if x.lo <= 0.0 && x.hi >= 0.0 {
        0.0
    } else {
        x.lo.abs().min(x.hi.abs())
    }
}

/// The gap from the edge to face `k` on one piece.
pub fn edge_face(l: &Local, k: usize) -> Bound {
    let (mid, over) = (&l.mid[k], &l.over[k]);
    let d = sqrt(&norm2(&sub(&l.c_mid.x, &mid.jet.x)));
    let n = cross(&over.jet.xu, &over.jet.xv);
    let slope = dot(&l.c_over.dx, &n).div(&sqrt(&norm2(&n)));
    let upper = match slope {
        Some(s) => d.add(&Interval::point(s.mul(&l.dt).mag())).hi,
        None => f64::INFINITY,
    };
    Bound { upper, lower: d.lo }
}

/// `S_u σ_u' + S_v σ_v'`: the velocity of the foot point.
fn foot_velocity(f: &Foot) -> Vec<Interval> {
    add(
        &scale(&f.jet.xu, &f.dsigma[0]),
        &scale(&f.jet.xv, &f.dsigma[1]),
    )
}

/// The gap between the two faces' foot points on one piece.
pub fn face_face(l: &Local) -> Bound {
    let e_mid = sub(&l.mid[0].jet.x, &l.mid[1].jet.x);
    let slope = sub(&foot_velocity(&l.over[0]), &foot_velocity(&l.over[1]));
    let e_over = add(&e_mid, &scale(&slope, &l.dt));
    Bound {
        upper: sqrt(&norm2(&e_over)).hi,
        lower: sqrt(&norm2(&e_mid)).lo,
    }
}
