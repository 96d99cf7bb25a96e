//! Exact intersections of rational Bézier curves: isolated points with
//! exact parameters (real algebraic numbers), their multiplicity, overlaps
//! with the exact Möbius map between the shared pieces, and
//! self-intersections (loops and cusps).
//!
//! ## Method
//!
//! Elimination (module `system`): for curves `A(s)`, `B(t)` with positive
//! weights, `A(s) = B(t)` is the polynomial system
//! `E_k = X_k^A(s) W^B(t) − X_k^B(t) W^A(s) = 0`. Two combinations are
//! eliminated by a Sylvester resultant in `t` (evaluated and interpolated in
//! `s`); the real roots of its square-free factors in `[0, 1]` are isolated
//! by Descartes' rule of signs; each root's `t` is the root of the first
//! subresultant, a rational function of `s`, and the remaining equations
//! are checked to vanish exactly. A root whose `t` is not unique (two
//! branches of `B` through one point of `A`) is retried with the roles of
//! `s` and `t` swapped, and in 3D with another projection.
//!
//! Overlaps (module `overlap`): when the resultant vanishes identically,
//! the curves lie on one rational curve; the Möbius map `s = φ(t)` with
//! `B = A ∘ φ` is found from three rational correspondences and verified as
//! a polynomial identity, the overlap is `{t ∈ [0, 1] : φ(t) ∈ [0, 1]}`,
//! and the factor `(ct + d)s − (at + b)` is divided out to find the
//! isolated intersections that remain (e.g. at a node of the common curve).
//!
//! Self-intersections: `E_k(s, t)` of a curve with itself is divisible by
//! `s − t`; the quotients vanish off the diagonal at the double points
//! (`s < t`), on it at the cusps (zero velocity).
//!
//! Common factors of the homogeneous components and degree elevation do not
//! matter: both disappear in the power basis after dividing by the gcd.
//!
//! One entry point, [`intersect`]: two curves or one with itself, exactly
//! over `BigRational`; a [`Filter`] first tries to decide in `f64` interval
//! arithmetic (rigorous: outward rounding, convex hull property, the
//! Krawczyk test for transversal crossings in the plane) and falls back to
//! the exact path where that fails; over `f64` an approximate path with the
//! caller's tolerance ([`Options::tol`]).
//!
//! Reference: Sederberg & Parry, *Comparison of three curve intersection
//! algorithms*, Computer-Aided Design 18 (1986) 58–63 (implicitization and
//! resultants); Basu, Pollack & Roy, *Algorithms in Real Algebraic
//! Geometry* (2006), §2.2 and §4.2 (Descartes' rule, subresultants);
//! Sederberg & Nishita, *Curve intersection using Bézier clipping*, CAD 22
//! (1990) (convex hull culling).

mod approx;
mod certify;
mod filter;
mod overlap;
mod pieces;
mod system;

pub use approx::ApproxIntersection;
pub use filter::CertifiedCrossing;
pub use overlap::Mobius;

use crate::algebra::{BPoly, RealAlgebraic, Scalar, Tolerance};
use crate::curve::RationalCurve;
use crate::error::Error;
use approx::intersect_approx;
use filter::certify_crossings;
use num_rational::BigRational;
use num_traits::{One, Zero};
use system::{combine, solve, PointCache, PowerCurve, Solution, Unsolved};

/// How two curves meet at an isolated intersection.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Contact {
    /// Multiplicity 1: the tangents differ.
    Transversal,
    /// Multiplicity `order + 1` at regular points: the curves touch with
    /// contact of order `order` (1 for a simple tangency).
    Tangential {
        /// The contact order, multiplicity − 1.
        order: usize,
    },
    /// One of the curves has zero velocity there (a cusp or a stationary
    /// point of its parameterization); the multiplicity is still exact.
    Singular,
    /// A self-intersection on the diagonal `s = t`: a cusp of the curve.
    Cusp,
    /// The curves lie on one curve and only touch at a shared end.
    Continuation,
}

/// An isolated intersection `A(s) = B(t)` with exact parameters and point.
#[derive(Clone, Debug)]
pub struct IntersectionPoint {
    /// The parameter on the first curve.
    pub s: RealAlgebraic,
    /// The parameter on the second curve (for a self-intersection, `s ≤ t`).
    pub t: RealAlgebraic,
    /// The common point.
    pub point: Vec<RealAlgebraic>,
    /// The intersection multiplicity (in a generic plane projection for
    /// curves in 3D and above).
    pub multiplicity: usize,
    /// The kind of contact.
    pub contact: Contact,
}

/// A shared piece: `A` on `[s0, s1]` and `B` on `[t0, t1]` are the same
/// curve, `s = φ(t)` (φ maps `t0` to `s.0` and `t1` to `s.1`).
#[derive(Clone, Debug)]
pub struct Overlap {
    /// The parameter interval on the first curve, as `φ(t0), φ(t1)`.
    pub s: (BigRational, BigRational),
    /// The parameter interval on the second curve, `t0 < t1`.
    pub t: (BigRational, BigRational),
    /// The reparameterization `s = φ(t)`.
    pub map: Mobius,
}

/// All intersections of two curves (or of a curve with itself).
#[derive(Clone, Debug, Default)]
pub struct Intersections {
    /// Isolated intersections, by increasing `s`.
    pub points: Vec<IntersectionPoint>,
    /// Shared pieces.
    pub overlaps: Vec<Overlap>,
}

/// Check what the elimination relies on: positive weights, equal
/// dimensions of at least 2, a curve that is not a single point.
fn prepared(c: &RationalCurve<BigRational>, name: &str) -> Result<PowerCurve, Error> {
    c.check_positive_weights()?;
    if c.dim() < 2 {
        return Err(Error::Shape(format!(
            "curve {name} has dimension {}: intersections need points in 2D or more",
            c.dim()
        )));
    }
    let p = PowerCurve::new(c);
    if p.is_point() {
        return Err(Error::Domain(format!(
            "curve {name} is a single point (all control points coincide)"
        )));
    }
    Ok(p)
}

/// The polynomial pairs tried for the elimination: `(E_0, E_1)` in the
/// plane; in 3D and above, combinations `E_0 + Σ c_k E_k`, `E_1 + Σ d_k E_k`
/// (a generic plane projection), the other equations checked exactly.
type Projection = (
    BPoly<BigRational>,
    BPoly<BigRational>,
    Vec<BPoly<BigRational>>,
);

fn projections(eqs: &[BPoly<BigRational>]) -> Vec<Projection> {
    let tries = if eqs.len() == 2 { 1 } else { 3 };
    (0..tries)
        .map(|k| {
            let int = |v: i64| BigRational::from_integer(v.into());
            let one = int(1);
            let mut f = vec![(one.clone(), &eqs[0])];
            let mut g = vec![(one, &eqs[1])];
            for (j, e) in eqs.iter().enumerate().skip(2) {
                let j = j as i64;
                f.push((int(2 + j + 3 * k), e));
                g.push((int(5 - 2 * j + 7 * k), e));
            }
            (combine(&f), combine(&g), eqs[2..].to_vec())
        })
        .collect()
}

/// Swap the roles of `s` and `t` in a solution set found with `t` outer.
fn swapped(sols: Vec<Solution>) -> Vec<Solution> {
    sols.into_iter()
        .map(|x| Solution {
            s: x.t,
            t: x.s,
            ..x
        })
        .collect()
}

/// Solve with `s` outer, and with `t` outer when a root is degenerate or an
/// equation does not involve `t` (a curve with a constant coordinate).
fn solve_either_way(
    p: &Projection,
    pa: &PowerCurve,
    pb: &PowerCurve,
) -> Result<Vec<Solution>, Unsolved> {
    let free_of_t = |e: &BPoly<BigRational>| e.deg_u().unwrap_or(0) == 0;
    let first = if free_of_t(&p.0) || free_of_t(&p.1) {
        Err(Unsolved::Degenerate(RealAlgebraic::zero()))
    } else {
        solve(&p.0, &p.1, &p.2, pa.weight(), pb.weight())
    };
    match first {
        Err(Unsolved::Degenerate(_)) => {
            let extra: Vec<_> = p.2.iter().map(BPoly::transpose).collect();
            let (f, g) = (p.0.transpose(), p.1.transpose());
            if let Some(none) = constant_equation(&f, &g) {
                return none;
            }
            solve(&f, &g, &extra, pb.weight(), pa.weight()).map(swapped)
        }
        other => other,
    }
}

/// When `f` or `g` is a constant: no solutions if it is a non-zero one,
/// a common factor (every point solves it) if it is zero.
fn constant_equation(
    f: &BPoly<BigRational>,
    g: &BPoly<BigRational>,
) -> Option<Result<Vec<Solution>, Unsolved>> {
    let constant =
        |e: &&BPoly<BigRational>| e.deg_u().unwrap_or(0) == 0 && e.deg_v().unwrap_or(0) == 0;
    [f, g].into_iter().find(constant).map(|e| {
        if e.is_zero() {
            Err(Unsolved::CommonFactor)
        } else {
            Ok(Vec::new())
        }
    })
}

/// Divide `p` by `d` as often as it divides.
fn strip_factor(p: &BPoly<BigRational>, d: &BPoly<BigRational>) -> BPoly<BigRational> {
    let mut p = p.clone();
    while let Some(q) = p.div_exact(d) {
        if p.deg_u() == q.deg_u() && p.coeffs() == q.coeffs() {
            break;
        }
        p = q;
    }
    p
}

/// How [`intersect`] uses `f64` interval arithmetic before the exact
/// elimination (exact scalars only).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Filter {
    /// The exact elimination only.
    #[default]
    Off,
    /// The interval stage first, the exact elimination where it cannot
    /// decide.
    First,
    /// The interval stage alone ([`Found::Undecided`] where it cannot
    /// decide): its cost is bounded whatever the degrees, so a caller can
    /// run it before paying for the exact path.
    Only,
}

/// How [`intersect`] decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// The interval filter of two exact curves (self-intersections are
    /// never decided by it).
    pub filter: Filter,
    /// For `f64` only: the tolerance, absolute in model units (default
    /// `1e-9`).
    pub tol: Tolerance,
}

impl Default for Options {
    /// No filter; for `f64` the tolerance [`Tolerance::default`] (`1e-9`).
    fn default() -> Self {
        Options {
            filter: Filter::Off,
            tol: Tolerance::default(),
        }
    }
}

/// Which stage decided an exact [`intersect`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DecidedBy {
    /// Interval arithmetic: hulls of subdivided control polygons and the
    /// Krawczyk test.
    Intervals,
    /// The exact elimination.
    Exact,
}

/// The answer of [`intersect`] over `BigRational`.
#[derive(Clone, Debug)]
pub enum Found {
    /// Decided by interval arithmetic: the curves meet exactly once in each
    /// box, transversally, and nowhere else (no tangency, no overlap);
    /// empty when they are separated.
    Certified(Vec<CertifiedCrossing>),
    /// Decided by the exact elimination.
    Exact(Intersections),
    /// [`Filter::Only`] and the interval stage could not decide.
    Undecided,
}

impl Found {
    /// Which stage decided (`None` when undecided).
    pub fn decided_by(&self) -> Option<DecidedBy> {
        match self {
            Found::Certified(_) => Some(DecidedBy::Intervals),
            Found::Exact(_) => Some(DecidedBy::Exact),
            Found::Undecided => None,
        }
    }

    /// The exact intersections, when the exact elimination decided (always
    /// with [`Filter::Off`]).
    pub fn exact(self) -> Option<Intersections> {
        match self {
            Found::Exact(x) => Some(x),
            _ => None,
        }
    }
}

/// A scalar [`intersect`] computes with, and its answer.
pub trait IntersectScalar: Scalar {
    /// What [`intersect`] returns.
    type Found;
    /// [`intersect`] over this scalar.
    ///
    /// # Errors
    ///
    /// As [`intersect`].
    fn intersect(
        a: &RationalCurve<Self>,
        b: Option<&RationalCurve<Self>>,
        options: Options,
    ) -> Result<Self::Found, Error>;
}

/// Exact, with the interval filter of [`Options::filter`].
impl IntersectScalar for BigRational {
    type Found = Found;

    fn intersect(
        a: &RationalCurve<Self>,
        b: Option<&RationalCurve<Self>>,
        options: Options,
    ) -> Result<Found, Error> {
        let Some(b) = b else {
            return match options.filter {
                Filter::Only => Ok(Found::Undecided),
                _ => self_intersect(a).map(Found::Exact),
            };
        };
        if options.filter != Filter::Off
            && let Some(found) = certify_crossings(a, b)?
        {
            return Ok(Found::Certified(found));
        }
        match options.filter {
            Filter::Only => Ok(Found::Undecided),
            _ => two_curves(a, b).map(Found::Exact),
        }
    }
}

/// Approximate, within [`Options::tol`]; two curves only.
impl IntersectScalar for f64 {
    type Found = Vec<ApproxIntersection>;

    fn intersect(
        a: &RationalCurve<Self>,
        b: Option<&RationalCurve<Self>>,
        options: Options,
    ) -> Result<Self::Found, Error> {
        let b = b.ok_or_else(|| {
            Error::Domain("self-intersections are exact only: use an exact scalar".into())
        })?;
        intersect_approx(a, b, options.tol.0)
    }
}

/// Every intersection of two rational curves over `[0, 1] × [0, 1]` (`b`
/// given), or of one curve with itself (`b = None`).
///
/// Over `BigRational`, exactly: isolated points with their parameters,
/// point, multiplicity and contact, and shared pieces with their Möbius
/// map; self-intersections are double points `A(s) = A(t)` with `s < t`
/// (loops, and a closed curve's shared end) and cusps (`s = t`, zero
/// velocity). [`Options::filter`] decides by `f64` interval arithmetic
/// first where it can (module docs; [`Found::decided_by`] says which
/// stage decided).
///
/// Over `f64`, within the tolerance `tol` (absolute, in model units):
/// subdivision to pieces of size `L = max(tol, √(tol·D))` (`D` the
/// diameter of both curves' boxes), Newton refinement from each cluster of
/// touching piece pairs, kept when `|A(s) − B(t)| ≤ tol`; a cluster of more
/// than 64 piece pairs is a suspected overlap with its parameter ranges,
/// unless Newton ends there on a transversal crossing (tangents at a sine
/// over 10⁻⁶; a heuristic: the exact path decides overlaps).
///
/// # Examples
///
/// The parabola `y = x²` (a quadratic Bézier curve through (−1, 1), (0, 0),
/// (1, 1)) meets the line `y = 1/2` at `x = ±1/√2`, which the filter
/// certifies in boxes:
///
/// ```
/// use exact_bezier::{intersect::{intersect, Filter, Found, Options}, RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let parabola = RationalCurve::polynomial(vec![p(-1, 1), p(0, -1), p(1, 1)]).unwrap();
/// let line = RationalCurve::polynomial(vec![
///     vec![ratio(-1, 1), ratio(1, 2)],
///     vec![ratio(1, 1), ratio(1, 2)],
/// ]).unwrap();
/// let x = intersect(&parabola, Some(&line), Options::default()).unwrap().exact().unwrap();
/// assert_eq!(x.points.len(), 2);
/// assert_eq!(x.points[1].point[0].to_string(), "sqrt(2)/2");
/// let filtered = Options { filter: Filter::First, ..Options::default() };
/// let Found::Certified(boxes) = intersect(&parabola, Some(&line), filtered).unwrap() else { panic!() };
/// assert!(boxes.iter().all(|k| k.point[1].lo <= 0.5 && 0.5 <= k.point[1].hi));
/// ```
///
/// The cubic through (0, 0), (3, 3), (−1, 3), (2, 0) (control points) has a
/// loop: its double point is reported once, with `s < t`.
///
/// ```
/// use exact_bezier::{intersect::{intersect, Contact, Options}, RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let c = RationalCurve::polynomial(vec![p(0, 0), p(3, 3), p(-1, 3), p(2, 0)]).unwrap();
/// let x = intersect(&c, None, Options::default()).unwrap().exact().unwrap();
/// assert_eq!(x.points.len(), 1);
/// assert!(x.points[0].s < x.points[0].t);
/// assert_eq!(x.points[0].contact, Contact::Transversal);
/// ```
///
/// In `f64`:
///
/// ```
/// use exact_bezier::{intersect::{intersect, Options}, RationalCurve};
/// let a = RationalCurve::polynomial(vec![vec![0.0, 0.0], vec![2.0, 2.0]]).unwrap();
/// let b = RationalCurve::polynomial(vec![vec![0.0, 2.0], vec![2.0, 0.0]]).unwrap();
/// let x = intersect(&a, Some(&b), Options::default()).unwrap();
/// assert_eq!(x.len(), 1);
/// assert!((x[0].s - 0.5).abs() < 1e-9 && (x[0].t - 0.5).abs() < 1e-9);
/// ```
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight, [`Error::Shape`] for
/// dimensions that differ or are below 2, [`Error::Domain`] for a curve
/// that is a single point, a curve that covers a piece of itself twice (an
/// improper parameterization) or a configuration the method does not
/// resolve (named in the message); in `f64`, [`Error::Domain`] for a
/// tolerance that is not finite and positive or a self-intersection,
/// [`Error::Limit`] when more than 100 000 piece pairs stay close (as
/// leaves, or at one level of the subdivision).
pub fn intersect<T: IntersectScalar>(
    a: &RationalCurve<T>,
    b: Option<&RationalCurve<T>>,
    options: Options,
) -> Result<T::Found, Error> {
    T::intersect(a, b, options)
}

/// The exact intersections of two curves (see [`intersect`]).
fn two_curves(
    a: &RationalCurve<BigRational>,
    b: &RationalCurve<BigRational>,
) -> Result<Intersections, Error> {
    if a.dim() != b.dim() {
        return Err(Error::Shape(format!(
            "the curves have dimensions {} and {}",
            a.dim(),
            b.dim()
        )));
    }
    let (pa, pb) = (prepared(a, "A")?, prepared(b, "B")?);
    // A coordinate that is the same constant on both curves gives E_k ≡ 0.
    let mut eqs: Vec<_> = (0..pa.dim()).map(|k| pa.equation(&pb, k)).collect();
    eqs.retain(|e| !e.is_zero());
    if eqs.len() < 2 {
        return collinear(&pa, &pb, &eqs[0]);
    }
    let mut last = String::new();
    for proj in projections(&eqs) {
        match solve_either_way(&proj, &pa, &pb) {
            Ok(sols) => return finish(&pa, &pb, sols, Vec::new()),
            Err(Unsolved::CommonFactor) => match overlap::find_mobius(&pa, &pb) {
                Some(phi) => return with_overlap(&pa, &pb, &proj, phi),
                None => last = "the curves share a component but are not Möbius reparameterizations of each other (an improper parameterization)".into(),
            },
            Err(Unsolved::Degenerate(s)) => {
                last = format!("several intersections share the parameter s = {s} and t is not unique either")
            }
        }
    }
    Err(Error::Domain(last))
}

/// Two curves on one line: related by a Möbius map (an overlap, possibly
/// empty) or not handled. A proper parameterization of a line has degree 1,
/// so off the map's graph the equation has no zeros.
fn collinear(
    pa: &PowerCurve,
    pb: &PowerCurve,
    eq: &BPoly<BigRational>,
) -> Result<Intersections, Error> {
    let phi = overlap::find_mobius(pa, pb).ok_or_else(|| {
        Error::Domain(
            "the curves lie on one line and are not Möbius reparameterizations of each other"
                .into(),
        )
    })?;
    with_overlap(pa, pb, &(eq.clone(), eq.clone(), Vec::new()), phi)
}

/// The overlaps given by `φ`, and the isolated intersections off them.
fn with_overlap(
    pa: &PowerCurve,
    pb: &PowerCurve,
    proj: &Projection,
    phi: Mobius,
) -> Result<Intersections, Error> {
    let mut overlaps = Vec::new();
    let mut touching = Vec::new();
    for (t0, t1) in phi.preimage_of_unit() {
        let s0 = phi.at(&t0).expect("inside the preimage");
        let s1 = phi.at(&t1).expect("inside the preimage");
        if t0 == t1 {
            touching.push((s0, t0));
        } else {
            overlaps.push(Overlap {
                s: (s0, s1),
                t: (t0, t1),
                map: phi.clone(),
            });
        }
    }
    let line = phi.graph();
    let rest = (
        strip_factor(&proj.0, &line),
        strip_factor(&proj.1, &line),
        proj.2.clone(),
    );
    let sols = match solve_either_way(&rest, pa, pb) {
        Ok(sols) => sols,
        Err(Unsolved::CommonFactor) => Vec::new(),
        Err(Unsolved::Degenerate(s)) => {
            return Err(Error::Domain(format!(
                "several intersections share the parameter s = {s} beside the overlap"
            )))
        }
    };
    let inside = |x: &RealAlgebraic, lo: &BigRational, hi: &BigRational| {
        let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        *x >= RealAlgebraic::from_rational(lo) && *x <= RealAlgebraic::from_rational(hi)
    };
    let off: Vec<Solution> = sols
        .into_iter()
        .filter(|x| {
            !overlaps
                .iter()
                .any(|o| inside(&x.t, &o.t.0, &o.t.1) || inside(&x.s, &o.s.0, &o.s.1))
        })
        .collect();
    let mut out = finish(pa, pb, off, overlaps)?;
    for (s, t) in touching {
        let (s, t) = (
            RealAlgebraic::from_rational(&s),
            RealAlgebraic::from_rational(&t),
        );
        if out.points.iter().any(|p| p.s == s && p.t == t) {
            continue;
        }
        out.points.push(IntersectionPoint {
            point: pa.point_at(&s, &mut PointCache::default())?,
            s,
            t,
            multiplicity: 1,
            contact: Contact::Continuation,
        });
    }
    out.points
        .sort_by(|x, y| x.s.partial_cmp(&y.s).expect("real numbers are ordered"));
    Ok(out)
}

/// Points, contacts and order for the solutions.
fn finish(
    pa: &PowerCurve,
    pb: &PowerCurve,
    sols: Vec<Solution>,
    overlaps: Vec<Overlap>,
) -> Result<Intersections, Error> {
    let mut points = Vec::with_capacity(sols.len());
    let mut cache = PointCache::default();
    for x in sols {
        let contact = if pa.stationary_at(&x.s) || pb.stationary_at(&x.t) {
            Contact::Singular
        } else if x.multiplicity == 1 {
            Contact::Transversal
        } else {
            Contact::Tangential {
                order: x.multiplicity - 1,
            }
        };
        points.push(IntersectionPoint {
            point: pa.point_at(&x.s, &mut cache)?,
            s: x.s,
            t: x.t,
            multiplicity: x.multiplicity,
            contact,
        });
    }
    points.sort_by(|x, y| x.s.partial_cmp(&y.s).expect("real numbers are ordered"));
    Ok(Intersections { points, overlaps })
}

/// The exact self-intersections of one curve (see [`intersect`]).
fn self_intersect(a: &RationalCurve<BigRational>) -> Result<Intersections, Error> {
    let pa = prepared(a, "A")?;
    let diagonal = BPoly::new(vec![
        crate::algebra::UPoly::new(vec![
            BigRational::from_integer(0.into()),
            BigRational::from_integer(1.into()),
        ]),
        crate::algebra::UPoly::constant(BigRational::from_integer((-1).into())),
    ]);
    let eqs: Vec<_> = (0..pa.dim())
        .map(|k| {
            pa.equation(&pa, k)
                .div_exact(&diagonal)
                .expect("s − t divides X(s)W(t) − X(t)W(s)")
        })
        .filter(|e: &BPoly<BigRational>| !e.is_zero())
        .collect();
    if eqs.len() < 2 {
        return straight(&pa);
    }
    let mut last = String::new();
    for proj in projections(&eqs) {
        match solve(&proj.0, &proj.1, &proj.2, pa.weight(), pa.weight()) {
            Ok(sols) => return finish_self(&pa, sols),
            Err(Unsolved::CommonFactor) => last =
                "the curve covers a piece of itself more than once (an improper parameterization)"
                    .into(),
            Err(Unsolved::Degenerate(s)) => {
                last = format!("three or more branches pass through the point at s = {s}")
            }
        }
    }
    Err(Error::Domain(last))
}

/// A curve on a line has no self-intersections iff it does not turn back:
/// a coordinate that varies, `X/W`, is monotone on `[0, 1]` (its derivative's
/// numerator `X'W − XW'` has no root of odd multiplicity in `(0, 1)`).
fn straight(pa: &PowerCurve) -> Result<Intersections, Error> {
    let w = pa.weight();
    let turns = pa.comps[..pa.dim()].iter().any(|x| {
        let d = system::derivative(x)
            .mul(w)
            .sub(&x.mul(&system::derivative(w)));
        !d.is_zero()
            && system::square_free_factors(&d)
                .iter()
                .filter(|(_, mult)| mult % 2 == 1)
                .any(|(f, _)| {
                    system::roots_in_unit(f)
                        .iter()
                        .any(|r| r.signum() > 0 && *r < RealAlgebraic::one())
                })
    });
    if turns {
        return Err(Error::Domain(
            "the curve runs back along a line: it covers a piece of itself twice".into(),
        ));
    }
    Ok(Intersections::default())
}

/// Double points with `s < t` and cusps on the diagonal.
fn finish_self(pa: &PowerCurve, sols: Vec<Solution>) -> Result<Intersections, Error> {
    let mut points = Vec::new();
    let mut cache = PointCache::default();
    for x in sols {
        let contact = match x.s.partial_cmp(&x.t) {
            Some(std::cmp::Ordering::Greater) => continue,
            Some(std::cmp::Ordering::Equal) => Contact::Cusp,
            _ if pa.stationary_at(&x.s) || pa.stationary_at(&x.t) => Contact::Singular,
            _ if x.multiplicity == 1 => Contact::Transversal,
            _ => Contact::Tangential {
                order: x.multiplicity - 1,
            },
        };
        points.push(IntersectionPoint {
            point: pa.point_at(&x.s, &mut cache)?,
            s: x.s,
            t: x.t,
            multiplicity: x.multiplicity,
            contact,
        });
    }
    Ok(Intersections {
        points,
        overlaps: Vec::new(),
    })
}

#[cfg(test)]
mod tests;
