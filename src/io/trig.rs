//! JSON for trigonometric patches (source 002): kinds `"trig-curve"` and
//! `"trig-rect"`, read exactly like the rest of the interchange format.
//!
//! ```text
//! {"kind": "trig-curve", "alpha": 1, "points": [P0, P1, P2, P3]}
//! {"kind": "trig-rect", "alpha": [α1, α2], "points": [[P00, …, P03], …, [P30, …, P33]]}
//! ```
//!
//! `points[i][j]` is `Pᵢⱼ` (`i` the u index); a single number as the
//! `"alpha"` of a trig-rect means `α1 = α2`. Every number is read exactly.
//! Any α is accepted (the basis is non-negative, so the convex-hull
//! property holds, exactly for α ∈ [0, 2]).
//!
//! Reference: source 002 Definitions 2–3; the format is that of
//! docs/FORMAT.md (`trig-curve` and `trig-rect`).

use crate::error::Error;
use crate::io::{array, field_array, missing, number, parse_json, point_to_json, JsonScalar};
use crate::trig::curve::TrigCurve;
use crate::trig::surface::TrigRect;
use crate::trig::TrigPatch;
use num_rational::BigRational;
use serde_json::{json, Map, Value};

fn points(v: &Value, what: &str) -> Result<Vec<Vec<BigRational>>, Error> {
    array(v, what)?
        .iter()
        .map(|p| array(p, what)?.iter().map(|x| number(x, what)).collect())
        .collect()
}

fn kind(v: &Value) -> Option<&str> {
    v.get("kind").and_then(Value::as_str)
}

/// Read one trigonometric patch from its JSON object (`"kind"`
/// `"trig-curve"` or `"trig-rect"`, `alpha`, `points`).
///
/// # Errors
///
/// As [`read_trig_patches`], for one object.
pub fn trig_patch_from_value(v: &Value) -> Result<TrigPatch<BigRational>, Error> {
    let obj = v
        .as_object()
        .ok_or_else(|| Error::Format(format!("expected a JSON object, found {v}")))?;
    read_one(obj)
}

fn read_one(obj: &Map<String, Value>) -> Result<TrigPatch<BigRational>, Error> {
    let alpha = obj.get("alpha").ok_or_else(|| missing("alpha"))?;
    let pts = obj.get("points");
    match obj.get("kind").and_then(Value::as_str) {
        Some("trig-curve") => {
            let a = number(alpha, "alpha")?;
            let p = pts.ok_or_else(|| missing("points"))?;
            return TrigCurve::new(points(p, "points")?, a).map(TrigPatch::Curve);
        }
        Some("trig-rect") => {}
        other => {
            return Err(Error::Format(format!(
                "unknown kind {other:?} (expected \"trig-curve\" or \"trig-rect\")"
            )))
        }
    }
    let [a1, a2] = match alpha {
        Value::Array(a) if a.len() == 2 => [number(&a[0], "alpha")?, number(&a[1], "alpha")?],
        Value::Array(a) => {
            return Err(Error::Shape(format!(
                "a trig-rect takes one alpha or two [α1, α2], not {}",
                a.len()
            )))
        }
        single => {
            let a: BigRational = number(single, "alpha")?;
            [a.clone(), a]
        }
    };
    let rows = field_array(obj, "points")?
        .iter()
        .enumerate()
        .map(|(i, row)| points(row, &format!("row {i} of points")))
        .collect::<Result<Vec<_>, _>>()?;
    TrigRect::new(rows, [a1, a2]).map(TrigPatch::Rect)
}

/// Read trigonometric patches from JSON text (one object or an array):
/// `Ok(None)` when no element has a trig kind (the text is for
/// [`read_patches`](crate::io::read_patches)).
///
/// # Errors
///
/// [`Error::Format`] for malformed JSON, missing fields or a file mixing trig
/// and other kinds; [`Error::BadNumber`] for inexact numbers;
/// [`Error::Shape`] for a net that is not 4 (× 4) points of one dimension.
///
/// # Examples
///
/// ```
/// use exact_bezier::{ratio, io::read_trig_patches, trig::TrigParam, trig::TrigPatch};
/// let text = r#"{"kind": "trig-curve", "alpha": "1/2", "points": [[0], [1], [2], [3]]}"#;
/// let v = read_trig_patches(text).unwrap().unwrap();
/// let TrigPatch::Curve(c) = &v[0] else { panic!() };
/// assert_eq!(c.alpha(), &ratio(1, 2));
/// assert!(read_trig_patches(r#"{"kind": "curve", "points": [[0]]}"#).unwrap().is_none());
/// ```
pub fn read_trig_patches(text: &str) -> Result<Option<Vec<TrigPatch<BigRational>>>, Error> {
    let v = parse_json(text)?;
    let items = match &v {
        Value::Array(items) => items.clone(),
        _ => vec![v],
    };
    let is_trig = |x: &Value| kind(x).is_some_and(|k| k.starts_with("trig-"));
    let trig = items.iter().filter(|x| is_trig(x)).count();
    if trig == 0 {
        return Ok(None);
    }
    if trig != items.len() {
        return Err(Error::Format(
            "a file cannot mix trig-curve/trig-rect with other kinds".into(),
        ));
    }
    items
        .iter()
        .enumerate()
        .map(|(k, item)| {
            trig_patch_from_value(item).map_err(|e| Error::Format(format!("element {k}: {e}")))
        })
        .collect::<Result<Vec<_>, _>>()
        .map(Some)
}

/// Write a trigonometric patch as JSON (`kind`, `alpha`, `points`).
///
/// ```
/// use exact_bezier::{ratio, io::read_trig_patches, io::trig_patch_to_json, trig::TrigCurve, trig::TrigPatch};
/// let c = TrigCurve::new((0..4).map(|i| vec![ratio(i, 3)]).collect(), ratio(3, 2)).unwrap();
/// let text = trig_patch_to_json(&TrigPatch::Curve(c.clone())).to_string();
/// assert_eq!(read_trig_patches(&text).unwrap().unwrap(), vec![TrigPatch::Curve(c)]);
/// ```
pub fn trig_patch_to_json<T: JsonScalar>(p: &TrigPatch<T>) -> Value {
    let pts = |row: &[Vec<T>]| Value::Array(row.iter().map(|q| point_to_json(q)).collect());
    match p {
        TrigPatch::Curve(c) => json!({
            "kind": "trig-curve",
            "alpha": c.alpha().to_json(),
            "points": pts(c.points()),
        }),
        TrigPatch::Rect(r) => json!({
            "kind": "trig-rect",
            "alpha": point_to_json(r.alpha()),
            "points": Value::Array(r.points().iter().map(|row| pts(row)).collect()),
        }),
    }
}
