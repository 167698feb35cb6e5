//! `zsim explain`: the history of one pixel through the whole scene.

use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use zsim::error::Error;
use zsim::exact::{Q, exact_and_decimal};
use zsim::explain::{entry_text, polygon_name};
use zsim::pipeline::Simulation;
use zsim::scene::Scene;
use zsim::trace::PixelWatcher;

use super::{Failure, Finish, emit};

/// Arguments of `zsim explain`.
#[derive(Debug, Args)]
pub struct ExplainArgs {
    /// The scene file (JSON).
    scene: PathBuf,
    /// The pixel, as X,Y (pixel (0, 0) is bottom left).
    #[arg(long, value_parser = parse_pixel, value_name = "X,Y")]
    pixel: (u32, u32),
}

/// Parses `X,Y`.
pub fn parse_pixel(text: &str) -> Result<(u32, u32), String> {
    let (x, y) = text.split_once(',').ok_or_else(|| format!("\"{text}\" is not X,Y (for example 20,15)"))?;
    let coordinate = |v: &str| v.trim().parse::<u32>().map_err(|_| format!("\"{v}\" is not a pixel coordinate"));
    Ok((coordinate(x)?, coordinate(y)?))
}

/// Checks that a pixel lies on the scene's raster.
pub fn check_pixel(scene: &Scene, (x, y): (u32, u32)) -> Result<(), Error> {
    if x >= scene.width || y >= scene.height {
        return Err(Error::Usage(format!(
            "pixel ({x}, {y}) is outside the {}×{} raster (x 0 … {}, y 0 … {})",
            scene.width,
            scene.height,
            scene.width - 1,
            scene.height - 1
        )));
    }
    Ok(())
}

pub fn run(args: &ExplainArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let scene = Scene::load(&args.scene)?;
    let (x, y) = args.pixel;
    check_pixel(&scene, args.pixel)?;
    let mut watcher = PixelWatcher::new([(x, y)]);
    let mut simulation = Simulation::new(&scene);
    simulation.finish(&mut watcher);
    let centre = |v: u32| exact_and_decimal(Q::new(2 * i128::from(v) + 1, 2));
    let mut text = format!(
        "pixel ({x}, {y}) of {}: centre ({}, {}), depth test {} (z {} stored)\n",
        args.scene.display(),
        centre(x),
        centre(y),
        scene.depth_test.name(),
        scene.depth_test.symbol()
    );
    if let Some(section) = scene.effects.section {
        text.push_str(&format!(
            "cross-section: only z {} {} is written\n",
            scene.depth_test.section_symbol(),
            zsim::explain::depth_text(&scene, section)
        ));
    }
    text.push_str(&format!("start: framebuffer {}, z-buffer {} (cleared)\n", scene.background, scene.clear_depth));
    for entry in watcher.history(x, y) {
        text.push_str(&format!("{}: {}\n", polygon_name(&scene, entry.index), entry_text(&scene, x, y, entry)));
    }
    let buffers = simulation.buffers();
    text.push_str(&format!("final: framebuffer {}, z-buffer {}\n", buffers.frame(x, y), buffers.depth(x, y)));
    emit(out, &text)?;
    Ok(Finish::Ok)
}
