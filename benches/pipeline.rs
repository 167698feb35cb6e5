//! What the effects cost a scene that asks for none: the same plain scene
//! through the loop the scene selects (the plain stages only) and through the
//! loop with every effect stage compiled in and checked per pixel. Criterion
//! measures both in one run; compare their times as a ratio.
//!
//! Run with `cargo bench --bench pipeline`.

use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use zsim::generate::RandomScene;
use zsim::pipeline::Simulation;
use zsim::scene::Scene;
use zsim::stages::StageSet;
use zsim::trace::Unobserved;

fn plain_scene() -> Scene {
    let spec =
        RandomScene { count: 2000, seed: 1, width: 256, height: 256, max_size: 24, frame_bits: 8, depth_bits: 16 };
    Scene::from_json(&spec.json(), Path::new("random.json")).expect("a valid random scene")
}

fn stages(c: &mut Criterion) {
    let scene = plain_scene();
    let mut group = c.benchmark_group("plain scene, 2000 triangles on 256x256");
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

criterion_group!(benches, stages);
criterion_main!(benches);
