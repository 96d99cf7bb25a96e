//! Models and audits in JSON: [`read_model`] reads the Bézier pieces of a
//! file (our JSON, NURBS objects, geomdl, or STEP) with where each came
//! from; [`piece_to_json`] and [`audit_to_json`] write them.

use super::{
    is_nurbs, number, parse_json, patch_from_value_as, patch_to_json, point_to_json, read_nurbs,
    JsonScalar,
};
use crate::algebra::{ExactNumber, Field, RealAlgebraic};
use crate::audit::brep::{BrepAudit, BrepEdge, EdgeClass, Grade, Measured, ToleranceSource};
use crate::audit::certify::Verdict;
use crate::audit::joint::Measure;
use crate::audit::{nurbs_pieces, Audit, ExactModel, Model, Origin, PatchEdge, Piece};
use crate::error::Error;
use crate::patch::Patch;
use crate::step::read_step;
use num_rational::BigRational;
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::io::BufRead;

/// A piece's origin as JSON: `{"element"|"entity", "faces", "span_u",
/// "span_v"}` (absent fields omitted).
pub fn origin_to_json(origin: &Origin) -> Value {
    let mut o = serde_json::Map::new();
    if let Some(e) = origin.element {
        o.insert("element".into(), json!(e));
    }
    if let Some(e) = origin.entity {
        o.insert("entity".into(), json!(format!("#{e}")));
        let faces: Vec<String> = origin.faces.iter().map(|f| format!("#{f}")).collect();
        o.insert("faces".into(), json!(faces));
    }
    if let Some(u) = &origin.u {
        o.insert("span_u".into(), point_to_json(u));
    }
    if let Some(v) = &origin.v {
        o.insert("span_v".into(), point_to_json(v));
    }
    Value::Object(o)
}

/// Read an origin written by [`origin_to_json`]: every field optional,
/// ids as `"#n"`, spans as two exact numbers.
///
/// # Errors
///
/// [`Error::Format`] for a mistyped field or an unknown one.
///
/// ```
/// use exact_bezier::io::{origin_from_json, origin_to_json, parse_json};
/// let v = parse_json(r##"{"entity": "#20", "faces": ["#30"], "span_u": [0, "1/2"]}"##).unwrap();
/// assert_eq!(origin_to_json(&origin_from_json(&v).unwrap()), v);
/// ```
pub fn origin_from_json(v: &Value) -> Result<Origin, Error> {
    let obj = v
        .as_object()
        .ok_or_else(|| Error::Format(format!("\"origin\" should be an object, found {v}")))?;
    let step_id = |x: &Value| {
        x.as_str()
            .and_then(|t| t.strip_prefix('#'))
            .and_then(|t| t.parse::<u64>().ok())
            .ok_or_else(|| Error::Format(format!("an origin id should be \"#n\", found {x}")))
    };
    let span = |x: &Value| -> Result<[BigRational; 2], Error> {
        match x.as_array().map(Vec::as_slice) {
            Some([a, b]) => Ok([number(a, "a span")?, number(b, "a span")?]),
            _ => Err(Error::Format(format!("a span should be [a, b], found {x}"))),
        }
    };
    let mut o = Origin::default();
    for (key, x) in obj {
        match key.as_str() {
            "element" => {
                o.element = Some(
                    x.as_u64()
                        .and_then(|e| usize::try_from(e).ok())
                        .ok_or_else(|| Error::Format(format!("origin element {x}")))?,
                );
            }
            "entity" => o.entity = Some(step_id(x)?),
            "faces" => {
                o.faces = x
                    .as_array()
                    .ok_or_else(|| Error::Format("origin faces should be a list".into()))?
                    .iter()
                    .map(step_id)
                    .collect::<Result<_, _>>()?;
            }
            "span_u" => o.u = Some(span(x)?),
            "span_v" => o.v = Some(span(x)?),
            other => return Err(Error::Format(format!("unknown origin field {other:?}"))),
        }
    }
    Ok(o)
}

/// The pieces of one JSON object; `element(d)` is the origin element of
/// its `d`-th NURBS (a geomdl file holds several).
fn json_pieces<T: ExactNumber>(
    v: &Value,
    element: &dyn Fn(usize) -> usize,
) -> Result<Vec<Piece<T>>, Error> {
    if is_nurbs(v) {
        let nurbs = read_nurbs(v)?;
        return Ok(nurbs
            .iter()
            .enumerate()
            .flat_map(|(d, n)| {
                let base = Origin {
                    element: Some(element(d)),
                    ..Origin::default()
                };
                nurbs_pieces(n, base)
            })
            .map(|p| Piece {
                patch: p.patch.map(T::from_rational),
                origin: p.origin,
            })
            .collect());
    }
    let origin = match v.get("origin") {
        Some(o) => origin_from_json(o)?,
        None => Origin {
            element: Some(element(0)),
            ..Origin::default()
        },
    };
    Ok(vec![Piece {
        patch: patch_from_value_as(v)?,
        origin,
    }])
}

/// Does the stream begin with `ISO-10303-21` (a STEP file)? Looks at the
/// buffered head only.
///
/// # Errors
///
/// [`Error::Io`] when the stream cannot be read.
pub fn is_step(input: &mut impl BufRead) -> Result<bool, Error> {
    let head = input
        .fill_buf()
        .map_err(|e| Error::Io(format!("cannot read the input: {e}")))?;
    let text_start = String::from_utf8_lossy(&head[..head.len().min(64)]).into_owned();
    Ok(text_start.trim_start().starts_with("ISO-10303-21"))
}

/// The surface pieces of a B-rep document or face object written by
/// `convert --to bezier` (docs/FORMAT.md, "B-rep"), `None` for other JSON.
fn brep_pieces(v: &Value) -> Option<Vec<&Value>> {
    fn surface_pieces(g: &Value) -> Vec<&Value> {
        g.get("pieces")
            .and_then(Value::as_array)
            .map(|p| p.iter().collect())
            .unwrap_or_default()
    }
    match v.get("kind").and_then(Value::as_str)? {
        "face" => Some(surface_pieces(v.get("surface")?)),
        "brep" => {
            let faces = v.get("faces").and_then(Value::as_array);
            let loose = v.get("unattached").and_then(Value::as_array);
            let faces = faces.into_iter().flatten().filter_map(|f| f.get("surface"));
            Some(
                faces
                    .chain(loose.into_iter().flatten())
                    .flat_map(surface_pieces)
                    .collect(),
            )
        }
        _ => None,
    }
}

/// Read a model from a stream: STEP if it begins with `ISO-10303-21`,
/// otherwise JSON (one object or an array, or a B-rep document or face
/// that `convert --to bezier` writes: its surface pieces). STEP is read statement by
/// statement; JSON is read whole. Every number must be rational; see
/// [`read_exact_model`] for pieces with algebraic numbers.
///
/// # Errors
///
/// The readers' errors (JSON: the failing element's index is named).
pub fn read_model(mut input: impl BufRead) -> Result<Model, Error> {
    if is_step(&mut input)? {
        return Ok(Model::from_step(read_step(input)?));
    }
    json_model(&parse_json(&read_text(input)?)?)
}

/// [`read_model`], with pieces over the real algebraic numbers when some
/// number of a JSON input is not rational (`"sqrt(2)/2"`, the grammar of
/// docs/algebraic_numbers.md, as `convert --to bezier` writes analytic
/// faces): what we write, we read.
///
/// # Errors
///
/// As [`read_model`]; a text neither reader accepts gets the rational
/// reader's error.
///
/// ```
/// use exact_bezier::{audit::ExactModel, io::read_exact_model};
/// let text = r#"[{"kind": "curve", "points": [[0, 0], [1, "sqrt(2)"]]}]"#;
/// let m = read_exact_model(text.as_bytes()).unwrap();
/// assert!(matches!(m, ExactModel::Algebraic(m) if m.pieces.len() == 1));
/// ```
pub fn read_exact_model(mut input: impl BufRead) -> Result<ExactModel, Error> {
    if is_step(&mut input)? {
        return Ok(ExactModel::Rational(Model::from_step(read_step(input)?)));
    }
    let v = parse_json(&read_text(input)?)?;
    match json_model(&v) {
        Ok(m) => Ok(ExactModel::Rational(m)),
        Err(rational) => json_model::<RealAlgebraic>(&v)
            .map(ExactModel::Algebraic)
            .map_err(|_| rational),
    }
}

fn read_text(mut input: impl BufRead) -> Result<String, Error> {
    let mut text = String::new();
    input
        .read_to_string(&mut text)
        .map_err(|e| Error::Io(format!("cannot read the input: {e}")))?;
    Ok(text)
}

/// The model of a JSON value (see [`read_model`]).
fn json_model<T: ExactNumber>(v: &Value) -> Result<Model<T>, Error> {
    if let Some(pieces) = brep_pieces(v) {
        let pieces = pieces
            .into_iter()
            .enumerate()
            .map(|(k, p)| {
                json_pieces(p, &|_| k).map_err(|e| Error::Format(format!("piece {k}: {e}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        return Ok(Model {
            pieces: pieces.into_iter().flatten().collect(),
            ..Model::default()
        });
    }
    let pieces = match v {
        Value::Array(items) => {
            let mut out = Vec::new();
            for (k, item) in items.iter().enumerate() {
                out.extend(
                    json_pieces(item, &|_| k)
                        .map_err(|e| Error::Format(format!("element {k}: {e}")))?,
                );
            }
            out
        }
        _ => json_pieces(v, &|d| d)?,
    };
    Ok(Model {
        pieces,
        ..Model::default()
    })
}

/// A piece as JSON: the patch object with an `"origin"` field.
///
/// # Errors
///
/// [`Error::PointAtInfinity`] never for positive weights (as
/// [`patch_to_json`](crate::io::patch_to_json)).
pub fn piece_to_json<T: JsonScalar + Field>(p: &Patch<T>, origin: &Origin) -> Result<Value, Error> {
    let mut v = patch_to_json(p)?;
    if let Value::Object(o) = &mut v {
        o.insert("origin".into(), origin_to_json(origin));
    }
    Ok(v)
}

/// The audit as JSON, with each patch's origin from `model`.
pub fn audit_to_json<T: JsonScalar>(audit: &Audit<T>, model: &Model<T>) -> Value {
    let pe = |e: &PatchEdge| json!({"patch": e.patch, "edge": e.edge.to_string(), "origin": origin_to_json(&model.pieces[e.patch].origin)});
    let seams: Vec<Value> = audit
        .seams
        .iter()
        .map(|s| {
            json!({
                "a": pe(&s.a),
                "b": pe(&s.b),
                "continuity": s.verdict.continuity.map_or(Value::Null, |c| json!(c.to_string())),
                "reason": s.verdict.reason,
                "reversed": s.verdict.reversed,
                "reparameterized": s.verdict.reparameterized,
                "non_manifold": s.non_manifold,
            })
        })
        .collect();
    let [g0, g1, g2, u] = audit.counts();
    json!({
        "summary": audit.summary(),
        "patches": audit.patches,
        "counts": {"G0": g0, "G1": g1, "G2": g2, "undecided": u},
        "seams": seams,
        "open_edges": audit.open_edges.iter().map(pe).collect::<Vec<_>>(),
        "degenerate_edges": audit.degenerate_edges.iter().map(|(e, p)| {
            let mut v = pe(e);
            v["point"] = point_to_json(p);
            v
        }).collect::<Vec<_>>(),
        "duplicates": audit.duplicates,
        "same_surface": same_surface(model),
        "not_audited": audit.not_rect,
        "skipped_entities": model.skipped,
        "invalid_entities": model.invalid.iter().map(|(id, r)| json!({"entity": format!("#{id}"), "reason": r})).collect::<Vec<_>>(),
        "faces_on_other_surfaces": model.other_faces.len(),
    })
}

/// The B-rep audit as JSON: `summary`, `faces`, `edges` (counts by
/// class), `continuity`, `tolerance`; with `full`, also `edge_list` (every
/// edge with its curve type, faces and class) and what was not converted.
pub fn brep_audit_to_json(a: &BrepAudit, full: bool) -> Value {
    let mut edges = serde_json::Map::new();
    edges.insert("total".into(), json!(a.edges.len()));
    for c in EdgeClass::ALL {
        edges.insert(c.name().into(), json!(a.count(c)));
    }
    let t = &a.tolerance;
    let source = match t.source {
        ToleranceSource::Given => "--tol",
        ToleranceSource::Declared => "UNCERTAINTY_MEASURE_WITH_UNIT",
        ToleranceSource::None => "none",
    };
    let mut v = json!({
        "summary": a.summary(),
        "faces": {"total": a.faces(), "by_surface": a.faces_by_surface},
        "edges": edges,
        "continuity": continuity_counts(a),
        "knot_lines": {
            "faces": a.knot_lines.len(),
            "total": a.knot_lines.values().map(Vec::len).sum::<usize>(),
            "by_continuity": a.knot_line_counts(),
        },
        "tolerance": {"length": t.length.as_ref().map(BigRational::to_json), "unit": t.unit,
                      "angle": t.angle.to_json(), "curvature": t.curvature.to_json(), "source": source},
    });
    if full {
        v["edge_list"] = a
            .edges
            .iter()
            .map(|e| {
                let mut v = json!({
                    "id": format!("#{}", e.id),
                    "curve": e.curve,
                    "faces": e.faces.iter().map(|f| format!("#{f}")).collect::<Vec<_>>(),
                    "class": e.class.name(),
                });
                edge_measures(e, &mut v);
                v
            })
            .collect();
        v["knot_line_list"] = a
            .knot_lines
            .iter()
            .flat_map(|(face, lines)| {
                lines.iter().map(move |l| {
                    json!({
                        "face": format!("#{face}"),
                        "direction": l.direction.name(),
                        "knot": l.knot.to_json(),
                        "degree": l.degree,
                        "continuity": l.continuity.map_or_else(|| "removable".to_string(), |r| format!("C{r}")),
                    })
                })
            })
            .collect();
        v["not_converted"] = json!(a.not_converted);
        v["invalid_entities"] = json!(a.invalid);
    }
    v
}

/// The `continuity` counts of a B-rep audit: measured shared and seam
/// edges by [`Grade`], `exact` among them, `not_measured`.
fn continuity_counts(a: &BrepAudit) -> Value {
    let grades = a.grades();
    let mut c = serde_json::Map::new();
    for g in [
        Grade::G2,
        Grade::G1,
        Grade::G0,
        Grade::Fails,
        Grade::Undecided,
    ] {
        c.insert(g.name().into(), json!(grades.get(&g).map_or(0, |k| k[0])));
    }
    c.insert(
        "exact".into(),
        json!(grades.values().map(|k| k[1]).sum::<usize>()),
    );
    c.insert(
        "not_measured".into(),
        json!(a.not_measured().values().sum::<usize>()),
    );
    Value::Object(c)
}

/// A measure as JSON: `0` when exact, else its enclosure with the piece
/// and piece parameters where the maximum is attained, or `"unproved"`.
fn measure_json(m: &Measure) -> Value {
    match m {
        Measure::Exact => json!(0),
        Measure::Enclosed { value, piece } => json!({
            "lo": value.lo, "hi": value.hi, "piece": piece, "t": [value.at.lo, value.at.hi],
        }),
        Measure::Unproved => json!("unproved"),
    }
}

fn verdict_name(v: &Verdict) -> &'static str {
    match v {
        Verdict::Exact => "exact",
        Verdict::WithinTolerance => "within_tolerance",
        Verdict::Fails { .. } => "fails",
        Verdict::Undecided => "undecided",
    }
}

/// Add an edge's measures and verdicts (or why it is not measured) to `v`.
fn edge_measures(e: &BrepEdge, v: &mut Value) {
    match &e.measured {
        Measured::NotApplicable => {}
        Measured::NotMeasured(why) => v["not_measured"] = json!(why),
        Measured::Measured(j) => {
            let (grade, exact) = Grade::of(j);
            v["measures"] = json!({
                "gap": j.gap.iter().map(measure_json).collect::<Vec<_>>(),
                "face_gap": measure_json(&j.face_gap),
                "angle": measure_json(&j.angle),
            });
            v["verdicts"] = json!({"G0": verdict_name(&j.g0), "G1": verdict_name(&j.g1)});
            if let (Some(c), Some(g2)) = (&j.curvature, &j.g2) {
                v["measures"]["curvature"] = measure_json(c);
                v["verdicts"]["G2"] = json!(verdict_name(g2));
            }
            v["continuity"] = json!(grade.name());
            v["exact"] = json!(exact);
        }
    }
}

/// Pieces that come from one source surface (one STEP entity or one NURBS
/// object), and STEP faces that share one surface entity.
fn same_surface<T>(model: &Model<T>) -> Vec<Value> {
    let mut by_source: BTreeMap<(Option<u64>, Option<usize>), Vec<usize>> = BTreeMap::new();
    for (k, p) in model.pieces.iter().enumerate() {
        let src = p.origin.source();
        if src != (None, None) {
            by_source.entry(src).or_default().push(k);
        }
    }
    by_source
        .into_iter()
        .filter_map(|((entity, element), pieces)| {
            let faces = &model.pieces[pieces[0]].origin.faces;
            (pieces.len() > 1 || faces.len() > 1).then(|| {
                json!({
                    "entity": entity.map(|e| format!("#{e}")),
                    "element": element,
                    "faces": faces.iter().map(|f| format!("#{f}")).collect::<Vec<_>>(),
                    "patches": pieces,
                })
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::Scalar;
    use crate::{ratio, RationalCurve, RectPatch, TriPatch};
    use proptest::collection::vec;
    use proptest::prelude::*;

    fn q() -> impl Strategy<Value = BigRational> {
        (-20i64..20, 1i64..7).prop_map(|(n, d)| ratio(n, d))
    }

    fn w() -> impl Strategy<Value = BigRational> {
        (1i64..20, 1i64..7).prop_map(|(n, d)| ratio(n, d))
    }

    /// A curve, rect or tri of small degree in 3D with positive weights.
    fn patch() -> impl Strategy<Value = Patch<BigRational>> {
        let pts = |n: usize| vec(vec(q(), 3), n);
        prop_oneof![
            (1usize..4).prop_flat_map(move |n| (pts(n + 1), vec(w(), n + 1))
                .prop_map(|(p, w)| { Patch::Curve(RationalCurve::new(p, w).unwrap()) })),
            (1usize..3, 1usize..3).prop_flat_map(move |(m, n)| (
                vec(pts(n + 1), m + 1),
                vec(vec(w(), n + 1), m + 1)
            )
                .prop_map(|(p, w)| Patch::Rect(RectPatch::new(p, w).unwrap()))),
            (1usize..3).prop_flat_map(move |n| {
                let rows: Vec<usize> = (0..=n).map(|j| n - j + 1).collect();
                let p: Vec<_> = rows.iter().map(|&l| pts(l)).collect();
                let ws: Vec<_> = rows.iter().map(|&l| vec(w(), l)).collect();
                (p, ws).prop_map(|(p, w)| Patch::Tri(TriPatch::new(p, w).unwrap()))
            }),
        ]
    }

    /// An origin as STEP or JSON inputs give them.
    fn span() -> impl Strategy<Value = [BigRational; 2]> {
        (q(), q()).prop_map(|(a, b)| [a, b])
    }

    fn origin() -> impl Strategy<Value = Origin> {
        (
            proptest::option::of(0usize..9),
            proptest::option::of(1u64..1000),
            vec(1u64..1000, 0..3),
            proptest::option::of(span()),
            proptest::option::of(span()),
        )
            .prop_map(|(element, entity, faces, u, v)| Origin {
                element,
                faces: if entity.is_some() { faces } else { Vec::new() },
                entity,
                u,
                v,
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// What `convert --to bezier` writes, every reader reads: the model
        /// reader gets the piece and its origin back, the patch reader the
        /// patch.
        #[test]
        fn written_pieces_read_back(pieces in vec((patch(), origin()), 0..4)) {
            let json: Vec<Value> = pieces.iter().map(|(p, o)| piece_to_json(p, o).unwrap()).collect();
            let text = Value::Array(json).to_string();
            let model = read_model(text.as_bytes()).unwrap();
            let back: Vec<(Patch<BigRational>, Origin)> =
                model.pieces.into_iter().map(|p| (p.patch, p.origin)).collect();
            prop_assert_eq!(&back, &pieces);
            let patches = crate::io::read_patches(&text).unwrap();
            let want: Vec<Patch<BigRational>> = pieces.into_iter().map(|(p, _)| p).collect();
            prop_assert_eq!(patches, want);
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(16))]
        /// Pieces with algebraic numbers (every homogeneous coordinate `x`
        /// of a rational piece made `x + √2·x²`, so weights stay positive
        /// and are irrational) are read back exactly, as an algebraic model.
        #[test]
        fn written_algebraic_pieces_read_back(pieces in vec((patch(), origin()), 1..3)) {
            let r2: RealAlgebraic = "sqrt(2)".parse().unwrap();
            let lift = |x: &BigRational| {
                let a = RealAlgebraic::from_rational(x);
                a.clone() + &(r2.clone() * &a * &a)
            };
            let pieces: Vec<(Patch<RealAlgebraic>, Origin)> =
                pieces.iter().map(|(p, o)| (p.map(lift), o.clone())).collect();
            let json: Vec<Value> = pieces.iter().map(|(p, o)| piece_to_json(p, o).unwrap()).collect();
            let text = Value::Array(json).to_string();
            prop_assert!(read_model(text.as_bytes()).is_err());
            let ExactModel::Algebraic(model) = read_exact_model(text.as_bytes()).unwrap() else {
                panic!("an irrational weight read as rational");
            };
            let back: Vec<(Patch<RealAlgebraic>, Origin)> =
                model.pieces.into_iter().map(|p| (p.patch, p.origin)).collect();
            prop_assert_eq!(&back, &pieces);
        }
    }

    #[test]
    fn geomdl_data_get_their_own_element() {
        let datum = r#"{"degree": 1, "knotvector": [0, 0, 1, 1], "control_points": {"points": [[0, 0], [1, 1]]}}"#;
        let text =
            format!(r#"{{"shape": {{"type": "curve", "data": [{datum}, {datum}, {datum}]}}}}"#);
        let m = read_model(text.as_bytes()).unwrap();
        let elements: Vec<Option<usize>> = m.pieces.iter().map(|p| p.origin.element).collect();
        assert_eq!(elements, [Some(0), Some(1), Some(2)]);
        assert!(read_model(&b"[]"[..]).unwrap().pieces.is_empty());
    }
}
