//! Exact coincidence and bulk de-duplication of patches.
//!
//! Source 000's Example 1 (a rational bicubic) is reparameterized by a
//! Möbius map, reversed and degree-elevated: a different control net for
//! the same surface. `coincide` says so exactly and returns the witness
//! (the symmetry and the exact Möbius parameters); a copy with one weight
//! changed by one part in a million is reported as different, with the
//! reason. `dedup` groups all of them into classes by their canonical keys.
//!
//! Run from the crate root: `cargo run --example dedup_patches`

use exact_bezier::{
    coincide::coincide, coincide::dedup, coincide::Options, io::read_patches, ratio, Patch,
};
use num_rational::BigRational;

fn main() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/yang_yong_example1.json"
    );
    let text = std::fs::read_to_string(path).expect("the fixture exists");
    let original = read_patches(&text).expect("valid JSON").remove(0);
    let Patch::Rect(rect) = &original else {
        unreachable!("Example 1 is a rect patch")
    };

    let copy = Patch::Rect(
        rect.mobius_u(&ratio(3, 5))
            .mobius_v(&ratio(7, 10))
            .reverse_v()
            .elevate(1, 2),
    );
    let mut weights = rect.weights();
    weights[1][1] = weights[1][1].clone() * ratio::<BigRational>(1_000_001, 1_000_000);
    let points = rect
        .ctrl()
        .iter()
        .map(|row| row.iter().map(|h| h.project().expect("w > 0")).collect())
        .collect();
    let perturbed =
        Patch::Rect(exact_bezier::RectPatch::new(points, weights).expect("positive weights"));

    let same = coincide(&original, &copy, Options::default()).expect("two rect patches");
    println!(
        "Möbius + reversed + elevated copy: coincident = {}",
        same.coincident
    );
    if let Some(w) = &same.witness {
        println!("  witness symmetry: {}", w.symmetry);
    }
    let differ = coincide(&original, &perturbed, Options::default()).expect("two rect patches");
    println!(
        "one weight × (1 + 10⁻⁶): coincident = {} ({})",
        differ.coincident, differ.reason
    );

    let classes = dedup(&[original, perturbed, copy]).expect("valid patches");
    println!("classes: {classes:?}");
    assert_eq!(classes, vec![vec![0, 2], vec![1]]);
}
