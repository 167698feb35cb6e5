//! Naming the misconception behind a wrong answer: the scene is drawn again
//! under each of the usual wrong rules, and the rule whose buffers agree with
//! the student's wrong cells best (and contradict their right ones least) is
//! named, with how many of the wrong cells it explains.
//!
//! Most wrong rules are rules the rasterizer takes as data, so a changed copy
//! of the scene is drawn by the one rasterizer: pixel corners, the cell rule,
//! the test reversed or not strict, depths truncated (`store: truncated`),
//! the rounded depth compared (`compare: level`), the last polygon alone. Two
//! are no rule of any course: rounding halves down and wrapping instead of
//! saturating replay the pixels the rasterizer covered, with the exact depth
//! it computed at each, under that store. The rest need no drawing: the
//! answer one polygon early, rows written bottom first.

use crate::numbers::{Q, floor_div};
use crate::raster::depth::{Depth, DepthTest, Stored};
use crate::rules::{ColumnRule, Compare, DepthStore};
use crate::scene::Scene;
use crate::simulate::events::{Observer, Outcome, PixelEvent};
use crate::simulate::simulation::Simulation;
use crate::teach::check::answer::{Answer, HINTED_CELLS, Matrix};
use crate::words::Lang;

/// A wrong rule students are known to follow.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Misconception {
    /// z truncated (rounded down) instead of rounded to the nearest integer.
    Truncated,
    /// Halves rounded down (10.5 stored as 10).
    HalfDown,
    /// The rounded depth compared with the stored level instead of the exact z.
    RoundedCompared,
    /// Depths beyond the z-buffer's range wrap around instead of saturating.
    NoSaturation,
    /// An equal depth passes the test (≥ instead of >).
    NotStrict,
    /// The test reversed: smaller z nearer, the buffer cleared to its largest level.
    Reversed,
    /// Only the last polygon drawn, on cleared buffers.
    LastOnly,
    /// The whole answer one polygon early.
    OneEarly,
    /// The rows written bottom row first.
    BottomFirst,
    /// Sampled at pixel corners (integer points) instead of centres.
    Corners,
    /// Columns by the cell that holds the crossing instead of the centres inside the span.
    CellRule,
}

impl Misconception {
    /// Every misconception, in the order ties are decided.
    pub const ALL: [Misconception; 11] = [
        Misconception::Truncated,
        Misconception::HalfDown,
        Misconception::RoundedCompared,
        Misconception::NoSaturation,
        Misconception::NotStrict,
        Misconception::Reversed,
        Misconception::OneEarly,
        Misconception::LastOnly,
        Misconception::BottomFirst,
        Misconception::Corners,
        Misconception::CellRule,
    ];

    /// Its name in CSV and JSON (the same in every language).
    pub fn name(self) -> &'static str {
        match self {
            Misconception::Truncated => "truncated",
            Misconception::HalfDown => "half-down",
            Misconception::RoundedCompared => "rounded-compared",
            Misconception::NoSaturation => "no-saturation",
            Misconception::NotStrict => "not-strict",
            Misconception::Reversed => "reversed",
            Misconception::LastOnly => "last-only",
            Misconception::OneEarly => "one-early",
            Misconception::BottomFirst => "bottom-first",
            Misconception::Corners => "corners",
            Misconception::CellRule => "cell-rule",
        }
    }

    /// What the student did, in the reader's language.
    pub fn words(self, lang: Lang) -> String {
        words!(lang, &format!("misconception-{}", self.name()))
    }
}

/// The misconception that explains an answer best.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Diagnosis {
    /// The wrong rule.
    pub misconception: Misconception,
    /// How many wrong cells it gives exactly as the student wrote them.
    pub explained: usize,
    /// How many cells are wrong.
    pub wrong: usize,
}

impl Diagnosis {
    /// One sentence: the rule and how many wrong cells it explains.
    pub fn words(&self, lang: Lang) -> String {
        words!(lang, "diagnosis", what = self.misconception.words(lang), explained = self.explained, wrong = self.wrong)
    }
}

/// The buffers (framebuffer, z-buffer; rows top first) after polygon `last`.
type State = (Matrix, Matrix);

/// The misconception that best explains a student's answer to `scene` after
/// polygon `last` (either buffer may be missing); see [`Diagnoser::diagnose`].
pub fn diagnose(scene: &Scene, last: usize, frame: Option<&Answer>, depth: Option<&Answer>) -> Option<Diagnosis> {
    Diagnoser::new(scene, last)?.diagnose(frame, depth)
}

/// The right buffers and those of every wrong rule, for one scene and
/// polygon, drawn once and then held against any number of answers.
#[derive(Debug, Clone)]
pub struct Diagnoser {
    right: State,
    cleared: (u32, u32),
    candidates: Vec<(Misconception, State)>,
}

impl Diagnoser {
    /// Draws the scene under every wrong rule; `None` when the scene is
    /// outside what they are defined for (an exact z-buffer, per-pixel
    /// effects, a test other than `greater` or `less`) or larger than
    /// [`HINTED_CELLS`] (the diagnosis holds the buffers of every wrong rule
    /// at once).
    pub fn new(scene: &Scene, last: usize) -> Option<Diagnoser> {
        let cells = u64::from(scene.width) * u64::from(scene.height);
        if !applies(scene) || last >= scene.polygons.len() || cells > HINTED_CELLS {
            return None;
        }
        let right = state(scene, last);
        let covered = covered_pixels(scene, last);
        let mut candidates: Vec<(Misconception, State)> = Misconception::ALL
            .into_iter()
            .filter_map(|m| buffers_under(m, scene, last, &right, &covered).map(|state| (m, state)))
            .collect();
        // The reversed test's common form: the other depth kept, but a cell nothing was drawn in
        // yet takes the first polygon there whatever its depth (the buffer never cleared to the
        // far end), and keeps showing the cleared value until then.
        candidates.extend(reversed_from_empty(scene, &covered).map(|state| (Misconception::Reversed, state)));
        candidates.retain(|(_, state)| *state != right);
        let cleared = (scene.background, scene.clear_depth.level()?);
        Some(Diagnoser { right, cleared, candidates })
    }

    /// For every wrong rule of [`Misconception::ALL`], how many cells of the
    /// two buffers its answer differs from the right one in: the fewest over
    /// its forms (the reversed test has two), 0 where it gives the right
    /// answer or does not apply. A rule that differs in no cell cannot be
    /// told from a right answer; one that differs in few is easily missed.
    pub fn separations(&self) -> Vec<(Misconception, usize)> {
        Misconception::ALL
            .into_iter()
            .map(|m| {
                let forms = self.candidates.iter().filter(|(c, _)| *c == m);
                let differing = |state: &State| {
                    let cells = |a: &Matrix, b: &Matrix| {
                        a.iter().flatten().zip(b.iter().flatten()).filter(|(x, y)| x != y).count()
                    };
                    cells(&state.0, &self.right.0) + cells(&state.1, &self.right.1)
                };
                (m, forms.map(|(_, state)| differing(state)).min().unwrap_or(0))
            })
            .collect()
    }

    /// The misconception whose buffers explain the most wrong cells net of
    /// the right cells they contradict, or `None`: for a right answer, or when
    /// no rule explains at least half the wrong cells and more of them than
    /// it contradicts right ones. Ties go to the earlier in [`Misconception::ALL`].
    /// A blank sheet (every answered cell the cleared value) follows no rule:
    /// it is `None` too. Cells left unanswered count for nothing.
    pub fn diagnose(&self, frame: Option<&Answer>, depth: Option<&Answer>) -> Option<Diagnosis> {
        let wrong = wrong_cells(&self.right, frame, depth);
        if wrong == 0 || is_blank(self.cleared, &self.right, frame, depth) {
            return None;
        }
        let mut best: Option<(i64, Diagnosis)> = None;
        for (misconception, under_rule) in &self.candidates {
            let (explained, contradicted) = explained_cells(&self.right, under_rule, frame, depth);
            let score = explained as i64 - contradicted as i64;
            if explained * 2 >= wrong && explained > contradicted && best.is_none_or(|(s, _)| score > s) {
                best = Some((score, Diagnosis { misconception: *misconception, explained, wrong }));
            }
        }
        best.map(|(_, diagnosis)| diagnosis)
    }
}

/// Whether the wrong rules are defined for the scene: the book's quantized
/// z-buffer, no per-pixel effects, a strict `greater` or `less` test.
fn applies(scene: &Scene) -> bool {
    scene.rules.store == DepthStore::Quantized
        && !scene.has_pixel_effects()
        && matches!(scene.depth_test, DepthTest::Greater | DepthTest::Less)
        && scene.clear_depth.level().is_some()
}

/// (explained, contradicted): the student's wrong cells that `rule` gives as
/// written, and the right cells where `rule` gives something else.
fn explained_cells(right: &State, rule: &State, frame: Option<&Answer>, depth: Option<&Answer>) -> (usize, usize) {
    let mut counts = (0, 0);
    for (answer, correct, under_rule) in [(frame, &right.0, &rule.0), (depth, &right.1, &rule.1)] {
        let Some(answer) = answer else { continue };
        for (i, x, a, c) in answer.cells(correct) {
            let r = under_rule[i][x];
            if a != c && a == r {
                counts.0 += 1;
            } else if a == c && r != c {
                counts.1 += 1;
            }
        }
    }
    counts
}

/// How many answered cells of the answers differ from `right`.
fn wrong_cells(right: &State, frame: Option<&Answer>, depth: Option<&Answer>) -> usize {
    [(frame, &right.0), (depth, &right.1)]
        .into_iter()
        .filter_map(|(answer, correct)| answer.map(|a| (a, correct)))
        .map(|(a, c)| a.cells(c).filter(|(_, _, a, c)| a != c).count())
        .sum()
}

/// Whether every answered cell holds its buffer's cleared value (the
/// background, the clear depth): a sheet handed in blank.
fn is_blank(cleared: (u32, u32), right: &State, frame: Option<&Answer>, depth: Option<&Answer>) -> bool {
    [(frame, &right.0, cleared.0), (depth, &right.1, cleared.1)]
        .into_iter()
        .filter_map(|(answer, correct, clear)| answer.map(|a| (a, correct, clear)))
        .all(|(a, c, clear)| a.cells(c).all(|(_, _, a, _)| a == clear))
}

/// The right buffers after polygon `last` (before any when `last` is `None`).
fn state_through(scene: &Scene, last: Option<usize>) -> State {
    let mut simulation = Simulation::new(scene);
    if let Some(last) = last {
        simulation.draw_through(last, &mut crate::simulate::events::Unobserved);
    }
    let buffers = simulation.buffers();
    (buffers.frame_rows(), buffers.depth_level_rows().expect("a quantized z-buffer"))
}

fn state(scene: &Scene, last: usize) -> State {
    state_through(scene, Some(last))
}

/// Every covered pixel centre the rasterizer tested, in order: polygon,
/// column, row and the exact depth compared there.
struct Covered(Vec<(usize, u32, u32, Depth)>);

impl Observer for Covered {
    const OBSERVES_SCANLINES: bool = false;
    const OBSERVES_POLYGONS: bool = false;

    fn pixel(&mut self, event: &PixelEvent) {
        if event.outcome != Outcome::OutsideDepthRange {
            self.0.push((event.index, event.x, event.y, event.compared.clone()));
        }
    }
}

fn covered_pixels(scene: &Scene, last: usize) -> Covered {
    let mut covered = Covered(Vec::new());
    Simulation::new(scene).draw_through(last, &mut covered);
    covered
}

/// The buffers `misconception` gives, or `None` where it does not apply (or
/// gives the right answer's twin, as reversing a test the scene already reverses).
fn buffers_under(
    misconception: Misconception,
    scene: &Scene,
    last: usize,
    right: &State,
    covered: &Covered,
) -> Option<State> {
    let max = scene.depth_max();
    // A copy of the scene under other rules, drawn by the one rasterizer.
    let drawn_as = |change: &dyn Fn(&mut Scene)| {
        let mut changed = scene.clone();
        change(&mut changed);
        state(&changed, last)
    };
    match misconception {
        Misconception::Truncated => Some(drawn_as(&|s| s.rules.store = DepthStore::Truncated)),
        Misconception::RoundedCompared => Some(drawn_as(&|s| s.rules.compare = Compare::Level)),
        // No rule rounds halves down or wraps: the covered pixels replayed under those stores.
        // Rounded half down: ⌈z − 1/2⌉ = −⌊(d − 2n) / 2d⌋.
        Misconception::HalfDown => replay(scene, covered, |n, d| -floor_div(d - 2 * n, 2 * d).0),
        Misconception::NoSaturation => {
            let levels = i128::from(max) + 1;
            replay(scene, covered, move |n, d| half_up(n, d).rem_euclid(levels))
        }
        Misconception::LastOnly => {
            let mut alone = scene.clone();
            alone.polygons = vec![scene.polygons[last].clone()];
            Some(state(&alone, 0))
        }
        Misconception::OneEarly => Some(state_through(scene, last.checked_sub(1))),
        Misconception::BottomFirst => {
            Some((right.0.iter().rev().cloned().collect(), right.1.iter().rev().cloned().collect()))
        }
        Misconception::NotStrict => Some(drawn_as(&|s| {
            s.depth_test = match s.depth_test {
                DepthTest::Greater => DepthTest::GreaterEqual,
                _ => DepthTest::LessEqual,
            }
        })),
        Misconception::Reversed => Some(drawn_as(&|s| {
            let (test, clear) = match s.depth_test {
                DepthTest::Greater => (DepthTest::Less, max),
                _ => (DepthTest::Greater, 0),
            };
            s.depth_test = test;
            s.clear_depth = Stored::Level(clear);
        })),
        Misconception::Corners => {
            let mut changed = scene.clone();
            for polygon in &mut changed.polygons {
                *polygon = polygon.shifted(Q::new(1, 2)).ok()?;
            }
            Some(state(&changed, last))
        }
        Misconception::CellRule => Some(drawn_as(&|s| s.rules.columns = ColumnRule::CellHolds)),
    }
}

/// The reversed test as students most often apply it: every covered pixel
/// replayed, the first to reach a cell written there whatever its depth, a
/// later one only where the reversed test passes on its exact depth against
/// the stored level; depths rounded half up and saturated as the book does.
fn reversed_from_empty(scene: &Scene, covered: &Covered) -> Option<State> {
    let (width, height) = (scene.width as usize, scene.height as usize);
    let max = i128::from(scene.depth_max());
    let clear = scene.clear_depth.level()?;
    let reversed = match scene.depth_test {
        DepthTest::Greater => DepthTest::Less,
        _ => DepthTest::Greater,
    };
    let mut frame = vec![vec![scene.background; width]; height];
    let mut depth = vec![vec![clear; width]; height];
    let mut drawn = vec![false; width * height];
    for (index, x, y, z) in &covered.0 {
        let (n, d) = z.fraction()?;
        let row = crate::raster::printed_row(height as u32, *y);
        let (cell, seen) = (&mut depth[row][*x as usize], &mut drawn[row * width + *x as usize]);
        if !*seen || reversed.passes(z, &Stored::Level(*cell)) {
            *cell = half_up(n, d).clamp(0, max) as u32;
            *seen = true;
            frame[row][*x as usize] = scene.polygons[*index].value;
        }
    }
    Some((frame, depth))
}

/// z = n/d rounded half up, as the book rounds.
fn half_up(n: i128, d: i128) -> i128 {
    floor_div(2 * n + d, 2 * d).0
}

/// The buffers when every covered pixel is stored as `level(n, d)` of its
/// exact depth n/d, saturated to the z-buffer's range, and tested on the
/// exact depth as the book tests it; `None` when a depth needs more than 128
/// bits (no student writes those).
fn replay(scene: &Scene, covered: &Covered, level: impl Fn(i128, i128) -> i128) -> Option<State> {
    let (width, height) = (scene.width as usize, scene.height as usize);
    let max = scene.depth_max();
    let clear = scene.clear_depth.level()?;
    let mut frame = vec![vec![scene.background; width]; height];
    let mut depth = vec![vec![clear; width]; height];
    for (index, x, y, z) in &covered.0 {
        let (n, d) = z.fraction()?;
        let row = crate::raster::printed_row(height as u32, *y);
        let cell = &mut depth[row][*x as usize];
        if scene.depth_test.passes(z, &Stored::Level(*cell)) {
            *cell = level(n, d).clamp(0, i128::from(max)) as u32;
            frame[row][*x as usize] = scene.polygons[*index].value;
        }
    }
    Some((frame, depth))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Found by a teacher: the reversed test as students most often write it
    /// (the smaller z kept, but a cell nothing was drawn in yet taking the
    /// first polygon whatever its depth) scored 89.1 with no cause named.
    #[test]
    fn the_reversed_tests_common_form_is_named() {
        // Two squares on a 12 × 2 raster, A (z = 5) over columns 0–2, B (z = 9) over 1–3; columns
        // 4–11 empty, which the test's other form (cleared to the far end, 15) contradicts.
        let scene = Scene::from_json(
            r#"{"width": 12, "height": 2, "polygons": [
                {"value": 1, "vertices": [[0, 0, 5], [3, 0, 5], [3, 2, 5], [0, 2, 5]]},
                {"value": 2, "vertices": [[1, 0, 9], [4, 0, 9], [4, 2, 9], [1, 2, 9]]}]}"#,
            std::path::Path::new("two.json"),
        )
        .unwrap();
        // Right: B nearer over the overlap. The student kept the smaller z there, and 0 in the empty column.
        let empty = [0; 8];
        let frame = Answer::complete(vec![[&[1, 1, 1, 2][..], &empty].concat(); 2]);
        let depth = Answer::complete(vec![[&[5, 5, 5, 9][..], &empty].concat(); 2]);
        let diagnosis = diagnose(&scene, 1, Some(&frame), Some(&depth)).unwrap();
        assert_eq!((diagnosis.misconception, diagnosis.explained, diagnosis.wrong), (Misconception::Reversed, 8, 8));
    }
}
