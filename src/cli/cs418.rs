//! `zsim cs418`: UIUC CS 418's rasterizer cases: run, compare, import.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::{Args, Subcommand, ValueEnum};
use zsim::cs418::{self, Arithmetic};

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
            let scene =
                zsim::cs418::import::scene_json(&cs418::report::load(case, cs418::report::Textures::Ignored)?.case)
                    .map_err(|e| e.in_file(case))?;
            super::emit_or_write(lang, out, output.as_deref(), &scene, &[case])?;
            Ok(Finish::Ok)
        }
    }
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
    let cs418::report::LoadedCase { case, textures } = cs418::report::load(path, cs418::report::Textures::Read)?;
    let arithmetic = match arith {
        Arith::DdaF64 => Arithmetic::DdaF64,
        Arith::Exact => Arithmetic::Exact,
    };
    // The case, its textures and the reference are the inputs no output may replace.
    let mut plan = zsim::Plan::new(&[path], zsim::Replace::Allowed);
    for (_, identity) in textures {
        plan.input(identity);
    }
    let reference = match compare {
        Some(png) => {
            let (image, identity) = cs418::report::reference(png)?;
            if let Some(identity) = identity {
                plan.input(identity);
            }
            Some((png, image))
        }
        None => None,
    };
    // In exact arithmetic the course's own floats are drawn too, to say where
    // they disagree: both at once, on two cores.
    let (result, course) = rayon::join(
        || cs418::render(&case, arithmetic),
        || (arithmetic == Arithmetic::Exact).then(|| cs418::render(&case, Arithmetic::DdaF64)),
    );
    let result = result.map_err(|e| e.in_file(path))?;
    let written = output.join(&case.output);
    plan.file(&written, result.image.to_png());
    plan.write()?;
    let mut text = zsim::words!(
        lang,
        "cs418-run-summary",
        path = zsim::shown_path(path),
        width = case.width.to_string(),
        height = case.height.to_string(),
        arithmetic = arithmetic.name(),
        features = cs418::report::features_text(&case),
        written = zsim::shown_path(&written)
    ) + "\n";
    if let Some(course) = course {
        text.push_str(&cs418::report::disagreements_text(lang, &course.map_err(|e| e.in_file(path))?, &result));
    }
    let mut finish = Finish::Ok;
    if let Some((png, image)) = reference {
        let (compared, differs) = cs418::report::compare_text(lang, png, &image, &result.image, tolerance)?;
        text.push_str(&compared);
        if differs {
            finish = Finish::Differs;
        }
    }
    emit(out, &text)?;
    Ok(finish)
}
