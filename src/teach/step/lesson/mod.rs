//! The lesson: one stateful model of a student stepping through a scene, with
//! or without a quiz, that every front end (the line mode, the full-screen
//! app, the browser playground) renders and sends commands to. It owns the
//! scene, parsed once, and the stepper over it, and decides at each moment
//! what may be shown and what is being asked. Its rules, the same in every
//! front end:
//!
//! - What is asked is never shown before it is answered: while coverage is
//!   asked, the crossings, spans and covered columns are hidden; while a
//!   pixel is asked, its exact z and what it stores (and every pixel after it
//!   on the scanline) are hidden: the plane is shown, computing z is the
//!   exercise.
//! - A wrong answer first gets a [`Hint`] that names the kind of mistake
//!   without the value, and a second try; a second wrong answer gets the
//!   answer with its reason.
//! - Moving on (next scanline, next or previous polygon, a row) is refused
//!   while the scanline's questions are open, until they are answered or
//!   skipped on purpose ([`Command::Skip`]; a skip counts as not answered).
//! - The [`Score`] counts first-try right, second-try right, revealed and
//!   skipped questions.
//!
//! The keys are one table ([`Command::from_key`], [`Command::parse`]) that
//! every front end reads, and every answer and move is worded here
//! ([`Said::text`]), so the three front ends ask and answer alike.

use self_cell::self_cell;

use crate::effects::arith::Arith;
use crate::numbers::fraction;
use crate::observe::explain::{polygon_name, scanline_text};
use crate::observe::trace::ScanlineRecord;
use crate::observe::tracer::Stop;
use crate::scene::Scene;
use crate::simulate::buffer::Buffers;
use crate::teach::check::diagnose::Misconception;
use crate::teach::step::table::{PixelRow, notes, pixel_rows, span_lines};
use crate::teach::step::{
    Meant, Moved, Question, QuizMode, RefusedMove, Stepper, Verdict, judge_coverage, judge_depth, judge_frame,
};

use crate::words::{Lang, printable};
use hint::{depth_hint, hint};

/// The stepper over a scene the lesson owns.
type StepperOf<'s> = Stepper<'s>;

self_cell!(
    /// The scene and the stepper that borrows it, held together.
    struct Held {
        owner: Scene,
        #[not_covariant]
        dependent: StepperOf,
    }
);

/// What the current stop may show: the rest is being asked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Showing {
    /// Whether the crossings, spans and covered columns may be shown.
    pub spans: bool,
    /// How many of the scanline's covered pixels (from the left) may be
    /// shown with their exact z and what they store.
    pub pixels: usize,
    /// How many covered pixels the scanline has.
    pub covered: usize,
}

/// What the current stop shows beside the buffers, worded and already cut
/// to what may be shown.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StopView {
    /// The stop.
    pub stop: Stop,
    /// The pixel row of the scanline.
    pub row: u32,
    /// The polygon: its name, plane and what it is.
    pub heading: String,
    /// How z steps along a scanline.
    pub slope: String,
    /// The scanline and its row.
    pub scanline: String,
    /// The crossings (`None` while coverage is asked).
    pub crossings: Option<String>,
    /// Each span's ends and columns (empty while coverage is asked).
    pub spans: Vec<String>,
    /// Each span with its ends' depths too (empty while anything is asked).
    pub span_depths: Vec<String>,
    /// The covered columns, left to right (empty while coverage is asked).
    pub columns: Vec<u32>,
    /// The rows of the covered pixels that may be shown.
    pub rows: Vec<PixelRow>,
    /// How many covered pixels are hidden after them (0 while coverage is asked).
    pub hidden: usize,
    /// The boundary centres' rules and an inexact arithmetic's values (once nothing is hidden).
    pub notes: Vec<String>,
}

/// A wrong answer kept for the summary: the question and what was typed.
#[derive(Debug, Clone)]
struct Mistake {
    question: Question,
    said: String,
    revealed: bool,
}

/// The quiz's place: which question of which stop, and how many tries.
#[derive(Debug, Clone)]
struct QuizState {
    mode: QuizMode,
    stop: Option<Stop>,
    coverage_done: bool,
    pixels_done: usize,
    wrong_tries: u8,
    score: Score,
    mistakes: Vec<Mistake>,
    /// The stops whose questions all ended (answered, shown or skipped):
    /// come back to, they show their answers and ask nothing, so that no
    /// question counts twice.
    ended: std::collections::BTreeSet<Stop>,
}

impl QuizState {
    /// Moves the questions to `stop`: a stop whose questions ended shows its answers.
    fn at(&mut self, stop: Option<Stop>) {
        if self.stop != stop {
            self.stop = stop;
            let ended = stop.is_some_and(|stop| self.ended.contains(&stop));
            self.coverage_done = ended;
            self.pixels_done = if ended { usize::MAX } else { 0 };
            self.wrong_tries = 0;
        }
    }

    /// The current stop's questions all ended.
    fn end_stop(&mut self) {
        if let Some(stop) = self.stop {
            self.ended.insert(stop);
        }
    }
}

/// The lesson: the scene, where the student is, and the quiz.
pub struct Lesson {
    held: Held,
    quiz: Option<QuizState>,
}

impl Lesson {
    /// The lesson of `scene`, before its first stop, showing `arith` beside
    /// the exact values, with a quiz in `mode` or none; [`Lesson::start`] moves
    /// to the first stop.
    pub fn new(scene: Scene, arith: Arith, mode: Option<QuizMode>) -> Lesson {
        let held = Held::new(scene, |scene| Stepper::new(scene, arith));
        let quiz = mode.map(|mode| QuizState {
            mode,
            stop: None,
            coverage_done: false,
            pixels_done: 0,
            wrong_tries: 0,
            score: Score::default(),
            mistakes: Vec::new(),
            ended: std::collections::BTreeSet::new(),
        });
        Lesson { held, quiz }
    }

    /// Moves to `at`, or to the first stop when `None`.
    pub fn start(&mut self, at: Option<Stop>) -> Said {
        let moved = self.held.with_dependent_mut(|_, stepper| stepper.start(at));
        self.arrived(moved)
    }

    /// Moves to scanline `row` of polygon `polygon` (0-based) whatever is
    /// open, as a page's address or a reload places the student; its
    /// questions are asked from the first.
    pub fn place(&mut self, polygon: usize, row: u32) -> Said {
        let moved = self.held.with_dependent_mut(|_, stepper| stepper.go_to(polygon, row));
        self.arrived(moved)
    }

    /// The scene.
    pub fn scene(&self) -> &Scene {
        self.held.borrow_owner()
    }

    /// The quiz's mode, if there is a quiz.
    pub fn mode(&self) -> Option<QuizMode> {
        self.quiz.as_ref().map(|quiz| quiz.mode)
    }

    /// The score (`None` without a quiz).
    pub fn score(&self) -> Option<Score> {
        self.quiz.as_ref().map(|quiz| quiz.score)
    }

    /// Where the student is: `None` at the end.
    pub fn at(&mut self) -> Option<Stop> {
        self.held.with_dependent_mut(|_, stepper| stepper.at())
    }

    /// The stepper, for what a front end draws of the recording (the raster,
    /// this polygon's earlier pixels). What it shows must go through
    /// [`Lesson::showing`].
    pub fn with_stepper<R>(&mut self, f: impl FnOnce(&mut Stepper<'_>) -> R) -> R {
        self.held.with_dependent_mut(|_, stepper| f(stepper))
    }

    /// The current stop's scanline (`None` at the end).
    pub fn record(&mut self) -> Option<ScanlineRecord> {
        self.with_stepper(|stepper| stepper.record().cloned())
    }

    /// The question open now, if any.
    pub fn question(&mut self) -> Option<Question> {
        let quiz = self.quiz.as_ref()?;
        let (mode, coverage_done, pixels_done) = (quiz.mode, quiz.coverage_done, quiz.pixels_done);
        self.with_stepper(|stepper| {
            let stop = stepper.at()?;
            let record = stepper.tracer().record(stop);
            if mode == QuizMode::Coverage && !coverage_done {
                return Some(Question::Coverage { stop, row: record.row });
            }
            let pixel = record.pixels.get(pixels_done)?.clone();
            let index = pixels_done;
            Some(match mode {
                QuizMode::Frame => Question::Frame { stop, index, pixel },
                QuizMode::Depth | QuizMode::Coverage => Question::Depth { stop, index, pixel },
            })
        })
    }

    /// Whether the open question has had one wrong answer (the next is its last try).
    pub fn second_try(&self) -> bool {
        self.quiz.as_ref().is_some_and(|quiz| quiz.wrong_tries > 0)
    }

    /// What the current stop may show now.
    pub fn showing(&mut self) -> Showing {
        let covered = self.record().map_or(0, |record| record.pixels.len());
        match self.question() {
            Some(Question::Coverage { .. }) => Showing { spans: false, pixels: 0, covered },
            Some(Question::Depth { index, .. } | Question::Frame { index, .. }) => {
                Showing { spans: true, pixels: index, covered }
            }
            None => Showing { spans: true, pixels: covered, covered },
        }
    }

    /// The open question as the student is asked it, in one line.
    pub fn prompt(&mut self, lang: Lang) -> Option<String> {
        let question = self.question()?;
        let scene = self.scene();
        let ask = match &question {
            Question::Coverage { stop, row } => words!(
                lang,
                "lesson-ask-coverage",
                polygon = polygon_name(lang, scene, stop.polygon),
                scanline = scanline_text(lang, *row)
            ),
            Question::Depth { pixel, .. } => {
                words!(lang, "lesson-ask-depth", x = pixel.x, y = pixel.y, stored = pixel.stored_before.text(lang))
            }
            Question::Frame { pixel, .. } => {
                words!(lang, "lesson-ask-frame", x = pixel.x, y = pixel.y, before = pixel.frame_before)
            }
        };
        Some(if self.second_try() { words!(lang, "lesson-last-try", ask = ask) } else { ask })
    }

    /// What the current stop shows, cut to what may be shown (`None` at the end).
    pub fn stop_view(&mut self, lang: Lang) -> Option<StopView> {
        let showing = self.showing();
        let stop = self.at()?;
        self.held.with_dependent_mut(|scene, stepper| {
            let arith = stepper.arith();
            let record = stepper.tracer().record(stop).clone();
            let words = stepper.stop_words(lang, stop);
            let slope = scene.polygons[stop.polygon].geometry().slope().map_or_else(String::new, fraction);
            let everything = showing.spans && showing.pixels == showing.covered;
            let shown = &record.pixels[..showing.pixels.min(record.pixels.len())];
            Some(StopView {
                stop,
                row: record.row,
                heading: words.heading,
                slope: words!(lang, "step-slope", slope = slope),
                scanline: words.scanline,
                crossings: showing.spans.then_some(words.crossings),
                spans: if showing.spans { words.spans } else { Vec::new() },
                // A span's end can be a pixel's centre: its depth is shown once no depth is asked.
                span_depths: if everything { span_lines(lang, scene, &record) } else { Vec::new() },
                columns: if showing.spans { record.pixels.iter().map(|p| p.x).collect() } else { Vec::new() },
                rows: pixel_rows(lang, scene, shown),
                // While coverage is asked, how many pixels are covered is the answer's length: not said.
                hidden: if showing.spans { record.pixels.len() - shown.len() } else { 0 },
                notes: if everything { notes(lang, scene, stop.polygon, &record, arith) } else { Vec::new() },
            })
        })
    }

    /// The buffers as the student may see them: after the stop's polygon's
    /// earlier scanlines and the shown pixels of its own (`None` at the end).
    pub fn buffers(&mut self) -> Option<Buffers> {
        self.buffers_after(usize::MAX)
    }

    /// The buffers after the stop's polygon's earlier scanlines and the first
    /// `pixels` of its own, no more than the student may see (`None` at the
    /// end): a front end that steps pixel by pixel shows fewer.
    pub fn buffers_after(&mut self, pixels: usize) -> Option<Buffers> {
        let pixels = pixels.min(self.showing().pixels);
        let stop = self.at()?;
        Some(self.with_stepper(|stepper| stepper.tracer().buffers_through(stop, pixels)))
    }

    /// The pixels the stop's polygon wrote on its earlier scanlines (empty at the end).
    pub fn earlier_writes(&mut self) -> Vec<(u32, u32)> {
        let Some(stop) = self.at() else { return Vec::new() };
        self.with_stepper(|stepper| {
            (stepper.tracer().trace(stop.polygon).scanlines[..stop.scanline].iter())
                .flat_map(|r| r.pixels.iter().filter(|e| e.outcome == crate::simulate::events::Outcome::Written))
                .map(|e| (e.x, e.y))
                .collect()
        })
    }

    /// Carries out `command` and says what became of it.
    pub fn act(&mut self, lang: Lang, command: Command) -> Said {
        if let Command::Answer(typed) = &command {
            return self.answer(lang, typed);
        }
        if command == Command::Quit {
            // A question answered once and still open counts, as not answered right.
            if let Some(quiz) = self.quiz.as_mut().filter(|quiz| quiz.wrong_tries > 0) {
                quiz.score.skipped += 1;
                quiz.wrong_tries = 0;
            }
            return Said::Quit;
        }
        if command == Command::Skip {
            return self.skip();
        }
        let open = self.open_questions();
        if open > 0 {
            return Said::Moved(Moved::Refused(RefusedMove::QuestionsOpen { open }));
        }
        let moved = self.held.with_dependent_mut(|_, stepper| match command {
            Command::Next => stepper.forward(),
            Command::Back => stepper.back(),
            Command::NextPolygon => stepper.next_polygon(),
            Command::PreviousPolygon => stepper.previous_polygon(),
            Command::Go(row) => stepper.go(row),
            Command::GoTo { polygon, row } => stepper.go_to(polygon, row),
            Command::Answer(_) | Command::Skip | Command::Quit => unreachable!("handled above"),
        });
        self.arrived(moved)
    }

    /// How many questions of the current stop are still open.
    pub fn open_questions(&mut self) -> usize {
        let Some(quiz) = &self.quiz else { return 0 };
        let (mode, coverage_done, pixels_done) = (quiz.mode, quiz.coverage_done, quiz.pixels_done);
        let Some(record) = self.record() else { return 0 };
        let coverage = usize::from(mode == QuizMode::Coverage && !coverage_done);
        coverage + record.pixels.len().saturating_sub(pixels_done)
    }

    fn arrived(&mut self, moved: Moved) -> Said {
        let at = self.at();
        if let Some(quiz) = &mut self.quiz {
            quiz.at(at);
        }
        Said::Moved(moved)
    }

    /// Skips every open question of the stop.
    fn skip(&mut self) -> Said {
        let open = self.open_questions();
        let Some(quiz) = &mut self.quiz else { return Said::Skipped(0) };
        quiz.score.skipped += open;
        quiz.coverage_done = true;
        quiz.pixels_done = usize::MAX;
        quiz.wrong_tries = 0;
        quiz.end_stop();
        Said::Skipped(open)
    }

    fn answer(&mut self, lang: Lang, typed: &str) -> Said {
        let Some(question) = self.question() else { return Said::NothingAsked(typed.to_string()) };
        let typed = typed.trim();
        let judged = self.held.with_dependent_mut(|scene, stepper| {
            let verdict = judge(lang, scene, stepper, &question, typed)?;
            let (covered, neighbours): (Vec<u32>, Vec<Vec<u32>>) = match &question {
                Question::Coverage { stop, row } => {
                    let columns = |record: &crate::observe::trace::ScanlineRecord| {
                        let mut x: Vec<u32> = record.pixels.iter().map(|p| p.x).collect();
                        x.sort_unstable();
                        x
                    };
                    let trace = stepper.tracer().trace(stop.polygon);
                    let near = trace.scanlines.iter().filter(|r| r.row + 1 == *row || r.row == *row + 1).map(columns);
                    let near = near.collect();
                    (columns(stepper.tracer().record(*stop)), near)
                }
                _ => (Vec::new(), Vec::new()),
            };
            let hint = (!verdict.right).then(|| hint(scene, &question, &covered, &neighbours, typed));
            Ok::<_, String>((verdict, hint))
        });
        let (verdict, hint) = match judged {
            Ok(judged) => judged,
            Err(again) => return Said::AskAgain(again),
        };
        let quiz = self.quiz.as_mut().expect("a question is asked only in a quiz");
        let first = quiz.wrong_tries == 0;
        let said = match (verdict.right, first) {
            (true, _) => {
                if first {
                    quiz.score.first_try += 1;
                } else {
                    quiz.score.second_try += 1;
                }
                Said::Right { verdict: Box::new(verdict), second_try: !first }
            }
            (false, true) => {
                quiz.wrong_tries = 1;
                let said = verdict.said.clone();
                quiz.mistakes.push(Mistake { question: question.clone(), said: said.clone(), revealed: false });
                return Said::TryAgain { said, hint: hint.unwrap_or(Hint::Other) };
            }
            (false, false) => {
                quiz.score.revealed += 1;
                quiz.mistakes.push(Mistake { question: question.clone(), said: verdict.said.clone(), revealed: true });
                Said::Revealed(Box::new(verdict))
            }
        };
        quiz.wrong_tries = 0;
        match question {
            Question::Coverage { .. } => quiz.coverage_done = true,
            Question::Depth { .. } | Question::Frame { .. } => quiz.pixels_done += 1,
        }
        if self.open_questions() == 0
            && let Some(quiz) = self.quiz.as_mut()
        {
            quiz.end_stop();
        }
        said
    }

    /// Ends the quiz as `q` ends it (a question answered once and still
    /// open counts, as not answered right) and says its [`summary`](Self::summary).
    pub fn finish(&mut self, lang: Lang) -> String {
        self.act(lang, Command::Quit);
        self.summary(lang)
    }

    /// The score and each question answered wrong, with what was right and why.
    pub fn summary(&mut self, lang: Lang) -> String {
        let Some(quiz) = &self.quiz else { return String::new() };
        let mistakes = quiz.mistakes.clone();
        let mut text = format!("{}\n", quiz.score.text(lang));
        let revealed: Vec<&Mistake> = mistakes.iter().filter(|m| m.revealed).collect();
        if !revealed.is_empty() {
            text.push_str(&format!("{}\n", words!(lang, "quiz-mistakes")));
        }
        for mistake in revealed {
            let line = self.held.with_dependent_mut(|scene, stepper| {
                let verdict = judge(lang, scene, stepper, &mistake.question, &mistake.said).ok()?;
                Some(crate::teach::step::mistake_text(lang, scene, &verdict))
            });
            if let Some(line) = line {
                text.push_str(&format!("  {line}\n"));
            }
        }
        text
    }
}

/// The library's judge of one question.
fn judge(
    lang: Lang,
    scene: &Scene,
    stepper: &mut Stepper<'_>,
    question: &Question,
    typed: &str,
) -> Result<Verdict, String> {
    let (right, meant, expected, why) = match question {
        Question::Coverage { stop, .. } => judge_coverage(lang, stepper.tracer().record(*stop), typed),
        // A value no cell holds is asked again, but not the depth left unsaturated: that is a mistake.
        Question::Depth { pixel, .. } => {
            judge_depth(lang, scene, pixel, typed).or_else(|again| match depth_hint(scene, pixel, typed) {
                Hint::Misconception(Misconception::NoSaturation) => {
                    let (_, meant, expected, why) = judge_depth(lang, scene, pixel, &pixel.stored_after.text(lang))?;
                    Ok((false, meant.map(|_| Meant::Value), expected, why))
                }
                _ => Err(again),
            })
        }
        Question::Frame { pixel, .. } => judge_frame(lang, scene, pixel, typed),
    }?;
    let said = printable(typed).into_owned();
    Ok(Verdict { question: question.clone(), right, said, meant, expected, why })
}

mod hint;
mod said;

pub use said::{Command, Hint, KEYS, Said, Score};

#[cfg(test)]
mod tests;
