//! UIUC CS 418's rasterizer assignment: the course's own input files and
//! reference images, read from `../shared/peer/uiuc-cs418/` (never copied
//! into the project). Where that folder is absent the tests say so on stderr.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use zsim::cs418::{Arithmetic, Image, RastFile, compare_images, differences, render};

use crate::{scene_file, snapshot, zsim};

/// The peer folder.
fn cases() -> PathBuf {
    crate::peer("uiuc-cs418", "the CS 418 reference images")
}

fn case(dir: &Path, name: &str) -> RastFile {
    let text = std::fs::read_to_string(dir.join(format!("rast-{name}.txt"))).expect("case file");
    RastFile::parse(&text, &|_| Err(zsim::cs418::TextureProblem::Missing))
        .unwrap_or_else(|e| panic!("{name}: {}", e.message(zsim::Lang::En)))
}

/// A case whose textures (not in the folder) are all replaced by one texel.
fn case_with_stand_in(dir: &Path, name: &str, texel: [u8; 4]) -> RastFile {
    let text = std::fs::read_to_string(dir.join(format!("rast-{name}.txt"))).expect("case file");
    RastFile::parse(&text, &|_| Ok(std::sync::Arc::new(stand_in(texel))))
        .unwrap_or_else(|e| panic!("{name}: {}", e.message(zsim::Lang::En)))
}

fn reference(dir: &Path, name: &str) -> Image {
    Image::from_png(&std::fs::read(dir.join(format!("rast-{name}.png"))).expect("reference image")).expect("a PNG")
}

/// Every case whose inputs are all in the folder (textures and decals need
/// images that are not), drawn in the course's f64 arithmetic, equals its
/// reference image within 1 per RGBA channel.
#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn every_case_with_its_inputs_reproduces_the_reference_image() {
    let dir = cases();
    let all = [
        "gray",
        "smallgap",
        "depth",
        "sRGB",
        "smoothcolor",
        "checkers",
        "gammabox",
        "perspective",
        "cull",
        "elements",
        "matrix",
        "2d3d",
        "alpha",
        "fsaa2",
        "fsaa8",
        "frustum",
    ];
    for name in all {
        let image = render(&case(&dir, name), Arithmetic::DdaF64)
            .unwrap_or_else(|e| panic!("{name}: {}", e.message(zsim::Lang::En)))
            .image;
        // rast-elements.txt draws the image the course calls oldlogo.
        let reference = reference(&dir, if name == "elements" { "oldlogo" } else { name });
        let difference = compare_images(&image, &reference, 1).expect("same size");
        assert_eq!(difference.pixels, vec![], "{name}: pixels differing by more than 1");
    }
}

/// The cases that load textures, with the course's real textures beside them:
/// points1, points2 and decals equal their references within 1 per RGBA
/// channel, texel for texel. The rule that got them there: the texel shown is
/// the one whose centre is nearest, `s·W` rounded half up (then wrapped), with
/// t = 0 at the file's top row; with `⌊s·W⌋` instead 33, 67 and 12,708 pixels
/// differed. textures too, once a negative coordinate's texel lies 5 texels
/// further on (690 pixels differed without that shift).
#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn textured_cases_reproduce_their_references_texel_for_texel() {
    let dir = cases();
    let with_textures = |name: &str| {
        let text = std::fs::read_to_string(dir.join(format!("rast-{name}.txt"))).unwrap();
        let load = |file: &str| {
            let bytes = std::fs::read(dir.join(file)).map_err(|_| zsim::cs418::TextureProblem::Missing)?;
            Image::from_png(&bytes).map(std::sync::Arc::new).map_err(zsim::cs418::TextureProblem::Image)
        };
        RastFile::parse(&text, &load).unwrap_or_else(|e| panic!("{name}: {}", e.message(zsim::Lang::En)))
    };
    for name in ["points1", "points2", "decals", "textures"] {
        let image = render(&with_textures(name), Arithmetic::DdaF64).unwrap().image;
        let difference = compare_images(&image, &reference(&dir, name), 1).expect("same size");
        assert_eq!(difference.pixels, vec![], "{name}: pixels differing by more than 1");
    }
}

/// manyclip clips triangles against the whole view volume. The course does
/// not say in what order its code clips the six planes or from which end it
/// measures an intersection, and on this case that float detail decides one
/// pixel: zsim (near, far, then x and y planes, Sutherland–Hodgman) draws
/// pixel (8, 10) on the boundary of a clipped edge, the reference leaves it
/// empty. Every other pixel is within 1, including the whole top row, which
/// the course's floats leave empty and exact arithmetic covers (see the next test).
#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn manyclip_reproduces_the_reference_but_for_one_clipped_boundary_pixel() {
    let dir = cases();
    let image = render(&case(&dir, "manyclip"), Arithmetic::DdaF64).expect("renders").image;
    let difference = compare_images(&image, &reference(&dir, "manyclip"), 1).expect("same size");
    let places: Vec<(u32, u32)> = difference.pixels.iter().map(|p| (p.0, p.1)).collect();
    assert_eq!(places, vec![(8, 10)]);
}

/// In exact arithmetic the clipped top edge of manyclip's first triangle lies
/// exactly on row 0, which the DDA's half-open rows include; the course's
/// floats put it a hair below, so the reference leaves the row empty. The
/// report names the triangle, the row and both spans.
#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn exact_arithmetic_shows_where_the_course_floats_land_on_the_other_side() {
    let dir = cases();
    let case = case(&dir, "manyclip");
    let (course, exact) = (render(&case, Arithmetic::DdaF64).unwrap(), render(&case, Arithmetic::Exact).unwrap());
    let cells = differences(&course, &exact);
    let top_row = cells.iter().filter(|c| c.y == 0).count();
    assert_eq!((cells.len(), top_row), (37, 26));
    let out = zsim(&[
        "cs418",
        "run",
        dir.join("rast-manyclip.txt").to_str().unwrap(),
        "-o",
        env!("CARGO_TARGET_TMPDIR"),
        "--arith",
        "exact",
    ]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stdout.contains("37 samples where the course's f64 arithmetic and exact arithmetic disagree"));
    assert!(out.stdout.contains(
        "pixel (14, 0): the triangle of vertices 0, 1, 2 (line 13): on row 0 its span is [40, 40) in f64 but [412/31, 40) exactly, so x = 14 is outside in f64 and inside exactly"
    ), "{}", out.stdout);
}

/// A one-texel texture of one colour, standing in for the course's textures
/// (block-I-*.png), which are not in the folder.
fn stand_in(rgba: [u8; 4]) -> Image {
    Image { width: 1, height: 1, rgba: rgba.to_vec() }
}

/// points1 and points2 end with textured point sprites whose texture is not
/// in the folder. Drawn with a stand-in texture of a colour the case never
/// draws (magenta), every pixel the stand-in does not show equals the
/// reference within 1, and the pixels it shows are exactly those where the
/// reference shows the texture: no colour appears in both sets. So the
/// sprites' squares, their depth against the triangles and points, and
/// everything else are the course's; only which texel each sprite pixel
/// shows cannot be checked here.
#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn points_match_the_reference_with_a_stand_in_for_the_missing_texture() {
    let dir = cases();
    let magenta = [255, 0, 255, 255];
    for (name, shown) in [("points1", 3342), ("points2", 3770)] {
        let case = case_with_stand_in(&dir, name, magenta);
        let image = render(&case, Arithmetic::DdaF64).unwrap().image;
        let reference = reference(&dir, name);
        let (mut texture_colours, mut other_colours) = (HashSet::new(), HashSet::new());
        for y in 0..image.height {
            for x in 0..image.width {
                let (a, b) = (image.pixel(x, y), reference.pixel(x, y));
                if a == magenta {
                    texture_colours.insert(b);
                    continue;
                }
                other_colours.insert(b);
                assert!(a.iter().zip(&b).all(|(p, q)| p.abs_diff(*q) <= 1), "{name} ({x}, {y}): {a:?} vs {b:?}");
            }
        }
        let count = image.rgba.chunks(4).filter(|p| *p == magenta).count();
        assert_eq!(count, shown, "{name}: pixels showing the sprites");
        assert!(texture_colours.contains(&[240, 88, 56, 255]), "{name}: the texture's orange");
        assert_eq!(texture_colours.intersection(&other_colours).count(), 0, "{name}");
    }
}

/// What is drawn where does not depend on textures, so `cs418 import` does
/// not read them: points1, copied alone into a folder without its texture,
/// imports (while `cs418 run` says which file is missing).
#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn import_does_not_need_the_textures() {
    let dir = cases();
    let alone = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cs418-without-textures");
    std::fs::create_dir_all(&alone).unwrap();
    let case = alone.join("rast-points1.txt");
    std::fs::copy(dir.join("rast-points1.txt"), &case).unwrap();
    assert!(!alone.join("block-I-orange-background.png").exists());
    let out = zsim(&["cs418", "import", case.to_str().unwrap()]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert_eq!(out.stdout.matches("\"name\": \"point ").count(), 20, "{}", out.stdout);
    // The preset by its name, not the old `gpu` it is also read as.
    assert!(out.stdout.contains(r#""rules": {"preset": "vulkan", "store": "exact"}"#), "{}", out.stdout);
    let run = zsim(&["cs418", "run", case.to_str().unwrap(), "-o", env!("CARGO_TARGET_TMPDIR")]);
    assert_eq!(run.code, 2);
    assert!(
        run.stderr.ends_with("line 17: texture \"block-I-orange-background.png\": no such file beside the case\n"),
        "{}",
        run.stderr
    );
}

/// textures and decals need four textures that are not in the folder; with
/// stand-ins (opaque for textures, half transparent for decals) zsim covers
/// exactly the pixels the reference covers.
#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn textured_cubes_cover_the_reference_pixels_with_stand_in_textures() {
    let dir = cases();
    for (name, texel) in [("textures", [255, 255, 0, 255]), ("decals", [255, 255, 0, 128])] {
        let case = case_with_stand_in(&dir, name, texel);
        let image = render(&case, Arithmetic::DdaF64).unwrap().image;
        let reference = reference(&dir, name);
        let covered = |image: &Image| image.rgba.chunks(4).map(|p| p[3] > 0).collect::<Vec<_>>();
        let ours = covered(&image);
        assert_eq!(ours, covered(&reference), "{name}");
        assert_eq!(ours.iter().filter(|c| **c).count(), 32363, "{name}");
    }
}

/// The command line writes the PNG the case names and compares it.
#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn run_writes_the_named_png_and_compares_it() {
    let dir = cases();
    let out_dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cs418-gray");
    let gray_against = |png: &str| {
        let (case, reference) = (dir.join("rast-gray.txt"), dir.join(png));
        zsim(&[
            "cs418",
            "run",
            case.to_str().unwrap(),
            "-o",
            out_dir.to_str().unwrap(),
            "--compare",
            reference.to_str().unwrap(),
        ])
    };
    let out = gray_against("rast-gray.png");
    assert_eq!(out.code, 0, "{}", out.stderr);
    assert!(out.stdout.contains("every channel of every pixel within 1"), "{}", out.stdout);
    let written = Image::from_png(&std::fs::read(out_dir.join("gray.png")).unwrap()).unwrap();
    assert_eq!((written.width, written.height), (20, 30));
    // A wrong answer exits 1 and lists the pixels.
    let out = gray_against("rast-smoothcolor.png");
    assert_eq!(out.code, 1);
    assert!(out.stdout.contains("pixels differ by more than 1"), "{}", out.stdout);
}

/// Malformed CS 418 files: exit 2, one line with the file and line, nothing on stdout.
#[test]
fn bad_cs418_files_name_the_file_the_line_and_the_problem() {
    let cases = [
        ("unknown.txt", "png 4 4 a.png\nfrobnicate 1 2\n", "line 2: unknown command \"frobnicate\""),
        (
            "count.txt",
            "png 4 4 a.png\nposition 2 1 2 3\n",
            "line 2: position 2: 3 numbers is not a whole number of vertices (1 and 1 left over)",
        ),
        (
            "range.txt",
            "png 4 4 a.png\nposition 2 0 0 1 0 0 1\ncolor 3 1 1 1 1 1 1 1 1 1\ndrawArraysTriangles 1 3\n",
            "line 4: vertex 3 is read, but \"position\" has 3 vertices",
        ),
        (
            "colours.txt",
            "png 4 4 a.png\nposition 2 0 0 1 0 0 1\ndrawArraysTriangles 0 3\n",
            "line 3: vertex 0 is read, but \"color\" has 0 vertices",
        ),
        (
            "elements.txt",
            "png 4 4 a.png\nposition 2 0 0 1 0 0 1\ncolor 3 1 1 1 1 1 1 1 1 1\nelements 0 1 2\ndrawElementsTriangles 6 0\n",
            "line 5: drawElementsTriangles 6 0 reads elements 0…5, but \"elements\" has 3",
        ),
        (
            "texture.txt",
            "png 4 4 a.png\ntexture wood.png\n",
            "line 2: texture \"wood.png\": no such file beside the case",
        ),
        (
            // The case names itself as its texture: a file, but not a PNG.
            "itself.txt",
            "png 4 4 a.png\ntexture itself.txt\n",
            "line 2: texture \"itself.txt\": not a PNG image (Invalid PNG signature.)",
        ),
        (
            "far.txt",
            "png 10 10 a.png\nposition 4 0 0 0 1 1 0 0 0.000000001 0 1 0 1\ncolor 3 1 1 1 1 1 1 1 1 1\ndrawArraysTriangles 0 3\n",
            "line 4: a vertex lands at (5000000004.999999, 5) on the image, too far outside it to rasterize (more than 1000 image sizes away): turn on \"frustum\" to clip it",
        ),
    ];
    for (name, text, message) in cases {
        let (dir, file) = scene_file(name, text);
        let path = dir.join(&file);
        let out = zsim(&["cs418", "run", path.to_str().unwrap(), "-o", dir.join("out").to_str().unwrap()]);
        assert_eq!(out.code, 2, "{name}");
        assert!(out.stdout.is_empty(), "{name}");
        assert_eq!(out.stderr, format!("zsim: {}: {message}\n", path.display()), "{name}");
    }
    // In the reader's language, the line's word too.
    let (dir, file) = scene_file("colours-ru.txt", "png 4 4 a.png\nposition 2 0 0 1 0 0 1\ndrawArraysTriangles 0 3\n");
    let path = dir.join(&file);
    let out = zsim(&["cs418", "run", path.to_str().unwrap(), "-o", dir.join("out").to_str().unwrap(), "--lang", "ru"]);
    assert_eq!(out.code, 2);
    assert_eq!(out.stderr, format!("zsim: {}: строка 3: читается вершина 0, а в «color» вершин 0\n", path.display()));
    {}
}

/// `run --compare-rules gpu` on two triangles sharing an edge: the book
/// draws the shared diagonal twice and the square's top and right edges not
/// at all; the top-left rule draws the diagonal once and swaps which outer
/// edges are in.
#[test]
fn compare_rules_lists_the_cells_and_the_edges_that_decided_them() {
    let out = zsim(&["run", "examples/shared_edge.json", "--compare-rules", "gpu"]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    snapshot!("compare_rules_shared_edge", out.stdout);
}

/// `zsim cs418 import` gives a scene that zsim's own rasterizer, with the
/// `gpu` rules, draws sample for sample as the course's DDA does in exact
/// arithmetic: each framebuffer cell holds the number of the primitive the
/// course's image shows there. Cases whose divisions by w give denominators
/// beyond zsim's exact range would be refused by the scene reader, and the
/// test would say which. textures and decals (64k samples each in exact
/// arithmetic, 19 s more in a debug build) have a test of their own, run on
/// demand (`cargo test --test integration -- --ignored`).
#[test]
#[ignore = "needs the courses' files in ../shared/peer"]
fn imported_cases_draw_as_the_course_draws_them_exactly() {
    let dir = cases();
    let names = [
        "gray",
        "smallgap",
        "depth",
        "sRGB",
        "smoothcolor",
        "checkers",
        "perspective",
        "alpha",
        "fsaa2",
        "frustum",
        "manyclip",
        "cull",
        "matrix",
        "elements",
        "2d3d",
        "gammabox",
        "fsaa8",
        "points1",
        "points2",
    ];
    // matrix multiplies by a matrix of 4-decimal numbers before dividing by w:
    // its polygons' common denominators (near 7·10^9) pass 2^34, so they run on
    // the big-integer tier, and still draw as the course does exactly.
    let refused: Vec<&str> = names.into_iter().filter(|name| !imported_case_draws_as_the_course(&dir, name)).collect();
    assert_eq!(refused, Vec::<&str>::new());
}

/// As above, for the two cases that draw textured triangles.
#[test]
#[ignore = "needs the courses' files in ../shared/peer (and 19 s in a debug build)"]
fn imported_textured_cases_draw_as_the_course_draws_them_exactly() {
    let dir = cases();
    for name in ["textures", "decals"] {
        assert!(imported_case_draws_as_the_course(&dir, name), "{name}: refused");
    }
}

/// Whether case `name`, imported, is read (false when refused as beyond the
/// exact range); asserts that zsim draws it sample for sample as the course.
fn imported_case_draws_as_the_course(dir: &Path, name: &str) -> bool {
    // Textures do not change what is drawn where; a stand-in will do.
    let case = case_with_stand_in(dir, name, [255, 255, 255, 255]);
    let json = zsim::cs418::import::scene_json(&case).unwrap();
    let scene = match zsim::Scene::from_json(&json, Path::new("imported.json")) {
        Ok(scene) => scene,
        Err(error) => {
            assert!(
                error.message(zsim::Lang::En).contains("beyond the exact range"),
                "{name}: {}",
                error.message(zsim::Lang::En)
            );
            return false;
        }
    };
    let exact = render(&case, Arithmetic::Exact).unwrap();
    let mut simulation = zsim::Simulation::new(&scene);
    simulation.finish(&mut zsim::Unobserved);
    for (y, row) in simulation.buffers().frame_rows().iter().enumerate() {
        for (x, &value) in row.iter().enumerate() {
            assert_eq!(value, exact.owner(x as u32, y as u32), "{name}: sample ({x}, {y})");
        }
    }
    true
}

/// A point far larger than the image draws only the image's samples, at once.
#[test]
fn a_huge_point_fills_the_image_without_walking_beyond_it() {
    let (dir, file) = scene_file(
        "huge_point.txt",
        "png 10 10 huge.png\nposition 2 0 0\ncolor 3 1 1 1\npointsize 1 1000000000000\ndrawArraysPoints 0 1\n",
    );
    let out = zsim(&["cs418", "run", dir.join(&file).to_str().unwrap(), "-o", dir.join("huge").to_str().unwrap()]);
    assert_eq!(out.code, 0, "{}", out.stderr);
    let image = Image::from_png(&std::fs::read(dir.join("huge/huge.png")).unwrap()).unwrap();
    assert!(image.rgba.chunks(4).all(|p| p == [255, 255, 255, 255]));
}

/// A triangle reaching 500 image sizes beyond every side of a 20×20 image
/// with 2×2 samples: its rows above and below the image and its columns left
/// and right of it visit nothing (exact arithmetic jumps over them to the
/// same points; the course's floats step over them without drawing), so both
/// arithmetics fill the image at once instead of walking 20,000² samples.
#[test]
fn a_triangle_far_beyond_the_image_visits_only_the_image() {
    let text = "png 20 20 far.png\nfsaa 2\nposition 2 -999 -999 1999 -999 -999 1999\ncolor 3 1 1 1 1 1 1 1 1 1\ndrawArraysTriangles 0 3\n";
    let case = RastFile::parse(text, &|_| Err(zsim::cs418::TextureProblem::Missing)).unwrap();
    for arithmetic in [Arithmetic::DdaF64, Arithmetic::Exact] {
        let image = render(&case, arithmetic).unwrap().image;
        assert!(image.rgba.chunks(4).all(|p| p == [255, 255, 255, 255]), "{arithmetic:?}");
    }
}

/// Random CS 418 files (every command, sizes and counts right and wrong,
/// numbers large, small, negative, zero): reading and drawing them in both
/// arithmetics either works or says what is wrong with a line; never a panic.
mod never_a_panic {
    use proptest::prelude::*;
    use zsim::cs418::{Arithmetic, Image, RastFile, render};

    /// A number, mostly ordinary, now and then extreme.
    fn value() -> impl Strategy<Value = String> {
        prop_oneof![
            6 => (-3i32..=3).prop_map(|v| v.to_string()),
            12 => (-2000i32..=2000).prop_map(|v| format!("{}", f64::from(v) / 1000.0)),
            1 => Just("1e30".to_string()),
            1 => Just("-1e-30".to_string()),
            1 => Just("0.000000001".to_string()),
        ]
    }

    /// A number or now and then not one.
    fn number() -> impl Strategy<Value = String> {
        prop_oneof![20 => value(), 1 => Just("x".to_string())]
    }

    fn line() -> impl Strategy<Value = String> {
        let keyword = prop::sample::select(vec![
            "position",
            "color",
            "texcoord",
            "pointsize",
            "elements",
            "uniformMatrix",
            "drawArraysTriangles",
            "drawElementsTriangles",
            "drawArraysPoints",
            "depth",
            "sRGB",
            "hyp",
            "cull",
            "frustum",
            "decals",
            "fsaa",
            "texture",
        ]);
        (keyword, 0usize..5, prop::collection::vec(number(), 0..18)).prop_map(
            |(keyword, size, numbers)| match keyword {
                "position" | "color" | "texcoord" | "pointsize" => format!("{keyword} {size} {}", numbers.join(" ")),
                "texture" => "texture t.png".to_string(),
                "elements" | "drawArraysTriangles" | "drawElementsTriangles" | "drawArraysPoints" | "fsaa" => {
                    let small: Vec<String> =
                        numbers.iter().map(|n| n.trim_start_matches('-').replace('.', "")).collect();
                    format!("{keyword} {}", small.join(" "))
                }
                _ => format!("{keyword} {}", numbers[..numbers.len().min(size / 4)].join(" ")),
            },
        )
    }

    /// A file that mostly makes sense: switches, then vertices with colours
    /// and texture coordinates (now and then one short), then draws that
    /// mostly stay in range.
    fn drawing() -> impl Strategy<Value = String> {
        let switches = prop::collection::vec(
            prop::sample::select(vec!["depth", "sRGB", "hyp", "cull", "frustum", "decals", "fsaa 2", "fsaa 3"]),
            0..5,
        );
        let vertices = prop::collection::vec(prop::collection::vec(value(), 10), 1..8);
        let draws = prop::collection::vec(
            (
                prop::sample::select(vec!["drawArraysTriangles", "drawElementsTriangles", "drawArraysPoints"]),
                0usize..4,
                0usize..3,
            ),
            1..4,
        );
        (switches, vertices, any::<bool>(), any::<bool>(), draws).prop_map(
            |(switches, vertices, texture, short, draws)| {
                let column = |range: std::ops::Range<usize>| {
                    let mut all: Vec<String> = vertices.iter().flat_map(|v| v[range.clone()].to_vec()).collect();
                    if short {
                        all.truncate(all.len() - (range.end - range.start));
                    }
                    all.join(" ")
                };
                let mut text = switches.join("\n");
                text += &format!(
                    "\nposition 4 {}",
                    vertices.iter().map(|v| v[0..4].join(" ")).collect::<Vec<_>>().join(" ")
                );
                text += &format!("\ncolor 4 {}", column(4..8));
                text += &format!("\ntexcoord 2 {}", column(8..10));
                text += &format!(
                    "\npointsize 1 {}",
                    vertices.iter().map(|v| v[4].trim_start_matches('-').to_string()).collect::<Vec<_>>().join(" ")
                );
                text += &format!(
                    "\nelements {}",
                    (0..vertices.len() + 1).rev().map(|i| i.to_string()).collect::<Vec<_>>().join(" ")
                );
                if texture {
                    text += "\ntexture t.png";
                }
                for (command, first, count) in draws {
                    let count = if command == "drawArraysPoints" { count + 1 } else { 3 * count };
                    text += &format!(
                        "\n{command} {} {}",
                        if command == "drawElementsTriangles" { count } else { first },
                        if command == "drawElementsTriangles" { first } else { count }
                    );
                }
                text
            },
        )
    }

    /// Reads `text` (any texture is a 2×1 one) and draws it in both
    /// arithmetics: each step works or names a line.
    fn drawn_or_refused_with_its_line(text: &str) -> Result<(), TestCaseError> {
        let texture = Image { width: 2, height: 1, rgba: vec![255, 0, 0, 255, 0, 0, 255, 128] };
        match RastFile::parse(text, &|_| Ok(std::sync::Arc::new(texture.clone()))) {
            Err(error) => prop_assert!(error.line.is_some(), "{}", error.message(zsim::Lang::En)),
            Ok(case) => {
                for arithmetic in [Arithmetic::DdaF64, Arithmetic::Exact] {
                    if let Err(error) = render(&case, arithmetic) {
                        prop_assert!(error.line.is_some(), "{}", error.message(zsim::Lang::En));
                    }
                }
            }
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

        #[test]
        fn any_drawing_is_drawn_or_refused_with_its_line(width in 1u32..12, height in 1u32..12, body in drawing()) {
            let text = format!("png {width} {height} out.png\n{body}");
            drawn_or_refused_with_its_line(&text)?;
        }

        /// The import's promise on random drawings: zsim's own rasterizer,
        /// given the imported scene, leaves in every sample the primitive the
        /// course's pipeline shows there in exact arithmetic (where the
        /// scene is within zsim's exact range).
        #[test]
        fn any_imported_drawing_draws_as_the_course_does_exactly(
            width in 1u32..10,
            height in 1u32..10,
            body in drawing(),
        ) {
            let text = format!("png {width} {height} out.png\n{body}");
            let texture = Image { width: 2, height: 1, rgba: vec![255, 0, 0, 255, 0, 0, 255, 128] };
            // Drawings that are no case, or no scene once imported, are rejected: the runner counts them.
            let Ok(case) = RastFile::parse(&text, &|_| Ok(std::sync::Arc::new(texture.clone()))) else {
                return Err(TestCaseError::reject("not a case"));
            };
            let Ok(json) = zsim::cs418::import::scene_json(&case) else {
                return Err(TestCaseError::reject("not importable"));
            };
            let Ok(scene) = zsim::Scene::from_json(&json, std::path::Path::new("imported.json")) else {
                return Err(TestCaseError::reject("not a scene"));
            };
            let exact = render(&case, Arithmetic::Exact).unwrap();
            let mut simulation = zsim::Simulation::new(&scene);
            simulation.finish(&mut zsim::Unobserved);
            for (y, row) in simulation.buffers().frame_rows().iter().enumerate() {
                for (x, &value) in row.iter().enumerate() {
                    prop_assert_eq!(value, exact.owner(x as u32, y as u32), "sample ({}, {})\n{}", x, y, text);
                }
            }
        }

        #[test]
        fn any_file_is_drawn_or_refused_with_its_line(
            width in 1u32..12,
            height in 1u32..12,
            lines in prop::collection::vec(line(), 0..14),
        ) {
            let text = format!("png {width} {height} out.png\n{}", lines.join("\n"));
            drawn_or_refused_with_its_line(&text)?;
        }
    }
}

/// The course examples of zsim's own run from a fresh clone (no peer files):
/// the BUET case folder and the CS 418 case with its texture beside it.
#[test]
fn the_course_examples_in_the_repository_run_from_a_clone() {
    let out = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("course-examples");
    let _ = std::fs::remove_dir_all(&out);
    let buet = zsim(&["buet", "run", "examples/buet/case", "-o", out.join("buet").to_str().unwrap()]);
    assert_eq!((buet.code, buet.stderr.as_str()), (0, ""));
    assert!(
        buet.stdout.starts_with("examples/buet/case: 2 triangles on 32×32, 175 pixel centres tested, 134 written\n"),
        "{}",
        buet.stdout
    );
    let z_buffer = std::fs::read_to_string(out.join("buet/z_buffer.txt")).unwrap();
    assert_eq!(z_buffer.lines().count(), 32, "one line per row");
    for stage in ["stage1.txt", "stage2.txt", "stage3.txt", "out.bmp"] {
        assert!(out.join("buet").join(stage).is_file(), "{stage}");
    }
    let cs418 = zsim(&["cs418", "run", "examples/cs418/rast-checker.txt", "-o", out.join("cs418").to_str().unwrap()]);
    assert_eq!((cs418.code, cs418.stderr.as_str()), (0, ""));
    let image = Image::from_png(&std::fs::read(out.join("cs418/checker.png")).unwrap()).unwrap();
    assert_eq!((image.width, image.height), (32, 32));
    // Every pixel is one of the texture's two colours (nearest texel, sRGB in and out), opaque.
    let texture = Image::from_png(&std::fs::read("examples/cs418/checker-texture.png").unwrap()).unwrap();
    let colours: HashSet<[u8; 4]> = texture.rgba.chunks(4).map(|c| [c[0], c[1], c[2], c[3]]).collect();
    assert_eq!(colours.len(), 2);
    let shown: Vec<[u8; 4]> = image.rgba.chunks(4).map(|c| [c[0], c[1], c[2], c[3]]).collect();
    assert!(shown.iter().all(|c| colours.contains(c)), "only the texture's colours");
    for colour in &colours {
        assert!(shown.iter().filter(|c| *c == colour).count() > 300, "both colours fill much of the image");
    }
}
