//! Overlaps: two curves that share a piece are related by a Möbius map.
//!
//! When the elimination's resultant vanishes identically, the curves lie on
//! one rational curve. If `A` is properly parameterized (one parameter per
//! generic point), `φ = A⁻¹ ∘ B` is a rational function over Q of degree 1,
//! `s = φ(t) = (a t + b)/(c t + d)`. It is found from three correspondences
//! `A(s_k) = B(t_k)` at rational `t_k` (then `s_k` is the single rational
//! common root of `X_k^A(s) w − x_k W^A(s)` over every coordinate), and
//! checked as a polynomial identity `A ∘ φ ≡ B` in homogeneous form:
//!
//! ```text
//! X_k^A(φ(t))·(ct + d)^{deg A} · W^B(t) = W^A(φ(t))·(ct + d)^{deg A} · X_k^B(t)   for every k
//! ```
//!
//! The overlap is then `{t ∈ [0, 1] : φ(t) ∈ [0, 1]}`, split at the
//! parameters where `φ` is 0, 1 or infinite.

use super::system::{PowerCurve, QPoly};
use crate::algebra::int::common_denominator;
use crate::algebra::sylvester::determinant;
use crate::algebra::UPoly;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// `s = (a t + b) / (c t + d)` with `ad − bc ≠ 0`.
#[derive(Clone, Debug, PartialEq)]
pub struct Mobius {
    /// The coefficients `[a, b, c, d]`.
    pub coeffs: [BigRational; 4],
}

impl Mobius {
    /// `φ(t)`, or `None` at the pole.
    pub fn at(&self, t: &BigRational) -> Option<BigRational> {
        let [a, b, c, d] = &self.coeffs;
        let den = c * t + d;
        (!den.is_zero()).then(|| (a * t + b) / den)
    }

    /// The same map with coprime integer coefficients and `d > 0` (or
    /// `c > 0` when `d = 0`): the identity is `[1, 0, 0, 1]`.
    fn normalized(&self) -> Mobius {
        let (ints, _): (Vec<BigInt>, _) = common_denominator(&self.coeffs);
        let gcd = ints.iter().fold(BigInt::zero(), |g, x| g.gcd(x));
        let [_, _, c, d] = &self.coeffs;
        let negative = d.is_negative() || (d.is_zero() && c.is_negative());
        let unit = if negative { -gcd } else { gcd };
        Mobius {
            coeffs: std::array::from_fn(|i| BigRational::new(ints[i].clone(), unit.clone())),
        }
    }

    /// The parameters in `(0, 1)` where `φ` is 0, 1 or infinite.
    fn breakpoints(&self) -> Vec<BigRational> {
        let [a, b, c, d] = &self.coeffs;
        // a t + b = 0, (a − c) t + (b − d) = 0, c t + d = 0.
        [(a, b), (&(a - c), &(b - d)), (c, d)]
            .into_iter()
            .filter(|(x, _)| !x.is_zero())
            .map(|(x, y)| -y / x)
            .filter(|t| t.is_positive() && *t < BigRational::one())
            .collect()
    }

    /// The maximal closed intervals `[t_0, t_1] ⊆ [0, 1]` that `φ` maps into
    /// `[0, 1]`, as `(t_0, t_1)` (possibly a single point `t_0 = t_1`).
    pub fn preimage_of_unit(&self) -> Vec<(BigRational, BigRational)> {
        let (zero, one) = (BigRational::zero(), BigRational::one());
        let mut cuts = self.breakpoints();
        cuts.push(zero.clone());
        cuts.push(one.clone());
        cuts.sort();
        cuts.dedup();
        let inside = |t: &BigRational| self.at(t).is_some_and(|s| s >= zero && s <= one);
        let mut out: Vec<(BigRational, BigRational)> = Vec::new();
        for w in cuts.windows(2) {
            let mid = (&w[0] + &w[1]) / BigRational::from_integer(2.into());
            if !inside(&mid) {
                continue;
            }
            match out.last_mut() {
                Some(last) if last.1 == w[0] && self.at(&w[0]).is_some() => last.1 = w[1].clone(),
                _ => out.push((w[0].clone(), w[1].clone())),
            }
        }
        for t in &cuts {
            let covered = out.iter().any(|(lo, hi)| lo <= t && t <= hi);
            if !covered && inside(t) {
                out.push((t.clone(), t.clone()));
            }
        }
        out.sort();
        out
    }

    /// The line `(c t + d) s − (a t + b) = 0` of the `(s, t)` plane as a
    /// polynomial in `t` with coefficients in `s`.
    pub fn graph(&self) -> crate::algebra::BPoly<BigRational> {
        let [a, b, c, d] = &self.coeffs;
        crate::algebra::BPoly::new(vec![
            UPoly::new(vec![-b.clone(), d.clone()]),
            UPoly::new(vec![-a.clone(), c.clone()]),
        ])
    }
}

/// The single rational `s` with `A(s) = B(t)`, if the common roots of the
/// coordinate equations are exactly one rational number.
fn inverse_at(a: &PowerCurve, b: &PowerCurve, t: &BigRational) -> Option<BigRational> {
    let wb = b.weight().eval(t);
    let common = (0..a.dim()).fold(QPoly::zero(), |g, k| {
        let xb = b.comps[k].eval(t);
        g.gcd(&a.comps[k].scale(&wb).sub(&a.weight().scale(&xb)))
    });
    (common.degree() == Some(1)).then(|| {
        let c = common.coeffs();
        -&c[0] / &c[1]
    })
}

/// `p(φ(t))·(c t + d)^n` for `p` of degree at most `n`.
fn compose(p: &QPoly, phi: &Mobius, n: usize) -> QPoly {
    let [a, b, c, d] = &phi.coeffs;
    let num = UPoly::new(vec![b.clone(), a.clone()]);
    let den = UPoly::new(vec![d.clone(), c.clone()]);
    let pow =
        |q: &QPoly, k: usize| (0..k).fold(UPoly::constant(BigRational::one()), |acc, _| acc.mul(q));
    p.coeffs()
        .iter()
        .enumerate()
        .fold(QPoly::zero(), |acc, (j, coef)| {
            acc.add(&pow(&num, j).mul(&pow(&den, n - j)).scale(coef))
        })
}

/// Is `A ∘ φ ≡ B` (as maps)?
fn maps_onto(a: &PowerCurve, b: &PowerCurve, phi: &Mobius) -> bool {
    let n = a.comps.iter().filter_map(UPoly::degree).max().unwrap_or(0);
    let wa = compose(a.weight(), phi, n);
    (0..a.dim()).all(|k| {
        let xa = compose(&a.comps[k], phi, n);
        xa.mul(b.weight()).sub(&wa.mul(&b.comps[k])).is_zero()
    })
}

/// The Möbius map `φ` with `B = A ∘ φ`, when there is one.
pub(crate) fn find_mobius(a: &PowerCurve, b: &PowerCurve) -> Option<Mobius> {
    // Distinct parameters 0, 1, 1/2, 1/3, 2/3, 1/4, … (reduced fractions).
    let samples = (1..=24i64).flat_map(|den| {
        (0..=den)
            .filter(move |&num| num_integer::gcd(num, den) == 1)
            .map(move |num| BigRational::new(num.into(), den.into()))
    });
    let pairs: Vec<(BigRational, BigRational)> = samples
        .filter_map(|t| inverse_at(a, b, &t).map(|s| (t, s)))
        .take(3)
        .collect();
    if pairs.len() < 3 {
        return None;
    }
    // a t + b − c t s − d s = 0 at each pair: the kernel of a 3 × 4 matrix,
    // by signed 3 × 3 minors.
    let rows: Vec<[BigRational; 4]> = pairs
        .iter()
        .map(|(t, s)| [t.clone(), BigRational::one(), -(t * s), -s.clone()])
        .collect();
    let minor = |skip: usize| {
        determinant(
            rows.iter()
                .map(|r| {
                    (0..4)
                        .filter(|&c| c != skip)
                        .map(|c| r[c].clone())
                        .collect()
                })
                .collect(),
        )
    };
    let sign = |i: usize| {
        if i.is_multiple_of(2) {
            BigRational::one()
        } else {
            -BigRational::one()
        }
    };
    let coeffs: [BigRational; 4] = std::array::from_fn(|i| sign(i) * minor(i));
    let [x, y, z, w] = &coeffs;
    if (x * w - y * z).is_zero() {
        return None;
    }
    let phi = Mobius { coeffs }.normalized();
    maps_onto(a, b, &phi).then_some(phi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ratio;

    fn m(a: i64, b: i64, c: i64, d: i64) -> Mobius {
        Mobius {
            coeffs: [ratio(a, 1), ratio(b, 1), ratio(c, 1), ratio(d, 1)],
        }
    }

    #[test]
    fn preimages_of_the_unit_interval() {
        // s = t/2: all of [0, 1] maps into [0, 1/2].
        assert_eq!(
            m(1, 0, 0, 2).preimage_of_unit(),
            vec![(ratio(0, 1), ratio(1, 1))]
        );
        // s = 2t: [0, 1/2].
        assert_eq!(
            m(2, 0, 0, 1).preimage_of_unit(),
            vec![(ratio(0, 1), ratio(1, 2))]
        );
        // s = t + 1: only t = 0 (s = 1), a single touching point.
        assert_eq!(
            m(1, 1, 0, 1).preimage_of_unit(),
            vec![(ratio(0, 1), ratio(0, 1))]
        );
        // s = 1 − 2t: [0, 1/2], reversed.
        assert_eq!(
            m(-2, 1, 0, 1).preimage_of_unit(),
            vec![(ratio(0, 1), ratio(1, 2))]
        );
        // s = t + 2: nothing.
        assert!(m(1, 2, 0, 1).preimage_of_unit().is_empty());
    }
}
