//! The lecture's degree reduction (source 001, "降阶"): the elevation
//! relation, the two recursions `P#` and `P*`, the Forrest and Farin
//! schemes, and the constrained least-squares perturbation — proved on
//! symbolic homogeneous control points for every degree `n ≤ 8`.

use super::{Claim, Verdict};
use exact_bezier::algebra::Poly;
use exact_bezier::algebra::{binomial, ratio, Tolerance};
use exact_bezier::curve::reduction::Reduction;
use exact_bezier::curve::RationalCurve;
use exact_bezier::hpoint::HPoint;
use num_traits::Zero;

const SOURCE: &str = "001 lecture, 降阶";
const MAX_N: usize = 10;

/// A degree-`n` curve with symbolic homogeneous points `(q{i}, w{i})`.
fn sym(n: usize, prefix: &str) -> RationalCurve<Poly> {
    let ctrl = (0..=n)
        .map(|i| HPoint {
            coords: vec![
                Poly::var(&format!("{prefix}q{i}")),
                Poly::var(&format!("{prefix}w{i}")),
            ],
        })
        .collect();
    RationalCurve::from_hom(ctrl).expect("symbols")
}

fn over(
    claim: &str,
    degrees: std::ops::RangeInclusive<usize>,
    how: &str,
    check: impl Fn(usize) -> bool,
) -> Claim {
    let (lo, hi) = (*degrees.start(), *degrees.end());
    let failure = degrees.into_iter().find(|&n| !check(n));
    let range = format!("{lo} ≤ n ≤ {hi}");
    Claim::check(
        &format!("{claim} — checked for every {range}"),
        SOURCE,
        Verdict::Proved,
        failure.is_none(),
        failure.map_or(format!("{how}; each n an identity"), |n| {
            format!("fails at n = {n}")
        }),
    )
    .with_bound(range)
}

/// Σ over coordinates and points of `a_i · b_i`.
fn inner(a: &[HPoint<Poly>], b: &[HPoint<Poly>]) -> Poly {
    a.iter()
        .zip(b)
        .flat_map(|(x, y)| x.coords.iter().zip(&y.coords).map(|(u, v)| u.clone() * v))
        .fold(Poly::zero(), |acc, x| acc + x)
}

/// The family's claims.
pub fn claims() -> Vec<Claim> {
    vec![
        over(
            "elevation relation: P_i = ((n−i)/n) P*_i + (i/n) P*_{i−1} (P* of degree n−1) is degree elevation",
            1..=MAX_N,
            "symbolic homogeneous P*_i: the printed relation equals elevate(1) coordinate by coordinate",
            |n| {
                let low = sym(n - 1, "s");
                let c = low.ctrl();
                let printed: Vec<HPoint<Poly>> = (0..=n)
                    .map(|i| {
                        let a = if i < n { c[i].scale(&ratio((n - i) as i64, n as i64)) } else { HPoint::zero(1) };
                        let b = if i > 0 { c[i - 1].scale(&ratio(i as i64, n as i64)) } else { HPoint::zero(1) };
                        a.add(&b)
                    })
                    .collect();
                low.elevate(1).ctrl() == printed.as_slice()
            },
        ),
        over(
            "the recursions P#_i = (nP_i − iP#_{i−1})/(n−i) (i = 0…n−1) and P*_{i−1} = (nP_i − (n−i)P*_i)/i (i = n…1) each recover P* from its elevation",
            1..=MAX_N,
            "symbolic homogeneous P*_i of degree n−1, elevated then reduced by each recursion",
            |n| {
                let low = sym(n - 1, "s");
                let up = low.elevate(1);
                up.reduce_forward().ok().as_deref() == Some(low.ctrl())
                    && up.reduce_backward().ok().as_deref() == Some(low.ctrl())
            },
        ),
        over(
            "Forrest's scheme (P# for i ≤ ⌊(n−1)/2⌋, P* after), Farin's scheme ((1 − i/(n−1))P#_i + (i/(n−1))P*_i) and the least-squares reduction invert elevation exactly",
            2..=MAX_N,
            "symbolic homogeneous P*_i of degree n−1",
            |n| {
                let low = sym(n - 1, "s");
                let up = low.elevate(1);
                [Reduction::Forrest, Reduction::Farin, Reduction::LeastSquares]
                    .iter()
                    .all(|&s| up.reduce(s).ok().as_ref() == Some(&low))
            },
        ),
        over(
            "Forrest's and Farin's schemes interpolate the end points of any curve: P̂_0 = P_0, P̂_{n−1} = P_n",
            2..=MAX_N,
            "symbolic homogeneous P_i (not an elevation)",
            |n| {
                let c = sym(n, "p");
                [Reduction::Forrest, Reduction::Farin].iter().all(|&s| {
                    let r = c.reduce(s).expect("degree ≥ 2");
                    r.ctrl()[0] == c.ctrl()[0] && r.ctrl()[n - 1] == c.ctrl()[n]
                })
            },
        ),
        over(
            "least squares: ε_i = −(−1)ⁱC(n,i)D/C(2n,n), D = Σ(−1)ʲC(n,j)P_j, satisfies Σ(−1)ⁱC(n,i)(P_i + ε_i) = 0 (the perturbed curve has degree n−1)",
            1..=MAX_N,
            "symbolic homogeneous P_i; Σ_i C(n,i)² = C(2n,n) checked exactly",
            |n| {
                let c = sym(n, "p");
                let eps = c.lsq_perturbation().expect("n ≥ 1");
                let moved: Vec<HPoint<Poly>> = c.ctrl().iter().zip(&eps).map(|(a, e)| a.add(e)).collect();
                let squares = (0..=n).map(|i| binomial(n, i).pow(2)).sum::<num_bigint::BigInt>();
                squares == binomial(2 * n, n)
                    && RationalCurve::from_hom(moved).is_ok_and(|m| m.degeneracy().is_zero_within(Tolerance::EXACT))
            },
        ),
        over(
            "least squares is optimal: ε is orthogonal to every feasible change, so for any perturbation δ meeting the constraint Σ|δ_i|² = Σ|ε_i|² + Σ|δ_i − ε_i|² ≥ Σ|ε_i|²",
            1..=MAX_N,
            "symbolic P_i and a symbolic null-space vector z (z_0…z_{n−1} free, z_n fixed by Σ(−1)ⁱC(n,i)z_i = 0): Σ ε_i·z_i = 0 identically; δ − ε is such a z",
            |n| {
                let c = sym(n, "p");
                let eps = c.lsq_perturbation().expect("n ≥ 1");
                // a_n = (−1)ⁿ, so z_n = −(−1)ⁿ Σ_{i<n} (−1)ⁱ C(n,i) z_i.
                let mut z: Vec<HPoint<Poly>> = (0..n)
                    .map(|i| HPoint { coords: vec![Poly::var(&format!("zq{i}")), Poly::var(&format!("zw{i}"))] })
                    .collect();
                let partial = RationalCurve::from_hom({
                    let mut full = z.clone();
                    full.push(HPoint::zero(1));
                    full
                })
                .expect("symbols")
                .degeneracy();
                let sign = if n % 2 == 0 { -1 } else { 1 };
                z.push(partial.scale(&ratio(sign, 1)));
                let zc = RationalCurve::from_hom(z.clone()).expect("symbols");
                zc.degeneracy().is_zero_within(Tolerance::EXACT) && inner(&eps, &z).is_zero()
            },
        ),
    ]
}
