//! The one rasterizer: polygons in scene order, each scan-converted by
//! half-interval scanlines, its covered centres depth-tested and stored,
//! with only the stages the scene asks for.

use crate::buffer::Buffers;
use crate::depth::DepthStepper;
use crate::exact::fraction;
use crate::rules::{DepthStore, RowRule};
use crate::scan::{self, Crossing, Span};
use crate::scene::{Scene, Winding};
use crate::trace::{Fate, Observer, Outcome, PixelEvent, PolygonEvent, ScanlineEvent};

/// Counts of a run so far.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    /// Polygons processed (drawn or skipped).
    pub polygons: usize,
    /// Covered pixel centres whose depth was tested.
    pub tested: u64,
    /// Pixels written.
    pub written: u64,
}

/// A scene being drawn, one polygon at a time.
#[derive(Debug, Clone)]
pub struct Simulation<'s> {
    scene: &'s Scene,
    buffers: Buffers,
    next: usize,
    stats: Stats,
    crossings: Vec<Crossing>,
    spans: Vec<Span>,
}

impl<'s> Simulation<'s> {
    /// Cleared buffers: the background value, and the depth test's farthest depth.
    pub fn new(scene: &'s Scene) -> Simulation<'s> {
        Simulation {
            scene,
            buffers: Buffers::new(scene.width, scene.height, scene.background, scene.clear_depth),
            next: 0,
            stats: Stats::default(),
            crossings: Vec::new(),
            spans: Vec::new(),
        }
    }

    /// The buffers as they are now.
    pub fn buffers(&self) -> &Buffers {
        &self.buffers
    }

    /// The counts so far.
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// The index of the polygon the next [`Simulation::draw_next`] draws.
    pub fn next_index(&self) -> usize {
        self.next
    }

    /// Draws the next polygon; returns its index, or `None` when all are done.
    pub fn draw_next<O: Observer>(&mut self, observer: &mut O) -> Option<usize> {
        let index = self.next;
        let polygon = self.scene.polygons.get(index)?;
        self.next += 1;
        self.stats.polygons += 1;
        let fate = fate(self.scene, index);
        observer.polygon(&PolygonEvent { index, polygon, fate });
        if fate == Fate::Drawn {
            self.draw(index, observer);
        }
        Some(index)
    }

    /// Draws the remaining polygons up to and including polygon `last`.
    pub fn draw_through<O: Observer>(&mut self, last: usize, observer: &mut O) {
        while self.next <= last && self.draw_next(observer).is_some() {}
    }

    /// Draws every remaining polygon.
    pub fn finish<O: Observer>(&mut self, observer: &mut O) {
        while self.draw_next(observer).is_some() {}
    }

    fn draw<O: Observer>(&mut self, index: usize, observer: &mut O) {
        let scene = self.scene;
        let polygon = &scene.polygons[index];
        let geometry = &polygon.geometry;
        let depth_max = scene.depth_max();
        let rules = scene.rules;
        let Some(rows) = scan::rows(&geometry.points, geometry.denominator, scene.height, rules.rows) else {
            return;
        };
        for row in rows {
            let scan_y = scan::scanline_y(row, geometry.denominator);
            scan::crossings(&geometry.points, scan_y, rules.rows, &mut self.crossings);
            scan::spans(
                &self.crossings,
                geometry.denominator,
                scene.width,
                (rules.rows, rules.columns),
                &mut self.spans,
            );
            observer.scanline(&ScanlineEvent { index, polygon, row, crossings: &self.crossings, spans: &self.spans });
            for span in &self.spans {
                let Some((first, last)) = span.columns else { continue };
                let mut stepper = DepthStepper::start(geometry, i128::from(first), scan_y);
                for x in first..=last {
                    let depth = stepper.current();
                    stepper.advance();
                    let stored_before = self.buffers.depth(x, row);
                    let frame_before = self.buffers.frame(x, row);
                    let outcome = if scene
                        .depth_range
                        .is_some_and(|(front, rear)| depth.cmp_q(front).is_lt() || depth.cmp_q(rear).is_gt())
                    {
                        Outcome::OutsideDepthRange
                    } else if !scene.depth_test.passes(depth, stored_before) {
                        Outcome::Hidden
                    } else if scene.effects.section.is_some_and(|z| !scene.depth_test.keeps_section(depth, z)) {
                        Outcome::BeyondSection
                    } else {
                        Outcome::Written
                    };
                    self.stats.tested += 1;
                    let (stored_after, frame_after) = if outcome == Outcome::Written {
                        self.stats.written += 1;
                        let stored = depth.stored(rules.store, depth_max);
                        self.buffers.store(x, row, polygon.value, stored);
                        (stored, polygon.value)
                    } else {
                        (stored_before, frame_before)
                    };
                    observer.pixel(&PixelEvent {
                        index,
                        x,
                        y: row,
                        depth,
                        stored_before,
                        frame_before,
                        outcome,
                        stored_after,
                        frame_after,
                    });
                }
            }
        }
    }
}

/// Whether polygon `index` is drawn, and if not, why.
pub fn fate(scene: &Scene, index: usize) -> Fate {
    let geometry = &scene.polygons[index].geometry;
    if geometry.is_degenerate() {
        return Fate::Degenerate;
    }
    match Winding::of(geometry.c()) {
        None => Fate::EdgeOn,
        Some(winding) if scene.effects.cull == Some(winding) => Fate::Culled(winding),
        Some(_) => Fate::Drawn,
    }
}

/// The stages that run for this scene, in order, in words.
pub fn stages(scene: &Scene) -> Vec<String> {
    let mut stages = Vec::new();
    if let Some(winding) = scene.effects.cull {
        stages.push(format!("back-face culling ({} polygons skipped)", winding.name()));
    }
    if let Some(window) = scene.window {
        stages.push(format!(
            "window {} … {} × {} … {} onto the raster",
            fraction(window.left),
            fraction(window.right),
            fraction(window.bottom),
            fraction(window.top)
        ));
    }
    stages.push(match scene.rules.rows {
        RowRule::HalfOpen => "scan conversion".to_string(),
        RowRule::Closed => "scan conversion (closed rows, cells holding the crossings)".to_string(),
    });
    if let Some((front, rear)) = scene.depth_range {
        stages.push(format!("depth range (discard z outside {} … {})", fraction(front), fraction(rear)));
    }
    stages.push(format!("depth test (z {} stored)", scene.depth_test.symbol()));
    if let Some(section) = scene.effects.section {
        stages.push(format!("cross-section (z {} {})", scene.depth_test.section_symbol(), fraction(section)));
    }
    stages.push(match scene.rules.store {
        DepthStore::Quantized => format!("store (rounded half up, saturated to 0…{})", scene.depth_max()),
        DepthStore::Exact => "store (exact depth)".to_string(),
    });
    stages
}
