//! zsim beside the machine's OpenGL (Mesa's llvmpipe where no GPU is
//! present), on the same triangles: each side drawn in turn, pair after pair
//! in one run, so that a busy machine slows both alike; medians and their
//! ratio. zsim's time is what `zsim run --format none` prints as rasterized
//! (clearing the buffers, then every polygon, in buffers made beforehand):
//! here the buffers are made once and cleared each round, tile by tile as
//! each is drawn ([`Simulation::redraw`]) as llvmpipe clears its tiles; the GPU's is a
//! clear, the draw of a vertex buffer uploaded beforehand, and `glFinish`.

use std::time::{Duration, Instant};

use crate::error::Error;
use crate::observe::gpu::{Gl, GpuError, Margin, Triangles, triangles_within};
use crate::scene::Scene;
use crate::simulate::events::Fate;
use crate::simulate::simulation::Simulation;

/// The times of a race, pair by pair.
#[derive(Debug, Clone, PartialEq)]
pub struct Race {
    /// The GPU implementation, as it names itself.
    pub renderer: String,
    /// Triangles the GPU drew (polygons as fans).
    pub triangles: usize,
    /// The polygons drawn as those fans.
    pub polygons: usize,
    /// The scene's polygons that draw nothing (degenerate, edge-on, culled,
    /// outside the view), for which no triangle is sent.
    pub skipped: usize,
    /// Pixel centres zsim tested in one drawing.
    pub pixels: u64,
    /// Threads zsim drew on.
    pub threads: usize,
    /// The side of the tiles zsim drew in; 0 polygon by polygon.
    pub tile: u32,
    /// zsim's time in each pair.
    pub zsim: Vec<Duration>,
    /// The GPU's time in each pair.
    pub gpu: Vec<Duration>,
    /// zsim's whole run in each pair: buffers made fresh (the kernel
    /// handing over their pages), then every polygon, as `zsim run`'s
    /// buffers made and rasterized together.
    pub fresh: Vec<Duration>,
    /// A copy of as many bytes as the buffers take, in each pair: what the
    /// machine's memory allows, measured in the same run.
    pub copy: Vec<Duration>,
    /// The bytes both buffers take ([`crate::simulate::buffer::Buffers::memory_bytes`]).
    pub bytes: u64,
    /// The raster's pixels.
    pub cells: u64,
}

impl Race {
    /// The report, two lines in `lang`: the scene (shown as `scene`), the
    /// counts, the threads (llvmpipe's as `lp`, LP_NUM_THREADS) and the
    /// pairs; then both medians, their ratio and the range of the pairs'.
    pub fn report(&self, lang: crate::words::Lang, scene: &str, lp: &str) -> String {
        use crate::words::{localize_decimal, printable};
        let ms = |d: Duration| localize_decimal(lang, format!("{:.2}", d.as_secs_f64() * 1e3));
        let ratio = |r: f64| localize_decimal(lang, format!("{r:.2}"));
        let (low, high) = self.pair_ratios();
        let header = words!(
            lang,
            "speed-header",
            scene = scene,
            triangles = self.triangles,
            polygons = self.polygons,
            skipped = self.skipped,
            pixels = self.pixels,
            threads = self.threads,
            tile = self.tile,
            renderer = printable(&self.renderer).into_owned(),
            lp = printable(lp).into_owned(),
            pairs = self.zsim.len()
        );
        let times = words!(
            lang,
            "speed-result",
            zsim = ms(self.zsim_median()),
            gpu = ms(self.gpu_median()),
            ratio = ratio(self.ratio()),
            low = ratio(low),
            high = ratio(high)
        );
        let gpu = self.gpu_median().as_secs_f64().max(1e-12);
        let fresh = median(&self.fresh);
        let whole = words!(lang, "speed-fresh", fresh = ms(fresh), ratio = ratio(fresh.as_secs_f64() / gpu));
        let (rate, bandwidth, limit) = self.rates();
        let millions = |v: f64| localize_decimal(lang, format!("{:.1}", v / 1e6));
        let memory = words!(
            lang,
            "speed-memory",
            rate = millions(rate),
            megabytes = localize_decimal(lang, format!("{:.1}", self.bytes as f64 / 1e6)),
            copy = localize_decimal(lang, significant(median(&self.copy).as_secs_f64() * 1e3)),
            bandwidth = localize_decimal(lang, format!("{:.2}", bandwidth / 1e9)),
            bytes = localize_decimal(lang, format!("{:.2}", self.bytes as f64 / self.cells.max(1) as f64)),
            limit = millions(limit)
        );
        format!("{header}\n{times}\n{whole}\n{memory}\n")
    }

    /// Pixel centres zsim tested a second (at its median), the bytes a second
    /// the copy moved (each read once and written once), and the pixels a
    /// second that rate allows when each pixel's cells are read and written
    /// once.
    pub fn rates(&self) -> (f64, f64, f64) {
        let rate = self.pixels as f64 / self.zsim_median().as_secs_f64().max(1e-12);
        let bandwidth = self.bytes as f64 / median(&self.copy).as_secs_f64().max(1e-12);
        let per_pixel = self.bytes as f64 / self.cells.max(1) as f64;
        (rate, bandwidth, bandwidth / per_pixel.max(1e-12))
    }

    /// zsim's median time.
    pub fn zsim_median(&self) -> Duration {
        median(&self.zsim)
    }

    /// The GPU's median time.
    pub fn gpu_median(&self) -> Duration {
        median(&self.gpu)
    }

    /// zsim's median over the GPU's: below 1, zsim is faster.
    pub fn ratio(&self) -> f64 {
        self.zsim_median().as_secs_f64() / self.gpu_median().as_secs_f64().max(1e-12)
    }

    /// The lowest and highest ratio of one pair.
    pub fn pair_ratios(&self) -> (f64, f64) {
        let ratios = self.zsim.iter().zip(&self.gpu).map(|(z, g)| z.as_secs_f64() / g.as_secs_f64().max(1e-12));
        ratios.fold((f64::INFINITY, 0.0f64), |(low, high), r| (low.min(r), high.max(r)))
    }
}

/// The median of some durations (the lower middle one of an even count).
/// `value` with at least two decimals and three significant digits, so that
/// a copy that takes microseconds is not shown as 0.00 ms.
fn significant(value: f64) -> String {
    let decimals = if value > 0.0 { (2 - value.log10().floor() as i32).clamp(2, 9) } else { 2 };
    format!("{value:.*}", decimals as usize)
}

fn median(times: &[Duration]) -> Duration {
    let mut sorted = times.to_vec();
    sorted.sort_unstable();
    sorted.get(sorted.len().saturating_sub(1) / 2).copied().unwrap_or_default()
}

/// Races zsim against the machine's OpenGL on `scene`, `pairs` times after
/// one untimed round each: zsim on `threads` threads in tiles of `tile`
/// (`None`: as [`Simulation::default_tile`] chooses; 0 polygon by polygon on
/// this thread). The GPU draws with the scene's depth test into a
/// framebuffer of the raster's size (plus the margin that keeps vertices
/// unclipped, see [`Triangles`]).
pub fn race(scene: &Scene, pairs: usize, tile: Option<u32>, threads: usize) -> Result<Race, Error> {
    if scene.has_pixel_effects() || scene.effects.antialias.is_some() {
        return Err(GpuError::PlainOnly.into());
    }
    let no_gpu = Error::from;
    let Triangles { triangles, margin, .. } = triangles_within(scene, Margin::AsNeeded);
    let polygons = (0..scene.polygons.len()).filter(|&i| crate::simulate::setup::fate(scene, i) == Fate::Drawn).count();
    let skipped = scene.polygons.len() - polygons;
    let gl = Gl::open().map_err(no_gpu)?;
    let size = (scene.width + 2 * margin, scene.height + 2 * margin);
    let drawing = gl.upload(size, &triangles, Some((scene.depth_test, scene.depth_max()))).map_err(no_gpu)?;
    // The buffers are made once, as the GPU's framebuffer is: each round
    // clears and draws them (a fresh 4096² pair of buffers was mostly the
    // kernel handing over zeroed pages, a cost llvmpipe does not pay per frame).
    let mut simulation = Simulation::new_on(scene, threads);
    let tile = tile.unwrap_or_else(|| simulation.default_tile(threads));
    let bytes = simulation.buffers().memory_bytes();
    // Every polygon, polygon by polygon on this thread (tile 0) or in tiles; the threads drawn on.
    let draw = |simulation: &mut Simulation<'_>| match tile {
        0 => simulation.draw_parallel_through(scene.polygons.len().saturating_sub(1), 0, 1, &|| {}),
        tile => simulation.finish_parallel(tile, threads, &|| {}),
    };
    // Each round clears and draws: in tiles, each tile is cleared as it is
    // drawn, as llvmpipe clears its tiles.
    let mut zsim = || {
        let start = Instant::now();
        let threads = simulation.redraw(tile, threads, &|| {});
        (start.elapsed(), simulation.stats().tested, threads)
    };
    let gpu = || {
        let start = Instant::now();
        drawing.draw();
        start.elapsed()
    };
    // As `zsim run` draws: fresh buffers, then every polygon.
    let fresh = || {
        let start = Instant::now();
        let mut simulation = Simulation::new_on(scene, threads);
        draw(&mut simulation);
        std::hint::black_box(simulation.stats().tested);
        start.elapsed()
    };
    // The memory's own speed: as many bytes as the buffers take, copied (both touched beforehand).
    let (source, mut target) = (vec![1u8; bytes as usize], vec![0u8; bytes as usize]);
    let mut copy = || {
        let start = Instant::now();
        target.copy_from_slice(std::hint::black_box(&source));
        std::hint::black_box(&target);
        start.elapsed()
    };
    // One round each before timing: caches, page faults, the JIT's first compile.
    let (_, pixels, threads) = zsim();
    gpu();
    fresh();
    copy();
    let mut race = Race {
        renderer: gl.renderer().to_string(),
        triangles: triangles.len(),
        polygons,
        skipped,
        pixels,
        threads,
        tile,
        zsim: Vec::with_capacity(pairs),
        gpu: Vec::with_capacity(pairs),
        fresh: Vec::with_capacity(pairs),
        copy: Vec::with_capacity(pairs),
        bytes,
        cells: u64::from(scene.width) * u64::from(scene.height),
    };
    // In turn, round after round: so that a busy moment of the machine falls on all of them.
    for _ in 0..pairs {
        race.zsim.push(zsim().0);
        race.gpu.push(gpu());
        race.fresh.push(fresh());
        race.copy.push(copy());
    }
    // Read back once so that an error the GPU recorded while drawing (glGetError) is reported.
    drawing.picture().map_err(no_gpu)?;
    Ok(race)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_time_keeps_three_significant_digits() {
        let shown = [0.004_7, 0.047, 0.47, 4.7, 47.0, 0.0].map(significant);
        assert_eq!(shown, ["0.00470", "0.0470", "0.470", "4.70", "47.00", "0.00"]);
    }

    #[test]
    fn medians_and_ratios_are_of_the_pairs() {
        let ms = Duration::from_millis;
        let race = Race {
            renderer: "test".into(),
            triangles: 1,
            polygons: 1,
            skipped: 0,
            pixels: 1,
            threads: 1,
            tile: 0,
            zsim: vec![ms(30), ms(10), ms(20), ms(40)],
            gpu: vec![ms(10), ms(20), ms(20), ms(80)],
            fresh: vec![ms(50)],
            copy: vec![ms(2)],
            bytes: 5_000_000,
            cells: 1_000_000,
        };
        assert_eq!((race.zsim_median(), race.gpu_median()), (ms(20), ms(20)));
        assert_eq!(race.ratio(), 1.0);
        assert_eq!(race.pair_ratios(), (0.5, 3.0));
        assert_eq!(median(&[]), Duration::ZERO);
        // 1 pixel in 20 ms; 5 MB copied in 2 ms; 5 bytes a pixel.
        assert_eq!(race.rates(), (50.0, 2.5e9, 5e8));
    }
}
