//! The stepper's recording: the polygons of a scene recorded one at a time
//! as a student reaches them, the stops (scanlines with covered centres)
//! between them, and the buffers at any point. The teaching model
//! (`teach::step`: moving between stops, the quiz and its judge) reads it.

use crate::observe::explain::{fate_text, scanline_text};
use crate::observe::trace::{Recorder, ScanlineRecord};
use crate::scene::Scene;
use crate::simulate::buffer::Buffers;
use crate::simulate::events::Fate;
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
pub fn skip_text(lang: crate::words::Lang, scene: &Scene, skip: &Skip) -> String {
    let name = |polygon: usize| crate::observe::explain::polygon_name(lang, scene, polygon);
    match *skip {
        Skip::NotDrawn { polygon, fate } => {
            words!(lang, "step-skip-fate", polygon = name(polygon), why = fate_text(lang, fate).unwrap_or_default())
        }
        Skip::NoScanline { polygon } => words!(lang, "step-skip-no-scanline", polygon = name(polygon)),
        Skip::NoCentre { polygon, row, crossings: true } => {
            words!(lang, "step-skip-no-centre", polygon = name(polygon), scanline = scanline_text(lang, row))
        }
        Skip::NoCentre { polygon, row, crossings: false } => {
            words!(
                lang,
                "step-skip-no-centre-no-crossings",
                polygon = name(polygon),
                scanline = scanline_text(lang, row)
            )
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

/// A stop of the stepper: a recorded scanline of a polygon that covers at
/// least one pixel centre. Stops are ordered as the algorithm reaches them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Stop {
    /// 0-based polygon index.
    pub polygon: usize,
    /// Index into the polygon's recorded scanlines (bottom to top), not a row.
    pub scanline: usize,
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

    /// The first stop after `from` (exclusive), or from the start, and what
    /// was passed over on the way there.
    pub fn next_stop(&mut self, from: Option<Stop>) -> (Option<Stop>, Vec<Skip>) {
        let mut skipped = Vec::new();
        let (mut polygon, mut scanline) = match from {
            Some(stop) => (stop.polygon, stop.scanline + 1),
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
                    return (Some(Stop { polygon, scanline }), skipped);
                }
                skipped.push(Skip::NoCentre { polygon, row: record.row, crossings: !record.crossings.is_empty() });
                scanline += 1;
            }
            polygon += 1;
            scanline = 0;
        }
        (None, skipped)
    }

    /// The stop before `from`, if any (`from` need not be a stop: polygon
    /// `polygons.len()` asks for the last stop of all).
    pub fn previous_stop(&mut self, from: Stop) -> Option<Stop> {
        let mut previous = None;
        for polygon in 0..=from.polygon.min(self.scene.polygons.len().saturating_sub(1)) {
            let trace = self.trace(polygon);
            for (scanline, record) in trace.scanlines.iter().enumerate() {
                let stop = Stop { polygon, scanline };
                if !record.pixels.is_empty() && stop < from {
                    previous = Some(stop);
                }
            }
        }
        previous
    }

    /// The record of a stop's scanline.
    pub fn record(&mut self, stop: Stop) -> &ScanlineRecord {
        &self.trace(stop.polygon).scanlines[stop.scanline]
    }

    /// The buffers after a stop's scanline.
    pub fn buffers_after(&mut self, stop: Stop) -> Buffers {
        self.buffers_through(stop, usize::MAX)
    }

    /// The buffers after the scanlines of the stop's polygon before it and
    /// the first `pixels` covered pixels of its own.
    pub fn buffers_through(&mut self, stop: Stop, pixels: usize) -> Buffers {
        let trace = self.trace(stop.polygon);
        let mut buffers = trace.before.clone();
        for (j, record) in trace.scanlines[..=stop.scanline].iter().enumerate() {
            let count = if j == stop.scanline { pixels.min(record.pixels.len()) } else { record.pixels.len() };
            for pixel in &record.pixels[..count] {
                buffers.store(pixel.x, pixel.y, pixel.frame_after, pixel.stored_after.clone());
            }
        }
        buffers
    }
}
