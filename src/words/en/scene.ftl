# zsim's words in English: reading a scene: its JSON, settings, numbers, geometry; files and what the system says.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

subject-it = it
scene-header = scene { $path }: { $width }×{ $height } pixels, framebuffer { $frame_bits } bits, z-buffer { $depth_bits } bits (0…{ $depth_max }), depth test { $test } ({ $rule }), cleared to { $clear }
scene-stages = stages: { $stages }
scene-effects = effects: { $effects }
file-written-about = wrote { $path } ({ $about })
file-written-page = wrote { $path } (open it in a browser; it needs no network)
scene-covers-no-pixel = This scene covers no pixel.
error-read = { $path }: cannot read: { $reason }
error-write = { $path }: cannot write: { $reason }
error-polygon = { $path }: { $polygon }: { $problem }
geometry-too-few = has { $count } vertices; a polygon needs at least 3
geometry-too-many = has { $count } vertices; zsim takes at most { $max }
geometry-out-of-range = vertex { $vertex } has coordinate { $value } beyond the exact range: with the polygon's common denominator { $denominator }, |coordinate| × 2 × { $denominator } must be at most 2^4096 (use smaller coordinates or fewer decimal places)
digits = { $count } digits
geometry-off-plane-z = is not planar: vertex { $vertex } is off the plane { $plane } through vertices { $i }, { $j }, { $k } by Δz = { $off }
geometry-off-plane = is not planar: vertex { $vertex } gives { $off } instead of 0 in the plane { $plane } through vertices { $i }, { $j }, { $k }
vertex-decimal-comma = a vertex has four numbers, { $written }, among [x, y, z] vertices: is { $comma } a decimal comma? JSON numbers take a point: write { $meant }
clip-space-mixed = mixes [x, y, z] vertices with clip-space [x, y, z, w] ones: write every vertex of a polygon the same way
clip-space-alone = has clip-space vertices [x, y, z, w], which the viewport maps onto the raster; they do not combine with a window or the perspective effect
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
# Where a polygon with a problem came from, when not a file.
origin-supersampled = the scene supersampled { $factor }×
origin-snapped = the scene snapped to fixed:{ $bits }
png-not-an-image = not a PNG image ({ $reason })
png-too-large = the PNG is too large
png-broken = a broken PNG image ({ $reason })
png-colour-type = an unexpected PNG colour type { $kind }
# Where an exercise meets each hard case.
place-vertex-on-scanline = polygon { $polygon }: vertex { $vertex } ({ $x }, { $y }) lies on the scanline of row { $row }
place-centre-on-edge = pixel ({ $x }, { $y }): its centre lies on an edge of polygon { $polygon }
place-spans = polygon { $polygon }: row { $row } has { $spans } spans
place-half-depth = pixel ({ $x }, { $y }), polygon { $polygon }: z = { $z } rounds up to { $stored }
place-saturation = pixel ({ $x }, { $y }), polygon { $polygon }: z = { $z } rounds to { $rounded }, stored as { $stored }
place-hidden = pixel ({ $x }, { $y }), polygon { $polygon }: z = { $z } does not pass the test against { $stored } stored
place-intersecting = polygons { $first } and { $second }: each is in front of the other somewhere
# The course commands and other command-line reports.
file-written = wrote { $path }
file-written-in = wrote { $files } in { $path }
png-no-fonts = this system has no fonts, so its text would be missing; write an SVG (-o FILE.svg)
png-figure-too-large = the figure is too large
error-output = cannot write the output: { $reason }
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
stdout-closed = standard output is closed
token-cut = { $shown }… ({ $count } characters)
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
error-outside-folder = { $path }: a name inside a file must stay in that file's folder ({ $folder }): no "..", no absolute path
png-declares-too-many-pixels = the PNG declares { $width } × { $height } pixels, more than zsim decodes ({ $max })
png-figure-too-many-pixels = at that --scale the PNG would have more than { $max } pixels: ask for less
limit-cells-or-polygons = This scene is too large to show cell by cell (more than { $cells } pixels or { $polygons } polygons): only the final buffers are shown.
limit-printed-cells = This raster has more than { $cells } pixels: its buffers are drawn but not printed here; zsim run --final prints them.
limit-figure-cells = The page draws figures of rasters of up to { $cells } pixels; zsim figure draws this one.
scene-not-json = The scene is not JSON: { $reason }
edit-does-not-fit = That change does not fit this scene's JSON.
address-holds-no-scene = The address does not hold a scene: #scene= must be followed by the scene's JSON in base64url.
scene-name-default = the scene
error-at-line = line { $line }: { $text }
limit-scene-bytes = the page reads scenes of up to { $max } bytes; this one has { $bytes }: zsim run draws it
limit-page-cells = the page draws rasters of up to { $max } pixels; this one has { $cells }: zsim run draws it
limit-page-polygons = the page draws up to { $max } polygons; this scene has { $count }: zsim run draws it
limit-page-vertices = the page draws polygons of up to { $max } vertices; polygon { $polygon } has { $count }: zsim run draws it
limit-page-reach = the page draws scenes whose polygons' bounding boxes cover up to { $max } pixels of the raster in all; this one's cover { $reach }: zsim run draws it
limit-recorded-reach = the recorded page steps scenes whose polygons' bounding boxes cover up to { $max } pixels of the raster in all; this one's cover { $reach }: zsim step steps it in a terminal
limit-recorded-page = the recorded page steps scenes of up to { $cells } pixels and { $polygons } polygons; this one has { $has_cells } pixels and { $has_polygons } { $has_polygons ->
    [one] polygon
   *[other] polygons
}: zsim step steps it in a terminal
