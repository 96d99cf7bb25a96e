//! Canonical keys: an exact, hashable normal form of a curve's or rect
//! patch's class under the maps (1)–(6) of [`coincide`](crate::coincide::coincide),
//! so that N patches are grouped in O(N) expected time ([`dedup`]).
//!
//! The key of a patch: reduce it to minimal bidegree; for each admissible
//! symmetry (the 2 reversals of a curve; the 8 symmetries of a patch that
//! give bidegree (min, max)) read the normalized control points `Ĥ_{i,j}`
//! row by row and the weight invariants `I_{i,j}` with their signs; keep
//! the lexicographically smallest. Points are compared first, so the
//! invariants (powers of rationals) are computed only for the symmetries
//! that tie on points — usually one.
//!
//! Why it is canonical: if b is a copy of a under symmetry S, Möbius maps and
//! scaling, the reduced nets satisfy `H^b = k ρ^i σ^j · S(H^a)`, which leaves
//! `Ĥ` and `I` unchanged; so the set of candidate keys of b equals that of a
//! (T ↦ T∘S permutes the symmetries) and so do their minima. Conversely equal
//! keys mean equal points and invariants under some symmetries, which by the
//! completeness of the invariants (`proofs/src/coincide.rs`) makes the patches
//! coincident.
//!
//! For positive weights the invariants are the weights normalized to
//! `ω_{0,0} = ω_{1,0} = ω_{0,1} = 1` by an exact rational Möbius map and
//! scaling (ρ = ω_{0,0}/ω_{1,0}, σ = ω_{0,0}/ω_{0,1}, k = 1/ω_{0,0}).

use crate::algebra::limbs::push_decimal;
use crate::algebra::scalar::Ordered;
use crate::algebra::RealAlgebraic;
use crate::coincide::minimal::{certified_minimal, minimal_net, Net, Reducible};
use crate::coincide::{net_of, Prepared, Symmetry, View};
use crate::error::Error;
use crate::Patch;
use num_rational::BigRational;
use rayon::prelude::*;
use sha2::{Digest, Sha256};
use std::cmp::Ordering;
use std::collections::HashMap;
use std::fmt;
use std::hash::{BuildHasherDefault, Hasher};

mod small;
pub use small::SmallPatch;

/// The canonical key of a curve's or rect patch's coincidence class.
///
/// # Examples
///
/// ```
/// use exact_bezier::{coincide::canonical_key, Patch, RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let c = RationalCurve::new(vec![p(0, 0), p(1, 2), p(3, 0)], vec![ratio(1, 1), ratio(2, 1), ratio(5, 1)]).unwrap();
/// let copy = c.mobius(&ratio(1, 3)).reverse().elevate(1).scale_weights(&ratio(7, 2));
/// assert_eq!(canonical_key(&Patch::Curve(c)).unwrap(), canonical_key(&Patch::Curve(copy)).unwrap());
/// ```
/// Over `BigRational` (the default) keys are hashable and have a text
/// ([`CanonicalKey::text`]); over [`RealAlgebraic`] they compare exactly,
/// and [`CanonicalKey::to_rational`] gives the rational key when every
/// number of the key is rational.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CanonicalKey<T = BigRational> {
    curve: bool,
    degree: (usize, usize),
    points: Vec<Option<Vec<T>>>,
    invariants: Vec<(i8, T)>,
}

impl<T> CanonicalKey<T> {
    /// The minimal (bi)degree of the class.
    pub fn degree(&self) -> (usize, usize) {
        self.degree
    }

    /// The weight invariants `I_{i,j}` row by row (for positive weights:
    /// the weights normalized to `ω_{0,0} = ω_{1,0} = ω_{0,1} = 1`).
    pub fn invariants(&self) -> impl Iterator<Item = &T> {
        self.invariants.iter().map(|(_, x)| x)
    }

    /// The same key with every number mapped by `f` (`None` if `f` is
    /// `None` for one of them).
    fn try_map<U>(&self, f: impl Fn(&T) -> Option<U>) -> Option<CanonicalKey<U>> {
        let point = |p: &Option<Vec<T>>| match p {
            None => Some(None),
            Some(p) => p.iter().map(&f).collect::<Option<Vec<U>>>().map(Some),
        };
        Some(CanonicalKey {
            curve: self.curve,
            degree: self.degree,
            points: self.points.iter().map(point).collect::<Option<_>>()?,
            invariants: self
                .invariants
                .iter()
                .map(|(s, x)| f(x).map(|x| (*s, x)))
                .collect::<Option<_>>()?,
        })
    }
}

impl CanonicalKey<RealAlgebraic> {
    /// The rational key when every number of this one is rational: then it
    /// is the key (and [`text`](CanonicalKey::text)) that the same patch
    /// written over Q has, since keys are built from values only. A patch
    /// whose key is not rational coincides with no patch over Q.
    pub fn to_rational(&self) -> Option<CanonicalKey<BigRational>> {
        self.try_map(RealAlgebraic::as_rational)
    }

    /// The key with each irrational number replaced by `?`, as text: equal
    /// keys have equal skeletons (which numbers are rational is a property
    /// of the values), so it buckets irrational keys for exact comparison.
    pub fn skeleton(&self) -> String {
        let shown = self.try_map(|x| {
            Some(
                x.as_rational()
                    .map_or("?".to_string(), |q| rational_text(&q)),
            )
        });
        let shown = shown.expect("every number has a text");
        let numbers = |v: &[String]| v.join(",");
        let points: Vec<String> = shown
            .points
            .iter()
            .map(|p| p.as_deref().map_or("*".into(), numbers))
            .collect();
        let invariants: Vec<String> = shown
            .invariants
            .iter()
            .map(|(s, x)| format!("{}:{x}", sign_char(*s)))
            .collect();
        format!(
            "{}{};I={}",
            text_head(self.curve, self.degree),
            points.join(";"),
            invariants.join(";")
        )
    }
}

fn positions(m: usize, n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..=m).flat_map(move |i| (0..=n).map(move |j| (i, j)))
}

/// The exact order of two values (exact scalars are totally ordered).
fn exact_cmp<T: PartialOrd>(a: &T, b: &T) -> Ordering {
    a.partial_cmp(b).unwrap_or(Ordering::Equal)
}

fn cmp_points<T: Ordered>(a: &View<'_, T>, b: &View<'_, T>) -> Ordering {
    positions(a.m, a.n)
        .map(|(i, j)| exact_cmp(&a.hat(i, j), &b.hat(i, j)))
        .find(|o| o.is_ne())
        .unwrap_or(Ordering::Equal)
}

fn invariants<T: Ordered>(v: &View<'_, T>) -> Vec<(i8, T)> {
    positions(v.m, v.n)
        .map(|(i, j)| v.sign(i, j))
        .zip(v.invariants())
        .collect()
}

/// The canonical key of a curve or rect patch (exact), over Q or over the
/// real algebraic numbers (see [`CanonicalKey`]).
///
/// # Errors
///
/// [`Error::Shape`] for a tri patch, [`Error::Weight`] for a non-positive weight.
pub fn canonical_key<T: Reducible>(p: &Patch<T>) -> Result<CanonicalKey<T>, Error> {
    let (net, curve) = net_of(p)?;
    Ok(key_of_minimal(&minimal_net(&net).patch, curve))
}

/// The key of a net already of minimal (bi)degree.
fn key_of_minimal<T: Reducible>(red: &Net<T>, curve: bool) -> CanonicalKey<T> {
    let prep = Prepared::new(red);
    let (m, n) = (prep.m, prep.n);
    let target = if curve { (m, n) } else { (m.min(n), m.max(n)) };
    let views: Vec<View<'_, T>> = Symmetry::admissible(curve, (m, n), target)
        .map(|s| prep.view(s))
        .collect();
    let mut best: Vec<View<'_, T>> = Vec::new();
    for v in views {
        match best.first().map(|b| cmp_points(&v, b)) {
            None | Some(Ordering::Equal) => best.push(v),
            Some(Ordering::Less) => best = vec![v],
            Some(Ordering::Greater) => {}
        }
    }
    let (view, invariants) = best
        .iter()
        .map(|v| (v, invariants(v)))
        .min_by(|a, b| exact_cmp(&a.1, &b.1))
        .expect("the identity is admissible");
    CanonicalKey {
        curve,
        degree: target,
        points: positions(view.m, view.n)
            .map(|(i, j)| view.hat(i, j).cloned())
            .collect(),
        invariants,
    }
}

/// The version tag of the key text and digest ([`CanonicalKey::text`]).
pub const KEY_VERSION: &str = "eb1";

pub(super) fn push_rational(out: &mut String, q: &BigRational) {
    // `BigRational` is kept in lowest terms with a positive denominator.
    let limbs = |n: &num_bigint::BigInt| n.magnitude().iter_u64_digits().collect();
    let negative = q.numer().sign() == num_bigint::Sign::Minus;
    push_decimal(out, negative, limbs(q.numer()));
    if !q.is_integer() {
        out.push('/');
        push_decimal(out, false, limbs(q.denom()));
    }
}

/// `q` as in the key text.
fn rational_text(q: &BigRational) -> String {
    let mut s = String::new();
    push_rational(&mut s, q);
    s
}

/// The sign of an invariant in the key text.
fn sign_char(sign: i8) -> char {
    match sign.cmp(&0) {
        Ordering::Less => '-',
        Ordering::Equal => '0',
        Ordering::Greater => '+',
    }
}

impl CanonicalKey {
    /// The versioned key text, injective on keys and stable across runs,
    /// platforms and thread counts (only exact integers in decimal):
    ///
    /// ```text
    /// eb1;KIND;M,N;P=x,y,…;x,y,…;…;I=s:q;s:q;…
    /// ```
    ///
    /// `KIND` is `curve` or `rect`, `M,N` the minimal (bi)degree, then the
    /// normalized points `Ĥ_{i,j}` row by row (coordinates as `p` or `p/q`
    /// in lowest terms, the trailing 1 of a non-zero weight included; `*`
    /// for a zero vector), then each weight invariant as its sign (`+`, `0`,
    /// `-`) and its value. See `docs/bulk_dedup.md`.
    ///
    /// ```
    /// use exact_bezier::{coincide::canonical_key, Patch, RationalCurve, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let c = RationalCurve::new(vec![p(0), p(1)], vec![ratio(1, 1), ratio(1, 3)]).unwrap();
    /// assert_eq!(canonical_key(&Patch::Curve(c)).unwrap().text(), "eb1;curve;1,0;P=0,1;1,1;I=+:1;+:1");
    /// ```
    pub fn text(&self) -> String {
        let mut out = text_head(self.curve, self.degree);
        for (k, p) in self.points.iter().enumerate() {
            if k > 0 {
                out.push(';');
            }
            match p {
                None => out.push('*'),
                Some(p) => {
                    for (c, x) in p.iter().enumerate() {
                        if c > 0 {
                            out.push(',');
                        }
                        push_rational(&mut out, x);
                    }
                }
            }
        }
        out.push_str(";I=");
        for (k, (sign, x)) in self.invariants.iter().enumerate() {
            if k > 0 {
                out.push(';');
            }
            out.push(sign_char(*sign));
            out.push(':');
            push_rational(&mut out, x);
        }
        out
    }

    /// SHA-256 of [`text`](Self::text): a fixed-size key, printed as
    /// `eb1:` and 64 hex digits.
    pub fn digest(&self) -> KeyDigest {
        KeyDigest::of_text(&self.text())
    }
}

/// `eb1;KIND;M,N;P=`: the head of the key text.
fn text_head(curve: bool, (m, n): (usize, usize)) -> String {
    let kind = if curve { "curve" } else { "rect" };
    format!("{KEY_VERSION};{kind};{m},{n};P=")
}

/// The key text of a patch ([`CanonicalKey::text`]). A net certified
/// minimal (modulo p, the common case) is keyed without reduction: its
/// points compared in machine integers when they fit `i128`, with the
/// weight invariants in machine integers too or, when those leave `i128`,
/// over Q; a net whose points do not fit takes the general path over Q;
/// an uncertified one goes through [`canonical_key`]. Same text every way.
///
/// ```
/// use exact_bezier::{coincide::canonical_key, coincide::canonical_text, Patch, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let r = RectPatch::new(
///     vec![vec![p(0, 0), p(0, 1)], vec![p(1, 0), p(2, 3)]],
///     vec![vec![ratio(1, 1), ratio(2, 1)], vec![ratio(3, 1), ratio(1, 2)]],
/// ).unwrap();
/// let patch = Patch::Rect(r);
/// assert_eq!(canonical_text(&patch).unwrap(), canonical_key(&patch).unwrap().text());
/// ```
///
/// # Errors
///
/// As [`canonical_key`].
pub fn canonical_text(p: &Patch<BigRational>) -> Result<String, Error> {
    let (net, curve) = net_of(p)?;
    if !certified_minimal(&net) {
        return canonical_key(p).map(|k| k.text());
    }
    Ok(small::key_text_rational_invariants(&net, curve)
        .unwrap_or_else(|| key_of_minimal(&net, curve).text()))
}

/// How [`canonical_text`] reduces a patch to minimal degree, read modulo
/// `p = 2⁶¹ − 1` before any exact work, and whether the key of a minimal
/// net stays in machine integers, so that a caller can charge the work
/// first ([`key_plan`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyPlan {
    /// Certified minimal, and no number of the key leaves `i128`: the key
    /// text is read off the net in machine integers (work proportional to
    /// its size, on machine words).
    Machine,
    /// Certified minimal, but a number of the key leaves `i128`: the key is
    /// read off the net over `BigRational` (numbers growing with the degree
    /// through the invariants).
    Minimal,
    /// The net looks like an elevation of one of this lower bidegree
    /// (`(m, 0)` for a curve): one exact pass undoes it, then the key of the
    /// lower net (a common factor of the lower net costs a gcd of its degree).
    Elevated((usize, usize)),
    /// Neither: the exact bivariate gcd of the whole net may run.
    General,
}

/// The [`KeyPlan`] of a curve or rect patch over Q. For a certified net it
/// runs the machine-integer key text to see whether it fits (work linear in
/// the net; [`SmallPatch::certify`] keeps that text).
///
/// ```
/// use exact_bezier::{coincide::canonical::{key_plan, KeyPlan}, Patch, RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let c = RationalCurve::new(vec![p(0), p(1), p(3)], vec![ratio(1, 1), ratio(2, 1), ratio(1, 1)]).unwrap();
/// assert_eq!(key_plan(&Patch::Curve(c.clone())).unwrap(), KeyPlan::Machine);
/// assert_eq!(key_plan(&Patch::Curve(c.elevate(5))).unwrap(), KeyPlan::Elevated((2, 0)));
/// ```
///
/// # Errors
///
/// As [`canonical_key`].
pub fn key_plan(p: &Patch<BigRational>) -> Result<KeyPlan, Error> {
    let (net, curve) = net_of(p)?;
    if certified_minimal(&net) {
        return Ok(match small::key_text(&net, curve) {
            Some(_) => KeyPlan::Machine,
            None => KeyPlan::Minimal,
        });
    }
    let shape = (net.len() - 1, net[0].len() - 1);
    Ok(match BigRational::degree_lower_bound(&net) {
        Some(d) if d != shape => KeyPlan::Elevated(d),
        _ => KeyPlan::General,
    })
}

/// A fixed-size canonical key: SHA-256 of [`CanonicalKey::text`]. Equal for
/// coincident patches; distinct for others unless SHA-256 collides.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct KeyDigest(pub [u8; 32]);

impl KeyDigest {
    /// SHA-256 of a key text.
    pub fn of_text(text: &str) -> KeyDigest {
        KeyDigest(Sha256::digest(text.as_bytes()).into())
    }
}

impl fmt::Display for KeyDigest {
    /// `eb1:` and the digest in lowercase hex.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        const HEX: &[u8; 16] = b"0123456789abcdef";
        let mut hex = String::with_capacity(64);
        for b in self.0 {
            hex.push(char::from(HEX[usize::from(b >> 4)]));
            hex.push(char::from(HEX[usize::from(b & 15)]));
        }
        f.write_str(KEY_VERSION)?;
        f.write_str(":")?;
        f.write_str(&hex)
    }
}

/// The digest of a patch's canonical key (`eb1:…` when displayed).
///
/// ```
/// use exact_bezier::{coincide::key_digest, Patch, RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let c = RationalCurve::new(vec![p(0), p(1), p(3)], vec![ratio(1, 1), ratio(2, 1), ratio(1, 1)]).unwrap();
/// let k = key_digest(&Patch::Curve(c.clone())).unwrap();
/// assert_eq!(k, key_digest(&Patch::Curve(c.reverse().mobius(&ratio(1, 3)))).unwrap());
/// assert!(k.to_string().starts_with("eb1:"));
/// ```
///
/// # Errors
///
/// As [`canonical_key`].
pub fn key_digest(p: &Patch<BigRational>) -> Result<KeyDigest, Error> {
    canonical_text(p).map(|t| KeyDigest::of_text(&t))
}

/// Hashes a [`KeyDigest`] (or any SHA-256 digest, `[u8; 32]`) by its
/// first 8 bytes: they are already uniform, so `SipHash` over all 32 would
/// be wasted work. For hash maps keyed by digests
/// (`HashMap<KeyDigest, V, BuildHasherDefault<DigestHasher>>`).
#[derive(Default)]
pub struct DigestHasher(u64);

impl Hasher for DigestHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8).take(1) {
            let mut word = [0u8; 8];
            word[..chunk.len()].copy_from_slice(chunk);
            self.0 ^= u64::from_le_bytes(word);
        }
    }
}

/// Streaming grouping into coincidence classes by key digest: per input
/// one class id (4 bytes), per class one digest and its first member —
/// O(1) expected time per input, memory independent of the patches' size.
///
/// Classes are numbered by first appearance, so the result depends only on
/// the order of the inputs (never on hashing or threads).
///
/// ```
/// use exact_bezier::{coincide::Deduper, Patch, RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let a = RationalCurve::new(vec![p(0), p(1), p(3)], vec![ratio(1, 1), ratio(2, 1), ratio(1, 1)]).unwrap();
/// let mut d = Deduper::default();
/// assert_eq!(d.insert(&Patch::Curve(a.clone())).unwrap(), 0);
/// assert_eq!(d.insert(&Patch::Curve(a.mobius(&ratio(1, 5)))).unwrap(), 0);
/// assert_eq!(d.insert(&Patch::Curve(a.elevate(1).scale_weights(&ratio(1, 2)).reverse())).unwrap(), 0);
/// assert_eq!(d.classes(), vec![vec![0, 1, 2]]);
/// ```
///
/// Patches over the real algebraic numbers enter by
/// [`insert_algebraic`](Self::insert_algebraic): a rational key joins the
/// digest index (so they group with their copies over Q); an irrational
/// key — algebraic numbers have no cheap canonical text — is kept whole
/// and compared exactly with the kept keys of the same
/// [`skeleton`](CanonicalKey::skeleton).
#[derive(Clone, Debug, Default)]
pub struct Deduper {
    index: HashMap<KeyDigest, u32, BuildHasherDefault<DigestHasher>>,
    irrational: HashMap<KeyDigest, Vec<(CanonicalKey<RealAlgebraic>, u32)>>,
    class_of: Vec<u32>,
    first: Vec<u32>,
}

impl Deduper {
    /// Add the next input (its index is the number inserted before it);
    /// returns its class id (classes are numbered by first appearance).
    ///
    /// # Errors
    ///
    /// As [`canonical_key`].
    pub fn insert(&mut self, p: &Patch<BigRational>) -> Result<usize, Error> {
        self.insert_digest(key_digest(p)?)
    }

    /// Add the next input by its key digest; returns its class id.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] beyond 2³² − 1 inputs.
    pub fn insert_digest(&mut self, key: KeyDigest) -> Result<usize, Error> {
        let next = self.next_class()?;
        let id = *self.index.entry(key).or_insert(next);
        Ok(self.record(id, next))
    }

    /// Add the next input by its key over the real algebraic numbers;
    /// returns its class id (see the type's docs).
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] beyond 2³² − 1 inputs.
    pub fn insert_algebraic(&mut self, key: CanonicalKey<RealAlgebraic>) -> Result<usize, Error> {
        if let Some(q) = key.to_rational() {
            return self.insert_digest(q.digest());
        }
        let next = self.next_class()?;
        let bucket = self
            .irrational
            .entry(KeyDigest::of_text(&key.skeleton()))
            .or_default();
        let id = match bucket.iter().find(|(k, _)| *k == key) {
            Some((_, id)) => *id,
            None => {
                bucket.push((key, next));
                next
            }
        };
        Ok(self.record(id, next))
    }

    /// The id a new class would get; an error beyond 2³² − 1 inputs.
    fn next_class(&self) -> Result<u32, Error> {
        let too_many = || Error::Shape("more than 2^32 - 1 inputs".into());
        u32::try_from(self.class_of.len()).map_err(|_| too_many())?;
        u32::try_from(self.first.len()).map_err(|_| too_many())
    }

    /// Record the next input in class `id` (new if `id == next`).
    fn record(&mut self, id: u32, next: u32) -> usize {
        if id == next {
            self.first.push(self.class_of.len() as u32);
        }
        self.class_of.push(id);
        id as usize
    }

    /// The number of inputs so far.
    pub fn len(&self) -> usize {
        self.class_of.len()
    }

    /// No input yet?
    pub fn is_empty(&self) -> bool {
        self.class_of.is_empty()
    }

    /// The number of classes so far.
    pub fn class_count(&self) -> usize {
        self.first.len()
    }

    /// The first member (representative) of class `id`.
    pub fn representative(&self, id: usize) -> usize {
        self.first[id] as usize
    }

    /// The classes in compact form (a counting sort of the class ids, O(N)).
    pub fn into_classes(self) -> Classes {
        let mut start = vec![0u32; self.first.len() + 1];
        for &c in &self.class_of {
            start[c as usize + 1] += 1;
        }
        for k in 1..start.len() {
            start[k] += start[k - 1];
        }
        let mut fill = start.clone();
        let mut members = vec![0u32; self.class_of.len()];
        for (k, &c) in self.class_of.iter().enumerate() {
            members[fill[c as usize] as usize] = k as u32;
            fill[c as usize] += 1;
        }
        Classes { start, members }
    }

    /// The classes: member indices in input order, classes by first member.
    pub fn classes(self) -> Vec<Vec<usize>> {
        self.into_classes()
            .iter()
            .map(|c| c.iter().map(|&k| k as usize).collect())
            .collect()
    }
}

/// Coincidence classes as one array of member indices, class after class
/// (each in input order; classes by first member).
#[derive(Clone, Debug)]
pub struct Classes {
    start: Vec<u32>,
    members: Vec<u32>,
}

impl Classes {
    /// The number of classes.
    pub fn len(&self) -> usize {
        self.start.len() - 1
    }

    /// No classes (no input)?
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The members of each class, in order.
    pub fn iter(&self) -> impl Iterator<Item = &[u32]> {
        self.start
            .windows(2)
            .map(|w| &self.members[w[0] as usize..w[1] as usize])
    }
}

/// Group patches into coincidence classes by their canonical keys (computed
/// in parallel, then grouped by a [`Deduper`]): each class lists member
/// indices in input order; classes are ordered by their first member.
///
/// ```
/// use exact_bezier::{coincide::dedup, Patch, RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let a = RationalCurve::new(vec![p(0), p(1), p(3)], vec![ratio(1, 1), ratio(2, 1), ratio(1, 1)]).unwrap();
/// let b = a.reverse().mobius(&ratio(1, 4));
/// let c = RationalCurve::polynomial(vec![p(0), p(1), p(3)]).unwrap();
/// let classes = dedup(&[Patch::Curve(a), Patch::Curve(c), Patch::Curve(b)]).unwrap();
/// assert_eq!(classes, vec![vec![0, 2], vec![1]]);
/// ```
///
/// # Errors
///
/// As [`canonical_key`], naming the first failing element.
pub fn dedup(patches: &[Patch<BigRational>]) -> Result<Vec<Vec<usize>>, Error> {
    let keys: Vec<Result<KeyDigest, Error>> = patches.par_iter().map(key_digest).collect();
    let mut d = Deduper::default();
    for (k, key) in keys.into_iter().enumerate() {
        let key = key.map_err(|e| Error::Format(format!("element {k}: {e}")))?;
        d.insert_digest(key)?;
    }
    Ok(d.classes())
}
