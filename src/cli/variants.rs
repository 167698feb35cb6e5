//! `zsim run` with another loop order, a segmented z-buffer or antialiasing,
//! and the transparency report.

use std::io::Write;

use comfy_table::{Table, presets};
use zsim::Buffers;
use zsim::Scene;
use zsim::Simulation;
use zsim::Unobserved;
use zsim::antialias;
use zsim::explain::polygon_name;
use zsim::report::{self, MatrixStyle};
use zsim::variants::{self, ArcDifference, Inside, Segments};

use super::{Failure, Finish, emit};

/// What `run` was asked for besides the plain z-buffer.
pub struct Variant {
    pub segments: Option<Segments>,
    pub pixel_order: Option<Inside>,
    pub axes: bool,
    pub json: bool,
    pub final_only: bool,
}

fn exact_json<T: Into<zsim::Exact> + Clone>(rows: &[Vec<T>]) -> serde_json::Value {
    rows.iter().map(|row| row.iter().map(|v| zsim::report::exact_json(v.clone())).collect::<Vec<_>>()).collect()
}

fn buffers_json(scene: &Scene, name: &str, buffers: &Buffers) -> serde_json::Value {
    serde_json::json!({
        "width": scene.width, "height": scene.height, "effects": scene.effects.names(),
        "steps": [{"polygon": name, "frame": buffers.frame_rows(), "depth": buffers.depth_rows()}],
    })
}

/// Both buffers after all polygons.
fn matrices(lang: zsim::Lang, buffers: &Buffers, axes: bool) -> String {
    let style = MatrixStyle { axes, color: super::use_color(), ..MatrixStyle::default() };
    format!(
        "\n{}\n{}\n{}\n{}",
        zsim::words!(lang, "run-frame-after-all"),
        report::matrix_styled(&buffers.frame_rows(), &style),
        zsim::words!(lang, "run-depth-after-all"),
        report::matrix_styled(&buffers.depth_rows(), &style)
    )
}

/// Whether two runs left the same buffers, in words.
fn comparison(lang: zsim::Lang, ours: &Buffers, plain: &Buffers) -> String {
    let (frame, depth) = ours.differences(plain);
    let differing = frame + depth;
    if differing == 0 {
        zsim::words!(lang, "variant-identical")
    } else {
        zsim::words!(lang, "variant-differs", count = differing.to_string())
    }
}

pub fn run(
    lang: zsim::Lang,
    scene: &Scene,
    path: &str,
    variant: &Variant,
    out: &mut dyn Write,
) -> Result<Finish, Failure> {
    let last_name = scene.polygons.last().map_or(String::new(), |p| p.name.clone());
    let mut plain = Simulation::new(scene);
    plain.finish(&mut Unobserved);
    if let Some(segments) = variant.segments {
        let (buffers, stats) = variants::run_segmented(scene, segments);
        if variant.json {
            emit(out, &format!("{}\n", buffers_json(scene, &last_name, &buffers)))?;
            return Ok(Finish::Ok);
        }
        let depth_bits = u64::from(scene.depth_bits);
        let full = u64::from(scene.width) * u64::from(scene.height);
        let mut text = report::scene_header(lang, scene, path);
        let drawn = (0..scene.polygons.len()).filter(|&i| zsim::fate(scene, i) == zsim::Fate::Drawn).count();
        let lines = [
            zsim::words!(lang, "segments-kind", count = stats.segments.to_string(), segments = segments.to_string()),
            zsim::words!(
                lang,
                "segments-memory",
                cells = stats.depth_cells.to_string(),
                bits = depth_bits.to_string(),
                total = (stats.depth_cells * depth_bits).to_string(),
                whole_cells = full.to_string(),
                whole_bits = (full * depth_bits).to_string()
            ),
            zsim::words!(lang, "segments-visits", visits = stats.polygon_visits.to_string(), whole = drawn.to_string()),
            zsim::words!(lang, "variant-result", result = comparison(lang, &buffers, plain.buffers())),
        ];
        for line in lines {
            text.push_str(&format!("{line}\n"));
        }
        text.push_str(&matrices(lang, &buffers, variant.axes));
        emit(out, &text)?;
        return Ok(Finish::Ok);
    }
    if let Some(inside) = variant.pixel_order {
        let (buffers, differences) = variants::run_pixel_order(scene, inside);
        if variant.json {
            emit(out, &format!("{}\n", buffers_json(scene, &last_name, &buffers)))?;
            return Ok(Finish::Ok);
        }
        let mut text = report::scene_header(lang, scene, path);
        let test = match inside {
            Inside::Ray => zsim::words!(lang, "pixel-order-ray"),
            Inside::Arc => zsim::words!(lang, "pixel-order-arc"),
        };
        text.push_str(&format!("{}\n", zsim::words!(lang, "pixel-order-heading", test = test)));
        let result = zsim::words!(lang, "variant-result", result = comparison(lang, &buffers, plain.buffers()));
        text.push_str(&format!("{result}\n"));
        if !differences.is_empty() {
            let mut table = Table::new();
            table.load_style(presets::ASCII_MARKDOWN).set_header([
                "x".to_string(),
                "y".to_string(),
                zsim::words!(lang, "pixel-order-header-polygon"),
                zsim::words!(lang, "pixel-order-header-why"),
            ]);
            for d in &differences {
                let why = match d.why {
                    ArcDifference::OnBoundary => zsim::words!(lang, "pixel-order-on-boundary"),
                    ArcDifference::Winding(w) => zsim::words!(lang, "pixel-order-winding", winding = w.to_string()),
                };
                table.add_row([d.x.to_string(), d.y.to_string(), polygon_name(lang, scene, d.polygon), why]);
            }
            let line = zsim::words!(lang, "pixel-order-disagree", count = differences.len().to_string());
            text.push_str(&format!("{line}\n{table}\n"));
        }
        text.push_str(&matrices(lang, &buffers, variant.axes));
        emit(out, &text)?;
        return Ok(Finish::Ok);
    }
    let settings = scene.effects.antialias.expect("run only sends antialiased scenes here");
    let pictures = antialias::run(scene, settings)?;
    if variant.json {
        let steps: Vec<serde_json::Value> = pictures
            .iter()
            .zip(&scene.polygons)
            .skip(if variant.final_only { pictures.len().saturating_sub(1) } else { 0 })
            .map(|(p, polygon)| serde_json::json!({"polygon": polygon.name, "frame": exact_json(&p.frame), "depth": exact_json(&p.depth)}))
            .collect();
        let json = serde_json::json!({"width": scene.width, "height": scene.height, "effects": scene.effects.names(), "steps": steps});
        emit(out, &format!("{json}\n"))?;
        return Ok(Finish::Ok);
    }
    let k = settings.samples;
    let mut text = report::scene_header(lang, scene, path);
    let at = if settings.depth_at_samples { "antialias-at-sample" } else { "antialias-at-centre" };
    let line = zsim::words!(
        lang,
        "antialias-heading",
        k = k.to_string(),
        at = zsim::words!(lang, at),
        samples = (k * k).to_string()
    );
    text.push_str(&format!("{line}\n"));
    let style = MatrixStyle { axes: variant.axes, color: super::use_color(), ..MatrixStyle::default() };
    for (index, picture) in pictures.iter().enumerate() {
        if variant.final_only && index + 1 != pictures.len() {
            continue;
        }
        let name = polygon_name(lang, scene, index);
        text.push_str(&format!(
            "\n{}\n\n{}\n{}\n{}\n{}",
            report::polygon_heading(lang, scene, index),
            zsim::words!(lang, "antialias-frame-after", polygon = name.as_str()),
            report::matrix_styled(&picture.frame, &style),
            zsim::words!(lang, "antialias-depth-after", polygon = name.as_str()),
            report::matrix_styled(&picture.depth, &style)
        ));
    }
    emit(out, &text)?;
    Ok(Finish::Ok)
}

/// The cells where drawing order with opacity differs from the back-to-front blend.
pub fn local_errors_text(lang: zsim::Lang, scene: &Scene, drawn: &Buffers) -> String {
    let errors = variants::local_errors(scene, drawn);
    if errors.is_empty() {
        return format!("\n{}\n", zsim::words!(lang, "transparency-all-match"));
    }
    let mut table = Table::new();
    table.load_style(presets::ASCII_MARKDOWN).set_header([
        "x".to_string(),
        "y".to_string(),
        zsim::words!(lang, "transparency-header-drawn"),
        zsim::words!(lang, "transparency-header-back-to-front"),
        zsim::words!(lang, "transparency-header-polygons"),
    ]);
    for e in &errors {
        let order: Vec<String> = e.back_to_front.iter().map(|&i| polygon_name(lang, scene, i)).collect();
        table.add_row([e.x.to_string(), e.y.to_string(), e.drawn.to_string(), e.correct.to_string(), order.join(", ")]);
    }
    format!("\n{}\n{table}\n", zsim::words!(lang, "transparency-differs", count = errors.len().to_string()))
}
