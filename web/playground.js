// The playground's page: it shows what zsim's library (compiled to
// WebAssembly, `wasm_bindgen` below) says of the scene, and asks the library
// for every verdict. It holds no rule of its own: editing the scene, the
// buffers, the stepper and its quiz (one library object, `WebLesson`: what
// may be shown, what is asked, each verdict and the score), a homework's
// check and the words all come from the module. The address is the state:
// `#scene=…&polygon=P&scanline=Y&quiz=K&pixel=X,Y`.
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
  let z, lang = "en", words = {}, scene = "", view = null, drag = null;
  // The stepper and its quiz (the library's object) and what it last said it shows.
  let lesson = null, lessonState = null, lessonScene = null, addressTimer = null;
  // The pixel whose history is shown, and the keyboard's pixel cursor on the raster.
  let picked = null, cursor = null;
  // The address the page shows: written by the page or applied from a link.
  let applied = null;
  // A class's student and their variant code, from their link (`&student=…&variant=…`): the
  // homework is saved as the file they hand in.
  let student = "", variant = "";
  // The raster's width on the screen, kept by a ResizeObserver.
  let gridWidth = 640;
  // Framebuffer values as colours: the library's (the figure's), 0 white.
  const colour = (value) => value === 0 || !view ? "#ffffff" : view.palette[(value - 1) % view.palette.length];

  function call(name, ...args) { return JSON.parse(z[name](lang, ...args)); }

  function setLanguage(code) {
    lang = code;
    words = JSON.parse(z.words(lang));
    if (student) showStudent();
    document.documentElement.lang = lang;
    $("lang").value = lang;
    document.title = words.title;
    $("title").textContent = words.title;
    $("intro").textContent = words.intro;
    document.querySelectorAll("[data-word]").forEach((e) => { e.textContent = words[e.dataset.word]; });
    document.querySelectorAll("[data-aria-word]").forEach((e) => { e.setAttribute("aria-label", words[e.dataset.ariaWord]); });
    renderExamples();
    if (lesson) lesson.set_language(lang);
    document.querySelectorAll(".frameName").forEach((e) => { e.textContent = words.frameName; });
    document.querySelectorAll(".depthName").forEach((e) => { e.textContent = words.depthName; });
    setScene(scene, true);
  }

  // The scene's text is the one source: every control edits it through the library. It is read
  // once, by the lesson, and its view, buffers, figure and histories are asked of that reading.
  function setScene(text, keepEditor) {
    scene = text;
    if (!keepEditor || $("json").value !== text) $("json").value = text;
    let next;
    if (!lesson || lessonScene !== text) {
      next = newLesson(lessonState && lessonState.at);
    } else {
      // The same scene in another language: the lesson goes on where it was, score and all.
      next = JSON.parse(lesson.view());
      lessonState = JSON.parse(lesson.state());
    }
    $("json").classList.toggle("invalid", !next.ok);
    $("json").setAttribute("aria-invalid", String(!next.ok));
    $("error").textContent = next.ok ? "" : next.error;
    markError(next.ok ? null : next.at);
    // What is drawn is the last scene that could be read: dimmed while the text is not one.
    $("view").classList.toggle("stale", !next.ok);
    if (!next.ok) {
      // The polygon at fault marked in its own table, where the page shows the table.
      if (next.at && next.at.polygon !== undefined && view && view.byPolygon) {
        renderPolygons(parsed() || {});
        markError(next.at);
      }
      view = null;
      ["framebuffer", "zbuffer", "afterFrame", "afterDepth", "explain"].forEach((id) => { $(id).textContent = ""; });
      return;
    }
    view = next;
    render();
    // The address follows a moment later: a drag's many edits write it once.
    clearTimeout(addressTimer);
    addressTimer = setTimeout(() => writeAddress(false), 150);
  }

  // Where an error is, marked where the student typed it: a polygon's table, a setting's box,
  // or the JSON's line (said under the error); `null` clears every mark.
  function markError(at) {
    document.querySelectorAll(".invalid").forEach((e) => { if (e.id !== "json") e.classList.remove("invalid"); });
    document.querySelectorAll("[aria-invalid='true']").forEach((e) => { if (e.id !== "json") e.removeAttribute("aria-invalid"); });
    if (!at) return;
    const settings = { width: "width", height: "height", frame_bits: "frameBits", depth_bits: "depthBits", depth_test: "depthTest" };
    const marked = at.polygon !== undefined ? document.querySelectorAll(`#polygons table`)[at.polygon]
      : at.key !== undefined ? $(settings[at.key]) : null;
    if (marked) {
      marked.classList.add("invalid");
      (marked.matches("input, select") ? [marked] : marked.querySelectorAll("input")).forEach((e) => e.setAttribute("aria-invalid", "true"));
    }
    if (at.line !== undefined) {
      const line = el("code", at.said, "errorLine");
      $("error").append(el("br"), line);
    }
  }

  // The quiz asked: "depth", "frame", "coverage", or "" for none.
  function quizMode() { return $("quiz").checked ? $("quizKind").value : ""; }

  // A new lesson of the scene (the quiz as chosen) at `place` ({polygon, row}), or at its first
  // stop; answers with the scene's view, or its error ({ok: false, error, at}).
  function newLesson(place) {
    if (lesson) lesson.free();
    lesson = null;
    lessonState = null;
    lessonScene = null;
    try {
      lesson = new z.WebLesson(lang, scene, quizMode(), place ? place.polygon : 0, place ? place.row : 0);
    } catch (error) {
      return JSON.parse(error);
    }
    lessonScene = scene;
    lessonState = JSON.parse(lesson.state());
    $("said").textContent = "";
    return JSON.parse(lesson.view());
  }

  // Sends the lesson a command ({key}, {go: [polygon, row]}, {answer}) and shows what it said; a
  // move is a new entry of the browser's history unless `fromAddress` (Back, forward or an edited
  // address, which the address already says).
  function act(command, fromAddress) {
    if (!lesson) return;
    const result = JSON.parse(lesson.act(JSON.stringify(command)));
    if (!result.ok) return;
    if (result.kind === "quit") {
      // The quiz ended: its summary stays, and the stepper goes on where it was, without a quiz.
      const at = result.state.at;
      $("quiz").checked = false;
      view = newLesson(at);
      if (view.ok) render();
      writeAddress(false);
      $("said").textContent = result.summary;
      $("said").className = result.kind;
      return;
    }
    lessonState = result.state;
    $("said").textContent = result.said;
    $("said").className = result.kind;
    renderLesson();
    if (result.kind === "moved") writeAddress(!fromAddress);
    // A move the address asked for and the lesson refused: the address says where the lesson still
    // is, as a new entry, so that Back goes back again once the questions are answered.
    else if (fromAddress) writeAddress(true);
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
    // The settings as the library draws the scene (a preset's and the defaults resolved).
    for (const id of ["width", "height", "frameBits", "depthBits"]) {
      if (document.activeElement !== $(id)) $(id).value = view.settings[id];
    }
    $("depthTest").value = view.settings.depthTest;
    $("rules").value = typeof object.rules === "string" ? object.rules : "";
    renderPolygons(object);
    renderGrid();
    $("notes").replaceChildren(...view.notes.map((n) => el("p", n, "help")));
    renderLesson();
    renderHomeworkChoices();
    renderFigure();
    // The pixel's history follows every edit.
    if (picked) explainPixel(picked.x, picked.y);
  }

  // The figure, drawn by the library when its section is open.
  function renderFigure() {
    if (!$("figureBox").open || !lesson) return;
    if (lessonState && lessonState.buffersHidden) { $("figure").replaceChildren(el("p", lessonState.buffersHidden, "help")); return; }
    const figure = JSON.parse(lesson.figure());
    if (figure.ok) $("figure").innerHTML = figure.svg;
    else $("figure").replaceChildren(el("p", figure.error, "help"));
  }

  function renderPolygons(object) {
    const box = $("polygons");
    if (box.contains(document.activeElement)) return;
    // The table only where the library shows the scene polygon by polygon (a few dozen polygons).
    const polygons = Array.isArray(object.polygons) && view.byPolygon ? object.polygons : [];
    // The same tables as before (polygons, vertices and language alike): only their values change.
    const shape = lang + "|" + polygons.map((p) => (Array.isArray(p.vertices) ? p.vertices.map((v) => (Array.isArray(v) ? v.length : 0)).join(".") : "")).join(",");
    if (box.dataset.shape === shape) {
      box.querySelectorAll("input.value").forEach((input) => {
        const value = polygons[input.dataset.p].value;
        input.value = value === undefined ? "" : value;
      });
      box.querySelectorAll("input.coord").forEach((input) => {
        input.value = polygons[input.dataset.p].vertices[input.dataset.v][input.dataset.c];
      });
      return;
    }
    box.dataset.shape = shape;
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
      value.setAttribute("aria-label", `${words.polygon} ${p + 1}: ${words.value}`);
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
      add.onclick = () => edit({ op: "add-vertex", polygon: p + 1 });
      const remove = el("button", words.removeVertex, "removeVertex");
      remove.onclick = () => edit({ op: "remove-vertex", polygon: p + 1 });
      const drop = el("button", words.removePolygon, "removePolygon");
      drop.onclick = () => edit({ op: "remove", path: ["polygons", p] });
      cell.append(add, remove, drop);
      buttons.appendChild(cell);
      table.appendChild(buttons);
      box.appendChild(table);
    });
  }

  // The framebuffer the raster shows, rows top first, each with its pixel y: in the quiz the
  // lesson's (what may be shown so far), otherwise the final one.
  function shownFrame() {
    if (quizMode() && lessonState && lessonState.cells) return lessonState.cells;
    return view.rows;
  }

  // The raster: each cell filled by the framebuffer, outlines, vertices to drag, and the lesson's scanline.
  function renderGrid() {
    const grid = $("grid"), w = view.width, h = view.height;
    grid.setAttribute("viewBox", `0 0 ${w} ${h}`);
    grid.setAttribute("aria-label", words.gridLabel);
    const rows = shownFrame();
    // The cells as one piece of markup (numbers only), made once for a raster's size; an edit
    // recolours them.
    const size = `${w}x${h}:${rows.length}`;
    if (grid.dataset.size !== size) {
      let cells = "";
      rows.forEach((row, i) => row.cells.forEach((value, x) => {
        cells += `<rect x="${x}" y="${i}" width="1" height="1" class="cell" data-x="${x}" data-y="${row.y}"/>`;
      }));
      grid.innerHTML = cells;
      grid.dataset.size = size;
      grid.dataset.shape = "";
    }
    colourCells(rows);
    const draggable = view.draggable;
    // A handle at least 24 px across on any screen (26, for rounding), from the raster's width as
    // last laid out (reading it now would lay the whole page out again).
    const pixelsPerUnit = Math.max(1, gridWidth) / w;
    const radius = Math.max(0.35, w / 90, 13 / pixelsPerUnit);
    // The outlines and handles: moved in place while the polygons keep their vertices' count.
    const shape = `${draggable}:` + view.polygons.map((p) => p.points.length).join(",");
    if (grid.dataset.shape === shape) {
      const outlines = grid.querySelectorAll(":scope > polygon.outline"), handles = grid.querySelectorAll(":scope > circle.vertex");
      let k = 0;
      view.polygons.forEach((polygon, p) => {
        outlines[p].setAttribute("points", polygon.points.map(([x, y]) => `${x},${y}`).join(" "));
        if (!draggable) return;
        polygon.points.forEach(([x, y]) => {
          const handle = handles[k++];
          handle.setAttribute("cx", x);
          handle.setAttribute("cy", y);
          handle.setAttribute("r", radius);
          handle.setAttribute("fill", colour(polygon.value));
        });
      });
      renderLegend(rows);
      return;
    }
    grid.querySelectorAll(":scope > :not(.cell)").forEach((e) => e.remove());
    grid.dataset.shape = shape;
    view.polygons.forEach((polygon, p) => {
      const points = polygon.points.map(([x, y]) => `${x},${y}`).join(" ");
      grid.appendChild(svg("polygon", { points, class: "outline", stroke: "#333" }));
    });
    if (draggable) {
      view.polygons.forEach((polygon, p) => {
        polygon.points.forEach(([x, y], v) => {
          const handle = svg("circle", { cx: x, cy: y, r: radius, class: "vertex", fill: colour(polygon.value) });
          handle.dataset.p = p;
          handle.dataset.v = v;
          handle.addEventListener("pointerdown", (e) => {
            e.preventDefault();
            handle.setPointerCapture(e.pointerId);
            drag = { polygon: polygon.number, vertex: v + 1, last: null };
          });
          grid.appendChild(handle);
        });
      });
    }
    renderLegend(rows);
  }

  function colourCells(rows) {
    const cells = $("grid").children, w = view.width;
    rows.forEach((row, i) => row.cells.forEach((value, x) => {
      const fill = colour(value), cell = cells[i * w + x];
      if (cell && cell.getAttribute("fill") !== fill) cell.setAttribute("fill", fill);
    }));
  }

  // Which colour is which value: each value the raster shows.
  function renderLegend(rows) {
    const values = [...new Set(rows.flatMap((row) => row.cells))].sort((a, b) => a - b);
    const items = values.map((v) => {
      const item = el("span", view.legend[v], "legendItem");
      const swatch = el("span", undefined, "swatch");
      swatch.style.background = colour(v);
      item.prepend(swatch);
      return item;
    });
    $("legend").replaceChildren(...(items.length ? [el("span", words.legend + " "), ...items] : []));
  }

  // The lesson's scanline on the raster: the line y + ½, its crossings and covered cells once
  // they may be shown, the pixel asked, and the keyboard's cursor.
  function drawLesson() {
    const grid = $("grid");
    if (!view) return;
    grid.querySelectorAll(".lesson").forEach((e) => e.remove());
    if (quizMode() && lessonState && lessonState.cells) colourCells(lessonState.cells);
    const s = lessonState, g = svg("g", { class: "lesson" });
    if (s && s.at) {
      const y = s.at.line;
      g.appendChild(svg("line", { x1: 0, y1: y, x2: view.width, y2: y, class: "scanline" }));
      s.columns.forEach((x) => g.appendChild(svg("rect", { x, y: y - 0.5, width: 1, height: 1, class: "covered" })));
      s.crossingsX.forEach((x) => g.appendChild(svg("circle", { cx: x, cy: y, r: 0.22, class: "crossing" })));
      if (s.askedX !== null && s.askedX !== undefined) {
        g.appendChild(svg("rect", { x: s.askedX, y: y - 0.5, width: 1, height: 1, class: "asked" }));
      }
    }
    if (cursor) g.appendChild(svg("rect", { x: cursor.x, y: cursor.row, width: 1, height: 1, class: "cursor" }));
    grid.appendChild(g);
  }

  // A vertex dragged: the pointer in the raster's own units, which the library snaps and turns
  // into the scene's coordinates.
  document.addEventListener("pointermove", (e) => {
    if (!drag || !view) return;
    const point = new DOMPoint(e.clientX, e.clientY).matrixTransform($("grid").getScreenCTM().inverse());
    const result = call("edit", scene, JSON.stringify({ op: "drag", polygon: drag.polygon, vertex: drag.vertex, to: [point.x, point.y], snap: $("snap").value }));
    if (!result.ok) { $("error").textContent = result.error; return; }
    if (result.scene !== scene) setScene(result.scene);
  });
  document.addEventListener("pointerup", () => { drag = null; });

  // A pixel's history; the pixel as the address or a click gives it, which the library reads
  // (one off the raster is said, not drawn).
  function explainPixel(x, y) {
    const result = lesson ? JSON.parse(lesson.explain(String(x), String(y))) : { ok: false, error: "" };
    $("explain").textContent = result.ok ? result.text : result.error;
    const grid = $("grid");
    grid.querySelectorAll(".picked").forEach((e) => e.remove());
    picked = result.ok || result.hidden ? { x: Number(x), y: Number(y) } : null;
    const row = picked ? view.rows.findIndex((r) => r.y === picked.y) : -1;
    if (row >= 0) grid.appendChild(svg("rect", { x: picked.x, y: row, width: 1, height: 1, class: "picked" }));
  }

  // The buffers after the chosen polygon, asked of the library when shown (not one set per polygon on every edit).
  function renderAfter() {
    const select = $("afterSelect");
    const shown = view.byPolygon ? view.polygons : [];
    const chosen = shown.some((p) => String(p.number) === select.value) ? select.value : shown.length ? String(shown[0].number) : "";
    select.replaceChildren(...shown.map((p) => { const o = el("option", p.label); o.value = p.number; return o; }));
    select.value = chosen;
    const after = chosen && lesson ? JSON.parse(lesson.after(Number(chosen))) : { ok: false };
    // While a question is open the library's words stand in for what would answer it.
    const hidden = lessonState && lessonState.buffersHidden;
    $("afterHeading").textContent = after.ok && !hidden ? `${after.heading} — ${after.counts}` : "";
    $("afterFrame").textContent = hidden || (after.ok ? after.frame : "");
    $("afterDepth").textContent = hidden || (after.ok ? after.depth : "");
  }

  // The final buffers and the buffers after each polygon, or the words that stand in for them.
  function renderBuffers() {
    const hidden = lessonState && lessonState.buffersHidden;
    $("framebuffer").textContent = hidden || view.framebuffer;
    $("zbuffer").textContent = hidden || view.zbuffer;
    renderAfter();
    if ($("figureBox").open) renderFigure();
    if (picked) explainPixel(picked.x, picked.y);
  }

  // What the lesson shows now, already cut by the library to what may be shown.
  function renderLesson() {
    const s = lessonState, box = $("stop");
    const asking = Boolean(s && s.prompt);
    $("answerForm").hidden = !asking;
    $("skip").hidden = !quizMode();
    $("endQuiz").hidden = !quizMode();
    $("score").textContent = s && s.score ? s.score : "";
    if (view && view.ok) renderBuffers();
    drawLesson();
    if (!s || !s.at) {
      box.replaceChildren(el("p", s && s.end ? s.end : ""));
      $("status").textContent = "";
      return;
    }
    $("status").textContent = s.scanline;
    if (asking) $("prompt").textContent = s.prompt;
    box.replaceChildren(el("h3", s.heading), el("p", s.slope));
    if (s.crossings) box.appendChild(el("p", s.crossings));
    (s.spanDepths.length ? s.spanDepths : s.spans).forEach((t) => box.appendChild(el("p", t)));
    const table = el("table");
    table.id = "pixels";
    table.appendChild(el("caption", s.scanline));
    const head = el("tr");
    ["x", "z", words.stored, words.depthName, words.frameName, words.why].forEach((t) => {
      const th = el("th", t);
      th.scope = "col";
      head.appendChild(th);
    });
    table.appendChild(head);
    s.rows.forEach((r) => {
      const tr = el("tr", undefined, r.written ? "right" : "wrong");
      [String(r.x), r.z, r.stored, r.after, String(r.frame), r.test].forEach((t) => tr.appendChild(el("td", t)));
      table.appendChild(tr);
    });
    if (s.hidden) {
      const tr = el("tr"), td = el("td", s.hiddenSaid, "help");
      td.colSpan = 6;
      tr.appendChild(td);
      table.appendChild(tr);
    }
    if (s.rows.length || s.hidden) box.appendChild(table);
    s.notes.forEach((n) => box.appendChild(el("p", n, "help")));
    box.appendChild(matrix(s.frame, words.frameName));
    box.appendChild(matrix(s.depth, words.depthName));
  }

  // A buffer as the lesson prints it (rows and columns numbered), the scanline's row (`▶`) marked.
  function matrix(text, name) {
    const figure = el("figure", undefined, "matrix");
    figure.appendChild(el("figcaption", name));
    const pre = el("pre");
    // Scrolled sideways on a narrow screen, so reachable by keyboard.
    pre.tabIndex = 0;
    (text || "").split("\n").forEach((line) => {
      pre.appendChild(line.startsWith("▶") ? el("mark", line) : document.createTextNode(line));
      pre.appendChild(document.createTextNode("\n"));
    });
    figure.appendChild(pre);
    return figure;
  }

  function renderHomeworkChoices() {
    const select = $("hwAfter"), chosen = select.value, choices = view.checkable;
    select.replaceChildren(...choices.map((c) => { const o = el("option", c.label); o.value = c.number; return o; }));
    select.value = choices.some((c) => String(c.number) === chosen) ? chosen : choices.length ? choices[choices.length - 1].number : "";
    // A grid of inputs only for a raster the page shows cell by cell (the notes say why not).
    $("answerGrid").disabled = !view.cellByCell;
    if (!view.cellByCell) $("answerCells").replaceChildren();
  }

  // A grid of cells to type an answer into, top row first, starting from the cleared buffer;
  // what is typed is written into the answer's text as the book prints a matrix.
  function answerGrid() {
    const box = $("answerCells");
    if (box.firstChild) { box.replaceChildren(); return; }
    const buffer = $("hwBuffer").value, start = view.cleared[buffer];
    const lines = $("answer").value.trim().split("\n").map((l) => l.trim().split(/\s+/));
    const fits = lines.length === view.rows.length && lines.every((l) => l.length === view.width);
    const table = el("table");
    view.rows.forEach((row, i) => {
      const tr = el("tr");
      for (let x = 0; x < view.width; x++) {
        const input = el("input");
        input.value = fits ? lines[i][x] : start === null ? "" : String(start);
        Object.assign(input.dataset, { x, y: row.y });
        input.setAttribute("aria-label", `(${x}, ${row.y})`);
        const td = el("td");
        td.appendChild(input);
        tr.appendChild(td);
      }
      table.appendChild(tr);
    });
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
    const score = el("p", result.score); score.id = "hwScore"; box.appendChild(score);
  }

  // The homework as the file the student hands in (`IDENTITY.frame.txt`, the variant's code in its
  // first line), made by the library and downloaded.
  function saveAnswer() {
    const result = call("answer_file", scene, $("hwBuffer").value, $("answer").value, student, variant);
    if (!result.ok) { $("verdict").replaceChildren(el("p", result.error, "again")); return; }
    const link = el("a");
    link.href = URL.createObjectURL(new Blob([result.text], { type: "text/plain" }));
    link.download = result.name;
    document.body.appendChild(link);
    link.click();
    link.remove();
  }

  // The student and variant of a class's link, shown above the homework.
  function showStudent() {
    const shown = student !== "";
    $("variantLine").hidden = !shown;
    $("saveAnswer").hidden = !shown;
    if (shown) $("variantLine").textContent = z.variant_line(lang, student, variant);
  }

  // The address's parts: `scene`, `polygon`, `scanline`, `quiz`, `pixel`.
  function addressParts() {
    const parts = {};
    location.hash.replace(/^#/, "").split("&").forEach((part) => {
      const i = part.indexOf("=");
      if (i > 0) parts[part.slice(0, i)] = part.slice(i + 1);
    });
    return parts;
  }

  // The address follows the page: the scene, the stepper's stop, the quiz and the pixel.
  function writeAddress(push) {
    if (!z) return;
    let hash = "#" + z.fragment_of(scene);
    const s = lessonState;
    if (s && s.at) hash += `&polygon=${s.at.polygon}&scanline=${s.at.row}`;
    if (quizMode()) hash += `&quiz=${quizMode()}`;
    if (picked) hash += `&pixel=${picked.x},${picked.y}`;
    if (student) hash += `&student=${encodeURIComponent(student)}&variant=${encodeURIComponent(variant)}`;
    if (location.hash !== hash) {
      try { history[push ? "pushState" : "replaceState"](null, "", hash); } catch (e) { /* a page from disk may refuse */ }
    }
    applied = location.hash;
    $("link").value = location.href;
  }

  // The page follows the address (opened, edited, back or forward): a scene that cannot be read
  // is said on the page, never replaced silently.
  function readAddress() {
    const parts = addressParts();
    let text = null;
    if (parts.scene !== undefined) {
      const result = call("scene_of_fragment", "scene=" + parts.scene);
      if (result.ok) text = result.scene;
      else $("error").textContent = result.error;
    }
    if (parts.quiz !== undefined) {
      const kind = words.quizKinds.includes(parts.quiz) ? parts.quiz : "";
      $("quiz").checked = kind !== "";
      if (kind) $("quizKind").value = kind;
    }
    const place = parts.polygon !== undefined && parts.scanline !== undefined
      ? { polygon: Number(parts.polygon) || 0, row: Number(parts.scanline) || 0 } : null;
    const pixel = parts.pixel && /^\d+,\d+$/.test(parts.pixel) ? parts.pixel.split(",") : null;
    if (parts.student !== undefined) {
      try { student = decodeURIComponent(parts.student); variant = decodeURIComponent(parts.variant || ""); } catch (e) { student = ""; }
      if (z) showStudent();
    }
    return { text, place, pixel, broken: parts.scene !== undefined && text === null };
  }

  function applyAddress() {
    // A followed link fires popstate and hashchange alike: the address is applied once.
    if (location.hash === applied) return;
    applied = location.hash;
    const mode = quizMode();
    const { text, place, pixel, broken } = readAddress();
    if (broken) return;
    if (text !== null && text !== scene) {
      lessonState = place ? { at: place } : null;
      setScene(text);
    } else if (lesson && view && view.ok && quizMode() === mode) {
      // The same scene and quiz: Back, forward or an edited address move within the lesson, score
      // and all, refused as a key is while questions are open; the address then says where it is.
      if (place) act({ go: [place.polygon, place.row] }, true);
      writeAddress(false);
    } else {
      view = newLesson(place);
      if (view.ok) render();
    }
    if (pixel && view && view.ok) explainPixel(pixel[0], pixel[1]);
  }

  function renderExamples() {
    if (!z) return;
    const select = $("examples"), chosen = select.value;
    select.replaceChildren(...JSON.parse(z.examples()).map((e, i) => {
      const o = el("option", words[e.word]);
      o.value = i;
      return o;
    }));
    select.value = chosen || "0";
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
    $("addPolygon").onclick = () => edit({ op: "add-polygon" });
    $("examples").onchange = () => {
      lessonState = null;
      picked = null;
      setScene(JSON.parse(z.examples())[Number($("examples").value)].scene);
    };
    $("reset").onclick = () => {
      lessonState = null;
      picked = null;
      $("quiz").checked = false;
      $("examples").value = "0";
      $("explain").textContent = "";
      setScene(z.book_scene());
    };
    $("share").onclick = async () => {
      writeAddress(false);
      const link = location.href;
      $("link").value = link;
      try {
        await navigator.clipboard.writeText(link);
        $("shared").textContent = words.copied;
      } catch (e) {
        $("link").select();
        const copied = document.execCommand && document.execCommand("copy");
        $("shared").textContent = copied ? words.copied : words.shared;
      }
    };
    window.addEventListener("popstate", applyAddress);
    window.addEventListener("hashchange", applyAddress);
    for (const [id, key] of [["back", "b"], ["next", "n"], ["prevPolygon", "P"], ["nextPolygon", "p"], ["skip", "s"], ["endQuiz", "q"]]) {
      $(id).onclick = () => act({ key });
    }
    const requiz = () => { view = newLesson(lessonState && lessonState.at); render(); writeAddress(false); };
    $("quiz").onchange = requiz;
    $("quizKind").onchange = () => { if (quizMode()) requiz(); };
    // Enter checks: the form's submit.
    $("answerForm").addEventListener("submit", (e) => {
      e.preventDefault();
      const typed = $("quizAnswer").value;
      if (typed.trim() === "") return;
      $("quizAnswer").value = "";
      act({ answer: typed });
      $("quizAnswer").focus();
    });
    // The keys as the buttons say, where no field takes what is typed.
    document.addEventListener("keydown", (e) => {
      if (e.ctrlKey || e.metaKey || e.altKey || !lesson) return;
      if (e.target.closest && e.target.closest("input, textarea, select")) return;
      if (words.keys.some((k) => k.key === e.key)) {
        e.preventDefault();
        act({ key: e.key });
      }
    });
    // The raster by keyboard: arrows move a pixel cursor, Enter explains the pixel.
    $("grid").addEventListener("keydown", (e) => {
      if (!view) return;
      // The cursor moves over the page's rows (top first); the pixel it is on is the row's y.
      const moves = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
      if (moves[e.key] && view.rows.length) {
        e.preventDefault();
        const at = cursor || { x: 0, row: 0 };
        cursor = {
          x: Math.min(view.width - 1, Math.max(0, at.x + moves[e.key][0])),
          row: Math.min(view.rows.length - 1, Math.max(0, at.row + moves[e.key][1])),
        };
        drawLesson();
      } else if (e.key === "Enter" && cursor) {
        e.preventDefault();
        explainPixel(cursor.x, view.rows[cursor.row].y);
        writeAddress(false);
      }
    });
    new ResizeObserver((entries) => {
      const width = entries[0].contentRect.width;
      if (width && Math.abs(width - gridWidth) > 1) {
        gridWidth = width;
        if (view) renderGrid();
      }
    }).observe($("grid"));
    $("afterSelect").onchange = renderAfter;
    $("checkAnswer").onclick = checkAnswer;
    $("saveAnswer").onclick = saveAnswer;
    $("answerGrid").onclick = answerGrid;
    $("figureBox").addEventListener("toggle", renderFigure);
    // A click on a cell asks for its history (one listener for every cell).
    $("grid").addEventListener("click", (e) => {
      const cell = e.target.closest("rect.cell");
      if (cell) { explainPixel(Number(cell.dataset.x), Number(cell.dataset.y)); writeAddress(false); }
    });
  }

  async function start() {
    // The module's bytes come with the page as a script, so that a site opened from disk works too.
    const base64 = window.ZSIM_WASM_BASE64;
    const bytes = window.ZSIM_WASM || (base64 && Uint8Array.from(atob(base64), (c) => c.charCodeAt(0)));
    await wasm_bindgen({ module_or_path: bytes || "zsim_web_bg.wasm" });
    z = wasm_bindgen;
    wire();
    const asked = new URLSearchParams(location.search).get("lang");
    const preferred = asked ? [asked] : window.ZSIM_LANG ? [window.ZSIM_LANG] : (navigator.languages && navigator.languages.length ? navigator.languages : [navigator.language || "en"]);
    lang = z.choose_language(preferred.join("\n"));
    words = JSON.parse(z.words(lang));
    // A page written with its quiz on (`zsim step --html --quiz`), unless the address says otherwise.
    if (window.ZSIM_QUIZ) { $("quiz").checked = true; $("quizKind").value = window.ZSIM_QUIZ; }
    const { text, place, pixel } = readAddress();
    applied = location.hash;
    lessonState = place ? { at: place } : null;
    scene = text !== null ? text : window.ZSIM_SCENE || z.book_scene();
    const error = $("error").textContent;
    setLanguage(lang);
    // A broken address is said, not replaced silently (the scene shown is the book's).
    if (error) $("error").textContent = error;
    if (pixel) { explainPixel(pixel[0], pixel[1]); writeAddress(false); }
  }
  start();
})();
