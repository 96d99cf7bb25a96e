//! Bernstein polynomials with interval coefficients, in scaled form, and
//! their products (enclosures: the binomials are enclosed by Pascal's
//! rule in interval arithmetic, every operation rounded outward).
//!
//! A polynomial of degree `n` is held by `c̃_i = C(n, i) c_i`, its
//! coefficients in the basis `tⁱ(1 − t)^{n−i}`, so that a product is a
//! convolution: `(fg)~_l = Σ_{i+j=l} f̃_i g̃_j` (Farin, *Curves and
//! Surfaces for CAGD*, §5.5).
//!
//! ```
//! use exact_bezier::algebra::interval_bernstein::bernstein_product;
//! use exact_bezier::algebra::Interval;
//! // t · t = t²: [0, 1] × [0, 1] → [0, 0, 1].
//! let t = [0.0, 1.0].map(Interval::point);
//! let sq = bernstein_product(&t, &t);
//! assert!(sq[1].lo <= 0.0 && 0.0 <= sq[1].hi && sq[2].lo <= 1.0 && 1.0 <= sq[2].hi);
//! ```

use super::interval::{next_down, next_up};
use super::Interval;
use std::borrow::Cow;
use std::sync::OnceLock;

/// Polynomials in scaled Bernstein form (see the module documentation),
/// one per homogeneous coordinate.
pub type Scaled = Vec<Interval>;

/// The rows of Pascal's triangle [`binomials`] keeps, once computed:
/// `0..CACHED` (a convolution of the audit reaches degree 60 or so).
const CACHED: usize = 128;

/// `C(n, i)` for `i = 0..=n`, enclosed (Pascal's triangle in interval
/// arithmetic: every sum is widened by an ulp on each side, exact or not,
/// so the enclosures are a few ulps wide). Rows below `CACHED` are computed
/// once per process, the same operations in the same order, so the same
/// bits as computing them again.
pub fn binomials(n: usize) -> Cow<'static, [Interval]> {
    static ROWS: OnceLock<Vec<Vec<Interval>>> = OnceLock::new();
    match ROWS.get_or_init(|| pascal(CACHED - 1)).get(n) {
        Some(row) => Cow::Borrowed(row),
        None => Cow::Owned(pascal(n).pop().expect("row n")),
    }
}

/// Rows `0..=n` of Pascal's triangle, enclosed.
fn pascal(n: usize) -> Vec<Vec<Interval>> {
    let mut rows = vec![vec![Interval::point(1.0)]];
    for k in 0..n {
        let row = &rows[k];
        let mut next = Vec::with_capacity(row.len() + 1);
        next.push(Interval::point(1.0));
        next.extend(row.windows(2).map(|w| w[0].add(&w[1])));
        next.push(Interval::point(1.0));
        rows.push(next);
    }
    rows
}

/// The scaled form of Bernstein coefficients `c`.
pub fn scale(c: &[Interval]) -> Scaled {
    let b = binomials(c.len() - 1);
    c.iter().zip(b.iter()).map(|(x, k)| x.mul(k)).collect()
}

/// The Bernstein coefficients of a scaled form (`None` never happens for
/// a nonempty form: binomials are at least 1).
pub fn unscale(c: &[Interval]) -> Option<Vec<Interval>> {
    let b = binomials(c.len() - 1);
    c.iter().zip(b.iter()).map(|(x, k)| x.div(k)).collect()
}

/// The fewest products `a.len()·b.len()` for which [`mul`] takes
/// [`convolve_finite`]: below, its setup (four arrays, the run-time
/// choice of vectors) costs more than the loops save. Measured
/// (2026-11-28, release build without LTO, AVX-512, best of 7 runs of a
/// loop of calls), `convolve_finite` / `convolve` in ns a call: 2×4 268 /
/// 81, 4×4 364 / 215, 7×7 765 / 466, 4×13 517 / 436, 10×10 656 / 639,
/// 13×13 1 148 / 1 353, 20×20 1 779 / 3 119, 40×40 2 922 / 11 422. The
/// criterion bench `interval_mul` times [`mul`] on finite operands against
/// the same operands with one end at −∞ (always [`convolve`]); on
/// 2026-11-29 (fat LTO, AMD Zen 5), medians in ns: 10×10 197 / 340,
/// 13×13 357 / 567, 20×20 537 / 1 337, 40×40 848 / 5 382, and below the
/// threshold equal (2×4 36 / 34, 7×7 167 / 166), as both take [`convolve`].
const FINITE_FROM: usize = 100;

/// The product of two scaled forms (a convolution):
/// `out_l = Σ_{i+j=l} a_i b_j`, accumulated in the order of `i`, each
/// product and sum rounded outward ([`Interval::mul`], [`Interval::add`]).
/// Where every end point is finite and the operands are not short
/// (`FINITE_FROM`), by `convolve_finite`, which gives the same bits
/// faster.
pub fn mul(a: &[Interval], b: &[Interval]) -> Scaled {
    let finite = |x: &Interval| x.lo.is_finite() && x.hi.is_finite();
    if a.len() * b.len() >= FINITE_FROM && a.iter().chain(b).all(finite) {
        convolve_finite(a, b)
    } else {
        convolve(a, b)
    }
}

/// [`mul`] by its definition, one interval operation at a time.
fn convolve(a: &[Interval], b: &[Interval]) -> Scaled {
    let mut out = vec![Interval::point(0.0); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] = out[i + j].add(&x.mul(y));
        }
    }
    out
}

/// [`convolve`] for finite end points, bit for bit: the ends `lo`, `hi`
/// in separate arrays, and for each `a_i` a loop over `j` with no branch
/// (the compiler vectorises it), taking the two of the four products
/// [`Interval::mul`] compares that its sign selects:
///
/// ```text
/// a_i ≥ 0:  [min(a·c, ā·c), max(a·d, ā·d)]
/// a_i ≤ 0:  [min(a·d, ā·d), max(a·c, ā·c)]      a_i = [a, ā], b_j = [c, d]
/// else:     [min(a·d, ā·c), max(a·c, ā·d)]
/// ```
///
/// The exact least and greatest of the four products are among the two
/// kept (for `a ≥ 0`, `a·c ≤ a·d` and `ā·c ≤ ā·d`, and so on), and rounding
/// to nearest is monotone, so the rounded ones are too: the same `f64`s,
/// up to the sign of a zero, which the outward step then maps to the
/// same value. Finite factors make no NaN (`0·∞` is the only one a
/// product can give, a sum of outward-rounded ends never adds `+∞` to
/// `−∞`), where `Interval::mul` would drop it.
fn convolve_finite(a: &[Interval], b: &[Interval]) -> Scaled {
    let (c, d): (Vec<f64>, Vec<f64>) = b.iter().map(|y| (y.lo, y.hi)).unzip();
    let mut lo = vec![0.0; a.len() + b.len() - 1];
    let mut hi = lo.clone();
    let job = Convolution {
        a,
        ends: [&c, &d],
        out: [&mut lo, &mut hi],
    };
    crate::widest::run(job);
    lo.into_iter()
        .zip(hi)
        .map(|(lo, hi)| Interval { lo, hi })
        .collect()
}

/// The loops of [`convolve_finite`]: `a`, the ends `c`, `d` of `b`, and
/// the ends of the output, run on the widest vector instructions the
/// processor has ([`crate::widest`]).
struct Convolution<'a> {
    a: &'a [Interval],
    ends: [&'a [f64]; 2],
    out: [&'a mut [f64]; 2],
}

impl crate::widest::Job for Convolution<'_> {
    type Output = ();

    /// For each `a_i`, the products with `b` added to the output from
    /// `i` on ([`accumulate`]).
    #[inline(always)]
    fn run(self) {
        let ([c, d], [lo, hi]) = (self.ends, self.out);
        let m = c.len();
        for (i, x) in self.a.iter().enumerate() {
            let (low, high) = if x.lo >= 0.0 {
                ((c, c), (d, d))
            } else if x.hi <= 0.0 {
                ((d, d), (c, c))
            } else {
                ((d, c), (c, d))
            };
            accumulate(
                [x.lo, x.hi],
                [low.0, low.1],
                [high.0, high.1],
                [&mut lo[i..i + m], &mut hi[i..i + m]],
            );
        }
    }
}

/// `out_j ⊕= [min(x₀·l₀_j, x₁·l₁_j), max(x₀·h₀_j, x₁·h₁_j)]`, each step
/// rounded outward, for the slices of one length ([`convolve_finite`]).
#[inline(always)]
fn accumulate(x: [f64; 2], l: [&[f64]; 2], h: [&[f64]; 2], [lo, hi]: [&mut [f64]; 2]) {
    let least = |p: f64, q: f64| if p < q { p } else { q };
    let most = |p: f64, q: f64| if p > q { p } else { q };
    let m = lo.len();
    let (l, h, hi) = (
        [&l[0][..m], &l[1][..m]],
        [&h[0][..m], &h[1][..m]],
        &mut hi[..m],
    );
    for j in 0..m {
        let p = next_down(least(x[0] * l[0][j], x[1] * l[1][j]));
        let q = next_up(most(x[0] * h[0][j], x[1] * h[1][j]));
        lo[j] = next_down(lo[j] + p);
        hi[j] = next_up(hi[j] + q);
    }
}

/// The Bernstein coefficients of the product of two Bernstein polynomials
/// (enclosed): `c_m = Σ_{i+j=m} C(n₁,i) C(n₂,j) / C(n₁+n₂,m) · p_i q_j`.
pub fn bernstein_product(p: &[Interval], q: &[Interval]) -> Vec<Interval> {
    unscale(&mul(&scale(p), &scale(q))).expect("binomials are at least 1")
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Intervals with finite ends of mixed signs, zeros among them.
    fn intervals(len: std::ops::Range<usize>) -> impl Strategy<Value = Vec<Interval>> {
        let end = prop_oneof![Just(0.0), Just(-0.0), -1e3f64..1e3, -1e-300f64..1e-300];
        prop::collection::vec((end.clone(), end), len).prop_map(|v| {
            v.into_iter()
                .map(|(a, b)| Interval {
                    lo: a.min(b),
                    hi: a.max(b),
                })
                .collect()
        })
    }

    proptest! {
        /// The finite kernel gives the definition's bits.
        #[test]
        fn convolve_finite_is_convolve(a in intervals(1..12), b in intervals(1..40)) {
            let (fast, slow) = (convolve_finite(&a, &b), convolve(&a, &b));
            let bits = |v: &[Interval]| v.iter().map(|x| (x.lo.to_bits(), x.hi.to_bits())).collect::<Vec<_>>();
            prop_assert_eq!(bits(&fast), bits(&slow));
        }
    }

    /// Cached rows are Pascal's, computed again.
    #[test]
    fn cached_binomials_are_pascal() {
        for n in [0, 1, 5, 60, CACHED - 1, CACHED, CACHED + 3] {
            assert_eq!(&binomials(n)[..], &pascal(n)[n][..]);
        }
        let six = binomials(4)[2];
        assert!(six.lo <= 6.0 && 6.0 <= six.hi && six.width() < 1e-14);
    }
}
