//! Lane-major `f64` batch kernels: the `f64` fast path of
//! [`Evaluator::eval_batch`](super::Evaluator::eval_batch) and
//! [`Jets::eval_batch`](super::Jets::eval_batch) for nets of stride 3
//! (planar) and 4 (spatial).
//!
//! The points of a batch go `L` at a time ([`LANES`], or [`LANES_AVX512`]
//! for curves in the AVX-512 build). Every value of the Horner–Bernstein
//! scheme of [`super`] is held as a [`Lane`], one `f64` per point, and
//! every step is a loop over the lanes with no dependence
//! between them, so the compiler turns it into vector instructions on
//! stable Rust, without `unsafe` and without SIMD intrinsics:
//!
//! ```text
//! acc[k][l] ← acc[k][l]·a[l] + bⁱ[l]·G_i[k]        k < stride, l < L
//! X[k][l]   = acc[k][l] / acc[w][l]
//! ```
//!
//! Which vector instructions depends on the build the batch runs ([`Isa`]):
//! the baseline one (on `x86_64` SSE2, two `f64` per instruction), or,
//! with the default feature `simd`, the same kernels compiled with the
//! x86-64-v4 features (AVX-512: eight `f64` per instruction) or, failing
//! those, the x86-64-v3 ones (AVX2: four), whichever is the widest the
//! processor has (detected at run time, once): `pulp::x86::V4` or `V3`
//! calls a `#[target_feature]` function on our behalf, safely after its
//! detection, and every kernel below is `#[inline(always)]` so that the
//! whole of it is compiled inside that function. The batches of curves,
//! tri patches and bicubics are written in `pulp`'s vectors instead
//! (`pulp::Simd`, safe, the same code for AVX2 and AVX-512), each by a
//! loop of its own ([`curve_batch`], [`patch_batch`]), with the points
//! written by an in-order interleave of each instruction set ([`Zip`]):
//! their lane loops the fat-LTO build had compiled badly (accumulators
//! taken apart into single values, shuffles that read back from memory
//! what had just been stored), and a change to one shape's code moved
//! the others' times. Rect patches of other degrees keep the lane loops
//! of [`project`].
//!
//! The scalar kernel (`horner` in [`super`], one point at a time) stays
//! the reference. The baseline build performs the same IEEE operations in
//! the same order as it in each lane (Rust never fuses a multiply and an
//! add on its own), so its values equal the scalar kernel's **bit for
//! bit**. The vector builds, whose instruction sets have FMA, fuse each
//! Horner step `acc·a + (bⁱ·G_i)` and each `o + vʲ·R_j` of a tri patch
//! into one rounding instead of two ([`madd`]).
//!
//! # Tolerance of the fused builds
//!
//! Both the scalar kernel and the fused lanes compute every homogeneous
//! coordinate as a sum of terms `a^{n−i} bⁱ C(n,i) H_i` (curve; the
//! products of two such for a rect, of three for a tri patch) in which
//! each term meets at most `K` roundings, each a factor `(1 + δ)`,
//! `|δ| ≤ u = 2⁻⁵³`: the product `C·H` of the scaled net (1), the powers
//! `bⁱ` (`i − 1`), `bⁱ·G_i` (1), then a multiply and an add per later
//! Horner step (2 each, 1 fused), and for a tri patch `vʲ` (`j − 1`), `vʲ·R_j`
//! (1) and the running sum (`n − j + 1`). Counting:
//!
//! ```text
//! K = 2n + 1 (curve n),   2m + 2n + 1 (rect (m, n)),   3n + 1 (tri n)
//! |Ĥ_k − H_k| ≤ γ_K·H̃_k,      γ_K = K·u / (1 − K·u)
//! |X̂_k − X_k| ≤ B_k·(1 + u) + u·|X_k|,
//!      B_k = γ_K·(H̃_k + |X_k|·H̃_w) / (|H_w| − γ_K·H̃_w)      (if positive)
//! ```
//!
//! for either kernel, where `H` is the exact homogeneous point at the
//! `f64` homogeneous parameters both compute (`1 − t` and the rest, the
//! same operations), `H̃` the same sum with the absolute values of the
//! control coordinates and parameters, and `X_k = H_k / H_w` (Higham,
//! *Accuracy and Stability of Numerical Algorithms*, 2nd ed., Lemma 3.1
//! and §5.1; the last line is the quotient of two perturbed values and one
//! rounded division). The fused lanes and the scalar kernel therefore
//! differ by at most **twice** these bounds: that is the documented
//! tolerance of a batch run by a vector build, a few units in the last
//! place of `H̃_k/H_w` for the degrees of everyday CAD. The property test
//! below checks the bound for both kernels, in every vector build the
//! processor runs (AVX-512 and AVX2 on an AVX-512 machine), against exact
//! `BigRational` sums, and bit identity for the baseline build. A batch whose length
//! is not a multiple of `L` fills its last group with the parameter
//! `0` and keeps only the real points.
//!
//! Cost per point (flops, divides), stride `s` (weight included):
//!
//! ```text
//! curve n:      1 + n(3s + 1)                                     s − 1
//! rect (m, n):  2 + (m + 1)·n(3s + 1) + m(3s + 1)                 s − 1
//! tri n:        2 + n(n + 1)/2·(3s + 1) + n(2s + 1)               s − 1
//! ```
//!
//! e.g. 31 flops and 2 divides for a planar cubic, 197 and 3 for a
//! spatial bicubic, 107 and 3 for a spatial cubic triangle. The vector
//! builds evaluate a bicubic by its Bernstein values instead
//! ([`rect_bernstein`]): 154 flops and 3 divides for a spatial one; and
//! a curve of degree `n ≥ 4` by blocks of 4 terms ([`curve_blocks`]),
//! `k₀ ≡ n + 1 mod 4` terms first (`1 ≤ k₀ ≤ 4`), then `Q = (n + 1 −
//! k₀)/4` blocks:
//!
//! ```text
//! curve n ≥ 4:  9 + (k₀ − 1)(3s + 1) + (Q − 1) + 10sQ            s − 1
//! ```
//!
//! 90 flops for a planar curve of degree 10, 318 for degree 40 (101 and
//! 401 by Horner).
//!
//! The divides of a group are issued before the multiply–adds of the
//! next ([`project`]), so that the divider and the multiply–add units
//! work at once.

use super::{Net, Shape};
use crate::error::Error;
use std::any::Any;

/// Points evaluated together in the baseline and AVX2 builds: each
/// [`Lane`] is two 256-bit or four 128-bit vector registers.
const LANES: usize = 8;

/// Points evaluated together in the AVX-512 build: each [`Lane`] is two
/// 512-bit registers, so every Horner step runs two independent chains
/// of vector instructions, which hides the latency of one (4 cycles for
/// an FMA) behind the other.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
const LANES_AVX512: usize = 16;

/// One `f64` per point of a group of `L` points.
type Lane<const L: usize> = [f64; L];

/// The homogeneous parameters of a group of points, lane-major: `(1 − t,
/// t)`, `(1 − u, u, 1 − v, v)` or `(u, v, 1 − u − v)`, as
/// [`Net::hom_params`] computes them for one point.
type Hom<const L: usize> = [Lane<L>; 4];

/// The instruction set a batch is compiled for: the kernels below are
/// `#[inline(always)]` down to their loops, so `run!` compiles them
/// once per variant, each vectorised for its own instructions.
#[derive(Clone, Copy, Debug)]
pub(super) enum Isa {
    /// The target's baseline (on `x86_64` SSE2: two `f64` per instruction).
    Baseline,
    /// AVX2 with FMA and the rest of x86-64-v3 (four `f64` per
    /// instruction), detected at run time; `pulp` makes the safe call into
    /// code compiled with those features.
    #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
    Avx2(pulp::x86::V3),
    /// AVX-512 (F, BW, CD, DQ, VL: x86-64-v4, eight `f64` per
    /// instruction) with FMA, detected at run time, called through
    /// `pulp` as [`Isa::Avx2`].
    #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
    Avx512(pulp::x86::V4),
}

impl Isa {
    /// The widest instruction set this processor runs (detected once,
    /// then read from a static), else [`Isa::Baseline`].
    pub(super) fn detect() -> Self {
        #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
        if let Some(v4) = pulp::x86::V4::try_new() {
            return Isa::Avx512(v4);
        } else if let Some(v3) = pulp::x86::V3::try_new() {
            return Isa::Avx2(v3);
        }
        Isa::Baseline
    }
}

/// Whether the AVX-512 build runs a batch of `shape` [`LANES_AVX512`]
/// points at a time: curves (one chain of multiply–adds per coordinate,
/// whose FMA latency two registers a value hide: degree 40 13.0 → 9.4 ns
/// a point by Horner, degree 10 3.9 → 3.3 ns), not patches (a cubic triangle took 6.2 ns
/// instead of 5.4, a bicubic no less than 7.3; `peer_eval`, 2026-11-28).
fn wide(shape: Shape) -> bool {
    matches!(shape, Shape::Curve(_))
}

/// A batch kernel of lane count `L`, compiled for the instructions `V`.
trait Kernel {
    type Output;
    fn run<const L: usize, V: Target>(self, simd: V) -> Self::Output;
}

/// The instructions a kernel is compiled for, known from its type (so
/// that every choice below is made at compile time): the baseline
/// ([`Baseline`]) or, with the feature `simd`, `pulp`'s tokens of AVX2
/// and AVX-512.
trait Target: Copy {
    /// Whether the multiply–adds are fused ([`madd`]): false for the
    /// baseline, which has no FMA instruction, true for the vector
    /// builds, which have one.
    const FUSED: bool;

    /// The homogeneous points of a curve net `g` of degree `n` at the
    /// parameters `h`.
    fn curve<const S: usize, const L: usize>(self, n: usize, g: &[f64], h: &Hom<L>)
        -> [Lane<L>; S];

    /// [`eval_batch`] by a loop of its own for the nets of a kernel
    /// compiled for `SQUARE` (see [`Job`]), if the target has one at `L`
    /// lanes ([`curve_batch`], [`patch_batch`]); `None` otherwise, for
    /// [`project`]'s.
    fn batch<const S: usize, const L: usize, const SQUARE: usize, T: Any>(
        self,
        net: &Net<f64>,
        params: &[T],
        out: &mut [T],
    ) -> Option<Result<(), Error>>;

    /// The homogeneous points of a rect net `g` of degree `(D, D)`,
    /// `D ≤ 3`, at the parameters `h`.
    fn square<const S: usize, const L: usize, const D: usize>(
        self,
        g: &[f64],
        h: &Hom<L>,
    ) -> [Lane<L>; S];
}

/// The target's baseline instructions ([`Isa::Baseline`]).
#[derive(Clone, Copy)]
struct Baseline;

impl Target for Baseline {
    const FUSED: bool = false;

    /// [`horner`], the scalar kernel's operations.
    #[inline(always)]
    fn curve<const S: usize, const L: usize>(
        self,
        n: usize,
        g: &[f64],
        h: &Hom<L>,
    ) -> [Lane<L>; S] {
        horner::<S, L>(false, n + 1, broadcast::<S, L>(g), &h[0], &h[1])
    }

    /// `None`: [`project`]'s loop.
    #[inline(always)]
    fn batch<const S: usize, const L: usize, const SQUARE: usize, T: Any>(
        self,
        _: &Net<f64>,
        _: &[T],
        _: &mut [T],
    ) -> Option<Result<(), Error>> {
        None
    }

    /// [`rect`]'s Horner steps, the scalar kernel's operations, with the
    /// rows on the stack.
    #[inline(always)]
    fn square<const S: usize, const L: usize, const D: usize>(
        self,
        g: &[f64],
        h: &Hom<L>,
    ) -> [Lane<L>; S] {
        let mut rows = [[[0.0; L]; S]; 4];
        rect::<S, L>(false, (D, D), g, h, &mut rows[..=D])
    }
}

#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
impl<V: Zip> Target for V {
    const FUSED: bool = true;

    /// [`curve_vectors`] in `V`'s vectors.
    #[inline(always)]
    fn curve<const S: usize, const L: usize>(
        self,
        n: usize,
        g: &[f64],
        h: &Hom<L>,
    ) -> [Lane<L>; S] {
        curve_vectors::<S, L, V>(self, n, g, h)
    }

    /// [`curve_batch`] for curves, a group being two vectors of points
    /// (the AVX-512 build at `LANES_AVX512`, the AVX2 one at `LANES`);
    /// [`patch_batch`] for tri patches and bicubics.
    #[inline(always)]
    fn batch<const S: usize, const L: usize, const SQUARE: usize, T: Any>(
        self,
        net: &Net<f64>,
        params: &[T],
        out: &mut [T],
    ) -> Option<Result<(), Error>> {
        match SQUARE {
            CURVES => (L * size_of::<f64>() == 2 * size_of::<V::f64s>())
                .then(|| curve_batch::<S, L, T, V>(self, net, params, out)),
            TRIS => patch_batch::<S, L, 0, T, V>(self, net, params, out),
            3 => patch_batch::<S, L, 3, T, V>(self, net, params, out),
            _ => None,
        }
    }

    /// [`rect_bernstein`] in `V`'s vectors.
    #[inline(always)]
    fn square<const S: usize, const L: usize, const D: usize>(
        self,
        g: &[f64],
        h: &Hom<L>,
    ) -> [Lane<L>; S] {
        rect_bernstein::<S, L, D, V>(self, g, h)
    }
}

/// A batch job (evaluation or jets) whose kernel is compiled for nets of
/// any shape if `SQUARE` is 0, for curve nets only if it is [`CURVES`],
/// for tri nets only if it is [`TRIS`], else for rect nets of degree
/// `(SQUARE, SQUARE)` only (see [`by_shape`]).
trait Job {
    type Output;
    fn run<const L: usize, const SQUARE: usize, V: Target>(self, simd: V) -> Self::Output;
}

/// A [`Job`] compiled for `SQUARE` (see [`Job`]): a [`Kernel`].
struct Square<J, const SQUARE: usize>(J);

impl<J: Job, const SQUARE: usize> Kernel for Square<J, SQUARE> {
    type Output = J::Output;

    #[inline(always)]
    fn run<const L: usize, V: Target>(self, simd: V) -> J::Output {
        self.0.run::<L, SQUARE, V>(simd)
    }
}

/// `job` for nets of `shapes` (the nets of a jet may differ in degree)
/// ([`dispatch`]): bicubics alone, the commonest
/// patch in CAD data, by a kernel of its own whose loops are unrolled and
/// whose values stay in registers ([`rect_bernstein`] in the vector
/// builds, and the baseline's Horner steps with their rows on the stack);
/// every other shape by one kernel. `peer_eval` (2026-11-28, AVX-512):
/// bicubic 5.5–6.3 → 4.0–4.3 ns a point in a build without LTO (best of
/// 6 alternated runs at load 1.2–1.6), 6.9–10.9 → 6.5–7.0 in the fat-LTO
/// one (README, "Divides under the next group's work"), then 6.0–6.3 →
/// 4.8–5.4 there with [`rect_bernstein`] in `pulp`'s vectors. The same for the
/// cubic triangle was no faster (Horner steps unrolled, 4.0–4.1 ns either
/// way) or slower (its Bernstein values, 5.4 ns). Curves alone and tri
/// patches alone, by kernels compiled for them ([`CURVES`], [`TRIS`]):
/// in the vector builds each has a loop of its own ([`Target::batch`];
/// by the lane loops of the other shapes, a kernel for curves alone had
/// made their code worse).
#[inline(always)]
fn by_shape<J: Job>(isa: Isa, mut shapes: impl Iterator<Item = Shape>, job: J) -> J::Output {
    let first = shapes.next();
    let wide = first.is_some_and(wide);
    match first {
        Some(Shape::Rect(3, 3)) if shapes.all(|s| s == Shape::Rect(3, 3)) => {
            dispatch(isa, wide, Square::<J, 3>(job))
        }
        Some(Shape::Curve(_)) if shapes.all(|s| matches!(s, Shape::Curve(_))) => {
            dispatch(isa, wide, Square::<J, CURVES>(job))
        }
        Some(Shape::Tri(_)) if shapes.all(|s| matches!(s, Shape::Tri(_))) => {
            dispatch(isa, wide, Square::<J, TRIS>(job))
        }
        _ => dispatch(isa, wide, Square::<J, 0>(job)),
    }
}

/// The `SQUARE` of a [`Job`] compiled for curve nets only.
const CURVES: usize = usize::MAX;

/// The `SQUARE` of a [`Job`] compiled for tri nets only.
const TRIS: usize = usize::MAX - 1;

/// `kernel` compiled for the instruction set `isa`, [`LANES_AVX512`]
/// points at a time in the AVX-512 build if `wide`, else [`LANES`]. The
/// kernel must be inlined whole into the call that `pulp` makes with the
/// instruction set's features, hence the `#[inline(always)]` of every
/// kernel function below and of [`Fused::call`] (a closure called through
/// `FnOnce` was inlined only while the kernel was small, and its code then
/// lacked the features: `mul_add` became a library call). Each arm passes
/// its instructions as a type ([`Target`]), so that every choice they
/// decide (the branch of [`madd`], the bicubic's kernel) is made at
/// compile time: a token passed as a value of [`Isa`] left them to run
/// time, and the compiler then split the curves' divides into 128-bit
/// ones (cubic 1.6 → 3.0 ns a point).
#[inline(always)]
fn dispatch<K: Kernel>(isa: Isa, wide: bool, kernel: K) -> K::Output {
    // Read by the AVX-512 arm only (absent without the feature `simd`).
    let _ = wide;
    match isa {
        Isa::Baseline => kernel.run::<LANES, _>(Baseline),
        #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
        Isa::Avx2(v3) => v3.vectorize(Fused::<K, LANES, _>(kernel, v3)),
        #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
        Isa::Avx512(v4) if wide => v4.vectorize(Fused::<K, LANES_AVX512, _>(kernel, v4)),
        #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
        Isa::Avx512(v4) => v4.vectorize(Fused::<K, LANES, _>(kernel, v4)),
    }
}

/// A kernel run fused at `L` lanes, as `pulp` calls it.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
struct Fused<K, const L: usize, V>(K, V);

#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
impl<K: Kernel, const L: usize, V: Target> pulp::NullaryFnOnce for Fused<K, L, V> {
    type Output = K::Output;

    #[inline(always)]
    fn call(self) -> K::Output {
        self.0.run::<L, V>(self.1)
    }
}

/// The `f64` batch of [`Evaluator::eval_batch`](super::Evaluator::eval_batch)
/// when `T` is `f64` (recognised by its type id) and the stride is 3 or 4,
/// Cartesian points into `out`; `None`, nothing done, otherwise. `rows`
/// is scratch space, grown on first use. The buffer lengths are checked.
///
/// # Errors
///
/// [`Error::PointAtInfinity`] at the first point whose weight is zero.
pub(super) fn eval_batch<T: Any>(
    isa: Isa,
    net: &Net<T>,
    params: &[T],
    out: &mut [T],
    rows: &mut Vec<f64>,
) -> Option<Result<(), Error>> {
    let net = f64_net(net)?;
    let shape = std::iter::once(net.shape());
    match net.stride() {
        3 => Some(by_shape(
            isa,
            shape,
            Project::<'_, 3, T> {
                net,
                params,
                out,
                rows,
            },
        )),
        4 => Some(by_shape(
            isa,
            shape,
            Project::<'_, 4, T> {
                net,
                params,
                out,
                rows,
            },
        )),
        _ => None,
    }
}

/// The arguments of [`project`] at the stride `S`.
struct Project<'a, const S: usize, T> {
    net: &'a Net<f64>,
    params: &'a [T],
    out: &'a mut [T],
    rows: &'a mut Vec<f64>,
}

impl<const S: usize, T: Any> Job for Project<'_, S, T> {
    type Output = Result<(), Error>;

    #[inline(always)]
    fn run<const L: usize, const SQUARE: usize, V: Target>(self, simd: V) -> Self::Output {
        project::<S, L, SQUARE, T, V>(simd, self.net, self.params, self.out, self.rows)
    }
}

/// The `f64` batch of [`Jets::eval_batch`](super::Jets::eval_batch): the
/// homogeneous points of every net of `nets` (one shape, one stride 3 or
/// 4), back to back per point; `None` as for [`eval_batch`].
pub(super) fn jets_batch<T: Any>(
    isa: Isa,
    nets: &[Net<T>],
    params: &[T],
    out: &mut [T],
    rows: &mut Vec<f64>,
) -> Option<()> {
    // Every net has the type of the first (no allocation: `tests/alloc.rs`).
    let first = f64_net(nets.first()?)?;
    let shape = nets.iter().map(|n| n.shape());
    match first.stride() {
        3 => by_shape(
            isa,
            shape,
            JetNets::<'_, 3, T> {
                nets,
                params,
                out,
                rows,
            },
        ),
        4 => by_shape(
            isa,
            shape,
            JetNets::<'_, 4, T> {
                nets,
                params,
                out,
                rows,
            },
        ),
        _ => return None,
    }
    Some(())
}

/// The arguments of [`jets`] at the stride `S`.
struct JetNets<'a, const S: usize, T> {
    nets: &'a [Net<T>],
    params: &'a [T],
    out: &'a mut [T],
    rows: &'a mut Vec<f64>,
}

impl<const S: usize, T: Any> Job for JetNets<'_, S, T> {
    type Output = ();

    #[inline(always)]
    fn run<const L: usize, const SQUARE: usize, V: Target>(self, simd: V) {
        jets::<S, L, SQUARE, T, V>(simd, self.nets, self.params, self.out, self.rows)
    }
}

/// [`eval_batch`] at the stride `S`, software-pipelined: the divides of
/// one group are issued before the Horner steps of the next, and its
/// points written after them, so that the divider works while the
/// multiply–add units do (written after the divides, the points' stores
/// wait on them and fill the scheduler, and the two kinds of work ran one
/// after the other).
#[inline(always)]
fn project<const S: usize, const L: usize, const SQUARE: usize, T: Any, V: Target>(
    simd: V,
    net: &Net<f64>,
    params: &[T],
    out: &mut [T],
    rows: &mut Vec<f64>,
) -> Result<(), Error> {
    if let Some(done) = simd.batch::<S, L, SQUARE, T>(net, params, out) {
        return done;
    }
    let k = net.shape().params();
    let mut last: Option<([Lane<L>; S], &mut [T])> = None;
    for (p, o) in params.chunks(L * k).zip(out.chunks_mut(L * (S - 1))) {
        let divided = last.take().map(|(h, o)| (quotients(&h), o));
        let h = hom_net::<S, L, SQUARE, V>(simd, net, &hom_lanes(net.shape(), p), rows);
        if let Some((x, o)) = divided {
            write(x, o)?;
        }
        last = Some((h, o));
    }
    match last {
        Some((h, o)) => write(quotients(&h), o),
        None => Ok(()),
    }
}

/// [`eval_batch`] of a curve net in the vector builds (the
/// [`Target::batch`] of `V`): a loop of its own, with no shape to
/// dispatch on inside it, each group's parameters read as whole vectors
/// ([`column()`]), each vector of them evaluated by [`curve_vector`] and
/// divided at once; a planar group's points go out by [`zip_planar`].
/// `peer_eval` (AVX-512, fat LTO, 2026-11-29, 200 000 points, best of 30
/// passes, three runs): planar cubic 0.86–0.89 → 0.38–0.39 ns a point,
/// degree 10 1.34–1.36 → 1.02–1.03, degree 40 3.33–3.41 → 3.06–3.09. By
/// the lane loops of [`project`], the fat-LTO build took the Horner
/// accumulators apart into single values (`vextractf32x4`, spills).
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn curve_batch<const S: usize, const L: usize, T: Any, V: Zip>(
    simd: V,
    net: &Net<f64>,
    params: &[T],
    out: &mut [T],
) -> Result<(), Error> {
    let (points, _) = net.scaled().as_chunks::<S>();
    for (p, o) in params.chunks(L).zip(out.chunks_mut(L * (S - 1))) {
        let t = column::<L, 1, T>(p, 0);
        let (t, _) = V::as_simd_f64s(&t);
        let point = |b| curve_point::<S, V>(simd, points, b);
        let x = [point(t[0]), point(t[1])];
        if S == 3 && zip_planar::<L, T, V>(simd, &x[0], &x[1], o) {
            continue;
        }
        // By value, so that the points may stay in registers.
        write::<S, L, T>(each(|k| bytemuck::cast([x[0][k], x[1][k]])), o)?;
    }
    Ok(())
}

/// [`eval_batch`] of a tri net, or of a rect net of degree `(D, D)` if
/// `D` is not 0, in the vector builds (the [`Target::batch`] of `V`);
/// `None` for a net of another shape. As [`curve_batch`]: each vector of
/// a group's parameters evaluated by [`tri_vector`] or [`square_vector`]
/// and divided at once; a group of one vector of spatial points goes out
/// by [`zip_spatial`].
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn patch_batch<const S: usize, const L: usize, const D: usize, T: Any, V: Zip>(
    simd: V,
    net: &Net<f64>,
    params: &[T],
    out: &mut [T],
) -> Option<Result<(), Error>> {
    let (points, _) = net.scaled().as_chunks::<S>();
    let one = simd.splat_f64s(1.0);
    let minus = |x, y| simd.sub_f64s(x, y);
    let hom = |u, v| match net.shape() {
        Shape::Tri(n) => Some(tri_vector::<S, V>(
            simd,
            n,
            points,
            [u, v, minus(minus(one, u), v)],
        )),
        Shape::Rect(..) if D > 0 => Some(square_vector::<S, D, V>(
            simd,
            points,
            [minus(one, u), u, minus(one, v), v],
        )),
        _ => None,
    };
    'groups: for (p, o) in params.chunks(2 * L).zip(out.chunks_mut(L * (S - 1))) {
        let (u, v) = (column::<L, 2, T>(p, 0), column::<L, 2, T>(p, 1));
        let (u, v) = (V::as_simd_f64s(&u).0, V::as_simd_f64s(&v).0);
        let one_vector = u.len() == 1;
        let mut x = [[0.0; L]; S];
        for (q, (u, v)) in u.iter().zip(v).enumerate() {
            let mut h = hom(*u, *v)?;
            for c in 0..S - 1 {
                h[c] = simd.div_f64s(h[c], h[S - 1]);
            }
            if one_vector && S == 4 && zip_spatial::<L, T, V>(simd, &h, o) {
                continue 'groups;
            }
            for (x, h) in x.iter_mut().zip(h) {
                V::as_mut_simd_f64s(x).0[q] = h;
            }
        }
        if let Err(e) = write(x, o) {
            return Some(Err(e));
        }
    }
    Some(Ok(()))
}

/// [`tri`] on one vector of lanes `(u, v, w)`, every multiply–add fused:
/// the same operations in the same order.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn tri_vector<const S: usize, V: pulp::Simd>(
    simd: V,
    n: usize,
    points: &[[f64; S]],
    [u, v, w]: [V::f64s; 3],
) -> [V::f64s; S] {
    let (mut out, mut vpow, mut start) = ([simd.splat_f64s(0.0); S], simd.splat_f64s(1.0), 0);
    for j in 0..=n {
        let row = &points[start..start + n - j + 1];
        start += n - j + 1;
        let r = horner_vectors::<S, V>(simd, row, w, u);
        if j == 0 {
            out = r;
        } else {
            for (o, r) in out.iter_mut().zip(r) {
                *o = simd.mul_add_f64s(vpow, r, *o);
            }
        }
        if j < n {
            vpow = simd.mul_f64s(vpow, v);
        }
    }
    out
}

/// A whole group of one vector of spatial points `x` (`[X, Y, Z, W]`)
/// into `o` by [`Zip::zip3`], if their weights are all non-zero and the
/// instruction set has it; false, nothing written, otherwise.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn zip_spatial<const L: usize, T: Any, V: Zip>(simd: V, x: &[V::f64s], o: &mut [T]) -> bool {
    let at_infinity = simd.equal_f64s(x[3], simd.splat_f64s(0.0));
    let (rows, _) = o.as_chunks_mut::<L>();
    let [first, second, third] = rows else {
        return false;
    };
    if bytemuck::bytes_of(&at_infinity).iter().any(|b| *b != 0) {
        return false;
    }
    let Some(zipped) = simd.zip3(x[0], x[1], x[2]) else {
        return false;
    };
    for (row, z) in [first, second, third].into_iter().zip(zipped) {
        let row: &mut Lane<L> = as_f64_mut(row);
        V::as_mut_simd_f64s(row).0[0] = z;
    }
    true
}

/// A whole group of planar points `x₀, x₁` (`[X, Y, W]`, one vector of
/// points each) into `o` by [`Zip::zip`], if their weights are all
/// non-zero; false, nothing written, otherwise (a partial group, or a
/// point at infinity: [`write()`]'s case). The compiler's own shuffles, for
/// a loop of fixed length over a whole group's lanes, read the points
/// back from memory by loads that straddle two of their stores: planar
/// cubic 0.72 ns a point, against 0.38 this way.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn zip_planar<const L: usize, T: Any, V: Zip>(
    simd: V,
    x0: &[V::f64s],
    x1: &[V::f64s],
    o: &mut [T],
) -> bool {
    let zero = simd.splat_f64s(0.0);
    let at_infinity = simd.or_m64s(simd.equal_f64s(x0[2], zero), simd.equal_f64s(x1[2], zero));
    let (rows, _) = o.as_chunks_mut::<L>();
    let [first, second] = rows else {
        return false;
    };
    if bytemuck::bytes_of(&at_infinity).iter().any(|b| *b != 0) {
        return false;
    }
    for (row, x) in [first, second].into_iter().zip([x0, x1]) {
        let row: &mut Lane<L> = as_f64_mut(row);
        V::as_mut_simd_f64s(row)
            .0
            .copy_from_slice(&simd.zip(x[0], x[1]));
    }
    true
}

/// The in-order interleave of two vectors, which `pulp` does not offer
/// (its `interleave_shfl_f64s` leaves the lanes in an order of its own).
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
trait Zip: pulp::Simd {
    /// `[x₀, y₀, x₁, y₁, …]`: the lanes of `x` and `y` alternately, in
    /// order, as two vectors.
    fn zip(self, x: Self::f64s, y: Self::f64s) -> [Self::f64s; 2];

    /// `[x₀, y₀, z₀, x₁, …]`, as three vectors, where the instruction set
    /// does it in a few instructions; `None` otherwise.
    fn zip3(self, x: Self::f64s, y: Self::f64s, z: Self::f64s) -> Option<[Self::f64s; 3]>;
}

#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
impl Zip for pulp::x86::V3 {
    /// Two in-lane unpacks (`x₀y₀x₂y₂`, `x₁y₁x₃y₃`), then their halves
    /// exchanged.
    #[inline(always)]
    fn zip(self, x: Self::f64s, y: Self::f64s) -> [Self::f64s; 2] {
        let (x, y) = (bytemuck::cast(x), bytemuck::cast(y));
        let (even, odd) = (
            self.avx._mm256_unpacklo_pd(x, y),
            self.avx._mm256_unpackhi_pd(x, y),
        );
        [
            bytemuck::cast(self.avx._mm256_permute2f128_pd::<0x20>(even, odd)),
            bytemuck::cast(self.avx._mm256_permute2f128_pd::<0x31>(even, odd)),
        ]
    }

    /// `None`: AVX2 has no permute of two sources by lane index.
    #[inline(always)]
    fn zip3(self, _: Self::f64s, _: Self::f64s, _: Self::f64s) -> Option<[Self::f64s; 3]> {
        None
    }
}

#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
impl Zip for pulp::x86::V4 {
    /// One two-source permute a half.
    #[inline(always)]
    fn zip(self, x: Self::f64s, y: Self::f64s) -> [Self::f64s; 2] {
        let (x, y) = (bytemuck::cast(x), bytemuck::cast(y));
        let half = |k: i64| {
            let index = self.avx512f._mm512_setr_epi64(
                k,
                8 + k,
                k + 1,
                9 + k,
                k + 2,
                10 + k,
                k + 3,
                11 + k,
            );
            bytemuck::cast(self.avx512f._mm512_permutex2var_pd(x, index, y))
        };
        [half(0), half(4)]
    }

    /// Per output vector, the lanes of `x` and `y` by one two-source
    /// permute, then those of `z` by one masked permute: output `k` holds
    /// the values `8k … 8k + 7` of `x₀ y₀ z₀ x₁ y₁ z₁ …`.
    #[inline(always)]
    fn zip3(self, x: Self::f64s, y: Self::f64s, z: Self::f64s) -> Option<[Self::f64s; 3]> {
        let (x, y, z) = (bytemuck::cast(x), bytemuck::cast(y), bytemuck::cast(z));
        let out = |k: i64| {
            // Value `i` of the stream is coordinate `i mod 3` of point `i / 3`;
            // `x` is source lanes 0–7 of the first permute, `y` lanes 8–15.
            let lane = |i: i64| match i % 3 {
                1 => 8 + i / 3,
                _ => i / 3,
            };
            let l = |j: i64| lane(8 * k + j);
            let index =
                self.avx512f
                    ._mm512_setr_epi64(l(0), l(1), l(2), l(3), l(4), l(5), l(6), l(7));
            let xy = self.avx512f._mm512_permutex2var_pd(x, index, y);
            let zs = (0..8)
                .filter(|j| (8 * k + j) % 3 == 2)
                .fold(0u8, |m, j| m | 1 << j);
            bytemuck::cast(self.avx512f._mm512_mask_permutexvar_pd(xy, zs, index, z))
        };
        Some([out(0), out(1), out(2)])
    }
}

/// The point of a curve of control `points` at one vector of parameters
/// `t`: its Cartesian coordinates, then its weight.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn curve_point<const S: usize, V: pulp::Simd>(
    simd: V,
    points: &[[f64; S]],
    t: V::f64s,
) -> [V::f64s; S] {
    let a = simd.sub_f64s(simd.splat_f64s(1.0), t);
    let h = curve_vector::<S, V>(simd, points, a, t);
    let mut x = h;
    for x in &mut x[..S - 1] {
        *x = simd.div_f64s(*x, h[S - 1]);
    }
    x
}

/// The Cartesian coordinates `h[c] / h[d]` (`d = S − 1`) of a group's
/// homogeneous points, all lanes in one straight block, kept whole
/// vectors by `black_box` (which holds them in memory: otherwise the
/// compiler splits them to fit the stores of [`write()`], half as wide; 15 %
/// on a cubic triangle). `x[d]` is the weight itself.
#[inline(always)]
fn quotients<const S: usize, const L: usize>(h: &[Lane<L>; S]) -> [Lane<L>; S] {
    let d = S - 1;
    let mut x: [Lane<L>; S] = each(|c| lane(|l| if c < d { h[c][l] / h[d][l] } else { h[d][l] }));
    std::hint::black_box(&mut x);
    x
}

/// A group's points `x` ([`quotients`]) into `o`, up to the first at
/// infinity (none in a group whose weights are all non-zero: the common
/// case, written by a loop of fixed length).
///
/// # Errors
///
/// [`Error::PointAtInfinity`] if a weight of the group's real points is
/// zero.
#[inline(always)]
fn write<const S: usize, const L: usize, T: Any>(
    x: [Lane<L>; S],
    o: &mut [T],
) -> Result<(), Error> {
    let d = S - 1;
    // A branch-free test of every lane first (one vector compare; the
    // unused lanes have the parameter 0, never a weight of 0 there unless
    // the first control point's), the search only if it finds a zero.
    let any_zero = x[d].iter().fold(false, |z, w| z | (*w == 0.0));
    let finite = match any_zero {
        true => x[d][..o.len() / d].iter().position(|w| *w == 0.0),
        false => None,
    };
    let o = match finite {
        Some(f) => &mut o[..f * d],
        None => o,
    };
    for (l, o) in o.chunks_exact_mut(d).enumerate() {
        for (o, xk) in o.iter_mut().zip(x) {
            *as_f64_mut(o) = xk[l];
        }
    }
    match finite {
        Some(_) => Err(Error::PointAtInfinity),
        None => Ok(()),
    }
}

/// [`jets_batch`] at the stride `S`.
#[inline(always)]
fn jets<const S: usize, const L: usize, const SQUARE: usize, T: Any, V: Target>(
    simd: V,
    nets: &[Net<T>],
    params: &[T],
    out: &mut [T],
    rows: &mut Vec<f64>,
) {
    let shape = nets[0].shape();
    let k = shape.params();
    let per_point = nets.len() * S;
    for (p, o) in params.chunks(L * k).zip(out.chunks_mut(L * per_point)) {
        let hom = hom_lanes(shape, p);
        for (i, net) in nets.iter().filter_map(f64_net).enumerate() {
            let h = hom_net::<S, L, SQUARE, V>(simd, net, &hom, rows);
            for (l, o) in o.chunks_exact_mut(per_point).enumerate() {
                for (o, hk) in o[i * S..(i + 1) * S].iter_mut().zip(&h) {
                    *as_f64_mut(o) = hk[l];
                }
            }
        }
    }
}

/// The lane-major homogeneous parameters of up to `L` points
/// (`shape.params()` values each, `0` in the unused lanes).
#[inline(always)]
fn hom_lanes<const L: usize, T: Any>(shape: Shape, params: &[T]) -> Hom<L> {
    let (p, q) = match shape {
        Shape::Curve(_) => (column::<L, 1, T>(params, 0), [0.0; L]),
        _ => (column::<L, 2, T>(params, 0), column::<L, 2, T>(params, 1)),
    };
    let minus = |x: &Lane<L>, y: &Lane<L>| -> Lane<L> { lane(|l| x[l] - y[l]) };
    let one = [1.0; L];
    match shape {
        Shape::Curve(_) => [minus(&one, &p), p, one, one],
        Shape::Rect(..) => [minus(&one, &p), p, minus(&one, &q), q],
        Shape::Tri(_) => [p, q, minus(&minus(&one, &p), &q), one],
    }
}

/// Parameter `j` of each of up to `L` points of `K` parameters each
/// (`0` in the unused lanes). A whole group is read as an array of known
/// length, which the compiler loads as vectors; only the last, partial
/// group of a batch goes value by value.
#[inline(always)]
fn column<const L: usize, const K: usize, T: Any>(params: &[T], j: usize) -> Lane<L> {
    let (points, _) = params.as_chunks::<K>();
    match <&[[T; K]; L]>::try_from(points) {
        Ok(whole) => lane(|l| as_f64(&whole[l][j])),
        Err(_) => lane(|l| points.get(l).map_or(0.0, |p| as_f64(&p[j]))),
    }
}

/// The homogeneous points of `net` at a group's parameters `h`, one
/// [`Lane`] per coordinate: the scheme of [`Net::eval_hom_into`], lane by
/// lane, each multiply–add fused or not ([`madd`]); for a rect net of
/// degree `(SQUARE, SQUARE)`, `SQUARE ≤ 3`, if `SQUARE` is not 0 ([`Job`]).
#[inline(always)]
fn hom_net<const S: usize, const L: usize, const SQUARE: usize, V: Target>(
    simd: V,
    net: &Net<f64>,
    h: &Hom<L>,
    rows: &mut Vec<f64>,
) -> [Lane<L>; S] {
    let (g, fused) = (net.scaled(), V::FUSED);
    match (SQUARE, net.shape()) {
        (_, Shape::Curve(n)) => simd.curve::<S, L>(n, g, h),
        (1..=3, _) => simd.square::<S, L, SQUARE>(g, h),
        (_, Shape::Rect(m, n)) => {
            rows.resize((m + 1) * S * L, 0.0);
            let (rows, _) = rows.as_chunks_mut::<L>();
            let (rows, _) = rows.as_chunks_mut::<S>();
            rect::<S, L>(fused, (m, n), g, h, rows)
        }
        (_, Shape::Tri(n)) => tri::<S, L>(fused, n, g, h),
    }
}

/// A rect patch of degree `(m, n)`: the sum of each row of the net by
/// [`horner`] in `v` into `rows` (`m + 1` of them), then the sum of the
/// rows in `u`.
#[inline(always)]
fn rect<const S: usize, const L: usize>(
    fused: bool,
    (m, n): (usize, usize),
    g: &[f64],
    h: &Hom<L>,
    rows: &mut [[Lane<L>; S]],
) -> [Lane<L>; S] {
    for (row, r) in g.chunks_exact((n + 1) * S).zip(rows.iter_mut()) {
        *r = horner::<S, L>(fused, n + 1, broadcast::<S, L>(row), &h[2], &h[3]);
    }
    horner::<S, L>(fused, m + 1, |i, k| rows[i][k], &h[0], &h[1])
}

/// A rect patch of degree `(D, D)`, `D ≤ 3`, in the vector builds: the
/// Bernstein values `a^{D−j} b^j` of each direction first (the binomials
/// are in the scaled net `g`), then each row `Σ_j B_j(v)·G_ij` and the
/// point `Σ_i B_i(u)·row_i`, each term one fused multiply–add. For a
/// bicubic: 94 vector operations a point (12 for the values, 64 for the
/// rows, 16 for the point, 2 for `1 − u`, `1 − v`) and 154 flops, instead
/// of [`rect`]'s 137 and 197, whose Horner steps multiply each term by a
/// power before they add it. A term meets no more roundings than in
/// [`rect`]: the scaled net 1, its value `D − 1`, its own multiply–add
/// and the `D − j` later ones of its row (`2D + 1` at most), then its
/// row's value `D − 1`, the row's multiply–add and the `D − i` later ones
/// in the point (`2D` at most): `4D + 1 = 2m + 2n + 1` in all, so the
/// tolerance of the module holds unchanged.
///
/// Written in the vectors of `V` (`pulp::Simd`: eight `f64` for AVX-512,
/// four for AVX2; the `L` lanes are `L / F64_LANES` of them, each summed
/// on its own), not as loops over the lanes: the fat-LTO build
/// re-vectorised those loops with permutes and ran the bicubic at 6.0–6.3
/// ns a point against 4.8–5.4 this way (`peer_eval`, 2026-11-28).
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn rect_bernstein<const S: usize, const L: usize, const D: usize, V: pulp::Simd>(
    simd: V,
    g: &[f64],
    h: &Hom<L>,
) -> [Lane<L>; S] {
    let (points, _) = g.as_chunks::<S>();
    let (a, b) = (V::as_simd_f64s(&h[0]).0, V::as_simd_f64s(&h[1]).0);
    let (c, d) = (V::as_simd_f64s(&h[2]).0, V::as_simd_f64s(&h[3]).0);
    let mut out = [[0.0; L]; S];
    for q in 0..a.len() {
        let o = square_vector::<S, D, V>(simd, points, [a[q], b[q], c[q], d[q]]);
        for (out, o) in out.iter_mut().zip(o) {
            V::as_mut_simd_f64s(out).0[q] = o;
        }
    }
    out
}

/// [`rect_bernstein`] on one vector of lanes `(1 − u, u, 1 − v, v)`.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn square_vector<const S: usize, const D: usize, V: pulp::Simd>(
    simd: V,
    points: &[[f64; S]],
    [a, b, c, d]: [V::f64s; 4],
) -> [V::f64s; S] {
    let bu = bernstein::<V, D>(simd, a, b);
    let bv = bernstein::<V, D>(simd, c, d);
    let mut o = [simd.splat_f64s(0.0); S];
    for i in 0..=D {
        let row = &points[i * (D + 1)..(i + 1) * (D + 1)];
        for (k, o) in o.iter_mut().enumerate() {
            let mut r = simd.mul_f64s(bv[0], simd.splat_f64s(row[0][k]));
            for j in 1..=D {
                r = simd.mul_add_f64s(bv[j], simd.splat_f64s(row[j][k]), r);
            }
            *o = match i {
                0 => simd.mul_f64s(bu[0], r),
                _ => simd.mul_add_f64s(bu[i], r, *o),
            };
        }
    }
    o
}

/// `a^{D−j} b^j` for `j ≤ D ≤ 3` in each lane of a vector (the entries
/// past `D` are 0): products of running powers, at most `D − 1`
/// roundings each.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn bernstein<V: pulp::Simd, const D: usize>(simd: V, a: V::f64s, b: V::f64s) -> [V::f64s; 4] {
    let (one, zero) = (simd.splat_f64s(1.0), simd.splat_f64s(0.0));
    let (a2, b2) = (simd.mul_f64s(a, a), simd.mul_f64s(b, b));
    match D {
        0 => [one, zero, zero, zero],
        1 => [a, b, zero, zero],
        2 => [a2, simd.mul_f64s(a, b), b2, zero],
        _ => [
            simd.mul_f64s(a2, a),
            simd.mul_f64s(a2, b),
            simd.mul_f64s(a, b2),
            simd.mul_f64s(b2, b),
        ],
    }
}

/// A curve of degree `n` in the vector builds, in `V`'s vectors (eight
/// `f64` for AVX-512, four for AVX2; the `L` lanes are `L / F64_LANES` of
/// them, each evaluated on its own by [`curve_vector`]).
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn curve_vectors<const S: usize, const L: usize, V: pulp::Simd>(
    simd: V,
    n: usize,
    g: &[f64],
    h: &Hom<L>,
) -> [Lane<L>; S] {
    let (points, _) = g.as_chunks::<S>();
    let points = &points[..=n];
    let (a, b) = (V::as_simd_f64s(&h[0]).0, V::as_simd_f64s(&h[1]).0);
    let mut out = [[0.0; L]; S];
    for (q, (a, b)) in a.iter().zip(b).enumerate() {
        for (out, x) in out
            .iter_mut()
            .zip(curve_vector::<S, V>(simd, points, *a, *b))
        {
            V::as_mut_simd_f64s(out).0[q] = x;
        }
    }
    out
}

/// The homogeneous points of a curve of control `points` at one vector
/// of homogeneous parameters `(a, b) = (1 − t, t)`: [`horner_vectors`]
/// below degree [`BLOCK`], [`curve_blocks`] from it.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn curve_vector<const S: usize, V: pulp::Simd>(
    simd: V,
    points: &[[f64; S]],
    a: V::f64s,
    b: V::f64s,
) -> [V::f64s; S] {
    match points.len() > BLOCK {
        true => curve_blocks::<S, V>(simd, points, a, b),
        false => horner_vectors::<S, V>(simd, points, a, b),
    }
}

/// [`horner`] on one vector of lanes, every multiply–add fused: the same
/// operations in the same order.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn horner_vectors<const S: usize, V: pulp::Simd>(
    simd: V,
    points: &[[f64; S]],
    a: V::f64s,
    b: V::f64s,
) -> [V::f64s; S] {
    let mut acc = vectors::<S, V>(simd, |k| simd.splat_f64s(points[0][k]));
    let mut bpow = simd.splat_f64s(1.0);
    for point in &points[1..] {
        bpow = simd.mul_f64s(bpow, b);
        for (acc, x) in acc.iter_mut().zip(point) {
            let term = simd.mul_f64s(bpow, simd.splat_f64s(*x));
            *acc = simd.mul_add_f64s(*acc, a, term);
        }
    }
    acc
}

/// The terms `K` of a block of [`curve_blocks`].
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
const BLOCK: usize = 4;

/// A curve of degree `n ≥ K` ([`BLOCK`]) in the vector builds:
/// `Σ_i a^{n−i} bⁱ G_i` (binomials in the scaled net's
/// `points`) by blocks of `K`
/// terms. The first `k₀` terms (`k₀ ≡ n + 1 mod K`, `1 ≤ k₀ ≤ K`) go
/// by [`horner_vectors`]; then, Horner-like over the blocks,
///
/// ```text
/// acc ← acc·a^K + b^s·Σ_{r<K} a^{K−1−r} b^r G_{s+r}      s = k₀, k₀ + K, …, n + 1 − K
/// ```
///
/// with the Bernstein values `a^{K−1−r} b^r` computed once a group
/// ([`block_values`]). A block costs `K + 2` multiply–adds or multiplies a
/// coordinate for `K` terms, against `2K` by [`horner_vectors`], and its sums do
/// not wait on the blocks before it: one multiply–add a block is the
/// whole chain of latencies, not one a term. Measured (`peer_eval`,
/// AVX-512, builds without LTO, 2026-11-28, load 1.7–2.5): planar degree
/// 40 8.3 → 6.0 ns a point, degree 10 2.7–3.0 → 2.4–2.6; AVX2 degree 40
/// 14.4 → 11.2, degree 10 unchanged (4.2); blocks of 5 or 8 terms
/// were slower than by Horner (their values no longer fit the registers).
///
/// Roundings: a term of a block starting at `s` meets at most `n + K + 1
/// ≤ 2n + 1`: the scaled net 1, its value `K − 2`, its block's
/// multiply–adds `K`, `b^s` `s − 1` and the product by it 1, its step 1,
/// and `K` for each of the `(n + 1 − s − K)/K` later blocks (`a^K` `K −
/// 1`, the step 1). A term of the first `k₀` meets `2k₀ − 1` in
/// [`horner_vectors`] and `K` a later block: `n + k₀` in all. So the tolerance of
/// the module holds unchanged.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn curve_blocks<const S: usize, V: pulp::Simd>(
    simd: V,
    points: &[[f64; S]],
    a: V::f64s,
    b: V::f64s,
) -> [V::f64s; S] {
    let (a, b) = (powers(simd, a), powers(simd, b));
    let first = match points.len() % BLOCK {
        0 => BLOCK,
        k => k,
    };
    let mut acc = horner_vectors::<S, V>(simd, &points[..first], a[1], b[1]);
    let (values, mut bs) = (block_values(simd, &a, &b), b[first]);
    let (blocks, _) = points[first..].as_chunks::<BLOCK>();
    for (q, block) in blocks.iter().enumerate() {
        if q > 0 {
            bs = simd.mul_f64s(bs, b[BLOCK]);
        }
        let sum = block_sum::<S, V>(simd, &values, block);
        for (acc, sum) in acc.iter_mut().zip(sum) {
            *acc = simd.mul_add_f64s(*acc, a[BLOCK], simd.mul_f64s(bs, sum));
        }
    }
    acc
}

/// `x^j` for `j ≤ BLOCK` in every lane, by running products (`j − 1`
/// roundings).
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn powers<V: pulp::Simd>(simd: V, x: V::f64s) -> [V::f64s; BLOCK + 1] {
    let mut p = [simd.splat_f64s(1.0); BLOCK + 1];
    p[1] = x;
    for j in 2..=BLOCK {
        p[j] = simd.mul_f64s(p[j - 1], x);
    }
    p
}

/// The Bernstein values `a^{K−1−r} b^r`, `r < K = BLOCK`, from the
/// powers of [`powers`] (`K − 2` roundings at most).
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn block_values<V: pulp::Simd>(
    simd: V,
    a: &[V::f64s; BLOCK + 1],
    b: &[V::f64s; BLOCK + 1],
) -> [V::f64s; BLOCK] {
    let mut v = [simd.splat_f64s(0.0); BLOCK];
    for (r, v) in v.iter_mut().enumerate() {
        *v = match (r, BLOCK - 1 - r) {
            (0, e) => a[e],
            (r, 0) => b[r],
            (r, e) => simd.mul_f64s(a[e], b[r]),
        };
    }
    v
}

/// `Σ_r v_r P_r` over the `K` ([`BLOCK`]) points `P` of a block, each
/// coordinate a chain of fused multiply–adds.
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn block_sum<const S: usize, V: pulp::Simd>(
    simd: V,
    v: &[V::f64s; BLOCK],
    points: &[[f64; S]; BLOCK],
) -> [V::f64s; S] {
    let mut out = vectors::<S, V>(simd, |k| simd.mul_f64s(v[0], simd.splat_f64s(points[0][k])));
    for (v, p) in v.iter().zip(points).skip(1) {
        for (o, x) in out.iter_mut().zip(p) {
            *o = simd.mul_add_f64s(*v, simd.splat_f64s(*x), *o);
        }
    }
    out
}

/// A tri patch of degree `n`: for each `j`, the points `G_{i,j,k}`
/// (`i + k = n − j`) summed by [`horner`] in `(w, u)`, added to the
/// point times `vʲ`.
#[inline(always)]
fn tri<const S: usize, const L: usize>(
    fused: bool,
    n: usize,
    g: &[f64],
    h: &Hom<L>,
) -> [Lane<L>; S] {
    let (mut out, mut vpow, mut start) = ([[0.0; L]; S], [1.0; L], 0);
    for j in 0..=n {
        let len = (n - j + 1) * S;
        let r = horner::<S, L>(
            fused,
            n - j + 1,
            broadcast::<S, L>(&g[start..start + len]),
            &h[2],
            &h[0],
        );
        start += len;
        if j == 0 {
            out = r;
        } else {
            for (o, r) in out.iter_mut().zip(&r) {
                for l in 0..L {
                    o[l] = madd(fused, vpow[l], r[l], o[l]);
                }
            }
        }
        if j < n {
            for l in 0..L {
                vpow[l] *= h[1][l];
            }
        }
    }
    out
}

/// Coordinate `k` of point `i` of `points` (`S` scalars a point), the same
/// in every lane. The points are read as arrays of `S`, so that a Horner
/// step checks the bound of `i` once, not once per coordinate.
#[inline(always)]
fn broadcast<const S: usize, const L: usize>(
    points: &[f64],
) -> impl Fn(usize, usize) -> Lane<L> + '_ {
    let (points, _) = points.as_chunks::<S>();
    move |i, k| [points[i][k]; L]
}

/// `Σ_i a^{count−1−i} bⁱ G_i` by Horner in every lane, `G_i` coordinate
/// `k` being `point(i, k)`: the operations of `horner_width` in [`super`]
/// (`bⁱ ← bⁱ⁻¹·b`, `acc ← acc·a + bⁱ·G_i`), in the same order, the
/// multiply–add fused or not ([`madd`]).
#[inline(always)]
fn horner<const S: usize, const L: usize>(
    fused: bool,
    count: usize,
    point: impl Fn(usize, usize) -> Lane<L>,
    a: &Lane<L>,
    b: &Lane<L>,
) -> [Lane<L>; S] {
    let mut acc: [Lane<L>; S] = each(|k| point(0, k));
    let mut bpow = [1.0; L];
    for i in 1..count {
        for l in 0..L {
            bpow[l] *= b[l];
        }
        for (k, acc) in acc.iter_mut().enumerate() {
            let x = point(i, k);
            for l in 0..L {
                acc[l] = madd(fused, acc[l], a[l], bpow[l] * x[l]);
            }
        }
    }
    acc
}

/// The lane `[f(0), …, f(L − 1)]`, by a loop that is inlined whole
/// (`std::array::from_fn` of 16 values was left as a call in the AVX-512
/// build, its body not vectorised: 2–3× slower).
#[inline(always)]
fn lane<const L: usize>(f: impl Fn(usize) -> f64) -> Lane<L> {
    let mut x = [0.0; L];
    for (l, x) in x.iter_mut().enumerate() {
        *x = f(l);
    }
    x
}

/// The vectors `[f(0), …, f(N − 1)]`, as [`lane`]: an array's `map`
/// may be left as a call, compiled without the instruction set's
/// features (the bicubic's `h.each_ref().map(…)` was, in a fat-LTO build
/// of 2026-11-29: 1.9 → 2.8 ns a point).
#[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
#[inline(always)]
fn vectors<const N: usize, V: pulp::Simd>(simd: V, f: impl Fn(usize) -> V::f64s) -> [V::f64s; N] {
    let mut x = [simd.splat_f64s(0.0); N];
    for (k, x) in x.iter_mut().enumerate() {
        *x = f(k);
    }
    x
}

/// The coordinates `[f(0), …, f(S − 1)]` of a group, as [`lane`].
#[inline(always)]
fn each<const S: usize, const L: usize>(f: impl Fn(usize) -> Lane<L>) -> [Lane<L>; S] {
    let mut x = [[0.0; L]; S];
    for (k, x) in x.iter_mut().enumerate() {
        *x = f(k);
    }
    x
}

/// `x·y + z`: one fused multiply–add (one rounding) if `fused`, else a
/// multiply and an add (two roundings: the scalar kernel's operations).
/// Only the vector builds, whose instruction sets have FMA, pass `true`
/// (without the instruction `mul_add` is a slow library call).
#[inline(always)]
fn madd(fused: bool, x: f64, y: f64, z: f64) -> f64 {
    if fused {
        x.mul_add(y, z)
    } else {
        x * y + z
    }
}

/// `net` as a net of `f64` (`None` unless `T` is `f64`).
#[inline(always)]
fn f64_net<T: Any>(net: &Net<T>) -> Option<&Net<f64>> {
    (net as &dyn Any).downcast_ref()
}

/// `x`, an `f64` as the type `T`, as an `f64`.
#[inline(always)]
fn as_f64<T: Any>(x: &T) -> f64 {
    *(x as &dyn Any).downcast_ref().expect("the scalar is f64")
}

/// [`as_f64`], mutable (or an array of `f64`, as the array of `T`).
#[inline(always)]
fn as_f64_mut<T: Any, F: Any>(x: &mut T) -> &mut F {
    (x as &mut dyn Any)
        .downcast_mut()
        .expect("the scalar is f64")
}

#[cfg(test)]
mod tests {
    use super::super::{Evaluator, Jets};
    use super::*;
    use crate::hpoint::HPoint;
    use crate::{BigInt, BigRational};
    use crate::{RationalCurve, RectPatch, TriPatch};
    use num_traits::{One, Signed, Zero};
    use proptest::prelude::*;

    /// A random rational net of `shape`: coordinates in `[−10, 10]`,
    /// weights in `[1/2, 2]`, `stride` coordinates a point.
    fn net(shape: Shape, stride: usize) -> impl Strategy<Value = Vec<HPoint<f64>>> {
        let point = (
            prop::collection::vec(-10.0..10.0f64, stride - 1),
            0.5..2.0f64,
        )
            .prop_map(|(x, w)| HPoint {
                coords: x.iter().map(|x| x * w).chain([w]).collect(),
            });
        prop::collection::vec(point, shape.points())
    }

    /// A random shape with its net (stride 3 or 4) and a batch of 0 … 21
    /// parameter points in its domain (`u + v ≤ 1` for a tri patch).
    fn case() -> impl Strategy<Value = (Shape, Vec<HPoint<f64>>, Vec<f64>)> {
        let shape = prop_oneof![
            (0..=12usize).prop_map(Shape::Curve),
            (0..=4usize, 0..=4usize).prop_map(|(m, n)| Shape::Rect(m, n)),
            // The bicubic's own kernel (`rect_bernstein` in the vector builds).
            Just(Shape::Rect(3, 3)),
            (0..=6usize).prop_map(Shape::Tri),
        ];
        (shape, 3..=4usize, 0..=21usize).prop_flat_map(|(shape, stride, points)| {
            let params =
                prop::collection::vec((0.0..=1.0f64, 0.0..=1.0f64), points).prop_map(move |uv| {
                    uv.into_iter()
                        .flat_map(|(u, v)| match shape {
                            Shape::Curve(_) => vec![u],
                            Shape::Tri(_) => vec![u, v * (1.0 - u)],
                            Shape::Rect(..) => vec![u, v],
                        })
                        .collect::<Vec<f64>>()
                });
            (Just(shape), net(shape, stride), params)
        })
    }

    /// The evaluator and the jets of a net of `shape`, built from its
    /// curve or patch.
    fn kernels(shape: Shape, points: Vec<HPoint<f64>>) -> (Evaluator<f64>, Jets<f64>) {
        match shape {
            Shape::Curve(_) => {
                let c = RationalCurve::from_hom(points).unwrap();
                (Evaluator::curve(&c), Jets::curve(&c))
            }
            Shape::Rect(_, n) => {
                let rows = points.chunks(n + 1).map(<[_]>::to_vec).collect();
                let r = RectPatch::from_hom(rows).unwrap();
                (Evaluator::rect(&r), Jets::rect(&r))
            }
            Shape::Tri(n) => {
                let mut rest = points.as_slice();
                let rows = (0..=n)
                    .map(|j| {
                        let (row, tail) = rest.split_at(n - j + 1);
                        rest = tail;
                        row.to_vec()
                    })
                    .collect();
                let t = TriPatch::from_hom(rows).unwrap();
                (Evaluator::tri(&t), Jets::tri(&t))
            }
        }
    }

    /// The homogeneous points of `jets` at `params`, one jet after another:
    /// [`Jets::eval_into`] point by point, the scalar reference.
    fn scalar_jets(jets: &mut Jets<f64>, params: &[f64], k: usize) -> Vec<f64> {
        let per_jet = (k + 1) * jets.stride();
        let mut out = vec![f64::NAN; params.len() / k * per_jet];
        for (p, o) in params.chunks(k).zip(out.chunks_mut(per_jet)) {
            jets.eval_into(p, o);
        }
        out
    }

    /// The bits of `values`, so that `prop_assert_eq!` compares them
    /// exactly.
    fn bits(values: &[f64]) -> Vec<u64> {
        values.iter().map(|v| v.to_bits()).collect()
    }

    /// `x` exactly.
    fn q(x: f64) -> BigRational {
        BigRational::from_float(x).expect("a finite f64")
    }

    /// `K`, the most roundings a term of the sum meets in either kernel
    /// (module documentation, Tolerance).
    fn roundings(shape: Shape) -> i64 {
        let k = match shape {
            Shape::Curve(n) => 2 * n + 1,
            Shape::Rect(m, n) => 2 * m + 2 * n + 1,
            Shape::Tri(n) => 3 * n + 1,
        };
        k as i64
    }

    /// `γ_K = K·u / (1 − K·u)`, `u = 2⁻⁵³` (Higham, *Accuracy and
    /// Stability of Numerical Algorithms*, 2nd ed., Lemma 3.1), for the
    /// roundings `K` of [`roundings`].
    fn gamma(shape: Shape) -> BigRational {
        let ku = BigRational::new(roundings(shape).into(), BigInt::from(1u64 << 53));
        ku.clone() / (BigRational::one() - ku)
    }

    /// The exact homogeneous point `H` of `net` at the `f64` homogeneous
    /// parameters `hom` (those both kernels compute), and `H̃`, the same
    /// sum with every control coordinate and parameter replaced by its
    /// absolute value: the generic kernel over `BigRational`.
    fn exact(net: &Net<f64>, hom: &[f64]) -> (Vec<BigRational>, Vec<BigRational>) {
        let sum = |f: &dyn Fn(f64) -> f64| {
            let n = net.map_coords(net.coords().iter().map(|x| q(f(*x))).collect());
            let h: Vec<BigRational> = hom.iter().map(|x| q(f(*x))).collect();
            let mut out = vec![BigRational::zero(); net.stride()];
            n.eval_hom_into(&h, &mut out, &mut n.workspace());
            out
        };
        (sum(&|x| x), sum(&f64::abs))
    }

    /// The homogeneous parameters of one parameter point, as the kernels
    /// compute them.
    fn hom(shape: Shape, p: &[f64]) -> Vec<f64> {
        match shape {
            Shape::Curve(_) => vec![1.0 - p[0], p[0]],
            Shape::Rect(..) => vec![1.0 - p[0], p[0], 1.0 - p[1], p[1]],
            Shape::Tri(_) => vec![p[0], p[1], 1.0 - p[0] - p[1]],
        }
    }

    /// Whether each computed homogeneous coordinate `got` is within
    /// `γ_K·H̃` of the exact `H` (the module's tolerance).
    fn hom_within(
        got: &[f64],
        (h, abs): &(Vec<BigRational>, Vec<BigRational>),
        g: &BigRational,
    ) -> bool {
        got.iter()
            .zip(h.iter().zip(abs))
            .all(|(x, (h, a))| (q(*x) - h).abs() <= g.clone() * a)
    }

    /// Whether each computed Cartesian coordinate `got` is within the
    /// bound of the module's tolerance of the exact `X_k = H_k / H_w`.
    fn point_within(
        got: &[f64],
        (h, abs): &(Vec<BigRational>, Vec<BigRational>),
        g: &BigRational,
    ) -> bool {
        let d = h.len() - 1;
        let u = BigRational::new(1.into(), BigInt::from(1u64 << 53));
        let room = h[d].abs() - g.clone() * &abs[d];
        room.is_positive()
            && got.iter().enumerate().all(|(k, x)| {
                let exact = h[k].clone() / &h[d];
                let b = g.clone() * (abs[k].clone() + exact.abs() * &abs[d]) / &room;
                let bound = b.clone() * (BigRational::one() + &u) + u.clone() * exact.abs();
                (q(*x) - exact).abs() <= bound
            })
    }

    proptest! {
        /// The baseline build equals the scalar reference (one point at a
        /// time, `eval_into`) bit for bit; the build chosen at run time
        /// (AVX2 or AVX-512, with fused multiply–adds), the public
        /// batches, and the scalar kernel itself are within the bound of
        /// the module's tolerance of the exact value (computed in
        /// `BigRational` from the same `f64` inputs), so the fused lanes
        /// and the scalar kernel differ by at most twice it — for points
        /// and jets of random rational curves, rect and tri patches, on
        /// batches of every length (full groups and a padded last group).
        #[test]
        fn lanes_are_within_the_documented_tolerance((shape, points, params) in case()) {
            let (mut ev, mut jets) = kernels(shape, points);
            let (k, d) = (shape.params(), jets.stride() - 1);
            let mut scalar = vec![f64::NAN; params.len() / k * d];
            for (p, o) in params.chunks(k).zip(scalar.chunks_mut(d)) {
                ev.eval_into(p, o).unwrap();
            }
            let scalar_jets = scalar_jets(&mut jets, &params, k);
            let mut rows = Vec::new();
            let mut batch = vec![f64::NAN; scalar.len()];
            eval_batch(Isa::Baseline, &ev.net, &params, &mut batch, &mut rows)
                .expect("an f64 net of stride 3 or 4")
                .unwrap();
            prop_assert_eq!(bits(&batch), bits(&scalar));
            let mut jet_batch = vec![f64::NAN; scalar_jets.len()];
            jets_batch(Isa::Baseline, &jets.nets, &params, &mut jet_batch, &mut rows)
                .expect("f64 nets of stride 3 or 4");
            prop_assert_eq!(bits(&jet_batch), bits(&scalar_jets));
            let mut fused = Vec::new();
            for isa in vector_builds() {
                let (mut points, mut jet_points) = (batch.clone(), jet_batch.clone());
                eval_batch(isa, &ev.net, &params, &mut points, &mut rows).unwrap().unwrap();
                jets_batch(isa, &jets.nets, &params, &mut jet_points, &mut rows).unwrap();
                fused.push((points, jet_points));
            }
            let mut public = batch.clone();
            ev.eval_batch(&params, &mut public).unwrap();
            let mut public_jets = jet_batch.clone();
            jets.eval_batch(&params, &mut public_jets).unwrap();
            let g = gamma(shape);
            let per_jet = jets.nets.len() * (d + 1);
            for (i, p) in params.chunks(k).enumerate() {
                let h = hom(shape, p);
                let e = exact(&ev.net, &h);
                for got in [&scalar, &public].into_iter().chain(fused.iter().map(|f| &f.0)) {
                    prop_assert!(point_within(&got[i * d..(i + 1) * d], &e, &g), "point {}", i);
                }
                for (j, net) in jets.nets.iter().enumerate() {
                    let e = exact(net, &h);
                    let at = i * per_jet + j * (d + 1);
                    for got in [&scalar_jets, &public_jets].into_iter().chain(fused.iter().map(|f| &f.1)) {
                        prop_assert!(hom_within(&got[at..at + d + 1], &e, &g), "jet {} of point {}", j, i);
                    }
                }
            }
        }
    }

    /// The vector builds this processor runs: the widest
    /// ([`Isa::detect`]) and, on an AVX-512 one, the AVX2 build as well.
    fn vector_builds() -> Vec<Isa> {
        let mut isas = vec![Isa::detect()];
        #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
        if let (Isa::Avx512(_), Some(v3)) = (isas[0], pulp::x86::V3::try_new()) {
            isas.push(Isa::Avx2(v3));
        }
        isas
    }

    /// The same for spatial patches, whose whole groups go out by one
    /// interleave of three vectors in the AVX-512 build: a linear triangle
    /// with the weights `1` at `w = 1`, `−1` at `u = 1` and `1` at `v = 1`
    /// (weight `1 − 2u` on the edge `v = 0`), and a bicubic whose first
    /// two rows weigh `1` and last two `−1` (weight zero at `u = 1/2` by
    /// symmetry, every value exact on dyadic parameters); 16 points
    /// `(u, v) = (k/16, 0)`, the zero at `k = 8`, the first point of the
    /// second group of 8. The batch
    /// fails with the scalar kernel's error, after writing the 8 points
    /// before it, each within the module's tolerance of the scalar kernel
    /// (here within 8 units in the last place of the largest coordinate).
    #[test]
    fn a_zero_weight_in_a_whole_group_of_spatial_points() {
        let h = |x: f64, y: f64, z: f64, w: f64| HPoint {
            coords: vec![x * w, y * w, z * w, w],
        };
        let tri = vec![
            h(0.0, 0.0, 1.0, 1.0),
            h(1.0, 0.0, 2.0, -1.0),
            h(0.0, 1.0, 3.0, 1.0),
        ];
        let square = (0..16)
            .map(|k| {
                let (i, j) = ((k / 4) as f64, (k % 4) as f64);
                h(i, j, i * j - 1.5, if k < 8 { 1.0 } else { -1.0 })
            })
            .collect();
        for (shape, points) in [(Shape::Tri(1), tri), (Shape::Rect(3, 3), square)] {
            let (mut ev, _) = kernels(shape, points);
            let params: Vec<f64> = (0..16).flat_map(|k| [k as f64 / 16.0, 0.0]).collect();
            let mut scalar = [0.0; 3];
            assert!(
                matches!(
                    ev.eval_into(&params[16..18], &mut scalar),
                    Err(Error::PointAtInfinity)
                ),
                "{shape:?}: {scalar:?}"
            );
            for isa in vector_builds() {
                let mut out = [f64::NAN; 48];
                let done = eval_batch(isa, &ev.net, &params, &mut out, &mut Vec::new());
                assert!(
                    matches!(done, Some(Err(Error::PointAtInfinity))),
                    "{shape:?} {isa:?}"
                );
                for (p, x) in params[..16].chunks(2).zip(out.chunks_exact(3)) {
                    ev.eval_into(p, &mut scalar).unwrap();
                    let scale = scalar.iter().fold(1.0f64, |m, c| m.max(c.abs()));
                    for (x, s) in x.iter().zip(&scalar) {
                        assert!(
                            (x - s).abs() <= 8.0 * f64::EPSILON * scale,
                            "{shape:?} {isa:?} at {p:?}"
                        );
                    }
                }
            }
        }
    }

    /// A fused multiply–add changes the value where the scalar kernel's
    /// two roundings lose something: at `t = 1/3` on the cubic below, the
    /// build with FMA gives a different last bit from the baseline on at
    /// least one of 64 points, so the test above does check a tolerance,
    /// not bit identity, on such a processor.
    #[cfg(all(feature = "simd", target_arch = "x86_64"))]
    #[test]
    fn fused_lanes_differ_from_the_scalar_kernel_somewhere() {
        if !std::is_x86_feature_detected!("fma") || matches!(Isa::detect(), Isa::Baseline) {
            return;
        }
        let c = RationalCurve::new(
            vec![
                vec![0.1, 0.7],
                vec![1.3, -2.9],
                vec![3.7, 2.3],
                vec![4.1, 0.3],
            ],
            vec![1.0, 0.3, 1.7, 0.9],
        )
        .unwrap();
        let ev = Evaluator::curve(&c);
        let ts: Vec<f64> = (0..64).map(|k| (k as f64 + 0.3) / 67.0).collect();
        let (mut base, mut fused, mut rows) = (vec![0.0; 128], vec![0.0; 128], Vec::new());
        eval_batch(Isa::Baseline, &ev.net, &ts, &mut base, &mut rows)
            .unwrap()
            .unwrap();
        eval_batch(Isa::detect(), &ev.net, &ts, &mut fused, &mut rows)
            .unwrap()
            .unwrap();
        assert_ne!(bits(&base), bits(&fused));
    }

    /// Whether the processor has every feature of x86-64-v3 that the
    /// AVX2 build is compiled with (the standard library's detection,
    /// independent of `pulp`'s).
    #[cfg(all(feature = "simd", target_arch = "x86_64"))]
    fn has_v3() -> bool {
        std::is_x86_feature_detected!("avx2")
            && std::is_x86_feature_detected!("fma")
            && std::is_x86_feature_detected!("bmi1")
            && std::is_x86_feature_detected!("bmi2")
            && std::is_x86_feature_detected!("lzcnt")
            && std::is_x86_feature_detected!("popcnt")
            && std::is_x86_feature_detected!("sse4.2")
    }

    /// Whether it has, besides, the AVX-512 features of x86-64-v4.
    #[cfg(all(feature = "simd", target_arch = "x86_64"))]
    fn has_v4() -> bool {
        has_v3()
            && std::is_x86_feature_detected!("avx512f")
            && std::is_x86_feature_detected!("avx512bw")
            && std::is_x86_feature_detected!("avx512cd")
            && std::is_x86_feature_detected!("avx512dq")
            && std::is_x86_feature_detected!("avx512vl")
    }

    /// Run-time detection picks AVX2 exactly when the processor has the
    /// x86-64-v3 features but not those of x86-64-v4.
    #[cfg(all(feature = "simd", target_arch = "x86_64"))]
    #[test]
    fn detect_takes_avx2_where_the_processor_has_it() {
        assert_eq!(matches!(Isa::detect(), Isa::Avx2(_)), has_v3() && !has_v4());
    }

    /// Run-time detection picks AVX-512 exactly when the processor has
    /// the x86-64-v4 features (the widest build), so that on such a
    /// machine the property test above covers the AVX-512 build.
    #[cfg(all(feature = "simd", target_arch = "x86_64"))]
    #[test]
    fn detect_takes_avx512_where_the_processor_has_it() {
        assert_eq!(matches!(Isa::detect(), Isa::Avx512(_)), has_v4());
    }

    /// A zero weight inside a group is the error of the scalar path: the
    /// line from `(0, 0)` with weight 1 to `(1, 1)` with weight −1 has the
    /// homogeneous point `(−t, −t, 1 − 2t)`, weight zero at `t = 1/2` (the
    /// fifth point of the batch); the points before it are written.
    #[test]
    fn a_zero_weight_is_a_point_at_infinity() {
        let c = RationalCurve::new(vec![vec![0.0, 0.0], vec![1.0, 1.0]], vec![1.0, -1.0]).unwrap();
        let mut ev = Evaluator::curve(&c);
        let ts: Vec<f64> = (0..9).map(|k| k as f64 / 8.0).collect();
        let mut out = [0.0; 18];
        assert!(matches!(
            ev.eval_batch(&ts, &mut out),
            Err(Error::PointAtInfinity)
        ));
        // X(1/4) = −(1/4)/(1/2).
        assert_eq!(out[4..6], [-0.5, -0.5]);
    }

    /// The same in a whole group of a vector build (the planar curves'
    /// interleaved stores stand aside for it): 40 points `t = k/32`, the
    /// zero weight at `k = 16`, the first point of the second group of 16
    /// (AVX-512) or of the third of 8 (AVX2); the 16 points before it are
    /// written, each `X(t) = −t/(1 − 2t)` exactly (dyadic `t`).
    #[test]
    fn a_zero_weight_in_a_whole_group_is_a_point_at_infinity() {
        let c = RationalCurve::new(vec![vec![0.0, 0.0], vec![1.0, 1.0]], vec![1.0, -1.0]).unwrap();
        let ev = Evaluator::curve(&c);
        let ts: Vec<f64> = (0..40).map(|k| k as f64 / 32.0).collect();
        for isa in vector_builds() {
            let mut out = [f64::NAN; 80];
            let done = eval_batch(isa, &ev.net, &ts, &mut out, &mut Vec::new());
            assert!(matches!(done, Some(Err(Error::PointAtInfinity))), "{isa:?}");
            for (t, x) in ts[..16].iter().zip(out.chunks_exact(2)) {
                let expected = -t / (1.0 - 2.0 * t);
                assert_eq!(x, [expected, expected], "{isa:?} at t = {t}");
            }
        }
    }
}
