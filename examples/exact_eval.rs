//! Exact evaluation, and an exact "is this a circle?" check.
//!
//! A rational quadratic with weights (1, 3/5, 1) is an arc of the unit
//! circle (half-angle cosine 3/5). Evaluated exactly at rational parameters,
//! every point satisfies x² + y² = 1 with no tolerance; `circle_of` finds
//! the centre and squared radius exactly. The same curve in `f64` is shown
//! for comparison: its residual is rounding noise, not zero.
//!
//! Run: `cargo run --example exact_eval`

use exact_bezier::{curve::circle_of, ratio, RationalCurve, Tolerance};
use num_rational::BigRational;

fn main() {
    let p = |x: BigRational, y: BigRational| vec![x, y];
    let arc = RationalCurve::new(
        vec![
            p(ratio(1, 1), ratio(0, 1)),
            p(ratio(1, 1), ratio(4, 3)),
            p(ratio(-7, 25), ratio(24, 25)),
        ],
        vec![ratio(1, 1), ratio(3, 5), ratio(1, 1)],
    )
    .expect("a well-formed curve");

    for k in 0..=4 {
        let t = ratio::<BigRational>(k, 4);
        let x = arc.eval(&t).expect("positive weights: no pole");
        let r2 = x[0].clone() * &x[0] + x[1].clone() * &x[1];
        println!("t = {t}: point ({}, {}), x² + y² = {r2}", x[0], x[1]);
        assert_eq!(r2, ratio(1, 1), "exactly on the unit circle");
    }

    let circle = circle_of(&arc, Tolerance::EXACT).expect("an arc of a circle");
    println!(
        "circle: centre ({}, {}), radius² {}",
        circle.center[0], circle.center[1], circle.radius_squared
    );

    let arc64 = arc.map(exact_bezier::algebra::rational_to_f64);
    let x = arc64.eval(&(1.0 / 3.0)).expect("no pole");
    println!(
        "f64 at t = 1/3: x² + y² − 1 = {:e} (rounding)",
        x[0] * x[0] + x[1] * x[1] - 1.0
    );
}
