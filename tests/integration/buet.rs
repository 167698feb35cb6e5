//! BUET CSE 410 "Offline 2: Rasterization": the course's published golden
//! cases, read from `../shared/peer/buet-cse410-a/` (never copied into the
//! project). Where that folder is absent (a user's own clone), the golden
//! tests say so on stderr instead of passing silently.

use std::path::{Path, PathBuf};

use crate::{scene_file, snapshot, zsim, zsim_in};

/// The peer cases folder.
fn cases() -> PathBuf {
    crate::peer("buet-cse410-a", "the BUET golden cases")
}

/// A text file with line ends and trailing spaces normalized.
fn normalized(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines().map(|line| line.trim_end_matches([' ', '\r'])).collect::<Vec<_>>().join("\n")
}

/// Runs `zsim buet run` on case `n` and returns the output folder.
fn run_case(dir: &Path, n: u32, from: &str) -> PathBuf {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("buet-{n}-{from}"));
    let _ = std::fs::remove_dir_all(&out);
    let case = dir.join(n.to_string());
    let run = zsim(&["buet", "run", case.to_str().unwrap(), "--from", from, "-o", out.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""), "case {n} from {from}");
    out
}

fn assert_same(expected: &Path, ours: &Path, what: &str) {
    let (a, b) = (normalized(expected), normalized(ours));
    if a != b {
        let line =
            a.lines().zip(b.lines()).position(|(x, y)| x != y).unwrap_or(a.lines().count().min(b.lines().count()));
        panic!(
            "{what}: {} differs from the golden file at line {}:\n golden: {:?}\n zsim:   {:?}",
            ours.display(),
            line + 1,
            a.lines().nth(line),
            b.lines().nth(line)
        );
    }
}

/// Runs case `n` from `from` and compares every file both have with the golden one.
fn assert_case_reproduces(dir: &Path, n: u32, from: &str) {
    let case = dir.join(n.to_string());
    let out = run_case(dir, n, from);
    for file in ["stage1.txt", "stage2.txt", "stage3.txt", "z_buffer.txt"] {
        if case.join(file).is_file() && out.join(file).is_file() {
            assert_same(&case.join(file), &out.join(file), &format!("case {n} from {from}: {file}"));
        }
    }
    assert!(out.join("z_buffer.txt").is_file(), "case {n}: z_buffer.txt written");
    if case.join("out.bmp").is_file() {
        let (golden, ours) =
            (std::fs::read(case.join("out.bmp")).unwrap(), std::fs::read(out.join("out.bmp")).unwrap());
        assert!(golden == ours, "case {n} from {from}: out.bmp differs");
    }
}

#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn every_case_reproduces_from_stage3() {
    let dir = cases();
    for n in (1..=5).filter(|n| dir.join(n.to_string()).join("stage3.txt").is_file()) {
        assert_case_reproduces(&dir, n, "stage3");
    }
}

#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn every_case_reproduces_from_scene() {
    let dir = cases();
    for n in 1..=5 {
        assert_case_reproduces(&dir, n, "scene");
        // From scene.txt zsim writes all three stages.
        let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("buet-{n}-scene"));
        assert!(out.join("stage1.txt").is_file() && out.join("stage3.txt").is_file(), "case {n}");
    }
}

#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn check_accepts_the_golden_answer_and_explains_a_wrong_one() {
    let dir = cases();
    let case = dir.join("1");
    let golden = case.join("z_buffer.txt");
    let run = zsim(&["buet", "check", case.to_str().unwrap(), "--answer", golden.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""), "{}", run.stdout);
    // Change the first value on the first line with values.
    let text = std::fs::read_to_string(&golden).unwrap();
    let wrong = text.replacen("0.979798\t", "0.979799\t", 1);
    let (scratch, _) = scene_file("unused_buet.json", "{}");
    let answer = scratch.join("wrong_z_buffer.txt");
    std::fs::write(&answer, wrong).unwrap();
    let run = zsim(&["buet", "check", case.to_str().unwrap(), "--answer", answer.to_str().unwrap()]);
    assert_eq!(run.code, 1, "{}", run.stdout);
    assert!(run.stdout.contains("1 value differs"), "{}", run.stdout);
    assert!(run.stdout.contains("| 0.979799 | 0.979798 | cell ("), "{}", run.stdout);
    // Its table wrapped its reasons at 347 characters: it stays 100 columns wide at most.
    let widest = run.stdout.lines().filter(|l| l.starts_with('|')).map(|l| l.chars().count()).max().unwrap();
    assert!(widest <= 100, "widest line {widest}: {}", run.stdout);
    // A malformed answer is refused.
    std::fs::write(&answer, "0.5\tabc\n").unwrap();
    let run = zsim(&["buet", "check", case.to_str().unwrap(), "--answer", answer.to_str().unwrap()]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert!(run.stderr.ends_with("line 1, value 2: \"abc\" is not a number\n"), "{}", run.stderr);
}

#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn an_imported_case_runs_steps_and_explains_like_any_scene() {
    let dir = cases();
    let run = zsim(&["buet", "import", dir.join("1").to_str().unwrap()]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let (scratch, name) = scene_file("buet_case_1.json", &run.stdout);
    let json = zsim_in(Some(&scratch), &["run", &name, "--format", "json", "--final"]);
    let value: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    assert_eq!(value["width"], 500);
    // Pixel (250, 250) is the first triangle's, at z = 4876543/5000000.
    let explain = zsim_in(Some(&scratch), &["explain", &name, "--pixel", "250,250"]);
    assert!(explain.stdout.contains("so 4876543/5000000 ≈ 0.975309 is stored (exactly)"), "{}", explain.stdout);
    assert!(
        explain.stdout.ends_with("final: framebuffer 2696126, z-buffer 4876543/5000000 ≈ 0.975309\n"),
        "{}",
        explain.stdout
    );
    let step = zsim_in(Some(&scratch), &["step", &name, "--polygon", "1", "--scanline", "260"]);
    assert!(
        step.stdout.contains("span 1: x_a = 250, z_a = 4876543/5000000 ≈ 0.975309; x_b = 10904171/40000 ≈ 272.60"),
        "{}",
        step.stdout
    );
    let figure = zsim_in(Some(&scratch), &["figure", &name, "-o", "buet_case_1.svg"]);
    assert_eq!(figure.code, 0, "{}", figure.stderr);
}

/// The second config form (window and depth range given), on a case made here.
#[test]
fn the_second_config_form_sets_window_range_and_clear_value() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("buet-second-form");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    // A 4×2 raster over x −2 … 2, y −1 … 1; depth range 0 … 5, cleared to 5.
    std::fs::write(dir.join("config.txt"), "4 2\n-2\n-1\n0 5\n").unwrap();
    // Triangle 1 covers everything at z = 3; triangle 2 lies in front (z = 1) on the left
    // half; triangle 3 would be nearer (z = −1) but lies outside the depth range.
    std::fs::write(
        dir.join("stage3.txt"),
        "-9 -9 3\n9 -9 3\n0 9 3\n\n-2 -1 1\n0 -1 1\n-2 1 1\n\n-9 -9 -1\n9 -9 -1\n0 9 -1\n\n",
    )
    .unwrap();
    let out = dir.join("out");
    let run = zsim(&["buet", "run", dir.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    // In pixel units x_px = x + 2 and y_px = y + 1, so triangle 2 is (0, 0), (2, 0), (0, 2).
    // The top row's scanline y_px = 1.5 crosses it at 0 and 0.5: cells 0 … 0. The bottom
    // row's (0.5) at 0 and 1.5: cells 0 … 1. Triangle 1 (z = 3) fills the rest; triangle 3
    // (z = −1) is discarded everywhere, and every cell is below the clear value 5.
    assert_eq!(
        std::fs::read_to_string(out.join("z_buffer.txt")).unwrap(),
        "1.000000\t3.000000\t3.000000\t3.000000\t\n1.000000\t1.000000\t3.000000\t3.000000\t\n"
    );
    let import = zsim(&["buet", "import", dir.to_str().unwrap()]);
    snapshot!("buet_import_second_form", import.stdout);
}

#[test]
fn malformed_cases_are_refused_with_the_file_and_line() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("buet-bad");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("config.txt"), "500 500\n").unwrap();
    std::fs::write(dir.join("scene.txt"), "0 0 50\n0 0 0\n0 1 0\n80 1 1 100\ntriangle\n0 0 5\n5 0\n0 5 5\nend\n")
        .unwrap();
    let run = zsim(&["buet", "run", dir.to_str().unwrap(), "-o", dir.join("out").to_str().unwrap()]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert!(
        run.stderr.ends_with("scene.txt: line 7: expected a triangle vertex (3 numbers), found \"5 0\"\n"),
        "{}",
        run.stderr
    );
    std::fs::write(dir.join("config.txt"), "500\n").unwrap();
    let run = zsim(&["buet", "run", dir.to_str().unwrap(), "-o", dir.join("out").to_str().unwrap()]);
    assert_eq!(run.code, 2);
    assert!(
        run.stderr.ends_with("config.txt: line 1: the first line must be the raster size \"W H\"\n"),
        "{}",
        run.stderr
    );
    let run = zsim(&["buet", "run", dir.to_str().unwrap(), "-o", dir.join("out").to_str().unwrap(), "--lang", "uk"]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("config.txt: рядок 1: "), "{}", run.stderr);
}

/// The 2018 assignment's kind of input: a window 0.7 wide over 500 pixels
/// and 7-decimal coordinates (`tests/fixtures/buet-2018`, made for this
/// test). Its first triangle passes the word range (2^34) and is drawn on the
/// big-integer tier instead of refused; the depth at pixel (250, 249) equals
/// the plane's at that centre, 700662989706936810113/36888584653298750000,
/// computed apart with Python's `fractions` from the decimals as written.
#[test]
fn seven_decimal_cases_are_drawn_exactly_instead_of_refused() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/buet-2018");
    let case = zsim::buet::Case::load(&dir, None).expect("drawn, not refused");
    assert!(case.scene.polygons[0].geometry().is_big(), "triangle 1 passes 2^34");
    let out_dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("buet-2018");
    let out = zsim(&["buet", "run", dir.to_str().unwrap(), "-o", out_dir.to_str().unwrap()]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let (scene_dir, scene) = scene_file("buet-2018.json", &case.scene_json);
    let explain = zsim_in(Some(&scene_dir), &["explain", &scene, "--pixel", "250,249"]);
    assert!(
        explain
            .stdout
            .ends_with("final: framebuffer 2696126, z-buffer 700662989706936810113/36888584653298750000 ≈ 18.994033\n"),
        "{}",
        explain.stdout
    );
}

/// `buet run --lang ru` said "2 треугольников": the count agrees with its noun in every language.
#[test]
fn buet_run_counts_triangles_with_the_right_plural() {
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("buet-plural");
    for (lang, words) in [("en", "2 triangles on"), ("ru", "2 треугольника на"), ("uk", "2 трикутники на")]
    {
        let run = crate::zsim(&["buet", "run", "examples/buet/case", "--lang", lang, "-o", out.to_str().unwrap()]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        assert!(run.stdout.starts_with(&format!("examples/buet/case: {words} 32×32")), "{}", run.stdout);
    }
}
