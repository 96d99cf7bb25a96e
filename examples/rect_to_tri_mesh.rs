//! Convert a rectangular patch into two triangular patches exactly, check
//! the conversion at a point, and write a triangle mesh.
//!
//! A rational (2, 1) patch becomes two triangles of degree 3 (source 003,
//! Theorem 2.3). The first triangle at barycentric (u, v, 1 − u − v) equals
//! the rectangle at (u, v), exactly. The triangles are then meshed with
//! exact normals and written as an OBJ file to the system's temporary
//! directory.
//!
//! Run: `cargo run --example rect_to_tri_mesh` (feature `render`: on in the
//! workspace; for the crate alone add `--features render`)

use exact_bezier::{convert::rect_to_tris, ratio, render::Mesh, Patch, RectPatch};
use num_rational::BigRational;

fn main() {
    let p = |x: i64, y: i64, z: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1), ratio(z, 1)];
    let rect = RectPatch::new(
        vec![
            vec![p(0, 0, 0), p(0, 2, 1)],
            vec![p(1, 0, 2), p(1, 2, 3)],
            vec![p(2, 0, 0), p(2, 2, 1)],
        ],
        vec![
            vec![ratio(1, 1), ratio(2, 1)],
            vec![ratio(1, 2), ratio(1, 1)],
            vec![ratio(1, 1), ratio(3, 2)],
        ],
    )
    .expect("a (2, 1) patch with positive weights");

    let [t1, t2] = rect_to_tris(&rect);
    println!(
        "rect degree {:?} → two tris of degree {}",
        rect.degree(),
        t1.degree()
    );

    let (u, v) = (ratio::<BigRational>(1, 5), ratio(1, 2));
    let on_rect = rect.eval(&u, &v).expect("no pole");
    let on_tri = t1.eval(&u, &v).expect("no pole");
    let shown: Vec<String> = on_rect.iter().map(ToString::to_string).collect();
    println!(
        "rect(1/5, 1/2) = tri(1/5, 1/2, 3/10) = ({})",
        shown.join(", ")
    );
    assert_eq!(on_rect, on_tri, "the conversion is exact");

    let mesh = Mesh::from_patches(&[Patch::Tri(t1), Patch::Tri(t2)], 16).expect("finite normals");
    let path = std::env::temp_dir().join("exact_bezier_rect_to_tri.obj");
    std::fs::write(&path, mesh.to_obj()).expect("the temporary directory is writable");
    println!("wrote {}", path.display());
}
