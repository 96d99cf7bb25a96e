//! The actual work of writing a number-field element as text, against a
//! product in the same field, counted by the work meter
//! (`exact_bezier::limits::meter`): the measurement behind
//! `exact_bezier::limits::write_ops`.
//!
//! ```text
//! cargo run --release --example write_cost
//! ```

use exact_bezier::algebra::{ExactNumber, RealAlgebraic};
use exact_bezier::limits::{exact_work, field_op_cost, metered, with_limits, write_ops, Limits};

/// Elements generating fields of degree 4, 6, 8 and 10.
const ELEMENTS: [&str; 4] = [
    "sqrt(2 + sqrt(5))",
    "CRootOf(x**3 - x - 1, 0)*sqrt(2)",
    "sqrt(2)*sqrt(2 + sqrt(5))",
    "CRootOf(x**5 - x - 1, 0)*sqrt(3)",
];

fn main() -> Result<(), exact_bezier::Error> {
    println!("  D   product  charged   write   charged  write/D^5");
    for text in ELEMENTS {
        with_limits(Limits::DEFAULT, || -> Result<(), exact_bezier::Error> {
            let a = RealAlgebraic::from_text(text)?;
            let b = a.clone() * &a + &RealAlgebraic::from_text("3/7")?;
            let before = metered();
            let c = b.clone() * &a;
            let product = metered() - before;
            let written = c.to_string();
            let write = metered() - before - product;
            let d = c.root_degree().unwrap_or(1) as u64;
            let op = field_op_cost(d, true);
            println!(
                "{d:>3} {product:>9} {:>8} {write:>8} {:>8} {:>9.1}",
                exact_work(1, 0) * op,
                exact_work(write_ops(d, true), 0) * op,
                write as f64 / d.pow(5) as f64
            );
            std::hint::black_box(written);
            Ok(())
        })?;
    }
    Ok(())
}
