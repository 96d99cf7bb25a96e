//! Circular arcs as rational Bézier curves: the quadratic arc and the
//! λ-family of standard-form rational cubics of Hang & Li (source 004).
//!
//! Conventions. `c = cos(θ/2)` for the centre angle `θ`; `k = 1 + 2c`. The
//! quadratic arc [`QuadArc`] has homogeneous control points
//!
//! ```text
//! A₀ = (b̄₀, 1),   A₁ = (c·b̄₁, c)  (or (b, 0) when θ = π),   A₂ = (b̄₂, 1)
//! ```
//!
//! (weights 1, c, 1). Every standard cubic of the family is this quadratic,
//! Möbius-reparameterized with weight ratio `σ` (non-standard weights
//! `1, cσ, σ²`, source 004 eqs. 3–5) and multiplied by the linear factor
//! `(1 − u) + u/σ²` that makes the end weights 1. With `σ = p/q`:
//!
//! ```text
//! C₀ = p²q²·A₀,   C₁ = q(2p³·A₁ + q³·A₀)/3,
//! C₂ = p(p³·A₂ + 2q³·A₁)/3,   C₃ = p²q²·A₂          (common factor p²q²)
//! ```
//!
//! and the paper's λ is tied to σ by `σ³ = N/D` with
//!
//! ```text
//! N = 1 − λk,   D = 1 + 2λck,   E = 1 − λ(1 − 4c²)   (N + 2cD = kE)
//! ```
//!
//! so `ω₁ = kσ/(3N)`, `ω₂ = kE/(3Dσ)`, `b₁* = (D·b̄₀ + 2cN·b̄₁)/k`,
//! `b₂* = (N·b̄₂ + 2cD·b̄₁)/(kE)` (eq. 1, checked in `proofs/src/hang_li.rs`).
//! λ is admissible (positive weights) iff `N, D, E > 0`.
//!
//! Exactness: [`Roots`] gives exact cube and square roots for
//! [`RealAlgebraic`](crate::algebra::RealAlgebraic) (always), for
//! `BigRational` when they are rational ([`Error::NotRational`] otherwise),
//! and rounded ones for `f64`; the `arc` command computes over the real
//! algebraic numbers, so every λ gives an exact cubic.
//!
//! Reference: source 004 (Hang & Li 2011) §1–§3.

mod inverse;

pub use inverse::{lambda_change_delta, lambda_change_param};

use crate::algebra::scalar::{ratio, Field, Ordered, Roots, Scalar, Tolerance};
use crate::curve::RationalCurve;
use crate::error::Error;
use crate::hpoint::HPoint;

/// A circular arc as a rational quadratic Bézier curve with weights
/// `1, c, 1`, `c = cos(θ/2)`; for `θ = π` the middle point is the direction
/// `b` at infinity (weight 0), source 004 eq. (2).
///
/// # Examples
///
/// The arc of the unit circle from (1, 0) to (7/25, 24/25): half-angle with
/// `cos = 4/5`, `sin = 3/5`.
///
/// ```
/// use exact_bezier::{arc::QuadArc, ratio, Tolerance};
/// use exact_bezier::BigRational;
/// let b0 = vec![ratio::<BigRational>(1, 1), ratio(0, 1)];
/// let b2 = vec![ratio(7, 25), ratio(24, 25)];
/// let arc = QuadArc::from_ends(&b0, &b2, &ratio(4, 5), &ratio(3, 5), Tolerance::EXACT).unwrap();
/// assert_eq!(arc.ctrl()[1].coords, vec![ratio(4, 5), ratio(3, 5), ratio(4, 5)]); // b̄₁ = (1, 3/4)
/// let x = arc.to_curve().eval(&ratio(1, 3)).unwrap();
/// assert_eq!(x[0].clone() * &x[0] + x[1].clone() * &x[1], ratio(1, 1));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct QuadArc<T> {
    ctrl: [HPoint<T>; 3],
}

/// # Construction
impl<T: Scalar> QuadArc<T> {
    /// The arc with homogeneous control points `[A₀, A₁, A₂]`, trusted to be
    /// `(b̄₀, 1), (c·b̄₁, c), (b̄₂, 1)` of a circular arc (unchecked; used with
    /// symbolic scalars, where nothing can be checked).
    pub fn new_raw(ctrl: [HPoint<T>; 3]) -> Self {
        QuadArc { ctrl }
    }

    /// The same arc over another scalar type.
    pub fn map<U: Scalar>(&self, f: impl Fn(&T) -> U) -> QuadArc<U> {
        let [a0, a1, a2] = &self.ctrl;
        QuadArc {
            ctrl: [a0.map(&f), a1.map(&f), a2.map(&f)],
        }
    }

    /// The homogeneous control points `[A₀, A₁, A₂]`.
    pub fn ctrl(&self) -> &[HPoint<T>; 3] {
        &self.ctrl
    }

    /// `c = cos(θ/2)`, the middle weight.
    pub fn cos_half(&self) -> &T {
        self.ctrl[1].weight()
    }

    /// The quadratic rational Bézier curve itself.
    pub fn to_curve(&self) -> RationalCurve<T> {
        RationalCurve::from_hom(self.ctrl.to_vec()).expect("three points of one dimension")
    }
}

/// # Checked construction
impl<T: Ordered> QuadArc<T> {
    /// The arc from `b̄₀` counter-clockwise to `b̄₂` (plane) with centre angle
    /// `θ`, given by `cos(θ/2)` and `sin(θ/2)`:
    ///
    /// ```text
    /// A₁ = (c·m + (s/2)·(e_y, −e_x), c),  m = (b̄₀ + b̄₂)/2,  e = b̄₂ − b̄₀
    /// ```
    ///
    /// i.e. `b̄₁ = m + (tan(θ/2)/2)·(e_y, −e_x)` (the tangents' intersection);
    /// for `θ = π` (c = 0) `A₁` is the direction `(e_y, −e_x)/2` of length
    /// the radius. Any `0 < θ < 2π` is a valid quadratic arc; the cubic
    /// family needs `θ < 4π/3` (see [`check_lambda`]).
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] unless both points are 2D and distinct;
    /// [`Error::Domain`] unless `c² + s² = 1` (within `tol`) and `s > 0`.
    pub fn from_ends(
        b0: &[T],
        b2: &[T],
        cos_half: &T,
        sin_half: &T,
        tol: Tolerance,
    ) -> Result<Self, Error> {
        if b0.len() != 2 || b2.len() != 2 {
            return Err(Error::Shape("arc end points must be 2D".into()));
        }
        let (c, s) = (cos_half, sin_half);
        let unit = c.clone() * c + &(s.clone() * s) - T::one();
        if !unit.is_zero_within(tol) || !s.is_positive_within(tol) {
            return Err(Error::Domain(format!(
                "(cos θ/2, sin θ/2) = ({}, {}) must satisfy c² + s² = 1 with s > 0",
                c.to_f64(),
                s.to_f64()
            )));
        }
        let e = [b2[0].clone() - &b0[0], b2[1].clone() - &b0[1]];
        if e.iter().all(|x| x.is_zero_within(tol)) {
            return Err(Error::Shape("arc end points coincide".into()));
        }
        let half = ratio::<T>(1, 2);
        let mid = [
            (b0[0].clone() + &b2[0]) * &half,
            (b0[1].clone() + &b2[1]) * &half,
        ];
        let hs = s.clone() * &half;
        let a1 = HPoint {
            coords: vec![
                c.clone() * &mid[0] + &(hs.clone() * &e[1]),
                c.clone() * &mid[1] - &(hs * &e[0]),
                c.clone(),
            ],
        };
        Ok(QuadArc {
            ctrl: [HPoint::from_cartesian(b0), a1, HPoint::from_cartesian(b2)],
        })
    }

    /// The arc with control points `b̄₀, b̄₁, b̄₂` (any dimension ≥ 2) and
    /// middle weight `c = cos(θ/2) ≠ 0` (source 004 §1): checks that the
    /// control triangle is isosceles (`|b̄₁ − b̄₀| = |b̄₁ − b̄₂|`) with base
    /// angle `α`, `cos α = |c|`:
    /// `c²·|b̄₁ − b̄₀|²·|b̄₂ − b̄₀|² = ((b̄₁ − b̄₀)·(b̄₂ − b̄₀))²`. A negative
    /// `c` gives the complementary (major) arc, `π < θ < 2π`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] for mismatched dimensions or a degenerate triangle;
    /// [`Error::Domain`] if `c ∉ (−1, 1)`, `c = 0`, or the triangle does not
    /// fit `c`.
    pub fn from_control(
        b0: &[T],
        b1: &[T],
        b2: &[T],
        cos_half: &T,
        tol: Tolerance,
    ) -> Result<Self, Error> {
        let n = b0.len();
        if n < 2 || b1.len() != n || b2.len() != n {
            return Err(Error::Shape(
                "arc control points need one dimension ≥ 2".into(),
            ));
        }
        let c = cos_half;
        let inside = c.abs_val() < T::one();
        if c.is_zero_within(tol) || !inside {
            return Err(Error::Domain(format!(
                "cos(θ/2) = {} must lie in (−1, 1) and not be 0 (θ = π needs a direction: QuadArc::semicircle)",
                c.to_f64()
            )));
        }
        let u = sub(b1, b0);
        let e = sub(b2, b0);
        let (uu, ee, ue) = (dot(&u, &u), dot(&e, &e), dot(&u, &e));
        if ee.is_zero_within(tol) || uu.is_zero_within(tol) {
            return Err(Error::Shape("degenerate arc control triangle".into()));
        }
        let v = sub(b1, b2);
        let isosceles = (dot(&v, &v) - &uu).is_zero_within(tol);
        let angle = (c.clone() * c * &uu * &ee - &(ue.clone() * &ue)).is_zero_within(tol);
        if !isosceles || !angle || !ue.is_positive_within(tol) {
            return Err(Error::Domain(format!(
                "control triangle does not fit cos(θ/2) = {}: need |b̄₁−b̄₀| = |b̄₁−b̄₂| and base angle α with cos α = |cos(θ/2)|",
                c.to_f64()
            )));
        }
        Ok(QuadArc {
            ctrl: [
                HPoint::from_cartesian(b0),
                HPoint::from_point(b1, c),
                HPoint::from_cartesian(b2),
            ],
        })
    }

    /// The semicircle (θ = π) from `b̄₀` to `b̄₂` bulging along the direction
    /// `b` (source 004 eq. 2): `b ⟂ b̄₂ − b̄₀` and `|b|` = the radius, so
    /// `A₁ = (b, 0)`.
    ///
    /// # Errors
    ///
    /// [`Error::Shape`] for mismatched dimensions; [`Error::Domain`] unless
    /// `b·(b̄₂ − b̄₀) = 0` and `4|b|² = |b̄₂ − b̄₀|² ≠ 0`.
    pub fn semicircle(b0: &[T], b2: &[T], b: &[T], tol: Tolerance) -> Result<Self, Error> {
        let n = b0.len();
        if n < 2 || b2.len() != n || b.len() != n {
            return Err(Error::Shape(
                "semicircle points need one dimension ≥ 2".into(),
            ));
        }
        let e = sub(b2, b0);
        let ee = dot(&e, &e);
        let radius_ok = (T::from_i64(4) * dot(b, b) - &ee).is_zero_within(tol);
        if ee.is_zero_within(tol) || !dot(b, &e).is_zero_within(tol) || !radius_ok {
            return Err(Error::Domain(
                "the direction b must be perpendicular to b̄₂ − b̄₀ with |b| = |b̄₂ − b̄₀|/2".into(),
            ));
        }
        let mut a1: Vec<T> = b.to_vec();
        a1.push(T::zero());
        Ok(QuadArc {
            ctrl: [
                HPoint::from_cartesian(b0),
                HPoint { coords: a1 },
                HPoint::from_cartesian(b2),
            ],
        })
    }
}

/// `a − b` coordinatewise.
fn sub<T: Scalar>(a: &[T], b: &[T]) -> Vec<T> {
    a.iter().zip(b).map(|(x, y)| x.clone() - y).collect()
}

/// The dot product `a·b`.
fn dot<T: Scalar>(a: &[T], b: &[T]) -> T {
    a.iter()
        .zip(b)
        .fold(T::zero(), |acc, (x, y)| acc + &(x.clone() * y))
}

/// # The cubic family (ring operations only)
impl<T: Scalar> QuadArc<T> {
    /// The non-standard quadratic with weight ratio `σ = p/q`: homogeneous
    /// control points `q²A₀, pq·A₁, p²A₂`, i.e. weights proportional to
    /// `1, cσ, σ²`, so `ω̄₁/ω̄₀ = cσ`, `ω̄₁/ω̄₂ = c/σ` (source 004 eqs. 3, 4);
    /// for θ = π, scaled by `1/(pq)`, `ω̄₀ = 1/σ`, `ω̄₂ = σ` and the direction
    /// `b` with coefficient 1 (eq. 5). It traces the arc with the same
    /// parameterization as [`QuadArc::cubic_hom`]`(p, q)`.
    ///
    /// ```
    /// use exact_bezier::{arc::QuadArc, ratio, Tolerance};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let arc = QuadArc::from_ends(&p(0, 0), &p(2, 0), &ratio(3, 5), &ratio(4, 5), Tolerance::EXACT).unwrap();
    /// let quad = arc.nonstandard_quadratic(&ratio(2, 1), &ratio(1, 1));
    /// assert_eq!(quad.weights(), vec![ratio(1, 1), ratio(6, 5), ratio(4, 1)]); // 1, cσ, σ²
    /// ```
    pub fn nonstandard_quadratic(&self, p: &T, q: &T) -> RationalCurve<T> {
        let [a0, a1, a2] = &self.ctrl;
        let ctrl = vec![
            a0.scale(&(q.clone() * q)),
            a1.scale(&(p.clone() * q)),
            a2.scale(&(p.clone() * p)),
        ];
        RationalCurve::from_hom(ctrl).expect("three points of one dimension")
    }

    /// The cubic of the family with `σ = p/q`, with the common factor `p²q²`
    /// (see the module docs): `L(u)·Q̄(u)` with `Q̄` the
    /// [`nonstandard_quadratic`](QuadArc::nonstandard_quadratic) and
    /// `L(u) = p²(1 − u) + q²u`. Ring operations only, so it runs on symbols.
    ///
    /// ```
    /// use exact_bezier::{arc::QuadArc, ratio, Tolerance};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let arc = QuadArc::semicircle(&p(0, 0), &p(2, 0), &p(0, 1), Tolerance::EXACT).unwrap();
    /// let (two, one) = (ratio(2, 1), ratio(1, 1));
    /// let cubic = arc.cubic_hom(&two, &one);
    /// let quad = arc.nonstandard_quadratic(&two, &one);
    /// // Same point at every parameter: cubic = L·quadratic.
    /// let u = ratio(1, 3);
    /// assert_eq!(cubic.eval(&u).unwrap(), quad.eval(&u).unwrap());
    /// assert_eq!(cubic.weights()[0], ratio(4, 1)); // the factor p²q²
    /// ```
    pub fn cubic_hom(&self, p: &T, q: &T) -> RationalCurve<T> {
        let [a0, a1, a2] = &self.ctrl;
        let third = ratio::<T>(1, 3);
        let (p2, q2) = (p.clone() * p, q.clone() * q);
        let (p3, q3) = (p2.clone() * p, q2.clone() * q);
        let pq2 = p2 * &q2;
        let c1 = a1
            .scale(&(T::from_i64(2) * &p3))
            .add(&a0.scale(&q3))
            .scale(&(q.clone() * &third));
        let c2 = a2
            .scale(&p3)
            .add(&a1.scale(&(T::from_i64(2) * &q3)))
            .scale(&(p.clone() * &third));
        let ctrl = vec![a0.scale(&pq2), c1, c2, a2.scale(&pq2)];
        RationalCurve::from_hom(ctrl).expect("four points of one dimension")
    }
}

/// # The standard cubic (division at the end)
impl<T: Field> QuadArc<T> {
    /// The standard-form cubic (`ω₀ = ω₃ = 1`) with weight ratio `σ > 0`:
    ///
    /// ```text
    /// ω₁ = (2cσ + σ⁻²)/3,  ω₂ = (σ² + 2c/σ)/3,
    /// b₁* = (b̄₀ + 2cσ³·b̄₁)/(1 + 2cσ³),  b₂* = (σ³·b̄₂ + 2c·b̄₁)/(σ³ + 2c)
    /// ```
    ///
    /// which is source 004 eq. (1) with `σ³ = N/D` (and eq. 2 for θ = π).
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] if `σ = 0`.
    ///
    /// # Examples
    ///
    /// The semicircle of source 004 §1 (θ = π, c = 0) with `σ = 2`
    /// (λ = 1 − σ³ = −7): `ω₁ = σ⁻²/3 = 1/12`, `ω₂ = σ²/3 = 4/3`.
    ///
    /// ```
    /// use exact_bezier::{arc::QuadArc, ratio, Tolerance};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let arc = QuadArc::semicircle(&p(0, 0), &p(2, 0), &p(0, 1), Tolerance::EXACT).unwrap();
    /// let cubic = arc.standard_cubic(&ratio(2, 1)).unwrap();
    /// assert_eq!(cubic.weights(), vec![ratio(1, 1), ratio(1, 12), ratio(4, 3), ratio(1, 1)]);
    /// ```
    pub fn standard_cubic(&self, sigma: &T) -> Result<RationalCurve<T>, Error> {
        if sigma.is_zero() {
            return Err(Error::Domain("the weight ratio σ must not be 0".into()));
        }
        let scale = (sigma.clone() * sigma).recip();
        Ok(self.cubic_hom(sigma, &T::one()).scale_weights(&scale))
    }
}

/// The factors `N = 1 − λk`, `D = 1 + 2λck`, `E = 1 − λ(1 − 4c²)` of
/// source 004 eq. (1), `k = 1 + 2c`; `σ³ = N/D`, `N + 2cD = kE`.
#[derive(Clone, Debug, PartialEq)]
pub struct LambdaFactors<T> {
    /// `N = 1 − λ(1 + 2c)`.
    pub n: T,
    /// `D = 1 + 2λc(1 + 2c)`.
    pub d: T,
    /// `E = 1 − λ(1 − 4c²)`.
    pub e: T,
}

impl<T: Scalar> LambdaFactors<T> {
    /// The factors for `c = cos(θ/2)` and `λ`.
    ///
    /// ```
    /// use exact_bezier::{arc::LambdaFactors, ratio};
    /// use exact_bezier::BigRational;
    /// let f = LambdaFactors::new(&ratio::<BigRational>(1, 2), &ratio(1, 5));
    /// assert_eq!((f.n, f.d, f.e), (ratio(3, 5), ratio(7, 5), ratio(1, 1)));
    /// ```
    pub fn new(c: &T, lambda: &T) -> Self {
        let one = T::one();
        let k = one.clone() + &(T::from_i64(2) * c);
        let lk = lambda.clone() * &k;
        LambdaFactors {
            n: one.clone() - &lk,
            d: one.clone() + &(T::from_i64(2) * c * &lk),
            e: one.clone() - &(lambda.clone() * &(one - &(T::from_i64(4) * c * c))),
        }
    }
}

/// The admissible interval of λ for `c = cos(θ/2) ∈ (−1/2, 1)` (source 004
/// eq. 1): `(−1/(2ck), 1/k)` for `c > 0` (0 < θ < π), `(−∞, 1/(1 − 4c²))`
/// for `c ≤ 0` (π ≤ θ < 4π/3); `None` stands for −∞. It is exactly the set
/// where `N, D, E > 0` (all weights positive; proved in `proofs/src/hang_li.rs`).
///
/// # Errors
///
/// [`Error::Domain`] if `c ∉ (−1/2, 1)`, i.e. `θ ∉ (0, 4π/3)`.
///
/// ```
/// use exact_bezier::{arc::lambda_interval, ratio};
/// use exact_bezier::BigRational;
/// assert_eq!(lambda_interval(&ratio::<BigRational>(1, 2)).unwrap(), (Some(ratio(-1, 2)), ratio(1, 2)));
/// assert_eq!(lambda_interval(&ratio::<BigRational>(0, 1)).unwrap(), (None, ratio(1, 1)));
/// ```
pub fn lambda_interval<T: Ordered>(c: &T) -> Result<(Option<T>, T), Error> {
    let (one, two) = (T::one(), T::from_i64(2));
    if !(c.clone() * &two > -one.clone() && *c < one) {
        return Err(Error::Domain(format!(
            "cos(θ/2) = {} must lie in (−1/2, 1): the centre angle θ must lie in (0, 4π/3)",
            c.to_f64()
        )));
    }
    let k = one.clone() + &(two.clone() * c);
    if *c > T::zero() {
        Ok((Some(-(two * c * &k).recip()), k.recip()))
    } else {
        Ok((None, (one - &(T::from_i64(4) * c * c)).recip()))
    }
}

/// Check that λ is admissible for `c`: `N, D, E > 0`.
///
/// # Errors
///
/// [`Error::Domain`] naming the interval of [`lambda_interval`].
///
/// ```
/// use exact_bezier::{arc::check_lambda, ratio};
/// use exact_bezier::BigRational;
/// let c = ratio::<BigRational>(1, 2); // θ = 2π/3: λ ∈ (−1/2, 1/2)
/// assert!(check_lambda(&c, &ratio(2, 5)).is_ok());
/// assert!(check_lambda(&c, &ratio(1, 2)).is_err());
/// ```
pub fn check_lambda<T: Ordered>(c: &T, lambda: &T) -> Result<(), Error> {
    let (lo, hi) = lambda_interval(c)?;
    let f = LambdaFactors::new(c, lambda);
    let zero = T::zero();
    if f.n > zero && f.d > zero && f.e > zero {
        return Ok(());
    }
    let lo = lo.map_or("−∞".to_string(), |x| x.to_f64().to_string());
    Err(Error::Domain(format!(
        "λ = {} is outside the admissible interval ({lo}, {}) for cos(θ/2) = {}",
        lambda.to_f64(),
        hi.to_f64(),
        c.to_f64()
    )))
}

/// The weight ratio `σ = ∛(N/D)` of λ (source 004 eq. 3 divided by `c`).
///
/// # Errors
///
/// As [`check_lambda`]; [`Error::NotRational`] when `N/D` has no exact cube
/// root in `T` (exact scalars).
///
/// ```
/// use exact_bezier::{arc::sigma_of_lambda, ratio};
/// use exact_bezier::BigRational;
/// // θ = π: σ³ = 1 − λ.
/// assert_eq!(sigma_of_lambda(&ratio::<BigRational>(0, 1), &ratio(-7, 1)).unwrap(), ratio(2, 1));
/// assert!(sigma_of_lambda(&ratio::<BigRational>(0, 1), &ratio(1, 5)).is_err());
/// ```
pub fn sigma_of_lambda<T: Roots>(c: &T, lambda: &T) -> Result<T, Error> {
    check_lambda(c, lambda)?;
    let f = LambdaFactors::new(c, lambda);
    let cube = f.n / &f.d;
    cube.nth_root(3).ok_or_else(|| {
        Error::NotRational(format!("σ = ∛(N/D) = ∛({}) is irrational", cube.to_f64()))
    })
}

/// λ from the cube `m = σ³` of the weight ratio: `λ = (1 − m)/(k(1 + 2cm))`
/// (the inverse of `σ³ = N/D`; source 004 eq. 7 with `m = μ√μ(1/ū − 1)³`).
///
/// # Errors
///
/// [`Error::Domain`] when `k(1 + 2cm) = 0`.
///
/// ```
/// use exact_bezier::{arc::lambda_of_sigma_cubed, ratio};
/// use exact_bezier::BigRational;
/// assert_eq!(lambda_of_sigma_cubed(&ratio::<BigRational>(1, 2), &ratio(3, 7)).unwrap(), ratio(1, 5));
/// ```
pub fn lambda_of_sigma_cubed<T: Field>(c: &T, m: &T) -> Result<T, Error> {
    let one = T::one();
    let two = T::from_i64(2);
    let k = one.clone() + &(two.clone() * c);
    let den = k * &(one.clone() + &(two * c * m));
    if den.is_zero() {
        return Err(Error::Domain("λ is infinite for this σ³".into()));
    }
    Ok((one - m) / &den)
}

/// # The λ-family
impl<T: Roots> QuadArc<T> {
    /// The standard-form cubic of source 004 eq. (1) (eq. (2) for θ = π) for
    /// `λ`: `σ = ∛(N/D)` ([`sigma_of_lambda`]), then
    /// [`standard_cubic`](Self::standard_cubic). Exact over
    /// [`RealAlgebraic`](crate::algebra::RealAlgebraic) for every admissible
    /// λ; over `BigRational` only when σ is rational.
    ///
    /// # Errors
    ///
    /// [`Error::Domain`] if θ ∉ (0, 4π/3) or λ is not admissible;
    /// [`Error::NotRational`] over `BigRational` when σ is irrational.
    ///
    /// ```
    /// use exact_bezier::{algebra::RealAlgebraic, arc::QuadArc, ratio, Scalar, Tolerance};
    /// use exact_bezier::BigRational;
    /// let p = |x: i64, y: i64| vec![ratio::<BigRational>(x, 1), ratio(y, 1)];
    /// let arc = QuadArc::semicircle(&p(0, 0), &p(2, 0), &p(0, 1), Tolerance::EXACT).unwrap();
    /// assert!(arc.cubic_for_lambda(&ratio(-7, 1)).is_ok());                // σ³ = 8
    /// assert!(arc.cubic_for_lambda(&ratio(1, 5)).is_err());                // σ³ = 4/5
    /// assert!(arc.cubic_for_lambda(&ratio(1, 1)).is_err());                // λ < 1 needed
    /// // Over the real algebraic numbers every admissible λ is exact:
    /// // ω₂ = σ²/3 = ∛(16/25)/3 at λ = 1/5.
    /// let exact = arc.map(RealAlgebraic::from_rational);
    /// let cubic = exact.cubic_for_lambda(&RealAlgebraic::from_rational(&ratio(1, 5))).unwrap();
    /// assert_eq!(cubic.weights()[2], "cbrt(16/25)/3".parse::<RealAlgebraic>().unwrap());
    /// ```
    pub fn cubic_for_lambda(&self, lambda: &T) -> Result<RationalCurve<T>, Error> {
        self.standard_cubic(&sigma_of_lambda(self.cos_half(), lambda)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn q(p: i64, d: i64) -> BigRational {
        ratio(p, d)
    }

    #[test]
    fn cube_roots_exact_and_signed() {
        assert_eq!(q(-8, 27).nth_root(3), Some(q(-2, 3)));
        assert_eq!(q(4, 1).nth_root(3), None);
        assert_eq!(q(64, 1).nth_root(6), Some(q(2, 1)));
    }

    #[test]
    fn interval_matches_signs_of_factors() {
        for c in [q(1, 2), q(3, 5), q(-1, 4), q(0, 1), q(9, 10)] {
            let (lo, hi) = lambda_interval(&c).unwrap();
            let inside = |l: &BigRational| check_lambda(&c, l).is_ok();
            assert!(!inside(&hi));
            assert!(inside(&(hi.clone() - q(1, 1000))));
            match lo {
                Some(lo) => {
                    assert!(!inside(&lo));
                    assert!(inside(&(lo + q(1, 1000))));
                }
                None => assert!(inside(&q(-1_000_000, 1))),
            }
        }
        assert!(lambda_interval(&q(-1, 2)).is_err());
    }

    #[test]
    fn standard_cubic_has_unit_end_weights() {
        let p = |x: i64, y: i64| vec![q(x, 1), q(y, 1)];
        let arc =
            QuadArc::from_ends(&p(0, 0), &p(2, 0), &q(3, 5), &q(4, 5), Tolerance::EXACT).unwrap();
        let cubic = arc.standard_cubic(&q(3, 2)).unwrap();
        let w = cubic.weights();
        assert_eq!((w[0].clone(), w[3].clone()), (q(1, 1), q(1, 1)));
        // Same points as the quadratic at the matching parameter: s/(1−s) = σ·u/(1−u).
        let u = q(1, 3);
        let s = q(3, 7); // σu/(1−u) = 3/4 ⇒ s = 3/7
        assert_eq!(cubic.eval(&u).unwrap(), arc.to_curve().eval(&s).unwrap());
    }
}
