//! `zsim tinyrenderer`: tinyrenderer's z-buffer lesson: run a model as the
//! lesson does (its two TGA images), or import it as a zsim scene.

use std::io::Write;
use std::path::PathBuf;

use clap::{Args, Subcommand, ValueEnum};
use zsim::tinyrenderer::{self, SIZE};

use super::{Failure, Finish, emit};

/// Arguments of `zsim tinyrenderer`.
#[derive(Debug, Args)]
pub struct TinyrendererArgs {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Draw a model as the lesson's program does: zbuffer.tga and framebuffer.tga into OUT_DIR.
    Run {
        /// The model (an OBJ file: v and f lines are read, others passed over).
        model: PathBuf,
        /// The folder to write into; no file in it is replaced.
        #[arg(short, long, value_name = "OUT_DIR")]
        output: PathBuf,
        /// The lesson's f64 arithmetic, or exact, which also lists the pixels where the two differ.
        #[arg(long, value_enum, default_value_t = LessonArith::F64)]
        arith: LessonArith,
        /// Write the TGA files without run-length encoding (types 2 and 3 instead of 10 and 11).
        #[arg(long)]
        uncompressed: bool,
        /// The image's side in pixels (the lesson's is 800).
        #[arg(long, default_value_t = SIZE, value_parser = |text: &str| side(super::language_of_the_run(), text))]
        size: i64,
    },
    /// Print the model as a zsim scene under the lesson's rules, for run, explain, step, check and figure.
    Import {
        /// The model (an OBJ file).
        model: PathBuf,
        /// Project the vertices in the lesson's f64 or exactly.
        #[arg(long, value_enum, default_value_t = LessonArith::F64)]
        arith: LessonArith,
        /// Write the scene to this file instead of standard output.
        #[arg(short, long, value_name = "FILE")]
        output: Option<PathBuf>,
        /// The raster's side in pixels: the lesson's 800, or a small one (32, 48) to step through by hand.
        #[arg(long, default_value_t = SIZE, value_parser = |text: &str| side(super::language_of_the_run(), text))]
        size: i64,
    },
}

fn side(lang: zsim::Lang, text: &str) -> Result<i64, String> {
    match text.parse::<i64>() {
        Ok(n) if tinyrenderer::SIDES.contains(&n) => Ok(n),
        _ => Err(zsim::words!(
            lang,
            "usage-tinyrenderer-size",
            text = zsim::printable(&zsim::token(lang, text)).into_owned(),
            min = *tinyrenderer::SIDES.start(),
            max = *tinyrenderer::SIDES.end()
        )),
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum LessonArith {
    /// The lesson's arithmetic: f64, as its C++ computes.
    F64,
    /// Exact fractions.
    Exact,
}

impl LessonArith {
    fn lesson(self) -> tinyrenderer::LessonArith {
        match self {
            LessonArith::F64 => tinyrenderer::LessonArith::F64,
            LessonArith::Exact => tinyrenderer::LessonArith::Exact,
        }
    }
}

pub fn run(lang: zsim::Lang, args: &TinyrendererArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    match &args.command {
        Command::Run { model, output, arith, uncompressed, size } => {
            let loaded = tinyrenderer::load(model)?;
            let drawn = tinyrenderer::render(&loaded, arith.lesson(), *size);
            let side = *size as u16;
            let frame: Vec<u8> = drawn.framebuffer.iter().flatten().copied().collect();
            let files = [
                ("zbuffer.tga".to_string(), tinyrenderer::tga(side, side, 1, &drawn.zbuffer, !uncompressed)),
                ("framebuffer.tga".to_string(), tinyrenderer::tga(side, side, 3, &frame, !uncompressed)),
            ];
            zsim::write_fresh(output, &files, &[model.as_path()])?;
            let drawn_faces = loaded.faces.len() - drawn.skipped;
            let mut text = format!(
                "{}\n",
                zsim::words!(
                    lang,
                    "tinyrenderer-run",
                    model = zsim::shown_path(model),
                    faces = loaded.faces.len(),
                    skipped = drawn.skipped,
                    drawn = drawn_faces,
                    folder = zsim::shown_path(output)
                )
            );
            if *arith == LessonArith::Exact {
                text.push_str(&tinyrenderer::differences_text(lang, &loaded, &drawn, *size));
            }
            emit(out, &text)?;
            Ok(Finish::Ok)
        }
        Command::Import { model, arith, output, size } => {
            let scene = tinyrenderer::scene_json(&tinyrenderer::load(model)?, arith.lesson(), *size);
            super::emit_or_write(lang, out, output.as_deref(), &scene, &[model])?;
            Ok(Finish::Ok)
        }
    }
}
