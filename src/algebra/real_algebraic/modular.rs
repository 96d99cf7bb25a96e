//! Coprimality and square-freeness over Q certified by one reduction
//! modulo the prime `p = 2⁶¹ − 1` ([`Fp`]): a cheap exact test that lets
//! the callers skip the gcd over Q in the generic case.
//!
//! ```text
//! a, b ∈ Q[x], p divides no denominator, deg (a mod p) = deg a:
//!     gcd(a mod p, b mod p) = 1 in F_p[x]   ⇒   gcd(a, b) = 1 in Q[x]
//! ```
//!
//! Proof: a common factor `g` of `a` and `b` over Q can be taken in
//! `Z_(p)[x]` with unit content (Gauss's lemma over the local ring
//! `Z_(p)`); its leading coefficient divides that of `a`, a unit, so `g mod
//! p` keeps its degree `≥ 1` and divides both images. With `b = a'` (and
//! `p > deg a`, so that the image of `a'` is the derivative of the image of
//! `a`) the same argument certifies that `a` is square-free. The converse
//! fails only when `p` divides a resultant: then the caller computes over Q
//! as before, so the answer never depends on the prime.
//!
//! Reference: Cohen, *A Course in Computational Algebraic Number Theory*
//! (1993), §3.3 (modular gcd); von zur Gathen & Gerhard, *Modern Computer
//! Algebra* (3rd ed., 2013), §6.4 (lucky primes).

use super::polys::QPoly;
use crate::algebra::modp::Fp;
use crate::algebra::upoly::UPoly;

/// The image of `a` modulo `p`, or `None` when `p` divides a denominator.
fn image(a: &QPoly) -> Option<UPoly<Fp>> {
    let c: Option<Vec<Fp>> = a.coeffs().iter().map(Fp::from_rational_checked).collect();
    c.map(UPoly::new)
}

/// The image of `a` when it keeps the degree of `a` (a non-zero `a`).
fn faithful_image(a: &QPoly) -> Option<UPoly<Fp>> {
    let img = image(a)?;
    (a.degree().is_some() && img.degree() == a.degree()).then_some(img)
}

/// `true` only if `gcd(a, b) = 1` over Q (certified modulo `p`); `false`
/// means "not certified", not "not coprime".
pub(crate) fn certainly_coprime(a: &QPoly, b: &QPoly) -> bool {
    let (Some(x), Some(y)) = (faithful_image(a), image(b)) else {
        return false;
    };
    x.gcd(&y).degree() == Some(0)
}

/// `true` only if `a` (non-zero) is square-free over Q (certified modulo
/// `p`); `false` means "not certified".
pub(crate) fn certainly_square_free(a: &QPoly) -> bool {
    let Some(x) = faithful_image(a) else {
        return false;
    };
    if a.degree().unwrap_or(0) as u64 >= crate::algebra::modp::MODULUS {
        return false;
    }
    x.gcd(&x.derivative()).degree() == Some(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ratio;

    use crate::algebra::real_algebraic::polys::int_poly as poly;

    #[test]
    fn certificates_agree_with_the_gcd_over_q() {
        // (x − 1)(x + 2) and (x − 1)(x − 3) share x − 1; x² − 2 and x − 3 do not.
        assert!(!certainly_coprime(&poly(&[-2, 1, 1]), &poly(&[3, -4, 1])));
        assert!(certainly_coprime(&poly(&[-2, 0, 1]), &poly(&[-3, 1])));
        // (x − 1)² x is not square-free; x³ − 2 is.
        assert!(!certainly_square_free(&poly(&[0, 1, -2, 1])));
        assert!(certainly_square_free(&poly(&[-2, 0, 0, 1])));
        // Halves, thirds: reduced modulo p through their inverses.
        let half = UPoly::new(vec![ratio(-1, 2), ratio(1, 3), ratio(1, 1)]);
        assert!(certainly_square_free(&half));
    }
}
