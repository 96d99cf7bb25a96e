//! Source 004 (Hang & Li 2011), the numbers: Tables 1 and 2 and the worked
//! examples of §4, compared with ours at printed precision.
//!
//! Method. A printed decimal `v` with `d` digits is reproduced when our value
//! lies within half a unit of its last digit. Weights are decided exactly:
//! `ω₁³ = k³/(27N²D)` and `ω₂³ = k³E³/(27ND²)` are rational (family
//! `hang_li`, claim "ω₁³ = …"), so `v − h ≤ ω ≤ v + h ⇔ (v−h)³ ≤ ω³ ≤ (v+h)³`.
//! Shoulder points `P(1/2)` carry cube roots (and √3 in Table 1): they are
//! computed by the same generic construction in `f64` (error ≪ 10⁻¹²,
//! against a half unit of 5·10⁻⁵). The §4 quarter circle is checked exactly
//! with √2 as a symbol `r`, `r² = 2`.

use super::hang_li::omega_cubes;
use super::{Claim, Verdict};
use crate::algebra::poly::Poly;
use crate::algebra::scalar::{ratio, Ordered, Scalar, Tolerance};
use crate::arc::{sigma_of_lambda, QuadArc};
use crate::curve::circle::circle_of;
use crate::curve::RationalCurve;
use crate::hpoint::HPoint;
use crate::io::parse_rational;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

const SRC: &str = "004 Hang & Li";

/// The printed decimal and half a unit of its last digit.
fn printed(text: &str) -> (BigRational, BigRational) {
    let v = parse_rational(text).expect("printed decimals parse");
    let digits = text.split_once('.').map_or(0, |(_, f)| f.len()) as i64;
    let half = ratio::<BigRational>(1, 2) / BigRational::from_i64(10).pow_u32(digits as u32);
    (v, half)
}

/// Does the positive number with cube `cube` round to `text`?
fn cube_rounds_to(cube: &BigRational, text: &str) -> bool {
    let (v, h) = printed(text);
    let (lo, hi) = (v.clone() - &h, v + &h);
    lo.pow_u32(3) <= *cube && *cube <= hi.pow_u32(3)
}

/// Does `ours` round to `text`? Decided only with a margin of 10⁻⁹ to the
/// rounding boundary (far above the f64 error), else `false`.
fn f64_rounds_to(ours: f64, text: &str) -> bool {
    let (v, h) = printed(text);
    (ours - v.to_f64()).abs() <= h.to_f64() - 1e-9
}

/// The distance of `ours` to the nearer rounding boundary of `text`.
fn margin(ours: f64, text: &str) -> f64 {
    let (v, h) = printed(text);
    h.to_f64() - (ours - v.to_f64()).abs()
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
        &ratio(1, 2),
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
        &BigRational::zero(),
        &semicircle().map(Ordered::to_f64),
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
/// printed "ρ" is a 0), in `f64`.
fn table1_arc() -> QuadArc<f64> {
    QuadArc::from_control(
        &[0.0, 0.0],
        &[1.0, 3f64.sqrt()],
        &[2.0, 0.0],
        &0.5,
        Tolerance(1e-12),
    )
    .expect("the 2π/3 arc")
}

/// The semicircle b̄₀ = (0, 0), b̄₂ = (2, 0), b = (0, 1), exactly.
fn semicircle() -> QuadArc<BigRational> {
    let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    QuadArc::semicircle(&p(0, 0), &p(2, 0), &p(0, 1), Tolerance::EXACT).expect("semicircle")
}

/// Compare one table: weights exactly, shoulder points in f64.
fn table(name: &str, c: &BigRational, arc: &QuadArc<f64>, rows: &[Row]) -> Vec<Claim> {
    let mut out = Vec::new();
    for row in rows {
        let lambda = parse_rational(row.lambda).expect("printed λ");
        let (c1, c2) = omega_cubes(c, &lambda);
        let source = format!("{SRC} {name}");
        for (label, cube, text) in [("ω₁", &c1, row.w1), ("ω₂", &c2, row.w2)] {
            let ours = cube.to_f64().cbrt();
            out.push(Claim::compare(
                &format!("{name}, λ = {}: {label} = {text}", row.lambda),
                &source,
                Verdict::Reproduced,
                cube_rounds_to(cube, text),
                text,
                &format!("{ours:.7} ({label}³ = {cube} exactly)"),
            ));
        }
        let shoulder = sigma_of_lambda(&c.to_f64(), &lambda.to_f64())
            .and_then(|s| arc.standard_cubic(&s))
            .and_then(|cubic| cubic.eval(&0.5));
        let Ok(point) = shoulder else {
            continue;
        };
        for (label, ours, text) in [("x", point[0], row.x), ("y", point[1], row.y)] {
            out.push(Claim::compare(
                &format!(
                    "{name}, λ = {}: shoulder point {label} = {text}",
                    row.lambda
                ),
                &source,
                Verdict::Reproduced,
                f64_rounds_to(ours, text),
                text,
                &format!(
                    "{ours:.7} (P(1/2) of the f64 cubic; margin {:.1e} to the rounding boundary)",
                    margin(ours, text)
                ),
            ));
        }
    }
    out
}

/// `√2` as the symbol `r` with `r² = 2`.
fn root2(p: &Poly) -> Poly {
    p.reduce_power("r2", 2, &Poly::from_int(2))
}

/// The printed quarter-circle cubic: b̄₀, (b̄₀ + 4b̄₁)/5, (2b̄₂ + b̄₁)/3, b̄₂
/// with weights 1, 5/6, 1, 1.
fn printed_quarter() -> RationalCurve<BigRational> {
    let p = |x: i64, xd: i64, y: i64, yd: i64| vec![ratio::<BigRational>(x, xd), ratio(y, yd)];
    RationalCurve::new(
        vec![p(1, 1, 0, 1), p(1, 1, 4, 5), p(1, 3, 1, 1), p(0, 1, 1, 1)],
        vec![ratio(1, 1), ratio(5, 6), ratio(1, 1), ratio(1, 1)],
    )
    .expect("four points")
}

/// §4, first example: the 90° arc of the unit circle, shoulder (3/5, 4/5).
fn quarter_circle() -> Vec<Claim> {
    let src = format!("{SRC} §4 example 1");
    let (r, one, two) = (Poly::var("r2"), Poly::from_int(1), Poly::from_int(2));
    let c = r.clone() * Poly::constant(ratio(1, 2)); // cos 45° = √2/2
    let b = |x: i64, y: i64| vec![Poly::from_int(x), Poly::from_int(y)];
    let arc = QuadArc::new_raw([
        HPoint::from_cartesian(&b(1, 0)),
        HPoint::from_point(&b(1, 1), &c),
        HPoint::from_cartesian(&b(0, 1)),
    ]);
    // μ of (3/5, 4/5): the line b̄₁p does not depend on the middle weight, so
    // the same control points with weight 1 give it exactly.
    let q = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    let exact_ctrl = QuadArc::new_raw([
        HPoint::from_cartesian(&q(1, 0)),
        HPoint::from_cartesian(&q(1, 1)),
        HPoint::from_cartesian(&q(0, 1)),
    ]);
    let mu = exact_ctrl.mu_of_point(&[ratio(3, 5), ratio(4, 5)]);
    let mu_star = exact_ctrl.mu_of_point(&[ratio(1, 2), ratio(1, 2)]); // same line as (√2/2, √2/2)
                                                                       // Eq. (9): λ* = (1 − μ√μ)/((1+2c)(1 + 2μ√μc)) with μ√μ = 2√2; claimed (3√2 − 5)/5.
    let m = two.clone() * &r;
    let (num, den) = (
        one.clone() - &m,
        (one.clone() + two.clone() * &c) * &(one.clone() + two.clone() * &m * &c),
    );
    let lambda_ok =
        root2(&(num * Poly::from_int(5) - (Poly::from_int(3) * &r - Poly::from_int(5)) * den))
            .is_zero();
    // σ = √μ(1/ū − 1) = √2 at ū = 1/2; the cubic of the construction, normalized by σ² = 2.
    let cubic = arc.cubic_hom(&r, &one);
    let got: Vec<Vec<Poly>> = cubic
        .ctrl()
        .iter()
        .map(|h| {
            h.coords
                .iter()
                .map(|x| root2(&(x.clone() * Poly::constant(ratio(1, 2)))))
                .collect()
        })
        .collect();
    let want = printed_quarter();
    let same_cubic = got.iter().zip(want.ctrl()).all(|(g, w)| {
        g.iter()
            .zip(&w.coords)
            .all(|(a, b)| a.as_constant().as_ref() == Some(b))
    });
    let circle = circle_of(&want, Tolerance::EXACT);
    let shoulder = want.eval(&ratio(1, 2)).expect("finite");
    // Weights of the quadratic, eqs. (3), (4): ω̄₁/ω̄₀ = cσ, ω̄₁/ω̄₂ = c/σ = c·σ/2.
    let ratio_ok = root2(&(c.clone() * &r)) == one
        && root2(&(c.clone() * &r * Poly::constant(ratio(1, 2)))) == Poly::constant(ratio(1, 2));
    // Parameter of p* = (√2/2, √2/2) on the printed cubic.
    let sym = want.map(|x| Poly::constant(x.clone()));
    let on_curve = |u: &Poly| {
        let h = sym.eval_hom(u);
        let half = r.clone() * Poly::constant(ratio(1, 2));
        (0..2).all(|i| root2(&(h.coords[i].clone() - &(half.clone() * &h.coords[2]))).is_zero())
    };
    let ours_u = r.clone() - &one; // 1/(1 + √2)
    let printed_u = r.clone() * Poly::constant(ratio(1, 4)); // 1/(2√2)
    let at_printed = want
        .map(Ordered::to_f64)
        .eval(&(2f64.sqrt() / 4.0))
        .expect("finite");
    vec![
        Claim::compare(
            "§4 ex. 1: m = (1/3, 2/3), μ = |b̄₀m|/|mb̄₂| = 2 for p = (3/5, 4/5)",
            &src,
            Verdict::Reproduced,
            mu == Ok(ratio(2, 1)),
            "μ = 2",
            &format!("μ = {:?}", mu.map(|x| x.to_string())),
        ),
        Claim::compare(
            "§4 ex. 1: eq. (9) gives λ* = (3√2 − 5)/5",
            &src,
            Verdict::Reproduced,
            lambda_ok,
            "λ* = (3√2 − 5)/5",
            "(1 − 2√2)/((1+√2)(1+2·2√2·√2/2)) = (3√2 − 5)/5, exact with r² = 2",
        ),
        Claim::compare(
            "§4 ex. 1: the cubic is b̄₀, (b̄₀+4b̄₁)/5, (2b̄₂+b̄₁)/3, b̄₂ with ω = 1, 5/6, 1, 1",
            &src,
            Verdict::Reproduced,
            same_cubic,
            "(1,0), (1,4/5), (1/3,1), (0,1); 1, 5/6, 1, 1",
            &format!("the construction with c = √2/2, σ = √2 reduced mod r² = 2: {:?}", got.iter().map(|h| h.iter().map(|x| x.to_string()).collect::<Vec<_>>()).collect::<Vec<_>>()),
        ),
        Claim::compare(
            "§4 ex. 1: the printed cubic lies on the unit circle and P(1/2) = (3/5, 4/5)",
            &src,
            Verdict::Reproduced,
            circle.as_ref().is_ok_and(|c| c.center == q(0, 0) && c.radius_squared == ratio(1, 1))
                && shoulder == vec![ratio(3, 5), ratio(4, 5)],
            "unit circle, shoulder (3/5, 4/5)",
            &format!("circle test: {circle:?}; P(1/2) = ({}, {})", shoulder[0], shoulder[1]),
        ),
        Claim::compare(
            "§4 ex. 1: eqs. (3), (4) give ω̄₁/ω̄₀ = 1, ω̄₁/ω̄₂ = 1/2",
            &src,
            Verdict::Reproduced,
            ratio_ok,
            "1 and 1/2",
            "cσ = (√2/2)·√2 = 1, c/σ = 1/2 (r² = 2)",
        ),
        Claim::compare(
            "§4 ex. 1: μ = 1 for p* = (√2/2, √2/2)",
            &src,
            Verdict::Reproduced,
            mu_star == Ok(ratio(1, 1)),
            "μ = 1",
            &format!("μ = {:?} (p* lies on the line through b̄₁ and (1/2, 1/2))", mu_star.map(|x| x.to_string())),
        ),
        Claim::compare(
            "§4 ex. 1: the parameter of p* = (√2/2, √2/2) is ū = 1/(2√2)",
            &src,
            Verdict::Mismatch,
            on_curve(&printed_u),
            "ū = 1/(2√2) ≈ 0.353553",
            &format!(
                "ū = √2 − 1 = 1/(1+√2) ≈ {:.6} (P(√2 − 1) = p* exactly with r² = 2: {}); at 1/(2√2) the cubic is at ({:.6}, {:.6}); the printed value is the radicand μ√μ·D/N = 1/(2√2) of eq. (10) without the cube root and X/(X+1)",
                2f64.sqrt() - 1.0,
                on_curve(&ours_u),
                at_printed[0],
                at_printed[1]
            ),
        ),
    ]
}

/// §4, second example: the semicircle, ū = 0.5185900 and p* = (0.8817, 0.9930).
fn semicircle_example() -> Vec<Claim> {
    let src = format!("{SRC} §4 example 2");
    let arc = semicircle();
    let p = vec![ratio::<BigRational>(1, 1), ratio(1, 1)];
    let u_printed = parse_rational("0.5185900").expect("decimal");
    let mu = arc.mu_of_point(&p);
    let lambda = arc.lambda_for_point(&p, &u_printed);
    let lambda_f = lambda.as_ref().map(Ordered::to_f64).unwrap_or(f64::NAN);
    let fp = arc.map(Ordered::to_f64);
    let u_exact = fp.param_of_point(&[1.0, 1.0], &0.2).unwrap_or(f64::NAN);
    // Control points at λ = 0.2, exactly: x(C₁) = w(C₁)·(0, 1.6), x(C₂) = w(C₂)·(2, 2.5) mod r³ = 0.8.
    let sym = arc.map(|x| Poly::constant(x.clone()));
    let cubic = sym.cubic_hom(&Poly::var("r"), &Poly::from_int(1));
    let rel = Poly::constant(ratio(4, 5));
    let lies = |i: usize, x: BigRational, y: BigRational| {
        let h = &cubic.ctrl()[i];
        [x, y].iter().enumerate().all(|(k, v)| {
            (h.coords[k].clone() - &(h.weight().clone() * Poly::constant(v.clone())))
                .reduce_power("r", 3, &rel)
                .is_zero()
        })
    };
    let ctrl_ok = lies(1, ratio(0, 1), ratio(8, 5)) && lies(2, ratio(2, 1), ratio(5, 2));
    let pstar = vec![
        parse_rational("0.8817").expect("x"),
        parse_rational("0.9930").expect("y"),
    ];
    let mu_star = arc.mu_of_point(&pstar);
    let mu_star_f = mu_star.as_ref().map(Ordered::to_f64).unwrap_or(f64::NAN);
    let u_star = fp
        .param_of_point(&[0.8817, 0.9930], &0.2)
        .unwrap_or(f64::NAN);
    // The exact shoulder A of λ = 0.3 (which p* rounds): ū/(1−ū) = σ(0.3)/σ(0.2).
    let ratio_sigma = (0.7f64 / 0.8).cbrt();
    let u_of_a = ratio_sigma / (1.0 + ratio_sigma);
    vec![
        Claim::compare(
            "§4 ex. 2: μ = 1 for p = (1, 1)",
            &src,
            Verdict::Reproduced,
            mu == Ok(ratio(1, 1)),
            "μ = 1",
            &format!("{:?}", mu.map(|x| x.to_string())),
        ),
        Claim::compare(
            "§4 ex. 2: eq. (8) with ū = 0.5185900 gives λ* = 0.2",
            &src,
            Verdict::Reproduced,
            lambda.is_ok() && (lambda_f - 0.2).abs() <= 0.05,
            "λ* = 0.2",
            &format!("λ* = 1 − (1/ū − 1)³ = {lambda_f:.7} exactly from the printed ū"),
        ),
        Claim::compare(
            "§4 ex. 2: ū = 0.5185900 is the parameter of p = (1, 1) for λ* = 0.2",
            &src,
            Verdict::Mismatch,
            f64_rounds_to(u_exact, "0.5185900"),
            "0.5185900",
            &format!("ū = 1/(1 + ∛0.8) = {u_exact:.7} (eq. 11); the printed ū carries 5 correct decimals"),
        ),
        Claim::compare(
            "§4 ex. 2: b₁* = b̄₀ + 1.6b, b₂* = b̄₂ + 2.5b at λ* = 0.2",
            &src,
            Verdict::Reproduced,
            ctrl_ok,
            "b̄₀ + 1.6b, b̄₂ + 2.5b",
            "x(Cᵢ) = w(Cᵢ)·bᵢ* exactly, mod r³ = 4/5",
        ),
        Claim::compare(
            "§4 ex. 2: ω₁ = 0.3868, ω₂ = 0.2873 at λ* = 0.2",
            &src,
            Verdict::Reproduced,
            {
                let (a, b) = omega_cubes(&BigRational::zero(), &ratio(1, 5));
                cube_rounds_to(&a, "0.3868") && cube_rounds_to(&b, "0.2873")
            },
            "0.3868, 0.2873",
            "ω₁³ = 1/(27·0.8²), ω₂³ = 0.8²/27, rounded exactly",
        ),
        Claim::compare(
            "§4 ex. 2: μ = 0.8817/(2 − 0.8817) = 0.7884288 for p* = (0.8817, 0.9930)",
            &src,
            Verdict::Mismatch,
            mu_star.as_ref().is_ok_and(|m| {
                let (v, h) = printed("0.7884288");
                (m.clone() - v).abs() <= h
            }),
            "0.7884288",
            &format!("μ = 8817/11183 = {mu_star_f:.9}, which rounds to 0.7884289 (the printed digits are truncated)"),
        ),
        Claim::compare(
            "§4 ex. 2: the parameter of p* = (0.8817, 0.9930) for λ* = 0.2 is ū = 0.488829",
            &src,
            Verdict::Mismatch,
            f64_rounds_to(u_star, "0.488829"),
            "0.488829",
            &format!("eq. (11) with μ = 8817/11183: ū = {u_star:.6} (the printed 0.488829 looks like a digit slip of 0.488883); for the exact shoulder A of λ = 0.3, which p* rounds, ū = {u_of_a:.6}"),
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_decisions() {
        assert!(cube_rounds_to(&ratio(8, 1), "2.000"));
        assert!(!cube_rounds_to(&ratio(8, 1), "2.001"));
        assert!(f64_rounds_to(0.577351, "0.5774"));
        assert!(!f64_rounds_to(0.57725, "0.5774"));
    }
}
