//! Grading a class: each student's answers (a framebuffer and/or a z-buffer
//! matrix, as `zsim check` reads them) against zsim's, one row a student,
//! and the cells most students got wrong. Data only; the CLI reads the
//! folder and prints.

use rayon::prelude::*;

use crate::numbers::{Q, decimal};
use crate::observe::check::{Matrix, compare};
use crate::observe::explain::Buffer;
use crate::teach::diagnose::{Diagnoser, Diagnosis};

/// One student's answer for one buffer, as found in the class folder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Handed {
    /// No file for this buffer.
    Missing,
    /// A file that is not a matrix of the raster's shape: why, naming the file.
    Malformed(String),
    /// The matrix read.
    Matrix(Matrix),
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
    /// A file is not a matrix of the raster's shape: which and why.
    Malformed(String),
    /// A buffer the class hands in has no file from this student: which.
    Missing(String),
}

impl std::fmt::Display for Status {
    /// `ok`, `wrong`, `malformed: <why>`, `missing: <what>`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Status::Ok => f.write_str("ok"),
            Status::Wrong => f.write_str("wrong"),
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
    /// Right cells over all cells the class hands in (a missing or malformed
    /// answer has none right), as a fraction from 0 to 1.
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

/// Grades every submission against the expected matrices (one per buffer
/// the class hands in, top row first); rows in the order of `submissions`.
/// Also returns each student's wrong cells per buffer, for the common
/// mistakes. With a `diagnoser`, each wrong answer's likely misconception is named.
pub fn grade(
    submissions: &[Submission],
    expected: &[(Buffer, Matrix)],
    diagnoser: Option<&Diagnoser>,
) -> Vec<(Grade, Vec<WrongCells>)> {
    let total: usize = expected.iter().map(|(_, m)| m.iter().map(Vec::len).sum::<usize>()).sum();
    // Students in parallel, rows in their order.
    submissions
        .par_iter()
        .map(|submission| {
            let (mut frame_wrong, mut depth_wrong, mut right) = (None, None, 0usize);
            let (mut malformed, mut missing, mut wrong) = (None, None, false);
            let mut cells = Vec::new();
            let mut read: [Option<&Matrix>; 2] = [None, None];
            for (buffer, matrix) in expected {
                let handed = submission.answers.iter().find(|(b, _)| b == buffer).map(|(_, h)| h);
                let name = format!("{}.{}.txt", submission.student, file_kind(*buffer));
                match handed.unwrap_or(&Handed::Missing) {
                    Handed::Missing => {
                        missing.get_or_insert(name);
                    }
                    Handed::Malformed(why) => {
                        malformed.get_or_insert(why.clone());
                    }
                    Handed::Matrix(answer) => {
                        read[usize::from(*buffer == Buffer::Depth)] = Some(answer);
                        let mismatches = compare(answer, matrix);
                        let size: usize = matrix.iter().map(Vec::len).sum();
                        right += size - mismatches.len();
                        wrong |= !mismatches.is_empty();
                        match buffer {
                            Buffer::Frame => frame_wrong = Some(mismatches.len()),
                            Buffer::Depth => depth_wrong = Some(mismatches.len()),
                        }
                        cells.push(WrongCells { buffer: *buffer, cells: mismatches });
                    }
                }
            }
            let status = match (malformed, missing, wrong) {
                (Some(why), _, _) => Status::Malformed(why),
                (None, Some(what), _) => Status::Missing(what),
                (None, None, true) => Status::Wrong,
                (None, None, false) => Status::Ok,
            };
            let score = if total == 0 { Q::from_integer(0) } else { Q::new(right as i128, total as i128) };
            let misconception = diagnoser.filter(|_| wrong).and_then(|d| d.diagnose(read[0], read[1]));
            let student = submission.student.clone();
            (Grade { student, frame_wrong, depth_wrong, score, status, misconception }, cells)
        })
        .collect()
}

/// A student's wrong cells in one buffer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WrongCells {
    /// Which buffer.
    pub buffer: Buffer,
    /// The cells, in reading order.
    pub cells: Vec<crate::observe::check::Mismatch>,
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

    #[test]
    fn rows_tell_ok_wrong_malformed_and_missing_with_scores() {
        let expected = vec![(Buffer::Frame, vec![vec![1, 0], vec![1, 1]])];
        let class = [
            submission("ana", Handed::Matrix(vec![vec![1, 0], vec![1, 1]])),
            submission("bo", Handed::Matrix(vec![vec![1, 1], vec![1, 1]])),
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
                ("bo".into(), Some(1), "75.0".into(), "wrong".into()),
                ("cy".into(), None, "0.0".into(), "malformed: cy.frame.txt: 2 rows; the raster has 3".into()),
                ("di".into(), None, "0.0".into(), "missing: di.frame.txt".into()),
            ]
        );
    }
}
