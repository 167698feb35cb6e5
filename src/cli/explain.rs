//! `zsim explain`: the history of one pixel through the whole scene.

use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use zsim::Error;
use zsim::PixelWatcher;
use zsim::Scene;
use zsim::Simulation;
use zsim::explain::{entry_text, polygon_name};
use zsim::{Q, exact_and_decimal};

use super::{Failure, Finish, emit};

/// Arguments of `zsim explain`.
#[derive(Debug, Args)]
pub struct ExplainArgs {
    /// The scene file (JSON), or - for standard input.
    scene: PathBuf,
    /// The pixel, as X,Y (pixel (0, 0) is bottom left).
    #[arg(long, value_parser = parse_pixel, value_name = "X,Y")]
    pixel: (u32, u32),
    /// Also show each polygon's point-in-polygon tests at the centre (ray and arc), as `--order pixels` uses them.
    #[arg(long)]
    inside: bool,
    /// Also show what this arithmetic leaves in the pixel: f64, f64-incremental, f32-incremental, f32, f32-edge or fixed:K.
    #[arg(long, default_value = "exact", value_parser = zsim::arith::Arith::parse)]
    arith: zsim::arith::Arith,
    /// Also show which segment holds the pixel and which polygons that segment visits.
    #[arg(long, value_name = "strips:N|tiles:N|rows:1", value_parser = zsim::variants::Segments::parse)]
    segments: Option<zsim::variants::Segments>,
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
        return Err(zsim::Usage::PixelOutside { x, y, width: scene.width, height: scene.height }.into());
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
    let mut text = zsim::words!(
        "explain-heading",
        x = x,
        y = y,
        file = args.scene.display().to_string(),
        cx = centre(x),
        cy = centre(y),
        test = scene.depth_test.name(),
        rule = scene.depth_test.rule_text()
    ) + "\n";
    if let Some(section) = scene.effects.section {
        let line = zsim::words!(
            "explain-section",
            op = scene.depth_test.section_symbol(),
            section = zsim::explain::depth_text(&scene, section)
        );
        text.push_str(&format!("{line}\n"));
    }
    text.push_str(&zsim::words!("explain-start", frame = scene.background, depth = scene.clear_depth.to_string()));
    text.push('\n');
    if let Some(segments) = args.segments {
        text.push_str(&segment_text(&scene, segments, (x, y)));
    }
    for entry in watcher.history(x, y) {
        let line = zsim::words!(
            "polygon-line",
            polygon = polygon_name(&scene, entry.index),
            text = entry_text(&scene, x, y, entry)
        );
        text.push_str(&line);
        text.push('\n');
        if args.inside && entry.fate == zsim::Fate::Drawn {
            text.push_str(&format!("  {}\n", inside_text(&scene.polygons[entry.index], x, y)));
        }
    }
    let buffers = simulation.buffers();
    text.push_str(&zsim::words!("explain-final", frame = buffers.frame(x, y), depth = buffers.depth(x, y).to_string()));
    text.push('\n');
    if let Some(settings) = scene.effects.antialias {
        text.push_str(&antialias_text(&scene, settings, (x, y))?);
    }
    if args.arith != zsim::arith::Arith::Exact {
        zsim::arith::check_supported(&scene, args.arith)?;
        let (mode, _) = zsim::arith::run(&scene, args.arith)?;
        let same = mode.frame(x, y) == buffers.frame(x, y) && mode.depth(x, y) == buffers.depth(x, y);
        let line = zsim::words!(
            "explain-arith",
            arith = args.arith.to_string(),
            frame = mode.frame(x, y).to_string(),
            depth = mode.depth(x, y).to_string(),
            verdict = if same { zsim::words!("explain-arith-same") } else { zsim::words!("explain-arith-differs") }
        );
        text.push_str(&format!("{line}\n"));
    }
    emit(out, &text)?;
    Ok(Finish::Ok)
}

/// The two point-in-polygon tests at the centre of (x, y).
fn inside_text(polygon: &zsim::Polygon, x: u32, y: u32) -> String {
    use zsim::variants::{ArcDifference, arc_inside, ray_inside};
    let side =
        |inside: bool| if inside { zsim::words!("explain-inside-in") } else { zsim::words!("explain-inside-out") };
    let ray = side(ray_inside(polygon, x, y));
    let arc = match arc_inside(polygon, x, y) {
        (_, ArcDifference::OnBoundary) => zsim::words!("explain-arc-boundary"),
        (inside, ArcDifference::Winding(w)) => {
            zsim::words!("explain-arc-winding", winding = w.to_string(), inside = side(inside))
        }
    };
    zsim::words!("explain-inside", ray = ray, arc = arc)
}

/// The segment holding (x, y) and the polygons it visits.
fn segment_text(scene: &Scene, segments: zsim::variants::Segments, (x, y): (u32, u32)) -> String {
    let rects = segments.rects(scene.width, scene.height);
    let Some((number, rect)) = rects
        .iter()
        .enumerate()
        .find(|(_, r)| (r.columns.0..=r.columns.1).contains(&x) && (r.rows.0..=r.rows.1).contains(&y))
    else {
        return String::new();
    };
    let visited: Vec<String> =
        zsim::variants::visited_in(scene, *rect).into_iter().map(|i| polygon_name(scene, i)).collect();
    let visited = if visited.is_empty() { zsim::words!("explain-segment-none") } else { visited.join(", ") };
    zsim::words!(
        "explain-segment",
        number = (number + 1).to_string(),
        count = rects.len().to_string(),
        segments = segments.to_string(),
        first = rect.columns.0.to_string(),
        last = rect.columns.1.to_string(),
        bottom = rect.rows.0.to_string(),
        top = rect.rows.1.to_string(),
        cells = (u64::from(rect.columns.1 - rect.columns.0 + 1) * u64::from(rect.rows.1 - rect.rows.0 + 1)).to_string(),
        visited = visited
    ) + "\n"
}

/// What antialiasing does at (x, y): each sample's history (depth at the
/// samples) or each polygon's covered samples and centre-depth test (depth at
/// the pixel), and the mean.
fn antialias_text(scene: &Scene, settings: zsim::Antialias, (x, y): (u32, u32)) -> Result<String, Failure> {
    let k = settings.samples;
    let (pictures, notes) = zsim::antialias::run_watching(scene, settings, Some((x, y)))?;
    let mut text = zsim::words!("explain-antialias", k = k.to_string()) + "\n";
    if settings.depth_at_samples {
        let big = zsim::antialias::supersampled(scene, k)?;
        let samples: Vec<(u32, u32)> = (0..k).flat_map(|j| (0..k).map(move |i| (x * k + i, y * k + j))).collect();
        let mut watcher = PixelWatcher::new(samples.iter().copied());
        let mut simulation = Simulation::new(&big);
        simulation.finish(&mut watcher);
        for &(sx, sy) in &samples {
            let line = zsim::words!(
                "explain-sample",
                i = (sx - x * k).to_string(),
                j = (sy - y * k).to_string(),
                x = zsim::exact_and_decimal(Q::new(2 * i128::from(sx) + 1, 2 * i128::from(k))),
                y = zsim::exact_and_decimal(Q::new(2 * i128::from(sy) + 1, 2 * i128::from(k))),
                frame = simulation.buffers().frame(sx, sy).to_string(),
                depth = simulation.buffers().depth(sx, sy).to_string()
            );
            text.push_str(&format!("{line}\n"));
            for entry in watcher.history(sx, sy) {
                if entry.pixel.is_some() {
                    let line = zsim::words!(
                        "polygon-line",
                        polygon = polygon_name(scene, entry.index),
                        text = entry_text(&big, sx, sy, entry)
                    );
                    text.push_str(&format!("  {line}\n"));
                }
            }
        }
    } else {
        for note in &notes {
            let samples: Vec<String> = note.samples.iter().map(|(i, j)| format!("({i}, {j})")).collect();
            let d = &note.decision;
            let result = match d.outcome {
                zsim::Outcome::Written => {
                    zsim::words!("explain-pixel-mode-written", stored = d.stored.to_string())
                }
                _ => zsim::words!("explain-pixel-mode-not-written"),
            };
            let line = zsim::words!(
                "explain-pixel-mode",
                polygon = polygon_name(scene, note.index),
                samples = samples.join(" "),
                depth = zsim::explain::depth_text(scene, d.compared.value()),
                result = result
            );
            text.push_str(&format!("{line}\n"));
        }
    }
    if let Some(last) = pictures.last() {
        let row = (scene.height - 1 - y) as usize;
        let line = zsim::words!(
            "explain-mean",
            frame = zsim::fraction(last.frame[row][x as usize]),
            depth = zsim::fraction(&last.depth[row][x as usize])
        );
        text.push_str(&format!("{line}\n"));
    }
    Ok(text)
}
