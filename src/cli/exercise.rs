//! `zsim exercise`: a new exercise in the book's style, with its worksheet
//! and answer key, repeatable from its seed.

use std::io::Write;
use std::path::PathBuf;

use clap::Args;
use zsim::Error;
use zsim::exercise::{HardCase, Spec, make};
use zsim::picture::Format;

use super::{Failure, Finish, emit};

/// Arguments of `zsim exercise`.
#[derive(Debug, Args)]
pub struct ExerciseArgs {
    /// Seed: the same seed (and options) gives byte-identical files. With --roster, the course's seed, which every student's seed comes from.
    #[arg(long, default_value_t = 1)]
    pub(super) seed: u64,
    /// A variant for each student of this roster (Moodle, Canvas, Gradescope or PrairieLearn export, or one identity a line): the manifest DIR/variants.json, the keys, one folder per student under DIR/students.
    #[arg(long, value_name = "FILE")]
    pub(super) roster: Option<PathBuf>,
    /// With --roster: the column that names the students (its header, e.g. "ID number"); default: Email address (Moodle), SIS Login ID (Canvas), Email (Gradescope), UID (PrairieLearn).
    #[arg(long, value_name = "COLUMN", requires = "roster")]
    pub(super) identity: Option<String>,
    /// With --roster: how many times each --hard case arises in every variant (the polygons it arises in; pairs for intersecting).
    #[arg(long, default_value_t = 1, requires = "roster")]
    pub(super) times: usize,
    /// With --roster: the fewest cells in which each wrong rule's answer differs from every variant's key.
    #[arg(long, default_value_t = 3, requires = "roster")]
    pub(super) distinct: usize,
    /// With --roster: the wrong rules every variant tells apart, comma-separated (default: truncated, half-down, reversed, one-early, last-only, bottom-first, corners, cell-rule, and no-saturation with --hard saturation).
    #[arg(long, value_name = "LIST", requires = "roster")]
    pub(super) rules: Option<String>,
    /// With --roster: give this student (identity) a new variant; name them again for another.
    #[arg(long, value_name = "ID", requires = "roster")]
    pub(super) reseed: Vec<String>,
    /// With --roster: what each student hands in, comma-separated: frame, depth.
    #[arg(long, value_name = "LIST", default_value = "frame,depth", requires = "roster")]
    pub(super) hand_in: String,
    /// With --roster: the playground's address; each student's hand-in.txt gets their own link (their scene, the quiz on).
    #[arg(long, value_name = "URL", requires = "roster")]
    pub(super) site: Option<String>,
    /// With --roster: also write a PrairieLearn question into this folder (info.json, question.html, server.py, the external grader in tests/).
    #[arg(long, value_name = "DIR", requires = "roster")]
    pub(super) prairielearn: Option<PathBuf>,
    /// Raster size, WxH (4 … 64 each).
    #[arg(long, default_value = "16x16", value_parser = parse_size)]
    pub(super) size: (u32, u32),
    /// How many polygons (1 … 8).
    #[arg(long, default_value_t = 2)]
    pub(super) polygons: usize,
    /// Framebuffer bits (1 … 8).
    #[arg(long, default_value_t = 2)]
    pub(super) frame_bits: u32,
    /// z-buffer bits (1 … 16).
    #[arg(long, default_value_t = 4)]
    pub(super) depth_bits: u32,
    /// Cases the exercise must contain, comma-separated: vertex-on-scanline, centre-on-edge, half-depth, saturation, hidden, intersecting, concave.
    #[arg(long, value_name = "LIST")]
    pub(super) hard: Option<String>,
    /// How the polygons may look: book (each covers at least --min-pixels centres, every depth within the z-buffer's range unless saturation is asked for) or free (slivers and negative depths allowed).
    #[arg(long, value_enum, default_value_t = StyleArg::Book)]
    pub(super) style: StyleArg,
    /// With --style book: the fewest pixel centres each polygon covers.
    #[arg(long, default_value_t = 12)]
    pub(super) min_pixels: u32,
    /// The formats of the worksheet and the solution, comma-separated: svg, png, pdf, tex (TikZ in a LaTeX document).
    #[arg(long, value_name = "LIST", default_value = "svg", value_delimiter = ',', value_parser = super::choice(&Format::NAMES, Format::parse))]
    pub(super) formats: Vec<Format>,
    /// Also write the answer after each polygon (answer.after-N.frame.txt, …).
    #[arg(long)]
    pub(super) each_polygon: bool,
    /// The folder to write into (made if need be).
    #[arg(short, long, value_name = "DIR")]
    pub(super) output: PathBuf,
    /// Also write a Gradescope autograder into this folder (setup.sh, run_autograder, scene.json; zip its files with zsim's .deb beside them).
    #[arg(long, value_name = "DIR")]
    pub(super) gradescope: Option<PathBuf>,
    /// With --gradescope: who sees the results.
    #[arg(long, default_value = "visible", requires = "gradescope", value_parser = super::choice(&zsim::gradescope::Visibility::NAMES, zsim::gradescope::Visibility::parse))]
    pub(super) visibility: zsim::gradescope::Visibility,
    /// With --gradescope: the points the exercise is worth.
    #[arg(long, default_value_t = 100, requires = "gradescope", value_parser = clap::value_parser!(u32).range(1..=i64::from(zsim::gradescope::MAX_POINTS)))]
    pub(super) points: u32,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub(super) enum StyleArg {
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
    let spec = spec(args)?;
    let exercise = make(lang, &spec).map_err(Error::from)?;
    let dir = &args.output;
    // Everything is made first and written at the end, replacing nothing.
    let made = zsim::exercise::files::files(lang, &exercise, &spec, &args.formats, args.each_polygon, dir)?;
    let (files, notes) = (made.files, made.notes);
    let written: Vec<String> = files.iter().map(|(name, _)| name.clone()).collect();
    // Both folders are planned whole, and nothing is written when one file is refused.
    let mut plan = zsim::Plan::new(&[], zsim::Replace::Never);
    for (name, bytes) in files {
        plan.file(dir.join(name), bytes);
    }
    let mut text = format!(
        "{notes}{}\n",
        zsim::words!(lang, "file-written-in", files = written.join(", "), path = zsim::shown_path(dir))
    );
    if let Some(folder) = &args.gradescope {
        if zsim::same_folder(folder, dir) {
            return Err(Error::from(zsim::OutputRefused::IsInput { folder: folder.clone() }).into());
        }
        let expect = if args.each_polygon { zsim::check::Expect::Each } else { zsim::check::Expect::Final };
        let grading = zsim::gradescope::Autograde { visibility: args.visibility, points: args.points };
        let files = zsim::gradescope::autograder(&exercise.json, &expect, grading, lang);
        let names: Vec<&str> = files.iter().map(|(name, _)| name.as_str()).collect();
        let line = zsim::words!(lang, "file-written-in", files = names.join(", "), path = zsim::shown_path(folder));
        text.push_str(&format!("{line}\n"));
        for (name, bytes) in files {
            // Gradescope runs setup.sh and run_autograder as they are.
            if ["setup.sh", "run_autograder"].contains(&name.as_str()) {
                plan.executable(folder.join(name), bytes);
            } else {
                plan.file(folder.join(name), bytes);
            }
        }
    }
    plan.write()?;
    emit(out, &text)?;
    Ok(Finish::Ok)
}

/// The exercise the flags ask for (with --roster, each variant's; its seed the course's).
pub(super) fn spec(args: &ExerciseArgs) -> Result<Spec, Error> {
    Ok(Spec {
        seed: args.seed,
        width: args.size.0,
        height: args.size.1,
        polygons: args.polygons,
        frame_bits: args.frame_bits,
        depth_bits: args.depth_bits,
        hard: HardCase::parse_list(args.hard.as_deref().unwrap_or(if args.roster.is_some() {
            zsim::course::fair::CLASS_HARD
        } else {
            ""
        }))?,
        style: match args.style {
            StyleArg::Book => zsim::exercise::Style::Book,
            StyleArg::Free => zsim::exercise::Style::Free,
        },
        min_pixels: args.min_pixels,
    })
}
