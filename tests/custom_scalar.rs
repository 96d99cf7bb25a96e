//! The scalar tower is open: a number type defined here, outside the
//! crate, implements [`Ring`] (through the `std::ops` traits and
//! num-traits' `Zero` / `One`), [`MulAcc`], [`Scalar`] and [`Field`], and
//! the generic algorithms run on it.
//!
//! The type is the prime field `Z/pZ`, `p = 2³¹ − 1`. It contains "Q" in
//! the sense the tower asks for: `from_rational(a/b) = a·b⁻¹ mod p`, a ring
//! homomorphism on the rationals whose denominators are prime to `p`. So
//! every computation on such rationals, done over `BigRational` and then
//! reduced mod `p`, must give what the same computation gives over `Z/pZ`
//! (an independent route: exact rational arithmetic, one reduction at the
//! end). Checked here for evaluation (one point and a batch), subdivision
//! and Möbius maps of a rational curve, a rect patch and a tri patch.

use exact_bezier::eval::Evaluator;
use exact_bezier::{ratio, Field, MulAcc, RationalCurve, RectPatch, Scalar, TriPatch};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// The prime `2³¹ − 1`.
const P: u64 = (1 << 31) - 1;

/// An element of `Z/pZ`, its representative in `0 … p − 1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Mp(u64);

impl Mp {
    /// The residue of an integer.
    fn from_bigint_mod(n: &BigInt) -> Mp {
        let r = n % BigInt::from(P);
        let r = r.to_i64().expect("a residue fits") + P as i64;
        Mp(r as u64 % P)
    }

    /// `self^e` by repeated squaring.
    fn pow(self, mut e: u64) -> Mp {
        let (mut base, mut acc) = (self, Mp(1));
        while e > 0 {
            if e & 1 == 1 {
                acc = acc * base;
            }
            base = base * base;
            e >>= 1;
        }
        acc
    }

    /// `1/self` by Fermat (`self^{p−2}`). **Panics for zero.**
    fn inverse(self) -> Mp {
        assert!(self.0 != 0, "0 has no inverse mod p");
        self.pow(P - 2)
    }
}

/// `impl Op<Mp> for Mp` and `impl Op<&Mp> for Mp` from one `fn(u64, u64) -> u64`.
macro_rules! binary_op {
    ($op:ident, $method:ident, $body:expr) => {
        impl $op<Mp> for Mp {
            type Output = Mp;
            fn $method(self, rhs: Mp) -> Mp {
                let f: fn(u64, u64) -> u64 = $body;
                Mp(f(self.0, rhs.0))
            }
        }
        impl<'a> $op<&'a Mp> for Mp {
            type Output = Mp;
            fn $method(self, rhs: &'a Mp) -> Mp {
                self.$method(*rhs)
            }
        }
    };
}

binary_op!(Add, add, |a, b| (a + b) % P);
binary_op!(Sub, sub, |a, b| (a + P - b) % P);
binary_op!(Mul, mul, |a, b| a * b % P);
binary_op!(Div, div, |a, b| (Mp(a) * Mp(b).inverse()).0);

impl Neg for Mp {
    type Output = Mp;
    fn neg(self) -> Mp {
        Mp((P - self.0) % P)
    }
}

impl Zero for Mp {
    fn zero() -> Mp {
        Mp(0)
    }
    fn is_zero(&self) -> bool {
        self.0 == 0
    }
}

impl One for Mp {
    fn one() -> Mp {
        Mp(1)
    }
}

/// The default `acc·a + c·x`.
impl MulAcc for Mp {}

impl Scalar for Mp {
    fn from_i64(n: i64) -> Mp {
        Mp::from_bigint_mod(&BigInt::from(n))
    }

    /// `a·b⁻¹ mod p` for `q = a/b`. **Panics if `p` divides `b`.**
    fn from_rational(q: &BigRational) -> Mp {
        Mp::from_bigint_mod(q.numer()) / Mp::from_bigint_mod(q.denom())
    }
}

/// Division by the inverse (the default `recip`).
impl Field for Mp {}

/// The reduction `Q → Z/pZ` of a list of rationals.
fn reduce(xs: &[BigRational]) -> Vec<Mp> {
    xs.iter().map(Mp::from_rational).collect()
}

/// The homogeneous coordinates of control points, flattened.
fn coords<'a, T: Clone + 'a>(
    points: impl IntoIterator<Item = &'a exact_bezier::hpoint::HPoint<T>>,
) -> Vec<T> {
    points.into_iter().flat_map(|h| h.coords.clone()).collect()
}

/// A planar rational cubic with weights and points over many denominators.
fn curve() -> RationalCurve<BigRational> {
    let pts = vec![
        vec![ratio(1, 3), ratio(-2, 7)],
        vec![ratio(5, 2), ratio(11, 5)],
        vec![ratio(-7, 4), ratio(3, 1)],
        vec![ratio(9, 8), ratio(-1, 6)],
    ];
    let weights = vec![ratio(1, 1), ratio(3, 5), ratio(7, 4), ratio(2, 9)];
    RationalCurve::new(pts, weights).unwrap()
}

/// A spatial rect patch of bidegree (2, 1).
fn rect() -> RectPatch<BigRational> {
    let p = |x: i64, y: i64, z: i64, d: i64| vec![ratio(x, d), ratio(y, d + 1), ratio(z, d + 2)];
    let pts = vec![
        vec![p(0, 0, 1, 1), p(0, 3, 2, 2)],
        vec![p(4, -1, 5, 3), p(2, 7, -3, 5)],
        vec![p(6, 1, 0, 7), p(5, 5, 9, 4)],
    ];
    let weights = vec![
        vec![ratio(1, 1), ratio(2, 3)],
        vec![ratio(5, 4), ratio(1, 7)],
        vec![ratio(3, 2), ratio(9, 10)],
    ];
    RectPatch::new(pts, weights).unwrap()
}

/// A spatial tri patch of degree 2.
fn tri() -> TriPatch<BigRational> {
    let p = |x: i64, y: i64, z: i64| vec![ratio(x, 3), ratio(y, 5), ratio(z, 7)];
    let pts = vec![
        vec![p(0, 0, 1), p(3, 1, 2), p(6, -2, 0)],
        vec![p(1, 4, 3), p(4, 5, -1)],
        vec![p(2, 8, 5)],
    ];
    let weights = vec![
        vec![ratio(1, 1), ratio(2, 3), ratio(4, 5)],
        vec![ratio(7, 6), ratio(3, 11)],
        vec![ratio(5, 2)],
    ];
    TriPatch::new(pts, weights).unwrap()
}

#[test]
fn field_laws_hold() {
    let (a, b) = (Mp::from_rational(&ratio(3, 7)), Mp::from_i64(-12));
    assert_eq!(a * Mp::from_i64(7), Mp::from_i64(3));
    assert_eq!((a / b) * b, a);
    assert_eq!(b.recip() * b, Mp::one());
    assert_eq!(a + (-a), Mp::zero());
    let mut acc = a;
    Mp::mul_acc(&mut acc, &b, &a, &b);
    assert_eq!(acc, a * b + a * b);
}

#[test]
fn curve_operations_commute_with_reduction() {
    let q = curve();
    let m = q.map(Mp::from_rational);
    let t = ratio::<BigRational>(2, 7);
    let tm = Mp::from_rational(&t);
    assert_eq!(m.eval(&tm).unwrap(), reduce(&q.eval(&t).unwrap()));

    let ts: Vec<BigRational> = (1..=9).map(|k| ratio(k, 10)).collect();
    let mut out_q = vec![ratio(0, 1); 2 * ts.len()];
    Evaluator::curve(&q).eval_batch(&ts, &mut out_q).unwrap();
    let mut out_m = vec![Mp::zero(); out_q.len()];
    Evaluator::curve(&m)
        .eval_batch(&reduce(&ts), &mut out_m)
        .unwrap();
    assert_eq!(out_m, reduce(&out_q));

    let (left_q, right_q) = q.subdivide(&t);
    let (left_m, right_m) = m.subdivide(&tm);
    assert_eq!(coords(left_m.ctrl()), reduce(&coords(left_q.ctrl())));
    assert_eq!(coords(right_m.ctrl()), reduce(&coords(right_q.ctrl())));

    let alpha = ratio::<BigRational>(3, 11);
    let moved = m.mobius(&Mp::from_rational(&alpha));
    assert_eq!(
        coords(moved.ctrl()),
        reduce(&coords(q.mobius(&alpha).ctrl()))
    );
}

#[test]
fn rect_operations_commute_with_reduction() {
    let q = rect();
    let m = q.map(Mp::from_rational);
    let (u, v) = (ratio::<BigRational>(1, 3), ratio::<BigRational>(5, 8));
    let (um, vm) = (Mp::from_rational(&u), Mp::from_rational(&v));
    assert_eq!(m.eval(&um, &vm).unwrap(), reduce(&q.eval(&u, &v).unwrap()));

    let uv = [u.clone(), v.clone(), v.clone(), u.clone()];
    let mut out_q = vec![ratio(0, 1); 6];
    Evaluator::rect(&q).eval_batch(&uv, &mut out_q).unwrap();
    let mut out_m = vec![Mp::zero(); 6];
    Evaluator::rect(&m)
        .eval_batch(&reduce(&uv), &mut out_m)
        .unwrap();
    assert_eq!(out_m, reduce(&out_q));

    let (left_q, right_q) = q.subdivide_u(&u);
    let (left_m, right_m) = m.subdivide_u(&um);
    assert_eq!(
        coords(left_m.ctrl().iter().flatten()),
        reduce(&coords(left_q.ctrl().iter().flatten()))
    );
    assert_eq!(
        coords(right_m.ctrl().iter().flatten()),
        reduce(&coords(right_q.ctrl().iter().flatten()))
    );

    let moved_q = q.mobius_u(&ratio(2, 5)).mobius_v(&ratio(7, 9));
    let moved_m = m
        .mobius_u(&Mp::from_rational(&ratio(2, 5)))
        .mobius_v(&Mp::from_rational(&ratio(7, 9)));
    assert_eq!(
        coords(moved_m.ctrl().iter().flatten()),
        reduce(&coords(moved_q.ctrl().iter().flatten()))
    );
}

#[test]
fn tri_operations_commute_with_reduction() {
    let q = tri();
    let m = q.map(Mp::from_rational);
    let (u, v) = (ratio::<BigRational>(1, 4), ratio::<BigRational>(2, 5));
    let (um, vm) = (Mp::from_rational(&u), Mp::from_rational(&v));
    assert_eq!(m.eval(&um, &vm).unwrap(), reduce(&q.eval(&u, &v).unwrap()));

    let mut out_q = vec![ratio(0, 1); 3];
    Evaluator::tri(&q)
        .eval_batch(&[u.clone(), v.clone()], &mut out_q)
        .unwrap();
    let mut out_m = vec![Mp::zero(); 3];
    Evaluator::tri(&m)
        .eval_batch(&[um, vm], &mut out_m)
        .unwrap();
    assert_eq!(out_m, reduce(&out_q));

    let w = ratio::<BigRational>(1, 1) - &u - &v;
    let pieces_q = q.subdivide_at(&[u.clone(), v.clone(), w.clone()]);
    let pieces_m = m.subdivide_at(&[um, vm, Mp::from_rational(&w)]);
    for (pm, pq) in pieces_m.iter().zip(&pieces_q) {
        assert_eq!(
            coords(pm.rows().iter().flatten()),
            reduce(&coords(pq.rows().iter().flatten()))
        );
    }
}
