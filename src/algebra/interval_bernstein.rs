//! Bernstein polynomials with interval coefficients, in scaled form, and
//! their products (enclosures: the binomials are exact integers while
//! below 2⁵³ and enclosed above, every operation rounded outward).
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

use super::Interval;

/// Polynomials in scaled Bernstein form (see the module documentation),
/// one per homogeneous coordinate.
pub type Scaled = Vec<Interval>;

/// `C(n, i)` for `i = 0..=n`, enclosed (Pascal's triangle in interval
/// arithmetic: exact while below 2⁵³).
pub fn binomials(n: usize) -> Vec<Interval> {
    let mut row = vec![Interval::point(1.0)];
    for _ in 0..n {
        let mut next = Vec::with_capacity(row.len() + 1);
        next.push(Interval::point(1.0));
        next.extend(row.windows(2).map(|w| w[0].add(&w[1])));
        next.push(Interval::point(1.0));
        row = next;
    }
    row
}

/// The scaled form of Bernstein coefficients `c`.
pub fn scale(c: &[Interval]) -> Scaled {
    let b = binomials(c.len() - 1);
    c.iter().zip(&b).map(|(x, k)| x.mul(k)).collect()
}

/// The Bernstein coefficients of a scaled form (`None` never happens for
/// a nonempty form: binomials are at least 1).
pub fn unscale(c: &[Interval]) -> Option<Vec<Interval>> {
    let b = binomials(c.len() - 1);
    c.iter().zip(&b).map(|(x, k)| x.div(k)).collect()
}

/// The product of two scaled forms (a convolution).
pub fn mul(a: &[Interval], b: &[Interval]) -> Scaled {
    let mut out = vec![Interval::point(0.0); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] = out[i + j].add(&x.mul(y));
        }
    }
    out
}

/// The Bernstein coefficients of the product of two Bernstein polynomials
/// (enclosed): `c_m = Σ_{i+j=m} C(n₁,i) C(n₂,j) / C(n₁+n₂,m) · p_i q_j`.
pub fn bernstein_product(p: &[Interval], q: &[Interval]) -> Vec<Interval> {
    unscale(&mul(&scale(p), &scale(q))).expect("binomials are at least 1")
}
