//! Fraction-free exact evaluation: [`FastCurve`], [`FastRect`] and
//! [`FastTri`] clear the
//! denominators of an exact curve or patch once, then evaluate at a rational
//! parameter `t = p/q` by de Casteljau at the homogeneous parameter
//! `(q − p : p)` on [`Int`] — machine integers while they fit, big integers
//! after — and divide once at the end. Same values as
//! [`RationalCurve::eval`], [`RectPatch::eval`] and [`TriPatch::eval`],
//! exactly; the speed-up is measured in `benches/curve.rs`,
//! `benches/rect.rs` and `benches/tri.rs`.
//!
//! ```text
//! X(p/q) = H_d / H_w,   H = Σ (L·w_i P_i, L·w_i) C(n,i) (q−p)^{n−i} pⁱ   (L = common denominator)
//! ```

use crate::algebra::int::{common_denominator, Int};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::{de_casteljau_hom, HPoint};
use crate::rect::RectPatch;
use crate::tri::{casteljau_level, TriPatch};
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
/// use exact_bezier::{fast_eval::FastCurve, RationalCurve, ratio};
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
/// use exact_bezier::{fast_eval::FastRect, RectPatch, ratio};
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

/// A rational triangular patch prepared for fast exact evaluation.
///
/// ```
/// use exact_bezier::{fast_eval::FastTri, TriPatch, ratio};
/// use num_rational::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 3), ratio(y, 5)];
/// let t = TriPatch::new(vec![vec![p(0, 0), p(1, 2), p(3, 0)], vec![p(0, 2), p(2, 3)], vec![p(0, 4)]],
///                       vec![vec![ratio(1, 1), ratio(2, 3), ratio(1, 1)], vec![ratio(1, 2), ratio(3, 2)], vec![ratio(1, 1)]]).unwrap();
/// let (u, v) = (ratio(1, 4), ratio(2, 7));
/// assert_eq!(FastTri::new(&t).eval(&u, &v).unwrap(), t.eval(&u, &v).unwrap());
/// ```
#[derive(Clone, Debug)]
pub struct FastTri {
    rows: Vec<Vec<HPoint<Int>>>,
}

impl FastTri {
    /// Clear the denominators of `t` (one lcm over the whole net).
    pub fn new(t: &TriPatch<BigRational>) -> FastTri {
        let flat: Vec<&HPoint<BigRational>> = t.rows().iter().flatten().collect();
        let mut ints = integral(&flat).into_iter();
        let rows = t
            .rows()
            .iter()
            .map(|r| ints.by_ref().take(r.len()).collect())
            .collect();
        FastTri { rows }
    }

    /// `X(u, v, 1 − u − v)`, exactly: equal to [`TriPatch::eval`]. With
    /// `u = a/q`, `v = b/q` over a common denominator `q`, triangular de
    /// Casteljau runs at the integer barycentric triple `(a, b, q − a − b)`.
    ///
    /// # Errors
    ///
    /// [`Error::PointAtInfinity`] if the weight function vanishes there.
    pub fn eval(&self, u: &BigRational, v: &BigRational) -> Result<Vec<BigRational>, Error> {
        let (nums, q) = common_denominator(&[u, v]);
        let [a, b]: [Int; 2] = nums.try_into().expect("two parameters");
        let c = Int::from_bigint(q) - &a - &b;
        let bary = [a, b, c];
        let mut rows = self.rows.clone();
        while rows.len() > 1 {
            rows = casteljau_level(&rows, &bary);
        }
        project(&rows[0][0])
    }
}
