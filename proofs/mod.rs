//! The claims of the sources, and our own theorems, established by
//! computation.
//!
//! One file per claim family. Each family is a function returning its
//! [`Claim`]s; every verdict is **computed** — by the symbolic scalar
//! ([`Poly`]) for identities that must hold for all symbol
//! values, by exact rationals for printed examples. A claim the computation
//! refutes is kept with its counterexample and the corrected statement: that
//! is a result, not a failure. Each claim also records the verdict we
//! expect, so `exact-bezier prove` (and `cargo test`) fail if a computation
//! ever changes its answer.
//!
//! Verdicts: `proved` (identity holds for all values), `refuted` (the printed
//! claim is false; `detail` has the counterexample and the correction),
//! `reproduced` (a printed number agrees with ours), `mismatch` (it does not;
//! `detail` has both values).

use crate::poly::Poly;
use serde_json::{json, Value};
use std::fmt;

pub mod bernstein;
pub mod blossoms;
pub mod calculus;
pub mod coincide;
pub mod conversions;
pub mod curves;
pub mod hang_li;
pub mod hang_li_tables;
pub mod lecture_joins;
pub mod nurbs;
pub mod quiz;
pub mod reduction;
pub mod surfaces;
pub mod triangles;
pub mod trig_basis;
pub mod trig_rational;
pub mod trig_stitching;
pub mod yang_yong;
pub mod yang_yong_examples;
pub mod zhang_chen_feng;

/// The outcome of checking one claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The identity holds for all values of its symbols.
    Proved,
    /// The claim is false as printed.
    Refuted,
    /// A printed number or table entry agrees with our computation.
    Reproduced,
    /// A printed number or table entry disagrees with our computation.
    Mismatch,
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Verdict::Proved => "proved",
            Verdict::Refuted => "refuted",
            Verdict::Reproduced => "reproduced",
            Verdict::Mismatch => "mismatch",
        })
    }
}

/// One checked claim.
#[derive(Clone, Debug, PartialEq)]
pub struct Claim {
    /// The statement, in words and formulas.
    pub claim: String,
    /// Where it comes from: seed file and equation/section, or `"ours"`.
    pub source: String,
    /// The computed verdict.
    pub verdict: Verdict,
    /// The verdict this project expects (a regression guard).
    pub expected: Verdict,
    /// Counterexample, both values, or how it was established.
    pub detail: String,
}

impl Claim {
    /// A claim whose truth is the boolean `holds`: `Proved` or `Refuted`.
    pub fn check(
        claim: &str,
        source: &str,
        expected: Verdict,
        holds: bool,
        detail: String,
    ) -> Claim {
        Claim {
            claim: claim.into(),
            source: source.into(),
            verdict: if holds {
                Verdict::Proved
            } else {
                Verdict::Refuted
            },
            expected,
            detail,
        }
    }

    /// The identity `lhs == rhs` of polynomials: `Proved` when they are equal
    /// for all symbol values, else `Refuted` with the difference in `detail`.
    pub fn identity(
        claim: &str,
        source: &str,
        expected: Verdict,
        lhs: &Poly,
        rhs: &Poly,
        how: &str,
    ) -> Claim {
        let diff = lhs.clone() - rhs;
        let detail = if num_traits::Zero::is_zero(&diff) {
            how.to_string()
        } else {
            format!("{how}; lhs − rhs = {}", abbreviate(&diff.to_string()))
        };
        Claim::check(
            claim,
            source,
            expected,
            num_traits::Zero::is_zero(&diff),
            detail,
        )
    }

    /// A printed value compared with ours: `Reproduced` or `Mismatch`.
    pub fn compare(
        claim: &str,
        source: &str,
        expected: Verdict,
        agrees: bool,
        printed: &str,
        ours: &str,
    ) -> Claim {
        Claim {
            claim: claim.into(),
            source: source.into(),
            verdict: if agrees {
                Verdict::Reproduced
            } else {
                Verdict::Mismatch
            },
            expected,
            detail: format!("printed {printed}; ours {ours}"),
        }
    }

    /// Does the computed verdict match the expected one?
    pub fn as_expected(&self) -> bool {
        self.verdict == self.expected
    }

    /// The `prove --json` object: `claim`, `source`, `verdict`, `detail`
    /// (and `expected`).
    pub fn to_json(&self) -> Value {
        json!({
            "claim": self.claim,
            "source": self.source,
            "verdict": self.verdict.to_string(),
            "expected": self.expected.to_string(),
            "detail": self.detail,
        })
    }
}

/// Shorten a long formula for a one-line detail.
pub fn abbreviate(text: &str) -> String {
    const MAX: usize = 300;
    if text.chars().count() <= MAX {
        text.to_string()
    } else {
        let head: String = text.chars().take(MAX).collect();
        format!("{head} … ({} characters)", text.chars().count())
    }
}

/// A named family of claims.
pub struct Family {
    /// File name in `proofs/` without `.rs`.
    pub name: &'static str,
    /// Computes the family's claims.
    pub run: fn() -> Vec<Claim>,
}

/// Every family, in report order.
#[rustfmt::skip]
pub const FAMILIES: &[Family] = &[
    Family { name: "quiz", run: quiz::claims },
    Family { name: "bernstein", run: bernstein::claims },
    Family { name: "curves", run: curves::claims },
    Family { name: "lecture_joins", run: lecture_joins::claims },
    Family { name: "reduction", run: reduction::claims },
    Family { name: "trig_basis", run: trig_basis::claims },
    Family { name: "trig_stitching", run: trig_stitching::claims },
    Family { name: "trig_rational", run: trig_rational::claims },
    Family { name: "hang_li", run: hang_li::claims },
    Family { name: "hang_li_tables", run: hang_li_tables::claims },
    Family { name: "surfaces", run: surfaces::claims },
    Family { name: "yang_yong", run: yang_yong::claims },
    Family { name: "yang_yong_examples", run: yang_yong_examples::claims },
    Family { name: "zhang_chen_feng", run: zhang_chen_feng::claims },
    Family { name: "triangles", run: triangles::claims },
    Family { name: "blossoms", run: blossoms::claims },
    Family { name: "conversions", run: conversions::claims },
    Family { name: "coincide", run: coincide::claims },
    Family { name: "nurbs", run: nurbs::claims },
];

/// Run every family (in parallel threads) and return the claims in order.
pub fn run_all() -> Vec<(&'static str, Vec<Claim>)> {
    std::thread::scope(|scope| {
        let handles: Vec<_> = FAMILIES
            .iter()
            .map(|f| (f.name, scope.spawn(f.run)))
            .collect();
        handles
            .into_iter()
            .map(|(name, h)| {
                let claims = h.join().unwrap_or_else(|_| {
                    vec![Claim {
                        claim: format!("family {name} runs to completion"),
                        source: "ours".into(),
                        verdict: Verdict::Refuted,
                        expected: Verdict::Proved,
                        detail: "the family panicked".into(),
                    }]
                });
                (name, claims)
            })
            .collect()
    })
}
