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

mod algebra;
mod arc;
mod audit;
mod bernstein;
mod blossom;
mod canonical;
mod circle;
#[cfg(feature = "cli")]
#[doc(hidden)]
pub mod cli;
mod coincide;
mod continuity;
mod convert;
pub mod coords;
mod curve;
mod curve_deriv;
mod curve_geometry;
mod degree_reduction;
mod display;
mod error;
mod fast_eval;
mod hpoint;
mod int;
mod interval;
mod io;
pub mod limits;
#[cfg(feature = "render")]
mod mesh;
mod minimal_degree;
mod modp;
mod nurbs;
#[cfg(feature = "render")]
pub mod plot;
mod poly;
mod rect;
mod rect_join;
mod rect_ops;
mod reparam;
#[cfg(any(test, feature = "cli"))]
mod samples;
mod scalar;
#[cfg(feature = "serde")]
mod serde_support;
mod standard;
mod step;
#[cfg(feature = "proptest")]
pub mod strategy;
mod tri;
mod trig;
mod trig_io;
mod upoly;

/// The claims of the sources and their proofs, run by `exact-bezier prove`.
/// Not part of the public API.
#[cfg(feature = "cli")]
#[doc(hidden)]
#[path = "../proofs/mod.rs"]
pub mod proofs;

/// The README's Rust examples, run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

pub use algebra::real_algebraic::{text::parse_algebraic, RealAlgebraic};
pub use arc::{
    check_lambda, lambda_change_delta, lambda_change_param, lambda_interval, lambda_of_sigma_cubed,
    sigma_of_lambda, ArcCubic, Computed, LambdaFactors, QuadArc,
};
pub use audit::{
    audit, piece_to_json, read_model, seam_continuity, Audit, Continuity, Model, Origin, PatchEdge,
    Piece, Seam, SeamVerdict,
};
pub use bernstein::{bernstein, bernstein_all};
pub use blossom::{polar_bivariate, polar_tensor, polar_univariate, rect_blossom, ShiftOp};
pub use canonical::{canonical_key, dedup, CanonicalKey, Deduper};
pub use canonical::{canonical_text, key_digest, Classes, KeyDigest, KEY_VERSION};
pub use circle::{circle_of, integer_coords, Circle, NotCircle};
pub use coincide::{
    boundary_curve, coincide, coincide_curves, coincide_f64, coincide_rects, shared_boundaries,
    Coincidence, Edge, MobiusParam, ReductionInfo, Symmetry, Witness,
};
pub use continuity::{g2_leading_points, join, Join};
pub use convert::{
    bilinear, degree_raising_matrix, rect_to_tri, rect_to_tris, square_corners,
    tri_to_degenerate_rect, tri_to_rect_hu, tri_to_rect_on_quad, tri_to_rects,
    tri_to_rects_operators, Half, Split,
};
pub use curve::{mobius_factors, RationalCurve};
pub use curve_deriv::forward_differences;
pub use curve_geometry::{cross_norm_sq, ConicType, CurveEnd};
pub use degree_reduction::Reduction;
pub use error::{Error, MAX_DEGREE};
pub use fast_eval::{FastCurve, FastRect, FastTri};
pub use hpoint::{de_casteljau, de_casteljau_hom, HPoint};
pub use int::Int;
pub use interval::{coincide_filtered, DecidedBy, Interval};
pub use io::{for_each_chunk, patch_from_value_as, read_patches_as, ExactNumber, Record};
pub use io::{
    parse_json, parse_rational, patch_from_value, patch_to_json, point_to_json, read_patches,
    JsonScalar, Patch,
};
#[cfg(feature = "render")]
pub use mesh::{curve_jet, normal_direction, rect_jet, tri_jet, Jet, Mesh, MAX_DENSITY};
pub use minimal_degree::{
    bernstein_to_power, minimal_curve, minimal_rect, multiply_components, power_to_bernstein,
    Minimal,
};
pub use modp::Fp;
pub use nurbs::json::{is_nurbs, read_nurbs, Nurbs, SpannedPatch};
pub use nurbs::{CurvePiece, Knots, NurbsCurve, NurbsSurface, SurfacePiece};
pub use poly::Poly;
pub use rect::{RectPatch, Side};
pub use rect_join::{g0_join, g1_join};
pub use rect_ops::Corner;
pub use reparam::{bernstein_product, quadratic_coefficients, Quadratic};
pub use scalar::{
    binomial, binomial_scalar, ratio, rational_root, rational_to_f64, Field, Ordered, Ring, Roots,
    Scalar, Tolerance,
};
pub use standard::{
    corner_weights, standardize_curve, standardize_curve_algebraic, standardize_curve_exact_or_f64,
    standardize_mobius, standardize_quadratic, standardize_quadratic_compact, standardize_rect,
    standardize_rect_algebraic, standardize_rect_exact_or_f64, theorem1_holds, Exactness, Standard,
    StandardMap,
};
pub use step::{read_step, StepEntity, StepModel};
pub use tri::{affine_combination, tri_bernstein, Bary, TriPatch, SYMMETRIES};
pub use trig::basis::{circle_normal_form, trig_basis_values, TrigFn, TrigParam};
pub use trig::bowl::trig_bowl;
pub use trig::curve::TrigCurve;
pub use trig::stitch::{trig_g0, trig_g1_factor, trig_stitch, trig_tangent_continuous, TrigJoin};
pub use trig::surface::TrigRect;
pub use trig_io::{read_trig_patches, trig_patch_to_json, TrigPatch};
pub use upoly::{BPoly, UPoly};
