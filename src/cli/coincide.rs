//! `coincide A B [--filtered] [--scalar f64 --tol T]`: are two curves or
//! rect patches the same up to Möbius maps, reversal, swapping, elevation,
//! common factors and weight scaling? Exit 0 either way.

use super::{load_one, ScalarKind};
use crate::error::Error;
use crate::interval::coincide_filtered;
use crate::io::Patch;
use crate::scalar::Tolerance;
use num_rational::BigRational;
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

/// Read exactly one curve or patch from `path`.
fn one_patch(path: &str) -> Result<Patch<BigRational>, Error> {
    load_one(path, |n| {
        format!("{path} holds {n} patches; coincide compares one with one")
    })
}

pub fn run(a: &Args) -> Result<Value, Error> {
    let (pa, pb) = (one_patch(&a.a)?, one_patch(&a.b)?);
    match a.scalar {
        ScalarKind::F64 => {
            if a.filtered {
                return Err(Error::Domain(
                    "--filtered is the exact predicate: it does not combine with --scalar f64"
                        .into(),
                ));
            }
            let tol = a.tol.unwrap_or(Tolerance::default().0);
            if !tol.is_finite() || tol < 0.0 {
                return Err(Error::Domain(format!(
                    "--tol {tol} must be a finite number ≥ 0"
                )));
            }
            let c = crate::coincide::coincide_f64(&pa.to_f64(), &pb.to_f64(), Tolerance(tol))?;
            let mut v = c.to_json();
            v["tolerance"] = tol.into();
            Ok(v)
        }
        ScalarKind::Exact => {
            if a.tol.is_some() {
                return Err(Error::Domain(
                    "--tol applies to --scalar f64 only: the exact decision has no tolerance"
                        .into(),
                ));
            }
            if a.filtered {
                let (c, by) = coincide_filtered(&pa, &pb)?;
                let mut v = c.to_json();
                v["decided_by"] = format!("{by:?}").to_lowercase().into();
                Ok(v)
            } else {
                Ok(crate::coincide::coincide(&pa, &pb)?.to_json())
            }
        }
    }
}
