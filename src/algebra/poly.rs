//! [`Poly`]: sparse multivariate polynomials over Q with named variables — the
//! symbolic instantiation of [`Scalar`].
//!
//! Running a generic algorithm on `Poly` values (symbols for parameters,
//! control points and weights) turns it into a computation on formulas: an
//! identity that comes out `== 0` holds for **all** values of the symbols.
//!
//! Variables are interned by name in a process-wide table, so `Poly::var("a")`
//! always denotes the same variable.
//!
//! # Representation (built for speed on proofs)
//!
//! A polynomial is `(1/d)·Σ c_m·m`: integer coefficients `c_m` ([`Int`]:
//! `i128` until it overflows) over one positive common denominator `d`, with
//! `gcd(d, c_m…) = 1`. Terms are kept in a vector sorted by a monomial order,
//! and each monomial packs its `(variable, exponent)` factors into machine
//! words (up to six inline). So a sum is one merge, a product is a heap
//! merge of sorted streams (no map, no sort), and the integer arithmetic of a
//! typical identity never allocates and never runs a gcd per term (the
//! denominator is reduced once per operation, and only when it is not 1).
//! Products of operands with three or more terms, and powers, run on
//! exponent vectors packed into one `u64` per monomial for the operation
//! (`packed`): the order is integer order, a monomial product one addition.
//! The representation is canonical, so `==` is exact equality of
//! polynomials.
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

use crate::algebra::int::Int;
use crate::algebra::scalar::Scalar;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::collections::HashMap;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::ops::{Add, Mul, Neg, Sub};
use std::sync::{Mutex, OnceLock};

mod monomial;
mod packed;
mod power;
mod terms;

use monomial::Monomial;
use packed::Packing;
use terms::{content_with, divide, is_negative, is_one, mul, sum_scaled, Terms};

/// The process-wide table of variable names; a variable's id is its index.
#[derive(Default)]
struct Registry {
    names: Vec<String>,
    ids: HashMap<String, u32>,
}

fn registry() -> &'static Mutex<Registry> {
    static REGISTRY: OnceLock<Mutex<Registry>> = OnceLock::new();
    REGISTRY.get_or_init(|| Mutex::new(Registry::default()))
}

fn intern(name: &str) -> u32 {
    let mut table = registry().lock().unwrap_or_else(|e| e.into_inner());
    if let Some(&i) = table.ids.get(name) {
        return i;
    }
    let id = u32::try_from(table.names.len()).expect("fewer than 2^32 variables");
    table.names.push(name.to_string());
    table.ids.insert(name.to_string(), id);
    id
}

fn name_of(id: u32) -> String {
    let table = registry().lock().unwrap_or_else(|e| e.into_inner());
    table.names[id as usize].clone()
}

/// A polynomial in named variables with rational coefficients.
///
/// Implements [`Scalar`] (not `Field`: it has no division and no sign).
#[derive(Clone, PartialEq)]
pub struct Poly {
    /// Integer coefficients, sorted by monomial, non-zero.
    terms: Terms,
    /// The positive common denominator, coprime to the coefficients (1 for 0).
    den: Int,
}

impl Poly {
    /// `terms / den` brought to canonical form (`den > 0`).
    fn normalized(mut terms: Terms, den: Int) -> Poly {
        if terms.is_empty() {
            return Poly::zero();
        }
        let den = if is_negative(&den) {
            terms::scale(&mut terms, &Int::Small(-1));
            -den
        } else {
            den
        };
        if is_one(&den) {
            return Poly { terms, den };
        }
        let g = content_with(&terms, &den);
        divide(&mut terms, &g);
        Poly {
            terms,
            den: den.div_exact(&g),
        }
    }

    /// The constant term `c` times `m`, over `den`.
    fn term(m: Monomial, c: Int, den: Int) -> Poly {
        if c.is_zero() {
            return Poly::zero();
        }
        Poly::normalized(vec![(m, c)], den)
    }

    /// The variable named `name`.
    pub fn var(name: &str) -> Poly {
        Poly::term(
            Monomial::power(intern(name), 1),
            Int::Small(1),
            Int::Small(1),
        )
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
        Poly::term(
            Monomial::default(),
            Int::from_ref(q.numer()),
            Int::from_ref(q.denom()),
        )
    }

    /// The integer constant `n`.
    pub fn from_int(n: i64) -> Poly {
        Poly::term(Monomial::default(), Int::Small(n.into()), Int::Small(1))
    }

    /// `self^e`.
    ///
    /// With two to `e + 2` terms, by the power-series recurrence
    /// `f·D(f^e) = e·D(f)·f^e` solved term by term (see `power`:
    /// `(#self − 1)·#self^e` term products), else by repeated
    /// multiplication with `self` on packed monomials (see `packed`):
    /// `Σ_k #(self^k)·#self` term products and no squaring of a large
    /// intermediate, which on sparse operands costs far more (Monagan &
    /// Pearce, *Sparse polynomial powering using heaps*, 2012). The integer
    /// part needs no normalization: by Gauss's lemma the content of `P^e` is
    /// `content(P)^e`, coprime to `den^e`.
    pub fn pow(&self, e: u32) -> Poly {
        if e < 2 || self.terms.len() < 2 {
            return crate::algebra::scalar::pow(self, e);
        }
        let den = crate::algebra::scalar::pow(&self.den, e);
        // On operands whose products never coincide, the recurrence costs
        // about (#self − 1)/e of repeated multiplication (both counted in
        // term products), so up to 9/8 of it at #self = e + 2; coinciding
        // products shrink #self^e and favour it (p^8 of 10 terms: 0.6×).
        if self.terms.len() <= e as usize + 2
            && let Some(terms) = power::power(&self.terms, e)
        {
            return Poly { terms, den };
        }
        let Some(packing) = Packing::for_product(&[&self.terms], u64::from(e)) else {
            return crate::algebra::scalar::pow(self, e);
        };
        let base = packing.pack(&self.terms);
        let mut acc = base.mul(&base);
        for _ in 2..e {
            acc = acc.mul(&base);
        }
        Poly {
            terms: packing.unpack(acc),
            den,
        }
    }

    /// Number of non-zero terms.
    pub fn num_terms(&self) -> usize {
        self.terms.len()
    }

    /// The coefficient `c/den` as a rational.
    fn rational(&self, c: &Int) -> BigRational {
        BigRational::new(c.to_bigint(), self.den.to_bigint())
    }

    /// The constant value if the polynomial has no variables.
    pub fn as_constant(&self) -> Option<BigRational> {
        match self.terms.as_slice() {
            [] => Some(BigRational::zero()),
            [(m, c)] if m.is_one() => Some(self.rational(c)),
            _ => None,
        }
    }

    /// The names of the variables that occur, sorted by name.
    pub fn variables(&self) -> Vec<String> {
        let mut ids: Vec<u32> = self
            .terms
            .iter()
            .flat_map(|(m, _)| m.factors().map(|(v, _)| v))
            .collect();
        ids.sort_unstable();
        ids.dedup();
        let mut names: Vec<String> = ids.into_iter().map(name_of).collect();
        names.sort();
        names
    }

    /// Degree in the variable `name` (0 for the zero polynomial).
    pub fn degree_in(&self, name: &str) -> u32 {
        self.degree_in_id(intern(name))
    }

    fn degree_in_id(&self, id: u32) -> u32 {
        self.terms
            .iter()
            .map(|(m, _)| m.exponent(id))
            .max()
            .unwrap_or(0)
    }

    /// Total degree (0 for constants and for the zero polynomial).
    pub fn total_degree(&self) -> u32 {
        let d = self
            .terms
            .iter()
            .map(|(m, _)| m.total_degree())
            .max()
            .unwrap_or(0);
        u32::try_from(d).unwrap_or(u32::MAX)
    }

    /// The coefficient polynomials in variable `id`: `self = Σ_k out[k]·x^k`.
    /// Each stays sorted: dropping `x` from monomials with the same
    /// exponent of `x` keeps their order.
    fn coefficients_in(&self, id: u32) -> Vec<Poly> {
        let mut out: Vec<Terms> = vec![Vec::new(); self.degree_in_id(id) as usize + 1];
        for (m, c) in &self.terms {
            out[m.exponent(id) as usize].push((m.with_exponent(id, 0), c.clone()));
        }
        out.into_iter()
            .map(|t| Poly::normalized(t, self.den.clone()))
            .collect()
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
        let terms = self
            .terms
            .iter()
            .filter(|(m, _)| m.exponent(id) == k)
            .map(|(m, c)| (m.with_exponent(id, 0), c.clone()))
            .collect();
        Poly::normalized(terms, self.den.clone())
    }

    /// The coefficients `out` with `self = Σ_k out[k]·names[k]`, in one
    /// pass over the terms (the coefficients of a map that is linear in
    /// symbolic inputs, without one scan per input); `None` unless `self`
    /// is linear and homogeneous in the names: every term of degree exactly
    /// 1 in them together (no term free of them, none with a square or a
    /// product of two), so the identity holds exactly.
    ///
    /// ```
    /// use exact_bezier::Poly;
    /// let (x, y, z) = (Poly::var("x"), Poly::var("y"), Poly::var("z"));
    /// let p = x.clone() * &z + y.clone() * Poly::from_int(3);
    /// assert_eq!(p.linear_coefficients(&["x", "y"]), Some(vec![z.clone(), Poly::from_int(3)]));
    /// assert_eq!((p.clone() + z.clone()).linear_coefficients(&["x", "y"]), None);
    /// assert_eq!((p + x.clone() * &y).linear_coefficients(&["x", "y"]), None);
    /// ```
    pub fn linear_coefficients(&self, names: &[&str]) -> Option<Vec<Poly>> {
        // The index of each name by variable id, in a table indexed by the
        // id (one load per factor of every term, where a hash map of the ids
        // cost a hash per factor: 19 % of the quadratic-map claim at (10, 10)).
        let ids: Vec<u32> = names.iter().map(|n| intern(n)).collect();
        let mut index = vec![None; ids.iter().max().map_or(0, |&id| id as usize + 1)];
        for (k, &id) in ids.iter().enumerate() {
            index[id as usize] = Some(k);
        }
        let mut out: Vec<Terms> = vec![Vec::new(); names.len()];
        for (m, c) in &self.terms {
            let mut named = m
                .factors()
                .filter_map(|(id, e)| Some((index.get(id as usize).copied()??, id, e)));
            match (named.next(), named.next()) {
                (Some((k, id, 1)), None) => out[k].push((m.with_exponent(id, 0), c.clone())),
                _ => return None,
            }
        }
        Some(
            out.into_iter()
                .map(|t| Poly::normalized(t, self.den.clone()))
                .collect(),
        )
    }

    /// Multiply by the monomial `x_id^e` (keeps the order).
    fn shift(mut self, id: u32, e: u32) -> Poly {
        if e > 0 {
            let x = Monomial::power(id, e);
            for (m, _) in &mut self.terms {
                *m = m.mul(&x);
            }
        }
        self
    }

    /// Substitute the polynomial `value` for the variable `name` (Horner's
    /// rule on the coefficients in `name`).
    ///
    /// ```
    /// use exact_bezier::Poly;
    /// let (x, y) = (Poly::var("x"), Poly::var("y"));
    /// let p = x.pow(2) + Poly::from_int(1);
    /// assert_eq!(p.subst("x", &(y.clone() + Poly::from_int(1))), y.pow(2) + Poly::from_int(2) * &y + Poly::from_int(2));
    /// ```
    pub fn subst(&self, name: &str, value: &Poly) -> Poly {
        let mut coeffs = self.coefficients_in(intern(name));
        let top = coeffs.pop().unwrap_or_else(Poly::zero);
        coeffs
            .into_iter()
            .rev()
            .fold(top, |acc, c| acc * value + &c)
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
            let mut t = BigRational::from_integer(c.to_bigint());
            for (v, e) in m.factors() {
                let val = ids.iter().find(|(id, _)| *id == v)?.1;
                t *= num_traits::pow(val.clone(), e as usize);
            }
            acc += t;
        }
        Some(acc / BigRational::from_integer(self.den.to_bigint()))
    }

    /// Reduce modulo the relation `name^d = replacement`: every power
    /// `name^e` with `e ≥ d` is rewritten as `name^{e−d} · replacement`,
    /// repeatedly, until the degree in `name` is below `d` (`replacement`
    /// must have degree < d in `name`). This is the normal form in
    /// `Q[…, name]/(name^d − replacement)`, e.g. `s² = 1 − c²` for
    /// trigonometric identities or `r³ = radicand` for cube roots.
    ///
    /// Works on the coefficients in `name`, from the top down: `c_e·name^e`
    /// adds `c_e·r_k` to the coefficient of `name^{e−d+k}` for each term
    /// `r_k·name^k` of the replacement.
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
        let r = replacement.coefficients_in(id);
        let mut c = self.coefficients_in(id);
        let d = d as usize;
        for e in (d..c.len()).rev() {
            let top = std::mem::take(&mut c[e]);
            if top.is_zero() {
                continue;
            }
            for (k, rk) in r.iter().enumerate() {
                if !rk.is_zero() {
                    let slot = &mut c[e - d + k];
                    *slot = std::mem::take(slot) + &(top.clone() * rk);
                }
            }
        }
        c.truncate(d);
        // Distinct powers of `name` have disjoint monomials: a merge each.
        c.into_iter()
            .enumerate()
            .fold(Poly::zero(), |acc, (e, ce)| acc + ce.shift(id, e as u32))
    }

    /// Multiply by a rational constant.
    pub fn scale(&self, q: &BigRational) -> Poly {
        if q.is_zero() {
            return Poly::zero();
        }
        let mut terms = self.terms.clone();
        terms::scale(&mut terms, &Int::from_ref(q.numer()));
        Poly::normalized(terms, mul(&self.den, &Int::from_ref(q.denom())))
    }

    /// The linear combination `Σ q_k·p_k` of polynomials `p_k` with rational
    /// factors `q_k`: every part brought to the common denominator
    /// `L = lcm(den(p_k)·den(q_k))`, then one k-way merge and one
    /// normalization (a sum of scaled copies normalizes each copy and each
    /// partial sum).
    ///
    /// ```
    /// use exact_bezier::{Poly, ratio};
    /// use exact_bezier::BigRational;
    /// let (x, y) = (Poly::var("x"), Poly::var("y"));
    /// let (a, b): (BigRational, BigRational) = (ratio(1, 2), ratio(-2, 3));
    /// let p = x.clone() + &y;
    /// assert_eq!(Poly::linear_combination([(&p, &a), (&y, &b)]), x * ratio::<Poly>(1, 2) - y * ratio::<Poly>(1, 6));
    /// ```
    pub fn linear_combination<'a>(
        parts: impl IntoIterator<Item = (&'a Poly, &'a BigRational)>,
    ) -> Poly {
        let parts = parts
            .into_iter()
            .filter(|(p, q)| !p.is_zero() && !q.is_zero())
            .map(|(p, q)| {
                let den = mul(&p.den, &Int::from_ref(q.denom()));
                (&p.terms, Int::from_ref(q.numer()), den)
            })
            .collect();
        Poly::combine(parts)
    }

    /// `Σ (n_k/d_k)·t_k` for term lists `t_k`, integers `n_k ≠ 0` and
    /// `d_k > 0`: over `L = lcm(d_k)`, each list scaled by `n_k·L/d_k`.
    /// (Packing the lists for the merge costs more than it saves: the merge
    /// touches each term once, packing and unpacking touch it twice.)
    fn combine(parts: Vec<(&Terms, Int, Int)>) -> Poly {
        let lcm = lcm_of(parts.iter().map(|(_, _, d)| d));
        let scaled: Vec<(&Terms, Int)> = parts
            .into_iter()
            .map(|(t, n, d)| (t, mul(&n, &lcm.div_exact(&d))))
            .collect();
        Poly::normalized(sum_scaled(&scaled), lcm)
    }

    /// The terms as `(variables with exponents, coefficient)`, in the
    /// canonical (monomial) order.
    pub fn terms(&self) -> impl Iterator<Item = (Vec<(String, u32)>, BigRational)> + '_ {
        self.terms.iter().map(|(m, c)| {
            let vars = m.factors().map(|(v, e)| (name_of(v), e)).collect();
            (vars, self.rational(c))
        })
    }

    /// The sum `a·self + b·other` of the integer parts, over the common
    /// denominator: `fa = L/d_self`, `fb = ±L/d_other`, `L = lcm`.
    fn add_signed(&self, other: &Poly, negate: bool) -> Poly {
        let sign = |f: Int| if negate { -f } else { f };
        if self.den == other.den {
            let t = terms::add(
                &self.terms,
                &Int::Small(1),
                &other.terms,
                &sign(Int::Small(1)),
            );
            return Poly::normalized(t, self.den.clone());
        }
        let g = self.den.gcd(&other.den);
        let fa = other.den.div_exact(&g);
        let fb = self.den.div_exact(&g);
        let t = terms::add(&self.terms, &fa, &other.terms, &sign(fb));
        Poly::normalized(t, mul(&self.den, &fa))
    }

    /// `Σ p_k·q_k` in one merge ([`terms::sum_of_shifted`]) when one factor
    /// of every product has at most two terms: the streams are the longer
    /// factor times each term of the shorter, every coefficient scaled to
    /// the common denominator `L = lcm(den p_k · den q_k)`. `None` (the
    /// caller multiplies and adds) when a product has two longer factors:
    /// those run faster on packed monomials.
    fn sum_of_products(pairs: &[(&Poly, &Poly)]) -> Option<Poly> {
        let ordered: Vec<(&Poly, &Poly)> = pairs
            .iter()
            .map(|&(p, q)| {
                if p.terms.len() >= q.terms.len() {
                    (p, q)
                } else {
                    (q, p)
                }
            })
            .collect();
        if ordered.iter().any(|(_, short)| short.terms.len() > 2) {
            return None;
        }
        let dens: Vec<Int> = ordered.iter().map(|(p, q)| mul(&p.den, &q.den)).collect();
        let lcm = lcm_of(dens.iter());
        let parts: Vec<(&Terms, &Monomial, Int)> = ordered
            .iter()
            .zip(&dens)
            .flat_map(|((long, short), d)| {
                let f = lcm.div_exact(d);
                short
                    .terms
                    .iter()
                    .map(move |(m, c)| (&long.terms, m, mul(c, &f)))
            })
            .collect();
        Some(Poly::normalized(terms::sum_of_shifted(&parts), lcm))
    }

    /// The product: on packed monomials when both operands have three or
    /// more terms and the result's exponents fit one word, else by the
    /// merge of `terms` (one or two streams, or wide exponents).
    fn mul_ref(&self, other: &Poly) -> Poly {
        let (a, b) = (&self.terms, &other.terms);
        let packing = if a.len().min(b.len()) >= 3 {
            Packing::for_product(&[a, b], 1)
        } else {
            None
        };
        let t = match packing {
            Some(p) => p.unpack(p.pack(a).mul(&p.pack(b))),
            None => terms::mul_terms(a, b),
        };
        Poly::normalized(t, mul(&self.den, &other.den))
    }
}

/// The least common multiple of positive denominators (1 for none).
fn lcm_of<'a>(dens: impl Iterator<Item = &'a Int>) -> Int {
    dens.fold(Int::Small(1), |l, d| {
        let g = l.gcd(d);
        mul(&l, &d.div_exact(&g))
    })
}

impl Eq for Poly {}

impl Hash for Poly {
    fn hash<H: Hasher>(&self, state: &mut H) {
        let int = |c: &Int, state: &mut H| match c {
            Int::Small(x) => x.hash(state),
            Int::Big(x) => x.hash(state),
        };
        for (m, c) in &self.terms {
            m.hash(state);
            int(c, state);
        }
        int(&self.den, state);
    }
}

impl Default for Poly {
    fn default() -> Poly {
        Poly::zero()
    }
}

impl Zero for Poly {
    fn zero() -> Self {
        Poly {
            terms: Vec::new(),
            den: Int::Small(1),
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
    fn add(self, rhs: &Poly) -> Poly {
        if self.is_zero() {
            return rhs.clone();
        }
        self.add_signed(rhs, false)
    }
}
impl Add for Poly {
    type Output = Poly;
    fn add(self, rhs: Poly) -> Poly {
        if self.is_zero() {
            return rhs;
        }
        self + &rhs
    }
}
impl Sub<&Poly> for Poly {
    type Output = Poly;
    fn sub(self, rhs: &Poly) -> Poly {
        self.add_signed(rhs, true)
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
        for (_, c) in &mut self.terms {
            *c = -std::mem::replace(c, Int::Small(0));
        }
        self
    }
}

/// The sum of many polynomials at once ([`Poly::linear_combination`] with
/// factors 1): adding k polynomials of N terms in all costs one k-way merge,
/// O(N log k) comparisons and N term moves, and one normalization, where a
/// left fold `acc + p` costs O(N k) (every addition merges the whole
/// accumulator).
///
/// ```
/// use exact_bezier::Poly;
/// let x = Poly::var("x");
/// let s: Poly = (0..4).map(|k| x.pow(k)).sum();
/// assert_eq!(s, Poly::from_int(1) + x.clone() + x.pow(2) + x.pow(3));
/// ```
impl std::iter::Sum for Poly {
    fn sum<I: Iterator<Item = Poly>>(iter: I) -> Poly {
        let polys: Vec<Poly> = iter.filter(|p| !p.is_zero()).collect();
        Poly::combine(
            polys
                .iter()
                .map(|p| (&p.terms, Int::Small(1), p.den.clone()))
                .collect(),
        )
    }
}

impl crate::algebra::scalar::MulAcc for Poly {
    /// `acc·a + c·x` by `Poly::sum_of_products` when it applies (the de
    /// Casteljau step by binomials), else two products and a sum.
    fn mul_acc(acc: &mut Poly, a: &Poly, c: &Poly, x: &Poly) {
        *acc = match Poly::sum_of_products(&[(acc, a), (c, x)]) {
            Some(p) => p,
            None => std::mem::take(acc) * a + &(c.clone() * x),
        };
    }
}

impl Scalar for Poly {
    fn from_i64(n: i64) -> Self {
        Poly::from_int(n)
    }
    fn from_rational(q: &BigRational) -> Self {
        Poly::constant(q.clone())
    }
    fn pow_u32(&self, e: u32) -> Self {
        self.pow(e)
    }
    fn sum_of(parts: Vec<Self>) -> Self {
        parts.into_iter().sum()
    }
    /// One merge of all the parts ([`Poly`]'s `Sum`).
    const SUMS_AT_ONCE: bool = true;
}

impl fmt::Debug for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Poly({self})")
    }
}

/// Deterministic display order of a monomial: by variable name, then by
/// descending exponent (independent of interning order).
fn sort_key(m: &Monomial) -> Vec<(String, i64)> {
    let mut key: Vec<(String, i64)> = m
        .factors()
        .map(|(v, e)| (name_of(v), -i64::from(e)))
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
        let mut terms: Vec<(&Monomial, BigRational)> = self
            .terms
            .iter()
            .map(|(m, c)| (m, self.rational(c)))
            .collect();
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
        // Lowering the exponent of one variable in every monomial that has
        // it keeps their order.
        let terms = self
            .terms
            .iter()
            .filter_map(|(m, c)| {
                let e = m.exponent(id);
                (e > 0).then(|| (m.with_exponent(id, e - 1), mul(c, &Int::Small(e.into()))))
            })
            .collect();
        Poly::normalized(terms, self.den.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;

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

    #[test]
    fn dense_power_has_multinomial_coefficients() {
        // (1 + x + y + z)^9 by the recurrence: the coefficient of
        // x^a y^b z^c is 9!/(a! b! c! (9−a−b−c)!), all C(12, 3) = 220 terms.
        let (x, y, z) = (Poly::var("x"), Poly::var("y"), Poly::var("z"));
        let p = (Poly::from_int(1) + &x + &y + &z).pow(9);
        assert_eq!(p.num_terms(), 220);
        let fact = |n: u32| (1..=n).map(i64::from).product::<i64>();
        for a in 0..=9 {
            for b in 0..=9 - a {
                for c in 0..=9 - a - b {
                    let m = x.pow(a) * &y.pow(b) * &z.pow(c);
                    let want = fact(9) / (fact(a) * fact(b) * fact(c) * fact(9 - a - b - c));
                    let got = [("x", a), ("y", b), ("z", c)]
                        .iter()
                        .fold(p.clone(), |q, &(v, e)| q.coeff_of(v, e));
                    assert_eq!(got, Poly::from_int(want), "{m}");
                }
            }
        }
    }

    #[test]
    fn recurrence_needs_a_weight_singling_out_the_least_monomial() {
        // y + x + y² (x interned first, so more significant): the least
        // monomial y ties with x in total degree, with y² in the degree in
        // x, and x has a lower degree in y. Names of this test only.
        let (x, y) = (Poly::var("weightless_x"), Poly::var("weightless_y"));
        let p = y.clone() + &x + &y.pow(2);
        assert_eq!(power::power(&p.terms, 3), None);
        let by_hand = p.clone() * &p * &p;
        assert_eq!(p.pow(3), by_hand);
    }

    mod laws {
        //! Ring laws, substitution, reduction and derivative on random
        //! polynomials, cross-checked against evaluation in `BigRational`
        //! (an independent path: no merge, no heap).
        use super::*;
        use proptest::prelude::*;

        const VARS: [&str; 3] = ["x", "y", "z"];

        /// A polynomial with up to 6 terms, exponents ≤ 3, coefficients
        /// n/d with |n| ≤ 40 (sometimes far beyond i128 after products).
        fn poly() -> impl Strategy<Value = Poly> {
            let term = (-40i64..=40, 1i64..=6, [0u32..=3, 0u32..=3, 0u32..=3]);
            proptest::collection::vec(term, 0..6).prop_map(|terms| {
                terms.into_iter().fold(Poly::zero(), |acc, (n, d, e)| {
                    let m = VARS
                        .iter()
                        .zip(e)
                        .fold(ratio::<Poly>(n, d), |m, (v, k)| m * Poly::var(v).pow(k));
                    acc + m
                })
            })
        }

        fn point() -> impl Strategy<Value = Vec<(&'static str, BigRational)>> {
            [
                (-9i64..=9, 1i64..=5),
                (-9i64..=9, 1i64..=5),
                (-9i64..=9, 1i64..=5),
            ]
            .prop_map(|v| {
                VARS.iter()
                    .zip(v)
                    .map(|(n, (a, b))| (*n, ratio(a, b)))
                    .collect()
            })
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(64))]

            #[test]
            fn ring_laws(a in poly(), b in poly(), c in poly()) {
                prop_assert_eq!(a.clone() * &b, b.clone() * &a);
                prop_assert_eq!((a.clone() * &b) * &c, a.clone() * (b.clone() * &c));
                prop_assert_eq!((a.clone() + &b) * &c, a.clone() * &c + b.clone() * &c);
                prop_assert_eq!((a.clone() + &b) - &b, a.clone());
                prop_assert_eq!(a.clone() + (-a.clone()), Poly::zero());
            }

            #[test]
            fn evaluation_is_a_homomorphism(a in poly(), b in poly(), at in point()) {
                let ev = |p: &Poly| p.eval(&at).expect("every variable has a value");
                prop_assert_eq!(ev(&(a.clone() * &b)), ev(&a) * ev(&b));
                prop_assert_eq!(ev(&(a.clone() - &b)), ev(&a) - ev(&b));
                prop_assert_eq!(ev(&a.pow(3)), num_traits::pow(ev(&a), 3));
            }

            #[test]
            fn substitution_and_derivative(a in poly(), b in poly(), at in point()) {
                let ev = |p: &Poly| p.eval(&at).expect("every variable has a value");
                // a(x := b) at the point is a at (b(point), y, z).
                let mut moved = at.clone();
                moved[0].1 = ev(&b);
                prop_assert_eq!(ev(&a.subst("x", &b)), a.eval(&moved).expect("values"));
                // Leibniz rule.
                let d = |p: &Poly| p.derivative("y");
                prop_assert_eq!(d(&(a.clone() * &b)), d(&a) * &b + a.clone() * &d(&b));
            }

            #[test]
            fn packed_product_matches_the_merge_kernel(a in poly(), b in poly(), k in 0u32..40) {
                // The packed heap against the heap on unpacked monomials,
                // with coefficients scaled by 7^k (past i128 for large k).
                // Squares (up to 21 terms) take the heap, the others the scan.
                let big = a.clone() * &Poly::from_int(7).pow(k);
                let (a2, b2) = (big.pow(2), b.pow(2) + &a);
                for (x, y) in [(&a, &b), (&big, &b), (&big, &big), (&a2, &b2)] {
                    let merged = Poly::normalized(
                        terms::mul_terms(&x.terms, &y.terms),
                        mul(&x.den, &y.den),
                    );
                    prop_assert_eq!(x.clone() * y, merged);
                }
            }

            #[test]
            fn merged_sums_match_pairwise_addition(
                parts in proptest::collection::vec((poly(), -9i64..=9, 1i64..=6), 0..7),
                k in 0u32..40,
            ) {
                // The k-way merge against a left fold of two-way merges
                // (`add_signed`), with parts scaled by 7^k (past i128).
                let big = Poly::from_int(7).pow(k);
                let parts: Vec<(Poly, BigRational)> = parts
                    .into_iter()
                    .map(|(p, n, d)| (p * &big, ratio(n, d)))
                    .collect();
                let folded = parts
                    .iter()
                    .fold(Poly::zero(), |acc, (p, q)| acc + &p.scale(q));
                let merged = Poly::linear_combination(parts.iter().map(|(p, q)| (p, q)));
                prop_assert_eq!(&merged, &folded);
                let plain = parts.iter().fold(Poly::zero(), |acc, (p, _)| acc + p);
                // The merge on unpacked monomials (the wide-exponent route).
                let lcm = parts.iter().fold(Int::Small(1), |l, (p, _)| {
                    let g = l.gcd(&p.den);
                    mul(&l, &p.den.div_exact(&g))
                });
                let lists: Vec<(&Terms, Int)> = parts
                    .iter()
                    .filter(|(p, _)| !p.is_zero())
                    .map(|(p, _)| (&p.terms, lcm.div_exact(&p.den)))
                    .collect();
                prop_assert_eq!(&Poly::normalized(sum_scaled(&lists), lcm), &plain);
                prop_assert_eq!(parts.into_iter().map(|(p, _)| p).sum::<Poly>(), plain);
            }

            #[test]
            fn fused_step_matches_products_and_sum(
                acc in poly(), x in poly(), a in poly(), c in poly(), k in 0u32..40,
            ) {
                // `acc·a + c·x` in one merge (factors of at most two terms)
                // and by the fallback (longer factors) against two products
                // and a sum, with one factor scaled past i128.
                use crate::algebra::scalar::MulAcc;
                let big = Poly::from_int(7).pow(k);
                let two = |p: &Poly| Poly::normalized(p.terms.iter().take(2).cloned().collect(), p.den.clone());
                for (a, c) in [(two(&a), two(&c) * &big), (a.clone(), c.clone() * &big)] {
                    let mut fused = acc.clone();
                    Poly::mul_acc(&mut fused, &a, &c, &x);
                    prop_assert_eq!(fused, acc.clone() * &a + &(c.clone() * &x));
                }
            }

            #[test]
            fn pow_is_repeated_multiplication(a in poly(), e in 0u32..7) {
                // By the merge kernel, one factor at a time.
                let by_merge = (0..e).fold(Poly::one(), |acc, _| {
                    Poly::normalized(terms::mul_terms(&acc.terms, &a.terms), mul(&acc.den, &a.den))
                });
                prop_assert_eq!(a.pow(e), by_merge);
            }

            #[test]
            fn recurrence_power_is_repeated_multiplication(a in poly(), e in 2u32..9, k in 0u32..40) {
                // The power-series recurrence against the merge kernel, one
                // factor at a time, with coefficients scaled by 7^k (past
                // i128 for large k) and shifted by a monomial (so the least
                // monomial is not 1 and some pairs are not divisible by it).
                let shifted = a.clone() * &Poly::var("y") * &Poly::from_int(7).pow(k);
                for base in [&a, &shifted] {
                    let Some(power) = power::power(&base.terms, e) else { continue };
                    let by_merge = (1..e).fold(base.terms.clone(), |acc, _| terms::mul_terms(&acc, &base.terms));
                    prop_assert_eq!(power, by_merge);
                }
            }

            #[test]
            fn reduce_power_is_a_normal_form(a in poly(), q in poly(), r in poly()) {
                // Relation x² = r with r of degree < 2 in x.
                let r = r.coeff_of("x", 0) + r.coeff_of("x", 1) * Poly::var("x");
                let rel = Poly::var("x").pow(2) - &r;
                let red = a.reduce_power("x", 2, &r);
                prop_assert!(red.degree_in("x") < 2);
                prop_assert_eq!((a.clone() + q * &rel).reduce_power("x", 2, &r), red);
            }
        }
    }
}
