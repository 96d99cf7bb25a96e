//! Normalized control nets and their views under the 8 symmetries of the
//! unit square: the data both the pairwise decision and the canonical key
//! are read from.
//!
//! For every position the homogeneous point `H_{i,j}` is split into a
//! *scale* `s_{i,j}` (the weight if it is non-zero, else the first non-zero
//! coordinate; 0 for the zero vector) and the *normalized point*
//! `Ĥ_{i,j} = H_{i,j} / s_{i,j}` (the Cartesian point with a trailing 1 when
//! the weight is non-zero). Under the Möbius maps and weight scaling,
//! `H_{i,j} ↦ k ρ^i σ^j H_{i,j}`: the normalized points are unchanged and
//! the scales move by `k ρ^i σ^j`. The weight invariants
//!
//! ```text
//! I_{i,j} = s_{i,j}^{ab} · s_{0,0}^{ib + ja − ab} / (s_{a,0}^{ib} · s_{0,b}^{ja})
//! ```
//!
//! with pivots `a`, `b` (the first non-zero positions (a, 0), (0, b) with
//! a, b > 0; a = b = 1 for positive weights, where
//! `I_{i,j} = ω_{i,j} ω_{0,0}^{i+j−1} / (ω_{1,0}^i ω_{0,1}^j)`, the weights
//! normalized to `ω_{0,0} = ω_{1,0} = ω_{0,1} = 1`) are invariant, and with
//! the signs `sgn(s_{i,j} s_{0,0})` they are complete: see `proofs/src/coincide.rs`.

use super::Symmetry;
use crate::algebra::scalar::{Field, Ordered, Scalar};
use crate::coincide::minimal::Net;
use crate::hpoint::HPoint;

/// A net split into normalized points and scales, in its own orientation.
#[derive(Clone, Debug)]
pub(crate) struct Prepared<T> {
    pub m: usize,
    pub n: usize,
    /// `Ĥ_{i,j}`, `None` for the zero vector.
    pub hat: Vec<Vec<Option<Vec<T>>>>,
    /// `s_{i,j}` (zero for the zero vector).
    pub scale: Vec<Vec<T>>,
}

/// The scale coordinate of a homogeneous point: the weight if non-zero,
/// else the first non-zero coordinate. Exact zero tests even for `f64`: a
/// tiny weight (a Möbius parameter near 0 or 1 makes weights span many
/// orders of magnitude) is still the scale, and tolerances apply only when
/// normalized quantities are compared.
fn scale_of<T: Field>(h: &HPoint<T>) -> Option<T> {
    if !h.weight().is_zero() {
        return Some(h.weight().clone());
    }
    h.coords.iter().find(|c| !c.is_zero()).cloned()
}

impl<T: Ordered> Prepared<T> {
    pub fn new(net: &Net<T>) -> Self {
        let (m, n) = (net.len() - 1, net[0].len() - 1);
        let mut hat = Vec::with_capacity(m + 1);
        let mut scale = Vec::with_capacity(m + 1);
        for row in net {
            let mut hr = Vec::with_capacity(n + 1);
            let mut sr = Vec::with_capacity(n + 1);
            for h in row {
                match scale_of(h) {
                    Some(s) => {
                        hr.push(Some(T::divide_each(&h.coords, &s)));
                        sr.push(s);
                    }
                    None => {
                        hr.push(None);
                        sr.push(T::zero());
                    }
                }
            }
            hat.push(hr);
            scale.push(sr);
        }
        Prepared { m, n, hat, scale }
    }

    /// This net seen through `sym`.
    pub fn view(&self, sym: Symmetry) -> View<'_, T> {
        let (m, n) = if sym.swap {
            (self.n, self.m)
        } else {
            (self.m, self.n)
        };
        View { p: self, sym, m, n }
    }
}

/// A [`Prepared`] net seen through a symmetry: position (i, j) of the
/// transformed net reads position `src(i, j)` of the original.
#[derive(Debug)]
pub(crate) struct View<'a, T> {
    p: &'a Prepared<T>,
    pub sym: Symmetry,
    pub m: usize,
    pub n: usize,
}

// Manual impls: a view is a reference, copyable whatever `T` is.
impl<T> Clone for View<'_, T> {
    fn clone(&self) -> Self {
        *self
    }
}
impl<T> Copy for View<'_, T> {}

impl<'a, T: Ordered> View<'a, T> {
    /// The original position of transformed position (i, j).
    pub fn src(&self, i: usize, j: usize) -> (usize, usize) {
        let i1 = if self.sym.reverse_u { self.m - i } else { i };
        let j1 = if self.sym.reverse_v { self.n - j } else { j };
        if self.sym.swap {
            (j1, i1)
        } else {
            (i1, j1)
        }
    }

    pub fn hat(&self, i: usize, j: usize) -> Option<&'a Vec<T>> {
        let (a, b) = self.src(i, j);
        self.p.hat[a][b].as_ref()
    }

    pub fn scale(&self, i: usize, j: usize) -> &'a T {
        let (a, b) = self.src(i, j);
        &self.p.scale[a][b]
    }

    fn nonzero(&self, i: usize, j: usize) -> bool {
        !self.scale(i, j).is_zero()
    }

    /// The pivots `a` and `b` (first non-zero positions (a, 0), (0, b)).
    pub fn pivots(&self) -> (Option<usize>, Option<usize>) {
        (
            (1..=self.m).find(|&i| self.nonzero(i, 0)),
            (1..=self.n).find(|&j| self.nonzero(0, j)),
        )
    }

    /// `sgn(s_{i,j} · s_{0,0})` as −1, 0, 1.
    pub fn sign(&self, i: usize, j: usize) -> i8 {
        let sign = |x: &T| x.sign_order() as i8;
        sign(self.scale(i, j)) * sign(self.scale(0, 0))
    }

    /// All weight invariants `I_{i,j}`, row by row (0 at a zero position).
    ///
    /// With pivots a = b = 1 (always, for positive weights) they are the
    /// scales normalized by an exact Möbius map and scaling,
    /// `I_{i,j} = (s_{i,j}/s_{0,0}) · A^i · B^j` with `A = s_{0,0}/s_{1,0}`,
    /// `B = s_{0,0}/s_{0,1}` — the same rational as [`invariant_parts`] gives,
    /// computed with two products per position; otherwise that formula.
    pub fn invariants(&self) -> Vec<T> {
        let (pu, pv) = self.pivots();
        let s00 = self.scale(0, 0);
        let ok = |p: Option<usize>, deg: usize| p == Some(1) || (p.is_none() && deg == 0);
        let positions = (0..=self.m).flat_map(|i| (0..=self.n).map(move |j| (i, j)));
        if !(ok(pu, self.m) && ok(pv, self.n)) {
            return positions
                .map(|(i, j)| {
                    if !self.nonzero(i, j) {
                        return T::zero();
                    }
                    let (num, den) = invariant_parts(|a, b| self.scale(a, b).clone(), i, j, pu, pv);
                    num / den
                })
                .collect();
        }
        let powers = |pivot: Option<(usize, usize)>, deg: usize| {
            let base =
                pivot.map_or_else(T::one, |(a, b)| s00.mul_scalar(&self.scale(a, b).recip()));
            let mut out = vec![T::one()];
            for k in 0..deg {
                out.push(out[k].mul_scalar(&base));
            }
            out
        };
        let (pa, pb) = (
            powers(pu.map(|a| (a, 0)), self.m),
            powers(pv.map(|b| (0, b)), self.n),
        );
        let inv00 = s00.recip();
        positions
            .map(|(i, j)| {
                self.scale(i, j)
                    .mul_scalar(&inv00)
                    .mul_scalar(&pa[i])
                    .mul_scalar(&pb[j])
            })
            .collect()
    }
}

/// Numerator and denominator of the weight invariant
/// `I_{i,j} = s_{i,j}^{ab} · s_{0,0}^{ib + ja − ab} / (s_{a,0}^{ib} · s_{0,b}^{ja})`
/// from the scales `s`, with pivots `a = pu`, `b = pv` (a missing pivot, for
/// a direction of degree 0, counts as 1 with no factor). Ring operations
/// only, so the proofs run it on symbols.
pub fn invariant_parts<T: Scalar>(
    s: impl Fn(usize, usize) -> T,
    i: usize,
    j: usize,
    pu: Option<usize>,
    pv: Option<usize>,
) -> (T, T) {
    let (a, b) = (pu.unwrap_or(1), pv.unwrap_or(1));
    let s00 = s(0, 0);
    let mut num = s(i, j).pow_u32((a * b) as u32);
    let mut den = T::one();
    let e00 = (i * b + j * a) as i64 - (a * b) as i64;
    if e00 >= 0 {
        num = num * s00.pow_u32(e00 as u32);
    } else {
        den = den * s00.pow_u32((-e00) as u32);
    }
    if let Some(a) = pu {
        den = den * s(a, 0).pow_u32((i * b) as u32);
    }
    if let Some(b) = pv {
        den = den * s(0, b).pow_u32((j * a) as u32);
    }
    (num, den)
}
