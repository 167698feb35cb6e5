// The playground's page: it shows what zsim's library (compiled to
// WebAssembly, `wasm_bindgen` below) says of the scene, and asks the library
// for every verdict. It holds no rule of its own: editing the scene, the
// buffers, the quiz's verdicts, a homework's check and the words all come
// from the module.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const el = (tag, text, cls) => {
    const e = document.createElement(tag);
    if (text !== undefined && text !== null) e.textContent = text;
    if (cls) e.className = cls;
    return e;
  };
  const SVG = "http://www.w3.org/2000/svg";
  const svg = (tag, attrs) => {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    return e;
  };
  // Framebuffer values as colours (0, the usual background, is white).
  const PALETTE = ["#ffffff", "#56b4e9", "#e69f00", "#009e73", "#f0e442", "#0072b2", "#d55e00", "#cc79a7"];
  let z, lang = "en", words = {}, scene = "", view = null, at = 0, drag = null;
  // What the shown stop shows, from the library (with the view, or asked when the stop changes).
  let shownStop = null;

  function call(name, ...args) { return JSON.parse(z[name](lang, ...args)); }

  function setLanguage(code) {
    lang = code;
    words = JSON.parse(z.words(lang));
    document.documentElement.lang = lang;
    $("lang").value = lang;
    document.title = words.title;
    $("title").textContent = words.title;
    $("intro").textContent = words.intro;
    document.querySelectorAll("[data-word]").forEach((e) => { e.textContent = words[e.dataset.word]; });
    document.querySelectorAll(".frameName").forEach((e) => { e.textContent = words.frameName; });
    document.querySelectorAll(".depthName").forEach((e) => { e.textContent = words.depthName; });
    setScene(scene, true);
  }

  // The scene's text is the one source: every control edits it through the library.
  function setScene(text, keepEditor) {
    scene = text;
    if (!keepEditor || $("json").value !== text) $("json").value = text;
    const next = JSON.parse(z.view(lang, text, at));
    $("json").classList.toggle("invalid", !next.ok);
    $("error").textContent = next.ok ? "" : next.error;
    // What is drawn is the last scene that could be read: dimmed while the text is not one.
    $("view").classList.toggle("stale", !next.ok);
    if (!next.ok) {
      view = null;
      ["framebuffer", "zbuffer", "afterFrame", "afterDepth", "explain"].forEach((id) => { $(id).textContent = ""; });
      return;
    }
    const sameStops = view && view.stops.length === next.stops.length;
    view = next;
    if (!sameStops) at = 0;
    at = Math.min(at, Math.max(0, view.stops.length - 1));
    // The view brings what the current stop shows: no second tracing of the scene.
    if (view.stop && sameStops) shownStop = { scene, at, lang, data: Object.assign({ ok: true }, view.stop) };
    render();
  }

  function edit(change) {
    const result = call("edit", scene, JSON.stringify(change));
    if (!result.ok) { $("error").textContent = result.error; return false; }
    setScene(result.scene);
    return true;
  }

  // The scene as JSON, for filling the controls (the library reads and edits it).
  function parsed() { try { return JSON.parse(scene); } catch (e) { return null; } }

  function render() {
    const object = parsed() || {};
    for (const [id, key] of [["width", "width"], ["height", "height"], ["frameBits", "frame_bits"], ["depthBits", "depth_bits"]]) {
      if (document.activeElement !== $(id)) $(id).value = object[key] === undefined ? { width: 32, height: 32, frame_bits: 2, depth_bits: 4 }[key] : object[key];
    }
    $("depthTest").value = object.depth_test || "greater";
    $("rules").value = typeof object.rules === "string" ? object.rules : "";
    renderPolygons(object);
    renderGrid(object);
    $("notes").replaceChildren(...view.notes.map((n) => el("p", n, "help")));
    $("framebuffer").textContent = view.framebuffer;
    $("zbuffer").textContent = view.zbuffer;
    renderAfter();
    renderStop();
    renderHomeworkChoices();
    renderFigure();
  }

  // The figure, drawn by the library when its section is open.
  function renderFigure() {
    if (!$("figureBox").open) return;
    const figure = call("figure", scene);
    $("figure").innerHTML = figure.ok ? figure.svg : "";
  }

  function renderPolygons(object) {
    const box = $("polygons");
    if (box.contains(document.activeElement)) return;
    // The table only where the library shows the scene polygon by polygon (a few dozen polygons).
    const polygons = Array.isArray(object.polygons) && view.after.length === view.polygons.length ? object.polygons : [];
    box.replaceChildren();
    polygons.forEach((polygon, p) => {
      const table = el("table", undefined, "vertices");
      const head = el("tr");
      const title = el("th", `${words.polygon} ${p + 1}`);
      title.colSpan = 2;
      head.appendChild(title);
      const valueCell = el("td");
      valueCell.colSpan = 2;
      valueCell.append(words.value + " ");
      const value = el("input", undefined, "value");
      value.value = polygon.value === undefined ? "" : polygon.value;
      value.dataset.p = p;
      value.onchange = () => edit({ op: "set", path: ["polygons", p, "value"], value: value.value });
      valueCell.appendChild(value);
      head.appendChild(valueCell);
      table.appendChild(head);
      const names = el("tr");
      ["", "x", "y", "z"].forEach((n) => names.appendChild(el("th", n)));
      table.appendChild(names);
      (polygon.vertices || []).forEach((vertex, v) => {
        const row = el("tr");
        row.appendChild(el("td", String(v + 1)));
        (Array.isArray(vertex) ? vertex : []).forEach((c, i) => {
          const td = el("td");
          const input = el("input", undefined, "coord");
          input.value = c;
          Object.assign(input.dataset, { p, v, c: i });
          input.setAttribute("aria-label", `${words.polygon} ${p + 1} ${v + 1} ${"xyzw"[i]}`);
          input.onchange = () => edit({ op: "set", path: ["polygons", p, "vertices", v, i], value: input.value });
          td.appendChild(input);
          row.appendChild(td);
        });
        table.appendChild(row);
      });
      const buttons = el("tr");
      const cell = el("td");
      cell.colSpan = 4;
      const add = el("button", words.addVertex, "addVertex");
      add.onclick = () => {
        const vs = polygon.vertices || [];
        const last = vs[vs.length - 1] || [0, 0, 0];
        edit({ op: "insert", path: ["polygons", p, "vertices", vs.length], value: JSON.stringify(last) });
      };
      const remove = el("button", words.removeVertex, "removeVertex");
      remove.onclick = () => edit({ op: "remove", path: ["polygons", p, "vertices", (polygon.vertices || []).length - 1] });
      const drop = el("button", words.removePolygon, "removePolygon");
      drop.onclick = () => edit({ op: "remove", path: ["polygons", p] });
      cell.append(add, remove, drop);
      buttons.appendChild(cell);
      table.appendChild(buttons);
      box.appendChild(table);
    });
  }

  // The raster: each cell filled by the final framebuffer, outlines, and vertices to drag.
  function renderGrid(object) {
    const grid = $("grid"), w = view.width, h = view.height;
    grid.setAttribute("viewBox", `0 0 ${w} ${h}`);
    // Cell by cell only where the library shows the scene so (a few thousand cells).
    const rows = view.cellByCell ? view.framebuffer.trim().split("\n").map((r) => r.trim().split(/\s+/).map(Number)) : [];
    // The cells as one piece of markup (numbers only), made once for a raster's size; an edit
    // recolours them and redraws only the outlines and vertices.
    const size = `${w}x${h}:${rows.length}`;
    if (grid.dataset.size !== size) {
      let cells = "";
      rows.forEach((row, i) => row.forEach((value, x) => {
        cells += `<rect x="${x}" y="${i}" width="1" height="1" class="cell" data-x="${x}" data-y="${h - 1 - i}"/>`;
      }));
      grid.innerHTML = cells;
      grid.dataset.size = size;
    } else {
      grid.querySelectorAll(":scope > :not(.cell)").forEach((e) => e.remove());
    }
    const cells = grid.children;
    rows.forEach((row, i) => row.forEach((value, x) => {
      const fill = PALETTE[value % PALETTE.length], cell = cells[i * w + x];
      if (cell.getAttribute("fill") !== fill) cell.setAttribute("fill", fill);
    }));
    // Only a scene in pixel units can be dragged: its vertices are the raster's coordinates.
    const draggable = !object.window && !(object.effects && object.effects.perspective);
    view.polygons.forEach((polygon, p) => {
      const colour = PALETTE[polygon.value % PALETTE.length];
      const points = polygon.outline.map(([x, y]) => `${x},${h - y}`).join(" ");
      grid.appendChild(svg("polygon", { points, class: "outline", stroke: "#333" }));
      if (!draggable) return;
      polygon.outline.forEach(([x, y], v) => {
        const handle = svg("circle", { cx: x, cy: h - y, r: Math.max(0.35, w / 90), class: "vertex", fill: colour });
        handle.dataset.p = p;
        handle.dataset.v = v;
        handle.addEventListener("pointerdown", (e) => {
          e.preventDefault();
          handle.setPointerCapture(e.pointerId);
          drag = { p, v, last: null };
        });
        grid.appendChild(handle);
      });
    });
  }

  function pointIn(e) {
    const grid = $("grid");
    const point = new DOMPoint(e.clientX, e.clientY).matrixTransform(grid.getScreenCTM().inverse());
    const step = Number($("snap").value);
    const snap = (v) => String(Number((Math.round(v / step) * step).toFixed(4)));
    return [snap(point.x), snap(view.height - point.y)];
  }

  document.addEventListener("pointermove", (e) => {
    if (!drag || !view) return;
    const [x, y] = pointIn(e);
    if (drag.last && drag.last[0] === x && drag.last[1] === y) return;
    drag.last = [x, y];
    moveVertex(drag.p, drag.v, x, y);
  });
  document.addEventListener("pointerup", () => { drag = null; });

  function moveVertex(p, v, x, y) {
    const result = call("edit", scene, JSON.stringify({ op: "set", path: ["polygons", p, "vertices", v, 0], value: x }));
    if (!result.ok) { $("error").textContent = result.error; return; }
    const moved = call("edit", result.scene, JSON.stringify({ op: "set", path: ["polygons", p, "vertices", v, 1], value: y }));
    if (!moved.ok) { $("error").textContent = moved.error; return; }
    setScene(moved.scene);
  }

  function explainPixel(x, y) {
    const result = call("explain", scene, x, y);
    $("explain").textContent = result.ok ? result.text : result.error;
    const grid = $("grid");
    grid.querySelectorAll(".picked").forEach((e) => e.remove());
    grid.appendChild(svg("rect", { x, y: view.height - 1 - y, width: 1, height: 1, class: "picked" }));
  }

  function renderAfter() {
    const select = $("afterSelect");
    const chosen = Math.min(Number(select.value || 0), Math.max(0, view.after.length - 1));
    select.replaceChildren(...view.after.map((a, i) => { const o = el("option", view.polygons[i].label); o.value = i; return o; }));
    select.value = chosen;
    const after = view.after[chosen];
    $("afterHeading").textContent = after ? `${after.heading} — ${after.counts}` : "";
    $("afterFrame").textContent = after ? after.frame : "";
    $("afterDepth").textContent = after ? after.depth : "";
  }

  function renderStop() {
    const box = $("stop");
    if (!view.stops[at]) { box.replaceChildren(); $("status").textContent = ""; return; }
    if (!shownStop || shownStop.scene !== scene || shownStop.at !== at || shownStop.lang !== lang) {
      shownStop = { scene, at, lang, data: call("stop", scene, at) };
    }
    const stop = shownStop.data.ok ? shownStop.data : null;
    $("status").textContent = view.stops.length ? words.status.replace("{at}", at + 1).replace("{count}", view.stops.length) : "";
    if (!stop) { box.replaceChildren(); return; }
    const quiz = $("quiz").checked, kind = $("quizKind").value;
    box.replaceChildren(el("h3", stop.heading), el("p", stop.scanline));
    if (quiz) {
      const label = el("label", words.coverage + " ");
      const coverage = el("input");
      coverage.id = "coverage";
      label.appendChild(coverage);
      const why = el("span", "", "why");
      why.id = "coverageWhy";
      box.append(label, why);
    } else {
      box.appendChild(el("p", stop.crossings));
      stop.spans.forEach((s) => box.appendChild(el("p", s)));
      stop.notes.forEach((s) => box.appendChild(el("p", s, "help")));
    }
    const table = el("table");
    table.id = "pixels";
    const head = el("tr");
    const asked = kind === "frame" ? words.frameName : words.depthName;
    ["x", "z", words.stored, quiz ? asked : words.depthName, words.why].forEach((h) => head.appendChild(el("th", h)));
    table.appendChild(head);
    stop.pixels.forEach((p, i) => {
      const tr = el("tr", undefined, quiz ? "" : p.written ? "right" : "wrong");
      tr.append(el("td", String(p.x)), el("td", p.z), el("td", p.stored));
      if (quiz) {
        const td = el("td"), input = el("input");
        input.dataset.pixel = i;
        td.appendChild(input);
        tr.append(td, el("td", "", "why"));
      } else {
        tr.append(el("td", p.written ? p.after : words.keeps.replace("{after}", p.after)), el("td", p.reason));
      }
      table.appendChild(tr);
    });
    box.appendChild(table);
    if (quiz) {
      const check = el("button", words.check);
      check.id = "checkQuiz";
      check.onclick = () => {
        const typed = $("coverage").value.trim();
        if (typed !== "") show($("coverageWhy"), call("judge", scene, at, "coverage", 0, typed));
        table.querySelectorAll("input").forEach((input) => {
          const cell = input.parentElement.nextSibling, text = input.value.trim();
          if (text === "") { cell.className = "why again"; cell.textContent = words.unanswered; return; }
          show(cell, call("judge", scene, at, kind, Number(input.dataset.pixel), text));
        });
      };
      box.appendChild(check);
    } else {
      box.appendChild(el("pre", $("quizKind").value === "frame" ? stop.frame : stop.depth));
    }
  }

  function show(cell, verdict) {
    if (!verdict.ok) { cell.className = "why again"; cell.textContent = verdict.error; return; }
    if (verdict.again !== undefined) { cell.className = "why again"; cell.textContent = verdict.again; return; }
    cell.className = verdict.right ? "why right" : "why wrong";
    cell.textContent = verdict.line;
  }

  function renderHomeworkChoices() {
    const select = $("hwAfter"), chosen = select.value;
    select.replaceChildren(...view.polygons.map((p, i) => { const o = el("option", p.label); o.value = i; return o; }));
    select.value = chosen !== "" && Number(chosen) < view.polygons.length ? chosen : Math.max(0, view.polygons.length - 1);
  }

  // A grid of cells to type an answer into, top row first, starting from the cleared buffer;
  // what is typed is written into the answer's text as the book prints a matrix.
  function answerGrid() {
    const box = $("answerCells");
    if (box.firstChild) { box.replaceChildren(); return; }
    const buffer = $("hwBuffer").value, start = view.cleared[buffer];
    const lines = $("answer").value.trim().split("\n").map((l) => l.trim().split(/\s+/));
    const fits = lines.length === view.height && lines.every((l) => l.length === view.width);
    const table = el("table");
    for (let i = 0; i < view.height; i++) {
      const tr = el("tr");
      for (let x = 0; x < view.width; x++) {
        const input = el("input");
        input.value = fits ? lines[i][x] : start === null ? "" : String(start);
        Object.assign(input.dataset, { x, y: view.height - 1 - i });
        input.setAttribute("aria-label", `(${x}, ${view.height - 1 - i})`);
        const td = el("td");
        td.appendChild(input);
        tr.appendChild(td);
      }
      table.appendChild(tr);
    }
    table.addEventListener("input", () => {
      const rows = [...table.rows].map((tr) => [...tr.querySelectorAll("input")].map((i) => i.value.trim() || "?").join(" "));
      $("answer").value = rows.join("\n") + "\n";
    });
    box.appendChild(table);
    table.dispatchEvent(new Event("input"));
  }

  function checkAnswer() {
    const box = $("verdict");
    const result = call("check", scene, Number($("hwAfter").value), $("hwBuffer").value, $("answer").value);
    if (!result.ok) { box.replaceChildren(el("p", result.error, "again")); return; }
    box.replaceChildren(el("p", result.verdict, result.right ? "right" : "wrong"));
    if (result.hint) box.appendChild(el("p", result.hint));
    if (result.wrong.length) {
      const table = el("table");
      table.id = "wrongCells";
      const head = el("tr");
      result.columns.forEach((c) => head.appendChild(el("th", c)));
      table.appendChild(head);
      result.wrong.forEach((c) => {
        const tr = el("tr");
        [c.x, c.y, c.answer, c.expected, c.reason].forEach((v) => tr.appendChild(el("td", String(v))));
        table.appendChild(tr);
      });
      box.appendChild(table);
    }
    if (result.more) box.appendChild(el("p", result.more));
    if (result.diagnosis) { const d = el("p", result.diagnosis); d.id = "diagnosis"; box.appendChild(d); }
  }

  function sceneFromAddress() {
    if (!location.hash.startsWith("#scene=")) return null;
    const result = call("scene_of_fragment", location.hash);
    if (!result.ok) { $("error").textContent = result.error; return null; }
    return result.scene;
  }

  function wire() {
    $("lang").onchange = () => setLanguage($("lang").value);
    $("json").addEventListener("input", () => setScene($("json").value, true));
    for (const [id, key] of [["width", "width"], ["height", "height"], ["frameBits", "frame_bits"], ["depthBits", "depth_bits"]]) {
      $(id).addEventListener("change", () => edit({ op: "set", path: [key], value: $(id).value }));
    }
    $("depthTest").onchange = () => edit({ op: "set", path: ["depth_test"], value: JSON.stringify($("depthTest").value) });
    $("rules").onchange = () => {
      const value = $("rules").value;
      const object = parsed() || {};
      if (value === "" && object.rules === undefined) return;
      edit(value === "" ? { op: "remove", path: ["rules"] } : { op: "set", path: ["rules"], value: JSON.stringify(value) });
    };
    $("addPolygon").onclick = () => {
      const object = parsed() || {};
      const count = Array.isArray(object.polygons) ? object.polygons.length : 0;
      const w = view ? view.width : 32, h = view ? view.height : 32;
      const polygon = { value: 1, vertices: [[Math.round(w / 4), Math.round(h / 4), 1], [Math.round(w / 2), Math.round(3 * h / 4), 1], [Math.round(3 * w / 4), Math.round(h / 4), 1]] };
      edit({ op: "insert", path: ["polygons", count], value: JSON.stringify(polygon) });
    };
    $("share").onclick = () => {
      history.replaceState(null, "", "#" + z.fragment_of(scene));
      $("shared").textContent = words.shared;
    };
    window.addEventListener("hashchange", () => { const text = sceneFromAddress(); if (text !== null) setScene(text); });
    $("back").onclick = () => { at = Math.max(0, at - 1); renderStop(); };
    $("next").onclick = () => { at = Math.min(view.stops.length - 1, at + 1); renderStop(); };
    $("quiz").onchange = renderStop;
    $("quizKind").onchange = renderStop;
    $("afterSelect").onchange = renderAfter;
    $("checkAnswer").onclick = checkAnswer;
    $("answerGrid").onclick = answerGrid;
    $("figureBox").addEventListener("toggle", renderFigure);
    // A click on a cell asks for its history (one listener for every cell).
    $("grid").addEventListener("click", (e) => {
      const cell = e.target.closest("rect.cell");
      if (cell) explainPixel(Number(cell.dataset.x), Number(cell.dataset.y));
    });
  }

  async function start() {
    await wasm_bindgen({ module_or_path: window.ZSIM_WASM || "zsim_web_bg.wasm" });
    z = wasm_bindgen;
    wire();
    const asked = new URLSearchParams(location.search).get("lang");
    const preferred = asked ? [asked] : window.ZSIM_LANG ? [window.ZSIM_LANG] : (navigator.languages && navigator.languages.length ? navigator.languages : [navigator.language || "en"]);
    scene = sceneFromAddress() || window.ZSIM_SCENE || z.book_scene();
    setLanguage(z.choose_language(preferred.join("\n")));
  }
  start();
})();
