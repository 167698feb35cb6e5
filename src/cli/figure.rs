//! `zsim figure`: the raster as an SVG for a handout.

use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use zsim::error::Error;
use zsim::explain::polygon_name;
use zsim::figure::{MAX_FIGURE_SIDE, Shading, svg};
use zsim::pipeline::Simulation;
use zsim::scene::Scene;
use zsim::trace::Unobserved;

use super::{Failure, Finish, emit};

/// Arguments of `zsim figure`.
#[derive(Debug, Args)]
pub struct FigureArgs {
    /// The scene file (JSON).
    scene: PathBuf,
    /// Draw the state after this polygon (number from 1, or name); default: the last.
    #[arg(long, value_name = "N|NAME")]
    after: Option<String>,
    /// Shade pixels by z-buffer value instead of filling them by framebuffer value.
    #[arg(long)]
    depth: bool,
    /// The SVG file to write.
    #[arg(short, long, value_name = "FILE.svg")]
    output: PathBuf,
}

pub fn run(args: &FigureArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let scene = Scene::load(&args.scene)?;
    if scene.width > MAX_FIGURE_SIDE || scene.height > MAX_FIGURE_SIDE {
        return Err(Error::Usage(format!(
            "{}: a figure draws rasters up to {MAX_FIGURE_SIDE}×{MAX_FIGURE_SIDE}; this one is {}×{}",
            args.scene.display(),
            scene.width,
            scene.height
        ))
        .into());
    }
    if scene.polygons.is_empty() {
        return Err(Error::Usage(format!("{}: the scene has no polygons to draw", args.scene.display())).into());
    }
    let last = match &args.after {
        Some(spec) => scene.find_polygon(spec)?,
        None => scene.polygons.len() - 1,
    };
    let mut simulation = Simulation::new(&scene);
    simulation.draw_through(last, &mut Unobserved);
    let shading = if args.depth { Shading::Depth } else { Shading::Frame };
    let what = if args.depth { "z-buffer" } else { "framebuffer" };
    let title = format!("{}: {what} after {}", args.scene.display(), polygon_name(&scene, last));
    let text = svg(&scene, simulation.buffers(), last, shading, &title);
    std::fs::write(&args.output, text).map_err(|source| Error::Write { path: args.output.clone(), source })?;
    emit(out, &format!("wrote {} ({title})\n", args.output.display()))?;
    Ok(Finish::Ok)
}
