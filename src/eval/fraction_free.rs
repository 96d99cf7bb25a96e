//! Fraction-free exact evaluation, the `BigRational` fast path of
//! [`Evaluator::eval_batch`].
//!
//! ```text
//! net:    H_i = L·(w_i P_i, w_i) ∈ Zᵈ⁺¹        (L = lcm of all denominators, once)
//! curve:  t = p/q            → (a : b) = (q − p : p)
//! rect:   u = p/q, v = r/s   → (q − p : p), (s − r : r)
//! tri:    (u, v) = (a/q, b/q) → (a, b, q − a − b)
//! X = H_d / H_w              (reduced with one big gcd per point, below)
//! ```
//!
//! The point's coordinates share their denominator `H_w`, so they are
//! reduced together ([`fractions_over`]): `g = gcd(H_w, ∏ H_d mod H_w)` is
//! the one gcd of the weight's size, and each `gcd(H_d, H_w)` divides `g`,
//! which is mostly 1 or a machine word. A point of `d` coordinates costs
//! one big gcd, not `d`.
//!
//! The kernel is the generic one of [`Net::eval_hom_into`], run point by
//! point on the narrowest integer type that provably holds all its values:
//! `i128`, then [`Wide`] (256 bits, on the stack), then [`Wide512`] (512
//! bits, on the stack), then [`Int`] (machine word or big integer,
//! checked). With `N` the bits of the largest `|H_i|`
//! and `P` those of the largest homogeneous parameter, every value of the
//! kernel has fewer than `E` bits of magnitude:
//!
//! ```text
//! curve n:      E = N + n + n·P + bits(n+1)
//!               (G_i = C(n,i) H_i < 2^{N+n};  out_k = Σ_{i≤k} a^{k−i} bⁱ G_i,  k + 1 terms)
//! rect (m, n):  E = N + m + n + (m+n)·P + bits(m+1) + bits(n+1)
//!               (rows as curves of degree n, then a curve of degree m over them)
//! tri n:        E = N + 2n + n·P + 2·bits(n+1)
//!               (G < 3ⁿ|H| ≤ 2^{2n}|H|;  Σ_j vʲ R_j,  R_j a curve of degree n − j)
//! ```
//!
//! so `E ≤ 127` runs on `i128`, `E ≤ 255` on `Wide` and `E ≤ 511` on
//! `Wide512`, without overflow tests and without allocation.

use super::blocks::BlockedCurve;
use super::{Evaluator, Net, Shape, Workspace};
use crate::algebra::gcd::{fractions_over, fractions_over_limbs, gcd_u128, Scratch, SignedLimbs};
use crate::algebra::int::{common_denominator, Int};
use crate::algebra::scalar::{Field, MulAcc};
use crate::algebra::wide::Wide;
use crate::algebra::wide512::Wide512;
use crate::error::Error;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;
use std::any::Any;

/// An integer type the kernel runs on.
trait KernelInt: MulAcc {
    /// Every integer of at most this many bits is exact in the type.
    const BITS: u64;

    /// The integer `n`, of at most [`KernelInt::BITS`] bits.
    fn from_int(n: &Int) -> Self;

    /// The point `xs[i] / den` in lowest terms, written to `out` (`den ≠
    /// 0`): by default one gcd of the weight's size for all coordinates,
    /// on the limbs ([`fractions_over_limbs`], with the lane's [`Buffers`]).
    fn fractions(xs: &[Self], den: &Self, out: &mut [BigRational], buffers: &mut Buffers) {
        let (numers, denom) = buffers.limbs.split_at_mut(xs.len());
        for (x, buf) in xs.iter().zip(numers.iter_mut()) {
            x.write_limbs(buf);
        }
        den.write_limbs(&mut denom[0]);
        fractions_over_limbs(numers, &mut denom[0], out, &mut buffers.scratch);
    }

    /// The integer's sign and magnitude, written over `into`.
    fn write_limbs(&self, into: &mut SignedLimbs);

    /// How many points a Horner sum takes at a time at the homogeneous
    /// parameter `(a : b)` (see `horner` in [`super`]): 1, unless products
    /// of big numbers cost more than products by machine words.
    fn horner_block(a: &Self, b: &Self) -> usize {
        let _ = (a, b);
        1
    }
}

impl KernelInt for i128 {
    const BITS: u64 = 127;

    fn from_int(n: &Int) -> i128 {
        match n {
            Int::Small(v) => *v,
            Int::Big(_) => unreachable!("a big Int has more than 127 bits"),
        }
    }

    /// One word gcd per coordinate, as before the shared gcd: the product
    /// of the coordinates would leave the machine words.
    fn fractions(xs: &[i128], den: &i128, out: &mut [BigRational], _: &mut Buffers) {
        for (o, num) in out.iter_mut().zip(xs) {
            // |num|, |den| < 2¹²⁷: the quotients and their negations fit.
            let g = gcd_u128(num.unsigned_abs(), den.unsigned_abs()) as i128;
            let (n, d) = (num / g, den / g);
            let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
            *o = BigRational::new_raw(BigInt::from(n), BigInt::from(d));
        }
    }

    fn write_limbs(&self, into: &mut SignedLimbs) {
        let m = self.unsigned_abs();
        into.negative = *self < 0;
        into.limbs.clear();
        into.limbs.extend([m as u64, (m >> 64) as u64]);
    }
}

/// `n` in a fixed-width type whose `from_big` takes every value the bound
/// admits.
fn stack_int<T: From<i128>>(n: &Int, from_big: fn(&BigInt) -> Option<T>) -> T {
    match n {
        Int::Small(v) => T::from(*v),
        Int::Big(b) => from_big(b).expect("the bound admits the value"),
    }
}

impl KernelInt for Wide {
    const BITS: u64 = Wide::BITS;

    fn from_int(n: &Int) -> Wide {
        stack_int(n, Wide::from_bigint)
    }

    fn write_limbs(&self, into: &mut SignedLimbs) {
        into.negative = self.is_negative();
        into.limbs.clear();
        into.limbs.extend(self.magnitude_limbs());
    }
}

impl KernelInt for Wide512 {
    const BITS: u64 = Wide512::BITS;

    fn from_int(n: &Int) -> Wide512 {
        stack_int(n, Wide512::from_bigint)
    }

    fn write_limbs(&self, into: &mut SignedLimbs) {
        into.negative = self.is_negative();
        into.limbs.clear();
        into.limbs.extend(self.magnitude());
    }
}

impl KernelInt for Int {
    const BITS: u64 = u64::MAX;

    fn from_int(n: &Int) -> Int {
        n.clone()
    }

    fn write_limbs(&self, into: &mut SignedLimbs) {
        match self {
            Int::Small(v) => v.write_limbs(into),
            Int::Big(b) => {
                into.negative = b.sign() == num_bigint::Sign::Minus;
                into.limbs.clear();
                into.limbs.extend(b.magnitude().iter_u64_digits());
            }
        }
    }

    /// Blocks of `k` points with `a^k`, `b^k` below 2⁶³ (one machine word
    /// each): parameters of `p` bits give `k = ⌊63/p⌋`.
    fn horner_block(a: &Int, b: &Int) -> usize {
        let bits = a.bits().max(b.bits()).max(1);
        (63 / bits) as usize
    }
}

/// The kernel on one integer type: the net converted once, its workspace
/// and the homogeneous parameters and point of the current evaluation.
struct Lane<T> {
    net: Net<T>,
    ws: Workspace<T>,
    hom: Vec<T>,
    point: Vec<T>,
    buffers: Buffers,
}

/// A lane's buffers for the reduction of its points, kept from point to
/// point: the coordinates and the weight as limbs, and the product's.
struct Buffers {
    limbs: Vec<SignedLimbs>,
    scratch: Scratch,
}

impl<T: KernelInt> Lane<T> {
    fn new(net: &Net<Int>) -> Self {
        let net = net.map_coords(net.coords().iter().map(T::from_int).collect());
        Lane {
            ws: net.workspace(),
            hom: Vec::with_capacity(4),
            point: vec![T::zero(); net.stride()],
            buffers: Buffers {
                limbs: vec![SignedLimbs::default(); net.stride()],
                scratch: Scratch::default(),
            },
            net,
        }
    }

    /// The Cartesian point at the integer homogeneous parameters `hom`.
    fn eval(&mut self, hom: &[Int], out: &mut [BigRational]) -> Result<(), Error> {
        self.hom.clear();
        self.hom.extend(hom.iter().map(T::from_int));
        self.net
            .eval_hom_blocked(&self.hom, &mut self.point, &mut self.ws, T::horner_block);
        let (x, w) = self.point.split_at(self.point.len() - 1);
        if w[0].is_zero() {
            return Err(Error::PointAtInfinity);
        }
        T::fractions(x, &w[0], out, &mut self.buffers);
        Ok(())
    }
}

/// The kernels of one net, each built on first use: four integer types
/// over one common denominator, and blocks over their own denominators for
/// curves whose one-denominator integers outgrow 512 bits
/// ([`BlockedCurve`]).
struct Kernels<'a> {
    rational: &'a Net<BigRational>,
    net: Net<Int>,
    /// The common denominator of `net`, the lcm of all denominators.
    den: BigInt,
    /// Bits of the largest integer coordinate of the net.
    net_bits: u64,
    word: Option<Lane<i128>>,
    wide: Option<Lane<Wide>>,
    wide512: Option<Lane<Wide512>>,
    big: Option<Lane<Int>>,
    blocked: Option<Option<(BlockedCurve, Vec<BigInt>)>>,
}

impl<'a> Kernels<'a> {
    fn new(rational: &'a Net<BigRational>) -> Self {
        // A projective rescaling: the points of the integer net are those
        // of `rational`.
        let (nums, den) = common_denominator(rational.coords());
        let net = rational.map_coords(nums);
        Kernels {
            rational,
            net_bits: net.coords().iter().map(Int::bits).max().unwrap_or(0),
            net,
            den,
            word: None,
            wide: None,
            wide512: None,
            big: None,
            blocked: None,
        }
    }

    /// The point at `hom` on the narrowest kernel its bound admits.
    fn eval(&mut self, hom: &[Int], out: &mut [BigRational]) -> Result<(), Error> {
        let param_bits = hom.iter().map(Int::bits).max().unwrap_or(0);
        // The lane holds the parameters too: of degree 0, they enter no
        // value of the kernel but must still fit its integers.
        let bits = value_bits(self.net.shape(), self.net_bits, param_bits).max(param_bits);
        let net = &self.net;
        if bits <= <i128 as KernelInt>::BITS {
            return self
                .word
                .get_or_insert_with(|| Lane::new(net))
                .eval(hom, out);
        }
        if bits <= Wide::BITS {
            return self
                .wide
                .get_or_insert_with(|| Lane::new(net))
                .eval(hom, out);
        }
        if bits <= Wide512::BITS {
            return self
                .wide512
                .get_or_insert_with(|| Lane::new(net))
                .eval(hom, out);
        }
        let (rational, den) = (self.rational, &self.den);
        let blocked = self.blocked.get_or_insert_with(|| {
            BlockedCurve::new(rational, den).map(|b| (b, vec![BigInt::zero(); rational.stride()]))
        });
        if let Some((curve, point)) = blocked
            && curve.eval(&hom[0], &hom[1], point)
        {
            return project(point, out);
        }
        self.big
            .get_or_insert_with(|| Lane::new(net))
            .eval(hom, out)
    }
}

/// The Cartesian point of a big homogeneous one ([`fractions_over`]).
fn project(h: &[BigInt], out: &mut [BigRational]) -> Result<(), Error> {
    let (x, w) = h.split_at(h.len() - 1);
    if w[0].is_zero() {
        return Err(Error::PointAtInfinity);
    }
    fractions_over(x.to_vec(), w[0].clone(), out);
    Ok(())
}

/// The bound `E` of the module documentation: every value of the kernel
/// is below `2^E` in magnitude.
fn value_bits(shape: Shape, net_bits: u64, param_bits: u64) -> u64 {
    let bits = |k: usize| u64::from(usize::BITS - k.leading_zeros());
    let (n, p) = (net_bits, param_bits);
    match shape {
        Shape::Curve(d) => n + d as u64 * (1 + p) + bits(d + 1),
        Shape::Rect(du, dv) => n + (du + dv) as u64 * (1 + p) + bits(du + 1) + bits(dv + 1),
        Shape::Tri(d) => n + d as u64 * (2 + p) + 2 * bits(d + 1),
    }
}

/// The integer homogeneous parameters of one parameter point (machine
/// words, no allocation, while its numbers fit).
fn hom_params<'a>(shape: Shape, params: impl Iterator<Item = &'a BigRational>, hom: &mut Vec<Int>) {
    hom.clear();
    let mut parts = params.map(|t| (Int::from_ref(t.numer()), Int::from_ref(t.denom())));
    match shape {
        Shape::Curve(_) | Shape::Rect(..) => {
            for (p, q) in parts {
                hom.push(q - &p);
                hom.push(p);
            }
        }
        Shape::Tri(_) => {
            let mut next = || parts.next().expect("a tri patch point has two parameters");
            let ((pu, qu), (pv, qv)) = (next(), next());
            let g = qu.gcd(&qv);
            let (fu, fv) = (qv.div_exact(&g), qu.div_exact(&g));
            let q = qu * &fu;
            let (a, b) = (pu * &fu, pv * &fv);
            let w = q - &a - &b;
            hom.extend([a, b, w]);
        }
    }
}

/// The batch of [`Evaluator::eval_batch`], fraction-free, when `T` is
/// `BigRational` (recognised by its type id); `None`, nothing done, for
/// every other scalar.
pub(super) fn eval_batch<T: Field>(
    ev: &Evaluator<T>,
    params: &[T],
    out: &mut [T],
) -> Option<Result<(), Error>> {
    let net = (ev.net() as &dyn Any).downcast_ref::<Net<BigRational>>()?;
    Some(eval_rational(net, params, out))
}

/// [`eval_batch`] on the net of a `BigRational` evaluator: the scalars
/// `T` of `params` and `out` are `BigRational`.
fn eval_rational<T: Any>(net: &Net<BigRational>, params: &[T], out: &mut [T]) -> Result<(), Error> {
    let shape = net.shape();
    let mut kernels = Kernels::new(net);
    let (k, d) = (shape.params(), net.dim());
    let mut hom = Vec::with_capacity(4);
    let mut point = vec![BigRational::zero(); d];
    for (p, o) in params.chunks(k).zip(out.chunks_mut(d)) {
        hom_params(shape, p.iter().map(rational), &mut hom);
        kernels.eval(&hom, &mut point)?;
        for (o, x) in o.iter_mut().zip(&mut point) {
            std::mem::swap(rational_mut(o), x);
        }
    }
    Ok(())
}

/// `x`, a `BigRational` as the type `T`, as a `BigRational`.
fn rational<T: Any>(x: &T) -> &BigRational {
    (x as &dyn Any)
        .downcast_ref()
        .expect("the scalar is BigRational")
}

/// [`rational`], mutable.
fn rational_mut<T: Any>(x: &mut T) -> &mut BigRational {
    (x as &mut dyn Any)
        .downcast_mut()
        .expect("the scalar is BigRational")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    use proptest::prelude::*;

    /// A curve net of degree `n` whose every coordinate is `±(2^N − 1)`,
    /// with alternating signs chosen by `signs`.
    fn extreme_net(shape: Shape, net_bits: u32, signs: u64) -> Net<Int> {
        let top: BigInt = (BigInt::from(1) << net_bits) - 1;
        let coords = (0..shape.points() * 3)
            .map(|i| {
                let v = if signs >> (i % 64) & 1 == 1 {
                    -&top
                } else {
                    top.clone()
                };
                Int::from_bigint(v)
            })
            .collect();
        Net::new(coords, 3, shape).unwrap()
    }

    /// The homogeneous point of `net` at `hom` on the lane of `T`, as big
    /// integers.
    fn lane_point<T: KernelInt>(net: &Net<Int>, hom: &[Int], big: fn(&T) -> BigInt) -> Vec<BigInt> {
        let mut lane = Lane::<T>::new(net);
        lane.hom = hom.iter().map(T::from_int).collect();
        lane.net
            .eval_hom_into(&lane.hom, &mut lane.point, &mut lane.ws);
        lane.point.iter().map(big).collect()
    }

    #[test]
    fn degree_zero_takes_parameters_of_any_size() {
        // A constant curve and patches at a 200-bit parameter: the
        // parameters alone outgrow the word and wide tiers.
        let t = BigRational::new(BigInt::from(1), BigInt::from(3) << 200);
        let p = vec![ratio::<BigRational>(5, 7), ratio(-2, 1)];
        let curve = crate::RationalCurve::new(vec![p.clone()], vec![ratio(3, 1)]).unwrap();
        assert_eq!(curve.eval(&t).unwrap(), p);
        let rect = crate::RectPatch::new(vec![vec![p.clone()]], vec![vec![ratio(3, 1)]]).unwrap();
        assert_eq!(rect.eval(&t, &t).unwrap(), p);
        let tri = crate::TriPatch::new(vec![vec![p.clone()]], vec![vec![ratio(3, 1)]]).unwrap();
        assert_eq!(tri.eval(&t, &t).unwrap(), p);
    }

    /// The bound is an upper bound: at the extreme net (every coordinate
    /// of `N` bits) and extreme parameters (all `±(2^P − 1)`), the exact
    /// value computed on `Int` has fewer than `E` bits, for every shape and
    /// degree up to 12, and the narrow kernels agree with `Int` whenever
    /// the bound admits them.
    #[test]
    fn bound_holds_at_the_extremes() {
        for d in 0..=12usize {
            for shape in [Shape::Curve(d), Shape::Rect(d, d / 2 + 1), Shape::Tri(d)] {
                for (net_bits, p) in [(20u32, 9u32), (60, 20), (1, 1), (300, 12), (200, 24)] {
                    for signs in [0u64, u64::MAX, 0x5555_5555_5555_5555] {
                        let net = extreme_net(shape, net_bits, signs);
                        let top = Int::from((1i128 << p) - 1);
                        let hom: Vec<Int> = (0..4)
                            .map(|i| {
                                if signs >> i & 1 == 1 {
                                    -top.clone()
                                } else {
                                    top.clone()
                                }
                            })
                            .collect();
                        let hom = &hom[..match shape {
                            Shape::Tri(_) => 3,
                            Shape::Curve(_) => 2,
                            Shape::Rect(..) => 4,
                        }];
                        let mut big = Lane::<Int>::new(&net);
                        big.net.eval_hom_into(hom, &mut big.point, &mut big.ws);
                        let e = value_bits(shape, u64::from(net_bits), u64::from(p));
                        for v in &big.point {
                            assert!(
                                v.bits() <= e,
                                "{shape:?} N={net_bits} P={p}: {} > {e}",
                                v.bits()
                            );
                        }
                        let want: Vec<BigInt> = big.point.iter().map(Int::to_bigint).collect();
                        if e <= Wide::BITS {
                            let got = lane_point(&net, hom, Wide::to_bigint);
                            assert_eq!(got, want, "{shape:?} N={net_bits} P={p}");
                        }
                        if e <= Wide512::BITS {
                            let got = lane_point(&net, hom, Wide512::to_bigint);
                            assert_eq!(got, want, "{shape:?} N={net_bits} P={p}");
                        }
                    }
                }
            }
        }
    }

    /// The fast path is taken for `BigRational` and only for it.
    #[test]
    fn only_rationals_take_the_fast_path() {
        let exact = Net::new(
            vec![ratio::<BigRational>(1, 2), ratio(1, 1)],
            2,
            Shape::Curve(0),
        )
        .unwrap();
        let mut out = vec![ratio(0, 1)];
        let result = eval_batch(&Evaluator::new(exact), &[ratio(1, 3)], &mut out);
        assert_eq!((result, out), (Some(Ok(())), vec![ratio(1, 2)]));
        let float = Evaluator::new(Net::new(vec![0.5, 1.0], 2, Shape::Curve(0)).unwrap());
        assert_eq!(eval_batch(&float, &[0.25], &mut [0.0]), None);
    }

    proptest! {
        // Degree-40 points on the generic path cost milliseconds each.
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// Every kernel gives the Cartesian point of the generic
        /// `BigRational` path (Horner on fractions), for curves up to degree
        /// 40 with weights over many denominators (as CAD data has them) at
        /// small and at large parameters: the point moves from the `i128`
        /// kernel to `Wide` and to `Int`, blocked or not.
        #[test]
        fn tiers_agree_with_rationals(
            n in 1usize..=40,
            seed in prop::collection::vec((-10_000i64..10_000, -10_000i64..10_000, 1i64..20_000), 41),
            (p, q) in (-3_000i64..3_000, 1i64..1_000),
            scale in 0u32..4,
        ) {
            let big = num_traits::pow(BigInt::from(1_000_003), 10 * scale as usize);
            let t = BigRational::new(BigInt::from(p) * &big, BigInt::from(q) * &big + 1);
            let pts: Vec<crate::hpoint::HPoint<BigRational>> = seed[..=n]
                .iter()
                .enumerate()
                .map(|(i, &(x, y, w))| {
                    let w = ratio::<BigRational>(w, 600 + i as i64);
                    let coords = vec![ratio::<BigRational>(x, 100) * &w, ratio::<BigRational>(y, 100) * &w, w];
                    crate::hpoint::HPoint { coords }
                })
                .collect();
            let mut ev = Evaluator::new(Net::from_points(&pts, Shape::Curve(n)).unwrap());
            let mut fast = vec![ratio(0, 1); 2];
            let mut generic = fast.clone();
            let fast_result = ev.eval_batch(std::slice::from_ref(&t), &mut fast);
            let generic_result = ev.eval_batch_generic(std::slice::from_ref(&t), &mut generic);
            prop_assert_eq!(fast_result.is_ok(), generic_result.is_ok());
            prop_assert_eq!(fast, generic);
        }
    }
}
