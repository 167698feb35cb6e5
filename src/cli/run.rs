//! `zsim run`: the buffers after each polygon, as the book prints them.

use std::io::Write;
use std::path::PathBuf;

use clap::{Args, ValueEnum};
use zsim::pipeline::{self, Simulation};
use zsim::report::{self, MatrixStyle, RunJson, StepJson};
use zsim::scene::Scene;
use zsim::trace::Unobserved;

use super::{Failure, Finish, emit};

/// Arguments of `zsim run`.
#[derive(Debug, Args)]
pub struct RunArgs {
    /// The scene file (JSON).
    scene: PathBuf,
    /// Print only the state after the last polygon.
    #[arg(long = "final")]
    final_only: bool,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Label rows with y and columns with x.
    #[arg(long)]
    axes: bool,
    /// Loop order: polygons then their pixels (the z-buffer), or every pixel then every polygon (seed 001).
    #[arg(long, value_enum, default_value_t = Order::Polygons)]
    order: Order,
    /// The point-in-polygon test of --order pixels.
    #[arg(long, value_enum, default_value_t = InsideTest::Ray)]
    inside: InsideTest,
    /// A z-buffer only as large as one segment: strips:N, tiles:N or rows:1 (seed 000).
    #[arg(long, value_name = "strips:N|tiles:N|rows:1", value_parser = zsim::variants::Segments::parse)]
    segments: Option<zsim::variants::Segments>,
}

/// The loop order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Order {
    /// For every polygon, for every pixel it covers: the z-buffer.
    Polygons,
    /// For every pixel, for every polygon, with one depth variable (seed 001).
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

pub fn run(args: &RunArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let scene = Scene::load(&args.scene)?;
    let path = args.scene.display().to_string();
    let json = args.format == Format::Json;
    if args.segments.is_some() || args.order == Order::Pixels || scene.effects.antialias.is_some() {
        if args.format == Format::None {
            return Err(zsim::error::Error::Usage("--format none summarizes the z-buffer loop; use text or json with --segments, --order pixels or antialias".into()).into());
        }
        let variant = super::variants::Variant {
            segments: args.segments,
            pixel_order: (args.order == Order::Pixels).then_some(match args.inside {
                InsideTest::Ray => zsim::variants::Inside::Ray,
                InsideTest::Arc => zsim::variants::Inside::Arc,
            }),
            axes: args.axes,
            json,
            final_only: args.final_only,
        };
        return super::variants::run(&scene, &path, &variant, out);
    }
    let mut simulation = Simulation::new(&scene);
    match args.format {
        Format::Text => {
            emit(out, &report::scene_header(&scene, &args.scene.display().to_string()))?;
            let last = scene.polygons.len().checked_sub(1);
            let mut before = simulation.stats();
            while let Some(index) = simulation.draw_next(&mut Unobserved) {
                let after = simulation.stats();
                let polygon = &scene.polygons[index];
                let mut text = format!("\n{}\n", report::polygon_heading(&scene, index));
                text.push_str(&format!(
                    "  {} pixel centres covered, {} written\n",
                    after.tested - before.tested,
                    after.written - before.written
                ));
                before = after;
                if !args.final_only || Some(index) == last {
                    text.push_str(&buffers_text(&simulation, index, &polygon.name, args.axes));
                }
                emit(out, &text)?;
            }
            if scene.effects.transparency {
                emit(out, &super::variants::local_errors_text(&scene, simulation.buffers()))?;
            }
        }
        Format::Json => {
            let mut steps = Vec::with_capacity(scene.polygons.len());
            while let Some(index) = simulation.draw_next(&mut Unobserved) {
                if args.final_only && index + 1 != scene.polygons.len() {
                    continue;
                }
                steps.push(StepJson {
                    polygon: scene.polygons[index].name.clone(),
                    frame: simulation.buffers().frame_rows(),
                    depth: simulation.buffers().depth_rows(),
                });
            }
            let json = RunJson { width: scene.width, height: scene.height, effects: scene.effects.names(), steps };
            let text = serde_json::to_string(&json).expect("serializing plain data cannot fail");
            emit(out, &format!("{text}\n"))?;
        }
        Format::None => {
            simulation.finish(&mut Unobserved);
            emit(out, &format!("{}\n", summary(&scene, &args.scene.display().to_string(), &simulation)))?;
        }
    }
    Ok(Finish::Ok)
}

fn buffers_text(simulation: &Simulation<'_>, index: usize, name: &str, axes: bool) -> String {
    let style = MatrixStyle { axes, color: super::use_color(), ..MatrixStyle::default() };
    format!(
        "\nframebuffer after polygon {n} \"{name}\":\n{}\nz-buffer after polygon {n} \"{name}\":\n{}",
        report::matrix_styled(&simulation.buffers().frame_rows(), &style),
        report::matrix_styled(&simulation.buffers().depth_rows(), &style),
        n = index + 1,
    )
}

fn summary(scene: &Scene, path: &str, simulation: &Simulation<'_>) -> String {
    let stats = simulation.stats();
    let effects = scene.effects.names();
    format!(
        "{path}: {} polygons, {} pixel centres tested, {} written; effects: {}; stages: {}",
        stats.polygons,
        stats.tested,
        stats.written,
        if effects.is_empty() { "none".to_string() } else { effects.join(", ") },
        pipeline::stages(scene).join(" → "),
    )
}
