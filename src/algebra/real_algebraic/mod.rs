//! [`RealAlgebraic`]: exact real algebraic numbers, a [`Field`] +
//! [`Ordered`] scalar with exact n-th roots ([`Roots`]), so that every
//! generic algorithm of the crate (standard forms, curvature, arcs, …) runs
//! on numbers such as `√6/6` or `∛(3/2)` without rounding.
//!
//! ## Two representations, one type
//!
//! - **Radical sums** (`radical`): `Σ c_k ∏ b_j^{e_{k,j}}`, rationals `c_k`
//!   times products of real radicals of pairwise coprime integers. Ring
//!   operations are sparse polynomial arithmetic, `==` is structural (the
//!   monomials are linearly independent over Q, Mordell 1953), division goes
//!   through the minimal polynomial. Rationals, `√q`, `∛q`, and everything
//!   the sources' standard forms, arcs and trigonometric angles produce stay
//!   here: this is the number-field fast path.
//! - **Isolated roots** (`root`): a monic square-free polynomial over Q and
//!   an isolating interval with rational endpoints. Needed for roots of sums
//!   (`∛(1 + √2)`), `CRootOf(x⁵ − x − 1, 0)`, and anything combined with
//!   them. Sums and products use resultants (`Res_z(p(z), q(t − z))`,
//!   `Res_z(p(z), z^{deg q} q(t/z))`), made square-free; the result's root is
//!   isolated by refining the operands until the Sturm count of the new
//!   polynomial on the combined enclosure is 1. Degrees multiply, so long
//!   chains in this representation are expensive (`deg(α+β) ≤ deg α·deg β`).
//!
//! ## Exactness contract
//!
//! Zero is decided exactly (structurally for radical sums; for isolated
//! roots the value is irrational by invariant and a resultant result whose
//! root is rational is recognised: a rational root `k/L` of an integer
//! polynomial with leading coefficient `L` is found by refining to width
//! `< 1/L`). Signs and comparisons refine enclosures until they exclude 0;
//! they terminate because the value is non-zero. No tolerance anywhere.
//!
//! Reference: Cohen, *A Course in Computational Algebraic Number Theory*
//! (1993), §3.3, §4.1; Yap, *Fundamental Problems of Algorithmic Algebra*
//! (2000), ch. 7; Mordell, *On the linear independence of algebraic
//! numbers*, Pacific J. Math. 3 (1953) 625–630.

pub(crate) mod descartes;
pub(crate) mod field;
mod memo;
pub(crate) mod modular;
pub(crate) mod polys;
pub(crate) mod radical;
pub(crate) mod root;
pub mod text;

use crate::algebra::int::common_denominator;
use crate::algebra::scalar::{Field, Ordered, Roots, Scalar};
use crate::algebra::upoly::UPoly;
use crate::error::Error;
use field::{FieldNum, NumberField};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use polys::QPoly;
use radical::RadicalSum;
use root::RootNum;
use std::cmp::Ordering;
use std::sync::Arc;

/// An exact real algebraic number.
///
/// ```text
/// value = Σ c_k ∏ b_j^{e_kj}   (radical sum)     or   the root of p in (lo, hi)
/// ```
///
/// # Examples
///
/// ```
/// use exact_bezier::{algebra::RealAlgebraic, Roots, Scalar};
/// let r = |n: i64| RealAlgebraic::from_i64(n);
/// let (s2, s3) = (r(2).nth_root(2).unwrap(), r(3).nth_root(2).unwrap());
/// let sum = s2.clone() + &s3;
/// // (√2 + √3)² = 5 + 2√6, exactly.
/// assert_eq!(sum.clone() * &sum, r(5) + r(2) * r(6).nth_root(2).unwrap());
/// assert_eq!(sum.to_string(), "sqrt(2) + sqrt(3)");
/// assert!(s2 < s3);
/// ```
#[derive(Clone)]
pub struct RealAlgebraic(Repr);

#[derive(Clone)]
enum Repr {
    Radical(RadicalSum),
    Root(Arc<RootNum>),
    Field(Arc<FieldValue>),
}

/// A non-zero, non-rational element of a number field ([`field`]), with its
/// isolated-root form computed once when asked for (text, defining
/// polynomial, rationality).
struct FieldValue {
    num: FieldNum,
    plain: std::sync::OnceLock<RealAlgebraic>,
}

impl RealAlgebraic {
    fn radical(s: RadicalSum) -> Self {
        RealAlgebraic(Repr::Radical(s))
    }

    /// The rational `q` (by value; [`Scalar::from_rational`] takes a reference).
    pub(crate) fn rat(q: BigRational) -> Self {
        Self::radical(RadicalSum::rational(q))
    }

    /// `Some(q)` when the number is rational.
    pub fn as_rational(&self) -> Option<BigRational> {
        match &self.0 {
            Repr::Radical(s) => s.as_rational(),
            Repr::Root(_) => None,
            Repr::Field(_) => self.plain().as_rational(),
        }
    }

    /// The element `c(θ)` of field `k`: a rational when `c` reduces to a
    /// constant (zero when `c(θ) = 0`).
    fn from_field(k: Arc<NumberField>, c: &QPoly) -> Self {
        match FieldNum::new(k, c) {
            None => Self::zero(),
            Some(n) if n.a.degree() == Some(0) => Self::rat(n.a.coeffs()[0].clone()),
            Some(num) => RealAlgebraic(Repr::Field(Arc::new(FieldValue {
                num,
                plain: std::sync::OnceLock::new(),
            }))),
        }
    }

    /// This number as a field element (`Err` with the value when it is
    /// rational): a radical sum lives in the field of its radicals
    /// ([`Self::radical_parts`]; its own minimal polynomial's field only
    /// when that one would be over the limit); an isolated root generates
    /// its own field (defining polynomial, isolating interval), a negative
    /// one as `−θ` for the positive `θ = −x`, so that `x` and `−x` share a
    /// field.
    fn field_parts(&self) -> Result<FieldNum, BigRational> {
        if let Repr::Radical(s) = &self.0 {
            if let Some(q) = s.as_rational() {
                return Err(q);
            }
            if let Some(x) = Self::radical_parts(s, None) {
                return Ok(x);
            }
        }
        if !matches!(self.0, Repr::Field(_)) && self.signum() < 0 {
            return (-self.clone()).field_parts().map(|x| x.neg());
        }
        match &self.0 {
            Repr::Radical(s) => {
                let p = s.minimal_polynomial().monic();
                let (lo, hi) = field::isolate_value(&p, |prec| s.enclosure(prec));
                Ok(FieldNum::generator(NumberField::new(p, lo, hi)))
            }
            Repr::Root(r) => {
                let (lo, hi) = r.interval();
                Ok(FieldNum::generator(NumberField::new(
                    r.poly().clone(),
                    lo,
                    hi,
                )))
            }
            Repr::Field(v) => Ok(v.num.clone()),
        }
    }

    /// The irrational radical sum `s` as an element of a number field that
    /// contains `within` (when given) and the fields `Q(b^{1/n})` of its
    /// radicals ([`radical_field`]: one per base `b`, `n` the least common
    /// denominator of `b`'s exponents): every sum of the same radicals
    /// lands in the same field, of the degree the radicals span
    /// ([`RealAlgebraic::span_degree`]) times `within`'s, and a field that
    /// already holds those radicals is not extended. `None` when a field
    /// would be over [`crate::limits::MAX_FIELD_DEGREE`].
    fn radical_parts(s: &RadicalSum, within: Option<&Arc<NumberField>>) -> Option<FieldNum> {
        let bases = s.bases();
        let mut gens = Vec::with_capacity(bases.len());
        let mut k = within.cloned();
        for b in &bases {
            let n = s.exponent_lcm(b);
            // Q(b^{1/n}) has degree n: over the limit, no field is built
            // (and xⁿ − b is not even written down).
            if n > crate::limits::MAX_FIELD_DEGREE as i64 {
                return None;
            }
            let g = radical_field(b, n);
            k = Some(match k {
                None => g.clone(),
                Some(k) => field::extend(&k, &g)?,
            });
            gens.push((g, n));
        }
        let k = k?;
        let images = gens
            .iter()
            .map(|(g, _)| field::image_in(&k, g))
            .collect::<Option<Vec<QPoly>>>()?;
        let terms: Vec<(BigRational, Vec<u32>)> = s
            .terms()
            .iter()
            .map(|(m, c)| {
                let exps = bases
                    .iter()
                    .zip(&gens)
                    .map(|(b, (_, n))| {
                        m.0.iter()
                            .find(|(x, _)| x == b)
                            .map_or(0, |(_, e)| (e * *n).to_integer() as u32)
                    })
                    .collect();
                (c.clone(), exps)
            })
            .collect();
        FieldNum::new(k.clone(), &field::sum_of_monomials(&k, &images, &terms))
    }

    /// Both numbers in one field, `(K, a, b)` with `self = a(θ)`,
    /// `other = b(θ)`; `None` when that field would be over
    /// [`crate::limits::MAX_FIELD_DEGREE`]. A radical sum meets a field
    /// element in the field extended by its radicals only.
    fn common(&self, other: &Self) -> Option<(Arc<NumberField>, QPoly, QPoly)> {
        let radical = |x: &Self| match &x.0 {
            Repr::Radical(s) if s.as_rational().is_none() => Some(s.clone()),
            _ => None,
        };
        match (radical(self), radical(other)) {
            (Some(s), None) => {
                let b = other.field_parts().ok()?;
                let a = Self::radical_parts(&s, Some(&b.field))?;
                return field::unify(&a, &b);
            }
            (None, Some(s)) => {
                let a = self.field_parts().ok()?;
                let b = Self::radical_parts(&s, Some(&a.field))?;
                return field::unify(&a, &b);
            }
            _ => {}
        }
        let constant = |q: BigRational| UPoly::constant(q);
        match (self.field_parts(), other.field_parts()) {
            (Ok(a), Ok(b)) => field::unify(&a, &b),
            (Ok(a), Err(q)) => Some((a.field, a.a, constant(q))),
            (Err(q), Ok(b)) => Some((b.field, constant(q), b.a)),
            (Err(_), Err(_)) => None,
        }
    }

    /// The isolated-root (or radical) form of a field element, computed
    /// once: the minimal polynomial of `a(θ)` ([`FieldNum::minimal_polynomial`]),
    /// whose root is isolated from `a(θ)`'s enclosures and then simplified
    /// (rationals and `x^n − c` become radical sums).
    fn plain(&self) -> Self {
        match &self.0 {
            Repr::Field(v) => v
                .plain
                .get_or_init(|| {
                    let known = polys::Isolator::new(&v.num.minimal_polynomial());
                    Self::isolate_enclosed(&known, |prec| v.num.enclosure(prec))
                })
                .clone(),
            _ => self.clone(),
        }
    }

    /// The `k`-th real root (0-based, increasing) of a non-zero polynomial
    /// over Q, like SymPy's `CRootOf(p, k)` for real roots.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] when `p` is zero or has at most `k` real roots.
    ///
    /// ```
    /// use exact_bezier::{algebra::RealAlgebraic, algebra::UPoly, ratio};
    /// let p = UPoly::new(vec![ratio(-2, 1), ratio(0, 1), ratio(1, 1)]); // x² − 2
    /// let r = RealAlgebraic::root_of(&p, 1).unwrap();
    /// assert_eq!(r.to_string(), "sqrt(2)");
    /// ```
    pub fn root_of(p: &UPoly<BigRational>, k: usize) -> Result<Self, Error> {
        if p.is_zero() {
            return Err(Error::Domain("the zero polynomial has no roots".into()));
        }
        let b = polys::cauchy_bound(p);
        let found = Self::real_roots_in(p, &-b.clone(), &b);
        let n = found.len();
        found.into_iter().nth(k).ok_or_else(|| {
            Error::Domain(format!(
                "root index {k} is out of range: the polynomial has {n} real roots"
            ))
        })
    }

    /// Every distinct real root of a non-zero polynomial `p` in the open
    /// interval `(a, b)`, increasing.
    ///
    /// Cost: the square-free part (a check modulo a prime in the generic
    /// case), then one Descartes count of `O(d²)` integer operations per
    /// bisection step (`descartes`; the number of steps grows with
    /// `log(1/root separation)`).
    pub fn real_roots_in(p: &UPoly<BigRational>, a: &BigRational, b: &BigRational) -> Vec<Self> {
        if p.degree().unwrap_or(0) == 0 || a >= b {
            return Vec::new();
        }
        let known = polys::Isolator::new(p);
        let bound = BigRational::from_integer(known.sign.root_bound());
        let lo = if *a > -bound.clone() {
            a.clone()
        } else {
            -bound.clone()
        };
        let hi = if *b < bound { b.clone() } else { bound.clone() };
        if lo >= hi {
            return Vec::new();
        }
        // Descartes counts need ends that are not roots: a root at an end
        // is outside the open interval, so isolate on (−B, B) and filter.
        let ends_clear = known.sign.sign_at(&lo) != 0 && known.sign.sign_at(&hi) != 0;
        let (lo, hi) = if ends_clear {
            (lo, hi)
        } else {
            (-bound.clone(), bound)
        };
        let (above, below) = (Self::rat(a.clone()), Self::rat(b.clone()));
        descartes::isolate(&known.sign, &lo, &hi)
            .into_iter()
            .map(|(l, h)| Self::isolated(known.sf.clone(), l, h))
            .filter(|x| ends_clear || (*x > above && *x < below))
            .collect()
    }

    /// The root of the square-free `p` isolated in `(lo, hi)` (endpoints not
    /// roots), simplified: rational roots and roots of `x^n − c` come back as
    /// radical sums.
    fn isolated(p: QPoly, lo: BigRational, hi: BigRational) -> Self {
        let node = RootNum::new(p, lo, hi);
        match rational_root_in(&node) {
            Some(s) => Self::radical(s),
            None => Self::irrational(node),
        }
    }

    /// An isolated root known to be irrational (an irrational shifted,
    /// scaled, negated or inverted by rationals); `x^n − c` still becomes a
    /// radical.
    fn irrational(node: RootNum) -> Self {
        match binomial_root(&node) {
            Some(s) => Self::radical(s),
            None => RealAlgebraic(Repr::Root(Arc::new(node))),
        }
    }

    /// The number defined by polynomial `p` (any non-zero multiple of its
    /// minimal polynomial) and enclosures `enclose(prec)` that shrink to it
    /// as `prec` grows.
    fn from_enclosures(p: &QPoly, enclose: impl Fn(u32) -> (BigRational, BigRational)) -> Self {
        Self::isolate_enclosed(&polys::Isolator::new(p), enclose)
    }

    /// The root of `known.sf` that the enclosures `enclose(prec)` shrink
    /// to: refined until the enclosure holds exactly one root.
    fn isolate_enclosed(
        known: &polys::Isolator,
        enclose: impl Fn(u32) -> (BigRational, BigRational),
    ) -> Self {
        match polys::isolate_by_enclosures(&known.sign, enclose) {
            Ok((lo, hi)) => Self::isolated(known.sf.clone(), lo, hi),
            Err(q) => Self::rat(q),
        }
    }

    /// The degree of the defining polynomial when the number is held as an
    /// isolated root of a general polynomial (`CRootOf`), `None` for a sum
    /// of radicals. Arithmetic on such numbers goes through resultants, so
    /// the degrees of results multiply: what cost models need to know.
    ///
    /// ```
    /// use exact_bezier::algebra::RealAlgebraic;
    /// let r: RealAlgebraic = "CRootOf(x**5 - x - 1, 0)".parse().unwrap();
    /// assert_eq!(r.root_degree(), Some(5));
    /// assert_eq!("sqrt(2)".parse::<RealAlgebraic>().unwrap().root_degree(), None);
    /// ```
    pub fn root_degree(&self) -> Option<usize> {
        match &self.0 {
            Repr::Radical(_) => None,
            Repr::Root(r) => r.poly().degree(),
            Repr::Field(v) => Some(v.num.field.degree()),
        }
    }

    /// The most bits (numerator + denominator) of a rational in this
    /// number's representation: a radical sum's coefficients (with its
    /// bases), an isolated root's polynomial, a field element's polynomial
    /// and its field's. No arithmetic: what cost models need to know.
    pub fn coefficient_bits(&self) -> u64 {
        match &self.0 {
            Repr::Radical(s) => s.coefficient_bits(),
            Repr::Root(r) => polys::poly_bits(r.poly()),
            Repr::Field(v) => polys::poly_bits(&v.num.a).max(polys::poly_bits(v.num.field.poly())),
        }
    }

    /// The degree over Q of the field that the numbers `xs` span, as the
    /// exact arithmetic represents it, and whether they are all sums of
    /// radicals (whose arithmetic needs no field: their degree only bounds
    /// root indices). Radical sums count the degree of the radicals they
    /// use (`RadicalSum::span_degree`); every other number (an isolated
    /// root, a field element) the degree of its field, distinct fields
    /// multiplying, as their compositum needs (`deg K₁K₂ ≤ deg K₁·deg K₂`),
    /// except that a field (or a radical's field `Q(b^{1/n})`) another one
    /// of them was built from is counted once, inside that one.
    /// Saturates at `u64::MAX`. Cost: a gcd-free basis of the radicals'
    /// bases; no arithmetic on the numbers.
    ///
    /// ```
    /// use exact_bezier::algebra::RealAlgebraic;
    /// let x = |t: &str| t.parse::<RealAlgebraic>().unwrap();
    /// // √2, √3, √6 span Q(√2, √3), of degree 4.
    /// assert_eq!(RealAlgebraic::span_degree(&[x("sqrt(2)"), x("sqrt(3) + 1"), x("sqrt(6)")]), (4, true));
    /// // A root of x³ − x − 1 and √2: 3 · 2.
    /// assert_eq!(RealAlgebraic::span_degree(&[x("CRootOf(x**3 - x - 1, 0)"), x("sqrt(2)/2")]), (6, false));
    /// ```
    pub fn span_degree<'a>(xs: impl IntoIterator<Item = &'a RealAlgebraic>) -> (u64, bool) {
        let mut radicals = Vec::new();
        let mut roots: Vec<(field::Key, u64)> = Vec::new();
        let mut fields: Vec<Arc<NumberField>> = Vec::new();
        for x in xs {
            match &x.0 {
                Repr::Radical(s) => radicals.extend(s.root_indices()),
                Repr::Root(r) => {
                    let key = (r.poly().coeffs().to_vec(), r.index());
                    if !roots.iter().any(|(k, _)| *k == key) {
                        roots.push((key, r.poly().degree().unwrap_or(1) as u64));
                    }
                }
                Repr::Field(v) => {
                    if !fields.iter().any(|f| f.key() == v.num.field.key()) {
                        fields.push(v.num.field.clone());
                    }
                }
            }
        }
        // A field built from another (or from a radical's field
        // `Q(b^{1/n})`, radical_field) already holds it: counted once.
        let held = |key: &field::Key, own: Option<&NumberField>| {
            fields
                .iter()
                .any(|f| own.is_none_or(|o| o.key() != f.key()) && f.holds(key))
        };
        let radicals_only = roots.is_empty() && fields.is_empty();
        radicals.sort();
        radicals.dedup();
        // Only a radical field of degree n ≤ MAX_FIELD_DEGREE is ever
        // built (radical_parts), so only such a radical can be held.
        let small = |n: u64| n <= crate::limits::MAX_FIELD_DEGREE as u64;
        radicals.retain(|(b, n)| !(small(*n) && held(&radical_key(b, *n), None)));
        let degree = fields
            .iter()
            .filter(|f| !held(&f.key(), Some(f)))
            .map(|f| f.degree() as u64)
            .chain(roots.iter().filter(|(k, _)| !held(k, None)).map(|r| r.1))
            .fold(RadicalSum::span_degree(&radicals), u64::saturating_mul);
        (degree, radicals_only)
    }

    /// Refuse (before computing it) an `n`-th root of `self` whose field
    /// would be over [`crate::limits::MAX_FIELD_DEGREE`], or, for a radical
    /// `c·∏b^e`, whose root index would be over
    /// [`crate::limits::MAX_RADICAL_INDEX`]. `what` names the number.
    pub(crate) fn check_root_degree(&self, n: u32, what: &str) -> Result<(), Error> {
        let (d, radical) = Self::span_degree([self]);
        let single = matches!(&self.0, Repr::Radical(s) if s.single_term().is_some());
        crate::limits::check_field_degree(d.saturating_mul(n.into()), radical && single, what)
    }

    /// Refuse (before computing it) an arithmetic operation on `self` and
    /// `other` whose field would be over [`crate::limits::MAX_FIELD_DEGREE`]
    /// (two radical sums need no field). `what` names the numbers. The
    /// operators `+ − × ÷` cannot fail: on such a pair they fall back to
    /// resultants, whose degree is the product of the operands' (unbounded
    /// cost along a chain); a caller that must stay bounded (the Python
    /// `Algebraic`) checks here first.
    ///
    /// ```
    /// use exact_bezier::algebra::RealAlgebraic;
    /// let x = |t: &str| t.parse::<RealAlgebraic>().unwrap();
    /// let (a, b) = (x("CRootOf(x**7 - x - 1, 0)"), x("CRootOf(x**5 - x - 1, 0)"));
    /// // Degree 7 · 5 = 35 > 32.
    /// assert!(a.check_pair_degree(&b, "a + b").is_err());
    /// assert!(a.check_pair_degree(&x("sqrt(2)"), "a + √2").is_ok());
    /// ```
    pub fn check_pair_degree(&self, other: &Self, what: &str) -> Result<(), Error> {
        let (d, radical) = Self::span_degree([self, other]);
        if radical {
            return Ok(());
        }
        crate::limits::check_field_degree(d, false, what)
    }

    /// A polynomial over Q with this number as a root: the minimal
    /// polynomial for radical sums, the square-free defining polynomial
    /// otherwise.
    pub fn defining_polynomial(&self) -> UPoly<BigRational> {
        match &self.0 {
            Repr::Radical(s) => s.minimal_polynomial(),
            Repr::Root(r) => r.poly().clone(),
            Repr::Field(_) => self.plain().defining_polynomial(),
        }
    }

    /// Rational bounds `lo ≤ self ≤ hi` that shrink to the value as `prec`
    /// grows (width `O(2^{−prec})`); `lo = hi` for rationals.
    ///
    /// ```
    /// use exact_bezier::{algebra::RealAlgebraic, Roots, Scalar, ratio};
    /// let s2 = RealAlgebraic::from_i64(2).nth_root(2).unwrap();
    /// let (lo, hi) = s2.enclosure(20);
    /// assert!(lo < ratio(14143, 10000) && hi > ratio(14142, 10000));
    /// ```
    pub fn enclosure(&self, prec: u32) -> (BigRational, BigRational) {
        match &self.0 {
            Repr::Radical(s) => s.enclosure(prec),
            Repr::Root(r) => r.enclosure(prec),
            Repr::Field(v) => v.num.enclosure(prec),
        }
    }

    /// The exact sign: `−1`, `0` or `1`.
    pub fn signum(&self) -> i32 {
        match &self.0 {
            Repr::Radical(s) => s.signum(),
            Repr::Root(r) => r.signum(),
            Repr::Field(v) => v.num.signum(),
        }
    }

    /// `self + other` through resultants (at least one operand an isolated
    /// root): a rational operand shifts the polynomial instead.
    fn add_general(&self, other: &Self) -> Self {
        if let Some(q) = other.as_rational() {
            return self.shifted(&q);
        }
        if let Some(q) = self.as_rational() {
            return other.shifted(&q);
        }
        let p = polys::sum_poly(&self.defining_polynomial(), &other.defining_polynomial());
        Self::from_enclosures(&p, |prec| {
            let (a, b) = self.enclosure(prec);
            let (c, d) = other.enclosure(prec);
            (a + c, b + d)
        })
    }

    fn shifted(&self, q: &BigRational) -> Self {
        match &self.0 {
            Repr::Radical(s) => Self::radical(s.add(&RadicalSum::rational(q.clone()))),
            Repr::Root(r) => {
                let (lo, hi) = r.interval();
                Self::irrational(RootNum::new(
                    polys::shift(r.poly(), q).monic(),
                    lo + q,
                    hi + q,
                ))
            }
            Repr::Field(_) => self.plain().shifted(q),
        }
    }

    fn scaled(&self, q: &BigRational) -> Self {
        if q.is_zero() {
            return Self::zero();
        }
        match &self.0 {
            Repr::Radical(s) => Self::radical(s.scale(q)),
            Repr::Root(r) => {
                let (lo, hi) = r.interval();
                let (a, b) = (lo * q, hi * q);
                let (lo, hi) = if q.is_positive() { (a, b) } else { (b, a) };
                Self::irrational(RootNum::new(
                    polys::scale_roots(r.poly(), q).monic(),
                    lo,
                    hi,
                ))
            }
            Repr::Field(_) => self.plain().scaled(q),
        }
    }

    fn mul_general(&self, other: &Self) -> Self {
        if let Some(q) = other.as_rational() {
            return self.scaled(&q);
        }
        if let Some(q) = self.as_rational() {
            return other.scaled(&q);
        }
        // Neither is zero, so a factor x may be divided out of each
        // defining polynomial (q(0) ≠ 0 for the product resultant).
        let strip = |p: QPoly| {
            let mut c = p.coeffs().to_vec();
            while c.first().is_some_and(Zero::is_zero) {
                c.remove(0);
            }
            UPoly::new(c)
        };
        let p = polys::product_poly(
            &strip(self.defining_polynomial()),
            &strip(other.defining_polynomial()),
        );
        Self::from_enclosures(&p, |prec| {
            let (a, b) = self.enclosure(prec);
            let (c, d) = other.enclosure(prec);
            let products = [&a * &c, &a * &d, &b * &c, &b * &d];
            let lo = products.iter().min().expect("four").clone();
            let hi = products.iter().max().expect("four").clone();
            (lo, hi)
        })
    }

    /// `1/self`. **Panics if `self` is zero.**
    fn recip_exact(&self) -> Self {
        match &self.0 {
            Repr::Radical(s) => Self::radical(s.recip()),
            Repr::Field(v) => Self::from_field(v.num.field.clone(), &v.num.recip().a),
            Repr::Root(r) => {
                r.signum(); // refines until 0 ∉ [lo, hi]
                let (lo, hi) = r.interval();
                let (lo, hi) = if lo.is_zero() || hi.is_zero() {
                    r.enclosure(64 + r.interval().0.denom().bits() as u32)
                } else {
                    (lo, hi)
                };
                Self::irrational(RootNum::new(
                    polys::reverse(r.poly()).monic(),
                    hi.recip(),
                    lo.recip(),
                ))
            }
        }
    }

    /// `num(α) / den(α)` at `α = self`, exactly, without arithmetic in the
    /// field of `α` (whose degrees would multiply):
    ///
    /// ```text
    /// p̃ = p / gcd(p, den)                    p: the defining polynomial of α
    /// R(x) = Res_y(p̃(y), x·den(y) − num(y)) = lc^e ∏ (x·den(α_i) − num(α_i))
    /// ```
    ///
    /// `R` has degree `deg p̃` and the value among its roots; the root is
    /// isolated by rational interval evaluation of `num` and `den` on
    /// enclosures of `α`. Cost: that of `value_polynomial` (`deg p̃ + 1`
    /// fraction-free Sylvester determinants of size at most `2 deg p̃ − 1`)
    /// and the isolation.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] when `den(α) = 0`.
    ///
    /// ```
    /// use exact_bezier::{algebra::{RealAlgebraic, UPoly}, Roots, Scalar, ratio};
    /// let s2 = RealAlgebraic::from_i64(2).nth_root(2).unwrap();
    /// let p = |c: &[i64]| UPoly::new(c.iter().map(|&v| ratio(v, 1)).collect());
    /// // (1 + α²) / (1 + α) at α = √2 is 3/(1 + √2) = 3√2 − 3.
    /// let v = s2.rational_function_at(&p(&[1, 0, 1]), &p(&[1, 1])).unwrap();
    /// assert_eq!(v, RealAlgebraic::from_i64(3) * &s2 - &RealAlgebraic::from_i64(3));
    /// ```
    pub fn rational_function_at(
        &self,
        num: &UPoly<BigRational>,
        den: &UPoly<BigRational>,
    ) -> Result<Self, Error> {
        let pole = || Error::Domain(format!("the denominator vanishes at {self}"));
        if let Some(a) = self.as_rational() {
            let d = den.eval(&a);
            return if d.is_zero() {
                Err(pole())
            } else {
                Ok(Self::rat(num.eval(&a) / d))
            };
        }
        let p = self.defining_polynomial();
        let common = polys::gcd(&p, den);
        if common.degree().unwrap_or(0) > 0
            && Self::real_roots_in(
                &common,
                &-polys::cauchy_bound(&common),
                &polys::cauchy_bound(&common),
            )
            .contains(self)
        {
            return Err(pole());
        }
        let p = p.div_exact(&common).expect("the gcd divides");
        Ok(self.rational_function_root(&Self::value_polynomial(&p, num, den), num, den))
    }

    /// `R(x) = ∏_{p(α) = 0} (x·den(α) − num(α))` (a resultant by Poisson's
    /// formula, up to a constant), prepared for isolation: its roots are the values `num(α)/den(α)` at the roots `α`
    /// of `p`, which must be coprime to `den`. `num` and `den` are first
    /// reduced modulo `p`; `R` is interpolated from its values at `x = 0 …
    /// deg p`, each a norm modulo `p` ([`polys::norm`]: one pseudo-division
    /// of `p` by the low-degree `x·den − num`, then a Sylvester determinant
    /// of size below `2e` for `e = max(deg num, deg den)`, not one of size
    /// `deg p + e`).
    pub(crate) fn value_polynomial(
        p: &QPoly,
        num: &UPoly<BigRational>,
        den: &UPoly<BigRational>,
    ) -> polys::Isolator {
        // num(α), den(α) only depend on num, den modulo p; one denominator
        // for both scales R by a constant.
        let reduce = |c: &UPoly<BigRational>| c.div_rem(p).expect("p is non-zero").1;
        let (num_p, den_p) = (reduce(num), reduce(den));
        let len = num_p.coeffs().len().max(den_p.coeffs().len());
        let both: Vec<BigRational> = (0..len)
            .flat_map(|i| [&num_p, &den_p].map(|c| c.coeffs().get(i).cloned().unwrap_or_default()))
            .collect();
        let (ints, _): (Vec<BigInt>, _) = common_denominator(&both);
        let big = polys::primitive_integer(p);
        let samples: Vec<BigRational> = (0..=p.degree().unwrap_or(0))
            .map(|x| {
                let x = BigInt::from(x);
                let h: Vec<BigInt> = ints.chunks(2).map(|c| &x * &c[1] - &c[0]).collect();
                polys::norm(&big, &h)
            })
            .collect();
        polys::Isolator::new(&polys::interpolate(&samples))
    }

    /// `num(α)/den(α)` at `α = self` (irrational, `den(α) ≠ 0`), given a
    /// prepared polynomial `known` that vanishes there: the root is
    /// isolated by rational interval evaluation of `num` and `den` on
    /// enclosures of `α`. Lets a caller that knows such a polynomial (an
    /// intersection's `t` is a root of `Res_s`) skip the resultant.
    pub(crate) fn rational_function_root(
        &self,
        known: &polys::Isolator,
        num: &UPoly<BigRational>,
        den: &UPoly<BigRational>,
    ) -> Self {
        let wide = BigRational::from_integer(known.sign.root_bound());
        Self::isolate_enclosed(known, |prec| {
            let (lo, hi) = self.enclosure(prec);
            let (n_lo, n_hi) = polys::eval_on_interval(num, &lo, &hi);
            let (d_lo, d_hi) = polys::eval_on_interval(den, &lo, &hi);
            if d_lo.is_positive() || d_hi.is_negative() {
                // Quotients reduced by Lehmer's gcd (num-rational's binary
                // gcd is quadratic on these enclosures' big integers).
                let (inv_lo, inv_hi) = (d_lo.recip(), d_hi.recip());
                let quotient = crate::algebra::gcd::product;
                let q = [
                    quotient(&n_lo, &inv_lo),
                    quotient(&n_lo, &inv_hi),
                    quotient(&n_hi, &inv_lo),
                    quotient(&n_hi, &inv_hi),
                ];
                let min = q.iter().min().expect("four").clone();
                let max = q.iter().max().expect("four").clone();
                (min, max)
            } else {
                (-wide.clone(), wide.clone())
            }
        })
    }

    /// The real `n`-th root of `x ≥ 0` (any sign for odd `n`).
    fn root_exact(&self, n: u32) -> Option<Self> {
        match self.signum() {
            0 => return Some(Self::zero()),
            -1 if n.is_multiple_of(2) => return None,
            -1 => return (-self.clone()).root_exact(n).map(|r| -r),
            _ => {}
        }
        if let Repr::Radical(s) = &self.0
            && let Some(r) = s.monomial_root(n)
        {
            return Some(Self::radical(r));
        }
        let enclose = |prec: u32| {
            let (lo, hi) = self.enclosure(prec * n);
            (
                root_floor(&lo, n, prec),
                root_floor(&hi, n, prec)
                    + BigRational::new(1.into(), BigInt::one() << prec as usize),
            )
        };
        if let Ok(x) = self.field_parts()
            && let Some(y) = x.root(n, enclose)
        {
            return Some(Self::from_field(y.field, &y.a));
        }
        let p = polys::compose_power(&self.defining_polynomial(), n);
        Some(Self::from_enclosures(&p, |prec| {
            let (lo, hi) = self.enclosure(prec * n);
            (
                root_floor(&lo, n, prec),
                root_floor(&hi, n, prec)
                    + BigRational::new(1.into(), BigInt::one() << prec as usize),
            )
        }))
    }

    /// The nearest-or-adjacent `f64`: refined until both ends of the
    /// enclosure convert to the same `f64`.
    fn to_f64_exact(&self) -> f64 {
        let mut prec = 64;
        loop {
            let (lo, hi) = self.enclosure(prec);
            let (a, b) = (lo.to_f64(), hi.to_f64());
            if a == b || prec > 4096 {
                return a;
            }
            prec *= 2;
        }
    }

    /// The value rounded to `digits` decimal places (half away from zero
    /// for rationals; irrational values are never halfway), as text.
    ///
    /// ```
    /// use exact_bezier::{algebra::RealAlgebraic, Roots, Scalar};
    /// let s2 = RealAlgebraic::from_i64(2).nth_root(2).unwrap();
    /// assert_eq!(s2.to_decimal(30), "1.414213562373095048801688724210");
    /// ```
    pub fn to_decimal(&self, digits: usize) -> String {
        let scale = BigRational::from_integer(num_traits::pow(BigInt::from(10), digits));
        let half = BigRational::new(1.into(), 2.into());
        let rounded = match self.as_rational() {
            Some(q) => {
                let x = q.abs() * &scale + &half;
                let r = x.floor().to_integer();
                if q.is_negative() {
                    -r
                } else {
                    r
                }
            }
            None => {
                let mut prec = 16 + 4 * digits as u32;
                loop {
                    let (lo, hi) = self.enclosure(prec);
                    let a = (lo * &scale + &half).floor().to_integer();
                    let b = (hi * &scale + &half).floor().to_integer();
                    if a == b {
                        break a;
                    }
                    prec *= 2;
                }
            }
        };
        decimal_text(&rounded, digits)
    }

    /// Exact equality without subtraction: radical sums compare
    /// structurally; an isolated root `r` equals `x` iff `x` is a root of
    /// `r`'s polynomial inside `r`'s isolating interval (exact evaluation in
    /// the radical field, or a common root of the gcd of both polynomials in
    /// the intersection of both intervals).
    fn same_value(&self, other: &Self) -> bool {
        match (&self.0, &other.0) {
            (Repr::Radical(a), Repr::Radical(b)) => a.add(&b.neg()).is_zero(),
            (Repr::Field(_), _) | (_, Repr::Field(_)) => match self.common(other) {
                Some((k, a, b)) => FieldNum::new(k, &a.sub(&b)).is_none(),
                None => self.plain().same_value(&other.plain()),
            },
            (Repr::Root(r), _) => other.is_isolated_root_of(r),
            (_, Repr::Root(r)) => self.is_isolated_root_of(r),
        }
    }

    fn is_isolated_root_of(&self, r: &RootNum) -> bool {
        let (lo, hi) = r.interval();
        match &self.0 {
            Repr::Radical(s) => {
                if s.as_rational().is_some() {
                    return false; // r is irrational
                }
                let value = r
                    .poly()
                    .coeffs()
                    .iter()
                    .rev()
                    .fold(RadicalSum::default(), |acc, c| {
                        acc.mul(s).add(&RadicalSum::rational(c.clone()))
                    });
                value.is_zero()
                    && s.add(&RadicalSum::rational(-lo)).signum() > 0
                    && s.add(&RadicalSum::rational(-hi)).signum() < 0
            }
            Repr::Root(t) => {
                let g = polys::gcd(r.poly(), t.poly());
                let (a, b) = t.interval();
                let (lo, hi) = (lo.max(a), hi.min(b));
                g.degree().unwrap_or(0) > 0
                    && lo < hi
                    && polys::count_roots(&polys::sturm_sequence(&g), &lo, &hi) == 1
            }
            Repr::Field(_) => self.plain().is_isolated_root_of(r),
        }
    }

    /// Exact comparison: equality decided exactly ([`Self::same_value`]),
    /// then enclosures refined until they separate (they must).
    fn compare(&self, other: &Self) -> Ordering {
        if self.same_value(other) {
            return Ordering::Equal;
        }
        let mut prec = 2;
        loop {
            let (a, b) = self.enclosure(prec);
            let (c, d) = other.enclosure(prec);
            if b < c {
                return Ordering::Less;
            }
            if d < a {
                return Ordering::Greater;
            }
            prec *= 2;
        }
    }
}

/// The field `Q(b^{1/n}) = Q[x]/(xⁿ − b)` of the positive real root of an
/// integer base `b > 1` of a radical sum (`xⁿ − b` is square-free), the
/// root isolated from the radical's enclosures. Registered, so every
/// radical sum over `b^{1/n}` shares it.
fn radical_field(b: &BigInt, n: i64) -> Arc<NumberField> {
    let mut c = vec![BigRational::zero(); n as usize + 1];
    c[0] = -BigRational::from_integer(b.clone());
    c[n as usize] = BigRational::one();
    let p = UPoly::new(c);
    let root = RadicalSum::int_power(b, radical::Exp::new(1, n));
    let (lo, hi) = field::isolate_value(&p, |prec| root.enclosure(prec));
    NumberField::new(p, lo, hi)
}

/// The key of [`radical_field`]`(b, n)`: `xⁿ − b` and the index of its
/// positive root among the real roots (the larger of two for even `n`).
fn radical_key(b: &BigInt, n: u64) -> field::Key {
    let mut c = vec![BigRational::zero(); n as usize + 1];
    c[0] = -BigRational::from_integer(b.clone());
    c[n as usize] = BigRational::one();
    (c, usize::from(n.is_multiple_of(2)))
}

/// `floor(x^{1/n} · 2^prec) / 2^prec` for `x ≥ 0` (0 for `x < 0`).
fn root_floor(x: &BigRational, n: u32, prec: u32) -> BigRational {
    if !x.is_positive() {
        return BigRational::zero();
    }
    let scaled = (x * BigRational::from_integer(BigInt::one() << (prec as usize * n as usize)))
        .floor()
        .to_integer();
    BigRational::new(scaled.nth_root(n), BigInt::one() << prec as usize)
}

/// `n / 10^digits` as a decimal string.
fn decimal_text(n: &BigInt, digits: usize) -> String {
    let neg = n.is_negative();
    let mut s = n.abs().to_string();
    if digits > 0 {
        if s.len() <= digits {
            s = format!("{}{s}", "0".repeat(digits + 1 - s.len()));
        }
        s.insert(s.len() - digits, '.');
    }
    if neg {
        format!("-{s}")
    } else {
        s
    }
}

/// The isolated root as a rational, if it is one: a rational root of an
/// integer polynomial with leading coefficient `L` is `k/L` for an integer
/// `k`, and an interval narrower than `1/L` holds at most one such point.
fn rational_root_in(node: &RootNum) -> Option<RadicalSum> {
    let ints = polys::primitive_integer(node.poly());
    if !polys::may_have_rational_root(&ints) {
        return None;
    }
    let lead = ints.last().expect("non-zero").clone();
    let prec = lead.bits() as u32 + 1;
    let (lo, hi) = node.enclosure(prec);
    let l = BigRational::from_integer(lead.clone());
    let k = (&lo * &l).ceil().to_integer();
    let candidate = BigRational::new(k, lead);
    (candidate < hi && node.poly().eval(&candidate).is_zero())
        .then(|| RadicalSum::rational(candidate))
}

/// The isolated root of `x^n − c` as `±|c|^{1/n}` (the radical form).
fn binomial_root(node: &RootNum) -> Option<RadicalSum> {
    let c = node.poly().coeffs();
    let n = c.len() - 1;
    if n == 2 {
        return Some(quadratic_root(node));
    }
    if n < 2 || c[1..n].iter().any(|x| !x.is_zero()) {
        return None;
    }
    let r = -c[0].clone();
    let sign = node.signum();
    let abs_root = RadicalSum::rational(r.abs()).monomial_root(n as u32)?;
    Some(if sign < 0 { abs_root.neg() } else { abs_root })
}

/// The irrational root of a monic quadratic `x² + c₁x + c₀` isolated by
/// `node`, as the radical sum `(−c₁ ± √(c₁² − 4c₀))/2`: the larger root
/// (`+`) when the polynomial is positive at the interval's upper end.
fn quadratic_root(node: &RootNum) -> RadicalSum {
    let c = node.poly().coeffs();
    let two = BigRational::from_integer(2.into());
    let disc = &c[1] * &c[1] - BigRational::from_integer(4.into()) * &c[0];
    let root_disc = RadicalSum::rational(disc)
        .monomial_root(2)
        .expect("two real roots: a positive discriminant");
    let larger = node.poly().eval(&node.interval().1).is_positive();
    let signed = if larger { root_disc } else { root_disc.neg() };
    signed
        .add(&RadicalSum::rational(-c[1].clone()))
        .scale(&two.recip())
}

impl std::fmt::Debug for RealAlgebraic {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{self}")
    }
}

impl PartialEq for RealAlgebraic {
    fn eq(&self, other: &Self) -> bool {
        self.same_value(other)
    }
}

impl PartialOrd for RealAlgebraic {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.compare(other))
    }
}

impl Zero for RealAlgebraic {
    fn zero() -> Self {
        Self::rat(BigRational::zero())
    }
    fn is_zero(&self) -> bool {
        matches!(&self.0, Repr::Radical(s) if s.is_zero())
    }
}

impl One for RealAlgebraic {
    fn one() -> Self {
        Self::rat(BigRational::one())
    }
}

impl std::ops::Neg for RealAlgebraic {
    type Output = Self;
    fn neg(self) -> Self {
        match &self.0 {
            Repr::Radical(s) => Self::radical(s.neg()),
            Repr::Root(r) => {
                let (lo, hi) = r.interval();
                Self::irrational(RootNum::new(polys::reflect(r.poly()).monic(), -hi, -lo))
            }
            Repr::Field(v) => Self::from_field(v.num.field.clone(), &v.num.neg().a),
        }
    }
}

impl std::ops::Add<&RealAlgebraic> for RealAlgebraic {
    type Output = Self;
    fn add(self, other: &Self) -> Self {
        match (&self.0, &other.0) {
            (Repr::Radical(a), Repr::Radical(b)) => Self::radical(a.add(b)),
            _ => match self.common(other) {
                Some((k, a, b)) => Self::from_field(k, &a.add(&b)),
                None => self.add_general(other),
            },
        }
    }
}

impl std::ops::Sub<&RealAlgebraic> for RealAlgebraic {
    type Output = Self;
    fn sub(self, other: &Self) -> Self {
        match (&self.0, &other.0) {
            (Repr::Radical(a), Repr::Radical(b)) => Self::radical(a.add(&b.neg())),
            _ => match self.common(other) {
                Some((k, a, b)) => Self::from_field(k, &a.sub(&b)),
                None => self + &(-other.clone()),
            },
        }
    }
}

impl std::ops::Mul<&RealAlgebraic> for RealAlgebraic {
    type Output = Self;
    fn mul(self, other: &Self) -> Self {
        match (&self.0, &other.0) {
            (Repr::Radical(a), Repr::Radical(b)) => Self::radical(a.mul(b)),
            _ if self.is_zero() || other.is_zero() => Self::zero(),
            _ => match self.common(other) {
                Some((k, a, b)) => {
                    let c = k.product(&a, &b);
                    Self::from_field(k, &c)
                }
                None => self.mul_general(other),
            },
        }
    }
}

impl std::ops::Div<&RealAlgebraic> for RealAlgebraic {
    type Output = Self;
    /// **Panics if `other` is zero.**
    #[allow(clippy::suspicious_arithmetic_impl)] // x / y = x · (1/y)
    fn div(self, other: &Self) -> Self {
        self * &other.recip_exact()
    }
}

macro_rules! by_value {
    ($($tr:ident $f:ident),*) => {$(
        impl std::ops::$tr for RealAlgebraic {
            type Output = Self;
            fn $f(self, other: Self) -> Self {
                std::ops::$tr::$f(self, &other)
            }
        }
    )*};
}
by_value!(Add add, Sub sub, Mul mul, Div div);

impl crate::algebra::scalar::MulAcc for RealAlgebraic {}

impl Scalar for RealAlgebraic {
    fn from_i64(n: i64) -> Self {
        Self::rat(BigRational::from_integer(n.into()))
    }
    fn from_rational(q: &BigRational) -> Self {
        RealAlgebraic::rat(q.clone())
    }
}

impl Field for RealAlgebraic {
    fn recip(&self) -> Self {
        self.recip_exact()
    }
}

impl Ordered for RealAlgebraic {
    fn to_f64(&self) -> f64 {
        self.to_f64_exact()
    }

    /// [`RealAlgebraic::enclosure`] at 64 bits.
    fn rational_bounds(&self) -> Option<(BigRational, BigRational)> {
        Some(self.enclosure(64))
    }
}

impl Roots for RealAlgebraic {
    /// The real n-th root: always `Some` for `x ≥ 0` (`n ≥ 1`) and for odd
    /// `n`; `None` for even roots of negatives and `n = 0`.
    fn nth_root(&self, n: u32) -> Option<Self> {
        match n {
            0 => None,
            1 => Some(self.clone()),
            _ => self.root_exact(n),
        }
    }

    /// `None` when the root's field would be over the field degree limit
    /// (or a radical's index over the radical index limit), checked before
    /// any work ([`RealAlgebraic::span_degree`]).
    fn bounded_root(&self, n: u32) -> Option<Self> {
        self.check_root_degree(n, "the root").ok()?;
        self.nth_root(n)
    }
}

impl std::fmt::Display for RealAlgebraic {
    /// The SymPy-compatible text form ([`text`]).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.0 {
            Repr::Radical(s) => write!(f, "{}", text::radical_text(s)),
            Repr::Root(r) => write!(f, "{}", text::root_text(r.poly(), r.index())),
            Repr::Field(_) => write!(f, "{}", self.plain()),
        }
    }
}

impl std::str::FromStr for RealAlgebraic {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        text::parse(s)
    }
}

#[cfg(test)]
mod tests;
