//! A course at scale: `zsim exercise --roster` (scenes, SVG worksheets, keys,
//! the manifest) and `zsim grade --variants` (every student's two files
//! against their own key) on rosters of 250 and 1,000 students, each run a
//! whole process of the release binary, the two sizes alternating, five
//! rounds; the medians of the wall time and of the peak memory (GNU time's
//! `%M`), and the ratio of the two sizes' peaks, which a memory flat in the
//! class's size keeps near 1. The goals: 1,000 students made within 60 s and
//! graded within 10 s on a 2-core machine. Run with `cargo bench --bench course`.

use std::path::{Path, PathBuf};
use std::process::Command;

const ROUNDS: usize = 5;
const SIZES: [usize; 2] = [250, 1000];

/// One run of `zsim ARGS` in `dir` under GNU time: (wall seconds, peak kB).
fn timed(dir: &Path, args: &[&str]) -> (f64, u64) {
    let output = Command::new("/usr/bin/time")
        .args(["-f", "%e %M", env!("CARGO_BIN_EXE_zsim")])
        .args(args)
        .current_dir(dir)
        .env("LANG", "C.UTF-8")
        .output()
        .expect("GNU time (/usr/bin/time, Debian's time package)");
    let stderr = String::from_utf8_lossy(&output.stderr);
    let last = stderr.lines().last().unwrap_or_default();
    let mut parts = last.split_whitespace();
    let seconds = parts.next().and_then(|s| s.parse().ok()).unwrap_or_else(|| panic!("no time in {stderr}"));
    let peak = parts.next().and_then(|s| s.parse().ok()).unwrap_or_else(|| panic!("no peak in {stderr}"));
    (seconds, peak)
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(|a, b| a.partial_cmp(b).unwrap());
    values[values.len() / 2]
}

/// A folder with a plain roster of `students` and, once made, a class
/// folder of every student's key handed in as their answer.
fn class(root: &Path, students: usize) -> PathBuf {
    let dir = root.join(format!("class-{students}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let roster: String = (1..=students).map(|k| format!("student{k:05}@uni.edu\n")).collect();
    std::fs::write(dir.join("roster.txt"), roster).unwrap();
    dir
}

fn main() {
    let root = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("bench-course");
    let mut made: Vec<(Vec<f64>, Vec<f64>)> = vec![(Vec::new(), Vec::new()); SIZES.len()];
    let mut graded: Vec<(Vec<f64>, Vec<f64>)> = vec![(Vec::new(), Vec::new()); SIZES.len()];
    for _ in 0..ROUNDS {
        for (k, students) in SIZES.into_iter().enumerate() {
            let dir = class(&root, students);
            let (seconds, peak) = timed(&dir, &["exercise", "--roster", "roster.txt", "-o", "out"]);
            assert!(dir.join("out/variants.json").is_file(), "the class was made");
            made[k].0.push(seconds);
            made[k].1.push(peak as f64);
            std::fs::create_dir_all(dir.join("answers")).unwrap();
            for entry in std::fs::read_dir(dir.join("out/keys")).unwrap() {
                let path = entry.unwrap().path();
                std::fs::copy(&path, dir.join("answers").join(path.file_name().unwrap())).unwrap();
            }
            let (seconds, peak) =
                timed(&dir, &["grade", "--variants", "out/variants.json", "answers", "--format", "csv"]);
            graded[k].0.push(seconds);
            graded[k].1.push(peak as f64);
        }
    }
    for (what, runs) in [("exercise --roster", &mut made), ("grade --variants", &mut graded)] {
        for (k, students) in SIZES.into_iter().enumerate() {
            let (seconds, peak) = &mut runs[k];
            println!(
                "{what}, {students} students: wall {:.2} s median (min {:.2}, max {:.2}), peak {:.1} MB median",
                median(seconds),
                seconds[0],
                seconds[seconds.len() - 1],
                median(peak) / 1000.0
            );
        }
        let ratio = median(&mut runs[1].1) / median(&mut runs[0].1);
        println!("{what}: peak at {} students / peak at {}: {ratio:.2}", SIZES[1], SIZES[0]);
    }
}
