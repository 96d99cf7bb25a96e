//! The symbolic engine ([`Poly`]) on the identity that the SymPy peer also
//! checks: the Möbius maps (2)(3) of source 000 in both directions keep
//! every point of a fully symbolic rational (m, m) patch (symbolic points,
//! weights, α, β, s, t). Two formulations, each mirrored step by step by the
//! peer (`benches/peers/sympy_mobius.py`):
//!
//! - `mobius identity/m=…`: the library's own algorithms (`mobius_u`,
//!   `mobius_v`, then de Casteljau by `eval_hom` and
//!   `eval_hom_projective`), as in `proofs/src/yang_yong.rs`;
//! - `mobius identity, Bernstein sums/m=…`: both sides written as the
//!   defining double Bernstein sums and expanded.
//!
//! Two more groups time the kernels of the quadratic reparameterization
//! claims (no peer):
//!
//! - `linear combination/k=…`: `Σ q_i·p_i` of k polynomials of a few
//!   hundred terms in four variables with rational `q_i`, as the grid
//!   evaluation of `quadratic_keeps_points` sums them;
//! - `quadratic reparam/m=…`: `RectPatch::quadratic_reparam` of the fully
//!   symbolic (m, m) weight net with symbolic α1, α2, β1, β2.
//!
//! Run with the peer: `benches/peers/sympy_bench.sh`. Alone:
//! `cargo bench --bench poly -- --warm-up-time 1 --measurement-time 2`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::hpoint::HPoint;
use exact_bezier::rect::RectPatch;
use exact_bezier::reparam::Quadratic;
use exact_bezier::{algebra::binomial_scalar, bernstein::bernstein, ratio, BigRational, Poly};
use exact_bezier_proofs::yang_yong::mobius_uv_sides;
use num_traits::{One, Zero};

/// The bidegrees of the peer table.
const DEGREES: [usize; 4] = [3, 5, 6, 8];

/// Both coordinates of both sides as double Bernstein sums:
/// `Σ B_i(s)B_j(t)·ω̃_ij·c_ij` against
/// `Σ C(m,i)C(m,j)((1−α)s)^i(α(1−s))^{m−i}((1−β)t)^j(β(1−t))^{m−j}·c_ij`,
/// each summed by `Poly`'s balanced `Sum`.
fn bernstein_sums(m: usize) -> bool {
    let (a, b, s, t) = (
        Poly::var("α"),
        Poly::var("β"),
        Poly::var("s"),
        Poly::var("t"),
    );
    let one = Poly::one();
    let e = |x: usize| x as u32;
    ["p", "w"].iter().all(|k| {
        let pairs = || (0..=m).flat_map(|i| (0..=m).map(move |j| (i, j)));
        let new: Poly = pairs()
            .map(|(i, j)| {
                let mob = (one.clone() - &a).pow(e(i))
                    * a.pow(e(m - i))
                    * (one.clone() - &b).pow(e(j))
                    * b.pow(e(m - j));
                bernstein::<Poly>(i, m, &s)
                    * bernstein::<Poly>(j, m, &t)
                    * mob
                    * Poly::var(&format!("{k}{i}{j}"))
            })
            .sum();
        let old: Poly = pairs()
            .map(|(i, j)| {
                binomial_scalar::<Poly>(m, i)
                    * binomial_scalar::<Poly>(m, j)
                    * ((one.clone() - &a) * &s).pow(e(i))
                    * (a.clone() * &(one.clone() - &s)).pow(e(m - i))
                    * ((one.clone() - &b) * &t).pow(e(j))
                    * (b.clone() * &(one.clone() - &t)).pow(e(m - j))
                    * Poly::var(&format!("{k}{i}{j}"))
            })
            .sum();
        new == old
    })
}

fn mobius(c: &mut Criterion) {
    let mut group = c.benchmark_group("mobius identity");
    group.sample_size(10);
    for m in DEGREES {
        group.bench_function(format!("m={m}"), |b| {
            b.iter(|| {
                let (new, old) = mobius_uv_sides(black_box(m), black_box(m));
                assert_eq!(new, old, "the identity holds");
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("mobius identity, Bernstein sums");
    group.sample_size(10);
    for m in DEGREES {
        group.bench_function(format!("m={m}"), |b| {
            b.iter(|| assert!(bernstein_sums(black_box(m)), "the identity holds"))
        });
    }
    group.finish();
}

/// `k` polynomials `(α1 + i·α2 − β1 + 2β2 + 1)^5·(α2 − i)`, `i < k`, and
/// the factors `(i + 1)/(2i + 3)`.
fn combination_input(k: usize) -> (Vec<Poly>, Vec<BigRational>) {
    let v = Poly::var;
    let parts = (0..k as i64)
        .map(|i| {
            let base = v("α1") + &(v("α2") * &Poly::from_int(i)) - &v("β1")
                + &(v("β2") * &Poly::from_int(2))
                + &Poly::one();
            base.pow(5) * &(v("α2") - &Poly::from_int(i))
        })
        .collect();
    let factors = (0..k as i64).map(|i| ratio(i + 1, 2 * i + 3)).collect();
    (parts, factors)
}

/// The fully symbolic weight net `(0, w_ij)` of bidegree (m, m).
fn weight_net(m: usize) -> RectPatch<Poly> {
    let ctrl = (0..=m)
        .map(|i| {
            (0..=m)
                .map(|j| HPoint {
                    coords: vec![Poly::zero(), Poly::var(&format!("w{i}{j}"))],
                })
                .collect()
        })
        .collect();
    RectPatch::from_hom(ctrl).expect("a symbolic net")
}

fn quadratic(c: &mut Criterion) {
    let mut group = c.benchmark_group("linear combination");
    group.sample_size(10);
    for k in [9, 17] {
        let (parts, factors) = combination_input(k);
        group.bench_function(format!("k={k}"), |b| {
            b.iter(|| {
                let sum: Poly = black_box(&parts)
                    .iter()
                    .zip(&factors)
                    .map(|(p, q)| p.scale(q))
                    .sum();
                assert!(!sum.is_zero());
            })
        });
    }
    group.finish();
    let mut group = c.benchmark_group("quadratic reparam");
    group.sample_size(10);
    let v = Poly::var;
    let q = Quadratic {
        alpha1: v("α1"),
        alpha2: v("α2"),
        beta1: v("β1"),
        beta2: v("β2"),
    };
    for m in [3, 5] {
        let net = weight_net(m);
        group.bench_function(format!("m={m}"), |b| {
            b.iter(|| {
                assert_eq!(
                    black_box(&net).quadratic_reparam(&q).degree(),
                    (2 * m, 2 * m)
                )
            })
        });
    }
    group.finish();
}

criterion_group!(benches, mobius, quadratic);
criterion_main!(benches);
