//! Faces swept by a curve with no closed form — a `SURFACE_OF_REVOLUTION`
//! of a B-spline or an ellipse, a `SURFACE_OF_LINEAR_EXTRUSION` of a
//! B-spline or of a circle not along its axis — as a grid of spanned
//! Bézier pieces, measured like a B-spline face
//! ([`SplineSurface::from_pieces`](super::certify::spline::SplineSurface::from_pieces)).
//!
//! **The grid.** The reader's pieces ([`crate::analytic::revolution`],
//! [`crate::analytic::extrusion`]) are a tensor grid in row-major order:
//! for a revolution the four quarter arcs of the turn (u, the angle) times
//! the profile's pieces (v); for an extrusion the curve's pieces (u) times
//! one segment (v). Each patch is `σ(a(s), b(t))` for the rational pieces
//! `a`, `b` of its two directions and the map `σ`, affine in each
//! argument, of the surface's formula (the swept curve's point `b`
//! turned by the angle whose cosine and sine are `a`; the curve's point
//! `a` moved by `b`·V).
//!
//! **Spans that make the surface `C¹`.** Measures across a break between
//! two pieces need the surface `C¹` there in the one parameter that runs
//! through both (the foot-point system holds first derivatives,
//! [`super::certify::spline`]). Along one direction the pieces are given
//! spans one after the other: with `d⁻` the derivative at the end of piece
//! `k` in its own parameter and `d⁺` that at the start of piece `k + 1`,
//! the derivatives in the common parameter are `d⁻/h_k` and `d⁺/h_{k+1}`
//! for spans of lengths `h`. If `d⁺ = r·d⁻` with a rational `r > 0`, the
//! span `h_{k+1} = r·h_k` makes them equal: the direction's curve is `C¹`
//! across the break, and so is the surface, `σ` being affine in it (for a
//! revolution `∂σ/∂v` is the turned `b'`, for an extrusion `∂σ/∂u = a'`).
//! Otherwise the break is only `C⁰` (span 1, no box crosses it). The
//! derivative of a rational piece at its ends is `n·(w₁/w₀)(P₁ − P₀)` and
//! `n·(w_{n−1}/w_n)(P_n − P_{n−1})` (Farin, *Curves and Surfaces for
//! CAGD*, §13.4), exact in `Q`.
//!
//! **The turn.** The quarter arcs ([`crate::analytic::quarter_arcs`],
//! weights 1, 1, 2) start with speed 2 and end with speed 1, so the turn's
//! spans double: `[0, 1]`, `[1, 3]`, `[3, 7]`, `[7, 15]`, every join `C¹`.
//! (Möbius-reparameterizing every other arc to weights ∝ (2, 1, 1) would
//! give unit spans, but a circle edge's own quarter arcs, weights 1, 1, 2,
//! would then map to the face's parameters by a Möbius function instead
//! of an affine one, which the cubic fitted to an edge's feet
//! ([`super::certify::compose`]) follows less well: on the revolved vase
//! of the corpus its gap bound went from 2·10⁻¹² to 10⁻⁴.) The border at
//! 0° is a border: an edge crossing it has its feet jump from one end of
//! the turn to the other, and its measures there stay unproved, as on a
//! closed B-spline face.
//!
//! Only rational grids are measured (coordinates in `Q`: the axis or the
//! extrusion vector has a rational direction); others are named as not
//! measured.

use crate::algebra::RealAlgebraic;
use crate::analytic::quarter_arcs;
use crate::hpoint::HPoint;
use crate::nurbs::SpannedPatch;
use crate::patch::Patch;
use crate::rect::RectPatch;
use crate::step::brep::{Face, Geometry};
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

type Q = BigRational;

/// A swept face's pieces with spans, and the inner breaks of each
/// direction across which the surface is `C¹`.
#[derive(Clone, Debug)]
pub struct SweptGrid {
    /// The pieces, each with its span in u and in v.
    pub pieces: Vec<SpannedPatch>,
    /// The breaks in u, then in v, where the surface is `C¹`.
    pub smooth: [Vec<Q>; 2],
}

/// A direction's spans: the breaks `b₀ = 0 < b₁ < …` and the inner breaks
/// across which it is `C¹`.
#[derive(Clone, Debug, PartialEq)]
struct Chain {
    breaks: Vec<Q>,
    smooth: Vec<Q>,
}

/// The grid of face `f` when its surface is a swept surface with no closed
/// form: `None` for other faces, `Some(Err(why))` when it is one that
/// cannot be measured.
pub fn swept_grid(f: &Face) -> Option<Result<SweptGrid, String>> {
    let Geometry::Analytic(a) = &f.surface.geometry else {
        return None;
    };
    let revolution = match f.surface.kind.as_str() {
        "SURFACE_OF_REVOLUTION" => true,
        "SURFACE_OF_LINEAR_EXTRUSION" => false,
        _ => return None,
    };
    if a.closed_form.is_some() {
        return None;
    }
    let why = |s: &str| format!("{} face: {s}", f.surface.kind);
    if a.approximate.is_some() {
        return Some(Err(why("converted approximately")));
    }
    let Some(patches) = a
        .pieces
        .iter()
        .map(rational_rect)
        .collect::<Option<Vec<_>>>()
    else {
        return Some(Err(why(
            "pieces with irrational coordinates (an axis or a vector with no rational direction)",
        )));
    };
    Some(grid(patches, revolution).ok_or_else(|| why("pieces that are not a full grid")))
}

/// The rows of the grid (u) and its columns (v), chained.
fn grid(patches: Vec<RectPatch<Q>>, revolution: bool) -> Option<SweptGrid> {
    let rows = if revolution { 4 } else { patches.len() };
    if rows == 0 || !patches.len().is_multiple_of(rows) {
        return None;
    }
    let columns = patches.len() / rows;
    let (patches, u) = if revolution {
        let arcs: Vec<Vec<HPoint<Q>>> = quarter_arcs::<Q>()
            .into_iter()
            .map(|arc| arc.iter().map(|(p, w)| HPoint::from_point(p, w)).collect())
            .collect();
        (patches, chain(&arcs))
    } else {
        let firsts: Vec<Vec<HPoint<Q>>> = (0..rows)
            .map(|i| {
                patches[i * columns]
                    .ctrl()
                    .iter()
                    .map(|row| row[0].clone())
                    .collect()
            })
            .collect();
        let u = chain(&firsts);
        (patches, u)
    };
    let v = chain(
        &patches[..columns]
            .iter()
            .map(|p| p.ctrl()[0].clone())
            .collect::<Vec<_>>(),
    );
    let pieces = patches
        .into_iter()
        .enumerate()
        .map(|(k, p)| {
            let (i, j) = (k / columns, k % columns);
            SpannedPatch {
                patch: Patch::Rect(p),
                u: [u.breaks[i].clone(), u.breaks[i + 1].clone()],
                v: Some([v.breaks[j].clone(), v.breaks[j + 1].clone()]),
            }
        })
        .collect();
    Some(SweptGrid {
        pieces,
        smooth: [u.smooth, v.smooth],
    })
}

/// Spans for consecutive rational curve pieces (homogeneous control
/// points), `C¹` across every break where the end derivatives are positive
/// multiples of each other (see the module documentation).
fn chain(pieces: &[Vec<HPoint<Q>>]) -> Chain {
    let mut breaks = vec![Q::zero()];
    let mut smooth = Vec::new();
    let mut span = Q::one();
    for (k, piece) in pieces.iter().enumerate() {
        if k > 0 {
            match end_derivative(&pieces[k - 1], true)
                .zip(end_derivative(piece, false))
                .and_then(|(before, after)| positive_ratio(&before, &after))
            {
                Some(r) => {
                    span *= r;
                    smooth.push(breaks[k].clone());
                }
                None => span = Q::one(),
            }
        }
        breaks.push(breaks[k].clone() + &span);
    }
    Chain { breaks, smooth }
}

/// The derivative of a rational Bézier piece at its end (`at_end`) or its
/// start, in its own parameter: `n·(w₁/w₀)(P₁ − P₀)` at the start; `None`
/// for a piece of degree 0 or a zero end weight.
fn end_derivative(piece: &[HPoint<Q>], at_end: bool) -> Option<Vec<Q>> {
    let n = piece.len().checked_sub(1).filter(|&n| n > 0)?;
    let (outer, inner) = if at_end {
        (&piece[n], &piece[n - 1])
    } else {
        (&piece[0], &piece[1])
    };
    let (wo, wi) = (outer.weight(), inner.weight());
    if wo.is_zero() || wi.is_zero() {
        return None;
    }
    // n·(w_inner/w_outer)(P_inner − P_outer), negated at the end.
    let factor = Q::from_integer(n.into()) * wi / wo;
    let factor = if at_end { -factor } else { factor };
    Some(
        inner
            .weighted()
            .iter()
            .zip(outer.weighted())
            .map(|(a, b)| (a / wi - b / wo) * &factor)
            .collect(),
    )
}

/// `r > 0` with `after = r·before`, if there is one (`before ≠ 0`).
fn positive_ratio(before: &[Q], after: &[Q]) -> Option<Q> {
    let i = before.iter().position(|x| !x.is_zero())?;
    let r = &after[i] / &before[i];
    let parallel = before.iter().zip(after).all(|(b, a)| b * &r == *a);
    (parallel && r.is_positive()).then_some(r)
}

/// A rectangular piece over `RealAlgebraic` as one over `Q`, if every
/// coordinate is rational.
fn rational_rect(p: &Patch<RealAlgebraic>) -> Option<RectPatch<Q>> {
    let Patch::Rect(r) = p else {
        return None;
    };
    let rows = r
        .ctrl()
        .iter()
        .map(|row| {
            row.iter()
                .map(|h| h.try_map(&RealAlgebraic::as_rational))
                .collect::<Option<Vec<_>>>()
        })
        .collect::<Option<Vec<_>>>()?;
    RectPatch::from_hom(rows).ok()
}

#[cfg(test)]
mod tests;
