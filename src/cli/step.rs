//! `zsim step`: one scanline at a time, in a terminal or driven line by line
//! from standard input, with an optional quiz.

use std::io::{BufRead, IsTerminal, Write};
use std::path::PathBuf;

use clap::Args;
use comfy_table::{Cell, Color, Table, presets};
use zsim::Error;
use zsim::explain::{depth_text, fate_text, pixel_reason, polygon_name, scanline_text};
use zsim::report::{self, MatrixStyle};
use zsim::{Exact, Q, exact_and_decimal, fraction};
use zsim::{Meant, Scene, Skip, Tracer, does_not_fit, judge, skip_text};
use zsim::{Outcome, PixelEvent};

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
    /// A quiz: before each pixel's result, ask what the z-buffer will hold; `--quiz coverage` first asks which centres the scanline covers. With --polygon and --scanline it starts there.
    #[arg(long, value_enum, num_args = 0..=1, default_missing_value = "depth", value_name = "depth|coverage")]
    quiz: Option<QuizMode>,
    /// Write the stepper as one self-contained HTML page (-o FILE.html) instead of running it.
    #[arg(long, requires = "output", conflicts_with_all = ["polygon", "quiz"])]
    html: bool,
    /// The page to write, with --html.
    #[arg(short, long, value_name = "FILE.html", requires = "html")]
    output: Option<PathBuf>,
    /// Also show what an inexact arithmetic computes on each scanline: f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K.
    #[arg(long, default_value = "exact", value_parser = zsim::arith::Arith::parse)]
    arith: zsim::arith::Arith,
}

/// What the quiz asks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum QuizMode {
    /// The z-buffer value after each covered pixel.
    Depth,
    /// First which centres the scanline covers, then the z-buffer values.
    Coverage,
}

pub fn run(args: &StepArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let scene = Scene::load(&args.scene)?;
    zsim::arith::check_supported(&scene, args.arith)?;
    let color = super::use_color();
    let mut tracer = Tracer::new(&scene, args.arith);
    if let (true, Some(output)) = (args.html, &args.output) {
        let name =
            args.scene.file_name().map_or_else(|| args.scene.display().to_string(), |n| n.to_string_lossy().into());
        let page = super::page::page(&mut tracer, &name);
        super::not_an_input(output, &[&args.scene])?;
        std::fs::write(output, page).map_err(|source| Error::Write { path: output.clone(), source })?;
        emit(out, &format!("{}\n", zsim::words!("file-written-page", path = output.display().to_string())))?;
        return Ok(Finish::Ok);
    }
    let mut start = None;
    if let (Some(spec), Some(row)) = (&args.polygon, args.scanline) {
        let polygon = scene.find_polygon(spec)?;
        let trace = tracer.trace(polygon);
        if let Some(text) = fate_text(trace.fate) {
            let name = scene.polygons[polygon].name.clone();
            return Err(Error::from(zsim::Usage::NoScanlines { index: polygon, name, why: text }).into());
        }
        let Some(k) = trace.scanlines.iter().position(|r| r.row == row) else {
            let rows = trace.scanlines.first().zip(trace.scanlines.last()).map(|(first, last)| (first.row, last.row));
            let name = scene.polygons[polygon].name.clone();
            return Err(Error::from(zsim::Usage::ScanlineNotReached { index: polygon, name, row, rows }).into());
        };
        if args.quiz.is_none() {
            emit(out, &stop_text(&mut tracer, polygon, k, color))?;
            return Ok(Finish::Ok);
        }
        start = Some((polygon, k));
    }
    // On a terminal, the full-screen app; piped or redirected, the line mode scripts rely on.
    if std::io::stdin().is_terminal() && std::io::stdout().is_terminal() {
        let mut app = super::tui::App::new(&mut tracer, start, args.quiz.is_some());
        super::tui::run(&mut app)?;
        // The screen is gone: the score and each mistake stay on the terminal, as in the line mode.
        if let Some(summary) = app.quiz_summary() {
            emit(out, &summary)?;
        }
        return Ok(Finish::Ok);
    }
    interactive(&scene, &args.scene.display().to_string(), &mut tracer, (args.quiz, start), color, out)
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
fn help() -> String {
    zsim::words!("step-help")
}

fn interactive(
    scene: &Scene,
    path: &str,
    tracer: &mut Tracer<'_>,
    (quiz, start): (Option<QuizMode>, Option<(usize, usize)>),
    color: bool,
    out: &mut dyn Write,
) -> Result<Finish, Failure> {
    let mut input = Input::stdin();
    let mut quiz_state = QuizState::default();
    emit(out, &format!("{}{}{}\n", report::scene_header(scene, path), antialias_note(scene), help()))?;
    let mut position = match start {
        Some(at) => Some(at),
        None => {
            let (first, skipped) = tracer.next_stop(None);
            emit(out, &mentions(scene, &skipped))?;
            first
        }
    };
    let mut show = true;
    loop {
        let mut typed = None;
        match position {
            Some((p, k)) if show => {
                if let Some(mode) = quiz {
                    match ask(scene, tracer, (p, k), mode, &mut quiz_state, &mut input, out)? {
                        Asked::Answered => {}
                        Asked::Quit => break,
                        // A navigation key during the questions: leave them and go.
                        Asked::Navigate(line) => typed = Some(line),
                    }
                }
                if typed.is_none() {
                    emit(out, &stop_text(tracer, p, k, color))?;
                }
            }
            None if show => emit(out, &format!("{}\n", zsim::words!("step-end")))?,
            _ => {}
        }
        let line = match typed {
            Some(line) => line,
            None => match input.read(out, &zsim::words!("step-prompt"))? {
                Some(line) => line,
                None => break,
            },
        };
        show = true;
        match parse_command(&line) {
            Command::Quit => break,
            Command::Next => {
                let (next, skipped) = match position {
                    Some(at) => tracer.next_stop(Some(at)),
                    None => (None, Vec::new()),
                };
                emit(out, &mentions(scene, &skipped))?;
                position = next;
            }
            Command::NextPolygon => {
                let from = position.map(|(p, _)| {
                    let count = tracer.trace(p).scanlines.len();
                    (p, count.saturating_sub(1))
                });
                if from.is_some() {
                    let (next, skipped) = tracer.next_stop(from);
                    emit(out, &mentions(scene, &skipped))?;
                    position = next;
                }
            }
            Command::Back => {
                let previous = match position {
                    Some(at) => tracer.previous_stop(at),
                    None => tracer.previous_stop((scene.polygons.len(), 0)),
                };
                match previous {
                    Some(at) => position = Some(at),
                    None => {
                        emit(out, &format!("{}\n", zsim::words!("step-first")))?;
                        show = false;
                    }
                }
            }
            Command::Go(row) if row >= scene.height => {
                let last = (scene.height - 1).to_string();
                emit(out, &format!("{}\n", zsim::words!("step-outside-raster", row = row.to_string(), last = last)))?;
                show = false;
            }
            Command::Go(row) => {
                let p = position.map_or(0, |(p, _)| p).min(scene.polygons.len().saturating_sub(1));
                let found = tracer.trace(p).scanlines.iter().position(|r| r.row == row);
                match found {
                    Some(k) => position = Some((p, k)),
                    None => {
                        let message = zsim::words!(
                            "step-not-reach",
                            polygon = polygon_name(scene, p),
                            scanline = scanline_text(row)
                        ) + "\n";
                        emit(out, &message)?;
                        show = false;
                    }
                }
            }
            Command::Unknown(text) => {
                emit(out, &format!("{}\n", zsim::words!("step-unknown", text = text, help = help())))?;
                show = false;
            }
        }
    }
    if quiz.is_some() {
        emit(out, &quiz_state.summary())?;
    }
    Ok(Finish::Ok)
}

/// The quiz's score and the mistakes made, for the summary.
#[derive(Debug, Default)]
pub(super) struct QuizState {
    pub(super) right: usize,
    pub(super) asked: usize,
    mistakes: Vec<String>,
}

impl QuizState {
    /// Scores one answer and says so: `right` or `wrong` with the reason.
    pub(super) fn score(&mut self, right: bool, mistake: impl FnOnce() -> String) -> String {
        self.asked += 1;
        if right {
            self.right += 1;
            zsim::words!("tui-right")
        } else {
            self.mistakes.push(mistake());
            zsim::words!("tui-wrong")
        }
    }

    /// The score, and each mistake with what was right and why.
    pub(super) fn summary(&self) -> String {
        let score = zsim::words!("quiz-score", right = self.right.to_string(), asked = self.asked.to_string());
        let mut text = format!("{score}\n");
        if !self.mistakes.is_empty() {
            text.push_str(&format!("{}\n", zsim::words!("quiz-mistakes")));
            for mistake in &self.mistakes {
                text.push_str(&format!("  {mistake}\n"));
            }
        }
        text
    }
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

/// What a quiz answer meant, in words.
fn meant_text(meant: Meant) -> String {
    {
        match meant {
            Meant::NotWritten => zsim::words!("meant-not-written"),
            Meant::ValueWritten => zsim::words!("meant-value-written"),
            Meant::ValueKept => zsim::words!("meant-value-kept"),
            Meant::Value => zsim::words!("meant-value"),
        }
    }
}

/// Reads lines until one is an answer (`-` or a number), `q`, or a navigation command.
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

/// The covered columns as a student writes them: `16-27`, `3-5 9-12`, or `-` for none.
fn columns_text(columns: &[u32]) -> String {
    let mut runs: Vec<(u32, u32)> = Vec::new();
    for &x in columns {
        match runs.last_mut() {
            Some((_, last)) if *last + 1 == x => *last = x,
            _ => runs.push((x, x)),
        }
    }
    if runs.is_empty() {
        return "-".to_string();
    }
    runs.iter().map(|(a, b)| if a == b { a.to_string() } else { format!("{a}-{b}") }).collect::<Vec<_>>().join(" ")
}

/// Reads `16-27`, `3-5 9-12`, `4` or `-` as columns; `None` when it is not that.
fn parse_columns(text: &str) -> Option<Vec<u32>> {
    if text == "-" {
        return Some(Vec::new());
    }
    let mut columns = Vec::new();
    for run in text.split([' ', ',']).filter(|r| !r.is_empty()) {
        let (a, b) = run.split_once(['-', '…']).unwrap_or((run, run));
        let (a, b): (u32, u32) = (a.trim().parse().ok()?, b.trim().parse().ok()?);
        if a > b || b - a > 100_000 {
            return None;
        }
        columns.extend(a..=b);
    }
    columns.sort_unstable();
    columns.dedup();
    Some(columns)
}

fn mentions(scene: &Scene, skipped: &[Skip]) -> String {
    skipped.iter().map(|skip| format!("  · {}\n", skip_text(scene, skip))).collect()
}

/// Asks the quiz questions of a stop: with `coverage`, first which centres
/// the scanline covers; then, for each covered pixel, what the z-buffer holds after it.
fn ask(
    scene: &Scene,
    tracer: &mut Tracer<'_>,
    (p, k): (usize, usize),
    mode: QuizMode,
    state: &mut QuizState,
    input: &mut Input,
    out: &mut dyn Write,
) -> Result<Asked, Failure> {
    let record = tracer.trace(p).scanlines[k].clone();
    let (name, row) = (polygon_name(scene, p), record.row);
    let of_name = zsim::explain::polygon_after(scene, p);
    if mode == QuizMode::Coverage {
        let ask = zsim::words!("quiz-coverage-ask", polygon = &name, scanline = scanline_text(row));
        emit(out, &format!("{ask}\n"))?;
        let covered: Vec<u32> = record.pixels.iter().map(|e| e.x).collect();
        let hint = zsim::words!("quiz-coverage-hint");
        let columns = loop {
            let answer = match read_answer(input, out, &zsim::words!("quiz-coverage-prompt"), &hint)? {
                Ok(answer) => answer,
                Err(asked) => return Ok(asked),
            };
            match parse_columns(&answer) {
                Some(columns) => break (answer, columns),
                None => emit(out, &format!("{hint}\n"))?,
            }
        };
        let right_text = columns_text(&covered);
        let spans: Vec<String> = record
            .spans
            .iter()
            .map(|s| zsim::words!("span", left = exact_and_decimal(&s.left), right = exact_and_decimal(&s.right)))
            .collect();
        let why = zsim::words!("quiz-coverage-why", spans = spans.join(&zsim::words!("list-comma")));
        let verdict = state.score(columns.1 == covered, || {
            zsim::words!(
                "quiz-coverage-mistake",
                row = row.to_string(),
                polygon = &of_name,
                said = &columns.0,
                right = &right_text,
                why = &why
            )
        });
        let line = zsim::words!(
            "quiz-coverage-verdict",
            right = &right_text,
            said = &columns.0,
            verdict = verdict,
            why = &why,
            score = state.right.to_string(),
            asked = state.asked.to_string()
        );
        emit(out, &format!("  {line}\n"))?;
    }
    let ask = zsim::words!("quiz-depth-ask", polygon = &name, scanline = scanline_text(row));
    emit(out, &format!("{ask}\n"))?;
    let hint = zsim::words!("quiz-depth-hint");
    for pixel in &record.pixels {
        let prompt =
            zsim::words!("quiz-depth-prompt", x = pixel.x, y = pixel.y, stored = pixel.stored_before.to_string());
        let answer = loop {
            let text = match read_answer(input, out, &prompt, &hint)? {
                Ok(text) => text,
                Err(asked) => return Ok(asked),
            };
            if let Some(problem) = does_not_fit(scene, &text) {
                emit(out, &format!("{problem}\n"))?;
                continue;
            }
            match judge(pixel, &text) {
                Some(judged) => break (text, judged),
                None => emit(out, &format!("{}\n", zsim::words!("quiz-not-an-answer", text = &text, hint = &hint)))?,
            }
        };
        let (right, meant) = answer.1;
        let written = pixel.outcome == Outcome::Written;
        let expected = if written {
            pixel.stored_after.to_string()
        } else {
            zsim::words!("quiz-keeps", value = pixel.stored_after.to_string())
        };
        let reason = pixel_reason(scene, pixel);
        let verdict = state.score(right, || {
            zsim::words!(
                "quiz-depth-mistake",
                x = pixel.x,
                y = pixel.y,
                polygon = &of_name,
                said = &answer.0,
                right = &expected,
                reason = &reason
            )
        });
        let said = if right {
            zsim::words!("quiz-said-meant", said = &answer.0, meant = meant_text(meant))
        } else {
            zsim::words!("quiz-said", said = &answer.0)
        };
        let line = zsim::words!(
            "quiz-depth-verdict",
            x = pixel.x,
            y = pixel.y,
            said = said,
            verdict = verdict,
            reason = &reason,
            score = state.right.to_string(),
            asked = state.asked.to_string()
        );
        emit(out, &format!("  {line}\n"))?;
    }
    Ok(Asked::Answered)
}

/// For an antialiased scene, what `step` shows and what it does not.
fn antialias_note(scene: &Scene) -> String {
    match scene.effects.antialias {
        Some(settings) => format!("   {}\n", zsim::words!("step-antialias-note", k = settings.samples.to_string())),
        None => String::new(),
    }
}

/// Everything shown for one scanline of one polygon.
fn stop_text(tracer: &mut Tracer<'_>, p: usize, k: usize, color: bool) -> String {
    let scene = tracer.scene;
    let record = tracer.trace(p).scanlines[k].clone();
    let geometry = scene.polygons[p].geometry();
    let slope = geometry.slope().map_or_else(String::new, fraction);
    let mut text = format!("\n── {}\n", report::polygon_heading(scene, p));
    text.push_str(&antialias_note(scene));
    text.push_str(&format!("   {}\n", zsim::words!("step-slope", slope = slope)));
    let heading = zsim::words!("step-scanline", scanline = scanline_text(record.row), row = record.row.to_string());
    text.push_str(&format!("{heading}\n"));
    let crossings: Vec<String> = record.crossings.iter().map(exact_and_decimal).collect();
    let list = if crossings.is_empty() {
        zsim::words!("step-crossings-none")
    } else {
        crossings.join(&zsim::words!("list-comma"))
    };
    text.push_str(&format!("{}\n", zsim::words!("step-crossings", list = list)));
    for (n, span) in record.spans.iter().enumerate() {
        let columns = match span.columns {
            Some((first, last)) => {
                zsim::words!("step-columns", first = first.to_string(), last = last.to_string())
            }
            None => zsim::words!("step-no-column"),
        };
        let depth = |z: &Option<Exact>| z.as_ref().map_or_else(|| zsim::words!("z-beyond"), |z| depth_text(scene, z));
        let line = zsim::words!(
            "step-span",
            n = (n + 1).to_string(),
            xa = exact_and_decimal(&span.left),
            za = depth(&span.left_depth),
            xb = exact_and_decimal(&span.right),
            zb = depth(&span.right_depth),
            columns = columns
        );
        text.push_str(&format!("{line}\n"));
    }
    if !record.pixels.is_empty() {
        text.push_str(&format!("{}\n", pixel_table(scene, &record.pixels, color)));
    }
    // Centres exactly on the polygon's boundary along this scanline, and the rule deciding each.
    for x in 0..scene.width {
        if let Some(tie) = zsim::tie::tie_text(scene.rules, &scene.polygons[p].vertices(), x, record.row) {
            text.push_str(&format!("{}\n", zsim::words!("step-tie", x = x.to_string(), text = tie)));
        }
    }
    if let zsim::arith::Arith::Fixed(bits) = tracer.arith {
        let line = zsim::words!("step-fixed", bits = bits.to_string(), unit = (1u64 << bits).to_string());
        text.push_str(&format!("{line}\n"));
    }
    if let Some(float) = zsim::arith::float_scanline(scene, p, record.row, tracer.arith) {
        let crossings: Vec<String> = float.crossings.iter().map(|x| format!("{x:.9}")).collect();
        let pixels: Vec<String> = float
            .pixels
            .iter()
            .map(|(x, z)| {
                let exact = record.pixels.iter().find(|e| e.x == *x).map(|e| e.depth.value());
                let note = match exact {
                    Some(e) => zsim::words!("step-float-exact", z = zsim::decimal(e, 9)),
                    None => zsim::words!("step-float-not-exact"),
                };
                format!("x = {x}: z = {z:.9} ({note})")
            })
            .collect();
        let missed: Vec<String> = record
            .pixels
            .iter()
            .filter(|e| !float.pixels.iter().any(|(x, _)| *x == e.x))
            .map(|e| e.x.to_string())
            .collect();
        let found = match float.bounding_columns {
            Some((first, last)) => {
                zsim::words!("step-float-edges", first = first.to_string(), last = last.to_string())
            }
            None if crossings.is_empty() => zsim::words!("step-float-no-crossings"),
            None => zsim::words!("step-float-crossings", crossings = crossings.join(", ")),
        };
        let heading = zsim::words!("step-float-heading", arith = tracer.arith.to_string(), found = found);
        let pixels = if pixels.is_empty() { zsim::words!("step-float-no-pixel") } else { pixels.join("\n  ") };
        text.push_str(&format!("{heading}\n  {pixels}\n"));
        if !missed.is_empty() {
            let line = zsim::words!("step-float-missed", columns = missed.join(", "));
            text.push_str(&format!("  {line}\n"));
        }
    }
    let buffers = tracer.buffers_after(p, k);
    let low = record.row.saturating_sub(2);
    let high = (record.row + 2).min(scene.height - 1);
    let style = MatrixStyle { axes: true, color, rows: Some(low..=high), mark: Some(record.row) };
    let (low, high) = (low.to_string(), high.to_string());
    text.push_str(&format!(
        "{}\n{}",
        zsim::words!("step-frame-after", low = &low, high = &high),
        report::matrix_styled(&buffers.frame_rows(), &style)
    ));
    text.push_str(&format!(
        "{}\n{}",
        zsim::words!("step-depth-after", low = &low, high = &high),
        report::matrix_styled(&buffers.depth_rows(), &style)
    ));
    text
}

fn pixel_table(scene: &Scene, pixels: &[PixelEvent], color: bool) -> Table {
    let mut table = Table::new();
    table.load_style(presets::ASCII_MARKDOWN).set_header([
        "x".to_string(),
        zsim::words!("step-col-centre"),
        "z".to_string(),
        "≈ z".to_string(),
        zsim::words!("step-col-step"),
        zsim::words!("step-col-stored"),
        zsim::words!("step-col-test"),
        zsim::words!("step-col-after"),
        zsim::words!("step-col-frame"),
    ]);
    let depth_test = scene.depth_test;
    let op = depth_test.symbol();
    for (i, pixel) in pixels.iter().enumerate() {
        let z = pixel.depth.value();
        let step = match i.checked_sub(1).map(|j| &pixels[j]) {
            Some(previous) if previous.x + 1 == pixel.x => fraction(z.minus(&previous.depth.value())),
            _ => zsim::words!("step-start"),
        };
        // `always` and `never` compare nothing: they say so instead of a symbol.
        let uncompared = |passed| depth_test.outcome_text(&fraction(&z), &pixel.stored_before.to_string(), passed);
        let test = match pixel.outcome {
            Outcome::Written if !depth_test.compares() => zsim::words!("step-written", test = uncompared(true)),
            Outcome::Hidden if !depth_test.compares() => zsim::words!("step-hidden", test = uncompared(false)),
            Outcome::Written => {
                zsim::words!("step-test-written", z = fraction(&z), op = op, stored = pixel.stored_before.to_string())
            }
            Outcome::Hidden => {
                zsim::words!("step-test-hidden", z = fraction(&z), op = op, stored = pixel.stored_before.to_string())
            }
            Outcome::BeyondSection => {
                zsim::words!("step-beyond-section", op = op, stored = pixel.stored_before.to_string())
            }
            Outcome::OutsideDepthRange => zsim::words!("step-outside-range", z = fraction(&z)),
        };
        let mut test = Cell::new(test);
        if color {
            test = test.fg(if pixel.outcome == Outcome::Written { Color::Green } else { Color::Red });
        }
        table.add_row(vec![
            Cell::new(pixel.x),
            Cell::new(exact_and_decimal(Q::new(2 * i128::from(pixel.x) + 1, 2))),
            Cell::new(fraction(&z)),
            Cell::new(zsim::localize_decimal(zsim::decimal(z, 2))),
            Cell::new(step),
            Cell::new(&pixel.stored_before),
            test,
            Cell::new(&pixel.stored_after),
            Cell::new(pixel.frame_after),
        ]);
    }
    table
}
