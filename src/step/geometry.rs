//! The analytic geometry entities of a STEP file (ISO 10303-42 §4.4) as
//! exact rational Bézier pieces, read from the parsed instances
//! ([`parser::Instance`](super::parser::Instance)) by id.
//!
//! The instances are looked up in a [`Table`] (a `HashMap` of the DATA
//! section by id), held in a [`Context`] with the model's plane angle
//! unit and, optionally, a reader of B-spline curves (B-spline entities are
//! read by [`read_step`](super::read_step); the swept curve of an extrusion
//! or revolution and the basis of a trimmed curve may be one). Two entry
//! points: [`curve_pieces`] and [`surface_pieces`]; [`surface_parameters`]
//! locates points in an elementary surface's parameter plane. Every number is read
//! exactly with [`parse_rational`]; directions are normalised exactly
//! ([`Frame::from_placement`]), so `T` needs exact square roots for general
//! files: [`RealAlgebraic`](crate::algebra::RealAlgebraic).
//!
//! | entity | attributes read (after the name) |
//! | --- | --- |
//! | `CARTESIAN_POINT` | coordinates |
//! | `DIRECTION` | direction ratios |
//! | `VECTOR` | orientation, magnitude (`V = magnitude · d/|d|`) |
//! | `AXIS1_PLACEMENT` | location, axis (`$`: z) |
//! | `AXIS2_PLACEMENT_2D` / `_3D` | location, (axis,) ref_direction (`$`: ISO defaults) |
//! | `LINE` | pnt, dir (a `VECTOR`) |
//! | `CIRCLE`, `ELLIPSE` | position (2D or 3D placement), radius / semi_axis_1, semi_axis_2 |
//! | `POLYLINE` | points |
//! | `TRIMMED_CURVE` | basis_curve, trim_1, trim_2, sense_agreement, master_representation |
//! | `PLANE` | position |
//! | `CYLINDRICAL_SURFACE`, `SPHERICAL_SURFACE` | position, radius |
//! | `CONICAL_SURFACE` | position, radius, semi_angle |
//! | `TOROIDAL_SURFACE`, `DEGENERATE_TOROIDAL_SURFACE` | position, major_radius, minor_radius (, select_outer: the same pieces) |
//! | `SURFACE_OF_LINEAR_EXTRUSION` | swept_curve, extrusion_axis (a `VECTOR`) |
//! | `SURFACE_OF_REVOLUTION` | swept_curve, axis_position (an `AXIS1_PLACEMENT`) |
//!
//! A malformed entity is an [`Error::Format`] naming its id and type; a
//! curve or surface that is not rational (`OFFSET_SURFACE`, `OFFSET_CURVE_3D`,
//! …) is [`Curve::Unsupported`] / [`Surface::Unsupported`] with its name.

use super::parser::{Instance, Param, Record};
use crate::algebra::parse_rational;
use crate::algebra::scalar::{Field, Ordered, Roots};
use crate::analytic::trim::dyadic;
use crate::analytic::{
    circle, cone, cone_slope, covering_range, ellipse, extrusion, line_segment, locate_vertex,
    plane, polyline, revolution, sphere, split_between, torus, AngleUnit, ClosedForm, Frame,
    Frame2, Implicit, Unbounded,
};
use crate::analytic::{cross, dot};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::rect::RectPatch;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::collections::HashMap;

mod parameters;
pub use parameters::{surface_parameters, Parameter, SurfaceParameters};

/// The DATA section's instances by id, under a fast hash of the ids
/// (`foldhash`, randomly seeded like std's: crafted ids do not collide).
pub type Table = HashMap<u64, Instance, foldhash::fast::RandomState>;

/// A reader of B-spline curve entities by id, as exact pieces in order.
pub type BSplineCurves<'a, T> = &'a dyn Fn(u64) -> Result<Vec<RationalCurve<T>>, Error>;

/// What the readers need besides an entity id.
#[derive(Clone)]
pub struct Context<'a, T> {
    /// The instances.
    pub table: &'a Table,
    /// The plane angle unit of the representation context.
    pub angle_unit: AngleUnit,
    /// B-spline curves for swept and trimmed curves (`None`: such entities
    /// are answered [`Curve::BSpline`] / [`Surface::Unsupported`]).
    pub bspline_curve: Option<BSplineCurves<'a, T>>,
}

/// A curve entity's exact pieces.
#[derive(Clone, Debug, PartialEq)]
pub struct CurvePieces<T> {
    /// The entity type, e.g. `CIRCLE`.
    pub entity: String,
    /// The pieces, in the curve's direction (a trimmed curve's: from trim_1
    /// to trim_2).
    pub pieces: Vec<RationalCurve<T>>,
    /// Do the pieces form a closed curve (a full circle or ellipse)?
    pub closed: bool,
    /// For a `TRIMMED_CURVE`: the exact squared distances of its two trim
    /// points from the curve points chosen (0 for parameter trims).
    pub trim_distance_sq: Option<[T; 2]>,
    /// Why the pieces are not exactly the entity, if they are not.
    pub approximate: Option<String>,
}

/// A surface entity's exact pieces.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfacePieces<T> {
    /// The entity type, e.g. `CYLINDRICAL_SURFACE`.
    pub entity: String,
    /// The patches (see [`crate::analytic`] for each type's layout).
    pub patches: Vec<RectPatch<T>>,
    /// Why the pieces are not exactly the entity (a cone's slope), if not.
    pub approximate: Option<String>,
    /// The closed form of an elementary surface (plane, cylinder, cone,
    /// sphere, torus; a cone's slope exact or within a bound), or of a
    /// surface of extrusion recognised as one ([`extruded_closed_form`]).
    pub closed_form: Option<Box<ClosedForm<T>>>,
}

/// What a curve id is.
#[derive(Clone, Debug, PartialEq)]
pub enum Curve<T> {
    /// An analytic curve, as pieces.
    Pieces(CurvePieces<T>),
    /// A B-spline entity (read by [`read_step`](super::read_step)).
    BSpline(u64),
    /// A curve type that is not rational or not read here.
    Unsupported {
        /// The id.
        id: u64,
        /// The entity name.
        name: String,
    },
}

/// What a surface id is.
#[derive(Clone, Debug, PartialEq)]
pub enum Surface<T> {
    /// An analytic surface, as pieces.
    Pieces(SurfacePieces<T>),
    /// A B-spline entity (read by [`read_step`](super::read_step)).
    BSpline(u64),
    /// A surface type that is not rational or not read here.
    Unsupported {
        /// The id.
        id: u64,
        /// The entity name (or why it is not read).
        name: String,
    },
}

/// An entity's record with its id and name, for reading and errors.
struct Ent<'a> {
    id: u64,
    rec: &'a Record,
}

impl<'a> Ent<'a> {
    fn err(&self, msg: impl std::fmt::Display) -> Error {
        Error::Format(format!("#{} {}: {msg}", self.id, self.rec.name))
    }

    fn param(&self, i: usize) -> Result<&'a Param, Error> {
        self.rec
            .params
            .get(i)
            .ok_or_else(|| self.err(format!("attribute {i} is missing")))
    }

    fn reference(&self, i: usize) -> Result<u64, Error> {
        match self.param(i)? {
            Param::Ref(r) => Ok(*r),
            p => Err(self.err(format!("attribute {i} should be a reference, not {p:?}"))),
        }
    }

    fn optional_ref(&self, i: usize) -> Result<Option<u64>, Error> {
        match self.param(i)? {
            Param::Unset => Ok(None),
            _ => self.reference(i).map(Some),
        }
    }

    fn text(&self, i: usize) -> Result<&'a str, Error> {
        match self.param(i)? {
            Param::Number(t) => Ok(t),
            Param::Typed(_, inner) if matches!(inner.as_slice(), [Param::Number(_)]) => {
                match &inner[0] {
                    Param::Number(t) => Ok(t),
                    _ => unreachable!("matched a number"),
                }
            }
            p => Err(self.err(format!("attribute {i} should be a number, not {p:?}"))),
        }
    }

    fn number<T: Field>(&self, i: usize) -> Result<T, Error> {
        let q = parse_rational(self.text(i)?).map_err(|e| self.err(e))?;
        Ok(T::from_rational(&q))
    }

    fn flag(&self, i: usize) -> Result<bool, Error> {
        match self.param(i)? {
            Param::Enum(e) if e == "T" => Ok(true),
            Param::Enum(e) if e == "F" => Ok(false),
            p => Err(self.err(format!("attribute {i} should be .T. or .F., not {p:?}"))),
        }
    }
}

/// The simple instance `id`, or `None` for a complex one.
fn entity(table: &Table, id: u64) -> Result<Option<Ent<'_>>, Error> {
    let inst = table
        .get(&id)
        .ok_or_else(|| Error::Format(format!("#{id} is referenced but not in the file")))?;
    Ok((!inst.complex).then(|| Ent {
        id,
        rec: &inst.records[0],
    }))
}

/// The simple instance `id`, which must be of type `want` (one of).
fn expect<'a>(table: &'a Table, id: u64, want: &[&str]) -> Result<Ent<'a>, Error> {
    match entity(table, id)? {
        Some(e) if want.contains(&e.rec.name.as_str()) => Ok(e),
        Some(e) => Err(e.err(format!("expected {}", want.join(" or ")))),
        None => Err(Error::Format(format!(
            "#{id}: expected {}, found a complex instance",
            want.join(" or ")
        ))),
    }
}

fn is_bspline(inst: &Instance) -> bool {
    inst.records.iter().any(|r| {
        [
            "B_SPLINE_",
            "BEZIER_",
            "UNIFORM_",
            "QUASI_UNIFORM_",
            "RATIONAL_B_SPLINE_",
        ]
        .iter()
        .any(|p| r.name.starts_with(p))
    })
}

fn coordinates<T: Field>(table: &Table, id: u64, name: &str) -> Result<Vec<T>, Error> {
    Ok(rationals(table, id, name)?
        .iter()
        .map(T::from_rational)
        .collect())
}

fn rationals(table: &Table, id: u64, name: &str) -> Result<Vec<BigRational>, Error> {
    let e = expect(table, id, &[name])?;
    match e.param(1)? {
        Param::List(xs) if !xs.is_empty() => xs
            .iter()
            .map(|x| match x {
                Param::Number(t) => parse_rational(t).map_err(|err| e.err(err)),
                p => Err(e.err(format!("a coordinate should be a number, not {p:?}"))),
            })
            .collect(),
        p => Err(e.err(format!("expected a non-empty list of numbers, not {p:?}"))),
    }
}

/// A `CARTESIAN_POINT`'s coordinates, exactly.
///
/// # Errors
///
/// [`Error::Format`] naming the id when it is missing or malformed.
pub fn point<T: Field>(table: &Table, id: u64) -> Result<Vec<T>, Error> {
    coordinates(table, id, "CARTESIAN_POINT")
}

/// A `DIRECTION`'s ratios, exactly, scaled by a positive rational to
/// coprime integers (`(0.6, 0.8, 0)` ↦ `(3, 4, 0)`): the same direction,
/// not normalised, with the smallest numbers for the square roots of the
/// frames built on it.
///
/// # Errors
///
/// As [`point`].
pub fn direction<T: Field>(table: &Table, id: u64) -> Result<Vec<T>, Error> {
    let d = rationals(table, id, "DIRECTION")?;
    let lcm = d.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
    let ints: Vec<BigInt> = d.iter().map(|x| (x * &lcm).to_integer()).collect();
    let gcd = ints.iter().fold(BigInt::zero(), |g, x| g.gcd(x));
    Ok(ints
        .into_iter()
        .map(|x| {
            let x = if gcd.is_zero() { x } else { x / &gcd };
            T::from_rational(&BigRational::from_integer(x))
        })
        .collect())
}

/// A `VECTOR(orientation, magnitude)` as `magnitude · d/|d|`, exact with
/// exact roots.
///
/// # Errors
///
/// As [`point`]; [`Error::NotRational`] without the root in `T`.
pub fn vector<T: Field + Ordered + Roots>(table: &Table, id: u64) -> Result<Vec<T>, Error> {
    let e = expect(table, id, &["VECTOR"])?;
    let d: Vec<T> = direction(table, e.reference(1)?)?;
    let m: T = e.number(2)?;
    let dd = d.iter().fold(T::zero(), |acc, x| acc + &(x.clone() * x));
    if dd.is_zero() {
        return Err(e.err("a zero orientation"));
    }
    let len = dd
        .nth_root(2)
        .ok_or_else(|| Error::NotRational(format!("#{id} VECTOR: |d| is irrational")))?;
    // m/|d| = m·√dd/dd: a division by the rational-valued dd, not by a root.
    let k = m * &len / &dd;
    Ok(d.into_iter().map(|x| x * &k).collect())
}

/// The frame of an `AXIS2_PLACEMENT_3D` or (embedded, with `z = 0` of
/// dimension 2) `AXIS2_PLACEMENT_2D`.
///
/// # Errors
///
/// As [`point`], and those of [`Frame::from_placement`].
pub fn placement<T: Field + Ordered + Roots>(table: &Table, id: u64) -> Result<Frame<T>, Error> {
    let e = expect(table, id, &["AXIS2_PLACEMENT_3D", "AXIS2_PLACEMENT_2D"])?;
    let location: Vec<T> = point(table, e.reference(1)?)?;
    let dir = |i: usize| -> Result<Option<Vec<T>>, Error> {
        e.optional_ref(i)?.map(|r| direction(table, r)).transpose()
    };
    if e.rec.name == "AXIS2_PLACEMENT_2D" {
        let f = Frame2::from_placement(&location, dir(2)?.as_deref()).map_err(|x| e.err(x))?;
        return Ok(Frame {
            origin: f.origin,
            x: f.x,
            y: f.y,
            z: vec![T::zero(), T::zero()],
        });
    }
    let (axis, refd) = (dir(2)?, dir(3)?);
    Frame::from_placement(&location, axis.as_deref(), refd.as_deref()).map_err(|x| e.err(x))
}

/// An `AXIS1_PLACEMENT`'s location and unit axis (`$`: (0, 0, 1)).
///
/// # Errors
///
/// As [`placement`].
pub fn axis1<T: Field + Ordered + Roots>(
    table: &Table,
    id: u64,
) -> Result<(Vec<T>, Vec<T>), Error> {
    let e = expect(table, id, &["AXIS1_PLACEMENT"])?;
    let location: Vec<T> = point(table, e.reference(1)?)?;
    let axis = e
        .optional_ref(2)?
        .map(|r| direction(table, r))
        .transpose()?;
    let f = Frame::from_placement(&location, axis.as_deref(), None).map_err(|x| e.err(x))?;
    Ok((f.origin, f.z))
}

/// A basis curve read for trimming: its pieces and how an ISO parameter
/// maps to a piece position.
struct Basis<T> {
    pieces: Vec<RationalCurve<T>>,
    closed: bool,
    kind: Kind<T>,
    trim_distance_sq: Option<[T; 2]>,
    approximate: Option<String>,
}

enum Kind<T> {
    /// A line segment over `[u0, u1]` of the line's parameter.
    Line([T; 2]),
    /// A circle or ellipse: the parameter is an angle.
    Conic,
    /// A polyline: piece `k` is `[k, k + 1]`.
    Polyline,
    /// A B-spline read by the context: parameters are not mapped.
    Other,
}

/// The pieces of the curve `id`: a `LINE` as one segment whose parameter
/// range covers the projections of `cover` (the points the caller needs on
/// it, e.g. an edge's vertices; `[0, 1]` with none), a `CIRCLE`/`ELLIPSE`
/// as four quarter arcs, a `POLYLINE` as its segments, a `TRIMMED_CURVE`
/// as the exact pieces between its trims (see [`CurvePieces`]). A
/// parameter trim on a circle or ellipse (an angle) is located at the
/// dyadic half-angle tangent `m/2⁴⁰` nearest its `f64` value: the point is
/// exactly on the curve, its parameter within about 2⁻⁴⁰ of the decimal,
/// and the result says so in `approximate`.
///
/// # Errors
///
/// [`Error::Format`] naming the entity for malformed data; the errors of
/// [`Frame::from_placement`] and [`split_between`].
pub fn curve_pieces<T: Field + Ordered + Roots>(
    ctx: &Context<'_, T>,
    id: u64,
    cover: &[Vec<T>],
) -> Result<Curve<T>, Error> {
    match basis(ctx, id, cover, &[], None)? {
        Ok((b, entity)) => Ok(Curve::Pieces(CurvePieces {
            entity,
            pieces: b.pieces,
            closed: b.closed,
            trim_distance_sq: b.trim_distance_sq,
            approximate: b.approximate,
        })),
        Err(other) => Ok(other),
    }
}

type Read<T> = Result<(Basis<T>, String), Curve<T>>;

/// Read a curve as a [`Basis`], or say why not (`Err(Curve::…)`).
/// `params` are line parameters to cover too; `exclude` a direction along
/// which points may be offset (an extrusion's vector).
fn basis<T: Field + Ordered + Roots>(
    ctx: &Context<'_, T>,
    id: u64,
    cover: &[Vec<T>],
    params: &[T],
    exclude: Option<&[T]>,
) -> Result<Read<T>, Error> {
    let table = ctx.table;
    let Some(e) = entity(table, id)? else {
        return bspline_or_unsupported(ctx, id);
    };
    let name = e.rec.name.clone();
    let read = |pieces, closed, kind| {
        let b = Basis {
            pieces,
            closed,
            kind,
            trim_distance_sq: None,
            approximate: None,
        };
        Ok(Ok((b, name.clone())))
    };
    match name.as_str() {
        "LINE" => {
            let p: Vec<T> = point(table, e.reference(1)?)?;
            let v: Vec<T> = vector(table, e.reference(2)?)?;
            let [u0, u1] = line_range(&e, &p, &v, cover, params, exclude)?;
            read(
                vec![line_segment(&p, &v, &u0, &u1)],
                false,
                Kind::Line([u0, u1]),
            )
        }
        "CIRCLE" => {
            let f = placement(table, e.reference(1)?)?;
            read(circle(&f, &e.number(2)?), true, Kind::Conic)
        }
        "ELLIPSE" => {
            let f = placement(table, e.reference(1)?)?;
            read(ellipse(&f, &e.number(2)?, &e.number(3)?), true, Kind::Conic)
        }
        "POLYLINE" => {
            let ids = match e.param(1)? {
                Param::List(xs) => xs.clone(),
                p => return Err(e.err(format!("points should be a list, not {p:?}"))),
            };
            let pts = ids
                .iter()
                .map(|p| match p {
                    Param::Ref(r) => point(table, *r),
                    p => Err(e.err(format!("a point should be a reference, not {p:?}"))),
                })
                .collect::<Result<Vec<Vec<T>>, Error>>()?;
            if pts.len() < 2 {
                return Err(e.err("a polyline needs at least two points"));
            }
            read(polyline(&pts), false, Kind::Polyline)
        }
        "TRIMMED_CURVE" => trimmed(ctx, &e),
        _ => bspline_or_unsupported(ctx, id),
    }
}

/// A B-spline curve through the context's reader, else its id; any other
/// entity: unsupported.
fn bspline_or_unsupported<T: Field>(ctx: &Context<'_, T>, id: u64) -> Result<Read<T>, Error> {
    let inst = &ctx.table[&id];
    if !is_bspline(inst) {
        let name = inst.record_names();
        return Ok(Err(Curve::Unsupported { id, name }));
    }
    match ctx.bspline_curve {
        Some(read) => Ok(Ok((
            Basis {
                pieces: read(id)?,
                closed: false,
                kind: Kind::Other,
                trim_distance_sq: None,
                approximate: None,
            },
            "B_SPLINE_CURVE".into(),
        ))),
        None => Ok(Err(Curve::BSpline(id))),
    }
}

/// The parameter range `[u0, u1]` of a line `p + u·v` covering `cover` and
/// `params`: `u = (P − p)·v' / (v·v')` with `v' = v` or, when points may be
/// offset along `x` (`exclude`), `v' = v − (v·x/|x|²) x` (then the offset
/// does not change `u`). Widened to `[u − 1, u + 1]` for a single value;
/// `[0, 1]` with nothing to cover.
fn line_range<T: Field + Ordered>(
    e: &Ent<'_>,
    p: &[T],
    v: &[T],
    cover: &[Vec<T>],
    params: &[T],
    exclude: Option<&[T]>,
) -> Result<[T; 2], Error> {
    let dot = |a: &[T], b: &[T]| {
        a.iter()
            .zip(b)
            .fold(T::zero(), |s, (x, y)| s + &(x.clone() * y))
    };
    let w: Vec<T> = match exclude {
        Some(x) => {
            let k = dot(v, x) / &dot(x, x);
            v.iter()
                .zip(x)
                .map(|(a, b)| a.clone() - &(k.clone() * b))
                .collect()
        }
        None => v.to_vec(),
    };
    let vw = dot(v, &w);
    if vw.is_zero() {
        return Err(e.err("the line is parallel to the extrusion (or of zero length)"));
    }
    let mut us: Vec<T> = params.to_vec();
    for c in cover {
        let d: Vec<T> = c.iter().zip(p).map(|(a, b)| a.clone() - b).collect();
        us.push(dot(&d, &w) / &vw);
    }
    let Some(first) = us.first().cloned() else {
        return Ok([T::zero(), T::one()]);
    };
    let (lo, hi) = us.into_iter().fold((first.clone(), first), |(lo, hi), u| {
        (
            if u < lo { u.clone() } else { lo },
            if u > hi { u } else { hi },
        )
    });
    Ok(if lo == hi {
        [lo.clone() - &T::one(), hi + &T::one()]
    } else {
        [lo, hi]
    })
}

/// One trim of a `TRIMMED_CURVE`: its point and/or parameter text.
struct Trim<T> {
    point: Option<Vec<T>>,
    param: Option<String>,
}

fn trim_select<T: Field>(table: &Table, e: &Ent<'_>, i: usize) -> Result<Trim<T>, Error> {
    let items = match e.param(i)? {
        Param::List(xs) => xs,
        p => return Err(e.err(format!("trim_{} should be a list, not {p:?}", i - 1))),
    };
    let mut t = Trim {
        point: None,
        param: None,
    };
    for item in items {
        match item {
            Param::Ref(r) => t.point = Some(point(table, *r)?),
            Param::Typed(n, v) if n == "PARAMETER_VALUE" => match v.as_slice() {
                [Param::Number(x)] => t.param = Some(x.clone()),
                _ => return Err(e.err("a PARAMETER_VALUE should hold one number")),
            },
            p => {
                return Err(e.err(format!(
                    "a trim should be a point or a PARAMETER_VALUE, not {p:?}"
                )))
            }
        }
    }
    if t.point.is_none() && t.param.is_none() {
        return Err(e.err(format!("trim_{} is empty", i - 1)));
    }
    Ok(t)
}

/// A `TRIMMED_CURVE`: the basis pieces between the trims (ISO 10303-42
/// §4.4.36: from trim_1 to trim_2, along the basis when sense_agreement,
/// against it otherwise; a point trim is used unless master_representation
/// is `.PARAMETER.` and a parameter is given).
fn trimmed<T: Field + Ordered + Roots>(
    ctx: &Context<'_, T>,
    e: &Ent<'_>,
) -> Result<Read<T>, Error> {
    let trims = [
        trim_select::<T>(ctx.table, e, 2)?,
        trim_select::<T>(ctx.table, e, 3)?,
    ];
    let sense = e.flag(4)?;
    let master = match e.param(5)? {
        Param::Enum(m) => m.clone(),
        p => {
            return Err(e.err(format!(
                "master_representation should be an enumeration, not {p:?}"
            )))
        }
    };
    // Which trims are points (the others are parameters).
    let by_point: Vec<bool> = trims
        .iter()
        .map(|t| t.point.is_some() && (master != "PARAMETER" || t.param.is_none()))
        .collect();
    let cover: Vec<Vec<T>> = trims
        .iter()
        .zip(&by_point)
        .filter(|(_, p)| **p)
        .filter_map(|(t, _)| t.point.clone())
        .collect();
    let params = trims
        .iter()
        .zip(&by_point)
        .filter(|(_, p)| !**p)
        .map(|(t, _)| {
            t.param
                .as_deref()
                .map(parse_rational)
                .expect("a parameter trim")
        })
        .collect::<Result<Vec<_>, Error>>()
        .map_err(|x| e.err(x))?;
    let params: Vec<T> = params.iter().map(T::from_rational).collect();
    let b = match basis(ctx, e.reference(1)?, &cover, &params, None)? {
        Ok((b, _)) => b,
        Err(other) => return Ok(Err(other)),
    };
    let mut approximate = None;
    let mut positions = Vec::new();
    let mut distances = Vec::new();
    for (t, &p) in trims.iter().zip(&by_point) {
        if p {
            let pt = t.point.as_ref().expect("a point trim");
            let (k, s) = locate_vertex(&b.pieces, pt, 0.0);
            let on = b.pieces[k].eval(&s)?;
            let d = pt.iter().zip(&on).fold(T::zero(), |acc, (x, y)| {
                let z = x.clone() - y;
                acc + &(z.clone() * &z)
            });
            distances.push(d);
            positions.push((k, s));
        } else {
            let text = t.param.as_deref().expect("a parameter trim");
            let (pos, why) = param_position(&ctx.angle_unit, &b, e, text)?;
            approximate = approximate.or(why);
            distances.push(T::zero());
            positions.push(pos);
        }
    }
    let n = b.pieces.len();
    let (work, positions): (Vec<RationalCurve<T>>, Vec<(usize, T)>) = if sense {
        (b.pieces, positions)
    } else {
        (
            b.pieces.iter().rev().map(RationalCurve::reverse).collect(),
            positions
                .into_iter()
                .map(|(k, t)| (n - 1 - k, T::one() - &t))
                .collect(),
        )
    };
    let whole = positions[0] == positions[1];
    let (p0, p1) = (&positions[0], &positions[1]);
    let pieces = split_between(&work, (p0.0, &p0.1), (p1.0, &p1.1), whole).map_err(|x| e.err(x))?;
    let distances: [T; 2] = distances.try_into().expect("two trims");
    Ok(Ok((
        Basis {
            pieces,
            closed: whole,
            kind: Kind::Other,
            trim_distance_sq: Some(distances),
            approximate,
        },
        e.rec.name.clone(),
    )))
}

/// The piece position of the ISO parameter `text` on a basis curve, and why
/// it is approximate if it is.
fn param_position<T: Field + Ordered>(
    unit: &AngleUnit,
    b: &Basis<T>,
    e: &Ent<'_>,
    text: &str,
) -> Result<((usize, T), Option<String>), Error> {
    let u: T = T::from_rational(&parse_rational(text).map_err(|x| e.err(x))?);
    let n = b.pieces.len();
    match &b.kind {
        Kind::Line([u0, u1]) => Ok(((0, (u - u0) / &(u1.clone() - u0)), None)),
        Kind::Polyline => {
            // Piece k covers [k, k + 1]; the last piece also takes u = n.
            let mut k = 0;
            while k + 1 < n && u >= T::from_i64(k as i64 + 1) {
                k += 1;
            }
            let t = u - &T::from_i64(k as i64);
            if t < T::zero() || t > T::one() {
                return Err(e.err(format!("parameter {text} is outside the polyline")));
            }
            Ok(((k, t), None))
        }
        Kind::Conic => {
            let quarter = std::f64::consts::FRAC_PI_2;
            let phi = unit.to_radians_f64(u.to_f64()).rem_euclid(4.0 * quarter);
            let k = ((phi / quarter).floor() as usize).min(3);
            let t = ((phi - k as f64 * quarter) / 2.0).tan();
            let why = format!(
                "#{} {}: the angle {text} is taken at the half-angle tangent 2⁻⁴⁰-nearest its f64 value (a point exactly on the curve)",
                e.id, e.rec.name
            );
            Ok(((k, T::from_rational(&dyadic(t))), Some(why)))
        }
        Kind::Other => Err(e.err("a parameter trim of a B-spline basis curve is not mapped")),
    }
}

/// The pieces of the surface `id`, covering the points `boundary` (the
/// control points of the face's bounding edges) in its unbounded directions
/// (see [`covering_range`]; with no points the unbounded ranges are
/// `[0, 1]`). A cone whose semi_angle is not a multiple of 15° has a slope
/// approximated within a stated bound ([`cone_slope`]), said in
/// `approximate`.
///
/// # Errors
///
/// [`Error::Format`] naming the entity for malformed data; those of
/// [`Frame::from_placement`], [`cone_slope`], [`covering_range`].
pub fn surface_pieces<T: Field + Ordered + Roots>(
    ctx: &Context<'_, T>,
    id: u64,
    boundary: &[Vec<T>],
) -> Result<Surface<T>, Error> {
    let table = ctx.table;
    let Some(e) = entity(table, id)? else {
        return Ok(unsupported_surface(table, id));
    };
    let unit_range = || vec![[T::zero(), T::one()], [T::zero(), T::one()]];
    let range = |u: &Unbounded<'_, T>| -> Result<Vec<[T; 2]>, Error> {
        if boundary.is_empty() {
            Ok(unit_range())
        } else {
            covering_range(u, boundary).map_err(|x| e.err(x))
        }
    };
    let pieces = |patches, approximate, closed_form: Option<ClosedForm<T>>| {
        Ok(Surface::Pieces(SurfacePieces {
            entity: e.rec.name.clone(),
            patches,
            approximate,
            closed_form: closed_form.map(Box::new),
        }))
    };
    let exact = |i| Some(ClosedForm::exact(i));
    let frame = || placement::<T>(table, e.reference(1)?);
    match e.rec.name.as_str() {
        "PLANE" => {
            let f = frame()?;
            let r = range(&Unbounded::Plane(&f))?;
            pieces(
                vec![plane(&f, [&r[0][0], &r[0][1]], [&r[1][0], &r[1][1]])],
                None,
                exact(Implicit::Plane { frame: f }),
            )
        }
        "CYLINDRICAL_SURFACE" | "CONICAL_SURFACE" => {
            let f = frame()?;
            let r = range(&Unbounded::Axial(&f))?;
            let v = [&r[0][0], &r[0][1]];
            let radius: T = e.number(2)?;
            if e.rec.name == "CYLINDRICAL_SURFACE" {
                let patches = crate::analytic::cylinder(&f, &radius, v);
                return pieces(
                    patches,
                    None,
                    exact(Implicit::Cylinder { frame: f, radius }),
                );
            }
            let text = e.text(3)?;
            let s = cone_slope::<T>(text, &ctx.angle_unit).map_err(|x| e.err(x))?;
            let why = (!s.exact).then(|| {
                format!(
                    "#{id} CONICAL_SURFACE: tan of the semi_angle {text} is a rational within {} of it",
                    s.error
                )
            });
            let patches = cone(&f, &radius, &s.tan, v);
            let closed_form = ClosedForm {
                implicit: Implicit::Cone {
                    frame: f,
                    radius,
                    slope: s.tan,
                },
                slope_error: (!s.exact).then_some(s.error),
                reversed: false,
            };
            pieces(patches, why, Some(closed_form))
        }
        "SPHERICAL_SURFACE" => {
            let (frame, radius) = (frame()?, e.number(2)?);
            let patches = sphere(&frame, &radius);
            pieces(patches, None, exact(Implicit::Sphere { frame, radius }))
        }
        "TOROIDAL_SURFACE" | "DEGENERATE_TOROIDAL_SURFACE" => {
            let (frame, major, minor) = (frame()?, e.number(2)?, e.number(3)?);
            let patches = torus(&frame, &major, &minor);
            pieces(
                patches,
                None,
                exact(Implicit::Torus {
                    frame,
                    major,
                    minor,
                }),
            )
        }
        "SURFACE_OF_LINEAR_EXTRUSION" => {
            let v: Vec<T> = vector(table, e.reference(2)?)?;
            let curve = match basis(ctx, e.reference(1)?, boundary, &[], Some(&v))? {
                Ok((b, _)) => b.pieces,
                Err(c) => return Ok(swept_unsupported(id, &e, &c)),
            };
            let r = range(&Unbounded::Extrusion {
                curve: &curve,
                vector: &v,
            })?;
            let closed_form = extruded_closed_form(table, e.reference(1)?, &v)?;
            pieces(
                extrusion(&curve, &v, [&r[0][0], &r[0][1]])?,
                None,
                closed_form,
            )
        }
        "SURFACE_OF_REVOLUTION" => {
            let (origin, axis) = axis1::<T>(table, e.reference(2)?)?;
            let swept = e.reference(1)?;
            let cover = revolved_line_cover(table, swept, &origin, &axis, boundary)?;
            let curve = match basis(ctx, swept, &[], &cover, None)? {
                Ok((b, _)) => b.pieces,
                Err(c) => return Ok(swept_unsupported(id, &e, &c)),
            };
            pieces(revolution(&curve, &origin, &axis)?, None, None)
        }
        _ => Ok(unsupported_surface(table, id)),
    }
}

/// The elementary surface that the linear extrusion of the curve `swept`
/// (a `LINE` or `CIRCLE`, or the basis of a `TRIMMED_CURVE` of one) along
/// `v` is, decided exactly; `None` for other curves (a B-spline's, an
/// ellipse's) and for a circle not extruded along its axis (an elliptic
/// cylinder). With `σ(u, w) = C(u) + w·v`, the entity's normal is
/// `σ_u × σ_w = C'(u) × v`:
///
/// - a line `C = p + u·d` (`d × v ≠ 0`) sweeps the plane through `p` with
///   normal `d × v` (the plane's own `ẑ`);
/// - a circle `C = c + r(cos u x̂ + sin u ŷ)` with `v = λẑ` sweeps the
///   cylinder of its frame and radius: `C' × v = λ r (cos u x̂ + sin u ŷ)`,
///   outward (the cylinder's gradient) when `λ > 0`, else reversed.
///
/// # Errors
///
/// [`Error::Format`] for a malformed line or circle.
pub fn extruded_closed_form<T: Field + Ordered + Roots>(
    table: &Table,
    swept: u64,
    v: &[T],
) -> Result<Option<ClosedForm<T>>, Error> {
    let mut id = swept;
    let e = loop {
        let Some(e) = entity(table, id)? else {
            return Ok(None);
        };
        match e.rec.name.as_str() {
            "TRIMMED_CURVE" => id = e.reference(1)?,
            _ => break e,
        }
    };
    match e.rec.name.as_str() {
        "LINE" => {
            let p: Vec<T> = point(table, e.reference(1)?)?;
            let d: Vec<T> = vector(table, e.reference(2)?)?;
            let n = cross(&d, v);
            if p.len() != 3 || n.iter().all(Zero::is_zero) {
                return Ok(None);
            }
            let frame = Frame::from_placement(&p, Some(&n), Some(&d)).map_err(|x| e.err(x))?;
            Ok(Some(ClosedForm::exact(Implicit::Plane { frame })))
        }
        "CIRCLE" => {
            let frame: Frame<T> = placement(table, e.reference(1)?)?;
            let radius: T = e.number(2)?;
            if frame.z.len() != 3 || !cross(&frame.z, v).iter().all(Zero::is_zero) {
                return Ok(None);
            }
            let reversed = dot(&frame.z, v) < T::zero();
            Ok(Some(ClosedForm {
                implicit: Implicit::Cylinder { frame, radius },
                slope_error: None,
                reversed,
            }))
        }
        _ => Ok(None),
    }
}

/// For a revolved `LINE`, the line parameters covering the boundary points
/// ([`Unbounded::RevolvedLine`]); nothing for other curves.
fn revolved_line_cover<T: Field + Ordered + Roots>(
    table: &Table,
    swept: u64,
    origin: &[T],
    axis: &[T],
    boundary: &[Vec<T>],
) -> Result<Vec<T>, Error> {
    let Some(line) = entity(table, swept)?.filter(|l| l.rec.name == "LINE") else {
        return Ok(Vec::new());
    };
    if boundary.is_empty() {
        return Ok(Vec::new());
    }
    let p: Vec<T> = point(table, line.reference(1)?)?;
    let d: Vec<T> = vector(table, line.reference(2)?)?;
    let u = Unbounded::RevolvedLine {
        point: &p,
        direction: &d,
        origin,
        axis,
    };
    let [r] = <[[T; 2]; 1]>::try_from(covering_range(&u, boundary).map_err(|x| line.err(x))?)
        .expect("one range");
    Ok(r.to_vec())
}

fn swept_unsupported<T>(id: u64, e: &Ent<'_>, c: &Curve<T>) -> Surface<T> {
    let what = match c {
        Curve::BSpline(b) => format!("B-spline curve #{b} (no B-spline reader in the context)"),
        Curve::Unsupported { id, name } => format!("{name} #{id}"),
        Curve::Pieces(_) => "curve".into(),
    };
    Surface::Unsupported {
        id,
        name: format!("{} of a {what}", e.rec.name),
    }
}

fn unsupported_surface<T>(table: &Table, id: u64) -> Surface<T> {
    let inst = &table[&id];
    if is_bspline(inst) {
        return Surface::BSpline(id);
    }
    let name = inst.record_names();
    Surface::Unsupported { id, name }
}
