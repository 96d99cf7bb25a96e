//! Pictures: the SVG parses as XML with the expected elements inside its
//! viewBox, the PNG decodes to the asked size with the expected colours,
//! the CLI writes both and rejects bad requests, and the gallery regenerates.

use crate::common::bin;
use exact_bezier::render::plot::{plot_png, plot_svg, Plane, PlotOptions, Projection, Split};
use exact_bezier::{io::read_patches, Patch};
use num_rational::BigRational;
use resvg::tiny_skia::Pixmap;
use std::path::PathBuf;

const EXAMPLE1: &str = include_str!("../../../tests/fixtures/yang_yong_example1.json");
const TRI: &str = include_str!("../../../docs/figures/inputs/source003_fig5a_tri.json");
const CUBIC: &str = r#"{"kind": "curve", "degree": 3,
 "points": [[0,0],[1,2],[3,2],[4,0]], "weights": [1, "1/3", "1/3", 1]}"#;

fn patches(text: &str) -> Vec<Patch<BigRational>> {
    read_patches(text).unwrap()
}

/// Elements of an SVG by class, with all drawn coordinates checked to lie
/// in the viewBox.
struct Svg {
    width: f64,
    height: f64,
    classes: Vec<(String, String)>,
    texts: Vec<String>,
}

impl Svg {
    fn parse(text: &str) -> Svg {
        let doc = roxmltree::Document::parse(text).expect("well-formed XML");
        let root = doc.root_element();
        assert_eq!(root.tag_name().name(), "svg");
        let vb: Vec<f64> = root
            .attribute("viewBox")
            .unwrap()
            .split(' ')
            .map(|x| x.parse().unwrap())
            .collect();
        assert_eq!(vb[..2], [0.0, 0.0]);
        let (width, height) = (vb[2], vb[3]);
        let inside = |x: f64, y: f64| {
            assert!(
                (0.0..=width).contains(&x) && (0.0..=height).contains(&y),
                "({x}, {y}) outside the viewBox {width}×{height}"
            )
        };
        let mut classes = Vec::new();
        let mut texts = Vec::new();
        for n in root.descendants().filter(|n| n.is_element()) {
            let num = |a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
            match n.tag_name().name() {
                "polyline" => {
                    let pts = n.attribute("points").unwrap();
                    assert!(pts.split(' ').count() >= 2);
                    for p in pts.split(' ') {
                        let (x, y) = p.split_once(',').unwrap();
                        inside(x.parse().unwrap(), y.parse().unwrap());
                    }
                }
                "circle" => inside(num("cx"), num("cy")),
                "text" => texts.push(n.text().unwrap_or_default().to_string()),
                _ => {}
            }
            if let Some(c) = n.attribute("class") {
                classes.push((n.tag_name().name().to_string(), c.to_string()));
            }
        }
        Svg {
            width,
            height,
            classes,
            texts,
        }
    }

    fn count(&self, tag: &str, class: &str) -> usize {
        self.classes
            .iter()
            .filter(|(t, c)| t == tag && c == class)
            .count()
    }
}

fn opts(iso: usize) -> PlotOptions {
    PlotOptions {
        iso,
        ..PlotOptions::default()
    }
}

#[test]
fn rect_svg_has_iso_lines_and_net_inside_the_view_box() {
    let svg = Svg::parse(&plot_svg(&patches(EXAMPLE1), &opts(5)).unwrap());
    assert_eq!((svg.width, svg.height), (800.0, 600.0));
    // 6 lines u = i/5 and 6 lines v = j/5; a 3×3 net has 3 rows + 3 columns.
    assert_eq!(svg.count("polyline", "line"), 12);
    assert_eq!(svg.count("polyline", "net"), 6);
    assert_eq!(svg.count("circle", "ctrl"), 9);
    assert_eq!(svg.count("circle", "speed"), 0);
    assert!(svg.texts.is_empty(), "surfaces carry no weight labels");
}

#[test]
fn speed_dots_sit_on_the_parameter_grid() {
    let o = PlotOptions {
        speed: true,
        ..opts(4)
    };
    let svg = Svg::parse(&plot_svg(&patches(EXAMPLE1), &o).unwrap());
    assert_eq!(svg.count("circle", "speed"), 25);
    let tri = Svg::parse(&plot_svg(&patches(TRI), &o).unwrap());
    assert_eq!(tri.count("circle", "speed"), 15); // i + j ≤ 4
    let curve = Svg::parse(&plot_svg(&patches(CUBIC), &o).unwrap());
    assert_eq!(curve.count("circle", "speed"), 5);
}

#[test]
fn tri_svg_has_three_families_and_a_triangular_net() {
    let svg = Svg::parse(&plot_svg(&patches(TRI), &opts(6)).unwrap());
    // Families u, v, w = k/6 for k = 0..5; the degree-2 net has 2 lines per direction.
    assert_eq!(svg.count("polyline", "line"), 18);
    assert_eq!(svg.count("polyline", "net"), 6);
    assert_eq!(svg.count("circle", "ctrl"), 6);
}

#[test]
fn curve_svg_labels_exact_weights() {
    let svg = Svg::parse(&plot_svg(&patches(CUBIC), &opts(8)).unwrap());
    assert_eq!(svg.count("polyline", "line"), 1);
    assert_eq!(svg.count("polyline", "net"), 1);
    assert_eq!(svg.texts, ["w=1", "w=1/3", "w=1/3", "w=1"]);
    // All weights 1: no labels.
    let poly = r#"{"kind": "curve", "degree": 2, "points": [[0,0],[1,1],[2,0]]}"#;
    let svg = Svg::parse(&plot_svg(&patches(poly), &opts(8)).unwrap());
    assert!(svg.texts.is_empty());
}

#[test]
fn splits_draw_one_piece_per_part() {
    let rect = plot_svg(
        &patches(EXAMPLE1),
        &PlotOptions {
            split: Split::Diagonal,
            ..opts(4)
        },
    )
    .unwrap();
    // Two triangles, 3 families of 4 lines each.
    assert_eq!(Svg::parse(&rect).count("polyline", "line"), 24);
    let split = Split::parse("0.3,0.5,0.3,0.5,0.5,0.5").unwrap();
    assert_eq!(split, Split::Triangle([0.3, 0.5, 0.3, 0.5, 0.5, 0.5]));
    let tri = plot_svg(&patches(TRI), &PlotOptions { split, ..opts(4) }).unwrap();
    // Three quadrilaterals, 2·5 lines each.
    assert_eq!(Svg::parse(&tri).count("polyline", "line"), 30);
    // A diagonal split of a triangle is refused, as are points off the triangle.
    let bad = PlotOptions {
        split: Split::Diagonal,
        ..opts(4)
    };
    assert!(plot_svg(&patches(TRI), &bad).is_err());
    assert!(Split::parse("0.8,0.5,0.3,0.5,0.5,0.5").is_err()); // a + c > 1
    assert!(Split::parse("0.3,0.5,0.3,0.5,0.5,0.4").is_err()); // e + f ≠ 1
}

#[test]
fn several_patches_get_distinct_colours() {
    let mut all = patches(EXAMPLE1);
    all.extend(patches(TRI));
    let svg = plot_svg(&all, &opts(3)).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let colours: std::collections::BTreeSet<&str> = doc
        .descendants()
        .filter(|n| n.attribute("class") == Some("line"))
        .map(|n| n.attribute("stroke").unwrap())
        .collect();
    assert_eq!(colours.len(), 2);
}

#[test]
fn projections_map_as_documented() {
    let p = [1.0, 2.0, 3.0];
    assert_eq!(Projection::Plane(Plane::Yz).apply(p), [2.0, 3.0]);
    // Looking down the x axis (az = 0, el = 0): right is y, up is z.
    let q = Projection::View { az: 0.0, el: 0.0 }.apply(p);
    assert!((q[0] - 2.0).abs() < 1e-12 && (q[1] - 3.0).abs() < 1e-12);
    assert!(Projection::parse_view("-60,30").is_ok());
    assert!(Projection::parse_view("60").is_err());
    assert!(Projection::parse_view("nan,3").is_err());
    assert!(Projection::parse_plane("zx").is_err());
}

/// Count pixels that are clearly not white, and those near a palette colour.
pub(crate) fn pixels(png: &[u8], w: u32, h: u32, rgb: [u8; 3]) -> (usize, usize) {
    let pm = Pixmap::decode_png(png).expect("PNG decodes");
    assert_eq!((pm.width(), pm.height()), (w, h));
    let ink = pm
        .pixels()
        .iter()
        .filter(|p| p.red() < 200 || p.green() < 200 || p.blue() < 200);
    let near = |p: &&resvg::tiny_skia::PremultipliedColorU8| {
        let c = p.demultiply();
        [c.red(), c.green(), c.blue()]
            .iter()
            .zip(rgb)
            .all(|(a, b)| a.abs_diff(b) < 40)
    };
    (ink.clone().count(), ink.filter(near).count())
}

#[test]
fn png_decodes_to_the_size_asked_with_both_split_colours() {
    let o = PlotOptions {
        width: 320,
        height: 240,
        split: Split::Diagonal,
        ..opts(4)
    };
    let png = plot_png(&patches(EXAMPLE1), &o).unwrap();
    let (ink, blue) = pixels(&png, 320, 240, [0x1f, 0x77, 0xb4]);
    let (_, red) = pixels(&png, 320, 240, [0xd6, 0x27, 0x28]);
    assert!(ink > 1000, "only {ink} drawn pixels");
    assert!(blue > 100 && red > 100, "blue {blue}, red {red}");
}

#[test]
fn the_smallest_picture_stays_inside_its_view_box() {
    let o = PlotOptions {
        width: 16,
        height: 16,
        speed: true,
        ..opts(2)
    };
    let svg = Svg::parse(&plot_svg(&patches(EXAMPLE1), &o).unwrap());
    assert_eq!((svg.width, svg.height), (16.0, 16.0));
}

#[test]
fn bad_options_are_errors() {
    let p = patches(EXAMPLE1);
    for o in [
        PlotOptions {
            width: 0,
            ..opts(4)
        },
        PlotOptions { iso: 0, ..opts(4) },
        PlotOptions {
            samples: 0,
            ..opts(4)
        },
    ] {
        assert!(plot_svg(&p, &o).is_err());
    }
    let four_d = r#"{"kind": "curve", "degree": 1, "points": [[0,0,0,0],[1,1,1,1]]}"#;
    assert!(plot_svg(&patches(four_d), &opts(4)).is_err());
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("exact-bezier-plot-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn cli_writes_svg_and_png_and_rejects_bad_requests() {
    let d = temp_dir("cli");
    let svg = d.join("e1.svg");
    let png = d.join("e1.png");
    let fixture = "tests/fixtures/yang_yong_example1.json";
    for (out, extra) in [
        (&svg, vec!["--view", "-60,30"]),
        (&png, vec!["--plane", "xz"]),
    ] {
        let st = bin()
            .args([
                "plot",
                fixture,
                "-o",
                out.to_str().unwrap(),
                "--iso",
                "4",
                "--width",
                "300",
                "--height",
                "200",
            ])
            .args(extra)
            .output()
            .unwrap();
        assert!(st.status.success());
        let report: serde_json::Value = serde_json::from_slice(&st.stdout).unwrap();
        assert_eq!(report["patches"], 1);
    }
    let s = Svg::parse(&crate::common::read_to_string(&svg).unwrap());
    assert_eq!(
        (s.width, s.height, s.count("polyline", "line")),
        (300.0, 200.0, 10)
    );
    assert!(pixels(&std::fs::read(&png).unwrap(), 300, 200, [0, 0, 0]).0 > 300);
    for bad in [
        vec!["plot", fixture, "-o", "x.pdf"],
        vec!["plot", fixture, "-o", "x.svg", "--view", "1,2,3"],
        vec![
            "plot",
            fixture,
            "-o",
            "x.svg",
            "--split",
            "0.3,0.5,0.3,0.5,0.5,0.5",
        ],
        vec!["plot", "no-such-file.json", "-o", "x.svg"],
    ] {
        let out = bin().args(&bad).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{bad:?}");
        assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"));
    }
}

#[test]
fn gallery_regenerates_every_entry() {
    let d = temp_dir("gallery");
    let out = bin()
        .args(["figures", "--out", d.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let manifest: serde_json::Value =
        serde_json::from_str(include_str!("../../../docs/figures/gallery.json")).unwrap();
    let entries = manifest.as_array().unwrap();
    assert!(entries.len() >= 9);
    for e in entries {
        let name = e["name"].as_str().unwrap();
        let svg = crate::common::read_to_string(d.join(format!("{name}.svg"))).unwrap();
        assert!(Svg::parse(&svg).count("polyline", "line") >= 1, "{name}");
        let png = std::fs::read(d.join(format!("{name}.png"))).unwrap();
        assert!(pixels(&png, 800, 600, [0, 0, 0]).0 > 1000, "{name}");
        // Entries with "mesh" flags also give an OBJ: 25² vertices at density 24
        // for each rect, 25·26/2 for each tri (patches are not welded).
        if e.get("mesh").is_some() {
            let obj = crate::common::read_to_string(d.join(format!("{name}.obj"))).unwrap();
            let v = obj.lines().filter(|l| l.starts_with("v ")).count();
            assert!(
                v > 0 && (v % 625 == 0 || v % 325 == 0),
                "{name}: {v} vertices"
            );
        }
    }
    // The derived input of Fig. 3(b) is the reparameterized patch.
    let derived =
        crate::common::read_to_string(d.join("inputs/000-fig3b-example1-mobius.json")).unwrap();
    assert_eq!(read_patches(&derived).unwrap().len(), 1);
    let readme = crate::common::read_to_string(d.join("README.md")).unwrap();
    assert!(readme.contains("reparam tests/fixtures/yang_yong_example1.json --mobius 0.3798,1/3"));
}
