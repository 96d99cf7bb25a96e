use super::*;
use crate::algebra::interval_bernstein::{scale, unscale, Scaled};

fn pts(c: &[f64]) -> Vec<Interval> {
    c.iter().map(|&x| Interval::point(x)).collect()
}

/// The curve `(t, t², t³ + δ)`, `w = 1`, by its cubic Bernstein
/// coefficients (the blossoms of the monomials: `t → i/3`,
/// `t² → i(i−1)/6`, `t³ → [i = 3]`).
fn twisted_cubic(delta: f64) -> Vec<Scaled> {
    let third = 1.0 / 3.0;
    [
        pts(&[0.0, third, 2.0 * third, 1.0]),
        pts(&[0.0, 0.0, third, 1.0]),
        pts(&[delta, delta, delta, 1.0 + delta]),
        pts(&[1.0; 4]),
    ]
    .iter()
    .map(|c| scale(c))
    .collect()
}

/// The bilinear patch `(u, v, uv)`, rows along `u`.
fn saddle() -> Vec<Vec<Interval>> {
    let p = [
        [0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 1.0],
    ];
    (0..4)
        .map(|d| {
            p.iter()
                .map(|x| Interval::point(if d == 3 { 1.0 } else { x[d] }))
                .collect()
        })
        .collect()
}

/// The saddle composed with `u = t`, `v = t²` (as quadratics: `[0, ½, 1]`
/// and `[0, 0, 1]`).
fn saddle_along_t_t2() -> Vec<Scaled> {
    let coords = saddle();
    let net = NetRef {
        rows: 2,
        cols: 2,
        coords: &coords,
    };
    compose(&net, &[0.0, 0.5, 1.0], &[0.0, 0.0, 1.0])
}

#[test]
fn the_saddle_along_u_t_v_t2_is_the_twisted_cubic() {
    let s = saddle_along_t_t2();
    // Degree (1 + 1)·2 = 4; the quartic blossoms of t, t², t³ and 1.
    let want: [fn(f64) -> f64; 4] = [
        |i| i / 4.0,
        |i| i * (i - 1.0) / 12.0,
        |i| i * (i - 1.0) * (i - 2.0) / 24.0,
        |_| 1.0,
    ];
    for (d, f) in want.iter().enumerate() {
        let got = unscale(&s[d]).unwrap();
        assert_eq!(got.len(), 5);
        for (i, c) in got.iter().enumerate() {
            let x = f(i as f64);
            assert!(c.lo <= x && x <= c.hi && c.width() < 1e-14, "{d} {i} {c:?}");
        }
    }
}

#[test]
fn a_curve_delta_above_the_saddle_is_bounded_by_delta() {
    let s = saddle_along_t_t2();
    for delta in [0.0, 1e-7, 0.25] {
        let b = distance_bound(&twisted_cubic(delta), &s).unwrap();
        assert!(delta <= b && b <= delta + 1e-13, "{delta}: {b}");
    }
}

/// The quarter cylinder `x² + y² = 1`, `0 ≤ z ≤ 1`: rows along the arc
/// `((1 − u²), 2u, 1 + u²)` (homogeneous, Bernstein `[1,1,0]`,
/// `[0,1,2]`, `[1,1,2]`), columns along `z`.
fn cylinder() -> Vec<Vec<Interval>> {
    let arc = [[1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 2.0, 2.0]];
    let mut coords = vec![Vec::new(); 4];
    for a in arc {
        for z in [0.0, 1.0] {
            coords[0].push(Interval::point(a[0]));
            coords[1].push(Interval::point(a[1]));
            coords[2].push(Interval::point(z * a[2]));
            coords[3].push(Interval::point(a[2]));
        }
    }
    coords
}

#[test]
fn a_circle_of_radius_1_plus_delta_is_bounded_near_delta() {
    let coords = cylinder();
    let net = NetRef {
        rows: 3,
        cols: 2,
        coords: &coords,
    };
    let delta = 1e-6;
    // The circle of radius 1 + δ at z = ½ over the arc's parameter
    // range [0, h]: u = h·t, v = ½ (linear).
    for h in [1.0, 1.0 / 64.0] {
        let s = compose(&net, &[0.0, h], &[0.5, 0.5]);
        // The same arc over [0, h], exactly: blossoms of (1 − u², 2u,
        // 1 + u²) at u = h·t, degree 2: [1, 1, 1 − h²], [0, h, 2h],
        // [1, 1, 1 + h²].
        let r = 1.0 + delta;
        let c: Vec<Scaled> = [
            pts(&[r, r, r * (1.0 - h * h)]),
            pts(&[0.0, r * h, r * 2.0 * h]),
            pts(&[0.5, 0.5, 0.5 * (1.0 + h * h)]),
            pts(&[1.0, 1.0, 1.0 + h * h]),
        ]
        .iter()
        .map(|c| scale(c))
        .collect();
        let b = distance_bound(&c, &s).unwrap();
        // Proved: at least the true distance δ; the rational hull is
        // within a factor of the weights' spread of it.
        assert!(b >= delta, "{h}: {b}");
        assert!(b <= delta * (1.0 + h * h) * (1.0 + 1e-9), "{h}: {b}");
    }
}

#[test]
fn a_denominator_not_proved_positive_gives_no_bound() {
    let c = twisted_cubic(0.0);
    let mut s = twisted_cubic(0.0);
    s[3] = scale(&pts(&[1.0, -1.0, 1.0, 1.0]));
    assert_eq!(distance_bound(&c, &s), None);
}

#[test]
fn interpolation_reproduces_a_cubic() {
    // t³ at t = 0, ⅓, ⅔, 1: Bernstein coefficients [0, 0, 0, 1].
    let v: Vec<f64> = (0..4).map(|j| (j as f64 / 3.0).powi(3)).collect();
    let c = interpolate(&v).unwrap();
    for (got, want) in c.iter().zip([0.0, 0.0, 0.0, 1.0]) {
        assert!((got - want).abs() < 1e-14, "{c:?}");
    }
    assert_eq!(interpolate(&[2.5]).unwrap(), vec![2.5]);
}

/// [`compose`] by its definition, one coordinate at a time with
/// [`mul`] (the route before the coordinates went side by side).
fn compose_by_coordinate(net: &NetRef<'_>, u: &[f64], v: &[f64]) -> Vec<Scaled> {
    let (bu, bv) = (basis_of(u, net.rows - 1), basis_of(v, net.cols - 1));
    net.coords
        .iter()
        .map(|c| {
            let mut out = vec![Interval::point(0.0); bu[0].len() + bv[0].len() - 1];
            for (i, b) in bu.iter().enumerate() {
                let mut row = vec![Interval::point(0.0); bv[0].len()];
                for (j, f) in bv.iter().enumerate() {
                    for (o, x) in row.iter_mut().zip(f) {
                        *o = o.add(&c[i * net.cols + j].mul(x));
                    }
                }
                for (o, x) in out.iter_mut().zip(mul(b, &row)) {
                    *o = o.add(&x);
                }
            }
            out
        })
        .collect()
}

proptest::proptest! {
    /// The four coordinates side by side give each coordinate's bits.
    #[test]
    fn composing_side_by_side_is_composing_by_coordinate(
        rows in 1usize..=5, cols in 1usize..=5,
        seed in proptest::collection::vec(-1e3f64..1e3, 8..=40),
        u in proptest::collection::vec(0.0f64..=1.0, 1..=5),
        v in proptest::collection::vec(0.0f64..=1.0, 1..=5),
    ) {
        let k = u.len().min(v.len());
        let coords: Vec<Vec<Interval>> = (0..4)
            .map(|d| {
                (0..rows * cols)
                    .map(|p| {
                        let x = seed[(7 * p + 3 * d) % seed.len()];
                        Interval { lo: x, hi: x + x.abs() * 1e-12 }
                    })
                    .collect()
            })
            .collect();
        let net = NetRef { rows, cols, coords: &coords };
        let bits = |s: Vec<Scaled>| -> Vec<Vec<(u64, u64)>> {
            s.iter().map(|c| c.iter().map(|x| (x.lo.to_bits(), x.hi.to_bits())).collect()).collect()
        };
        proptest::prop_assert_eq!(
            bits(compose(&net, &u[..k], &v[..k])),
            bits(compose_by_coordinate(&net, &u[..k], &v[..k]))
        );
    }
}
