//! `zsim accuracy`: every arithmetic mode on one generated set of scenes,
//! compared with the exact mode, and a sweep of depth bits on nearly
//! coplanar polygons (the Ukrainian Wikipedia's precision discussion, measured).
//!
//! Times are measured here, in one run: the modes take turns in each of
//! five rounds (`ROUNDS`) and each keeps its least, so that a busy machine slows
//! them alike; the sweep's depths, the least of three runs each. Compare
//! them as ratios.

use std::fmt::Write as _;
use std::path::Path;
use std::time::Duration;

use rayon::prelude::*;

use crate::effects::arith::{self, Arith};
use crate::error::Error;
use crate::scene::Scene;
use crate::scene::random::SplitMix64;
use crate::simulate::buffer::Buffers;
use crate::simulate::setup::Stats;

/// What `zsim accuracy` is asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AccuracyRequest {
    /// Seed of the generated scenes.
    pub seed: u64,
    /// Raster width.
    pub width: u32,
    /// Raster height.
    pub height: u32,
    /// Random scenes per triangle size.
    pub scenes: u32,
}

/// One row of the modes table.
#[derive(Debug, Clone, PartialEq)]
pub struct ModeRow {
    /// The mode.
    pub mode: Arith,
    /// Least time of three runs over the whole set.
    pub time: Duration,
    /// Covered pixel centres the mode tested.
    pub pixels: u64,
    /// Framebuffer cells that differ from exact.
    pub frame_mismatches: u64,
    /// z-buffer cells that differ from exact.
    pub depth_mismatches: u64,
    /// Largest |level − exact level| over the cells where the mode shows the
    /// same framebuffer value as exact (coverage differences are counted in
    /// `frame_mismatches`), in units of the last place (one level).
    pub worst_depth_error: u64,
}

impl ModeRow {
    /// Nanoseconds a pixel: this mode's time over the pixels `exact` tested.
    pub fn ns_per_pixel(&self, exact: &ModeRow) -> f64 {
        self.time.as_nanos() as f64 / exact.pixels.max(1) as f64
    }
}

/// `accuracy --format json`: both tables, the modes' times per pixel of
/// exact's (the first row). The fields in the order of their names, as the
/// output has always been written.
#[derive(Debug, serde::Serialize)]
pub struct AccuracyJson {
    depth_bits: Vec<BitsJson>,
    modes: Vec<ModeJson>,
}

/// A row of [`AccuracyJson`]'s modes.
#[derive(Debug, serde::Serialize)]
struct ModeJson {
    depth_mismatches: u64,
    frame_mismatches: u64,
    mode: String,
    ns_per_pixel: f64,
    pixels: u64,
    worst_depth_error: u64,
}

/// A row of [`AccuracyJson`]'s depth bits.
#[derive(Debug, serde::Serialize)]
struct BitsJson {
    bits: u32,
    memory_bytes: u64,
    ms: f64,
    z_fighting_cells: u64,
}

impl AccuracyJson {
    /// The tables `modes` (exact first) and `bits`.
    pub fn of(modes: &[ModeRow], bits: &[BitsRow]) -> AccuracyJson {
        let exact = modes.first();
        AccuracyJson {
            depth_bits: bits
                .iter()
                .map(|b| BitsJson {
                    bits: b.bits,
                    memory_bytes: b.memory,
                    ms: b.time.as_secs_f64() * 1000.0,
                    z_fighting_cells: b.z_fighting,
                })
                .collect(),
            modes: modes
                .iter()
                .map(|r| ModeJson {
                    depth_mismatches: r.depth_mismatches,
                    frame_mismatches: r.frame_mismatches,
                    mode: r.mode.to_string(),
                    ns_per_pixel: exact.map_or(0.0, |exact| r.ns_per_pixel(exact)),
                    pixels: r.pixels,
                    worst_depth_error: r.worst_depth_error,
                })
                .collect(),
        }
    }
}

/// One row of the depth-bits sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct BitsRow {
    /// z-buffer bits.
    pub bits: u32,
    /// Cells where the visible polygon is not the nearer one by exact depth.
    pub z_fighting: u64,
    /// z-buffer memory in bytes.
    pub memory: u64,
    /// Least time of three runs.
    pub time: Duration,
}

/// A scene of random triangles with vertices on a 1/256 grid and depths on a
/// 1/256 grid within a 24-bit z-buffer: values floating point cannot hold
/// exactly, as real scenes have.
fn random_scene(rng: &mut SplitMix64, settings: &AccuracyRequest, size: u32, count: usize) -> String {
    let (w, h) = (i64::from(settings.width) * 256, i64::from(settings.height) * 256);
    let extent = i64::from(size) * 256;
    let mut out = format!(
        "{{\"width\": {}, \"height\": {}, \"frame_bits\": 8, \"depth_bits\": 24, \"polygons\": [",
        settings.width, settings.height
    );
    for i in 0..count {
        let (x0, y0) = (rng.range(0, (w - extent).max(0)), rng.range(0, (h - extent).max(0)));
        let mut vertices = Vec::new();
        for _ in 0..3 {
            let (x, y) = (x0 + rng.range(0, extent), y0 + rng.range(0, extent));
            let z = rng.range(0, (1 << 24) * 256 - 1);
            vertices.push(format!("[\"{x}/256\", \"{y}/256\", \"{z}/256\"]"));
        }
        let comma = if i + 1 < count { "," } else { "" };
        let _ = write!(out, "{{\"value\": {}, \"vertices\": [{}]}}{comma}", rng.range(1, 255), vertices.join(", "));
    }
    out.push_str("]}");
    out
}

/// The hard cases: a long sliver 1/256 thin, a plane nearly edge-on, vertices
/// on pixel centres, coplanar overlapping polygons and depths of exactly k + 1/2.
fn hard_scenes(settings: &AccuracyRequest) -> Vec<String> {
    let (w, h) = (settings.width, settings.height);
    vec![
        format!(
            r#"{{"width": {w}, "height": {h}, "frame_bits": 8, "depth_bits": 16, "polygons": [{{"value": 1, "vertices": [[0, "1/3", 100], [{w}, "{}/256", 200], [{w}, "{}/256", 300]]}}]}}"#,
            u64::from(h) * 128,
            u64::from(h) * 128 + 1
        ),
        format!(
            r#"{{"width": {w}, "height": {h}, "frame_bits": 8, "depth_bits": 16, "polygons": [{{"value": 2, "vertices": [[0, 0, 1000], [{w}, 0, 1000], [{w}, {h}, "2000001/2000"]]}}, {{"value": 3, "vertices": [[0, 0, 60000], [{w}, 1, 0], [0, {h}, 30000]]}}]}}"#
        ),
        format!(
            r#"{{"width": {w}, "height": {h}, "frame_bits": 8, "depth_bits": 8, "polygons": [{{"value": 4, "vertices": [[0.5, 0.5, 10.5], ["{}.5", 0.5, 100.5], [0.5, "{}.5", 200.5]]}}]}}"#,
            w - 1,
            h - 1
        ),
        format!(
            r#"{{"width": {w}, "height": {h}, "frame_bits": 8, "depth_bits": 12, "polygons": [{{"value": 5, "vertices": [[0, 0, "2049/2"], [{w}, 0, "2049/2"], [0, {h}, "2049/2"]]}}, {{"value": 6, "vertices": [[{w}, {h}, "2049/2"], [0, {h}, "2049/2"], [{w}, 0, "2049/2"]]}}]}}"#
        ),
    ]
}

/// The accuracy set: random scenes of several triangle sizes, then the hard cases.
pub fn scenes(settings: &AccuracyRequest) -> Result<Vec<Scene>, Error> {
    let mut rng = SplitMix64::new(settings.seed);
    let mut texts = Vec::new();
    let area = u64::from(settings.width) * u64::from(settings.height);
    for size in [4u32, 16, 64, 256].into_iter().filter(|s| *s <= settings.width.min(settings.height)) {
        // About four times the raster's area in covered pixels per scene.
        let count = ((area * 8) / (u64::from(size) * u64::from(size))).clamp(4, 20_000) as usize;
        for _ in 0..settings.scenes {
            texts.push(random_scene(&mut rng, settings, size, count));
        }
    }
    texts.extend(hard_scenes(settings));
    texts.iter().map(|t| Scene::from_json(t, Path::new("(accuracy set)"))).collect()
}

/// A clock the caller lends: the time since a moment of its choosing. The
/// library reads no clock of its own (WebAssembly has none to read).
pub type Clock<'a> = &'a dyn Fn() -> Duration;

/// The least time of three runs of `f`, after one untimed run.
fn timed<T>(clock: Clock<'_>, mut f: impl FnMut() -> Result<T, Error>) -> Result<(T, Duration), Error> {
    let mut best = Duration::MAX;
    let mut result = None;
    // One untimed run first, so that the sweep's first depth pays no more for cold caches.
    f()?;
    for _ in 0..3 {
        let start = clock();
        let value = f()?;
        best = best.min(clock().saturating_sub(start));
        result = Some(value);
    }
    Ok((result.expect("three runs were made"), best))
}

fn compare(ours: &Buffers, exact: &Buffers) -> (u64, u64, u64) {
    let (mut frame, mut depth, mut worst) = (0, 0, 0);
    for y in 0..exact.height() {
        for x in 0..exact.width() {
            frame += u64::from(ours.frame(x, y) != exact.frame(x, y));
            let (a, b) = (ours.depth(x, y).level().unwrap_or(0), exact.depth(x, y).level().unwrap_or(0));
            depth += u64::from(a != b);
            if ours.frame(x, y) == exact.frame(x, y) {
                worst = worst.max(u64::from(a.abs_diff(b)));
            }
        }
    }
    (frame, depth, worst)
}

/// Rounds in which every mode draws the set once, in turn; a mode's time is
/// its least (a busy machine only ever adds time, and whatever slows one
/// round slows every mode in it alike).
const ROUNDS: usize = 5;

/// Runs every mode over the set, timed by `clock`.
pub fn modes(scenes: &[Scene], clock: Clock<'_>) -> Result<Vec<ModeRow>, Error> {
    // The references, the conversions and the comparisons on every core; the
    // timed runs one after the other, on one.
    let exact: Vec<Buffers> =
        scenes.par_iter().map(|s| arith::run(s, Arith::Exact).map(|r| r.0)).collect::<Result<_, _>>()?;
    // Each mode's input is converted first (vertices snapped, or turned into floats with
    // their planes), as the exact mode's is when the scene is read; only the raster is timed.
    let inputs = Arith::ALL
        .iter()
        .map(|&mode| scenes.par_iter().map(|s| arith::Prepared::new(s, mode)).collect::<Result<Vec<_>, _>>())
        .collect::<Result<Vec<_>, _>>()?;
    let raster = |inputs: &[arith::Prepared<'_>]| inputs.iter().map(arith::Prepared::raster).collect::<Vec<_>>();
    // One untimed round first, so that no mode pays for cold caches.
    let mut results: Vec<Vec<(Buffers, Stats)>> = inputs.iter().map(|inputs| raster(inputs)).collect();
    let mut times = vec![Duration::MAX; inputs.len()];
    for _ in 0..ROUNDS {
        for (k, inputs) in inputs.iter().enumerate() {
            let start = clock();
            results[k] = raster(inputs);
            times[k] = times[k].min(clock().saturating_sub(start));
        }
    }
    let mut rows = Vec::new();
    for ((&mode, results), time) in Arith::ALL.iter().zip(&results).zip(times) {
        let mut row = ModeRow { mode, time, pixels: 0, frame_mismatches: 0, depth_mismatches: 0, worst_depth_error: 0 };
        let compared: Vec<_> = results.par_iter().zip(&exact).map(|((b, _), r)| compare(b, r)).collect();
        for ((_, stats), (frame, depth, worst)) in results.iter().zip(compared) {
            row.pixels += stats.tested;
            row.frame_mismatches += frame;
            row.depth_mismatches += depth;
            row.worst_depth_error = row.worst_depth_error.max(worst);
        }
        rows.push(row);
    }
    Ok(rows)
}

/// Two nearly coplanar planes crossing along x = y. Depths are world depths
/// in 0 … 1 times 2^bits (the z-buffer's levels): plane A is `1/2 + x/2^20`,
/// plane B `1/2 + y/2^20`, so the planes part by one level per 2^(20 − bits)
/// pixels. Powers of two keep every value within the exact range.
fn coplanar_scene(width: u32, height: u32, bits: u32) -> String {
    let level = |world_numerator: u64, world_shift: u32| -> String {
        // world_numerator / 2^world_shift × 2^bits, as a reduced fraction.
        if bits >= world_shift {
            format!("\"{}\"", u128::from(world_numerator) << (bits - world_shift))
        } else {
            format!("\"{world_numerator}/{}\"", 1u128 << (world_shift - bits))
        }
    };
    // 1/2 + t/2^20 = (2^19 + t)/2^20.
    let z = |t: u32| level((1 << 19) + u64::from(t), 20);
    let (w, h) = (width, height);
    format!(
        r#"{{"width": {w}, "height": {h}, "depth_bits": {bits}, "polygons": [
            {{"name": "A", "value": 1, "vertices": [[0, 0, {}], [{w}, 0, {}], [{w}, {h}, {}], [0, {h}, {}]]}},
            {{"name": "B", "value": 2, "vertices": [[0, 0, {}], [{w}, 0, {}], [{w}, {h}, {}], [0, {h}, {}]]}}]}}"#,
        z(0),
        z(w),
        z(w),
        z(0),
        z(0),
        z(0),
        z(h),
        z(h)
    )
}

/// The depth-bits sweep: 4, 8, 16, 24 and 32 bits.
pub fn bits_sweep(settings: &AccuracyRequest, clock: Clock<'_>) -> Result<Vec<BitsRow>, Error> {
    let mut rows = Vec::new();
    for bits in [4u32, 8, 16, 24, 32] {
        let scene = Scene::from_json(&coplanar_scene(settings.width, settings.height, bits), Path::new("(coplanar)"))?;
        let ((buffers, _), time) = timed(clock, || arith::run(&scene, Arith::Exact))?;
        // The nearer polygon by world depth: A where x ≥ y at the centre (ties keep A, drawn first), B elsewhere.
        let mut z_fighting = 0;
        for y in 0..settings.height {
            for x in 0..settings.width {
                let nearer = if x >= y { 1 } else { 2 };
                z_fighting += u64::from(buffers.frame(x, y) != nearer);
            }
        }
        let memory = (u64::from(settings.width) * u64::from(settings.height) * u64::from(bits)).div_ceil(8);
        rows.push(BitsRow { bits, z_fighting, memory, time });
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `accuracy --format json`'s shape, times per pixel taken over exact's pixels.
    #[test]
    fn the_json_has_its_shape() {
        let row = |mode, nanos, pixels| ModeRow {
            mode,
            time: Duration::from_nanos(nanos),
            pixels,
            frame_mismatches: 1,
            depth_mismatches: 2,
            worst_depth_error: 3,
        };
        let modes = [row(Arith::Exact, 400, 100), row(Arith::F32, 200, 90)];
        let bits = [BitsRow { bits: 8, z_fighting: 5, memory: 4096, time: Duration::from_micros(1500) }];
        let json = AccuracyJson::of(&modes, &bits);
        assert_eq!((json.modes[0].ns_per_pixel, json.modes[1].ns_per_pixel), (4.0, 2.0));
        crate::shape_snapshot("accuracy_json", &json);
    }
}
