//! The teaching tools: `step` (one scanline, and driven through standard
//! input), `explain`, `check` and `figure`, all on the real binary.

use std::process::Command;

use crate::{Run, scene_file, snapshot, zsim, zsim_in};

/// Runs `zsim` with `input` on standard input (not a terminal).
fn zsim_with_input(args: &[&str], input: &str) -> Run {
    crate::zsim_stdin(args, input)
}

/// The cells of the table row for pixel `x` in `step` output.
fn table_row(stdout: &str, x: u32) -> Vec<String> {
    let line = stdout
        .lines()
        .find(|line| line.starts_with(&format!("| {x} ")))
        .unwrap_or_else(|| panic!("no table row for pixel {x} in:\n{stdout}"));
    line.trim_matches('|').split('|').map(|cell| cell.trim().to_string()).collect()
}

#[test]
fn step_one_scanline_shows_the_books_pixel_20_15() {
    let run = zsim(&["step", "examples/rogers.json", "--polygon", "2", "--scanline", "15"]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    assert!(run.stdout.contains("crossings: 31/2 ≈ 15.50, 169/6 ≈ 28.17"), "{}", run.stdout);
    // x, centre, z, ≈ z, step, stored, test, after, frame
    assert_eq!(
        table_row(&run.stdout, 20),
        ["20", "41/2 ≈ 20.50", "43/4", "10.75", "-3/4", "10", "43/4 > 10: written", "11", "2"]
    );
    // Pixel (20, 17) on its own scanline: written though the stored value stays 10.
    let run = zsim(&["step", "examples/rogers.json", "--polygon", "triangle", "--scanline", "17"]);
    assert_eq!(table_row(&run.stdout, 20)[2..=8], ["41/4", "10.25", "-3/4", "10", "41/4 > 10: written", "10", "2"]);
    snapshot!(
        "step_rogers_triangle_15",
        zsim(&["step", "examples/rogers.json", "--polygon", "2", "--scanline", "15"]).stdout
    );
}

#[test]
fn step_refuses_a_scanline_the_polygon_does_not_reach() {
    let run = zsim(&["step", "examples/rogers.json", "--polygon", "2", "--scanline", "30"]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert_eq!(run.stderr, "zsim: polygon 2 \"triangle\" does not reach the scanline y = 30.5: its rows are 10 … 24\n");
    let run = zsim(&["step", "examples/rogers.json", "--polygon", "9", "--scanline", "3"]);
    assert_eq!(run.code, 2);
    assert_eq!(run.stderr, "zsim: there is no polygon 9: the scene has 2 (number them from 1)\n");
}

#[test]
fn step_is_driven_by_commands_on_standard_input() {
    // next, back, go to scanline 20, next polygon, an unknown command, quit.
    let run = zsim_with_input(&["step", "examples/rogers.json"], "n\nb\ng 20\np\nx\nq\n");
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    let scanlines: Vec<&str> = run.stdout.lines().filter(|l| l.starts_with("scanline ")).collect();
    assert_eq!(
        scanlines,
        [
            "scanline y = 5.5 (row 5)",
            "scanline y = 6.5 (row 6)",
            "scanline y = 5.5 (row 5)",
            "scanline y = 20.5 (row 20)",
            "scanline y = 10.5 (row 10)"
        ]
    );
    assert!(run.stdout.contains("unknown command \"x\""));
    snapshot!("step_rogers_stdin", run.stdout);
}

#[test]
fn step_passes_over_empty_scanlines_and_skipped_polygons_with_a_mention() {
    let (dir, name) = scene_file(
        "step_skips.json",
        r#"{"width": 6, "height": 6, "effects": {"cull": "cw"}, "polygons": [
            {"name": "back", "value": 1, "vertices": [[0,0,5],[0,6,5],[6,0,5]]},
            {"name": "thin", "value": 2, "vertices": [[0.6,0,5],[1.4,0,5],[1.4,3,5],[0.6,3,5]]},
            {"name": "front", "value": 3, "vertices": [[0,0,5],[6,0,5],[0,6,5]]}]}"#,
    );
    let run = crate::zsim_in(Some(&dir), &["step", &name]);
    let mentions: Vec<&str> = run.stdout.lines().filter(|l| l.starts_with("  · ")).collect();
    assert_eq!(
        mentions,
        [
            "  · polygon 1 \"back\": culled: its vertices run clockwise, so it is not drawn",
            "  · polygon 2 \"thin\", scanline y = 0.5: no pixel centre covered",
            "  · polygon 2 \"thin\", scanline y = 1.5: no pixel centre covered",
            "  · polygon 2 \"thin\", scanline y = 2.5: no pixel centre covered",
        ]
    );
    assert!(run.stdout.contains("── polygon 3 \"front\""));
}

#[test]
fn quiz_scores_the_students_answers() {
    // The rectangle's first scanline (row 5): 10 is stored at every pixel; `-` at (12, 5) gets
    // the kind of its mistake, then a second try.
    let run = zsim_with_input(&["step", "examples/rogers.json", "--quiz"], "10\n10\n-\n10\nq\n");
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    assert!(run.stdout.contains("pixel (10, 5), stored 0: the z-buffer after?"), "{}", run.stdout);
    assert!(run.stdout.contains("  10 (the value written): right. z = 10 > 0 stored"), "{}", run.stdout);
    assert!(
        run.stdout.contains("  -: not yet: this pixel passes the depth test: compare its exact z with the stored value again (one more try)\nlast try: pixel (12, 5)"),
        "{}",
        run.stdout
    );
    assert!(run.stdout.contains("  10 (the value written): right at the second try."), "{}", run.stdout);
    assert!(
        run.stdout.ends_with("quiz: 2 right at the first try, 1 at the second, 0 shown, 0 skipped, of 3 questions\n"),
        "{}",
        run.stdout
    );
}

/// Moving on is refused while the scanline's questions are open (found by a
/// teacher: `p`, `n`, `b` and `g` left them behind); `s` skips them on purpose.
#[test]
fn quiz_refuses_to_move_on_until_the_questions_are_answered_or_skipped() {
    let run = zsim_with_input(&["step", "examples/rogers.json", "--quiz"], "p\n\ng 15\nabc\ns\np\n6\nq\n");
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    let refusals =
        run.stdout.matches("  15 open questions on this scanline: answer them first, or s to skip them\n").count();
    assert_eq!(refusals, 3, "{}", run.stdout);
    assert!(run.stdout.contains("\"abc\" is not an answer: type the value"), "{}", run.stdout);
    assert!(run.stdout.contains("  skipped: 15 questions (counted as not answered)"), "{}", run.stdout);
    // `p`: the triangle's first scanline (row 10), whose pixel 28 gets 6.
    assert!(run.stdout.contains("pixel (28, 10), stored 0: the z-buffer after?"), "{}", run.stdout);
    assert!(run.stdout.contains("  6 (the value written): right."), "{}", run.stdout);
    assert!(
        run.stdout.ends_with("quiz: 1 right at the first try, 0 at the second, 0 shown, 15 skipped, of 16 questions\n"),
        "{}",
        run.stdout
    );
}

/// Found by a new user: at the hidden pixel (21, 15) the value it keeps, 10, was marked wrong.
#[test]
fn quiz_accepts_both_answers_for_a_hidden_pixel_and_starts_where_asked() {
    let answers = "15\n14\n13\n12\n12\n11\n10\nq\n";
    let run =
        zsim_with_input(&["step", "examples/rogers.json", "--quiz", "--polygon", "2", "--scanline", "15"], answers);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    assert!(run.stdout.contains("  11 (the value written): right. z = 43/4"), "{}", run.stdout);
    assert!(
        run.stdout.contains("  10 (not written: the value it keeps): right. z = 10 is not > 10 stored"),
        "{}",
        run.stdout
    );
    let run = zsim_with_input(
        &["step", "examples/rogers.json", "--quiz", "--polygon", "2", "--scanline", "15"],
        "15\n14\n13\n12\n12\n11\n-\nq\n",
    );
    assert!(run.stdout.contains("  - (not written): right."), "{}", run.stdout);
}

/// The coverage question hides the crossings, spans and covered columns
/// until it is answered, takes every notation zsim prints, names the kind
/// of a wrong answer, and shows the answer after a second wrong one.
#[test]
fn quiz_coverage_asks_which_centres_are_covered_first() {
    let args = ["step", "examples/rogers.json", "--quiz", "coverage", "--polygon", "2", "--scanline", "15"];
    let run = zsim_with_input(&args, "16-28\n15 … 27\nq\n");
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    let asked = run.stdout.find("which columns' centres does it cover?").expect(&run.stdout);
    assert!(!run.stdout[..asked].contains("crossings:"), "the crossings would answer it: {}", run.stdout);
    assert!(
        run.stdout.contains(
            "  16-28: not yet: these are the columns of the row just below or above: this scanline is y = row + ½"
        ),
        "{}",
        run.stdout
    );
    assert!(
        run.stdout.contains("  15 … 27: right at the second try. the spans are 31/2 ≈ 15.50 … 169/6 ≈ 28.17"),
        "{}",
        run.stdout
    );
    let run = zsim_with_input(&args, "16-28\n16-27\nq\n");
    assert!(run.stdout.contains("  16-27: wrong again. The answer is 15-27: the spans are"), "{}", run.stdout);
    assert!(
        run.stdout.contains("your mistakes:\n  row 15 of polygon 2 \"triangle\": you said columns 16-27, right 15-27"),
        "{}",
        run.stdout
    );
}

/// The framebuffer question in the line mode: the value after each pixel,
/// judged by value, and a value no framebuffer cell can hold asked again.
#[test]
fn quiz_frame_asks_the_framebuffer_value() {
    let run = zsim_with_input(
        &["step", "examples/rogers.json", "--quiz", "frame", "--polygon", "2", "--scanline", "15"],
        "4\n2\n1\nq\n",
    );
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    assert!(run.stdout.contains("pixel (15, 15), framebuffer 1: the framebuffer after?"), "{}", run.stdout);
    assert!(
        run.stdout.contains("4 does not fit this framebuffer: its cells hold whole values 0 … 3"),
        "{}",
        run.stdout
    );
    assert!(run.stdout.contains("  2 (the value written): right."), "{}", run.stdout);
    assert!(run.stdout.contains("  1: not yet: this pixel passes the depth test"), "{}", run.stdout);
    assert!(run.stdout.contains("quiz: 1 right at the first try"), "{}", run.stdout);
}

/// Found by a new maintainer: the line mode put what was typed into its
/// message raw, where the full-screen app escaped it; an escape sequence
/// typed at the prompt now reaches the terminal escaped.
#[test]
fn the_line_mode_escapes_what_was_typed() {
    let run = zsim_with_input(&["step", "examples/rogers.json"], "\u{1b}[31mred\nq\n");
    assert!(run.stdout.contains("\\u{1b}[31mred"), "{}", run.stdout);
    assert!(!run.stdout.contains('\u{1b}'), "{}", run.stdout);
}

#[test]
fn go_to_a_row_off_the_raster_says_so() {
    let run = zsim_with_input(&["step", "examples/rogers.json"], "g 99\nq\n");
    assert!(run.stdout.contains("row 99 is outside the raster (rows 0 … 31)\n"), "{}", run.stdout);
}

#[test]
fn explain_walks_through_pixel_20_15_like_the_book() {
    let run = zsim(&["explain", "examples/rogers.json", "--pixel", "20,15"]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    assert!(run.stdout.contains(
        "polygon 2 \"triangle\": on the scanline y = 15.5 it spans 31/2 ≈ 15.50 … 169/6 ≈ 28.17, which holds the centre x = 41/2 ≈ 20.50; z = 43/4 ≈ 10.75 > 10 stored, so 11 is stored (10.75 rounds up to 11) and the framebuffer gets 2"
    ));
    // Found by a new user: the book's key subtlety, z = 41/4 > 10 written though 10 is stored, named.
    let pixel_20_17 = zsim(&["explain", "examples/rogers.json", "--pixel", "20,17"]);
    assert!(
        pixel_20_17
            .stdout
            .contains("z = 41/4 ≈ 10.25 > 10 stored, so 10 is stored (10.25 rounds to 10) and the framebuffer gets 2"),
        "{}",
        pixel_20_17.stdout
    );
    assert!(run.stdout.ends_with("final: framebuffer 2, z-buffer 11\n"));
    snapshot!("explain_rogers_20_15", run.stdout);
    snapshot!("explain_rogers_27_10", zsim(&["explain", "examples/rogers.json", "--pixel", "27,10"]).stdout);
    snapshot!("explain_section_16_15", zsim(&["explain", "examples/section.json", "--pixel", "16,15"]).stdout);
}

#[test]
fn explain_refuses_pixels_off_the_raster() {
    let run = zsim(&["explain", "examples/rogers.json", "--pixel", "32,0"]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert_eq!(run.stderr, "zsim: pixel (32, 0) is outside the 32×32 raster (x 0 … 31, y 0 … 31)\n");
    let run = zsim(&["explain", "examples/rogers.json", "--pixel", "3"]);
    assert_eq!(run.code, 2);
}

#[test]
fn check_finds_the_books_errata() {
    // The printed z-buffer after the triangle differs at exactly the misprinted cells.
    let run = zsim(&["check", "examples/rogers.json", "--depth", "tests/fixtures/rogers/depth_after_triangle.txt"]);
    assert_eq!((run.code, run.stderr.as_str()), (1, ""));
    let rows = crate::table_rows(&run.stdout);
    let cells: Vec<(&str, &str)> = rows.iter().skip(1).map(|r| (r[0].as_str(), r[1].as_str())).collect();
    assert_eq!(cells, [("27", "10"), ("28", "10"), ("29", "10")]);
    assert_eq!(
        rows[1][4],
        "no polygon covers (27, 10): on the scanline y = 10.5 polygon 1 \"rectangle\" spans 10 … 25 and polygon 2 \"triangle\" spans 57/2 ≈ 28.50 … 179/6 ≈ 29.83; it keeps the cleared depth 0"
    );
    snapshot!("check_rogers_book_depth", run.stdout);
    // The printed framebuffer has 33 rows: refused as the wrong shape.
    let run = zsim(&["check", "examples/rogers.json", "--frame", "tests/fixtures/rogers/frame_after_triangle.txt"]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert_eq!(run.stderr, "zsim: tests/fixtures/rogers/frame_after_triangle.txt: 33 rows; the raster has 32\n");
}

#[test]
fn check_accepts_a_right_answer_after_any_polygon() {
    let run = zsim(&[
        "check",
        "examples/rogers.json",
        "--after",
        "rectangle",
        "--frame",
        "tests/fixtures/rogers/frame_after_rectangle.txt",
        "--depth",
        "tests/fixtures/rogers/depth_after_rectangle.txt",
    ]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""), "{}", run.stdout);
    assert_eq!(run.stdout.lines().filter(|l| l.contains("all 1024 cells match")).count(), 2);
}

#[test]
fn check_explains_a_students_mistakes() {
    // A student who compared rounded depths would leave (20, 17) as the rectangle's 1.
    let mut answer = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/rogers/depth_after_triangle.txt"),
    )
    .unwrap();
    answer = answer.replace(
        "10 10 10 10 10 10 10 10 10 10 10 10 10 10 10 0 0 6 5 0 0 0",
        "10 10 10 10 10 10 10 10 10 10 10 10 10 10 10 0 0 0 6 5 0 0",
    );
    let mut lines: Vec<String> = answer.lines().map(str::to_string).collect();
    lines.insert(0, "# my z-buffer after the triangle".to_string());
    // Row y = 15 (line 17 of the 32 rows, top first): say 10 at (20, 15).
    let row = 31 - 15 + 1;
    let mut cells: Vec<String> = lines[row].split_whitespace().map(str::to_string).collect();
    cells[20] = "10".to_string();
    lines[row] = cells.join(" ");
    let (dir, _) = scene_file("unused.json", "{}");
    let answer_path = dir.join("student_depth.txt");
    std::fs::write(&answer_path, lines.join("\n")).unwrap();
    let run = zsim(&["check", "examples/rogers.json", "--depth", answer_path.to_str().unwrap()]);
    assert_eq!(run.code, 1);
    assert!(run.stdout.contains("1 of 1024 cells differs"), "{}", run.stdout);
    assert_eq!(
        crate::table_rows(&run.stdout)[1],
        [
            "20",
            "15",
            "10",
            "11",
            "polygon 2 \"triangle\" covers (20, 15): z = 43/4 ≈ 10.75 > 10 stored, so 11 is stored (10.75 rounds up to 11)"
        ]
    );
}

/// Every problem of a file is named, up to three, then how many more (the
/// teacher's side: only the first was reported).
#[test]
fn check_refuses_malformed_answers() {
    let (dir, _) = scene_file("unused2.json", "{}");
    let bad = dir.join("bad_answer.txt");
    std::fs::write(&bad, "0 0 x\n").unwrap();
    let run = zsim(&["check", "examples/rogers.json", "--frame", bad.to_str().unwrap()]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert!(
        run.stderr.ends_with(
            "bad_answer.txt: line 1, value 3 (x = 2, y = 31): \"x\" is not a whole number (a 2-bit framebuffer holds 0 … 3) \
             · line 1: 3 values; the raster is 32 wide · 1 row; the raster has 32\n"
        ),
        "{}",
        run.stderr
    );
    let run = zsim(&["check", "examples/rogers.json"]);
    assert_eq!(run.code, 2);
    assert_eq!(run.stderr, "zsim: check needs an answer: --frame FILE and/or --depth FILE\n");
}

#[test]
fn figure_writes_a_well_formed_svg() {
    let (dir, _) = scene_file("unused3.json", "{}");
    let output = dir.join("rogers.svg");
    let run = zsim_in(None, &["figure", "examples/rogers.json", "-o", output.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    let svg = std::fs::read_to_string(&output).unwrap();
    let document = roxmltree::Document::parse(&svg).expect("the SVG is well-formed XML");
    let count = |id: &str, tag: &str| {
        let group = document.descendants().find(|n| n.attribute("id") == Some(id)).unwrap();
        group.children().filter(|n| n.has_tag_name(tag)).count()
    };
    assert_eq!(count("centres", "circle"), 1024, "one centre per pixel");
    assert_eq!(count("scanlines", "line"), 32, "one half-interval scanline per row");
    assert_eq!(count("polygons", "polygon"), 2);
    // Runs of equal cells in a row are one rectangle 24 units high and 24 units per cell wide.
    let pixels = document.descendants().find(|n| n.attribute("id") == Some("pixels")).unwrap();
    let cells: u32 = pixels
        .children()
        .filter(|n| n.has_tag_name("rect"))
        .map(|n| n.attribute("width").unwrap().parse::<u32>().unwrap() / 24)
        .sum();
    assert_eq!(cells, 337, "the non-background cells of the book's framebuffer after the triangle");
    snapshot!("figure_rogers_svg", svg);
    let depth = dir.join("rogers_depth.svg");
    let run =
        zsim_in(None, &["figure", "examples/rogers.json", "--depth", "--after", "1", "-o", depth.to_str().unwrap()]);
    assert_eq!(run.code, 0);
    let svg = std::fs::read_to_string(&depth).unwrap();
    assert!(roxmltree::Document::parse(&svg).is_ok());
    assert_eq!(svg.matches("<polygon ").count(), 1, "only the polygons up to --after are outlined");
}

#[test]
fn colour_only_on_a_terminal_and_never_with_no_color() {
    // Piped output (every test above) has no escape codes.
    assert!(!zsim(&["run", "examples/rogers.json"]).stdout.contains('\x1b'));
    // On a pseudo-terminal (util-linux `script`), matrices are coloured unless NO_COLOR is set.
    let binary = env!("CARGO_BIN_EXE_zsim");
    let on_terminal = |no_color: bool| {
        let mut command = Command::new("script");
        command.args(["-qec", &format!("{binary} run examples/rogers.json --final"), "/dev/null"]);
        command.current_dir(env!("CARGO_MANIFEST_DIR")).env_remove("NO_COLOR");
        if no_color {
            command.env("NO_COLOR", "1");
        }
        command.output()
    };
    match on_terminal(false) {
        Ok(output) if output.status.success() => {
            assert!(String::from_utf8_lossy(&output.stdout).contains('\x1b'), "coloured on a terminal");
            let plain = on_terminal(true).unwrap();
            assert!(!String::from_utf8_lossy(&plain.stdout).contains('\x1b'), "NO_COLOR turns colour off");
        }
        _ => eprintln!("notice: `script` is not available, so colour on a terminal was not tested"),
    }
}

/// Found by a new user: an SVG written into a `.png`.
#[test]
#[ignore = "needs the figures feature"]
fn figure_writes_a_png_for_png() {
    let (dir, _) = scene_file("unused5.json", "{}");
    let png = dir.join("rogers.png");
    let run = zsim(&["figure", "examples/rogers.json", "-o", png.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG\r\n\x1a\n"), "a PNG file");
}

/// Found by a new user: no legend, labels on outlines, two similar greens,
/// no values in the cells, no worksheet.
#[test]
fn figure_has_a_legend_values_and_a_worksheet() {
    let (dir, _) = scene_file("unused4.json", "{}");
    let svg_path = dir.join("values.svg");
    let run = zsim(&["figure", "examples/rogers.json", "--values", "-o", svg_path.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    let document = roxmltree::Document::parse(&svg).unwrap();
    let group = |id: &str| document.descendants().find(|n| n.attribute("id") == Some(id)).unwrap();
    let values: Vec<&str> =
        group("values").children().filter(|n| n.has_tag_name("text")).filter_map(|n| n.text()).collect();
    assert_eq!(values.len(), 1024, "a value in every cell");
    assert_eq!(values.iter().filter(|v| **v == "2").count(), 64, "the triangle's 64 written pixels");
    let legend: Vec<&str> =
        group("legend").children().filter(|n| n.has_tag_name("text")).filter_map(|n| n.text()).collect();
    // The legend names the polygons each value comes from (found by a new student: "value 1/2" alone),
    // and the x axis says its numbers stand at pixel centres (a vertex at x = 3.5 sits under "3").
    assert_eq!(legend, ["0: background", "value 1: \"rectangle\"", "value 2: \"triangle\""]);
    let axes: Vec<&str> =
        group("axes").children().filter(|n| n.has_tag_name("text")).filter_map(|n| n.text()).collect();
    assert!(axes.contains(&"x (numbers at pixel centres, x + ½)"), "{axes:?}");
    // The worksheet: an empty raster, every outline, every vertex labelled.
    let worksheet = dir.join("worksheet.svg");
    let run = zsim(&["figure", "examples/rogers.json", "--after", "0", "-o", worksheet.to_str().unwrap()]);
    assert_eq!(run.code, 0);
    let svg = std::fs::read_to_string(&worksheet).unwrap();
    let document = roxmltree::Document::parse(&svg).unwrap();
    let group = |id: &str| document.descendants().find(|n| n.attribute("id") == Some(id)).unwrap();
    assert_eq!(group("pixels").children().filter(|n| n.has_tag_name("rect")).count(), 0, "nothing filled");
    assert_eq!(group("polygons").children().filter(|n| n.has_tag_name("polygon")).count(), 2);
    let labels: Vec<&str> =
        group("vertices").children().filter(|n| n.has_tag_name("text")).filter_map(|n| n.text()).collect();
    // Left of the raster the vertices left of their polygon's middle, top down; then the right.
    assert_eq!(
        labels,
        ["(10, 25, 10)", "(15, 15, 15)", "(10, 5, 10)", "(25, 25, 10)", "(25, 25, 5)", "(30, 10, 5)", "(25, 5, 10)"]
    );
    // A Word file is refused with the formats there are.
    let run = zsim(&["figure", "examples/rogers.json", "-o", dir.join("rogers.docx").to_str().unwrap()]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert!(run.stderr.contains("a figure is written as .svg, .png, .pdf or .tex (TikZ)"), "{}", run.stderr);
}

/// Found by a new user: the title held the path as typed and was cut off on small rasters.
#[test]
fn figure_titles_wrap_and_can_be_chosen() {
    let (dir, _) = scene_file("unused5.json", "{}");
    let path = dir.join("aa.svg");
    let run = zsim(&["figure", "examples/antialias.json", "-o", path.to_str().unwrap()]);
    assert_eq!(run.code, 0);
    let svg = std::fs::read_to_string(&path).unwrap();
    let document = roxmltree::Document::parse(&svg).unwrap();
    let width: usize = document.root_element().attribute("width").unwrap().parse().unwrap();
    let lines: Vec<&str> = document
        .root_element()
        .children()
        .filter(|n| n.has_tag_name("text") && n.attribute("font-size") == Some("13"))
        .filter_map(|n| n.text())
        .collect();
    assert!(lines.len() >= 2, "the long title wraps: {lines:?}");
    assert!(lines.iter().all(|l| l.chars().count() * 15 / 2 <= width), "each line fits {width} units: {lines:?}");
    assert!(lines.join(" ").starts_with(
        "antialias.json: framebuffer after polygon 2 \"wedge\", its 2×2 samples per pixel before averaging"
    ));
    let run = zsim(&["figure", "examples/rogers.json", "--title", "Exercise 3", "-o", path.to_str().unwrap()]);
    assert_eq!(run.code, 0);
    assert!(std::fs::read_to_string(&path).unwrap().contains(r#"font-size="13">Exercise 3</text>"#));
}

/// Found by a new user: `step` announced supersampling but showed plain coverage without saying so.
#[test]
fn step_says_it_shows_coverage_before_antialiasing() {
    let run = zsim(&["step", "examples/antialias.json", "--polygon", "2", "--scanline", "3"]);
    assert_eq!(run.code, 0);
    assert!(
        run.stdout.contains("note: this scene asks for 2×2 supersampling; step shows each pixel centre's plain coverage and depth, before supersampling and averaging"),
        "{}",
        run.stdout
    );
}

/// Found by a new user: a 7 in a 2-bit framebuffer, commas, a bad file next to a
/// good one, an answer written bottom row first, and a table 200 columns wide.
#[test]
fn check_reads_handed_in_answers_as_students_write_them() {
    let (dir, _) = scene_file("unused6.json", "{}");
    let (frame, depth) = (crate::book_answer("frame", ", "), crate::book_answer("depth", " "));
    let (frame_path, depth_path) = (dir.join("commas.frame.txt"), dir.join("good.depth.txt"));
    std::fs::write(&frame_path, &frame).unwrap();
    std::fs::write(&depth_path, &depth).unwrap();
    let run = zsim(&["check", "examples/rogers.json", "--frame", frame_path.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""), "commas between numbers are read");
    // A value the buffer cannot hold, named at its line, column and cell.
    let seven = dir.join("seven.frame.txt");
    std::fs::write(&seven, frame.replacen("0, 0", "0, 7", 1)).unwrap();
    let run = zsim(&[
        "check",
        "examples/rogers.json",
        "--frame",
        seven.to_str().unwrap(),
        "--depth",
        depth_path.to_str().unwrap(),
    ]);
    assert_eq!(run.code, 2, "a malformed file is bad input");
    assert_eq!(
        run.stderr,
        format!(
            "zsim: {}: line 1, value 2 (x = 1, y = 31): 7 does not fit a 2-bit framebuffer (0 … 3)\n",
            seven.display()
        )
    );
    assert!(run.stdout.contains("all 1024 cells match the z-buffer"), "the good file is still checked: {}", run.stdout);
    // Written bottom row first: said so.
    let upside_down: String = depth.lines().rev().map(|l| format!("{l}\n")).collect();
    let flipped = dir.join("flipped.depth.txt");
    std::fs::write(&flipped, upside_down).unwrap();
    let run = zsim(&["check", "examples/rogers.json", "--depth", flipped.to_str().unwrap()]);
    assert_eq!(run.code, 1);
    assert!(
        run.stdout.contains("hint: read bottom row first, it matches; write the top row (y = 31) first and each row from x = 0, as the book prints them\n"),
        "{}",
        run.stdout
    );
    // The table fits 80 columns.
    let wide = run.stdout.lines().map(|l| l.chars().count()).max().unwrap();
    assert!(run.stdout.lines().filter(|l| l.starts_with('|')).all(|l| l.chars().count() <= 80), "widest line {wide}");
}

/// The stepper as a page: one self-contained file that needs nothing from
/// outside (what it shows is driven through a browser in `browser.rs`).
#[test]
fn step_writes_a_self_contained_page() {
    let (dir, _) = scene_file("unused7.json", "{}");
    let page = dir.join("step.html");
    let run = zsim(&["step", "examples/rogers.json", "--html", "-o", page.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    // SVG's namespace name is a name, never fetched.
    let html = std::fs::read_to_string(&page).unwrap().replace("\"http://www.w3.org/2000/svg\"", "\"svg\"");
    for outside in ["http://", "https://", "<script src", "<link", "@import"] {
        assert!(!html.contains(outside), "the page needs nothing from outside: found {outside}");
    }
    assert!(!html.contains("selftest"), "no test mode inside the product");
}

/// A terminal of `width`×`height` in tmux running `command` (in the
/// project's folder, `zsim` the binary under test), given `keys` one group at
/// a time once `ready` shows; returns the whole screen (with what scrolled
/// off) once `done` shows. A test that calls it is `#[ignore = "needs tmux"]`.
pub(crate) fn in_tmux(size: (u16, u16), command: &str, ready: &str, keys: &[&[&str]], done: &str) -> String {
    use std::process::Command;
    if Command::new("tmux").arg("-V").output().is_err() {
        crate::missing("tmux", "the stepper and run in a real terminal");
    }
    let session = format!("zsim-{}-{}", std::process::id(), done.len() + command.len());
    let tmux = |args: &[&str]| Command::new("tmux").args(args).output().expect("tmux runs");
    let command = command.replace("zsim ", &format!("{} ", env!("CARGO_BIN_EXE_zsim"))) + "; sleep 60";
    let (width, height) = (size.0.to_string(), size.1.to_string());
    let dir = env!("CARGO_MANIFEST_DIR");
    let version = tmux(&["-V"]).stdout;
    crate::ran("the stepper and run in a real terminal", String::from_utf8_lossy(&version).trim());
    let started = tmux(&["new-session", "-d", "-s", &session, "-x", &width, "-y", &height, "-c", dir, &command]);
    assert!(started.status.success(), "{}", String::from_utf8_lossy(&started.stderr));
    let screen =
        || String::from_utf8_lossy(&tmux(&["capture-pane", "-p", "-S", "-", "-t", &session]).stdout).into_owned();
    let wait_for = |text: &str| {
        for _ in 0..100 {
            let shown = screen();
            if shown.contains(text) {
                return shown;
            }
            std::thread::sleep(std::time::Duration::from_millis(100));
        }
        panic!("never showed {text:?}:\n{}", screen());
    };
    wait_for(ready);
    for group in keys {
        tmux(&[&["send-keys", "-t", &session][..], group].concat());
        std::thread::sleep(std::time::Duration::from_millis(300));
    }
    let shown = wait_for(done);
    tmux(&["kill-session", "-t", &session]);
    shown
}

/// The full-screen quiz in a real terminal (tmux): answered right, then
/// wrong twice (a hint, then the answer), then `q`. When the screen closes the score and each mistake stay on
/// the terminal, as the line mode prints them, and the terminal is given back.
#[test]
#[ignore = "needs tmux"]
fn the_full_screen_quiz_prints_its_score_when_it_closes_in_a_real_terminal() {
    let command = "zsim step examples/rogers.json --quiz --polygon 2 --scanline 15; echo EXIT=$?";
    let keys: [&[&str]; 4] = [&["1", "5", "Enter"], &["1", "Enter"], &["1", "Enter"], &["q"]];
    let shown = in_tmux((100, 30), command, "stored 10: the z-buffer after?", &keys, "EXIT=");
    assert!(
        shown.contains("quiz: 1 right at the first try, 0 at the second, 1 shown, 0 skipped, of 2 questions"),
        "{shown}"
    );
    assert!(shown.contains("your mistakes:"), "{shown}");
    assert!(shown.contains("(16, 15) of polygon 2 \"triangle\": you said 1, right 14: "), "{shown}");
    assert!(shown.contains("EXIT=0"), "{shown}");
}

/// Found by a new student: 99 on a 4-bit z-buffer was scored wrong; it is no
/// level at all, so the line-mode quiz says so and asks again.
#[test]
fn quiz_asks_again_for_a_number_the_z_buffer_cannot_hold() {
    let args = ["step", "examples/rogers.json", "--quiz", "--polygon", "2", "--scanline", "15"];
    let run = zsim_with_input(&args, "99\n7/2\n15\nq\n");
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    assert!(run.stdout.contains("99 does not fit this z-buffer: its cells hold whole levels 0 … 15; type again\n"));
    assert!(run.stdout.contains("7/2 does not fit this z-buffer"), "{}", run.stdout);
    assert!(run.stdout.contains("  15 (the value written): right."), "{}", run.stdout);
    assert!(
        run.stdout.ends_with("quiz: 1 right at the first try, 0 at the second, 0 shown, 0 skipped, of 1 question\n"),
        "{}",
        run.stdout
    );
}

/// On a terminal `run` labels its matrices (a student wants the axes); piped
/// or with `--no-axes` it prints the book's bare matrices.
#[test]
#[ignore = "needs tmux"]
fn run_labels_the_matrices_on_a_terminal_and_not_when_piped() {
    let command = "echo START; zsim run examples/rogers.json --after 1 | tail -3; zsim run examples/rogers.json --after 1 --no-axes > /dev/tty; zsim run examples/rogers.json --after 1; echo DONE";
    let shown = in_tmux((120, 200), command, "START", &[], "DONE");
    let labelled = "     0 1 2 3 4 5 6 7 8 9 10 11";
    assert_eq!(shown.matches(labelled).count(), 2, "twice labelled (frame and depth), once only: {shown}");
    assert!(shown.contains("31 | 0 0 0"), "{shown}");
    // Piped (the first command through tail) and --no-axes: bare.
    assert!(!zsim(&["run", "examples/rogers.json", "--after", "1"]).stdout.contains(" | "));
}

/// Found by a teacher: `check SCENE FILE` got clap's bare "unexpected
/// argument"; it now says to name the answer with `--frame` or `--depth`.
#[test]
fn check_with_an_answer_named_bare_says_to_use_frame_or_depth() {
    let run = zsim(&["check", "examples/rogers.json", "answer.txt"]);
    assert_eq!(run.code, 2);
    assert_eq!(run.stderr, "zsim: answer.txt is an answer: name it with --frame answer.txt or --depth answer.txt\n");
}

/// Found by a teacher: an empty answer said "0 rows; the raster has 32"; a
/// decimal comma (`9,5`, as `--lang ru` itself writes numbers) voided the
/// row with "33 values; the raster is 32 wide" and no word of the comma.
#[test]
fn an_empty_answer_and_a_decimal_comma_are_named_as_such() {
    let (dir, _) = scene_file("unused-comma.json", "{}");
    let empty = dir.join("empty.txt");
    std::fs::write(&empty, "\n# nothing yet\n").unwrap();
    let run = zsim(&["check", "examples/rogers.json", "--frame", empty.to_str().unwrap()]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.ends_with("empty.txt: the file is empty: it holds no row of the answer\n"), "{}", run.stderr);
    let answer = crate::book_answer("frame", " ").replacen("\n0 ", "\n9,5 ", 1);
    let comma = dir.join("comma.txt");
    std::fs::write(&comma, &answer).unwrap();
    let run = zsim(&["check", "examples/rogers.json", "--frame", comma.to_str().unwrap()]);
    assert_eq!(run.code, 2, "{}", run.stdout);
    assert!(
        run.stderr.ends_with(
            "comma.txt: line 2: 9,5 has a decimal comma; each cell holds a whole number (cells are apart by spaces)\n"
        ),
        "{}",
        run.stderr
    );
}

/// Found by a teacher: a framebuffer given as `--depth` printed a 338-row
/// table without a word that it is the framebuffer.
#[test]
fn a_framebuffer_given_as_the_depth_answer_is_named_as_such() {
    let (dir, _) = scene_file("unused-other.json", "{}");
    let frame = dir.join("frame-as-depth.txt");
    std::fs::write(&frame, crate::book_answer("frame", " ")).unwrap();
    let run = zsim(&["check", "examples/rogers.json", "--depth", frame.to_str().unwrap()]);
    assert_eq!(run.code, 1, "{}", run.stderr);
    assert_eq!(
        run.stdout.lines().nth(1),
        Some("this is exactly the framebuffer, not the z-buffer: was it handed in as the other buffer?"),
        "{}",
        run.stdout
    );
}

/// Found by a student: a line of the line mode that is not UTF-8 ended the
/// lesson with "cannot write the output" and lost the score. It is asked
/// again, and the lesson goes on.
#[test]
fn a_line_that_is_not_text_is_asked_again() {
    let args = ["step", "examples/rogers.json", "--quiz", "--polygon", "2", "--scanline", "24"];
    let output = Command::new(env!("CARGO_BIN_EXE_zsim"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("LANG", "C.UTF-8")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .and_then(|mut child| {
            use std::io::Write;
            child.stdin.take().unwrap().write_all(b"\xff\xfe\n15\nq\n")?;
            child.wait_with_output()
        })
        .unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert_eq!(output.status.code(), Some(0), "{}", String::from_utf8_lossy(&output.stderr));
    assert!(stdout.contains("that line is not text (UTF-8): type it again\n"), "{stdout}");
    assert!(stdout.contains("\n  15: not yet"), "the answer after it is judged: {stdout}");
}

/// Found by a student: `zsim step --quiz < /dev/zero` grew until the
/// allocator aborted. A line past the line mode's bound ends the lesson in
/// one line, with the score so far, exit 2.
#[test]
fn a_line_past_its_bound_ends_the_lesson_with_its_score() {
    let output = Command::new(env!("CARGO_BIN_EXE_zsim"))
        .args(["step", "examples/rogers.json", "--quiz", "--polygon", "2", "--scanline", "24"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("LANG", "C.UTF-8")
        .stdin(std::fs::File::open("/dev/zero").unwrap())
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(stderr, "zsim: a line longer than 4096 bytes: the lesson ends here, with its score above\n");
    assert!(String::from_utf8(output.stdout).unwrap().contains("quiz: 0 right at the first try"));
}

/// Found by a teacher: `--quiz --polygon 2` was refused until a scanline was
/// named, and `--html --quiz` in clap's bare words. A polygon alone starts at
/// its first scanline; `--html --quiz` writes the playground with its quiz on
/// where this zsim carries it, and says in the reader's language why not
/// where it does not, or where the arithmetic is not exact.
#[test]
fn a_polygon_alone_starts_at_its_first_scanline_and_html_quiz_is_said() {
    let alone = zsim(&["step", "examples/rogers.json", "--polygon", "2"]);
    assert_eq!(alone.code, 0, "{}", alone.stderr);
    assert!(alone.stdout.contains("scanline y = 10.5 (row 10)"), "the triangle's first row: {}", alone.stdout);
    let quiz = zsim_with_input(&["step", "examples/rogers.json", "--quiz", "--polygon", "2"], "q\n");
    assert_eq!(quiz.code, 0, "{}", quiz.stderr);
    assert!(quiz.stdout.contains("scanline y = 10.5 (row 10)"), "{}", quiz.stdout);
    let inexact = zsim(&["step", "examples/rogers.json", "--html", "--quiz", "--arith", "f64", "-o", "never.html"]);
    assert_eq!(
        (inexact.code, inexact.stderr.as_str()),
        (2, "zsim: --html --quiz writes the playground, whose quiz asks in exact arithmetic: leave out --arith\n")
    );
    let russian =
        zsim(&["step", "examples/rogers.json", "--html", "--quiz", "--arith", "f64", "-o", "x.html", "--lang", "ru"]);
    assert!(russian.stderr.starts_with("zsim: --html --quiz записывает песочницу"), "{}", russian.stderr);
    let page = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("html-quiz.html");
    let _ = std::fs::remove_file(&page);
    let html = zsim(&["step", "examples/rogers.json", "--html", "--quiz", "coverage", "-o", page.to_str().unwrap()]);
    if option_env!("ZSIM_PLAYGROUND").is_some() {
        assert_eq!(html.code, 0, "{}", html.stderr);
        let written = std::fs::read_to_string(&page).unwrap();
        assert!(written.contains("window.ZSIM_QUIZ = \"coverage\";") && written.contains("window.ZSIM_WASM"));
    } else {
        assert_eq!(html.code, 2);
        assert!(html.stderr.starts_with("zsim: this zsim was built without the browser playground"), "{}", html.stderr);
        assert!(!page.exists());
    }
}

/// `zsim playground -o DIR` writes the site this zsim carries (the files `web/build` writes but the
/// WebAssembly module, which travels as a script); written again, it replaces them. A zsim built
/// without the playground says so in one line and writes nothing.
#[test]
fn zsim_playground_writes_the_site_or_says_it_has_none() {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("playground-site");
    let _ = std::fs::remove_dir_all(&dir);
    let site = dir.to_str().unwrap();
    let run = zsim(&["playground", "-o", site]);
    let Some(built) = option_env!("ZSIM_PLAYGROUND") else {
        assert_eq!((run.code, run.stderr.lines().count()), (2, 1), "{}", run.stderr);
        assert!(run.stderr.starts_with("zsim: this zsim was built without the browser playground"), "{}", run.stderr);
        assert!(!dir.exists());
        return;
    };
    assert_eq!(run.code, 0, "{}", run.stderr);
    for name in ["index.html", "playground.js", "playground.css", "zsim_web.js", "zsim_module.js"] {
        let written = std::fs::read(dir.join(name)).unwrap();
        assert_eq!(written, std::fs::read(std::path::Path::new(built).join(name)).unwrap(), "{name}");
    }
    assert_eq!(zsim(&["playground", "-o", site]).code, 0, "written again over the old site");
}
