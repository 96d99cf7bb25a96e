//! Trigonometric curves and surfaces with shape parameters (source 002,
//! Sun & Shi): the basis (1), curves, tensor-product surfaces, G¹ stitching
//! and the bowl of §5 — generic over the scalar, exact at the rational
//! points of the unit circle, symbolic in `Q[s, c]/(s² + c² − 1)`.
//!
//! Reference: source 002.

pub use basis::{circle_normal_form, trig_basis_values, TrigFn, TrigParam};
pub use bowl::trig_bowl;
pub use curve::TrigCurve;
pub use patch::TrigPatch;
pub use stitch::{trig_g0, trig_g1_factor, trig_stitch, trig_tangent_continuous, TrigJoin};
pub use surface::TrigRect;

pub mod basis;
pub mod bowl;
pub mod curve;
mod patch;
pub mod rational;
pub mod stitch;
pub mod surface;
