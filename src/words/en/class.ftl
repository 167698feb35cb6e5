# A class: rosters, the manifest, variants, handouts, grading against each student's key, the platforms' graders.
roster-empty = { $path }: no student in the roster
roster-unknown-header = { $path }: line 1: not a roster zsim knows: its columns are { $headers }; give Moodle's, Canvas's, Gradescope's or PrairieLearn's export, or one identity a line
roster-no-such-column = { $path }: no column "{ $column }" to name the students by; the roster's columns are { $headers }
roster-empty-identity = { $path }: line { $line }: the student's { $column } is empty
roster-duplicate = { $path }: line { $line }: { $identity } is on the roster already (line { $first }); gradebooks match identities without letter case
roster-unnameable = { $path }: line { $line }: "{ $identity }" cannot name a student's files (no /, \, :, *, ?, ", <, >, | or control character, no leading dot, at most 200 bytes): choose another column with --identity
roster-too-many = { $path }: more than { $max } students: split the class
roster-unreadable = { $path }: line { $line }: { $reason }
manifest-layout = { $place }: not a class's variants.json: { $why }
manifest-format = { $place }: "{ $found }" is not a layout this zsim reads (it reads "{ $expected }")
manifest-hand-in = { $place }: what each student hands in must be "frame", "depth" or both
manifest-twice = { $place }: { $what } is in the manifest twice
manifest-unnameable = { $place }: "{ $identity }" cannot name a student's files
manifest-scene = { $place }: { $why }
class-student-unfit = no variant for { $identity }: { $why }
class-reseed-not-on-roster = --reseed { $identity }: nobody on the roster has that identity
class-counts = --times takes 1 … 8 and --distinct 1 … 1024
class-not-a-rule = "{ $name }" is not a wrong rule: { $names }
class-hand-in-list = --hand-in "{ $name }": give frame, depth or both, comma-separated
class-worksheet-title = { $name } · variant { $code }: { $width }×{ $height } raster, { $count ->
    [one] { $count } polygon
   *[other] { $count } polygons
  }
class-worksheet-hand-in = Hand in { $files }, keeping their first lines (variant { $code }).
class-worksheets-title = { $count ->
    [one] { $count } worksheet
   *[other] { $count } worksheets
  }
class-template-what = the { $buffer } after the last polygon, { $name }
class-template-how = top row first, one row a line, { $width } numbers a row separated by spaces; ? for a cell not worked out
class-hand-in-who = { $name } ({ $identity }), variant { $code }
class-hand-in-files = Hand in { $count ->
    [one] one file
   *[other] { $count } files
  }:
class-hand-in-file = { $file }: the { $buffer } after the last polygon
class-hand-in-format = Each: { $height } rows of { $width } whole numbers, top row first, separated by spaces; ? for a cell you did not work out. Start from the blank files beside this one and keep their first lines (variant { $code }).
class-hand-in-link = Try it in the browser, with questions: { $link }
class-summary = { $students ->
    [one] { $students } student
   *[other] { $students } students
  }, course seed { $seed }: a variant each of { $width }×{ $height } with { $polygons } polygons; each holds { $hard } exactly { $times ->
    [one] once
   *[other] { $times } times
  } and no other hard case, and each wrong rule ({ $rules }) differs from its key in { $distinct } cells or more
class-column-code = variant
class-column-apart = rules apart (fewest cells)
course-misnamed = { $file } is misnamed and was not graded: name it { $expected }
course-swapped = { $file } carries variant { $code }, which is { $owner }'s: swapped sheets?
course-two-files = two files answer the { $buffer }: { $files }; neither was graded
course-not-on-roster = { $file } was not graded: nobody on the roster is { $identity }
course-grade-summary = class { $class } against { $variants }: { $students ->
    [one] { $students } student
   *[other] { $students } students
  }; { $ok } ok, { $wrong } wrong, { $malformed } malformed, { $missing } missing an answer
course-by-kind = wrong cells by kind of case (students wrong there, of those whose scene holds it):
course-kind-line = { $case }: { $wrong } of { $holding }, { $cells ->
    [one] { $cells } cell
   *[other] { $cells } cells
  }
course-changes = { $count ->
    [0] scores changed since the earlier grading: none
    [one] scores changed since the earlier grading: { $count }
   *[other] scores changed since the earlier grading: { $count }
  }
course-change = { $student }: { $before } → { $after }: { $why }
course-change-added = not graded before
course-change-removed = no longer in the manifest
course-change-scene = their scene was changed in the manifest
course-change-files = their files changed
course-change-key = the same scene's key changed (another zsim)
course-change-rule = the same files and key, scored by another rule
course-feedback = { $student } (variant { $code }): score { $score } %, { $status }
platform-unreadable = { $file }: { $why }
platform-unknown-student = nobody on the class's roster submitted this: the platform named { $given }; ask the teacher to add you
platform-group = a group of students with different variants ({ $students }): each submits their own
platform-unknown-code = variant { $code } is nobody's in the class's manifest: ask the teacher
platform-needs-file = the platform's file that names the submission (--metadata for Gradescope, --data for PrairieLearn) was not given
platform-question-title = z-buffer by hand
platform-question-variant = Your variant:
usage-grade-variants-folder = grade --variants FILE takes one folder, the class's: zsim grade --variants DIR/variants.json CLASS
usage-grade-scene-and-class = grade takes the scene and the class folder: zsim grade SCENE CLASS (or --variants DIR/variants.json CLASS)
class-page-save = Save as the file to hand in
class-page-variant = Your variant: { $code } ({ $student })
class-page-score = score { $score } %
