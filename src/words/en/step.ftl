# zsim's words in English: stepping and the lesson: the stepper's views and keys, the questions, hints and misconceptions, the page's controls.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

step-slope = along a scanline z steps by −a/c = { $slope }
step-scanline = scanline { $scanline } (row { $row })
step-crossings = crossings: { $list }
step-crossings-none = none
step-span = span { $n }: x_a = { $xa }, z_a = { $za }; x_b = { $xb }, z_b = { $zb }; { $columns }
step-columns = columns { $first } … { $last }
step-no-column = no column
step-col-centre = centre
step-col-step = step
step-col-stored = stored
step-col-test = test
step-col-after = after
step-col-frame = frame
step-start = start
step-written = { $test }: written
step-hidden = { $test }: hidden
step-test-written = { $z } { $op } { $stored }: written
step-test-hidden = { $z } { $op } { $stored }: no, hidden
step-beyond-section = { $op } { $stored }, beyond the section
step-outside-range = { $z }: outside the depth range, discarded
step-tie = tie at x = { $x }: { $text }
step-frame-after = framebuffer after this scanline (rows { $low } … { $high }):
step-depth-after = z-buffer after this scanline (rows { $low } … { $high }):
step-end = end of the scene: no more scanlines (b back, q quit)
step-first = already at the first scanline
step-outside-raster = row { $row } is outside the raster (rows 0 … { $last })
step-not-reach = { $polygon } does not reach the scanline { $scanline }
step-unknown = unknown command "{ $text }"; { $help }
step-prompt = { "zsim step> " }
title-stepper = zsim step ·{ $heading } · { $view }{ $score } · ? keys
score-short = { " · quiz " }{ $right }/{ $asked }
key-does-nothing = that key does nothing here: ? shows the keys
no-later-polygon = no later polygon covers a pixel
no-earlier-polygon = no earlier polygon covers a pixel
go-to-row-prompt = go to scanline of row: { $text }▏ (Enter to go, Esc to cancel)
keys-summary = n/→ next · b/← back · p/P polygon · g go · f/z buffer · m pixel steps · q quit
no-scanline = no scanline
columns-shown = x { $first } … { $last } of 0 … { $max }
pixel-table-heading = x { $z } test → stored (frame)
keys-pixel-by-pixel = m: pixel by pixel, with the reasons
pixel-centre-depth = ({ $x }, { $y }): centre x = { $centre }, z = { $z }{ $steps }
keys-heading = { " keys " }
keys-help =
    g                  go to the scanline of a row
    f / z              show the framebuffer / z-buffer
    m                  step by pixel / by scanline
    PgUp PgDn < >      scroll the raster
    { "[ ]" }                scroll the table
    ?                  these keys (any key closes)

    yellow: the span's covered pixels
    cyan: this polygon's earlier writes
quiz-mistakes = your mistakes:
quiz-coverage-hint = type the covered columns as first-last (several runs apart: 3-5 9-12), or - for none
quiz-coverage-why = the spans are { $spans }; a column is covered when its centre x + 1/2 lies within one
quiz-coverage-mistake = row { $row } of { $polygon }: you said columns { $said }, right { $right }: { $why }
quiz-depth-hint = type the value the z-buffer will hold, or - for not written (q stops the quiz)
quiz-not-an-answer = "{ $text }" is not an answer: { $hint }
quiz-does-not-fit = { $text } does not fit this z-buffer: its cells hold whole levels 0 … { $max }; type again
quiz-keeps = - (it keeps { $value })
quiz-depth-mistake = ({ $x }, { $y }) of { $polygon }: you said { $said }, right { $right }: { $reason }
command-back = ◀ Back (b)
command-next = Next ▶ (n)
command-previous-polygon = ◀◀ Polygon (P)
command-next-polygon = Polygon ▶▶ (p)
command-show-frame = Framebuffer (f)
command-show-depth = Z-buffer (z)
quiz-label = quiz
column-stored = stored
column-depth-after = z-buffer after
column-why = why
keeps-value = – (keeps { $value })
command-check-answers = Check my answers
# What the stepper passes over on its way to the next covered scanline.
step-skip-fate = { $polygon }: { $why }
step-skip-no-scanline = { $polygon }: reaches no scanline of the raster
step-skip-no-centre = { $polygon }, scanline { $scanline }: no pixel centre covered
step-skip-no-centre-no-crossings = { $polygon }, scanline { $scanline }: no pixel centre covered (no crossings)
step-antialias-note = note: this scene asks for { $k }×{ $k } supersampling; step shows each pixel centre's plain coverage and depth, before supersampling and averaging (`zsim run` shows the averaged buffers, `zsim explain --pixel X,Y` each pixel's samples)
step-fixed = in fixed:{ $bits } arithmetic the vertices are first snapped to multiples of 1/{ $unit }, then these exact rules run on the snapped polygon (`zsim run --arith fixed:{ $bits }` shows the result)
step-float-exact = exact { $z }
step-float-not-exact = exact arithmetic does not cover it
step-float-edges = edge functions at the centres of the bounding box's columns { $first } … { $last }
step-float-no-crossings = crossings none
step-float-crossings = crossings { $crossings }
step-float-heading = in { $arith } arithmetic: { $found }
step-float-no-pixel = no pixel covered
step-float-missed = it misses the exact centres x = { $columns }
pixel-order-ray = ray casting (left-open/right-closed vertex rule; on the boundary counts)
pixel-order-arc = the arc-length method (quadrant table; on the boundary counts)
pixel-order-heading = order: for every pixel, for every polygon, one depth variable (the Chinese course notes); inside test: { $test }
pixel-order-header-polygon = polygon
pixel-order-header-why = why the inside tests differ
pixel-order-on-boundary = the centre lies exactly on the boundary: arc counts it inside, while the half-interval rule leaves out top edges and vertices (an edge counts only at its lower end)
pixel-order-winding = the polygon winds { $winding } times around the centre: arc counts a non-zero winding as inside, the paired crossings (even-odd) as outside
pixel-order-disagree = { $count } centre(s) where arc and the scanline rule disagree:
misconception-truncated = depths truncated (rounded down) instead of rounded to the nearest integer
misconception-half-down = halves rounded down instead of up (10.5 stored as 10)
misconception-rounded-compared = the rounded depth compared with the stored one instead of the exact z
misconception-no-saturation = depths beyond the z-buffer's range wrapped around instead of saturating
misconception-not-strict = an equal depth let through (≥ instead of >)
misconception-reversed = the depth test reversed (smaller z taken as nearer)
misconception-last-only = only the last polygon drawn
misconception-one-early = the answer for one polygon earlier
misconception-bottom-first = the rows written bottom row first
misconception-corners = pixels sampled at their corners instead of their centres
misconception-cell-rule = columns taken from the cells the span's ends fall in instead of the centres inside the span
quiz-frame-hint = type the value the framebuffer will hold, or - for not written (q stops the quiz)
quiz-frame-does-not-fit = { $text } does not fit this framebuffer: its cells hold whole values 0 … { $max }; type again
title-scene-editor = zsim playground: the z-buffer, step by step
intro-scene-editor = Edit the scene; every buffer below is drawn by zsim's own library, compiled for your browser.
field-language = Language
field-width = width
field-height = height
field-frame-bits = framebuffer bits
field-depth-bits = z-buffer bits
field-depth-test = depth test
field-preset = rules
field-preset-none = the book's
field-snap = snap to
field-polygon = polygon
field-value = value
command-add-polygon = + polygon
command-remove-polygon = − polygon
command-add-vertex = + vertex
command-remove-vertex = − vertex
command-copy-link = Copy a link to this scene
link-in-address-bar = The link is in the address bar: copy it from there.
raster-help = Drag a vertex to move it; click a pixel to see its history.
homework-help = Type or paste the matrix as the book prints it, top row first.
command-check = Check
column-after = after
column-your-answer = your answer
no-such-polygon = There is no such polygon in this scene.
lesson-key-next = next scanline
lesson-key-back = back
lesson-key-next-polygon = next polygon
lesson-key-previous-polygon = previous polygon
lesson-key-skip = skip this scanline's questions
lesson-key-quit = quit
lesson-keys = keys: { $keys }, g Y go to scanline Y; an answer is checked with Enter
lesson-hint-misconception = it looks as if { $what }
lesson-hint-is-written = this pixel passes the depth test: compare its exact z with the stored value again
lesson-hint-is-not-written = this pixel does not pass the depth test: compare its exact z with the stored value again
lesson-hint-centre-on-boundary = a centre lies exactly on the polygon's boundary: which rule decides it?
lesson-right = { $said }: right. { $why }
lesson-right-second = { $said }: right at the second try. { $why }
lesson-try-again = { $said }: not yet: { $hint } (one more try)
lesson-hint-neighbouring-row = these are the columns of the row just below or above: this scanline is y = row + ½
lesson-hint-rounded-up = it looks as if you rounded up: the z-buffer stores the nearest integer (halves up)
lesson-hint-half-down = it looks as if you rounded a half down: halves round up
lesson-try-again-plain = { $said }: not yet (one more try)
lesson-revealed = { $said }: wrong again. The answer is { $expected }: { $why }
lesson-skipped = skipped: { $count } questions (counted as not answered)
lesson-score = quiz: { $first } right at the first try, { $second } at the second, { $revealed } shown, { $skipped } skipped, of { $asked ->
    [one] { $asked } question
   *[other] { $asked } questions
  }
lesson-ask-coverage = { $polygon }, scanline { $scanline }: which columns' centres does it cover? (columns as first-last, e.g. 3-7, or - for none)
lesson-ask-depth = pixel ({ $x }, { $y }), stored { $stored }: the z-buffer after? (a value, or - if not written)
lesson-ask-frame = pixel ({ $x }, { $y }), framebuffer { $before }: the framebuffer after? (a value, or - if not written)
lesson-last-try = last try: { $ask }
lesson-questions-open = { $open } open questions on this scanline: answer them first, or s to skip them
lesson-no-such-polygon = there is no polygon { $polygon }: the scene has { $count }
quiz-not-on-recorded-steps = This page shows the steps and asks nothing: the quiz is in the browser playground (the page this command writes when zsim is built with it; see the guide's chapter "The browser playground") and in zsim step --quiz.
command-skip = Skip (s)
command-end-quiz = End the quiz (q)
quiz-kind-label = what the quiz asks
quiz-kind-coverage = covered columns, then the z-buffer
command-reset = Reset
link-copied = The link is copied.
raster-label = The raster: arrow keys move the pixel cursor, Enter explains that pixel
example-rogers = The book's example
example-section = The book's section
example-less = Depth test "less"
example-cull = Back faces culled
example-concave = A concave polygon
legend-heading = Framebuffer values:
legend-value = { $value }
lesson-said-meant = { $said } ({ $meant })
lesson-nothing-to-skip = no question is open here: nothing to skip
step-line-not-text = that line is not text (UTF-8): type it again
lesson-hidden-until-answered = hidden until this scanline's questions are answered or skipped
