//! # exact-bezier
//!
//! Rational Bézier curves, rectangular (tensor-product) patches and
//! triangular patches. Every algorithm is written once, generically over a
//! scalar type, and runs with several scalars:
//!
//! | scalar | for |
//! | --- | --- |
//! | `f64` | speed; comparisons take an explicit [`Tolerance`] |
//! | [`BigRational`](num_rational::BigRational) | exact answers, where equality is equality |
//! | [`Poly`] | proofs: an identity that comes out `== 0` on symbols holds for all their values |
//!
//! ## Start here
//!
//! - **Curves and patches**: [`RationalCurve`], [`RectPatch`] and
//!   [`TriPatch`] are stored homogeneously as `(w·P, w)`. They offer
//!   evaluation, derivatives, subdivision, elevation and Möbius maps. Their
//!   facets are in the modules [`curve`] (curvature, joins, degree
//!   reduction, circles), [`rect`] and [`tri`].
//! - **Many points fast**: [`eval::Evaluator`] evaluates a batch of
//!   parameters into your buffer with no allocation per point (`f64`), and
//!   exact evaluation is fraction-free on machine integers.
//! - **Exact numbers**: [`ratio`] builds a rational. [`io`] reads the JSON
//!   format of `docs/FORMAT.md` (numbers are read exactly from their text)
//!   and writes it back.
//! - **Is this the same surface?** [`coincide::coincide`] decides it exactly,
//!   up to Möbius maps, reversal, swap, elevation, common factors and weight
//!   scaling. [`coincide::canonical_key`] and [`coincide::dedup`] do the
//!   same in bulk.
//! - **Reparameterization and standard form** (source 000): [`reparam`].
//! - **Rectangle ↔ triangle conversions and blossoms** (source 003):
//!   [`convert`] and [`blossom`].
//! - **Trigonometric patches** (source 002): [`trig`]. **Circular arcs**
//!   (source 004): [`arc`].
//! - **The number types** behind the generic code, namely the traits
//!   [`Ring`], [`Scalar`], [`Field`] and [`Ordered`], are in [`algebra`].
//! - `use exact_bezier::prelude::*;` imports the common types.
//!
//! ```
//! use exact_bezier::prelude::*;
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
//! ## Features
//!
//! | feature | default | what it adds |
//! | --- | --- | --- |
//! | `cli` | yes | the `exact-bezier` binary (turns on `render`) |
//! | `serde` | yes | `serde` for curves and patches (Bézier, trigonometric, NURBS) and results (coincidence, standard forms), in the JSON format of [`io`]; `FromStr` from that text |
//! | `render` | with `cli` | `render`: SVG/PNG plots and OBJ/STL/PLY meshes |
//! | `proptest` | no | `strategy`: proptest strategies for curves and patches |
//! | `mint` | no | [`coords`]: control points from `mint` points |
//!
//! With `default-features = false` the crate is the mathematics and the
//! JSON format ([`io`]) alone: it depends on the `num-*` crates and
//! `serde_json`, and not on `clap` or `resvg`.
//!
//! ## Sources
//!
//! The algorithms come from five documents, which the docs cite as
//! "source 000" to "source 004". The README's bibliography lists them in
//! full. Every claim the sources make is checked in `proofs/`
//! (`exact-bezier prove`).

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod algebra;
pub mod arc;
pub mod audit;
pub mod bernstein;
pub mod blossom;
pub mod coincide;
pub mod convert;
pub mod coords;
pub mod curve;
mod display;
pub mod error;
pub mod eval;
pub mod hpoint;
pub mod intersect;
pub mod io;
pub mod limits;
pub mod nurbs;
pub mod prelude;
pub mod rect;
#[cfg(feature = "render")]
pub mod render;
pub mod reparam;
#[cfg(test)]
mod samples;
#[cfg(feature = "serde")]
mod serde_support;
pub mod step;
#[cfg(feature = "proptest")]
pub mod strategy;
pub mod tri;
pub mod trig;

pub use algebra::{ratio, Field, Ordered, Poly, Ring, Roots, Scalar, Tolerance};
pub use curve::RationalCurve;
pub use error::Error;
pub use io::Patch;
pub use limits::MAX_DEGREE;
pub use rect::RectPatch;
pub use tri::TriPatch;

/// The README's Rust examples, run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
