//! A course: a variant per student of the roster (`exercise --roster`),
//! fair by construction, and each student graded against their own key
//! (`grade --variants`), on the platforms' own file layouts.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use crate::zsim_in;

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("course").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Canvas's gradebook export: its `Points Possible` row, quoted names with commas, accents, CRLF.
const CANVAS: &str = "\u{feff}Student,ID,SIS User ID,SIS Login ID,Section,Homework 1 (12)\r\n\
    \"    Points Possible\",,,,,10\r\n\
    \"Lima, Ana\",101,A1,ana,Sec 1,\r\n\
    \"Chen, Bo\",102,B2,bo,Sec 1,\r\n\
    \"Østby, Cy\",103,C3,cy,Sec 1,\r\n\
    \"Diaz, Di\",104,D4,di,Sec 1,\r\n";

/// Makes the class of `roster` (written as `roster.csv`) into `dir/out` with `extra` flags.
fn class(dir: &Path, roster: &str, extra: &[&str]) -> crate::Run {
    std::fs::write(dir.join("roster.csv"), roster).unwrap();
    let mut args = vec!["exercise", "--roster", "roster.csv", "--seed", "2026", "-o", "out"];
    args.extend(extra);
    zsim_in(Some(dir), &args)
}

fn manifest(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("out/variants.json")).unwrap()).unwrap()
}

fn files_under(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(folder) = stack.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else {
                let name = path.strip_prefix(dir).unwrap().display().to_string();
                files.push((name, std::fs::read(&path).unwrap()));
            }
        }
    }
    files.sort();
    files
}

#[test]
fn the_same_roster_and_seed_give_byte_identical_files() {
    let (a, b) = (scratch("identical-a"), scratch("identical-b"));
    assert_eq!(class(&a, CANVAS, &[]).code, 0);
    assert_eq!(class(&b, CANVAS, &[]).code, 0);
    let (first, second) = (files_under(&a.join("out")), files_under(&b.join("out")));
    assert!(first.len() > 20, "{:?}", first.iter().map(|f| &f.0).collect::<Vec<_>>());
    assert!(first == second, "two runs of one roster and seed differ");
}

#[test]
fn a_student_reseeded_or_added_later_changes_nobody_elses_variant() {
    let dir = scratch("reseed");
    assert_eq!(class(&dir, CANVAS, &[]).code, 0);
    let before = manifest(&dir)["students"].as_array().unwrap().clone();
    let scene_of = |students: &[serde_json::Value], id: &str| {
        students.iter().find(|s| s["identity"] == id).map(|s| (s["scene"].to_string(), s["code"].clone()))
    };
    let reseeded = scratch("reseed-2");
    assert_eq!(class(&reseeded, CANVAS, &["--reseed", "BO"]).code, 0);
    let after = manifest(&reseeded)["students"].as_array().unwrap().clone();
    for id in ["ana", "cy", "di"] {
        assert_eq!(scene_of(&before, id), scene_of(&after, id), "{id}'s variant changed");
    }
    assert_ne!(scene_of(&before, "bo"), scene_of(&after, "bo"), "bo was reseeded");
    assert_eq!(after.iter().find(|s| s["identity"] == "bo").unwrap()["attempt"], 1);
    let grown = scratch("reseed-grown");
    let roster = format!("{CANVAS}\"Eve, Eve\",105,E5,eve,Sec 2,\r\n");
    assert_eq!(class(&grown, &roster, &[]).code, 0);
    let grown = manifest(&grown)["students"].as_array().unwrap().clone();
    assert_eq!(grown.len(), 5);
    for id in ["ana", "bo", "cy", "di"] {
        assert_eq!(scene_of(&before, id), scene_of(&grown, id), "{id}'s variant changed when eve joined");
    }
    let unknown = class(&scratch("reseed-unknown"), CANVAS, &["--reseed", "zed"]);
    assert_eq!(
        (unknown.code, unknown.stderr.trim()),
        (2, "zsim: --reseed zed: nobody on the roster has that identity")
    );
}

/// Every variant's stored counts are what its stored scene holds, recounted
/// from the scene by the library; every asked case arises exactly once and
/// every other case not at all; every required wrong rule's answer differs
/// from the key in 3 cells or more; no two students share a scene, a key or a code.
#[test]
fn every_variant_holds_each_asked_case_once_and_tells_each_wrong_rule_apart() {
    let dir = scratch("fair");
    let run = class(&dir, CANVAS, &[]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let text = std::fs::read_to_string(dir.join("out/variants.json")).unwrap();
    let loaded = zsim::course::manifest::read(&text, Path::new("variants.json")).unwrap();
    let settings = &loaded.manifest.settings;
    assert_eq!(settings.hard, ["vertex-on-scanline", "centre-on-edge", "half-depth", "hidden"]);
    let (mut scenes, mut keys, mut codes) = (BTreeSet::new(), BTreeSet::new(), BTreeSet::new());
    for (variant, scene) in loaded.manifest.students.iter().zip(&loaded.scenes) {
        let census = zsim::exercise::census(zsim::Lang::En, scene);
        for case in zsim::exercise::HardCase::ALL {
            let expected = usize::from(settings.hard.contains(&case.name().to_string()));
            assert_eq!(census.count(case), expected, "{}: {}", variant.identity, case.name());
            let stored = variant.cases.iter().find(|c| c.name == case.name()).unwrap().count;
            assert_eq!(stored, expected, "{}: the manifest's {}", variant.identity, case.name());
        }
        let separations = zsim::diagnose::Diagnoser::new(scene, scene.polygons.len() - 1).unwrap().separations();
        for rule in &settings.rules {
            let (_, cells) = separations.iter().find(|(m, _)| m.name() == rule).unwrap();
            assert!(*cells >= 3, "{}: {rule} differs in {cells} cells", variant.identity);
        }
        let key = zsim::course::fair::key_of(scene);
        assert!(
            scenes.insert(variant.scene.get().to_string()) && keys.insert(key) && codes.insert(variant.code.clone())
        );
    }
    let table = std::fs::read_to_string(dir.join("out/fairness.csv")).unwrap();
    assert!(
        table.starts_with("identity,code,vertex-on-scanline,centre-on-edge,half-depth,saturation,hidden,"),
        "{table}"
    );
    assert_eq!(table.lines().count(), 5);
    assert!(run.stdout.contains("4 students, course seed 2026"), "{}", run.stdout);
}

/// The teacher's files and nothing of them in a student's folder: the
/// student's folder holds their scene, worksheet, templates of `?` and what
/// to hand in; no line of their key appears in any of them.
#[test]
fn a_students_folder_holds_nothing_that_gives_a_cell_away() {
    let dir = scratch("folders");
    assert_eq!(class(&dir, CANVAS, &["--site", "https://example.edu/zsim/"]).code, 0);
    let ana = dir.join("out/students/ana");
    let names: Vec<String> = files_under(&ana).into_iter().map(|f| f.0).collect();
    assert_eq!(names, ["ana.depth.txt", "ana.frame.txt", "hand-in.txt", "scene.json", "worksheet.svg"]);
    for buffer in ["frame", "depth"] {
        let key = std::fs::read_to_string(dir.join(format!("out/keys/ana.{buffer}.txt"))).unwrap();
        let rows: Vec<&str> =
            key.lines().filter(|l| !l.starts_with('#') && l.chars().any(|c| c != '0' && c.is_ascii_digit())).collect();
        assert!(!rows.is_empty());
        for (name, bytes) in files_under(&ana) {
            let text = String::from_utf8_lossy(&bytes);
            for row in &rows {
                let row = row.split_whitespace().collect::<Vec<_>>().join(" ");
                assert!(!text.contains(&row), "{name} holds a row of ana's {buffer} key: {row}");
            }
        }
    }
    let template = std::fs::read_to_string(ana.join("ana.frame.txt")).unwrap();
    assert!(template.lines().filter(|l| !l.starts_with('#')).all(|l| l.split(' ').all(|c| c == "?")));
    let hand_in = std::fs::read_to_string(ana.join("hand-in.txt")).unwrap();
    let code = manifest(&dir)["students"][0]["code"].as_str().unwrap().to_string();
    assert!(
        hand_in.starts_with(&format!("Lima, Ana (ana), variant {code}\nHand in 2 files:\n  ana.frame.txt")),
        "{hand_in}"
    );
    assert!(hand_in.contains("https://example.edu/zsim/#scene=") && hand_in.contains("&quiz=depth"), "{hand_in}");
    let svg = std::fs::read_to_string(ana.join("worksheet.svg")).unwrap();
    assert!(
        svg.contains(&format!("Lima, Ana · variant {code}")) && svg.contains("Hand in ana.frame.txt, ana.depth.txt")
    );
    let all = std::fs::read_to_string(dir.join("out/worksheets.html")).unwrap();
    let order: Vec<usize> = ["Lima, Ana", "Chen, Bo", "Østby, Cy", "Diaz, Di"]
        .iter()
        .map(|n| all.find(&format!("<h2>{n}")).unwrap())
        .collect();
    assert!(order.windows(2).all(|w| w[0] < w[1]), "the worksheets in the roster's order");
}

/// Copies `from` to `to` in the class folder.
fn hand(dir: &Path, from: &str, to: &str) {
    std::fs::create_dir_all(dir.join("class")).unwrap();
    std::fs::copy(dir.join(from), dir.join("class").join(to)).unwrap();
}

#[test]
fn each_student_is_graded_against_their_own_key_and_every_odd_file_is_named() {
    let dir = scratch("grade");
    assert_eq!(class(&dir, CANVAS, &[]).code, 0);
    hand(&dir, "out/keys/ana.frame.txt", "ana.frame.txt");
    hand(&dir, "out/keys/ana.depth.txt", "ana.depth.txt");
    // bo hands in ana's sheets: swapped, and graded against bo's own key.
    hand(&dir, "out/keys/ana.frame.txt", "bo.frame.txt");
    hand(&dir, "out/keys/bo.depth.txt", "bo.depth.txt");
    // cy misnames the framebuffer and hands in the depth twice, in two cases.
    hand(&dir, "out/keys/cy.frame.txt", "cy_frame.txt");
    hand(&dir, "out/keys/cy.depth.txt", "cy.depth.txt");
    hand(&dir, "out/keys/cy.depth.txt", "CY.depth.txt");
    // di hands in nothing; eve is not on the roster.
    hand(&dir, "out/keys/ana.frame.txt", "eve.frame.txt");
    let run = zsim_in(Some(&dir), &["grade", "--variants", "out/variants.json", "class", "--format", "json"]);
    assert_eq!(run.code, 1, "{}", run.stderr);
    let json: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    let row = |id: &str| json["students"].as_array().unwrap().iter().find(|s| s["student"] == id).unwrap().clone();
    assert_eq!((row("ana")["score"].as_f64(), row("ana")["status"].as_str()), (Some(100.0), Some("ok")));
    let bo = row("bo");
    assert!(bo["score"].as_f64().unwrap() < 100.0 && bo["frame_wrong"].as_u64().unwrap() > 0, "{bo}");
    let ana_code = manifest(&dir)["students"][0]["code"].as_str().unwrap().to_string();
    assert_eq!(bo["notes"][0], format!("bo.frame.txt carries variant {ana_code}, which is ana's: swapped sheets?"));
    let cy = row("cy");
    let notes: Vec<&str> = cy["notes"].as_array().unwrap().iter().map(|n| n.as_str().unwrap()).collect();
    assert!(notes.contains(&"cy_frame.txt is misnamed and was not graded: name it cy.frame.txt"), "{notes:?}");
    assert!(
        notes.contains(&"two files answer the z-buffer: CY.depth.txt, cy.depth.txt; neither was graded"),
        "{notes:?}"
    );
    assert_eq!((row("di")["score"].as_f64(), row("di")["status"].as_str()), (Some(0.0), Some("missing: di.frame.txt")));
    assert_eq!(json["not_graded"][0], "eve.frame.txt was not graded: nobody on the roster is eve");
    // Every roster row in every gradebook, di with 0.
    let moodle = zsim_in(
        Some(&dir),
        &["grade", "--variants", "out/variants.json", "class", "--format", "moodle", "--identity", "email"],
    );
    assert!(moodle.stdout.lines().any(|l| l == "di,0.00"), "{}", moodle.stdout);
    let canvas = zsim_in(Some(&dir), &["grade", "--variants", "out/variants.json", "class", "--format", "canvas"]);
    assert_eq!(canvas.stdout.lines().count(), 6, "{}", canvas.stdout);
    assert!(canvas.stderr.contains("zsim: eve.frame.txt was not graded"), "{}", canvas.stderr);
    let csv = zsim_in(Some(&dir), &["grade", "--variants", "out/variants.json", "class", "--format", "csv"]);
    assert!(
        csv.stdout.lines().any(|l| l.starts_with("di,") && l.contains(",0.0,missing: di.frame.txt")),
        "{}",
        csv.stdout
    );
}

/// Feedback names the student's own files and scene, never where the teacher keeps them.
#[test]
fn feedback_names_the_students_files_never_the_teachers_paths() {
    let dir = scratch("feedback");
    assert_eq!(class(&dir, CANVAS, &[]).code, 0);
    // bo writes the rows bottom first.
    std::fs::create_dir_all(dir.join("class")).unwrap();
    for buffer in ["frame", "depth"] {
        let key = std::fs::read_to_string(dir.join(format!("out/keys/bo.{buffer}.txt"))).unwrap();
        let mut lines: Vec<&str> = key.lines().filter(|l| !l.starts_with('#')).collect();
        lines.reverse();
        std::fs::write(dir.join(format!("class/bo.{buffer}.txt")), lines.join("\n") + "\n").unwrap();
    }
    let run = zsim_in(Some(&dir), &["grade", "--variants", "out/variants.json", "class", "-o", "feedback"]);
    assert_eq!(run.code, 1, "{}", run.stderr);
    assert!(run.stdout.contains("rows written bottom row first"), "{}", run.stdout);
    let feedback = std::fs::read_to_string(dir.join("feedback/bo.feedback.txt")).unwrap();
    assert!(feedback.starts_with("bo (variant "), "{feedback}");
    assert!(
        feedback.contains("bo.depth.txt") && !feedback.contains("class/") && !feedback.contains("out/"),
        "{feedback}"
    );
    let di = std::fs::read_to_string(dir.join("feedback/di.feedback.txt")).unwrap();
    assert!(di.contains("no file answers this: hand in di.frame.txt"), "{di}");
}

#[test]
fn compare_says_whose_scores_changed_and_why() {
    let dir = scratch("compare");
    assert_eq!(class(&dir, CANVAS, &[]).code, 0);
    hand(&dir, "out/keys/ana.frame.txt", "ana.frame.txt");
    hand(&dir, "out/keys/bo.frame.txt", "bo.frame.txt");
    let grade = |extra: &[&str]| {
        let mut args = vec!["grade", "--variants", "out/variants.json", "class"];
        args.extend(extra);
        zsim_in(Some(&dir), &args)
    };
    std::fs::write(dir.join("before.json"), grade(&["--format", "json"]).stdout).unwrap();
    // ana hands in her z-buffer too; bo's scene is edited in the manifest (a teacher's correction).
    hand(&dir, "out/keys/ana.depth.txt", "ana.depth.txt");
    let text = std::fs::read_to_string(dir.join("out/variants.json")).unwrap();
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    let scene = json["students"][1]["scene"].as_object_mut().unwrap();
    scene.insert("background".into(), serde_json::json!(1));
    std::fs::write(dir.join("out/variants.json"), serde_json::to_string_pretty(&json).unwrap()).unwrap();
    let run = grade(&["--compare", "before.json"]);
    assert!(run.stdout.contains("ana: 50.0 → 100.0: their files changed"), "{}", run.stdout);
    assert!(run.stdout.contains("bo: 50.0 → "), "{}", run.stdout);
    assert!(run.stdout.contains("their scene was changed in the manifest"), "{}", run.stdout);
}

/// A folder laid out as Gradescope lays `/autograder` out: the autograder's
/// files in `source/`, the submitters in `submission_metadata.json`, their
/// files in `submission/`; `run_autograder` run as Gradescope runs it.
#[test]
fn the_gradescope_autograder_finds_each_students_variant_by_sid_then_email() {
    let dir = scratch("gradescope");
    std::fs::write(dir.join("roster.csv"), "Name,Email,SID\nAna Lima,ana@uni.edu,s1\nBo Chen,bo@uni.edu,s2\n").unwrap();
    let run =
        zsim_in(Some(&dir), &["exercise", "--roster", "roster.csv", "-o", "out", "--gradescope", "autograder/source"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let root = dir.join("autograder");
    let grade = |users: &str, files: &[(&str, &str)]| {
        let _ = std::fs::remove_dir_all(root.join("submission"));
        std::fs::create_dir_all(root.join("submission")).unwrap();
        for (from, to) in files {
            std::fs::copy(dir.join(from), root.join("submission").join(to)).unwrap();
        }
        std::fs::write(root.join("submission_metadata.json"), format!("{{\"users\": {users}, \"id\": 1}}")).unwrap();
        run_grader(&root.join("source/run_autograder"), ("AUTOGRADER_ROOT", &root))
    };
    let by_sid = grade(
        r#"[{"email": "ANA.LIMA@other.org", "sid": "s1"}]"#,
        &[("out/keys/ana@uni.edu.frame.txt", "ana@uni.edu.frame.txt"), ("out/keys/ana@uni.edu.depth.txt", "depth.txt")],
    );
    assert_eq!(by_sid["score"], 100.0, "{by_sid}");
    let by_email =
        grade(r#"[{"email": "Bo@Uni.edu", "sid": null}]"#, &[("out/keys/ana@uni.edu.frame.txt", "frame.txt")]);
    assert!(by_email["score"].as_f64().unwrap() < 50.0, "bo is graded against bo's key: {by_email}");
    assert_eq!(by_email["tests"][1]["output"], "no file answers this: hand in depth.txt\n");
    let unknown = grade(r#"[{"email": "eve@uni.edu", "sid": "s9"}]"#, &[]);
    assert_eq!((unknown["score"].as_f64(), unknown["visibility"].as_str()), (Some(0.0), Some("visible")));
    assert!(
        unknown["output"].as_str().unwrap().starts_with("nobody on the class's roster submitted this"),
        "{unknown}"
    );
    let group = grade(r#"[{"email": "ana@uni.edu"}, {"email": "bo@uni.edu"}]"#, &[]);
    assert!(group["output"].as_str().unwrap().starts_with("a group of students with different variants"), "{group}");
}

/// A folder laid out as PrairieLearn lays `/grade` out: the question's
/// `tests/` (the manifest, `run.sh`), `data/data.json` with the variant the
/// question gave, the student's files in `student/`.
#[test]
fn the_prairielearn_grader_scores_the_questions_variant_and_refuses_a_malformed_file_without_cost() {
    let dir = scratch("prairielearn");
    std::fs::write(dir.join("roster.csv"), "UID,UIN,Name\nana@uni.edu,1,Ana\nbo@uni.edu,2,Bo\n").unwrap();
    let run = zsim_in(Some(&dir), &["exercise", "--roster", "roster.csv", "-o", "out", "--prairielearn", "question"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let info: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("question/info.json")).unwrap()).unwrap();
    assert_eq!(info["externalGradingOptions"]["entrypoint"], "/grade/tests/run.sh");
    let code = manifest(&dir)["students"][1]["code"].as_str().unwrap().to_string();
    let root = dir.join("grade");
    std::fs::create_dir_all(root.join("data")).unwrap();
    copy_folder(&dir.join("question/tests"), &root.join("tests"));
    let grade = |files: &[(&str, &str)]| {
        let _ = std::fs::remove_dir_all(root.join("student"));
        std::fs::create_dir_all(root.join("student")).unwrap();
        for (from, to) in files {
            std::fs::copy(dir.join(from), root.join("student").join(to)).unwrap();
        }
        let data =
            format!(r#"{{"params": {{"variant": "{code}"}}, "correct_answers": {{}}, "submitted_answers": {{}}}}"#);
        std::fs::write(root.join("data/data.json"), data).unwrap();
        let bin = Path::new(env!("CARGO_BIN_EXE_zsim")).parent().unwrap();
        let status = std::process::Command::new("bash")
            .arg(root.join("tests/run.sh"))
            .env("GRADE_ROOT", &root)
            .env("PATH", format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default()))
            .status()
            .unwrap();
        assert!(status.success());
        serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(root.join("results/results.json")).unwrap())
            .unwrap()
    };
    let right =
        grade(&[("out/keys/bo@uni.edu.frame.txt", "frame.txt"), ("out/keys/bo@uni.edu.depth.txt", "depth.txt")]);
    assert_eq!((right["gradable"].as_bool(), right["score"].as_f64()), (Some(true), Some(1.0)), "{right}");
    let half = grade(&[("out/keys/bo@uni.edu.frame.txt", "frame.txt")]);
    assert_eq!(half["score"].as_f64(), Some(0.5), "{half}");
    std::fs::write(dir.join("garbage.txt"), "1 2 x\n").unwrap();
    let malformed = grade(&[("garbage.txt", "frame.txt"), ("out/keys/bo@uni.edu.depth.txt", "depth.txt")]);
    assert_eq!(malformed["gradable"], false, "{malformed}");
    assert!(malformed["format_errors"][0].as_str().unwrap().starts_with("frame.txt: line 1"), "{malformed}");
}

/// Runs a platform's grader script as the platform does, `root` standing for
/// its folder (`/autograder`, `/grade`) and this zsim on the path; its results.json.
fn run_grader(script: &Path, (variable, root): (&str, &Path)) -> serde_json::Value {
    let bin = Path::new(env!("CARGO_BIN_EXE_zsim")).parent().unwrap();
    let status = std::process::Command::new("bash")
        .arg(script)
        .env(variable, root)
        .env("PATH", format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default()))
        .status()
        .unwrap();
    assert!(status.success());
    serde_json::from_str(&std::fs::read_to_string(root.join("results/results.json")).unwrap()).unwrap()
}

fn copy_folder(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, to.join(path.file_name().unwrap())).unwrap();
    }
}

/// Each shape of roster through the command line, and a bad one refused in
/// one line naming the file and the line.
#[test]
fn rosters_of_each_platform_are_read_and_bad_ones_refused_naming_the_line() {
    let dir = scratch("rosters");
    let shapes = [
        ("moodle", "First name,Last name,ID number,Email address\nAna,Lima,1001,ana@uni.edu\n", "ana@uni.edu"),
        ("canvas", CANVAS, "ana"),
        ("gradescope", "Name,Email,SID\nAna Lima,ana@uni.edu,s1\n", "ana@uni.edu"),
        ("prairielearn", "UID,UIN,Name\nana@uni.edu,1001,Ana Lima\n", "ana@uni.edu"),
        ("plain", "ana@uni.edu\n", "ana@uni.edu"),
    ];
    for (shape, text, first) in shapes {
        let folder = dir.join(shape);
        std::fs::create_dir_all(&folder).unwrap();
        let run = class(&folder, text, &["--polygons", "2"]);
        assert_eq!(run.code, 0, "{shape}: {}", run.stderr);
        let manifest = manifest(&folder);
        assert_eq!(
            (manifest["roster"].as_str(), manifest["students"][0]["identity"].as_str()),
            (Some(shape), Some(first))
        );
    }
    let refused = [
        ("Name,Email,SID\nAna,ana@uni.edu,1\nBo,,2\n", "zsim: roster.csv: line 3: the student's Email is empty"),
        (
            "Name,Email,SID\nAna,ana@uni.edu,1\nAna,Ana@Uni.edu,2\n",
            "zsim: roster.csv: line 3: Ana@Uni.edu is on the roster already (line 2); gradebooks match identities without letter case",
        ),
        (
            "Given,Family\nAna,Lima\n",
            "zsim: roster.csv: line 1: not a roster zsim knows: its columns are \"Given\", \"Family\"; give Moodle's, Canvas's, Gradescope's or PrairieLearn's export, or one identity a line",
        ),
    ];
    for (text, error) in refused {
        let run = class(&dir, text, &[]);
        assert_eq!((run.code, run.stderr.trim()), (2, error));
    }
    assert!(!dir.join("out").exists(), "nothing written for a refused roster");
}

/// The Safety chapter's limits on a roster, just below and just above.
#[test]
fn a_roster_of_the_most_students_is_read_and_one_more_is_refused() {
    use zsim::course::roster::{Unusable, parse};
    let most = crate::limits::stated("Students on a roster").count();
    let text: String = (0..most).map(|k| format!("s{k}@uni.edu\n")).collect();
    assert_eq!(parse(&text, None).unwrap().students.len(), most);
    let more = format!("{text}s{most}@uni.edu\n");
    assert_eq!(parse(&more, None), Err(Unusable::TooMany { max: most }));
    let longest = crate::limits::stated("A student's identity").count();
    let name = "é".repeat(longest / 2);
    assert_eq!(parse(&format!("{name}\n"), None).unwrap().students[0].identity.len(), longest);
    assert_eq!(parse(&format!("{name}a\n"), None), Err(Unusable::Unnameable { line: 1, identity: format!("{name}a") }));
}

/// Found at a course's scale: a class writes a folder a student, and every
/// folder's handle stayed open until the last file was placed, so a class of
/// 1,100 students stopped at a common limit of 1,024 descriptors ("Too many
/// open files"). 80 students are written under a limit of 64.
#[test]
fn a_class_of_more_folders_than_open_descriptors_is_written() {
    let dir = scratch("descriptors");
    let roster: String = (1..=80).map(|k| format!("s{k:03}\n")).collect();
    std::fs::write(dir.join("roster.txt"), roster).unwrap();
    let output = std::process::Command::new("bash")
        .args(["-c", "ulimit -n 64 && exec \"$0\" \"$@\"", env!("CARGO_BIN_EXE_zsim")])
        .args([
            "exercise",
            "--roster",
            "roster.txt",
            "--polygons",
            "1",
            "--hard",
            "",
            "--rules",
            "truncated",
            "-o",
            "out",
        ])
        .current_dir(&dir)
        .env("LANG", "C.UTF-8")
        .output()
        .unwrap();
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    assert_eq!(std::fs::read_dir(dir.join("out/students")).unwrap().count(), 80);
}
