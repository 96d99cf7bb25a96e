//! Sampling patches into a [`Drawing`]: polylines, dots and labels in model
//! space (3D; 2D points get `z = 0`).
//!
//! Every line is drawn at **equal parameter steps**: iso-lines at
//! `u = i/N`, `v = j/N` (and `w = k/N` on triangles), sampled at equal steps
//! along the line, so a reparameterization changes the picture.
//!
//! A patch is drawn over one or more *pieces* of its parameter domain: a
//! quadrilateral mapped bilinearly from `[0,1]²`,
//! `L(s,t) = (1−s)(1−t)c₀ + s(1−t)c₁ + st·c₂ + (1−s)t·c₃` (source 003,
//! eq. 20), or a triangle mapped linearly from barycentric `(a, b, c)`,
//! `a·V₀ + b·V₁ + c·V₂`. A [`Split`] chooses pieces that show how a patch
//! divides (source 003, Figs 1, 4, 5).

use super::Split;
use crate::algebra::scalar::Ordered;
use crate::error::Error;
use crate::eval::Evaluator;
use crate::patch::Patch;
use std::fmt::Display;

/// What a mark shows; decides its style.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Role {
    /// Control polygon or net (light, dashed).
    Net,
    /// A curve or an iso-parameter line.
    Surface,
    /// A point at an equal parameter step (`--speed`).
    Speed,
    /// A control point (size grows with its weight).
    Ctrl,
}

/// A polyline in model space.
#[derive(Clone, Debug)]
pub(crate) struct Stroke {
    pub role: Role,
    pub color: usize,
    pub points: Vec<[f64; 3]>,
}

/// A dot in model space, radius in pixels.
#[derive(Clone, Debug)]
pub(crate) struct Dot {
    pub role: Role,
    pub color: usize,
    pub at: [f64; 3],
    pub radius: f64,
}

/// A text label in model space (drawn in SVG only).
#[derive(Clone, Debug)]
pub(crate) struct Label {
    pub color: usize,
    pub at: [f64; 3],
    pub text: String,
}

/// Everything to draw, before projection.
#[derive(Clone, Debug, Default)]
pub(crate) struct Drawing {
    pub strokes: Vec<Stroke>,
    pub dots: Vec<Dot>,
    pub labels: Vec<Label>,
}

/// Sampling density: `iso` lines per direction, `samples` points per line.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Density {
    pub iso: usize,
    pub samples: usize,
    pub speed: bool,
    pub net: bool,
}

/// A piece of a parameter domain (see the module docs).
#[derive(Clone, Copy, Debug)]
enum Domain {
    Quad([[f64; 2]; 4]),
    Triangle([[f64; 2]; 3]),
}

impl Domain {
    /// The `(u, v)` of local coordinates: `(s, t)` for a quad, barycentric
    /// `(a, b, 1 − a − b)` for a triangle.
    fn at(&self, s: f64, t: f64) -> [f64; 2] {
        let mix = |c: &[[f64; 2]], w: &[f64]| {
            let f = |k: usize| c.iter().zip(w).map(|(p, x)| p[k] * x).sum();
            [f(0), f(1)]
        };
        match self {
            Domain::Quad(c) => mix(
                c,
                &[(1.0 - s) * (1.0 - t), s * (1.0 - t), s * t, (1.0 - s) * t],
            ),
            Domain::Triangle(c) => mix(c, &[s, t, 1.0 - s - t]),
        }
    }

    /// Local coordinates of the iso-lines, each a list of `(s, t)`.
    fn iso_lines(&self, d: Density) -> Vec<Vec<(f64, f64)>> {
        let (n, m) = (d.iso as f64, d.samples as f64);
        let steps =
            |f: &dyn Fn(f64) -> (f64, f64)| (0..=d.samples).map(|k| f(k as f64 / m)).collect();
        let mut lines = Vec::new();
        match self {
            Domain::Quad(_) => {
                for i in 0..=d.iso {
                    let c = i as f64 / n;
                    lines.push(steps(&|x| (c, x)));
                    lines.push(steps(&|x| (x, c)));
                }
            }
            Domain::Triangle(_) => {
                // One family per barycentric coordinate held at k/N < 1.
                for k in 0..d.iso {
                    let c = k as f64 / n;
                    let r = 1.0 - c;
                    lines.push(steps(&|x| (c, r * (1.0 - x))));
                    lines.push(steps(&|x| (r * x, c)));
                    lines.push(steps(&|x| (r * (1.0 - x), r * x)));
                }
            }
        }
        lines
    }

    /// Local coordinates of the parameter grid nodes (`--speed`).
    fn nodes(&self, iso: usize) -> Vec<(f64, f64)> {
        let n = iso as f64;
        let all = (0..=iso).flat_map(|i| (0..=iso).map(move |j| (i, j)));
        match self {
            Domain::Quad(_) => all.map(|(i, j)| (i as f64 / n, j as f64 / n)).collect(),
            Domain::Triangle(_) => all
                .filter(|(i, j)| i + j <= iso)
                .map(|(i, j)| (i as f64 / n, j as f64 / n))
                .collect(),
        }
    }
}

/// The pieces of a patch's domain for a split.
fn pieces(patch: &Patch<f64>, split: &Split) -> Result<Vec<Domain>, Error> {
    const UNIT: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    // Triangle vertices T₁ (u=1), T₂ (v=1), T₃ (w=1).
    let (t1, t2, t3) = ([1.0, 0.0], [0.0, 1.0], [0.0, 0.0]);
    Ok(match (patch, split) {
        (Patch::Rect(_), Split::None) => vec![Domain::Quad(UNIT)],
        (Patch::Rect(_), Split::Diagonal) => vec![
            Domain::Triangle([t1, t2, t3]),
            Domain::Triangle([t2, t1, [1.0, 1.0]]),
        ],
        (Patch::Tri(_), Split::None) => vec![Domain::Triangle([t1, t2, t3])],
        (Patch::Tri(_), Split::Triangle(p)) => {
            let [a, b, c, d, e, f] = *p;
            let (p1, p2, p3, p4, p5) = (t3, [b, 0.0], [a, c], [0.0, d], [e, f]);
            vec![
                Domain::Quad([p1, p2, p3, p4]),
                Domain::Quad([p2, t1, p5, p3]),
                Domain::Quad([p4, p3, p5, t2]),
            ]
        }
        (Patch::Curve(_), Split::None) => Vec::new(),
        (p, s) => {
            return Err(Error::Shape(format!(
                "the split {} does not apply to a {}",
                s.name(),
                p.kind()
            )))
        }
    })
}

/// Sample `patches` into a drawing; colours are numbered per piece.
pub(crate) fn draw<T: Ordered + Display>(
    patches: &[Patch<T>],
    split: &Split,
    d: Density,
) -> Result<Drawing, Error> {
    let mut out = Drawing::default();
    let mut color = 0;
    for p in patches {
        let pf = p.map(Ordered::to_f64);
        let first = color;
        if let Patch::Curve(_) = &pf {
            curve(&mut out, &pf, color, d)?;
            color += 1;
        }
        for dom in pieces(&pf, split)? {
            piece(&mut out, &pf, &dom, color, d)?;
            color += 1;
        }
        if d.net {
            net(&mut out, p, first)?;
        }
    }
    Ok(out)
}

/// Sample `items` into a drawing, each in its given colour, without nets
/// (the audit's seam picture).
pub(crate) fn draw_colored<T: Ordered + Display>(
    items: &[(Patch<T>, usize)],
    d: Density,
) -> Result<Drawing, Error> {
    let mut out = Drawing::default();
    for (p, color) in items {
        let pf = p.map(Ordered::to_f64);
        if let Patch::Curve(_) = &pf {
            curve(&mut out, &pf, *color, d)?;
        }
        for dom in pieces(&pf, &Split::None)? {
            piece(&mut out, &pf, &dom, *color, d)?;
        }
    }
    Ok(out)
}

/// The points of a patch at the parameters `uvs` (`[t, _]` for a curve),
/// as 3D `f64`, by one batch evaluation.
fn points(p: &Patch<f64>, uvs: impl Iterator<Item = [f64; 2]>) -> Result<Vec<[f64; 3]>, Error> {
    let (mut ev, per_point) = match p {
        Patch::Curve(c) => (Evaluator::curve(c), 1),
        Patch::Rect(r) => (Evaluator::rect(r), 2),
        Patch::Tri(t) => (Evaluator::tri(t), 2),
    };
    let params: Vec<f64> = uvs.flat_map(|uv| uv.into_iter().take(per_point)).collect();
    let d = ev.net().dim();
    let mut out = vec![0.0; params.len() / per_point * d];
    ev.eval_batch(&params, &mut out)?;
    out.chunks(d).map(to3).collect()
}

fn to3(x: &[f64]) -> Result<[f64; 3], Error> {
    if x.len() > 3 || x.iter().any(|c| !c.is_finite()) {
        return Err(Error::NotFinite(format!(
            "cannot draw the point {x:?}: it must be finite and 1D to 3D"
        )));
    }
    let mut p = [0.0; 3];
    p[..x.len()].copy_from_slice(x);
    Ok(p)
}

fn curve(out: &mut Drawing, p: &Patch<f64>, color: usize, d: Density) -> Result<(), Error> {
    let m = d.samples as f64;
    stroke(out, p, color, (0..=d.samples).map(|k| [k as f64 / m, 0.0]))?;
    if d.speed {
        let n = d.iso as f64;
        speed_dots(out, p, color, (0..=d.iso).map(|k| [k as f64 / n, 0.0]))?;
    }
    Ok(())
}

fn piece(
    out: &mut Drawing,
    p: &Patch<f64>,
    dom: &Domain,
    color: usize,
    d: Density,
) -> Result<(), Error> {
    for line in dom.iso_lines(d) {
        stroke(out, p, color, line.iter().map(|&(s, t)| dom.at(s, t)))?;
    }
    if d.speed {
        let nodes = dom.nodes(d.iso);
        speed_dots(out, p, color, nodes.iter().map(|&(s, t)| dom.at(s, t)))?;
    }
    Ok(())
}

/// The polyline through `p` at the parameters `uvs`.
fn stroke(
    out: &mut Drawing,
    p: &Patch<f64>,
    color: usize,
    uvs: impl Iterator<Item = [f64; 2]>,
) -> Result<(), Error> {
    let points = points(p, uvs)?;
    out.strokes.push(Stroke {
        role: Role::Surface,
        color,
        points,
    });
    Ok(())
}

/// A `--speed` dot on `p` at each of the parameters `uvs`.
fn speed_dots(
    out: &mut Drawing,
    p: &Patch<f64>,
    color: usize,
    uvs: impl Iterator<Item = [f64; 2]>,
) -> Result<(), Error> {
    for at in points(p, uvs)? {
        out.dots.push(Dot {
            role: Role::Speed,
            color,
            at,
            radius: 2.5,
        });
    }
    Ok(())
}

/// Control polygon / net, control points sized by |weight|, and (curves)
/// weight labels when the weights are not all 1.
fn net<T: Ordered + Display>(out: &mut Drawing, p: &Patch<T>, color: usize) -> Result<(), Error> {
    let (grid, weights): (Vec<Vec<Vec<T>>>, Vec<Vec<T>>) = match p {
        Patch::Curve(c) => (vec![c.points()?], vec![c.weights()]),
        Patch::Rect(r) => (r.points()?, r.weights()),
        Patch::Tri(t) => {
            let pts = t
                .rows()
                .iter()
                .map(|row| row.iter().map(|h| h.project()).collect())
                .collect::<Result<_, _>>()?;
            (pts, t.weights())
        }
    };
    let grid: Vec<Vec<[f64; 3]>> = grid
        .iter()
        .map(|row| {
            row.iter()
                .map(|x| to3(&x.iter().map(Ordered::to_f64).collect::<Vec<_>>()))
                .collect()
        })
        .collect::<Result<_, _>>()?;
    for line in net_lines(p, &grid) {
        out.strokes.push(Stroke {
            role: Role::Net,
            color,
            points: line,
        });
    }
    let all_one = weights.iter().flatten().all(|w| *w == T::one());
    let wmax = weights
        .iter()
        .flatten()
        .map(|w| w.to_f64().abs())
        .fold(0.0, f64::max);
    for (row, wrow) in grid.iter().zip(&weights) {
        for (&at, w) in row.iter().zip(wrow) {
            let radius = if all_one {
                3.0
            } else {
                2.0 + 5.0 * (w.to_f64().abs() / wmax).sqrt()
            };
            out.dots.push(Dot {
                role: Role::Ctrl,
                color,
                at,
                radius,
            });
            if !all_one && matches!(p, Patch::Curve(_)) {
                out.labels.push(Label {
                    color,
                    at,
                    text: format!("w={w}"),
                });
            }
        }
    }
    Ok(())
}

/// The polylines of a control net: the polygon of a curve; rows and columns
/// of a rect net; the three directions (constant j, constant i, constant
/// k = n − i − j) of a tri net.
fn net_lines<T>(p: &Patch<T>, grid: &[Vec<[f64; 3]>]) -> Vec<Vec<[f64; 3]>> {
    let mut lines: Vec<Vec<[f64; 3]>> = Vec::new();
    match p {
        Patch::Curve(_) | Patch::Rect(_) => {
            lines.extend(grid.iter().cloned());
            if !matches!(p, Patch::Curve(_)) {
                lines.extend((0..grid[0].len()).map(|j| grid.iter().map(|row| row[j]).collect()));
            }
        }
        Patch::Tri(_) => {
            let n = grid.len() - 1;
            lines.extend(grid.iter().cloned());
            lines.extend((0..=n).map(|i| (0..=n - i).map(|j| grid[j][i]).collect()));
            lines.extend((0..=n).map(|k| (0..=n - k).map(|j| grid[j][n - k - j]).collect()));
        }
    }
    lines.retain(|l| l.len() > 1);
    lines
}
