//! The scalar tower and the number types the algorithms run on: the
//! [`Ring`] / [`MulAcc`] / [`Scalar`] / [`Field`] / [`Ordered`] traits (public,
//! so that a number type of your own can implement them), exact integers
//! with a machine-word fast path ([`Int`]) and 256- and 512-bit stack
//! tiers ([`Wide`], [`Wide512`]), multivariate polynomials over Q
//! ([`Poly`], the symbolic scalar of the proofs), univariate and bivariate
//! polynomials ([`UPoly`], [`BPoly`]), the prime field [`Fp`], `f64`
//! intervals with outward rounding ([`Interval`]), exact real algebraic
//! numbers ([`RealAlgebraic`]), Lehmer's gcd of big integers ([`gcd`]) and
//! Sylvester resultants with formal degrees ([`sylvester`]).

pub mod gcd;
pub(crate) mod int;
pub(crate) mod interval;
pub mod interval_bernstein;
pub(crate) mod limbs;
pub(crate) mod modp;
pub(crate) mod number;
pub(crate) mod poly;
pub mod real_algebraic;
pub(crate) mod scalar;
pub mod sylvester;
pub(crate) mod upoly;
pub(crate) mod wide;
pub(crate) mod wide512;

pub use int::Int;
pub use interval::Interval;
pub use modp::Fp;
pub use number::{parse_rational, ExactNumber};
pub use poly::Poly;
pub use real_algebraic::{text::parse_algebraic, RealAlgebraic};
pub use scalar::{
    binomial, binomial_scalar, ratio, rational_root, rational_to_f64, recip_int, Field, MulAcc,
    Ordered, Ring, Roots, Scalar, Tolerance,
};
pub use sylvester::{linear_eliminant, resultant};
pub use upoly::{BPoly, UPoly};
pub use wide::Wide;
pub use wide512::Wide512;
