//! Real roots counted and isolated by Descartes' rule of signs on an
//! interval (the Vincent–Collins–Akritas bisection): no Sturm sequence, so
//! no remainder sequence whose coefficients grow with the degree.
//!
//! ```text
//! (lo, hi) = (a/c, b/c), w = b − a:
//!   P(x) = c^d p((a + w x)/c)            roots in (0, 1)    (homogeneous Horner)
//!   Q(y) = (1 + y)^d P(1/(1 + y))         roots in (0, ∞)    (reverse, Taylor shift by 1)
//!   V    = sign variations of Q's coefficients ≥ #roots of p in (lo, hi),  V ≡ #roots (mod 2)
//! ```
//!
//! So `V = 0` excludes a root and `V = 1` certifies exactly one. For a
//! square-free `p` an interval narrow enough around a simple root, or away
//! from every root, has `V ≤ 1` (Obreshkoff's one- and two-circle
//! theorems), so bisection terminates.
//!
//! Reference: Collins & Akritas, *Polynomial real root isolation using
//! Descartes' rule of signs*, SYMSAC 1976; Krandick & Mehlhorn, *New bounds
//! for the Descartes method*, J. Symbolic Comput. 41 (2006) 49–66.

use super::polys::{split_point, SignPoly};
use crate::algebra::int::common_denominator;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// The sign variations `V` of the integer polynomial `p` (coefficients,
/// lowest power first) on the open interval `(lo, hi)`, `lo < hi`.
pub(crate) fn variations(p: &[BigInt], lo: &BigRational, hi: &BigRational) -> usize {
    let Some(d) = p.len().checked_sub(1) else {
        return 0;
    };
    let (ends, c): (Vec<BigInt>, BigInt) = common_denominator(&[lo.clone(), hi.clone()]);
    let (a, w) = (&ends[0], &ends[1] - &ends[0]);
    crate::limits::meter(
        3 * (d as u64 + 1).pow(2),
        p.iter().map(BigInt::bits).max().unwrap_or(0) + d as u64 * (c.bits() + w.bits() + 1),
    );
    // Horner: H ← H·(a + w x) + p_i c^{d−i}, from H = p_d.
    let mut h = vec![p[d].clone()];
    let mut c_pow = BigInt::from(1);
    for coeff in p[..d].iter().rev() {
        c_pow *= &c;
        let mut next = vec![BigInt::zero(); h.len() + 1];
        for (k, x) in h.iter().enumerate() {
            next[k] += x * a;
            next[k + 1] += x * &w;
        }
        next[0] += coeff * &c_pow;
        h = next;
    }
    // Reverse, then shift by one: Q(y) = Σ h_{d−k} (1 + y)^k.
    h.reverse();
    for i in 0..d {
        for k in (i..d).rev() {
            let add = h[k + 1].clone();
            h[k] += add;
        }
    }
    let signs = h.iter().filter(|x| !x.is_zero()).map(BigInt::is_positive);
    let mut prev = None;
    signs.fold(0, |n, s| {
        let changed = prev.is_some_and(|p| p != s);
        prev = Some(s);
        n + usize::from(changed)
    })
}

/// Isolating intervals (open, endpoints not roots, one root each,
/// increasing) of the real roots in `(a, b)` of the square-free `p`, where
/// `a < b` are not roots.
pub(crate) fn isolate(
    p: &SignPoly,
    a: &BigRational,
    b: &BigRational,
) -> Vec<(BigRational, BigRational)> {
    let mut out = Vec::new();
    let mut stack = vec![(a.clone(), b.clone())];
    while let Some((lo, hi)) = stack.pop() {
        match variations(p.coeffs(), &lo, &hi) {
            0 => {}
            1 => out.push((lo, hi)),
            _ => {
                let mid = split_point(p, &lo, &hi);
                stack.push((mid.clone(), hi));
                stack.push((lo, mid));
            }
        }
    }
    out.sort_by(|x, y| x.0.cmp(&y.0));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::real_algebraic::polys::{count_roots, sturm_sequence};
    use crate::ratio;

    use crate::algebra::real_algebraic::polys::int_poly as poly;

    #[test]
    fn isolation_agrees_with_sturm_counts() {
        // (x − 1/3)(x − 1/2)(x − 2)(x² − 2)(x² + 1), scaled to integers.
        let p = poly(&[-1, 3])
            .mul(&poly(&[-1, 2]))
            .mul(&poly(&[-2, 1]))
            .mul(&poly(&[-2, 0, 1]))
            .mul(&poly(&[1, 0, 1]));
        let sign = SignPoly::new(&p);
        let (a, b) = (ratio(-7, 3), ratio(5, 2));
        let found = isolate(&sign, &a, &b);
        assert_eq!(found.len(), 5);
        let seq = sturm_sequence(&p);
        assert_eq!(count_roots(&seq, &a, &b), 5);
        for (lo, hi) in &found {
            assert_eq!(count_roots(&seq, lo, hi), 1);
        }
        // Only the roots 1/3 and 1/2 lie in (0, 1), √2 and 2 above it.
        assert_eq!(isolate(&sign, &ratio(0, 1), &ratio(1, 1)).len(), 2);
        assert_eq!(variations(sign.coeffs(), &ratio(3, 1), &ratio(9, 1)), 0);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// Descartes isolation finds the roots Sturm's theorem counts, one
        /// per interval, on random integer polynomials of degree ≤ 8.
        #[test]
        fn descartes_isolation_matches_sturm_counts(
            c in proptest::collection::vec(-20i64..=20, 2..=9),
            a in -4i64..=3,
            width in 1i64..=5,
        ) {
            let p = poly(&c);
            proptest::prop_assume!(p.degree().unwrap_or(0) > 0);
            let sf = crate::algebra::real_algebraic::polys::square_free_part(&p);
            let sign = SignPoly::new(&sf);
            let (a, b) = (ratio(a, 1), ratio(a + width, 1));
            proptest::prop_assume!(sign.sign_at(&a) != 0 && sign.sign_at(&b) != 0);
            let seq = sturm_sequence(&sf);
            let found = isolate(&sign, &a, &b);
            proptest::prop_assert_eq!(found.len(), count_roots(&seq, &a, &b));
            for (lo, hi) in &found {
                proptest::prop_assert_eq!(count_roots(&seq, lo, hi), 1);
            }
        }
    }
}
