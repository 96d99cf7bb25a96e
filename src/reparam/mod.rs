//! The quadratic reparameterization of a rect patch (source 000, §2).
//!
//! Substitute in `X(u, v)` of bidegree (m, n)
//!
//! ```text
//! u(s, t) = (α − 1)s / (2αs − s − α),   α = α(t) = α1·t + α2·(1 − t)   (2)(9)
//! v(s, t) = (β − 1)t / (2βt − t − β),   β = β(s) = β1·s + β2·(1 − s)   (3)(10)
//! ```
//!
//! Derivation (ours, by homogeneous substitution). With
//! `E = α(1 − s) + (1 − α)s = −(2αs − s − α)` we have `u = (1 − α)s / E` and
//! `1 − u = α(1 − s) / E`, so
//!
//! ```text
//! B_{i,m}(u) = B_{i,m}(s) · α(t)^{m−i} (1 − α(t))^i / E^m,
//! B_{j,n}(v) = B_{j,n}(t) · β(s)^{n−j} (1 − β(s))^j / F^n.
//! ```
//!
//! The factors `E^m F^n` are common to numerator and denominator of `X` and
//! cancel. `α(t)^{m−i}(1 − α(t))^i = Σ_l c′_{l,i} B_{l,m}(t)` (a product of
//! m linear polynomials in t: Bernstein coefficients from the blossom), and
//! likewise `β(s)^{n−j}(1 − β(s))^j = Σ_l e′_{l,j} B_{l,n}(s)`. Products of
//! Bernstein polynomials, `B_{a,p} B_{b,q} = C(p,a)C(q,b)/C(p+q,a+b) B_{a+b,p+q}`,
//! give a patch of bidegree (m + n, m + n) in (s, t) with homogeneous control
//! points
//!
//! ```text
//! H̃_{k1,k2} = Σ_i Σ_j ω_{i,j}(P_{i,j}, 1) · C(m,i)C(n,l2)/C(m+n,k1) · e′_{l2,j}
//!                                        · C(m,l1)C(n,j)/C(m+n,k2) · c′_{l1,i},
//! l2 = k1 − i ∈ [0, n],  l1 = k2 − j ∈ [0, m],
//! ```
//!
//! which is eq. (16)/(17) with the paper's `c_{l,i} = (−1)^m c′_{l,i}` and
//! `e_{l,j} = (−1)^n e′_{l,j}` (the paper keeps the sign of
//! `(α2 t − α1 t − α2)^{m−i}(α1 t + α2 − α2 t − 1)^i`; for `m + n` odd its
//! weights all come out negative — the same surface, but not positive
//! weights; we use `c′`, `e′`).
//!
//! The new patch at `(s, t)` equals the old at `(u(s,t), v(s,t))`; for
//! `α1, α2, β1, β2 ∈ (0, 1)` each iso-line map is a Möbius map of `[0, 1]`
//! onto itself, the four sides of the square map onto themselves, so
//! the image of `[0, 1]²` is `[0, 1]²` and the point set is kept (proofs
//! family `yang_yong`).

pub mod standard;

pub use standard::{
    corner_weights, standard_quadratic_map, standardize, theorem1_holds, Method, Options, Standard,
    StandardMap, Standardize,
};

use crate::algebra::scalar::{binomial, binomial_scalar, recip_int, Field, Scalar};
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;

/// The four coefficients of the quadratic reparameterization, in the paper's
/// convention: `α(t) = α1·t + α2·(1 − t)`, `β(s) = β1·s + β2·(1 − s)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Quadratic<T> {
    /// α at t = 1 (the side `v = 1` gets the Möbius map with α1).
    pub alpha1: T,
    /// α at t = 0 (the side `v = 0`).
    pub alpha2: T,
    /// β at s = 1 (the side `u = 1`).
    pub beta1: T,
    /// β at s = 0 (the side `u = 0`).
    pub beta2: T,
}

/// The Bernstein coefficients of a product of Bernstein-form polynomials:
/// `(Σ a_k B_{k,p})(Σ b_l B_{l,q}) = Σ a_k b_l C(p,k)C(q,l)/C(p+q,k+l) B_{k+l,p+q}`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{reparam::bernstein_product, ratio};
/// use exact_bezier::BigRational;
/// // t · t = t²: coefficients (0, 1) times (0, 1) is (0, 0, 1).
/// let a: Vec<BigRational> = vec![ratio(0, 1), ratio(1, 1)];
/// assert_eq!(bernstein_product(&a, &a), vec![ratio(0, 1), ratio(0, 1), ratio(1, 1)]);
/// ```
pub fn bernstein_product<T: Scalar>(a: &[T], b: &[T]) -> Vec<T> {
    let (p, q) = (a.len() - 1, b.len() - 1);
    let mut out = vec![T::zero(); p + q + 1];
    for (k, ak) in a.iter().enumerate() {
        for (l, bl) in b.iter().enumerate() {
            let c = binomial_scalar::<T>(p, k) * binomial_scalar::<T>(q, l);
            let term = ak.clone() * bl * &c;
            out[k + l] = out[k + l].clone() + &scale_down(term, p + q, k + l);
        }
    }
    out
}

/// `x / C(n, k)` (exact: Scalar contains Q).
fn scale_down<T: Scalar>(x: T, n: usize, k: usize) -> T {
    x * recip_int::<T>(&binomial(n, k))
}

/// The coefficients `c′[i][l]`, `i, l = 0…m`: the Bernstein coefficients in
/// t of `α(t)^{m−i} (1 − α(t))^i` for the linear `α(t)` with `α(0) = at0`,
/// `α(1) = at1`. The paper's Appendix 1 prints `c_{l,i} = (−1)^m c′[i][l]`
/// for m = 3 (with the inputs `at0 = α2`, `at1 = α1`).
///
/// ```
/// use exact_bezier::{reparam::quadratic_coefficients, Poly};
/// let (a1, a2) = (Poly::var("α1"), Poly::var("α2"));
/// let c = quadratic_coefficients(3, &a2, &a1);
/// assert_eq!(c[0][1], a2.pow(2) * &a1); // so c_{1,0} = −α2²α1, not the printed −α2³α1
/// ```
pub fn quadratic_coefficients<T: Scalar>(m: usize, at0: &T, at1: &T) -> Vec<Vec<T>> {
    let one = T::one();
    let a = [at0.clone(), at1.clone()];
    let b = [one.clone() - at0, one - at1];
    (0..=m)
        .map(|i| {
            let mut acc = vec![T::one()];
            for _ in 0..m - i {
                acc = bernstein_product(&acc, &a);
            }
            for _ in 0..i {
                acc = bernstein_product(&acc, &b);
            }
            acc
        })
        .collect()
}

/// # Quadratic reparameterization
impl<T: Scalar> RectPatch<T> {
    /// The quadratic reparameterization (source 000, eqs (9)–(17), corrected):
    /// the exact patch of bidegree `(m + n, m + n)` whose value at `(s, t)` is
    /// this patch's at `(u(s, t), v(s, t))` (see the module docs for the
    /// formula and its derivation). Ring operations only: runs on symbols.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, reparam::Quadratic, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let s = RectPatch::new(vec![vec![p(0, 0), p(0, 2)], vec![p(2, 0), p(4, 4)]],
    ///                        vec![vec![ratio(1, 1), ratio(2, 1)], vec![ratio(3, 1), ratio(1, 2)]]).unwrap();
    /// let q = Quadratic { alpha1: ratio(1, 3), alpha2: ratio(1, 2), beta1: ratio(2, 3), beta2: ratio(1, 4) };
    /// let r = s.quadratic_reparam(&q);
    /// assert_eq!(r.degree(), (2, 2));
    /// let (st, tt) = (ratio(1, 3), ratio(2, 5));
    /// let (u, v) = q.param(&st, &tt).unwrap();
    /// assert_eq!(r.eval(&st, &tt).unwrap(), s.eval(&u, &v).unwrap());
    /// ```
    pub fn quadratic_reparam(&self, q: &Quadratic<T>) -> RectPatch<T> {
        let (m, n) = self.degree();
        let c = quadratic_coefficients(m, &q.alpha2, &q.alpha1);
        let e = quadratic_coefficients(n, &q.beta2, &q.beta1);
        let d = m + n;
        // The s-factor of term (i, j) at k1 and its t-factor at k2 (None
        // outside the range of l2 = k1 − i and l1 = k2 − j).
        let s_part = |i: usize, j: usize, k1: usize| -> Option<T> {
            let l2 = k1.checked_sub(i).filter(|l| *l <= n)?;
            let b = binomial_scalar::<T>(m, i) * binomial_scalar::<T>(n, l2);
            Some(scale_down(b * &e[j][l2], d, k1))
        };
        let t_part = |i: usize, j: usize, k2: usize| -> Option<T> {
            let l1 = k2.checked_sub(j).filter(|l| *l <= m)?;
            let b = binomial_scalar::<T>(m, l1) * binomial_scalar::<T>(n, j);
            Some(scale_down(b * &c[i][l1], d, k2))
        };
        let table = |f: &dyn Fn(usize, usize, usize) -> Option<T>| -> Vec<Vec<Vec<Option<T>>>> {
            (0..=m)
                .map(|i| {
                    (0..=n)
                        .map(|j| (0..=d).map(|k| f(i, j, k)).collect())
                        .collect()
                })
                .collect()
        };
        let (sp, tp) = (table(&s_part), table(&t_part));
        let ctrl = (0..=d)
            .map(|k1| {
                (0..=d)
                    .map(|k2| {
                        // Per coordinate, the terms summed at once (Scalar::sum_of).
                        let mut parts: Vec<Vec<T>> = vec![Vec::new(); self.dim() + 1];
                        for (i, row) in self.ctrl().iter().enumerate() {
                            for (j, h) in row.iter().enumerate() {
                                if let (Some(a), Some(b)) = (&sp[i][j][k1], &tp[i][j][k2]) {
                                    let f = a.clone() * b;
                                    for (part, x) in parts.iter_mut().zip(&h.coords) {
                                        part.push(x.clone() * &f);
                                    }
                                }
                            }
                        }
                        HPoint {
                            coords: parts.into_iter().map(T::sum_of).collect(),
                        }
                    })
                    .collect()
            })
            .collect();
        RectPatch::from_hom(ctrl).expect("a (m+n, m+n) grid of points of one dimension")
    }
}

/// # The u-only quadratic map (β constant)
impl<T: Scalar> RectPatch<T> {
    /// The quadratic map in u alone, `u(s, t)` with `α(t) = α1·t + α2·(1 − t)`
    /// and `v = t`: a patch of bidegree `(m, m + n)` with
    /// `H̃_{i,k} = Σ_j ω_{i,j}(P_{i,j}, 1) · C(m,l)C(n,j)/C(m+n,k) · c′_{l,i}`,
    /// `l = k − j`. When `β1 = β2 = β`, [`RectPatch::quadratic_reparam`] is
    /// this map after [`RectPatch::mobius_v`]`(β)`, degree-elevated n times
    /// in s (proofs family `yang_yong`): the standard form of
    /// [`crate::reparam::standardize`] (quadratic) exists already in bidegree
    /// `(m, m + n)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{RectPatch, reparam::Quadratic, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let s = RectPatch::new(vec![vec![p(0, 0), p(0, 2)], vec![p(2, 0), p(4, 4)]],
    ///                        vec![vec![ratio(1, 1), ratio(2, 1)], vec![ratio(3, 1), ratio(1, 2)]]).unwrap();
    /// let (a1, a2, b): (BigRational, BigRational, BigRational) = (ratio(1, 3), ratio(1, 2), ratio(2, 5));
    /// let q = Quadratic { alpha1: a1.clone(), alpha2: a2.clone(), beta1: b.clone(), beta2: b.clone() };
    /// let compact = s.mobius_v(&b).quadratic_reparam_u(&a1, &a2);
    /// assert_eq!(compact.degree(), (1, 2));
    /// assert_eq!(compact.elevate(1, 0), s.quadratic_reparam(&q));
    /// ```
    pub fn quadratic_reparam_u(&self, alpha1: &T, alpha2: &T) -> RectPatch<T> {
        let (m, n) = self.degree();
        let c = quadratic_coefficients(m, alpha2, alpha1);
        let ctrl = self
            .ctrl()
            .iter()
            .enumerate()
            .map(|(i, row)| {
                (0..=m + n)
                    .map(|k| {
                        let mut acc = HPoint::zero(self.dim());
                        for (j, h) in row.iter().enumerate() {
                            if let Some(l) = k.checked_sub(j).filter(|l| *l <= m) {
                                let b = binomial_scalar::<T>(m, l) * binomial_scalar::<T>(n, j);
                                acc = acc.add(&h.scale(&scale_down(b * &c[i][l], m + n, k)));
                            }
                        }
                        acc
                    })
                    .collect()
            })
            .collect();
        RectPatch::from_hom(ctrl).expect("an (m, m+n) grid of points of one dimension")
    }
}

impl<T: Scalar> Quadratic<T> {
    /// The homogeneous parameters of the map at `(s, t)`:
    /// `([α(1 − s), (1 − α)s], [β(1 − t), (1 − β)t])`, i.e.
    /// `(1 − u, u)·E` and `(1 − v, v)·F`. Feed them to
    /// [`RectPatch::eval_hom_projective`] to evaluate the original patch at
    /// `(u(s,t), v(s,t))` without division.
    pub fn param_hom(&self, s: &T, t: &T) -> ([T; 2], [T; 2]) {
        let one = T::one();
        let alpha = self.alpha1.clone() * t + &(self.alpha2.clone() * &(one.clone() - t));
        let beta = self.beta1.clone() * s + &(self.beta2.clone() * &(one.clone() - s));
        (
            [
                alpha.clone() * &(one.clone() - s),
                (one.clone() - &alpha) * s,
            ],
            [beta.clone() * &(one.clone() - t), (one - &beta) * t],
        )
    }
}

impl<T: Field> Quadratic<T> {
    /// The parameter map `(u(s, t), v(s, t))` of eqs (2)(3)(9)(10).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] where a denominator `2αs − s − α` or `2βt − t − β`
    /// vanishes (never for α's and β's in (0, 1) and (s, t) in [0, 1]²).
    pub fn param(&self, s: &T, t: &T) -> Result<(T, T), Error> {
        let (u, v) = self.param_hom(s, t);
        let ratio_of = |p: &[T; 2], what: &str| -> Result<T, Error> {
            let den = p[0].clone() + &p[1];
            if den.is_zero() {
                return Err(Error::Domain(format!(
                    "the quadratic map has a pole in {what} at (s, t) = ({s:?}, {t:?})"
                )));
            }
            Ok(p[1].clone() / &den)
        };
        Ok((ratio_of(&u, "u")?, ratio_of(&v, "v")?))
    }
}
