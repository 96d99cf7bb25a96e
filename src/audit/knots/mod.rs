//! Knot lines of B-spline faces: the continuity of a face's own surface
//! across each interior knot, which is not a seam between faces (issue 28,
//! "knot lines are not seams").
//!
//! A B-spline surface of degree `p` in u is `C^{p−μ}` across a u-knot of
//! multiplicity μ ≤ p; its control net may make it smoother (a removable
//! knot). The continuity is that of the homogeneous surface `ω·(S, 1)` in
//! the file's own parameters, the one knot multiplicities control; its
//! projection to space is at least as smooth.
//!
//! [`surface_knot_lines`] decides the order on the B-spline's own data by
//! exact knot removal (module `removal`): write the surface as
//! `S(u, v) = Σ_j N_j(v) C_j(u)` with the column curves
//! `C_j(u) = Σ_i N_i(u) ctrl[i][j]`. The jump of the i-th u-derivative
//! across `u = k` is then `Σ_j N_j(v) · jump_i(C_j)`, a B-spline in v; on
//! each v-span its local basis functions are linearly independent, so the
//! jump vanishes along the whole line iff it vanishes for every column
//! curve (of the spans the surface has). A curve is `C^{p−μ+t}` at a knot
//! iff the knot can be removed `t` times, exactly; so the line's order is
//! the least over the columns of `p − μ + t`, and `None` (one polynomial)
//! when every column loses all μ copies. v-knots are the same with rows.
//!
//! A knot of multiplicity μ ≥ p + 1 cuts the surface into two independent
//! parts: they meet along a v-span when the last control points before the
//! knot and the first after it are the same up to one nonzero factor
//! (homogeneous points scaled apart describe the same rational surface).
//! Spans where they do not meet are left out of the line's order; a line
//! that meets nowhere is not listed (a broken net is reported by the
//! reader, not here). The tests compute the same on the surface's Bézier
//! pieces (module `pieces`, the independent oracle).
//!
//! Reference: Piegl & Tiller, *The NURBS Book* (2nd ed., 1997), §2.5
//! (continuity at a knot), §5.4 (knot removal, algorithm A5.8).

use crate::hpoint::HPoint;
use crate::nurbs::{Knots, NurbsSurface};
use num_rational::BigRational;
use num_traits::{One, Zero};
use removal::Near;

#[cfg(test)]
mod pieces;
mod removal;

type Q = BigRational;

/// The parameter direction a knot line runs across.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// A u-knot: the line `u = k`.
    U,
    /// A v-knot: the line `v = k`.
    V,
}

impl Direction {
    /// `"u"` or `"v"`.
    pub fn name(self) -> &'static str {
        match self {
            Direction::U => "u",
            Direction::V => "v",
        }
    }
}

/// The continuity of a face's surface across one interior knot.
#[derive(Clone, Debug, PartialEq)]
pub struct KnotLine {
    /// Across which parameter.
    pub direction: Direction,
    /// The knot value, in the file's parameters.
    pub knot: Q,
    /// The degree in that direction.
    pub degree: usize,
    /// `Some(r)`: the pieces join `C^r` and no smoother (`r < degree`);
    /// `None`: every derivative agrees, the pieces are one polynomial and
    /// the knot could be removed. `Some(0)` is a line where the surface
    /// only meets itself; pieces that do not meet at all are not listed
    /// (a broken net is reported by the reader, not here).
    pub continuity: Option<usize>,
}

/// The interior knot lines of a B-spline surface, u-knots first, each in
/// increasing order, decided by exact knot removal on the control net
/// (see the module docs): for a knot of multiplicity μ in degree `p`,
///
/// ```text
/// continuity = min over the column curves of p − μ + t,
///              t = how many times the knot can be removed from the column,
///              None when every column loses all μ copies.
/// ```
///
/// The result equals the order read off the surface's Bézier pieces
/// (the tests' oracle), without computing them. Exact. A knot of multiplicity μ ≥ p + 1 needs
/// nonzero weights at the control points on both sides of it to be seen
/// as met (readers give positive weights).
///
/// # Examples
///
/// A bilinear sheet split at u = 1/2 is one polynomial across the knot:
///
/// ```
/// use exact_bezier::audit::knots::{surface_knot_lines, Direction};
/// use exact_bezier::hpoint::HPoint;
/// use exact_bezier::nurbs::{Knots, NurbsSurface};
/// use exact_bezier::{ratio, BigRational};
/// let q = |n: i64, d: i64| ratio::<BigRational>(n, d);
/// let pt = |x: i64, y: i64| HPoint::from_cartesian(&[q(x, 1), q(y, 1), q(0, 1)]);
/// let u = Knots::new(1, vec![q(0, 1), q(0, 1), q(1, 2), q(1, 1), q(1, 1)], 3).unwrap();
/// let v = Knots::new(1, vec![q(0, 1), q(0, 1), q(1, 1), q(1, 1)], 2).unwrap();
/// let net = vec![vec![pt(0, 0), pt(0, 1)], vec![pt(1, 0), pt(1, 1)], vec![pt(2, 0), pt(2, 1)]];
/// let s = NurbsSurface::new(u, v, net).unwrap();
/// let lines = surface_knot_lines(&s);
/// assert_eq!(lines.len(), 1);
/// assert_eq!((lines[0].direction, lines[0].knot.clone()), (Direction::U, q(1, 2)));
/// assert_eq!(lines[0].continuity, None);
/// ```
pub fn surface_knot_lines(s: &NurbsSurface<Q>) -> Vec<KnotLine> {
    let (u, v) = s.knots();
    let net = s.control_points();
    let mut out = lines_across(u, v, |i, j| &net[i][j], Direction::U);
    out.extend(lines_across(v, u, |i, j| &net[j][i], Direction::V));
    out
}

/// The knot lines across the knots `across`, the net read as
/// `at(i, j)` with `i` along `across` and `j` along `along`.
fn lines_across<'a>(
    across: &Knots,
    along: &Knots,
    at: impl Fn(usize, usize) -> &'a HPoint<Q>,
    direction: Direction,
) -> Vec<KnotLine> {
    interior_knots(across)
        .into_iter()
        .filter_map(|(first, last)| {
            let joins: Vec<Option<Join>> = (0..along.count())
                .map(|j| join(across, first, last, |i| at(i, j)))
                .collect();
            Some(KnotLine {
                direction,
                knot: across.knots()[last].clone(),
                degree: across.degree(),
                continuity: least_over_spans(along, &joins)?,
            })
        })
        .collect()
}

/// The index ranges `first..=last` of the distinct knot values strictly
/// inside the domain `(u_p, u_{n+1})`, in increasing order. All copies of
/// such a value have indices in `p + 1 ..= n`.
fn interior_knots(knots: &Knots) -> Vec<(usize, usize)> {
    let (p, end, u) = (knots.degree(), knots.count(), knots.knots());
    (p + 1..end)
        .filter(|&i| u[p] < u[i] && u[i] < u[end] && u[i - 1] < u[i])
        .map(|i| {
            let copies = u[i..].iter().take_while(|x| **x == u[i]).count();
            (i, i + copies - 1)
        })
        .collect()
}

/// How one column curve crosses a knot, when its two sides meet: the
/// factor the points before the knot were scaled by (1 below multiplicity
/// p + 1) and the order there (`None`: one polynomial).
struct Join {
    scale: Q,
    order: Option<usize>,
}

/// The [`Join`] of the column curve with points `point(i)` across the knot
/// copies `first..=last` of `knots`; `None` when its two sides do not meet
/// (multiplicity μ ≥ p + 1 only). Those sides end at `P_{first−1}` and
/// begin at `P_{last−p}`; they meet when `P_{last−p} = c·P_{first−1}`
/// with `c` the ratio of the two weights.
fn join<'a>(
    knots: &Knots,
    first: usize,
    last: usize,
    point: impl Fn(usize) -> &'a HPoint<Q>,
) -> Option<Join> {
    let (p, mult) = (knots.degree(), last + 1 - first);
    let near = Near::around(knots, first, last, &point);
    if mult <= p {
        let order = near.order();
        return Some(Join {
            scale: Q::one(),
            order,
        });
    }
    let (before, after) = (point(first - 1), point(last - p));
    if before.weight().is_zero() || after.weight().is_zero() {
        return None;
    }
    let scale = after.weight() / before.weight();
    (before.scale(&scale) == *after).then(|| Join {
        order: near.joined(&scale).order(),
        scale,
    })
}

/// The least order along the line over the spans of `along` whose local
/// columns `l − q ..= l` all meet with one scale; `None` when no span
/// meets (`Some(None)`: one polynomial everywhere).
fn least_over_spans(along: &Knots, joins: &[Option<Join>]) -> Option<Option<usize>> {
    let q = along.degree();
    along
        .spans()
        .into_iter()
        .filter_map(|l| {
            let columns = &joins[l - q..=l];
            let scale = &columns[0].as_ref()?.scale;
            columns.iter().try_fold(None, |least, c| {
                let c = c.as_ref().filter(|c| c.scale == *scale)?;
                Some(lower(least, c.order))
            })
        })
        .reduce(lower)
}

/// The lower of two orders, `None` (every derivative agrees) the highest.
fn lower(a: Option<usize>, b: Option<usize>) -> Option<usize> {
    match (a, b) {
        (Some(x), Some(y)) => Some(x.min(y)),
        (x, None) | (None, x) => x,
    }
}

#[cfg(test)]
mod tests;
