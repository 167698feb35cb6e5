//! For the teacher: `zsim exercise` makes an exercise with its answer key,
//! `zsim grade` grades a folder of answers. Both through the real binary.

use std::path::{Path, PathBuf};

use zsim::Q;
use zsim::Scene;
use zsim::Simulation;
use zsim::{Outcome, Recorder};

use crate::zsim;

/// A fresh scratch folder.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Replaces the value at (x, y) (y up, 32 rows) in an answer's text.
fn with_cell(answer: &str, x: usize, y: usize, value: u32) -> String {
    let mut rows: Vec<Vec<String>> =
        answer.lines().map(|l| l.split_whitespace().map(str::to_string).collect()).collect();
    let height = rows.len();
    rows[height - 1 - y][x] = value.to_string();
    rows.iter().map(|r| r.join(" ") + "\n").collect()
}

/// A class: ana right, bo and cy wrong at the book's subtle cells, di's
/// framebuffer malformed, ed without a z-buffer answer.
fn class_folder(name: &str) -> PathBuf {
    let dir = scratch(name);
    let (frame, depth) = (crate::book_answer("frame", " "), crate::book_answer("depth", " "));
    let write = |name: &str, text: &str| std::fs::write(dir.join(name), text).unwrap();
    write("ana.frame.txt", &frame);
    write("ana.depth.txt", &depth);
    // (20, 15) holds 11 and (20, 17) holds 10: the rounding the book turns on.
    let mistaken = with_cell(&with_cell(&depth, 20, 15, 10), 20, 17, 11);
    write("bo.frame.txt", &frame);
    write("bo.depth.txt", &mistaken);
    write("cy.frame.txt", &with_cell(&frame, 0, 0, 2));
    write("cy.depth.txt", &mistaken);
    write("di.frame.txt", "0 1 x\n");
    write("di.depth.txt", &depth);
    write("ed.frame.txt", &frame);
    write("notes.md", "passed over: not an answer");
    dir
}

#[test]
fn grade_gives_a_row_per_student_sorted_with_the_status_of_each() {
    let class = class_folder("class-rows");
    let run = zsim(&["grade", "examples/rogers.json", path(&class), "--format", "csv"]);
    // The gradebook stays importable: the folder's other file is named on standard error.
    let not_graded = "zsim: not graded: notes.md is not an answer file (NAME.frame.txt or NAME.depth.txt)\n";
    assert_eq!((run.code, run.stderr.as_str()), (1, not_graded), "some answers are wrong: exit 1");
    // The book's scene changes 337 cells of each buffer, 674 in all: bo has 672 of them right,
    // cy 672 less one cell written where the background stays, di and ed one buffer's 337.
    assert_eq!(
        run.stdout,
        "student,frame_wrong,depth_wrong,score,status,misconception\n\
         ana,0,0,100.0,ok,\n\
         bo,0,2,99.7,wrong,\n\
         cy,1,2,99.6,wrong,\n\
         di,,0,50.0,\"malformed: di.frame.txt: line 1, value 3 (x = 2, y = 31): \"\"x\"\" is not a whole number (a 2-bit framebuffer holds 0 … 3) \
         · line 1: 3 values; the raster is 32 wide · 1 row; the raster has 32\",\n\
         ed,0,,50.0,missing: ed.depth.txt,\n"
    );
}

#[test]
fn grade_lists_the_common_mistakes_with_zsims_reason() {
    let class = class_folder("class-mistakes");
    let run = zsim(&["grade", "examples/rogers.json", path(&class)]);
    assert_eq!(run.code, 1);
    assert!(
        run.stdout.starts_with("class ")
            && run.stdout.contains(": 5 students; 1 ok, 2 wrong, 1 malformed, 1 missing an answer\n"),
        "{}",
        run.stdout
    );
    let mistakes = run.stdout.split_once("common mistakes").expect("a common-mistakes section").1;
    // Both of bo's and cy's shared cells, with the reason; cy's own (0, 0) is not common.
    assert!(mistakes.contains("| z-buffer | 20 | 17 | 2 of 5 | 10    | 11 (2×)"), "{mistakes}");
    assert!(mistakes.contains("| z-buffer | 20 | 15 | 2 of 5 | 11    | 10 (2×)"), "{mistakes}");
    assert!(mistakes.contains("z = 41/4"), "{mistakes}");
    assert!(!mistakes.contains("| framebuffer | 0  | 0 "), "{mistakes}");
    let json = zsim(&["grade", "examples/rogers.json", path(&class), "--format", "json"]);
    let value: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    assert_eq!(value["students"].as_array().unwrap().len(), 5);
    assert_eq!(value["students"][1]["depth_wrong"], 2);
    assert_eq!(value["students"][3]["frame_wrong"], serde_json::Value::Null);
    assert_eq!(value["common_mistakes"][0]["students"], serde_json::json!(["bo", "cy"]));
}

#[test]
fn grade_writes_each_student_checks_explanation() {
    let class = class_folder("class-feedback");
    let feedback = scratch("feedback");
    let run = zsim(&["grade", "examples/rogers.json", path(&class), "--format", "csv", "-o", path(&feedback)]);
    assert_eq!(run.code, 1);
    let bo = std::fs::read_to_string(feedback.join("bo.feedback.txt")).unwrap();
    // Checked where the student's files are: the feedback names them and the scene by their own
    // names, never where the teacher keeps them.
    let rogers = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/rogers.json");
    let check =
        crate::zsim_in(Some(&class), &["check", path(&rogers), "--frame", "bo.frame.txt", "--depth", "bo.depth.txt"]);
    let (heading, rest) = bo.split_once('\n').unwrap();
    assert_eq!(heading, "bo: rogers.json after polygon 2 \"triangle\": score 99.7 %, wrong");
    assert_eq!(rest, check.stdout, "the feedback is what `zsim check` says");
    assert!(!bo.contains(path(&class)), "no teacher's path in the feedback: {bo}");
    let di = std::fs::read_to_string(feedback.join("di.feedback.txt")).unwrap();
    assert!(di.contains("di.frame.txt: line 1, value 3 (x = 2, y = 31): \"x\" is not a whole number"), "{di}");
    assert!(di.contains("di.depth.txt: all 1024 cells match"), "the answer that was read is still checked: {di}");
    assert!(std::fs::read_to_string(feedback.join("common-mistakes.txt")).unwrap().contains("2 of 5"));
}

/// The table and each student's feedback speak the student's language
/// (`--lang` or the locale); CSV and JSON are the same in every language.
#[test]
fn grade_speaks_the_language_but_csv_and_json_do_not_change() {
    let class = class_folder("class-ru");
    let feedback = scratch("feedback-ru");
    let run = zsim(&["grade", "examples/rogers.json", path(&class), "--lang", "ru", "-o", path(&feedback)]);
    assert_eq!(run.code, 1);
    assert!(
        run.stdout.contains(
            "после многоугольника 2 «triangle»: 5 студентов; верно: 1, с ошибками: 2, с негодными файлами: 1, без ответа: 1\n"
        ),
        "{}",
        run.stdout
    );
    assert!(
        run.stdout
            .contains("| ed      | 0                     | -                 | 50,0     | нет файла: ed.depth.txt"),
        "{}",
        run.stdout
    );
    assert!(run.stdout.contains("| z-буфер | 20 | 17 | 2 из 5   | 10    | 11 (2×)"), "{}", run.stdout);
    let bo = std::fs::read_to_string(feedback.join("bo.feedback.txt")).unwrap();
    assert!(bo.starts_with("bo: rogers.json, после многоугольника 2 «triangle»: 99,7 %, с ошибками\n"), "{bo}");
    for format in ["csv", "json"] {
        let english = zsim(&["grade", "examples/rogers.json", path(&class), "--format", format]).stdout;
        for lang in ["ru", "uk", "zh"] {
            let other = zsim(&["grade", "examples/rogers.json", path(&class), "--format", format, "--lang", lang]);
            assert_eq!(other.stdout, english, "{format} in {lang}");
        }
    }
}

#[test]
fn grade_exits_0_for_a_right_class_and_2_for_bad_usage() {
    let (frame, depth) = (crate::book_answer("frame", " "), crate::book_answer("depth", " "));
    let right = scratch("class-right");
    std::fs::write(right.join("ana.frame.txt"), &frame).unwrap();
    std::fs::write(right.join("ana.depth.txt"), &depth).unwrap();
    let run = zsim(&["grade", "examples/rogers.json", path(&right), "--format", "csv"]);
    assert_eq!(
        (run.code, run.stdout.as_str()),
        (0, "student,frame_wrong,depth_wrong,score,status,misconception\nana,0,0,100.0,ok,\n")
    );
    let run = zsim(&["grade", "examples/rogers.json", "no/such/folder"]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert!(run.stderr.starts_with("zsim: no/such/folder: cannot read"), "{}", run.stderr);
    let empty = scratch("class-empty");
    let run = zsim(&["grade", "examples/rogers.json", path(&empty)]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("no answers found: name each student's files NAME.frame.txt"), "{}", run.stderr);
    let run = zsim(&["grade", "no-such-scene.json", path(&right)]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
}

/// The cases of an exercise, found here from a recorded trace, apart from zsim's own finder.
fn cases_in_trace(scene: &Scene) -> Vec<&'static str> {
    let mut recorder = Recorder::default();
    Simulation::new(scene).finish(&mut recorder);
    let mut cases = Vec::new();
    let half = Q::new(1, 2);
    let on_scanline = recorder.scanlines.iter().any(|s| {
        let y = Q::from_integer(i128::from(s.row)) + half;
        scene.polygons[s.index].vertices().iter().any(|v| v[1] == y)
    });
    let centre_on_edge = recorder
        .scanlines
        .iter()
        .any(|s| s.pixels.iter().any(|p| s.crossings.iter().any(|c| *c == Q::from_integer(i128::from(p.x)) + half)));
    let pixels: Vec<_> = recorder.scanlines.iter().flat_map(|s| s.pixels.iter()).collect();
    let half_depth = pixels.iter().any(|p| {
        let z = p.compared.value().to_big();
        z.clone() - z.floor() == num_rational::BigRational::new(1.into(), 2.into())
    });
    let saturation = pixels.iter().any(|p| {
        p.outcome == Outcome::Written
            && (p.compared.rounded() < 0.into() || p.compared.rounded() > scene.depth_max().into())
    });
    let hidden = pixels.iter().any(|p| p.outcome == Outcome::Hidden);
    // Intersecting: a later polygon both overwrites and is hidden by the same earlier one.
    let mut owner = vec![None; (scene.width * scene.height) as usize];
    let (mut over, mut under) = (Vec::new(), Vec::new());
    for p in &pixels {
        let cell = (p.y * scene.width + p.x) as usize;
        match (p.outcome, owner[cell]) {
            (Outcome::Written, Some(o)) if o != p.index => over.push((o, p.index)),
            (Outcome::Hidden, Some(o)) if o != p.index => under.push((o, p.index)),
            _ => {}
        }
        if p.outcome == Outcome::Written {
            owner[cell] = Some(p.index);
        }
    }
    let intersecting = over.iter().any(|pair| under.contains(pair));
    let concave = recorder.scanlines.iter().any(|s| s.spans.len() >= 2);
    for (present, name) in [
        (on_scanline, "vertex-on-scanline"),
        (centre_on_edge, "centre-on-edge"),
        (half_depth, "half-depth"),
        (saturation, "saturation"),
        (hidden, "hidden"),
        (intersecting, "intersecting"),
        (concave, "concave"),
    ] {
        if present {
            cases.push(name);
        }
    }
    cases
}

#[test]
fn an_exercise_contains_every_hard_case_asked_for_and_its_key_checks() {
    let all = "vertex-on-scanline,centre-on-edge,half-depth,saturation,hidden,intersecting,concave";
    for (seed, hard, polygons) in
        [("1", all, "3"), ("2", "concave", "1"), ("3", "hidden,half-depth", "2"), ("4", "", "2")]
    {
        let dir = scratch(&format!("exercise-{seed}"));
        let mut args = vec!["exercise", "--seed", seed, "--polygons", polygons, "-o", path(&dir)];
        if !hard.is_empty() {
            args.extend(["--hard", hard]);
        }
        let run = zsim(&args);
        assert_eq!((run.code, run.stderr.as_str()), (0, ""), "seed {seed}");
        let scene = Scene::load(&dir.join("scene.json")).unwrap();
        let present = cases_in_trace(&scene);
        for case in hard.split(',').filter(|c| !c.is_empty()) {
            assert!(present.contains(&case), "seed {seed}: {case} is not in the trace; found {present:?}");
            assert!(run.stdout.contains(&format!("\n  {case}: ")), "seed {seed}: the exercise states {case}");
        }
        // The exercise states exactly the cases the trace shows.
        let stated: Vec<&str> =
            run.stdout.lines().filter_map(|l| l.strip_prefix("  ")?.split_once(':').map(|s| s.0)).collect();
        assert_eq!(stated, present, "seed {seed}");
        let check = zsim(&[
            "check",
            path(&dir.join("scene.json")),
            "--frame",
            path(&dir.join("answer.frame.txt")),
            "--depth",
            path(&dir.join("answer.depth.txt")),
        ]);
        assert_eq!(check.code, 0, "seed {seed}: {}", check.stdout);
        let worksheet = std::fs::read_to_string(dir.join("worksheet.svg")).unwrap();
        let document = roxmltree::Document::parse(&worksheet).expect("the worksheet is well-formed SVG");
        let labels = document
            .descendants()
            .filter(|n| n.parent().is_some_and(|p| p.attribute("id") == Some("vertices")) && n.has_tag_name("text"))
            .count();
        let vertices: usize = scene.polygons.iter().map(|p| p.vertices().len()).sum();
        assert_eq!(labels, vertices, "seed {seed}: every vertex labelled");
        assert!(
            !worksheet.contains(
                r#"<g id="pixels" stroke="none" shape-rendering="crispEdges">
<rect"#
            ),
            "seed {seed}: the worksheet's grid is empty"
        );
    }
}

#[test]
fn the_same_seed_gives_byte_identical_files() {
    let (one, two) = (scratch("exercise-same-1"), scratch("exercise-same-2"));
    // In any language: the scene file and the answers are the same (Russian
    // once wrote 4,5 in the JSON, a different scene); only the worksheet's
    // and the solution's words change.
    let russian = scratch("exercise-same-ru");
    for (dir, lang) in [(&one, "en"), (&two, "en"), (&russian, "ru")] {
        let run = zsim(&[
            "--lang",
            lang,
            "exercise",
            "--seed",
            "42",
            "--hard",
            "hidden,concave",
            "--polygons",
            "3",
            "--each-polygon",
            "-o",
            path(dir),
        ]);
        assert_eq!(run.code, 0, "{}", run.stderr);
    }
    let mut names: Vec<String> =
        std::fs::read_dir(&one).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    assert_eq!(
        names,
        [
            "answer.after-1.depth.txt",
            "answer.after-1.frame.txt",
            "answer.after-2.depth.txt",
            "answer.after-2.frame.txt",
            "answer.depth.txt",
            "answer.frame.txt",
            "exercise.txt",
            "scene.json",
            "solution.svg",
            "worksheet.svg"
        ]
    );
    for name in &names {
        let (a, b) = (std::fs::read(one.join(name)).unwrap(), std::fs::read(two.join(name)).unwrap());
        if name.ends_with(".txt") && name != "exercise.txt" || name == "scene.json" {
            assert_eq!(std::fs::read(russian.join(name)).unwrap(), a, "{name} in Russian");
        }
        // exercise.txt names its folder; everything else is the same byte for byte.
        if name == "exercise.txt" {
            let strip = |t: Vec<u8>| {
                String::from_utf8(t)
                    .unwrap()
                    .lines()
                    .filter(|l| !l.starts_with("check an answer"))
                    .collect::<Vec<_>>()
                    .join("\n")
            };
            assert_eq!(strip(a), strip(b));
        } else {
            assert_eq!(a, b, "{name}");
        }
    }
    let worksheet = std::fs::read_to_string(russian.join("worksheet.svg")).unwrap();
    assert!(worksheet.contains("Нарисуйте многоугольники по порядку (сначала A)"), "{worksheet}");
    // The answer after polygon 1 checks as the state after polygon 1.
    let run = zsim(&[
        "check",
        path(&one.join("scene.json")),
        "--after",
        "1",
        "--depth",
        path(&one.join("answer.after-1.depth.txt")),
    ]);
    assert_eq!(run.code, 0, "{}", run.stdout);
}

#[test]
fn exercise_refuses_what_it_cannot_make() {
    let dir = scratch("exercise-bad");
    let run = zsim(&["exercise", "--hard", "tricky", "-o", path(&dir)]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert!(run.stderr.starts_with("zsim: \"tricky\" is not a hard case: vertex-on-scanline"), "{}", run.stderr);
    let run = zsim(&["exercise", "--hard", "hidden", "--polygons", "1", "-o", path(&dir)]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("need two polygons or more"), "{}", run.stderr);
    let run = zsim(&["exercise", "--size", "100x100", "-o", path(&dir)]);
    assert_eq!(run.code, 2);
    assert_eq!(run.stderr, "zsim: an exercise is 4 … 64 pixels on a side, not 100×100\n");
}

/// Found by a teacher: some exercises had slivers covering 7 scattered
/// pixels or depths below zero, unlike a textbook exercise. With the default
/// style every polygon covers at least --min-pixels centres (counted here by
/// drawing each polygon alone with every fragment passing) and every vertex
/// depth lies within the z-buffer's range; --style free still allows both.
#[test]
fn a_book_style_exercise_has_no_sliver_and_no_depth_outside_the_range() {
    let coverage = |scene: &serde_json::Value, index: usize| -> usize {
        let mut alone = scene.clone();
        alone["polygons"] = serde_json::json!([scene["polygons"][index].clone()]);
        alone["depth_test"] = "always".into();
        let json = serde_json::to_string(&alone).unwrap();
        let scene = zsim::Scene::from_json(&json, Path::new("alone.json")).unwrap();
        let mut simulation = zsim::Simulation::new(&scene);
        simulation.finish(&mut zsim::Unobserved);
        simulation.buffers().frame_rows().iter().flatten().filter(|v| **v != 0).count()
    };
    let mut free_sliver_or_outside = false;
    for seed in 1..=12 {
        for (style, min) in [("book", "12"), ("book", "30"), ("free", "12")] {
            let dir = scratch(&format!("style-{style}-{min}-{seed}"));
            let seed_text = seed.to_string();
            let args = ["exercise", "--seed", &seed_text, "--polygons", "3", "--style", style, "--min-pixels", min];
            let run = zsim(&[&args[..], &["-o", path(&dir)]].concat());
            assert_eq!((run.code, run.stderr.as_str()), (0, ""), "seed {seed}");
            let text = std::fs::read_to_string(dir.join("scene.json")).unwrap();
            let scene: serde_json::Value = serde_json::from_str(&text).unwrap();
            let polygons = scene["polygons"].as_array().unwrap().len();
            let smallest = (0..polygons).map(|i| coverage(&scene, i)).min().unwrap();
            let depths: Vec<f64> = scene["polygons"]
                .as_array()
                .unwrap()
                .iter()
                .flat_map(|p| p["vertices"].as_array().unwrap().iter().map(|v| v[2].as_f64().unwrap()))
                .collect();
            let inside = depths.iter().all(|z| (0.0..=15.0).contains(z));
            if style == "book" {
                assert!(smallest >= min.parse().unwrap(), "seed {seed}: a polygon covers {smallest} centres");
                assert!(inside, "seed {seed}: depths {depths:?}");
            } else {
                free_sliver_or_outside |= smallest < 12 || !inside;
            }
        }
    }
    assert!(free_sliver_or_outside, "the free style is what the book style excludes");
}

/// `grade --format json` gave the score as a string ("98.5"), and `grade
/// --help` showed a CSV header without the `misconception` column the CSV has.
#[test]
fn grade_json_scores_are_numbers_and_the_help_shows_the_csv_header() {
    let run = zsim(&["grade", "examples/rogers.json", "examples/class", "--format", "json"]);
    let report: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    let scores: Vec<f64> =
        report["students"].as_array().unwrap().iter().map(|s| s["score"].as_f64().unwrap()).collect();
    assert_eq!(scores[..2], [100.0, 95.5], "{}", run.stdout);
    let csv = zsim(&["grade", "examples/rogers.json", "examples/class", "--format", "csv"]).stdout;
    let header = csv.lines().next().unwrap();
    assert!(zsim(&["grade", "--help"]).stdout.contains(&format!("header row: {header}\n")), "{header}");
}

/// `grade` passed over files it could not match without a word:
/// `frank.depht.txt` and `bob.FRAME.txt` left frank and bob ungraded, exit 0.
/// Each file not graded is named with why, a near miss with the name it
/// should have, in the table and in the JSON, and the exit status is 1.
#[test]
fn grade_names_every_file_it_did_not_grade() {
    let class = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("class-near-misses");
    let _ = std::fs::remove_dir_all(&class);
    std::fs::create_dir_all(&class).unwrap();
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/class");
    for (from, to) in [
        ("ana.frame.txt", "ana.frame.txt"),
        ("ana.depth.txt", "ana.depth.txt"),
        ("bo.depth.txt", "frank.depht.txt"),
        ("di.frame.txt", "bob.FRAME.txt"),
    ] {
        std::fs::copy(examples.join(from), class.join(to)).unwrap();
    }
    std::fs::write(class.join("notes.md"), "the answers are in the .txt files\n").unwrap();
    let folder = class.to_str().unwrap();
    let run = zsim(&["grade", "examples/rogers.json", folder, "--lang", "en"]);
    assert_eq!(run.code, 1, "a student's work was not graded: {}", run.stdout);
    assert!(
        run.stdout.ends_with(
            "not graded: bob.FRAME.txt looks like bob's framebuffer: name it bob.frame.txt\n\
             not graded: frank.depht.txt looks like frank's z-buffer: name it frank.depth.txt\n\
             not graded: notes.md is not an answer file (NAME.frame.txt or NAME.depth.txt)\n"
        ),
        "{}",
        run.stdout
    );
    let json = zsim(&["grade", "examples/rogers.json", folder, "--format", "json"]);
    assert_eq!(json.code, 1);
    let report: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    let not_graded = report["not_graded"].as_array().unwrap();
    assert_eq!(not_graded.len(), 3);
    assert_eq!(
        (not_graded[1]["file"].as_str(), not_graded[1]["student"].as_str()),
        (Some("frank.depht.txt"), Some("frank"))
    );
    assert_eq!(not_graded[2]["student"], serde_json::Value::Null);
    // A gradebook for a platform stays importable: the files not graded are named on standard error.
    for format in ["csv", "moodle", "canvas"] {
        let run = zsim(&["grade", "examples/rogers.json", folder, "--format", format, "--lang", "en"]);
        assert_eq!(run.code, 1, "{format}");
        assert!(!run.stdout.contains("depht"), "{format}: {}", run.stdout);
        let named = "zsim: not graded: frank.depht.txt looks like frank's z-buffer: name it frank.depth.txt\n";
        assert_eq!(run.stderr.lines().count(), 3, "{format}: {}", run.stderr);
        assert!(run.stderr.contains(named), "{format}: {}", run.stderr);
    }
    // Only stray files, no misnamed answer: named, but everyone's work was graded.
    std::fs::remove_file(class.join("frank.depht.txt")).unwrap();
    std::fs::remove_file(class.join("bob.FRAME.txt")).unwrap();
    let run = zsim(&["grade", "examples/rogers.json", folder]);
    assert_eq!(run.code, 0, "{}", run.stdout);
    assert!(run.stdout.contains("not graded: notes.md is not an answer file"), "{}", run.stdout);
}

/// `exercise --lang ru` wrote "тест глубины greater" in the teacher's notes:
/// the depth test is named in the notes' language.
#[test]
fn exercise_notes_name_the_depth_test_in_their_language() {
    for (lang, ending) in [
        ("ru", "тест глубины больше"),
        ("uk", "тест глибини більше"),
        ("zh", "深度测试 大于"),
        ("en", "depth test greater"),
    ] {
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("exercise-notes-{lang}"));
        let _ = std::fs::remove_dir_all(&dir);
        let run = zsim(&["exercise", "-o", dir.to_str().unwrap(), "--lang", lang]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        let notes = std::fs::read_to_string(dir.join("exercise.txt")).unwrap();
        assert!(notes.lines().next().unwrap().ends_with(ending), "{notes}");
    }
}

/// Asked for by a student who worked out only the top half: `?` cells are
/// not answered, so they earn nothing and cost nothing; `check` says how
/// many were left and exits 1; `grade` calls the student incomplete.
#[test]
fn unanswered_cells_are_counted_by_check_and_grade() {
    let half = "tests/fixtures/rogers/frame_top_half.txt";
    let run = zsim(&["check", "examples/rogers.json", "--frame", half]);
    assert_eq!(run.code, 1, "not yet the whole answer: {}", run.stdout);
    assert!(
        run.stdout.contains("all 512 cells match the framebuffer after polygon 2 \"triangle\"; 512 of 1024 cells were left unanswered (? or .)"),
        "{}",
        run.stdout
    );
    let class = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("class-unanswered");
    let _ = std::fs::remove_dir_all(&class);
    std::fs::create_dir_all(&class).unwrap();
    std::fs::copy(half, class.join("half.frame.txt")).unwrap();
    let json = zsim(&["grade", "examples/rogers.json", class.to_str().unwrap(), "--format", "json"]);
    assert_eq!(json.code, 1);
    let report: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    let student = &report["students"][0];
    assert_eq!(
        (student["status"].as_str(), student["unanswered"].as_u64()),
        (Some("incomplete: 512 unanswered"), Some(512))
    );
    assert_eq!(student["frame_wrong"], 0);
    // The changed cells in the top half, over the 337 the triangle and rectangle change in all.
    let top: usize = std::fs::read_to_string(half)
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#'))
        .flat_map(|l| l.split_whitespace().filter(|v| *v != "0" && *v != "?"))
        .count();
    let score = (top as f64 * 1000.0 / 337.0).round() / 10.0;
    assert_eq!(student["score"].as_f64(), Some(score), "{top} of 337");
}

/// Found by a teacher: "common mistakes" stopped at 10 rows without saying
/// how many more there were.
#[test]
fn common_mistakes_say_how_many_they_leave_out() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("mistakes-left-out");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    // Two students who hand in the cleared framebuffer: every cell either polygon writes is wrong twice.
    let zeros = format!("{}\n", vec!["0"; 32].join(" ")).repeat(32);
    for student in ["ann", "bob"] {
        std::fs::write(dir.join(format!("{student}.frame.txt")), &zeros).unwrap();
    }
    let run = crate::zsim(&["grade", "examples/rogers.json", dir.to_str().unwrap()]);
    let written = crate::book_answer("frame", " ").split_whitespace().filter(|v| *v != "0").count();
    assert!(
        run.stdout
            .ends_with(&format!("{} more cells that two or more students got wrong are not listed\n", written - 10)),
        "{}",
        run.stdout
    );
}

/// Found by a teacher: the Gradescope `setup.sh` said "build it with cargo
/// deb", which fails on a clone; it names `packaging/deb`, which is there.
#[test]
fn the_gradescope_setup_names_the_command_that_builds_the_package() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("gradescope-setup");
    let _ = std::fs::remove_dir_all(&dir);
    let (exercise, grader) = (dir.join("ex"), dir.join("grader"));
    let run = crate::zsim(&[
        "exercise",
        "--seed",
        "3",
        "-o",
        exercise.to_str().unwrap(),
        "--gradescope",
        grader.to_str().unwrap(),
    ]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let setup = std::fs::read_to_string(grader.join("setup.sh")).unwrap();
    assert!(setup.contains("packaging/deb") && !setup.contains("cargo deb"), "{setup}");
    assert!(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("packaging/deb").is_file());
}

/// Found by a teacher: a student whose only file was misnamed
/// (`frank.frmae.txt`) got no row at all, a Windows double extension
/// (`ivan.frame.txt.txt`) got no hint, and the feedback said only "missing"
/// where the report said which file looked like the student's.
#[test]
fn a_misnamed_only_student_gets_a_row_the_hint_and_feedback_that_says_so() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("misnamed-only");
    let _ = std::fs::remove_dir_all(&dir);
    let class = dir.join("class");
    std::fs::create_dir_all(&class).unwrap();
    let answer = crate::book_answer("frame", " ");
    for name in ["ann.frame.txt", "frank.frmae.txt", "ivan.frame.txt.txt"] {
        std::fs::write(class.join(name), &answer).unwrap();
    }
    let feedback = dir.join("feedback");
    let run =
        crate::zsim(&["grade", "examples/rogers.json", class.to_str().unwrap(), "-o", feedback.to_str().unwrap()]);
    assert_eq!(run.code, 1, "{}", run.stderr);
    for line in [
        "| frank   | -           | -           | 0.0     | missing: frank.frame.txt |",
        "| ivan    | -           | -           | 0.0     | missing: ivan.frame.txt  |",
        "not graded: frank.frmae.txt looks like frank's framebuffer: name it frank.frame.txt",
        "not graded: ivan.frame.txt.txt looks like ivan's framebuffer: name it ivan.frame.txt",
    ] {
        assert!(run.stdout.lines().any(|l| l == line), "{line:?} in:\n{}", run.stdout);
    }
    let frank = std::fs::read_to_string(feedback.join("frank.feedback.txt")).unwrap();
    assert!(frank.contains("frank.frmae.txt looks like frank's framebuffer"), "{frank}");
}

/// Found by a teacher: names that differ only in case (`Emma`, `emma`)
/// refused the whole class in every format. A name never stops a class: both
/// are graded in every report and get their feedback; only the Moodle and
/// Canvas imports, which would merge them, leave those two rows out and say so.
#[test]
fn names_that_differ_only_in_case_are_graded_both_and_left_out_of_an_import_alone() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("case-names");
    let _ = std::fs::remove_dir_all(&dir);
    let class = dir.join("class");
    std::fs::create_dir_all(&class).unwrap();
    let answer = crate::book_answer("frame", " ");
    for name in ["Emma.frame.txt", "emma.frame.txt", "zoe.frame.txt"] {
        std::fs::write(class.join(name), &answer).unwrap();
    }
    let run = crate::zsim(&["grade", "examples/rogers.json", class.to_str().unwrap(), "--format", "csv"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let students: Vec<&str> = run.stdout.lines().skip(1).map(|l| l.split(',').next().unwrap()).collect();
    assert_eq!(students, ["Emma", "emma", "zoe"]);
    for format in ["moodle", "canvas"] {
        let run = crate::zsim(&["grade", "examples/rogers.json", class.to_str().unwrap(), "--format", format]);
        assert_eq!(run.code, 1, "{format}: {}", run.stdout);
        assert!(run.stdout.contains("zoe,") && !run.stdout.to_lowercase().contains("emma"), "{format}: {}", run.stdout);
        assert_eq!(
            run.stderr.trim(),
            "zsim: left out of the gradebook: \"Emma\" and \"emma\" are one student to a gradebook (the same cell, without case): rename one and import their rows again"
        );
    }
    let feedback = dir.join("feedback");
    let run =
        crate::zsim(&["grade", "examples/rogers.json", class.to_str().unwrap(), "-o", feedback.to_str().unwrap()]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(feedback.join("Emma.feedback.txt").is_file() && feedback.join("emma.feedback.txt").is_file());
}
