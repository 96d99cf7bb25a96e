//! `figures [--manifest M] [--out DIR] [--only NAME] [--root ROOT]`:
//! regenerate the gallery.
//!
//! The gallery is data: `gallery.json` is a JSON array with one entry per
//! figure,
//!
//! ```text
//! {"name": "stem", "caption": "…", "inputs": [INPUT, …], "args": ["--iso", "10", …]}
//! ```
//!
//! where an INPUT is a JSON file path (relative to ROOT: by default the
//! crate's folder, so the command works from any working directory), or
//! `{"run": ["SUBCOMMAND", "ARG", …]}`: that command line is run in-process
//! (not `figures` or `prove`: no recursion; an ARG naming a file under ROOT
//! is that file) and its standard output (patches in the format of
//! docs/FORMAT.md) is saved as `OUT/inputs/stem.json` (`stem-K.json` for the
//! K-th of several) and used as the input. `args` are `plot` flags. Each
//! entry gives `OUT/stem.svg` and `OUT/stem.png`; an optional `"mesh":
//! ["--density", "24", …]` (`mesh` flags) also gives `OUT/stem.obj`.
//! `OUT/README.md` lists them all with their captions and commands, and is
//! rewritten in full on every run (also with `--only`).

use super::mesh as mesh_cmd;
use super::plot::{self as plot_cmd, write_output};
use super::read_input;
use clap::Parser;
use exact_bezier::Error;
use serde_json::{json, Value};
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// Arguments of `figures`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The gallery list (JSON array of entries) [default: ROOT/docs/figures/gallery.json].
    #[arg(long)]
    manifest: Option<String>,
    /// Folder for the images, derived inputs and README.md [default: ROOT/docs/figures].
    #[arg(long)]
    out: Option<String>,
    /// Regenerate only this entry (README.md is rewritten in full all the same).
    #[arg(long)]
    only: Option<String>,
    /// Folder that the gallery's input paths are relative to [default: the
    /// crate's folder, where this binary was built from], so `figures` works
    /// from any working directory.
    #[arg(long)]
    root: Option<String>,
}

/// Where the gallery's files are: paths as shown in README.md, and as opened.
struct Paths {
    root: PathBuf,
    /// `--out` as given, or `docs/figures`.
    out_shown: String,
    /// `--out` as given (relative to the working directory), or `ROOT/docs/figures`.
    out: String,
}

impl Paths {
    fn new(a: &Args) -> Self {
        // The repository's root: the workspace folder above this crate.
        let root = match a.root.as_deref() {
            Some(r) => PathBuf::from(r),
            None => PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/..")),
        };
        let (out_shown, out) = match &a.out {
            Some(o) => (o.clone(), o.clone()),
            None => (
                "docs/figures".to_string(),
                Self::under(&root, "docs/figures"),
            ),
        };
        Paths {
            root,
            out_shown,
            out,
        }
    }

    fn under(root: &Path, rel: &str) -> String {
        root.join(rel).to_string_lossy().into_owned()
    }

    /// `p` as opened: relative paths are relative to the root.
    fn open(&self, p: &str) -> String {
        Self::under(&self.root, p)
    }

    /// An argument of a `run` input: a path under the root if that file exists.
    fn arg(&self, a: &str) -> String {
        if self.root.join(a).is_file() {
            self.open(a)
        } else {
            a.to_string()
        }
    }
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

/// Run `exact-bezier SUB FILES… -o TARGET EXTRA…` in-process.
fn render(sub: &str, files: &[String], target: &str, extra: &[String]) -> Result<(), Error> {
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
    Ok(())
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

/// One input of an entry: the file as shown and as opened, and how it is
/// made (`None` for a file of the repository).
struct Input {
    shown: String,
    file: String,
    run: Option<Vec<String>>,
}

/// The input file for one INPUT (`stem` names the file of a `run` input).
fn input(input: &Value, paths: &Paths, stem: &str) -> Result<Input, Error> {
    if let Some(path) = input.as_str() {
        return Ok(Input {
            shown: path.to_string(),
            file: paths.open(path),
            run: None,
        });
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
    Ok(Input {
        shown: format!("{}/inputs/{stem}.json", paths.out_shown),
        file: format!("{}/inputs/{stem}.json", paths.out),
        run: Some(run),
    })
}

/// Write a `run` input's file by running its command in-process, under this
/// run's limits and work budget.
fn make_input(i: &Input, paths: &Paths) -> Result<(), Error> {
    let Some(run) = &i.run else { return Ok(()) };
    let argv = std::iter::once("exact-bezier".to_string()).chain(run.iter().map(|a| paths.arg(a)));
    let res = super::run_with(argv.collect(), super::Stdin::Bytes(Vec::new()));
    if res.code != 0 {
        return Err(Error::Format(format!(
            "exact-bezier {} failed: {}",
            run.join(" "),
            res.stderr.trim()
        )));
    }
    write_output(&i.file, res.stdout.as_bytes())
}

/// The inputs of an entry (one file per input; `stem-K` for the K-th of several).
fn inputs(e: &Entry, paths: &Paths) -> Result<Vec<Input>, Error> {
    (0..e.inputs.len())
        .map(|k| {
            let stem = if e.inputs.len() == 1 {
                e.name.clone()
            } else {
                format!("{}-{}", e.name, k + 1)
            };
            input(&e.inputs[k], paths, &stem)
        })
        .collect()
}

/// The `plot`/`mesh` command lines of an entry: (subcommand, target name, flags).
fn renders(e: &Entry) -> Vec<(&'static str, String, Vec<String>)> {
    let titled: Vec<String> = ["--title".to_string(), e.caption.clone()]
        .into_iter()
        .chain(e.args.iter().cloned())
        .collect();
    let mut v = vec![
        ("plot", format!("{}.svg", e.name), titled),
        ("plot", format!("{}.png", e.name), e.args.clone()),
    ];
    if let Some(m) = &e.mesh {
        v.push(("mesh", format!("{}.obj", e.name), m.clone()));
    }
    v
}

/// Make one figure: its inputs, SVG, PNG and OBJ.
fn make(e: &Entry, paths: &Paths) -> Result<(), Error> {
    let ins = inputs(e, paths)?;
    for i in &ins {
        make_input(i, paths)?;
    }
    let files: Vec<String> = ins.into_iter().map(|i| i.file).collect();
    for (sub, target, flags) in renders(e) {
        render(sub, &files, &format!("{}/{target}", paths.out), &flags)?;
    }
    Ok(())
}

/// The README.md section of one figure (the PNG and OBJ command lines, with
/// paths as shown).
fn section(e: &Entry, paths: &Paths) -> Result<String, Error> {
    let ins = inputs(e, paths)?;
    let mut s = format!(
        "## {}\n\n{}\n\n![{}]({}.png)\n\n",
        e.name, e.caption, e.name, e.name
    );
    for i in &ins {
        if let Some(run) = &i.run {
            let _ = writeln!(
                s,
                "- input `{}` = `exact-bezier {}`",
                i.shown,
                run.join(" ")
            );
        }
    }
    let shown: Vec<&str> = ins.iter().map(|i| i.shown.as_str()).collect();
    for (sub, target, flags) in renders(e).into_iter().skip(1) {
        let _ = writeln!(
            s,
            "- `exact-bezier {sub} {} -o {}/{target} {}`",
            shown.join(" "),
            paths.out_shown,
            flags.join(" ")
        );
    }
    s.push('\n');
    Ok(s)
}

/// Regenerate the gallery (or one entry of it, `--only`) and its README.md;
/// reports `{"figures": [names], "out": OUT}`.
pub fn run(a: &Args) -> Result<Value, Error> {
    let paths = Paths::new(a);
    let manifest_shown = a.manifest.as_deref().unwrap_or("docs/figures/gallery.json");
    let manifest_file = match &a.manifest {
        Some(m) => m.clone(),
        None => paths.open(manifest_shown),
    };
    let all = entries(&exact_bezier::io::parse_json(&read_input(&manifest_file)?)?)?;
    let chosen: Vec<&Entry> = all
        .iter()
        .filter(|e| a.only.as_ref().is_none_or(|n| *n == e.name))
        .collect();
    if let (true, Some(name)) = (chosen.is_empty(), &a.only) {
        let names: Vec<&str> = all.iter().map(|e| e.name.as_str()).collect();
        return Err(Error::Format(format!(
            "no gallery entry named {name:?}; the entries are {}",
            names.join(", ")
        )));
    }
    for e in &chosen {
        make(e, &paths)?;
    }
    let mut readme = format!(
        "# Figures\n\nGenerated by `exact-bezier figures --out {}` from `{manifest_shown}`; do not edit by hand.\n\
         To add a figure, add one entry to that file and rerun.\n\n",
        paths.out_shown
    );
    for e in &all {
        readme.push_str(&section(e, &paths)?);
    }
    write_output(&format!("{}/README.md", paths.out), readme.as_bytes())?;
    Ok(
        json!({"out": paths.out_shown, "figures": chosen.iter().map(|e| e.name.clone()).collect::<Vec<_>>()}),
    )
}
