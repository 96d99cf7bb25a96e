//! The difference of the two faces' normal curvatures across an edge.
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
//! with `n̂` the face's unit normal oriented out of the solid.
//!
//! **Which direction.** In the direction of the edge's tangent the normal
//! curvatures of two faces with a common tangent plane always agree
//! (Meusnier's theorem, do Carmo §3-2: both equal `κ_C cos ∠(n_C, n̂)` for
//! the edge curve `C`), and so does the mixed term; what G2 adds to G1 is
//! the normal curvature *across* the edge. So the measure is taken in the
//! direction `w = n × C'` (in the tangent plane, perpendicular to the
//! edge), pulled back to each face by the first fundamental form:
//! `(a, b) ∝ (G (S_u·w) − F (S_v·w), E (S_v·w) − F (S_u·w))`. The measure
//! is `|κ₁ − κ₂|`, 0 exactly along a curvature-continuous (G2) edge.
//! Enclosed directly on the foot box of each piece (width proportional to
//! the piece's length).

use super::bezier::PatchJet;
use super::foot::Foot;
use super::gap::abs_lower;
use super::ivec::{cross, dot, norm2};
use super::local::{Face, Local};
use super::maximize::Bound;
use crate::algebra::Interval;

/// `κ_n` of a face across the edge of tangent `dc`, at every point of the
/// surface its jet `j` encloses (a foot box), relative to the normal
/// `sign · S_u × S_v`; `None` if `I(w, w)`'s enclosure holds 0.
pub fn curvature_across(j: &PatchJet, sign: &Interval, dc: &[Interval]) -> Option<Interval> {
    let n = cross(&j.xu, &j.xv);
    let len = norm2(&n).sqrt()?;
    let w = cross(&n, dc);
    let (e, ff, g) = (dot(&j.xu, &j.xu), dot(&j.xu, &j.xv), dot(&j.xv, &j.xv));
    let (uw, vw) = (dot(&j.xu, &w), dot(&j.xv, &w));
    let a = g.mul(&uw).sub(&ff.mul(&vw));
    let b = e.mul(&vw).sub(&ff.mul(&uw));
    let quad = |p: Interval, q: Interval, r: Interval| {
        p.mul(&a.sqr())
            .add(&Interval::point(2.0).mul(&q).mul(&a.mul(&b)))
            .add(&r.mul(&b.sqr()))
    };
    let second = quad(dot(&j.xuu, &n), dot(&j.xuv, &n), dot(&j.xvv, &n));
    let first = quad(e, ff, g);
    second.mul(sign).div(&first.mul(&len))
}

fn difference(feet: &[Foot; 2], faces: &[Face; 2], dc: &[Interval]) -> Option<Interval> {
    let k1 = curvature_across(&feet[0].jet, &faces[0].sign(), dc)?;
    let k2 = curvature_across(&feet[1].jet, &faces[1].sign(), dc)?;
    Some(k1.sub(&k2))
}

/// `|κ₁ − κ₂|` on one piece (`None`: a curvature is not enclosed there).
pub fn curvature(l: &Local, faces: &[Face; 2]) -> Option<Bound> {
    let over = difference(&l.over, faces, &l.c_over.dx)?;
    let mid = difference(&l.mid, faces, &l.c_mid.dx)?;
    Some(Bound {
        upper: over.mag(),
        lower: abs_lower(&mid),
    })
}
