//! The source tree's layers point one way: each top-level part of `src/`
//! imports only the parts before it in [`LAYERS`] (the guide's Development
//! chapter draws the same list), no file under `src/` passes 800 lines, and the library never
//! prints. Read from the source as text, as a maintainer would check it.

use std::path::{Path, PathBuf};

/// The layers, lowest first (`words` and `error` are used from above).
const LAYERS: [&str; 13] = [
    "words", "numbers", "rules", "geometry", "error", "door", "raster", "scene", "simulate", "effects", "observe",
    "teach", "courses",
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
                ["app", "cli", "lib", "main"].contains(&part.as_str()),
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
    assert_eq!(parts, LAYERS.len() + 4, "src/ holds the layers, lib.rs, main.rs, cli/ and app/");
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
    let binary =
        |f: &PathBuf| f.starts_with(src.join("cli")) || f.starts_with(src.join("app")) || f.ends_with("main.rs");
    for file in files.iter().filter(|f| !binary(f)) {
        let code = code(file);
        for call in ["println!", "print!(", "eprintln!", "eprint!(", "dbg!"] {
            assert!(!code.contains(call), "{} calls {call}", file.display());
        }
    }
}

/// A file's module path: `src/simulate/levels.rs` is `simulate::levels`,
/// `src/scene/file/mod.rs` is `scene::file`, `src/lib.rs` the root.
fn module_of(src: &Path, file: &Path) -> Vec<String> {
    let relative = file.strip_prefix(src).unwrap().with_extension("");
    let mut parts: Vec<String> = relative.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib" | "main")) {
        parts.pop();
    }
    parts
}

/// No two files of `src/` import each other, directly or round a longer
/// circle (found by a new maintainer: `cli/step.rs` ↔ `cli/tui.rs`,
/// `cli/check.rs` ↔ `cli/gradescope.rs`, `cli/grade.rs` ↔ `cli/gradebooks.rs`,
/// `simulate/levels.rs` ↔ `simulate/triangle.rs`). A folder's `mod.rs` is the
/// folder's own face: its files may use it and it them.
#[test]
fn no_import_circle_between_files() {
    let src = src();
    let mut files = Vec::new();
    sources(&src, &mut files);
    let modules: Vec<Vec<String>> = files.iter().map(|f| module_of(&src, f)).collect();
    let find = |path: &[String]| (1..=path.len()).rev().find_map(|n| modules.iter().position(|m| m[..] == path[..n]));
    let mut edges: Vec<Vec<usize>> = vec![Vec::new(); files.len()];
    for (me, file) in files.iter().enumerate() {
        let is_mod = file.file_name().is_some_and(|n| n == "mod.rs");
        let module = &modules[me];
        let parent: Vec<String> =
            if is_mod { module.clone() } else { module[..module.len().saturating_sub(1)].to_vec() };
        let code = code(file);
        let mut targets = Vec::new();
        for (prefix, base) in [("crate::", Vec::new()), ("super::", parent[..parent.len().saturating_sub(1)].to_vec())]
        {
            for (at, _) in code.match_indices(prefix) {
                let rest = &code[at + prefix.len()..];
                let names: Vec<&str> = if let Some(group) = rest.strip_prefix('{') {
                    group.split('}').next().unwrap().split(',').map(|n| n.trim().split("::").next().unwrap()).collect()
                } else {
                    vec![rest]
                };
                for name in names {
                    let path: Vec<String> = name
                        .split("::")
                        .map(|p| p.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>())
                        .take_while(|p| !p.is_empty())
                        .collect();
                    let mut full = base.clone();
                    full.extend(path);
                    targets.push(full);
                }
            }
        }
        for target in targets {
            let Some(to) = find(&target) else { continue };
            let own_face = !is_mod && modules[to] == parent;
            let own_file = is_mod && modules[to].starts_with(module) && modules[to].len() == module.len() + 1;
            if to != me && !own_face && !own_file && !edges[me].contains(&to) {
                edges[me].push(to);
            }
        }
    }
    let reaches = |from: usize, to: usize| {
        let (mut seen, mut stack) = (vec![false; files.len()], vec![from]);
        while let Some(at) = stack.pop() {
            if at == to {
                return true;
            }
            if !std::mem::replace(&mut seen[at], true) {
                stack.extend(&edges[at]);
            }
        }
        false
    };
    let circles: Vec<String> = (0..files.len())
        .flat_map(|a| edges[a].iter().map(move |&b| (a, b)))
        .filter(|&(a, b)| reaches(b, a))
        .map(|(a, b)| {
            format!(
                "{} → {}",
                files[a].strip_prefix(&src).unwrap().display(),
                files[b].strip_prefix(&src).unwrap().display()
            )
        })
        .collect();
    assert!(circles.is_empty(), "imports that come back round: {circles:#?}");
    assert!(edges.iter().map(Vec::len).sum::<usize>() > 150, "the imports were found");
}

/// The language is passed where words are made, never held behind the
/// caller's back (found by a new maintainer: a thread-local copied by hand
/// into every rayon task, and left changed by a panic).
#[test]
fn no_thread_local_in_the_source() {
    let mut files = Vec::new();
    sources(&src(), &mut files);
    for file in &files {
        assert!(!std::fs::read_to_string(file).unwrap().contains("thread_local!"), "{}", file.display());
    }
}

/// Every file goes through one door in and one door out: outside `src/door/`
/// no code (tests aside) opens, reads or writes a file by itself, so the
/// rules for inputs and outputs cannot be skipped by a new command. Listing a
/// folder (`read_dir`) is allowed; what is found is read through the door.
#[test]
fn every_file_goes_through_the_door() {
    let src = src();
    let mut files = Vec::new();
    sources(&src, &mut files);
    let opens = [
        "fs::read(",
        "fs::read_to_string(",
        "fs::write(",
        "File::open(",
        "File::create(",
        "OpenOptions::new(",
        "fs::copy(",
        "fs::rename(",
        "fs::create_dir",
        "fs::set_permissions(",
    ];
    let mut found = Vec::new();
    for file in &files {
        let relative = file.strip_prefix(&src).unwrap();
        if relative.starts_with("door") {
            continue;
        }
        let code = code(file);
        for open in opens {
            if code.contains(open) {
                found.push(format!("{} uses {open}", relative.display()));
            }
        }
    }
    assert!(found.is_empty(), "files opened outside src/door/: {found:#?}");
}

/// The library builds without the command line: with no default features its
/// normal dependencies hold none of the command line's and terminal's crates
/// (the browser front end needs exactly that).
#[test]
fn the_library_needs_none_of_the_command_lines_crates() {
    let output = std::process::Command::new(env!("CARGO"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["tree", "--offline", "--no-default-features", "-e", "normal", "--prefix", "none", "--format", "{p}"])
        .output()
        .expect("cargo runs");
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let tree = String::from_utf8(output.stdout).unwrap();
    assert!(tree.lines().any(|l| l.starts_with("zsim ")), "{tree}");
    let names: Vec<&str> = tree.lines().filter_map(|l| l.split(' ').next()).collect();
    for crate_name in ["clap", "ratatui", "crossterm", "comfy-table", "indicatif", "clap_complete", "clap_mangen"] {
        assert!(!names.contains(&crate_name), "{crate_name} is in the library's tree:\n{tree}");
    }
}

/// The command line only parses, calls the library and lays its facts out
/// (found by a new maintainer: 5,413 lines of it doing the library's work).
#[test]
fn the_command_line_stays_small() {
    let mut files = Vec::new();
    sources(&src().join("cli"), &mut files);
    let lines: usize = files.iter().map(|f| std::fs::read_to_string(f).unwrap().lines().count()).sum();
    // A class's commands render three reports more (the fairness table, a class's grades by kind
    // of case, each student's feedback); what they compute is the library's (teach/course/).
    assert!(lines <= 3400, "src/cli/ has {lines} lines: what it computes belongs in the library");
}

/// A comment says why; a figure's date, the commit it was measured at or
/// the machine it ran on goes stale the day after, and lives in a dated
/// design note under `docs/design/` (found by a new maintainer: five ratios,
/// two commits and a date in one doc comment).
#[test]
fn no_comment_names_a_date_a_commit_or_a_machine() {
    let mut files = Vec::new();
    sources(&src(), &mut files);
    let mut found = Vec::new();
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        for (n, line) in text.lines().enumerate() {
            let Some((_, comment)) = line.split_once("//") else { continue };
            let date = comment.as_bytes().windows(10).any(|w| {
                w.iter().enumerate().all(|(i, b)| if i == 4 || i == 7 { *b == b'-' } else { b.is_ascii_digit() })
                    && w.starts_with(b"20")
            });
            let commit = comment.split_whitespace().collect::<Vec<_>>().windows(2).any(|w| {
                w[0] == "commit"
                    && w[1].len() >= 7
                    && w[1].trim_end_matches([',', ')', '.']).chars().all(|c| c.is_ascii_hexdigit())
            });
            let machine = ["EPYC", "this machine", "Xeon", "Ryzen"].iter().any(|m| comment.contains(m));
            if date || commit || machine {
                found.push(format!("{}:{}: {}", file.display(), n + 1, line.trim()));
            }
        }
    }
    assert!(found.is_empty(), "{found:#?}");
}

/// The errors of the low floor (`src/error.rs`) are facts of the scene, the
/// files and the answers, shown by every front end alike: neither the file
/// nor a message it words names a command-line flag (the command line's own
/// refusals live with it, as `zsim::Refusal`s of their own).
#[test]
fn the_low_floors_errors_name_no_command_line_flag() {
    let text = std::fs::read_to_string(src().join("error.rs")).unwrap();
    let flag = |s: &str| s.match_indices("--").any(|(at, _)| s[at + 2..].starts_with(|c: char| c.is_ascii_lowercase()));
    let named: Vec<&str> = text.lines().filter(|line| flag(line)).collect();
    assert!(named.is_empty(), "{named:?}");
    let english: String = std::fs::read_dir(src().join("words/en"))
        .unwrap()
        .map(|entry| std::fs::read_to_string(entry.unwrap().path()).unwrap())
        .collect();
    let keys: Vec<&str> = text.split('"').skip(1).step_by(2).filter(|k| k.contains('-') && !k.contains(' ')).collect();
    assert!(keys.len() > 15, "{keys:?}");
    // What every layer shares, no more: each layer's refusals live beside its code (the door's
    // outputs, a scene's polygons, a figure's, a check's, grading's), none named after a command.
    for gone in ["enum Usage", "enum Task", "Usage(", "Task::"] {
        assert!(!text.contains(gone), "error.rs keeps {gone}");
    }
    for key in keys {
        let message = english.lines().find(|line| line.starts_with(&format!("{key} = ")));
        if let Some(message) = message {
            assert!(!flag(message), "{message}");
        }
    }
}

/// The layers are drawn in one place, the guide's Development chapter: its
/// tree of `src/` names the layers in the order the imports follow, then the
/// command line and the full-screen app.
#[test]
fn the_guide_draws_the_layers_as_the_code_has_them() {
    let guide = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/src/development.md")).unwrap();
    let tree = &guide[guide.find("```text\nsrc/\n").expect("the tree of src/")..];
    let tree = &tree[..tree.find("\n```").unwrap()];
    let drawn: Vec<&str> = tree
        .lines()
        .filter_map(|line| line.strip_prefix("├── ").or_else(|| line.strip_prefix("└── ")))
        .map(|entry| entry.split_whitespace().next().unwrap().trim_end_matches('/').trim_end_matches(".rs"))
        .collect();
    let expected: Vec<&str> = LAYERS.iter().copied().chain(["cli", "app"]).collect();
    assert_eq!(drawn, expected);
}

/// One name per thing: no two types of the crate (structs, enums, traits,
/// type aliases, however public) share a name, so that an import or a
/// document naming one cannot mean the other (found by a maintainer:
/// `zsim::Refusal` and `step::Refusal`, `zsim::Buffers` and `page::Buffers`,
/// two `TooLarge`s, two `Case`s, two `Settings`, …). One type declared twice
/// in a file under two `cfg`s is one type.
#[test]
fn no_two_types_share_a_name() {
    let mut files = Vec::new();
    sources(&src(), &mut files);
    let mut declared: std::collections::BTreeMap<String, Vec<String>> = std::collections::BTreeMap::new();
    for file in &files {
        let relative = file.strip_prefix(src()).unwrap().display().to_string();
        for line in code(file).lines() {
            let words: Vec<&str> = line.split_whitespace().collect();
            let Some(at) = words.iter().position(|w| ["struct", "enum", "trait", "type"].contains(w)) else { continue };
            if !words[..at].iter().all(|w| w.starts_with("pub")) || at == 0 {
                continue;
            }
            let Some(name) = words.get(at + 1) else { continue };
            let name: String = name.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            if name.starts_with(|c: char| c.is_ascii_uppercase()) {
                let places = declared.entry(name).or_default();
                if !places.contains(&relative) {
                    places.push(relative.clone());
                }
            }
        }
    }
    let shared: Vec<String> = declared
        .iter()
        .filter(|(_, places)| places.len() > 1)
        .map(|(name, places)| format!("{name}: {}", places.join(", ")))
        .collect();
    assert!(declared.len() > 100, "{} types found", declared.len());
    assert!(shared.is_empty(), "types that share a name: {shared:#?}");
}
