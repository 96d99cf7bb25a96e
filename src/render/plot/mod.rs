//! Pictures of curves and patches: SVG written directly, PNG rasterized from
//! that SVG with `resvg` (pure Rust; no system font or graphics libraries).
//!
//! What is drawn:
//!
//! - a **curve**: the curve, its control polygon (light, dashed) and its
//!   control points; when the weights are not all 1, each control point's
//!   size grows with `√(ω/ω_max)` and the SVG labels it `w=ω` (exact text);
//! - a **rect or tri patch**: iso-parameter lines at equal parameter steps
//!   (`u = i/N`, `v = j/N`; on triangles also `w = k/N`) and the control net;
//! - **several patches**: one colour per piece, from a fixed palette;
//! - `speed`: dots at the equal parameter steps (`t = k/N` on curves, the
//!   grid nodes on patches), so the parameter speed, and a
//!   reparameterization, is visible (source 000, Figs 3 and 4);
//! - a [`Split`]: a rect patch over its two triangles `u + v ≤ 1`, `u + v ≥ 1`
//!   (source 003, Fig. 4), or a tri patch over the three quadrilaterals of
//!   source 003 Fig. 1 (`p₁ … p₅` from `a … f`, eq. 19), one colour each.
//!
//! The projection is [`Projection::View`] (axonometric) or
//! [`Projection::Plane`]; by default the `xy` plane when every point has
//! `z = 0`, else [`Projection::DEFAULT_3D`].
//!
//! ```
//! use exact_bezier::render::plot::{plot_svg, PlotOptions};
//! use exact_bezier::io::read_patches;
//! let c = read_patches(r#"{"kind": "curve", "degree": 2, "points": [[0,0],[1,2],[2,0]], "weights": [1, "1/2", 1]}"#).unwrap();
//! let svg = plot_svg(&c, &PlotOptions::default()).unwrap();
//! assert!(svg.contains(r#"class="net""#) && svg.contains(">w=1/2</text>"));
//! ```

mod png;
mod sample;
mod svg;
mod view;

pub use view::{Plane, Projection};

use crate::algebra::scalar::Ordered;
use crate::error::Error;
use crate::patch::Patch;
use num_traits::One;
use std::fmt::Display;

/// How a patch's domain is divided into separately coloured pieces.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum Split {
    /// The whole domain, one piece.
    #[default]
    None,
    /// A rect patch over its triangles Δ₁ = {u + v ≤ 1} and Δ₂ = {u + v ≥ 1}
    /// (source 003, §2 and Fig. 4).
    Diagonal,
    /// A tri patch over the quadrilaterals D₁ = p₁p₂p₃p₄, D₂ = p₂T₁p₅p₃,
    /// D₃ = p₄p₃p₅T₂ with `(u, v)` of p₁ = (0,0), p₂ = (b,0), p₃ = (a,c),
    /// p₄ = (0,d), p₅ = (e,f): the parameters `[a, b, c, d, e, f]`
    /// (source 003, eq. 19 and Fig. 1).
    Triangle([f64; 6]),
}

impl Split {
    /// A short name for messages.
    pub fn name(&self) -> &'static str {
        match self {
            Split::None => "none",
            Split::Diagonal => "diagonal",
            Split::Triangle(_) => "a,b,c,d,e,f",
        }
    }

    /// Read `diagonal` or six numbers `a,b,c,d,e,f` (exact text, drawn as
    /// `f64`), with `a, c, a + c, b, d` in `[0, 1]` and `e, f ≥ 0`,
    /// `e + f = 1` (p₅ on the edge T₁T₂).
    ///
    /// # Errors
    ///
    /// [`Error::BadNumber`] for unreadable numbers, [`Error::Domain`] when
    /// the points leave the triangle or there are not six of them.
    pub fn parse(text: &str) -> Result<Split, Error> {
        if text == "diagonal" {
            return Ok(Split::Diagonal);
        }
        let q = text
            .split(',')
            .map(crate::algebra::parse_rational)
            .collect::<Result<Vec<_>, _>>()?;
        let f: Vec<f64> = q.iter().map(Ordered::to_f64).collect();
        let unit = |x: f64| (0.0..=1.0).contains(&x);
        match f[..] {
            [a, b, c, d, e, g]
                if [a, b, c, d, e, g, a + c].into_iter().all(unit)
                    && q[4].clone() + &q[5] == num_rational::BigRational::one() =>
            {
                Ok(Split::Triangle([a, b, c, d, e, g]))
            }
            _ => Err(Error::Domain(format!(
                "--split wants 'diagonal' or a,b,c,d,e,f with a,b,c,d,a+c in [0,1], e,f ≥ 0, e+f = 1; got {text:?}"
            ))),
        }
    }
}

/// Everything that decides a picture besides the patches.
#[derive(Clone, Debug, PartialEq)]
pub struct PlotOptions {
    /// The projection; `None` chooses as in the module docs.
    pub projection: Option<Projection>,
    /// Width in pixels (16 to 8192).
    pub width: u32,
    /// Height in pixels (16 to 8192).
    pub height: u32,
    /// Iso-lines per direction: steps `1/iso` (1 to 200).
    pub iso: usize,
    /// Samples per line (1 to 4000).
    pub samples: usize,
    /// Mark the equal parameter steps with dots.
    pub speed: bool,
    /// Draw control polygons and nets.
    pub net: bool,
    /// How each patch's domain is divided.
    pub split: Split,
    /// The SVG `<title>`.
    pub title: String,
}

impl Default for PlotOptions {
    /// 800 × 600, 8 iso steps, 64 samples per line, nets on, no speed dots.
    fn default() -> Self {
        PlotOptions {
            projection: None,
            width: 800,
            height: 600,
            iso: 8,
            samples: 64,
            speed: false,
            net: true,
            split: Split::None,
            title: "exact-bezier".into(),
        }
    }
}

impl PlotOptions {
    fn density(&self) -> sample::Density {
        sample::Density {
            iso: self.iso,
            samples: self.samples,
            speed: self.speed,
            net: self.net,
        }
    }

    fn check(&self) -> Result<(), Error> {
        let px = 16..=8192;
        if !px.contains(&self.width) || !px.contains(&self.height) {
            return Err(Error::Domain(format!(
                "picture size {}×{} must be within 16 to 8192 pixels each way",
                self.width, self.height
            )));
        }
        if !(1..=200).contains(&self.iso) || !(1..=4000).contains(&self.samples) {
            return Err(Error::Domain(format!(
                "--iso {} must be 1 to 200 and --samples {} 1 to 4000",
                self.iso, self.samples
            )));
        }
        Ok(())
    }
}

/// The SVG picture of `patches`.
///
/// # Errors
///
/// [`Error::Domain`] for options out of range; [`Error::Shape`] for a split
/// that does not fit a patch kind; [`Error::NotFinite`] /
/// [`Error::PointAtInfinity`] when a point cannot be drawn (more than 3
/// coordinates, or a zero weight on the curve).
pub fn plot_svg<T: Ordered + Display>(
    patches: &[Patch<T>],
    opts: &PlotOptions,
) -> Result<String, Error> {
    opts.check()?;
    let drawing = sample::draw(patches, &opts.split, opts.density())?;
    Ok(finish(&drawing, opts))
}

/// The PNG picture of `items`, each curve or patch in its own palette
/// colour (index mod 8: 0 blue, 1 red, 2 green, 3 purple, 4 orange, 5 cyan,
/// 6 brown, 7 pink); no nets (`audit --plot` colours seams by verdict).
///
/// # Errors
///
/// As [`plot_svg`].
pub fn plot_colored_png<T: Ordered + Display>(
    items: &[(Patch<T>, usize)],
    opts: &PlotOptions,
) -> Result<Vec<u8>, Error> {
    opts.check()?;
    let drawing = sample::draw_colored(items, opts.density())?;
    png::rasterize(&finish(&drawing, opts))
}

/// Project and write a drawing as SVG.
fn finish(drawing: &sample::Drawing, opts: &PlotOptions) -> String {
    let flat = drawing
        .strokes
        .iter()
        .flat_map(|s| &s.points)
        .chain(drawing.dots.iter().map(|d| &d.at))
        .all(|p| p[2] == 0.0);
    let proj = opts.projection.unwrap_or(if flat {
        Projection::Plane(Plane::Xy)
    } else {
        Projection::DEFAULT_3D
    });
    svg::write(drawing, proj, opts.width, opts.height, &opts.title)
}

/// The PNG picture of `patches`: [`plot_svg`] rasterized (labels omitted).
///
/// # Errors
///
/// As [`plot_svg`].
pub fn plot_png<T: Ordered + Display>(
    patches: &[Patch<T>],
    opts: &PlotOptions,
) -> Result<Vec<u8>, Error> {
    png::rasterize(&plot_svg(patches, opts)?)
}
