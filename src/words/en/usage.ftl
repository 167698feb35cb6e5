# zsim's words in English: requests that do not fit the command or the scene.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

# Requests that do not fit the command or the scene.
usage-arith-plain-rules = { $arith } arithmetic simulates the plain algorithm with the book's rules; this scene asks for other rules or per-pixel effects, which exact arithmetic draws
usage-arith-greater-or-less = { $arith } arithmetic simulates the depth tests greater and less; this scene asks for { $test }, which exact arithmetic draws
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
usage-not-a-hard-case = "{ $name }" is not a hard case: { $names }
usage-exercise-size = an exercise is 4 … 64 pixels on a side, not { $width }×{ $height }
usage-exercise-polygons = an exercise has 1 … 8 polygons, not { $count }
usage-exercise-bits = an exercise done by hand has a framebuffer of 1 … 8 bits and a z-buffer of 1 … 16
usage-exercise-two-polygons = hidden and intersecting need two polygons or more
usage-exercise-not-found = no scene of { $polygons } polygons on { $width }×{ $height } with all of { $cases } came up in { $tries } tries; ask for fewer cases, more polygons or a larger raster
usage-inside-needs-pixel-order = --inside chooses the point-in-polygon test of --order pixels; add --order pixels
usage-tiles-need-format-none = --tile and --threads apply to --format none, --final and --after (otherwise the state after each polygon is shown, drawn in order)
usage-format-none-is-plain = --format none summarizes the z-buffer loop; use text or json with --segments, --order pixels or antialias
usage-no-scanlines = { $polygon } has no scanlines: { $why }
usage-scanline-rows = { $reach }: its rows are { $first } … { $last }
usage-scanline-no-rows = { $reach }: it reaches no row of the raster
usage-output-is-input = { $path } is one of the inputs zsim reads: write the output elsewhere
usage-output-would-replace = { $path } already holds { $files }{ $more ->
    [0] {""}
   *[other] { " " }and { $more } more
}: zsim replaces no file; choose a new or empty folder
usage-tile-zero = --tile takes 1 or more pixels (0 would draw nothing)
usage-compare-gpu-plain = the GPU is compared on the plain algorithm: this scene asks for per-pixel effects or antialiasing
usage-pixel-not-xy = "{ $text }" is not X,Y (for example 20,15)
usage-pixel-coordinate = "{ $text }" is not a pixel coordinate
usage-arith = "{ $text }" is not an arithmetic mode: exact, f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K (K from 0 to 24)
usage-missing = missing: { $args }
usage-invalid-value = "{ $value }" is not a value for { $arg }: { $reason }
usage-unknown-argument = unknown option { $arg }
usage-unknown-command = unknown command { $name }
usage-conflict = { $arg } cannot be given with { $other }
usage-see-help = see zsim --help
usage-no-submission = { $folder }: no answer here: frame.txt, depth.txt, after-N.frame.txt or after-N.depth.txt
usage-identity-column = --identity: this platform does not import by "{ $column }" (Moodle: email, idnumber, username; Canvas: id, sis-user-id, sis-login-id)
usage-no-points = --points must be at least 1
usage-tinyrenderer-size = "{ $text }" is not an image side: { $min } … { $max } pixels
usage-not-a-preset = "{ $text }" is not a rule preset: use rogers, buet, gl, vulkan (d3d, webgpu) or tinyrenderer
segments-form = "{ $text }" is not strips:N, tiles:N or rows:1 (N ≥ 1)
segments-count = "{ $count }" is not a whole number
segments-rows = rows takes only 1 (one scanline at a time)
usage-output-name-too-long = { $path }: the name is longer than file systems hold ({ $max } bytes); nothing was written
usage-output-twice = { $path } would be written twice by one command; nothing was written
usage-same-answer-twice = { $path }: { $files } answer for the same buffer of the same state: hand in one
grade-left-out-of-import = left out of the gradebook: "{ $first }" and "{ $second }" are one student to a gradebook (the same cell, without case): rename one and import their rows again
usage-answer-without-buffer = { $path } is an answer: name it with --frame { $path } or --depth { $path }
usage-line-too-long = a line longer than { $max } bytes: the lesson ends here, with its score above
usage-html-quiz = --html --quiz writes the playground, whose quiz asks in exact arithmetic: leave out --arith
usage-no-playground = this zsim was built without the browser playground: install the Debian package or a release archive, which carry it, or build zsim with it (web/build, then ZSIM_PLAYGROUND=target/web cargo build)
