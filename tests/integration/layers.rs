//! The source tree's layers point one way: each top-level part of `src/`
//! imports only the parts before it in [`LAYERS`] (the crate docs draw the
//! same list), no file under `src/` passes 800 lines, and the library never
//! prints. Read from the source as text, as a maintainer would check it.

use std::path::{Path, PathBuf};

/// The layers, lowest first (`words` and `error` are used from above).
const LAYERS: [&str; 12] = [
    "words", "numbers", "rules", "geometry", "error", "raster", "scene", "simulate", "effects", "observe", "teach",
    "courses",
];

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// A file's code without its test module and comments.
fn code(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    let text = text.split("#[cfg(test)]\nmod tests").next().unwrap();
    text.lines().map(|line| line.split("//").next().unwrap()).collect::<Vec<_>>().join("\n")
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

#[test]
fn every_layer_imports_only_the_layers_before_it() {
    let src = src();
    let mut files = Vec::new();
    sources(&src, &mut files);
    let mut upward = Vec::new();
    for file in &files {
        let relative = file.strip_prefix(&src).unwrap();
        let part =
            relative.components().next().unwrap().as_os_str().to_string_lossy().trim_end_matches(".rs").to_string();
        let Some(me) = LAYERS.iter().position(|l| *l == part) else {
            assert!(
                ["cli", "lib", "main"].contains(&part.as_str()),
                "{}: a top-level part outside the layers",
                relative.display()
            );
            continue;
        };
        let code = code(file);
        for layer in LAYERS.iter().skip(me + 1) {
            if code.contains(&format!("crate::{layer}::")) || code.contains(&format!("crate::{layer};")) {
                upward.push(format!("{} imports {layer}", relative.display()));
            }
        }
    }
    assert!(upward.is_empty(), "imports that run back up: {upward:#?}");
    let parts = std::fs::read_dir(&src).unwrap().count();
    assert_eq!(parts, LAYERS.len() + 3, "src/ holds the layers, lib.rs, main.rs and cli/");
}

#[test]
fn no_source_file_passes_800_lines() {
    let mut files = Vec::new();
    sources(&src(), &mut files);
    let long: Vec<String> = files
        .iter()
        .map(|f| (f, std::fs::read_to_string(f).unwrap().lines().count()))
        .filter(|(_, lines)| *lines > 800)
        .map(|(f, lines)| format!("{}: {lines} lines", f.display()))
        .collect();
    assert!(long.is_empty(), "{long:?}");
}

#[test]
fn the_library_never_prints() {
    let src = src();
    let mut files = Vec::new();
    sources(&src, &mut files);
    for file in files.iter().filter(|f| !f.starts_with(src.join("cli")) && !f.ends_with("main.rs")) {
        let code = code(file);
        for call in ["println!", "print!(", "eprintln!", "eprint!(", "dbg!"] {
            assert!(!code.contains(call), "{} calls {call}", file.display());
        }
    }
}
