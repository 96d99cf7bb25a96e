//! Canonical keys: an exact, hashable normal form of a curve's or rect
//! patch's class under the maps (1)–(6) of [`coincide`](crate::coincide),
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
//! completeness of the invariants (`proofs/coincide.rs`) makes the patches
//! coincident.
//!
//! For positive weights the invariants are the weights normalized to
//! `ω_{0,0} = ω_{1,0} = ω_{0,1} = 1` by an exact rational Möbius map and
//! scaling (ρ = ω_{0,0}/ω_{1,0}, σ = ω_{0,0}/ω_{0,1}, k = 1/ω_{0,0}).

use crate::coincide::{net_of, Prepared, Symmetry, View};
use crate::error::Error;
use crate::io::Patch;
use crate::minimal_degree::minimal_net;
use num_rational::BigRational;
use std::cmp::Ordering;
use std::collections::HashMap;

/// The canonical key of a curve's or rect patch's coincidence class.
///
/// # Examples
///
/// ```
/// use exact_bezier::{canonical_key, Patch, RationalCurve, ratio};
/// use num_rational::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let c = RationalCurve::new(vec![p(0, 0), p(1, 2), p(3, 0)], vec![ratio(1, 1), ratio(2, 1), ratio(5, 1)]).unwrap();
/// let copy = c.mobius(&ratio(1, 3)).reverse().elevate(1).scale_weights(&ratio(7, 2));
/// assert_eq!(canonical_key(&Patch::Curve(c)).unwrap(), canonical_key(&Patch::Curve(copy)).unwrap());
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CanonicalKey {
    curve: bool,
    degree: (usize, usize),
    points: Vec<Option<Vec<BigRational>>>,
    invariants: Vec<(i8, BigRational)>,
}

impl CanonicalKey {
    /// The minimal (bi)degree of the class.
    pub fn degree(&self) -> (usize, usize) {
        self.degree
    }

    /// The weight invariants `I_{i,j}` row by row (for positive weights:
    /// the weights normalized to `ω_{0,0} = ω_{1,0} = ω_{0,1} = 1`).
    pub fn invariants(&self) -> impl Iterator<Item = &BigRational> {
        self.invariants.iter().map(|(_, x)| x)
    }
}

fn positions(m: usize, n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..=m).flat_map(move |i| (0..=n).map(move |j| (i, j)))
}

fn cmp_points(a: &View<'_, BigRational>, b: &View<'_, BigRational>) -> Ordering {
    positions(a.m, a.n)
        .map(|(i, j)| a.hat(i, j).cmp(&b.hat(i, j)))
        .find(|o| o.is_ne())
        .unwrap_or(Ordering::Equal)
}

fn invariants(v: &View<'_, BigRational>) -> Vec<(i8, BigRational)> {
    positions(v.m, v.n)
        .map(|(i, j)| v.sign(i, j))
        .zip(v.invariants())
        .collect()
}

/// The canonical key of a curve or rect patch (exact).
///
/// # Errors
///
/// [`Error::Shape`] for a tri patch, [`Error::Weight`] for a non-positive weight.
pub fn canonical_key(p: &Patch<BigRational>) -> Result<CanonicalKey, Error> {
    let (net, curve) = net_of(p)?;
    let red = minimal_net(&net).patch;
    let prep = Prepared::new(&red);
    let (m, n) = (prep.m, prep.n);
    let target = if curve { (m, n) } else { (m.min(n), m.max(n)) };
    let views: Vec<View<'_, BigRational>> = Symmetry::admissible(curve, (m, n), target)
        .map(|s| prep.view(s))
        .collect();
    let mut best: Vec<View<'_, BigRational>> = Vec::new();
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
        .min_by(|a, b| a.1.cmp(&b.1))
        .expect("the identity is admissible");
    Ok(CanonicalKey {
        curve,
        degree: target,
        points: positions(view.m, view.n)
            .map(|(i, j)| view.hat(i, j).cloned())
            .collect(),
        invariants,
    })
}

impl CanonicalKey {
    /// An injective byte encoding of the key (length-prefixed numerators
    /// and denominators), compact enough to keep one per class in memory.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = vec![u8::from(self.curve)];
        let usize_bytes =
            |out: &mut Vec<u8>, x: usize| out.extend_from_slice(&(x as u64).to_le_bytes());
        usize_bytes(&mut out, self.degree.0);
        usize_bytes(&mut out, self.degree.1);
        let rational = |out: &mut Vec<u8>, q: &BigRational| {
            for part in [q.numer(), q.denom()] {
                let (sign, bytes) = part.to_bytes_le();
                out.push(sign as u8);
                out.extend_from_slice(&(bytes.len() as u32).to_le_bytes());
                out.extend_from_slice(&bytes);
            }
        };
        for p in &self.points {
            match p {
                None => out.push(0),
                Some(p) => {
                    out.push(1);
                    out.extend_from_slice(&(p.len() as u32).to_le_bytes());
                    p.iter().for_each(|x| rational(&mut out, x));
                }
            }
        }
        for (sign, x) in &self.invariants {
            out.push(*sign as u8);
            rational(&mut out, x);
        }
        out
    }
}

/// Streaming grouping into coincidence classes: one exact canonical key
/// per input, one compact key ([`CanonicalKey::to_bytes`]) kept per class,
/// O(1) expected time per input.
///
/// ```
/// use exact_bezier::{Deduper, Patch, RationalCurve, ratio};
/// use num_rational::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let a = RationalCurve::new(vec![p(0), p(1), p(3)], vec![ratio(1, 1), ratio(2, 1), ratio(1, 1)]).unwrap();
/// let mut d = Deduper::default();
/// assert_eq!(d.insert(&Patch::Curve(a.clone())).unwrap(), 0);
/// assert_eq!(d.insert(&Patch::Curve(a.mobius(&ratio(1, 5)))).unwrap(), 0);
/// assert_eq!(d.insert(&Patch::Curve(a.elevate(1).scale_weights(&ratio(1, 2)).reverse())).unwrap(), 0);
/// assert_eq!(d.classes(), vec![vec![0, 1, 2]]);
/// ```
#[derive(Clone, Debug, Default)]
pub struct Deduper {
    index: HashMap<Box<[u8]>, usize>,
    classes: Vec<Vec<usize>>,
    seen: usize,
}

impl Deduper {
    /// Add the next input (its index is the number inserted before it);
    /// returns its class id (classes are numbered by first appearance).
    ///
    /// # Errors
    ///
    /// As [`canonical_key`].
    pub fn insert(&mut self, p: &Patch<BigRational>) -> Result<usize, Error> {
        let key = canonical_key(p)?.to_bytes().into_boxed_slice();
        let next = self.classes.len();
        let id = *self.index.entry(key).or_insert(next);
        if id == next {
            self.classes.push(Vec::new());
        }
        self.classes[id].push(self.seen);
        self.seen += 1;
        Ok(id)
    }

    /// The classes: member indices in input order, classes by first member.
    pub fn classes(self) -> Vec<Vec<usize>> {
        self.classes
    }
}

/// Group patches into coincidence classes by their canonical keys, in
/// O(N) expected time (see [`Deduper`]): each class lists member indices in
/// input order; classes are ordered by their first member.
///
/// ```
/// use exact_bezier::{dedup, Patch, RationalCurve, ratio};
/// use num_rational::BigRational;
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
/// As [`canonical_key`], naming the element.
pub fn dedup(patches: &[Patch<BigRational>]) -> Result<Vec<Vec<usize>>, Error> {
    let mut d = Deduper::default();
    for (k, p) in patches.iter().enumerate() {
        d.insert(p)
            .map_err(|e| Error::Format(format!("element {k}: {e}")))?;
    }
    Ok(d.classes())
}
