//! `zsim figure`: the raster as an SVG (or PNG) for a handout.

use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use zsim::Error;
use zsim::Scene;
use zsim::Simulation;
use zsim::explain::polygon_after;
use zsim::figure::{Annotations, MAX_FIGURE_SIDE, Shading, svg_with};

use super::{Failure, Finish, emit};

/// Arguments of `zsim figure`.
#[derive(Debug, Args)]
pub struct FigureArgs {
    /// The scene file (JSON), or - for standard input.
    scene: PathBuf,
    /// Draw the state after this polygon (number from 1, or name); default: the last. 0: the empty grid with every outline and vertex, a worksheet.
    #[arg(long, value_name = "N|NAME")]
    after: Option<String>,
    /// Shade pixels by z-buffer value instead of filling them by framebuffer value.
    #[arg(long)]
    depth: bool,
    /// Print each cell's value (framebuffer, or z-buffer with --depth) in its pixel, as an answer key does.
    #[arg(long)]
    values: bool,
    /// The title (default: the scene's file name and what is drawn).
    #[arg(long)]
    title: Option<String>,
    /// The file to write, by its extension: .svg, .png (a picture), .pdf (a page), .tex (a TikZ picture in a LaTeX document); .png and .pdf need a build with the figures feature, as the package is.
    #[arg(short, long, value_name = "FILE.svg|png|pdf|tex")]
    output: PathBuf,
    /// With -o FILE.tex: the tikzpicture alone, for \input in your own document (which loads tikz).
    #[arg(long)]
    tikz_only: bool,
    /// With -o FILE.png: pixels per unit of the drawing (default 2, lowered to keep the longer side within 4096 pixels; at most 8192 × 8192 pixels in all).
    #[arg(long, value_name = "PIXELS", value_parser = |text: &str| text.parse::<f32>().ok().filter(|s| s.is_finite() && *s > 0.0 && *s <= 64.0).ok_or_else(|| format!("\"{text}\" is not a scale from 0 to 64")))]
    scale: Option<f32>,
    /// With -o FILE.pdf: the page, a4 or letter (turned to landscape when the figure fits larger so).
    #[arg(long, value_name = "a4|letter", default_value = "a4", value_parser = |t: &str| zsim::picture::Paper::parse(t).ok_or_else(|| format!("\"{t}\" is not a paper: a4 or letter")))]
    paper: zsim::picture::Paper,
}

pub fn run(lang: zsim::Lang, args: &FigureArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let Some(format) = zsim::picture::Format::of(&args.output) else {
        return Err(super::flags::Flag::FigureFormat { path: args.output.clone() }.into());
    };
    let scene = Scene::load(&args.scene)?;
    if scene.width > MAX_FIGURE_SIDE || scene.height > MAX_FIGURE_SIDE {
        return Err(Error::from(zsim::picture::FigureRefused::TooLarge {
            path: args.scene.clone(),
            width: scene.width,
            height: scene.height,
            max: MAX_FIGURE_SIDE,
        })
        .into());
    }
    if scene.polygons.is_empty() {
        return Err(Error::from(zsim::picture::FigureRefused::NoPolygons { path: args.scene.clone() }).into());
    }
    // `--after 0`: nothing drawn yet, every polygon outlined with its vertices: a worksheet.
    let worksheet = args.after.as_deref() == Some("0");
    let last = match &args.after {
        Some(_) if worksheet => scene.polygons.len() - 1,
        Some(spec) => scene.find_polygon(spec)?,
        None => scene.polygons.len() - 1,
    };
    let shading = if args.depth { Shading::Depth } else { Shading::Frame };
    let buffer = zsim::words!(lang, if args.depth { "buffer-depth" } else { "buffer-frame" });
    let file = args.scene.file_name().map_or_else(|| zsim::shown_path(&args.scene), |n| n.to_string_lossy().into());
    let mut title = if worksheet {
        zsim::words!(lang, "figure-title-worksheet", file = file)
    } else {
        zsim::words!(
            lang,
            "figure-title-after",
            file = file,
            buffer = buffer,
            polygon = polygon_after(lang, &scene, last)
        )
    };
    // Antialiasing: the figure shows the samples, before they are averaged, and says so.
    let scene = match scene.effects.antialias {
        Some(settings) if !worksheet => {
            let k = settings.samples;
            title.push_str(&zsim::words!(lang, "figure-title-samples", k = k));
            zsim::antialias::supersampled(&scene, k)?
        }
        _ => scene,
    };
    let title = args.title.clone().unwrap_or(title);
    let mut simulation = Simulation::new(&scene);
    if !worksheet {
        // On every core, in tiles: the same cells as drawing in order.
        let threads = std::thread::available_parallelism().map_or(1, usize::from);
        simulation.draw_parallel_through(last, simulation.default_tile(threads), threads, &|| {});
    }
    let extras = Annotations { vertex_labels: worksheet, caption: Vec::new(), values: args.values };
    let text = svg_with(lang, &scene, simulation.buffers(), last, shading, &title, &extras);
    let bytes = format.encode(lang, &text, &args.output, args.tikz_only, (args.scale, args.paper))?;
    let mut plan = zsim::Plan::new(&[&args.scene], zsim::Replace::Allowed);
    plan.file(&args.output, bytes);
    plan.write()?;
    emit(
        out,
        &format!(
            "{}\n",
            zsim::words!(
                lang,
                "file-written-about",
                path = zsim::shown_path(&args.output),
                about = zsim::printable(&title).into_owned()
            )
        ),
    )?;
    Ok(Finish::Ok)
}
