//! What accuracy costs in time, measured as ratios in one run
//! (`cargo bench --bench speed`):
//!
//! - `arithmetic`: the accuracy set (256×256, triangles of 4 … 256 px, the hard
//!   cases) in exact mode, in `f32-incremental` and in `f32-edge` (the loop a
//!   GPU runs: edge functions over the bounding box);
//! - `peer`: the same small triangles drawn by zsim (exact and `f32-edge`)
//!   and by a public crate's software rasterizer, `euc` 0.5 (barycentric
//!   weights per pixel over the bounding box, an `f32` depth buffer);
//! - `small triangles`: a cache-resident scene of small triangles, for pixels per second;
//! - `tracing`: the same run unobserved, with an observer that counts pixels,
//!   and with the full recorder that `step` uses;
//! - `large scene`: 4096×4096 with 100,000 random triangles, polygon by
//!   polygon and in 64-pixel tiles on one thread, two, and all cores;
//! - `span loop and setup`, apart: a few large triangles, whose time is
//!   their spans' cells (per pixel), and many of a pixel or two, whose time
//!   is their setup (per triangle), each on a 1024×1024 raster drawn
//!   polygon by polygon on one thread.

use std::path::Path;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use zsim::RandomScene;
use zsim::Scene;
use zsim::Simulation;
use zsim::accuracy::{self, AccuracyRequest};
use zsim::arith::{Arith, Prepared};
use zsim::{Observer, PixelEvent, Recorder, Unobserved};

fn random(count: usize, side: u32, max_size: u32, seed: u64) -> Scene {
    let spec = RandomScene { count, seed, width: side, height: side, max_size, frame_bits: 8, depth_bits: 24 };
    Scene::from_json(&spec.json(), Path::new("random.json")).expect("a valid random scene")
}

fn pixels(scene: &Scene) -> u64 {
    let mut simulation = Simulation::new(scene);
    simulation.finish(&mut Unobserved);
    simulation.stats().tested
}

fn arithmetic(c: &mut Criterion) {
    let scenes =
        accuracy::scenes(&AccuracyRequest { seed: 1, width: 256, height: 256, scenes: 2 }).expect("the accuracy set");
    let mut group = c.benchmark_group("arithmetic on the accuracy set");
    group.sample_size(10);
    for mode in [Arith::Exact, Arith::F32Incremental, Arith::F32Edge] {
        let inputs: Vec<Prepared> = scenes.iter().map(|s| Prepared::new(s, mode).expect("supported")).collect();
        group.bench_function(mode.to_string(), |b| b.iter(|| inputs.iter().map(|p| p.raster().1.tested).sum::<u64>()));
    }
    group.finish();
}

fn small_triangles(c: &mut Criterion) {
    let mut group = c.benchmark_group("small triangles, 256x256");
    group.sample_size(20);
    // 4000 triangles within squares of 8 … 24 px (on average about 6 … 60 covered pixels each).
    for max_size in [8, 12, 16, 24] {
        let scene = random(4000, 256, max_size, 2);
        group.throughput(Throughput::Elements(pixels(&scene)));
        group.bench_function(format!("exact, up to {max_size} px"), |b| {
            b.iter(|| {
                let mut simulation = Simulation::new(&scene);
                simulation.finish(&mut Unobserved);
                simulation.stats().written
            })
        });
    }
    group.finish();
}

/// Counts pixel events: the least an observer can do.
#[derive(Default)]
struct Counter(u64);

impl Observer for Counter {
    fn pixel(&mut self, _event: &PixelEvent) {
        self.0 += 1;
    }
}

fn tracing(c: &mut Criterion) {
    let scene = random(2000, 256, 24, 3);
    let mut group = c.benchmark_group("tracing, 2000 triangles on 256x256");
    group.sample_size(20);
    group.bench_function("unobserved", |b| {
        b.iter(|| {
            let mut simulation = Simulation::new(&scene);
            simulation.finish(&mut Unobserved);
            simulation.stats().written
        })
    });
    group.bench_function("counting observer", |b| {
        b.iter(|| {
            let mut counter = Counter::default();
            Simulation::new(&scene).finish(&mut counter);
            counter.0
        })
    });
    group.bench_function("recorder (step)", |b| {
        b.iter(|| {
            let mut recorder = Recorder::default();
            Simulation::new(&scene).finish(&mut recorder);
            recorder.scanlines.len()
        })
    });
    group.finish();
}

fn large_scene(c: &mut Criterion) {
    let scene = random(100_000, 4096, 30, 1);
    let mut group = c.benchmark_group("4096x4096, 100000 triangles");
    group.sample_size(10).throughput(Throughput::Elements(pixels(&scene)));
    group.bench_function("polygon by polygon", |b| {
        b.iter(|| {
            let mut simulation = Simulation::new(&scene);
            simulation.finish(&mut Unobserved);
            simulation.stats().written
        })
    });
    // Clearing the buffers is inside every measurement, as in `run --format none`.
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    for threads in [1, 2, cores].into_iter().collect::<std::collections::BTreeSet<_>>() {
        group.bench_function(format!("tiles of 64, {threads} thread{}", if threads == 1 { "" } else { "s" }), |b| {
            b.iter(|| {
                let mut simulation = Simulation::new(&scene);
                simulation.finish_parallel(64, threads, &|| {});
                simulation.stats().written
            })
        });
    }
    group.finish();
}

/// The triangles of a scene as `euc` draws them: one value and one depth per
/// triangle, vertices in its clip space (x, y in −1 … 1 over the raster; euc
/// puts y = 1 at the top row, so the picture is mirrored, which costs nothing).
struct Flat;

impl euc::Pipeline for Flat {
    type Vertex = ([f32; 4], u8);
    type VsOut = ();
    type Pixel = u8;

    #[inline(always)]
    fn vert(&self, vertex: &Self::Vertex) -> ([f32; 4], Self::VsOut) {
        (vertex.0, ())
    }

    #[inline(always)]
    fn frag(&self, _: &Self::VsOut) -> u8 {
        1
    }

    #[inline(always)]
    fn get_depth_strategy(&self) -> euc::DepthStrategy {
        // zsim's `greater`: the larger depth is nearer.
        euc::DepthStrategy::IfMoreWrite
    }
}

fn euc_vertices(scene: &Scene) -> Vec<([f32; 4], u8)> {
    let (w, h) = (scene.width as f64, scene.height as f64);
    scene
        .polygons
        .iter()
        .flat_map(|p| {
            let vertices: Vec<_> = p.vertices().iter().map(|v| v.each_ref().map(zsim::to_f64)).collect();
            vertices.into_iter().map(move |[x, y, z]| {
                ([(2.0 * x / w - 1.0) as f32, (2.0 * y / h - 1.0) as f32, z as f32, 1.0], p.value as u8)
            })
        })
        .collect()
}

fn peer(c: &mut Criterion) {
    use euc::{Pipeline, buffer::Buffer2d, rasterizer};
    let mut group = c.benchmark_group("peer rasterizer, 4000 triangles on 256x256");
    group.sample_size(20);
    for max_size in [8, 24] {
        let scene = random(4000, 256, max_size, 2);
        group.throughput(Throughput::Elements(pixels(&scene)));
        group.bench_function(format!("zsim exact, up to {max_size} px"), |b| {
            b.iter(|| {
                let mut simulation = Simulation::new(&scene);
                simulation.finish(&mut Unobserved);
                simulation.stats().written
            })
        });
        let edge = Prepared::new(&scene, Arith::F32Edge).expect("supported");
        group.bench_function(format!("zsim f32-edge, up to {max_size} px"), |b| b.iter(|| edge.raster().1.written));
        let vertices = euc_vertices(&scene);
        group.bench_function(format!("euc 0.5, up to {max_size} px"), |b| {
            b.iter(|| {
                // Cleared for every run, as zsim's buffers are.
                let mut frame = Buffer2d::new([256, 256], 0u8);
                let mut depth = Buffer2d::new([256, 256], 0.0f32);
                Flat.draw::<rasterizer::Triangles<_, rasterizer::BackfaceCullingDisabled>, _>(
                    &vertices,
                    &mut frame,
                    Some(&mut depth),
                );
                frame.as_ref()[0]
            })
        });
    }
    group.finish();
}

fn span_loop_and_setup(c: &mut Criterion) {
    let mut group = c.benchmark_group("span loop and setup, 1024x1024");
    group.sample_size(20);
    let draw = |scene: &Scene| {
        let mut simulation = Simulation::new(scene);
        simulation.finish(&mut Unobserved);
        simulation.stats().written
    };
    // 40 triangles within squares of up to 1024 px: spans hundreds of cells long.
    let large = random(40, 1024, 1024, 5);
    group.throughput(Throughput::Elements(pixels(&large)));
    group.bench_function("span loop (per pixel)", |b| b.iter(|| draw(&large)));
    // 50,000 triangles within squares of 3 px: a pixel or none each.
    let tiny = random(50_000, 1024, 3, 5);
    group.throughput(Throughput::Elements(tiny.polygons.len() as u64));
    group.bench_function("setup (per triangle)", |b| b.iter(|| draw(&tiny)));
    group.finish();
}

criterion_group!(benches, arithmetic, small_triangles, tracing, large_scene, peer, span_loop_and_setup);
criterion_main!(benches);
