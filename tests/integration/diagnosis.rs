//! The misconception behind a wrong answer is named: each answer here is made
//! by a wrong rule without the diagnosis's own code (a changed scene drawn by
//! zsim, a file written by hand, or the book's plane evaluated in the test),
//! and the diagnosis must name that rule and explain every wrong cell.

use std::path::Path;

use zsim::check::Answer;
use zsim::diagnose::{Misconception, diagnose};
use zsim::{Scene, Simulation, Unobserved};

type Matrix = Vec<Vec<u32>>;

fn rogers_text() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/rogers.json")).unwrap()
}

/// The buffers (rows top first) of a scene given as JSON, after polygon `last` (all when `None`).
fn drawn(json: &str, last: Option<usize>) -> (Matrix, Matrix) {
    let scene = Scene::from_json(json, Path::new("s.json")).unwrap();
    let mut simulation = Simulation::new(&scene);
    match last {
        Some(last) => simulation.draw_through(last, &mut Unobserved),
        None => simulation.finish(&mut Unobserved),
    }
    (simulation.buffers().frame_rows(), simulation.buffers().depth_level_rows().unwrap())
}

/// The book's scene with one top-level setting added.
fn rogers_with(setting: &str) -> String {
    rogers_text().replacen('{', &format!("{{ {setting},"), 1)
}

fn named(scene_json: &str, frame: &Matrix, depth: &Matrix) -> (Misconception, usize, usize) {
    let scene = Scene::from_json(scene_json, Path::new("s.json")).unwrap();
    let last = scene.polygons.len() - 1;
    let (frame, depth) = (Answer::complete(frame.clone()), Answer::complete(depth.clone()));
    let found = diagnose(&scene, last, Some(&frame), Some(&depth)).expect("a misconception is named");
    (found.misconception, found.explained, found.wrong)
}

/// The triangle's exact depth at pixel (x, y)'s centre: z = (120 − 3x − y)/4
/// with x, y at the centre, as a fraction n/8.
fn triangle_z_eighths(x: usize, y: usize) -> i64 {
    // 4z = 120 − 3(x + 1/2) − (y + 1/2)  ⇒  8z = 240 − 6x − 3 − 2y − 1.
    240 - 6 * x as i64 - 2 * y as i64 - 4
}

#[test]
fn each_wrong_rule_is_named_on_the_books_example() {
    let rogers = rogers_text();
    let (frame, depth) = drawn(&rogers, None);
    let height = frame.len();
    let mut cases: Vec<(Misconception, Matrix, Matrix)> = Vec::new();
    // Scenes changed as the wrong rule changes them, drawn by zsim.
    let scene_rules = [
        (Misconception::NotStrict, rogers.replace(r#""depth_test": "greater""#, r#""depth_test": "greater-equal""#)),
        (Misconception::Reversed, rogers.replace(r#""depth_test": "greater""#, r#""depth_test": "less""#)),
        (Misconception::CellRule, rogers_with(r#""rules": {"columns": "cell"}"#)),
        (
            Misconception::Corners,
            rogers_with(r#""window": {"left": -0.5, "right": 31.5, "bottom": -0.5, "top": 31.5}"#),
        ),
    ];
    for (misconception, json) in scene_rules {
        let (f, d) = drawn(&json, None);
        cases.push((misconception, f, d));
    }
    let (f, d) = drawn(&rogers, Some(0));
    cases.push((Misconception::OneEarly, f, d));
    let triangle_alone = rogers_text().replace(
        r#"{"name": "rectangle", "value": 1, "vertices": [[10, 5, 10], [10, 25, 10], [25, 25, 10], [25, 5, 10]]},"#,
        "",
    );
    let (f, d) = drawn(&triangle_alone, None);
    cases.push((Misconception::LastOnly, f, d));
    cases.push((
        Misconception::BottomFirst,
        frame.iter().rev().cloned().collect(),
        depth.iter().rev().cloned().collect(),
    ));
    // The depth rules, from the triangle's plane: where the triangle shows,
    // its depth stored otherwise; where it was hidden or won by less than a
    // half against the rectangle, the compare on the rounded level.
    let (mut truncated, mut half_down, mut rounded_frame, mut rounded_depth) =
        (depth.clone(), depth.clone(), frame.clone(), depth.clone());
    for (row, cells) in frame.iter().enumerate() {
        let y = height - 1 - row;
        for (x, &value) in cells.iter().enumerate() {
            let eighths = triangle_z_eighths(x, y);
            if value == 2 {
                truncated[row][x] = (eighths.div_euclid(8)).clamp(0, 15) as u32;
                // Halves (z = k + 1/2, eighths ≡ 4 mod 8) go down.
                if eighths.rem_euclid(8) == 4 {
                    half_down[row][x] -= 1;
                }
                // Over the rectangle (stored 10) a depth that rounds to 10 does not pass 10 > 10.
                let over_rectangle = (10..25).contains(&x) && (5..25).contains(&y);
                if over_rectangle && (eighths + 4).div_euclid(8) == 10 {
                    rounded_frame[row][x] = 1;
                    rounded_depth[row][x] = 10;
                }
            }
        }
    }
    cases.push((Misconception::Truncated, frame.clone(), truncated.clone()));
    cases.push((Misconception::HalfDown, frame.clone(), half_down));
    cases.push((Misconception::RoundedCompared, rounded_frame, rounded_depth));
    // The file written for the class example by hand agrees with the plane.
    let bo =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/class/bo.depth.txt")).unwrap();
    let bo: Matrix = bo.lines().map(|l| l.split_whitespace().map(|v| v.parse().unwrap()).collect()).collect();
    assert_eq!(bo, truncated);
    let mut found = Vec::new();
    for (misconception, f, d) in &cases {
        let (name, explained, wrong) = named(&rogers, f, d);
        assert!(wrong > 0, "{misconception:?} changes the answer");
        found.push((*misconception, name, explained == wrong));
    }
    let expected: Vec<_> = cases.iter().map(|(m, ..)| (*m, *m, true)).collect();
    assert_eq!(found, expected);
}

/// Depths beyond a 4-bit range wrap around: the same scene on 8 bits, each
/// level taken modulo 16.
#[test]
fn wrapping_instead_of_saturating_is_named() {
    let scene = r#"{"width": 16, "height": 16, "polygons": [
        {"name": "ramp", "value": 1, "vertices": [[0, 0, 4], [16, 0, 24], [16, 16, 24], [0, 16, 4]]}]}"#;
    let (frame, _) = drawn(scene, None);
    let (_, wide) = drawn(&scene.replacen('{', r#"{"depth_bits": 8,"#, 1), None);
    let wrapped: Matrix = wide.iter().map(|row| row.iter().map(|v| v % 16).collect()).collect();
    let (name, explained, wrong) = named(scene, &frame, &wrapped);
    assert_eq!((name, explained == wrong), (Misconception::NoSaturation, true));
}

/// A right answer has no misconception, and a few scattered slips are not
/// blamed on a rule.
#[test]
fn a_right_answer_or_a_few_slips_name_nothing() {
    let rogers = rogers_text();
    let scene = Scene::from_json(&rogers, Path::new("s.json")).unwrap();
    let (frame, mut depth) = drawn(&rogers, None);
    let read = |m: &Matrix| Some(Answer::complete(m.clone()));
    assert_eq!(diagnose(&scene, 1, read(&frame).as_ref(), read(&depth).as_ref()), None);
    depth[3][3] = 7;
    depth[30][1] = 2;
    assert_eq!(diagnose(&scene, 1, read(&frame).as_ref(), read(&depth).as_ref()), None);
}

/// Found by a teacher: a sheet handed in blank (every cell the cleared
/// value) was labelled "only the last polygon drawn". It follows no rule.
#[test]
fn a_blank_sheet_names_no_misconception() {
    let rogers = rogers_text();
    let scene = Scene::from_json(&rogers, Path::new("s.json")).unwrap();
    let (frame, depth) = drawn(&rogers, None);
    let (blank_frame, blank_depth) = (vec![vec![0; 32]; 32], vec![vec![0; 32]; 32]);
    assert_ne!((&frame, &depth), (&blank_frame, &blank_depth), "the scene draws something");
    let (frame, depth) = (Answer::complete(blank_frame), Answer::complete(blank_depth));
    assert_eq!(diagnose(&scene, 1, Some(&frame), Some(&depth)), None);
    assert_eq!(diagnose(&scene, 1, Some(&frame), None), None);
}
