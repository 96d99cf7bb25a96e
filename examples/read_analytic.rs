//! Read every analytic curve and surface entity of STEP files as exact
//! rational pieces (over the real algebraic numbers) and time it:
//!
//! ```text
//! cargo run --release --example read_analytic -- FILE.stp [FILE.stp …]
//! ```
//!
//! The plane angle unit is taken as degrees when the file declares a
//! `CONVERSION_BASED_UNIT('DEGREE', …)`, else radians (a shortcut of this
//! example; the B-rep reader takes it from the representation context).
//! Unbounded directions use the range `[0, 1]` (no face boundary here).

use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::analytic::AngleUnit;
use exact_bezier::step::geometry::{curve_pieces, surface_pieces, Context, Curve, Surface, Table};
use exact_bezier::step::parser::Reader;
use std::collections::BTreeMap;
use std::time::Instant;

const CURVES: &[&str] = &["LINE", "CIRCLE", "ELLIPSE", "POLYLINE", "TRIMMED_CURVE"];
const SURFACES: &[&str] = &[
    "PLANE",
    "CYLINDRICAL_SURFACE",
    "CONICAL_SURFACE",
    "SPHERICAL_SURFACE",
    "TOROIDAL_SURFACE",
    "DEGENERATE_TOROIDAL_SURFACE",
    "SURFACE_OF_LINEAR_EXTRUSION",
    "SURFACE_OF_REVOLUTION",
];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    for path in std::env::args().skip(1) {
        let text = std::fs::read_to_string(&path)?;
        let start = Instant::now();
        let mut reader = Reader::new(text.as_bytes());
        let mut table = Table::default();
        while let Some(inst) = reader.next_instance()? {
            table.insert(inst.id, inst);
        }
        let parsed = start.elapsed();
        let angle_unit = if text.contains("CONVERSION_BASED_UNIT('DEGREE'") {
            AngleUnit::Degree
        } else {
            AngleUnit::radian()
        };
        let ctx = Context::<RealAlgebraic> {
            table: &table,
            angle_unit,
            bspline_curve: None,
        };
        let mut counts: BTreeMap<String, usize> = BTreeMap::new();
        let (mut pieces, mut approximate, mut other) = (0, 0, 0);
        for (id, inst) in &table {
            let name = inst.records[0].name.as_str();
            if inst.complex || !(CURVES.contains(&name) || SURFACES.contains(&name)) {
                continue;
            }
            *counts.entry(name.to_owned()).or_default() += 1;
            if CURVES.contains(&name) {
                match curve_pieces(&ctx, *id, &[])? {
                    Curve::Pieces(c) => {
                        pieces += c.pieces.len();
                        approximate += usize::from(c.approximate.is_some());
                    }
                    _ => other += 1,
                }
            } else {
                match surface_pieces(&ctx, *id, &[])? {
                    Surface::Pieces(s) => {
                        pieces += s.patches.len();
                        approximate += usize::from(s.approximate.is_some());
                    }
                    _ => other += 1,
                }
            }
        }
        println!(
            "{path}: parsed in {parsed:?}, all in {:?}; {counts:?}; {pieces} pieces, {approximate} approximate, {other} B-spline/unsupported",
            start.elapsed()
        );
    }
    Ok(())
}
