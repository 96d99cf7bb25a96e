//! STEP (ISO 10303-21, AP203/AP214/AP242) B-spline geometry, read exactly:
//! `B_SPLINE_CURVE_WITH_KNOTS`, `B_SPLINE_SURFACE_WITH_KNOTS`,
//! `BEZIER_CURVE`/`BEZIER_SURFACE`, `UNIFORM_…`/`QUASI_UNIFORM_…`, and their
//! complex-instance rational forms
//! `(BOUNDED_SURFACE() B_SPLINE_SURFACE(…) B_SPLINE_SURFACE_WITH_KNOTS(…) …
//! RATIONAL_B_SPLINE_SURFACE(…) …)`, with `CARTESIAN_POINT` references
//! resolved and the `ADVANCED_FACE`s (or `FACE_SURFACE`s) that use each
//! surface. Every number is read exactly from its text (`2.5E-1` is 1/4).
//!
//! Entity layouts (ISO 10303-42 §4.4): a `b_spline_surface` is
//! `(u_degree, v_degree, control_points_list, surface_form, u_closed,
//! v_closed, self_intersect)`, the list's outer index running along u;
//! `…_with_knots` adds `(u_multiplicities, v_multiplicities, u_knots,
//! v_knots, knot_spec)`; `rational_…` adds the weights grid. Curves likewise
//! with one degree and `(degree, control_points_list, curve_form,
//! closed_curve, self_intersect)` then `(multiplicities, knots, knot_spec)`.
//! Uniform knots are `−p, −p+1, …` (step 1); quasi-uniform knots are
//! `0^{p+1}, 1, …, (n−p)^{p+1}`; a Bézier entity has `0^{p+1} 1^{p+1}`.
//!
//! Other entities are skipped and counted by name, never an error; an
//! entity of a supported type that is malformed is reported with its id
//! and skipped too (a model audit should see the rest of the file).
//!
//! The topology (solids, shells, faces, loops, edges, vertices), the units
//! and the tolerance are read by [`read_brep`] ([`brep`]).

use crate::algebra::parse_rational;
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::nurbs::{Knots, Nurbs, NurbsCurve, NurbsSurface};
use num_rational::BigRational;
use num_traits::{One, Signed};
use rayon::prelude::*;
use std::collections::{BTreeMap, HashMap};
use std::io::BufRead;

pub mod brep;
pub mod geometry;
pub mod parser;

pub use brep::{read_brep, read_brep_with, BrepModel, BrepOptions};

use parser::{Instance, Param, Reader, Record};

/// A B-spline entity of the file, converted.
#[derive(Clone, Debug)]
pub struct StepEntity {
    /// Its instance id.
    pub id: u64,
    /// The entity name (the leaf type for complex instances).
    pub name: String,
    /// The geometry.
    pub nurbs: Nurbs,
    /// The faces (`ADVANCED_FACE`/`FACE_SURFACE` ids) whose geometry it is.
    pub faces: Vec<u64>,
}

/// The B-spline geometry of a STEP file and what was skipped.
#[derive(Clone, Debug, Default)]
pub struct StepModel {
    /// The supported entities, by increasing id.
    pub entities: Vec<StepEntity>,
    /// Skipped entity types with their counts.
    pub skipped: BTreeMap<String, usize>,
    /// Supported entities that could not be read: `(id, reason)`.
    pub invalid: Vec<(u64, String)>,
    /// Faces whose surface is not a supported B-spline: `(face, surface)`.
    pub other_faces: Vec<(u64, u64)>,
}

/// What a supported entity needs until its points are known.
struct Pending {
    name: String,
    parts: BTreeMap<String, Vec<Param>>,
}

/// The record names that make an instance a supported curve or surface.
const SURFACE: &str = "B_SPLINE_SURFACE";
const CURVE: &str = "B_SPLINE_CURVE";

/// The part of a complex B-spline instance that says where its knots come
/// from (`…_WITH_KNOTS`, `UNIFORM_…`, `QUASI_UNIFORM_…`, `BEZIER_…`),
/// whatever the order of the parts; `base` is `B_SPLINE_SURFACE` or
/// `B_SPLINE_CURVE`.
fn knot_part<'a>(base: &str, names: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let kind = &base["B_SPLINE_".len()..];
    let names: Vec<&str> = names.collect();
    let wanted = [
        format!("{base}_WITH_KNOTS"),
        format!("QUASI_UNIFORM_{kind}"),
        format!("UNIFORM_{kind}"),
        format!("BEZIER_{kind}"),
    ];
    wanted
        .iter()
        .find_map(|w| names.iter().copied().find(|n| n == w))
}

/// Split a simple instance into the parts of its supertype chain, as a
/// complex instance would list them: `NAME(name, base…, own…)` becomes
/// `B_SPLINE_X(base…)` and `NAME(own…)`.
fn parts_of(inst: &Instance) -> Option<(String, BTreeMap<String, Vec<Param>>)> {
    let mut parts = BTreeMap::new();
    if inst.complex {
        for r in &inst.records {
            parts.insert(r.name.clone(), r.params.clone());
        }
        let base = [SURFACE, CURVE]
            .into_iter()
            .find(|b| parts.contains_key(*b))?;
        let leaf = knot_part(base, parts.keys().map(String::as_str)).unwrap_or(base);
        return Some((leaf.to_owned(), parts));
    }
    let Record { name, params } = &inst.records[0];
    let (base, len) = if name.contains("_SURFACE") {
        (SURFACE, 7)
    } else if name.contains("_CURVE") {
        (CURVE, 5)
    } else {
        return None;
    };
    let supported = [
        "B_SPLINE_SURFACE_WITH_KNOTS",
        "BEZIER_SURFACE",
        "UNIFORM_SURFACE",
        "QUASI_UNIFORM_SURFACE",
        "B_SPLINE_CURVE_WITH_KNOTS",
        "BEZIER_CURVE",
        "UNIFORM_CURVE",
        "QUASI_UNIFORM_CURVE",
    ];
    if !supported.contains(&name.as_str()) || params.len() < len + 1 {
        return None;
    }
    parts.insert(base.to_owned(), params[1..=len].to_vec());
    parts.insert(name.clone(), params[len + 1..].to_vec());
    Some((name.clone(), parts))
}

fn num(p: &Param, what: &str) -> Result<BigRational, Error> {
    match p {
        Param::Number(t) => parse_rational(t),
        Param::Typed(_, inner) if inner.len() == 1 => num(&inner[0], what),
        _ => Err(Error::Format(format!("{what} should be a number"))),
    }
}

fn list<'a>(p: &'a Param, what: &str) -> Result<&'a [Param], Error> {
    match p {
        Param::List(v) => Ok(v),
        _ => Err(Error::Format(format!("{what} should be a list"))),
    }
}

fn count(p: &Param, what: &str) -> Result<usize, Error> {
    let q = num(p, what)?;
    if !q.is_integer() || q.is_negative() {
        return Err(Error::Format(format!(
            "{what} should be a non-negative integer, not {q}"
        )));
    }
    q.to_integer()
        .try_into()
        .map_err(|_| Error::Format(format!("{what} is too large")))
}

fn numbers(p: &Param, what: &str) -> Result<Vec<BigRational>, Error> {
    list(p, what)?.iter().map(|x| num(x, what)).collect()
}

/// Knots of one direction: from the `_WITH_KNOTS` part (`mults`, `values`
/// given), or generated for Bézier / uniform / quasi-uniform entities.
fn knots(
    leaf: &str,
    degree: usize,
    count: usize,
    explicit: Option<(&Param, &Param)>,
) -> Result<Knots, Error> {
    if let Some((m, v)) = explicit {
        let mults = list(m, "knot multiplicities")?
            .iter()
            .map(|x| self::count(x, "a knot multiplicity"))
            .collect::<Result<Vec<_>, _>>()?;
        return Knots::from_multiplicities(degree, &numbers(v, "knots")?, &mults, count);
    }
    let int = |i: i64| BigRational::from_integer(i.into());
    let n = count as i64 + degree as i64 + 1;
    let p = degree as i64;
    let values: Vec<BigRational> = if leaf.contains("BEZIER") {
        if count != degree + 1 {
            return Err(Error::Shape(format!(
                "a Bézier entity of degree {degree} needs {} points per direction, not {count}",
                degree + 1
            )));
        }
        (0..n).map(|i| int(i64::from(i > p))).collect()
    } else if leaf.contains("QUASI_UNIFORM") {
        (0..n)
            .map(|i| int((i - p).clamp(0, count as i64 - p)))
            .collect()
    } else if leaf.contains("UNIFORM") {
        (0..n).map(|i| int(i - p)).collect()
    } else {
        return Err(Error::Format(format!("{leaf} has no knots")));
    };
    Knots::new(degree, values, count)
}

/// A weight: positive and exact.
fn weight(p: &Param) -> Result<BigRational, Error> {
    let w = num(p, "a weight")?;
    if !w.is_positive() {
        return Err(Error::Weight {
            index: "in the STEP weights".into(),
            value: w.to_string(),
        });
    }
    Ok(w)
}

type Points = HashMap<u64, Vec<BigRational>>;

fn hpoint(p: &Param, w: BigRational, points: &Points) -> Result<HPoint<BigRational>, Error> {
    let Param::Ref(id) = p else {
        return Err(Error::Format(
            "a control point should be a reference #id".into(),
        ));
    };
    let x = points
        .get(id)
        .ok_or_else(|| Error::Format(format!("control point #{id} is not a CARTESIAN_POINT")))?;
    Ok(HPoint::from_point(x, &w))
}

/// Homogeneous points of one row, with the row of weights if rational.
fn hrow(
    refs: &Param,
    weights: Option<&Param>,
    points: &Points,
) -> Result<Vec<HPoint<BigRational>>, Error> {
    let refs = list(refs, "control points")?;
    let ws = match weights {
        Some(w) => list(w, "weights")?
            .iter()
            .map(weight)
            .collect::<Result<Vec<_>, _>>()?,
        None => vec![BigRational::one(); refs.len()],
    };
    if ws.len() != refs.len() {
        return Err(Error::Shape(format!(
            "{} control points but {} weights",
            refs.len(),
            ws.len()
        )));
    }
    refs.iter()
        .zip(ws)
        .map(|(r, w)| hpoint(r, w, points))
        .collect()
}

fn build(p: &Pending, points: &Points) -> Result<Nurbs, Error> {
    let leaf = p.name.as_str();
    let rational = |name: &str| p.parts.get(name).and_then(|v| v.first());
    if let Some(base) = p.parts.get(SURFACE) {
        let [du, dv, net, ..] = base.as_slice() else {
            return Err(Error::Format("B_SPLINE_SURFACE needs 7 parameters".into()));
        };
        let (du, dv) = (count(du, "u_degree")?, count(dv, "v_degree")?);
        let rows = list(net, "control_points_list")?;
        let wrows = rational("RATIONAL_B_SPLINE_SURFACE")
            .map(|w| list(w, "weights_data"))
            .transpose()?;
        if wrows.is_some_and(|w| w.len() != rows.len()) {
            return Err(Error::Shape(
                "the weights grid differs from the control net".into(),
            ));
        }
        let hom = rows
            .iter()
            .enumerate()
            .map(|(i, r)| hrow(r, wrows.map(|w| &w[i]), points))
            .collect::<Result<Vec<_>, _>>()?;
        let cv = hom.first().map_or(0, Vec::len);
        let k = p.parts.get("B_SPLINE_SURFACE_WITH_KNOTS");
        let ku = knots(
            leaf,
            du,
            hom.len(),
            k.and_then(|k| Some((k.first()?, k.get(2)?))),
        )?;
        let kv = knots(leaf, dv, cv, k.and_then(|k| Some((k.get(1)?, k.get(3)?))))?;
        return NurbsSurface::new(ku, kv, hom).map(Nurbs::Surface);
    }
    let base = p
        .parts
        .get(CURVE)
        .ok_or_else(|| Error::Format("not a B-spline".into()))?;
    let [d, pts, ..] = base.as_slice() else {
        return Err(Error::Format("B_SPLINE_CURVE needs 5 parameters".into()));
    };
    let d = count(d, "degree")?;
    let hom = hrow(pts, rational("RATIONAL_B_SPLINE_CURVE"), points)?;
    let k = p.parts.get("B_SPLINE_CURVE_WITH_KNOTS");
    let kn = knots(
        leaf,
        d,
        hom.len(),
        k.and_then(|k| Some((k.first()?, k.get(1)?))),
    )?;
    NurbsCurve::new(kn, hom).map(Nurbs::Curve)
}

/// The coordinates of a `CARTESIAN_POINT('name', (x, y, z))`.
fn cartesian(r: &Record) -> Result<Vec<BigRational>, Error> {
    let coords = r
        .params
        .get(1)
        .ok_or_else(|| Error::Format("CARTESIAN_POINT needs coordinates".into()))?;
    let x = numbers(coords, "a coordinate")?;
    if x.is_empty() {
        return Err(Error::Shape("a CARTESIAN_POINT with no coordinates".into()));
    }
    Ok(x)
}

/// Read the B-spline geometry of a STEP file from a stream.
///
/// # Errors
///
/// [`Error::Format`] for malformed exchange syntax (with its line). Unknown
/// or malformed entities are not errors: see [`StepModel`].
pub fn read_step(input: impl BufRead) -> Result<StepModel, Error> {
    let mut reader = Reader::new(input);
    let mut collector = Collector::default();
    while let Some(inst) = reader.next_instance()? {
        collector.add(&inst);
    }
    Ok(collector.finish())
}

/// Gathers the points, B-spline entities and faces of a stream of
/// instances, then converts the B-splines.
#[derive(Default)]
struct Collector {
    model: StepModel,
    points: Points,
    pending: BTreeMap<u64, Pending>,
    faces: Vec<(u64, u64)>,
}

/// Whether `inst` is a (simple) `CARTESIAN_POINT`.
fn is_point(inst: &Instance) -> bool {
    !inst.complex && inst.records[0].name == "CARTESIAN_POINT"
}

impl Collector {
    /// [`Collector::add`] for a whole file's instances, the
    /// `CARTESIAN_POINT`s (most of a model's numbers) parsed on all cores.
    fn add_all(&mut self, insts: &[&Instance]) {
        let points: Vec<(u64, Result<Vec<BigRational>, Error>)> = insts
            .par_iter()
            .filter(|inst| is_point(inst))
            .map(|inst| (inst.id, cartesian(&inst.records[0])))
            .collect();
        for (id, point) in points {
            self.add_point(id, point);
        }
        for inst in insts.iter().filter(|inst| !is_point(inst)) {
            self.add(inst);
        }
    }

    fn add_point(&mut self, id: u64, point: Result<Vec<BigRational>, Error>) {
        match point {
            Ok(x) => {
                self.points.insert(id, x);
            }
            Err(e) => self.model.invalid.push((id, e.to_string())),
        }
    }

    fn add(&mut self, inst: &Instance) {
        let first = &inst.records[0];
        if is_point(inst) {
            return self.add_point(inst.id, cartesian(first));
        }
        let model = &mut self.model;
        if !inst.complex && (first.name == "ADVANCED_FACE" || first.name == "FACE_SURFACE") {
            match first.params.get(2) {
                Some(Param::Ref(s)) => self.faces.push((inst.id, *s)),
                _ => model.invalid.push((
                    inst.id,
                    format!("{} without a surface reference", first.name),
                )),
            }
        } else if let Some((name, parts)) = parts_of(inst) {
            self.pending.insert(inst.id, Pending { name, parts });
        } else {
            let name = if inst.complex {
                format!("({})", inst.record_names())
            } else {
                first.name.clone()
            };
            *model.skipped.entry(name).or_default() += 1;
        }
    }

    fn finish(self) -> StepModel {
        let mut model = self.model;
        let mut face_of: HashMap<u64, Vec<u64>> = HashMap::new();
        for (f, s) in self.faces {
            if self.pending.contains_key(&s) {
                face_of.entry(s).or_default().push(f);
            } else {
                model.other_faces.push((f, s));
            }
        }
        for (id, p) in self.pending {
            match build(&p, &self.points) {
                Ok(nurbs) => model.entities.push(StepEntity {
                    id,
                    name: p.name,
                    nurbs,
                    faces: face_of.remove(&id).unwrap_or_default(),
                }),
                Err(e) => model.invalid.push((id, format!("{}: {e}", p.name))),
            }
        }
        model
    }
}

#[cfg(test)]
mod tests;
