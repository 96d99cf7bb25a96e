//! NURBS in JSON, read exactly: our `"kind": "nurbs-curve"` /
//! `"nurbs-surface"` objects and geomdl's `exchange.export_json` layout.
//!
//! ```text
//! {"kind": "nurbs-curve", "degree": p, "knots": [u_0, …, u_{n+p+1}],
//!  "points": [P_0, …, P_n], "weights": [w_0, …, w_n]}
//! {"kind": "nurbs-surface", "degree": [p, q], "knots": [[u…], [v…]],
//!  "points": [[P_00 … P_0m], …], "weights": same shape}
//! ```
//!
//! `weights` is optional (all 1) and must be positive; `points[i][j]` has
//! `i` along u. Numbers are exact as everywhere (`0.1` is 1/10).
//!
//! geomdl (NURBS-Python) writes `{"shape": {"type": "curve"|"surface",
//! "data": [...]}}`; each datum has `degree`, `knotvector`,
//! `control_points: {points, weights?}` (points Cartesian, unweighted) and,
//! for surfaces, `size` = [count_u, count_v] with the flat point list in
//! u-major order (index `i·count_v + j`). geomdl 5 spells the surface fields
//! `degree_u`, `degree_v`, `knotvector_u`, `knotvector_v`, `size_u`,
//! `size_v`; both spellings are read.

use super::{array, missing, number, point, positive_weight, JsonScalar};
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::nurbs::{Knots, Nurbs, NurbsCurve, NurbsSurface};
use num_rational::BigRational;
use num_traits::One;
use serde_json::{json, Map, Value};

/// Write `n` in our JSON layout (`"kind": "nurbs-curve"` or
/// `"nurbs-surface"`, Cartesian points, weights), which [`read_nurbs`] reads
/// back to an equal value.
///
/// ```
/// use exact_bezier::io::parse_json;
/// use exact_bezier::io::{nurbs_to_json, read_nurbs};
/// let v = parse_json(r#"{"kind": "nurbs-curve", "degree": 1, "knots": [0, 0, "1/2", 1, 1],
///                      "points": [[0, 0], [1, 2], [3, 0]], "weights": [1, "1/3", 1]}"#).unwrap();
/// let n = read_nurbs(&v).unwrap().remove(0);
/// assert_eq!(read_nurbs(&nurbs_to_json(&n)).unwrap(), vec![n]);
/// ```
pub fn nurbs_to_json(n: &Nurbs) -> Value {
    let knots = |k: &Knots| Value::Array(k.knots().iter().map(JsonScalar::to_json).collect());
    // Weights are positive (checked by every constructor from input), so
    // each point projects.
    let cart = |h: &HPoint<BigRational>| {
        let w = h.weight();
        Value::Array(h.weighted().iter().map(|x| (x / w).to_json()).collect())
    };
    let weights = |row: &[HPoint<BigRational>]| {
        Value::Array(row.iter().map(|h| h.weight().to_json()).collect())
    };
    let points = |row: &[HPoint<BigRational>]| Value::Array(row.iter().map(cart).collect());
    match n {
        Nurbs::Curve(c) => json!({
            "kind": "nurbs-curve",
            "degree": c.knots().degree(),
            "knots": knots(c.knots()),
            "points": points(c.control_points()),
            "weights": weights(c.control_points()),
        }),
        Nurbs::Surface(s) => {
            let (u, v) = s.knots();
            json!({
                "kind": "nurbs-surface",
                "degree": [u.degree(), v.degree()],
                "knots": [knots(u), knots(v)],
                "points": s.control_points().iter().map(|r| points(r)).collect::<Vec<_>>(),
                "weights": s.control_points().iter().map(|r| weights(r)).collect::<Vec<_>>(),
            })
        }
    }
}

/// Is `v` a NURBS object this module reads (our kinds or geomdl's layout)?
pub fn is_nurbs(v: &Value) -> bool {
    match v.get("kind").and_then(Value::as_str) {
        Some(k) => k.starts_with("nurbs-"),
        None => v.get("shape").is_some(),
    }
}

/// Every NURBS object in `v` (one of ours, or all of a geomdl file).
///
/// # Errors
///
/// [`Error::Format`] for a missing or mistyped field; the shape, weight,
/// degree and knot errors of [`Knots::new`] and the constructors.
pub fn read_nurbs(v: &Value) -> Result<Vec<Nurbs>, Error> {
    let obj = v
        .as_object()
        .ok_or_else(|| Error::Format(format!("expected a JSON object, found {v}")))?;
    match obj.get("kind").and_then(Value::as_str) {
        Some("nurbs-curve") => Ok(vec![Nurbs::Curve(ours_curve(obj)?)]),
        Some("nurbs-surface") => Ok(vec![Nurbs::Surface(ours_surface(obj)?)]),
        Some(k) => Err(Error::Format(format!(
            "unknown kind {k:?} (expected \"nurbs-curve\" or \"nurbs-surface\")"
        ))),
        None => geomdl(obj),
    }
}

fn field<'a>(obj: &'a Map<String, Value>, name: &str) -> Result<&'a Value, Error> {
    obj.get(name).ok_or_else(|| missing(name))
}

fn count(v: &Value, what: &str) -> Result<usize, Error> {
    v.as_u64()
        .and_then(|d| usize::try_from(d).ok())
        .ok_or_else(|| {
            Error::Format(format!(
                "{what} should be a non-negative integer, found {v}"
            ))
        })
}

fn knot_list(v: &Value, what: &str) -> Result<Vec<BigRational>, Error> {
    array(v, what)?.iter().map(|x| number(x, what)).collect()
}

/// Homogeneous points from Cartesian points and optional weights (all 1).
fn hom_list(
    pts: &[Value],
    weights: Option<&Vec<Value>>,
    label: &str,
) -> Result<Vec<HPoint<BigRational>>, Error> {
    if let Some(w) = weights
        && w.len() != pts.len()
    {
        return Err(Error::Shape(format!(
            "{} control points{label} but {} weights",
            pts.len(),
            w.len()
        )));
    }
    pts.iter()
        .enumerate()
        .map(|(i, p)| {
            let x = point(p, &format!("P_{i}{label}"))?;
            let w = match weights {
                Some(w) => positive_weight(&w[i], format!("w_{i}{label}"))?,
                None => BigRational::one(),
            };
            Ok(HPoint::from_point(&x, &w))
        })
        .collect()
}

fn ours_curve(obj: &Map<String, Value>) -> Result<NurbsCurve<BigRational>, Error> {
    let pts = array(field(obj, "points")?, "points")?;
    let weights = obj
        .get("weights")
        .map(|w| array(w, "weights"))
        .transpose()?;
    let knots = Knots::new(
        count(field(obj, "degree")?, "degree")?,
        knot_list(field(obj, "knots")?, "knots")?,
        pts.len(),
    )?;
    NurbsCurve::new(knots, hom_list(pts, weights, "")?)
}

fn pair<'a>(v: &'a Value, what: &str) -> Result<[&'a Value; 2], Error> {
    match array(v, what)?.as_slice() {
        [a, b] => Ok([a, b]),
        other => Err(Error::Shape(format!(
            "{what} should have 2 entries (u, v), not {}",
            other.len()
        ))),
    }
}

fn ours_surface(obj: &Map<String, Value>) -> Result<NurbsSurface<BigRational>, Error> {
    let [du, dv] = pair(field(obj, "degree")?, "degree")?;
    let [ku, kv] = pair(field(obj, "knots")?, "knots")?;
    let rows = array(field(obj, "points")?, "points")?;
    let wrows = obj
        .get("weights")
        .map(|w| array(w, "weights"))
        .transpose()?;
    if let Some(w) = wrows
        && w.len() != rows.len()
    {
        return Err(Error::Shape(format!(
            "{} rows of points but {} rows of weights",
            rows.len(),
            w.len()
        )));
    }
    let net = rows
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let w = wrows.map(|w| array(&w[i], "weights")).transpose()?;
            hom_list(array(r, "points")?, w, &format!(" in row {i}"))
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let count_v = net.first().map_or(0, Vec::len);
    let u = Knots::new(count(du, "degree")?, knot_list(ku, "knots")?, net.len())?;
    let v = Knots::new(count(dv, "degree")?, knot_list(kv, "knots")?, count_v)?;
    NurbsSurface::new(u, v, net)
}

fn geomdl(obj: &Map<String, Value>) -> Result<Vec<Nurbs>, Error> {
    let shape = field(obj, "shape")?
        .as_object()
        .ok_or_else(|| Error::Format("geomdl \"shape\" should be an object".into()))?;
    let kind = field(shape, "type")?
        .as_str()
        .unwrap_or_default()
        .to_owned();
    array(field(shape, "data")?, "data")?
        .iter()
        .enumerate()
        .map(|(k, d)| {
            let d = d
                .as_object()
                .ok_or_else(|| Error::Format(format!("geomdl datum {k} is not an object")))?;
            match kind.as_str() {
                "curve" => geomdl_curve(d).map(Nurbs::Curve),
                "surface" => geomdl_surface(d).map(Nurbs::Surface),
                other => Err(Error::Format(format!(
                    "geomdl shape type {other:?} (expected \"curve\" or \"surface\")"
                ))),
            }
            .map_err(|e| Error::Format(format!("geomdl datum {k}: {e}")))
        })
        .collect()
}

/// geomdl's `control_points: {points, weights?}`.
fn geomdl_points(d: &Map<String, Value>) -> Result<Vec<HPoint<BigRational>>, Error> {
    let cp = field(d, "control_points")?;
    let pts = array(
        cp.get("points")
            .ok_or_else(|| missing("control_points.points"))?,
        "points",
    )?;
    let w = cp.get("weights").map(|w| array(w, "weights")).transpose()?;
    hom_list(pts, w, "")
}

fn geomdl_curve(d: &Map<String, Value>) -> Result<NurbsCurve<BigRational>, Error> {
    let ctrl = geomdl_points(d)?;
    let knots = Knots::new(
        count(field(d, "degree")?, "degree")?,
        knot_list(field(d, "knotvector")?, "knotvector")?,
        ctrl.len(),
    )?;
    NurbsCurve::new(knots, ctrl)
}

/// A geomdl surface field in either spelling: `name: [u, v]` or
/// `name_u`, `name_v`.
fn either<'a>(d: &'a Map<String, Value>, name: &str) -> Result<[&'a Value; 2], Error> {
    match d.get(name) {
        Some(v) => pair(v, name),
        None => Ok([
            field(d, &format!("{name}_u"))?,
            field(d, &format!("{name}_v"))?,
        ]),
    }
}

fn geomdl_surface(d: &Map<String, Value>) -> Result<NurbsSurface<BigRational>, Error> {
    let [du, dv] = either(d, "degree")?;
    let [ku, kv] = either(d, "knotvector")?;
    let [su, sv] = either(d, "size")?;
    let (su, sv) = (count(su, "size")?, count(sv, "size")?);
    let flat = geomdl_points(d)?;
    if su.checked_mul(sv) != Some(flat.len()) {
        return Err(Error::Shape(format!(
            "size {su}×{sv} but {} control points",
            flat.len()
        )));
    }
    let net: Vec<Vec<HPoint<BigRational>>> = flat.chunks(sv.max(1)).map(<[_]>::to_vec).collect();
    let u = Knots::new(count(du, "degree")?, knot_list(ku, "knotvector")?, su)?;
    let v = Knots::new(count(dv, "degree")?, knot_list(kv, "knotvector")?, sv)?;
    NurbsSurface::new(u, v, net)
}
