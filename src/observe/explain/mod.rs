//! Explanations in words a student can follow, built from the rasterizer's
//! events: what the depth test made of a pixel, the history of a pixel
//! through a scene, and why a cell holds its value. Beside it: a pixel's
//! whole history (`history`), the rule that decides a centre on an edge
//! (`tie`).

pub mod history;
pub mod tie;

use crate::numbers::{Exact, Q, exact_and_decimal, exact_and_places};
use crate::observe::trace::{PixelHistoryEntry, ScanlineRecord, SpanRecord};
use crate::raster::depth::{Depth, Stored};
use crate::rules::DepthStore;
use crate::scene::Scene;
use crate::simulate::events::{Fate, Outcome, PixelEvent};
use crate::words::Lang;

/// Which buffer a sentence is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Buffer {
    /// The framebuffer.
    Frame,
    /// The z-buffer.
    Depth,
}

impl Buffer {
    /// `framebuffer` or `z-buffer`, in the current language.
    pub fn name(self, lang: Lang) -> String {
        match self {
            Buffer::Frame => words!(lang, "buffer-frame"),
            Buffer::Depth => words!(lang, "buffer-depth"),
        }
    }
}

/// A depth as shown for this scene: 2 decimals with a quantized z-buffer,
/// 6 with an exact one (whose depths usually lie within −1 … 1).
pub fn depth_text(lang: Lang, scene: &Scene, z: impl Into<Exact>) -> String {
    match scene.rules.store {
        DepthStore::Quantized | DepthStore::Truncated => exact_and_decimal(lang, z),
        DepthStore::Exact => exact_and_places(lang, z, 6),
    }
}

/// `polygon 2 "triangle"`.
pub fn polygon_name(lang: Lang, scene: &Scene, index: usize) -> String {
    crate::words::polygon_label(lang, "polygon-name", index, &scene.polygons[index].name)
}

/// `polygon 2 "triangle"` after "after" (a genitive in some languages).
pub fn polygon_after(lang: Lang, scene: &Scene, index: usize) -> String {
    crate::words::polygon_label(lang, "polygon-after", index, &scene.polygons[index].name)
}

/// `43/4 ≈ 10.75 … 179/6 ≈ 29.83`.
pub fn span_text(lang: Lang, span: &SpanRecord) -> String {
    words!(lang, "span", left = exact_and_decimal(lang, &span.left), right = exact_and_decimal(lang, &span.right))
}

/// `y = 15.5`: the scanline through row `row`.
pub fn scanline_text(lang: Lang, row: u32) -> String {
    words!(lang, "scanline", y = crate::words::localize_decimal(lang, format!("{row}.5")))
}

/// The direction a polygon's vertices run, in words.
pub fn winding_text(lang: Lang, winding: crate::scene::Winding) -> String {
    match winding {
        crate::scene::Winding::Cw => words!(lang, "winding-cw"),
        crate::scene::Winding::Ccw => words!(lang, "winding-ccw"),
    }
}

/// What is stored for an exact depth, naming the rounding when z is not
/// whole (`10 is stored (10.25 rounds to 10)`, the book's pixel (20, 17))
/// and the saturation when it does not fit.
pub fn stored_text(lang: Lang, scene: &Scene, depth: &Depth) -> String {
    match depth.stored(scene.rules.store, scene.depth_max()) {
        Stored::Level(stored) if scene.rules.store == crate::rules::DepthStore::Truncated => {
            let value = depth.value();
            if value.is_integer() && value.floor() == stored.into() {
                words!(lang, "stored-whole", stored = stored)
            } else if value.floor() == stored.into() {
                words!(lang, "stored-truncated", stored = stored, value = crate::numbers::short(lang, value))
            } else {
                words!(lang, "stored-truncated-saturated", stored = stored, value = exact_and_decimal(lang, value))
            }
        }
        Stored::Level(stored) => {
            let rounded = depth.rounded();
            let value = depth.value();
            if rounded == stored.into() && value.is_integer() {
                words!(lang, "stored-whole", stored = stored)
            } else if rounded == stored.into() {
                let key = if Exact::integer(rounded) > value { "stored-rounded-up" } else { "stored-rounded" };
                words!(lang, key, stored = stored, value = crate::numbers::short(lang, value))
            } else {
                words!(
                    lang,
                    "stored-saturated",
                    stored = stored,
                    value = exact_and_decimal(lang, depth.value()),
                    rounded = rounded.to_string()
                )
            }
        }
        exact @ Stored::Exact(_) => words!(lang, "stored-exact", stored = exact.text(lang)),
    }
}

/// One sentence on what the depth test made of a covered pixel:
/// `z = 43/4 ≈ 10.75 > 10 stored, so 11 is stored and the framebuffer gets 2`.
pub fn pixel_reason(lang: Lang, scene: &Scene, event: &PixelEvent) -> String {
    let z = match scene.effects.perspective {
        Some(perspective) if perspective.store_w => words!(
            lang,
            "z-w-buffer",
            w = depth_text(lang, scene, event.compared.value()),
            z = depth_text(lang, scene, event.depth.value())
        ),
        Some(perspective) => words!(
            lang,
            "z-projected",
            z = depth_text(lang, scene, event.depth.value()),
            w = perspective
                .eye_value(&event.depth.value())
                .map_or_else(|| words!(lang, "z-beyond"), |w| depth_text(lang, scene, w))
        ),
        None => depth_text(lang, scene, event.compared.value()),
    };
    let stored_before = event.stored_before.text(lang);
    match event.outcome {
        Outcome::Written => {
            let polygon = &scene.polygons[event.index];
            let frame = match polygon.opacity {
                Some(alpha) => words!(
                    lang,
                    "frame-blended",
                    frame = event.frame_after,
                    alpha = crate::numbers::fraction(alpha),
                    value = polygon.value,
                    rest = crate::numbers::fraction(Q::from_integer(1) - alpha),
                    under = event.frame_before
                ),
                None => event.frame_after.to_string(),
            };
            words!(
                lang,
                "reason-written",
                test = scene.depth_test.outcome_text(lang, &z, &stored_before, true),
                stored = stored_text(lang, scene, &event.compared),
                frame = frame
            )
        }
        Outcome::Hidden => {
            words!(lang, "reason-hidden", test = scene.depth_test.outcome_text(lang, &z, &stored_before, false))
        }
        Outcome::OutsideDepthRange => {
            let (front, rear) = scene.depth_range.unwrap_or((Q::from_integer(0), Q::from_integer(0)));
            words!(
                lang,
                "reason-outside-range",
                z = z,
                front = depth_text(lang, scene, front),
                rear = depth_text(lang, scene, rear)
            )
        }
        Outcome::BeyondSection => {
            let section = scene.effects.section.map_or(String::new(), |z| depth_text(lang, scene, z));
            words!(
                lang,
                "reason-beyond-section",
                test = scene.depth_test.outcome_text(lang, &z, &stored_before, true),
                op = scene.depth_test.section_symbol(),
                section = section
            )
        }
    }
}

/// Why a polygon was not drawn at all, or `None` when it was.
pub fn fate_text(lang: Lang, fate: Fate) -> Option<String> {
    match fate {
        Fate::Drawn => None,
        Fate::Culled(winding) => Some(words!(lang, "fate-culled", winding = winding_text(lang, winding))),
        Fate::EdgeOn => Some(words!(lang, "fate-edge-on")),
        Fate::Degenerate => Some(words!(lang, "fate-degenerate")),
        Fate::SmallArea => Some(words!(lang, "fate-small-area")),
        Fate::ClippedAway => Some(words!(lang, "fate-clipped")),
        Fate::OutsideView => Some(words!(lang, "fate-outside-view")),
    }
}

/// What one polygon did at pixel (x, y), in one sentence.
pub fn entry_text(lang: Lang, scene: &Scene, x: u32, y: u32, entry: &PixelHistoryEntry) -> String {
    if let Some(text) = fate_text(lang, entry.fate) {
        return text;
    }
    let centre = Q::new(2 * i128::from(x) + 1, 2);
    // A centre exactly on the boundary: say which rule decided it.
    let tie = crate::observe::tie::tie_text(lang, scene.rules, &scene.polygons[entry.index].vertices(), x, y)
        .map_or(String::new(), |t| words!(lang, "tie-wrap", text = t));
    match (&entry.scanline, &entry.pixel) {
        (None, _) => words!(lang, "entry-no-row", scanline = scanline_text(lang, y), tie = tie),
        (Some(scanline), Some(pixel)) => {
            let reason = pixel_reason(lang, scene, pixel);
            match scanline.span_covering(x) {
                Some(span) => words!(
                    lang,
                    "entry-covered",
                    scanline = scanline_text(lang, y),
                    span = span_text(lang, span),
                    centre = exact_and_decimal(lang, centre),
                    tie = tie,
                    reason = reason
                ),
                None => words!(
                    lang,
                    "entry-covered-no-span",
                    scanline = scanline_text(lang, y),
                    centre = exact_and_decimal(lang, centre),
                    tie = tie,
                    reason = reason
                ),
            }
        }
        (Some(scanline), None) => words!(
            lang,
            "entry-not-inside",
            scanline = scanline_text(lang, y),
            spans = spans_of(lang, scanline, &words!(lang, "subject-it")),
            centre = exact_and_decimal(lang, centre),
            tie = tie
        ),
    }
}

/// `it spans 57/2 … 179/6` (or has no crossings), with `subject` for "it".
fn spans_of(lang: Lang, scanline: &ScanlineRecord, subject: &str) -> String {
    if scanline.spans.is_empty() {
        return words!(lang, "spans-none", subject = subject);
    }
    let spans: Vec<String> = scanline.spans.iter().map(|span| span_text(lang, span)).collect();
    words!(lang, "spans-some", subject = subject, spans = spans.join(&words!(lang, "list-and")))
}

/// Why cell (x, y) of `buffer` holds what it holds after the polygons in
/// `history` (all of them up to the one the check is after), in one sentence.
pub fn why(lang: Lang, scene: &Scene, buffer: Buffer, x: u32, y: u32, history: &[PixelHistoryEntry]) -> String {
    let last_write = history
        .iter()
        .rev()
        .find_map(|entry| entry.pixel.as_ref().filter(|p| p.outcome == Outcome::Written).map(|p| (entry.index, p)));
    let result = |pixel: &PixelEvent| match buffer {
        Buffer::Frame => words!(lang, "result-frame", value = pixel.frame_after),
        Buffer::Depth => stored_text(lang, scene, &pixel.compared),
    };
    let semicolon = words!(lang, "list-semicolon");
    if let Some((index, pixel)) = last_write {
        let z = depth_text(lang, scene, pixel.compared.value());
        let mut text = words!(
            lang,
            "why-covers",
            polygon = polygon_name(lang, scene, index),
            x = x,
            y = y,
            test = scene.depth_test.outcome_text(lang, &z, &pixel.stored_before.text(lang), true),
            result = result(pixel)
        );
        let later: Vec<String> = history
            .iter()
            .filter(|entry| entry.index > index && entry.pixel.is_some())
            .map(|entry| {
                words!(
                    lang,
                    "why-later-item",
                    polygon = polygon_name(lang, scene, entry.index),
                    reason = entry.pixel.as_ref().map_or_else(String::new, |p| pixel_reason(lang, scene, p))
                )
            })
            .collect();
        if !later.is_empty() {
            text.push_str(&words!(lang, "why-later", list = later.join(&semicolon)));
        }
        return text;
    }
    let cleared = match buffer {
        Buffer::Frame => words!(lang, "cleared-frame", value = scene.background),
        Buffer::Depth => words!(lang, "cleared-depth", value = scene.clear_depth.text(lang)),
    };
    let covered: Vec<String> = history
        .iter()
        .filter_map(|entry| {
            entry.pixel.as_ref().map(|p| {
                words!(
                    lang,
                    "why-covered-item",
                    polygon = polygon_name(lang, scene, entry.index),
                    reason = pixel_reason(lang, scene, p)
                )
            })
        })
        .collect();
    if !covered.is_empty() {
        return words!(lang, "why-nothing-written", x = x, y = y, list = covered.join(&semicolon), cleared = cleared);
    }
    let reaching: Vec<String> = history
        .iter()
        .filter_map(|entry| entry.scanline.as_ref().map(|s| spans_of(lang, s, &polygon_name(lang, scene, entry.index))))
        .collect();
    if reaching.is_empty() {
        words!(lang, "why-none-reaches", x = x, y = y, scanline = scanline_text(lang, y), cleared = cleared)
    } else {
        words!(
            lang,
            "why-not-covered",
            x = x,
            y = y,
            scanline = scanline_text(lang, y),
            list = reaching.join(&words!(lang, "list-and")),
            cleared = cleared
        )
    }
}
