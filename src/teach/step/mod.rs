//! The stepper as a teaching model: where the student is (a [`Stop`]), how
//! each key moves (next, back, next or previous polygon, a row), what a stop
//! shows, and the quiz: which question comes next, how an answer is judged
//! (one function per kind of question), the score and each mistake. The
//! line mode, the full-screen app and the page render these facts and hold
//! no rule of their own.

pub mod lesson;
pub mod page;
pub mod table;

use crate::effects::arith::Arith;
use crate::numbers::{Exact, exact_and_decimal, parse_number};
use crate::observe::explain::{pixel_reason, polygon_after, polygon_name, scanline_text};
use crate::observe::trace::ScanlineRecord;
use crate::observe::tracer::{Skip, Stop, Tracer};
use crate::scene::Scene;
use crate::simulate::events::{Outcome, PixelEvent};
use crate::words::Lang;
use crate::words::printable;
use crate::words::token;

/// Why a move did not go anywhere.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum RefusedMove {
    /// Back from the first stop.
    First,
    /// Previous polygon from the first polygon with a stop.
    NoEarlierPolygon,
    /// A row beyond the raster.
    OutsideRaster {
        /// The row asked for.
        row: u32,
    },
    /// Next polygon from the last polygon with a stop.
    NoLaterPolygon,
    /// A move while the scanline's questions are open.
    QuestionsOpen {
        /// How many.
        open: usize,
    },
    /// A polygon number beyond the scene's.
    NoSuchPolygon {
        /// 0-based polygon index asked for.
        polygon: usize,
    },
    /// A row the current polygon does not reach.
    NotReached {
        /// 0-based polygon index.
        polygon: usize,
        /// The row asked for.
        row: u32,
    },
}

impl RefusedMove {
    /// The refusal in one line of the reader's language.
    pub fn text(&self, lang: Lang, scene: &Scene) -> String {
        match *self {
            RefusedMove::First => words!(lang, "step-first"),
            RefusedMove::NoEarlierPolygon => words!(lang, "no-earlier-polygon"),
            RefusedMove::NoLaterPolygon => words!(lang, "no-later-polygon"),
            RefusedMove::QuestionsOpen { open } => words!(lang, "lesson-questions-open", open = open.to_string()),
            RefusedMove::NoSuchPolygon { polygon } => words!(
                lang,
                "lesson-no-such-polygon",
                polygon = (polygon + 1).to_string(),
                count = scene.polygons.len().to_string()
            ),
            RefusedMove::OutsideRaster { row } => {
                words!(lang, "step-outside-raster", row = row.to_string(), last = (scene.height - 1).to_string())
            }
            RefusedMove::NotReached { polygon, row } => {
                words!(
                    lang,
                    "step-not-reach",
                    polygon = polygon_name(lang, scene, polygon),
                    scanline = scanline_text(lang, row)
                )
            }
        }
    }
}

/// What a move did.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Moved {
    /// Arrived at a stop, or at the end (no stop after the last); what was
    /// passed over on the way.
    To {
        /// Where: `None` is the end.
        at: Option<Stop>,
        /// What was passed over.
        skipped: Vec<Skip>,
    },
    /// Stayed where it was.
    Refused(RefusedMove),
}

/// The stepper: a recording of the scene and the stop the student is at.
pub struct Stepper<'s> {
    tracer: Tracer<'s>,
    at: Option<Stop>,
}

impl<'s> Stepper<'s> {
    /// The stepper before the first stop of `scene`, showing `arith` beside
    /// the exact values; [`Stepper::start`] moves to the first stop.
    pub fn new(scene: &'s Scene, arith: Arith) -> Stepper<'s> {
        Stepper { tracer: Tracer::new(scene, arith), at: None }
    }

    /// The scene stepped through.
    pub fn scene(&self) -> &'s Scene {
        self.tracer.scene
    }

    /// The arithmetic shown beside the exact values.
    pub fn arith(&self) -> Arith {
        self.tracer.arith
    }

    /// The recording (the buffers at any point, each polygon's trace).
    pub fn tracer(&mut self) -> &mut Tracer<'s> {
        &mut self.tracer
    }

    /// Moves to `at`, or to the first stop when `None`.
    pub fn start(&mut self, at: Option<Stop>) -> Moved {
        match at {
            Some(stop) => self.arrive(Some(stop), Vec::new()),
            None => {
                let (first, skipped) = self.tracer.next_stop(None);
                self.arrive(first, skipped)
            }
        }
    }

    /// Where the student is: `None` at the end.
    pub fn at(&self) -> Option<Stop> {
        self.at
    }

    /// The current stop's scanline, `None` at the end.
    pub fn record(&mut self) -> Option<&ScanlineRecord> {
        let stop = self.at?;
        Some(self.tracer.record(stop))
    }

    fn arrive(&mut self, at: Option<Stop>, skipped: Vec<Skip>) -> Moved {
        self.at = at;
        Moved::To { at, skipped }
    }

    /// The next stop (or the end).
    pub fn forward(&mut self) -> Moved {
        match self.at {
            Some(stop) => {
                let (next, skipped) = self.tracer.next_stop(Some(stop));
                self.arrive(next, skipped)
            }
            None => self.arrive(None, Vec::new()),
        }
    }

    /// The stop before (from the end, the last stop).
    pub fn back(&mut self) -> Moved {
        let from = self.at.unwrap_or(Stop { polygon: self.scene().polygons.len(), scanline: 0 });
        match self.tracer.previous_stop(from) {
            Some(stop) => self.arrive(Some(stop), Vec::new()),
            None => Moved::Refused(RefusedMove::First),
        }
    }

    /// The first stop of a later polygon; on the last polygon (or at the
    /// end) refused, and the place kept.
    pub fn next_polygon(&mut self) -> Moved {
        let Some(stop) = self.at else { return Moved::Refused(RefusedMove::NoLaterPolygon) };
        let last = self.tracer.trace(stop.polygon).scanlines.len().saturating_sub(1);
        match self.tracer.next_stop(Some(Stop { polygon: stop.polygon, scanline: last })) {
            (Some(next), skipped) => self.arrive(Some(next), skipped),
            (None, _) => Moved::Refused(RefusedMove::NoLaterPolygon),
        }
    }

    /// The first stop of the polygon before the current one.
    pub fn previous_polygon(&mut self) -> Moved {
        let polygon = self.at.map_or(self.scene().polygons.len(), |stop| stop.polygon);
        let mut found = self.tracer.previous_stop(Stop { polygon, scanline: 0 });
        // To the first covering scanline of that polygon.
        while let Some(stop) = found {
            match self.tracer.previous_stop(stop) {
                Some(earlier) if earlier.polygon == stop.polygon => found = Some(earlier),
                _ => break,
            }
        }
        match found {
            Some(stop) => self.arrive(Some(stop), Vec::new()),
            None => Moved::Refused(RefusedMove::NoEarlierPolygon),
        }
    }

    /// Scanline `row` of the current polygon (the last polygon at the end).
    pub fn go(&mut self, row: u32) -> Moved {
        let polygon = self.at.map_or(0, |stop| stop.polygon).min(self.scene().polygons.len().saturating_sub(1));
        self.go_to(polygon, row)
    }

    /// Scanline `row` of polygon `polygon` (0-based).
    pub fn go_to(&mut self, polygon: usize, row: u32) -> Moved {
        let scene = self.scene();
        if polygon >= scene.polygons.len() {
            return Moved::Refused(RefusedMove::NoSuchPolygon { polygon });
        }
        if row >= scene.height {
            return Moved::Refused(RefusedMove::OutsideRaster { row });
        }
        match self.tracer.trace(polygon).scanlines.iter().position(|r| r.row == row) {
            Some(scanline) => self.arrive(Some(Stop { polygon, scanline }), Vec::new()),
            None => Moved::Refused(RefusedMove::NotReached { polygon, row }),
        }
    }

    /// What a stop shows beside the buffers, worded: the polygon, the
    /// scanline, its crossings and spans.
    pub fn stop_words(&mut self, lang: Lang, stop: Stop) -> StopWords {
        let scene = self.scene();
        let record = self.tracer.record(stop);
        let crossings: Vec<String> = record.crossings.iter().map(|x| exact_and_decimal(lang, x)).collect();
        let crossings = if crossings.is_empty() {
            words!(lang, "step-crossings", list = words!(lang, "step-crossings-none"))
        } else {
            words!(lang, "step-crossings", list = crossings.join(&words!(lang, "list-comma")))
        };
        let spans = record
            .spans
            .iter()
            .enumerate()
            .map(|(i, span)| {
                let columns = span.columns.map_or_else(
                    || words!(lang, "span-no-centre"),
                    |(first, last)| words!(lang, "step-columns", first = first.to_string(), last = last.to_string()),
                );
                words!(
                    lang,
                    "span-line",
                    n = (i + 1).to_string(),
                    left = exact_and_decimal(lang, &span.left),
                    right = exact_and_decimal(lang, &span.right),
                    columns = columns
                )
            })
            .collect();
        StopWords {
            heading: crate::observe::report::polygon_heading(lang, scene, stop.polygon),
            scanline: words!(
                lang,
                "step-scanline",
                scanline = scanline_text(lang, record.row),
                row = record.row.to_string()
            ),
            crossings,
            spans,
        }
    }
}

/// What a stop shows beside the buffers, in the reader's language.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StopWords {
    /// The polygon: its name, plane and what it is.
    pub heading: String,
    /// The scanline and its row.
    pub scanline: String,
    /// The crossings, sorted.
    pub crossings: String,
    /// Each span with its columns.
    pub spans: Vec<String>,
}

/// A [`Skip`] in one line of the reader's language.
pub use crate::observe::tracer::skip_text;

/// What the quiz asks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum QuizMode {
    /// The z-buffer value after each covered pixel.
    Depth,
    /// The framebuffer value after each covered pixel.
    Frame,
    /// First which centres the scanline covers, then the z-buffer values.
    Coverage,
}

/// A question of the quiz.
#[derive(Debug, Clone)]
pub enum Question {
    /// Which columns' centres does the scanline cover?
    Coverage {
        /// The stop.
        stop: Stop,
        /// The pixel row.
        row: u32,
    },
    /// What does the z-buffer hold after this pixel?
    Depth {
        /// The stop.
        stop: Stop,
        /// Which covered pixel of the stop, from 0.
        index: usize,
        /// The pixel (the value before is shown; the rest is the answer).
        pixel: PixelEvent,
    },
    /// What does the framebuffer hold after this pixel?
    Frame {
        /// The stop.
        stop: Stop,
        /// Which covered pixel of the stop, from 0.
        index: usize,
        /// The pixel (the value before is shown; the rest is the answer).
        pixel: PixelEvent,
    },
}

/// What a depth answer meant.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Meant {
    /// `-`: not written.
    NotWritten,
    /// The value written.
    ValueWritten,
    /// The value a pixel not written keeps.
    ValueKept,
    /// Some value.
    Value,
}

impl Meant {
    /// What the answer meant, in words.
    pub fn text(self, lang: Lang) -> String {
        match self {
            Meant::NotWritten => words!(lang, "meant-not-written"),
            Meant::ValueWritten => words!(lang, "meant-value-written"),
            Meant::ValueKept => words!(lang, "meant-value-kept"),
            Meant::Value => words!(lang, "meant-value"),
        }
    }
}

/// The judgement of one answer.
#[derive(Debug, Clone)]
pub struct Verdict {
    /// The question answered.
    pub question: Question,
    /// Whether the answer is right.
    pub right: bool,
    /// What the student typed, trimmed.
    pub said: String,
    /// What a depth answer meant (`None` for coverage).
    pub meant: Option<Meant>,
    /// The right answer as a student writes it (`16-27`; `15`; `keeps 0`).
    pub expected: String,
    /// Why that is the answer: the spans, or the pixel's test.
    pub why: String,
}

/// A wrong answer as the summary lists it.
pub(crate) fn mistake_text(lang: Lang, scene: &Scene, verdict: &Verdict) -> String {
    match &verdict.question {
        Question::Coverage { stop, row } => words!(
            lang,
            "quiz-coverage-mistake",
            row = row.to_string(),
            polygon = polygon_after(lang, scene, stop.polygon),
            said = &verdict.said,
            right = &verdict.expected,
            why = &verdict.why
        ),
        Question::Depth { stop, pixel, .. } | Question::Frame { stop, pixel, .. } => words!(
            lang,
            "quiz-depth-mistake",
            x = pixel.x,
            y = pixel.y,
            polygon = polygon_after(lang, scene, stop.polygon),
            said = &verdict.said,
            right = &verdict.expected,
            reason = &verdict.why
        ),
    }
}

/// A judged answer: right, what it meant, the right answer and why.
type Judged = (bool, Option<Meant>, String, String);

/// Judges a coverage answer (`16-27`, `3-5 9-12`, `4` or `-`); `Err` with
/// the reason to ask again when it is not columns.
pub fn judge_coverage(lang: Lang, record: &ScanlineRecord, typed: &str) -> Result<Judged, String> {
    let Some(columns) = parse_columns(typed) else { return Err(words!(lang, "quiz-coverage-hint")) };
    let covered: Vec<u32> = record.pixels.iter().map(|e| e.x).collect();
    let spans: Vec<String> = record
        .spans
        .iter()
        .map(|s| {
            words!(lang, "span", left = exact_and_decimal(lang, &s.left), right = exact_and_decimal(lang, &s.right))
        })
        .collect();
    let why = words!(lang, "quiz-coverage-why", spans = spans.join(&words!(lang, "list-comma")));
    Ok((columns == covered, None, columns_text(&covered), why))
}

/// Judges a depth answer for a pixel: `-` (not written) or a number, right
/// when it is the value the z-buffer holds after the pixel (for a pixel not
/// written, `-` or the value it keeps); `Err` with the reason to ask again
/// for text that is neither, or a number no cell can hold.
pub fn judge_depth(lang: Lang, scene: &Scene, pixel: &PixelEvent, typed: &str) -> Result<Judged, String> {
    let written = pixel.outcome == Outcome::Written;
    let expected = if written {
        pixel.stored_after.text(lang)
    } else {
        words!(lang, "quiz-keeps", value = pixel.stored_after.text(lang))
    };
    let why = pixel_reason(lang, scene, pixel);
    if typed == "-" {
        return Ok((!written, Some(Meant::NotWritten), expected, why));
    }
    if let Some(problem) = does_not_fit(lang, scene, typed) {
        return Err(problem);
    }
    let Ok(value) = parse_number(typed) else {
        let shown = printable(&token(lang, typed)).into_owned();
        return Err(words!(lang, "quiz-not-an-answer", text = shown, hint = words!(lang, "quiz-depth-hint")));
    };
    let (right, meant) = match Exact::Word(value) == pixel.stored_after.value() {
        true if written => (true, Meant::ValueWritten),
        true => (true, Meant::ValueKept),
        false => (false, Meant::Value),
    };
    Ok((right, Some(meant), expected, why))
}

/// Judges a framebuffer answer for a pixel: `-` (not written) or a whole
/// value, right when it is the value the framebuffer holds after the pixel;
/// `Err` with the reason to ask again for text that is neither, or a value
/// no cell can hold.
pub fn judge_frame(lang: Lang, scene: &Scene, pixel: &PixelEvent, typed: &str) -> Result<Judged, String> {
    let written = pixel.outcome == Outcome::Written;
    let expected = if written {
        pixel.frame_after.to_string()
    } else {
        words!(lang, "quiz-keeps", value = pixel.frame_after.to_string())
    };
    let why = pixel_reason(lang, scene, pixel);
    if typed == "-" {
        return Ok((!written, Some(Meant::NotWritten), expected, why));
    }
    let Ok(value) = parse_number(typed) else {
        let shown = printable(&token(lang, typed)).into_owned();
        return Err(words!(lang, "quiz-not-an-answer", text = shown, hint = words!(lang, "quiz-frame-hint")));
    };
    let max = crate::scene::max_for_bits(scene.frame_bits);
    if !value.is_integer() || *value.numer() < 0 || *value.numer() > i128::from(max) {
        let shown = printable(&token(lang, typed)).into_owned();
        return Err(words!(lang, "quiz-frame-does-not-fit", text = shown, max = max.to_string()));
    }
    let (right, meant) = match *value.numer() == i128::from(pixel.frame_after) {
        true if written => (true, Meant::ValueWritten),
        true => (true, Meant::ValueKept),
        false => (false, Meant::Value),
    };
    Ok((right, Some(meant), expected, why))
}

/// Why `typed` is a number no cell of `scene`'s z-buffer can hold (a
/// quantized z-buffer holds whole levels 0 … max); `None` for any other text.
fn does_not_fit(lang: Lang, scene: &Scene, typed: &str) -> Option<String> {
    if scene.rules.store != crate::rules::DepthStore::Quantized {
        return None;
    }
    let value = parse_number(typed).ok()?;
    let max = scene.depth_max();
    let fits = value.is_integer() && *value.numer() >= 0 && *value.numer() <= i128::from(max);
    (!fits).then(|| {
        words!(lang, "quiz-does-not-fit", text = printable(&token(lang, typed)).into_owned(), max = max.to_string())
    })
}

/// The covered columns as a student writes them: `16-27`, `3-5 9-12`, or `-` for none.
pub fn columns_text(columns: &[u32]) -> String {
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

/// Reads columns as zsim writes them and students type them: runs as
/// `16-27`, `16 … 27`, `16...27` or `16..27`, apart by spaces or commas
/// (`3-5 9-12`, `28, 29`), a single `4`, or `-` for none; `None` when it is
/// not that.
pub fn parse_columns(text: &str) -> Option<Vec<u32>> {
    if text.trim() == "-" {
        return Some(Vec::new());
    }
    // Every way of writing a run's dash as `-`, with no space around it.
    let dashed = text.replace("...", "-").replace('…', "-").replace("..", "-").replace(['–', '—'], "-");
    let mut joined = String::with_capacity(dashed.len());
    for (i, part) in dashed.split('-').enumerate() {
        if i > 0 {
            joined.truncate(joined.trim_end().len());
            joined.push('-');
            joined.push_str(part.trim_start());
        } else {
            joined.push_str(part);
        }
    }
    let mut columns = Vec::new();
    for run in joined.split([' ', ',', ';']).filter(|r| !r.is_empty()) {
        let (a, b) = run.split_once('-').unwrap_or((run, run));
        let (a, b): (u32, u32) = (a.parse().ok()?, b.parse().ok()?);
        if a > b || b - a > 100_000 || columns.len() > 100_000 {
            return None;
        }
        columns.extend(a..=b);
    }
    if columns.is_empty() {
        return None;
    }
    columns.sort_unstable();
    columns.dedup();
    Some(columns)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn book() -> Scene {
        Scene::load(std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/rogers.json"))).unwrap()
    }

    #[test]
    fn columns_are_read_as_students_write_them() {
        assert_eq!(parse_columns("16-27"), Some((16..=27).collect()));
        assert_eq!(parse_columns("3-5 9"), Some(vec![3, 4, 5, 9]));
        assert_eq!(parse_columns("-"), Some(vec![]));
        assert_eq!(parse_columns("x"), None);
        for typed in ["28 … 29", "28-29", "28..29", "28...29", "28, 29", "28 29", "28 - 29", "28–29"] {
            assert_eq!(parse_columns(typed), Some(vec![28, 29]), "{typed}");
        }
        assert_eq!(parse_columns("3-5, 9 … 10"), Some(vec![3, 4, 5, 9, 10]));
        assert_eq!(parse_columns("-3"), None);
        assert_eq!(parse_columns("5-3"), None);
        assert_eq!(parse_columns(""), None);
        assert_eq!(columns_text(&[3, 4, 5, 9]), "3-5 9");
    }

    /// Found by a student: `p` on the last polygon said it could not move,
    /// then moved to the end of the scene.
    #[test]
    fn the_next_polygon_from_the_last_is_refused_and_the_place_kept() {
        let scene = book();
        let mut stepper = Stepper::new(&scene, Arith::Exact);
        stepper.start(None);
        let Moved::To { at: Some(second), .. } = stepper.next_polygon() else { panic!("no second polygon") };
        assert_eq!(second.polygon, 1);
        assert_eq!(stepper.next_polygon(), Moved::Refused(RefusedMove::NoLaterPolygon));
        assert_eq!(stepper.at(), Some(second));
        while stepper.at().is_some() {
            stepper.forward();
        }
        assert_eq!(stepper.next_polygon(), Moved::Refused(RefusedMove::NoLaterPolygon));
        assert_eq!(stepper.at(), None);
    }

    #[test]
    fn back_from_the_end_is_the_last_stop_and_from_the_first_is_refused() {
        let scene = book();
        let mut stepper = Stepper::new(&scene, Arith::Exact);
        stepper.start(None);
        assert_eq!(stepper.back(), Moved::Refused(RefusedMove::First));
        while stepper.at().is_some() {
            stepper.forward();
        }
        let Moved::To { at: Some(last), .. } = stepper.back() else { panic!("no last stop") };
        assert_eq!(last.polygon, scene.polygons.len() - 1);
    }
}
