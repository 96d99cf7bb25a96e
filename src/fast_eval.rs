//! Fraction-free exact evaluation: [`FastCurve`] and [`FastRect`] clear the
//! denominators of an exact curve or patch once, then evaluate at a rational
//! parameter `t = p/q` by de Casteljau at the homogeneous parameter
//! `(q − p : p)` on [`Int`] — machine integers while they fit, big integers
//! after — and divide once at the end. Same values as
//! [`RationalCurve::eval`] and [`RectPatch::eval`], exactly; the speed-up
//! is measured in `benches/curve.rs` and `benches/rect.rs`.
//!
//! ```text
//! X(p/q) = H_d / H_w,   H = Σ (L·w_i P_i, L·w_i) C(n,i) (q−p)^{n−i} pⁱ   (L = common denominator)
//! ```

use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::{de_casteljau_hom, HPoint};
use crate::int::{common_denominator, Int};
use crate::rect::RectPatch;
use num_rational::BigRational;
use num_traits::Zero;

/// Integer homogeneous points from exact ones, over one common denominator
/// (a projective rescaling: the points they represent are unchanged).
fn integral(points: &[&HPoint<BigRational>]) -> Vec<HPoint<Int>> {
    let all: Vec<&BigRational> = points.iter().flat_map(|p| p.coords.iter()).collect();
    let (nums, _) = common_denominator(&all);
    let len = points.first().map_or(0, |p| p.coords.len());
    nums.chunks(len.max(1))
        .map(|c| HPoint { coords: c.to_vec() })
        .collect()
}

/// The homogeneous parameter `(q − p, p)` of `t = p/q` as integers.
fn hom_param(t: &BigRational) -> (Int, Int) {
    let p = Int::from_bigint(t.numer().clone());
    let q = Int::from_bigint(t.denom().clone());
    (q - &p, p)
}

/// Divide the integer homogeneous point once.
fn project(h: &HPoint<Int>) -> Result<Vec<BigRational>, Error> {
    let (coords, w) = h.coords.split_at(h.coords.len() - 1);
    if w[0].is_zero() {
        return Err(Error::PointAtInfinity);
    }
    let w = w[0].to_bigint();
    Ok(coords
        .iter()
        .map(|x| BigRational::new(x.to_bigint(), w.clone()))
        .collect())
}

/// A rational curve prepared for fast exact evaluation.
///
/// ```
/// use exact_bezier::{FastCurve, RationalCurve, ratio};
/// use num_rational::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 3), ratio(y, 7)];
/// let c = RationalCurve::new(vec![p(0, 0), p(1, 3), p(4, 3), p(5, -1)],
///                            vec![ratio(1, 1), ratio(2, 5), ratio(1, 3), ratio(3, 2)]).unwrap();
/// let fast = FastCurve::new(&c);
/// let t = ratio(2, 9);
/// assert_eq!(fast.eval(&t).unwrap(), c.eval(&t).unwrap());
/// ```
#[derive(Clone, Debug)]
pub struct FastCurve {
    ctrl: Vec<HPoint<Int>>,
}

impl FastCurve {
    /// Clear the denominators of `c` (one lcm, done once).
    pub fn new(c: &RationalCurve<BigRational>) -> FastCurve {
        FastCurve {
            ctrl: integral(&c.ctrl().iter().collect::<Vec<_>>()),
        }
    }

    /// `X(t)`, exactly: equal to [`RationalCurve::eval`].
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes at `t`.
    pub fn eval(&self, t: &BigRational) -> Result<Vec<BigRational>, Error> {
        let (a, b) = hom_param(t);
        project(&de_casteljau_hom(&self.ctrl, &a, &b))
    }
}

/// A rational tensor-product patch prepared for fast exact evaluation.
///
/// ```
/// use exact_bezier::{FastRect, RectPatch, ratio};
/// use num_rational::BigRational;
/// let p = |x: i64, y: i64, z: i64| vec![ratio::<BigRational>(x, 2), ratio(y, 3), ratio(z, 5)];
/// let s = RectPatch::new(vec![vec![p(0, 0, 1), p(0, 3, 2)], vec![p(4, 1, 0), p(5, 5, 5)]],
///                        vec![vec![ratio(1, 1), ratio(2, 3)], vec![ratio(3, 4), ratio(1, 1)]]).unwrap();
/// let (u, v) = (ratio(1, 3), ratio(4, 7));
/// assert_eq!(FastRect::new(&s).eval(&u, &v).unwrap(), s.eval(&u, &v).unwrap());
/// ```
#[derive(Clone, Debug)]
pub struct FastRect {
    rows: Vec<Vec<HPoint<Int>>>,
}

impl FastRect {
    /// Clear the denominators of `r` (one lcm over the whole net).
    pub fn new(r: &RectPatch<BigRational>) -> FastRect {
        let flat: Vec<&HPoint<BigRational>> = r.ctrl().iter().flatten().collect();
        let cols = r.ctrl()[0].len();
        let ints = integral(&flat);
        FastRect {
            rows: ints.chunks(cols).map(<[HPoint<Int>]>::to_vec).collect(),
        }
    }

    /// `X(u, v)`, exactly: equal to [`RectPatch::eval`] (de Casteljau in v
    /// on each row, then in u).
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes there.
    pub fn eval(&self, u: &BigRational, v: &BigRational) -> Result<Vec<BigRational>, Error> {
        let (va, vb) = hom_param(v);
        let col: Vec<HPoint<Int>> = self
            .rows
            .iter()
            .map(|row| de_casteljau_hom(row, &va, &vb))
            .collect();
        let (ua, ub) = hom_param(u);
        project(&de_casteljau_hom(&col, &ua, &ub))
    }
}
