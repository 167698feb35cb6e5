//! `zsim run`: text, `--final`, `--axes`, `--format json` and `--format none`.

use crate::{scene_file, snapshot, zsim, zsim_in};

#[test]
fn json_has_one_step_per_polygon_top_row_first() {
    let run = zsim(&["run", "examples/rogers.json", "--format", "json"]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    let json: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    let keys: Vec<&str> = json.as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(keys, ["effects", "height", "steps", "width"]);
    assert_eq!(json["width"], 32);
    assert_eq!(json["height"], 32);
    assert_eq!(json["effects"], serde_json::json!([]));
    let steps = json["steps"].as_array().unwrap();
    assert_eq!(steps.len(), 2);
    assert_eq!(steps[0]["polygon"], "rectangle");
    assert_eq!(steps[1]["polygon"], "triangle");
    // Row 0 of the output is y = 31; pixel (20, 15) is in row 31 − 15 = 16.
    assert_eq!(steps[1]["frame"][16][20], 2);
    assert_eq!(steps[1]["depth"][16][20], 11);
    assert_eq!(steps[1]["depth"].as_array().unwrap().len(), 32);
}

#[test]
fn json_lists_the_effects_simulated_and_keeps_steps_that_draw_nothing() {
    let (dir, name) = scene_file(
        "section_and_edge_on.json",
        r#"{"width": 8, "height": 8, "effects": {"section": 12},
            "polygons": [{"name": "wall", "value": 1, "vertices": [[2,0,0],[2,8,0],[2,8,9],[2,0,9]]},
                         {"name": "floor", "value": 2, "vertices": [[0,0,10],[8,0,10],[8,8,10],[0,8,10]]}]}"#,
    );
    let run = zsim_in(Some(&dir), &["run", &name, "--format", "json"]);
    let json: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    assert_eq!(json["effects"], serde_json::json!(["section"]));
    assert_eq!(json["steps"][0]["polygon"], "wall");
    assert_eq!(json["steps"][0]["frame"], serde_json::json!(vec![vec![0; 8]; 8]));
    assert_eq!(json["steps"][1]["frame"], serde_json::json!(vec![vec![2; 8]; 8]));
}

#[test]
fn final_prints_only_the_last_state() {
    let run = zsim(&["run", "examples/rogers.json", "--final"]);
    assert_eq!(run.code, 0);
    assert_eq!(run.stdout.matches("framebuffer after").count(), 1);
    assert!(run.stdout.contains("framebuffer after polygon 2 \"triangle\""));
    let json = zsim(&["run", "examples/rogers.json", "--final", "--format", "json"]);
    let json: serde_json::Value = serde_json::from_str(&json.stdout).unwrap();
    assert_eq!(json["steps"].as_array().unwrap().len(), 1);
}

#[test]
fn format_none_prints_one_summary_line() {
    let run = zsim(&["run", "examples/rogers.json", "--format", "none"]);
    assert_eq!(run.code, 0);
    assert_eq!(run.stdout.lines().count(), 1);
    // The times differ from run to run: check their form, snapshot the rest.
    let (counts, times) = run.stdout.split_once("; read ").expect("the summary ends with the times");
    let shape = times.trim_end().replace(|c: char| c.is_ascii_digit(), "9");
    assert!(
        shape.starts_with("9")
            && shape.contains(" ms, buffers made 9.9 ms, rasterized ")
            && shape.contains(" M pixels/s); "),
        "{times}"
    );
    // 32×32 cells: a byte each for the 2-bit framebuffer, 4 bytes each for
    // the depth levels; the scene and the peak are measured.
    let memory = times.split_once("; memory: ").expect("the times end with the memory").1;
    assert!(memory.starts_with("buffers 5.0 KiB, scene "), "{memory}");
    if cfg!(target_os = "linux") {
        // A tiny scene: the peak without a ratio (the program is most of it).
        let peak = memory.split_once("peak resident ").expect("Linux tells the peak").1;
        assert!(peak.trim_end().ends_with(" MiB") && !peak.contains('×'), "{peak}");
    }
    snapshot!("run_rogers_none", format!("{counts}\n"));
}

/// A scene without polygons is drawn (nothing happens) and says so, showing
/// the buffers as cleared, rather than printing its header alone.
#[test]
fn an_empty_scene_says_so_and_shows_the_cleared_buffers() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("empty-scene");
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("empty.json");
    std::fs::write(&scene, r#"{"width": 4, "height": 3, "depth_bits": 4, "depth_test": "less", "polygons": []}"#)
        .unwrap();
    let run = zsim(&["run", scene.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    let (_, shown) = run.stdout.split_once("effects: none\n").expect("the header");
    assert_eq!(
        shown,
        "\nthe scene has no polygons: the buffers stay as cleared\n\nframebuffer, cleared:\n0 0 0 0\n0 0 0 0\n0 0 0 0\n\nz-buffer, cleared:\n15 15 15 15\n15 15 15 15\n15 15 15 15\n"
    );
}

/// `--final` and `--after` draw on every core (tiles on threads, then the
/// last polygon alone for its counts) and print the same bytes as one thread
/// drawing polygon by polygon, in text and JSON.
#[test]
fn final_and_after_print_the_same_bytes_on_any_number_of_threads() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("final-threads");
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("scene.json");
    let random =
        zsim(&["random", "--count", "3000", "--width", "96", "--height", "80", "--max-size", "20", "--seed", "5"]);
    std::fs::write(&scene, random.stdout).unwrap();
    let scene = scene.to_str().unwrap();
    for shown in [
        &["--final"][..],
        &["--after", "1717"],
        &["--final", "--format", "json"],
        &["--after", "2", "--format", "json"],
    ] {
        let one = zsim(&[&["run", scene, "--threads", "1"], shown].concat());
        assert_eq!((one.code, one.stderr.as_str()), (0, ""), "{shown:?}");
        assert!(one.stdout.len() > 96 * 80, "{shown:?}: the buffers are printed");
        for threads in
            [&["--threads", "2"][..], &["--threads", "3", "--tile", "8"], &["--threads", "1", "--tile", "16"], &[]]
        {
            let run = zsim(&[&["run", scene], shown, threads].concat());
            assert_eq!((run.code, run.stderr.as_str()), (0, ""), "{shown:?} {threads:?}");
            assert!(run.stdout == one.stdout, "{shown:?} {threads:?}: the output differs from one thread's");
        }
    }
}

#[test]
fn format_none_says_how_many_threads_drew() {
    let drew = |args: &[&str]| {
        let run = zsim(&[&["run", "examples/rogers.json", "--format", "none"], args].concat());
        assert_eq!((run.code, run.stderr.as_str()), (0, ""));
        let (_, after) = run.stdout.split_once(" ms on ").expect("the summary names the threads");
        after.split_once(" (").expect("then the rate").0.to_string()
    };
    assert_eq!(drew(&["--threads", "1"]), "1 thread", "one thread, polygon by polygon");
    assert_eq!(drew(&["--threads", "1", "--tile", "8"]), "1 thread");
    assert_eq!(drew(&["--threads", "3", "--tile", "8"]), "3 threads");
    assert_eq!(drew(&["--threads", "2"]), "2 threads", "tiles of 256 by default");
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    let all = drew(&[]);
    assert_eq!(
        all,
        if cores == 1 { "1 thread".to_string() } else { format!("{cores} threads") },
        "all cores by default"
    );
    // A scene with a per-pixel effect runs the general loop, on one thread, and says so.
    let run = zsim(&["run", "examples/section.json", "--format", "none", "--threads", "2"]);
    assert!(run.stdout.contains(" ms on 1 thread ("), "{}", run.stdout);
}

#[test]
fn axes_label_rows_and_columns() {
    let run = zsim(&["run", "examples/rogers.json", "--final", "--axes"]);
    assert_eq!(run.code, 0);
    snapshot!("run_rogers_final_axes", run.stdout);
}

/// Regression: `--format json` built every step in memory before writing, so a large
/// scene ran out of memory (and `| head` could not stop it). Steps now stream, and a
/// closed pipe ends the run quietly with status 0.
#[test]
fn json_streams_and_stops_quietly_on_a_closed_pipe() {
    use std::io::Read;
    use std::process::{Command, Stdio};
    let spec =
        zsim::RandomScene { count: 400, seed: 5, width: 512, height: 512, max_size: 64, frame_bits: 8, depth_bits: 16 };
    let (dir, name) = scene_file("many_steps.json", &spec.json());
    let mut child = Command::new(env!("CARGO_BIN_EXE_zsim"))
        .args(["run", &name, "--format", "json"])
        .current_dir(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 64];
    child.stdout.as_mut().unwrap().read_exact(&mut first).unwrap();
    assert!(first.starts_with(br#"{"width":512,"height":512,"effects":[],"steps":[{"polygon":"t1""#));
    drop(child.stdout.take());
    let output = child.wait_with_output().unwrap();
    assert_eq!(output.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&output.stderr), "");
}

/// Found by a new user: an antialiased scene's JSON held floats (`2.5`, `4.0`).
#[test]
fn json_holds_exact_values_as_integers_or_fraction_strings() {
    let run = zsim(&["run", "examples/antialias.json", "--format", "json", "--final"]);
    // The shape of `run --format json`, averaged cells as exact values.
    snapshot!("run_json_antialias_final", run.stdout);
    let json: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    let frame = &json["steps"][0]["frame"];
    // Row y = 4 (second from the top): 1 1 5/2 3/2 1 1 1 1.
    assert_eq!(frame[1], serde_json::json!([1, 1, "5/2", "3/2", 1, 1, 1, 1]));
    let cells = json["steps"][0]["depth"]
        .as_array()
        .unwrap()
        .iter()
        .chain(frame.as_array().unwrap())
        .flat_map(|r| r.as_array().unwrap().clone());
    assert!(
        cells.clone().all(|v| v.is_u64() || v.as_str().is_some_and(|s| s.contains('/'))),
        "integers or fractions only"
    );
}

/// Found by a new user: a missing comma was reported as `?: not valid JSON: … at line 3 column 3`.
#[test]
fn a_missing_comma_is_placed_where_it_belongs() {
    let (dir, name) =
        crate::scene_file("missing_comma.json", "{\n  \"width\": 4, \"height\": 3\n  \"polygons\": []\n}\n");
    let run = crate::zsim_in(Some(&dir), &["run", &name]);
    assert_eq!(run.code, 2);
    assert_eq!(
        run.stderr,
        "zsim: missing_comma.json: not valid JSON: `,` or `}` was expected (line 3, column 3) (a comma is missing at the end of line 2)\n"
    );
}

#[test]
fn run_after_a_polygon_and_from_standard_input() {
    let after = zsim(&["run", "examples/rogers.json", "--after", "rectangle"]);
    assert_eq!(after.code, 0);
    assert_eq!(after.stdout.matches("\npolygon ").count(), 1, "only the state after polygon 1");
    assert!(after.stdout.contains("framebuffer after polygon 1 \"rectangle\":"));
    let final_only = zsim(&["run", "examples/rogers.json", "--final"]);
    assert_eq!(final_only.stdout.matches("\npolygon ").count(), 1, "--final prints the last heading only");
    // `-` reads the scene from standard input.
    let stdout =
        crate::zsim_stdin(&["run", "-", "--final"], &std::fs::read_to_string("examples/rogers.json").unwrap()).stdout;
    assert_eq!(stdout.replacen("scene -:", "scene examples/rogers.json:", 1), final_only.stdout);
}

/// `run --format none` said "1 polygons" for a scene of one polygon.
#[test]
fn format_none_counts_one_polygon_in_the_singular() {
    let (dir, name) = crate::scene_file(
        "one_polygon.json",
        r#"{"polygons": [{"value": 1, "vertices": [[0, 0, 1], [4, 0, 1], [0, 4, 1]]}]}"#,
    );
    let run = crate::zsim_in(Some(&dir), &["run", &name, "--format", "none", "--lang", "en"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(
        run.stdout.starts_with(&format!("{name}: 1 polygon, 10 pixel centres tested, 10 written;")),
        "{}",
        run.stdout
    );
}

/// `run --help` named four of the five presets `--compare-rules` takes
/// (tinyrenderer was missing): it names every one, each read back as itself.
#[test]
fn compare_rules_help_names_every_preset() {
    let help = zsim(&["run", "--help"]).stdout;
    let line = help.lines().find(|l| l.contains("--compare-rules")).unwrap();
    let text = &help[help.find(line).unwrap()..];
    let text = &text[..text.find("\n\n").unwrap_or(text.len())];
    for preset in zsim::Preset::ALL {
        assert!(text.contains(preset.key()), "--compare-rules' help names {}: {text}", preset.key());
        assert_eq!(zsim::Preset::parse(preset.key()), Ok(preset));
    }
}

/// Found by a teacher: the man pages' examples named `examples/rogers.json`,
/// which does not exist where the package installs them; they name the
/// installed examples, `/usr/share/doc/zsim/examples/` (`.ci/package` runs one
/// after installing the package).
#[test]
fn the_man_pages_examples_name_the_installed_examples() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("man-pages");
    let _ = std::fs::remove_dir_all(&dir);
    let run = crate::zsim(&["manual", "--dir", dir.to_str().unwrap()]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let page = std::fs::read_to_string(dir.join("zsim-run.1")).unwrap();
    let examples = page.split(".SH EXAMPLES").nth(1).expect("an EXAMPLES section");
    assert!(examples.contains("zsim run /usr/share/doc/zsim/examples/rogers.json"), "{examples}");
    assert!(!examples.contains(" examples/"), "{examples}");
}
