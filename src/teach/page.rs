//! `zsim step --html`: the stepper as one self-contained page (no network,
//! no external script or style) for a course site or a lecture. Every stop,
//! every number and every word on it comes from the teaching model
//! ([`crate::teach::step`]), embedded as data; the page's script only shows
//! it. The quiz's answers are judged by the model's rule for depth answers
//! (`-`, or a number read exactly: an integer, a decimal or a fraction, that
//! a cell can hold), which the script applies to the embedded right answer;
//! the tests hold the two to the same verdicts through a real browser.

use crate::numbers::exact_and_decimal;
use crate::observe::explain::pixel_reason;
use crate::observe::report::{MatrixCell, MatrixStyle, matrix_styled};
use crate::observe::step::Stop;
use crate::simulate::events::Outcome;
use crate::teach::step::{Moved, Stepper};
use crate::words::Lang;

/// The page for the whole scene: every scanline that covers a pixel, in order.
pub fn page(lang: Lang, stepper: &mut Stepper<'_>, title: &str) -> String {
    let scene = stepper.scene();
    let stops = stops(lang, stepper);
    // The page's words, in the student's language; {…} marks what the script fills in.
    let words = serde_json::json!({
        "noPixel": words!(lang, "page-no-pixel"),
        "frameAfter": words!(lang, "page-frame-after"),
        "depthAfter": words!(lang, "page-depth-after"),
        "frameBefore": words!(lang, "page-frame-before"),
        "depthBefore": words!(lang, "page-depth-before"),
        "notNumber": words!(lang, "page-not-a-number", text = "{text}"),
        "doesNotFit": words!(lang, "quiz-does-not-fit", text = "{text}", max = scene.depth_max().to_string()),
        "unanswered": words!(lang, "page-unanswered"),
        "stored": words!(lang, "page-column-stored"),
        "yours": words!(lang, "page-column-yours"),
        "after": words!(lang, "page-column-after"),
        "why": words!(lang, "page-column-why"),
        "check": words!(lang, "page-check"),
        "keeps": words!(lang, "page-keeps", value = "{after}"),
        "right": words!(lang, "page-right"),
        "wrong": words!(lang, "page-wrong"),
        "quizScore": words!(lang, "page-quiz-score", right = "{right}", total = "{total}"),
        "status": words!(lang, "page-status", at = "{at}", count = "{count}"),
    });
    // The most a cell can hold, for the quiz's "no cell can hold it" (`None`: exact depths).
    let max = (scene.rules.store == crate::rules::DepthStore::Quantized).then(|| scene.depth_max());
    let data = serde_json::json!({"title": title, "width": scene.width, "height": scene.height, "op": scene.depth_test.symbol(), "max": max, "words": words, "stops": stops});
    let data = serde_json::to_string(&data).expect("serializing plain data cannot fail");
    let (head, tail) = TEMPLATE.split_once("{{DATA}}").expect("the template has a place for the data");
    // The data goes in last, so that nothing in it (a polygon named "{{TITLE}}") is
    // taken for a place in the template.
    format!("{}{}{}", fill(lang, head, title), embedded_json(&data), fill(lang, tail, title))
}

/// Every stop of the scene (each scanline that covers a pixel, in order) as
/// data for a page ([`stop_data`]).
pub fn stops(lang: Lang, stepper: &mut Stepper<'_>) -> Vec<serde_json::Value> {
    let mut stops = Vec::new();
    let mut moved = stepper.start(None);
    while let Moved::To { at: Some(stop), .. } = moved {
        stops.push(stop_data(lang, stepper, stop, Buffers::Cells));
        moved = stepper.forward();
    }
    stops
}

/// Where the stepper's stops are, without what each shows: each stop's
/// polygon and row, in order.
pub fn stop_places(stepper: &mut Stepper<'_>) -> Vec<Stop> {
    let mut places = Vec::new();
    let mut moved = stepper.start(None);
    while let Moved::To { at: Some(stop), .. } = moved {
        places.push(stop);
        moved = stepper.forward();
    }
    places
}

/// How a page wants a stop's buffers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Buffers {
    /// Rows of cells, top row first, to draw a grid of.
    Cells,
    /// The matrices as `zsim run` prints them.
    Printed,
}

/// One stop as data for a page: its heading, crossings, spans with their
/// ends' depths and the notes in words, each pixel's depth, test and reason,
/// and both buffers after it, as `asked`.
pub fn stop_data(lang: Lang, stepper: &mut Stepper<'_>, stop: Stop, asked: Buffers) -> serde_json::Value {
    let scene = stepper.scene();
    let record = stepper.tracer().record(stop).clone();
    let buffers = stepper.tracer().buffers_after(stop);
    let pixels: Vec<serde_json::Value> = record
        .pixels
        .iter()
        .map(|e| {
            serde_json::json!({
                "x": e.x, "z": exact_and_decimal(lang, e.depth.value()), "stored": e.stored_before.text(lang),
                "written": e.outcome == Outcome::Written, "after": e.stored_after.text(lang),
                "afterExact": crate::numbers::fraction(e.stored_after.value()), "frame": e.frame_after,
                "frameBefore": e.frame_before,
                "reason": pixel_reason(lang, scene, e),
            })
        })
        .collect();
    let stop_words = stepper.stop_words(lang, stop);
    let matrices = buffer_data(&buffers, asked);
    serde_json::json!({
        "polygon": stop.polygon, "heading": stop_words.heading, "row": record.row,
        "scanline": stop_words.scanline, "crossings": stop_words.crossings,
        // Each span with its ends' depths (x_a, z_a, x_b, z_b) and its columns, as the line mode shows it.
        "spans": crate::teach::stop::span_lines(lang, scene, &record),
        "notes": crate::teach::stop::notes(lang, scene, stop.polygon, &record, stepper.arith()),
        "pixels": pixels,
        "frame": matrices.0,
        "depth": matrices.1,
    })
}

/// A state's two buffers as a page asks for them ([`Buffers`]).
pub fn buffer_data(
    buffers: &crate::simulate::buffer::Buffers,
    asked: Buffers,
) -> (serde_json::Value, serde_json::Value) {
    match asked {
        Buffers::Cells => (
            serde_json::json!(buffers.frame_rows()),
            serde_json::json!(
                buffers
                    .depth_rows()
                    .iter()
                    .map(|r| r.iter().map(MatrixCell::text).collect::<Vec<_>>())
                    .collect::<Vec<_>>()
            ),
        ),
        Buffers::Printed => {
            let style = MatrixStyle::default();
            (matrix_styled(&buffers.frame_rows(), &style).into(), matrix_styled(&buffers.depth_rows(), &style).into())
        }
    }
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
        ("{{BACK}}", Some("page-back")),
        ("{{NEXT}}", Some("page-next")),
        ("{{PREVIOUS_POLYGON}}", Some("page-previous-polygon")),
        ("{{NEXT_POLYGON}}", Some("page-next-polygon")),
        ("{{FRAME}}", Some("page-frame")),
        ("{{DEPTH}}", Some("page-depth")),
        ("{{QUIZ}}", Some("page-quiz")),
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
.written, .right { color: #1a7f37; } .hidden, .wrong { color: #b42318; } .unanswered { color: #9a6700; }
button { margin: 0 .3em .5em 0; }
#status { color: #555; }
</style></head>
<body>
<h1>zsim step: {{TITLE}}</h1>
<div>
<button id="back">{{BACK}}</button><button id="next">{{NEXT}}</button>
<button id="prevPolygon">{{PREVIOUS_POLYGON}}</button><button id="nextPolygon">{{NEXT_POLYGON}}</button>
<button id="frame">{{FRAME}}</button><button id="depth">{{DEPTH}}</button>
<label><input type="checkbox" id="quiz"> {{QUIZ}}</label>
<span id="status"></span>
</div>
<div id="main"><div id="raster"></div><div id="panel"></div></div>
<script type="application/json" id="data">{{DATA}}</script>
<script>
"use strict";
const data = JSON.parse(document.getElementById("data").textContent);
const words = data.words;
let at = 0, view = "frame";
const el = (tag, text, cls) => { const e = document.createElement(tag); if (text !== undefined) e.textContent = text; if (cls) e.className = cls; return e; };
// The raster: after the scanline, or in the quiz until its answers are checked, before it
// (the covered cells of the current row as they were), so that the grid gives nothing away.
function renderGrid(stop, quiz) {
  const before = quiz && !stop.checked;
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
  const rows = view === "frame" ? stop.frame : stop.depth;
  rows.forEach((row, i) => {
    const y = data.height - 1 - i;
    const tr = el("tr", undefined, y === stop.row ? "current" : "");
    tr.appendChild(el("th", (y === stop.row ? "▶ " : "") + y));
    row.forEach((v, x) => {
      const cls = y === stop.row && covered.has(x) ? "span" : earlier.has(y + "," + x) ? "earlier" : "";
      const p = y === stop.row && before ? covered.get(x) : undefined;
      const shown = p === undefined ? v : view === "frame" ? p.frameBefore : p.stored;
      tr.appendChild(el("td", String(shown), cls));
    });
    table.appendChild(tr);
  });
  const caption = before ? (view === "frame" ? words.frameBefore : words.depthBefore) : (view === "frame" ? words.frameAfter : words.depthAfter);
  document.getElementById("raster").replaceChildren(el("div", caption), table);
}
function render() {
  const stop = data.stops[at];
  if (!stop) { document.getElementById("panel").textContent = words.noPixel; return; }
  const quiz = document.getElementById("quiz").checked;
  renderGrid(stop, quiz);
  const panel = document.getElementById("panel");
  panel.replaceChildren(el("h2", stop.heading), el("p", stop.scanline), el("p", stop.crossings));
  stop.spans.forEach(s => panel.appendChild(el("p", s)));
  const pixels = el("table"); pixels.id = "pixels";
  const head = el("tr"); ["x", "z", words.stored, quiz ? words.yours : words.after, words.why].forEach(h => head.appendChild(el("th", h)));
  pixels.appendChild(head);
  stop.pixels.forEach(p => {
    // In the quiz the row's colour would tell written from hidden: none until checked.
    const tr = el("tr", undefined, quiz ? "" : p.written ? "written" : "hidden");
    tr.appendChild(el("td", String(p.x))); tr.appendChild(el("td", p.z)); tr.appendChild(el("td", p.stored));
    if (quiz) {
      const td = el("td"); const input = el("input"); input.size = 4; input.dataset.x = p.x; td.appendChild(input); tr.appendChild(td);
      tr.appendChild(el("td", "", "why"));
    } else {
      tr.appendChild(el("td", p.written ? p.after : words.keeps.replace("{after}", p.after)));
      tr.appendChild(el("td", p.reason));
    }
    pixels.appendChild(tr);
  });
  panel.appendChild(pixels);
  if (quiz) {
    const check = el("button", words.check); check.id = "check";
    check.onclick = () => {
      let right = 0;
      pixels.querySelectorAll("input").forEach((input, i) => {
        const p = stop.pixels[i], typed = input.value.trim(), why = input.parentElement.nextSibling;
        const verdict = typed === "" ? { again: words.unanswered } : judge(p, typed);
        if (verdict.again !== undefined) { why.className = "why unanswered"; why.textContent = verdict.again; return; }
        right += verdict.right ? 1 : 0;
        why.className = verdict.right ? "why right" : "why wrong";
        why.textContent = (verdict.right ? words.right : words.wrong) + p.reason;
      });
      stop.checked = true;
      renderGrid(stop, true);
      document.getElementById("status").textContent = words.quizScore.replace("{right}", right).replace("{total}", stop.pixels.length);
    };
    panel.appendChild(check);
  }
  document.getElementById("status").textContent = words.status.replace("{at}", at + 1).replace("{count}", data.stops.length);
}
// A number read exactly, as the model reads one (an integer, a decimal with an optional
// exponent, or a fraction of two): [numerator, denominator] as BigInts; null if it is not one.
function decimal(text) {
  const m = /^([+-]?)(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d{1,4}))?$/.exec(text.trim());
  if (!m || (m[2] + (m[3] || "")) === "") return null;
  let num = BigInt((m[2] || "") + (m[3] || "")), den = 10n ** BigInt((m[3] || "").length);
  const e = m[4] ? Number(m[4]) : 0;
  if (e > 0) num *= 10n ** BigInt(e); else if (e < 0) den *= 10n ** BigInt(-e);
  return [m[1] === "-" ? -num : num, den];
}
function exact(text) {
  const parts = text.split("/");
  if (parts.length > 2) return null;
  const a = decimal(parts[0]);
  if (!a || parts.length === 1) return a;
  const b = decimal(parts[1]);
  if (!b || b[0] === 0n) return null;
  const n = a[0] * b[1], d = a[1] * b[0];
  return d < 0n ? [-n, -d] : [n, d];
}
// The model's judge of a depth answer (teach::step::judge_depth): "-" means not written;
// a number is right when it is the value the z-buffer holds after the pixel; anything else,
// or a number no cell can hold, is asked again.
function judge(p, typed) {
  if (typed === "-") return { right: !p.written };
  const q = exact(typed);
  if (!q) return { again: words.notNumber.replace("{text}", typed) };
  if (data.max !== null && (q[0] % q[1] !== 0n || q[0] / q[1] < 0n || q[0] / q[1] > BigInt(data.max)))
    return { again: words.doesNotFit.replace("{text}", typed) };
  const r = exact(p.afterExact);
  return { right: q[0] * r[1] === r[0] * q[1] };
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
document.getElementById("quiz").onchange = render;
document.addEventListener("keydown", e => {
  if (e.target.tagName === "INPUT" && e.target.type !== "checkbox") return;
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
