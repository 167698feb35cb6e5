//! Drawing on several threads gives the same buffers, byte for byte, as
//! drawing polygon by polygon on one: pinned on the large scene of the speed
//! goal (`zsim random --count 100000 --width 4096 --height 4096 --max-size 30
//! --frame-bits 8 --depth-bits 24 --seed 1`) by a hash of its final JSON.

use std::io::Write;
use std::path::Path;

use zsim::RandomScene;
use zsim::Scene;
use zsim::Simulation;
use zsim::Unobserved;
use zsim::report::StepJson;

/// FNV-1a over the bytes written: a stable hash, the same on every machine and Rust version.
struct Fnv(u64);

impl Write for Fnv {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        for byte in bytes {
            self.0 = (self.0 ^ u64::from(*byte)).wrapping_mul(0x0000_0100_0000_01b3);
        }
        Ok(bytes.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The hash of the final step as `zsim run --format json --final` writes it.
fn json_hash(scene: &Scene, simulation: &Simulation<'_>) -> u64 {
    let step = StepJson {
        polygon: scene.polygons.last().expect("polygons").name.clone(),
        frame: simulation.buffers().frame_rows(),
        depth: simulation.buffers().depth_rows(),
    };
    let mut hash = Fnv(0xcbf2_9ce4_8422_2325);
    serde_json::to_writer(&mut hash, &step).expect("hashing cannot fail");
    hash.0
}

#[test]
#[ignore = "needs minutes at opt-level 0 (100,000 triangles on 4096 × 4096, drawn six times): .ci/run runs it"]
fn the_large_scene_draws_identically_on_any_number_of_threads_and_tiles() {
    let spec =
        RandomScene { count: 100_000, seed: 1, width: 4096, height: 4096, max_size: 30, frame_bits: 8, depth_bits: 24 };
    let scene = Scene::from_json(&spec.json(), Path::new("large.json")).expect("a valid random scene");
    let mut in_order = Simulation::new(&scene);
    in_order.finish(&mut Unobserved);
    let expected = json_hash(&scene, &in_order);
    // Pinned from polygon-by-polygon drawing on one thread (the loop before threads existed).
    assert_eq!(expected, PINNED, "the large scene's final JSON changed: {expected:#018x}");
    for (threads, tile) in [(1, 64), (2, 64), (2, 100), (3, 17), (4, 64)] {
        let mut simulation = Simulation::new(&scene);
        let drew = simulation.finish_parallel(tile, threads, &|| {});
        assert_eq!(drew, threads, "every asked thread drew");
        assert_eq!(simulation.buffers(), in_order.buffers(), "{threads} threads, tiles of {tile}");
        assert_eq!(simulation.stats(), in_order.stats(), "{threads} threads, tiles of {tile}");
    }
}

/// FNV-1a of the `steps` element that `zsim run large.json --format json --final`
/// printed (release build, one thread, before threads existed), hashed by a
/// separate C program over the bytes between `"steps":[` and the closing `]`.
const PINNED: u64 = 0xddb9_435e_c19c_fac6;

/// `zsim speed` draws every round into the buffers of the first, cleared
/// in place (as the GPU it races clears its framebuffer): each round gives
/// what a fresh simulation gives, after a round left the buffers full or
/// half drawn, polygon by polygon and in tiles.
#[test]
fn a_restarted_simulation_draws_what_a_fresh_one_draws() {
    let spec =
        RandomScene { count: 3000, seed: 7, width: 300, height: 200, max_size: 40, frame_bits: 8, depth_bits: 16 };
    let scene = Scene::from_json(&spec.json(), Path::new("restart.json")).expect("a valid random scene");
    let mut fresh = Simulation::new(&scene);
    fresh.finish(&mut Unobserved);
    let mut reused = Simulation::new(&scene);
    reused.draw_through(1500, &mut Unobserved);
    for round in 0..3 {
        reused.restart();
        assert_eq!(reused.stats(), Simulation::new(&scene).stats(), "round {round}: counts start at zero");
        assert_eq!(reused.buffers(), Simulation::new(&scene).buffers(), "round {round}: cleared");
        if round == 1 {
            reused.finish_parallel(16, 2, &|| {});
        } else {
            reused.finish(&mut Unobserved);
        }
        assert_eq!(reused.buffers(), fresh.buffers(), "round {round}");
        assert_eq!(reused.stats(), fresh.stats(), "round {round}");
    }
}

/// Large buffers cleared on several threads (made, and made again by
/// `restart`) hold what one thread clears, for every width of framebuffer
/// cell and for exact depths; the drawing on them is the same.
#[test]
fn buffers_cleared_on_several_threads_are_the_ones_one_thread_clears() {
    for (frame_bits, depth) in [
        (8, r#""depth_bits": 16"#),
        (12, r#""depth_bits": 24"#),
        (32, r#""rules": {"store": "exact"}, "clear_depth": "-7/3""#),
    ] {
        let text = format!(
            r#"{{"width": 1200, "height": 900, "frame_bits": {frame_bits}, "background": 5, {depth},
                "polygons": [{{"value": 3, "vertices": [[10, 10, 4], [1100, 40, 9], [300, 880, 2]]}}]}}"#
        );
        let scene = Scene::from_json(&text, Path::new("clear.json")).expect("a valid scene");
        let one = Simulation::new(&scene);
        for threads in [2, 3] {
            let mut several = Simulation::new_on(&scene, threads);
            assert_eq!(several.buffers(), one.buffers(), "{frame_bits} bits, {threads} threads: made");
            several.finish(&mut Unobserved);
            several.restart();
            assert_eq!(several.buffers(), one.buffers(), "{frame_bits} bits, {threads} threads: cleared again");
        }
    }
}

/// What draws when no tile is asked for: one thread polygon by polygon while
/// both buffers take at most a quarter of a last-level cache (8 MiB, the
/// rest left to other work), in tiles of 256 beyond it
/// (there one triangle's rows lie far apart and go to memory and back), and
/// more threads always in tiles of 256.
#[test]
fn one_thread_draws_buffers_beyond_the_cache_in_tiles() {
    let tile = |side: u32, frame_bits: u32, threads: usize| {
        let spec =
            RandomScene { count: 1, seed: 1, width: side, height: side, max_size: 4, frame_bits, depth_bits: 24 };
        let scene = Scene::from_json(&spec.json(), Path::new("side.json")).expect("a valid random scene");
        Simulation::new(&scene).default_tile(threads)
    };
    // A quarter of the last-level cache: 8 MiB. 1024² with 4-byte frame cells
    // (and 4-byte depth cells) is 8 MiB, still within; with 1-byte ones 5 MiB.
    assert_eq!(tile(1024, 8, 1), 0);
    assert_eq!(tile(1024, 24, 1), 0);
    assert_eq!(tile(1025, 24, 1), 256, "8 MiB and a row more");
    assert_eq!(tile(2048, 8, 1), 256);
    assert_eq!(tile(4096, 8, 1), 256);
    assert_eq!(tile(32, 2, 2), 256);
}
