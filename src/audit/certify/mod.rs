//! Certified measures of an edge between two faces: the largest gap,
//! tangent-plane angle and normal-curvature difference along it, each an
//! enclosure `[lo, hi]` proved to contain the true maximum, and verdicts
//! against tolerances. See `docs/audit.md`, "Certified measures".
//!
//! The data are exact (rationals, or real algebraic numbers enclosed by
//! rational intervals through [`Enclose`]); the proofs run in interval
//! arithmetic with outward rounding ([`crate::algebra::Interval`]) on
//! enclosures of the exact control points:
//!
//! 1. [`bezier`]: enclosures of curves and patches and their derivatives
//!    over parameter boxes (Bernstein pieces, convex hull);
//! 2. [`krawczyk`] and [`foot`]: the face parameters of the edge's foot
//!    points, proved for a whole piece of the edge at once (Krawczyk);
//! 3. [`gap`], [`angle`], [`curvature`]: bounds of each measure on a
//!    piece of the edge, mean-value forms where the quantity is small;
//! 4. [`maximize`]: branch and bound over the edge's parameter to a target
//!    width, charged to the work budget;
//! 5. [`measure`] and [`verdict`]: all measures of an edge, and verdicts.
//!
//! ```
//! use exact_bezier::{ratio, BigRational, RationalCurve, RectPatch};
//! use exact_bezier::audit::certify::*;
//! let q = |n: i64, d: i64| ratio::<BigRational>(n, d);
//! let p = |x: BigRational, y: BigRational, z: BigRational| vec![x, y, z];
//! // Two unit squares meeting along the x axis at a right angle.
//! let floor = RectPatch::polynomial(vec![
//!     vec![p(q(0, 1), q(0, 1), q(0, 1)), p(q(0, 1), q(-1, 1), q(0, 1))],
//!     vec![p(q(1, 1), q(0, 1), q(0, 1)), p(q(1, 1), q(-1, 1), q(0, 1))],
//! ]).unwrap();
//! let wall = RectPatch::polynomial(vec![
//!     vec![p(q(0, 1), q(0, 1), q(0, 1)), p(q(0, 1), q(0, 1), q(1, 1))],
//!     vec![p(q(1, 1), q(0, 1), q(0, 1)), p(q(1, 1), q(0, 1), q(1, 1))],
//! ]).unwrap();
//! let edge = RationalCurve::polynomial(vec![p(q(0, 1), q(0, 1), q(0, 1)), p(q(1, 1), q(0, 1), q(0, 1))]).unwrap();
//! let faces = [
//!     Face { patch: IPatch::new(&floor).unwrap(), outward: false },
//!     Face { patch: IPatch::new(&wall).unwrap(), outward: true },
//! ];
//! let m = measure_edge(&[ICurve::new(&edge).unwrap()], &faces, &Precision::default()).unwrap().measures;
//! let right = std::f64::consts::FRAC_PI_2;
//! assert!(m.angle.lo <= right && right <= m.angle.hi && m.angle.hi - m.angle.lo < 1e-9);
//! assert_eq!(m.gap[0].lo, 0.0);
//! assert!(m.gap[0].hi < 1e-12);
//! ```

pub mod angle;
pub mod bezier;
pub mod closed_form;
pub mod compose;
pub mod curvature;
pub mod field;
pub mod foot;
pub mod gap;
pub mod ivec;
pub mod krawczyk;
pub mod local;
pub mod maximize;
pub mod measure;
pub mod normal_path;
pub mod quad;
pub mod spline;
pub mod tube;
pub mod verdict;

pub use bezier::{ICurve, IPatch};
pub use local::Face;
pub use maximize::{Enclosure, Target};
pub use measure::{measure_edge, EdgeMeasures, EdgeReport, Precision};
pub use verdict::{judge, verdicts, Tolerances, Verdict, Verdicts};

use crate::algebra::{Interval, RealAlgebraic};
use num_rational::BigRational;

/// Exact numbers that can be enclosed by an [`Interval`].
pub trait Enclose {
    /// An interval proved to contain `self`.
    fn enclose(&self) -> Interval;
}

impl Enclose for BigRational {
    fn enclose(&self) -> Interval {
        Interval::enclose(self)
    }
}

impl Enclose for RealAlgebraic {
    /// The hull of the enclosures of rational bounds `lo ≤ x ≤ hi` of width
    /// about `2⁻⁶⁴` ([`RealAlgebraic::enclosure`]).
    fn enclose(&self) -> Interval {
        let (lo, hi) = self.enclosure(64);
        Interval::enclose(&lo).hull(&Interval::enclose(&hi))
    }
}

#[cfg(test)]
mod tests;
