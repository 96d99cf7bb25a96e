//! The machine's peak for the `f64` lane kernels (issue 31): fused
//! multiply–adds and divides of 4 doubles (AVX2) and of 8 doubles
//! (AVX-512), each timed on many independent chains, so that the
//! throughput of the execution units, not the latency of one chain,
//! bounds the time.
//!
//! ```text
//! fma:    acc_k ← acc_k·m + c       k < K chains,   2 flops per double
//!         (m = 1 − 10⁻⁹, c = 10⁻⁹: the values stay near 1/2 … 1)
//! divide: acc_k ← d / acc_k         (the values alternate x, d/x)
//! GFLOP/s = 2 · width · K · iterations / seconds
//! ```
//!
//! `K` is 12 for 4-wide FMAs (16 `ymm` registers), 24 for 8-wide ones (32
//! `zmm` registers) and 8 for divides: more chains than latency ×
//! throughput in every case (FMA: 4 cycles × 2 a cycle; divide: at most 24
//! cycles of latency for one every 4 to 16 cycles, Intel's and AMD's
//! published tables). The best of [`RUNS`] runs is kept. The clock this
//! implies is the 4-wide FMA rate over 16 flops a cycle: every x86-64
//! processor with FMA since Haswell (Intel) and Zen 2 (AMD) has two
//! 256-bit FMA pipes.
//!
//! This is the only `unsafe` of the benchmark helpers: calling a
//! `#[target_feature]` function after the standard library's run-time
//! detection (the library itself keeps `#![forbid(unsafe_code)]`).

use serde_json::{Map, Value};
use std::hint::black_box;
use std::time::Instant;

// The constants pass through `black_box`: otherwise the compiler sees a
// fixed point of the loop and drops it.

/// Runs of each measurement; the fastest counts.
const RUNS: usize = 25;

/// Loop iterations of one run (each does every chain once).
const ITERATIONS: u64 = 1_000_000;

/// The peak rates of this processor as a JSON object: `fma4_gflops`,
/// `fma8_gflops` (GFLOP/s of 4- and 8-wide FMAs, an FMA counting two
/// flops), `div4_per_ns`, `div8_per_ns` (double-precision divides a
/// nanosecond, 4- and 8-wide) and `clock_ghz` (`fma4_gflops / 16`); a
/// rate is absent where the processor lacks its instructions.
pub fn peak() -> Value {
    let mut out = Map::new();
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        if has!("avx2") && has!("fma") {
            // SAFETY: the processor has AVX2 and FMA (detected just above).
            let fma4 = best(2 * 4 * 12, || unsafe { x86::fma4(black_box(ITERATIONS)) });
            let div4 = best(4 * 8, || unsafe { x86::div4(black_box(ITERATIONS)) });
            out.insert("fma4_gflops".into(), fma4.into());
            out.insert("div4_per_ns".into(), div4.into());
            out.insert("clock_ghz".into(), (fma4 / 16.0).into());
        }
        if has!("avx512f") {
            // SAFETY: the processor has AVX-512F (detected just above).
            let fma8 = best(2 * 8 * 24, || unsafe { x86::fma8(black_box(ITERATIONS)) });
            let div8 = best(8 * 8, || unsafe { x86::div8(black_box(ITERATIONS)) });
            out.insert("fma8_gflops".into(), fma8.into());
            out.insert("div8_per_ns".into(), div8.into());
        }
    }
    Value::Object(out)
}

/// Operations a nanosecond of the fastest of [`RUNS`] runs of `f`, which
/// does `per_iteration` operations in each of [`ITERATIONS`] iterations
/// (its result is kept, so the work is not optimised away).
fn best(per_iteration: u64, mut f: impl FnMut() -> f64) -> f64 {
    (0..RUNS)
        .map(|_| {
            let start = Instant::now();
            black_box(f());
            (per_iteration * ITERATIONS) as f64 / start.elapsed().as_nanos() as f64
        })
        .fold(0.0, f64::max)
}

/// The timed loops, one per instruction and width.
#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;
    use std::hint::black_box;

    /// 12 chains of 4-wide FMAs, `iterations` times; one lane of their sum.
    #[target_feature(enable = "avx2,fma")]
    pub fn fma4(iterations: u64) -> f64 {
        let (m, c) = (
            _mm256_set1_pd(black_box(1.0 - 1e-9)),
            _mm256_set1_pd(black_box(1e-9)),
        );
        let mut acc = [_mm256_set1_pd(black_box(0.5)); 12];
        for _ in 0..iterations {
            for a in &mut acc {
                *a = _mm256_fmadd_pd(*a, m, c);
            }
        }
        _mm256_cvtsd_f64(
            acc.iter()
                .fold(_mm256_setzero_pd(), |s, a| _mm256_add_pd(s, *a)),
        )
    }

    /// 8 chains of 4-wide divides `acc ← d / acc`, `iterations` times; one
    /// lane of their sum.
    #[target_feature(enable = "avx2,fma")]
    pub fn div4(iterations: u64) -> f64 {
        let d = _mm256_set1_pd(black_box(3.0));
        let mut acc = [_mm256_set1_pd(black_box(1.5)); 8];
        for _ in 0..iterations {
            for a in &mut acc {
                *a = _mm256_div_pd(d, *a);
            }
        }
        _mm256_cvtsd_f64(
            acc.iter()
                .fold(_mm256_setzero_pd(), |s, a| _mm256_add_pd(s, *a)),
        )
    }

    /// 24 chains of 8-wide FMAs, `iterations` times; one lane of their sum.
    #[target_feature(enable = "avx512f")]
    pub fn fma8(iterations: u64) -> f64 {
        let (m, c) = (
            _mm512_set1_pd(black_box(1.0 - 1e-9)),
            _mm512_set1_pd(black_box(1e-9)),
        );
        let mut acc = [_mm512_set1_pd(black_box(0.5)); 24];
        for _ in 0..iterations {
            for a in &mut acc {
                *a = _mm512_fmadd_pd(*a, m, c);
            }
        }
        _mm512_reduce_add_pd(
            acc.iter()
                .fold(_mm512_setzero_pd(), |s, a| _mm512_add_pd(s, *a)),
        )
    }

    /// 8 chains of 8-wide divides `acc ← d / acc`, `iterations` times; one
    /// lane of their sum.
    #[target_feature(enable = "avx512f")]
    pub fn div8(iterations: u64) -> f64 {
        let d = _mm512_set1_pd(black_box(3.0));
        let mut acc = [_mm512_set1_pd(black_box(1.5)); 8];
        for _ in 0..iterations {
            for a in &mut acc {
                *a = _mm512_div_pd(d, *a);
            }
        }
        _mm512_reduce_add_pd(
            acc.iter()
                .fold(_mm512_setzero_pd(), |s, a| _mm512_add_pd(s, *a)),
        )
    }
}
