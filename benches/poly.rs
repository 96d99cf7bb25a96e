//! The symbolic engine ([`Poly`](exact_bezier::Poly)) on the identity that
//! the SymPy peer also checks: the Möbius maps (2)(3) of source 000 in both
//! directions keep every point of a fully symbolic rational (m, m) patch
//! (symbolic points, weights, α, β, s, t), built by the library's own
//! `mobius_u`, `mobius_v`, `eval_hom` and `eval_hom_projective`.
//!
//! Run with the peer: `benches/peers/sympy_bench.sh` (criterion here, then
//! `benches/peers/sympy_mobius.py` for SymPy and the table). Alone:
//! `cargo bench --bench poly -- --warm-up-time 1 --measurement-time 2`

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use exact_bezier::proofs::yang_yong::mobius_uv_sides;

/// The bidegrees of the peer table.
const DEGREES: [usize; 4] = [3, 5, 6, 8];

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
}

criterion_group!(benches, mobius);
criterion_main!(benches);
