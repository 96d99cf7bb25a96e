use super::*;
use crate::algebra::{Ordered, RealAlgebraic, Scalar};
use crate::patch::Patch;
use crate::ratio;
use std::collections::BTreeMap;

type Q = BigRational;

fn q(n: i64, d: i64) -> Q {
    ratio(n, d)
}

pub(super) fn read(data: &str) -> BrepModel {
    let text =
        format!("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n{data}ENDSEC;\nEND-ISO-10303-21;\n");
    read_brep(text.as_bytes()).unwrap()
}

/// A unit square face z = 0 with four LINE edges, an open shell.
pub(super) const SQUARE: &str = "\
#1=CARTESIAN_POINT('',(0.,0.,0.));#2=CARTESIAN_POINT('',(1.,0.,0.));\n\
#3=CARTESIAN_POINT('',(1.,1.,0.));#4=CARTESIAN_POINT('',(0.,1.,0.));\n\
#11=VERTEX_POINT('',#1);#12=VERTEX_POINT('',#2);#13=VERTEX_POINT('',#3);#14=VERTEX_POINT('',#4);\n\
#21=EDGE_CURVE('',#11,#12,#31,.T.);#22=EDGE_CURVE('',#12,#13,#32,.T.);\n\
#23=EDGE_CURVE('',#13,#14,#33,.T.);#24=EDGE_CURVE('',#14,#11,#34,.T.);\n\
#31=LINE('',#1,#5);#32=LINE('',#2,#6);#33=LINE('',#3,#7);#34=LINE('',#4,#8);\n\
#5=VECTOR('',#15,1.);#6=VECTOR('',#16,1.);#7=VECTOR('',#17,1.);#8=VECTOR('',#18,1.);\n\
#15=DIRECTION('',(1.,0.,0.));#16=DIRECTION('',(0.,1.,0.));\n\
#17=DIRECTION('',(-1.,0.,0.));#18=DIRECTION('',(0.,-1.,0.));\n\
#9=AXIS2_PLACEMENT_3D('',#1,$,$);\n\
#41=ORIENTED_EDGE('',*,*,#21,.T.);#42=ORIENTED_EDGE('',*,*,#22,.T.);\n\
#43=ORIENTED_EDGE('',*,*,#23,.T.);#44=ORIENTED_EDGE('',*,*,#24,.T.);\n\
#50=EDGE_LOOP('',(#41,#42,#43,#44));#51=FACE_OUTER_BOUND('',#50,.T.);\n\
#52=PLANE('',#9);#53=ADVANCED_FACE('',(#51),#52,.T.);\n\
#60=OPEN_SHELL('',(#53));#61=SHELL_BASED_SURFACE_MODEL('',(#60));\n\
#62=MANIFOLD_SURFACE_SHAPE_REPRESENTATION('square',(#61),#70);\n";

/// A context in millimetres, degrees, tolerance 1/100 mm.
pub(super) const MM_DEG: &str = "\
#70=(GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#74))\n\
 GLOBAL_UNIT_ASSIGNED_CONTEXT((#71,#73)) REPRESENTATION_CONTEXT('',''));\n\
#71=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.));\n\
#72=(NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.));\n\
#75=PLANE_ANGLE_MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(0.0174532925),#72);\n\
#73=(CONVERSION_BASED_UNIT('DEGREE',#75) NAMED_UNIT(#76) PLANE_ANGLE_UNIT());\n\
#76=DIMENSIONAL_EXPONENTS(0.,0.,0.,0.,0.,0.,0.);\n\
#74=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-02),#71,'distance_accuracy_value','');\n";

#[test]
fn an_open_shell_its_edges_vertices_units_and_tolerance() {
    let m = read(&format!("{SQUARE}{MM_DEG}"));
    assert_eq!(m.bodies.len(), 1);
    assert_eq!(m.bodies[0].name, "square");
    assert_eq!(m.bodies[0].solids, [61]);
    let solid = &m.solids[&61];
    assert_eq!(solid.kind, "SHELL_BASED_SURFACE_MODEL");
    assert!(!solid.shells[0].closed);
    let face = &m.faces[&53];
    assert_eq!(face.surface.kind, "PLANE");
    // One bilinear patch covering the square's edges: the unit square.
    let Geometry::Analytic(a) = &face.surface.geometry else {
        panic!("a converted plane: {:?}", face.surface.geometry)
    };
    assert!(a.approximate.is_none());
    let [Patch::Rect(r)] = &a.pieces[..] else {
        panic!("one rect piece: {:?}", a.pieces)
    };
    let mut corners: Vec<Vec<Q>> = r
        .points()
        .unwrap()
        .into_iter()
        .flatten()
        .map(|p| p.iter().map(|x| x.as_rational().unwrap()).collect())
        .collect();
    corners.sort();
    let want = |x: i64, y: i64| vec![q(x, 1), q(y, 1), q(0, 1)];
    assert_eq!(corners, [want(0, 0), want(0, 1), want(1, 0), want(1, 1)]);
    // Each edge runs from its start vertex to its end exactly.
    for e in [21, 22, 23, 24] {
        let edge = &m.edges[&e];
        let Geometry::Analytic(a) = &edge.curve.geometry else {
            panic!("a converted line")
        };
        let zero = <crate::algebra::RealAlgebraic as crate::algebra::Scalar>::from_i64(0);
        assert_eq!(a.vertex_distance_sq, Some([zero.clone(), zero]));
    }
    let Loop::Edges(es) = &face.bounds[0].edges else {
        panic!("an edge loop")
    };
    let edges: Vec<u64> = es.iter().map(|e| e.edge).collect();
    assert_eq!(edges, [21, 22, 23, 24]);
    // Every edge of a lone face is open.
    assert_eq!(m.summary.edge_uses, BTreeMap::from([(EdgeUse::Open, 4)]));
    assert_eq!(m.vertices[&13], vec![q(1, 1), q(1, 1), q(0, 1)]);
    assert_eq!(m.edges[&23].start, 13);
    assert_eq!(m.summary.edges_by_curve["LINE"], 4);
    assert!(m.summary.not_converted.is_empty());
    let c = &m.contexts[&70];
    assert_eq!(c.length.as_ref().unwrap().metres, q(1, 1000));
    assert_eq!(c.angle, Some(AngleUnit::Degree));
    assert_eq!(c.tolerance, Some(q(1, 100)));
    assert!(m.summary.invalid.is_empty(), "{:?}", m.summary.invalid);
}

#[test]
fn a_face_on_a_rectangular_trim_is_its_basis_with_the_trims_orientation() {
    let face = "#53=ADVANCED_FACE('',(#51),#52,.T.);";
    let plain = read(&format!("{SQUARE}{MM_DEG}"));
    for (senses, same_sense) in [(".T.,.T.", true), (".T.,.F.", false), (".F.,.F.", true)] {
        // The trim, and a trim of the trim, of the square's plane.
        let trims = format!(
            "#53=ADVANCED_FACE('',(#51),#55,.T.);\n\
             #54=RECTANGULAR_TRIMMED_SURFACE('',#52,-1.,2.,-1.,2.,.T.,.T.);\n\
             #55=RECTANGULAR_TRIMMED_SURFACE('',#54,0.,1.,0.,1.,{senses});\n"
        );
        let m = read(&format!("{}{MM_DEG}", SQUARE.replace(face, &trims)));
        let f = &m.faces[&53];
        assert_eq!(
            (f.trimmed, f.same_sense),
            (Some(55), same_sense),
            "{senses}"
        );
        assert_eq!(f.surface.entity, 52);
        assert_eq!(m.summary.faces_by_surface["RECTANGULAR_TRIMMED_SURFACE"], 1);
        let pieces = |m: &BrepModel| match &m.faces[&53].surface.geometry {
            Geometry::Analytic(a) => a.pieces.clone(),
            g => panic!("a converted plane: {g:?}"),
        };
        assert_eq!(pieces(&m), pieces(&plain));
    }
    let cycle = SQUARE.replace(
        face,
        "#53=ADVANCED_FACE('',(#51),#54,.T.);#54=RECTANGULAR_TRIMMED_SURFACE('',#54,0.,1.,0.,1.,.T.,.T.);",
    );
    let m = read(&format!("{cycle}{MM_DEG}"));
    assert!(m
        .summary
        .invalid
        .iter()
        .any(|(id, why)| *id == 53 && why.contains("nested")));
}

#[test]
fn inch_and_metre_units_exactly() {
    let inch =
        "#70=(GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#74))\n\
 GLOBAL_UNIT_ASSIGNED_CONTEXT((#71)) REPRESENTATION_CONTEXT('',''));\n\
#77=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.));\n\
#78=LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#77);\n\
#71=(CONVERSION_BASED_UNIT('INCH',#78) LENGTH_UNIT() NAMED_UNIT(#76));\n\
#76=DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n\
#74=UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(0.0508),#77,'distance_accuracy_value','');\n";
    let m = read(&format!("{SQUARE}{inch}"));
    let c = &m.contexts[&70];
    let l = c.length.as_ref().unwrap();
    // 1 in = 25.4 mm = 127/5000 m; 0.0508 mm = 1/500 in.
    assert_eq!((l.name.as_str(), l.metres.clone()), ("INCH", q(127, 5000)));
    assert_eq!(c.tolerance, Some(q(1, 500)));
    let metre = "#70=(GEOMETRIC_REPRESENTATION_CONTEXT(3)\n\
 GLOBAL_UNIT_ASSIGNED_CONTEXT((#71,#72)) REPRESENTATION_CONTEXT('',''));\n\
#71=(LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT($,.METRE.));\n\
#72=(NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.));\n";
    let m = read(&format!("{SQUARE}{metre}"));
    let c = &m.contexts[&70];
    assert_eq!(c.length.as_ref().unwrap().metres, q(1, 1));
    assert_eq!(c.angle, Some(AngleUnit::Radian(q(1, 1))));
    assert_eq!(c.tolerance, None);
}

/// A cube [0,1]³ of 6 planar faces sharing 12 edges, as a closed shell;
/// `extra` follows (e.g. a void).
fn cube(base: u64) -> String {
    let id = |k: u64| base + k;
    let mut s = String::new();
    for (k, (x, y, z)) in (0..8)
        .map(|k| (k & 1, (k >> 1) & 1, (k >> 2) & 1))
        .enumerate()
    {
        let k = k as u64;
        s += &format!(
            "#{}=CARTESIAN_POINT('',({x}.,{y}.,{z}.));#{}=VERTEX_POINT('',#{});\n",
            id(k),
            id(10 + k),
            id(k)
        );
    }
    // Edges between vertices differing in one bit.
    let mut edges = Vec::new();
    for a in 0..8u64 {
        for bit in [1, 2, 4] {
            if a & bit == 0 {
                edges.push((a, a | bit));
            }
        }
    }
    for (k, (a, b)) in edges.iter().enumerate() {
        let k = k as u64;
        s += &format!(
            "#{}=EDGE_CURVE('',#{},#{},#{},.T.);#{}=LINE('',#{},#{});\n",
            id(20 + k),
            id(10 + a),
            id(10 + b),
            id(40 + k),
            id(40 + k),
            id(*a),
            id(99)
        );
    }
    // Faces: fix one bit to 0 or 1; the loop visits the 4 vertices in order.
    let mut faces = Vec::new();
    for (f, (bit, val)) in [1u64, 2, 4]
        .iter()
        .flat_map(|&b| [(b, 0u64), (b, 1)])
        .enumerate()
    {
        let others: Vec<u64> = [1u64, 2, 4].into_iter().filter(|&o| o != bit).collect();
        let corner = |i: u64| {
            let g = [0, 1, 3, 2][i as usize];
            val * bit + (g & 1) * others[0] + (g >> 1) * others[1]
        };
        let mut oes = Vec::new();
        for i in 0..4u64 {
            let (a, b) = (corner(i), corner((i + 1) % 4));
            let (lo, hi) = (a.min(b), a.max(b));
            let e = edges.iter().position(|&x| x == (lo, hi)).unwrap() as u64;
            let oe = id(100 + 10 * f as u64 + i);
            s += &format!(
                "#{oe}=ORIENTED_EDGE('',*,*,#{},.{}.);\n",
                id(20 + e),
                if a < b { "T" } else { "F" }
            );
            oes.push(format!("#{oe}"));
        }
        let (lp, bd, fc) = (id(200 + f as u64), id(210 + f as u64), id(220 + f as u64));
        s += &format!(
            "#{lp}=EDGE_LOOP('',({}));#{bd}=FACE_OUTER_BOUND('',#{lp},.T.);#{fc}=ADVANCED_FACE('',(#{bd}),#{},.T.);\n",
            oes.join(","),
            id(98)
        );
        faces.push(format!("#{fc}"));
    }
    s += &format!(
        "#{}=PLANE('',#1);#{}=CLOSED_SHELL('',({}));\n",
        id(98),
        id(230),
        faces.join(",")
    );
    s
}

#[test]
fn brep_with_voids_closed_shells_use_every_edge_twice() {
    let data = format!(
        "{}{}#900=ORIENTED_CLOSED_SHELL('',*,#2230,.F.);\n\
         #901=BREP_WITH_VOIDS('',#1230,(#900));\n\
         #902=ADVANCED_BREP_SHAPE_REPRESENTATION('',(#901),#903);\n\
         #903=(GEOMETRIC_REPRESENTATION_CONTEXT(3) REPRESENTATION_CONTEXT('',''));\n",
        cube(1000),
        cube(2000)
    );
    let m = read(&data);
    let solid = &m.solids[&901];
    assert_eq!(solid.kind, "BREP_WITH_VOIDS");
    assert_eq!(solid.shells.len(), 2);
    assert!(solid.shells[0].orientation);
    assert!(!solid.shells[1].orientation);
    for shell in &solid.shells {
        assert!(shell.closed);
        let uses = shell.edge_uses(&m);
        assert_eq!(uses.len(), 12);
        assert!(uses.values().all(|&u| u == 2), "{uses:?}");
    }
    assert_eq!(m.faces.len(), 12);
    assert_eq!(m.summary.edge_uses, BTreeMap::from([(EdgeUse::Shared, 24)]));
    assert!(m.summary.invalid.is_empty(), "{:?}", m.summary.invalid);
}

/// A cylinder's lateral face: one seam edge used twice by the face, with a
/// 2D line pcurve per side, two circle edges.
#[test]
fn a_seam_edge_is_used_twice_by_one_face_with_its_pcurves() {
    let data = "\
#1=CARTESIAN_POINT('',(1.,0.,0.));#2=CARTESIAN_POINT('',(1.,0.,1.));\n\
#11=VERTEX_POINT('',#1);#12=VERTEX_POINT('',#2);\n\
#20=EDGE_CURVE('',#11,#12,#21,.T.);#21=SEAM_CURVE('',#22,(#23,#24),.PCURVE_S1.);\n\
#22=LINE('',#1,#9);#23=PCURVE('',#30,#25);#24=PCURVE('',#30,#26);\n\
#25=DEFINITIONAL_REPRESENTATION('',(#27),#8);#26=DEFINITIONAL_REPRESENTATION('',(#28),#8);\n\
#27=LINE('',#3,#9);#28=LINE('',#4,#9);\n\
#40=EDGE_CURVE('',#11,#11,#41,.T.);#41=CIRCLE('',#9,1.);\n\
#42=EDGE_CURVE('',#12,#12,#43,.T.);#43=CIRCLE('',#9,1.);\n\
#51=ORIENTED_EDGE('',*,*,#40,.T.);#52=ORIENTED_EDGE('',*,*,#20,.T.);\n\
#53=ORIENTED_EDGE('',*,*,#42,.F.);#54=ORIENTED_EDGE('',*,*,#20,.F.);\n\
#55=EDGE_LOOP('',(#51,#52,#53,#54));#56=FACE_OUTER_BOUND('',#55,.T.);\n\
#30=CYLINDRICAL_SURFACE('',#9,1.);#57=ADVANCED_FACE('',(#56),#30,.T.);\n\
#58=OPEN_SHELL('',(#57));\n";
    let m = read(data);
    let seam = &m.edges[&20];
    assert_eq!(seam.usage(), EdgeUse::Seam);
    assert_eq!(seam.via.as_deref(), Some("SEAM_CURVE"));
    assert_eq!(seam.curve.entity, 22);
    let pc: Vec<(u64, u64, u64)> = seam
        .pcurves
        .iter()
        .map(|p| (p.id, p.surface, p.curve.entity))
        .collect();
    assert_eq!(pc, [(23, 30, 27), (24, 30, 28)]);
    assert_eq!(m.edges[&40].usage(), EdgeUse::Open);
    assert_eq!(m.loose_shells.len(), 1);
    assert_eq!(m.summary.faces_by_surface["CYLINDRICAL_SURFACE"], 1);
}

/// The pcurve pieces of edge `e` on surface `surface`, in `f64`: its first,
/// middle (the middle piece at ½) and last points.
fn pcurve_points(m: &BrepModel, e: u64, surface: u64) -> [[f64; 2]; 3] {
    let pc = m.edges[&e]
        .pcurves
        .iter()
        .find(|p| p.surface == surface)
        .unwrap();
    let Geometry::Analytic(a) = &pc.curve.geometry else {
        panic!("{:?}", pc.curve.geometry)
    };
    let at = |k: usize, t: i64| {
        let Patch::Curve(c) = &a.pieces[k] else {
            panic!("a pcurve piece is a curve")
        };
        let p = c.eval(&RealAlgebraic::from_rational(&q(t, 2))).unwrap();
        [p[0].to_f64(), p[1].to_f64()]
    };
    let n = a.pieces.len();
    [at(0, 0), at(n / 2, 1), at(n - 1, 2)]
}

/// A half cylinder x² + y² = 1, 0 ≤ z ≤ 2, y ≤ 0: two arc edges run
/// against their circles (`same_sense` false) from (1, 0) to (−1, 0)
/// through (0, −1), two line edges; each with a LINE pcurve. The arcs'
/// pcurves walk from u = 0 down to u = −π, the lines' sit at u = 0 and at
/// u = π (not −π: the turn nearest the line), all exactly straight.
#[test]
fn line_pcurves_on_a_cylinder_are_trimmed_to_their_edges() {
    let data = "\
#1=CARTESIAN_POINT('',(0.,0.,0.));#2=DIRECTION('',(0.,0.,1.));#3=DIRECTION('',(1.,0.,0.));\n\
#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);#5=CYLINDRICAL_SURFACE('',#4,1.);\n\
#6=CARTESIAN_POINT('',(0.,0.,2.));#7=AXIS2_PLACEMENT_3D('',#6,#2,#3);\n\
#11=VERTEX_POINT('',#21);#12=VERTEX_POINT('',#22);#13=VERTEX_POINT('',#23);#14=VERTEX_POINT('',#24);\n\
#21=CARTESIAN_POINT('',(1.,0.,0.));#22=CARTESIAN_POINT('',(-1.,0.,0.));\n\
#23=CARTESIAN_POINT('',(1.,0.,2.));#24=CARTESIAN_POINT('',(-1.,0.,2.));\n\
#30=DIRECTION('',(1.,0.));#31=VECTOR('',#30,1.);#32=DIRECTION('',(0.,1.));#33=VECTOR('',#32,1.);\n\
#34=CARTESIAN_POINT('',(0.,0.));#35=CARTESIAN_POINT('',(0.,2.));#36=CARTESIAN_POINT('',(3.14159265359,0.));\n\
#40=EDGE_CURVE('',#11,#12,#41,.F.);#41=SURFACE_CURVE('',#42,(#43),.CURVE_3D.);#42=CIRCLE('',#4,1.);\n\
#43=PCURVE('',#5,#44);#44=DEFINITIONAL_REPRESENTATION('',(#45),#9);#45=LINE('',#34,#31);\n\
#50=EDGE_CURVE('',#13,#14,#51,.F.);#51=SURFACE_CURVE('',#52,(#53),.CURVE_3D.);#52=CIRCLE('',#7,1.);\n\
#53=PCURVE('',#5,#54);#54=DEFINITIONAL_REPRESENTATION('',(#55),#9);#55=LINE('',#35,#31);\n\
#60=EDGE_CURVE('',#11,#13,#61,.T.);#61=SURFACE_CURVE('',#62,(#63),.CURVE_3D.);#62=LINE('',#21,#68);\n\
#63=PCURVE('',#5,#64);#64=DEFINITIONAL_REPRESENTATION('',(#65),#9);#65=LINE('',#34,#33);\n\
#66=DIRECTION('',(0.,0.,1.));#68=VECTOR('',#66,1.);\n\
#70=EDGE_CURVE('',#12,#14,#71,.T.);#71=SURFACE_CURVE('',#72,(#73),.CURVE_3D.);#72=LINE('',#22,#68);\n\
#73=PCURVE('',#5,#74);#74=DEFINITIONAL_REPRESENTATION('',(#75),#9);#75=LINE('',#36,#33);\n\
#81=ORIENTED_EDGE('',*,*,#40,.T.);#82=ORIENTED_EDGE('',*,*,#70,.T.);\n\
#83=ORIENTED_EDGE('',*,*,#50,.F.);#84=ORIENTED_EDGE('',*,*,#60,.F.);\n\
#85=EDGE_LOOP('',(#81,#82,#83,#84));#86=FACE_OUTER_BOUND('',#85,.T.);\n\
#87=ADVANCED_FACE('',(#86),#5,.T.);#88=OPEN_SHELL('',(#87));\n";
    let m = read(data);
    assert!(
        m.summary.pcurves_not_converted.is_empty(),
        "{:?}",
        m.summary
    );
    let pi = std::f64::consts::PI;
    let near =
        |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12;
    for (edge, z) in [(40, 0.0), (50, 2.0)] {
        let [first, middle, last] = pcurve_points(&m, edge, 5);
        assert!(
            near(first, [0.0, z]) && near(last, [-pi, z]),
            "edge #{edge}: {first:?} {last:?}"
        );
        // The middle lies on the walked half, u ∈ (−π, 0).
        assert!(
            middle[0] < -0.1 && middle[0] > -pi + 0.1,
            "edge #{edge}: {middle:?}"
        );
    }
    let [first, _, last] = pcurve_points(&m, 60, 5);
    assert!(
        near(first, [0.0, 0.0]) && near(last, [0.0, 2.0]),
        "{first:?} {last:?}"
    );
    let [first, _, last] = pcurve_points(&m, 70, 5);
    // The vertex (−1, 0) is at u = π by atan2; the line is at 3.14159265359.
    assert!(
        (first[0] - pi).abs() < 1e-10 && (last[0] - pi).abs() < 1e-10,
        "{first:?} {last:?}"
    );
    assert_eq!((first[1], last[1]), (0.0, 2.0));
}

/// A surface of revolution of the B-spline segment (1, 0, 0)–(1, 0, 2)
/// about ẑ (a unit cylinder, u the angle, v the knot parameter): a quarter
/// circle edge from (1, 0, 0) to (0, 1, 0) with the pcurve v = 0 runs from
/// u = 0 to u = π/2 (not −π/2 or 3π/2: the angle's sense is about the axis).
#[test]
fn a_line_pcurve_on_a_surface_of_revolution_turns_about_its_axis() {
    let data = "\
#1=CARTESIAN_POINT('',(0.,0.,0.));#2=DIRECTION('',(0.,0.,1.));#3=DIRECTION('',(1.,0.,0.));\n\
#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);#5=AXIS1_PLACEMENT('',#1,#2);\n\
#6=CARTESIAN_POINT('',(1.,0.,0.));#7=CARTESIAN_POINT('',(1.,0.,2.));#8=CARTESIAN_POINT('',(0.,1.,0.));\n\
#9=B_SPLINE_CURVE_WITH_KNOTS('',1,(#6,#7),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),.UNSPECIFIED.);\n\
#10=SURFACE_OF_REVOLUTION('',#9,#5);\n\
#11=VERTEX_POINT('',#6);#12=VERTEX_POINT('',#8);\n\
#20=EDGE_CURVE('',#11,#12,#21,.T.);#21=SURFACE_CURVE('',#22,(#23),.CURVE_3D.);#22=CIRCLE('',#4,1.);\n\
#23=PCURVE('',#10,#24);#24=DEFINITIONAL_REPRESENTATION('',(#25),#99);#25=LINE('',#26,#27);\n\
#26=CARTESIAN_POINT('',(0.,0.));#27=VECTOR('',#28,1.);#28=DIRECTION('',(1.,0.));\n\
#30=ORIENTED_EDGE('',*,*,#20,.T.);#31=EDGE_LOOP('',(#30));#32=FACE_OUTER_BOUND('',#31,.T.);\n\
#33=ADVANCED_FACE('',(#32),#10,.T.);#34=OPEN_SHELL('',(#33));\n";
    let m = read(data);
    assert!(
        m.summary.pcurves_not_converted.is_empty(),
        "{:?}",
        m.summary
    );
    let [first, _, last] = pcurve_points(&m, 20, 10);
    let near = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-9;
    let quarter = std::f64::consts::FRAC_PI_2;
    assert!(
        near(first, [0.0, 0.0]) && near(last, [quarter, 0.0]),
        "{first:?} {last:?}"
    );
}

/// On a plane the pcurve is trimmed exactly: the vertices' frame
/// coordinates lie on it and the squared distances are 0.
#[test]
fn a_pcurve_on_a_plane_is_trimmed_exactly() {
    let data = format!(
        "{SQUARE}#90=SURFACE_CURVE('',#31,(#91),.CURVE_3D.);#91=PCURVE('',#52,#92);\n\
#92=DEFINITIONAL_REPRESENTATION('',(#93),#9);#93=LINE('',#94,#95);\n\
#94=CARTESIAN_POINT('',(0.,0.));#95=VECTOR('',#96,1.);#96=DIRECTION('',(1.,0.));\n"
    )
    .replace(
        "#21=EDGE_CURVE('',#11,#12,#31,.T.)",
        "#21=EDGE_CURVE('',#11,#12,#90,.T.)",
    );
    let m = read(&data);
    let pc = &m.edges[&21].pcurves[0];
    let Geometry::Analytic(a) = &pc.curve.geometry else {
        panic!("{:?}", pc.curve.geometry)
    };
    let zero = RealAlgebraic::from_i64(0);
    assert_eq!(a.vertex_distance_sq, Some([zero.clone(), zero]));
    let Patch::Curve(c) = &a.pieces[0] else {
        panic!()
    };
    let one = RealAlgebraic::from_i64(1);
    let z = RealAlgebraic::from_i64(0);
    assert_eq!(
        c.points().unwrap(),
        vec![vec![z.clone(), z.clone()], vec![one, z]]
    );
}

/// A rational quasi-uniform B-spline curve edge written as a complex
/// instance with its parts in an unusual order (was: "has no knots").
#[test]
fn complex_parts_in_any_order_and_a_bspline_edge() {
    let data = "\
#1=CARTESIAN_POINT('',(1.,0.,0.));#2=CARTESIAN_POINT('',(1.,1.,0.));#3=CARTESIAN_POINT('',(0.,1.,0.));\n\
#11=VERTEX_POINT('',#1);#12=VERTEX_POINT('',#3);\n\
#20=(RATIONAL_B_SPLINE_CURVE((1.,0.5,1.)) REPRESENTATION_ITEM('') QUASI_UNIFORM_CURVE()\n\
 B_SPLINE_CURVE(2,(#1,#2,#3),.UNSPECIFIED.,.F.,.F.) BOUNDED_CURVE() CURVE() GEOMETRIC_REPRESENTATION_ITEM());\n\
#21=EDGE_CURVE('',#11,#12,#20,.T.);#22=ORIENTED_EDGE('',*,*,#21,.T.);\n\
#23=EDGE_LOOP('',(#22));#24=FACE_BOUND('',#23,.F.);#25=PLANE('',#9);\n\
#26=FACE_SURFACE('',(#24),#25,.F.);\n";
    let m = read(data);
    assert!(m.summary.invalid.is_empty(), "{:?}", m.summary.invalid);
    let e = &m.edges[&21];
    assert_eq!(e.curve.kind, "QUASI_UNIFORM_CURVE");
    let Geometry::BSpline(b) = &e.curve.geometry else {
        panic!("{:?}", e.curve.geometry)
    };
    let p = b.pieces();
    assert_eq!(p.len(), 1);
    let Patch::Curve(c) = &p[0].patch else {
        panic!("a curve")
    };
    // By hand at t = 1/2 (Bernstein 1/4, 1/2, 1/4; weights 1, 1/2, 1):
    // (1/4·(1,0) + 1/4·(1,1) + 1/4·(0,1)) / (3/4) = (2/3, 2/3).
    let x = c.eval(&q(1, 2)).unwrap();
    assert_eq!(x, vec![q(2, 3), q(2, 3), q(0, 1)]);
    let f = &m.faces[&26];
    assert!(!f.same_sense);
    assert!(!f.bounds[0].outer && !f.bounds[0].orientation);
}

#[test]
fn a_bspline_edge_between_inner_points_of_its_curve_is_trimmed_to_them() {
    // The parabola with control points (1,0), (1,1), (0,1) has
    // x(1/2) = (1,0)/4 + (1,1)/2 + (0,1)/4 = (3/4, 3/4), a decimal vertex.
    let data = "\
#1=CARTESIAN_POINT('',(1.,0.,0.));#2=CARTESIAN_POINT('',(1.,1.,0.));#3=CARTESIAN_POINT('',(0.,1.,0.));\n\
#4=CARTESIAN_POINT('',(0.75,0.75,0.));\n\
#11=VERTEX_POINT('',#4);#12=VERTEX_POINT('',#3);\n\
#20=B_SPLINE_CURVE_WITH_KNOTS('',2,(#1,#2,#3),.UNSPECIFIED.,.F.,.F.,(3,3),(0.,1.),.UNSPECIFIED.);\n\
#21=EDGE_CURVE('',#12,#11,#20,.F.);#22=ORIENTED_EDGE('',*,*,#21,.T.);\n\
#23=EDGE_LOOP('',(#22));#24=FACE_BOUND('',#23,.T.);#25=PLANE('',#9);#9=AXIS2_PLACEMENT_3D('',#1,$,$);\n\
#26=FACE_SURFACE('',(#24),#25,.T.);\n";
    let m = read(data);
    let e = &m.edges[&21];
    assert_eq!(e.curve.kind, "B_SPLINE_CURVE_WITH_KNOTS");
    let Geometry::Analytic(a) = &e.curve.geometry else {
        panic!("trimmed pieces: {:?}", e.curve.geometry)
    };
    // Against the curve: from (0, 1, 0) back to (3/4, 3/4, 0), exactly on it.
    let at = |k: usize, t: i64| match &a.pieces[k] {
        Patch::Curve(c) => c.eval(&RealAlgebraic::from_i64(t)).unwrap(),
        p => panic!("an edge piece is a curve: {p:?}"),
    };
    let ends: Vec<Vec<Q>> = [at(0, 0), at(a.pieces.len() - 1, 1)]
        .iter()
        .map(|p| p.iter().map(|x| x.as_rational().unwrap()).collect())
        .collect();
    assert_eq!(
        ends,
        [
            vec![q(0, 1), q(1, 1), q(0, 1)],
            vec![q(3, 4), q(3, 4), q(0, 1)]
        ]
    );
    let zero = RealAlgebraic::from_i64(0);
    assert_eq!(a.vertex_distance_sq, Some([zero.clone(), zero]));
}

/// Faces by surface type and edges by curve type, counted from the text
/// without the reader: statements split at `;`, the reference before the
/// final `.T.`/`.F.` of each face/edge, and the type name of its target.
fn independent_counts(text: &str) -> (BTreeMap<String, usize>, BTreeMap<String, usize>) {
    let mut kinds: HashMap<u64, (String, String)> = HashMap::new();
    for st in text.split(';') {
        let st: String = st.chars().filter(|c| !c.is_whitespace()).collect();
        let Some(rest) = st.strip_prefix('#') else {
            continue;
        };
        let Some((id, body)) = rest.split_once('=') else {
            continue;
        };
        let Ok(id) = id.parse::<u64>() else { continue };
        let name = if body.starts_with('(') {
            if body.contains("B_SPLINE_SURFACE(") {
                "B_SPLINE_SURFACE".to_owned()
            } else {
                "complex".to_owned()
            }
        } else {
            body.split('(').next().unwrap_or("").to_owned()
        };
        kinds.insert(id, (name, body.to_owned()));
    }
    let last_ref = |body: &str| -> u64 {
        let head = &body[..body.rfind(",.").unwrap()];
        head[head.rfind('#').unwrap() + 1..].parse().unwrap()
    };
    let first_ref = |body: &str| -> u64 {
        let t = &body[body.find('#').unwrap() + 1..];
        t[..t.find(|c: char| !c.is_ascii_digit()).unwrap()]
            .parse()
            .unwrap()
    };
    let simplify = |n: &str| {
        if n.starts_with("B_SPLINE") {
            "B_SPLINE_SURFACE".to_owned()
        } else {
            n.to_owned()
        }
    };
    let mut faces = BTreeMap::new();
    let mut edges = BTreeMap::new();
    let mut used = std::collections::BTreeSet::new();
    for (name, body) in kinds.values() {
        if name == "ADVANCED_FACE" {
            let s = &kinds[&last_ref(body)].0;
            *faces.entry(simplify(s)).or_insert(0) += 1;
        }
        if name == "ORIENTED_EDGE" {
            used.insert(last_ref(body));
        }
    }
    for e in used {
        let (_, body) = &kinds[&e];
        let mut c = last_ref(body);
        if matches!(kinds[&c].0.as_str(), "SURFACE_CURVE" | "SEAM_CURVE") {
            c = first_ref(&kinds[&c].1);
        }
        *edges.entry(kinds[&c].0.clone()).or_insert(0) += 1;
    }
    (faces, edges)
}

fn fixture(name: &str) -> String {
    let path = format!("{}/tests/fixtures/step/{name}", env!("CARGO_MANIFEST_DIR"));
    String::from_utf8_lossy(&std::fs::read(path).unwrap()).into_owned()
}

/// The reader's counts with every B-spline surface leaf type as one.
fn reader_counts(m: &BrepModel) -> (BTreeMap<String, usize>, BTreeMap<String, usize>) {
    let mut faces = BTreeMap::new();
    for (k, n) in &m.summary.faces_by_surface {
        let k = if k.contains("_SURFACE_WITH_KNOTS") || k.starts_with("BEZIER") {
            "B_SPLINE_SURFACE".to_owned()
        } else {
            k.clone()
        };
        *faces.entry(k).or_insert(0) += n;
    }
    (faces, m.summary.edges_by_curve.clone())
}

/// The distance² between a vertex and the end of a B-spline edge curve
/// (start when `at_start`), exactly: a Bézier piece's ends are its end
/// control points.
fn end_gap(m: &BrepModel, e: &Edge) -> Option<Q> {
    let Geometry::BSpline(b) = &e.curve.geometry else {
        return None;
    };
    let p = b.pieces();
    let end = |k: usize, t: Q| match &p[k].patch {
        Patch::Curve(c) => c.eval(&t).unwrap(),
        _ => unreachable!("a curve's pieces are curves"),
    };
    let (first, last) = (end(0, q(0, 1)), end(p.len() - 1, q(1, 1)));
    let (a, b) = if e.same_sense {
        (first, last)
    } else {
        (last, first)
    };
    let d2 = |x: &[Q], y: &[Q]| {
        x.iter()
            .zip(y)
            .map(|(s, t)| (s - t) * (s - t))
            .fold(q(0, 1), |acc, v| acc + v)
    };
    Some(std::cmp::max(
        d2(&a, &m.vertices[&e.start]),
        d2(&b, &m.vertices[&e.end]),
    ))
}

fn check_nist(name: &str, faces: &[(&str, usize)]) -> BrepModel {
    let text = fixture(name);
    // The topology only: the analytic geometry is tested on smaller files.
    let m = read_brep_with(text.as_bytes(), BrepOptions { analytic: false }).unwrap();
    let (scan_faces, scan_edges) = independent_counts(&text);
    let want: BTreeMap<String, usize> = faces.iter().map(|(k, n)| ((*k).to_owned(), *n)).collect();
    // The hand-checked numbers of the README, the text scan and the reader.
    assert_eq!(scan_faces, want, "{name}: scan");
    assert_eq!(reader_counts(&m), (want, scan_edges), "{name}: reader");
    assert!(m.summary.invalid.is_empty(), "{:?}", m.summary.invalid);
    let shells: Vec<&Shell> = m
        .solids
        .values()
        .flat_map(|s| &s.shells)
        .chain(&m.loose_shells)
        .collect();
    assert!(!shells.is_empty());
    for shell in shells.iter().filter(|s| s.closed) {
        assert!(
            shell.edge_uses(&m).values().all(|&u| u == 2),
            "{name}: shell #{}",
            shell.id
        );
    }
    let tol = m
        .contexts
        .values()
        .find_map(|c| c.tolerance.clone())
        .unwrap();
    for e in m.edges.values() {
        if let Some(gap2) = end_gap(&m, e) {
            assert!(gap2 <= tol.clone() * &tol, "{name}: edge #{}", e.id);
        }
    }
    m
}

#[test]
fn nist_ctc_01_faces_edges_shells_and_vertices() {
    let m = check_nist(
        "nist_ctc_01_asme1_ap242.stp",
        &[
            ("PLANE", 56),
            ("CYLINDRICAL_SURFACE", 57),
            ("CONICAL_SURFACE", 4),
        ],
    );
    assert_eq!(m.faces.len(), 117);
}

#[test]
fn nist_ctc_02_faces_edges_shells_and_vertices() {
    let m = check_nist(
        "nist_ctc_02_asme1_ap203.stp",
        &[
            ("PLANE", 129),
            ("CYLINDRICAL_SURFACE", 224),
            ("CONICAL_SURFACE", 82),
            ("SPHERICAL_SURFACE", 24),
            ("B_SPLINE_SURFACE", 28),
        ],
    );
    assert_eq!(m.faces.len(), 487);
    let converted = m
        .faces
        .values()
        .filter(|f| matches!(f.surface.geometry, Geometry::BSpline(_)))
        .count();
    assert_eq!(converted, 28);
    let c = m.contexts.values().next().unwrap();
    assert_eq!(c.length.as_ref().unwrap().metres, q(1, 1000));
    assert_eq!(c.angle, Some(AngleUnit::Degree));
    assert_eq!(c.tolerance, Some(q(127, 2500)));
}

#[test]
fn nist_ftc_06_faces_edges_shells_and_vertices() {
    let m = check_nist(
        "nist_ftc_06_asme1_rd.stp",
        &[
            ("PLANE", 71),
            ("CYLINDRICAL_SURFACE", 58),
            ("CONICAL_SURFACE", 4),
            ("SPHERICAL_SURFACE", 5),
            ("TOROIDAL_SURFACE", 6),
        ],
    );
    assert_eq!(m.faces.len(), 144);
}
