//! Exact coincidence of rational curves and tensor-product patches: are two
//! inputs the same parametric patch up to
//!
//! 1. an orientation-preserving Möbius map of each parameter,
//!    `u = (α − 1)s / (2αs − s − α)`, α ∈ (0, 1) (source 000 eqs 2, 3);
//! 2. reversal of either parameter; 3. swapping u and v;
//! 4. degree elevation; 5. common factors of the homogeneous components;
//! 6. uniform scaling of the weights (source 000 eq. 5)?
//!
//! The decision: reduce both inputs to minimal bidegree
//! ([`minimal_rect`]); then for each admissible symmetry
//! compare the normalized control points exactly and the weight invariants
//! `I_{i,j}` (module `view`). After reduction, Möbius maps and
//! scaling act on the homogeneous control points by `H_{i,j} ↦ k ρ^i σ^j H_{i,j}`
//! with `ρ = (1 − α)/α > 0`, `σ = (1 − β)/β > 0` (eq. 4 with `k` absorbing
//! `α^m β^n`), so two reduced nets coincide iff their normalized points agree
//! and their invariants and signs agree (proved in `proofs/src/coincide.rs`).
//! The witness is exact: `ρ = x_{1,0}` is rational whenever both nets have
//! non-zero `H_{1,0}` (always, for positive weights), hence `α = 1/(1 + ρ)`
//! is rational too; otherwise `ρ^a` is given.
//!
//! Beyond source 000 §3, which compares standardized patches (needing m-th
//! roots, so not exact over Q, and blind to reversal, swapping and common
//! factors). Two patches related by a reparameterization of higher degree
//! (e.g. the quadratic one of eqs 9–17) are *not* coincident in this sense.
//!
//! Module layout: `view` (normalized nets under symmetries), this file (the
//! one entry point [`coincide`] with its [`Options`], the decision and its
//! witness), `filter` (the interval filter), `boundary` (shared boundary
//! curves).

pub mod canonical;
mod certificate;
mod coprime;
mod filter;
pub mod minimal;

pub use canonical::{canonical_key, dedup, CanonicalKey, Deduper};
pub use canonical::{canonical_text, key_digest, Classes, KeyDigest, KEY_VERSION};
pub use minimal::{minimal_curve, minimal_rect, multiply_components, Minimal, Reducible};

mod boundary;
mod view;

pub use boundary::{boundary_curve, shared_boundaries, Edge};
pub use view::invariant_parts;
pub(crate) use view::{Prepared, View};

use crate::algebra::scalar::{Ordered, Roots, Scalar, Tolerance};
use crate::algebra::RealAlgebraic;
use crate::coincide::minimal::{curve_net, drop_elevation, minimal_net, Net};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::rect::RectPatch;
use crate::Patch;
use num_rational::BigRational;
use std::borrow::Cow;
use std::fmt;

/// One of the 8 symmetries of the parameter square: first swap u and v (if
/// `swap`), then reverse u, then reverse v. Curves use only `reverse_u`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Symmetry {
    /// Swap the parameters: new (u, v) is old (v, u).
    pub swap: bool,
    /// Reverse u: new u is old 1 − u.
    pub reverse_u: bool,
    /// Reverse v: new v is old 1 − v.
    pub reverse_v: bool,
}

impl Symmetry {
    /// The identity.
    pub const IDENTITY: Symmetry = Symmetry {
        swap: false,
        reverse_u: false,
        reverse_v: false,
    };

    /// All 8 symmetries, identity first.
    pub fn all() -> impl Iterator<Item = Symmetry> {
        (0..8u8).map(|b| Symmetry {
            swap: b & 4 != 0,
            reverse_u: b & 1 != 0,
            reverse_v: b & 2 != 0,
        })
    }

    /// The symmetries that map a net of bidegree `(m, n)` to one of
    /// bidegree `(m2, n2)`; for curves (`curve`) only the reversals of u.
    pub(crate) fn admissible(
        curve: bool,
        (m, n): (usize, usize),
        (m2, n2): (usize, usize),
    ) -> impl Iterator<Item = Symmetry> {
        Symmetry::all().filter(move |s| {
            if curve {
                !s.swap && !s.reverse_v && (m, n) == (m2, n2)
            } else if s.swap {
                (n, m) == (m2, n2)
            } else {
                (m, n) == (m2, n2)
            }
        })
    }

    /// Apply to a patch: swap, then reverse u, then reverse v.
    ///
    /// ```
    /// use exact_bezier::{RectPatch, coincide::Symmetry, ratio};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
    /// let r = RectPatch::polynomial(vec![vec![p(0), p(1)], vec![p(2), p(3)]]).unwrap();
    /// let s = Symmetry { swap: true, reverse_u: true, reverse_v: false };
    /// // New (u, v) = (0, 0) reads old (u, v) = (0, 1) → P_{0,1} = 1.
    /// assert_eq!(s.apply_rect(&r).points().unwrap()[0][0], p(1));
    /// ```
    pub fn apply_rect<T: Scalar>(&self, r: &RectPatch<T>) -> RectPatch<T> {
        let mut out = if self.swap { r.swap_uv() } else { r.clone() };
        if self.reverse_u {
            out = out.reverse_u();
        }
        if self.reverse_v {
            out = out.reverse_v();
        }
        out
    }

    /// Apply to a curve (only `reverse_u` acts).
    pub fn apply_curve<T: Scalar>(&self, c: &RationalCurve<T>) -> RationalCurve<T> {
        if self.reverse_u {
            c.reverse()
        } else {
            c.clone()
        }
    }
}

impl fmt::Display for Symmetry {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parts: Vec<&str> = [
            (self.swap, "swap u,v"),
            (self.reverse_u, "reverse u"),
            (self.reverse_v, "reverse v"),
        ]
        .iter()
        .filter(|(on, _)| *on)
        .map(|(_, name)| *name)
        .collect();
        if parts.is_empty() {
            f.write_str("identity")
        } else {
            f.write_str(&parts.join(" + "))
        }
    }
}

/// A Möbius parameter of the witness, in one direction.
#[derive(Clone, Debug, PartialEq)]
pub enum MobiusParam<T> {
    /// The direction has degree 0: no parameter.
    None,
    /// `ρ = (1 − α)/α` and `α = 1/(1 + ρ)`, both exact for exact scalars.
    Value {
        /// `ρ`.
        rho: T,
        /// `α`.
        alpha: T,
    },
    /// `ρ` is not computed: irrational over Q, or (over the real algebraic
    /// numbers) its root would need a field over the field degree limit
    /// ([`Roots::bounded_root`]): `ρ^exponent = power` (then `α = 1/(1 + ρ)`).
    Power {
        /// The exponent `a`.
        exponent: usize,
        /// `ρ^a`.
        power: T,
    },
}

/// How b is obtained from a (after both are reduced to minimal degree):
/// `b = k · Möbius_v(β) · Möbius_u(α) · symmetry(a)`, i.e. weights
/// `ω^b_{i,j} = k (1 − α)^i α^{m−i} (1 − β)^j β^{n−j} ω^{S(a)}_{i,j}`.
#[derive(Clone, Debug, PartialEq)]
pub struct Witness<T> {
    /// The symmetry applied to a first.
    pub symmetry: Symmetry,
    /// The Möbius parameter in u.
    pub u: MobiusParam<T>,
    /// The Möbius parameter in v.
    pub v: MobiusParam<T>,
    /// The uniform weight scale `k` (when α and β are exact).
    pub k: Option<T>,
    /// `ω^b_{0,0} / ω^{S(a)}_{0,0} = k α^m β^n`.
    pub corner_ratio: T,
}

/// The minimal-degree reduction applied to one input.
#[derive(Clone, Debug, PartialEq)]
pub struct ReductionInfo {
    /// (Bi)degree before.
    pub from: (usize, usize),
    /// (Bi)degree after.
    pub to: (usize, usize),
    /// The common factor removed (`"1"` if none; always `"1"` on the f64 path,
    /// which undoes elevation only).
    pub common_factor: String,
}

/// The answer of [`coincide`]: a decision with its reason and witness.
#[derive(Clone, Debug, PartialEq)]
pub struct Coincidence<T> {
    /// Are the inputs the same patch up to the maps (1)–(6)?
    pub coincident: bool,
    /// Why: the witness in words, or the first difference found.
    pub reason: String,
    /// The maps taking a to b, when coincident.
    pub witness: Option<Witness<T>>,
    /// The reductions of a and b.
    pub reductions: [ReductionInfo; 2],
    /// Which stage decided ([`DecidedBy::Exact`] unless [`Options::filtered`]
    /// let an interval stage decide).
    pub decided_by: DecidedBy,
}

/// Which stage decided a [`coincide`] call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DecidedBy {
    /// Interval bounds on the corner points.
    Corners,
    /// Interval bounds on the control points and weight invariants.
    Intervals,
    /// The full decision (exact, or within the tolerance for `f64`).
    Exact,
}

/// How [`coincide`] decides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Decide with `f64` interval bounds first when they can (module
    /// `filter`: only "not coincident" is certified that way), exactly
    /// otherwise: the same answer. Over `BigRational` only; other scalars
    /// take the full decision.
    pub filtered: bool,
    /// For `f64` only: points within `tol` (absolute), weight invariants
    /// within `tol` relative to their size, power coefficients within `tol`
    /// treated as zero when undoing elevation. Exact scalars ignore it.
    pub tol: Tolerance,
}

impl Options {
    /// The filtered exact decision ([`Options::filtered`]).
    pub fn filtered() -> Options {
        Options {
            filtered: true,
            ..Options::default()
        }
    }

    /// The `f64` decision within `tol` ([`Options::tol`]).
    pub fn within(tol: Tolerance) -> Options {
        Options {
            tol,
            ..Options::default()
        }
    }
}

impl Default for Options {
    /// Unfiltered; for `f64` the tolerance [`Tolerance::default`] (`1e-9`).
    fn default() -> Self {
        Options {
            filtered: false,
            tol: Tolerance::default(),
        }
    }
}

/// Why one symmetry failed: `stage` 0 points, 1 signs, 2 invariants; the
/// furthest failure over all symmetries is reported.
/// The text is built only for the reported failure (formatting numbers,
/// especially `f64`, costs more than the comparison).
struct Mismatch<'a> {
    stage: u8,
    position: usize,
    text: Box<dyn Fn() -> String + 'a>,
}

fn point_text<T: fmt::Display>(h: &[T]) -> String {
    let shown = if h.last().is_some_and(|w| w.to_string() == "1") {
        &h[..h.len() - 1]
    } else {
        h
    };
    let parts: Vec<String> = shown.iter().map(ToString::to_string).collect();
    format!("({})", parts.join(", "))
}

/// Relative closeness `|x − y| ≤ tol · max(|x|, |y|)` (exact equality for
/// exact scalars). Purely relative: invariants of Möbius-moved weights span
/// many orders of magnitude, so no absolute floor.
fn close<T: Ordered>(x: &T, y: &T, tol: Tolerance) -> bool {
    let (ax, ay) = (x.abs_val(), y.abs_val());
    let big = if ax > ay { ax } else { ay };
    if big.is_zero() {
        return true;
    }
    ((x.clone() - y) / big).is_zero_within(tol)
}

/// Compare b's view with a's view position by position (same shape).
fn compare<'a, T: Roots + fmt::Display>(
    va: View<'a, T>,
    vb: View<'a, T>,
    tol: Tolerance,
) -> Result<Witness<T>, Mismatch<'a>> {
    let positions: Vec<(usize, usize)> = (0..=va.m)
        .flat_map(|i| (0..=va.n).map(move |j| (i, j)))
        .collect();
    for (idx, &(i, j)) in positions.iter().enumerate() {
        let same = match (va.hat(i, j), vb.hat(i, j)) {
            (None, None) => true,
            (Some(p), Some(q)) => p
                .iter()
                .zip(q)
                .all(|(x, y)| (x.clone() - y).is_zero_within(tol)),
            _ => false,
        };
        if !same {
            let show = |h: Option<&Vec<T>>| h.map_or("0".to_string(), |h| point_text(h));
            return Err(Mismatch {
                stage: 0,
                position: idx,
                text: Box::new(move || {
                    format!(
                        "control point P_{{{i},{j}}} differs: {} vs {}",
                        show(va.hat(i, j)),
                        show(vb.hat(i, j))
                    )
                }),
            });
        }
    }
    for (idx, &(i, j)) in positions.iter().enumerate() {
        if va.sign(i, j) != vb.sign(i, j) {
            return Err(Mismatch {
                stage: 1,
                position: idx,
                text: Box::new(move || format!("the sign of ω_{{{i},{j}}}·ω_{{0,0}} differs")),
            });
        }
    }
    let (inv_a, inv_b) = (va.invariants(), vb.invariants());
    for (idx, (&(i, j), (ia, ib))) in positions
        .iter()
        .zip(inv_a.into_iter().zip(inv_b))
        .enumerate()
    {
        if !close(&ia, &ib, tol) {
            return Err(Mismatch {
                stage: 2,
                position: idx,
                text: Box::new(move || format!("weight invariant I_{{{i},{j}}} is {ia} vs {ib}")),
            });
        }
    }
    Ok(witness(&va, &vb))
}

/// The Möbius parameters and scale once the nets are known to match.
fn witness<T: Roots>(va: &View<'_, T>, vb: &View<'_, T>) -> Witness<T> {
    let lambda = |i: usize, j: usize| vb.scale(i, j).clone() / va.scale(i, j);
    let l00 = lambda(0, 0);
    let (pu, pv) = va.pivots();
    let param = |pivot: Option<usize>, at: &dyn Fn(usize) -> (usize, usize)| match pivot {
        None => MobiusParam::None,
        Some(a) => {
            let (i, j) = at(a);
            let power = lambda(i, j) / &l00;
            match power.bounded_root(a as u32) {
                Some(rho) => {
                    let alpha = (T::one() + &rho).recip();
                    MobiusParam::Value { rho, alpha }
                }
                None => MobiusParam::Power { exponent: a, power },
            }
        }
    };
    let u = param(pu, &|a| (a, 0));
    let v = param(pv, &|b| (0, b));
    let factor = |p: &MobiusParam<T>, deg: usize| match p {
        MobiusParam::None => Some(T::one()),
        MobiusParam::Value { alpha, .. } => Some(alpha.pow_u32(deg as u32)),
        MobiusParam::Power { .. } => None,
    };
    let k = factor(&u, va.m)
        .zip(factor(&v, va.n))
        .map(|(fu, fv)| l00.clone() / &(fu * &fv));
    Witness {
        symmetry: va.sym,
        u,
        v,
        k,
        corner_ratio: l00,
    }
}

/// Decide for two reduced nets.
fn decide<T: Roots + fmt::Display>(
    na: &Net<T>,
    nb: &Net<T>,
    curve: bool,
    tol: Tolerance,
    reductions: [ReductionInfo; 2],
) -> Coincidence<T> {
    let (pa, pb) = (Prepared::new(na), Prepared::new(nb));
    let vb = pb.view(Symmetry::IDENTITY);
    let mut best: Option<Mismatch> = None;
    let mut tried = 0;
    for sym in Symmetry::admissible(curve, (pa.m, pa.n), (pb.m, pb.n)) {
        tried += 1;
        match compare(pa.view(sym), vb, tol) {
            Ok(w) => {
                let reason = format!(
                    "same {} up to {} and Möbius/weight scaling",
                    if curve { "curve" } else { "patch" },
                    w.symmetry
                );
                return Coincidence {
                    coincident: true,
                    reason,
                    witness: Some(w),
                    reductions,
                    decided_by: DecidedBy::Exact,
                };
            }
            Err(e) => {
                if best
                    .as_ref()
                    .is_none_or(|b| (e.stage, e.position) > (b.stage, b.position))
                {
                    best = Some(e);
                }
            }
        }
    }
    let reason = match best {
        None => format!(
            "minimal (bi)degrees differ: {:?} vs {:?}",
            reductions[0].to, reductions[1].to
        ),
        Some(e) => format!("{} (best of {tried} symmetries)", (e.text)()),
    };
    Coincidence {
        coincident: false,
        reason,
        witness: None,
        reductions,
        decided_by: DecidedBy::Exact,
    }
}

fn info<T>(red: &Minimal<Net<T>, T>) -> ReductionInfo {
    ReductionInfo {
        from: red.degree_before,
        to: red.degree_after,
        common_factor: red.common_factor.clone(),
    }
}

fn shape_of<T>(net: &Net<T>) -> (usize, usize) {
    (net.len() - 1, net[0].len() - 1)
}

/// The homogeneous net of a curve or rect patch with positive weights
/// (a rect patch's own net, borrowed).
pub(crate) fn net_of<T: Ordered>(p: &Patch<T>) -> Result<(Cow<'_, Net<T>>, bool), Error> {
    match p {
        Patch::Curve(c) => {
            c.check_positive_weights()?;
            Ok((Cow::Owned(curve_net(c)), true))
        }
        Patch::Rect(r) => {
            r.check_positive_weights()?;
            Ok((Cow::Borrowed(r.ctrl_rows()), false))
        }
        Patch::Tri(_) => Err(Error::Shape(
            "coincide compares curves and rect patches, not tri patches".into(),
        )),
    }
}

fn kinds_differ<T: Scalar>(a: &Patch<T>, b: &Patch<T>) -> Option<Coincidence<T>> {
    (a.kind() != b.kind()).then(|| Coincidence {
        coincident: false,
        reason: format!("a {} and a {} are never the same patch", a.kind(), b.kind()),
        witness: None,
        reductions: std::array::from_fn(|_| ReductionInfo {
            from: (0, 0),
            to: (0, 0),
            common_factor: "1".into(),
        }),
        decided_by: DecidedBy::Exact,
    })
}

/// Coincidence of two curves or two rect patches (see the module docs).
///
/// Over exact scalars no tolerance: over `BigRational` no roots either;
/// over [`RealAlgebraic`] (patches with algebraic control points or
/// weights, e.g. a standard form) the same decision runs on exact algebraic
/// numbers, and the witness's `ρ = (λ_{a,0}/λ_{0,0})^{1/a}` is always a
/// number (an exact root). [`Options::filtered`] decides over `BigRational`
/// by `f64` interval bounds first where they can (same answer,
/// [`Coincidence::decided_by`] says which stage decided; the reductions
/// reported by an interval stage are those known at that point).
///
/// Over `f64` the decision is within [`Options::tol`]: points within `tol`
/// (absolute), invariants within `tol` (relative to their size); degree
/// elevation is undone with power coefficients within `tol` treated as
/// zero; common factors of degree ≥ 1 are **not** removed (a floating-point
/// gcd is not a decision: use an exact scalar).
///
/// # Examples
///
/// Source 000 Example 1 against a Möbius-reparameterized, reversed and
/// elevated copy of itself:
///
/// ```
/// use exact_bezier::{coincide::{coincide, Options}, io::read_patches, Patch, ratio};
/// let text = std::fs::read_to_string("tests/fixtures/yang_yong_example1.json").unwrap();
/// let a = read_patches(&text).unwrap().remove(0);
/// let Patch::Rect(r) = &a else { unreachable!() };
/// let b = Patch::Rect(r.mobius_u(&ratio(3, 5)).mobius_v(&ratio(7, 10)).reverse_v().elevate(1, 2));
/// let c = coincide(&a, &b, Options::default()).unwrap();
/// assert!(c.coincident);
/// assert_eq!(c.witness.unwrap().symmetry.to_string(), "reverse v");
/// ```
///
/// Examples 1 and 3: different exactly, decided by intervals when filtered,
/// the same within a coarse `f64` tolerance:
///
/// ```
/// use exact_bezier::{coincide::{coincide, DecidedBy, Options}, io::read_patches, Tolerance};
/// let read = |f: &str| read_patches(&std::fs::read_to_string(f).unwrap()).unwrap().remove(0);
/// let ex1 = read("tests/fixtures/yang_yong_example1.json");
/// let ex3 = read("tests/fixtures/yang_yong_example3.json");
/// let c = coincide(&ex1, &ex3, Options::filtered()).unwrap();
/// assert!(!c.coincident);
/// assert_eq!(c.decided_by, DecidedBy::Intervals);
/// let (f1, f3) = (ex1.to_f64(), ex3.to_f64());
/// assert!(!coincide(&f1, &f3, Options::within(Tolerance(1e-9))).unwrap().coincident);
/// assert!(coincide(&f1, &f3, Options::within(Tolerance(0.05))).unwrap().coincident);
/// ```
///
/// # Errors
///
/// [`Error::Shape`] for tri patches; [`Error::Weight`] for a non-positive
/// weight.
pub fn coincide<T: CoincideScalar>(
    a: &Patch<T>,
    b: &Patch<T>,
    options: Options,
) -> Result<Coincidence<T>, Error> {
    let ((na, curve), (nb, _)) = (net_of(a)?, net_of(b)?);
    if let Some(c) = kinds_differ(a, b) {
        return Ok(c);
    }
    Ok(T::decide_nets(&na, &nb, curve, options))
}

/// A scalar [`coincide`] decides over: how two homogeneous nets of one kind
/// are reduced and compared.
pub trait CoincideScalar: Roots + fmt::Display {
    /// The decision for the nets `na`, `nb` (curves when `curve`).
    fn decide_nets(
        na: &Net<Self>,
        nb: &Net<Self>,
        curve: bool,
        options: Options,
    ) -> Coincidence<Self>;
}

/// Exact; [`Options::filtered`] runs the interval filter first.
impl CoincideScalar for BigRational {
    fn decide_nets(
        na: &Net<Self>,
        nb: &Net<Self>,
        curve: bool,
        options: Options,
    ) -> Coincidence<Self> {
        if options.filtered {
            filter::filtered(na, nb, curve)
        } else {
            exact_nets(na, nb, curve)
        }
    }
}

/// Exact, on real algebraic numbers.
impl CoincideScalar for RealAlgebraic {
    fn decide_nets(na: &Net<Self>, nb: &Net<Self>, curve: bool, _: Options) -> Coincidence<Self> {
        exact_nets(na, nb, curve)
    }
}

/// Within [`Options::tol`]; elevation undone, common factors kept.
impl CoincideScalar for f64 {
    fn decide_nets(
        na: &Net<Self>,
        nb: &Net<Self>,
        curve: bool,
        options: Options,
    ) -> Coincidence<Self> {
        let tol = options.tol;
        let (ra, rb) = (drop_elevation(na, tol), drop_elevation(nb, tol));
        let info = |from: &Net<f64>, to: &Net<f64>| ReductionInfo {
            from: shape_of(from),
            to: shape_of(to),
            common_factor: "1".into(),
        };
        let reductions = [info(na, &ra), info(nb, &rb)];
        decide(&ra, &rb, curve, tol, reductions)
    }
}

/// The exact decision for two homogeneous nets of the same kind.
pub(crate) fn exact_nets<T: Reducible + Roots>(
    na: &Net<T>,
    nb: &Net<T>,
    curve: bool,
) -> Coincidence<T> {
    let (ra, rb) = (minimal_net(na), minimal_net(nb));
    decide(
        &ra.patch,
        &rb.patch,
        curve,
        Tolerance::EXACT,
        [info(&ra), info(&rb)],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    use crate::samples::cubic as curve;

    #[test]
    fn curve_copies_coincide_with_exact_witness() {
        let a = curve();
        let b = a
            .mobius(&ratio(2, 7))
            .scale_weights(&ratio(5, 3))
            .reverse()
            .elevate(2);
        let c = coincide(&Patch::Curve(a), &Patch::Curve(b), Options::default()).unwrap();
        assert!(c.coincident, "{}", c.reason);
        let w = c.witness.unwrap();
        assert!(w.symmetry.reverse_u);
        // b reversed back is a.mobius(2/7); reversing turns α into 1 − α.
        assert_eq!(
            w.u,
            MobiusParam::Value {
                rho: ratio(2, 5),
                alpha: ratio(5, 7)
            }
        );
        assert_eq!(w.k, Some(ratio(5, 3)));
    }

    #[test]
    fn perturbed_weight_is_named() {
        let a = curve();
        let w = a.weights();
        let pts = a.points().unwrap();
        let mut w2 = w.clone();
        w2[2] = ratio(1, 2);
        let b = RationalCurve::new(pts, w2).unwrap();
        let c = coincide(&Patch::Curve(a), &Patch::Curve(b), Options::default()).unwrap();
        assert!(!c.coincident);
        assert!(
            c.reason
                .starts_with("weight invariant I_{2,0} is 1/12 vs 1/8"),
            "{}",
            c.reason
        );
    }
}
