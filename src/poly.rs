//! [`Poly`]: sparse multivariate polynomials over Q with named variables — the
//! symbolic instantiation of [`Scalar`].
//!
//! Running a generic algorithm on `Poly` values (symbols for parameters,
//! control points and weights) turns it into a computation on formulas: an
//! identity that comes out `== 0` holds for **all** values of the symbols.
//!
//! Variables are interned by name in a process-wide table, so `Poly::var("a")`
//! always denotes the same variable. A polynomial is a map from monomials
//! (sorted lists of `(variable, exponent)`) to non-zero rational coefficients;
//! the representation is canonical, so `==` is exact equality of polynomials.
//!
//! # Examples
//!
//! ```
//! use exact_bezier::Poly;
//! let (a, b) = (Poly::var("a"), Poly::var("b"));
//! let lhs = (a.clone() + &b).pow(2);
//! let rhs = a.pow(2) + Poly::from_int(2) * &a * &b + b.pow(2);
//! assert_eq!(lhs, rhs);
//! assert_eq!(lhs.to_string(), "a^2 + 2*a*b + b^2");
//! ```

use crate::scalar::Scalar;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::sync::{Mutex, OnceLock};

/// The process-wide table of variable names; a variable's id is its index.
fn registry() -> &'static Mutex<Vec<String>> {
    static REGISTRY: OnceLock<Mutex<Vec<String>>> = OnceLock::new();
    REGISTRY.get_or_init(|| Mutex::new(Vec::new()))
}

fn intern(name: &str) -> u32 {
    let mut table = registry().lock().unwrap_or_else(|e| e.into_inner());
    if let Some(i) = table.iter().position(|n| n == name) {
        return i as u32;
    }
    table.push(name.to_string());
    (table.len() - 1) as u32
}

fn name_of(id: u32) -> String {
    let table = registry().lock().unwrap_or_else(|e| e.into_inner());
    table[id as usize].clone()
}

/// A monomial: `(variable id, exponent)` pairs sorted by id, exponents > 0.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Monomial(Vec<(u32, u32)>);

impl Monomial {
    fn mul(&self, other: &Monomial) -> Monomial {
        let (a, b) = (&self.0, &other.0);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a[i].0.cmp(&b[j].0) {
                std::cmp::Ordering::Less => {
                    out.push(a[i]);
                    i += 1;
                }
                std::cmp::Ordering::Greater => {
                    out.push(b[j]);
                    j += 1;
                }
                std::cmp::Ordering::Equal => {
                    out.push((a[i].0, a[i].1 + b[j].1));
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend_from_slice(&b[j..]);
        Monomial(out)
    }

    /// Exponent of variable `id` (0 if absent).
    fn exponent(&self, id: u32) -> u32 {
        self.0.iter().find(|(v, _)| *v == id).map_or(0, |(_, e)| *e)
    }

    /// The monomial with variable `id` removed.
    fn without(&self, id: u32) -> Monomial {
        Monomial(self.0.iter().copied().filter(|(v, _)| *v != id).collect())
    }

    fn total_degree(&self) -> u32 {
        self.0.iter().map(|(_, e)| e).sum()
    }
}

/// A polynomial in named variables with rational coefficients.
///
/// Implements [`Scalar`] (not `Field`: it has no division and no sign).
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Poly {
    terms: BTreeMap<Monomial, BigRational>,
}

impl Poly {
    /// The variable named `name`.
    pub fn var(name: &str) -> Poly {
        let mut terms = BTreeMap::new();
        terms.insert(Monomial(vec![(intern(name), 1)]), BigRational::one());
        Poly { terms }
    }

    /// `n` variables `prefix0, prefix1, …`.
    ///
    /// ```
    /// use exact_bezier::Poly;
    /// let p = Poly::vars("p", 3);
    /// assert_eq!(p[2].to_string(), "p2");
    /// ```
    pub fn vars(prefix: &str, n: usize) -> Vec<Poly> {
        (0..n).map(|i| Poly::var(&format!("{prefix}{i}"))).collect()
    }

    /// The constant `q`.
    pub fn constant(q: BigRational) -> Poly {
        let mut terms = BTreeMap::new();
        if !q.is_zero() {
            terms.insert(Monomial::default(), q);
        }
        Poly { terms }
    }

    /// The integer constant `n`.
    pub fn from_int(n: i64) -> Poly {
        Poly::constant(BigRational::from_integer(BigInt::from(n)))
    }

    /// `self^e`.
    pub fn pow(&self, e: u32) -> Poly {
        self.pow_u32(e)
    }

    /// Number of non-zero terms.
    pub fn num_terms(&self) -> usize {
        self.terms.len()
    }

    /// The constant value if the polynomial has no variables.
    pub fn as_constant(&self) -> Option<BigRational> {
        match self.terms.len() {
            0 => Some(BigRational::zero()),
            1 => self.terms.get(&Monomial::default()).cloned(),
            _ => None,
        }
    }

    /// The names of the variables that occur, sorted by name.
    pub fn variables(&self) -> Vec<String> {
        let mut ids: Vec<u32> = self
            .terms
            .keys()
            .flat_map(|m| m.0.iter().map(|(v, _)| *v))
            .collect();
        ids.sort_unstable();
        ids.dedup();
        let mut names: Vec<String> = ids.into_iter().map(name_of).collect();
        names.sort();
        names
    }

    /// Degree in the variable `name` (0 for the zero polynomial).
    pub fn degree_in(&self, name: &str) -> u32 {
        let id = intern(name);
        self.terms.keys().map(|m| m.exponent(id)).max().unwrap_or(0)
    }

    /// Total degree (0 for constants and for the zero polynomial).
    pub fn total_degree(&self) -> u32 {
        self.terms
            .keys()
            .map(Monomial::total_degree)
            .max()
            .unwrap_or(0)
    }

    /// The coefficient of `name^k`, a polynomial in the other variables:
    /// `self = Σ_k coeff_of(name, k) · name^k`.
    ///
    /// ```
    /// use exact_bezier::Poly;
    /// let (x, y) = (Poly::var("x"), Poly::var("y"));
    /// let p = x.pow(2) * &y + x.clone() * Poly::from_int(3) + Poly::from_int(1);
    /// assert_eq!(p.coeff_of("x", 2), y);
    /// assert_eq!(p.coeff_of("x", 0), Poly::from_int(1));
    /// ```
    pub fn coeff_of(&self, name: &str, k: u32) -> Poly {
        let id = intern(name);
        let mut terms = BTreeMap::new();
        for (m, c) in &self.terms {
            if m.exponent(id) == k {
                terms.insert(m.without(id), c.clone());
            }
        }
        Poly { terms }
    }

    /// Substitute the polynomial `value` for the variable `name`.
    ///
    /// ```
    /// use exact_bezier::Poly;
    /// let (x, y) = (Poly::var("x"), Poly::var("y"));
    /// let p = x.pow(2) + Poly::from_int(1);
    /// assert_eq!(p.subst("x", &(y.clone() + Poly::from_int(1))), y.pow(2) + Poly::from_int(2) * &y + Poly::from_int(2));
    /// ```
    pub fn subst(&self, name: &str, value: &Poly) -> Poly {
        let id = intern(name);
        let mut powers: HashMap<u32, Poly> = HashMap::new();
        let mut out = Poly::zero();
        for (m, c) in &self.terms {
            let e = m.exponent(id);
            let rest = Poly {
                terms: BTreeMap::from([(m.without(id), c.clone())]),
            };
            if e == 0 {
                out = out + rest;
                continue;
            }
            let pw = powers.entry(e).or_insert_with(|| value.pow(e)).clone();
            out = out + rest * pw;
        }
        out
    }

    /// Substitute the rational `value` for the variable `name`.
    pub fn subst_rational(&self, name: &str, value: &BigRational) -> Poly {
        self.subst(name, &Poly::constant(value.clone()))
    }

    /// Evaluate with every variable given a rational value; `None` if a
    /// variable that occurs is missing from `values`.
    ///
    /// ```
    /// use exact_bezier::{Poly, ratio};
    /// let p = Poly::var("x") * Poly::var("y");
    /// assert_eq!(p.eval(&[("x", ratio(1, 2)), ("y", ratio(4, 1))]), Some(ratio(2, 1)));
    /// assert_eq!(p.eval(&[("x", ratio(1, 2))]), None);
    /// ```
    pub fn eval(&self, values: &[(&str, BigRational)]) -> Option<BigRational> {
        let ids: Vec<(u32, &BigRational)> = values.iter().map(|(n, v)| (intern(n), v)).collect();
        let mut acc = BigRational::zero();
        for (m, c) in &self.terms {
            let mut t = c.clone();
            for (v, e) in &m.0 {
                let val = ids.iter().find(|(id, _)| id == v)?.1;
                t *= num_traits::pow(val.clone(), *e as usize);
            }
            acc += t;
        }
        Some(acc)
    }

    /// Reduce modulo the relation `name^d = replacement`: every power
    /// `name^e` with `e ≥ d` is rewritten as `name^{e−d} · replacement`,
    /// repeatedly, until the degree in `name` is below `d` (`replacement`
    /// must have degree < d in `name`). This is the normal form in
    /// `Q[…, name]/(name^d − replacement)`, e.g. `s² = 1 − c²` for
    /// trigonometric identities or `r³ = radicand` for cube roots.
    ///
    /// **Panics if `d` is 0 or `replacement` has degree ≥ `d` in `name`.**
    ///
    /// ```
    /// use exact_bezier::Poly;
    /// let (s, c) = (Poly::var("s"), Poly::var("c"));
    /// let one = Poly::from_int(1);
    /// let rel = one.clone() - c.pow(2);
    /// assert_eq!((s.pow(2) + c.pow(2)).reduce_power("s", 2, &rel), one);
    /// assert_eq!(s.pow(3).reduce_power("s", 2, &rel), s.clone() - s * c.pow(2));
    /// ```
    pub fn reduce_power(&self, name: &str, d: u32, replacement: &Poly) -> Poly {
        assert!(d > 0 && replacement.degree_in(name) < d, "invalid relation");
        let id = intern(name);
        let mut cur = self.clone();
        while cur.degree_in(name) >= d {
            let mut out = Poly::zero();
            for (m, c) in &cur.terms {
                let e = m.exponent(id);
                let mut rest = m.without(id);
                if e >= d {
                    if e > d {
                        rest = rest.mul(&Monomial(vec![(id, e - d)]));
                    }
                    let term = Poly {
                        terms: BTreeMap::from([(rest, c.clone())]),
                    };
                    out = out + term * replacement;
                } else {
                    out.add_term(m.clone(), c.clone());
                }
            }
            cur = out;
        }
        cur
    }

    /// Multiply by a rational constant.
    pub fn scale(&self, q: &BigRational) -> Poly {
        if q.is_zero() {
            return Poly::zero();
        }
        Poly {
            terms: self.terms.iter().map(|(m, c)| (m.clone(), c * q)).collect(),
        }
    }

    /// The terms as `(variables with exponents, coefficient)`, in the
    /// canonical order.
    pub fn terms(&self) -> impl Iterator<Item = (Vec<(String, u32)>, &BigRational)> {
        self.terms
            .iter()
            .map(|(m, c)| (m.0.iter().map(|(v, e)| (name_of(*v), *e)).collect(), c))
    }

    fn add_term(&mut self, m: Monomial, c: BigRational) {
        use std::collections::btree_map::Entry;
        match self.terms.entry(m) {
            Entry::Vacant(e) => {
                if !c.is_zero() {
                    e.insert(c);
                }
            }
            Entry::Occupied(mut e) => {
                *e.get_mut() += c;
                if e.get().is_zero() {
                    e.remove();
                }
            }
        }
    }

    fn mul_ref(&self, other: &Poly) -> Poly {
        let mut out = Poly::zero();
        for (ma, ca) in &self.terms {
            for (mb, cb) in &other.terms {
                out.add_term(ma.mul(mb), ca * cb);
            }
        }
        out
    }
}

impl Zero for Poly {
    fn zero() -> Self {
        Poly {
            terms: BTreeMap::new(),
        }
    }
    fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }
}

impl One for Poly {
    fn one() -> Self {
        Poly::from_int(1)
    }
}

impl Add<&Poly> for Poly {
    type Output = Poly;
    fn add(mut self, rhs: &Poly) -> Poly {
        for (m, c) in &rhs.terms {
            self.add_term(m.clone(), c.clone());
        }
        self
    }
}
impl Add for Poly {
    type Output = Poly;
    fn add(self, rhs: Poly) -> Poly {
        self + &rhs
    }
}
impl Sub<&Poly> for Poly {
    type Output = Poly;
    fn sub(mut self, rhs: &Poly) -> Poly {
        for (m, c) in &rhs.terms {
            self.add_term(m.clone(), -c.clone());
        }
        self
    }
}
impl Sub for Poly {
    type Output = Poly;
    fn sub(self, rhs: Poly) -> Poly {
        self - &rhs
    }
}
impl Mul<&Poly> for Poly {
    type Output = Poly;
    fn mul(self, rhs: &Poly) -> Poly {
        self.mul_ref(rhs)
    }
}
impl Mul for Poly {
    type Output = Poly;
    fn mul(self, rhs: Poly) -> Poly {
        self.mul_ref(&rhs)
    }
}
impl Neg for Poly {
    type Output = Poly;
    fn neg(mut self) -> Poly {
        for c in self.terms.values_mut() {
            *c = -c.clone();
        }
        self
    }
}

impl Scalar for Poly {
    fn from_i64(n: i64) -> Self {
        Poly::from_int(n)
    }
    fn from_rational(q: &BigRational) -> Self {
        Poly::constant(q.clone())
    }
}

impl fmt::Debug for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Poly({self})")
    }
}

/// Deterministic display order of a monomial: by variable name, then by
/// descending exponent (independent of interning order).
fn sort_key(m: &Monomial) -> Vec<(String, i64)> {
    let mut key: Vec<(String, i64)> =
        m.0.iter()
            .map(|(v, e)| (name_of(*v), -(*e as i64)))
            .collect();
    key.sort();
    key
}

/// Readable form: terms by descending total degree, then by variable order;
/// `3/2*a^2*b - a + 1`.
impl fmt::Display for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return write!(f, "0");
        }
        let mut terms: Vec<(&Monomial, &BigRational)> = self.terms.iter().collect();
        terms.sort_by(|a, b| {
            b.0.total_degree().cmp(&a.0.total_degree()).then_with(|| {
                // Higher powers of alphabetically earlier variables first.
                sort_key(a.0).cmp(&sort_key(b.0))
            })
        });
        for (k, (m, c)) in terms.into_iter().enumerate() {
            let negative = c.is_negative();
            let mag = c.abs();
            match (k, negative) {
                (0, true) => write!(f, "-")?,
                (0, false) => {}
                (_, true) => write!(f, " - ")?,
                (_, false) => write!(f, " + ")?,
            }
            let vars: Vec<String> = sort_key(m)
                .into_iter()
                .map(|(v, e)| if e == -1 { v } else { format!("{v}^{}", -e) })
                .collect();
            if vars.is_empty() {
                write!(f, "{mag}")?;
            } else if mag.is_one() {
                write!(f, "{}", vars.join("*"))?;
            } else {
                write!(f, "{}*{}", mag, vars.join("*"))?;
            }
        }
        Ok(())
    }
}

impl Poly {
    /// The partial derivative `∂/∂name` (0 if `name` does not occur).
    ///
    /// ```
    /// use exact_bezier::Poly;
    /// let (x, y) = (Poly::var("x"), Poly::var("y"));
    /// let p = x.pow(3) * &y + y.clone();
    /// assert_eq!(p.derivative("x"), Poly::from_int(3) * x.pow(2) * &y);
    /// ```
    pub fn derivative(&self, name: &str) -> Poly {
        let id = intern(name);
        let mut out = Poly::zero();
        for (m, c) in &self.terms {
            let e = m.exponent(id);
            if e > 0 {
                let mut rest = m.without(id);
                if e > 1 {
                    rest = rest.mul(&Monomial(vec![(id, e - 1)]));
                }
                out.add_term(rest, c.clone() * BigRational::from_integer(e.into()));
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::ratio;

    #[test]
    fn ring_laws_on_samples() {
        let (x, y, z) = (Poly::var("x"), Poly::var("y"), Poly::var("z"));
        let a = x.clone() * &y - Poly::from_int(3);
        let b = y.pow(3) + x.clone();
        let c = z.clone() - x.clone() * ratio::<Poly>(1, 2);
        assert_eq!(a.clone() * &b, b.clone() * &a);
        assert_eq!((a.clone() + &b) * &c, a.clone() * &c + b.clone() * &c);
        assert_eq!(a.clone() - &a, Poly::zero());
        assert_eq!((a.clone() * &b) * &c, a * (b * c));
    }

    #[test]
    fn degree_and_coefficients() {
        let (x, y) = (Poly::var("x"), Poly::var("y"));
        let p = x.pow(3) * &y + x.clone() * y.pow(2);
        assert_eq!(p.degree_in("x"), 3);
        assert_eq!(p.degree_in("y"), 2);
        assert_eq!(p.total_degree(), 4);
        assert_eq!(p.coeff_of("y", 2), x);
        assert!(p.as_constant().is_none());
        assert_eq!(Poly::zero().as_constant(), Some(BigRational::zero()));
    }

    #[test]
    fn substitution_composes() {
        let (x, t) = (Poly::var("x"), Poly::var("t"));
        let p = x.pow(2) - x.clone();
        let q = p.subst("x", &(t.clone() * ratio::<Poly>(2, 1)));
        assert_eq!(
            q,
            t.pow(2) * Poly::from_int(4) - t.clone() * Poly::from_int(2)
        );
        assert_eq!(q.subst_rational("t", &ratio(1, 2)), Poly::zero());
    }

    #[test]
    fn display_is_readable() {
        let (a, b) = (Poly::var("α2"), Poly::var("α1"));
        let p = -(a.pow(3)) * &b + a.clone() * ratio::<Poly>(1, 3) - Poly::from_int(1);
        assert_eq!(p.to_string(), "-α1*α2^3 + 1/3*α2 - 1");
        assert_eq!(Poly::zero().to_string(), "0");
    }
}
