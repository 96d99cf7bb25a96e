//! A symbolic proof of a user's own identity with `Poly`.
//!
//! The claim: splitting a rational cubic at t = 1/3 and evaluating the left
//! piece at s gives the original curve at s/3 — for every control point,
//! every weight and every s. The generic algorithms run unchanged on the
//! symbolic scalar `Poly`; the identity holds for all values of the symbols
//! exactly when the difference of the homogeneous results is the zero
//! polynomial. A wrong claim (the left piece at s equals the curve at s/2)
//! is refuted the same way, with a non-zero remainder.
//!
//! Run: `cargo run --example prove_identity`

use exact_bezier::{ratio, Poly, RationalCurve};

fn main() {
    let points = Poly::vars("p", 4);
    let weights = Poly::vars("w", 4);
    let curve = RationalCurve::new(points.iter().map(|p| vec![p.clone()]).collect(), weights)
        .expect("four symbolic control points");
    let s = Poly::var("s");
    let third = Poly::constant(ratio(1, 3));

    let (left, _right) = curve.subdivide(&third);
    let lhs = left.eval_hom(&s);
    let rhs = curve.eval_hom(&(s.clone() * &third));
    let holds = lhs == rhs;
    println!("left piece at s == curve at s/3 for all p, w, s: {holds}");
    assert!(holds);

    let wrong = curve.eval_hom(&(s.clone() * &Poly::constant(ratio(1, 2))));
    let refuted = lhs != wrong;
    println!("left piece at s == curve at s/2: refuted = {refuted}");
    let difference = lhs.weight().clone() - wrong.weight();
    println!("  weight difference (not the zero polynomial): {difference}");
    assert!(refuted);
}
