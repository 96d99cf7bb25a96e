//! [`Patch::size`]: what the cost model of `limits` needs to know of a
//! patch (it goes with `Patch` wherever `Patch` lives).

use crate::algebra::scalar::Scalar;
use crate::hpoint::HPoint;
use crate::limits::{Cost, Size};
use crate::Patch;

impl<T: Scalar + Cost> Patch<T> {
    /// The [`Size`] of this patch: degree, kind, dimension, the most bits
    /// and the largest operation cost of its stored (homogeneous) numbers.
    pub fn size(&self) -> Size {
        let (degree, tri, dim, points): (_, _, _, Vec<&HPoint<T>>) = match self {
            Patch::Curve(c) => ((c.degree(), 0), false, c.dim(), c.ctrl().iter().collect()),
            Patch::Rect(r) => (
                r.degree(),
                false,
                r.dim(),
                r.ctrl().iter().flatten().collect(),
            ),
            Patch::Tri(t) => (
                (t.degree(), 0),
                true,
                t.dim(),
                t.rows().iter().flatten().collect(),
            ),
        };
        let numbers = points
            .into_iter()
            .flat_map(|h| h.weighted().iter().chain([h.weight()]));
        Size::measure(degree, tri, dim, numbers)
    }
}
