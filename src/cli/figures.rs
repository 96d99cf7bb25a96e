//! `figures [--manifest docs/figures/gallery.json] [--out docs/figures]
//! [--only NAME]`: regenerate the gallery.
//!
//! The gallery is data: `gallery.json` is a JSON array with one entry per
//! figure,
//!
//! ```text
//! {"name": "stem", "caption": "…", "inputs": [INPUT, …], "args": ["--iso", "10", …]}
//! ```
//!
//! where an INPUT is a JSON file path (relative to the working directory),
//! or `{"run": ["SUBCOMMAND", "ARG", …]}`: that command line is run
//! in-process (not `figures` or `prove`: no recursion) and its standard output (patches in the DESIGN §4 format) is
//! saved as `OUT/inputs/stem.json` (`stem-K.json` for the K-th of several)
//! and used as the input. `args` are `plot` flags. Each entry gives
//! `OUT/stem.svg` and `OUT/stem.png`; an optional `"mesh": ["--density",
//! "24", …]` (`mesh` flags) also gives `OUT/stem.obj`. `OUT/README.md`
//! lists them all with their captions and commands.

use super::mesh as mesh_cmd;
use super::plot::{self as plot_cmd, write_output};
use super::read_input;
use crate::error::Error;
use clap::Parser;
use serde_json::{json, Value};
use std::fmt::Write;

/// Arguments of `figures`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The gallery list (JSON array of entries).
    #[arg(long, default_value = "docs/figures/gallery.json")]
    manifest: String,
    /// Folder for the images, derived inputs and README.md.
    #[arg(long, default_value = "docs/figures")]
    out: String,
    /// Regenerate only this entry.
    #[arg(long)]
    only: Option<String>,
}

/// One gallery entry.
struct Entry {
    name: String,
    caption: String,
    inputs: Vec<Value>,
    args: Vec<String>,
    mesh: Option<Vec<String>>,
}

/// A `plot` or `mesh` command line, parsed as the real command line is.
#[derive(Parser, Debug)]
#[command(name = "exact-bezier")]
struct Line {
    #[command(subcommand)]
    command: Sub,
}

#[derive(clap::Subcommand, Debug)]
enum Sub {
    Plot(plot_cmd::Args),
    Mesh(mesh_cmd::Args),
}

/// Run `exact-bezier SUB FILES… -o TARGET EXTRA…`; returns its text.
fn render(sub: &str, files: &[String], target: &str, extra: &[String]) -> Result<String, Error> {
    let argv: Vec<String> = ["exact-bezier", sub]
        .into_iter()
        .map(String::from)
        .chain(files.iter().cloned())
        .chain(["-o".to_string(), target.to_string()])
        .chain(extra.iter().cloned())
        .collect();
    let line = Line::try_parse_from(&argv)
        .map_err(|err| Error::Format(format!("{}: {err}", argv.join(" "))))?;
    match line.command {
        Sub::Plot(a) => plot_cmd::run(&a)?,
        Sub::Mesh(a) => mesh_cmd::run(&a)?,
    };
    Ok(argv.join(" "))
}

fn field<'a>(v: &'a Value, key: &str, entry: usize) -> Result<&'a Value, Error> {
    v.get(key)
        .ok_or_else(|| Error::Format(format!("gallery entry {entry} has no \"{key}\"")))
}

fn strings(v: &Value, what: &str) -> Result<Vec<String>, Error> {
    v.as_array()
        .and_then(|a| a.iter().map(|s| s.as_str().map(String::from)).collect())
        .ok_or_else(|| Error::Format(format!("{what} must be an array of strings")))
}

fn entries(manifest: &Value) -> Result<Vec<Entry>, Error> {
    let list = manifest
        .as_array()
        .ok_or_else(|| Error::Format("the gallery must be a JSON array of entries".into()))?;
    list.iter()
        .enumerate()
        .map(|(k, e)| {
            let text = |key| {
                field(e, key, k)?.as_str().map(String::from).ok_or_else(|| {
                    Error::Format(format!("gallery entry {k}: \"{key}\" must be a string"))
                })
            };
            let name = text("name")?;
            if name.is_empty()
                || !name
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
            {
                return Err(Error::Format(format!(
                    "gallery entry {k}: name {name:?} must be letters, digits, - or _"
                )));
            }
            Ok(Entry {
                caption: text("caption")?,
                inputs: field(e, "inputs", k)?.as_array().cloned().ok_or_else(|| {
                    Error::Format(format!("gallery entry {k}: \"inputs\" must be an array"))
                })?,
                args: e
                    .get("args")
                    .map_or(Ok(Vec::new()), |a| strings(a, "\"args\""))?,
                mesh: e.get("mesh").map(|a| strings(a, "\"mesh\"")).transpose()?,
                name,
            })
        })
        .collect()
}

/// The input file for one INPUT, running this binary for a `run` input.
fn resolve(input: &Value, out: &str, stem: &str) -> Result<(String, String), Error> {
    if let Some(path) = input.as_str() {
        return Ok((path.to_string(), path.to_string()));
    }
    let run = strings(
        input
            .get("run")
            .ok_or_else(|| Error::Format("an input must be a path or {\"run\": [...]}".into()))?,
        "\"run\"",
    )?;
    if matches!(run.first().map(String::as_str), Some("figures" | "prove")) {
        return Err(Error::Format(format!(
            "a gallery input cannot run {:?}: only commands that write patches",
            run[0]
        )));
    }
    // In-process, under this run's limits and work budget.
    let argv = std::iter::once("exact-bezier".to_string()).chain(run.iter().cloned());
    let res = super::run_with(argv.collect(), super::Stdin::Bytes(Vec::new()));
    if res.code != 0 {
        return Err(Error::Format(format!(
            "exact-bezier {} failed: {}",
            run.join(" "),
            res.stderr.trim()
        )));
    }
    let path = format!("{out}/inputs/{stem}.json");
    write_output(&path, res.stdout.as_bytes())?;
    Ok((path, format!("exact-bezier {}", run.join(" "))))
}

/// Make one figure: its inputs, SVG and PNG; returns its README section.
fn make(e: &Entry, out: &str) -> Result<String, Error> {
    let mut files = Vec::new();
    let mut how = Vec::new();
    for (k, input) in e.inputs.iter().enumerate() {
        let stem = if e.inputs.len() == 1 {
            e.name.clone()
        } else {
            format!("{}-{}", e.name, k + 1)
        };
        let (file, origin) = resolve(input, out, &stem)?;
        if file != origin {
            how.push(format!("`{file}` = `{origin}`"));
        }
        files.push(file);
    }
    let titled: Vec<String> = ["--title".to_string(), e.caption.clone()]
        .into_iter()
        .chain(e.args.iter().cloned())
        .collect();
    render("plot", &files, &format!("{out}/{}.svg", e.name), &titled)?;
    let mut lines = vec![render(
        "plot",
        &files,
        &format!("{out}/{}.png", e.name),
        &e.args,
    )?];
    if let Some(m) = &e.mesh {
        lines.push(render("mesh", &files, &format!("{out}/{}.obj", e.name), m)?);
    }
    let mut s = format!(
        "## {}\n\n{}\n\n![{}]({}.png)\n\n",
        e.name, e.caption, e.name, e.name
    );
    for h in how {
        let _ = writeln!(s, "- input {h}");
    }
    for line in lines {
        let _ = writeln!(s, "- `{line}`");
    }
    s.push('\n');
    Ok(s)
}

/// Regenerate the gallery; reports `{"figures": [names], "out": OUT}`.
pub fn run(a: &Args) -> Result<Value, Error> {
    let manifest = crate::io::parse_json(&read_input(&a.manifest)?)?;
    let all = entries(&manifest)?;
    let chosen: Vec<&Entry> = all
        .iter()
        .filter(|e| a.only.as_ref().is_none_or(|n| *n == e.name))
        .collect();
    if chosen.is_empty() {
        return Err(Error::Format(format!(
            "no gallery entry named {:?}",
            a.only
        )));
    }
    let mut readme = format!(
        "# Figures\n\nGenerated by `exact-bezier figures --out {}` from `{}`; do not edit by hand.\n\
         To add a figure, add one entry to that file and rerun.\n\n",
        a.out, a.manifest
    );
    for e in &chosen {
        readme.push_str(&make(e, &a.out)?);
    }
    if a.only.is_none() {
        write_output(&format!("{}/README.md", a.out), readme.as_bytes())?;
    }
    Ok(json!({"out": a.out, "figures": chosen.iter().map(|e| e.name.clone()).collect::<Vec<_>>()}))
}
