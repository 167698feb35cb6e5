//! The student's language: the book's example explained and checked in
//! English, Russian, Ukrainian and Chinese, chosen by `--lang` or the locale.

use crate::{snapshot, zsim, zsim_with};

const ANSWER: &str = "tests/fixtures/rogers/depth_after_triangle.txt";

/// `explain --pixel 20,15` tells the pixel's story in each language with the
/// same exact numbers; the decimal beside them follows the language.
#[test]
fn explain_tells_the_books_pixel_in_each_language() {
    for lang in ["en", "ru", "uk", "zh"] {
        let out = zsim(&["explain", "examples/rogers.json", "--pixel", "20,15", "--lang", lang]);
        assert_eq!(out.code, 0, "{lang}: {}", out.stderr);
        assert!(out.stdout.contains("43/4"), "{lang}: the exact depth is there");
        snapshot!(format!("explain_rogers_20_15_{lang}"), out.stdout);
    }
    // English is the default and unchanged: the same text as without --lang.
    assert_eq!(
        zsim(&["explain", "examples/rogers.json", "--pixel", "20,15"]).stdout,
        zsim(&["explain", "examples/rogers.json", "--pixel", "20,15", "--lang", "en"]).stdout
    );
}

/// The depth test is named in the reader's language wherever the scene is
/// described (`run`'s header, `explain`'s heading); the scene file's keyword
/// stays English only in English.
#[test]
fn the_depth_test_is_named_in_each_language() {
    for (lang, named) in [
        ("en", "depth test greater ("),
        ("ru", "тест глубины больше ("),
        ("uk", "тест глибини більше ("),
        ("zh", "深度测试 大于（"),
    ] {
        let run = zsim(&["run", "examples/rogers.json", "--final", "--lang", lang]);
        let header = run.stdout.lines().next().unwrap_or_default();
        assert!(header.contains(named), "{lang}: {header}");
        let explain = zsim(&["explain", "examples/rogers.json", "--pixel", "20,15", "--lang", lang]);
        let heading = explain.stdout.lines().next().unwrap_or_default();
        assert!(heading.contains(&named.replace(" (", "").replace('（', "")), "{lang}: {heading}");
        if lang != "en" {
            assert!(!header.contains("greater") && !heading.contains("greater"), "{lang}: {header}\n{heading}");
        }
    }
}

/// `check` of the z-buffer as the book prints it (three cells differ: the
/// printed errata) in each language.
#[test]
fn check_explains_the_books_misprints_in_each_language() {
    for lang in ["en", "ru", "uk", "zh"] {
        let out = zsim(&["check", "examples/rogers.json", "--depth", ANSWER, "--lang", lang]);
        assert_eq!(out.code, 1, "{lang}: {}", out.stderr);
        snapshot!(format!("check_rogers_depth_{lang}"), out.stdout);
    }
}

/// Without `--lang` the locale decides, as gettext reads it: `LC_ALL`, then
/// `LC_MESSAGES`, then `LANG`; an unknown language is English.
#[test]
fn the_locale_chooses_the_language() {
    let check =
        |env: &[(&str, &str)]| zsim_with(None, &["check", "examples/rogers.json", "--depth", ANSWER], env).stdout;
    let russian = check(&[("LANG", "ru_RU.UTF-8")]);
    assert!(
        russian.starts_with("z-буфер tests/fixtures/rogers/depth_after_triangle.txt: отличаются 3 ячейки из 1024"),
        "{russian}"
    );
    assert!(check(&[("LANG", "ru_RU.UTF-8"), ("LC_ALL", "zh_CN.UTF-8")]).starts_with("z缓冲器"));
    assert!(check(&[("LANG", "de_DE.UTF-8")]).starts_with("z-buffer"));
    // --lang wins over the locale.
    let forced = zsim_with(
        None,
        &["check", "examples/rogers.json", "--depth", ANSWER, "--lang", "uk"],
        &[("LANG", "ru_RU.UTF-8")],
    );
    assert!(forced.stdout.contains("відрізняються 3 клітинки"), "{}", forced.stdout);
    let bad = zsim(&["check", "examples/rogers.json", "--depth", ANSWER, "--lang", "fr"]);
    assert_eq!(bad.code, 2);
    assert!(bad.stderr.contains("\"fr\" is not a language zsim speaks: use en, ru, uk or zh"), "{}", bad.stderr);
}

/// One scanline of `step` (line mode) in each language: the book's
/// triangle on the scanline through pixel (20, 15).
#[test]
fn step_shows_one_scanline_in_each_language() {
    for lang in ["en", "ru", "uk", "zh"] {
        let out = crate::zsim_stdin(
            &["step", "examples/rogers.json", "--polygon", "2", "--scanline", "15", "--lang", lang],
            "q\n",
        );
        assert_eq!(out.code, 0, "{lang}: {}", out.stderr);
        snapshot!(format!("step_rogers_triangle_15_{lang}"), out.stdout);
    }
}

/// Bad input is refused in the student's language, the file and the place
/// as they are; JSON output is the same in every language.
#[test]
fn errors_speak_the_language_and_json_does_not_change() {
    let (dir, file) = crate::scene_file(
        "bent_ru.json",
        r#"{"polygons": [{"name": "bent", "value": 1, "vertices": [[0,0,0],[4,0,0],[4,4,0],[0,4,1]]}], "frame_bits": 40}"#,
    );
    let out = crate::zsim_in(Some(&dir), &["run", &file, "--lang", "ru"]);
    assert_eq!((out.code, out.stdout.as_str()), (2, ""));
    assert_eq!(out.stderr, "zsim: bent_ru.json: frame_bits: 40 не поддерживается: допустимо от 1 до 32 бит\n");
    let (dir, file) = crate::scene_file(
        "bent_uk.json",
        r#"{"polygons": [{"name": "bent", "value": 1, "vertices": [[0,0,0],[4,0,0],[4,4,0],[0,4,1]]}]}"#,
    );
    let out = crate::zsim_in(Some(&dir), &["run", &file, "--lang", "uk"]);
    assert_eq!(
        out.stderr,
        "zsim: bent_uk.json: багатокутник 1 «bent»: не плоский: вершина 4 відстоїть від площини z = 0, проведеної через вершини 1, 2, 3, на Δz = 1\n"
    );
    let json = |lang: &str| zsim(&["run", "examples/rogers.json", "--format", "json", "--lang", lang]).stdout;
    let english = json("en");
    assert!(english.starts_with("{\"width\":32"));
    for lang in ["ru", "uk", "zh"] {
        assert_eq!(json(lang), english, "{lang}");
    }
}

/// A figure's title and the line saying where it went speak the language
/// too; an unnamed polygon is named by its number, in the language's case.
#[test]
fn figures_are_titled_in_each_language() {
    let (dir, file) = crate::scene_file(
        "unnamed.json",
        r#"{"width": 8, "height": 8, "polygons": [{"value": 1, "vertices": [[1,1,3],[6,1,3],[3,6,3]]}]}"#,
    );
    let expected = [
        ("en", "wrote unnamed_title.svg (unnamed.json: framebuffer after polygon 1)\n"),
        ("ru", "записан unnamed_title.svg (unnamed.json: буфер кадра после многоугольника 1)\n"),
        ("uk", "записано unnamed_title.svg (unnamed.json: буфер кадру після багатокутника 1)\n"),
        ("zh", "已写入 unnamed_title.svg（unnamed.json：多边形 1之后的帧缓冲器）\n"),
    ];
    for (lang, line) in expected {
        let out = crate::zsim_in(Some(&dir), &["figure", &file, "-o", "unnamed_title.svg", "--lang", lang]);
        assert_eq!((out.code, out.stdout.as_str()), (0, line), "{lang}: {}", out.stderr);
        let svg = std::fs::read_to_string(dir.join("unnamed_title.svg")).expect("written");
        let title = line.split_once(['(', '（']).unwrap().1.trim_end_matches(['\n', ')', '）']);
        assert!(svg.contains(&format!("<title>{title}</title>")), "{lang}: {svg}");
    }
    // A worksheet's vertex labels: with a decimal comma, coordinates are parted by semicolons.
    let (dir, file) = crate::scene_file(
        "halves.json",
        r#"{"width": 8, "height": 8, "polygons": [{"value": 1, "vertices": [[1.5,1,3],[6,1,3],[3,6,0.25]]}]}"#,
    );
    for (lang, label) in [("en", ">(1.5, 1, 3)<"), ("ru", ">(1,5; 1; 3)<"), ("zh", ">(1.5, 1, 3)<")] {
        let out = crate::zsim_in(Some(&dir), &["figure", &file, "--after", "0", "-o", "halves.svg", "--lang", lang]);
        assert_eq!(out.code, 0, "{lang}: {}", out.stderr);
        let svg = std::fs::read_to_string(dir.join("halves.svg")).expect("written");
        assert!(
            svg.contains(label) && svg.contains(if lang == "ru" { "(3; 6; 0,25)" } else { "(3, 6, 0.25)" }),
            "{lang}: {svg}"
        );
    }
}

/// The variables a catalogue message uses (`{ $name }`), by key.
fn catalogue_variables(language: &str) -> std::collections::BTreeMap<String, std::collections::BTreeSet<String>> {
    let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("src/words/{language}"));
    // Every area's resource, one after the other.
    let text: String = std::fs::read_dir(folder)
        .unwrap()
        .map(|entry| std::fs::read_to_string(entry.unwrap().path()).unwrap() + "\n")
        .collect();
    let mut messages = std::collections::BTreeMap::new();
    let mut current: Option<String> = None;
    for line in text.lines() {
        let is_key = line.split_once(" = ").or_else(|| line.strip_suffix(" =").map(|k| (k, "")));
        match is_key {
            Some((key, _)) if !key.starts_with([' ', '#', '}', '[', '*']) && !key.is_empty() => {
                current = Some(key.to_string());
            }
            _ if line.starts_with([' ', '}']) => {}
            _ => current = None,
        }
        if let Some(key) = &current {
            let entry: &mut std::collections::BTreeSet<String> = messages.entry(key.clone()).or_default();
            for part in line.split("$").skip(1) {
                let name: String = part.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
                entry.insert(name);
            }
        }
    }
    messages
}

/// Every `words!(lang, "key", name = …)` in the source passes each variable its
/// message uses in every language, so no reader meets a `{$name}` unfilled
/// (a debug build stops there; a release build prints it).
#[test]
fn every_message_gets_every_variable_it_uses_in_every_language() {
    let languages: Vec<_> = ["en", "ru", "uk", "zh"].map(|l| (l, catalogue_variables(l))).into();
    let mut files = Vec::new();
    let mut folders = vec![std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src")];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    let mut problems = Vec::new();
    let mut calls = 0;
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        for (start, _) in text.match_indices("words!(") {
            // The call's text after its language, up to its closing parenthesis.
            let after = text[start + "words!(".len()..].trim_start();
            let Some(after) = after.strip_prefix("lang").map(str::trim_start).and_then(|a| a.strip_prefix(',')) else {
                continue;
            };
            let body = after.trim_start();
            if !body.starts_with('"') {
                continue;
            }
            let mut depth = 1;
            let end = body
                .char_indices()
                .find(|(_, c)| {
                    depth += match c {
                        '(' => 1,
                        ')' => -1,
                        _ => 0,
                    };
                    depth == 0
                })
                .map_or(body.len(), |(i, _)| i);
            let call = &body[..end];
            let key = call[1..].split('"').next().unwrap();
            if key == "key" {
                continue; // the macro's own documentation
            }
            calls += 1;
            let given: Vec<&str> = call
                .split([',', '(', '\n'])
                .filter_map(|part| part.split_once('=').map(|(name, _)| name.trim()))
                .filter(|name| !name.is_empty() && name.chars().all(|c| c.is_ascii_lowercase() || c == '_'))
                .collect();
            for (language, messages) in &languages {
                match messages.get(key) {
                    None => problems.push(format!("{}: {key}: no message in {language}", file.display())),
                    Some(used) => {
                        for name in used.iter().filter(|name| !given.contains(&name.as_str())) {
                            problems.push(format!("{}: {key}: {language} uses ${name}, not given", file.display()));
                        }
                    }
                }
            }
        }
    }
    assert!(calls > 300, "{calls} calls found");
    assert!(problems.is_empty(), "{problems:#?}");
}

/// With `LANG=ru_RU.UTF-8`, what `explain`, `step` and `check` print and
/// every error they give is Russian: no English word is left once the
/// tokens quoted from the input (the scene's polygon names, file names,
/// option names, a value in quotes or backticks) are set aside.
#[test]
fn a_russian_locale_leaves_no_english_word_in_explain_step_check_or_their_errors() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("russian-words");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = |name: &str, text: &str| {
        std::fs::write(dir.join(name), text).unwrap();
        dir.join(name).display().to_string()
    };
    let unknown_key =
        scene("unknown.json", r#"{"polygons": [{"value": 1, "vertices": [[0,0,0],[1,0,0],[0,1,0]], "colour": 2}]}"#);
    let wrong_type = scene("type.json", r#"{"polygons": 3}"#);
    let cut_short = scene("cut.json", r#"{"polygons": ["#);
    let runs: Vec<Vec<&str>> = vec![
        vec!["explain", "examples/rogers.json", "--pixel", "20,15"],
        vec!["explain", "examples/rogers.json", "--pixel", "99,9"],
        vec!["explain", "examples/rogers.json", "--pixel", "abc"],
        vec!["explain", "examples/rogers.json", "--pixel", "1,1", "--arith", "f16"],
        vec!["explain", "missing.json", "--pixel", "1,1"],
        vec!["explain", &unknown_key, "--pixel", "1,1"],
        vec!["explain", &wrong_type, "--pixel", "1,1"],
        vec!["explain", &cut_short, "--pixel", "1,1"],
        vec!["step", "examples/rogers.json", "--polygon", "2", "--scanline", "15"],
        vec!["step", "examples/rogers.json", "--polygon", "2", "--scanline", "99"],
        vec!["step", "examples/rogers.json", "--polygon", "7", "--scanline", "1"],
        vec!["step", "examples/rogers.json", "--polygon", "2"],
        vec!["step", "examples/rogers.json", "--polygon", "2", "--scanline", "15", "--wrong"],
        vec!["check", "examples/rogers.json", "--depth", "examples/class/bo.depth.txt"],
        vec!["check", "examples/rogers.json", "--frame", "examples/class/di.frame.txt"],
        vec!["check", "examples/rogers.json", "--frame", "missing.txt"],
        vec!["check", "examples/rogers.json", "--depth", "tests/fixtures/rogers/frame_after_triangle.txt"],
    ];
    let mut english = Vec::new();
    for args in &runs {
        let run = crate::zsim_with(None, args, &[("LANG", "ru_RU.UTF-8")]);
        assert!(run.code <= 2, "{args:?}");
        for line in run.stdout.lines().chain(run.stderr.lines()) {
            let words = latin_words(line);
            if !words.is_empty() {
                english.push(format!("{args:?}: {words:?} in {line}"));
            }
        }
    }
    assert!(english.is_empty(), "English left in Russian output:\n{}", english.join("\n"));
}

/// The words of three or more Latin letters in a line, once quoted tokens
/// (in «», "", ``), paths, options and the program's name are set aside.
fn latin_words(line: &str) -> Vec<String> {
    let mut kept = String::new();
    let mut quote: Option<char> = None;
    for c in line.chars() {
        match (quote, c) {
            (None, '«') => quote = Some('»'),
            (None, '"') => quote = Some('"'),
            (None, '`') => quote = Some('`'),
            (Some(end), c) if c == end => quote = None,
            (Some(_), _) => {}
            (None, c) => kept.push(c),
        }
    }
    // The program, the scene's polygon names, a format's name and the keys of
    // the scene file a message locates a problem at (`polygons`, `colour`).
    let allowed = ["zsim", "help", "rectangle", "triangle", "JSON", "polygons", "colour"];
    kept.split_whitespace()
        .filter(|w| {
            !w.starts_with("--")
                && !w.starts_with('<')
                && !w.contains('/')
                && !w.contains(".json")
                && !w.contains(".txt")
        })
        .flat_map(|w| w.split(|c: char| !c.is_ascii_alphabetic()).map(str::to_string).collect::<Vec<_>>())
        .filter(|w| w.len() >= 3 && !allowed.contains(&w.as_str()))
        .collect()
}
