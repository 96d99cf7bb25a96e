//! Verdicts of an edge's continuity against tolerances.
//!
//! For each order (G0: the gaps; G1: the angle; G2: the curvature
//! difference) the verdict is
//!
//! - [`Verdict::Exact`]: the deviation is proved to be 0 — by the exact
//!   seam test ([`crate::audit::seam_continuity`]) where the faces share
//!   their boundary exactly;
//! - [`Verdict::WithinTolerance`]: the enclosure's upper end is below the
//!   tolerance, so the true maximum deviation is;
//! - [`Verdict::Fails`]: the lower end is above the tolerance, so the true
//!   maximum deviation is too — with its enclosure and where;
//! - [`Verdict::Undecided`]: the enclosure straddles the tolerance.

use super::maximize::Enclosure;
use super::measure::EdgeMeasures;
use crate::audit::seam::Continuity;

/// The tolerances a model is judged against.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Length, in model units (default `10⁻⁶`; a model's declared
    /// uncertainty replaces it).
    pub length: f64,
    /// Angle between tangent planes, in radians (default `10⁻⁶`: above the
    /// rounding of 15-digit decimals, below any intended kink).
    pub angle: f64,
    /// Difference of normal curvatures, per length unit (default `10⁻³`).
    pub curvature: f64,
}

impl Default for Tolerances {
    fn default() -> Self {
        Tolerances {
            length: 1e-6,
            angle: 1e-6,
            curvature: 1e-3,
        }
    }
}

/// The verdict of one order of continuity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Verdict {
    /// The deviation is proved to be exactly 0.
    Exact,
    /// The deviation is proved to be below the tolerance.
    WithinTolerance,
    /// The deviation is proved to be above the tolerance.
    Fails {
        /// Its enclosure, with where it is attained.
        magnitude: Enclosure,
    },
    /// The enclosure straddles the tolerance.
    Undecided,
}

/// Judge an enclosure of a deviation against `tol`.
///
/// ```
/// use exact_bezier::algebra::Interval;
/// use exact_bezier::audit::certify::{judge, Enclosure, Verdict};
/// let e = Enclosure { lo: 2e-7, hi: 3e-7, at: Interval::point(0.5), tight: true };
/// assert_eq!(judge(&e, 1e-6), Verdict::WithinTolerance);
/// assert_eq!(judge(&e, 1e-7), Verdict::Fails { magnitude: e });
/// assert_eq!(judge(&e, 2.5e-7), Verdict::Undecided);
/// ```
pub fn judge(e: &Enclosure, tol: f64) -> Verdict {
    if e.hi < tol {
        Verdict::WithinTolerance
    } else if e.lo > tol {
        Verdict::Fails { magnitude: *e }
    } else {
        Verdict::Undecided
    }
}

/// The verdicts of an edge, G0 to G2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Verdicts {
    /// Positions (the largest of the three gaps).
    pub g0: Verdict,
    /// Tangent planes (the angle).
    pub g1: Verdict,
    /// Normal curvatures.
    pub g2: Verdict,
}

/// The verdicts of measured edge `m` against `tol`; `exact` is the exact
/// seam test's answer where the faces share the edge exactly (orders up to
/// it are [`Verdict::Exact`]).
pub fn verdicts(m: &EdgeMeasures, tol: &Tolerances, exact: Option<Continuity>) -> Verdicts {
    let gap = m.gap[0].max(m.gap[1]).max(m.face_gap);
    let order = |k: Continuity, e: &Enclosure, t: f64| match exact {
        Some(c) if c >= k => Verdict::Exact,
        _ => judge(e, t),
    };
    Verdicts {
        g0: order(Continuity::G0, &gap, tol.length),
        g1: order(Continuity::G1, &m.angle, tol.angle),
        g2: order(Continuity::G2, &m.curvature, tol.curvature),
    }
}
