//! `zsim step` on a terminal: a full-screen app redrawn in place. The raster
//! on the left (framebuffer or z-buffer) with the scanline marked, the
//! current span highlighted and this polygon's earlier pixels set apart; on
//! the right the polygon, the scanline, its crossings and spans, and the
//! current pixel's row of the table. Keys act without Enter. Everything shown
//! comes from the same recorded trace as the line mode ([`super::step`]).

use ratatui::Frame;
use ratatui::crossterm::event::{self, Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers};
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Wrap};
use zsim::Buffers;
use zsim::explain::{pixel_reason, polygon_name, scanline_text};
use zsim::report;
use zsim::{Outcome, ScanlineRecord};
use zsim::{Q, exact_and_decimal, fraction};

use zsim::Tracer;

/// Which buffer the raster shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum View {
    /// The framebuffer.
    Frame,
    /// The z-buffer.
    Depth,
}

/// The quiz inside the app: the answer being typed, and the score with
/// each mistake (the summary printed when the app closes).
#[derive(Debug, Default)]
struct Quiz {
    typed: String,
    /// The verdict on the last answer, shown until the next key.
    verdict: Option<String>,
    state: super::step::QuizState,
}

/// The stepper's state. Keys change it ([`App::key`]); [`App::draw`] shows it.
pub struct App<'t, 's> {
    tracer: &'t mut Tracer<'s>,
    /// The current stop: polygon and recorded scanline; `None` at the end.
    at: Option<(usize, usize)>,
    /// In pixel steps, how many of the scanline's pixels are done (shown);
    /// in scanline steps, `None` (all of them).
    pixel: Option<usize>,
    view: View,
    help: bool,
    /// The `g` prompt's text while it is open.
    go: Option<String>,
    message: String,
    /// Rows and columns the raster is scrolled by, from where it centres itself.
    scroll: (i32, i32),
    /// Lines the right panel is scrolled by.
    table_scroll: u16,
    quiz: Option<Quiz>,
    /// Set by `q`, Esc or Ctrl-C.
    pub quit: bool,
}

impl<'t, 's> App<'t, 's> {
    /// The app at `start`, or at the first scanline that covers a pixel.
    pub fn new(tracer: &'t mut Tracer<'s>, start: Option<(usize, usize)>, quiz: bool) -> App<'t, 's> {
        let at = start.or_else(|| tracer.next_stop(None).0);
        App {
            tracer,
            at,
            pixel: quiz.then_some(0),
            view: View::Frame,
            help: false,
            go: None,
            message: String::new(),
            scroll: (0, 0),
            table_scroll: 0,
            quiz: quiz.then(Quiz::default),
            quit: false,
        }
    }

    fn record(&mut self) -> Option<ScanlineRecord> {
        let (p, k) = self.at?;
        Some(self.tracer.trace(p).scanlines[k].clone())
    }

    /// Handles one key press.
    pub fn key(&mut self, key: KeyEvent) {
        self.message.clear();
        if key.modifiers.contains(KeyModifiers::CONTROL) && key.code == KeyCode::Char('c') {
            self.quit = true;
            return;
        }
        if let Some(text) = &mut self.go {
            match key.code {
                KeyCode::Char(c) if c.is_ascii_digit() => text.push(c),
                KeyCode::Backspace => {
                    text.pop();
                }
                KeyCode::Enter => {
                    let row = text.parse::<u32>().ok();
                    self.go = None;
                    if let Some(row) = row {
                        self.go_to(row);
                    }
                }
                KeyCode::Esc => self.go = None,
                _ => {}
            }
            return;
        }
        // A digit or `-` while a verdict shows starts the next answer (it is not lost).
        if let Some(quiz) = &mut self.quiz
            && quiz.verdict.is_some()
            && matches!(key.code, KeyCode::Char(c) if c.is_ascii_digit() || c == '-')
        {
            quiz.verdict = None;
        }
        if self.quiz.is_some() && self.asking() && self.quiz_key(key) {
            return;
        }
        if self.help && !matches!(key.code, KeyCode::Char('q') | KeyCode::Esc) {
            self.help = false;
            return;
        }
        match key.code {
            KeyCode::Char('q') | KeyCode::Esc => self.quit = true,
            KeyCode::Char('n' | ' ') | KeyCode::Enter | KeyCode::Right | KeyCode::Down => self.next(),
            KeyCode::Char('b') | KeyCode::Left | KeyCode::Up => self.back(),
            KeyCode::Char('p') => self.next_polygon(),
            KeyCode::Char('P') => self.previous_polygon(),
            KeyCode::Char('g') => self.go = Some(String::new()),
            KeyCode::Char('f') => self.view = View::Frame,
            KeyCode::Char('z') => self.view = View::Depth,
            KeyCode::Char('m') if self.quiz.is_none() => {
                self.pixel = if self.pixel.is_some() { None } else { Some(1) };
            }
            KeyCode::Char('?') => self.help = true,
            KeyCode::PageUp => self.scroll.0 -= 4,
            KeyCode::PageDown => self.scroll.0 += 4,
            KeyCode::Char('<') => self.scroll.1 -= 4,
            KeyCode::Char('>') => self.scroll.1 += 4,
            KeyCode::Char('[') => self.table_scroll = self.table_scroll.saturating_sub(4),
            KeyCode::Char(']') => self.table_scroll += 4,
            _ => self.message = zsim::words!("tui-key-nothing"),
        }
    }

    /// Whether the quiz waits for the value of the next pixel.
    fn asking(&mut self) -> bool {
        let Some(record) = self.record() else { return false };
        let done = self.pixel.unwrap_or(0);
        done < record.pixels.len() && self.quiz.as_ref().is_some_and(|q| q.verdict.is_none())
    }

    /// A key while the quiz asks. Typing: any character but the keys that
    /// act alone (`q`, `?`, and `n`, `b`, `p`, `P`, `g`, `f`, `z` before
    /// anything is typed) goes into the answer, Backspace takes one back,
    /// Enter answers: a number or `-` is scored, anything else is said to be
    /// no answer (or a number the z-buffer cannot hold, out of range) and
    /// asked again. Returns `false` for a key that acts as usual.
    fn quiz_key(&mut self, key: KeyEvent) -> bool {
        let Some(record) = self.record() else { return false };
        let (scene, p) = (self.tracer.scene, self.at.map_or(0, |at| at.0));
        let Some(quiz) = &mut self.quiz else { return false };
        match key.code {
            KeyCode::Char('q' | '?') => return false,
            KeyCode::Char('n' | 'b' | 'p' | 'P' | 'g' | 'f' | 'z' | ' ') if quiz.typed.is_empty() => return false,
            KeyCode::Char(c) if !c.is_control() => quiz.typed.push(c),
            KeyCode::Backspace => {
                quiz.typed.pop();
            }
            KeyCode::Enter if !quiz.typed.is_empty() => {
                let done = self.pixel.unwrap_or(0);
                let pixel = record.pixels[done].clone();
                let typed = std::mem::take(&mut quiz.typed);
                if let Some(problem) = zsim::does_not_fit(scene, &typed) {
                    self.message = problem;
                    return true;
                }
                let Some((right, _)) = zsim::judge(&pixel, &typed) else {
                    let hint = zsim::words!("quiz-depth-hint");
                    self.message = zsim::words!("quiz-not-an-answer", text = zsim::token(&typed), hint = hint);
                    return true;
                };
                let reason = pixel_reason(scene, &pixel);
                let verdict = quiz.state.score(right, || {
                    let expected = if pixel.outcome == zsim::Outcome::Written {
                        pixel.stored_after.to_string()
                    } else {
                        zsim::words!("quiz-keeps", value = pixel.stored_after.to_string())
                    };
                    zsim::words!(
                        "quiz-depth-mistake",
                        x = pixel.x,
                        y = pixel.y,
                        polygon = zsim::explain::polygon_after(scene, p),
                        said = &typed,
                        right = expected,
                        reason = &reason
                    )
                });
                quiz.verdict = Some(zsim::words!(
                    "tui-quiz-verdict",
                    x = pixel.x,
                    y = pixel.y,
                    typed = &typed,
                    verdict = verdict,
                    reason = reason
                ));
                self.pixel = Some(done + 1);
            }
            _ => return false,
        }
        true
    }

    /// The quiz's score and each mistake, to print when the app has closed
    /// (as the line mode ends); `None` without a quiz.
    pub fn quiz_summary(&self) -> Option<String> {
        self.quiz.as_ref().map(|quiz| quiz.state.summary())
    }

    fn next(&mut self) {
        if let Some(quiz) = &mut self.quiz {
            quiz.verdict = None;
        }
        let Some(at) = self.at else { return };
        if let Some(done) = self.pixel {
            let count = self.tracer.trace(at.0).scanlines[at.1].pixels.len();
            if done < count {
                if self.quiz.is_none() {
                    self.pixel = Some(done + 1);
                }
                return;
            }
        }
        let (next, skipped) = self.tracer.next_stop(Some(at));
        if !skipped.is_empty() {
            let scene = self.tracer.scene;
            let skipped: Vec<String> = skipped.iter().map(|skip| zsim::skip_text(scene, skip)).collect();
            self.message = zsim::words!("tui-passed-over", list = skipped.join(&zsim::words!("list-semicolon")));
        }
        match next {
            Some(stop) => self.arrive(stop),
            None => self.message = zsim::words!("step-end"),
        }
    }

    fn back(&mut self) {
        let Some(at) = self.at else { return };
        match self.pixel {
            Some(done) if done > 1 && self.quiz.is_none() => self.pixel = Some(done - 1),
            _ => match self.tracer.previous_stop(at) {
                Some(stop) => self.arrive(stop),
                None => self.message = zsim::words!("step-first"),
            },
        }
    }

    fn arrive(&mut self, stop: (usize, usize)) {
        self.at = Some(stop);
        self.scroll = (0, 0);
        self.table_scroll = 0;
        if self.pixel.is_some() {
            self.pixel = Some(if self.quiz.is_some() { 0 } else { 1 });
        }
    }

    fn next_polygon(&mut self) {
        let Some((p, _)) = self.at else { return };
        let last = self.tracer.trace(p).scanlines.len().saturating_sub(1);
        match self.tracer.next_stop(Some((p, last))).0 {
            Some(stop) => self.arrive(stop),
            None => self.message = zsim::words!("tui-no-later"),
        }
    }

    fn previous_polygon(&mut self) {
        let Some((p, _)) = self.at else { return };
        let mut stop = self.tracer.previous_stop((p, 0));
        // To the first covering scanline of that polygon.
        while let Some(s) = stop {
            match self.tracer.previous_stop(s) {
                Some(earlier) if earlier.0 == s.0 => stop = Some(earlier),
                _ => break,
            }
        }
        match stop {
            Some(s) => self.arrive(s),
            None => self.message = zsim::words!("tui-no-earlier"),
        }
    }

    fn go_to(&mut self, row: u32) {
        let scene = self.tracer.scene;
        if row >= scene.height {
            let last = (scene.height - 1).to_string();
            self.message = zsim::words!("step-outside-raster", row = row.to_string(), last = last);
            return;
        }
        let p = self.at.map_or(0, |(p, _)| p);
        match self.tracer.trace(p).scanlines.iter().position(|r| r.row == row) {
            Some(k) => self.arrive((p, k)),
            None => {
                self.message =
                    zsim::words!("step-not-reach", polygon = polygon_name(scene, p), scanline = scanline_text(row))
            }
        }
    }

    /// Draws the whole screen.
    pub fn draw(&mut self, frame: &mut Frame<'_>) {
        let area = frame.area();
        let [title, body, status] =
            Layout::vertical([Constraint::Length(1), Constraint::Min(3), Constraint::Length(2)]).areas(area);
        let scene = self.tracer.scene;
        let record = self.record();
        let heading = match (self.at, &record) {
            (Some((p, _)), Some(r)) => {
                zsim::words!("tui-heading", polygon = polygon_name(scene, p), scanline = scanline_text(r.row))
            }
            _ => zsim::words!("tui-heading-end"),
        };
        let view = match self.view {
            View::Frame => zsim::words!("buffer-frame"),
            View::Depth => zsim::words!("buffer-depth"),
        };
        let score = self.quiz.as_ref().map_or(String::new(), |q| {
            zsim::words!("tui-score", right = q.state.right.to_string(), asked = q.state.asked.to_string())
        });
        frame.render_widget(
            Paragraph::new(zsim::words!("tui-title", heading = heading, view = view, score = score))
                .style(Style::new().add_modifier(Modifier::REVERSED)),
            title,
        );
        let raster_width = (area.width * 11 / 20).max(20);
        let [left, right] = Layout::horizontal([Constraint::Length(raster_width), Constraint::Min(20)]).areas(body);
        self.draw_raster(frame, left, record.as_ref());
        if self.help {
            // Over the raster too, as wide as its longest line allows, so that a key and what it
            // does stay on one line (in the right pane alone they wrapped apart on 80×24).
            let text = ratatui::text::Text::from(zsim::words!("tui-help"));
            let width = (text.width() as u16 + 2).min(body.width);
            let height = (text.height() as u16 + 2).min(body.height);
            let area = Rect { x: body.x + (body.width - width) / 2, y: body.y, width, height };
            let help = Paragraph::new(text)
                .wrap(Wrap { trim: false })
                .block(Block::bordered().title(zsim::words!("tui-keys")));
            frame.render_widget(Clear, area);
            frame.render_widget(help, area);
        } else {
            let lines = self.details(record.as_ref());
            frame.render_widget(
                Paragraph::new(lines)
                    .wrap(Wrap { trim: false })
                    .scroll((self.table_scroll, 0))
                    .block(Block::new().borders(Borders::LEFT)),
                right,
            );
        }
        let status_text = if let Some(text) = &self.go {
            zsim::words!("tui-go", text = text)
        } else if let Some(verdict) = self.quiz.as_ref().and_then(|q| q.verdict.clone()) {
            zsim::words!("tui-verdict-next", verdict = verdict)
        } else if self.quiz.is_some() && self.asking() {
            let record = record.as_ref().expect("asking implies a scanline");
            let pixel = &record.pixels[self.pixel.unwrap_or(0)];
            let typed = self.quiz.as_ref().map_or("", |q| q.typed.as_str());
            let ask = zsim::words!(
                "tui-quiz-ask",
                x = pixel.x,
                y = pixel.y,
                stored = pixel.stored_before.to_string(),
                typed = typed
            );
            // Why the last answer was asked again, before the question.
            if self.message.is_empty() { ask } else { format!("{} {ask}", self.message) }
        } else if !self.message.is_empty() {
            self.message.clone()
        } else {
            zsim::words!("tui-status")
        };
        frame.render_widget(Paragraph::new(status_text).wrap(Wrap { trim: true }), status);
    }

    /// The raster's rows that fit, top row first, centred on the scanline.
    fn draw_raster(&mut self, frame: &mut Frame<'_>, area: Rect, record: Option<&ScanlineRecord>) {
        let scene = self.tracer.scene;
        let Some((p, k)) = self.at else {
            frame.render_widget(Paragraph::new(zsim::words!("tui-no-scanline")), area);
            return;
        };
        let done = self.pixel.unwrap_or(usize::MAX);
        let buffers: Buffers = self.tracer.buffers_through(p, k, done);
        let values: Vec<Vec<String>> = match self.view {
            View::Frame => buffers.frame_rows().iter().map(|r| r.iter().map(u32::to_string).collect()).collect(),
            View::Depth => {
                buffers.depth_rows().iter().map(|r| r.iter().map(report::MatrixCell::text).collect()).collect()
            }
        };
        let cell = values.iter().flatten().map(String::len).max().unwrap_or(1) + 1;
        let (width, height) = (scene.width as i32, scene.height as i32);
        // Below the rows: the column numbers, then which columns are shown.
        let rows_shown = (area.height as i32 - 2).max(1);
        let columns_shown = ((area.width as i32 - 5) / cell as i32).max(1);
        let row = record.map_or(0, |r| r.row as i32);
        let (span_first, span_last) = record
            .and_then(|r| r.spans.iter().filter_map(|s| s.columns).reduce(|a, b| (a.0.min(b.0), a.1.max(b.1))))
            .map_or((0, 0), |(a, b)| (a as i32, b as i32));
        // Top row shown, and first column shown: centred, then scrolled, then kept on the raster.
        let top = (row + rows_shown / 2 - self.scroll.0).clamp((rows_shown - 1).min(height - 1), height - 1);
        let first =
            ((span_first + span_last) / 2 - columns_shown / 2 + self.scroll.1).clamp(0, (width - columns_shown).max(0));
        let trace_pixels: std::collections::HashSet<(u32, u32)> = self.tracer.trace(p).scanlines[..k]
            .iter()
            .flat_map(|r| r.pixels.iter().filter(|e| e.outcome == Outcome::Written).map(|e| (e.x, e.y)))
            .collect();
        let current: Vec<u32> = record.map_or(Vec::new(), |r| r.pixels.iter().map(|e| e.x).collect());
        let focus = record.and_then(|r| done.checked_sub(1).and_then(|i| r.pixels.get(i))).map(|e| e.x);
        let mut lines = Vec::new();
        for y in (0..=top).rev().take(rows_shown as usize) {
            let marker = if y == row { "▶" } else { " " };
            let mut spans = vec![Span::raw(format!("{marker}{y:>3}│"))];
            for x in first..(first + columns_shown).min(width) {
                let text = format!("{:>cell$}", values[(height - 1 - y) as usize][x as usize]);
                let (xu, yu) = (x as u32, y as u32);
                let mut style = Style::new();
                if trace_pixels.contains(&(xu, yu)) {
                    style = style.fg(Color::Cyan);
                }
                if y == row && current.contains(&xu) {
                    style = style.bg(Color::Yellow).fg(Color::Black);
                }
                if y == row && focus == Some(xu) {
                    style = style.add_modifier(Modifier::REVERSED | Modifier::BOLD);
                }
                spans.push(Span::styled(text, style));
            }
            lines.push(Line::from(spans));
        }
        let last_shown = (first + columns_shown).min(width) - 1;
        lines.push(Line::from(format!("     {}", column_numbers(first..=last_shown, cell))));
        let shown = zsim::words!(
            "tui-columns-shown",
            first = first.to_string(),
            last = last_shown.to_string(),
            max = (width - 1).to_string()
        );
        lines.push(Line::from(format!("    {shown}")));
        frame.render_widget(Paragraph::new(lines), area);
    }

    /// The right panel: the polygon, the scanline, crossings, spans, and the pixel's row.
    fn details(&mut self, record: Option<&ScanlineRecord>) -> Vec<Line<'static>> {
        let scene = self.tracer.scene;
        let (Some((p, _)), Some(record)) = (self.at, record) else {
            return vec![Line::from(zsim::words!("tui-end"))];
        };
        let geometry = scene.polygons[p].geometry();
        let slope = geometry.slope().map_or_else(String::new, fraction);
        let mut lines = vec![
            Line::styled(report::polygon_heading(scene, p), Style::new().add_modifier(Modifier::BOLD)),
            Line::from(zsim::words!("tui-slope", slope = slope)),
            Line::from(zsim::words!(
                "step-scanline",
                scanline = scanline_text(record.row),
                row = record.row.to_string()
            )),
        ];
        let crossings: Vec<String> = record.crossings.iter().map(exact_and_decimal).collect();
        lines.push(Line::from(zsim::words!("step-crossings", list = crossings.join(&zsim::words!("list-comma")))));
        for (i, span) in record.spans.iter().enumerate() {
            let columns = span.columns.map_or_else(
                || zsim::words!("tui-no-centre"),
                |(f, l)| zsim::words!("step-columns", first = f.to_string(), last = l.to_string()),
            );
            lines.push(Line::from(zsim::words!(
                "tui-span",
                n = (i + 1).to_string(),
                left = exact_and_decimal(&span.left),
                right = exact_and_decimal(&span.right),
                columns = columns
            )));
        }
        lines.push(Line::from(""));
        let Some(done) = self.pixel else {
            // Scanline steps: the table, one line a pixel: x, z, the test, what is stored.
            // `always` and `never` compare nothing: say so instead of a symbol.
            let (op, compares) = match scene.depth_test.compares() {
                true => (scene.depth_test.symbol().to_string(), true),
                false => (zsim::words!("tui-uncompared", test = scene.depth_test.symbol()), false),
            };
            let zs: Vec<String> = record.pixels.iter().map(|e| exact_and_decimal(e.depth.value())).collect();
            let width = zs.iter().map(|z| z.chars().count()).max().unwrap_or(1);
            lines.push(Line::styled(
                format!("  {}", zsim::words!("tui-table-heading", z = format!("{:<width$}", "z"))),
                Style::new().add_modifier(Modifier::BOLD),
            ));
            for (pixel, z) in record.pixels.iter().zip(&zs) {
                let (test, verdict, style) = match pixel.outcome {
                    Outcome::Written => {
                        (String::new(), format!("{} ({})", pixel.stored_after, pixel.frame_after), Color::Green)
                    }
                    _ => (
                        if compares { zsim::words!("tui-not") } else { String::new() },
                        zsim::words!("tui-hidden"),
                        Color::Red,
                    ),
                };
                let line = format!("{:>3} {z:<width$} {test}{op}{} → {verdict}", pixel.x, pixel.stored_before);
                lines.push(Line::styled(line, Style::new().fg(style)));
            }
            lines.push(Line::from(zsim::words!("tui-pixel-by-pixel")));
            return lines;
        };
        // Pixel steps: the pixel just done (none yet at the start).
        let shown: Vec<_> = done.checked_sub(1).and_then(|i| record.pixels.get(i)).into_iter().collect();
        let first_z = record.pixels.first().map(|e| e.depth.value());
        for pixel in shown {
            let z = pixel.depth.value();
            let step = match &first_z {
                Some(start) if pixel.x > record.pixels[0].x => {
                    let count = (pixel.x - record.pixels[0].x).to_string();
                    zsim::words!("tui-steps-from", count = count, start = fraction(start))
                }
                _ => String::new(),
            };
            lines.push(Line::from(zsim::words!(
                "tui-pixel",
                x = pixel.x,
                y = pixel.y,
                centre = exact_and_decimal(Q::new(2 * i128::from(pixel.x) + 1, 2)),
                z = exact_and_decimal(z),
                steps = step
            )));
            let style = if pixel.outcome == Outcome::Written {
                Style::new().fg(Color::Green)
            } else {
                Style::new().fg(Color::Red)
            };
            lines.push(Line::styled(format!("  {}", pixel_reason(scene, pixel)), style));
        }
        lines
    }
}

/// Runs the app on the terminal until the user quits; the terminal is given
/// back as it was (raw mode off, alternate screen left) on quitting and on a
/// panic (ratatui's hook).
/// The numbers of `columns`, each right-aligned under its cell of `cell`
/// characters, left out where it would touch the number before it (on
/// narrow cells every other one, or fewer, is shown).
fn column_numbers(columns: std::ops::RangeInclusive<i32>, cell: usize) -> String {
    let mut line = String::new();
    for (k, x) in columns.enumerate() {
        let number = x.to_string();
        let end = (k + 1) * cell;
        let start = end - number.len().min(end);
        // One space at least between two numbers.
        if start > line.len() || (line.is_empty() && start == 0) {
            line.push_str(&" ".repeat(start - line.len()));
            line.push_str(&number);
        }
    }
    line
}

pub fn run(app: &mut App<'_, '_>) -> std::io::Result<()> {
    let mut terminal = ratatui::init();
    let result = (|| {
        while !app.quit {
            terminal.draw(|frame| app.draw(frame))?;
            if let Event::Key(key) = event::read()?
                && key.kind == KeyEventKind::Press
            {
                app.key(key);
            }
        }
        Ok(())
    })();
    ratatui::restore();
    result
}

#[cfg(test)]
#[path = "tui_tests.rs"]
mod tests;
