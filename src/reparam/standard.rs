//! Standard forms: end weights 1 for curves, corner weights 1 for rect
//! patches (source 000, Theorem 1, eq. (8), and (18)(19) generalized to any
//! bidegree).
//!
//! Every standard form here is a reparameterization that keeps the point set
//! (a Möbius map, or the quadratic map of [`crate::reparam::Quadratic`]) followed by a
//! uniform weight scaling (eq. 5), both proved to keep every point in the
//! proofs family `yang_yong`.
//!
//! One entry point, [`standardize`], for curves and rect patches over any
//! scalar with roots. The formulas need m-th and n-th roots: over Q they
//! are exact when the roots are rational (else [`Error::NotRational`]); on
//! [`RealAlgebraic`](crate::algebra::RealAlgebraic) (lift the input with
//! `map(Scalar::from_rational)`) the same code is exact for every input;
//! over `f64` it is approximate.
//!
//! ## Generalizing (18)(19) to bidegree (m, n)
//!
//! The quadratic map gives the corner weights (ours, proved for all
//! (m, n) ≤ (4, 4); the paper prints the bicubic case before (18), correctly)
//!
//! ```text
//! ω̃_{0,0}     = α2^m β2^n ω_{0,0}          ω̃_{m+n,0}   = (1 − α2)^m β1^n ω_{m,0}
//! ω̃_{0,m+n}   = α1^m (1 − β2)^n ω_{0,n}    ω̃_{m+n,m+n} = (1 − α1)^m (1 − β1)^n ω_{m,n}
//! ```
//!
//! Three equations in four unknowns. We fix **β1 = β2 = β** as the paper
//! does: then v is a plain linear Möbius map of t (the extra freedom is spent
//! in u only), and the equations decouple into closed forms with one root
//! each:
//!
//! ```text
//! α2 = 1 / (1 + (ω_{0,0}/ω_{m,0})^{1/m})      (side v = 0)
//! α1 = 1 / (1 + (ω_{0,n}/ω_{m,n})^{1/m})      (side v = 1)
//! β  = 1 / (1 + (α2^m ω_{0,0} / (α1^m ω_{0,n}))^{1/n})
//! ```
//!
//! which is (19) for m = n = 3. (Fixing α1 = α2 instead is the mirror image.)
//! When Theorem 1 holds, α1 = α2 and the map is linear: we then use (8),
//! which keeps the bidegree (m, n).
//!
//! With β1 = β2 the result of the quadratic map, of bidegree (m + n, m + n)
//! as the paper states, is the n-fold degree elevation in s of a patch of
//! bidegree (m, m + n) (ours, proved in `yang_yong`):
//! [`Options::compact`] selects that smaller form.

use crate::algebra::scalar::{ratio, Ordered, Roots, Scalar, Tolerance};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::rect::RectPatch;
use crate::reparam::Quadratic;

/// The reparameterization a standard form applied, with its parameters.
#[derive(Clone, Debug, PartialEq)]
pub enum StandardMap<T> {
    /// Linear Möbius maps (eqs 2, 3) in u with `alpha` and in v with `beta`
    /// (for a curve `beta` is `None`), then weights times `k` (eq. 5).
    Mobius {
        /// α of eq. (2).
        alpha: T,
        /// β of eq. (3); `None` for a curve.
        beta: Option<T>,
        /// The weight scale k of eq. (5).
        k: T,
    },
    /// The quadratic map (eqs 9, 10), then weights times `k`.
    Quadratic {
        /// α1, α2, β1, β2.
        map: Quadratic<T>,
        /// The weight scale.
        k: T,
    },
}

/// A standard form and the map that produced it.
#[derive(Clone, Debug, PartialEq)]
pub struct Standard<P, T> {
    /// The curve or patch in standard form.
    pub patch: P,
    /// How it was obtained.
    pub map: StandardMap<T>,
}

/// Which reparameterization [`standardize`] applies to a rect patch.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Method {
    /// The linear (8) when Theorem 1 holds (bidegree kept), the quadratic
    /// map otherwise.
    #[default]
    Auto,
    /// The linear (8); [`Error::Domain`] when Theorem 1 fails.
    Mobius,
    /// The quadratic map of the generalized (19), even when Theorem 1 holds.
    Quadratic,
}

/// How [`standardize`] works on a rect patch (a curve always takes the
/// Möbius map of eq. 2).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Options {
    /// The linear or the quadratic method.
    pub method: Method,
    /// The quadratic form in the compact bidegree `(m, m + n)` instead of
    /// the paper's `(m + n, m + n)` (which is the compact one elevated n
    /// times in s).
    pub compact: bool,
    /// Tolerance of Theorem 1's test for `f64` (default `1e-9`); exact
    /// scalars test exactly.
    pub tol: Tolerance,
}

impl Options {
    /// Whether [`standardize`] takes the linear (8) for `p` (else the
    /// quadratic map): Theorem 1 decides for [`Method::Auto`].
    pub fn linear<T: Scalar>(&self, p: &RectPatch<T>) -> bool {
        match self.method {
            Method::Auto => theorem1_holds(p, self.tol),
            Method::Mobius => true,
            Method::Quadratic => false,
        }
    }
}

/// A curve or rect patch [`standardize`] brings to standard form.
pub trait Standardize: Sized {
    /// The scalar of the control points and weights.
    type Scalar: Roots;
    /// The standard form of `self` under `options`.
    ///
    /// # Errors
    ///
    /// As [`standardize`].
    fn standardize(&self, options: Options) -> Result<Standard<Self, Self::Scalar>, Error>;
}

/// The standard form of a curve (end weights 1) or a rect patch (corner
/// weights 1), see the module docs: the curve by eqs (2)(4)(5); the rect by
/// the linear (8) when Theorem 1 holds (or [`Method::Mobius`]), else by the
/// quadratic map of the generalized (19) (bidegree `(m + n, m + n)`, or
/// `(m, m + n)` with [`Options::compact`]), then `k = 1/ω̃_{0,0}`.
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight; [`Error::Domain`] naming the
/// violated condition for [`Method::Mobius`] when Theorem 1 fails (`|…| >
/// tol` for `f64`); [`Error::NotRational`] when a root is irrational for
/// `BigRational` (use `RealAlgebraic` for an exact answer to every input).
///
/// # Examples
///
/// ```
/// use exact_bezier::{RationalCurve, reparam::{standardize, Options}, ratio, algebra::RealAlgebraic, Scalar};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let c = RationalCurve::new(vec![p(0), p(1), p(3)], vec![ratio(4, 1), ratio(1, 1), ratio(1, 1)]).unwrap();
/// let s = standardize(&c, Options::default()).unwrap();
/// // The standard middle weight is w₁/√(w₀w₂) = 1/√4.
/// assert_eq!(s.patch.weights(), vec![ratio(1, 1), ratio(1, 2), ratio(1, 1)]);
/// // With w₀ = 2 the root is irrational: exact over the algebraic numbers.
/// let c = RationalCurve::new(vec![p(0), p(1), p(3)], vec![ratio(2, 1), ratio(1, 1), ratio(1, 1)]).unwrap();
/// let s = standardize(&c.map(RealAlgebraic::from_rational), Options::default()).unwrap();
/// assert_eq!(s.patch.weights()[1].to_string(), "sqrt(2)/2");
/// ```
///
/// Source 000, Example 3 (Theorem 1 holds; exact: α = 3/5, β = 7/10), and
/// a patch where it fails (quadratic, compact bidegree (1, 2)):
///
/// ```
/// use exact_bezier::{io::read_patches, Patch, RectPatch, reparam::{standardize, corner_weights, Options, StandardMap}, ratio};
/// use exact_bezier::BigRational;
/// let text = std::fs::read_to_string("tests/fixtures/yang_yong_example3.json").unwrap();
/// let Patch::Rect(r) = &read_patches(&text).unwrap()[0] else { panic!() };
/// let s = standardize(r, Options::default()).unwrap();
/// let StandardMap::Mobius { alpha, beta, .. } = &s.map else { panic!() };
/// assert_eq!((alpha.clone(), beta.clone()), (ratio(3, 5), Some(ratio(7, 10))));
///
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let w = vec![vec![ratio(1, 1), ratio(1, 1)], vec![ratio(4, 1), ratio(9, 1)]];
/// let patch = RectPatch::new(vec![vec![p(0), p(1)], vec![p(2), p(3)]], w).unwrap();
/// let full = standardize(&patch, Options::default()).unwrap();
/// assert_eq!(corner_weights(&full.patch), [ratio(1, 1), ratio(1, 1), ratio(1, 1), ratio(1, 1)]);
/// let compact = standardize(&patch, Options { compact: true, ..Options::default() }).unwrap();
/// assert_eq!(compact.patch.degree(), (1, 2));
/// assert_eq!(compact.patch.elevate(1, 0), full.patch);
/// ```
pub fn standardize<P: Standardize>(
    p: &P,
    options: Options,
) -> Result<Standard<P, P::Scalar>, Error> {
    p.standardize(options)
}

/// `1 / (1 + (num/den)^{1/n})`, the Möbius α that maps end weights
/// `num, den` to equal ones (`1/2` when `n = 0`).
fn alpha_for<T: Roots>(num: &T, den: &T, n: usize, what: &str) -> Result<T, Error> {
    if n == 0 {
        return Ok(ratio(1, 2));
    }
    let q = num.clone() / den;
    let r = q
        .nth_root(n as u32)
        .ok_or_else(|| irrational(what, n, &q))?;
    Ok((T::one() + &r).recip())
}

fn irrational<T: Ordered>(what: &str, n: usize, q: &T) -> Error {
    Error::NotRational(format!(
        "{what}: the {n}-th root of {} is irrational",
        q.to_f64()
    ))
}

/// The curve: Möbius `α = 1/(1 + (w₀/w_n)^{1/n})` then `k = 1/(w₀ αⁿ)`
/// (source 000 §0, Farin's standard form, eqs (2)(4)(5), curve case);
/// `options` do not apply.
impl<T: Roots> Standardize for RationalCurve<T> {
    type Scalar = T;

    fn standardize(&self, _: Options) -> Result<Standard<Self, T>, Error> {
        self.check_positive_weights()?;
        let w = self.weights();
        let n = self.degree();
        let alpha = alpha_for(&w[0], &w[n], n, "curve standard form α")?;
        let moved = self.mobius(&alpha);
        let k = moved.weights()[0].recip();
        Ok(Standard {
            patch: moved.scale_weights(&k),
            map: StandardMap::Mobius {
                alpha,
                beta: None,
                k,
            },
        })
    }
}

/// The rect patch: the method of `options` (Theorem 1 decides for
/// [`Method::Auto`]), see [`standardize`].
impl<T: Roots> Standardize for RectPatch<T> {
    type Scalar = T;

    fn standardize(&self, options: Options) -> Result<Standard<Self, T>, Error> {
        self.check_positive_weights()?;
        if options.linear(self) {
            linear(self, options.tol)
        } else {
            quadratic(self, options.compact)
        }
    }
}

/// The corner weights `(ω_{0,0}, ω_{m,0}, ω_{0,n}, ω_{m,n})`.
pub fn corner_weights<T: Scalar>(p: &RectPatch<T>) -> [T; 4] {
    let (m, n) = p.degree();
    let w = |i: usize, j: usize| p.ctrl()[i][j].weight().clone();
    [w(0, 0), w(m, 0), w(0, n), w(m, n)]
}

/// Theorem 1 (source 000): a patch can be standardized by linear Möbius maps
/// (2)(3) and a scaling (5) iff `ω_{m,0} ω_{0,n} = ω_{0,0} ω_{m,n}`
/// (`|difference| ≤ tol` for `f64`).
///
/// ```
/// use exact_bezier::{RectPatch, reparam::theorem1_holds, ratio, Tolerance};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let w = |a: i64, b: i64, c: i64, d: i64| vec![vec![ratio(a, 1), ratio(b, 1)], vec![ratio(c, 1), ratio(d, 1)]];
/// let net = vec![vec![p(0), p(1)], vec![p(2), p(3)]];
/// assert!(theorem1_holds(&RectPatch::new(net.clone(), w(2, 3, 4, 6)).unwrap(), Tolerance::EXACT));
/// assert!(!theorem1_holds(&RectPatch::new(net, w(2, 3, 4, 5)).unwrap(), Tolerance::EXACT));
/// ```
pub fn theorem1_holds<T: Scalar>(p: &RectPatch<T>, tol: Tolerance) -> bool {
    let [w00, wm0, w0n, wmn] = corner_weights(p);
    (wm0 * &w0n - &(w00 * &wmn)).is_zero_within(tol)
}

/// The linear standardization (8): `α = 1/(1 + (ω_{0,0}/ω_{m,0})^{1/m})`,
/// `β = 1/(1 + (ω_{0,0}/ω_{0,n})^{1/n})`, `k = 1/(ω_{0,0} α^m β^n)`; the
/// result has bidegree (m, n) and corner weights 1. [`Error::Domain`]
/// naming the violated condition when Theorem 1 fails.
fn linear<T: Roots>(p: &RectPatch<T>, tol: Tolerance) -> Result<Standard<RectPatch<T>, T>, Error> {
    let [w00, wm0, w0n, wmn] = corner_weights(p);
    let (m, n) = p.degree();
    if !theorem1_holds(p, tol) {
        return Err(Error::Domain(format!(
            "Theorem 1 fails: ω_{{{m},0}}·ω_{{0,{n}}} = {} ≠ ω_{{0,0}}·ω_{{{m},{n}}} = {}, so no linear Möbius map standardizes this patch (use the quadratic reparameterization)",
            (wm0 * &w0n).to_f64(),
            (w00 * &wmn).to_f64()
        )));
    }
    let alpha = alpha_for(&w00, &wm0, m, "eq. (8) α")?;
    let beta = alpha_for(&w00, &w0n, n, "eq. (8) β")?;
    let moved = p.mobius_u(&alpha).mobius_v(&beta);
    let k = moved.ctrl()[0][0].weight().recip();
    Ok(Standard {
        patch: moved.scale_weights(&k),
        map: StandardMap::Mobius {
            alpha,
            beta: Some(beta),
            k,
        },
    })
}

/// Standardization of any (m, n) patch by the quadratic map with β1 = β2
/// (the generalized (19), see the module docs), then `k = 1/(α2^m β^n ω_{0,0})`:
/// bidegree (m + n, m + n) and corner weights 1. `compact`: since β1 = β2,
/// the map is a Möbius map in v followed by the quadratic map in u alone
/// ([`RectPatch::quadratic_reparam_u`]), of bidegree `(m, m + n)`; the
/// paper's patch is that one degree-elevated n times in s (proved in
/// `yang_yong`).
fn quadratic<T: Roots>(
    p: &RectPatch<T>,
    compact: bool,
) -> Result<Standard<RectPatch<T>, T>, Error> {
    let map = standard_quadratic_map(p)?;
    let moved = if compact {
        p.mobius_v(&map.beta1)
            .quadratic_reparam_u(&map.alpha1, &map.alpha2)
    } else {
        p.quadratic_reparam(&map)
    };
    let k = moved.ctrl()[0][0].weight().recip();
    Ok(Standard {
        patch: moved.scale_weights(&k),
        map: StandardMap::Quadratic { map, k },
    })
}

/// The map of the quadratic standardization alone: the generalized eq.
/// (19) of source 000, `α2 = 1/(1 + (ω_{0,0}/ω_{m,0})^{1/m})`,
/// `α1 = 1/(1 + (ω_{0,n}/ω_{m,n})^{1/m})` and `β1 = β2 = 1/(1 + ρ)` with
/// `ρ = (α2^m ω_{0,0} / (α1^m ω_{0,n}))^{1/n}` — without the (m + n, m + n)
/// patch (cheap where the patch is not: Example 2's exact form takes
/// seconds, its map milliseconds).
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight; over `BigRational`,
/// [`Error::NotRational`] when a root is irrational.
///
/// ```
/// use exact_bezier::{algebra::RealAlgebraic, io::read_patches, reparam::standard_quadratic_map, Patch, Scalar};
/// let text = std::fs::read_to_string("tests/fixtures/yang_yong_example2.json").unwrap();
/// let Patch::Rect(p) = read_patches(&text).unwrap().remove(0) else { unreachable!() };
/// let map = standard_quadratic_map(&p.map(RealAlgebraic::from_rational)).unwrap();
/// assert_eq!(map.alpha2, "1/(1 + cbrt(3/2))".parse::<RealAlgebraic>().unwrap());
/// ```
pub fn standard_quadratic_map<T: Roots>(p: &RectPatch<T>) -> Result<Quadratic<T>, Error> {
    p.check_positive_weights()?;
    let (m, n) = p.degree();
    let [w00, wm0, w0n, wmn] = corner_weights(p);
    let alpha2 = alpha_for(&w00, &wm0, m, "eq. (19) α2")?;
    let alpha1 = alpha_for(&w0n, &wmn, m, "eq. (19) α1")?;
    let beta = match beta_root(&alpha1, &alpha2, &w00, &w0n, m, n)? {
        Some(r) => (T::one() + &r).recip(),
        None => ratio(1, 2),
    };
    Ok(Quadratic {
        alpha1,
        alpha2,
        beta1: beta.clone(),
        beta2: beta,
    })
}

/// The root `ρ = (α2^m ω_{0,0} / (α1^m ω_{0,n}))^{1/n}` of eq. (19)'s β
/// (`None` when `n = 0`).
///
/// Computed first as `((α2/α1)^{m/g})^{g/n} · (ω_{0,0}/ω_{0,n})^{1/n}` with
/// `g = gcd(m, n)` — the same positive number — because each factor is a
/// root of something simpler: for `n | m` the first factor is a power of
/// `α2/α1`, so an algebraic `ρ` stays in the field of the α's and one new
/// radical of the corner weights (Example 2: no resultants). Falls back to
/// the direct root when a factor has no exact root (a rational `ρ` may have
/// irrational factors).
fn beta_root<T: Roots>(
    alpha1: &T,
    alpha2: &T,
    w00: &T,
    w0n: &T,
    m: usize,
    n: usize,
) -> Result<Option<T>, Error> {
    if n == 0 {
        return Ok(None);
    }
    let g = num_integer::gcd(m, n);
    let ratio_power = (alpha2.clone() / alpha1).pow_u32((m / g) as u32);
    let split = ratio_power
        .nth_root((n / g) as u32)
        .zip((w00.clone() / w0n).nth_root(n as u32))
        .map(|(a, b)| a * &b);
    if let Some(r) = split {
        return Ok(Some(r));
    }
    let q = alpha2.pow_u32(m as u32) * w00 / &(alpha1.pow_u32(m as u32) * w0n);
    q.nth_root(n as u32)
        .map(Some)
        .ok_or_else(|| irrational("eq. (19) β1 = β2", n, &q))
}
