//! What the effects cost a scene that asks for none: the same plain scene
//! through the core alone (the rasterizer with a bench-local depth test and
//! store, no simulation, no effects), through the simulation as shipped (every
//! effect compiled in; the scene selects the plain stages), and through the
//! loop with every effect stage checked per pixel. Criterion measures all
//! three in one run; compare their times as ratios.
//!
//! Also tinyrenderer's lesson on an overdrawn model (20 faces that each
//! cover most of the 800×800 image): its time a pixel tested, which a
//! model of 1,000 such faces multiplies (it once took 30 times longer when
//! its area formula went through `array::map` without link-time optimization).
//!
//! Run with `cargo bench --bench pipeline`.

use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use zsim::RandomScene;
use zsim::Scene;
use zsim::Simulation;
use zsim::StageSet;
use zsim::Unobserved;
use zsim::{Crossing, Span};
use zsim::{Depth, Stored};
use zsim::{PixelRect, RasterSink, Scratch, rasterize};

fn plain_scene() -> Scene {
    let spec =
        RandomScene { count: 2000, seed: 1, width: 256, height: 256, max_size: 24, frame_bits: 8, depth_bits: 16 };
    Scene::from_json(&spec.json(), Path::new("random.json")).expect("a valid random scene")
}

/// The core alone: the book's depth test and store on plain vectors.
struct CoreOnly<'a> {
    width: usize,
    value: u32,
    depth_max: u32,
    frame: &'a mut [u32],
    depth: &'a mut [u32],
}

impl RasterSink for CoreOnly<'_> {
    const OBSERVES_SCANLINES: bool = false;

    fn scanline(&mut self, _row: u32, _crossings: &[Crossing], _spans: &[Span]) {}

    fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
        let cell = y as usize * self.width + x as usize;
        if zsim::DepthTest::Greater.passes(&depth, &Stored::Level(self.depth[cell])) {
            self.depth[cell] = depth.quantized(self.depth_max);
            self.frame[cell] = self.value;
        }
    }
}

fn stages(c: &mut Criterion) {
    let scene = plain_scene();
    let mut group = c.benchmark_group("plain scene, 2000 triangles on 256x256");
    group.bench_function("core alone (rasterizer and a bare depth test)", |b| {
        b.iter(|| {
            let cells = scene.width as usize * scene.height as usize;
            let (mut frame, mut depth) = (vec![0u32; cells], vec![0u32; cells]);
            let mut scratch = Scratch::default();
            let rect = PixelRect::raster(scene.width, scene.height);
            for (index, polygon) in scene.polygons.iter().enumerate() {
                if zsim::fate(&scene, index) != zsim::Fate::Drawn {
                    continue;
                }
                let mut sink = CoreOnly {
                    width: scene.width as usize,
                    value: polygon.value,
                    depth_max: scene.depth_max(),
                    frame: &mut frame,
                    depth: &mut depth,
                };
                rasterize(polygon.geometry(), scene.rules, rect, &mut scratch, &mut sink);
            }
            depth[0]
        })
    });
    for (name, stage_set) in [
        ("stages as asked (plain loop)", StageSet::AsAsked),
        ("all effect stages compiled in", StageSet::AllCompiledIn),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut simulation = Simulation::with_stages(&scene, stage_set);
                simulation.finish(&mut Unobserved);
                simulation.stats().written
            })
        });
    }
    group.finish();
}

fn tinyrenderer_overdraw(c: &mut Criterion) {
    let mut obj = String::new();
    for face in 0..20 {
        let z = f64::from(face % 10) / 10.0;
        obj.push_str(&format!("v -0.9 -0.9 {z}\nv 0.9 -0.9 {z}\nv 0 0.9 {z}\n"));
    }
    for face in 0..20 {
        obj.push_str(&format!("f {} {} {}\n", 3 * face + 1, 3 * face + 2, 3 * face + 3));
    }
    let model = zsim::tinyrenderer::Model::parse(&obj).expect("the model reads");
    let mut group = c.benchmark_group("tinyrenderer, 20 overdrawn faces on 800x800");
    group.sample_size(10);
    group.bench_function("the lesson's f64", |b| {
        b.iter(|| {
            zsim::tinyrenderer::render(&model, zsim::tinyrenderer::LessonArith::F64, 800).zbuffer[400 * 800 + 400]
        })
    });
    group.finish();
}

criterion_group!(benches, stages, tinyrenderer_overdraw);
criterion_main!(benches);
