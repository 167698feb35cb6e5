//! Effects a scene opts into: perspective with near-plane clipping and the
//! w-buffer, and the guarantee that a scene without effects runs the plain loop
//! with the same result as the loop with every stage compiled in.

use std::path::Path;

use zsim::pipeline::{Simulation, StageSet};
use zsim::scene::Scene;
use zsim::trace::Unobserved;

use crate::{snapshot, zsim};

fn load(path: &str) -> Scene {
    Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join(path)).unwrap()
}

fn scene(json: &str) -> Scene {
    Scene::from_json(json, Path::new("inline.json")).unwrap()
}

fn final_buffers(scene: &Scene, stages: StageSet) -> (Vec<Vec<u32>>, Vec<Vec<zsim::depth::Stored>>) {
    let mut simulation = Simulation::with_stages(scene, stages);
    simulation.finish(&mut Unobserved);
    (simulation.buffers().frame_rows(), simulation.buffers().depth_rows())
}

#[test]
fn plain_loop_and_all_stages_agree_on_every_example() {
    for entry in std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("examples")).unwrap() {
        let path = entry.unwrap().path();
        let scene = Scene::load(&path).unwrap();
        assert_eq!(
            final_buffers(&scene, StageSet::AsAsked),
            final_buffers(&scene, StageSet::AllCompiledIn),
            "{}",
            path.display()
        );
    }
}

#[test]
fn w_buffer_keeps_what_saturated_z_prime_loses() {
    // The near card (z = 30, z' = 120) and the far wall behind it (z = 20, z' = 40)
    // both saturate a 5-bit z'-buffer at 31, so the wall, drawn second, wins; the
    // w-buffer stores 30 and 20 and keeps the card in front.
    let at = |path: &str| final_buffers(&load(path), StageSet::AsAsked).0[31 - 16][16];
    assert_eq!(at("examples/perspective.json"), 2, "z'-buffer: the far wall overwrites");
    assert_eq!(at("examples/perspective_w.json"), 1, "w-buffer: the near card stays");
    let run = zsim(&["explain", "examples/perspective_w.json", "--pixel", "16,16"]);
    assert!(
        run.stdout.contains("z = 20 (the w-buffer's eye-space depth; projected z' = 40) is not > 30 stored"),
        "{}",
        run.stdout
    );
    let run = zsim(&["explain", "examples/perspective.json", "--pixel", "16,16"]);
    assert!(run.stdout.contains("z = 40 (projected z'; eye-space w = 20) > 31 stored"), "{}", run.stdout);
    snapshot!("run_perspective_w", zsim(&["run", "examples/perspective_w.json", "--final"]).stdout);
}

#[test]
fn a_clipped_triangle_draws_as_its_projected_clipped_polygon() {
    // d = 40, n = 2: the near plane is z = 38. Vertices A(12, 12, 0), B(20, 12, 0) are in
    // front, C(16, 20, 76) behind: the seed's second case, the quadrilateral DABE.
    // D on CA: t = (38 − 76)/(0 − 76) = 1/2 → (14, 16, 38); E on BC: t = 38/76 → (18, 16, 38).
    // Projected (scale d/(d − z): 1 at z = 0, 20 at z = 38): A(12, 12, 0), B(20, 12, 0),
    // E(16 + 2·20, 16, 760) = (56, 16, 760), D(16 − 2·20, 16, 760) = (−24, 16, 760).
    let clipped = scene(
        r#"{"width": 32, "height": 32, "depth_bits": 12, "effects": {"perspective": {"distance": 40, "near": 2}},
            "polygons": [{"name": "t", "value": 1, "vertices": [[12, 12, 0], [20, 12, 0], [16, 20, 76]]}]}"#,
    );
    let by_hand = scene(
        r#"{"width": 32, "height": 32, "depth_bits": 12,
            "polygons": [{"name": "t", "value": 1, "vertices": [[-24, 16, 760], [12, 12, 0], [20, 12, 0], [56, 16, 760]]}]}"#,
    );
    assert_eq!(clipped.polygons[0].vertices.len(), 4);
    assert_eq!(final_buffers(&clipped, StageSet::AsAsked), final_buffers(&by_hand, StageSet::AsAsked));
}

#[test]
fn a_polygon_behind_the_near_plane_is_clipped_away() {
    let behind = scene(
        r#"{"width": 8, "height": 8, "effects": {"perspective": {"distance": 10, "near": 1}},
            "polygons": [{"name": "behind", "value": 1, "vertices": [[0, 0, 12], [8, 0, 12], [0, 8, 12]]}]}"#,
    );
    let (frame, _) = final_buffers(&behind, StageSet::AsAsked);
    assert!(frame.iter().flatten().all(|&v| v == 0));
    assert_eq!(zsim::pipeline::fate(&behind, 0), zsim::trace::Fate::ClippedAway);
}
