//! The two fast readers held to serde's reading and to the plain way's.

use crate::words::Lang;
use std::path::Path;

use proptest::prelude::*;

use super::{Number, PolygonFile, VerticesFile, pieces, plain, strict};
use crate::numbers::Exact;

/// A polygon as read, field by field, to compare two readings.
type Fields = (Option<String>, u64, Option<crate::numbers::Q>, Vec<[Exact; 3]>, Vec<[Exact; 4]>);

fn fields(polygon: PolygonFile) -> Fields {
    let PolygonFile { name, value, opacity, vertices: VerticesFile { xyz, clip } } = polygon;
    (name, value, opacity.map(|Number(q)| q), xyz, clip)
}

fn space() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec!["", " ", "\n", "\t ", "\r\n  "])
}

/// Numbers of every form JSON has, and some it has not.
fn any_number() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec![
        "0",
        "-0",
        "12",
        "-34",
        "1.5",
        "-0.25",
        "0.0",
        "007",
        "1e3",
        "1E-2",
        "0.5e+1",
        "123456789012345678",
        "-123456789012345678",
        "1234567890123456789",
        "-9223372036854775808",
        "-9223372036854775809",
        "18446744073709551615",
        "18446744073709551616",
        "99999999999999999999999",
        "0.1234567890123456789012345678901234567890",
        "\"1/3\"",
        "\"2.5\"",
        "null",
        "true",
        "1.",
        "-",
        ".5",
        "[1]",
    ])
}

/// Numbers of the common shape only.
fn plain_number() -> impl Strategy<Value = String> {
    (any::<bool>(), 0_u64..100_000_000_000_000_000, prop::option::of(0_u32..10_000)).prop_map(
        |(negative, whole, fraction)| {
            let sign = if negative { "-" } else { "" };
            match fraction {
                Some(fraction) => format!("{sign}{whole}.{fraction}"),
                None => format!("{sign}{whole}"),
            }
        },
    )
}

fn any_name() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec![
        r#""a""#,
        r#""t1""#,
        r#""""#,
        r#""a, {\"b\": 1}""#,
        "\"caf\u{e9} \u{4e09}\"",
        r#""tab\there""#,
        "\"\u{1}\"",
        r#""\u0041""#,
        r#""\ud800""#,
        r#""x\"""#,
        "null",
        "7",
    ])
}

fn any_value() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec![
        "0",
        "7",
        "255",
        "-1",
        "-0",
        "01",
        "7.0",
        "1e2",
        "18446744073709551615",
        "18446744073709551616",
        "\"7\"",
        "null",
    ])
}

/// `[[…], …]`: up to four vertices of `sizes` coordinates, each written by `number`.
fn vertex_list<S: Strategy<Value = T>, T: AsRef<str> + std::fmt::Debug>(
    number: impl Fn() -> S,
    sizes: Vec<usize>,
) -> impl Strategy<Value = String> {
    let vertex = (prop::sample::select(sizes), prop::collection::vec(number(), 5), space());
    prop::collection::vec(vertex, 0..5).prop_map(|vertices| {
        let vertices: Vec<String> = vertices
            .iter()
            .map(|(size, coordinates, gap)| {
                let coordinates: Vec<&str> = coordinates[..*size].iter().map(AsRef::as_ref).collect();
                format!("[{gap}{}{gap}]", coordinates.join(&format!("{gap},")))
            })
            .collect();
        format!("[{}]", vertices.join(", "))
    })
}

/// Coordinates mostly of the common shape, the others of any form.
fn mostly_plain_number() -> impl Strategy<Value = String> {
    prop_oneof![4 => plain_number(), 1 => any_number().prop_map(String::from)]
}

/// A polygon's text: a name or not, a value and vertices, in any order,
/// and sometimes a member more (a key twice, `opacity`, an unknown key);
/// its tokens of every form, valid or not.
fn any_polygon() -> impl Strategy<Value = String> {
    (
        (any::<bool>(), prop::collection::vec(0_usize..5, 0..2), 0_usize..5),
        any_name(),
        any_value(),
        vertex_list(mostly_plain_number, vec![2, 3, 3, 3, 4, 4, 5]),
        space(),
    )
        .prop_map(|((named, extra, order), name, value, vertices, gap)| {
            let mut keys: Vec<usize> = if named { vec![0, 1, 2] } else { vec![1, 2] };
            keys.extend(extra);
            let mut members: Vec<String> = keys
                .iter()
                .map(|&key| match key {
                    0 => format!(r#""name"{gap}:{gap}{name}"#),
                    1 => format!(r#""value":{gap}{value}"#),
                    2 => format!(r#""vertices": {vertices}"#),
                    3 => r#""opacity": 0.5"#.to_string(),
                    _ => r#""colour": 1"#.to_string(),
                })
                .collect();
            let turn = order % members.len();
            members.rotate_left(turn);
            format!("{gap}{{{gap}{}{gap}}}{gap}", members.join(&format!("{gap},{gap}")))
        })
}

/// A polygon of the common shape, its members in any order.
fn plain_polygon() -> impl Strategy<Value = String> {
    (
        prop::option::of(prop::sample::select(vec!["a", "t1", "", "caf\u{e9}", "a, {b}"])),
        0_u64..1000,
        vertex_list(plain_number, vec![3, 4]),
        any::<bool>(),
        space(),
    )
        .prop_map(|(name, value, vertices, reversed, gap)| {
            let mut members = vec![format!(r#""value":{gap}{value}"#), format!(r#""vertices":{gap}{vertices}"#)];
            if let Some(name) = name {
                members.push(format!(r#""name": "{name}""#));
            }
            if reversed {
                members.reverse();
            }
            format!("{{{gap}{}}}", members.join(&format!(",{gap}")))
        })
}

/// A scene of the common shape, or not: settings, then polygons with names
/// that hold what looks like a polygon's start, some without a name, and
/// maybe a polygon that is not valid or a setting after the list.
fn scene_text() -> impl Strategy<Value = (String, bool)> {
    let name = prop::option::of(prop::sample::select(vec![
        r#""t""#,
        r#""a, {b""#,
        r#""x\", {\"name\": \"fake\", \"value\": 1, \"vertices\": [[0, 0, 0], [9, 0, 0], [0, 9, 0]]}, {\"y""#,
        r#""}], \"width\": 9}""#,
        r#""\\""#,
    ]));
    let triangle = (name, 0_u32..4, 0_i32..50, 0_i32..50, 1_i32..9, space());
    (prop::collection::vec(triangle, 1..25), 0_u32..12, prop::sample::select(vec!["", r#""width": 64, "#]))
        .prop_map(|(triangles, flaw, settings)| {
            let polygons: Vec<String> = triangles
                .iter()
                .map(|(name, value, x, y, size, gap)| {
                    let name = name.map(|name| format!(r#""name": {name}, "#)).unwrap_or_default();
                    let (right, top) = (x + size, y + size);
                    format!(
                        r#"{gap}{{{name}"value": {value}, "vertices": [[{x}, {y}, 1], [{right}, {y}, 2],{gap}[{x}, {top}, 3]]}}"#
                    )
                })
                .collect();
            let polygons = polygons.join(",\n");
            // One scene in twelve has a polygon with a value beyond 2 bits, one a setting after the list.
            let common = flaw > 1;
            let text = match flaw {
                0 => format!(r#"{{{settings}"polygons": [{polygons}, {{"value": 9, "vertices": [[0,0,0],[1,0,0],[0,1,0]]}}]}}"#),
                1 => format!(r#"{{"polygons": [{polygons}], {settings}"height": 50}}"#),
                _ => format!("{{{settings}\"polygons\": [\n{polygons}\n]}}\n"),
            };
            (text, common)
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4096, ..ProptestConfig::default() })]

    /// Whatever the text, a polygon the strict reader reads is the one serde reads.
    #[test]
    fn the_strict_reader_reads_nothing_otherwise_than_serde(text in any_polygon()) {
        if let Some(polygon) = strict::polygon(&text) {
            let serde = serde_json::from_str::<PolygonFile>(&text);
            prop_assert!(serde.is_ok(), "serde refuses {text}: {:?}", serde.err());
            prop_assert_eq!(fields(polygon), fields(serde.unwrap()));
        }
    }

    /// A polygon of the common shape is read by the strict reader, as serde reads it.
    #[test]
    fn the_strict_reader_reads_the_common_shape(text in plain_polygon()) {
        let polygon = strict::polygon(&text);
        prop_assert!(polygon.is_some(), "not read: {}", text);
        let serde = serde_json::from_str::<PolygonFile>(&text).unwrap();
        prop_assert_eq!(fields(polygon.unwrap()), fields(serde));
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Cut anywhere, the pieces read the scene the plain way reads, or leave
    /// it to the plain way; a scene of the common shape they read.
    #[test]
    fn pieces_read_the_scene_the_plain_way_reads((text, common) in scene_text(), piece_bytes in 1_usize..400) {
        let path = Path::new("scene.json");
        let pieces = pieces::read_in(&text, path, piece_bytes);
        prop_assert_eq!(pieces.is_some(), common, "{}", text);
        if let Some(scene) = pieces {
            prop_assert_eq!(Some(scene), plain(&text, path).ok());
        }
    }
}

/// A `{` after a `,` inside a name looks like a polygon's start: a piece
/// cut there reads a polygon that is not in the scene, and is passed over.
#[test]
fn a_polygon_start_inside_a_name_is_passed_over() {
    let fake = r#"{\"name\": \"fake\", \"value\": 1, \"vertices\": [[0, 0, 0], [9, 0, 0], [0, 9, 0]]}"#;
    let text = format!(
        r#"{{"polygons": [{{"name": "first", "value": 1, "vertices": [[0, 0, 0], [5, 0, 0], [0, 5, 0]]}},
            {{"name": "x, {fake}, {fake}", "value": 2, "vertices": [[1, 1, 1], [6, 1, 1], [1, 6, 1]]}},
            {{"value": 3, "vertices": [[2, 2, 2], [7, 2, 2], [2, 7, 2]]}}]}}"#
    );
    // The second piece cut just after the name's `x`, before its `, {`.
    let piece_bytes = text.find("x, {").unwrap() + 1 - (text.find("[{").unwrap() + 1);
    let scene = pieces::read_in(&text, Path::new("scene.json"), piece_bytes).unwrap();
    let names: Vec<&str> = scene.polygons.iter().map(|polygon| polygon.name.as_str()).collect();
    assert_eq!(names.len(), 3);
    assert_eq!(names[0], "first");
    assert!(names[1].starts_with("x, {"));
    assert_eq!(names[2], crate::words::default_name(2));
    assert_eq!(Ok(scene), plain(&text, Path::new("scene.json")).map_err(|error| error.message(Lang::En)));
}

/// Past 18 digits a coordinate is no longer summed as it is scanned: the
/// bounds of `i64` and `u64` and beyond are read as serde reads them.
#[test]
fn long_integers_are_read_as_serde_reads_them() {
    for number in ["-9223372036854775808", "-9223372036854775809", "18446744073709551615", "18446744073709551616"] {
        let text = format!(r#"{{"value": 1, "vertices": [[{number}, 0, 0]]}}"#);
        let strict = strict::polygon(&text).map(fields);
        assert_eq!(strict, Some(fields(serde_json::from_str::<PolygonFile>(&text).unwrap())), "{number}");
    }
}

/// A scene that is not read is refused as facts, read with no language:
/// where (a polygon and the path within it, a line, where a comma belongs),
/// what (a setting's key and values), and serde's own description, which is
/// worded only where it is shown.
#[test]
fn a_refused_scene_is_facts_worded_where_shown() {
    use super::refused::{FormatProblem, JsonKind, MissingComma, Place, SceneProblem, SceneRefused, SettingProblem};
    let problem = |text: &str| {
        let error = super::read(text, Path::new("s.json")).unwrap_err();
        let refused = error.refused::<SceneRefused>().expect("a scene's refusal").clone();
        assert_eq!(refused.path, Path::new("s.json"));
        (refused.problem, error.message(Lang::Ru))
    };
    assert_eq!(problem("[1, 2]").0, SceneProblem::NotObject(JsonKind::Array));
    let (frame_bits, russian) = problem(r#"{"frame_bits": 33, "polygons": []}"#);
    assert_eq!(frame_bits, SceneProblem::Setting { key: "frame_bits", problem: SettingProblem::Bits(33) });
    assert!(russian.starts_with("s.json: frame_bits: 33 "), "{russian}");
    let (window, _) = problem(r#"{"window": {"left": 2, "right": 1, "bottom": 0, "top": "1/2"}, "polygons": []}"#);
    let q = |n: i128, d: i128| crate::numbers::Q::new(n, d);
    let sides = [q(2, 1), q(1, 1), q(0, 1), q(1, 2)];
    assert_eq!(window, SceneProblem::Setting { key: "window", problem: SettingProblem::Window { sides } });
    let (wrong_type, _) = problem("{\"polygons\": [{\"value\": 1, \"vertices\": [[0, 0, 0], [1, 0, \"x\"]]}]}");
    let SceneProblem::Format(FormatProblem { place, line, syntax, comma, .. }) = wrong_type else {
        panic!("a format problem: {wrong_type:?}")
    };
    assert_eq!(place, Some(Place { polygon: Some(0), path: "vertices[1][2]".into() }));
    assert_eq!((line, syntax, comma), (Some(1), false, None));
    let (no_comma, english) = {
        let text = "{\n  \"width\": 4\n  \"polygons\": []\n}";
        let error = super::read(text, Path::new("s.json")).unwrap_err();
        (error.refused::<SceneRefused>().unwrap().problem.clone(), error.message(Lang::En))
    };
    let SceneProblem::Format(FormatProblem { place: None, line: Some(3), syntax: true, comma, .. }) = no_comma else {
        panic!("a syntax problem on line 3: {no_comma:?}")
    };
    assert_eq!(comma, Some(MissingComma::EndOfLine(2)));
    assert!(english.ends_with("(a comma is missing at the end of line 2)"), "{english}");
}
