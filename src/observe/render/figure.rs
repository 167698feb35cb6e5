//! The raster as an SVG figure like the book's: the pixel grid, pixel
//! centres, half-interval scanlines, polygon outlines and covered pixels
//! filled by framebuffer value (or shaded by depth). Coordinates are written
//! from exact values with [`crate::numbers::decimal`]; nothing passes through
//! floating point.

use crate::words::Lang;
use std::fmt::Write as _;

use crate::raster::convert::{Scratch, rasterize};
use crate::raster::depth::Stored;
use crate::raster::sink::{CoveredCentres, PixelRect};
use crate::simulate::buffer::Buffers;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;

use crate::numbers::{Exact, Q, decimal, short};
use crate::scene::Scene;

use super::svg_text::{escape, is_wide};
use super::vertex_labels;

/// Largest raster side a figure draws.
pub const MAX_FIGURE_SIDE: u32 = 1024;

/// Largest raster side for which the grid, the centres and the scanlines are
/// drawn; beyond it they would cover the picture.
pub const MAX_DETAILED_SIDE: u32 = 64;

/// Size of one pixel in the figure, in SVG user units.
const CELL: i128 = 24;
const MARGIN_LEFT: i128 = 40;
const MARGIN_TOP: i128 = 36;
const MARGIN_RIGHT: i128 = 16;
const MARGIN_BOTTOM: i128 = 40;
/// Height of the legend's row below the axes.
const LEGEND: i128 = 22;

/// Fill colours for framebuffer values 1, 2, …; 0 (the usual background) is
/// white. Okabe and Ito's colour-blind-safe set, ordered so that 1, 2 and 3
/// (a 2-bit framebuffer) are light, middle and dark in grey print too.
/// The playground colours its raster with the same set.
pub const PALETTE: [&str; 7] = ["#f0e442", "#e69f00", "#0072b2", "#009e73", "#cc79a7", "#56b4e9", "#d55e00"];

/// What the cells show.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shading {
    /// Filled by framebuffer value.
    Frame,
    /// Shaded by z-buffer value: nearer is darker.
    Depth,
}

/// What a figure adds for a worksheet or an answer key.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Annotations {
    /// Label each outlined polygon's vertices with their coordinates `(x, y, z)`.
    pub vertex_labels: bool,
    /// Lines of text below the axes (what to fill in, say).
    pub caption: Vec<String>,
    /// Print each cell's value (framebuffer or z-buffer, as shaded) in its pixel.
    pub values: bool,
}

/// Draws the buffers after polygon `last` (0-based): polygons `0 ..= last`
/// are outlined. The raster must be at most [`MAX_FIGURE_SIDE`] on a side.
pub fn svg(lang: Lang, scene: &Scene, buffers: &Buffers, last: usize, shading: Shading, title: &str) -> String {
    svg_with(lang, scene, buffers, last, shading, title, &Annotations::default())
}

/// Like [`svg`], with vertex labels and a caption.
pub fn svg_with(
    lang: Lang,
    scene: &Scene,
    buffers: &Buffers,
    last: usize,
    shading: Shading,
    title: &str,
    extras: &Annotations,
) -> String {
    let title = &*drawn(title, MAX_DRAWN_TITLE);
    let (width, height) = (i128::from(scene.width), i128::from(scene.height));
    // Vertex labels stand in a column on each side of the raster: room for the widest.
    let vertices = if extras.vertex_labels { vertex_labels::texts(lang, scene, last) } else { Vec::new() };
    let pad = vertices.iter().map(|v| vertex_labels::width(&v.text)).max().map_or(0, |w| w + 16);
    // The polygons' names stand in a column right of the raster, each led to
    // its polygon by a line, so that no name covers a cell, a value or another polygon.
    let names = name_labels(scene, buffers, last);
    let column = names.iter().map(|n| bold_width(&n.text)).max().map_or(0, |w| w + 34);
    let (left, right) = (MARGIN_LEFT + pad, MARGIN_RIGHT + pad + column);
    let total_width = left + width * CELL + right;
    // About 6 units a character at font size 11.
    let caption = wrap(&extras.caption, ((total_width - left - 8) / 6).max(20) as usize);
    let caption_height = 16 * caption.len() as i128;
    // The title wraps too (font size 13: about 7.5 units a character); the raster starts below it.
    let title_lines = wrap(&[title.to_string()], ((total_width - left - 8) * 2 / 15).max(20) as usize);
    let top = MARGIN_TOP + 18 * (title_lines.len() as i128 - 1);
    let legend = legend(lang, scene, buffers, shading);
    // A column of vertex labels longer than the raster is tall lengthens the picture.
    let side_count = |left_side: bool| vertices.iter().filter(|v| v.left == left_side).count() as i128;
    let labels_height = (side_count(true).max(side_count(false)) * vertex_labels::LINE).max(height * CELL);
    let total_height = top + labels_height + MARGIN_BOTTOM + LEGEND + caption_height;
    // Pixel-unit point to SVG coordinates: x right, y up (flipped).
    let sx = |x: Q| decimal(Q::from_integer(left) + x * CELL, 2);
    let sy = |y: Q| decimal(Q::from_integer(top) + (Q::from_integer(height) - y) * CELL, 2);
    let int = |v: i128| Q::from_integer(v);
    // The same for a vertex, exact however large (clip space may make it so).
    let svg_x = |x: &Exact| Exact::Word(int(left)).plus(&x.times(CELL));
    let svg_y = |y: &Exact| Exact::Word(int(top + height * CELL)).minus(&y.times(CELL));
    let vx = |x: &Exact| decimal(svg_x(x), 2);
    let vy = |y: &Exact| decimal(svg_y(y), 2);
    // An outline reaching far past the picture (a vertex near the eye in
    // perspective) is cut to a box around it: the picture shows the same
    // lines, and every coordinate stays within what TeX can hold.
    let reach = (total_width.max(total_height) * 2) as f64;
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{total_width}" height="{total_height}" viewBox="0 0 {total_width} {total_height}" font-family="sans-serif" font-size="11">"#
    );
    let _ = writeln!(out, r#"<title>{}</title>"#, escape(title));
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    for (k, line) in title_lines.iter().enumerate() {
        let _ = writeln!(out, r#"<text x="{left}" y="{}" font-size="13">{}</text>"#, 20 + 18 * k, escape(line));
    }
    // Covered pixels.
    let _ = writeln!(out, r#"<g id="pixels" stroke="none" shape-rendering="crispEdges">"#);
    let range = exact_range(scene, buffers);
    for y in 0..scene.height {
        // Runs of equal cells in a row become one rectangle.
        let mut x = 0;
        while x < scene.width {
            let fill = cell_fill(scene, buffers, x, y, shading, &range);
            let mut end = x + 1;
            while end < scene.width && cell_fill(scene, buffers, end, y, shading, &range) == fill {
                end += 1;
            }
            if let Some(fill) = fill {
                let what = if end - x == 1 {
                    words!(
                        lang,
                        "figure-cell",
                        x = x,
                        y = y,
                        frame = buffers.frame(x, y),
                        depth = buffers.depth(x, y).text(lang)
                    )
                } else {
                    words!(lang, "figure-cells", from = x, to = end - 1, y = y, frame = buffers.frame(x, y))
                };
                let _ = writeln!(
                    out,
                    r#"<rect x="{}" y="{}" width="{}" height="{CELL}" fill="{fill}"><title>{}</title></rect>"#,
                    sx(int(i128::from(x))),
                    sy(int(i128::from(y) + 1)),
                    CELL * i128::from(end - x),
                    escape(&what)
                );
            }
            x = end;
        }
    }
    let _ = writeln!(out, "</g>");
    let detailed = scene.width.max(scene.height) <= MAX_DETAILED_SIDE;
    // The pixel grid.
    let _ = writeln!(out, r##"<g id="grid" stroke="#b0b0b0" stroke-width="0.5">"##);
    for x in 0..=width {
        let _ =
            writeln!(out, r#"<line x1="{0}" y1="{1}" x2="{0}" y2="{2}"/>"#, sx(int(x)), sy(int(0)), sy(int(height)));
    }
    for y in (0..=height).filter(|_| detailed) {
        let _ = writeln!(out, r#"<line x1="{1}" y1="{0}" x2="{2}" y2="{0}"/>"#, sy(int(y)), sx(int(0)), sx(int(width)));
    }
    let _ = writeln!(out, "</g>");
    // Half-interval scanlines through the centres.
    let _ = writeln!(out, r##"<g id="scanlines" stroke="#3a6ea5" stroke-width="0.6" stroke-dasharray="3 3">"##);
    for row in (0..height).filter(|_| detailed) {
        let y = Q::new(2 * row + 1, 2);
        let _ = writeln!(out, r#"<line x1="{1}" y1="{0}" x2="{2}" y2="{0}"/>"#, sy(y), sx(int(0)), sx(int(width)));
    }
    let _ = writeln!(out, "</g>");
    // Pixel centres (left out where values are printed in the cells).
    let _ = writeln!(out, r##"<g id="centres" fill="#333333">"##);
    for row in (0..height).filter(|_| detailed && !extras.values) {
        for column in 0..width {
            let (cx, cy) = (Q::new(2 * column + 1, 2), Q::new(2 * row + 1, 2));
            let _ = writeln!(out, r#"<circle cx="{}" cy="{}" r="1.3"/>"#, sx(cx), sy(cy));
        }
    }
    let _ = writeln!(out, "</g>");
    // Polygon outlines, with their names.
    let _ = writeln!(out, r#"<g id="polygons" fill="none" stroke="black" stroke-width="1.5">"#);
    for (index, polygon) in scene.polygons.iter().enumerate().take(last + 1) {
        if polygon.vertices().is_empty() {
            // Clipped away in clip space: nothing on the raster to outline.
            continue;
        }
        let corners: Vec<(f64, f64)> = polygon
            .vertices()
            .iter()
            .map(|v| (crate::numbers::to_f64(svg_x(&v[0])), crate::numbers::to_f64(svg_y(&v[1]))))
            .collect();
        let points: Vec<String> = if corners.iter().any(|(x, y)| x.abs() > reach || y.abs() > reach) {
            clip_to_box(&corners, [-reach, -reach, reach, reach])
                .iter()
                .map(|(x, y)| format!("{x:.2},{y:.2}"))
                .collect()
        } else {
            polygon.vertices().iter().map(|v| format!("{},{}", vx(&v[0]), vy(&v[1]))).collect()
        };
        // An unnamed polygon is labelled by its number alone, titled in the reader's language.
        let unnamed = crate::words::is_default_name(&polygon.name, index);
        let title = if unnamed {
            crate::observe::explain::polygon_name(lang, scene, index)
        } else {
            drawn(&polygon.name, MAX_DRAWN_NAME).into_owned()
        };
        let _ = writeln!(out, r#"<polygon points="{}"><title>{}</title></polygon>"#, points.join(" "), escape(&title));
    }
    let _ = writeln!(out, "</g>");
    // The names: top to bottom in the order of their anchors, each as near its
    // anchor's height as the names above it allow, a leader line to the anchor.
    let _ = writeln!(out, r##"<g id="names" font-weight="bold" stroke-width="0.8">"##);
    let column_x = left + width * CELL + pad + 20;
    let mut order: Vec<&NameLabel> = names.iter().collect();
    order.sort_by(|a, b| b.anchor.1.total_cmp(&a.anchor.1));
    let mut next_free = (top + 4) as f64;
    // The heights the names' leaders cross the right-hand vertex labels' column at.
    let mut leader_rows = Vec::new();
    for name in order {
        // The leader leaves the anchor's centre at 45° for the row's lane, three quarters down
        // the row (between its scanline and the grid line below: no centre, value, grid line or
        // scanline there), runs right along it out of the raster, then to the name.
        let ax = left as f64 + name.anchor.0 * CELL as f64;
        let ay = (top + height * CELL) as f64 - name.anchor.1 * CELL as f64;
        let lane = ay + CELL as f64 / 4.0;
        let edge = (left + width * CELL + pad + 6) as f64;
        let y = (lane + 4.0).max(next_free);
        next_free = y + 16.0;
        leader_rows.push(lane);
        let _ = writeln!(
            out,
            r##"<polyline points="{ax:.2},{ay:.2} {:.2},{lane:.2} {edge:.2},{lane:.2} {},{:.2}" fill="none" stroke="#333333"/><circle cx="{ax:.2}" cy="{ay:.2}" r="2.6" fill="black" stroke="white"/><text x="{column_x}" y="{y:.2}" fill="black">{}</text>"##,
            ax + CELL as f64 / 4.0,
            column_x - 3,
            y - 4.0,
            escape(&name.text)
        );
    }
    let _ = writeln!(out, "</g>");
    if extras.values {
        cell_values(lang, &mut out, scene, buffers, shading, (&sx, &sy));
    }
    if extras.vertex_labels {
        let raster = [left as f64, top as f64, (left + width * CELL) as f64, (top + height * CELL) as f64];
        let bottom = (top + labels_height) as f64;
        vertex_labels::draw(&mut out, &vertices, (&vx, &vy), (raster, CELL as f64), bottom, &leader_rows);
    }
    // Axes: column numbers below, row numbers on the left.
    let step = if width.max(height) > 64 {
        8
    } else if width.max(height) > 32 {
        4
    } else {
        1
    };
    let _ = writeln!(out, r#"<g id="axes" fill="black" text-anchor="middle">"#);
    let below = decimal(Q::from_integer(top + height * CELL + 14), 2);
    for column in (0..width).step_by(step) {
        let _ = writeln!(out, r#"<text x="{}" y="{below}">{column}</text>"#, sx(Q::new(2 * column + 1, 2)));
    }
    // The x axis's label says where the numbers stand: at pixel centres (x + 1/2).
    let _ = writeln!(
        out,
        r#"<text x="{}" y="{}">{}</text>"#,
        sx(Q::new(width, 2)),
        decimal(Q::from_integer(top + height * CELL + 30), 2),
        escape(&words!(lang, "figure-axis-x"))
    );
    for row in (0..height).step_by(step) {
        let _ = writeln!(
            out,
            r#"<text x="{}" y="{}" text-anchor="end">{row}</text>"#,
            left - 6,
            // Centred on the row's scanline: the leaders' lanes run under the numbers.
            sy(Q::new(2 * row + 1, 2) - Q::new(1, 6))
        );
    }
    let _ = writeln!(out, r#"<text x="{}" y="{}">y</text>"#, left - 28, sy(Q::new(height, 2)));
    let _ = writeln!(out, "</g>");
    let legend_top = top + height * CELL + MARGIN_BOTTOM;
    let _ = writeln!(out, r#"<g id="legend" fill="black">"#);
    let mut x = left;
    for (fill, label) in &legend {
        let _ = writeln!(
            out,
            r##"<rect x="{x}" y="{}" width="12" height="12" fill="{fill}" stroke="#808080" stroke-width="0.5"/><text x="{}" y="{}">{}</text>"##,
            legend_top,
            x + 16,
            legend_top + 10,
            escape(label)
        );
        x += 16 + text_width(label) + 14;
    }
    let _ = writeln!(out, "</g>");
    if !caption.is_empty() {
        let _ = writeln!(out, r#"<g id="caption" fill="black">"#);
        for (k, line) in caption.iter().enumerate() {
            let y = legend_top + LEGEND + 16 * k as i128 + 4;
            let _ = writeln!(out, r#"<text x="{left}" y="{y}">{}</text>"#, escape(line));
        }
        let _ = writeln!(out, "</g>");
    }
    let _ = writeln!(out, "</svg>");
    out
}

/// The width of a legend label in the figure's 11 px sans-serif: about 7 px
/// a character, 12 for the wide ones of Chinese (from U+2E80 on).
fn text_width(label: &str) -> i128 {
    label.chars().map(|c| if is_wide(c) { 12 } else { 7 }).sum()
}

/// The legend's entries, `(fill, label)`: each framebuffer value present
/// (the background first), or for depth shading the far and near ends.
fn legend(lang: Lang, scene: &Scene, buffers: &Buffers, shading: Shading) -> Vec<(String, String)> {
    match shading {
        Shading::Frame => {
            let mut values: Vec<u32> = buffers.frame_rows().into_iter().flatten().collect();
            values.sort_unstable();
            values.dedup();
            if !values.contains(&scene.background) {
                values.insert(0, scene.background);
            }
            values
                .into_iter()
                .map(|v| {
                    if v == scene.background {
                        ("#ffffff".to_string(), words!(lang, "figure-background", value = v))
                    } else {
                        (frame_fill(scene, v), value_label(lang, scene, v))
                    }
                })
                .collect()
        }
        Shading::Depth => {
            let larger_nearer = if scene.depth_test.larger_is_nearer() { "yes" } else { "no" };
            vec![
                ("#ffffff".to_string(), words!(lang, "figure-cleared", value = scene.clear_depth.text(lang))),
                ("#e6e6e6".to_string(), words!(lang, "figure-far", larger_nearer = larger_nearer)),
                ("#3c3c3c".to_string(), words!(lang, "figure-near", larger_nearer = larger_nearer)),
            ]
        }
    }
}

/// A closed outline clipped to the box `[x0, y0, x1, y1]`
/// (Sutherland–Hodgman, one side of the box at a time): the part of it
/// inside the box, the same lines there.
fn clip_to_box(points: &[(f64, f64)], [x0, y0, x1, y1]: [f64; 4]) -> Vec<(f64, f64)> {
    // Each side as (axis, sign, value): a point is inside when sign × (its coordinate − value) ≥ 0.
    let sides = [(0, 1.0, x0), (0, -1.0, x1), (1, 1.0, y0), (1, -1.0, y1)];
    let inside =
        |p: (f64, f64), (axis, sign, value): (usize, f64, f64)| sign * (if axis == 0 { p.0 } else { p.1 } - value);
    let mut out = points.to_vec();
    for side in sides {
        let input = std::mem::take(&mut out);
        for (i, &current) in input.iter().enumerate() {
            let previous = input[(i + input.len() - 1) % input.len()];
            let (a, b) = (inside(previous, side), inside(current, side));
            if (a >= 0.0) != (b >= 0.0) {
                let t = a / (a - b);
                out.push((previous.0 + t * (current.0 - previous.0), previous.1 + t * (current.1 - previous.1)));
            }
            if b >= 0.0 {
                out.push(current);
            }
        }
    }
    out
}

/// The most characters of a polygon's name a figure draws; a longer name is
/// cut and ends in `…` (the scene keeps it whole: names are cut for drawing,
/// not for reading).
pub const MAX_DRAWN_NAME: usize = 80;

/// The most characters of a figure's title drawn, as [`MAX_DRAWN_NAME`].
pub const MAX_DRAWN_TITLE: usize = 400;

/// `text` cut to `max` characters for drawing, ending in `…` when cut.
pub fn drawn(text: &str, max: usize) -> std::borrow::Cow<'_, str> {
    match text.char_indices().nth(max) {
        None => std::borrow::Cow::Borrowed(text),
        Some((end, _)) => std::borrow::Cow::Owned(format!("{}…", &text[..end])),
    }
}

/// A framebuffer value's legend label, naming the polygons that write it
/// (up to two; more are counted).
fn value_label(lang: Lang, scene: &Scene, value: u32) -> String {
    let names: Vec<String> = scene
        .polygons
        .iter()
        .filter(|p| p.value == value)
        .map(|p| format!("\"{}\"", drawn(&p.name, MAX_DRAWN_NAME)))
        .collect();
    let names = match names.len() {
        0 => return words!(lang, "figure-value", value = value),
        1 | 2 => names.join(&words!(lang, "list-comma")),
        count => words!(lang, "figure-polygons", count = count),
    };
    words!(lang, "figure-value-named", value = value, names = names)
}

/// Each cell's value written in its pixel: black on light fills, white on dark.
fn cell_values(
    lang: Lang,
    out: &mut String,
    scene: &Scene,
    buffers: &Buffers,
    shading: Shading,
    (sx, sy): (&dyn Fn(Q) -> String, &dyn Fn(Q) -> String),
) {
    let _ = writeln!(out, r#"<g id="values" font-size="9" text-anchor="middle">"#);
    let range = exact_range(scene, buffers);
    for y in 0..scene.height {
        for x in 0..scene.width {
            let (text, fill) = match shading {
                Shading::Frame => (buffers.frame(x, y).to_string(), cell_fill(scene, buffers, x, y, shading, &range)),
                Shading::Depth => {
                    let text = match buffers.depth(x, y) {
                        Stored::Level(level) => level.to_string(),
                        Stored::Exact(value) => short(lang, value),
                    };
                    (text, cell_fill(scene, buffers, x, y, shading, &range))
                }
            };
            let colour = if fill.as_deref().is_some_and(is_dark) { "white" } else { "black" };
            // The baseline 2 px above the centre: the dashed scanline through the
            // centre runs just under the digits, not through them.
            let (cx, cy) = (Q::new(2 * i128::from(x) + 1, 2), Q::new(2 * i128::from(y) + 1, 2) + Q::new(1, 12));
            let _ = writeln!(out, r#"<text x="{}" y="{}" fill="{colour}">{}</text>"#, sx(cx), sy(cy), escape(&text));
        }
    }
    let _ = writeln!(out, "</g>");
}

/// Whether a `#rrggbb` fill is dark enough for white text (luma below one half).
fn is_dark(fill: &str) -> bool {
    let channel = |k: usize| u32::from_str_radix(fill.get(1 + 2 * k..3 + 2 * k).unwrap_or("ff"), 16).unwrap_or(255);
    299 * channel(0) + 587 * channel(1) + 114 * channel(2) < 500 * 255
}

/// The fill of cell (x, y), or `None` where it shows the background.
fn cell_fill(
    scene: &Scene,
    buffers: &Buffers,
    x: u32,
    y: u32,
    shading: Shading,
    range: &(Exact, Exact),
) -> Option<String> {
    match shading {
        Shading::Frame => {
            let value = buffers.frame(x, y);
            (value != scene.background).then(|| frame_fill(scene, value))
        }
        Shading::Depth => {
            let value = buffers.depth(x, y);
            (value != scene.clear_depth).then(|| depth_grey(&value, scene, range))
        }
    }
}

/// A framebuffer value's fill: the palette for small values, the value
/// itself as RGB when the framebuffer holds 24-bit colours.
fn frame_fill(scene: &Scene, value: u32) -> String {
    if scene.frame_bits == 24 {
        format!("#{value:06x}")
    } else {
        PALETTE[(value as usize).saturating_sub(1) % PALETTE.len()].to_string()
    }
}

/// A grey for a depth: nearer (by the depth test) is darker. Levels are
/// scaled by the level range; exact depths by the range `[low, high]` of the
/// values in the buffer.
fn depth_grey(value: &Stored, scene: &Scene, (low, high): &(Exact, Exact)) -> String {
    let integer = |v: u32| BigRational::from_integer(BigInt::from(v));
    let (value, low, high) = match value {
        Stored::Level(level) => (integer(*level), integer(0), integer(scene.depth_max())),
        Stored::Exact(value) => (value.to_big(), low.to_big(), high.to_big()),
    };
    let span = if high > low { &high - &low } else { integer(1) };
    let offset = if scene.depth_test.larger_is_nearer() { value - low } else { high - value };
    // 230 (far) … 60 (near), in whole steps.
    let shade = (offset / span * integer(170)).floor().to_integer().clamp(BigInt::from(0), BigInt::from(170));
    let level = 230 - shade.to_u8().expect("clamped");
    format!("#{level:02x}{level:02x}{level:02x}")
}

/// A point in pixel units, for placing names.
type Point = (f64, f64);

/// A polygon's name in the figure and the point, in pixel units, it is led to.
struct NameLabel {
    text: String,
    anchor: (f64, f64),
}

/// Each drawn polygon's name (its number and name; the number alone when it
/// has none), anchored at the pixel centre it covers, nearest its middle,
/// where the framebuffer shows its value; failing that at the centre it
/// covers nearest its middle, or its middle (a polygon that covers none).
/// Placement only: f64 is exact enough to choose a point to draw a line to.
/// For each cell, the first two values other than the background shown to
/// its right in its row: what tells in one look whether a row right of a
/// cell shows any polygon but one (a scan of the row for each cell made a
/// large raster's figure take as long as its side times its cells).
struct ShownToTheRight {
    width: u32,
    /// Per cell, row by row: the first value right of it, then the first
    /// other than that one (`None`: no such value).
    values: Vec<[Option<u32>; 2]>,
}

impl ShownToTheRight {
    fn of(scene: &Scene, buffers: &Buffers) -> Self {
        let width = scene.width;
        let mut values = vec![[None; 2]; width as usize * scene.height as usize];
        for y in 0..scene.height {
            let row = y as usize * width as usize;
            let mut seen: [Option<u32>; 2] = [None; 2];
            for x in (0..width).rev() {
                values[row + x as usize] = seen;
                let v = buffers.frame(x, y);
                if v == scene.background || seen[0] == Some(v) || seen[1].is_some() {
                    continue;
                }
                seen = match seen[0] {
                    None => [Some(v), None],
                    Some(first) => [Some(first), Some(v)],
                };
            }
        }
        ShownToTheRight { width, values }
    }

    /// Whether a value other than `value` and the background is shown right of (x, y).
    fn other_than(&self, x: u32, y: u32, value: u32) -> bool {
        let [first, second] = self.values[y as usize * self.width as usize + x as usize];
        second.is_some() || first.is_some_and(|v| v != value)
    }
}

fn name_labels(scene: &Scene, buffers: &Buffers, last: usize) -> Vec<NameLabel> {
    let mut labels = Vec::new();
    let mut scratch = Scratch::default();
    let right = ShownToTheRight::of(scene, buffers);
    for (index, polygon) in scene.polygons.iter().enumerate().take(last + 1) {
        let outline: Vec<(f64, f64)> = polygon
            .vertices()
            .iter()
            .map(|v| (crate::numbers::to_f64(v[0].clone()), crate::numbers::to_f64(v[1].clone())))
            .collect();
        if outline.is_empty() {
            continue;
        }
        let n = outline.len() as f64;
        let middle = (outline.iter().map(|p| p.0).sum::<f64>() / n, outline.iter().map(|p| p.1).sum::<f64>() / n);
        let distance = |p: (f64, f64)| (p.0 - middle.0).powi(2) + (p.1 - middle.1).powi(2);
        // Best first: a centre whose row, to its right, shows no other polygon
        // (the leader runs along that row's top edge), then any centre showing
        // this polygon, then any it covers.
        let (mut clear, mut visible, mut inside): (Option<Point>, Option<Point>, Option<Point>) = (None, None, None);
        let nearer = |best: Option<(f64, f64)>, p: (f64, f64)| match best {
            Some(b) if distance(b) <= distance(p) => Some(b),
            _ => Some(p),
        };
        // The centres it covers, as the one rasterizer finds them under the scene's rules.
        let geometry = polygon.geometry();
        let mut centres = CoveredCentres::default();
        if !geometry.is_degenerate() && geometry.c() != 0 {
            let raster = PixelRect::raster(scene.width, scene.height);
            rasterize(geometry, scene.rules, raster, &mut scratch, &mut centres);
        }
        for (x, y) in centres.0 {
            let centre = (f64::from(x) + 0.5, f64::from(y) + 0.5);
            inside = nearer(inside, centre);
            if buffers.frame(x, y) == polygon.value {
                visible = nearer(visible, centre);
                if !right.other_than(x, y, polygon.value) {
                    clear = nearer(clear, centre);
                }
            }
        }
        let unnamed = crate::words::is_default_name(&polygon.name, index);
        let text = if unnamed {
            (index + 1).to_string()
        } else {
            format!("{} {}", index + 1, drawn(&polygon.name, MAX_DRAWN_NAME))
        };
        labels.push(NameLabel { text, anchor: clear.or(visible).or(inside).unwrap_or(middle) });
    }
    labels
}

/// The width of a bold label at font size 11.
fn bold_width(label: &str) -> i128 {
    label.chars().map(|c| if is_wide(c) { 12 } else { 8 }).sum()
}

/// The least and greatest exact depths written (for shading).
fn exact_range(scene: &Scene, buffers: &Buffers) -> (Exact, Exact) {
    let written: Vec<Exact> =
        buffers.depth_rows().into_iter().flatten().filter(|v| *v != scene.clear_depth).map(|v| v.value()).collect();
    let range = written.iter().min().cloned().zip(written.iter().max().cloned());
    range.unwrap_or((Exact::Word(Q::from_integer(0)), Exact::Word(Q::from_integer(1))))
}

/// The lines, each broken at spaces to at most `width` characters.
fn wrap(lines: &[String], width: usize) -> Vec<String> {
    let mut out = Vec::new();
    for line in lines {
        let mut current = String::new();
        for (spaced, word) in breakable(line) {
            let joiner = usize::from(spaced && !current.is_empty());
            if !current.is_empty() && columns(&current) + joiner + columns(word) > width {
                out.push(std::mem::take(&mut current));
            } else if joiner == 1 {
                current.push(' ');
            }
            current.push_str(word);
        }
        out.push(current);
    }
    out
}

/// The columns a text takes: one a character, two a wide one.
fn columns(text: &str) -> usize {
    text.chars().map(|c| if is_wide(c) { 2 } else { 1 }).sum()
}

/// The pieces a line may be broken between, each with whether a space
/// precedes it: its words, and within a word each wide character alone.
fn breakable(line: &str) -> Vec<(bool, &str)> {
    let mut pieces = Vec::new();
    for word in line.split(' ') {
        let mut start = 0;
        for (i, c) in word.char_indices() {
            let end = i + c.len_utf8();
            // A break before and after each wide character, none elsewhere.
            let next_wide = word[end..].chars().next().is_some_and(is_wide);
            if is_wide(c) || next_wide || end == word.len() {
                pieces.push((start == 0, &word[start..end]));
                start = end;
            }
        }
        if word.is_empty() {
            pieces.push((true, word));
        }
    }
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Luma of a `#rrggbb` colour, 0 … 1000.
    fn luma(fill: &str) -> u32 {
        let channel = |k: usize| u32::from_str_radix(&fill[1 + 2 * k..3 + 2 * k], 16).unwrap();
        (299 * channel(0) + 587 * channel(1) + 114 * channel(2)) / 255
    }

    /// Found by a new user: values 2 and 3 were two similar greens. A 2-bit
    /// framebuffer's values 1, 2, 3 and the white background differ in grey print
    /// by at least a sixth of the range.
    #[test]
    fn palette_levels_are_distinct_in_grey() {
        let lumas: Vec<u32> = ["#ffffff", PALETTE[0], PALETTE[1], PALETTE[2]].iter().map(|c| luma(c)).collect();
        for pair in lumas.windows(2) {
            assert!(pair[0] > pair[1] + 160, "{lumas:?}");
        }
    }

    /// The book's example, drawn.
    fn rogers_drawn() -> (Scene, Buffers) {
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/rogers.json")).unwrap();
        let scene = Scene::from_json(&text, std::path::Path::new("rogers.json")).unwrap();
        let mut simulation = crate::Simulation::new(&scene);
        simulation.finish(&mut crate::Unobserved);
        let buffers = simulation.into_buffers();
        (scene, buffers)
    }

    /// Found by a new student: "1 rectangle" stood at the rectangle's middle,
    /// inside the triangle, and names covered cell values. Each name now
    /// stands right of the raster, led to a cell that shows its polygon and
    /// whose row, to its right, shows no other polygon.
    #[test]
    fn names_stand_beside_the_raster_led_to_a_cell_of_their_own() {
        let (scene, buffers) = rogers_drawn();
        let buffers = &buffers;
        let names = name_labels(&scene, buffers, 1);
        let texts: Vec<&str> = names.iter().map(|n| n.text.as_str()).collect();
        assert_eq!(texts, ["1 rectangle", "2 triangle"]);
        // The centres nearest each middle that qualify: (17, 9) below the
        // triangle for the rectangle, (25, 16) right of the rectangle for the triangle.
        assert_eq!(names.iter().map(|n| n.anchor).collect::<Vec<_>>(), [(17.5, 9.5), (25.5, 16.5)]);
        for (name, polygon) in names.iter().zip(&scene.polygons) {
            let (x, y) = (name.anchor.0 as u32, name.anchor.1 as u32);
            assert_eq!(buffers.frame(x, y), polygon.value);
            assert!((x + 1..scene.width).all(|r| [polygon.value, scene.background].contains(&buffers.frame(r, y))));
        }
        let svg = svg(Lang::En, &scene, buffers, 1, Shading::Frame, "t");
        let raster_right = MARGIN_LEFT + 32 * CELL;
        let name_x: Vec<i128> = svg
            .lines()
            .filter(|l| l.contains("</text>") && (l.contains(">1 rectangle<") || l.contains(">2 triangle<")))
            .map(|l| l.split("<text x=\"").nth(1).unwrap().split('"').next().unwrap().parse().unwrap())
            .collect();
        assert_eq!(name_x.len(), 2);
        assert!(name_x.iter().all(|x| *x > raster_right), "{name_x:?}");
    }

    /// Found by a new student: with `--values` the dashed scanlines ran
    /// through the digits. Every value's baseline lies 2 px above the scanline
    /// of its row.
    #[test]
    fn values_sit_above_the_dashed_scanlines() {
        let (scene, buffers) = rogers_drawn();
        let extras = Annotations { values: true, ..Annotations::default() };
        let svg = svg_with(Lang::En, &scene, &buffers, 1, Shading::Frame, "t", &extras);
        let group = |id: &str| -> Vec<f64> {
            let start = svg.find(&format!("<g id=\"{id}\"")).unwrap();
            let body = &svg[start..start + svg[start..].find("</g>").unwrap()];
            let attribute = if id == "values" { " y=\"" } else { " y1=\"" };
            body.split(attribute).skip(1).map(|rest| rest.split('"').next().unwrap().parse().unwrap()).collect()
        };
        let (values, scanlines) = (group("values"), group("scanlines"));
        assert_eq!(values.len(), 32 * 32);
        assert!(values.iter().all(|y| scanlines.iter().any(|line| (line - y - 2.0).abs() < 1e-9)), "{values:?}");
    }

    /// The legend's labels are spaced by their width: a Chinese character
    /// takes about twice a Latin or Cyrillic one.
    #[test]
    fn legend_labels_are_spaced_by_their_width() {
        assert_eq!((text_width("value 1"), text_width("значение 1"), text_width("值 1")), (49, 70, 26));
    }

    #[test]
    fn text_wraps_at_spaces() {
        assert_eq!(wrap(&["a bb ccc dd".to_string()], 5), ["a bb", "ccc", "dd"]);
    }

    /// Chinese has no spaces: its text breaks between any two characters,
    /// each counted two columns wide; Latin words within it stay whole.
    #[test]
    fn chinese_text_wraps_between_characters() {
        assert_eq!(wrap(&["写出帧缓冲器和 z 缓冲器".to_string()], 8), ["写出帧缓", "冲器和 z", "缓冲器"]);
        assert_eq!(wrap(&["值 0 … 15（四舍五入）".to_string()], 10), ["值 0 … 15", "（四舍五入", "）"]);
    }
}
