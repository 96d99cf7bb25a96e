//! Standard forms: end weights 1 for curves, corner weights 1 for rect
//! patches (source 000, Theorem 1, eq. (8), and (18)(19) generalized to any
//! bidegree).
//!
//! Every standard form here is a reparameterization that keeps the point set
//! (a Möbius map, or the quadratic map of [`crate::reparam::Quadratic`]) followed by a
//! uniform weight scaling (eq. 5), both proved to keep every point in the
//! proofs family `yang_yong`.
//!
//! The formulas need m-th and n-th roots. Over Q they are exact when the
//! roots are rational ([`rational_root`](crate::algebra::rational_root)); [`standardize_curve_algebraic`]
//! and [`standardize_rect_algebraic`] run the same code on
//! [`RealAlgebraic`] and are exact for every input. The older
//! [`standardize_rect_exact_or_f64`] and [`standardize_curve_exact_or_f64`]
//! fall back to `f64` instead.
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
//! [`standardize_quadratic_compact`] returns that smaller form.

use crate::algebra::real_algebraic::RealAlgebraic;
use crate::algebra::scalar::{ratio, Field, Ordered, Roots, Scalar, Tolerance};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::io::{patch_to_json, JsonScalar};
use crate::patch::Patch;
use crate::rect::RectPatch;
use crate::reparam::Quadratic;
use num_rational::BigRational;
use num_traits::One;
use serde_json::{json, Value};

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

impl<T: JsonScalar> StandardMap<T> {
    /// The `reparameterization` object of `standardize`'s output:
    /// `{"kind": "mobius", "alpha", "beta"?, "k"}` or `{"kind": "quadratic",
    /// "alpha1", "alpha2", "beta1", "beta2", "k"}` (docs/FORMAT.md).
    pub fn to_json(&self) -> Value {
        let j = |x: &T| x.to_json();
        match self {
            StandardMap::Mobius { alpha, beta, k } => match beta {
                Some(b) => json!({"kind": "mobius", "alpha": j(alpha), "beta": j(b), "k": j(k)}),
                None => json!({"kind": "mobius", "alpha": j(alpha), "k": j(k)}),
            },
            StandardMap::Quadratic { map, k } => json!({
                "kind": "quadratic",
                "alpha1": j(&map.alpha1), "alpha2": j(&map.alpha2),
                "beta1": j(&map.beta1), "beta2": j(&map.beta2), "k": j(k)
            }),
        }
    }
}

impl<P: Clone + Into<Patch<T>>, T: JsonScalar + Field> Standard<P, T> {
    /// The `standardize` command's object: `{"exact": true,
    /// "reparameterization": {...}, "patch": {...}}` (docs/FORMAT.md).
    ///
    /// # Errors
    ///
    /// As [`patch_to_json`] (a weight that is not positive).
    pub fn to_json(&self) -> Result<Value, Error> {
        Ok(json!({
            "exact": true,
            "reparameterization": self.map.to_json(),
            "patch": patch_to_json(&self.patch.clone().into())?,
        }))
    }
}

/// An exact result, or an `f64` one when an exact answer would need an
/// irrational root.
#[derive(Clone, Debug, PartialEq)]
pub enum Exactness<E, F> {
    /// Computed over Q.
    Exact(E),
    /// Computed in `f64` (the reason is the `NotRational` message).
    Approximate(F, String),
}

/// A curve's standard form over Q; or, when the root is irrational, the
/// same curve exactly reparameterized by a rational α̃ near the true α (end
/// weights 1 and 1 + O(n·2⁻⁵²)), see [`standardize_curve_exact_or_f64`].
pub type CurveOutcome = Exactness<
    Standard<RationalCurve<BigRational>, BigRational>,
    Standard<RationalCurve<BigRational>, BigRational>,
>;

/// A rect patch's standard form over Q, or in `f64`.
pub type RectOutcome =
    Exactness<Standard<RectPatch<BigRational>, BigRational>, Standard<RectPatch<f64>, f64>>;

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

/// The standard form of a curve (end weights 1): Möbius `α = 1/(1 + (w₀/w_n)^{1/n})`
/// then `k = 1/(w₀ αⁿ)`. Exact when `w₀/w_n` is an n-th power in Q.
///
/// Reference: source 000 §0 (Farin's standard form), eqs (2)(4)(5), curve case.
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight; [`Error::NotRational`] when
/// the root is irrational for exact `T`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{RationalCurve, reparam::standardize_curve, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let c = RationalCurve::new(vec![p(0), p(1), p(3)], vec![ratio(4, 1), ratio(1, 1), ratio(1, 1)]).unwrap();
/// let s = standardize_curve(&c).unwrap();
/// // The standard middle weight is w₁/√(w₀w₂) = 1/√4.
/// assert_eq!(s.patch.weights(), vec![ratio(1, 1), ratio(1, 2), ratio(1, 1)]);
/// ```
pub fn standardize_curve<T: Roots>(
    c: &RationalCurve<T>,
) -> Result<Standard<RationalCurve<T>, T>, Error> {
    c.check_positive_weights()?;
    let w = c.weights();
    let n = c.degree();
    let alpha = alpha_for(&w[0], &w[n], n, "curve standard form α")?;
    let moved = c.mobius(&alpha);
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

/// [`standardize_curve`] exactly; when the root is irrational, the nearly
/// standard form of `near_standard_curve`: exact numbers, so weights far
/// outside the `f64` range (`1e-400`) neither underflow nor overflow.
///
/// # Errors
///
/// As [`standardize_curve`], except that `NotRational` becomes `Approximate`.
pub fn standardize_curve_exact_or_f64(
    c: &RationalCurve<BigRational>,
) -> Result<CurveOutcome, Error> {
    match standardize_curve(c) {
        Ok(s) => Ok(Exactness::Exact(s)),
        Err(Error::NotRational(why)) => Ok(Exactness::Approximate(near_standard_curve(c), why)),
        Err(e) => Err(e),
    }
}

/// The nearly standard form when the root is irrational: α rounded to a
/// rational α̃ computed in the log domain (no `f64` overflow or underflow
/// however extreme the weights), then the Möbius map and the scale
/// `k = 1/w̃₀` applied **exactly**: the same curve, end weights 1 and
/// `1 + O(n·2⁻⁵²)`.
fn near_standard_curve(
    c: &RationalCurve<BigRational>,
) -> Standard<RationalCurve<BigRational>, BigRational> {
    let w = c.weights();
    let n = c.degree();
    let alpha = alpha_near(&(w[0].clone() / &w[n]), n);
    let moved = c.mobius(&alpha);
    let k = moved.weights()[0].recip();
    let patch = moved.scale_weights(&k);
    Standard {
        patch,
        map: StandardMap::Mobius {
            alpha,
            beta: None,
            k,
        },
    }
}

/// A rational near `1 / (1 + q^{1/n})` for `q > 0`, from `log₂ q` (exact
/// power-of-two part plus the `f64` logarithm of a mantissa in `[1/2, 2)`).
fn alpha_near(q: &BigRational, n: usize) -> BigRational {
    use num_bigint::BigInt;
    let shift = q.numer().bits() as i64 - q.denom().bits() as i64;
    let two_pow = |e: i64| -> BigRational {
        let p = BigInt::from(1) << e.unsigned_abs();
        if e >= 0 {
            BigRational::from_integer(p)
        } else {
            BigRational::new(BigInt::from(1), p)
        }
    };
    let mantissa = (q / two_pow(shift)).to_f64();
    let l = (mantissa.log2() + shift as f64) / n.max(1) as f64;
    let whole = l.floor();
    let frac = BigRational::from_float(2f64.powf(l - whole)).unwrap_or_else(BigRational::one);
    let root = frac * two_pow(whole as i64);
    (BigRational::one() + root).recip()
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
/// result has bidegree (m, n) and corner weights 1.
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight; [`Error::Domain`] naming the
/// violated condition when Theorem 1 fails (`|…| > tol` for `f64`);
/// [`Error::NotRational`] when a root is irrational for exact `T`.
///
/// # Examples
///
/// Source 000, Example 3 (exact: α = 3/5, β = 7/10):
///
/// ```
/// use exact_bezier::{io::read_patches, Patch, reparam::standardize_mobius, reparam::StandardMap, ratio, Tolerance};
/// let text = std::fs::read_to_string("tests/fixtures/yang_yong_example3.json").unwrap();
/// let Patch::Rect(r) = &read_patches(&text).unwrap()[0] else { panic!() };
/// let s = standardize_mobius(r, Tolerance::EXACT).unwrap();
/// let StandardMap::Mobius { alpha, beta, .. } = &s.map else { panic!() };
/// assert_eq!((alpha.clone(), beta.clone()), (ratio(3, 5), Some(ratio(7, 10))));
/// ```
pub fn standardize_mobius<T: Roots>(
    p: &RectPatch<T>,
    tol: Tolerance,
) -> Result<Standard<RectPatch<T>, T>, Error> {
    p.check_positive_weights()?;
    if !theorem1_holds(p, tol) {
        let [w00, wm0, w0n, wmn] = corner_weights(p);
        let (m, n) = p.degree();
        return Err(Error::Domain(format!(
            "Theorem 1 fails: ω_{{{m},0}}·ω_{{0,{n}}} = {} ≠ ω_{{0,0}}·ω_{{{m},{n}}} = {}, so no linear Möbius map standardizes this patch (use the quadratic reparameterization)",
            (wm0 * &w0n).to_f64(),
            (w00 * &wmn).to_f64()
        )));
    }
    mobius_unchecked(p)
}

fn mobius_unchecked<T: Roots>(p: &RectPatch<T>) -> Result<Standard<RectPatch<T>, T>, Error> {
    let (m, n) = p.degree();
    let [w00, wm0, w0n, _] = corner_weights(p);
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
/// (the generalized (19), see the module docs), then `k = 1/(α2^m β^n ω_{0,0})`.
/// The result has bidegree (m + n, m + n) and corner weights 1.
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight; [`Error::NotRational`] when
/// a root is irrational for exact `T`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{RectPatch, reparam::standardize_quadratic, reparam::corner_weights, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let w = vec![vec![ratio(1, 1), ratio(1, 1)], vec![ratio(4, 1), ratio(9, 1)]];
/// let s = standardize_quadratic(&RectPatch::new(vec![vec![p(0), p(1)], vec![p(2), p(3)]], w).unwrap()).unwrap();
/// assert_eq!(corner_weights(&s.patch), [ratio(1, 1), ratio(1, 1), ratio(1, 1), ratio(1, 1)]);
/// ```
pub fn standardize_quadratic<T: Roots>(
    p: &RectPatch<T>,
) -> Result<Standard<RectPatch<T>, T>, Error> {
    let map = standard_quadratic_map(p)?;
    Ok(scaled(p.quadratic_reparam(&map), map))
}

/// [`standardize_quadratic`] in the compact bidegree `(m, m + n)`: since
/// β1 = β2, the map is a Möbius map in v followed by the quadratic map in u
/// alone ([`RectPatch::quadratic_reparam_u`]); the paper's `(m + n, m + n)`
/// patch is this one degree-elevated n times in s (proved in `yang_yong`).
///
/// # Errors
///
/// As [`standardize_quadratic`].
///
/// # Examples
///
/// ```
/// use exact_bezier::{RectPatch, reparam::standardize_quadratic, reparam::standardize_quadratic_compact, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let w = vec![vec![ratio(1, 1), ratio(1, 1)], vec![ratio(4, 1), ratio(9, 1)]];
/// let patch = RectPatch::new(vec![vec![p(0), p(1)], vec![p(2), p(3)]], w).unwrap();
/// let compact = standardize_quadratic_compact(&patch).unwrap();
/// assert_eq!(compact.patch.degree(), (1, 2));
/// assert_eq!(compact.patch.elevate(1, 0), standardize_quadratic(&patch).unwrap().patch);
/// ```
pub fn standardize_quadratic_compact<T: Roots>(
    p: &RectPatch<T>,
) -> Result<Standard<RectPatch<T>, T>, Error> {
    let map = standard_quadratic_map(p)?;
    let moved = p
        .mobius_v(&map.beta1)
        .quadratic_reparam_u(&map.alpha1, &map.alpha2);
    Ok(scaled(moved, map))
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

/// Scale the weights so that `ω_{0,0}` becomes 1.
fn scaled<T: Roots>(moved: RectPatch<T>, map: Quadratic<T>) -> Standard<RectPatch<T>, T> {
    let k = moved.ctrl()[0][0].weight().recip();
    Standard {
        patch: moved.scale_weights(&k),
        map: StandardMap::Quadratic { map, k },
    }
}

/// The standard form of a rect patch: linear (8) when Theorem 1 holds
/// (bidegree kept), quadratic otherwise (bidegree (m + n, m + n)).
///
/// # Errors
///
/// As [`standardize_mobius`] and [`standardize_quadratic`].
pub fn standardize_rect<T: Roots>(
    p: &RectPatch<T>,
    tol: Tolerance,
) -> Result<Standard<RectPatch<T>, T>, Error> {
    if theorem1_holds(p, tol) {
        standardize_mobius(p, tol)
    } else {
        standardize_quadratic(p)
    }
}

/// The standard form of a curve over the real algebraic numbers: exact for
/// every curve with positive weights ([`standardize_curve`] run on
/// [`RealAlgebraic`]; the roots are radicals of the end weights).
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight.
///
/// ```
/// use exact_bezier::{RationalCurve, reparam::standardize_curve_algebraic, ratio};
/// use exact_bezier::BigRational;
/// let p = |x: i64| vec![ratio::<BigRational>(x, 1)];
/// let c = RationalCurve::new(vec![p(0), p(1), p(3)], vec![ratio(2, 1), ratio(1, 1), ratio(1, 1)]).unwrap();
/// let s = standardize_curve_algebraic(&c).unwrap();
/// // The standard middle weight is w₁/√(w₀w₂) = 1/√2.
/// assert_eq!(s.patch.weights()[1].to_string(), "sqrt(2)/2");
/// ```
pub fn standardize_curve_algebraic(
    c: &RationalCurve<BigRational>,
) -> Result<Standard<RationalCurve<RealAlgebraic>, RealAlgebraic>, Error> {
    standardize_curve(&c.map(Scalar::from_rational))
}

/// [`standardize_rect`] over the real algebraic numbers: exact for every
/// patch with positive weights. The linear (8) or quadratic method is chosen
/// exactly (Theorem 1 on the exact input); `compact` selects
/// [`standardize_quadratic_compact`].
///
/// # Errors
///
/// [`Error::Weight`] for a non-positive weight.
pub fn standardize_rect_algebraic(
    p: &RectPatch<BigRational>,
    compact: bool,
) -> Result<Standard<RectPatch<RealAlgebraic>, RealAlgebraic>, Error> {
    let a = p.map(Scalar::from_rational);
    if theorem1_holds(p, Tolerance::EXACT) {
        mobius_unchecked(&a)
    } else if compact {
        standardize_quadratic_compact(&a)
    } else {
        standardize_quadratic(&a)
    }
}

/// [`standardize_rect`] exactly, or in `f64` when a root is irrational. The
/// choice between the linear and the quadratic method is made exactly on the
/// exact input. `compact` selects [`standardize_quadratic_compact`]
/// (bidegree (m, m + n)) over the paper's (m + n, m + n) form.
///
/// # Errors
///
/// As [`standardize_rect`], except that `NotRational` becomes `Approximate`.
pub fn standardize_rect_exact_or_f64(
    p: &RectPatch<BigRational>,
    compact: bool,
) -> Result<RectOutcome, Error> {
    let linear = theorem1_holds(p, Tolerance::EXACT);
    let quadratic = |p: &RectPatch<BigRational>| {
        if compact {
            standardize_quadratic_compact(p)
        } else {
            standardize_quadratic(p)
        }
    };
    let exact = if linear {
        standardize_mobius(p, Tolerance::EXACT)
    } else {
        quadratic(p)
    };
    match exact {
        Ok(s) => Ok(Exactness::Exact(s)),
        Err(Error::NotRational(why)) => {
            let f = p.map(Ordered::to_f64);
            let approx = if linear {
                mobius_unchecked(&f)?
            } else if compact {
                standardize_quadratic_compact(&f)?
            } else {
                standardize_quadratic(&f)?
            };
            Ok(Exactness::Approximate(approx, why))
        }
        Err(e) => Err(e),
    }
}
