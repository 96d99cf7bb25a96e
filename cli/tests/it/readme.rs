//! The shell examples of README.md and docs/*.md (` ```console ` blocks)
//! run against the built binary, and their output must match the text
//! shown. `...` on a line of its own stands for any lines, and `[..]` for
//! the rest of a line.

#[test]
fn readme_and_docs_examples() {
    trycmd::TestCases::new()
        .register_bin(
            "exact-bezier",
            std::path::Path::new(env!("CARGO_BIN_EXE_exact-bezier")),
        )
        .case("../README.md")
        .case("../docs/*.md");
}
