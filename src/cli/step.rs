//! `zsim step`: one scanline at a time, in a terminal or driven line by line
//! from standard input, with an optional quiz.

use std::io::{IsTerminal, Write};
use std::path::PathBuf;

use clap::Args;
use comfy_table::{Cell, Color, Table, presets};
use zsim::Error;
use zsim::explain::fate_text;
use zsim::lesson::{Command, Lesson, Said};
use zsim::report::{self, MatrixStyle};
use zsim::step::Moved;
use zsim::{Scene, Stop};

use super::{Failure, Finish, emit};

/// A stop `--polygon` and `--scanline` ask for that the scene does not have.
#[derive(Debug)]
enum Unreached {
    /// The polygon is not drawn (culled, edge-on, degenerate, outside the view).
    NotDrawn {
        /// 0-based polygon index.
        index: usize,
        /// Its name.
        name: String,
        /// Why it is not drawn.
        fate: zsim::Fate,
    },
    /// The polygon does not reach the row.
    Row {
        /// 0-based polygon index.
        index: usize,
        /// Its name.
        name: String,
        /// The row asked for.
        row: u32,
        /// The first and last rows it reaches, if any.
        rows: Option<(u32, u32)>,
    },
}

impl zsim::Refusal for Unreached {
    fn message(&self, lang: zsim::Lang) -> String {
        match self {
            Unreached::NotDrawn { index, name, fate } => zsim::words!(
                lang,
                "usage-no-scanlines",
                polygon = zsim::polygon_label(lang, "polygon-name", *index, name),
                why = fate_text(lang, *fate).unwrap_or_default()
            ),
            Unreached::Row { index, name, row, rows } => {
                let reach = zsim::words!(
                    lang,
                    "step-not-reach",
                    polygon = zsim::polygon_label(lang, "polygon-name", *index, name),
                    scanline = zsim::words!(lang, "scanline", y = zsim::localize_decimal(lang, format!("{row}.5")))
                );
                match rows {
                    Some((first, last)) => zsim::words!(
                        lang,
                        "usage-scanline-rows",
                        reach = reach,
                        first = first.to_string(),
                        last = last.to_string()
                    ),
                    None => zsim::words!(lang, "usage-scanline-no-rows", reach = reach),
                }
            }
        }
    }
}

/// Arguments of `zsim step`.
#[derive(Debug, Args)]
pub struct StepArgs {
    /// The scene file (JSON), or - for standard input.
    scene: PathBuf,
    /// Show one step of this polygon (number from 1, or name) and exit: its scanline --scanline, else its first; with --quiz, start there.
    #[arg(long, value_name = "N|NAME")]
    polygon: Option<String>,
    /// The row of the scanline to show (the scanline is at y = row + 1/2); needs --polygon.
    #[arg(long, value_name = "Y", requires = "polygon")]
    scanline: Option<u32>,
    /// A quiz: before each pixel's result, ask what the z-buffer will hold; `--quiz frame` asks what the framebuffer will hold; `--quiz coverage` first asks which centres the scanline covers. With --polygon and --scanline it starts there.
    #[arg(long, value_enum, num_args = 0..=1, default_missing_value = "depth", value_name = "depth|frame|coverage")]
    quiz: Option<QuizMode>,
    /// Write the stepper as one self-contained HTML page (-o FILE.html) instead of running it: the playground where this zsim carries it, with --quiz its quiz on.
    #[arg(long, requires = "output", conflicts_with = "polygon")]
    html: bool,
    /// The page to write, with --html.
    #[arg(short, long, value_name = "FILE.html", requires = "html")]
    output: Option<PathBuf>,
    /// Also show what an inexact arithmetic computes on each scanline: f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K.
    #[arg(long, default_value = "exact", value_parser = |text: &str| zsim::arith::Arith::parse(text).map_err(|e| e.message(super::language_of_the_run())))]
    arith: zsim::arith::Arith,
}

/// What the quiz asks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum QuizMode {
    /// The z-buffer value after each covered pixel.
    Depth,
    /// The framebuffer value after each covered pixel.
    Frame,
    /// First which centres the scanline covers, then the z-buffer values.
    Coverage,
}

pub fn run(lang: zsim::Lang, args: &StepArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let text = zsim::read_text(&args.scene)?;
    let scene = Scene::from_json(&text, &args.scene)?;
    zsim::arith::check_supported(&scene, args.arith)?;
    let color = super::use_color();
    // The page's quiz is the playground's, which asks in exact arithmetic.
    match (args.html && args.quiz.is_some(), args.arith == zsim::arith::Arith::Exact) {
        (true, false) => return Err(super::flags::Flag::HtmlQuiz.into()),
        (true, true) if zsim::playground::site_files().is_none() => return Err(super::flags::Flag::NoPlayground.into()),
        _ => {}
    }
    if let (true, Some(output)) = (args.html, &args.output) {
        let quiz = args.quiz.map(Into::into);
        let page =
            zsim::playground::step_page(lang, &scene, &text, &args.scene, args.arith, quiz).map_err(Error::from)?;
        let mut plan = zsim::Plan::new(&[&args.scene], zsim::Replace::Allowed);
        plan.file(output, page);
        plan.write()?;
        emit(out, &format!("{}\n", zsim::words!(lang, "file-written-page", path = zsim::shown_path(output))))?;
        return Ok(Finish::Ok);
    }
    let mut lesson = Lesson::new(scene, args.arith, args.quiz.map(Into::into));
    let mut start = None;
    if let Some(spec) = &args.polygon {
        let scene = lesson.scene();
        let polygon = scene.find_polygon(spec)?;
        let name = scene.polygons[polygon].name.clone();
        let (fate, rows, scanline) = lesson.with_stepper(|stepper| {
            let trace = stepper.tracer().trace(polygon);
            let rows = trace.scanlines.first().zip(trace.scanlines.last()).map(|(first, last)| (first.row, last.row));
            // The scanline asked for, else the polygon's first.
            let scanline = match args.scanline {
                Some(row) => trace.scanlines.iter().position(|r| r.row == row),
                None => (!trace.scanlines.is_empty()).then_some(0),
            };
            (trace.fate, rows, scanline)
        });
        if fate_text(lang, fate).is_some() {
            return Err(Error::from(Unreached::NotDrawn { index: polygon, name, fate }).into());
        }
        let Some(scanline) = scanline else {
            let row = args.scanline.unwrap_or(0);
            return Err(Error::from(Unreached::Row { index: polygon, name, row, rows }).into());
        };
        let stop = Stop { polygon, scanline };
        if args.quiz.is_none() {
            lesson.start(Some(stop));
            emit(out, &stop_text(lang, &mut lesson, color))?;
            return Ok(Finish::Ok);
        }
        start = Some(stop);
    }
    // On a terminal, the full-screen app; piped or redirected, the line mode scripts rely on.
    if std::io::stdin().is_terminal() && std::io::stdout().is_terminal() {
        lesson.start(start);
        crate::app::run(&mut crate::app::App::new(&mut lesson, lang))?;
        // The screen is gone (q, Esc or Ctrl-C): the quiz's score and each mistake stay on the
        // terminal, as in the line mode.
        emit(out, &lesson.finish(lang))?;
        return Ok(Finish::Ok);
    }
    interactive(lang, &zsim::shown_path(&args.scene), &mut lesson, start, color, out)
}

impl From<QuizMode> for zsim::step::QuizMode {
    fn from(mode: QuizMode) -> zsim::step::QuizMode {
        match mode {
            QuizMode::Depth => zsim::step::QuizMode::Depth,
            QuizMode::Frame => zsim::step::QuizMode::Frame,
            QuizMode::Coverage => zsim::step::QuizMode::Coverage,
        }
    }
}

/// Lines typed by the user (or piped in by a script).
struct Input {
    stdin: std::io::StdinLock<'static>,
    terminal: bool,
}

/// The longest line the line mode reads, in bytes: a command or an answer
/// is a few characters; `< /dev/zero` is not a line to hold.
const MAX_LINE_BYTES: usize = 4096;

impl Input {
    fn stdin() -> Input {
        let stdin = std::io::stdin();
        Input { terminal: stdin.is_terminal(), stdin: stdin.lock() }
    }

    /// The next line; the prompt is shown only on a terminal. `None` at the end of input.
    fn read(&mut self, out: &mut dyn Write, prompt: &str) -> Result<Option<zsim::Line>, Failure> {
        if self.terminal {
            emit(out, prompt)?;
            out.flush()?;
        }
        Ok(zsim::read_line_within(&mut self.stdin, MAX_LINE_BYTES)?)
    }
}

/// The line mode: the lesson's stop as lines and a table, its question on a
/// line of its own, each typed line a [`Command`] whose outcome the lesson
/// words. A stop is shown when it is reached (cut to what may be shown) and
/// again in full once its last question is answered or skipped.
fn interactive(
    lang: zsim::Lang,
    path: &str,
    lesson: &mut Lesson,
    start: Option<Stop>,
    color: bool,
    out: &mut dyn Write,
) -> Result<Finish, Failure> {
    let mut input = Input::stdin();
    let header = report::scene_header(lang, lesson.scene(), path);
    emit(out, &format!("{header}{}{}\n", antialias_note(lang, lesson.scene()), Command::keys_text(lang)))?;
    let said = lesson.start(start);
    say(out, lang, lesson, &said)?;
    let mut show = true;
    loop {
        if show {
            match lesson.at() {
                Some(_) => emit(out, &stop_text(lang, lesson, color))?,
                None => emit(out, &format!("{}\n", zsim::words!(lang, "step-end")))?,
            }
        }
        let prompt = match lesson.prompt(lang) {
            Some(question) => {
                emit(out, &format!("{question}\n"))?;
                "> ".to_string()
            }
            None => zsim::words!(lang, "step-prompt"),
        };
        let line = match input.read(out, &prompt)? {
            None => break,
            Some(zsim::Line::Text(line)) => line,
            Some(zsim::Line::NotText) => {
                emit(out, &format!("{}\n", zsim::words!(lang, "step-line-not-text")))?;
                show = false;
                continue;
            }
            Some(zsim::Line::TooLong) => {
                emit(out, &lesson.finish(lang))?;
                return Err(super::flags::Flag::LineTooLong { max: MAX_LINE_BYTES }.into());
            }
        };
        let open_before = lesson.open_questions();
        let said = lesson.act(lang, Command::parse(&line));
        if matches!(said, Said::Quit) {
            break;
        }
        say(out, lang, lesson, &said)?;
        show = match said {
            Said::Moved(Moved::To { .. }) => true,
            // The last open question ended: the stop in full.
            Said::Right { .. } | Said::Revealed(_) | Said::Skipped(_) => {
                open_before > 0 && lesson.open_questions() == 0
            }
            _ => false,
        };
    }
    // `q` or the end of the input.
    emit(out, &lesson.finish(lang))?;
    Ok(Finish::Ok)
}

/// What became of a command, as lines (nothing for a move that passed nothing over).
fn say(out: &mut dyn Write, lang: zsim::Lang, lesson: &Lesson, said: &Said) -> Result<(), Failure> {
    let text = said.text(lang, lesson.scene());
    if text.is_empty() {
        return Ok(());
    }
    let lines: String = text.lines().map(|line| format!("  {line}\n")).collect();
    emit(out, &lines)
}

/// For an antialiased scene, what `step` shows and what it does not.
fn antialias_note(lang: zsim::Lang, scene: &Scene) -> String {
    match scene.effects.antialias {
        Some(settings) => {
            format!("   {}\n", zsim::words!(lang, "step-antialias-note", k = settings.samples.to_string()))
        }
        None => String::new(),
    }
}

/// What one scanline of one polygon shows, cut to what the lesson may show.
fn stop_text(lang: zsim::Lang, lesson: &mut Lesson, color: bool) -> String {
    let Some(view) = lesson.stop_view(lang) else { return String::new() };
    let scene = lesson.scene();
    let mut text = format!("\n── {}\n", view.heading);
    text.push_str(&antialias_note(lang, scene));
    text.push_str(&format!("   {}\n{}\n", view.slope, view.scanline));
    if let Some(crossings) = &view.crossings {
        text.push_str(&format!("{crossings}\n"));
    }
    // The spans with their ends' depths once nothing is asked; until then without.
    let spans = if view.span_depths.is_empty() { &view.spans } else { &view.span_depths };
    for line in spans {
        text.push_str(&format!("{line}\n"));
    }
    if !view.rows.is_empty() {
        text.push_str(&format!("{}\n", pixel_table(lang, &view.rows, color)));
    }
    for line in &view.notes {
        text.push_str(&format!("{line}\n"));
    }
    let height = scene.height;
    let Some(buffers) = lesson.buffers() else { return text };
    let low = view.row.saturating_sub(2);
    let high = (view.row + 2).min(height - 1);
    let style = MatrixStyle { axes: true, color, rows: Some(low..=high), mark: Some(view.row) };
    let (low, high) = (low.to_string(), high.to_string());
    text.push_str(&format!(
        "{}\n{}",
        zsim::words!(lang, "step-frame-after", low = &low, high = &high),
        report::matrix_styled(&buffers.frame_rows(), &style)
    ));
    text.push_str(&format!(
        "{}\n{}",
        zsim::words!(lang, "step-depth-after", low = &low, high = &high),
        report::matrix_styled(&buffers.depth_rows(), &style)
    ));
    text
}

fn pixel_table(lang: zsim::Lang, rows: &[zsim::table::PixelRow], color: bool) -> Table {
    let mut table = Table::new();
    table.load_style(presets::ASCII_MARKDOWN).set_header(zsim::table::pixel_header(lang));
    for row in rows.iter().cloned() {
        let mut test = Cell::new(row.test);
        if color {
            test = test.fg(if row.written { Color::Green } else { Color::Red });
        }
        table.add_row(vec![
            Cell::new(row.x),
            Cell::new(row.centre),
            Cell::new(row.z),
            Cell::new(row.approx),
            Cell::new(row.step),
            Cell::new(row.stored),
            test,
            Cell::new(row.after),
            Cell::new(row.frame),
        ]);
    }
    table
}
