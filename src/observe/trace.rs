//! What the rasterizer does, as events handed to an [`Observer`]. Events are
//! data only; `step`, `explain` and `check` build their reports from them.
//! A run with [`Unobserved`] pays nothing: every method is an empty default
//! that the compiler removes.

use std::collections::BTreeMap;

use crate::numbers::{Exact, Q};
use crate::raster::depth::{Depth, Stored, depth_at};
use crate::raster::scan::{Crossing, Span};
use crate::scene::{Polygon, Winding};

/// Receives the rasterizer's events. Every method defaults to doing nothing.
pub trait Observer {
    /// Whether this observer looks at pixel events at all; the rasterizer
    /// skips building them (and may take a faster inner loop) when not.
    const OBSERVES_PIXELS: bool = true;
    /// Whether this observer looks at scanline events; the rasterizer skips
    /// building their crossings and spans when not.
    const OBSERVES_SCANLINES: bool = true;
    /// Whether this observer looks at polygon events; a run that looks at
    /// none of the three draws its polygons in one loop without them.
    const OBSERVES_POLYGONS: bool = true;

    /// A polygon is about to be drawn (or skipped, see [`Fate`]).
    fn polygon(&mut self, _event: &PolygonEvent<'_>) {}
    /// A scanline of the current polygon has its crossings and spans; sent
    /// only for rows that lie inside the raster and the polygon's y range.
    fn scanline(&mut self, _event: &ScanlineEvent<'_>) {}
    /// A covered pixel centre was tested.
    fn pixel(&mut self, _event: &PixelEvent) {}
}

/// The observer of a run nobody watches.
#[derive(Debug, Clone, Copy, Default)]
pub struct Unobserved;

impl Observer for Unobserved {
    const OBSERVES_PIXELS: bool = false;
    const OBSERVES_SCANLINES: bool = false;
    const OBSERVES_POLYGONS: bool = false;
}

/// What happens to a polygon as a whole.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fate {
    /// It is scan-converted.
    Drawn,
    /// Back-face culling skips it: its vertices run this way.
    Culled(Winding),
    /// Newell's `c = 0` with a non-zero normal: seen edge-on, it covers no pixel.
    EdgeOn,
    /// Newell's normal is zero (collinear vertices, or loops that cancel): no plane, no pixel.
    Degenerate,
    /// With perspective, every vertex lies behind the near plane: nothing is drawn.
    ClippedAway,
    /// Given in clip space, nothing of it lies inside the view volume.
    OutsideView,
}

/// A polygon starts.
#[derive(Debug, Clone, Copy)]
pub struct PolygonEvent<'a> {
    /// 0-based index in the scene.
    pub index: usize,
    /// The polygon.
    pub polygon: &'a Polygon,
    /// Whether it is drawn.
    pub fate: Fate,
}

/// One scanline of a polygon.
#[derive(Debug, Clone, Copy)]
pub struct ScanlineEvent<'a> {
    /// 0-based polygon index.
    pub index: usize,
    /// The polygon.
    pub polygon: &'a Polygon,
    /// The pixel row; the scanline is at `y = row + 1/2`.
    pub row: u32,
    /// The edge crossings, sorted left to right.
    pub crossings: &'a [Crossing],
    /// The crossings paired into spans, with the columns each covers.
    pub spans: &'a [Span],
}

/// The outcome of one covered pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// The depth test passed: both buffers were written.
    Written,
    /// The depth test failed: nothing changed.
    Hidden,
    /// The depth test passed but the depth lies in front of the cross-section.
    BeyondSection,
    /// The depth lies outside the scene's depth range: discarded before the test.
    OutsideDepthRange,
}

/// One covered pixel centre and what the depth test made of it.
#[derive(Debug, Clone)]
pub struct PixelEvent {
    /// 0-based polygon index.
    pub index: usize,
    /// Column.
    pub x: u32,
    /// Row.
    pub y: u32,
    /// The exact depth of the polygon's plane at the centre (with perspective, the projected z').
    pub depth: Depth,
    /// The depth that was tested and stored: `depth`, or with a w-buffer the eye-space depth.
    pub compared: Depth,
    /// The z-buffer before.
    pub stored_before: Stored,
    /// The framebuffer before.
    pub frame_before: u32,
    /// What happened.
    pub outcome: Outcome,
    /// The z-buffer after.
    pub stored_after: Stored,
    /// The framebuffer after.
    pub frame_after: u32,
}

/// One span of a recorded scanline, in pixel units.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SpanRecord {
    /// Left crossing `x_a`.
    pub left: Exact,
    /// Right crossing `x_b`.
    pub right: Exact,
    /// The plane's depth at `(x_a, y)` (seed 000's `z_a`); `None` when the
    /// plane has no z term (never for a polygon that is drawn).
    pub left_depth: Option<Exact>,
    /// The plane's depth at `(x_b, y)` (`z_b`), as `left_depth`.
    pub right_depth: Option<Exact>,
    /// The covered columns, if any.
    pub columns: Option<(u32, u32)>,
}

/// Everything that happened on one scanline of one polygon.
#[derive(Debug, Clone)]
pub struct ScanlineRecord {
    /// 0-based polygon index.
    pub index: usize,
    /// The pixel row.
    pub row: u32,
    /// The crossings, sorted, in pixel units.
    pub crossings: Vec<Exact>,
    /// The spans.
    pub spans: Vec<SpanRecord>,
    /// The covered pixels, left to right.
    pub pixels: Vec<PixelEvent>,
}

impl ScanlineRecord {
    /// Builds the record of a scanline event (pixels are added as they come).
    pub fn from_event(event: &ScanlineEvent<'_>) -> ScanlineRecord {
        let geometry = &event.polygon.geometry;
        let y = Exact::Word(Q::new(2 * i128::from(event.row) + 1, 2));
        // Scanline events are only sent for drawn polygons, whose c ≠ 0.
        let depth = |x: &Exact| depth_at(geometry, x, &y);
        ScanlineRecord {
            index: event.index,
            row: event.row,
            crossings: event.crossings.iter().map(|c| c.x()).collect(),
            spans: event
                .spans
                .iter()
                .map(|span| {
                    let (left, right) = (span.left.x(), span.right.x());
                    SpanRecord {
                        left_depth: depth(&left),
                        right_depth: depth(&right),
                        left,
                        right,
                        columns: span.columns,
                    }
                })
                .collect(),
            pixels: Vec::new(),
        }
    }

    /// The span whose columns hold column `x`, if any.
    pub fn span_covering(&self, x: u32) -> Option<&SpanRecord> {
        self.spans.iter().find(|s| s.columns.is_some_and(|(first, last)| (first..=last).contains(&x)))
    }
}

/// Records every scanline and pixel of the polygons it watches (for `step`).
#[derive(Debug, Clone, Default)]
pub struct Recorder {
    /// The polygons seen, with their fates, in order.
    pub polygons: Vec<(usize, Fate)>,
    /// The scanlines, in drawing order.
    pub scanlines: Vec<ScanlineRecord>,
}

impl Observer for Recorder {
    fn polygon(&mut self, event: &PolygonEvent<'_>) {
        self.polygons.push((event.index, event.fate));
    }

    fn scanline(&mut self, event: &ScanlineEvent<'_>) {
        self.scanlines.push(ScanlineRecord::from_event(event));
    }

    fn pixel(&mut self, event: &PixelEvent) {
        if let Some(scanline) = self.scanlines.last_mut() {
            scanline.pixels.push(event.clone());
        }
    }
}

/// What one polygon did at one watched pixel.
#[derive(Debug, Clone)]
pub struct PixelHistoryEntry {
    /// 0-based polygon index.
    pub index: usize,
    /// Whether the polygon was drawn at all.
    pub fate: Fate,
    /// Its scanline through the pixel's row, when the row is within its y range.
    pub scanline: Option<ScanlineRecord>,
    /// The depth test at the pixel, when a span covered its centre.
    pub pixel: Option<PixelEvent>,
}

/// Watches a few pixels through a whole run (for `explain` and `check`):
/// for each, one entry per polygon.
#[derive(Debug, Clone, Default)]
pub struct PixelWatcher {
    /// Keyed by (y, x) so one scanline's pixels are a contiguous range.
    watched: BTreeMap<(u32, u32), Vec<PixelHistoryEntry>>,
}

impl PixelWatcher {
    /// Watches the given pixels (x, y).
    pub fn new(pixels: impl IntoIterator<Item = (u32, u32)>) -> PixelWatcher {
        PixelWatcher { watched: pixels.into_iter().map(|(x, y)| ((y, x), Vec::new())).collect() }
    }

    /// The history of pixel (x, y), one entry per polygon processed.
    pub fn history(&self, x: u32, y: u32) -> &[PixelHistoryEntry] {
        self.watched.get(&(y, x)).map_or(&[], Vec::as_slice)
    }
}

impl Observer for PixelWatcher {
    fn polygon(&mut self, event: &PolygonEvent<'_>) {
        for history in self.watched.values_mut() {
            history.push(PixelHistoryEntry { index: event.index, fate: event.fate, scanline: None, pixel: None });
        }
    }

    fn scanline(&mut self, event: &ScanlineEvent<'_>) {
        let mut record = None;
        for history in self.watched.range_mut((event.row, 0)..=(event.row, u32::MAX)).map(|(_, h)| h) {
            let record = record.get_or_insert_with(|| ScanlineRecord::from_event(event));
            if let Some(entry) = history.last_mut() {
                entry.scanline = Some(record.clone());
            }
        }
    }

    fn pixel(&mut self, event: &PixelEvent) {
        if let Some(entry) = self.watched.get_mut(&(event.y, event.x)).and_then(|h| h.last_mut()) {
            entry.pixel = Some(event.clone());
        }
    }
}
