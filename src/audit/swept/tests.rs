//! Spans of swept faces: expected values from the arcs' and knot vectors'
//! own formulas, and the surface checked `C¹` across every break by its
//! derivatives at points (a second method: the chain reads only the end
//! control points).

use super::*;
use crate::analytic::{extrusion, revolution};
use crate::curve::RationalCurve;
use crate::nurbs::{Knots, Nurbs, NurbsCurve};
use crate::ratio;

fn q(n: i64) -> Q {
    ratio(n, 1)
}

fn qs(v: &[i64]) -> Vec<Q> {
    v.iter().map(|&n| q(n)).collect()
}

fn curve(points: &[[i64; 3]], weights: &[i64]) -> RationalCurve<Q> {
    let p = points.iter().map(|p| qs(p)).collect();
    RationalCurve::new(p, qs(weights)).unwrap()
}

fn hom(c: &RationalCurve<Q>) -> Vec<HPoint<Q>> {
    c.ctrl().to_vec()
}

#[test]
fn the_turn_doubles_its_spans() {
    // Arc 0 is X(t) = ((1 − t²)/(1 + t²), 2t/(1 + t²)), the angle 2·atan t:
    // speed 2/(1 + t²), 2 at its start and 1 at its end; every arc is arc 0
    // turned. So span k + 1 is twice span k: breaks 0, 1, 3, 7, 15, each
    // inner one C¹.
    let arcs: Vec<Vec<HPoint<Q>>> = quarter_arcs::<Q>()
        .into_iter()
        .map(|arc| arc.iter().map(|(p, w)| HPoint::from_point(p, w)).collect())
        .collect();
    let c = chain(&arcs);
    assert_eq!(c.breaks, qs(&[0, 1, 3, 7, 15]));
    assert_eq!(c.smooth, qs(&[1, 3, 7]));
}

#[test]
fn a_c1_profile_is_chained_by_its_knot_spans() {
    // A quadratic B-spline with knots 0, 0, 0, 1, 3, 3, 3: C¹ at 1, its
    // pieces over [0, 1] and [1, 3]; the chain gives the same spans.
    let knots = Knots::new(2, qs(&[0, 0, 0, 1, 3, 3, 3]), 4).unwrap();
    let points = [[0, 0, 0], [1, 2, 0], [4, 2, 1], [5, 0, 3]];
    let ctrl = points
        .iter()
        .map(|p| HPoint::from_cartesian(&qs(p)))
        .collect();
    let pieces = Nurbs::Curve(NurbsCurve::new(knots, ctrl).unwrap()).pieces();
    let hom: Vec<Vec<HPoint<Q>>> = pieces
        .iter()
        .map(|p| match &p.patch {
            Patch::Curve(c) => c.ctrl().to_vec(),
            _ => unreachable!("curve pieces"),
        })
        .collect();
    let c = chain(&hom);
    assert_eq!(c.breaks, qs(&[0, 1, 3]));
    assert_eq!(c.smooth, qs(&[1]));
}

#[test]
fn a_corner_or_a_reversal_is_not_smooth() {
    let a = curve(&[[0, 0, 0], [1, 0, 0]], &[1, 1]);
    let corner = curve(&[[1, 0, 0], [1, 1, 0]], &[1, 1]);
    let back = curve(&[[1, 0, 0], [0, 0, 0]], &[1, 1]);
    for b in [corner, back] {
        let c = chain(&[hom(&a), hom(&b)]);
        assert_eq!(c.breaks, qs(&[0, 1, 2]));
        assert!(c.smooth.is_empty());
    }
    // A piece that stops (a repeated end point) has no direction there.
    let stop = curve(&[[0, 0, 0], [1, 0, 0], [1, 0, 0]], &[1, 1, 1]);
    let on = curve(&[[1, 0, 0], [2, 0, 0]], &[1, 1]);
    assert!(chain(&[hom(&stop), hom(&on)]).smooth.is_empty());
}

/// `∂S/∂u` (or `∂S/∂v`) of piece `p` at `(u, v)` in the grid's parameter:
/// the piece's own derivative over its span.
fn partial(p: &SpannedPatch, along_u: bool, at: [Q; 2]) -> Vec<Q> {
    let Patch::Rect(r) = &p.patch else {
        unreachable!("rect pieces")
    };
    let (a, b) = if along_u { (1, 0) } else { (0, 1) };
    let d = r.derivatives(a, b, &at[0], &at[1]).unwrap();
    let span = if along_u { &p.u } else { p.v.as_ref().unwrap() };
    let h = &span[1] - &span[0];
    d[a][b].iter().map(|x| x / &h).collect()
}

/// Every inner break the grid calls smooth has equal first derivatives on
/// both sides, at several points along it.
fn assert_c1_across_breaks(g: &SweptGrid, columns: usize) {
    let rows = g.pieces.len() / columns;
    let along: [Q; 3] = [ratio(0, 1), ratio(1, 3), ratio(1, 1)];
    for i in 0..rows {
        for j in 0..columns {
            let here = &g.pieces[i * columns + j];
            if i + 1 < rows && g.smooth[0].contains(&here.u[1]) {
                let next = &g.pieces[(i + 1) * columns + j];
                for s in &along {
                    assert_eq!(
                        partial(here, true, [q(1), s.clone()]),
                        partial(next, true, [q(0), s.clone()])
                    );
                }
            }
            if j + 1 < columns && g.smooth[1].contains(&here.v.as_ref().unwrap()[1]) {
                let next = &g.pieces[i * columns + j + 1];
                for s in &along {
                    assert_eq!(
                        partial(here, false, [s.clone(), q(1)]),
                        partial(next, false, [s.clone(), q(0)])
                    );
                }
            }
        }
    }
}

/// A C¹ profile in two pieces (a cubic B-spline with a simple inner knot),
/// off the axis.
fn profile() -> Vec<RationalCurve<Q>> {
    let knots = Knots::new(3, qs(&[0, 0, 0, 0, 2, 3, 3, 3, 3]), 5).unwrap();
    let points = [[2, 0, 0], [3, 0, 1], [1, 1, 2], [2, 0, 4], [3, 1, 5]];
    let ctrl = points
        .iter()
        .map(|p| HPoint::from_cartesian(&qs(p)))
        .collect();
    Nurbs::Curve(NurbsCurve::new(knots, ctrl).unwrap())
        .pieces()
        .into_iter()
        .map(|p| match p.patch {
            Patch::Curve(c) => c,
            _ => unreachable!("curve pieces"),
        })
        .collect()
}

#[test]
fn a_revolution_is_c1_across_every_break_it_calls_smooth() {
    let patches = revolution(&profile(), &qs(&[0, 0, 0]), &qs(&[0, 0, 1])).unwrap();
    let g = grid(patches.clone(), true).unwrap();
    assert_eq!(g.pieces.len(), 8);
    assert_eq!(g.smooth[0], qs(&[1, 3, 7]));
    assert_eq!(g.pieces[7].u, [q(7), q(15)]);
    // The profile's pieces span [0, 2] and [2, 3] of its knots: in the
    // chain, [0, 1] and [1, 3/2].
    assert_eq!(g.smooth[1], qs(&[1]));
    assert_eq!(g.pieces[1].v, Some([q(1), ratio(3, 2)]));
    assert_c1_across_breaks(&g, 2);
}

#[test]
fn an_extrusion_is_c1_across_every_break_it_calls_smooth() {
    let patches = extrusion(&profile(), &qs(&[1, 2, 2]), [&q(-1), &q(2)]).unwrap();
    let g = grid(patches, false).unwrap();
    assert_eq!(g.pieces.len(), 2);
    assert_eq!(g.smooth, [qs(&[1]), vec![]]);
    assert_c1_across_breaks(&g, 1);
}

#[test]
fn a_grid_that_is_not_full_is_refused() {
    let patches = revolution(&profile(), &qs(&[0, 0, 0]), &qs(&[0, 0, 1])).unwrap();
    assert!(grid(patches[..7].to_vec(), true).is_none());
    assert!(grid(Vec::new(), false).is_none());
}
