//! Every limit the guide's Safety chapter states, tested just below and just
//! above, with the peak memory of the run just below measured where the limit
//! bounds memory. The tests take each value and figure from the chapter's
//! table ("The limits, tested"), so the chapter says what they hold; a test
//! here checks that each row names a test that reads it.

use std::path::{Path, PathBuf};

use crate::zsim;

/// The chapter the limits are stated in.
const CHAPTER: &str = "docs/src/safety.md";

/// One row of the Safety chapter's table of limits.
#[derive(Debug, Clone)]
pub struct Stated {
    /// The limit, as the table names it.
    pub limit: String,
    /// Its value (the column's number).
    pub value: u64,
    /// The peak the run just below it is held under, in KiB, where the table gives one.
    pub peak_kib: Option<i64>,
    /// The test that holds it.
    pub test: String,
}

impl Stated {
    /// The value as a `usize`.
    pub fn count(&self) -> usize {
        usize::try_from(self.value).unwrap()
    }

    /// Checks a measured peak (KiB, as GNU time gives it) against the table's.
    pub fn hold_peak(&self, peak_kib: i64) {
        let bound = self.peak_kib.unwrap_or_else(|| panic!("the table gives no peak for {}", self.limit));
        // Said on the terminal past the harness's capture, for the design notes.
        use std::io::Write;
        let _ = writeln!(std::io::stderr(), "PEAK: {}: {peak_kib} KiB (held under {bound} KiB)", self.limit);
        assert!(
            peak_kib < bound,
            "{}: peaked at {peak_kib} KiB, over the {bound} KiB the Safety chapter states",
            self.limit
        );
    }
}

/// A number as the chapter writes it (`67,108,864 bytes`, `1,000 MiB`): its
/// first run of digits and commas.
fn number(text: &str) -> Option<u64> {
    let start = text.find(|c: char| c.is_ascii_digit())?;
    let digits: String =
        text[start..].chars().take_while(|c| c.is_ascii_digit() || *c == ',').filter(|c| *c != ',').collect();
    digits.parse().ok()
}

/// The rows of the chapter's table of limits.
pub fn table() -> Vec<Stated> {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(CHAPTER)).unwrap();
    let section = text.split("## The limits, tested").nth(1).expect("the Safety chapter's table of limits");
    section
        .lines()
        .filter(|line| line.starts_with("| ") && !line.starts_with("| Limit |"))
        .map(|line| {
            let columns: Vec<&str> = line.trim_matches('|').split(" | ").map(str::trim).collect();
            assert_eq!(columns.len(), 6, "a row of six columns: {line}");
            let value = number(columns[1]).unwrap_or_else(|| panic!("no value in {line}"));
            let peak_kib = number(columns[4]).map(|mib| i64::try_from(mib).unwrap() * 1024);
            Stated { limit: columns[0].to_string(), value, peak_kib, test: columns[5].trim_matches('`').to_string() }
        })
        .collect()
}

/// The row of the limit named `limit`.
pub fn stated(limit: &str) -> Stated {
    table().into_iter().find(|row| row.limit == limit).unwrap_or_else(|| panic!("no row for {limit:?} in {CHAPTER}"))
}

/// The peak resident memory of one run of the binary, in KiB, as GNU time
/// (`/usr/bin/time -f %M`) reports it. Not from this process's own `wait4`:
/// a child spawned from the test harness starts as a copy of it, and the
/// kernel counts the harness's resident memory at the spawn (lavapipe and the
/// other tests' buffers, 276 MB in one full run) as the child's peak; GNU
/// time is small when it starts zsim.
pub fn peak_kib(args: &[&str]) -> (i32, i64) {
    let (code, kib, _) = timed(args, Kept::Neither);
    (code, kib)
}

/// [`peak_kib`], and what the run wrote on its standard output.
pub fn measured(args: &[&str]) -> (i32, i64, String) {
    timed(args, Kept::Output)
}

/// [`peak_kib`], and what the run wrote on its standard error (one line or
/// so: a refusal), for a run too long to make twice.
pub fn measured_refusal(args: &[&str]) -> (i32, i64, String) {
    timed(args, Kept::Errors)
}

/// Which of a run's streams is kept; the others are thrown away unread
/// (some runs write hundreds of megabytes).
#[derive(Clone, Copy, PartialEq)]
enum Kept {
    Neither,
    Output,
    Errors,
}

/// A run under GNU time, with the stream `keep` says.
fn timed(args: &[&str], keep: Kept) -> (i32, i64, String) {
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let run = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let report = std::env::temp_dir().join(format!("zsim-peak-{}-{run}", std::process::id()));
    let output = std::process::Command::new("/usr/bin/time")
        .args(["-f", "%M", "-o"])
        .arg(&report)
        .arg(env!("CARGO_BIN_EXE_zsim"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(if keep == Kept::Output { std::process::Stdio::piped() } else { std::process::Stdio::null() })
        .stderr(if keep == Kept::Errors { std::process::Stdio::piped() } else { std::process::Stdio::null() })
        .output()
        .expect("GNU time (/usr/bin/time, Debian's time package; .ci/run installs it)");
    let text = std::fs::read_to_string(&report).unwrap();
    let _ = std::fs::remove_file(&report);
    let kib = text.lines().last().and_then(|l| l.trim().parse().ok()).unwrap_or_else(|| panic!("time said {text:?}"));
    let kept = if keep == Kept::Errors { &output.stderr } else { &output.stdout };
    (output.status.code().unwrap_or(-1), kib, String::from_utf8_lossy(kept).into_owned())
}

/// An empty scratch folder of its own.
fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("limits").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn path(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Each row of the table names a test that exists and reads that row, so
/// no figure in the chapter is one no test holds.
#[test]
fn each_limit_in_the_safety_chapter_names_a_test_that_reads_it() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut sources = String::new();
    let mut folders = vec![root.join("tests"), root.join("src")];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(folder).unwrap() {
            let file = entry.unwrap().path();
            if file.is_dir() {
                folders.push(file);
            } else if file.extension().is_some_and(|e| e == "rs") {
                sources.push_str(&std::fs::read_to_string(&file).unwrap());
                sources.push('\n');
            }
        }
    }
    let rows = table();
    assert!(rows.len() >= 20, "{} rows", rows.len());
    for row in rows {
        let start = sources.find(&format!("fn {}(", row.test)).unwrap_or_else(|| panic!("no test {}", row.test));
        let body = &sources[start..];
        let end = body[3..].find("\nfn ").or_else(|| body[3..].find("\n#[test]")).map_or(body.len(), |e| e + 3);
        assert!(
            body[..end].contains(&format!("stated({:?})", row.limit)),
            "{} does not read the row {:?}",
            row.test,
            row.limit
        );
    }
}

/// A scene of exactly the largest size a file may have, of as many
/// polygons as it holds, is read and run; one byte more is refused before it
/// is read, in one line.
#[test]
fn a_file_of_the_largest_size_is_read_and_one_byte_more_is_refused() {
    let limit = stated("A file zsim reads");
    let dir = scratch("largest-file");
    // The most polygons a file of the limit's size holds: the shortest triangles JSON writes.
    let one = r#"{"value":1,"vertices":[[0,0,1],[1,0,1],[0,1,1]]}"#;
    let head = r#"{"width":32,"height":32,"polygons":["#;
    let count = (limit.count() - head.len() - 2) / (one.len() + 1);
    let text = format!("{head}{}]}}", vec![one; count].join(","));
    let padded = format!("{text}{}", " ".repeat(limit.count() - text.len()));
    let scene = dir.join("tiny.json");
    std::fs::write(&scene, &padded).unwrap();
    let (code, peak, report) = measured(&["run", path(&scene), "--format", "none", "--lang", "en"]);
    assert_eq!(code, 0);
    limit.hold_peak(peak);
    assert!(report.contains(&format!(": {count} polygons, ")), "{report}");
    std::fs::write(&scene, padded + " ").unwrap();
    let run = zsim(&["run", path(&scene)]);
    assert_eq!((run.code, run.stdout.as_str(), run.stderr.lines().count()), (2, "", 1), "{}", run.stderr);
    assert!(run.stderr.contains(&format!("({} MiB)", limit.value >> 20)), "{}", run.stderr);
}

/// A 4096 × 4096 texture (the most pixels an image may declare) is decoded
/// and drawn; one row more is refused from its header, before decoding.
#[test]
fn an_image_of_the_largest_declared_size_is_drawn_and_one_row_more_is_refused() {
    let limit = stated("An image's declared pixels");
    let dir = scratch("largest-image");
    let side = (limit.value as f64).sqrt() as u32;
    assert_eq!(u64::from(side) * u64::from(side), limit.value);
    for (name, height) in [("t.png", side), ("taller.png", side + 1)] {
        let mut bytes = Vec::new();
        let mut encoder = png::Encoder::new(&mut bytes, side, height);
        encoder.set_color(png::ColorType::Grayscale);
        let pixels: Vec<u8> = (0..side as usize * height as usize).map(|i| (i % 251) as u8).collect();
        encoder.write_header().unwrap().write_image_data(&pixels).unwrap();
        std::fs::write(dir.join(name), bytes).unwrap();
    }
    let case = |texture: &str| {
        let file = dir.join(format!("{texture}.txt"));
        std::fs::write(
            &file,
            format!(
                "png 8 8 out.png\ntexture {texture}\ntexcoord 2 0 0  1 0  0 1\nposition 2 -1 -1  1 -1  -1 1\ndrawArraysTriangles 0 3\n"
            ),
        )
        .unwrap();
        file
    };
    let out = dir.join("out");
    let (code, peak) = peak_kib(&["cs418", "run", path(&case("t.png")), "-o", path(&out)]);
    assert_eq!(code, 0);
    limit.hold_peak(peak);
    let run = zsim(&["cs418", "run", path(&case("taller.png")), "-o", path(&dir.join("out2"))]);
    assert_eq!((run.code, run.stderr.lines().count()), (2, 1), "{}", run.stderr);
    assert!(run.stderr.contains(&format!("declares {side} × {} pixels", side + 1)), "{}", run.stderr);
}

/// A CS 418 case's textures together hold at most as many pixels as one
/// largest image: 4096 × 4095 and 4096 × 1 together are decoded and drawn
/// within the one image's peak; a third texture of one pixel more is refused
/// from its header, naming the case's line (found by a maintainer: four
/// different 4096² textures peaked at 2.37 GB).
#[test]
fn a_cs418_cases_textures_hold_the_most_pixels_together_and_one_more_is_refused() {
    let limit = stated("A CS 418 case's textures together");
    let one = stated("An image's declared pixels");
    assert_eq!(limit.value, one.value, "together, as many as one largest image");
    let dir = scratch("textures-together");
    let side = (limit.value as f64).sqrt() as u32;
    for (name, width, height) in [("big.png", side, side - 1), ("row.png", side, 1), ("dot.png", 1, 1)] {
        let mut bytes = Vec::new();
        let mut encoder = png::Encoder::new(&mut bytes, width, height);
        encoder.set_color(png::ColorType::Grayscale);
        let pixels: Vec<u8> = (0..width as usize * height as usize).map(|i| (i % 251) as u8).collect();
        encoder.write_header().unwrap().write_image_data(&pixels).unwrap();
        std::fs::write(dir.join(name), bytes).unwrap();
    }
    let draw = "texcoord 2 0 0  1 0  0 1\nposition 2 -1 -1  1 -1  -1 1\ndrawArraysTriangles 0 3\n";
    let case = |name: &str, textures: &[&str]| {
        let file = dir.join(name);
        let body: String = textures.iter().map(|t| format!("texture {t}\n{draw}")).collect();
        std::fs::write(&file, format!("png 8 8 out.png\n{body}")).unwrap();
        file
    };
    let together = case("together.txt", &["big.png", "row.png"]);
    let (code, peak) = peak_kib(&["cs418", "run", path(&together), "-o", path(&dir.join("out"))]);
    assert_eq!(code, 0);
    limit.hold_peak(peak);
    let more = case("more.txt", &["big.png", "row.png", "dot.png"]);
    let run = zsim(&["cs418", "run", path(&more), "-o", path(&dir.join("out2"))]);
    assert_eq!((run.code, run.stderr.lines().count()), (2, 1), "{}", run.stderr);
    assert!(
        run.stderr.contains(&format!("would hold {} pixels together with this one", limit.value + 1)),
        "{}",
        run.stderr
    );
    assert!(run.stderr.contains("more.txt"), "the case is named: {}", run.stderr);
}

/// A token in an error is quoted whole up to the limit; one character more
/// and it is cut to its first 32 characters and its length.
#[test]
fn a_token_is_quoted_whole_up_to_its_limit_then_cut() {
    let limit = stated("A token quoted whole");
    let scene = |token: &str| {
        format!(r#"{{"polygons": [{{"value": 1, "vertices": [["{token}", 0, 1], [8, 0, 1], [0, 8, 1]]}}]}}"#)
    };
    let dir = scratch("token");
    let file = dir.join("s.json");
    let whole = format!("{}x", "7".repeat(limit.count() - 1));
    std::fs::write(&file, scene(&whole)).unwrap();
    let run = zsim(&["run", path(&file)]);
    assert!(run.stderr.contains(&format!("\"{whole}\" is not a number")), "{}", run.stderr);
    let longer = format!("{}x", "7".repeat(limit.count()));
    std::fs::write(&file, scene(&longer)).unwrap();
    let run = zsim(&["run", path(&file)]);
    assert_eq!(run.code, 2);
    assert!(
        run.stderr.contains(&format!("\"{}… ({} characters)\" is not a number", "7".repeat(32), limit.value + 1)),
        "{}",
        run.stderr
    );
}

/// An output whose name is as long as file systems hold is written; one
/// byte more is refused in one line and nothing is written.
#[test]
fn an_output_name_as_long_as_file_systems_hold_is_written() {
    let limit = stated("An output's name");
    let dir = scratch("long-name");
    let name = format!("{}.svg", "n".repeat(limit.count() - 4));
    let run = zsim(&["figure", "examples/rogers.json", "-o", path(&dir.join(&name))]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert!(std::fs::read_to_string(dir.join(&name)).unwrap().starts_with("<svg"));
    let longer = format!("n{name}");
    let run = zsim(&["figure", "examples/rogers.json", "-o", path(&dir.join(&longer))]);
    assert_eq!((run.code, run.stderr.lines().count()), (2, 1), "{}", run.stderr);
    assert!(run.stderr.contains(&format!("({} bytes)", limit.value)), "{}", run.stderr);
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(left, [std::ffi::OsString::from(&name)]);
}

/// A scene of `width` × `height` whose one triangle covers the raster's
/// lower left half, with `extra` as more of its settings.
fn half_covered(width: u32, height: u32, extra: &str) -> String {
    format!(
        r#"{{"width": {width}, "height": {height}{extra}, "polygons": [{{"value": 1, "vertices": [[0, 0, 3], [{width}, 0, 7], [0, {height}, 11]]}}]}}"#
    )
}

/// The first wrong cells of an answer are explained one by one; past the
/// limit the rest are counted.
#[test]
fn the_first_wrong_cells_are_explained_and_the_rest_counted() {
    let limit = stated("Wrong cells explained");
    let dir = scratch("explained");
    let (width, height) = (100, (limit.count() + 1).div_ceil(100) as u32 + 1);
    let scene = dir.join("s.json");
    std::fs::write(&scene, half_covered(width, height, "")).unwrap();
    let right = zsim(&["run", path(&scene), "--final", "--format", "json"]);
    let json: serde_json::Value = serde_json::from_str(&right.stdout).unwrap();
    let frame: Vec<Vec<u64>> = serde_json::from_value(json["steps"][0]["frame"].clone()).unwrap();
    for (wrong, more) in [(limit.count(), None), (limit.count() + 1, Some("… and 1 more cell differs, not listed"))] {
        // The first `wrong` cells, top row first, answered 0 for 1 and 1 for 0.
        let rows: Vec<String> = frame
            .iter()
            .enumerate()
            .map(|(y, row)| {
                let cell =
                    |(x, v): (usize, &u64)| if y * 100 + x < wrong { (1 - v).to_string() } else { v.to_string() };
                row.iter().enumerate().map(cell).collect::<Vec<_>>().join(" ")
            })
            .collect();
        let answer = dir.join(format!("a{wrong}.frame.txt"));
        std::fs::write(&answer, rows.join("\n") + "\n").unwrap();
        let run = zsim(&["check", path(&scene), "--frame", path(&answer)]);
        assert_eq!(run.code, 1, "{}", run.stderr);
        assert!(run.stdout.contains(&format!("{wrong} of {} cells differ", width * height)), "{}", &run.stdout[..300]);
        match more {
            None => assert!(!run.stdout.contains("not listed"), "{}", run.stdout.lines().last().unwrap()),
            Some(more) => assert!(run.stdout.contains(more), "{}", run.stdout.lines().last().unwrap()),
        }
    }
}

/// An answer written bottom row first is told so on a raster of the limit's
/// cells; on one row more it is checked cell by cell without looking.
#[test]
fn misreadings_are_looked_for_up_to_their_limit() {
    let limit = stated("Misreadings looked for");
    let dir = scratch("misreadings");
    let side = (limit.value as f64).sqrt() as u32;
    assert_eq!(u64::from(side) * u64::from(side), limit.value);
    for (height, hinted) in [(side, true), (side + 1, false)] {
        let scene = dir.join(format!("s{height}.json"));
        std::fs::write(&scene, half_covered(side, height, "")).unwrap();
        let right = zsim(&["run", path(&scene), "--final", "--format", "json"]);
        let json: serde_json::Value = serde_json::from_str(&right.stdout).unwrap();
        // The framebuffer's rows, top first, written bottom row first.
        let rows: Vec<String> = json["steps"][0]["frame"]
            .as_array()
            .unwrap()
            .iter()
            .rev()
            .map(|row| row.as_array().unwrap().iter().map(|v| v.to_string()).collect::<Vec<_>>().join(" "))
            .collect();
        let answer = dir.join(format!("a{height}.frame.txt"));
        std::fs::write(&answer, rows.join("\n") + "\n").unwrap();
        let args = ["check", path(&scene), "--frame", path(&answer)];
        let run = zsim(&args);
        assert_eq!(run.code, 1, "{}", run.stderr);
        assert_eq!(run.stdout.contains("hint: read bottom row first, it matches"), hinted, "{height} rows");
        if hinted {
            let (_, peak) = peak_kib(&args);
            limit.hold_peak(peak);
        }
    }
}

/// A raster of the most pixels a scene may have is drawn (a triangle over
/// half of it); one row more is refused at its setting.
#[test]
fn a_raster_of_the_most_pixels_is_drawn_and_one_row_more_is_refused() {
    let (limit, side) = (stated("A scene's raster"), stated("A raster's side"));
    let dir = scratch("largest-raster");
    let width = u32::try_from(side.value).unwrap();
    // The longest side, on a raster one pixel high; one more refused.
    let thin = dir.join("thin.json");
    std::fs::write(&thin, half_covered(width, 1, "")).unwrap();
    assert_eq!(zsim(&["run", path(&thin), "--format", "none"]).code, 0);
    std::fs::write(&thin, half_covered(width + 1, 1, "")).unwrap();
    let run = zsim(&["run", path(&thin), "--format", "none"]);
    assert_eq!((run.code, run.stderr.lines().count()), (2, 1), "{}", run.stderr);
    assert!(run.stderr.contains(&side.value.to_string()), "{}", run.stderr);
    let height = u32::try_from(limit.value / u64::from(width)).unwrap();
    assert_eq!(u64::from(width) * u64::from(height), limit.value);
    let scene = dir.join("s.json");
    std::fs::write(&scene, half_covered(width, height, "")).unwrap();
    let (code, peak) = peak_kib(&["run", path(&scene), "--format", "none"]);
    assert_eq!(code, 0);
    limit.hold_peak(peak);
    std::fs::write(&scene, half_covered(width, height + 1, "")).unwrap();
    let run = zsim(&["run", path(&scene), "--format", "none"]);
    assert_eq!((run.code, run.stderr.lines().count()), (2, 1), "{}", run.stderr);
    assert!(run.stderr.contains(&format!("beyond the limit of {}", limit.value)), "{}", run.stderr);
}

/// `run --format json` writes the buffers row by row: its peak is the
/// buffers and little more, not the text of every number.
#[test]
fn json_output_is_written_row_by_row() {
    let limit = stated("JSON output, row by row");
    let dir = scratch("json-rows");
    let side = (limit.value as f64).sqrt() as u32;
    let scene = dir.join("s.json");
    std::fs::write(&scene, half_covered(side, side, r#", "frame_bits": 32, "depth_bits": 32"#)).unwrap();
    let (code, peak) = peak_kib(&["run", path(&scene), "--final", "--format", "json"]);
    assert_eq!(code, 0);
    limit.hold_peak(peak);
}

/// A CS 418 image of the most samples zsim draws is drawn; one column more
/// is refused at its line, before any sample buffer is allocated.
#[test]
fn a_cs418_image_of_the_most_samples_is_drawn_and_one_more_is_refused() {
    let limit = stated("A CS 418 image's samples");
    let dir = scratch("largest-cs418");
    let (width, height) = (4096u64, limit.value / 4096);
    assert_eq!(width * height, limit.value);
    let case = dir.join("case.txt");
    let draw = "position 2 -1 -1 1 -1 -1 1\ncolor 3 1 1 1 1 1 1 1 1 1\ndrawArraysTriangles 0 3\n";
    std::fs::write(&case, format!("png {width} {height} out.png\n{draw}")).unwrap();
    let (code, peak) = peak_kib(&["cs418", "run", path(&case), "-o", path(&dir.join("out"))]);
    assert_eq!(code, 0);
    limit.hold_peak(peak);
    std::fs::write(&case, format!("png {} {height} out.png\n{draw}", width + 1)).unwrap();
    let run = zsim(&["cs418", "run", path(&case), "-o", path(&dir.join("out2"))]);
    assert_eq!((run.code, run.stderr.lines().count()), (2, 1), "{}", run.stderr);
    assert!(run.stderr.contains(&format!("more than zsim draws ({})", limit.value)), "{}", run.stderr);
}

/// A tinyrenderer vertex projected to the limit lands there, in either
/// arithmetic; one projected past it, however far, is held there (the area
/// of a triangle with such corners still fits 128 bits; that such a model
/// draws at once, `a_vertex_far_outside_the_image_draws_at_once`).
#[test]
fn a_projected_coordinate_is_held_at_its_limit() {
    use zsim::tinyrenderer::{LessonArith, Model, project};
    let limit = stated("A projected coordinate (tinyrenderer)");
    let far = i64::try_from(limit.value).unwrap();
    // An image 2 pixels wide: x on the screen is (x + 1) · 2 / 2, so x = 2^40 − 1 lands on 2^40.
    let x = |pixels: i64| (pixels - 1).to_string();
    let model =
        Model::parse(&format!("v {} 0 0\nv {} 0 0\nv {} 0 0\nv 1e308 0 0\n", x(far - 1), x(far), x(far + 1))).unwrap();
    for arith in [LessonArith::F64, LessonArith::Exact] {
        let screen: Vec<i64> = (0..4).map(|v| project(&model, v, arith, 2)[0]).collect();
        assert_eq!(screen, [far - 1, far, far, far], "{arith:?}");
    }
}

/// Each of the page's limits holds at its value and refuses one more, naming
/// itself and what draws the scene instead; the page prints and draws
/// buffers up to its limit and says why not past it.
#[test]
fn each_page_limit_holds_at_its_value_and_refuses_one_more() {
    use zsim::page_limits::{PageLimit, check_text};
    let (text, raster, polygons, vertices, reach, printed) = (
        stated("The page's scene text"),
        stated("The page's raster"),
        stated("The page's polygons"),
        stated("The page's vertices a polygon"),
        stated("What the page's polygons reach"),
        stated("The page's printed buffers and figure"),
    );
    let scene = |width: u64, height: u64, count: usize, corners: usize| {
        let polygon = |n: usize| {
            if n == 3 {
                return r#"{"value":1,"vertices":[[1,1,1],[7,1,1],[1,7,1]]}"#.to_string();
            }
            let points: Vec<String> = (0..n)
                .map(|k| {
                    let angle = k as f64 / n as f64 * std::f64::consts::TAU;
                    format!("[{:.6},{:.6},1]", 4.0 + 3.0 * angle.cos(), 4.0 + 3.0 * angle.sin())
                })
                .collect();
            format!(r#"{{"value":1,"vertices":[{}]}}"#, points.join(","))
        };
        let list: Vec<String> = (0..count).map(|k| polygon(if k == 0 { corners } else { 3 })).collect();
        format!(r#"{{"width":{width},"height":{height},"polygons":[{}]}}"#, list.join(","))
    };
    let view = |text: &str| zsim::playground::view(zsim::Lang::En, text);
    // The text.
    let book = std::fs::read_to_string("examples/rogers.json").unwrap();
    let padded = format!("{book}{}", " ".repeat(text.count() - book.len()));
    assert_eq!(view(&padded)["ok"], true);
    let refused = view(&(padded + " "));
    assert_eq!(
        refused["error"],
        format!(
            "the page reads scenes of up to {} bytes; this one has {}: zsim run draws it",
            text.value,
            text.value + 1
        )
    );
    // The raster.
    let side = (raster.value as f64).sqrt() as u64;
    assert_eq!(check_text(&scene(side, side, 1, 3), None), Ok(()));
    let cells = check_text(&scene(side, side + 1, 1, 3), None).unwrap_err();
    assert_eq!(cells, PageLimit::Cells { path: None, cells: side * (side + 1) });
    assert_eq!(
        zsim::Refusal::message(&cells, zsim::Lang::En),
        format!(
            "the page draws rasters of up to {} pixels; this one has {}: zsim run draws it",
            raster.value,
            side * (side + 1)
        )
    );
    // The polygons.
    assert_eq!(check_text(&scene(16, 16, polygons.count(), 3), None), Ok(()));
    let many = check_text(&scene(16, 16, polygons.count() + 1, 3), None).unwrap_err();
    assert_eq!(many, PageLimit::Polygons { path: None, count: polygons.count() + 1 });
    // The vertices.
    assert_eq!(check_text(&scene(16, 16, 2, vertices.count()), None), Ok(()));
    let corners = check_text(&scene(16, 16, 2, vertices.count() + 1), Some(Path::new("v.json"))).unwrap_err();
    assert_eq!(
        zsim::Refusal::message(&corners, zsim::Lang::En),
        format!(
            "v.json: the page draws polygons of up to {} vertices; polygon 1 has {}: zsim run draws it",
            vertices.value,
            vertices.value + 1
        )
    );
    assert!(zsim::Refusal::message(&corners, zsim::Lang::Ru).contains(&(vertices.value + 1).to_string()));
    // What the polygons reach: raster-sized triangles on a 1024 × 1024 raster, as many as it allows.
    let triangles = |count: u64| {
        let one = r#"{"value":1,"vertices":[[0,0,1],[1024,0,5],[0,1024,9]]}"#;
        format!(r#"{{"width":1024,"height":1024,"polygons":[{}]}}"#, vec![one; count as usize].join(","))
    };
    let most = reach.value / (1024 * 1024);
    assert_eq!(view(&triangles(most))["ok"], true);
    assert_eq!(
        view(&triangles(most + 1))["error"],
        format!(
            "the page draws scenes whose polygons' bounding boxes cover up to {} pixels of the raster in all; this one's cover {}: zsim run draws it",
            reach.value,
            (most + 1) * 1024 * 1024
        )
    );
    // The printed buffers and the figure.
    let side = (printed.value as f64).sqrt() as u64;
    for (height, shown) in [(side, true), (side + 1, false)] {
        let text = scene(side, height, 1, 3);
        let viewed = view(&text);
        assert_eq!(viewed["framebuffer"].as_str().unwrap().is_empty(), !shown, "{height} rows");
        let figure = zsim::playground::figure(zsim::Lang::En, &text);
        assert_eq!(figure["ok"], shown, "{height} rows");
        if !shown {
            let said = format!(
                "The page draws figures of rasters of up to {} pixels; zsim figure draws this one.",
                printed.value
            );
            assert_eq!(figure["error"], said);
            assert!(viewed["notes"].to_string().contains(&printed.value.to_string()), "{}", viewed["notes"]);
        }
    }
}

/// The figure of a raster as large as a figure draws is drawn; one row
/// more is refused in one line.
#[test]
fn a_figure_of_the_largest_raster_is_drawn_and_one_row_more_is_refused() {
    let limit = stated("A figure's raster");
    let dir = scratch("largest-figure");
    let side = limit.value as u32;
    let scene = dir.join("s.json");
    let svg = dir.join("s.svg");
    std::fs::write(&scene, half_covered(side, side, "")).unwrap();
    let (code, peak) = peak_kib(&["figure", path(&scene), "-o", path(&svg)]);
    assert_eq!(code, 0);
    limit.hold_peak(peak);
    assert!(std::fs::read_to_string(&svg).unwrap().starts_with("<svg"));
    std::fs::write(&scene, half_covered(side, side + 1, "")).unwrap();
    let run = zsim(&["figure", path(&scene), "-o", path(&dir.join("t.svg"))]);
    assert_eq!((run.code, run.stderr.lines().count()), (2, 1), "{}", run.stderr);
    assert!(run.stderr.contains(&limit.value.to_string()), "{}", run.stderr);
}

/// A tile smaller than the least side is drawn as one of it: tiles of 1 and
/// 7 pixels draw what 8 draws, at its peak (their bins would cost more than
/// the buffers); `--tile 0` is refused.
#[test]
fn tiles_smaller_than_the_least_are_drawn_as_it() {
    let limit = stated("A tile's least side");
    let dir = scratch("least-tile");
    let scene = dir.join("s.json");
    std::fs::write(&scene, half_covered(2048, 2048, "")).unwrap();
    let least = limit.value.to_string();
    let run = |tile: &str| peak_kib(&["run", path(&scene), "--format", "none", "--threads", "1", "--tile", tile]);
    let (code, at_least) = run(&least);
    assert_eq!(code, 0);
    limit.hold_peak(at_least);
    for smaller in ["1", &(limit.value - 1).to_string()] {
        let (code, peak) = run(smaller);
        assert_eq!(code, 0);
        assert!(peak < at_least + 8 * 1024, "--tile {smaller}: {peak} KiB, --tile {least}: {at_least} KiB");
    }
    let small = dir.join("small.json");
    std::fs::write(&small, half_covered(64, 64, "")).unwrap();
    let drawn = |tile: &str| zsim(&["run", path(&small), "--final", "--threads", "1", "--tile", tile]).stdout;
    assert_eq!(drawn("1"), drawn(&least));
    let refused = zsim(&["run", path(&scene), "--format", "none", "--tile", "0"]);
    assert_eq!((refused.code, refused.stderr.lines().count()), (2, 1), "{}", refused.stderr);
}

/// A triangle once read takes under 500 bytes, as `run` reports the scene's
/// memory: a 20,000-triangle scene as zsim makes them for its benchmarks.
#[test]
fn a_triangle_takes_under_500_bytes_once_read() {
    let limit = stated("A triangle once read");
    let dir = scratch("scene-memory");
    let scene = dir.join("r20k.json");
    let made = zsim(&[
        "random",
        "--count",
        "20000",
        "--width",
        "2048",
        "--height",
        "2048",
        "--max-size",
        "40",
        "--seed",
        "3",
        "-o",
        path(&scene),
    ]);
    assert_eq!(made.code, 0, "{}", made.stderr);
    let run = zsim(&["run", path(&scene), "--format", "none", "--lang", "en"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let reported = run.stdout.split_once(", scene ").expect("run reports the scene's memory").1;
    let (number, unit) = reported.split_once(' ').unwrap();
    let scale = match &unit[..3] {
        "KiB" => 1024.0,
        "MiB" => 1024.0 * 1024.0,
        other => panic!("{other}"),
    };
    let each = number.parse::<f64>().unwrap() * scale / 20_000.0;
    assert!(each < limit.value as f64, "{each} bytes a triangle");
    assert!(each > 100.0, "{each} bytes a triangle: the report is not the scene's");
}
