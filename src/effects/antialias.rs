//! Antialiasing by post-filtering (the Russian coursework): the scene is computed at k×k
//! samples per pixel and averaged. Two approaches, as the seed describes:
//!
//! - `"depth": "sample"`: both buffers at k× resolution; colours and depths
//!   are averaged per pixel (the memory-hungry second approach);
//! - `"depth": "pixel"`: the framebuffer at k× resolution and the z-buffer at
//!   screen resolution, the depth computed once, at the pixel's centre. When
//!   a polygon covers part of a pixel, its plane's depth at the pixel centre
//!   (even where the centre itself lies outside the polygon) is tested
//!   against and stored in that pixel's z-buffer cell, and only the covered
//!   samples take its value.
//!
//! Sample (i, j) of pixel (x, y) is at `(x + (2i + 1)/2k, y + (2j + 1)/2k)`:
//! the centres of a k×k grid, so `samples: 1` is exactly the plain z-buffer.

use std::collections::BTreeMap;

use crate::error::{Error, PolygonOrigin, PolygonProblem};

use crate::numbers::{Exact, Q};
use crate::raster::convert::{Scratch, rasterize};
use crate::raster::depth::{Depth, depth_at_centre};
use crate::raster::scan::{Crossing, Span};
use crate::raster::sink::{PixelRect, RasterSink};
use crate::scene::{Antialias, Scene};
use crate::simulate::buffer::Buffers;
use crate::simulate::events::{Fate, Outcome, Unobserved};
use crate::simulate::setup::fate;
use crate::simulate::simulation::Simulation;
use crate::simulate::stages::{PixelStages, Plain, WithEffects, blend};

/// The averaged picture after one polygon.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Averaged {
    /// Mean framebuffer value of each pixel's samples, rows top first: exact
    /// fractions of k².
    pub frame: Vec<Vec<Q>>,
    /// Each pixel's depth, rows top first: the mean of its samples' depths
    /// (sample mode) or its one z-buffer value (pixel mode).
    pub depth: Vec<Vec<Exact>>,
}

/// The scene at k× resolution: every vertex's x and y times k.
pub fn supersampled(scene: &Scene, k: u32) -> Result<Scene, Error> {
    let mut big = scene.clone();
    big.width = scene.width * k;
    big.height = scene.height * k;
    let factor = i128::from(k);
    for (index, polygon) in big.polygons.iter_mut().enumerate() {
        if polygon.vertices().is_empty() {
            // Clipped away in clip space: nothing on the raster to scale.
            continue;
        }
        let vertices =
            polygon.vertices().iter().map(|v| [v[0].times(factor), v[1].times(factor), v[2].clone()]).collect();
        *polygon = polygon.with_vertices(vertices).map_err(|e| Error::Polygon {
            origin: PolygonOrigin::Supersampled { factor: k },
            index,
            name: polygon.name.clone(),
            problem: Box::new(PolygonProblem::Geometry(e)),
        })?;
    }
    Ok(big)
}

/// Runs an antialiased scene; one averaged picture per polygon, in order.
pub fn run(scene: &Scene, settings: Antialias) -> Result<Vec<Averaged>, Error> {
    run_watching(scene, settings, None).map(|(pictures, _)| pictures)
}

/// What pixel mode did at one watched pixel, per polygon (for `explain`).
#[derive(Debug, Clone)]
pub struct PixelModeNote {
    /// 0-based polygon index.
    pub index: usize,
    /// The covered samples, as (i, j) within the pixel.
    pub samples: Vec<(u32, u32)>,
    /// The plane's depth at the pixel centre, and what the test made of it.
    pub decision: crate::simulate::stages::Decision,
}

/// [`run`], noting in pixel mode what happens at pixel `watch`.
pub fn run_watching(
    scene: &Scene,
    settings: Antialias,
    watch: Option<(u32, u32)>,
) -> Result<(Vec<Averaged>, Vec<PixelModeNote>), Error> {
    let mut notes = Vec::new();
    let k = settings.samples;
    let big = supersampled(scene, k)?;
    if settings.depth_at_samples {
        let mut simulation = Simulation::new(&big);
        let mut pictures = Vec::with_capacity(scene.polygons.len());
        while simulation.draw_next(&mut Unobserved).is_some() {
            let buffers = simulation.buffers();
            pictures.push(average(
                scene,
                k,
                |x, y| Q::from_integer(i128::from(buffers.frame(x, y))),
                |x, y| buffers.depth(x, y).value(),
            ));
        }
        return Ok((pictures, notes));
    }
    // Pixel mode: samples' framebuffer at k×, z-buffer at screen resolution.
    let stages: Box<dyn PixelStages> =
        if scene.has_pixel_effects() { Box::new(WithEffects::new(scene)) } else { Box::new(Plain::new(scene)) };
    let mut samples =
        Buffers::new(big.width, big.height, scene.frame_bits, scene.background, scene.clear_depth.clone());
    let mut depth =
        Buffers::new(scene.width, scene.height, scene.frame_bits, scene.background, scene.clear_depth.clone());
    let mut scratch = Scratch::default();
    let mut pictures = Vec::with_capacity(scene.polygons.len());
    for (index, polygon) in scene.polygons.iter().enumerate() {
        if fate(scene, index) == Fate::Drawn {
            let mut sink = Covered { k, by_pixel: BTreeMap::new() };
            rasterize(
                big.polygons[index].geometry(),
                scene.rules,
                PixelRect::raster(big.width, big.height),
                &mut scratch,
                &mut sink,
            );
            for ((y, x), covered) in sink.by_pixel {
                // The depth of the polygon's plane at the pixel's centre, once per pixel.
                let centre_depth = depth_at_centre(polygon.geometry(), x, y);
                let decision = stages.decide(polygon, centre_depth, depth.depth(x, y), depth.frame(x, y));
                if watch == Some((x, y)) {
                    let samples = covered.iter().map(|(sx, sy)| (sx - x * k, sy - y * k)).collect();
                    notes.push(PixelModeNote { index, samples, decision: decision.clone() });
                }
                if decision.outcome != Outcome::Written {
                    continue;
                }
                depth.store(x, y, decision.frame, decision.stored.clone());
                for (sx, sy) in covered {
                    let under = samples.frame(sx, sy);
                    let value = polygon.opacity.map_or(polygon.value, |alpha| blend(polygon.value, under, alpha));
                    samples.store(sx, sy, value, samples.depth(sx, sy));
                }
            }
        }
        pictures.push(average(
            scene,
            k,
            |x, y| Q::from_integer(i128::from(samples.frame(x, y))),
            |x, y| depth.depth(x / k, y / k).value(),
        ));
    }
    Ok((pictures, notes))
}

/// Groups one polygon's covered samples by screen pixel.
struct Covered {
    k: u32,
    by_pixel: BTreeMap<(u32, u32), Vec<(u32, u32)>>,
}

impl RasterSink for Covered {
    const OBSERVES_SCANLINES: bool = false;

    fn scanline(&mut self, _row: u32, _crossings: &[Crossing], _spans: &[Span]) {}

    fn pixel(&mut self, x: u32, y: u32, _depth: Depth) {
        self.by_pixel.entry((y / self.k, x / self.k)).or_default().push((x, y));
    }
}

/// Means over each pixel's k×k samples of `frame` and `depth` (sample
/// coordinates), rows top first.
fn average(scene: &Scene, k: u32, frame: impl Fn(u32, u32) -> Q, depth: impl Fn(u32, u32) -> Exact) -> Averaged {
    let count = i128::from(k) * i128::from(k);
    let mean = |f: &dyn Fn(u32, u32) -> Exact, x: u32, y: u32| -> Exact {
        let mut sum = Exact::Word(Q::from_integer(0));
        for j in 0..k {
            for i in 0..k {
                sum = sum.plus(&f(x * k + i, y * k + j));
            }
        }
        sum.divided_by(count)
    };
    let rows = |f: &dyn Fn(u32, u32) -> Exact| -> Vec<Vec<Exact>> {
        (0..scene.height).rev().map(|y| (0..scene.width).map(|x| mean(f, x, y)).collect()).collect()
    };
    let frame = |x, y| Exact::Word(frame(x, y));
    let frame = rows(&frame).into_iter().map(|row| row.iter().map(|v| v.word().expect("a mean of levels")).collect());
    Averaged { frame: frame.collect(), depth: rows(&depth) }
}
