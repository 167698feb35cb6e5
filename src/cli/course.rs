//! A course on the command line: `exercise --roster` (a variant per
//! student), `grade --variants` (each against their own key) and
//! `autograde` (a platform's grader, for one submission).

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use comfy_table::{ContentArrangement, Table, presets};
use zsim::course::fair::{ClassSpec, default_rules, make_class};
use zsim::course::folders::{Handouts, answer_name};
use zsim::course::grading::{CourseGrades, Row, grade_course};
use zsim::course::manifest::{Loaded, Manifest};
use zsim::course::report::{Change, changes, csv, json, read_previous};
use zsim::{Error, Lang};

use super::exercise::ExerciseArgs;
use super::grade::{GradeArgs, ReportFormat};
use super::{Failure, Finish, emit, emit_then};

/// `zsim exercise --roster FILE -o DIR`.
pub fn exercise(lang: Lang, args: &ExerciseArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let roster_path = args.roster.as_deref().expect("called with --roster");
    let roster = zsim::course::roster::load(roster_path, args.identity.as_deref())?;
    let exercise = super::exercise::spec(args)?;
    let rules =
        args.rules.as_deref().map_or_else(|| Ok(default_rules(&exercise.hard)), zsim::course::fair::parse_rules)?;
    let hand_in = zsim::course::fair::parse_hand_in(&args.hand_in)?;
    let spec = ClassSpec { exercise, times: args.times, distinct: args.distinct, rules, hand_in };
    let manifest = make_class(lang, &spec, &roster, &args.reseed)?;
    let dir = &args.output;
    for other in [&args.gradescope, &args.prairielearn].into_iter().flatten() {
        if zsim::same_folder(other, dir) {
            return Err(Error::from(zsim::OutputRefused::IsInput { folder: other.clone() }).into());
        }
    }
    let table = fairness_table(lang, &manifest);
    let handouts = Handouts { lang, manifest: &manifest, formats: &args.formats, site: args.site.as_deref() };
    let mut plan = zsim::Plan::new(&[roster_path], zsim::Replace::Never);
    let listed = zsim::course::folders::plan(&handouts, dir, format!("{table}\n"), &mut plan);
    let written = zsim::words!(lang, "file-written-in", files = listed.join(", "), path = zsim::shown_path(dir));
    let mut text = format!("{}\n{table}\n{written}\n", manifest.summary(lang));
    let json = manifest.to_json();
    if let Some(folder) = &args.gradescope {
        let files = zsim::course::platforms::gradescope_autograder(&json, args.visibility.name(), args.points, lang);
        text.push_str(&planned(lang, &mut plan, folder, files, &["setup.sh", "run_autograder"]));
    }
    if let Some(folder) = &args.prairielearn {
        let files =
            zsim::course::platforms::prairielearn_question(&manifest, &json, "prairielearn/grader-python", lang);
        text.push_str(&planned(lang, &mut plan, folder, files, &["tests/run.sh"]));
    }
    plan.write()?;
    emit(out, &text)?;
    Ok(Finish::Ok)
}

/// Plans a platform's files into `folder` (`executable` among them made so) and says where.
fn planned(
    lang: Lang,
    plan: &mut zsim::Plan<'_>,
    folder: &Path,
    files: Vec<(String, Vec<u8>)>,
    executable: &[&str],
) -> String {
    let names: Vec<String> = files.iter().map(|(name, _)| name.clone()).collect();
    for (name, bytes) in files {
        if executable.contains(&name.as_str()) {
            plan.executable(folder.join(&name), bytes);
        } else {
            plan.file(folder.join(&name), bytes);
        }
    }
    format!("{}\n", zsim::words!(lang, "file-written-in", files = names.join(", "), path = zsim::shown_path(folder)))
}

/// The fairness table: a row a student, the asked cases' counts, and the
/// fewest cells any required wrong rule lies from the key.
fn fairness_table(lang: Lang, manifest: &Manifest) -> Table {
    let mut table = Table::new();
    table.load_style(presets::ASCII_MARKDOWN).set_content_arrangement(ContentArrangement::Disabled).set_width(100);
    let mut header = vec![zsim::words!(lang, "grade-column-student"), zsim::words!(lang, "class-column-code")];
    header.extend(manifest.settings.hard.iter().cloned());
    header.push(zsim::words!(lang, "class-column-apart"));
    table.set_header(header);
    for variant in &manifest.students {
        let mut row = vec![zsim::printable(&variant.identity).into_owned(), variant.code.clone()];
        for case in &manifest.settings.hard {
            let count = variant.cases.iter().find(|c| c.name == *case).map_or(0, |c| c.count);
            row.push(count.to_string());
        }
        let fewest = variant
            .separations
            .iter()
            .filter(|s| manifest.settings.rules.contains(&s.name))
            .min_by_key(|s| s.count)
            .map_or_else(String::new, |s| format!("{} ({})", s.count, s.name));
        row.push(fewest);
        table.add_row(row);
    }
    table
}

/// The arguments of `grade` that grading against a manifest uses.
struct GradeVariants<'a> {
    variants: &'a Path,
    class: &'a Path,
    format: ReportFormat,
    output: Option<&'a Path>,
    compare: Option<&'a Path>,
    gradebook: (Option<zsim::gradebooks::IdentityColumn>, Option<&'a str>, u32),
}

/// `zsim grade --variants DIR/variants.json CLASS`: one folder, the class's.
pub fn grade(lang: Lang, args: &GradeArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let (Some(variants), Some(class), None) = (&args.variants, &args.scene, &args.class) else {
        return Err(super::flags::Flag::GradeFolders { variants: true }.into());
    };
    let args = &GradeVariants {
        variants,
        class,
        format: args.format,
        output: args.output.as_deref(),
        compare: args.compare.as_deref(),
        gradebook: (args.identity, args.item.as_deref(), args.points),
    };
    let loaded = zsim::course::manifest::load(args.variants)?;
    let plain = matches!(args.format, ReportFormat::Csv | ReportFormat::Json);
    let graded = grade_course(if plain { Lang::En } else { lang }, &loaded, args.class)?;
    let previous = match args.compare {
        Some(path) => Some(read_previous(path)?),
        None => None,
    };
    let changes = previous.as_ref().map(|p| changes(&loaded.manifest, &graded, p)).unwrap_or_default();
    let grades = graded.grades();
    let text = match args.format {
        ReportFormat::Moodle | ReportFormat::Canvas => {
            let (identity, item, points) = args.gradebook;
            super::grade::gradebook_of(args.format, identity, item, points, &grades)?
        }
        ReportFormat::Csv => csv(&loaded.manifest, &graded),
        ReportFormat::Json => json(&loaded.manifest, &graded, &changes),
        ReportFormat::Text => text(lang, args, &graded, &changes),
    };
    if let Some(folder) = args.output {
        let regraded = if plain { Some(grade_course(lang, &loaded, args.class)?) } else { None };
        feedback(lang, folder, args, &loaded, regraded.as_ref().unwrap_or(&graded))?;
    }
    if !matches!(args.format, ReportFormat::Text | ReportFormat::Json) {
        graded.strays.iter().for_each(|s| super::say(&s.text(lang)));
        for row in &graded.rows {
            row.notes.iter().for_each(|n| super::say(&format!("{}: {}", row.grade.student, n.text(lang))));
        }
    }
    let ok = graded.strays.is_empty()
        && graded.rows.iter().all(|r| r.grade.status == zsim::grade::Status::Ok && r.notes.is_empty());
    emit_then(out, &text, if ok { Finish::Ok } else { Finish::Differs })
}

fn text(lang: Lang, args: &GradeVariants<'_>, graded: &CourseGrades, changes: &[Change]) -> String {
    use zsim::grade::Status;
    let grades = graded.grades();
    let count = |f: &dyn Fn(&Status) -> bool| grades.iter().filter(|g| f(&g.status)).count();
    let mut text = zsim::words!(
        lang,
        "course-grade-summary",
        class = zsim::shown_path(args.class),
        variants = zsim::shown_path(args.variants),
        students = grades.len(),
        ok = count(&|s| *s == Status::Ok),
        wrong = count(&|s| matches!(s, Status::Wrong | Status::Incomplete(_))),
        malformed = count(&|s| matches!(s, Status::Malformed(_))),
        missing = count(&|s| matches!(s, Status::Missing(_)))
    ) + "\n";
    let mut table = Table::new();
    table.load_style(presets::ASCII_MARKDOWN).set_content_arrangement(ContentArrangement::Dynamic).set_width(100);
    let columns = ["student", "code", "frame", "depth", "score", "status", "cause"];
    table.set_header(columns.iter().map(|c| match *c {
        "code" => zsim::words!(lang, "class-column-code"),
        c => zsim::words!(lang, &format!("grade-column-{c}")),
    }));
    for row in &graded.rows {
        let grade = &row.grade;
        let count = |c: Option<usize>| c.map_or_else(|| "-".to_string(), |c| c.to_string());
        let status = grade.status.words(lang);
        table.add_row([
            zsim::printable(&grade.student).into_owned(),
            row.code.clone(),
            count(grade.frame_wrong),
            count(grade.depth_wrong),
            zsim::localize_decimal(lang, grade.percent()),
            status,
            grade.misconception.map_or_else(String::new, |d| d.misconception.words(lang)),
        ]);
    }
    text.push_str(&format!("{table}\n"));
    for row in &graded.rows {
        for note in &row.notes {
            text.push_str(&format!("{}: {}\n", zsim::printable(&row.grade.student), note.text(lang)));
        }
    }
    for stray in &graded.strays {
        text.push_str(&format!("{}\n", stray.text(lang)));
    }
    text.push('\n');
    text.push_str(&super::grade::causes_text(lang, &grades));
    text.push_str(&format!("{}\n", zsim::words!(lang, "course-by-kind")));
    for (case, holding, wrong, cells) in graded.by_kind() {
        if holding > 0 {
            let line = zsim::words!(
                lang,
                "course-kind-line",
                case = case.name(),
                wrong = wrong,
                holding = holding,
                cells = cells
            );
            text.push_str(&format!("  {line}\n"));
        }
    }
    if args.compare.is_some() {
        text.push_str(&format!("\n{}\n", zsim::words!(lang, "course-changes", count = changes.len())));
        for change in changes {
            text.push_str(&format!("  {}\n", change.text(lang)));
        }
    }
    text
}

/// Each student's feedback (their score, what is said of their files, and
/// `zsim check`'s report on their own files and scene, naming only their
/// files) and the class's summary by kind of case.
fn feedback(
    lang: Lang,
    folder: &Path,
    args: &GradeVariants<'_>,
    loaded: &Loaded,
    graded: &CourseGrades,
) -> Result<(), Error> {
    let mut plan = zsim::Plan::new(&[args.class, args.variants], zsim::Replace::Never);
    let names = zsim::class::feedback_names(graded.rows.iter().map(|r| r.grade.student.as_str()));
    for (row, name) in graded.rows.iter().zip(names) {
        plan.file_made(folder.join(name), move || feedback_of(lang, loaded, row).map(String::into_bytes));
    }
    let summary = text(lang, args, graded, &[]);
    plan.file(folder.join("common-mistakes.txt"), summary);
    plan.write().map(drop)
}

fn feedback_of(lang: Lang, loaded: &Loaded, row: &Row) -> Result<String, Error> {
    let variant = &loaded.manifest.students[row.index];
    let scene = &loaded.scenes[row.index];
    let grade = &row.grade;
    let mut text = zsim::words!(
        lang,
        "course-feedback",
        student = zsim::printable(&grade.student).into_owned(),
        code = variant.code.as_str(),
        score = zsim::localize_decimal(lang, grade.percent()),
        status = grade.status.words(lang)
    ) + "\n";
    for note in &row.notes {
        text.push_str(&format!("{}\n", note.text(lang)));
    }
    for buffer in loaded.manifest.buffers() {
        if !row.files.iter().any(|f| f.buffer == buffer) {
            let file = answer_name(&variant.identity, buffer);
            text.push_str(&format!("{}\n", zsim::words!(lang, "gradescope-missing", file = file)));
        }
    }
    let last = scene.polygons.len() - 1;
    let mut answers = Vec::new();
    for file in &row.files {
        match zsim::check::read_answer(&file.path, scene, file.buffer, zsim::Links::Refuse) {
            Ok(answer) => answers.push((file.buffer, PathBuf::from(&file.name), answer)),
            Err(error) => text.push_str(&format!("{}\n", zsim::check::as_the_student_sees(lang, &error, &file.path))),
        }
    }
    if !answers.is_empty() {
        let answers = answers.iter().map(|(b, p, a)| (*b, p.as_path(), a.clone())).collect();
        let report =
            zsim::check::check(lang, scene, Path::new("scene.json"), last, answers, zsim::arith::Arith::Exact)?;
        text.push_str(&super::check::report_text(lang, &report));
    }
    Ok(text)
}

/// Arguments of `zsim autograde`.
#[derive(Debug, Args)]
pub struct AutogradeArgs {
    /// The platform whose grader runs this: gradescope or prairielearn.
    #[arg(value_enum)]
    platform: Platform,
    /// The class's manifest (variants.json), which the grader carries.
    #[arg(long, value_name = "FILE")]
    variants: PathBuf,
    /// Gradescope: the submission's metadata (submission_metadata.json).
    #[arg(long, value_name = "FILE")]
    metadata: Option<PathBuf>,
    /// PrairieLearn: the grading job's data (data.json).
    #[arg(long, value_name = "FILE")]
    data: Option<PathBuf>,
    /// The student's files (IDENTITY.frame.txt or frame.txt, and the depth's likewise).
    #[arg(long, value_name = "DIR")]
    submission: PathBuf,
    /// Gradescope: who sees the results.
    #[arg(long, default_value = "visible", value_parser = super::choice(&zsim::gradescope::Visibility::NAMES, zsim::gradescope::Visibility::parse))]
    visibility: zsim::gradescope::Visibility,
    /// Gradescope: the points the submission is worth.
    #[arg(long, default_value_t = 100, value_parser = clap::value_parser!(u32).range(1..=i64::from(zsim::gradescope::MAX_POINTS)))]
    points: u32,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Platform {
    /// Gradescope's autograder: results.json with a test per buffer.
    Gradescope,
    /// PrairieLearn's external grader: results.json with score, gradable and format_errors.
    Prairielearn,
}

/// `zsim autograde`: one submission graded against its student's variant,
/// results.json on standard output whatever happens (exit 0), so that the
/// platform always shows the student a message.
pub fn autograde(lang: Lang, args: &AutogradeArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let render = |report: &zsim::check::CheckReport| super::check::report_text(lang, report);
    let platform = match args.platform {
        Platform::Gradescope => zsim::course::platforms::Platform::Gradescope {
            metadata: args.metadata.as_deref(),
            grading: zsim::gradescope::Autograde { visibility: args.visibility, points: args.points },
        },
        Platform::Prairielearn => zsim::course::platforms::Platform::PrairieLearn { data: args.data.as_deref() },
    };
    let results = zsim::course::platforms::autograde(lang, &platform, &args.variants, &args.submission, &render);
    let text = results.unwrap_or_else(|why| zsim::course::platforms::unusable(&why.message(lang), &platform));
    emit_then(out, &text, Finish::Ok)
}
