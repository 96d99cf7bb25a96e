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
//! torus      s = ε(q − r), q = √((ρ − c)² + h²)  n̂ = ε((ρ − c)a/ρ, (ρ − c)b/ρ, h)/q
//! ```
//!
//! Each surface is a surface of revolution (the plane trivially), so the
//! distance from a point is the distance, in the point's meridian
//! half-plane `ρ ≥ 0`, from the meridian section: a line (cylinder, cone:
//! two lines, the nearer being the one with `m` of the sign shown), a
//! circle (sphere), arcs of the two circles of radius `r` centred at
//! `ρ = ±R` (torus). For a ring torus (`r < R`) the nearer is the one
//! centred at `c = R` (their centres are `2R > 2r` apart), `ε = 1`. When
//! `r ≥ R` the torus intersects itself: the part of the circle at `c = R`
//! with `ρ ≥ 0` is the outer part (the apple), that of the circle at
//! `c = −R` the inner part (the lemon, when `r > R`), whose ISO normal
//! `σ_u × σ_v = (R + r cos v)·r·(cos v, sin v)` (in `(ρ, h)`, with
//! `R + r cos v < 0` there) points into its circle: `ε = −1`. The formula
//! holds where the foot point `c + r(ρ − c)/q` has `ρ > 0` (it is then on
//! the part). [`ISurface::nearer_part`] picks the part.
//!
//! `n̂` is `∇s`, it points the way of [`Implicit::gradient`], and along a
//! curve `P(t)`: `d s(P(t))/dt = n̂·P'(t)` — the slope [`super::gap`] uses.
//! A cone whose slope is known only within a bound ([`ClosedForm`]) is
//! enclosed with its slope widened by the bound: the formulas hold for
//! every slope in the interval, so they enclose the true cone's.
//!
//! The normal's Jacobian `J = ∂n̂/∂P` ([`DistanceField::normal_jacobian`])
//! is a sum of rank-one terms in the unit vectors `e = (a, b, 0)/ρ`,
//! `e_φ = (−b, a, 0)/ρ` (around the axis) and, for the torus,
//! `t̂ = (h/q) e − c ẑ` with `c = (ρ − C)/q` (along the meridian circle of
//! centre `ρ = C`, `C = ±R`):
//!
//! ```text
//! plane      J = 0
//! cylinder   J = e_φ e_φᵀ / ρ
//! sphere     J = (I − n̂ n̂ᵀ) / |P − C|
//! cone       J = e_φ e_φᵀ / (ρ √(1 + k²))
//! torus      J = ε(c e_φ e_φᵀ / ρ + t̂ t̂ᵀ / q)
//! ```
//!
//! (`n̂` turns about the axis at the rate `1/ρ` times its radial part, and
//! in the meridian plane about the meridian's centre of curvature.)

use super::field::{DistanceField, IMat3};
use super::gap::abs_lower;
use super::ivec::{add, dot, scale, sub, IVec};
use super::normal_path::ScaledVec;
use super::Enclose;
use crate::algebra::interval_bernstein::{mul, Scaled};
use crate::algebra::{Interval, Scalar};
use crate::analytic::{ClosedForm, Implicit};

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
    Cylinder {
        radius: Interval,
    },
    Sphere {
        radius: Interval,
    },
    Cone {
        radius: Interval,
        slope: Interval,
    },
    /// The part on the circles of radius `minor` centred at `ρ = centre`
    /// (module docs), with `ε = 1` when `outward`.
    Torus {
        major: Interval,
        minor: Interval,
        centre: Interval,
        outward: bool,
    },
}

/// The slack of a normal path off the foot normal by at most the sine
/// `sine` (`sin θ ≤ |e|/|v|` for a path `v + e`): `θ ≤ (π/2) sin θ` below a
/// right angle (`sin` is concave there), and the angle is below a right
/// angle when `|e| < |v|`. `None` from a sine of 1 on.
fn slack_of(sine: f64) -> Option<f64> {
    let slack = Interval::point(std::f64::consts::FRAC_PI_2)
        .mul(&Interval::point(sine))
        .hi;
    (sine < 1.0 && slack.is_finite()).then_some(slack)
}

/// `f · k` for each coefficient of a scaled form.
fn times(f: &[Interval], k: &Interval) -> Scaled {
    f.iter().map(|v| v.mul(k)).collect()
}

/// `a² + b²` of two scaled forms (`W²ρ²` from `W a`, `W b`).
fn squares(a: &Scaled, b: &Scaled) -> Scaled {
    mul(a, a)
        .iter()
        .zip(&mul(b, b))
        .map(|(x, y)| x.add(y))
        .collect()
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
    /// Enclose `s` (a torus: its ring, or when `r ≥ R` its outer part;
    /// see [`ISurface::nearer_part`]); `None` for a torus with `R < 0`.
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
                if major.lo < 0.0 {
                    return None;
                }
                Kind::Torus {
                    major,
                    minor,
                    centre: major,
                    outward: true,
                }
            }
        };
        let f = s.frame();
        Some(ISurface {
            kind,
            origin: enclose_all(&f.origin),
            axes: [enclose_all(&f.x), enclose_all(&f.y), enclose_all(&f.z)],
        })
    }

    /// Enclose a surface known by its [`ClosedForm`]: a cone whose slope
    /// is within `slope_error` of the true `tan α` gets the slope interval
    /// widened by that bound (outward), so it encloses the true cone's
    /// slope. The entity's orientation (`reversed`) is the caller's.
    pub fn enclosing<T: Scalar + Enclose>(form: &ClosedForm<T>) -> Option<ISurface> {
        let mut s = ISurface::new(&form.implicit)?;
        if let (Kind::Cone { slope, .. }, Some(e)) = (&mut s.kind, &form.slope_error) {
            let e = Interval::enclose(e).hi;
            *slope = slope.add(&Interval { lo: -e, hi: e });
        }
        Some(s)
    }

    /// For a torus with `r > R`, the part (apple or lemon) nearer the box
    /// `p` when that is proved (`|q' − r| < |q − r|` over `p`, with `q`,
    /// `q'` the distances from the circles at `ρ = R` and `ρ = −R`): the
    /// distance from the whole surface near `p`. Otherwise `self`.
    pub fn nearer_part(self, p: &[Interval]) -> ISurface {
        let Kind::Torus { major, minor, .. } = self.kind else {
            return self;
        };
        if minor.lo <= major.hi {
            return self;
        }
        let (rho, h) = self.meridian(p);
        let off = |c: Interval| {
            let q = rho.sub(&c).sqr().add(&h.sqr()).sqrt()?;
            Some(q.sub(&minor))
        };
        let lemon = matches!((off(major), off(major.neg())),
            (Some(apple), Some(lemon)) if lemon.mag() < abs_lower(&apple));
        let (centre, outward) = if lemon {
            (major.neg(), false)
        } else {
            (major, true)
        };
        ISurface {
            kind: Kind::Torus {
                major,
                minor,
                centre,
                outward,
            },
            ..self
        }
    }

    /// `(ρ, h)` of the box `p`.
    fn meridian(&self, p: &[Interval]) -> (Interval, Interval) {
        let [a, b, h] = self.local(p);
        let rho = a.sqr().add(&b.sqr()).sqrt().expect("a sum of squares");
        (rho, h)
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

    /// The foot normal `n̂(C(t))` times a positive polynomial, along the
    /// curve whose homogeneous coordinates `(X, W)` are the scaled forms
    /// `c` ([`super::normal_path`]), with the angle it may be off by. With
    /// `r = X − W o` (`o` the frame's origin or the sphere's centre) and
    /// `(a, b, h)` its frame coordinates: the plane's `ẑ`, the cylinder's
    /// radial part `a x̂ + b ŷ` (`W ρ n̂`) and the sphere's `r`
    /// (`W |P − C| n̂`), exactly. The cone's `n̂ ∝ T = (a, b, −σkρ)`
    /// (`σ` the sign of `m = R + k h` over the piece, `ρ = √(a² + b²)`) is
    /// not a polynomial; `N = σ (2ma, 2mb, −k(m² + ρ²))` (times `W²`) is,
    /// and `N = 2|m| T − σ k (|m| − ρ)² ẑ`: off `T` only in the square of
    /// `|ρ − |m|| = |s| √(1 + k²)`, so `sin θ ≤ |k| g² √(1 + k²) / (2|m|ρ)`
    /// for a curve within `g` of the cone whose points over the piece are
    /// the box `over` (the slack is `π/2` times that: `θ ≤ (π/2) sin θ`
    /// below a right angle). Until 2026-11-29 the path was
    /// `(a, b, −km)`, off by up to `|k| √(1 + k²) g / ρ`: linear in the
    /// gap, `1.3·10⁻⁶` rad on creases of `tail_section_asm.stp` whose
    /// cones lie `5·10⁻⁵` mm off their edges, more than the `1 %` of a
    /// `7·10⁻⁵` rad crease its angle is refined to, so the refinement ran
    /// to its work cap. The torus's foot normal (on the part of the circles
    /// of radius `r` about `ρ = R`, orientation `ε`) is
    /// `ε ((ρ − R)a/ρ, (ρ − R)b/ρ, h)/q`, `q` the distance from the circle;
    /// with `p₀` the middle of `ρ` over the box,
    /// `N = ε ((p₀² + ρ² − 2p₀R)a, (p₀² + ρ² − 2p₀R)b, (p₀² + ρ²)h)`
    /// (times `W³`) is `2p₀ρ q n̂ + ε (ρ − p₀)² (a, b, h)`, so
    /// `sin θ ≤ (ρ − p₀)² √(ρ² + h²) / (2 p₀ ρ q)`: the square of the spread
    /// of `ρ` over the piece, whatever the gap (none before 2026-11-29: the
    /// torus's angles were bounded by mean-value forms, 58 648 pieces for
    /// the 48 cone–torus edges of `tail_section_asm.stp`, 3 792 now).
    /// `None` for a piece that reaches the axis, the circle, or the foot
    /// off its part, or a cone piece that reaches its axis or the apex's
    /// plane.
    pub fn normal_along(
        &self,
        c: &[Scaled],
        over: &[Interval],
        g: f64,
    ) -> Option<(ScaledVec, f64)> {
        let r = |k: usize| -> Scaled {
            c[k].iter()
                .zip(&c[3])
                .map(|(x, w)| x.sub(&w.mul(&self.origin[k])))
                .collect()
        };
        let r = [r(0), r(1), r(2)];
        let along = |e: &IVec| -> Scaled {
            (0..c[3].len())
                .map(|i| (0..3).fold(Interval::point(0.0), |a, k| a.add(&r[k][i].mul(&e[k]))))
                .collect()
        };
        let frame = |v: [&Scaled; 3]| -> ScaledVec {
            [0, 1, 2].map(|k| {
                (0..v[0].len())
                    .map(|i| {
                        (0..3).fold(Interval::point(0.0), |acc, j| {
                            acc.add(&v[j][i].mul(&self.axes[j][k]))
                        })
                    })
                    .collect()
            })
        };
        match self.kind {
            Kind::Plane => Some(([0, 1, 2].map(|k| vec![self.axes[2][k]]), 0.0)),
            Kind::Cylinder { .. } => {
                let zero = vec![Interval::point(0.0); c[3].len()];
                Some((
                    frame([&along(&self.axes[0]), &along(&self.axes[1]), &zero]),
                    0.0,
                ))
            }
            Kind::Sphere { .. } => Some((r, 0.0)),
            Kind::Cone { radius, slope } => {
                let [a, b, h] = self.local(over);
                let rho = a.sqr().add(&b.sqr()).sqrt()?.lo;
                let m = radius.add(&slope.mul(&h));
                let (sign, least_m) = if m.lo > 0.0 {
                    (1.0, m.lo)
                } else if m.hi < 0.0 {
                    (-1.0, -m.hi)
                } else {
                    return None;
                };
                if rho <= 0.0 {
                    return None;
                }
                let (x, y) = (along(&self.axes[0]), along(&self.axes[1]));
                let m: Scaled = along(&self.axes[2])
                    .iter()
                    .zip(&c[3])
                    .map(|(h, w)| radius.mul(w).add(&slope.mul(h)))
                    .collect();
                let twice = Interval::point(2.0 * sign);
                let factor = slope.mul(&Interval::point(sign)).neg();
                let vertical: Scaled = mul(&m, &m)
                    .iter()
                    .zip(&squares(&x, &y))
                    .map(|(mm, q)| mm.add(q).mul(&factor))
                    .collect();
                let norm = Interval::point(1.0).add(&slope.sqr()).sqrt()?;
                let gap = Interval::point(g);
                let sine = Interval::point(slope.mag())
                    .mul(&gap.sqr())
                    .mul(&norm)
                    .div(&Interval::point(2.0 * least_m).mul(&Interval::point(rho)))?
                    .hi;
                let n = frame([
                    &times(&mul(&m, &x), &twice),
                    &times(&mul(&m, &y), &twice),
                    &vertical,
                ]);
                Some((n, slack_of(sine)?))
            }
            Kind::Torus {
                minor,
                centre,
                outward,
                ..
            } => {
                let [a, b, h] = self.local(over);
                let rho = a.sqr().add(&b.sqr()).sqrt()?;
                let radial = rho.sub(&centre);
                let q = radial.sqr().add(&h.sqr()).sqrt()?;
                if rho.lo <= 0.0 || q.lo <= 0.0 {
                    return None;
                }
                // The foot point's ρ: on the part only when positive.
                if centre.add(&minor.mul(&radial.div(&q)?)).lo <= 0.0 {
                    return None;
                }
                let p0 = Interval::point(rho.mid());
                let (x, y, z) = (
                    along(&self.axes[0]),
                    along(&self.axes[1]),
                    along(&self.axes[2]),
                );
                let ww = mul(&c[3], &c[3]);
                let base: Scaled = ww
                    .iter()
                    .zip(&squares(&x, &y))
                    .map(|(w2, q)| w2.mul(&p0.sqr()).add(q))
                    .collect();
                let twice = Interval::point(2.0).mul(&p0).mul(&centre);
                let across: Scaled = base
                    .iter()
                    .zip(&ww)
                    .map(|(s, w2)| s.sub(&w2.mul(&twice)))
                    .collect();
                let e = Interval::point(if outward { 1.0 } else { -1.0 });
                let n = frame([
                    &times(&mul(&across, &x), &e),
                    &times(&mul(&across, &y), &e),
                    &times(&mul(&base, &z), &e),
                ]);
                let off = rho.sub(&p0).mag();
                let reach = rho.sqr().add(&h.sqr()).sqrt()?;
                let sine = Interval::point(off)
                    .sqr()
                    .mul(&reach)
                    .div(&Interval::point(2.0).mul(&p0).mul(&rho).mul(&q))?
                    .hi;
                Some((n, slack_of(sine)?))
            }
        }
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
            Kind::Torus {
                minor,
                centre,
                outward,
                ..
            } => {
                let r = rho()?;
                let radial = r.sub(&centre);
                let q = radial.sqr().add(&h.sqr()).sqrt()?;
                if q.lo <= 0.0 {
                    return None;
                }
                let c = radial.div(&q)?;
                // The foot point's ρ: on the part only when positive.
                if centre.add(&minor.mul(&c)).lo <= 0.0 {
                    return None;
                }
                let e = Interval::point(if outward { 1.0 } else { -1.0 });
                (
                    q.sub(&minor).mul(&e),
                    [
                        c.mul(&a.div(&r)?).mul(&e),
                        c.mul(&b.div(&r)?).mul(&e),
                        h.div(&q)?.mul(&e),
                    ],
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
            Kind::Torus {
                centre, outward, ..
            } => {
                let r = rho()?;
                let radial = r.sub(&centre);
                let q = radial.sqr().add(&h.sqr()).sqrt()?;
                let c = radial.div(&q)?;
                let hq = h.div(&q)?;
                let e = Interval::point(if outward { 1.0 } else { -1.0 });
                let t = [hq.mul(&a.div(&r)?), hq.mul(&b.div(&r)?), c.neg()];
                add_outer(&mut j, &c.div(&r)?.mul(&e), &self.world(&around(&r)?));
                add_outer(&mut j, &inv(&q)?.mul(&e), &self.world(&t));
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::Roots;
    use crate::algebra::RealAlgebraic;
    use crate::analytic::{cone_slope, AngleUnit, Frame};
    use num_rational::BigRational;

    fn frame<T: Scalar>() -> Frame<T> {
        let (o, l) = (T::zero(), T::one());
        Frame::from_axes(
            vec![o.clone(), o.clone(), o.clone()],
            vec![l.clone(), o.clone(), o.clone()],
            vec![o.clone(), o, l],
        )
    }

    fn at(x: f64, y: f64, z: f64) -> Vec<Interval> {
        vec![Interval::point(x), Interval::point(y), Interval::point(z)]
    }

    fn holds(i: Interval, x: f64, width: f64) {
        assert!(i.lo <= x && x <= i.hi && i.hi - i.lo < width, "{i:?} ∌ {x}");
    }

    /// The 30° cone of radius 1 at `h = 0`: exactly (slope `√3/3`), and
    /// from the decimal angle "30." in rationals (no `√3`: the slope is a
    /// dyadic within a proved bound). At `(3, 0, 0)` the distance from the
    /// line `ρ = 1 + h/√3` of the meridian plane is `2/√(4/3) = √3`, the
    /// foot normal `(1, 0, −1/√3)/√(4/3) = (√3/2, 0, −1/2)`.
    #[test]
    fn a_cone_from_a_decimal_angle_encloses_the_exact_cone() {
        let exact = Implicit::Cone {
            frame: frame::<RealAlgebraic>(),
            radius: RealAlgebraic::from_i64(1),
            slope: RealAlgebraic::from_i64(3).nth_root(2).unwrap() / RealAlgebraic::from_i64(3),
        };
        let s = cone_slope::<BigRational>("30.", &AngleUnit::Degree).unwrap();
        assert!(!s.exact);
        let form = ClosedForm {
            implicit: Implicit::Cone {
                frame: frame::<BigRational>(),
                radius: BigRational::from_integer(1.into()),
                slope: s.tan,
            },
            slope_error: Some(s.error),
            reversed: false,
        };
        let p = at(3.0, 0.0, 0.0);
        let e = ISurface::new(&exact).unwrap().distance(&p).unwrap();
        let d = ISurface::enclosing(&form).unwrap().distance(&p).unwrap();
        let root3 = 3f64.sqrt();
        for x in [&e, &d] {
            holds(x.signed, root3, 1e-12);
            holds(x.normal[0], root3 / 2.0, 1e-12);
            holds(x.normal[2], -0.5, 1e-12);
        }
        assert!(d.signed.lo <= e.signed.lo && e.signed.hi <= d.signed.hi);
    }

    /// The cone `ρ = 1 + h/2` along the line `(1 + t/2 + δ, 0, t)`,
    /// `t ∈ [0, 1]`: radially `δ` outside its generator, so at distance
    /// `g = δ/√(1 + ¼)` from it, where the foot normal is
    /// `(1, 0, −½)/√(1 + ¼)` all along (independently: the generator's
    /// direction `(½, 0, 1)` is perpendicular to it). The normal path is
    /// exact on the generator (`δ = 0`) and within its slack off it, which
    /// is of the order of `δ²`.
    #[test]
    fn a_cone_s_normal_path_is_within_its_slack() {
        use crate::algebra::interval_bernstein::scale as scaled;
        let cone = ISurface::new(&Implicit::Cone {
            frame: frame::<BigRational>(),
            radius: BigRational::from_integer(1.into()),
            slope: BigRational::new(1.into(), 2.into()),
        })
        .unwrap();
        let normal = [1.0, 0.0, -0.5].map(|x| vec![Interval::point(x)]);
        for delta in [0.0, 1e-3] {
            let x0 = 1.0 + delta;
            let line: Vec<Scaled> = [[x0, x0 + 0.5], [0.0, 0.0], [0.0, 1.0], [1.0, 1.0]]
                .iter()
                .map(|c| scaled(&c.map(Interval::point)))
                .collect();
            let over = vec![
                Interval {
                    lo: x0,
                    hi: x0 + 0.5,
                },
                Interval::point(0.0),
                Interval { lo: 0.0, hi: 1.0 },
            ];
            let g = delta / 1.25f64.sqrt() * (1.0 + 1e-12);
            let (path, slack) = cone.normal_along(&line, &over, g).unwrap();
            let (upper, _) = super::super::normal_path::angle_between(&path, &normal).unwrap();
            if delta == 0.0 {
                assert!(slack < 1e-300 && upper < 1e-14, "{upper} {slack}");
            } else {
                // Off by kδ²/(2mρ(1 + k²)) = 2.0·10⁻⁷ at t = 0 (m = 1,
                // ρ = 1 + δ: the error kδ² along ẑ, seen at the angle
                // whose cosine is 1/√(1 + k²)); the slack, (π/2)·k√(1 + k²)·g²/(2mρ) with
                // g² = δ²/(1 + k²) and the least m and ρ of the box,
                // 3.5·10⁻⁷, covers it (the path of before, (a, b, −km),
                // was off by 4·10⁻⁴).
                assert!(
                    upper > 1.99e-7 && upper <= slack && slack < 3.6e-7,
                    "{upper} {slack}"
                );
            }
        }
    }

    fn torus(major: i64, minor: i64) -> ISurface {
        ISurface::new(&Implicit::Torus {
            frame: frame::<BigRational>(),
            major: BigRational::from_integer(major.into()),
            minor: BigRational::from_integer(minor.into()),
        })
        .unwrap()
    }

    /// The torus `R = 2, r = 1` along the segment from `(2.8, 0.1, 0.3)` to
    /// `(2.9, 0.4, 0.5)`, off the surface: at eleven points the path's
    /// direction is within its slack of the foot normal computed
    /// independently in `f64` (`((ρ − R)a/ρ, (ρ − R)b/ρ, h)/q`, the
    /// direction from the nearest point of the core circle) and more than
    /// a tenth of it away at one of them, and the slack
    /// of the segment's first half is under a third of the whole's (it
    /// shrinks like the square of the spread of `ρ`).
    #[test]
    fn a_torus_normal_path_is_within_its_slack() {
        let torus = torus(2, 1);
        let path = |p0: [f64; 3], p1: [f64; 3]| {
            let c: Vec<Scaled> = (0..3)
                .map(|k| vec![Interval::point(p0[k]), Interval::point(p1[k])])
                .chain(std::iter::once(vec![Interval::point(1.0); 2]))
                .collect();
            let over: Vec<Interval> = (0..3)
                .map(|k| Interval {
                    lo: p0[k].min(p1[k]),
                    hi: p0[k].max(p1[k]),
                })
                .collect();
            torus.normal_along(&c, &over, 0.0).unwrap()
        };
        let (p0, p1) = ([2.8, 0.1, 0.3], [2.9, 0.4, 0.5]);
        let (n, slack) = path(p0, p1);
        let mut most = 0.0_f64;
        for i in 0..=10 {
            let t = i as f64 / 10.0;
            let p: Vec<f64> = (0..3).map(|k| p0[k] + t * (p1[k] - p0[k])).collect();
            let rho = p[0].hypot(p[1]);
            let q = (rho - 2.0).hypot(p[2]);
            let foot = [
                (rho - 2.0) * p[0] / rho / q,
                (rho - 2.0) * p[1] / rho / q,
                p[2] / q,
            ];
            let value: Vec<f64> = n
                .iter()
                .map(|f| {
                    let d = f.len() - 1;
                    f.iter()
                        .enumerate()
                        .map(|(j, x)| x.mid() * t.powi(j as i32) * (1.0 - t).powi((d - j) as i32))
                        .sum()
                })
                .collect();
            let cross = [
                value[1] * foot[2] - value[2] * foot[1],
                value[2] * foot[0] - value[0] * foot[2],
                value[0] * foot[1] - value[1] * foot[0],
            ];
            let dot: f64 = (0..3).map(|k| value[k] * foot[k]).sum();
            let angle = (cross.iter().map(|x| x * x).sum::<f64>().sqrt()).atan2(dot);
            assert!(angle <= slack + 1e-12, "t = {t}: {angle} > {slack}");
            most = most.max(angle);
        }
        // The path is really off the normal (at the segment's ends, where
        // ρ is farthest from p₀): 2.1·10⁻⁴ against a slack of 1.3·10⁻³,
        // which also counts the box's extremes of ρ, h and q.
        assert!(most > slack / 10.0, "{most} against {slack}");
        let middle = [0, 1, 2].map(|k| (p0[k] + p1[k]) / 2.0);
        let (_, half) = path(p0, middle);
        assert!(
            slack > 0.0 && slack < 2e-3 && half < slack / 3.0,
            "{half} {slack}"
        );
    }

    /// The spindle torus `R = 1, r = 2`: in the half-plane `y = 0, x > 0`
    /// its apple is the arc of the circle of radius 2 about `(1, 0)`
    /// through `x = 3`, its lemon that of the circle about `(−1, 0)`
    /// through `x = 1`. `(4, 0, 0)` is 1 outside the apple (normal `+x`);
    /// `(1/2, 0, 0)` is 1/2 inside the lemon, whose ISO normal points to
    /// the axis (`−x`), so `s = +1/2` with `n̂ = (−1, 0, 0)`.
    #[test]
    fn a_spindle_torus_apple_and_lemon() {
        let p = at(4.0, 0.0, 0.0);
        let s = torus(1, 2).nearer_part(&p);
        let d = s.distance(&p).unwrap();
        holds(d.signed, 1.0, 1e-12);
        holds(d.normal[0], 1.0, 1e-12);
        let p = at(0.5, 0.0, 0.0);
        let s = torus(1, 2).nearer_part(&p);
        let d = s.distance(&p).unwrap();
        holds(d.signed, 0.5, 1e-12);
        holds(d.normal[0], -1.0, 1e-12);
        // Its gradient's way: F's ∇ at the lemon point (1, 0, 0).
        let g = Implicit::Torus {
            frame: frame::<BigRational>(),
            major: BigRational::from_integer(1.into()),
            minor: BigRational::from_integer(2.into()),
        }
        .gradient(&[1, 0, 0].map(|n| BigRational::from_integer(n.into())));
        assert!(g[0] < BigRational::from_integer(0.into()));
        // The apple's formula is refused where its foot is past the axis:
        // at (0.1, 0, 0.5) the foot is at ρ = 1 + 2(−0.9)/√1.06 < 0.
        assert!(torus(1, 2).distance(&at(0.1, 0.0, 0.5)).is_none());
    }

    /// The horn torus `R = r = 1`: `(3, 0, 1)` is `√5 − 1` from the circle
    /// of radius 1 about `(1, 0)`; near its cusp (the centre) nothing is
    /// proved.
    #[test]
    fn a_horn_torus() {
        let p = at(3.0, 0.0, 1.0);
        let d = torus(1, 1).nearer_part(&p).distance(&p).unwrap();
        holds(d.signed, 5f64.sqrt() - 1.0, 1e-12);
        let near = vec![
            Interval {
                lo: -1e-3,
                hi: 1e-3
            };
            3
        ];
        assert!(torus(1, 1).distance(&near).is_none());
    }

    /// The normal's Jacobian of the spindle torus's lemon and apple against
    /// central differences of [`DistanceField::distance`]'s normal.
    #[test]
    fn a_spindle_torus_normal_jacobian_is_the_normals_derivative() {
        for p in [[0.5, 0.1, 0.2], [3.5, -0.4, 0.6]] {
            let s = torus(1, 2).nearer_part(&at(p[0], p[1], p[2]));
            let j = s.normal_jacobian(&at(p[0], p[1], p[2])).unwrap();
            let d = 1e-6;
            for k in 0..3 {
                let mut lo = p;
                let mut hi = p;
                lo[k] -= d;
                hi[k] += d;
                let n = |q: [f64; 3]| s.distance(&at(q[0], q[1], q[2])).unwrap().normal;
                let (a, b) = (n(lo), n(hi));
                for i in 0..3 {
                    let fd = (b[i].mid() - a[i].mid()) / (2.0 * d);
                    assert!(
                        (j[i][k].mid() - fd).abs() < 1e-6,
                        "{p:?} J[{i}][{k}] {:?} vs {fd}",
                        j[i][k]
                    );
                }
            }
        }
    }
}
