//! Source 004 (Hang & Li 2011), the numbers: Tables 1 and 2 and the worked
//! examples of §4, compared with ours at printed precision, exactly.
//!
//! Method. Every table entry and every §4 number is computed by the generic
//! library code — [`sigma_of_lambda`], [`QuadArc::standard_cubic`],
//! [`RationalCurve::eval`], [`QuadArc::mu_of_point`],
//! [`QuadArc::lambda_for_point`], [`QuadArc::param_of_point`],
//! [`circle_of`] — instantiated on the exact real algebraic numbers
//! [`RealAlgebraic`]: `σ = ∛(N/D)` is a cube root, Table 1's arc carries
//! `b̄₁ = (1, √3)` and §4 example 1 `c = √2/2`, so the weights are elements
//! of `Q(∛(N/D))` and the shoulder points `P(1/2)` of `Q(√3, ∛(N/D))`.
//! A printed decimal `v` with `d` digits is reproduced iff
//!
//! ```text
//! v − h ≤ x ≤ v + h,   h = 10^{−d}/2
//! ```
//!
//! decided by the exact comparison of [`RealAlgebraic`] (enclosures refined
//! until they separate from the rational bounds `v ± h`): no `f64` and no
//! tolerance anywhere on that path. Each `detail` shows our exact value
//! (the SymPy-compatible text of [`RealAlgebraic`]), its correctly rounded
//! decimal expansion ([`RealAlgebraic::to_decimal`], three digits beyond the
//! printed ones) and the printed value.

use super::printed::{decimal, rounds_to, shown};
use super::{Claim, Verdict};
use exact_bezier::algebra::parse_rational;
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::algebra::{ratio, Field, Roots, Scalar, Tolerance};
use exact_bezier::arc::{sigma_of_lambda, QuadArc};
use exact_bezier::curve::circle::circle_of;
use exact_bezier::curve::RationalCurve;
use exact_bezier::Error;

const SRC: &str = "004 Hang & Li";

/// The exact scalar of this family.
type R = RealAlgebraic;

/// The integer `n`.
fn int(n: i64) -> R {
    R::from_i64(n)
}

/// The printed decimal (or fraction) `text`, exactly.
fn exact(text: &str) -> R {
    R::from_rational(&parse_rational(text).expect("printed numbers parse"))
}

/// The planar point `(x, y)`.
fn pt(x: R, y: R) -> Vec<R> {
    vec![x, y]
}

/// The standard cubic of λ for `arc` (source 004 eq. 1, eq. 2 for θ = π).
fn cubic_of(arc: &QuadArc<R>, lambda: &R) -> Result<RationalCurve<R>, Error> {
    sigma_of_lambda(arc.cos_half(), lambda).and_then(|s| arc.standard_cubic(&s))
}

/// One printed table row: λ, ω₁, ω₂, shoulder x, y.
struct Row {
    lambda: &'static str,
    w1: &'static str,
    w2: &'static str,
    x: &'static str,
    y: &'static str,
}

/// All claims of the family.
pub fn claims() -> Vec<Claim> {
    let mut out = table(
        "Table 1 (θ = 2π/3)",
        &table1_arc(),
        &[
            Row {
                lambda: "-0.3",
                w1: "0.6614",
                w2: "1.0499",
                x: "1.2976",
                y: "0.5383",
            },
            Row {
                lambda: "-0.25",
                w1: "0.6410",
                w2: "0.9245",
                x: "1.2388",
                y: "0.5524",
            },
            Row {
                lambda: "0",
                w1: "0.6667",
                w2: "0.6667",
                x: "1.0",
                y: "0.5774",
            },
            Row {
                lambda: "0.2",
                w1: "0.8377",
                w2: "0.6316",
                x: "0.8142",
                y: "0.5623",
            },
            Row {
                lambda: "0.4",
                w1: "1.6025",
                w2: "0.7704",
                x: "0.5509",
                y: "0.4864",
            },
        ],
    );
    out.extend(table(
        "Table 2 (θ = π)",
        &semicircle(),
        &[
            Row {
                lambda: "-0.45",
                w1: "0.2602",
                w2: "0.4270",
                x: "1.1232",
                y: "0.9924",
            },
            Row {
                lambda: "-0.25",
                w1: "0.2873",
                w2: "0.3868",
                x: "1.0742",
                y: "0.9972",
            },
            Row {
                lambda: "0",
                w1: "0.3333",
                w2: "0.3333",
                x: "1",
                y: "1",
            },
            Row {
                lambda: "0.2",
                w1: "0.3868",
                w2: "0.2873",
                x: "0.9258",
                y: "0.9972",
            },
            Row {
                lambda: "0.3",
                w1: "0.4228",
                w2: "0.2628",
                x: "0.8817",
                y: "0.9930",
            },
        ],
    ));
    out.extend(quarter_circle());
    out.extend(semicircle_example());
    out
}

/// Table 1's arc: b̄₀ = (0, 0), b̄₁ = (1, √3), b̄₂ = (2, 0), c = 1/2 (the
/// printed "ρ" is a 0), exactly.
fn table1_arc() -> QuadArc<R> {
    let root3 = int(3).nth_root(2).expect("√3");
    QuadArc::from_control(
        &pt(int(0), int(0)),
        &pt(int(1), root3),
        &pt(int(2), int(0)),
        &ratio(1, 2),
        Tolerance::EXACT,
    )
    .expect("the 2π/3 arc")
}

/// The semicircle b̄₀ = (0, 0), b̄₂ = (2, 0), b = (0, 1), exactly.
fn semicircle() -> QuadArc<R> {
    QuadArc::semicircle(
        &pt(int(0), int(0)),
        &pt(int(2), int(0)),
        &pt(int(0), int(1)),
        Tolerance::EXACT,
    )
    .expect("semicircle")
}

/// Compare one table: the weights ω₁, ω₂ and the shoulder point `P(1/2)` of
/// the standard cubic of each λ, exactly.
fn table(name: &str, arc: &QuadArc<R>, rows: &[Row]) -> Vec<Claim> {
    let source = format!("{SRC} {name}");
    let mut out = Vec::new();
    for row in rows {
        let entries = cubic_of(arc, &exact(row.lambda)).and_then(|cubic| {
            let w = cubic.weights();
            let p = cubic.eval(&ratio(1, 2))?;
            Ok([w[1].clone(), w[2].clone(), p[0].clone(), p[1].clone()])
        });
        let items = [
            ("ω₁", row.w1),
            ("ω₂", row.w2),
            ("shoulder point x", row.x),
            ("shoulder point y", row.y),
        ];
        for (i, (label, text)) in items.into_iter().enumerate() {
            let claim = format!("{name}, λ = {}: {label} = {text}", row.lambda);
            let ours = entries.as_ref().map(|v| v[i].clone()).map_err(Clone::clone);
            out.push(decimal(
                &claim,
                &source,
                Verdict::Reproduced,
                &ours,
                text,
                |x| {
                    if i < 2 {
                        format!(" ({label}³ = {})", x.pow_u32(3))
                    } else {
                        " (P(1/2) of the standard cubic)".to_string()
                    }
                },
            ));
        }
    }
    out
}

/// The printed quarter-circle cubic: b̄₀, (b̄₀ + 4b̄₁)/5, (2b̄₂ + b̄₁)/3, b̄₂
/// with weights 1, 5/6, 1, 1.
fn printed_quarter() -> RationalCurve<R> {
    let p = |x: i64, xd: i64, y: i64, yd: i64| pt(ratio(x, xd), ratio(y, yd));
    RationalCurve::new(
        vec![p(1, 1, 0, 1), p(1, 1, 4, 5), p(1, 3, 1, 1), p(0, 1, 1, 1)],
        vec![int(1), ratio(5, 6), int(1), int(1)],
    )
    .expect("four points")
}

/// A cubic's Cartesian control points and weights, as text.
fn cubic_text(cubic: &RationalCurve<R>) -> String {
    let points = cubic.points().map_or_else(
        |e| e.to_string(),
        |ps| {
            ps.iter()
                .map(|p| format!("({}, {})", p[0], p[1]))
                .collect::<Vec<_>>()
                .join(", ")
        },
    );
    let weights: Vec<String> = cubic.weights().iter().map(R::to_string).collect();
    format!("{points}; {}", weights.join(", "))
}

/// A point as exact text and decimals to `places` digits.
fn point_text(p: &[R], places: usize) -> String {
    let coords: Vec<String> = p.iter().map(R::to_string).collect();
    let decimals: Vec<String> = p.iter().map(|x| x.to_decimal(places)).collect();
    format!("({}) ≈ ({})", coords.join(", "), decimals.join(", "))
}

/// A result as text.
fn result_text(r: &Result<R, Error>) -> String {
    r.as_ref().map_or_else(|e| e.to_string(), R::to_string)
}

/// §4, first example: the 90° arc of the unit circle, shoulder (3/5, 4/5).
fn quarter_circle() -> Vec<Claim> {
    let src = format!("{SRC} §4 example 1");
    let root2 = int(2).nth_root(2).expect("√2");
    let c = root2.clone() * &ratio(1, 2); // cos 45° = √2/2
    let arc = QuadArc::from_control(
        &pt(int(1), int(0)),
        &pt(int(1), int(1)),
        &pt(int(0), int(1)),
        &c,
        Tolerance::EXACT,
    )
    .expect("the 90° arc");
    let half = ratio::<R>(1, 2);
    let p = pt(ratio(3, 5), ratio(4, 5));
    let mu = arc.mu_of_point(&p);
    // Eq. (9): λ* at ū = 1/2; σ = √μ(1/ū − 1) = √2.
    let lambda = arc.lambda_for_point(&p, &half);
    let lambda_printed = (int(3) * &root2 - &int(5)) / &int(5);
    let cubic = lambda.clone().and_then(|l| cubic_of(&arc, &l));
    let want = printed_quarter();
    let circle = circle_of(&want, Tolerance::EXACT);
    let shoulder = want.eval(&half);
    // Weights of the non-standard quadratic, eqs. (3), (4): 1, cσ, σ².
    let quad_w = arc
        .sigma_for_point(&p, &half)
        .map(|s| arc.nonstandard_quadratic(&s, &int(1)).weights());
    let ratios = quad_w
        .as_ref()
        .map(|w| (w[1].clone() / &w[0], w[1].clone() / &w[2]));
    // p* = (√2/2, √2/2) and its parameter on the cubic of λ*.
    let p_star = pt(c.clone(), c.clone());
    let mu_star = arc.mu_of_point(&p_star);
    let u_star = lambda.clone().and_then(|l| arc.param_of_point(&p_star, &l));
    let u_printed = (int(2) * &root2).recip(); // 1/(2√2)
    let at = |u: &R| cubic.as_ref().map_err(Clone::clone).and_then(|k| k.eval(u));
    let at_ours = u_star.as_ref().map_err(Clone::clone).and_then(at);
    let at_printed = at(&u_printed);
    vec![
        Claim::compare(
            "§4 ex. 1: m = (1/3, 2/3), μ = |b̄₀m|/|mb̄₂| = 2 for p = (3/5, 4/5)",
            &src,
            Verdict::Reproduced,
            mu.as_ref().is_ok_and(|m| *m == int(2)),
            "μ = 2",
            &format!("μ = {}", result_text(&mu)),
        ),
        Claim::compare(
            "§4 ex. 1: eq. (9) gives λ* = (3√2 − 5)/5",
            &src,
            Verdict::Reproduced,
            lambda.as_ref().is_ok_and(|l| *l == lambda_printed),
            "λ* = (3√2 − 5)/5",
            &format!(
                "λ* = (1 − M)/((1 + 2c)(1 + 2cM)), M = μ√μ = 2√2, c = √2/2: {}",
                lambda.as_ref().map_or_else(|e| e.to_string(), |l| shown(l, "0.000000"))
            ),
        ),
        Claim::compare(
            "§4 ex. 1: the cubic is b̄₀, (b̄₀+4b̄₁)/5, (2b̄₂+b̄₁)/3, b̄₂ with ω = 1, 5/6, 1, 1",
            &src,
            Verdict::Reproduced,
            cubic.as_ref().is_ok_and(|k| *k == want),
            "(1,0), (1,4/5), (1/3,1), (0,1); 1, 5/6, 1, 1",
            &format!(
                "the standard cubic of λ* (σ = ∛(N/D) = √2): {}",
                cubic.as_ref().map_or_else(|e| e.to_string(), cubic_text)
            ),
        ),
        Claim::compare(
            "§4 ex. 1: the printed cubic lies on the unit circle and P(1/2) = (3/5, 4/5)",
            &src,
            Verdict::Reproduced,
            circle.as_ref().is_ok_and(|k| k.center == pt(int(0), int(0)) && k.radius_squared == int(1))
                && shoulder.as_ref().is_ok_and(|s| *s == pt(ratio(3, 5), ratio(4, 5))),
            "unit circle, shoulder (3/5, 4/5)",
            &format!(
                "circle test: {}; P(1/2) = {}",
                circle.as_ref().map_or_else(
                    |e| format!("{e:?}"),
                    |k| format!("centre ({}, {}), R² = {}", k.center[0], k.center[1], k.radius_squared)
                ),
                shoulder.as_ref().map_or_else(|e| e.to_string(), |s| point_text(s, 6))
            ),
        ),
        Claim::compare(
            "§4 ex. 1: eqs. (3), (4) give ω̄₁/ω̄₀ = 1, ω̄₁/ω̄₂ = 1/2",
            &src,
            Verdict::Reproduced,
            ratios.as_ref().is_ok_and(|(a, b)| *a == int(1) && *b == ratio(1, 2)),
            "1 and 1/2",
            &ratios.as_ref().map_or_else(
                |e| e.to_string(),
                |(a, b)| format!("the non-standard quadratic with σ = √2 has weights 1, cσ, σ²: ω̄₁/ω̄₀ = cσ = {a}, ω̄₁/ω̄₂ = c/σ = {b}"),
            ),
        ),
        Claim::compare(
            "§4 ex. 1: μ = 1 for p* = (√2/2, √2/2)",
            &src,
            Verdict::Reproduced,
            mu_star.as_ref().is_ok_and(|m| *m == int(1)),
            "μ = 1",
            &format!("μ = {}", result_text(&mu_star)),
        ),
        Claim::compare(
            "§4 ex. 1: the parameter of p* = (√2/2, √2/2) is ū = 1/(2√2)",
            &src,
            Verdict::Mismatch,
            u_star.as_ref().is_ok_and(|u| *u == u_printed),
            &format!("ū = 1/(2√2) = {}", shown(&u_printed, "0.000")),
            &format!(
                "ū = {} by eq. (10) (P(ū) = p* exactly: {}); at 1/(2√2) the cubic is at {}; the printed value is the radicand μ√μ·D/N = 1/(2√2) of eq. (10) without the cube root and X/(X+1)",
                u_star.as_ref().map_or_else(|e| e.to_string(), |u| shown(u, "0.000")),
                at_ours.as_ref().is_ok_and(|q| *q == p_star),
                at_printed.as_ref().map_or_else(|e| e.to_string(), |q| point_text(q, 6)),
            ),
        ),
    ]
}

/// §4, second example: the semicircle, ū = 0.5185900 and p* = (0.8817, 0.9930).
fn semicircle_example() -> Vec<Claim> {
    let src = format!("{SRC} §4 example 2");
    let arc = semicircle();
    let p = pt(int(1), int(1));
    let fifth = ratio::<R>(1, 5);
    let mu = arc.mu_of_point(&p);
    let lambda = arc.lambda_for_point(&p, &exact("0.5185900"));
    let u_exact = arc.param_of_point(&p, &fifth);
    let cubic = cubic_of(&arc, &fifth);
    let points = cubic
        .as_ref()
        .map_err(Clone::clone)
        .and_then(RationalCurve::points);
    let weights = cubic.as_ref().map(RationalCurve::weights);
    let p_star = pt(exact("0.8817"), exact("0.9930"));
    let mu_star = arc.mu_of_point(&p_star);
    let u_star = arc.param_of_point(&p_star, &fifth);
    // The exact shoulder A of λ = 0.3 (which p* rounds, Table 2) and its
    // parameter on the cubic of λ = 0.2.
    let u_of_a = cubic_of(&arc, &exact("0.3"))
        .and_then(|k| k.eval(&ratio(1, 2)))
        .and_then(|a| arc.param_of_point(&a, &fifth));
    vec![
        Claim::compare(
            "§4 ex. 2: μ = 1 for p = (1, 1)",
            &src,
            Verdict::Reproduced,
            mu.as_ref().is_ok_and(|m| *m == int(1)),
            "μ = 1",
            &format!("μ = {}", result_text(&mu)),
        ),
        decimal(
            "§4 ex. 2: eq. (8) with ū = 0.5185900 gives λ* = 0.2",
            &src,
            Verdict::Reproduced,
            &lambda,
            "0.2",
            |_| " (λ* = 1 − (1/ū − 1)³ from the printed ū)".to_string(),
        ),
        decimal(
            "§4 ex. 2: ū = 0.5185900 is the parameter of p = (1, 1) for λ* = 0.2",
            &src,
            Verdict::Mismatch,
            &u_exact,
            "0.5185900",
            |u| {
                format!(
                    " (eq. 11: 1/(1 + ∛0.8)); the printed ū rounds correctly to 5 decimals, 0.51859: {}",
                    rounds_to(u, "0.51859")
                )
            },
        ),
        Claim::compare(
            "§4 ex. 2: b₁* = b̄₀ + 1.6b, b₂* = b̄₂ + 2.5b at λ* = 0.2",
            &src,
            Verdict::Reproduced,
            points.as_ref().is_ok_and(|ps| {
                ps[1] == pt(int(0), exact("1.6")) && ps[2] == pt(int(2), exact("2.5"))
            }),
            "b̄₀ + 1.6b, b̄₂ + 2.5b",
            &format!(
                "the standard cubic of λ = 1/5 (σ = ∛(4/5)): {}",
                cubic.as_ref().map_or_else(|e| e.to_string(), cubic_text)
            ),
        ),
        Claim::compare(
            "§4 ex. 2: ω₁ = 0.3868, ω₂ = 0.2873 at λ* = 0.2",
            &src,
            Verdict::Reproduced,
            weights
                .as_ref()
                .is_ok_and(|w| rounds_to(&w[1], "0.3868") && rounds_to(&w[2], "0.2873")),
            "0.3868, 0.2873",
            &weights.as_ref().map_or_else(
                |e| e.to_string(),
                |w| {
                    format!(
                        "ω₁ = {}, ω₂ = {}",
                        shown(&w[1], "0.3868"),
                        shown(&w[2], "0.2873")
                    )
                },
            ),
        ),
        decimal(
            "§4 ex. 2: μ = 0.8817/(2 − 0.8817) = 0.7884288 for p* = (0.8817, 0.9930)",
            &src,
            Verdict::Mismatch,
            &mu_star,
            "0.7884288",
            |m| {
                format!(
                    ", which rounds to {} (the printed digits are truncated)",
                    m.to_decimal(7)
                )
            },
        ),
        decimal(
            "§4 ex. 2: the parameter of p* = (0.8817, 0.9930) for λ* = 0.2 is ū = 0.488829",
            &src,
            Verdict::Mismatch,
            &u_star,
            "0.488829",
            |u| {
                format!(
                    " (eq. 11 with μ = 8817/11183; the printed 0.488829 looks like a digit slip of {}); for the exact shoulder A of λ = 0.3, which p* rounds, ū = {}",
                    u.to_decimal(6),
                    u_of_a.as_ref().map_or_else(|e| e.to_string(), |v| shown(v, "0.488829")),
                )
            },
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_is_decided_exactly() {
        let root3 = int(3).nth_root(2).unwrap();
        let y = root3.recip(); // √3/3 = 0.57735…
        assert!(rounds_to(&y, "0.5774"));
        assert!(rounds_to(&y, "0.57735"));
        assert!(!rounds_to(&y, "0.5773"));
        assert!(!rounds_to(&y, "0.577351")); // 0.5773502…
                                             // The rounding boundaries belong to the printed value.
        assert!(rounds_to(&ratio(57735, 100_000), "0.5774"));
        assert!(rounds_to(&ratio(57745, 100_000), "0.5774"));
        assert!(!rounds_to(&ratio(577_451, 1_000_000), "0.5774"));
        // ∛2 = 1.25992104989…: right at 7 digits, wrong when truncated.
        let cbrt2 = int(2).nth_root(3).unwrap();
        assert!(rounds_to(&cbrt2, "1.2599210"));
        assert!(!rounds_to(&cbrt2, "1.2599211"));
        assert!(rounds_to(&int(1), "1"));
        assert!(rounds_to(&int(1), "1.0"));
    }

    #[test]
    fn detail_shows_exact_and_decimal_values() {
        let y = int(3).nth_root(2).unwrap().recip();
        assert_eq!(shown(&y, "0.5774"), "sqrt(3)/3 ≈ 0.5773503");
        let claim = decimal("c", "s", Verdict::Mismatch, &Ok(y), "0.5773", |_| {
            String::new()
        });
        assert_eq!(claim.verdict, Verdict::Mismatch);
        assert_eq!(claim.detail, "printed 0.5773; ours sqrt(3)/3 ≈ 0.5773503");
        let failed = decimal(
            "c",
            "s",
            Verdict::Reproduced,
            &Err(Error::Domain("no".into())),
            "1",
            |_| String::new(),
        );
        assert_eq!(failed.verdict, Verdict::Broken);
    }
}
