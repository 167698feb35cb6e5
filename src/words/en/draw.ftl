# zsim's words in English: drawing a scene: run's reports, the stages, headings, rules and presets, effects, explain, figures, the GPU and speed.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
depth-test-greater = greater
depth-test-less = less
depth-test-greater-equal = greater-equal
depth-test-less-equal = less-equal
depth-test-always = always
depth-test-never = never
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
heading-polygon-scanline = { " " }{ $polygon }, scanline { $scanline }
heading-end-of-scene = { " end of the scene" }
end-of-scene = end of the scene
span-line = span { $n }: { $left } … { $right }; { $columns }
span-no-centre = no centre
test-passes-uncompared = { $test } passes,{ " " }
test-not = { "not " }
outcome-hidden-short = hidden
depth-steps-from = { ", " }{ $count } steps of −a/c from { $start }
meant-not-written = not written
meant-value-written = the value written
meant-value-kept = not written: the value it keeps
meant-value = a value
frame-after-scanline = framebuffer after this scanline
depth-after-scanline = z-buffer after this scanline
scanline-of-count = scanline { $at } of { $count }
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
fate-outside-view = it lies outside the view volume (−w ≤ x, y, z ≤ w): clipped away, not drawn
heading-outside-view = { $start }: outside the view volume (−w ≤ x, y, z ≤ w): clipped away, not drawn
heading-view = { "; clip space: " }{ $inside } of { $of } vertices inside the view volume, drawn as one { $n }-gon after clipping, division by w and the viewport
polygon-opacity = opacity { $alpha } is outside 0 … 1
polygon-value-too-wide = value { $value } does not fit a { $bits }-bit framebuffer (at most { $max })
list-or = { $rest } or { $last }
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
run-summary = { $path }: { $polygons } { $polygons ->
    [one] polygon
   *[other] polygons
}, { $tested } pixel centres tested, { $written } written; effects: { $effects }; stages: { $stages }; read { $read } ms{ $made }, rasterized { $raster } ms on { $threads } { $threads ->
    [one] thread
   *[other] threads
} ({ $rate } M pixels/s); memory: buffers { $buffers }, scene { $scene }{ $peak }
run-summary-peak = , peak resident { $peak }
run-summary-peak-ratio = , peak resident { $peak } ({ $ratio }× buffers + scene)
run-summary-made = , buffers made { $made } ms
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
speed-fresh = zsim's whole run, its buffers made fresh (as `zsim run`'s buffers made and rasterized together): { $fresh } ms (median), { $ratio }× the GPU's time
speed-memory = zsim tested { $rate } million pixel centres a second; a copy of the buffers' { $megabytes } MB took { $copy } ms ({ $bandwidth } GB/s), which at { $bytes } bytes a pixel, each read and written once, allows { $limit } million pixels a second
gpu-why-depth-unread = the GPU shows { $shown }; the scene's rules keep { $book } (the depths decided: the GPU interpolates them in f32)
gpu-no-vulkan = no Vulkan device found: { $reason } (install mesa-vulkan-drivers)
gpu-not-built = this zsim was built without its { $feature } feature: build it with `cargo install --path . --features { $feature }`
figures-not-built = this zsim was built without { $format } figures (the figures feature, off in a default build): build it with `cargo install --path . --features figures`; the Debian package has them. SVG and TeX figures need nothing
rules-store-truncated = depth truncated (rounded down) and saturated
rules-sample-corner = ; samples at integer corners (x, y)
rules-compare-level = ; the depth compared as the level it is stored as
rules-min-area = ; polygons of signed area below { $area } skipped
stage-store-truncated = store (truncated, saturated to 0…{ $max })
preset-tinyrenderer = tinyrenderer's z-buffer lesson
fate-small-area = its signed area is below the rules' bound (a back face or a sliver): it is skipped
heading-small-area = { $start }: plane { $plane }, skipped (signed area below the rules' bound: a back face or a sliver)
explain-others = { $count } other polygons do not reach this pixel's scanline: { $skipped } not drawn at all (skipped, culled or edge-on), { $off } whose rows lie elsewhere
explain-corner-sample = the rules sample the integer point ({ $x }, { $y }): zsim draws the scene shifted by ½, so that this centre is that point, and the coordinates below are the shifted ones
stored-truncated = { $stored } is stored ({ $value } truncated to { $stored })
stored-truncated-saturated = { $stored } is stored ({ $value } truncated, saturated to { $stored })
heading-scene = Scene
heading-scene-json = Scene JSON
heading-buffers-each-polygon = Buffers after each polygon
heading-final-buffers = Final buffers (as zsim run --final prints them)
heading-raster = The raster
heading-pixel-history = The pixel's history
heading-scanline-by-scanline = Scanline by scanline
heading-figure = The figure
heading-homework = Check a homework answer
antialias-not-drawn = This page draws the scene without its antialiasing; zsim run shows the antialiased pictures.
heading-examples = Examples
buffer-kind-label = which buffer
pixels-hidden-asked = { $count ->
    [one] 1 more covered pixel, asked next
   *[other] { $count } more covered pixels, asked one at a time
}
