//! `zsim step --html`: the stepper as one self-contained page (no network,
//! no external script or style) for a course site or a lecture. Every number
//! on it comes from the recorded trace, embedded as data; the page's script
//! only shows it.

use zsim::Outcome;
use zsim::exact_and_decimal;
use zsim::explain::{pixel_reason, scanline_text};
use zsim::report::{self, MatrixCell};

use zsim::Tracer;

/// The page for the whole scene: every scanline that covers a pixel, in order.
pub fn page(tracer: &mut Tracer<'_>, title: &str) -> String {
    let scene = tracer.scene;
    let mut stops = Vec::new();
    let mut at = tracer.next_stop(None).0;
    while let Some((p, k)) = at {
        let record = tracer.trace(p).scanlines[k].clone();
        let buffers = tracer.buffers_after(p, k);
        let pixels: Vec<serde_json::Value> = record
            .pixels
            .iter()
            .map(|e| {
                serde_json::json!({
                    "x": e.x, "z": exact_and_decimal(e.depth.value()), "stored": e.stored_before.to_string(),
                    "written": e.outcome == Outcome::Written, "after": e.stored_after.to_string(),
                    "afterValue": zsim::report::exact_json(e.stored_after.value()), "frame": e.frame_after,
                    "frameBefore": e.frame_before,
                    "reason": pixel_reason(scene, e),
                })
            })
            .collect();
        let spans: Vec<String> = record
            .spans
            .iter()
            .enumerate()
            .map(|(i, s)| {
                let columns = s.columns.map_or_else(
                    || zsim::words!("tui-no-centre"),
                    |(f, l)| zsim::words!("step-columns", first = f.to_string(), last = l.to_string()),
                );
                zsim::words!(
                    "tui-span",
                    n = (i + 1).to_string(),
                    left = exact_and_decimal(&s.left),
                    right = exact_and_decimal(&s.right),
                    columns = columns
                )
            })
            .collect();
        let crossings: Vec<String> = record.crossings.iter().map(exact_and_decimal).collect();
        stops.push(serde_json::json!({
            "polygon": p, "heading": report::polygon_heading(scene, p), "row": record.row,
            "scanline": zsim::words!("step-scanline", scanline = scanline_text(record.row), row = record.row.to_string()),
            "crossings": zsim::words!("step-crossings", list = crossings.join(&zsim::words!("list-comma"))),
            "spans": spans, "pixels": pixels,
            "frame": buffers.frame_rows(),
            "depth": buffers.depth_rows().iter().map(|r| r.iter().map(MatrixCell::text).collect::<Vec<_>>()).collect::<Vec<_>>(),
        }));
        at = tracer.next_stop(Some((p, k))).0;
    }
    // The page's words, in the student's language; {…} marks what the script fills in.
    let words = serde_json::json!({
        "noPixel": zsim::words!("page-no-pixel"),
        "frameAfter": zsim::words!("page-frame-after"),
        "depthAfter": zsim::words!("page-depth-after"),
        "frameBefore": zsim::words!("page-frame-before"),
        "depthBefore": zsim::words!("page-depth-before"),
        "notNumber": zsim::words!("page-not-a-number", text = "{text}"),
        "unanswered": zsim::words!("page-unanswered"),
        "stored": zsim::words!("page-column-stored"),
        "yours": zsim::words!("page-column-yours"),
        "after": zsim::words!("page-column-after"),
        "why": zsim::words!("page-column-why"),
        "check": zsim::words!("page-check"),
        "keeps": zsim::words!("page-keeps", value = "{after}"),
        "right": zsim::words!("page-right"),
        "wrong": zsim::words!("page-wrong"),
        "quizScore": zsim::words!("page-quiz-score", right = "{right}", total = "{total}"),
        "status": zsim::words!("page-status", at = "{at}", count = "{count}"),
    });
    let data = serde_json::json!({"title": title, "width": scene.width, "height": scene.height, "op": scene.depth_test.symbol(), "words": words, "stops": stops});
    let data = serde_json::to_string(&data).expect("serializing plain data cannot fail");
    let (head, tail) = TEMPLATE.split_once("{{DATA}}").expect("the template has a place for the data");
    // The data goes in last, so that nothing in it (a polygon named "{{TITLE}}") is
    // taken for a place in the template.
    format!("{}{}{}", fill(head, title), embedded_json(&data), fill(tail, title))
}

/// Markup's special characters written as JSON escapes (`<` as `\u003c`, …),
/// so that no string in the data can end the `<script>` element holding it
/// (`</script>`), open a comment that hides its end (`<!--`) or start an
/// entity; the JSON reads the same.
fn embedded_json(json: &str) -> String {
    json.replace('<', "\\u003c").replace('>', "\\u003e").replace('&', "\\u0026")
}

/// A part of the template with its title and words filled in, escaped.
fn fill(part: &str, title: &str) -> String {
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
        let text = key.map_or_else(|| zsim::language().code().to_string(), |key| zsim::message(key, &[]));
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
table.raster th { font-weight: normal; color: #888; padding: 0 4px; }
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
<pre id="selftest" hidden></pre>
<script>const pageErrors = []; window.addEventListener("error", e => pageErrors.push(e.message));</script>
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
      // A number (integer, fraction or decimal) or "-" is an answer, judged right or wrong
      // (coloured so); anything else is said not to be a number, an empty box unanswered.
      const number = /^-?(\d+(\/\d+)?|\d*\.\d+)$/;
      pixels.querySelectorAll("input").forEach((input, i) => {
        const p = stop.pixels[i], typed = input.value.trim(), why = input.parentElement.nextSibling;
        if (typed === "" || (typed !== "-" && !number.test(typed))) {
          why.className = "why unanswered";
          why.textContent = typed === "" ? words.unanswered : words.notNumber.replace("{text}", typed);
          return;
        }
        const ok = typed === "-" ? !p.written : typed === String(p.afterValue);
        right += ok ? 1 : 0;
        why.className = ok ? "why right" : "why wrong";
        why.textContent = (ok ? words.right : words.wrong) + p.reason;
      });
      stop.checked = true;
      renderGrid(stop, true);
      document.getElementById("status").textContent = words.quizScore.replace("{right}", right).replace("{total}", stop.pixels.length);
    };
    panel.appendChild(check);
  }
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
// #selftest: clicks through as a person would and writes what the page showed (for the tests).
if (location.hash === "#selftest") {
  const seen = [];
  const heading = () => document.querySelector("#panel p").textContent;
  seen.push("start: " + heading());
  document.getElementById("next").click(); seen.push("after Next: " + heading());
  document.getElementById("nextPolygon").click();
  while (data.stops[at].row !== 15 && at < data.stops.length - 1) document.getElementById("next").click();
  seen.push("at: " + heading());
  seen.push("panel: " + document.getElementById("panel").textContent);
  // The quiz on the same scanline, in the z-buffer: the grid before, then answers right, wrong,
  // not a number, and "-" for the hidden pixel (21, 15), checked.
  document.getElementById("quiz").click();
  document.getElementById("depth").click();
  const row = () => Array.from(document.querySelectorAll("#raster tr.current td")).slice(15, 28).map(td => td.textContent).join(" ");
  seen.push("quiz grid: " + document.querySelector("#raster div").textContent + ": " + row());
  const inputs = document.querySelectorAll("#pixels input");
  inputs[0].value = "15"; inputs[1].value = "10"; inputs[2].value = "zz";
  inputs.forEach(input => { if (input.dataset.x === "21") input.value = "-"; });
  document.getElementById("check").click();
  const verdicts = Array.from(document.querySelectorAll("#pixels td.why")).map((td, i) => inputs[i].dataset.x + " " + td.className.replace("why ", "") + " " + td.textContent.split(":")[0]);
  seen.push("verdicts: " + verdicts.join(" | "));
  seen.push("checked grid: " + document.querySelector("#raster div").textContent + ": " + row());
  seen.push("score: " + document.getElementById("status").textContent);
  seen.push("errors: " + (pageErrors.length ? pageErrors.join("; ") : "none"));
  const out = document.getElementById("selftest"); out.hidden = false; out.textContent = seen.join("\n");
}
</script>
</body></html>
"##;
