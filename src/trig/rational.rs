//! Trigonometric curves and surfaces as **exact** rational Bézier curves and
//! patches in the half-angle parameter `τ = tan(t/2)`.
//!
//! On `t ∈ [0, π/2]`, `τ ∈ [0, 1]` and
//!
//! ```text
//! s = sin t = 2τ/(1+τ²),   c = cos t = (1−τ²)/(1+τ²)
//! ```
//!
//! so every function `a₀ + a₁s + a₂c + a₃s² + a₄sc` of the trigonometric
//! basis (source 002 eq. 1) is a quartic in τ divided by `(1+τ²)²`:
//!
//! ```text
//! (1+τ²)²·1  = 1 + 2τ² + τ⁴      (1+τ²)²·s  = 2τ + 2τ³      (1+τ²)²·c = 1 − τ⁴
//! (1+τ²)²·s² = 4τ²               (1+τ²)²·sc = 2τ − 2τ³
//! ```
//!
//! A trig curve is therefore the rational quartic with homogeneous control
//! points `Σᵢ bᵢₖ (Pᵢ, 1)`, where `bᵢₖ` are the Bernstein coefficients of
//! `(1+τ²)² Xᵢ`; the weights are those of `(1+τ²)²` (partition of unity),
//! `1, 1, 4/3, 2, 4`. A trig-rect is the tensor product: a rational (4, 4)
//! patch. The point sets are identical and the map is exact over every
//! scalar, so plotting, meshing, coincidence and every other rational
//! Bézier algorithm apply to trigonometric patches unchanged.
//!
//! Reference: source 002 eq. (1); the half-angle substitution is ours.

use crate::algebra::scalar::{ratio, Scalar};
use crate::bernstein::power_to_bernstein;
use crate::curve::RationalCurve;
use crate::hpoint::HPoint;
use crate::rect::RectPatch;
use crate::trig::basis::TrigFn;
use crate::trig::curve::TrigCurve;
use crate::trig::surface::TrigRect;
use num_rational::BigRational;

/// Power-form coefficients (in τ, degree ≤ 4) of `(1+τ²)²` times each of
/// `1, s, c, s², sc`.
const MONOMIALS_TIMES_DENOMINATOR: [[i64; 5]; 5] = [
    [1, 0, 2, 0, 1],
    [0, 2, 0, 2, 0],
    [1, 0, 0, 0, -1],
    [0, 0, 4, 0, 0],
    [0, 2, 0, -2, 0],
];

/// The quartic Bernstein coefficients (in τ) of `(1+τ²)²·m` for each
/// monomial `m` of `1, s, c, s², sc`.
fn monomial_bernstein<T: Scalar>() -> [[T; 5]; 5] {
    MONOMIALS_TIMES_DENOMINATOR.map(|power| {
        let power: Vec<BigRational> = power.iter().map(|&a| ratio(a, 1)).collect();
        let b = power_to_bernstein(&power, 4);
        std::array::from_fn(|k| T::from_rational(&b[k]))
    })
}

/// The quartic Bernstein coefficients (in τ) of `(1+τ²)² f` for a function
/// `f` of the trigonometric basis.
fn quartic_numerator<T: Scalar>(f: &TrigFn<T>, monomials: &[[T; 5]; 5]) -> [T; 5] {
    std::array::from_fn(|k| {
        f.coeffs()
            .iter()
            .zip(monomials)
            .fold(T::zero(), |acc, (a, m)| acc + &(a.clone() * &m[k]))
    })
}

/// `(1+τ²)² Xᵢ(t; α)` in quartic Bernstein form, for the four basis functions.
fn basis_numerators<T: Scalar>(alpha: &T) -> [[T; 5]; 4] {
    let monomials = monomial_bernstein::<T>();
    TrigFn::basis(alpha).map(|x| quartic_numerator(&x, &monomials))
}

impl<T: Scalar> TrigCurve<T> {
    /// The same curve as an exact rational quartic in `τ = tan(t/2)`: the
    /// rational curve at `τ` is the trig curve at `t = 2 arctan τ`
    /// (see the module docs for the construction).
    ///
    /// ```
    /// use exact_bezier::{ratio, trig::TrigCurve, trig::TrigParam};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let c = TrigCurve::new(vec![p(0, 0), p(1, 2), p(3, 2), p(4, 0)], ratio(1, 1)).unwrap();
    /// let q = c.to_rational();
    /// assert_eq!(q.weights(), vec![ratio(1, 1), ratio(1, 1), ratio(4, 3), ratio(2, 1), ratio(4, 1)]);
    /// let tau = ratio(1, 2); // sin t = 4/5, cos t = 3/5
    /// assert_eq!(q.eval(&tau).unwrap(), c.eval(&TrigParam::from_tau(&tau)));
    /// ```
    pub fn to_rational(&self) -> RationalCurve<T> {
        let b = basis_numerators(self.alpha());
        let ctrl = (0..5)
            .map(|k| {
                weighted_sum(
                    self.points()
                        .iter()
                        .zip(&b)
                        .map(|(p, bi)| (p, bi[k].clone())),
                )
            })
            .collect();
        RationalCurve::from_hom(ctrl).expect("four points of one dimension give five")
    }
}

impl<T: Scalar> TrigRect<T> {
    /// The same surface as an exact rational (4, 4) tensor-product patch in
    /// `(τ_u, τ_v) = (tan(u/2), tan(v/2))`: the tensor product of the curve
    /// construction.
    ///
    /// ```
    /// use exact_bezier::{ratio, trig::TrigParam, trig::TrigRect};
    /// use exact_bezier::BigRational;
    /// let net = (0..4).map(|i| (0..4).map(|j| vec![ratio::<BigRational>(i, 1), ratio(j, 1), ratio(i * j, 1)]).collect()).collect();
    /// let s = TrigRect::new(net, [ratio(1, 2), ratio(3, 2)]).unwrap();
    /// let r = s.to_rational();
    /// let (tu, tv) = (ratio(1, 3), ratio(1, 2));
    /// assert_eq!(r.eval(&tu, &tv).unwrap(), s.eval(&TrigParam::from_tau(&tu), &TrigParam::from_tau(&tv)));
    /// ```
    pub fn to_rational(&self) -> RectPatch<T> {
        let [a1, a2] = self.alpha();
        let (bu, bv) = (basis_numerators(a1), basis_numerators(a2));
        let ctrl = (0..5)
            .map(|k| {
                (0..5)
                    .map(|l| {
                        weighted_sum(self.points().iter().zip(&bu).flat_map(|(row, bi)| {
                            row.iter()
                                .zip(&bv)
                                .map(move |(p, bj)| (p, bi[k].clone() * &bj[l]))
                        }))
                    })
                    .collect()
            })
            .collect();
        RectPatch::from_hom(ctrl).expect("a 4 × 4 net of one dimension gives 5 × 5")
    }
}

/// `Σ c·(P, 1)` as a homogeneous point.
fn weighted_sum<'a, T: Scalar + 'a>(terms: impl Iterator<Item = (&'a Vec<T>, T)>) -> HPoint<T> {
    let mut terms = terms.peekable();
    let dim = terms.peek().map_or(0, |(p, _)| p.len());
    terms.fold(HPoint::zero(dim), |acc, (p, c)| {
        acc.add(&HPoint::from_point(p, &T::one()).scale(&c))
    })
}
