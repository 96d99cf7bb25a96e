//! Number-field arithmetic with bounded degree: the numbers of one
//! computation live in one field `K = Q[x]/(p)`, each a polynomial `a(x)`
//! of degree `< deg p` evaluated at a distinguished real root `θ` of `p`.
//!
//! ```text
//! field          K = Q[x]/(p),  p monic and square-free (not necessarily irreducible),
//!                θ: the root of p in an isolating interval (lo, hi)
//! element        a(θ) with deg a < deg p
//! + − ×          polynomial operations mod p                    (degree never above deg p)
//! zero test      a(θ) = 0  iff  θ is a root of gcd(a, p)        (Sturm count on (lo, hi))
//! inverse        e = a + p/gcd(a, p) agrees with a at θ and is a unit mod p;
//!                1/e by the extended Euclidean algorithm mod p
//! sign           interval Horner of a on θ's interval, refined until it excludes 0
//! ```
//!
//! Two fields `Q(θ₁)`, `Q(θ₂)` meet in the algebra `A = K₁[y]/(f(y))`
//! (`f = p₂`, degree `D = deg p₁ · deg p₂`); a root `y = a(θ)^{1/n}` extends
//! `K` to `A = K[y]/(yⁿ − a(x))`, `D = n · deg p` (with `a` first replaced by
//! the unit `a + p/gcd(a, p)`, equal to it at `θ`, so that `A` is reduced).
//! Both are the same construction: the primitive element `φ = y + c·x` for
//! the first small integer `c` (1, −1, 2, −2, …) whose powers `1, φ, …,
//! φ^{D−1}` are linearly independent in `A` (Krylov). Then
//! `A ≅ Q[t]/(r)` with `r` the dependency `φ^D = Σ z_k φ^k` (square-free,
//! because `A` is a product of fields), and `x`, `y` are expressed in `φ` by
//! the same elimination. The real `φ` is isolated by refining `θ` and `y`.
//! The degree `D` is known before the work: above
//! [`MAX_FIELD_DEGREE`](crate::limits::MAX_FIELD_DEGREE) nothing is built
//! and the caller falls back to the resultant path.
//!
//! Fields are registered by `(p, index of θ)`; every field records the
//! fields it was built from (`K₁ → A`, `K₂ → A`, `K → K(y)`; their own
//! ancestors' images are composed when first asked for), and the
//! compositum of a pair is cached, so an element of `K₁` meets one of
//! `A ⊇ K₁` in `A`, the numbers of one input end in one field, and a pair
//! of fields is combined once.
//!
//! Reference: Della Dora, Dicrescenzo & Duval, *About a new method for
//! computing in algebraic number fields*, EUROCAL 1985 (dynamic evaluation:
//! computing modulo a square-free, possibly reducible `p`); Cohen, *A Course
//! in Computational Algebraic Number Theory* (1993), §4.5 (primitive
//! elements of compositums).

use super::polys::{self, QPoly, SignPoly};
use super::root::RootNum;
use crate::algebra::upoly::UPoly;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::collections::HashMap;
use std::sync::{Arc, LazyLock, Mutex};

/// A field is identified by its monic polynomial and the index of `θ`
/// among the real roots.
pub(crate) type Key = (Vec<BigRational>, usize);

/// `Q[x]/(p)` with the real root `θ` of `p`.
#[derive(Debug)]
pub(crate) struct NumberField {
    p: QPoly,
    theta: RootNum,
    key: Key,
    /// The fields this one was built from directly, with the image of
    /// their generator: `K' → K`, `θ' ↦ image(θ)`.
    parents: Mutex<Vec<(Arc<NumberField>, QPoly)>>,
    /// The images of further ancestors' generators, composed along the
    /// parents when first asked for ([`NumberField::image_of`]): composing
    /// them eagerly at every step of a tower of roots cost minutes at
    /// degree 64 (coefficients grow with each composition).
    ancestors: Mutex<HashMap<Key, QPoly>>,
}

/// An element `a(θ)` of a field, `deg a < deg p`.
#[derive(Clone, Debug)]
pub(crate) struct FieldNum {
    pub(crate) field: Arc<NumberField>,
    pub(crate) a: QPoly,
}

/// `K₁ → K` (`θ₁ ↦ first(θ)`) and `K₂ → K` (`θ₂ ↦ second(θ)`).
#[derive(Clone)]
struct Embedding {
    target: Arc<NumberField>,
    first: QPoly,
    second: QPoly,
}

/// Registered fields and embeddings (cleared when they grow past this many
/// entries, so a long-running process does not accumulate them).
const CACHE_SIZE: usize = 1024;

static FIELDS: LazyLock<Mutex<HashMap<Key, Arc<NumberField>>>> =
    LazyLock::new(|| Mutex::new(HashMap::new()));
static EMBEDDINGS: LazyLock<Mutex<HashMap<(Key, Key), Embedding>>> =
    LazyLock::new(|| Mutex::new(HashMap::new()));

fn q(n: i64) -> BigRational {
    BigRational::from_integer(n.into())
}

fn x_poly() -> QPoly {
    UPoly::new(vec![q(0), q(1)])
}

impl NumberField {
    /// The registered field of the root of `p` (monic, square-free, degree
    /// ≥ 2) isolated in `(lo, hi)`.
    pub(crate) fn new(p: QPoly, lo: BigRational, hi: BigRational) -> Arc<Self> {
        let theta = RootNum::new(p.clone(), lo, hi);
        let key = (p.coeffs().to_vec(), theta.index());
        let mut fields = FIELDS.lock().expect("not poisoned");
        if let Some(f) = fields.get(&key) {
            return f.clone();
        }
        if fields.len() >= CACHE_SIZE {
            fields.clear();
        }
        let f = Arc::new(NumberField {
            p,
            theta,
            key,
            parents: Mutex::new(Vec::new()),
            ancestors: Mutex::new(HashMap::new()),
        });
        fields.insert(f.key.clone(), f.clone());
        f
    }

    /// The field's identity: `p`'s coefficients and the index of `θ` among
    /// its real roots.
    pub(crate) fn key(&self) -> Key {
        self.key.clone()
    }

    /// The defining polynomial `p`.
    pub(crate) fn poly(&self) -> &QPoly {
        &self.p
    }

    /// Record that `parent` embeds here by `θ_parent ↦ image(θ)` (and so,
    /// through it, do `parent`'s own ancestors).
    fn adopt(&self, parent: &Arc<NumberField>, image: &QPoly) {
        if parent.key == self.key {
            return;
        }
        let mut parents = self.parents.lock().expect("not poisoned");
        if parents.iter().all(|(k, _)| k.key != parent.key) {
            parents.push((parent.clone(), image.clone()));
        }
    }

    /// The image of `ancestor`'s generator here, if it is one: a parent's
    /// image, or an ancestor's image in a parent composed with that
    /// parent's image here (cached).
    fn image_of(&self, ancestor: &NumberField) -> Option<QPoly> {
        if let Some(g) = self
            .ancestors
            .lock()
            .expect("not poisoned")
            .get(&ancestor.key)
        {
            return Some(g.clone());
        }
        let parents = self.parents.lock().expect("not poisoned").clone();
        let found = parents.iter().find_map(|(k, image)| {
            if k.key == ancestor.key {
                Some(image.clone())
            } else {
                k.image_of(ancestor).map(|g| self.compose(&g, image))
            }
        })?;
        let mut cache = self.ancestors.lock().expect("not poisoned");
        cache.insert(ancestor.key.clone(), found.clone());
        Some(found)
    }

    /// Is the field keyed `key` this one or one it was built from (through
    /// any chain of parents)? No arithmetic.
    pub(crate) fn holds(&self, key: &Key) -> bool {
        if &self.key == key {
            return true;
        }
        let parents = self.parents.lock().expect("not poisoned").clone();
        parents.iter().any(|(k, _)| k.holds(key))
    }

    /// `deg p`.
    pub(crate) fn degree(&self) -> usize {
        self.p.degree().unwrap_or(0)
    }

    /// `a mod p` (metered: a division step per degree of `a` at or above
    /// `deg p`, `deg p` coefficient operations each).
    fn reduce(&self, a: &QPoly) -> QPoly {
        let (len, d) = (a.coeffs().len(), self.degree());
        if len > d {
            polys::meter((len - d) * d, &[a, &self.p]);
        }
        a.div_rem(&self.p).expect("p is non-zero").1
    }

    /// `a · b`, not yet reduced (metered: `len a · len b` coefficient
    /// products).
    pub(crate) fn product(&self, a: &QPoly, b: &QPoly) -> QPoly {
        polys::meter(a.coeffs().len() * b.coeffs().len(), &[a, b]);
        a.mul(b)
    }

    /// `a(b(x)) mod p` (Horner).
    fn compose(&self, a: &QPoly, b: &QPoly) -> QPoly {
        a.coeffs().iter().rev().fold(UPoly::zero(), |acc, c| {
            self.reduce(&self.product(&acc, b).add(&UPoly::constant(c.clone())))
        })
    }

    /// Is `a(θ) = 0`? An interval evaluation usually says no at once;
    /// otherwise `θ` must be a root of `gcd(a, p)` in its interval.
    fn vanishes(&self, a: &QPoly) -> bool {
        if a.is_zero() {
            return true;
        }
        let (lo, hi) = self.theta.interval();
        let (v_lo, v_hi) = polys::eval_on_interval(a, &lo, &hi);
        if v_lo.is_positive() || v_hi.is_negative() {
            return false;
        }
        let g = polys::gcd(a, &self.p);
        g.degree().unwrap_or(0) > 0 && polys::count_roots(&polys::sturm_sequence(&g), &lo, &hi) == 1
    }

    /// A unit `e` of `Q[x]/(p)` with `e(θ) = a(θ) ≠ 0`: `a + p/gcd(a, p)`
    /// (at a root of `g = gcd(a, p)` the second term is non-zero, at a root
    /// of `p/g` the first).
    fn unit(&self, a: &QPoly) -> QPoly {
        let g = polys::gcd(a, &self.p);
        if g.degree().unwrap_or(0) == 0 {
            return a.clone();
        }
        a.add(&self.p.div_exact(&g).expect("the gcd divides"))
    }

    /// `1/a(θ)` for `a(θ) ≠ 0`: the extended Euclidean algorithm on
    /// `(p, e)` with `e` the unit of [`Self::unit`] (`s_i·e ≡ r_i mod p`).
    fn inverse(&self, a: &QPoly) -> QPoly {
        let (mut r0, mut r1) = (self.p.clone(), self.unit(a));
        let (mut s0, mut s1) = (QPoly::zero(), UPoly::constant(q(1)));
        while r1.degree().unwrap_or(0) > 0 {
            let steps = r0.coeffs().len().saturating_sub(r1.coeffs().len()) + 1;
            polys::meter(steps * r1.coeffs().len(), &[&r0, &r1]);
            let (quot, rem) = r0.div_rem(&r1).expect("non-zero");
            let s2 = s0.sub(&self.product(&quot, &s1));
            (r0, r1, s0, s1) = (r1, rem, s1, s2);
        }
        let c = r1.lead().expect("e is a unit mod p").recip();
        self.reduce(&s1.scale(&c))
    }

    /// Rational bounds on `a(θ)` of width at most `2^{−prec}`.
    fn enclosure(&self, a: &QPoly, prec: u32) -> (BigRational, BigRational) {
        let eps = BigRational::new(1.into(), BigInt::one() << prec as usize);
        let mut theta_prec = prec + 8;
        loop {
            let (lo, hi) = self.theta.enclosure(theta_prec);
            let (v_lo, v_hi) = polys::eval_on_interval(a, &lo, &hi);
            if &v_hi - &v_lo <= eps {
                return (v_lo, v_hi);
            }
            theta_prec += theta_prec / 2 + 8;
        }
    }
}

impl FieldNum {
    /// The generator `θ` of `field`.
    pub(crate) fn generator(field: Arc<NumberField>) -> Self {
        FieldNum { field, a: x_poly() }
    }

    /// `c(θ)` for a polynomial `c` (reduced mod p); `None` when `c(θ) = 0`.
    pub(crate) fn new(field: Arc<NumberField>, c: &QPoly) -> Option<Self> {
        let a = field.reduce(c);
        (!field.vanishes(&a)).then_some(FieldNum { field, a })
    }

    /// Rational bounds of width at most `2^{−prec}`.
    pub(crate) fn enclosure(&self, prec: u32) -> (BigRational, BigRational) {
        self.field.enclosure(&self.a, prec)
    }

    /// The sign (never 0: elements are non-zero by construction).
    pub(crate) fn signum(&self) -> i32 {
        polys::sign_by_refinement(8, |prec| self.enclosure(prec))
    }

    /// The minimal polynomial of `a(θ)` over Q (monic): the first linear
    /// dependence among `1, a, a², …` reduced mod `p`, found by incremental
    /// Gaussian elimination on their coefficient vectors (at most `deg p`
    /// products mod `p` and a `deg p`-square elimination, where the
    /// characteristic polynomial by resultants needs `deg p + 1` Sylvester
    /// determinants of size `2 deg p − 1`: 91 s against under a second for
    /// a degree-32 tower of square roots in a debug build).
    pub(crate) fn minimal_polynomial(&self) -> QPoly {
        let k = &self.field;
        let d = k.degree();
        let mut rows: Vec<(usize, Vec<BigRational>, Vec<BigRational>)> = Vec::new();
        let mut power = UPoly::constant(q(1));
        for j in 0..=d {
            let mut v = power.coeffs().to_vec();
            v.resize(d, BigRational::zero());
            let mut combo = vec![BigRational::zero(); j + 1];
            combo[j] = q(1);
            for (pivot, row, rc) in &rows {
                if v[*pivot].is_zero() {
                    continue;
                }
                crate::limits::meter((d + j + 1) as u64, vector_bits(row.iter().chain(rc)));
                let f = &v[*pivot] / &row[*pivot];
                for (x, r) in v.iter_mut().zip(row) {
                    *x -= &f * r;
                }
                for (c, r) in combo.iter_mut().zip(rc) {
                    *c -= &f * r;
                }
            }
            match v.iter().position(|x| !x.is_zero()) {
                None => return UPoly::new(combo),
                Some(pivot) => rows.push((pivot, v, combo)),
            }
            power = k.reduce(&k.product(&power, &self.a));
        }
        unreachable!("d + 1 vectors in a space of dimension d are dependent")
    }

    /// `−self`.
    pub(crate) fn neg(&self) -> Self {
        FieldNum {
            field: self.field.clone(),
            a: self.a.scale(&q(-1)),
        }
    }

    /// `1/self`.
    pub(crate) fn recip(&self) -> Self {
        FieldNum {
            field: self.field.clone(),
            a: self.field.inverse(&self.a),
        }
    }

    /// The real `n`-th root (`self > 0`, `n ≥ 2`) in `K(y)`, `yⁿ = a'(x)`;
    /// `None` when `n · deg p` is over the field-degree limit.
    pub(crate) fn root(
        &self,
        n: u32,
        enclose: impl Fn(u32) -> (BigRational, BigRational),
    ) -> Option<Self> {
        let k = &self.field;
        let d = k.degree().checked_mul(n as usize)?;
        if d > crate::limits::MAX_FIELD_DEGREE {
            return None;
        }
        let mut f = vec![QPoly::zero(); n as usize];
        f[0] = k.unit(&self.a).scale(&q(-1));
        let emb = primitive_element(k, &f, enclose);
        emb.target.adopt(k, &emb.first);
        Some(FieldNum {
            field: emb.target,
            a: emb.second,
        })
    }
}

/// The image of `g`'s generator in `k` when `k` is `g` or was built from
/// it (directly or through other fields).
pub(crate) fn image_in(k: &NumberField, g: &NumberField) -> Option<QPoly> {
    if k.key == g.key {
        return Some(x_poly());
    }
    k.image_of(g)
}

/// A field containing `k` and `g` (`k` itself when it already contains
/// `g`); `None` when a new compositum would be over the field-degree limit.
pub(crate) fn extend(k: &Arc<NumberField>, g: &Arc<NumberField>) -> Option<Arc<NumberField>> {
    if image_in(k, g).is_some() {
        return Some(k.clone());
    }
    unify(
        &FieldNum::generator(k.clone()),
        &FieldNum::generator(g.clone()),
    )
    .map(|(f, _, _)| f)
}

/// `Σ_t c_t ∏_j g_j^{e_tj}` in `k`, for the images `g_j` of generators
/// and terms `(c_t, e_t)` (each power computed once, products reduced).
pub(crate) fn sum_of_monomials(
    k: &NumberField,
    gens: &[QPoly],
    terms: &[(BigRational, Vec<u32>)],
) -> QPoly {
    let mut powers: Vec<Vec<QPoly>> = gens.iter().map(|_| vec![UPoly::constant(q(1))]).collect();
    let mut total = QPoly::zero();
    for (c, exps) in terms {
        let mut acc = UPoly::constant(c.clone());
        for (j, &e) in exps.iter().enumerate() {
            while powers[j].len() <= e as usize {
                let next = k.reduce(&k.product(powers[j].last().expect("x⁰"), &gens[j]));
                powers[j].push(next);
            }
            if e > 0 {
                acc = k.reduce(&k.product(&acc, &powers[j][e as usize]));
            }
        }
        total = total.add(&acc);
    }
    total
}

/// Both elements written in one field: `(K, a, b)`; `None` when their
/// compositum would be over the field-degree limit.
pub(crate) fn unify(a: &FieldNum, b: &FieldNum) -> Option<(Arc<NumberField>, QPoly, QPoly)> {
    let (ka, kb) = (&a.field, &b.field);
    if ka.key == kb.key {
        return Some((ka.clone(), a.a.clone(), b.a.clone()));
    }
    if let Some(image) = kb.image_of(ka) {
        return Some((kb.clone(), kb.compose(&a.a, &image), b.a.clone()));
    }
    if let Some(image) = ka.image_of(kb) {
        return Some((ka.clone(), a.a.clone(), ka.compose(&b.a, &image)));
    }
    let emb = embedding(ka, kb)?;
    let k = &emb.target;
    Some((
        k.clone(),
        k.compose(&a.a, &emb.first),
        k.compose(&b.a, &emb.second),
    ))
}

/// The cached embedding of `K₁`, `K₂` into one field, or a new compositum.
fn embedding(k1: &Arc<NumberField>, k2: &Arc<NumberField>) -> Option<Embedding> {
    {
        let cache = EMBEDDINGS.lock().expect("not poisoned");
        if let Some(e) = cache.get(&(k1.key.clone(), k2.key.clone())) {
            return Some(e.clone());
        }
        if let Some(e) = cache.get(&(k2.key.clone(), k1.key.clone())) {
            return Some(Embedding {
                target: e.target.clone(),
                first: e.second.clone(),
                second: e.first.clone(),
            });
        }
    }
    if k1.degree().checked_mul(k2.degree())? > crate::limits::MAX_FIELD_DEGREE {
        return None;
    }
    let f: Vec<QPoly> = k2.p.coeffs()[..k2.degree()]
        .iter()
        .map(|c| UPoly::constant(c.clone()))
        .collect();
    let emb = primitive_element(k1, &f, |prec| k2.theta.enclosure(prec));
    emb.target.adopt(k1, &emb.first);
    emb.target.adopt(k2, &emb.second);
    let mut cache = EMBEDDINGS.lock().expect("not poisoned");
    if cache.len() >= CACHE_SIZE {
        cache.clear();
    }
    cache.insert((k1.key.clone(), k2.key.clone()), emb.clone());
    Some(emb)
}

/// An element of `A = K[y]/(f(y))` (`f` monic of degree `n` with
/// coefficients `f[0..n]` in `K`): the coefficients of `y^0 … y^{n−1}`,
/// each reduced mod p.
type Tower = Vec<QPoly>;

/// `φ·v` with `φ = y + c·x` in `A`.
fn times_phi(k: &NumberField, f: &[QPoly], c: &BigRational, v: &Tower) -> Tower {
    let n = f.len();
    let mut out: Tower = v
        .iter()
        .map(|a| k.reduce(&a.mul(&x_poly())).scale(c))
        .collect();
    for j in 0..n - 1 {
        out[j + 1] = out[j + 1].add(&v[j]);
    }
    // y · v[n−1] y^{n−1} = v[n−1] yⁿ = −v[n−1] Σ f_j y^j.
    for j in 0..n {
        out[j] = k.reduce(&out[j].sub(&k.product(&v[n - 1], &f[j])));
    }
    out
}

/// The coordinates of a tower element in the basis `x^i y^j` (index `j·d + i`).
fn flatten(v: &Tower, d: usize) -> Vec<BigRational> {
    let mut out = vec![BigRational::zero(); d * v.len()];
    for (j, a) in v.iter().enumerate() {
        for (i, c) in a.coeffs().iter().enumerate() {
            out[j * d + i] = c.clone();
        }
    }
    out
}

/// The primitive element `φ = y + c·x` of `A = K[y]/(f(y))` (module docs),
/// its field registered with `φ` isolated from `y`'s enclosures
/// `y_enclose(prec)` and `θ`'s, and the images of `x` and `y` in it.
fn primitive_element(
    k: &NumberField,
    f: &[QPoly],
    y_enclose: impl Fn(u32) -> (BigRational, BigRational),
) -> Embedding {
    let (d, n) = (k.degree(), f.len());
    let size = d * n;
    let mut unit_y = vec![QPoly::zero(); n];
    unit_y[1] = UPoly::constant(q(1));
    let mut unit_x = vec![QPoly::zero(); n];
    unit_x[0] = x_poly();
    let (ex, ey) = (flatten(&unit_x, d), flatten(&unit_y, d));
    for step in 1i64.. {
        let c = q(if step % 2 == 1 {
            step.div_euclid(2) + 1
        } else {
            -step / 2
        });
        let mut power: Tower = vec![QPoly::zero(); n];
        power[0] = UPoly::constant(q(1));
        let mut columns = Vec::with_capacity(size + 1);
        for _ in 0..=size {
            columns.push(flatten(&power, d));
            power = times_phi(k, f, &c, &power);
        }
        let top = columns.pop().expect("size + 1 columns");
        let Some(z) = solve(columns, &[top, ex.clone(), ey.clone()]) else {
            continue;
        };
        let mut r: Vec<BigRational> = z[0].iter().map(|v| -v.clone()).collect();
        r.push(q(1));
        let r = UPoly::new(r);
        let (lo, hi) = isolate_sum(&r, &c, |prec| k.theta.enclosure(prec), &y_enclose);
        return Embedding {
            target: NumberField::new(r, lo, hi),
            first: UPoly::new(z[1].clone()),
            second: UPoly::new(z[2].clone()),
        };
    }
    unreachable!("some c among the first integers separates the conjugates")
}

/// An isolating interval for the root `y + c·x` of the square-free `r`
/// from enclosures of `x` and `y`.
fn isolate_sum(
    r: &QPoly,
    c: &BigRational,
    x_enclose: impl Fn(u32) -> (BigRational, BigRational),
    y_enclose: impl Fn(u32) -> (BigRational, BigRational),
) -> (BigRational, BigRational) {
    isolate_value(r, |prec| {
        let (x_lo, x_hi) = x_enclose(prec);
        let (y_lo, y_hi) = y_enclose(prec);
        let (a, b) = (&x_lo * c, &x_hi * c);
        if c.is_positive() {
            (y_lo + a, y_hi + b)
        } else {
            (y_lo + b, y_hi + a)
        }
    })
}

/// An isolating interval for the irrational root of the square-free
/// polynomial `p` that the enclosures `enclose(prec)` shrink to
/// ([`polys::isolate_by_enclosures`]).
pub(crate) fn isolate_value(
    p: &QPoly,
    enclose: impl Fn(u32) -> (BigRational, BigRational),
) -> (BigRational, BigRational) {
    polys::isolate_by_enclosures(&SignPoly::new(p), enclose)
        .expect("an irrational value: enclosures never collapse")
}

/// The solutions `z` of `M z = b` for each right-hand side `b`, where
/// `columns` are the columns of the square matrix `M`; `None` when `M` is
/// singular (Gauss–Jordan elimination over Q).
fn solve(
    columns: Vec<Vec<BigRational>>,
    rhs: &[Vec<BigRational>],
) -> Option<Vec<Vec<BigRational>>> {
    let size = columns.len();
    let width = size + rhs.len();
    let mut rows: Vec<Vec<BigRational>> = (0..size)
        .map(|i| {
            columns
                .iter()
                .chain(rhs)
                .map(|col| col[i].clone())
                .collect()
        })
        .collect();
    for col in 0..size {
        let pivot = (col..size).find(|&r| !rows[r][col].is_zero())?;
        rows.swap(pivot, col);
        let inv = rows[col][col].recip();
        let pivot_row: Vec<BigRational> = rows[col].iter().map(|v| v * &inv).collect();
        let pivot_bits = vector_bits(&pivot_row);
        for (r, row) in rows.iter_mut().enumerate() {
            if r == col || row[col].is_zero() {
                continue;
            }
            crate::limits::meter((width - col) as u64, pivot_bits);
            let factor = row[col].clone();
            for k in col..width {
                row[k] = &row[k] - &factor * &pivot_row[k];
            }
        }
        rows[col] = pivot_row;
    }
    Some(
        (0..rhs.len())
            .map(|j| rows.iter().map(|row| row[size + j].clone()).collect())
            .collect(),
    )
}

/// The most bits of the rationals `v` (for the actual-work meter).
fn vector_bits<'a>(v: impl IntoIterator<Item = &'a BigRational>) -> u64 {
    v.into_iter().map(crate::limits::bits).max().unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn poly(v: &[i64]) -> QPoly {
        UPoly::new(v.iter().map(|&x| q(x)).collect())
    }

    fn field(p: &[i64], lo: (i64, i64), hi: (i64, i64)) -> Arc<NumberField> {
        let r = |(a, b): (i64, i64)| BigRational::new(a.into(), b.into());
        NumberField::new(poly(p), r(lo), r(hi))
    }

    #[test]
    fn compositum_of_two_square_roots() {
        // Q(√2, √3) = Q(√2 + c√3) has degree 4 and √2·√3 squares to 6.
        let k2 = field(&[-2, 0, 1], (1, 1), (2, 1));
        let k3 = field(&[-3, 0, 1], (1, 1), (2, 1));
        let (k, a, b) = unify(&FieldNum::generator(k2), &FieldNum::generator(k3)).unwrap();
        assert_eq!(k.degree(), 4);
        let prod = k.reduce(&a.mul(&b));
        assert_eq!(k.reduce(&prod.mul(&prod)), poly(&[6]));
        assert_eq!(k.reduce(&a.mul(&a)), poly(&[2]));
        assert_eq!(k.reduce(&b.mul(&b)), poly(&[3]));
    }

    #[test]
    fn inverse_in_a_reducible_field() {
        // p = (x² − 2)(x − 3), θ = √2: x − 3 is a zero divisor mod p but
        // not zero at θ; its inverse is 1/(√2 − 3) = −(3 + √2)/7.
        let k = field(&[6, -2, -3, 1], (1, 1), (2, 1));
        let a = poly(&[-3, 1]);
        assert!(!k.vanishes(&a));
        assert!(k.vanishes(&poly(&[-2, 0, 1])));
        let inv = k.inverse(&a);
        let expected = poly(&[-3, -1]).scale(&BigRational::new(1.into(), 7.into()));
        assert!(k.vanishes(&inv.sub(&expected)));
    }
}
