//! AFL++ fuzz target: arbitrary bytes as a scene file, and as the numbers of
//! structurally valid but extreme scenes (coordinates at the exact range's
//! limit, fine fractions, huge depths), through validation and every
//! rasterizer path. Any panic, overflow or broken invariant is a crash.
//!
//! Build and run (see the README): `cargo afl build --release` in `fuzz/`, then
//! `cargo afl fuzz -i seeds -o findings target/release/zsim-fuzz`.

use std::path::Path;

use zsim::Simulation;
use zsim::StageSet;
use zsim::Scene;
use zsim::{PixelWatcher, Recorder, Unobserved};

/// Builds an extreme but well-formed scene from bytes: every polygon's
/// coordinates come from 8-byte chunks, scaled near the limit 2^33 or made
/// into fine fractions.
fn structured(bytes: &[u8]) -> String {
    let mut values = bytes.chunks(8).map(|c| {
        let mut word = [0u8; 8];
        word[..c.len()].copy_from_slice(c);
        i64::from_le_bytes(word)
    });
    let mut polygons = Vec::new();
    while polygons.len() < 4 {
        let Some(kind) = values.next() else { break };
        let count = 3 + (kind.rem_euclid(3)) as usize;
        let mut vertices = Vec::new();
        for _ in 0..count {
            let mut coordinate = || -> String {
                let v = values.next().unwrap_or(0);
                match v.rem_euclid(4) {
                    0 => (v >> 2).rem_euclid(1 << 34).wrapping_sub(1 << 33).to_string(),
                    1 => format!("\"{}/{}\"", (v >> 2) % 100_000, (v >> 40).rem_euclid(99_999) + 1),
                    2 => ((v >> 2) % 64).to_string(),
                    _ => format!("{}.{:07}", (v >> 2) % 800, (v >> 30).rem_euclid(10_000_000)),
                }
            };
            let (x, y, z) = (coordinate(), coordinate(), coordinate());
            vertices.push(format!("[{x}, {y}, {z}]"));
        }
        polygons.push(format!("{{\"value\": 1, \"vertices\": [{}]}}", vertices.join(", ")));
    }
    let bits = bytes.first().map_or(4, |b| 1 + u32::from(*b) % 32);
    let test = if bytes.get(1).is_some_and(|b| b % 2 == 1) { "less" } else { "greater" };
    format!(
        "{{\"width\": 16, \"height\": 16, \"depth_bits\": {bits}, \"depth_test\": \"{test}\", \"polygons\": [{}]}}",
        polygons.join(", ")
    )
}

fn exercise(text: &str) {
    // ZSIM_FUZZ_PRINT=1 shows the scene an input stands for (to turn a crash into a test).
    if std::env::var_os("ZSIM_FUZZ_PRINT").is_some() {
        eprintln!("{text}");
    }
    let Ok(scene) = Scene::from_json(text, Path::new("fuzz.json")) else { return };
    // Keep each input fast: the fuzzer wants many executions, not big rasters.
    if u64::from(scene.width) * u64::from(scene.height) > 64 * 64 || scene.polygons.len() > 64 {
        return;
    }
    let mut plain = Simulation::new(&scene);
    plain.finish(&mut Unobserved);
    let mut all = Simulation::with_stages(&scene, StageSet::AllCompiledIn);
    let mut recorder = Recorder::default();
    all.finish(&mut recorder);
    assert_eq!(plain.buffers(), all.buffers(), "the plain loop and the loop with every stage disagree");
    let mut tiled = Simulation::new(&scene);
    tiled.finish_tiled(5);
    assert_eq!(plain.buffers(), tiled.buffers(), "tiles change the result");
    let mut watcher = PixelWatcher::new([(0, 0), (scene.width / 2, scene.height / 2)]);
    Simulation::new(&scene).finish(&mut watcher);
    for mode in zsim::arith::Arith::ALL {
        if zsim::arith::check_supported(&scene, mode).is_ok() {
            let _ = zsim::arith::run(&scene, mode);
        }
    }
}

fn main() {
    afl::fuzz!(|data: &[u8]| {
        if data.first().is_some_and(|b| b % 2 == 0) {
            if let Ok(text) = std::str::from_utf8(&data[1..]) {
                exercise(text);
            }
        } else {
            exercise(&structured(data.get(1..).unwrap_or(&[])));
        }
    });
}
