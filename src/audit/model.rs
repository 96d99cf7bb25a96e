//! A model: the Bézier pieces of a file with where each came from — read
//! from our JSON (patches, `nurbs-*` objects, geomdl) or from STEP.

use crate::error::Error;
use crate::io::{is_nurbs, read_nurbs};
use crate::io::{parse_json, patch_from_value, point_to_json, JsonScalar};
use crate::nurbs::Nurbs;
use crate::patch::Patch;
use crate::step::read_step;
use num_rational::BigRational;
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::io::BufRead;

/// Where a piece came from.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Origin {
    /// Position of its object in a JSON input (array index), if JSON.
    pub element: Option<usize>,
    /// The STEP entity id, if STEP.
    pub entity: Option<u64>,
    /// The faces whose surface it is (STEP).
    pub faces: Vec<u64>,
    /// The knot span in u (along a curve), for NURBS.
    pub u: Option<[BigRational; 2]>,
    /// The knot span in v, for NURBS surfaces.
    pub v: Option<[BigRational; 2]>,
}

impl Origin {
    /// `{"element"|"entity", "faces", "span_u", "span_v"}` (absent fields omitted).
    pub fn to_json(&self) -> Value {
        let mut o = serde_json::Map::new();
        if let Some(e) = self.element {
            o.insert("element".into(), json!(e));
        }
        if let Some(e) = self.entity {
            o.insert("entity".into(), json!(format!("#{e}")));
            let faces: Vec<String> = self.faces.iter().map(|f| format!("#{f}")).collect();
            o.insert("faces".into(), json!(faces));
        }
        if let Some(u) = &self.u {
            o.insert("span_u".into(), point_to_json(u));
        }
        if let Some(v) = &self.v {
            o.insert("span_v".into(), point_to_json(v));
        }
        Value::Object(o)
    }

    /// The source object (entity or element) this piece belongs to.
    pub fn source(&self) -> (Option<u64>, Option<usize>) {
        (self.entity, self.element)
    }
}

/// One Bézier piece of a model.
#[derive(Clone, Debug, PartialEq)]
pub struct Piece {
    /// The piece.
    pub patch: Patch<BigRational>,
    /// Where it came from.
    pub origin: Origin,
}

/// The pieces of a file, and what was skipped reading it.
#[derive(Clone, Debug, Default)]
pub struct Model {
    /// Every piece, in file order.
    pub pieces: Vec<Piece>,
    /// STEP entity types skipped, with counts.
    pub skipped: BTreeMap<String, usize>,
    /// STEP entities of a supported type that could not be read.
    pub invalid: Vec<(u64, String)>,
    /// STEP faces on surfaces that are not B-splines: `(face, surface)`.
    pub other_faces: Vec<(u64, u64)>,
}

fn nurbs_pieces(n: &Nurbs, base: Origin) -> impl Iterator<Item = Piece> + '_ {
    n.pieces().into_iter().map(move |p| Piece {
        patch: p.patch,
        origin: Origin {
            u: Some(p.u),
            v: p.v,
            ..base.clone()
        },
    })
}

fn json_pieces(v: &Value, element: Option<usize>) -> Result<Vec<Piece>, Error> {
    let base = Origin {
        element,
        ..Origin::default()
    };
    if is_nurbs(v) {
        let nurbs = read_nurbs(v)?;
        return Ok(nurbs
            .iter()
            .flat_map(|n| nurbs_pieces(n, base.clone()))
            .collect());
    }
    Ok(vec![Piece {
        patch: patch_from_value(v)?,
        origin: base,
    }])
}

/// Read a model from a stream: STEP if it begins with `ISO-10303-21`,
/// otherwise JSON (one object or an array). STEP is read statement by
/// statement; JSON is read whole.
///
/// # Errors
///
/// The readers' errors (JSON: the failing element's index is named).
pub fn read_model(mut input: impl BufRead) -> Result<Model, Error> {
    let head = input
        .fill_buf()
        .map_err(|e| Error::Io(format!("cannot read the input: {e}")))?;
    let text_start = String::from_utf8_lossy(&head[..head.len().min(64)]).into_owned();
    if text_start.trim_start().starts_with("ISO-10303-21") {
        let step = read_step(input)?;
        let pieces = step
            .entities
            .iter()
            .flat_map(|e| {
                let base = Origin {
                    entity: Some(e.id),
                    faces: e.faces.clone(),
                    ..Origin::default()
                };
                nurbs_pieces(&e.nurbs, base).collect::<Vec<_>>()
            })
            .collect();
        return Ok(Model {
            pieces,
            skipped: step.skipped,
            invalid: step.invalid,
            other_faces: step.other_faces,
        });
    }
    let mut text = String::new();
    input
        .read_to_string(&mut text)
        .map_err(|e| Error::Io(format!("cannot read the input: {e}")))?;
    let v = parse_json(&text)?;
    let pieces = match &v {
        Value::Array(items) => {
            let mut out = Vec::new();
            for (k, item) in items.iter().enumerate() {
                out.extend(
                    json_pieces(item, Some(k))
                        .map_err(|e| Error::Format(format!("element {k}: {e}")))?,
                );
            }
            out
        }
        _ => json_pieces(&v, Some(0))?,
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
pub fn piece_to_json<T: JsonScalar + crate::Field>(
    p: &Patch<T>,
    origin: &Origin,
) -> Result<Value, Error> {
    let mut v = crate::io::patch_to_json(p)?;
    if let Value::Object(o) = &mut v {
        o.insert("origin".into(), origin.to_json());
    }
    Ok(v)
}
