//! `zsim check`: compares a student's matrices with zsim's and explains every
//! differing cell.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::Args;
use comfy_table::{Table, presets};
use zsim::Error;
use zsim::Scene;
use zsim::Simulation;
use zsim::check::{CellRange, Matrix, Mismatch, compare, misreading, parse_answer};
use zsim::explain::{Buffer, why};
use zsim::{PixelWatcher, Unobserved};

use super::gradescope;
use super::{Failure, Finish, emit};

/// Arguments of `zsim check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// The scene file (JSON), or - for standard input.
    scene: PathBuf,
    /// The answer for the framebuffer: integers as the book prints them, top row first.
    #[arg(long, value_name = "FILE")]
    frame: Option<PathBuf>,
    /// The answer for the z-buffer.
    #[arg(long, value_name = "FILE")]
    depth: Option<PathBuf>,
    /// Check the state after this polygon (number from 1, or name); default: the last.
    #[arg(long, value_name = "N|NAME")]
    after: Option<String>,
    /// The arithmetic the answer was computed in: exact, f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K.
    #[arg(long, default_value = "exact", value_parser = |text: &str| zsim::arith::Arith::parse(super::language_of_the_run(), text))]
    arith: zsim::arith::Arith,
    /// A folder of answers as an autograder receives them: frame.txt and/or depth.txt (after the last polygon), after-N.frame.txt and after-N.depth.txt (after polygon N).
    #[arg(long, value_name = "DIR", conflicts_with_all = ["frame", "depth", "after"])]
    submission: Option<PathBuf>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// With --format gradescope: who sees the results.
    #[arg(long, value_enum, default_value_t = gradescope::Visibility::Visible)]
    visibility: gradescope::Visibility,
    /// With --format gradescope: the points the whole submission is worth, shared equally by its tests.
    #[arg(long, default_value_t = 100)]
    points: u32,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Format {
    /// The wrong cells, each explained.
    Text,
    /// An autograder's results.json for Gradescope: one test per buffer and polygon step, the explanation in its output; exit 0 whatever the answer.
    Gradescope,
}

/// Reads an answer file for one of `scene`'s buffers: a matrix as the book
/// prints it; a symbolic link is followed only where `links` says so.
pub fn read_answer(
    lang: zsim::Lang,
    path: &Path,
    scene: &Scene,
    buffer: Buffer,
    links: zsim::Links,
) -> Result<Matrix, Error> {
    let text = zsim::read_text_with(lang, path, links)?;
    let (max, description) = match buffer {
        Buffer::Frame => (
            zsim::max_for_bits(scene.frame_bits),
            zsim::words!(lang, "answer-frame-range", bits = scene.frame_bits.to_string()),
        ),
        Buffer::Depth => {
            (scene.depth_max(), zsim::words!(lang, "answer-depth-range", bits = scene.depth_bits.to_string()))
        }
    };
    parse_answer(lang, &text, scene.width, scene.height, CellRange { max, buffer: &description })
        .map_err(|message| Error::Answer { path: path.to_owned(), message })
}

/// An error about a student's answer file as the student and the class
/// table show it: the file's name where the message has its path (where the
/// class folder or the autograder keeps it stretches tables and is nobody's
/// business), in any language's wording, control characters escaped.
pub fn as_the_student_sees(lang: zsim::Lang, error: &Error, path: &Path) -> String {
    let file = path.file_name().map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
    zsim::printable(&error.message(lang).replace(&path.display().to_string(), &file)).into_owned()
}

pub fn run(lang: zsim::Lang, args: &CheckArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let scene = Scene::load(lang, &args.scene)?;
    if args.frame.is_none() && args.depth.is_none() && args.submission.is_none() {
        return Err(Error::from(zsim::Usage::CheckNeedsAnswer).into());
    }
    if scene.polygons.is_empty() {
        return Err(Error::from(zsim::Usage::NoPolygons { path: args.scene.clone(), task: zsim::Task::Check }).into());
    }
    let last = match &args.after {
        Some(spec) => scene.find_polygon(spec)?,
        None => scene.polygons.len() - 1,
    };
    let states = match &args.submission {
        // An autograder writes results.json whatever it is given: an empty submission scores 0.
        Some(folder) if args.format == Format::Gradescope => match submission_files(folder, &scene) {
            Ok(states) => states,
            Err(error) => {
                emit(out, &gradescope::nothing_to_grade(&error.message(lang), args.visibility))?;
                return Ok(Finish::Ok);
            }
        },
        Some(folder) => submission_files(folder, &scene)?,
        None => vec![(
            last,
            [(Buffer::Frame, &args.frame), (Buffer::Depth, &args.depth)]
                .into_iter()
                .filter_map(|(b, p)| Some((b, p.clone()?)))
                .collect(),
        )],
    };
    if args.format == Format::Gradescope {
        let results =
            gradescope::results(lang, &scene, &args.scene, &states, args.arith, args.visibility, args.points)?;
        emit(out, &results)?;
        return Ok(Finish::Ok);
    }
    if args.submission.is_some() {
        let mut finish = Finish::Ok;
        for (last, files) in &states {
            let mut read = Vec::new();
            for (buffer, path) in files {
                read.push((*buffer, path.as_path(), read_answer(lang, path, &scene, *buffer, zsim::Links::Refuse)?));
            }
            let report = report(lang, &scene, &args.scene, *last, read, args.arith)?;
            emit(out, &report.text)?;
            if report.differs() {
                finish = Finish::Differs;
            }
        }
        return Ok(finish);
    }
    // A malformed file is reported (exit 2), but the other answer is still checked.
    let mut answers = Vec::new();
    let mut malformed = None;
    for (buffer, path) in [(Buffer::Frame, &args.frame), (Buffer::Depth, &args.depth)] {
        if let Some(path) = path {
            match read_answer(lang, path, &scene, buffer, zsim::Links::Follow) {
                Ok(answer) => answers.push((buffer, path.as_path(), answer)),
                Err(error) => {
                    malformed.get_or_insert(error);
                }
            }
        }
    }
    if !answers.is_empty() {
        let report = report(lang, &scene, &args.scene, last, answers, args.arith)?;
        emit(out, &report.text)?;
        if malformed.is_none() {
            return Ok(if report.differs() { Finish::Differs } else { Finish::Ok });
        }
    }
    Err(malformed.expect("an answer was given, read or malformed").into())
}

/// What checking one student's answers found.
pub struct Report {
    /// What `zsim check` prints: per answer, "all cells match" or the table of wrong cells.
    pub text: String,
    /// How many cells differ, over all the answers.
    pub wrong: usize,
}

impl Report {
    /// Whether any cell differs.
    pub fn differs(&self) -> bool {
        self.wrong > 0
    }
}

/// Answer files for the state after one polygon (0-based): each buffer's file.
pub type State = (usize, Vec<(Buffer, PathBuf)>);

/// The answer files of a submission folder, grouped by the polygon they are
/// the state after: `frame.txt` and `depth.txt` after the last,
/// `after-N.frame.txt` and `after-N.depth.txt` after polygon N; other files
/// are passed over. Symbolic links are not followed.
pub fn submission_files(folder: &Path, scene: &Scene) -> Result<Vec<State>, Error> {
    let last = scene.polygons.len() - 1;
    let read_error = |source| Error::Read { path: folder.to_owned(), source };
    let mut states: Vec<State> = Vec::new();
    let mut names: Vec<String> =
        std::fs::read_dir(folder).map_err(read_error)?.filter_map(|e| e.ok()?.file_name().into_string().ok()).collect();
    names.sort();
    for name in names {
        let (after, kind) = match name.strip_prefix("after-").and_then(|rest| rest.split_once('.')) {
            Some((number, kind)) => match number.parse::<usize>() {
                Ok(n) if (1..=last).contains(&n) => (n - 1, kind),
                _ => continue,
            },
            None => (last, name.as_str()),
        };
        let buffer = match kind {
            "frame.txt" => Buffer::Frame,
            "depth.txt" => Buffer::Depth,
            _ => continue,
        };
        let path = folder.join(&name);
        match states.iter_mut().find(|(a, _)| *a == after) {
            Some((_, files)) => files.push((buffer, path)),
            None => states.push((after, vec![(buffer, path)])),
        }
    }
    if states.is_empty() {
        return Err(zsim::Usage::NoSubmission { folder: folder.to_owned() }.into());
    }
    states.sort_by_key(|(after, _)| *after);
    for (_, files) in &mut states {
        files.sort_by_key(|(buffer, _)| *buffer != Buffer::Frame);
    }
    Ok(states)
}

/// Checks `answers` (already read) against the buffers after polygon `last`,
/// computed in `arith`, and explains every wrong cell: `zsim check`'s output,
/// also the feedback `zsim grade` writes for each student.
pub fn report(
    lang: zsim::Lang,
    scene: &Scene,
    scene_path: &Path,
    last: usize,
    answers: Vec<(Buffer, &Path, Matrix)>,
    arith: zsim::arith::Arith,
) -> Result<Report, Error> {
    zsim::arith::check_supported(scene, arith)?;
    let mut simulation = Simulation::new(scene);
    simulation.draw_through(last, &mut Unobserved);
    // An inexact mode's buffers after polygon `last`: run it on the scene cut after that polygon.
    let mode_buffers = if arith == zsim::arith::Arith::Exact {
        None
    } else {
        let mut prefix = scene.clone();
        prefix.polygons.truncate(last + 1);
        Some(zsim::arith::run(&prefix, arith)?.0)
    };
    let reference = mode_buffers.as_ref().unwrap_or(simulation.buffers());
    let cells = scene.width as usize * scene.height as usize;
    // The misconception that explains the wrong cells, for answers checked exactly.
    let diagnosis = if arith == zsim::arith::Arith::Exact {
        let answer = |wanted: Buffer| answers.iter().find(|(b, _, _)| *b == wanted).map(|(_, _, m)| m);
        zsim::diagnose::diagnose(scene, last, answer(Buffer::Frame), answer(Buffer::Depth))
    } else {
        None
    };
    let mut results = Vec::new();
    for (buffer, path, answer) in answers {
        let expected = match buffer {
            Buffer::Frame => reference.frame_rows(),
            Buffer::Depth => reference.depth_level_rows().ok_or_else(|| {
                Error::from(zsim::Usage::ExactDepthsHaveNoMatrix {
                    path: scene_path.to_path_buf(),
                    task: zsim::Task::Check,
                })
            })?,
        };
        let hint = misreading(&answer, &expected);
        results.push((buffer, path, compare(&answer, &expected), hint));
    }
    // Watch the differing cells through a second run, to explain each.
    let mut watcher = PixelWatcher::new(results.iter().flat_map(|(_, _, m, _)| m.iter().map(|c| (c.x, c.y))));
    if results.iter().any(|(_, _, m, _)| !m.is_empty()) {
        Simulation::new(scene).draw_through(last, &mut watcher);
    }
    let mut text = String::new();
    let wrong = results.iter().map(|(_, _, m, _)| m.len()).sum();
    for (buffer, path, mismatches, hint) in &results {
        let (after, file) = (zsim::explain::polygon_after(lang, scene, last), path.display().to_string());
        if mismatches.is_empty() {
            let line = zsim::words!(
                lang,
                "check-all-match",
                buffer = buffer.name(lang),
                file = file,
                cells = cells,
                after = after
            );
            text.push_str(&line);
            text.push('\n');
            continue;
        }
        let line = zsim::words!(
            lang,
            "check-differ",
            buffer = buffer.name(lang),
            file = file,
            count = mismatches.len(),
            cells = cells,
            after = after
        );
        text.push_str(&line);
        text.push('\n');
        if let Some((how, left)) = hint {
            let (how, top) = (how.words(lang), scene.height - 1);
            let line = if *left == 0 {
                zsim::words!(lang, "check-hint-matches", how = how, top = top)
            } else {
                zsim::words!(lang, "check-hint-fewer", how = how, left = *left, top = top)
            };
            text.push_str(&line);
            text.push('\n');
        }
        text.push_str(&format!(
            "{}\n",
            table(lang, scene, *buffer, mismatches, &watcher, (arith, simulation.buffers()))
        ));
    }
    if let Some(diagnosis) = diagnosis {
        text.push_str(&format!("{}\n", diagnosis.words(lang)));
    }
    Ok(Report { text, wrong })
}

fn table(
    lang: zsim::Lang,
    scene: &Scene,
    buffer: Buffer,
    mismatches: &[Mismatch],
    watcher: &PixelWatcher,
    (arith, exact): (zsim::arith::Arith, &zsim::Buffers),
) -> Table {
    let mut table = Table::new();
    // Wrapped to 80 columns: the "why" column breaks over lines instead of running on.
    table
        .load_style(presets::ASCII_MARKDOWN)
        .set_content_arrangement(comfy_table::ContentArrangement::Dynamic)
        .set_width(80)
        .set_header([
            "x".to_string(),
            "y".to_string(),
            zsim::words!(lang, "check-column-answer"),
            zsim::words!(lang, "check-column-right"),
            zsim::words!(lang, "check-column-why"),
        ]);
    for cell in mismatches {
        let history = watcher.history(cell.x, cell.y);
        let mut reason = why(lang, scene, buffer, cell.x, cell.y, history);
        let exact_value = match buffer {
            Buffer::Frame => exact.frame(cell.x, cell.y),
            Buffer::Depth => exact.depth(cell.x, cell.y).level().unwrap_or(0),
        };
        if exact_value != cell.expected {
            reason = zsim::words!(
                lang,
                "check-in-arith",
                arith = arith.to_string(),
                mode = cell.expected,
                exact = exact_value,
                reason = reason
            );
        }
        table.add_row([
            cell.x.to_string(),
            cell.y.to_string(),
            cell.answer.to_string(),
            cell.expected.to_string(),
            reason,
        ]);
    }
    table
}
