//! A B-spline face as a [`DistanceField`]: the signed distance from points
//! to a (rational) B-spline surface, its unit normal and the normal's
//! derivative, through certified foot points.
//!
//! **Jets over boxes of the surface's parameters.** The surface is held as
//! its exact Bézier pieces with their knot spans (each enclosed at first
//! use, [`IPatch`]). Over a box `U × V` of the surface's own parameters,
//! [`SplineField`]'s [`Jets::jet`] is the hull of the jets of every piece the
//! box meets, each taken in the piece's local parameter `(u − a)/(b − a)`
//! with the derivatives scaled by `1/(b − a)` per order in `u` (likewise in
//! `v`). The hull is a valid slope enclosure for Krawczyk's operator
//! ([`super::krawczyk`]) and for the mean-value forms when `S` is `C¹`
//! across the knots the box crosses: the foot-point system is then
//! continuous and piecewise `C¹`, and the mean value theorem holds piece by
//! piece along a segment. A box that crosses a knot where the knot vector
//! only guarantees `C⁰` (multiplicity equal to the degree) is refused.
//!
//! **Beyond the border.** An edge along a face's border has foot points a
//! rounding error on either side of it. The surface is continued past its
//! border by its border pieces' own polynomials (a box may reach a quarter
//! of the border piece's span beyond it, which lets Newton and Krawczyk's
//! boxes straddle the border), so that such feet are proved. A foot
//! counts only when Krawczyk's image, which holds it, lies within
//! `BORDER_SLACK` (10⁻⁹ of the domain's width) of the domain: farther
//! out, the continuation is not the face — its normal there has turned
//! away from the border's, while the face's nearest point is on its
//! border — and the foot is refused (the measure is then taken from the
//! composed bounds below, which stay on the face, or left unproved). In a
//! direction where the surface is closed (its two borders are one curve,
//! compared exactly: proportional rows of control points) a foot found
//! past the seam is moved by a period to the other side, where the
//! surface really is, and proved there.
//!
//! **Gaps by composition.** The distance from an edge to the face itself
//! is bounded by [`SplineField::gap_over`]: `|C − S∘p|` for a cubic `p` in
//! the face's parameters fitted to the edge's feet and clamped into the
//! domain (see [`super::compose`]). Being the distance to points of the
//! face, it needs no foot proved and holds at the border; its error
//! shrinks like the fourth power of the edge piece's length.
//!
//! **Foot points.** For a box `P` of points the foot `σ(P)` solves the
//! foot-point system ([`super::krawczyk`]) in the surface's parameters:
//! `f64` Newton from the last foot found (else from the nearest of a grid
//! of points of every piece), then ε-inflated Krawczyk boxes until one is
//! proved. There, with `n = S_u × S_v` and `N = n/|n|` (the surface's own
//! normal, ISO 10303-42), `s = (P − S(σ))·N`, and by the implicit function
//! theorem `∂σ/∂P = −F_σ⁻¹ F_P` with `F_P = −(S_u, S_v)ᵀ`, so that
//! `J = ∂N/∂P = N_u ⊗ ∇u + N_v ⊗ ∇v`, where
//! `N_u = (n_u − N (N·n_u))/|n|`, `n_u = S_uu × S_v + S_u × S_uv` and
//! likewise in `v` (do Carmo, *Differential Geometry of Curves and
//! Surfaces*, 1976, §3-3). The foot proved is the unique stationary point of
//! `|P − S|²` in its box; near the surface (gaps far below its radii of
//! curvature) it is the nearest point.
//!
//! ```
//! use exact_bezier::audit::certify::field::DistanceField;
//! use exact_bezier::audit::certify::spline::{SplineField, SplineSurface};
//! use exact_bezier::algebra::Interval;
//! use exact_bezier::hpoint::HPoint;
//! use exact_bezier::nurbs::{Knots, NurbsSurface, Nurbs};
//! use exact_bezier::{ratio, BigRational};
//! let q = |n: i64| ratio::<BigRational>(n, 1);
//! // The plane z = 0 over [0, 2] × [0, 1], two linear pieces in u.
//! let pt = |x: i64, y: i64| HPoint::from_cartesian(&[q(x), q(y), q(0)]);
//! let u = Knots::new(1, vec![q(0), q(0), q(1), q(2), q(2)], 3).unwrap();
//! let v = Knots::new(1, vec![q(0), q(0), q(1), q(1)], 2).unwrap();
//! let net = vec![vec![pt(0, 0), pt(0, 1)], vec![pt(1, 0), pt(1, 1)], vec![pt(2, 0), pt(2, 1)]];
//! let s = NurbsSurface::new(u, v, net).unwrap();
//! let pieces = Nurbs::Surface(s.clone()).pieces();
//! let surface = SplineSurface::new(&s, &pieces).unwrap();
//! let field = SplineField::new(&surface);
//! // A point 1/8 above the plane, over the first piece.
//! let p = [0.5, 0.5, 0.125].map(Interval::point);
//! let d = field.distance(&p).unwrap();
//! assert!(d.signed.lo <= 0.125 && 0.125 <= d.signed.hi && d.signed.width() < 1e-14);
//! assert!(d.normal[2].lo > 0.999_999);
//! // Over the knot line u = 1, where the linear pieces meet only C⁰ by the
//! // knot vector, the foot is not proved.
//! assert!(field.distance(&[1.0, 0.5, 0.125].map(Interval::point)).is_none());
//! ```

use super::bezier::{ICurve, IPatch, Jet64, PatchJet};
use super::closed_form::Distance;
use super::compose::{compose, distance_bound, interpolate};
use super::curvature::curvature_across;
use super::field::{DistanceField, IMat3};
use super::foot::{derivative, newton};
use super::ivec::{add, cross, dot, norm2, scale, sub, IVec};
use super::krawczyk::{krawczyk, mid_inverse, system, Jets};
use super::normal_path::{patch_normal, ScaledVec};
use super::tube;
use crate::algebra::interval_bernstein::{scale as scaled_form, Scaled};
use crate::algebra::Interval;
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::limits;
use crate::nurbs::{Knots, NurbsSurface, SpannedPatch};
use crate::patch::Patch;
use crate::rect::RectPatch;
use num_rational::BigRational;
use num_traits::Zero;
use std::cell::{Cell, RefCell};
use std::collections::HashMap;
use std::rc::Rc;
use std::sync::OnceLock;

type Q = BigRational;

/// How many foot boxes a field remembers (the measures of one piece of an
/// edge ask for the same boxes several times).
const RECENT: usize = 8;

/// Points per side of the grid of each piece that seeds Newton.
const SEEDS: usize = 5;

/// Work units charged per control point of a piece whose jet is enclosed:
/// a bicubic jet (16 points, 4 000 units) took about 40 µs (`perf` of an
/// audit of wavy-cube.stp: about 100 000 jets in 4 s), 10 ns a unit, near
/// the cost model's mean of 7 ns a unit (docs/limits.md).
const JET_WORK: u64 = 250;

/// The most pieces along each axis a foot box may meet.
const FOOT_PIECES: usize = 2;

/// A first foot box's half-widths, in units of the foot's linearized
/// spread over the box of points ([`spread`]).
const START_SPREAD: f64 = 1.5;

/// How many times a foot box is doubled before the foot is given up.
const INFLATIONS: usize = 8;

/// How far beyond its border, relative to the domain's width, a foot
/// point proved on the surface's continuation still counts as the face's
/// (a rounding error of an edge along the border): farther out, the
/// continuation is not the face, and the foot is refused.
const BORDER_SLACK: f64 = 1e-9;

/// The degree of the curves `p` in the surface's parameters that
/// [`SplineField::gap_over`] fits to the feet of an edge.
const FIT_DEGREE: usize = 3;

/// Work units charged per control point of a piece composed with a fitted
/// curve (a bicubic composition with a cubic makes about 6 000 interval
/// products, near a jet's cost).
const COMPOSE_WORK: u64 = 250;

/// The least part of a piece's width a knot-line crossing is from the
/// piece's ends for [`SplineField::cuts`] to cut there.
const SLIVER: f64 = 1e-6;

/// The `j`-th of the [`FIT_DEGREE`]` + 1` equally spaced parameters of `t`.
fn node(t: Interval, j: usize) -> f64 {
    t.lo + (t.hi - t.lo) * j as f64 / FIT_DEGREE as f64
}

/// One parameter direction of the surface: the knots bounding its pieces
/// and the smoothness across them.
#[derive(Clone, Debug)]
struct Axis {
    /// The distinct knots `b₀ < … < b_n` bounding the pieces, enclosed.
    breaks: Vec<Interval>,
    /// `smooth[k]`: is the surface `C¹` across `b_{k+1}` by its knot
    /// vector (multiplicity below the degree)?
    smooth: Vec<bool>,
    /// How far a box may reach beyond `b₀` and beyond `b_n`.
    reach: [f64; 2],
    /// Whether the surface is closed in this parameter: its borders at
    /// `b₀` and `b_n` are one curve (a periodic surface's seam).
    closed: bool,
}

/// A piece a parameter interval meets: its index, the interval's part in
/// the piece's local parameter, and `1/(b − a)`.
type Part = (usize, Interval, Interval);

impl Axis {
    /// The axis of the pieces bounded by `breaks` (sorted, distinct),
    /// `C¹` across `breaks[k + 1]` where `smooth[k]`.
    fn new(breaks: &[Q], smooth: Vec<bool>) -> Axis {
        let enclosed: Vec<Interval> = breaks.iter().map(Interval::enclose).collect();
        let n = enclosed.len() - 1;
        let quarter = |a: &Interval, b: &Interval| (b.lo - a.hi) / 4.0;
        Axis {
            reach: [
                quarter(&enclosed[0], &enclosed[1]),
                quarter(&enclosed[n - 1], &enclosed[n]),
            ],
            breaks: enclosed,
            smooth,
            closed: false,
        }
    }

    /// `x` moved by whole periods into the domain where the axis is
    /// closed (a foot found past the seam is the same point of the
    /// surface on the other side); `x` itself otherwise.
    fn wrap(&self, x: f64) -> f64 {
        let [lo, hi] = [0, self.breaks.len() - 1].map(|k| self.breaks[k].mid());
        let period = hi - lo;
        if !self.closed || (lo..=hi).contains(&x) || !period.is_finite() || period <= 0.0 {
            return x;
        }
        lo + (x - lo).rem_euclid(period)
    }

    /// Does the enclosure `x` lie within the domain widened on each side by
    /// [`BORDER_SLACK`] of its width?
    fn holds(&self, x: Interval) -> bool {
        let [lo, hi] = self.domain();
        let slack = BORDER_SLACK * (hi - lo);
        x.lo >= lo - slack && x.hi <= hi + slack
    }

    /// The piece whose span holds `x` (the first or last for `x` beyond
    /// the border).
    fn index(&self, x: f64) -> usize {
        let above = self.breaks[1..self.breaks.len() - 1]
            .iter()
            .take_while(|b| b.mid() <= x)
            .count();
        above.min(self.breaks.len() - 2)
    }

    /// `[b₀, b_n]`.
    fn domain(&self) -> [f64; 2] {
        [self.breaks[0].lo, self.breaks[self.breaks.len() - 1].hi]
    }

    /// The pieces `x` meets, with its part in each; `None` when `x` is not
    /// finite, reaches beyond the border's reach, or crosses a knot where
    /// the surface is only `C⁰`.
    fn parts(&self, x: Interval) -> Option<Vec<Part>> {
        let [first, last] = self.domain();
        let inside = x.lo >= first - self.reach[0] && x.hi <= last + self.reach[1];
        if !(x.lo.is_finite() && x.hi.is_finite() && inside) {
            return None;
        }
        let n = self.breaks.len() - 1;
        let mut out: Vec<Part> = Vec::new();
        for i in 0..n {
            let (a, b) = (self.breaks[i], self.breaks[i + 1]);
            let lo = if i == 0 { x.lo } else { x.lo.max(a.lo) };
            let hi = if i == n - 1 { x.hi } else { x.hi.min(b.hi) };
            if lo > hi {
                continue;
            }
            if let Some(&(prev, ..)) = out.last()
                && prev + 1 == i
                && !self.smooth[prev]
                && x.lo < a.lo
                && x.hi > a.hi
            {
                return None;
            }
            let span = b.sub(&a);
            let local = Interval { lo, hi }.sub(&a).div(&span)?;
            out.push((i, local, Interval::point(1.0).div(&span)?));
        }
        (!out.is_empty()).then_some(out)
    }
}

/// A foot box proved for a box of points, with what the measures take
/// from it.
#[derive(Clone, Debug)]
struct FootBox {
    /// The surface's jet over `uv`.
    jet: PatchJet,
    /// `s` and `N`.
    distance: Distance,
    /// `∇u`, `∇v`: the rows of `∂σ/∂P`.
    gradient: [IVec; 2],
}

/// A box of points, by the bits of its ends, and its foot box if proved.
type Remembered = (Vec<[u64; 2]>, Option<Rc<FootBox>>);

/// A B-spline surface held for certified measures: its pieces on the
/// grid of knot spans, enclosed at first use. Shared by the fields of
/// every edge of its face (and across threads).
#[derive(Debug)]
pub struct SplineSurface<'a> {
    axes: [Axis; 2],
    /// The pieces by `(i, j)`: `grid[i·n_v + j]`.
    grid: Vec<&'a RectPatch<Q>>,
    /// Their enclosures, made at first use (`None`: a weight not proved
    /// positive).
    enclosed: Vec<OnceLock<Option<IPatch>>>,
    /// Points of every piece with their parameters: Newton's starts when
    /// no nearby foot is known.
    seeds: OnceLock<Vec<([f64; 3], [f64; 2])>>,
}

/// A B-spline surface seen from the points around it (see the module
/// documentation): the surface, and what one edge's measures remember.
#[derive(Clone, Debug)]
pub struct SplineField<'a> {
    surface: &'a SplineSurface<'a>,
    /// The last foot found.
    guess: Cell<Option<[f64; 2]>>,
    /// The last boxes of points asked for, by their bits, and their feet.
    recent: RefCell<Vec<Remembered>>,
    /// The jet at the last parameter point asked for (Newton's last step
    /// is Krawczyk's first centre).
    last_point: RefCell<Option<([u64; 2], PatchJet)>>,
    /// The last pieces of an edge whose feet were found, by their curve
    /// and the bits of their ends, with the feet.
    recent_feet: RefCell<Vec<RememberedFeet>>,
    /// The parts of the edge whose feet near a fitted curve are proved
    /// ([`SplineField::part`]), by their curve and the bits of their ends:
    /// the angle proves them, the curvature takes them again.
    parts: RefCell<HashMap<PartKey, Rc<PartFeet>>>,
}

/// A part of an edge: its curve (by address: the edge's curves outlive its
/// fields' use) and the bits of its parameter interval's ends.
type PartKey = (usize, [u64; 2]);

/// A piece of an edge, by its curve and the bits of its ends, and its
/// feet if found.
type RememberedFeet = (PartKey, Option<Vec<[f64; 2]>>);

/// The key of part `t` of `curve`.
fn part_key(curve: &ICurve, t: Interval) -> PartKey {
    (
        std::ptr::from_ref(curve) as usize,
        [t.lo.to_bits(), t.hi.to_bits()],
    )
}

/// Are two rows of homogeneous control points one border curve: `b_j =
/// λ a_j` for one `λ ≠ 0` (proportional rows give the same rational
/// curve, point by point)?
fn same_border(a: &[HPoint<Q>], b: &[HPoint<Q>]) -> bool {
    let (Some(pa), Some(pb)) = (a.first(), b.first()) else {
        return false;
    };
    if a.len() != b.len() || pa.weight().is_zero() {
        return false;
    }
    let lambda = pb.weight() / pa.weight();
    !lambda.is_zero()
        && a.iter().zip(b).all(|(x, y)| {
            x.coords
                .iter()
                .zip(&y.coords)
                .all(|(p, q)| &(p * &lambda) == q)
        })
}

/// Is a B-spline with knot vector `knots` `C¹` across its knot `b`
/// (multiplicity below the degree)?
fn knot_smooth(b: &Q, knots: &Knots) -> bool {
    knots.knots().iter().filter(|k| *k == b).count() < knots.degree()
}

/// The index of `x` among the sorted `breaks`.
fn index_of(breaks: &[Q], x: &Q) -> Result<usize, Error> {
    breaks
        .binary_search(x)
        .map_err(|_| Error::Shape("a Bézier piece's span is not between knots".into()))
}

impl<'a> SplineSurface<'a> {
    /// The surface `s` whose Bézier pieces with their spans are
    /// `pieces` (as [`crate::nurbs::Nurbs::pieces`] gives them).
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless the pieces are rectangular patches tiling a
    /// grid of spans, one per cell.
    pub fn new(
        s: &NurbsSurface<Q>,
        pieces: &'a [SpannedPatch],
    ) -> Result<SplineSurface<'a>, Error> {
        let (ku, kv) = s.knots();
        SplineSurface::from_pieces(pieces, |b| knot_smooth(b, ku), |b| knot_smooth(b, kv))
    }

    /// The surface tiled by `pieces` (rectangular patches, one per cell of
    /// the grid of their spans), `C¹` across an inner break `b` of the
    /// spans in `u` where `smooth_u(b)` (likewise in `v`): the caller
    /// vouches for it, as a knot vector does for a B-spline. A break where
    /// the surface is not `C¹` must answer `false` (boxes do not cross it).
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless the pieces tile a grid of spans, one per
    /// cell.
    pub fn from_pieces(
        pieces: &'a [SpannedPatch],
        smooth_u: impl Fn(&Q) -> bool,
        smooth_v: impl Fn(&Q) -> bool,
    ) -> Result<SplineSurface<'a>, Error> {
        let spans = |pick: fn(&SpannedPatch) -> Option<&[Q; 2]>| -> Result<Vec<Q>, Error> {
            let mut b: Vec<Q> = Vec::new();
            for p in pieces {
                let span =
                    pick(p).ok_or_else(|| Error::Shape("a curve piece in a surface".into()))?;
                b.extend(span.iter().cloned());
            }
            b.sort();
            b.dedup();
            if b.len() < 2 {
                return Err(Error::Shape("a B-spline surface with no pieces".into()));
            }
            Ok(b)
        };
        let (bu, bv) = (spans(|p| Some(&p.u))?, spans(|p| p.v.as_ref())?);
        let (nu, nv) = (bu.len() - 1, bv.len() - 1);
        let mut grid: Vec<Option<&'a RectPatch<Q>>> = vec![None; nu * nv];
        for p in pieces {
            let (Patch::Rect(r), Some(v)) = (&p.patch, &p.v) else {
                return Err(Error::Shape(
                    "a B-spline surface piece that is not a rectangular patch".into(),
                ));
            };
            let cell = index_of(&bu, &p.u[0])? * nv + index_of(&bv, &v[0])?;
            if grid[cell].replace(r).is_some() {
                return Err(Error::Shape("two Bézier pieces on one knot span".into()));
            }
        }
        let grid = grid
            .into_iter()
            .collect::<Option<Vec<_>>>()
            .ok_or_else(|| Error::Shape("a knot span with no Bézier piece".into()))?;
        let inner = |b: &[Q], smooth: &dyn Fn(&Q) -> bool| -> Vec<bool> {
            b[1..b.len() - 1].iter().map(smooth).collect()
        };
        let mut axes = [
            Axis::new(&bu, inner(&bu, &smooth_u)),
            Axis::new(&bv, inner(&bv, &smooth_v)),
        ];
        axes[0].closed = (0..nv).all(|j| {
            let (first, last) = (grid[j].ctrl(), grid[(nu - 1) * nv + j].ctrl());
            same_border(&first[0], &last[last.len() - 1])
        });
        axes[1].closed = (0..nu).all(|i| {
            let column = |p: &RectPatch<Q>, last: bool| -> Vec<HPoint<Q>> {
                p.ctrl()
                    .iter()
                    .map(|row| row[if last { row.len() - 1 } else { 0 }].clone())
                    .collect()
            };
            same_border(
                &column(grid[i * nv], false),
                &column(grid[i * nv + nv - 1], true),
            )
        });
        Ok(SplineSurface {
            axes,
            enclosed: grid.iter().map(|_| OnceLock::new()).collect(),
            grid,
            seeds: OnceLock::new(),
        })
    }

    fn columns(&self) -> usize {
        self.axes[1].breaks.len() - 1
    }

    /// Piece `k`, enclosed.
    fn piece(&self, k: usize) -> Result<&IPatch, Error> {
        self.enclosed[k]
            .get_or_init(|| IPatch::with_enclosed_derivatives(self.grid[k]).ok())
            .as_ref()
            .ok_or_else(|| {
                Error::Domain("a B-spline piece whose weights are not proved positive".into())
            })
    }

    /// Points of every piece on a `SEEDS × SEEDS` grid of its local
    /// parameters, in `f64`, with their surface parameters.
    fn seeds(&self) -> &[([f64; 3], [f64; 2])] {
        self.seeds.get_or_init(|| {
            let nv = self.columns();
            let mut out = Vec::new();
            for k in 0..self.grid.len() {
                let Ok(patch) = self.piece(k) else { continue };
                let (a, b) = (
                    &self.axes[0].breaks[k / nv],
                    &self.axes[0].breaks[k / nv + 1],
                );
                let (c, d) = (
                    &self.axes[1].breaks[k % nv],
                    &self.axes[1].breaks[k % nv + 1],
                );
                for i in 0..SEEDS {
                    for j in 0..SEEDS {
                        let (s, t) = (i as f64 / (SEEDS - 1) as f64, j as f64 / (SEEDS - 1) as f64);
                        if let Some(x) = patch.approximate_point(s, t) {
                            let at = [
                                a.mid() + s * (b.mid() - a.mid()),
                                c.mid() + t * (d.mid() - c.mid()),
                            ];
                            out.push((x, at));
                        }
                    }
                }
            }
            out
        })
    }

    /// The parameters of the seed nearest to `c`, with its squared
    /// distance.
    fn nearest_seed(&self, c: &[Interval]) -> Option<([f64; 2], f64)> {
        self.seeds()
            .iter()
            .map(|s| (s.1, squared_distance(&s.0, c)))
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// The piece (its index in the grid) whose span holds the parameters
    /// `g`, the border pieces holding what lies beyond the border.
    /// Does the box `b` meet at most [`FOOT_PIECES`] pieces along each
    /// axis, within the border's reach?
    fn few_pieces(&self, b: [Interval; 2]) -> bool {
        (0..2).all(|k| {
            self.axes[k]
                .parts(b[k])
                .is_some_and(|p| p.len() <= FOOT_PIECES)
        })
    }

    fn cell(&self, g: [f64; 2]) -> usize {
        let [i, j] = [0, 1].map(|k| self.axes[k].index(g[k]));
        i * self.columns() + j
    }
}

impl<'a> SplineField<'a> {
    /// The field of `surface`, remembering nothing yet.
    pub fn new(surface: &'a SplineSurface<'a>) -> SplineField<'a> {
        SplineField {
            surface,
            guess: Cell::new(None),
            recent: RefCell::new(Vec::new()),
            last_point: RefCell::new(None),
            recent_feet: RefCell::new(Vec::new()),
            parts: RefCell::new(HashMap::new()),
        }
    }

    /// The piece whose span holds `(u, v)` (the border pieces beyond the
    /// border), `(u, v)` in its local parameters, and the derivatives'
    /// scales `1/(b − a)` along each axis (spans in `f64`).
    fn local(&self, u: f64, v: f64) -> ((usize, f64, f64), (f64, f64)) {
        let cell = self.surface.cell([u, v]);
        let ij = [cell / self.surface.columns(), cell % self.surface.columns()];
        let [(lu, su), (lv, sv)] = [0, 1].map(|k| {
            let (a, b) = (
                self.surface.axes[k].breaks[ij[k]].mid(),
                self.surface.axes[k].breaks[ij[k] + 1].mid(),
            );
            ((if k == 0 { u } else { v } - a) / (b - a), 1.0 / (b - a))
        });
        ((cell, lu, lv), (su, sv))
    }

    /// The foot box of the points `p`, remembered among the last few.
    fn foot(&self, p: &[Interval]) -> Option<Rc<FootBox>> {
        let key: Vec<[u64; 2]> = p.iter().map(|x| [x.lo.to_bits(), x.hi.to_bits()]).collect();
        if let Some((_, f)) = self.recent.borrow().iter().find(|(k, _)| *k == key) {
            return f.clone();
        }
        let f = self.prove_foot(p).map(Rc::new);
        let mut recent = self.recent.borrow_mut();
        if recent.len() == RECENT {
            recent.remove(0);
        }
        recent.push((key, f.clone()));
        f
    }

    /// Newton for a guess, then ε-inflation (Rump) until Krawczyk's
    /// operator maps a box `g ± r` into its interior: `r` starts at
    /// [`START_SPREAD`] times the foot's linearized spread over `p` and
    /// doubles, while the box meets at most [`FOOT_PIECES`] pieces per
    /// axis (a wider box is not worth its jets: the caller splits `p`).
    fn prove_foot(&self, p: &[Interval]) -> Option<FootBox> {
        let c: IVec = p.iter().map(|x| Interval::point(x.mid())).collect();
        let g = self.foot_f64(&c)?;
        let wrapped = [0, 1].map(|k| self.surface.axes[k].wrap(g[k]));
        let g = if wrapped == g {
            g
        } else {
            let g = newton(self, &c, wrapped)?;
            self.guess.set(Some(g));
            g
        };
        let at = self.approximate_jet(g[0], g[1]).ok()?;
        let domain = self.domain();
        let mut r = spread(&at, p)?;
        for (k, rk) in r.iter_mut().enumerate() {
            *rk = START_SPREAD * *rk + 1e-13 * (domain[k][1] - domain[k][0]);
        }
        for _ in 0..INFLATIONS {
            let b = [0, 1].map(|k| Interval {
                lo: g[k] - r[k],
                hi: g[k] + r[k],
            });
            if !self.surface.few_pieces(b) {
                return None;
            }
            if let Ok(Some(k)) = krawczyk(self, b, p)
                && b[0].interior_contains(&k[0])
                && b[1].interior_contains(&k[1])
            {
                if !(0..2).all(|a| self.surface.axes[a].holds(k[a])) {
                    return None;
                }
                return self.finish(p, b);
            }
            r = r.map(|x| 2.0 * x);
        }
        None
    }

    /// An `f64` foot of the point `c` by Newton: from the last foot found,
    /// else from the nearest seed.
    fn foot_f64(&self, c: &[Interval]) -> Option<[f64; 2]> {
        let near = |g: [f64; 2]| -> Option<([f64; 2], f64)> {
            let x = self.approximate_jet(g[0], g[1]).ok()?.x;
            let x: Vec<f64> = x.iter().map(Interval::mid).collect();
            Some((g, squared_distance(&[x[0], x[1], x[2]], c)))
        };
        let seed = self.surface.nearest_seed(c)?;
        let from_guess = self.guess.get().and_then(|g| near(newton(self, c, g)?));
        // A foot farther than the nearest seed is another stationary point.
        let g = match from_guess {
            Some((g, d)) if d <= seed.1 => g,
            other => {
                let from_seed = newton(self, c, seed.0).and_then(near);
                match (other, from_seed) {
                    (Some(a), Some(b)) => {
                        if a.1 <= b.1 {
                            a.0
                        } else {
                            b.0
                        }
                    }
                    (a, b) => a.or(b)?.0,
                }
            }
        };
        self.guess.set(Some(g));
        Some(g)
    }

    /// A proved upper bound of the distance from every point of `curve`
    /// over `t` to the surface within its domain: `|C − S∘p|` bounded by
    /// [`distance_bound`] for a cubic `p` through the `f64` feet at four
    /// equally spaced parameters, its control points clamped into the
    /// piece most of them lie in (see [`super::compose`]), on each part of
    /// `t` between the [`SplineField::cuts`]. `None` when a foot is not
    /// found or the bound is not finite (the caller splits `t`).
    pub fn gap_over(&self, curve: &ICurve, t: Interval) -> Option<f64> {
        let cuts = self.cuts(curve, t)?;
        let mut most = 0.0_f64;
        for part in parts(t, &cuts) {
            let fit = self.fit_over(curve, part)?;
            self.charge_compositions(fit.cell, 1)?;
            let s = compose(
                &self.surface.piece(fit.cell).ok()?.homogeneous(),
                &fit.u,
                &fit.v,
            );
            most = most.max(distance_bound(&curve_over(curve, part), &s)?);
        }
        Some(most)
    }

    /// Where in `t` the curve's feet cross a knot line of the surface:
    /// empty when the feet at four equally spaced
    /// parameters lie in one piece, else the first crossing (found in
    /// `f64`: any cut is valid, a good one only keeps each part's feet in
    /// one piece) at least [`SLIVER`] of `t`'s width from its ends. A
    /// crossing nearer an end is that of an edge that starts or ends on
    /// the knot line, its foot there a rounding error across it: cutting
    /// there made a part of `10⁻¹²` of the piece that cost as much as the
    /// rest (a tenth of the parts of `tail_section_asm.stp`'s B-spline
    /// edges until 2026-11-29). Not cutting is as sound: the fitted curve
    /// is clamped into one piece and the feet's boxes take the jets of
    /// every piece they meet. `None` when a foot is not found.
    pub fn cuts(&self, curve: &ICurve, t: Interval) -> Option<Vec<f64>> {
        let feet = self.feet_along(curve, t)?;
        let cells: Vec<usize> = feet.iter().map(|g| self.surface.cell(*g)).collect();
        let margin = SLIVER * (t.hi - t.lo);
        for j in (0..FIT_DEGREE).filter(|&j| cells[j] != cells[j + 1]) {
            let x = self.crossing(curve, node(t, j), node(t, j + 1), [feet[j], feet[j + 1]])?;
            if x > t.lo + margin && x < t.hi - margin {
                return Some(vec![x]);
            }
        }
        Some(Vec::new())
    }

    /// The face's normal along the curve over `t`, a part of an edge
    /// between [`SplineField::cuts`]: the normal of `S` along the fitted
    /// cubic `p` ([`super::normal_path::patch_normal`]), and how far, in
    /// radians, it may turn from there to the normal at the foot points.
    ///
    /// The feet lie in each of the part's proved boxes around `p`
    /// (`SplineField::part`): within `e_u`, `e_v` of `p` in the
    /// parameters. Along the segment from `p(t)` to the foot, inside a
    /// box `Q`, the unit normal turns at most
    /// `sup_Q |N_u| e_u + sup_Q |N_v| e_v` radians (the length of its path
    /// on the unit sphere); the slack is the least of these bounds over
    /// the ways the feet are proved (each one holds). `None` when not
    /// proved.
    pub fn normal_over(&self, curve: &ICurve, t: Interval) -> Option<NormalPath> {
        let part = self.part(curve, t)?;
        let slack = part.nears.iter().filter_map(|n| n.slack).reduce(f64::min)?;
        let [s, su, sv] = &part.composed;
        let normal = patch_normal(s, su, sv);
        Some(NormalPath { normal, slack })
    }

    /// The face's normal curvature across the edge over `t`, a part of an
    /// edge between [`SplineField::cuts`], relative to the surface's own
    /// normal `S_u × S_v`: at the foot points of every `C(t)`, and at the
    /// foot of `C(t_m)`, `t_m` the part's `f64` midpoint. The feet are
    /// those of [`SplineField::normal_over`], in the boxes of
    /// `SplineField::part`, within `e_u`, `e_v` of the fitted `p`: over
    /// the part, the curvature is enclosed on the boxes' jets in the
    /// direction `n × C'(t)`; at `t_m`, on the jet of the box
    /// `p(s_m) ± e` (`s_m` the midpoint's parameter on the part); where the
    /// feet are proved two ways, the intersection of the two enclosures
    /// (each holds). Like the normal path, it needs no foot proved by
    /// Krawczyk's operator at a single box of points, so it holds where
    /// the feet fall a rounding error past the face's border. `None` when
    /// not proved.
    pub fn curvature_over(&self, curve: &ICurve, t: Interval) -> Option<CurvaturePath> {
        let part = self.part(curve, t)?;
        part.nears
            .iter()
            .filter_map(|near| self.curvature_near(&part.fit, near, curve, t))
            .reduce(CurvaturePath::meet)
    }

    /// [`SplineField::curvature_over`] on the boxes of one way of proving
    /// the feet.
    fn curvature_near(
        &self,
        fit: &Fit,
        near: &Near,
        curve: &ICurve,
        t: Interval,
    ) -> Option<CurvaturePath> {
        let one = Interval::point(1.0);
        let along = curve.jet(t).ok()?.dx;
        let mut over: Option<Interval> = None;
        for (jet, ..) in &near.jets {
            let k = curvature_across(jet, &one, &along)?;
            over = Some(over.map_or(k, |o| o.hull(&k)));
        }
        let tm = Interval::point(t.mid());
        let sm = tm
            .sub(&Interval::point(t.lo))
            .div(&Interval::point(t.hi).sub(&Interval::point(t.lo)))?;
        let centre = [0, 1].map(|k| {
            let (a, span) = self.span(fit.cell, k);
            let local = bernstein_at([&fit.u, &fit.v][k], sm);
            let g = local.mul(&span).add(&a);
            Interval {
                lo: g.lo - near.radius[k],
                hi: g.hi + near.radius[k],
            }
        });
        let jet = self.jet(centre[0], centre[1]).ok()?;
        let mid = curvature_across(&jet, &one, &curve.jet(tm).ok()?.dx)?;
        Some(CurvaturePath { over: over?, mid })
    }

    /// The fitted cubic `p` over part `t` of `curve`
    /// ([`SplineField::fit_over`]), `H`, `H_u`, `H_v` of its piece composed
    /// with it (scaled forms, charged as three compositions) and the boxes
    /// proved to hold the feet near it ([`SplineField::nears`]); remembered
    /// when proved, so that the curvature takes again what the angle
    /// proved. `None` when not proved.
    fn part(&self, curve: &ICurve, t: Interval) -> Option<Rc<PartFeet>> {
        let key = part_key(curve, t);
        if let Some(p) = self.parts.borrow().get(&key) {
            return Some(p.clone());
        }
        let fit = self.fit_over(curve, t)?;
        self.charge_compositions(fit.cell, 3)?;
        let nets = self.surface.piece(fit.cell).ok()?.first_order_nets();
        let composed = nets.map(|n| compose(&n, &fit.u, &fit.v));
        let nears = self.nears(&fit, curve, t, &composed);
        if nears.is_empty() {
            return None;
        }
        let part = Rc::new(PartFeet {
            fit,
            composed,
            nears,
        });
        self.parts.borrow_mut().insert(key, part.clone());
        Some(part)
    }

    /// The boxes that hold the feet of the curve's points over part `t`
    /// near its fitted curve `p`, from `H`, `H_u`, `H_v` composed with `p`
    /// (`h`), proved one of two ways: from the gap bound `g` of
    /// `|C − S∘p|` ([`SplineField::near_by_gap`]: within `2g/σ` of `p`),
    /// or by the tube of the foot-point system's residual along `p`
    /// ([`SplineField::tube_near`]). The way whose radii are estimated the
    /// smaller is tried first (`2g/σ̃`, `σ̃` the `f64` stretch at the middle
    /// of `p`'s hull, against the tube's first radii `2|Y₀| R` times `5/8`,
    /// the `1.25 |Y| R` it proves where `Y J ≈ I`): where the edge is
    /// really off the face the tube is the tighter, where it lies on the
    /// face up to rounding the gap's radius often is. The other is tried
    /// only where the first is not proved or its normal turn is not: each
    /// costs jets that the measure's work cap then lacks (until
    /// 2026-11-28 the tube was tried first everywhere, the gap after it:
    /// 33 edges of `tail_section_asm.stp` decided before the tube were
    /// undecided after it).
    fn nears(&self, fit: &Fit, curve: &ICurve, t: Interval, h: &[Vec<Scaled>; 3]) -> Vec<Near> {
        let gap = distance_bound(&curve_over(curve, t), &h[0]);
        let centre = self.place(fit.cell, [&fit.u, &fit.v], [0.0; 2]);
        let stretch = self
            .approximate_jet(centre[0].mid(), centre[1].mid())
            .ok()
            .and_then(|j| least_stretch(&j));
        let start = self.tube_start(fit, curve, t, h);
        let estimates = [
            gap.zip(stretch).map(|(g, s)| 2.0 * g / s),
            start.map(|s| 0.625 * s.first[0].max(s.first[1])),
        ];
        let by_gap = || self.near_by_gap(fit, gap?, stretch?);
        let tube = || self.tube_near(fit, curve, t, start?);
        let tube_first = match estimates {
            [Some(g), Some(e)] => e < g,
            [None, Some(_)] => true,
            _ => false,
        };
        let ways: [&dyn Fn() -> Option<Near>; 2] = if tube_first {
            [&tube, &by_gap]
        } else {
            [&by_gap, &tube]
        };
        let mut out = Vec::new();
        for way in ways {
            if let Some(near) = way() {
                let turns = near.slack.is_some();
                out.push(near);
                if turns {
                    break;
                }
            }
        }
        out
    }

    /// What the tube of [`SplineField::nears`] starts from
    /// ([`super::tube`]): the residual's bounds `R` turned into the
    /// surface's parameters (`÷ (b − a)`) and the first radii
    /// `e = 2|Y₀| R` (`Y₀` the inverse of the `f64` Jacobian at the middle
    /// of `p`'s hull). `None` where the residual is not bounded.
    fn tube_start(
        &self,
        fit: &Fit,
        curve: &ICurve,
        t: Interval,
        h: &[Vec<Scaled>; 3],
    ) -> Option<TubeStart> {
        let local = tube::residual(&curve_over(curve, t), &h[0], &h[1], &h[2])?;
        let r = [0, 1].map(|k| {
            let (_, span) = self.span(fit.cell, k);
            Interval::point(local[k]).div(&span).map(|x| x.hi)
        });
        let residual = [r[0]?, r[1]?];
        let centre = self.place(fit.cell, [&fit.u, &fit.v], [0.0; 2]);
        let at = self
            .approximate_jet(centre[0].mid(), centre[1].mid())
            .ok()?;
        let (_, j) = system(&at, &curve.jet(Interval::point(t.mid())).ok()?.x);
        let y = mid_inverse(&j)?;
        let first =
            [0, 1].map(|i| 2.0 * (y[i][0].abs() * residual[0] + y[i][1].abs() * residual[1]));
        Some(TubeStart { residual, first })
    }

    /// The tube of [`SplineField::nears`] from `start`: boxes around the
    /// hulls of `p`'s control points, halving `p` where a box does not
    /// prove the tube ([`SplineField::tube_boxes`]). `None` when not
    /// proved.
    fn tube_near(&self, fit: &Fit, curve: &ICurve, t: Interval, start: TubeStart) -> Option<Near> {
        let domain = self.domain();
        let tube = Tube {
            curve,
            t,
            residual: start.residual,
            floor: [0, 1].map(|k| 1e-15 * (domain[k][1] - domain[k][0])),
            place: &|c, radius| self.place(fit.cell, c, radius),
        };
        let mut jets = Vec::new();
        let whole = Interval { lo: 0.0, hi: 1.0 };
        self.tube_boxes(
            &tube,
            [&fit.u, &fit.v],
            whole,
            start.first,
            HALVINGS,
            &mut jets,
        )?;
        let radius = jets.iter().fold([0.0_f64; 2], |m, (_, e, _)| {
            [m[0].max(e[0]), m[1].max(e[1])]
        });
        Some(Near::new(jets, radius))
    }

    /// The first way of [`SplineField::nears`]: boxes that hold
    /// the feet of the curve's points over a part whose fitted curve is `p`
    /// and gap bound `gap` (the bound of `|C − S∘p|`): the nearest point
    /// `S(q)` to `C(t)` within a box `Q` around `p` is no farther than
    /// `S(p(t))`, so `|S(q) − S(p)| ≤ 2g` and `|q − p| ≤ ε = 2g/σ` (mean
    /// value theorem) where every `(S_u S_v)` over `Q` stretches by at least
    /// `σ`; within `Q`'s margin, `q` is a foot point. Boxes around the hulls of `p`'s
    /// control points widened by a margin of `8 g / σ̃` (`σ̃` the stretch
    /// `estimate`, in `f64` at the centre: the margin holds `ε = 2g/σ` while
    /// `σ ≥ σ̃/4`), halving `p` where a box does not prove that much
    /// ([`SplineField::boxes_near`]).
    fn near_by_gap(&self, fit: &Fit, gap: f64, estimate: f64) -> Option<Near> {
        let domain = self.domain();
        let margin = [0, 1].map(|k| 8.0 * gap / estimate + 1e-12 * (domain[k][1] - domain[k][0]));
        let need = Interval::point(2.0)
            .mul(&Interval::point(gap))
            .div(&Interval::point(margin[0].min(margin[1])))?
            .hi;
        let mut jets = Vec::new();
        let stretch = self.boxes_near(
            [&fit.u, &fit.v],
            &|c| self.place(fit.cell, c, margin),
            need,
            HALVINGS,
            &mut jets,
        )?;
        let eps = Interval::point(2.0)
            .mul(&Interval::point(gap))
            .div(&Interval::point(stretch))?
            .hi;
        let jets = jets.into_iter().map(|j| (j, [eps; 2], eps)).collect();
        eps.is_finite().then(|| Near::new(jets, [eps; 2]))
    }

    /// The box of parameters of piece `cell` around the hull of the
    /// Bernstein coefficients `c` (local parameters) widened by `margin`.
    fn place(&self, cell: usize, c: [&[f64]; 2], margin: [f64; 2]) -> [Interval; 2] {
        [0, 1].map(|k| {
            let (lo, hi) = c[k]
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
                    (a.min(*x), b.max(*x))
                });
            // f64 de Casteljau halves are within a few ulps of the
            // true control points.
            let local = Interval {
                lo: lo - 1e-14,
                hi: hi + 1e-14,
            };
            let (a, s) = self.span(cell, k);
            let g = local.mul(&s).add(&a);
            Interval {
                lo: g.lo - margin[k],
                hi: g.hi + margin[k],
            }
        })
    }

    /// The surface's jets over a box `place(p, e)` around the curve `p`
    /// with Bernstein coefficients `c` (the part of the fitted curve over
    /// the sub-range `range` of the part's parameter) proving the tube of
    /// radii `e` for the edge's points over that sub-range
    /// ([`tube::holds`]), or over the boxes of its halves (de Casteljau)
    /// down to `depth` halvings, pushed on `jets` with their radii; `None`
    /// when not proved. Each box starts from the radii `guess`, then takes
    /// the radii [`tube::radius`] asks for over it (a quarter more, and the
    /// floor), enlarging the box while they exceed its own, up to
    /// [`TUBE_TRIES`] times.
    fn tube_boxes(
        &self,
        tube: &Tube<'_>,
        c: [&[f64]; 2],
        range: Interval,
        guess: [f64; 2],
        depth: usize,
        jets: &mut Vec<(PatchJet, [f64; 2], f64)>,
    ) -> Option<()> {
        let points = tube.points(range)?;
        let mut e = [0, 1].map(|k| guess[k].max(tube.floor[k]));
        for _ in 0..TUBE_TRIES {
            let q = (tube.place)(c, e);
            let Ok(jet) = self.jet(q[0], q[1]) else { break };
            let Some(need) = tube::radius(&jet, &points, tube.residual) else {
                break;
            };
            let want = [0, 1].map(|k| 1.25 * need[k] + tube.floor[k]);
            if want[0] <= e[0] && want[1] <= e[1] {
                if tube::holds(&jet, &points, tube.residual, want) {
                    let length = Interval::point(want[0])
                        .sqr()
                        .add(&Interval::point(want[1]).sqr())
                        .sqrt()?
                        .hi;
                    jets.push((jet, want, length));
                    return Some(());
                }
                break;
            }
            e = [0, 1].map(|k| 2.0 * want[k].max(e[k]));
        }
        if depth == 0 {
            return None;
        }
        let [(u0, v0), (u1, v1)] = halves(c)?;
        let m = range.mid();
        let (left, right) = (
            Interval {
                lo: range.lo,
                hi: m,
            },
            Interval {
                lo: m,
                hi: range.hi,
            },
        );
        self.tube_boxes(tube, [&u0, &v0], left, guess, depth - 1, jets)?;
        self.tube_boxes(tube, [&u1, &v1], right, guess, depth - 1, jets)
    }

    /// The surface's jets over the box `place(p)` of the curve `p` with
    /// Bernstein coefficients `c`, or over the boxes of its halves (de
    /// Casteljau) down to `depth` halvings, pushed on `jets`, each
    /// proving a least stretch of at least `need`; returns the least
    /// stretch proved, `None` when not proved.
    fn boxes_near(
        &self,
        c: [&[f64]; 2],
        place: &dyn Fn([&[f64]; 2]) -> [Interval; 2],
        need: f64,
        depth: usize,
        jets: &mut Vec<PatchJet>,
    ) -> Option<f64> {
        let q = place(c);
        if let Ok(jet) = self.jet(q[0], q[1])
            && let Some(stretch) = least_stretch(&jet).filter(|s| *s >= need)
        {
            jets.push(jet);
            return Some(stretch);
        }
        if depth == 0 {
            return None;
        }
        let [(u0, v0), (u1, v1)] = halves(c)?;
        let a = self.boxes_near([&u0, &v0], place, need, depth - 1, jets)?;
        let b = self.boxes_near([&u1, &v1], place, need, depth - 1, jets)?;
        Some(a.min(b))
    }

    /// The start `a` of piece `cell`'s span along axis `k` and its length
    /// `b − a`, enclosed.
    fn span(&self, cell: usize, k: usize) -> (Interval, Interval) {
        let i = if k == 0 {
            cell / self.surface.columns()
        } else {
            cell % self.surface.columns()
        };
        let (a, b) = (
            self.surface.axes[k].breaks[i],
            self.surface.axes[k].breaks[i + 1],
        );
        (a, b.sub(&a))
    }

    /// Charge `count` compositions of piece `cell` with a fitted curve.
    fn charge_compositions(&self, cell: usize, count: u64) -> Option<()> {
        let net = self.surface.grid[cell].ctrl();
        let points = (net.len() * net[0].len()) as u64;
        limits::charge(
            "a B-spline face's composition",
            COMPOSE_WORK * points * count,
        )
        .ok()
    }

    /// The cubic `p` through the curve's feet over `t`, in the local
    /// parameters of the piece most of them lie in, its control points
    /// clamped into `[0, 1]²`.
    fn fit_over(&self, curve: &ICurve, t: Interval) -> Option<Fit> {
        let feet = self.feet_along(curve, t)?;
        let cell = self.common_cell(&feet);
        let ij = [cell / self.surface.columns(), cell % self.surface.columns()];
        let fit = |k: usize| -> Option<Vec<f64>> {
            let (a, b) = (
                self.surface.axes[k].breaks[ij[k]].mid(),
                self.surface.axes[k].breaks[ij[k] + 1].mid(),
            );
            let local: Vec<f64> = feet.iter().map(|g| (g[k] - a) / (b - a)).collect();
            Some(
                interpolate(&local)?
                    .iter()
                    .map(|x| x.clamp(0.0, 1.0))
                    .collect(),
            )
        };
        Some(Fit {
            cell,
            u: fit(0)?,
            v: fit(1)?,
        })
    }

    /// The `f64` feet of the curve at the [`FIT_DEGREE`]` + 1` equally
    /// spaced parameters of `t`.
    /// The last few are remembered (the gap and the angle ask for the
    /// same pieces).
    fn feet_along(&self, curve: &ICurve, t: Interval) -> Option<Vec<[f64; 2]>> {
        let key = part_key(curve, t);
        if let Some((_, f)) = self.recent_feet.borrow().iter().find(|(k, _)| *k == key) {
            return f.clone();
        }
        let feet: Option<Vec<[f64; 2]>> = (0..=FIT_DEGREE)
            .map(|j| self.foot_f64(&curve.approximate_point(node(t, j))?))
            .collect();
        let mut recent = self.recent_feet.borrow_mut();
        if recent.len() == RECENT {
            recent.remove(0);
        }
        recent.push((key, feet.clone()));
        feet
    }

    /// The piece most of `feet` lie in (ties: the first).
    fn common_cell(&self, feet: &[[f64; 2]]) -> usize {
        let cells: Vec<usize> = feet.iter().map(|g| self.surface.cell(*g)).collect();
        let count = |c: &usize| cells.iter().filter(|x| *x == c).count();
        cells
            .iter()
            .copied()
            .rev()
            .max_by_key(count)
            .expect("feet at four parameters")
    }

    /// Where between `a` and `b` the feet (`ends`, in different pieces)
    /// cross the first knot line between their pieces: regula falsi
    /// (Illinois) on the foot's parameter minus the knot, in `f64`.
    fn crossing(&self, curve: &ICurve, a: f64, b: f64, ends: [[f64; 2]; 2]) -> Option<f64> {
        let [i, j] = ends.map(|g| [0, 1].map(|k| self.surface.axes[k].index(g[k])));
        let k = usize::from(i[0] == j[0]);
        let knot = self.surface.axes[k].breaks[i[k].max(j[k])].mid();
        let (mut x, mut fx) = ([a, b], [ends[0][k] - knot, ends[1][k] - knot]);
        let mut side = 2;
        for _ in 0..30 {
            if fx[0] == fx[1] {
                break;
            }
            let m = x[1] - fx[1] * (x[1] - x[0]) / (fx[1] - fx[0]);
            if !(m > x[0].min(x[1]) && m < x[0].max(x[1])) {
                break;
            }
            let fm = self.foot_f64(&curve.approximate_point(m)?)?[k] - knot;
            let keep = usize::from(fm.signum() == fx[1].signum());
            x[keep] = m;
            fx[keep] = fm;
            if side == keep {
                fx[1 - keep] /= 2.0;
            }
            side = keep;
            if fm == 0.0 || (x[1] - x[0]).abs() < 1e-15 * (1.0 + x[0].abs()) {
                break;
            }
        }
        let m = if fx[0].abs() < fx[1].abs() {
            x[0]
        } else {
            x[1]
        };
        m.is_finite().then_some(m)
    }

    /// Shrink a proved box by two Krawczyk steps, then take `s`, `N` and
    /// `∂σ/∂P` over it.
    fn finish(&self, p: &[Interval], mut b: [Interval; 2]) -> Option<FootBox> {
        let shrinks = if p.iter().all(|x| x.width() == 0.0) {
            0
        } else {
            2
        };
        for _ in 0..shrinks {
            if let Ok(Some(k)) = krawczyk(self, b, p) {
                match (b[0].intersect(&k[0]), b[1].intersect(&k[1])) {
                    (Some(u), Some(v)) => b = [u, v],
                    _ => break,
                }
            }
        }
        let jet = self.jet(b[0], b[1]).ok()?;
        let gradient = foot_gradient(&jet, p)?;
        let normal = unit_normal(&jet)?;
        let signed = dot(&sub(p, &jet.x), &normal);
        Some(FootBox {
            jet,
            distance: Distance { signed, normal },
            gradient,
        })
    }
}

/// How far, to first order, the foot moves in each parameter as the point
/// ranges over the box `p`, from the `f64` jet `at` near the foot of its
/// centre: `Σ_j |A_kj| h_j`, with `h` the box's half-widths and
/// `A = (MᵀM)⁻¹Mᵀ` the least-squares inverse of `M = (S_u S_v)`; `None`
/// where `MᵀM` is singular. An estimate only: Krawczyk's operator proves
/// the box it starts.
fn spread(at: &PatchJet, p: &[Interval]) -> Option<[f64; 2]> {
    let m = [&at.xu, &at.xv].map(|d| d.iter().map(Interval::mid).collect::<Vec<f64>>());
    let g = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    let (a, b, d) = (g(&m[0], &m[0]), g(&m[0], &m[1]), g(&m[1], &m[1]));
    let det = a * d - b * b;
    if !(det.is_finite() && det > 0.0) {
        return None;
    }
    let inverse = [[d / det, -b / det], [-b / det, a / det]];
    Some([0, 1].map(|k| {
        (0..3)
            .map(|j| {
                let row = inverse[k][0] * m[0][j] + inverse[k][1] * m[1][j];
                row.abs() * p[j].width() / 2.0
            })
            .sum()
    }))
}

/// A cubic `p` in the local parameters of piece `cell`, by its Bernstein
/// coefficients.
#[derive(Clone, Debug)]
struct Fit {
    cell: usize,
    u: Vec<f64>,
    v: Vec<f64>,
}

/// A face's normal along a part of an edge ([`SplineField::normal_over`]).
#[derive(Clone, Debug)]
pub struct NormalPath {
    /// A positive multiple of the normal along a curve of the face near
    /// the edge, a polynomial in the part's parameter (scaled form).
    pub normal: ScaledVec,
    /// At most the angle, in radians, between that normal and the normal
    /// at the foot point of each point of the edge.
    pub slack: f64,
}

/// A face's normal curvature across an edge over a part of it
/// ([`SplineField::curvature_over`]), relative to the surface's own
/// normal.
#[derive(Clone, Copy, Debug)]
pub struct CurvaturePath {
    /// At the foot point of every point of the part.
    pub over: Interval,
    /// At the foot point of the part's midpoint.
    pub mid: Interval,
}

impl CurvaturePath {
    /// The intersection of two enclosures of one curvature path (each
    /// holds, so their common part does); the hull where rounding left
    /// them apart.
    fn meet(self, o: CurvaturePath) -> CurvaturePath {
        let both = |a: Interval, b: Interval| a.intersect(&b).unwrap_or_else(|| a.hull(&b));
        CurvaturePath {
            over: both(self.over, o.over),
            mid: both(self.mid, o.mid),
        }
    }
}

/// A part of an edge with its fitted curve, what is composed with it and
/// the boxes that hold its feet ([`SplineField::part`]).
#[derive(Debug)]
struct PartFeet {
    fit: Fit,
    /// `H`, `H_u`, `H_v` composed with the fitted curve (scaled forms).
    composed: [Vec<Scaled>; 3],
    /// The ways the feet are proved near the fitted curve (one or two).
    nears: Vec<Near>,
}

/// The boxes that hold the feet near a fitted curve, proved one way
/// ([`SplineField::nears`]).
#[derive(Debug)]
struct Near {
    /// The surface's jets over boxes covering the tube around the fitted
    /// curve, each with the radii `e_u`, `e_v` it proves and a bound of
    /// the length `|e|` of the step: every foot of the edge's points over
    /// its sub-range is within them of the fitted curve, in the surface's
    /// parameters.
    jets: Vec<(PatchJet, [f64; 2], f64)>,
    /// The greatest radii over the boxes.
    radius: [f64; 2],
    /// At most the angle the unit normal turns from the fitted curve to
    /// the feet: the greatest [`turn`] over the boxes; `None` where a
    /// normal is not proved.
    slack: Option<f64>,
}

impl Near {
    /// The boxes `jets` with their radii, the greatest `radius`, and the
    /// slack they prove.
    fn new(jets: Vec<(PatchJet, [f64; 2], f64)>, radius: [f64; 2]) -> Near {
        let slack = jets
            .iter()
            .try_fold(0.0_f64, |most, (jet, radius, length)| {
                Some(most.max(turn(jet, *radius, *length)?))
            });
        Near {
            jets,
            radius,
            slack,
        }
    }
}

/// Where the tube of [`SplineField::tube_near`] starts.
#[derive(Clone, Copy, Debug)]
struct TubeStart {
    /// The residual's bounds, in the surface's parameters.
    residual: [f64; 2],
    /// The first radii tried.
    first: [f64; 2],
}

/// How many boxes [`SplineField::tube_boxes`] tries for one part of a
/// fitted curve before halving it.
const TUBE_TRIES: usize = 3;

/// The box of parameters around a curve `p` (its Bernstein coefficients)
/// widened by radii.
type Place<'a> = dyn Fn([&[f64]; 2], [f64; 2]) -> [Interval; 2] + 'a;

/// What [`SplineField::tube_boxes`] proves the tube for.
struct Tube<'a> {
    /// The edge's curve.
    curve: &'a ICurve,
    /// The part of its parameter the fitted curve runs over.
    t: Interval,
    /// The residual's bounds, in the surface's parameters.
    residual: [f64; 2],
    /// The least radii tried: 10⁻¹⁵ of the domain's width.
    floor: [f64; 2],
    /// The box around a part of the fitted curve, widened by radii.
    place: &'a Place<'a>,
}

impl Tube<'_> {
    /// The edge's points over the sub-range `range` of the part's
    /// parameter `s` (`t = t.lo + s (t.hi − t.lo)`), enclosed.
    fn points(&self, range: Interval) -> Option<IVec> {
        let width = Interval::point(self.t.hi).sub(&Interval::point(self.t.lo));
        let sub = Interval::point(self.t.lo).add(&width.mul(&range));
        let sub = Interval {
            lo: sub.lo.max(self.t.lo),
            hi: sub.hi.min(self.t.hi),
        };
        Some(self.curve.jet(sub).ok()?.x)
    }
}

/// The value at `s` of the polynomial with Bernstein coefficients `c`
/// (de Casteljau, outward rounded).
fn bernstein_at(c: &[f64], s: Interval) -> Interval {
    let r = Interval::point(1.0).sub(&s);
    let mut b: Vec<Interval> = c.iter().map(|x| Interval::point(*x)).collect();
    for k in (1..b.len()).rev() {
        for i in 0..k {
            b[i] = b[i].mul(&r).add(&b[i + 1].mul(&s));
        }
    }
    b[0]
}

/// How many times [`SplineField::tube_boxes`] may halve a fitted curve.
const HALVINGS: usize = 3;

/// The Bernstein coefficients `(u, v)` of the two halves of the curve
/// `p = (u, v)` with coefficients `c` ([`RationalCurve::subdivide`] at
/// `1/2`, in `f64`); `None` when a coefficient is not finite.
fn halves(c: [&[f64]; 2]) -> Option<[(Vec<f64>, Vec<f64>); 2]> {
    let points = c[0].iter().zip(c[1]).map(|(u, v)| vec![*u, *v]).collect();
    let (left, right) = RationalCurve::polynomial(points).ok()?.subdivide(&0.5);
    let coords = |half: &RationalCurve<f64>, k: usize| -> Vec<f64> {
        half.ctrl()
            .iter()
            .map(|h| h.coords[k] / h.coords[2])
            .collect()
    };
    Some([&left, &right].map(|h| (coords(h, 0), coords(h, 1))))
}

/// The parts of `t` between the sorted `cuts`.
pub fn parts(t: Interval, cuts: &[f64]) -> Vec<Interval> {
    let mut ends = vec![t.lo];
    ends.extend(cuts.iter().copied().filter(|x| *x > t.lo && *x < t.hi));
    ends.push(t.hi);
    ends.windows(2)
        .map(|w| Interval { lo: w[0], hi: w[1] })
        .collect()
}

/// The curve over `t` as scaled forms of its homogeneous coordinates.
pub fn curve_over(curve: &ICurve, t: Interval) -> Vec<Scaled> {
    curve.piece_over(t).iter().map(|x| scaled_form(x)).collect()
}

/// `|x − c|²` in `f64`, `c` by its midpoints.
fn squared_distance(x: &[f64; 3], c: &[Interval]) -> f64 {
    x.iter().zip(c).map(|(a, b)| (a - b.mid()).powi(2)).sum()
}

/// `x · k` for each derivative's scale.
fn scaled(j: PatchJet, su: &Interval, sv: &Interval) -> PatchJet {
    PatchJet {
        x: j.x,
        xu: scale(&j.xu, su),
        xv: scale(&j.xv, sv),
        xuu: scale(&j.xuu, &su.sqr()),
        xuv: scale(&j.xuv, &su.mul(sv)),
        xvv: scale(&j.xvv, &sv.sqr()),
    }
}

/// The hull of two jets, part by part.
fn hull(a: &PatchJet, b: &PatchJet) -> PatchJet {
    let h = |x: &IVec, y: &IVec| -> IVec { x.iter().zip(y).map(|(p, q)| p.hull(q)).collect() };
    PatchJet {
        x: h(&a.x, &b.x),
        xu: h(&a.xu, &b.xu),
        xv: h(&a.xv, &b.xv),
        xuu: h(&a.xuu, &b.xuu),
        xuv: h(&a.xuv, &b.xuv),
        xvv: h(&a.xvv, &b.xvv),
    }
}

impl Jets for SplineField<'_> {
    /// The hull of the jets of the pieces `u × v` meets (see the module
    /// documentation).
    fn jet(&self, u: Interval, v: Interval) -> Result<PatchJet, Error> {
        let point =
            (u.width() == 0.0 && v.width() == 0.0).then(|| [u.lo.to_bits(), v.lo.to_bits()]);
        if let (Some(key), Some((at, jet))) = (point, &*self.last_point.borrow())
            && key == *at
        {
            return Ok(jet.clone());
        }
        let jet = self.jet_uncached(u, v)?;
        if let Some(key) = point {
            *self.last_point.borrow_mut() = Some((key, jet.clone()));
        }
        Ok(jet)
    }

    /// The jet of the piece whose span holds `(u, v)` (the border pieces
    /// beyond the border), in its local parameters, derivatives scaled.
    fn approximate_jet(&self, u: f64, v: f64) -> Result<PatchJet, Error> {
        let ((cell, lu, lv), (su, sv)) = self.local(u, v);
        let jet = self.surface.piece(cell)?.approximate_jet(lu, lv)?;
        Ok(scaled(jet, &Interval::point(su), &Interval::point(sv)))
    }

    /// [`Jets::approximate_jet`] in plain numbers, scaled in `f64`.
    fn jet_f64(&self, u: f64, v: f64) -> Result<Jet64, Error> {
        let ((cell, lu, lv), (su, sv)) = self.local(u, v);
        let [x, xu, xv, xuu, xuv, xvv] = self.surface.piece(cell)?.jet_f64(lu, lv)?;
        let times = |a: [f64; 3], k: f64| a.map(|c| c * k);
        Ok([
            x,
            times(xu, su),
            times(xv, sv),
            times(xuu, su * su),
            times(xuv, su * sv),
            times(xvv, sv * sv),
        ])
    }

    fn domain(&self) -> [[f64; 2]; 2] {
        self.surface.axes.each_ref().map(Axis::domain)
    }

    /// The domain and the border pieces' reach beyond it.
    fn reach(&self) -> [[f64; 2]; 2] {
        self.surface.axes.each_ref().map(|a| {
            let [lo, hi] = a.domain();
            [lo - a.reach[0], hi + a.reach[1]]
        })
    }
}

impl SplineField<'_> {
    /// [`Jets::jet`] without the cache, charged [`JET_WORK`] per piece
    /// control point.
    fn jet_uncached(&self, u: Interval, v: Interval) -> Result<PatchJet, Error> {
        let refused = || {
            Error::Domain("a box beyond a B-spline surface's border, or across a C⁰ knot".into())
        };
        let pu = self.surface.axes[0].parts(u).ok_or_else(refused)?;
        let pv = self.surface.axes[1].parts(v).ok_or_else(refused)?;
        let nv = self.surface.columns();
        let mut out: Option<PatchJet> = None;
        for (i, lu, su) in &pu {
            for (j, lv, sv) in &pv {
                let patch = self.surface.grid[i * nv + j];
                let points = patch.ctrl().len() * patch.ctrl()[0].len();
                limits::charge("a B-spline face's jet", JET_WORK * points as u64)?;
                let jet = scaled(self.surface.piece(i * nv + j)?.jet(*lu, *lv)?, su, sv);
                out = Some(match out {
                    Some(o) => hull(&o, &jet),
                    None => jet,
                });
            }
        }
        out.ok_or_else(refused)
    }
}

/// `∂σ/∂P = −F_σ⁻¹ F_P` over the jet `s` for the points `p`: its rows
/// `∇u`, `∇v`; `None` where `F_σ` is not proved regular.
fn foot_gradient(s: &PatchJet, p: &[Interval]) -> Option<[IVec; 2]> {
    let (_, j) = system(s, p);
    let mut gradient = [IVec::new(), IVec::new()];
    for axis in 0..3 {
        let d = derivative(&j, [s.xu[axis].neg(), s.xv[axis].neg()])?;
        gradient[0].push(d[0]);
        gradient[1].push(d[1]);
    }
    Some(gradient)
}

/// `N_u`, `N_v`: the rates of the unit normal `N` (enclosed over the jet
/// `s` by `normal`) along the parameters, `(n_u − N (N·n_u))/|n|` with
/// `n = S_u × S_v`, `n_u = S_uu × S_v + S_u × S_uv` (likewise in `v`).
fn normal_rates(s: &PatchJet, normal: &[Interval]) -> Option<[IVec; 2]> {
    let length = norm2(&cross(&s.xu, &s.xv)).sqrt()?;
    let rate = |dn: IVec| -> Option<IVec> {
        let along = dot(normal, &dn);
        sub(&dn, &scale(normal, &along))
            .iter()
            .map(|x| x.div(&length))
            .collect()
    };
    Some([
        rate(add(&cross(&s.xuu, &s.xv), &cross(&s.xu, &s.xuv)))?,
        rate(add(&cross(&s.xuv, &s.xv), &cross(&s.xu, &s.xvv)))?,
    ])
}

/// `J = N_u ⊗ ∇u + N_v ⊗ ∇v` from the jet `s`, the unit normal over it and
/// `∂σ/∂P`.
fn jacobian(s: &PatchJet, normal: &[Interval], [du, dv]: &[IVec; 2]) -> Option<IMat3> {
    let [nu, nv] = normal_rates(s, normal)?;
    Some(std::array::from_fn(|a| {
        std::array::from_fn(|b| nu[a].mul(&du[b]).add(&nv[a].mul(&dv[b])))
    }))
}

/// The unit normal `n/|n|`, `n = S_u × S_v`, over the jet `s`; `None`
/// where `|n|`'s enclosure reaches 0.
fn unit_normal(s: &PatchJet) -> Option<IVec> {
    let n = cross(&s.xu, &s.xv);
    let length = norm2(&n).sqrt()?;
    if length.lo <= 0.0 {
        return None;
    }
    n.iter().map(|x| x.div(&length)).collect()
}

/// A lower bound of the least singular value of every matrix `(S_u S_v)`
/// over the jet `s`: `√λ`, `λ` the greatest of three lower bounds of the
/// least eigenvalue of the Gram matrix `[[a, b], [b, d]]`: its closed form
/// `(a + d)/2 − √(((a − d)/2)² + b²)` (tight for a box of nearly equal
/// columns), Gershgorin's `min(a, d) − |b|` (tight where `a` and `d`
/// differ, which the closed form's cancellation loses over a wide box),
/// and `det/trace = |S_u × S_v|²/(a + d)` (the product of the two
/// eigenvalues over their sum is at most the lesser; Lagrange's identity
/// `ad − b² = |S_u × S_v|²` keeps it free of the cancellation);
/// `None` unless positive.
fn least_stretch(s: &PatchJet) -> Option<f64> {
    let (a, b, d) = (dot(&s.xu, &s.xu), dot(&s.xu, &s.xv), dot(&s.xv, &s.xv));
    let half = Interval::point(0.5);
    let spread = a.sub(&d).mul(&half).sqr().add(&b.sqr()).sqrt()?;
    let closed = a.add(&d).mul(&half).sub(&spread).lo;
    let gershgorin = Interval::point(a.lo.min(d.lo))
        .sub(&Interval::point(b.mag()))
        .lo;
    let quotient = norm2(&cross(&s.xu, &s.xv))
        .div(&a.add(&d))
        .map_or(f64::NEG_INFINITY, |q| q.lo);
    let least = closed.max(gershgorin).max(quotient);
    (least > 0.0).then(|| Interval::point(least).sqrt().map(|x| x.lo))?
}

/// At most the angle, in radians, the unit normal turns along a segment
/// of parameters within the box of `jet` whose steps are at most `radius`
/// in each parameter and `length` long: the least of
/// `sup |N_u| e_u + sup |N_v| e_v` and `sup √(|N_u|² + |N_v|²) · length`
/// (Cauchy–Schwarz); `None` where the normal is not proved.
fn turn(jet: &PatchJet, radius: [f64; 2], length: f64) -> Option<f64> {
    let [nu, nv] = normal_rates(jet, &unit_normal(jet)?)?;
    let (a, b) = (norm2(&nu), norm2(&nv));
    let e = radius.map(Interval::point);
    let apart = a.sqrt()?.mul(&e[0]).add(&b.sqrt()?.mul(&e[1])).hi;
    let along = a.add(&b).sqrt()?.mul(&Interval::point(length)).hi;
    let t = apart.min(along);
    t.is_finite().then_some(t)
}

impl DistanceField for SplineField<'_> {
    fn distance(&self, p: &[Interval]) -> Option<Distance> {
        Some(self.foot(p)?.distance.clone())
    }

    /// `J = N_u ⊗ ∇u + N_v ⊗ ∇v` at the feet of `p`.
    fn normal_jacobian(&self, p: &[Interval]) -> Option<IMat3> {
        let f = self.foot(p)?;
        jacobian(&f.jet, &f.distance.normal, &f.gradient)
    }

    /// `J` at the foot points themselves (`P = S(σ)`, the same foot box):
    /// `∂σ/∂P` from the foot-point system with `S − P` enclosed by
    /// `S(X) − S(X)`.
    fn normal_jacobian_at_foot(
        &self,
        p: &[Interval],
        _: &[Interval],
        _: &Interval,
    ) -> Option<IMat3> {
        let f = self.foot(p)?;
        let gradient = foot_gradient(&f.jet, &f.jet.x)?;
        jacobian(&f.jet, &f.distance.normal, &gradient)
    }
}

#[cfg(test)]
mod tests;
