//! The integration tests, built as one binary: one link of the library
//! instead of one per file. Each module is one former `tests/NAME.rs`.
//! (`tests/fuzz.rs` stays a separate binary: it installs its own global
//! allocator; so does `tests/readme.rs`, which runs the documented shell
//! examples from the workspace root.)

mod algebraic;
mod algebraic_budget;
mod arcs;
mod audit;
mod budget_findings;
mod coincide;
mod common;
mod conversions;
mod curves;
mod dedup;
mod eval_batch;
mod intersect;
mod mesh;
mod plot;
mod schema;
mod sources;
mod surfaces;
mod trig;
