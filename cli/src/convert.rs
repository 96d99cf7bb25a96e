//! `convert FILE --to tri|rect|rational|bezier [--split a,b,c,d,e,f] [--degenerate]
//! [--normalize] [--scalar f64]`: rectangle ↔ triangle conversions
//! (source 003; source 001, Hu 2001), and trigonometric patches (source
//! 002) to their exact rational Bézier form, NURBS/STEP to their Bézier
//! pieces with origins (`docs/nurbs_step.md`). Output: a JSON array of patches.

use super::{
    charge_each, load_exact, on_exact, open_input, parse_list, patch_f64, read_input, ExactScalar,
    ScalarKind,
};
use crate::session::emit_raw;
use exact_bezier::algebra::{Field, Ordered, RealAlgebraic, Scalar};
use exact_bezier::audit::{ExactModel, Model, Origin};
use exact_bezier::convert::{rect_to_tris, tri_to_degenerate_rect, tri_to_rects, Split};
use exact_bezier::io::trig::read_trig_patches;
use exact_bezier::io::{
    brep_to_json, brep_to_lines, is_step, patch_to_json, piece_to_json, read_exact_model,
    JsonScalar,
};
use exact_bezier::limits::{self, check_degree, Size};
use exact_bezier::patch::Patch;
use exact_bezier::step::{read_brep, BrepModel};
use exact_bezier::trig::TrigPatch;
use exact_bezier::Error;
use num_rational::BigRational;
use serde_json::Value;

/// What to convert to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Target {
    /// rect (m, n) → two tris of degree m + n, on Δ1 (u + v ≤ 1) then Δ2.
    Tri,
    /// tri of degree n → three rects (n, n) on D1, D2, D3, or one degenerate rect.
    Rect,
    /// trig-curve → rational quartic, trig-rect → rational (4, 4) rect, exactly,
    /// in τ = tan(t/2) (source 002 patches for every rational-Bézier command).
    Rational,
    /// NURBS (JSON, geomdl) → its rational Bézier pieces, each with
    /// `"origin"`: element, knot spans; STEP → its B-rep: faces with surface
    /// pieces and bounds, edges with curve pieces, vertices, units,
    /// tolerance and a summary (see docs/nurbs_step.md, docs/FORMAT.md).
    Bezier,
}

/// Arguments of `convert`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Input file (JSON), or - for standard input.
    file: String,
    /// Target kind.
    #[arg(long, value_enum)]
    to: Target,
    /// Split of the triangle for --to rect: a,b,c,d,e,f with p2 = (b, 0),
    /// p3 = (a, c), p4 = (0, d), p5 = (e, f), e + f = 1 (source 003 eq. 19).
    /// Default: the centroid and edge midpoints, 1/3,1/2,1/3,1/2,1/2,1/2.
    #[arg(long)]
    split: Option<String>,
    /// For --to rect: one degenerate rect (n, n) instead of three
    /// (rect(s, t) = tri(s, (1 − s)t)).
    #[arg(long)]
    degenerate: bool,
    /// Scale the weights of each output patch to sum 1 (as in source 003 §4).
    #[arg(long)]
    normalize: bool,
    /// Scalar to compute with.
    #[arg(long, value_enum, default_value_t)]
    scalar: ScalarKind,
    /// With --to bezier on STEP: JSON Lines, one face, edge or vertex a
    /// line, then the model (bodies, units, tolerance, summary) last.
    #[arg(long)]
    jsonl: bool,
}

/// The options that shape each conversion.
struct Plan<T> {
    to: Target,
    split: Split<T>,
    degenerate: bool,
    normalize: bool,
}

pub fn run(a: &Args) -> Result<Value, Error> {
    if a.to == Target::Rational {
        return trig_to_rational(a);
    }
    if a.to == Target::Bezier {
        return nurbs_to_bezier(a);
    }
    if a.jsonl {
        return Err(Error::Format(
            "--jsonl applies to --to bezier on STEP input".into(),
        ));
    }
    if a.to == Target::Tri && (a.split.is_some() || a.degenerate) {
        return Err(Error::Format(
            "--split and --degenerate apply to --to rect only".into(),
        ));
    }
    if a.degenerate && a.split.is_some() {
        return Err(Error::Format(
            "--degenerate gives one rect and takes no --split".into(),
        ));
    }
    let split = match &a.split {
        Some(text) => {
            let p = parse_list(text)?;
            let params: [BigRational; 6] = p.try_into().map_err(|p: Vec<BigRational>| {
                Error::Shape(format!(
                    "--split needs 6 numbers a,b,c,d,e,f, not {}",
                    p.len()
                ))
            })?;
            Split::new(params)?
        }
        None => Split::standard(),
    };
    let plan = Plan {
        to: a.to,
        split,
        degenerate: a.degenerate,
        normalize: a.normalize,
    };
    on_exact!(load_exact(&a.file)?, patches => convert_each(&patches, &plan, a.scalar))
}

/// Convert every patch over `T` (exactly, or on its nearest `f64` patch).
fn convert_each<T: ExactScalar>(
    patches: &[Patch<T>],
    plan: &Plan<BigRational>,
    scalar: ScalarKind,
) -> Result<Value, Error> {
    let split_bits = limits::max_bits(plan.split.params());
    for p in patches {
        if let Patch::Rect(r) = p {
            let (m, n) = r.degree();
            check_degree(m + n)?;
        }
    }
    charge_each("convert", patches, scalar, |s| convert_cost(s, split_bits))?;
    let mut out = Vec::new();
    for p in patches {
        match scalar {
            ScalarKind::Exact => out.extend(convert_with(p, &plan.map(T::from_rational))?),
            ScalarKind::F64 => {
                out.extend(convert_with(&patch_f64(p)?, &plan.map(Ordered::to_f64))?)
            }
        }
    }
    Ok(Value::Array(out))
}

impl Plan<BigRational> {
    /// The same plan with the split parameters mapped by `f`.
    fn map<U: Scalar>(&self, f: impl Fn(&BigRational) -> U) -> Plan<U> {
        Plan {
            to: self.to,
            split: Split::new_unchecked(self.split.params().clone().map(|x| f(&x))),
            degenerate: self.degenerate,
            normalize: self.normalize,
        }
    }
}

/// Estimated `(operations, bits)` of converting a patch of size `s`: a rect
/// (m, n) gives two tris of degree N = m + n, each coefficient a sum over
/// the net; a tri of degree n gives three rects (n, n), each coefficient a
/// sum over the net with split parameters of `split_bits` bits. Each term
/// of those sums costs 4 operations (to tri) or 8 (to rect, whose split
/// parameters make larger fractions; calibrated, `cli/benches/cost_model.rs`).
fn convert_cost(s: &Size, split_bits: u64) -> (u64, u64) {
    let d1 = s.dim as u64 + 1;
    let (m, n) = (s.degree.0 as u64, s.degree.1 as u64);
    // Written: three (m, m) rects of a tri patch, two tri patches of
    // degree m + n of a rect.
    if s.tri {
        let net = (m + 1) * (m + 2) / 2;
        (
            96 * (m + 1) * (m + 1) * net * d1 + s.write_ops(3 * (m + 1) * (m + 1) * d1),
            s.grown_bits(2 * m, split_bits),
        )
    } else {
        let big = m + n + 1;
        (
            8 * big * big * (m + 1) * (n + 1) * d1 + s.write_ops(big * (big + 1) * d1),
            s.grown_bits(2 * (m + n), 1),
        )
    }
}

fn convert_with<T: JsonScalar + Ordered>(
    p: &Patch<T>,
    plan: &Plan<T>,
) -> Result<Vec<Value>, Error> {
    let converted: Vec<Patch<T>> = match (p, plan.to) {
        (Patch::Rect(r), Target::Tri) => rect_to_tris(r).into_iter().map(Patch::Tri).collect(),
        (Patch::Tri(t), Target::Rect) if plan.degenerate => {
            vec![Patch::Rect(tri_to_degenerate_rect(t))]
        }
        (Patch::Tri(t), Target::Rect) => tri_to_rects(t, &plan.split)
            .into_iter()
            .map(Patch::Rect)
            .collect(),
        (other, to) => {
            return Err(Error::Format(format!(
                "convert --to {} needs {} patches, not a {}",
                if to == Target::Tri { "tri" } else { "rect" },
                if to == Target::Tri { "rect" } else { "tri" },
                other.kind()
            )))
        }
    };
    converted
        .iter()
        .map(|q| {
            let q = if plan.normalize {
                normalized(q)?
            } else {
                q.clone()
            };
            patch_to_json(&q)
        })
        .collect()
}

/// `--to bezier`: every piece of the model with its origin.
fn nurbs_to_bezier(a: &Args) -> Result<Value, Error> {
    if a.split.is_some() || a.degenerate {
        return Err(Error::Format(
            "--split and --degenerate apply to --to rect only".into(),
        ));
    }
    let mut input = open_input(&a.file)?;
    if is_step(&mut input)? {
        return step_to_bezier(read_brep(input)?, a);
    }
    if a.jsonl {
        return Err(Error::Format("--jsonl applies to STEP input".into()));
    }
    let out = match read_exact_model(input)? {
        ExactModel::Rational(m) => write_pieces(&m, a)?,
        ExactModel::Algebraic(m) => write_pieces(&m, a)?,
    };
    Ok(Value::Array(out))
}

/// Every piece of a model with its origin (see [`write_piece`]).
fn write_pieces<T: JsonScalar + Ordered>(m: &Model<T>, a: &Args) -> Result<Vec<Value>, Error> {
    m.pieces
        .iter()
        .map(|p| write_piece(&p.patch, &p.origin, a))
        .collect()
}

/// A piece with its origin, normalized and over the scalar of `a`.
fn write_piece<T: JsonScalar + Ordered>(
    p: &Patch<T>,
    origin: &Origin,
    a: &Args,
) -> Result<Value, Error> {
    let scaled;
    let patch = if a.normalize {
        scaled = normalized(p)?;
        &scaled
    } else {
        p
    };
    match a.scalar {
        ScalarKind::Exact => piece_to_json(patch, origin),
        ScalarKind::F64 => piece_to_json(&patch.to_f64(), origin),
    }
}

/// A STEP B-rep: one document, or JSON Lines (every line but the last
/// emitted here, the model line returned). The model is freed on a worker
/// thread while the lines are written.
fn step_to_bezier(m: BrepModel, a: &Args) -> Result<Value, Error> {
    let write = |p: &Patch<RealAlgebraic>, o: &Origin| write_piece(p, o, a);
    if !a.jsonl {
        return brep_to_json(&m, &write);
    }
    let lines = brep_to_lines(&m, &write)?;
    rayon::spawn(move || drop(m));
    let mut text = String::with_capacity(lines.items.iter().map(|l| l.len() + 1).sum());
    for item in &lines.items {
        text.push_str(item);
        text.push('\n');
    }
    emit_raw(&text);
    Ok(lines.model)
}

/// The patch with weights scaled to sum 1.
fn normalized<T: Field>(p: &Patch<T>) -> Result<Patch<T>, Error> {
    let sum = |w: Vec<Vec<T>>| w.into_iter().flatten().fold(T::zero(), |acc, x| acc + &x);
    let total = match p {
        Patch::Rect(r) => sum(r.weights()),
        Patch::Tri(t) => t.weight_sum(),
        Patch::Curve(c) => c.weights().into_iter().fold(T::zero(), |acc, x| acc + &x),
    };
    if total.is_zero() {
        return Err(Error::PointAtInfinity);
    }
    let k = total.recip();
    Ok(match p {
        Patch::Rect(r) => Patch::Rect(r.scale_weights(&k)),
        Patch::Tri(t) => Patch::Tri(t.scale_weights(&k)),
        Patch::Curve(c) => Patch::Curve(c.scale_weights(&k)),
    })
}

/// `--to rational`: every trig patch of the file as its exact rational
/// Bézier form (see `TrigCurve::to_rational`, `TrigRect::to_rational`).
fn trig_to_rational(a: &Args) -> Result<Value, Error> {
    if a.split.is_some() || a.degenerate {
        return Err(Error::Format(
            "--split and --degenerate apply to --to rect only".into(),
        ));
    }
    let patches = read_trig_patches(&read_input(&a.file)?)?.ok_or_else(|| {
        Error::Format("convert --to rational needs trig-curve or trig-rect patches".into())
    })?;
    for p in &patches {
        limits::charge("convert --to rational", trig_rational_cost(p, a.scalar))?;
    }
    let out = patches
        .iter()
        .map(|p| match a.scalar {
            ScalarKind::Exact => trig_rational_json(p, a.normalize),
            ScalarKind::F64 => trig_rational_json(&p.to_f64(), a.normalize),
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Value::Array(out))
}

/// The work of one trig patch's rational form: [`TRIG_OPS_PER_NUMBER`]
/// operations for each number of the result (a quartic curve or a (4, 4)
/// rect, homogeneous) on numbers of the patch's size; `f64` as
/// [`limits::f64_work`].
fn trig_rational_cost(p: &TrigPatch<BigRational>, scalar: ScalarKind) -> u64 {
    let bits = std::cell::Cell::new(0);
    let _ = p.map(|x| {
        bits.set(bits.get().max(limits::bits(x)));
        0.0
    });
    let (points, d) = match p {
        TrigPatch::Curve(c) => (5, c.points().first().map_or(0, Vec::len)),
        TrigPatch::Rect(r) => (
            25,
            r.points()
                .first()
                .and_then(|row| row.first())
                .map_or(0, Vec::len),
        ),
    };
    let ops = TRIG_OPS_PER_NUMBER * points * (d as u64 + 1);
    match scalar {
        ScalarKind::Exact => limits::exact_work(ops, bits.get()),
        ScalarKind::F64 => limits::f64_work(ops),
    }
}

/// Operations per number of a trig patch's rational form: the four trig
/// basis functions of each direction rewritten in `τ = tan(t/2)` and
/// multiplied out (calibrated by `cli/benches/cost_model.rs`: the four
/// trig-rects of `tests/fixtures/bowl.json` took 16 ms, 4 ms a patch).
const TRIG_OPS_PER_NUMBER: u64 = 1024;

fn trig_rational_json<T: JsonScalar + Ordered>(
    p: &TrigPatch<T>,
    normalize: bool,
) -> Result<Value, Error> {
    let patch = match p {
        TrigPatch::Curve(c) => Patch::Curve(c.to_rational()),
        TrigPatch::Rect(r) => Patch::Rect(r.to_rational()),
    };
    let patch = if normalize {
        normalized(&patch)?
    } else {
        patch
    };
    patch_to_json(&patch)
}
