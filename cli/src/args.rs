//! The command line's arguments (clap): the global flags, the scalar
//! choice and one variant per subcommand, and the dispatch to the
//! subcommand modules.

use crate::*;
use clap::{Parser, Subcommand, ValueEnum};
use exact_bezier::limits::Limits;
use exact_bezier::Error;
use serde_json::Value;

/// Rational Bézier curves and patches, exactly.
#[derive(Parser, Debug)]
#[command(name = "exact-bezier", version, about)]
pub struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
    /// Most decimal digits per input number, exponent included (docs/limits.md).
    #[arg(long, global = true, value_parser = parse_count, value_name = "N")]
    max_digits: Option<u64>,
    /// Most bytes of one input file or of standard input.
    #[arg(long, global = true, value_parser = parse_count, value_name = "BYTES")]
    max_input_bytes: Option<u64>,
    /// Most estimated work units of one command (docs/limits.md).
    #[arg(long, global = true, value_parser = parse_count, value_name = "UNITS")]
    max_work: Option<u64>,
    /// Print JSON results over several indented lines (default: one line).
    #[arg(long, global = true)]
    pub(crate) pretty: bool,
}

impl Cli {
    /// The limits asked for by the global flags (defaults otherwise).
    pub(crate) fn limits(&self) -> Limits {
        let d = Limits::DEFAULT;
        Limits {
            max_digits: self.max_digits.unwrap_or(d.max_digits),
            max_input_bytes: self.max_input_bytes.unwrap_or(d.max_input_bytes),
            max_work: self.max_work.unwrap_or(d.max_work),
        }
    }

    pub(crate) fn sets_limits(&self) -> bool {
        self.max_digits.is_some() || self.max_input_bytes.is_some() || self.max_work.is_some()
    }
}

/// The value of a limit flag: an integer in digits (`10000000000`) or in
/// the scientific notation the limit messages print (`1e10`, `1.00e10`,
/// `2.5e9`), whose value must be a whole number of at most `u64::MAX`.
fn parse_count(text: &str) -> Result<u64, String> {
    let bad = || format!("{text:?} is not a whole number (digits, or as 1e10 or 2.5e9)");
    let (mantissa, exponent) = match text.split_once(['e', 'E']) {
        Some((m, e)) => (m, e.strip_prefix('+').unwrap_or(e)),
        None => (text, "0"),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let fraction = fraction.trim_end_matches('0');
    let digits = format!("{whole}{fraction}");
    let all_digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    if !all_digits(&digits) || !all_digits(exponent) || whole.is_empty() {
        return Err(bad());
    }
    let too_large = || format!("{text} is over the largest count, {}", u64::MAX);
    let shift = exponent
        .parse::<u32>()
        .ok()
        .and_then(|e| e.checked_sub(fraction.len() as u32))
        .ok_or_else(bad)?;
    let base: u64 = digits.parse().map_err(|_| too_large())?;
    10u64
        .checked_pow(shift)
        .and_then(|scale| base.checked_mul(scale))
        .ok_or_else(too_large)
}

/// Which scalar a command computes with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum, Default)]
pub enum ScalarKind {
    /// Exact rationals.
    #[default]
    Exact,
    /// IEEE double precision.
    F64,
}

#[derive(Subcommand, Debug)]
pub(crate) enum Command {
    /// Evaluate a curve or patch: {"point": [...]}.
    #[command(
        after_help = "Parameters are exact text (1/3, 0.25). A curve takes t in [0, 1]; a rect takes u,v in [0, 1]²; a tri takes barycentric u,v with u, v ≥ 0 and u + v ≤ 1 (w = 1 − u − v; u = 1 is the vertex points[0][n], v = 1 is points[n][0], w = 1 is points[0][0]). A trig patch takes tau=T (τ = tan(t/2)). Outside the domain needs --extrapolate.\n\nExample: exact-bezier eval tests/fixtures/yang_yong_example1.json --at 1/3,1/2"
    )]
    Eval(eval::Args),
    /// Reparameterize: linear Möbius map (--mobius ALPHA[,BETA]) or quadratic map of a rect (--quadratic A1,A2,B1,B2).
    #[command(
        after_help = "The linear Möbius map u = (α − 1)s / (2αs − s − α) with 0 < α < 1 (α = 1/2 is the identity) keeps every point of the patch and changes only its weights (source 000, eqs. 2–4). The quadratic map of source 000, eqs. 9–10, raises a rect (m, n) to (m + n, m + n).\n\nExample: exact-bezier reparam tests/fixtures/yang_yong_example1.json --mobius 3/5,7/10"
    )]
    Reparam(transform::ReparamArgs),
    /// Standard form: end weights 1 (curve) or corner weights 1 (rect).
    #[command(
        after_help = "Finds the reparameterization that makes the end weights (curve) or the corner weights (rect) equal to 1, exactly, with real algebraic numbers where roots are needed (sqrt, cbrt: docs/algebraic_numbers.md). A rect whose corner weights satisfy ω_m0·ω_0n = ω_00·ω_mn takes a linear Möbius map (source 000, Theorem 1); any other takes the quadratic map of eqs. 9–19.\n\nExample: exact-bezier standardize tests/fixtures/yang_yong_example3.json"
    )]
    Standardize(standardize::Args),
    /// Raise the degree (--by R[,S]).
    #[command(
        after_help = "The same curve or patch with its degree raised by R (and by S in v for a rect); the points do not change.\n\nExample: exact-bezier elevate tests/fixtures/yang_yong_example1.json --by 1,2"
    )]
    Elevate(transform::ElevateArgs),
    /// Convert rect ↔ tri (--to tri | --to rect [--split a,b,c,d,e,f] [--degenerate]).
    #[command(
        after_help = "--to tri: a rect (m, n) becomes two tris of degree m + n, on u + v ≤ 1 and on its complement. --to rect: a tri of degree n becomes three rects (n, n) over a split of the triangle (see --split), or one degenerate rect. --to rational: a trig patch becomes its exact rational Bézier form. --to bezier: NURBS or STEP input becomes its rational Bézier pieces.\n\nExample: exact-bezier convert tests/fixtures/zcf_4_2_tri.json --to rect --split 1/3,1/2,1/3,1/2,1/2,1/2"
    )]
    Convert(convert::Args),
    /// Run every proof in proofs/ and print one line per claim.
    #[command(
        after_help = "Each claim gets a verdict: proved, checked, refuted, reproduced, mismatch or broken (see the README). Exit 0 iff every claim has its expected verdict.\n\nExample: exact-bezier prove --family bernstein"
    )]
    Prove(prove::Args),
    /// Draw curves and patches as SVG or PNG (-o OUT.svg|OUT.png).
    #[command(
        after_help = "Example: exact-bezier plot tests/fixtures/yang_yong_example1.json -o example1.png"
    )]
    Plot(plot::Args),
    /// Triangulate patches with normals as OBJ, STL or PLY (-o OUT.obj).
    #[command(
        after_help = "Example: exact-bezier mesh tests/fixtures/yang_yong_example1.json -o example1.obj --density 16"
    )]
    Mesh(mesh::Args),
    /// Regenerate the figure gallery (docs/figures/gallery.json).
    #[command(after_help = "Example: exact-bezier figures --only 000-fig3a-example1")]
    Figures(figures::Args),
    /// Derivative of a curve: {"order": K, "derivative": [...]}.
    #[command(
        after_help = "Example: exact-bezier deriv docs/examples/curve.json --at 1/2 --order 2"
    )]
    Deriv(deriv::Args),
    /// Curvature of a curve: {"curvature_squared": κ², "curvature": κ, "curvature_approx": κ as f64}, exact (κ = √κ², algebraic).
    #[command(after_help = "Example: exact-bezier curvature docs/examples/curve.json --at 1/2")]
    Curvature(curvature::Args),
    /// G0/G1/G2 verdicts for the join of curve A's end to curve B's start.
    #[command(
        after_help = "G0: B starts where A ends. G1: also the same tangent direction, Q1 − Q0 = (nα/m)(Pn − Pn−1) with α > 0 (the corrected form of source 001). G2: also the same curvature vector.\n\nExample: exact-bezier join docs/examples/curve.json docs/examples/curve.json"
    )]
    Join(join::Args),
    /// Lower the degree of a curve by one (--method forrest|farin|lsq|exact).
    #[command(
        after_help = "forrest and farin may give non-positive weights: the result is then written with valid: false, and the exit code is 3. exact succeeds only when the curve truly has a lower degree.\n\nExample: exact-bezier reduce docs/examples/curve.json --method lsq"
    )]
    Reduce(reduce::Args),
    /// A circular arc as a standard-form rational cubic (source 004 eq. 1).
    #[command(
        after_help = "λ picks one member of the family of standard-form cubics of the same arc. It is admissible (all weights positive) iff 1 − λk > 0, 1 + 2λck > 0 and 1 − λ(1 − 4c²) > 0, with c = cos(θ/2) and k = 1 + 2c: λ in (−1/(2ck), 1/k) for 0 < θ < π, and λ < 1/(1 − 4c²) for π ≤ θ < 4π/3.\n\nExample: exact-bezier arc --cos-half 'sqrt(2)/2' --lambda 0 --points '1,0;1,1;0,1'"
    )]
    Arc(arc::Args),
    /// Does a curve lie on a circle? Exact centre and radius², or the reason.
    #[command(after_help = "Example: exact-bezier is-circle docs/examples/arc.json")]
    IsCircle(is_circle::Args),
    /// Are two curves or rect patches the same up to reparameterization?
    #[command(
        after_help = "Same up to Möbius maps of each parameter, reversal, swapping u and v, degree elevation, common factors and weight scaling, decided exactly (no roots, no tolerance). The witness gives the map. Exit 0 either way.\n\nExample: exact-bezier coincide tests/fixtures/yang_yong_example1.json tests/fixtures/yang_yong_example3.json"
    )]
    Coincide(coincide::Args),
    /// Exact intersections of two curves (or self-intersections of one): points, contacts, overlaps.
    #[command(
        after_help = "Parameters and points are exact real algebraic numbers (sqrt(...), CRootOf(...)) with f64 approximations; an overlap gives the parameter intervals on both curves and the Möbius map s = (a t + b)/(c t + d) between them. Without B: loops (s < t) and cusps of A.\n\nExample: exact-bezier intersect docs/examples/curve.json docs/examples/line.json"
    )]
    Intersect(intersect::Args),
    /// Group curves/rect patches (JSON Lines or array) into coincidence classes, one JSON line each.
    #[command(after_help = "Example: exact-bezier dedup patches.jsonl --witness")]
    Dedup(dedup::Args),
    /// One canonical coincidence key per curve/rect patch, one JSON line each.
    #[command(after_help = "Example: exact-bezier key patches.jsonl")]
    Key(key::Args),
    /// Exact audit of a model (JSON, NURBS or STEP): shared edges G0/G1/G2, open/degenerate edges, duplicates.
    #[command(after_help = "Example: exact-bezier audit tests/fixtures/teapot.json --summary")]
    Audit(audit::Args),
}

/// Run one command: its JSON result, or its exit code when the command
/// prints for itself (`prove`).
pub(crate) fn dispatch(command: Command) -> Result<Result<Value, i32>, Error> {
    let value = match command {
        Command::Eval(a) => return eval::run(&a),
        Command::Reparam(a) => transform::reparam(&a),
        Command::Elevate(a) => transform::elevate(&a),
        Command::Standardize(a) => standardize::run(&a),
        Command::Convert(a) => convert::run(&a),
        Command::Prove(a) => return prove::run(&a).map(Err),
        Command::Plot(a) => plot::run(&a),
        Command::Mesh(a) => mesh::run(&a),
        Command::Figures(a) => figures::run(&a),
        Command::Deriv(a) => deriv::run(&a),
        Command::Curvature(a) => curvature::run(&a),
        Command::Join(a) => join::run(&a),
        Command::Reduce(a) => reduce::run(&a),
        Command::Arc(a) => arc::run(&a),
        Command::IsCircle(a) => is_circle::run(&a),
        Command::Coincide(a) => coincide::run(&a),
        Command::Intersect(a) => intersect::run(&a),
        Command::Dedup(a) => return dedup::run(&a).map(|()| Err(0)),
        Command::Key(a) => return key::run(&a).map(|()| Err(0)),
        Command::Audit(a) => audit::run(&a),
    }?;
    Ok(Ok(value))
}

#[cfg(test)]
mod tests {
    use super::parse_count;

    #[test]
    fn limit_counts_take_digits_and_the_printed_scientific_form() {
        assert_eq!(parse_count("10000000000"), Ok(10_000_000_000));
        assert_eq!(parse_count("1e10"), Ok(10_000_000_000));
        assert_eq!(parse_count("1.00e10"), Ok(10_000_000_000));
        assert_eq!(parse_count("2.5E+9"), Ok(2_500_000_000));
        assert_eq!(parse_count("0"), Ok(0));
        assert_eq!(parse_count("18446744073709551615"), Ok(u64::MAX));
        for bad in [
            "", "e5", "1.5", "2.55e1", "-1", "1e", "1e-2", "0x10", "1 e3", "1.e3.2",
        ] {
            assert!(parse_count(bad).is_err(), "{bad}");
        }
        for over in ["18446744073709551616", "1e20", "99999999999999999999e0"] {
            assert!(parse_count(over).unwrap_err().contains("largest"), "{over}");
        }
    }
}
