//! [`covering_range`]: the range of a surface's unbounded parameter(s) that
//! covers a face, from points whose convex hull contains the face's edges.
//!
//! A face's bounding edges are rational curves with positive weights, so
//! each lies in the convex hull of its control points. Every unbounded
//! parameter below is an affine function of the surface point (or bounded
//! by affine functions of it), so its extreme values over that hull are
//! attained at the given points: the exact min/max of the projections
//! (in `T`, no rounding) covers the face. No margin is added; only when
//! the points project to a single value (no face has zero extent) is the
//! range widened to `[x − 1, x + 1]` so the pieces are not degenerate.

use super::frame::Frame;
use super::{dot, sub};
use crate::algebra::scalar::{Field, Ordered};
use crate::curve::RationalCurve;
use crate::error::Error;
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::Zero;

/// A surface with unbounded parameter directions.
#[derive(Clone, Debug)]
pub enum Unbounded<'a, T> {
    /// A plane: both `u = (P − C)·x̂` and `v = (P − C)·ŷ`.
    Plane(&'a Frame<T>),
    /// A cylinder or cone: `v = (P − C)·ẑ`.
    Axial(&'a Frame<T>),
    /// An extrusion `λ(u) + v V`: `v = (P·V − λ(u)·V)/|V|²`, bounded by the
    /// projections of the points and of the curve's control points.
    Extrusion {
        /// The swept curve's pieces.
        curve: &'a [RationalCurve<T>],
        /// `V`.
        vector: &'a [T],
    },
    /// The revolution of the line `L + v D` about the axis through `A` with
    /// unit direction `â`: `v = ((P − A)·â − (L − A)·â)/(D·â)` (the
    /// rotation keeps the axial coordinate); needs `D·â ≠ 0`.
    RevolvedLine {
        /// `L`.
        point: &'a [T],
        /// `D`.
        direction: &'a [T],
        /// `A`.
        origin: &'a [T],
        /// `â`.
        axis: &'a [T],
    },
}

/// The ranges `[lo, hi]` of the unbounded parameters of `surface` that
/// cover `points` (two ranges, u then v, for a plane; one, v, otherwise).
/// Exact for exact `T`.
///
/// # Errors
///
/// [`Error::Domain`] with no points, or for a line revolved in a plane
/// perpendicular to the axis (`D·â = 0`: its parameter is a radius, not
/// an affine function); [`Error::PointAtInfinity`] for a zero weight.
///
/// ```
/// use exact_bezier::{analytic::{covering_range, Frame, Unbounded}, ratio, BigRational};
/// let q = |n: i64| ratio::<BigRational>(n, 1);
/// let f = Frame::from_axes(vec![q(0), q(0), q(1)], vec![q(1), q(0), q(0)], vec![q(0), q(0), q(1)]);
/// let pts = vec![vec![q(1), q(0), q(5)], vec![q(0), q(1), q(-2)]];
/// assert_eq!(covering_range(&Unbounded::Axial(&f), &pts).unwrap(), vec![[q(-3), q(4)]]);
/// ```
pub fn covering_range<T: Field + Ordered>(
    surface: &Unbounded<'_, T>,
    points: &[Vec<T>],
) -> Result<Vec<[T; 2]>, Error> {
    if points.is_empty() {
        return Err(Error::Domain("no points to cover".into()));
    }
    Ok(match surface {
        Unbounded::Plane(fr) => {
            let relative = Relative::new(points, Some(&fr.origin));
            vec![
                widen(relative.projection_extremes(&fr.x)),
                widen(relative.projection_extremes(&fr.y)),
            ]
        }
        Unbounded::Axial(fr) => {
            vec![widen(
                Relative::new(points, Some(&fr.origin)).projection_extremes(&fr.z),
            )]
        }
        Unbounded::Extrusion { curve, vector } => {
            if curve.is_empty() {
                return Err(Error::Domain("an extrusion of no curve pieces".into()));
            }
            let vv = dot(vector, vector);
            let [p_lo, p_hi] = Relative::new(points, None).projection_extremes(vector);
            let mut ctrl = Vec::new();
            for c in curve.iter() {
                ctrl.extend(c.points()?);
            }
            let [c_lo, c_hi] = Relative::new(&ctrl, None).projection_extremes(vector);
            vec![widen([(p_lo - &c_hi) / &vv, (p_hi - &c_lo) / &vv])]
        }
        Unbounded::RevolvedLine {
            point,
            direction,
            origin,
            axis,
        } => {
            let da = dot(direction, axis);
            if da.is_zero() {
                return Err(Error::Domain(
                    "a line revolved in a plane perpendicular to the axis".into(),
                ));
            }
            let base = dot(&sub(point, origin), axis);
            // v is an affine function of the axial coordinate: its extremes
            // are the images of the coordinate's (swapped when D·â < 0,
            // which `widen` orders).
            let [lo, hi] = Relative::new(points, Some(origin)).projection_extremes(axis);
            vec![widen([(lo - &base) / &da, (hi - &base) / &da])]
        }
    })
}

/// Points `P` taken relative to an origin `O` (`P − O`; `P` itself without
/// one), with fixed-point enclosures of the coordinates of every `P − O`
/// where `T` has [`Ordered::rational_bounds`], computed once for all the
/// directions they are projected on (and the origin's once for all points).
struct Relative<'a, T> {
    points: &'a [Vec<T>],
    origin: Option<&'a [T]>,
    enclosures: Option<Vec<Vec<[BigInt; 2]>>>,
}

impl<'a, T: Field + Ordered> Relative<'a, T> {
    fn new(points: &'a [Vec<T>], origin: Option<&'a [T]>) -> Self {
        let enclosures = relative_enclosures(points, origin);
        Relative {
            points,
            origin,
            enclosures,
        }
    }

    /// The exact `(P − O)·d`.
    fn exact(&self, p: &[T], d: &[T]) -> T {
        match self.origin {
            Some(o) => dot(&sub(p, o), d),
            None => dot(p, d),
        }
    }

    /// The exact `[min, max]` of the projections `(P − O)·d`.
    ///
    /// With enclosures, every projection is first enclosed by integer
    /// interval arithmetic; a point whose enclosure lies wholly above
    /// another's cannot be the minimum (nor, below, the maximum), so only
    /// the others are projected exactly. The answer is that of projecting
    /// every point.
    fn projection_extremes(&self, d: &[T]) -> [T; 2] {
        let all = || extremes(self.points.iter().map(|p| self.exact(p, d)));
        let (Some(enclosures), Some(d_fixed)) = (
            &self.enclosures,
            d.iter().map(fixed).collect::<Option<Vec<_>>>(),
        ) else {
            return all();
        };
        let projections: Vec<[BigInt; 2]> = enclosures
            .iter()
            .map(|p| interval_dot(p, &d_fixed))
            .collect();
        let lowest_top = projections.iter().map(|[_, hi]| hi).min();
        let highest_bottom = projections.iter().map(|[lo, _]| lo).max();
        let (Some(lowest_top), Some(highest_bottom)) = (lowest_top, highest_bottom) else {
            return all();
        };
        let pairs = || self.points.iter().zip(&projections);
        let [lo, _] = extremes(
            pairs()
                .filter(|(_, [lo, _])| lo <= lowest_top)
                .map(|(p, _)| self.exact(p, d)),
        );
        let [_, hi] = extremes(
            pairs()
                .filter(|(_, [_, hi])| hi >= highest_bottom)
                .map(|(p, _)| self.exact(p, d)),
        );
        [lo, hi]
    }
}

/// Fractional bits of the fixed-point enclosures of [`fixed`].
const FIXED_BITS: usize = 64;

/// For every point, `[L, H]` per coordinate with `L ≤ (pᵢ − oᵢ)·2^{64} ≤ H`
/// (`pᵢ` without an origin), from [`fixed`] enclosures; `None` when `T`
/// has no bounds.
fn relative_enclosures<T: Ordered>(
    points: &[Vec<T>],
    origin: Option<&[T]>,
) -> Option<Vec<Vec<[BigInt; 2]>>> {
    let origin: Option<Vec<[BigInt; 2]>> = match origin {
        Some(o) => Some(o.iter().map(fixed).collect::<Option<_>>()?),
        None => None,
    };
    points
        .iter()
        .map(|p| {
            p.iter()
                .enumerate()
                .map(|(i, x)| {
                    let xi = fixed(x)?;
                    Some(match &origin {
                        Some(o) => [&xi[0] - &o[i][1], &xi[1] - &o[i][0]],
                        None => xi,
                    })
                })
                .collect()
        })
        .collect()
}

/// `[L, H]` with `L ≤ Σ xᵢ·dᵢ ≤ H` for `xᵢ ∈ x[i]`, `dᵢ ∈ d[i]`: exact
/// integer interval arithmetic on the fixed-point enclosures (a product of
/// two is a multiple of `2^{−128}`).
fn interval_dot(x: &[[BigInt; 2]], d: &[[BigInt; 2]]) -> [BigInt; 2] {
    x.iter()
        .zip(d)
        .fold([BigInt::zero(), BigInt::zero()], |[l, h], (xi, di)| {
            let [lo, hi] = interval_product(xi, di);
            [l + lo, h + hi]
        })
}

/// `[⌊lo·2^{64}⌋, ⌈hi·2^{64}⌉]` of `x`'s rational bounds.
fn fixed<T: Ordered>(x: &T) -> Option<[BigInt; 2]> {
    let (lo, hi) = x.rational_bounds()?;
    let down = (lo.numer() << FIXED_BITS).div_floor(lo.denom());
    let up = -((-(hi.numer() << FIXED_BITS)).div_floor(hi.denom()));
    Some([down, up])
}

/// `[a, b]·[c, d]`: the least and greatest of the four corner products.
fn interval_product([a, b]: &[BigInt; 2], [c, d]: &[BigInt; 2]) -> [BigInt; 2] {
    let corners = [a * c, a * d, b * c, b * d];
    let lo = corners.iter().min().expect("four corners").clone();
    let hi = corners.iter().max().expect("four corners").clone();
    [lo, hi]
}

/// The min and max of a non-empty sequence.
fn extremes<T: Ordered>(mut xs: impl Iterator<Item = T>) -> [T; 2] {
    let first = xs.next().expect("a non-empty sequence");
    xs.fold([first.clone(), first], |[lo, hi], x| {
        let lo = if x < lo { x.clone() } else { lo };
        let hi = if x > hi { x } else { hi };
        [lo, hi]
    })
}

/// `[lo, hi]`, ordered, and widened by 1 each way when `lo = hi`.
fn widen<T: Ordered>([a, b]: [T; 2]) -> [T; 2] {
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    if lo == hi {
        return [lo - &T::one(), hi + &T::one()];
    }
    [lo, hi]
}
