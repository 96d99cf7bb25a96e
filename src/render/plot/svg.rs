//! Writing a [`Drawing`] as SVG 1.1 text (hand-written XML: a handful of
//! `polyline`, `circle` and `text` elements need no library).
//!
//! Element classes, for styling and for tests: `line` (curves and
//! iso-lines), `net` (control polygons and nets), `ctrl` (control points),
//! `speed` (equal-parameter-step points), `weight` (weight labels).

use super::sample::{Drawing, Role};
use super::view::{Frame, Projection};
use std::fmt::Write;

/// Distinct colours, one per piece (cycled): a colour-blind-aware set.
const PALETTE: [&str; 8] = [
    "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2",
];

/// Margin around the drawing, in pixels (at most a tenth of the shorter
/// side, so small pictures keep a positive drawing area).
const MARGIN: f64 = 30.0;

fn color(k: usize) -> &'static str {
    PALETTE[k % PALETTE.len()]
}

/// Escape text for XML content and attributes.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The SVG document for `drawing` seen through `proj`, fitted into
/// `width × height` pixels; `title` goes into a `<title>` element.
pub(crate) fn write(
    drawing: &Drawing,
    proj: Projection,
    width: u32,
    height: u32,
    title: &str,
) -> String {
    let (w, h) = (f64::from(width), f64::from(height));
    let flat = drawing
        .strokes
        .iter()
        .flat_map(|s| s.points.iter())
        .chain(drawing.dots.iter().map(|d| &d.at))
        .map(|&p| proj.apply(p));
    let frame = Frame::fit(flat, w, h, MARGIN.min(w.min(h) / 10.0));
    let px = |p: [f64; 3]| frame.apply(proj.apply(p));
    let mut s = String::new();
    let _ = writeln!(s, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="{width}" height="{height}" viewBox="0 0 {width} {height}">"#
    );
    let _ = writeln!(s, "<title>{}</title>", escape(title));
    let _ = writeln!(
        s,
        r#"<rect x="0" y="0" width="{width}" height="{height}" fill="white"/>"#
    );
    // Nets under the lines, points on top.
    for role in [Role::Net, Role::Surface] {
        for st in drawing.strokes.iter().filter(|st| st.role == role) {
            let pts: Vec<String> = st
                .points
                .iter()
                .map(|&p| {
                    let q = px(p);
                    format!("{:.2},{:.2}", q[0], q[1])
                })
                .collect();
            let style = match role {
                Role::Net => {
                    r#"class="net" stroke-width="1" stroke-opacity="0.45" stroke-dasharray="5 3""#
                }
                _ => r#"class="line" stroke-width="1.6""#,
            };
            let _ = writeln!(
                s,
                r#"<polyline {style} fill="none" stroke="{}" stroke-linejoin="round" points="{}"/>"#,
                color(st.color),
                pts.join(" ")
            );
        }
    }
    for d in &drawing.dots {
        let q = px(d.at);
        let c = color(d.color);
        let style = match d.role {
            Role::Ctrl => format!(
                r#"class="ctrl" fill="white" fill-opacity="0.8" stroke="{c}" stroke-opacity="0.6" stroke-width="1.2""#
            ),
            _ => format!(r#"class="speed" fill="{c}""#),
        };
        let _ = writeln!(
            s,
            r#"<circle {style} cx="{:.2}" cy="{:.2}" r="{:.2}"/>"#,
            q[0], q[1], d.radius
        );
    }
    for l in &drawing.labels {
        let q = px(l.at);
        let _ = writeln!(
            s,
            r#"<text class="weight" x="{:.2}" y="{:.2}" font-family="sans-serif" font-size="13" fill="{}">{}</text>"#,
            q[0] + 7.0,
            q[1] - 7.0,
            color(l.color),
            escape(&l.text)
        );
    }
    s.push_str("</svg>\n");
    s
}
