//! The library's layers (see the crate docs, "Layers"): every `crate::…`
//! path in a module names a module strictly below it, so no module imports
//! from a module above it and no two modules import each other.
//!
//! The check reads the sources: `use crate::…` trees (groups expanded) and
//! inline `crate::…` paths, after removing comments and the unit-test
//! modules (`#[cfg(test)] mod tests` and `tests.rs` files, which may use
//! fixtures from anywhere).

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

/// The top-level modules of `src/`, lowest first.
const LAYERS: &[&str] = &[
    "error",
    "limits",
    "widest",
    "algebra",
    "hpoint",
    "bernstein",
    "eval",
    "curve",
    "rect",
    "tri",
    "display",
    "patch",
    "blossom",
    "convert",
    "reparam",
    "arc",
    "trig",
    "coincide",
    "intersect",
    "nurbs",
    "analytic",
    "step",
    "audit",
    "io",
    "serde_support",
    "render",
    "coords",
    "strategy",
    "samples",
    "prelude",
];

/// Items re-exported at the crate root, and the module each comes from.
const ROOT_ITEMS: &[(&str, &str)] = &[
    ("Error", "error"),
    ("MAX_DEGREE", "limits"),
    ("BigRational", "algebra"),
    ("BigInt", "algebra"),
    ("Scalar", "algebra"),
    ("Field", "algebra"),
    ("Ordered", "algebra"),
    ("Ring", "algebra"),
    ("MulAcc", "algebra"),
    ("Poly", "algebra"),
    ("Roots", "algebra"),
    ("Tolerance", "algebra"),
    ("ratio", "algebra"),
    ("RationalCurve", "curve"),
    ("RectPatch", "rect"),
    ("TriPatch", "tri"),
    ("Patch", "patch"),
];

fn rank(module: &str) -> Option<usize> {
    LAYERS.iter().position(|m| *m == module)
}

/// The module a `crate::` path's first segment belongs to.
fn home(first: &str) -> Option<&str> {
    if rank(first).is_some() {
        return Some(LAYERS[rank(first)?]);
    }
    ROOT_ITEMS
        .iter()
        .find(|(item, _)| *item == first)
        .map(|(_, m)| *m)
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).expect("readable source dir") {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The source without comments (`//…` to the end of the line, `/* … */`) and
/// without a trailing `#[cfg(test)] mod tests { … }`. String literals are
/// kept: a `//` inside one would cut the line, which only loses text.
fn code_of(source: &str) -> String {
    let mut code = String::with_capacity(source.len());
    let mut rest = source;
    while let Some(i) = rest.find('/') {
        code.push_str(&rest[..i]);
        let tail = &rest[i..];
        if tail.starts_with("//") {
            rest = tail.find('\n').map_or("", |j| &tail[j..]);
        } else if tail.starts_with("/*") {
            rest = tail.find("*/").map_or("", |j| &tail[j + 2..]);
        } else {
            code.push('/');
            rest = &tail[1..];
        }
    }
    code.push_str(rest);
    match code.find("#[cfg(test)]\nmod tests") {
        Some(i) => code[..i].to_string(),
        None => code,
    }
}

/// The first segment after `crate::` of every path in `code`, with `use`
/// groups expanded (`use crate::{a::X, b};` gives `a` and `b`).
fn crate_paths(code: &str) -> Vec<String> {
    let mut firsts = Vec::new();
    let mut rest = code;
    while let Some(i) = rest.find("crate::") {
        let before = rest[..i].chars().last();
        rest = &rest[i + "crate::".len()..];
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '$') {
            continue; // `exact_crate::`, `$crate::`
        }
        if let Some(group) = rest.strip_prefix('{') {
            let end = matching_brace(group);
            firsts.extend(top_level_items(&group[..end]));
        } else {
            firsts.push(ident(rest).to_string());
        }
    }
    firsts
}

fn ident(s: &str) -> &str {
    let end = s
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    &s[..end]
}

fn matching_brace(s: &str) -> usize {
    let mut depth = 0;
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' if depth == 0 => return i,
            '}' => depth -= 1,
            _ => {}
        }
    }
    s.len()
}

/// The first identifiers of the comma-separated items of a `use` group.
fn top_level_items(group: &str) -> Vec<String> {
    let mut items = Vec::new();
    let mut depth = 0;
    let mut start = 0;
    for (i, c) in group.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                items.push(ident(group[start..i].trim()).to_string());
                start = i + 1;
            }
            _ => {}
        }
    }
    items.push(ident(group[start..].trim()).to_string());
    items.retain(|s| !s.is_empty() && s != "self");
    items
}

#[test]
fn every_import_points_down() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut violations = BTreeSet::new();
    for file in &files {
        let rel = file.strip_prefix(&src).expect("under src");
        let first = rel.components().next().expect("a component");
        let module = first.as_os_str().to_str().expect("UTF-8 name");
        let module = module.strip_suffix(".rs").unwrap_or(module);
        if module == "lib" || rel.ends_with("tests.rs") {
            continue;
        }
        let Some(from) = rank(module) else {
            violations.insert(format!("module `{module}` is not in LAYERS"));
            continue;
        };
        let code = code_of(&fs::read_to_string(file).expect("readable file"));
        for first in crate_paths(&code) {
            match home(&first) {
                Some(target) if target == module => {}
                Some(target) if rank(target) < Some(from) => {}
                Some(target) => {
                    violations.insert(format!(
                        "{}: `{module}` imports `{target}` above it",
                        rel.display()
                    ));
                }
                None => {
                    violations.insert(format!(
                        "{}: `crate::{first}` is not a known module or root item",
                        rel.display()
                    ));
                }
            }
        }
    }
    assert!(
        violations.is_empty(),
        "layer violations:\n{}",
        violations.into_iter().collect::<Vec<_>>().join("\n")
    );
}

#[test]
fn the_checker_sees_groups_and_inline_paths() {
    let code = code_of(
        "use crate::{algebra::Scalar, io::{a, b}, self};\n// crate::audit\nfn f() { crate::eval::x(); }\n#[cfg(test)]\nmod tests { use crate::render; }",
    );
    assert_eq!(crate_paths(&code), ["algebra", "io", "eval"]);
}
