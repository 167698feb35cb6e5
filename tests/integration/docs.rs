//! The README and the guide show what zsim prints: every ```console block of
//! `README.md` and `docs/src/*.md` is run by trycmd and its output compared
//! (`...` stands for lines left out, `[..]` for part of a line such as a
//! time). Each document runs in a scratch folder of its own holding a copy of
//! `examples/` and `tests/fixtures/`, so the commands that write files write them there; the
//! course's published files are reached as `../shared/peer/…`, as from the
//! repository. The front door stays short: at most 250 lines.

use std::path::{Path, PathBuf};

use crate::{missing, ran};

/// The README's and the chapters' examples that need nothing outside the project.
#[test]
fn the_readme_and_the_guide_show_what_zsim_prints() {
    let commands = run_documents("documents", false);
    assert!(commands >= 25, "the documents' console examples were found: {commands}");
}

/// The chapters' examples that run the courses' published files
/// (`../shared/peer/…`), draw PNG and PDF figures (the figures feature) or
/// race Mesa's llvmpipe (`zsim speed`).
#[test]
#[ignore = "needs the courses' files in ../shared/peer, the figures feature and Mesa's llvmpipe"]
fn the_chapters_on_courses_and_figures_show_what_zsim_prints() {
    let commands = run_documents("documents-outside", true);
    assert!(commands >= 20, "the chapters' console examples were found: {commands}");
}

/// Whether a document's examples need something from outside the project:
/// the courses' files, a PNG or PDF figure, or the machine's OpenGL.
fn needs_outside(examples: &[String]) -> bool {
    examples
        .iter()
        .any(|c| c.contains("../shared/") || c.contains(".png") || c.contains(".pdf") || c.starts_with("zsim speed"))
}

/// Runs the console examples of the README and the chapters, those that
/// need something outside the project (`outside`, [`needs_outside`]) or the
/// others, each document in a scratch folder of its own under `name`;
/// returns how many commands ran.
fn run_documents(name: &str, outside: bool) -> usize {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    assert!(readme.lines().count() <= 250, "README.md has {} lines: the guide lives in docs/", readme.lines().count());
    let scratch = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
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
        if examples.is_empty() || needs_outside(&examples) != outside {
            continue;
        }
        commands += examples.len();
        let stem = document.file_stem().unwrap().to_str().unwrap();
        std::fs::write(scratch.join(format!("{stem}.md")), &text).unwrap();
        copy_folder(&root.join("examples"), &scratch.join(format!("{stem}.in/examples")));
        copy_folder(&root.join("tests/fixtures"), &scratch.join(format!("{stem}.in/tests/fixtures")));
    }
    if outside {
        if !shared.is_dir() {
            missing("../shared (the courses' published files)", "the course chapters' examples");
        }
        std::os::unix::fs::symlink(std::fs::canonicalize(&shared).unwrap(), scratch.join("shared")).unwrap();
    }
    trycmd::TestCases::new()
        .register_bin("zsim", Path::new(env!("CARGO_BIN_EXE_zsim")))
        .env("LC_ALL", "C")
        .env("NO_COLOR", "1")
        .case(scratch.join("*.md"))
        .run();
    ran("the README's and the guide's examples", &format!("trycmd, {commands} commands"));
    commands
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

/// Found building the guide: four links pointed out of the book
/// (`../../README.md`, `SUMMARY.md`, the design notes), which mdbook turns
/// into pages it never writes. Every link of a chapter leads to another
/// chapter (or a file beside them) and, with `#…`, to a heading there; every
/// relative link of the README leads to a file of the repository. The built
/// book's links are checked again in CI (`.ci/book`).
#[test]
fn the_guides_and_the_readmes_links_lead_somewhere() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let src = root.join("docs/src");
    let mut documents: Vec<PathBuf> = std::fs::read_dir(&src).unwrap().map(|e| e.unwrap().path()).collect();
    documents.retain(|p| p.extension().is_some_and(|e| e == "md"));
    documents.push(root.join("README.md"));
    let mut broken = Vec::new();
    let mut links = 0;
    for document in &documents {
        let text = std::fs::read_to_string(document).unwrap();
        for target in markdown_links(&text) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            links += 1;
            let (file, anchor) = target.split_once('#').unwrap_or((&target, ""));
            let folder = document.parent().unwrap();
            let path = if file.is_empty() { document.clone() } else { folder.join(file) };
            let inside_the_book = document.starts_with(&src);
            let found = std::fs::canonicalize(&path).ok();
            let fine = match &found {
                None => false,
                Some(found) if inside_the_book => found.starts_with(std::fs::canonicalize(&src).unwrap()),
                Some(_) => true,
            };
            let heading = anchor.is_empty()
                || found.as_ref().is_some_and(|f| {
                    headings(&std::fs::read_to_string(f).unwrap_or_default()).contains(&anchor.to_string())
                });
            if !fine || !heading {
                broken.push(format!("{}: {target}", document.strip_prefix(root).unwrap().display()));
            }
        }
    }
    assert!(links >= 10, "the documents' links were found: {links}");
    assert!(broken.is_empty(), "links that lead nowhere in the built guide: {broken:#?}");
}

/// The targets of a document's `[text](target)` links, outside code.
fn markdown_links(text: &str) -> Vec<String> {
    let mut targets = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        // Inline code is no link: drop what is between backticks.
        let prose: String = line.split('`').step_by(2).collect::<Vec<_>>().join(" ");
        let mut rest = prose.as_str();
        while let Some(at) = rest.find("](") {
            let after = &rest[at + 2..];
            let Some(end) = after.find(')') else { break };
            targets.push(after[..end].to_string());
            rest = &after[end..];
        }
    }
    targets
}

/// The anchors mdbook gives a document's headings: lower case, spaces as
/// `-`, only letters, digits, `-` and `_` kept.
fn headings(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|line| line.strip_prefix('#'))
        .map(|heading| {
            let heading = heading.trim_start_matches('#').trim().to_lowercase();
            heading
                .chars()
                .filter_map(|c| match c {
                    ' ' => Some('-'),
                    c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
                    _ => None,
                })
                .collect()
        })
        .collect()
}
