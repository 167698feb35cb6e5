//! Stability: the exact rasterizer against an independent per-pixel reference
//! written differently (an even-odd count of rational crossings at each
//! centre, the plane evaluated with `Q`), and metamorphic properties that must
//! hold exactly. Proptest searches for a counterexample; a failure prints the
//! scene it found.

use std::path::Path;

use proptest::prelude::*;
use zsim::Q;
use zsim::Scene;
use zsim::Simulation;
use zsim::{Observer, PixelEvent, ScanlineEvent, Unobserved};

const W: u32 = 12;
const H: u32 = 10;

/// A vertex on a grid of quarter pixels (so vertices fall on centres, on
/// half-pixel lines and between), with a depth in sixths.
fn vertex() -> impl Strategy<Value = (i64, i64, i64)> {
    (-4i64..(W as i64 * 4 + 4), -4i64..(H as i64 * 4 + 4), 0i64..90)
}

fn polygon() -> impl Strategy<Value = Vec<(i64, i64, i64)>> {
    prop::collection::vec(vertex(), 3..=3)
}

fn scene_json(polygons: &[Vec<(i64, i64, i64)>]) -> String {
    scene_json_with_test(polygons, "greater")
}

/// The scene with the depth test `test` (`greater`, `less`, `greater-equal`, `less-equal`, `always`, `never`).
fn scene_json_with_test(polygons: &[Vec<(i64, i64, i64)>], test: &str) -> String {
    let list: Vec<String> = polygons
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let vertices: Vec<String> =
                p.iter().map(|(x, y, z)| format!("[\"{x}/4\", \"{y}/4\", \"{z}/6\"]")).collect();
            format!("{{\"value\": {}, \"vertices\": [{}]}}", i % 3 + 1, vertices.join(", "))
        })
        .collect();
    format!(
        "{{\"width\": {W}, \"height\": {H}, \"depth_bits\": 4, \"depth_test\": \"{test}\", \"polygons\": [{}]}}",
        list.join(", ")
    )
}

/// A framebuffer and a z-buffer, rows top first.
type Buffers = (Vec<Vec<u32>>, Vec<Vec<u32>>);

fn run(json: &str) -> Option<Buffers> {
    let scene = Scene::from_json(json, Path::new("prop.json")).ok()?;
    let mut simulation = Simulation::new(&scene);
    simulation.finish(&mut Unobserved);
    Some((simulation.buffers().frame_rows(), simulation.buffers().depth_level_rows()?))
}

/// The reference: for every pixel, every polygon in order; inside by counting
/// the crossings (half-open in y) left of or at the centre and pairing them;
/// depth from the plane through three vertices, by Cramer's rule in `Q`.
fn reference(polygons: &[Vec<(i64, i64, i64)>]) -> Buffers {
    let mut frame = vec![vec![0u32; W as usize]; H as usize];
    let mut depth = vec![vec![0u32; W as usize]; H as usize];
    for (i, p) in polygons.iter().enumerate() {
        let v: Vec<[Q; 3]> =
            p.iter().map(|&(x, y, z)| [Q::new(x.into(), 4), Q::new(y.into(), 4), Q::new(z.into(), 6)]).collect();
        // Normal (u × w) of the triangle; c = 0 means edge-on or degenerate: nothing drawn.
        let u = [v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]];
        let w = [v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]];
        let n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
        if n[2] == Q::from_integer(0) {
            continue;
        }
        for row in 0..H {
            let yc = Q::new(2 * i128::from(row) + 1, 2);
            let mut xs: Vec<Q> = Vec::new();
            for k in 0..3 {
                let (a, b) = (v[k], v[(k + 1) % 3]);
                let (lo, hi) = if a[1] < b[1] { (a[1], b[1]) } else { (b[1], a[1]) };
                if a[1] != b[1] && lo <= yc && yc < hi {
                    xs.push(a[0] + (b[0] - a[0]) * (yc - a[1]) / (b[1] - a[1]));
                }
            }
            xs.sort();
            for col in 0..W {
                let xc = Q::new(2 * i128::from(col) + 1, 2);
                let inside = xs.chunks_exact(2).any(|pair| pair[0] <= xc && xc <= pair[1]);
                if !inside {
                    continue;
                }
                let z = v[0][2] - (n[0] * (xc - v[0][0]) + n[1] * (yc - v[0][1])) / n[2];
                let cell = (H - 1 - row) as usize;
                let stored = Q::from_integer(depth[cell][col as usize].into());
                if z > stored {
                    frame[cell][col as usize] = (i % 3 + 1) as u32;
                    let level = (z + Q::new(1, 2)).floor().to_integer().clamp(0, 15);
                    depth[cell][col as usize] = level as u32;
                }
            }
        }
    }
    (frame, depth)
}

/// JSON-like text: scene keys, numbers of every form, nesting and junk.
fn scene_text() -> impl Strategy<Value = String> {
    let number = prop_oneof![
        any::<i64>().prop_map(|v| v.to_string()),
        any::<f64>().prop_map(|v| v.to_string()),
        "\"-?[0-9]{1,40}/-?[0-9]{1,40}\"",
        "-?[0-9]{0,40}\\.[0-9]{0,40}([eE]-?[0-9]{1,3})?",
        "\"[a-z0-9./]{0,8}\"",
    ];
    let vertex = prop::collection::vec(number.clone(), 0..5).prop_map(|v| format!("[{}]", v.join(", ")));
    let polygon =
        (prop::collection::vec(vertex, 0..6), number.clone(), "[a-z]{0,6}").prop_map(|(vertices, value, key)| {
            format!("{{\"value\": {value}, \"vertices\": [{}], \"{key}\": 1}}", vertices.join(", "))
        });
    let key = prop_oneof![
        Just("width"),
        Just("height"),
        Just("frame_bits"),
        Just("depth_bits"),
        Just("background"),
        Just("depth_test"),
        Just("clear_depth"),
        Just("window"),
        Just("rules"),
        Just("effects"),
        Just("depth_range"),
        Just("widht"),
    ];
    (prop::collection::vec((key, number), 0..5), prop::collection::vec(polygon, 0..4), "[ -~]{0,3}").prop_map(
        |(settings, polygons, junk)| {
            let settings: Vec<String> = settings.iter().map(|(k, v)| format!("\"{k}\": {v}")).collect();
            format!(
                "{{{} \"polygons\": [{}]}}{junk}",
                settings.iter().map(|s| format!("{s}, ")).collect::<String>(),
                polygons.join(", ")
            )
        },
    )
}

/// Small triangles (within 3 pixels, vertices on a 1/2 grid so that edges
/// often pass through centres, depths over
/// sixths on any plane) as the unobserved loop draws them by edge functions,
/// against the scan converter one pixel at a time: the same buffers and counts
/// under every depth test, on several depth sizes.
fn small_triangles_scene(triangles: &[[(i64, i64); 3]], planes: &[(i64, i64, i64)], test: &str, bits: u32) -> String {
    let list: Vec<String> = triangles
        .iter()
        .zip(planes.iter().cycle())
        .enumerate()
        .map(|(i, (t, (z0, sx, sy)))| {
            let vertices: Vec<String> =
                t.iter().map(|(x, y)| format!("[\"{x}/2\", \"{y}/2\", \"{}/6\"]", z0 + sx * x + sy * y)).collect();
            format!("{{\"value\": {}, \"vertices\": [{}]}}", i % 3 + 1, vertices.join(", "))
        })
        .collect();
    format!(
        "{{\"width\": 12, \"height\": 10, \"depth_bits\": {bits}, \"depth_test\": \"{test}\", \"polygons\": [{}]}}",
        list.join(", ")
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn small_triangles_draw_as_the_scan_converter_draws_them(
        triangles in prop::collection::vec(
            (-2i64..25, -2i64..21).prop_flat_map(|(x, y)| prop::array::uniform3((x..x + 7, y..y + 7))),
            1..30,
        ),
        planes in prop::collection::vec((0i64..200, -9i64..10, -9i64..10), 1..4),
        test in prop::sample::select(vec!["greater", "less", "greater-equal", "less-equal", "always", "never"]),
        bits in prop::sample::select(vec![2u32, 4, 8]),
    ) {
        let json = small_triangles_scene(&triangles, &planes, test, bits);
        let scene = Scene::from_json(&json, Path::new("small.json")).expect("a valid scene");
        let mut quiet = Simulation::new(&scene);
        quiet.finish(&mut Unobserved);
        let mut watched = Simulation::new(&scene);
        let mut watching = Watching::default();
        watched.finish(&mut watching);
        prop_assert_eq!(quiet.buffers(), watched.buffers(), "scene: {}", json);
        prop_assert_eq!(quiet.stats(), watched.stats(), "scene: {}", json);
        prop_assert_eq!(watching.pixels, quiet.stats().tested);
    }
}

/// A planar polygon of 3 to 6 vertices (convex, concave or self-crossing):
/// z = z0 + sx·x + sy·y in the scene's units of quarters and sixths.
fn planar_polygon() -> impl Strategy<Value = Vec<(i64, i64, i64)>> {
    planar_polygon_on(W, H, 60)
}

/// A planar polygon on a `width` × `height` raster, its depths from about
/// `z0` (in sixths) sloping both ways.
fn planar_polygon_on(width: u32, height: u32, z0: i64) -> impl Strategy<Value = Vec<(i64, i64, i64)>> {
    let (x, y) = (-4i64..(i64::from(width) * 4 + 4), -4i64..(i64::from(height) * 4 + 4));
    (prop::collection::vec((x, y), 3..=6), 0i64..z0.max(1), -2i64..3, -2i64..3)
        .prop_map(|(points, z0, sx, sy)| points.into_iter().map(|(x, y)| (x, y, z0 + sx * x + sy * y)).collect())
}

/// Looks at every pixel and scanline, so the rasterizer takes its general
/// path: a crossing list per row, one pixel at a time.
#[derive(Default)]
struct Watching {
    pixels: u64,
    rows: u64,
}

impl Observer for Watching {
    fn scanline(&mut self, _event: &ScanlineEvent<'_>) {
        self.rows += 1;
    }

    fn pixel(&mut self, _event: &PixelEvent) {
        self.pixels += 1;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// The unobserved run (its own loop, two-edge bands, 64-bit spans), a
    /// watched run (the general path) and tiled runs on 1 to 4 threads leave
    /// the same buffers and the same counts.
    #[test]
    fn every_path_draws_alike(
        polygons in prop::collection::vec(planar_polygon(), 1..5),
        tile in 1u32..6,
        threads in 1usize..5,
        test in prop::sample::select(vec!["greater", "less", "greater-equal", "less-equal", "always", "never"]),
        stop in 0usize..5,
    ) {
        // Every depth test: the unobserved loop's branch-free comparison against `DepthTest::passes`.
        let json = scene_json_with_test(&polygons, test);
        every_path_agrees(&json, tile, threads, stop)?;
    }

    /// As [`every_path_draws_alike`], on rasters wider than a tile whose
    /// spans reach 16 to 64 cells (the 64-bit lanes) and whose z-buffers hold
    /// 16 to 30 bits (past the 32-bit lanes' 2^28).
    #[test]
    fn every_path_draws_alike_on_wide_rasters_and_deep_buffers(
        (polygons, width, bits) in (24u32..72, prop::sample::select(vec![16u32, 27, 28, 29, 30]))
            .prop_flat_map(|(width, bits)| {
                let z0 = 6i64 << bits.min(40);
                (prop::collection::vec(planar_polygon_on(width, 6, z0), 1..4), Just(width), Just(bits))
            }),
        tile in 1u32..40,
        threads in 1usize..3,
        test in prop::sample::select(vec!["greater", "less", "greater-equal", "less-equal"]),
        stop in 0usize..3,
    ) {
        let json = scene_json_with_test(&polygons, test)
            .replacen(&format!("\"width\": {W}, \"height\": {H}, \"depth_bits\": 4"), &format!("\"width\": {width}, \"height\": 6, \"depth_bits\": {bits}"), 1);
        every_path_agrees(&json, tile, threads, stop)?;
    }
}

/// The unobserved run, a watched run, tiled runs on `threads` threads and
/// runs partly in order leave the same buffers and counts for the scene `json`.
fn every_path_agrees(json: &str, tile: u32, threads: usize, stop: usize) -> Result<(), TestCaseError> {
    {
        let json = json.to_string();
        // Input that is not a scene is rejected, so that the runner counts it (not passed unrun).
        let Ok(scene) = Scene::from_json(&json, Path::new("prop.json")) else {
            return Err(TestCaseError::reject("not a scene"));
        };
        let mut quiet = Simulation::new(&scene);
        quiet.finish(&mut Unobserved);
        let mut watched = Simulation::new(&scene);
        let mut watching = Watching::default();
        watched.finish(&mut watching);
        let mut tiled = Simulation::new(&scene);
        tiled.finish_parallel(tile, threads, &|| {});
        prop_assert_eq!(quiet.buffers(), watched.buffers(), "scene: {}", json);
        prop_assert_eq!(quiet.buffers(), tiled.buffers(), "tile {}, {} threads, scene: {}", tile, threads, json);
        prop_assert_eq!(quiet.stats(), watched.stats());
        prop_assert_eq!(watching.pixels, quiet.stats().tested);
        prop_assert_eq!(quiet.stats().written, tiled.stats().written);
        // Part of the scene on threads (as `--final` and `--after` draw it), the rest in order.
        let stop = stop.min(scene.polygons.len() - 1);
        let (mut in_order, mut partly) = (Simulation::new(&scene), Simulation::new(&scene));
        in_order.draw_through(stop, &mut Unobserved);
        partly.draw_parallel_through(stop, tile, threads, &|| {});
        prop_assert_eq!(
            in_order.buffers(),
            partly.buffers(),
            "through {}, tile {}, {} threads: {}",
            stop,
            tile,
            threads,
            json
        );
        prop_assert_eq!(in_order.stats(), partly.stats());
        // The first polygons in order, the rest on threads: the tiles start from the cells
        // drawn so far, not from the cleared ones.
        let mut then_tiled = in_order.clone();
        then_tiled.finish_parallel(tile, threads, &|| {});
        while in_order.draw_next(&mut Unobserved).is_some() {}
        while partly.draw_next(&mut Unobserved).is_some() {}
        prop_assert_eq!(quiet.buffers(), partly.buffers());
        prop_assert_eq!(in_order.stats(), partly.stats());
        prop_assert_eq!(quiet.buffers(), then_tiled.buffers(), "tiled after {}: {}", stop, json);
        prop_assert_eq!(quiet.stats().written, then_tiled.stats().written);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// The everyday guard against panics in the reader: any text is a scene or an error,
    /// and a scene small enough runs.
    #[test]
    fn any_scene_text_is_read_or_refused_without_panicking(text in scene_text()) {
        if let Ok(scene) = Scene::from_json(&text, Path::new("arbitrary.json"))
            && u64::from(scene.width) * u64::from(scene.height) <= 64 * 64
        {
            let mut simulation = Simulation::new(&scene);
            simulation.finish(&mut Unobserved);
        }
    }

    #[test]
    fn exact_mode_matches_an_independent_reference(polygons in prop::collection::vec(polygon(), 1..5)) {
        let json = scene_json(&polygons);
        if let Some(ours) = run(&json) {
            prop_assert_eq!(ours, reference(&polygons), "scene: {}", json);
        }
    }

    #[test]
    fn shifting_by_whole_pixels_shifts_the_output(polygons in prop::collection::vec(polygon(), 1..4), dx in 0i64..3, dy in 0i64..3) {
        let shifted: Vec<Vec<(i64, i64, i64)>> =
            polygons.iter().map(|p| p.iter().map(|&(x, y, z)| (x + 4 * dx, y + 4 * dy, z)).collect()).collect();
        let (Some(a), Some(b)) = (run(&scene_json(&polygons)), run(&scene_json(&shifted))) else {
            return Err(TestCaseError::reject("not a scene"));
        };
        let (dx, dy) = (dx as usize, dy as usize);
        // Cell (x, y) of the original is cell (x + dx, y + dy) of the shifted scene, where both are on the raster.
        for y in 0..H as usize - dy {
            for x in 0..W as usize - dx {
                let (ra, rb) = (H as usize - 1 - y, H as usize - 1 - (y + dy));
                prop_assert_eq!(a.0[ra][x], b.0[rb][x + dx], "frame at (x={}, y={})", x, y);
                prop_assert_eq!(a.1[ra][x], b.1[rb][x + dx], "depth at (x={}, y={})", x, y);
            }
        }
    }

    #[test]
    fn starting_at_another_vertex_or_reversing_changes_nothing(polygons in prop::collection::vec(polygon(), 1..4)) {
        let rotated: Vec<Vec<(i64, i64, i64)>> = polygons.iter().map(|p| vec![p[1], p[2], p[0]]).collect();
        let reversed: Vec<Vec<(i64, i64, i64)>> = polygons.iter().map(|p| vec![p[2], p[1], p[0]]).collect();
        let base = run(&scene_json(&polygons));
        prop_assert_eq!(&base, &run(&scene_json(&rotated)));
        prop_assert_eq!(&base, &run(&scene_json(&reversed)));
    }

    #[test]
    fn a_convex_quad_equals_its_fan_of_two_triangles(x0 in 0i64..20, y0 in 0i64..20, w in 4i64..24, h in 4i64..20, z in 0i64..80, slope in -3i64..4) {
        // A planar convex quadrilateral z = z0 + slope·x/24, and its fan from vertex 1.
        let corner = |x: i64, y: i64| (x, y, z + slope * x / 4);
        let quad = vec![corner(x0, y0), corner(x0 + w, y0), corner(x0 + w, y0 + h), corner(x0, y0 + h)];
        let json_quad = scene_json(std::slice::from_ref(&quad)).replace(r#""value": 1"#, r#""value": 2"#);
        let fan = vec![vec![quad[0], quad[1], quad[2]], vec![quad[0], quad[2], quad[3]]];
        // Both triangles get value 2 (the scene writer numbers values by index: 1, 2 …).
        let json_fan = scene_json(&fan).replace(r#""value": 1"#, r#""value": 2"#);
        prop_assert_eq!(run(&json_quad), run(&json_fan), "quad {:?}", quad);
    }
}
