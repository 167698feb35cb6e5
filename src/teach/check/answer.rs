//! Homework answers: reading a matrix as the book prints it, and finding the
//! cells that differ from zsim's.

use crate::observe::explain::Buffer;
use crate::words::Lang;

/// A matrix of a buffer's values, top row first.
pub type Matrix = Vec<Vec<u32>>;

/// An answer read from a file or typed in: its values, top row first, and
/// the cells the student did not work out (written `?` or `.`), which are
/// judged neither right nor wrong.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Answer {
    /// The values, top row first; an unanswered cell holds 0.
    pub rows: Matrix,
    /// Per cell in reading order, whether it was left unanswered; empty when
    /// every cell was answered.
    left: Vec<bool>,
}

impl Answer {
    /// An answer with every cell worked out.
    pub fn complete(rows: Matrix) -> Answer {
        Answer { rows, left: Vec::new() }
    }

    /// Whether the cell in row `row` (top first), column `x` was answered.
    pub fn answered(&self, row: usize, x: usize) -> bool {
        let width = self.rows.first().map_or(0, Vec::len);
        self.left.is_empty() || !self.left[row * width + x]
    }

    /// How many cells were left unanswered.
    pub fn unanswered(&self) -> usize {
        self.left.iter().filter(|left| **left).count()
    }

    /// Every answered cell's value with the expected one beside it:
    /// (row top first, column, answer, expected).
    pub fn cells<'a>(&'a self, expected: &'a Matrix) -> impl Iterator<Item = (usize, usize, u32, u32)> + 'a {
        self.rows.iter().zip(expected).enumerate().flat_map(move |(i, (row, right))| {
            row.iter()
                .zip(right)
                .enumerate()
                .filter(move |(x, _)| self.answered(i, *x))
                .map(move |(x, (&a, &e))| (i, x, a, e))
        })
    }
}

/// What an answer's cells may hold: `0 ..= max`, said as `a 2-bit framebuffer`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CellRange {
    /// The largest value a cell holds.
    pub max: u32,
    /// The buffer the answer is for.
    pub buffer: Buffer,
    /// Its bits.
    pub bits: u32,
}

impl CellRange {
    /// The buffer, for messages: `a 2-bit framebuffer`, `a 4-bit z-buffer`.
    fn words(self, lang: Lang) -> String {
        match self.buffer {
            Buffer::Frame => words!(lang, "answer-frame-range", bits = self.bits.to_string()),
            Buffer::Depth => words!(lang, "answer-depth-range", bits = self.bits.to_string()),
        }
    }
}

/// An answer that was not read, as facts: the first [`PROBLEMS_NAMED`]
/// problems, how many there are in all, and what the cells may hold; worded
/// where it is shown ([`AnswerRefused::message`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AnswerRefused {
    /// What the cells may hold.
    pub range: CellRange,
    /// The first problems, in the answer's order.
    pub named: Vec<AnswerProblem>,
    /// How many problems there are in all.
    pub count: usize,
}

/// One problem of an answer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum AnswerProblem {
    /// No row at all.
    Empty,
    /// A decimal comma (`9,5`) in a line that is not the raster's width.
    DecimalComma {
        /// The line, from 1.
        line: usize,
        /// The number as written.
        text: String,
    },
    /// A cell that is not a whole number.
    NotANumber {
        /// Where.
        at: CellAt,
        /// The cell as written.
        cell: String,
    },
    /// A value the buffer cannot hold.
    TooLarge {
        /// Where.
        at: CellAt,
        /// The value.
        value: u64,
    },
    /// A row of the wrong length.
    RowLength {
        /// The line, from 1.
        line: usize,
        /// How many values it has.
        count: usize,
        /// The raster's width.
        width: u32,
    },
    /// The wrong number of rows.
    RowCount {
        /// How many rows the answer has.
        count: usize,
        /// The raster's height.
        height: u32,
    },
}

/// Where a cell of an answer is: its line and place in the line (both from
/// 1), and the raster's cell (x, y) it stands for when the shape allows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CellAt {
    /// The line, from 1.
    pub line: usize,
    /// The value's place in the line, from 1.
    pub column: usize,
    /// The raster's cell, `(x, y)`.
    pub cell: Option<(usize, usize)>,
}

impl AnswerRefused {
    /// The problems named, separated by ` · `, then how many more there are, in `lang`.
    pub fn message(&self, lang: Lang) -> String {
        let mut text = self.named.iter().map(|problem| self.problem(lang, problem)).collect::<Vec<_>>().join(" · ");
        if self.count > self.named.len() {
            text.push_str(&words!(lang, "answer-more-problems", count = self.count - self.named.len()));
        }
        text
    }

    fn problem(&self, lang: Lang, problem: &AnswerProblem) -> String {
        let at = |at: &CellAt| {
            let (line, column) = (at.line.to_string(), at.column.to_string());
            match at.cell {
                Some((x, y)) => {
                    words!(lang, "answer-at-cell", line = line, column = column, x = x.to_string(), y = y.to_string())
                }
                None => words!(lang, "answer-at", line = line, column = column),
            }
        };
        let (buffer, max) = (self.range.words(lang), self.range.max.to_string());
        match problem {
            AnswerProblem::Empty => words!(lang, "answer-empty"),
            AnswerProblem::DecimalComma { line, text } => words!(
                lang,
                "answer-decimal-comma",
                line = line.to_string(),
                text = crate::words::printable(text).into_owned()
            ),
            AnswerProblem::NotANumber { at: place, cell } => words!(
                lang,
                "answer-not-a-number",
                at = at(place),
                cell = crate::words::token(lang, cell),
                buffer = buffer,
                max = max
            ),
            AnswerProblem::TooLarge { at: place, value } => {
                words!(lang, "answer-too-large", at = at(place), value = value.to_string(), buffer = buffer, max = max)
            }
            AnswerProblem::RowLength { line, count, width } => {
                words!(lang, "answer-row-length", line = line.to_string(), count = *count, width = width.to_string())
            }
            AnswerProblem::RowCount { count, height } => {
                words!(lang, "answer-row-count", count = *count, height = height.to_string())
            }
        }
    }
}

/// Reads an answer: integers separated by spaces or commas (`0, 1, 2` as
/// handed in is fine), top row first, one row a line, `?` or `.` for a cell
/// not worked out; blank lines and lines starting with `#` are ignored. Checks each value against `range` and the
/// shape against the raster; the error names the line, the column and the
/// raster cell, and says what was found: the first [`PROBLEMS_NAMED`]
/// problems, and how many there are.
pub fn parse_answer(text: &str, width: u32, height: u32, range: CellRange) -> Result<Answer, AnswerRefused> {
    let mut problems = Problems::default();
    let mut left = Vec::new();
    let lines = text
        .lines()
        .enumerate()
        .map(|(n, line)| (n + 1, line.trim()))
        .filter(|(_, line)| !line.is_empty() && !line.starts_with('#'));
    // The rows read, kept only while the answer has no problem (past one, only counted).
    let mut rows = Vec::new();
    let mut row_count = 0;
    for (row_index, (line_number, line)) in lines.enumerate() {
        row_count += 1;
        if problems.count > 0 {
            rows = Vec::new();
        }
        // The raster row this line stands for when the shape is right: the top row first.
        let y = (height as usize).checked_sub(row_index + 1);
        let cells: Vec<&str> = line.split([' ', '\t', ',']).filter(|cell| !cell.is_empty()).collect();
        // `9,5` (a decimal comma, as a Russian or Ukrainian student writes a number) would read as
        // two cells: said as what it is, first, not as values too large or a row too long.
        let comma = line.split_whitespace().find(|token| {
            token.split_once(',').is_some_and(|(a, b)| {
                let digits = |t: &str| !t.is_empty() && t.bytes().all(|c| c.is_ascii_digit());
                digits(a) && digits(b)
            })
        });
        if let (Some(token), true) = (comma, cells.len() != width as usize) {
            problems.push(|| AnswerProblem::DecimalComma { line: line_number, text: token.to_string() });
            continue;
        }
        let mut row = Vec::with_capacity(cells.len());
        for (column, cell) in cells.iter().enumerate() {
            let at = CellAt {
                line: line_number,
                column: column + 1,
                cell: y.filter(|_| column < width as usize).map(|y| (column, y)),
            };
            if matches!(*cell, "?" | ".") {
                // Marked only once the first is met: a complete answer holds no mask.
                if left.is_empty() {
                    left = vec![false; width as usize * height as usize];
                }
                if let Some(y) = y.filter(|_| column < width as usize) {
                    left[(height as usize - 1 - y) * width as usize + column] = true;
                }
                row.push(0);
                continue;
            }
            let Ok(value) = cell.parse::<u64>() else {
                problems.push(|| AnswerProblem::NotANumber { at, cell: cell.to_string() });
                row.push(0);
                continue;
            };
            if value > u64::from(range.max) {
                problems.push(|| AnswerProblem::TooLarge { at, value });
            }
            row.push(value.min(u64::from(range.max)) as u32);
        }
        if row.len() != width as usize {
            problems.push(|| AnswerProblem::RowLength { line: line_number, count: row.len(), width });
        }
        if problems.count == 0 {
            rows.push(row);
        }
    }
    if row_count == 0 {
        return Err(AnswerRefused { range, named: vec![AnswerProblem::Empty], count: 1 });
    }
    if row_count != height as usize {
        problems.push(|| AnswerProblem::RowCount { count: row_count, height });
    }
    if problems.count == 0 {
        return Ok(Answer { rows, left });
    }
    Err(AnswerRefused { range, named: problems.named, count: problems.count })
}

/// An answer file's problems: the first [`PROBLEMS_NAMED`] kept, the rest
/// only counted (a file of garbage costs what its cells cost, not a problem each).
#[derive(Default)]
struct Problems {
    named: Vec<AnswerProblem>,
    count: usize,
}

impl Problems {
    /// One more problem, made by `problem` only if it is among those named.
    fn push(&mut self, problem: impl FnOnce() -> AnswerProblem) {
        if self.count < PROBLEMS_NAMED {
            self.named.push(problem());
        }
        self.count += 1;
    }
}

/// How many of an answer file's problems a message names.
pub const PROBLEMS_NAMED: usize = 3;

/// Another way an answer may have been written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Misreading {
    /// The bottom row first (upside down).
    BottomRowFirst,
    /// Column by column: rows and columns swapped.
    Transposed,
}

impl Misreading {
    /// How it was written, in words: `bottom row first`.
    pub fn words(self, lang: Lang) -> String {
        match self {
            Misreading::BottomRowFirst => words!(lang, "misreading-upside-down"),
            Misreading::Transposed => words!(lang, "misreading-transposed"),
        }
    }
}

/// The largest raster, in cells, on which a wrong answer is looked at for
/// more than its wrong cells (a misreading here, the likely misconception in
/// the diagnosis): 1024 × 1024. Both hold several more buffers of the
/// raster at once, so they are for homework-sized scenes; a larger answer is
/// checked cell by cell all the same.
pub const HINTED_CELLS: u64 = 1 << 20;

/// When an answer that differs would match, or nearly, read another way:
/// bottom row first (upside down) or with rows and columns swapped. Returns
/// how it was written and how many cells differ when read that way; not
/// looked for past [`HINTED_CELLS`] (two more copies of the answer), nor in
/// an answer with cells left unanswered (which cells were left is itself
/// written one way).
pub fn misreading(answer: &Answer, expected: &Matrix) -> Option<(Misreading, usize)> {
    if answer.unanswered() > 0 {
        return None;
    }
    let answer = &answer.rows;
    // A right answer was read right.
    let cells: usize = answer.iter().map(Vec::len).sum();
    if cells as u64 > HINTED_CELLS {
        return None;
    }
    let differing = compare(answer, expected).len();
    if differing == 0 {
        return None;
    }
    let upside_down: Matrix = answer.iter().rev().cloned().collect();
    let mut readings = vec![(Misreading::BottomRowFirst, compare(&upside_down, expected).len())];
    if answer.len() == answer.first().map_or(0, Vec::len) {
        let transposed: Matrix = (0..answer.len()).map(|c| answer.iter().map(|row| row[c]).collect()).collect();
        readings.push((Misreading::Transposed, compare(&transposed, expected).len()));
    }
    // Worth saying when that reading leaves at most a quarter of the differences.
    readings.into_iter().filter(|(_, count)| *count * 4 <= differing).min_by_key(|(_, count)| *count)
}

/// One cell where the answer differs from zsim.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mismatch {
    /// Column.
    pub x: u32,
    /// Row (0 at the bottom).
    pub y: u32,
    /// The answer's value.
    pub answer: u32,
    /// zsim's value.
    pub expected: u32,
}

/// The answered cells where `answer` differs from `expected` (top row
/// first), in reading order: top row first, left to right.
pub fn compare_answer(answer: &Answer, expected: &Matrix) -> Vec<Mismatch> {
    let height = expected.len() as u32;
    answer
        .cells(expected)
        .filter(|(_, _, a, e)| a != e)
        .map(|(i, x, answer, expected)| Mismatch { x: x as u32, y: crate::raster::row_y(height, i), answer, expected })
        .collect()
}

/// The cells where `answer` differs from `expected` (both top row first),
/// in reading order: top row first, left to right.
pub fn compare(answer: &Matrix, expected: &Matrix) -> Vec<Mismatch> {
    let height = expected.len() as u32;
    let mut mismatches = Vec::new();
    for (i, (answer_row, expected_row)) in answer.iter().zip(expected).enumerate() {
        for (x, (&a, &e)) in answer_row.iter().zip(expected_row).enumerate() {
            if a != e {
                mismatches.push(Mismatch { x: x as u32, y: crate::raster::row_y(height, i), answer: a, expected: e });
            }
        }
    }
    mismatches
}

#[cfg(test)]
mod tests {
    use super::*;

    const FRAME: CellRange = CellRange { max: 3, buffer: Buffer::Frame, bits: 2 };

    /// The answer read, or its refusal worded in English.
    fn parse_answer(text: &str, width: u32, height: u32, range: CellRange) -> Result<Answer, String> {
        super::parse_answer(text, width, height, range).map_err(|refused| refused.message(Lang::En))
    }

    #[test]
    fn comments_blank_lines_and_commas_are_taken() {
        let text = "# my answer\n\n1 2\n\n3, 0\n";
        assert_eq!(parse_answer(text, 2, 2, FRAME).unwrap().rows, vec![vec![1, 2], vec![3, 0]]);
        assert_eq!(parse_answer("1,2\n3 ,0\n", 2, 2, FRAME).unwrap().rows, vec![vec![1, 2], vec![3, 0]]);
    }

    #[test]
    fn wrong_shapes_say_what_was_found() {
        assert_eq!(parse_answer("1 2\n3 0\n1 1\n", 2, 2, FRAME).unwrap_err(), "3 rows; the raster has 2");
        assert_eq!(parse_answer("1 2\n3\n", 2, 2, FRAME).unwrap_err(), "line 2: 1 value; the raster is 2 wide");
        assert_eq!(
            parse_answer("1 x\n", 2, 1, FRAME).unwrap_err(),
            "line 1, value 2 (x = 1, y = 0): \"x\" is not a whole number (a 2-bit framebuffer holds 0 … 3)"
        );
    }

    /// Found by a new user: a 7 in a 2-bit framebuffer was an ordinary wrong cell.
    #[test]
    fn a_value_the_buffer_cannot_hold_is_named_at_its_cell() {
        assert_eq!(
            parse_answer("0 0\n0 7\n", 2, 2, FRAME).unwrap_err(),
            "line 2, value 2 (x = 1, y = 0): 7 does not fit a 2-bit framebuffer (0 … 3)"
        );
    }

    #[test]
    fn answers_written_upside_down_or_transposed_are_recognised() {
        let expected = vec![vec![1, 1, 0], vec![1, 0, 0], vec![0, 0, 0]];
        let upside_down: Matrix = expected.iter().rev().cloned().collect();
        let read = |m: &Matrix| Answer::complete(m.clone());
        assert_eq!(misreading(&read(&upside_down), &expected), Some((Misreading::BottomRowFirst, 0)));
        let transposed = vec![vec![1, 1, 0], vec![1, 0, 0], vec![0, 0, 0]];
        let other = vec![vec![0, 1, 1], vec![0, 0, 1], vec![0, 0, 0]];
        let transposed_other: Matrix = (0..3).map(|c| other.iter().map(|row| row[c]).collect()).collect();
        assert_eq!(misreading(&read(&transposed_other), &other), Some((Misreading::Transposed, 0)));
        // A plain mistake is not a misreading.
        let mut one_wrong = transposed.clone();
        one_wrong[0][0] = 2;
        assert_eq!(misreading(&read(&one_wrong), &expected), None);
    }

    /// Asked for by a student who worked out a few rows: `?` and `.` mark
    /// the cells left, which are neither right nor wrong.
    #[test]
    fn question_marks_and_dots_leave_cells_unanswered() {
        let answer = parse_answer("? 1\n. 2\n", 2, 2, FRAME).unwrap();
        assert_eq!(answer.unanswered(), 2);
        assert_eq!((answer.answered(0, 0), answer.answered(0, 1), answer.answered(1, 0)), (false, true, false));
        let expected = vec![vec![3, 1], vec![0, 0]];
        assert_eq!(compare_answer(&answer, &expected), vec![Mismatch { x: 1, y: 0, answer: 2, expected: 0 }]);
        assert_eq!(parse_answer("1 2\n3 0\n", 2, 2, FRAME).unwrap().unanswered(), 0);
        // A question mark is a cell like any other: the row still needs its width.
        assert_eq!(parse_answer("?\n1 1\n", 2, 2, FRAME).unwrap_err(), "line 1: 1 value; the raster is 2 wide");
    }

    /// An answer that is not read is refused as facts, read with no
    /// language: each problem where it is, with what was found, the first
    /// three kept and all of them counted.
    #[test]
    fn a_refused_answer_is_facts() {
        let refused = super::parse_answer("1 x\n0 9 9 9\n1,5\n2\n", 2, 2, FRAME).unwrap_err();
        let at = |line, column, cell| CellAt { line, column, cell };
        assert_eq!(
            refused.named,
            vec![
                AnswerProblem::NotANumber { at: at(1, 2, Some((1, 1))), cell: "x".into() },
                AnswerProblem::TooLarge { at: at(2, 2, Some((1, 0))), value: 9 },
                AnswerProblem::TooLarge { at: at(2, 3, None), value: 9 },
            ]
        );
        // Past those three: the third 9, the row too long, the 5 of `1,5`, the short row, four rows.
        assert_eq!(refused.count, 8);
        assert!(refused.message(Lang::En).ends_with(" · and 5 more problems"), "{}", refused.message(Lang::En));
        assert_eq!(super::parse_answer("# nothing\n", 2, 2, FRAME).unwrap_err().named, vec![AnswerProblem::Empty]);
    }

    #[test]
    fn mismatches_name_cells_with_y_up() {
        let expected = vec![vec![0, 0], vec![0, 5]];
        let answer = vec![vec![0, 1], vec![0, 5]];
        assert_eq!(compare(&answer, &expected), vec![Mismatch { x: 1, y: 1, answer: 1, expected: 0 }]);
    }
}
