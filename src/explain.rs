//! Explanations in words a student can follow, built from the rasterizer's
//! events: what the depth test made of a pixel, the history of a pixel
//! through a scene, and why a cell holds its value.

use crate::depth::{Depth, Stored};
use crate::exact::{Q, exact_and_decimal, exact_and_places};
use crate::rules::DepthStore;
use crate::scene::Scene;
use crate::trace::{Fate, Outcome, PixelEvent, PixelHistoryEntry, ScanlineRecord, SpanRecord};

/// Which buffer a sentence is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Buffer {
    /// The framebuffer.
    Frame,
    /// The z-buffer.
    Depth,
}

impl Buffer {
    /// `framebuffer` or `z-buffer`.
    pub fn name(self) -> &'static str {
        match self {
            Buffer::Frame => "framebuffer",
            Buffer::Depth => "z-buffer",
        }
    }
}

/// A depth as shown for this scene: 2 decimals with a quantized z-buffer,
/// 6 with an exact one (whose depths usually lie within −1 … 1).
pub fn depth_text(scene: &Scene, z: Q) -> String {
    match scene.rules.store {
        DepthStore::Quantized => exact_and_decimal(z),
        DepthStore::Exact => exact_and_places(z, 6),
    }
}

/// `polygon 2 "triangle"`.
pub fn polygon_name(scene: &Scene, index: usize) -> String {
    format!("polygon {} \"{}\"", index + 1, scene.polygons[index].name)
}

/// `43/4 ≈ 10.75 … 179/6 ≈ 29.83`.
pub fn span_text(span: &SpanRecord) -> String {
    format!("{} … {}", exact_and_decimal(span.left), exact_and_decimal(span.right))
}

/// `y = 15.5`: the scanline through row `row`.
pub fn scanline_text(row: u32) -> String {
    format!("y = {row}.5")
}

/// What is stored for an exact depth, naming the rounding when z is not
/// whole (`10 is stored (10.25 rounds to 10)`, the book's pixel (20, 17))
/// and the saturation when it does not fit.
pub fn stored_text(scene: &Scene, depth: Depth) -> String {
    match depth.stored(scene.rules.store, scene.depth_max()) {
        Stored::Level(stored) => {
            let rounded = depth.rounded();
            let value = depth.value();
            if rounded == i128::from(stored) && value.is_integer() {
                format!("{stored} is stored")
            } else if rounded == i128::from(stored) {
                let how = if Q::from_integer(rounded) > value { "up " } else { "" };
                format!("{stored} is stored ({} rounds {how}to {stored})", crate::exact::short(value))
            } else {
                format!(
                    "{stored} is stored ({} rounds to {rounded}, saturated to {stored})",
                    exact_and_decimal(depth.value())
                )
            }
        }
        exact @ Stored::Exact(_) => format!("{exact} is stored (exactly)"),
    }
}

/// One sentence on what the depth test made of a covered pixel:
/// `z = 43/4 ≈ 10.75 > 10 stored, so 11 is stored and the framebuffer gets 2`.
pub fn pixel_reason(scene: &Scene, event: &PixelEvent) -> String {
    let z = match scene.effects.perspective {
        Some(perspective) if perspective.store_w => format!(
            "{} (the w-buffer's eye-space depth; projected z' = {})",
            depth_text(scene, event.compared.value()),
            depth_text(scene, event.depth.value())
        ),
        Some(perspective) => format!(
            "{} (projected z'; eye-space w = {})",
            depth_text(scene, event.depth.value()),
            perspective
                .eye_value(event.depth.value())
                .map_or_else(|| "(beyond 128-bit exact arithmetic)".to_string(), |w| depth_text(scene, w))
        ),
        None => depth_text(scene, event.compared.value()),
    };
    match event.outcome {
        Outcome::Written => {
            let polygon = &scene.polygons[event.index];
            let frame = match polygon.opacity {
                Some(alpha) => format!(
                    "{} (opacity {}: {}·{} + {}·{} under, rounded half up)",
                    event.frame_after,
                    crate::exact::fraction(alpha),
                    crate::exact::fraction(alpha),
                    polygon.value,
                    crate::exact::fraction(Q::from_integer(1) - alpha),
                    event.frame_before
                ),
                None => event.frame_after.to_string(),
            };
            format!(
                "z = {}, so {} and the framebuffer gets {frame}",
                scene.depth_test.outcome_text(&z, &event.stored_before.to_string(), true),
                stored_text(scene, event.compared)
            )
        }
        Outcome::Hidden => format!(
            "z = {}: hidden, nothing changes",
            scene.depth_test.outcome_text(&z, &event.stored_before.to_string(), false)
        ),
        Outcome::OutsideDepthRange => {
            let (front, rear) = scene.depth_range.unwrap_or((Q::from_integer(0), Q::from_integer(0)));
            format!(
                "z = {z} is outside the depth range {} … {}: discarded",
                depth_text(scene, front),
                depth_text(scene, rear)
            )
        }
        Outcome::BeyondSection => {
            let section = scene.effects.section.map_or(String::new(), |z| depth_text(scene, z));
            format!(
                "z = {}, but the cross-section keeps only z {} {section}: not written",
                scene.depth_test.outcome_text(&z, &event.stored_before.to_string(), true),
                scene.depth_test.section_symbol()
            )
        }
    }
}

/// Why a polygon was not drawn at all, or `None` when it was.
pub fn fate_text(fate: Fate) -> Option<String> {
    match fate {
        Fate::Drawn => None,
        Fate::Culled(winding) => Some(format!("culled: its vertices run {winding}, so it is not drawn")),
        Fate::EdgeOn => Some("seen edge-on (c = 0): it covers no pixel".to_string()),
        Fate::Degenerate => Some("degenerate (Newell's normal is zero): it covers no pixel".to_string()),
        Fate::ClippedAway => Some("every vertex lies behind the near plane: clipped away, not drawn".to_string()),
    }
}

/// What one polygon did at pixel (x, y), in one sentence.
pub fn entry_text(scene: &Scene, x: u32, y: u32, entry: &PixelHistoryEntry) -> String {
    if let Some(text) = fate_text(entry.fate) {
        return text;
    }
    let centre = Q::new(2 * i128::from(x) + 1, 2);
    // A centre exactly on the boundary: say which rule decided it.
    let tie = crate::tie::tie_text(scene.rules, &scene.polygons[entry.index].vertices, x, y)
        .map_or(String::new(), |t| format!(" ({t})"));
    match (&entry.scanline, &entry.pixel) {
        (None, _) => format!("its y range does not reach the scanline {}{tie}", scanline_text(y)),
        (Some(scanline), Some(pixel)) => {
            let span = scanline.span_covering(x).map_or(String::new(), |s| format!(" {}", span_text(s)));
            format!(
                "on the scanline {} it spans{span}, which holds the centre x = {}{tie}; {}",
                scanline_text(y),
                exact_and_decimal(centre),
                pixel_reason(scene, pixel)
            )
        }
        (Some(scanline), None) => {
            format!(
                "on the scanline {} {}; the centre x = {} is not inside{tie}",
                scanline_text(y),
                spans_of(scanline, "it"),
                exact_and_decimal(centre)
            )
        }
    }
}

/// `it spans 57/2 … 179/6` (or has no crossings), with `subject` for "it".
fn spans_of(scanline: &ScanlineRecord, subject: &str) -> String {
    if scanline.spans.is_empty() {
        return format!("{subject} has no crossings");
    }
    let spans: Vec<String> = scanline.spans.iter().map(span_text).collect();
    format!("{subject} spans {}", spans.join(" and "))
}

/// Why cell (x, y) of `buffer` holds what it holds after the polygons in
/// `history` (all of them up to the one the check is after), in one sentence.
pub fn why(scene: &Scene, buffer: Buffer, x: u32, y: u32, history: &[PixelHistoryEntry]) -> String {
    let last_write = history
        .iter()
        .rev()
        .find_map(|entry| entry.pixel.filter(|p| p.outcome == Outcome::Written).map(|p| (entry.index, p)));
    let result = |pixel: &PixelEvent| match buffer {
        Buffer::Frame => format!("the framebuffer holds {}", pixel.frame_after),
        Buffer::Depth => stored_text(scene, pixel.compared),
    };
    if let Some((index, pixel)) = last_write {
        let z = depth_text(scene, pixel.compared.value());
        let mut text = format!(
            "{} covers ({x}, {y}): z = {}, so {}",
            polygon_name(scene, index),
            scene.depth_test.outcome_text(&z, &pixel.stored_before.to_string(), true),
            result(&pixel)
        );
        let later: Vec<String> = history
            .iter()
            .filter(|entry| entry.index > index && entry.pixel.is_some())
            .map(|entry| {
                format!("{} ({})", polygon_name(scene, entry.index), pixel_reason(scene, &entry.pixel.unwrap()))
            })
            .collect();
        if !later.is_empty() {
            text.push_str(&format!("; later {}", later.join("; ")));
        }
        return text;
    }
    let cleared = match buffer {
        Buffer::Frame => format!("the background {}", scene.background),
        Buffer::Depth => format!("the cleared depth {}", scene.clear_depth),
    };
    let covered: Vec<String> = history
        .iter()
        .filter_map(|entry| {
            entry
                .pixel
                .map(|p| format!("{} covers it but {}", polygon_name(scene, entry.index), pixel_reason(scene, &p)))
        })
        .collect();
    if !covered.is_empty() {
        return format!("nothing was written at ({x}, {y}): {}; it keeps {cleared}", covered.join("; "));
    }
    let reaching: Vec<String> = history
        .iter()
        .filter_map(|entry| entry.scanline.as_ref().map(|s| spans_of(s, &polygon_name(scene, entry.index))))
        .collect();
    if reaching.is_empty() {
        format!("no polygon covers ({x}, {y}): none reaches the scanline {}; it keeps {cleared}", scanline_text(y))
    } else {
        format!(
            "no polygon covers ({x}, {y}): on the scanline {} {}; it keeps {cleared}",
            scanline_text(y),
            reaching.join(" and ")
        )
    }
}
