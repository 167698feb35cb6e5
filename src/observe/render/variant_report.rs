//! What a variant of the loop did, in words: a segmented z-buffer's cost,
//! the pixel-order loop's disagreements with the z-buffer, antialiasing's
//! pictures, and where drawing order with opacity differs from the
//! back-to-front blend. The command line prints these and lays the rows out
//! as tables.

use crate::effects::antialias::Averaged as Picture;
use crate::effects::variants::{self, ArcDifference, Inside, SegmentStats, Segments};
use crate::observe::explain::polygon_name;
use crate::observe::render::report::{self, ExactCell, Listed, MatrixStyle, RunJson, StepJson, polygon_heading};
use crate::raster::depth::Stored;
use crate::scene::Antialias as AntialiasSettings;
use crate::scene::Scene;
use crate::simulate::buffer::Buffers;
use crate::simulate::events::Fate;
use crate::simulate::setup::fate;
use crate::words::Lang;

/// A run's JSON with one step, the buffers after the last polygon `name`.
pub fn buffers_json(scene: &Scene, name: &str, buffers: &Buffers) -> RunJson {
    let step = StepJson { polygon: name.to_string(), frame: buffers.frame_rows(), depth: buffers.depth_rows() };
    RunJson { width: scene.width, height: scene.height, effects: scene.effects.names(), steps: vec![step] }
}

/// An antialiased run's JSON: each polygon's averaged buffers as exact
/// values (the last only with `final_only`).
pub fn antialias_json(scene: &Scene, pictures: &[Picture], final_only: bool) -> RunJson<ExactCell> {
    fn exact<T: Into<crate::numbers::Exact> + Clone, C>(
        rows: &[Vec<T>],
        cell: impl Fn(crate::numbers::Exact) -> C,
    ) -> Vec<Vec<C>> {
        rows.iter().map(|row| row.iter().map(|v| cell(v.clone().into())).collect()).collect()
    }
    let steps = pictures
        .iter()
        .zip(&scene.polygons)
        .skip(if final_only { pictures.len().saturating_sub(1) } else { 0 })
        .map(|(p, polygon)| StepJson {
            polygon: polygon.name.clone(),
            frame: exact(&p.frame, ExactCell),
            depth: exact(&p.depth, Stored::Exact),
        })
        .collect();
    RunJson { width: scene.width, height: scene.height, effects: scene.effects.names(), steps }
}

/// Both buffers after all polygons, headed.
pub fn matrices_text(lang: Lang, buffers: &Buffers, style: &MatrixStyle) -> String {
    format!(
        "\n{}\n{}\n{}\n{}",
        words!(lang, "run-frame-after-all"),
        report::matrix_styled(&buffers.frame_rows(), style),
        words!(lang, "run-depth-after-all"),
        report::matrix_styled(&buffers.depth_rows(), style)
    )
}

/// Whether a variant left the same buffers as the plain z-buffer, in words.
pub fn comparison_text(lang: Lang, ours: &Buffers, plain: &Buffers) -> String {
    let (frame, depth) = ours.differences(plain);
    let differing = frame + depth;
    let result = if differing == 0 {
        words!(lang, "variant-identical")
    } else {
        words!(lang, "variant-differs", count = differing.to_string())
    };
    words!(lang, "variant-result", result = result)
}

/// A segmented z-buffer's lines: how many segments, the memory it held
/// against the whole z-buffer's, how often polygons were visited.
pub fn segmented_lines(lang: Lang, scene: &Scene, segments: Segments, stats: &SegmentStats) -> Vec<String> {
    let depth_bits = u64::from(scene.depth_bits);
    let full = u64::from(scene.width) * u64::from(scene.height);
    let drawn = (0..scene.polygons.len()).filter(|&i| fate(scene, i) == Fate::Drawn).count();
    vec![
        words!(lang, "segments-kind", count = stats.segments.to_string(), segments = segments.to_string()),
        words!(
            lang,
            "segments-memory",
            cells = stats.depth_cells.to_string(),
            bits = depth_bits.to_string(),
            total = (stats.depth_cells * depth_bits).to_string(),
            whole_cells = full.to_string(),
            whole_bits = (full * depth_bits).to_string()
        ),
        words!(lang, "segments-visits", visits = stats.polygon_visits.to_string(), whole = drawn.to_string()),
    ]
}

/// The pixel-order loop's heading for its point-in-polygon test.
pub fn pixel_order_heading(lang: Lang, inside: Inside) -> String {
    let test = match inside {
        Inside::Ray => words!(lang, "pixel-order-ray"),
        Inside::Arc => words!(lang, "pixel-order-arc"),
    };
    words!(lang, "pixel-order-heading", test = test)
}

/// Where the arc-length test disagrees with ray casting, a row a cell (x,
/// y, polygon, why); `None` where they agree.
pub fn pixel_order_disagreements(
    lang: Lang,
    scene: &Scene,
    differences: &[variants::InsideDifference],
) -> Option<Listed<4>> {
    if differences.is_empty() {
        return None;
    }
    let header = [
        "x".to_string(),
        "y".to_string(),
        words!(lang, "pixel-order-header-polygon"),
        words!(lang, "pixel-order-header-why"),
    ];
    let rows = differences
        .iter()
        .map(|d| {
            let why = match d.why {
                ArcDifference::OnBoundary => words!(lang, "pixel-order-on-boundary"),
                ArcDifference::Winding(w) => words!(lang, "pixel-order-winding", winding = w.to_string()),
            };
            [d.x.to_string(), d.y.to_string(), polygon_name(lang, scene, d.polygon), why]
        })
        .collect();
    Some(Listed { line: words!(lang, "pixel-order-disagree", count = differences.len().to_string()), header, rows })
}

/// An antialiased run in words: the heading, then each polygon's averaged
/// buffers (the last only with `final_only`).
pub fn antialias_text(
    lang: Lang,
    scene: &Scene,
    settings: AntialiasSettings,
    pictures: &[Picture],
    (style, final_only): (&MatrixStyle, bool),
) -> String {
    let k = settings.samples;
    let at = if settings.depth_at_samples { "antialias-at-sample" } else { "antialias-at-centre" };
    let at = words!(lang, at);
    let mut text =
        format!("{}\n", words!(lang, "antialias-heading", k = k.to_string(), at = at, samples = (k * k).to_string()));
    for (index, picture) in pictures.iter().enumerate() {
        if final_only && index + 1 != pictures.len() {
            continue;
        }
        let name = polygon_name(lang, scene, index);
        text.push_str(&format!(
            "\n{}\n\n{}\n{}\n{}\n{}",
            polygon_heading(lang, scene, index),
            words!(lang, "antialias-frame-after", polygon = name.as_str()),
            report::matrix_styled(&picture.frame, style),
            words!(lang, "antialias-depth-after", polygon = name.as_str()),
            report::matrix_styled(&picture.depth, style)
        ));
    }
    text
}

/// Where drawing order with opacity differs from the back-to-front blend,
/// a row a cell; `Err` with the line that says all match.
pub fn local_errors(lang: Lang, scene: &Scene, drawn: &Buffers) -> Result<Listed<5>, String> {
    let errors = variants::local_errors(scene, drawn);
    if errors.is_empty() {
        return Err(words!(lang, "transparency-all-match"));
    }
    let header = [
        "x".to_string(),
        "y".to_string(),
        words!(lang, "transparency-header-drawn"),
        words!(lang, "transparency-header-back-to-front"),
        words!(lang, "transparency-header-polygons"),
    ];
    let rows = errors
        .iter()
        .map(|e| {
            let order: Vec<String> = e.back_to_front.iter().map(|&i| polygon_name(lang, scene, i)).collect();
            [e.x.to_string(), e.y.to_string(), e.drawn.to_string(), e.correct.to_string(), order.join(", ")]
        })
        .collect();
    Ok(Listed { line: words!(lang, "transparency-differs", count = errors.len().to_string()), header, rows })
}
