//! Lane-major `f64` batch kernels: the `f64` fast path of
//! [`Evaluator::eval_batch`](super::Evaluator::eval_batch) and
//! [`Jets::eval_batch`](super::Jets::eval_batch) for nets of stride 3
//! (planar) and 4 (spatial).
//!
//! The points of a batch go [`LANES`] at a time. Every value of the
//! Horner–Bernstein scheme of [`super`] is held as a [`Lane`], one `f64`
//! per point, and every step is a loop over the lanes with no dependence
//! between them, so the compiler turns it into vector instructions on
//! stable Rust, without `unsafe` and without SIMD intrinsics:
//!
//! ```text
//! acc[k][l] ← acc[k][l]·a[l] + bⁱ[l]·G_i[k]        k < stride, l < LANES
//! X[k][l]   = acc[k][l] / acc[w][l]
//! ```
//!
//! Which vector instructions depends on the build the batch runs ([`Isa`]):
//! the baseline one (on `x86_64` SSE2, two `f64` per instruction), or,
//! with the default feature `simd` on a processor that has AVX2 (detected
//! at run time, once), the same kernels compiled with the x86-64-v3
//! features enabled (four `f64` per instruction): `pulp::x86::V3` calls a
//! `#[target_feature]` function on our behalf, safely after its detection,
//! and every kernel below is `#[inline(always)]` so that the whole of it is
//! compiled inside that function. On the development machine (Zen 4) the
//! AVX2 build takes 0.39–0.48 of the baseline build's time per point on
//! planar curves of degree 3, 10 and 40, a cubic triangle and a bicubic
//! (`benches/peers/peer_eval.py`, README, Speed). AVX-512 is not dispatched:
//! `pulp`'s `x86-v4` needs Rust 1.89 (the crate's minimum is 1.85), and
//! Zen 4 runs 512-bit arithmetic as two 256-bit halves.
//!
//! The scalar kernel (`horner` in [`super`], one point at a time) stays
//! the reference: each lane performs the same IEEE operations in the same
//! order as it (Rust never fuses a multiply and an add on its own, even
//! where FMA is enabled, and nothing here asks for `mul_add`), so a
//! batch's values equal the scalar kernel's **bit for bit** in either
//! build — the documented tolerance is zero, and the property test below
//! checks it with `==` on random rational curves, rect and tri patches,
//! through each build. A batch whose length is
//! not a multiple of [`LANES`] fills its last group with the parameter
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
//! spatial bicubic, 107 and 3 for a spatial cubic triangle.

use super::{Net, Shape};
use crate::error::Error;
use std::any::Any;

/// Points evaluated together: each [`Lane`] is two 256-bit or four
/// 128-bit vector registers.
pub(super) const LANES: usize = 8;

/// One `f64` per point of a group.
pub(super) type Lane = [f64; LANES];

/// The homogeneous parameters of a group of points, lane-major: `(1 − t,
/// t)`, `(1 − u, u, 1 − v, v)` or `(u, v, 1 − u − v)`, as
/// [`Net::hom_params`] computes them for one point.
type Hom = [Lane; 4];

/// The instruction set a batch is compiled for: the kernels below are
/// `#[inline(always)]` down to their loops, so [`Isa::run`] compiles them
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
}

impl Isa {
    /// The widest instruction set this processor runs (detected once,
    /// then read from a static), else [`Isa::Baseline`].
    pub(super) fn detect() -> Self {
        #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
        if let Some(v3) = pulp::x86::V3::try_new() {
            return Isa::Avx2(v3);
        }
        Isa::Baseline
    }

    /// `kernel()` compiled for this instruction set (it must be inlined
    /// whole into the call, hence the `#[inline(always)]` of the kernels).
    #[inline(always)]
    fn run<R>(self, kernel: impl FnOnce() -> R) -> R {
        match self {
            Isa::Baseline => kernel(),
            #[cfg(all(feature = "simd", any(target_arch = "x86", target_arch = "x86_64")))]
            Isa::Avx2(v3) => v3.vectorize(kernel),
        }
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
    rows: &mut Vec<Lane>,
) -> Option<Result<(), Error>> {
    let net = (net as &dyn Any).downcast_ref::<Net<f64>>()?;
    match net.stride() {
        3 => Some(isa.run(|| project::<3, T>(net, params, out, rows))),
        4 => Some(isa.run(|| project::<4, T>(net, params, out, rows))),
        _ => None,
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
    rows: &mut Vec<Lane>,
) -> Option<()> {
    let first = (nets.first()? as &dyn Any).downcast_ref::<Net<f64>>()?;
    let nets = nets
        .iter()
        .map(|n| (n as &dyn Any).downcast_ref::<Net<f64>>());
    match first.stride() {
        3 => isa.run(|| jets::<3, T>(first.shape(), nets, params, out, rows)),
        4 => isa.run(|| jets::<4, T>(first.shape(), nets, params, out, rows)),
        _ => return None,
    }
    Some(())
}

/// [`eval_batch`] at the stride `S`.
#[inline(always)]
fn project<const S: usize, T: Any>(
    net: &Net<f64>,
    params: &[T],
    out: &mut [T],
    rows: &mut Vec<Lane>,
) -> Result<(), Error> {
    let (k, d) = (net.shape().params(), S - 1);
    for (p, o) in params.chunks(LANES * k).zip(out.chunks_mut(LANES * d)) {
        let h = hom_net::<S>(net, &hom_lanes(net.shape(), p), rows);
        // The divides of all lanes in one straight block, kept whole
        // vectors by `black_box` (which holds `x` in memory: otherwise the
        // compiler splits them to fit the interleaved stores below, half
        // as wide; 15 % on a cubic triangle), then the points up to the
        // first at infinity (none in a group whose weights are all
        // non-zero: the common case, written by a loop of fixed length).
        // `x[d]` is the weight itself, not written.
        let mut x: [Lane; S] = std::array::from_fn(|c| {
            std::array::from_fn(|l| if c < d { h[c][l] / h[d][l] } else { h[d][l] })
        });
        std::hint::black_box(&mut x);
        let at_infinity = h[d][..o.len() / d].contains(&0.0);
        let o = if at_infinity {
            let finite = h[d].iter().position(|w| *w == 0.0).unwrap_or(LANES);
            &mut o[..finite * d]
        } else {
            o
        };
        for (l, o) in o.chunks_exact_mut(d).enumerate() {
            for (o, xk) in o.iter_mut().zip(&x) {
                *as_f64_mut(o) = xk[l];
            }
        }
        if at_infinity {
            return Err(Error::PointAtInfinity);
        }
    }
    Ok(())
}

/// [`jets_batch`] at the stride `S`.
#[inline(always)]
fn jets<'a, const S: usize, T: Any>(
    shape: Shape,
    nets: impl Iterator<Item = Option<&'a Net<f64>>> + Clone,
    params: &[T],
    out: &mut [T],
    rows: &mut Vec<Lane>,
) {
    let k = shape.params();
    let per_point = nets.clone().count() * S;
    for (p, o) in params
        .chunks(LANES * k)
        .zip(out.chunks_mut(LANES * per_point))
    {
        let hom = hom_lanes(shape, p);
        for (i, net) in nets.clone().enumerate() {
            let h = hom_net::<S>(net.expect("the nets of one jet share T"), &hom, rows);
            for (l, o) in o.chunks_exact_mut(per_point).enumerate() {
                for (o, hk) in o[i * S..(i + 1) * S].iter_mut().zip(&h) {
                    *as_f64_mut(o) = hk[l];
                }
            }
        }
    }
}

/// The lane-major homogeneous parameters of up to [`LANES`] points
/// (`shape.params()` values each, `0` in the unused lanes).
#[inline(always)]
fn hom_lanes<T: Any>(shape: Shape, params: &[T]) -> Hom {
    let k = shape.params();
    let at =
        |j: usize| -> Lane { std::array::from_fn(|l| params.get(l * k + j).map_or(0.0, as_f64)) };
    let (p, q) = (at(0), if k > 1 { at(1) } else { [0.0; LANES] });
    let minus = |x: &Lane, y: &Lane| -> Lane { std::array::from_fn(|l| x[l] - y[l]) };
    let one = [1.0; LANES];
    match shape {
        Shape::Curve(_) => [minus(&one, &p), p, one, one],
        Shape::Rect(..) => [minus(&one, &p), p, minus(&one, &q), q],
        Shape::Tri(_) => [p, q, minus(&minus(&one, &p), &q), one],
    }
}

/// The homogeneous points of `net` at a group's parameters `h`, one
/// [`Lane`] per coordinate: the scheme of [`Net::eval_hom_into`], lane by
/// lane.
#[inline(always)]
fn hom_net<const S: usize>(net: &Net<f64>, h: &Hom, rows: &mut Vec<Lane>) -> [Lane; S] {
    let g = net.scaled();
    match net.shape() {
        Shape::Curve(n) => horner::<S>(n + 1, broadcast::<S>(g), &h[0], &h[1]),
        Shape::Rect(m, n) => {
            rows.resize((m + 1) * S, [0.0; LANES]);
            for (row, r) in g.chunks_exact((n + 1) * S).zip(rows.chunks_exact_mut(S)) {
                r.copy_from_slice(&horner::<S>(n + 1, broadcast::<S>(row), &h[2], &h[3]));
            }
            horner::<S>(m + 1, |i, k| rows[i * S + k], &h[0], &h[1])
        }
        Shape::Tri(n) => {
            let (mut out, mut vpow, mut start) = ([[0.0; LANES]; S], [1.0; LANES], 0);
            for j in 0..=n {
                let len = (n - j + 1) * S;
                let r = horner::<S>(
                    n - j + 1,
                    broadcast::<S>(&g[start..start + len]),
                    &h[2],
                    &h[0],
                );
                start += len;
                if j == 0 {
                    out = r;
                } else {
                    for (o, r) in out.iter_mut().zip(&r) {
                        for l in 0..LANES {
                            o[l] += vpow[l] * r[l];
                        }
                    }
                }
                if j < n {
                    for l in 0..LANES {
                        vpow[l] *= h[1][l];
                    }
                }
            }
            out
        }
    }
}

/// Coordinate `k` of point `i` of `points` (`S` scalars a point), the same
/// in every lane.
#[inline(always)]
fn broadcast<const S: usize>(points: &[f64]) -> impl Fn(usize, usize) -> Lane + '_ {
    move |i, k| [points[i * S + k]; LANES]
}

/// `Σ_i a^{count−1−i} bⁱ G_i` by Horner in every lane, `G_i` coordinate
/// `k` being `point(i, k)`: the operations of `horner_width` in [`super`]
/// (`bⁱ ← bⁱ⁻¹·b`, `acc ← acc·a + bⁱ·G_i`), in the same order.
#[inline(always)]
fn horner<const S: usize>(
    count: usize,
    point: impl Fn(usize, usize) -> Lane,
    a: &Lane,
    b: &Lane,
) -> [Lane; S] {
    let mut acc: [Lane; S] = std::array::from_fn(|k| point(0, k));
    let mut bpow = [1.0; LANES];
    for i in 1..count {
        for l in 0..LANES {
            bpow[l] *= b[l];
        }
        for (k, acc) in acc.iter_mut().enumerate() {
            let x = point(i, k);
            for l in 0..LANES {
                acc[l] = acc[l] * a[l] + bpow[l] * x[l];
            }
        }
    }
    acc
}

/// `x`, an `f64` as the type `T`, as an `f64`.
#[inline(always)]
fn as_f64<T: Any>(x: &T) -> f64 {
    *(x as &dyn Any).downcast_ref().expect("the scalar is f64")
}

/// [`as_f64`], mutable.
#[inline(always)]
fn as_f64_mut<T: Any>(x: &mut T) -> &mut f64 {
    (x as &mut dyn Any)
        .downcast_mut()
        .expect("the scalar is f64")
}

#[cfg(test)]
mod tests {
    use super::super::{Evaluator, Jets};
    use super::*;
    use crate::hpoint::HPoint;
    use crate::{RationalCurve, RectPatch, TriPatch};
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

    proptest! {
        /// The lane kernels equal the scalar reference (one point at a
        /// time, `eval_into`) bit for bit — the documented tolerance is
        /// zero — for points and jets of random rational curves, rect and
        /// tri patches, on batches of every length (full groups and a
        /// padded last group), through the public batches (which take the
        /// scalar kernel itself for fewer than four points) and through
        /// each instruction set: the baseline build and the one chosen at
        /// run time (AVX2 on a processor that has it).
        #[test]
        fn lanes_equal_the_scalar_kernel((shape, points, params) in case()) {
            let (mut ev, mut jets) = kernels(shape, points);
            let (k, d) = (shape.params(), jets.stride() - 1);
            let mut scalar = vec![f64::NAN; params.len() / k * d];
            for (p, o) in params.chunks(k).zip(scalar.chunks_mut(d)) {
                ev.eval_into(p, o).unwrap();
            }
            let scalar_jets = scalar_jets(&mut jets, &params, k);
            let mut batch = vec![f64::NAN; scalar.len()];
            ev.eval_batch(&params, &mut batch).unwrap();
            prop_assert_eq!(bits(&batch), bits(&scalar));
            let mut jet_batch = vec![f64::NAN; scalar_jets.len()];
            jets.eval_batch(&params, &mut jet_batch).unwrap();
            prop_assert_eq!(bits(&jet_batch), bits(&scalar_jets));
            let mut rows = Vec::new();
            for isa in [Isa::Baseline, Isa::detect()] {
                batch.fill(f64::NAN);
                eval_batch(isa, &ev.net, &params, &mut batch, &mut rows)
                    .expect("an f64 net of stride 3 or 4")
                    .unwrap();
                prop_assert_eq!(bits(&batch), bits(&scalar), "{:?}", isa);
                jet_batch.fill(f64::NAN);
                jets_batch(isa, &jets.nets, &params, &mut jet_batch, &mut rows)
                    .expect("f64 nets of stride 3 or 4");
                prop_assert_eq!(bits(&jet_batch), bits(&scalar_jets), "{:?}", isa);
            }
        }
    }

    /// Run-time detection picks AVX2 exactly when the processor has the
    /// x86-64-v3 features the kernels are compiled with (the standard
    /// library's detection, independent of `pulp`'s), so that on such a
    /// machine the property test above covers both builds.
    #[cfg(all(feature = "simd", target_arch = "x86_64"))]
    #[test]
    fn detect_takes_avx2_where_the_processor_has_it() {
        let v3 = std::is_x86_feature_detected!("avx2")
            && std::is_x86_feature_detected!("fma")
            && std::is_x86_feature_detected!("bmi1")
            && std::is_x86_feature_detected!("bmi2")
            && std::is_x86_feature_detected!("lzcnt")
            && std::is_x86_feature_detected!("popcnt")
            && std::is_x86_feature_detected!("sse4.2");
        assert_eq!(matches!(Isa::detect(), Isa::Avx2(_)), v3);
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
}
