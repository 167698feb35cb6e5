//! Embeds the browser playground in `zsim step --html` when the build is
//! given it: `ZSIM_PLAYGROUND` names the folder `web/build` writes
//! (`target/web`). Without it, `step --html` writes the recorded stepper page.
//! Also gathers the commands of the README's and the guide's ```console
//! examples (which `cargo test` runs) for the man pages' EXAMPLES.

fn main() {
    examples();
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
