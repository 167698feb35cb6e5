# zsim's words in English: checking and grading answers, gradebooks, exercises.
# Each message is one sentence or phrase; the facts arrive as arguments already
# written as numbers; spaces at either end are kept with string literals ({ " and " }).

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
# Course files (CS 418, BUET) and images: what is wrong with them.
case-line = line { $line }: { $problem }
case-unknown-command = unknown command "{ $command }"
case-keyword-problem = { $keyword }: { $problem }
exercise-notes-settings = exercise: seed { $seed }, { $width }×{ $height } raster, { $polygons } polygons, framebuffer { $frame_bits } bits, z-buffer { $depth_bits } bits (0 … { $max }), depth test { $test }
exercise-notes-asked = asked for: { $asked } (candidate { $candidate } of the seed's sequence)
exercise-notes-no-case = no particular case
exercise-notes-contains = it contains (found in the run's trace, first place each):
exercise-notes-none = none of the hard cases
exercise-notes-next = check an answer: zsim check { $path } --frame FRAME.txt --depth DEPTH.txt; grade a class: zsim grade { $path } CLASS_DIR
diagnosis = likely cause: { $what } (explains { $explained } of the { $wrong } wrong { $wrong ->
    [one] cell
   *[other] cells
})
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
gradescope-test = { $buffer } after { $after }
expect-not-states = "{ $text }" is not a list of states: write final, each, or polygon numbers from 1 separated by commas (1,3)
gradescope-missing = no file answers this: hand in { $file }
gradescope-score-rule = score: the share of the { $changed } cells the scene changes that are right ({ $right }), less one such share for each of the { $stray } cells written where the buffer keeps its cleared value; unanswered cells count for nothing
gradescope-ambiguous = { $files } all answer this: none is graded; hand in one
gradescope-unused = not graded (the assignment does not ask for them): { $files }
check-more-cells = … and { $count } more { $count ->
    [one] cell differs
   *[other] cells differ
}, not listed
grade-skipped = not graded: { $file } is not an answer file (NAME.frame.txt or NAME.depth.txt)
grade-skipped-near = not graded: { $file } looks like { $student }'s { $buffer }: name it { $name }
answer-grid-label = Type into a grid (starts from the cleared buffer)
answer-empty = the file is empty: it holds no row of the answer
answer-decimal-comma = line { $line }: { $text } has a decimal comma; each cell holds a whole number (cells are apart by spaces)
grade-mistakes-more = { $count } more { $count ->
    [one] cell
   *[other] cells
} that two or more students got wrong { $count ->
    [one] is
   *[other] are
} not listed
check-hint-other-buffer = this is exactly the { $other }, not the { $buffer }: was it handed in as the other buffer?
