//! `eval` for trigonometric patches (source 002): `--at tau=1/3[,tau=1/2]`
//! evaluates exactly at `τ = tan(t/2)`; `--at angle=pi/3[,angle=pi/4]`
//! exactly at rational multiples of π (multiples of π/12, whose sine and
//! cosine lie in Q(√2, √3), computed as real algebraic numbers); `--at
//! 0.7[,0.3]` takes angles in radians and evaluates in `f64`.
//!
//! ```text
//! cos 0 = 1, cos π/12 = (√6 + √2)/4, cos π/6 = √3/2, cos π/4 = √2/2,
//! cos π/3 = 1/2, cos 5π/12 = (√6 − √2)/4, cos π/2 = 0;  sin t = cos(π/2 − t)
//! ```

use super::{one_or_many, ScalarKind};
use exact_bezier::algebra::parse_rational;
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::algebra::{Ordered, Roots, Scalar};
use exact_bezier::io::{point_to_json, JsonScalar};
use exact_bezier::trig::basis::TrigParam;
use exact_bezier::trig::TrigPatch;
use exact_bezier::Error;
use num_rational::BigRational;
use num_traits::Zero;
use serde_json::{json, Value};

/// Parsed `--at` values.
enum TrigAt {
    /// `tau=…` values, exact, each in `[0, 1]`.
    Tau(Vec<BigRational>),
    /// Angles `k·π/12`, exact, each in `[0, π/2]` (`k` in 0..=6).
    Twelfths(Vec<u32>),
    /// Angles in radians, each in `[0, π/2]`.
    Angle(Vec<f64>),
}

/// `t/π` from `pi`, `pi/m`, `k*pi`, `k*pi/m` or `0` (exact rationals).
fn pi_multiple(text: &str) -> Result<BigRational, Error> {
    let bad = || {
        Error::Format(format!(
            "angle={text} is not of the form k*pi/m (for example angle=pi/3, angle=5*pi/12)"
        ))
    };
    if text == "0" {
        return Ok(BigRational::from_i64(0));
    }
    let (k, rest) = match text.split_once("*") {
        Some((k, rest)) => (parse_rational(k.trim()).map_err(|_| bad())?, rest.trim()),
        None => (BigRational::from_i64(1), text),
    };
    let rest = rest.strip_prefix("pi").ok_or_else(bad)?;
    let m = match rest.strip_prefix('/') {
        Some(m) => parse_rational(m.trim()).map_err(|_| bad())?,
        None if rest.is_empty() => BigRational::from_i64(1),
        None => return Err(bad()),
    };
    if m.is_zero() {
        return Err(bad());
    }
    Ok(k / m)
}

/// `k` with `t = k·π/12`, for `t ∈ [0, π/2]`.
fn twelfths(text: &str) -> Result<u32, Error> {
    let r = pi_multiple(text)?;
    let k = r.clone() * BigRational::from_i64(12);
    if r < BigRational::from_i64(0) || r > BigRational::new(1.into(), 2.into()) {
        return Err(Error::Domain(format!(
            "the angle {text} is outside [0, π/2]"
        )));
    }
    if !k.is_integer() {
        return Err(Error::Domain(format!(
            "angle={text}: exact angles are the multiples of pi/12 (15°), whose sine and cosine are radicals; give tau=… or radians for f64"
        )));
    }
    Ok(k.to_integer().try_into().unwrap_or(0))
}

/// `cos(k·π/12)` for `k` in 0..=6, exactly.
fn cos_twelfth(k: u32) -> RealAlgebraic {
    let q = |n: i64, d: i64| RealAlgebraic::from_rational(&BigRational::new(n.into(), d.into()));
    let sqrt = |n: i64| {
        q(n, 1)
            .nth_root(2)
            .expect("square roots of positive integers exist")
    };
    match k {
        0 => q(1, 1),
        1 => (sqrt(6) + &sqrt(2)) * &q(1, 4),
        2 => sqrt(3) * &q(1, 2),
        3 => sqrt(2) * &q(1, 2),
        4 => q(1, 2),
        5 => (sqrt(6) - &sqrt(2)) * &q(1, 4),
        _ => q(0, 1),
    }
}

/// The exact trig parameter at `k·π/12`.
fn twelfth_param(k: u32) -> TrigParam<RealAlgebraic> {
    TrigParam::new(cos_twelfth(6 - k), cos_twelfth(k))
}

fn parse_at(text: &str) -> Result<TrigAt, Error> {
    let items: Vec<&str> = text.split(',').map(str::trim).collect();
    let taus: Vec<Option<&str>> = items.iter().map(|s| s.strip_prefix("tau=")).collect();
    if taus.iter().all(Option::is_some) {
        let taus = taus
            .into_iter()
            .flatten()
            .map(parse_rational)
            .collect::<Result<Vec<_>, _>>()?;
        if let Some(t) = taus
            .iter()
            .find(|t| **t < BigRational::from_i64(0) || **t > BigRational::from_i64(1))
        {
            return Err(Error::Domain(format!(
                "tau = {t} is outside [0, 1] (t ∈ [0, π/2])"
            )));
        }
        return Ok(TrigAt::Tau(taus));
    }
    if taus.iter().any(Option::is_some) {
        return Err(Error::Format("--at mixes tau=… values and angles".into()));
    }
    let exact: Vec<Option<&str>> = items.iter().map(|s| s.strip_prefix("angle=")).collect();
    if exact.iter().all(Option::is_some) {
        let ks = exact
            .into_iter()
            .flatten()
            .map(twelfths)
            .collect::<Result<_, _>>()?;
        return Ok(TrigAt::Twelfths(ks));
    }
    if exact.iter().any(Option::is_some) {
        return Err(Error::Format(
            "--at mixes angle=… values and other forms".into(),
        ));
    }
    let angles: Vec<f64> = items
        .iter()
        .map(|s| parse_rational(s).map(|q| q.to_f64()))
        .collect::<Result<_, _>>()?;
    if let Some(t) = angles
        .iter()
        .find(|t| !(0.0..=std::f64::consts::FRAC_PI_2).contains(*t))
    {
        return Err(Error::Domain(format!("the angle {t} is outside [0, π/2]")));
    }
    Ok(TrigAt::Angle(angles))
}

fn eval_one<T: JsonScalar>(p: &TrigPatch<T>, at: &[TrigParam<T>]) -> Result<Value, Error> {
    let point = match (p, at) {
        (TrigPatch::Curve(c), [t]) => c.eval(t),
        (TrigPatch::Rect(r), [u, v]) => r.eval(u, v),
        (TrigPatch::Curve(_), _) => {
            return Err(Error::Shape(format!(
                "a trig-curve takes 1 parameter in --at, not {}",
                at.len()
            )))
        }
        (TrigPatch::Rect(_), _) => {
            return Err(Error::Shape(format!(
                "a trig-rect takes 2 parameters in --at, not {}",
                at.len()
            )))
        }
    };
    Ok(json!({ "point": point_to_json(&point) }))
}

/// Evaluate the trig patches at `--at`.
pub fn run(
    patches: &[TrigPatch<BigRational>],
    at: &str,
    scalar: ScalarKind,
) -> Result<Value, Error> {
    let values = match (parse_at(at)?, scalar) {
        (TrigAt::Tau(t), ScalarKind::Exact) => {
            let at: Vec<_> = t.iter().map(TrigParam::from_tau).collect();
            patches
                .iter()
                .map(|p| eval_one(p, &at))
                .collect::<Result<Vec<_>, _>>()?
        }
        (TrigAt::Tau(t), ScalarKind::F64) => {
            let at: Vec<_> = t.iter().map(|x| TrigParam::from_tau(&x.to_f64())).collect();
            patches
                .iter()
                .map(|p| eval_one(&p.to_f64(), &at))
                .collect::<Result<Vec<_>, _>>()?
        }
        (TrigAt::Twelfths(ks), ScalarKind::Exact) => {
            let at: Vec<_> = ks.iter().map(|k| twelfth_param(*k)).collect();
            patches
                .iter()
                .map(|p| eval_one(&p.map(RealAlgebraic::from_rational), &at))
                .collect::<Result<Vec<_>, _>>()?
        }
        (TrigAt::Twelfths(ks), ScalarKind::F64) => {
            let at: Vec<_> = ks
                .iter()
                .map(|k| TrigParam::from_angle(f64::from(*k) * std::f64::consts::PI / 12.0))
                .collect();
            patches
                .iter()
                .map(|p| eval_one(&p.to_f64(), &at))
                .collect::<Result<Vec<_>, _>>()?
        }
        (TrigAt::Angle(t), _) => {
            let at: Vec<_> = t.iter().map(|x| TrigParam::from_angle(*x)).collect();
            patches
                .iter()
                .map(|p| eval_one(&p.to_f64(), &at))
                .collect::<Result<Vec<_>, _>>()?
        }
    };
    Ok(one_or_many(values))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The exact values of `cos(kπ/12)`, `sin(kπ/12)` satisfy sin² + cos² = 1,
    /// the double-angle formulas between `k` and `2k`, and agree with `f64`
    /// (which fixes the signs and the branch).
    #[test]
    fn twelfths_are_sine_and_cosine() {
        let one = RealAlgebraic::from_i64(1);
        let two = RealAlgebraic::from_i64(2);
        for k in 0..=6u32 {
            let p = twelfth_param(k);
            assert_eq!(
                p.sin.clone() * &p.sin + &(p.cos.clone() * &p.cos),
                one,
                "k = {k}"
            );
            let t = f64::from(k) * std::f64::consts::PI / 12.0;
            assert!((p.cos.to_f64() - t.cos()).abs() < 1e-15);
            assert!((p.sin.to_f64() - t.sin()).abs() < 1e-15);
            if k <= 3 {
                let d = twelfth_param(2 * k);
                assert_eq!(
                    d.cos,
                    two.clone() * &p.cos * &p.cos - &one,
                    "cos 2θ, k = {k}"
                );
                assert_eq!(d.sin, two.clone() * &p.sin * &p.cos, "sin 2θ, k = {k}");
            }
        }
    }

    #[test]
    fn angle_text_forms() {
        assert_eq!(twelfths("pi/3").unwrap(), 4);
        assert_eq!(twelfths("5*pi/12").unwrap(), 5);
        assert_eq!(twelfths("1/2*pi").unwrap(), 6);
        assert_eq!(twelfths("0").unwrap(), 0);
        assert!(matches!(twelfths("pi/5"), Err(Error::Domain(_))));
        assert!(matches!(twelfths("2*pi/3"), Err(Error::Domain(_))));
        assert!(matches!(twelfths("pi/0"), Err(Error::Format(_))));
        assert!(matches!(twelfths("tau"), Err(Error::Format(_))));
    }
}
