//! Run a loop compiled for the widest vector instructions the processor
//! has: with the feature `simd` on x86, AVX-512 or AVX2 where present
//! (detected at run time; `pulp` makes the safe call into code compiled
//! with those features), else the target's baseline (on `x86_64` SSE2: two
//! `f64` per instruction). The same IEEE operations in the same order in
//! every build (Rust never fuses a product and a sum), so the same bits.
//! A job's [`Job::run`] must be `#[inline(always)]` down to its loops, so
//! that it is compiled once per instruction set.

/// A loop to run on the widest instructions.
pub(crate) trait Job {
    type Output;
    /// The work; `#[inline(always)]` in every implementation.
    fn run(self) -> Self::Output;
}

/// [`Job::run`], compiled for AVX-512 or AVX2 where the processor has
/// them.
pub(crate) fn run<J: Job>(job: J) -> J::Output {
    #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
    {
        if let Some(v4) = pulp::x86::V4::try_new() {
            return v4.vectorize(Vectorized(job));
        } else if let Some(v3) = pulp::x86::V3::try_new() {
            return v3.vectorize(Vectorized(job));
        }
    }
    job.run()
}

/// `pulp`'s view of a [`Job`].
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
struct Vectorized<J>(J);

#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
impl<J: Job> pulp::NullaryFnOnce for Vectorized<J> {
    type Output = J::Output;

    #[inline(always)]
    fn call(self) -> J::Output {
        self.0.run()
    }
}
