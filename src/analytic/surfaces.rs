//! Surfaces of ISO 10303-42 §4.4 as exact rational Bézier patches.
//!
//! ```text
//! plane        σ(u, v) = C + u x̂ + v ŷ
//! cylinder     σ(u, v) = C + R (cos u x̂ + sin u ŷ) + v ẑ
//! cone         σ(u, v) = C + (R + v tan α)(cos u x̂ + sin u ŷ) + v ẑ
//! sphere       σ(u, v) = C + R cos v (cos u x̂ + sin u ŷ) + R sin v ẑ,   v ∈ [−90°, 90°]
//! torus        σ(u, v) = C + (R + r cos v)(cos u x̂ + sin u ŷ) + r sin v ẑ
//! extrusion    σ(u, v) = λ(u) + v V
//! revolution   σ(u, v) = A + ((λ(v) − A)·â) â + cos u · ρ(v) + sin u · â × ρ(v),
//!              ρ(v) = (λ(v) − A) − ((λ(v) − A)·â) â      (Rodrigues' rotation)
//! ```
//!
//! Each is bi-affine in the points `a = (cos u, sin u)` (or `u`) and
//! `b = (cos v, sin v)` (or `v`, or `λ`), so the patch with control points
//! `σ(a_i, b_j)` and weights `w_i w'_j` over the control points of the two
//! parameter curves is the surface exactly (Piegl–Tiller, *The NURBS Book*,
//! §8.2–§8.5: the tensor product of rational curves). Angular directions are
//! four quarter arcs (sphere latitude: two, from −90°); unbounded directions
//! take `[v0, v1]` from the caller (see [`covering_range`](super::covering_range)).
//! Patches are listed u-major: patch `iu·n_v + iv`.

use super::curves::quarter_arcs;
use super::frame::Frame;
use super::{add, cross, dot, scale, sub};
use crate::algebra::scalar::{Field, Scalar};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;

/// The control points (parameter-space coordinates) and weights of one
/// piece of a parameter curve.
type Piece<T> = Vec<(Vec<T>, T)>;

/// The tensor-product patches of the bi-affine map `s` over the pieces of
/// two parameter curves: `P_{ij} = s(a_i, b_j)`, `ω_{ij} = w_i w'_j`.
fn tensor<T: Scalar>(
    u: &[Piece<T>],
    v: &[Piece<T>],
    s: impl Fn(&[T], &[T]) -> Vec<T>,
) -> Vec<RectPatch<T>> {
    let mut out = Vec::with_capacity(u.len() * v.len());
    for pu in u {
        for pv in v {
            let ctrl = pu
                .iter()
                .map(|(a, wa)| {
                    pv.iter()
                        .map(|(b, wb)| HPoint::from_point(&s(a, b), &(wa.clone() * wb)))
                        .collect()
                })
                .collect();
            out.push(RectPatch::from_hom(ctrl).expect("a full rectangular net"));
        }
    }
    out
}

/// The four quarter arcs as parameter pieces.
fn turn<T: Scalar>() -> Vec<Piece<T>> {
    quarter_arcs::<T>()
        .into_iter()
        .map(|arc| arc.into_iter().map(|(cs, w)| (cs.to_vec(), w)).collect())
        .collect()
}

/// The one linear piece from `a` to `b`.
fn segment<T: Scalar>(a: &T, b: &T) -> Vec<Piece<T>> {
    vec![vec![
        (vec![a.clone()], T::one()),
        (vec![b.clone()], T::one()),
    ]]
}

/// The pieces of a rational curve as parameter pieces (its control points).
fn curve_pieces<T: Field>(curves: &[RationalCurve<T>]) -> Result<Vec<Piece<T>>, Error> {
    curves
        .iter()
        .map(|c| Ok(c.points()?.into_iter().zip(c.weights()).collect()))
        .collect()
}

/// The plane `C + u x̂ + v ŷ` over the box `[u0, u1] × [v0, v1]`: one
/// bilinear patch, `u = u0 + s(u1 − u0)`, `v = v0 + t(v1 − v0)`.
///
/// ```
/// use exact_bezier::{analytic::{plane, Frame}, ratio, BigRational};
/// let q = |n: i64| ratio::<BigRational>(n, 1);
/// let f = Frame::from_axes(vec![q(1), q(1), q(1)], vec![q(0), q(1), q(0)], vec![q(1), q(0), q(0)]);
/// let p = plane(&f, [&q(0), &q(2)], [&q(0), &q(4)]);
/// // ŷ = ẑ × x̂ = (0, 0, 1).
/// assert_eq!(p.eval(&ratio(1, 2), &ratio(1, 4)).unwrap(), vec![q(1), q(2), q(2)]);
/// ```
pub fn plane<T: Scalar>(frame: &Frame<T>, u: [&T; 2], v: [&T; 2]) -> RectPatch<T> {
    let s = |a: &[T], b: &[T]| frame.point(&a[0], &b[0], &T::zero());
    tensor(&segment(u[0], u[1]), &segment(v[0], v[1]), s).remove(0)
}

/// The cylinder of radius `radius` about the frame's axis, `v ∈ [v0, v1]`:
/// four bidegree (2, 1) patches (quarter arcs in u). Exact; ring only.
pub fn cylinder<T: Scalar>(frame: &Frame<T>, radius: &T, v: [&T; 2]) -> Vec<RectPatch<T>> {
    cone(frame, radius, &T::zero(), v)
}

/// The cone `C + (R + v·tan α)(cos u x̂ + sin u ŷ) + v ẑ`, `v ∈ [v0, v1]`,
/// given `slope = tan α` (see [`cone_slope`](super::cone_slope)): four
/// bidegree (2, 1) patches. Exact in `slope`; ring operations only.
pub fn cone<T: Scalar>(frame: &Frame<T>, radius: &T, slope: &T, v: [&T; 2]) -> Vec<RectPatch<T>> {
    let s = |a: &[T], b: &[T]| {
        let r = radius.clone() + &(b[0].clone() * slope);
        frame.point(&(r.clone() * &a[0]), &(r * &a[1]), &b[0])
    };
    tensor(&turn(), &segment(v[0], v[1]), s)
}

/// The sphere of radius `radius` about the frame's origin: 4 × 2 bidegree
/// (2, 2) patches, u the longitude (quarter arcs from `x̂`), v the latitude
/// (patch row `iv = 0` for `[−90°, 0°]`, `1` for `[0°, 90°]`).
pub fn sphere<T: Scalar>(frame: &Frame<T>, radius: &T) -> Vec<RectPatch<T>> {
    let s = |a: &[T], b: &[T]| {
        let r = radius.clone() * &b[0];
        frame.point(
            &(r.clone() * &a[0]),
            &(r * &a[1]),
            &(radius.clone() * &b[1]),
        )
    };
    let mut arcs = turn();
    let latitude = vec![arcs.swap_remove(3), arcs.swap_remove(0)];
    tensor(&turn(), &latitude, s)
}

/// The torus `C + (R + r cos v)(cos u x̂ + sin u ŷ) + r sin v ẑ` (`major`
/// R, `minor` r; also the degenerate torus r > R, whose pieces cover both
/// the outer and inner parts): 4 × 4 bidegree (2, 2) patches.
pub fn torus<T: Scalar>(frame: &Frame<T>, major: &T, minor: &T) -> Vec<RectPatch<T>> {
    let s = |a: &[T], b: &[T]| {
        let r = major.clone() + &(minor.clone() * &b[0]);
        frame.point(&(r.clone() * &a[0]), &(r * &a[1]), &(minor.clone() * &b[1]))
    };
    tensor(&turn(), &turn(), s)
}

/// The surface of linear extrusion `λ(u) + v V` of the curve pieces
/// `curve` (3D), `v ∈ [v0, v1]`: one bidegree (n, 1) patch per piece.
///
/// # Errors
///
/// [`Error::PointAtInfinity`] if a piece has a zero weight.
pub fn extrusion<T: Field>(
    curve: &[RationalCurve<T>],
    vector: &[T],
    v: [&T; 2],
) -> Result<Vec<RectPatch<T>>, Error> {
    let s = |a: &[T], b: &[T]| add(a, &scale(vector, &b[0]));
    Ok(tensor(&curve_pieces(curve)?, &segment(v[0], v[1]), s))
}

/// The surface of revolution of the curve pieces `curve` (3D) about the
/// axis through `origin` with **unit** direction `axis` (e.g. a
/// [`Frame`]'s `z`): 4 × (pieces) patches of bidegree (2, n), u the angle
/// (quarter arcs, measured from each curve point), v the curve's pieces.
///
/// # Errors
///
/// [`Error::PointAtInfinity`] if a piece has a zero weight.
pub fn revolution<T: Field>(
    curve: &[RationalCurve<T>],
    origin: &[T],
    axis: &[T],
) -> Result<Vec<RectPatch<T>>, Error> {
    let s = |a: &[T], b: &[T]| {
        let d = sub(b, origin);
        let along = scale(axis, &dot(&d, axis));
        let rho = sub(&d, &along);
        let turned = add(&scale(&rho, &a[0]), &scale(&cross(axis, &rho), &a[1]));
        add(&add(origin, &along), &turned)
    };
    Ok(tensor(&turn(), &curve_pieces(curve)?, s))
}
