//! The lesson's rules, one test each, on the book's triangle (polygon 2,
//! scanline 15.5: columns 15 … 27, the centre of 15 on its left edge).

use super::*;
use crate::observe::tracer::Stop;

fn book() -> Scene {
    Scene::load(std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/rogers.json"))).unwrap()
}

/// The triangle's scanline 15.5 (its sixth recorded scanline: rows 10 … 15).
const TRIANGLE_15: Stop = Stop { polygon: 1, scanline: 5 };

fn lesson(mode: QuizMode) -> Lesson {
    let mut lesson = Lesson::new(book(), Arith::Exact, Some(mode));
    lesson.start(Some(TRIANGLE_15));
    lesson
}

fn answer(lesson: &mut Lesson, typed: &str) -> Said {
    lesson.act(Lang::En, Command::Answer(typed.to_string()))
}

fn hint_of(said: &Said) -> Hint {
    match said {
        Said::TryAgain { hint, .. } => *hint,
        other => panic!("no hint: {other:?}"),
    }
}

/// Everything a front end may show of the stop, as one text.
fn shown(lesson: &mut Lesson) -> String {
    let view = lesson.stop_view(Lang::En).unwrap();
    let rows: Vec<String> =
        view.rows.iter().map(|r| format!("{} {} {} {} {}", r.x, r.z, r.test, r.after, r.frame)).collect();
    format!(
        "{}\n{:?}\n{}\n{:?}\n{}\n{}",
        view.slope,
        view.crossings,
        view.spans.join("\n"),
        view.columns,
        rows.join("\n"),
        view.notes.join("\n")
    )
}

#[test]
fn while_coverage_is_asked_the_crossings_spans_and_columns_are_hidden() {
    let mut lesson = lesson(QuizMode::Coverage);
    assert_eq!(lesson.showing(), Showing { spans: false, pixels: 0, covered: 13 });
    let view = lesson.stop_view(Lang::En).unwrap();
    // Not even how many centres are covered: that is the answer's length.
    assert_eq!((view.crossings, view.spans, view.columns, view.rows.len(), view.hidden), (None, vec![], vec![], 0, 0));
    // The buffers: the triangle's rows before this one, none of this row's pixels.
    let buffers = lesson.buffers().unwrap();
    let before = lesson.with_stepper(|stepper| stepper.tracer().buffers_through(TRIANGLE_15, 0));
    assert_eq!(buffers.frame_rows(), before.frame_rows());
    assert!(matches!(answer(&mut lesson, "15-27"), Said::Right { second_try: false, .. }));
    let view = lesson.stop_view(Lang::En).unwrap();
    assert_eq!(view.columns, (15..=27).collect::<Vec<_>>());
}

#[test]
fn while_a_depth_is_asked_that_pixels_z_and_the_rest_are_hidden() {
    let mut lesson = lesson(QuizMode::Depth);
    // (15, 15): z = 29/2, which is also the span's left end depth.
    let text = shown(&mut lesson);
    assert!(!text.contains("29/2") && !text.contains("14.5"), "{text}");
    assert!(matches!(answer(&mut lesson, "15"), Said::Right { second_try: false, .. }));
    // (16, 15): z = 55/4 stays hidden; (15, 15) is shown.
    let text = shown(&mut lesson);
    assert!(text.contains("15 29/2") && !text.contains("55/4"), "{text}");
    assert_eq!(lesson.showing().pixels, 1);
}

#[test]
fn a_wrong_answer_gets_its_kind_first_then_the_answer_with_its_reason() {
    let mut lesson = lesson(QuizMode::Depth);
    // (15, 15): z = 29/2 rounds half up to 15; 14 is the half rounded down.
    let said = answer(&mut lesson, "14");
    assert_eq!(hint_of(&said), Hint::Misconception(Misconception::HalfDown));
    let text = said.text(Lang::En, lesson.scene());
    assert!(!text.contains("15") && !text.contains("29/2"), "the hint names no value: {text}");
    assert!(lesson.second_try());
    assert!(lesson.prompt(Lang::En).unwrap().starts_with("last try: pixel (15, 15)"));
    let Said::Revealed(verdict) = answer(&mut lesson, "13") else { panic!("not revealed") };
    assert_eq!(verdict.expected, "15");
    assert_eq!(lesson.score(), Some(Score { revealed: 1, ..Score::default() }));
    // (16, 15): z = 55/4 = 13.75; 13 is truncated. Then right at the second try.
    assert_eq!(hint_of(&answer(&mut lesson, "13")), Hint::Misconception(Misconception::Truncated));
    assert!(matches!(answer(&mut lesson, "14"), Said::Right { second_try: true, .. }));
    assert_eq!(lesson.score(), Some(Score { second_try: 1, revealed: 1, ..Score::default() }));
}

#[test]
fn the_depth_test_reversed_and_the_rounded_depth_compared_are_named() {
    let mut lesson = lesson(QuizMode::Depth);
    for typed in ["15", "14", "13", "12", "12", "11", "10"] {
        assert!(matches!(answer(&mut lesson, typed), Said::Right { .. }), "{typed}");
    }
    // (22, 15): z = 37/4 behind the stored 10; 9 stores the pixel's own depth.
    assert_eq!(hint_of(&answer(&mut lesson, "9")), Hint::IsNotWritten);
    // (20, 17): z = 41/4 passes 10 yet rounds to 10: "not written" compares the rounded depth.
    lesson.act(Lang::En, Command::Skip);
    assert!(matches!(lesson.act(Lang::En, Command::GoTo { polygon: 1, row: 17 }), Said::Moved(Moved::To { .. })));
    loop {
        let Some(Question::Depth { pixel, .. }) = lesson.question() else { panic!("no depth question") };
        if pixel.x == 20 {
            break;
        }
        let right = pixel.stored_after.text(Lang::En);
        assert!(matches!(answer(&mut lesson, &right), Said::Right { .. }));
    }
    assert_eq!(hint_of(&answer(&mut lesson, "-")), Hint::Misconception(Misconception::RoundedCompared));
}

#[test]
fn an_equal_depth_written_is_named_not_strict() {
    let mut lesson = lesson(QuizMode::Frame);
    for _ in 15..21 {
        assert!(matches!(answer(&mut lesson, "2"), Said::Right { .. }));
    }
    // (21, 15): z = 10 equals the stored 10, so the rectangle's 1 stays.
    assert_eq!(hint_of(&answer(&mut lesson, "2")), Hint::Misconception(Misconception::NotStrict));
}

/// Found by a student: for the triangle's row 10 (right: 28-29), `10-20`
/// was told "a centre lies exactly on the polygon's boundary"; `6` for
/// z = 21/4 got only "compute z … then round". A hint names a mistake only
/// where a known wrong rule gives exactly the answer; otherwise "not yet".
#[test]
fn a_hint_names_a_mistake_only_where_a_wrong_rule_gives_exactly_the_answer() {
    // Row 15 covers 15 … 27, the centre of 15 on the left edge; row 14 covers 16 … 28.
    let coverage = [
        ("16-27", Hint::CentreOnBoundary),
        ("16-28", Hint::NeighbouringRow),
        ("15-26", Hint::Other),
        ("15-28", Hint::Other),
        ("10-20", Hint::Other),
    ];
    for (typed, hint) in coverage {
        let mut lesson = lesson(QuizMode::Coverage);
        assert_eq!(hint_of(&answer(&mut lesson, typed)), hint, "{typed}");
    }
    // (15, 15): z = 29/2, right 15.
    let depth = [("14", Hint::Misconception(Misconception::HalfDown)), ("13", Hint::Other), ("12", Hint::Other)];
    for (typed, hint) in depth {
        let mut lesson = lesson(QuizMode::Depth);
        assert_eq!(hint_of(&answer(&mut lesson, typed)), hint, "{typed}");
    }
    // A square at z = 21/4: right 5; 6 is rounded up.
    let text = r#"{"width": 2, "height": 2, "polygons": [{"value": 1, "vertices": [[0, 0, 5.25], [2, 0, 5.25], [2, 2, 5.25], [0, 2, 5.25]]}]}"#;
    let scene = Scene::from_json(text, std::path::Path::new("s.json")).unwrap();
    for (typed, hint) in [("6", Hint::RoundedUp), ("7", Hint::Other)] {
        let mut lesson = Lesson::new(scene.clone(), Arith::Exact, Some(QuizMode::Depth));
        lesson.start(None);
        assert_eq!(hint_of(&answer(&mut lesson, typed)), hint, "{typed}");
    }
    let mut lesson = lesson(QuizMode::Depth);
    let said = answer(&mut lesson, "13").text(Lang::En, lesson.scene());
    assert_eq!(said, "13: not yet (one more try)");
}

#[test]
fn every_notation_zsim_prints_is_taken_back() {
    for typed in ["15 … 27", "15-27", "15..27", "15...27", "15 - 27"] {
        let mut lesson = lesson(QuizMode::Coverage);
        assert!(matches!(answer(&mut lesson, typed), Said::Right { .. }), "{typed}");
    }
}

#[test]
fn moving_on_is_refused_while_questions_are_open_until_skipped() {
    let mut lesson = lesson(QuizMode::Coverage);
    for command in [Command::Next, Command::Back, Command::NextPolygon, Command::PreviousPolygon, Command::Go(16)] {
        let said = lesson.act(Lang::En, command.clone());
        assert!(
            matches!(said, Said::Moved(Moved::Refused(RefusedMove::QuestionsOpen { open: 14 }))),
            "{command:?}: {said:?}"
        );
    }
    assert_eq!(lesson.at(), Some(TRIANGLE_15));
    assert!(matches!(lesson.act(Lang::En, Command::Skip), Said::Skipped(14)));
    assert_eq!(lesson.showing(), Showing { spans: true, pixels: 13, covered: 13 });
    assert!(matches!(lesson.act(Lang::En, Command::Next), Said::Moved(Moved::To { at: Some(_), .. })));
    assert_eq!(lesson.score(), Some(Score { skipped: 14, ..Score::default() }));
    assert_eq!(lesson.open_questions(), 13, "the next scanline (columns 16 … 27) asks again");
}

/// A depth beyond the z-buffer's range, not saturated, is a mistake named as
/// such, not a value "no cell can hold" asked again.
#[test]
fn an_unsaturated_depth_is_a_mistake_named_as_such() {
    let text = r#"{"width": 4, "height": 4, "polygons": [{"value": 1, "vertices": [[0, 0, 20], [4, 0, 20], [4, 4, 20], [0, 4, 20]]}]}"#;
    let scene = Scene::from_json(text, std::path::Path::new("s.json")).unwrap();
    let mut lesson = Lesson::new(scene, Arith::Exact, Some(QuizMode::Depth));
    lesson.start(None);
    assert!(matches!(answer(&mut lesson, "99"), Said::AskAgain(_)));
    assert!(matches!(answer(&mut lesson, "x"), Said::AskAgain(_)));
    assert_eq!(hint_of(&answer(&mut lesson, "20")), Hint::Misconception(Misconception::NoSaturation));
    assert!(matches!(answer(&mut lesson, "15"), Said::Right { second_try: true, .. }));
}

#[test]
fn the_keys_are_one_table() {
    assert_eq!(Command::parse(""), Command::Next);
    assert_eq!(Command::parse(" n "), Command::Next);
    assert_eq!(Command::parse("P"), Command::PreviousPolygon);
    assert_eq!(Command::parse("g 12"), Command::Go(12));
    assert_eq!(Command::parse("-"), Command::Answer("-".into()));
    assert_eq!(Command::parse("28 … 29"), Command::Answer("28 … 29".into()));
    for (key, _) in KEYS {
        assert_eq!(Command::parse(&key.to_string()), Command::from_key(key).unwrap());
    }
}

#[test]
fn the_summary_counts_each_way_a_question_ended() {
    let mut lesson = lesson(QuizMode::Depth);
    answer(&mut lesson, "15");
    answer(&mut lesson, "13");
    answer(&mut lesson, "14");
    answer(&mut lesson, "1");
    answer(&mut lesson, "2");
    lesson.act(Lang::En, Command::Skip);
    let summary = lesson.summary(Lang::En);
    assert!(
        summary.starts_with(
            "quiz: 1 right at the first try, 1 at the second, 1 shown, 10 skipped, of 13 questions\nyour mistakes:\n  (17, 15) of polygon 2 \"triangle\": you said 2, right 13: "
        ),
        "{summary}"
    );
}

#[test]
fn a_skip_with_nothing_open_says_so_and_counts_nothing() {
    let mut lesson = Lesson::new(book(), Arith::Exact, None);
    lesson.start(None);
    let said = lesson.act(Lang::En, Command::Skip);
    assert!(matches!(said, Said::Skipped(0)));
    assert_eq!(said.text(Lang::En, lesson.scene()), "no question is open here: nothing to skip");
    assert_eq!(lesson.score(), None);
}

/// Found by a student: a question whose answer was shown was asked again
/// when its scanline was come back to, and then counted as right at the
/// first try; one answered once and left open at `q` was not counted; and
/// the score said "of 1 questions".
#[test]
fn each_question_counts_once_come_back_to_or_left_open_at_quit() {
    let mut lesson = lesson(QuizMode::Depth);
    assert!(matches!(answer(&mut lesson, "14"), Said::TryAgain { .. }));
    assert!(matches!(answer(&mut lesson, "13"), Said::Revealed(_)));
    assert!(matches!(lesson.act(Lang::En, Command::Skip), Said::Skipped(12)));
    assert!(matches!(lesson.act(Lang::En, Command::Next), Said::Moved(Moved::To { .. })));
    assert!(matches!(lesson.act(Lang::En, Command::Skip), Said::Skipped(_)));
    let before = lesson.score();
    assert!(matches!(lesson.act(Lang::En, Command::Back), Said::Moved(Moved::To { .. })));
    assert_eq!(lesson.at(), Some(TRIANGLE_15));
    assert_eq!(lesson.open_questions(), 0, "its questions ended: its answers are shown");
    assert!(matches!(answer(&mut lesson, "15"), Said::NothingAsked(_)));
    assert_eq!(lesson.score(), before);
    let mut lesson = self::lesson(QuizMode::Depth);
    assert!(matches!(answer(&mut lesson, "14"), Said::TryAgain { .. }));
    assert!(matches!(lesson.act(Lang::En, Command::Quit), Said::Quit));
    let score = lesson.score().unwrap();
    assert_eq!((score.skipped, score.asked()), (1, 1));
    assert_eq!(
        score.text(Lang::En),
        "quiz: 0 right at the first try, 0 at the second, 0 shown, 1 skipped, of 1 question"
    );
}
