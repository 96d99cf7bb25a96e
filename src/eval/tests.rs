use super::*;
use crate::algebra::scalar::ratio;
use crate::hpoint::de_casteljau_hom;
use crate::{Poly, RationalCurve, RectPatch, TriPatch};
use num_rational::BigRational;
use num_traits::Zero;

/// A symbolic homogeneous point `(x_name, y_name, w_name)`.
fn sym_point(name: &str) -> HPoint<Poly> {
    HPoint {
        coords: ["x", "y", "w"]
            .iter()
            .map(|c| Poly::var(&format!("{c}{name}")))
            .collect(),
    }
}

fn hom_eval(net: &Net<Poly>, hom: &[Poly]) -> Vec<Poly> {
    let mut out = vec![Poly::zero(); net.stride()];
    net.eval_hom_into(hom, &mut out, &mut net.workspace());
    out
}

/// The Horner–Bernstein kernel equals de Casteljau at a symbolic
/// homogeneous parameter, for symbolic nets: an identity in every control
/// coordinate and in `(a, b)`, for each degree up to 8.
#[test]
fn curve_kernel_is_de_casteljau_symbolically() {
    let (a, b) = (Poly::var("a"), Poly::var("b"));
    for n in 0..=8 {
        let pts: Vec<HPoint<Poly>> = (0..=n).map(|i| sym_point(&i.to_string())).collect();
        let c = RationalCurve::from_hom(pts.clone()).unwrap();
        let h = hom_eval(&Net::from_curve(&c), &[a.clone(), b.clone()]);
        assert_eq!(h, de_casteljau_hom(&pts, &a, &b).coords, "degree {n}");
    }
}

/// Rect: the kernel equals de Casteljau on each row then across, for
/// symbolic nets of bidegree up to (3, 3) at symbolic `(a_u : b_u)`,
/// `(a_v : b_v)`.
#[test]
fn rect_kernel_is_de_casteljau_symbolically() {
    let hom: Vec<Poly> = ["au", "bu", "av", "bv"]
        .iter()
        .map(|s| Poly::var(s))
        .collect();
    for (m, n) in [(0, 2), (1, 1), (2, 3), (3, 3)] {
        let rows: Vec<Vec<HPoint<Poly>>> = (0..=m)
            .map(|i| (0..=n).map(|j| sym_point(&format!("{i}_{j}"))).collect())
            .collect();
        let r = RectPatch::from_hom(rows.clone()).unwrap();
        let h = hom_eval(&Net::from_rect(&r), &hom);
        let col: Vec<HPoint<Poly>> = rows
            .iter()
            .map(|row| de_casteljau_hom(row, &hom[2], &hom[3]))
            .collect();
        assert_eq!(
            h,
            de_casteljau_hom(&col, &hom[0], &hom[1]).coords,
            "({m}, {n})"
        );
    }
}

/// Tri: the kernel equals triangular de Casteljau at symbolic barycentric
/// `(u, v, w)` (not constrained to sum to 1) for degrees up to 4.
#[test]
fn tri_kernel_is_de_casteljau_symbolically() {
    let (u, v, w) = (Poly::var("u"), Poly::var("v"), Poly::var("w"));
    for n in 0..=4 {
        let rows: Vec<Vec<HPoint<Poly>>> = (0..=n)
            .map(|j| {
                (0..=n - j)
                    .map(|i| sym_point(&format!("{i}_{j}")))
                    .collect()
            })
            .collect();
        let t = TriPatch::from_hom(rows).unwrap();
        let h = hom_eval(&Net::from_tri(&t), &[u.clone(), v.clone(), w.clone()]);
        assert_eq!(h, t.eval_hom_bary(&u, &v, &w).coords, "degree {n}");
    }
}

fn wavy_curve(n: i64) -> RationalCurve<BigRational> {
    let pts = (0..=n)
        .map(|i| vec![ratio((i * i * 7) % 23 - 11, 3 + i % 5), ratio(i - 4, 7)])
        .collect();
    let ws = (0..=n).map(|i| ratio(12345 + 17 * i, 678)).collect();
    RationalCurve::new(pts, ws).unwrap()
}

/// The fraction-free batch equals the generic `BigRational` batch (and so
/// de Casteljau, by the symbolic tests) at awkward parameters.
#[test]
fn fraction_free_equals_generic_exact() {
    let ts = [
        ratio(0, 1),
        ratio(1, 1),
        ratio(123, 457),
        ratio(99, 100),
        ratio(-3, 2),
    ];
    for n in [1, 3, 10, 40] {
        let c = wavy_curve(n);
        let mut ev = Evaluator::curve(&c);
        let mut fast = vec![ratio(0, 1); ts.len() * 2];
        let mut slow = fast.clone();
        ev.eval_batch(&ts, &mut fast).unwrap();
        ev.eval_batch_generic(&ts, &mut slow).unwrap();
        assert_eq!(fast, slow, "degree {n}");
        assert_eq!(
            c.eval(&ts[2]).unwrap(),
            c.eval_hom(&ts[2]).project().unwrap()
        );
    }
}

/// `f64`: the kernel agrees with de Casteljau to 1e-12 relative to the size
/// of the net, up to degree 40.
#[test]
fn f64_kernel_agrees_with_de_casteljau() {
    for n in [3, 10, 40] {
        let c = wavy_curve(n).map(crate::Ordered::to_f64);
        let mut ev = Evaluator::curve(&c);
        let mut x = [0.0; 2];
        for k in 0..=50 {
            let t = k as f64 / 50.0;
            ev.eval_into(&[t], &mut x).unwrap();
            let y = c.eval_hom(&t).project().unwrap();
            for (p, q) in x.iter().zip(&y) {
                assert!(
                    (p - q).abs() <= 1e-12 * (1.0 + q.abs()),
                    "degree {n}, t = {t}"
                );
            }
        }
    }
}

/// A curve batch (the lane kernels of `lanes`, eight points at a time, the
/// last group padded) gives the values of one point at a time, within
/// `1e-12` relative as de Casteljau above: bit for bit in the baseline
/// build, within the derived bound of `lanes` (checked there against
/// exact sums) where the run-time build fuses its multiply–adds.
#[test]
fn f64_lanes_agree_with_single_points() {
    let c = wavy_curve(10).map(crate::Ordered::to_f64);
    let mut ev = Evaluator::curve(&c);
    let ts: Vec<f64> = (0..11).map(|k| k as f64 / 10.0).collect();
    let mut batch = vec![0.0; 22];
    ev.eval_batch(&ts, &mut batch).unwrap();
    for (t, x) in ts.iter().zip(batch.chunks(2)) {
        let mut one = [0.0; 2];
        ev.eval_into(&[*t], &mut one).unwrap();
        for (p, q) in x.iter().zip(&one) {
            assert!((p - q).abs() <= 1e-12 * (1.0 + q.abs()), "t = {t}");
        }
    }
}

#[test]
fn mismatched_buffers_are_shape_errors() {
    let mut ev = Evaluator::curve(&wavy_curve(3));
    let mut out = vec![ratio(0, 1); 3];
    assert!(matches!(
        ev.eval_batch(&[ratio(1, 2), ratio(1, 3)], &mut out),
        Err(Error::Shape(_))
    ));
    assert!(matches!(
        Net::new(vec![1.0; 5], 3, Shape::Curve(1)),
        Err(Error::Shape(_))
    ));
}

/// Curve jets equal `H` and `H'` of de Casteljau on the hodograph
/// (`RationalCurve::hom_derivs_at`, a second method), exactly, at awkward
/// parameters and up to degree 40; and symbolically for degree 0 … 6.
#[test]
fn curve_jets_equal_hodograph_de_casteljau() {
    let ts = [ratio(0, 1), ratio(1, 1), ratio(123, 457), ratio(-3, 2)];
    for n in [0, 1, 3, 10, 40] {
        let c = wavy_curve(n);
        let mut jets = Jets::curve(&c);
        let s = jets.stride();
        let mut out = vec![ratio(0, 1); ts.len() * 2 * s];
        jets.eval_batch(&ts, &mut out).unwrap();
        for (t, o) in ts.iter().zip(out.chunks_exact(2 * s)) {
            let want = c.hom_derivs_at(t, 1);
            assert_eq!(o[..s], want[0].coords[..], "H, degree {n}");
            assert_eq!(o[s..], want[1].coords[..], "H', degree {n}");
        }
    }
    let t = Poly::var("t");
    for n in 0..=6 {
        let pts: Vec<HPoint<Poly>> = (0..=n).map(|i| sym_point(&i.to_string())).collect();
        let c = RationalCurve::from_hom(pts).unwrap();
        let mut out = vec![Poly::zero(); 6];
        Jets::curve(&c)
            .eval_batch(std::slice::from_ref(&t), &mut out)
            .unwrap();
        let want = c.hom_derivs_at(&t, 1);
        assert_eq!(out[3..], want[1].coords[..], "symbolic H', degree {n}");
    }
}

/// A jets batch checks its buffer lengths.
#[test]
fn jets_batch_rejects_mismatched_buffers() {
    let c = wavy_curve(3);
    let mut out = vec![ratio(0, 1); 5];
    assert!(matches!(
        Jets::curve(&c).eval_batch(&[ratio(1, 2)], &mut out),
        Err(Error::Shape(_))
    ));
}
