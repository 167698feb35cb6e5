//! `zsim step`: one scanline at a time, in a terminal or driven line by line
//! from standard input, with an optional quiz.

use std::io::{BufRead, IsTerminal, Write};
use std::path::PathBuf;

use clap::Args;
use comfy_table::{Cell, Color, Table, presets};
use zsim::Error;
use zsim::explain::{fate_text, polygon_name, scanline_text};
use zsim::report::{self, MatrixStyle};
use zsim::step::{Moved, Question, Quiz, Reply, Stepper, skip_text};
use zsim::{PixelEvent, Scene, Stop};
use zsim::{exact_and_decimal, fraction};

use super::{Failure, Finish, emit};

/// Arguments of `zsim step`.
#[derive(Debug, Args)]
pub struct StepArgs {
    /// The scene file (JSON), or - for standard input.
    scene: PathBuf,
    /// Show one step of this polygon (number from 1, or name) and exit; needs --scanline.
    #[arg(long, value_name = "N|NAME", requires = "scanline")]
    polygon: Option<String>,
    /// The row of the scanline to show (the scanline is at y = row + 1/2); needs --polygon.
    #[arg(long, value_name = "Y", requires = "polygon")]
    scanline: Option<u32>,
    /// A quiz: before each pixel's result, ask what the z-buffer will hold; `--quiz frame` asks what the framebuffer will hold; `--quiz coverage` first asks which centres the scanline covers. With --polygon and --scanline it starts there.
    #[arg(long, value_enum, num_args = 0..=1, default_missing_value = "depth", value_name = "depth|frame|coverage")]
    quiz: Option<QuizMode>,
    /// Write the stepper as one self-contained HTML page (-o FILE.html) instead of running it.
    #[arg(long, requires = "output", conflicts_with_all = ["polygon", "quiz"])]
    html: bool,
    /// The page to write, with --html.
    #[arg(short, long, value_name = "FILE.html", requires = "html")]
    output: Option<PathBuf>,
    /// Also show what an inexact arithmetic computes on each scanline: f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K.
    #[arg(long, default_value = "exact", value_parser = |text: &str| zsim::arith::Arith::parse(super::language_of_the_run(), text))]
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
    let text = zsim::read_text(lang, &args.scene)?;
    let scene = Scene::from_json(lang, &text, &args.scene)?;
    zsim::arith::check_supported(&scene, args.arith)?;
    let color = super::use_color();
    let mut stepper = Stepper::new(&scene, args.arith);
    if let (true, Some(output)) = (args.html, &args.output) {
        let name = args.scene.file_name().map_or_else(|| zsim::shown_path(&args.scene), |n| n.to_string_lossy().into());
        // The playground where this zsim was built with it (exact arithmetic only); the recorded stepper otherwise.
        let playground =
            (args.arith == zsim::arith::Arith::Exact).then(|| zsim::playground::one_file_page(lang, &text));
        let page = playground.flatten().unwrap_or_else(|| zsim::page::page(lang, &mut stepper, &name));
        let mut plan = zsim::Plan::new(&[&args.scene], zsim::Replace::Allowed);
        plan.file(output, page);
        plan.write()?;
        emit(out, &format!("{}\n", zsim::words!(lang, "file-written-page", path = zsim::shown_path(output))))?;
        return Ok(Finish::Ok);
    }
    let mut start = None;
    if let (Some(spec), Some(row)) = (&args.polygon, args.scanline) {
        let polygon = scene.find_polygon(spec)?;
        let trace = stepper.tracer().trace(polygon);
        if let Some(text) = fate_text(lang, trace.fate) {
            let name = scene.polygons[polygon].name.clone();
            return Err(Error::from(zsim::Usage::NoScanlines { index: polygon, name, why: text }).into());
        }
        let Some(scanline) = trace.scanlines.iter().position(|r| r.row == row) else {
            let rows = trace.scanlines.first().zip(trace.scanlines.last()).map(|(first, last)| (first.row, last.row));
            let name = scene.polygons[polygon].name.clone();
            return Err(Error::from(zsim::Usage::ScanlineNotReached { index: polygon, name, row, rows }).into());
        };
        let stop = Stop { polygon, scanline };
        if args.quiz.is_none() {
            emit(out, &stop_text(lang, &mut stepper, stop, color))?;
            return Ok(Finish::Ok);
        }
        start = Some(stop);
    }
    let mut quiz = args.quiz.map(|mode| Quiz::new(mode.into()));
    // On a terminal, the full-screen app; piped or redirected, the line mode scripts rely on.
    if std::io::stdin().is_terminal() && std::io::stdout().is_terminal() {
        stepper.start(start);
        crate::app::run(&mut crate::app::App::new(&mut stepper, quiz.as_mut(), lang))?;
        // The screen is gone: the score and each mistake stay on the terminal, as in the line mode.
        if let Some(quiz) = &quiz {
            emit(out, &quiz.summary(lang))?;
        }
        return Ok(Finish::Ok);
    }
    interactive(lang, &zsim::shown_path(&args.scene), &mut stepper, start, quiz.as_mut(), color, out)
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
    lines: std::io::Lines<std::io::StdinLock<'static>>,
    terminal: bool,
}

impl Input {
    fn stdin() -> Input {
        let stdin = std::io::stdin();
        Input { terminal: stdin.is_terminal(), lines: stdin.lock().lines() }
    }

    /// The next line; the prompt is shown only on a terminal. `None` at the end of input.
    fn read(&mut self, out: &mut dyn Write, prompt: &str) -> Result<Option<String>, Failure> {
        if self.terminal {
            emit(out, prompt)?;
            out.flush()?;
        }
        Ok(self.lines.next().transpose()?)
    }
}

/// What the user asked for at the prompt.
enum Command {
    Next,
    NextPolygon,
    Back,
    Go(u32),
    Quit,
    Unknown(String),
}

fn parse_command(line: &str) -> Command {
    let words: Vec<&str> = line.split_whitespace().collect();
    match words.as_slice() {
        [] | ["n"] => Command::Next,
        ["p"] => Command::NextPolygon,
        ["b"] => Command::Back,
        ["q"] => Command::Quit,
        ["g", row] => row.parse().map_or_else(|_| Command::Unknown(line.to_string()), Command::Go),
        _ => Command::Unknown(line.to_string()),
    }
}

/// The keys of the line mode, in words.
fn help(lang: zsim::Lang) -> String {
    zsim::words!(lang, "step-help")
}

/// What a move passed over, or why it stayed, as lines of the line mode.
fn moved_text(lang: zsim::Lang, scene: &Scene, moved: &Moved) -> String {
    match moved {
        Moved::To { skipped, .. } => {
            skipped.iter().map(|skip| format!("  · {}\n", skip_text(lang, scene, skip))).collect()
        }
        Moved::Refused(refusal) => format!("{}\n", refusal.text(lang, scene)),
    }
}

fn interactive(
    lang: zsim::Lang,
    path: &str,
    stepper: &mut Stepper<'_>,
    start: Option<Stop>,
    mut quiz: Option<&mut Quiz>,
    color: bool,
    out: &mut dyn Write,
) -> Result<Finish, Failure> {
    let scene = stepper.scene();
    let mut input = Input::stdin();
    emit(out, &format!("{}{}{}\n", report::scene_header(lang, scene, path), antialias_note(lang, scene), help(lang)))?;
    let moved = stepper.start(start);
    emit(out, &moved_text(lang, scene, &moved))?;
    let mut show = true;
    loop {
        let mut typed = None;
        match stepper.at() {
            Some(stop) if show => {
                if let Some(quiz) = quiz.as_deref_mut() {
                    match ask(lang, stepper, quiz, &mut input, out)? {
                        Asked::Answered => {}
                        Asked::Quit => break,
                        // A navigation key during the questions: leave them and go.
                        Asked::Navigate(line) => typed = Some(line),
                    }
                }
                if typed.is_none() {
                    emit(out, &stop_text(lang, stepper, stop, color))?;
                }
            }
            None if show => emit(out, &format!("{}\n", zsim::words!(lang, "step-end")))?,
            _ => {}
        }
        let line = match typed {
            Some(line) => line,
            None => match input.read(out, &zsim::words!(lang, "step-prompt"))? {
                Some(line) => line,
                None => break,
            },
        };
        let moved = match parse_command(&line) {
            Command::Quit => break,
            Command::Next => stepper.forward(),
            Command::NextPolygon => stepper.next_polygon(),
            Command::Back => stepper.back(),
            Command::Go(row) => stepper.go(row),
            Command::Unknown(text) => {
                emit(
                    out,
                    &format!(
                        "{}\n",
                        zsim::words!(
                            lang,
                            "step-unknown",
                            text = zsim::printable(&zsim::token(lang, &text)).into_owned(),
                            help = help(lang)
                        )
                    ),
                )?;
                show = false;
                continue;
            }
        };
        emit(out, &moved_text(lang, scene, &moved))?;
        show = !matches!(moved, Moved::Refused(_));
    }
    if let Some(quiz) = quiz {
        emit(out, &quiz.summary(lang))?;
    }
    Ok(Finish::Ok)
}

/// How one scanline's questions ended.
enum Asked {
    /// Every question answered.
    Answered,
    /// `q`, or the end of input.
    Quit,
    /// A navigation command typed instead of an answer: carried out.
    Navigate(String),
}

/// Reads lines until one is an answer, `q`, or a navigation command.
fn read_answer(
    input: &mut Input,
    out: &mut dyn Write,
    prompt: &str,
    hint: &str,
) -> Result<Result<String, Asked>, Failure> {
    loop {
        let Some(line) = input.read(out, prompt)? else { return Ok(Err(Asked::Quit)) };
        let answer = line.trim();
        if answer == "q" {
            return Ok(Err(Asked::Quit));
        }
        if matches!(parse_command(answer), Command::NextPolygon | Command::Back | Command::Go(_)) || answer == "n" {
            return Ok(Err(Asked::Navigate(answer.to_string())));
        }
        if !answer.is_empty() {
            return Ok(Ok(answer.to_string()));
        }
        emit(out, &format!("{hint}\n"))?;
    }
}

/// Asks the quiz's questions of the current stop, as the model orders them
/// (with `coverage`, first which centres the scanline covers; then, for each
/// covered pixel, what the z-buffer holds after it).
fn ask(
    lang: zsim::Lang,
    stepper: &mut Stepper<'_>,
    quiz: &mut Quiz,
    input: &mut Input,
    out: &mut dyn Write,
) -> Result<Asked, Failure> {
    let scene = stepper.scene();
    while let Some(question) = quiz.question(stepper) {
        let (prompt, hint) = match &question {
            Question::Coverage { stop, row } => {
                let ask = zsim::words!(
                    lang,
                    "quiz-coverage-ask",
                    polygon = polygon_name(lang, scene, stop.polygon),
                    scanline = scanline_text(lang, *row)
                );
                emit(out, &format!("{ask}\n"))?;
                (zsim::words!(lang, "quiz-coverage-prompt"), zsim::words!(lang, "quiz-coverage-hint"))
            }
            Question::Depth { stop, index, pixel } => {
                if *index == 0 {
                    let row = pixel.y;
                    let ask = zsim::words!(
                        lang,
                        "quiz-depth-ask",
                        polygon = polygon_name(lang, scene, stop.polygon),
                        scanline = scanline_text(lang, row)
                    );
                    emit(out, &format!("{ask}\n"))?;
                }
                let prompt = zsim::words!(
                    lang,
                    "quiz-depth-prompt",
                    x = pixel.x,
                    y = pixel.y,
                    stored = pixel.stored_before.text(lang)
                );
                (prompt, zsim::words!(lang, "quiz-depth-hint"))
            }
            Question::Frame { stop, index, pixel } => {
                if *index == 0 {
                    let ask = zsim::words!(
                        lang,
                        "quiz-frame-ask",
                        polygon = polygon_name(lang, scene, stop.polygon),
                        scanline = scanline_text(lang, pixel.y)
                    );
                    emit(out, &format!("{ask}\n"))?;
                }
                let prompt =
                    zsim::words!(lang, "quiz-frame-prompt", x = pixel.x, y = pixel.y, before = pixel.frame_before);
                (prompt, zsim::words!(lang, "quiz-frame-hint"))
            }
        };
        let verdict = loop {
            let typed = match read_answer(input, out, &prompt, &hint)? {
                Ok(typed) => typed,
                Err(asked) => return Ok(asked),
            };
            match quiz.answer(lang, stepper, &typed).expect("a question is asked") {
                Reply::Judged(verdict) => break verdict,
                Reply::AskAgain(why) => emit(out, &format!("{why}\n"))?,
            }
        };
        let right_or_wrong =
            if verdict.right { zsim::words!(lang, "tui-right") } else { zsim::words!(lang, "tui-wrong") };
        let (score, asked) = (quiz.right.to_string(), quiz.asked.to_string());
        let line = match &verdict.question {
            Question::Coverage { .. } => zsim::words!(
                lang,
                "quiz-coverage-verdict",
                right = &verdict.expected,
                said = &verdict.said,
                verdict = right_or_wrong,
                why = &verdict.why,
                score = score,
                asked = asked
            ),
            Question::Depth { pixel, .. } | Question::Frame { pixel, .. } => {
                let said = match (verdict.right, verdict.meant) {
                    (true, Some(meant)) => {
                        zsim::words!(lang, "quiz-said-meant", said = &verdict.said, meant = meant.text(lang))
                    }
                    _ => zsim::words!(lang, "quiz-said", said = &verdict.said),
                };
                zsim::words!(
                    lang,
                    "quiz-depth-verdict",
                    x = pixel.x,
                    y = pixel.y,
                    said = said,
                    verdict = right_or_wrong,
                    reason = &verdict.why,
                    score = score,
                    asked = asked
                )
            }
        };
        emit(out, &format!("  {line}\n"))?;
    }
    Ok(Asked::Answered)
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

/// Everything shown for one scanline of one polygon.
fn stop_text(lang: zsim::Lang, stepper: &mut Stepper<'_>, stop: Stop, color: bool) -> String {
    let scene = stepper.scene();
    let p = stop.polygon;
    let record = stepper.tracer().record(stop).clone();
    let geometry = scene.polygons[p].geometry();
    let slope = geometry.slope().map_or_else(String::new, fraction);
    let mut text = format!("\n── {}\n", report::polygon_heading(lang, scene, p));
    text.push_str(&antialias_note(lang, scene));
    text.push_str(&format!("   {}\n", zsim::words!(lang, "step-slope", slope = slope)));
    let heading =
        zsim::words!(lang, "step-scanline", scanline = scanline_text(lang, record.row), row = record.row.to_string());
    text.push_str(&format!("{heading}\n"));
    let crossings: Vec<String> = record.crossings.iter().map(|x| exact_and_decimal(lang, x)).collect();
    let list = if crossings.is_empty() {
        zsim::words!(lang, "step-crossings-none")
    } else {
        crossings.join(&zsim::words!(lang, "list-comma"))
    };
    text.push_str(&format!("{}\n", zsim::words!(lang, "step-crossings", list = list)));
    for line in zsim::stop::span_lines(lang, scene, &record) {
        text.push_str(&format!("{line}\n"));
    }
    if !record.pixels.is_empty() {
        text.push_str(&format!("{}\n", pixel_table(lang, scene, &record.pixels, color)));
    }
    for line in zsim::stop::notes(lang, scene, p, &record, stepper.arith()) {
        text.push_str(&format!("{line}\n"));
    }
    let buffers = stepper.tracer().buffers_after(stop);
    let low = record.row.saturating_sub(2);
    let high = (record.row + 2).min(scene.height - 1);
    let style = MatrixStyle { axes: true, color, rows: Some(low..=high), mark: Some(record.row) };
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

fn pixel_table(lang: zsim::Lang, scene: &Scene, pixels: &[PixelEvent], color: bool) -> Table {
    let mut table = Table::new();
    table.load_style(presets::ASCII_MARKDOWN).set_header(zsim::stop::pixel_header(lang));
    for row in zsim::stop::pixel_rows(lang, scene, pixels) {
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
