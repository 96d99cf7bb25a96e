//! # exact-bezier
//!
//! Rational Bézier curves, rectangular (tensor-product) patches and
//! triangular patches, with every algorithm written once, generically over a
//! [`Scalar`], and run over three instantiations: `f64` for speed,
//! [`BigRational`](num_rational::BigRational) for exact answers, and the
//! symbolic [`Poly`] for proofs of identities for all parameter values.
//!
//! ```
//! use exact_bezier::{RationalCurve, Poly, ratio};
//! use num_rational::BigRational;
//!
//! // An arc of the unit circle as an exact rational quadratic: half-angle
//! // with cos = 3/5, so the middle weight is 3/5 and the middle point (1, 4/3).
//! let p = |x: BigRational, y: BigRational| vec![x, y];
//! let arc = RationalCurve::new(
//!     vec![p(ratio(1, 1), ratio(0, 1)), p(ratio(1, 1), ratio(4, 3)), p(ratio(-7, 25), ratio(24, 25))],
//!     vec![ratio(1, 1), ratio(3, 5), ratio(1, 1)],
//! ).unwrap();
//! let x = arc.eval(&ratio(1, 3)).unwrap();
//! assert_eq!(x[0].clone() * &x[0] + x[1].clone() * &x[1], ratio(1, 1)); // on the circle, exactly
//!
//! // The same Möbius code, run on symbols, proves the weight rule for all α, s.
//! let sym = arc.map(|q| Poly::constant(q.clone()));
//! let (alpha, s) = (Poly::var("alpha"), Poly::var("s"));
//! let moved = sym.mobius(&alpha).eval_hom(&s);
//! assert_eq!(moved.dim(), 2);
//! ```
//!
//! Conventions and sources are stated in each module; the claims of the
//! sources are checked in `proofs/` (`exact-bezier prove`).

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod bernstein;
mod canonical;
pub mod cli;
mod coincide;
mod curve;
mod error;
mod hpoint;
mod interval;
mod io;
mod minimal_degree;
mod modp;
mod poly;
mod rect;
mod scalar;
#[cfg(feature = "proptest")]
pub mod strategy;
mod tri;
mod upoly;

#[path = "../proofs/mod.rs"]
pub mod proofs;

pub use bernstein::{bernstein, bernstein_all};
pub use canonical::{canonical_key, dedup, CanonicalKey, Deduper};
pub use coincide::{
    boundary_curve, coincide, coincide_curves, coincide_f64, coincide_rects, shared_boundaries,
    Coincidence, Edge, MobiusParam, NthRoot, ReductionInfo, Symmetry, Witness,
};
pub use curve::{mobius_factors, RationalCurve};
pub use error::{Error, MAX_DEGREE};
pub use hpoint::{de_casteljau, HPoint};
pub use interval::{coincide_filtered, DecidedBy, Interval};
pub use io::{
    parse_json, parse_rational, patch_from_value, patch_to_json, point_to_json, read_patches,
    JsonScalar, Patch,
};
pub use minimal_degree::{
    bernstein_to_power, minimal_curve, minimal_rect, multiply_components, power_to_bernstein,
    Minimal,
};
pub use modp::Fp;
pub use poly::Poly;
pub use rect::RectPatch;
pub use scalar::{
    binomial, binomial_scalar, ratio, rational_root, rational_to_f64, Field, Ordered, Scalar,
    Tolerance,
};
pub use tri::TriPatch;
pub use upoly::{BPoly, UPoly};
