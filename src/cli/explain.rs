//! `zsim explain`: the history of one pixel through the whole scene.

use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use zsim::Error;
use zsim::Scene;

use super::{Failure, Finish, emit};

/// Arguments of `zsim explain`.
#[derive(Debug, Args)]
pub struct ExplainArgs {
    /// The scene file (JSON), or - for standard input.
    scene: PathBuf,
    /// The pixel, as X,Y (pixel (0, 0) is bottom left).
    #[arg(long, value_parser = |text: &str| parse_pixel(super::language_of_the_run(), text), value_name = "X,Y")]
    pixel: (u32, u32),
    /// Also show each polygon's point-in-polygon tests at the centre (ray and arc), as `--order pixels` uses them.
    #[arg(long)]
    inside: bool,
    /// Also show what this arithmetic leaves in the pixel: f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K.
    #[arg(long, default_value = "exact", value_parser = |text: &str| zsim::arith::Arith::parse(text).map_err(|e| e.message(super::language_of_the_run())))]
    arith: zsim::arith::Arith,
    /// Also show which segment holds the pixel and which polygons that segment visits.
    #[arg(long, value_name = "strips:N|tiles:N|rows:1", value_parser = |text: &str| zsim::variants::Segments::parse(text).map_err(|e| e.message(super::language_of_the_run())))]
    segments: Option<zsim::variants::Segments>,
}

/// Parses `X,Y`.
pub fn parse_pixel(lang: zsim::Lang, text: &str) -> Result<(u32, u32), String> {
    let shown = |v: &str| zsim::printable(&zsim::token(lang, v)).into_owned();
    let (x, y) = text.split_once(',').ok_or_else(|| zsim::words!(lang, "usage-pixel-not-xy", text = shown(text)))?;
    let coordinate =
        |v: &str| v.trim().parse::<u32>().map_err(|_| zsim::words!(lang, "usage-pixel-coordinate", text = shown(v)));
    Ok((coordinate(x)?, coordinate(y)?))
}

/// Checks that a pixel lies on the scene's raster.
pub fn check_pixel(scene: &Scene, (x, y): (u32, u32)) -> Result<(), Error> {
    if x >= scene.width || y >= scene.height {
        let (x, y) = (u64::from(x), u64::from(y));
        return Err(zsim::history::PixelOutside { x, y, width: scene.width, height: scene.height }.into());
    }
    Ok(())
}

pub fn run(lang: zsim::Lang, args: &ExplainArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let scene = Scene::load(&args.scene)?;
    check_pixel(&scene, args.pixel)?;
    let extras = zsim::history::Extras { inside: args.inside, arith: args.arith, segments: args.segments };
    let history = zsim::history::history(&scene, args.pixel, extras)?;
    emit(out, &history.text(lang, &scene, &args.scene))?;
    Ok(Finish::Ok)
}
