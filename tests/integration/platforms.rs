//! Grades handed to the courses' platforms, each held to the platform's
//! published layout: Gradescope's autograder specification (the example
//! `results.json` of "Autograder Specifications"), Moodle's gradebook export
//! (which its import reads back), Canvas's gradebook export.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use crate::zsim;

/// The keys of the example `results.json` in Gradescope's specification: top
/// level, and of each test.
const GRADESCOPE_TOP: [&str; 7] =
    ["score", "execution_time", "output", "visibility", "stdout_visibility", "extra_data", "tests"];
const GRADESCOPE_TEST: [&str; 12] = [
    "score",
    "max_score",
    "status",
    "name",
    "name_format",
    "number",
    "output",
    "output_format",
    "tags",
    "visibility",
    "extra_data",
    "leaderboard",
];

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("platforms").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs the exercise's `run_autograder` as Gradescope would, in a folder
/// standing for `/autograder`, and returns its results.json.
fn autograde(root: &Path, submission: &[(&str, String)]) -> serde_json::Value {
    let folder = root.join("submission");
    let _ = std::fs::remove_dir_all(&folder);
    std::fs::create_dir_all(&folder).unwrap();
    for (name, text) in submission {
        std::fs::write(folder.join(name), text).unwrap();
    }
    let bin = Path::new(env!("CARGO_BIN_EXE_zsim")).parent().unwrap();
    let path = format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default());
    let status = std::process::Command::new("bash")
        .arg(root.join("source/run_autograder"))
        .env("AUTOGRADER_ROOT", root)
        .env("PATH", path)
        .status()
        .unwrap();
    assert!(status.success());
    serde_json::from_str(&std::fs::read_to_string(root.join("results/results.json")).unwrap()).unwrap()
}

/// What Gradescope requires of a results.json: only keys of its example,
/// a known status and visibility, scores within their maximum, and a total.
fn assert_gradescope_layout(results: &serde_json::Value) {
    let keys = |v: &serde_json::Value| v.as_object().unwrap().keys().cloned().collect::<BTreeSet<String>>();
    assert!(keys(results).iter().all(|k| GRADESCOPE_TOP.contains(&k.as_str())), "{results}");
    assert!(results["score"].is_number());
    let visibilities = ["hidden", "after_due_date", "after_published", "visible"];
    assert!(visibilities.contains(&results["visibility"].as_str().unwrap()));
    let mut total = 0.0;
    for test in results["tests"].as_array().unwrap() {
        assert!(keys(test).iter().all(|k| GRADESCOPE_TEST.contains(&k.as_str())), "{test}");
        assert!(["passed", "failed"].contains(&test["status"].as_str().unwrap()));
        assert!(visibilities.contains(&test["visibility"].as_str().unwrap()));
        let (score, max) = (test["score"].as_f64().unwrap(), test["max_score"].as_f64().unwrap());
        assert!((0.0..=max).contains(&score), "{test}");
        assert!(test["name"].is_string() && test["output"].is_string());
        total += score;
    }
    assert!((results["score"].as_f64().unwrap() - total).abs() < 1e-9);
}

#[test]
fn an_exercise_writes_a_gradescope_autograder_that_grades_by_buffer_and_polygon() {
    let dir = scratch("gradescope");
    let (exercise, root) = (dir.join("ex"), dir.join("autograder"));
    let run = zsim(&[
        "exercise",
        "--seed",
        "9",
        "--each-polygon",
        "-o",
        exercise.to_str().unwrap(),
        "--gradescope",
        root.join("source").to_str().unwrap(),
        "--visibility",
        "after_due_date",
        "--points",
        "12",
    ]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    let key = |name: &str| std::fs::read_to_string(exercise.join(name)).unwrap();
    // The answer key, handed in as a student would: every test passed, 12 points.
    let right = [
        ("after-1.frame.txt", key("answer.after-1.frame.txt")),
        ("after-1.depth.txt", key("answer.after-1.depth.txt")),
        ("frame.txt", key("answer.frame.txt")),
        ("depth.txt", key("answer.depth.txt")),
    ];
    let results = autograde(&root, &right);
    assert_gradescope_layout(&results);
    // The same folder checked as text: each state after its polygon, every cell right, exit 0.
    let text = zsim(&[
        "check",
        root.join("source/scene.json").to_str().unwrap(),
        "--submission",
        root.join("submission").to_str().unwrap(),
    ]);
    assert_eq!((text.code, text.stdout.matches("all 256 cells match").count()), (0, 4), "{}", text.stdout);
    let names: Vec<&str> = results["tests"].as_array().unwrap().iter().map(|t| t["name"].as_str().unwrap()).collect();
    assert_eq!(
        names,
        [
            "framebuffer after polygon 1 \"A\"",
            "z-buffer after polygon 1 \"A\"",
            "framebuffer after polygon 2 \"B\"",
            "z-buffer after polygon 2 \"B\""
        ]
    );
    assert_eq!(results["score"], 12.0);
    assert_eq!(results["tests"][0]["visibility"], "after_due_date");
    // One cell wrong in the final z-buffer, a malformed framebuffer, and the
    // states after polygon 1 not handed in: every test fails.
    let mut depth = key("answer.depth.txt");
    depth.replace_range(0..1, if depth.starts_with('0') { "1" } else { "0" });
    let results = autograde(&root, &[("frame.txt", "0 x\n".into()), ("depth.txt", depth)]);
    assert_gradescope_layout(&results);
    let tests = results["tests"].as_array().unwrap();
    for missing in &tests[..2] {
        assert_eq!((missing["score"].as_f64(), missing["status"].as_str()), (Some(0.0), Some("failed")));
        assert!(missing["output"].as_str().unwrap().starts_with("no file answers this: hand in after-1."), "{missing}");
    }
    assert_eq!((tests[2]["score"].as_f64(), tests[2]["status"].as_str()), (Some(0.0), Some("failed")));
    assert!(tests[2]["output"].as_str().unwrap().contains("\"x\" is not a whole number"), "{}", tests[2]);
    // 3 points for the final z-buffer: the share of the cells the polygons change (cleared to 0)
    // that are right, less one share for a cell written where 0 stays; one cell is wrong either
    // way, so (changed − 1) / changed of 3 points, rounded down to a hundredth.
    let changed = key("answer.depth.txt").split_whitespace().filter(|v| *v != "0").count() as u64;
    let points = (300 * (changed - 1) / changed) as f64 / 100.0;
    assert_eq!((tests[3]["score"].as_f64(), tests[3]["status"].as_str()), (Some(points), Some("failed")));
    let output = tests[3]["output"].as_str().unwrap();
    assert!(output.contains("1 of 256 cells differs"), "{output}");
    let rule = format!("score: the share of the {changed} cells the scene changes that are right");
    assert!(output.contains(&rule), "the rule is stated with the student's counts: {output}");
    // Nothing handed in: a score of 0 and, in each test, which file was missing.
    let results = autograde(&root, &[]);
    assert_gradescope_layout(&results);
    assert_eq!(results["score"], 0.0);
    let tests = results["tests"].as_array().unwrap();
    assert_eq!(tests.len(), 4);
    assert!(tests.iter().all(|t| t["output"].as_str().unwrap().starts_with("no file answers this")), "{results}");
}

/// Moodle's gradebook export writes `First name,Surname,ID number,
/// Institution,Department,Email address`, then `Assignment: NAME (Real)` per
/// item; its import maps one of those identity columns and takes the grade
/// columns, refusing the file when a value lies outside the item's range.
#[test]
fn grade_writes_a_moodle_import() {
    let moodle_export = ["First name", "Surname", "ID number", "Institution", "Department", "Email address"];
    let run = zsim(&["grade", "examples/rogers.json", "examples/class", "--format", "moodle", "--points", "20"]);
    assert_eq!(run.code, 1, "{}", run.stderr);
    assert_eq!(run.stdout, "Email address,Assignment: z-buffer (Real)\nana,20.00\nbo,19.11\ncy,10.00\ndi,10.00\n");
    for identity in ["email", "idnumber", "username"] {
        let run =
            zsim(&["grade", "examples/rogers.json", "examples/class", "--format", "moodle", "--identity", identity]);
        let header = run.stdout.lines().next().unwrap().split(',').next().unwrap().to_string();
        assert!(moodle_export.contains(&header.as_str()) || header == "Username", "{header}");
        for line in run.stdout.lines().skip(1) {
            let grade: f64 = line.split(',').nth(1).unwrap().parse().unwrap();
            assert!((0.0..=100.0).contains(&grade), "{line}");
        }
    }
    let run = zsim(&["grade", "examples/rogers.json", "examples/class", "--format", "moodle", "--identity", "id"]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("does not import by \"ID\""), "{}", run.stderr);
}

/// Canvas's gradebook export: `Student,ID,SIS User ID,SIS Login ID,Section`,
/// then `NAME (ID)` per assignment, and a second row `Points Possible`.
#[test]
fn grade_writes_a_canvas_import() {
    let run = zsim(&[
        "grade",
        "examples/rogers.json",
        "examples/class",
        "--format",
        "canvas",
        "--item",
        "Z-buffer (4711)",
        "--points",
        "10",
    ]);
    assert_eq!(
        run.stdout,
        "Student,ID,SIS User ID,SIS Login ID,Section,Z-buffer (4711)\n\
         Points Possible,,,,,10\n\
         ana,,,ana,,10.00\n\
         bo,,,bo,,9.55\n\
         cy,,,cy,,5.00\n\
         di,,,di,,5.00\n"
    );
    let run = zsim(&["grade", "examples/rogers.json", "examples/class", "--format", "canvas", "--identity", "id"]);
    assert!(run.stdout.lines().nth(2).unwrap().starts_with("ana,ana,,,,"), "{}", run.stdout);
}
