//! The certificate modulo `p = 2⁶¹ − 1` that a net is of minimal bidegree
//! ([`minimal`](super::minimal) explains why it is sound), on flat grids:
//! the `C` homogeneous components of a net of bidegree `(m, n)` are one
//! buffer of `C(m+1)(n+1)` residues. The certificate reads the Bernstein
//! coefficients directly ([`FpGrids::bernstein_certified`]: forward
//! differences for the degree, the components specialized at a probe and
//! converted to the power basis in one direction only); a grid converted
//! to the power basis in place, line by line, by forward differences
//! ([`FpGrids::into_power`]) gives the degree bound of an elevated net.
//! The coprimality test runs its pseudo-remainder sequence in two buffers.
//! One allocation per grid and a few per test, where nested vectors took
//! one per row, point and line (issue 31: the certificate runs on every
//! record of `key` and `dedup`).

use crate::algebra::modp::{Fp, MODULUS};
use crate::bernstein::binomial_rows;
use num_traits::{One, Zero};
use std::cell::RefCell;

/// Fixed evaluation points in `Z/pZ` for the coprimality certificate.
const PROBE_U: u64 = 0x2545_F491_4F6C_DD1D % MODULUS;
const PROBE_V: u64 = 0x1B87_3593_9E37_79B9 % MODULUS;

/// The largest degree whose Pascal's triangle a thread keeps
/// ([`with_pascal`]): 64² residues at most.
const PASCAL_KEPT: usize = 64;

thread_local! {
    /// Pascal's triangle modulo p of the largest degree up to
    /// [`PASCAL_KEPT`] used on this thread: the triangle of a lower degree
    /// is its first rows, so it is built once per thread, not once per net.
    static PASCAL: RefCell<Vec<Vec<Fp>>> = const { RefCell::new(Vec::new()) };
}

/// `f` of Pascal's triangle modulo p of degree at least `n`
/// ([`binomial_rows`]): the thread's kept triangle, grown when `n` is over
/// its degree, or one built for this call above [`PASCAL_KEPT`].
fn with_pascal<R>(n: usize, f: impl FnOnce(&[Vec<Fp>]) -> R) -> R {
    if n > PASCAL_KEPT {
        return f(&binomial_rows::<Fp>(n));
    }
    PASCAL.with(|kept| {
        let mut kept = kept.borrow_mut();
        if kept.len() <= n {
            *kept = binomial_rows::<Fp>(n);
        }
        f(&kept)
    })
}

/// Grids of residues of `comps` components of bidegree `(m, n)`, flat:
/// the coefficient `(p, q)` of component `c` is `data[(c(m+1) + p)(n+1) + q]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct FpGrids {
    data: Vec<Fp>,
    comps: usize,
    m: usize,
    n: usize,
}

impl FpGrids {
    /// The grids of `data` laid out as above (`data.len()` is
    /// `comps(m+1)(n+1)`), coefficients in the basis they were given in.
    pub(crate) fn new(data: Vec<Fp>, comps: usize, (m, n): (usize, usize)) -> FpGrids {
        debug_assert_eq!(data.len(), comps * (m + 1) * (n + 1));
        FpGrids { data, comps, m, n }
    }

    /// These grids of Bernstein coefficients converted to the power basis
    /// in place: each row (in v), then each column (in u), by
    /// [`bernstein_to_power_strided`] with the rows `n` and `m` of
    /// Pascal's triangle.
    pub(crate) fn into_power(mut self) -> FpGrids {
        let (m, n) = (self.m, self.n);
        let g = &mut self;
        with_pascal(m.max(n), |pascal| {
            for row in g.data.chunks_exact_mut(n + 1) {
                bernstein_to_power_strided(row, 1, &pascal[n]);
            }
            for grid in g.data.chunks_exact_mut((m + 1) * (n + 1)) {
                for q in 0..=n {
                    bernstein_to_power_strided(&mut grid[q..], n + 1, &pascal[m]);
                }
            }
        });
        self
    }

    /// On grids of Bernstein coefficients: the certificate of minimal
    /// bidegree, the same answer as the test on the power grids
    /// ([`into_power`](FpGrids::into_power): the actual bidegree is the full
    /// `(m, n)` and [`coprime`](FpGrids::coprime) holds; property-tested)
    /// for about half the work (no change of basis of the whole grid). The power coefficients
    /// of `u^m` form the polynomial in v whose Bernstein coefficients are
    /// the m-th forward differences of the columns (the change of basis in
    /// v is invertible mod p, `n < p`), so the u-degree is m when one of
    /// them is non-zero; and a component specialized at `v = v₀` is its
    /// Bernstein rows evaluated at `v₀` (`Σ_q b_{p,q} B_{q,n}(v₀)`), then
    /// converted to the power basis in u alone. Likewise in v.
    pub(crate) fn bernstein_certified(&self) -> bool {
        let (m, n) = (self.m, self.n);
        let (u0, v0) = (Fp::new(PROBE_U), Fp::new(PROBE_V));
        with_pascal(m.max(n), |pascal| {
            let top_u =
                |c: usize, q: usize| top_difference((0..=m).map(|p| self.at(c, p, q)), &pascal[m]);
            let top_v =
                |c: usize, p: usize| top_difference(self.row(c, p).iter().copied(), &pascal[n]);
            let full_u = m == 0 || (0..self.comps).any(|c| (0..=n).any(|q| !top_u(c, q).is_zero()));
            let full_v = n == 0 || (0..self.comps).any(|c| (0..=m).any(|p| !top_v(c, p).is_zero()));
            if !(full_u && full_v) {
                return false;
            }
            let at_v0 = bernstein_values(v0, &pascal[n]);
            let at_u0 = bernstein_values(u0, &pascal[m]);
            self.coprime_in(m, |c, out| {
                out.extend((0..=m).map(|p| dot(self.row(c, p).iter().copied(), &at_v0)));
                bernstein_to_power_strided(out, 1, &pascal[m]);
            }) && self.coprime_in(n, |c, out| {
                out.extend((0..=n).map(|q| dot((0..=m).map(|p| self.at(c, p, q)), &at_u0)));
                bernstein_to_power_strided(out, 1, &pascal[n]);
            })
        })
    }

    /// Row `p` (the coefficients of `u^p v^0 … u^p v^n`) of component `c`.
    fn row(&self, c: usize, p: usize) -> &[Fp] {
        let at = (c * (self.m + 1) + p) * (self.n + 1);
        &self.data[at..at + self.n + 1]
    }

    /// The coefficient of `u^p v^q` in component `c`.
    pub(crate) fn at(&self, c: usize, p: usize, q: usize) -> Fp {
        self.row(c, p)[q]
    }

    /// The largest `(p, q)` with a non-zero coefficient, over all components.
    pub(crate) fn actual_degree(&self) -> (usize, usize) {
        let (mut dm, mut dn) = (0, 0);
        for c in 0..self.comps {
            for p in 0..=self.m {
                if let Some(q) = self.row(c, p).iter().rposition(|x| !x.is_zero()) {
                    dm = dm.max(p);
                    dn = dn.max(q);
                }
            }
        }
        (dm, dn)
    }

    /// The certificate on power grids: the actual bidegree is the full
    /// `(m, n)` and the components are coprime in both directions (the
    /// reference for [`bernstein_certified`](FpGrids::bernstein_certified)).
    #[cfg(test)]
    pub(crate) fn certified(&self) -> bool {
        self.actual_degree() == (self.m, self.n) && self.coprime()
    }

    /// No common factor of positive degree: in u (specialized at
    /// `v = PROBE_V`) and in v (at `u = PROBE_U`).
    pub(crate) fn coprime(&self) -> bool {
        let (u0, v0) = (Fp::new(PROBE_U), Fp::new(PROBE_V));
        self.coprime_in(self.m, |c, out| {
            out.extend((0..=self.m).map(|p| horner(self.row(c, p).iter().copied(), v0)));
        }) && self.coprime_in(self.n, |c, out| {
            out.extend((0..=self.n).map(|q| horner((0..=self.m).map(|p| self.at(c, p, q)), u0)));
        })
    }

    /// No common factor of positive degree in the direction whose
    /// specialized component `c` `spec(c, out)` appends to `out` (degree
    /// `deg` expected): some component keeps degree `deg`, and the gcd of
    /// all of them, by pseudo-remainders, is a constant.
    fn coprime_in(&self, deg: usize, spec: impl Fn(usize, &mut Vec<Fp>)) -> bool {
        if deg == 0 {
            return true;
        }
        let (mut next, mut gcd) = (Vec::with_capacity(deg + 1), Vec::with_capacity(deg + 1));
        let mut full = false;
        for c in 0..self.comps {
            next.clear();
            spec(c, &mut next);
            trim(&mut next);
            full |= next.len() == deg + 1;
            pseudo_gcd_in(&mut gcd, &mut next);
            // A constant gcd stays constant: decided once a component is full.
            if full && gcd.len() == 1 {
                return true;
            }
        }
        false
    }
}

/// `a ← ` a polynomial over F_p (coefficients from the constant up, no
/// trailing zeros) with the degree of `gcd(a, b)`; `b` is used up. Euclid's
/// algorithm with pseudo-remainders ([`pseudo_rem`]), which need no inverse
/// modulo p (each is a remainder times a nonzero constant, so the
/// sequence's degrees are those of the monic one; von zur Gathen &
/// Gerhard, *Modern Computer Algebra*, §6.12).
fn pseudo_gcd_in(a: &mut Vec<Fp>, b: &mut Vec<Fp>) {
    while !b.is_empty() {
        pseudo_rem(a, b);
        std::mem::swap(a, b);
    }
}

/// `a ← lc(b)^k · (a mod b)` for `b ≠ 0`: while `deg a ≥ deg b`,
/// `a ← lc(b)·a − lc(a)·x^(deg a − deg b)·b` (the leading term cancels).
fn pseudo_rem(a: &mut Vec<Fp>, b: &[Fp]) {
    let lb = b[b.len() - 1];
    while a.len() >= b.len() {
        let la = a[a.len() - 1];
        let shift = a.len() - b.len();
        for x in a.iter_mut() {
            *x = *x * lb;
        }
        for (x, &y) in a[shift..].iter_mut().zip(b) {
            *x = *x - la * y;
        }
        trim(a);
    }
}

/// The Bernstein coefficients `b_0 … b_n` at `line[0], line[s], …`
/// (stride `s`, `n + 1 = binom.len()`) replaced in place by the power
/// coefficients `a_k = C(n, k) Δ^k b_0`, where `Δ^k b_0 = Σ_i (−1)^(k−i)
/// C(k, i) b_i` is the k-th forward difference (the power form of a Bézier
/// polynomial; Farin, *Curves and Surfaces for CAGD*, 5th ed., §5.2–5.3):
/// `n(n+1)/2` subtractions and `n + 1` products instead of a product per
/// term of each sum. `binom` is row `n` of Pascal's triangle modulo p.
fn bernstein_to_power_strided(line: &mut [Fp], s: usize, binom: &[Fp]) {
    let n = binom.len() - 1;
    // After pass k, position i ≥ k holds Δ^k b_(i−k).
    for k in 1..=n {
        for i in (k..=n).rev() {
            line[i * s] = line[i * s] - line[(i - 1) * s];
        }
    }
    for (k, &c) in binom.iter().enumerate() {
        line[k * s] = line[k * s] * c;
    }
}

/// The k-th forward difference `Δ^k b_0 = Σ_i (−1)^(k−i) C(k, i) b_i` of
/// `b_0 … b_k` (`binom`: row k of Pascal's triangle modulo p).
fn top_difference(b: impl Iterator<Item = Fp>, binom: &[Fp]) -> Fp {
    let k = binom.len() - 1;
    b.zip(binom)
        .enumerate()
        .fold(Fp::zero(), |acc, (i, (x, &c))| {
            if (k - i).is_multiple_of(2) {
                acc + c * x
            } else {
                acc - c * x
            }
        })
}

/// The Bernstein basis of degree n at x: `B_{k,n}(x) = C(n, k) x^k (1 − x)^(n−k)`
/// for k = 0 … n (`binom`: row n of Pascal's triangle modulo p).
fn bernstein_values(x: Fp, binom: &[Fp]) -> Vec<Fp> {
    let n = binom.len() - 1;
    let y = Fp::one() - x;
    // x^k ascending, then times (1 − x)^(n−k) descending.
    let mut out: Vec<Fp> = Vec::with_capacity(n + 1);
    let mut power = Fp::one();
    for &c in binom {
        out.push(c * power);
        power = power * x;
    }
    let mut power = Fp::one();
    for b in out.iter_mut().rev() {
        *b = *b * power;
        power = power * y;
    }
    out
}

/// `Σ_k a_k w_k`.
fn dot(a: impl Iterator<Item = Fp>, w: &[Fp]) -> Fp {
    a.zip(w).fold(Fp::zero(), |acc, (x, &y)| acc + x * y)
}

/// Drop the trailing zeros of `c`.
fn trim(c: &mut Vec<Fp>) {
    while c.last().is_some_and(Fp::is_zero) {
        c.pop();
    }
}

/// `Σ_k c_k x^k` for the coefficients `c_0, c_1, …` (Horner's rule).
fn horner(coeffs: impl DoubleEndedIterator<Item = Fp>, x: Fp) -> Fp {
    coeffs.rev().fold(Fp::zero(), |acc, c| acc * x + c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::upoly::UPoly;
    use crate::coincide::minimal::power_components;
    use crate::hpoint::HPoint;
    use proptest::prelude::*;

    /// Polynomials over F_p of degree < 4, from small coefficients (so
    /// that common factors are frequent), times a planted factor.
    fn fp_polys() -> impl Strategy<Value = Vec<Vec<Fp>>> {
        let poly = || prop::collection::vec(0u64..3, 0..4);
        (prop::collection::vec(poly(), 1..4), poly()).prop_map(|(ps, factor)| {
            let f = UPoly::new(factor.into_iter().map(Fp::new).collect());
            let f = if f.is_zero() {
                UPoly::constant(Fp::new(1))
            } else {
                f
            };
            ps.into_iter()
                .map(|p| {
                    UPoly::new(p.into_iter().map(Fp::new).collect())
                        .mul(&f)
                        .coeffs()
                        .to_vec()
                })
                .collect()
        })
    }

    /// Nets over F_p of bidegree up to (3, 3), 1–3 components, small
    /// residues (zeros and common factors are frequent), flat.
    fn fp_nets() -> impl Strategy<Value = (Vec<Fp>, usize, (usize, usize))> {
        (1usize..4, 0usize..4, 0usize..4).prop_flat_map(|(comps, m, n)| {
            prop::collection::vec(0u64..3, comps * (m + 1) * (n + 1))
                .prop_map(move |v| (v.into_iter().map(Fp::new).collect(), comps, (m, n)))
        })
    }

    /// The same net as nested points, for [`power_components`].
    fn nested(data: &[Fp], comps: usize, (m, n): (usize, usize)) -> Vec<Vec<HPoint<Fp>>> {
        let at = |c: usize, i: usize, j: usize| data[(c * (m + 1) + i) * (n + 1) + j];
        (0..=m)
            .map(|i| {
                (0..=n)
                    .map(|j| HPoint {
                        coords: (0..comps).map(|c| at(c, i, j)).collect(),
                    })
                    .collect()
            })
            .collect()
    }

    /// Coprimality in one direction by monic Euclid ([`UPoly::gcd`]) on
    /// the specialized components.
    fn coprime_by_upoly(polys: &[UPoly<Fp>], deg: usize) -> bool {
        if deg == 0 {
            return true;
        }
        let full = polys.iter().any(|p| p.degree() == Some(deg));
        let g = polys.iter().fold(UPoly::zero(), |g, p| g.gcd(p));
        full && g.degree() == Some(0)
    }

    proptest! {
        #[test]
        fn pseudo_remainders_find_the_gcd_degree_of_monic_euclid(polys in fp_polys()) {
            let mut monic = UPoly::zero();
            let mut pseudo = Vec::new();
            for p in &polys {
                monic = monic.gcd(&UPoly::new(p.clone()));
                pseudo_gcd_in(&mut pseudo, &mut p.clone());
                prop_assert_eq!(monic.degree(), pseudo.len().checked_sub(1));
            }
        }

        #[test]
        fn a_kept_triangle_gives_the_rows_of_a_lower_degree(a in 0usize..70, b in 0usize..70) {
            // Grown to `a` (kept up to PASCAL_KEPT), then read at `b`.
            with_pascal(a, |_| ());
            let rows = with_pascal(b, |p| p[..=b].to_vec());
            prop_assert_eq!(rows, binomial_rows::<Fp>(b));
        }

        #[test]
        fn flat_grids_are_the_nested_power_components((data, comps, shape) in fp_nets()) {
            let g = FpGrids::new(data.clone(), comps, shape).into_power();
            let nested = power_components(&nested(&data, comps, shape));
            for (c, grid) in nested.iter().enumerate() {
                for (p, row) in grid.iter().enumerate() {
                    for (q, x) in row.iter().enumerate() {
                        prop_assert_eq!(g.at(c, p, q), *x);
                    }
                }
            }
        }

        #[test]
        fn the_bernstein_test_is_the_test_on_power_grids((data, comps, shape) in fp_nets()) {
            let power = FpGrids::new(data.clone(), comps, shape).into_power().certified();
            prop_assert_eq!(FpGrids::new(data, comps, shape).bernstein_certified(), power);
        }

        #[test]
        fn the_flat_test_is_coprimality_by_monic_euclid((data, comps, (m, n)) in fp_nets()) {
            let g = FpGrids::new(data, comps, (m, n));
            let (u0, v0) = (Fp::new(PROBE_U), Fp::new(PROBE_V));
            let in_u: Vec<UPoly<Fp>> = (0..comps)
                .map(|c| UPoly::new((0..=m).map(|p| horner((0..=n).map(|q| g.at(c, p, q)), v0)).collect()))
                .collect();
            let in_v: Vec<UPoly<Fp>> = (0..comps)
                .map(|c| UPoly::new((0..=n).map(|q| horner((0..=m).map(|p| g.at(c, p, q)), u0)).collect()))
                .collect();
            prop_assert_eq!(g.coprime(), coprime_by_upoly(&in_u, m) && coprime_by_upoly(&in_v, n));
        }
    }
}
