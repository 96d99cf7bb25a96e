//! What every measure needs on one piece `T` of an edge: the curve's jet
//! over `T` and at its midpoint `t_m`, and both faces' verified foot
//! points over `T` and at `t_m`. Newton starts from the last foot found
//! (pieces are examined in order of splitting, so it is usually close).

use super::bezier::{CurveJet, ICurve, IPatch};
use super::foot::{foot, Foot};
use crate::algebra::Interval;
use crate::error::Error;

/// A face along an edge: its patch, and whether `S_u × S_v` points out of
/// the solid (`true`) or into it (STEP: the face's `same_sense`).
#[derive(Clone, Debug)]
pub struct Face {
    /// The face's patch, enclosed.
    pub patch: IPatch,
    /// Does `S_u × S_v` point outward?
    pub outward: bool,
}

impl Face {
    /// `±1`: the orientation sign of `S_u × S_v`.
    pub fn sign(&self) -> Interval {
        Interval::point(if self.outward { 1.0 } else { -1.0 })
    }
}

/// The jets of one piece `T` of the edge.
#[derive(Clone, Debug)]
pub struct Local {
    /// `C`, `C'` at `t_m`.
    pub c_mid: CurveJet,
    /// `C`, `C'` over `T`.
    pub c_over: CurveJet,
    /// `T − t_m`.
    pub dt: Interval,
    /// Both faces' feet over `T`.
    pub over: [Foot; 2],
    /// Both faces' feet at `t_m`.
    pub mid: [Foot; 2],
}

/// Finds [`Local`]s along one edge curve, remembering the last feet.
#[derive(Debug)]
pub struct Tracker<'a> {
    curve: &'a ICurve,
    faces: [&'a IPatch; 2],
    guess: [Option<[f64; 2]>; 2],
}

impl<'a> Tracker<'a> {
    /// A tracker for `curve` against the two faces.
    pub fn new(curve: &'a ICurve, faces: &'a [Face; 2]) -> Tracker<'a> {
        Tracker {
            curve,
            faces: [&faces[0].patch, &faces[1].patch],
            guess: [None; 2],
        }
    }

    /// The feet of both faces over `t` and at its midpoint (`None` if not
    /// proved there).
    fn feet(&mut self, t: Interval) -> Result<Option<[Foot; 2]>, Error> {
        let mut out = Vec::with_capacity(2);
        for k in 0..2 {
            match foot(self.curve, self.faces[k], t, self.guess[k])? {
                Some(f) => {
                    self.guess[k] = Some(f.uv.map(|x| x.mid()));
                    out.push(f);
                }
                None => {
                    self.guess[k] = None;
                    return Ok(None);
                }
            }
        }
        Ok(out.try_into().ok())
    }

    /// The [`Local`] of the piece `t`, `None` when a foot is not proved.
    ///
    /// # Errors
    ///
    /// Those of the jets ([`ICurve::jet`], [`IPatch::jet`]).
    pub fn local(&mut self, t: Interval) -> Result<Option<Local>, Error> {
        let m = Interval::point(t.mid());
        let (Some(mid), Some(over)) = (self.feet(m)?, self.feet(t)?) else {
            return Ok(None);
        };
        Ok(Some(Local {
            c_mid: self.curve.jet(m)?,
            c_over: self.curve.jet(t)?,
            dt: t.sub(&m),
            over,
            mid,
        }))
    }
}
