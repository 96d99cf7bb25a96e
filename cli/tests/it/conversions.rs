//! Conversions rect ↔ tri on random exact patches (evaluated at the mapped
//! parameters), the source 003 §4 fixtures, split validation and the CLI.

use crate::common::cli;
use exact_bezier::strategy::{rect, tri, unit_parameter};
use exact_bezier::{
    convert::bilinear, convert::rect_to_tri, convert::rect_to_tris, convert::square_corners,
    convert::tri_to_degenerate_rect, convert::tri_to_rect_hu, convert::tri_to_rect_on_quad,
    convert::tri_to_rects, convert::tri_to_rects_operators, convert::Half, convert::Split,
    io::read_patches, Error, Patch, RectPatch, TriPatch,
};
use num_rational::BigRational;
use num_traits::One;
use proptest::prelude::*;

type Q = BigRational;

fn r(p: i64, q: i64) -> Q {
    exact_bezier::ratio(p, q)
}

/// A point (u, v) of the closed triangle u, v ≥ 0, u + v ≤ 1.
fn in_triangle() -> impl Strategy<Value = (Q, Q)> {
    // (a(1 − b), ab): a ∈ [0, 1] scales the segment from T3 towards (1 − b, b).
    (unit_parameter(), unit_parameter()).prop_map(|(a, b)| (a.clone() * (Q::one() - &b), a * b))
}

/// A random split with p2, p4, p5 inside their edges and p3 in
/// (0, 0.45)², kept when [`Split::new`] accepts it (convex quadrilaterals).
fn split() -> impl Strategy<Value = Split<Q>> {
    (1i64..10, 1i64..10, 1i64..10, 1i64..9, 1i64..9).prop_filter_map(
        "a convex split",
        |(b, d, e, a, c)| {
            Split::new([
                r(a, 20),
                r(b, 10),
                r(c, 20),
                r(d, 10),
                r(e, 10),
                r(10 - e, 10),
            ])
            .ok()
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn rect_to_tris_keeps_points(p in rect(2, 3, 3), (u, v) in in_triangle()) {
        let [lower, upper] = rect_to_tris(&p);
        prop_assert_eq!(lower.eval(&u, &v).unwrap(), p.eval(&u, &v).unwrap());
        let (s, t) = Half::Upper.rect_param(&u, &v);
        prop_assert_eq!(upper.eval(&u, &v).unwrap(), p.eval(&s, &t).unwrap());
    }

    #[test]
    fn tri_to_rects_keeps_points(t in tri(3, 3), sp in split(), s in unit_parameter(), tt in unit_parameter()) {
        let rects = tri_to_rects(&t, &sp);
        for (d, piece) in rects.iter().enumerate() {
            let x = bilinear(&sp.quad(d).unwrap(), &s, &tt);
            prop_assert_eq!(piece.eval(&s, &tt).unwrap(), t.eval(&x[0], &x[1]).unwrap());
        }
    }

    #[test]
    fn operator_formulas_match_blossoming(t in tri(3, 2), sp in split()) {
        let blossoming = tri_to_rects(&t, &sp);
        prop_assert_eq!(&tri_to_rects_operators(&t, &sp), &blossoming);
        prop_assert_eq!(&tri_to_rect_hu(&t, &sp), &blossoming[0]);
    }

    #[test]
    fn degenerate_rect_keeps_points(t in tri(4, 2), s in unit_parameter(), tt in unit_parameter()) {
        let d = tri_to_degenerate_rect(&t);
        let v = (Q::one() - &s) * &tt;
        prop_assert_eq!(d.eval(&s, &tt).unwrap(), t.eval(&s, &v).unwrap());
    }

    #[test]
    fn round_trip_recovers_the_rectangle(p in rect(2, 2, 3), s in unit_parameter(), tt in unit_parameter()) {
        for (half, t) in [Half::Lower, Half::Upper].into_iter().zip(rect_to_tris(&p)) {
            let back = tri_to_rect_on_quad(&t, &square_corners(half));
            prop_assert_eq!(&back, &p.elevate(2, 2));
        }
        let d = tri_to_degenerate_rect(&rect_to_tri(&p, Half::Lower));
        let v = (Q::one() - &s) * &tt;
        prop_assert_eq!(d.eval(&s, &tt).unwrap(), p.eval(&s, &v).unwrap());
    }
}

#[test]
fn bad_splits_are_domain_errors() {
    let cases = [
        (
            [r(3, 10), r(0, 1), r(3, 10), r(1, 2), r(1, 2), r(1, 2)],
            "0 < b < 1",
        ),
        (
            [r(3, 10), r(1, 2), r(3, 10), r(1, 2), r(1, 2), r(1, 3)],
            "e + f = 1",
        ),
        (
            [r(7, 10), r(1, 2), r(3, 10), r(1, 2), r(1, 2), r(1, 2)],
            "inside the triangle",
        ),
        // p3 = (0.05, 0.05) close to T3: D1 = [T3, p2, p3, p4] turns right at p3.
        (
            [r(1, 20), r(1, 2), r(1, 20), r(1, 2), r(1, 2), r(1, 2)],
            "D1 is not strictly convex",
        ),
        // p3 near T1: D2 = [p2, T1, p5, p3] is not convex.
        (
            [r(8, 10), r(1, 2), r(1, 10), r(1, 2), r(1, 2), r(1, 2)],
            "not strictly convex",
        ),
    ];
    for (params, want) in cases {
        let err = Split::new(params).unwrap_err();
        assert!(matches!(err, Error::Domain(_)), "{err}");
        assert!(err.to_string().contains(want), "{err}");
    }
    assert!(Split::new(Split::<Q>::standard().params().clone()).is_ok());
}

fn fixture(name: &str) -> Vec<Patch<Q>> {
    let path = format!(
        "{}/tests/fixtures/{name}",
        concat!(env!("CARGO_MANIFEST_DIR"), "/..")
    );
    read_patches(&crate::common::read_to_string(path).unwrap()).unwrap()
}

fn as_rect(p: &Patch<Q>) -> &RectPatch<Q> {
    match p {
        Patch::Rect(r) => r,
        other => panic!("expected a rect, got a {}", other.kind()),
    }
}

fn as_tri(p: &Patch<Q>) -> &TriPatch<Q> {
    match p {
        Patch::Tri(t) => t,
        other => panic!("expected a tri, got a {}", other.kind()),
    }
}

const SAMPLES: [(i64, i64, i64); 5] = [(0, 0, 1), (1, 3, 7), (2, 5, 11), (1, 2, 4), (3, 1, 5)];

/// The written-out §4.1 triangles (Δ1 and the omitted Δ2) are the printed
/// rectangle at the mapped parameters.
#[test]
fn fixture_4_1_triangles_match_the_rectangle() {
    let input = fixture("zcf_4_1_rect.json");
    let rect = as_rect(&input[0]);
    let out = fixture("zcf_4_1_tris.json");
    for (half, p) in [Half::Lower, Half::Upper].into_iter().zip(&out) {
        let t = as_tri(p);
        assert_eq!(t.degree(), 4);
        assert_eq!(t.weight_sum(), Q::one());
        for (a, b, den) in SAMPLES {
            let (u, v) = (r(a, den), r(b, den));
            let (s, tt) = half.rect_param(&u, &v);
            assert_eq!(t.eval(&u, &v).unwrap(), rect.eval(&s, &tt).unwrap());
        }
    }
}

/// The written-out §4.2 rectangles (D1 and the omitted D2, D3) are the
/// printed triangle at the bilinear images.
#[test]
fn fixture_4_2_rectangles_match_the_triangle() {
    let input = fixture("zcf_4_2_tri.json");
    let t = as_tri(&input[0]);
    let out = fixture("zcf_4_2_rects.json");
    let sp = Split::new([r(3, 10), r(1, 2), r(3, 10), r(1, 2), r(1, 2), r(1, 2)]).unwrap();
    assert_eq!(out.len(), 3);
    for (d, p) in out.iter().enumerate() {
        let rect = as_rect(p);
        let total: Q = rect.weights().into_iter().flatten().sum();
        assert_eq!(total, Q::one());
        for (a, b, den) in SAMPLES {
            let (s, tt) = (r(a, den), r(b, den));
            let x = bilinear(&sp.quad(d).unwrap(), &s, &tt);
            assert_eq!(rect.eval(&s, &tt).unwrap(), t.eval(&x[0], &x[1]).unwrap());
        }
    }
}

/// The CLI regenerates the committed fixtures exactly.
#[test]
fn cli_reproduces_the_fixtures() {
    let (code, out, _) = cli(&[
        "convert",
        "tests/fixtures/zcf_4_1_rect.json",
        "--to",
        "tri",
        "--normalize",
    ]);
    assert_eq!(code, 0);
    let want = fixture("zcf_4_1_tris.json");
    assert_eq!(read_patches(&out).unwrap(), want);
    let (code, out, _) = cli(&[
        "convert",
        "tests/fixtures/zcf_4_2_tri.json",
        "--to",
        "rect",
        "--split",
        "0.3,0.5,0.3,0.5,0.5,0.5",
        "--normalize",
    ]);
    assert_eq!(code, 0);
    assert_eq!(read_patches(&out).unwrap(), fixture("zcf_4_2_rects.json"));
}

#[test]
fn cli_default_split_and_degenerate() {
    let t = as_tri(&fixture("zcf_4_2_tri.json")[0]).clone();
    let (code, out, _) = cli(&["convert", "tests/fixtures/zcf_4_2_tri.json", "--to", "rect"]);
    assert_eq!(code, 0);
    let got: Vec<RectPatch<Q>> = read_patches(&out)
        .unwrap()
        .iter()
        .map(|p| as_rect(p).clone())
        .collect();
    assert_eq!(got, tri_to_rects(&t, &Split::standard()).to_vec());
    let (code, out, _) = cli(&[
        "convert",
        "tests/fixtures/zcf_4_2_tri.json",
        "--to",
        "rect",
        "--degenerate",
    ]);
    assert_eq!(code, 0);
    assert_eq!(
        as_rect(&read_patches(&out).unwrap()[0]),
        &tri_to_degenerate_rect(&t)
    );
    let (code, out, _) = cli(&[
        "convert",
        "tests/fixtures/zcf_4_2_tri.json",
        "--to",
        "rect",
        "--scalar",
        "f64",
    ]);
    assert_eq!(code, 0);
    assert_eq!(read_patches(&out).unwrap().len(), 3);
}

#[test]
fn cli_rejects_bad_requests() {
    for args in [
        vec![
            "convert",
            "tests/fixtures/zcf_4_2_tri.json",
            "--to",
            "rect",
            "--split",
            "0.3,0.5,0.3,0.5,0.5,0.4",
        ],
        vec![
            "convert",
            "tests/fixtures/zcf_4_2_tri.json",
            "--to",
            "rect",
            "--split",
            "0.3,0.5",
        ],
        vec!["convert", "tests/fixtures/zcf_4_2_tri.json", "--to", "tri"],
        vec![
            "convert",
            "tests/fixtures/zcf_4_1_rect.json",
            "--to",
            "rect",
        ],
        vec![
            "convert",
            "tests/fixtures/zcf_4_1_rect.json",
            "--to",
            "tri",
            "--degenerate",
        ],
    ] {
        let (code, out, err) = cli(&args);
        assert_eq!(code, 2, "{args:?}: {out}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("error: "), "{err}");
    }
}
