//! `zsim exercise`: a new exercise in the book's style, with its worksheet
//! and answer key, repeatable from its seed.

use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use zsim::Error;
use zsim::Simulation;
use zsim::Unobserved;
use zsim::exercise::{Exercise, HardCase, Spec, make};
use zsim::figure::{Extras, Shading, svg_with};
use zsim::picture::Format;
use zsim::report::matrix;

use super::{Failure, Finish, emit};

/// Arguments of `zsim exercise`.
#[derive(Debug, Args)]
pub struct ExerciseArgs {
    /// Seed: the same seed (and options) gives byte-identical files.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Raster size, WxH (4 … 64 each).
    #[arg(long, default_value = "16x16", value_parser = parse_size)]
    size: (u32, u32),
    /// How many polygons (1 … 8).
    #[arg(long, default_value_t = 2)]
    polygons: usize,
    /// Framebuffer bits (1 … 8).
    #[arg(long, default_value_t = 2)]
    frame_bits: u32,
    /// z-buffer bits (1 … 16).
    #[arg(long, default_value_t = 4)]
    depth_bits: u32,
    /// Cases the exercise must contain, comma-separated: vertex-on-scanline, centre-on-edge, half-depth, saturation, hidden, intersecting, concave.
    #[arg(long, value_name = "LIST")]
    hard: Option<String>,
    /// How the polygons may look: book (each covers at least --min-pixels centres, every depth within the z-buffer's range unless saturation is asked for) or free (slivers and negative depths allowed).
    #[arg(long, value_enum, default_value_t = StyleArg::Book)]
    style: StyleArg,
    /// With --style book: the fewest pixel centres each polygon covers.
    #[arg(long, default_value_t = 12)]
    min_pixels: u32,
    /// The formats of the worksheet and the solution, comma-separated: svg, png, pdf, tex (TikZ in a LaTeX document).
    #[arg(long, value_name = "LIST", default_value = "svg", value_delimiter = ',', value_parser = super::choice(&Format::NAMES, Format::parse))]
    formats: Vec<Format>,
    /// Also write the answer after each polygon (answer.after-N.frame.txt, …).
    #[arg(long)]
    each_polygon: bool,
    /// The folder to write into (made if need be).
    #[arg(short, long, value_name = "DIR")]
    output: PathBuf,
    /// Also write a Gradescope autograder into this folder (setup.sh, run_autograder, scene.json; zip its files with zsim's .deb beside them).
    #[arg(long, value_name = "DIR")]
    gradescope: Option<PathBuf>,
    /// With --gradescope: who sees the results.
    #[arg(long, default_value = "visible", requires = "gradescope", value_parser = super::choice(&zsim::gradescope::Visibility::NAMES, zsim::gradescope::Visibility::parse))]
    visibility: zsim::gradescope::Visibility,
    /// With --gradescope: the points the exercise is worth.
    #[arg(long, default_value_t = 100, requires = "gradescope")]
    points: u32,
}

/// A figure's SVG in each format asked for: `(NAME.ext, bytes)`.
fn figure_files(
    lang: zsim::Lang,
    name: &str,
    svg: &str,
    formats: &[Format],
    dir: &std::path::Path,
) -> Result<Vec<(String, Vec<u8>)>, Error> {
    let mut files: Vec<(String, Vec<u8>)> = Vec::new();
    for format in formats {
        let file = format!("{name}.{}", format.extension());
        if !files.iter().any(|(f, _)| *f == file) {
            let bytes = format.encode(lang, svg, &dir.join(&file), false)?;
            files.push((file, bytes));
        }
    }
    Ok(files)
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum StyleArg {
    /// Like the book's example.
    Book,
    /// Any polygons that contain the asked cases.
    Free,
}

fn parse_size(text: &str) -> Result<(u32, u32), String> {
    text.split_once(['x', '×'])
        .and_then(|(w, h)| Some((w.trim().parse().ok()?, h.trim().parse().ok()?)))
        .ok_or_else(|| format!("\"{text}\" is not a size: write WxH, e.g. 16x16"))
}

pub fn run(lang: zsim::Lang, args: &ExerciseArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let spec = Spec {
        seed: args.seed,
        width: args.size.0,
        height: args.size.1,
        polygons: args.polygons,
        frame_bits: args.frame_bits,
        depth_bits: args.depth_bits,
        hard: HardCase::parse_list(args.hard.as_deref().unwrap_or("")).map_err(Error::from)?,
        style: match args.style {
            StyleArg::Book => zsim::exercise::Style::Book,
            StyleArg::Free => zsim::exercise::Style::Free,
        },
        min_pixels: args.min_pixels,
    };
    let exercise = make(lang, &spec).map_err(Error::from)?;
    let dir = &args.output;
    // Everything is made first and written at the end, replacing nothing.
    let mut files: Vec<(String, Vec<u8>)> = Vec::new();
    let mut write = |name: &str, text: &str| -> Result<(), Error> {
        files.push((name.to_string(), text.as_bytes().to_vec()));
        Ok(())
    };
    write("scene.json", &exercise.json)?;
    let scene = &exercise.scene;
    let last = scene.polygons.len() - 1;
    let mut simulation = Simulation::new(scene);
    let mut written = vec!["scene.json".to_string()];
    while let Some(index) = simulation.draw_next(&mut Unobserved) {
        if args.each_polygon && index < last {
            for (kind, text) in answers(&simulation) {
                let name = format!("answer.after-{}.{kind}.txt", index + 1);
                write(&name, &text)?;
                written.push(name);
            }
        }
    }
    for (kind, text) in answers(&simulation) {
        let name = format!("answer.{kind}.txt");
        write(&name, &text)?;
        written.push(name);
    }
    // The worksheet and the solution are handed to students: in their language.
    let seed = args.seed.to_string();
    let worksheet = svg_with(
        lang,
        scene,
        Simulation::new(scene).buffers(),
        last,
        Shading::Frame,
        &zsim::words!(
            lang,
            "exercise-title",
            seed = &seed,
            width = scene.width,
            height = scene.height,
            count = scene.polygons.len()
        ),
        &Extras {
            vertex_labels: true,
            caption: vec![
                zsim::words!(lang, "exercise-task-draw", max = scene.depth_max()),
                zsim::words!(lang, "exercise-task-write"),
            ],
            values: false,
        },
    );
    let mut figures = figure_files(lang, "worksheet", &worksheet, &args.formats, dir)?;
    let solution = svg_with(
        lang,
        scene,
        simulation.buffers(),
        last,
        Shading::Frame,
        &zsim::words!(lang, "exercise-solution-title", seed = &seed),
        &Extras { vertex_labels: true, caption: Vec::new(), values: true },
    );
    figures.extend(figure_files(lang, "solution", &solution, &args.formats, dir)?);
    written.extend(figures.iter().map(|(name, _)| name.clone()));
    let notes = notes(lang, &exercise, &spec, args);
    write("exercise.txt", &notes)?;
    written.push("exercise.txt".into());
    files.extend(figures);
    super::write_fresh(dir, &files, &[])?;
    let line = zsim::words!(lang, "file-written-in", files = written.join(", "), path = dir.display().to_string());
    emit(out, &format!("{notes}{line}\n"))?;
    if let Some(folder) = &args.gradescope {
        let files = zsim::gradescope::autograder(&exercise.json, args.visibility, args.points, lang);
        super::write_fresh(folder, &files, &[dir.as_path()])?;
        for script in ["setup.sh", "run_autograder"] {
            executable(&folder.join(script))?;
        }
        let names: Vec<&str> = files.iter().map(|(name, _)| name.as_str()).collect();
        let line = zsim::words!(lang, "file-written-in", files = names.join(", "), path = folder.display().to_string());
        emit(out, &format!("{line}\n"))?;
    }
    Ok(Finish::Ok)
}

/// Marks a script zsim wrote as executable (Gradescope runs `run_autograder` as is).
fn executable(path: &std::path::Path) -> Result<(), Error> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(path, std::fs::Permissions::from_mode(0o755))
            .map_err(|source| Error::Write { path: path.to_owned(), source })?;
    }
    Ok(())
}

/// The framebuffer and the z-buffer as `zsim check` reads them.
fn answers(simulation: &Simulation<'_>) -> [(&'static str, String); 2] {
    let buffers = simulation.buffers();
    let depth = buffers.depth_level_rows().expect("exercises keep a quantized z-buffer");
    [("frame", matrix(&buffers.frame_rows(), false)), ("depth", matrix(&depth, false))]
}

/// What the teacher reads: the settings, the cases asked for and found, and where.
fn notes(lang: zsim::Lang, exercise: &Exercise, spec: &Spec, args: &ExerciseArgs) -> String {
    let scene = &exercise.scene;
    let asked: Vec<&str> = spec.hard.iter().map(|c| c.name()).collect();
    let mut text = zsim::words!(
        lang,
        "exercise-notes-settings",
        seed = spec.seed.to_string(),
        width = scene.width.to_string(),
        height = scene.height.to_string(),
        polygons = scene.polygons.len().to_string(),
        frame_bits = scene.frame_bits.to_string(),
        depth_bits = scene.depth_bits.to_string(),
        max = scene.depth_max().to_string()
    ) + "\n";
    let asked = if asked.is_empty() { zsim::words!(lang, "exercise-notes-no-case") } else { asked.join(", ") };
    let line = zsim::words!(lang, "exercise-notes-asked", asked = asked, candidate = exercise.tries.to_string());
    text.push_str(&format!("{line}\n{}\n", zsim::words!(lang, "exercise-notes-contains")));
    if exercise.found.is_empty() {
        text.push_str(&format!("  {}\n", zsim::words!(lang, "exercise-notes-none")));
    }
    for found in &exercise.found {
        text.push_str(&format!("  {}: {}\n", found.case, found.place));
    }
    let scene_path = args.output.join("scene.json");
    let line = zsim::words!(lang, "exercise-notes-next", path = scene_path.display().to_string());
    text.push_str(&format!("{line}\n"));
    text
}
