//! The browser playground's side in the library: everything the page shows
//! of a scene, as data made here from the scene's JSON text, so that the
//! page (compiled to WebAssembly with this library) renders facts and holds
//! no rule of its own. Each function takes the scene as text, exactly as the
//! page's editor holds it, and answers with JSON: the buffers after each
//! polygon and at the end (as `zsim run --final` prints them), the stepper's
//! lesson (the stepper and its quiz), a homework answer's check, a pixel's history,
//! the book-style figure, an edit of the scene, and the page's words.
//!
//! A scene is named in messages by [`scene_name`] ("the scene", in the
//! student's language), where the command line names its file: the student
//! never had a file. A scene travels in a page's address as `#scene=` and the scene
//! JSON in base64url (RFC 4648 §5, padding optional): [`fragment_of`] and
//! [`scene_of_fragment`].

use std::path::Path;

use base64::Engine as _;
use serde_json::Value;

use crate::effects::arith::Arith;
use crate::error::Refusal;
use crate::observe::explain::Buffer;
use crate::observe::explain::history::{Extras, history};
use crate::observe::render::figure::{self, Shading};
use crate::observe::render::report;
use crate::scene::Scene;
use crate::scene::refused::{FormatProblem, SceneProblem, SceneRefused};
use crate::simulate::events::Unobserved;
use crate::simulate::simulation::Simulation;
use crate::teach::check::answer_from_text;
pub use crate::teach::page_limits::{MAX_PAGE_SCENE_BYTES, MAX_PRINTED_CELLS, MAX_SHOWN_CELLS, MAX_SHOWN_POLYGONS};
use crate::teach::page_limits::{PageLimit, check_reach, check_text};
use crate::teach::step::lesson::{Command, Lesson, Said};
use crate::teach::step::page::printed_buffers;
use crate::teach::step::{Moved, QuizMode};
use crate::words::Lang;

mod shown;
mod site;
pub use shown::{
    Acted, AfterView, AnswerFileView, At, CheckView, Checkable, ClearedTo, DrawnSettings, ErrorAt, Failed, FigureView,
    KeyAction, LessonView, PolygonView, QUIZ_KINDS, RasterRow, SceneView, TextView, keys, lesson_view, quiz_mode,
    scene_view,
};
pub use site::{one_file_page, site_files, step_page, write_site};

mod edit;
pub use edit::{Edit, edit, layout};

/// How the scene typed into the page is named in messages: "the scene", in
/// the student's language.
pub fn scene_name(lang: Lang) -> String {
    words!(lang, "scene-name-default")
}

/// Whether the page shows `scene` cell by cell and polygon by polygon (its
/// buffers after each polygon, the stepper).
fn shown_by_polygon(scene: &Scene) -> bool {
    u64::from(scene.width) * u64::from(scene.height) <= MAX_SHOWN_CELLS && scene.polygons.len() <= MAX_SHOWN_POLYGONS
}

/// Why a scene of `bytes` bytes is not read by the page, in one line.
fn too_long(lang: Lang, bytes: usize) -> String {
    PageLimit::Bytes { path: None, bytes }.message(lang)
}

/// [`Failed`] as the JSON the page reads.
fn failed(error: String) -> Value {
    Failed::because(error).value()
}

/// The scene read from `text`, or its error worded as the command line words
/// it ([`Failed`]), with where the page marks it ([`ErrorAt`]).
fn scene_of(lang: Lang, text: &str) -> Result<Scene, Value> {
    let refused = |too_large: PageLimit| failed(too_large.message(lang));
    // The page's limits, before the scene is read (reading is the work they spare)…
    check_text(text, None).map_err(refused)?;
    let scene = Scene::from_json(text, Path::new(&scene_name(lang))).map_err(|error| {
        let problem = error.refused::<SceneRefused>().map(|refused| &refused.problem);
        let at = match (&error, problem) {
            (crate::error::Error::Polygon { index, .. }, _) => Some(ErrorAt::Polygon { polygon: *index }),
            (_, Some(SceneProblem::Setting { key, .. })) => Some(ErrorAt::Setting { key: key.to_string() }),
            (_, Some(SceneProblem::Format(FormatProblem { line: Some(line), .. }))) => {
                let shown = text.lines().nth(line.saturating_sub(1)).unwrap_or_default();
                let shown = crate::words::printable(shown).into_owned();
                let said = words!(lang, "error-at-line", line = *line, text = shown.clone());
                Some(ErrorAt::Line { line: *line, text: shown, said })
            }
            _ => None,
        };
        Failed { at, ..Failed::because(error.message(lang)) }.value()
    })?;
    // …and what its polygons reach, before anything is drawn.
    check_reach(&scene, None).map_err(refused)?;
    Ok(scene)
}

/// Everything the page shows of the scene in `text`: its size, whether the
/// page shows it polygon by polygon (`byPolygon`) and then each polygon's
/// outline in pixel units (`polygons`), the states a homework answer may be
/// checked against (`checkable`: `{"index", "label"}`), the final buffers as `zsim run --final` prints
/// them (`framebuffer`, `zbuffer`), the palette and notes; or `{"ok":
/// false, "error": …}` with the scene's error. The buffers after one
/// polygon are [`after`]'s, the stepper's the lesson's ([`lesson_state`]).
pub fn view(lang: Lang, text: &str) -> Value {
    match scene_of(lang, text) {
        Ok(scene) => view_of(lang, &scene),
        Err(error) => error,
    }
}

/// [`view`] of a scene already read (the lesson's: one reading for every view): [`SceneView`].
pub fn view_of(lang: Lang, scene: &Scene) -> Value {
    shown::value(shown::scene_view(lang, scene))
}

/// The buffers after polygon `number` (from 1, as the page names it) of the
/// scene in `text`, as `zsim run --after` prints them, with the polygon's
/// heading and counts: `{"heading", "counts", "frame", "depth"}`, or
/// `{"ok": false, "error"}` (also where the page does not show the scene
/// polygon by polygon).
pub fn after(lang: Lang, text: &str, number: usize) -> Value {
    match scene_of(lang, text) {
        Ok(scene) => after_of(lang, &scene, number),
        Err(error) => error,
    }
}

/// [`after`] of a scene already read (the lesson's: one reading for every view).
pub fn after_of(lang: Lang, scene: &Scene, number: usize) -> Value {
    let cells = u64::from(scene.width) * u64::from(scene.height);
    let Some(index) = number.checked_sub(1).filter(|index| *index < scene.polygons.len()) else {
        return failed(words!(lang, "no-such-polygon"));
    };
    if cells > MAX_SHOWN_CELLS || scene.polygons.len() > MAX_SHOWN_POLYGONS {
        return failed(words!(lang, "no-such-polygon"));
    }
    let mut simulation = Simulation::new(scene);
    let mut last = None;
    for _ in 0..=index {
        last = simulation.draw_next_counted(&mut Unobserved);
    }
    let Some(drawn) = last else { return failed(words!(lang, "no-such-polygon")) };
    let (frame, depth) = printed_buffers(simulation.buffers());
    shown::value(AfterView {
        ok: true,
        heading: report::polygon_heading(lang, scene, drawn.index),
        counts: words!(lang, "run-counts", covered = drawn.tested.to_string(), written = drawn.written.to_string()),
        frame,
        depth,
    })
}

/// The book-style figure of the scene in `text` after its last polygon, as
/// `zsim figure` draws it (SVG), or `{"ok": false, "error"}` (also for a
/// raster of more than [`MAX_PRINTED_CELLS`] pixels).
pub fn figure(lang: Lang, text: &str) -> Value {
    match scene_of(lang, text) {
        Ok(scene) => figure_of(lang, &scene),
        Err(error) => error,
    }
}

/// [`figure`] of a scene already read (the lesson's: one reading for every view).
pub fn figure_of(lang: Lang, scene: &Scene) -> Value {
    let Some(last) = scene.polygons.len().checked_sub(1) else {
        return failed(words!(lang, "no-such-polygon"));
    };
    if u64::from(scene.width) * u64::from(scene.height) > MAX_PRINTED_CELLS {
        return failed(words!(lang, "limit-figure-cells", cells = MAX_PRINTED_CELLS.to_string()));
    }
    let mut simulation = Simulation::new(scene);
    simulation.finish(&mut Unobserved);
    let svg = figure::svg(lang, scene, simulation.buffers(), last, Shading::Frame, &scene_name(lang));
    shown::value(FigureView { ok: true, svg })
}

/// The lesson of the scene in `text` with a quiz in `mode` or none, at
/// `place` (polygon from 1, pixel row: where an address points) or, when it
/// is `None` or no stop of the scene, at the first stop; or `{"ok": false,
/// "error"}` with the scene's error.
pub fn lesson(lang: Lang, text: &str, mode: Option<QuizMode>, place: Option<(usize, u32)>) -> Result<Lesson, Value> {
    let mut lesson = Lesson::new(scene_of(lang, text)?, Arith::Exact, mode);
    // A scene the page does not show cell by cell is not stepped: the lesson stays before its first stop.
    if !shown_by_polygon(lesson.scene()) {
        return Ok(lesson);
    }
    let placed = place.is_some_and(|(polygon, row)| {
        matches!(lesson.place(polygon.saturating_sub(1), row), Said::Moved(Moved::To { at: Some(_), .. }))
    });
    if !placed {
        lesson.start(None);
    }
    Ok(lesson)
}

/// A page's command to the lesson: `{"key": "n"}` (a key of
/// [`crate::teach::step::lesson::KEYS`]), `{"go": [polygon, row]}` (polygon
/// from 1, as an address names it) or `{"answer": "15"}`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PageCommand {
    /// A key that acts alone.
    Key(char),
    /// A polygon (from 1) and a pixel row.
    Go(usize, u32),
    /// An answer to the open question.
    Answer(String),
}

impl PageCommand {
    /// The command of the page's JSON text; `None` for text that is not one.
    pub fn parse(text: &str) -> Option<PageCommand> {
        let command: Value = serde_json::from_str(text).ok()?;
        if let Some(key) = command.get("key") {
            let mut chars = key.as_str()?.chars();
            return match (chars.next(), chars.next()) {
                (Some(key), None) => Some(PageCommand::Key(key)),
                _ => None,
            };
        }
        if let Some(go) = command.get("go") {
            let polygon = usize::try_from(go.get(0)?.as_u64()?).ok()?;
            return Some(PageCommand::Go(polygon, u32::try_from(go.get(1)?.as_u64()?).ok()?));
        }
        Some(PageCommand::Answer(command.get("answer")?.as_str()?.to_string()))
    }
}

/// [`lesson_acted`] as JSON: [`Acted`], or `{"ok": false, "error"}`.
pub fn lesson_act(lang: Lang, lesson: &mut Lesson, command: &str) -> Value {
    match lesson_acted(lang, lesson, command) {
        Ok(acted) => shown::value(acted),
        Err(error) => error,
    }
}

/// Carries out `command` (JSON, [`PageCommand`]) and answers with what became
/// of it ([`Acted`]); `Err` with `{"ok": false, "error"}` for a command that
/// is not one.
pub fn lesson_acted(lang: Lang, lesson: &mut Lesson, command: &str) -> Result<Acted, Value> {
    let command = match PageCommand::parse(command) {
        Some(PageCommand::Key(key)) => Command::from_key(key),
        Some(PageCommand::Go(polygon, row)) => {
            Some(Command::GoTo { polygon: polygon.saturating_sub(1).min(usize::MAX - 1), row })
        }
        Some(PageCommand::Answer(typed)) => Some(Command::Answer(typed)),
        None => None,
    };
    let Some(command) = command else {
        return Err(failed(words!(lang, "edit-does-not-fit")));
    };
    let said = lesson.act(lang, command);
    let kind = match &said {
        Said::Moved(Moved::To { .. }) => "moved",
        Said::Moved(Moved::Refused(_)) => "refused",
        Said::Right { .. } => "right",
        Said::TryAgain { .. } => "tryAgain",
        Said::Revealed(_) => "revealed",
        Said::AskAgain(_) => "askAgain",
        Said::Skipped(_) => "skipped",
        Said::NothingAsked(_) => "nothingAsked",
        Said::Quit => "quit",
    };
    let text = said.text(lang, lesson.scene());
    // The quiz ended: its score and each mistake, as the line mode ends with them.
    let summary = matches!(said, Said::Quit).then(|| lesson.summary(lang));
    Ok(Acted { ok: true, kind, said: text, summary, state: lesson_view(lang, lesson) })
}

/// Everything the page shows of the lesson now, already cut to what may be
/// shown: [`LessonView`].
pub fn lesson_state(lang: Lang, lesson: &mut Lesson) -> Value {
    shown::value(shown::lesson_view(lang, lesson))
}

/// A homework answer for `buffer` after polygon `number` (from 1, as the page names it),
/// typed or pasted as the book prints a matrix, checked as `zsim check`
/// checks a file: `{"verdict", "hint", "wrong": [{x, y, answer, expected,
/// reason}], "more", "diagnosis"}`, or `{"ok": false, "error"}` for a scene
/// or an answer that cannot be read.
pub fn check(lang: Lang, text: &str, number: usize, buffer: Buffer, typed: &str) -> Value {
    let scene = match scene_of(lang, text) {
        Ok(scene) => scene,
        Err(error) => return error,
    };
    let Some(after) = number.checked_sub(1).filter(|index| *index < scene.polygons.len()) else {
        return failed(words!(lang, "no-such-polygon"));
    };
    let answer = match answer_from_text(typed, &scene, buffer) {
        Ok(answer) => answer,
        Err(refused) => return failed(refused.message(lang)),
    };
    let name = words!(lang, "column-your-answer");
    let answers = vec![(buffer, Path::new(&name), answer)];
    let report =
        match crate::teach::check::check(lang, &scene, Path::new(&scene_name(lang)), after, answers, Arith::Exact) {
            Ok(report) => report,
            Err(error) => return failed(error.message(lang)),
        };
    let answer = &report.answers[0];
    let more = (answer.differing > answer.wrong.len())
        .then(|| words!(lang, "check-more-cells", count = answer.differing - answer.wrong.len()));
    // The score by grading's rule, as `grade` gives this answer alone.
    let percent =
        crate::numbers::decimal(crate::teach::grade::score(&[answer.earned]) * crate::numbers::Q::from_integer(100), 1);
    let score = words!(lang, "class-page-score", score = crate::words::localize_decimal(lang, percent));
    let columns = [
        "x".to_string(),
        "y".to_string(),
        words!(lang, "check-column-answer"),
        words!(lang, "check-column-right"),
        words!(lang, "check-column-why"),
    ];
    shown::value(CheckView {
        ok: true,
        right: answer.wrong.is_empty(),
        verdict: report.verdict(lang, answer),
        hint: answer.hint.clone(),
        score,
        wrong: answer.wrong.clone(),
        more,
        diagnosis: report.diagnosis.clone(),
        columns,
    })
}

/// A homework answer as the file a student of a class hands in: the answer
/// for `buffer` after the last polygon, typed as the book prints a matrix,
/// written as `IDENTITY.frame.txt` (or `.depth.txt`) with the variant's code
/// in its first line, as `grade --variants` reads it:
/// `{"ok": true, "name", "text"}`, or `{"ok": false, "error"}` for an answer
/// that cannot be read or an identity that cannot name a file.
pub fn answer_file(lang: Lang, text: &str, buffer: Buffer, typed: &str, student: &str, code: &str) -> Value {
    let scene = match scene_of(lang, text) {
        Ok(scene) => scene,
        Err(error) => return error,
    };
    if student.is_empty() || !crate::teach::course::roster::nameable(student) {
        let identity = crate::words::printable(student).into_owned();
        return failed(words!(lang, "manifest-unnameable", place = scene_name(lang), identity = identity));
    }
    let answer = match answer_from_text(typed, &scene, buffer) {
        Ok(answer) => answer,
        Err(refused) => return failed(refused.message(lang)),
    };
    let code: String = code.chars().filter(|c| c.is_ascii_alphanumeric() || *c == '-').take(7).collect();
    let mut file = format!("# variant {code}\n");
    for (row, cells) in answer.rows.iter().enumerate() {
        let cells: Vec<String> = cells
            .iter()
            .enumerate()
            .map(|(x, v)| if answer.answered(row, x) { v.to_string() } else { "?".into() })
            .collect();
        file.push_str(&cells.join(" "));
        file.push('\n');
    }
    let name = format!("{student}.{}.txt", crate::teach::grade::file_kind(buffer));
    shown::value(AnswerFileView { ok: true, name, text: file })
}

/// Pixel `(x, y)`'s history through the scene, as `zsim explain` prints it.
pub fn explain(lang: Lang, text: &str, x: u32, y: u32) -> Value {
    match scene_of(lang, text) {
        Ok(scene) => explain_of(lang, &scene, x, y),
        Err(error) => error,
    }
}

/// [`explain_typed`] of the lesson's scene, but hidden while a question of
/// the lesson is open: any pixel's history would answer it or a later one.
pub fn lesson_explain(lang: Lang, lesson: &mut Lesson, x: &str, y: &str) -> Value {
    if lesson.open_questions() > 0 {
        return Failed { hidden: true, ..Failed::because(words!(lang, "lesson-hidden-until-answered")) }.value();
    }
    explain_typed(lang, lesson.scene(), x, y)
}

/// [`explain_of`] of a pixel given as the page's address or a click gives
/// it, as text: a coordinate that is not a whole number, or a pixel off the
/// raster (however far: `4294967306` is not wrapped to `10`), is said in one
/// line, as `zsim explain` says it.
pub fn explain_typed(lang: Lang, scene: &Scene, x: &str, y: &str) -> Value {
    let coordinate = |text: &str| {
        let digits = !text.is_empty() && text.len() <= 20 && text.bytes().all(|b| b.is_ascii_digit());
        digits
            .then(|| text.parse::<u64>().ok())
            .flatten()
            .ok_or_else(|| failed(words!(lang, "usage-pixel-coordinate", text = crate::words::token(lang, text))))
    };
    let (x, y) = match (coordinate(x), coordinate(y)) {
        (Ok(x), Ok(y)) => (x, y),
        (Err(error), _) | (_, Err(error)) => return error,
    };
    match (u32::try_from(x), u32::try_from(y)) {
        (Ok(x), Ok(y)) => explain_of(lang, scene, x, y),
        _ => {
            let (width, height) = (scene.width, scene.height);
            let error = crate::error::Refusal::message(
                &crate::observe::explain::history::PixelOutside { x, y, width, height },
                lang,
            );
            failed(error)
        }
    }
}

/// [`explain`] of a scene already read (the lesson's: one reading for every view).
pub fn explain_of(lang: Lang, scene: &Scene, x: u32, y: u32) -> Value {
    match history(scene, (x, y), Extras::default()) {
        Ok(history) => {
            shown::value(TextView { ok: true, text: history.text(lang, scene, Path::new(&scene_name(lang))) })
        }
        Err(error) => failed(error.message(lang)),
    }
}

/// The address fragment that carries a scene: `scene=` and the text in
/// base64url without padding.
pub fn fragment_of(text: &str) -> String {
    format!("scene={}", base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(text.as_bytes()))
}

/// The scene text carried by `fragment` (`scene=…`, with or without `#`,
/// base64url with or without padding); `Err` worded in `lang`.
pub fn scene_of_fragment(lang: Lang, fragment: &str) -> Result<String, String> {
    let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
    let Some(encoded) = fragment.strip_prefix("scene=") else { return Err(words!(lang, "address-holds-no-scene")) };
    let encoded = encoded.trim_end_matches('=');
    // The decoded length, known before decoding: three bytes each four characters, and one or two
    // for a last group of two or three.
    let bytes = encoded.len() / 4 * 3 + [0, 0, 1, 2][encoded.len() % 4];
    if bytes > MAX_PAGE_SCENE_BYTES {
        return Err(too_long(lang, bytes));
    }
    let bytes = base64::engine::general_purpose::URL_SAFE_NO_PAD
        .decode(encoded)
        .map_err(|_| words!(lang, "address-holds-no-scene"))?;
    String::from_utf8(bytes).map_err(|_| words!(lang, "error-not-utf8"))
}

/// The page's own words in `lang`, by the name the page gives each.
pub fn page_words(lang: Lang) -> Value {
    let mut words = serde_json::Map::new();
    for (name, key) in PAGE_WORDS {
        words.insert(name.to_string(), Value::String(crate::words::text(lang, key, &[])));
    }
    words.insert("lang".into(), Value::String(lang.code().into()));
    // The keys the page takes, from the lesson's one table, and the quiz's kinds.
    words.insert("keys".into(), shown::value(keys(lang)));
    words.insert("quizKinds".into(), shown::value(QUIZ_KINDS));
    words.insert("depthName".into(), Value::String(Buffer::Depth.name(lang)));
    words.insert("frameName".into(), Value::String(Buffer::Frame.name(lang)));
    Value::Object(words)
}

/// The line above a class's homework: whose it is and the variant's code, from the student's link.
pub fn variant_line(lang: Lang, student: &str, code: &str) -> String {
    words!(lang, "class-page-variant", code = code, student = student)
}

/// The page's labels: the name the page uses, and the catalogue's key.
const PAGE_WORDS: [(&str, &str); 57] = [
    ("saveAnswer", "class-page-save"),
    ("title", "title-scene-editor"),
    ("intro", "intro-scene-editor"),
    ("language", "field-language"),
    ("sceneHeading", "heading-scene"),
    ("width", "field-width"),
    ("height", "field-height"),
    ("frameBits", "field-frame-bits"),
    ("depthBits", "field-depth-bits"),
    ("depthTest", "field-depth-test"),
    ("preset", "field-preset"),
    ("presetNone", "field-preset-none"),
    ("snap", "field-snap"),
    ("polygon", "field-polygon"),
    ("value", "field-value"),
    ("addPolygon", "command-add-polygon"),
    ("removePolygon", "command-remove-polygon"),
    ("addVertex", "command-add-vertex"),
    ("removeVertex", "command-remove-vertex"),
    ("json", "heading-scene-json"),
    ("share", "command-copy-link"),
    ("shared", "link-in-address-bar"),
    ("buffers", "heading-buffers-each-polygon"),
    ("finalBuffers", "heading-final-buffers"),
    ("grid", "heading-raster"),
    ("gridHelp", "raster-help"),
    ("explainHeading", "heading-pixel-history"),
    ("stepper", "heading-scanline-by-scanline"),
    ("figure", "heading-figure"),
    ("homework", "heading-homework"),
    ("homeworkHelp", "homework-help"),
    ("checkAnswer", "command-check"),
    ("answerGrid", "answer-grid-label"),
    ("after", "column-after"),
    ("back", "command-back"),
    ("next", "command-next"),
    ("quiz", "quiz-label"),
    ("stored", "column-stored"),
    ("why", "column-why"),
    ("check", "command-check-answers"),
    ("previousPolygon", "command-previous-polygon"),
    ("nextPolygon", "command-next-polygon"),
    ("skip", "command-skip"),
    ("endQuiz", "command-end-quiz"),
    ("quizKind", "quiz-kind-label"),
    ("coverageKind", "quiz-kind-coverage"),
    ("examples", "heading-examples"),
    ("reset", "command-reset"),
    ("copied", "link-copied"),
    ("gridLabel", "raster-label"),
    ("bufferKind", "buffer-kind-label"),
    ("exampleRogers", "example-rogers"),
    ("exampleSection", "example-section"),
    ("exampleLess", "example-less"),
    ("exampleCull", "example-cull"),
    ("exampleConcave", "example-concave"),
    ("legend", "legend-heading"),
];

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    const BOOK: &str = include_str!("../../../examples/rogers.json");

    /// The page's final buffers are `zsim run --final`'s matrices: here the
    /// book's depth 15 at (15, 15) and the triangle's 2 beside the rectangle.
    #[test]
    fn the_final_buffers_are_run_final_s_matrices() {
        let view = view(Lang::En, BOOK);
        let depth = view["zbuffer"].as_str().unwrap();
        let row_15 = depth.lines().nth(31 - 15).unwrap();
        assert_eq!(row_15.split_whitespace().nth(15), Some("15"));
        assert_eq!(view["framebuffer"].as_str().unwrap().lines().count(), 32);
        assert_eq!(view["byPolygon"], true);
        // After the rectangle alone (polygon 1): 10 at (15, 15), where the triangle later writes 15.
        let first = after(Lang::En, BOOK, 1);
        assert_eq!(
            first["depth"].as_str().unwrap().lines().nth(31 - 15).unwrap().split_whitespace().nth(15),
            Some("10")
        );
        assert_eq!(after(Lang::En, BOOK, 2)["depth"], view["zbuffer"]);
        assert_eq!(
            (after(Lang::En, BOOK, 3)["ok"].as_bool(), after(Lang::En, BOOK, 0)["ok"].as_bool()),
            (Some(false), Some(false))
        );
    }

    /// Found by a student: `#pixel=0,32` (one past the book's raster) panicked
    /// the module and the page stopped answering; `2^32 + 10` wrapped to 10.
    #[test]
    fn a_pixel_off_the_raster_is_said_as_explain_says_it_however_far() {
        let scene = Scene::from_json(BOOK, Path::new("the scene")).unwrap();
        let said = |x: &str, y: &str| explain_typed(Lang::En, &scene, x, y);
        let outside = "is outside the 32×32 raster (x 0 … 31, y 0 … 31)";
        assert_eq!(said("0", "32")["error"], format!("pixel (0, 32) {outside}"));
        assert_eq!(said("4294967306", "0")["error"], format!("pixel (4294967306, 0) {outside}"));
        assert_eq!(said("1.5", "0")["error"], "\"1.5\" is not a pixel coordinate");
        assert_eq!(said("20", "15")["ok"], true);
        assert!(said("20", "15")["text"].as_str().unwrap().contains("43/4 ≈ 10.75"));
    }

    /// Found by a student: with the quiz on, the page showed what it asked
    /// (the asked pixel's history, the final buffers). While a question is
    /// open the history is hidden and the state says what stands in for the
    /// buffers; once the scanline's questions end, both are shown.
    #[test]
    fn while_a_question_is_open_the_history_and_the_buffers_are_hidden() {
        let mut lesson = lesson(Lang::En, BOOK, Some(QuizMode::Depth), Some((2, 15))).unwrap();
        let hidden = "hidden until this scanline's questions are answered or skipped";
        assert_eq!(lesson_explain(Lang::En, &mut lesson, "15", "15")["error"], hidden);
        assert_eq!(lesson_explain(Lang::En, &mut lesson, "0", "0")["hidden"], true);
        assert_eq!(lesson_state(Lang::En, &mut lesson)["buffersHidden"], hidden);
        lesson_act(Lang::En, &mut lesson, r#"{"key": "s"}"#);
        assert_eq!(lesson_state(Lang::En, &mut lesson)["buffersHidden"], Value::Null);
        assert!(lesson_explain(Lang::En, &mut lesson, "15", "15")["text"].as_str().unwrap().contains("29/2"));
    }

    /// Found by a maintainer: the page showed `depth_test || "greater"`
    /// though a `"rules": "buet"` scene draws with `less`. The view gives the
    /// settings as the scene is drawn, and the page shows those.
    #[test]
    fn the_view_gives_the_settings_as_the_scene_is_drawn() {
        let buet = r#"{"width": 8, "height": 4, "rules": "buet", "polygons": []}"#;
        let settings = &view(Lang::En, buet)["settings"];
        assert_eq!(settings["depthTest"], "less");
        assert_eq!((settings["width"].as_u64(), settings["frameBits"].as_u64()), (Some(8), Some(2)));
        assert_eq!(view(Lang::En, BOOK)["settings"]["depthTest"], "greater");
    }

    /// A scene's error is the command line's, naming the scene and the place.
    #[test]
    fn a_bad_scene_is_worded_as_the_command_line_words_it() {
        let view = view(
            Lang::En,
            r#"{"width": 32, "height": 32, "polygons": [{"value": 1, "vertices": [[1, 2, 3], [4, 5]]}]}"#,
        );
        assert_eq!(view["ok"], false);
        let error = view["error"].as_str().unwrap();
        assert!(error.starts_with("the scene: polygon 1: vertices[1]: 2 entries"), "{error}");
        // Where the page marks it: the polygon's table, the setting, or the JSON's line.
        assert_eq!(view["at"]["line"], 1, "{view}");
        let view = super::view(Lang::En, "{\n  \"width\": 32,\n  \"height\": 32\n  \"polygons\": []\n}");
        let said = "line 4:   \"polygons\": []";
        assert_eq!(view["at"], json!({"line": 4, "text": "  \"polygons\": []", "said": said}), "{view}");
        let view = super::view(
            Lang::En,
            r#"{"width": 8, "height": 8, "polygons": [{"value": 1, "vertices": [[0, 0, 1], [1, 1, 1]]}]}"#,
        );
        assert_eq!(view["at"], json!({"polygon": 0}), "{view}");
        let view = super::view(Lang::En, r#"{"width": 0, "height": 32, "polygons": []}"#);
        assert_eq!(view["at"], json!({"key": "width"}), "{view}");
    }

    /// An edit keeps every other number exactly as written and lays the scene out one polygon a line.
    #[test]
    fn an_edit_changes_one_value_and_keeps_the_rest_exact() {
        let text = r#"{"polygons": [{"value": 1, "vertices": [[0.1, "43/4", 3], [1, 2, 3], [5, 1, 2]]}], "width": 8, "height": 8}"#;
        let edited =
            edit(Lang::En, text, r#"{"op": "set", "path": ["polygons", 0, "vertices", 1, 0], "value": "12.5"}"#)
                .unwrap();
        assert_eq!(
            edited,
            "{\n  \"width\": 8,\n  \"height\": 8,\n  \"polygons\": [\n    {\"value\": 1, \"vertices\": [[0.1, \"43/4\", 3], [12.5, 2, 3], [5, 1, 2]]}\n  ]\n}\n"
        );
        let fraction = edit(Lang::En, &edited, r#"{"op": "set", "path": ["width"], "value": "43/4"}"#).unwrap();
        assert!(fraction.contains("\"width\": \"43/4\""), "{fraction}");
        assert!(edit(Lang::En, &edited, r#"{"op": "remove", "path": ["polygons", 3]}"#).is_err());
    }

    /// A scene sent as `#scene=` comes back as it went, padded or not.
    #[test]
    fn a_scene_travels_in_the_address_and_back() {
        let fragment = fragment_of(BOOK);
        assert!(!fragment.contains(['+', '/', '=']) || fragment.starts_with("scene="));
        assert_eq!(scene_of_fragment(Lang::En, &format!("#{fragment}")).unwrap(), BOOK);
        assert_eq!(scene_of_fragment(Lang::En, "scene=e30=").unwrap(), "{}");
        assert_eq!(scene_of_fragment(Lang::En, "scene=e30").unwrap(), "{}");
        assert!(scene_of_fragment(Lang::En, "scene=%%%").is_err());
        // A scene longer than the page reads is refused in one line that names the limit, before any work.
        let long = fragment_of(&" ".repeat(MAX_PAGE_SCENE_BYTES + 3));
        let refused = scene_of_fragment(Lang::En, &long).unwrap_err();
        assert_eq!(
            refused,
            format!(
                "the page reads scenes of up to 1048576 bytes; this one has {}: zsim run draws it",
                MAX_PAGE_SCENE_BYTES + 3
            )
        );
        let view = view(Lang::En, &" ".repeat(MAX_PAGE_SCENE_BYTES + 1));
        assert_eq!(
            view["error"],
            "the page reads scenes of up to 1048576 bytes; this one has 1048577: zsim run draws it"
        );
    }

    /// The page's lesson is the library's: the same refusals, hints and score as every front end.
    #[test]
    fn the_page_asks_the_librarys_lesson() {
        // The counts the page shows reach Fluent as numbers, worded here (plurals and all).
        let mut asked = lesson(Lang::En, BOOK, Some(QuizMode::Depth), Some((2, 15))).unwrap();
        let state = lesson_state(Lang::En, &mut asked);
        assert_eq!(state["hiddenSaid"], "13 more covered pixels, asked one at a time", "{state}");
        assert_eq!(words!(Lang::En, "pixels-hidden-asked", count = 1), "1 more covered pixel, asked next");
        let legend = view(Lang::Ru, BOOK)["legend"].clone();
        assert_eq!(legend.as_array().map(Vec::len), Some(4), "one name for each of the 2-bit framebuffer's values");
        let mut lesson = lesson(Lang::En, BOOK, Some(QuizMode::Depth), None).unwrap();
        let moved = lesson_act(Lang::En, &mut lesson, r#"{"go": [2, 15]}"#);
        assert_eq!(moved["kind"], "refused", "{moved}");
        lesson_act(Lang::En, &mut lesson, r#"{"key": "s"}"#);
        let moved = lesson_act(Lang::En, &mut lesson, r#"{"go": [2, 15]}"#);
        assert_eq!((moved["kind"].as_str(), moved["state"]["at"]["row"].as_u64()), (Some("moved"), Some(15)));
        assert_eq!(moved["state"]["rows"].as_array().unwrap().len(), 0, "{moved}");
        let wrong = lesson_act(Lang::En, &mut lesson, r#"{"answer": "14"}"#);
        assert_eq!(wrong["kind"], "tryAgain");
        assert!(!wrong["said"].as_str().unwrap().contains("15"), "{wrong}");
        let right = lesson_act(Lang::En, &mut lesson, r#"{"answer": "15"}"#);
        assert_eq!(right["kind"], "right");
        assert_eq!(right["state"]["rows"][0]["z"], "29/2");
        assert!(right["state"]["score"].as_str().unwrap().contains("1 at the second"), "{right}");
    }

    /// The page's words exist in every language (a missing key would show its name).
    #[test]
    fn every_page_word_is_in_every_catalogue() {
        for lang in Lang::ALL {
            let words = page_words(lang);
            for (name, key) in PAGE_WORDS {
                assert_ne!(words[name].as_str().unwrap(), key, "{key} missing in {}", lang.code());
            }
        }
    }
}
