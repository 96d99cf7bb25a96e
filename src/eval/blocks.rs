//! Exact evaluation of high-degree curves with one common denominator per
//! block of control points: most of the work runs on 256-bit integers
//! ([`Wide`]) even when the whole curve's integers are far larger.
//!
//! Clearing the denominators of all `n + 1` control points at once makes
//! every integer as large as the lcm of all of them (hundreds of bits for
//! CAD weights like 12345/678 at degree 40). Blocks of `k` consecutive
//! points each have their own, much smaller, common denominator:
//!
//! ```text
//! h_i = (w_i P_i, w_i) ∈ Q^{d+1},  block j = points s_j … s_j + k_j − 1
//! L_j = lcm of the denominators in block j,  L = lcm_j L_j,  M_j = L / L_j
//! g_i = C(n,i)·L_j·h_i ∈ Z                                (i in block j)
//! c_j = Σ_{r<k_j} a^{k_j−1−r} bʳ g_{s_j+r}                (256 bits, no allocation)
//! acc ← acc·a^{k_j} + (b^{s_j}·M_j)·c_j                   (big integers, once per block)
//! ```
//!
//! and `acc = L·Σ_i C(n,i) a^{n−i} bⁱ h_i`: the homogeneous point of the
//! one-denominator kernel ([`super::fraction_free`]), so the projection is
//! the same. The block sums are the kernel's Horner sums ([`horner_lanes`]),
//! below `k·2^{(k−1)P}·2^{B_j}` for parameters of `P` bits and block
//! integers of `B_j` bits; a point whose bound exceeds 255 bits is left to
//! the one-denominator kernel.

use super::{horner_lanes, Net, Shape};
use crate::algebra::int::{common_denominator, Int};
use crate::algebra::scalar::binomial;
use crate::algebra::wide::Wide;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::One;

/// Points per block: small enough that a block's denominators stay small,
/// large enough that the big-integer step is rare.
const BLOCK: usize = 8;

/// One block: its factor `M_j` and its integer points.
#[derive(Clone, Debug)]
struct Block {
    factor: BigInt,
    points: Vec<Wide>,
    /// Bits of the largest `|g_i|` of the block.
    bits: u64,
}

/// A curve's net split into blocks over their own denominators.
#[derive(Clone, Debug)]
pub(crate) struct BlockedCurve {
    stride: usize,
    blocks: Vec<Block>,
    /// One block's sums, reused.
    sums: Vec<Wide>,
}

impl BlockedCurve {
    /// The blocks of a curve net of degree at least `2·BLOCK − 1` whose
    /// denominators have the lcm `global` (`L`), or `None` for a lower
    /// degree, another shape, or a block whose integers exceed 255 bits.
    pub(crate) fn new(net: &Net<BigRational>, global: &BigInt) -> Option<Self> {
        let Shape::Curve(n) = net.shape() else {
            return None;
        };
        if n + 1 < 2 * BLOCK {
            return None;
        }
        let stride = net.stride();
        let mut blocks = Vec::with_capacity((n + 1).div_ceil(BLOCK));
        for (j, chunk) in net.coords().chunks(BLOCK * stride).enumerate() {
            let (ints, den) = common_denominator::<BigInt>(chunk);
            let mut points = Vec::with_capacity(chunk.len());
            for (r, point) in ints.chunks_exact(stride).enumerate() {
                let c = binomial(n, j * BLOCK + r);
                for x in point {
                    points.push(Wide::from_bigint(&(&c * x))?);
                }
            }
            let bits = points.iter().map(Wide::bits).max().unwrap_or(0);
            blocks.push(Block {
                factor: global / den,
                points,
                bits,
            });
        }
        Some(BlockedCurve {
            stride,
            blocks,
            sums: vec![Wide::from(0); stride],
        })
    }

    /// The homogeneous point `L·Σ_i C(n,i) a^{n−i} bⁱ h_i` into `out`, or
    /// `false` (nothing written) when a block sum could exceed 255 bits at
    /// these parameters.
    pub(crate) fn eval(&mut self, a: &Int, b: &Int, out: &mut [BigInt]) -> bool {
        let p = a.bits().max(b.bits());
        let bits = |k: usize| u64::from(usize::BITS - k.leading_zeros());
        let fits = p <= 126
            && self.blocks.iter().all(|blk| {
                let k = blk.points.len() / self.stride;
                blk.bits + (k as u64 - 1) * p + bits(k) <= Wide::BITS
            });
        if !fits {
            return false;
        }
        let (aw, bw) = (Wide::from(small(a)), Wide::from(small(b)));
        let (a, b) = (a.to_bigint(), b.to_bigint());
        let mut b_start = BigInt::one();
        for (j, blk) in self.blocks.iter().enumerate() {
            let k = blk.points.len() / self.stride;
            horner_lanes::<Wide, 1>(&blk.points, self.stride, [&aw], [&bw], &mut self.sums);
            let factor = &b_start * &blk.factor;
            let a_k = a.pow(k as u32);
            for (o, c) in out.iter_mut().zip(&self.sums) {
                let term = &factor * c.to_bigint();
                if j == 0 {
                    *o = term;
                } else {
                    *o *= &a_k;
                    *o += term;
                }
            }
            b_start *= b.pow(k as u32);
        }
        true
    }
}

/// The value of an `Int` of at most 126 bits (as every parameter that
/// passes the bound of [`BlockedCurve::eval`]).
fn small(n: &Int) -> i128 {
    match n {
        Int::Small(v) => *v,
        Int::Big(_) => unreachable!("a parameter of at most 126 bits is a machine integer"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;

    /// A planar degree-`n` net with weights over many denominators.
    fn net(n: usize) -> Net<BigRational> {
        let coords = (0..=n as i64)
            .flat_map(|i| {
                let w = ratio::<BigRational>(10_000 + 37 * i, 600 + i);
                [
                    ratio::<BigRational>((i * i * 31) % 2001 - 1000, 100) * &w,
                    ratio::<BigRational>((i * 17) % 997 - 500, 100) * &w,
                    w,
                ]
            })
            .collect();
        Net::new(coords, 3, Shape::Curve(n)).unwrap()
    }

    /// The blocked sum is the very integer point of the one-denominator
    /// kernel on `Int` (the same lcm `L`), at parameters of 1 to 12 bits;
    /// too large a parameter is declined, not mis-evaluated.
    #[test]
    fn blocks_equal_the_one_denominator_kernel() {
        for n in [15, 16, 23, 40] {
            let rational = net(n);
            let (ints, den) = common_denominator::<Int>(rational.coords());
            let mut blocked = BlockedCurve::new(&rational, &den).expect("degree ≥ 15 blocks");
            let whole = rational.map_coords(ints);
            for (p, q) in [
                (0i128, 1i128),
                (1, 1),
                (123, 457),
                (-3, 2),
                (1 << 11, (1 << 12) - 3),
            ] {
                let (a, b) = (Int::from(q - p), Int::from(p));
                let mut point = vec![BigInt::from(0); 3];
                assert!(blocked.eval(&a, &b, &mut point), "degree {n}, t = {p}/{q}");
                let mut want = vec![Int::from(0); 3];
                whole.eval_hom_into(&[a, b], &mut want, &mut whole.workspace());
                let want: Vec<BigInt> = want.iter().map(Int::to_bigint).collect();
                assert_eq!(point, want, "degree {n}, t = {p}/{q}");
            }
            let huge = Int::from(i128::MAX);
            assert!(!blocked.eval(&huge, &huge, &mut vec![BigInt::from(0); 3]));
        }
        assert!(
            BlockedCurve::new(&net(14), &BigInt::one()).is_none(),
            "too few points for two blocks"
        );
    }
}
