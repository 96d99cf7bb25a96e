//! The lecture's geometric-continuity conditions for joining two Bézier
//! curves (source 001, "Gⁿ 几何连续性"): `P` with control points
//! `P_0 … P_n`, `Q` with `Q_0 … Q_m`, joined at `P_n = Q_0`.
//!
//! Printed:
//!
//! ```text
//! G¹: Q_0 − Q_1 = α (P_n − P_{n−1})
//! G²: Q_2 = (α² + 2α + β/(n−1) + 1) P_n − (2α² + 2α + β/(n−1)) P_{n−1} + α² P_{n−2},
//!     Q''(0) = α² P''(1) + β P'(1)
//! ```
//!
//! Findings: the G¹ sign is wrong (it describes a cusp; correct is
//! `Q_1 − Q_0 = (nα/m)(P_n − P_{n−1})`, `α > 0`); the G² formula is right
//! for `m = n` with the corrected `Q_1`, wrong with the printed one, and
//! wrong for `m ≠ n` (corrected: [`g2_leading_points`]).

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::algebra::{ratio, Scalar, Tolerance};
use exact_bezier::curve::geometry::cross_norm_sq;
use exact_bezier::curve::join::{g2_leading_points, join};
use exact_bezier::curve::RationalCurve;
use num_rational::BigRational;
use num_traits::{One, Zero};

const SOURCE: &str = "001 lecture, Gⁿ 几何连续性";
/// The largest degrees n, m of the "every degree" claims.
const MAX_DEGREE: usize = 10;

fn v(name: &str) -> Poly {
    Poly::var(name)
}

/// Symbolic 2D points `{prefix}{i}_{k}`, `i = 0 … n`.
fn points(prefix: &str, n: usize) -> Vec<Vec<Poly>> {
    (0..=n)
        .map(|i| (0..2).map(|k| v(&format!("{prefix}{i}_{k}"))).collect())
        .collect()
}

/// `Σ c_j · x_j` for points.
fn combo(cs: &[Poly], xs: &[&Vec<Poly>]) -> Vec<Poly> {
    (0..xs[0].len())
        .map(|k| {
            cs.iter()
                .zip(xs)
                .fold(Poly::zero(), |acc, (c, x)| acc + c.clone() * &x[k])
        })
        .collect()
}

/// `(X'(at), X''(at))` of a polynomial curve given by its points.
fn end_derivs(pts: &[Vec<Poly>], at: &Poly) -> (Vec<Poly>, Vec<Poly>) {
    let c = RationalCurve::polynomial(pts.to_vec()).expect("symbols");
    let d = c.hom_derivs_at(at, 2);
    (d[1].weighted().to_vec(), d[2].weighted().to_vec())
}

/// The residuals `Q'(0) − α P'(1)` and `Q''(0) − α² P''(1) − β P'(1)` for
/// `Q = [q0, q1, q2, free symbols…]` of degree `m`.
fn residuals(p: &[Vec<Poly>], q012: [Vec<Poly>; 3], m: usize) -> (Vec<Poly>, Vec<Poly>) {
    let (alpha, beta) = (v("alpha"), v("beta"));
    let mut q: Vec<Vec<Poly>> = q012.to_vec();
    q.extend(points("r", m).into_iter().skip(3));
    let (p1, p2) = end_derivs(p, &Poly::one());
    let (q1, q2) = end_derivs(&q, &Poly::zero());
    let a2 = alpha.clone() * &alpha;
    let r1 = combo(&[Poly::one(), -alpha], &[&q1, &p1]);
    let r2 = combo(&[Poly::one(), -a2, -beta], &[&q2, &p2, &p1]);
    (r1, r2)
}

fn all_zero(x: &[Poly]) -> bool {
    x.iter().all(Zero::is_zero)
}

/// The printed `Q_0, Q_1, Q_2` for degree `n`, with `Q_1` from the printed
/// G¹ sign (`printed_g1`) or the corrected one.
fn printed_q(p: &[Vec<Poly>], printed_g1: bool) -> [Vec<Poly>; 3] {
    let n = p.len() - 1;
    let (a, b) = (v("alpha"), v("beta"));
    let (pn, pn1, pn2) = (&p[n], &p[n - 1], &p[n - 2]);
    let sign = if printed_g1 {
        -Poly::one()
    } else {
        Poly::one()
    };
    let q1 = combo(&[Poly::one() + sign.clone() * &a, -(sign * &a)], &[pn, pn1]);
    let bn = b * ratio::<Poly>(1, n as i64 - 1);
    let a2 = a.clone() * &a;
    let two = Poly::from_int(2);
    let c0 = a2.clone() + two.clone() * &a + &bn + Poly::one();
    let c1 = two.clone() * &a2 + two * &a + &bn;
    let q2 = combo(&[c0, -c1, a2], &[pn, pn1, pn2]);
    [pn.clone(), q1, q2]
}

fn g1_sign_claim() -> Claim {
    let q = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    let curve = |a, b| RationalCurve::polynomial(vec![a, b]).expect("2D points");
    let p = curve(q(0, 0), q(1, 0));
    let straight = curve(q(1, 0), q(2, 0));
    let cusp = curve(q(1, 0), q(0, 0));
    // Printed: Q0 − Q1 = α (P1 − P0) with P1 − P0 = (1, 0): α is the x-part.
    let printed_alpha = |c: &RationalCurve<BigRational>| {
        let pts = c.points().expect("unit weights");
        pts[0][0].clone() - &pts[1][0]
    };
    let g1 = |c| join(&p, c, Tolerance::EXACT).map(|j| j.g1).unwrap_or(false);
    let (a_straight, a_cusp) = (printed_alpha(&straight), printed_alpha(&cusp));
    // Under the printed condition with α > 0 the straight continuation fails
    // and the cusp passes; under any α the cusp passes. Either way it
    // disagrees with G¹.
    let agrees = (a_straight > BigRational::zero()) == g1(&straight)
        && (a_cusp > BigRational::zero()) == g1(&cusp);
    Claim::check(
        "G¹ continuity ⟺ Q0 − Q1 = α(Pn − Pn−1) (α > 0), i.e. Pn−1, Pn = Q0, Q1 collinear",
        SOURCE,
        Verdict::Refuted,
        agrees,
        format!(
            "counterexample P = (0,0),(1,0): Q = (1,0),(2,0) continues straight (G¹, even C¹) but needs α = {a_straight} < 0; Q = (1,0),(0,0) turns back (a cusp, not G¹) yet satisfies it with α = {a_cusp} > 0; collinearity alone admits the cusp. Correct: Q1 − Q0 = (nα/m)(Pn − Pn−1) with α > 0, i.e. Q'(0) = α P'(1) (proved below)"
        ),
    )
}

/// The corrected G¹ coefficient `nα/m` of `Q1 = Pn + (nα/m)(Pn − Pn−1)`.
fn g1_coefficient(n: usize, m: usize) -> Poly {
    ratio::<Poly>(n as i64, m as i64) * v("alpha")
}

fn corrected_g1_claim() -> Claim {
    corrected_g1_with(g1_coefficient)
}

/// The corrected G¹ claim with the coefficient `r(n, m)` of
/// `Q1 = Pn + r(Pn − Pn−1)` (the tests feed wrong ones through it).
fn corrected_g1_with(coefficient: impl Fn(usize, usize) -> Poly) -> Claim {
    let failure = (1..=MAX_DEGREE)
        .flat_map(|n| (1..=MAX_DEGREE).map(move |m| (n, m)))
        .find(|&(n, m)| {
            let p = points("p", n);
            let r = coefficient(n, m);
            let q1 = combo(&[Poly::one() + &r, -r], &[&p[n], &p[n - 1]]);
            let mut q = vec![p[n].clone(), q1];
            q.extend(points("r", m).into_iter().skip(2));
            let (p1, _) = end_derivs(&p, &Poly::one());
            let (qd, _) = end_derivs(&q, &Poly::zero());
            !all_zero(&combo(&[Poly::one(), -v("alpha")], &[&qd, &p1]))
        });
    Claim::check(
        &format!("corrected G¹ for every 1 ≤ n, m ≤ {MAX_DEGREE}: Q0 = Pn, Q1 = Pn + (nα/m)(Pn − Pn−1) gives Q'(0) = α P'(1) (same direction for α > 0)"),
        "ours (corrects 001 lecture, Gⁿ 几何连续性)",
        Verdict::Proved,
        failure.is_none(),
        failure.map_or("symbolic α, 2D P_i and free Q_2…Q_m, each (n, m) an identity".into(), |f| format!("fails at (n, m) = {f:?}")),
    )
    .with_bound(format!("1 ≤ n, m ≤ {MAX_DEGREE}"))
}

fn printed_g2_claims() -> Vec<Claim> {
    let equal_degrees = (2..=MAX_DEGREE).find(|&n| {
        let p = points("p", n);
        let (r1, r2) = residuals(&p, printed_q(&p, false), n);
        !(all_zero(&r1) && all_zero(&r2))
    });
    let p = points("p", 3);
    let (_, with_printed_g1) = residuals(&p, printed_q(&p, true), 3);
    let (_, other_degree) = residuals(&p, printed_q(&p, false), 2);
    vec![
        Claim::check(
            &format!("G² for every 2 ≤ n ≤ {MAX_DEGREE}: Q2 = (α²+2α+β/(n−1)+1)Pn − (2α²+2α+β/(n−1))Pn−1 + α²Pn−2 gives Q''(0) = α²P''(1) + βP'(1) (equal degrees m = n, Q1 = Pn + α(Pn − Pn−1))"),
            SOURCE,
            Verdict::Proved,
            equal_degrees.is_none(),
            equal_degrees.map_or(
                "symbolic α, β, 2D P_i and free Q_3…Q_n: Q'(0) − αP'(1) and Q''(0) − α²P''(1) − βP'(1) vanish identically for each n".into(),
                |n| format!("fails at n = {n}"),
            ),
        )
        .with_bound(format!("2 ≤ n ≤ {MAX_DEGREE}")),
        Claim::identity(
            "G² formula together with the printed G¹ statement (Q1 = Pn − α(Pn − Pn−1)) gives Q''(0) = α²P''(1) + βP'(1)",
            SOURCE,
            Verdict::Refuted,
            &with_printed_g1[0],
            &Poly::zero(),
            "n = m = 3, x-coordinate of Q''(0) − α²P''(1) − βP'(1); the formula needs Q1 = Pn + α(Pn − Pn−1)",
        ),
        Claim::identity(
            "G² formula for degrees m ≠ n (P of degree n, Q of degree m): Q''(0) = α²P''(1) + βP'(1)",
            SOURCE,
            Verdict::Refuted,
            &other_degree[0],
            &Poly::zero(),
            "n = 3, m = 2, x-coordinate of Q''(0) − α²P''(1) − βP'(1). Correct for any m: Q1 = Pn + (nα/m)(Pn − Pn−1), Q2 = (1 + 2nα/m + (n(n−1)α² + nβ)/(m(m−1)))Pn − (2nα/m + (2n(n−1)α² + nβ)/(m(m−1)))Pn−1 + (n(n−1)α²/(m(m−1)))Pn−2",
        ),
    ]
}

fn corrected_g2_claim() -> Claim {
    let failure = (2..=MAX_DEGREE)
        .flat_map(|n| (2..=MAX_DEGREE).map(move |m| (n, m)))
        .find(|&(n, m)| {
            let p = points("p", n);
            let Ok(q) = g2_leading_points(&p, m, &v("alpha"), &v("beta")) else {
                return true;
            };
            let (r1, r2) = residuals(&p, q, m);
            !(all_zero(&r1) && all_zero(&r2))
        });
    Claim::check(
        &format!("corrected G² for every 2 ≤ n, m ≤ {MAX_DEGREE} (g2_leading_points) gives Q'(0) = αP'(1) and Q''(0) = α²P''(1) + βP'(1)"),
        "ours (generalizes 001 lecture, Gⁿ 几何连续性)",
        Verdict::Proved,
        failure.is_none(),
        failure.map_or("symbolic α, β, 2D P_i and free Q_3…Q_m, each (n, m) an identity".into(), |f| format!("fails at (n, m) = {f:?}")),
    )
    .with_bound(format!("2 ≤ n, m ≤ {MAX_DEGREE}"))
}

fn curvature_continuity_claim() -> Claim {
    // X' = a, X'' = b at the end of P; Q'(0) = αa, Q''(0) = α²b + βa.
    let (a, b) = (Poly::vars("a", 3), Poly::vars("b", 3));
    let (alpha, beta) = (v("alpha"), v("beta"));
    let qa: Vec<Poly> = a.iter().map(|x| x.clone() * &alpha).collect();
    let qb: Vec<Poly> = a
        .iter()
        .zip(&b)
        .map(|(x, y)| y.clone() * &alpha * &alpha + &(x.clone() * &beta))
        .collect();
    let norm6 = |x: &[Poly]| {
        x.iter()
            .fold(Poly::zero(), |s, y| s + y.clone() * y)
            .pow_u32(3)
    };
    let lhs = cross_norm_sq(&qa, &qb) * norm6(&a);
    let rhs = cross_norm_sq(&a, &b) * norm6(&qa);
    Claim::identity(
        "Q'(0) = αP'(1), Q''(0) = α²P''(1) + βP'(1) make the curvatures equal at the join (κ² = |X'×X''|²/|X'|⁶), i.e. G² is curvature continuity",
        SOURCE,
        Verdict::Proved,
        &lhs,
        &rhs,
        "symbolic 3D vectors P'(1), P''(1), α, β; cross-multiplied",
    )
}

/// The lecture's example Φ: `V0 + (V1−V0)t/3` on [0,1], then
/// `V0 + (V1−V0)/3 + (t−1)·2(V1−V0)/3` on [1,2]: printed
/// `Φ'(1⁻) = (V1−V0)/3`, `Φ'(1⁺) = 2(V1−V0)/3`, a straight line (G¹, not C¹).
fn phi_example_claim() -> Claim {
    let q = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    // V0 = (0,0), V1 = (3,6): the pieces as linear Bézier curves over [0,1].
    let first = RationalCurve::polynomial(vec![q(0, 0), q(1, 2)]).expect("2D points");
    let second = RationalCurve::polynomial(vec![q(1, 2), q(3, 6)]).expect("2D points");
    let d_minus = first.deriv(&ratio(1, 1), 1).expect("polynomial");
    let d_plus = second.deriv(&ratio(0, 1), 1).expect("polynomial");
    let j = join(&first, &second, Tolerance::EXACT).expect("same dimension");
    let show = |p: &[BigRational]| format!("({}, {})", p[0], p[1]);
    let agrees = d_minus == q(1, 2) && d_plus == q(2, 4) && j.g2 && j.alpha == Some(ratio(2, 1));
    Claim::compare(
        "Φ example: Φ'(1⁻) = (V1−V0)/3 ≠ Φ'(1⁺) = 2(V1−V0)/3, yet Φ is a straight line (geometrically smooth, not C¹)",
        "001 lecture, 几何连续性 vs. 函数连续性",
        Verdict::Reproduced,
        agrees,
        "Φ'(1⁻) = (V1−V0)/3, Φ'(1⁺) = 2(V1−V0)/3, a straight line",
        &format!(
            "with V0 = (0,0), V1 = (3,6): Φ'(1⁻) = {}, Φ'(1⁺) = {}; join G1 = {}, G2 = {}, α = {}",
            show(&d_minus),
            show(&d_plus),
            j.g1,
            j.g2,
            j.alpha.as_ref().map_or("none".into(), |a| a.to_string())
        ),
    )
}

/// The family's claims.
pub fn claims() -> Vec<Claim> {
    let mut all = vec![phi_example_claim(), g1_sign_claim(), corrected_g1_claim()];
    all.extend(printed_g2_claims());
    all.push(corrected_g2_claim());
    all.push(curvature_continuity_claim());
    all
}

#[cfg(test)]
mod tests {
    //! The verdicts discriminate: a wrong formula fed through the same
    //! claim code is refuted.
    use super::*;

    #[test]
    fn wrong_g1_coefficients_are_refuted() {
        assert_eq!(corrected_g1_claim().verdict, Verdict::Proved);
        let flipped = |n: usize, m: usize| -g1_coefficient(n, m);
        assert_eq!(corrected_g1_with(flipped).verdict, Verdict::Refuted);
        let shifted = |n: usize, m: usize| g1_coefficient(n + 1, m);
        assert_eq!(corrected_g1_with(shifted).verdict, Verdict::Refuted);
    }
}
