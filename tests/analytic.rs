//! The analytic curves and surfaces of STEP as exact rational pieces
//! (`exact_bezier::analytic`, `exact_bezier::step::geometry`): implicit
//! equations exactly on frames with irrational unit vectors, agreement with
//! the ISO closed forms evaluated independently, a real NIST file read
//! whole, and properties of trimming and frames.

use exact_bezier::algebra::{parse_rational, RealAlgebraic};
use exact_bezier::analytic::{
    circle, cone, cone_slope, covering_range, cylinder, ellipse, plane, sphere, torus,
    trim_between, AngleUnit, Frame, Unbounded,
};
use exact_bezier::hpoint::HPoint;
use exact_bezier::step::geometry::{self, Context, Curve, Surface, Table};
use exact_bezier::step::parser::Reader;
use exact_bezier::{ratio, BigRational, Ordered, RationalCurve, Roots, Scalar};
use num_traits::{One, Zero};
use proptest::prelude::*;

type R = RealAlgebraic;

fn dec(s: &str) -> R {
    R::from_rational(&parse_rational(s).unwrap())
}

fn v3(a: &str, b: &str, c: &str) -> Vec<R> {
    vec![dec(a), dec(b), dec(c)]
}

/// Two frames whose unit vectors are irrational: a decimal ref_direction
/// (0.6, 0.8, 0) against the axis (1, 1, 1), and the axis (1, 1, 0) with
/// ref_direction (0.707106781186548, −0.707106781186548, 0).
fn frames() -> Vec<Frame<R>> {
    vec![
        Frame::from_placement(
            &v3("1.5", "-2", "0.25"),
            Some(&v3("1", "1", "1")),
            Some(&v3("0.6", "0.8", "0")),
        )
        .unwrap(),
        Frame::from_placement(
            &v3("0", "3", "-1"),
            Some(&v3("1", "1", "0")),
            Some(&v3("0.707106781186548", "-0.707106781186548", "0")),
        )
        .unwrap(),
    ]
}

fn dot<T: Scalar>(a: &[T], b: &[T]) -> T {
    a.iter()
        .zip(b)
        .fold(T::zero(), |s, (x, y)| s + &(x.clone() * y))
}

/// `(α, β, η, W)`: frame coordinates of a homogeneous point, times W.
fn hcoords(f: &Frame<R>, h: &HPoint<R>) -> [R; 4] {
    let w = h.weight().clone();
    let d: Vec<R> = h
        .weighted()
        .iter()
        .zip(&f.origin)
        .map(|(x, c)| x.clone() - &(c.clone() * &w))
        .collect();
    [dot(&d, &f.x), dot(&d, &f.y), dot(&d, &f.z), w]
}

fn sq(x: &R) -> R {
    x.clone() * x
}

/// `k + 1` distinct parameters in [0, 1]: a polynomial of degree ≤ k in a
/// variable that vanishes at all of them vanishes identically.
fn grid(k: i64) -> Vec<R> {
    (0..=k).map(|i| ratio(i, k)).collect()
}

/// Every patch satisfies `implicit` at a grid of `(du + 1) × (dv + 1)`
/// parameters, where (du, dv) bounds the bidegree of `implicit ∘ patch`:
/// the residual is then zero identically.
fn holds_on_grid(
    f: &Frame<R>,
    patches: &[exact_bezier::RectPatch<R>],
    (du, dv): (i64, i64),
    implicit: impl Fn(&[R; 4]) -> R,
) {
    for (i, p) in patches.iter().enumerate() {
        for u in grid(du) {
            for v in grid(dv) {
                let c = hcoords(f, &p.eval_hom(&u, &v));
                assert!(implicit(&c).is_zero(), "patch {i} at ({u}, {v})");
            }
        }
    }
}

#[test]
fn implicit_equations_hold_exactly_on_irrational_frames() {
    let (r, rr, k) = (dec("2.5"), dec("0.75"), dec("0.5"));
    let (v0, v1) = (dec("-1"), dec("3"));
    for f in frames() {
        let radial = |c: &[R; 4]| sq(&c[0]) + &sq(&c[1]);
        holds_on_grid(&f, &cylinder(&f, &r, [&v0, &v1]), (4, 2), |c| {
            radial(c) - &(sq(&r) * &sq(&c[3]))
        });
        holds_on_grid(&f, &cone(&f, &r, &k, [&v0, &v1]), (4, 2), |c| {
            radial(c) - &sq(&(r.clone() * &c[3] + &(k.clone() * &c[2])))
        });
        holds_on_grid(&f, &sphere(&f, &r), (4, 4), |c| {
            radial(c) + &sq(&c[2]) - &(sq(&r) * &sq(&c[3]))
        });
        let tori = torus(&f, &r, &rr);
        holds_on_grid(&f, &tori[..1], (8, 8), |c| {
            let w2 = sq(&c[3]);
            let s = radial(c) + &sq(&c[2]) + &((sq(&r) - &sq(&rr)) * &w2);
            sq(&s) - &(R::from_i64(4) * &sq(&r) * &w2 * &radial(c))
        });
        for arc in circle(&f, &r) {
            for t in grid(4) {
                let c = hcoords(&f, &arc.eval_hom(&t));
                assert!(c[2].is_zero());
                assert!((radial(&c) - &(sq(&r) * &sq(&c[3]))).is_zero());
            }
        }
    }
}

/// `(cos φ, sin φ)` for `φ = k·90° + 2·atan t`, from the angle-sum formula
/// and the half-angle identities (independent of the library's arcs).
fn iso_angle(k: usize, t: &R) -> (R, R) {
    let d = R::one() + &sq(t);
    let (c, s) = ((R::one() - &sq(t)) / &d, R::from_i64(2) * t / &d);
    let (ck, sk) = (
        R::from_i64([1, 0, -1, 0][k % 4]),
        R::from_i64([0, 1, 0, -1][k % 4]),
    );
    (c.clone() * &ck - &(s.clone() * &sk), s * &ck + &(c * &sk))
}

/// `C + a·x̂ + b·ŷ + h·ẑ`, written out here.
fn at(f: &Frame<R>, a: &R, b: &R, h: &R) -> Vec<R> {
    (0..3)
        .map(|i| {
            f.origin[i].clone()
                + &(a.clone() * &f.x[i])
                + &(b.clone() * &f.y[i])
                + &(h.clone() * &f.z[i])
        })
        .collect()
}

#[test]
fn pieces_agree_with_iso_closed_forms() {
    let ts: Vec<R> = [(0, 1), (1, 7), (1, 3), (1, 2), (3, 4), (1, 1)]
        .iter()
        .map(|&(n, d)| ratio(n, d))
        .collect();
    let (r, rr, k) = (dec("2.5"), dec("0.75"), dec("0.5"));
    let (a, b) = (dec("3"), dec("1.25"));
    let (v0, v1) = (dec("-1"), dec("3"));
    let zero = R::zero();
    for f in frames() {
        let el = ellipse(&f, &a, &b);
        let sph = sphere(&f, &r);
        let tor = torus(&f, &r, &rr);
        let con = cone(&f, &r, &k, [&v0, &v1]);
        for (iu, s) in ts.iter().enumerate() {
            for (ku, arc) in el.iter().enumerate() {
                let (c, sn) = iso_angle(ku, s);
                let want = at(&f, &(a.clone() * &c), &(b.clone() * &sn), &zero);
                assert_eq!(arc.eval(s).unwrap(), want);
            }
            let t = &ts[(iu + 2) % ts.len()];
            for ku in 0..4 {
                let (cu, su) = iso_angle(ku, s);
                // Sphere: latitude row 0 is [−90°, 0°] (k = 3), row 1 [0°, 90°].
                for (kv, row) in [(3, 0), (0, 1)] {
                    let (cv, sv) = iso_angle(kv, t);
                    let want = at(
                        &f,
                        &(r.clone() * &cv * &cu),
                        &(r.clone() * &cv * &su),
                        &(r.clone() * &sv),
                    );
                    assert_eq!(sph[ku * 2 + row].eval(s, t).unwrap(), want);
                }
                for kv in 0..4 {
                    let (cv, sv) = iso_angle(kv, t);
                    let rad = r.clone() + &(rr.clone() * &cv);
                    let want = at(&f, &(rad.clone() * &cu), &(rad * &su), &(rr.clone() * &sv));
                    assert_eq!(tor[ku * 4 + kv].eval(s, t).unwrap(), want);
                }
                // Cone: v = v0 + t (v1 − v0).
                let v = v0.clone() + &(t.clone() * &(v1.clone() - &v0));
                let rad = r.clone() + &(v.clone() * &k);
                let want = at(&f, &(rad.clone() * &cu), &(rad * &su), &v);
                assert_eq!(con[ku].eval(s, t).unwrap(), want);
            }
            let p = plane(&f, [&v0, &v1], [&a, &b]);
            let (pu, pv) = (
                v0.clone() + &(s.clone() * &(v1.clone() - &v0)),
                a.clone() + &(t.clone() * &(b.clone() - &a)),
            );
            assert_eq!(p.eval(s, t).unwrap(), at(&f, &pu, &pv, &zero));
        }
    }
}

#[test]
fn covering_range_is_the_exact_extent() {
    let f = &frames()[0];
    // Points at known frame coordinates (a, b, h).
    let pts: Vec<Vec<R>> = [("1", "2", "-3"), ("-4", "0.5", "7"), ("0", "0", "0.25")]
        .iter()
        .map(|(a, b, h)| at(f, &dec(a), &dec(b), &dec(h)))
        .collect();
    assert_eq!(
        covering_range(&Unbounded::Axial(f), &pts).unwrap(),
        vec![[dec("-3"), dec("7")]]
    );
    assert_eq!(
        covering_range(&Unbounded::Plane(f), &pts).unwrap(),
        vec![[dec("-4"), dec("1")], [dec("0"), dec("2")]]
    );
}

#[test]
fn cone_slopes_exact_at_multiples_of_15_degrees_and_bounded_otherwise() {
    let s = cone_slope::<R>("45.", &AngleUnit::Degree).unwrap();
    assert!(s.exact && s.tan == R::one());
    let s = cone_slope::<R>("0.261799387799149", &AngleUnit::radian()).unwrap();
    // π/12 to 15 decimals: tan = 2 − √3.
    assert!(s.exact);
    assert_eq!(s.tan, R::from_i64(2) - &R::from_i64(3).nth_root(2).unwrap());
    // One unit off in the last digit is not π/12 any more.
    let s = cone_slope::<R>("0.261799387799140", &AngleUnit::radian()).unwrap();
    assert!(!s.exact);
    let s = cone_slope::<R>("9.46232220802597", &AngleUnit::Degree).unwrap();
    assert!(!s.exact);
    let f64_tan = 9.46232220802597f64.to_radians().tan();
    assert!((s.tan.to_f64() - f64_tan).abs() < 1e-14);
    assert!(s.error < ratio::<BigRational>(1, 1 << 62));
    assert!(cone_slope::<R>("90.", &AngleUnit::Degree).is_err());
    assert!(cone_slope::<R>("0.", &AngleUnit::radian()).is_err());
}

fn table_of(text: &str) -> Table {
    let mut reader = Reader::new(text.as_bytes());
    let mut table = Table::default();
    while let Some(inst) = reader.next_instance().unwrap() {
        table.insert(inst.id, inst);
    }
    table
}

const FTC_06: &str = include_str!("fixtures/step/nist_ftc_06_asme1_rd.stp");

/// Instances named `name` by a plain text count of `=NAME(`.
fn text_count(text: &str, name: &str) -> usize {
    text.matches(&format!("={name}(")).count()
}

#[test]
fn nist_ftc_06_every_analytic_entity_reads() {
    let table = table_of(FTC_06);
    let ctx = Context::<R> {
        table: &table,
        angle_unit: AngleUnit::Degree,
        bspline_curve: None,
    };
    let start = std::time::Instant::now();
    let curves = ["LINE", "CIRCLE", "ELLIPSE", "POLYLINE", "TRIMMED_CURVE"];
    let surfaces = [
        "PLANE",
        "CYLINDRICAL_SURFACE",
        "CONICAL_SURFACE",
        "SPHERICAL_SURFACE",
        "TOROIDAL_SURFACE",
        "SURFACE_OF_LINEAR_EXTRUSION",
        "SURFACE_OF_REVOLUTION",
    ];
    let mut ids: Vec<(&u64, &exact_bezier::step::parser::Instance)> = table.iter().collect();
    ids.sort_by_key(|(id, _)| **id);
    for name in curves.iter().chain(&surfaces) {
        let of_type: Vec<u64> = ids
            .iter()
            .filter(|(_, i)| !i.complex && i.records[0].name == *name)
            .map(|(id, _)| **id)
            .collect();
        assert_eq!(of_type.len(), text_count(FTC_06, name), "{name}");
        for id in of_type {
            let read = if curves.contains(name) {
                matches!(geometry::curve_pieces(&ctx, id, &[]), Ok(Curve::Pieces(_)))
            } else {
                matches!(
                    geometry::surface_pieces(&ctx, id, &[]),
                    Ok(Surface::Pieces(_))
                )
            };
            assert!(read, "#{id} {name}");
        }
    }
    eprintln!(
        "read every analytic entity of FTC 06 in {:?}",
        start.elapsed()
    );
    assert_eq!(text_count(FTC_06, "CIRCLE"), 140);
    assert_eq!(text_count(FTC_06, "TOROIDAL_SURFACE"), 6);
}

#[test]
fn nist_ftc_06_circles_lie_in_their_planes_exactly() {
    let table = table_of(FTC_06);
    let ctx = Context::<R> {
        table: &table,
        angle_unit: AngleUnit::Degree,
        bspline_curve: None,
    };
    let mut checked = 0;
    for (id, inst) in &table {
        if inst.complex || inst.records[0].name != "CIRCLE" {
            continue;
        }
        // The plane from the raw attributes: centre and (unnormalised) axis.
        let rec = &inst.records[0];
        let place = |i: usize| match &rec.params[i] {
            exact_bezier::step::parser::Param::Ref(r) => *r,
            p => panic!("#{id}: {p:?}"),
        };
        let p = &table[&place(1)].records[0];
        let pref = |i: usize| match &p.params[i] {
            exact_bezier::step::parser::Param::Ref(r) => *r,
            q => panic!("#{id}: {q:?}"),
        };
        let centre: Vec<R> = geometry::point(&table, pref(1)).unwrap();
        let axis: Vec<R> = geometry::direction(&table, pref(2)).unwrap();
        let Ok(Curve::Pieces(c)) = geometry::curve_pieces(&ctx, *id, &[]) else {
            panic!("#{id} did not read");
        };
        let radius = match &rec.params[2] {
            exact_bezier::step::parser::Param::Number(t) => dec(t),
            q => panic!("{q:?}"),
        };
        for piece in &c.pieces {
            let pts = piece.points().unwrap();
            for q in &pts {
                let d: Vec<R> = q.iter().zip(&centre).map(|(a, b)| a.clone() - b).collect();
                assert!(
                    dot(&d, &axis).is_zero(),
                    "#{id}: a control point off the plane"
                );
            }
            for q in [&pts[0], &pts[2]] {
                let d: Vec<R> = q.iter().zip(&centre).map(|(a, b)| a.clone() - b).collect();
                assert_eq!(dot(&d, &d), sq(&radius), "#{id}: an end off the circle");
            }
        }
        checked += 1;
    }
    assert_eq!(checked, 140);
}

const SMALL: &str = "DATA;
#1=CARTESIAN_POINT('',(0.,0.,0.));
#2=DIRECTION('',(0.,0.,1.));
#3=DIRECTION('',(1.,0.,0.));
#4=AXIS2_PLACEMENT_3D('',#1,#2,#3);
#5=CYLINDRICAL_SURFACE('',#4,2.);
#6=OFFSET_SURFACE('',#5,1.,.F.);
#7=CYLINDRICAL_SURFACE('',#4);
#8=CIRCLE('',#9,1.);
#9=DIRECTION('',(1.,0.,0.));
#10=CARTESIAN_POINT('',(2.,0.,5.));
#11=CARTESIAN_POINT('',(0.,2.,-1.));
#12=CIRCLE('',#4,2.);
#13=TRIMMED_CURVE('',#12,(#10),(#11),.T.,.CARTESIAN.);
#14=VECTOR('',#2,4.);
#15=LINE('',#1,#14);
#16=TRIMMED_CURVE('',#15,(PARAMETER_VALUE(0.5)),(PARAMETER_VALUE(2.)),.T.,.PARAMETER.);
ENDSEC;
";

#[test]
fn entities_are_read_or_refused_by_name() {
    let table = table_of(SMALL);
    let ctx = Context::<R> {
        table: &table,
        angle_unit: AngleUnit::radian(),
        bspline_curve: None,
    };
    assert!(matches!(
        geometry::surface_pieces(&ctx, 6, &[]),
        Ok(Surface::Unsupported { id: 6, ref name }) if name == "OFFSET_SURFACE"
    ));
    let e = geometry::surface_pieces(&ctx, 7, &[])
        .unwrap_err()
        .to_string();
    assert!(e.contains("#7 CYLINDRICAL_SURFACE"), "{e}");
    let e = geometry::curve_pieces(&ctx, 8, &[])
        .unwrap_err()
        .to_string();
    assert!(e.contains("#9 DIRECTION"), "{e}");
    // The cylinder's pieces cover the boundary points' heights exactly.
    let pts = vec![v3("2", "0", "5"), v3("0", "2", "-1")];
    let Ok(Surface::Pieces(s)) = geometry::surface_pieces(&ctx, 5, &pts) else {
        panic!("a cylinder");
    };
    assert_eq!(s.patches.len(), 4);
    assert_eq!(
        s.patches[0].eval(&R::zero(), &R::zero()).unwrap(),
        v3("2", "0", "-1")
    );
    assert_eq!(
        s.patches[0].eval(&R::zero(), &R::one()).unwrap(),
        v3("2", "0", "5")
    );
    // A circle trimmed between two points: a quarter, exactly on it; the
    // points (2,0,5) and (0,2,-1) are off its plane by 5 and 1 (squared 25, 1).
    let Ok(Curve::Pieces(c)) = geometry::curve_pieces(&ctx, 13, &[]) else {
        panic!("a trimmed circle");
    };
    assert_eq!(c.pieces.len(), 1);
    assert_eq!(c.trim_distance_sq, Some([dec("25"), dec("1")]));
    // A line trimmed by parameters: |V| = 4, so from (0,0,2) to (0,0,8).
    let Ok(Curve::Pieces(l)) = geometry::curve_pieces(&ctx, 16, &[]) else {
        panic!("a trimmed line");
    };
    assert_eq!(l.pieces[0].eval(&R::zero()).unwrap(), v3("0", "0", "2"));
    assert_eq!(l.pieces[0].eval(&R::one()).unwrap(), v3("0", "0", "8"));
}

type Q = BigRational;

/// The rational circle of radius 5/2 about (1, 2, 3) in a rational frame.
fn q_circle() -> Vec<RationalCurve<Q>> {
    let q = |n: i64, d: i64| ratio::<Q>(n, d);
    let f = Frame::from_axes(
        vec![q(1, 1), q(2, 1), q(3, 1)],
        vec![q(3, 5), q(4, 5), q(0, 1)],
        vec![q(0, 1), q(0, 1), q(1, 1)],
    );
    circle(&f, &q(5, 2))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Trimming at two vertices on the curve gives pieces whose ends are
    /// the vertices (distance 0) and which, piece by piece, are the
    /// original pieces subdivided (de Casteljau) at the vertices.
    #[test]
    fn trim_between_resubdivides(k1 in 0usize..4, m1 in 1i64..256, k2 in 0usize..4, m2 in 1i64..256, sense: bool) {
        let arcs = q_circle();
        let (t1, t2) = (ratio::<Q>(m1, 256), ratio::<Q>(m2, 256));
        let (a, b) = (arcs[k1].eval(&t1).unwrap(), arcs[k2].eval(&t2).unwrap());
        let tr = trim_between(&arcs, &a, &b, sense, 0.0).unwrap();
        prop_assert!(tr.start_distance_sq == ratio(0, 1) && tr.end_distance_sq == ratio(0, 1));
        prop_assert_eq!(&tr.start, &a);
        prop_assert_eq!(&tr.end, &b);
        prop_assert_eq!(tr.pieces[0].eval(&ratio(0, 1)).unwrap(), a.clone());
        prop_assert_eq!(tr.pieces.last().unwrap().eval(&ratio(1, 1)).unwrap(), b.clone());
        // The expected pieces, in edge direction, built with subdivide.
        let one = ratio::<Q>(1, 1);
        let (work, (ks, ts), (ke, te)) = if sense {
            (arcs.clone(), (k1, t1), (k2, t2))
        } else {
            let rev: Vec<_> = arcs.iter().rev().map(RationalCurve::reverse).collect();
            (rev, (3 - k1, one.clone() - &t1), (3 - k2, one.clone() - &t2))
        };
        let whole = a == b;
        let mut want = Vec::new();
        if !whole && ks == ke && ts < te {
            let (left, _) = work[ks].subdivide(&te);
            want.push(left.subdivide(&(ts.clone() / &te)).1);
        } else {
            want.push(work[ks].subdivide(&ts).1);
            let mut k = (ks + 1) % 4;
            while k != ke {
                want.push(work[k].clone());
                k = (k + 1) % 4;
            }
            want.push(work[ke].subdivide(&te).0);
        }
        prop_assert_eq!(tr.pieces, want);
    }

    /// A frame from integer directions is orthonormal and right-handed,
    /// exactly, with ẑ along the axis and x̂ towards ref_direction.
    #[test]
    fn frames_are_orthonormal(z in prop::array::uniform3(-4i64..5), x in prop::array::uniform3(-4i64..5)) {
        let to = |v: [i64; 3]| v.iter().map(|&c| R::from_i64(c)).collect::<Vec<R>>();
        let (z, x) = (to(z), to(x));
        let cross = [
            z[1].clone() * &x[2] - &(z[2].clone() * &x[1]),
            z[2].clone() * &x[0] - &(z[0].clone() * &x[2]),
            z[0].clone() * &x[1] - &(z[1].clone() * &x[0]),
        ];
        prop_assume!(cross.iter().any(|c| !c.is_zero()));
        let f = Frame::from_placement(&to([0, 0, 0]), Some(&z), Some(&x)).unwrap();
        let axes = [&f.x, &f.y, &f.z];
        for i in 0..3 {
            for j in 0..3 {
                let want = if i == j { R::one() } else { R::zero() };
                prop_assert_eq!(dot(axes[i], axes[j]), want);
            }
        }
        prop_assert!(dot(&f.z, &z) > R::zero());
        prop_assert!(dot(&f.x, &x) > R::zero());
        // det [x̂ ŷ ẑ] = x̂ · (ŷ × ẑ) = 1.
        let yz = [
            f.y[1].clone() * &f.z[2] - &(f.y[2].clone() * &f.z[1]),
            f.y[2].clone() * &f.z[0] - &(f.y[0].clone() * &f.z[2]),
            f.y[0].clone() * &f.z[1] - &(f.y[1].clone() * &f.z[0]),
        ];
        prop_assert_eq!(dot(&f.x, &yz), R::one());
    }
}
