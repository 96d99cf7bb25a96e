//! Distances to an elementary surface and its unit normal, from its closed
//! form ([`Implicit`]), enclosed over a box of points: no foot point needs
//! to be found, because for these surfaces both are explicit.
//!
//! In frame coordinates `(a, b, h)`, `ρ = √(a² + b²)`, the signed distance
//! `s` of a point from the surface and the unit normal `n̂` at its foot
//! point (nearest point) are
//!
//! ```text
//! plane      s = h                              n̂ = (0, 0, 1)
//! cylinder   s = ρ − R                          n̂ = (a/ρ, b/ρ, 0)
//! sphere     s = |P − C| − R                    n̂ = (a, b, h)/|P − C|
//! cone       s = (ρ − m)/√(1 + k²), m = R + k h n̂ = (a/ρ, b/ρ, −k)/√(1 + k²)     (m > 0)
//!            s = (ρ + m)/√(1 + k²)              n̂ = (a/ρ, b/ρ, k)/√(1 + k²)      (m < 0)
//! torus      s = q − r, q = √((ρ − R)² + h²)    n̂ = ((ρ − R)a/ρ, (ρ − R)b/ρ, h)/q  (r < R)
//! ```
//!
//! Each surface is a surface of revolution (the plane trivially), so the
//! distance from a point is the distance, in the point's meridian plane,
//! from the meridian section: a line (cylinder, cone: two lines, the
//! nearer being the one with `m` of the sign shown), a circle (sphere,
//! torus: two circles, the nearer one centred at `ρ = R` because their
//! centres are `2R > 2r` apart). `n̂` is `∇s`, it points the way of
//! [`Implicit::gradient`], and along a curve `P(t)`:
//! `d s(P(t))/dt = n̂·P'(t)` — the slope [`super::gap`] uses.
//!
//! The normal's Jacobian `J = ∂n̂/∂P` ([`DistanceField::normal_jacobian`])
//! is a sum of rank-one terms in the unit vectors `e = (a, b, 0)/ρ`,
//! `e_φ = (−b, a, 0)/ρ` (around the axis) and, for the torus,
//! `t̂ = (h/q) e − c ẑ` with `c = (ρ − R)/q` (along the meridian circle):
//!
//! ```text
//! plane      J = 0
//! cylinder   J = e_φ e_φᵀ / ρ
//! sphere     J = (I − n̂ n̂ᵀ) / |P − C|
//! cone       J = e_φ e_φᵀ / (ρ √(1 + k²))
//! torus      J = c e_φ e_φᵀ / ρ + t̂ t̂ᵀ / q
//! ```
//!
//! (`n̂` turns about the axis at the rate `1/ρ` times its radial part, and
//! in the meridian plane about the meridian's centre of curvature.)

use super::field::{DistanceField, IMat3};
use super::ivec::{add, dot, scale, sub, IVec};
use super::Enclose;
use crate::algebra::{Interval, Scalar};
use crate::analytic::Implicit;

/// An [`Implicit`] surface with enclosed data.
#[derive(Clone, Debug)]
pub struct ISurface {
    kind: Kind,
    origin: IVec,
    axes: [IVec; 3],
}

#[derive(Clone, Copy, Debug)]
enum Kind {
    Plane,
    Cylinder { radius: Interval },
    Sphere { radius: Interval },
    Cone { radius: Interval, slope: Interval },
    Torus { major: Interval, minor: Interval },
}

/// The signed distance and foot normal over a box.
#[derive(Clone, Debug)]
pub struct Distance {
    /// `s`.
    pub signed: Interval,
    /// `n̂` (world coordinates).
    pub normal: IVec,
}

fn enclose_all<T: Enclose>(v: &[T]) -> IVec {
    v.iter().map(Enclose::enclose).collect()
}

impl ISurface {
    /// Enclose `s`; `None` for a torus with `r ≥ R` (its inner part is
    /// not the nearer circle's).
    pub fn new<T: Scalar + Enclose>(s: &Implicit<T>) -> Option<ISurface> {
        let kind = match s {
            Implicit::Plane { .. } => Kind::Plane,
            Implicit::Cylinder { radius, .. } => Kind::Cylinder {
                radius: radius.enclose(),
            },
            Implicit::Sphere { radius, .. } => Kind::Sphere {
                radius: radius.enclose(),
            },
            Implicit::Cone { radius, slope, .. } => Kind::Cone {
                radius: radius.enclose(),
                slope: slope.enclose(),
            },
            Implicit::Torus { major, minor, .. } => {
                let (major, minor) = (major.enclose(), minor.enclose());
                if minor.hi >= major.lo {
                    return None;
                }
                Kind::Torus { major, minor }
            }
        };
        let f = s.frame();
        Some(ISurface {
            kind,
            origin: enclose_all(&f.origin),
            axes: [enclose_all(&f.x), enclose_all(&f.y), enclose_all(&f.z)],
        })
    }

    /// The point's frame coordinates `(a, b, h)`.
    fn local(&self, p: &[Interval]) -> [Interval; 3] {
        let d = sub(p, &self.origin);
        [0, 1, 2].map(|k| dot(&d, &self.axes[k]))
    }

    /// A frame vector in world coordinates.
    fn world(&self, v: &[Interval; 3]) -> IVec {
        add(
            &add(&scale(&self.axes[0], &v[0]), &scale(&self.axes[1], &v[1])),
            &scale(&self.axes[2], &v[2]),
        )
    }
}

impl DistanceField for ISurface {
    /// `s` and `n̂` over the box `p`; `None` where they are not proved
    /// (the box reaches the axis, the centre, the cone's apex plane).
    fn distance(&self, p: &[Interval]) -> Option<Distance> {
        let [a, b, h] = self.local(p);
        let rho = || {
            let r = a.sqr().add(&b.sqr()).sqrt()?;
            (r.lo > 0.0).then_some(r)
        };
        let (signed, [na, nb, nh]) = match self.kind {
            Kind::Plane => (h, [0.0, 0.0, 1.0].map(Interval::point)),
            Kind::Cylinder { radius } => {
                let r = rho()?;
                (
                    r.sub(&radius),
                    [a.div(&r)?, b.div(&r)?, Interval::point(0.0)],
                )
            }
            Kind::Sphere { radius } => {
                let r = a.sqr().add(&b.sqr()).add(&h.sqr()).sqrt()?;
                if r.lo <= 0.0 {
                    return None;
                }
                (r.sub(&radius), [a.div(&r)?, b.div(&r)?, h.div(&r)?])
            }
            Kind::Cone { radius, slope } => {
                let r = rho()?;
                let m = radius.add(&slope.mul(&h));
                let norm = Interval::point(1.0).add(&slope.sqr()).sqrt()?;
                let (s, k) = if m.lo > 0.0 {
                    (r.sub(&m), slope.neg())
                } else if m.hi < 0.0 {
                    (r.add(&m), slope)
                } else {
                    return None;
                };
                (
                    s.div(&norm)?,
                    [
                        a.div(&r)?.div(&norm)?,
                        b.div(&r)?.div(&norm)?,
                        k.div(&norm)?,
                    ],
                )
            }
            Kind::Torus { major, minor } => {
                let r = rho()?;
                let radial = r.sub(&major);
                let q = radial.sqr().add(&h.sqr()).sqrt()?;
                if q.lo <= 0.0 {
                    return None;
                }
                let c = radial.div(&q)?;
                (
                    q.sub(&minor),
                    [c.mul(&a.div(&r)?), c.mul(&b.div(&r)?), h.div(&q)?],
                )
            }
        };
        let normal = self.world(&[na, nb, nh]);
        Some(Distance { signed, normal })
    }

    /// `J` over the box `p` (module docs); `None` where a denominator's
    /// enclosure holds 0.
    fn normal_jacobian(&self, p: &[Interval]) -> Option<IMat3> {
        let [a, b, h] = self.local(p);
        let zero = Interval::point(0.0);
        let rho = || {
            let r = a.sqr().add(&b.sqr()).sqrt()?;
            (r.lo > 0.0).then_some(r)
        };
        let around = |r: &Interval| Some([b.neg().div(r)?, a.div(r)?, zero]);
        let mut j = [[zero; 3]; 3];
        match self.kind {
            Kind::Plane => {}
            Kind::Cylinder { .. } => {
                let r = rho()?;
                add_outer(&mut j, &inv(&r)?, &self.world(&around(&r)?));
            }
            Kind::Sphere { .. } => {
                let r = a.sqr().add(&b.sqr()).add(&h.sqr()).sqrt()?;
                let n = self.world(&[a.div(&r)?, b.div(&r)?, h.div(&r)?]);
                let k = inv(&r)?;
                for (i, row) in j.iter_mut().enumerate() {
                    row[i] = k;
                }
                add_outer(&mut j, &k.neg(), &n);
            }
            Kind::Cone { slope, .. } => {
                let r = rho()?;
                let norm = Interval::point(1.0).add(&slope.sqr()).sqrt()?;
                add_outer(&mut j, &inv(&r.mul(&norm))?, &self.world(&around(&r)?));
            }
            Kind::Torus { major, .. } => {
                let r = rho()?;
                let radial = r.sub(&major);
                let q = radial.sqr().add(&h.sqr()).sqrt()?;
                let c = radial.div(&q)?;
                let hq = h.div(&q)?;
                let t = [hq.mul(&a.div(&r)?), hq.mul(&b.div(&r)?), c.neg()];
                add_outer(&mut j, &c.div(&r)?, &self.world(&around(&r)?));
                add_outer(&mut j, &inv(&q)?, &self.world(&t));
            }
        }
        Some(j)
    }
}

/// `1/x`.
fn inv(x: &Interval) -> Option<Interval> {
    Interval::point(1.0).div(x)
}

/// `j += k u uᵀ`.
fn add_outer(j: &mut IMat3, k: &Interval, u: &[Interval]) {
    for (row, ui) in j.iter_mut().zip(u) {
        let kui = k.mul(ui);
        for (x, uj) in row.iter_mut().zip(u) {
            *x = x.add(&kui.mul(uj));
        }
    }
}
