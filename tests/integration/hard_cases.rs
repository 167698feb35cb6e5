//! The numerically hard cases of the exact rules, each pinned by a named test
//! with exact expected buffers.

use std::path::Path;

use zsim::Scene;
use zsim::Simulation;
use zsim::Unobserved;

/// Runs a scene given as JSON and returns (framebuffer, z-buffer), top row first.
fn run(json: &str) -> (Vec<Vec<u32>>, Vec<Vec<u32>>) {
    let scene = Scene::from_json(json, Path::new("inline.json")).unwrap();
    let mut simulation = Simulation::new(&scene);
    simulation.finish(&mut Unobserved);
    (simulation.buffers().frame_rows(), simulation.buffers().depth_level_rows().unwrap())
}

fn rows(text: &str) -> Vec<Vec<u32>> {
    crate::parse_matrix(text)
}

#[test]
fn vertices_on_pixel_centres_are_covered() {
    // Triangle with its corners exactly on the centres of (0,0), (4,0) and (0,4).
    let (frame, _) = run(
        r#"{"width": 6, "height": 5, "polygons": [{"value": 1, "vertices": [[0.5,0.5,5],[4.5,0.5,5],[0.5,4.5,5]]}]}"#,
    );
    assert_eq!(
        frame,
        rows("0 0 0 0 0 0\n1 1 0 0 0 0\n1 1 1 0 0 0\n1 1 1 1 0 0\n1 1 1 1 1 0"),
        "the top vertex's row (y + 1/2 = 4.5 = y_max) is excluded by the half-open rule; the others are in"
    );
}

#[test]
fn edge_through_pixel_centres_covers_them() {
    // The hypotenuse x + y = 5 passes through the centres (0.5, 4.5), (1.5, 3.5), …
    let (frame, _) =
        run(r#"{"width": 5, "height": 5, "polygons": [{"value": 1, "vertices": [[0,0,5],[5,0,5],[0,5,5]]}]}"#);
    assert_eq!(frame, rows("1 0 0 0 0\n1 1 0 0 0\n1 1 1 0 0\n1 1 1 1 0\n1 1 1 1 1"));
}

#[test]
fn vertex_exactly_on_a_scanline_counts_once() {
    // A diamond whose left and right vertices lie on scanline 2.5.
    let (frame, _) = run(
        r#"{"width": 7, "height": 5, "polygons": [{"value": 1, "vertices": [[3.5,0,5],[6,2.5,5],[3.5,5,5],[1,2.5,5]]}]}"#,
    );
    assert_eq!(frame, rows("0 0 0 1 0 0 0\n0 0 1 1 1 0 0\n0 1 1 1 1 1 0\n0 0 1 1 1 0 0\n0 0 0 1 0 0 0"));
}

#[test]
fn horizontal_edges_bound_rows_half_open() {
    // A square from y = 1 to y = 3: rows 1 and 2 (centres 1.5, 2.5); row 3's 3.5 is out.
    let (frame, _) =
        run(r#"{"width": 4, "height": 5, "polygons": [{"value": 1, "vertices": [[1,1,5],[3,1,5],[3,3,5],[1,3,5]]}]}"#);
    assert_eq!(frame, rows("0 0 0 0\n0 0 0 0\n0 1 1 0\n0 1 1 0\n0 0 0 0"));
}

#[test]
fn span_shrinking_to_one_centre_covers_exactly_it() {
    // A downward-pointing triangle whose span on scanline 0.5 is the single point x = 2.5.
    let (frame, _) =
        run(r#"{"width": 5, "height": 2, "polygons": [{"value": 1, "vertices": [[2.5,0.5,5],[4.5,2,5],[0.5,2,5]]}]}"#);
    assert_eq!(frame, rows("0 1 1 1 0\n0 0 1 0 0"));
}

#[test]
fn sliver_thinner_than_a_pixel_covers_only_centres_inside_it() {
    // A sliver 1/256 wide around x = 2.5 covers column 2 on every row; one beside it covers nothing.
    let (frame, _) = run(r#"{"width": 5, "height": 4, "polygons": [
            {"value": 1, "vertices": [["639/256",0,5],["641/256",0,5],["641/256",4,5],["639/256",4,5]]},
            {"value": 2, "vertices": [["700/256",0,5],["701/256",0,5],["701/256",4,5],["700/256",4,5]]}]}"#);
    assert_eq!(frame, rows("0 0 1 0 0\n0 0 1 0 0\n0 0 1 0 0\n0 0 1 0 0"));
}

#[test]
fn depth_exactly_half_rounds_up() {
    // Plane z = x / 2 + 1/4: at the centre of column 0, z = 1/2; column 2, z = 3/2; column 4, 5/2.
    let (_, depth) = run(
        r#"{"width": 5, "height": 1, "depth_bits": 4, "polygons": [{"value": 1, "vertices": [[0,0,"1/4"],[5,0,"11/4"],[5,1,"11/4"],[0,1,"1/4"]]}]}"#,
    );
    assert_eq!(depth, rows("1 1 2 2 3"));
}

#[test]
fn depth_equal_to_the_stored_value_does_not_overwrite() {
    // Two coincident squares at z = 5: the first drawn keeps every pixel.
    let (frame, depth) = run(r#"{"width": 2, "height": 1, "polygons": [
            {"value": 1, "vertices": [[0,0,5],[2,0,5],[2,1,5],[0,1,5]]},
            {"value": 2, "vertices": [[0,0,5],[2,0,5],[2,1,5],[0,1,5]]}]}"#);
    assert_eq!((frame, depth), (rows("1 1"), rows("5 5")));
}

#[test]
fn depth_below_zero_and_above_the_maximum_saturates() {
    // greater: a plane at z = −3 never beats the cleared 0; a plane at z = 40 stores 15.
    let (frame, depth) = run(r#"{"width": 2, "height": 1, "polygons": [
            {"value": 1, "vertices": [[0,0,-3],[1,0,-3],[1,1,-3],[0,1,-3]]},
            {"value": 2, "vertices": [[1,0,40],[2,0,40],[2,1,40],[1,1,40]]}]}"#);
    assert_eq!((frame, depth), (rows("0 2"), rows("0 15")));
    // less: cleared to 15; a plane at z = −3 is written and stores 0, one at 40 is hidden.
    let (frame, depth) = run(r#"{"width": 2, "height": 1, "depth_test": "less", "polygons": [
            {"value": 1, "vertices": [[0,0,-3],[1,0,-3],[1,1,-3],[0,1,-3]]},
            {"value": 2, "vertices": [[1,0,40],[2,0,40],[2,1,40],[1,1,40]]}]}"#);
    assert_eq!((frame, depth), (rows("1 0"), rows("0 15")));
}

#[test]
fn concave_polygon_leaves_its_notch_empty() {
    // A "U" shape: the notch between x = 2 and x = 4 above y = 2 stays background.
    let (frame, _) = run(
        r#"{"width": 6, "height": 4, "polygons": [{"value": 1, "vertices": [[0,0,5],[6,0,5],[6,4,5],[4,4,5],[4,2,5],[2,2,5],[2,4,5],[0,4,5]]}]}"#,
    );
    assert_eq!(frame, rows("1 1 0 0 1 1\n1 1 0 0 1 1\n1 1 1 1 1 1\n1 1 1 1 1 1"));
}

#[test]
fn self_intersecting_polygon_fills_by_even_odd_pairs() {
    // A bow-tie in the plane z = 0 whose two loops run opposite ways: Newell's
    // normal cancels, so it has no plane and covers nothing.
    let (frame, _) =
        run(r#"{"width": 4, "height": 4, "polygons": [{"value": 1, "vertices": [[0,0,5],[4,4,5],[4,0,5],[0,4,5]]}]}"#);
    assert_eq!(frame, rows("0 0 0 0\n0 0 0 0\n0 0 0 0\n0 0 0 0"));
    // A pentagram: the crossings pair 1st–2nd, 3rd–4th, so the centre pentagon
    // is a hole and only the five points are filled. (Expected matrix worked out
    // with an even-odd count of Python `Fraction` crossings at each centre.)
    let (frame, _) = run(
        r#"{"width": 10, "height": 10, "polygons": [{"value": 1, "vertices": [[5,10,5],[8,0,5],[0,6,5],[10,6,5],[2,0,5]]}]}"#,
    );
    assert_eq!(
        frame,
        rows(
            "0 0 0 0 0 0 0 0 0 0
             0 0 0 0 0 0 0 0 0 0
             0 0 0 0 1 1 0 0 0 0
             0 0 0 0 1 1 0 0 0 0
             0 1 1 1 0 0 1 1 1 0
             0 0 1 0 0 0 0 1 0 0
             0 0 0 0 0 0 0 0 0 0
             0 0 0 1 1 1 1 0 0 0
             0 0 1 1 0 0 1 1 0 0
             0 0 1 0 0 0 0 1 0 0"
        )
    );
}

#[test]
fn collinear_polygon_covers_nothing() {
    let (frame, depth) =
        run(r#"{"width": 3, "height": 3, "polygons": [{"value": 1, "vertices": [[0,0,0],[1,1,1],[3,3,3]]}]}"#);
    assert_eq!((frame, depth), (rows("0 0 0\n0 0 0\n0 0 0"), rows("0 0 0\n0 0 0\n0 0 0")));
}

#[test]
fn edge_on_polygon_covers_nothing() {
    let (frame, _) =
        run(r#"{"width": 3, "height": 3, "polygons": [{"value": 1, "vertices": [[1,0,0],[1,3,0],[1,3,5],[1,0,5]]}]}"#);
    assert_eq!(frame, rows("0 0 0\n0 0 0\n0 0 0"));
}

#[test]
fn sliver_1_256_thin_and_thousands_of_pixels_long() {
    // A quad 1/256 px thick around the scanline y = 0.5, 4096 px long: every centre of row 0 lies in it.
    let (frame, _) = run(
        r#"{"width": 4096, "height": 2, "polygons": [{"value": 1, "vertices": [[0, "127/256", 5], [4096, "127/256", 5], [4096, "129/256", 5], [0, "129/256", 5]]}]}"#,
    );
    assert_eq!(frame[1].iter().filter(|&&v| v == 1).count(), 4096, "row 0: all 4096 centres covered");
    assert!(frame[0].iter().all(|&v| v == 0), "row 1 untouched");
    // The same sliver just above the centres covers nothing.
    let (frame, _) = run(
        r#"{"width": 4096, "height": 2, "polygons": [{"value": 1, "vertices": [[0, "129/256", 5], [4096, "129/256", 5], [4096, "130/256", 5], [0, "130/256", 5]]}]}"#,
    );
    assert!(frame.iter().flatten().all(|&v| v == 0));
}

#[test]
fn nearly_edge_on_plane_saturates_instead_of_overflowing() {
    // z = 2^30·y: the normal lies almost in the picture plane. Depths run to 2^32 and beyond
    // the 4-bit range; they saturate at 15 (and the arithmetic, overflow-checked in tests, holds).
    let (frame, depth) = run(
        r#"{"width": 4, "height": 4, "polygons": [{"value": 1, "vertices": [[0, 0, 0], [4, 0, 0], [4, 4, 4294967296], [0, 4, 4294967296]]}]}"#,
    );
    assert!(frame.iter().flatten().all(|&v| v == 1));
    assert!(depth.iter().flatten().all(|&v| v == 15), "{depth:?}");
}

#[test]
fn intersecting_polygons_are_owned_by_the_sign_of_the_exact_depth_difference() {
    // Plane A: z = x; plane B: z = 8 − x + 1/3. They cross at x = 25/6 ≈ 4.17: centres 0.5 … 3.5
    // are B's (B nearer), 4.5 … 7.5 are A's. A is drawn first; B wins only where strictly nearer.
    let (frame, _) = run(r#"{"width": 8, "height": 1, "depth_bits": 8, "polygons": [
            {"value": 1, "vertices": [[0, 0, 0], [8, 0, 8], [8, 1, 8], [0, 1, 0]]},
            {"value": 2, "vertices": [[0, 0, "25/3"], [8, 0, "1/3"], [8, 1, "1/3"], [0, 1, "25/3"]]}]}"#);
    assert_eq!(frame, rows("2 2 2 2 1 1 1 1"));
    // Coplanar and overlapping: equal depths everywhere, so the first drawn keeps every pixel.
    let (frame, _) = run(r#"{"width": 4, "height": 1, "polygons": [
            {"value": 1, "vertices": [[0, 0, 3], [3, 0, 6], [3, 1, 6], [0, 1, 3]]},
            {"value": 2, "vertices": [[1, 0, 4], [4, 0, 7], [4, 1, 7], [1, 1, 4]]}]}"#);
    assert_eq!(frame, rows("1 1 1 2"));
}

#[test]
fn coordinates_at_the_documented_limit_do_not_overflow() {
    // |coordinate|·2D ≤ 2^34 with D = 1: integer coordinates up to ±2^33. A triangle that large
    // covers the whole raster; every intermediate value stays in i128 (overflow checks are on in tests).
    let (frame, depth) = run(
        r#"{"width": 4, "height": 4, "depth_bits": 32, "polygons": [{"value": 1, "vertices": [[-8589934592, -8589934592, -8589934592], [8589934592, -8589934592, 8589934592], [0, 8589934592, 0]]}]}"#,
    );
    assert!(frame.iter().flatten().all(|&v| v == 1));
    // The plane is z = x: at the centre x + 1/2 the depth is stored rounded half up.
    assert_eq!(depth[3], vec![1, 2, 3, 4], "{depth:?}");
}

/// Regression (found by the fuzzer): the exact depth at a span's end, a crossing
/// rather than a pixel centre, overflowed `i128` for coordinates near the word
/// limit and panicked while `step` recorded the scanline; it was then reported
/// as too large. Computed from the reduced plane `z = −(Ax + By + D)/C`, every
/// span end now has its exact depth: the plane through the three vertices, in
/// big rationals.
#[test]
fn span_end_depths_near_the_word_limit_are_exact() {
    use num_bigint::BigInt;
    use num_rational::BigRational;
    let vertices = [
        [5722406912i64, 168441290, -4290115062],
        [36, -8236231403, -8589934592],
        [-8589934592, -8589934592, -8589934592],
    ];
    let json = format!(
        r#"{{"width": 16, "height": 16, "depth_bits": 21, "polygons": [{{"value": 1, "vertices": {vertices:?}}}]}}"#
    );
    let scene = Scene::from_json(&json, Path::new("fuzz.json")).unwrap();
    let mut recorder = zsim::Recorder::default();
    Simulation::new(&scene).finish(&mut recorder);
    let v: Vec<[BigRational; 3]> = vertices.iter().map(|p| p.map(|c| BigRational::from_integer(c.into()))).collect();
    // z at (x, y) on the plane through the vertices (barycentric weights by Cramer's rule).
    let z_at = |x: &BigRational, y: &BigRational| {
        let det = (&v[1][0] - &v[0][0]) * (&v[2][1] - &v[0][1]) - (&v[2][0] - &v[0][0]) * (&v[1][1] - &v[0][1]);
        let w1 = ((x - &v[0][0]) * (&v[2][1] - &v[0][1]) - (&v[2][0] - &v[0][0]) * (y - &v[0][1])) / &det;
        let w2 = ((&v[1][0] - &v[0][0]) * (y - &v[0][1]) - (x - &v[0][0]) * (&v[1][1] - &v[0][1])) / &det;
        &v[0][2] + w1 * (&v[1][2] - &v[0][2]) + w2 * (&v[2][2] - &v[0][2])
    };
    let mut ends = 0;
    for scanline in &recorder.scanlines {
        let y = BigRational::new(BigInt::from(2 * scanline.row + 1), BigInt::from(2));
        for span in &scanline.spans {
            for (x, depth) in [(&span.left, &span.left_depth), (&span.right, &span.right_depth)] {
                let depth = depth.as_ref().unwrap_or_else(|| panic!("row {}: no depth at x = {x}", scanline.row));
                assert_eq!(depth.to_big(), z_at(&x.to_big(), &y), "row {}, x = {x}", scanline.row);
                ends += 1;
            }
        }
    }
    assert_eq!(ends, 32, "one span per row, two ends each");
}

/// Regression (found by the fuzzer): in the incremental float modes an edge
/// starting billions of rows below the raster was stepped row by row up to it,
/// which hung; edges are now set up at the first row on the raster.
#[test]
fn incremental_edges_start_at_the_raster_not_far_below_it() {
    let scene = Scene::from_json(r#"{"width": 16, "height": 16, "depth_bits": 5, "polygons": [{"value": 1, "vertices": [[36, 12, 29], [29, -7027767160, -8589934592], [-8589934592, -8589934592, -8589934592], [-8589934592, -8589934592, -8589934592]]}]}"#,
        Path::new("fuzz.json"),
    )
    .unwrap();
    let start = std::time::Instant::now();
    let (stepped, _) = zsim::arith::run(&scene, zsim::arith::Arith::F32Incremental).unwrap();
    let (exact, _) = zsim::arith::run(&scene, zsim::arith::Arith::Exact).unwrap();
    assert!(start.elapsed().as_secs() < 5, "set up at the raster, not stepped from row −7·10^9");
    assert_eq!(stepped.width(), exact.width());
}
