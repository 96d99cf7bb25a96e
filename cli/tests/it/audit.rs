//! `audit` on real models: Newell's teapot, the bowl of source 002, a
//! cylinder and a torus built from exact rational circles, a B-spline
//! surface split at an inner knot; `convert --to bezier` on NURBS and STEP.
//! Verdicts are checked against independent computations (control-point
//! conditions, brute-force edge matching, f64 normals), never against the
//! audit's own output.

use crate::common::{cli, cli_json};
use exact_bezier::{
    audit::audit, audit::Continuity, audit::Model, audit::Piece, io::read_model,
    io::read_trig_patches, trig::TrigPatch, Patch, RectPatch,
};
use num_rational::BigRational;
use serde_json::Value;

type Q = BigRational;

fn fixture(name: &str) -> String {
    format!(
        "{}/tests/fixtures/{name}",
        concat!(env!("CARGO_MANIFEST_DIR"), "/..")
    )
}

fn model(name: &str) -> Model {
    read_model(std::io::BufReader::new(
        crate::common::open(fixture(name)).unwrap(),
    ))
    .unwrap()
}

fn rect(m: &Model, k: usize) -> &RectPatch<Q> {
    match &m.pieces[k].patch {
        Patch::Rect(r) => r,
        _ => panic!("rect"),
    }
}

fn sub(a: &[Q], b: &[Q]) -> Vec<Q> {
    a.iter().zip(b).map(|(x, y)| x - y).collect()
}

/// The boundary control points of edge `e` ("u=0", …) in edge order, and
/// the next row inward.
fn edge_rows(r: &RectPatch<Q>, e: &str) -> (Vec<Vec<Q>>, Vec<Vec<Q>>) {
    let p = r.points().unwrap();
    let (m, n) = r.degree();
    let col = |j: usize| p.iter().map(|row| row[j].clone()).collect::<Vec<_>>();
    match e {
        "u=0" => (p[0].clone(), p[1].clone()),
        "u=1" => (p[m].clone(), p[m - 1].clone()),
        "v=0" => (col(0), col(1)),
        "v=1" => (col(n), col(n - 1)),
        _ => panic!("edge {e}"),
    }
}

#[test]
fn teapot_seams_open_and_degenerate_edges_checked_independently() {
    let m = model("teapot.json");
    let a = audit(&m).unwrap();
    assert_eq!(a.patches, 32);
    let json = exact_bezier::io::audit_to_json(&a, &m);
    // Independent seam finding: two edges are shared iff their control
    // points agree in order or reversed (the teapot has no reparameterized
    // edges); collapsed edges have one point four times.
    let edges = ["u=0", "u=1", "v=0", "v=1"];
    let mut shared = 0;
    let mut degenerate = 0;
    let mut open = 0;
    for i in 0..32 {
        for e in edges {
            let (row, _) = edge_rows(rect(&m, i), e);
            if row.iter().all(|p| *p == row[0]) {
                degenerate += 1;
                continue;
            }
            let mut rev = row.clone();
            rev.reverse();
            let partners = (0..32)
                .flat_map(|j| edges.map(|f| (j, f)))
                .filter(|&(j, f)| (j, f) != (i, e))
                .filter(|&(j, f)| {
                    let other = edge_rows(rect(&m, j), f).0;
                    other == row || other == rev
                })
                .count();
            if partners == 0 {
                open += 1;
            }
            shared += partners;
        }
    }
    assert_eq!(a.seams.len(), shared / 2);
    assert_eq!(a.open_edges.len(), open);
    assert_eq!(a.degenerate_edges.len(), degenerate);
    assert!(a.seams.len() >= 40 && degenerate >= 8, "{}", a.summary());
    // Verdicts: where the cross-boundary control points are collinear with
    // one constant ratio (b₁ − b₀ = −λ (a₁ − a₀), λ > 0, the same λ for every
    // column), the join is C¹ after scaling — at least G¹.
    let mut checked = 0;
    for (s, sj) in a.seams.iter().zip(json["seams"].as_array().unwrap()) {
        let (ea, eb) = (
            sj["a"]["edge"].as_str().unwrap(),
            sj["b"]["edge"].as_str().unwrap(),
        );
        let (a0, a1) = edge_rows(rect(&m, s.a.patch), ea);
        let (mut b0, mut b1) = edge_rows(rect(&m, s.b.patch), eb);
        if b0 != a0 {
            b0.reverse();
            b1.reverse();
        }
        assert_eq!(a0, b0);
        let da: Vec<Vec<Q>> = a1.iter().zip(&a0).map(|(x, y)| sub(x, y)).collect();
        let db: Vec<Vec<Q>> = b1.iter().zip(&b0).map(|(x, y)| sub(x, y)).collect();
        let ratio = |u: &[Q], v: &[Q]| -> Option<Q> {
            let k = u.iter().position(|x| *x != Q::from_integer(0.into()))?;
            let r = -(v[k].clone() / &u[k]);
            (u.iter().zip(v).all(|(x, y)| *y == -(x * &r)) && r > Q::from_integer(0.into()))
                .then_some(r)
        };
        let ratios: Vec<Option<Q>> = da.iter().zip(&db).map(|(u, v)| ratio(u, v)).collect();
        if ratios.iter().all(|r| r.is_some() && *r == ratios[0]) {
            checked += 1;
            assert!(
                s.verdict.continuity >= Some(Continuity::G1),
                "{:?}: {}",
                (s.a, s.b),
                s.verdict.reason
            );
        }
    }
    assert!(
        checked >= 30,
        "only {checked} seams met the control-point condition"
    );
}

#[test]
fn cylinder_from_four_rational_arcs_is_g2_everywhere() {
    let m = model("cylinder.json");
    let a = audit(&m).unwrap();
    // Four arcs: four seams (the last closes the circle), the 8 rims open.
    assert_eq!(
        (
            a.patches,
            a.seams.len(),
            a.open_edges.len(),
            a.degenerate_edges.len()
        ),
        (4, 4, 8, 0),
        "{}",
        a.summary()
    );
    for s in &a.seams {
        assert_eq!(
            s.verdict.continuity,
            Some(Continuity::G2),
            "{}",
            s.verdict.reason
        );
    }
    // Every piece lies on x² + y² = 1, exactly.
    for k in 0..4 {
        let x = rect(&m, k)
            .eval(&Q::new(2.into(), 7.into()), &Q::new(1.into(), 3.into()))
            .unwrap();
        assert_eq!(
            x[0].clone() * &x[0] + x[1].clone() * &x[1],
            Q::from_integer(1.into())
        );
    }
}

#[test]
fn torus_is_closed_and_g2_everywhere() {
    let m = model("torus.json");
    let a = audit(&m).unwrap();
    assert_eq!(
        (a.patches, a.seams.len(), a.open_edges.len()),
        (16, 32, 0),
        "{}",
        a.summary()
    );
    assert_eq!(a.counts(), [0, 0, 32, 0]);
    // Independently: a point of each piece satisfies the torus equation
    // (x² + y² + z² + R² − r²)² = 4R²(x² + y²), R = 3, r = 1.
    let c = |n: i64| Q::from_integer(n.into());
    for k in 0..16 {
        let x = rect(&m, k)
            .eval(&Q::new(1.into(), 5.into()), &Q::new(3.into(), 4.into()))
            .unwrap();
        let rho = x[0].clone() * &x[0] + x[1].clone() * &x[1];
        let lhs = rho.clone() + x[2].clone() * &x[2] + c(8);
        assert_eq!(lhs.clone() * &lhs, c(36) * rho);
    }
}

#[test]
fn split_at_an_inner_knot_the_halves_meet_g2_on_one_surface() {
    let m = model("split_surface.json");
    let a = audit(&m).unwrap();
    assert_eq!((a.patches, a.seams.len(), a.open_edges.len()), (2, 1, 6));
    assert_eq!(
        a.seams[0].verdict.continuity,
        Some(Continuity::G2),
        "{}",
        a.seams[0].verdict.reason
    );
    let same = &exact_bezier::io::audit_to_json(&a, &m)["same_surface"];
    assert_eq!(same[0]["patches"], serde_json::json!([0, 1]));
}

/// The bowl of source 002 in its exact rational form: the G¹-stitched bowl
/// audits G¹ (or better) at every seam; the unstitched bowl has a G⁰ seam.
#[test]
fn bowl_of_source_002_exact_rational_form() {
    let verdicts = |name: &str| {
        let trig = read_trig_patches(&crate::common::read_to_string(fixture(name)).unwrap())
            .unwrap()
            .unwrap();
        let pieces = trig
            .iter()
            .map(|p| match p {
                TrigPatch::Rect(r) => Piece {
                    patch: Patch::Rect(r.to_rational()),
                    origin: Default::default(),
                },
                TrigPatch::Curve(_) => panic!("the bowl is made of trig-rects"),
            })
            .collect();
        let m = Model {
            pieces,
            ..Model::default()
        };
        let a = audit(&m).unwrap();
        assert!(!a.seams.is_empty(), "{}", a.summary());
        a.seams
            .iter()
            .map(|s| s.verdict.continuity)
            .collect::<Vec<_>>()
    };
    let g1 = verdicts("bowl.json");
    assert!(g1.iter().all(|v| *v >= Some(Continuity::G1)), "{g1:?}");
    let g0 = verdicts("bowl_g0.json");
    assert!(g0.contains(&Some(Continuity::G0)), "{g0:?}");
}

#[test]
fn cli_audit_and_convert_to_bezier() {
    let (code, v) = cli_json(&["audit", "tests/fixtures/cylinder.json", "--summary"]);
    assert_eq!(code, 0);
    assert_eq!(v["counts"]["G2"], 4);
    let (code, v) = cli_json(&[
        "convert",
        "tests/fixtures/split_surface.json",
        "--to",
        "bezier",
    ]);
    assert_eq!(code, 0);
    let pieces = v.as_array().unwrap();
    assert_eq!(pieces.len(), 2);
    assert_eq!(pieces[1]["origin"]["span_u"], serde_json::json!(["1/2", 1]));
    assert_eq!(pieces[1]["kind"], "rect");
    let (code, _, err) = cli(&["audit", "tests/fixtures/README.md"]);
    assert_eq!(code, 2);
    assert!(err.starts_with("error: malformed input"), "{err}");
}

#[test]
fn step_file_convert_and_audit() {
    // Two bilinear B-spline faces sharing the edge x = 1, written with
    // reals in STEP syntax; the second surface's edge runs backwards.
    let step = "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n\
#1=CARTESIAN_POINT('',(0.,0.,0.));#2=CARTESIAN_POINT('',(0.,1.,0.));\
#3=CARTESIAN_POINT('',(1.,0.,0.));#4=CARTESIAN_POINT('',(1.,1.,0.));\
#5=CARTESIAN_POINT('',(2.,0.,5.E-1));#6=CARTESIAN_POINT('',(2.,1.,5.E-1));\
#10=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#1,#2),(#3,#4)),.UNSPECIFIED.,.F.,.F.,.F.,(2,2),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.);\
#11=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#4,#3),(#6,#5)),.UNSPECIFIED.,.F.,.F.,.F.,(2,2),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.);\
#20=ADVANCED_FACE('',(),#10,.T.);#21=ADVANCED_FACE('',(),#11,.T.);#22=AXIS2_PLACEMENT_3D('',#1,$,$);\nENDSEC;\nEND-ISO-10303-21;\n";
    let path = std::env::temp_dir().join(format!("exact_bezier_audit_{}.stp", std::process::id()));
    std::fs::write(&path, step).unwrap();
    let p = path.to_str().unwrap();
    let (code, v) = cli_json(&["audit", p]);
    assert_eq!(code, 0);
    assert_eq!(v["seams"].as_array().unwrap().len(), 1);
    let seam = &v["seams"][0];
    assert_eq!(seam["continuity"], "G0", "{seam}");
    assert_eq!(seam["reversed"], true);
    assert_eq!(seam["a"]["origin"]["faces"], serde_json::json!(["#20"]));
    assert_eq!(v["skipped_entities"]["AXIS2_PLACEMENT_3D"], 1);
    let (code, v) = cli_json(&["convert", p, "--to", "bezier"]);
    assert_eq!(code, 0);
    let piece = &v["faces"][1]["surface"]["pieces"][0];
    assert_eq!(piece["origin"]["entity"], "#11");
    assert_eq!(piece["points"][1][1], serde_json::json!([2, 0, "1/2"]));
    std::fs::remove_file(&path).unwrap();
    let _: Value = v;
}

#[test]
fn audit_plot_writes_a_png_and_refuses_other_names() {
    let out = std::env::temp_dir().join(format!("exact_bezier_audit_{}.png", std::process::id()));
    let o = out.to_str().unwrap();
    let (code, _) = cli_json(&[
        "audit",
        "tests/fixtures/split_surface.json",
        "--summary",
        "--plot",
        o,
    ]);
    assert_eq!(code, 0);
    let png = std::fs::read(&out).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    std::fs::remove_file(&out).unwrap();
    let (code, _, err) = cli(&[
        "audit",
        "tests/fixtures/split_surface.json",
        "--plot",
        "x.svg",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains(".png"), "{err}");
}

/// geomdl's `exchange.export_json` layout (geomdl 5 field names and the
/// newer `degree`/`knotvector`/`size` lists) gives the same pieces as our
/// `nurbs-surface` object; a geomdl curve too.
#[test]
fn geomdl_json_layouts_read_as_our_nurbs() {
    use exact_bezier::io::{read_nurbs, read_patches};
    let ours = r#"{"kind": "nurbs-surface", "degree": [2, 1], "knots": [[0,0,0,"1/2",1,1,1],[0,0,1,1]],
        "points": [[[0,0,0],[0,1,0]],[[1,0,1],[1,1,1]],[[2,0,0],[2,1,"0.5"]],[[3,0,1],[3,1,0]]],
        "weights": [[1,2],[1,1],[3,1],[1,1]]}"#;
    let flat = r#"[[0,0,0],[0,1,0],[1,0,1],[1,1,1],[2,0,0],[2,1,0.5],[3,0,1],[3,1,0]]"#;
    let v5 = format!(
        r#"{{"shape": {{"type": "surface", "count": 1, "data": [{{"type": "spline", "rational": true,
        "degree_u": 2, "degree_v": 1, "knotvector_u": [0,0,0,0.5,1,1,1], "knotvector_v": [0,0,1,1],
        "size_u": 4, "size_v": 2, "control_points": {{"points": {flat}, "weights": [1,2,1,1,3,1,1,1]}}}}]}}}}"#
    );
    let v6 = format!(
        r#"{{"shape": {{"type": "surface", "count": 1, "data": [{{"type": "spline", "rational": true,
        "degree": [2, 1], "knotvector": [[0,0,0,0.5,1,1,1],[0,0,1,1]], "size": [4, 2],
        "control_points": {{"points": {flat}, "weights": [1,2,1,1,3,1,1,1]}}}}]}}}}"#
    );
    let want = read_patches(ours).unwrap();
    assert_eq!(want.len(), 2);
    assert_eq!(read_patches(&v5).unwrap(), want);
    assert_eq!(read_patches(&v6).unwrap(), want);
    let curve = r#"{"shape": {"type": "curve", "data": [{"degree": 1, "knotvector": [0,0,0.25,1,1],
        "control_points": {"points": [[0,0],[1,0],[1,1]]}}]}}"#;
    let n = read_nurbs(&serde_json::from_str(curve).unwrap()).unwrap();
    let spans: Vec<[Q; 2]> = n[0].pieces().into_iter().map(|p| p.u).collect();
    assert_eq!(spans.len(), 2);
    assert_eq!(spans[0][1], Q::new(1.into(), 4.into()));
    // A wrong size is a typed error, not a panic.
    let bad = v6.replace("[4, 2]", "[3, 2]");
    assert!(read_patches(&bad)
        .unwrap_err()
        .to_string()
        .contains("size 3×2"));
}

/// `text` with every non-zero coordinate of every `CARTESIAN_POINT` moved
/// by 1 to 3 units in the last place of its `f64` value (cycling +1, −2,
/// +3, …) and written back as the shortest decimal of that `f64`: the
/// model as an exporter that rounds through `f64` would write it. Zero
/// stays zero (a rounding of 0 is 0).
fn moved_by_ulps(text: &str) -> String {
    const NAME: &str = "CARTESIAN_POINT(";
    let mut out = String::with_capacity(text.len() + text.len() / 4);
    let mut rest = text;
    let mut k = 0u64;
    while let Some(at) = rest.find(NAME) {
        let body = at + NAME.len();
        out.push_str(&rest[..body]);
        // Skip the quoted name (`''` is a quote inside it), then take the
        // parenthesized coordinate list.
        let after_name = skip_quoted(&rest[body..]) + body;
        let open = after_name + rest[after_name..].find('(').expect("a coordinate list");
        let close = open + rest[open..].find(')').expect("a closed list");
        out.push_str(&rest[body..=open]);
        let coords: Vec<String> = rest[open + 1..close]
            .split(',')
            .map(|c| {
                k += 1;
                moved(c.trim(), k)
            })
            .collect();
        out.push_str(&coords.join(","));
        rest = &rest[close..];
    }
    out.push_str(rest);
    out
}

/// The index just past a leading `'…'` string of `s` (0 if none).
fn skip_quoted(s: &str) -> usize {
    let Some(start) = s.find('\'') else { return 0 };
    let mut i = start + 1;
    let bytes = s.as_bytes();
    while i < bytes.len() {
        if bytes[i] == b'\'' {
            if bytes.get(i + 1) == Some(&b'\'') {
                i += 2;
                continue;
            }
            return i + 1;
        }
        i += 1;
    }
    s.len()
}

/// A STEP real moved by `1 + (k mod 3)` ulps, up for odd `k`, down for
/// even, written with a decimal point as STEP requires.
fn moved(real: &str, k: u64) -> String {
    let x: f64 = real.parse().unwrap_or_else(|_| panic!("a real: {real:?}"));
    if x == 0.0 {
        return real.to_string();
    }
    let steps = 1 + k % 3;
    let bits = if (k % 2 == 1) == (x > 0.0) {
        x.to_bits() + steps
    } else {
        x.to_bits() - steps
    };
    let y = f64::from_bits(bits);
    assert!(y.is_finite() && y != x && (y > 0.0) == (x > 0.0));
    let shown = format!("{y:?}").replace('e', "E");
    match shown.find('E') {
        Some(e) if !shown[..e].contains('.') => format!("{}.{}", &shown[..e], &shown[e..]),
        _ => shown,
    }
}

/// Issue 28, "stable under rounding": the edge classes and the continuity
/// verdicts of real models, with the default tolerances, are the same after
/// every coordinate is moved by a few ulps through `f64`. Only the count of
/// *exact* verdicts may fall (an exact 0 deviation becomes a tiny one,
/// within tolerance).
#[test]
fn brep_verdicts_are_stable_under_f64_rounding() {
    for name in ["sg1-c5-214.stp", "0058_isolated_blends_test_12.stp"] {
        let path = fixture(&format!("step/{name}"));
        let text = crate::common::read_to_string(&path).unwrap();
        let moved_text = moved_by_ulps(&text);
        assert_ne!(moved_text, text, "{name}: nothing moved");
        let moved_path =
            std::env::temp_dir().join(format!("eb-ulps-{}-{name}", std::process::id()));
        std::fs::write(&moved_path, &moved_text).unwrap();
        let (code, before) = cli_json(&["audit", &path, "--summary"]);
        assert_eq!(code, 0, "{name}: {before}");
        let (code, after) = cli_json(&["audit", moved_path.to_str().unwrap(), "--summary"]);
        assert_eq!(code, 0, "{name} moved: {after}");
        assert_eq!(before["edges"], after["edges"], "{name}");
        assert_eq!(before["faces"], after["faces"], "{name}");
        for order in ["G2", "G1", "G0", "fails", "undecided", "not_measured"] {
            assert_eq!(
                before["continuity"][order], after["continuity"][order],
                "{name}: {order} changed; before {}, after {}",
                before["continuity"], after["continuity"]
            );
        }
        let exact = |v: &Value| v["continuity"]["exact"].as_u64().unwrap();
        assert!(exact(&after) <= exact(&before), "{name}");
        std::fs::remove_file(&moved_path).ok();
    }
}

/// `audit --plot` of a STEP B-rep colours each edge by its verdict: every
/// grade the summary counts shows in its colour (over 50 pixels), and no
/// grade it does not count (under 20: a few blended pixels): the vase-like part `sg1-c5-214.stp` (G2 seams between its
/// cylinders and G0 creases), the red cube with its cylinder (only G0
/// edges). The counts come from the summary, the colours from the decoded
/// picture.
#[test]
fn brep_plot_colours_edges_by_verdict() {
    // The plot palette (src/render/plot/svg.rs) by continuity count.
    const COLOURS: [(&str, [u8; 3]); 6] = [
        ("G2", [0x2c, 0xa0, 0x2c]),
        ("G1", [0x1f, 0x77, 0xb4]),
        ("G0", [0xd6, 0x27, 0x28]),
        ("fails", [0xe3, 0x77, 0xc2]),
        ("undecided", [0xff, 0x7f, 0x0e]),
        ("not_measured", [0x17, 0xbe, 0xcf]),
    ];
    let out = std::env::temp_dir().join(format!("eb-brep-plot-{}.png", std::process::id()));
    let o = out.to_str().unwrap();
    for model in ["step/sg1-c5-214.stp", "step/red_cube_blue_cylinder.step"] {
        let (code, v) = cli_json(&["audit", &fixture(model), "--summary", "--plot", o]);
        assert_eq!(code, 0, "{model}: {v}");
        let png = std::fs::read(&out).unwrap();
        let c = &v["continuity"];
        assert!(c["G0"].as_u64() > Some(0), "{model}: {c}");
        for (grade, rgb) in COLOURS {
            let pixels = crate::plot::pixels(&png, 800, 600, rgb).1;
            match c[grade].as_u64() {
                // Anti-aliased edges blend into a few pixels of any colour.
                Some(0) => assert!(
                    pixels < 20,
                    "{model}: no {grade} edge, yet {pixels} {grade} pixels"
                ),
                Some(_) => assert!(
                    pixels > 50,
                    "{model}: {grade} edges drawn in {pixels} pixels"
                ),
                None => panic!("{model}: no {grade} count in {c}"),
            }
        }
    }
    std::fs::remove_file(&out).ok();
    let (code, _, err) = cli(&["audit", &fixture("step/sg1-c5-214.stp"), "--plot", "x.svg"]);
    assert_eq!(code, 2);
    assert!(err.contains(".png"), "{err}");
}
