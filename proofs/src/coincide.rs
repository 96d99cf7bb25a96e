//! Coincidence of rational patches (issue 4; source 000 §3).
//!
//! Claims, with symbolic weights `w_{i,j}`, `b_{i,j}`, Möbius parameters
//! `α`, `β` and scale `k` (bidegrees (m, n) with 1 ≤ m ≤ 3, 0 ≤ n ≤ 3;
//! n = 0 is the curve case):
//!
//! * **invariance**: the weight invariants `I_{i,j}` computed by our code
//!   (`invariant_parts`) take the same value on `w` and on
//!   `k · Möbius_v(β) · Möbius_u(α) · w` (eqs 4, 5) — as the polynomial
//!   identity `N(w)·D(w') = N(w')·D(w)`;
//! * **completeness with witness**: for arbitrary `w`, `b`, the witness
//!   `k̂ = b_{0,0}/w_{0,0}`, `ρ̂ = b_{1,0}w_{0,0}/(w_{1,0}b_{0,0})`,
//!   `σ̂ = b_{0,1}w_{0,0}/(w_{0,1}b_{0,0})` satisfies
//!   `numer(k̂ ρ̂^i σ̂^j w_{i,j} − b_{i,j}) = w_{0,0} b_{0,0} · (N(w)D(b) − N(b)D(w))`,
//!   so (weights non-zero) the witness reproduces b exactly iff every
//!   invariant agrees — and ρ̂, σ̂, k̂ are rational, hence so are
//!   `α = 1/(1 + ρ̂)`, `β = 1/(1 + σ̂)`;
//! * **Möbius after elevation** carries the common linear factor
//!   `L(s) = α(1 − s) + (1 − α)s`: `Möbius(elevate(c)) = L · Möbius(c)` in
//!   Bernstein form (curve degrees 1–4), which is why the reduction needs a gcd;
//! * the conjecture that common factors of a tensor patch split into a
//!   u-part times a v-part, refuted by `1 + uv`;
//! * source 000 Example 3 vs Example 1, decided exactly.

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::algebra::{binomial_scalar, ratio};
use exact_bezier::coincide::minimal::{minimal_rect, multiply_components};
use exact_bezier::coincide::{coincide, invariant_parts, Options};
use exact_bezier::curve::RationalCurve;
use exact_bezier::hpoint::HPoint;
use exact_bezier::io::read_patches;
use exact_bezier::patch::Patch;
use exact_bezier::rect::RectPatch;
use num_rational::BigRational;

const SOURCE: &str = "ours (issue 4)";

/// Symbolic weights `prefix{i}_{j}` of bidegree (m, n).
fn weights(prefix: &str, m: usize, n: usize) -> Vec<Vec<Poly>> {
    (0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| Poly::var(&format!("{prefix}{i}_{j}")))
                .collect()
        })
        .collect()
}

fn symbolic_patch(w: &[Vec<Poly>]) -> RectPatch<Poly> {
    let pts = w
        .iter()
        .enumerate()
        .map(|(i, r)| {
            (0..r.len())
                .map(|j| vec![Poly::var(&format!("p{i}_{j}"))])
                .collect()
        })
        .collect();
    RectPatch::new(pts, w.to_vec()).expect("symbolic weights are non-zero")
}

fn pivots(n: usize) -> (Option<usize>, Option<usize>) {
    (Some(1), (n > 0).then_some(1))
}

fn positions(m: usize, n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..=m).flat_map(move |i| (0..=n).map(move |j| (i, j)))
}

fn invariance(m: usize, n: usize) -> Claim {
    let w = weights("w", m, n);
    let (alpha, beta, k) = (Poly::var("alpha"), Poly::var("beta"), Poly::var("k"));
    let moved = symbolic_patch(&w)
        .mobius_u(&alpha)
        .mobius_v(&beta)
        .scale_weights(&k)
        .weights();
    let (pu, pv) = pivots(n);
    let bad: Vec<String> = positions(m, n)
        .filter(|&(i, j)| {
            let (na, da) = invariant_parts(|a, b| w[a][b].clone(), i, j, pu, pv);
            let (nb, db) = invariant_parts(|a, b| moved[a][b].clone(), i, j, pu, pv);
            na * &db != nb * &da
        })
        .map(|(i, j)| format!("I_{{{i},{j}}}"))
        .collect();
    Claim::check(
        &format!("bidegree ({m},{n}): every weight invariant I_{{i,j}} is unchanged by Möbius maps in u and v and uniform weight scaling"),
        "ours (issue 4); maps from source 000 eqs (2)–(5)",
        Verdict::Proved,
        bad.is_empty(),
        if bad.is_empty() {
            format!("N(w)·D(w') = N(w')·D(w) as polynomials in w, α, β, k for all {} positions", (m + 1) * (n + 1))
        } else {
            format!("fails at {}", bad.join(", "))
        },
    )
}

fn completeness(m: usize, n: usize) -> Claim {
    let (w, b) = (weights("w", m, n), weights("b", m, n));
    let (pu, pv) = pivots(n);
    let one = Poly::from_int(1);
    let bad: Vec<String> = positions(m, n)
        .filter(|&(i, j)| {
            // k̂ ρ̂^i σ̂^j w_ij − b_ij over its denominator w00 (w10 b00)^i (w01 b00)^j.
            let rho_num = b[1][0].clone() * &w[0][0];
            let rho_den = w[1][0].clone() * &b[0][0];
            let (sig_num, sig_den) = if n > 0 {
                (b[0][1].clone() * &w[0][0], w[0][1].clone() * &b[0][0])
            } else {
                (one.clone(), one.clone())
            };
            let num = b[0][0].clone() * rho_num.pow(i as u32) * sig_num.pow(j as u32) * &w[i][j];
            let den = w[0][0].clone() * rho_den.pow(i as u32) * sig_den.pow(j as u32);
            let witness_num = num - b[i][j].clone() * &den;
            let (na, da) = invariant_parts(|x, y| w[x][y].clone(), i, j, pu, pv);
            let (nb, db) = invariant_parts(|x, y| b[x][y].clone(), i, j, pu, pv);
            witness_num != w[0][0].clone() * &b[0][0] * (na * &db - nb * &da)
        })
        .map(|(i, j)| format!("({i},{j})"))
        .collect();
    Claim::check(
        &format!("bidegree ({m},{n}): the rational witness k̂ = b00/w00, ρ̂ = b10·w00/(w10·b00), σ̂ = b01·w00/(w01·b00) maps weights w to b exactly iff every invariant I_{{i,j}} agrees (completeness)"),
        SOURCE,
        Verdict::Proved,
        bad.is_empty(),
        if bad.is_empty() {
            "numer(k̂ρ̂^iσ̂^j w_ij − b_ij) = w00·b00·(N(w)D(b) − N(b)D(w)) for every position, as polynomials".into()
        } else {
            format!("fails at {}", bad.join(", "))
        },
    )
}

fn mobius_after_elevation(m: usize) -> Claim {
    let pts: Vec<Vec<Poly>> = (0..=m).map(|i| vec![Poly::var(&format!("p{i}"))]).collect();
    let c = RationalCurve::new(pts, Poly::vars("w", m + 1)).expect("symbolic weights");
    let alpha = Poly::var("alpha");
    let lhs = c.elevate(1).mobius(&alpha);
    let small = c.mobius(&alpha);
    let s = small.ctrl();
    let one_minus = Poly::from_int(1) - &alpha;
    let rhs: Vec<HPoint<Poly>> = (0..=m + 1)
        .map(|k| {
            let mut acc = HPoint::zero(1);
            if k <= m {
                let f = alpha.clone()
                    * binomial_scalar::<Poly>(m + 1 - k, 1)
                    * ratio::<Poly>(1, m as i64 + 1);
                acc = acc.add(&s[k].scale(&f));
            }
            if k > 0 {
                let f =
                    one_minus.clone() * Poly::from_int(k as i64) * ratio::<Poly>(1, m as i64 + 1);
                acc = acc.add(&s[k - 1].scale(&f));
            }
            acc
        })
        .collect();
    Claim::check(
        &format!("degree {m}: Möbius(α) after elevation equals L·Möbius(α) with L(s) = α(1 − s) + (1 − α)s — a common linear factor of all homogeneous components"),
        SOURCE,
        Verdict::Proved,
        lhs.ctrl() == rhs.as_slice(),
        "Bernstein product (Σ c_i B_{i,m})(α B_{0,1} + (1−α) B_{1,1}) = Σ_k [(m+1−k)α c_k + k(1−α) c_{k−1}]/(m+1) B_{k,m+1}, compared coordinate by coordinate".into(),
    )
}

fn factor_splitting() -> Claim {
    // A (1, 2) patch with distinct corner weights (no common factor).
    let q = |x: i64, y: i64, z: i64| vec![ratio(x, 1), ratio(y, 1), ratio(z, 1)];
    let base = RectPatch::new(
        vec![
            vec![q(0, 0, 0), q(0, 1, 2), q(0, 3, 1)],
            vec![q(2, 0, 1), q(2, 2, 5), q(1, 3, 0)],
        ],
        vec![
            vec![ratio(1, 1), ratio(2, 1), ratio(1, 2)],
            vec![ratio(3, 1), ratio(1, 1), ratio(1, 1)],
        ],
    )
    .expect("valid patch");
    let one = || ratio::<BigRational>(1, 1);
    let big = multiply_components(&base, &[vec![one(), one()], vec![one(), ratio(2, 1)]]);
    let red = minimal_rect(&big).expect("positive corner weights");
    let g = red.factor.to_poly("u", "v");
    let zero = BigRational::from_integer(0.into());
    let (gu, gv) = (g.subst_rational("v", &zero), g.subst_rational("u", &zero));
    let g00 = gu.subst_rational("u", &zero);
    let splits = g.clone() * &g00 == gu * &gv;
    Claim::check(
        "a common factor of a tensor patch's homogeneous components is a product of a factor in u alone and a factor in v alone",
        "ours (a tempting shortcut for minimal degree, checked)",
        Verdict::Refuted,
        splits,
        format!(
            "counterexample: a (1,2) patch times 1 + uv is a (2,3) patch whose components have gcd {} (irreducible, mixed: g(u,v)·g(0,0) ≠ g(u,0)·g(0,v)); our bivariate gcd reduces it back to bidegree {:?} and the original net (equal: {}). Correct statement: the gcd is a general bivariate polynomial",
            red.common_factor,
            red.degree_after,
            red.patch == base
        ),
    )
    .given(
        red.degree_after == base.degree(),
        "the bivariate gcd removes the planted factor (bidegree back to the base's)",
    )
}

fn fixture(text: &str) -> Patch<BigRational> {
    read_patches(text).expect("fixture parses").remove(0)
}

fn example3_vs_example1() -> Vec<Claim> {
    let ex1 = fixture(include_str!("../../tests/fixtures/yang_yong_example1.json"));
    let ex3 = fixture(include_str!("../../tests/fixtures/yang_yong_example3.json"));
    let exact = coincide(&ex1, &ex3, Options::default()).expect("valid fixtures");
    let filtered = coincide(&ex1, &ex3, Options::filtered()).expect("valid fixtures");
    let by = filtered.decided_by;
    let Patch::Rect(r3) = &ex3 else {
        unreachable!("fixture 3 is a rect patch")
    };
    let w = r3.weights();
    let (lhs, rhs) = (w[0][0].clone() * &w[2][2], w[2][0].clone() * &w[0][2]);
    let rho2 = w[0][0].clone() / &w[2][0];
    let sigma2 = w[0][0].clone() / &w[0][2];
    vec![
        Claim::check(
            "Example 3 (weights 1.44, 0.885, 3.24, 4.22, 6.2, 10.13, 7.84, 9.65, 17.64) is the same surface as Example 1",
            "000 §3 Example 3 (\"所给定曲面和例 1 中曲面是同一个曲面\")",
            Verdict::Refuted,
            exact.coincident || filtered.coincident,
            format!(
                "exact decision: {}; the filtered predicate agrees ({by:?}). The printed weights are Example 1's \
                 Möbius image rounded to 3–4 digits: Example 3's own standardization is exact (ρ² = ω00/ω20 = {rho2}, \
                 σ² = ω00/ω02 = {sigma2}, rational squares, so α = 3/5, β = 7/10 and all standard weights rational) while \
                 Example 1's needs ρ = √(8/3), so their standard forms cannot be equal either; they agree only to ≈ 3 digits",
                exact.reason
            ),
        ),
        Claim::compare(
            "Example 3: ω00·ω22 = ω02·ω20 with the printed value 25.4036",
            "000 §3 Example 3",
            Verdict::Mismatch,
            lhs == ratio(254036, 10000),
            "25.4036",
            &format!("ω00·ω22 = {lhs} and ω20·ω02 = {rhs} (Theorem 1 holds exactly, the printed product is a misprint)"),
        )
        .given(lhs == rhs, "ω00·ω22 = ω02·ω20 exactly (Theorem 1 applies)"),
    ]
}

/// The family's claims.
pub fn claims() -> Vec<Claim> {
    let mut out = Vec::new();
    for m in 1..=3 {
        for n in 0..=3 {
            out.push(invariance(m, n));
            out.push(completeness(m, n));
        }
    }
    out.extend((1..=4).map(mobius_after_elevation));
    out.push(factor_splitting());
    out.extend(example3_vs_example1());
    out
}
