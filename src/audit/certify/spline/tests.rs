use super::*;
use crate::algebra::{RealAlgebraic, Scalar};
use crate::audit::certify::field::normal_curvature;
use crate::audit::certify::Verdict;
use crate::audit::joint::{measure_joint, JointFace, JointSurface, JointTolerances, Measure};
use crate::curve::RationalCurve;
use crate::hpoint::HPoint;
use crate::nurbs::Nurbs;
use crate::ratio;

fn q(n: i64, d: i64) -> Q {
    ratio(n, d)
}

/// The homogeneous point `(w·x, w·y, w·z, w)`.
fn h(x: Q, y: Q, z: Q, w: Q) -> HPoint<Q> {
    HPoint {
        coords: vec![&x * &w, &y * &w, &z * &w, w],
    }
}

/// The quarter cylinder `x² + y² = 1`, `0 ≤ z ≤ 2`: in `u` the quarter
/// circle `((1 − u²), 2u)/(1 + u²)` written in Bernstein form (control
/// points `(1, 0)`, `(1, 1)`, `(0, 1)` with weights 1, 1, 2), in `v` the
/// line `z = 2v` as a quadratic B-spline with knots `0, 0, 0, ½, 1, 1, 1`
/// (control values `2 × ` the Greville abscissae `0, ¼, ¾, 1`): two pieces,
/// `C¹` across `v = ½`. `S_u × S_v` points away from the axis.
fn quarter_cylinder() -> NurbsSurface<Q> {
    let zs = [q(0, 1), q(1, 2), q(3, 2), q(2, 1)];
    let circle = [
        (q(1, 1), q(0, 1), q(1, 1)),
        (q(1, 1), q(1, 1), q(1, 1)),
        (q(0, 1), q(1, 1), q(2, 1)),
    ];
    let net = circle
        .iter()
        .map(|(x, y, w)| {
            zs.iter()
                .map(|z| h(x.clone(), y.clone(), z.clone(), w.clone()))
                .collect()
        })
        .collect();
    let u = Knots::new(2, [0, 0, 0, 1, 1, 1].map(|k| q(k, 1)).to_vec(), 3).unwrap();
    let v = Knots::new(
        2,
        vec![
            q(0, 1),
            q(0, 1),
            q(0, 1),
            q(1, 2),
            q(1, 1),
            q(1, 1),
            q(1, 1),
        ],
        4,
    )
    .unwrap();
    NurbsSurface::new(u, v, net).unwrap()
}

/// The plane `x = 1` for `−1 ≤ y ≤ 0`, `0 ≤ z ≤ 2`: `(1, −u, 2v)`, bilinear,
/// with an interior knot in `u` (multiplicity 1 of degree 1: only `C⁰` by
/// its knot vector). `S_u × S_v = (−2, 0, 0)`, toward the cylinder's axis.
fn tangent_plane() -> NurbsSurface<Q> {
    let net = [0, 1, 2]
        .iter()
        .map(|&i| {
            [0, 1]
                .iter()
                .map(|&j| h(q(1, 1), q(-i, 2), q(2 * j, 1), q(1, 1)))
                .collect()
        })
        .collect();
    let u = Knots::new(1, vec![q(0, 1), q(0, 1), q(1, 2), q(1, 1), q(1, 1)], 3).unwrap();
    let v = Knots::new(1, vec![q(0, 1), q(0, 1), q(1, 1), q(1, 1)], 2).unwrap();
    NurbsSurface::new(u, v, net).unwrap()
}

fn pieces(s: &NurbsSurface<Q>) -> Vec<SpannedPatch> {
    Nurbs::Surface(s.clone()).pieces()
}

fn contains(x: &Interval, value: f64, width: f64) -> bool {
    x.lo <= value && value <= x.hi && x.width() <= width
}

/// A point `3/2` from the axis, on the knot line `z = 1`: `s = 1/2` (the
/// cylinder's closed form), `N` radial, and the normal curvatures at the
/// foot those of the unit cylinder: `−1` around it, 0 along it.
#[test]
fn a_point_off_a_b_spline_cylinder_has_the_cylinder_s_distance_and_curvatures() {
    let s = quarter_cylinder();
    let ps = pieces(&s);
    let field_surface = SplineSurface::new(&s, &ps).unwrap();
    let field = SplineField::new(&field_surface);
    let (c, sn) = (0.6f64, 0.8f64);
    let p = [1.5 * c, 1.5 * sn, 1.0].map(Interval::point);
    let d = field.distance(&p).unwrap();
    assert!(contains(&d.signed, 0.5, 1e-12), "{:?}", d.signed);
    for (n, want) in d.normal.iter().zip([c, sn, 0.0]) {
        assert!(contains(n, want, 1e-12), "{n:?} ≠ {want}");
    }
    let j = field
        .normal_jacobian_at_foot(&p, &d.normal, &d.signed)
        .unwrap();
    let around = [-sn, c, 0.0].map(Interval::point);
    let along = [0.0, 0.0, 1.0].map(Interval::point);
    assert!(contains(
        &normal_curvature(&j, &around).unwrap(),
        -1.0,
        1e-9
    ));
    assert!(contains(&normal_curvature(&j, &along).unwrap(), 0.0, 1e-9));
    // Off the surface, J is that of the distance field: 1/ρ around.
    let j = field.normal_jacobian(&p).unwrap();
    assert!(contains(
        &normal_curvature(&j, &around).unwrap(),
        -1.0 / 1.5,
        1e-9
    ));
    // A box of points: every point's distance lies in the enclosure.
    let b: Vec<Interval> = p
        .iter()
        .map(|x| Interval {
            lo: x.lo - 1e-3,
            hi: x.hi + 1e-3,
        })
        .collect();
    let wide = field.distance(&b).unwrap();
    assert!(
        wide.signed.lo <= 0.5 - 1e-3 && 0.5 + 1e-3 <= wide.signed.hi,
        "{:?}",
        wide.signed
    );
}

/// Boxes across a knot the knot vector makes only `C⁰` are refused, boxes
/// that only touch it are not; nor are boxes a little beyond the border,
/// while boxes beyond a quarter of the border span are.
#[test]
fn jets_are_refused_across_a_c0_knot_and_far_beyond_the_border() {
    let s = tangent_plane();
    let ps = pieces(&s);
    let field_surface = SplineSurface::new(&s, &ps).unwrap();
    let field = SplineField::new(&field_surface);
    let v = Interval { lo: 0.25, hi: 0.5 };
    let across = Interval { lo: 0.25, hi: 0.75 };
    assert!(matches!(field.jet(across, v), Err(Error::Domain(_))));
    assert!(field.jet(Interval { lo: 0.25, hi: 0.5 }, v).is_ok());
    assert!(field.jet(Interval { lo: 0.5, hi: 0.75 }, v).is_ok());
    assert!(field.jet(Interval::point(0.5), v).is_ok());
    let near = field.jet(Interval { lo: -0.1, hi: 0.0 }, v).unwrap();
    // y = −u, continued: over u ∈ [−0.1, 0], y ∈ [0, 0.1].
    assert!(near.x[1].lo <= 0.0 && 0.1 <= near.x[1].hi && near.x[1].width() < 0.1 + 1e-9);
    assert!(matches!(
        field.jet(Interval { lo: -0.2, hi: 0.0 }, v),
        Err(Error::Domain(_))
    ));
    // The cylinder is C¹ across v = ½: boxes across it are taken (S_v = (0, 0, 2)
    // is enclosed, loosely over a wide box: the quotient rule's terms do not cancel).
    let c = quarter_cylinder();
    let cp = pieces(&c);
    let cyl_surface = SplineSurface::new(&c, &cp).unwrap();
    let cyl = SplineField::new(&cyl_surface);
    let j = cyl.jet(Interval { lo: 0.2, hi: 0.3 }, across).unwrap();
    assert!(contains(&j.xv[2], 2.0, 1.0), "{:?}", j.xv[2]);
}

/// A point over the `C⁰` knot line of the plane: its foot box straddles the
/// line, so it is not proved (and no wrong answer is given); points beside
/// it are.
#[test]
fn feet_on_a_c0_knot_line_are_not_proved() {
    let s = tangent_plane();
    let ps = pieces(&s);
    let field_surface = SplineSurface::new(&s, &ps).unwrap();
    let field = SplineField::new(&field_surface);
    let on = [1.25, -0.5, 1.0].map(Interval::point);
    assert!(field.distance(&on).is_none());
    let beside = [1.25, -0.25, 1.0].map(Interval::point);
    let d = field.distance(&beside).unwrap();
    // S_u × S_v points to −x: the point at x = 1.25 is on the negative side.
    assert!(contains(&d.signed, -0.25, 1e-12), "{:?}", d.signed);
}

/// The edge `(1, 0, z)` between the quarter cylinder and its tangent plane,
/// both B-spline faces and both along their borders: gap 0, the tangent
/// planes agree (G1; the plane's face is reversed so that both normals
/// point away from the axis), and the normal curvatures across the edge
/// are `−1` and `0` (independent: the cylinder's radius), so G2 fails by 1.
#[test]
fn a_b_spline_cylinder_and_its_tangent_plane_are_g1_not_g2() {
    let (c, p) = (quarter_cylinder(), tangent_plane());
    let (cp, pp) = (pieces(&c), pieces(&p));
    let (cs, ps) = (
        SplineSurface::new(&c, &cp).unwrap(),
        SplineSurface::new(&p, &pp).unwrap(),
    );
    let faces = [
        JointFace {
            surface: JointSurface::Spline(Box::new(SplineField::new(&cs))),
            same_sense: true,
        },
        JointFace {
            surface: JointSurface::Spline(Box::new(SplineField::new(&ps))),
            same_sense: false,
        },
    ];
    let r = |n: i64| RealAlgebraic::from_i64(n);
    let edge = RationalCurve::polynomial(vec![
        vec![r(1), r(0), r(0)],
        vec![r(1), r(0), RealAlgebraic::from_rational(&q(1, 8))],
    ])
    .unwrap();
    // The gaps, bounded by composition along the faces' borders, come out
    // near 10⁻¹⁴; an edge of length 1/8 keeps the angle's Krawczyk feet
    // within the cap of a measure on B-spline faces.
    let tol = JointTolerances {
        length: Some(Interval::point(1e-7)),
        angle: Interval::point(1e-6),
        curvature: Interval::point(1e-3),
    };
    let m = measure_joint(&[edge], &faces, &tol).unwrap();
    assert_eq!(m.g0, Verdict::WithinTolerance, "{m:?}");
    assert_eq!(m.g1, Verdict::WithinTolerance, "{m:?}");
    let Some(Measure::Enclosed { value, .. }) = m.curvature else {
        panic!("{m:?}")
    };
    assert!(
        value.lo <= 1.0 && 1.0 <= value.hi && value.hi - value.lo < 1e-2,
        "{value:?}"
    );
    assert!(matches!(m.g2, Some(Verdict::Fails { .. })), "{m:?}");
}

/// An edge a known distance off a B-spline face: the line
/// `(1 + 10⁻⁷, y, 1)` against the plane `x = 1` (both faces): the gap
/// enclosure holds `10⁻⁷`, its upper bound within `10⁻⁹` of it.
#[test]
fn a_gap_to_a_b_spline_face_is_measured_right() {
    let p = tangent_plane();
    let pp = pieces(&p);
    let surface = SplineSurface::new(&p, &pp).unwrap();
    let face = || JointFace {
        surface: JointSurface::Spline(Box::new(SplineField::new(&surface))),
        same_sense: false,
    };
    let faces = [face(), face()];
    let off = RealAlgebraic::from_rational(&(q(1, 1) + q(1, 10_000_000)));
    let r = |n: i64, d: i64| RealAlgebraic::from_rational(&q(n, d));
    let edge = RationalCurve::polynomial(vec![
        vec![off.clone(), r(-1, 8), r(1, 1)],
        vec![off, r(-3, 8), r(1, 1)],
    ])
    .unwrap();
    let tol = JointTolerances {
        length: None,
        angle: Interval::point(1e-6),
        curvature: Interval::point(1e-3),
    };
    let m = measure_joint(&[edge], &faces, &tol).unwrap();
    let Measure::Enclosed { value, .. } = m.gap[0] else {
        panic!("{m:?}")
    };
    // The upper bound is tight; the lower is 0 on B-spline faces (a foot
    // found by Newton is not proved the nearest).
    assert!(
        value.lo <= 1e-7 && 1e-7 <= value.hi && value.hi < 1e-7 + 1e-9,
        "{value:?}"
    );
}

/// The line `(1 + 10⁻⁷, 0, z)`, `0 ≤ z ≤ 2`: radially `10⁻⁷` outside the
/// quarter cylinder's border `u = 0`, along its whole height.
fn line_off_the_border() -> ICurve {
    line_off_the_border_by(q(1, 10_000_000))
}

/// The line `(1 + d, 0, z)`, `0 ≤ z ≤ 2`.
fn line_off_the_border_by(d: Q) -> ICurve {
    let x = q(1, 1) + d;
    let line = RationalCurve::polynomial(vec![
        vec![x.clone(), q(0, 1), q(0, 1)],
        vec![x, q(0, 1), q(2, 1)],
    ])
    .unwrap();
    ICurve::new(&line).unwrap()
}

/// `gap_over` along the whole height of the quarter cylinder, across its
/// interior knot line, for the line `(1 + 10⁻⁷, 0, z)`, radially `10⁻⁷`
/// outside its border `u = 0`: the bound holds `10⁻⁷` and is within
/// `10⁻⁹` of it, in one piece of the edge.
#[test]
fn a_composed_gap_bound_crosses_a_knot_line_and_holds_the_border() {
    let (c, curve) = (quarter_cylinder(), line_off_the_border());
    let cp = pieces(&c);
    let surface = SplineSurface::new(&c, &cp).unwrap();
    let field = SplineField::new(&surface);
    let b = field
        .gap_over(&curve, Interval { lo: 0.0, hi: 1.0 })
        .unwrap();
    assert!((1e-7..1e-7 + 1e-9).contains(&b), "{b}");
}

/// The normal of the quarter cylinder along the line `(1 + 10⁻⁷, 0, z)`,
/// `0 ≤ z ≤ 2`, on each side of its knot line: the foot normal is
/// `(1, 0, 0)` all along (independently: radial at `y = 0`). The path's
/// angle to it plus the slack (the foot is within `2g/σ` of the fitted
/// curve, `g ≈ 10⁻⁷`, and the unit cylinder's normal turns at rate 2 per
/// unit of `u` where `|S_u| = 2`) stays under `10⁻⁶`.
#[test]
fn a_normal_path_along_a_b_spline_cylinder_is_radial() {
    let (c, curve) = (quarter_cylinder(), line_off_the_border());
    let cp = pieces(&c);
    let surface = SplineSurface::new(&c, &cp).unwrap();
    let field = SplineField::new(&surface);
    let t = Interval { lo: 0.0, hi: 1.0 };
    let cuts = field.cuts(&curve, t).unwrap();
    assert_eq!(cuts.len(), 1, "{cuts:?}");
    assert!((cuts[0] - 0.5).abs() < 1e-9, "{cuts:?}");
    let radial = [1.0, 0.0, 0.0].map(|x| vec![Interval::point(x)]);
    for part in parts(t, &cuts) {
        let path = field.normal_over(&curve, part).unwrap();
        let (upper, _) =
            crate::audit::certify::normal_path::angle_between(&path.normal, &radial).unwrap();
        assert!(
            path.slack > 0.0 && upper + path.slack < 1e-6,
            "{upper} {}",
            path.slack
        );
    }
}

/// The line `((1 + d)·3/5, (1 + d)·4/5, z)`, `0 ≤ z ≤ 2`: radially `d`
/// off the quarter cylinder at `u = 1/2` (`((1 − u²), 2u)/(1 + u²)`).
fn line_off_the_middle_by(d: Q) -> ICurve {
    let r = q(1, 1) + d;
    let (x, y) = (&r * &q(3, 5), &r * &q(4, 5));
    let line = RationalCurve::polynomial(vec![
        vec![x.clone(), y.clone(), q(0, 1)],
        vec![x, y, q(2, 1)],
    ])
    .unwrap();
    ICurve::new(&line).unwrap()
}

/// A field remembers the feet of a piece of an edge by its curve as well
/// as its parameters: two curves of one edge, both over `[0, 1]`, each get
/// their own. The line at `u = 1/2`, `10⁻⁷` off the quarter cylinder, is
/// bounded within `10⁻⁹` of `10⁻⁷` after the line along its border was
/// (until 2026-11-28 the second took the first's feet, keyed by the
/// parameters alone, and its bound was `|(3/5, 4/5) − (1, 0)|`, 0.89).
#[test]
fn feet_are_remembered_per_curve() {
    let c = quarter_cylinder();
    let cp = pieces(&c);
    let surface = SplineSurface::new(&c, &cp).unwrap();
    let field = SplineField::new(&surface);
    let whole = Interval { lo: 0.0, hi: 1.0 };
    let (border, middle) = (
        line_off_the_border(),
        line_off_the_middle_by(q(1, 10_000_000)),
    );
    assert!(field.gap_over(&border, whole).is_some());
    let b = field.gap_over(&middle, whole).unwrap();
    assert!((1e-7..1e-7 + 1e-9).contains(&b), "{b}");
}

/// The curvature across an edge takes again the feet the normal path
/// proved on the same part: after `normal_over`, `curvature_over` charges
/// one jet (at the part's midpoint), far less than on a fresh field, where
/// it composes the piece with the fitted curve and proves the boxes.
#[test]
fn the_curvature_takes_the_feet_the_angle_proved() {
    let c = quarter_cylinder();
    let cp = pieces(&c);
    let surface = SplineSurface::new(&c, &cp).unwrap();
    let curve = line_off_the_middle_by(q(1, 1000));
    let part = Interval { lo: 0.0, hi: 0.5 };
    let charged = |field: &SplineField<'_>| {
        limits::with_limits(limits::Limits::DEFAULT, || {
            assert!(field.curvature_over(&curve, part).is_some());
            limits::charged()
        })
    };
    let fresh = charged(&SplineField::new(&surface));
    let field = SplineField::new(&surface);
    assert!(field.normal_over(&curve, part).is_some());
    let again = charged(&field);
    // One bi-quadratic piece's jet: 9 control points.
    assert_eq!(
        again,
        JET_WORK * 9,
        "{again} after the angle, {fresh} fresh"
    );
    assert!(fresh > 3 * again, "{fresh}");
}

/// Points a little beyond the plane's border `u = 0` (`y > 0`): their feet
/// on the plane's continuation are refused, since the face's nearest point
/// is on its border, not there; a foot beyond it by a rounding error
/// (10⁻¹² of the domain) is the face's, with the plane's distance.
#[test]
fn feet_on_the_continuation_past_the_border_are_refused() {
    let s = tangent_plane();
    let ps = pieces(&s);
    let field_surface = SplineSurface::new(&s, &ps).unwrap();
    let field = SplineField::new(&field_surface);
    // Within the border's reach (a quarter of the span 1/2): Newton finds
    // the foot u = −0.1, −10⁻⁸, which is not on the face.
    for y in [0.1, 1e-8] {
        assert!(field
            .distance(&[1.25, y, 1.0].map(Interval::point))
            .is_none());
    }
    let d = field
        .distance(&[1.25, 1e-12, 1.0].map(Interval::point))
        .unwrap();
    assert!(contains(&d.signed, -0.25, 1e-12), "{:?}", d.signed);
}

/// The unit cylinder `x² + y² = 1`, `0 ≤ z ≤ 2`, closed in `u`: four
/// rational quadratic quarter arcs on the spans `[k, k + 1]` (the first
/// with control points `(1, 0)`, `(1, 1)`, `(0, 1)` and weights 1, 1, 2, each
/// next one turned by a quarter and its weights doubled, so that the
/// homogeneous nets join), linear in `v`. The last arc ends at `(1, 0)`
/// with weight 16: its border row is 16 times the first's.
fn closed_cylinder() -> Vec<SpannedPatch> {
    let arc = [(1, 0, 1), (1, 1, 1), (0, 1, 2)];
    (0..4)
        .map(|k: i64| {
            let turn = |(x, y): (i64, i64)| match k {
                0 => (x, y),
                1 => (-y, x),
                2 => (-x, -y),
                _ => (y, -x),
            };
            let (points, weights): (Vec<Vec<Vec<Q>>>, Vec<Vec<Q>>) = arc
                .iter()
                .map(|&(x, y, w)| {
                    let (x, y) = turn((x, y));
                    let row = [0, 2].map(|z| vec![q(x, 1), q(y, 1), q(z, 1)]).to_vec();
                    (row, vec![q(w << k, 1); 2])
                })
                .unzip();
            SpannedPatch {
                patch: Patch::Rect(RectPatch::new(points, weights).unwrap()),
                u: [q(k, 1), q(k + 1, 1)],
                v: Some([q(0, 1), q(1, 1)]),
            }
        })
        .collect()
}

/// The cylinder is seen closed in `u` (not in `v`), and a point just
/// before its seam, asked right after one just past it (so that Newton
/// starts from the first arc and lands on its continuation below `u = 0`),
/// gets its foot on the last arc, where the surface is: the cylinder's
/// distance and radial normal.
#[test]
fn feet_past_a_closed_surface_s_seam_are_proved_on_the_other_side() {
    let ps = closed_cylinder();
    let surface = SplineSurface::from_pieces(&ps, |_| false, |_| false).unwrap();
    assert!(surface.axes[0].closed && !surface.axes[1].closed);
    assert!((surface.axes[0].wrap(-0.25) - 3.75).abs() < 1e-15);
    assert_eq!(surface.axes[1].wrap(-0.25), -0.25);
    let field = SplineField::new(&surface);
    for angle in [0.01f64, -0.01] {
        let (c, s) = (angle.cos(), angle.sin());
        let d = field
            .distance(&[2.0 * c, 2.0 * s, 1.0].map(Interval::point))
            .unwrap();
        assert!(contains(&d.signed, 1.0, 1e-12), "{angle}: {:?}", d.signed);
        for (n, want) in d.normal.iter().zip([c, s, 0.0]) {
            assert!(contains(n, want, 1e-12), "{angle}: {n:?} ≠ {want}");
        }
    }
    assert!(field.guess.get().unwrap()[0] > 3.9);
}

/// The line `(1 + 10⁻³, 0, z)`, really `10⁻³` off the quarter cylinder:
/// its feet are on the border `u = 0` (independently: radial at `y = 0`),
/// where the fitted curve runs, so the residual along it is rounding and
/// the slack (the tube's, [`super::tube`]) far below the `2·10⁻³` of the
/// bound from the gap alone (`L·2g/σ`, `L = σ = 2`): the path's angle to
/// the radial normal plus the slack stays under `10⁻⁹` on each side of
/// the knot line.
#[test]
fn a_normal_path_a_real_gap_off_a_b_spline_cylinder_has_a_small_slack() {
    let c = quarter_cylinder();
    let curve = line_off_the_border_by(q(1, 1000));
    let cp = pieces(&c);
    let surface = SplineSurface::new(&c, &cp).unwrap();
    let field = SplineField::new(&surface);
    let t = Interval { lo: 0.0, hi: 1.0 };
    let cuts = field.cuts(&curve, t).unwrap();
    let radial = [1.0, 0.0, 0.0].map(|x| vec![Interval::point(x)]);
    for part in parts(t, &cuts) {
        let path = field.normal_over(&curve, part).unwrap();
        let (upper, _) =
            crate::audit::certify::normal_path::angle_between(&path.normal, &radial).unwrap();
        assert!(upper + path.slack < 1e-9, "{upper} {}", path.slack);
    }
}
