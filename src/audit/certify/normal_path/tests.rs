use super::*;
use crate::algebra::interval_bernstein::scale;
use crate::audit::certify::compose::{compose, NetRef};

fn pts(c: &[f64]) -> Vec<Interval> {
    c.iter().map(|&x| Interval::point(x)).collect()
}

/// The homogeneous net (coordinate-major, rows along `u`) of the points
/// `p` (row-major, weight 1 or the fourth entry).
fn net(p: &[[f64; 4]]) -> Vec<Vec<Interval>> {
    (0..4)
        .map(|d| p.iter().map(|x| Interval::point(x[d])).collect())
        .collect()
}

/// The forward differences of a net along its rows (`along_u`) or its
/// columns: the hodograph's net without its degree factor (a positive
/// multiple, which leaves the normal's direction).
fn differences(c: &[Vec<Interval>], rows: usize, cols: usize, along_u: bool) -> Vec<Vec<Interval>> {
    let (r, k) = if along_u {
        (rows - 1, cols)
    } else {
        (rows, cols - 1)
    };
    c.iter()
        .map(|x| {
            (0..r)
                .flat_map(|i| (0..k).map(move |j| (i, j)))
                .map(|(i, j)| {
                    let next = if along_u {
                        (i + 1) * cols + j
                    } else {
                        i * cols + j + 1
                    };
                    x[next].sub(&x[i * cols + j])
                })
                .collect()
        })
        .collect()
}

/// `n` along `p = (u, v)` for the net `c` of `rows × cols` points.
fn normal_of(
    c: &[Vec<Interval>],
    rows: usize,
    cols: usize,
    u: &[f64],
    v: &[f64],
) -> (Vec<Scaled>, ScaledVec) {
    let (du, dv) = (
        differences(c, rows, cols, true),
        differences(c, rows, cols, false),
    );
    let h = compose(
        &NetRef {
            rows,
            cols,
            coords: c,
        },
        u,
        v,
    );
    let nets = [
        NetRef {
            rows: rows - 1,
            cols,
            coords: &du,
        },
        NetRef {
            rows,
            cols: cols - 1,
            coords: &dv,
        },
    ];
    let [hu, hv] = nets.each_ref().map(|n| compose(n, u, v));
    let n = patch_normal(&h, &hu, &hv);
    (h, n)
}

fn path(c: [&[f64]; 3]) -> ScaledVec {
    c.map(|x| scale(&pts(x)))
}

#[test]
fn the_saddle_normal_along_t_t2_is_minus_t2_minus_t_1() {
    // (u, v, uv): S_u × S_v = (−v, −u, 1); along (t, t²): (−t², −t, 1),
    // quadratic Bernstein coefficients [0, 0, −1], [0, −½, −1], [1, 1, 1].
    let c = net(&[
        [0.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, 1.0],
        [1.0, 0.0, 0.0, 1.0],
        [1.0, 1.0, 1.0, 1.0],
    ]);
    let (_, n) = normal_of(&c, 2, 2, &[0.0, 0.5, 1.0], &[0.0, 0.0, 1.0]);
    let want = path([&[0.0, 0.0, -1.0], &[0.0, -0.5, -1.0], &[1.0, 1.0, 1.0]]);
    let (upper, mid) = angle_between(&n, &want).unwrap();
    assert!(
        upper < 1e-13 && mid.lo <= 0.0 + 1e-300 && mid.hi < 1e-13,
        "{upper} {mid:?}"
    );
}

#[test]
fn a_rational_quarter_cylinder_has_the_radial_normal() {
    // Rows along the arc (1 − u², 2u, 1 + u²) counterclockwise, columns
    // along z: S_u × S_v = (−y, x, 0) × (0, 0, 1) = (x, y, 0), outward.
    let arc = [[1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 2.0, 2.0]];
    let p: Vec<[f64; 4]> = arc
        .iter()
        .flat_map(|a| [0.0, 1.0].map(|z| [a[0], a[1], z * a[2], a[2]]))
        .collect();
    let c = net(&p);
    for u in [[0.0, 1.0], [0.25, 0.5]] {
        let (h, n) = normal_of(&c, 3, 2, &u, &[0.5, 0.5]);
        // The radial direction at S(p(t)), times W > 0: (X, Y, 0).
        let zero = vec![Interval::point(0.0); h[0].len()];
        let radial = [h[0].clone(), h[1].clone(), zero];
        let (upper, _) = angle_between(&n, &radial).unwrap();
        assert!(upper < 1e-13, "{u:?}: {upper}");
    }
}

/// The planes `z = 0` and `z = k y`, as bilinear nets.
fn planes(k: f64) -> [ScaledVec; 2] {
    let flat = net(&[
        [0.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, 0.0, 1.0],
        [1.0, 0.0, 0.0, 1.0],
        [1.0, 1.0, 0.0, 1.0],
    ]);
    let tilted = net(&[
        [0.0, 0.0, 0.0, 1.0],
        [0.0, 1.0, k, 1.0],
        [1.0, 0.0, 0.0, 1.0],
        [1.0, 1.0, k, 1.0],
    ]);
    // Along the line x = t, y = ½ of each.
    [flat, tilted].map(|c| normal_of(&c, 2, 2, &[0.0, 1.0], &[0.5, 0.5]).1)
}

#[test]
fn a_kink_of_atan_1e_5_is_enclosed() {
    // (1, 0, 0) × (0, 1, k) = (0, −k, 1): the angle to (0, 0, 1) is atan k.
    let [a, b] = planes(1e-5);
    let kink = 1e-5f64.atan();
    let (upper, mid) = angle_between(&a, &b).unwrap();
    assert!(kink <= upper && upper <= kink * (1.0 + 1e-9), "{upper}");
    assert!(
        mid.lo <= kink && kink <= mid.hi && mid.width() < 1e-15,
        "{mid:?}"
    );
}

#[test]
fn opposite_normals_are_a_fold() {
    let [a, b] = planes(0.0);
    assert!(angle_between(&a, &b).unwrap().0 < 1e-15);
    let (upper, mid) = angle_between(&a, &reversed(&b)).unwrap();
    let pi = std::f64::consts::PI;
    assert!(pi <= upper && upper <= pi * (1.0 + 1e-9), "{upper}");
    assert!(mid.lo <= pi && pi <= mid.hi, "{mid:?}");
}

/// The normal `ẑ` and the linear path `(0, −1, k t)`, `t ∈ [0, 1]`: a
/// crease whose angle `π/2 − atan(k t)` (`k > 0`) is greatest at `t = 0`,
/// or `π/2 + atan(|k| t)` (`k < 0`) at `t = 1`. The cosine changes sign or
/// vanishes, so the tangent's bound does not hold; the cosine's does.
#[test]
fn a_crease_at_a_right_angle_is_enclosed() {
    let z = [pts(&[0.0, 0.0]), pts(&[0.0, 0.0]), pts(&[1.0, 1.0])];
    let half = std::f64::consts::FRAC_PI_2;
    for k in [0.1, -0.1] {
        let path = [pts(&[0.0, 0.0]), pts(&[-1.0, -1.0]), pts(&[0.0, k])];
        let (upper, mid) = angle_between(&z, &path).unwrap();
        let most = if k > 0.0 { half } else { half + (-k).atan() };
        assert!(most <= upper && upper <= most + 1e-3, "{k}: {upper}");
        let at_half = half - (k / 2.0).atan();
        assert!(mid.lo <= at_half && at_half <= mid.hi, "{k}: {mid:?}");
    }
}
