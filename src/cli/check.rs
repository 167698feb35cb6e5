//! `zsim check`: compares a student's matrices with zsim's and explains every
//! differing cell.

use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use comfy_table::{Table, presets};
use zsim::Error;
use zsim::Scene;
use zsim::check::{CheckReport, State, WrongCell, check, read_answer, submission_files};
use zsim::explain::Buffer;
use zsim::gradescope::{Autograde, Visibility};

use super::{Failure, Finish, emit, emit_then};

/// Arguments of `zsim check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// The scene file (JSON), or - for standard input.
    scene: PathBuf,
    /// An answer named without --frame or --depth: refused, saying which to use.
    #[arg(hide = true, value_name = "ANSWER")]
    stray: Option<PathBuf>,
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
    #[arg(long, default_value = "exact", value_parser = |text: &str| zsim::arith::Arith::parse(text).map_err(|e| e.message(super::language_of_the_run())))]
    arith: zsim::arith::Arith,
    /// A folder of answers as an autograder receives them: frame.txt and/or depth.txt (after the last polygon), after-N.frame.txt and after-N.depth.txt (after polygon N).
    #[arg(long, value_name = "DIR", conflicts_with_all = ["frame", "depth", "after"])]
    submission: Option<PathBuf>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// With --format gradescope: who sees the results.
    #[arg(long, default_value = "visible", value_parser = super::choice(&Visibility::NAMES, Visibility::parse))]
    visibility: Visibility,
    /// With --format gradescope: the points the whole submission is worth, shared equally by its tests.
    #[arg(long, default_value_t = 100, value_parser = clap::value_parser!(u32).range(1..=i64::from(zsim::gradescope::MAX_POINTS)))]
    points: u32,
    /// With --format gradescope: the states the submission must answer, each a test per buffer (final, each, or polygon numbers such as 1,3); other files earn nothing.
    #[arg(long, default_value = "final", value_parser = |text: &str| zsim::check::Expect::parse(text).map_err(|e| e.message(super::language_of_the_run())))]
    expect: zsim::check::Expect,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Format {
    /// The wrong cells, each explained.
    Text,
    /// An autograder's results.json for Gradescope: one test per buffer and polygon step, the explanation in its output; exit 0 whatever the answer.
    Gradescope,
}

pub fn run(lang: zsim::Lang, args: &CheckArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    if let Some(path) = &args.stray {
        return Err(super::flags::Flag::AnswerWithoutBuffer { path: path.clone() }.into());
    }
    let scene = Scene::load(&args.scene)?;
    if args.frame.is_none() && args.depth.is_none() && args.submission.is_none() {
        return Err(super::flags::Flag::CheckNeedsAnswer.into());
    }
    if scene.polygons.is_empty() {
        return Err(Error::from(zsim::check::CheckRefused::NoPolygons { path: args.scene.clone() }).into());
    }
    let last = match &args.after {
        Some(spec) => scene.find_polygon(spec)?,
        None => scene.polygons.len() - 1,
    };
    if args.format == Format::Gradescope {
        // An autograder writes results.json whatever it is given: a missing answer scores 0.
        let found = match &args.submission {
            Some(folder) => zsim::check::expected_answers(folder, &scene, &args.expect),
            None => Ok(zsim::check::named_answers(last, &[args.frame.as_deref(), args.depth.as_deref()])),
        };
        let (expected, unused) = match found {
            Ok(found) => found,
            Err(error) => {
                return emit_then(
                    out,
                    &zsim::gradescope::nothing_to_grade(&error.message(lang), args.visibility),
                    Finish::Ok,
                );
            }
        };
        let grading = Autograde { visibility: args.visibility, points: args.points };
        let render = |report: &CheckReport| report_text(lang, report);
        let found = (expected.as_slice(), unused.as_slice());
        let results = zsim::gradescope::results(lang, (&scene, &args.scene), found, args.arith, grading, &render)?;
        return emit_then(out, &results, Finish::Ok);
    }
    let states = match &args.submission {
        Some(folder) => submission_files(folder, &scene)?,
        None => vec![State {
            after: last,
            files: [(Buffer::Frame, &args.frame), (Buffer::Depth, &args.depth)]
                .into_iter()
                .filter_map(|(b, p)| Some((b, p.clone()?)))
                .collect(),
        }],
    };
    if args.submission.is_some() {
        let (mut finish, mut text) = (Finish::Ok, String::new());
        for state in &states {
            let mut read = Vec::new();
            for (buffer, path) in &state.files {
                read.push((*buffer, path.as_path(), read_answer(path, &scene, *buffer, zsim::Links::Refuse)?));
            }
            let report = check(lang, &scene, &args.scene, state.after, read, args.arith)?;
            text.push_str(&report_text(lang, &report));
            if report.differs() {
                finish = Finish::Differs;
            }
        }
        return emit_then(out, &text, finish);
    }
    // A malformed file is reported (exit 2), but the other answer is still checked.
    let mut answers = Vec::new();
    let mut malformed = None;
    for (buffer, path) in [(Buffer::Frame, &args.frame), (Buffer::Depth, &args.depth)] {
        if let Some(path) = path {
            match read_answer(path, &scene, buffer, zsim::Links::Follow) {
                Ok(answer) => answers.push((buffer, path.as_path(), answer)),
                Err(error) => {
                    malformed.get_or_insert(error);
                }
            }
        }
    }
    if !answers.is_empty() {
        let report = check(lang, &scene, &args.scene, last, answers, args.arith)?;
        if malformed.is_none() {
            let finish = if report.differs() { Finish::Differs } else { Finish::Ok };
            return emit_then(out, &report_text(lang, &report), finish);
        }
        emit(out, &report_text(lang, &report))?;
    }
    Err(malformed.expect("an answer was given, read or malformed").into())
}

/// A check's report as `zsim check` prints it: per answer, "all cells
/// match" or the wrong cells in a table, each explained; then the likely
/// misconception. `grade` writes the same as each student's feedback, and
/// Gradescope's results hold it as each test's output.
pub fn report_text(lang: zsim::Lang, report: &CheckReport) -> String {
    let mut text = String::new();
    for answer in &report.answers {
        text.push_str(&format!("{}\n", report.verdict(lang, answer)));
        if answer.wrong.is_empty() {
            continue;
        }
        let count = answer.differing;
        if let Some(hint) = &answer.hint {
            text.push_str(&format!("{hint}\n"));
        }
        text.push_str(&format!("{}\n", table(lang, &answer.wrong)));
        if count > answer.wrong.len() {
            let more = zsim::words!(lang, "check-more-cells", count = count - answer.wrong.len());
            text.push_str(&format!("{more}\n"));
        }
    }
    if let Some(diagnosis) = &report.diagnosis {
        text.push_str(&format!("{diagnosis}\n"));
    }
    text
}

fn table(lang: zsim::Lang, wrong: &[WrongCell]) -> Table {
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
    for cell in wrong {
        table.add_row([
            cell.x.to_string(),
            cell.y.to_string(),
            cell.answer.to_string(),
            cell.expected.to_string(),
            cell.reason.clone(),
        ]);
    }
    table
}
