//! Source 000 (Yang & Yong, *Standardization of rational Bézier surfaces*):
//! the Möbius maps (2)(3), weight rule (4), scaling (5), Theorem 1, the
//! quadratic reparameterization (9)–(17) with Appendix 1, and the
//! standardization (18)(19) — checked symbolically.
//!
//! Symbolic setting: the control net is **fully symbolic** — a 1D
//! homogeneous net whose every coordinate (`p_{ij}` = ω_{ij}·x_{ij} and
//! `w_{ij}` = ω_{ij}) is a symbol. Every algorithm involved acts on the
//! homogeneous coordinates linearly and coordinate by coordinate, so an
//! identity for this net holds for nets of any dimension. Bidegrees: every
//! (m, n) up to a per-claim bound (8 or 5; 10 or 8 with `prove --deep`) that each claim's text states.

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::algebra::{binomial_scalar, ratio};
use exact_bezier::bernstein::bernstein;
use exact_bezier::hpoint::HPoint;
use exact_bezier::rect::RectPatch;
use exact_bezier::reparam::standard::corner_weights;
use exact_bezier::reparam::{quadratic_coefficients, Quadratic};
use num_rational::BigRational;
use num_traits::Zero;

const SRC: &str = "000 Yang & Yong";
/// The largest m and n checked by the cheap claims (weights, corners).
const MAX: usize = 8;
/// The largest m and n of the costly claims — the quadratic-map claims
/// other than the point identity (an (m+n, m+n) result on a symbolic
/// weight net): 5 by default, 10 with `prove --deep` ([`super::deep`];
/// raised from 8 on 2026-11-29, when one-step elevation, a zero net for the
/// corners of (19) and work shared out as it comes brought the family at 10
/// from 11.9 to about 9 s).
fn max_symbolic() -> usize {
    if super::deep() {
        10
    } else {
        5
    }
}

/// The largest m and n of the point identities — the Möbius maps (2)(3),
/// the scaling (5) and the quadratic map (9)–(17), which compare whole
/// patches: 5 by default, 10 with `prove --deep` (raised from 8 when the
/// quadratic map's identity moved from a grid of values to Bernstein
/// coefficients, 2026-11-27).
fn max_point_identity() -> usize {
    if super::deep() {
        10
    } else {
        5
    }
}

/// The fully symbolic 1D net of bidegree (m, n): `ctrl[i][j] = (p_ij, w_ij)`.
pub(crate) fn sym_net(m: usize, n: usize) -> RectPatch<Poly> {
    let ctrl = (0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| HPoint {
                    coords: vec![
                        Poly::var(&format!("p{i}{j}")),
                        Poly::var(&format!("w{i}{j}")),
                    ],
                })
                .collect()
        })
        .collect();
    RectPatch::from_hom(ctrl).expect("a symbolic net")
}

fn v(name: &str) -> Poly {
    Poly::var(name)
}

fn one() -> Poly {
    Poly::from_int(1)
}

/// All bidegrees (m, n), 1 ≤ m, n ≤ max.
fn bidegrees(max: usize) -> Vec<(usize, usize)> {
    (1..=max)
        .flat_map(|m| (1..=max).map(move |n| (m, n)))
        .collect()
}

/// One claim from a per-bidegree check: proved iff it holds for all; the
/// detail names the first failure.
fn for_all_bidegrees(
    max: usize,
    claim: &str,
    source: &str,
    expected: Verdict,
    check: impl Fn(usize, usize) -> Option<String> + Sync,
) -> Claim {
    let [failure] = failures_by_bidegree(max, |m, n| [check(m, n)]);
    bidegree_claim(max, claim, source, expected, failure)
}

/// Per check, its first failure over the bidegrees up to `max` (in the
/// order of [`bidegrees`]), prefixed with the bidegree: for claims whose
/// checks share one computation per bidegree.
fn failures_by_bidegree<const K: usize>(
    max: usize,
    checks: impl Fn(usize, usize) -> [Option<String>; K] + Sync,
) -> [Option<String>; K] {
    super::first_failures(&bidegrees(max), |&(m, n)| {
        checks(m, n).map(|r| r.map(|why| format!("(m, n) = ({m}, {n}): {why}")))
    })
}

/// The claim checked for every bidegree up to `max`, from its first
/// failure (`None`: it holds for all).
fn bidegree_claim(
    max: usize,
    claim: &str,
    source: &str,
    expected: Verdict,
    failure: Option<String>,
) -> Claim {
    let holds = failure.is_none();
    Claim::check(
        &format!("{claim} — checked for every 1 ≤ m, n ≤ {max}"),
        source,
        expected,
        holds,
        failure.unwrap_or_else(|| {
            format!("identity in Q[symbols] for every (m, n) ≤ ({max}, {max}), fully symbolic net")
        }),
    )
    .with_bound(format!("1 ≤ m, n ≤ {max}"))
}

fn differ(a: &HPoint<Poly>, b: &HPoint<Poly>) -> Option<String> {
    let d = a.sub(b);
    (!d.is_zero_within(exact_bezier::Tolerance::EXACT))
        .then(|| super::abbreviate(&format!("difference {:?}", d.coords)))
}

/// Every claim of this family.
pub fn claims() -> Vec<Claim> {
    let mut out = vec![
        mobius_keeps_points(true),
        mobius_keeps_points(false),
        weight_rule(),
        scaling_keeps_points(),
        theorem1_only_if(),
        theorem1_if(),
    ];
    let [keeps, corners, eq17] = quadratic_map_claims();
    out.extend([
        keeps,
        corners,
        eq19_equal_corners(),
        eq17,
        compact_form(),
        bernstein_product_eq15(),
    ]);
    out.extend(appendix_c());
    out.extend(denominators());
    out
}

/// (2)(3): the new patch at (s, v) is the old one at (u(s), v), as the
/// homogeneous identity `H̃(s, v) = H(α(1−s), (1−α)s; 1 − v, v)`.
fn mobius_keeps_points(in_u: bool) -> Claim {
    let (dir, eq) = if in_u { ("u", "(2)") } else { ("v", "(3)") };
    for_all_bidegrees(
        max_point_identity(),
        &format!("Möbius map {eq} in {dir} keeps every point: new(s, t) = old at u(s) (resp. v(t)), for all α, s, t"),
        &format!("{SRC} eq. {eq}, (4)"),
        Verdict::Proved,
        |m, n| {
            let p = sym_net(m, n);
            let (a, s, t) = (v("α"), v("s"), v("t"));
            let hom = [a.clone() * &(one() - &s), (one() - &a) * &s];
            let plain = [one() - &t, t.clone()];
            let (new, old) = if in_u {
                (p.mobius_u(&a).eval_hom(&s, &t), p.eval_hom_projective(&hom, &plain))
            } else {
                let hom_t = [a.clone() * &(one() - &t), (one() - &a) * &t];
                let plain_s = [one() - &s, s.clone()];
                (p.mobius_v(&a).eval_hom(&s, &t), p.eval_hom_projective(&plain_s, &hom_t))
            };
            differ(&new, &old)
        },
    )
}

/// Both sides of the Möbius maps (2)(3) applied together, on the fully
/// symbolic (m, n) net: the new patch at (s, t), `H̃(s, t)`, and the old one
/// at the mapped homogeneous parameters, `H(α(1−s), (1−α)s; β(1−t), (1−β)t)`.
/// They are equal as polynomials; this is also the identity of the SymPy
/// peer benchmark (`benches/poly.rs`, `benches/peers/`).
pub fn mobius_uv_sides(m: usize, n: usize) -> (HPoint<Poly>, HPoint<Poly>) {
    let p = sym_net(m, n);
    let (a, b, s, t) = (v("α"), v("β"), v("s"), v("t"));
    let hom = |x: &Poly, y: &Poly| [x.clone() * &(one() - y), (one() - x) * y];
    let new = p.mobius_u(&a).mobius_v(&b).eval_hom(&s, &t);
    let old = p.eval_hom_projective(&hom(&a, &s), &hom(&b, &t));
    (new, old)
}

/// (4)'s factor `(1 − α)^i α^{m−i}(1 − β)^j β^{n−j}` for entry (i, j).
fn weight_factor(i: usize, j: usize, m: usize, n: usize) -> Poly {
    let (a, b) = (v("α"), v("β"));
    (one() - &a).pow(i as u32)
        * a.pow((m - i) as u32)
        * (one() - &b).pow(j as u32)
        * b.pow((n - j) as u32)
}

/// (4): ω̃_{i,j} = ω_{i,j}(1 − α)^i α^{m−i}(1 − β)^j β^{n−j}.
fn weight_rule() -> Claim {
    weight_rule_with(weight_factor)
}

/// (4) with the factor of entry (i, j) given by `factor(i, j, m, n)` (the
/// tests feed wrong ones through the same code).
fn weight_rule_with(factor: impl Fn(usize, usize, usize, usize) -> Poly + Sync) -> Claim {
    for_all_bidegrees(
        MAX,
        "weight rule (4): after (2)(3) ω̃_{i,j} = ω_{i,j}(1−α)^i α^{m−i}(1−β)^j β^{n−j}, points P_{i,j} unchanged",
        &format!("{SRC} eq. (4)"),
        Verdict::Proved,
        |m, n| {
            let p = sym_net(m, n);
            let q = p.mobius_u(&v("α")).mobius_v(&v("β"));
            for i in 0..=m {
                for j in 0..=n {
                    let want = p.ctrl()[i][j].scale(&factor(i, j, m, n));
                    if let Some(d) = differ(&q.ctrl()[i][j], &want) {
                        return Some(format!("entry ({i},{j}): {d}"));
                    }
                }
            }
            None
        },
    )
}

/// (5): scaling every weight by k multiplies H by k (same point).
fn scaling_keeps_points() -> Claim {
    for_all_bidegrees(
        max_point_identity(),
        "uniform weight scaling (5) keeps every point: H̃(u, v) = k·H(u, v)",
        &format!("{SRC} eq. (5)"),
        Verdict::Proved,
        |m, n| {
            let p = sym_net(m, n);
            let (k, s, t) = (v("k"), v("s"), v("t"));
            differ(
                &p.scale_weights(&k).eval_hom(&s, &t),
                &p.eval_hom(&s, &t).scale(&k),
            )
        },
    )
}

/// Theorem 1, only if: the corner cross ratio ω_{m,0}ω_{0,n}/(ω_{0,0}ω_{m,n})
/// is invariant under (2)(3)(5); a standard form has ratio 1.
fn theorem1_only_if() -> Claim {
    for_all_bidegrees(
        MAX,
        "Theorem 1 (only if): ω̃_{m,0}ω̃_{0,n}·ω_{0,0}ω_{m,n} = ω̃_{0,0}ω̃_{m,n}·ω_{m,0}ω_{0,n} after (2)(3)(5), for all α, β, k; the standard form has cross ratio 1, so ω_{m,0}ω_{0,n} = ω_{0,0}ω_{m,n} is necessary",
        &format!("{SRC} Theorem 1"),
        Verdict::Proved,
        |m, n| {
            let p = sym_net(m, n);
            let q = p.mobius_u(&v("α")).mobius_v(&v("β")).scale_weights(&v("k"));
            let [a00, am0, a0n, amn] = corner_weights(&p);
            let [b00, bm0, b0n, bmn] = corner_weights(&q);
            let lhs = bm0 * &b0n * &a00 * &amn;
            let rhs = b00 * &bmn * &am0 * &a0n;
            (lhs != rhs).then(|| "cross ratio changed".to_string())
        },
    )
}

/// Theorem 1, if: every corner quadruple with ω_{m,0}ω_{0,n} = ω_{0,0}ω_{m,n}
/// is ω_{0,0} = (1−a)^m(1−b)^n z, ω_{m,0} = a^m(1−b)^n z, ω_{0,n} = (1−a)^m b^n z,
/// ω_{m,n} = a^m b^n z (a, b ∈ (0,1), z > 0); (8) gives α = a, β = b, and the
/// map makes the four corners equal (then k of (8) makes them 1).
fn theorem1_if() -> Claim {
    for_all_bidegrees(
        MAX,
        "Theorem 1 (if), by exhibiting the map: for corner weights with ω_{m,0}ω_{0,n} = ω_{0,0}ω_{m,n}, eq. (8)'s α, β make the four corner weights equal",
        &format!("{SRC} Theorem 1, eq. (8)"),
        Verdict::Proved,
        |m, n| {
            let (a, b, z) = (v("a"), v("b"), v("z"));
            let (mu, nu) = (m as u32, n as u32);
            let ca = |x: bool| if x { a.pow(mu) } else { (one() - &a).pow(mu) };
            let cb = |y: bool| if y { b.pow(nu) } else { (one() - &b).pow(nu) };
            let mut p = sym_net(m, n);
            p = set_corners(&p, [ca(false) * &cb(false) * &z, ca(true) * &cb(false) * &z, ca(false) * &cb(true) * &z, ca(true) * &cb(true) * &z]);
            let [w00, wm0, w0n, wmn] = corner_weights(&p);
            // (8): ((1 − α)/α)^m = ω00/ωm0 and ((1 − β)/β)^n = ω00/ω0n with α = a, β = b.
            if w00.clone() * &a.pow(mu) != wm0.clone() * &(one() - &a).pow(mu)
                || w00.clone() * &b.pow(nu) != w0n.clone() * &(one() - &b).pow(nu)
                || wm0.clone() * &w0n != w00 * &wmn
            {
                return Some("the parametrization does not satisfy (8)".into());
            }
            let q = p.mobius_u(&a).mobius_v(&b);
            let c = corner_weights(&q);
            (c.iter().any(|x| *x != c[0])).then(|| "corners differ".into())
        },
    )
}

/// Replace the weights of the four corners (scaling the homogeneous point so
/// the Cartesian point stays `p_ij / w_ij` symbolic: we set coords to
/// `(x·w, w)` with a fresh symbol x).
fn set_corners(p: &RectPatch<Poly>, w: [Poly; 4]) -> RectPatch<Poly> {
    let (m, n) = p.degree();
    let mut ctrl = p.ctrl().to_vec();
    for (k, (i, j)) in [(0, 0), (m, 0), (0, n), (m, n)].into_iter().enumerate() {
        let x = v(&format!("x{i}{j}"));
        ctrl[i][j] = HPoint {
            coords: vec![x * &w[k], w[k].clone()],
        };
    }
    RectPatch::from_hom(ctrl).expect("same shape")
}

/// The symbolic quadratic map.
fn sym_quadratic() -> Quadratic<Poly> {
    Quadratic {
        alpha1: v("α1"),
        alpha2: v("α2"),
        beta1: v("β1"),
        beta2: v("β2"),
    }
}

/// (9)–(17): the new patch at (s, t) is the old one at (u(s,t), v(s,t)):
/// `H̃(s, t) = H(α(1−s), (1−α)s; β(1−t), (1−β)t)`, a homogeneous identity.
///
/// How it is established (every (m, n) ≤ (5, 5), or (10, 10) with `prove --deep`): α1, α2, β1,
/// β2 are symbols. The map from the net to either side is linear and acts on
/// each homogeneous coordinate alike, so it suffices to check each basis net
/// (one weight 1 at (i, j), everything else 0); the new side's net for it is
/// the coefficient of that weight's symbol in one run on the symbolic weight
/// net. The old side, definition (1) at the homogeneous parameters of the
/// map, is for that basis net
/// `[C(m,i) s^i (1−s)^(m−i) (1−β(s))^j β(s)^(n−j)] · [C(n,j) t^j (1−t)^(n−j) (1−α(t))^i α(t)^(m−i)]`
/// with `α(t) = α1·t + α2·(1−t)` and `β(s) = β1·s + β2·(1−s)`: a product of
/// m + n linear factors in s and m + n in t, whose Bernstein coefficients of
/// degree (m+n, m+n) [`linear_product`] builds factor by factor. Two
/// polynomials in Bernstein form of one bidegree are equal iff their
/// coefficients are, so the identity is m+n+1 squared coefficient equalities
/// per basis net — no evaluation at all.
fn quadratic_keeps_points(max: usize, failure: Option<String>) -> Claim {
    bidegree_claim(
        max,
        "quadratic reparameterization (9)-(17) keeps every point: new(s, t) = old(u(s,t), v(s,t)) (homogeneous identity, common factor E^m F^n), for all α1, α2, β1, β2, s, t",
        &format!("{SRC} eqs. (9)-(17)"),
        Verdict::Proved,
        failure,
    )
}

/// The three claims read off one run of the quadratic map (9)–(17) per
/// bidegree on the net of symbolic weights, with symbolic α1, α2, β1, β2:
/// [`quadratic_keeps_points`], [`quadratic_corner_weights`] and
/// [`eq17_matches`]. The run and the weights' parts (the coefficient of
/// each ω_ij) are computed once for the three, which each computed them
/// for itself until 2026-11-28; the first claim's time holds the shared work.
fn quadratic_map_claims() -> [Claim; 3] {
    let max = max_symbolic();
    let [keeps, corners, eq17] = failures_by_bidegree(max, quadratic_map_checks);
    [
        quadratic_keeps_points(max, keeps),
        quadratic_corner_weights(max, corners),
        eq17_matches(max, eq17),
    ]
}

/// The outcomes at one bidegree of the three checks of
/// [`quadratic_map_claims`], on one run of the map.
fn quadratic_map_checks(m: usize, n: usize) -> [Option<String>; 3] {
    let q = sym_quadratic();
    let p = weight_net(m, n);
    let r = p.quadratic_reparam(&q);
    let corners = corners_differ(&p, &r, m, n);
    match weight_parts(&r, m, n) {
        Err(why) => [Some(why.clone()), corners, Some(why)],
        Ok(parts) => [
            points_differ(&q, &parts, m, n),
            corners,
            eq17_differs(&q, &parts, m, n),
        ],
    }
}

/// The check of `quadratic_keeps_points` at one bidegree: `None` when the
/// identity holds, else what differs. Public for the FLINT peer benchmark
/// (`benches/peers/arith`), which runs the same steps in FLINT.
pub fn quadratic_identity(m: usize, n: usize) -> Option<String> {
    let q = sym_quadratic();
    let r = weight_net(m, n).quadratic_reparam(&q);
    weight_parts(&r, m, n).map_or_else(Some, |parts| points_differ(&q, &parts, m, n))
}

/// `parts[k1][k2][i·(n+1) + j]`: the coefficient of ω_ij in weight
/// (k1, k2) of `r`, the map of the (m, n) net of symbolic weights; an error
/// if `r` is not of bidegree (m+n, m+n) or a weight is not linear and
/// homogeneous in the ω_ij ([`Poly::linear_coefficients`]).
fn weight_parts(r: &RectPatch<Poly>, m: usize, n: usize) -> Result<Vec<Vec<Vec<Poly>>>, String> {
    let d = m + n;
    if r.degree() != (d, d) {
        return Err(format!("bidegree {:?}", r.degree()));
    }
    let names = weight_names(m, n);
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    r.weights()
        .iter()
        .map(|row| {
            row.iter()
                .map(|x| {
                    x.linear_coefficients(&names)
                        .ok_or_else(|| "a weight not linear in the ω_ij".to_string())
                })
                .collect()
        })
        .collect()
}

/// The point identity of [`quadratic_keeps_points`] on the weights' parts
/// ([`weight_parts`]): `None` when every Bernstein coefficient agrees.
fn points_differ(
    q: &Quadratic<Poly>,
    parts: &[Vec<Vec<Poly>>],
    m: usize,
    n: usize,
) -> Option<String> {
    let (s, one_minus_s) = ([Poly::zero(), one()], [one(), Poly::zero()]);
    let alpha = [q.alpha2.clone(), q.alpha1.clone()];
    let beta = [q.beta2.clone(), q.beta1.clone()];
    let complement = |x: &[Poly; 2]| [one() - &x[0], one() - &x[1]];
    for (i0, j0) in (0..=m).flat_map(|i| (0..=n).map(move |j| (i, j))) {
        let s_side = linear_product(
            binomial_scalar::<Poly>(m, i0),
            &[
                (&s, i0),
                (&one_minus_s, m - i0),
                (&complement(&beta), j0),
                (&beta, n - j0),
            ],
        );
        let t_side = linear_product(
            binomial_scalar::<Poly>(n, j0),
            &[
                (&s, j0),
                (&one_minus_s, n - j0),
                (&complement(&alpha), i0),
                (&alpha, m - i0),
            ],
        );
        for (k1, a) in s_side.iter().enumerate() {
            for (k2, b) in t_side.iter().enumerate() {
                if parts[k1][k2][i0 * (n + 1) + j0] != a.clone() * b {
                    return Some(format!(
                        "basis net ({i0},{j0}): Bernstein coefficient ({k1}, {k2})"
                    ));
                }
            }
        }
    }
    None
}

/// The weights of the quadratic map (9)–(17) applied to the (m, n) net of
/// symbolic weights `w_ij` (points 0), with symbolic α1, α2, β1, β2: the
/// output the FLINT peer benchmark compares term by term.
pub fn quadratic_weights(m: usize, n: usize) -> Vec<Vec<Poly>> {
    weight_net(m, n)
        .quadratic_reparam(&sym_quadratic())
        .weights()
}

/// The Bernstein coefficients of `c · Π f_k^e_k` for linear factors
/// `f = f[0]·(1 − x) + f[1]·x` given by their two Bernstein coefficients:
/// multiplying `Σ_k g_k B^p_k` by `f` gives
/// `Σ_k [(p+1−k)·g_k·f[0] + k·g_(k−1)·f[1]]/(p+1) · B^(p+1)_k`
/// (from `(1 − x)B^p_k = (p+1−k)/(p+1)·B^(p+1)_k` and
/// `x·B^p_(k−1) = k/(p+1)·B^(p+1)_k`).
fn linear_product(c: Poly, factors: &[(&[Poly; 2], usize)]) -> Vec<Poly> {
    let times = |g: &[Poly], f: &[Poly; 2]| -> Vec<Poly> {
        let p = g.len() - 1;
        (0..=p + 1)
            .map(|k| {
                let low = (k <= p).then(|| {
                    g[k].clone() * &f[0] * ratio::<Poly>((p + 1 - k) as i64, (p + 1) as i64)
                });
                let high = (k > 0)
                    .then(|| g[k - 1].clone() * &f[1] * ratio::<Poly>(k as i64, (p + 1) as i64));
                low.into_iter()
                    .chain(high)
                    .fold(Poly::zero(), |acc, x| acc + &x)
            })
            .collect()
    };
    factors
        .iter()
        .flat_map(|(f, e)| std::iter::repeat_n(*f, *e))
        .fold(vec![c], |g, f| times(&g, f))
}

/// The names of [`weight_net`]'s weights, `w_ij` at index `i·(n+1) + j`.
fn weight_names(m: usize, n: usize) -> Vec<String> {
    (0..=m)
        .flat_map(|i| (0..=n).map(move |j| format!("w{i}{j}")))
        .collect()
}

/// The net with homogeneous coordinates (0, w_ij): symbolic weights only.
fn weight_net(m: usize, n: usize) -> RectPatch<Poly> {
    let ctrl = (0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| HPoint {
                    coords: vec![Poly::zero(), v(&format!("w{i}{j}"))],
                })
                .collect()
        })
        .collect();
    RectPatch::from_hom(ctrl).expect("a symbolic net")
}

/// The (m, n) net whose control points are all 0 (homogeneous (0, 0)).
fn zero_net(m: usize, n: usize) -> RectPatch<Poly> {
    let zero = HPoint {
        coords: vec![Poly::zero(), Poly::zero()],
    };
    RectPatch::from_hom(vec![vec![zero; n + 1]; m + 1]).expect("a net of (m+1)×(n+1) points")
}

/// The corner weights printed before (18) (bicubic), generalized:
/// ω̃_{0,0} = α2^m β2^n ω_{0,0}, ω̃_{m+n,0} = (1−α2)^m β1^n ω_{m,0},
/// ω̃_{0,m+n} = α1^m (1−β2)^n ω_{0,n}, ω̃_{m+n,m+n} = (1−α1)^m(1−β1)^n ω_{m,n}.
fn quadratic_corner_weights(max: usize, failure: Option<String>) -> Claim {
    bidegree_claim(
        max,
        "corner weights before (18): ω̃_{0,0} = α2^m β2^n ω00, ω̃_{m+n,0} = (1−α2)^m β1^n ω_{m0}, ω̃_{0,m+n} = α1^m(1−β2)^n ω_{0n}, ω̃_{m+n,m+n} = (1−α1)^m(1−β1)^n ω_{mn} (printed for m = n = 3, e.g. ω̃_{6,0} = (1−α2)³β1³ω30, ω̃_{0,6} = (1−β2)³α1³ω03)",
        &format!("{SRC} §2, before eq. (18)"),
        Verdict::Proved,
        failure,
    )
}

/// The check of [`quadratic_corner_weights`]: `r` is the map of the net `p`
/// of bidegree (m, n).
fn corners_differ(p: &RectPatch<Poly>, r: &RectPatch<Poly>, m: usize, n: usize) -> Option<String> {
    let (mu, nu) = (m as u32, n as u32);
    let (a1, a2, b1, b2) = (v("α1"), v("α2"), v("β1"), v("β2"));
    let [w00, wm0, w0n, wmn] = corner_weights(p);
    let want = [
        a2.pow(mu) * &b2.pow(nu) * &w00,
        (one() - &a2).pow(mu) * &b1.pow(nu) * &wm0,
        a1.pow(mu) * &(one() - &b2).pow(nu) * &w0n,
        (one() - &a1).pow(mu) * &(one() - &b1).pow(nu) * &wmn,
    ];
    (corner_weights(r) != want).then(|| "corner weights differ".into())
}

/// (19) generalized: α2 = 1/(1 + (ω00/ω_{m0})^{1/m}), α1 = 1/(1 + (ω_{0n}/ω_{mn})^{1/m}),
/// β1 = β2 = 1/(1 + (α2^m ω00/(α1^m ω_{0n}))^{1/n}) make the four corners
/// equal. Every positive corner quadruple is, for unique a1, a2, b ∈ (0, 1),
/// z > 0: ω00 = (1−a2)^m X, ω_{m0} = a2^m X, ω_{0n} = (1−a1)^m Y, ω_{mn} = a1^m Y
/// with X = a1^m(1−a1)^m(1−b)^n z, Y = a2^m(1−a2)^m b^n z; then (19) gives
/// α2 = a2, α1 = a1, β = b (checked), and the corners come out equal.
/// The map runs on a net with these corners and every other point 0: the
/// corner-weight claim ([`quadratic_corner_weights`], symbolic weights and
/// map) proves that the map's corners depend on the net's corners alone,
/// and the symbolic interior weights cost 45 % of this claim's time.
fn eq19_equal_corners() -> Claim {
    for_all_bidegrees(
        max_symbolic(),
        "(19), generalized to (m, n) with β1 = β2: the quadratic map makes the four corner weights equal (to α2^m β^n ω00)",
        &format!("{SRC} eqs. (18), (19)"),
        Verdict::Proved,
        |m, n| {
            let (a1, a2, b, z) = (v("a1"), v("a2"), v("b"), v("z"));
            let (mu, nu) = (m as u32, n as u32);
            let x = a1.pow(mu) * &(one() - &a1).pow(mu) * &(one() - &b).pow(nu) * &z;
            let y = a2.pow(mu) * &(one() - &a2).pow(mu) * &b.pow(nu) * &z;
            let w = [
                (one() - &a2).pow(mu) * &x,
                a2.pow(mu) * &x,
                (one() - &a1).pow(mu) * &y,
                a1.pow(mu) * &y,
            ];
            // (19)'s roots, as identities: ((1−α2)/α2)^m = ω00/ω_{m0}, ((1−α1)/α1)^m = ω_{0n}/ω_{mn},
            // ((1−β)/β)^n = α2^m ω00 / (α1^m ω_{0n}).
            let roots_ok = w[0].clone() * &a2.pow(mu) == w[1].clone() * &(one() - &a2).pow(mu)
                && w[2].clone() * &a1.pow(mu) == w[3].clone() * &(one() - &a1).pow(mu)
                && a2.pow(mu) * &w[0] * &b.pow(nu) == a1.pow(mu) * &w[2] * &(one() - &b).pow(nu);
            if !roots_ok {
                return Some("the parametrization does not solve (19)".into());
            }
            // The other weights are 0: the corner-weight claim proves, for symbolic weights
            // and maps, that the corners of the map depend on the corners of the net alone.
            let p = set_corners(&zero_net(m, n), w);
            let q = Quadratic { alpha1: a1.clone(), alpha2: a2.clone(), beta1: b.clone(), beta2: b.clone() };
            let c = corner_weights(&p.quadratic_reparam(&q));
            (c.iter().any(|x| *x != c[0])).then(|| "corners differ".into())
        },
    )
}

/// With β1 = β2 = β the (m+n, m+n) patch is an n-fold degree elevation in s
/// of the (m, m+n) patch `mobius_v(β)` then `quadratic_reparam_u(α1, α2)`.
fn compact_form() -> Claim {
    for_all_bidegrees(
        max_symbolic(),
        "ours: with β1 = β2 = β (as in (19)) the (m+n, m+n) result is the n-fold degree elevation in s of an exact (m, m+n) patch (Möbius in v, then the quadratic map in u only), so the standard form exists in bidegree (m, m+n)",
        &format!("{SRC} eqs. (16), (19)"),
        Verdict::Proved,
        |m, n| {
            let p = weight_net(m, n);
            let (a1, a2, b) = (v("α1"), v("α2"), v("β"));
            let q = Quadratic { alpha1: a1.clone(), alpha2: a2.clone(), beta1: b.clone(), beta2: b.clone() };
            let compact = p.mobius_v(&b).quadratic_reparam_u(&a1, &a2);
            (compact.elevate(n, 0) != p.quadratic_reparam(&q)).then(|| "differ".into())
        },
    )
}

/// The paper's sign-carrying `c_{l,i}` (Appendix 1, eq. (12)):
/// `(α2t − α1t − α2)^{m−i}(α1t + α2 − α2t − 1)^i = Σ_l c_{l,i} B_{l,m}(t)`,
/// i.e. `(−1)^m c′`. Returned as `c[l][i]`.
fn paper_c(m: usize, at0: &Poly, at1: &Poly) -> Vec<Vec<Poly>> {
    let cp = quadratic_coefficients(m, at0, at1);
    let sign = if m.is_multiple_of(2) { one() } else { -one() };
    (0..=m)
        .map(|l| (0..=m).map(|i| cp[i][l].clone() * &sign).collect())
        .collect()
}

/// (17) evaluated literally (with corrected c and e) for the weights, compared
/// with ours: equal up to the common sign (−1)^{m+n}. Both are linear in
/// the input weights, so they are compared weight by weight: the
/// coefficient of each ω_ij in our weight (k1, k2) against (17)'s term for
/// it (zero where (i, j) is outside (17)'s sum).
fn eq17_matches(max: usize, failure: Option<String>) -> Claim {
    bidegree_claim(
        max,
        "eq. (17) (with Appendix-1 c_{l,i} and the analogous e_{l,j}) gives our weights times (−1)^{m+n} (equal for m + n even, e.g. bicubic; all negative for m + n odd)",
        &format!("{SRC} eqs. (15)-(17)"),
        Verdict::Proved,
        failure,
    )
}

/// The check of [`eq17_matches`] on the weights' parts ([`weight_parts`]).
fn eq17_differs(
    q: &Quadratic<Poly>,
    parts: &[Vec<Vec<Poly>>],
    m: usize,
    n: usize,
) -> Option<String> {
    let c = paper_c(m, &q.alpha2, &q.alpha1);
    let e = paper_c(n, &q.beta2, &q.beta1);
    let d = m + n;
    let sign = if d.is_multiple_of(2) { 1 } else { -1 };
    for k1 in 0..=d {
        for k2 in 0..=d {
            let ours = &parts[k1][k2];
            for (i, j) in (0..=m).flat_map(|i| (0..=n).map(move |j| (i, j))) {
                let term = if (k1.saturating_sub(n)..=k1.min(m)).contains(&i)
                    && (k2.saturating_sub(m)..=k2.min(n)).contains(&j)
                {
                    let num = exact_bezier::algebra::binomial(m, k2 - j)
                        * exact_bezier::algebra::binomial(n, j)
                        * exact_bezier::algebra::binomial(n, k1 - i)
                        * exact_bezier::algebra::binomial(m, i);
                    let den = exact_bezier::algebra::binomial(d, k2)
                        * exact_bezier::algebra::binomial(d, k1);
                    c[k2 - j][i].clone()
                        * &e[k1 - i][j]
                        * &Poly::constant(BigRational::new(num * sign, den))
                } else {
                    Poly::zero()
                };
                if ours[i * (n + 1) + j] != term {
                    return Some(format!("weight ({k1},{k2}), the part of ω_{i}{j}"));
                }
            }
        }
    }
    None
}

/// (15): B_{a,p}(s) B_{b,q}(s) = C(p,a)C(q,b)/C(p+q,a+b) B_{a+b,p+q}(s).
fn bernstein_product_eq15() -> Claim {
    let s = v("s");
    let mut bad = None;
    for p in 0..=MAX {
        for q in 0..=MAX {
            for a in 0..=p {
                for b in 0..=q {
                    let lhs = bernstein::<Poly>(a, p, &s) * &bernstein::<Poly>(b, q, &s);
                    let f = BigRational::new(
                        exact_bezier::algebra::binomial(p, a)
                            * exact_bezier::algebra::binomial(q, b),
                        exact_bezier::algebra::binomial(p + q, a + b),
                    );
                    if lhs != bernstein::<Poly>(a + b, p + q, &s).scale(&f) && bad.is_none() {
                        bad = Some(format!("p={p}, q={q}, a={a}, b={b}"));
                    }
                }
            }
        }
    }
    Claim::check(
        &format!("eq. (15)'s product rule B_{{i,m}}(s)B_{{l,n}}(s) = C(m,i)C(n,l)/C(m+n,i+l)·B_{{i+l,m+n}}(s), hence bidegree (m+n, m+n) — checked for every m, n ≤ {MAX}"),
        &format!("{SRC} eq. (15)"),
        Verdict::Proved,
        bad.is_none(),
        bad.unwrap_or_else(|| format!("identity in s for all degrees ≤ {MAX}")),
    )
    .with_bound(format!("m, n ≤ {MAX}"))
}

/// Appendix 1: each printed c_{l,i} (bicubic) against ours (Display of Poly).
fn appendix_c() -> Vec<Claim> {
    let (a1, a2) = (v("α1"), v("α2"));
    let c = paper_c(3, &a2, &a1);
    let third = ratio::<Poly>(1, 3);
    let printed: [(usize, usize, &str, Poly); 16] = [
        (0, 0, "−α2³", -a2.pow(3)),
        (1, 0, "−α2³α1", -a2.pow(3) * &a1),
        (2, 0, "−α2α1²", -a2.clone() * &a1.pow(2)),
        (3, 0, "−α1³", -a1.pow(3)),
        (0, 1, "α2²(α2 − 1)", a2.pow(2) * &(a2.clone() - one())),
        (
            1,
            1,
            "α2(3α1α2 − 2α1 − α2)/3",
            a2.clone() * &(Poly::from_int(3) * &a1 * &a2 - Poly::from_int(2) * &a1 - &a2) * &third,
        ),
        (
            2,
            1,
            "α1(3α1α2 − α1 − 2α2)/3",
            a1.clone() * &(Poly::from_int(3) * &a1 * &a2 - &a1 - Poly::from_int(2) * &a2) * &third,
        ),
        (3, 1, "α1²(α1 − 1)", a1.pow(2) * &(a1.clone() - one())),
        (
            0,
            2,
            "−α2(α2 − 1)²",
            -a2.clone() * &(a2.clone() - one()).pow(2),
        ),
        (
            1,
            2,
            "−(α2 − 1)(−2α2 + 3α2α1 − α1)/3",
            -(a2.clone() - one())
                * &(Poly::from_int(-2) * &a2 + Poly::from_int(3) * &a2 * &a1 - &a1)
                * &third,
        ),
        (
            2,
            2,
            "−(−1 + α1)(−2α1 + 3α2α1 − α2)/3",
            -(a1.clone() - one())
                * &(Poly::from_int(-2) * &a1 + Poly::from_int(3) * &a2 * &a1 - &a2)
                * &third,
        ),
        (
            3,
            2,
            "−α1(α1 − 1)²",
            -a1.clone() * &(a1.clone() - one()).pow(2),
        ),
        (0, 3, "(α2 − 1)³", (a2.clone() - one()).pow(3)),
        (
            1,
            3,
            "(α2 − 1)²(α1 − 1)",
            (a2.clone() - one()).pow(2) * &(a1.clone() - one()),
        ),
        (
            2,
            3,
            "(α1 − 1)²(α2 − 1)",
            (a1.clone() - one()).pow(2) * &(a2.clone() - one()),
        ),
        (3, 3, "(α1 − 1)³", (a1.clone() - one()).pow(3)),
    ];
    printed
        .into_iter()
        .map(|(l, i, text, poly)| {
            let ours = &c[l][i];
            let agrees = *ours == poly;
            let expected = if (l, i) == (1, 0) {
                Verdict::Mismatch
            } else {
                Verdict::Reproduced
            };
            Claim::compare(
                &format!("Appendix 1: c_{{{l},{i}}} = {text}"),
                &format!("{SRC} Appendix 1, eq. (12)"),
                expected,
                agrees,
                &format!("{text} = {poly}"),
                &format!("{ours}"),
            )
        })
        .collect()
}

/// (11), (13), (14): the printed denominators, checked by cross
/// multiplication: `B_{j,n}(v)·D = N_j` with `v = V/W`,
/// `B_{j,n}(v) = C(n,j) V^j (W − V)^{n−j} / W^n`.
fn denominators() -> Vec<Claim> {
    let (s, t) = (v("s"), v("t"));
    let (a1, a2, b1, b2) = (v("α1"), v("α2"), v("β1"), v("β2"));
    let two = Poly::from_int(2);
    // The u side, m = 3 (eq. 11 / 13): numerator Σ_l c_{l,i} B_{i,m}(s) B_{l,m}(t).
    let check = |m: usize, x: &Poly, y: &Poly, c0: &Poly, c1: &Poly, den: &Poly| -> bool {
        // x is the variable of the map (s for u), y the interpolating one (t).
        let c = paper_c(m, c0, c1);
        let a = c1.clone() * y + &(c0.clone() * &(one() - y));
        let (vn, vd) = ((a.clone() - one()) * x, two.clone() * &a * x - x - &a);
        (0..=m).all(|i| {
            let num: Poly = (0..=m).fold(Poly::zero(), |acc, l| {
                acc + c[l][i].clone() * &bernstein::<Poly>(i, m, x) * &bernstein::<Poly>(l, m, y)
            });
            let lhs = binomial_scalar::<Poly>(m, i)
                * &vn.pow(i as u32)
                * &(vd.clone() - &vn).pow((m - i) as u32)
                * den;
            lhs == num * &vd.pow(m as u32)
        })
    };
    let d1 = (two.clone() * &s * &a1 * &t + two.clone() * &s * &a2
        - two.clone() * &s * &a2 * &t
        - &s
        - a1.clone() * &t
        - &a2
        + a2.clone() * &t)
        .pow(3);
    let d11 = (two.clone() * &s * &a1 + two.clone() * &s * &a2
        - two.clone() * &s * &a2 * &t
        - &s
        - a1.clone() * &t
        - &a2
        + a2.clone() * &t)
        .pow(3);
    let d2 = |e: u32| {
        (two.clone() * &s * &b1 * &t + two.clone() * &t * &b2
            - two.clone() * &s * &b2 * &t
            - &t
            - b1.clone() * &s
            - &b2
            + b2.clone() * &s)
            .pow(e)
    };
    let d2_printed = (two.clone() * &s * &b1 * &t + two.clone() * &t * &b2
        - two.clone() * &s * &a2 * &t
        - &t
        - a1.clone() * &s
        - &a2
        + a2.clone() * &s)
        .pow(3);
    let src = |eq: &str| format!("{SRC} eq. {eq}");
    vec![
        Claim::check(
            "eq. (13): B_{i,3}(u) = Σ_l c_{l,i} B_{i,3}(s) B_{l,3}(t) / D1 with D1 = (2sα1t + 2sα2 − 2sα2t − s − α1t − α2 + α2t)^3 (corrected c_{1,0})",
            &src("(13)"),
            Verdict::Proved,
            check(3, &s, &t, &a2, &a1, &d1),
            "cross-multiplied identity in Q[s, t, α1, α2]".into(),
        ),
        Claim::check(
            "eq. (11) as printed: denominator (2sα1 + 2sα2 − 2sα2t − s − α1t − α2 + α2t)^m",
            &src("(11)"),
            Verdict::Refuted,
            check(3, &s, &t, &a2, &a1, &d11),
            "misprint: the first term must be 2sα1t (as in D1 of (13)): the denominator is (2αs − s − α)^m with α = α1t + α2(1−t)".into(),
        ),
        Claim::check(
            "eq. (14) as printed: D2 = (2sβ1t + 2tβ2 − 2sα2t − t − α1s − α2 + α2s)^m",
            &src("(14)"),
            Verdict::Refuted,
            check(3, &t, &s, &b2, &b1, &d2_printed),
            "misprint: α's in place of β's; correct D2 = (2sβ1t + 2tβ2 − 2sβ2t − t − β1s − β2 + β2s)^n = (2βt − t − β)^n with β = β1s + β2(1−s)".into(),
        ),
        Claim::check(
            "eq. (14) corrected: D2 = (2sβ1t + 2tβ2 − 2sβ2t − t − β1s − β2 + β2s)^n (checked n = 3)",
            &src("(14)"),
            Verdict::Proved,
            check(3, &t, &s, &b2, &b1, &d2(3)),
            "cross-multiplied identity in Q[s, t, β1, β2]".into(),
        ),
        Claim::check(
            "eq. (14)'s exponent m: with the corrected base but exponent m = 3 for n = 2",
            &src("(14)"),
            Verdict::Refuted,
            check(2, &t, &s, &b2, &b1, &d2(3)),
            "the exponent must be n (the v-degree): for (m, n) = (3, 2) the identity fails with exponent 3 and holds with 2 (next claim)".into(),
        ),
        Claim::check(
            "eq. (14) corrected, exponent n: n = 2",
            &src("(14)"),
            Verdict::Proved,
            check(2, &t, &s, &b2, &b1, &d2(2)),
            "cross-multiplied identity in Q[s, t, β1, β2]".into(),
        ),
    ]
}

#[cfg(test)]
mod tests {
    //! The verdicts discriminate: a wrong formula fed through the same
    //! claim code is refuted.
    use super::*;

    #[test]
    fn wrong_weight_rules_are_refuted() {
        assert_eq!(weight_rule().verdict, Verdict::Proved);
        // Index shifted: (1 − α)^{m−i} α^i, the exponents of the other end.
        let swapped = |i: usize, j: usize, m: usize, n: usize| weight_factor(m - i, j, m, n);
        assert_eq!(weight_rule_with(swapped).verdict, Verdict::Refuted);
        // Sign flipped in one factor: (α − 1)^i.
        let flipped = |i: usize, j: usize, m: usize, n: usize| {
            weight_factor(i, j, m, n) * (-one()).pow(i as u32)
        };
        assert_eq!(weight_rule_with(flipped).verdict, Verdict::Refuted);
    }

    /// `linear_product`'s Bernstein coefficients, summed against the
    /// Bernstein basis, give the product expanded directly in x.
    #[test]
    fn linear_product_is_the_product_in_bernstein_form() {
        let (x, a, b) = (v("x"), v("a"), v("b"));
        let f = [a.clone(), b.clone()]; // a(1 − x) + b·x
        let s = [Poly::zero(), one()]; // x
        let coeffs = linear_product(ratio(3, 2), &[(&f, 2), (&s, 1)]);
        assert_eq!(coeffs.len(), 4);
        let in_x: Poly = coeffs
            .iter()
            .enumerate()
            .map(|(k, c)| c.clone() * &bernstein::<Poly>(k, 3, &x))
            .sum();
        let linear = a.clone() * &(one() - &x) + &(b * &x);
        assert_eq!(in_x, linear.pow(2) * &x * ratio::<Poly>(3, 2));
        // By hand: the coefficients of (3/2)·x·(a(1 − x) + b x)² are
        // (0, a²/2, ab, 3b²/2).
        assert_eq!(coeffs[1], a.pow(2) * ratio::<Poly>(1, 2));
    }
}
