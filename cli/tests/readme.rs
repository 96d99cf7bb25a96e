//! The shell examples of README.md and docs/*.md (at the workspace root) (` ```console ` blocks)
//! run against the built binary, and their output must match the text
//! shown. `...` on a line of its own stands for any lines, and `[..]` for
//! the rest of a line.

#[test]
fn readme_and_docs_examples() {
    // The examples' paths are relative to the repository root, as a user
    // runs them (this binary holds this one test, so the change of working
    // directory affects nothing else).
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap();
    std::env::set_current_dir(root).unwrap();
    trycmd::TestCases::new()
        .register_bin(
            "exact-bezier",
            std::path::Path::new(env!("CARGO_BIN_EXE_exact-bezier")),
        )
        .case("README.md")
        .case("docs/*.md");
}
