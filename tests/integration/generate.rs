//! `zsim memory` (the book's figures) and `zsim random` (repeatable scenes).

use std::path::Path;

use zsim::Scene;

use crate::{snapshot, zsim};

#[test]
fn memory_gives_the_books_figures() {
    // 512×512, 24-bit framebuffer, 20-bit z-buffer, plus `extra` options.
    let book = |extra: &[&str]| {
        let mut args = vec!["memory", "--width", "512", "--height", "512", "--frame-bits", "24", "--depth-bits", "20"];
        args.extend_from_slice(extra);
        zsim(&args)
    };
    let run = book(&[]);
    assert_eq!(run.code, 0);
    assert!(run.stdout.ends_with("total: 1441792 bytes = 1.441 MB (1.375 MiB)\n"), "{}", run.stdout);
    snapshot!("memory_512_24_20", run.stdout);
    let run = book(&["--supersample", "2"]);
    assert!(run.stdout.ends_with("total: 5767168 bytes = 5.767 MB (5.500 MiB)\n"), "{}", run.stdout);
    // The first approach keeps the z-buffer at screen resolution: 4·786432 + 655360 bytes.
    let run = book(&["--supersample", "2", "--depth-at", "pixel"]);
    assert!(run.stdout.contains("total: 3801088 bytes"), "{}", run.stdout);
    let run = zsim(&["memory", "--frame-bits", "0"]);
    assert_eq!((run.code, run.stderr.as_str()), (2, "zsim: --frame-bits 0: use 1 to 64 bits\n"));
}

#[test]
fn random_scenes_repeat_for_a_seed_and_respect_the_size() {
    let args = ["random", "--count", "50", "--seed", "3", "--width", "64", "--height", "48", "--max-size", "10"];
    let first = zsim(&args);
    assert_eq!(first.code, 0, "{}", first.stderr);
    assert_eq!(first.stdout, zsim(&args).stdout, "same seed, same scene");
    let scene = Scene::from_json(&first.stdout, Path::new("random.json")).expect("a valid scene");
    assert_eq!((scene.width, scene.height, scene.polygons.len()), (64, 48, 50));
    for polygon in &scene.polygons {
        let xs: Vec<_> = polygon.vertices().iter().map(|v| v[0].word().expect("small")).collect();
        let ys: Vec<_> = polygon.vertices().iter().map(|v| v[1].word().expect("small")).collect();
        let extent = |v: &[zsim::Q]| *v.iter().max().unwrap() - *v.iter().min().unwrap();
        assert!(extent(&xs) <= 10.into() && extent(&ys) <= 10.into(), "{} is larger than 10 px", polygon.name);
    }
    let other =
        zsim(&["random", "--count", "50", "--seed", "4", "--width", "64", "--height", "48", "--max-size", "10"]);
    assert_ne!(first.stdout, other.stdout);
}

/// `memory` printed "0.000 MB" for buffers under a kilobyte: below a
/// megabyte the total is in kilobytes.
#[test]
fn memory_below_a_megabyte_is_in_kilobytes() {
    let run = zsim(&["memory", "--width", "1", "--height", "1"]);
    assert_eq!(run.stdout.lines().last(), Some("total: 2 bytes = 0.002 kB (0.002 KiB)"));
    let run = zsim(&["memory", "--width", "32", "--height", "32"]);
    assert_eq!(run.stdout.lines().last(), Some("total: 768 bytes = 0.768 kB (0.750 KiB)"));
}
