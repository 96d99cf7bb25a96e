//! Certified measures and verdicts of one B-rep edge between its two faces
//! (a shared edge), or between a face and itself (a seam), where both faces
//! are elementary surfaces with a closed form: exact ([`Implicit`]), or
//! enclosed ([`ISurface`]: a cone whose slope is known within a bound).
//! See `docs/audit.md`, "STEP B-rep input".
//!
//! **Exact paths first** (where the faces are exact). With `F` a face's implicit equation of degree `d`
//! and a curve piece of degree `n` with positive weights, `w(t)^d F(C(t))`
//! is a polynomial of degree `≤ d·n` in `t`; it vanishes identically iff it
//! vanishes at `d·n + 1` distinct parameters. So `F(C(t_j)) = 0` at
//! `t_j = j/(d·n)`, exactly, proves the gap to that face is 0. Likewise the
//! cross product of the two faces' [`Implicit::gradient`]s (degrees `g₁`,
//! `g₂` in the point) is a polynomial of degree `≤ (g₁ + g₂)·n`: zero at
//! `(g₁ + g₂)·n + 1` parameters proves the tangent planes coincide along the
//! whole edge, and the sign of the oriented normals' dot product at one
//! point says whether the faces continue each other (angle exactly 0) or
//! fold back (exactly π).
//!
//! **Enclosures otherwise.** Along each Bézier piece of the edge, over a
//! piece `T` of its parameter with midpoint `t_m`:
//! - the gap to a face is `|s(C(t))|`, `s` the closed-form signed distance
//!   ([`ISurface`]); by the mean value theorem
//!   `s(C(T)) ⊆ s(C(t_m)) + (n̂(C(T))·C'(T))(T − t_m)`, tight like `|T|²`
//!   where the edge runs along the face;
//! - the gap between the faces, between the two foot points
//!   `C − s₁n̂₁` and `C − s₂n̂₂`, is enclosed from the two gaps by the
//!   triangle inequality (`face_gap`);
//! - the angle between the oriented foot normals `±n̂₁`, `±n̂₂` is
//!   [`polar_angle`] of `(|N₁ × N₂|, N₁·N₂)`: where both faces have a
//!   normal path (plane, cylinder, sphere, cone, B-spline;
//!   [`normal_path`]) from the rational hull of the two paths over `T`
//!   and their value at `t_m`, each less its slack;
//!   else over `T` by mean-value forms and at `t_m`;
//!
//! and [`maximize`](super::certify::maximize::maximize) refines to the target width. Each edge has its own work
//! cap ([`EDGE_WORK`]); a measure not proved within it is *unproved* and
//! its verdict *undecided*.

use super::certify::angle::polar_angle;
use super::certify::bezier::CurveJet;
use super::certify::closed_form::{Distance, ISurface};
use super::certify::field::{apply, normal_curvature, DistanceField};
use super::certify::gap::abs_lower;
use super::certify::ivec::{add, cross, dot, norm2, scale, IVec};
use super::certify::maximize::{maximize_over, Bound, Enclosure, Target};
use super::certify::normal_path;
use super::certify::spline::{curve_over, parts, NormalPath, SplineField};
use super::certify::{ICurve, Verdict};
use crate::algebra::{Interval, RealAlgebraic, Scalar};
use crate::analytic::{cross as exact_cross, dot as exact_dot, Implicit};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::limits::{self, Limits};
use num_traits::Zero;
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

type Curve = RationalCurve<RealAlgebraic>;

/// The work cap of one edge (in [`limits`] units): about 50 000 pieces of
/// [`maximize`](super::certify::maximize::maximize). Running out leaves the enclosures proved so far (wider
/// than the target). The work an edge used is then charged to the
/// command's budget, and the cap never exceeds what is left of that budget.
pub const EDGE_WORK: u64 = 100_000_000;

/// The work cap of one measure of an edge (shared by its pieces): a
/// quarter of [`EDGE_WORK`], so that each of the five measures gets its
/// turn.
const MEASURE_WORK: u64 = EDGE_WORK / 4;

/// The work cap of an angle or curvature measure on a B-spline face,
/// whose normal paths and foot boxes cost a few compositions or jets per
/// piece of the edge, where a closed form takes one evaluation: a tenth of
/// [`MEASURE_WORK`], so that an audit of a model with a thousand such
/// edges ends in seconds (tail_section_asm.stp: 19.7 s, 537 of its 1 423
/// edges undecided; with a quarter, 50 s and 452 before the cones' paths). Measures not proved
/// within it are unproved, their verdicts undecided (docs/audit.md).
const SPLINE_MEASURE_WORK: u64 = MEASURE_WORK / 10;

/// The finest length f64 interval arithmetic resolves on an edge whose
/// coordinates are at most `M` in magnitude: `2⁻⁴⁴ M` (a few hundred
/// ulps of `M`, what the jets and closed forms lose to outward rounding).
/// Gaps are not refined below it: a declared tolerance finer than it
/// (some files declare 10⁻¹² mm) leaves a gap of that size undecided
/// rather than spending the edge's work cap on rounding noise.
fn length_resolution(curves: &[ICurve]) -> Result<f64, Error> {
    let mut m: f64 = 0.0;
    for c in curves {
        for x in c.jet(Interval { lo: 0.0, hi: 1.0 })?.x {
            m = m.max(x.mag());
        }
    }
    Ok(m * 2f64.powi(-44))
}

/// Work units charged per exact point test (calibrated with the other
/// commands, `cli/benches/cost_model.rs`: at 50 000 the `audit` of
/// red_cube_blue_cylinder.step, 12 of whose 14 edges are proved exact, was
/// charged 4.4 times its time).
const EXACT_POINT_WORK: u64 = 10_000;

/// A face's surface, as far as it is known.
#[derive(Clone, Debug)]
pub enum JointSurface<'a> {
    /// Exactly: the exact tests (a gap exactly 0, tangent planes exactly
    /// the same) run before the enclosures.
    Exact(&'a Implicit<RealAlgebraic>),
    /// By enclosures of its data only (a cone whose slope is known within
    /// a bound): every measure is an enclosure.
    Enclosed(ISurface),
    /// A B-spline surface, through certified foot points: every measure is
    /// an enclosure.
    Spline(Box<SplineField<'a>>),
}

impl JointSurface<'_> {
    /// The exact closed form, if known.
    fn exact(&self) -> Option<&Implicit<RealAlgebraic>> {
        match self {
            JointSurface::Exact(s) => Some(s),
            JointSurface::Enclosed(_) | JointSurface::Spline(_) => None,
        }
    }

    /// The surface as a distance field near the point `near` (a torus
    /// that meets itself: its part nearer `near`).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] for a torus whose major radius is negative.
    fn field(&self, near: &[Interval]) -> Result<Field<'_>, Error> {
        let closed = |s: Option<ISurface>| match s {
            Some(s) => Ok(Field::Closed(s.nearer_part(near))),
            None => Err(Error::Domain(
                "a torus whose major radius is negative".into(),
            )),
        };
        match self {
            JointSurface::Exact(s) => closed(ISurface::new(*s)),
            JointSurface::Enclosed(s) => closed(Some(s.clone())),
            JointSurface::Spline(s) => Ok(Field::Spline(s)),
        }
    }
}

/// A face's distance field for one edge: a closed form made for it, or the
/// face's B-spline field.
enum Field<'s> {
    Closed(ISurface),
    Spline(&'s SplineField<'s>),
}

impl Field<'_> {
    /// The face's normal along part `t` of the curve as a polynomial: a
    /// closed form's at the foot points themselves (no slack), a B-spline's
    /// by composition ([`SplineField::normal_over`]); `gap` bounds the
    /// distance from the curve to the face (the cone's slack needs it; the
    /// part's own bound is taken where smaller).
    fn normal_path(&self, curve: &ICurve, t: Interval, gap: f64) -> Option<NormalPath> {
        match self {
            Field::Closed(s) => {
                // The distance over this part, tight like |t|³ (the gap
                // measure's own bound stops at a third of the tolerance).
                let (cm, co, dt) = curve_jets(curve, t).ok()?;
                let near = side(s, &cm, &co, dt).map_or(gap, |d| d.signed.mag().min(gap));
                let (normal, slack) = s.normal_along(&curve_over(curve, t), &co.x, near)?;
                Some(NormalPath { normal, slack })
            }
            Field::Spline(s) => s.normal_over(curve, t),
        }
    }

    fn get(&self) -> &dyn DistanceField {
        match self {
            Field::Closed(s) => s,
            Field::Spline(s) => *s,
        }
    }
}

/// One face along the edge: its closed form and orientation.
#[derive(Clone, Debug)]
pub struct JointFace<'a> {
    /// The face's surface.
    pub surface: JointSurface<'a>,
    /// Does the face's normal agree with the surface's normal (the way of
    /// [`Implicit::gradient`] and [`ISurface`]'s `n̂`)?
    pub same_sense: bool,
}

/// One measure of an edge: the maximum along it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Measure {
    /// Proved to be exactly 0 everywhere along the edge.
    Exact,
    /// Enclosed: the maximum is in `[value.lo, value.hi]`, attained in
    /// `value.at` of the edge's Bézier piece `piece` (parameter `[0, 1]`).
    Enclosed {
        /// The enclosure.
        value: Enclosure,
        /// The edge piece where the maximum is attained.
        piece: usize,
    },
    /// Not proved within the work cap, or a foot point is singular.
    Unproved,
}

/// The measures and verdicts of one edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointMeasures {
    /// The largest distance from the edge curve to each face's surface.
    pub gap: [Measure; 2],
    /// The largest distance between the two faces' foot points.
    pub face_gap: Measure,
    /// The largest angle between the faces' oriented normals, radians.
    pub angle: Measure,
    /// G0: the gaps against the length tolerance.
    pub g0: Verdict,
    /// G1: the angle against the angular tolerance.
    pub g1: Verdict,
    /// The largest difference of the faces' normal curvatures across the
    /// edge, per length unit; `None` where G0 or G1 does not hold (G2 is
    /// then moot, and not measured).
    pub curvature: Option<Measure>,
    /// G2: the curvature difference against the curvature tolerance, where
    /// measured.
    pub g2: Option<Verdict>,
}

/// Is `F` zero along every piece (exactly, at `d·n + 1` parameters)?
fn lies_on(pieces: &[Curve], f: &Implicit<RealAlgebraic>) -> Result<bool, Error> {
    for c in pieces {
        for t in sample_params(f.degree() * c.degree())? {
            if !f.value(&c.eval(&t)?).is_zero() {
                return Ok(false);
            }
        }
    }
    Ok(true)
}

/// `j/m`, `j = 0…m`, charged.
fn sample_params(m: usize) -> Result<Vec<RealAlgebraic>, Error> {
    let m = m.max(1);
    limits::charge(
        "an exact test along an edge",
        EXACT_POINT_WORK * (m as u64 + 1),
    )?;
    Ok((0..=m)
        .map(|j| RealAlgebraic::from_i64(j as i64) / &RealAlgebraic::from_i64(m as i64))
        .collect())
}

/// The oriented gradient of a face at `p`.
fn oriented(
    (surface, same_sense): (&Implicit<RealAlgebraic>, bool),
    p: &[RealAlgebraic],
) -> Vec<RealAlgebraic> {
    let g = surface.gradient(p);
    if same_sense {
        g
    } else {
        g.into_iter().map(|x| -x).collect()
    }
}

/// Are the faces' tangent planes the same all along the edge (exactly)?
/// `Some(0)` when the oriented normals agree, `Some(π)` at a fold, `None`
/// when not proved parallel.
fn exact_angle(
    pieces: &[Curve],
    faces: [(&Implicit<RealAlgebraic>, bool); 2],
) -> Result<Option<bool>, Error> {
    let g = faces[0].0.gradient_degree() + faces[1].0.gradient_degree();
    let mut sign = None;
    for c in pieces {
        for t in sample_params(g * c.degree())? {
            let p = c.eval(&t)?;
            let (n1, n2) = (oriented(faces[0], &p), oriented(faces[1], &p));
            if !exact_cross(&n1, &n2).iter().all(Zero::is_zero) {
                return Ok(None);
            }
            let d = exact_dot(&n1, &n2);
            if d.is_zero() {
                return Ok(None);
            }
            sign.get_or_insert(d.signum() > 0);
        }
    }
    Ok(sign)
}

/// What one piece `T` of the edge proves.
struct Around {
    /// The curve at `t_m` and over `T`.
    cm: CurveJet,
    co: CurveJet,
    /// `T − t_m`.
    dt: Interval,
    /// Distances at `t_m`.
    mid: [Distance; 2],
    /// Normals over `T`.
    over: [Distance; 2],
    /// `s` over `T`: the mean-value form, intersected with the Taylor form
    /// of order 2 where the face's normal Jacobian is enclosed.
    signed: [Interval; 2],
}

/// What one face proves over `T`: [`Around`]'s part for it.
struct Side {
    mid: Distance,
    over: Distance,
    signed: Interval,
}

/// The curve at `t_m` and over `T`, and `T − t_m`.
fn curve_jets(curve: &ICurve, t: Interval) -> Result<(CurveJet, CurveJet, Interval), Error> {
    let m = Interval::point(t.mid());
    Ok((curve.jet(m)?, curve.jet(t)?, t.sub(&m)))
}

/// One face's distances at `t_m` and over `T`, `s` over `T` (the
/// mean-value form, intersected with the Taylor form of order 2 where the
/// face's normal Jacobian is enclosed).
fn side(field: &dyn DistanceField, cm: &CurveJet, co: &CurveJet, dt: Interval) -> Option<Side> {
    // Over `T` first: where it is not proved, the point at `t_m` is not
    // needed.
    let over = field.distance(&co.x)?;
    let mid = field.distance(&cm.x)?;
    let mean_value = mid.signed.add(&dot(&over.normal, &co.dx).mul(&dt));
    let signed = match field.normal_jacobian(&co.x) {
        // g(t) = s(C(t)): g' = n̂·C', g'' = C'ᵀ J C' + n̂·C''.
        Some(j) => {
            let second = dot(&co.dx, &apply(&j, &co.dx)).add(&dot(&over.normal, &co.ddx));
            let taylor = mid
                .signed
                .add(&dot(&mid.normal, &cm.dx).mul(&dt))
                .add(&second.mul(&dt.sqr()).mul(&Interval::point(0.5)));
            mean_value.intersect(&taylor).unwrap_or(mean_value)
        }
        None => mean_value,
    };
    Some(Side { mid, over, signed })
}

fn around(curve: &ICurve, fields: Fields<'_>, t: Interval) -> Result<Option<Around>, Error> {
    let (cm, co, dt) = curve_jets(curve, t)?;
    let (Some(s0), Some(s1)) = (side(fields[0], &cm, &co, dt), side(fields[1], &cm, &co, dt))
    else {
        return Ok(None);
    };
    Ok(Some(Around {
        signed: [s0.signed, s1.signed],
        mid: [s0.mid, s1.mid],
        over: [s0.over, s1.over],
        cm,
        co,
        dt,
    }))
}

/// The two faces' distance fields.
type Fields<'a> = [&'a dyn DistanceField; 2];

fn length(v: &[Interval]) -> Interval {
    norm2(v).sqrt().expect("a sum of squares is never negative")
}

/// The angle between the oriented normals `N_i = ±n̂_i`: over `T` by
/// interval extension, and by the mean-value forms of `V = N₁ × N₂` and
/// `c = N₁·N₂` with `N_i' = ±J_i C'` (tight like `|T|²` where the faces are
/// nearly tangent), whichever is narrower; at `t_m` for the lower bound.
fn angle_bound(a: &Around, fields: Fields<'_>, signs: [Interval; 2]) -> Bound {
    let oriented = |d: &[Distance; 2]| [0, 1].map(|k| scale(&d[k].normal, &signs[k]));
    let [m1, m2] = oriented(&a.mid);
    let [o1, o2] = oriented(&a.over);
    let naive = (length(&cross(&o1, &o2)), dot(&o1, &o2));
    let (sin, cos) = match normal_rates(a, fields, signs) {
        Some([d1, d2]) => {
            let dv = add(&cross(&d1, &o2), &cross(&o1, &d2));
            let v = add(&cross(&m1, &m2), &scale(&dv, &a.dt));
            let dc = dot(&d1, &o2).add(&dot(&o1, &d2));
            let c = dot(&m1, &m2).add(&dc.mul(&a.dt));
            (narrower(naive.0, length(&v)), narrower(naive.1, c))
        }
        None => naive,
    };
    Bound {
        upper: polar_angle(&sin, &cos).hi,
        lower: polar_angle(&length(&cross(&m1, &m2)), &dot(&m1, &m2)).lo,
    }
}

/// `N_i' = ±J_i(C(T)) C'(T)` over `T`, when both Jacobians are enclosed.
fn normal_rates(a: &Around, fields: Fields<'_>, signs: [Interval; 2]) -> Option<[IVec; 2]> {
    let rate = |k: usize| {
        let j = fields[k].normal_jacobian(&a.co.x)?;
        Some(scale(&apply(&j, &a.co.dx), &signs[k]))
    };
    Some([rate(0)?, rate(1)?])
}

/// The intersection of two enclosures of one quantity (the first if they
/// do not meet, which rounding alone cannot cause).
fn narrower(a: Interval, b: Interval) -> Interval {
    a.intersect(&b).unwrap_or(a)
}

/// `|κ₁ − κ₂|` across the edge: each face's normal curvature relative to
/// its oriented normal, `κ_i = ∓ wᵢᵀ J_i wᵢ / |wᵢ|²` at the foot point
/// `F_i = C − s_i n̂_i` in the direction `w_i = n̂_i × C'` (across the
/// edge, in the face's tangent plane; [`normal_curvature`]); over `T` for
/// the upper bound, at `t_m` for the lower.
fn curvature_bound(a: &Around, fields: Fields<'_>, signs: [Interval; 2]) -> Option<Bound> {
    let diff = |c: &CurveJet, d: &[Distance; 2], s: [&Interval; 2]| {
        let k = |i: usize| Some(kappa(fields[i], c, &d[i], s[i])?.mul(&signs[i]));
        Some(k(0)?.sub(&k(1)?))
    };
    let over = diff(&a.co, &a.over, [&a.signed[0], &a.signed[1]])?;
    let mid = diff(&a.cm, &a.mid, [&a.mid[0].signed, &a.mid[1].signed])?;
    Some(Bound {
        upper: over.mag(),
        lower: abs_lower(&mid),
    })
}

/// A face's normal curvature relative to its surface's normal at the foot
/// points of the curve points `c.x` (normal and signed distance `d`, `s`),
/// across the curve of tangent `c.dx` ([`curvature_bound`]).
fn kappa(field: &dyn DistanceField, c: &CurveJet, d: &Distance, s: &Interval) -> Option<Interval> {
    let j = field.normal_jacobian_at_foot(&c.x, &d.normal, s)?;
    normal_curvature(&j, &cross(&d.normal, &c.dx))
}

/// The gap to a face with a closed form from what it proves over `T`:
/// at most `|s|`, at least `|s(C(t_m))|`.
fn gap_bound(side: &Side) -> Bound {
    Bound {
        upper: side.signed.mag(),
        lower: abs_lower(&side.mid.signed),
    }
}

/// The gap between the faces' foot points from the two gaps: at every `t`,
/// `|S₁ − S₂| ≤ |s₁| + |s₂|` (through `C(t)`), so the maximum is at most
/// the sum of the two maxima; where gap `i` is greatest it is at least that
/// gap less the other's maximum.
fn face_gap(gap: &[Measure; 2]) -> Measure {
    let value = |m: &Measure| match m {
        Measure::Exact => Some((
            Enclosure {
                lo: 0.0,
                hi: 0.0,
                at: Interval { lo: 0.0, hi: 1.0 },
                tight: true,
            },
            0,
        )),
        Measure::Enclosed { value, piece } => Some((*value, *piece)),
        Measure::Unproved => None,
    };
    match (gap, value(&gap[0]), value(&gap[1])) {
        ([Measure::Exact, Measure::Exact], _, _) => Measure::Exact,
        (_, Some((a, i)), Some((b, j))) => {
            let (big, piece) = if a.hi >= b.hi { (a, i) } else { (b, j) };
            let lo = (a.lo - b.hi).max(b.lo - a.hi).max(0.0);
            let hi = Interval::point(a.hi).add(&Interval::point(b.hi)).hi;
            Measure::Enclosed {
                value: Enclosure {
                    lo,
                    hi,
                    at: big.at,
                    tight: a.tight && b.tight,
                },
                piece,
            }
        }
        _ => Measure::Unproved,
    }
}

/// The maximum of one measure over all pieces, with its piece.
/// What the pieces `T` of an edge's curves prove, kept for the edge's
/// other measures: gap, angle and curvature bisect the same dyadic pieces
/// (the work charged per piece is the same either way, so the caps, and
/// the results, are as without it).
#[derive(Default)]
struct Proved {
    boxes: RefCell<HashMap<PieceKey, Option<Rc<Around>>>>,
}

/// A curve's index and the bits of `T`'s ends.
type PieceKey = (usize, u64, u64);

impl Proved {
    /// [`around`] piece `t` of curve `k`, once.
    fn around(
        &self,
        k: usize,
        curve: &ICurve,
        fields: Fields<'_>,
        t: Interval,
    ) -> Result<Option<Rc<Around>>, Error> {
        let key = (k, t.lo.to_bits(), t.hi.to_bits());
        if let Some(a) = self.boxes.borrow().get(&key) {
            return Ok(a.clone());
        }
        let a = around(curve, fields, t)?.map(Rc::new);
        self.boxes.borrow_mut().insert(key, a.clone());
        Ok(a)
    }
}

/// The gap to a B-spline face by [`SplineField::gap_over`]: at most
/// `|C − S∘p|`; at least 0 (a foot found by Newton may be a stationary
/// point other than the nearest, so its distance is no lower bound: an
/// edge far from the face is undecided, never wrongly failed).
fn spline_gap(curves: &[ICurve], field: &SplineField<'_>, goal: Goal) -> Result<Measure, Error> {
    along_by(curves, goal, MEASURE_WORK, |_, c, t| {
        Ok(field
            .gap_over(c, t)
            .map(|upper| Bound { upper, lower: 0.0 }))
    })
}

/// The angle between the faces over piece `t` of `curve` from their
/// normal paths ([`super::certify::normal_path`]), on each part between
/// the knot lines the feet cross on either face: at most the paths' angle
/// plus both slacks, at least its greatest value at a part's ends and
/// midpoint less them.
/// `gaps` bound the distances from the edge to the faces; `reversed` when
/// one face's orientation is opposite its surface's.
/// `None` when a part is not proved (the caller splits `t`).
fn composed_angle(
    fields: [&Field<'_>; 2],
    gaps: [f64; 2],
    reversed: bool,
    curve: &ICurve,
    t: Interval,
) -> Option<Bound> {
    over_parts(fields, curve, t, |part| {
        let [a, b] = [0, 1].map(|k| fields[k].normal_path(curve, part, gaps[k]));
        let (a, b) = (a?, b?);
        let second = if reversed {
            normal_path::reversed(&b.normal)
        } else {
            b.normal
        };
        let (upper, mid) = normal_path::angle_between(&a.normal, &second)?;
        let [start, end] = normal_path::angle_at_ends(&a.normal, &second);
        let value = mid.lo.max(start.lo).max(end.lo);
        let slack = Interval::point(a.slack).add(&Interval::point(b.slack));
        Some(Bound {
            upper: Interval::point(upper).add(&slack).hi,
            lower: Interval::point(value).sub(&slack).lo,
        })
    })
}

/// The greatest of `measure`'s upper and lower bounds over the parts of
/// piece `t` of `curve` ([`spline_parts`]); `None` when a part is not proved.
fn over_parts(
    fields: [&Field<'_>; 2],
    curve: &ICurve,
    t: Interval,
    measure: impl Fn(Interval) -> Option<Bound>,
) -> Option<Bound> {
    let mut bound = Bound {
        upper: 0.0,
        lower: 0.0,
    };
    for part in spline_parts(fields, curve, t)? {
        let b = measure(part)?;
        bound.upper = bound.upper.max(b.upper);
        bound.lower = bound.lower.max(b.lower);
    }
    Some(bound)
}

/// The parts of piece `t` of `curve` between the knot lines the feet
/// cross on either face ([`SplineField::cuts`]); `None` when a foot is
/// not found.
fn spline_parts(fields: [&Field<'_>; 2], curve: &ICurve, t: Interval) -> Option<Vec<Interval>> {
    let mut cuts = Vec::new();
    for f in fields {
        if let Field::Spline(s) = f {
            cuts.extend(s.cuts(curve, t)?);
        }
    }
    cuts.sort_by(f64::total_cmp);
    Some(parts(t, &cuts))
}

/// The curvature difference across the edge over piece `t` of `curve`
/// where a face is a B-spline's, on each part between the knot lines the
/// feet cross: a B-spline face's curvature on the boxes that hold its feet
/// near the fitted curve ([`SplineField::curvature_over`]), a closed
/// form's at its feet ([`kappa`]); at most the greatest difference over a
/// part, at least its value at a part's midpoint. `signs` orient each
/// face's normal. `None` when a part is not proved (the caller splits
/// `t`).
fn composed_curvature(
    fields: [&Field<'_>; 2],
    signs: [Interval; 2],
    curve: &ICurve,
    t: Interval,
) -> Option<Bound> {
    over_parts(fields, curve, t, |part| {
        let [a, b] = [0, 1].map(|k| {
            curvature_along(fields[k], curve, part)
                .map(|[over, mid]| [over.mul(&signs[k]), mid.mul(&signs[k])])
        });
        let (a, b) = (a?, b?);
        Some(Bound {
            upper: a[0].sub(&b[0]).mag(),
            lower: abs_lower(&a[1].sub(&b[1])),
        })
    })
}

/// A face's normal curvature across the edge, relative to its surface's
/// normal, over part `t` of `curve` and at the part's midpoint `t_m` (the
/// `f64` midpoint, for both faces alike).
fn curvature_along(field: &Field<'_>, curve: &ICurve, t: Interval) -> Option<[Interval; 2]> {
    match field {
        Field::Spline(s) => s.curvature_over(curve, t).map(|c| [c.over, c.mid]),
        Field::Closed(s) => {
            let (cm, co, dt) = curve_jets(curve, t).ok()?;
            let side = side(s, &cm, &co, dt)?;
            Some([
                kappa(s, &co, &side.over, &side.signed)?,
                kappa(s, &cm, &side.mid, &side.mid.signed)?,
            ])
        }
    }
}

/// How far a measure along an edge is refined: to `target`, or less once
/// its verdict is decided — the upper bound under `below` (the measure is
/// within tolerance), or the lower bound over `above` (it fails) with the
/// enclosure within `failed_rel` of its upper end ([`FAILED_REL`], or
/// [`FAILED_CURVATURE_REL`] for the curvature).
#[derive(Clone, Copy, Debug)]
struct Goal {
    target: Target,
    below: f64,
    above: f64,
    failed_rel: f64,
}

/// The relative width a failing gap or angle is refined to (its
/// magnitude to 1 %).
const FAILED_REL: f64 = 1e-2;

/// The relative width a failing curvature difference is refined to (its
/// magnitude to 10 %). Curvature enclosures narrow only linearly with the
/// piece: the target's `10⁻³` cost up to the whole work cap, and 1 %, as
/// for the gap and the angle until 2026-11-29, a sixth of the audit's
/// time on `tail_section_asm.stp` (4.17 against 3.53 s, the same verdicts
/// on all 19 STEP fixtures).
const FAILED_CURVATURE_REL: f64 = 1e-1;

impl Goal {
    /// Is the verdict decided by the greatest upper bound `upper` and the
    /// greatest lower bound `lower` proved so far?
    fn decided(&self, upper: f64, lower: f64) -> bool {
        upper < self.below || (lower > self.above && upper - lower <= self.failed_rel * upper)
    }
}

/// The maximum over all the edge's curves of a measure bounded on piece
/// `t` of curve `k` by `bound(k, curve, t)`: one branch and bound over the
/// pieces of every curve ([`maximize_over`]), within `work`. Until
/// 2026-11-29 each curve had its own branch and bound, with an equal share
/// of what was left of `work`, refined to the goal on its own: a curve
/// whose maximum lay under another's was refined to `1 %` of its own
/// (a crease's angle along an edge of many pieces), for nothing.
fn along_by(
    curves: &[ICurve],
    goal: Goal,
    work: u64,
    mut bound: impl FnMut(usize, &ICurve, Interval) -> Result<Option<Bound>, Error>,
) -> Result<Measure, Error> {
    if curves.is_empty() {
        return Err(Error::Shape("an edge with no curve pieces".into()));
    }
    let ranges = vec![Interval { lo: 0.0, hi: 1.0 }; curves.len()];
    let (value, piece) = capped(work, "a certified measure along an edge", || {
        maximize_over(
            &ranges,
            goal.target,
            |upper, lower| goal.decided(upper, lower),
            |k, t| bound(k, &curves[k], t),
        )
    })?;
    Ok(Measure::Enclosed { value, piece })
}

/// A measure, unproved on a work-cap or singular-foot error.
fn settle(r: Result<Measure, Error>) -> Result<Measure, Error> {
    match r {
        Err(Error::Limit(_) | Error::Domain(_)) => Ok(Measure::Unproved),
        r => r,
    }
}

/// `None` when the work cap ran out.
fn within_cap<T>(r: Result<T, Error>) -> Result<Option<T>, Error> {
    match r {
        Err(Error::Limit(_)) => Ok(None),
        r => r.map(Some),
    }
}

/// The angle of a fold, π, enclosed, everywhere along the edge.
fn fold() -> Measure {
    let pi = std::f64::consts::PI;
    Measure::Enclosed {
        value: Enclosure {
            lo: pi * (1.0 - 1e-15),
            hi: pi * (1.0 + 1e-15),
            at: Interval { lo: 0.0, hi: 1.0 },
            tight: true,
        },
        piece: 0,
    }
}

/// The tolerances of the verdicts, in model units and radians, each
/// enclosed (the exact tolerance lies in the interval; `None` length: only
/// an exact gap holds).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointTolerances {
    /// Length.
    pub length: Option<Interval>,
    /// Angle.
    pub angle: Interval,
    /// Difference of normal curvatures, per length unit.
    pub curvature: Interval,
}

/// The verdict of measures against `tol`: exact when all are exactly 0,
/// else the tolerance test of the largest (within when its upper end is
/// below the tolerance, fails when its lower end is above it), undecided
/// when one is unproved.
fn verdict(ms: &[Measure], tol: Option<Interval>) -> Verdict {
    let mut worst: Option<Enclosure> = None;
    for m in ms {
        match m {
            Measure::Exact => {}
            Measure::Unproved => return Verdict::Undecided,
            Measure::Enclosed { value, .. } => {
                worst = Some(worst.map_or(*value, |w| w.max(*value)));
            }
        }
    }
    match (worst, tol) {
        (None, _) => Verdict::Exact,
        (Some(w), Some(t)) if w.hi < t.lo => Verdict::WithinTolerance,
        (Some(w), t) if w.lo > t.map_or(0.0, |t| t.hi) => Verdict::Fails { magnitude: w },
        (Some(_), _) => Verdict::Undecided,
    }
}

/// Measure the edge with Bézier `pieces` between two faces, and judge it
/// against `tol`. Runs under its own work cap [`EDGE_WORK`] (at most what is
/// left of the command's budget), and charges the work it used.
///
/// # Errors
///
/// [`Error::Shape`] for an edge with no pieces or not in 3D;
/// [`Error::Weight`] for a non-positive weight.
///
/// ```
/// use exact_bezier::algebra::{Interval, RealAlgebraic, Scalar};
/// use exact_bezier::analytic::{Frame, Implicit};
/// use exact_bezier::audit::certify::Verdict;
/// use exact_bezier::audit::joint::{measure_joint, JointFace, JointSurface, JointTolerances, Measure};
/// use exact_bezier::RationalCurve;
/// let q = |n: i64| RealAlgebraic::from_i64(n);
/// let o = vec![q(0), q(0), q(0)];
/// // The floor z = 0 (normal down, out of the solid) and the wall y = 0
/// // (its normal −ŷ): a right-angled edge along the x axis.
/// let floor = Implicit::Plane { frame: Frame::from_axes(o.clone(), vec![q(1), q(0), q(0)], vec![q(0), q(0), q(1)]) };
/// let wall = Implicit::Plane { frame: Frame::from_axes(o.clone(), vec![q(1), q(0), q(0)], vec![q(0), q(1), q(0)]) };
/// let edge = RationalCurve::polynomial(vec![o, vec![q(1), q(0), q(0)]]).unwrap();
/// let faces = [
///     JointFace { surface: JointSurface::Exact(&floor), same_sense: false },
///     JointFace { surface: JointSurface::Exact(&wall), same_sense: false },
/// ];
/// let tol = JointTolerances {
///     length: Some(Interval::point(1e-6)),
///     angle: Interval::point(1e-6),
///     curvature: Interval::point(1e-3),
/// };
/// let m = measure_joint(&[edge], &faces, &tol).unwrap();
/// assert_eq!(m.gap, [Measure::Exact, Measure::Exact]);
/// assert_eq!(m.g0, Verdict::Exact);
/// let Measure::Enclosed { value, .. } = m.angle else { panic!() };
/// let right = std::f64::consts::FRAC_PI_2;
/// assert!(value.lo <= right && right <= value.hi && value.hi - value.lo < 1e-9);
/// assert!(matches!(m.g1, Verdict::Fails { .. }));
/// assert_eq!(m.g2, None); // a crease: curvature is moot
/// ```
pub fn measure_joint(
    pieces: &[Curve],
    faces: &[JointFace<'_>; 2],
    tol: &JointTolerances,
) -> Result<JointMeasures, Error> {
    capped(EDGE_WORK, "the certified measures of an edge", || {
        measure_capped(pieces, faces, tol)
    })
}

/// Run `f` under a work cap of `work` units (at most what is left of the
/// current budget), then charge what it used as `what`.
fn capped<T>(work: u64, what: &str, f: impl FnOnce() -> Result<T, Error>) -> Result<T, Error> {
    let outer = limits::current();
    let cap = Limits {
        max_work: work.min(outer.max_work.saturating_sub(limits::charged())),
        ..outer
    };
    let (result, used) = limits::with_limits(cap, || {
        let r = f();
        (r, limits::charged())
    });
    limits::charge(what, used)?;
    result
}

fn measure_capped(
    pieces: &[Curve],
    faces: &[JointFace<'_>; 2],
    tol: &JointTolerances,
) -> Result<JointMeasures, Error> {
    if pieces.is_empty() {
        return Err(Error::Shape("an edge with no curve pieces".into()));
    }
    let curves = pieces
        .iter()
        .map(ICurve::new)
        .collect::<Result<Vec<_>, _>>()?;
    // A self-intersecting torus: its part (apple or lemon) the edge is on.
    let mid = curves[0].jet(Interval::point(0.5))?.x;
    let (s0, s1) = (faces[0].surface.field(&mid)?, faces[1].surface.field(&mid)?);
    let fields: Fields<'_> = [s0.get(), s1.get()];
    let signs = faces
        .clone()
        .map(|f| Interval::point(if f.same_sense { 1.0 } else { -1.0 }));
    // Refined to 10⁻³ relative or a hundredth of the tolerance, or until
    // below a third of it (the two gaps' sum bounds the face gap).
    let floor = length_resolution(&curves)?;
    let length = match tol.length {
        Some(t) => Goal {
            target: Target {
                rel: 1e-3,
                abs: (t.lo / 100.0).max(floor),
            },
            below: t.lo / 3.0,
            above: t.hi,
            failed_rel: FAILED_REL,
        },
        None => Goal {
            target: Target {
                rel: 1e-3,
                abs: floor,
            },
            below: 0.0,
            above: 0.0,
            failed_rel: FAILED_REL,
        },
    };
    let angular = Goal {
        target: Target {
            rel: 1e-3,
            abs: tol.angle.lo / 100.0,
        },
        below: tol.angle.lo,
        above: tol.angle.hi,
        failed_rel: FAILED_REL,
    };
    let proved = Proved::default();
    let work = if [&s0, &s1].iter().any(|f| matches!(f, Field::Spline(_))) {
        SPLINE_MEASURE_WORK
    } else {
        MEASURE_WORK
    };
    let mut gap = [Measure::Unproved; 2];
    for (k, g) in gap.iter_mut().enumerate() {
        let on = match faces[k].surface.exact() {
            Some(f) => within_cap(lies_on(pieces, f))?,
            None => Some(false),
        };
        *g = match on {
            Some(true) => Measure::Exact,
            Some(false) => settle(match [&s0, &s1][k] {
                Field::Spline(f) => spline_gap(&curves, f, length),
                Field::Closed(f) => along_by(&curves, length, MEASURE_WORK, |_, c, t| {
                    let (cm, co, dt) = curve_jets(c, t)?;
                    Ok(side(f, &cm, &co, dt).map(|s| gap_bound(&s)))
                }),
            })?,
            None => Measure::Unproved,
        };
    }
    let face_gap = face_gap(&gap);
    let exact = match (faces[0].surface.exact(), faces[1].surface.exact()) {
        (Some(f0), Some(f1)) => exact_angle(
            pieces,
            [(f0, faces[0].same_sense), (f1, faces[1].same_sense)],
        ),
        _ => Ok(None),
    };
    let angle = match within_cap(exact)? {
        Some(Some(true)) => Measure::Exact,
        Some(Some(false)) => fold(),
        Some(None) => {
            let reversed = faces[0].same_sense != faces[1].same_sense;
            let gaps = gap.map(|g| match g {
                Measure::Exact => 0.0,
                Measure::Enclosed { value, .. } => value.hi,
                Measure::Unproved => f64::INFINITY,
            });
            settle(along_by(
                &curves,
                angular,
                work,
                |k, c, t| match composed_angle([&s0, &s1], gaps, reversed, c, t) {
                    Some(b) => Ok(Some(b)),
                    None => Ok(proved
                        .around(k, c, fields, t)?
                        .map(|a| angle_bound(&a, fields, signs))),
                },
            ))?
        }
        None => Measure::Unproved,
    };
    let (g0, g1) = (
        verdict(&[gap[0], gap[1], face_gap], tol.length),
        verdict(&[angle], Some(tol.angle)),
    );
    let curvature = if holds(&g0) && holds(&g1) {
        Some(
            if angle == Measure::Exact
                && matches!(
                    (faces[0].surface.exact(), faces[1].surface.exact()),
                    (Some(a), Some(b)) if a == b
                )
            {
                Measure::Exact
            } else {
                let target = Goal {
                    target: Target {
                        rel: 1e-3,
                        abs: tol.curvature.lo / 100.0,
                    },
                    below: tol.curvature.lo,
                    above: tol.curvature.hi,
                    failed_rel: FAILED_CURVATURE_REL,
                };
                let spline = [&s0, &s1].iter().any(|f| matches!(f, Field::Spline(_)));
                settle(along_by(&curves, target, work, |k, c, t| {
                    let composed = spline
                        .then(|| composed_curvature([&s0, &s1], signs, c, t))
                        .flatten();
                    match composed {
                        Some(b) => Ok(Some(b)),
                        None => Ok(proved
                            .around(k, c, fields, t)?
                            .and_then(|a| curvature_bound(&a, fields, signs))),
                    }
                }))?
            },
        )
    } else {
        None
    };
    Ok(JointMeasures {
        g0,
        g1,
        g2: curvature.map(|c| verdict(&[c], Some(tol.curvature))),
        curvature,
        gap,
        face_gap,
        angle,
    })
}

/// Does the order hold (exactly or within tolerance)?
fn holds(v: &Verdict) -> bool {
    matches!(v, Verdict::Exact | Verdict::WithinTolerance)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::{circle, Frame};
    use crate::ratio;
    use num_rational::BigRational;

    fn q(n: i64, d: i64) -> RealAlgebraic {
        RealAlgebraic::from_rational(&ratio::<BigRational>(n, d))
    }

    fn v(x: (i64, i64), y: (i64, i64), z: (i64, i64)) -> Vec<RealAlgebraic> {
        vec![q(x.0, x.1), q(y.0, y.1), q(z.0, z.1)]
    }

    fn tol(length: f64, angle: f64) -> JointTolerances {
        JointTolerances {
            length: Some(Interval::point(length)),
            angle: Interval::point(angle),
            curvature: Interval::point(1e-3),
        }
    }

    fn enclosed(m: Measure) -> Enclosure {
        match m {
            Measure::Enclosed { value, .. } => value,
            other => panic!("not enclosed: {other:?}"),
        }
    }

    /// The face z = 0 and the face through the line y = 0, z = 10⁻⁷ with
    /// normal (0, −10⁻⁵, 1): the edge, that line, is 10⁻⁷ off the first
    /// face and on the second, and the faces meet at atan(10⁻⁵) rad.
    fn gap_and_kink(same_sense: bool, t: &JointTolerances) -> JointMeasures {
        let floor = Implicit::Plane {
            frame: Frame::from_axes(
                v((0, 1), (0, 1), (0, 1)),
                v((1, 1), (0, 1), (0, 1)),
                v((0, 1), (0, 1), (1, 1)),
            ),
        };
        let tilted = Implicit::Plane {
            frame: Frame::from_placement(
                &v((0, 1), (0, 1), (1, 10_000_000)),
                Some(&v((0, 1), (-1, 100_000), (1, 1))),
                Some(&v((1, 1), (0, 1), (0, 1))),
            )
            .unwrap(),
        };
        let edge = RationalCurve::polynomial(vec![
            v((0, 1), (0, 1), (1, 10_000_000)),
            v((1, 1), (0, 1), (1, 10_000_000)),
        ])
        .unwrap();
        let faces = [
            JointFace {
                surface: JointSurface::Exact(&floor),
                same_sense: true,
            },
            JointFace {
                surface: JointSurface::Exact(&tilted),
                same_sense,
            },
        ];
        measure_joint(&[edge], &faces, t).unwrap()
    }

    #[test]
    fn a_gap_of_1e_7_and_a_kink_of_atan_1e_5() {
        let m = gap_and_kink(true, &tol(1e-6, 1e-6));
        // Independently: the edge is at height 1e-7 over z = 0; the angle
        // between (0, 0, 1) and (0, −1e-5, 1) is atan(1e-5).
        let g = enclosed(m.gap[0]);
        assert!(g.lo <= 1e-7 && 1e-7 <= g.hi && g.hi - g.lo < 1e-12, "{g:?}");
        assert_eq!(m.gap[1], Measure::Exact);
        let f = enclosed(m.face_gap);
        assert!(f.lo <= 1e-7 && 1e-7 <= f.hi && f.hi < 1.01e-7, "{f:?}");
        let a = enclosed(m.angle);
        let kink = 1e-5f64.atan();
        assert!(a.lo <= kink && kink <= a.hi && a.hi - a.lo < 1e-10, "{a:?}");
        assert_eq!(m.g0, Verdict::WithinTolerance);
        assert!(matches!(m.g1, Verdict::Fails { magnitude } if magnitude.lo > 1e-6));
        // Tighter length tolerance: G0 fails; looser angle tolerance: G1 holds.
        let m = gap_and_kink(true, &tol(1e-8, 1e-4));
        assert!(matches!(m.g0, Verdict::Fails { magnitude } if magnitude.lo > 1e-8));
        assert_eq!(m.g1, Verdict::WithinTolerance);
        // A tolerance inside the gap's enclosure cannot be decided.
        let m = gap_and_kink(true, &tol(1e-7, 1e-4));
        assert_eq!(m.g0, Verdict::Undecided);
    }

    #[test]
    fn a_reversed_face_is_a_fold() {
        let m = gap_and_kink(false, &tol(1e-6, 1e-6));
        let a = enclosed(m.angle);
        let fold = std::f64::consts::PI - 1e-5f64.atan();
        assert!(a.lo <= fold && fold <= a.hi, "{a:?}");
    }

    /// The cylinder x² + y² = 4 with the plane z = 0 along their circle
    /// (a right angle, gaps exactly 0) and with the plane x = 2 along the
    /// line x = 2, y = 0 (tangent: angle exactly 0).
    #[test]
    fn exact_paths_on_a_cylinder() {
        let axes = Frame::from_axes(
            v((0, 1), (0, 1), (0, 1)),
            v((1, 1), (0, 1), (0, 1)),
            v((0, 1), (0, 1), (1, 1)),
        );
        let cylinder = Implicit::Cylinder {
            frame: axes.clone(),
            radius: q(2, 1),
        };
        let floor = Implicit::Plane {
            frame: axes.clone(),
        };
        let rim = circle(&axes, &q(2, 1));
        let faces = [
            JointFace {
                surface: JointSurface::Exact(&cylinder),
                same_sense: true,
            },
            JointFace {
                surface: JointSurface::Exact(&floor),
                same_sense: false,
            },
        ];
        let m = measure_joint(&rim, &faces, &tol(1e-6, 1e-6)).unwrap();
        assert_eq!(
            (m.gap, m.face_gap, m.g0),
            ([Measure::Exact; 2], Measure::Exact, Verdict::Exact)
        );
        let a = enclosed(m.angle);
        let right = std::f64::consts::FRAC_PI_2;
        assert!(
            a.lo <= right && right <= a.hi && a.hi - a.lo < 1e-3 * right,
            "{a:?}"
        );

        let side = Implicit::Plane {
            frame: Frame::from_axes(
                v((2, 1), (0, 1), (0, 1)),
                v((0, 1), (1, 1), (0, 1)),
                v((1, 1), (0, 1), (0, 1)),
            ),
        };
        let line =
            RationalCurve::polynomial(vec![v((2, 1), (0, 1), (0, 1)), v((2, 1), (0, 1), (3, 1))])
                .unwrap();
        let faces = [
            JointFace {
                surface: JointSurface::Exact(&cylinder),
                same_sense: true,
            },
            JointFace {
                surface: JointSurface::Exact(&side),
                same_sense: true,
            },
        ];
        let m = measure_joint(&[line], &faces, &tol(1e-6, 1e-6)).unwrap();
        assert_eq!(
            (m.angle, m.g0, m.g1),
            (Measure::Exact, Verdict::Exact, Verdict::Exact)
        );
    }
}
