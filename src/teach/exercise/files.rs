//! An exercise's files, all made before any is written: the scene, the
//! answer key (after the last polygon, and with `each_polygon` after each),
//! the worksheet and the solution in each format asked for, and the notes
//! the teacher reads.

use std::path::Path;

use crate::error::Error;
use crate::observe::render::figure::{Annotations, Shading, svg_with};
use crate::observe::render::picture::{Format, Paper};
use crate::observe::render::report::matrix;
use crate::simulate::events::Unobserved;
use crate::simulate::simulation::Simulation;
use crate::words::Lang;

use super::{Exercise, Spec};

/// The files of an exercise, in the order they are listed, and its notes.
#[derive(Debug, Clone)]
pub struct ExerciseFiles {
    /// Each file's name in the exercise's folder and its bytes.
    pub files: Vec<(String, Vec<u8>)>,
    /// The notes (also the file `exercise.txt`).
    pub notes: String,
}

/// Every file of `exercise` for the folder `dir`: the worksheet and the
/// solution in each of `formats`, in `lang` (they are handed to students).
pub fn files(
    lang: Lang,
    exercise: &Exercise,
    spec: &Spec,
    formats: &[Format],
    each_polygon: bool,
    dir: &Path,
) -> Result<ExerciseFiles, Error> {
    let mut files: Vec<(String, Vec<u8>)> = vec![("scene.json".to_string(), exercise.json.as_bytes().to_vec())];
    let scene = &exercise.scene;
    let last = scene.polygons.len() - 1;
    let mut simulation = Simulation::new(scene);
    while let Some(index) = simulation.draw_next(&mut Unobserved) {
        if each_polygon && index < last {
            for (kind, text) in answers(&simulation) {
                files.push((format!("answer.after-{}.{kind}.txt", index + 1), text.into_bytes()));
            }
        }
    }
    for (kind, text) in answers(&simulation) {
        files.push((format!("answer.{kind}.txt"), text.into_bytes()));
    }
    let seed = spec.seed.to_string();
    let title = words!(
        lang,
        "exercise-title",
        seed = &seed,
        width = scene.width,
        height = scene.height,
        count = scene.polygons.len()
    );
    let caption =
        vec![words!(lang, "exercise-task-draw", max = scene.depth_max()), words!(lang, "exercise-task-write")];
    let blank = Simulation::new(scene);
    let extras = Annotations { vertex_labels: true, caption, values: false };
    let worksheet = svg_with(lang, scene, blank.buffers(), last, Shading::Frame, &title, &extras);
    files.extend(figure_files(lang, "worksheet", &worksheet, formats, dir)?);
    let title = words!(lang, "exercise-solution-title", seed = &seed);
    let extras = Annotations { vertex_labels: true, caption: Vec::new(), values: true };
    let solution = svg_with(lang, scene, simulation.buffers(), last, Shading::Frame, &title, &extras);
    files.extend(figure_files(lang, "solution", &solution, formats, dir)?);
    let notes = notes(lang, exercise, spec, dir);
    files.push(("exercise.txt".to_string(), notes.as_bytes().to_vec()));
    Ok(ExerciseFiles { files, notes })
}

/// A figure's SVG in each format asked for: `(NAME.ext, bytes)`.
fn figure_files(
    lang: Lang,
    name: &str,
    svg: &str,
    formats: &[Format],
    dir: &std::path::Path,
) -> Result<Vec<(String, Vec<u8>)>, Error> {
    let mut files: Vec<(String, Vec<u8>)> = Vec::new();
    for format in formats {
        // Beside zsim's PDF, the TeX source is NAME-tikz.tex: pdflatex on it writes NAME-tikz.pdf.
        let beside_pdf = *format == Format::Tex && formats.contains(&Format::Pdf);
        let file = format!("{name}{}.{}", if beside_pdf { "-tikz" } else { "" }, format.extension());
        if !files.iter().any(|(f, _)| *f == file) {
            let bytes = format.encode(lang, svg, &dir.join(&file), false, (None, Paper::default()))?;
            files.push((file, bytes));
        }
    }
    Ok(files)
}

/// The framebuffer and the z-buffer as `zsim check` reads them.
fn answers(simulation: &Simulation<'_>) -> [(&'static str, String); 2] {
    let buffers = simulation.buffers();
    let depth = buffers.depth_level_rows().expect("exercises keep a quantized z-buffer");
    [("frame", matrix(&buffers.frame_rows(), false)), ("depth", matrix(&depth, false))]
}

/// What the teacher reads: the settings, the cases asked for and found, and where.
fn notes(lang: Lang, exercise: &Exercise, spec: &Spec, dir: &Path) -> String {
    let scene = &exercise.scene;
    let asked: Vec<&str> = spec.hard.iter().map(|c| c.name()).collect();
    let mut text = words!(
        lang,
        "exercise-notes-settings",
        seed = spec.seed.to_string(),
        width = scene.width.to_string(),
        height = scene.height.to_string(),
        polygons = scene.polygons.len().to_string(),
        frame_bits = scene.frame_bits.to_string(),
        depth_bits = scene.depth_bits.to_string(),
        max = scene.depth_max().to_string(),
        test = scene.depth_test.local_name(lang)
    ) + "\n";
    let asked = if asked.is_empty() { words!(lang, "exercise-notes-no-case") } else { asked.join(", ") };
    let line = words!(lang, "exercise-notes-asked", asked = asked, candidate = exercise.tries.to_string());
    text.push_str(&format!("{line}\n{}\n", words!(lang, "exercise-notes-contains")));
    if exercise.found.is_empty() {
        text.push_str(&format!("  {}\n", words!(lang, "exercise-notes-none")));
    }
    for found in &exercise.found {
        text.push_str(&format!("  {}: {}\n", found.case, found.place));
    }
    let scene_path = dir.join("scene.json");
    let line = words!(lang, "exercise-notes-next", path = crate::words::shown_path(&scene_path));
    text.push_str(&format!("{line}\n"));
    text
}
