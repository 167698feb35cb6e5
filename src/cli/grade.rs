//! `zsim grade`: every student's answers in a folder, one row a student, the
//! cells most students got wrong, and optionally a feedback file each.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use comfy_table::{ContentArrangement, Table, presets};
use zsim::Error;
use zsim::Scene;
use zsim::arith::Arith;
use zsim::class::{ClassGrades, grade_class};
use zsim::explain::{polygon_after, polygon_name};
use zsim::grade::{CommonMistake, Grade, Status};

use super::check::report_text;
use super::{Failure, Finish, emit_then};
use zsim::check::{as_the_student_sees, check_with, read_answer};
use zsim::gradebooks::{self, IdentityColumn};

/// Arguments of `zsim grade`.
#[derive(Debug, Args)]
pub struct GradeArgs {
    /// The scene file (JSON) of the exercise (not with --variants).
    #[arg(value_name = "SCENE")]
    pub(super) scene: Option<PathBuf>,
    /// The folder of answers: NAME.frame.txt and/or NAME.depth.txt per student, as `zsim check` reads them.
    #[arg(value_name = "CLASS")]
    pub(super) class: Option<PathBuf>,
    /// A class with a variant each (`exercise --roster`'s DIR/variants.json): each student's IDENTITY.frame.txt and IDENTITY.depth.txt graded against their own scene; everyone on the roster gets a row.
    #[arg(long, value_name = "FILE", conflicts_with = "after")]
    pub(super) variants: Option<PathBuf>,
    /// With --variants: an earlier `--format json` of the class; says whose scores changed and why.
    #[arg(long, value_name = "FILE", requires = "variants")]
    pub(super) compare: Option<PathBuf>,
    /// Grade the state after this polygon (number from 1, or name); default: the last.
    #[arg(long, value_name = "N|NAME")]
    after: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    pub(super) format: ReportFormat,
    /// Write each student's feedback (`zsim check`'s explanation of every wrong cell) to FOLDER/NAME.feedback.txt, and the common mistakes to FOLDER/common-mistakes.txt; FOLDER may not be the class folder, and no file in it is replaced.
    #[arg(short, long, value_name = "FOLDER")]
    pub(super) output: Option<PathBuf>,
    /// With --format moodle or canvas: the column that names the student (Moodle: email, idnumber, username; Canvas: id, sis-user-id, sis-login-id); the student's file name is its value.
    #[arg(long, value_parser = super::choice(&IdentityColumn::NAMES, IdentityColumn::parse))]
    pub(super) identity: Option<IdentityColumn>,
    /// With --format moodle or canvas: the grade column's header (Moodle: "Assignment: NAME (Real)" as its exports write it; Canvas: "NAME (ID)" to fill an existing assignment).
    #[arg(long, value_name = "NAME")]
    pub(super) item: Option<String>,
    /// With --format moodle or canvas: the points the exercise is worth (the item's maximum grade).
    #[arg(long, default_value_t = 100)]
    pub(super) points: u32,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(super) enum ReportFormat {
    /// A table, then the common mistakes.
    Text,
    /// One row a student with a header row: student,frame_wrong,depth_wrong,score,status,misconception.
    Csv,
    /// One object: students and common mistakes.
    Json,
    /// Moodle's gradebook import: the identity column, then the grade (0 … points).
    Moodle,
    /// Canvas's gradebook import: Student, ID, SIS User ID, SIS Login ID, Section, the assignment; a Points Possible row.
    Canvas,
}

pub fn run(lang: zsim::Lang, args: &GradeArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let (Some(scene_path), Some(class)) = (&args.scene, &args.class) else {
        return Err(super::flags::Flag::GradeFolders { variants: false }.into());
    };
    let args = &Plain { scene: scene_path.clone(), class: class.clone(), args };
    let scene = Scene::load(&args.scene)?;
    if scene.polygons.is_empty() {
        return Err(Error::from(zsim::class::GradeRefused::NoPolygons { path: args.scene.clone() }).into());
    }
    let last = match &args.after {
        Some(spec) => scene.find_polygon(spec)?,
        None => scene.polygons.len() - 1,
    };
    // CSV and JSON are the same in every language: their reasons and names in English.
    let plain = matches!(args.format, ReportFormat::Csv | ReportFormat::Json);
    let class = grade_class(if plain { zsim::Lang::En } else { lang }, &scene, &args.scene, &args.class, last)?;
    let rows = class.rows();
    // Students a gradebook cannot tell apart (`Emma`, `emma`) are graded both in every report; an
    // import leaves their rows out, and says so, rather than let the platform merge them.
    let merged = gradebooks::indistinct(&rows);
    let text = match args.format {
        ReportFormat::Moodle | ReportFormat::Canvas => {
            let apart: std::collections::HashSet<&str> =
                merged.iter().flat_map(|(a, b)| [a.as_str(), b.as_str()]).collect();
            for (first, second) in &merged {
                super::say(&zsim::words!(
                    lang,
                    "grade-left-out-of-import",
                    first = first.as_str(),
                    second = second.as_str()
                ));
            }
            let imported: Vec<&Grade> = rows.iter().copied().filter(|g| !apart.contains(g.student.as_str())).collect();
            gradebook(args, &imported)?
        }
        ReportFormat::Csv => gradebooks::csv(&rows),
        ReportFormat::Json => {
            let en = zsim::Lang::En;
            let found = (&class.mistakes[..], &class.reasons[..], &class.skipped[..]);
            gradebooks::json(en, &args.scene, &polygon_name(en, &scene, last), &rows, found)
        }
        ReportFormat::Text => {
            let counts = |f: fn(&Grade) -> bool| rows.iter().filter(|g| f(g)).count();
            let summary = zsim::words!(
                lang,
                "grade-summary",
                class = zsim::shown_path(&args.class),
                scene = zsim::shown_path(&args.scene),
                polygon = polygon_after(lang, &scene, last),
                students = rows.len(),
                ok = counts(|g| g.status == Status::Ok),
                wrong = counts(|g| matches!(g.status, Status::Wrong | Status::Incomplete(_))),
                malformed = counts(|g| matches!(g.status, Status::Malformed(_))),
                missing = counts(|g| matches!(g.status, Status::Missing(_)))
            );
            let skipped: String = class.skipped.iter().map(|s| format!("{}\n", s.text(lang))).collect();
            format!(
                "{summary}\n{}\n\n{}{}{skipped}",
                table(lang, &rows),
                causes_text(lang, &rows),
                mistakes_text(lang, (&class.mistakes, class.mistakes_left_out), &class.reasons, rows.len())
            )
        }
    };
    if let Some(folder) = &args.output {
        // Feedback is for the students: in their language, graded again only where the table was English.
        let regraded = if plain { Some(grade_class(lang, &scene, &args.scene, &args.class, last)?) } else { None };
        write_feedback(lang, folder, (&scene, args), regraded.as_ref().unwrap_or(&class))?;
    }
    // A gradebook stays importable: the files not graded are named on standard error.
    if matches!(args.format, ReportFormat::Csv | ReportFormat::Moodle | ReportFormat::Canvas) {
        class.skipped.iter().for_each(|skipped| super::say(&skipped.text(lang)));
    }
    // A misnamed answer is a student's work not graded, as a wrong one is.
    let all_graded = class.skipped.iter().all(|s| s.meant.is_none());
    let imported = merged.is_empty() || !matches!(args.format, ReportFormat::Moodle | ReportFormat::Canvas);
    let ok = all_graded && imported && rows.iter().all(|g| g.status == zsim::grade::Status::Ok);
    let finish = if ok { Finish::Ok } else { Finish::Differs };
    emit_then(out, &text, finish)
}

/// `grade SCENE CLASS`'s arguments, the two paths given.
struct Plain<'a> {
    scene: PathBuf,
    class: PathBuf,
    args: &'a GradeArgs,
}

impl std::ops::Deref for Plain<'_> {
    type Target = GradeArgs;

    fn deref(&self) -> &GradeArgs {
        self.args
    }
}

/// A gradebook import for Moodle or Canvas, with the identity column checked
/// against the platform.
fn gradebook(args: &GradeArgs, rows: &[&Grade]) -> Result<String, Failure> {
    gradebook_of(args.format, args.identity, args.item.as_deref(), args.points, rows)
}

/// [`gradebook`] from its parts.
pub(super) fn gradebook_of(
    format: ReportFormat,
    identity: Option<IdentityColumn>,
    item: Option<&str>,
    points: u32,
    rows: &[&Grade],
) -> Result<String, Failure> {
    let moodle = format == ReportFormat::Moodle;
    let identity = identity.unwrap_or(if moodle { IdentityColumn::Email } else { IdentityColumn::SisLoginId });
    if identity.is_moodle() != moodle {
        return Err(super::flags::Flag::IdentityColumn { column: identity.header() }.into());
    }
    if points == 0 {
        return Err(super::flags::Flag::NoPoints.into());
    }
    Ok(if moodle {
        gradebooks::moodle(rows, identity, item.unwrap_or("Assignment: z-buffer (Real)"), points)
    } else {
        gradebooks::canvas(rows, identity, item.unwrap_or("z-buffer"), points)
    })
}

fn table(lang: zsim::Lang, rows: &[&Grade]) -> Table {
    let mut table = Table::new();
    // A likely-cause column only when a cause was found for someone.
    let causes = rows.iter().any(|g| g.misconception.is_some());
    let columns = ["student", "frame", "depth", "score", "status", "cause"];
    let header = columns[..if causes { 6 } else { 5 }].iter().map(|c| zsim::words!(lang, &format!("grade-column-{c}")));
    // Long statuses and causes wrap inside their column: the table stays 100 columns wide at most.
    table
        .load_style(presets::ASCII_MARKDOWN)
        .set_content_arrangement(comfy_table::ContentArrangement::Dynamic)
        .set_width(100)
        .set_header(header);
    for grade in rows {
        let count = |c: Option<usize>| c.map_or_else(|| "-".to_string(), |c| c.to_string());
        let mut row = vec![
            grade.student.clone(),
            count(grade.frame_wrong),
            count(grade.depth_wrong),
            zsim::localize_decimal(lang, grade.percent()),
            grade.status.words(lang),
        ];
        if causes {
            row.push(grade.misconception.map_or_else(String::new, |d| {
                let what = d.misconception.words(lang);
                zsim::words!(lang, "grade-cause", what = what, explained = d.explained, wrong = d.wrong)
            }));
        }
        table.add_row(row);
    }
    table
}

/// The class's likely causes: each misconception named for a student, with
/// how many students it was named for, most first.
pub(super) fn causes_text(lang: zsim::Lang, rows: &[&Grade]) -> String {
    let counts = zsim::grade::causes(rows);
    if counts.is_empty() {
        return String::new();
    }
    let mut text = format!("{}\n", zsim::words!(lang, "grade-causes"));
    for (misconception, count) in counts {
        let line = zsim::words!(
            lang,
            "grade-cause-count",
            what = misconception.words(lang),
            count = count,
            students = rows.len()
        );
        text.push_str(&format!("  {line}\n"));
    }
    text.push('\n');
    text
}

fn mistakes_text(
    lang: zsim::Lang,
    (mistakes, left_out): (&[CommonMistake], usize),
    reasons: &[String],
    students: usize,
) -> String {
    if mistakes.is_empty() {
        return format!("{}\n", zsim::words!(lang, "grade-mistakes-none"));
    }
    let mut table = Table::new();
    table
        .load_style(presets::ASCII_MARKDOWN)
        .set_content_arrangement(ContentArrangement::Dynamic)
        .set_width(100)
        .set_header([
            zsim::words!(lang, "grade-column-buffer"),
            "x".to_string(),
            "y".to_string(),
            zsim::words!(lang, "grade-column-wrong"),
            zsim::words!(lang, "check-column-right"),
            zsim::words!(lang, "grade-column-answered"),
            zsim::words!(lang, "check-column-why"),
        ]);
    for (mistake, reason) in mistakes.iter().zip(reasons) {
        let answered: Vec<String> =
            mistake.answers.iter().map(|(value, count)| format!("{value} ({count}×)")).collect();
        table.add_row([
            mistake.buffer.name(lang).to_string(),
            mistake.x.to_string(),
            mistake.y.to_string(),
            zsim::words!(lang, "grade-students-of", count = mistake.students.len(), total = students),
            mistake.right.to_string(),
            answered.join(", "),
            reason.clone(),
        ]);
    }
    let more = match left_out {
        0 => String::new(),
        count => format!("{}\n", zsim::words!(lang, "grade-mistakes-more", count = count)),
    };
    format!("{}\n{table}\n{more}", zsim::words!(lang, "grade-mistakes"))
}

/// FOLDER/NAME.feedback.txt for each student and FOLDER/common-mistakes.txt:
/// every name planned and checked first, then each student's feedback made
/// and written one at a time, so that a class of any size holds one
/// student's feedback at a time.
fn write_feedback(
    lang: zsim::Lang,
    folder: &Path,
    (scene, args): (&Scene, &Plain<'_>),
    class: &ClassGrades,
) -> Result<(), Error> {
    let (last, shown) = (class.last, zsim::own_name(&args.scene));
    // The scene's buffers and wrong rules drawn once for the class, each student's files found once: a
    // class of thousands costs what its students cost, not their square.
    let prepared = zsim::check::PreparedCheck::new(scene, last);
    let mut files_of: std::collections::HashMap<&str, Vec<&zsim::class::AnswerFile>> = std::collections::HashMap::new();
    for file in &class.files {
        files_of.entry(file.student.as_str()).or_default().push(file);
    }
    let (prepared, files_of) = (&prepared, &files_of);
    let mut plan = zsim::Plan::new(&[&args.class], zsim::Replace::Never);
    // Each student's own file name, told apart where two would take one.
    let names = zsim::class::feedback_names(class.rows().into_iter().map(|grade| grade.student.as_str()));
    for (grade, name) in class.rows().into_iter().zip(names) {
        // NAME.feedback.txt never ends as a submitted NAME.frame.txt or NAME.depth.txt
        // does, nor is it the summary's name, whatever the student's name.
        plan.file_made(folder.join(name), move || {
            let mut text = zsim::words!(
                lang,
                "grade-feedback",
                student = &grade.student,
                scene = zsim::shown_name(&args.scene),
                polygon = polygon_after(lang, scene, last),
                score = zsim::localize_decimal(lang, grade.percent()),
                status = grade.status.words(lang)
            ) + "\n";
            // A file that looked like this student's but was not graded: said as the report says it.
            for skipped in
                class.skipped.iter().filter(|s| s.meant.as_ref().is_some_and(|(who, _)| *who == grade.student))
            {
                text.push_str(&format!("{}\n", skipped.text(lang)));
            }
            // The answers that were read, explained as `zsim check` explains them.
            let mut answers = Vec::new();
            for file in files_of.get(grade.student.as_str()).into_iter().flatten() {
                match read_answer(&file.path, scene, file.buffer, zsim::Links::Refuse) {
                    Ok(matrix) => answers.push((file.buffer, zsim::own_name(&file.path), matrix)),
                    Err(error) => text.push_str(&format!("{}\n", as_the_student_sees(lang, &error, &file.path))),
                }
            }
            if !answers.is_empty() {
                let report = check_with(lang, scene, shown, last, answers, Arith::Exact, Some(prepared))?;
                text.push_str(&report_text(lang, &report));
            }
            Ok(text.into_bytes())
        });
    }
    let mistakes = mistakes_text(lang, (&class.mistakes, class.mistakes_left_out), &class.reasons, class.graded.len());
    plan.file(folder.join("common-mistakes.txt"), mistakes);
    plan.write().map(drop)
}
