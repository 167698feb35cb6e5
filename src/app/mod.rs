//! The full-screen app: `zsim step` on a terminal, a front end of its own
//! beside the command line (`cli/`, which starts it) and the page, redrawn in
//! place with ratatui. The raster
//! on the left (framebuffer or z-buffer) with the scanline marked, the
//! current span highlighted and this polygon's earlier pixels set apart; on
//! the right the polygon, the scanline, its crossings and spans, and the
//! current pixel's row of the table. Keys act without Enter. Everything shown
//! comes from the library's step model (`zsim::step`), as the line mode's
//! and the page's do; the app keeps only what is on the screen.

use ratatui::Frame;
use ratatui::crossterm::event::{self, Event, KeyCode, KeyEvent, KeyEventKind, KeyModifiers};
use ratatui::layout::{Constraint, Layout, Rect};
use ratatui::style::{Color, Modifier, Style};
use ratatui::text::{Line, Span};
use ratatui::widgets::{Block, Borders, Clear, Paragraph, Wrap};
use zsim::explain::{pixel_reason, polygon_name, scanline_text};
use zsim::lesson::{Command, Lesson, Said};
use zsim::report;
use zsim::step::Moved;
use zsim::{Outcome, ScanlineRecord};
use zsim::{Q, exact_and_decimal, fraction};

/// Which buffer the raster shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum View {
    /// The framebuffer.
    Frame,
    /// The z-buffer.
    Depth,
}

/// The stepper's screen state. Keys change it ([`App::key`]); [`App::draw`]
/// shows it. Where the student is, what may be shown and what is asked are
/// the library's [`Lesson`]'s; the app keeps only what is on the screen.
pub struct App<'l> {
    lesson: &'l mut Lesson,
    /// Outside the quiz, in pixel steps, how many of the scanline's pixels
    /// are shown; in scanline steps, `None` (all of them).
    pixel: Option<usize>,
    view: View,
    help: bool,
    /// The `g` prompt's text while it is open.
    go: Option<String>,
    /// What became of the last command, worded by the lesson.
    message: String,
    /// Rows and columns the raster is scrolled by, from where it centres itself.
    scroll: (i32, i32),
    /// Lines the right panel is scrolled by.
    table_scroll: u16,
    /// The quiz answer being typed.
    typed: String,
    /// Set by `q`, Esc or Ctrl-C.
    pub quit: bool,
    /// The language the screen speaks.
    lang: zsim::Lang,
}

impl<'l> App<'l> {
    /// The app at the lesson's stop.
    pub fn new(lesson: &'l mut Lesson, lang: zsim::Lang) -> App<'l> {
        App {
            lesson,
            pixel: None,
            view: View::Frame,
            help: false,
            go: None,
            message: String::new(),
            scroll: (0, 0),
            table_scroll: 0,
            typed: String::new(),
            quit: false,
            lang,
        }
    }

    fn record(&mut self) -> Option<ScanlineRecord> {
        self.lesson.record()
    }

    /// How many of the current scanline's pixels are shown.
    fn shown_pixels(&mut self) -> usize {
        match self.lesson.mode() {
            Some(_) => self.lesson.showing().pixels,
            None => self.pixel.unwrap_or(usize::MAX),
        }
    }

    /// Handles one key press.
    pub fn key(&mut self, key: KeyEvent) {
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
                        self.act(Command::Go(row));
                    }
                }
                KeyCode::Esc => self.go = None,
                _ => {}
            }
            return;
        }
        if self.lesson.question().is_some() && self.quiz_key(key) {
            return;
        }
        self.message.clear();
        if self.help && !matches!(key.code, KeyCode::Char('q') | KeyCode::Esc) {
            self.help = false;
            return;
        }
        match key.code {
            KeyCode::Char('q') | KeyCode::Esc => self.act(Command::Quit),
            KeyCode::Char('n' | ' ') | KeyCode::Enter | KeyCode::Right | KeyCode::Down => self.next(),
            KeyCode::Char('b') | KeyCode::Left | KeyCode::Up => self.back(),
            KeyCode::Char(key @ ('p' | 'P' | 's')) => {
                if let Some(command) = Command::from_key(key) {
                    self.act(command);
                }
            }
            KeyCode::Char('g') => self.go = Some(String::new()),
            KeyCode::Char('f') => self.view = View::Frame,
            KeyCode::Char('z') => self.view = View::Depth,
            KeyCode::Char('m') if self.lesson.mode().is_none() => {
                self.pixel = if self.pixel.is_some() { None } else { Some(1) };
            }
            KeyCode::Char('?') => self.help = true,
            KeyCode::PageUp => self.scroll.0 -= 4,
            KeyCode::PageDown => self.scroll.0 += 4,
            KeyCode::Char('<') => self.scroll.1 -= 4,
            KeyCode::Char('>') => self.scroll.1 += 4,
            KeyCode::Char('[') => self.table_scroll = self.table_scroll.saturating_sub(4),
            KeyCode::Char(']') => self.table_scroll += 4,
            _ => self.message = zsim::words!(self.lang, "key-does-nothing"),
        }
    }

    /// A key while the quiz asks. Typing: any character but the keys that
    /// act alone (`q`, `?`, and `n`, `b`, `p`, `P`, `s`, `g`, `f`, `z` before
    /// anything is typed) goes into the answer, Backspace takes one back,
    /// Enter answers: the lesson judges it. Returns `false` for a key that
    /// acts as usual.
    fn quiz_key(&mut self, key: KeyEvent) -> bool {
        match key.code {
            KeyCode::Char('q' | '?') => return false,
            KeyCode::Char('n' | 'b' | 'p' | 'P' | 's' | 'g' | 'f' | 'z' | ' ') if self.typed.is_empty() => {
                return false;
            }
            KeyCode::Char(c) if !c.is_control() => self.typed.push(c),
            KeyCode::Backspace => {
                self.typed.pop();
            }
            KeyCode::Enter if !self.typed.is_empty() => {
                let typed = std::mem::take(&mut self.typed);
                self.act(Command::Answer(typed));
            }
            _ => return false,
        }
        true
    }

    /// Sends `command` to the lesson; what became of it goes on the status line.
    fn act(&mut self, command: Command) {
        let said = self.lesson.act(self.lang, command);
        if matches!(said, Said::Quit) {
            self.quit = true;
            return;
        }
        self.message = said.text(self.lang, self.lesson.scene());
        if let Said::Moved(Moved::To { .. }) = said {
            self.scroll = (0, 0);
            self.table_scroll = 0;
            self.typed.clear();
            if self.pixel.is_some() {
                self.pixel = Some(1);
            }
        }
    }

    fn next(&mut self) {
        let Some(count) = self.record().map(|record| record.pixels.len()) else { return };
        if self.lesson.mode().is_none()
            && let Some(done) = self.pixel
            && done < count
        {
            self.pixel = Some(done + 1);
            return;
        }
        self.act(Command::Next);
    }

    fn back(&mut self) {
        // From the end, back to the last scanline, as the line mode and the page go.
        if self.lesson.at().is_none() {
            self.act(Command::Back);
            return;
        }
        match self.pixel {
            Some(done) if done > 1 && self.lesson.mode().is_none() => self.pixel = Some(done - 1),
            _ => self.act(Command::Back),
        }
    }

    /// Draws the whole screen.
    pub fn draw(&mut self, frame: &mut Frame<'_>) {
        let lang = self.lang;
        let area = frame.area();
        let status_text = if let Some(text) = &self.go {
            zsim::words!(lang, "go-to-row-prompt", text = text)
        } else if let Some(ask) = self.lesson.prompt(lang) {
            let ask = format!("{ask} {}▏", zsim::printable(&self.typed));
            // What became of the last answer, on its own lines above the question.
            if self.message.is_empty() { ask } else { format!("{}\n{ask}", self.message) }
        } else if !self.message.is_empty() {
            self.message.clone()
        } else {
            zsim::words!(lang, "keys-summary")
        };
        // The status gets the lines its text wraps to (a quiz's reason to ask again on lines of
        // its own above the question), at least two, at most half the screen.
        let status_paragraph = Paragraph::new(status_text).wrap(Wrap { trim: true });
        let wrapped = status_paragraph.line_count(area.width) as u16;
        let status_lines = wrapped.clamp(2, (area.height / 2).max(2));
        // When it cannot all show, its end does: the question and what is typed.
        let status_paragraph = status_paragraph.scroll((wrapped.saturating_sub(status_lines), 0));
        let [title, body, status] =
            Layout::vertical([Constraint::Length(1), Constraint::Min(3), Constraint::Length(status_lines)]).areas(area);
        let record = self.record();
        let at = self.lesson.at();
        let scene = self.lesson.scene();
        let heading = match (at, &record) {
            (Some(stop), Some(r)) => zsim::words!(
                lang,
                "heading-polygon-scanline",
                polygon = polygon_name(lang, scene, stop.polygon),
                scanline = scanline_text(lang, r.row)
            ),
            _ => zsim::words!(lang, "heading-end-of-scene"),
        };
        let view = match self.view {
            View::Frame => zsim::words!(lang, "buffer-frame"),
            View::Depth => zsim::words!(lang, "buffer-depth"),
        };
        let score = self.lesson.score().map_or(String::new(), |score| {
            let right = score.first_try + score.second_try;
            zsim::words!(lang, "score-short", right = right.to_string(), asked = score.asked().to_string())
        });
        frame.render_widget(
            Paragraph::new(zsim::words!(lang, "title-stepper", heading = heading, view = view, score = score))
                .style(Style::new().add_modifier(Modifier::REVERSED)),
            title,
        );
        let raster_width = (area.width * 11 / 20).max(20);
        let [left, right] = Layout::horizontal([Constraint::Length(raster_width), Constraint::Min(20)]).areas(body);
        self.draw_raster(frame, left, record.as_ref());
        if self.help {
            // Over the raster too, as wide as its longest line allows, so that a key and what it
            // does stay on one line (in the right pane alone they wrapped apart on 80×24).
            let text = ratatui::text::Text::from(help(lang));
            let width = (text.width() as u16 + 2).min(body.width);
            let height = (text.height() as u16 + 2).min(body.height);
            let area = Rect { x: body.x + (body.width - width) / 2, y: body.y, width, height };
            let help = Paragraph::new(text)
                .wrap(Wrap { trim: false })
                .block(Block::bordered().title(zsim::words!(lang, "keys-heading")));
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
        frame.render_widget(status_paragraph, status);
    }

    /// The raster's rows that fit, top row first, centred on the scanline.
    fn draw_raster(&mut self, frame: &mut Frame<'_>, area: Rect, record: Option<&ScanlineRecord>) {
        let lang = self.lang;
        let done = self.shown_pixels();
        let Some(buffers) = self.lesson.buffers_after(done) else {
            frame.render_widget(Paragraph::new(zsim::words!(lang, "no-scanline")), area);
            return;
        };
        // Until the coverage question is answered, the covered cells are not marked.
        let coverage_pending = !self.lesson.showing().spans;
        let scene = self.lesson.scene();
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
        // Centred on the span, or while the coverage question waits (where the span lies
        // would answer it), on the raster.
        let (span_first, span_last) = match record {
            _ if coverage_pending => (0, width - 1),
            _ => record
                .and_then(|r| r.spans.iter().filter_map(|s| s.columns).reduce(|a, b| (a.0.min(b.0), a.1.max(b.1))))
                .map_or((0, 0), |(a, b)| (a as i32, b as i32)),
        };
        // Top row shown, and first column shown: centred, then scrolled, then kept on the raster.
        let top = (row + rows_shown / 2 - self.scroll.0).clamp((rows_shown - 1).min(height - 1), height - 1);
        let first =
            ((span_first + span_last) / 2 - columns_shown / 2 + self.scroll.1).clamp(0, (width - columns_shown).max(0));
        let trace_pixels: std::collections::HashSet<(u32, u32)> = self.lesson.earlier_writes().into_iter().collect();
        let current: Vec<u32> = match record {
            Some(r) if !coverage_pending => r.pixels.iter().map(|e| e.x).collect(),
            _ => Vec::new(),
        };
        let focus = record.and_then(|r| done.checked_sub(1).and_then(|i| r.pixels.get(i))).map(|e| e.x);
        let mut lines = Vec::new();
        for y in (0..=top).rev().take(rows_shown as usize) {
            let marker = if y == row { "▶" } else { " " };
            let mut spans = vec![Span::raw(format!("{marker}{y:>3}│"))];
            for x in first..(first + columns_shown).min(width) {
                let text = format!("{:>cell$}", values[zsim::printed_row(height as u32, y as u32)][x as usize]);
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
            lang,
            "columns-shown",
            first = first.to_string(),
            last = last_shown.to_string(),
            max = (width - 1).to_string()
        );
        lines.push(Line::from(format!("    {shown}")));
        frame.render_widget(Paragraph::new(lines), area);
    }

    /// The right panel: the polygon, the scanline, crossings, spans, and the pixel's row.
    fn details(&mut self, record: Option<&ScanlineRecord>) -> Vec<Line<'static>> {
        let lang = self.lang;
        let (Some(view), Some(record)) = (self.lesson.stop_view(lang), record) else {
            return vec![Line::from(zsim::words!(lang, "end-of-scene"))];
        };
        let mut lines = vec![
            Line::styled(view.heading, Style::new().add_modifier(Modifier::BOLD)),
            Line::from(view.slope),
            Line::from(view.scanline),
        ];
        // The lesson leaves out the crossings and spans while they would answer the coverage question.
        lines.extend(view.crossings.into_iter().map(Line::from));
        lines.extend(view.spans.into_iter().map(Line::from));
        lines.push(Line::from(""));
        let pixel_steps = if self.lesson.mode().is_some() { Some(self.shown_pixels()) } else { self.pixel };
        let scene = self.lesson.scene();
        let Some(done) = pixel_steps else {
            // Scanline steps: the lesson's table, one line a pixel: x, z to two places, the test
            // with its outcome, what is stored (and the framebuffer).
            let width = view.rows.iter().map(|r| r.approx.chars().count()).max().unwrap_or(1).max(3);
            lines.push(Line::styled(
                format!("  {}", zsim::words!(lang, "pixel-table-heading", z = format!("{:>width$}", "≈ z"))),
                Style::new().add_modifier(Modifier::BOLD),
            ));
            for row in &view.rows {
                let style = if row.written { Color::Green } else { Color::Red };
                let line = format!("{:>3} {:>width$} {} → {} ({})", row.x, row.approx, row.test, row.after, row.frame);
                lines.push(Line::styled(line, Style::new().fg(style)));
            }
            lines.push(Line::from(zsim::words!(lang, "keys-pixel-by-pixel")));
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
                    zsim::words!(lang, "depth-steps-from", count = count, start = fraction(start))
                }
                _ => String::new(),
            };
            lines.push(Line::from(zsim::words!(
                lang,
                "pixel-centre-depth",
                x = pixel.x,
                y = pixel.y,
                centre = exact_and_decimal(lang, Q::new(2 * i128::from(pixel.x) + 1, 2)),
                z = exact_and_decimal(lang, z),
                steps = step
            )));
            let style = if pixel.outcome == Outcome::Written {
                Style::new().fg(Color::Green)
            } else {
                Style::new().fg(Color::Red)
            };
            lines.push(Line::styled(format!("  {}", pixel_reason(lang, scene, pixel)), style));
        }
        lines
    }
}

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

/// Runs the app on the terminal until the user quits; the terminal is given
/// back as it was (raw mode off, alternate screen left) on quitting and on a
/// panic (ratatui's hook).
pub fn run(app: &mut App<'_>) -> std::io::Result<()> {
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
mod tests;

/// The keys box: the lesson's keys from its one table ([`zsim::lesson::KEYS`]),
/// each with the app's other keys for the same command, then the app's own.
fn help(lang: zsim::Lang) -> String {
    let also = |key: char| match key {
        'n' => " Space Enter → ↓",
        'b' => " ← ↑",
        'q' => " Esc Ctrl-C",
        _ => "",
    };
    let mut text: String = zsim::lesson::KEYS
        .iter()
        .map(|(key, word)| format!("{:<19}{}\n", format!("{key}{}", also(*key)), zsim::message(lang, word, &[])))
        .collect();
    text.push_str(&zsim::words!(lang, "keys-help"));
    text
}
