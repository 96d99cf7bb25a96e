//! Blossoms (polar forms): symmetric, multi-affine functions that agree with
//! a polynomial on the diagonal (source 003 §1, Definitions 1.1–1.3).
//!
//! Two independent constructions are provided, so that each checks the
//! other (uniqueness, Property 1.4):
//!
//! - from Bézier control points, by de Casteljau with a different argument
//!   at each level: curves ([`RationalCurve::blossom`](crate::RationalCurve::blossom)),
//!   triangles ([`TriPatch::blossom`], the blossoming algorithm eq. 26),
//!   tensor-product patches ([`rect_blossom`]); and by the shift-operator
//!   product of eq. (2) ([`ShiftOp`]);
//! - from power-form coefficients, by elementary symmetric sums:
//!   [`polar_univariate`], [`polar_bivariate`] (total degree n),
//!   [`polar_tensor`] (bidegree (m, n)).
//!
//! Everything is a ring computation: exact for exact scalars, and an
//! identity for all symbol values with [`Poly`](crate::Poly).

use crate::algebra::scalar::{binomial, recip_int, Scalar};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;
use crate::tri::{casteljau_level, Bary, TriPatch};

/// # Blossom (polar form) of a triangular patch
impl<T: Scalar> TriPatch<T> {
    /// The blossom `b[x⁽¹⁾, …, x⁽ⁿ⁾]` of the homogeneous patch, by the
    /// blossoming algorithm (source 003 eq. 26):
    ///
    /// ```text
    /// B^d_{ijk} = u⁽ᵈ⁾ B^{d−1}_{i+1,j,k} + v⁽ᵈ⁾ B^{d−1}_{i,j+1,k} + w⁽ᵈ⁾ B^{d−1}_{i,j,k+1},
    /// B^0_{ijk} = Q̂_{ijk},   b[x⁽¹⁾, …, x⁽ⁿ⁾] = B^n_{000}
    /// ```
    ///
    /// Symmetric, affine in each barycentric argument, `b[x, …, x] = T̂(x)`,
    /// and `b[T1^i, T2^j, T3^k] = Q̂_{ijk}` (dual functionals, eq. 4) — all
    /// proved in `proofs/src/blossoms.rs`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless exactly `n` arguments are given.
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::{TriPatch, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let t = TriPatch::polynomial(vec![vec![p(0), p(1), p(2)], vec![p(3), p(4)], vec![p(5)]]).unwrap();
    /// let (t1, t2) = ([ratio(1, 1), ratio(0, 1), ratio(0, 1)], [ratio(0, 1), ratio(1, 1), ratio(0, 1)]);
    /// // b[T1, T2] = Q_{110}
    /// assert_eq!(t.blossom(&[t1, t2]).unwrap(), t.get(1, 1).clone());
    /// ```
    pub fn blossom(&self, args: &[Bary<T>]) -> Result<HPoint<T>, Error> {
        if args.len() != self.degree() {
            return Err(Error::Shape(format!(
                "the blossom of a degree {} triangular patch takes {} arguments, not {}",
                self.degree(),
                self.degree(),
                args.len()
            )));
        }
        Ok(self.blossom_unchecked(args))
    }

    /// [`TriPatch::blossom`] without the argument count check.
    /// **Panics unless `args.len()` is the degree.**
    pub(crate) fn blossom_unchecked(&self, args: &[Bary<T>]) -> HPoint<T> {
        let mut rows = self.rows().to_vec();
        for b in args {
            rows = casteljau_level(&rows, b);
        }
        rows.swap_remove(0).swap_remove(0)
    }
}

/// The blossom `b[u₁, …, u_m; v₁, …, v_n]` of a tensor-product patch
/// (source 003 Definition 1.3): the curve blossom in v on every row
/// `i` of the control net, then the curve blossom in u of the results.
/// `b[0^{m−i}, 1^i; 0^{n−j}, 1^j] = P̂_{ij}` (eq. 5).
///
/// # Errors
///
/// [`Error::Shape`] unless `us.len() = m` and `vs.len() = n`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{blossom::rect_blossom, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let r = RectPatch::polynomial(vec![vec![p(0), p(1)], vec![p(2), p(7)]]).unwrap();
/// assert_eq!(rect_blossom(&r, &[ratio(1, 1)], &[ratio(0, 1)]).unwrap(), r.ctrl()[1][0]);
/// ```
pub fn rect_blossom<T: Scalar>(r: &RectPatch<T>, us: &[T], vs: &[T]) -> Result<HPoint<T>, Error> {
    let column = r
        .ctrl()
        .iter()
        .map(|row| RationalCurve::from_hom(row.clone())?.blossom(vs))
        .collect::<Result<Vec<_>, _>>()?;
    RationalCurve::from_hom(column)?.blossom(us)
}

/// A homogeneous polynomial of degree `d` in the shift operators of source
/// 003 eq. (3), `E₁ Q_{ijk} = Q_{i+1,j,k}`, `E₂ Q_{ijk} = Q_{i,j+1,k}`,
/// `E₃ Q_{ijk} = Q_{i,j,k+1}`:
///
/// ```text
/// Σ_{i+j+k=d} c_{ijk} E₁ⁱ E₂ʲ E₃ᵏ,   applied to Q_{000}:  Σ c_{ijk} Q_{ijk}
/// ```
///
/// Eq. (2) writes the blossom as `Π_k (u⁽ᵏ⁾E₁ + v⁽ᵏ⁾E₂ + w⁽ᵏ⁾E₃) Q_{000}`;
/// the lecture's form (source 001, Hu 1996 eq. 6) writes `I` for `E₃`
/// in two-index notation, where a product of degree d < n is padded by
/// `I^{n−d}` = `E₃^{n−d}` ([`ShiftOp::apply`] does this).
#[derive(Clone, Debug, PartialEq)]
pub struct ShiftOp<T> {
    /// `coef[j][i] = c_{i,j,d−i−j}`.
    coef: Vec<Vec<T>>,
}

impl<T: Scalar> ShiftOp<T> {
    /// The identity operator (degree 0).
    pub fn identity() -> Self {
        ShiftOp {
            coef: vec![vec![T::one()]],
        }
    }

    /// The linear operator `u E₁ + v E₂ + w E₃` for `b = [u, v, w]`.
    pub fn linear(b: &Bary<T>) -> Self {
        ShiftOp {
            coef: vec![vec![b[2].clone(), b[0].clone()], vec![b[1].clone()]],
        }
    }

    /// The degree `d`.
    pub fn degree(&self) -> usize {
        self.coef.len() - 1
    }

    /// The product `self · other` (the operators commute).
    pub fn mul(&self, other: &Self) -> Self {
        let (p, q) = (self.degree(), other.degree());
        let mut coef: Vec<Vec<T>> = (0..=p + q)
            .map(|j| vec![T::zero(); p + q - j + 1])
            .collect();
        for (j1, r1) in self.coef.iter().enumerate() {
            for (i1, c1) in r1.iter().enumerate() {
                for (j2, r2) in other.coef.iter().enumerate() {
                    for (i2, c2) in r2.iter().enumerate() {
                        let slot = &mut coef[j1 + j2][i1 + i2];
                        *slot = slot.clone() + &(c1.clone() * c2);
                    }
                }
            }
        }
        ShiftOp { coef }
    }

    /// `selfᵉ` (`self⁰` is the identity).
    pub fn pow(&self, e: usize) -> Self {
        (0..e).fold(Self::identity(), |acc, _| acc.mul(self))
    }

    /// The product `Π_k (u⁽ᵏ⁾E₁ + v⁽ᵏ⁾E₂ + w⁽ᵏ⁾E₃)` of eq. (2).
    pub fn product(args: &[Bary<T>]) -> Self {
        args.iter()
            .fold(Self::identity(), |acc, b| acc.mul(&Self::linear(b)))
    }

    /// Apply to `Q̂_{000}` of the patch `t` of degree n ≥ d, padding with
    /// `E₃^{n−d}` (the identity `I` of two-index notation):
    /// `Σ c_{ijk} Q̂_{i,j,k+n−d}`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] if the operator's degree exceeds the patch degree.
    pub fn apply(&self, t: &TriPatch<T>) -> Result<HPoint<T>, Error> {
        let (d, n) = (self.degree(), t.degree());
        if d > n {
            return Err(Error::Shape(format!(
                "a degree {d} shift operator cannot act on a degree {n} patch"
            )));
        }
        let mut acc = HPoint::zero(t.dim());
        for (j, row) in self.coef.iter().enumerate() {
            for (i, c) in row.iter().enumerate() {
                acc = acc.add(&t.get(i, j).scale(c));
            }
        }
        Ok(acc)
    }
}

/// Elementary symmetric sums `e_0, …, e_n` of `args` (`e_a = 0` for a > len).
fn elementary<T: Scalar>(args: &[T], n: usize) -> Vec<T> {
    let mut e = vec![T::zero(); n + 1];
    e[0] = T::one();
    for x in args {
        for a in (1..=n).rev() {
            e[a] = e[a].clone() + &(e[a - 1].clone() * x);
        }
    }
    e
}

/// The polar form of the univariate polynomial `p(t) = Σ_a coef[a] tᵃ`
/// regarded as of degree `n` (source 003 Definition 1.1):
/// `B_n[p](u₁, …, u_n) = Σ_a coef[a] e_a(u₁, …, u_n) / C(n, a)`,
/// `e_a` the elementary symmetric sums.
///
/// # Errors
///
/// [`Error::Shape`] if `coef` has more than `n + 1` entries or `args` not `n`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{blossom::polar_univariate, ratio};
/// use exact_bezier::BigRational;
/// // p(t) = t² as degree 2: B[u₁, u₂] = u₁ u₂
/// let c = [ratio::<BigRational>(0, 1), ratio(0, 1), ratio(1, 1)];
/// assert_eq!(polar_univariate(&c, 2, &[ratio(2, 1), ratio(3, 1)]).unwrap(), ratio(6, 1));
/// ```
pub fn polar_univariate<T: Scalar>(coef: &[T], n: usize, args: &[T]) -> Result<T, Error> {
    if coef.len() > n + 1 || args.len() != n {
        return Err(Error::Shape(format!(
            "a degree {n} polar form needs at most {} coefficients and {n} arguments, not {} and {}",
            n + 1,
            coef.len(),
            args.len()
        )));
    }
    let e = elementary(args, n);
    Ok(coef.iter().enumerate().fold(T::zero(), |acc, (a, c)| {
        acc + &(c.clone() * &e[a] * &recip_int::<T>(&binomial(n, a)))
    }))
}

/// The polar form of the bivariate polynomial `p(x, y) = Σ coef[a][b] xᵃ yᵇ`
/// of total degree ≤ n (source 003 Definition 1.2), with `n` arguments
/// `(x⁽ᵏ⁾, y⁽ᵏ⁾)`:
///
/// ```text
/// B_n[xᵃ yᵇ] = Σ_{A, B disjoint, |A| = a, |B| = b} Π_{k∈A} x⁽ᵏ⁾ Π_{k∈B} y⁽ᵏ⁾ / (n!/(a! b! (n−a−b)!))
/// ```
///
/// (the sums are the coefficients of `Π_k (1 + x⁽ᵏ⁾X + y⁽ᵏ⁾Y)`).
///
/// # Errors
///
/// [`Error::Shape`] if a coefficient has `a + b > n` or `args.len() ≠ n`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{blossom::polar_bivariate, ratio};
/// use exact_bezier::BigRational;
/// // p = x·y as degree 2: B[(x1,y1),(x2,y2)] = (x1 y2 + x2 y1)/2
/// let z = ratio::<BigRational>(0, 1);
/// let c = vec![vec![z.clone(), z.clone()], vec![z.clone(), ratio(1, 1)]];
/// let args = [[ratio(1, 1), ratio(2, 1)], [ratio(3, 1), ratio(5, 1)]];
/// assert_eq!(polar_bivariate(&c, 2, &args).unwrap(), ratio(11, 2));
/// ```
pub fn polar_bivariate<T: Scalar>(coef: &[Vec<T>], n: usize, args: &[[T; 2]]) -> Result<T, Error> {
    let too_high = coef.iter().enumerate().any(|(a, row)| {
        row.iter()
            .enumerate()
            .any(|(b, c)| a + b > n && !c.is_zero())
    });
    if too_high || args.len() != n {
        return Err(Error::Shape(format!(
            "a total degree {n} polar form needs coefficients with a + b ≤ {n} and {n} arguments, not {}",
            args.len()
        )));
    }
    // g[a][b]: coefficient of XᵃYᵇ in Π (1 + x⁽ᵏ⁾X + y⁽ᵏ⁾Y), a + b ≤ n.
    let mut g: Vec<Vec<T>> = (0..=n).map(|a| vec![T::zero(); n - a + 1]).collect();
    g[0][0] = T::one();
    for [x, y] in args {
        for s in (1..=n).rev() {
            for a in 0..=s {
                let b = s - a;
                let mut add = T::zero();
                if a > 0 {
                    add = add + &(g[a - 1][b].clone() * x);
                }
                if b > 0 {
                    add = add + &(g[a][b - 1].clone() * y);
                }
                g[a][b] = g[a][b].clone() + &add;
            }
        }
    }
    let mut acc = T::zero();
    for (a, row) in coef.iter().enumerate() {
        for (b, c) in row.iter().enumerate().filter(|(b, _)| a + b <= n) {
            // n!/(a! b! (n−a−b)!) = C(n, a) · C(n − a, b)
            let multinomial = binomial(n, a) * binomial(n - a, b);
            acc = acc + &(c.clone() * &g[a][b] * &recip_int::<T>(&multinomial));
        }
    }
    Ok(acc)
}

/// The polar form of the tensor-product polynomial
/// `p(x, y) = Σ coef[a][b] xᵃ yᵇ` of bidegree ≤ (m, n) (source 003
/// Definition 1.3): `B_{(m,n)}[p](u; v) = Σ coef[a][b] e_a(u)/C(m, a) ·
/// e_b(v)/C(n, b)`.
///
/// # Errors
///
/// [`Error::Shape`] if a coefficient index exceeds (m, n) or the argument
/// counts are not m and n.
///
/// # Examples
///
/// ```
/// use exact_bezier::{blossom::polar_tensor, ratio};
/// use exact_bezier::BigRational;
/// // p = x·y, bidegree (1, 1): B[u₁; v₁] = u₁ v₁
/// let z = ratio::<BigRational>(0, 1);
/// let c = vec![vec![z.clone(), z.clone()], vec![z, ratio(1, 1)]];
/// assert_eq!(polar_tensor(&c, (1, 1), &[ratio(2, 1)], &[ratio(5, 1)]).unwrap(), ratio(10, 1));
/// ```
pub fn polar_tensor<T: Scalar>(
    coef: &[Vec<T>],
    (m, n): (usize, usize),
    us: &[T],
    vs: &[T],
) -> Result<T, Error> {
    if coef.len() > m + 1 || coef.iter().any(|r| r.len() > n + 1) || us.len() != m || vs.len() != n
    {
        return Err(Error::Shape(format!(
            "a bidegree ({m}, {n}) polar form needs at most ({}, {}) coefficients and ({m}, {n}) arguments, not ({}, {})",
            m + 1,
            n + 1,
            us.len(),
            vs.len()
        )));
    }
    let (eu, ev) = (elementary(us, m), elementary(vs, n));
    let mut acc = T::zero();
    for (a, row) in coef.iter().enumerate() {
        for (b, c) in row.iter().enumerate() {
            let k = recip_int::<T>(&(binomial(m, a) * binomial(n, b)));
            acc = acc + &(c.clone() * &eu[a] * &ev[b] * &k);
        }
    }
    Ok(acc)
}
