//! The polynomial system of an intersection and its exact real solutions.
//!
//! A rational curve of degree `n` in the power basis has homogeneous
//! components `X_0(s), …, X_{d−1}(s), W(s)` over Q (common factors
//! removed). Two curves meet at `(s, t)` iff, for every coordinate `k`,
//!
//! ```text
//! E_k(s, t) = X_k^A(s) W^B(t) − X_k^B(t) W^A(s) = 0      (W^A, W^B > 0 on [0, 1])
//! ```
//!
//! Two generic combinations `F = E_0 + Σ c_k E_k`, `G = E_1 + Σ d_k E_k`
//! (`k ≥ 2`; just `E_0, E_1` in the plane) are solved by elimination:
//! `R(s) = Res_t(F, G)`, Yun's square-free factorization `R = ∏ a_j^j`,
//! isolation of the roots of each `a_j` in `[0, 1]` by Descartes counts
//! (square-freeness and coprimality certified modulo a prime first, so the
//! generic case builds no remainder sequence over Q), then the unique
//! `t = −e_0(s)/e_1(s)` from the first subresultant (exact, as a real
//! algebraic number, see [`RealAlgebraic::rational_function_at`]), and
//! each remaining `E_k` checked to vanish exactly (its value at
//! `t = −e_0/e_1`, cleared of denominators, shares the root with `a_j`).
//! The multiplicity of a root of `R` is the intersection multiplicity of the
//! projected curves when that root has a single solution `t` over C — which
//! `e_1(s) ≠ 0` certifies.
//!
//! Reference: Sederberg & Parry, *Comparison of three curve intersection
//! algorithms*, CAD 18 (1986) (implicitization by resultants); Basu,
//! Pollack & Roy (2006) §4.2 (subresultants), §2.2 (Descartes' rule).

use crate::algebra::real_algebraic::polys;
use crate::algebra::sylvester::{linear_eliminant_in_t, resultant_in_t};
use crate::algebra::{BPoly, RealAlgebraic, Scalar, UPoly};
use crate::bernstein::bernstein_to_power;
use crate::curve::RationalCurve;
use crate::error::Error;
use num_rational::BigRational;
use num_traits::{One, Zero};
pub(crate) use polys::derivative;

/// A univariate polynomial over Q.
pub(crate) type QPoly = UPoly<BigRational>;

/// A curve as power-basis homogeneous components `[X_0, …, X_{d−1}, W]`,
/// their common factor divided out.
#[derive(Clone, Debug)]
pub(crate) struct PowerCurve {
    pub comps: Vec<QPoly>,
}

impl PowerCurve {
    /// The components of `c`, reduced by their gcd (a factor without roots
    /// in `[0, 1]`, since it divides the positive weight polynomial).
    pub fn new(c: &RationalCurve<BigRational>) -> Self {
        let comps: Vec<QPoly> = (0..=c.dim())
            .map(|k| {
                let coord: Vec<BigRational> =
                    c.ctrl().iter().map(|h| h.coords[k].clone()).collect();
                UPoly::new(bernstein_to_power(&coord))
            })
            .collect();
        let g = comps.iter().fold(QPoly::zero(), |g, p| polys::gcd(&g, p));
        let comps = comps
            .iter()
            .map(|p| p.div_exact(&g).expect("the gcd divides"))
            .collect();
        PowerCurve { comps }
    }

    /// The number of Cartesian coordinates.
    pub fn dim(&self) -> usize {
        self.comps.len() - 1
    }

    /// The weight polynomial `W`.
    pub fn weight(&self) -> &QPoly {
        &self.comps[self.dim()]
    }

    /// `true` when the curve is a single point (`X_k W' − X_k' W ≡ 0`).
    pub fn is_point(&self) -> bool {
        let w = self.weight();
        let dw = polys::derivative(w);
        self.comps[..self.dim()]
            .iter()
            .all(|x| x.mul(&dw).sub(&polys::derivative(x).mul(w)).is_zero())
    }

    /// `E_k(s, t) = X_k^A(s) W^B(t) − X_k^B(t) W^A(s)` with `self = A`, as a
    /// polynomial in `t` with coefficients in `s`.
    pub fn equation(&self, other: &PowerCurve, k: usize) -> BPoly<BigRational> {
        let (xa, wa) = (&self.comps[k], self.weight());
        let (xb, wb) = (other.comps[k].coeffs(), other.weight().coeffs());
        let len = xb.len().max(wb.len());
        let zero = BigRational::zero();
        BPoly::new(
            (0..len)
                .map(|j| {
                    let w = wb.get(j).unwrap_or(&zero);
                    let x = xb.get(j).unwrap_or(&zero);
                    xa.scale(w).sub(&wa.scale(x))
                })
                .collect(),
        )
    }

    /// The `k`-th coordinate `X_k(α)/W(α)`, exactly.
    pub fn coordinate_at(&self, k: usize, alpha: &RealAlgebraic) -> Result<RealAlgebraic, Error> {
        alpha.rational_function_at(&self.comps[k], self.weight())
    }

    /// The exact point at `α`, sharing per-coordinate value polynomials
    /// among the roots of one defining polynomial through `cache`.
    pub fn point_at(
        &self,
        alpha: &RealAlgebraic,
        cache: &mut PointCache,
    ) -> Result<Vec<RealAlgebraic>, Error> {
        let p = alpha.defining_polynomial();
        let w = self.weight();
        if alpha.as_rational().is_some() || polys::gcd(&p, w).degree().unwrap_or(0) > 0 {
            return (0..self.dim())
                .map(|k| self.coordinate_at(k, alpha))
                .collect();
        }
        let index = match cache.0.iter().position(|(q, _)| *q == p) {
            Some(i) => i,
            None => {
                let known = self.comps[..self.dim()]
                    .iter()
                    .map(|x| RealAlgebraic::value_polynomial(&p, x, w))
                    .collect();
                cache.0.push((p, known));
                cache.0.len() - 1
            }
        };
        Ok(cache.0[index]
            .1
            .iter()
            .zip(&self.comps)
            .map(|(known, x)| alpha.rational_function_root(known, x, w))
            .collect())
    }

    /// `true` when the velocity vanishes at `α` (every `X_k' W − X_k W'` is
    /// zero there): a cusp or a stationary point of the parameterization.
    pub fn stationary_at(&self, alpha: &RealAlgebraic) -> bool {
        let w = self.weight();
        let dw = polys::derivative(w);
        self.comps[..self.dim()].iter().all(|x| {
            let v = polys::derivative(x).mul(w).sub(&x.mul(&dw));
            vanishes_at(&v, alpha)
        })
    }
}

/// For each defining polynomial already met, the polynomials whose roots
/// are the point's coordinates at its roots ([`PowerCurve::point_at`]).
#[derive(Default)]
pub(crate) struct PointCache(Vec<(QPoly, Vec<polys::Isolator>)>);

/// A combination `Σ c_k p_k` of bivariate polynomials.
pub(crate) fn combine(parts: &[(BigRational, &BPoly<BigRational>)]) -> BPoly<BigRational> {
    let len = parts
        .iter()
        .map(|(_, p)| p.coeffs().len())
        .max()
        .unwrap_or(0);
    BPoly::new(
        (0..len)
            .map(|j| {
                parts.iter().fold(QPoly::zero(), |acc, (c, p)| {
                    p.coeffs()
                        .get(j)
                        .map_or(acc.clone(), |a| acc.add(&a.scale(c)))
                })
            })
            .collect(),
    )
}

/// Does `p` vanish at `α`? Exactly: for irrational `α`, `α` must be a root
/// of `gcd(p, m)` with `m` its defining polynomial.
pub(crate) fn vanishes_at(p: &QPoly, alpha: &RealAlgebraic) -> bool {
    if let Some(a) = alpha.as_rational() {
        return p.eval(&a).is_zero();
    }
    if p.is_zero() {
        return true;
    }
    let g = polys::gcd(&alpha.defining_polynomial(), p);
    if g.degree().unwrap_or(0) == 0 {
        return false;
    }
    let b = polys::cauchy_bound(&g);
    RealAlgebraic::real_roots_in(&g, &-b.clone(), &b).contains(alpha)
}

/// Yun's square-free factorization: `p = c ∏ a_j^j` with `a_j` monic,
/// square-free and pairwise coprime; returns the non-constant `(a_j, j)`.
pub(crate) fn square_free_factors(p: &QPoly) -> Vec<(QPoly, usize)> {
    let mut out = Vec::new();
    let dp = polys::derivative(p);
    let g = polys::gcd(p, &dp);
    let mut b = p.div_exact(&g).expect("the gcd divides");
    let mut c = dp.div_exact(&g).expect("the gcd divides");
    let mut d = c.sub(&polys::derivative(&b));
    let mut j = 1;
    while b.degree().unwrap_or(0) > 0 {
        let a = polys::gcd(&b, &d);
        b = b.div_exact(&a).expect("the gcd divides");
        c = d.div_exact(&a).expect("the gcd divides");
        d = c.sub(&polys::derivative(&b));
        if a.degree().unwrap_or(0) > 0 {
            out.push((polys::monic(&a), j));
        }
        j += 1;
    }
    out
}

/// The real roots of the square-free `a` in the closed interval `[0, 1]`,
/// increasing.
pub(crate) fn roots_in_unit(a: &QPoly) -> Vec<RealAlgebraic> {
    let (zero, one) = (BigRational::zero(), BigRational::one());
    let mut roots = Vec::new();
    if a.eval(&zero).is_zero() {
        roots.push(RealAlgebraic::from_rational(&zero));
    }
    roots.extend(RealAlgebraic::real_roots_in(a, &zero, &one));
    if a.eval(&one).is_zero() {
        roots.push(RealAlgebraic::from_rational(&one));
    }
    roots
}

/// An exact solution `(s, t)` of the system in `[0, 1]²`.
#[derive(Clone, Debug)]
pub(crate) struct Solution {
    pub s: RealAlgebraic,
    pub t: RealAlgebraic,
    /// The root multiplicity of `s` in the resultant.
    pub multiplicity: usize,
}

/// Why a system could not be solved by elimination in `t`.
#[derive(Debug)]
pub(crate) enum Unsolved {
    /// `F` and `G` share a factor: the resultant is identically zero.
    CommonFactor,
    /// A root `s` with several common `t` (or one at infinity).
    Degenerate(RealAlgebraic),
}

/// The solutions of `F = G = 0` (and `extra = 0`) in `[0, 1]²`.
///
/// `weight` is the outer curve's weight polynomial: where it vanishes,
/// `F(s, ·)` and `G(s, ·)` are both multiples of the inner weight and the
/// resultant vanishes without an intersection; those factors (no roots in
/// `[0, 1]`) are divided out so that the remaining factors, and the degrees
/// of the parameters' defining polynomials, are not inflated.
/// `inner_weight` (the inner curve's) plays the same role for `Res_s`.
pub(crate) fn solve(
    f: &BPoly<BigRational>,
    g: &BPoly<BigRational>,
    extra: &[BPoly<BigRational>],
    weight: &QPoly,
    inner_weight: &QPoly,
) -> Result<Vec<Solution>, Unsolved> {
    if f.deg_u().unwrap_or(0) == 0 || g.deg_u().unwrap_or(0) == 0 {
        return Err(Unsolved::CommonFactor);
    }
    let r = resultant_in_t(f, g);
    if r.is_zero() {
        return Err(Unsolved::CommonFactor);
    }
    let r = without_weight_factors(r, weight);
    let (e1, e0) = linear_eliminant_in_t(f, g);
    let minus_e0 = e0.scale(&-BigRational::one());
    let mut t_poly = None;
    let mut out = Vec::new();
    for (factor, multiplicity) in square_free_factors(&r) {
        for s in roots_in_unit(&factor) {
            if vanishes_at(&e1, &s) {
                return Err(Unsolved::Degenerate(s));
            }
            let t = if s.as_rational().is_some() {
                s.rational_function_at(&minus_e0, &e1)
                    .map_err(|_| Unsolved::Degenerate(s.clone()))?
            } else {
                let known = t_poly.get_or_insert_with(|| t_resultant(f, g, inner_weight));
                let degree = s.defining_polynomial().degree();
                match known {
                    Some(known) if known.sf.degree() <= degree => {
                        s.rational_function_root(known, &minus_e0, &e1)
                    }
                    _ => s
                        .rational_function_at(&minus_e0, &e1)
                        .map_err(|_| Unsolved::Degenerate(s.clone()))?,
                }
            };
            if t.signum() < 0 || t > RealAlgebraic::one() {
                continue;
            }
            let on_all = extra
                .iter()
                .all(|e| vanishes_at(&substitute_t(e, &minus_e0, &e1), &s));
            if on_all {
                out.push(Solution { s, t, multiplicity });
            }
        }
    }
    Ok(out)
}

/// `Res_s(F, G)`, prepared for root isolation: every `t` of a solution is
/// among its roots, so an irrational `t` is isolated from enclosures of
/// `−e_0(s)/e_1(s)` without a resultant over the field of `s`. `None` when
/// it does not exist or vanishes identically.
fn t_resultant(
    f: &BPoly<BigRational>,
    g: &BPoly<BigRational>,
    inner_weight: &QPoly,
) -> Option<polys::Isolator> {
    let (ft, gt) = (f.transpose(), g.transpose());
    if ft.deg_u().unwrap_or(0) == 0 || gt.deg_u().unwrap_or(0) == 0 {
        return None;
    }
    let r = without_weight_factors(resultant_in_t(&ft, &gt), inner_weight);
    (r.degree().unwrap_or(0) > 0).then(|| polys::Isolator::new(&r))
}

/// `r` without the factors it shares with `weight` (as often as they
/// divide): roots of a weight are no intersections, they only inflate the
/// degree.
fn without_weight_factors(mut r: QPoly, weight: &QPoly) -> QPoly {
    if r.is_zero() {
        return r;
    }
    loop {
        let common = polys::gcd(&r, weight);
        if common.degree().unwrap_or(0) == 0 {
            return r;
        }
        r = r.div_exact(&common).expect("the gcd divides");
    }
}

/// `E(s, n(s)/d(s)) · d(s)^{deg_t E}`, a polynomial in `s`.
fn substitute_t(e: &BPoly<BigRational>, n: &QPoly, d: &QPoly) -> QPoly {
    let deg = e.deg_u().unwrap_or(0);
    let pow =
        |p: &QPoly, k: usize| (0..k).fold(UPoly::constant(BigRational::one()), |acc, _| acc.mul(p));
    e.coeffs()
        .iter()
        .enumerate()
        .fold(QPoly::zero(), |acc, (j, a)| {
            acc.add(&a.mul(&pow(n, j)).mul(&pow(d, deg - j)))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::algebra::real_algebraic::polys::int_poly as p;

    #[test]
    fn yun_splits_multiplicities() {
        // (x − 1)² (x + 2)³ x
        let f = p(&[-1, 1])
            .mul(&p(&[-1, 1]))
            .mul(&p(&[2, 1]))
            .mul(&p(&[2, 1]))
            .mul(&p(&[2, 1]))
            .mul(&p(&[0, 1]));
        let got = square_free_factors(&f);
        assert_eq!(
            got,
            vec![(p(&[0, 1]), 1), (p(&[-1, 1]), 2), (p(&[2, 1]), 3)]
        );
    }
}
