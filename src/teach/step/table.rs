//! What one stop of the stepper shows in full, worded: each span with its
//! ends' depths, each covered pixel's row (centre, exact and rounded depth,
//! the step from its neighbour, the test and what is stored), the centres
//! on the polygon's boundary with the rule that decides them, and what an
//! inexact arithmetic computes on the same scanline. The line mode prints
//! these as lines and a table; any other front end may.

use crate::effects::arith::{Arith, float_scanline};
use crate::numbers::{Exact, Q, decimal, exact_and_decimal, fraction};
use crate::observe::explain::depth_text;
use crate::observe::tie::{boundary_columns, tie_text};
use crate::observe::trace::ScanlineRecord;
use crate::scene::Scene;
use crate::simulate::events::{Outcome, PixelEvent};
use crate::words::{Lang, localize_decimal};

/// One covered pixel's row of the stop's table, each cell worded.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct PixelRow {
    /// Column.
    pub x: u32,
    /// The centre's x, exact and decimal.
    pub centre: String,
    /// The exact depth.
    pub z: String,
    /// The depth to two places.
    pub approx: String,
    /// The step from the pixel to its left, or that the span starts here.
    pub step: String,
    /// The z-buffer before.
    pub stored: String,
    /// The depth test and its outcome.
    pub test: String,
    /// The z-buffer after.
    pub after: String,
    /// The framebuffer after.
    pub frame: u32,
    /// Whether the pixel was written.
    pub written: bool,
}

/// The headings of [`PixelRow`]'s cells, in order.
pub fn pixel_header(lang: Lang) -> [String; 9] {
    [
        "x".to_string(),
        words!(lang, "step-col-centre"),
        "z".to_string(),
        "≈ z".to_string(),
        words!(lang, "step-col-step"),
        words!(lang, "step-col-stored"),
        words!(lang, "step-col-test"),
        words!(lang, "step-col-after"),
        words!(lang, "step-col-frame"),
    ]
}

/// The rows of a scanline's covered pixels.
pub fn pixel_rows(lang: Lang, scene: &Scene, pixels: &[PixelEvent]) -> Vec<PixelRow> {
    let depth_test = scene.depth_test;
    let op = depth_test.symbol();
    pixels
        .iter()
        .enumerate()
        .map(|(i, pixel)| {
            let z = pixel.depth.value();
            let step = match i.checked_sub(1).map(|j| &pixels[j]) {
                Some(previous) if previous.x + 1 == pixel.x => fraction(z.minus(&previous.depth.value())),
                _ => words!(lang, "step-start"),
            };
            let stored = pixel.stored_before.text(lang);
            // `always` and `never` compare nothing: they say so instead of a symbol.
            let uncompared = |passed| depth_test.outcome_text(lang, &fraction(&z), &stored, passed);
            let test = match pixel.outcome {
                Outcome::Written if !depth_test.compares() => words!(lang, "step-written", test = uncompared(true)),
                Outcome::Hidden if !depth_test.compares() => words!(lang, "step-hidden", test = uncompared(false)),
                Outcome::Written => words!(lang, "step-test-written", z = fraction(&z), op = op, stored = &stored),
                Outcome::Hidden => words!(lang, "step-test-hidden", z = fraction(&z), op = op, stored = &stored),
                Outcome::BeyondSection => words!(lang, "step-beyond-section", op = op, stored = &stored),
                Outcome::OutsideDepthRange => words!(lang, "step-outside-range", z = fraction(&z)),
            };
            PixelRow {
                x: pixel.x,
                centre: exact_and_decimal(lang, Q::new(2 * i128::from(pixel.x) + 1, 2)),
                z: fraction(&z),
                approx: localize_decimal(lang, decimal(z, 2)),
                step,
                stored,
                test,
                after: pixel.stored_after.text(lang),
                frame: pixel.frame_after,
                written: pixel.outcome == Outcome::Written,
            }
        })
        .collect()
}

/// Each span of the scanline with its ends' depths and its columns.
pub fn span_lines(lang: Lang, scene: &Scene, record: &ScanlineRecord) -> Vec<String> {
    let depth = |z: &Option<Exact>| z.as_ref().map_or_else(|| words!(lang, "z-beyond"), |z| depth_text(lang, scene, z));
    record
        .spans
        .iter()
        .enumerate()
        .map(|(n, span)| {
            let columns = match span.columns {
                Some((first, last)) => words!(lang, "step-columns", first = first.to_string(), last = last.to_string()),
                None => words!(lang, "step-no-column"),
            };
            words!(
                lang,
                "step-span",
                n = (n + 1).to_string(),
                xa = exact_and_decimal(lang, &span.left),
                za = depth(&span.left_depth),
                xb = exact_and_decimal(lang, &span.right),
                zb = depth(&span.right_depth),
                columns = columns
            )
        })
        .collect()
}

/// What follows the table: the centres exactly on polygon `polygon`'s
/// boundary along the scanline and the rule deciding each; with an inexact
/// `arith`, what it computes there beside the exact values.
pub fn notes(lang: Lang, scene: &Scene, polygon: usize, record: &ScanlineRecord, arith: Arith) -> Vec<String> {
    let mut lines = Vec::new();
    let vertices = scene.polygons[polygon].vertices();
    // Only the columns whose centre can lie on the boundary, not every column of the raster.
    for x in boundary_columns(&vertices, record.row).into_iter().filter(|&x| x < scene.width) {
        if let Some(tie) = tie_text(lang, scene.rules, &vertices, x, record.row) {
            lines.push(words!(lang, "step-tie", x = x.to_string(), text = tie));
        }
    }
    if let Arith::Fixed(bits) = arith {
        lines.push(words!(lang, "step-fixed", bits = bits.to_string(), unit = (1u64 << bits).to_string()));
    }
    let Some(float) = float_scanline(scene, polygon, record.row, arith) else { return lines };
    let crossings: Vec<String> = float.crossings.iter().map(|x| format!("{x:.9}")).collect();
    let pixels: Vec<String> = float
        .pixels
        .iter()
        .map(|(x, z)| {
            let exact = record.pixels.iter().find(|e| e.x == *x).map(|e| e.depth.value());
            let note = match exact {
                Some(e) => words!(lang, "step-float-exact", z = decimal(e, 9)),
                None => words!(lang, "step-float-not-exact"),
            };
            format!("x = {x}: z = {z:.9} ({note})")
        })
        .collect();
    let missed: Vec<String> = record
        .pixels
        .iter()
        .filter(|e| !float.pixels.iter().any(|(x, _)| *x == e.x))
        .map(|e| e.x.to_string())
        .collect();
    let found = match float.bounding_columns {
        Some((first, last)) => words!(lang, "step-float-edges", first = first.to_string(), last = last.to_string()),
        None if crossings.is_empty() => words!(lang, "step-float-no-crossings"),
        None => words!(lang, "step-float-crossings", crossings = crossings.join(", ")),
    };
    let heading = words!(lang, "step-float-heading", arith = arith.to_string(), found = found);
    let pixels = if pixels.is_empty() { words!(lang, "step-float-no-pixel") } else { pixels.join("\n  ") };
    lines.push(format!("{heading}\n  {pixels}"));
    if !missed.is_empty() {
        lines.push(format!("  {}", words!(lang, "step-float-missed", columns = missed.join(", "))));
    }
    lines
}
