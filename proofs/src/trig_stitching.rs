//! Source 002 (Sun & Shi) §3–§5: cross-boundary derivatives (7)/(10), the G¹
//! stitching Theorems 3–5 with their corollaries, the stitching algorithm
//! of §4 and the bowl of §5.
//!
//! Symbolic in the shape parameters, μ, the control points (1-D symbols;
//! coordinates are independent) and `(s, c)` modulo `s² + c² = 1`; printed
//! rules are refuted by exact rational counterexamples run through the
//! exact G¹ checker [`trig_g1_factor`].

use super::trig_basis::{det4, int, nf, same, sym_param};
use super::{Claim, Verdict};
use exact_bezier::algebra::ratio;
use exact_bezier::algebra::Poly;
use exact_bezier::trig::basis::TrigParam;
use exact_bezier::trig::bowl::trig_bowl;
use exact_bezier::trig::curve::TrigCurve;
use exact_bezier::trig::stitch::{
    cross, trig_g0, trig_g1_factor, trig_tangent_continuous, TrigJoin,
};
use exact_bezier::trig::surface::TrigRect;
use exact_bezier::Tolerance;
use num_rational::BigRational;
use num_traits::Zero;

const SRC: &str = "002 Sun & Shi";
type Q = BigRational;
const EXACT: Tolerance = Tolerance::EXACT;

fn var(name: &str) -> Poly {
    Poly::var(name)
}

/// A symbolic 1-D net `{name}{i}{j}`, with some entries overridden.
fn net(
    name: &str,
    alpha: [Poly; 2],
    over: impl Fn(usize, usize) -> Option<Poly>,
) -> TrigRect<Poly> {
    let pts = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| vec![over(i, j).unwrap_or_else(|| var(&format!("{name}{i}{j}")))])
                .collect()
        })
        .collect();
    TrigRect::new(pts, alpha).expect("4 × 4 net")
}

/// `Σₖ Xₖ(t; α) fₖ` at the symbolic `t` (1-D).
fn trig_sum(f: impl Fn(usize) -> Poly, alpha: &Poly, at: &TrigParam<Poly>) -> Poly {
    TrigCurve::new((0..4).map(|k| vec![f(k)]).collect(), alpha.clone())
        .expect("four points")
        .eval(at)[0]
        .clone()
}

/// An exact 3-D net `(i, j, (i·j + i) mod 4) + offset`.
fn exact_net(offset: i64) -> Vec<Vec<Vec<Q>>> {
    (0..4)
        .map(|i| {
            (0..4)
                .map(|j| vec![ratio(i, 1), ratio(j + offset, 1), ratio((i * j + i) % 4, 1)])
                .collect()
        })
        .collect()
}

/// The neighbour by the paper's printed rule (Theorem 3 2), canonical u–u):
/// `Qᵢ₀ = Pᵢ₃`, `Qᵢ₁ = Pᵢ₃ + (2 + α₂)/(μ (2 + λ₂)) (Pᵢ₃ − Pᵢ₂)`, shape
/// `(α₁, λ₂)`; the last two columns are a shifted copy.
fn printed_rule(s1: &TrigRect<Q>, a2: &Q, l2: &Q, mu: &Q) -> TrigRect<Q> {
    let two = ratio::<Q>(2, 1);
    let k = (two.clone() + a2) / (mu.clone() * (two + l2));
    let rest = exact_net(5);
    let pts = (0..4)
        .map(|i| {
            let p3 = &s1.points()[i][3];
            let p2 = &s1.points()[i][2];
            let q1 = p3
                .iter()
                .zip(p2)
                .map(|(a, b)| a.clone() + &(k.clone() * (a.clone() - b)))
                .collect();
            vec![p3.clone(), q1, rest[i][2].clone(), rest[i][3].clone()]
        })
        .collect();
    TrigRect::new(pts, [s1.alpha()[0].clone(), l2.clone()]).expect("4 × 4")
}

/// Every claim of §3–§5.
pub fn claims() -> Vec<Claim> {
    let mut out = derivative_claims();
    out.extend(g0_claims());
    out.extend(g1_claims());
    out.extend(bowl_claims());
    out
}

fn derivative_claims() -> Vec<Claim> {
    let (a1, a2, l1, l2) = (var("alpha1"), var("alpha2"), var("lambda1"), var("lambda2"));
    let s1 = net("p", [a1.clone(), a2.clone()], |_, _| None);
    let s2 = net("q", [l1.clone(), l2.clone()], |_, _| None);
    let p = |i: usize, j: usize| s1.points()[i][j][0].clone();
    let q = |i: usize, j: usize| s2.points()[i][j][0].clone();
    let (u, v) = (sym_param("u"), sym_param("v"));
    let (o, e) = (TrigParam::start(), TrigParam::end());
    let sum_u = trig_sum(|i| p(i, 3) - p(i, 2), &a1, &u);
    let sum_v = trig_sum(|j| p(3, j) - p(2, j), &a2, &v);
    let dv = s1.partial(0, 1, &u, &e)[0].clone();
    let du = s1.partial(1, 0, &e, &v)[0].clone();
    let dv2_ok = same(
        &s2.partial(0, 1, &u, &o)[0],
        &(l2.clone() * trig_sum(|i| q(i, 1) - q(i, 0), &l1, &u)),
    );
    let du2_ok = same(
        &s2.partial(1, 0, &o, &v)[0],
        &(l1.clone() * trig_sum(|j| q(1, j) - q(0, j), &l2, &v)),
    );
    let four_plus = |a: &Poly| int(4) + int(2) * a.clone();
    // Exact counterexample: Pᵢⱼ = j (1-D), α₁ = α₂ = 1, at u = 0.
    let ce = TrigRect::new(
        (0..4)
            .map(|_| (0..4).map(|j| vec![ratio::<Q>(j, 1)]).collect())
            .collect(),
        [ratio(1, 1), ratio(1, 1)],
    )
    .expect("4 × 4");
    let ce_dv = ce.partial(0, 1, &TrigParam::start(), &TrigParam::end())[0].clone();
    vec![
        Claim::check(
            "(7) ∂S₁/∂v(u, π/2) = (4 + 2α₂) Σ Xᵢ(u; α₁)(Pᵢ₃ − Pᵢ₂), ∂S₂/∂v(u, 0) = (4 + 2λ₂) Σ Xᵢ(u; λ₁)(Qᵢ₁ − Qᵢ₀)",
            &format!("{SRC} §3 eq. (7)"),
            Verdict::Refuted,
            same(&dv, &(four_plus(&a2) * &sum_u)),
            format!(
                "the factor is α₂ (resp. λ₂), since X'(π/2) = (0, 0, −α, α) and X'(0) = (−α, α, 0, 0); \
                 counterexample Pᵢⱼ = j, α₁ = α₂ = 1, u = 0: ∂S/∂v = {ce_dv}, printed 6"
            ),
        ),
        Claim::check(
            "corrected (7): ∂S₁/∂v(u, π/2) = α₂ Σ Xᵢ(u; α₁)(Pᵢ₃ − Pᵢ₂) and ∂S₂/∂v(u, 0) = λ₂ Σ Xᵢ(u; λ₁)(Qᵢ₁ − Qᵢ₀)",
            "ours",
            Verdict::Proved,
            same(&dv, &(a2.clone() * &sum_u)) && dv2_ok && ce_dv == ratio(1, 1),
            "symbolic in α₁, α₂, λ₁, λ₂, the 32 points and u".into(),
        ),
        Claim::check(
            "(10) ∂S₁/∂u(π/2, v) = (4 + 2α₁) Σ Xⱼ(v; α₂)(P₃ⱼ − P₂ⱼ), ∂S₂/∂u(0, v) = (4 + 2λ₁) Σ Xⱼ(v; λ₂)(Q₁ⱼ − Q₀ⱼ)",
            &format!("{SRC} §3 eq. (10)"),
            Verdict::Refuted,
            same(&du, &(four_plus(&a1) * &sum_v)),
            "the factor is α₁ (resp. λ₁); the transpose of the (7) counterexample".into(),
        ),
        Claim::check(
            "corrected (10): ∂S₁/∂u(π/2, v) = α₁ Σ Xⱼ(v; α₂)(P₃ⱼ − P₂ⱼ) and ∂S₂/∂u(0, v) = λ₁ Σ Xⱼ(v; λ₂)(Q₁ⱼ − Q₀ⱼ)",
            "ours",
            Verdict::Proved,
            same(&du, &(a1.clone() * &sum_v)) && du2_ok,
            "symbolic".into(),
        ),
    ]
}

fn g0_claims() -> Vec<Claim> {
    let (a1, a2, l2) = (var("alpha1"), var("alpha2"), var("lambda2"));
    let s1 = net("p", [a1.clone(), a2.clone()], |_, _| None);
    let p = |i: usize, j: usize| s1.points()[i][j][0].clone();
    let (u, o, e) = (sym_param("u"), TrigParam::start(), TrigParam::end());
    let s2_uu = net("q", [a1.clone(), l2.clone()], |i, j| {
        (j == 0).then(|| p(i, 3))
    });
    let s2_vv = net("q", [var("lambda1"), a2.clone()], |i, j| {
        (i == 0).then(|| p(3, j))
    });
    let s2_uv = net("q", [var("lambda1"), a1.clone()], |i, j| {
        (i == 0).then(|| p(j, 3))
    });
    let suff = same(&s1.eval(&u, &e)[0], &s2_uu.eval(&u, &o)[0])
        && same(&s1.eval(&e, &u)[0], &s2_vv.eval(&o, &u)[0])
        && same(&s1.eval(&u, &e)[0], &s2_uv.eval(&o, &u)[0]);
    // Exact counterexample to necessity: the same edge with α = 1 and α = 2.
    let with_edge = |offset: i64, j: usize, x: [Q; 4], z: [Q; 4], a: i64| {
        let mut pts = exact_net(offset);
        for i in 0..4 {
            pts[i][j] = vec![x[i].clone(), ratio(3, 1), z[i].clone()];
        }
        TrigRect::new(pts, [ratio(a, 1), ratio(1, 1)]).expect("4 × 4")
    };
    let ints = |v: [i64; 4]| v.map(|k| ratio::<Q>(k, 1));
    let ce1 = with_edge(0, 3, ints([0, 1, 2, 3]), ints([0, 2, 6, 3]), 1);
    let ce2 = with_edge(
        3,
        0,
        [ratio(0, 1), ratio(1, 2), ratio(5, 2), ratio(3, 1)],
        [ratio(0, 1), ratio(1, 1), ratio(9, 2), ratio(3, 1)],
        2,
    );
    let necessity = !(trig_g0(&ce1, &ce2, TrigJoin::UU, EXACT) && ce1.alpha()[0] != ce2.alpha()[0]);
    // Corrected: p = P₀c² + P₃s² + α(P₁−P₀)s(1−s) + α(P₂−P₃)c(1−c), four independent functions.
    let pts = Poly::vars("x", 4);
    let alpha = var("alpha");
    let at = sym_param("");
    let (s, c) = (at.sin.clone(), at.cos.clone());
    let curve = trig_sum(|k| pts[k].clone(), &alpha, &at);
    let normal = pts[0].clone() * c.pow(2)
        + pts[3].clone() * s.pow(2)
        + alpha.clone() * (pts[1].clone() - &pts[0]) * &s * (int(1) - s.clone())
        + alpha.clone() * (pts[2].clone() - &pts[3]) * &c * (int(1) - c.clone());
    let funcs = [
        c.pow(2),
        s.pow(2),
        s.clone() - s.pow(2),
        c.clone() - c.pow(2),
    ];
    let coeff = |f: &Poly, k: usize| {
        let f = nf(f);
        let (s_pow, c_pow) = [(0, 0), (1, 0), (0, 1), (2, 0)][k];
        f.coeff_of("s", s_pow).coeff_of("c", c_pow)
    };
    let m: [[Poly; 4]; 4] = std::array::from_fn(|r| std::array::from_fn(|k| coeff(&funcs[r], k)));
    let independent = det4(&m);
    let (l1_, l2_) = (var("lambda1"), var("lambda2"));
    let corollary = s1.eval(&u, &e)[0].derivative("alpha2").is_zero()
        && s1.eval(&e, &u)[0].derivative("alpha1").is_zero()
        && net("q", [l1_.clone(), l2_.clone()], |_, _| None).eval(&u, &o)[0]
            .derivative("lambda2")
            .is_zero()
        && net("q", [l1_, l2_], |_, _| None).eval(&o, &u)[0]
            .derivative("lambda1")
            .is_zero();
    vec![
        Claim::check(
            "Theorems 3–5 1) sufficiency: Pᵢ₃ = Qᵢ₀, α₁ = λ₁ (u–u); P₃ⱼ = Q₀ⱼ, α₂ = λ₂ (v–v); \
             Pₖ₃ = Q₀ₖ, α₁ = λ₂ (u–v) give a common boundary",
            &format!("{SRC} §3 Theorems 3–5 condition 1)"),
            Verdict::Proved,
            suff,
            "symbolic. Misprints: the proof of Theorem 3 writes S₁(u, 0) = S₂(u, 0) for S₁(u, π/2) = \
             S₂(u, 0), and Theorem 5 writes Pᵢ₃ = Q₀ⱼ (i, j = 0…3) for Pₖ₃ = Q₀ₖ (k = 0…3)"
                .into(),
        ),
        Claim::check(
            "Theorems 3–5 1) necessity: a common boundary forces Pᵢ₃ = Qᵢ₀ and α₁ = λ₁ (likewise v–v, u–v)",
            &format!("{SRC} §3 Theorems 3–5 (\"充要条件\")"),
            Verdict::Refuted,
            necessity,
            "counterexample (u–u, exact): edge x = (0, 1, 2, 3), z = (0, 2, 6, 3) with α₁ = 1 and \
             x = (0, 1/2, 5/2, 3), z = (0, 1, 9/2, 3) with λ₁ = 2 (y = 3) are the same curve; trig_g0 = true"
                .into(),
        ),
        Claim::check(
            "corrected G⁰ (u–u): S₁(u, π/2) ≡ S₂(u, 0) iff P₀₃ = Q₀₀, P₃₃ = Q₃₀, α₁(P₁₃ − P₀₃) = λ₁(Q₁₀ − Q₀₀), \
             α₁(P₂₃ − P₃₃) = λ₁(Q₂₀ − Q₃₀)",
            "ours",
            Verdict::Proved,
            same(&curve, &normal) && !independent.is_zero() && independent.as_constant().is_some(),
            format!(
                "p(t) = P₀c² + P₃s² + α(P₁−P₀)s(1−s) + α(P₂−P₃)c(1−c) and c², s², s−s², c−c² are \
                 independent (determinant {independent} on 1, s, c, s²); v–v and u–v by exchanging u, v"
            ),
        ),
        Claim::check(
            "Corollaries 1–3 1): with a common boundary, changing only α₂, λ₂ (u–u), α₁, λ₁ (v–v), α₂, λ₁ (u–v) keeps G⁰",
            &format!("{SRC} §3 Corollaries 1–3"),
            Verdict::Proved,
            corollary,
            "the edge curves do not contain those parameters (∂/∂α vanishes)".into(),
        ),
    ]
}

/// The factor realised by the printed rule of `join` with α = (1, 1),
/// λ = (2, 2) (for u–v: λ = (2, 1) so that λ₂ = α₁), μ = 1.
fn printed_factor(join: TrigJoin) -> Option<Q> {
    let one = ratio::<Q>(1, 1);
    let two = ratio::<Q>(2, 1);
    let s1 = TrigRect::new(exact_net(0), [one.clone(), one.clone()]).expect("4 × 4");
    match join {
        TrigJoin::UU => {
            let s2 = printed_rule(&s1, &one, &two, &one);
            trig_g1_factor(&s1, &s2, join, EXACT)
        }
        TrigJoin::VV => {
            let s2 = printed_rule(&s1.swap_uv(), &one, &two, &one).swap_uv();
            trig_g1_factor(&s1, &s2, join, EXACT)
        }
        TrigJoin::UV => {
            // Theorem 5: (Pₖ₃ − Pₖ₂)/(2 + λ₂) = μ (Q₁ₖ − Q₀ₖ)/(2 + α₁) with λ₂ = α₁ = 1, λ₁ = 2.
            let t = printed_rule(&s1, &one, &one, &one);
            let s2 = TrigRect::new(t.points().to_vec(), [one.clone(), two]).expect("4 × 4");
            trig_g1_factor(&s1, &s2.swap_uv(), join, EXACT)
        }
    }
}

fn g1_claims() -> Vec<Claim> {
    let (a1, a2, l1, l2, mu) = (
        var("alpha1"),
        var("alpha2"),
        var("lambda1"),
        var("lambda2"),
        var("mu"),
    );
    let d = |k: usize| var(&format!("d{k}"));
    let p3 = |k: usize| var(&format!("p{k}3"));
    let (u, o, e) = (
        sym_param("u"),
        TrigParam::<Poly>::start(),
        TrigParam::<Poly>::end(),
    );
    // u–u: α₂ ΔPᵢ = μ λ₂ ΔQᵢ with ΔPᵢ = μλ₂dᵢ, ΔQᵢ = α₂dᵢ.
    let s1 = net("p", [a1.clone(), a2.clone()], |i, j| {
        (j == 2).then(|| p3(i) - mu.clone() * &l2 * d(i))
    });
    let s2 = net("q", [a1.clone(), l2.clone()], |i, j| match j {
        0 => Some(p3(i)),
        1 => Some(p3(i) + a2.clone() * d(i)),
        _ => None,
    });
    let uu = same(
        &s1.partial(0, 1, &u, &e)[0],
        &(mu.clone() * &s2.partial(0, 1, &u, &o)[0]),
    );
    // v–v: α₁ ΔP = μ λ₁ ΔQ along u = π/2 / u = 0.
    let p3j = |k: usize| var(&format!("p3{k}"));
    let t1 = net("p", [a1.clone(), a2.clone()], |i, j| {
        (i == 2).then(|| p3j(j) - mu.clone() * &l1 * d(j))
    });
    let t2 = net("q", [l1.clone(), a2.clone()], |i, j| match i {
        0 => Some(p3j(j)),
        1 => Some(p3j(j) + a1.clone() * d(j)),
        _ => None,
    });
    let vv = same(
        &t1.partial(1, 0, &e, &u)[0],
        &(mu.clone() * &t2.partial(1, 0, &o, &u)[0]),
    );
    // u–v: α₂ (Pₖ₃ − Pₖ₂) = μ λ₁ (Q₁ₖ − Q₀ₖ), λ₂ = α₁.
    let r1 = net("p", [a1.clone(), a2.clone()], |i, j| {
        (j == 2).then(|| p3(i) - mu.clone() * &l1 * d(i))
    });
    let r2 = net("q", [l1.clone(), a1.clone()], |i, j| match i {
        0 => Some(p3(j)),
        1 => Some(p3(j) + a2.clone() * d(j)),
        _ => None,
    });
    let uv = same(
        &r1.partial(0, 1, &u, &e)[0],
        &(mu.clone() * &r2.partial(1, 0, &o, &u)[0]),
    );
    let factors = [TrigJoin::UU, TrigJoin::VV, TrigJoin::UV].map(printed_factor);
    let show = |f: &Option<Q>| f.as_ref().map_or("none".to_string(), |q| q.to_string());
    vec![
        Claim::check(
            "corrected G¹ conditions (in the sense of (6), given G⁰ with α₁ = λ₁ etc.): u–u α₂(Pᵢ₃ − Pᵢ₂) = μλ₂(Qᵢ₁ − Qᵢ₀); \
             v–v α₁(P₃ⱼ − P₂ⱼ) = μλ₁(Q₁ⱼ − Q₀ⱼ); u–v α₂(Pₖ₃ − Pₖ₂) = μλ₁(Q₁ₖ − Q₀ₖ)",
            "ours",
            Verdict::Proved,
            uu && vv && uv,
            "symbolic in α₁, α₂, λ₁, λ₂, μ and the points: the cross-boundary derivatives satisfy \
             ∂S₁ = μ ∂S₂ identically; the converse holds because the basis is independent (det α² ≠ 0)"
                .into(),
        ),
        Claim::check(
            "Theorem 3 2): G¹ with factor μ of (6) iff (Pᵢ₃ − Pᵢ₂)/(2 + λ₂) = μ(Qᵢ₁ − Qᵢ₀)/(2 + α₂)",
            &format!("{SRC} §3 Theorem 3 condition 2)"),
            Verdict::Refuted,
            factors[0] == Some(ratio(1, 1)),
            format!(
                "α₁ = α₂ = 1, λ₂ = 2, μ = 1: the printed rule gives ∂S₁/∂v = μ'∂S₂/∂v with μ' = {} (exact checker); \
                 in general μ' = μα₂(2+λ₂)/(λ₂(2+α₂)), = μ only when α₂ = λ₂. As 'some μ > 0 exists' the printed \
                 condition is equivalent to the corrected one (both say ΔQᵢ = kΔPᵢ, k > 0)",
                show(&factors[0])
            ),
        ),
        Claim::check(
            "Theorem 4 2): G¹ with factor μ iff (P₃ⱼ − P₂ⱼ)/(2 + λ₁) = μ(Q₁ⱼ − Q₀ⱼ)/(2 + α₁)",
            &format!("{SRC} §3 Theorem 4 condition 2)"),
            Verdict::Refuted,
            factors[1] == Some(ratio(1, 1)),
            format!("α₁ = α₂ = 1, λ₁ = 2, μ = 1: realised factor {} (the transpose of Theorem 3)", show(&factors[1])),
        ),
        Claim::check(
            "Theorem 5 2): G¹ with factor μ iff (Pᵢ₃ − Pᵢ₂)/(2 + λ₂) = μ(Q₁ⱼ − Q₀ⱼ)/(2 + α₁)",
            &format!("{SRC} §3 Theorem 5 condition 2)"),
            Verdict::Refuted,
            factors[2] == Some(ratio(1, 1)),
            format!(
                "α₁ = α₂ = λ₂ = 1, λ₁ = 2, μ = 1: realised factor {} = μα₂/λ₁; the printed rule uses λ₂, α₁ \
                 where the cross derivatives carry α₂ (of S₁) and λ₁ (of S₂)",
                show(&factors[2])
            ),
        ),
        faux_claim(),
    ]
}

/// (5) ⇒ (6) fails: two planar surfaces with tangent-plane continuity but
/// no constant μ.
fn faux_claim() -> Claim {
    let one = ratio::<Q>(1, 1);
    let p = |x: i64, y: i64| vec![ratio::<Q>(x, 1), ratio(y, 1), ratio(0, 1)];
    let s1 = TrigRect::new(
        (0..4).map(|i| (0..4).map(|j| p(i, j)).collect()).collect(),
        [one.clone(), one.clone()],
    )
    .expect("4 × 4");
    let s2 = TrigRect::new(
        (0..4)
            .map(|i| vec![p(i, 3), p(i, 4 + i), p(i, 5 + i), p(i, 6 + i)])
            .collect(),
        [one.clone(), one],
    )
    .expect("4 × 4");
    let factor = trig_g1_factor(&s1, &s2, TrigJoin::UU, EXACT);
    let g0 = trig_g0(&s1, &s2, TrigJoin::UU, EXACT);
    let lift = |s: &TrigRect<Q>| s.map(|q| Poly::constant(q.clone()));
    let (a, b) = (lift(&s1), lift(&s2));
    let u = sym_param("u");
    let (o, e) = (TrigParam::start(), TrigParam::end());
    let n1 = cross(&a.partial(1, 0, &u, &e), &a.partial(0, 1, &u, &e));
    let n2 = cross(&b.partial(1, 0, &u, &o), &b.partial(0, 1, &u, &o));
    let rho = trig_sum(|i| Poly::from_int(1 + i as i64), &Poly::from_int(1), &u);
    let parallel = n1.iter().zip(&n2).all(|(x, y)| same(&(rho.clone() * x), y));
    let checker = trig_tangent_continuous(&s1, &s2, TrigJoin::UU, EXACT) == Ok(true);
    Claim::check(
        "Theorem 3 proof: by Faux's method the normal condition (5) reduces to (6) ∂S₁/∂v = μ ∂S₂/∂v \
         (so condition 2) is necessary)",
        &format!("{SRC} §3 eqs. (5)→(6)"),
        Verdict::Refuted,
        !(g0 && parallel && checker) || factor.is_some(),
        format!(
            "counterexample: Pᵢⱼ = (i, j, 0), Qᵢⱼ = (i, 3, 0), (i, 4+i, 0), (i, 5+i, 0), (i, 6+i, 0), all α = 1: \
             G⁰ {g0}, N₂ ≡ ρ(u)N₁ with ρ = Σ Xᵢ(u)(1+i) ≥ 1 (tangent planes agree, same side) = {parallel}, \
             trig_tangent_continuous = {checker}, but no constant μ (checker: {factor:?}). Corrected: G¹ iff ∂S₁/∂v = μ(u)∂S₂/∂v + ν(u)∂S/∂u with \
             μ(u) > 0; (6) is sufficient only"
        ),
    )
}

fn bowl_claims() -> Vec<Claim> {
    let r = |k: i64| ratio::<Q>(k, 100);
    let alpha1 = r(120);
    let alpha2 = [r(130), r(110), r(110), r(130)];
    let mu = [r(100), r(80), r(80), r(70)];
    let g0_bowl = trig_bowl(&alpha1, &alpha2, None).expect("printed data");
    let g0_ok = (0..4).all(|k| trig_g0(&g0_bowl[k], &g0_bowl[(k + 1) % 4], TrigJoin::UU, EXACT));
    let dp: Vec<Q> = (0..3)
        .map(|d| g0_bowl[0].points()[0][3][d].clone() - &g0_bowl[0].points()[0][2][d])
        .collect();
    let dq: Vec<Q> = (0..3)
        .map(|d| g0_bowl[1].points()[0][1][d].clone() - &g0_bowl[1].points()[0][0][d])
        .collect();
    let cross_zero = cross(&dp, &dq).iter().all(Zero::is_zero);
    let printed_not_g1 = trig_g1_factor(&g0_bowl[0], &g0_bowl[1], TrigJoin::UU, EXACT).is_none();
    let g1_bowl = trig_bowl(&alpha1, &alpha2, Some(&mu)).expect("positive μ");
    let factors: Vec<Option<Q>> = (0..4)
        .map(|k| trig_g1_factor(&g1_bowl[k], &g1_bowl[(k + 1) % 4], TrigJoin::UU, EXACT))
        .collect();
    let s2_printed = printed_rule(&g1_bowl[0], &alpha2[0], &alpha2[1], &mu[0]);
    let realised = trig_g1_factor(&g1_bowl[0], &s2_printed, TrigJoin::UU, EXACT);
    let realised_text = realised.as_ref().map_or("none".into(), |q| q.to_string());
    vec![
        Claim::check(
            "§5 Fig. 4: S₁ and S₂ (printed 16 + 12 points, Qᵢ₀ = Pᵢ₃, α₁ = λ₁) join G⁰; with our completion \
             S₃, S₄ every join of the ring is G⁰",
            &format!("{SRC} §5"),
            Verdict::Proved,
            g0_ok,
            "exact; α₁ = λ₁ = β₁ = γ₁ = 1.2, α₂ = (1.3, 1.1, 1.1, 1.3) of Fig. 6(a)".into(),
        ),
        Claim::check(
            "§5: the printed S₁S₂ join is not G¹ in the sense of (6) for any shape parameters",
            "ours",
            Verdict::Proved,
            !cross_zero && printed_not_g1,
            "ΔP₀ = P₀₃ − P₀₂ = (2.51, −1.35, −0.06) and ΔQ₀ = Q₀₁ − Q₀₀ = (−0.04, 0.26, 0.06) are not \
             parallel, while (6) needs α₂ΔPᵢ = μλ₂ΔQᵢ; so Figs. 5–6 used other Q_{i1}"
                .into(),
        ),
        Claim::check(
            "§4 algorithm (corrected): the bowl built by trig_stitch with Fig. 5(a) μ = (1, 0.8, 0.8, 0.7) \
             and Fig. 6(a) shapes is G¹ at all four joins with exactly those μ",
            "ours",
            Verdict::Proved,
            factors.iter().zip(&mu).all(|(f, m)| f.as_ref() == Some(m)),
            format!(
                "exact checker factors: {}",
                factors.iter().map(|f| f.as_ref().map_or("none".into(), |q| q.to_string())).collect::<Vec<_>>().join(", ")
            ),
        ),
        Claim::compare(
            "§5 Figs. 5(a)/6(a): the printed rule with μ₁ = 1, α₂ = 1.3, λ₂ = 1.1 joins S₁S₂ with normal factor μ₁ = 1",
            &format!("{SRC} §5 Figs. 5–6"),
            Verdict::Mismatch,
            realised == Some(mu[0].clone()),
            "μ₁ = 1",
            &format!("{realised_text} (= 1.3·3.1/(1.1·3.3))"),
        ),
    ]
}
