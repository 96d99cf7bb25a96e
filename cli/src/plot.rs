//! `plot FILE... -o OUT.svg|OUT.png [--view AZ,EL | --plane xy|xz|yz]
//! [--width W] [--height H] [--iso N] [--samples S] [--speed] [--no-net]
//! [--split diagonal|a,b,c,d,e,f] [--title T]`.

use super::{charge_each, load_all_exact, on_exact, ExactScalar, ScalarKind};
use exact_bezier::limits::{self, MAX_PIXELS, MAX_PLOT_POINTS};
use exact_bezier::patch::Patch;
use exact_bezier::render::plot::{plot_png, plot_svg, PlotOptions, Projection, Split};
use exact_bezier::Error;

use serde_json::{json, Value};

/// Arguments of `plot`.
#[derive(clap::Args, Debug, Clone)]
pub struct Args {
    /// Input files (JSON); all their curves and patches go into one picture.
    #[arg(required = true)]
    files: Vec<String>,
    /// Output file: .svg or .png.
    #[arg(short, long)]
    output: String,
    /// Axonometric view: azimuth,elevation in degrees (default -60,30 for 3D input).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "plane")]
    view: Option<String>,
    /// Orthographic view onto a coordinate plane: xy, xz or yz.
    #[arg(long)]
    plane: Option<String>,
    /// Width in pixels.
    #[arg(long, default_value_t = 800)]
    width: u32,
    /// Height in pixels.
    #[arg(long, default_value_t = 600)]
    height: u32,
    /// Iso-parameter lines at steps 1/N (and speed dots at the same steps).
    #[arg(long, default_value_t = 8)]
    iso: usize,
    /// Samples along each curve or iso-line.
    #[arg(long, default_value_t = 64)]
    samples: usize,
    /// Mark equal parameter steps with dots, so the parameter speed shows.
    #[arg(long)]
    speed: bool,
    /// Leave out control polygons and nets.
    #[arg(long)]
    no_net: bool,
    /// Colour the pieces of a split: 'diagonal' (rect → two triangles) or
    /// a,b,c,d,e,f (tri → three quadrilaterals, source 003 Fig. 1).
    #[arg(long)]
    split: Option<String>,
    /// Title stored in the SVG.
    #[arg(long)]
    title: Option<String>,
}

impl Args {
    fn options(&self) -> Result<PlotOptions, Error> {
        let projection = match (&self.view, &self.plane) {
            (Some(v), _) => Some(Projection::parse_view(v)?),
            (None, Some(p)) => Some(Projection::parse_plane(p)?),
            (None, None) => None,
        };
        Ok(PlotOptions {
            projection,
            width: self.width,
            height: self.height,
            iso: self.iso,
            samples: self.samples,
            speed: self.speed,
            net: !self.no_net,
            split: self
                .split
                .as_deref()
                .map_or(Ok(Split::None), Split::parse)?,
            title: self.title.clone().unwrap_or_else(|| self.files.join(" + ")),
        })
    }
}

/// Write the picture; reports `{"output": OUT, "format": "svg"|"png", "patches": n}`.
pub fn run(a: &Args) -> Result<Value, Error> {
    let opts = a.options()?;
    on_exact!(load_all_exact(&a.files)?, patches => plot_to(a, &patches, &opts))
}

/// Draw `patches` into the output file of `a`.
fn plot_to<T: ExactScalar>(
    a: &Args,
    patches: &[Patch<T>],
    opts: &PlotOptions,
) -> Result<Value, Error> {
    let lower = a.output.to_ascii_lowercase();
    check_plot_size(patches, opts, lower.ends_with(".png"))?;
    let (bytes, format) = if lower.ends_with(".svg") {
        (plot_svg(patches, opts)?.into_bytes(), "svg")
    } else if lower.ends_with(".png") {
        (plot_png(patches, opts)?, "png")
    } else {
        return Err(Error::Format(format!(
            "the output {:?} must end in .svg or .png",
            a.output
        )));
    };
    write_output(&a.output, &bytes)?;
    Ok(json!({"output": a.output, "format": format, "patches": patches.len()}))
}

/// Refuse pictures over [`MAX_PIXELS`] or [`MAX_PLOT_POINTS`] sample
/// points (curves, iso-lines both ways, speed dots), then charge the `f64`
/// evaluations of the samples and, for a PNG (`raster`), the rasterizing
/// and encoding of every pixel ([`PNG_UNITS_PER_PIXEL`]).
fn check_plot_size<T: ExactScalar>(
    patches: &[Patch<T>],
    opts: &PlotOptions,
    raster: bool,
) -> Result<(), Error> {
    let pixels = u64::from(opts.width) * u64::from(opts.height);
    if pixels > MAX_PIXELS {
        return Err(Error::Limit(format!(
            "a {}×{} picture has {pixels} pixels, over the limit of {MAX_PIXELS}",
            opts.width, opts.height
        )));
    }
    let (iso, samples) = (opts.iso as u64 + 1, opts.samples as u64 + 1);
    let per_surface = 2 * iso * samples + iso * iso;
    let points: u64 = patches
        .iter()
        .map(|p| match p {
            Patch::Curve(_) => samples + iso,
            _ => per_surface,
        })
        .sum();
    if points > MAX_PLOT_POINTS {
        return Err(Error::Limit(format!(
            "--iso {} and --samples {} on {} patches give {points} sample points, over the limit of {MAX_PLOT_POINTS}",
            opts.iso,
            opts.samples,
            patches.len()
        )));
    }
    charge_each("plot", patches, ScalarKind::F64, |s| {
        (s.eval_ops().saturating_mul(per_surface), 0)
    })?;
    if raster {
        limits::charge("plot (PNG)", pixels.saturating_mul(PNG_UNITS_PER_PIXEL))?;
    }
    Ok(())
}

/// Work units of rasterizing and encoding one pixel of a PNG: 800×600
/// pixels of a (8, 8) rect took 15 ms more than its SVG (release build,
/// `cli/benches/cost_model.rs`), 31 ns a pixel.
pub(crate) const PNG_UNITS_PER_PIXEL: u64 = 4;

/// Write `bytes` to `path`, creating its folder.
pub(super) fn write_output(path: &str, bytes: &[u8]) -> Result<(), Error> {
    let p = std::path::Path::new(path);
    if let Some(dir) = p.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| {
            Error::Format(format!(
                "cannot create {:?}: {e}",
                dir.display().to_string()
            ))
        })?;
    }
    std::fs::write(p, bytes).map_err(|e| Error::Format(format!("cannot write {path:?}: {e}")))
}
