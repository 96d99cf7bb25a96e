//! Certified foot points: the face parameters `σ(t) = (u, v)` of the
//! point of a patch nearest to the edge point `C(t)`, proved for every `t`
//! of a piece of the edge at once, and the derivative `σ'(t)`.
//!
//! An `f64` Newton iteration on the foot-point system (see
//! [`super::krawczyk`]) gives a guess `g`; boxes `g ± r` with growing `r`
//! (ε-inflation, Rump) are tried until the Krawczyk operator maps one into
//! its interior, which proves one foot point per `t` in that box; two more
//! Krawczyk steps shrink it. The foot point must lie in
//! `[−η, 1 + η]²` with `η` = [`DOMAIN_MARGIN`]: an edge runs along the
//! border of its face, so its foot points may fall a rounding error
//! outside the piece, on the patch's own rational continuation.
//!
//! **Derivative.** Differentiating `F(σ(t), t) = 0` (implicit function
//! theorem; `J` is regular on a Krawczyk-verified box):
//! `σ' = −J⁻¹ F_t` with `F_t = (−C'·S_u, −C'·S_v)`.

use super::bezier::{ICurve, IPatch, PatchJet};
use super::ivec::dot;
use super::krawczyk::{inverse, krawczyk, system, system_f64, IMat, Jets};
use crate::algebra::Interval;
use crate::error::Error;

/// How far outside `[0, 1]²` a foot point may lie.
pub const DOMAIN_MARGIN: f64 = 1.0 / 1024.0;

/// A verified foot box over a piece of the edge, with the jets on it.
#[derive(Clone, Debug)]
pub struct Foot {
    /// The box of `(u, v)` holding the foot point of every `C(t)`.
    pub uv: [Interval; 2],
    /// The patch's jet over `uv`.
    pub jet: PatchJet,
    /// `σ'(t)` over the piece.
    pub dsigma: [Interval; 2],
}

/// Below this, a Newton step that does not shrink is rounding noise.
const NOISE: f64 = 1e-9;

/// `f64` Newton on the foot-point system from `start`, each step clamped
/// into [`Jets::reach`] (a foot on the border of a face is a border point
/// whatever the first steps overshoot); `None` if a step is not finite.
pub fn newton<S: Jets + ?Sized>(patch: &S, c: &[Interval], start: [f64; 2]) -> Option<[f64; 2]> {
    let far = patch.reach();
    let c = [0, 1, 2].map(|k| c[k].mid());
    let mut g = start;
    let mut last = f64::INFINITY;
    for _ in 0..40 {
        let (f, j) = system_f64(&patch.jet_f64(g[0], g[1]).ok()?, &c);
        let y = inverse(&j)?;
        let step = [
            y[0][0] * f[0] + y[0][1] * f[1],
            y[1][0] * f[0] + y[1][1] * f[1],
        ];
        if !(step[0].is_finite() && step[1].is_finite()) {
            return None;
        }
        g = [0, 1].map(|k| (g[k] - step[k]).clamp(far[k][0], far[k][1]));
        let size = step[0].abs().max(step[1].abs());
        // Converged, or at rounding's noise floor (near a solution, a step
        // no shorter than the last).
        if size < 1e-15 || (size < NOISE && size >= last) {
            break;
        }
        last = size;
    }
    Some(g)
}

/// The nearest of a 9 × 9 grid of patch points to `c`: Newton's start
/// when no nearby solution is known.
fn grid_start(patch: &IPatch, c: &[Interval]) -> Option<[f64; 2]> {
    let mut best: Option<(f64, [f64; 2])> = None;
    for i in 0..=8 {
        for j in 0..=8 {
            let g = [f64::from(i) / 8.0, f64::from(j) / 8.0];
            let x = patch
                .jet(Interval::point(g[0]), Interval::point(g[1]))
                .ok()?
                .x;
            let d: f64 = x
                .iter()
                .zip(c)
                .map(|(a, b)| (a.mid() - b.mid()).powi(2))
                .sum();
            if best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, g));
            }
        }
    }
    best.map(|(_, g)| g)
}

fn inside(b: &[Interval; 2]) -> bool {
    b.iter()
        .all(|x| x.lo >= -DOMAIN_MARGIN && x.hi <= 1.0 + DOMAIN_MARGIN)
}

/// `−J⁻¹ F_t` by Cramer's rule, `None` when `det J`'s enclosure holds 0.
pub fn derivative(j: &IMat, ft: [Interval; 2]) -> Option<[Interval; 2]> {
    let det = j[0][0].mul(&j[1][1]).sub(&j[0][1].mul(&j[1][0]));
    let a = j[1][1].mul(&ft[0]).sub(&j[0][1].mul(&ft[1]));
    let b = j[0][0].mul(&ft[1]).sub(&j[1][0].mul(&ft[0]));
    Some([a.div(&det)?.neg(), b.div(&det)?.neg()])
}

/// The verified foot box over the edge piece `t` (an `f64` interval of the
/// curve's parameter), starting Newton at `guess` (else from a grid);
/// `None` when not verified (the caller splits `t`).
///
/// # Errors
///
/// Those of [`ICurve::jet`].
pub fn foot(
    curve: &ICurve,
    patch: &IPatch,
    t: Interval,
    guess: Option<[f64; 2]>,
) -> Result<Option<Foot>, Error> {
    let cj = curve.jet(t)?;
    let cm = curve.jet(Interval::point(t.mid()))?.x;
    let g = guess
        .and_then(|g| newton(patch, &cm, g))
        .or_else(|| grid_start(patch, &cm).and_then(|g| newton(patch, &cm, g)));
    let Some(g) = g else { return Ok(None) };
    let mut r = 4.0 * t.width() + 1e-13;
    for _ in 0..10 {
        let b = g.map(|x| Interval {
            lo: x - r,
            hi: x + r,
        });
        if let Ok(Some(k)) = krawczyk(patch, b, &cj.x)
            && b[0].interior_contains(&k[0])
            && b[1].interior_contains(&k[1])
        {
            return finish(patch, &cj, k);
        }
        r *= 4.0;
    }
    Ok(None)
}

/// Shrink a verified box by two Krawczyk steps, check the domain, and
/// add the jet and `σ'`.
fn finish(
    patch: &IPatch,
    cj: &super::bezier::CurveJet,
    mut b: [Interval; 2],
) -> Result<Option<Foot>, Error> {
    for _ in 0..2 {
        if let Some(k) = krawczyk(patch, b, &cj.x)? {
            match (b[0].intersect(&k[0]), b[1].intersect(&k[1])) {
                (Some(u), Some(v)) => b = [u, v],
                _ => break,
            }
        }
    }
    if !inside(&b) {
        return Ok(None);
    }
    let jet = patch.jet(b[0], b[1])?;
    let (_, j) = system(&jet, &cj.x);
    let ft = [dot(&cj.dx, &jet.xu).neg(), dot(&cj.dx, &jet.xv).neg()];
    Ok(derivative(&j, ft).map(|dsigma| Foot { uv: b, jet, dsigma }))
}
