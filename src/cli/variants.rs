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

fn matrices(buffers: &Buffers, what: &str, axes: bool) -> String {
    let style = MatrixStyle { axes, color: super::use_color(), ..MatrixStyle::default() };
    format!(
        "\nframebuffer {what}:\n{}\nz-buffer {what}:\n{}",
        report::matrix_styled(&buffers.frame_rows(), &style),
        report::matrix_styled(&buffers.depth_rows(), &style)
    )
}

/// Whether two runs left the same buffers, in words.
fn comparison(ours: &Buffers, plain: &Buffers) -> String {
    let (frame, depth) = ours.differences(plain);
    let differing = frame + depth;
    if differing == 0 {
        "identical to the plain z-buffer's (framebuffer and z-buffer)".to_string()
    } else {
        format!("{differing} cells differ from the plain z-buffer's")
    }
}

pub fn run(scene: &Scene, path: &str, variant: &Variant, out: &mut dyn Write) -> Result<Finish, Failure> {
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
        let mut text = report::scene_header(scene, path);
        text.push_str(&format!(
            "segments: {} ({}), each polygon sorted into the segments its bounding box touches\n\
             z-buffer memory: {} cells × {depth_bits} bits = {} bits (whole raster: {} cells, {} bits)\n\
             polygon visits: {} (whole raster: {})\n",
            stats.segments,
            segments,
            stats.depth_cells,
            stats.depth_cells * depth_bits,
            full,
            full * depth_bits,
            stats.polygon_visits,
            (0..scene.polygons.len()).filter(|&i| zsim::fate(scene, i) == zsim::Fate::Drawn).count()
        ));
        text.push_str(&format!("result: {}\n", comparison(&buffers, plain.buffers())));
        text.push_str(&matrices(&buffers, "after all polygons", variant.axes));
        emit(out, &text)?;
        return Ok(Finish::Ok);
    }
    if let Some(inside) = variant.pixel_order {
        let (buffers, differences) = variants::run_pixel_order(scene, inside);
        if variant.json {
            emit(out, &format!("{}\n", buffers_json(scene, &last_name, &buffers)))?;
            return Ok(Finish::Ok);
        }
        let mut text = report::scene_header(scene, path);
        let test = match inside {
            Inside::Ray => "ray casting (left-open/right-closed vertex rule; on the boundary counts)",
            Inside::Arc => "the arc-length method (quadrant table; on the boundary counts)",
        };
        text.push_str(&format!(
            "order: for every pixel, for every polygon, one depth variable (the Chinese course notes); inside test: {test}\n"
        ));
        text.push_str(&format!("result: {}\n", comparison(&buffers, plain.buffers())));
        if !differences.is_empty() {
            let mut table = Table::new();
            table.load_style(presets::ASCII_MARKDOWN).set_header(["x", "y", "polygon", "why the inside tests differ"]);
            for d in &differences {
                let why = match d.why {
                    ArcDifference::OnBoundary => "the centre lies exactly on the boundary: arc counts it inside, while the half-interval rule leaves out top edges and vertices (an edge counts only at its lower end)".to_string(),
                    ArcDifference::Winding(w) => format!("the polygon winds {w} times around the centre: arc counts a non-zero winding as inside, the paired crossings (even-odd) as outside"),
                };
                table.add_row([d.x.to_string(), d.y.to_string(), polygon_name(scene, d.polygon), why]);
            }
            text.push_str(&format!(
                "{} centre(s) where arc and the scanline rule disagree:\n{table}\n",
                differences.len()
            ));
        }
        text.push_str(&matrices(&buffers, "after all polygons", variant.axes));
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
    let mut text = report::scene_header(scene, path);
    text.push_str(&format!(
        "antialiasing: {k}×{k} samples per pixel, depth at each {}; values are means over the samples (fractions of {})\n",
        if settings.depth_at_samples { "sample" } else { "pixel's centre" },
        k * k
    ));
    let style = MatrixStyle { axes: variant.axes, color: super::use_color(), ..MatrixStyle::default() };
    for (index, picture) in pictures.iter().enumerate() {
        if variant.final_only && index + 1 != pictures.len() {
            continue;
        }
        let name = polygon_name(scene, index);
        text.push_str(&format!(
            "\n{}\n\nframebuffer after {name}, averaged:\n{}\nz-buffer after {name}, averaged:\n{}",
            report::polygon_heading(scene, index),
            report::matrix_styled(&picture.frame, &style),
            report::matrix_styled(&picture.depth, &style)
        ));
    }
    emit(out, &text)?;
    Ok(Finish::Ok)
}

/// The cells where drawing order with opacity differs from the back-to-front blend.
pub fn local_errors_text(scene: &Scene, drawn: &Buffers) -> String {
    let errors = variants::local_errors(scene, drawn);
    if errors.is_empty() {
        return "\ntransparency: every cell matches the correct back-to-front blend\n".to_string();
    }
    let mut table = Table::new();
    table.load_style(presets::ASCII_MARKDOWN).set_header([
        "x",
        "y",
        "drawn",
        "back to front",
        "polygons there, back to front",
    ]);
    for e in &errors {
        let order: Vec<String> = e.back_to_front.iter().map(|&i| polygon_name(scene, i)).collect();
        table.add_row([e.x.to_string(), e.y.to_string(), e.drawn.to_string(), e.correct.to_string(), order.join(", ")]);
    }
    format!(
        "\ntransparency: {} cells differ from the correct back-to-front blend (the local errors of drawing in the wrong order: a polygon behind a transparent one, drawn after it, fails the depth test):\n{table}\n",
        errors.len()
    )
}
