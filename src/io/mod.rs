//! JSON interchange (docs/FORMAT.md): one object per curve or patch, or an
//! array of them; every number read **exactly** from its text.
//!
//! ```text
//! {"kind": "curve", "degree": 3, "points": [[0,0],[1,2],[3,2],[4,0]], "weights": [1, "1/3", "1/3", 1]}
//! {"kind": "rect", "degree": [m, n], "points": [[P_00 … P_0n], …, [P_m0 … P_mn]], "weights": same shape}
//! {"kind": "tri", "degree": n, "points": [[P_{0,0,n} … P_{n,0,0}], …, [P_{0,n,0}]], "weights": same shape}
//! ```
//!
//! Numbers may be JSON numbers (`0.885` is 885/1000, `1e-3` is 1/1000) or
//! strings (`"1/3"`, `"-2.5"`). `weights` is optional (all 1). Weights must be
//! positive. Degrees are limited to [`MAX_DEGREE`](crate::limits::MAX_DEGREE).

mod results;
pub mod trig;

pub use crate::algebra::parse_rational;
pub use results::{coincidence_to_json, standard_to_json};

pub use trig::{read_trig_patches, trig_patch_from_value, trig_patch_to_json};

use crate::algebra::poly::Poly;
use crate::algebra::scalar::{Field, Scalar};
use crate::algebra::ExactNumber;
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::limits::check_degree;
use crate::rect::RectPatch;
use crate::tri::TriPatch;
use num_rational::BigRational;
use serde_json::{Map, Number, Value};

mod brep;
mod duplicate_keys;
mod model;
mod nurbs;
pub use brep::{
    brep_model_json, brep_to_json, brep_to_lines, edge_to_json, face_to_json, BrepLines,
    PieceWriter,
};
pub use model::{
    audit_to_json, brep_audit_to_json, is_step, origin_from_json, origin_to_json, piece_to_json,
    read_exact_model, read_model,
};
pub use nurbs::{is_nurbs, nurbs_to_json, read_nurbs};
mod fast;
mod stream;
pub use fast::read_small_patch;
pub use stream::{for_each_chunk, Record};

use crate::patch::Patch;

/// `v` (a JSON number or a string) as an exact number; `what` names it in
/// the error.
pub(crate) fn number<T: ExactNumber>(v: &Value, what: &str) -> Result<T, Error> {
    match v {
        Value::Number(n) => T::from_text(&n.to_string()),
        Value::String(s) => T::from_text(s),
        _ => Err(Error::Format(format!(
            "{what} should be a number, found {v}"
        ))),
    }
}

/// `v` as a JSON array; `what` names it in the error.
pub(crate) fn array<'a>(v: &'a Value, what: &str) -> Result<&'a Vec<Value>, Error> {
    v.as_array()
        .ok_or_else(|| Error::Format(format!("{what} should be an array, found {v}")))
}

pub(crate) fn point<T: ExactNumber>(v: &Value, what: &str) -> Result<Vec<T>, Error> {
    let coords = array(v, what)?;
    if coords.is_empty() {
        return Err(Error::Shape(format!("{what} has no coordinates")));
    }
    crate::limits::check_dimension(coords.len())?;
    coords.iter().map(|c| number(c, what)).collect()
}

pub(crate) fn positive_weight<T: ExactNumber>(v: &Value, index: String) -> Result<T, Error> {
    let w: T = number(v, &format!("weight {index}"))?;
    if w <= T::zero() {
        return Err(Error::Weight {
            index,
            value: w.to_string(),
        });
    }
    Ok(w)
}

fn declared_degree(obj: &Map<String, Value>) -> Option<&Value> {
    obj.get("degree")
}

/// The field `name` of `obj`, an array.
pub(crate) fn field_array<'a>(
    obj: &'a Map<String, Value>,
    name: &str,
) -> Result<&'a Vec<Value>, Error> {
    array(obj.get(name).ok_or_else(|| missing(name))?, name)
}

/// The `points` of a curve or tri patch (`what`: "a curve") and its degree
/// `n = points.len() − 1`, checked against [`MAX_DEGREE`](crate::limits::MAX_DEGREE) and against the
/// declared `degree`; `mismatch(d, len)` words the error for a declared
/// `d + 1` (`"?"` if `d` is not a count) where `len` entries were given.
fn points_of_degree<'a>(
    obj: &'a Map<String, Value>,
    what: &str,
    mismatch: impl Fn(&Value, String, usize) -> String,
) -> Result<(&'a Vec<Value>, usize), Error> {
    let pts = field_array(obj, "points")?;
    if pts.is_empty() {
        return Err(Error::Shape(format!(
            "{what} needs at least one control point"
        )));
    }
    let n = pts.len() - 1;
    check_degree(n)?;
    if let Some(d) = declared_degree(obj)
        && d.as_u64() != Some(n as u64)
    {
        let want = d.as_u64().map_or("?".into(), |d| (d + 1).to_string());
        return Err(Error::Shape(mismatch(d, want, pts.len())));
    }
    Ok((pts, n))
}

fn read_curve<T: ExactNumber>(obj: &Map<String, Value>) -> Result<RationalCurve<T>, Error> {
    let (pts, n) = points_of_degree(obj, "a curve", |d, want, len| {
        format!("a degree {d} curve should have {want} control points, not {len}")
    })?;
    let points = pts
        .iter()
        .enumerate()
        .map(|(i, p)| point(p, &format!("P_{i}")))
        .collect::<Result<Vec<_>, _>>()?;
    let weights = match obj.get("weights") {
        None => vec![T::one(); pts.len()],
        Some(w) => {
            let w = array(w, "weights")?;
            if w.len() != pts.len() {
                return Err(Error::Shape(format!(
                    "a degree {n} curve needs {} weights, not {}",
                    n + 1,
                    w.len()
                )));
            }
            w.iter()
                .enumerate()
                .map(|(i, x)| positive_weight(x, format!("w_{i}")))
                .collect::<Result<_, _>>()?
        }
    };
    RationalCurve::new(points, weights)
}

/// Rows of exact Cartesian points.
type PointGrid<T> = Vec<Vec<Vec<T>>>;
/// Rows of exact weights.
type WeightGrid<T> = Vec<Vec<T>>;

/// Read a grid of rows whose lengths are given by `row_len(j)`.
fn read_grid<T: ExactNumber>(
    obj: &Map<String, Value>,
    rows: usize,
    row_len: impl Fn(usize) -> usize,
    label: impl Fn(usize, usize) -> String,
) -> Result<(PointGrid<T>, WeightGrid<T>), Error> {
    let pts = field_array(obj, "points")?;
    if pts.len() != rows {
        return Err(Error::Shape(format!(
            "the control net should have {rows} rows, not {}",
            pts.len()
        )));
    }
    let weights_json = match obj.get("weights") {
        Some(w) => Some(array(w, "weights")?),
        None => None,
    };
    if let Some(w) = weights_json
        && w.len() != rows
    {
        return Err(Error::Shape(format!(
            "the weights should have {rows} rows, not {}",
            w.len()
        )));
    }
    let mut points = Vec::with_capacity(rows);
    let mut weights = Vec::with_capacity(rows);
    for (a, row) in pts.iter().enumerate() {
        let row = array(row, &format!("row {a} of points"))?;
        if row.len() != row_len(a) {
            return Err(Error::Shape(format!(
                "row {a} of the control net should have {} points, not {}",
                row_len(a),
                row.len()
            )));
        }
        points.push(
            row.iter()
                .enumerate()
                .map(|(b, p)| point(p, &format!("P_{}", label(a, b))))
                .collect::<Result<Vec<_>, _>>()?,
        );
        weights.push(match weights_json {
            None => vec![T::one(); row.len()],
            Some(w) => {
                let wr = array(&w[a], &format!("row {a} of weights"))?;
                if wr.len() != row.len() {
                    return Err(Error::Shape(format!(
                        "row {a} of the weights should have {} entries, not {}",
                        row.len(),
                        wr.len()
                    )));
                }
                wr.iter()
                    .enumerate()
                    .map(|(b, x)| positive_weight(x, format!("w_{}", label(a, b))))
                    .collect::<Result<_, _>>()?
            }
        });
    }
    Ok((points, weights))
}

fn read_rect<T: ExactNumber>(obj: &Map<String, Value>) -> Result<RectPatch<T>, Error> {
    let pts = field_array(obj, "points")?;
    let rows = pts.len();
    let cols = pts.first().and_then(Value::as_array).map_or(0, Vec::len);
    if rows == 0 || cols == 0 {
        return Err(Error::Shape(
            "a rect patch needs at least one control point".into(),
        ));
    }
    let (m, n) = (rows - 1, cols - 1);
    check_degree(m)?;
    check_degree(n)?;
    if let Some(d) = declared_degree(obj) {
        let want = Value::from(vec![m as u64, n as u64]);
        if *d != want {
            return Err(Error::Shape(format!(
                "a rect patch of degree {d} does not match its {rows}×{cols} control net (degree [{m}, {n}])"
            )));
        }
    }
    let (p, w) = read_grid(obj, rows, |_| cols, |i, j| format!("{{{i},{j}}}"))?;
    RectPatch::new(p, w)
}

fn read_tri<T: ExactNumber>(obj: &Map<String, Value>) -> Result<TriPatch<T>, Error> {
    let (_, n) = points_of_degree(obj, "a tri patch", |d, want, len| {
        format!("a tri patch of degree {d} needs {want} rows of points, not {len}")
    })?;
    let (p, w) = read_grid(
        obj,
        n + 1,
        |j| n - j + 1,
        |j, i| format!("{{{i},{j},{}}}", n - i - j),
    )?;
    TriPatch::new(p, w)
}

/// The error for a missing object field.
pub(crate) fn missing(field: &str) -> Error {
    Error::Format(format!("missing field \"{field}\""))
}

/// The fields of a patch object, the annotations `arc` writes beside them
/// and the `"origin"` `convert --to bezier` writes (read and ignored here;
/// [`read_model`] keeps the origin); any other field is refused
/// (docs/limits.md).
const PATCH_FIELDS: [&str; 8] = [
    "kind", "degree", "points", "weights", "exact", "cos_half", "lambda", "origin",
];

/// Read one patch from a JSON object.
///
/// # Errors
///
/// [`Error::Format`] for an unknown `kind` or missing fields, and the shape,
/// weight, degree and number errors of the format.
pub fn patch_from_value(v: &Value) -> Result<Patch<BigRational>, Error> {
    patch_from_value_as(v)
}

/// [`patch_from_value`] for any exact number type, e.g.
/// `patch_from_value_as::<RealAlgebraic>` for patches with algebraic
/// weights (as `standardize` writes them).
///
/// # Errors
///
/// As [`patch_from_value`].
pub fn patch_from_value_as<T: ExactNumber>(v: &Value) -> Result<Patch<T>, Error> {
    let obj = v
        .as_object()
        .ok_or_else(|| Error::Format(format!("expected a JSON object, found {v}")))?;
    let kind = obj
        .get("kind")
        .and_then(Value::as_str)
        .ok_or_else(|| missing("kind"))?;
    if let Some(key) = obj.keys().find(|k| !PATCH_FIELDS.contains(&k.as_str()))
        && matches!(kind, "curve" | "rect" | "tri")
    {
        return Err(Error::Format(format!(
                "unknown field {key:?} (a {kind} has only \"kind\", \"degree\", \"points\", \"weights\", \"origin\")"
            )));
    }
    match kind {
        "curve" => read_curve(obj).map(Patch::Curve),
        "rect" => read_rect(obj).map(Patch::Rect),
        "tri" => read_tri(obj).map(Patch::Tri),
        other => Err(Error::Format(unknown_kind(other))),
    }
}

/// The message for a `"kind"` this reader does not take: every kind of the
/// format (docs/FORMAT.md), and where the other readers are.
fn unknown_kind(kind: &str) -> String {
    let elsewhere = match kind {
        "trig-curve" | "trig-rect" => " (a trigonometric patch: read it with `io::read_trig_patches`; CLI `eval`, `convert --to rational`)",
        "nurbs-curve" | "nurbs-surface" => " (a NURBS: read it with `io::read_nurbs`; CLI `convert --to bezier`)",
        _ => "",
    };
    format!(
        "kind {kind:?} is not a Bézier patch kind{elsewhere}; the kinds are \"curve\", \"rect\", \"tri\", \"trig-curve\", \"trig-rect\", \"nurbs-curve\" and \"nurbs-surface\", in lower case"
    )
}

/// Parse JSON text exactly (numbers keep their full text).
///
/// # Errors
///
/// [`Error::Format`] naming the line and column of a syntax error, or a
/// key repeated in one object (policy: refused, docs/limits.md).
pub fn parse_json(text: &str) -> Result<Value, Error> {
    let v = serde_json::from_str(text).map_err(|e| Error::Format(e.to_string()))?;
    duplicate_keys::check_no_duplicate_keys(text)?;
    Ok(v)
}

/// Read a file's content: one patch object or an array of them.
///
/// # Errors
///
/// As [`patch_from_value`]; the index of the failing element is named.
///
/// # Examples
///
/// ```
/// use exact_bezier::{io::read_patches, Patch, ratio};
/// let v = read_patches(r#"{"kind": "curve", "points": [[0,0],[1,2],[2,0]], "weights": [1, "1/3", 1]}"#).unwrap();
/// let Patch::Curve(c) = &v[0] else { panic!() };
/// assert_eq!(c.weights()[1], ratio(1, 3));
/// ```
pub fn read_patches(text: &str) -> Result<Vec<Patch<BigRational>>, Error> {
    let v = parse_json(text)?;
    match &v {
        Value::Array(items) => {
            let mut out = Vec::new();
            for (k, item) in items.iter().enumerate() {
                out.extend(
                    patches_from_value(item)
                        .map_err(|e| Error::Format(format!("element {k}: {e}")))?,
                );
            }
            Ok(out)
        }
        _ => patches_from_value(&v),
    }
}

/// Read patches whose numbers are of type `T` (one object or an array of
/// curve, rect and tri objects), e.g. `read_patches_as::<RealAlgebraic>`
/// for the output of `standardize`.
///
/// # Errors
///
/// As [`read_patches`].
pub fn read_patches_as<T: ExactNumber>(text: &str) -> Result<Vec<Patch<T>>, Error> {
    match parse_json(text)? {
        Value::Array(items) => items
            .iter()
            .enumerate()
            .map(|(k, item)| {
                patch_from_value_as(item).map_err(|e| Error::Format(format!("element {k}: {e}")))
            })
            .collect(),
        v => Ok(vec![patch_from_value_as(&v)?]),
    }
}

/// One patch, or the Bézier pieces of a NURBS object ([`read_nurbs`]).
fn patches_from_value(v: &Value) -> Result<Vec<Patch<BigRational>>, Error> {
    if is_nurbs(v) {
        let nurbs = read_nurbs(v)?;
        return Ok(nurbs
            .iter()
            .flat_map(|n| n.pieces())
            .map(|p| p.patch)
            .collect());
    }
    Ok(vec![patch_from_value(v)?])
}

/// Scalars that can be written to JSON: exact numbers as integers or
/// `"p/q"` strings, `f64` as numbers, polynomials as their formula text.
pub trait JsonScalar: Scalar {
    /// The JSON value of `self`.
    fn to_json(&self) -> Value;
}

impl JsonScalar for BigRational {
    fn to_json(&self) -> Value {
        if self.is_integer() {
            let text = self.numer().to_string();
            // arbitrary_precision keeps big integers exact.
            match text.parse::<Number>() {
                Ok(n) => Value::Number(n),
                Err(_) => Value::String(text),
            }
        } else {
            Value::String(self.to_string())
        }
    }
}

impl JsonScalar for f64 {
    fn to_json(&self) -> Value {
        Number::from_f64(*self).map_or_else(|| Value::String(self.to_string()), Value::Number)
    }
}

impl JsonScalar for Poly {
    fn to_json(&self) -> Value {
        Value::String(self.to_string())
    }
}

/// Kept here, not beside the type: JSON belongs to `io`, above `algebra`.
impl JsonScalar for crate::algebra::RealAlgebraic {
    /// Rationals as [`BigRational`] writes them (integers as JSON numbers,
    /// else `"p/q"`); irrational numbers as strings in the text grammar.
    fn to_json(&self) -> serde_json::Value {
        match self.as_rational() {
            Some(q) => q.to_json(),
            None => serde_json::Value::String(self.to_string()),
        }
    }
}

/// A point as a JSON array.
pub fn point_to_json<T: JsonScalar>(p: &[T]) -> Value {
    Value::Array(p.iter().map(JsonScalar::to_json).collect())
}

fn grid_to_json<T: JsonScalar>(g: &[Vec<Vec<T>>]) -> Value {
    Value::Array(
        g.iter()
            .map(|r| Value::Array(r.iter().map(|p| point_to_json(p)).collect()))
            .collect(),
    )
}

fn weights_to_json<T: JsonScalar>(g: &[Vec<T>]) -> Value {
    Value::Array(g.iter().map(|r| point_to_json(r)).collect())
}

/// Write a patch in the interchange format (Cartesian points and weights).
///
/// # Errors
///
/// [`Error::PointAtInfinity`] if a weight is zero;
/// [`Error::DegreeTooHigh`] over [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
pub fn patch_to_json<T: JsonScalar + Field>(p: &Patch<T>) -> Result<Value, Error> {
    // What we write, we read: never a degree the reader refuses.
    match p {
        Patch::Curve(c) => check_degree(c.degree())?,
        Patch::Rect(r) => {
            check_degree(r.degree().0)?;
            check_degree(r.degree().1)?;
        }
        Patch::Tri(t) => check_degree(t.degree())?,
    }
    let mut obj = Map::new();
    obj.insert("kind".into(), p.kind().into());
    match p {
        Patch::Curve(c) => {
            obj.insert("degree".into(), c.degree().into());
            let pts = c.points()?;
            obj.insert(
                "points".into(),
                Value::Array(pts.iter().map(|q| point_to_json(q)).collect()),
            );
            obj.insert("weights".into(), point_to_json(&c.weights()));
        }
        Patch::Rect(r) => {
            let (m, n) = r.degree();
            obj.insert("degree".into(), Value::from(vec![m, n]));
            obj.insert("points".into(), grid_to_json(&r.points()?));
            obj.insert("weights".into(), weights_to_json(&r.weights()));
        }
        Patch::Tri(t) => {
            obj.insert("degree".into(), t.degree().into());
            let pts: Vec<Vec<Vec<T>>> = t
                .rows()
                .iter()
                .map(|r| r.iter().map(|h| h.project()).collect::<Result<_, _>>())
                .collect::<Result<_, _>>()?;
            obj.insert("points".into(), grid_to_json(&pts));
            obj.insert("weights".into(), weights_to_json(&t.weights()));
        }
    }
    Ok(Value::Object(obj))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;

    #[test]
    fn numbers_are_exact() {
        assert_eq!(parse_rational("1.44").unwrap(), ratio(144, 100));
        assert_eq!(parse_rational("2").unwrap(), ratio(2, 1));
        assert_eq!(parse_rational("-.5").unwrap(), ratio(-1, 2));
        assert_eq!(parse_rational("3e2").unwrap(), ratio(300, 1));
        for bad in ["", "1/0", "abc", "1.2.3", "inf", "--1", "1e"] {
            assert!(parse_rational(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn json_numbers_keep_their_text() {
        let v = read_patches(r#"{"kind":"curve","points":[[0.1],[0.30000000000000004]]}"#).unwrap();
        let Patch::Curve(c) = &v[0] else { panic!() };
        let pts = c.points().unwrap();
        assert_eq!(pts[0][0], ratio(1, 10));
        assert_eq!(
            pts[1][0],
            parse_rational("30000000000000004/100000000000000000").unwrap()
        );
    }

    #[test]
    fn bad_inputs_are_typed_errors() {
        let cases = [
            (
                r#"{"kind":"curve","points":[[0,0],[1,1]],"weights":[1,0]}"#,
                "weight w_1 is 0",
            ),
            (
                r#"{"kind":"curve","points":[[0,0],[1,1]],"weights":[1,-2]}"#,
                "weight w_1 is -2",
            ),
            (
                r#"{"kind":"curve","degree":3,"points":[[0,0],[1,1]]}"#,
                "should have 4",
            ),
            (r#"{"kind":"curve","points":[[0,0],[1]]}"#, "dimension"),
            (r#"{"kind":"rect","points":[[[0],[1]],[[2]]]}"#, "row 1"),
            (
                r#"{"kind":"tri","points":[[[0],[1]],[[2]],[[3]]]}"#,
                "row 0",
            ),
            (
                r#"{"kind":"blob","points":[]}"#,
                "is not a Bézier patch kind",
            ),
            (
                r#"{"kind":"curve","points":[["NaN"]]}"#,
                "not an exact number",
            ),
            (r#"{"kind":"curve","points":[[0],[1]"#, "malformed"),
        ];
        for (text, want) in cases {
            let err = read_patches(text).unwrap_err().to_string();
            assert!(err.contains(want), "{text}: {err}");
        }
        let big: Vec<String> = (0..=crate::limits::MAX_DEGREE + 1)
            .map(|i| format!("[{i}]"))
            .collect();
        let text = format!(r#"{{"kind":"curve","points":[{}]}}"#, big.join(","));
        assert!(matches!(
            read_patches(&text),
            Err(Error::DegreeTooHigh { .. })
        ));
    }

    #[test]
    fn round_trip_through_json() {
        let text = r#"[{"kind":"rect","points":[[[0,0],[1,"1/3"]],[[2,0],[3,3]]],"weights":[[1,2],[3,"1/2"]]},
                      {"kind":"tri","points":[[[0,0],[1,0]],[[0,1]]],"weights":[[1,2],[3]]}]"#;
        let patches = read_patches(text).unwrap();
        for p in &patches {
            let back = patch_from_value(&patch_to_json(p).unwrap()).unwrap();
            assert_eq!(&back, p);
        }
    }
}
