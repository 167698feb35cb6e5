//! `zsim run`: the buffers after each polygon, as the book prints them.

use std::io::Write;
use std::path::PathBuf;

use std::io::IsTerminal;
use std::time::{Duration, Instant};

use clap::{Args, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use zsim::Scene;
use zsim::Simulation;
use zsim::Unobserved;
use zsim::arith::Arith;
use zsim::report::{self, MatrixStyle, RunFigures};

use super::{Failure, Finish, emit, json_line};

/// Arguments of `zsim run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    /// The scene file (JSON), or - for standard input.
    scene: PathBuf,
    /// Print only the state after the last polygon.
    #[arg(long = "final")]
    final_only: bool,
    /// Print only the state after this polygon (number from 1, or name); the polygons after it are not drawn.
    #[arg(long, value_name = "N|NAME")]
    after: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Label rows with y and columns with x (the default on a terminal; piped or redirected, the book's bare matrices).
    #[arg(long, overrides_with = "no_axes")]
    axes: bool,
    /// Print the bare matrices, without labels, also on a terminal.
    #[arg(long)]
    no_axes: bool,
    /// Loop order: polygons then their pixels (the z-buffer), or every pixel then every polygon (the Chinese course notes).
    #[arg(long, value_enum, default_value_t = Order::Polygons)]
    order: Order,
    /// The point-in-polygon test of --order pixels.
    #[arg(long, value_enum)]
    inside: Option<InsideTest>,
    /// A z-buffer only as large as one segment: strips:N, tiles:N or rows:1 (the Russian lecture notes).
    #[arg(long, value_name = "strips:N|tiles:N|rows:1", value_parser = |text: &str| zsim::variants::Segments::parse(text).map_err(|e| e.message(super::language_of_the_run())))]
    segments: Option<zsim::variants::Segments>,
    /// With --format none, --final or --after: draw tile by tile, N×N pixels (default 256 when more than one thread draws or the buffers outgrow 8 MiB; 1 to 7 draw as 8, whose bins cost less than the buffers).
    #[arg(long, value_name = "N")]
    tile: Option<u32>,
    /// With --format none, --final or --after: how many threads draw the tiles (default: all cores; 1 without --tile draws polygon by polygon while the buffers fit 8 MiB). The result is the same for every count.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Draw the scene with the machine's GPU through this API (gl: OpenGL, e.g. Mesa's llvmpipe; vulkan, with the `vulkan` feature) and list every cell where it shows another polygon than zsim under the scene's rules or the API's preset, and why.
    #[cfg(feature = "gpu")]
    #[arg(long, value_enum, value_name = "API")]
    compare_gpu: Option<GpuApi>,
    /// List the cells where the scene's rules and this preset's (rogers, buet, gl, vulkan or tinyrenderer) draw differently, and why.
    #[arg(long, value_name = "PRESET", value_parser = |text: &str| zsim::Preset::parse(text).map_err(|e| e.message(super::language_of_the_run())))]
    compare_rules: Option<zsim::Preset>,
    /// Arithmetic: exact, f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K.
    #[arg(long, default_value = "exact", value_parser = |text: &str| Arith::parse(text).map_err(|e| e.message(super::language_of_the_run())))]
    arith: Arith,
}

/// The smallest tile drawn: below it the tiles' bins would outweigh the buffers.
const MIN_TILE: u32 = 8;

/// The loop order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Order {
    /// For every polygon, for every pixel it covers: the z-buffer.
    Polygons,
    /// For every pixel, for every polygon, with one depth variable (the Chinese course notes).
    Pixels,
}

/// The point-in-polygon test.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum InsideTest {
    /// Ray casting with the left-open/right-closed vertex rule; on the boundary counts.
    Ray,
    /// The arc-length method with its quadrant table; on the boundary counts.
    Arc,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Format {
    /// The book's matrices with polygon headings.
    Text,
    /// One JSON object: width, height, effects, steps.
    Json,
    /// A one-line summary only.
    None,
}

pub fn run(lang: zsim::Lang, args: &RunArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    if args.inside.is_some() && args.order != Order::Pixels {
        return Err(super::flags::Flag::InsideNeedsPixelOrder.into());
    }
    if args.tile == Some(0) {
        return Err(super::flags::Flag::TileZero.into());
    }
    let final_only = args.final_only || args.after.is_some();
    if (args.tile.is_some() || args.threads.is_some()) && args.format != Format::None && !final_only {
        return Err(super::flags::Flag::TilesNeedFormatNone.into());
    }
    let reading = Instant::now();
    let mut scene = Scene::load(&args.scene)?;
    let read_time = reading.elapsed();
    // `--after N`: the scene up to polygon N, shown as `--final` shows the last.
    if let Some(spec) = &args.after {
        let last = scene.find_polygon(spec)?;
        scene.polygons.truncate(last + 1);
    }
    let path = zsim::shown_path(&args.scene);
    #[cfg(feature = "gpu")]
    if let Some(api) = args.compare_gpu {
        let api = match api {
            GpuApi::Gl => zsim::gpu::GpuApi::Gl,
            GpuApi::Vulkan => zsim::gpu::GpuApi::Vulkan,
        };
        let comparison = zsim::gpu::compare(lang, &scene, api)?;
        emit(out, &comparison.text(lang, &scene, &path))?;
        return Ok(Finish::Ok);
    }
    if let Some(preset) = args.compare_rules {
        emit(out, &zsim::tie::compare_rules_text(lang, &scene, &path, preset))?;
        return Ok(Finish::Ok);
    }
    if args.arith != Arith::Exact {
        return run_inexact(lang, args, &scene, &path, read_time, out);
    }
    let json = args.format == Format::Json;
    if args.segments.is_some() || args.order == Order::Pixels || scene.effects.antialias.is_some() {
        if args.format == Format::None {
            return Err(super::flags::Flag::FormatNoneIsPlain.into());
        }
        let variant = super::variants::RunVariant {
            segments: args.segments,
            pixel_order: (args.order == Order::Pixels).then_some(match args.inside.unwrap_or(InsideTest::Ray) {
                InsideTest::Ray => zsim::variants::Inside::Ray,
                InsideTest::Arc => zsim::variants::Inside::Arc,
            }),
            axes: axes(args),
            json,
            final_only,
        };
        return super::variants::run(lang, &scene, &path, &variant, out);
    }
    let making = Instant::now();
    let mut simulation = Simulation::new_on(&scene, threads(args));
    // `--format none` times clearing and drawing as a GPU's frame is timed: in buffers made
    // beforehand, their memory already handed over (timed apart).
    if args.format == Format::None {
        simulation.take_pages();
    }
    let made = making.elapsed();
    match args.format {
        Format::Text => {
            emit(out, &report::scene_header(lang, &scene, &zsim::shown_path(&args.scene)))?;
            let last = scene.polygons.len().checked_sub(1);
            if final_only {
                draw_all_but_the_last(&mut simulation, &scene, args);
            }
            while let Some(drawn) = simulation.draw_next_counted(&mut Unobserved) {
                let (index, polygon) = (drawn.index, &scene.polygons[drawn.index]);
                let counts = (drawn.tested, drawn.written);
                if final_only && Some(index) != last {
                    continue;
                }
                let mut text = format!("\n{}\n", report::polygon_heading(lang, &scene, index));
                let counts =
                    zsim::words!(lang, "run-counts", covered = counts.0.to_string(), written = counts.1.to_string());
                text.push_str(&format!("  {counts}\n"));
                text.push_str(&buffers_text(lang, &simulation, index, &polygon.name, axes(args)));
                emit(out, &text)?;
            }
            if scene.polygons.is_empty() {
                let style = MatrixStyle { axes: axes(args), color: super::use_color(), ..MatrixStyle::default() };
                let buffers = simulation.buffers();
                emit(
                    out,
                    &format!(
                        "\n{}\n\n{}\n{}\n{}\n{}",
                        zsim::words!(lang, "run-no-polygons"),
                        zsim::words!(lang, "run-frame-cleared"),
                        report::matrix_styled(&buffers.frame_rows(), &style),
                        zsim::words!(lang, "run-depth-cleared"),
                        report::matrix_styled(&buffers.depth_rows(), &style),
                    ),
                )?;
            }
            if scene.effects.transparency {
                emit(out, &super::variants::local_errors_text(lang, &scene, simulation.buffers()))?;
            }
        }
        Format::Json => {
            // The same object as `RunJson`, written one row at a time so that memory stays
            // near the buffers' own and a closed pipe stops the run early.
            report::write_run_json_start(out, &scene)?;
            if final_only {
                draw_all_but_the_last(&mut simulation, &scene, args);
            }
            let mut first = true;
            while let Some(index) = simulation.draw_next(&mut Unobserved) {
                if final_only && index + 1 != scene.polygons.len() {
                    continue;
                }
                if !first {
                    emit(out, ",")?;
                }
                report::write_step_json(out, &scene.polygons[index].name, simulation.buffers())?;
                first = false;
            }
            report::write_run_json_end(out)?;
        }
        Format::None => {
            let threads = threads(args);
            // A bar only where a person waits: scenes of 10,000 polygons or more.
            let long_run = scene.polygons.len() >= 10_000;
            let tile = tiles(args, &simulation, threads);
            // Made before the clock starts: its label loads the catalogue, which is not drawing.
            let (length, unit) = tile.map_or((scene.polygons.len(), "progress-polygons"), |tile| {
                (scene.height.div_ceil(tile) as usize, "progress-bands")
            });
            let progress = progress_bar(long_run, length, &zsim::words!(lang, unit));
            let rasterizing = Instant::now();
            let drew = if let Some(tile) = tile {
                let band_done = || progress.inc(1);
                // Each tile cleared as it is drawn.
                simulation.redraw(tile, threads, &band_done)
            } else {
                simulation.restart();
                // The bar moves every 1024 polygons, so that it costs nothing per polygon.
                for first in (0..scene.polygons.len()).step_by(1024) {
                    let last = (first + 1024).min(scene.polygons.len()) - 1;
                    simulation.draw_parallel_through(last, 0, 1, &|| {});
                    progress.set_position(last as u64 + 1);
                }
                1
            };
            progress.finish_and_clear();
            let raster_time = rasterizing.elapsed();
            emit(
                out,
                &format!(
                    "{}\n",
                    report::run_summary(
                        lang,
                        &scene,
                        &path,
                        RunFigures {
                            stats: simulation.stats(),
                            buffers: simulation.buffers().memory_bytes(),
                            read: read_time,
                            made: Some(made),
                            raster: raster_time,
                            threads: drew,
                            peak: peak_resident_bytes(),
                        },
                    )
                ),
            )?;
        }
    }
    Ok(Finish::Ok)
}

/// Whether the matrices are labelled: `--axes`, or on a terminal unless `--no-axes`.
fn axes(args: &RunArgs) -> bool {
    args.axes || (!args.no_axes && std::io::stdout().is_terminal())
}

/// How many threads draw: `--threads`, else every core.
fn threads(args: &RunArgs) -> usize {
    args.threads.map_or_else(|| std::thread::available_parallelism().map_or(1, usize::from), |threads| threads as usize)
}

/// The side of the tiles to draw in, or `None` to draw polygon by polygon:
/// `--tile`, else as the simulation chooses for this many threads
/// ([`Simulation::default_tile`]). Tiles keep the cells in cache and are drawn
/// a band of tiles per job on `threads` threads; the result is the same as
/// polygon by polygon. A tile's bin (a vector, 24 bytes, and its polygons)
/// costs less than its cells (8 bytes each) only from 8×8 on: smaller tiles
/// draw as 8×8, alike.
fn tiles(args: &RunArgs, simulation: &Simulation<'_>, threads: usize) -> Option<u32> {
    match args.tile {
        Some(tile) => Some(tile.max(MIN_TILE)),
        None => Some(simulation.default_tile(threads)).filter(|&tile| tile > 0),
    }
}

/// For `--final` and `--after`: every polygon but the last, on every core
/// (in tiles, identical to drawing them in order), so that the last one is
/// drawn alone and its counts can be told.
fn draw_all_but_the_last(simulation: &mut Simulation<'_>, scene: &Scene, args: &RunArgs) {
    let Some(last) = scene.polygons.len().checked_sub(2) else { return };
    let threads = threads(args);
    match tiles(args, simulation, threads) {
        Some(tile) => {
            simulation.draw_parallel_through(last, tile, threads, &|| {});
        }
        None => {
            simulation.draw_parallel_through(last, 0, 1, &|| {});
        }
    }
}

fn buffers_text(lang: zsim::Lang, simulation: &Simulation<'_>, index: usize, name: &str, axes: bool) -> String {
    let style = MatrixStyle { axes, color: super::use_color(), ..MatrixStyle::default() };
    format!(
        "\n{}\n{}\n{}\n{}",
        zsim::words!(lang, "run-frame-after", polygon = zsim::polygon_label(lang, "polygon-after", index, name)),
        report::matrix_styled(&simulation.buffers().frame_rows(), &style),
        zsim::words!(lang, "run-depth-after", polygon = zsim::polygon_label(lang, "polygon-after", index, name)),
        report::matrix_styled(&simulation.buffers().depth_rows(), &style),
    )
}

/// A progress bar over `length` `unit`s (polygons, bands of tiles) on standard error, shown only there on a
/// terminal and only for long runs.
fn progress_bar(long: bool, length: usize, unit: &str) -> ProgressBar {
    if !long || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(length as u64);
    if let Ok(style) = ProgressStyle::with_template(&format!("{{bar:40}} {{pos}}/{{len}} {unit}, {{per_sec}}")) {
        bar.set_style(style);
    }
    bar
}

/// The process's peak resident size so far, from `/proc/self/status`
/// (`VmHWM`); `None` where there is no such file (systems other than Linux).
fn peak_resident_bytes() -> Option<u64> {
    let status = zsim::read_bytes(std::path::Path::new("/proc/self/status"), zsim::Links::Follow).ok()?;
    let status = String::from_utf8(status).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.trim_start_matches("VmHWM:").trim().trim_end_matches("kB").trim().parse().ok()?;
    Some(kib * 1024)
}

/// `run --arith MODE` for an inexact mode: the final buffers, and how they differ from exact.
fn run_inexact(
    lang: zsim::Lang,
    args: &RunArgs,
    scene: &Scene,
    path: &str,
    read_time: Duration,
    out: &mut dyn Write,
) -> Result<Finish, Failure> {
    zsim::arith::check_supported(scene, args.arith)?;
    if args.segments.is_some() || args.order != Order::Polygons {
        return Err(super::flags::Flag::ArithPlainLoopOnly.into());
    }
    let prepared = zsim::arith::Prepared::new(scene, args.arith)?;
    let rasterizing = Instant::now();
    let (buffers, stats) = prepared.raster();
    let raster_time = rasterizing.elapsed();
    let last = scene.polygons.last().map_or(String::new(), |p| p.name.clone());
    match args.format {
        Format::Json => {
            emit(out, &json_line(&zsim::variant_report::buffers_json(scene, &last, &buffers)))?;
        }
        Format::None => {
            let figures = RunFigures {
                stats,
                buffers: buffers.memory_bytes(),
                read: read_time,
                made: None,
                raster: raster_time,
                threads: 1,
                peak: peak_resident_bytes(),
            };
            let text = report::run_summary(lang, scene, path, figures);
            emit(out, &format!("{text}{}\n", zsim::words!(lang, "run-summary-arith", arith = args.arith.to_string())))?;
        }
        Format::Text => {
            // Only the text report compares with exact, so timing a mode runs that mode alone.
            let (exact, _) = zsim::arith::run(scene, Arith::Exact)?;
            let (frame_cells, depth_cells) = buffers.differences(&exact);
            let style = MatrixStyle { axes: axes(args), color: super::use_color(), ..MatrixStyle::default() };
            emit(
                out,
                &format!(
                    "{}{}\n\n{}\n{}\n{}\n{}",
                    report::scene_header(lang, scene, path),
                    zsim::words!(
                        lang,
                        "run-arith-compared",
                        arith = args.arith.to_string(),
                        frame = frame_cells.to_string(),
                        depth = depth_cells.to_string()
                    ),
                    zsim::words!(lang, "run-frame-after-all"),
                    report::matrix_styled(&buffers.frame_rows(), &style),
                    zsim::words!(lang, "run-depth-after-all"),
                    report::matrix_styled(&buffers.depth_rows(), &style)
                ),
            )?;
        }
    }
    Ok(Finish::Ok)
}

/// A GPU API `--compare-gpu` draws with.
#[cfg(feature = "gpu")]
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum GpuApi {
    /// OpenGL through EGL (Mesa's llvmpipe where no GPU is present).
    Gl,
    /// Vulkan (Mesa's lavapipe where no GPU is present), in a zsim built with the `vulkan` feature.
    Vulkan,
}
