//! `eval` for trigonometric patches (source 002): `--at tau=1/3[,tau=1/2]`
//! evaluates exactly at `τ = tan(t/2)`; `--at 0.7[,0.3]` takes angles in
//! radians and evaluates in `f64`.

use super::{one_or_many, ScalarKind};
use crate::algebra::scalar::{Ordered, Scalar};
use crate::error::Error;
use crate::io::trig::TrigPatch;
use crate::io::{parse_rational, point_to_json, JsonScalar};
use crate::trig::basis::TrigParam;
use num_rational::BigRational;
use serde_json::{json, Value};

/// Parsed `--at` values.
enum TrigAt {
    /// `tau=…` values, exact, each in `[0, 1]`.
    Tau(Vec<BigRational>),
    /// Angles in radians, each in `[0, π/2]`.
    Angle(Vec<f64>),
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
