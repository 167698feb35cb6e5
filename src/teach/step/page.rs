//! `zsim step --html`: the stepper as one self-contained page (no network,
//! no external script or style) for a course site or a lecture. Every stop,
//! every number and every word on it comes from the teaching model
//! ([`crate::teach::step`]), embedded as data; the page's script only shows
//! it. It asks nothing: a quiz is judged by the library's lesson
//! ([`crate::teach::step::lesson`]), which this page does not carry, so it says in
//! one line where the quiz is (the browser playground, `step --quiz`).

use serde::Serialize;

use crate::numbers::exact_and_decimal;
use crate::observe::explain::pixel_reason;
use crate::observe::report::{MatrixCell, MatrixStyle, matrix_styled};
use crate::observe::tracer::Stop;
use crate::simulate::events::Outcome;
use crate::teach::step::{Moved, Stepper};
use crate::words::Lang;

/// The page for the whole scene: every scanline that covers a pixel, in order.
pub fn page(lang: Lang, stepper: &mut Stepper<'_>, title: &str) -> String {
    let scene = stepper.scene();
    let stops = stops(lang, stepper);
    // The page's words, in the student's language; {…} marks what the script fills in.
    let words = StepPageWords {
        no_pixel: words!(lang, "scene-covers-no-pixel"),
        frame_after: words!(lang, "frame-after-scanline"),
        depth_after: words!(lang, "depth-after-scanline"),
        stored: words!(lang, "column-stored"),
        after: words!(lang, "column-depth-after"),
        why: words!(lang, "column-why"),
        keeps: words!(lang, "keeps-value", value = "{after}"),
        status: words!(lang, "scanline-of-count", at = "{at}", count = "{count}"),
    };
    // The top row's y: the rows are printed top first.
    let top = crate::raster::row_y(scene.height, 0);
    // The buffers once, as cleared; each stop carries only its pixels' values after it, which the
    // script applies in order (a page of every buffer at every stop grew as the cube of the side).
    let cleared = crate::simulate::simulation::Simulation::new(scene);
    let cleared = cell_buffers(cleared.buffers());
    let data = StepPageData {
        title,
        width: scene.width,
        height: scene.height,
        top,
        op: scene.depth_test.symbol(),
        words,
        cleared,
        stops,
    };
    let data = serde_json::to_string(&data).expect("serializing plain data cannot fail");
    let (head, tail) = TEMPLATE.split_once("{{DATA}}").expect("the template has a place for the data");
    // The data goes in last, so that nothing in it (a polygon named "{{TITLE}}") is
    // taken for a place in the template.
    format!("{}{}{}", fill(lang, head, title), embedded_json(&data), fill(lang, tail, title))
}

/// What the step page's script reads: the raster, the cleared buffers, every
/// stop and the page's words.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
struct StepPageData<'a> {
    title: &'a str,
    width: u32,
    height: u32,
    /// The top row's y.
    top: u32,
    /// The depth test's symbol.
    op: &'static str,
    words: StepPageWords,
    cleared: CellBuffers,
    stops: Vec<StopData>,
}

/// The step page's words, in the student's language; `{…}` marks what the
/// script fills in.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
struct StepPageWords {
    no_pixel: String,
    frame_after: String,
    depth_after: String,
    stored: String,
    after: String,
    why: String,
    keeps: String,
    status: String,
}

/// One stop as a page reads it ([`stop_data`]).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct StopData {
    /// The polygon, from 0.
    pub polygon: usize,
    /// The polygon's heading.
    pub heading: String,
    /// The scanline's pixel row.
    pub row: u32,
    /// The scanline and its row, in words.
    pub scanline: String,
    /// The crossings, sorted.
    pub crossings: String,
    /// Each span with its ends' depths (x_a, z_a, x_b, z_b) and its columns,
    /// as the line mode shows it.
    pub spans: Vec<String>,
    /// The notes, in words.
    pub notes: Vec<String>,
    /// Each covered pixel, in order.
    pub pixels: Vec<PixelData>,
}

/// One covered pixel of a stop as a page reads it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PixelData {
    /// Its column.
    pub x: u32,
    /// Its depth, exact and in decimals.
    pub z: String,
    /// What the z-buffer held before it.
    pub stored: String,
    /// Whether it was written.
    pub written: bool,
    /// What the z-buffer holds after it.
    pub after: String,
    /// The z-buffer's cell after it, as the grid writes a cell.
    pub cell: String,
    /// The framebuffer's value after it.
    pub frame: u32,
    /// Why, in words.
    pub reason: String,
}

/// Every stop of the scene (each scanline that covers a pixel, in order) as
/// data for a page ([`stop_data`]).
pub fn stops(lang: Lang, stepper: &mut Stepper<'_>) -> Vec<StopData> {
    let mut stops = Vec::new();
    let mut moved = stepper.start(None);
    while let Moved::To { at: Some(stop), .. } = moved {
        stops.push(stop_data(lang, stepper, stop));
        moved = stepper.forward();
    }
    stops
}

/// One stop as data for a page: its heading, crossings, spans with their
/// ends' depths and the notes in words, and each covered pixel's depth, test,
/// reason and the values both buffers hold after it (applied in order from
/// the cleared buffers, they give the buffers at any stop).
pub fn stop_data(lang: Lang, stepper: &mut Stepper<'_>, stop: Stop) -> StopData {
    let scene = stepper.scene();
    let record = stepper.tracer().record(stop).clone();
    let pixels = record
        .pixels
        .iter()
        .map(|e| PixelData {
            x: e.x,
            z: exact_and_decimal(lang, e.depth.value()),
            stored: e.stored_before.text(lang),
            written: e.outcome == Outcome::Written,
            after: e.stored_after.text(lang),
            cell: MatrixCell::text(&e.stored_after),
            frame: e.frame_after,
            reason: pixel_reason(lang, scene, e),
        })
        .collect();
    let stop_words = stepper.stop_words(lang, stop);
    StopData {
        polygon: stop.polygon,
        heading: stop_words.heading,
        row: record.row,
        scanline: stop_words.scanline,
        crossings: stop_words.crossings,
        spans: crate::teach::step::table::span_lines(lang, scene, &record),
        notes: crate::teach::step::table::notes(lang, scene, stop.polygon, &record, stepper.arith()),
        pixels,
    }
}

/// A state's two buffers cell by cell, top row first, to draw a grid of.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct CellBuffers {
    /// The framebuffer's values.
    pub frame: Vec<Vec<u32>>,
    /// The z-buffer's cells, as the grid writes a cell.
    pub depth: Vec<Vec<String>>,
}

/// `buffers` cell by cell.
pub fn cell_buffers(buffers: &crate::simulate::buffer::Buffers) -> CellBuffers {
    let depth = buffers.depth_rows().iter().map(|r| r.iter().map(MatrixCell::text).collect()).collect();
    CellBuffers { frame: buffers.frame_rows(), depth }
}

/// `buffers` as `zsim run` prints them: the framebuffer, then the z-buffer.
pub fn printed_buffers(buffers: &crate::simulate::buffer::Buffers) -> (String, String) {
    let style = MatrixStyle::default();
    (matrix_styled(&buffers.frame_rows(), &style), matrix_styled(&buffers.depth_rows(), &style))
}

/// Markup's special characters written as JSON escapes (`<` as `\u003c`, …),
/// so that no string in the data can end the `<script>` element holding it
/// (`</script>`), open a comment that hides its end (`<!--`) or start an
/// entity; the JSON reads the same.
pub(crate) fn embedded_json(json: &str) -> String {
    json.replace('<', "\\u003c").replace('>', "\\u003e").replace('&', "\\u0026")
}

/// A part of the template with its title and words filled in, escaped.
fn fill(lang: Lang, part: &str, title: &str) -> String {
    let mut part = part.to_string();
    for (marker, key) in [
        ("{{LANG}}", None),
        ("{{BACK}}", Some("command-back")),
        ("{{NEXT}}", Some("command-next")),
        ("{{PREVIOUS_POLYGON}}", Some("command-previous-polygon")),
        ("{{NEXT_POLYGON}}", Some("command-next-polygon")),
        ("{{FRAME}}", Some("command-show-frame")),
        ("{{DEPTH}}", Some("command-show-depth")),
        ("{{NO_QUIZ}}", Some("quiz-not-on-recorded-steps")),
    ] {
        let text = key.map_or_else(|| lang.code().to_string(), |key| crate::words::text(lang, key, &[]));
        part = part.replace(marker, &escape(&text));
    }
    // The title last: what it holds is never taken for a place in the template.
    part.replace("{{TITLE}}", &escape(title))
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

const TEMPLATE: &str = r##"<!DOCTYPE html>
<html lang="{{LANG}}"><head><meta charset="utf-8"><title>zsim step: {{TITLE}}</title>
<style>
body { font-family: sans-serif; margin: 1em; color: #222; }
#main { display: flex; gap: 1.5em; align-items: flex-start; }
table.raster { border-collapse: collapse; font-family: monospace; font-size: 12px; }
table.raster td { border: 1px solid #ddd; padding: 1px 3px; text-align: right; min-width: 1.4em; }
table.raster th { font-weight: normal; color: #888; padding: 0 4px; white-space: nowrap; }
tr.current td { border-top: 2px solid #3a6ea5; border-bottom: 2px solid #3a6ea5; }
td.span { background: #f0e442; }
td.earlier { color: #0072b2; font-weight: bold; }
#panel { max-width: 40em; }
#pixels { border-collapse: collapse; font-size: 13px; }
#pixels td, #pixels th { border-bottom: 1px solid #eee; padding: 2px 6px; text-align: left; }
.written { color: #1a7f37; } .hidden { color: #b42318; }
button { margin: 0 .3em .5em 0; }
#status { color: #555; }
</style></head>
<body>
<h1>zsim step: {{TITLE}}</h1>
<div>
<button id="back">{{BACK}}</button><button id="next">{{NEXT}}</button>
<button id="prevPolygon">{{PREVIOUS_POLYGON}}</button><button id="nextPolygon">{{NEXT_POLYGON}}</button>
<button id="frame">{{FRAME}}</button><button id="depth">{{DEPTH}}</button>
<span id="status"></span>
</div>
<p id="noQuiz">{{NO_QUIZ}}</p>
<div id="main"><div id="raster"></div><div id="panel"></div></div>
<script type="application/json" id="data">{{DATA}}</script>
<script>
"use strict";
const data = JSON.parse(document.getElementById("data").textContent);
const words = data.words;
let at = 0, view = "frame";
const el = (tag, text, cls) => { const e = document.createElement(tag); if (text !== undefined) e.textContent = text; if (cls) e.className = cls; return e; };
// The raster after the scanline: its covered cells in yellow, the polygon's earlier writes in blue.
function renderGrid(stop) {
  const covered = new Map(stop.pixels.map(p => [p.x, p]));
  const earlier = new Set();
  for (let i = 0; i < at; i++) {
    const s = data.stops[i];
    if (s.polygon === stop.polygon) s.pixels.filter(p => p.written).forEach(p => earlier.add(s.row + "," + p.x));
  }
  const table = el("table", undefined, "raster");
  // Column numbers above the grid, as the rows carry theirs.
  const numbers = el("tr"); numbers.appendChild(el("th", ""));
  for (let x = 0; x < data.width; x++) numbers.appendChild(el("th", String(x)));
  table.appendChild(numbers);
  // The buffers after this stop: the cleared buffers with every stop's pixels up to it applied.
  const rows = (view === "frame" ? data.cleared.frame : data.cleared.depth).map(r => r.slice());
  for (let i = 0; i <= at; i++) {
    const s = data.stops[i], row = rows[data.top - s.row];
    s.pixels.forEach(p => { row[p.x] = view === "frame" ? p.frame : p.cell; });
  }
  rows.forEach((row, i) => {
    const y = data.top - i;
    const tr = el("tr", undefined, y === stop.row ? "current" : "");
    tr.appendChild(el("th", (y === stop.row ? "▶ " : "") + y));
    row.forEach((v, x) => {
      const cls = y === stop.row && covered.has(x) ? "span" : earlier.has(y + "," + x) ? "earlier" : "";
      tr.appendChild(el("td", String(v), cls));
    });
    table.appendChild(tr);
  });
  document.getElementById("raster").replaceChildren(el("div", view === "frame" ? words.frameAfter : words.depthAfter), table);
}
function render() {
  const stop = data.stops[at];
  if (!stop) { document.getElementById("panel").textContent = words.noPixel; return; }
  renderGrid(stop);
  const panel = document.getElementById("panel");
  panel.replaceChildren(el("h2", stop.heading), el("p", stop.scanline), el("p", stop.crossings));
  stop.spans.forEach(s => panel.appendChild(el("p", s)));
  const pixels = el("table"); pixels.id = "pixels";
  const head = el("tr"); ["x", "z", words.stored, words.after, words.why].forEach(h => head.appendChild(el("th", h)));
  pixels.appendChild(head);
  stop.pixels.forEach(p => {
    const tr = el("tr", undefined, p.written ? "written" : "hidden");
    tr.appendChild(el("td", String(p.x))); tr.appendChild(el("td", p.z)); tr.appendChild(el("td", p.stored));
    tr.appendChild(el("td", p.written ? p.after : words.keeps.replace("{after}", p.after)));
    tr.appendChild(el("td", p.reason));
    pixels.appendChild(tr);
  });
  panel.appendChild(pixels);
  document.getElementById("status").textContent = words.status.replace("{at}", at + 1).replace("{count}", data.stops.length);
}
function go(i) { at = Math.max(0, Math.min(data.stops.length - 1, i)); render(); }
function polygon(direction) {
  const p = data.stops[at].polygon;
  let i = at;
  if (direction > 0) { while (i < data.stops.length && data.stops[i].polygon === p) i++; }
  else { while (i > 0 && data.stops[i - 1].polygon === p) i--; if (i > 0) { const q = data.stops[i - 1].polygon; i--; while (i > 0 && data.stops[i - 1].polygon === q) i--; } }
  if (i < data.stops.length) go(i);
}
document.getElementById("next").onclick = () => go(at + 1);
document.getElementById("back").onclick = () => go(at - 1);
document.getElementById("nextPolygon").onclick = () => polygon(1);
document.getElementById("prevPolygon").onclick = () => polygon(-1);
document.getElementById("frame").onclick = () => { view = "frame"; render(); };
document.getElementById("depth").onclick = () => { view = "depth"; render(); };
document.addEventListener("keydown", e => {
  const k = e.key;
  if (k === "n" || k === " " || k === "ArrowRight" || k === "ArrowDown") go(at + 1);
  else if (k === "b" || k === "ArrowLeft" || k === "ArrowUp") go(at - 1);
  else if (k === "p") polygon(1); else if (k === "P") polygon(-1);
  else if (k === "f") { view = "frame"; render(); } else if (k === "z") { view = "depth"; render(); }
  else return;
  e.preventDefault();
});
render();
</script>
</body></html>
"##;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;

    /// A stop as the page's script reads it, its type's shape: the first
    /// stop of a right triangle on a 4×3 raster.
    #[test]
    fn a_stop_is_typed() {
        let text = r#"{"width": 4, "height": 3, "polygons": [{"name": "t", "value": 1, "vertices": [[0, 0, 1], [4, 0, 1], [0, 3, 1]]}]}"#;
        let scene = Scene::from_json(text, std::path::Path::new("small.json")).unwrap();
        let mut stepper = Stepper::new(&scene, crate::effects::arith::Arith::Exact);
        let stops = stops(Lang::En, &mut stepper);
        assert_eq!((stops.len(), stops[0].row, stops[0].pixels.len()), (3, 0, 3));
        insta::with_settings!({snapshot_path => "../../../snapshots", prepend_module_to_snapshot => false, omit_expression => true}, {
            insta::assert_snapshot!("step_page_stop", serde_json::to_string_pretty(&stops[0]).unwrap());
        });
    }

    /// The page carries the cleared buffers and each stop's pixels; applied in
    /// order (as its script applies them) they are the buffers after each stop,
    /// on every example scene.
    #[test]
    fn each_stops_pixels_applied_in_order_give_the_buffers_after_it() {
        let folder = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/examples"));
        let mut checked = 0;
        for entry in std::fs::read_dir(folder).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_none_or(|e| e != "json") {
                continue;
            }
            let scene = Scene::load(&path).unwrap();
            let mut stepper = Stepper::new(&scene, crate::effects::arith::Arith::Exact);
            let stops = stops(Lang::En, &mut stepper);
            let cleared = crate::simulate::simulation::Simulation::new(&scene);
            let CellBuffers { mut frame, mut depth } = cell_buffers(cleared.buffers());
            let top = crate::raster::row_y(scene.height, 0);
            let mut moved = stepper.start(None);
            for data in &stops {
                let Moved::To { at: Some(stop), .. } = moved else { panic!("as many stops") };
                let row = (top - data.row) as usize;
                for pixel in &data.pixels {
                    let x = pixel.x as usize;
                    frame[row][x] = pixel.frame;
                    depth[row][x] = pixel.cell.clone();
                }
                let after = cell_buffers(&stepper.tracer().buffers_after(stop));
                assert_eq!((&frame, &depth), (&after.frame, &after.depth), "{}", path.display());
                moved = stepper.forward();
                checked += 1;
            }
        }
        assert!(checked > 100, "{checked} stops");
    }
}
