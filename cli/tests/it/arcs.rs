//! Circular arcs of source 004: exact properties over random rational
//! half-angles (rational points of the unit circle, c = (1−τ²)/(1+τ²),
//! s = 2τ/(1+τ²)) and λ with perfect-cube radicands (λ built from a rational
//! σ: σ³ = N/D by construction), plus the command line.

use crate::common::cli;
use exact_bezier::strategy::point;
use exact_bezier::{
    algebra::RealAlgebraic, arc::check_lambda, arc::lambda_change_delta, arc::lambda_change_param,
    arc::lambda_of_sigma_cubed, arc::QuadArc, curve::circle_of, ratio, Field, RationalCurve,
    Scalar, Tolerance,
};
use num_rational::BigRational;
use proptest::prelude::*;

type Q = BigRational;
type A = RealAlgebraic;

/// A half-angle with rational cos and sin, θ ∈ (0, 4π/3): τ = tan(θ/4) < √3.
fn half_angle() -> impl Strategy<Value = (Q, Q)> {
    (1i64..=17, 1i64..=10)
        .prop_filter("θ < 4π/3", |(a, b)| a * a < 3 * b * b)
        .prop_map(|(a, b)| {
            let t = ratio::<Q>(a, b);
            let d = Q::from_i64(1) + &t * &t;
            ((Q::from_i64(1) - &t * &t) / &d, t * Q::from_i64(2) / d)
        })
}

/// A positive weight ratio σ.
fn sigma() -> impl Strategy<Value = Q> {
    (1i64..=12, 1i64..=12).prop_map(|(p, q)| ratio(p, q))
}

/// An arc with random distinct end points and rational half-angle.
fn arc() -> impl Strategy<Value = QuadArc<Q>> {
    (point(2), point(2), half_angle())
        .prop_filter("distinct ends", |(a, b, _)| a != b)
        .prop_map(|(a, b, (c, s))| QuadArc::from_ends(&a, &b, &c, &s, Tolerance::EXACT).unwrap())
}

/// λ of σ, if admissible.
fn lambda_of(arc: &QuadArc<Q>, sigma: &Q) -> Option<Q> {
    let l = lambda_of_sigma_cubed(arc.cos_half(), &sigma.pow_u32(3)).ok()?;
    check_lambda(arc.cos_half(), &l).ok().map(|_| l)
}

fn exact(arc: &QuadArc<Q>, l: &Q) -> RationalCurve<Q> {
    arc.cubic_for_lambda(l)
        .expect("a perfect-cube radicand gives a rational σ")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn cubic_is_exact_standard_and_circular(arc in arc(), s in sigma()) {
        let l = lambda_of(&arc, &s);
        prop_assume!(l.is_some());
        let l = l.unwrap();
        let cubic = exact(&arc, &l);
        let w = cubic.weights();
        prop_assert_eq!(&w[0], &Q::from_i64(1));
        prop_assert_eq!(&w[3], &Q::from_i64(1));
        prop_assert!(w.iter().all(|x| *x > Q::from_i64(0)));
        let circle = circle_of(&cubic, Tolerance::EXACT).unwrap();
        prop_assert_eq!(circle, circle_of(&arc.to_curve(), Tolerance::EXACT).unwrap());
    }

    #[test]
    fn shoulder_moves_towards_b0_as_lambda_grows(arc in arc(), a in sigma(), b in sigma()) {
        prop_assume!(a != b);
        let (s1, s2) = if a > b { (a, b) } else { (b, a) };
        let (l1, l2) = (lambda_of(&arc, &s1), lambda_of(&arc, &s2));
        prop_assume!(l1.is_some() && l2.is_some());
        let (l1, l2) = (l1.unwrap(), l2.unwrap());
        prop_assert!(l1 < l2); // σ³ = N/D decreases in λ
        let half = ratio::<Q>(1, 2);
        let p1 = exact(&arc, &l1).eval(&half).unwrap();
        let p2 = exact(&arc, &l2).eval(&half).unwrap();
        // The shoulder is the quadratic's point at s/(1−s) = σ, so μ = σ².
        let (m1, m2) = (arc.mu_of_point(&p1).unwrap(), arc.mu_of_point(&p2).unwrap());
        prop_assert_eq!(&m1, &(s1.clone() * &s1));
        prop_assert_eq!(&m2, &(s2.clone() * &s2));
        prop_assert!(m2 < m1);
        // Both inverse problems give back λ and 1/2.
        prop_assert_eq!(arc.lambda_for_point(&p1, &half).unwrap(), l1.clone());
        prop_assert_eq!(arc.param_of_point(&p2, &l2).unwrap(), half.clone());
        // Eq. (6): the point at ū on the λ₂ cubic is at u(ū) on the λ₁ cubic.
        let delta = lambda_change_delta(arc.cos_half(), &l1, &l2).unwrap();
        prop_assert_eq!(&delta, &(s1.clone() / &s2));
        let ub = ratio::<Q>(2, 7);
        let u = lambda_change_param(&delta, &ub).unwrap();
        prop_assert_eq!(exact(&arc, &l1).eval(&u).unwrap(), exact(&arc, &l2).eval(&ub).unwrap());
    }
}

fn q(p: i64, d: i64) -> Q {
    ratio(p, d)
}

#[test]
fn lambda_outside_interval_is_a_typed_error() {
    let p = |x: i64, y: i64| vec![q(x, 1), q(y, 1)];
    let arc = QuadArc::from_ends(&p(0, 0), &p(2, 0), &q(3, 5), &q(4, 5), Tolerance::EXACT).unwrap();
    // c = 3/5, k = 11/5: interval (−25/66, 5/11).
    assert!(arc.cubic_for_lambda(&q(5, 11)).is_err());
    assert!(arc.cubic_for_lambda(&q(-25, 66)).is_err());
    assert!(arc.cubic_for_lambda(&q(0, 1)).is_ok());
    let wide =
        QuadArc::from_ends(&p(0, 0), &p(2, 0), &q(-3, 5), &q(4, 5), Tolerance::EXACT).unwrap();
    assert!(
        wide.cubic_for_lambda(&q(0, 1)).is_err(),
        "θ > 4π/3 has no cubic family"
    );
}

/// σ³ = 4/5 is not a rational cube: over Q the cubic is refused as
/// `NotRational`; over the real algebraic numbers it is exact, with the hand
/// values of eq. (2) for the semicircle of radius 1: ω₁ = 1/(3σ²),
/// ω₂ = σ²/3 (σ² = ∛(16/25)), b₁* = (0, 8/5), b₂* = (2, 5/2) — the inner
/// control points rational although the weights are not.
#[test]
fn irrational_radicand_is_exact_over_the_algebraic_numbers() {
    let p = |x: i64, y: i64| vec![q(x, 1), q(y, 1)];
    let half = QuadArc::semicircle(&p(0, 0), &p(2, 0), &p(0, 1), Tolerance::EXACT).unwrap();
    assert!(matches!(
        half.cubic_for_lambda(&q(1, 5)),
        Err(exact_bezier::Error::NotRational(_))
    ));
    let alg = half.map(A::from_rational);
    let c = alg.cubic_for_lambda(&A::from_rational(&q(1, 5))).unwrap();
    let a = |s: &str| s.parse::<A>().unwrap();
    let sigma2 = a("cbrt(16/25)");
    assert_eq!(c.weights()[1], (A::from_i64(3) * &sigma2).recip());
    assert_eq!(c.weights()[2], sigma2 / &A::from_i64(3));
    let pts = c.points().unwrap();
    assert_eq!(pts[1], vec![a("0"), a("8/5")]);
    assert_eq!(pts[2], vec![a("2"), a("5/2")]);
}

/// The command line gives Table 1's first row exactly (b̄₁ = (1, √3) read as
/// algebraic text; source 004 prints ω₁ = 0.6614, ω₂ = 1.0499). By hand,
/// c = 1/2, λ = −3/10: k = 2, N = 8/5, D = 2/5, E = 1, σ³ = N/D = 4, so
/// ω₁ = kσ/(3N) = 5σ/12 and ω₂ = kE/(3Dσ) = 5/(3σ): ω₁³ = 125/432 and
/// ω₂³ = 125/108.
#[test]
fn cli_arc_is_exact_for_table_1() {
    let (code, out, err) = cli(&[
        "arc",
        "--cos-half",
        "1/2",
        "--lambda",
        "-0.3",
        "--points",
        "1,0;1,sqrt(3);-1/2,sqrt(3)/2",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["exact"], true);
    let w = |k: usize| v["weights"][k].as_str().unwrap().parse::<A>().unwrap();
    assert_eq!(w(1).pow_u32(3), A::from_rational(&q(125, 432)));
    assert_eq!(w(2).pow_u32(3), A::from_rational(&q(125, 108)));
}

#[test]
fn bad_arcs_are_rejected() {
    let p = |x: i64, y: i64| vec![q(x, 1), q(y, 1)];
    assert!(QuadArc::from_ends(&p(0, 0), &p(2, 0), &q(1, 2), &q(1, 2), Tolerance::EXACT).is_err());
    assert!(
        QuadArc::from_control(&p(0, 0), &p(1, 2), &p(2, 0), &q(1, 2), Tolerance::EXACT).is_err()
    );
    assert!(QuadArc::semicircle(&p(0, 0), &p(2, 0), &p(0, 2), Tolerance::EXACT).is_err());
}

#[test]
fn cli_arc_and_is_circle() {
    let (code, text, _) = cli(&[
        "arc",
        "--cos-half",
        "0",
        "--lambda",
        "-7",
        "--points",
        "0,0;2,0",
        "--direction",
        "0,1",
    ]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["exact"], true);
    // σ = 2: b₁* = b̄₀ + 2(1−λ)b = (0, 16), ω₁ = 1/12, ω₂ = 4/3 (eq. 2 by hand).
    assert_eq!(v["points"][1].to_string(), "[0,16]");
    assert_eq!(v["weights"].to_string(), r#"[1,"1/12","4/3",1]"#);
    let path = std::env::temp_dir().join(format!("arc-cli-{}.json", std::process::id()));
    std::fs::write(&path, &text).unwrap();
    let (code, text, _) = cli(&["is-circle", path.to_str().unwrap()]);
    std::fs::remove_file(&path).ok();
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["circle"], true);
    assert_eq!(v["center"].to_string(), "[1,0]");
    assert_eq!(v["radius_squared"].to_string(), "1");
    let (code, _, _) = cli(&[
        "arc",
        "--cos-half",
        "0",
        "--lambda",
        "1",
        "--points",
        "0,0;2,0",
        "--direction",
        "0,1",
    ]);
    assert_eq!(code, 2);
}
