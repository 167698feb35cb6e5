//! What the page shows, as types: the scene's view ([`SceneView`]) and the
//! lesson's state ([`LessonView`]), serialized to the JSON the page renders.
//! Everything the page would otherwise decide is decided here: the settings
//! as the scene is drawn (a preset's and the defaults resolved), which
//! vertices can be dragged, the raster's cells as numbers with each row's
//! pixel y, every position already in the page's coordinates (rows top
//! first, y down: the page flips nothing), the keys and the quiz's kinds,
//! and polygons numbered from 1 wherever the page shows or names one.

use serde::Serialize;

use crate::numbers::to_f64;
use crate::observe::render::figure;
use crate::observe::render::report::{MatrixStyle, matrix_styled};
use crate::scene::Scene;
use crate::simulate::events::Unobserved;
use crate::simulate::simulation::Simulation;
use crate::teach::page_limits::{MAX_PRINTED_CELLS, MAX_SHOWN_CELLS, MAX_SHOWN_POLYGONS};
use crate::teach::step::lesson::{KEYS, Lesson};
use crate::teach::step::page::printed_buffers;
use crate::teach::step::table::PixelRow;
use crate::teach::step::{Question, QuizMode};
use crate::words::{Lang, polygon_label};

/// The quiz's kinds, as the page's address and its menu name them.
pub const QUIZ_KINDS: [&str; 3] = ["depth", "frame", "coverage"];

/// A quiz's kind by its name in the page's address; `None` for any other.
pub fn quiz_mode(name: &str) -> Option<QuizMode> {
    match name {
        "depth" => Some(QuizMode::Depth),
        "frame" => Some(QuizMode::Frame),
        "coverage" => Some(QuizMode::Coverage),
        _ => None,
    }
}

/// Everything the page shows of a scene (the stepper's part is [`LessonView`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct SceneView {
    /// Always true: the scene was read (an error is the other shape the page gets).
    pub ok: bool,
    /// The raster's width in pixels.
    pub width: u32,
    /// The raster's height in pixels.
    pub height: u32,
    /// The settings as the scene is drawn: what the page's fields show.
    pub settings: DrawnSettings,
    /// Each polygon's outline, where the page shows the scene polygon by polygon.
    pub polygons: Vec<PolygonView>,
    /// Whether the page shows the scene polygon by polygon.
    pub by_polygon: bool,
    /// Whether the vertices can be dragged: they are the raster's own
    /// coordinates (no window, no perspective).
    pub draggable: bool,
    /// The states a homework answer may be checked against.
    pub checkable: Vec<Checkable>,
    /// Whether the page colours the raster cell by cell.
    pub cell_by_cell: bool,
    /// What each buffer is cleared to: where a student's answer grid starts.
    pub cleared: ClearedTo,
    /// The final framebuffer as `zsim run --final` prints it bare ("" past the printed limit).
    pub framebuffer: String,
    /// The final z-buffer, likewise.
    pub zbuffer: String,
    /// The final framebuffer's cells, top row first (empty unless cell by cell).
    pub rows: Vec<RasterRow>,
    /// What the page says of the scene (what it leaves out, and why).
    pub notes: Vec<String>,
    /// The figure's colours for framebuffer values 1, 2, … (0 is white).
    pub palette: [&'static str; 7],
    /// Each framebuffer value's name in the legend, by value.
    pub legend: Vec<String>,
}

/// The settings as the scene is drawn.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct DrawnSettings {
    /// Raster width.
    pub width: u32,
    /// Raster height.
    pub height: u32,
    /// Framebuffer bits.
    pub frame_bits: u32,
    /// z-buffer bits.
    pub depth_bits: u32,
    /// The depth test by name (`greater`, `less`, …).
    pub depth_test: &'static str,
}

/// One polygon as the raster draws it.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct PolygonView {
    /// Its number, from 1, as the page and the address name it.
    pub number: usize,
    /// Its name in the scene.
    pub name: String,
    /// "after polygon N …", in the page's language.
    pub label: String,
    /// Its framebuffer value.
    pub value: u32,
    /// Its vertices in the page's coordinates: x, and y down from the raster's top.
    pub points: Vec<[f64; 2]>,
}

/// A state a homework answer may be checked against: after polygon `number`.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Checkable {
    /// The polygon's number, from 1.
    pub number: usize,
    /// "after polygon N …".
    pub label: String,
}

/// What each buffer is cleared to.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct ClearedTo {
    /// The framebuffer's background.
    pub frame: u32,
    /// The z-buffer's clearing level (none for exact depths).
    pub depth: Option<u32>,
}

/// One row of the raster, top first.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct RasterRow {
    /// Its pixel y.
    pub y: u32,
    /// Its cells' framebuffer values, x from 0.
    pub cells: Vec<u32>,
}

/// The buffers after one polygon, as `zsim run --after` prints them, with
/// the polygon's heading and counts ([`crate::playground::after`]).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct AfterView {
    /// Always true (a failure is [`Failed`]).
    pub ok: bool,
    /// The polygon's heading.
    pub heading: String,
    /// Its covered and written pixels, in words.
    pub counts: String,
    /// The framebuffer, printed.
    pub frame: String,
    /// The z-buffer, printed.
    pub depth: String,
}

/// The book-style figure after the last polygon ([`crate::playground::figure`]).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct FigureView {
    /// Always true (a failure is [`Failed`]).
    pub ok: bool,
    /// The figure, as SVG.
    pub svg: String,
}

/// A text the page shows as it is: a pixel's history
/// ([`crate::playground::explain`]).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct TextView {
    /// Always true (a failure is [`Failed`]).
    pub ok: bool,
    /// The text.
    pub text: String,
}

/// A homework answer checked ([`crate::playground::check`]).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct CheckView {
    /// Always true (a failure is [`Failed`]).
    pub ok: bool,
    /// Whether every answered cell is right.
    pub right: bool,
    /// The verdict, in words.
    pub verdict: String,
    /// The hint, where there is one.
    pub hint: Option<String>,
    /// The score by grading's rule, in words.
    pub score: String,
    /// The wrong cells named, each with why.
    pub wrong: Vec<crate::teach::check::WrongCell>,
    /// How many more cells differ, in words, where some are not named.
    pub more: Option<String>,
    /// The likely misconception, where one is found.
    pub diagnosis: Option<String>,
    /// The wrong cells' table's headings.
    pub columns: [String; 5],
}

/// A homework answer as the file a student hands in ([`crate::playground::answer_file`]).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct AnswerFileView {
    /// Always true (a failure is [`Failed`]).
    pub ok: bool,
    /// The file's name.
    pub name: String,
    /// Its text.
    pub text: String,
}

/// What the page gets instead of what it asked for: why not, in words.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Failed {
    /// Always false: nothing but the reason came back.
    pub ok: bool,
    /// Why not, in the page's language.
    pub error: String,
    /// Where the scene's text is wrong, for the page to mark (a scene's error only).
    pub at: Option<ErrorAt>,
    /// Whether it is an open question that hides what was asked for.
    pub hidden: bool,
}

/// Where a scene's text is wrong.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[serde(untagged)]
pub enum ErrorAt {
    /// A polygon (0-based, the page's table of it).
    Polygon {
        /// Its index.
        polygon: usize,
    },
    /// A setting, by its key.
    Setting {
        /// The key.
        key: String,
    },
    /// JSON that does not read: the line (from 1), its text, and both worded.
    Line {
        /// The line's number.
        line: usize,
        /// Its text, printable.
        text: String,
        /// "line N: …".
        said: String,
    },
}

impl Failed {
    /// The page told why not.
    pub fn because(error: String) -> Failed {
        Failed { ok: false, error, at: None, hidden: false }
    }

    /// As the JSON the page reads.
    pub fn value(&self) -> serde_json::Value {
        value(self)
    }
}

/// A view as the JSON the page reads (every view is plain data, which
/// serializes without fail).
pub(super) fn value(view: impl Serialize) -> serde_json::Value {
    serde_json::to_value(view).unwrap_or_default()
}

/// The scene's view of `scene`.
pub fn scene_view(lang: Lang, scene: &Scene) -> SceneView {
    let cells = u64::from(scene.width) * u64::from(scene.height);
    let by_polygon = cells <= MAX_SHOWN_CELLS && scene.polygons.len() <= MAX_SHOWN_POLYGONS;
    let label = |index: usize| polygon_label(lang, "polygon-after", index, &scene.polygons[index].name);
    let top = f64::from(scene.height);
    let polygons: Vec<PolygonView> = match by_polygon {
        true => (scene.polygons.iter().enumerate())
            .map(|(index, polygon)| PolygonView {
                number: index + 1,
                name: polygon.name.clone(),
                label: label(index),
                value: polygon.value,
                points: polygon.vertices().iter().map(|v| [to_f64(&v[0]), top - to_f64(&v[1])]).collect(),
            })
            .collect(),
        false => Vec::new(),
    };
    // After each polygon where the page shows them, after the last otherwise.
    let checkable = match by_polygon {
        true => polygons.iter().map(|p| Checkable { number: p.number, label: p.label.clone() }).collect(),
        false => (scene.polygons.len().checked_sub(1).into_iter())
            .map(|last| Checkable { number: last + 1, label: label(last) })
            .collect(),
    };
    let mut simulation = Simulation::new(scene);
    simulation.finish(&mut Unobserved);
    let buffers = simulation.buffers();
    let mut notes = Vec::new();
    if !by_polygon {
        notes.push(words!(
            lang,
            "limit-cells-or-polygons",
            cells = MAX_SHOWN_CELLS.to_string(),
            polygons = MAX_SHOWN_POLYGONS.to_string()
        ));
    }
    if scene.effects.antialias.is_some() {
        notes.push(words!(lang, "antialias-not-drawn"));
    }
    let printed = cells <= MAX_PRINTED_CELLS;
    if !printed {
        notes.push(words!(lang, "limit-printed-cells", cells = MAX_PRINTED_CELLS.to_string()));
    }
    let (framebuffer, zbuffer) = match printed {
        true => printed_buffers(buffers),
        false => (String::new(), String::new()),
    };
    let cell_by_cell = cells <= MAX_SHOWN_CELLS;
    SceneView {
        ok: true,
        width: scene.width,
        height: scene.height,
        settings: DrawnSettings {
            width: scene.width,
            height: scene.height,
            frame_bits: scene.frame_bits,
            depth_bits: scene.depth_bits,
            depth_test: scene.depth_test.name(),
        },
        polygons,
        by_polygon,
        draggable: scene.window.is_none() && scene.effects.perspective.is_none(),
        checkable,
        cell_by_cell,
        cleared: ClearedTo { frame: scene.background, depth: scene.clear_depth.level() },
        framebuffer,
        zbuffer,
        rows: match cell_by_cell {
            true => raster_rows(scene.height, buffers.frame_rows()),
            false => Vec::new(),
        },
        notes,
        palette: figure::PALETTE,
        legend: (0..1u32 << scene.frame_bits.min(8)).map(|value| words!(lang, "legend-value", value = value)).collect(),
    }
}

/// Rows top first, each with its pixel y.
fn raster_rows(height: u32, rows: Vec<Vec<u32>>) -> Vec<RasterRow> {
    (rows.into_iter().enumerate()).map(|(i, cells)| RasterRow { y: crate::raster::row_y(height, i), cells }).collect()
}

/// Everything the page shows of the lesson now, already cut to what may be
/// shown.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct LessonView {
    /// Where the lesson is; `None` at the end.
    pub at: Option<At>,
    /// At the end: why there is nothing more.
    pub end: Option<String>,
    /// The stop's polygon, its value and plane.
    pub heading: String,
    /// The step of z along a scanline.
    pub slope: String,
    /// "scanline y = 15.5 (row 15)".
    pub scanline: String,
    /// The crossings, once they may be shown.
    pub crossings: Option<String>,
    /// Where the scanline crosses the outline, in page x, once the crossings may be shown.
    pub crossings_x: Vec<f64>,
    /// The spans, once they may be shown.
    pub spans: Vec<String>,
    /// The spans with their ends' depths, once they may be shown.
    pub span_depths: Vec<String>,
    /// The covered columns, once they may be shown.
    pub columns: Vec<u32>,
    /// The shown pixels' rows.
    pub rows: Vec<PixelRow>,
    /// How many covered pixels are not shown yet.
    pub hidden: usize,
    /// That count, worded.
    pub hidden_said: Option<String>,
    /// What the stop says besides.
    pub notes: Vec<String>,
    /// The open question's kind, if one is open.
    pub asking: Option<&'static str>,
    /// The question, worded.
    pub prompt: Option<String>,
    /// The asked pixel's column.
    pub asked_x: Option<u32>,
    /// Whether the open question is at its second try.
    pub second_try: bool,
    /// How many of the stop's questions are open.
    pub open: usize,
    /// While a question is open: the words that stand in for what would
    /// answer it elsewhere on the page (the final buffers, the buffers after
    /// each polygon, the figure).
    pub buffers_hidden: Option<String>,
    /// The score, worded (a quiz only).
    pub score: Option<String>,
    /// The framebuffer's rows around the scanline, as the line mode prints them.
    pub frame: Option<String>,
    /// The z-buffer's rows around the scanline, likewise.
    pub depth: Option<String>,
    /// In a quiz, the framebuffer's cells as the student may see them, top row first.
    pub cells: Option<Vec<RasterRow>>,
}

/// Where the lesson is.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct At {
    /// The polygon's number, from 1.
    pub polygon: usize,
    /// The scanline's pixel row.
    pub row: u32,
    /// The scanline's y in the page's coordinates (down from the raster's top).
    pub line: f64,
}

/// The lesson's view now.
pub fn lesson_view(lang: Lang, lesson: &mut Lesson) -> LessonView {
    let asking = match lesson.question() {
        Some(Question::Coverage { .. }) => Some("coverage"),
        Some(Question::Depth { .. }) => Some("depth"),
        Some(Question::Frame { .. }) => Some("frame"),
        None => None,
    };
    let asked_x = match lesson.question() {
        Some(Question::Depth { pixel, .. } | Question::Frame { pixel, .. }) => Some(pixel.x),
        _ => None,
    };
    let open = lesson.open_questions();
    let shown = LessonView {
        asking,
        asked_x,
        prompt: lesson.prompt(lang),
        second_try: lesson.second_try(),
        open,
        score: lesson.score().map(|s| s.text(lang)),
        buffers_hidden: (open > 0).then(|| words!(lang, "lesson-hidden-until-answered")),
        ..LessonView::default()
    };
    let Some(view) = lesson.stop_view(lang) else {
        let scene = lesson.scene();
        let end = match u64::from(scene.width) * u64::from(scene.height) <= MAX_SHOWN_CELLS
            && scene.polygons.len() <= MAX_SHOWN_POLYGONS
        {
            true => words!(lang, "step-end"),
            false => words!(
                lang,
                "limit-cells-or-polygons",
                cells = MAX_SHOWN_CELLS.to_string(),
                polygons = MAX_SHOWN_POLYGONS.to_string()
            ),
        };
        return LessonView { end: Some(end), ..shown };
    };
    // The buffers' rows around the scanline, numbered as the line mode prints them, its row
    // marked `▶`; and the whole framebuffer's cells for the raster's colours.
    let height = lesson.scene().height;
    let rows = view.row.saturating_sub(2)..=(view.row + 2).min(height - 1);
    let style = MatrixStyle { axes: true, mark: Some(view.row), rows: Some(rows), color: false };
    let quiz = lesson.mode().is_some();
    let (frame, depth, cells) = match lesson.buffers() {
        Some(buffers) => (
            Some(matrix_styled(&buffers.frame_rows(), &style)),
            Some(matrix_styled(&buffers.depth_rows(), &style)),
            // The raster shows the lesson's framebuffer only in a quiz (else the final one).
            quiz.then(|| raster_rows(height, buffers.frame_rows())),
        ),
        None => (None, None, None),
    };
    // Where the scanline crosses the outline, for drawing, once the crossings may be shown.
    let crossings_x = match (&view.crossings, lesson.record()) {
        (Some(_), Some(record)) => record.crossings.iter().map(to_f64).collect(),
        _ => Vec::new(),
    };
    LessonView {
        // The row's centre line: halfway down its printed row.
        at: Some(At {
            polygon: view.stop.polygon + 1,
            row: view.row,
            line: crate::raster::printed_row(height, view.row) as f64 + 0.5,
        }),
        heading: view.heading,
        slope: view.slope,
        scanline: view.scanline,
        crossings: view.crossings,
        crossings_x,
        spans: view.spans,
        span_depths: view.span_depths,
        columns: view.columns,
        rows: view.rows,
        hidden: view.hidden,
        hidden_said: (view.hidden > 0).then(|| words!(lang, "pixels-hidden-asked", count = view.hidden)),
        notes: view.notes,
        frame,
        depth,
        cells,
        ..shown
    }
}

/// What became of a page's command to the lesson.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Acted {
    /// Always true: the command was one (a command that is not one is the other shape).
    pub ok: bool,
    /// What became of it: `moved`, `refused`, `right`, `tryAgain`,
    /// `revealed`, `askAgain`, `skipped`, `nothingAsked` or `quit`.
    pub kind: &'static str,
    /// What the lesson said, in words.
    pub said: String,
    /// After `quit`: the quiz's score and each mistake, as the line mode ends with them.
    pub summary: Option<String>,
    /// The lesson's state after it.
    pub state: LessonView,
}

/// A key the page takes, as the lesson's one table names it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct KeyAction {
    /// The key.
    pub key: char,
    /// What it does, in the page's language.
    pub does: String,
}

/// The lesson's keys ([`KEYS`]), each with what it does.
pub fn keys(lang: Lang) -> Vec<KeyAction> {
    KEYS.iter().map(|(key, word)| KeyAction { key: *key, does: crate::words::text(lang, word, &[]) }).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small scene whose every part shows: a right triangle on a 4×3 raster.
    const SMALL: &str = r#"{"width": 4, "height": 3, "polygons": [{"name": "t", "value": 1, "vertices": [[0, 0, 1], [4, 0, 1], [0, 3, 1]]}]}"#;

    fn scene() -> Scene {
        crate::scene::Scene::from_json(SMALL, std::path::Path::new("small.json")).unwrap()
    }

    fn snapshot(name: &str, value: &impl Serialize) {
        crate::shape_snapshot(name, value);
    }

    /// The scene's view as the page gets it: the page flips nothing, so the
    /// vertex (0, 3) is at the raster's top (page y 0) and the first row is
    /// pixel row 2.
    #[test]
    fn the_scene_view_is_in_the_pages_coordinates() {
        let view = scene_view(Lang::En, &scene());
        assert_eq!(view.polygons[0].points, [[0.0, 3.0], [4.0, 3.0], [0.0, 0.0]]);
        assert_eq!(view.rows.iter().map(|r| r.y).collect::<Vec<_>>(), [2, 1, 0]);
        assert_eq!((view.polygons[0].number, view.checkable[0].number), (1, 1));
        assert!(view.draggable);
        snapshot("playground_scene_view", &view);
    }

    /// The lesson's view while a depth question is open, and at the end.
    #[test]
    fn the_lesson_view_asks_and_ends() {
        let mut lesson = Lesson::new(scene(), crate::effects::arith::Arith::Exact, Some(QuizMode::Depth));
        lesson.start(None);
        let asking = lesson_view(Lang::En, &mut lesson);
        let at = asking.at.clone().unwrap();
        assert_eq!((at.polygon, at.row, at.line), (1, 0, 2.5), "row 0's centre line is 2.5 down from the top");
        assert!(asking.rows.is_empty() && asking.asking == Some("depth"));
        snapshot("playground_lesson_view_asking", &asking);
        lesson.act(Lang::En, crate::teach::step::lesson::Command::Skip);
        while lesson.at().is_some() {
            lesson.act(Lang::En, crate::teach::step::lesson::Command::Skip);
            lesson.act(Lang::En, crate::teach::step::lesson::Command::Next);
        }
        snapshot("playground_lesson_view_end", &lesson_view(Lang::En, &mut lesson));
    }

    /// What the page gets instead of a view: the reason, and where the scene's text is wrong.
    #[test]
    fn a_failure_says_why_and_where() {
        let failed = crate::teach::playground::view(Lang::En, "{\n  \"width\": 4,\n  \"polygons\": [\n}");
        assert_eq!((failed["ok"].as_bool(), failed["at"]["line"].as_u64()), (Some(false), Some(4)), "{failed}");
        snapshot("playground_failed", &failed);
    }

    /// The page's other answers, each its type's shape: the buffers after a
    /// polygon, a homework answer checked (wrong everywhere it is not 1) and
    /// handed in as a file, a pixel's history, and the figure (its SVG cut
    /// to its first element here).
    #[test]
    fn the_pages_other_answers_are_typed() {
        use crate::observe::explain::Buffer;
        use crate::teach::playground as page;
        let after = page::after(Lang::En, SMALL, 1);
        let scene = scene();
        let mut drawn = Simulation::new(&scene);
        drawn.finish(&mut Unobserved);
        let (frame, depth) = printed_buffers(drawn.buffers());
        assert_eq!((after["frame"].as_str(), after["depth"].as_str()), (Some(frame.as_str()), Some(depth.as_str())));
        snapshot("playground_after", &after);
        let typed = "1 1 1 1\n1 1 1 1\n1 1 1 1\n";
        let checked = page::check(Lang::En, SMALL, 1, Buffer::Frame, typed);
        assert_eq!((checked["right"].as_bool(), checked["wrong"].as_array().map(Vec::len)), (Some(false), Some(6)));
        snapshot("playground_check", &checked);
        let file = page::answer_file(Lang::En, SMALL, Buffer::Frame, typed, "ada", "k3x");
        assert_eq!(file["name"].as_str(), Some("ada.frame.txt"));
        snapshot("playground_answer_file", &file);
        snapshot("playground_history", &page::explain(Lang::En, SMALL, 0, 0));
        let mut figure = page::figure(Lang::En, SMALL);
        let svg = figure["svg"].as_str().unwrap_or_default();
        assert!(svg.starts_with("<svg"), "{svg}");
        figure["svg"] = svg[..svg.find('>').map_or(0, |end| end + 1)].into();
        snapshot("playground_figure", &figure);
    }

    /// The page's keys are the lesson's, every one.
    #[test]
    fn the_keys_are_the_lessons() {
        let keys = keys(Lang::En);
        assert_eq!(keys.iter().map(|k| k.key).collect::<String>(), "nbpPsq");
        snapshot("playground_keys", &keys);
    }
}
