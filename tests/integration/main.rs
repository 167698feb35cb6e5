//! zsim's integration tests: one binary, a module per area.
//!
//! - To add a scene: put it in `examples/` (or write it inline with
//!   [`scene_file`]), run it with [`zsim`] and snapshot what a person reads
//!   with [`snapshot!`].
//! - Snapshots live in the top-level `snapshots/` folder. After a deliberate
//!   change in output run `cargo insta review` (or `cargo insta test
//!   --review`), read each diff and accept it only if it is right.
//! - CLI tests run the real binary and check stdout, stderr and the exit code.

mod accuracy;
mod bad_input;
mod browser;
mod buet;
mod chromium;
mod classroom;
mod course;
mod cs418;
mod diagnosis;

mod docs;
mod door;
mod effects;
mod exact_range;
mod generate;
mod golden;
#[cfg(feature = "gpu")]
mod gpu;
mod handouts;
mod hard_cases;
mod hardening;
mod languages;
mod layers;
mod lesson;
mod limits;
mod platforms;
mod playground;
mod run_command;
mod stability;
mod teaching;
mod threads;
mod tinyrenderer;
mod untrusted;

use std::path::{Path, PathBuf};
use std::process::Command;

/// What a test needs from outside the project (a browser, tmux, TeX, a GPU,
/// the courses' files, a feature) is missing. Such a test is
/// `#[ignore = "needs …"]`, so that a plain `cargo test` lists it as ignored
/// instead of passing it unrun; asked for (`cargo test --features
/// figures,vulkan -- --include-ignored`, as `.ci/run` does after installing
/// everything), it fails here, saying what is missing.
pub fn missing(what: &str, check: &str) -> ! {
    panic!("{check} needs {what}, which is missing here: .ci/run installs it")
}

/// Says on the terminal (past the test harness's capture) that a check
/// needing an outside tool ran, and with what.
pub fn ran(check: &str, with: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "RAN: {check}, with {with}");
}

/// The folder `../shared/peer/NAME` of course files beside the project (never
/// copied into it); a test that reads it is `#[ignore = "needs the courses'
/// files in ../shared/peer"]`.
pub fn peer(name: &str, check: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/peer").join(name);
    if !dir.is_dir() {
        missing(&dir.display().to_string(), check);
    }
    dir
}

/// What one run of the binary produced.
pub struct Run {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

/// Runs the real `zsim` binary in `dir` (the project root when `None`).
pub fn zsim_in(dir: Option<&Path>, args: &[&str]) -> Run {
    zsim_with(dir, args, &[])
}

/// Runs the real `zsim` binary in `dir` with `LANG=C.UTF-8` (English) and
/// no other locale variables, then `env` on top.
pub fn zsim_with(dir: Option<&Path>, args: &[&str], env: &[(&str, &str)]) -> Run {
    zsim_full(dir, args, env, None)
}

/// Runs the real `zsim` binary in the project root with `input` on standard
/// input (a pipe, not a terminal).
pub fn zsim_stdin(args: &[&str], input: &str) -> Run {
    zsim_full(None, args, &[], Some(input))
}

fn zsim_full(dir: Option<&Path>, args: &[&str], env: &[(&str, &str)], input: Option<&str>) -> Run {
    use std::io::Write;
    use std::process::Stdio;
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut child = Command::new(env!("CARGO_BIN_EXE_zsim"))
        .args(args)
        .current_dir(dir.unwrap_or(root))
        .env("NO_COLOR", "1")
        // English unless a test asks for another language.
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .env("LANG", "C.UTF-8")
        .envs(env.iter().copied())
        .stdin(if input.is_some() { Stdio::piped() } else { Stdio::null() })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the zsim binary runs");
    if let Some(input) = input {
        child.stdin.take().expect("a pipe").write_all(input.as_bytes()).expect("input written");
    }
    let output = child.wait_with_output().expect("the zsim binary runs");
    Run {
        code: output.status.code().expect("zsim exits with a code, not a signal"),
        stdout: String::from_utf8(output.stdout).expect("stdout is UTF-8"),
        stderr: String::from_utf8(output.stderr).expect("stderr is UTF-8"),
    }
}

/// Runs the real `zsim` binary in the project root.
pub fn zsim(args: &[&str]) -> Run {
    zsim_in(None, args)
}

/// Writes a scene into the test scratch folder and returns that folder and
/// the file name, so error messages carry a short, stable path.
pub fn scene_file(name: &str, text: &str) -> (PathBuf, String) {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("scenes");
    std::fs::create_dir_all(&dir).expect("scratch folder");
    std::fs::write(dir.join(name), text).expect("scene written");
    (dir, name.to_string())
}

/// Parses a matrix as the book prints it: whitespace-separated integers, top row first.
pub fn parse_matrix(text: &str) -> Vec<Vec<u32>> {
    text.lines()
        .filter(|line| !line.trim().is_empty())
        .map(|line| line.split_whitespace().map(|v| v.parse().expect("a matrix cell")).collect())
        .collect()
}

/// Snapshots into the top-level `snapshots/` folder.
#[macro_export]
macro_rules! snapshot {
    ($name:expr, $value:expr) => {
        insta::with_settings!({
            snapshot_path => "../../snapshots",
            prepend_module_to_snapshot => false,
            omit_expression => true,
        }, {
            insta::assert_snapshot!($name, $value);
        })
    };
}

/// The rows of a markdown table as comfy-table prints it, with a wrapped
/// cell's continuation lines (first cell empty) joined to its row by a space.
pub fn table_rows(text: &str) -> Vec<Vec<String>> {
    let mut rows: Vec<Vec<String>> = Vec::new();
    for line in text.lines().filter(|l| l.starts_with('|') && !l.starts_with("|-")) {
        let cells: Vec<String> = line.trim_matches('|').split('|').map(|c| c.trim().to_string()).collect();
        match rows.last_mut() {
            Some(row) if cells[0].is_empty() => {
                for (cell, more) in row.iter_mut().zip(cells) {
                    if !more.is_empty() {
                        cell.push(' ');
                        cell.push_str(&more);
                    }
                }
            }
            _ => rows.push(cells),
        }
    }
    rows
}

/// The book's final framebuffer or z-buffer (`key`: `frame` or `depth`) as
/// `zsim run --format json --final` gives it, written as an answer file with
/// `separator` between the values.
pub fn book_answer(key: &str, separator: &str) -> String {
    let run = zsim(&["run", "examples/rogers.json", "--format", "json", "--final"]);
    let json: serde_json::Value = serde_json::from_str(&run.stdout).expect("run's JSON");
    json["steps"][0][key]
        .as_array()
        .expect("a matrix")
        .iter()
        .map(|row| {
            row.as_array().expect("a row").iter().map(|v| v.to_string()).collect::<Vec<_>>().join(separator) + "\n"
        })
        .collect()
}
