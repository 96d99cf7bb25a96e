//! The Krawczyk operator for the foot-point system of a point and a patch.
//!
//! The foot point `(u, v)` of a point `c` on a patch `S` makes `S − c`
//! normal to the surface:
//!
//! ```text
//! F(u, v) = ((S − c)·S_u, (S − c)·S_v) = 0,
//! J = [[S_u·S_u + (S − c)·S_uu, S_u·S_v + (S − c)·S_uv],
//!      [S_u·S_v + (S − c)·S_uv, S_v·S_v + (S − c)·S_vv]].
//! ```
//!
//! With `m` the centre of a box `B`, `Y` any real matrix (an approximate
//! inverse of `J(m)`), the Krawczyk operator is
//! `K(B) = m − Y F(m) + (I − Y J(B)) (B − m)`. If `K(B)` lies in the
//! interior of `B`, `F` has exactly one zero in `B`, and it lies in `K(B)`
//! (Moore, Kearfott & Cloud, *Introduction to Interval Analysis*, SIAM
//! 2009, §8.2; Krawczyk 1969). With `c` an enclosure of a whole piece of
//! the edge, the conclusion holds for each of its points at once.

use super::bezier::{IPatch, Jet64, PatchJet};
use crate::algebra::Interval;
use crate::error::Error;

/// A 2 × 2 interval matrix.
pub type IMat = [[Interval; 2]; 2];

/// A parametric surface whose point and derivatives up to order 2 can be
/// enclosed over boxes of its parameters: a Bézier patch ([`IPatch`]) or a
/// B-spline surface ([`super::spline::SplineField`]).
pub trait Jets {
    /// `S` and its derivatives over all `(u, v)` in the box `u × v`.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] where they are not enclosed (a weight's enclosure
    /// reaches 0, the box leaves where the surface is defined).
    fn jet(&self, u: Interval, v: Interval) -> Result<PatchJet, Error>;

    /// `S` and its derivatives near `(u, v)` in `f64` arithmetic: *not*
    /// an enclosure, only Newton's guesses take it. By default the jet
    /// over the point.
    ///
    /// # Errors
    ///
    /// Those of [`Jets::jet`].
    fn approximate_jet(&self, u: f64, v: f64) -> Result<PatchJet, Error> {
        self.jet(Interval::point(u), Interval::point(v))
    }

    /// [`Jets::approximate_jet`] as plain numbers ([`Jet64`]): by
    /// default its midpoints.
    ///
    /// # Errors
    ///
    /// Those of [`Jets::jet`].
    fn jet_f64(&self, u: f64, v: f64) -> Result<Jet64, Error> {
        let j = self.approximate_jet(u, v)?;
        Ok([&j.x, &j.xu, &j.xv, &j.xuu, &j.xuv, &j.xvv].map(|c| [0, 1, 2].map(|k| c[k].mid())))
    }

    /// The parameter domain `[[u₀, u₁], [v₀, v₁]]`.
    fn domain(&self) -> [[f64; 2]; 2];

    /// Where Newton may search (its steps are clamped into it): by
    /// default the domain widened threefold on each side.
    fn reach(&self) -> [[f64; 2]; 2] {
        self.domain()
            .map(|[a, b]| [a - 3.0 * (b - a), b + 3.0 * (b - a)])
    }
}

impl Jets for IPatch {
    fn jet(&self, u: Interval, v: Interval) -> Result<PatchJet, Error> {
        IPatch::jet(self, u, v)
    }

    fn approximate_jet(&self, u: f64, v: f64) -> Result<PatchJet, Error> {
        IPatch::approximate_jet(self, u, v)
    }

    fn jet_f64(&self, u: f64, v: f64) -> Result<Jet64, Error> {
        IPatch::jet_f64(self, u, v)
    }

    fn domain(&self) -> [[f64; 2]; 2] {
        [[0.0, 1.0]; 2]
    }
}

/// `F` and `J` of the foot-point system over a patch jet and point box `c`
/// (`foot_system` in interval arithmetic: enclosures).
pub fn system(s: &PatchJet, c: &[Interval]) -> ([Interval; 2], IMat) {
    foot_system([&s.x, &s.xu, &s.xv, &s.xuu, &s.xuv, &s.xvv], c)
}

/// [`system`] in `f64` at a point of the surface (`s`) and the point `c`:
/// Newton's step, not an enclosure.
pub fn system_f64(s: &Jet64, c: &[f64; 3]) -> ([f64; 2], [[f64; 2]; 2]) {
    foot_system(s.each_ref().map(|a| &a[..]), c)
}

/// The arithmetic of [`foot_system`]: intervals (rounded outward) for
/// enclosures, `f64` for Newton's guesses.
trait Arith: Copy {
    const ZERO: Self;
    fn plus(self, o: Self) -> Self;
    fn minus(self, o: Self) -> Self;
    fn times(self, o: Self) -> Self;
}

impl Arith for Interval {
    const ZERO: Interval = Interval { lo: 0.0, hi: 0.0 };
    fn plus(self, o: Interval) -> Interval {
        self.add(&o)
    }
    fn minus(self, o: Interval) -> Interval {
        self.sub(&o)
    }
    fn times(self, o: Interval) -> Interval {
        self.mul(&o)
    }
}

impl Arith for f64 {
    const ZERO: f64 = 0.0;
    fn plus(self, o: f64) -> f64 {
        self + o
    }
    fn minus(self, o: f64) -> f64 {
        self - o
    }
    fn times(self, o: f64) -> f64 {
        self * o
    }
}

/// The foot-point system `F = ((S − C)·S_u, (S − C)·S_v)` and its Jacobian
/// `J = [[S_u·S_u + (S − C)·S_uu, S_u·S_v + (S − C)·S_uv], [·, S_v·S_v + (S − C)·S_vv]]`
/// from `[S, S_u, S_v, S_uu, S_uv, S_vv]` and the point `c` (dot products
/// summed from 0 in coordinate order, as [`super::ivec::dot`]).
fn foot_system<T: Arith>(s: [&[T]; 6], c: &[T]) -> ([T; 2], [[T; 2]; 2]) {
    let [x, xu, xv, xuu, xuv, xvv] = s;
    let dot = |a: &[T], b: &[T]| {
        a.iter()
            .zip(b)
            .fold(T::ZERO, |acc, (p, q)| acc.plus(p.times(*q)))
    };
    let r: smallvec::SmallVec<[T; 3]> = x.iter().zip(c).map(|(p, q)| p.minus(*q)).collect();
    let cross = dot(xu, xv).plus(dot(&r, xuv));
    let j = [
        [dot(xu, xu).plus(dot(&r, xuu)), cross],
        [cross, dot(xv, xv).plus(dot(&r, xvv))],
    ];
    ([dot(&r, xu), dot(&r, xv)], j)
}

/// The inverse of the real 2 × 2 matrix `m`, if regular.
pub fn inverse(m: &[[f64; 2]; 2]) -> Option<[[f64; 2]; 2]> {
    let [[a, b], [c, d]] = *m;
    let det = a * d - b * c;
    (det.is_finite() && det != 0.0).then(|| [[d / det, -b / det], [-c / det, a / det]])
}

/// The inverse of the real 2 × 2 matrix of midpoints of `j`, if regular.
pub fn mid_inverse(j: &IMat) -> Option<[[f64; 2]; 2]> {
    inverse(&j.map(|r| r.map(|x| x.mid())))
}

/// `K(B)` for the box `b` and point enclosure `c`; `None` when the
/// Jacobian's midpoint is singular.
///
/// # Errors
///
/// Those of [`Jets::jet`].
pub fn krawczyk<S: Jets + ?Sized>(
    patch: &S,
    b: [Interval; 2],
    c: &[Interval],
) -> Result<Option<[Interval; 2]>, Error> {
    let m = b.map(|x| Interval::point(x.mid()));
    let (fm, _) = system(&patch.jet(m[0], m[1])?, c);
    let (_, jb) = system(&patch.jet(b[0], b[1])?, c);
    let d = [0, 1].map(|k| b[k].sub(&m[k]));
    Ok(operator(m, fm, &jb, d))
}

/// Krawczyk's operator about the centre `m` for the offsets `d = B − m`:
/// `m − Y f + (I − Y J)·d`, with `f` (an enclosure of) `F(m)`, `J` the
/// Jacobian enclosed over `B` and `Y` the inverse of `J`'s midpoint
/// matrix; `None` when that is singular.
pub fn operator(
    m: [Interval; 2],
    f: [Interval; 2],
    j: &IMat,
    d: [Interval; 2],
) -> Option<[Interval; 2]> {
    let y = mid_inverse(j)?.map(|r| r.map(Interval::point));
    let k = |i: usize| {
        let newton = (0..2).fold(m[i], |acc, l| acc.sub(&y[i][l].mul(&f[l])));
        (0..2).fold(newton, |acc, k| {
            let ident = Interval::point(if i == k { 1.0 } else { 0.0 });
            let yj = (0..2).fold(ident, |e, l| e.sub(&y[i][l].mul(&j[l][k])));
            acc.add(&yj.mul(&d[k]))
        })
    };
    Some([k(0), k(1)])
}
