//! The `exact-bezier` command line: see `exact-bezier --help`.

fn main() {
    std::process::exit(exact_bezier_cli::main());
}
