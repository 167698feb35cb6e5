//! Embeds the browser playground in `zsim step --html` when the build is
//! given it: `ZSIM_PLAYGROUND` names the folder `web/build` writes
//! (`target/web`). Without it, `step --html` writes the recorded stepper page.
//! Also gathers the commands of the README's and the guide's ```console
//! examples (which `cargo test` runs) for the man pages' EXAMPLES. Writes
//! the catalogues as this build keeps them (`OUT_DIR/words/`).

fn main() {
    examples();
    catalogues();
    println!("cargo::rustc-check-cfg=cfg(playground)");
    println!("cargo::rerun-if-env-changed=ZSIM_PLAYGROUND");
    let Some(folder) = std::env::var_os("ZSIM_PLAYGROUND") else { return };
    let folder = std::path::PathBuf::from(folder);
    let out = std::path::PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    for name in ["index.html", "playground.js", "playground.css", "zsim_web.js", "zsim_module.js"] {
        let from = folder.join(name);
        println!("cargo::rerun-if-changed={}", from.display());
        if let Err(error) = std::fs::copy(&from, out.join(name)) {
            panic!("ZSIM_PLAYGROUND={}: cannot read {name} ({error}): run web/build first", folder.display());
        }
    }
    println!("cargo::rustc-cfg=playground");
}

/// Writes `OUT_DIR/examples.txt`: every `$ zsim …` line of a ```console
/// block in README.md and docs/src/*.md, once each, in the documents' order,
/// that reads only files the package installs (those of `examples/`): the
/// man pages' examples, which must run as printed on the installed package.
fn examples() {
    let out = std::path::PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let mut documents = vec![std::path::PathBuf::from("README.md")];
    println!("cargo::rerun-if-changed=README.md");
    println!("cargo::rerun-if-changed=docs/src");
    if let Ok(entries) = std::fs::read_dir("docs/src") {
        let mut chapters: Vec<_> = entries.filter_map(|e| Some(e.ok()?.path())).collect();
        chapters.sort();
        documents.extend(chapters.into_iter().filter(|p| p.extension().is_some_and(|e| e == "md")));
    }
    let mut commands: Vec<String> = Vec::new();
    for document in documents {
        let text = std::fs::read_to_string(&document).unwrap_or_default();
        let mut inside = false;
        for line in text.lines() {
            if let Some(info) = line.strip_prefix("```") {
                inside = !inside && info.trim() == "console";
            } else if let Some(command) = line.strip_prefix("$ zsim ").filter(|_| inside)
                && !commands.iter().any(|c| c == command)
                && reads_installed_files(command)
            {
                commands.push(command.to_string());
            }
        }
    }
    std::fs::write(out.join("examples.txt"), commands.join("\n")).expect("OUT_DIR is writable");
}

/// Whether every file a command reads is one the package installs (under
/// `examples/`); what it writes (`-o`, `--dir`, …) may be anywhere.
fn reads_installed_files(command: &str) -> bool {
    let tokens: Vec<&str> = command.split(' ').collect();
    tokens.iter().enumerate().all(|(k, token)| {
        let written = k > 0 && ["-o", "--output", "--dir", "--gradescope", "--prairielearn"].contains(&tokens[k - 1]);
        let file = token.contains('/') || [".json", ".txt", ".obj", ".csv", ".tga"].iter().any(|e| token.ends_with(e));
        written || !file || token.starts_with("examples/")
    })
}

/// Writes `OUT_DIR/words/LANG/AREA.ftl`: each of `src/words`' catalogues
/// without the messages that only a part this build leaves out names (the
/// command line's `src/cli` and `src/app` without the `cli` feature, the
/// GPU's without `gpu`, the courses' without `courses`): a message is left
/// out when its key stands as a string literal in the sources and every file
/// it stands in is such a part's. A key that no source names literally is
/// kept. The browser's module, built without them, is that much smaller.
fn catalogues() {
    let out = std::path::PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    println!("cargo::rerun-if-changed=src");
    let enabled = |feature: &str| std::env::var_os(format!("CARGO_FEATURE_{}", feature.to_uppercase())).is_some();
    let parts: [(&str, &[&str]); 3] =
        [("cli", &["src/cli/", "src/app/"]), ("gpu", &["src/observe/gpu/"]), ("courses", &["src/courses/"])];
    let absent: Vec<&str> = parts
        .iter()
        .filter(|(feature, _)| !enabled(feature))
        .flat_map(|(_, folders)| folders.iter().copied())
        .collect();
    // Every string literal that could be a key, and whether it stands anywhere but in an absent part.
    let mut sources = Vec::new();
    rust_files(std::path::Path::new("src"), &mut sources);
    let mut named: std::collections::HashMap<String, bool> = std::collections::HashMap::new();
    for file in &sources {
        let shown = file.to_string_lossy().replace('\\', "/");
        let kept = !absent.iter().any(|folder| shown.starts_with(folder));
        let text = std::fs::read_to_string(file).unwrap_or_default();
        for literal in string_literals(&text) {
            if !literal.is_empty() && literal.bytes().all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'-')
            {
                *named.entry(literal).or_insert(false) |= kept;
            }
        }
    }
    let left_out = |key: &str| named.get(key).is_some_and(|kept| !kept);
    for lang in ["en", "ru", "uk", "zh"] {
        let folder = out.join("words").join(lang);
        std::fs::create_dir_all(&folder).expect("OUT_DIR is writable");
        for area in ["scene", "draw", "step", "check", "courses", "usage", "class"] {
            let text = std::fs::read_to_string(format!("src/words/{lang}/{area}.ftl")).expect("a catalogue");
            // A message is its line `key = …` and the lines after it up to the next entry (a
            // message, a term or a comment: a line that starts with a letter, `-` or `#`).
            let mut kept = String::new();
            let mut leaving = false;
            for line in text.lines() {
                if line.starts_with(|c: char| c.is_ascii_alphabetic() || c == '-' || c == '#') {
                    let key = line.split_once(" =").map(|(key, _)| key.trim());
                    leaving = key.is_some_and(left_out);
                }
                if !leaving {
                    kept.push_str(line);
                    kept.push('\n');
                }
            }
            std::fs::write(folder.join(format!("{area}.ftl")), kept).expect("OUT_DIR is writable");
        }
    }
}

/// The `.rs` files under `folder`, in no particular order.
fn rust_files(folder: &std::path::Path, files: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(folder).into_iter().flatten().flatten() {
        let path = entry.path();
        if path.is_dir() {
            rust_files(&path, files);
        } else if path.extension().is_some_and(|e| e == "rs") {
            files.push(path);
        }
    }
}

/// The string literals of Rust source `text` (plain and raw, their contents
/// as written), past comments and character literals.
fn string_literals(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut found = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        match chars[i] {
            '/' if chars.get(i + 1) == Some(&'/') => {
                while i < chars.len() && chars[i] != '\n' {
                    i += 1;
                }
            }
            '/' if chars.get(i + 1) == Some(&'*') => {
                i += 2;
                while i + 1 < chars.len() && !(chars[i] == '*' && chars[i + 1] == '/') {
                    i += 1;
                }
                i += 2;
            }
            // A character literal ('"', '\'', 'x'); a lifetime ('a) is passed over as code.
            '\'' if chars.get(i + 1) == Some(&'\\') => {
                i += 2;
                while i < chars.len() && chars[i] != '\'' {
                    i += 1;
                }
                i += 1;
            }
            '\'' if chars.get(i + 2) == Some(&'\'') => i += 3,
            'r' if matches!(chars.get(i + 1), Some('"' | '#'))
                && !chars[..i].last().is_some_and(|c| c.is_alphanumeric() || *c == '_') =>
            {
                let hashes = chars[i + 1..].iter().take_while(|c| **c == '#').count();
                if chars.get(i + 1 + hashes) != Some(&'"') {
                    i += 1;
                    continue;
                }
                let start = i + 2 + hashes;
                let mut end = start;
                while end < chars.len()
                    && !(chars[end] == '"'
                        && chars[end + 1..].iter().take(hashes).filter(|c| **c == '#').count() == hashes)
                {
                    end += 1;
                }
                found.push(chars[start..end.min(chars.len())].iter().collect());
                i = end + 1 + hashes;
            }
            '"' => {
                let mut literal = String::new();
                i += 1;
                while i < chars.len() && chars[i] != '"' {
                    if chars[i] == '\\' {
                        i += 1;
                    }
                    if let Some(c) = chars.get(i) {
                        literal.push(*c);
                    }
                    i += 1;
                }
                found.push(literal);
                i += 1;
            }
            _ => i += 1,
        }
    }
    found
}
