//! The common types in one import: `use exact_bezier::prelude::*;`.

pub use crate::BigRational;
pub use crate::{
    ratio, Error, Field, Ordered, Patch, Poly, RationalCurve, RectPatch, Ring, Roots, Scalar,
    Tolerance, TriPatch,
};
