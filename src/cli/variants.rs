//! `zsim run` with another loop order, a segmented z-buffer or antialiasing,
//! and the transparency report.

use std::io::Write;

use zsim::Buffers;
use zsim::Scene;
use zsim::Simulation;
use zsim::Unobserved;
use zsim::antialias;
use zsim::report::{self, MatrixStyle};
use zsim::variant_report;
use zsim::variants::{self, Inside, Segments};

use super::{Failure, Finish, emit, json_line};

/// What `run` was asked for besides the plain z-buffer.
pub struct RunVariant {
    pub segments: Option<Segments>,
    pub pixel_order: Option<Inside>,
    pub axes: bool,
    pub json: bool,
    pub final_only: bool,
}

pub fn run(
    lang: zsim::Lang,
    scene: &Scene,
    path: &str,
    variant: &RunVariant,
    out: &mut dyn Write,
) -> Result<Finish, Failure> {
    let last_name = scene.polygons.last().map_or(String::new(), |p| p.name.clone());
    let mut plain = Simulation::new(scene);
    plain.finish(&mut Unobserved);
    let style = MatrixStyle { axes: variant.axes, color: super::use_color(), ..MatrixStyle::default() };
    let mut text = report::scene_header(lang, scene, path);
    if let Some(segments) = variant.segments {
        let (buffers, stats) = variants::run_segmented(scene, segments);
        if variant.json {
            emit(out, &json_line(&variant_report::buffers_json(scene, &last_name, &buffers)))?;
            return Ok(Finish::Ok);
        }
        for line in variant_report::segmented_lines(lang, scene, segments, &stats) {
            text.push_str(&format!("{line}\n"));
        }
        text.push_str(&format!("{}\n", variant_report::comparison_text(lang, &buffers, plain.buffers())));
        text.push_str(&variant_report::matrices_text(lang, &buffers, &style));
    } else if let Some(inside) = variant.pixel_order {
        let (buffers, differences) = variants::run_pixel_order(scene, inside);
        if variant.json {
            emit(out, &json_line(&variant_report::buffers_json(scene, &last_name, &buffers)))?;
            return Ok(Finish::Ok);
        }
        text.push_str(&format!("{}\n", variant_report::pixel_order_heading(lang, inside)));
        text.push_str(&format!("{}\n", variant_report::comparison_text(lang, &buffers, plain.buffers())));
        if let Some(listed) = variant_report::pixel_order_disagreements(lang, scene, &differences) {
            text.push_str(&format!("{}\n{}\n", listed.line.clone(), super::table(listed)));
        }
        text.push_str(&variant_report::matrices_text(lang, &buffers, &style));
    } else {
        let settings = scene.effects.antialias.expect("run only sends antialiased scenes here");
        let pictures = antialias::run(scene, settings)?;
        if variant.json {
            emit(out, &json_line(&variant_report::antialias_json(scene, &pictures, variant.final_only)))?;
            return Ok(Finish::Ok);
        }
        text.push_str(&variant_report::antialias_text(lang, scene, settings, &pictures, (&style, variant.final_only)));
    }
    emit(out, &text)?;
    Ok(Finish::Ok)
}

/// The cells where drawing order with opacity differs from the back-to-front blend.
pub fn local_errors_text(lang: zsim::Lang, scene: &Scene, drawn: &Buffers) -> String {
    match variant_report::local_errors(lang, scene, drawn) {
        Err(all_match) => format!("\n{all_match}\n"),
        Ok(listed) => format!("\n{}\n{}\n", listed.line.clone(), super::table(listed)),
    }
}
