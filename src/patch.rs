//! One curve or patch of any shape: the sum type [`Patch`] of
//! [`RationalCurve`], [`RectPatch`] and [`TriPatch`], which commands,
//! coincidence, keys and audits take when the shape is known only at run
//! time (e.g. read from JSON by [`crate::io`]).

use crate::algebra::{Ordered, Scalar};
use crate::curve::RationalCurve;
use crate::hpoint::HPoint;
use crate::limits::{Cost, Size};
use crate::rect::RectPatch;
use crate::tri::TriPatch;

/// A curve, rectangular patch or triangular patch (the `"kind"` of the
/// JSON format: `"curve"`, `"rect"`, `"tri"`).
#[derive(Clone, Debug, PartialEq)]
pub enum Patch<T> {
    /// `"kind": "curve"`.
    Curve(RationalCurve<T>),
    /// `"kind": "rect"`.
    Rect(RectPatch<T>),
    /// `"kind": "tri"`.
    Tri(TriPatch<T>),
}

impl<T> From<RationalCurve<T>> for Patch<T> {
    fn from(c: RationalCurve<T>) -> Self {
        Patch::Curve(c)
    }
}

impl<T> From<RectPatch<T>> for Patch<T> {
    fn from(r: RectPatch<T>) -> Self {
        Patch::Rect(r)
    }
}

impl<T> From<TriPatch<T>> for Patch<T> {
    fn from(t: TriPatch<T>) -> Self {
        Patch::Tri(t)
    }
}

impl<T: Scalar> Patch<T> {
    /// The same patch over another scalar type.
    pub fn map<U: Scalar>(&self, f: impl Fn(&T) -> U) -> Patch<U> {
        match self {
            Patch::Curve(c) => Patch::Curve(c.map(f)),
            Patch::Rect(r) => Patch::Rect(r.map(f)),
            Patch::Tri(t) => Patch::Tri(t.map(f)),
        }
    }

    /// `"curve"`, `"rect"` or `"tri"`.
    pub fn kind(&self) -> &'static str {
        match self {
            Patch::Curve(_) => "curve",
            Patch::Rect(_) => "rect",
            Patch::Tri(_) => "tri",
        }
    }
}

impl<T: Ordered> Patch<T> {
    /// The patch with `f64` coordinates (nearest values).
    pub fn to_f64(&self) -> Patch<f64> {
        self.map(Ordered::to_f64)
    }
}

impl<T: Scalar + Cost> Patch<T> {
    /// The [`Size`] of this patch: degree, kind, dimension, the most bits
    /// of its stored (homogeneous) numbers and the degree of the number
    /// field they span.
    pub fn size(&self) -> Size {
        self.size_with(&[])
    }

    /// The [`Size`] of this patch computed with the numbers `with` (a
    /// command's parameters, another patch's numbers): they join the field
    /// degree, not the bits.
    pub fn size_with<'a>(&'a self, with: impl IntoIterator<Item = &'a T>) -> Size {
        let (degree, tri, dim) = match self {
            Patch::Curve(c) => ((c.degree(), 0), false, c.dim()),
            Patch::Rect(r) => (r.degree(), false, r.dim()),
            Patch::Tri(t) => ((t.degree(), 0), true, t.dim()),
        };
        Size::measure(degree, tri, dim, self.numbers(), with)
    }

    /// Every stored (homogeneous) number: weighted coordinates and weights.
    pub fn numbers(&self) -> Vec<&T> {
        let points: Vec<&HPoint<T>> = match self {
            Patch::Curve(c) => c.ctrl().iter().collect(),
            Patch::Rect(r) => r.ctrl().iter().flatten().collect(),
            Patch::Tri(t) => t.rows().iter().flatten().collect(),
        };
        points
            .into_iter()
            .flat_map(|h| h.weighted().iter().chain([h.weight()]))
            .collect()
    }
}
