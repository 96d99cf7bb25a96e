use super::*;
use crate::{ratio, Patch};

type Q = BigRational;

fn q(n: i64, d: i64) -> Q {
    ratio(n, d)
}

/// An arc of the unit cylinder x² + y² = 1, 0 ≤ z ≤ 2 (half-angle θ with
/// cos θ = 4/5: middle weight 4/5, middle point (1, 3/4)), as the rational
/// quadratic × linear complex instance CAD systems write, on a face; a
/// cubic Bézier curve; a B-spline curve with knots; a plane (skipped).
const FILE: &str = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nENDSEC;\nDATA;\n\
#10=CARTESIAN_POINT('',(1.,0.,0.));\n#11=CARTESIAN_POINT('',(1.,0.,2.));\n\
#12=CARTESIAN_POINT('',(1.,0.75,0.));\n#13=CARTESIAN_POINT('',(1.,7.5E-1,2.));\n\
#14=CARTESIAN_POINT('',(0.28,0.96,0.));\n#15=CARTESIAN_POINT('',(2.8E-1,0.96,2.));\n\
#20=(BOUNDED_SURFACE() B_SPLINE_SURFACE(2,1,((#10,#11),(#12,#13),(#14,#15)),.UNSPECIFIED.,.F.,.F.,.F.)\n\
 B_SPLINE_SURFACE_WITH_KNOTS((3,3),(2,2),(0.,1.5707963),(0.,2.),.UNSPECIFIED.)\n\
 GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(((1.,1.),(0.8,0.8),(1.,1.)))\n\
 REPRESENTATION_ITEM('') SURFACE());\n\
#30=ADVANCED_FACE('',(#31),#20,.T.);\n#31=FACE_OUTER_BOUND('',#32,.T.);\n\
#40=BEZIER_CURVE('',3,(#10,#12,#14,#15),.UNSPECIFIED.,.F.,.F.);\n\
#41=B_SPLINE_CURVE_WITH_KNOTS('',1,(#10,#12,#14),.UNSPECIFIED.,.F.,.F.,(2,1,2),(0.,0.25,1.),.UNSPECIFIED.);\n\
#42=B_SPLINE_CURVE_WITH_KNOTS('',1,(#10,#99),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,1.),.UNSPECIFIED.);\n\
#50=PLANE('',#51);\n#60=ADVANCED_FACE('',(#31),#50,.T.);\nENDSEC;\nEND-ISO-10303-21;\n";

#[test]
fn reads_the_rational_complex_surface_with_its_face() {
    let m = read_step(FILE.as_bytes()).unwrap();
    let s = &m.entities[0];
    assert_eq!(
        (s.id, s.name.as_str(), s.faces.clone()),
        (20, "B_SPLINE_SURFACE_WITH_KNOTS", vec![30])
    );
    let Nurbs::Surface(surf) = &s.nurbs else {
        panic!("a surface")
    };
    // The knot 1.5707963 is read exactly, not as the f64 nearest to it.
    assert_eq!(surf.knots().0.knots()[5], q(15_707_963, 10_000_000));
    let pieces = s.nurbs.pieces();
    assert_eq!(pieces.len(), 1);
    let Patch::Rect(r) = &pieces[0].patch else {
        panic!("a rect")
    };
    // A point of the arc: x² + y² = 1 exactly at u = 1/3.
    let x = r.eval(&q(1, 3), &q(1, 2)).unwrap();
    assert_eq!(x[0].clone() * &x[0] + x[1].clone() * &x[1], q(1, 1));
    assert_eq!(x[2], q(1, 1));
}

#[test]
fn curves_bezier_and_knots_skips_and_invalid_entities() {
    let m = read_step(FILE.as_bytes()).unwrap();
    let ids: Vec<u64> = m.entities.iter().map(|e| e.id).collect();
    assert_eq!(ids, [20, 40, 41]);
    assert_eq!(m.entities[1].nurbs.pieces().len(), 1);
    let spans: Vec<[Q; 2]> = m.entities[2]
        .nurbs
        .pieces()
        .into_iter()
        .map(|p| p.u)
        .collect();
    assert_eq!(spans, [[q(0, 1), q(1, 4)], [q(1, 4), q(1, 1)]]);
    assert_eq!(m.invalid.len(), 1);
    assert_eq!(m.invalid[0].0, 42);
    assert!(m.invalid[0].1.contains("#99"), "{}", m.invalid[0].1);
    assert_eq!(m.skipped.get("PLANE"), Some(&1));
    assert_eq!(m.skipped.get("FACE_OUTER_BOUND"), Some(&1));
    assert_eq!(m.other_faces, vec![(60, 50)]);
}

#[test]
fn quasi_uniform_and_uniform_knots() {
    let k = knots("QUASI_UNIFORM_CURVE", 2, 5, None).unwrap();
    let want: Vec<Q> = [0, 0, 0, 1, 2, 3, 3, 3].iter().map(|&x| q(x, 1)).collect();
    assert_eq!(k.knots(), &want[..]);
    let k = knots("UNIFORM_CURVE", 2, 4, None).unwrap();
    let want: Vec<Q> = (-2..5).map(|x| q(x, 1)).collect();
    assert_eq!(k.knots(), &want[..]);
    assert!(knots("BEZIER_CURVE", 2, 4, None).is_err());
}
