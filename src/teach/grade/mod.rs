//! Grading a class: each student's answers (a framebuffer and/or a z-buffer
//! matrix, as `zsim check` reads them) against zsim's, one row a student,
//! and the cells most students got wrong. Data only; the CLI reads the
//! folder and prints.

pub mod class;
pub mod gradebooks;
pub mod gradescope;

use rayon::prelude::*;

use crate::numbers::{Q, decimal};
use crate::observe::explain::Buffer;
use crate::teach::check::answer::{Answer, Matrix, compare_answer};
use crate::teach::check::diagnose::{Diagnoser, Diagnosis, Misconception};
use crate::words::Lang;

/// The right answer for one buffer a class hands in: its matrix (top row
/// first) and the value its cells hold before any polygon is drawn (the
/// background, the clear depth), which the score needs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Key {
    /// Which buffer.
    pub buffer: Buffer,
    /// The right matrix, top row first.
    pub matrix: Matrix,
    /// The cleared value.
    pub cleared: u32,
}

/// One student's answer for one buffer, as found in the class folder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Handed {
    /// No file for this buffer.
    Missing,
    /// A file that is not a matrix of the raster's shape: why, naming the file.
    Malformed(String),
    /// The answer read.
    Matrix(Answer),
}

/// One student's submission: a name (the file names' stem) and an answer per
/// buffer the class hands in.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Submission {
    /// The student's name.
    pub student: String,
    /// Per buffer handed in by anyone in the class: this student's answer.
    pub answers: Vec<(Buffer, Handed)>,
}

/// What a student's row says overall. Ordered by precedence: a malformed
/// file outweighs a missing one, which outweighs wrong cells.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Status {
    /// Every cell of every answer right.
    Ok,
    /// Some cells wrong.
    Wrong,
    /// No answered cell wrong, but these many left unanswered (`?`, `.`).
    Incomplete(usize),
    /// A file is not a matrix of the raster's shape: which and why.
    Malformed(String),
    /// A buffer the class hands in has no file from this student: which.
    Missing(String),
}

impl Status {
    /// The status in the reader's language (CSV and JSON keep the English
    /// words of its `Display`).
    pub fn words(&self, lang: Lang) -> String {
        match self {
            Status::Ok => words!(lang, "grade-status-ok"),
            Status::Wrong => words!(lang, "grade-status-wrong"),
            Status::Incomplete(count) => words!(lang, "grade-status-incomplete", count = *count),
            Status::Malformed(why) => words!(lang, "grade-status-malformed", why = why),
            Status::Missing(what) => words!(lang, "grade-status-missing", what = what),
        }
    }
}

impl std::fmt::Display for Status {
    /// `ok`, `wrong`, `incomplete: <n> unanswered`, `malformed: <why>`, `missing: <what>`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Status::Ok => f.write_str("ok"),
            Status::Wrong => f.write_str("wrong"),
            Status::Incomplete(count) => write!(f, "incomplete: {count} unanswered"),
            Status::Malformed(why) => write!(f, "malformed: {why}"),
            Status::Missing(what) => write!(f, "missing: {what}"),
        }
    }
}

/// One student's row.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Grade {
    /// The student's name.
    pub student: String,
    /// Wrong framebuffer cells, when a framebuffer answer was read.
    pub frame_wrong: Option<usize>,
    /// Wrong z-buffer cells, when a z-buffer answer was read.
    pub depth_wrong: Option<usize>,
    /// Cells left unanswered (`?`, `.`) in the answers read.
    pub unanswered: usize,
    /// The score, from 0 to 1, by [`score`]'s rule.
    pub score: Q,
    /// The verdict.
    pub status: Status,
    /// The wrong rule that explains the wrong cells, when one does.
    pub misconception: Option<Diagnosis>,
}

impl Grade {
    /// The score in percent with one decimal, rounded half up (`96.9`).
    pub fn percent(&self) -> String {
        decimal(self.score * Q::from_integer(100), 1)
    }
}

/// A cell that several students got wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CommonMistake {
    /// Which buffer.
    pub buffer: Buffer,
    /// Column.
    pub x: u32,
    /// Row (0 at the bottom).
    pub y: u32,
    /// The right value.
    pub right: u32,
    /// The students who got it wrong, in name order.
    pub students: Vec<String>,
    /// The wrong values given, each with how many gave it, most given first.
    pub answers: Vec<(u32, usize)>,
}

/// The value `buffer`'s cells hold before any polygon is drawn, as an
/// answer matrix holds it: the background, or the clear depth's level (0
/// when the z-buffer is cleared to something no level holds, as +∞).
pub fn cleared(scene: &crate::scene::Scene, buffer: Buffer) -> u32 {
    match buffer {
        Buffer::Frame => scene.background,
        Buffer::Depth => scene.clear_depth.level().unwrap_or(0),
    }
}

/// What one answer earns toward [`score`]: the cells the scene changes
/// (the key differs from the cleared value there), how many of them the
/// answer has right, and how many cells it writes where the key keeps the
/// cleared value. Unanswered cells are neither right nor written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Earned {
    /// Cells the scene changes.
    pub changed: usize,
    /// Of those, the cells answered right.
    pub right: usize,
    /// Cells written with something other than the cleared value where the key keeps it.
    pub stray: usize,
    /// All cells, and all cells answered right (for a scene that changes nothing).
    pub cells: usize,
    /// All cells answered right.
    pub all_right: usize,
}

impl Earned {
    /// What `answer` (or no answer: `None`) earns against the right
    /// matrix `key` whose cells were `cleared` before any polygon.
    pub fn of(answer: Option<&Answer>, key: &Matrix, cleared: u32) -> Earned {
        let changed = key.iter().flatten().filter(|v| **v != cleared).count();
        let cells = key.iter().map(Vec::len).sum();
        let mut earned = Earned { changed, cells, ..Earned::default() };
        for (_, _, a, e) in answer.into_iter().flat_map(|answer| answer.cells(key)) {
            earned.right += usize::from(a == e && e != cleared);
            earned.stray += usize::from(e == cleared && a != e);
            earned.all_right += usize::from(a == e);
        }
        earned
    }

    fn add(self, other: Earned) -> Earned {
        Earned {
            changed: self.changed + other.changed,
            right: self.right + other.right,
            stray: self.stray + other.stray,
            cells: self.cells + other.cells,
            all_right: self.all_right + other.all_right,
        }
    }
}

/// The score of a student's answers, from 0 to 1: the share of the cells
/// the scene changes that are right, less one such share for every cell
/// written where the key keeps the cleared value, and never below 0. A
/// blank sheet (every cell the cleared value) scores 0, a right one 1;
/// cells left unanswered earn nothing and cost nothing; a missing or
/// malformed answer earns nothing for the cells its buffer changes. When
/// the scene changes no cell, the share of all cells right.
pub fn score(earned: &[Earned]) -> Q {
    let total = earned.iter().copied().fold(Earned::default(), Earned::add);
    if total.changed == 0 {
        return if total.cells == 0 {
            Q::from_integer(0)
        } else {
            Q::new(total.all_right as i128, total.cells as i128)
        };
    }
    let net = total.right.saturating_sub(total.stray);
    Q::new(net as i128, total.changed as i128)
}

/// Grades every submission against the keys (one per buffer the class
/// hands in); rows in the order of `submissions`. Also returns each
/// student's wrong cells per buffer, for the common mistakes. With a
/// `diagnoser`, each wrong answer's likely misconception is named.
pub fn grade(submissions: &[Submission], keys: &[Key], diagnoser: Option<&Diagnoser>) -> Vec<(Grade, Vec<WrongCells>)> {
    // Students in parallel, rows in their order.
    submissions
        .par_iter()
        .map(|submission| {
            let (mut frame_wrong, mut depth_wrong, mut unanswered) = (None, None, 0);
            let (mut malformed, mut missing, mut wrong) = (None, None, false);
            let (mut cells, mut earned) = (Vec::new(), Vec::new());
            let mut read: [Option<&Answer>; 2] = [None, None];
            for key in keys {
                let buffer = key.buffer;
                let handed = submission.answers.iter().find(|(b, _)| *b == buffer).map(|(_, h)| h);
                let name = format!("{}.{}.txt", submission.student, file_kind(buffer));
                let answer = match handed.unwrap_or(&Handed::Missing) {
                    Handed::Missing => {
                        missing.get_or_insert(name);
                        None
                    }
                    Handed::Malformed(why) => {
                        malformed.get_or_insert(why.clone());
                        None
                    }
                    Handed::Matrix(answer) => {
                        read[usize::from(buffer == Buffer::Depth)] = Some(answer);
                        let mismatches = compare_answer(answer, &key.matrix);
                        wrong |= !mismatches.is_empty();
                        unanswered += answer.unanswered();
                        match buffer {
                            Buffer::Frame => frame_wrong = Some(mismatches.len()),
                            Buffer::Depth => depth_wrong = Some(mismatches.len()),
                        }
                        cells.push(WrongCells { buffer, cells: mismatches });
                        Some(answer)
                    }
                };
                earned.push(Earned::of(answer, &key.matrix, key.cleared));
            }
            let status = match (malformed, missing, wrong) {
                (Some(why), _, _) => Status::Malformed(why),
                (None, Some(what), _) => Status::Missing(what),
                (None, None, true) => Status::Wrong,
                (None, None, false) if unanswered > 0 => Status::Incomplete(unanswered),
                (None, None, false) => Status::Ok,
            };
            let misconception = diagnoser.filter(|_| wrong).and_then(|d| d.diagnose(read[0], read[1]));
            let student = submission.student.clone();
            let score = score(&earned);
            (Grade { student, frame_wrong, depth_wrong, unanswered, score, status, misconception }, cells)
        })
        .collect()
}

/// The misconceptions named for the students of `rows`, each with how many
/// students it was named for, most first (equal counts in the order `Misconception` declares them).
pub fn causes(rows: &[&Grade]) -> Vec<(Misconception, usize)> {
    let mut counts: Vec<(Misconception, usize)> = Vec::new();
    for misconception in rows.iter().filter_map(|g| g.misconception.map(|d| d.misconception)) {
        match counts.iter_mut().find(|(m, _)| *m == misconception) {
            Some((_, count)) => *count += 1,
            None => counts.push((misconception, 1)),
        }
    }
    counts.sort_by_key(|(m, count)| (std::cmp::Reverse(*count), *m));
    counts
}

/// A student's wrong cells in one buffer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WrongCells {
    /// Which buffer.
    pub buffer: Buffer,
    /// The cells, in reading order.
    pub cells: Vec<crate::teach::check::answer::Mismatch>,
}
/// The middle of an answer file's name: `NAME.frame.txt`, `NAME.depth.txt`.
pub fn file_kind(buffer: Buffer) -> &'static str {
    match buffer {
        Buffer::Frame => "frame",
        Buffer::Depth => "depth",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn submission(student: &str, frame: Handed) -> Submission {
        Submission { student: student.into(), answers: vec![(Buffer::Frame, frame)] }
    }

    fn key(matrix: Matrix) -> Vec<Key> {
        vec![Key { buffer: Buffer::Frame, matrix, cleared: 0 }]
    }

    fn answer(rows: Matrix) -> Handed {
        Handed::Matrix(Answer::complete(rows))
    }

    #[test]
    fn rows_tell_ok_wrong_malformed_and_missing_with_scores() {
        let expected = key(vec![vec![1, 0], vec![1, 1]]);
        let class = [
            submission("ana", answer(vec![vec![1, 0], vec![1, 1]])),
            submission("bo", answer(vec![vec![1, 1], vec![1, 1]])),
            submission("cy", Handed::Malformed("cy.frame.txt: 2 rows; the raster has 3".into())),
            submission("di", Handed::Missing),
        ];
        let rows: Vec<Grade> = grade(&class, &expected, None).into_iter().map(|(g, _)| g).collect();
        let summary: Vec<(String, Option<usize>, String, String)> =
            rows.iter().map(|g| (g.student.clone(), g.frame_wrong, g.percent(), g.status.to_string())).collect();
        assert_eq!(
            summary,
            vec![
                ("ana".into(), Some(0), "100.0".into(), "ok".into()),
                // Three changed cells right, one written where the key keeps the background: (3 − 1) / 3.
                ("bo".into(), Some(1), "66.7".into(), "wrong".into()),
                ("cy".into(), None, "0.0".into(), "malformed: cy.frame.txt: 2 rows; the raster has 3".into()),
                ("di".into(), None, "0.0".into(), "missing: di.frame.txt".into()),
            ]
        );
    }

    /// Found by a teacher: a sheet handed in blank scored 67–75 % and was
    /// labelled "only the last polygon drawn".
    #[test]
    fn a_blank_sheet_scores_nothing() {
        let expected = key(vec![vec![0, 2, 2, 0], vec![0, 2, 1, 0], vec![0, 0, 0, 0]]);
        let blank = vec![vec![0; 4]; 3];
        let rows = grade(&[submission("blank", answer(blank))], &expected, None);
        assert_eq!((rows[0].0.percent(), rows[0].0.frame_wrong), ("0.0".to_string(), Some(4)));
        // Everything drawn everywhere: the 4 changed cells' share less 8 stray cells, never below 0.
        let everywhere = vec![vec![2; 4]; 3];
        assert_eq!(grade(&[submission("all", answer(everywhere))], &expected, None)[0].0.percent(), "0.0");
    }

    /// Asked for by a student who worked out a few rows: `?` cells earn
    /// nothing and cost nothing, and the status says how many were left.
    #[test]
    fn unanswered_cells_earn_nothing_and_are_counted() {
        let expected = key(vec![vec![0, 2, 2, 0], vec![0, 2, 1, 0]]);
        let text = "0 2 2 0\n? ? ? ?\n";
        let range = crate::teach::check::answer::CellRange { max: 3, buffer: Buffer::Frame, bits: 2 };
        let half = crate::teach::check::answer::parse_answer(text, 4, 2, range).unwrap();
        let (row, _) = grade(&[submission("half", Handed::Matrix(half))], &expected, None).remove(0);
        assert_eq!(
            (row.percent(), row.frame_wrong, row.unanswered, row.status.to_string()),
            ("50.0".into(), Some(0), 4, "incomplete: 4 unanswered".into())
        );
    }
}
