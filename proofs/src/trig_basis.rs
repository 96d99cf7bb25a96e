//! Source 002 (Sun & Shi) §1–§2: the cubic trigonometric basis (1) with
//! shape parameter α, its curves (Definition 2) and surfaces (Definition 3),
//! and Theorems 1–2.
//!
//! Everything is symbolic in `s = sin t`, `c = cos t` (normal form modulo
//! `s² + c² = 1`, [`circle_normal_form`]), in α, and in the control points.
//! The basis has fixed degree 2 in (s, c), so no degree bound is needed;
//! control points are 1-dimensional symbols (each coordinate is
//! independent, so that is general).

use super::{Claim, Verdict};
use exact_bezier::algebra::ratio;
use exact_bezier::algebra::Poly;
use exact_bezier::trig::basis::{circle_normal_form, TrigFn, TrigParam};
use exact_bezier::trig::curve::TrigCurve;
use exact_bezier::trig::surface::TrigRect;
use num_rational::BigRational;
use num_traits::Zero;

const SRC: &str = "002 Sun & Shi";

/// The symbolic parameter `(s, c)` named `s{tag}`, `c{tag}`.
pub(crate) fn sym_param(tag: &str) -> TrigParam<Poly> {
    TrigParam::new(Poly::var(&format!("s{tag}")), Poly::var(&format!("c{tag}")))
}

/// Normal form modulo `s_u² + c_u² = 1` and `s_v² + c_v² = 1` (tags "" , "u", "v").
pub(crate) fn nf(p: &Poly) -> Poly {
    ["", "u", "v"].iter().fold(p.clone(), |q, tag| {
        circle_normal_form(&q, &format!("s{tag}"), &format!("c{tag}"))
    })
}

/// Is `a ≡ b` for all t (after reduction)?
pub(crate) fn same(a: &Poly, b: &Poly) -> bool {
    nf(&(a.clone() - b)).is_zero()
}

pub(crate) fn int(n: i64) -> Poly {
    Poly::from_int(n)
}

/// A surface with symbolic 1-D control points `{name}{i}{j}` and shape
/// parameters `a1`, `a2`.
fn sym_rect(name: &str, a1: &Poly, a2: &Poly) -> TrigRect<Poly> {
    let pts = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| vec![Poly::var(&format!("{name}{i}{j}"))])
                .collect()
        })
        .collect();
    TrigRect::new(pts, [a1.clone(), a2.clone()]).expect("4 × 4 net")
}

/// The basis (1) at the symbolic `(s, c)`.
fn basis_at(alpha: &Poly, k: usize) -> [Poly; 4] {
    let at = sym_param("");
    TrigFn::basis(alpha).map(|x| x.derivative_n(k).eval(&at))
}

/// The printed eq. (1), typed from the paper.
fn printed_basis(a: &Poly) -> [Poly; 4] {
    let (s, c) = (Poly::var("s"), Poly::var("c"));
    let s2 = s.pow(2);
    [
        int(1) - a.clone() * &s + (a.clone() - int(1)) * &s2,
        a.clone() * &s - a.clone() * &s2,
        -a.clone() + a.clone() * &c + a.clone() * &s2,
        a.clone() - a.clone() * &c + (int(1) - a) * &s2,
    ]
}

/// Our factorizations of (1), modulo s² + c² = 1.
fn factored(a: &Poly) -> [Poly; 4] {
    let (s, c) = (Poly::var("s"), Poly::var("c"));
    let lin = |x: &Poly| int(1) + (int(1) - a.clone()) * x;
    [
        (int(1) - s.clone()) * lin(&s),
        a.clone() * &s * (int(1) - s.clone()),
        a.clone() * &c * (int(1) - c.clone()),
        (int(1) - c.clone()) * lin(&c),
    ]
}

fn alpha() -> Poly {
    Poly::var("alpha")
}

fn all_same(a: &[Poly], b: &[Poly]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| same(x, y))
}

/// 4 × 4 determinant by cofactor expansion.
pub(crate) fn det4(m: &[[Poly; 4]; 4]) -> Poly {
    fn det(m: &[Vec<Poly>]) -> Poly {
        if m.len() == 1 {
            return m[0][0].clone();
        }
        (0..m.len()).fold(Poly::zero(), |acc, k| {
            let minor: Vec<Vec<Poly>> = m[1..]
                .iter()
                .map(|r| {
                    r.iter()
                        .enumerate()
                        .filter(|(j, _)| *j != k)
                        .map(|(_, x)| x.clone())
                        .collect()
                })
                .collect();
            let term = m[0][k].clone() * det(&minor);
            if k % 2 == 0 {
                acc + term
            } else {
                acc - term
            }
        })
    }
    det(&m.iter().map(|r| r.to_vec()).collect::<Vec<_>>())
}

/// The coefficient matrix of `X₀…X₃` on `1, s, c, s²` (their `s c`
/// coefficients are 0).
fn basis_matrix(a: &Poly) -> ([[Poly; 4]; 4], bool) {
    let x = TrigFn::basis(a);
    let m = std::array::from_fn(|i| std::array::from_fn(|k| x[i].coeffs()[k].clone()));
    (m, x.iter().all(|f| f.coeffs()[4].is_zero()))
}

/// Every claim of §1–§2 on the basis, curves and surfaces.
pub fn claims() -> Vec<Claim> {
    let mut out = basis_claims();
    out.extend(curve_claims());
    out.extend(surface_claims());
    out
}

fn basis_claims() -> Vec<Claim> {
    let a = alpha();
    let x = basis_at(&a, 0);
    let end = |at: TrigParam<Poly>| TrigFn::basis(&a).map(|f| f.eval(&at));
    let lin = int(1) + (int(1) - a.clone()) * Poly::var("x");
    let at_one = lin.subst_rational("x", &ratio(1, 1));
    let at_zero = lin.subst_rational("x", &ratio(0, 1));
    // Exact witnesses at τ = 1/2 (s = 4/5, c = 3/5), by hand:
    // α = 3: X₀ = (1 − 4/5)(1 − 2·4/5) = −3/25; α = −1: X₁ = −(4/5)(1/5) = −4/25.
    let half = TrigParam::from_tau(&ratio::<BigRational>(1, 2));
    let x0_a3 = TrigFn::basis(&ratio::<BigRational>(3, 1))[0].eval(&half);
    let x1_am1 = TrigFn::basis(&ratio::<BigRational>(-1, 1))[1].eval(&half);
    let at0 = TrigFn::basis(&Poly::zero()).map(|f| f.eval(&sym_param("")));
    let (s, c) = (Poly::var("s"), Poly::var("c"));
    let (m, no_sc) = basis_matrix(&a);
    let d1 = basis_at(&a, 1);
    let d_alpha: Vec<Poly> = x.iter().map(|p| p.derivative("alpha")).collect();
    let printed_d_alpha = [
        -s.clone() + s.pow(2),
        s.clone() - s.pow(2),
        int(-1) + c.clone() + s.pow(2),
        int(1) - c.clone() - s.pow(2),
    ];
    let signed_d_alpha = [
        -(s.clone() * (int(1) - s.clone())),
        s.clone() * (int(1) - s.clone()),
        c.clone() * (int(1) - c.clone()),
        -(c.clone() * (int(1) - c.clone())),
    ];
    let d_factored = [
        c.clone() * (int(2) * (a.clone() - int(1)) * &s - a.clone()),
        a.clone() * &c * (int(1) - int(2) * s.clone()),
        a.clone() * &s * (int(2) * c.clone() - int(1)),
        s.clone() * (a.clone() + int(2) * (int(1) - a.clone()) * &c),
    ];
    let rev = TrigFn::basis(&a).map(|f| f.eval(&sym_param("").reflect()));
    vec![
        Claim::check(
            "eq. (1) as implemented is the printed basis X₀…X₃",
            &format!("{SRC} eq. (1)"),
            Verdict::Proved,
            all_same(&x, &printed_basis(&a)),
            "symbolic in α, s, c".into(),
        ),
        Claim::identity(
            "② partition of unity: Σ Xᵢ(t) = 1 for every α and t",
            &format!("{SRC} §1 property ②"),
            Verdict::Proved,
            &x.iter().fold(Poly::zero(), |acc, p| acc + p),
            &int(1),
            "symbolic in α, s, c (holds even without s² + c² = 1)",
        ),
        Claim::check(
            "factorization: X₀ = (1−s)(1+(1−α)s), X₁ = αs(1−s), X₂ = αc(1−c), X₃ = (1−c)(1+(1−α)c)",
            "ours",
            Verdict::Proved,
            all_same(&x, &factored(&a)),
            "normal form modulo s² + c² = 1".into(),
        ),
        Claim::check(
            "① non-negativity: Xᵢ(t) ≥ 0 on [0, π/2] for α ∈ (0, 2]",
            &format!("{SRC} Definition 1 property ①"),
            Verdict::Proved,
            all_same(&x, &factored(&a)) && at_zero == int(1) && at_one == int(2) - a.clone(),
            "by the factorization: s, c, 1−s, 1−c ∈ [0, 1] on [0, π/2], and the linear factor \
             1 + (1−α)x is 1 at x = 0 and 2 − α ≥ 0 at x = 1"
                .into(),
        ),
        Claim::check(
            "sharp range: all Xᵢ ≥ 0 on [0, π/2] iff α ∈ [0, 2] (the paper's (0, 2] misses α = 0)",
            "ours",
            Verdict::Proved,
            x0_a3 == ratio(-3, 25)
                && x1_am1 == ratio(-4, 25)
                && all_same(&at0, &[c.pow(2), Poly::zero(), Poly::zero(), s.pow(2)])
                && at_one == int(2) - a.clone(),
            format!(
                "α > 2: X₀ = (1−s)(1+(1−α)s) < 0 for s ∈ (1/(α−1), 1), e.g. α = 3, τ = 1/2: X₀ = {x0_a3}; \
                 α < 0: X₁ = αs(1−s) < 0 inside, e.g. α = −1, τ = 1/2: X₁ = {x1_am1}; α = 0: (c², 0, 0, s²) ≥ 0"
            ),
        ),
        Claim::check(
            "③ end values: X(0) = (1, 0, 0, 0), X(π/2) = (0, 0, 0, 1)",
            &format!("{SRC} Definition 1 property ③"),
            Verdict::Proved,
            all_same(&end(TrigParam::start()), &[int(1), int(0), int(0), int(0)])
                && all_same(&end(TrigParam::end()), &[int(0), int(0), int(0), int(1)]),
            "symbolic in α".into(),
        ),
        Claim::check(
            "④ unimodality: each Xᵢ has one maximum on [0, π/2] (α ∈ (0, 2])",
            &format!("{SRC} Definition 1 property ④"),
            Verdict::Proved,
 all_same(&d1, &d_factored) && unimodal_factors_ok(&a),
            "X₀' = c(2(α−1)s − α) ≤ 0, X₁' = αc(1−2s), X₂' = αs(2c−1), X₃' = s(α + 2(1−α)c) ≥ 0: \
             maxima at t = 0, π/6, π/3, π/2 (linear factors checked at s, c ∈ {0, 1})"
                .into(),
        ),
        Claim::check(
            "linear independence: the coefficient matrix of X₀…X₃ on 1, s, c, s² has determinant α²",
            "ours",
            Verdict::Proved,
            no_sc && det4(&m) == a.pow(2),
            "so the basis is a basis iff α ≠ 0".into(),
        ),
        Claim::check(
            "symmetry: Xᵢ(π/2 − t) = X₃₋ᵢ(t)",
            "ours",
            Verdict::Proved,
            all_same(&rev, &[x[3].clone(), x[2].clone(), x[1].clone(), x[0].clone()]),
            "sin and cos swap; so reversing the control points reverses the curve".into(),
        ),
        Claim::check(
            "Theorem 1: dX₀/dα = −sin t + sin²t ≤ 0, dX₁/dα = sin t − sin²t ≥ 0, \
             dX₂/dα = −1 + cos t + sin²t ≥ 0, dX₃/dα = 1 − cos t − sin²t ≤ 0",
            &format!("{SRC} §2 Theorem 1 proof"),
            Verdict::Proved,
            all_same(&d_alpha, &printed_d_alpha) && all_same(&d_alpha, &signed_d_alpha),
            "∂/∂α symbolically; signs from −s(1−s), s(1−s), c(1−c), −c(1−c) with s, c ∈ [0, 1]".into(),
        ),
    ]
}

/// The linear factors of X₀' and X₃' at x ∈ {0, 1}: `2(α−1)x − α` is −α
/// and α − 2 (≤ 0), `α + 2(1−α)x` is α and 2 − α (≥ 0), for α ∈ (0, 2].
fn unimodal_factors_ok(a: &Poly) -> bool {
    let x = Poly::var("x");
    let f0 = int(2) * (a.clone() - int(1)) * &x - a.clone();
    let f3 = a.clone() + int(2) * (int(1) - a.clone()) * &x;
    let at = |f: &Poly, k: i64| f.subst_rational("x", &ratio(k, 1));
    at(&f0, 0) == -a.clone()
        && at(&f0, 1) == a.clone() - int(2)
        && at(&f3, 0) == a.clone()
        && at(&f3, 1) == int(2) - a.clone()
}

fn curve_claims() -> Vec<Claim> {
    let a = alpha();
    let pts: Vec<Vec<Poly>> = Poly::vars("p", 4).into_iter().map(|p| vec![p]).collect();
    let p = |i: usize| pts[i][0].clone();
    let curve = TrigCurve::new(pts.clone(), a.clone()).expect("four points");
    let at = sym_param("");
    let (s, c) = (Poly::var("s"), Poly::var("c"));
    let d1 = curve.derivative(1, &at)[0].clone();
    let printed_d1 = p(0) * (-a.clone() * &c + int(2) * (a.clone() - int(1)) * &s * &c)
        + p(1) * (a.clone() * &c - int(2) * a.clone() * &s * &c)
        + p(2) * (-a.clone() * &s + int(2) * a.clone() * &s * &c)
        + p(3) * (a.clone() * &s + int(2) * (int(1) - a.clone()) * &s * &c);
    let value = curve.eval(&at)[0].clone();
    let derivation =
        |f: &Poly| nf(&(c.clone() * f.derivative("s") - s.clone() * f.derivative("c")));
    let mut by_derivation = value.clone();
    let mut derivatives_agree = true;
    for k in 1..=4 {
        by_derivation = derivation(&by_derivation);
        derivatives_agree &= same(&curve.derivative(k, &at)[0], &by_derivation);
    }
    let chord = TrigCurve::new(pts.clone(), Poly::zero())
        .expect("four points")
        .eval(&at)[0]
        .clone();
    // Representation: α = 1 with (0, 2, 6, 3) and α = 2 with (0, 1, 9/2, 3).
    let one_d = |v: [BigRational; 4]| v.into_iter().map(|x| vec![x]).collect::<Vec<_>>();
    let c1 = TrigCurve::new(one_d([0, 2, 6, 3].map(|k| ratio(k, 1))), ratio(1, 1)).expect("4");
    let c2 = TrigCurve::new(
        one_d([ratio(0, 1), ratio(1, 1), ratio(9, 2), ratio(3, 1)]),
        ratio(2, 1),
    )
    .expect("4");
    vec![
        Claim::check(
            "curve property 1): p(0) = P₀, p(π/2) = P₃, p'(0) = α(P₁ − P₀), p'(π/2) = α(P₃ − P₂)",
            &format!("{SRC} Definition 2 property 1)"),
            Verdict::Proved,
            curve.eval(&TrigParam::start())[0] == p(0)
                && curve.eval(&TrigParam::end())[0] == p(3)
                && curve.derivative(1, &TrigParam::start())[0] == a.clone() * (p(1) - p(0))
                && curve.derivative(1, &TrigParam::end())[0] == a.clone() * (p(3) - p(2)),
            "symbolic in α and P₀…P₃; so the end tangents are P₀P₁ and P₂P₃ when α ≠ 0".into(),
        ),
        Claim::check(
            "the printed p'(t) = P₀[−α cos t + 2(α−1) sin t cos t] + P₁[α cos t − 2α sin t cos t] + \
             P₂[−α sin t + 2α sin t cos t] + P₃[α sin t + 2(1−α) sin t cos t]",
            &format!("{SRC} Definition 2, proof of 1)"),
            Verdict::Proved,
            same(&d1, &printed_d1),
            "normal form modulo s² + c² = 1".into(),
        ),
        Claim::check(
            "our derivatives of order 1…4 equal the derivation d/dt = c ∂/∂s − s ∂/∂c",
            "ours",
            Verdict::Proved,
            derivatives_agree,
            "symbolic in α, P, s, c".into(),
        ),
        Claim::check(
            "curve property 6) at α = 0 the curve lies on the chord: p = cos²t P₀ + sin²t P₃",
            &format!("{SRC} Definition 2 property 6)"),
            Verdict::Proved,
            same(&chord, &(c.pow(2) * p(0) + s.pow(2) * p(3))),
            "the limit α → 0 of the approximation property".into(),
        ),
        Claim::check(
            "property 4) representation is unique: equal curves/surfaces have equal control points and shape parameters",
            &format!("{SRC} Definition 3 property 4)"),
            Verdict::Refuted,
            c1.functions() != c2.functions(),
            "counterexample: α = 1 with P = (0, 2, 6, 3) and α = 2 with P = (0, 1, 9/2, 3) are the same \
             function of t (all coefficients on 1, s, c, s², sc agree); the tensor surface \
             (Σ Xᵢ(u)xᵢ, Σ Xⱼ(v)yⱼ) inherits it. Corrected: for α fixed and ≠ 0 the control points are \
             unique (det = α²); in general p = P₀c² + P₃s² + α(P₁−P₀)s(1−s) + α(P₂−P₃)c(1−c) determines \
             only P₀, P₃, α(P₁−P₀), α(P₂−P₃)"
                .into(),
        ),
    ]
}

fn surface_claims() -> Vec<Claim> {
    let (a1, a2) = (Poly::var("alpha1"), Poly::var("alpha2"));
    let s = sym_rect("p", &a1, &a2);
    let p = |i: usize, j: usize| s.points()[i][j][0].clone();
    let (o, e) = (TrigParam::<Poly>::start(), TrigParam::<Poly>::end());
    let (u, v) = (sym_param("u"), sym_param("v"));
    let corner = |ku: usize, kv: usize, x: &TrigParam<Poly>, y: &TrigParam<Poly>| {
        s.partial(ku, kv, x, y)[0].clone()
    };
    let corners_ok = corner(0, 0, &o, &o) == p(0, 0)
        && corner(0, 0, &o, &e) == p(0, 3)
        && corner(0, 0, &e, &o) == p(3, 0)
        && corner(0, 0, &e, &e) == p(3, 3);
    let tangents_ok = corner(1, 0, &o, &o) == a1.clone() * (p(1, 0) - p(0, 0))
        && corner(0, 1, &o, &o) == a2.clone() * (p(0, 1) - p(0, 0))
        && corner(1, 0, &o, &e) == a1.clone() * (p(1, 3) - p(0, 3))
        && corner(0, 1, &o, &e) == a2.clone() * (p(0, 3) - p(0, 2))
        && corner(1, 0, &e, &o) == a1.clone() * (p(3, 0) - p(2, 0))
        && corner(0, 1, &e, &o) == a2.clone() * (p(3, 1) - p(3, 0))
        && corner(1, 0, &e, &e) == a1.clone() * (p(3, 3) - p(2, 3))
        && corner(0, 1, &e, &e) == a2.clone() * (p(3, 3) - p(3, 2));
    let curve = |pts: Vec<Poly>, a: &Poly, at: &TrigParam<Poly>| {
        TrigCurve::new(pts.into_iter().map(|x| vec![x]).collect(), a.clone())
            .expect("four points")
            .eval(at)[0]
            .clone()
    };
    let boundaries = [
        (
            s.eval(&u, &o)[0].clone(),
            curve((0..4).map(|i| p(i, 0)).collect(), &a1, &u),
        ),
        (
            s.eval(&u, &e)[0].clone(),
            curve((0..4).map(|i| p(i, 3)).collect(), &a1, &u),
        ),
        (
            s.eval(&o, &v)[0].clone(),
            curve((0..4).map(|j| p(0, j)).collect(), &a2, &v),
        ),
        (
            s.eval(&e, &v)[0].clone(),
            curve((0..4).map(|j| p(3, j)).collect(), &a2, &v),
        ),
    ];
    let boundaries_ok = boundaries.iter().all(|(x, y)| same(x, y));
    let independent = boundaries[0].0.derivative("alpha2").is_zero()
        && boundaries[1].0.derivative("alpha2").is_zero()
        && boundaries[2].0.derivative("alpha1").is_zero()
        && boundaries[3].0.derivative("alpha1").is_zero();
    let zero = sym_rect("p", &Poly::zero(), &Poly::zero());
    let (su, cu, sv, cv) = (u.sin.clone(), u.cos.clone(), v.sin.clone(), v.cos.clone());
    let bilinear = cu.pow(2) * cv.pow(2) * p(0, 0)
        + cu.pow(2) * sv.pow(2) * p(0, 3)
        + su.pow(2) * cv.pow(2) * p(3, 0)
        + su.pow(2) * sv.pow(2) * p(3, 3);
    let at_zero = zero.eval(&u, &v)[0].clone();
    let inner_free = (0..4).all(|i| {
        (0..4).all(|j| {
            (i % 3 == 0 && j % 3 == 0) || at_zero.derivative(&format!("p{i}{j}")).is_zero()
        })
    });
    vec![
        Claim::check(
            "surface property 1): S interpolates P₀₀, P₀₃, P₃₀, P₃₃ at the corners",
            &format!("{SRC} Definition 3 property 1)"),
            Verdict::Proved,
            corners_ok,
            "symbolic in α₁, α₂ and the 16 points".into(),
        ),
        Claim::check(
            "surface property 1): the corner tangent planes are P₀₀P₀₁P₁₀, P₀₃P₀₂P₁₃, P₃₀P₂₀P₃₁, P₃₃P₂₃P₃₂",
            &format!("{SRC} Definition 3 property 1)"),
            Verdict::Proved,
            tangents_ok,
            "S_u(0,0) = α₁(P₁₀−P₀₀), S_v(0,0) = α₂(P₀₁−P₀₀), and likewise at the other corners \
             (S_u(0,π/2) = α₁(P₁₃−P₀₃), S_v(0,π/2) = α₂(P₀₃−P₀₂), …); planes as printed when α₁α₂ ≠ 0"
                .into(),
        ),
        Claim::check(
            "surface property 2): the boundaries are the trig curves on P_{i0}, P_{i3} (α₁) and P_{0j}, P_{3j} (α₂)",
            &format!("{SRC} Definition 3 property 2)"),
            Verdict::Proved,
            boundaries_ok,
            "symbolic in u or v, α₁, α₂ and the points".into(),
        ),
        Claim::check(
            "Theorem 2: S(u,0), S(u,π/2) depend on α₁ only and S(0,v), S(π/2,v) on α₂ only",
            &format!("{SRC} §2 Theorem 2"),
            Verdict::Proved,
            independent,
            "∂/∂α₂ of S(u,0), S(u,π/2) and ∂/∂α₁ of S(0,v), S(π/2,v) vanish identically".into(),
        ),
        Claim::check(
            "special case α₁ = α₂ = 0: S is the cubic Bézier trigonometric (triangular-domain) surface",
            &format!("{SRC} Definition 3 property 5)"),
            Verdict::Refuted,
            !(same(&at_zero, &bilinear) && inner_free),
            "at α = 0 the basis is (cos²t, 0, 0, sin²t) (det α² = 0): S(u,v;0,0) = \
             cos²u cos²v P₀₀ + cos²u sin²v P₀₃ + sin²u cos²v P₃₀ + sin²u sin²v P₃₃, the bilinear \
             patch of the four corners in (sin²u, sin²v), independent of the other 12 points; the \
             paper's own domain α ∈ (0, 2] excludes it"
                .into(),
        ),
    ]
}
