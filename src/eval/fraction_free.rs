//! Fraction-free exact evaluation, the `BigRational` fast path of
//! [`Field::eval_net`](crate::Field::eval_net).
//!
//! ```text
//! net:    H_i = L·(w_i P_i, w_i) ∈ Zᵈ⁺¹        (L = lcm of all denominators, once)
//! curve:  t = p/q            → (a : b) = (q − p : p)
//! rect:   u = p/q, v = r/s   → (q − p : p), (s − r : r)
//! tri:    (u, v) = (a/q, b/q) → (a, b, q − a − b)
//! X = H_d / H_w              (the only gcds: one per output coordinate,
//!                             by Lehmer's algorithm, crate::algebra::gcd)
//! ```
//!
//! The kernel is the generic one of [`Net::eval_hom_into`] run on [`Int`]:
//! `i128` while the values fit, big integers after, never a gcd on the way.

use super::{Evaluator, Net, Shape, Workspace};
use crate::algebra::gcd::fraction;
use crate::algebra::int::{common_denominator, Int};
use crate::error::Error;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;

/// The integer net over one common denominator (a projective rescaling:
/// the points it represents are unchanged).
fn integral(net: &Net<BigRational>) -> Net<Int> {
    let all: Vec<&BigRational> = net.coords().iter().collect();
    let (nums, _) = common_denominator(&all);
    net.map_coords(nums)
}

/// The integer homogeneous parameters of one parameter point.
fn hom_params(shape: Shape, params: &[BigRational], hom: &mut Vec<Int>) {
    hom.clear();
    let pair = |t: &BigRational| {
        let p = Int::from_bigint(t.numer().clone());
        let q = Int::from_bigint(t.denom().clone());
        (q - &p, p)
    };
    match shape {
        Shape::Curve(_) | Shape::Rect(..) => {
            for t in params {
                let (a, b) = pair(t);
                hom.push(a);
                hom.push(b);
            }
        }
        Shape::Tri(_) => {
            let (nums, q) = common_denominator(&[&params[0], &params[1]]);
            let w = Int::from_bigint(q) - &nums[0] - &nums[1];
            hom.extend(nums);
            hom.push(w);
        }
    }
}

/// Divide the integer homogeneous point once per coordinate.
fn project(h: &[Int], out: &mut [BigRational]) -> Result<(), Error> {
    let (x, w) = h.split_at(h.len() - 1);
    if w[0].is_zero() {
        return Err(Error::PointAtInfinity);
    }
    let w: BigInt = w[0].to_bigint();
    for (o, xi) in out.iter_mut().zip(x) {
        *o = fraction(xi.to_bigint(), w.clone());
    }
    Ok(())
}

/// The batch of [`Evaluator::eval_batch`] for `BigRational`, fraction-free.
pub(crate) fn eval_batch(
    ev: &Evaluator<BigRational>,
    params: &[BigRational],
    out: &mut [BigRational],
) -> Result<(), Error> {
    let net = integral(ev.net());
    let shape = net.shape();
    let mut ws: Workspace<Int> = net.workspace();
    let mut point = vec![Int::zero(); net.stride()];
    let mut hom = Vec::with_capacity(4);
    let (k, d) = (shape.params(), net.dim());
    for (p, o) in params.chunks(k).zip(out.chunks_mut(d)) {
        hom_params(shape, p, &mut hom);
        net.eval_hom_into(&hom, &mut point, &mut ws);
        project(&point, o)?;
    }
    Ok(())
}
