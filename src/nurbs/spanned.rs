//! A B-spline curve or surface, whichever an input holds ([`Nurbs`]), and
//! its Bézier pieces with the knot spans they came from ([`SpannedPatch`]).

use super::{NurbsCurve, NurbsSurface};
use crate::patch::Patch;
use num_rational::BigRational;

/// A B-spline curve or surface (read from JSON by [`crate::io::read_nurbs`]
/// or from STEP by [`crate::step`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Nurbs {
    /// A (rational) B-spline curve.
    Curve(NurbsCurve<BigRational>),
    /// A (rational) B-spline surface.
    Surface(NurbsSurface<BigRational>),
}

/// A Bézier piece with the knot spans it came from (`v` is `None` for a curve).
#[derive(Clone, Debug, PartialEq)]
pub struct SpannedPatch {
    /// The piece.
    pub patch: Patch<BigRational>,
    /// Its span in u (or along the curve).
    pub u: [BigRational; 2],
    /// Its span in v (surfaces).
    pub v: Option<[BigRational; 2]>,
}

impl Nurbs {
    /// The Bézier pieces with their spans.
    pub fn pieces(&self) -> Vec<SpannedPatch> {
        match self {
            Nurbs::Curve(c) => c
                .bezier_pieces()
                .into_iter()
                .map(|p| SpannedPatch {
                    patch: Patch::Curve(p.curve),
                    u: p.span,
                    v: None,
                })
                .collect(),
            Nurbs::Surface(s) => s
                .bezier_pieces()
                .into_iter()
                .map(|p| SpannedPatch {
                    patch: Patch::Rect(p.patch),
                    u: p.u,
                    v: Some(p.v),
                })
                .collect(),
        }
    }
}
