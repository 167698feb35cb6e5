//! Every bad input is refused with exit status 2, one line on stderr naming the
//! file (and the polygon, where there is one), and nothing on stdout.

use crate::{scene_file, snapshot, zsim_in};

const TRIANGLE: &str = r#"{"name": "ok", "value": 1, "vertices": [[0, 0, 0], [4, 0, 0], [0, 4, 0]]}"#;

/// Runs `zsim run` on a scene written from `text` and returns its one-line error.
fn refused(file: &str, text: &str) -> String {
    let (dir, name) = scene_file(file, text);
    let run = zsim_in(Some(&dir), &["run", &name]);
    assert_eq!(run.code, 2, "exit status for {file}; stderr: {}", run.stderr);
    assert_eq!(run.stdout, "", "nothing on stdout for {file}");
    assert_eq!(run.stderr.lines().count(), 1, "one line on stderr for {file}: {}", run.stderr);
    assert!(run.stderr.contains(file), "the message names the file: {}", run.stderr);
    run.stderr
}

#[test]
fn bad_scenes_are_refused_with_one_line_each() {
    let cases: Vec<(&str, String)> = vec![
        ("not_json.json", "this is not json".into()),
        ("trailing.json", format!(r#"{{"polygons": [{TRIANGLE}]}} extra"#)),
        ("unknown_key.json", format!(r#"{{"widht": 32, "polygons": [{TRIANGLE}]}}"#)),
        (
            "unknown_polygon_key.json",
            r#"{"polygons": [{"value": 1, "colour": 2, "vertices": [[0,0,0],[1,0,0],[0,1,0]]}]}"#.into(),
        ),
        ("unknown_effect.json", format!(r#"{{"effects": {{"sectoin": 3}}, "polygons": [{TRIANGLE}]}}"#)),
        ("bad_cull.json", format!(r#"{{"effects": {{"cull": "left"}}, "polygons": [{TRIANGLE}]}}"#)),
        ("bad_depth_test.json", format!(r#"{{"depth_test": "nearer", "polygons": [{TRIANGLE}]}}"#)),
        (
            "value_too_wide.json",
            r#"{"polygons": [{"name": "wide", "value": 4, "vertices": [[0,0,0],[1,0,0],[0,1,0]]}]}"#.into(),
        ),
        ("background_too_wide.json", format!(r#"{{"background": 7, "polygons": [{TRIANGLE}]}}"#)),
        ("frame_bits_zero.json", format!(r#"{{"frame_bits": 0, "polygons": [{TRIANGLE}]}}"#)),
        ("depth_bits_33.json", format!(r#"{{"depth_bits": 33, "polygons": [{TRIANGLE}]}}"#)),
        ("width_zero.json", format!(r#"{{"width": 0, "polygons": [{TRIANGLE}]}}"#)),
        ("height_huge.json", format!(r#"{{"height": 100000, "polygons": [{TRIANGLE}]}}"#)),
        ("too_many_cells.json", format!(r#"{{"width": 16384, "height": 16384, "polygons": [{TRIANGLE}]}}"#)),
        ("negative_width.json", format!(r#"{{"width": -3, "polygons": [{TRIANGLE}]}}"#)),
        ("two_vertices.json", r#"{"polygons": [{"name": "stick", "value": 1, "vertices": [[0,0,0],[1,1,1]]}]}"#.into()),
        ("short_vertex.json", r#"{"polygons": [{"value": 1, "vertices": [[0,0,0],[1,0],[0,1,0]]}]}"#.into()),
        (
            "not_planar.json",
            r#"{"polygons": [{"name": "bent", "value": 1, "vertices": [[0,0,0],[4,0,0],[4,4,0],[0,4,1]]}]}"#.into(),
        ),
        ("not_a_number.json", r#"{"polygons": [{"value": 1, "vertices": [[0,0,"abc"],[1,0,0],[0,1,0]]}]}"#.into()),
        (
            // Past the digits and powers of ten a vertex coordinate may have (memory, not exactness).
            "coordinate_too_long.json",
            r#"{"polygons": [{"value": 1, "vertices": [[0,0,"1e1001"],[1,0,0],[0,1,0]]}]}"#.into(),
        ),
        ("divide_by_zero.json", r#"{"polygons": [{"value": 1, "vertices": [[0,0,"1/0"],[1,0,0],[0,1,0]]}]}"#.into()),
        ("boolean_coordinate.json", r#"{"polygons": [{"value": 1, "vertices": [[0,0,true],[1,0,0],[0,1,0]]}]}"#.into()),
        ("bad_section.json", format!(r#"{{"effects": {{"section": "x"}}, "polygons": [{TRIANGLE}]}}"#)),
        (
            // Denominators 2 … 3001: their lcm, about 2^4328, passes the big tier's 2^4096.
            "out_of_range.json",
            format!(
                r#"{{"polygons": [{{"name": "absurd", "value": 1, "vertices": [{}]}}]}}"#,
                (1..=1500).map(|j| format!(r#"["1/{}", "1/{}", 0]"#, 2 * j, 2 * j + 1)).collect::<Vec<_>>().join(", ")
            ),
        ),
        (
            // Found by a property: this was refused as "beyond the exact range" with a false claim.
            "not_planar_far.json",
            r#"{"polygons": [{"name": "bent", "value": 1, "vertices": [[0, "0.123456789012", 0], ["0.123456789012", 0, -4], [-18, "-37/9", "0.123456789012"], [7, 18, "-15.202"]]}]}"#.into(),
        ),
        (
            // The plane through vertices 1-3 has 136-bit coefficients (checked apart in Python's fractions).
            "not_planar_huge_plane.json",
            r#"{"polygons": [{"name": "bent", "value": 1, "vertices": [["13", "-8.965147458463", "19"], ["4.36427322", "97/621", "4.601918766151"], ["-7.3178342886648", "33/600", "-4"], ["8.4723050710231", "3.0701032506", "-7.2743050146027"]]}]}"#.into(),
        ),
        (
            "perspective_negative.json",
            format!(r#"{{"effects": {{"perspective": {{"distance": -4, "near": 1}}}}, "polygons": [{TRIANGLE}]}}"#),
        ),
        (
            "perspective_store.json",
            format!(
                r#"{{"effects": {{"perspective": {{"distance": 40, "near": 1, "store": "x"}}}}, "polygons": [{TRIANGLE}]}}"#
            ),
        ),
        (
            "antialias_zero.json",
            format!(r#"{{"effects": {{"antialias": {{"samples": 0}}}}, "polygons": [{TRIANGLE}]}}"#),
        ),
        (
            "opacity_two.json",
            r#"{"polygons": [{"name": "glass", "value": 1, "opacity": 2, "vertices": [[0,0,0],[1,0,0],[0,1,0]]}]}"#
                .into(),
        ),
        ("unknown_preset.json", format!(r#"{{"rules": "mit", "polygons": [{TRIANGLE}]}}"#)),
        (
            "unknown_rule.json",
            format!(r#"{{"rules": {{"preset": "buet", "rowz": "closed"}}, "polygons": [{TRIANGLE}]}}"#),
        ),
        ("bad_rule_value.json", format!(r#"{{"rules": {{"columns": "nearest"}}, "polygons": [{TRIANGLE}]}}"#)),
        (
            "inverted_window.json",
            format!(r#"{{"window": {{"left": 1, "right": -1, "bottom": -1, "top": 1}}, "polygons": [{TRIANGLE}]}}"#),
        ),
        (
            "inverted_depth_range.json",
            format!(r#"{{"rules": "buet", "depth_range": [1, -1], "polygons": [{TRIANGLE}]}}"#),
        ),
        ("clear_depth_quantized.json", format!(r#"{{"clear_depth": 2, "polygons": [{TRIANGLE}]}}"#)),
        (
            "second_polygon.json",
            format!(r#"{{"polygons": [{TRIANGLE}, {{"name": "bad", "value": 1, "vertices": [[0,0,0],[1,0,0]]}}]}}"#),
        ),
    ];
    let mut messages = String::new();
    for (file, text) in &cases {
        messages.push_str(&refused(file, text));
    }
    snapshot!("bad_input_messages", messages);
}

#[test]
fn missing_file_is_refused() {
    let run = zsim_in(None, &["run", "no/such/scene.json"]);
    assert_eq!(run.code, 2);
    assert_eq!(run.stdout, "");
    assert!(run.stderr.starts_with("zsim: no/such/scene.json: cannot read:"), "{}", run.stderr);
}

#[test]
fn usage_errors_exit_with_2() {
    let run = zsim_in(None, &["run", "examples/rogers.json", "--format", "xml"]);
    assert_eq!(run.code, 2);
    assert_eq!(run.stdout, "");
    // Options that would otherwise be ignored say what they need.
    let run = zsim_in(None, &["run", "examples/rogers.json", "--inside", "arc"]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert_eq!(run.stderr, "zsim: --inside chooses the point-in-polygon test of --order pixels; add --order pixels\n");
    let run = zsim_in(None, &["run", "examples/rogers.json", "--tile", "8"]);
    assert_eq!(run.code, 2);
    assert_eq!(
        run.stderr,
        "zsim: --tile and --threads apply to --format none, --final and --after (otherwise the state after each polygon is shown, drawn in order)\n"
    );
    let run = zsim_in(None, &["run", "examples/rogers.json", "--threads", "2", "--format", "json"]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert!(run.stderr.starts_with("zsim: --tile and --threads apply to --format none"), "{}", run.stderr);
    let run = zsim_in(None, &["run", "examples/rogers.json", "--threads", "0", "--format", "none"]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""), "no thread cannot draw");
    // Found by trying absurd arguments: a count this large ran until memory ran out.
    let run = zsim_in(None, &["random", "--count", "99999999999"]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert_eq!(
        run.stderr,
        "zsim: --count 99999999999: at most 10000000 triangles (a scene that large takes about 10 GB to read back)\n"
    );
}

/// A polygon that does not read is named before an earlier one that reads
/// and is not valid: the file is read again in one piece to say where, as a
/// reader that stops at the first JSON it cannot take would.
#[test]
fn a_polygon_that_does_not_read_is_named_before_an_earlier_invalid_one() {
    let invalid = r#"{"name": "a", "value": 9, "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}"#;
    let unread = r#"{"name": "b", "value": 1, "vertices": "x"}"#;
    let (dir, name) = scene_file("both.json", &format!(r#"{{"polygons": [{invalid}, {unread}]}}"#));
    let run = crate::zsim_with(Some(&dir), &["run", &name], &[("LANG", "C.UTF-8")]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert_eq!(
        run.stderr,
        "zsim: both.json: polygon 2: vertices: invalid type: found the string \"x\" where a list was expected (line 1, column 129)\n"
    );
}

/// Polygons are validated on every core: when several are wrong, the first
/// in the file is named, whichever thread found which, and its message is in
/// the reader's language, as on one thread.
#[test]
fn the_first_bad_polygon_of_a_large_scene_is_named_in_the_readers_language() {
    let polygon = |i: usize| {
        let opacity = if i == 1234 || i == 3456 { r#""opacity": 2, "# } else { "" };
        format!(r#"{{"name": "p{i}", "value": 1, {opacity}"vertices": [[0, 0, 0], [4, 0, 0], [0, 4, 0]]}}"#)
    };
    let polygons: Vec<String> = (0..5000).map(polygon).collect();
    let (dir, name) = scene_file("two_bad.json", &format!(r#"{{"polygons": [{}]}}"#, polygons.join(",")));
    let run = crate::zsim_with(Some(&dir), &["run", &name], &[("LANG", "C.UTF-8")]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert_eq!(run.stderr, "zsim: two_bad.json: polygon 1235 \"p1234\": opacity 2 is outside 0 … 1\n");
    let run = crate::zsim_with(Some(&dir), &["run", &name], &[("LANG", "ru_RU.UTF-8")]);
    assert_eq!((run.code, run.stdout.as_str()), (2, ""));
    assert!(run.stderr.contains("непрозрачность 2 вне диапазона 0 … 1"), "{}", run.stderr);
    assert!(run.stderr.contains("p1234") && !run.stderr.contains("p3456"), "{}", run.stderr);
}

/// A vertex written with a decimal comma, `[1, 1, 2,5]` (natural in Russian
/// and Ukrainian), was refused as a mix of pixel and clip-space vertices:
/// it is named as a decimal comma, with the vertex probably meant.
#[test]
fn a_decimal_comma_is_named_as_one() {
    let text =
        r#"{"width": 8, "height": 8, "polygons": [{"value": 1, "vertices": [[1, 1, 2,5], [6, 1, 2], [1, 6, 2]]}]}"#;
    let (dir, name) = scene_file("comma.json", text);
    assert!(refused("comma.json", text).ends_with(
        "polygon 1: a vertex has four numbers, [1, 1, 2, 5], among [x, y, z] vertices: is 2,5 a decimal comma? \
         JSON numbers take a point: write [1, 1, 2.5]\n"
    ));
    let run = zsim_in(Some(&dir), &["run", &name, "--lang", "ru"]);
    assert!(
        run.stderr.contains("2,5 — это десятичная запятая? В JSON дробную часть отделяет точка: напишите [1, 1, 2.5]"),
        "{}",
        run.stderr
    );
    // A clip-space vertex that cannot be a decimal comma (a fraction for w) is still named as a mix.
    let mixed = r#"{"width": 8, "height": 8, "polygons": [{"value": 1, "vertices": [[1, 1, 2, "1/2"], [6, 1, 2], [1, 6, 2]]}]}"#;
    assert!(refused("mixed.json", mixed).contains("mixes [x, y, z] vertices with clip-space [x, y, z, w] ones"));
}
