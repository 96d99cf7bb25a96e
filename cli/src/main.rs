//! The `exact-bezier` command line: see `exact-bezier --help`.

/// The allocator: exact arithmetic makes and drops many small big integers,
/// which mimalloc serves faster than the system allocator.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    std::process::exit(exact_bezier_cli::main());
}
