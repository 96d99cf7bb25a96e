//! Exact univariate ([`UPoly`]) and bivariate ([`BPoly`]) polynomials in the
//! power basis over a field, with greatest common divisors.
//!
//! These carry the common-factor removal of [`minimal_degree`](crate::coincide::minimal_rect):
//! the homogeneous components of a patch, written in powers of `u` and `v`,
//! are divided by their gcd over Q. The field is generic: exact rationals for
//! the decision, the prime field [`Fp`](crate::algebra::Fp) for the fast coprimality
//! certificate. Zero tests are exact (`is_zero`), so the results are only
//! meaningful over exact fields; nothing here is used with `f64`.
//!
//! Conventions: `UPoly` holds `c_0 + c_1 x + … + c_d x^d` with `c_d ≠ 0`
//! (the zero polynomial has no coefficients); `BPoly` holds
//! `Σ_k a_k(v) u^k` with every `a_k ∈ K[v]` and `a_d ≠ 0`.
//!
//! Reference: the primitive pseudo-remainder sequence for gcds in `K[v][u]`
//! (Collins 1967; Knuth, TAOCP vol. 2, §4.6.1, Algorithm E).

use crate::algebra::poly::Poly;
use crate::algebra::scalar::Field;
use num_rational::BigRational;

/// A univariate polynomial `Σ c_k x^k` over a field, trailing zeros trimmed.
///
/// # Examples
///
/// ```
/// use exact_bezier::{algebra::UPoly, ratio};
/// use exact_bezier::BigRational;
/// let c = |v: &[i64]| UPoly::new(v.iter().map(|&x| ratio::<BigRational>(x, 1)).collect());
/// // (x − 1)(x + 2) and (x − 1)(x − 3) have gcd x − 1.
/// let a = c(&[-2, 1, 1]);
/// let b = c(&[3, -4, 1]);
/// assert_eq!(a.gcd(&b), c(&[-1, 1]));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct UPoly<T> {
    coeffs: Vec<T>,
}

impl<T: Field> UPoly<T> {
    /// The polynomial with coefficients `coeffs[k]` of `x^k` (trailing zeros
    /// are dropped).
    pub fn new(mut coeffs: Vec<T>) -> Self {
        while coeffs.last().is_some_and(|c| c.is_zero()) {
            coeffs.pop();
        }
        UPoly { coeffs }
    }

    /// The zero polynomial.
    pub fn zero() -> Self {
        UPoly { coeffs: Vec::new() }
    }

    /// The constant `c`.
    pub fn constant(c: T) -> Self {
        Self::new(vec![c])
    }

    /// The coefficients, lowest power first.
    pub fn coeffs(&self) -> &[T] {
        &self.coeffs
    }

    /// Is this the zero polynomial?
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// The degree (`None` for the zero polynomial).
    pub fn degree(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }

    /// The leading coefficient (`None` for zero).
    pub fn lead(&self) -> Option<&T> {
        self.coeffs.last()
    }

    /// `self + other`.
    pub fn add(&self, other: &Self) -> Self {
        self.zip_with(other, |a, b| a + b)
    }

    /// `self − other`.
    pub fn sub(&self, other: &Self) -> Self {
        self.zip_with(other, |a, b| a - b)
    }

    fn zip_with(&self, other: &Self, f: impl Fn(T, &T) -> T) -> Self {
        let len = self.coeffs.len().max(other.coeffs.len());
        let zero = T::zero();
        Self::new(
            (0..len)
                .map(|k| {
                    let a = self.coeffs.get(k).cloned().unwrap_or_else(T::zero);
                    f(a, other.coeffs.get(k).unwrap_or(&zero))
                })
                .collect(),
        )
    }

    /// `self · other`.
    pub fn mul(&self, other: &Self) -> Self {
        if self.is_zero() || other.is_zero() {
            return Self::zero();
        }
        let mut out = vec![T::zero(); self.coeffs.len() + other.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            for (j, b) in other.coeffs.iter().enumerate() {
                out[i + j] = out[i + j].clone() + &(a.clone() * b);
            }
        }
        Self::new(out)
    }

    /// `c · self`.
    pub fn scale(&self, c: &T) -> Self {
        Self::new(self.coeffs.iter().map(|a| a.clone() * c).collect())
    }

    /// The derivative `Σ k c_k x^(k−1)`.
    ///
    /// ```
    /// use exact_bezier::{algebra::UPoly, ratio, BigRational};
    /// // (1 + 2x + 3x²)' = 2 + 6x
    /// let c = |v: &[i64]| UPoly::new(v.iter().map(|&x| ratio::<BigRational>(x, 1)).collect());
    /// assert_eq!(c(&[1, 2, 3]).derivative(), c(&[2, 6]));
    /// ```
    pub fn derivative(&self) -> Self {
        Self::new(
            self.coeffs
                .iter()
                .enumerate()
                .skip(1)
                .map(|(k, c)| c.clone() * T::from_i64(k as i64))
                .collect(),
        )
    }

    /// The value at `x` (Horner).
    pub fn eval(&self, x: &T) -> T {
        self.coeffs
            .iter()
            .rev()
            .fold(T::zero(), |acc, c| acc * x + c)
    }

    /// Euclidean division: `(q, r)` with `self = q·d + r`, `deg r < deg d`;
    /// `None` when `d` is zero.
    pub fn div_rem(&self, d: &Self) -> Option<(Self, Self)> {
        let dd = d.degree()?;
        let lead = d.lead()?;
        let mut r = self.coeffs.clone();
        if r.len() <= dd {
            return Some((Self::zero(), self.clone()));
        }
        let mut q = vec![T::zero(); r.len() - dd];
        // One inversion, then products (exact fields: the same quotients).
        let inv = lead.recip();
        for k in (0..q.len()).rev() {
            let c = r[k + dd].clone() * &inv;
            for (i, di) in d.coeffs.iter().enumerate() {
                r[k + i] = r[k + i].clone() - &(c.clone() * di);
            }
            q[k] = c;
        }
        r.truncate(dd);
        Some((Self::new(q), Self::new(r)))
    }

    /// `self / d` when `d` divides `self` exactly, else `None`.
    pub fn div_exact(&self, d: &Self) -> Option<Self> {
        let (q, r) = self.div_rem(d)?;
        r.is_zero().then_some(q)
    }

    /// The monic multiple (leading coefficient 1); zero stays zero.
    pub fn monic(&self) -> Self {
        match self.lead() {
            Some(l) => self.scale(&l.recip()),
            None => Self::zero(),
        }
    }

    /// The monic greatest common divisor (zero iff both are zero), by
    /// Euclid's algorithm with every remainder made monic (over Q and over
    /// number fields this keeps the coefficients from growing with each
    /// step).
    pub fn gcd(&self, other: &Self) -> Self {
        let (mut a, mut b) = (self.clone(), other.monic());
        while let Some((_, r)) = a.div_rem(&b) {
            a = b;
            b = r.monic();
        }
        a.monic()
    }
}

/// A bivariate polynomial `Σ_k a_k(v) u^k` over a field, stored as
/// polynomials in `v` indexed by the power of `u`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{algebra::BPoly, ratio};
/// use exact_bezier::BigRational;
/// let q = |x: i64| ratio::<BigRational>(x, 1);
/// // grid[p][q] is the coefficient of u^p v^q.
/// // (1 + uv)(u − v) = u − v + u²v − uv²  and  (1 + uv)(2 + u) = 2 + u + 2uv + u²v.
/// let a = BPoly::from_grid(&[vec![q(0), q(-1), q(0)], vec![q(1), q(0), q(-1)], vec![q(0), q(1), q(0)]]);
/// let b = BPoly::from_grid(&[vec![q(2), q(0)], vec![q(1), q(2)], vec![q(0), q(1)]]);
/// let g = a.gcd(&b);
/// assert_eq!(g, BPoly::from_grid(&[vec![q(1), q(0)], vec![q(0), q(1)]]));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BPoly<T> {
    coeffs: Vec<UPoly<T>>,
}

impl<T: Field> BPoly<T> {
    /// The polynomial `Σ_k coeffs[k](v) u^k` (trailing zeros dropped).
    pub fn new(mut coeffs: Vec<UPoly<T>>) -> Self {
        while coeffs.last().is_some_and(UPoly::is_zero) {
            coeffs.pop();
        }
        BPoly { coeffs }
    }

    /// From a grid: `grid[p][q]` is the coefficient of `u^p v^q`.
    pub fn from_grid(grid: &[Vec<T>]) -> Self {
        Self::new(grid.iter().map(|row| UPoly::new(row.clone())).collect())
    }

    /// The coefficients as a `(m + 1) × (n + 1)` grid, zero padded:
    /// `grid[p][q]` is the coefficient of `u^p v^q`.
    pub fn to_grid(&self, m: usize, n: usize) -> Vec<Vec<T>> {
        (0..=m)
            .map(|p| {
                (0..=n)
                    .map(|q| {
                        self.coeffs
                            .get(p)
                            .and_then(|c| c.coeffs().get(q))
                            .cloned()
                            .unwrap_or_else(T::zero)
                    })
                    .collect()
            })
            .collect()
    }

    /// The coefficients `a_k(v)` of `u^k`.
    pub fn coeffs(&self) -> &[UPoly<T>] {
        &self.coeffs
    }

    /// Is this the zero polynomial?
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// Degree in `u` (`None` for zero).
    pub fn deg_u(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }

    /// Degree in `v` (`None` for zero).
    pub fn deg_v(&self) -> Option<usize> {
        self.coeffs.iter().filter_map(UPoly::degree).max()
    }

    /// Is this a non-zero constant?
    pub fn is_nonzero_constant(&self) -> bool {
        self.deg_u() == Some(0) && self.coeffs[0].degree() == Some(0)
    }

    /// The content in `K[v]`: the monic gcd of the coefficients `a_k(v)`.
    pub fn content(&self) -> UPoly<T> {
        self.coeffs.iter().fold(UPoly::zero(), |g, c| {
            if g.degree() == Some(0) {
                g
            } else {
                g.gcd(c)
            }
        })
    }

    fn map_coeffs(&self, f: impl Fn(&UPoly<T>) -> UPoly<T>) -> Self {
        Self::new(self.coeffs.iter().map(f).collect())
    }

    /// The primitive part `self / content` (zero stays zero).
    pub fn primitive_part(&self) -> Self {
        let c = self.content();
        if c.is_zero() {
            return self.clone();
        }
        self.map_coeffs(|a| {
            a.div_exact(&c)
                .expect("the content divides every coefficient")
        })
    }

    fn lead(&self) -> Option<&UPoly<T>> {
        self.coeffs.last()
    }

    /// `self · c(v)`.
    pub fn mul_v(&self, c: &UPoly<T>) -> Self {
        self.map_coeffs(|a| a.mul(c))
    }

    /// `self − u^shift · other`.
    fn sub_shifted(&self, other: &Self, shift: usize) -> Self {
        let len = self.coeffs.len().max(other.coeffs.len() + shift);
        let mut out: Vec<UPoly<T>> = (0..len)
            .map(|k| self.coeffs.get(k).cloned().unwrap_or_else(UPoly::zero))
            .collect();
        for (k, c) in other.coeffs.iter().enumerate() {
            out[k + shift] = out[k + shift].sub(c);
        }
        Self::new(out)
    }

    /// A pseudo-remainder of `self` by `d` in `K[v][u]`:
    /// `lc(d)^e · self − q·d` with `deg_u < deg_u d`; `None` if `d` is zero.
    fn pseudo_rem(&self, d: &Self) -> Option<Self> {
        let dd = d.deg_u()?;
        let ld = d.lead()?;
        let mut r = self.clone();
        while let Some(dr) = r.deg_u().filter(|&k| k >= dd) {
            let lr = r.lead().cloned().unwrap_or_else(UPoly::zero);
            r = r.mul_v(ld).sub_shifted(&d.mul_v(&lr), dr - dd);
        }
        Some(r)
    }

    /// The greatest common divisor in `K[u, v]`, normalized so that its
    /// leading coefficient (highest power of `u`, then of `v`) is 1; zero iff
    /// both are zero.
    ///
    /// `gcd = gcd(cont A, cont B) · pp(last non-zero remainder)` of the
    /// primitive pseudo-remainder sequence of `pp A`, `pp B` in `K[v][u]`.
    pub fn gcd(&self, other: &Self) -> Self {
        if self.is_zero() {
            return other.normalized();
        }
        if other.is_zero() {
            return self.normalized();
        }
        let c = self.content().gcd(&other.content());
        let (mut a, mut b) = (self.primitive_part(), other.primitive_part());
        if a.deg_u() < b.deg_u() {
            std::mem::swap(&mut a, &mut b);
        }
        while let Some(r) = a.pseudo_rem(&b) {
            a = b;
            b = r.primitive_part();
        }
        a.primitive_part().mul_v(&c).normalized()
    }

    /// `self / c(v)` when `c` divides every coefficient, else `None`.
    pub fn div_v(&self, c: &UPoly<T>) -> Option<Self> {
        let q: Option<Vec<UPoly<T>>> = self.coeffs.iter().map(|a| a.div_exact(c)).collect();
        q.map(Self::new)
    }

    /// `self · other`.
    pub fn mul(&self, other: &Self) -> Self {
        let mut out =
            vec![UPoly::zero(); (self.coeffs.len() + other.coeffs.len()).saturating_sub(1)];
        for (i, a) in self.coeffs.iter().enumerate() {
            for (j, b) in other.coeffs.iter().enumerate() {
                out[i + j] = out[i + j].add(&a.mul(b));
            }
        }
        Self::new(out)
    }

    /// The same polynomial with `u` and `v` exchanged.
    pub fn transpose(&self) -> Self {
        let (Some(m), Some(n)) = (self.deg_u(), self.deg_v()) else {
            return self.clone();
        };
        let g = self.to_grid(m, n);
        Self::new(
            (0..=n)
                .map(|q| UPoly::new(g.iter().map(|r| r[q].clone()).collect()))
                .collect(),
        )
    }

    /// The multiple with leading coefficient 1 (zero stays zero).
    pub fn normalized(&self) -> Self {
        match self.lead().and_then(UPoly::lead) {
            Some(l) => {
                let inv = UPoly::constant(l.recip());
                self.mul_v(&inv)
            }
            None => self.clone(),
        }
    }

    /// `self / d` when `d` divides `self` exactly in `K[u, v]`, else `None`.
    pub fn div_exact(&self, d: &Self) -> Option<Self> {
        let dd = d.deg_u()?;
        let ld = d.lead()?;
        let mut r = self.clone();
        let mut q = vec![UPoly::zero(); r.coeffs.len().saturating_sub(dd)];
        while let Some(dr) = r.deg_u().filter(|&k| k >= dd) {
            let c = r.lead()?.div_exact(ld)?;
            r = r.sub_shifted(&d.mul_v(&c), dr - dd);
            q[dr - dd] = c;
        }
        r.is_zero().then(|| Self::new(q))
    }
}

impl BPoly<BigRational> {
    /// The symbolic polynomial `Σ a_{p,q} u^p v^q` in the named variables.
    ///
    /// ```
    /// use exact_bezier::{algebra::BPoly, ratio};
    /// let g = BPoly::from_grid(&[vec![ratio(1, 1), ratio(0, 1)], vec![ratio(0, 1), ratio(2, 1)]]);
    /// assert_eq!(g.to_poly("u", "v").to_string(), "2*u*v + 1");
    /// ```
    pub fn to_poly(&self, u: &str, v: &str) -> Poly {
        let (u, v) = (Poly::var(u), Poly::var(v));
        let mut sum = Poly::from_int(0);
        for (p, c) in self.coeffs.iter().enumerate() {
            for (q, a) in c.coeffs().iter().enumerate() {
                sum = sum + u.pow(p as u32) * v.pow(q as u32) * Poly::constant(a.clone());
            }
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    type Q = BigRational;

    fn grid(g: &[&[i64]]) -> BPoly<Q> {
        BPoly::from_grid(
            &g.iter()
                .map(|r| r.iter().map(|&x| ratio::<Q>(x, 1)).collect())
                .collect::<Vec<_>>(),
        )
    }

    fn product(a: &BPoly<Q>, b: &BPoly<Q>) -> BPoly<Q> {
        let mut out = BPoly::new(vec![]);
        for (k, c) in a.coeffs().iter().enumerate() {
            let shifted = BPoly::new(
                std::iter::repeat_n(UPoly::zero(), k)
                    .chain(b.mul_v(c).coeffs().iter().cloned())
                    .collect(),
            );
            out = out.sub_shifted(&shifted, 0);
        }
        out.mul_v(&UPoly::constant(ratio(-1, 1)))
    }

    #[test]
    fn gcd_recovers_planted_factors() {
        // g = (1 + uv)(v − 2), mixed and pure-v factors.
        let g = product(&grid(&[&[1, 0], &[0, 1]]), &grid(&[&[-2, 1]]));
        let a = product(&g, &grid(&[&[1, 2], &[3, 0], &[0, 0, 5]]));
        let b = product(&g, &grid(&[&[0, 7], &[1, 1, 1]]));
        let got = a.gcd(&b);
        assert_eq!(got, g.normalized());
        assert!(a.div_exact(&got).is_some());
        assert_eq!(product(&a.div_exact(&got).unwrap(), &got), a);
    }

    #[test]
    fn coprime_gives_one() {
        let a = grid(&[&[1, 2], &[3, 4]]);
        let b = grid(&[&[5, 0, 1], &[0, 1]]);
        assert!(a.gcd(&b).is_nonzero_constant());
        assert!(a.div_exact(&b).is_none());
    }

    #[test]
    fn univariate_division() {
        let c = |v: &[i64]| UPoly::new(v.iter().map(|&x| ratio::<Q>(x, 1)).collect());
        let (q, r) = c(&[1, 0, 0, 1]).div_rem(&c(&[1, 1])).unwrap();
        assert_eq!(q, c(&[1, -1, 1]));
        assert!(r.is_zero());
        assert_eq!(c(&[1, 2, 3]).eval(&ratio(2, 1)), ratio(17, 1));
    }
}
