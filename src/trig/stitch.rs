//! G⁰ / G¹ joins of two trigonometric surfaces and the stitching
//! constructor (source 002 §3–§4), decided exactly.
//!
//! Canonical join (u–u): the edge `v = π/2` of `S₁` (parameter u, shape α₁)
//! meets the edge `v = 0` of `S₂` (parameter u, shape λ₁). The other joins
//! are reduced to it by exchanging u and v ([`TrigJoin`]).
//!
//! The correct conditions (proved in `proofs/src/trig_stitching.rs`), with
//! `ΔPᵢ = Pᵢ₃ − Pᵢ₂`, `ΔQᵢ = Qᵢ₁ − Qᵢ₀`:
//!
//! ```text
//! ∂S₁/∂v(u, π/2) = α₂ Σᵢ Xᵢ(u; α₁) ΔPᵢ        (not (4 + 2α₂) as printed in (7))
//! ∂S₂/∂v(u, 0)   = λ₂ Σᵢ Xᵢ(u; λ₁) ΔQᵢ
//! G⁰ ⇔ P₀₃ = Q₀₀, P₃₃ = Q₃₀, α₁(P₁₃ − P₀₃) = λ₁(Q₁₀ − Q₀₀), α₁(P₂₃ − P₃₃) = λ₁(Q₂₀ − Q₃₀)
//! (6) ∂S₁/∂v = μ ∂S₂/∂v, μ > 0  ⇔ (α₁ = λ₁ ≠ 0, G⁰)  α₂ ΔPᵢ = μ λ₂ ΔQᵢ
//! ```
//!
//! Reference: source 002 Theorems 3–5, eqs. (5)–(10), §4.

use super::basis::TrigParam;
use super::surface::TrigRect;
use crate::algebra::scalar::{ratio, Ordered, Scalar, Tolerance};
use crate::error::Error;

/// Which edges of two surfaces meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrigJoin {
    /// u–u (Theorem 3): `S₁(u, π/2)` meets `S₂(u, 0)`.
    UU,
    /// v–v (Theorem 4): `S₁(π/2, v)` meets `S₂(0, v)`.
    VV,
    /// u–v (Theorem 5): `S₁(u, π/2)` meets `S₂(0, u)`.
    UV,
}

impl TrigJoin {
    /// The pair reoriented so the join is the canonical u–u one.
    fn canonical<T: Scalar>(
        self,
        s1: &TrigRect<T>,
        s2: &TrigRect<T>,
    ) -> (TrigRect<T>, TrigRect<T>) {
        match self {
            TrigJoin::UU => (s1.clone(), s2.clone()),
            TrigJoin::VV => (s1.swap_uv(), s2.swap_uv()),
            TrigJoin::UV => (s1.clone(), s2.swap_uv()),
        }
    }
}

/// Do the two surfaces share the joining edge as the same parametric curve
/// (G⁰)? Decided by comparing the edge curves as functions (coefficients on
/// `1, s, c, s², s c`); exact for exact scalars, within `tol` for `f64`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{ratio, trig::trig_g0, Tolerance, trig::TrigJoin, trig::TrigRect};
/// use exact_bezier::BigRational;
/// let net = |dx: i64| -> Vec<Vec<Vec<BigRational>>> {
///     (0..4).map(|i| (0..4).map(|j| vec![ratio(i, 1), ratio(j + dx, 1), ratio(i * j, 1)]).collect()).collect()
/// };
/// let s1 = TrigRect::new(net(0), [ratio(1, 1), ratio(1, 1)]).unwrap();
/// let mut q = net(3);
/// for i in 0..4 { q[i][0] = s1.points()[i][3].clone(); }
/// let s2 = TrigRect::new(q, [ratio(1, 1), ratio(2, 1)]).unwrap();
/// assert!(trig_g0(&s1, &s2, TrigJoin::UU, Tolerance::EXACT));
/// ```
pub fn trig_g0<T: Ordered>(
    s1: &TrigRect<T>,
    s2: &TrigRect<T>,
    join: TrigJoin,
    tol: Tolerance,
) -> bool {
    let (a, b) = join.canonical(s1, s2);
    let (fa, fb) = (
        a.u_curve(0, &TrigParam::end()).functions(),
        b.u_curve(0, &TrigParam::start()).functions(),
    );
    fa.iter().zip(&fb).all(|(x, y)| {
        x.coeffs()
            .iter()
            .zip(y.coeffs())
            .all(|(p, q)| (p.clone() - q).is_zero_within(tol))
    })
}

/// The factor μ of a G¹ join in the sense of eq. (6): `Some(μ)` when the
/// join is G⁰ and `∂S₁/∂v(u, π/2) ≡ μ · ∂S₂/∂v(u, 0)` for one constant
/// `μ > 0` (canonical orientation), else `None` (also when both
/// cross-boundary derivatives vanish). This is the Faux condition the paper
/// uses; it implies tangent-plane continuity along the whole edge (for a
/// u–v join the two normal fields are then opposite, as the swap of u and v
/// reverses orientation).
///
/// # Examples
///
/// See [`trig_stitch`].
pub fn trig_g1_factor<T: Ordered>(
    s1: &TrigRect<T>,
    s2: &TrigRect<T>,
    join: TrigJoin,
    tol: Tolerance,
) -> Option<T> {
    if !trig_g0(s1, s2, join, tol) {
        return None;
    }
    let (a, b) = join.canonical(s1, s2);
    let flat = |r: &TrigRect<T>, at: TrigParam<T>| -> Vec<T> {
        r.u_curve(1, &at)
            .functions()
            .iter()
            .flat_map(|f| f.coeffs().clone())
            .collect()
    };
    let (d1, d2) = (flat(&a, TrigParam::end()), flat(&b, TrigParam::start()));
    let k = (0..d2.len()).max_by(|&i, &j| {
        d2[i]
            .abs_val()
            .partial_cmp(&d2[j].abs_val())
            .unwrap_or(std::cmp::Ordering::Equal)
    })?;
    if d2[k].is_zero_within(tol) {
        return None;
    }
    let mu = d1[k].clone() / &d2[k];
    let proportional = d1
        .iter()
        .zip(&d2)
        .all(|(x, y)| (x.clone() - &(mu.clone() * y)).is_zero_within(tol));
    (proportional && mu.is_positive_within(tol)).then_some(mu)
}

/// `a × b` in 3-D.
pub fn cross<T: Scalar>(a: &[T], b: &[T]) -> [T; 3] {
    std::array::from_fn(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        a[i].clone() * &b[j] - a[j].clone() * &b[i]
    })
}

/// Tangent-plane continuity (geometric G¹) of a G⁰ join of 3-D surfaces,
/// without assuming the form (6): the normals `N₁ = ∂S₁/∂u × ∂S₁/∂v` at
/// `v = π/2` and `N₂` of `S₂` at `v = 0` (canonical orientation) are
/// parallel along the whole edge, `N₁ × N₂ ≡ 0`, and point to the same side.
///
/// Exact: each component of `N₁ × N₂` is a polynomial of degree ≤ 8 in
/// `(sin u, cos u)`, i.e. `(1+τ²)⁻⁸` times a polynomial of degree ≤ 16 in
/// `τ = tan(u/2)`, so vanishing at the 17 parameters `τ = k/16` proves it
/// vanishes identically. The side (`N₁ · N₂ ≥ 0`, and `> 0` somewhere) is
/// checked at the same 17 parameters; between them it can only change where
/// a normal vanishes (a singular point of a surface).
///
/// Reference: source 002 eq. (5) (the normal condition), which (6) only
/// implies.
///
/// # Errors
///
/// [`Error::Shape`] unless both surfaces are 3-D.
///
/// # Examples
///
/// ```
/// use exact_bezier::{ratio, trig::trig_g1_factor, trig::trig_tangent_continuous, Tolerance, trig::TrigJoin, trig::TrigRect};
/// use exact_bezier::BigRational;
/// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1), ratio(0, 1)];
/// let one = || [ratio(1, 1), ratio(1, 1)];
/// let s1 = TrigRect::new((0..4).map(|i| (0..4).map(|j| p(i, j)).collect()).collect(), one()).unwrap();
/// let s2 = TrigRect::new((0..4).map(|i| vec![p(i, 3), p(i, 4 + i), p(i, 5 + i), p(i, 6 + i)]).collect(), one()).unwrap();
/// // Both lie in the plane z = 0: G¹, but with no constant factor μ.
/// assert_eq!(trig_tangent_continuous(&s1, &s2, TrigJoin::UU, Tolerance::EXACT), Ok(true));
/// assert_eq!(trig_g1_factor(&s1, &s2, TrigJoin::UU, Tolerance::EXACT), None);
/// ```
pub fn trig_tangent_continuous<T: Ordered>(
    s1: &TrigRect<T>,
    s2: &TrigRect<T>,
    join: TrigJoin,
    tol: Tolerance,
) -> Result<bool, Error> {
    if s1.points()[0][0].len() != 3 || s2.points()[0][0].len() != 3 {
        return Err(Error::Shape("normals need 3-D surfaces".into()));
    }
    if !trig_g0(s1, s2, join, tol) {
        return Ok(false);
    }
    let (a, b) = join.canonical(s1, s2);
    let (start, end) = (TrigParam::start(), TrigParam::end());
    let mut dots = Vec::with_capacity(17);
    for k in 0..=16 {
        let u = TrigParam::from_tau(&ratio::<T>(k, 16));
        let n1 = cross(&a.partial(1, 0, &u, &end), &a.partial(0, 1, &u, &end));
        let n2 = cross(&b.partial(1, 0, &u, &start), &b.partial(0, 1, &u, &start));
        if !cross(&n1, &n2).iter().all(|x| x.is_zero_within(tol)) {
            return Ok(false);
        }
        dots.push(
            n1.iter()
                .zip(&n2)
                .fold(T::zero(), |acc, (x, y)| acc + &(x.clone() * y)),
        );
    }
    let negative = dots.iter().any(|d| (-d.clone()).is_positive_within(tol));
    Ok(!negative && dots.iter().any(|d| d.is_positive_within(tol)))
}

/// The stitching constructor of §4 (u–u join): the neighbour `S₂` of `S₁`
/// with shape parameters `(α₁, λ₂)`, first rows
///
/// ```text
/// Qᵢ₀ = Pᵢ₃,   Qᵢ₁ = Pᵢ₃ + ∂ᵢ / (μ λ₂),   ∂ᵢ = α₂ (Pᵢ₃ − Pᵢ₂)
/// ```
///
/// (`∂ᵢ` the control points of `∂S₁/∂v(u, π/2)`) and the given far rows
/// `far[0][i] = Qᵢ₂`, `far[1][i] = Qᵢ₃`, so that `∂S₁/∂v = μ ∂S₂/∂v` along
/// the shared edge.
///
/// Reference: source 002 §4 steps 1–2, with Theorem 3 corrected.
///
/// # Errors
///
/// [`Error::Domain`] if `μ ≤ 0` or `λ₂ = 0` (the basis degenerates);
/// [`Error::Shape`] if the far rows are not 2 × 4 points of the dimension of
/// `S₁`.
///
/// # Examples
///
/// ```
/// use exact_bezier::{ratio, trig::trig_g1_factor, trig::trig_stitch, Tolerance, trig::TrigJoin, trig::TrigRect};
/// use exact_bezier::BigRational;
/// let net: Vec<Vec<Vec<BigRational>>> = (0..4)
///     .map(|i| (0..4).map(|j| vec![ratio(i, 1), ratio(j, 1), ratio(i * j % 3, 1)]).collect())
///     .collect();
/// let s1 = TrigRect::new(net, [ratio(6, 5), ratio(13, 10)]).unwrap();
/// let far = [2, 3].map(|j| (0..4).map(|i| vec![ratio(i, 1), ratio(3 + j, 1), ratio(0, 1)]).collect());
/// let s2 = trig_stitch(&s1, ratio(11, 10), ratio(4, 5), far).unwrap();
/// assert_eq!(trig_g1_factor(&s1, &s2, TrigJoin::UU, Tolerance::EXACT), Some(ratio(4, 5)));
/// ```
pub fn trig_stitch<T: Ordered>(
    s1: &TrigRect<T>,
    lambda2: T,
    mu: T,
    far: [Vec<Vec<T>>; 2],
) -> Result<TrigRect<T>, Error> {
    if !mu.is_positive_within(Tolerance::EXACT) {
        return Err(Error::Domain("the factor μ must be positive".into()));
    }
    if lambda2.is_zero() {
        return Err(Error::Domain("λ₂ = 0 makes X₁ = X₂ = 0".into()));
    }
    let edge = s1.u_curve(0, &TrigParam::end());
    let cross = s1.u_curve(1, &TrigParam::end());
    let k = (mu * &lambda2).recip();
    let first: Vec<Vec<T>> = edge
        .points()
        .iter()
        .zip(cross.points())
        .map(|(p, d)| {
            p.iter()
                .zip(d)
                .map(|(x, y)| x.clone() + &(y.clone() * &k))
                .collect()
        })
        .collect();
    let [q2, q3] = far;
    if q2.len() != 4 || q3.len() != 4 {
        return Err(Error::Shape("the far rows need 4 points each".into()));
    }
    let dim = edge.points()[0].len();
    if q2.iter().chain(&q3).any(|p| p.len() != dim) {
        return Err(Error::Shape(format!(
            "the far rows must be points of dimension {dim}"
        )));
    }
    let points = (0..4)
        .map(|i| {
            vec![
                edge.points()[i].clone(),
                first[i].clone(),
                q2[i].clone(),
                q3[i].clone(),
            ]
        })
        .collect();
    TrigRect::new(points, [s1.alpha()[0].clone(), lambda2])
}
