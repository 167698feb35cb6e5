//! The exact range on clip-space input: triangles cut by the view volume get
//! vertices with huge denominators, yet are drawn exactly, checked against an
//! independent computation in big rationals.

use std::path::Path;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use zsim::Scene;
use zsim::Simulation;
use zsim::Stored;
use zsim::Unobserved;

const SIZE: u32 = 16;
const DEPTH_MAX: i64 = 65535;

/// A small deterministic generator (xorshift), so the counts below are fixed.
struct Xorshift(u64);

impl Xorshift {
    /// A number with 3 decimals in `low … high` (thousandths), as text.
    fn decimal(&mut self, low: i64, high: i64) -> String {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        let v = low + (self.0 % (high - low + 1) as u64) as i64;
        format!("{}{}.{:03}", if v < 0 { "-" } else { "" }, v.abs() / 1000, v.abs() % 1000)
    }
}

/// A decimal `-12.345…` of any length, exactly.
fn decimal(text: &str) -> BigRational {
    let (whole, digits) = text.split_once('.').unwrap_or((text, ""));
    BigRational::new(format!("{whole}{digits}").parse().unwrap(), BigInt::from(10).pow(digits.len() as u32))
}

fn parse(text: &str) -> BigRational {
    let (sign, digits) = text.strip_prefix('-').map_or((1, text), |rest| (-1, rest));
    let (whole, fraction) = digits.split_once('.').unwrap();
    let n: i64 = format!("{whole}{fraction}").parse().unwrap();
    BigRational::new(BigInt::from(sign * n), BigInt::from(1000))
}

/// Where the view ray through the centre of pixel `(column, row)` meets the
/// triangle, by the triangle's own clip-space vertices: `None` when it misses
/// the triangle or the view volume; otherwise whether it meets it strictly
/// inside (no tie with any edge, clip plane or vertex) and the depth there,
/// `(z/w + 1)·depth_max/2`.
fn independent(v: &[[BigRational; 4]], column: u32, row: u32) -> Option<(bool, BigRational)> {
    let ndc = |i: u32| BigRational::new(BigInt::from(2 * i + 1), BigInt::from(SIZE)) - BigRational::one();
    let (xn, yn) = (ndc(column), ndc(row));
    // The point Σλᵢ·Vᵢ lies on the ray when x = xn·w and y = yn·w: λ is along f × g.
    let f: Vec<BigRational> = v.iter().map(|p| &p[0] - &xn * &p[3]).collect();
    let g: Vec<BigRational> = v.iter().map(|p| &p[1] - &yn * &p[3]).collect();
    let mu = [&f[1] * &g[2] - &f[2] * &g[1], &f[2] * &g[0] - &f[0] * &g[2], &f[0] * &g[1] - &f[1] * &g[0]];
    let sum = &mu[0] + &mu[1] + &mu[2];
    if sum.is_zero() {
        return None;
    }
    let lambda: Vec<BigRational> = mu.iter().map(|m| m / &sum).collect();
    if lambda.iter().any(Signed::is_negative) {
        return None;
    }
    let at = |axis: usize| (0..3).fold(BigRational::zero(), |s, i| s + &lambda[i] * &v[i][axis]);
    let (z, w) = (at(2), at(3));
    if !w.is_positive() || z > w || z < -&w {
        return None;
    }
    let strictly = lambda.iter().all(Signed::is_positive) && z < w && z > -&w;
    let depth = (z / w + BigRational::one()) * BigRational::new(BigInt::from(DEPTH_MAX), BigInt::from(2));
    Some((strictly, depth))
}

/// Draws a one-polygon scene (an exact store, value 1) and checks every
/// pixel against `expected(column, row)`, which says whether the centre is
/// on the polygon, strictly inside it, and the exact depth stored there: a
/// covered centre must be expected, with exactly that depth, and every
/// centre strictly inside must be covered. Returns the pixels covered and how
/// many of them hold a depth beyond 128 bits.
fn check_pixels(json: &str, expected: impl Fn(u32, u32) -> Option<(bool, BigRational)>) -> (usize, usize) {
    let scene = Scene::from_json(json, Path::new("scene.json"))
        .unwrap_or_else(|e| panic!("{}: {json}", e.message(zsim::Lang::En)));
    let mut simulation = Simulation::new(&scene);
    simulation.finish(&mut Unobserved);
    let buffers = simulation.buffers();
    let (mut covered, mut beyond) = (0, 0);
    for row in 0..SIZE {
        for column in 0..SIZE {
            let expected = expected(column, row);
            if buffers.frame(column, row) == 1 {
                covered += 1;
                let Some((_, depth)) = expected else { panic!("({column}, {row}) drawn outside: {json}") };
                let Stored::Exact(stored) = buffers.depth(column, row) else { panic!("an exact store: {json}") };
                beyond += usize::from(stored.word().is_none());
                assert_eq!(stored.to_big(), depth, "({column}, {row}) of {json}");
            } else {
                let strictly = expected.is_some_and(|(strictly, _)| strictly);
                assert!(!strictly, "({column}, {row}) strictly inside but not drawn: {json}");
            }
        }
    }
    (covered, beyond)
}

/// Random triangles of 3-decimal clip-space coordinates (x, y, z in −3 … 3,
/// w in −1 … 3), most of them cut by the view volume: every one is drawn
/// (before the big-integer tier kept its vertices in big integers, 14 of
/// these 100 were refused as beyond the exact range, and 86 before it worked
/// from lines and planes). Each covers only centres where the view ray meets
/// the triangle inside the view volume, with exactly the depth there, and
/// covers every centre strictly inside.
#[test]
fn clipped_clip_space_triangles_are_drawn_exactly() {
    let mut random = Xorshift(0x2545_f491_4f6c_dd1d);
    let (mut covered, mut big) = (0, 0);
    for case in 0..100 {
        let vertices: Vec<[String; 4]> = (0..3)
            .map(|_| {
                let [x, y, z] = std::array::from_fn(|_| random.decimal(-3000, 3000));
                [x, y, z, random.decimal(-1000, 3000)]
            })
            .collect();
        let json = format!(
            r#"{{"width": {SIZE}, "height": {SIZE}, "depth_bits": 16, "depth_test": "less", "rules": {{"store": "exact"}}, "polygons": [{{"value": 1, "vertices": {}}}]}}"#,
            serde_json::to_string(&vertices).unwrap()
        );
        let scene = Scene::from_json(&json, Path::new("clip.json"))
            .unwrap_or_else(|e| panic!("case {case}: {}", e.message(zsim::Lang::En)));
        big += usize::from(scene.polygons[0].geometry().is_big());
        let v: Vec<[BigRational; 4]> = vertices.iter().map(|p| p.clone().map(|c| parse(&c))).collect();
        covered += check_pixels(&json, |column, row| independent(&v, column, row)).0;
    }
    assert_eq!(big, 70, "drawn on the big-integer tier");
    assert_eq!(covered, 3070, "pixels covered");
}

/// A number `whole + 0.ddd…` with `places` random decimals, as text.
fn many_digits(random: &mut Xorshift, whole: std::ops::Range<i64>, places: usize) -> String {
    let whole = random.decimal(whole.start * 1000, whole.end * 1000 - 1000).split('.').next().unwrap().to_string();
    let digits: String = (0..places).map(|_| random.decimal(0, 9).chars().nth(4).unwrap()).collect();
    format!("{whole}.{digits}")
}

/// Whether the centre of `(column, row)` lies in the triangle (edges
/// included) and strictly inside it, and the depth of its plane there, in
/// big rationals (barycentric weights by Cramer's rule).
fn in_triangle(v: &[[BigRational; 3]], column: u32, row: u32) -> Option<(bool, BigRational)> {
    let half = |i: u32| BigRational::new(BigInt::from(2 * i + 1), BigInt::from(2));
    let (cx, cy) = (half(column), half(row));
    let side = |i: usize| {
        let (a, b) = (&v[i], &v[(i + 1) % 3]);
        (&b[0] - &a[0]) * (&cy - &a[1]) - (&b[1] - &a[1]) * (&cx - &a[0])
    };
    let sides: Vec<BigRational> = (0..3).map(side).collect();
    let inside = sides.iter().all(|s| !s.is_negative()) || sides.iter().all(|s| !s.is_positive());
    if !inside {
        return None;
    }
    let det = (&v[1][0] - &v[0][0]) * (&v[2][1] - &v[0][1]) - (&v[2][0] - &v[0][0]) * (&v[1][1] - &v[0][1]);
    let w1 = ((&cx - &v[0][0]) * (&v[2][1] - &v[0][1]) - (&v[2][0] - &v[0][0]) * (&cy - &v[0][1])) / &det;
    let w2 = ((&v[1][0] - &v[0][0]) * (&cy - &v[0][1]) - (&cx - &v[0][0]) * (&v[1][1] - &v[0][1])) / &det;
    let z = &v[0][2] + w1 * (&v[1][2] - &v[0][2]) + w2 * (&v[2][2] - &v[0][2]);
    Some((sides.iter().all(|s| !s.is_zero()), z))
}

/// Triangles given with 7 to 28 decimals (up to the 30 significant digits a
/// number may have): from about 14 significant digits their planes, and so
/// their depths, outgrow 128 bits (they were refused as too large for exact
/// arithmetic before). Every one is drawn: each covers only centres inside
/// the triangle, with exactly its plane's depth there (computed apart in big
/// rationals), and every centre strictly inside.
#[test]
fn triangles_with_many_significant_digits_are_drawn_exactly() {
    let mut random = Xorshift(0x9e37_79b9_7f4a_7c15);
    let (mut covered, mut beyond) = (0, 0);
    for places in [7, 10, 12, 14, 16, 17, 20, 24, 28].iter().cycle().take(27) {
        let vertices: Vec<[String; 3]> = (0..3)
            .map(|_| {
                [
                    many_digits(&mut random, 0..16, *places),
                    many_digits(&mut random, 0..16, *places),
                    many_digits(&mut random, 1..9, *places),
                ]
            })
            .collect();
        let json = format!(
            r#"{{"width": {SIZE}, "height": {SIZE}, "rules": {{"store": "exact"}}, "polygons": [{{"value": 1, "vertices": {}}}]}}"#,
            serde_json::to_string(&vertices).unwrap()
        );
        let v: Vec<[BigRational; 3]> = vertices.iter().map(|p| p.each_ref().map(|c| decimal(c))).collect();
        let (pixels, big) = check_pixels(&json, |column, row| in_triangle(&v, column, row));
        (covered, beyond) = (covered + pixels, beyond + big);
    }
    assert_eq!((covered, beyond), (505, 326), "pixels covered, and of them with depths beyond 128 bits");
}

/// Polygons that were refused as too large for exact arithmetic (the
/// bad-input snapshot held the first two until the reports went beyond 128
/// bits): 30-digit coordinates, whose plane passes 128 bits, two
/// denominators whose lcm does, with an edge whose line does, and
/// coordinates of 40 and 60 significant digits (refused when they were read,
/// as numbers are past 30 digits). Drawn, each covered centre inside with
/// its plane's depth, every centre strictly inside covered.
#[test]
fn polygons_once_refused_as_too_large_are_drawn_exactly() {
    let cases = [
        (r#"[[0,0,0],["123456789012345678901234567890",7,3],[5,"987654321098765432109876543211",11]]"#, 256),
        (
            r#"[["1/288230376151711717", 0, 0], ["800000000000000000000000000009/100000000000000000000000000001", 4, 0], [0, 4, 3]]"#,
            16,
        ),
        (
            r#"[["1.234567890123456789012345678901234567891", "2.5", "1"], ["15.987654321098765432109876543210987654321098765432109876543211", "3", "2"], [4, "14.000000000000000000000000000000000000000000000001", "3"]]"#,
            81,
        ),
    ];
    for (vertices, expected) in cases {
        let json = format!(
            r#"{{"width": {SIZE}, "height": {SIZE}, "depth_test": "always", "rules": {{"store": "exact"}}, "polygons": [{{"value": 1, "vertices": {vertices}}}]}}"#
        );
        let scene = Scene::from_json(&json, Path::new("large.json"))
            .unwrap_or_else(|e| panic!("{}", e.message(zsim::Lang::En)));
        let v: Vec<[BigRational; 3]> =
            scene.polygons[0].vertices().iter().map(|p| p.each_ref().map(zsim::Exact::to_big)).collect();
        let (covered, _) = check_pixels(&json, |column, row| in_triangle(&v, column, row));
        assert_eq!(covered, expected, "{vertices}");
    }
}

/// A w-buffer on a polygon of many significant digits (refused before as
/// "too fine for the w-buffer's exact arithmetic"), with a distance beyond
/// 2^20 (refused before too): each covered centre stores the eye-space depth
/// `d·z'/(d + z')` of the projected plane's `z'` there, computed apart in
/// big rationals from the projection `x' = c + (x − c)·d/(d − z)`,
/// `z' = z·d/(d − z)`.
#[test]
fn a_w_buffer_stores_eye_depths_beyond_128_bits_exactly() {
    let vertices = [
        ["3.1234567890123456789", "2.9876543210987654321", "-5.5555555555555555551"],
        ["13.123456789012345678", "4.1111111111111111111", "-9.8765432109876543219"],
        ["7.7777777777777777777", "13.987654321098765432", "-2.2222222222222222229"],
    ];
    let distance = "2000003/2";
    let json = format!(
        r#"{{"width": {SIZE}, "height": {SIZE}, "depth_test": "always", "rules": {{"store": "exact"}}, "effects": {{"perspective": {{"distance": "{distance}", "near": 1, "store": "w"}}}}, "polygons": [{{"value": 1, "vertices": {}}}]}}"#,
        serde_json::to_string(&vertices).unwrap()
    );
    let d = BigRational::new(BigInt::from(2_000_003), BigInt::from(2));
    let centre = BigRational::new(BigInt::from(SIZE), BigInt::from(2));
    let projected: Vec<[BigRational; 3]> = vertices
        .iter()
        .map(|v| {
            let [x, y, z] = v.each_ref().map(|c| decimal(c));
            let scale = &d / (&d - &z);
            [&centre + (x - &centre) * &scale, &centre + (y - &centre) * &scale, z * scale]
        })
        .collect();
    let eye_depth = |(strictly, z): (bool, BigRational)| (strictly, &d * &z / (&d + &z));
    let (covered, beyond) = check_pixels(&json, |column, row| in_triangle(&projected, column, row).map(eye_depth));
    assert_eq!((covered, beyond), (53, 53), "pixels covered, and of them with depths beyond 128 bits");
}

/// Clip-space triangles given with 14 to 30 significant digits: clipping
/// and the division by w give raster vertices beyond 128-bit fractions
/// (they were refused before: "gives numbers beyond the exact range"), and
/// they are drawn as the 3-decimal ones are, every pixel checked against the
/// view ray in big rationals. The first is the triangle the bad-input
/// snapshot held.
#[test]
fn clip_space_triangles_with_many_digits_are_drawn_exactly() {
    let mut random = Xorshift(0x0123_4567_89ab_cdef);
    let mut triangles: Vec<Vec<[String; 4]>> = vec![vec![
        ["0.123456789012345678901234567891", "0.2", "0.3", "1"].map(String::from),
        ["5", "0.1", "0.2", "1"].map(String::from),
        ["0.1", "7", "0.1", "0.999999999999999999999999999999"].map(String::from),
    ]];
    for places in [14, 20, 28] {
        for _ in 0..10 {
            triangles.push(
                (0..3)
                    .map(|_| {
                        let [x, y, z] = std::array::from_fn(|_| many_digits(&mut random, -3..4, places));
                        [x, y, z, many_digits(&mut random, 0..3, places)]
                    })
                    .collect(),
            );
        }
    }
    let (mut covered, mut beyond) = (0, 0);
    for (case, vertices) in triangles.iter().enumerate() {
        let json = format!(
            r#"{{"width": {SIZE}, "height": {SIZE}, "depth_bits": 16, "depth_test": "less", "rules": {{"store": "exact"}}, "polygons": [{{"value": 1, "vertices": {}}}]}}"#,
            serde_json::to_string(vertices).unwrap()
        );
        let scene = Scene::from_json(&json, Path::new("clip.json"))
            .unwrap_or_else(|e| panic!("case {case}: {}", e.message(zsim::Lang::En)));
        beyond += usize::from(scene.polygons[0].vertices().iter().flatten().any(|v| v.word().is_none()));
        let v: Vec<[BigRational; 4]> = vertices.iter().map(|p| p.each_ref().map(|c| decimal(c))).collect();
        covered += check_pixels(&json, |column, row| independent(&v, column, row)).0;
    }
    assert_eq!((covered, beyond), (713, 22), "pixels covered; triangles with raster vertices beyond 128 bits");
}
