//! `buet check`: a student's `z_buffer.txt` against the one the course's
//! program writes for a case, every differing value placed and explained.

use std::path::Path;

use crate::door::read_text;
use crate::error::Error;
use crate::observe::explain::{Buffer, why};
use crate::observe::trace::PixelWatcher;
use crate::simulate::events::Unobserved;
use crate::simulate::simulation::Simulation;
use crate::words::Lang;

use super::{BuetError, BuetProblem, Case, z_buffer_cells};

/// One value of a student's `z_buffer.txt` that differs from the course's.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Difference {
    /// The line, from 1 (the raster's top row first).
    pub line: usize,
    /// The value's place on its line, from 1.
    pub value: usize,
    /// What the student wrote (or a word for none).
    pub answer: String,
    /// What the course's program writes (or a word for none).
    pub right: String,
    /// Which cell it is and why it holds that, or that the value is extra.
    pub reason: String,
}

/// Checks the student's `answer` for `case`: each value that differs, in
/// reading order; none when the file matches.
pub fn check(lang: Lang, case: &Case, answer: &Path) -> Result<Vec<Difference>, Error> {
    let scene = &case.scene;
    let answer_rows = parse_answer(answer, scene.height)?;
    let mut simulation = Simulation::new(scene);
    simulation.finish(&mut Unobserved);
    let expected = z_buffer_cells(simulation.buffers(), case.config.z_max);
    // (row from the top, value index, answer, right, column)
    let mut found: Vec<(usize, usize, String, String, Option<u32>)> = Vec::new();
    for (i, (given, right)) in answer_rows.iter().zip(&expected).enumerate() {
        for k in 0..given.len().max(right.len()) {
            let a = given.get(k).cloned().unwrap_or_else(|| words!(lang, "buet-none"));
            let (column, r) = right.get(k).map_or((None, words!(lang, "buet-none")), |(x, v)| (Some(*x), v.clone()));
            if a != r {
                found.push((i, k, a, r, column));
            }
        }
    }
    let mut watcher = PixelWatcher::new(
        found.iter().filter_map(|(i, _, _, _, column)| column.map(|x| (x, crate::raster::row_y(scene.height, *i)))),
    );
    if !found.is_empty() {
        Simulation::new(scene).finish(&mut watcher);
    }
    Ok(found
        .into_iter()
        .map(|(i, k, answer, right, column)| {
            let reason = match column {
                Some(x) => {
                    let y = crate::raster::row_y(scene.height, i);
                    let why = why(lang, scene, Buffer::Depth, x, y, watcher.history(x, y));
                    words!(lang, "buet-cell", x = x.to_string(), y = y.to_string(), why = why)
                }
                None => words!(lang, "buet-extra-value"),
            };
            Difference { line: i + 1, value: k + 1, answer, right, reason }
        })
        .collect())
}

/// A student's z_buffer.txt: per row, the values written.
fn parse_answer(path: &Path, height: u32) -> Result<Vec<Vec<String>>, Error> {
    let text = read_text(path)?;
    let rows: Vec<Vec<String>> =
        text.lines().map(|line| line.split_whitespace().map(str::to_string).collect()).collect();
    for (i, row) in rows.iter().enumerate() {
        for (k, value) in row.iter().enumerate() {
            if value.parse::<f64>().is_err() {
                let problem = BuetProblem::AnswerNotANumber { line: i + 1, value: k + 1, text: value.clone() };
                return Err(BuetError { line: None, problem }.in_file(path));
            }
        }
    }
    if rows.len() != height as usize {
        let problem = BuetProblem::AnswerRows { rows: rows.len(), height };
        return Err(BuetError { line: None, problem }.in_file(path));
    }
    Ok(rows)
}
