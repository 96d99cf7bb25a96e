//! A STEP B-rep ([`BrepModel`]) as JSON: faces with their surface pieces and
//! bounds, edges with their curve pieces and pcurves, vertices, and the
//! model (bodies, solids, shells, units, tolerance, summary). Written as
//! one document or as JSON Lines (one object a line, the model last); the
//! layout is in docs/FORMAT.md ("B-rep").

use super::{point_to_json, JsonScalar};
use crate::algebra::RealAlgebraic;
use crate::algebra::Scalar;
use crate::audit::Origin;
use crate::error::Error;
use crate::patch::Patch;
use crate::step::brep::{
    AngleUnit, BSpline, Bound, Edge, EdgeUse, Face, Geometry, GeometryRef, Loop, Occurrence, Shell,
};
use crate::step::BrepModel;
use rayon::prelude::*;
use serde_json::{json, Map, Value};
use std::collections::BTreeSet;

/// Writes one piece with its origin (exactly, or as floats). B-spline
/// pieces are rational and analytic ones may hold radicals: both come
/// over the real algebraic numbers.
pub type PieceWriter<'a> =
    &'a (dyn Fn(&Patch<RealAlgebraic>, &Origin) -> Result<Value, Error> + Sync);

fn id(n: u64) -> Value {
    json!(format!("#{n}"))
}

fn ids(v: &[u64]) -> Value {
    Value::Array(v.iter().map(|&n| id(n)).collect())
}

/// `{"entity", "type", "status", "pieces" | "reason"}`; `faces` go into
/// each piece's origin.
fn geometry_json(g: &GeometryRef, faces: &[u64], write: PieceWriter) -> Result<Value, Error> {
    let mut o = Map::new();
    o.insert("entity".into(), id(g.entity));
    o.insert("type".into(), json!(g.kind));
    match &g.geometry {
        Geometry::BSpline(b) => {
            o.insert("status".into(), json!("converted"));
            let written = b
                .pieces()
                .iter()
                .map(|p| {
                    let origin = Origin {
                        entity: Some(g.entity),
                        faces: faces.to_vec(),
                        u: Some(p.u.clone()),
                        v: p.v.clone(),
                        element: None,
                    };
                    write(&p.patch.map(RealAlgebraic::from_rational), &origin)
                })
                .collect::<Result<Vec<_>, _>>()?;
            o.insert("pieces".into(), Value::Array(written));
        }
        Geometry::Analytic(a) => {
            o.insert("status".into(), json!("converted"));
            let origin = Origin {
                entity: Some(g.entity),
                faces: faces.to_vec(),
                u: None,
                v: None,
                element: None,
            };
            let written = a
                .pieces
                .iter()
                .map(|p| write(p, &origin))
                .collect::<Result<Vec<_>, _>>()?;
            o.insert("pieces".into(), Value::Array(written));
            if let Some(why) = &a.approximate {
                o.insert("approximate".into(), json!(why));
            }
            if let Some(d) = &a.vertex_distance_sq {
                o.insert("vertex_distance_sq".into(), point_to_json(d));
            }
        }
        Geometry::NotConverted => {
            o.insert("status".into(), json!("not converted"));
        }
        Geometry::Invalid(why) => {
            o.insert("status".into(), json!("invalid"));
            o.insert("reason".into(), json!(why));
        }
    }
    Ok(Value::Object(o))
}

fn bound_json(b: &Bound) -> Value {
    let mut o = json!({
        "id": id(b.id), "loop": id(b.loop_id), "outer": b.outer, "orientation": b.orientation,
    });
    match &b.edges {
        Loop::Edges(es) => {
            o["edges"] = es
                .iter()
                .map(|e| json!({"id": id(e.id), "edge": id(e.edge), "orientation": e.orientation}))
                .collect();
        }
        Loop::Vertex(v) => o["vertex"] = id(*v),
        Loop::Poly(pts) => o["polygon"] = pts.iter().map(|p| point_to_json(p)).collect(),
    }
    o
}

/// A face: `{"kind": "face", "id", "same_sense", "surface", "bounds"}`.
///
/// # Errors
///
/// The piece writer's errors.
pub fn face_to_json(f: &Face, write: PieceWriter) -> Result<Value, Error> {
    let mut o = json!({
        "kind": "face",
        "id": id(f.id),
        "same_sense": f.same_sense,
        "surface": geometry_json(&f.surface, &[f.id], write)?,
        "bounds": f.bounds.iter().map(bound_json).collect::<Vec<_>>(),
    });
    if let Some(t) = f.trimmed {
        o["trimmed"] = id(t);
    }
    Ok(o)
}

fn usage_name(u: EdgeUse) -> &'static str {
    match u {
        EdgeUse::Unused => "unused",
        EdgeUse::Open => "open",
        EdgeUse::Shared => "shared",
        EdgeUse::Seam => "seam",
        EdgeUse::NonManifold => "non-manifold",
    }
}

/// An edge: `{"kind": "edge", "id", "curve", "via"?, "start", "end",
/// "same_sense", "use", "faces", "pcurves"}`.
///
/// # Errors
///
/// The piece writer's errors.
pub fn edge_to_json(e: &Edge, write: PieceWriter) -> Result<Value, Error> {
    let faces: Vec<u64> = e
        .used_by
        .iter()
        .copied()
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    let pcurves = e
        .pcurves
        .iter()
        .map(|p| {
            Ok(json!({
                "id": id(p.id),
                "surface": id(p.surface),
                "curve": geometry_json(&p.curve, &faces, write)?,
            }))
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let mut o = json!({
        "kind": "edge",
        "id": id(e.id),
        "curve": geometry_json(&e.curve, &faces, write)?,
        "start": id(e.start),
        "end": id(e.end),
        "same_sense": e.same_sense,
        "use": usage_name(e.usage()),
        "faces": ids(&e.used_by),
        "pcurves": pcurves,
    });
    if let Some(via) = &e.via {
        o["via"] = json!(via);
    }
    Ok(o)
}

fn shell_json(s: &Shell) -> Value {
    json!({"id": id(s.id), "closed": s.closed, "orientation": s.orientation, "faces": ids(&s.faces)})
}

fn angle_json(a: &AngleUnit) -> Value {
    match a {
        AngleUnit::Radian(f) => json!({"name": "radian", "radians": f.to_json()}),
        AngleUnit::Degree => json!({"name": "degree", "radians": "pi/180"}),
        AngleUnit::Other(n, f) => json!({"name": n, "radians": f.to_json()}),
    }
}

/// `{"body", "root", "context", "path", "linear", "translation"}`: where a
/// body sits, `x ↦ linear·x + translation` exactly, in the length unit of
/// the root's context.
fn occurrence_json(o: &Occurrence) -> Value {
    let p = &o.placement;
    json!({
        "body": id(o.body),
        "root": id(o.root),
        "context": o.context.map(id),
        "path": ids(&o.path),
        "linear": p.linear.iter().map(|row| point_to_json(row)).collect::<Vec<_>>(),
        "translation": point_to_json(&p.translation),
    })
}

/// Why the faces have no pieces, when none has: never an empty answer
/// without a reason.
fn message(m: &BrepModel) -> Option<String> {
    let converted = m
        .faces
        .values()
        .filter(|f| {
            matches!(
                f.surface.geometry,
                Geometry::BSpline(_) | Geometry::Analytic(_)
            )
        })
        .count();
    if m.faces.is_empty() {
        return Some(format!(
            "the file holds no faces ({} B-spline entities outside faces are under \"unattached\")",
            m.geometry.entities.len()
        ));
    }
    (converted < m.faces.len()).then(|| {
        format!(
            "{} of {} faces have surfaces not converted to pieces (their type is in \"not_converted\"); their bounds and edges are written",
            m.faces.len() - converted,
            m.faces.len()
        )
    })
}

/// The model object: `{"kind": "brep", "bodies", "loose_shells",
/// "occurrences", "contexts", "summary", "unattached", "message"?}` (the faces, edges and
/// vertices are written beside it by [`brep_to_json`] or as lines by
/// [`brep_to_lines`]).
///
/// # Errors
///
/// The piece writer's errors (for the unattached B-spline pieces).
pub fn brep_model_json(m: &BrepModel, write: PieceWriter) -> Result<Value, Error> {
    let bodies: Vec<Value> = m
        .bodies
        .iter()
        .map(|b| {
            let solids: Vec<Value> = b
                .solids
                .iter()
                .filter_map(|s| m.solids.get(s))
                .map(|s| json!({"id": id(s.id), "type": s.kind, "shells": s.shells.iter().map(shell_json).collect::<Vec<_>>()}))
                .collect();
            json!({"id": id(b.id), "type": b.kind, "name": b.name, "solids": solids, "context": b.context.map(id)})
        })
        .collect();
    let contexts: Vec<Value> = m
        .contexts
        .values()
        .map(|c| {
            json!({
                "id": id(c.id),
                "length_unit": c.length.as_ref().map(|l| json!({"name": l.name, "metres": l.metres.to_json()})),
                "angle_unit": c.angle.as_ref().map(angle_json),
                "tolerance": c.tolerance.as_ref().map(JsonScalar::to_json),
            })
        })
        .collect();
    let occurrences: Vec<Value> = m.occurrences.iter().map(occurrence_json).collect();
    let s = &m.summary;
    let uses: Map<String, Value> = s
        .edge_uses
        .iter()
        .map(|(u, n)| (usage_name(*u).to_owned(), json!(n)))
        .collect();
    let used: BTreeSet<u64> = m
        .faces
        .values()
        .map(|f| f.surface.entity)
        .chain(m.edges.values().map(|e| e.curve.entity))
        .chain(
            m.edges
                .values()
                .flat_map(|e| e.pcurves.iter().map(|p| p.curve.entity)),
        )
        .collect();
    let mut unattached = Vec::new();
    for e in m.geometry.entities.iter().filter(|e| !used.contains(&e.id)) {
        let g = GeometryRef {
            entity: e.id,
            kind: e.name.clone(),
            geometry: Geometry::BSpline(BSpline::new(e.nurbs.clone())),
        };
        unattached.push(geometry_json(&g, &e.faces, write)?);
    }
    let mut o = json!({
        "kind": "brep",
        "bodies": bodies,
        "loose_shells": m.loose_shells.iter().map(shell_json).collect::<Vec<_>>(),
        "occurrences": occurrences,
        "contexts": contexts,
        "summary": {
            "faces": m.faces.len(),
            "edges": m.edges.len(),
            "vertices": m.vertices.len(),
            "occurrences": m.occurrences.len(),
            "faces_by_surface": s.faces_by_surface,
            "edges_by_curve": s.edges_by_curve,
            "not_converted": s.not_converted,
            "pcurves_not_converted": s.pcurves_not_converted,
            "approximate": s.approximate,
            "edge_uses": uses,
            "not_applied": s.not_applied,
            "invalid_entities": s.invalid.iter().chain(&m.geometry.invalid).map(|(e, r)| json!({"entity": id(*e), "reason": r})).collect::<Vec<_>>(),
        },
        "unattached": unattached,
    });
    if let Some(msg) = message(m) {
        o["message"] = json!(msg);
    }
    Ok(o)
}

/// The faces, edges and vertices of `m` as JSON, each passed through
/// `finish` on the core that wrote it.
fn parts<T: Send>(
    m: &BrepModel,
    write: PieceWriter,
    finish: impl Fn(Value) -> T + Sync,
) -> Result<[Vec<T>; 3], Error> {
    m.convert_pieces();
    let faces: Vec<&Face> = m.faces.values().collect();
    let edges: Vec<&Edge> = m.edges.values().collect();
    let faces = on_all_cores(&faces, |f| face_to_json(f, write).map(&finish))?;
    let edges = on_all_cores(&edges, |e| edge_to_json(e, write).map(&finish))?;
    let vertices: Vec<_> = m.vertices.iter().collect();
    let vertices = on_all_cores(&vertices, |&(&v, p)| {
        Ok(finish(
            json!({"kind": "vertex", "id": id(v), "point": point_to_json(p)}),
        ))
    })?;
    Ok([faces, edges, vertices])
}

/// `f` of every item, in order, computed on all cores under this thread's
/// limits; the first error in order, if any.
fn on_all_cores<I: Sync, T: Send, F>(items: &[I], f: F) -> Result<Vec<T>, Error>
where
    F: Fn(&I) -> Result<T, Error> + Sync,
{
    let limits = crate::limits::current();
    let results: Vec<Result<T, Error>> = items
        .par_iter()
        .map(|x| crate::limits::with_limits(limits, || f(x)))
        .collect();
    results.into_iter().collect()
}

/// The whole B-rep as one JSON document: the model object of
/// [`brep_model_json`] with `"faces"`, `"edges"` and `"vertices"` arrays.
///
/// # Errors
///
/// The piece writer's errors.
pub fn brep_to_json(m: &BrepModel, write: PieceWriter) -> Result<Value, Error> {
    let mut o = brep_model_json(m, write)?;
    let [faces, edges, vertices] = parts(m, write, |v| v)?;
    o["faces"] = Value::Array(faces);
    o["edges"] = Value::Array(edges);
    o["vertices"] = Value::Array(vertices);
    Ok(o)
}

/// The B-rep as JSON Lines: one face a line, then one edge, one vertex a
/// line, then the model object (so a reader streams the faces and finds
/// the summary at the end).
#[derive(Clone, Debug)]
pub struct BrepLines {
    /// One compact JSON text per face, edge and vertex, in that order
    /// (written on all cores, each without its newline).
    pub items: Vec<String>,
    /// The model object of [`brep_model_json`], the last line.
    pub model: Value,
}

/// The B-rep as [`BrepLines`]. Each item is written as text on the core
/// that built it, so the JSON values of the whole model never coexist.
///
/// # Errors
///
/// The piece writer's errors.
pub fn brep_to_lines(m: &BrepModel, write: PieceWriter) -> Result<BrepLines, Error> {
    let [mut items, edges, vertices] = parts(m, write, |v| v.to_string())?;
    items.extend(edges);
    items.extend(vertices);
    Ok(BrepLines {
        items,
        model: brep_model_json(m, write)?,
    })
}
