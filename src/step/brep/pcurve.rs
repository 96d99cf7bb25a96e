//! Analytic `PCURVE`s (a `LINE`, `CIRCLE`, … in a surface's parameter
//! plane) trimmed to their edge, like the edge's 3D curve: from the start
//! vertex to the end vertex, along the curve when the edge's `same_sense`.
//!
//! The vertices are 3D points; their place in the parameter plane is the
//! surface's own parameters of them ([`surface_parameters`]: planes,
//! cylinders, cones, spheres and tori):
//!
//! - on a **plane** both parameters are exact (the frame coordinates), the
//!   pcurve is trimmed exactly like a 3D edge ([`trim_between`]) and the
//!   exact squared distances in the parameter plane are kept
//!   (`vertex_distance_sq`);
//! - on the other surfaces an angle is located in `f64` and is defined up to
//!   whole turns. Only `LINE` pcurves are trimmed there (what CAD systems
//!   write: a cylinder's seam `u = const`, a circle edge `v = const`, a
//!   helix); the turn of each angle is chosen by the line: where the line
//!   holds the angle constant or crosses its direction, the turn nearest to
//!   the line; where the line runs along the angle only (a circle edge),
//!   the start is taken in the turn that begins at the line's point and the
//!   end is reached by walking from it in the edge's direction (a whole turn
//!   for a closed edge). The pieces are exactly the pcurve's between the
//!   located parameters; no `vertex_distance_sq` is written.
//!
//! - on a **B-spline** surface the knot parameters of each vertex are the
//!   nearest point found by Newton in `f64`
//!   ([`nearest_parameters`](crate::nurbs::nearest_parameters)); it must
//!   lie within ten times the model's tolerance of the vertex. `LINE`
//!   pcurves are trimmed there, exactly between the located parameters,
//!   without `vertex_distance_sq`.
//!
//! - on a **surface of revolution** of a B-spline curve, `v` is the curve's
//!   knot parameter of the point nearest the vertex in the half-plane
//!   (height along the axis, distance from it), found in `f64`, and `u` the
//!   angle from that point's radial vector to the vertex's; `LINE` pcurves
//!   are trimmed there likewise.
//!
//! Pcurves on surfaces of extrusion and of revolution of other curves, and
//! non-line pcurves on curved surfaces, stay unconverted and are counted
//! (`pcurves_not_converted`).
//!
//! [`trim_between`]: crate::analytic::trim_between

use super::{reference, surface_geometry, type_name, Builder, Geometry, GeometryRef, Pcurve};
use crate::algebra::{Ordered, RealAlgebraic, Scalar};
use crate::analytic::{cross, dot, scale, sub};
use crate::error::Error;
use crate::nurbs::{nearest_parameters, Nurbs, SpannedPatch};
use crate::patch::Patch;
use crate::step::brep::analytic::{lift, Units};
use crate::step::geometry::{axis1, curve_pieces, surface_parameters, Curve, Parameter};
use num_rational::BigRational;

/// A 2D point located in `f64`, with the period of each coordinate.
type Located = [(f64, Option<f64>); 2];

/// Every parameter pair `(u, v)` of one point on a surface.
type Candidates = Vec<[Parameter<RealAlgebraic>; 2]>;

impl Builder<'_> {
    /// The geometry of the pcurve `pc` of an edge from `start` to `end`:
    /// trimmed to the edge when it is analytic (module docs), else as read.
    pub(super) fn pcurve_geometry(
        &self,
        units: &Units,
        pc: &Pcurve,
        (start, end): (u64, u64),
        same_sense: bool,
    ) -> GeometryRef {
        let mut out = pc.curve.clone();
        if !self.analytic || !matches!(out.geometry, Geometry::NotConverted) {
            return out;
        }
        let ends = [start, end].map(|v| lift(&self.model.vertices[&v]));
        out.geometry = self
            .trimmed_pcurve(units, pc, &ends, start == end, same_sense)
            .unwrap_or_else(|e| Geometry::Invalid(e.to_string()));
        out
    }

    fn trimmed_pcurve(
        &self,
        units: &Units,
        pc: &Pcurve,
        ends: &[Vec<RealAlgebraic>; 2],
        closed: bool,
        same_sense: bool,
    ) -> Result<Geometry, Error> {
        let Some([s, e]) = self.vertex_parameters(units, pc.surface, ends)? else {
            return Ok(Geometry::NotConverted);
        };
        if let (Some(s), Some(e)) = (exact(&s[0]), exact(&e[0])) {
            return self.trimmed_curve(units, pc.curve.entity, &s, &e, same_sense);
        }
        if type_name(self.store, pc.curve.entity) != "LINE" {
            return Ok(Geometry::NotConverted);
        }
        let line = self.line_f64(units, pc.curve.entity, &[located(&s[0]), located(&e[0])])?;
        let walk = if same_sense { 1.0 } else { -1.0 };
        let (s, e, turned) = s
            .iter()
            .flat_map(|a| e.iter().map(move |b| (a, b)))
            .map(|(a, b)| {
                (
                    a,
                    b,
                    choose_turns([located(a), located(b)], line, closed, walk),
                )
            })
            .min_by(|x, y| line.misfit(&x.2).total_cmp(&line.misfit(&y.2)))
            .expect("every point has parameters");
        let (s, e) = (exact_point(s, &turned[0])?, exact_point(e, &turned[1])?);
        let mut g = self.trimmed_curve(units, pc.curve.entity, &s, &e, same_sense)?;
        if let Geometry::Analytic(a) = &mut g {
            a.vertex_distance_sq = None;
        }
        Ok(g)
    }

    /// Every parameter pair of each of the two vertices `ends` on the
    /// surface `surface`: by the closed forms on a plane, cylinder, cone,
    /// sphere or torus, the nearest point found on a B-spline surface;
    /// `None` for other surfaces.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] when the nearest point found on a B-spline surface
    /// is farther than ten times the snap distance (the model's tolerance).
    fn vertex_parameters(
        &self,
        units: &Units,
        surface: u64,
        ends: &[Vec<RealAlgebraic>; 2],
    ) -> Result<Option<[Candidates; 2]>, Error> {
        if let Some(map) = self.with_readers(units, |r| surface_parameters(r, surface))? {
            return Ok(Some([&ends[0], &ends[1]].map(|p| map.of(p))));
        }
        let kind = type_name(self.store, surface);
        if kind == "SURFACE_OF_REVOLUTION" {
            return self.revolution_parameters(surface, ends, units);
        }
        let Geometry::BSpline(spline) = surface_geometry(&kind, surface, &self.conv) else {
            return Ok(None);
        };
        let mut out = [Vec::new(), Vec::new()];
        for (p, params) in ends.iter().zip(&mut out) {
            let at: Vec<f64> = p.iter().map(Ordered::to_f64).collect();
            let Some((uv, d)) = nearest_parameters(spline.pieces(), &at) else {
                return Ok(None);
            };
            if d > 10.0 * units.snap {
                return Err(Error::Domain(format!(
                    "a vertex of the edge is {d:e} from the nearest point found on B-spline surface #{surface}"
                )));
            }
            params.push(uv.map(|value| Parameter::Located {
                value,
                period: None,
            }));
        }
        Ok(Some(out))
    }

    /// The parameters of the two vertices `ends` on the surface of
    /// revolution `surface` of a B-spline curve `λ` about the axis `(A, â)`
    /// (ISO 10303-42: `u` the angle of rotation, `v` the curve's parameter):
    /// `v` where `λ` has the vertex's height `(P − A)·â` and distance from
    /// the axis (the nearest point found in that half-plane by
    /// [`nearest_on_profile`]), and `u` the angle from `λ(v)`'s radial
    /// vector to the vertex's, about `â`, in the context's unit. `None` for
    /// another swept curve.
    ///
    /// # Errors
    ///
    /// As [`Builder::vertex_parameters`]; a malformed entity.
    fn revolution_parameters(
        &self,
        surface: u64,
        ends: &[Vec<RealAlgebraic>; 2],
        units: &Units,
    ) -> Result<Option<[Candidates; 2]>, Error> {
        let rec = &self.store[&surface].records[0];
        let swept = reference(rec.params.get(1), "swept_curve").map_err(Error::Format)?;
        let axis = reference(rec.params.get(2), "axis_position").map_err(Error::Format)?;
        let Some(Nurbs::Curve(_)) = self.conv.nurbs.get(&swept) else {
            return Ok(None);
        };
        let profile = self.conv.nurbs[&swept].pieces();
        let (origin, direction) = axis1::<RealAlgebraic>(self.store, axis)?;
        let f = |p: &[RealAlgebraic]| -> Vec<f64> { p.iter().map(Ordered::to_f64).collect() };
        let (a, z) = (f(&origin), f(&direction));
        let turn = units.angle.to_radians_f64(1.0);
        let mut out = [Vec::new(), Vec::new()];
        for (p, params) in ends.iter().zip(&mut out) {
            let (height, radial) = axial(&f(p), &a, &z);
            let Some((v, d, c)) = nearest_on_profile(&profile, &a, &z, [height, norm(&radial)])
            else {
                return Ok(None);
            };
            if d > 10.0 * units.snap {
                return Err(Error::Domain(format!(
                    "a vertex of the edge is {d:e} from the nearest point found on the surface of revolution #{surface}"
                )));
            }
            let (_, from) = axial(&c, &a, &z);
            let angle = dot(&cross(&z, &from), &radial).atan2(dot(&from, &radial));
            params.push([
                Parameter::Located {
                    value: angle / turn,
                    period: Some(std::f64::consts::TAU / turn),
                },
                Parameter::Located {
                    value: v,
                    period: None,
                },
            ]);
        }
        Ok(Some(out))
    }

    /// The line pcurve `id` as a point and direction in `f64`, from its
    /// pieces cut to cover the located points (any turn: the line is the same).
    fn line_f64(&self, units: &Units, id: u64, at: &[Located; 2]) -> Result<Line, Error> {
        let cover = at
            .iter()
            .map(|p| p.iter().map(|&(v, _)| from_f64(v)).collect())
            .collect::<Result<Vec<Vec<RealAlgebraic>>, Error>>()?;
        let Curve::Pieces(c) = self.with_readers(units, |r| curve_pieces(r, id, &cover))? else {
            return Err(Error::Format(format!(
                "#{id}: a LINE pcurve not read as a line"
            )));
        };
        let ends = c
            .pieces
            .first()
            .and_then(|piece| piece.points().ok())
            .filter(|pts| pts.len() == 2 && pts[0].len() == 2)
            .ok_or_else(|| Error::Format(format!("#{id}: a LINE pcurve is not one 2D segment")))?;
        let f = |p: &[RealAlgebraic]| [p[0].to_f64(), p[1].to_f64()];
        let (p0, p1) = (f(&ends[0]), f(&ends[1]));
        Ok(Line {
            point: p0,
            direction: [p1[0] - p0[0], p1[1] - p0[1]],
        })
    }
}

/// A 2D line `point + t·direction`, in `f64`.
#[derive(Clone, Copy, Debug)]
struct Line {
    point: [f64; 2],
    direction: [f64; 2],
}

impl Line {
    /// The sum of the distances of two points from the line.
    fn misfit(&self, points: &[[f64; 2]; 2]) -> f64 {
        let [dx, dy] = self.direction;
        let length = dx.hypot(dy);
        points
            .iter()
            .map(|p| {
                let (x, y) = (p[0] - self.point[0], p[1] - self.point[1]);
                (x * dy - y * dx).abs() / length
            })
            .sum()
    }
}

/// Both parameters exactly, when neither is an angle.
fn exact(p: &[Parameter<RealAlgebraic>; 2]) -> Option<Vec<RealAlgebraic>> {
    p.iter()
        .map(|x| match x {
            Parameter::Exact(t) => Some(t.clone()),
            Parameter::Located { .. } => None,
        })
        .collect()
}

/// The point with its exact parameters kept and its angles as located
/// (and turned) in `f64`, `at`.
fn exact_point(
    p: &[Parameter<RealAlgebraic>; 2],
    at: &[f64; 2],
) -> Result<Vec<RealAlgebraic>, Error> {
    p.iter()
        .zip(at)
        .map(|(x, &v)| match x {
            Parameter::Exact(t) => Ok(t.clone()),
            Parameter::Located { .. } => from_f64(v),
        })
        .collect()
}

fn located(p: &[Parameter<RealAlgebraic>; 2]) -> Located {
    p.clone().map(|x| match x {
        Parameter::Exact(t) => (t.to_f64(), None),
        Parameter::Located { value, period } => (value, period),
    })
}

/// The height `(p − a)·z` of `p` along the unit axis `(a, z)` and its
/// radial vector `(p − a) − height·z`.
fn axial(p: &[f64], a: &[f64], z: &[f64]) -> (f64, Vec<f64>) {
    let d = sub(p, a);
    let h = dot(&d, z);
    (h, sub(&d, &scale(z, &h)))
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

/// The knot parameter of the point of the profile curve (B-spline pieces
/// `profile`) nearest, in the half-plane (height, distance from the axis
/// `(a, z)`), to `target`, with that distance and the point: the best of 64
/// samples per piece, refined by a ternary search over the samples on
/// either side (a search heuristic in `f64`).
fn nearest_on_profile(
    profile: &[SpannedPatch],
    a: &[f64],
    z: &[f64],
    target: [f64; 2],
) -> Option<(f64, f64, Vec<f64>)> {
    const SAMPLES: u32 = 64;
    let mut best: Option<(f64, f64, Vec<f64>)> = None;
    for piece in profile {
        let Patch::Curve(c) = &piece.patch else {
            continue;
        };
        let c = c.map(Ordered::to_f64);
        let at = |t: f64| -> Option<(f64, Vec<f64>)> {
            let p = c.eval(&t).ok()?;
            let (h, r) = axial(&p, a, z);
            Some(((h - target[0]).hypot(norm(&r) - target[1]), p))
        };
        let span = [piece.u[0].to_f64(), piece.u[1].to_f64()];
        let step = 1.0 / f64::from(SAMPLES);
        let (k, _) = (0..=SAMPLES)
            .filter_map(|k| Some((k, at(f64::from(k) * step)?.0)))
            .min_by(|x, y| x.1.total_cmp(&y.1))?;
        let (mut lo, mut hi) = (
            (f64::from(k) - 1.0).max(0.0) * step,
            (f64::from(k) + 1.0).min(f64::from(SAMPLES)) * step,
        );
        for _ in 0..100 {
            let (m1, m2) = (lo + (hi - lo) / 3.0, hi - (hi - lo) / 3.0);
            if at(m1)?.0 <= at(m2)?.0 {
                hi = m2;
            } else {
                lo = m1;
            }
        }
        let t = 0.5 * (lo + hi);
        let (d, p) = at(t)?;
        if best.as_ref().is_none_or(|b| d < b.1) {
            best = Some((span[0] + t * (span[1] - span[0]), d, p));
        }
    }
    best
}

fn from_f64(v: f64) -> Result<RealAlgebraic, Error> {
    BigRational::from_float(v)
        .map(|q| RealAlgebraic::from_rational(&q))
        .ok_or_else(|| Error::Domain(format!("a surface parameter {v} is not finite")))
}

/// The start and end points in the parameter plane with each periodic
/// coordinate moved by whole turns as the module docs say; `walk` is `1`
/// when the edge runs along the line's direction, `−1` against it.
fn choose_turns(at: [Located; 2], line: Line, closed: bool, walk: f64) -> [[f64; 2]; 2] {
    let mut out = at.map(|p| [p[0].0, p[1].0]);
    for i in 0..2 {
        let (j, d) = (1 - i, line.direction);
        let Some(period) = at[0][i].1 else {
            continue;
        };
        if d[j] == 0.0 && d[i] != 0.0 {
            let base = line.point[i] - 1e-9 * period;
            out[0][i] -= period * ((out[0][i] - base) / period).floor();
            let s = walk * d[i].signum();
            let mut ahead = ((out[1][i] - out[0][i]) * s).rem_euclid(period);
            if closed && ahead < 1e-9 * period {
                ahead = period;
            }
            out[1][i] = out[0][i] + s * ahead;
        } else {
            for p in &mut out {
                let on_line = if d[i] == 0.0 {
                    line.point[i]
                } else {
                    line.point[i] + d[i] * (p[j] - line.point[j]) / d[j]
                };
                p[i] += period * ((on_line - p[i]) / period).round();
            }
        }
    }
    out
}
