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
