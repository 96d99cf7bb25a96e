//! `coincide A B [--filtered] [--scalar f64 --tol T]`: are two curves or
//! rect patches the same up to Möbius maps, reversal, swapping, elevation,
//! common factors and weight scaling? Exit 0 either way.

use super::{load_exact, patch_f64, ExactPatches, ExactScalar, ScalarKind};
use exact_bezier::algebra::Tolerance;
use exact_bezier::coincide::{coincide, Options};
use exact_bezier::io::coincidence_to_json;
use exact_bezier::limits::{self, Size};
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use serde_json::Value;

/// Arguments of `coincide`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// First input (JSON, one curve or rect patch), or - for standard input.
    a: String,
    /// Second input (JSON, one curve or rect patch).
    b: String,
    /// Scalar to compute with (exact by default).
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
    /// Tolerance for --scalar f64 (absolute for points, relative for weight
    /// invariants); default 1e-9.
    #[arg(long)]
    tol: Option<f64>,
    /// Exact answer, decided by f64 interval bounds when they can; adds
    /// "decided_by".
    #[arg(long)]
    filtered: bool,
}

/// Estimated `(operations, bits)` of deciding coincidence for a patch of
/// size `s` (canonical forms: polynomial gcds and Möbius solves over the
/// whole net, numbers grown by the total degree N):
/// `(N+1)³(d+1)` operations on `(N+1)·bits`-bit numbers (calibrated,
/// `cli/benches/cost_model.rs`: an elevated copy is reduced first, and
/// most of the work is on the net's own numbers).
pub(super) fn coincide_cost(s: &Size) -> (u64, u64) {
    let n1 = s.total_degree() + 1;
    (
        n1.pow(3) * (s.dim as u64 + 1),
        s.bits.max(8).saturating_mul(n1),
    )
}

/// Charge the decision for `pa` and `pb` ([`coincide_cost`]): both are
/// reduced to their least degree first, and two patches of different least
/// degrees differ, so the canonical forms are charged at the lower of the
/// two degrees, plus for each patch one exact pass over its net that
/// undoes an elevation (`(m+1)(n+1)(N_low+2)(d+1)` operations, as for an
/// elevated copy in `key`). Calibrated by `cli/benches/cost_model.rs`: a
/// (8, 8) net against its (16, 16) elevation took 28 ms, 30 times less than
/// the model at the higher degree.
fn charge_pair<T: ExactScalar>(
    pa: &Patch<T>,
    pb: &Patch<T>,
    scalar: ScalarKind,
) -> Result<(), Error> {
    let (sa, sb) = (pa.size(), pb.size());
    let low = if sa.total_degree() <= sb.total_degree() {
        sa.degree
    } else {
        sb.degree
    };
    // Both patches' numbers in one field: the decision compares them.
    let sizes = [pa.size_with(pb.numbers()), pb.size_with(pa.numbers())];
    let exact = scalar == ScalarKind::Exact;
    limits::charge_sizes("coincide", sizes, exact, |s| pair_cost(s, low))
}

/// The `(operations, bits)` of one side of a decision of size `s` whose
/// canonical forms are computed at degree `low` ([`charge_pair`]): the
/// model of [`coincide_cost`] there, plus the pass that undoes an
/// elevation from `s.degree`.
pub(super) fn pair_cost(s: &Size, low: (usize, usize)) -> (u64, u64) {
    let lower = Size { degree: low, ..*s };
    let (ops, bits) = coincide_cost(&lower);
    let undo = (s.degree.0 as u64 + 1)
        * (s.degree.1 as u64 + 1)
        * (lower.total_degree() + 2)
        * (s.dim as u64 + 1);
    (ops + undo, bits)
}

/// Read exactly one curve or patch from `path` (rational or algebraic).
fn one_patch(path: &str) -> Result<ExactPatches, Error> {
    let patches = load_exact(path)?;
    if patches.len() != 1 {
        return Err(Error::Shape(format!(
            "{path} holds {} patches; coincide compares one with one",
            patches.len()
        )));
    }
    Ok(patches)
}

/// Two rational inputs run on `BigRational` (with `--filtered` available);
/// if either has an algebraic number, both run on `RealAlgebraic`, where
/// `--filtered` is the exact decision itself (`"decided_by": "exact"`).
pub fn run(a: &Args) -> Result<Value, Error> {
    if a.filtered && a.scalar == ScalarKind::F64 {
        return Err(Error::Domain(
            "--filtered is the exact predicate: it does not combine with --scalar f64".into(),
        ));
    }
    if a.tol.is_some() && a.scalar == ScalarKind::Exact {
        return Err(Error::Domain(
            "--tol applies to --scalar f64 only: the exact decision has no tolerance".into(),
        ));
    }
    match (one_patch(&a.a)?, one_patch(&a.b)?) {
        (ExactPatches::Rational(pa), ExactPatches::Rational(pb)) => {
            if a.filtered {
                charge_pair(&pa[0], &pb[0], a.scalar)?;
                let c = coincide(&pa[0], &pb[0], Options::filtered())?;
                let mut v = coincidence_to_json(&c);
                v["decided_by"] = format!("{:?}", c.decided_by).to_lowercase().into();
                return Ok(v);
            }
            decide(a, &pa[0], &pb[0])
        }
        (pa, pb) => {
            let (pa, pb) = (pa.into_algebraic(), pb.into_algebraic());
            let mut v = decide(a, &pa[0], &pb[0])?;
            if a.filtered {
                v["decided_by"] = "exact".into();
            }
            Ok(v)
        }
    }
}

/// The exact decision over `T`, or (with `--scalar f64`) the tolerance one.
///
/// The work is charged with both patches' numbers in one field (the
/// decision compares them), refused over the field degree limit.
fn decide<T: ExactScalar>(a: &Args, pa: &Patch<T>, pb: &Patch<T>) -> Result<Value, Error> {
    charge_pair(pa, pb, a.scalar)?;
    match a.scalar {
        ScalarKind::F64 => {
            let tol = a.tol.unwrap_or(Tolerance::default().0);
            if !tol.is_finite() || tol < 0.0 {
                return Err(Error::Domain(format!(
                    "--tol {tol} must be a finite number ≥ 0"
                )));
            }
            let c = coincide(
                &patch_f64(pa)?,
                &patch_f64(pb)?,
                Options::within(Tolerance(tol)),
            )?;
            let mut v = coincidence_to_json(&c);
            v["tolerance"] = tol.into();
            Ok(v)
        }
        ScalarKind::Exact => Ok(coincidence_to_json(&coincide(pa, pb, Options::default())?)),
    }
}
