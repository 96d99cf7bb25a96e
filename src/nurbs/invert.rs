//! The knot parameters of a point on a NURBS surface (point inversion), in
//! `f64`: a search heuristic, to place an edge's vertices in a surface's
//! parameter plane (the pieces cut there are exact).
//!
//! Seeds are a grid on every Bézier piece; from the nearest few,
//! Gauss–Newton on `|S(s, t) − P|²` (the normal equations
//! `JᵀJ δ = −Jᵀ(S − P)` with `J = (S_s S_t)`, clamped to the piece) finds the
//! foot; the local `(s, t)` of the best is mapped to the knot span
//! (Piegl & Tiller, *The NURBS Book*, §6.1, point inversion).

use super::SpannedPatch;
use crate::algebra::Ordered;
use crate::patch::Patch;
use crate::rect::RectPatch;

/// How many grid points all seeds may take together (a bounded cost for
/// surfaces of many pieces).
const SEED_BUDGET: usize = 20_000;
/// How many of the nearest seeds Newton starts from.
const STARTS: usize = 4;
/// Newton steps per start.
const STEPS: usize = 40;

/// A piece in `f64` with its knot spans.
struct Piece {
    patch: RectPatch<f64>,
    u: [f64; 2],
    v: [f64; 2],
}

/// The knot parameters `(u, v)` of the point of the surface with Bézier
/// pieces `pieces` nearest to `p` that the search finds, with its distance
/// from `p`; `None` for no surface pieces or a point of another dimension.
///
/// ```
/// use exact_bezier::nurbs::{nearest_parameters, Knots, Nurbs, NurbsSurface};
/// use exact_bezier::{hpoint::HPoint, ratio, BigRational};
/// // The bilinear plane z = 0 over [0, 2] × [0, 1], knots (0, 0, 2, 2), (0, 0, 1, 1).
/// let h = |x: i64, y: i64| HPoint::from_point(&[ratio(x, 1), ratio(y, 1), ratio(0, 1)], &ratio(1, 1));
/// let q = |v: &[i64]| v.iter().map(|&x| ratio::<BigRational>(x, 1)).collect::<Vec<_>>();
/// let (u, v) = (Knots::new(1, q(&[0, 0, 2, 2]), 2).unwrap(), Knots::new(1, q(&[0, 0, 1, 1]), 2).unwrap());
/// let s = NurbsSurface::new(u, v, vec![vec![h(0, 0), h(0, 1)], vec![h(2, 0), h(2, 1)]]).unwrap();
/// let (uv, d) = nearest_parameters(&Nurbs::Surface(s).pieces(), &[1.5, 0.25, 0.0]).unwrap();
/// assert!((uv[0] - 1.5).abs() < 1e-12 && (uv[1] - 0.25).abs() < 1e-12 && d < 1e-12);
/// ```
pub fn nearest_parameters(pieces: &[SpannedPatch], p: &[f64]) -> Option<([f64; 2], f64)> {
    let pieces: Vec<Piece> = pieces.iter().filter_map(piece_f64).collect();
    if pieces.is_empty() || pieces.iter().any(|q| q.patch.dim() != p.len()) {
        return None;
    }
    let n = (SEED_BUDGET / pieces.len()).isqrt().clamp(2, 6);
    let mut seeds: Vec<(f64, usize, [f64; 2])> = Vec::new();
    for (k, piece) in pieces.iter().enumerate() {
        for i in 0..n {
            for j in 0..n {
                let st = [i as f64 / (n - 1) as f64, j as f64 / (n - 1) as f64];
                if let Some(d) = distance(&piece.patch, st, p) {
                    seeds.push((d, k, st));
                }
            }
        }
    }
    seeds.sort_by(|a, b| a.0.total_cmp(&b.0));
    seeds
        .iter()
        .take(STARTS)
        .filter_map(|&(_, k, st)| {
            let piece = &pieces[k];
            let st = newton(&piece.patch, st, p);
            let d = distance(&piece.patch, st, p)?;
            let at = |span: [f64; 2], x: f64| span[0] + x * (span[1] - span[0]);
            Some(([at(piece.u, st[0]), at(piece.v, st[1])], d))
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
}

fn piece_f64(s: &SpannedPatch) -> Option<Piece> {
    let Patch::Rect(r) = &s.patch else {
        return None;
    };
    let span = |x: &[num_rational::BigRational; 2]| [x[0].to_f64(), x[1].to_f64()];
    Some(Piece {
        patch: r.map(Ordered::to_f64),
        u: span(&s.u),
        v: span(s.v.as_ref()?),
    })
}

fn distance(patch: &RectPatch<f64>, st: [f64; 2], p: &[f64]) -> Option<f64> {
    let x = patch.eval(&st[0], &st[1]).ok()?;
    let d = x
        .iter()
        .zip(p)
        .map(|(a, b)| (a - b).powi(2))
        .sum::<f64>()
        .sqrt();
    d.is_finite().then_some(d)
}

/// Gauss–Newton from `st`, clamped to `[0, 1]²` (module docs).
fn newton(patch: &RectPatch<f64>, mut st: [f64; 2], p: &[f64]) -> [f64; 2] {
    for _ in 0..STEPS {
        let Ok(d) = patch.derivatives(1, 1, &st[0], &st[1]) else {
            break;
        };
        let (x, su, sv) = (&d[0][0], &d[1][0], &d[0][1]);
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
        let r: Vec<f64> = x.iter().zip(p).map(|(a, b)| a - b).collect();
        let (a, b, c) = (dot(su, su), dot(su, sv), dot(sv, sv));
        let (g0, g1) = (dot(su, &r), dot(sv, &r));
        let det = a * c - b * b;
        if !(det.is_finite() && det > 0.0) {
            break;
        }
        let step = [(-c * g0 + b * g1) / det, (b * g0 - a * g1) / det];
        let next = [
            (st[0] + step[0]).clamp(0.0, 1.0),
            (st[1] + step[1]).clamp(0.0, 1.0),
        ];
        let moved = (next[0] - st[0]).abs() + (next[1] - st[1]).abs();
        st = next;
        if moved < 1e-15 {
            break;
        }
    }
    st
}
