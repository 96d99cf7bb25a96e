//! Meshes: vertex and face counts, every vertex on the surface (checked
//! against exact rational evaluation), unit normals orthogonal to tangents
//! taken by exact central differences (a second method), consistent
//! orientation, the OBJ/STL/PLY files read back, and the homogeneous
//! derivatives proved symbolically per patch.

use crate::common::bin;
use exact_bezier::strategy::{rect, tri};
use exact_bezier::{
    io::read_patches, ratio, render::rect_jet, render::tri_jet, render::Mesh, Patch, Poly,
    RectPatch, TriPatch,
};
use num_rational::BigRational;
use proptest::prelude::*;

const EXAMPLE1: &str = include_str!("../../../tests/fixtures/yang_yong_example1.json");
const TRI: &str = include_str!("../../../docs/figures/inputs/source003_fig5a_tri.json");

/// Position tolerance: relative to the model size (Example 1 spans ~70).
const POS_TOL: f64 = 1e-9;
/// Tolerance on |n| − 1 and on cos(normal, tangent) by central differences
/// with step h = 10⁻⁴ (error O(h²)).
const UNIT_TOL: f64 = 1e-12;
const ORTHO_TOL: f64 = 1e-6;

fn exact(text: &str) -> Patch<BigRational> {
    read_patches(text).unwrap().remove(0)
}

fn q(p: i64, d: i64) -> BigRational {
    ratio(p, d)
}

/// Exact point of a rect or tri patch at (u, v), rounded at the end.
fn point(p: &Patch<BigRational>, u: &BigRational, v: &BigRational) -> [f64; 3] {
    let x = match p {
        Patch::Rect(r) => r.eval(u, v).unwrap(),
        Patch::Tri(t) => t.eval(u, v).unwrap(),
        Patch::Curve(_) => unreachable!(),
    };
    let f: Vec<f64> = x
        .iter()
        .map(exact_bezier::algebra::rational_to_f64)
        .collect();
    [f[0], f[1], *f.get(2).unwrap_or(&0.0)]
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt()
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| a[k] * b[k]).sum()
}

/// The parameters of the mesh vertices in the documented order.
fn grid(p: &Patch<BigRational>, n: i64) -> Vec<(BigRational, BigRational)> {
    match p {
        Patch::Rect(_) => (0..=n)
            .flat_map(|i| (0..=n).map(move |j| (q(i, n), q(j, n))))
            .collect(),
        _ => (0..=n)
            .flat_map(|j| (0..=n - j).map(move |i| (q(i, n), q(j, n))))
            .collect(),
    }
}

/// Check positions against exact evaluation, unit normals, normals ⟂ exact
/// central-difference tangents (interior points), and faces turning with
/// their vertex normals.
fn check_mesh(p: &Patch<BigRational>, m: &Mesh, n: i64) {
    let h = q(1, 10_000);
    for ((u, v), (x, nrm)) in grid(p, n).iter().zip(m.positions.iter().zip(&m.normals)) {
        assert!(
            dist(*x, point(p, u, v)) < POS_TOL * 100.0,
            "vertex at ({u}, {v})"
        );
        assert!((dot(*nrm, *nrm).sqrt() - 1.0).abs() < UNIT_TOL);
        let interior = u - &h > q(0, 1) && v - &h > q(0, 1) && {
            let rect = matches!(p, Patch::Rect(_));
            if rect {
                u + &h < q(1, 1) && v + &h < q(1, 1)
            } else {
                u + v + &h < q(1, 1)
            }
        };
        if interior {
            for (du, dv) in [(h.clone(), q(0, 1)), (q(0, 1), h.clone())] {
                let a = point(p, &(u + &du), &(v + &dv));
                let b = point(p, &(u - &du), &(v - &dv));
                let t = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
                let cos = dot(t, *nrm) / dot(t, t).sqrt();
                assert!(
                    cos.abs() < ORTHO_TOL,
                    "normal not ⟂ tangent at ({u}, {v}): {cos}"
                );
            }
        }
    }
    for t in &m.triangles {
        let [a, b, c] = t.map(|k| m.positions[k]);
        let e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let f = [
            e1[1] * e2[2] - e1[2] * e2[1],
            e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0],
        ];
        let sum: [f64; 3] = (0..3)
            .map(|k| t.iter().map(|&i| m.normals[i][k]).sum::<f64>())
            .collect::<Vec<_>>()
            .try_into()
            .unwrap();
        assert!(
            dot(f, sum) > 0.0,
            "triangle {t:?} turns against its normals"
        );
    }
}

#[test]
fn rect_mesh_counts_and_vertices_on_the_surface() {
    let p = exact(EXAMPLE1);
    let m = Mesh::from_patches(&[p.to_f64()], 8).unwrap();
    assert_eq!(
        (m.positions.len(), m.normals.len(), m.triangles.len()),
        (81, 81, 128)
    );
    check_mesh(&p, &m, 8);
    // The exact path rounds the same numbers.
    let e = Mesh::from_patches(std::slice::from_ref(&p), 8).unwrap();
    for (a, b) in e.positions.iter().zip(&m.positions) {
        assert!(dist(*a, *b) < POS_TOL * 100.0);
    }
}

#[test]
fn tri_mesh_counts_and_vertices_on_the_surface() {
    let p = exact(TRI);
    let m = Mesh::from_patches(&[p.to_f64()], 7).unwrap();
    assert_eq!((m.positions.len(), m.triangles.len()), (36, 49));
    check_mesh(&p, &m, 7);
}

#[test]
fn collapsed_edge_gets_face_normals() {
    // A rect patch whose u = 0 edge is one point: X_u × X_v = 0 there.
    let text = r#"{"kind": "rect", "degree": [1, 1],
        "points": [[[0,0,0],[0,0,0]], [[1,0,0],[1,1,1]]]}"#;
    let m = Mesh::from_patches(&[exact(text).to_f64()], 4).unwrap();
    for n in &m.normals {
        assert!(n.iter().all(|c| c.is_finite()));
        assert!((dot(*n, *n).sqrt() - 1.0).abs() < UNIT_TOL);
    }
}

#[test]
fn curves_and_bad_densities_are_errors() {
    let c = read_patches(r#"{"kind": "curve", "degree": 1, "points": [[0,0],[1,1]]}"#).unwrap();
    assert!(Mesh::from_patches(&c, 4).is_err());
    let p = [exact(EXAMPLE1)];
    assert!(Mesh::from_patches(&p, 0).is_err());
    assert!(Mesh::from_patches(&p, 100_000).is_err());
    let four_d = r#"{"kind": "tri", "degree": 1, "points": [[[0,0,0,0],[1,0,0,0]],[[0,1,0,0]]]}"#;
    assert!(Mesh::from_patches(&read_patches(four_d).unwrap(), 2).is_err());
}

fn run_mesh(out: &std::path::Path, extra: &[&str]) -> std::process::Output {
    bin()
        .args([
            "mesh",
            "tests/fixtures/yang_yong_example1.json",
            "-o",
            out.to_str().unwrap(),
        ])
        .args(extra)
        .output()
        .unwrap()
}

/// Read an OBJ back into a mesh: `v`, `vn`, faces `a//a` (1-based).
fn read_obj(text: &str) -> Mesh {
    let (mut v, mut vn, mut f) = (Vec::new(), Vec::new(), Vec::new());
    let xyz = |w: Vec<&str>| -> [f64; 3] { [0, 1, 2].map(|k| w[k].parse().unwrap()) };
    for line in text.lines() {
        let mut w = line.split_whitespace();
        match w.next() {
            Some("v") => v.push(xyz(w.collect())),
            Some("vn") => vn.push(xyz(w.collect())),
            Some("f") => {
                let ids: Vec<usize> = w
                    .map(|s| {
                        let (a, b) = s.split_once("//").unwrap();
                        assert_eq!(a, b, "vertex and normal indices agree");
                        a.parse::<usize>().unwrap() - 1
                    })
                    .collect();
                f.push([ids[0], ids[1], ids[2]]);
            }
            _ => {}
        }
    }
    Mesh {
        positions: v,
        normals: vn,
        triangles: f,
    }
}

#[test]
fn obj_file_reads_back_onto_the_surface() {
    let dir = std::env::temp_dir().join(format!("exact-bezier-mesh-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join("e1.obj");
    let out = run_mesh(&obj, &["--density", "6"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        (report["vertices"].as_u64(), report["triangles"].as_u64()),
        (Some(49), Some(72))
    );
    let mesh = read_obj(&crate::common::read_to_string(&obj).unwrap());
    let counts = (
        mesh.positions.len(),
        mesh.normals.len(),
        mesh.triangles.len(),
    );
    assert_eq!(counts, (49, 49, 72));
    assert!(mesh.triangles.iter().flatten().all(|&k| k < 49));
    check_mesh(&exact(EXAMPLE1), &mesh, 6);

    let stl = dir.join("e1.stl");
    assert!(run_mesh(&stl, &["--density", "3", "--scalar", "exact"])
        .status
        .success());
    let text = crate::common::read_to_string(&stl).unwrap();
    assert!(text.starts_with("solid ") && text.trim_end().ends_with("endsolid exact_bezier"));
    assert_eq!(text.matches("facet normal").count(), 18);
    assert_eq!(text.matches("vertex ").count(), 54);

    let ply = dir.join("e1.ply");
    assert!(run_mesh(&ply, &["--density", "3"]).status.success());
    let text = crate::common::read_to_string(&ply).unwrap();
    let body: Vec<&str> = text.split("end_header\n").nth(1).unwrap().lines().collect();
    assert!(text.contains("element vertex 16\n") && text.contains("element face 18\n"));
    assert_eq!(body.len(), 16 + 18);
    assert!(body[16..].iter().all(|l| l.starts_with("3 ")));

    for bad in [vec!["--density", "0"], vec!["-o", "x.dae"]] {
        let o = if bad[0] == "-o" {
            bin()
                .args(["mesh", "tests/fixtures/yang_yong_example1.json"])
                .args(&bad)
                .output()
                .unwrap()
        } else {
            run_mesh(&dir.join("bad.obj"), &bad)
        };
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
    }
}

/// `H(u + h, v)` and `H(u, v + h)` as polynomials in h: the h¹ coefficients
/// are `H_u` and `H_v` (Taylor), checked for all (u, v) with symbols.
fn linear_in_h(
    shifted: &exact_bezier::hpoint::HPoint<Poly>,
    expected: &exact_bezier::hpoint::HPoint<Poly>,
) -> bool {
    shifted
        .coords
        .iter()
        .zip(&expected.coords)
        .all(|(a, b)| a.coeff_of("h", 1) == *b)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn rect_jet_is_the_derivative(r in rect(2, 2, 3)) {
        let s: RectPatch<Poly> = r.map(|c| Poly::constant(c.clone()));
        let (u, v, h) = (Poly::var("u"), Poly::var("v"), Poly::var("h"));
        let j = rect_jet(&s, &u, &v);
        prop_assert_eq!(&j.value, &s.eval_hom(&u, &v));
        prop_assert!(linear_in_h(&s.eval_hom(&(u.clone() + &h), &v), &j.du));
        prop_assert!(linear_in_h(&s.eval_hom(&u, &(v.clone() + &h)), &j.dv));
    }

    #[test]
    fn tri_jet_is_the_derivative(t in tri(3, 3)) {
        let s: TriPatch<Poly> = t.map(|c| Poly::constant(c.clone()));
        let (u, v, h) = (Poly::var("u"), Poly::var("v"), Poly::var("h"));
        let j = tri_jet(&s, &u, &v);
        prop_assert_eq!(&j.value, &s.eval_hom(&u, &v));
        prop_assert!(linear_in_h(&s.eval_hom(&(u.clone() + &h), &v), &j.du));
        prop_assert!(linear_in_h(&s.eval_hom(&u, &(v.clone() + &h)), &j.dv));
    }
}
