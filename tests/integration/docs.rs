//! The README's short examples run as written: every `zsim …` line of its
//! `sh` blocks that needs only the repository's files (the others name a
//! student's answer or a class folder, which a reader brings), in a scratch
//! folder with the examples beside it, exits 0 and prints something. The
//! front door stays short: at most 250 lines.

use std::path::Path;

use crate::zsim_in;

#[test]
fn the_readme_is_short_and_its_examples_run() {
    let readme = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    assert!(readme.lines().count() <= 250, "README.md has {} lines: the guide lives in docs/", readme.lines().count());
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("readme");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut fence = None;
    let mut ran = 0;
    for line in readme.lines() {
        if let Some(kind) = line.strip_prefix("```") {
            fence = if fence.is_some() { None } else { Some(kind.to_string()) };
            continue;
        }
        if fence.as_deref() != Some("sh") || !line.starts_with("zsim ") {
            continue;
        }
        let command = line.split(" #").next().unwrap().trim();
        if ["answer.txt", "class/", ">", "cargo"].iter().any(|needs| command.contains(needs)) {
            continue;
        }
        for part in command.split(" && ") {
            let words: Vec<String> = part
                .split_whitespace()
                .skip(1)
                .map(|w| w.replacen("examples/", &format!("{}/", examples.display()), 1))
                .collect();
            let args: Vec<&str> = words.iter().map(String::as_str).collect();
            let run = zsim_in(Some(&dir), &args);
            assert_eq!((run.code, run.stderr.as_str()), (0, ""), "{part}");
            assert!(!run.stdout.is_empty(), "{part} prints something");
            ran += 1;
        }
    }
    assert!(ran >= 7, "the README's examples were found: {ran}");
}
