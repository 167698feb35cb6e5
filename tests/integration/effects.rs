//! Effects a scene opts into: perspective with near-plane clipping and the
//! w-buffer, and the guarantee that a scene without effects runs the plain loop
//! with the same result as the loop with every stage compiled in.

use std::path::Path;

use zsim::Scene;
use zsim::Simulation;
use zsim::StageSet;
use zsim::Unobserved;

use crate::{snapshot, zsim};

fn load(path: &str) -> Scene {
    Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join(path)).unwrap()
}

fn scene(json: &str) -> Scene {
    Scene::from_json(json, Path::new("inline.json")).unwrap()
}

fn final_buffers(scene: &Scene, stages: StageSet) -> (Vec<Vec<u32>>, Vec<Vec<zsim::Stored>>) {
    let mut simulation = Simulation::with_stages(scene, stages);
    simulation.finish(&mut Unobserved);
    (simulation.buffers().frame_rows(), simulation.buffers().depth_rows())
}

/// The scenes in `examples/` (its folders hold course cases in their own formats).
fn example_scenes() -> Vec<std::path::PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 10, "the example scenes are found");
    paths
}

#[test]
fn plain_loop_and_all_stages_agree_on_every_example() {
    for path in example_scenes() {
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
    // front, C(16, 20, 76) behind: the coursework's second case, the quadrilateral DABE.
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
    assert_eq!(clipped.polygons[0].vertices().len(), 4);
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
    assert_eq!(zsim::fate(&behind, 0), zsim::Fate::ClippedAway);
}

fn examples() -> Vec<(String, Scene)> {
    let mut scenes: Vec<(String, Scene)> = example_scenes()
        .into_iter()
        .filter(|p| !p.to_string_lossy().contains("antialias"))
        .map(|p| (p.display().to_string(), Scene::load(&p).unwrap()))
        .collect();
    for seed in 1..=5 {
        let spec =
            zsim::RandomScene { count: 40, seed, width: 24, height: 20, max_size: 12, frame_bits: 4, depth_bits: 6 };
        scenes.push((format!("random seed {seed}"), scene(&spec.json())));
    }
    scenes
}

#[test]
fn every_segmentation_equals_the_plain_z_buffer() {
    use zsim::variants::{Segments, run_segmented};
    for (name, scene) in examples() {
        let plain = final_buffers(&scene, StageSet::AsAsked);
        for segments in
            [Segments::Strips(1), Segments::Strips(3), Segments::Tiles(2), Segments::Tiles(5), Segments::Rows]
        {
            let (buffers, _) = run_segmented(&scene, segments);
            assert_eq!((buffers.frame_rows(), buffers.depth_rows()), plain, "{name} with {segments}");
        }
    }
    // The book's scene in 4 strips: a z-buffer of 8 rows, and 7 polygon visits instead of 2.
    let (_, stats) = run_segmented(&load("examples/rogers.json"), Segments::Strips(4));
    assert_eq!((stats.segments, stats.depth_cells, stats.polygon_visits), (4, 256, 7));
}

#[test]
fn pixel_order_with_ray_casting_equals_the_plain_z_buffer() {
    use zsim::variants::{Inside, run_pixel_order};
    for (name, scene) in examples() {
        let (buffers, differences) = run_pixel_order(&scene, Inside::Ray);
        assert_eq!((buffers.frame_rows(), buffers.depth_rows()), final_buffers(&scene, StageSet::AsAsked), "{name}");
        assert!(differences.is_empty());
    }
}

#[test]
fn arc_length_differs_only_on_boundaries_and_multiple_windings() {
    use zsim::variants::{ArcDifference, Inside, InsideDifference, run_pixel_order};
    // The book's scene has no centre on a boundary: arc agrees everywhere.
    let rogers = load("examples/rogers.json");
    let (buffers, differences) = run_pixel_order(&rogers, Inside::Arc);
    assert!(differences.is_empty());
    assert_eq!(buffers.frame_rows(), final_buffers(&rogers, StageSet::AsAsked).0);
    // A triangle whose top vertex is exactly the centre (1.5, 2.5) of pixel (1, 2):
    // the half-interval rule leaves that row out, arc counts the vertex as inside.
    let apex = scene(
        r#"{"width": 4, "height": 4, "polygons": [{"name": "apex", "value": 1, "vertices": [[0, 0, 5], [3, 0, 5], [1.5, 2.5, 5]]}]}"#,
    );
    let (buffers, differences) = run_pixel_order(&apex, Inside::Arc);
    assert_eq!(differences, vec![InsideDifference { x: 1, y: 2, polygon: 0, why: ArcDifference::OnBoundary }]);
    assert_eq!(buffers.frame(1, 2), 1);
    assert_eq!(final_buffers(&apex, StageSet::AsAsked).0[3 - 2][1], 0);
    // The pentagram's centre is wound around twice: arc fills the hole.
    let star = scene(
        r#"{"width": 10, "height": 10, "polygons": [{"name": "star", "value": 1, "vertices": [[5,10,5],[8,0,5],[0,6,5],[10,6,5],[2,0,5]]}]}"#,
    );
    let (_, differences) = run_pixel_order(&star, Inside::Arc);
    assert!(!differences.is_empty());
    assert!(
        differences
            .iter()
            .all(|d| matches!(d.why, ArcDifference::Winding(w) if w.abs() == 2) || d.why == ArcDifference::OnBoundary)
    );
    let run = zsim(&["run", "examples/concave.json", "--order", "pixels", "--inside", "arc"]);
    assert_eq!(run.code, 0);
    snapshot!("run_concave_pixels_arc", run.stdout);
}

#[test]
fn one_sample_per_pixel_is_the_plain_z_buffer() {
    use zsim::Antialias;
    use zsim::antialias;
    for (name, scene) in examples() {
        let (frame, depth) = final_buffers(&scene, StageSet::AsAsked);
        let as_q = |rows: Vec<Vec<u32>>| -> Vec<Vec<zsim::Q>> {
            rows.into_iter().map(|r| r.into_iter().map(|v| zsim::Q::from_integer(i128::from(v))).collect()).collect()
        };
        let depth_q: Vec<Vec<zsim::Exact>> = depth.iter().map(|r| r.iter().map(|v| v.value()).collect()).collect();
        for depth_at_samples in [true, false] {
            let pictures = antialias::run(&scene, Antialias { samples: 1, depth_at_samples }).unwrap();
            if let Some(last) = pictures.last() {
                assert_eq!(last.frame, as_q(frame.clone()), "{name}, depth at samples: {depth_at_samples}");
                assert_eq!(last.depth, depth_q, "{name}, depth at samples: {depth_at_samples}");
            }
        }
    }
}

#[test]
fn antialiased_values_are_exact_means_of_the_samples() {
    let run = zsim(&["run", "examples/antialias.json", "--final"]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    // Pixel (2, 4): three of its four samples are the wedge's 3 and one the wall's 1: (3 + 3 + 3 + 1)/4 = 5/2.
    assert!(run.stdout.contains("1 1 5/2 3/2 1   1   1 1"), "{}", run.stdout);
    snapshot!("run_antialias", run.stdout);
}

#[test]
fn transparency_reports_the_local_errors_of_drawing_order() {
    let scene = load("examples/transparency.json");
    let mut simulation = Simulation::new(&scene);
    simulation.finish(&mut Unobserved);
    let errors = zsim::variants::local_errors(&scene, simulation.buffers());
    let cells: Vec<(u32, u32, u32, u32)> = errors.iter().map(|e| (e.x, e.y, e.drawn, e.correct)).collect();
    // The glass (6, α = 1/2) over the background gives 3; the card behind it (2), drawn
    // after, fails the depth test; back to front it is 6/2 + 2/2 = 4.
    assert_eq!(cells, vec![(4, 1, 3, 4), (5, 1, 3, 4), (4, 2, 3, 4), (5, 2, 3, 4), (4, 3, 3, 4), (5, 3, 3, 4)]);
    snapshot!("run_transparency", zsim(&["run", "examples/transparency.json", "--final"]).stdout);
}

#[test]
fn explain_shows_each_effect_at_a_pixel() {
    let transparency = zsim(&["explain", "examples/transparency.json", "--pixel", "4,2"]);
    assert!(
        transparency.stdout.contains("the framebuffer gets 3 (opacity 1/2: 1/2·6 + 1/2·0 under, rounded half up)"),
        "{}",
        transparency.stdout
    );
    let arc = zsim(&["explain", "examples/concave.json", "--pixel", "14,5", "--inside", "--segments", "tiles:2"]);
    assert!(
        arc.stdout.contains("segment 2 of 4 (tiles:2): columns 10 … 19, rows 0 … 5; its z-buffer holds 60 cells"),
        "{}",
        arc.stdout
    );
    assert!(
        arc.stdout.contains("ray casting says outside; arc length: winding number -2, so inside"),
        "{}",
        arc.stdout
    );
    // A wrong --segments is refused in the reader's language.
    for (segments, lang, said) in [
        ("rows:2", "ru", "rows принимает только 1 (по одной строке развёртки)"),
        ("strips:x", "uk", "«x» — не ціле число"),
        ("ribbons:2", "zh", "“ribbons:2” 不是 strips:N、tiles:N 或 rows:1（N ≥ 1）"),
    ] {
        let refused = zsim(&["run", "examples/concave.json", "--segments", segments, "--lang", lang]);
        assert_eq!(refused.code, 2);
        assert!(refused.stderr.contains(&format!("{said} (")), "{}", refused.stderr);
    }
    let samples = zsim(&["explain", "examples/antialias.json", "--pixel", "2,4"]);
    assert!(samples.stdout.ends_with("mean over the samples: framebuffer 5/2, z-buffer 7\n"), "{}", samples.stdout);
    snapshot!("explain_antialias_2_4", samples.stdout);
}

#[test]
fn tiles_of_any_size_give_the_same_buffers() {
    for (name, scene) in examples() {
        let plain = final_buffers(&scene, StageSet::AsAsked);
        for tile in [1, 3, 8, 64] {
            let mut simulation = Simulation::new(&scene);
            simulation.finish_tiled(tile);
            assert_eq!(
                (simulation.buffers().frame_rows(), simulation.buffers().depth_rows()),
                plain,
                "{name}, tile {tile}"
            );
            assert_eq!(simulation.stats().polygons, scene.polygons.len(), "{name}");
        }
    }
}

/// Clip-space vertices `[x, y, z, w]`: a polygon through the eye is clipped
/// exactly at the near plane (2 of its 3 vertices inside, drawn as a
/// pentagon), one wholly behind is not drawn, and the nearer (smaller z',
/// depth test `less`) wins where they overlap.
#[test]
fn clip_space_vertices_are_clipped_divided_and_mapped_by_the_viewport() {
    let out = crate::zsim(&["run", "examples/clip_space.json"]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stdout.contains(
        "polygon 2 \"through the eye\" (value 2): plane -50x + 85y + 96z - 1400 = 0, counter-clockwise; clip space: 2 of 3 vertices inside the view volume, drawn as one 5-gon after clipping, division by w and the viewport"
    ), "{}", out.stdout);
    assert!(out.stdout.contains(
        "polygon 3 \"behind\" (value 3): outside the view volume (−w ≤ x, y, z ≤ w): clipped away, not drawn"
    ));
    let explain = crate::zsim(&["explain", "examples/clip_space.json", "--pixel", "12,14"]);
    assert!(explain.stdout.contains("z = 1585/192 ≈ 8.26 < 11 stored, so 8 is stored"), "{}", explain.stdout);
    assert!(explain.stdout.ends_with("final: framebuffer 2, z-buffer 8\n"), "{}", explain.stdout);
    // Mixed vertices and a window are refused, naming the polygon.
    for (name, json, message) in [
        (
            "mixed.json",
            r#"{"polygons": [{"value": 1, "vertices": [[0,0,0,1],[1,0,0],[0,1,0,1]]}]}"#,
            "mixes [x, y, z] vertices with clip-space [x, y, z, w] ones: write every vertex of a polygon the same way",
        ),
        (
            "window.json",
            r#"{"window": {"left": 0, "right": 1, "bottom": 0, "top": 1}, "polygons": [{"value": 1, "vertices": [[0,0,0,1],[1,0,0,1],[0,1,0,1]]}]}"#,
            "they do not combine with a window or the perspective effect",
        ),
    ] {
        let (dir, file) = crate::scene_file(name, json);
        let out = crate::zsim_in(Some(&dir), &["run", &file]);
        assert_eq!(out.code, 2);
        assert!(out.stderr.contains(message), "{}", out.stderr);
    }
}
