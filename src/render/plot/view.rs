//! Projections from model space to the picture plane, and the fit of a
//! drawing into a `width × height` pixel box.

use crate::error::Error;

/// How 3D points are mapped to the picture plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Axonometric (orthographic) view from azimuth `az` and elevation `el`
    /// in degrees, as in common plotting tools: the eye looks from the
    /// direction `(cos el·cos az, cos el·sin az, sin el)`;
    ///
    /// ```text
    /// x′ = −sin az·x + cos az·y
    /// y′ = cos el·z − sin el·(cos az·x + sin az·y)
    /// ```
    View {
        /// Azimuth in degrees (rotation about z, from the x axis).
        az: f64,
        /// Elevation in degrees (above the xy plane).
        el: f64,
    },
    /// Drop one coordinate: the `xy`, `xz` or `yz` plane.
    Plane(Plane),
}

/// A coordinate plane for [`Projection::Plane`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Plane {
    /// Keep x and y.
    Xy,
    /// Keep x and z.
    Xz,
    /// Keep y and z.
    Yz,
}

impl Projection {
    /// The default for 3D input: azimuth −60°, elevation 30°.
    pub const DEFAULT_3D: Projection = Projection::View {
        az: -60.0,
        el: 30.0,
    };

    /// The picture-plane point of `p` (y up).
    ///
    /// # Examples
    ///
    /// ```
    /// use exact_bezier::render::plot::{Plane, Projection};
    /// assert_eq!(Projection::Plane(Plane::Xz).apply([1.0, 2.0, 3.0]), [1.0, 3.0]);
    /// let top = Projection::View { az: -90.0, el: 90.0 }; // from above, x right
    /// let q = top.apply([1.0, 2.0, 3.0]);
    /// assert!((q[0] - 1.0).abs() < 1e-12 && (q[1] - 2.0).abs() < 1e-12);
    /// ```
    pub fn apply(&self, p: [f64; 3]) -> [f64; 2] {
        match *self {
            Projection::Plane(Plane::Xy) => [p[0], p[1]],
            Projection::Plane(Plane::Xz) => [p[0], p[2]],
            Projection::Plane(Plane::Yz) => [p[1], p[2]],
            Projection::View { az, el } => {
                let (sa, ca) = az.to_radians().sin_cos();
                let (se, ce) = el.to_radians().sin_cos();
                [
                    -sa * p[0] + ca * p[1],
                    ce * p[2] - se * (ca * p[0] + sa * p[1]),
                ]
            }
        }
    }

    /// Read `--view AZ,EL` (degrees, finite).
    ///
    /// # Errors
    ///
    /// [`Error::BadNumber`] unless the text is two finite numbers.
    pub fn parse_view(text: &str) -> Result<Projection, Error> {
        let nums: Vec<f64> = text
            .split(',')
            .map(|s| s.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| {
                Error::BadNumber(format!("--view wants AZ,EL in degrees, not {text:?}"))
            })?;
        match nums[..] {
            [az, el] if az.is_finite() && el.is_finite() => Ok(Projection::View { az, el }),
            _ => Err(Error::BadNumber(format!(
                "--view wants two finite angles AZ,EL, not {text:?}"
            ))),
        }
    }

    /// Read `--plane xy|xz|yz`.
    ///
    /// # Errors
    ///
    /// [`Error::Format`] for any other text.
    pub fn parse_plane(text: &str) -> Result<Projection, Error> {
        let plane = match text {
            "xy" => Plane::Xy,
            "xz" => Plane::Xz,
            "yz" => Plane::Yz,
            _ => {
                return Err(Error::Format(format!(
                    "--plane must be xy, xz or yz, not {text:?}"
                )))
            }
        };
        Ok(Projection::Plane(plane))
    }
}

/// The similarity that maps picture-plane points into a pixel box with a
/// margin, keeping the aspect ratio, with y pointing down as in SVG.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Frame {
    scale: f64,
    offset: [f64; 2],
}

impl Frame {
    /// Fit the bounding box of `points` into `width × height` pixels with
    /// `margin` pixels on each side, centred. A single point (or none) is
    /// placed in the centre.
    pub(crate) fn fit(
        points: impl Iterator<Item = [f64; 2]>,
        width: f64,
        height: f64,
        margin: f64,
    ) -> Frame {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if lo[0] > hi[0] {
            (lo, hi) = ([0.0; 2], [0.0; 2]);
        }
        let span = [hi[0] - lo[0], hi[1] - lo[1]];
        let avail = [width - 2.0 * margin, height - 2.0 * margin];
        let scale = [avail[0] / span[0], avail[1] / span[1]]
            .into_iter()
            .filter(|s| s.is_finite())
            .fold(f64::INFINITY, f64::min);
        let scale = if scale.is_finite() { scale } else { 1.0 };
        let centre = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
        Frame {
            scale,
            offset: [
                width / 2.0 - scale * centre[0],
                height / 2.0 + scale * centre[1],
            ],
        }
    }

    /// The pixel position of a picture-plane point.
    pub(crate) fn apply(&self, p: [f64; 2]) -> [f64; 2] {
        [
            self.offset[0] + self.scale * p[0],
            self.offset[1] - self.scale * p[1],
        ]
    }
}
