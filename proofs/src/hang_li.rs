//! Source 004 (Hang & Li 2011), the formulas: eqs. (1)–(11) and the
//! properties 2)–6) of §1, proved for all θ and λ with the symbolic scalar.
//!
//! Symbols: `c = cos(θ/2)`, `s = sin(θ/2)` with `s² = 1 − c²`; `λ`; the cube
//! root `r` with `r³ = N·D²`, so that `σ = ∛(N/D) = r/D`,
//! `1/σ = ∛(D/N) = r²/(N·D)` (N, D, E as in [`LambdaFactors`]); `t`/`u` the
//! curve parameter; free control points `(x_i, y_i)` where a claim holds for
//! any points. Every identity is reduced modulo `r³ = N·D²` and `s² = 1 − c²`
//! after clearing denominators, so it holds for every admissible θ and λ.
//! Degree bound: the cubic family only (degree 3, identities of degree ≤ 6
//! in t).

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::algebra::{ratio, Scalar};
use exact_bezier::arc::{check_lambda, LambdaFactors, QuadArc};
use exact_bezier::curve::RationalCurve;
use exact_bezier::hpoint::HPoint;
use num_rational::BigRational;
use num_traits::Zero;

const SRC: &str = "004 Hang & Li";

fn v(name: &str) -> Poly {
    Poly::var(name)
}

fn int(n: i64) -> Poly {
    Poly::from_int(n)
}

fn q(p: i64, d: i64) -> Poly {
    ratio(p, d)
}

/// `k = 1 + 2c`.
fn k(c: &Poly) -> Poly {
    int(1) + int(2) * c
}

/// The factors N, D, E at the symbol `lambda`.
fn factors(c: &Poly, lambda: &Poly) -> LambdaFactors<Poly> {
    LambdaFactors::new(c, lambda)
}

/// Reduce modulo `r³ = N·D²` (for the symbol λ) and `s² = 1 − c²`.
fn reduce(p: &Poly) -> Poly {
    let (c, f) = (v("c"), factors(&v("c"), &v("lambda")));
    let cube = f.n * &f.d * &f.d;
    p.reduce_power("r", 3, &cube)
        .reduce_power("s", 2, &(int(1) - c.clone() * &c))
}

/// ∂p/∂name.
fn deriv(p: &Poly, name: &str) -> Poly {
    (1..=p.degree_in(name)).fold(Poly::zero(), |acc, e| {
        acc + p.coeff_of(name, e) * int(e as i64) * v(name).pow(e - 1)
    })
}

/// A claim that every polynomial in `polys` is zero (after `reduce`).
fn all_zero(claim: &str, source: &str, expected: Verdict, polys: &[Poly], how: &str) -> Claim {
    let bad = polys.iter().map(reduce).find(|p| !p.is_zero());
    let detail = match &bad {
        None => how.to_string(),
        Some(p) => format!(
            "{how}; non-zero remainder {}",
            super::abbreviate(&p.to_string())
        ),
    };
    Claim::check(claim, source, expected, bad.is_none(), detail)
}

/// The arc with free control points `(x_i, y_i)` and middle weight `c`.
fn free_arc(c: &Poly) -> QuadArc<Poly> {
    let pt = |i: usize| vec![v(&format!("x{i}")), v(&format!("y{i}"))];
    QuadArc::new_raw([
        HPoint::from_cartesian(&pt(0)),
        HPoint::from_point(&pt(1), c),
        HPoint::from_cartesian(&pt(2)),
    ])
}

/// The unit-circle arc `(c, −s) → (c, s)` through `(1, 0)`: `A₁ = (1, 0, c)`.
fn unit_arc() -> QuadArc<Poly> {
    let (c, s) = (v("c"), v("s"));
    QuadArc::new_raw([
        HPoint {
            coords: vec![c.clone(), -s.clone(), int(1)],
        },
        HPoint {
            coords: vec![int(1), int(0), c],
        },
        HPoint {
            coords: vec![v("c"), s, int(1)],
        },
    ])
}

/// The semicircle with free end points and free direction `b = (bx, by)`.
fn free_semicircle() -> QuadArc<Poly> {
    QuadArc::new_raw([
        HPoint::from_cartesian(&[v("x0"), v("y0")]),
        HPoint {
            coords: vec![v("bx"), v("by"), int(0)],
        },
        HPoint::from_cartesian(&[v("x2"), v("y2")]),
    ])
}

/// The 2×2 minors of two homogeneous points: all zero iff proportional.
fn minors(p: &HPoint<Poly>, q: &HPoint<Poly>) -> Vec<Poly> {
    let n = p.coords.len();
    let mut out = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            out.push(p.coords[i].clone() * &q.coords[j] - &(p.coords[j].clone() * &q.coords[i]));
        }
    }
    out
}

/// The symbolic λ-cubic with its common factor `r²D²`: `cubic_hom(r, D)`.
fn lambda_cubic(arc: &QuadArc<Poly>) -> RationalCurve<Poly> {
    let f = factors(&v("c"), &v("lambda"));
    arc.cubic_hom(&v("r"), &f.d)
}

/// Every claim of the family.
pub fn claims() -> Vec<Claim> {
    let mut out = vec![
        eq1_first_inner(),
        eq1_second_inner(),
        eq1_two_thirds_pi(),
        eq1_interval(),
        eq1_angle_bound(),
        eq1_circular(),
        eq1_standard(),
    ];
    out.extend(eq2_semicircle());
    out.extend([
        eq3_4_nonstandard(),
        eq3_4_coefficients(),
        eq5_semicircle(),
        eq6_reparam(),
    ]);
    out.extend([
        mu_lemma(),
        parameter_lemma(),
        eq7_lambda(),
        eq10_as_printed(),
    ]);
    out.extend(monotonicity::claims());
    out
}

/// Printed b₁*, ω₁ of eq. (1) against the construction.
fn eq1_first_inner() -> Claim {
    let (c, l, r) = (v("c"), v("lambda"), v("r"));
    let kk = k(&c);
    let f = factors(&c, &l);
    let cubic = lambda_cubic(&free_arc(&c));
    let h = &cubic.ctrl()[1];
    let norm = r.pow(2) * &f.d * &f.d; // the common factor r²D²
                                       // Printed ω₁ = (1/3)·k/(1 − λk)·∛((1 − λk)/(1 + 2λck)) = k·r/(3·N·D).
    let omega = h.weight().clone() * int(3) * &f.n * &f.d - kk.clone() * &r * &norm;
    // Printed b₁* = ([1 + 2λck]·b̄₀ + [2c − 2λck]·b̄₁)/(1 + 2c).
    let a = int(1) + int(2) * &l * &c * &kk;
    let b = int(2) * &c - int(2) * &l * &c * &kk;
    let mut polys = vec![omega];
    for (i, xy) in ["x", "y"].iter().enumerate() {
        let printed = a.clone() * v(&format!("{xy}0")) + &(b.clone() * v(&format!("{xy}1")));
        polys.push(h.coords[i].clone() * &kk - &(h.weight().clone() * &printed));
    }
    all_zero(
        "eq. (1): b₁* = ([1+2λc(1+2c)]b̄₀ + [2c−2λc(1+2c)]b̄₁)/(1+2c), ω₁ = (1/3)(1+2c)/(1−λ(1+2c))·∛((1−λ(1+2c))/(1+2λc(1+2c))) (c = cos θ/2)",
        &format!("{SRC} eq. (1)"),
        Verdict::Proved,
        &polys,
        "equals the construction L(u)·Q̄(u) (Möbius-reparameterized quadratic, σ = r/D, times the linear factor making ω₀ = ω₃ = 1); free control points, mod r³ = N·D²",
    )
}

/// Printed b₂*, ω₂ of eq. (1) against the construction.
fn eq1_second_inner() -> Claim {
    let (c, l, r) = (v("c"), v("lambda"), v("r"));
    let kk = k(&c);
    let f = factors(&c, &l);
    let cubic = lambda_cubic(&free_arc(&c));
    let h = &cubic.ctrl()[2];
    let norm = r.pow(2) * &f.d * &f.d;
    // Printed ω₂ = (1/3)·k·E/D·∛(D/N) = k·E·r²/(3·N·D²).
    let omega =
        h.weight().clone() * int(3) * &f.n * &f.d * &f.d - kk.clone() * &f.e * &r.pow(2) * &norm;
    // Printed b₂* = ((1 − λk)·b̄₂ + (2c + 4λc²k)·b̄₁)/(k·[1 − λ(1 − 4c²)]).
    let a = int(1) - l.clone() * &kk;
    let b = int(2) * &c + int(4) * &l * &c * &c * &kk;
    let den = kk.clone() * &(int(1) - l.clone() * &(int(1) - int(4) * &c * &c));
    let mut polys = vec![omega];
    for (i, xy) in ["x", "y"].iter().enumerate() {
        let printed = a.clone() * v(&format!("{xy}2")) + &(b.clone() * v(&format!("{xy}1")));
        polys.push(h.coords[i].clone() * &den - &(h.weight().clone() * &printed));
    }
    all_zero(
        "eq. (1): b₂* = ((1−λ(1+2c))b̄₂ + (2c+4λc²(1+2c))b̄₁)/((1+2c)[1−λ(1−4c²)]), ω₂ = (1/3)(1+2c)[1−λ(1−4c²)]/(1+2λc(1+2c))·∛((1+2λc(1+2c))/(1−λ(1+2c)))",
        &format!("{SRC} eq. (1)"),
        Verdict::Proved,
        &polys,
        "equals the construction; free control points, mod r³ = N·D²",
    )
}

/// The §1 example θ = 2π/3 (c = 1/2).
fn eq1_two_thirds_pi() -> Claim {
    let l = v("lambda");
    let half = q(1, 2);
    let arc = free_arc(&half);
    // c = 1/2: N = 1 − 2λ, D = 1 + 2λ; the root r³ = N·D² becomes ρ³ = (1 − 2λ)(1 + 2λ)².
    let f = factors(&half, &l);
    let rel = f.n.clone() * &f.d * &f.d;
    let cubic = arc.cubic_hom(&v("rho"), &f.d);
    let norm = v("rho").pow(2) * &f.d * &f.d;
    let (h1, h2) = (&cubic.ctrl()[1], &cubic.ctrl()[2]);
    let (p1, m1) = (int(1) + int(2) * &l, int(1) - int(2) * &l);
    let mut polys = vec![
        // ω₁ = 2/(3(1−2λ))·∛((1−2λ)/(1+2λ)) = 2ρ/(3(1−2λ)(1+2λ)).
        h1.weight().clone() * int(3) * &m1 * &p1 - int(2) * v("rho") * &norm,
        // ω₂ = 2/(3(1+2λ))·∛((1+2λ)/(1−2λ)) = 2ρ²/(3(1+2λ)·(1−2λ)(1+2λ)).
        h2.weight().clone() * int(3) * &p1 * &m1 * &p1 - int(2) * v("rho").pow(2) * &norm,
    ];
    for (i, xy) in ["x", "y"].iter().enumerate() {
        let (b0, b1, b2) = (
            v(&format!("{xy}0")),
            v(&format!("{xy}1")),
            v(&format!("{xy}2")),
        );
        polys.push(
            h1.coords[i].clone() * int(2)
                - &(h1.weight().clone() * &(p1.clone() * &b0 + &(m1.clone() * &b1))),
        );
        polys.push(
            h2.coords[i].clone() * int(2)
                - &(h2.weight().clone() * &(m1.clone() * &b2 + &(p1.clone() * &b1))),
        );
    }
    let polys: Vec<Poly> = polys
        .iter()
        .map(|p| p.reduce_power("rho", 3, &rel))
        .collect();
    all_zero(
        "§1 example θ = 2π/3: b₁* = ((1+2λ)b₀ + (1−2λ)b₁)/2, b₂* = ((1−2λ)b₂ + (1+2λ)b₁)/2, ω₁ = 2/(3(1−2λ))∛((1−2λ)/(1+2λ)), ω₂ = 2/(3(1+2λ))∛((1+2λ)/(1−2λ)), λ ∈ (−1/2, 1/2)",
        &format!("{SRC} §1 example after eq. (2)"),
        Verdict::Proved,
        &polys,
        "construction at c = 1/2, mod ρ³ = (1−2λ)(1+2λ)²; the interval is lambda_interval(1/2) (tested)",
    )
}

/// The admissible interval of eq. (1) is exactly where N, D, E > 0.
fn eq1_interval() -> Claim {
    let c = v("c");
    let kk = k(&c);
    let f4 = int(1) - int(4) * &c * &c;
    // λ = p/q homogeneously: N_h = q − pk, D_h = q + 2pck, E_h = q − p(1 − 4c²).
    let at = |p: &Poly, q: &Poly| {
        (
            q.clone() - &(p.clone() * &kk),
            q.clone() + &(int(2) * p * &c * &kk),
            q.clone() - &(p.clone() * &f4),
        )
    };
    let lo = (int(-1), int(2) * &c * &kk); // −1/(2ck)
    let hi = (int(1), kk.clone()); // 1/k
    let hi_neg = (int(1), f4.clone()); // 1/(1 − 4c²)
    let (n_lo, d_lo, e_lo) = at(&lo.0, &lo.1);
    let (n_hi, d_hi, e_hi) = at(&hi.0, &hi.1);
    let (n_hn, d_hn, e_hn) = at(&hi_neg.0, &hi_neg.1);
    let polys = vec![
        // c > 0: D vanishes at lo, N at hi; the other factors are positive there.
        d_lo,
        n_hi,
        n_lo - &(kk.clone() * &kk),  // N(lo) = k/(2c) > 0
        e_lo - &kk,                  // E(lo) = 1/(2c) > 0
        d_hi - &(kk.clone() * &kk),  // D(hi) = k > 0
        e_hi - &(int(2) * &c * &kk), // E(hi) = 2c > 0
        // c < 0: E vanishes at 1/(1−4c²), N and D are positive there.
        e_hn,
        n_hn + &(int(2) * &c * &kk), // N = −2ck/(1−4c²) > 0
        d_hn - &kk,                  // D = k/(1−4c²) > 0
    ];
    all_zero(
        "eq. (1): λ ∈ (−1/(2c(1+2c)), 1/(1+2c)) for 0 < θ < π and λ ∈ (−∞, 1/(1−4c²)) for π ≤ θ < 4π/3 — exactly where all weights are positive",
        &format!("{SRC} eq. (1), interval"),
        Verdict::Proved,
        &polys,
        "N, D, E are linear in λ; at each end of the printed interval one factor vanishes and the others are positive (identities at λ = p/q; for c < 0 all three → +∞ as λ → −∞), so N, D, E > 0 exactly inside; θ < 4π/3 ⇔ k = 1+2c > 0",
    )
}

/// The bound θ < 4π/3 is sharp: positive inner weights need c > −1/2.
fn eq1_angle_bound() -> Claim {
    let (c, sg) = (v("c"), v("sigma"));
    let cubic = free_arc(&c).cubic_hom(&sg, &int(1));
    let w = cubic.weights();
    let s3 = sg.pow(3);
    all_zero(
        "0 < θ < 4π/3 (source 004 §0–§1, after [6, 7]): the standard cubic family has positive weights exactly when cos(θ/2) > −1/2",
        &format!("{SRC} §1, range of θ"),
        Verdict::Proved,
        &[
            int(3) * &w[1] - &(int(2) * &c * &s3 + &int(1)),
            int(3) * &w[2] - &(sg.clone() * &(s3 + &(int(2) * &c))),
        ],
        "with the common factor σ² (σ = p/q, q = 1): 3ω₁σ² = 2cσ³ + 1 and 3ω₂σ = σ³ + 2c; for c < 0 both are positive iff −2c < σ³ < −1/(2c), an interval that is non-empty iff 4c² < 1; for c ≥ 0 every σ > 0 works",
    )
}

/// Every cubic of the family lies on the circle, for all θ and λ.
fn eq1_circular() -> Claim {
    let cubic = lambda_cubic(&unit_arc());
    let h = cubic.eval_hom(&v("t"));
    let (x, y, w) = (&h.coords[0], &h.coords[1], &h.coords[2]);
    let id = x.clone() * x + &(y.clone() * y) - &(w.clone() * w);
    all_zero(
        "the λ-cubic (1) of the unit-circle arc lies on the unit circle for every θ ∈ (0, 4π/3) and every λ (θ = π included: c = 0)",
        &format!("{SRC} eq. (1), (2)"),
        Verdict::Proved,
        &[id],
        "x(t)² + y(t)² − w(t)² ≡ 0 in t, mod s² = 1 − c² and r³ = N·D² (the circle test's identity with C = 0, R² = 1)",
    )
}

/// ω₀ = ω₃ = 1 after removing the common factor.
fn eq1_standard() -> Claim {
    let f = factors(&v("c"), &v("lambda"));
    let cubic = lambda_cubic(&free_arc(&v("c")));
    let norm = v("r").pow(2) * &f.d * &f.d;
    let w = cubic.weights();
    all_zero(
        "eq. (1) is standard: ω₀ = ω₃ = 1",
        &format!("{SRC} eq. (1)"),
        Verdict::Proved,
        &[w[0].clone() - &norm, w[3].clone() - &norm],
        "both end weights equal the common factor r²D²",
    )
}

/// Eq. (2), θ = π: control points and weights; ω₂ as printed is refuted.
fn eq2_semicircle() -> Vec<Claim> {
    let (l, r) = (v("lambda"), v("r"));
    let one_l = int(1) - &l;
    // c = 0: N = 1 − λ, D = 1, so r³ = 1 − λ, σ = r.
    let cubic = free_semicircle().cubic_hom(&r, &int(1));
    let (h1, h2) = (&cubic.ctrl()[1], &cubic.ctrl()[2]);
    let red = |p: Poly| p.reduce_power("r", 3, &one_l);
    let mut polys = vec![
        red(h1.weight().clone() * int(3) - &int(1)), // ω₁ = w₁/r² = 1/(3r²)
    ];
    for (i, (xy, b)) in [("x", "bx"), ("y", "by")].iter().enumerate() {
        let b1 = v(&format!("{xy}0")) + &(int(2) * &one_l * v(b));
        let b2 = (one_l.clone() * v(&format!("{xy}2")) + &(int(2) * v(b))) * &h2.weight().clone();
        polys.push(red(h1.coords[i].clone() - &(h1.weight().clone() * &b1)));
        polys.push(red(h2.coords[i].clone() * &one_l - &b2));
    }
    let ours_w2 = red(h2.weight().clone() * int(3) - &(r.pow(4))); // ω₂ = r²/3 ⇔ 3·w₂ = r²·r²
                                                                   // Cubes, free of the radical: ω₂ = w₂/r², so ω₂³·(1 − λ)² = w₂³ mod
                                                                   // r³ = 1 − λ (ours, from the construction) against the printed
                                                                   // ω₂³ = (1/27)(−λ)², both times (1 − λ)², compared at λ = 0.
    let ours_cube = red(h2.weight().pow(3));
    let printed_cube = l.pow(2) * &one_l.pow(2) * ratio::<Poly>(1, 27);
    let at_zero = |p: &Poly| p.eval(&[("lambda", BigRational::from_i64(0))]);
    let (printed_at_zero, ours_at_zero) = (at_zero(&printed_cube), at_zero(&ours_cube));
    vec![
        all_zero(
            "eq. (2), θ = π: b₁* = b̄₀ + 2(1−λ)b, b₂* = b̄₂ + 2b/(1−λ), ω₁ = 1/(3∛((1−λ)²)), λ < 1",
            &format!("{SRC} eq. (2)"),
            Verdict::Proved,
            &polys,
            "the construction at c = 0 with A₁ = (b, 0), free points and direction, mod r³ = 1 − λ",
        ),
        Claim::check(
            "eq. (2) and §2: ω₂ = (1/3)∛((1−λ)²) for θ = π",
            &format!("{SRC} §1 semicircle example, §2"),
            Verdict::Proved,
            ours_w2.is_zero(),
            "3·w₂ = r⁴ of the construction, mod r³ = 1 − λ".into(),
        ),
        Claim::check(
            "eq. (2) as printed: ω₂ = (1/3)∛((−λ)²)",
            &format!("{SRC} eq. (2)"),
            Verdict::Refuted,
            printed_at_zero == ours_at_zero,
            format!("at λ = 0 the printed ω₂³ is {}, the cubic's is {} (Table 2 prints ω₂ = 0.3333); correct: ω₂ = (1/3)∛((1−λ)²), as restated in the §1 example and §2", show(&printed_at_zero), show(&ours_at_zero)),
        )
        .given(ours_at_zero.is_some(), "the reduced ω₂³ of the construction is free of r"),
    ]
}

/// A rational value, or "undefined" when a symbol was left unassigned.
fn show(q: &Option<BigRational>) -> String {
    q.as_ref().map_or("undefined".into(), ToString::to_string)
}

/// Eqs. (3), (4): the non-standard quadratic of weights ω̄ has the same
/// parameterization as the cubic.
fn eq3_4_nonstandard() -> Claim {
    let (c, l, r) = (v("c"), v("lambda"), v("r"));
    let f = factors(&c, &l);
    let arc = free_arc(&c);
    let quad = arc.nonstandard_quadratic(&r, &f.d);
    let cubic = arc.cubic_hom(&r, &f.d);
    let w = quad.weights();
    let u = v("u");
    let linear = r.pow(2) * (int(1) - &u) + &(f.d.clone() * &f.d * &u);
    let same = cubic.eval_hom(&u).sub(&quad.eval_hom(&u).scale(&linear));
    let mut polys = vec![
        // (3): ω̄₁/ω̄₀ = c·∛(N/D) = c·r/D.
        w[1].clone() * &f.d - &(w[0].clone() * &c * &r),
        // (4): ω̄₁/ω̄₂ = c·∛(D/N) = c·r²/(N·D).
        w[1].clone() * &f.n * &f.d - &(w[2].clone() * &c * &r.pow(2)),
    ];
    polys.extend(same.coords);
    all_zero(
        "eqs. (3), (4): ω̄₁/ω̄₀ = c∛(N/D), ω̄₁/ω̄₂ = c∛(D/N) — this non-standard quadratic has the same parameterization as the cubic (1)",
        &format!("{SRC} eqs. (3), (4)"),
        Verdict::Proved,
        &polys,
        "cubic(u) ≡ L(u)·quadratic(u) with L(u) = r²(1−u) + D²u, free control points, mod r³ = N·D²",
    )
}

/// The two coefficient equations before (3), (4).
fn eq3_4_coefficients() -> Claim {
    let (c, l, r) = (v("c"), v("lambda"), v("r"));
    let kk = k(&c);
    let f = factors(&c, &l);
    let quad = free_arc(&c).nonstandard_quadratic(&r, &f.d);
    let w = quad.weights();
    let omega1 = (kk.clone() * &r, int(3) * &f.n * &f.d); // k r/(3ND)
    let omega2 = (kk.clone() * &f.e * &r.pow(2), int(3) * &f.n * &f.d * &f.d);
    // 2ω̄₁ − 3·(2c − 2λck)/k·ω̄₀ω₁ = 0 and 2ω̄₁ − 3·(2c + 4λc²k)/(k[1−λ(1−4c²)])·ω̄₂ω₂ = 0.
    let first = int(2) * &w[1] * &kk * &omega1.1
        - &(int(3) * (int(2) * &c - int(2) * &l * &c * &kk) * &w[0] * &omega1.0);
    let second = int(2) * &w[1] * &kk * &f.e * &omega2.1
        - &(int(3) * (int(2) * &c + int(4) * &l * &c * &c * &kk) * &w[2] * &omega2.0);
    all_zero(
        "§2: 2ω̄₁ − 3(2c−2λc(1+2c))/(1+2c)·ω̄₀ω₁ = 0 and 2ω̄₁ − 3(2c+4λc²(1+2c))/((1+2c)[1−λ(1−4c²)])·ω̄₂ω₂ = 0",
        &format!("{SRC} §2, equations before (3)"),
        Verdict::Proved,
        &[first, second],
        "with ω̄ = (D², c·r·D, r²) and ω₁, ω₂ of (1), mod r³ = N·D²",
    )
}

/// Eq. (5): θ = π, ω̄₀ = 1/∛(1−λ), ω̄₂ = ∛(1−λ), b with coefficient 1.
fn eq5_semicircle() -> Claim {
    let (l, r, u) = (v("lambda"), v("r"), v("u"));
    let one_l = int(1) - &l;
    let arc = free_semicircle();
    let cubic = arc.cubic_hom(&r, &int(1));
    let [a0, a1, a2] = arc.ctrl();
    // p(u)·(1−λ): ω̄₀ = 1/r = r²/(1−λ), ω̄₂ = r.
    let s = int(1) - &u;
    let printed = a0
        .scale(&(s.clone() * &s * &r.pow(2)))
        .add(&a1.scale(&(int(2) * &u * &s * &one_l)))
        .add(&a2.scale(&(u.clone() * &u * &r * &one_l)));
    let polys: Vec<Poly> = minors(&cubic.eval_hom(&u), &printed)
        .iter()
        .map(|p| p.reduce_power("r", 3, &one_l))
        .collect();
    all_zero(
        "eq. (5): for θ = π the quadratic with ω̄₀ = 1/∛(1−λ), ω̄₂ = ∛(1−λ), ω̄₁ = 0 and the term 2u(1−u)b̄ has the parameterization of the cubic (2)",
        &format!("{SRC} eq. (5)"),
        Verdict::Proved,
        &polys,
        "the two homogeneous points are proportional for all u (2×2 minors vanish), free points and direction, mod r³ = 1 − λ",
    )
}

/// Eq. (6): changing λ₁ → λ₂ is u = ū/(Δ(1−ū) + ū), Δ = σ₁/σ₂.
fn eq6_reparam() -> Claim {
    let (s1, s2, ub) = (v("sigma1"), v("sigma2"), v("ubar"));
    let arc = free_arc(&v("c"));
    let one = int(1);
    let c1 = arc.cubic_hom(&s1, &one);
    let c2 = arc.cubic_hom(&s2, &one);
    // (1 − u : u) = (Δ(1−ū) : ū) = (σ₁(1−ū) : σ₂ū).
    let moved = c1.eval_hom_param(&(s1.clone() * &(one.clone() - &ub)), &(s2.clone() * &ub));
    let direct = c2.eval_hom_param(&(one - &ub), &ub);
    all_zero(
        "eq. (6): the cubic for λ₁ at u = ū/(Δ(1−ū)+ū) is the cubic for λ₂ at ū, Δ = ∛([1−λ₁k][1+2λ₂ck]/([1+2λ₁ck][1−λ₂k])); also for θ = π",
        &format!("{SRC} eq. (6)"),
        Verdict::Proved,
        &minors(&moved, &direct),
        "with σᵢ = ∛(Nᵢ/Dᵢ) symbols, Δ = σ₁/σ₂ (so Δ³ is the printed radicand); proportional for all ū, free control points and c",
    )
}

/// μ = |b̄₀m|/|mb̄₂| = s²/(1−s)² for the arc point of quadratic parameter s.
fn mu_lemma() -> Claim {
    let s = v("s_par");
    let arc = free_arc(&v("c"));
    let [a0, a1, a2] = arc.ctrl();
    let p = arc.to_curve().eval_hom(&s);
    let m = a0.scale(&(int(1) - &s).pow(2)).add(&a2.scale(&s.pow(2)));
    let rows = [a1, &p, &m];
    let det = |i: usize, j: usize| {
        rows[1].coords[i].clone() * &rows[2].coords[j]
            - &(rows[1].coords[j].clone() * &rows[2].coords[i])
    };
    let d = rows[0].coords[0].clone() * &det(1, 2) - &(rows[0].coords[1].clone() * &det(0, 2))
        + &(rows[0].coords[2].clone() * &det(0, 1));
    all_zero(
        "§3.1: for the arc point p of quadratic parameter s, the line b̄₁p meets the chord at m = ((1−s)²b̄₀ + s²b̄₂)/((1−s)²+s²), so μ = |b̄₀m|/|mb̄₂| = s²/(1−s)² and s = √μ/(1+√μ)",
        &format!("{SRC} §3.1, fig. 5"),
        Verdict::Proved,
        &[d],
        "det[A₁; P(s); M(s)] ≡ 0 (collinear), free control points and c",
    )
}

/// The cubic of ratio σ puts the quadratic's point s at ū with
/// σ·ū/(1−ū) = s/(1−s).
fn parameter_lemma() -> Claim {
    let (sg, ub) = (v("sigma"), v("ubar"));
    let arc = free_arc(&v("c"));
    let one = int(1);
    let cubic = arc.cubic_hom(&sg, &one);
    let on_cubic = cubic.eval_hom_param(&(one.clone() - &ub), &ub);
    let on_quad = arc.to_curve().eval_hom_param(&(one - &ub), &(sg * &ub));
    all_zero(
        "the cubic with weight ratio σ passes at ū through the point of quadratic parameter s with s/(1−s) = σ·ū/(1−ū); hence ū = √μ/(σ+√μ) and σ = √μ(1/ū − 1)",
        &format!("{SRC} §3 (basis of eqs. 7–11)"),
        Verdict::Proved,
        &minors(&on_cubic, &on_quad),
        "proportional homogeneous points for all ū, σ, c and free control points",
    )
}

/// Eq. (7) (with (8), (9) as cases): λ* gives σ³ = M.
fn eq7_lambda() -> Claim {
    let (c, m) = (v("c"), v("M"));
    let kk = k(&c);
    // λ* = P/Q with P = 1 − M, Q = k(1 + 2cM): N/D = M ⇔ N_h − M·D_h = 0.
    let (p, qq) = (int(1) - &m, kk.clone() * &(int(1) + int(2) * &c * &m));
    let n_h = qq.clone() - &(p.clone() * &kk);
    let d_h = qq + &(int(2) * &p * &c * &kk);
    all_zero(
        "eq. (7): λ* = (1 − M)/((1+2c)(1 + 2Mc)), M = μ√μ(1/ū − 1)³, puts p at ū; (8) is c = 0, (9) is ū = 1/2",
        &format!("{SRC} eqs. (7)–(9)"),
        Verdict::Proved,
        &[n_h - &(m * &d_h)],
        "N(λ*)/D(λ*) = M = σ³ with σ = √μ(1/ū−1) from the parameter lemma",
    )
}

/// Eq. (10) as printed carries (1 + 2λ*c)(1 + 2c) where D = 1 + 2λ*c(1 + 2c).
fn eq10_as_printed() -> Claim {
    // c = 1/2, λ* = 0, μ = 1 (the midpoint): by symmetry ū = 1/2.
    let (c, lam, mu) = (
        ratio::<BigRational>(1, 2),
        BigRational::from_i64(0),
        BigRational::from_i64(1),
    );
    let ok = check_lambda(&c, &lam).is_ok();
    let one = BigRational::from_i64(1);
    let k = one.clone() + &c * BigRational::from_i64(2);
    let printed_radicand =
        &mu * (&one + &c * &lam * BigRational::from_i64(2)) * &k / (&one - &lam * &k);
    let ours_radicand =
        &mu * (&one + &c * &lam * &k * BigRational::from_i64(2)) / (&one - &lam * &k);
    Claim::check(
        "eq. (10) as printed: ū = X/(X+1), X = ∛(μ√μ(1+2λ*c)(1+2c)/(1−λ*(1+2c)))",
        &format!("{SRC} eq. (10)"),
        Verdict::Refuted,
        printed_radicand == ours_radicand,
        format!(
            "θ = 2π/3 (c = 1/2), λ* = 0, p the midpoint (μ = 1): ū must be 1/2 (symmetry; parameter lemma), ours X³ = {ours_radicand} gives ū = 1/2, the printed X³ = {printed_radicand} gives ū = ∛2/(∛2+1) ≈ 0.5575; correct: X³ = μ√μ(1 + 2λ*c(1+2c))/(1 − λ*(1+2c)), i.e. ū = 1/(∛(N/(D·μ√μ)) + 1); eq. (11) (c = 0) is right"
        ),
    )
    .given(ok, "λ* = 0 is admissible at c = 1/2")
}

mod monotonicity {
    //! Properties 2)–6) of §1, by derivatives of the cubes
    //! `ω₁³ = k³/(27N²D)`, `ω₂³ = k³E³/(27ND²)` (rational in λ) and sign
    //! analysis, plus a dense exact sample.
    use super::*;
    use exact_bezier::algebra::Ordered;
    use num_traits::Signed;

    pub fn claims() -> Vec<Claim> {
        vec![
            cubes(),
            omega1_derivative(),
            omega1_theta_below_pi(),
            omega1_theta_above_pi(),
            omega2_derivative(),
            omega2_theta_below_pi(),
            omega2_theta_above_pi(),
            semicircle_monotone(),
            growth_ratio(),
            growth_above_pi(),
            control_limits_below_pi(),
            control_limits_above_pi(),
            dense_sample(),
        ]
    }

    fn cubes() -> Claim {
        let (c, l, r) = (v("c"), v("lambda"), v("r"));
        let kk = k(&c);
        let f = factors(&c, &l);
        let k3 = kk.pow(3);
        // ω₁ = k r/(3ND), ω₂ = k E r²/(3ND²).
        let w1 = kk.clone() * &r;
        let w2 = kk.clone() * &f.e * &r.pow(2);
        let p1 = w1.pow(3) * &f.n.pow(2) * &f.d - &(k3.clone() * &(f.n.clone() * &f.d).pow(3));
        let p2 = w2.pow(3) * &f.n * &f.d.pow(2)
            - &(k3 * &f.e.pow(3) * &(f.n.clone() * &f.d.pow(2)).pow(3));
        all_zero(
            "ω₁³ = k³/(27N²D), ω₂³ = k³E³/(27ND²), (ω₁/ω₂)³ = D/(N·E³)",
            &format!("{SRC} §1 (ours, used for 3)–6))"),
            Verdict::Proved,
            &[p1, p2],
            "cubes of the printed ω₁, ω₂ (ω₁ = kr/(3ND), ω₂ = kEr²/(3ND²)) mod r³ = N·D²",
        )
    }

    /// (N²D)' = −2kN(1 − c + 3λck): ω₁ grows with λ iff 1 − c + 3λck > 0.
    fn omega1_derivative() -> Claim {
        let (c, l) = (v("c"), v("lambda"));
        let kk = k(&c);
        let f = factors(&c, &l);
        let g = f.n.pow(2) * &f.d;
        let lin = int(1) - &c + &(int(3) * &l * &c * &kk);
        all_zero(
            "d/dλ (N²D) = −2kN(1 − c + 3λck): on the admissible interval ω₁ increases iff 1 − c + 3λc(1+2c) > 0",
            &format!("{SRC} §1 property 3)"),
            Verdict::Proved,
            &[deriv(&g, "lambda") + &(int(2) * &kk * &f.n * &lin)],
            "ω₁³ = k³/(27N²D) with k, N, D > 0",
        )
    }

    fn omega1_theta_below_pi() -> Claim {
        let c = v("c");
        let kk = k(&c);
        // λ₀ = −(1−c)/(3ck): 6c(λ₀ − lo) = 1, 3c(hi − λ₀) = 1, and ω₁³(λ₀) = c².
        let (p, q) = (-(int(1) - &c), int(3) * &c * &kk);
        let n_h = q.clone() - &(p.clone() * &kk);
        let d_h = q.clone() + &(int(2) * &p * &c * &kk);
        let polys = vec![
            (p.clone() * int(2) * &c * &kk + &q) * int(6) * &c - &(q.clone() * int(2) * &c * &kk), // λ₀ − lo = 1/(6c)
            (q.clone() - &(p.clone() * &kk)) * int(3) * &c - &(q.clone() * &kk), // hi − λ₀ = 1/(3c)
            kk.pow(3) * &q.pow(3) - &(int(27) * &c * &c * &n_h.pow(2) * &d_h),   // ω₁³(λ₀) = c²
        ];
        all_zero(
            "property 3), 0 < θ < π: ω₁ strictly decreases on (−1/(2ck), λ₀), increases on [λ₀, 1/k), minimum c^{2/3} at λ₀ = −(1−c)/(3c(1+2c))",
            &format!("{SRC} §1 property 3)"),
            Verdict::Proved,
            &polys,
            "1 − c + 3λck changes sign at λ₀ (slope 3ck > 0); λ₀ − lo = 1/(6c) > 0, hi − λ₀ = 1/(3c) > 0; ω₁³(λ₀) = c²",
        )
    }

    /// c = −1/4: λ = 0 and λ = 122/93 < λ₀ both admissible, ω₁ increases.
    fn omega1_theta_above_pi() -> Claim {
        let c = ratio::<BigRational>(-1, 4);
        let (l0, l1) = (BigRational::from_i64(0), ratio::<BigRational>(122, 93));
        let w = |l: &BigRational| omega_cubes(&c, l).0;
        let k = BigRational::from_i64(1) + &c * BigRational::from_i64(2);
        let lambda0 = -(BigRational::from_i64(1) - &c) / (BigRational::from_i64(3) * &c * &k);
        let decreasing = w(&l1) < w(&l0);
        let admissible =
            check_lambda(&c, &l0).is_ok() && check_lambda(&c, &l1).is_ok() && l1 < lambda0;
        Claim::check(
            "property 3), π < θ < 4π/3: ω₁ strictly decreases on (−∞, λ₀), increases on [λ₀, 1/(1−4c²)), minimum c^{2/3} at λ₀",
            &format!("{SRC} §1 property 3)"),
            Verdict::Refuted,
            decreasing,
            format!(
                "c = −1/4 (θ ≈ 209°): λ₀ = {lambda0} lies beyond the upper end 4/3 (always: λ₀ − 1/(1−4c²) = (1+2c²)/(3|c|k(1−2c)) > 0); ω₁(0) = 1/6 < ω₁(122/93) = 31/80 (σ = 4/5, exact) although both λ < λ₀; correct: for c < 0, 1 − c + 3λck > 0 on the whole interval, so ω₁ strictly increases, inf ω₁ = 0 (λ → −∞), no minimum (ω₁³ = {} and {})",
                w(&l0),
                w(&l1)
            ),
        )
        .given(admissible, "λ = 0 and λ = 122/93 are admissible and below λ₀")
    }

    fn omega2_derivative() -> Claim {
        let (c, l) = (v("c"), v("lambda"));
        let kk = k(&c);
        let f = factors(&c, &l);
        let g = int(3) * deriv(&f.e, "lambda") * &f.n * &f.d
            - &(f.e.clone()
                * &(deriv(&f.n, "lambda") * &f.d + &(int(2) * &f.n * &deriv(&f.d, "lambda"))));
        let lin = l.clone() * &kk * &(int(1) + int(2) * &c * &c) - &(int(1) - &c);
        all_zero(
            "d/dλ (E³/(ND²)) = E²·G/(N²D³), G = 2k(λk(1+2c²) − (1 − c)): ω₂ increases iff λ > (1−c)/(k(1+2c²))",
            &format!("{SRC} §1 property 4)"),
            Verdict::Proved,
            &[g - &(int(2) * &kk * &lin)],
            "ω₂³ = k³E³/(27ND²), G = 3E'ND − E(N'D + 2ND')",
        )
    }

    fn omega2_theta_below_pi() -> Claim {
        let c = v("c");
        let kk = k(&c);
        let c2 = int(1) + int(2) * &c * &c;
        let (p, q) = (int(1) - &c, kk.clone() * &c2);
        let (n_h, d_h, e_h) = (
            q.clone() - &(p.clone() * &kk),
            q.clone() + &(int(2) * &p * &c * &kk),
            q.clone() - &(p.clone() * &(int(1) - int(4) * &c * &c)),
        );
        let polys = vec![
            (p.clone() * int(2) * &c * &kk + &q) * int(2) * &c * &c2
                - &(q.clone() * int(2) * &c * &kk), // λ₀ − lo = 1/(2c(1+2c²))
            (q.clone() - &(p.clone() * &kk)) * &c2 - &(q.clone() * &kk * &c), // hi − λ₀ = c/(1+2c²)
            kk.pow(3) * &e_h.pow(3) - &(int(27) * &c * &c * &n_h * &d_h.pow(2)), // ω₂³(λ₀) = c²
        ];
        all_zero(
            "property 4), 0 < θ < π: ω₂ strictly decreases on (−1/(2ck), λ₀), increases on [λ₀, 1/k), minimum c^{2/3} at λ₀ = (1−c)/((1+2c)(1+2c²))",
            &format!("{SRC} §1 property 4)"),
            Verdict::Proved,
            &polys,
            "G changes sign at λ₀; λ₀ − lo = 1/(2c(1+2c²)) > 0, hi − λ₀ = c/(1+2c²) > 0; ω₂³(λ₀) = c²",
        )
    }

    fn omega2_theta_above_pi() -> Claim {
        let c = ratio::<BigRational>(-1, 4);
        let one = BigRational::from_i64(1);
        let k = one.clone() + &c * BigRational::from_i64(2);
        let lambda0 = (one.clone() - &c) / (k * (one + &c * &c * BigRational::from_i64(2)));
        Claim::check(
            "property 4), π < θ < 4π/3: ω₂ decreases on (−∞, λ₀), increases on [λ₀, 1/(1−4c²)], minimum c^{2/3} at λ₀",
            &format!("{SRC} §1 property 4)"),
            Verdict::Refuted,
            check_lambda(&c, &lambda0).is_ok(),
            format!("c = −1/4: λ₀ = {lambda0} is not admissible (upper end {}; always λ₀ − 1/(1−4c²) = −3c/(k(1+2c²)(1−2c)) > 0); correct: for c < 0, ω₂ strictly decreases on the whole interval, inf ω₂ = 0 (λ → 1/(1−4c²), E → 0), no minimum", exact_bezier::arc::lambda_interval(&c).map(|(_, hi)| hi.to_string()).unwrap_or_default()),
        )
    }

    fn semicircle_monotone() -> Claim {
        let l = v("lambda");
        // c = 0: 1 − c + 3λck = 1 > 0, λk(1+2c²) − (1 − c) = λ − 1 < 0.
        let f = factors(&int(0), &l);
        let g1 = deriv(&(f.n.pow(2) * &f.d), "lambda") + &(int(2) * &f.n);
        let g2 = int(3) * deriv(&f.e, "lambda") * &f.n * &f.d
            - &(f.e.clone()
                * &(deriv(&f.n, "lambda") * &f.d + &(int(2) * &f.n * &deriv(&f.d, "lambda"))))
            - &(int(2) * &(l - &int(1)));
        all_zero(
            "property 5), θ = π: ω₁ increases, ω₂ decreases in λ",
            &format!("{SRC} §1 property 5)"),
            Verdict::Proved,
            &[g1, g2],
            "the derivative identities at c = 0: (N²D)' = −2N < 0, G = 2(λ − 1) < 0 on λ < 1",
        )
    }

    /// Property 6) for 0 < θ < π: as printed, "λ larger ⇒ ω₁ ≪ ω₂".
    fn growth_ratio() -> Claim {
        let c = ratio::<BigRational>(1, 2);
        let l = ratio::<BigRational>(49, 100);
        let (w1, w2) = omega_cubes(&c, &l);
        Claim::check(
            "property 6): as λ grows, ω₁ and ω₂ both grow with ω₁ ≪ ω₂; as λ falls, both grow with ω₂ ≫ ω₁",
            &format!("{SRC} §1 property 6)"),
            Verdict::Refuted,
            w1 < w2,
            format!("(ω₁/ω₂)³ = D/(N·E³) → ∞ as λ → 1/k (N → 0): at c = 1/2, λ = 49/100: ω₁³ = {w1}, ω₂³ = {w2}, ω₁ > ω₂ (Table 1 too: λ = 0.4, ω₁ = 1.6025 > ω₂ = 0.7704); correct for 0 < θ < π: λ → upper end ⇒ ω₁ ≫ ω₂, λ → lower end ⇒ ω₂ ≫ ω₁ (both → ∞ at both ends)"),
        )
    }

    fn growth_above_pi() -> Claim {
        let c = ratio::<BigRational>(-1, 4);
        let (a, b) = (
            omega_cubes(&c, &BigRational::from_i64(0)).0,
            omega_cubes(&c, &BigRational::from_i64(-1000)).0,
        );
        Claim::check(
            "property 6) for π < θ < 4π/3: ω₁, ω₂ both grow at both ends of the λ interval",
            &format!("{SRC} §1 property 6)"),
            Verdict::Refuted,
            b > a,
            format!("c = −1/4: ω₁³(0) = {a} > ω₁³(−1000) = {b}; ω₁³ = k³/(27N²D) → 0 as λ → −∞ and ω₂ → 0 as λ → 1/(1−4c²)"),
        )
    }

    fn control_limits_below_pi() -> Claim {
        let c = v("c");
        let kk = k(&c);
        let at = |p: &Poly, q: &Poly| {
            (
                q.clone() - &(p.clone() * &kk),
                q.clone() + &(int(2) * p * &c * &kk),
                q.clone() - &(p.clone() * &(int(1) - int(4) * &c * &c)),
            )
        };
        let (n_hi, d_hi, _) = at(&int(1), &kk);
        let (n_lo, d_lo, e_lo) = at(&int(-1), &(int(2) * &c * &kk));
        // b₁* = (D b̄₀ + 2cN b̄₁)/k, b₂* = (N b̄₂ + 2cD b̄₁)/(kE).
        let polys = vec![d_hi - &(kk.clone() * &kk), n_hi, d_lo, n_lo - &(kk * &e_lo)];
        all_zero(
            "property 2), 0 < θ < π: λ → 1/(1+2c) ⇒ b₁* → b̄₀, b₂* → b̄₁; λ → −1/(2c(1+2c)) ⇒ b₂* → b̄₂, b₁* → b̄₁",
            &format!("{SRC} §1 property 2)"),
            Verdict::Proved,
            &polys,
            "at the upper end D = k, N = 0; at the lower end D = 0, N = kE (λ = p/q homogeneous)",
        )
    }

    fn control_limits_above_pi() -> Claim {
        let c = ratio::<BigRational>(-1, 4);
        let l = ratio::<BigRational>(4, 3) - ratio::<BigRational>(1, 1000);
        let f = LambdaFactors::new(&c, &l);
        let kk = BigRational::from_i64(1) + &c * BigRational::from_i64(2);
        let coeff = f.n.clone() / (&kk * &f.e);
        Claim::check(
            "property 2), π < θ < 4π/3: λ → 1/(1−4c²) ⇒ b₁* → b̄₀, b₂* → b̄₁; λ → −∞ ⇒ b₂* → b̄₂, b₁* → b̄₁",
            &format!("{SRC} §1 property 2)"),
            Verdict::Refuted,
            coeff < BigRational::from_i64(2),
            format!("c = −1/4, λ = 4/3 − 1/1000: b₂* = (N·b̄₂ + 2cD·b̄₁)/(kE) has b̄₂-coefficient {} ≈ {:.1}: E → 0 at the upper end so b₂* runs to infinity, and b₁*'s b̄₀-coefficient D/k → 1/(1−4c²) ≠ 1; as λ → −∞, b₁* → ∞ and b₂* → (b̄₂ − 4c²b̄₁)/(1−4c²); the printed limits hold only for 0 < θ < π", coeff, coeff.to_f64()),
        )
    }

    /// Exact cubes of ω₁, ω₂ on a dense grid agree with the sign rules.
    fn dense_sample() -> Claim {
        let cs = [(1, 10), (1, 2), (3, 5), (9, 10), (-1, 4), (-2, 5), (0, 1)];
        let mut checked = 0;
        let mut bad = None;
        for (cn, cd) in cs {
            let c = ratio::<BigRational>(cn, cd);
            let k = BigRational::from_i64(1) + &c * BigRational::from_i64(2);
            let (lo, hi) = exact_bezier::arc::lambda_interval(&c).expect("c in range");
            let lo = lo.unwrap_or_else(|| hi.clone() - BigRational::from_i64(50));
            let steps = 400;
            let grid: Vec<BigRational> = (1..steps)
                .map(|i| lo.clone() + (hi.clone() - &lo) * ratio::<BigRational>(i, steps))
                .collect();
            // Per grid point: the cubes (ω₁³, ω₂³) and the two signs' arguments
            // `1 − c + 3λck` and `λk(1 + 2c²) − (1 − c)`, each computed once.
            let one = BigRational::from_i64(1);
            let (three, two) = (BigRational::from_i64(3), BigRational::from_i64(2));
            let at: Vec<_> = grid
                .iter()
                .map(|l| {
                    let s1 = one.clone() - &c + l * &c * &k * &three;
                    let s2 = l * &k * (one.clone() + &c * &c * &two) - (one.clone() - &c);
                    (omega_cubes(&c, l), s1.signum(), s2.signum())
                })
                .collect();
            for (pair, lambda) in at.windows(2).zip(&grid) {
                let [(a, s1a, s2a), (b, s1b, s2b)] = [&pair[0], &pair[1]];
                // Where the sign is the same at both ends, the step must go that way.
                let moves_as_signed =
                    |sa: &BigRational, sb: &BigRational, lo: &BigRational, hi: &BigRational| {
                        sa != sb || (!sa.is_positive() || hi > lo) && (!sa.is_negative() || hi < lo)
                    };
                if !(moves_as_signed(s1a, s1b, &a.0, &b.0) && moves_as_signed(s2a, s2b, &a.1, &b.1))
                    && bad.is_none()
                {
                    bad = Some(format!("c = {c}, λ = {lambda}"));
                }
                checked += 1;
            }
        }
        Claim::sampled(
            "dense exact sample: ω₁, ω₂ move as the derivative signs say (cross-check of 3)–5))",
            &format!("{SRC} §1 properties 3)–5)"),
            Verdict::Checked,
            bad.is_none(),
            bad.unwrap_or_else(|| format!("{checked} consecutive λ pairs on 399-point grids over the admissible interval (lower end −∞ cut at hi − 50) for c ∈ {{1/10, 1/2, 3/5, 9/10, −1/4, −2/5, 0}}: exact ω³ = k³/(27N²D), k³E³/(27ND²) compared")),
        )
    }
}

/// `(ω₁³, ω₂³)` exactly.
pub(crate) fn omega_cubes(c: &BigRational, l: &BigRational) -> (BigRational, BigRational) {
    let f = LambdaFactors::new(c, l);
    let k = BigRational::from_i64(1) + c * BigRational::from_i64(2);
    let k3 = &k * &k * &k / BigRational::from_i64(27);
    (
        k3.clone() / (&f.n * &f.n * &f.d),
        k3 * &f.e * &f.e * &f.e / (&f.n * &f.d * &f.d),
    )
}
