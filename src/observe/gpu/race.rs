//! zsim beside the machine's OpenGL (Mesa's llvmpipe where no GPU is
//! present), on the same triangles: each side drawn in turn, pair after pair
//! in one run, so that a busy machine slows both alike; medians and their
//! ratio. zsim's time is what `zsim run --format none` prints as rasterized
//! (clearing the buffers, then every polygon), except that the buffers are
//! made once and cleared in place each round; the GPU's is a clear, the draw
//! of a vertex buffer uploaded beforehand, and `glFinish`.

use std::time::{Duration, Instant};

use crate::error::{Error, Usage};
use crate::observe::gpu::{Gl, GpuError, Triangles, triangles};
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
        format!("{header}\n{times}\n")
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
pub fn race(
    lang: crate::words::Lang,
    scene: &Scene,
    pairs: usize,
    tile: Option<u32>,
    threads: usize,
) -> Result<Race, Error> {
    if scene.has_pixel_effects() || scene.effects.antialias.is_some() {
        return Err(Usage::CompareGpuPlainOnly.into());
    }
    let no_gpu = |error: GpuError| Error::from(Usage::NoGpu { reason: error.message(lang) });
    let Triangles { triangles, margin, .. } = triangles(scene);
    let polygons = (0..scene.polygons.len()).filter(|&i| crate::simulate::setup::fate(scene, i) == Fate::Drawn).count();
    let skipped = scene.polygons.len() - polygons;
    let gl = Gl::open().map_err(no_gpu)?;
    let size = (scene.width + 2 * margin, scene.height + 2 * margin);
    let drawing = gl.upload(size, &triangles, Some((scene.depth_test, scene.depth_max()))).map_err(no_gpu)?;
    // The buffers are made once, as the GPU's framebuffer is: each round
    // clears them and draws (a fresh 4096² pair of buffers was mostly the
    // kernel handing over zeroed pages, a cost llvmpipe does not pay per frame).
    let mut simulation = Simulation::new_on(scene, threads);
    let tile = tile.unwrap_or_else(|| simulation.default_tile(threads));
    let mut zsim = || {
        let start = Instant::now();
        simulation.restart();
        let threads = match tile {
            0 => simulation.draw_parallel_through(scene.polygons.len().saturating_sub(1), 0, 1, &|| {}),
            tile => simulation.finish_parallel(tile, threads, &|| {}),
        };
        (start.elapsed(), simulation.stats().tested, threads)
    };
    let gpu = || {
        let start = Instant::now();
        drawing.draw();
        start.elapsed()
    };
    // One round each before timing: caches, page faults, the JIT's first compile.
    let (_, pixels, threads) = zsim();
    gpu();
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
    };
    for _ in 0..pairs {
        race.zsim.push(zsim().0);
        race.gpu.push(gpu());
    }
    // Read back once so that an error the GPU recorded while drawing (glGetError) is reported.
    drawing.picture().map_err(no_gpu)?;
    Ok(race)
}

#[cfg(test)]
mod tests {
    use super::*;

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
        };
        assert_eq!((race.zsim_median(), race.gpu_median()), (ms(20), ms(20)));
        assert_eq!(race.ratio(), 1.0);
        assert_eq!(race.pair_ratios(), (0.5, 3.0));
        assert_eq!(median(&[]), Duration::ZERO);
    }
}
