//! Minimal (bi)degree of a rational curve or tensor-product patch: remove
//! the common factor of the homogeneous components (exact gcd over Q, or
//! over the real algebraic numbers) and
//! undo degree elevation.
//!
//! A patch of bidegree (m, n) with homogeneous control points
//! `H_{i,j} = (ω_{i,j} P_{i,j}, ω_{i,j})` has `d + 1` homogeneous components
//! `F_c(u, v) = Σ_i Σ_j H_{i,j}[c] B_{i,m}(u) B_{j,n}(v)`. The parametric map
//! `X = (F_0, …, F_{d−1}) / F_d` does not change when every `F_c` is divided
//! by `g = gcd(F_0, …, F_d)` in Q[u, v] (any common factor: it need **not**
//! split into a u-part times a v-part — `1 + uv` is a counterexample, see
//! the tests — so the gcd is a genuine bivariate one). After division the
//! actual degrees `(m', n')` in the power basis are read off and the
//! components are written back in the Bernstein basis of bidegree (m', n').
//! A curve is the case n = 0.
//!
//! Conversions (exact, [`crate::bernstein`]): power coefficients from Bernstein ones
//! `a_k = C(m, k) Σ_{i≤k} C(k, i) (−1)^{k−i} b_i`, and back
//! `b_i = Σ_{k≤i} C(i, k) / C(m', k) a_k`.
//!
//! Fast path: a certificate modulo the prime `p = 2⁶¹ − 1` (see
//! [`Fp`]) that the patch is already minimal, so that the exact
//! bivariate gcd runs only when the certificate fails.
//!
//! Reference: source 000 §3 ("调整使得两个曲面同阶") asks for equal degrees
//! only; the common-factor reduction is ours (issue 4).

use crate::algebra::modp::Fp;
use crate::algebra::scalar::{Field, Ordered, Scalar, Tolerance};
use crate::algebra::upoly::{BPoly, UPoly};
use crate::algebra::RealAlgebraic;
use crate::bernstein::{
    bernstein_to_power_into, bernstein_to_power_with, binomial_rows, power_to_bernstein,
    reduce_elevated,
};
use crate::coincide::certificate::FpGrids;
use crate::coincide::coprime::coprime_by_intervals;
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;
use num_rational::BigRational;
use num_traits::Zero;

/// A homogeneous control net `net[i][j]` of bidegree (m, n); a curve is (m, 0).
pub(crate) type Net<T> = Vec<Vec<HPoint<T>>>;

/// The net of a curve, as a (m, 0) patch.
pub(crate) fn curve_net<T: Scalar>(c: &RationalCurve<T>) -> Net<T> {
    c.ctrl().iter().map(|p| vec![p.clone()]).collect()
}

/// The power-basis grids of the `d + 1` homogeneous components:
/// `out[c][p][q]` is the coefficient of `u^p v^q` in `F_c`.
pub(crate) fn power_components<T: Scalar>(net: &Net<T>) -> Vec<Vec<Vec<T>>> {
    let (m, n) = (net.len() - 1, net[0].len() - 1);
    // Pascal's triangles of the row (v) and column (u) degrees, once.
    let by_row = binomial_rows::<T>(n);
    let by_col = (m != n).then(|| binomial_rows::<T>(m));
    let by_col = by_col.as_deref().unwrap_or(&by_row);
    // One line (row or column) and its conversion at a time, in two reused buffers.
    let cap = m.max(n) + 1;
    let (mut column, mut power) = (Vec::with_capacity(cap), Vec::with_capacity(cap));
    (0..net[0][0].coords.len())
        .map(|c| {
            let mut grid: Vec<Vec<T>> = net
                .iter()
                .map(|row| {
                    column.clear();
                    column.extend(row.iter().map(|h| h.coords[c].clone()));
                    bernstein_to_power_with(&column, &by_row)
                })
                .collect();
            for j in 0..=n {
                column.clear();
                column.extend(grid.iter().map(|r| r[j].clone()));
                bernstein_to_power_into(&column, by_col, &mut power);
                for (r, x) in grid.iter_mut().zip(power.drain(..)) {
                    r[j] = x;
                }
            }
            grid
        })
        .collect()
}

/// The actual bidegree of power grids: the largest `(p, q)` with a
/// coefficient that is not zero by `is_zero`, over all components.
fn actual_degree<T>(
    comps: &[Vec<Vec<T>>],
    is_zero: impl Fn(&T, &[Vec<T>]) -> bool,
) -> (usize, usize) {
    let (mut m, mut n) = (0, 0);
    for grid in comps {
        for (p, row) in grid.iter().enumerate() {
            for (q, a) in row.iter().enumerate() {
                if !is_zero(a, grid) {
                    m = m.max(p);
                    n = n.max(q);
                }
            }
        }
    }
    (m, n)
}

/// The net of bidegree `(m, n)` from power grids of degree ≤ (m, n).
fn net_from_power<T: Field>(comps: &[Vec<Vec<T>>], m: usize, n: usize) -> Net<T> {
    let bern: Vec<Vec<Vec<T>>> = comps
        .iter()
        .map(|g| {
            let cut: Vec<Vec<T>> = g.iter().take(m + 1).map(|r| r[..=n].to_vec()).collect();
            let rows: Vec<Vec<T>> = cut.iter().map(|r| power_to_bernstein(r, n)).collect();
            let cols: Vec<Vec<T>> = (0..=n)
                .map(|j| {
                    power_to_bernstein(&rows.iter().map(|r| r[j].clone()).collect::<Vec<_>>(), m)
                })
                .collect();
            (0..=m)
                .map(|i| cols.iter().map(|c| c[i].clone()).collect())
                .collect()
        })
        .collect();
    (0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| HPoint {
                    coords: bern.iter().map(|g| g[i][j].clone()).collect(),
                })
                .collect()
        })
        .collect()
}

/// Undo degree elevation only: write the net in the Bernstein basis of its
/// actual bidegree, treating a power coefficient as zero when it is within
/// `tol` relative to the largest coefficient of its component (exact for
/// exact `T`; the `f64` path of [`coincide`](crate::coincide::coincide)).
pub(crate) fn drop_elevation<T: Ordered>(net: &Net<T>, tol: Tolerance) -> Net<T> {
    let comps = power_components(net);
    let (m, n) = actual_degree(&comps, |a, grid| {
        let big = grid
            .iter()
            .flatten()
            .map(Ordered::abs_val)
            .fold(T::zero(), |x, y| if y > x { y } else { x });
        a.is_zero()
            || (big.is_positive_within(Tolerance::EXACT) && (a.clone() / &big).is_zero_within(tol))
    });
    if (m, n) == (net.len() - 1, net[0].len() - 1) {
        return net.clone();
    }
    net_from_power(&comps, m, n)
}

/// Divide every polynomial by the gcd of their contents in `K[v]` (the
/// common factor that depends on `v` alone); returns the quotients and it.
fn divide_pure_v<T: Field>(polys: Vec<BPoly<T>>) -> (Vec<BPoly<T>>, UPoly<T>) {
    let mut c = UPoly::zero();
    for p in &polys {
        if c.degree() == Some(0) {
            break;
        }
        c = c.gcd(&p.content());
    }
    if c.degree().is_none_or(|d| d == 0) {
        return (polys, UPoly::constant(T::one()));
    }
    let q = polys
        .iter()
        .map(|p| p.div_v(&c).expect("the content divides every coefficient"))
        .collect();
    (q, c)
}

/// The gcd of the components and the components divided by it, in three
/// steps: the factor in v alone (gcd of contents), the factor in u alone
/// (the same on the transposed polynomials), then a mixed factor by the
/// primitive pseudo-remainder gcd — skipped when `coprime` certifies there
/// is none. The factor returned has leading coefficient 1.
fn remove_common_factor<T: Field>(
    comps: &[Vec<Vec<T>>],
    coprime: impl Fn(&[BPoly<T>]) -> bool,
) -> (Vec<BPoly<T>>, BPoly<T>) {
    let polys: Vec<BPoly<T>> = comps.iter().map(|g| BPoly::from_grid(g)).collect();
    let (polys, gv) = divide_pure_v(polys);
    let (transposed, gu) = divide_pure_v(polys.iter().map(BPoly::transpose).collect());
    let polys: Vec<BPoly<T>> = transposed.iter().map(BPoly::transpose).collect();
    let pure = BPoly::new(vec![gv]).mul(&BPoly::new(vec![gu]).transpose());
    if coprime(&polys) {
        return (polys, pure);
    }
    let mut g = BPoly::new(vec![]);
    for p in &polys {
        if g.is_nonzero_constant() {
            break;
        }
        g = g.gcd(p);
    }
    if g.is_zero() || g.is_nonzero_constant() {
        return (polys, pure);
    }
    let quotients = polys
        .iter()
        .map(|p| p.div_exact(&g).expect("the gcd divides every component"))
        .collect();
    (quotients, pure.mul(&g))
}

/// The result of reducing a curve or patch over `T` to its minimal degree.
#[derive(Clone, Debug, PartialEq)]
pub struct Minimal<P, T = BigRational> {
    /// The reduced curve or patch (the same parametric map).
    pub patch: P,
    /// The (bi)degree before reduction (`(m, 0)` for a curve).
    pub degree_before: (usize, usize),
    /// The (bi)degree after reduction.
    pub degree_after: (usize, usize),
    /// The common factor `g(u, v)` removed from every homogeneous component,
    /// normalized to leading coefficient 1 and sign `g(0, 0) > 0`, as a
    /// formula in `u`, `v`; `"1"` if none.
    pub common_factor: String,
    /// The same factor `g(u, v)` as a polynomial.
    pub factor: BPoly<T>,
    /// Was minimality certified modulo `p` (no exact gcd was needed)?
    pub certified: bool,
}

/// Exact scalars whose nets [`minimal_rect`] and [`minimal_curve`] reduce:
/// a field with exact equality, plus what lets the reduction skip the
/// exact bivariate gcd when it can prove there is no common factor.
///
/// Implemented for `BigRational` (certificates modulo `p = 2⁶¹ − 1`) and
/// for [`RealAlgebraic`] (certificates by interval resultants; when they
/// fail, the gcd is computed exactly over the real algebraic numbers).
pub trait Reducible: Ordered + std::fmt::Display {
    /// A proof that `net` is already of minimal bidegree; `false` only
    /// means "not certified".
    fn certified_minimal(net: &Net<Self>) -> bool;
    /// A proof that `polys` have no common factor of positive degree;
    /// `false` only means "not certified".
    fn certified_coprime(polys: &[BPoly<Self>]) -> bool;
    /// `g(u, v)` as a formula.
    fn factor_text(g: &BPoly<Self>) -> String;
    /// A lower bound of the actual bidegree of `net`, found cheaply, or
    /// `None`: it is where `minimal_net` first tries to undo an elevation.
    fn degree_lower_bound(net: &Net<Self>) -> Option<(usize, usize)>;
}

impl Reducible for BigRational {
    fn certified_minimal(net: &Net<Self>) -> bool {
        certified_minimal(net)
    }

    fn certified_coprime(polys: &[BPoly<Self>]) -> bool {
        coprime_mod_p(polys)
    }

    fn factor_text(g: &BPoly<Self>) -> String {
        g.to_poly("u", "v").to_string()
    }

    /// The bidegree of the power-basis components modulo `p = 2⁶¹ − 1`: a
    /// coefficient that is zero over Q is zero modulo p, so this degree is
    /// at most the actual one.
    fn degree_lower_bound(net: &Net<Self>) -> Option<(usize, usize)> {
        bernstein_mod_p(net).map(|image| image.into_power().actual_degree())
    }
}

/// Certificates by interval arithmetic (`coprime_by_intervals`): the
/// actual degree is read exactly, coprimality from interval resultants.
impl Reducible for RealAlgebraic {
    fn certified_minimal(net: &Net<Self>) -> bool {
        let comps = power_components(net);
        let shape = (net.len() - 1, net[0].len() - 1);
        actual_degree(&comps, |a, _| a.is_zero()) == shape && coprime_by_intervals(&comps, shape)
    }

    fn certified_coprime(polys: &[BPoly<Self>]) -> bool {
        let m = polys.iter().filter_map(BPoly::deg_u).max().unwrap_or(0);
        let n = polys.iter().filter_map(BPoly::deg_v).max().unwrap_or(0);
        let grids: Vec<Vec<Vec<Self>>> = polys.iter().map(|p| p.to_grid(m, n)).collect();
        coprime_by_intervals(&grids, (m, n))
    }

    /// None: no cheap image (the exact zero tests of `drop_elevation` run).
    fn degree_lower_bound(_: &Net<Self>) -> Option<(usize, usize)> {
        None
    }

    /// The rational formula when every coefficient is rational, else
    /// `Σ (c)*u^p*v^q` with each `c` in the algebraic number grammar.
    fn factor_text(g: &BPoly<Self>) -> String {
        let rational: Option<Vec<UPoly<BigRational>>> = g
            .coeffs()
            .iter()
            .map(|c| {
                let cs: Option<Vec<BigRational>> =
                    c.coeffs().iter().map(RealAlgebraic::as_rational).collect();
                cs.map(UPoly::new)
            })
            .collect();
        if let Some(r) = rational {
            return BigRational::factor_text(&BPoly::new(r));
        }
        let mut terms = Vec::new();
        for (p, c) in g.coeffs().iter().enumerate() {
            for (q, a) in c.coeffs().iter().enumerate() {
                if !a.is_zero() {
                    terms.push(format!("({a})*u**{p}*v**{q}"));
                }
            }
        }
        terms.join(" + ")
    }
}

/// Exact reduction of a homogeneous net to minimal bidegree.
///
/// Weights stay positive at the corners: the removed factor is taken with
/// `g(0, 0) > 0` (it has no zero on the closed unit square when the corner
/// weights are positive, since it divides the weight function).
pub(crate) fn minimal_net<T: Reducible>(net: &Net<T>) -> Minimal<Net<T>, T> {
    let before = (net.len() - 1, net[0].len() - 1);
    let certified = |patch: Net<T>| Minimal {
        degree_after: (patch.len() - 1, patch[0].len() - 1),
        patch,
        degree_before: before,
        common_factor: "1".into(),
        factor: BPoly::from_grid(&[vec![T::one()]]),
        certified: true,
    };
    if T::certified_minimal(net) {
        return certified(net.clone());
    }
    // A cheap lower bound of the degree: undo the elevation to it in one
    // exact pass, checked (an elevated copy costs O(size · degree), not a
    // change of basis of the whole net).
    let shape = before;
    let fast = T::degree_lower_bound(net)
        .filter(|&d| d != shape)
        .and_then(|d| undo_elevation(net, d));
    if let Some(lowered) = &fast
        && T::certified_minimal(lowered)
    {
        return certified(lowered.clone());
    }
    let net = fast.as_ref().unwrap_or(net);
    // An elevated net without a common factor: undo the elevation (exact
    // zero tests in the power basis), then certify, before any gcd.
    let lowered = drop_elevation(net, Tolerance::EXACT);
    if lowered.len() * lowered[0].len() < net.len() * net[0].len() && T::certified_minimal(&lowered)
    {
        return certified(lowered);
    }
    let comps = power_components(net);
    let (mut quotients, mut g) = remove_common_factor(&comps, T::certified_coprime);
    let g00 = g.coeffs().first().and_then(|c| c.coeffs().first()).cloned();
    if g00.is_some_and(|x| x < T::zero()) {
        let minus = UPoly::constant(-T::one());
        g = g.mul_v(&minus);
        quotients = quotients.iter().map(|q| q.mul_v(&minus)).collect();
    }
    let (m, n) = quotients.iter().fold((0, 0), |(m, n), q| {
        (m.max(q.deg_u().unwrap_or(0)), n.max(q.deg_v().unwrap_or(0)))
    });
    let grids: Vec<Vec<Vec<T>>> = quotients.iter().map(|q| q.to_grid(m, n)).collect();
    Minimal {
        patch: net_from_power(&grids, m, n),
        degree_before: before,
        degree_after: (m, n),
        common_factor: T::factor_text(&g),
        factor: g,
        certified: false,
    }
}

/// A certificate, modulo `p = 2⁶¹ − 1`, that a net over Q is already of
/// minimal bidegree. `true` is a proof; `false` only means "not certified".
///
/// Why it is sound: (1) a power coefficient of `u^m` that is non-zero mod p
/// is non-zero over Q, so the u-degree is m (likewise v). (2) Suppose a
/// common factor `g` with `deg_u g ≥ 1` exists; take it primitive in
/// Z[u, v] (Gauss). If some component keeps its u-degree after reducing mod
/// p and setting `v = v₀`, then so does `g`, and `ḡ(u, v₀)` is a
/// non-constant common divisor of all specialized components over F_p; so a
/// gcd of 1 over F_p excludes such `g`. (3) The same with `u = u₀` excludes a
/// factor with `deg_v g ≥ 1`; what is left is a constant.
pub(crate) fn certified_minimal(net: &Net<BigRational>) -> bool {
    bernstein_mod_p(net).is_some_and(|image| image.bernstein_certified())
}

/// The image modulo `p` of `net` as flat grids of Bernstein coefficients
/// ([`FpGrids::new`]); `None` when a denominator is divisible by `p`.
fn bernstein_mod_p(net: &Net<BigRational>) -> Option<FpGrids> {
    let (m, n) = (net.len() - 1, net[0].len() - 1);
    let comps = net[0][0].coords.len();
    let mut numbers = Vec::with_capacity(comps * (m + 1) * (n + 1));
    for c in 0..comps {
        numbers.extend(net.iter().flatten().map(|h| &h.coords[c]));
    }
    Some(FpGrids::new(
        Fp::from_rationals_checked(&numbers)?,
        comps,
        (m, n),
    ))
}

/// The net of bidegree `(k, l)` whose degree elevation is `net`, or `None`
/// if there is none: [`reduce_elevated`] on every row (to degree `l`), then
/// on every column of the result (to degree `k`). Exact, `O(m·n·(k + l))`
/// operations per coordinate for a net of bidegree `(m, n)`.
fn undo_elevation<T: Field>(net: &Net<T>, (k, l): (usize, usize)) -> Option<Net<T>> {
    let len = net[0][0].coords.len();
    let reduce_points = |points: &[&HPoint<T>], to: usize| -> Option<Vec<HPoint<T>>> {
        let coords: Vec<Vec<T>> = (0..len)
            .map(|c| {
                let line: Vec<T> = points.iter().map(|h| h.coords[c].clone()).collect();
                reduce_elevated(&line, to)
            })
            .collect::<Option<_>>()?;
        Some(
            (0..=to)
                .map(|i| HPoint {
                    coords: coords.iter().map(|c| c[i].clone()).collect(),
                })
                .collect(),
        )
    };
    let rows: Vec<Vec<HPoint<T>>> = net
        .iter()
        .map(|row| reduce_points(&row.iter().collect::<Vec<_>>(), l))
        .collect::<Option<_>>()?;
    let cols: Vec<Vec<HPoint<T>>> = (0..=l)
        .map(|j| reduce_points(&rows.iter().map(|r| &r[j]).collect::<Vec<_>>(), k))
        .collect::<Option<_>>()?;
    Some(
        (0..=k)
            .map(|i| cols.iter().map(|c| c[i].clone()).collect())
            .collect(),
    )
}

/// The certificate of [`certified_minimal`] for polynomials over Q: `true`
/// proves they have no common factor of positive degree.
fn coprime_mod_p(polys: &[BPoly<BigRational>]) -> bool {
    let m = polys.iter().filter_map(BPoly::deg_u).max().unwrap_or(0);
    let n = polys.iter().filter_map(BPoly::deg_v).max().unwrap_or(0);
    let mut data = Vec::with_capacity(polys.len() * (m + 1) * (n + 1));
    for p in polys {
        for x in p.to_grid(m, n).iter().flatten() {
            match Fp::from_rational_checked(x) {
                Some(x) => data.push(x),
                None => return false,
            }
        }
    }
    FpGrids::new(data, polys.len(), (m, n)).coprime()
}

/// Multiply every homogeneous component of `r` (bidegree (m, n)) by the
/// polynomial `f(u, v) = Σ f_{a,b} B_{a,p}(u) B_{b,q}(v)` (bidegree (p, q)):
/// the result, of bidegree (m + p, n + q), is the same parametric map
/// wherever `f ≠ 0`, with `f` a common factor of its components. Bernstein
/// product: `H'_{k,l} = Σ C(m,i)C(p,a)C(n,j)C(q,b) / (C(m+p,k)C(n+q,l)) · f_{a,b} H_{i,j}`
/// over `i + a = k`, `j + b = l`. Ring operations only.
///
/// **Panics if `f` is empty or ragged.**
///
/// ```
/// use exact_bezier::{coincide::multiply_components, coincide::minimal_rect, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let r = RectPatch::polynomial(vec![vec![p(0), p(1)], vec![p(2), p(5)]]).unwrap();
/// // f = 1 + uv has Bernstein net [[1, 1], [1, 2]].
/// let f = vec![vec![ratio(1, 1), ratio(1, 1)], vec![ratio(1, 1), ratio(2, 1)]];
/// let big = multiply_components(&r, &f);
/// assert_eq!(big.degree(), (2, 2));
/// assert_eq!(minimal_rect(&big).unwrap().common_factor, "u*v + 1");
/// ```
pub fn multiply_components<T: Scalar>(r: &RectPatch<T>, f: &[Vec<T>]) -> RectPatch<T> {
    let ((m, n), (p, q)) = (r.degree(), (f.len() - 1, f[0].len() - 1));
    let net = r.ctrl();
    let coef = |a: usize, i: usize, k: usize, deg: usize, extra: usize| {
        BigRational::new(
            crate::algebra::scalar::binomial(deg, i) * crate::algebra::scalar::binomial(extra, a),
            crate::algebra::scalar::binomial(deg + extra, k),
        )
    };
    let ctrl = (0..=m + p)
        .map(|k| {
            (0..=n + q)
                .map(|l| {
                    let mut acc = HPoint::zero(r.dim());
                    for (a, row) in f.iter().enumerate() {
                        for (b, fv) in row.iter().enumerate() {
                            if k < a || l < b || k - a > m || l - b > n {
                                continue;
                            }
                            let (i, j) = (k - a, l - b);
                            let c = T::from_rational(&(coef(a, i, k, m, p) * coef(b, j, l, n, q)));
                            acc = acc.add(&net[i][j].scale(&(c * fv)));
                        }
                    }
                    acc
                })
                .collect()
        })
        .collect();
    RectPatch::from_hom(ctrl).expect("a product of valid nets")
}

/// Reduce a rational tensor-product patch (over Q, or over the real algebraic numbers) to its minimal bidegree:
/// divide the homogeneous components by their gcd and undo elevation.
///
/// # Examples
///
/// An elevated, then Möbius-reparameterized patch has the common linear
/// factor `α(1 − u) + (1 − α)u`; the reduction removes it.
///
/// ```
/// use exact_bezier::{coincide::minimal_rect, RectPatch, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let s = RectPatch::new(
///     vec![vec![p(0, 0), p(0, 1)], vec![p(1, 0), p(2, 3)]],
///     vec![vec![ratio(1, 1), ratio(2, 1)], vec![ratio(3, 1), ratio(1, 2)]],
/// ).unwrap();
/// let big = s.elevate(1, 2).mobius_u(&ratio(1, 3));
/// let r = minimal_rect(&big).unwrap();
/// assert_eq!(r.degree_before, (2, 3));
/// assert_eq!(r.degree_after, (1, 1));
/// assert_eq!(r.patch.eval(&ratio(1, 5), &ratio(2, 7)).unwrap(), big.eval(&ratio(1, 5), &ratio(2, 7)).unwrap());
/// ```
///
/// # Errors
///
/// [`Error::Shape`] if the reduced patch would have a control point of
/// weight zero (its control points are then not Cartesian points; the
/// homogeneous net is still available through [`crate::coincide::coincide`]).
pub fn minimal_rect<T: Reducible>(r: &RectPatch<T>) -> Result<Minimal<RectPatch<T>, T>, Error> {
    let red = minimal_net(&r.ctrl().to_vec());
    let patch = RectPatch::from_hom(red.patch.clone())?;
    check_finite_points(&red.patch)?;
    Ok(Minimal {
        patch,
        degree_before: red.degree_before,
        degree_after: red.degree_after,
        common_factor: red.common_factor,
        factor: red.factor,
        certified: red.certified,
    })
}

/// Reduce a rational curve (over any [`Reducible`] scalar) to its minimal degree (see
/// [`minimal_rect`]; the common factor is a polynomial in `u = t`).
///
/// ```
/// use exact_bezier::{coincide::minimal_curve, RationalCurve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
/// let c = RationalCurve::new(vec![p(0, 0), p(1, 2), p(3, 0)], vec![ratio(1, 1), ratio(2, 1), ratio(1, 1)]).unwrap();
/// let r = minimal_curve(&c.mobius(&ratio(1, 4)).elevate(2)).unwrap();
/// assert_eq!(r.degree_after, (2, 0));
/// ```
///
/// # Errors
///
/// As [`minimal_rect`].
pub fn minimal_curve<T: Reducible>(
    c: &RationalCurve<T>,
) -> Result<Minimal<RationalCurve<T>, T>, Error> {
    let red = minimal_net(&curve_net(c));
    check_finite_points(&red.patch)?;
    let ctrl = red.patch.iter().map(|row| row[0].clone()).collect();
    Ok(Minimal {
        patch: RationalCurve::from_hom(ctrl)?,
        degree_before: red.degree_before,
        degree_after: red.degree_after,
        common_factor: red.common_factor,
        factor: red.factor,
        certified: red.certified,
    })
}

fn check_finite_points<T: Scalar>(net: &Net<T>) -> Result<(), Error> {
    for (i, row) in net.iter().enumerate() {
        if let Some(j) = row.iter().position(|h| h.weight().is_zero()) {
            return Err(Error::Shape(format!(
                "the reduced control point ({i},{j}) has weight 0 (a point at infinity)"
            )));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::scalar::ratio;
    use crate::bernstein::bernstein_to_power;
    use crate::samples::rect_1x2 as sample;
    type Q = BigRational;

    #[test]
    fn round_trip_power_bernstein() {
        let b: Vec<Q> = vec![ratio(1, 2), ratio(-3, 1), ratio(5, 7), ratio(2, 1)];
        assert_eq!(power_to_bernstein(&bernstein_to_power(&b), 3), b);
    }

    #[test]
    fn generic_patch_is_certified() {
        let r = minimal_rect(&sample()).unwrap();
        assert!(r.certified);
        assert_eq!(r.patch, sample());
    }

    #[test]
    fn mixed_factor_one_plus_uv_is_removed() {
        // Multiply every component by 1 + uv (Bernstein (1,1): 1, 1, 1, 2).
        let s = sample();
        let f = RectPatch::new(
            vec![vec![vec![ratio::<Q>(0, 1)]; 2]; 2],
            vec![
                vec![ratio(1, 1), ratio(1, 1)],
                vec![ratio(1, 1), ratio(2, 1)],
            ],
        )
        .unwrap();
        let comps_s = power_components(&s.ctrl().to_vec());
        let fw: Vec<Vec<Q>> = power_components(&f.ctrl().to_vec()).pop().unwrap();
        let prod: Vec<BPoly<Q>> = comps_s
            .iter()
            .map(|g| {
                let a = BPoly::from_grid(g);
                let b = BPoly::from_grid(&fw);
                // a·b via div_exact's inverse: build by convolution.
                let (m, n) = (a.deg_u().unwrap() + 1, a.deg_v().unwrap_or(0) + 1);
                let (ga, gb) = (a.to_grid(m, n), b.to_grid(1, 1));
                let mut out = vec![vec![ratio::<Q>(0, 1); n + 2]; m + 2];
                for (p, r) in ga.iter().enumerate() {
                    for (q, x) in r.iter().enumerate() {
                        for (pp, rr) in gb.iter().enumerate() {
                            for (qq, y) in rr.iter().enumerate() {
                                out[p + pp][q + qq] = out[p + pp][q + qq].clone() + x.clone() * y;
                            }
                        }
                    }
                }
                BPoly::from_grid(&out)
            })
            .collect();
        let grids: Vec<Vec<Vec<Q>>> = prod.iter().map(|p| p.to_grid(2, 3)).collect();
        let big = net_from_power(&grids, 2, 3);
        let red = minimal_net(&big);
        assert!(!red.certified);
        assert_eq!(red.common_factor, "u*v + 1");
        assert_eq!(red.degree_after, (1, 2));
        assert_eq!(red.patch, s.ctrl().to_vec());
    }
}
