//! # exact-bezier
//!
//! Rational Bézier curves, rectangular (tensor-product) patches and
//! triangular patches. Every algorithm is written once, generically over a
//! scalar type, and runs with several scalars:
//!
//! | scalar | for |
//! | --- | --- |
//! | `f64` | speed; comparisons take an explicit [`Tolerance`] |
//! | [`BigRational`] | exact answers, where equality is equality |
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
//! ## Layers
//!
//! The modules form layers, each using only those below it (checked by
//! `tests/layers.rs`, which fails on an upward import or a circle):
//!
//! 1. [`Error`], [`limits`] and `widest` — errors, every limit and the cost
//!    model, and the run-time choice of vector instructions for loops;
//! 2. [`algebra`] — the scalar tower ([`Ring`], [`Scalar`], [`Field`],
//!    [`Ordered`]) and the number types: integers, intervals, the symbolic
//!    [`Poly`], real algebraic numbers, resultants;
//! 3. [`hpoint`] and [`bernstein`] — homogeneous points, de Casteljau, the
//!    Bernstein basis;
//! 4. [`eval`] — the evaluation kernels (batches, jets, fraction-free exact);
//! 5. [`curve`], [`rect`], [`tri`], then [`Patch`] — the three shapes and
//!    their sum;
//! 6. operations: [`blossom`], [`convert`], [`reparam`], [`arc`], [`trig`];
//! 7. predicates: [`coincide`], [`intersect`];
//! 8. formats: [`nurbs`], [`analytic`] (the analytic curves and surfaces of
//!    STEP as exact rational pieces), [`step`], [`io`] (all JSON reading and
//!    writing);
//! 9. applications: [`audit`], `render`, [`coords`], `strategy`, the
//!    [`prelude`].
//!
//! The command line (crate `exact-bezier-cli`) and the proofs report
//! (crate `exact-bezier-proofs`) are separate crates of the workspace that
//! use this crate's public API only.
//!
//! ## Features
//!
//! | feature | default | what it adds |
//! | --- | --- | --- |
//! | `serde` | yes | `serde` for curves and patches (Bézier, trigonometric, NURBS) and results (coincidence, standard forms), in the JSON format of [`io`]; `FromStr` from that text |
//! | `render` | no | `render`: SVG/PNG plots and OBJ/STL/PLY meshes (depends on `resvg`) |
//! | `proptest` | no | `strategy`: proptest strategies for curves and patches |
//! | `mint` | no | [`coords`]: control points from `mint` points |
//! | `simd` | yes | the `f64` batch kernels and the interval loops of the audit compiled for AVX-512 or AVX2 too, chosen at run time where the processor has them (through `pulp`); the same bits either way |
//!
//! With `default-features = false` the crate is the mathematics and the
//! JSON format ([`io`]) without the `serde` impls; it depends on `resvg`
//! only with `render`. The command-line tool `exact-bezier` is another
//! crate of the repository's workspace (`exact-bezier-cli`, in `cli/`),
//! which turns `render` on.
//!
//! ## Sources
//!
//! The algorithms come from five documents, which the docs cite as
//! "source 000" to "source 004" (the README's references give them in full,
//! with their Chinese titles):
//!
//! - **000**: Yang Yi-Jun, Yong Jun-Hai, Zhang Hui, Sun Jia-Guang,
//!   *Standardization of rational Bézier surfaces*, Journal of
//!   Computer-Aided Design & Computer Graphics, 2007.
//! - **001**: Hu Shi-Min, *Bézier curves and surfaces*, lecture slides of
//!   the course Fundamentals of Computer Graphics, Tsinghua University
//!   (undated).
//! - **002**: Sun Mingcan, Shi Jing, *Smooth stitching of bicubic Bézier
//!   triangular surface with shape parameters*, Journal of Yanbian
//!   University (Natural Science Edition), 2023.
//! - **003**: Zhang Ming-li, Chen Xiao-qun, Feng Yu-yu, *Conversion between
//!   rational rectangular and rational triangular Bézier patches by
//!   Blossoming method*, University of Science and Technology of China
//!   (our copy prints neither journal nor year).
//! - **004**: Hang Houjun, Li Wanggen, *Investigation of inner properties
//!   of the standard-form cubic rational Bézier representation of circular
//!   arcs*, Journal of Image and Graphics, 2011, 16(12).
//!
//! Every claim the sources make is checked by the workspace's proofs crate
//! (`proofs/`, run by `exact-bezier prove`).

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod algebra;
pub mod analytic;
pub mod arc;
pub mod audit;
pub mod bernstein;
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
pub mod patch;
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
mod widest;

// After `tri`: rustdoc lists a type's inherent impl blocks in module order,
// and `blossom` adds one to `TriPatch` that should follow its construction
// and evaluation.
pub mod blossom;

pub use algebra::{ratio, Field, MulAcc, Ordered, Poly, Ring, Roots, Scalar, Tolerance};
pub use curve::RationalCurve;
pub use error::Error;
pub use limits::MAX_DEGREE;
pub use patch::Patch;
pub use rect::RectPatch;
pub use tri::TriPatch;

/// Arbitrary-precision integers (`num-bigint`): the numerator and
/// denominator of a [`BigRational`], and the operands of
/// [`algebra::gcd`]. Re-exported for the same reason as [`BigRational`].
pub use num_bigint::{BigInt, BigUint};
/// Exact rational numbers (`num-rational`'s `BigRational`), the scalar of
/// exact answers. Re-exported so that code using this crate names it as
/// `exact_bezier::BigRational` (or through the [`prelude`]) and needs no
/// dependency of its own on `num-rational`.
pub use num_rational::BigRational;

/// The README's Rust examples, run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
