//! The general representation: a root of a square-free polynomial over Q
//! given by an isolating interval with rational endpoints, refined by
//! bisection on demand (the refinement is cached behind a mutex, so clones
//! share it). Signs at rationals only: no Sturm sequence (the index counts
//! the roots below by Descartes isolation).
//!
//! Invariant: `poly` is monic and square-free, `lo < hi`, neither endpoint
//! is a root, `poly` has exactly one root in `(lo, hi)`, and that root is
//! irrational (rational values are kept in the radical form).

use super::polys::{split_point, QPoly, SignPoly};
use num_rational::BigRational;
use num_traits::Signed;
use std::sync::Mutex;

/// An irrational real root of a square-free polynomial, isolated.
#[derive(Debug)]
pub(crate) struct RootNum {
    poly: QPoly,
    /// `poly` as primitive integers, for signs at the bisection points.
    sign: SignPoly,
    interval: Mutex<(BigRational, BigRational)>,
}

impl RootNum {
    /// The root of `poly` (monic, square-free) isolated in `(lo, hi)`.
    pub(crate) fn new(poly: QPoly, lo: BigRational, hi: BigRational) -> Self {
        RootNum {
            sign: SignPoly::new(&poly),
            poly,
            interval: Mutex::new((lo, hi)),
        }
    }

    /// The defining polynomial (monic, square-free).
    pub(crate) fn poly(&self) -> &QPoly {
        &self.poly
    }

    /// The current isolating interval.
    pub(crate) fn interval(&self) -> (BigRational, BigRational) {
        self.interval.lock().expect("not poisoned").clone()
    }

    /// Halve the isolating interval once (at a point that is not a root).
    fn bisect(&self) {
        let mut guard = self.interval.lock().expect("not poisoned");
        let (lo, hi) = guard.clone();
        let p = &self.sign;
        let mid = split_point(p, &lo, &hi);
        *guard = if p.sign_at(&lo) == p.sign_at(&mid) {
            (mid, hi)
        } else {
            (lo, mid)
        };
    }

    /// An isolating interval of width at most `2^{−prec}`.
    pub(crate) fn enclosure(&self, prec: u32) -> (BigRational, BigRational) {
        let eps = BigRational::new(1.into(), num_bigint::BigInt::from(1) << prec as usize);
        loop {
            let (lo, hi) = self.interval();
            if &hi - &lo <= eps {
                return (lo, hi);
            }
            self.bisect();
        }
    }

    /// The sign (never 0: the value is irrational).
    pub(crate) fn signum(&self) -> i32 {
        loop {
            let (lo, hi) = self.interval();
            if !lo.is_negative() {
                return 1;
            }
            if !hi.is_positive() {
                return -1;
            }
            self.bisect();
        }
    }

    /// How many real roots of `poly` are smaller than this one (the `k` of
    /// `CRootOf(poly, k)`): the roots isolated in `(−B, lo)` by Descartes
    /// counts, `B` a root bound (neither end is a root).
    pub(crate) fn index(&self) -> usize {
        let bound = num_rational::BigRational::from_integer(-self.sign.root_bound());
        let (lo, _) = self.interval();
        super::descartes::isolate(&self.sign, &bound, &lo).len()
    }
}
