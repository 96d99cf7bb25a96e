//! `intersect A [B] [--filtered] [--scalar f64 --tol T]`: the intersections
//! of two curves, or the self-intersections of one, exactly by default.
//!
//! Output (exact): `{"intersections": [{"s", "t", "point", "approx",
//! "multiplicity", "contact", "contact_order"?}], "overlaps": [{"s": [s0, s1],
//! "t": [t0, t1], "map", "mobius": [a, b, c, d]}]}` with parameters and
//! points in the algebraic number grammar (docs/FORMAT.md), `approx` their
//! `f64` values. `--filtered`: where `f64` interval arithmetic decides,
//! `{"crossings": [{"s": [lo, hi], "t": [lo, hi], "point": [[lo, hi], …]}],
//! "decided_by": "intervals"}` (certified boxes, one transversal crossing
//! each, no other common point); otherwise the exact output with
//! `"decided_by": "exact"`. With `--scalar f64`:
//! `{"intersections": [{"s", "t", "point", "distance"}], "overlaps":
//! [{"s": [s0, s1], "t": [t0, t1]}], "tolerance"}` as numbers.

use super::deriv::curve_of;
use super::{load_one, patch_f64, ScalarKind};
use exact_bezier::algebra::{Interval, Ordered, RealAlgebraic};
use exact_bezier::curve::RationalCurve;
use exact_bezier::intersect::{
    intersect, ApproxIntersection, CertifiedCrossing, Contact, Filter, Found, IntersectionPoint,
    Intersections, Options, Overlap,
};
use exact_bezier::io::JsonScalar;
use exact_bezier::limits::{self, Size};
use exact_bezier::{Error, Patch, Tolerance};
use num_rational::BigRational;
use serde_json::{json, Value};

/// Arguments of `intersect`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// First curve (JSON), or - for standard input.
    a: String,
    /// Second curve (JSON); without it, the self-intersections of the first.
    b: Option<String>,
    /// Scalar to compute with (exact by default).
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
    /// Tolerance for --scalar f64 (absolute, model units); default 1e-9.
    #[arg(long)]
    tol: Option<f64>,
    /// Decide in f64 interval arithmetic where it can (certified boxes of
    /// transversal crossings, or separation), exactly otherwise; adds
    /// "decided_by".
    #[arg(long)]
    filtered: bool,
}

/// Estimated `(operations, bits)` of the exact elimination for curves of
/// degrees `m`, `n`: `D + 1 = 2mn + 1` Sylvester determinants of size
/// `2n`, root isolation of a degree-`D` polynomial (`D³`), on numbers of
/// about `(m + n)·bits` bits. The `f64` search is charged these operations
/// ([`limits::f64_work`]).
fn intersect_cost(a: &Size, b: &Size) -> (u64, u64) {
    let (m, n) = (a.degree.0 as u64, b.degree.0 as u64);
    let d = 2 * m * n + 1;
    let size = 2 * m.max(n) + 2;
    (
        d * size.pow(3) * (a.dim as u64 + 1) + d.pow(3),
        (a.bits + b.bits + 64).saturating_mul(m + n),
    )
}

/// The exact work of the elimination: [`intersect_cost`]'s operations
/// times `mn/64` (the `mn` roots, each an algebraic number of degree up to
/// `mn` isolated by Descartes counts, its point's coordinates by `mn + 1`
/// norms; calibrated, `cli/benches/cost_model.rs`, 2026-11-27: two cubics
/// take 1.1 ms, two sextics 0.31 s, where the Sturm sequences and
/// Sylvester value resultants before took 4.1 ms and 31 s and were
/// charged `(mn)³/4096`).
fn exact_cost(a: &Size, b: &Size) -> u64 {
    let (ops, bits) = intersect_cost(a, b);
    let roots = a.degree.0 as u64 * b.degree.0 as u64;
    limits::exact_work(ops.saturating_mul(roots).div_ceil(64), bits)
}

/// The work of the interval stage of `--filtered` (charged before it
/// runs; the exact path is charged only if it is needed): at most 16
/// levels of 1024 piece pairs, charged two interval de Casteljau splits
/// of `(n + 1)²` operations per coordinate a pair. Since 2026-11-27 a
/// level splits each of its pieces once (at most 1024 a curve) and
/// computes its velocity hull once, then runs one Krawczyk test per pair:
/// less work than the per-pair splits and hulls the bound was calibrated
/// on, so it still bounds the stage.
fn filter_cost(a: &Size, b: &Size) -> u64 {
    let split = |s: &Size| (s.degree.0 as u64 + 1).pow(2) * (s.dim as u64 + 1);
    (16 * 1024 * 2 * (split(a) + split(b))).div_ceil(64)
}

/// Read one curve from `path`.
fn one_curve(path: &str) -> Result<RationalCurve<BigRational>, Error> {
    let p = load_one(path, |n| {
        format!("{path} holds {n} patches; intersect takes one curve per file")
    })?;
    curve_of(&p, "intersect").cloned()
}

pub fn run(a: &Args) -> Result<Value, Error> {
    let ca = one_curve(&a.a)?;
    let cb = a.b.as_deref().map(one_curve).transpose()?;
    let other = cb.as_ref().unwrap_or(&ca);
    let (sa, sb) = (
        Patch::Curve(ca.clone()).size(),
        Patch::Curve(other.clone()).size(),
    );
    let (ops, _) = intersect_cost(&sa, &sb);
    match a.scalar {
        ScalarKind::F64 => run_f64(a, &ca, cb.as_ref(), ops),
        ScalarKind::Exact => {
            if a.tol.is_some() {
                return Err(Error::Domain(
                    "--tol applies to --scalar f64 only: the exact intersection has no tolerance"
                        .into(),
                ));
            }
            if a.filtered {
                let Some(b) = &cb else {
                    return Err(Error::Domain(
                        "--filtered separates two curves: it needs a second curve".into(),
                    ));
                };
                limits::charge("intersect --filtered", filter_cost(&sa, &sb))?;
                let only = Options {
                    filter: Filter::Only,
                    ..Options::default()
                };
                if let Found::Certified(found) = intersect(&ca, Some(b), only)? {
                    return Ok(certified_json(&found));
                }
            }
            limits::charge("intersect", exact_cost(&sa, &sb))?;
            let found = intersect(&ca, cb.as_ref(), Options::default())?;
            let mut v = to_json(&found.exact().expect("the exact elimination decides"));
            if a.filtered {
                v["decided_by"] = "exact".into();
            }
            Ok(v)
        }
    }
}

fn run_f64(
    a: &Args,
    ca: &RationalCurve<BigRational>,
    cb: Option<&RationalCurve<BigRational>>,
    ops: u64,
) -> Result<Value, Error> {
    if a.filtered {
        return Err(Error::Domain(
            "--filtered is the exact predicate: it does not combine with --scalar f64".into(),
        ));
    }
    let Some(cb) = cb else {
        return Err(Error::Domain(
            "self-intersections are exact only: drop --scalar f64".into(),
        ));
    };
    let tol = a.tol.unwrap_or(1e-9);
    limits::charge("intersect", limits::f64_work(ops))?;
    let as_f64 = |c: &RationalCurve<BigRational>| match patch_f64(&Patch::Curve(c.clone()))? {
        Patch::Curve(c) => Ok(c),
        _ => unreachable!("a curve maps to a curve"),
    };
    let options = Options {
        tol: Tolerance(tol),
        ..Options::default()
    };
    let found = intersect(&as_f64(ca)?, Some(&as_f64(cb)?), options)?;
    let (overlaps, points): (Vec<&ApproxIntersection>, Vec<_>) =
        found.iter().partition(|x| x.overlap.is_some());
    Ok(json!({
        "intersections": points.iter().map(|x| json!({
            "s": x.s, "t": x.t, "point": x.point, "distance": x.distance,
        })).collect::<Vec<_>>(),
        "overlaps": overlaps.iter().filter_map(|x| x.overlap).map(|r| json!({
            "s": [r[0], r[1]], "t": [r[2], r[3]],
        })).collect::<Vec<_>>(),
        "tolerance": tol,
    }))
}

fn contact_name(c: &Contact) -> &'static str {
    match c {
        Contact::Transversal => "transversal",
        Contact::Tangential { .. } => "tangential",
        Contact::Singular => "singular",
        Contact::Cusp => "cusp",
        Contact::Continuation => "continuation",
    }
}

fn point_json(p: &IntersectionPoint) -> Value {
    let approx = |x: &RealAlgebraic| x.to_f64();
    let mut v = json!({
        "s": p.s.to_json(),
        "t": p.t.to_json(),
        "point": p.point.iter().map(RealAlgebraic::to_json).collect::<Vec<_>>(),
        "approx": {
            "s": approx(&p.s),
            "t": approx(&p.t),
            "point": p.point.iter().map(approx).collect::<Vec<_>>(),
        },
        "multiplicity": p.multiplicity,
        "contact": contact_name(&p.contact),
    });
    if let Contact::Tangential { order } = p.contact {
        v["contact_order"] = order.into();
    }
    v
}

fn overlap_json(o: &Overlap) -> Value {
    let [a, b, c, d] = &o.map.coeffs;
    json!({
        "s": [o.s.0.to_json(), o.s.1.to_json()],
        "t": [o.t.0.to_json(), o.t.1.to_json()],
        "map": format!("s = (({a})*t + ({b}))/(({c})*t + ({d}))"),
        "mobius": [a.to_json(), b.to_json(), c.to_json(), d.to_json()],
    })
}

/// `{"crossings": [{"s": [lo, hi], "t": [lo, hi], "point": [[lo, hi], …]}],
/// "decided_by": "intervals"}`: interval bounds as JSON numbers.
fn certified_json(found: &[CertifiedCrossing]) -> Value {
    let pair = |i: &Interval| json!([i.lo, i.hi]);
    json!({
        "crossings": found.iter().map(|k| json!({
            "s": pair(&k.s),
            "t": pair(&k.t),
            "point": k.point.iter().map(pair).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
        "decided_by": "intervals",
    })
}

fn to_json(x: &Intersections) -> Value {
    json!({
        "intersections": x.points.iter().map(point_json).collect::<Vec<_>>(),
        "overlaps": x.overlaps.iter().map(overlap_json).collect::<Vec<_>>(),
    })
}
