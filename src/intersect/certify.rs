//! Certified crossings of two planar curves in `f64` interval arithmetic:
//! the Krawczyk test on parameter boxes, driven by a subdivision that
//! discards box pairs whose control-polygon hulls are disjoint.
//!
//! For `f(s, t) = A(s) − B(t)` on a box `X = S × T` with midpoint `c`, an
//! enclosure `J(X)` of the Jacobian `[A'(S) | −B'(T)]` and any matrix `Y`
//! (here the inverse of `J`'s midpoint),
//!
//! ```text
//! K(X) = c − Y f(c) + (I − Y J(X)) (X − c)
//! K(X) ⊂ int X   ⇒  f has exactly one zero in X, and J is regular there (a transversal crossing)
//! K(X) ∩ X = ∅   ⇒  f has no zero in X
//! ```
//!
//! Every zero of `f` in `X` lies in `K(X)`, so `X ← K(X) ∩ X` shrinks a
//! certified box. Boxes of one subdivision have disjoint interiors and a
//! certified zero is interior, so no crossing is counted twice. A zero on
//! a box edge (an intersection at a curve's end, or exactly on a split
//! line) is never certified: the filter then leaves the case to the exact
//! path, as it does for tangencies and overlaps (singular `J`) and in 3D
//! (where a crossing is not a stable event that intervals can certify).
//!
//! Reference: Krawczyk, *Newton-Algorithmen zur Bestimmung von Nullstellen
//! mit Fehlerschranken*, Computing 4 (1969) 187–201; Moore, Kearfott &
//! Cloud, *Introduction to Interval Analysis* (2009), §8.

use crate::algebra::interval_bernstein::bernstein_product;
use crate::algebra::Interval;
use smallvec::SmallVec;

/// One planar curve: homogeneous control points `[x, y, w]` as boxes.
pub(super) type PlanarBoxes = [[Interval; 3]];

fn point(x: f64) -> Interval {
    Interval { lo: x, hi: x }
}

fn scale(k: f64, v: &Interval) -> Interval {
    point(k).mul(v)
}

/// Enclosures of `A(S)` and `A'(S)` for every parameter in `s`, by de
/// Casteljau in interval arithmetic (inclusion isotonic), or `None` when
/// the weight's enclosure contains 0.
pub(super) fn point_and_velocity(
    ctrl: &PlanarBoxes,
    s: Interval,
) -> Option<([Interval; 2], [Interval; 2])> {
    let n = ctrl.len() - 1;
    let one_minus = point(1.0).sub(&s);
    let mut rows: SmallVec<[[Interval; 3]; 16]> = SmallVec::from_slice(ctrl);
    for len in (3..=rows.len()).rev() {
        for i in 0..len - 1 {
            rows[i] =
                std::array::from_fn(|k| one_minus.mul(&rows[i][k]).add(&s.mul(&rows[i + 1][k])));
        }
    }
    let (h, dh): ([Interval; 3], [Interval; 3]) = if n == 0 {
        (rows[0], [point(0.0); 3])
    } else {
        (
            std::array::from_fn(|k| one_minus.mul(&rows[0][k]).add(&s.mul(&rows[1][k]))),
            std::array::from_fn(|k| scale(n as f64, &rows[1][k].sub(&rows[0][k]))),
        )
    };
    let w2 = h[2].mul(&h[2]);
    let p = [h[0].div(&h[2])?, h[1].div(&h[2])?];
    let v = [
        dh[0].mul(&h[2]).sub(&h[0].mul(&dh[2])).div(&w2)?,
        dh[1].mul(&h[2]).sub(&h[1].mul(&dh[2])).div(&w2)?,
    ];
    Some((p, v))
}

/// What the Krawczyk test says about a parameter box `[S, T]`.
pub(super) enum Krawczyk {
    /// Exactly one zero, transversal; the contracted box `K(X) ∩ X`.
    Unique([Interval; 2]),
    /// No zero.
    None,
    /// Undecided.
    Unknown,
}

fn mid(x: &Interval) -> f64 {
    0.5 * x.lo + 0.5 * x.hi
}

/// The hull of a list of intervals.
fn hull(v: &[Interval]) -> Interval {
    v.iter().fold(
        Interval {
            lo: f64::INFINITY,
            hi: f64::NEG_INFINITY,
        },
        |h, x| Interval {
            lo: h.lo.min(x.lo),
            hi: h.hi.max(x.hi),
        },
    )
}

/// A control polygon of boxes, flat: point `i` is `ctrl[i·stride …]`,
/// the Cartesian coordinates times the weight, then the weight when
/// `weighted` (else the weight is 1 exactly: a polynomial curve).
pub(super) struct Net<'a> {
    /// The boxes, point after point.
    pub ctrl: &'a [Interval],
    /// Boxes per point.
    pub stride: usize,
    /// Whether the last box of a point is its weight.
    pub weighted: bool,
}

impl Net<'_> {
    fn len(&self) -> usize {
        self.ctrl.len() / self.stride
    }

    fn coord(&self, i: usize, k: usize) -> Interval {
        self.ctrl[i * self.stride + k]
    }

    fn weight(&self, i: usize) -> Interval {
        match self.weighted {
            true => self.coord(i, self.stride - 1),
            false => point(1.0),
        }
    }

    /// Coordinate `k` of the Cartesian point `i`, `X_k / W`.
    fn cartesian(&self, i: usize, k: usize) -> Option<Interval> {
        match self.weighted {
            true => self.coord(i, k).div(&self.weight(i)),
            false => Some(self.coord(i, k)),
        }
    }

    /// Point `i` as `[X, Y, W]` (planar).
    pub fn homogeneous(&self, i: usize) -> [Interval; 3] {
        [self.coord(i, 0), self.coord(i, 1), self.weight(i)]
    }

    /// The planar point `i`, `None` when its weight box contains 0.
    pub fn projected(&self, i: usize) -> Option<[Interval; 2]> {
        Some([self.cartesian(i, 0)?, self.cartesian(i, 1)?])
    }

    /// An enclosure of the planar `A'(s)` over the piece's parameter range
    /// of width `width`, from its control polygon (parameter
    /// `u ∈ [0, 1]`): for a polynomial curve the hull of the hodograph's
    /// control points `n ΔP_i / width`; for a rational one
    /// `A' = (X'W − XW') / (W² · width)`, numerator and `W²` bounded by
    /// their Bernstein coefficients. Both are the convex hull property
    /// (tight for small pieces, unlike interval de Casteljau).
    pub fn velocity_hull(&self, width: f64) -> Option<[Interval; 2]> {
        let n = self.len() - 1;
        if n == 0 {
            return Some([point(0.0); 2]);
        }
        let delta = |i: usize, k: usize| self.coord(i + 1, k).sub(&self.coord(i, k));
        if !self.weighted {
            let speed = point(n as f64).div(&point(width))?;
            let v = |k: usize| (1..n).fold(delta(0, k), |h, i| h.hull(&delta(i, k)));
            return Some([v(0).mul_nonneg(&speed), v(1).mul_nonneg(&speed)]);
        }
        let diff = |k: usize| {
            (0..n)
                .map(|i| scale(n as f64, &delta(i, k)))
                .collect::<SmallVec<[Interval; 16]>>()
        };
        let coord = |k: usize| (0..=n).map(|i| self.coord(i, k)).collect::<Vec<_>>();
        let (w, dw) = (coord(2), diff(2));
        let w2 = hull(&bernstein_product(&w, &w));
        let v = |k: usize| {
            let a = bernstein_product(&diff(k), &w);
            let b = bernstein_product(&coord(k), &dw);
            let num: Vec<Interval> = a.iter().zip(&b).map(|(x, y)| x.sub(y)).collect();
            hull(&num).div(&w2)?.div(&point(width))
        };
        Some([v(0)?, v(1)?])
    }
}

/// The Jacobian enclosure `[[A'_x, −B'_x], [A'_y, −B'_y]]` from velocity
/// enclosures of the two curves.
pub(super) fn jacobian(va: [Interval; 2], vb: [Interval; 2]) -> [[Interval; 2]; 2] {
    let zero = point(0.0);
    [[va[0], zero.sub(&vb[0])], [va[1], zero.sub(&vb[1])]]
}

/// The Krawczyk test of `f(s, t) = A(s) − B(t)` on the box `x = [S, T]`,
/// with `c` a point of `x`, `f` an enclosure of `f(c)` and `j` an
/// enclosure of the Jacobian over the box.
pub(super) fn krawczyk(
    x: [Interval; 2],
    c: [f64; 2],
    f: [Interval; 2],
    j: [[Interval; 2]; 2],
) -> Krawczyk {
    if !(0..2).all(|i| x[i].lo <= c[i] && c[i] <= x[i].hi) {
        return Krawczyk::Unknown;
    }
    let m = [
        [mid(&j[0][0]), mid(&j[0][1])],
        [mid(&j[1][0]), mid(&j[1][1])],
    ];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    if !det.is_finite() || det == 0.0 {
        return Krawczyk::Unknown;
    }
    let y = [
        [m[1][1] / det, -m[0][1] / det],
        [-m[1][0] / det, m[0][0] / det],
    ];
    let dx = [x[0].sub(&point(c[0])), x[1].sub(&point(c[1]))];
    let k: [Interval; 2] = std::array::from_fn(|r| {
        let yf = scale(y[r][0], &f[0]).add(&scale(y[r][1], &f[1]));
        let mut acc = point(c[r]).sub(&yf);
        for (col, d) in dx.iter().enumerate() {
            // (I − Y J)_{r, col}
            let yj = scale(y[r][0], &j[0][col]).add(&scale(y[r][1], &j[1][col]));
            let e = point(if r == col { 1.0 } else { 0.0 }).sub(&yj);
            acc = acc.add(&e.mul(d));
        }
        acc
    });
    if k.iter().any(|v| !(v.lo.is_finite() && v.hi.is_finite())) {
        return Krawczyk::Unknown;
    }
    if k.iter().zip(&x).any(|(v, b)| v.disjoint(b)) {
        return Krawczyk::None;
    }
    if k.iter().zip(&x).all(|(v, b)| b.lo < v.lo && v.hi < b.hi) {
        return Krawczyk::Unique(k);
    }
    Krawczyk::Unknown
}

/// The Krawczyk test on `x` with `f(c)` at the midpoint and the Jacobian
/// from interval de Casteljau on the whole curves (adequate for small
/// boxes).
fn krawczyk_small(a: &PlanarBoxes, b: &PlanarBoxes, x: [Interval; 2]) -> Krawczyk {
    let c = [mid(&x[0]), mid(&x[1])];
    let parts = (
        point_and_velocity(a, x[0]),
        point_and_velocity(b, x[1]),
        point_and_velocity(a, point(c[0])),
        point_and_velocity(b, point(c[1])),
    );
    let (Some((_, va)), Some((_, vb)), Some((pa, _)), Some((pb, _))) = parts else {
        return Krawczyk::Unknown;
    };
    let f = [pa[0].sub(&pb[0]), pa[1].sub(&pb[1])];
    krawczyk(x, c, f, jacobian(va, vb))
}

/// `A(s)` and `A'(s)` in plain `f64` from the midpoints of the control
/// boxes, by de Casteljau: an estimate for Newton's method, not an
/// enclosure.
fn estimate(ctrl: &PlanarBoxes, s: f64) -> ([f64; 2], [f64; 2]) {
    let mut rows: SmallVec<[[f64; 3]; 16]> = ctrl.iter().map(|h| h.map(|v| mid(&v))).collect();
    let n = rows.len() - 1;
    for len in (3..=rows.len()).rev() {
        for i in 0..len - 1 {
            rows[i] = std::array::from_fn(|k| (1.0 - s) * rows[i][k] + s * rows[i + 1][k]);
        }
    }
    let (h, dh): ([f64; 3], [f64; 3]) = match n {
        0 => (rows[0], [0.0; 3]),
        _ => (
            std::array::from_fn(|k| (1.0 - s) * rows[0][k] + s * rows[1][k]),
            std::array::from_fn(|k| n as f64 * (rows[1][k] - rows[0][k])),
        ),
    };
    let v = |k: usize| (dh[k] * h[2] - h[k] * dh[2]) / (h[2] * h[2]);
    ([h[0] / h[2], h[1] / h[2]], [v(0), v(1)])
}

/// Newton steps in `f64` on `A(s) − B(t) = 0` from `z`, until a step is
/// below `10⁻¹²` (the next one is at rounding level) or for 8 steps.
fn newton(a: &PlanarBoxes, b: &PlanarBoxes, mut z: [f64; 2]) -> [f64; 2] {
    for _ in 0..8 {
        let ((pa, va), (pb, vb)) = (estimate(a, z[0]), estimate(b, z[1]));
        let f = [pa[0] - pb[0], pa[1] - pb[1]];
        let j = [[va[0], -vb[0]], [va[1], -vb[1]]];
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if !det.is_finite() || det == 0.0 {
            break;
        }
        let step = [
            (j[1][1] * f[0] - j[0][1] * f[1]) / det,
            (j[0][0] * f[1] - j[1][0] * f[0]) / det,
        ];
        z = [z[0] - step[0], z[1] - step[1]];
        if step[0].abs() <= 1e-12 && step[1].abs() <= 1e-12 {
            break;
        }
    }
    z
}

/// Shrink a certified box `x` (exactly one zero inside): boxes of radius
/// `r = 10⁻¹⁴ … 10⁻⁶` around a Newton estimate, inside `x`, are tried in
/// turn; the first that the Krawczyk test certifies holds that zero, and
/// `K ∩ box` is returned. `x` itself when none does.
pub(super) fn contract(a: &PlanarBoxes, b: &PlanarBoxes, x: [Interval; 2]) -> [Interval; 2] {
    let z = newton(a, b, [mid(&x[0]), mid(&x[1])]);
    if !(0..2).all(|i| x[i].lo < z[i] && z[i] < x[i].hi) {
        return x;
    }
    for r in [1e-14, 1e-12, 1e-10, 1e-8, 1e-6] {
        let y: [Interval; 2] = std::array::from_fn(|i| Interval {
            lo: x[i].lo.max(z[i] - r),
            hi: x[i].hi.min(z[i] + r),
        });
        if let Krawczyk::Unique(k) = krawczyk_small(a, b, y) {
            return std::array::from_fn(|i| Interval {
                lo: y[i].lo.max(k[i].lo),
                hi: y[i].hi.min(k[i].hi),
            });
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn boxes(pts: &[[f64; 3]]) -> Vec<[Interval; 3]> {
        pts.iter().map(|p| p.map(point)).collect()
    }

    fn flat(c: &[[Interval; 3]]) -> Vec<Interval> {
        c.iter().flatten().copied().collect()
    }

    fn velocity_hull(c: &[[Interval; 3]], width: f64) -> Option<[Interval; 2]> {
        let ctrl = flat(c);
        let net = Net {
            ctrl: &ctrl,
            stride: 3,
            weighted: true,
        };
        net.velocity_hull(width)
    }

    #[test]
    fn certifies_the_crossing_of_two_lines_and_excludes_a_far_box() {
        // A(s) = (3s, 3s), B(t) = (3t, 2 − 3t): they cross at s = t = 1/3.
        let a = boxes(&[[0.0, 0.0, 1.0], [3.0, 3.0, 1.0]]);
        let b = boxes(&[[0.0, 2.0, 1.0], [3.0, -1.0, 1.0]]);
        let near = Interval { lo: 0.3, hi: 0.35 };
        let Krawczyk::Unique(k) = krawczyk_small(&a, &b, [near, near]) else {
            panic!("the crossing at (1/3, 1/3) is certified");
        };
        assert!(k.iter().all(|v| v.lo <= 1.0 / 3.0 && 1.0 / 3.0 <= v.hi));
        let far = Interval { lo: 0.6, hi: 0.7 };
        assert!(matches!(krawczyk_small(&a, &b, [far, far]), Krawczyk::None));
        let x = contract(&a, &b, [near, near]);
        assert!(x
            .iter()
            .all(|v| v.hi - v.lo < 1e-12 && v.lo <= 1.0 / 3.0 && 1.0 / 3.0 <= v.hi));
    }

    #[test]
    fn hulls_of_bernstein_coefficients_enclose_the_velocity() {
        // The rational quadratic (0,0), (1,2), (2,0) with weights 1, 2, 1.
        let c = boxes(&[[0.0, 0.0, 1.0], [2.0, 4.0, 2.0], [2.0, 0.0, 1.0]]);
        let v = velocity_hull(&c, 1.0).unwrap();
        for k in 0..=20 {
            let s = k as f64 / 20.0;
            // X = 4s − 2s², Y = 8s(1 − s), W = 1 + 2s − 2s² (by hand).
            let (x, y, w) = (
                4.0 * s - 2.0 * s * s,
                8.0 * s * (1.0 - s),
                1.0 + 2.0 * s - 2.0 * s * s,
            );
            let (dx, dy, dw) = (4.0 - 4.0 * s, 8.0 - 16.0 * s, 2.0 - 4.0 * s);
            let d = [(dx * w - x * dw) / (w * w), (dy * w - y * dw) / (w * w)];
            for i in 0..2 {
                assert!(
                    v[i].lo - 1e-12 <= d[i] && d[i] <= v[i].hi + 1e-12,
                    "{s}: {} ∉ {:?}",
                    d[i],
                    v[i]
                );
            }
        }
        // A line's velocity is enclosed tightly.
        let line = boxes(&[[0.0, 0.0, 1.0], [3.0, 3.0, 1.0]]);
        let v = velocity_hull(&line, 0.5).unwrap();
        assert!(v
            .iter()
            .all(|x| x.lo <= 6.0 && 6.0 <= x.hi && x.hi - x.lo < 1e-12));
    }

    #[test]
    fn the_hodograph_hull_of_a_polynomial_net_encloses_its_velocity() {
        // The cubic with x-controls 0, 1, 3, 2 and y-controls 0, 2, −1, 1 (W ≡ 1):
        // x' = 3[(1 − s)² + 4s(1 − s) − s²], y' = 3[2(1 − s)² − 6s(1 − s) + 2s²].
        let ctrl: Vec<Interval> = [0.0, 0.0, 1.0, 2.0, 3.0, -1.0, 2.0, 1.0]
            .map(point)
            .to_vec();
        let net = Net {
            ctrl: &ctrl,
            stride: 2,
            weighted: false,
        };
        let v = net.velocity_hull(0.25).unwrap();
        for k in 0..=20 {
            let s = k as f64 / 20.0;
            let (a, b, c) = ((1.0 - s) * (1.0 - s), 2.0 * s * (1.0 - s), s * s);
            // On a piece of width 1/4, d/ds of the whole curve is 4 × d/du.
            let d = [
                12.0 * (a + 2.0 * b - c),
                12.0 * (2.0 * a - 3.0 * b + 2.0 * c),
            ];
            assert!((0..2).all(|i| v[i].lo <= d[i] && d[i] <= v[i].hi), "{s}");
        }
        // The hull of 4·3·ΔP: x ∈ [−12, 24], y ∈ [−36, 24], tight.
        assert!(v[0].lo >= -12.0 - 1e-12 && v[0].hi <= 24.0 + 1e-12);
        assert!(v[1].lo >= -36.0 - 1e-12 && v[1].hi <= 24.0 + 1e-12);
    }

    #[test]
    fn a_tangency_is_not_certified() {
        // y = x² (x from −1 to 1) against the line y = 0: J is singular.
        let a = boxes(&[[-1.0, 1.0, 1.0], [0.0, -1.0, 1.0], [1.0, 1.0, 1.0]]);
        let b = boxes(&[[-1.0, 0.0, 1.0], [1.0, 0.0, 1.0]]);
        let unit = Interval { lo: 0.0, hi: 1.0 };
        let (va, vb) = (
            velocity_hull(&a, 1.0).unwrap(),
            velocity_hull(&b, 1.0).unwrap(),
        );
        let (pa, _) = point_and_velocity(&a, point(0.5)).unwrap();
        let (pb, _) = point_and_velocity(&b, point(0.5)).unwrap();
        let f = [pa[0].sub(&pb[0]), pa[1].sub(&pb[1])];
        assert!(!matches!(
            krawczyk([unit, unit], [0.5, 0.5], f, jacobian(va, vb)),
            Krawczyk::Unique(_)
        ));
    }
}
