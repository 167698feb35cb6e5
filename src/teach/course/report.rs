//! What grading a class against its manifest reports for programs: the
//! CSV and JSON (the same in every language), and how the scores changed
//! since an earlier grading's JSON, and why: the scene edited in the
//! manifest, the files handed in changed, the key recomputed otherwise (a
//! later zsim), or the same inputs scored by another rule.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::error::Error;
use crate::teach::exercise::HardCase;
use crate::teach::grade::gradebooks::csv_field;
use crate::words::Lang;

use super::grading::{CourseGrades, Fingerprint};
use super::manifest::{Manifest, ManifestError, ManifestProblem};

/// `grade --variants --format csv`: a row a student, the same in every language.
pub fn csv(manifest: &Manifest, graded: &CourseGrades) -> String {
    let mut text = String::from("student,code,frame_wrong,depth_wrong,score,status,misconception,notes\n");
    for row in &graded.rows {
        let grade = &row.grade;
        let count = |c: Option<usize>| c.map_or_else(String::new, |c| c.to_string());
        let notes: Vec<String> = row.notes.iter().map(|n| n.text(Lang::En)).collect();
        text.push_str(&format!(
            "{},{},{},{},{},{},{},{}\n",
            csv_field(&grade.student),
            manifest.students[row.index].code,
            count(grade.frame_wrong),
            count(grade.depth_wrong),
            grade.percent(),
            csv_field(&grade.status.to_string()),
            grade.misconception.map_or("", |d| d.misconception.name()),
            csv_field(&notes.join("; "))
        ));
    }
    text
}

/// One student in `grade --variants --format json`.
#[derive(Debug, Serialize, Deserialize)]
pub struct StudentJson {
    student: String,
    code: String,
    frame_wrong: Option<usize>,
    depth_wrong: Option<usize>,
    unanswered: usize,
    score: serde_json::Number,
    status: String,
    misconception: Option<String>,
    files: Vec<String>,
    notes: Vec<String>,
    wrong_by_kind: Vec<KindJson>,
    fingerprint: Fingerprint,
}

/// A student's wrong cells touched by one kind of case.
#[derive(Debug, Serialize, Deserialize)]
pub struct KindJson {
    case: String,
    cells: usize,
}

/// `grade --variants --format json`.
#[derive(Debug, Serialize, Deserialize)]
pub struct ClassJson {
    format: String,
    students: Vec<StudentJson>,
    by_kind: Vec<ByKindJson>,
    not_graded: Vec<String>,
    #[serde(default)]
    changes: Vec<String>,
}

/// The class's wrong cells by one kind of case.
#[derive(Debug, Serialize, Deserialize)]
pub struct ByKindJson {
    case: String,
    holding: usize,
    wrong: usize,
    cells: usize,
}

/// What `grade --variants --format json` says its layout is.
pub const JSON_FORMAT: &str = "zsim class grades 1";

/// `grade --variants --format json`: the students, the kinds of case, the files not graded, the changes.
pub fn json(manifest: &Manifest, graded: &CourseGrades, changes: &[Change]) -> String {
    let students = graded
        .rows
        .iter()
        .map(|row| {
            let grade = &row.grade;
            StudentJson {
                student: grade.student.clone(),
                code: manifest.students[row.index].code.clone(),
                frame_wrong: grade.frame_wrong,
                depth_wrong: grade.depth_wrong,
                unanswered: grade.unanswered,
                score: grade.percent().parse().expect("a decimal is a JSON number"),
                status: grade.status.to_string(),
                misconception: grade.misconception.map(|d| d.misconception.name().to_string()),
                files: row.files.iter().map(|f| f.name.clone()).collect(),
                notes: row.notes.iter().map(|n| n.text(Lang::En)).collect(),
                wrong_by_kind: HardCase::ALL
                    .iter()
                    .filter(|c| row.kinds[**c as usize].1 > 0)
                    .map(|c| KindJson { case: c.name().into(), cells: row.kinds[*c as usize].1 })
                    .collect(),
                fingerprint: row.fingerprint,
            }
        })
        .collect();
    let by_kind = graded
        .by_kind()
        .into_iter()
        .map(|(case, holding, wrong, cells)| ByKindJson { case: case.name().into(), holding, wrong, cells })
        .collect();
    let class = ClassJson {
        format: JSON_FORMAT.into(),
        students,
        by_kind,
        not_graded: graded.strays.iter().map(|s| s.text(Lang::En)).collect(),
        changes: changes.iter().map(|c| c.text(Lang::En)).collect(),
    };
    serde_json::to_string_pretty(&class).expect("plain data") + "\n"
}

/// An earlier class's grades, read through the door.
pub fn read_previous(path: &Path) -> Result<ClassJson, Error> {
    let text = crate::door::read_text(path)?;
    let class: ClassJson = serde_json::from_str(&text).map_err(|e| {
        Error::from(ManifestError {
            path: path.to_owned(),
            place: String::new(),
            problem: ManifestProblem::Layout(e.to_string()),
        })
    })?;
    if class.format != JSON_FORMAT {
        return Err(Error::from(ManifestError {
            path: path.to_owned(),
            place: "format".into(),
            problem: ManifestProblem::Format(class.format),
        }));
    }
    Ok(class)
}

/// A student whose score changed since an earlier grading, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Change {
    student: String,
    before: Option<String>,
    after: Option<String>,
    why: Why,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Why {
    Added,
    Removed,
    Scene,
    Files,
    Key,
    Rule,
}

impl Change {
    /// One line in `lang`: the student, the scores, why.
    pub fn text(&self, lang: Lang) -> String {
        let why = match self.why {
            Why::Added => words!(lang, "course-change-added"),
            Why::Removed => words!(lang, "course-change-removed"),
            Why::Scene => words!(lang, "course-change-scene"),
            Why::Files => words!(lang, "course-change-files"),
            Why::Key => words!(lang, "course-change-key"),
            Why::Rule => words!(lang, "course-change-rule"),
        };
        let score =
            |s: &Option<String>| s.clone().map_or_else(|| "-".into(), |s| crate::words::localize_decimal(lang, s));
        words!(
            lang,
            "course-change",
            student = crate::words::printable(&self.student).into_owned(),
            before = score(&self.before),
            after = score(&self.after),
            why = why
        )
    }
}

/// Whose scores changed since `previous`, and why: the scene edited, the
/// files handed in changed, the key recomputed differently (another zsim),
/// or the same inputs scored by another rule.
pub fn changes(manifest: &Manifest, graded: &CourseGrades, previous: &ClassJson) -> Vec<Change> {
    let mut changes = Vec::new();
    for row in &graded.rows {
        let now = row.grade.percent();
        let id = row.grade.student.to_lowercase();
        match previous.students.iter().find(|s| s.student.to_lowercase() == id) {
            None => changes.push(Change {
                student: row.grade.student.clone(),
                before: None,
                after: Some(now),
                why: Why::Added,
            }),
            Some(before) if before.score.to_string() != now => {
                let (old, new) = (before.fingerprint, row.fingerprint);
                let why = if old.scene != new.scene {
                    Why::Scene
                } else if old.files != new.files {
                    Why::Files
                } else if old.key != new.key {
                    Why::Key
                } else {
                    Why::Rule
                };
                changes.push(Change {
                    student: row.grade.student.clone(),
                    before: Some(before.score.to_string()),
                    after: Some(now),
                    why,
                });
            }
            Some(_) => {}
        }
    }
    for before in &previous.students {
        if manifest.student(&before.student).is_none() {
            changes.push(Change {
                student: before.student.clone(),
                before: Some(before.score.to_string()),
                after: None,
                why: Why::Removed,
            });
        }
    }
    changes
}
