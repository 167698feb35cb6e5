# zsim's words in English. Each message is one sentence or phrase; the
# facts arrive as arguments already written as numbers ($z = "43/4 ≈ 10.75").
# Spaces at either end of a message are kept with string literals ({ " and " }).

buffer-frame = framebuffer
buffer-depth = z-buffer
polygon-name = { $named ->
    [yes] polygon { $number } "{ $name }"
   *[no] polygon { $number }
}
# After "after" (a genitive in Russian and Ukrainian).
polygon-after = { $named ->
    [yes] polygon { $number } "{ $name }"
   *[no] polygon { $number }
}
span = { $left } … { $right }
scanline = y = { $y }
list-and = { " and " }
list-semicolon = { "; " }
list-comma = { ", " }

winding-cw = clockwise
winding-ccw = counter-clockwise

stored-whole = { $stored } is stored
stored-rounded-up = { $stored } is stored ({ $value } rounds up to { $stored })
stored-rounded = { $stored } is stored ({ $value } rounds to { $stored })
stored-saturated = { $stored } is stored ({ $value } rounds to { $rounded }, saturated to { $stored })
stored-exact = { $stored } is stored (exactly)

z-w-buffer = { $w } (the w-buffer's eye-space depth; projected z' = { $z })
z-projected = { $z } (projected z'; eye-space w = { $w })
z-beyond = (beyond 128-bit exact arithmetic)

test-passed = { $z } { $op } { $stored } stored
test-failed = { $z } is not { $op } { $stored } stored
test-uncompared = { $z } ({ $test } passes; { $stored } stored)
rule-compared = z { $op } stored
rule-always = every fragment passes
rule-never = no fragment passes

frame-blended = { $frame } (opacity { $alpha }: { $alpha }·{ $value } + { $rest }·{ $under } under, rounded half up)
reason-written = z = { $test }, so { $stored } and the framebuffer gets { $frame }
reason-hidden = z = { $test }: hidden, nothing changes
reason-outside-range = z = { $z } is outside the depth range { $front } … { $rear }: discarded
reason-beyond-section = z = { $test }, but the cross-section keeps only z { $op } { $section }: not written

fate-culled = culled: its vertices run { $winding }, so it is not drawn
fate-edge-on = seen edge-on (c = 0): it covers no pixel
fate-degenerate = degenerate (Newell's normal is zero): it covers no pixel
fate-clipped = every vertex lies behind the near plane: clipped away, not drawn

entry-no-row = its y range does not reach the scanline { $scanline }{ $tie }
entry-covered = on the scanline { $scanline } it spans { $span }, which holds the centre x = { $centre }{ $tie }; { $reason }
entry-covered-no-span = on the scanline { $scanline } it spans, which holds the centre x = { $centre }{ $tie }; { $reason }
entry-not-inside = on the scanline { $scanline } { $spans }; the centre x = { $centre } is not inside{ $tie }
spans-none = { $subject } has no crossings
spans-some = { $subject } spans { $spans }
subject-it = it
tie-wrap = { " (" }{ $text })

why-covers = { $polygon } covers ({ $x }, { $y }): z = { $test }, so { $result }
why-later = { "; later " }{ $list }
why-later-item = { $polygon } ({ $reason })
result-frame = the framebuffer holds { $value }
cleared-frame = the background { $value }
cleared-depth = the cleared depth { $value }
why-covered-item = { $polygon } covers it but { $reason }
why-nothing-written = nothing was written at ({ $x }, { $y }): { $list }; it keeps { $cleared }
why-none-reaches = no polygon covers ({ $x }, { $y }): none reaches the scanline { $scanline }; it keeps { $cleared }
why-not-covered = no polygon covers ({ $x }, { $y }): on the scanline { $scanline } { $list }; it keeps { $cleared }

boundary-top = top edge
boundary-bottom = bottom edge
boundary-left = left edge
boundary-right = right edge
boundary-vertex = vertex
tie-vertex = the centre is exactly the vertex { $point }: the edges meeting there decide, by { $rule }
tie-edge-in = the centre lies exactly on the { $boundary } from { $a } to { $b }, which { $rule } includes
tie-edge-out = the centre lies exactly on the { $boundary } from { $a } to { $b }, which { $rule } leaves out
rule-columns-centre = the book's column rule (centres in [x_l, x_r], ends included)
rule-columns-cell = BUET's column rule (from the cell holding x_a to the one holding x_b)
rule-columns-half-open = the half-open column rule (centres in [x_l, x_r): left edges in, right edges out)
rule-rows-half-open = the book's half-interval rule (an edge counts for min ≤ y < max)
rule-rows-closed = BUET's closed rows (min ≤ y ≤ max)
rule-rows-top-left = the top-left rule (an edge counts for min < y ≤ max: top edges in, bottom edges out)

explain-heading = pixel ({ $x }, { $y }) of { $file }: centre ({ $cx }, { $cy }), depth test { $test } ({ $rule })
polygon-line = { $polygon }: { $text }
explain-start = start: framebuffer { $frame }, z-buffer { $depth } (cleared)
explain-final = final: framebuffer { $frame }, z-buffer { $depth }

check-all-match = { $buffer } { $file }: all { $cells } cells match the { $buffer } after { $after }
check-differ = { $buffer } { $file }: { $count } of { $cells } cells { $count ->
    [one] differs
   *[other] differ
  } from the { $buffer } after { $after }
check-unanswered = ; { $count } of { $cells } cells { $count ->
    [one] was
   *[other] were
  } left unanswered (? or .)
check-hint-matches = hint: read { $how }, it matches; write the top row (y = { $top }) first and each row from x = 0, as the book prints them
check-hint-fewer = hint: read { $how }, only { $left } cells differ; write the top row (y = { $top }) first and each row from x = 0, as the book prints them
check-column-answer = answer
check-column-right = right
check-column-why = why
check-in-arith = in { $arith } arithmetic the cell holds { $mode }; in exact arithmetic { $exact }: { $reason }
grade-summary = class { $class } on { $scene } after { $polygon }: { $students ->
    [one] { $students } student
   *[other] { $students } students
  }; { $ok } ok, { $wrong } wrong, { $malformed } malformed, { $missing } missing an answer
grade-column-student = student
grade-column-frame = frame wrong
grade-column-depth = depth wrong
grade-column-score = score %
grade-column-status = status
grade-column-buffer = buffer
grade-column-wrong = wrong
grade-column-answered = answered
grade-status-ok = ok
grade-status-wrong = wrong
grade-status-incomplete = incomplete: { $count } { $count ->
    [one] cell
   *[other] cells
  } left unanswered
grade-status-malformed = malformed: { $why }
grade-status-missing = missing: { $what }
grade-students-of = { $count } of { $total }
grade-mistakes = common mistakes (cells at least two students got wrong, most first):
grade-mistakes-none = common mistakes: no cell was got wrong by more than one student
grade-feedback = { $student }: { $scene } after { $polygon }: score { $score } %, { $status }
exercise-title = exercise, seed { $seed }: { $width }×{ $height } raster, { $count ->
    [one] { $count } polygon
   *[other] { $count } polygons
  }
exercise-solution-title = exercise, seed { $seed }: the framebuffer after the last polygon
exercise-task-draw = Draw the polygons in order (A first) with the z-buffer algorithm: larger z is nearer, the z-buffer starts at 0, holds 0 … { $max } (rounded, saturated).
exercise-task-write = Write the framebuffer (each polygon's value) and the z-buffer after the last polygon, top row first.
misreading-upside-down = bottom row first
misreading-transposed = with rows and columns swapped

## run and step: the scene's heading, the stages, a polygon's heading

depth-test-greater = greater
depth-test-less = less
depth-test-greater-equal = greater-equal
depth-test-less-equal = less-equal
depth-test-always = always
depth-test-never = never
scene-header = scene { $path }: { $width }×{ $height } pixels, framebuffer { $frame_bits } bits, z-buffer { $depth_bits } bits (0…{ $depth_max }), depth test { $test } ({ $rule }), cleared to { $clear }
scene-stages = stages: { $stages }
scene-effects = effects: { $effects }
effects-none = none
stage-cull = back-face culling ({ $winding } polygons skipped)
stage-near-plane = near-plane clipping (keep z ≤ { $near }) and perspective projection (eye at z = { $eye })
stage-supersampling-sample = supersampling { $k }×{ $k } (depth at each sample), then averaging
stage-supersampling-pixel = supersampling { $k }×{ $k } (depth at each pixel's centre), then averaging
stage-window = window { $left } … { $right } × { $bottom } … { $top } onto the raster
stage-scan = scan conversion
stage-scan-closed = scan conversion (closed rows, cells holding the crossings)
stage-scan-top-left = scan conversion (top-left rule)
stage-depth-range = depth range (discard z outside { $front } … { $rear })
stage-w-buffer = w-buffer (eye-space depth z = d·z'/(d + z'))
stage-depth-test = depth test ({ $rule })
stage-section = cross-section (z { $op } { $section })
stage-blend = blend by opacity (α·value + (1 − α)·under, rounded half up)
stage-store-quantized = store (rounded half up, saturated to 0…{ $max })
stage-store-exact = store (exact depth)
heading-start = { $polygon } (value { $value })
heading-degenerate = { $start }: degenerate: Newell's normal is zero (collinear vertices, or loops that cancel), so it has no plane and covers no pixel
heading-clipped-away = { $start }: behind the near plane: clipped away, not drawn
heading-edge-on = { $start }: plane { $plane }: seen edge-on (c = 0), it covers no pixel
heading-culled = { $start }: plane { $plane }, { $winding }: culled (cull { $cull }), not drawn
heading-drawn = { $start }: plane { $plane }{ $winding }{ $opacity }{ $clipped }
heading-drawn-projected = { $start }: projected plane { $plane }{ $winding }{ $opacity }{ $clipped }
heading-winding = { ", " }{ $winding }
heading-opacity = { ", opacity " }{ $alpha }
heading-clipped = { "; " }{ $front } of { $of } vertices in front of the near plane, drawn as one { $n }-gon
run-counts = { $covered } pixel centres covered, { $written } written
run-frame-after = framebuffer after { $polygon }:
run-depth-after = z-buffer after { $polygon }:
run-no-polygons = the scene has no polygons: the buffers stay as cleared
run-frame-cleared = framebuffer, cleared:
run-depth-cleared = z-buffer, cleared:
figure-title-worksheet = { $file }: the polygons to draw, on an empty raster
figure-title-after = { $file }: { $buffer } after { $polygon }
figure-title-samples = { ", " }its { $k }×{ $k } samples per pixel before averaging (`zsim run` gives the means)
figure-cell = ({ $x }, { $y }): frame { $frame }, depth { $depth }
figure-cells = ({ $from } … { $to }, { $y }): frame { $frame }
figure-background = { $value }: background
figure-value = value { $value }
figure-value-named = value { $value }: { $names }
figure-polygons = { $count } polygons
figure-axis-x = x (numbers at pixel centres, x + ½)
figure-cleared = cleared ({ $value })
figure-far = { $larger_nearer ->
    [yes] lower z: farther
   *[no] higher z: farther
}
figure-near = { $larger_nearer ->
    [yes] higher z: nearer
   *[no] lower z: nearer
}
file-written-about = wrote { $path } ({ $about })
file-written-page = wrote { $path } (open it in a browser; it needs no network)

## step, line by line

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

## step on a terminal: the full-screen app

tui-title = zsim step ·{ $heading } · { $view }{ $score } · ? keys
tui-heading = { " " }{ $polygon }, scanline { $scanline }
tui-heading-end = { " end of the scene" }
tui-score = { " · quiz " }{ $right }/{ $asked }
tui-key-nothing = that key does nothing here: ? shows the keys
tui-no-later = no later polygon covers a pixel
tui-no-earlier = no earlier polygon covers a pixel
tui-go = go to scanline of row: { $text }▏ (Enter to go, Esc to cancel)
tui-status = n/→ next · b/← back · p/P polygon · g go · f/z buffer · m pixel steps · q quit
tui-no-scanline = no scanline
tui-columns-shown = x { $first } … { $last } of 0 … { $max }
tui-end = end of the scene
tui-span = span { $n }: { $left } … { $right }; { $columns }
tui-no-centre = no centre
tui-table-heading = x { $z } test → stored (frame)
tui-uncompared = { $test } passes,{ " " }
tui-not = { "not " }
tui-hidden = hidden
tui-pixel-by-pixel = m: pixel by pixel, with the reasons
tui-steps-from = { ", " }{ $count } steps of −a/c from { $start }
tui-pixel = ({ $x }, { $y }): centre x = { $centre }, z = { $z }{ $steps }
tui-keys = { " keys " }
tui-help =
    n Space Enter → ↓  next scanline (or pixel)
    b ← ↑              back
    p / P              next / previous polygon
    g                  go to the scanline of a row
    f / z              show the framebuffer / z-buffer
    m                  step by pixel / by scanline
    PgUp PgDn < >      scroll the raster
    { "[ ]" }                scroll the table
    ?                  these keys (any key closes)
    q Esc Ctrl-C       quit

    yellow: the span's covered pixels
    cyan: this polygon's earlier writes

## the quiz (step --quiz)

quiz-mistakes = your mistakes:
meant-not-written = not written
meant-value-written = the value written
meant-value-kept = not written: the value it keeps
meant-value = a value
quiz-coverage-hint = type the covered columns as first-last (several runs apart: 3-5 9-12), or - for none
quiz-coverage-why = the spans are { $spans }; a column is covered when its centre x + 1/2 lies within one
quiz-coverage-mistake = row { $row } of { $polygon }: you said columns { $said }, right { $right }: { $why }
quiz-depth-hint = type the value the z-buffer will hold, or - for not written (q stops the quiz)
quiz-not-an-answer = "{ $text }" is not an answer: { $hint }
quiz-does-not-fit = { $text } does not fit this z-buffer: its cells hold whole levels 0 … { $max }; type again
quiz-keeps = - (it keeps { $value })
quiz-depth-mistake = ({ $x }, { $y }) of { $polygon }: you said { $said }, right { $right }: { $reason }

## step --html: the page

page-back = ◀ Back (b)
page-next = Next ▶ (n)
page-previous-polygon = ◀◀ Polygon (P)
page-next-polygon = Polygon ▶▶ (p)
page-frame = Framebuffer (f)
page-depth = Z-buffer (z)
page-quiz = quiz
page-no-pixel = This scene covers no pixel.
page-frame-after = framebuffer after this scanline
page-depth-after = z-buffer after this scanline
page-column-stored = stored
page-column-after = z-buffer after
page-column-why = why
page-keeps = – (keeps { $value })
page-check = Check my answers
page-status = scanline { $at } of { $count }

## errors a student meets most: the files, the polygons, the answers

error-read = { $path }: cannot read: { $reason }
error-write = { $path }: cannot write: { $reason }
error-polygon = { $path }: { $polygon }: { $problem }
geometry-too-few = has { $count } vertices; a polygon needs at least 3
geometry-too-many = has { $count } vertices; zsim takes at most { $max }
geometry-out-of-range = vertex { $vertex } has coordinate { $value } beyond the exact range: with the polygon's common denominator { $denominator }, |coordinate| × 2 × { $denominator } must be at most 2^4096 (use smaller coordinates or fewer decimal places)
digits = { $count } digits
geometry-off-plane-z = is not planar: vertex { $vertex } is off the plane { $plane } through vertices { $i }, { $j }, { $k } by Δz = { $off }
geometry-off-plane = is not planar: vertex { $vertex } gives { $off } instead of 0 in the plane { $plane } through vertices { $i }, { $j }, { $k }
answer-at-cell = line { $line }, value { $column } (x = { $x }, y = { $y })
answer-at = line { $line }, value { $column }
answer-not-a-number = { $at }: "{ $cell }" is not a whole number ({ $buffer } holds 0 … { $max })
answer-too-large = { $at }: { $value } does not fit { $buffer } (0 … { $max })
answer-row-length = line { $line }: { $count } { $count ->
    [one] value
   *[other] values
  }; the raster is { $width } wide
answer-row-count = { $count } { $count ->
    [one] row
   *[other] rows
}; the raster has { $height }
answer-frame-range = a { $bits }-bit framebuffer
answer-depth-range = a { $bits }-bit z-buffer

## explain's extras: sections, segments, inside tests, antialiasing, other arithmetic

explain-section = cross-section: only z { $op } { $section } is written
explain-inside = inside tests at the centre: ray casting says { $ray }; arc length: { $arc }
explain-inside-in = inside
explain-inside-out = outside
explain-arc-boundary = on the boundary, so inside
explain-arc-winding = winding number { $winding }, so { $inside }
explain-segment = segment { $number } of { $count } ({ $segments }): columns { $first } … { $last }, rows { $bottom } … { $top }; its z-buffer holds { $cells } cells; it visits { $visited }
explain-segment-none = no polygon
explain-antialias = antialiasing, { $k }×{ $k } samples (the lines above are the pixel's centre without it; sample lines count in 1/{ $k } pixels)
explain-sample = sample ({ $i }, { $j }) at ({ $x }, { $y }): framebuffer { $frame }, z-buffer { $depth }
explain-pixel-mode = { $polygon } covers samples { $samples }; its plane's depth at the pixel centre is { $depth }: { $result }
explain-pixel-mode-written = written, the z-buffer holds { $stored } and those samples take the value
explain-pixel-mode-not-written = not written
explain-mean = mean over the samples: framebuffer { $frame }, z-buffer { $depth }
explain-arith = in { $arith } arithmetic: framebuffer { $frame }, z-buffer { $depth } ({ $verdict })
explain-arith-same = the same as exact
explain-arith-differs = not what exact arithmetic gives

## clip-space vertices [x, y, z, w]

vertex-decimal-comma = a vertex has four numbers, { $written }, among [x, y, z] vertices: is { $comma } a decimal comma? JSON numbers take a point: write { $meant }
clip-space-mixed = mixes [x, y, z] vertices with clip-space [x, y, z, w] ones: write every vertex of a polygon the same way
clip-space-alone = has clip-space vertices [x, y, z, w], which the viewport maps onto the raster; they do not combine with a window or the perspective effect
fate-outside-view = it lies outside the view volume (−w ≤ x, y, z ≤ w): clipped away, not drawn
heading-outside-view = { $start }: outside the view volume (−w ≤ x, y, z ≤ w): clipped away, not drawn
heading-view = { "; clip space: " }{ $inside } of { $of } vertices inside the view volume, drawn as one { $n }-gon after clipping, division by w and the viewport

## the scene reader

scene-not-object = a scene is a JSON object such as {"{"}"width": 32, "height": 32, "polygons": [...]{"}"}, not { $found }
json-array = an array
json-string = a string
json-number = a number
json-bool = true or false
json-null = null
json-comma-end = { " (a comma is missing at the end of line " }{ $line })
json-comma-after = { " (a comma is missing after line " }{ $line } column { $column })
json-invalid = not valid JSON: { $error }
location-polygon = polygon { $number }
number-found-object = expected a number, found an object
number-found-bool = expected a number, found a boolean
number-found-null = expected a number, found null
number-found-list = expected a number, found a list
number-not-a-number = "{ $text }" is not a number (write an integer, a decimal such as 2.5, or a fraction such as "5/2")
number-zero-denominator = "{ $text }" divides by zero
number-too-large = "{ $text }" has too many digits to hold exactly (at most 30 significant digits)
number-too-long = "{ $text }" has too many digits or too large a power of ten (a vertex coordinate may have at most { $max } significant digits and powers of ten up to ±{ $max })
setting-bits = { $value } is not supported: use 1 to 32 bits
setting-side-zero = must be at least 1 pixel
setting-side-large = { $side } is beyond the limit of { $max } pixels
setting-cells = { $width }×{ $height } is { $cells } pixels, beyond the limit of { $max }
setting-background = { $value } does not fit a { $bits }-bit framebuffer (at most { $max })
setting-window = left { $left } must be below right { $right } and bottom { $bottom } below top { $top }
setting-depth-range = [{ $front }, { $rear }]: the front must not exceed the rear
setting-clear-depth = applies only to an exact z-buffer (rules with "store": "exact"); a quantized one is cleared to its farthest level
setting-perspective-positive = perspective: distance and near must be positive
setting-antialias-samples = antialias: samples { $samples } is not supported: use 1 to 16
setting-antialias-cells = antialias: { $width }×{ $height } pixels × { $samples }² samples is beyond the limit of { $max } cells
setting-antialias-exact = antialias averages a quantized z-buffer; it does not combine with an exact store
polygon-opacity = opacity { $alpha } is outside 0 … 1
polygon-value-too-wide = value { $value } does not fit a { $bits }-bit framebuffer (at most { $max })

# Where a polygon with a problem came from, when not a file.
origin-supersampled = the scene supersampled { $factor }×
origin-snapped = the scene snapped to fixed:{ $bits }

# Requests that do not fit the command or the scene.
usage-arith-plain-rules = --arith { $arith } simulates the plain algorithm with the book's rules; this scene asks for other rules or per-pixel effects (use --arith exact)
usage-arith-greater-or-less = --arith { $arith } simulates the depth tests greater and less; this scene asks for { $test } (use --arith exact)
usage-arith-plain-loop = --arith other than exact runs the plain z-buffer loop; drop --segments and --order
usage-no-polygon-numbered = there is no polygon { $number }: the scene has { $count } (number them from 1)
usage-no-polygon-named = there is no polygon named "{ $name }": the scene has { $names }
usage-pixel-outside = pixel ({ $x }, { $y }) is outside the { $width }×{ $height } raster (x 0 … { $last_x }, y 0 … { $last_y })
usage-figure-format = { $path }: a figure is written as .svg, .png, .pdf or .tex (TikZ)
usage-figure-too-large = { $path }: a figure draws rasters up to { $max }×{ $max }; this one is { $width }×{ $height }
usage-png-failed = { $path }: cannot draw the figure: { $reason }
usage-no-polygons-draw = { $path }: the scene has no polygons to draw
usage-no-polygons-grade = { $path }: the scene has no polygons to grade
usage-no-polygons-check = { $path }: the scene has no polygons to check
usage-exact-depths-grade = { $path }: this scene keeps exact depths, so its z-buffer has no integer matrix to grade; grade the framebuffers
usage-exact-depths-check = { $path }: this scene keeps exact depths, so its z-buffer has no integer matrix to check; check the framebuffer, or a BUET z_buffer.txt with `zsim buet check`
usage-check-needs-answer = check needs an answer: --frame FILE and/or --depth FILE
usage-no-answers = { $path }: no answers found: name each student's files NAME.frame.txt and/or NAME.depth.txt
usage-scenes-range = --scenes takes 1 to 100
usage-memory-bits = { $option } { $bits }: use 1 to 64 bits
usage-memory-zero = --width, --height and --supersample must be at least 1
usage-memory-too-large = the raster is too large to count (more than 2^50 cells)
usage-random-count = --count { $count }: at most { $max } triangles (a scene that large takes about 10 GB to read back)
usage-random-bits = --frame-bits and --depth-bits take 1 to 32
usage-random-side = --width and --height take 1 to { $max }
usage-not-a-hard-case = --hard: "{ $name }" is not a hard case: { $names }
usage-exercise-size = --size { $width }x{ $height }: an exercise is 4 … 64 pixels on a side
usage-exercise-polygons = --polygons { $count }: an exercise has 1 … 8 polygons
usage-exercise-bits = --frame-bits takes 1 … 8 and --depth-bits 1 … 16 for an exercise done by hand
usage-exercise-two-polygons = hidden and intersecting need two polygons or more (--polygons 2)
usage-exercise-not-found = no scene of { $polygons } polygons on { $width }×{ $height } with all of { $cases } came up in { $tries } tries; ask for fewer cases, more polygons or a larger raster
usage-inside-needs-pixel-order = --inside chooses the point-in-polygon test of --order pixels; add --order pixels
usage-tiles-need-format-none = --tile and --threads apply to --format none, --final and --after (otherwise the state after each polygon is shown, drawn in order)
usage-format-none-is-plain = --format none summarizes the z-buffer loop; use text or json with --segments, --order pixels or antialias
usage-no-scanlines = { $polygon } has no scanlines: { $why }
usage-scanline-rows = { $reach }: its rows are { $first } … { $last }
usage-scanline-no-rows = { $reach }: it reaches no row of the raster

# What the stepper passes over on its way to the next covered scanline.
step-skip-fate = { $polygon }: { $why }
step-skip-no-scanline = { $polygon }: reaches no scanline of the raster
step-skip-no-centre = { $polygon }, scanline { $scanline }: no pixel centre covered
step-skip-no-centre-no-crossings = { $polygon }, scanline { $scanline }: no pixel centre covered (no crossings)

# Course files (CS 418, BUET) and images: what is wrong with them.
case-line = line { $line }: { $problem }
case-unknown-command = unknown command "{ $command }"
case-keyword-problem = { $keyword }: { $problem }
list-or = { $rest } or { $last }
cs418-second-png = a second "png" line (the file names one image, on its first line)
cs418-before-png = "{ $keyword }" before the "png WIDTH HEIGHT FILE" line that must come first
cs418-flag-numbers = "{ $keyword }" takes no numbers, found { $found }
cs418-fsaa = fsaa { $level }: the level must be 1 to 8
cs418-size = { $keyword } { $size }: the size must be { $allowed }
cs418-not-an-index = elements: "{ $word }" is not an index (a whole number ≥ 0)
cs418-matrix = uniformMatrix needs 16 numbers, found { $found }
cs418-count = { $keyword }: count { $count } is not a multiple of 3
cs418-texture-name = texture needs a file name
cs418-texture = texture "{ $name }": { $why }
cs418-no-png = no "png WIDTH HEIGHT FILE" line: is this a CS 418 file?
cs418-png-words = png needs WIDTH HEIGHT FILE, found { $found } words
cs418-png-side = png: { $what } "{ $word }" must be a whole number from 1 to { $max }
cs418-png-file = png: "{ $file }" must be a plain file name, without folders
cs418-not-a-number = { $keyword }: "{ $word }" is not a number
cs418-integers = { $keyword } needs { $count } whole { $count ->
    [one] number
   *[other] numbers
}, found { $found }
cs418-not-a-whole-number = { $keyword }: "{ $word }" is not a whole number ≥ 0
cs418-sized = { $keyword } needs a size and then the numbers
cs418-size-word = { $keyword }: the size "{ $size }" is not a whole number
cs418-size-zero = { $keyword }: the size must not be 0
cs418-vertices = { $keyword } { $size }: { $numbers } numbers is not a whole number of vertices ({ $whole } and { $left } left over)
cs418-vertex-index = vertex { $index } is read, but "position" has { $count } vertices
cs418-texture-missing = no such file beside the case
cs418-texture-unreadable = cannot be read ({ $reason })
cs418-image-size = the image is { $width } × { $height }, the case draws { $case_width } × { $case_height }
png-not-an-image = not a PNG image ({ $reason })
png-too-large = the PNG is too large
png-broken = a broken PNG image ({ $reason })
png-colour-type = an unexpected PNG colour type { $kind }
buet-size = "{ $word }" is not a raster size from 1 to { $max }
buet-config-empty = is empty; it needs the raster size "W H"
buet-config-first = the first line must be the raster size "W H"
buet-one-number = expected one number
buet-z-range = expected "z_front z_rear"
buet-window-negative = left_x and bottom_y must be negative (the window is left_x … −left_x)
buet-z-order = z_front must not exceed z_rear
buet-config-lines = has { $count } non-empty lines; expected 1 ("W H") or 4 ("W H", left_x, bottom_y, "z_front z_rear")
buet-ends = ends where { $what } was expected
buet-numbers = expected { $what } ({ $count } numbers), found "{ $found }"
buet-what-eye = the eye position
buet-what-look = the look-at point
buet-what-up = the up direction
buet-what-perspective = fovY aspect near far
buet-what-vertex = a triangle vertex
buet-what-translation = a translation
buet-what-scale = scale factors
buet-what-rotation = an angle and an axis
buet-pop = pop without a matching push
buet-three-coordinates = expected three coordinates, found "{ $found }"
buet-triangles = has { $count } points, not a whole number of triangles
cs418-width = width
cs418-height = height

# The rule presets, as --compare-rules and reports name them.
rules-describe = rules { $preset }: { $rows }; { $columns }; { $store }
rules-rows-half-open = rows half-open (min ≤ y < max), crossings paired
rules-rows-closed = rows closed (min ≤ y ≤ max), one span from the least to the greatest crossing
rules-rows-top-left = rows top-left (min < y ≤ max: a top edge's centres in, a bottom edge's out), crossings paired
rules-columns-centre-inside = columns whose centre lies in the span
rules-columns-cell-holds = columns from the cell holding x_a to the cell holding x_b
rules-columns-half-open = columns whose centre lies in [x_l, x_r): a left edge's centres in, a right edge's out
rules-store-quantized = depth rounded half up and saturated
rules-store-exact = depth stored exactly

# Where an exercise meets each hard case.
place-vertex-on-scanline = polygon { $polygon }: vertex { $vertex } ({ $x }, { $y }) lies on the scanline of row { $row }
place-centre-on-edge = pixel ({ $x }, { $y }): its centre lies on an edge of polygon { $polygon }
place-spans = polygon { $polygon }: row { $row } has { $spans } spans
place-half-depth = pixel ({ $x }, { $y }), polygon { $polygon }: z = { $z } rounds up to { $stored }
place-saturation = pixel ({ $x }, { $y }), polygon { $polygon }: z = { $z } rounds to { $rounded }, stored as { $stored }
place-hidden = pixel ({ $x }, { $y }), polygon { $polygon }: z = { $z } does not pass the test against { $stored } stored
place-intersecting = polygons { $first } and { $second }: each is in front of the other somewhere

cs418-elements-range = drawElementsTriangles { $count } { $offset } reads elements { $offset }…{ $last }, but "elements" has { $has }
cs418-point-size-range = drawArraysPoints reads point size { $index }, but "pointsize" has { $has }
cs418-texcoord-range = vertex { $index } is drawn with a texture, but "texcoord" has { $has } vertices
cs418-too-far = a vertex lands at ({ $x }, { $y }) on the image, too far outside it to rasterize (more than { $reach } image sizes away): turn on "frustum" to clip it
cs418-too-many-primitives = { $count } primitives do not fit a 32-bit framebuffer

# The course commands and other command-line reports.
file-written = wrote { $path }
buet-run-summary = { $path }: { $triangles } { $triangles ->
    [one] triangle
   *[other] triangles
} on { $width }×{ $height }, { $tested } pixel centres tested, { $written } written
buet-answer-not-a-number = line { $line }, value { $value }: "{ $text }" is not a number
buet-answer-rows = { $rows } rows; the raster has { $height }
buet-none = (none)
buet-check-matches = { $answer }: every row matches the z-buffer of { $path }
buet-header-line = line
buet-header-value = value
buet-header-answer = answer
buet-header-right = right
buet-header-why = why
buet-cell = cell ({ $x }, { $y }): { $why }
buet-extra-value = zsim writes fewer values on this line: the answer has an extra one
buet-check-differs = { $answer }: { $count } { $count ->
    [one] value differs
   *[other] values differ
} from the z-buffer of { $path }
cs418-primitive-point = the point of vertices { $vertices } (line { $line })
cs418-primitive-triangle = the triangle of vertices { $vertices } (line { $line })
cs418-run-summary = { $path }: { $width } × { $height }, { $arithmetic } arithmetic{ $features }: wrote { $written }
cs418-compare-same = { $path }: every channel of every pixel within { $tolerance } (largest difference { $largest })
cs418-compare-differs = { $path }: { $count ->
    [one] 1 pixel differs
   *[other] { $count } pixels differ
} by more than { $tolerance } (largest difference { $largest }):
cs418-compare-pixel = ({ $x }, { $y }): zsim { $ours }, image { $theirs }
cs418-compare-more = … and { $count } more
cs418-arith-alike = the course's f64 arithmetic and exact arithmetic draw every sample alike
cs418-arith-disagree = { $count } { $count ->
    [one] sample
   *[other] samples
} where the course's f64 arithmetic and exact arithmetic disagree:
cs418-place-sample = sample ({ $x }, { $y }) of pixel ({ $px }, { $py })
cs418-place-pixel = pixel ({ $x }, { $y })
cs418-no-span = no span
cs418-inside = inside
cs418-outside = outside
cs418-why-span = { $primitive }: on row { $row } its span is { $course } in f64 but { $exact } exactly, so x = { $x } is { $course_side } in f64 and { $exact_side } exactly
cs418-nothing = nothing
cs418-why-depth = both arithmetics cover it with the same primitives, but the depth test keeps { $course } in f64 and { $exact } exactly (equal depths, or within rounding)
file-written-in = wrote { $files } in { $path }
exercise-notes-settings = exercise: seed { $seed }, { $width }×{ $height } raster, { $polygons } polygons, framebuffer { $frame_bits } bits, z-buffer { $depth_bits } bits (0 … { $max }), depth test { $test }
exercise-notes-asked = asked for: { $asked } (candidate { $candidate } of the seed's sequence)
exercise-notes-no-case = no particular case
exercise-notes-contains = it contains (found in the run's trace, first place each):
exercise-notes-none = none of the hard cases
exercise-notes-next = check an answer: zsim check { $path } --frame FRAME.txt --depth DEPTH.txt; grade a class: zsim grade { $path } CLASS_DIR
png-no-fonts = this system has no fonts, so its text would be missing; write an SVG (-o FILE.svg)
png-figure-too-large = the figure is too large
error-output = cannot write the output: { $reason }
memory-header-buffer = buffer
memory-header-cells = cells
memory-header-bits-per-cell = bits per cell
memory-header-bits = bits
memory-header-bytes = bytes
memory-total = total
memory-at-sample = sample
memory-at-pixel = pixel
memory-supersampled = , supersampled { $k }×{ $k } with the depth at each { $at }
memory-heading = { $width }×{ $height } pixels, framebuffer { $frame_bits } bits, z-buffer { $depth_bits } bits{ $sampling }
memory-total-line = total: { $total } bytes = { $megabytes }
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
run-summary = { $path }: { $polygons } { $polygons ->
    [one] polygon
   *[other] polygons
}, { $tested } pixel centres tested, { $written } written; effects: { $effects }; stages: { $stages }; read { $read } ms, rasterized { $raster } ms on { $threads } { $threads ->
    [one] thread
   *[other] threads
} ({ $rate } M pixels/s); memory: buffers { $buffers }, scene { $scene }{ $peak }
run-summary-peak = , peak resident { $peak }
run-summary-peak-ratio = , peak resident { $peak } ({ $ratio }× buffers + scene)
run-summary-no-effects = none
run-summary-arith = ; arithmetic { $arith }
run-arith-compared = arithmetic: { $arith }; compared with exact arithmetic, { $frame } framebuffer and { $depth } z-buffer cells differ
run-frame-after-all = framebuffer after all polygons:
run-depth-after-all = z-buffer after all polygons:
compare-rules-this = this scene's { $rules }
compare-rules-other = compared with { $rules }
compare-rules-same = every pixel comes out the same: no centre lies exactly on an edge where the rules differ
compare-rules-differ = { $count } { $count ->
    [one] pixel differs
   *[other] pixels differ
}:
compare-rules-nothing = nothing
compare-rules-cell = ({ $x }, { $y }): { $before } → { $after }; covered by { $covering } under { $rules }, by { $other_covering } under { $other_rules }
compare-rules-vertex = the centre ({ $x }.5, { $y }.5) is the vertex { $vertex } of "{ $name }": the edges meeting there decide, under each rule set as on its own edges
compare-rules-edge = the centre ({ $x }.5, { $y }.5) lies on the { $boundary } of "{ $name }" from { $from } to { $to }: { $verdict } under { $rules }, { $other_verdict } under { $other_rules }
compare-rules-covered = covered
compare-rules-left-out = left out
preset-rogers = the book's rules
preset-buet = BUET's rules
preset-gl = OpenGL's rule
preset-vulkan = the top-left rule of Vulkan and Direct3D
variant-identical = identical to the plain z-buffer's (framebuffer and z-buffer)
variant-differs = { $count } cells differ from the plain z-buffer's
variant-result = result: { $result }
segments-kind = segments: { $count } ({ $segments }), each polygon sorted into the segments its bounding box touches
segments-memory = z-buffer memory: { $cells } cells × { $bits } bits = { $total } bits (whole raster: { $whole_cells } cells, { $whole_bits } bits)
segments-visits = polygon visits: { $visits } (whole raster: { $whole })
pixel-order-ray = ray casting (left-open/right-closed vertex rule; on the boundary counts)
pixel-order-arc = the arc-length method (quadrant table; on the boundary counts)
pixel-order-heading = order: for every pixel, for every polygon, one depth variable (the Chinese course notes); inside test: { $test }
pixel-order-header-polygon = polygon
pixel-order-header-why = why the inside tests differ
pixel-order-on-boundary = the centre lies exactly on the boundary: arc counts it inside, while the half-interval rule leaves out top edges and vertices (an edge counts only at its lower end)
pixel-order-winding = the polygon winds { $winding } times around the centre: arc counts a non-zero winding as inside, the paired crossings (even-odd) as outside
pixel-order-disagree = { $count } centre(s) where arc and the scanline rule disagree:
antialias-at-sample = sample
antialias-at-centre = pixel's centre
antialias-heading = antialiasing: { $k }×{ $k } samples per pixel, depth at each { $at }; values are means over the samples (fractions of { $samples })
antialias-frame-after = framebuffer after { $polygon }, averaged:
antialias-depth-after = z-buffer after { $polygon }, averaged:
transparency-all-match = transparency: every cell matches the correct back-to-front blend
transparency-header-drawn = drawn
transparency-header-back-to-front = back to front
transparency-header-polygons = polygons there, back to front
transparency-differs = transparency: { $count } cells differ from the correct back-to-front blend (the local errors of drawing in the wrong order: a polygon behind a transparent one, drawn after it, fails the depth test):
accuracy-header-mode = mode
accuracy-header-ns = ns per pixel
accuracy-header-pixels = pixels
accuracy-header-frame = frame cells ≠ exact
accuracy-header-depth = depth cells ≠ exact
accuracy-header-worst = worst depth error (levels)
accuracy-header-time = time vs exact
accuracy-header-bits = depth bits
accuracy-header-fighting = z-fighting cells
accuracy-header-memory = z-buffer memory (bytes)
accuracy-header-ms = time (ms)
accuracy-set = accuracy set: { $scenes } scenes on { $width }×{ $height } (random triangles of 4, 16, 64 and 256 px with vertices on a 1/256 grid, seed { $seed }, and 4 hard cases); each mode's time is its least of 5 rounds in which the modes take turns
accuracy-sweep = two nearly coplanar planes crossing along x = y (world depths 0 … 1 times 2^bits levels; slopes 1/2^20 of the range per pixel), { $cells } cells:
progress-bands = bands of tiles
progress-polygons = polygons

# Inputs zsim refuses before reading.
error-not-regular = { $path }: is not a regular file (it is { $kind }): zsim reads only regular files
error-too-large = { $path }: is larger than zsim reads ({ $limit } MiB)
file-kind-directory = a folder
file-kind-fifo = a named pipe (FIFO)
file-kind-device = a device
file-kind-socket = a socket
file-kind-link = a symbolic link, which is not followed
file-kind-other = not a regular file
error-not-utf8 = not UTF-8 text
usage-output-is-input = { $path } is one of the inputs zsim reads: write the output elsewhere
usage-output-would-replace = { $path } already holds { $files }{ $more ->
    [0] {""}
   *[other] { " " }and { $more } more
}: zsim replaces no file; choose a new or empty folder
usage-tile-zero = --tile takes 1 or more pixels (0 would draw nothing)
stdout-closed = standard output is closed
buet-look-at-eye = the look-at point is the eye position: the view has no direction
buet-up-along-view = the up direction is zero or lies along the view direction: the camera has no orientation
buet-perspective = fovY and fovY·aspect must lie between 0 and 180 degrees, aspect and near be positive, and far differ from near
buet-rotation-axis = a rotation about the axis 0 0 0 has no direction
token-cut = { $shown }… ({ $count } characters)

# The machine's OpenGL.
gpu-no-library = no OpenGL found: { $reason } (install libegl1 libegl-mesa0 libgl1-mesa-dri)
gpu-refused = OpenGL refused { $step }: { $reason }
gpu-heading = { $path } drawn by { $renderer } beside zsim under the scene's rules and under the { $preset } preset
gpu-same = every pixel shows the same polygon on the GPU and in zsim
gpu-differ = { $count } { $count ->
    [one] pixel shows
   *[other] pixels show
} another polygon:
gpu-cell = ({ $x }, { $y }): the GPU shows { $gpu }; zsim shows { $book } under the scene's rules, { $covered } under { $preset }
gpu-background = nothing
gpu-exact-depth = { $polygon } at exact depth { $depth }
gpu-why-depth = the GPU stored depth { $gpu } (interpolated in f32, kept in 24 bits) for { $shown }; the scene's rules keep { $book }
gpu-not-convex = note: { $polygon } is not convex: the GPU draws it as a fan of triangles from its first vertex, which is not the polygon
speed-header = { $scene }: { $triangles } triangles (fans of { $polygons } polygons{ $skipped ->
    [0] {""}
   *[other] ; { $skipped } more draw nothing: degenerate, edge-on, culled or outside the view
  }), { $pixels } pixel centres tested; zsim on { $threads } { $threads ->
    [one] thread
   *[other] threads
}, { $tile ->
    [0] polygon by polygon
   *[other] in tiles of { $tile }
}, against { $renderer } (LP_NUM_THREADS={ $lp }), { $pairs } alternating pairs after one untimed round each
speed-result = zsim { $zsim } ms, GPU { $gpu } ms (medians): zsim takes { $ratio }× the GPU's time (pairs from { $low }× to { $high }×)
speed-fresh = zsim's whole run, in fresh buffers as `zsim run` draws: { $fresh } ms (median), { $ratio }× the GPU's time
speed-memory = zsim tested { $rate } million pixel centres a second; a copy of the buffers' { $megabytes } MB took { $copy } ms ({ $bandwidth } GB/s), which at { $bytes } bytes a pixel, each read and written once, allows { $limit } million pixels a second
usage-compare-gpu-plain = --compare-gpu compares the plain algorithm: this scene asks for per-pixel effects or antialiasing
usage-no-gpu = --compare-gpu: { $reason }
gpu-why-depth-unread = the GPU shows { $shown }; the scene's rules keep { $book } (the depths decided: the GPU interpolates them in f32)
gpu-no-vulkan = no Vulkan device found: { $reason } (install mesa-vulkan-drivers)
gpu-not-built = this zsim was built without its { $feature } feature: build it with `cargo install --path . --features { $feature }`

## What the system and the JSON reader say (words/system.rs)
io-not-found = no such file or folder
io-permission-denied = permission denied
io-already-exists = it already exists
io-is-a-directory = it is a folder
io-not-a-directory = a part of the path is not a folder
io-storage-full = the disk is full
io-read-only = the file system is read-only
io-not-utf8 = the file is not UTF-8 text
json-at = { $message } (line { $line }, column { $column })
json-invalid-type = invalid type: found { $found } where { $expected } was expected
json-invalid-value = invalid value: found { $found } where { $expected } was expected
json-invalid-length = { $length } entries where { $expected } was expected
json-missing-field = the field { $field } is missing
json-unknown-field = unknown field { $field }; the fields allowed: { $known }
json-unknown-field-none = unknown field { $field }
json-unknown-variant = unknown value { $variant }; the values allowed: { $known }
json-duplicate-field = the field { $field } is given twice
json-eof = the file ends in the middle of a value
json-expected-token = { $token } was expected
json-expected-value = a value was expected
json-trailing = there is text after the end of the scene
json-trailing-comma = a comma before a closing bracket
json-key-string = a key must be a string in quotes
json-invalid-number = invalid number
json-number-range = number out of range
json-invalid-escape = invalid escape in a string
json-too-deep = nested too deeply
json-control = a control character inside a string
json-found-integer = the integer { $value }
json-found-decimal = the decimal { $value }
json-found-string = the string { $value }
json-found-bool = { $value }
json-found-null = null
json-found-list = a list
json-found-object = an object
json-want-list = a list
json-want-string = a string
json-want-bool = true or false
json-want-number = a number (or a string holding a fraction or a decimal)
json-want-vertex = a vertex [x, y, z] (or [x, y, z, w] in clip space)
json-want-object = an object
json-want-whole = a whole number
usage-pixel-not-xy = "{ $text }" is not X,Y (for example 20,15)
usage-pixel-coordinate = "{ $text }" is not a pixel coordinate
usage-arith = "{ $text }" is not an arithmetic mode: exact, f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K (K from 0 to 24)
usage-missing = missing: { $args }
usage-invalid-value = "{ $value }" is not a value for { $arg }: { $reason }
usage-unknown-argument = unknown option { $arg }
usage-unknown-command = unknown command { $name }
usage-conflict = { $arg } cannot be given with { $other }
usage-see-help = see zsim --help

## The misconception behind a wrong answer (teach/diagnose.rs)
diagnosis = likely cause: { $what } (explains { $explained } of the { $wrong } wrong { $wrong ->
    [one] cell
   *[other] cells
})
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
grade-column-cause = likely cause
grade-cause = { $what } ({ $explained } of { $wrong })
grade-causes = likely causes in the class:
grade-cause-count = { $what }: { $count } of { $students } { $students ->
    [one] student
   *[other] students
}
answer-more-problems = { "" } · and { $count } more { $count ->
    [one] problem
   *[other] problems
}
usage-no-submission = { $folder }: no answer here: frame.txt, depth.txt, after-N.frame.txt or after-N.depth.txt
gradescope-test = { $buffer } after { $after }
usage-identity-column = --identity: this platform does not import by "{ $column }" (Moodle: email, idnumber, username; Canvas: id, sis-user-id, sis-login-id)
usage-no-points = --points must be at least 1
figures-not-built = this zsim was built without { $format } figures (the figures feature, off in a default build): build it with `cargo install --path . --features figures`; the Debian package has them. SVG and TeX figures need nothing

## tinyrenderer's OBJ files (courses/tinyrenderer.rs)
obj-vertex-count = a vertex needs x, y and z; this line has { $count }
obj-not-a-number = "{ $token }" is not a number
obj-face-corners = a face of the lesson has 3 corners; this one has { $count }
obj-bad-index = "{ $token }" is not a vertex number (from 1)
obj-too-many-faces = more than { $max } faces
obj-no-vertex = vertex { $index } does not exist: the file has { $count }
rules-store-truncated = depth truncated (rounded down) and saturated
rules-sample-corner = ; samples at integer corners (x, y)
rules-compare-level = ; the depth compared as the level it is stored as
rules-min-area = ; polygons of signed area below { $area } skipped
stage-store-truncated = store (truncated, saturated to 0…{ $max })
preset-tinyrenderer = tinyrenderer's z-buffer lesson
fate-small-area = its signed area is below the rules' bound (a back face or a sliver): it is skipped
heading-small-area = { $start }: plane { $plane }, skipped (signed area below the rules' bound: a back face or a sliver)
tinyrenderer-run = { $model }: { $faces } faces, { $skipped } skipped (area below 1), { $drawn } drawn; wrote zbuffer.tga and framebuffer.tga in { $folder }
tinyrenderer-differ = exact arithmetic gives another z-buffer level than the lesson's f64 at { $count } { $count ->
    [one] pixel
   *[other] pixels
}
tinyrenderer-differ-pixel = ({ $x }, { $y }), face { $face }: f64 { $float }, exact { $exact } (the interpolated z is an integer; f64 falls just below it and truncation drops a level)
tinyrenderer-line = line { $line }
explain-others = { $count } other polygons do not reach this pixel's scanline: { $skipped } not drawn at all (skipped, culled or edge-on), { $off } whose rows lie elsewhere
explain-corner-sample = the rules sample the integer point ({ $x }, { $y }): zsim draws the scene shifted by ½, so that this centre is that point, and the coordinates below are the shifted ones
stored-truncated = { $stored } is stored ({ $value } truncated to { $stored })
stored-truncated-saturated = { $stored } is stored ({ $value } truncated, saturated to { $stored })
usage-tinyrenderer-size = "{ $text }" is not an image side: { $min } … { $max } pixels
quiz-frame-hint = type the value the framebuffer will hold, or - for not written (q stops the quiz)
quiz-frame-does-not-fit = { $text } does not fit this framebuffer: its cells hold whole values 0 … { $max }; type again
usage-not-a-preset = "{ $text }" is not a rule preset: use rogers, buet, gl, vulkan (d3d, webgpu) or tinyrenderer
error-outside-folder = { $path }: a name inside a file must stay in that file's folder ({ $folder }): no "..", no absolute path
usage-output-name-too-long = { $path }: the name is longer than file systems hold ({ $max } bytes); nothing was written
usage-output-twice = { $path } would be written twice by one command; nothing was written
png-declares-too-many-pixels = the PNG declares { $width } × { $height } pixels, more than zsim decodes ({ $max })
cs418-too-many-samples = fsaa { $level } asks for { $samples } samples, more than zsim draws ({ $max }): lower fsaa or the image size
usage-same-answer-twice = { $path }: { $files } answer for the same buffer of the same state: hand in one
expect-not-states = "{ $text }" is not a list of states: write final, each, or polygon numbers from 1 separated by commas (1,3)
gradescope-missing = no file answers this: hand in { $file }
gradescope-score-rule = score: the share of the { $changed } cells the scene changes that are right ({ $right }), less one such share for each of the { $stray } cells written where the buffer keeps its cleared value; unanswered cells count for nothing
gradescope-ambiguous = { $files } all answer this: none is graded; hand in one
gradescope-unused = not graded (the assignment does not ask for them): { $files }
usage-same-student-twice = { $path }: { $files } are both "{ $student }" once their names are shown: rename one; nothing was graded
usage-gradebook-cannot-tell = "{ $first }" and "{ $second }" are one student to a gradebook (the same cell, without case): rename one; nothing was written
png-figure-too-many-pixels = at that --scale the PNG would have more than { $max } pixels: ask for less
check-more-cells = … and { $count } more { $count ->
    [one] cell differs
   *[other] cells differ
}, not listed

grade-skipped = not graded: { $file } is not an answer file (NAME.frame.txt or NAME.depth.txt)
grade-skipped-near = not graded: { $file } looks like { $student }'s { $buffer }: name it { $name }

## The browser playground
play-title = zsim playground: the z-buffer, step by step
play-intro = Edit the scene; every buffer below is drawn by zsim's own library, compiled for your browser.
play-language = Language
play-scene = Scene
play-width = width
play-height = height
play-frame-bits = framebuffer bits
play-depth-bits = z-buffer bits
play-depth-test = depth test
play-preset = rules
play-preset-none = the book's
play-snap = snap to
play-polygon = polygon
play-value = value
play-add-polygon = + polygon
play-remove-polygon = − polygon
play-add-vertex = + vertex
play-remove-vertex = − vertex
play-json = Scene JSON
play-share = Copy a link to this scene
play-shared = The link is in the address bar: copy it from there.
play-buffers = Buffers after each polygon
play-final = Final buffers (as zsim run --final prints them)
play-grid = The raster
play-grid-help = Drag a vertex to move it; click a pixel to see its history.
play-explain = The pixel's history
play-stepper = Scanline by scanline
play-figure = The figure
play-homework = Check a homework answer
play-homework-help = Type or paste the matrix as the book prints it, top row first.
play-check = Check
play-answer-grid = Type into a grid (starts from the cleared buffer)
play-after = after
play-your-answer = your answer
play-too-large = This scene is too large to show cell by cell (more than { $cells } pixels or { $polygons } polygons): only the final buffers are shown.
play-not-printed = This raster has more than { $cells } pixels: its buffers are drawn but not printed here; zsim run --final prints them.
play-no-antialias = This page draws the scene without its antialiasing; zsim run shows the antialiased pictures.
play-no-polygon = There is no such polygon in this scene.
play-not-json = The scene is not JSON: { $reason }
play-bad-edit = That change does not fit this scene's JSON.
play-bad-address = The address does not hold a scene: #scene= must be followed by the scene's JSON in base64url.

## The lesson (teach::lesson): the same in every front end.
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
lesson-hint-column-outside = you took in a column whose centre lies outside the span
lesson-hint-column-left-out = you left out a column whose centre lies inside the span
lesson-hint-other = compute z at the pixel's centre from the plane, compare it with the stored value, then round
lesson-right = { $said }: right. { $why }
lesson-right-second = { $said }: right at the second try. { $why }
lesson-try-again = { $said }: not yet: { $hint } (one more try)
lesson-revealed = { $said }: wrong again. The answer is { $expected }: { $why }
lesson-skipped = skipped: { $count } questions (counted as not answered)
lesson-score = quiz: { $first } right at the first try, { $second } at the second, { $revealed } shown, { $skipped } skipped, of { $asked } questions
lesson-ask-coverage = { $polygon }, scanline { $scanline }: which columns' centres does it cover? (columns as first-last, e.g. 3-7, or - for none)
lesson-ask-depth = pixel ({ $x }, { $y }), stored { $stored }: the z-buffer after? (a value, or - if not written)
lesson-ask-frame = pixel ({ $x }, { $y }), framebuffer { $before }: the framebuffer after? (a value, or - if not written)
lesson-last-try = last try: { $ask }
lesson-questions-open = { $open } open questions on this scanline: answer them first, or s to skip them
lesson-no-such-polygon = there is no polygon { $polygon }: the scene has { $count }
page-no-quiz = This page shows the steps and asks nothing: the quiz is in the browser playground (the page this command writes when zsim is built with it; see the guide's chapter "The browser playground") and in zsim step --quiz.
play-scene-name = the scene
page-skip = Skip (s)
play-quiz-kind = what the quiz asks
play-coverage-kind = covered columns, then the z-buffer
play-examples = Examples
play-reset = Reset
play-copied = The link is copied.
play-grid-label = The raster: arrow keys move the pixel cursor, Enter explains that pixel
play-buffer-kind = which buffer
play-example-rogers = The book's example
play-example-section = The book's section
play-example-less = Depth test "less"
play-example-cull = Back faces culled
play-example-concave = A concave polygon
play-legend = Framebuffer values:
play-hidden = { $count } more covered pixels, asked one at a time
play-legend-value = { $value }
lesson-said-meant = { $said } ({ $meant })
play-error-line = line { $line }: { $text }
answer-empty = the file is empty: it holds no row of the answer
answer-decimal-comma = line { $line }: { $text } has a decimal comma; each cell holds a whole number (cells are apart by spaces)
usage-answer-without-buffer = { $path } is an answer: name it with --frame { $path } or --depth { $path }
grade-mistakes-more = { $count } more { $count ->
    [one] cell
   *[other] cells
} that two or more students got wrong { $count ->
    [one] is
   *[other] are
} not listed
check-hint-other-buffer = this is exactly the { $other }, not the { $buffer }: was it handed in as the other buffer?
play-scene-too-long = This scene has { $bytes } bytes; the page reads scenes of up to { $max } bytes: zsim run draws it.
lesson-nothing-to-skip = no question is open here: nothing to skip
