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
//! Verdicts (see [`Verdict`]): `proved` (an identity over all symbol
//! values, or exact sampling whose sufficiency follows from a degree bound
//! the code computes and checks), `checked` (exact sampling without such a
//! bound, or an f64 comparison within a stated tolerance), `refuted` (the
//! printed claim is false; `detail` has the counterexample and the
//! correction), `reproduced` / `mismatch` (a printed number agrees with ours
//! or not; `detail` has both values), and `broken` (a precondition of the
//! check itself failed: nothing was decided, and it is never expected).
//!
//! Claims checked for every degree up to a bound say so in their text and
//! carry the bound ([`Claim::bound`](crate::Claim::bound), `degree_bound` in `prove --json`).

use exact_bezier::algebra::Poly;
use serde_json::{json, Value};
use std::cell::Cell;
use std::fmt;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

pub mod analytic;
pub mod bernstein;
pub mod blossoms;
pub mod calculus;
pub mod coincide;
pub mod conversions;
pub mod curves;
pub mod general_degree;
pub mod hang_li;
pub mod hang_li_tables;
pub mod lecture_joins;
pub mod nurbs;
mod printed;
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
    /// The identity holds for all values of its symbols (exact symbolic
    /// computation), or it holds on a sample that is sufficient because of
    /// a degree bound the code computes and checks. A claim about "every
    /// degree" is proved for the degrees its text and bound state.
    Proved,
    /// Holds on every exact sample point without a degree argument that
    /// makes the sample sufficient, or within a stated f64 tolerance:
    /// evidence, not a proof.
    Checked,
    /// The claim is false as printed: the counterexample and the compared
    /// values come from library code.
    Refuted,
    /// A printed number or table entry agrees with our computation.
    Reproduced,
    /// A printed number or table entry disagrees with our computation.
    Mismatch,
    /// A precondition of the check itself failed (its setup is not what the
    /// claim assumes), so nothing was decided. Never an expected verdict.
    Broken,
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Verdict::Proved => "proved",
            Verdict::Checked => "checked",
            Verdict::Refuted => "refuted",
            Verdict::Reproduced => "reproduced",
            Verdict::Mismatch => "mismatch",
            Verdict::Broken => "broken",
        })
    }
}

impl Verdict {
    /// `pass` if the claim holds, else `Refuted`.
    fn decided(holds: bool, pass: Verdict) -> Verdict {
        if holds {
            pass
        } else {
            Verdict::Refuted
        }
    }

    /// Every verdict, in report order.
    pub const ALL: [Verdict; 6] = [
        Verdict::Proved,
        Verdict::Checked,
        Verdict::Refuted,
        Verdict::Reproduced,
        Verdict::Mismatch,
        Verdict::Broken,
    ];
}

/// Set by `prove --deep`: families with a costly degree bound check to a
/// higher one (see [`set_deep`]).
static DEEP: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Check the costly families to their deep bounds (`prove --deep`): the
/// Möbius and scaling point identities and the quadratic-map claims of
/// `yang_yong` to m, n ≤ 10 instead of 5 (about 9 s instead of 0.4 s).
pub fn set_deep(on: bool) {
    DEEP.store(on, std::sync::atomic::Ordering::Relaxed);
}

/// Is the deep mode on ([`set_deep`])?
fn deep() -> bool {
    DEEP.load(std::sync::atomic::Ordering::Relaxed)
}

thread_local! {
    /// When the previous claim of the family running on this thread was
    /// completed (or the family started).
    static LAST_CLAIM: Cell<Option<Instant>> = const { Cell::new(None) };
}

/// Time since the previous claim on this thread was completed; restarts the
/// clock. Claims of a family are computed one after another, so this is the
/// time spent on the claim being built (plus any shared setup before it).
fn lap() -> Duration {
    let now = Instant::now();
    LAST_CLAIM
        .with(|last| last.replace(Some(now)))
        .map_or(Duration::ZERO, |then| now - then)
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
    /// The degree bound checked, for claims about every degree (also stated
    /// in `claim`), e.g. `"n ≤ 12"`.
    pub bound: Option<String>,
    /// Time spent computing the claim (see `lap`).
    pub elapsed: Duration,
}

impl Claim {
    /// The one constructor: stamps the elapsed time.
    fn new(
        claim: &str,
        source: &str,
        verdict: Verdict,
        expected: Verdict,
        detail: String,
    ) -> Claim {
        Claim {
            claim: claim.into(),
            source: source.into(),
            verdict,
            expected,
            detail,
            bound: None,
            elapsed: lap(),
        }
    }

    /// A claim decided exactly (symbolically, or by a sample made
    /// sufficient by a checked degree bound) by the boolean `holds`:
    /// `Proved` or `Refuted`.
    pub fn check(
        claim: &str,
        source: &str,
        expected: Verdict,
        holds: bool,
        detail: String,
    ) -> Claim {
        let verdict = Verdict::decided(holds, Verdict::Proved);
        Claim::new(claim, source, verdict, expected, detail)
    }

    /// A claim tested on samples only (exact points without a sufficiency
    /// argument, or f64 within a tolerance stated in `detail`): `Checked`
    /// when every sample agrees, else `Refuted`.
    pub fn sampled(
        claim: &str,
        source: &str,
        expected: Verdict,
        holds: bool,
        detail: String,
    ) -> Claim {
        Claim::new(
            claim,
            source,
            Verdict::decided(holds, Verdict::Checked),
            expected,
            detail,
        )
    }

    /// The claim, unless the check's own precondition `ok` fails: then the
    /// verdict is `Broken` and `detail` says which precondition (so a broken
    /// setup can never print the expected verdict).
    pub fn given(mut self, ok: bool, precondition: &str) -> Claim {
        if !ok {
            self.verdict = Verdict::Broken;
            self.detail = format!("precondition failed: {precondition}; {}", self.detail);
        }
        self
    }

    /// Record the degree bound checked (also stated in the claim's text).
    pub fn with_bound(mut self, bound: impl Into<String>) -> Claim {
        self.bound = Some(bound.into());
        self
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
        let verdict = if agrees {
            Verdict::Reproduced
        } else {
            Verdict::Mismatch
        };
        Claim::new(
            claim,
            source,
            verdict,
            expected,
            format!("printed {printed}; ours {ours}"),
        )
    }

    /// Does the computed verdict match the expected one?
    pub fn as_expected(&self) -> bool {
        self.verdict == self.expected
    }

    /// The `prove --json` object: `family`, `claim`, `source`, `verdict`,
    /// `expected`, `detail`, `degree_bound` (null when the claim is not
    /// about every degree) and `elapsed_ms`.
    pub fn to_json(&self, family: &str) -> Value {
        json!({
            "family": family,
            "claim": self.claim,
            "source": self.source,
            "verdict": self.verdict.to_string(),
            "expected": self.expected.to_string(),
            "detail": self.detail,
            "degree_bound": self.bound,
            "elapsed_ms": (self.elapsed.as_secs_f64() * 1e6).round() / 1e3,
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

/// Per check, the first `Some` over `items` in their order (like
/// `find_map`), for `K` checks computed together (claims that share one
/// costly computation per item: `check` gives the `K` outcomes of one
/// item). The items are shared out over the available cores as they come:
/// each worker takes the next item not yet taken (so a costly item does not
/// hold back the ones a fixed split would have queued behind it: the
/// bidegrees of `yang_yong` grow in cost, and a split by parity left one
/// core with 59 % of the work) and stops once each check has failed on one
/// of its items. Per check, the failure of least index among the workers'
/// is the first one overall, so the answer does not depend on the timing:
/// items are taken in increasing order, and a worker stops only with a
/// failure of every check at an index below the items it leaves, so the
/// least failing item of each check is always taken and checked.
pub(crate) fn first_failures<T: Sync, R: Send, const K: usize>(
    items: &[T],
    check: impl Fn(&T) -> [Option<R>; K] + Sync,
) -> [Option<R>; K] {
    let workers = std::thread::available_parallelism().map_or(1, |n| n.get());
    let (check, next) = (&check, &AtomicUsize::new(0));
    let none = || std::array::from_fn::<Option<(usize, R)>, K, _>(|_| None);
    std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|_| {
                scope.spawn(move || {
                    let mut found = none();
                    while !found.iter().all(Option::is_some) {
                        let k = next.fetch_add(1, Ordering::Relaxed);
                        if k >= items.len() {
                            break;
                        }
                        for (slot, r) in found.iter_mut().zip(check(&items[k])) {
                            if slot.is_none() {
                                *slot = r.map(|r| (k, r));
                            }
                        }
                    }
                    found
                })
            })
            .collect();
        let mut first = none();
        for h in handles {
            let found = h.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
            for (slot, f) in first.iter_mut().zip(found) {
                if let Some((k, r)) = f
                    && slot.as_ref().is_none_or(|(least, _)| k < *least)
                {
                    *slot = Some((k, r));
                }
            }
        }
        first.map(|f| f.map(|(_, r)| r))
    })
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
    Family { name: "general_degree", run: general_degree::claims },
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
    Family { name: "analytic", run: analytic::claims },
];

/// Run one family, timing each claim.
pub fn run_family(family: &Family) -> Vec<Claim> {
    LAST_CLAIM.with(|last| last.set(Some(Instant::now())));
    (family.run)()
}

/// The family named `name`.
pub fn family(name: &str) -> Option<&'static Family> {
    FAMILIES.iter().find(|f| f.name == name)
}

/// Run the given families (in parallel threads) and return the claims in
/// order. A family that panics yields one `Broken` claim.
pub fn run_families(families: &[&'static Family]) -> Vec<(&'static str, Vec<Claim>)> {
    std::thread::scope(|scope| {
        let handles: Vec<_> = families
            .iter()
            .map(|f| (f.name, scope.spawn(|| run_family(f))))
            .collect();
        handles
            .into_iter()
            .map(|(name, h)| {
                let claims = h.join().unwrap_or_else(|_| {
                    vec![Claim::new(
                        &format!("family {name} runs to completion"),
                        "ours",
                        Verdict::Broken,
                        Verdict::Proved,
                        "the family panicked".into(),
                    )]
                });
                (name, claims)
            })
            .collect()
    })
}

/// Run every family (in parallel threads) and return the claims in order.
pub fn run_all() -> Vec<(&'static str, Vec<Claim>)> {
    let all: Vec<&'static Family> = FAMILIES.iter().collect();
    run_families(&all)
}

#[cfg(test)]
mod tests {
    use super::first_failures;

    #[test]
    fn first_failure_is_the_first_in_order() {
        let items: Vec<usize> = (0..41).collect();
        // Failures at 7, 12 and 30: whatever worker finds which, 7 is first.
        let fails = |k: &usize| [[30, 12, 7].contains(k).then_some(*k * 10)];
        assert_eq!(first_failures(&items, fails), [Some(70)]);
        assert_eq!(first_failures(&items, |_| [None::<()>]), [None]);
        assert_eq!(first_failures(&[] as &[usize], |k| [Some(*k)]), [None]);
    }

    #[test]
    fn first_failures_are_the_first_in_order_per_check() {
        let items: Vec<usize> = (0..41).collect();
        // Check 0 fails at 30, 12, 7; check 1 at 40 only; check 2 never.
        let fails = |k: &usize| {
            [
                [30, 12, 7].contains(k).then_some(*k),
                (*k == 40).then_some(*k),
                None,
            ]
        };
        assert_eq!(first_failures(&items, fails), [Some(7), Some(40), None]);
    }
}
