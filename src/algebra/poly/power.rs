//! Powers `f^n` of a [`Poly`](crate::Poly) term list by the power-series
//! recurrence, one output term at a time, on packed monomials.
//!
//! For any derivation `D`, `f·D(f^n) = n·D(f)·f^n`. Take `D = Σ_v w_v·x_v·∂/∂x_v`
//! for a weight vector `w ≥ 0` (so `D(m) = w(m)·m` on a monomial `m`), write
//! `g = f^n`, and read off the coefficient of one monomial `M`:
//!
//! ```text
//! Σ_{f_i·g_j = M} (w(g_j) − n·w(f_i)) · f_i · g_j = 0
//! ```
//!
//! Let `t₀ = c₀·m₀` be the least term of `f` in the monomial order, and
//! choose `w` so that `m₀` is the unique minimum of `w` on `f`'s monomials
//! (tried: the total degree, then the degree in each variable). Then
//! `g₀ = t₀^n`, and the term of `g` at `M' = M/m₀ > m₀^n` is
//!
//! ```text
//! g_{M'} = Σ_{i ≥ 1, f_i·g_j = m₀·M'} (n·w(f_i) − w(g_j)) · f_i · g_j
//!          / ((w(M') − n·w(m₀)) · c₀)
//! ```
//!
//! an exact integer division (`g` has integer coefficients when `f` has),
//! whose divisor is positive because `w(M') > n·w(m₀)`. Every `g_j` on the
//! right is less than `M'` (as `f_i > m₀`), so the terms of `g` come out in
//! increasing order from a merge of the `#f − 1` streams `f_i·g_j/m₀` over
//! `j` (each increasing, and growing as `g` grows). That is
//! `(#f − 1)·#g` term products, where repeated multiplication costs
//! `#f·Σ_{k<n} #f^k`: five times fewer on a dense power such as
//! `(1 + x₀ + x₁ + x₂ + x₃)^20`.
//!
//! Reference: J. C. P. Miller's recurrence for powers of a power series
//! (Knuth, *TAOCP* vol. 2, §4.7, eq. (9)); its sparse multivariate form:
//! Monagan & Pearce, *Sparse polynomial powering using heaps*, CASC 2012,
//! §3 (the "FPS" algorithm, as in FLINT's `fmpz_mpoly_pow_fps`).

use super::packed::{Packed, Packing};
use super::terms::Terms;
use crate::algebra::int::Int;

/// `terms^n` (`terms` sorted, at least two terms, `n ≥ 2`) by the
/// recurrence; `None` when no packing holds `f^{n+1}` or no weight tried
/// singles out the least monomial.
pub(crate) fn power(terms: &Terms, n: u32) -> Option<Terms> {
    let packing = Packing::for_product(&[terms], u64::from(n) + 1)?;
    let f = packing.pack(terms);
    let fields = packing.fields();
    let exponents = |key: u64| fields.iter().map(move |&(_, s, mask)| (key >> s) & mask);
    let weights = weights(f.keys.iter().map(|&k| exponents(k).collect()).collect())?;
    // m₀ divides a key when each of its fields is at least m₀'s.
    let least: Vec<(u32, u64, u64)> = fields
        .iter()
        .zip(exponents(f.keys[0]))
        .filter(|&(_, e)| e > 0)
        .map(|(&(_, s, mask), e)| (s, mask, e))
        .collect();
    let divides = |key: u64| least.iter().all(|&(s, mask, e)| (key >> s) & mask >= e);
    let n = i64::from(n);
    let (keys, coeffs) = match fits_i128(&f.coeffs, &weights, n) {
        Some(small) => {
            let (keys, c) = Recurrence::new(&f.keys, &small, weights, n).run(divides);
            (keys, c.into_iter().map(Int::Small).collect())
        }
        None => Recurrence::new(&f.keys, &f.coeffs, weights, n).run(divides),
    };
    Some(packing.unpack(Packed { keys, coeffs }))
}

/// The weights `w(f_i)` of the terms (given by their exponent vectors)
/// under the first weight vector tried (all ones, then each unit vector)
/// for which the least monomial has the strictly least weight.
fn weights(exps: Vec<Vec<u64>>) -> Option<Vec<i64>> {
    let vars = exps.first()?.len();
    let total = |e: &Vec<u64>| e.iter().sum::<u64>();
    std::iter::once(None)
        .chain((0..vars).map(Some))
        .find_map(|v| {
            let w: Vec<i64> = exps
                .iter()
                .map(|e| v.map_or_else(|| total(e), |v| e[v]) as i64)
                .collect();
            w[1..].iter().all(|&wi| wi > w[0]).then_some(w)
        })
}

/// The coefficients as `i128` when every value of the recurrence provably
/// fits: `|g_j| ≤ ‖f‖₁^n` and each partial sum is at most
/// `n·(max w − w₀)·‖f‖₁^{n+1}` in magnitude.
fn fits_i128(coeffs: &[Int], w: &[i64], n: i64) -> Option<Vec<i128>> {
    let small: Vec<i128> = coeffs
        .iter()
        .map(|c| match c {
            Int::Small(x) => Some(*x),
            Int::Big(_) => None,
        })
        .collect::<Option<_>>()?;
    let norm = small
        .iter()
        .try_fold(0u128, |acc, c| acc.checked_add(c.unsigned_abs()))?;
    let spread = n * (w.iter().max()? - w[0]);
    let bits = |x: u128| u64::from(128 - x.leading_zeros());
    let bound = bits(spread as u128) + (n as u64 + 1) * bits(norm);
    (bound <= 126).then_some(small)
}

/// The coefficient arithmetic of the recurrence: `i128` without overflow
/// checks (under the bound of [`fits_i128`]) or [`Int`].
trait Coeff: Clone {
    /// `f·g·k`.
    fn term(f: &Self, g: &Self, k: i64) -> Self;
    /// `acc + x`.
    fn add(acc: Self, x: Self) -> Self;
    /// `self / (k·c)`, exact.
    fn divide(self, k: i64, c: &Self) -> Self;
    /// `c^n`.
    fn power(c: &Self, n: i64) -> Self;
    fn is_zero(&self) -> bool;
}

impl Coeff for i128 {
    fn term(f: &i128, g: &i128, k: i64) -> i128 {
        f * g * i128::from(k)
    }
    fn add(acc: i128, x: i128) -> i128 {
        acc + x
    }
    fn divide(self, k: i64, c: &i128) -> i128 {
        self / (i128::from(k) * c)
    }
    fn power(c: &i128, n: i64) -> i128 {
        c.pow(n as u32)
    }
    fn is_zero(&self) -> bool {
        *self == 0
    }
}

impl Coeff for Int {
    fn term(f: &Int, g: &Int, k: i64) -> Int {
        f.clone() * g * &Int::Small(k.into())
    }
    fn add(acc: Int, x: Int) -> Int {
        acc + &x
    }
    fn divide(self, k: i64, c: &Int) -> Int {
        self.div_exact(&(c.clone() * &Int::Small(k.into())))
    }
    fn power(c: &Int, n: i64) -> Int {
        crate::algebra::scalar::pow(c, n as u32)
    }
    fn is_zero(&self) -> bool {
        matches!(self, Int::Small(0))
    }
}

/// The state of the merge: `f` (packed, with weights), the terms of `g`
/// found so far, and per stream `i ≥ 1` its next index into `g` and the
/// key of `f_i·g_j/m₀` there (`u64::MAX` while it waits for `g` to grow).
struct Recurrence<'a, C> {
    f_keys: &'a [u64],
    f_coeffs: &'a [C],
    f_w: Vec<i64>,
    n: i64,
    g_keys: Vec<u64>,
    g_coeffs: Vec<C>,
    g_w: Vec<i64>,
    next: Vec<usize>,
    head: Vec<u64>,
}

impl<'a, C: Coeff> Recurrence<'a, C> {
    fn new(f_keys: &'a [u64], f_coeffs: &'a [C], f_w: Vec<i64>, n: i64) -> Self {
        // g₀ = t₀^n: its key is n·key(m₀) (fields never overflow: the
        // packing holds f^{n+1}).
        Recurrence {
            f_keys,
            f_coeffs,
            n,
            g_keys: vec![f_keys[0] * n as u64],
            g_coeffs: vec![C::power(&f_coeffs[0], n)],
            g_w: vec![f_w[0] * n],
            f_w,
            next: vec![0; f_keys.len()],
            head: vec![u64::MAX; f_keys.len()],
        }
    }

    /// Move stream `i` to its first pair `(i, j ≥ next[i])` whose product
    /// `m₀` divides (a pair it does not divide enters no equation with an
    /// unknown), or to waiting at the end of `g`.
    fn advance(&mut self, i: usize, divides: &impl Fn(u64) -> bool) {
        while let Some(&gk) = self.g_keys.get(self.next[i]) {
            let key = self.f_keys[i] + gk;
            if divides(key) {
                self.head[i] = key - self.f_keys[0];
                return;
            }
            self.next[i] += 1;
        }
        self.head[i] = u64::MAX;
    }

    /// The terms of `g` in increasing order: keys and coefficients.
    fn run(mut self, divides: impl Fn(u64) -> bool) -> (Vec<u64>, Vec<C>) {
        let streams = 1..self.f_keys.len();
        for i in streams.clone() {
            self.advance(i, &divides);
        }
        loop {
            let key = self.head[1..].iter().copied().min().unwrap_or(u64::MAX);
            if key == u64::MAX {
                break;
            }
            let (mut sum, mut w) = (None, 0);
            for i in streams.clone() {
                if self.head[i] == key {
                    let j = self.next[i];
                    w = self.f_w[i] + self.g_w[j] - self.f_w[0];
                    let k = self.n * self.f_w[i] - self.g_w[j];
                    let t = C::term(&self.f_coeffs[i], &self.g_coeffs[j], k);
                    sum = Some(match sum {
                        Some(s) => C::add(s, t),
                        None => t,
                    });
                    self.next[i] = j + 1;
                    self.advance(i, &divides);
                }
            }
            if let Some(s) = sum.filter(|s| !s.is_zero()) {
                let k = w - self.n * self.f_w[0];
                self.g_coeffs.push(s.divide(k, &self.f_coeffs[0]));
                self.g_keys.push(key);
                self.g_w.push(w);
                // Waiting streams resume at the new term.
                for i in streams.clone() {
                    if self.head[i] == u64::MAX {
                        self.advance(i, &divides);
                    }
                }
            }
        }
        (self.g_keys, self.g_coeffs)
    }
}
