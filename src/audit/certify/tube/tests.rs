use super::*;
use crate::audit::certify::bezier::{ICurve, IPatch};
use crate::audit::certify::compose::compose;
use crate::audit::certify::spline::curve_over;
use crate::curve::RationalCurve;
use crate::rect::RectPatch;
use crate::{ratio, BigRational};

type Q = BigRational;

fn q(n: i64, d: i64) -> Q {
    ratio(n, d)
}

/// The plane `S(u, v) = (2u, 3v, 0)`, bilinear: `S_u = (2, 0, 0)`,
/// `S_v = (0, 3, 0)`, no second derivatives.
fn plane() -> IPatch {
    let p = |x: i64, y: i64| vec![q(x, 1), q(y, 1), q(0, 1)];
    let r = RectPatch::polynomial(vec![vec![p(0, 0), p(0, 3)], vec![p(2, 0), p(2, 3)]]).unwrap();
    IPatch::with_enclosed_derivatives(&r).unwrap()
}

/// The line `C(s) = (2(1/4 + s/2), 3/2, 1/2)`, half a unit above the
/// plane: its feet are `u = 1/4 + s/2`, `v = 1/2`.
fn line() -> ICurve {
    let c = RationalCurve::polynomial(vec![
        vec![q(1, 2), q(3, 2), q(1, 2)],
        vec![q(3, 2), q(3, 2), q(1, 2)],
    ])
    .unwrap();
    ICurve::new(&c).unwrap()
}

/// The fitted cubic `p(s) = (1/4 + δ + s/2, 1/2)`: the feet moved by `δ`
/// in `u`, by its Bernstein coefficients.
fn fitted(delta: f64) -> (Vec<f64>, Vec<f64>) {
    let u = (0..4).map(|i| 0.25 + delta + 0.5 * f64::from(i) / 3.0);
    (u.collect(), vec![0.5; 4])
}

/// `F_u = (S(p) − C)·S_u = (2δ, 0, −1/2)·(2, 0, 0) = 4δ` and
/// `F_v = (2δ, 0, −1/2)·(0, 3, 0) = 0` all along, whatever the gap of
/// 1/2: the residual's bounds are `4δ` (to rounding: 10⁻⁷ of it, the
/// compositions' widths) and rounding.
#[test]
fn the_residual_along_a_curve_off_the_feet_is_its_offset_not_the_gap() {
    let (patch, curve) = (plane(), line());
    let (u, v) = fitted(1e-6);
    let [h, hu, hv] = patch.first_order_nets().map(|n| compose(&n, &u, &v));
    let c = curve_over(&curve, Interval { lo: 0.0, hi: 1.0 });
    let r = residual(&c, &h, &hu, &hv).unwrap();
    assert!(r[0] >= 4e-6 && r[0] < 4e-6 * (1.0 + 1e-7), "{r:?}");
    assert!(r[1] < 1e-12, "{r:?}");
}

/// On the plane `J = diag(4, 9)` exactly, so `Y = J⁻¹`, `I − YJ = 0` and
/// Krawczyk's box is `−Y [−R, R] = [−δ, δ] × [−0, 0]` (to rounding): the
/// tube needs radii `(δ, 0)` and holds with radii just above `δ`, not
/// just below.
#[test]
fn the_tube_holds_exactly_for_radii_above_the_offset() {
    let (patch, curve) = (plane(), line());
    let delta = 1e-6;
    let r = [4.0 * delta, 1e-300];
    let points = curve.jet(Interval { lo: 0.0, hi: 1.0 }).unwrap().x;
    let jet = patch
        .jet(Interval { lo: 0.2, hi: 0.8 }, Interval { lo: 0.4, hi: 0.6 })
        .unwrap();
    let need = radius(&jet, &points, r).unwrap();
    assert!(
        (need[0] - delta).abs() < 1e-9 * delta && need[1] < 1e-18,
        "{need:?}"
    );
    assert!(holds(&jet, &points, r, [1.01 * delta, 1e-12]));
    assert!(!holds(&jet, &points, r, [0.99 * delta, 1e-12]));
}
