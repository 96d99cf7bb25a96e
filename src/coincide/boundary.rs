//! Shared boundaries (source 000 §3, the stitching application): is a
//! boundary curve of one patch the same curve as a boundary curve of
//! another, up to Möbius maps, reversal, elevation, common factors and
//! weight scaling?

use super::{coincide, Coincidence, Options};
use crate::algebra::scalar::Scalar;
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::rect::RectPatch;
use crate::Patch;
use num_rational::BigRational;
use std::fmt;

/// One of the four boundary curves of a rect patch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Edge {
    /// `X(0, v)`: the control points `P_{0,j}`.
    U0,
    /// `X(1, v)`: the control points `P_{m,j}`.
    U1,
    /// `X(u, 0)`: the control points `P_{i,0}`.
    V0,
    /// `X(u, 1)`: the control points `P_{i,n}`.
    V1,
}

impl Edge {
    /// The four edges.
    pub const ALL: [Edge; 4] = [Edge::U0, Edge::U1, Edge::V0, Edge::V1];
}

impl fmt::Display for Edge {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Edge::U0 => "u=0",
            Edge::U1 => "u=1",
            Edge::V0 => "v=0",
            Edge::V1 => "v=1",
        })
    }
}

/// The boundary curve of `r` along `edge`, parameterized by the free
/// parameter in its own direction (exact: the control points of that row or
/// column of the net, weights included).
///
/// ```
/// use exact_bezier::{coincide::boundary_curve, coincide::Edge, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let r = RectPatch::polynomial(vec![vec![p(0), p(1), p(2)], vec![p(3), p(4), p(5)]]).unwrap();
/// assert_eq!(boundary_curve(&r, Edge::V1).points().unwrap(), vec![p(2), p(5)]);
/// ```
pub fn boundary_curve<T: Scalar>(r: &RectPatch<T>, edge: Edge) -> RationalCurve<T> {
    let net = r.ctrl();
    let (m, n) = r.degree();
    let ctrl = match edge {
        Edge::U0 => net[0].clone(),
        Edge::U1 => net[m].clone(),
        Edge::V0 => net.iter().map(|row| row[0].clone()).collect(),
        Edge::V1 => net.iter().map(|row| row[n].clone()).collect(),
    };
    RationalCurve::from_hom(ctrl).expect("a row of a valid net is a valid curve")
}

/// Every pair of edges `(edge of a, edge of b)` along which `a` and `b`
/// share the same boundary curve exactly, with its coincidence witness.
///
/// ```
/// use exact_bezier::{coincide::shared_boundaries, coincide::Edge, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let a = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 1)], vec![p(1, 0), p(1, 1)]]).unwrap();
/// // b's edge u = 0 is a's edge u = 1, traversed backwards and elevated.
/// let b = RectPatch::polynomial(vec![vec![p(1, 1), p(1, 0)], vec![p(2, 1), p(2, 0)]]).unwrap().elevate(0, 2);
/// let shared = shared_boundaries(&a, &b).unwrap();
/// assert_eq!(shared.len(), 1);
/// assert_eq!((shared[0].0, shared[0].1), (Edge::U1, Edge::U0));
/// ```
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight.
pub fn shared_boundaries(
    a: &RectPatch<BigRational>,
    b: &RectPatch<BigRational>,
) -> Result<Vec<(Edge, Edge, Coincidence<BigRational>)>, Error> {
    let mut out = Vec::new();
    for ea in Edge::ALL {
        for eb in Edge::ALL {
            let (ca, cb) = (boundary_curve(a, ea), boundary_curve(b, eb));
            let c = coincide(&Patch::Curve(ca), &Patch::Curve(cb), Options::default())?;
            if c.coincident {
                out.push((ea, eb, c));
            }
        }
    }
    Ok(out)
}
