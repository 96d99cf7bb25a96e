//! Source 001 (lecture), tensor-product surfaces: the two de Casteljau
//! orders, the intermediate-net formula, derivatives, the corner tangent
//! planes and the G⁰ control-point condition — checked symbolically.
//!
//! Symbolic setting as in `yang_yong`: fully symbolic homogeneous nets
//! (1D unless a claim needs 3D), every (m, n) with 1 ≤ m, n ≤ 4 unless
//! stated.

use super::yang_yong::sym_net;
use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::algebra::{ratio, Tolerance};
use exact_bezier::bernstein::bernstein;
use exact_bezier::hpoint::{de_casteljau, HPoint};
use exact_bezier::rect::join::g0_join;
use exact_bezier::rect::ops::{cross, Corner};
use exact_bezier::rect::RectPatch;
use num_rational::BigRational;
use num_traits::{One, Zero};

const SRC: &str = "001 lecture, 矩形域曲面";

fn bidegrees(max: usize) -> impl Iterator<Item = (usize, usize)> {
    (1..=max).flat_map(move |m| (1..=max).map(move |n| (m, n)))
}

/// Every claim of this family.
pub fn claims() -> Vec<Claim> {
    vec![
        orders_agree(),
        intermediate_printed(),
        intermediate_corrected(),
        projective_evaluation(),
        derivatives_taylor(),
        corner_planes(),
        g0_printed_index(),
        g0_corrected(),
    ]
}

/// The lecture's two recursions (u first, v first) give the same point.
fn orders_agree() -> Claim {
    let (u, v) = (Poly::var("u"), Poly::var("v"));
    let bad = bidegrees(4).find(|&(m, n)| {
        let p = sym_net(m, n);
        p.eval_hom_u_first(&u, &v) != p.eval_hom(&u, &v)
    });
    Claim::check(
        "the lecture's two de Casteljau orders (P^{k,0} in u then P^{m,l} in v; or P^{0,l} in v then P^{k,n} in u) give the same point for all u, v",
        &format!("{SRC}, de Casteljau算法"),
        Verdict::Proved,
        bad.is_none(),
        bad.map_or_else(
            || "identity in Q[u, v, net] for every (m, n) ≤ (4, 4)".into(),
            |b| format!("fails at {b:?}"),
        ),
    )
}

/// The intermediate net after k steps in u and l steps in v:
/// `P^{k,l}_{i,j}`, `i ≤ m − k`, `j ≤ n − l`.
fn intermediate(
    p: &RectPatch<Poly>,
    k: usize,
    l: usize,
    u: &Poly,
    v: &Poly,
) -> Vec<Vec<HPoint<Poly>>> {
    let step = |row: &[HPoint<Poly>], t: &Poly| -> Vec<HPoint<Poly>> {
        row.windows(2).map(|w| w[0].lerp(&w[1], t)).collect()
    };
    let mut net: Vec<Vec<HPoint<Poly>>> = p.ctrl().to_vec();
    for _ in 0..l {
        net = net.iter().map(|r| step(r, v)).collect();
    }
    for _ in 0..k {
        let cols = net[0].len();
        let t: Vec<Vec<HPoint<Poly>>> = (0..cols)
            .map(|j| step(&net.iter().map(|r| r[j].clone()).collect::<Vec<_>>(), u))
            .collect();
        net = (0..t[0].len())
            .map(|i| t.iter().map(|c| c[i].clone()).collect())
            .collect();
    }
    net
}

/// `Σ_i Σ_j net_{ij} B_{i,a}(u) B_{j,b}(v)`.
fn tensor_sum(net: &[Vec<HPoint<Poly>>], a: usize, b: usize, u: &Poly, v: &Poly) -> HPoint<Poly> {
    let mut acc = HPoint::zero(net[0][0].dim());
    for (i, row) in net.iter().enumerate() {
        for (j, h) in row.iter().enumerate() {
            acc = acc.add(&h.scale(&(bernstein(i, a, u) * &bernstein(j, b, v))));
        }
    }
    acc
}

/// As printed: `P(u,v) = Σ_{i=0}^{m−k} Σ_{j=0}^{n−l} P^{k,l}_{i,j} B_{i,m}(u) B_{j,n}(v)`.
fn intermediate_printed() -> Claim {
    let (u, v) = (Poly::var("u"), Poly::var("v"));
    let p = sym_net(2, 2);
    let net = intermediate(&p, 1, 0, &u, &v);
    let holds = tensor_sum(&net, 2, 2, &u, &v) == p.eval_hom(&u, &v);
    Claim::check(
        "as printed: P(u,v) = Σ_{i≤m−k} Σ_{j≤n−l} P^{k,l}_{ij} B_{i,m}(u) B_{j,n}(v)",
        &format!("{SRC}, de Casteljau算法"),
        Verdict::Refuted,
        holds,
        "counterexample (m, n) = (2, 2), (k, l) = (1, 0), symbolic net; the basis degrees must drop with the level: B_{i,m−k}(u) B_{j,n−l}(v)".into(),
    )
}

fn intermediate_corrected() -> Claim {
    let (u, v) = (Poly::var("u"), Poly::var("v"));
    let bad = bidegrees(3).find_map(|(m, n)| {
        let p = sym_net(m, n);
        let h = p.eval_hom(&u, &v);
        (0..=m)
            .flat_map(|k| (0..=n).map(move |l| (k, l)))
            .find(|&(k, l)| tensor_sum(&intermediate(&p, k, l, &u, &v), m - k, n - l, &u, &v) != h)
            .map(|kl| format!("(m, n) = ({m}, {n}), (k, l) = {kl:?}"))
    });
    Claim::check(
        "corrected: P(u,v) = Σ_{i≤m−k} Σ_{j≤n−l} P^{k,l}_{ij} B_{i,m−k}(u) B_{j,n−l}(v) at every level (k, l)",
        &format!("{SRC}, de Casteljau算法"),
        Verdict::Proved,
        bad.is_none(),
        bad.unwrap_or_else(|| "identity in Q[u, v, net] for every (m, n) ≤ (3, 3) and every level".into()),
    )
}

/// `eval_hom_projective` is definition (1) at homogeneous parameters.
fn projective_evaluation() -> Claim {
    let (u0, u1, v0, v1) = (
        Poly::var("u0"),
        Poly::var("u1"),
        Poly::var("v0"),
        Poly::var("v1"),
    );
    let bad = bidegrees(4).find(|&(m, n)| {
        let p = sym_net(m, n);
        let mut want = HPoint::zero(1);
        for (i, row) in p.ctrl().iter().enumerate() {
            for (j, h) in row.iter().enumerate() {
                let f = exact_bezier::algebra::binomial_scalar::<Poly>(m, i)
                    * &exact_bezier::algebra::binomial_scalar::<Poly>(n, j)
                    * &u1.pow(i as u32)
                    * &u0.pow((m - i) as u32)
                    * &v1.pow(j as u32)
                    * &v0.pow((n - j) as u32);
                want = want.add(&h.scale(&f));
            }
        }
        p.eval_hom_projective(&[u0.clone(), u1.clone()], &[v0.clone(), v1.clone()]) != want
    });
    Claim::check(
        "homogeneous-parameter de Casteljau = Σ C(m,i)C(n,j) u1^i u0^{m−i} v1^j v0^{n−j} ω_{ij}(P_{ij}, 1) (used to state reparameterization identities without division)",
        "ours",
        Verdict::Proved,
        bad.is_none(),
        bad.map_or_else(|| "identity for every (m, n) ≤ (4, 4)".into(), |b| format!("fails at {b:?}")),
    )
}

/// Taylor's formula, exact for polynomials: H(u + h, v + k) =
/// Σ_{a ≤ m, b ≤ n} h^a k^b / (a! b!) ∂^{a+b}H/∂u^a∂v^b (u, v): proves every
/// partial derivative of every order at once.
fn derivatives_taylor() -> Claim {
    let (u, v, h, k) = (
        Poly::var("u"),
        Poly::var("v"),
        Poly::var("h"),
        Poly::var("k"),
    );
    let fact = |n: usize| -> BigRational {
        (1..=n as i64).fold(ratio(1, 1), |a, x| a * ratio::<BigRational>(x, 1))
    };
    let bad = bidegrees(3).find(|&(m, n)| {
        let p = sym_net(m, n);
        let lhs = p.eval_hom(&(u.clone() + &h), &(v.clone() + &k));
        let mut rhs = HPoint::zero(1);
        for a in 0..=m {
            for b in 0..=n {
                let c = Poly::constant(ratio::<BigRational>(1, 1) / (fact(a) * fact(b)));
                let f = c * &h.pow(a as u32) * &k.pow(b as u32);
                rhs = rhs.add(&p.derivative_hom(a, b, &u, &v).scale(&f));
            }
        }
        lhs != rhs
            || !p
                .derivative_hom(m + 1, 0, &u, &v)
                .is_zero_within(Tolerance::EXACT)
    });
    Claim::check(
        "partial derivatives of every order: H(u+h, v+k) = Σ h^a k^b/(a! b!) ∂^{a+b}H/∂u^a∂v^b(u, v), with ∂^{a,b}H from forward differences m!/(m−a)!·n!/(n−b)!·Δ^{a,b}",
        &format!("{SRC} (curve derivative formula per direction)"),
        Verdict::Proved,
        bad.is_none(),
        bad.map_or_else(|| "identity in Q[u, v, h, k, net] for every (m, n) ≤ (3, 3)".into(), |b| format!("fails at {b:?}")),
    )
}

/// The corner tangent planes: at each corner the normal is parallel to the
/// normal of the printed triangle (3D net, symbolic points and weights).
fn corner_planes() -> Claim {
    let bad = bidegrees(4).find_map(|(m, n)| {
        let pts: Vec<Vec<Vec<Poly>>> = (0..=m)
            .map(|i| {
                (0..=n)
                    .map(|j| {
                        ["x", "y", "z"]
                            .iter()
                            .map(|c| Poly::var(&format!("{c}{i}{j}")))
                            .collect()
                    })
                    .collect()
            })
            .collect();
        let ws: Vec<Vec<Poly>> = (0..=m)
            .map(|i| (0..=n).map(|j| Poly::var(&format!("w{i}{j}"))).collect())
            .collect();
        let p = RectPatch::new(pts.clone(), ws).expect("symbolic weights are non-zero");
        Corner::ALL.iter().find_map(|&c| {
            let (u, v): (Poly, Poly) = c.params();
            let normal = p.normal_hom(&u, &v).expect("3D");
            let [a, b, d] = p.corner_triangle(c);
            let at = |(i, j): (usize, usize)| pts[i][j].clone();
            let edge = |x: (usize, usize)| -> Vec<Poly> {
                at(x)
                    .iter()
                    .zip(at(a))
                    .map(|(p, q)| p.clone() - &q)
                    .collect()
            };
            let tri = cross(&edge(b), &edge(d));
            let par = cross(&normal, &tri);
            let nonzero = normal.iter().any(|x| !x.is_zero());
            (!(par.iter().all(|x| x.is_zero()) && nonzero))
                .then(|| format!("(m, n) = ({m}, {n}), corner {c:?}"))
        })
    });
    Claim::check(
        "the triangles P00P10P01, P0nP1nP0,n−1, PmnPm,n−1Pm−1,n, Pm0Pm−1,0Pm1 span the tangent planes at the four corners (normal ∥ triangle normal, rational patches)",
        &format!("{SRC}, 矩形域Bézier曲面的性质"),
        Verdict::Proved,
        bad.is_none(),
        bad.unwrap_or_else(|| "symbolic 3D points and weights, every (m, n) ≤ (4, 4): N × ((P_b − P_a) × (P_c − P_a)) = 0 and N ≠ 0 as polynomials".into()),
    )
}

/// A 3D exact patch of bidegree (2, 1) and a partner sharing the row that
/// the printed G⁰ condition names.
fn g0_printed_index() -> Claim {
    let q = |x: i64, y: i64, z: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1), ratio(z, 1)];
    // (m, n) = (2, 1): the printed P_{n,i} = P_{1,i} is the middle row.
    let p = RectPatch::polynomial(vec![
        vec![q(0, 0, 0), q(0, 3, 1)],
        vec![q(1, 0, 2), q(1, 3, 0)],
        vec![q(2, 0, 0), q(2, 3, 1)],
    ])
    .expect("a net");
    let partner = RectPatch::polynomial(vec![
        vec![q(1, 0, 2), q(1, 3, 0)],
        vec![q(3, 0, 1), q(3, 3, 1)],
        vec![q(4, 0, 0), q(4, 3, 0)],
    ])
    .expect("a net");
    let joined = g0_join(&p, &partner, Tolerance::EXACT);
    Claim::check(
        "G⁰ as printed: P_{ni} = Q_{0i}, i = 0…m implies P(1, v) = Q(0, v)",
        &format!("{SRC}, 几何连续性"),
        Verdict::Refuted,
        joined,
        "counterexample (m, n) = (2, 1): Q_{0,j} = P_{1,j} (the printed P_{n,j}) but P(1, v) ≠ Q(0, v); the indices are swapped: P_{m,j} = Q_{0,j}, j = 0…n".into(),
    )
}

/// Corrected: Q_{0,j} = P_{m,j} (homogeneous, so weights too) gives G⁰.
fn g0_corrected() -> Claim {
    let v = Poly::var("v");
    let bad = bidegrees(4).find(|&(m, n)| {
        let p = sym_net(m, n);
        let mut ctrl = sym_net(m, n)
            .ctrl()
            .iter()
            .map(|r| r.iter().map(|h| h.scale(&Poly::var("λ"))).collect())
            .collect::<Vec<Vec<_>>>();
        ctrl[0] = p.ctrl()[m].clone();
        let q = RectPatch::from_hom(ctrl).expect("a net");
        de_casteljau(&p.ctrl()[m], &v) != q.eval_hom(&Poly::zero(), &v)
            || p.eval_hom(&Poly::one(), &v) != q.eval_hom(&Poly::zero(), &v)
    });
    Claim::check(
        "G⁰ corrected: P_{m,j} = Q_{0,j} (homogeneous: points and weights), j = 0…n, gives P(1, v) = Q(0, v)",
        &format!("{SRC}, 几何连续性"),
        Verdict::Proved,
        bad.is_none(),
        bad.map_or_else(|| "identity in Q[v, nets] for every (m, n) ≤ (4, 4)".into(), |b| format!("fails at {b:?}")),
    )
}
