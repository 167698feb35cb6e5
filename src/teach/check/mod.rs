//! Checking homework: a student's answer files read for a scene's buffers,
//! the answers of a submission folder found, and every wrong cell of an
//! answer explained, as facts that `check`, `grade`'s feedback and the
//! Gradescope results all render.

pub mod answer;
pub mod diagnose;

use std::path::{Path, PathBuf};

use crate::door::{Links, read_text_with};
use crate::effects::arith::{self, Arith};
use crate::error::{Error, Refusal};
use crate::observe::explain::{Buffer, polygon_after, why};
use crate::observe::trace::PixelWatcher;
use crate::scene::Scene;
use crate::simulate::events::Unobserved;
use crate::simulate::simulation::Simulation;
use crate::words::Lang;
use crate::words::printable;
pub use answer::{
    Answer, AnswerProblem, AnswerRefused, CellAt, CellRange, Matrix, Mismatch, Misreading, compare, compare_answer,
    misreading, parse_answer,
};

/// Reads an answer file for one of `scene`'s buffers: a matrix as the book
/// prints it; a symbolic link is followed only where `links` says so.
pub fn read_answer(path: &Path, scene: &Scene, buffer: Buffer, links: Links) -> Result<Answer, Error> {
    let text = read_text_with(path, links)?;
    answer_from_text(&text, scene, buffer)
        .map_err(|refused| AnswerFileRefused { path: path.to_owned(), refused }.into())
}

/// An answer file that was not read: its path and its problems.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AnswerFileRefused {
    /// The answer file.
    pub path: PathBuf,
    /// Why it was not read.
    pub refused: AnswerRefused,
}

impl Refusal for AnswerFileRefused {
    fn message(&self, lang: Lang) -> String {
        format!("{}: {}", crate::words::shown_path(&self.path), self.refused.message(lang))
    }
}

/// An answer for one of `scene`'s buffers read from `text` (a file's, or one
/// typed into the page); `Err` says why not, as facts.
pub fn answer_from_text(text: &str, scene: &Scene, buffer: Buffer) -> Result<Answer, AnswerRefused> {
    let range = match buffer {
        Buffer::Frame => {
            CellRange { max: crate::scene::max_for_bits(scene.frame_bits), buffer, bits: scene.frame_bits }
        }
        Buffer::Depth => CellRange { max: scene.depth_max(), buffer, bits: scene.depth_bits },
    };
    parse_answer(text, scene.width, scene.height, range)
}

/// An error about a student's answer file as the student and the class
/// table show it: the file's name where the message has its path (where the
/// class folder or the autograder keeps it stretches tables and is nobody's
/// business), control characters escaped.
pub fn as_the_student_sees(lang: Lang, error: &Error, path: &Path) -> String {
    printable(&error.message(lang).replace(&crate::words::shown_path(path), &crate::words::shown_name(path)))
        .into_owned()
}

/// The answer files for the state after one polygon.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct State {
    /// The polygon (0-based) the answers are the state after.
    pub after: usize,
    /// Each buffer's file, the framebuffer's first.
    pub files: Vec<(Buffer, PathBuf)>,
}

/// The state and buffer a submission's file name answers for: `frame.txt`
/// and `depth.txt` after the last polygon, `after-N.frame.txt` and
/// `after-N.depth.txt` after polygon N (ASCII digits, so `after-01` is
/// `after-1`, and `after-K` for the last polygon K is `frame.txt`'s state);
/// `None` for any other name.
pub fn answer_of(name: &str, polygons: usize) -> Option<(usize, Buffer)> {
    let (after, kind) = match name.strip_prefix("after-").and_then(|rest| rest.split_once('.')) {
        Some((number, kind)) => {
            if number.is_empty() || !number.bytes().all(|b| b.is_ascii_digit()) {
                return None;
            }
            let n: usize = number.trim_start_matches('0').parse().ok().filter(|n| (1..=polygons).contains(n))?;
            (n - 1, kind)
        }
        None => (polygons.checked_sub(1)?, name),
    };
    let buffer = match kind {
        "frame.txt" => Buffer::Frame,
        "depth.txt" => Buffer::Depth,
        _ => return None,
    };
    Some((after, buffer))
}

/// The files of a submission folder, as names: those that are not UTF-8
/// shown with U+FFFD, so they are never mistaken for a right name.
fn folder_names(folder: &Path) -> Result<Vec<String>, Error> {
    let read_error = |source| Error::Read { path: folder.to_owned(), source };
    let mut names: Vec<String> = std::fs::read_dir(folder)
        .map_err(read_error)?
        .filter_map(|e| Some(e.ok()?.file_name().to_string_lossy().into_owned()))
        .collect();
    names.sort();
    Ok(names)
}

/// A check refused: each with the facts its message states.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CheckRefused {
    /// A scene without polygons: no state to check against.
    NoPolygons {
        /// The scene file.
        path: PathBuf,
    },
    /// A scene keeping exact depths, whose z-buffer has no integer matrix to check.
    ExactDepths {
        /// The scene file.
        path: PathBuf,
    },
    /// A submission folder that holds no answer file.
    NoSubmission {
        /// The folder.
        folder: PathBuf,
    },
    /// Two files of a submission answering for one buffer of one state.
    SameAnswerTwice {
        /// The submission folder.
        folder: PathBuf,
        /// The two files, by name.
        files: Vec<String>,
    },
}

impl Refusal for CheckRefused {
    fn message(&self, lang: Lang) -> String {
        let path = |p: &PathBuf| crate::words::shown_path(p);
        match self {
            CheckRefused::NoPolygons { path: p } => words!(lang, "usage-no-polygons-check", path = path(p)),
            CheckRefused::ExactDepths { path: p } => words!(lang, "usage-exact-depths-check", path = path(p)),
            CheckRefused::NoSubmission { folder } => words!(lang, "usage-no-submission", folder = path(folder)),
            CheckRefused::SameAnswerTwice { folder, files } => {
                let files: Vec<String> = files.iter().map(|file| format!("\"{file}\"")).collect();
                words!(lang, "usage-same-answer-twice", path = path(folder), files = files.join(", "))
            }
        }
    }
}

/// The answer files of a submission folder, grouped by the polygon they are
/// the state after ([`answer_of`] reads the names); other files are passed
/// over. Two files answering for one buffer of one state (`after-1.frame.txt`
/// and `after-01.frame.txt`) are refused by name. Symbolic links are not
/// followed.
pub fn submission_files(folder: &Path, scene: &Scene) -> Result<Vec<State>, Error> {
    let mut states: Vec<State> = Vec::new();
    for name in folder_names(folder)? {
        let Some((after, buffer)) = answer_of(&name, scene.polygons.len()) else { continue };
        let path = folder.join(&name);
        match states.iter_mut().find(|state| state.after == after) {
            Some(state) => {
                if let Some((_, other)) = state.files.iter().find(|(b, _)| *b == buffer) {
                    let files = vec![crate::words::shown_name(other), printable(&name).into_owned()];
                    return Err(CheckRefused::SameAnswerTwice { folder: folder.to_owned(), files }.into());
                }
                state.files.push((buffer, path));
            }
            None => states.push(State { after, files: vec![(buffer, path)] }),
        }
    }
    if states.is_empty() {
        return Err(CheckRefused::NoSubmission { folder: folder.to_owned() }.into());
    }
    states.sort_by_key(|state| state.after);
    for state in &mut states {
        state.files.sort_by_key(|(buffer, _)| *buffer != Buffer::Frame);
    }
    Ok(states)
}

/// Which states an autograded submission must answer, as the teacher sets
/// them (`--expect`): each is one test per buffer, whatever else is handed in.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Expect {
    /// The state after the last polygon (the default).
    Final,
    /// The state after every polygon.
    Each,
    /// The states after these polygons, numbered from 1.
    After(Vec<usize>),
}

/// A text that names no states to check ([`Expect::parse`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotStates {
    /// The text given.
    pub text: String,
}

impl NotStates {
    /// The refusal in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        words!(lang, "expect-not-states", text = printable(&self.text).into_owned())
    }
}

impl Expect {
    /// Reads `final`, `each`, or polygon numbers from 1 separated by commas
    /// (`1,3`).
    pub fn parse(text: &str) -> Result<Expect, NotStates> {
        match text {
            "final" => Ok(Expect::Final),
            "each" => Ok(Expect::Each),
            _ => text
                .split(',')
                .map(|n| n.trim().parse::<usize>().ok().filter(|n| *n >= 1))
                .collect::<Option<Vec<usize>>>()
                .map(Expect::After)
                .ok_or_else(|| NotStates { text: text.to_string() }),
        }
    }

    /// As [`Expect::parse`] reads it.
    pub fn text(&self) -> String {
        match self {
            Expect::Final => "final".to_string(),
            Expect::Each => "each".to_string(),
            Expect::After(numbers) => numbers.iter().map(usize::to_string).collect::<Vec<_>>().join(","),
        }
    }

    /// The states (0-based polygons) for `scene`, in order, each once.
    pub fn states(&self, scene: &Scene) -> Result<Vec<usize>, Error> {
        let count = scene.polygons.len();
        let mut states = match self {
            Expect::Final => vec![count - 1],
            Expect::Each => (0..count).collect(),
            Expect::After(numbers) => {
                if let Some(&number) = numbers.iter().find(|n| **n > count) {
                    return Err(crate::scene::NoSuchPolygon::Numbered { number, count }.into());
                }
                numbers.iter().map(|n| n - 1).collect()
            }
        };
        states.sort_unstable();
        states.dedup();
        Ok(states)
    }
}

/// One buffer of one state an autograded submission must answer, and the
/// files that answer it: none (missing), one, or several (refused).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Expected {
    /// The polygon (0-based) it is the state after.
    pub after: usize,
    /// The buffer.
    pub buffer: Buffer,
    /// The files answering it.
    pub files: Vec<PathBuf>,
}

/// The tests of answers named one by one (`--frame`, `--depth`), for the
/// state after polygon `after`: a test per file given, framebuffer first.
pub fn named_answers(after: usize, [frame, depth]: &[Option<&Path>; 2]) -> (Vec<Expected>, Vec<String>) {
    let named = [(Buffer::Frame, frame), (Buffer::Depth, depth)];
    let tests = named
        .into_iter()
        .filter_map(|(buffer, path)| Some(Expected { after, buffer, files: vec![path.as_ref()?.to_path_buf()] }))
        .collect();
    (tests, Vec::new())
}

/// What an autograder grades in a submission folder: a test for each buffer
/// of each state `expect` names, in order, with the files that answer it,
/// and the names of the files that answer nothing asked (they earn nothing).
pub fn expected_answers(folder: &Path, scene: &Scene, expect: &Expect) -> Result<(Vec<Expected>, Vec<String>), Error> {
    let mut expected: Vec<Expected> = expect
        .states(scene)?
        .into_iter()
        .flat_map(|after| [Buffer::Frame, Buffer::Depth].map(|buffer| Expected { after, buffer, files: Vec::new() }))
        .collect();
    let mut unused = Vec::new();
    for name in folder_names(folder)? {
        let answer = answer_of(&name, scene.polygons.len());
        match answer.and_then(|(after, buffer)| expected.iter_mut().find(|e| (e.after, e.buffer) == (after, buffer))) {
            Some(test) => test.files.push(folder.join(&name)),
            None => unused.push(printable(&name).into_owned()),
        }
    }
    Ok((expected, unused))
}

/// One wrong cell of an answer, explained.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct WrongCell {
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// What the student wrote.
    pub answer: u32,
    /// What is right.
    pub expected: u32,
    /// Why, in the reader's language.
    pub reason: String,
}

/// What checking one answer file found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct AnswerCheck {
    /// The buffer it answers for.
    pub buffer: Buffer,
    /// The file, as given.
    pub file: String,
    /// The wrong cells, top row first.
    pub wrong: Vec<WrongCell>,
    /// How many cells differ in all: [`AnswerCheck::wrong`] explains the
    /// first [`MAX_EXPLAINED`] of them, top row first.
    pub differing: usize,
    /// How many cells were left unanswered (`?` or `.`): neither right nor wrong.
    pub unanswered: usize,
    /// What it earns by the score's rule ([`crate::teach::grade::score`]).
    pub earned: crate::teach::grade::Earned,
    /// A likely misreading of the whole matrix (flipped, transposed, …), worded.
    pub hint: Option<String>,
}

/// The most wrong cells of one answer explained, each with its reason; the
/// rest are counted. An answer wrong everywhere on a large raster would
/// otherwise hold a reason, and a watched history, for every cell.
pub const MAX_EXPLAINED: usize = 1000;

/// What checking a student's answers for the state after one polygon found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CheckReport {
    /// The state checked, worded: `after polygon 2 "triangle"`.
    pub after: String,
    /// Cells in a buffer.
    pub cells: usize,
    /// Each answer's findings, in the order given.
    pub answers: Vec<AnswerCheck>,
    /// The misconception that explains the wrong cells, worded (exact checks only).
    pub diagnosis: Option<String>,
}

impl CheckReport {
    /// How many cells differ, over all the answers.
    pub fn wrong(&self) -> usize {
        self.answers.iter().map(|a| a.differing).sum()
    }

    /// Whether any cell differs or was left unanswered: the answers are not
    /// yet the whole right answer.
    pub fn differs(&self) -> bool {
        self.wrong() > 0 || self.answers.iter().any(|a| a.unanswered > 0)
    }

    /// The verdict on one of its answers, one line in `lang`: all the cells
    /// answered match, or how many differ; and how many were left unanswered.
    pub fn verdict(&self, lang: Lang, answer: &AnswerCheck) -> String {
        let (buffer, file, after) = (answer.buffer.name(lang), &answer.file, &self.after);
        let cells = self.cells - answer.unanswered;
        let mut verdict = if answer.wrong.is_empty() {
            words!(lang, "check-all-match", buffer = buffer, file = file, cells = cells, after = after)
        } else {
            let count = answer.differing;
            words!(lang, "check-differ", buffer = buffer, file = file, count = count, cells = cells, after = after)
        };
        if answer.unanswered > 0 {
            verdict.push_str(&words!(lang, "check-unanswered", count = answer.unanswered, cells = self.cells));
        }
        verdict
    }
}

/// Checks `answers` (already read) against the buffers after polygon `last`,
/// computed in `arith`, and explains every wrong cell.
pub fn check(
    lang: Lang,
    scene: &Scene,
    scene_path: &Path,
    last: usize,
    answers: Vec<(Buffer, &Path, Answer)>,
    arith: Arith,
) -> Result<CheckReport, Error> {
    check_with(lang, scene, scene_path, last, answers, arith, None)
}

/// What checking many answers to one scene after one polygon shares, drawn
/// once (a class's feedback): the buffers after the polygon and the scene
/// drawn under each wrong rule.
pub struct PreparedCheck {
    buffers: crate::simulate::buffer::Buffers,
    diagnoser: Option<crate::teach::check::diagnose::Diagnoser>,
}

impl PreparedCheck {
    /// The buffers of `scene` after polygon `last` (0-based) and its wrong rules, drawn.
    pub fn new(scene: &Scene, last: usize) -> PreparedCheck {
        PreparedCheck {
            buffers: drawn_through(scene, last),
            diagnoser: crate::teach::check::diagnose::Diagnoser::new(scene, last),
        }
    }
}

/// The buffers of `scene` after polygon `last` (0-based).
fn drawn_through(scene: &Scene, last: usize) -> crate::simulate::buffer::Buffers {
    let mut simulation = Simulation::new(scene);
    simulation.draw_through(last, &mut Unobserved);
    simulation.buffers().clone()
}

/// [`check`] with what every answer shares drawn once ([`PreparedCheck`], for the
/// same scene and polygon) instead of drawn again for these answers.
pub fn check_with(
    lang: Lang,
    scene: &Scene,
    scene_path: &Path,
    last: usize,
    answers: Vec<(Buffer, &Path, Answer)>,
    arith: Arith,
    prepared: Option<&PreparedCheck>,
) -> Result<CheckReport, Error> {
    arith::check_supported(scene, arith)?;
    let drawn;
    let exact = match prepared {
        Some(prepared) => &prepared.buffers,
        None => {
            drawn = drawn_through(scene, last);
            &drawn
        }
    };
    // An inexact mode's buffers after polygon `last`: run it on the scene cut after that polygon.
    let mode_buffers = if arith == Arith::Exact {
        None
    } else {
        let mut prefix = scene.clone();
        prefix.polygons.truncate(last + 1);
        Some(arith::run(&prefix, arith)?.0)
    };
    let reference = mode_buffers.as_ref().unwrap_or(exact);
    // The misconception that explains the wrong cells, for answers checked exactly.
    let diagnosis = if arith == Arith::Exact {
        let answer = |wanted: Buffer| answers.iter().find(|(b, _, _)| *b == wanted).map(|(_, _, m)| m);
        match prepared {
            Some(prepared) => {
                prepared.diagnoser.as_ref().and_then(|d| d.diagnose(answer(Buffer::Frame), answer(Buffer::Depth)))
            }
            None => crate::teach::check::diagnose::diagnose(scene, last, answer(Buffer::Frame), answer(Buffer::Depth)),
        }
    } else {
        None
    };
    let mut results = Vec::new();
    for (buffer, path, answer) in answers {
        let expected = match buffer {
            Buffer::Frame => reference.frame_rows(),
            Buffer::Depth => reference
                .depth_level_rows()
                .ok_or_else(|| Error::from(CheckRefused::ExactDepths { path: scene_path.to_path_buf() }))?,
        };
        let hint = misreading(&answer, &expected);
        let mut mismatches = compare_answer(&answer, &expected);
        let differing = mismatches.len();
        // The other buffer handed in for this one (the framebuffer as the z-buffer's answer).
        let other = match buffer {
            Buffer::Frame => reference.depth_level_rows().map(|rows| (Buffer::Depth, rows)),
            Buffer::Depth => Some((Buffer::Frame, reference.frame_rows())),
        };
        let other = other.filter(|(_, rows)| differing > 0 && answer.unanswered() == 0 && answer.rows == *rows).map(
            |(other, _)| words!(lang, "check-hint-other-buffer", other = other.name(lang), buffer = buffer.name(lang)),
        );
        mismatches.truncate(MAX_EXPLAINED);
        let cleared = crate::teach::grade::cleared(scene, buffer);
        let earned = crate::teach::grade::Earned::of(Some(&answer), &expected, cleared);
        results.push((buffer, path, mismatches, (hint, other), (differing, answer.unanswered(), earned)));
    }
    // Watch the differing cells through a second run, to explain each.
    let mut watcher = PixelWatcher::new(results.iter().flat_map(|(_, _, m, _, _)| m.iter().map(|c| (c.x, c.y))));
    if results.iter().any(|(_, _, m, _, _)| !m.is_empty()) {
        Simulation::new(scene).draw_through(last, &mut watcher);
    }
    let answers = results
        .into_iter()
        .map(|(buffer, path, mismatches, hint, (differing, unanswered, earned))| {
            let wrong = mismatches
                .iter()
                .map(|cell| {
                    let mut reason = why(lang, scene, buffer, cell.x, cell.y, watcher.history(cell.x, cell.y));
                    let exact_value = match buffer {
                        Buffer::Frame => exact.frame(cell.x, cell.y),
                        Buffer::Depth => exact.depth(cell.x, cell.y).level().unwrap_or(0),
                    };
                    if exact_value != cell.expected {
                        reason = words!(
                            lang,
                            "check-in-arith",
                            arith = arith.to_string(),
                            mode = cell.expected,
                            exact = exact_value,
                            reason = reason
                        );
                    }
                    WrongCell { x: cell.x, y: cell.y, answer: cell.answer, expected: cell.expected, reason }
                })
                .collect();
            let (hint, other) = hint;
            let hint = other.or_else(|| {
                hint.map(|(how, left)| {
                    let (how, top) = (how.words(lang), scene.height - 1);
                    if left == 0 {
                        words!(lang, "check-hint-matches", how = how, top = top)
                    } else {
                        words!(lang, "check-hint-fewer", how = how, left = left, top = top)
                    }
                })
            });
            let file = crate::words::shown_path(path);
            AnswerCheck { buffer, file, wrong, differing, unanswered, earned, hint }
        })
        .collect();
    Ok(CheckReport {
        after: polygon_after(lang, scene, last),
        cells: scene.width as usize * scene.height as usize,
        answers,
        diagnosis: diagnosis.map(|d| d.words(lang)),
    })
}
