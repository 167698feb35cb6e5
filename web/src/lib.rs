//! The playground's WebAssembly module: zsim's library, and one function per
//! thing the page asks of it, each a thin wrapper over
//! [`zsim::playground`] that answers with JSON text. No rule lives here or
//! in the page's script.

use wasm_bindgen::prelude::*;
use zsim::Lang;
use zsim::lesson::Lesson;
use zsim::playground;

/// The language of a code (`ru`, `uk-UA`, `zh-CN`); English for others.
fn lang(code: &str) -> Lang {
    Lang::parse(code).unwrap_or_default()
}

/// The first of the browser's languages (`navigator.languages`, one per line) that zsim speaks; `en` if none.
#[wasm_bindgen]
pub fn choose_language(preferred: &str) -> String {
    preferred.lines().find_map(Lang::parse).unwrap_or_default().code().to_string()
}

/// The book's worked example, the scene a page opens with.
#[wasm_bindgen]
pub fn book_scene() -> String {
    include_str!("../../examples/rogers.json").to_string()
}

/// The examples the page's menu offers, as JSON: `[{"word", "scene"}]`, `word`
/// the page word that names it.
#[wasm_bindgen]
pub fn examples() -> String {
    let examples = [
        ("exampleRogers", include_str!("../../examples/rogers.json")),
        ("exampleSection", include_str!("../../examples/section.json")),
        ("exampleLess", include_str!("../../examples/less.json")),
        ("exampleCull", include_str!("../../examples/cull.json")),
        ("exampleConcave", include_str!("../../examples/concave.json")),
    ];
    let list: Vec<serde_json::Value> =
        examples.iter().map(|(word, scene)| serde_json::json!({"word": word, "scene": scene})).collect();
    serde_json::Value::Array(list).to_string()
}

/// See [`playground::answer_file`]; `buffer` is `frame` or `depth`.
#[wasm_bindgen]
pub fn answer_file(code: &str, scene: &str, buffer: &str, typed: &str, student: &str, variant: &str) -> String {
    let buffer = if buffer == "depth" { zsim::explain::Buffer::Depth } else { zsim::explain::Buffer::Frame };
    playground::answer_file(lang(code), scene, buffer, typed, student, variant).to_string()
}

/// The stepper and its quiz as one object the page keeps: the scene parsed
/// once, where the student is, what is asked and the score, all the
/// library's [`Lesson`]; the page sends it keys and answers and renders
/// what it answers.
#[wasm_bindgen]
pub struct WebLesson {
    lesson: Lesson,
    lang: Lang,
}

#[wasm_bindgen]
impl WebLesson {
    /// The lesson of `scene` at scanline `row` of polygon `polygon` (from 1;
    /// 0, or a place that is no stop: the first stop); `quiz` is `depth`,
    /// `frame`, `coverage` or anything else for none. `Err` with the scene's
    /// error (JSON text, `{"ok": false, "error"}`).
    #[wasm_bindgen(constructor)]
    pub fn new(code: &str, scene: &str, quiz: &str, polygon: usize, row: u32) -> Result<WebLesson, String> {
        let mode = playground::quiz_mode(quiz);
        let lang = lang(code);
        let place = (polygon > 0).then_some((polygon, row));
        let lesson = playground::lesson(lang, scene, mode, place).map_err(|error| error.to_string())?;
        Ok(WebLesson { lesson, lang })
    }

    /// Speaks `code` from now on.
    pub fn set_language(&mut self, code: &str) {
        self.lang = lang(code);
    }

    /// See [`playground::lesson_state`].
    pub fn state(&mut self) -> String {
        json(&playground::lesson_view(self.lang, &mut self.lesson))
    }

    /// See [`playground::lesson_act`]: `command` is `{"key": "n"}`, `{"go": [polygon, row]}` or `{"answer": "15"}`.
    pub fn act(&mut self, command: &str) -> String {
        match playground::lesson_acted(self.lang, &mut self.lesson, command) {
            Ok(acted) => json(&acted),
            Err(error) => error.to_string(),
        }
    }

    /// See [`playground::view`]: of the scene the lesson read.
    pub fn view(&self) -> String {
        json(&playground::scene_view(self.lang, self.lesson.scene()))
    }

    /// See [`playground::after`]: of the scene the lesson read, after polygon `number` (from 1).
    pub fn after(&self, number: usize) -> String {
        playground::after_of(self.lang, self.lesson.scene(), number).to_string()
    }

    /// See [`playground::lesson_explain`]: of the scene the lesson read, the
    /// pixel as the address or a click gives it (text, never wrapped to 32
    /// bits), hidden while a question is open.
    pub fn explain(&mut self, x: &str, y: &str) -> String {
        playground::lesson_explain(self.lang, &mut self.lesson, x, y).to_string()
    }

    /// See [`playground::figure`]: of the scene the lesson read.
    pub fn figure(&self) -> String {
        playground::figure_of(self.lang, self.lesson.scene()).to_string()
    }
}

/// See [`playground::variant_line`].
#[wasm_bindgen]
pub fn variant_line(code: &str, student: &str, variant: &str) -> String {
    playground::variant_line(lang(code), student, variant)
}

/// See [`playground::check`]: after polygon `number` (from 1); `buffer` is `frame` or `depth`.
#[wasm_bindgen]
pub fn check(code: &str, scene: &str, number: usize, buffer: &str, typed: &str) -> String {
    let buffer = if buffer == "frame" { zsim::explain::Buffer::Frame } else { zsim::explain::Buffer::Depth };
    playground::check(lang(code), scene, number, buffer, typed).to_string()
}

/// See [`playground::edit`]: `{"ok": true, "scene"}` or `{"ok": false, "error"}`.
#[wasm_bindgen]
pub fn edit(code: &str, scene: &str, change: &str) -> String {
    match playground::edit(lang(code), scene, change) {
        Ok(scene) => serde_json_text(true, "scene", &scene),
        Err(error) => serde_json_text(false, "error", &error),
    }
}

/// See [`playground::fragment_of`].
#[wasm_bindgen]
pub fn fragment_of(scene: &str) -> String {
    playground::fragment_of(scene)
}

/// See [`playground::scene_of_fragment`]: `{"ok": true, "scene"}` or `{"ok": false, "error"}`.
#[wasm_bindgen]
pub fn scene_of_fragment(code: &str, fragment: &str) -> String {
    match playground::scene_of_fragment(lang(code), fragment) {
        Ok(scene) => serde_json_text(true, "scene", &scene),
        Err(error) => serde_json_text(false, "error", &error),
    }
}

/// See [`playground::page_words`].
#[wasm_bindgen]
pub fn words(code: &str) -> String {
    playground::page_words(lang(code)).to_string()
}

/// `{"ok": ok, key: text}` as JSON text.
fn serde_json_text(ok: bool, key: &str, text: &str) -> String {
    let mut object = serde_json::Map::new();
    object.insert("ok".into(), ok.into());
    object.insert(key.into(), text.into());
    serde_json::Value::Object(object).to_string()
}

/// A typed view as the JSON text the page reads.
fn json(value: &impl serde::Serialize) -> String {
    serde_json::to_string(value).unwrap_or_default()
}
