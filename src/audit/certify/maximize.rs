//! Branch and bound for the maximum of a quantity along an edge.
//!
//! The edge's parameter interval is split into pieces `T`. For each piece
//! the caller proves an upper bound of the quantity on all of `T` and a
//! lower bound of its value at one point of `T` (see [`Bound`]). The piece
//! with the greatest upper bound `U` is split in two until
//! `U − L ≤ rel · U + abs`, `L` the greatest lower bound found: then the
//! maximum lies in `[L, U]`, attained in the hull of the pieces whose upper
//! bound reaches `L`. Every piece examined is charged to the work budget
//! ([`crate::limits::charge`]); when it runs out, the enclosure proved so
//! far is returned, marked not tight.

use crate::algebra::Interval;
use crate::error::Error;
use crate::limits;
use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// The tightness asked of an enclosure `[lo, hi]`: `hi − lo ≤ rel·hi + abs`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Target {
    /// Relative width.
    pub rel: f64,
    /// Absolute width (in the quantity's unit).
    pub abs: f64,
}

/// What the caller proves on one piece `T` of the edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bound {
    /// At least the quantity at every parameter of `T`.
    pub upper: f64,
    /// At most the quantity at some parameter of `T`.
    pub lower: f64,
}

/// A proved enclosure of a maximum along an edge.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Enclosure {
    /// The true maximum is at least this.
    pub lo: f64,
    /// The true maximum is at most this.
    pub hi: f64,
    /// The edge parameters where the maximum may be attained (it is
    /// attained somewhere in this interval).
    pub at: Interval,
    /// Whether the target width was reached (else the pieces became too
    /// short to split: `[lo, hi]` is still proved, only wider).
    pub tight: bool,
}

impl Enclosure {
    /// The greater of two maxima (over two parts of an edge).
    pub fn max(self, o: Enclosure) -> Enclosure {
        let at = if o.hi > self.hi { o.at } else { self.at };
        Enclosure {
            lo: self.lo.max(o.lo),
            hi: self.hi.max(o.hi),
            at,
            tight: self.tight && o.tight,
        }
    }
}

/// Pieces shorter than this are not split.
const MIN_PIECE: f64 = 1e-12;

/// Work units charged per piece examined (calibrated: a piece costs about
/// as much as a few hundred small exact operations).
pub const WORK_PER_PIECE: u64 = 2_000;

/// The maximum over `t ∈ range` of a quantity bounded piecewise by `bound`
/// (`Ok(None)`: not proved on this piece; it is split).
///
/// # Errors
///
/// [`Error::Limit`] when the work budget runs out before every piece has
/// a finite upper bound (once they have, running out returns the
/// enclosure proved so far, `tight: false`); [`Error::Domain`] when
/// a piece too short to split is still not proved; the errors of `bound`.
pub fn maximize(
    range: Interval,
    target: Target,
    bound: impl FnMut(Interval) -> Result<Option<Bound>, Error>,
) -> Result<Enclosure, Error> {
    maximize_until(range, target, |_, _| false, bound)
}

/// [`maximize`], stopping early, with `tight: false`, as soon as
/// `decided(U, L)` holds for the greatest upper bound `U` and the greatest
/// lower bound `L` (e.g. `U` below a tolerance, or `L` above it: the
/// verdict needs no tighter enclosure); asked only once `U` is finite.
///
/// # Errors
///
/// Those of [`maximize`].
pub fn maximize_until(
    range: Interval,
    target: Target,
    decided: impl Fn(f64, f64) -> bool,
    mut bound: impl FnMut(Interval) -> Result<Option<Bound>, Error>,
) -> Result<Enclosure, Error> {
    let (e, _) = maximize_over(&[range], target, decided, |_, t| bound(t))?;
    Ok(e)
}

/// [`maximize_until`] of one quantity over several ranges at once (the
/// Bézier pieces of an edge): one branch and bound whose pieces are those
/// of every range, `bound(k, T)` bounding piece `T` of range `k`, so the
/// splitting goes where the greatest upper bound is, whichever range it
/// is in, and a range whose bound is under what another already proves is
/// not refined at all. Returns the enclosure of the maximum over all the
/// ranges and the range of the greatest upper bound (`at` is in it: the
/// hull of that range's pieces whose upper bound reaches `L`).
///
/// # Errors
///
/// Those of [`maximize`].
pub fn maximize_over(
    ranges: &[Interval],
    target: Target,
    decided: impl Fn(f64, f64) -> bool,
    mut bound: impl FnMut(usize, Interval) -> Result<Option<Bound>, Error>,
) -> Result<(Enclosure, usize), Error> {
    let mut pieces: BinaryHeap<Piece> = BinaryHeap::new();
    let mut lower = f64::NEG_INFINITY;
    let mut todo: Vec<Piece> = ranges
        .iter()
        .enumerate()
        .rev()
        .map(|(range, &t)| Piece {
            upper: f64::INFINITY,
            t,
            range,
        })
        .collect();
    loop {
        while let Some(parent) = todo.pop() {
            if let Err(e) = limits::charge("a certified measure along an edge", WORK_PER_PIECE) {
                // Out of work: what is proved so far still stands, wider.
                pieces.push(parent);
                pieces.extend(todo.drain(..));
                return enclosure(&pieces, lower, false).ok_or(e);
            }
            let t = parent.t;
            let upper = match bound(parent.range, t)? {
                Some(b) => {
                    lower = lower.max(b.lower);
                    b.upper.min(parent.upper)
                }
                None if t.width() < MIN_PIECE => {
                    return Err(Error::Domain(format!(
                        "the foot points near edge parameter {:e} cannot be proved (the edge leaves the face or meets it at a singular point)",
                        t.mid()
                    )))
                }
                None => parent.upper,
            };
            pieces.push(Piece { upper, ..parent });
        }
        let top = *pieces.peek().expect("at least one piece");
        let (upper, t) = (top.upper, top.t);
        let done = upper.is_finite() && upper - lower <= target.rel * upper + target.abs;
        if done || (upper.is_finite() && decided(upper, lower)) || t.width() < MIN_PIECE {
            return Ok(enclosure(&pieces, lower, done).expect("a finite upper bound"));
        }
        pieces.pop();
        let m = t.mid();
        todo.push(Piece {
            t: Interval { lo: t.lo, hi: m },
            ..top
        });
        todo.push(Piece {
            t: Interval { lo: m, hi: t.hi },
            ..top
        });
    }
}

/// The enclosure the pieces prove: the greatest upper bound, the greatest
/// lower bound, where (in the range of the greatest upper bound), and that
/// range; `None` while some piece is unbounded.
fn enclosure(pieces: &BinaryHeap<Piece>, lower: f64, tight: bool) -> Option<(Enclosure, usize)> {
    let top = pieces.peek()?;
    if !top.upper.is_finite() {
        return None;
    }
    let at = pieces
        .iter()
        .filter(|p| p.range == top.range && p.upper >= lower)
        .fold(top.t, |a, p| a.hull(&p.t));
    Some((
        Enclosure {
            lo: lower.max(0.0),
            hi: top.upper,
            at,
            tight,
        },
        top.range,
    ))
}

/// A piece `t` of range `range` ordered by its upper bound (greatest
/// first).
#[derive(Clone, Copy, Debug)]
struct Piece {
    upper: f64,
    t: Interval,
    range: usize,
}

impl PartialEq for Piece {
    fn eq(&self, o: &Piece) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}

impl Eq for Piece {}

impl PartialOrd for Piece {
    fn partial_cmp(&self, o: &Piece) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Ord for Piece {
    fn cmp(&self, o: &Piece) -> Ordering {
        self.upper.total_cmp(&o.upper)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The constant `q(t) = 2` on `[0, 1]` (a cylinder's curvature),
    /// bounded on `[a, b]` by `2 + (b − a)` above (an overestimate that
    /// narrows linearly, like an interval extension's) and `2` below;
    /// counts the pieces.
    fn linear(count: &mut u32) -> impl FnMut(Interval) -> Result<Option<Bound>, Error> + '_ {
        move |t| {
            *count += 1;
            Ok(Some(Bound {
                upper: 2.0 + (t.hi - t.lo),
                lower: 2.0,
            }))
        }
    }

    const UNIT: Interval = Interval { lo: 0.0, hi: 1.0 };
    const TARGET: Target = Target {
        rel: 1e-3,
        abs: 0.0,
    };

    #[test]
    fn a_lower_bound_over_the_tolerance_stops_the_refinement_early() {
        let (mut full, mut early) = (0, 0);
        let tight = maximize(UNIT, TARGET, linear(&mut full)).unwrap();
        let failed = maximize_until(
            UNIT,
            TARGET,
            |u, l| l > 1.5 && u - l <= 1e-2 * u,
            linear(&mut early),
        )
        .unwrap();
        assert!(tight.tight && tight.hi - tight.lo <= 1e-3 * tight.hi);
        assert!(!failed.tight && failed.lo > 1.5 && failed.hi - failed.lo <= 1e-2 * failed.hi);
        for e in [tight, failed] {
            assert!(e.lo <= 2.0 && 2.0 <= e.hi, "{e:?}");
        }
        assert!(early * 5 < full, "{early} pieces against {full}");
    }

    /// Two ranges, the constants 1 and 2 bounded like [`linear`]: once
    /// the second proves a lower bound of 2, the first (upper bound 2 on
    /// the whole range) is never split; the maximum is the second's.
    #[test]
    fn a_range_under_another_s_lower_bound_is_not_refined() {
        let mut calls = [0u32; 2];
        let (e, range) = maximize_over(
            &[UNIT, UNIT],
            TARGET,
            |u, l| l > 1.5 && u - l <= 1e-2 * u,
            |k, t| {
                calls[k] += 1;
                let c = (k + 1) as f64;
                Ok(Some(Bound {
                    upper: c + (t.hi - t.lo),
                    lower: c,
                }))
            },
        )
        .unwrap();
        assert_eq!(range, 1);
        assert!(
            e.lo <= 2.0 && 2.0 <= e.hi && e.hi - e.lo <= 1e-2 * e.hi,
            "{e:?}"
        );
        assert_eq!(calls[0], 1, "{calls:?}");
        assert!(calls[1] > 1, "{calls:?}");
    }

    #[test]
    fn decided_is_not_asked_before_every_piece_is_bounded() {
        let mut first = true;
        let e = maximize_until(
            UNIT,
            TARGET,
            |_, _| true,
            |t| {
                let proved = !std::mem::take(&mut first);
                Ok(proved.then_some(Bound {
                    upper: 1.0 + t.hi,
                    lower: 1.0 + t.lo,
                }))
            },
        )
        .unwrap();
        assert!(e.hi.is_finite() && e.lo <= 2.0 && 2.0 <= e.hi, "{e:?}");
    }
}
