//! `zsim buet`: BUET CSE 410 "Offline 2" cases: run, import, check.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::{Args, Subcommand, ValueEnum};
use comfy_table::{Table, presets};
use zsim::Simulation;
use zsim::buet::{self, Case, Source};

use zsim::Unobserved;

use super::{Failure, Finish, emit};

/// Arguments of `zsim buet`.
#[derive(Debug, Args)]
pub struct BuetArgs {
    #[command(subcommand)]
    command: BuetCommand,
}

#[derive(Debug, Subcommand)]
enum BuetCommand {
    /// Run a case: write the stage files computed, z_buffer.txt and out.bmp (as the course writes it: its header's file size is one more than the file's).
    Run {
        /// The case folder (config.txt, and stage3.txt or scene.txt).
        case: PathBuf,
        /// Where stage 4's triangles come from (default: stage3 when the case has it).
        #[arg(long, value_enum)]
        from: Option<From>,
        /// The folder to write into.
        #[arg(short, long, value_name = "OUT_DIR")]
        output: PathBuf,
    },
    /// Print the case as a zsim scene, for run, step, explain and figure.
    Import {
        /// The case folder.
        case: PathBuf,
        /// Where the triangles come from (default: stage3 when the case has it).
        #[arg(long, value_enum)]
        from: Option<From>,
        /// Write the scene to this file instead of standard output.
        #[arg(short, long, value_name = "FILE")]
        output: Option<PathBuf>,
    },
    /// Compare a student's z_buffer.txt with the case's and explain each difference.
    Check {
        /// The case folder.
        case: PathBuf,
        /// The student's z_buffer.txt.
        #[arg(long, value_name = "FILE")]
        answer: PathBuf,
        /// Where the triangles come from (default: stage3 when the case has it).
        #[arg(long, value_enum)]
        from: Option<From>,
    },
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum From {
    /// The case's stage3.txt.
    Stage3,
    /// scene.txt, through stages 1–3 computed by zsim.
    Scene,
}

fn source(from: Option<From>) -> Option<Source> {
    from.map(|f| match f {
        From::Stage3 => Source::Stage3,
        From::Scene => Source::Scene,
    })
}

pub fn run(lang: zsim::Lang, args: &BuetArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    match &args.command {
        BuetCommand::Run { case, from, output } => run_case(lang, case, source(*from), output, out),
        BuetCommand::Import { case, from, output } => {
            let loaded = Case::load(case, source(*from))?;
            super::emit_or_write(lang, out, output.as_deref(), &loaded.scene_json, &[case])?;
            Ok(Finish::Ok)
        }
        BuetCommand::Check { case, answer, from } => check(lang, case, source(*from), answer, out),
    }
}

fn run_case(
    lang: zsim::Lang,
    dir: &Path,
    from: Option<Source>,
    output: &Path,
    out: &mut dyn Write,
) -> Result<Finish, Failure> {
    let case = Case::load(dir, from)?;
    // The course's files are written as the course writes them, replacing
    // earlier runs' outputs, but never into the case folder that is read.
    let mut plan = zsim::Plan::new(&[dir], zsim::Replace::Allowed);
    if let Some(stages) = &case.stages {
        for (n, triangles) in stages.iter().enumerate() {
            plan.file(output.join(format!("stage{}.txt", n + 1)), buet::stage_text(triangles));
        }
    }
    let mut simulation = Simulation::new(&case.scene);
    simulation.finish(&mut Unobserved);
    plan.file(output.join("z_buffer.txt"), buet::z_buffer_text(simulation.buffers(), case.config.z_max));
    plan.file(output.join("out.bmp"), buet::bmp(simulation.buffers()));
    let written = plan.write()?;
    let stats = simulation.stats();
    let mut text = zsim::words!(
        lang,
        "buet-run-summary",
        path = zsim::shown_path(dir),
        triangles = case.stage3.len(),
        width = case.config.width.to_string(),
        height = case.config.height.to_string(),
        tested = stats.tested.to_string(),
        written = stats.written.to_string()
    ) + "\n";
    for path in written {
        text.push_str(&format!("{}\n", zsim::words!(lang, "file-written", path = zsim::shown_path(&path))));
    }
    emit(out, &text)?;
    Ok(Finish::Ok)
}

fn check(
    lang: zsim::Lang,
    dir: &Path,
    from: Option<Source>,
    answer: &Path,
    out: &mut dyn Write,
) -> Result<Finish, Failure> {
    let case = Case::load(dir, from)?;
    let differences = buet::check::check(lang, &case, answer)?;
    let (answer, path) = (zsim::shown_path(answer), zsim::shown_path(dir));
    if differences.is_empty() {
        emit(out, &format!("{}\n", zsim::words!(lang, "buet-check-matches", answer = answer, path = path)))?;
        return Ok(Finish::Ok);
    }
    let mut table = Table::new();
    // The "why" column wraps: the table stays 100 columns wide at most.
    table.load_style(presets::ASCII_MARKDOWN).set_content_arrangement(comfy_table::ContentArrangement::Dynamic);
    table.set_width(100).set_header(
        ["buet-header-line", "buet-header-value", "buet-header-answer", "buet-header-right", "buet-header-why"]
            .map(|key| zsim::words!(lang, key)),
    );
    for d in &differences {
        table.add_row([d.line.to_string(), d.value.to_string(), d.answer.clone(), d.right.clone(), d.reason.clone()]);
    }
    let count = differences.len();
    let heading = zsim::words!(lang, "buet-check-differs", answer = answer, count = count, path = path);
    emit(out, &format!("{heading}\n{table}\n"))?;
    Ok(Finish::Differs)
}
