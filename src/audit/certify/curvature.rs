//! The difference of the two faces' normal curvatures in the direction of
//! the edge.
//!
//! **Definition** (do Carmo, *Differential Geometry of Curves and
//! Surfaces*, 1976, §3-2): the normal curvature of a surface in the
//! tangent direction `w = S_u a + S_v b` is `κ_n = II(w, w) / I(w, w)`,
//!
//! ```text
//! κ_n = (L a² + 2 M a b + N b²) / (E a² + 2 F a b + G b²),
//! E = S_u·S_u, F = S_u·S_v, G = S_v·S_v,
//! L = S_uu·n̂, M = S_uv·n̂, N = S_vv·n̂,
//! ```
//!
//! with `n̂` the face's unit normal oriented out of the solid. Along an
//! edge the direction is the edge's tangent pulled back to each face:
//! `(a, b) = σ'(t)`, the derivative of the foot point. The measure is
//! `|κ₁ − κ₂|`: 0 along a curvature-continuous (G2) edge, whose faces share
//! an oriented normal and every normal curvature. Enclosed directly on
//! the foot box of each piece (width proportional to the piece's length).

use super::foot::Foot;
use super::gap::abs_lower;
use super::ivec::{cross, dot, norm2};
use super::local::{Face, Local};
use super::maximize::Bound;
use crate::algebra::Interval;

/// `κ_n` of a face at its foot, in the direction `σ'`; `None` if `I(w, w)`'s
/// enclosure holds 0.
pub fn normal_curvature(f: &Foot, sign: &Interval) -> Option<Interval> {
    let j = &f.jet;
    let [a, b] = f.dsigma;
    let n = cross(&j.xu, &j.xv);
    let len = norm2(&n).sqrt()?;
    let quad = |p: Interval, q: Interval, r: Interval| {
        p.mul(&a.sqr())
            .add(&Interval::point(2.0).mul(&q).mul(&a.mul(&b)))
            .add(&r.mul(&b.sqr()))
    };
    let second = quad(dot(&j.xuu, &n), dot(&j.xuv, &n), dot(&j.xvv, &n));
    let first = quad(dot(&j.xu, &j.xu), dot(&j.xu, &j.xv), dot(&j.xv, &j.xv));
    second.mul(sign).div(&first.mul(&len))
}

fn difference(feet: &[Foot; 2], faces: &[Face; 2]) -> Option<Interval> {
    let k1 = normal_curvature(&feet[0], &faces[0].sign())?;
    let k2 = normal_curvature(&feet[1], &faces[1].sign())?;
    Some(k1.sub(&k2))
}

/// `|κ₁ − κ₂|` on one piece (`None`: a curvature is not enclosed there).
pub fn curvature(l: &Local, faces: &[Face; 2]) -> Option<Bound> {
    let over = difference(&l.over, faces)?;
    let mid = difference(&l.mid, faces)?;
    Some(Bound {
        upper: over.mag(),
        lower: abs_lower(&mid),
    })
}
