//! The lecture's evaluation quiz (source 001, "计算Bezier曲线上一点的值"):
//! the cubic with control points (10,0), (30,60), (130,60), (190,0) at
//! t = 1/2; the lecture marks answer C, (85, 45).

use super::{Claim, Verdict};
use exact_bezier::algebra::ratio;
use exact_bezier::curve::RationalCurve;
use num_rational::BigRational;

/// The quiz, checked by de Casteljau and by the hand-expanded Bernstein sum
/// `(P0 + 3P1 + 3P2 + P3)/8`.
pub fn claims() -> Vec<Claim> {
    let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    let pts = vec![p(10, 0), p(30, 60), p(130, 60), p(190, 0)];
    let curve = RationalCurve::polynomial(pts).expect("four 2D points");
    let ours = curve.eval(&ratio(1, 2)).expect("polynomial curve");
    // By hand: x = (10 + 90 + 390 + 190)/8 = 85, y = (0 + 180 + 180 + 0)/8 = 45.
    let by_hand = p(85, 45);
    let choices = [
        ("A", p(85, 30)),
        ("B", p(100, 45)),
        ("C", p(85, 45)),
        ("D", p(100, 30)),
    ];
    let chosen: Vec<&str> = choices
        .iter()
        .filter(|(_, c)| *c == ours)
        .map(|(k, _)| *k)
        .collect();
    vec![Claim::compare(
        "quiz: the cubic (10,0),(30,60),(130,60),(190,0) at t = 1/2 is answer C = (85, 45)",
        "001 lecture, quiz after de Casteljau",
        Verdict::Reproduced,
        chosen == ["C"] && ours == by_hand,
        "C (85,45)",
        &format!("({}, {}) = choice {:?}", ours[0], ours[1], chosen),
    )]
}
