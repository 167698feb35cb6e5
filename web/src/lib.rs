//! The playground's WebAssembly module: zsim's library, and one function per
//! thing the page asks of it, each a thin wrapper over
//! [`zsim::playground`] that answers with JSON text. No rule lives here or
//! in the page's script.

use wasm_bindgen::prelude::*;
use zsim::Lang;
use zsim::playground::{self, Question};

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

/// See [`playground::view`].
#[wasm_bindgen]
pub fn view(code: &str, scene: &str, at: usize) -> String {
    playground::view(lang(code), scene, at).to_string()
}

/// See [`playground::stop`].
#[wasm_bindgen]
pub fn stop(code: &str, scene: &str, stop: usize) -> String {
    playground::stop(lang(code), scene, stop).to_string()
}

/// See [`playground::figure`].
#[wasm_bindgen]
pub fn figure(code: &str, scene: &str) -> String {
    playground::figure(lang(code), scene).to_string()
}

/// See [`playground::judge`]: `question` is `coverage`, `depth` or `frame`.
#[wasm_bindgen]
pub fn judge(code: &str, scene: &str, stop: usize, question: &str, pixel: usize, typed: &str) -> String {
    let question = match question {
        "coverage" => Question::Coverage,
        "frame" => Question::Frame(pixel),
        _ => Question::Depth(pixel),
    };
    playground::judge(lang(code), scene, stop, question, typed).to_string()
}

/// See [`playground::check`]: `buffer` is `frame` or `depth`.
#[wasm_bindgen]
pub fn check(code: &str, scene: &str, after: usize, buffer: &str, typed: &str) -> String {
    let buffer = if buffer == "frame" { zsim::explain::Buffer::Frame } else { zsim::explain::Buffer::Depth };
    playground::check(lang(code), scene, after, buffer, typed).to_string()
}

/// See [`playground::explain`].
#[wasm_bindgen]
pub fn explain(code: &str, scene: &str, x: u32, y: u32) -> String {
    playground::explain(lang(code), scene, x, y).to_string()
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
