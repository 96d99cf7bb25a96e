//! Knot lines from Bézier pieces: the continuity across each interior knot
//! read off the exact rational Bézier pieces of a surface
//! ([`crate::nurbs::SpannedPatch`]): the tests' independent check of the
//! knot-removal method of the parent module, which needs no conversion to
//! pieces.
//!
//! Pieces `L` on `[a, k]` and `R` on `[k, b]` (the same v span, the same
//! degree `n` in u) join `C^r` when, for every `i ≤ r`, their i-th
//! u-derivatives agree along the whole knot line. In Bernstein form those
//! derivatives are, up to the common factor `n!/(n−i)!`,
//!
//! ```text
//! ∂ᵢL(k, v) ∝ Δⁱ L_{n−i}(v) / (k − a)ⁱ,   ∂ᵢR(k, v) ∝ Δⁱ R₀(v) / (b − k)ⁱ,
//! Δⁱ X_s = Σ_{l=0}^{i} (−1)^{i−l} C(i, l) X_{s+l}
//! ```
//!
//! (rows of homogeneous control points `ω·(P, 1)`, compared coefficient by
//! coefficient in the v direction's Bernstein basis), so the test is
//! rational arithmetic on the control net: no evaluation, no tolerance.
//! Reference: Piegl & Tiller, *The NURBS Book* (1997), §2.5 (continuity at
//! a knot).

use super::{Direction, KnotLine};
use crate::algebra::scalar::{binomial_scalar, pow};
use crate::hpoint::HPoint;
use crate::nurbs::SpannedPatch;
use crate::patch::Patch;
use crate::rect::RectPatch;
use num_rational::BigRational;
use num_traits::One;

type Q = BigRational;

/// The interior knot lines of a B-spline surface's Bézier pieces, u-knots
/// first, each in increasing order; the least order over the line's v (or
/// u) spans. Curves, and pieces without a v span, have none.
pub(super) fn knot_lines(pieces: &[SpannedPatch]) -> Vec<KnotLine> {
    let rects: Vec<Spanned> = pieces
        .iter()
        .filter_map(|s| match (&s.patch, &s.v) {
            (Patch::Rect(r), Some(v)) => Some(Spanned {
                patch: r.clone(),
                u: s.u.clone(),
                v: v.clone(),
            }),
            _ => None,
        })
        .collect();
    let swapped: Vec<Spanned> = rects.iter().map(Spanned::swapped).collect();
    let mut out = lines_across(&rects, Direction::U);
    out.extend(lines_across(&swapped, Direction::V));
    out
}

/// A rect piece with its spans.
struct Spanned {
    patch: RectPatch<Q>,
    u: [Q; 2],
    v: [Q; 2],
}

impl Spanned {
    /// The same piece with u and v exchanged.
    fn swapped(&self) -> Spanned {
        Spanned {
            patch: self.patch.swap_uv(),
            u: self.v.clone(),
            v: self.u.clone(),
        }
    }
}

/// The u-knot lines of `pieces` (labelled `direction`).
fn lines_across(pieces: &[Spanned], direction: Direction) -> Vec<KnotLine> {
    let mut knots: Vec<Q> = pieces
        .iter()
        .map(|p| p.u[1].clone())
        .filter(|k| pieces.iter().any(|q| q.u[0] == *k))
        .collect();
    knots.sort();
    knots.dedup();
    knots
        .into_iter()
        .filter_map(|k| {
            let orders: Vec<(usize, Option<usize>)> = pieces
                .iter()
                .filter(|l| l.u[1] == k)
                .filter_map(|l| {
                    let r = pieces.iter().find(|r| r.u[0] == k && r.v == l.v)?;
                    if r.patch.degree() != l.patch.degree() {
                        return None;
                    }
                    Some((l.patch.degree().0, order_across(l, r)?))
                })
                .collect();
            let degree = orders.first()?.0;
            // The least order along the line: `None` (C^∞) is the largest.
            let continuity = orders
                .iter()
                .map(|o| o.1)
                .min_by(|a, b| match (a, b) {
                    (None, None) => std::cmp::Ordering::Equal,
                    (None, Some(_)) => std::cmp::Ordering::Greater,
                    (Some(_), None) => std::cmp::Ordering::Less,
                    (Some(x), Some(y)) => x.cmp(y),
                })
                .flatten();
            Some(KnotLine {
                direction,
                knot: k,
                degree,
                continuity,
            })
        })
        .collect()
}

/// The order `r` to which `left` (ending at the knot) and `right`
/// (starting there) agree (see the module docs), `Some(None)` when every
/// derivative up to the degree agrees, `None` when they do not even meet.
/// A constant factor between the two pieces' homogeneous coordinates
/// (pieces scaled apart) is allowed: it is read off the first row's end
/// weights.
fn order_across(left: &Spanned, right: &Spanned) -> Option<Option<usize>> {
    let n = left.patch.degree().0;
    let (hl, hr) = (&left.u[1] - &left.u[0], &right.u[1] - &right.u[0]);
    let (lc, rc) = (left.patch.ctrl(), right.patch.ctrl());
    let scale = rc[0][0].weight() / lc[n][0].weight();
    let mut order = None;
    for i in 0..=n {
        let agree = (0..lc[0].len()).all(|j| {
            let l = difference(|s| &lc[n - i + s][j], i).scale(&(&scale / pow(&hl, i as u32)));
            let r = difference(|s| &rc[s][j], i).scale(&(Q::one() / pow(&hr, i as u32)));
            l == r
        });
        if !agree {
            return (i > 0).then(|| Some(i - 1));
        }
        order = Some(i);
    }
    debug_assert_eq!(order, Some(n));
    Some(None)
}

/// `Δⁱ X₀ = Σ_l (−1)^{i−l} C(i, l) X_l` of the homogeneous points `x(l)`.
fn difference<'a>(x: impl Fn(usize) -> &'a HPoint<Q>, i: usize) -> HPoint<Q> {
    (0..=i).fold(HPoint::zero(x(0).dim()), |acc, l| {
        let c: Q = binomial_scalar(i, l);
        let signed = if (i - l).is_multiple_of(2) { c } else { -c };
        acc.add(&x(l).scale(&signed))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::nurbs::{Knots, Nurbs, NurbsSurface};

    fn q(n: i64) -> Q {
        Q::from_integer(n.into())
    }

    /// A bicubic surface with u-knots `0⁴, (1/2)^μ, 1⁴` (μ = `mult`),
    /// v-knots `0⁴, 1⁴`, and control points `point(i, j)`.
    fn bicubic(mult: usize, point: impl Fn(usize, usize) -> [i64; 3]) -> Vec<SpannedPatch> {
        bicubic_at(Q::new(1.into(), 2.into()), mult, point)
    }

    /// [`bicubic`] with the inner knot at `knot`.
    fn bicubic_at(
        knot: Q,
        mult: usize,
        point: impl Fn(usize, usize) -> [i64; 3],
    ) -> Vec<SpannedPatch> {
        let rows = 4 + mult;
        let net = (0..rows)
            .map(|i| {
                (0..4)
                    .map(|j| HPoint::from_cartesian(&point(i, j).map(q)))
                    .collect()
            })
            .collect();
        let mut uk = vec![q(0); 4];
        uk.extend(std::iter::repeat_n(knot, mult));
        uk.extend(vec![q(1); 4]);
        let u = Knots::new(3, uk, rows).unwrap();
        let v = Knots::new(3, [vec![q(0); 4], vec![q(1); 4]].concat(), 4).unwrap();
        Nurbs::Surface(NurbsSurface::new(u, v, net).unwrap()).pieces()
    }

    /// Integer points whose heights follow no polynomial.
    fn wiggly(i: usize, j: usize) -> [i64; 3] {
        [i as i64, j as i64, ((i * 7 + j * 3) % 5) as i64]
    }

    /// A generic net is exactly as smooth as B-spline theory allows at a
    /// knot of multiplicity μ, `C^{3−μ}` (Piegl & Tiller §2.5), and no
    /// smoother.
    #[test]
    fn a_generic_net_is_as_smooth_as_its_knot_multiplicity() {
        // At 1/3 the spans differ (1/3 and 2/3): the derivatives are
        // compared in the file's parameter, not the pieces' own.
        for knot in [Q::new(1.into(), 2.into()), Q::new(1.into(), 3.into())] {
            for (mult, want) in [(1, 2), (2, 1), (3, 0)] {
                let lines = knot_lines(&bicubic_at(knot.clone(), mult, wiggly));
                assert_eq!(lines.len(), 1, "μ = {mult}");
                assert_eq!(lines[0].direction, Direction::U);
                assert_eq!(lines[0].knot, knot);
                assert_eq!(lines[0].degree, 3);
                assert_eq!(lines[0].continuity, Some(want), "μ = {mult} at {knot}");
            }
        }
    }

    /// Control points at the Greville abscissae of the knots (times 6:
    /// 0, 1, 3, 5, 6 for a simple knot at 1/2) reproduce the linear
    /// function x = 6u (linear precision), so with constant heights the
    /// surface is one polynomial and the knot is removable.
    #[test]
    fn a_net_with_linear_precision_has_a_removable_knot() {
        let greville = [0, 1, 3, 5, 6];
        let lines = knot_lines(&bicubic(1, |i, j| [greville[i], j as i64, 2]));
        assert_eq!(lines[0].continuity, None);
    }

    /// With a triple knot the pieces share the joint row 3: a spike there
    /// leaves them meeting (C⁰) with different slopes.
    #[test]
    fn a_spike_at_a_triple_knot_is_c0() {
        let greville = [0, 1, 2, 3, 4, 5, 6];
        let spike = |i: usize, j: usize| [greville[i], j as i64, i64::from(i == 3 && j == 1) * 5];
        assert_eq!(knot_lines(&bicubic(3, spike))[0].continuity, Some(0));
    }

    #[test]
    fn v_knots_are_found_by_symmetry() {
        let pieces: Vec<SpannedPatch> = bicubic(1, wiggly)
            .into_iter()
            .map(|s| SpannedPatch {
                patch: match s.patch {
                    Patch::Rect(r) => Patch::Rect(r.swap_uv()),
                    other => other,
                },
                u: s.v.clone().unwrap(),
                v: Some(s.u),
            })
            .collect();
        let lines = knot_lines(&pieces);
        assert_eq!(lines.len(), 1);
        assert_eq!(lines[0].direction, Direction::V);
        assert_eq!(lines[0].continuity, Some(2));
    }

    #[test]
    fn one_piece_has_no_knot_line() {
        assert!(knot_lines(&bicubic(0, wiggly)).is_empty());
    }
}
