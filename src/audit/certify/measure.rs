//! All certified measures of one edge between two faces.

use super::angle::angle;
use super::bezier::ICurve;
use super::curvature::curvature;
use super::gap::{edge_face, face_face};
use super::local::{Face, Local, Tracker};
use super::maximize::{maximize, Bound, Enclosure, Target};
use crate::algebra::Interval;
use crate::error::Error;

/// How tight the enclosures are made: each `[lo, hi]` is refined until
/// `hi − lo ≤ rel·hi + abs` (the `abs` in the quantity's unit).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Precision {
    /// Relative width, default `10⁻³`.
    pub rel: f64,
    /// Absolute width of gaps, in model length units, default `10⁻⁸` (a
    /// hundredth of the default length tolerance).
    pub length: f64,
    /// Absolute width of angles, in radians, default `10⁻⁸` (a hundredth of
    /// the default angle tolerance).
    pub angle: f64,
    /// Absolute width of curvature differences, per length unit, default
    /// `10⁻⁴` (a tenth of the default tolerance: the enclosure of a
    /// curvature narrows only linearly with the piece's length).
    pub curvature: f64,
}

impl Default for Precision {
    fn default() -> Self {
        Precision {
            rel: 1e-3,
            length: 1e-8,
            angle: 1e-8,
            curvature: 1e-4,
        }
    }
}

/// The certified measures of an edge: each the maximum along the edge,
/// enclosed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgeMeasures {
    /// The largest distance from the edge curve to each face (at its foot
    /// points).
    pub gap: [Enclosure; 2],
    /// The largest distance between the two faces' foot points.
    pub face_gap: Enclosure,
    /// The largest angle between the faces' oriented normals, in radians.
    pub angle: Enclosure,
    /// The largest difference of the faces' normal curvatures across the
    /// edge, per length unit.
    pub curvature: Enclosure,
}

/// The maximum of one measure along one edge piece.
fn along(
    curve: &ICurve,
    faces: &[Face; 2],
    abs: f64,
    rel: f64,
    f: impl Fn(&Local) -> Option<Bound>,
) -> Result<Enclosure, Error> {
    let mut tracker = Tracker::new(curve, faces);
    let range = Interval { lo: 0.0, hi: 1.0 };
    maximize(range, Target { rel, abs }, |t| {
        Ok(tracker.local(t)?.and_then(|l| f(&l)))
    })
}

/// The maximum of one measure along an edge of several pieces, with the
/// piece index where it is attained.
fn along_edge(
    edge: &[ICurve],
    faces: &[Face; 2],
    abs: f64,
    rel: f64,
    f: impl Fn(&Local) -> Option<Bound> + Copy,
) -> Result<(Enclosure, usize), Error> {
    let mut best: Option<(Enclosure, usize)> = None;
    for (k, c) in edge.iter().enumerate() {
        let e = along(c, faces, abs, rel, f)?;
        best = Some(match best {
            Some((b, i)) if b.hi >= e.hi => (b.max(e), i),
            Some((b, _)) => (e.max(b), k),
            None => (e, k),
        });
    }
    best.ok_or_else(|| Error::Shape("an edge with no curve pieces".into()))
}

/// Measure the edge (its Bézier pieces, each over `[0, 1]`) between two
/// faces. The `at` of each enclosure is a parameter interval of the piece
/// returned alongside in [`EdgeReport`].
///
/// # Errors
///
/// [`crate::Error::Limit`] when the work budget runs out (see
/// [`crate::limits`]); [`Error::Domain`] when a foot point cannot be
/// proved (the edge leaves a face, or a face is singular there).
pub fn measure_edge(
    edge: &[ICurve],
    faces: &[Face; 2],
    p: &Precision,
) -> Result<EdgeReport, Error> {
    let gap0 = along_edge(edge, faces, p.length, p.rel, |l| Some(edge_face(l, 0)))?;
    let gap1 = along_edge(edge, faces, p.length, p.rel, |l| Some(edge_face(l, 1)))?;
    let face_gap = along_edge(edge, faces, p.length, p.rel, |l| Some(face_face(l)))?;
    let angle = along_edge(edge, faces, p.angle, p.rel, |l| Some(angle(l, faces)))?;
    let curvature = along_edge(edge, faces, p.curvature, p.rel, |l| curvature(l, faces))?;
    Ok(EdgeReport {
        measures: EdgeMeasures {
            gap: [gap0.0, gap1.0],
            face_gap: face_gap.0,
            angle: angle.0,
            curvature: curvature.0,
        },
        pieces: [gap0.1, gap1.1, face_gap.1, angle.1, curvature.1],
    })
}

/// [`EdgeMeasures`] with the edge piece where each maximum is attained.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgeReport {
    /// The measures.
    pub measures: EdgeMeasures,
    /// The piece index of each maximum: gap to face 0, gap to face 1, face
    /// gap, angle, curvature.
    pub pieces: [usize; 5],
}
