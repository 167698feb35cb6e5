//! Recorders: observers that keep what the rasterizer did, for the reports
//! (`step`, `explain`, `check`) to read.

use std::collections::BTreeMap;

use crate::numbers::{Exact, Q};
use crate::raster::depth::depth_at;
use crate::simulate::events::{Fate, Observer, PixelEvent, PolygonEvent, ScanlineEvent};

/// One span of a recorded scanline, in pixel units.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SpanRecord {
    /// Left crossing `x_a`.
    pub left: Exact,
    /// Right crossing `x_b`.
    pub right: Exact,
    /// The plane's depth at `(x_a, y)` (the Russian lecture notes' `z_a`); `None` when the
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
        let geometry = &event.polygon.geometry();
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
