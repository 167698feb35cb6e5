# zsim's words in English: the courses' files and commands: CS 418, BUET, tinyrenderer.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
cs418-textures-too-large = the case's textures would hold { $pixels } pixels together with this one; a case's textures hold at most { $max } together
cs418-texture-unreadable = cannot be read ({ $reason })
cs418-image-size = the image is { $width } × { $height }, the case draws { $case_width } × { $case_height }
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
cs418-elements-range = drawElementsTriangles { $count } { $offset } reads elements { $offset }…{ $last }, but "elements" has { $has }
cs418-point-size-range = drawArraysPoints reads point size { $index }, but "pointsize" has { $has }
cs418-colour-range = vertex { $index } is read, but "color" has { $has } vertices
cs418-texcoord-range = vertex { $index } is drawn with a texture, but "texcoord" has { $has } vertices
cs418-too-far = a vertex lands at ({ $x }, { $y }) on the image, too far outside it to rasterize (more than { $reach } image sizes away): turn on "frustum" to clip it
cs418-too-many-primitives = { $count } primitives do not fit a 32-bit framebuffer
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
buet-look-at-eye = the look-at point is the eye position: the view has no direction
buet-up-along-view = the up direction is zero or lies along the view direction: the camera has no orientation
buet-perspective = fovY and fovY·aspect must lie between 0 and 180 degrees, aspect and near be positive, and far differ from near
buet-rotation-axis = a rotation about the axis 0 0 0 has no direction
obj-vertex-count = a vertex needs x, y and z; this line has { $count }
obj-not-a-number = "{ $token }" is not a number
obj-face-corners = a face of the lesson has 3 corners; this one has { $count }
obj-bad-index = "{ $token }" is not a vertex number (from 1)
obj-too-many-faces = more than { $max } faces
obj-no-vertex = vertex { $index } does not exist: the file has { $count }
tinyrenderer-run = { $model }: { $faces } faces, { $skipped } skipped (area below 1), { $drawn } drawn; wrote zbuffer.tga and framebuffer.tga in { $folder }
tinyrenderer-differ = exact arithmetic gives another z-buffer level than the lesson's f64 at { $count } { $count ->
    [one] pixel
   *[other] pixels
}
tinyrenderer-differ-pixel = ({ $x }, { $y }), face { $face }: f64 { $float }, exact { $exact } (the interpolated z is an integer; f64 falls just below it and truncation drops a level)
file-line = line { $line }
cs418-too-many-samples = fsaa { $level } asks for { $samples } samples, more than zsim draws ({ $max }): lower fsaa or the image size
