//! A worksheet's vertex labels: `(x, y, z)` of every vertex in a column on
//! each side of the raster, led to their vertices along the rows' free lanes,
//! so that no label or leader covers a centre, a value or another label.

use std::fmt::Write;

use super::svg_text::{escape, is_wide};
use crate::numbers::{Exact, Q, short};
use crate::scene::Scene;
use crate::words::Lang;

/// A vertex's coordinate to the figure's SVG coordinate, as text.
type ToSvg<'a> = dyn Fn(&Exact) -> String + 'a;

/// The height of a line of vertex labels.
pub(super) const LINE: i128 = 13;

/// A vertex's label: its point and `(x, y, z)`, and whether it stands left
/// of the raster (the vertex is left of its polygon's middle) or right.
pub(super) struct VertexText {
    point: [Exact; 2],
    pub(super) text: String,
    pub(super) left: bool,
}

/// The labels of the vertices of polygons `0 ..= last`, in the scene's order.
pub(super) fn texts(lang: Lang, scene: &Scene, last: usize) -> Vec<VertexText> {
    let mut texts = Vec::new();
    for polygon in scene.polygons.iter().take(last + 1).filter(|p| !p.vertices().is_empty()) {
        let vertices = polygon.vertices();
        let middle_x = middle(&vertices, 0);
        for v in vertices.iter() {
            let text = format!("({})", v.each_ref().map(|c| short(lang, c)).join(coordinate_separator(lang)));
            texts.push(VertexText { point: [v[0].clone(), v[1].clone()], text, left: v[0] < middle_x });
        }
    }
    texts
}

/// The width of a vertex label at font size 10: about 6 units a character,
/// 11 for a wide one.
pub(super) fn width(text: &str) -> i128 {
    text.chars().map(|c| if is_wide(c) { 11 } else { 6 }).sum()
}

/// The vertex labels in a column on each side of the `raster` (left, top,
/// right, bottom; rows `cell` high), never over a cell, a centre, a value or another label:
/// each as near its vertex's height as the labels above it allow (and,
/// right of the raster, off the heights where the names' leaders cross,
/// `leader_rows`), down to `bottom`, a dot on the vertex and a thin leader
/// from the dot to the label.
pub(super) fn draw(
    out: &mut String,
    labels: &[VertexText],
    (sx, sy): (&ToSvg, &ToSvg),
    (raster, cell): ([f64; 4], f64),
    bottom: f64,
    leader_rows: &[f64],
) {
    let _ = writeln!(out, r#"<g id="vertices" font-size="10" fill="black">"#);
    let at = |v: &VertexText| {
        let coordinate = |text: String| text.parse::<f64>().unwrap_or(0.0);
        (coordinate(sx(&v.point[0])), coordinate(sy(&v.point[1])))
    };
    // A leader leaves its vertex at 45° to the nearest lane (three quarters down a row, between
    // its scanline and the grid line below: no centre, value or line there) and runs along it.
    let rows = ((raster[3] - raster[1]) / cell).round().max(1.0);
    let lane = |y: f64| {
        let row = ((y - raster[1] - cell * 0.75) / cell).round().clamp(0.0, rows - 1.0);
        raster[1] + row * cell + cell * 0.75
    };
    for left in [true, false] {
        let mut side: Vec<(&VertexText, (f64, f64), f64)> =
            labels.iter().filter(|v| v.left == left).map(|v| (v, at(v))).map(|(v, p)| (v, p, lane(p.1))).collect();
        side.sort_by(|a, b| a.2.total_cmp(&b.2).then(a.1.1.total_cmp(&b.1.1)));
        // Baselines, top down: the text's middle at its lane's height or below the last label.
        let line = LINE as f64;
        let mut baselines: Vec<f64> = Vec::with_capacity(side.len());
        for (_, _, lane) in &side {
            let mut baseline = (lane + 3.5).max(baselines.last().map_or(raster[1] + 9.0, |b| b + line));
            // Right of the raster, off a name's leader (it crosses the column at that height).
            while !left && leader_rows.iter().any(|row| (baseline - 3.5 - row).abs() < line / 2.0 + 1.0) {
                baseline += 1.0;
            }
            baselines.push(baseline);
        }
        // Pushed back up from the bottom where the column ran past it.
        let mut limit = bottom;
        for baseline in baselines.iter_mut().rev() {
            if *baseline > limit {
                *baseline = limit;
            }
            limit = *baseline - line;
        }
        let (edge, outward) = if left { (raster[0], -1.0) } else { (raster[2], 1.0) };
        for ((label, (x, y), lane), baseline) in side.iter().zip(&baselines) {
            // Left, past the row numbers (the lane runs under them), right, just past the raster.
            let (text_x, beyond, anchor) =
                if left { (edge - 38.0, edge - 30.0, "end") } else { (edge + 10.0, edge + 2.0, "start") };
            let mut points = vec![(*x, *y)];
            // Inside the raster: to the lane, along it out of the raster (and the row numbers).
            if (raster[0]..=raster[2]).contains(x) && (raster[1]..=raster[3]).contains(y) {
                points.push((x + outward * (lane - y).abs(), *lane));
                points.push((beyond, *lane));
            }
            points.push((text_x - outward * 2.0, baseline - 3.5));
            let points: Vec<String> = points.iter().map(|(x, y)| format!("{x:.2},{y:.2}")).collect();
            let _ = writeln!(
                out,
                r##"<circle cx="{x:.2}" cy="{y:.2}" r="2.5"/><polyline points="{}" fill="none" stroke="#555555" stroke-width="0.6"/><text x="{text_x:.2}" y="{baseline:.2}" text-anchor="{anchor}">{}</text>"##,
                points.join(" "),
                escape(&label.text)
            );
        }
    }
    let _ = writeln!(out, "</g>");
}

/// The mean of the vertices' coordinate `axis`, exactly.
fn middle(vertices: &[[Exact; 3]], axis: usize) -> Exact {
    let sum = vertices.iter().fold(Exact::Word(Q::from_integer(0)), |sum, v| sum.plus(&v[axis]));
    sum.divided_by(vertices.len() as i128)
}

/// Between a point's coordinates: `, `, or `; ` where the decimal separator
/// is a comma (`(12,5; 3; 0,25)` in Russian), as `explain` writes centres.
fn coordinate_separator(lang: Lang) -> &'static str {
    if lang.decimal_separator() == ',' { "; " } else { ", " }
}
