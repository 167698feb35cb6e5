//! `zsim cs418`: UIUC CS 418's rasterizer cases: run, compare, import.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::{Args, Subcommand, ValueEnum};
use zsim::Error;
use zsim::cs418::{self, Arithmetic, Case, Comparison, Image, Reason};

use super::{Failure, Finish, emit};

/// Arguments of `zsim cs418`.
#[derive(Debug, Args)]
pub struct Cs418Args {
    #[command(subcommand)]
    command: Cs418Command,
}

#[derive(Debug, Subcommand)]
enum Cs418Command {
    /// Run a case: write the PNG its first line names into OUT_DIR.
    Run {
        /// The case file (rast-*.txt).
        case: PathBuf,
        /// The folder to write into.
        #[arg(short, long, value_name = "OUT_DIR")]
        output: PathBuf,
        /// The arithmetic: the course's f64 DDA (its reference images), or
        /// exact, which also lists the samples where the two disagree and why.
        #[arg(long, value_enum, default_value = "dda-f64")]
        arith: Arith,
        /// Compare the image with this PNG (the course's reference or a
        /// student's); exit 1 when a channel differs by more than --tolerance.
        #[arg(long, value_name = "PNG")]
        compare: Option<PathBuf>,
        /// Largest difference per channel that --compare accepts.
        #[arg(long, default_value_t = 1)]
        tolerance: u8,
    },
    /// Print what the case draws as a zsim scene (gpu rules, the course's
    /// samples on zsim's pixel centres, each polygon's value its primitive's
    /// number), for run, step, explain, check and figure. Textures change no
    /// sample's primitive, so their files are not read.
    Import {
        /// The case file.
        case: PathBuf,
        /// Write the scene to this file instead of standard output.
        #[arg(short, long, value_name = "FILE")]
        output: Option<PathBuf>,
    },
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Arith {
    /// The course's arithmetic: f64 throughout, the DDA stepped by adding.
    #[value(name = "dda-f64")]
    DdaF64,
    /// Exact rationals; reports where the course's floats differ.
    Exact,
}

pub fn run(lang: zsim::Lang, args: &Cs418Args, out: &mut dyn Write) -> Result<Finish, Failure> {
    match &args.command {
        Cs418Command::Run { case, output, arith, compare, tolerance } => {
            run_case(lang, case, output, *arith, compare.as_deref(), *tolerance, out)
        }
        Cs418Command::Import { case, output } => {
            let scene = zsim::cs418::import::scene_json(lang, &load(lang, case, Textures::Ignored)?)
                .map_err(|e| located(case, e))?;
            super::emit_or_write(lang, out, output.as_deref(), &scene, &[case])?;
            Ok(Finish::Ok)
        }
    }
}

fn located(path: &Path, error: cs418::CaseError) -> Error {
    Error::SceneFormat {
        path: path.to_owned(),
        location: error.line.map_or(String::new(), |line| format!("line {line}")),
        message: error.message,
    }
}

/// Whether a case's texture files are read.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Textures {
    /// Read from beside the case: the image needs them.
    Read,
    /// Not read (each stands in as one transparent texel): what is drawn
    /// where does not depend on them.
    Ignored,
}

fn load(lang: zsim::Lang, path: &Path, textures: Textures) -> Result<Case, Error> {
    let text = zsim::read_text(lang, path)?;
    let folder = path.parent().unwrap_or(Path::new("."));
    let texture = |name: &str| {
        if textures == Textures::Ignored {
            return Ok(Image { width: 1, height: 1, rgba: vec![0; 4] });
        }
        let file = folder.join(name);
        if !file.is_file() {
            return Err(zsim::words!(lang, "cs418-texture-missing"));
        }
        let bytes =
            std::fs::read(&file).map_err(|e| zsim::words!(lang, "cs418-texture-unreadable", reason = e.to_string()))?;
        Image::from_png(lang, &bytes)
    };
    let case = Case::parse(lang, &text, &texture).map_err(|e| located(path, e))?;
    Ok(case)
}

fn run_case(
    lang: zsim::Lang,
    path: &Path,
    output: &Path,
    arith: Arith,
    compare: Option<&Path>,
    tolerance: u8,
    out: &mut dyn Write,
) -> Result<Finish, Failure> {
    let case = load(lang, path, Textures::Read)?;
    let arithmetic = match arith {
        Arith::DdaF64 => Arithmetic::DdaF64,
        Arith::Exact => Arithmetic::Exact,
    };
    let reference = match compare {
        Some(png) => {
            let bytes = std::fs::read(png).map_err(|source| Error::Read { path: png.to_owned(), source })?;
            let image =
                Image::from_png(lang, &bytes).map_err(|message| Error::Answer { path: png.to_owned(), message })?;
            Some((png, image))
        }
        None => None,
    };
    // In exact arithmetic the course's own floats are drawn too, to say where
    // they disagree: both at once, on two cores, messages in `lang`.
    let (result, course) = rayon::join(
        || cs418::render(lang, &case, arithmetic),
        || (arithmetic == Arithmetic::Exact).then(|| cs418::render(lang, &case, Arithmetic::DdaF64)),
    );
    let result = result.map_err(|e| located(path, e))?;
    std::fs::create_dir_all(output).map_err(|source| Error::Write { path: output.to_owned(), source })?;
    let written = output.join(&case.output);
    std::fs::write(&written, result.image.to_png()).map_err(|source| Error::Write { path: written.clone(), source })?;
    let mut text = zsim::words!(
        lang,
        "cs418-run-summary",
        path = path.display().to_string(),
        width = case.width.to_string(),
        height = case.height.to_string(),
        arithmetic = arithmetic.name(),
        features = features(&case),
        written = written.display().to_string()
    ) + "\n";
    if let Some(course) = course {
        text.push_str(&disagreements(lang, &course.map_err(|e| located(path, e))?, &result));
    }
    let mut finish = Finish::Ok;
    if let Some((png, image)) = reference {
        match cs418::compare_images(&result.image, &image, tolerance) {
            None => {
                return Err(Error::Answer {
                    path: png.to_owned(),
                    message: zsim::words!(
                        lang,
                        "cs418-image-size",
                        width = image.width.to_string(),
                        height = image.height.to_string(),
                        case_width = case.width.to_string(),
                        case_height = case.height.to_string()
                    ),
                }
                .into());
            }
            Some(difference) if difference.pixels.is_empty() => {
                let line = zsim::words!(
                    lang,
                    "cs418-compare-same",
                    path = png.display().to_string(),
                    tolerance = tolerance.to_string(),
                    largest = difference.largest.to_string()
                );
                text.push_str(&format!("{line}\n"));
            }
            Some(difference) => {
                finish = Finish::Differs;
                let line = zsim::words!(
                    lang,
                    "cs418-compare-differs",
                    path = png.display().to_string(),
                    count = difference.pixels.len(),
                    tolerance = tolerance.to_string(),
                    largest = difference.largest.to_string()
                );
                text.push_str(&format!("{line}\n"));
                for (x, y, ours, theirs) in difference.pixels.iter().take(20) {
                    let line = zsim::words!(
                        lang,
                        "cs418-compare-pixel",
                        x = x.to_string(),
                        y = y.to_string(),
                        ours = format!("{ours:?}"),
                        theirs = format!("{theirs:?}")
                    );
                    text.push_str(&format!("  {line}\n"));
                }
                if difference.pixels.len() > 20 {
                    let more =
                        zsim::words!(lang, "cs418-compare-more", count = (difference.pixels.len() - 20).to_string());
                    text.push_str(&format!("  {more}\n"));
                }
            }
        }
    }
    emit(out, &text)?;
    Ok(finish)
}

fn features(case: &Case) -> String {
    let f = case.features;
    let mut on: Vec<String> =
        [(f.depth, "depth"), (f.srgb, "sRGB"), (f.hyp, "hyp"), (f.cull, "cull"), (f.frustum, "frustum")]
            .into_iter()
            .filter(|(on, _)| *on)
            .map(|(_, name)| name.to_string())
            .collect();
    if f.fsaa > 1 {
        on.push(format!("fsaa {}", f.fsaa));
    }
    if on.is_empty() { String::new() } else { format!(", {}", on.join(", ")) }
}

/// The samples where the course's floats and exact arithmetic disagree, each with why.
fn disagreements(lang: zsim::Lang, course: &Comparison, exact: &Comparison) -> String {
    let cells = cs418::differences(course, exact);
    if cells.is_empty() {
        return zsim::words!(lang, "cs418-arith-alike") + "\n";
    }
    let mut text = zsim::words!(lang, "cs418-arith-disagree", count = cells.len()) + "\n";
    for cell in &cells {
        let place = if course.level > 1 {
            zsim::words!(
                lang,
                "cs418-place-sample",
                x = cell.x.to_string(),
                y = cell.y.to_string(),
                px = cell.pixel.0.to_string(),
                py = cell.pixel.1.to_string()
            )
        } else {
            zsim::words!(lang, "cs418-place-pixel", x = cell.x.to_string(), y = cell.y.to_string())
        };
        let why = match &cell.reason {
            Reason::Span { primitive, course, exact, course_covers } => {
                let span = |s: &Option<(String, String)>| match s {
                    Some((l, r)) => format!("[{l}, {r})"),
                    None => zsim::words!(lang, "cs418-no-span"),
                };
                let (inside, outside) = (zsim::words!(lang, "cs418-inside"), zsim::words!(lang, "cs418-outside"));
                let (course_side, exact_side) = if *course_covers { (inside, outside) } else { (outside, inside) };
                zsim::words!(
                    lang,
                    "cs418-why-span",
                    primitive = primitive.message(lang),
                    row = cell.y.to_string(),
                    course = span(course),
                    exact = span(exact),
                    x = cell.x.to_string(),
                    course_side = course_side,
                    exact_side = exact_side
                )
            }
            Reason::Depth { course, exact } => {
                let who = |p: &Option<cs418::Primitive>| {
                    p.as_ref().map_or_else(|| zsim::words!(lang, "cs418-nothing"), |p| p.message(lang))
                };
                zsim::words!(lang, "cs418-why-depth", course = who(course), exact = who(exact))
            }
        };
        text.push_str(&format!("  {place}: {why}\n"));
    }
    text
}
