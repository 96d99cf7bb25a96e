//! Coincidence of bicubic patches: exact vs f64 vs filtered, on three kinds
//! of pairs (a Möbius/reversed/scaled copy; the same net with one weight
//! perturbed; an unrelated patch), and `dedup` of 100 000 bicubics with
//! planted duplicates (streamed through `Deduper`, generated on the fly;
//! `DEDUP_N` overrides the count — one 100 000 iteration takes minutes, and
//! criterion needs 10).
//!
//! The `bulk key` group prices one bicubic record of `exact-bezier key`:
//! parsing its JSON line into a patch (the yardstick), its key text by the
//! machine-integer fast path, and by the general `BigRational` path.
//!
//! Run: `cargo bench --bench coincide -- --warm-up-time 1 --measurement-time 3`

use criterion::{black_box, criterion_group, criterion_main, BatchSize, Criterion};
use exact_bezier::{
    coincide::canonical_key, coincide::canonical_text, coincide::coincide, coincide::key_digest,
    coincide::Deduper, coincide::Options, coincide::Symmetry, io::parse_json, io::patch_from_value,
    io::patch_to_json, ratio, Patch, RectPatch, Tolerance,
};
use num_rational::BigRational;

type Q = BigRational;

/// A small deterministic generator (SplitMix64): no randomness crates.
struct Gen(u64);

impl Gen {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn rational(&mut self, lo: i64, hi: i64) -> Q {
        let span = (hi - lo + 1) as u64;
        ratio(
            lo + (self.next() % span) as i64,
            1 + (self.next() % 100) as i64,
        )
    }
}

fn bicubic(g: &mut Gen) -> RectPatch<Q> {
    let pts = (0..4)
        .map(|_| {
            (0..4)
                .map(|_| (0..3).map(|_| g.rational(-1000, 1000)).collect())
                .collect()
        })
        .collect();
    let ws = (0..4)
        .map(|_| (0..4).map(|_| g.rational(1, 1000)).collect())
        .collect();
    RectPatch::new(pts, ws).expect("valid bicubic")
}

/// A Möbius-reparameterized, scaled, symmetric copy (still bicubic).
fn copy_of(r: &RectPatch<Q>, g: &mut Gen) -> RectPatch<Q> {
    let alpha = ratio(1 + (g.next() % 98) as i64, 99);
    let beta = ratio(1 + (g.next() % 98) as i64, 99);
    let sym = Symmetry::all()
        .nth((g.next() % 8) as usize)
        .expect("8 symmetries");
    sym.apply_rect(
        &r.mobius_u(&alpha)
            .mobius_v(&beta)
            .scale_weights(&ratio(7, 3)),
    )
}

fn pairs(c: &mut Criterion) {
    let mut g = Gen(42);
    let a = bicubic(&mut g);
    let copy = copy_of(&a, &mut g);
    let mut ws = a.weights();
    ws[2][1] = ws[2][1].clone() * ratio::<Q>(1001, 1000);
    let bent = RectPatch::new(a.points().expect("finite"), ws).expect("valid");
    let other = bicubic(&mut g);
    for (name, b) in [("copy", copy), ("weight+0.1%", bent), ("unrelated", other)] {
        let (pa, pb) = (Patch::Rect(a.clone()), Patch::Rect(b));
        let (fa, fb) = (pa.to_f64(), pb.to_f64());
        let mut group = c.benchmark_group(format!("coincide bicubic {name}"));
        group.bench_function("exact", |bch| {
            bch.iter(|| {
                coincide(black_box(&pa), black_box(&pb), Options::default()).expect("valid")
            })
        });
        group.bench_function("f64", |bch| {
            bch.iter(|| {
                coincide(
                    black_box(&fa),
                    black_box(&fb),
                    Options::within(Tolerance(1e-9)),
                )
                .expect("valid")
            })
        });
        group.bench_function("filtered", |bch| {
            bch.iter(|| {
                coincide(black_box(&pa), black_box(&pb), Options::filtered()).expect("valid")
            })
        });
        group.finish();
    }
}

/// Patch k of the dedup stream: 50 000 distinct bicubics, then one planted
/// copy of each (in a scrambled order).
fn stream_patch(k: usize, n: usize) -> Patch<Q> {
    let half = n / 2;
    let base = |j: usize| bicubic(&mut Gen(j as u64 * 7919 + 1));
    if k < half {
        Patch::Rect(base(k))
    } else {
        let j = (k - half) * 7 % half;
        Patch::Rect(copy_of(&base(j), &mut Gen(k as u64)))
    }
}

fn dedup_100k(c: &mut Criterion) {
    let n: usize = std::env::var("DEDUP_N")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(100_000);
    let mut group = c.benchmark_group("dedup");
    group.sample_size(10);
    let name = format!("{n} bicubics, half planted copies (incl. generation)");
    group.bench_function(name, |bch| {
        bch.iter_batched(
            Deduper::default,
            |mut d| {
                for k in 0..n {
                    d.insert(&stream_patch(k, n)).expect("valid");
                }
                let classes = d.classes();
                assert_eq!(classes.len(), n / 2);
                classes
            },
            BatchSize::PerIteration,
        )
    });
    group.bench_function(format!("generation of the {n} stream alone"), |bch| {
        bch.iter(|| {
            for k in 0..n {
                black_box(stream_patch(k, n));
            }
        })
    });
    group.finish();
}

fn bulk_key(c: &mut Criterion) {
    let mut g = Gen(7);
    let a = bicubic(&mut g);
    let copy = Patch::Rect(copy_of(&a, &mut g));
    let line = patch_to_json(&copy).expect("finite").to_string();
    let parse = |l: &str| patch_from_value(&parse_json(l).expect("json")).expect("patch");
    let mut group = c.benchmark_group("bulk key (one bicubic record)");
    group.bench_function("parse the line (yardstick)", |b| {
        b.iter(|| parse(black_box(&line)))
    });
    group.bench_function("parse + key digest", |b| {
        b.iter(|| key_digest(&parse(black_box(&line))).expect("valid"))
    });
    group.bench_function("key text, fast path", |b| {
        b.iter(|| canonical_text(black_box(&copy)).expect("valid"))
    });
    group.bench_function("key text, general path", |b| {
        b.iter(|| canonical_key(black_box(&copy)).expect("valid").text())
    });
    group.finish();
}

criterion_group!(benches, pairs, bulk_key, dedup_100k);
criterion_main!(benches);
