//! The stepper's model: the polygons of a scene recorded one at a time as a
//! student reaches them, the stops (scanlines with covered centres) between
//! them, the buffers at any point, and how a quiz answer is judged. The
//! terminal stepper, the full-screen app and the page all read it.

use crate::numbers::{Exact, parse_number};
use crate::observe::explain::{fate_text, scanline_text};
use crate::observe::trace::{Recorder, ScanlineRecord};
use crate::scene::Scene;
use crate::simulate::buffer::Buffers;
use crate::simulate::events::{Fate, Outcome, PixelEvent};
use crate::simulate::simulation::Simulation;

/// What the stepper passes over on its way to the next stop.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Skip {
    /// A polygon that is not drawn.
    NotDrawn {
        /// 0-based polygon index.
        polygon: usize,
        /// Why.
        fate: Fate,
    },
    /// A polygon that reaches no scanline of the raster.
    NoScanline {
        /// 0-based polygon index.
        polygon: usize,
    },
    /// A scanline of a polygon that covers no pixel centre.
    NoCentre {
        /// 0-based polygon index.
        polygon: usize,
        /// The pixel row.
        row: u32,
        /// Whether the scanline crosses the polygon at all.
        crossings: bool,
    },
}

/// A [`Skip`] in one line of the reader's language.
pub fn skip_text(scene: &Scene, skip: &Skip) -> String {
    let name = |polygon: usize| crate::observe::explain::polygon_name(scene, polygon);
    match *skip {
        Skip::NotDrawn { polygon, fate } => {
            words!("step-skip-fate", polygon = name(polygon), why = fate_text(fate).unwrap_or_default())
        }
        Skip::NoScanline { polygon } => words!("step-skip-no-scanline", polygon = name(polygon)),
        Skip::NoCentre { polygon, row, crossings: true } => {
            words!("step-skip-no-centre", polygon = name(polygon), scanline = scanline_text(row))
        }
        Skip::NoCentre { polygon, row, crossings: false } => {
            words!("step-skip-no-centre-no-crossings", polygon = name(polygon), scanline = scanline_text(row))
        }
    }
}

/// One polygon's recorded scanlines, with the buffers before it.
pub struct PolygonTrace {
    /// Whether it is drawn, and if not, why.
    pub fate: Fate,
    before: Buffers,
    /// Its scanlines, bottom to top.
    pub scanlines: Vec<ScanlineRecord>,
}

/// Records polygons as the user reaches them.
pub struct Tracer<'s> {
    /// The scene stepped through.
    pub scene: &'s Scene,
    simulation: Simulation<'s>,
    traces: Vec<PolygonTrace>,
    /// The arithmetic the stepper shows beside the exact values.
    pub arith: crate::effects::arith::Arith,
}

impl<'s> Tracer<'s> {
    /// A tracer at the start of `scene`, nothing drawn yet.
    pub fn new(scene: &'s Scene, arith: crate::effects::arith::Arith) -> Tracer<'s> {
        Tracer { scene, simulation: Simulation::new(scene), traces: Vec::new(), arith }
    }

    /// The trace of polygon `index`, drawing the polygons up to it if needed.
    pub fn trace(&mut self, index: usize) -> &PolygonTrace {
        while self.traces.len() <= index {
            let before = self.simulation.buffers().clone();
            let mut recorder = Recorder::default();
            self.simulation.draw_next(&mut recorder);
            let fate = recorder.polygons.first().map_or(Fate::Drawn, |p| p.1);
            self.traces.push(PolygonTrace { fate, before, scanlines: recorder.scanlines });
        }
        &self.traces[index]
    }

    /// The positions (polygon, scanline) that have covered pixels, after `from` (exclusive) or from the start.
    /// And what was passed over on the way there.
    pub fn next_stop(&mut self, from: Option<(usize, usize)>) -> (Option<(usize, usize)>, Vec<Skip>) {
        let mut skipped = Vec::new();
        let (mut polygon, mut scanline) = match from {
            Some((p, s)) => (p, s + 1),
            None => (0, 0),
        };
        while polygon < self.scene.polygons.len() {
            let trace = self.trace(polygon);
            if trace.fate != Fate::Drawn {
                skipped.push(Skip::NotDrawn { polygon, fate: trace.fate });
            } else if trace.scanlines.is_empty() && scanline == 0 {
                skipped.push(Skip::NoScanline { polygon });
            }
            while scanline < trace.scanlines.len() {
                let record = &trace.scanlines[scanline];
                if !record.pixels.is_empty() {
                    return (Some((polygon, scanline)), skipped);
                }
                skipped.push(Skip::NoCentre { polygon, row: record.row, crossings: !record.crossings.is_empty() });
                scanline += 1;
            }
            polygon += 1;
            scanline = 0;
        }
        (None, skipped)
    }

    /// The stop before `from`, if any.
    pub fn previous_stop(&mut self, from: (usize, usize)) -> Option<(usize, usize)> {
        let mut stops = Vec::new();
        for polygon in 0..=from.0 {
            let trace = self.trace(polygon);
            for (k, record) in trace.scanlines.iter().enumerate() {
                if !record.pixels.is_empty() && (polygon, k) < from {
                    stops.push((polygon, k));
                }
            }
        }
        stops.pop()
    }

    /// The buffers after scanline `k` of polygon `p`.
    pub fn buffers_after(&mut self, p: usize, k: usize) -> Buffers {
        self.buffers_through(p, k, usize::MAX)
    }

    /// The buffers after the scanlines before `k` of polygon `p` and the first
    /// `pixels` covered pixels of scanline `k`.
    pub fn buffers_through(&mut self, p: usize, k: usize, pixels: usize) -> Buffers {
        let trace = self.trace(p);
        let mut buffers = trace.before.clone();
        for (j, record) in trace.scanlines[..=k].iter().enumerate() {
            let count = if j == k { pixels.min(record.pixels.len()) } else { record.pixels.len() };
            for pixel in &record.pixels[..count] {
                buffers.store(pixel.x, pixel.y, pixel.frame_after, pixel.stored_after.clone());
            }
        }
        buffers
    }
}

/// Judges a quiz answer for a pixel: whether it is right, and what the
/// student meant; `None` when the text is neither `-` nor a number. Right is
/// the value the z-buffer holds after the pixel; for a pixel not written,
/// `-` or the value it keeps. The line mode and the full-screen app both ask this.
pub fn judge(pixel: &PixelEvent, typed: &str) -> Option<(bool, Meant)> {
    let written = pixel.outcome == Outcome::Written;
    if typed == "-" {
        return Some((!written, Meant::NotWritten));
    }
    let value = parse_number(typed).ok()?;
    Some(match Exact::Word(value) == pixel.stored_after.value() {
        true if written => (true, Meant::ValueWritten),
        true => (true, Meant::ValueKept),
        false => (false, Meant::Value),
    })
}

/// Why `typed` is a number no cell of `scene`'s z-buffer can hold (a
/// quantized z-buffer holds whole levels 0 … max), so that the quiz asks
/// again instead of scoring it; `None` for any other text (`judge` decides).
pub fn does_not_fit(scene: &Scene, typed: &str) -> Option<String> {
    if scene.rules.store != crate::rules::DepthStore::Quantized {
        return None;
    }
    let value = parse_number(typed).ok()?;
    let max = scene.depth_max();
    let fits = value.is_integer() && *value.numer() >= 0 && *value.numer() <= i128::from(max);
    (!fits).then(|| words!("quiz-does-not-fit", text = typed, max = max.to_string()))
}

/// What a quiz answer meant.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Meant {
    /// `-`: not written.
    NotWritten,
    /// The value written.
    ValueWritten,
    /// The value a pixel not written keeps.
    ValueKept,
    /// Some value.
    Value,
}
