//! One trigonometric curve or surface of source 002 (Sun & Shi), whichever
//! the input holds: the sum type [`TrigPatch`].

use super::curve::TrigCurve;
use super::surface::TrigRect;
use crate::algebra::{Ordered, Scalar};
use num_rational::BigRational;

/// A trigonometric curve or tensor-product surface (the JSON kinds
/// `"trig-curve"` and `"trig-rect"`).
#[derive(Clone, Debug, PartialEq)]
pub enum TrigPatch<T> {
    /// `"kind": "trig-curve"`.
    Curve(TrigCurve<T>),
    /// `"kind": "trig-rect"`.
    Rect(TrigRect<T>),
}

impl<T: Scalar> TrigPatch<T> {
    /// Apply `f` to every number (e.g. exact → `f64` with [`Ordered::to_f64`]).
    pub fn map<U: Scalar>(&self, f: impl Fn(&T) -> U) -> TrigPatch<U> {
        match self {
            TrigPatch::Curve(c) => TrigPatch::Curve(c.map(f)),
            TrigPatch::Rect(r) => TrigPatch::Rect(r.map(f)),
        }
    }
}

impl TrigPatch<BigRational> {
    /// The nearest `f64` patch.
    pub fn to_f64(&self) -> TrigPatch<f64> {
        self.map(Ordered::to_f64)
    }
}
