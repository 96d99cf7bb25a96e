//! The file's own surface parameters `(u, v)` of points on an elementary
//! surface (ISO 10303-42 §4.4.10–§4.4.15), to trim the curves of its
//! parameter plane (`PCURVE`s) at an edge's vertices.
//!
//! With `(a, b, c)` the frame coordinates `((P − C)·x̂, (P − C)·ŷ, (P − C)·ẑ)`
//! of the point `P` (exact) and angles in the context's plane angle unit:
//!
//! ```text
//! plane      u = a,                 v = b
//! cylinder   u = atan2(b, a),       v = c
//! cone       u = atan2(b, a),       v = c
//! sphere     u = atan2(b, a),       v = atan2(c, √(a² + b²))
//! torus      u = atan2(b, a),       v = atan2(c, √(a² + b²) − R)
//!            (a degenerate torus, r > R, also: u + ½ turn, atan2(c, −√(a² + b²) − R))
//! ```
//!
//! (the inverses of the parameterizations of [`crate::analytic`]'s
//! surfaces). Lengths are exact; angles are transcendental in general and
//! are located in `f64` (the curve pieces cut there are still exactly the
//! curve's). An angle is defined up to whole turns: [`Parameter::Located`]
//! carries the period, and the caller picks the turn.

use super::{entity, placement, Context, Error};
use crate::algebra::scalar::{Field, Ordered, Roots};
use crate::analytic::{AngleUnit, Frame};

/// One surface parameter of a point.
#[derive(Clone, Debug, PartialEq)]
pub enum Parameter<T> {
    /// A length, exactly: a plane's `u` and `v`, a cylinder's or cone's `v`.
    Exact(T),
    /// A parameter located in `f64`: an angle in the context's unit, with
    /// the period (one turn, in the unit) when it is periodic (all but a
    /// sphere's latitude); or a B-spline surface's knot parameter found by
    /// [`nearest_parameters`](crate::nurbs::nearest_parameters).
    Located {
        /// The value (an angle is in `(−½, ½]` turn).
        value: f64,
        /// One turn, in the unit, or `None` (not periodic).
        period: Option<f64>,
    },
}

/// The kinds of elementary surface whose parameters are known in closed form.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Plane,
    /// A cylinder or a cone: `v` is the height along the axis.
    Axial,
    Sphere,
    /// With its major and minor radii.
    Torus {
        major: f64,
        minor: f64,
    },
}

/// The parameter map of one elementary surface.
#[derive(Clone, Debug)]
pub struct SurfaceParameters<T> {
    frame: Frame<T>,
    kind: Kind,
    angle_unit: AngleUnit,
}

/// The parameter map of the surface `id`, `None` when it is not a plane,
/// cylinder, cone, sphere or torus (a B-spline surface, a swept surface:
/// their parameters need an inversion, not done here).
///
/// # Errors
///
/// [`Error::Format`] for a malformed entity; those of
/// [`Frame::from_placement`].
pub fn surface_parameters<T: Field + Ordered + Roots>(
    ctx: &Context<'_, T>,
    id: u64,
) -> Result<Option<SurfaceParameters<T>>, Error> {
    let Some(e) = entity(ctx.table, id)? else {
        return Ok(None);
    };
    let kind = match e.rec.name.as_str() {
        "PLANE" => Kind::Plane,
        "CYLINDRICAL_SURFACE" | "CONICAL_SURFACE" => Kind::Axial,
        "SPHERICAL_SURFACE" => Kind::Sphere,
        "TOROIDAL_SURFACE" | "DEGENERATE_TOROIDAL_SURFACE" => Kind::Torus {
            major: e.number::<T>(2)?.to_f64(),
            minor: e.number::<T>(3)?.to_f64(),
        },
        _ => return Ok(None),
    };
    Ok(Some(SurfaceParameters {
        frame: placement(ctx.table, e.reference(1)?)?,
        kind,
        angle_unit: ctx.angle_unit.clone(),
    }))
}

impl<T: Field + Ordered> SurfaceParameters<T> {
    /// The parameters `(u, v)` of the point `p` (3D), by the table in the
    /// module docs; on a degenerate torus (minor radius over major) also
    /// the second pair `(u + ½ turn, atan2(c, −√(a² + b²) − R))`, where the
    /// point lies on the part with `R + r cos v < 0`.
    ///
    /// ```
    /// use exact_bezier::step::geometry::{surface_parameters, Context, Parameter, Table};
    /// use exact_bezier::step::parser::Reader;
    /// use exact_bezier::{analytic::AngleUnit, ratio, BigRational};
    /// let data = "DATA;#1=CARTESIAN_POINT('',(0.,0.,0.));#2=DIRECTION('',(0.,0.,1.));\
    ///     #3=DIRECTION('',(1.,0.,0.));#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);\
    ///     #5=CYLINDRICAL_SURFACE('',#4,2.);ENDSEC;";
    /// let mut reader = Reader::new(data.as_bytes());
    /// let mut table = Table::default();
    /// while let Some(i) = reader.next_instance().unwrap() {
    ///     table.insert(i.id, i);
    /// }
    /// let ctx = Context::<BigRational> { table: &table, angle_unit: AngleUnit::radian(), bspline_curve: None };
    /// let s = surface_parameters(&ctx, 5).unwrap().unwrap();
    /// let [[u, v]] = &s.of(&[ratio(0, 1), ratio(2, 1), ratio(7, 2)])[..] else { panic!() };
    /// // A quarter turn about ẑ, at height 7/2.
    /// let Parameter::Located { value, period } = u else { panic!() };
    /// assert!((value - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
    /// assert_eq!(*period, Some(2.0 * std::f64::consts::PI));
    /// assert_eq!(*v, Parameter::Exact(ratio(7, 2)));
    /// ```
    pub fn of(&self, p: &[T]) -> Vec<[Parameter<T>; 2]> {
        let [a, b, c] = self.frame.coords(p);
        if self.kind == Kind::Plane {
            return vec![[Parameter::Exact(a), Parameter::Exact(b)]];
        }
        let (af, bf, cf) = (a.to_f64(), b.to_f64(), c.to_f64());
        let turn = self.in_unit(std::f64::consts::TAU);
        let angle = |radians: f64, period| Parameter::Located {
            value: self.in_unit(radians),
            period,
        };
        let u = angle(bf.atan2(af), Some(turn));
        match self.kind {
            Kind::Sphere => vec![[u, angle(cf.atan2(af.hypot(bf)), None)]],
            Kind::Torus { major, minor } => {
                let rho = af.hypot(bf);
                let mut out = vec![[u, angle(cf.atan2(rho - major), Some(turn))]];
                if minor > major {
                    let opposite = angle((-bf).atan2(-af), Some(turn));
                    out.push([opposite, angle(cf.atan2(-rho - major), Some(turn))]);
                }
                out
            }
            _ => vec![[u, Parameter::Exact(c)]],
        }
    }

    /// An angle in radians in the context's unit.
    fn in_unit(&self, radians: f64) -> f64 {
        radians / self.angle_unit.to_radians_f64(1.0)
    }
}
