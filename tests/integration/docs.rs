//! The README and the guide show what zsim prints: every ```console block of
//! `README.md` and `docs/src/*.md` is run by trycmd and its output compared
//! (`...` stands for lines left out, `[..]` for part of a line such as a
//! time). Each document runs in a scratch folder of its own holding a copy of
//! `examples/` and `tests/fixtures/`, so the commands that write files write them there; the
//! course's published files are reached as `../shared/peer/…`, as from the
//! repository. The front door stays short: at most 250 lines.

use std::path::{Path, PathBuf};

use crate::{ran, skipped};

#[test]
fn the_readme_and_the_guide_show_what_zsim_prints() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    assert!(readme.lines().count() <= 250, "README.md has {} lines: the guide lives in docs/", readme.lines().count());
    let scratch = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("documents");
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).unwrap();
    let shared = root.join("../shared");
    let mut documents = vec![root.join("README.md")];
    let mut chapters: Vec<PathBuf> =
        std::fs::read_dir(root.join("docs/src")).unwrap().map(|e| e.unwrap().path()).collect();
    chapters.sort();
    documents.extend(chapters.into_iter().filter(|p| p.extension().is_some_and(|e| e == "md")));
    let mut commands = 0;
    for document in &documents {
        let text = std::fs::read_to_string(document).unwrap();
        let examples = console_commands(&text);
        if examples.is_empty() {
            continue;
        }
        if examples.iter().any(|c| c.contains("../shared/")) && !shared.is_dir() {
            skipped("../shared (the courses' published files)", &format!("{}'s examples", document.display()));
            continue;
        }
        commands += examples.len();
        let stem = document.file_stem().unwrap().to_str().unwrap();
        std::fs::write(scratch.join(format!("{stem}.md")), &text).unwrap();
        copy_folder(&root.join("examples"), &scratch.join(format!("{stem}.in/examples")));
        copy_folder(&root.join("tests/fixtures"), &scratch.join(format!("{stem}.in/tests/fixtures")));
    }
    if shared.is_dir() {
        std::os::unix::fs::symlink(std::fs::canonicalize(&shared).unwrap(), scratch.join("shared")).unwrap();
    }
    assert!(commands >= 40, "the documents' console examples were found: {commands}");
    trycmd::TestCases::new()
        .register_bin("zsim", Path::new(env!("CARGO_BIN_EXE_zsim")))
        .env("LC_ALL", "C")
        .env("NO_COLOR", "1")
        .case(scratch.join("*.md"))
        .run();
    ran("the README's and the guide's examples", &format!("trycmd, {commands} commands"));
}

/// The commands (`$ …` lines) of a document's ```console blocks.
fn console_commands(text: &str) -> Vec<String> {
    let mut inside = false;
    let mut commands = Vec::new();
    for line in text.lines() {
        if let Some(info) = line.strip_prefix("```") {
            inside = !inside && info.trim() == "console";
            continue;
        }
        if let Some(command) = line.strip_prefix("$ ").filter(|_| inside) {
            commands.push(command.to_string());
        }
    }
    commands
}

fn copy_folder(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        let target = to.join(path.file_name().unwrap());
        if path.is_dir() {
            copy_folder(&path, &target);
        } else {
            std::fs::copy(&path, &target).unwrap();
        }
    }
}
