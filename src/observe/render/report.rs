//! Reports people read: matrices as the book prints them, and the JSON
//! output of `zsim run`. Strings only; the CLI does the printing.

use crate::words::Lang;
use serde::Serialize;

use crate::numbers::{Exact, decimal};
use crate::raster::depth::Stored;

impl Serialize for Stored {
    /// A level as an integer; an exact depth as [`exact_json`] writes it.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Stored::Level(level) => serializer.serialize_u32(*level),
            Stored::Exact(value) => exact_json(value).serialize(serializer),
        }
    }
}

/// An exact value in a matrix of JSON output, as [`exact_json`] writes it.
#[derive(Debug, Clone)]
pub struct ExactCell(pub Exact);

impl Serialize for ExactCell {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        exact_json(self.0.clone()).serialize(serializer)
    }
}

/// An exact value in JSON output, never a float: an integer when it is
/// whole (`4`), otherwise the reduced fraction as a string (`"5/2"`), so that
/// every cell of a matrix has one of two types whatever the scene.
pub fn exact_json(value: impl Into<Exact>) -> serde_json::Value {
    let value = value.into();
    match value.word().and_then(|q| i64::try_from(*q.numer()).ok()) {
        Some(whole) if value.is_integer() => serde_json::Value::from(whole),
        _ => serde_json::Value::from(crate::numbers::fraction(value)),
    }
}

use crate::scene::perspective::Clip;
use crate::scene::{Scene, Winding};
use crate::simulate::events::Fate;
use crate::simulate::setup::fate;
use crate::simulate::stages::describe as stages;

/// The lines that open a text report: the scene's size, bit depths, test,
/// the stages that run and the effects asked for.
pub fn scene_header(lang: Lang, scene: &Scene, path: &str) -> String {
    let effects = scene.effects.names();
    let header = words!(
        lang,
        "scene-header",
        path = path,
        width = scene.width.to_string(),
        height = scene.height.to_string(),
        frame_bits = scene.frame_bits.to_string(),
        depth_bits = scene.depth_bits.to_string(),
        depth_max = scene.depth_max().to_string(),
        test = scene.depth_test.local_name(lang),
        rule = scene.depth_test.rule_text(lang),
        clear = scene.clear_depth.text(lang)
    );
    let effects = if effects.is_empty() { words!(lang, "effects-none") } else { effects.join(", ") };
    format!(
        "{header}\n{}\n{}\n",
        words!(lang, "scene-stages", stages = stages(lang, scene).join(" → ")),
        words!(lang, "scene-effects", effects = effects)
    )
}

/// One line naming a polygon, its value, its plane and what happens to it:
/// `polygon 2 "triangle" (value 2): plane 3x + y + 4z - 120 = 0, counter-clockwise`.
pub fn polygon_heading(lang: Lang, scene: &Scene, index: usize) -> String {
    let polygon = &scene.polygons[index];
    let geometry = polygon.geometry();
    let start = words!(
        lang,
        "heading-start",
        polygon = crate::observe::explain::polygon_name(lang, scene, index),
        value = polygon.value.to_string()
    );
    let plane = geometry.plane().to_string();
    match fate(scene, index) {
        Fate::Degenerate => words!(lang, "heading-degenerate", start = start),
        Fate::ClippedAway => words!(lang, "heading-clipped-away", start = start),
        Fate::OutsideView => words!(lang, "heading-outside-view", start = start),
        Fate::EdgeOn => words!(lang, "heading-edge-on", start = start, plane = plane),
        Fate::SmallArea => words!(lang, "heading-small-area", start = start, plane = plane),
        Fate::Culled(winding) => words!(
            lang,
            "heading-culled",
            start = start,
            plane = plane,
            winding = crate::observe::explain::winding_text(lang, winding),
            cull = winding.name()
        ),
        Fate::Drawn => {
            let winding = Winding::of(geometry.c()).map_or(String::new(), |w| {
                words!(lang, "heading-winding", winding = crate::observe::explain::winding_text(lang, w))
            });
            let clipped = match polygon.clip {
                Clip::Kept { front, of } if front < of => words!(
                    lang,
                    "heading-clipped",
                    front = front.to_string(),
                    of = of.to_string(),
                    n = polygon.vertices().len().to_string()
                ),
                Clip::View { inside, of } => words!(
                    lang,
                    "heading-view",
                    inside = inside.to_string(),
                    of = of.to_string(),
                    n = polygon.vertices().len().to_string()
                ),
                _ => String::new(),
            };
            let opacity = polygon
                .opacity
                .map_or(String::new(), |a| words!(lang, "heading-opacity", alpha = crate::numbers::fraction(a)));
            let key = if polygon.eye_vertices.is_some() { "heading-drawn-projected" } else { "heading-drawn" };
            words!(lang, key, start = start, plane = plane, winding = winding, opacity = opacity, clipped = clipped)
        }
    }
}

/// How [`matrix`] prints.
#[derive(Debug, Clone, Default)]
pub struct MatrixStyle {
    /// Label rows with y and columns with x.
    pub axes: bool,
    /// Colour cells by value with ANSI escapes (for terminals only).
    pub color: bool,
    /// Print only the rows with y in this range (all when `None`).
    pub rows: Option<std::ops::RangeInclusive<u32>>,
    /// Mark the row with this y with `▶`.
    pub mark: Option<u32>,
}

/// Formats a matrix (rows top first) as the book prints it: each column
/// right-aligned to its widest value, columns separated by one space.
/// With `axes`, rows are labelled with y (top row = `height − 1`) and
/// columns with x.
pub fn matrix<T: MatrixCell>(rows: &[Vec<T>], axes: bool) -> String {
    matrix_styled(rows, &MatrixStyle { axes, ..MatrixStyle::default() })
}

/// A value printed in a matrix cell.
pub trait MatrixCell {
    /// Its text.
    fn text(&self) -> String;
    /// The number that picks its colour.
    fn colour_key(&self) -> u32;
}

impl MatrixCell for u32 {
    fn text(&self) -> String {
        self.to_string()
    }

    fn colour_key(&self) -> u32 {
        *self
    }
}

impl MatrixCell for Stored {
    /// A level as an integer; an exact depth as a decimal with 6 places.
    fn text(&self) -> String {
        match self {
            Stored::Level(level) => level.to_string(),
            Stored::Exact(value) => decimal(value, 6),
        }
    }

    fn colour_key(&self) -> u32 {
        self.level().unwrap_or(1)
    }
}

impl MatrixCell for Exact {
    /// An exact value as a reduced fraction (`3/4`), whole numbers plain.
    fn text(&self) -> String {
        crate::numbers::fraction(self)
    }

    fn colour_key(&self) -> u32 {
        let rounded = (self.to_big() + num_rational::BigRational::new(1.into(), 2.into())).floor().to_integer();
        num_traits::ToPrimitive::to_u32(&rounded.clamp(0.into(), u32::MAX.into())).unwrap_or(0)
    }
}

impl MatrixCell for crate::numbers::Q {
    /// An exact value as a reduced fraction (`3/4`), whole numbers plain.
    fn text(&self) -> String {
        crate::numbers::fraction(*self)
    }

    fn colour_key(&self) -> u32 {
        self.round().to_integer().clamp(0, i128::from(u32::MAX)) as u32
    }
}

/// [`matrix`] with colour, a window of rows and a marked row.
pub fn matrix_styled<T: MatrixCell>(rows: &[Vec<T>], style: &MatrixStyle) -> String {
    let height = rows.len();
    let width = rows.first().map_or(0, Vec::len);
    let texts: Vec<Vec<String>> = rows.iter().map(|row| row.iter().map(MatrixCell::text).collect()).collect();
    let mut column_widths: Vec<usize> =
        (0..width).map(|x| texts.iter().map(|row| row[x].chars().count()).max().unwrap_or(1)).collect();
    if style.axes {
        for (x, w) in column_widths.iter_mut().enumerate() {
            *w = (*w).max(digits(x as u32));
        }
    }
    let label_width = digits(height.saturating_sub(1) as u32);
    let marker = |y: u32| match style.mark {
        Some(m) if m == y => "▶ ",
        Some(_) => "  ",
        None => "",
    };
    let mut out = String::new();
    for (i, row) in rows.iter().enumerate() {
        let y = crate::raster::row_y(height as u32, i);
        if style.rows.as_ref().is_some_and(|r| !r.contains(&y)) {
            continue;
        }
        out.push_str(marker(y));
        if style.axes {
            out.push_str(&format!("{y:>label_width$} | "));
        }
        // Each cell right-aligned to its column, written straight into the text (no string a cell).
        for (x, ((value, text), &w)) in row.iter().zip(&texts[i]).zip(&column_widths).enumerate() {
            if x > 0 {
                out.push(' ');
            }
            if style.color {
                out.push_str(&paint(&format!("{text:>w$}"), value.colour_key(), true));
            } else {
                out.extend(std::iter::repeat_n(' ', w.saturating_sub(text.chars().count())));
                out.push_str(text);
            }
        }
        out.push('\n');
    }
    if style.axes {
        let pad = if style.mark.is_some() { "  " } else { "" };
        let total: usize = column_widths.iter().sum::<usize>() + width.saturating_sub(1);
        out.push_str(&format!("{pad}{:>label_width$} +-{}\n", "", "-".repeat(total)));
        let labels: Vec<String> = column_widths.iter().enumerate().map(|(x, w)| format!("{x:>w$}")).collect();
        out.push_str(&format!("{pad}{:>label_width$}   {}\n", "", labels.join(" ")));
    }
    out
}

/// Wraps a cell in an ANSI colour chosen by its value (0 is dim).
pub fn paint(text: &str, value: u32, color: bool) -> String {
    const PALETTE: [u8; 6] = [33, 36, 35, 32, 34, 31];
    if !color {
        return text.to_string();
    }
    if value == 0 {
        return format!("\x1b[2m{text}\x1b[0m");
    }
    format!("\x1b[{}m{text}\x1b[0m", PALETTE[(value as usize - 1) % PALETTE.len()])
}

fn digits(value: u32) -> usize {
    value.checked_ilog10().map_or(1, |d| d as usize + 1)
}

/// The JSON printed by `zsim run --format json` (and by its variants: the
/// segmented and pixel-order loops, and antialiasing with exact averages as
/// its framebuffer's cells, `F` = [`ExactCell`]). Scripts and graders rely on
/// this shape: keep it stable.
#[derive(Debug, Serialize)]
pub struct RunJson<F = u32> {
    /// Raster width.
    pub width: u32,
    /// Raster height.
    pub height: u32,
    /// Names of the effects simulated, `[]` for the plain algorithm.
    pub effects: Vec<&'static str>,
    /// One step per polygon, in scene order.
    pub steps: Vec<StepJson<F>>,
}

/// Writes one [`StepJson`] for `buffers` after polygon `polygon`, exactly
/// as serde_json writes it (compact), row by row straight from the cells: the
/// memory it takes is one row's, not the matrices' and the text's (4.5 GB for
/// a 16,384 × 4,096 raster with 32-bit buffers when built whole).
pub fn write_step_json(
    out: &mut dyn std::io::Write,
    polygon: &str,
    buffers: &crate::simulate::buffer::Buffers,
) -> std::io::Result<()> {
    let name = serde_json::to_string(polygon).expect("a string serializes");
    write!(out, "{{\"polygon\":{name},\"frame\":[")?;
    write_rows(out, buffers, |line, x, y| line.push_str(itoa_u32(buffers.frame(x, y), &mut [0; 10])))?;
    out.write_all(b"],\"depth\":[")?;
    write_rows(out, buffers, |line, x, y| match buffers.depth(x, y) {
        Stored::Level(level) => line.push_str(itoa_u32(level, &mut [0; 10])),
        Stored::Exact(value) => line.push_str(&exact_json(value).to_string()),
    })?;
    out.write_all(b"]}")
}

/// The raster's rows as JSON arrays, top row first, separated by commas, one
/// row in memory at a time; `cell` writes the cell at (x, y).
fn write_rows(
    out: &mut dyn std::io::Write,
    buffers: &crate::simulate::buffer::Buffers,
    mut cell: impl FnMut(&mut String, u32, u32),
) -> std::io::Result<()> {
    let mut line = String::new();
    for (i, y) in (0..buffers.height()).rev().enumerate() {
        line.clear();
        line.push_str(if i == 0 { "[" } else { ",[" });
        for x in 0..buffers.width() {
            if x > 0 {
                line.push(',');
            }
            cell(&mut line, x, y);
        }
        line.push(']');
        out.write_all(line.as_bytes())?;
    }
    Ok(())
}

/// `value` in decimal digits, written into `buffer`.
fn itoa_u32(mut value: u32, buffer: &mut [u8; 10]) -> &str {
    let mut start = buffer.len();
    loop {
        start -= 1;
        buffer[start] = b'0' + (value % 10) as u8;
        value /= 10;
        if value == 0 {
            break;
        }
    }
    std::str::from_utf8(&buffer[start..]).expect("ASCII digits")
}

/// The buffers after one polygon.
#[derive(Debug, Serialize)]
pub struct StepJson<F = u32> {
    /// The polygon's name.
    pub polygon: String,
    /// The framebuffer, top row first.
    pub frame: Vec<Vec<F>>,
    /// The z-buffer, top row first: integer levels, or for an exact z-buffer
    /// each exact depth as [`exact_json`] writes it.
    pub depth: Vec<Vec<Stored>>,
}

/// What a run measured, for its summary.
#[derive(Debug, Clone, Copy)]
pub struct RunFigures {
    /// Polygons, tested centres and written pixels.
    pub stats: crate::simulate::setup::Stats,
    /// Bytes of the buffers' cells.
    pub buffers: u64,
    /// Reading the scene.
    pub read: std::time::Duration,
    /// Making the buffers and taking their memory from the system, where
    /// that is timed apart from rasterizing.
    pub made: Option<std::time::Duration>,
    /// Rasterizing: from clearing the buffers to the last polygon.
    pub raster: std::time::Duration,
    /// Threads that drew.
    pub threads: usize,
    /// The process's peak resident size, where the system tells it.
    pub peak: Option<u64>,
}

/// `run --format none`'s one line: counts, effects, stages, the time spent
/// reading and rasterizing, and the memory held: the buffers' cells, the
/// scene, and the process's peak resident size (where the system tells it).
/// The caller measures the times (a clock is the front end's: WebAssembly
/// has none).
pub fn run_summary(lang: Lang, scene: &Scene, path: &str, figures: RunFigures) -> String {
    let RunFigures { stats, buffers, read, made, raster, threads, peak } = figures;
    let ms = |time: std::time::Duration| format!("{:.1}", time.as_secs_f64() * 1000.0);
    let effects = scene.effects.names();
    let rate = stats.tested as f64 / raster.as_secs_f64().max(1e-9) / 1e6;
    let scene_bytes = scene.memory_bytes();
    // The ratio means something only where the buffers and the scene dominate the
    // process (from 16 MiB); below, the program itself is most of the peak.
    let peak = match peak {
        Some(peak) if buffers + scene_bytes >= 16 << 20 => words!(
            lang,
            "run-summary-peak-ratio",
            peak = bytes(peak),
            ratio = format!("{:.2}", peak as f64 / (buffers + scene_bytes) as f64)
        ),
        Some(peak) => words!(lang, "run-summary-peak", peak = bytes(peak)),
        None => String::new(),
    };
    words!(
        lang,
        "run-summary",
        path = path,
        polygons = stats.polygons,
        tested = stats.tested.to_string(),
        written = stats.written.to_string(),
        effects = if effects.is_empty() { words!(lang, "run-summary-no-effects") } else { effects.join(", ") },
        stages = stages(lang, scene).join(" → "),
        read = ms(read),
        made = made.map_or(String::new(), |made| words!(lang, "run-summary-made", made = ms(made))),
        raster = ms(raster),
        threads = threads,
        rate = format!("{rate:.1}"),
        buffers = bytes(buffers),
        scene = bytes(scene_bytes),
        peak = peak
    )
}

/// A size in KiB (below 1 MiB) or MiB, one decimal.
fn bytes(count: u64) -> String {
    const KIB: f64 = 1024.0;
    if (count as f64) < KIB * KIB {
        format!("{:.1} KiB", count as f64 / KIB)
    } else {
        format!("{:.1} MiB", count as f64 / (KIB * KIB))
    }
}

/// Writes the start of a [`RunJson`] for `scene`, up to its open `steps`
/// list, exactly as serde_json writes the whole object (compact): the steps
/// follow one by one ([`write_step_json`], comma-separated), then
/// [`write_run_json_end`], so that a large run is streamed a polygon at a
/// time (`run_json_streamed_is_run_json`).
pub fn write_run_json_start(out: &mut dyn std::io::Write, scene: &Scene) -> std::io::Result<()> {
    let effects = serde_json::to_string(&scene.effects.names()).expect("names serialize");
    write!(out, "{{\"width\":{},\"height\":{},\"effects\":{effects},\"steps\":[", scene.width, scene.height)
}

/// Ends what [`write_run_json_start`] began, with a line break.
pub fn write_run_json_end(out: &mut dyn std::io::Write) -> std::io::Result<()> {
    out.write_all(b"]}\n")
}

/// A table's facts: the line that says what it lists, its headings and a
/// row of cells each.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Listed<const N: usize> {
    /// What the rows are, in a line.
    pub line: String,
    /// The headings.
    pub header: [String; N],
    /// The rows.
    pub rows: Vec<[String; N]>,
}

/// `zsim memory`'s table: each buffer's cells, bits per cell, bits and
/// bytes, and their total (the line says nothing: the heading does).
pub fn memory_table(lang: Lang, [frame, depth]: [crate::scene::random::BufferMemory; 2]) -> Listed<5> {
    let header = [
        "memory-header-buffer",
        "memory-header-cells",
        "memory-header-bits-per-cell",
        "memory-header-bits",
        "memory-header-bytes",
    ]
    .map(|key| words!(lang, key));
    let mut rows: Vec<[String; 5]> = [("buffer-frame", frame), ("buffer-depth", depth)]
        .into_iter()
        .map(|(name, buffer)| {
            [
                words!(lang, name),
                buffer.cells.to_string(),
                buffer.bits_per_cell.to_string(),
                buffer.bits().to_string(),
                buffer.bytes().to_string(),
            ]
        })
        .collect();
    rows.push([
        words!(lang, "memory-total"),
        String::new(),
        String::new(),
        (frame.bits() + depth.bits()).to_string(),
        (frame.bytes() + depth.bytes()).to_string(),
    ]);
    Listed { line: String::new(), header, rows }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The streamed object is the one serde_json writes whole.
    #[test]
    fn run_json_streamed_is_run_json() {
        let scene = Scene::from_json(
            r#"{"width": 3, "height": 2, "polygons": [{"name": "a\"b", "value": 1, "vertices": [[0, 0, 5], [3, 0, 5], [0, 2, 5]]}]}"#,
            std::path::Path::new("s.json"),
        )
        .unwrap();
        let mut simulation = crate::simulate::simulation::Simulation::new(&scene);
        simulation.finish(&mut crate::simulate::events::Unobserved);
        let buffers = simulation.buffers();
        let mut streamed = Vec::new();
        write_run_json_start(&mut streamed, &scene).unwrap();
        write_step_json(&mut streamed, "a\"b", buffers).unwrap();
        write_run_json_end(&mut streamed).unwrap();
        let whole = RunJson {
            width: 3,
            height: 2,
            effects: scene.effects.names(),
            steps: vec![StepJson { polygon: "a\"b".into(), frame: buffers.frame_rows(), depth: buffers.depth_rows() }],
        };
        assert_eq!(String::from_utf8(streamed).unwrap(), serde_json::to_string(&whole).unwrap() + "\n");
    }

    /// Found by a new user: with `"store": "exact"` and `"clear_depth": 1` the
    /// heading said "cleared to 15" while the buffer held 1.
    #[test]
    fn heading_tells_the_clear_value_the_buffer_holds_for_every_preset_and_override() {
        use crate::simulate::simulation::Simulation;
        let mut checked = 0;
        for preset in ["rogers", "buet"] {
            for store in [None, Some("quantized"), Some("exact")] {
                for test in [None, Some("greater"), Some("less")] {
                    for clear in [None, Some("1"), Some("\"5/2\"")] {
                        let quantized = store == Some("quantized") || (store.is_none() && preset == "rogers");
                        if quantized && clear.is_some() {
                            continue; // refused: a quantized z-buffer is cleared to its farthest level
                        }
                        let rules = match store {
                            None => format!("\"{preset}\""),
                            Some(store) => format!(r#"{{"preset": "{preset}", "store": "{store}"}}"#),
                        };
                        let test_key = test.map_or(String::new(), |t| format!(r#""depth_test": "{t}", "#));
                        let clear_key = clear.map_or(String::new(), |c| format!(r#""clear_depth": {c}, "#));
                        let json = format!(
                            r#"{{"width": 4, "height": 3, "rules": {rules}, {test_key}{clear_key}"polygons": [{{"value": 1, "vertices": [[0, 0, "1/2"], [1, 0, "1/2"], [0, 1, "1/2"]]}}]}}"#
                        );
                        let scene = Scene::from_json(&json, std::path::Path::new("s.json")).expect(&json);
                        let mut simulation = Simulation::new(&scene);
                        simulation.finish(&mut crate::simulate::events::Unobserved);
                        // (3, 2) is far from the one small triangle: it keeps the clear value.
                        let held = simulation.buffers().depth(3, 2).text(Lang::En);
                        let heading = scene_header(Lang::En, &scene, "s.json");
                        assert!(
                            heading.contains(&format!("cleared to {held}\n")),
                            "{json}\nthe buffer holds {held}, the heading says: {heading}"
                        );
                        checked += 1;
                    }
                }
            }
        }
        assert_eq!(checked, 36, "every combination that is not refused was checked");
    }

    #[test]
    fn columns_are_right_aligned_to_their_widest_value() {
        let rows = vec![vec![0, 10, 0], vec![0, 5, 0]];
        assert_eq!(matrix(&rows, false), "0 10 0\n0  5 0\n");
    }

    #[test]
    fn axes_label_rows_with_y_and_columns_with_x() {
        let rows = vec![vec![1, 2], vec![3, 4]];
        assert_eq!(matrix(&rows, true), "1 | 1 2\n0 | 3 4\n  +----\n    0 1\n");
    }
}
