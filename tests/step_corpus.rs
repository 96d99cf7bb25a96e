//! The public STEP corpus (tests/fixtures/step/, provenance in its README):
//! the B-rep reader's counts against the independent counter's
//! (`benches/peers/step_counts.py`, pure Python, its output in
//! `counts.json`), and the exact analytic geometry of whole models: every
//! edge's pieces end within the file's tolerance of its vertices.

use exact_bezier::algebra::{RealAlgebraic, Scalar};
use exact_bezier::step::brep::{EdgeUse, Geometry};
use exact_bezier::step::{read_brep_with, BrepModel, BrepOptions};
use num_rational::BigRational;
use serde_json::Value;
use std::collections::BTreeMap;

fn dir() -> String {
    format!("{}/tests/fixtures/step", env!("CARGO_MANIFEST_DIR"))
}

fn read(name: &str, analytic: bool) -> BrepModel {
    let bytes = std::fs::read(format!("{}/{name}", dir())).unwrap();
    read_brep_with(&bytes[..], BrepOptions { analytic }).unwrap()
}

/// B-spline surface and curve names differ between the two readers for
/// complex instances (which part names the entity): they are compared
/// as one class.
fn class(name: &str) -> String {
    if name.contains("B_SPLINE") || name.contains("BEZIER") {
        "B-spline".into()
    } else {
        name.into()
    }
}

fn classes<'a>(counts: impl Iterator<Item = (&'a String, usize)>) -> BTreeMap<String, usize> {
    let mut out = BTreeMap::new();
    for (k, n) in counts {
        *out.entry(class(k)).or_insert(0) += n;
    }
    out
}

fn json_counts(v: &Value) -> BTreeMap<String, usize> {
    let owned: Vec<(String, usize)> = v
        .as_object()
        .unwrap()
        .iter()
        .map(|(k, n)| (k.clone(), n.as_u64().unwrap() as usize))
        .collect();
    classes(owned.iter().map(|(k, n)| (k, *n)))
}

#[test]
fn every_corpus_file_counts_as_the_independent_counter() {
    let text = std::fs::read_to_string(format!("{}/counts.json", dir())).unwrap();
    let counts: Value = serde_json::from_str(&text).unwrap();
    let files = counts.as_object().unwrap();
    assert!(files.len() >= 19, "{} files", files.len());
    for (name, want) in files {
        let m = read(name, false);
        assert!(
            m.summary.invalid.is_empty(),
            "{name}: {:?}",
            m.summary.invalid
        );
        let faces = classes(m.summary.faces_by_surface.iter().map(|(k, n)| (k, *n)));
        assert_eq!(
            faces,
            json_counts(&want["faces"]["by_surface"]),
            "{name}: faces"
        );
        let edges = classes(m.summary.edges_by_curve.iter().map(|(k, n)| (k, *n)));
        assert_eq!(
            edges,
            json_counts(&want["edges"]["by_curve_3d"]),
            "{name}: edges"
        );
        let uses = &want["edge_uses"];
        for (u, key) in [
            (EdgeUse::Shared, "shared"),
            (EdgeUse::Seam, "seam"),
            (EdgeUse::Open, "open"),
            (EdgeUse::NonManifold, "non_manifold"),
        ] {
            let ours = m.summary.edge_uses.get(&u).copied().unwrap_or(0) as u64;
            assert_eq!(Some(ours), uses[key].as_u64(), "{name}: {key} edges");
        }
    }
}

/// The model's declared tolerance squared (the first context that has one).
fn tolerance_sq(m: &BrepModel) -> BigRational {
    let t = m
        .contexts
        .values()
        .find_map(|c| c.tolerance.clone())
        .expect("a declared tolerance");
    t.clone() * t
}

/// Files of four systems whose every face and edge is analytic or B-spline.
const WHOLE: [&str; 4] = [
    "screw.step",
    "red_cube_blue_cylinder.step",
    "revolved_vase_occt.step",
    "0045_bb_boxblend_03_colored_mirrored.stp",
];

#[test]
fn analytic_models_are_converted_whole_and_edges_meet_their_vertices() {
    for name in WHOLE {
        let m = read(name, true);
        let tol2 = RealAlgebraic::from_rational(&tolerance_sq(&m));
        assert!(
            m.summary.not_converted.is_empty(),
            "{name}: {:?}",
            m.summary.not_converted
        );
        for f in m.faces.values() {
            assert!(
                matches!(
                    f.surface.geometry,
                    Geometry::Analytic(_) | Geometry::Pieces(_)
                ),
                "{name}: face #{} {:?}",
                f.id,
                f.surface.geometry
            );
        }
        for e in m.edges.values() {
            match &e.curve.geometry {
                Geometry::Analytic(a) => {
                    let [d0, d1] = a.vertex_distance_sq.as_ref().unwrap();
                    assert!(d0 <= &tol2 && d1 <= &tol2, "{name}: edge #{}", e.id);
                    // The pieces join end to start exactly.
                    for w in a.pieces.windows(2) {
                        let end = last_point(&w[0]);
                        assert_eq!(end, first_point(&w[1]), "{name}: edge #{}", e.id);
                    }
                }
                Geometry::Pieces(_) => {}
                g => panic!("{name}: edge #{} {g:?}", e.id),
            }
        }
    }
}

fn curve_ends(
    p: &exact_bezier::patch::Patch<RealAlgebraic>,
) -> (Vec<RealAlgebraic>, Vec<RealAlgebraic>) {
    match p {
        exact_bezier::patch::Patch::Curve(c) => {
            let pts = c.points().unwrap();
            (pts[0].clone(), pts[pts.len() - 1].clone())
        }
        _ => panic!("an edge piece is a curve"),
    }
}

fn first_point(p: &exact_bezier::patch::Patch<RealAlgebraic>) -> Vec<RealAlgebraic> {
    curve_ends(p).0
}

fn last_point(p: &exact_bezier::patch::Patch<RealAlgebraic>) -> Vec<RealAlgebraic> {
    curve_ends(p).1
}

#[test]
fn cylinder_pieces_lie_on_the_cylinder_of_the_file() {
    // red_cube_blue_cylinder.step, lines 93, 133, 195–197: CYLINDRICAL_SURFACE
    // #103 of radius 0.005 on the placement at (0.01, 0.005, 0.01) with axis
    // (0, 0, 1). Every piece corner (corners interpolate) is at distance
    // exactly 1/200 from the axis.
    let m = read("red_cube_blue_cylinder.step", true);
    let face = m
        .faces
        .values()
        .find(|f| f.surface.kind == "CYLINDRICAL_SURFACE")
        .unwrap();
    let Geometry::Analytic(a) = &face.surface.geometry else {
        panic!("converted")
    };
    assert_eq!(a.pieces.len(), 4);
    let r = |n: i64, d: i64| RealAlgebraic::from_rational(&BigRational::new(n.into(), d.into()));
    for p in &a.pieces {
        let exact_bezier::patch::Patch::Rect(rect) = p else {
            panic!("a rect piece")
        };
        let grid = rect.points().unwrap();
        for row in [&grid[0], &grid[grid.len() - 1]] {
            for c in [&row[0], &row[row.len() - 1]] {
                let (x, y) = (c[0].clone() - r(1, 100), c[1].clone() - r(1, 200));
                assert_eq!(x.clone() * &x + &(y.clone() * &y), r(1, 40000));
            }
        }
    }
}

/// The B-rep audit classifies every edge of every corpus model as the
/// independent counter does (shared / seam / open / non-manifold from the
/// loops), finds no open edge in a model whose shells are all closed, and
/// takes a declared `UNCERTAINTY_MEASURE_WITH_UNIT` as its length
/// tolerance (one of the counter's values, parsed here).
#[test]
fn brep_audit_classifies_edges_as_the_independent_counter() {
    use exact_bezier::audit::brep::ToleranceSource;
    use exact_bezier::audit::brep::{audit_brep, default_angle_tolerance, EdgeClass};
    let text = std::fs::read_to_string(format!("{}/counts.json", dir())).unwrap();
    let counts: Value = serde_json::from_str(&text).unwrap();
    for (name, want) in counts.as_object().unwrap() {
        let m = read(name, false);
        let a = audit_brep(&m, None, default_angle_tolerance());
        let uses = &want["edge_uses"];
        for c in [
            EdgeClass::Shared,
            EdgeClass::Seam,
            EdgeClass::Open,
            EdgeClass::NonManifold,
        ] {
            assert_eq!(
                Some(a.count(c) as u64),
                uses[c.name()].as_u64(),
                "{name}: {} edges",
                c.name()
            );
        }
        let shells = m
            .solids
            .values()
            .flat_map(|s| &s.shells)
            .chain(&m.loose_shells);
        if shells.clone().count() > 0 && shells.clone().all(|s| s.closed) {
            assert_eq!(a.count(EdgeClass::Open), 0, "{name}: a closed model");
        }
        let declared = want["contexts"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|c| c["uncertainty"].as_array().cloned().unwrap_or_default())
            .filter(|u| u["measure"] == "LENGTH_MEASURE")
            .map(|u| exact_bezier::algebra::parse_rational(u["value"].as_str().unwrap()).unwrap())
            .collect::<Vec<_>>();
        // The counter lists every context of the file; ours are the
        // bodies' contexts: our tolerance is one of the declared values.
        match &a.tolerance.length {
            Some(t) => assert!(declared.contains(t), "{name}: tolerance {t}"),
            None => assert!(declared.is_empty(), "{name}: tolerance"),
        }
        let source = if !declared.is_empty() {
            ToleranceSource::Declared
        } else {
            ToleranceSource::None
        };
        assert_eq!(a.tolerance.source, source, "{name}");
        assert_eq!(a.faces(), m.faces.len(), "{name}: faces");
    }
}
