//! Gradebooks: `grade --format csv` and `--format json` (the same in every
//! language), and the imports `--format moodle` and `--format canvas` write a
//! class's scores in the layout each platform imports. Moodle maps one
//! identity column (email address, ID number or username) to its users and
//! takes a grade column per item, refusing the whole file when a value lies
//! outside the item's range; Canvas takes its export's layout, `Student, ID,
//! SIS User ID, SIS Login ID, Section` then one column per assignment, and a
//! second row `Points Possible`. The identity is each student's file name
//! (`ana@uni.edu.frame.txt` gives `ana@uni.edu`); the grade is the share of
//! right cells times the points, with two decimals, always within 0 … points.

use std::path::Path;

use crate::numbers::{Q, decimal};
use crate::teach::grade::{CommonMistake, Grade};
use crate::words::Lang;

/// Which column names the student in the import.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IdentityColumn {
    /// Moodle: "Email address" (the default for Moodle).
    Email,
    /// Moodle: "ID number".
    Idnumber,
    /// Moodle: "Username".
    Username,
    /// Canvas: "ID".
    Id,
    /// Canvas: "SIS User ID".
    SisUserId,
    /// Canvas: "SIS Login ID" (the default for Canvas).
    SisLoginId,
}

impl IdentityColumn {
    /// Every identity, in the order of [`IdentityColumn::NAMES`].
    pub const ALL: [IdentityColumn; 6] = [
        IdentityColumn::Email,
        IdentityColumn::Idnumber,
        IdentityColumn::Username,
        IdentityColumn::Id,
        IdentityColumn::SisUserId,
        IdentityColumn::SisLoginId,
    ];

    /// The names a user chooses them by.
    pub const NAMES: [&'static str; 6] = ["email", "idnumber", "username", "id", "sis-user-id", "sis-login-id"];

    /// The identity named `name` (one of [`IdentityColumn::NAMES`]).
    pub fn parse(name: &str) -> Option<IdentityColumn> {
        IdentityColumn::NAMES.iter().position(|n| *n == name).map(|i| IdentityColumn::ALL[i])
    }

    /// The column's header as the platform writes it in its own exports.
    pub fn header(self) -> &'static str {
        match self {
            IdentityColumn::Email => "Email address",
            IdentityColumn::Idnumber => "ID number",
            IdentityColumn::Username => "Username",
            IdentityColumn::Id => "ID",
            IdentityColumn::SisUserId => "SIS User ID",
            IdentityColumn::SisLoginId => "SIS Login ID",
        }
    }

    /// Whether Moodle imports by this column (else Canvas does).
    pub fn is_moodle(self) -> bool {
        matches!(self, IdentityColumn::Email | IdentityColumn::Idnumber | IdentityColumn::Username)
    }
}

/// A student's grade out of `points`, with two decimals (rounded half up,
/// so never above `points`).
fn points_of(grade: &Grade, points: u32) -> String {
    decimal(grade.score * Q::from_integer(i128::from(points)), 2)
}

/// The students a gradebook cannot tell apart: the identity cells it would
/// receive are the same once written as a CSV cell (`=x` is written `'=x`)
/// and compared without case, as Moodle and Canvas match identities. Each
/// such pair, as shown, first seen first; their rows are left out of an
/// import (the rest of the class is imported) and said apart.
pub fn indistinct(rows: &[&Grade]) -> Vec<(String, String)> {
    let mut seen: std::collections::HashMap<String, &str> = std::collections::HashMap::with_capacity(rows.len());
    let mut pairs = Vec::new();
    for grade in rows {
        let key = csv_field(&grade.student).to_lowercase();
        match seen.get(&key) {
            Some(other) => pairs.push((other.to_string(), grade.student.clone())),
            None => {
                seen.insert(key, &grade.student);
            }
        }
    }
    pairs
}

/// Moodle's gradebook import: the identity column, then the grade item.
pub fn moodle(rows: &[&Grade], identity: IdentityColumn, item: &str, points: u32) -> String {
    let mut text = format!("{},{}\n", identity.header(), csv_field(item));
    for grade in rows {
        text.push_str(&format!("{},{}\n", csv_field(&grade.student), points_of(grade, points)));
    }
    text
}

/// Canvas's gradebook import: its five identity columns, the assignment,
/// the `Points Possible` row; the student's name goes in `Student` and in
/// the identity column chosen.
pub fn canvas(rows: &[&Grade], identity: IdentityColumn, item: &str, points: u32) -> String {
    const COLUMNS: [&str; 5] = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"];
    let mut text = format!("{},{}\n", COLUMNS.join(","), csv_field(item));
    text.push_str(&format!("Points Possible,,,,,{points}\n"));
    for grade in rows {
        let name = csv_field(&grade.student);
        let cells: Vec<String> = COLUMNS
            .iter()
            .map(|column| match *column {
                "Student" => name.clone(),
                column if column == identity.header() => name.clone(),
                _ => String::new(),
            })
            .collect();
        text.push_str(&format!("{},{}\n", cells.join(","), points_of(grade, points)));
    }
    text
}

/// A CSV field, quoted when it holds a comma, a quote or a line break (RFC
/// 4180). A cell a spreadsheet would run as a formula (one starting with `=`,
/// `+`, `-`, `@`, a tab or a carriage return: a student's name is anyone's
/// text) starts with `'` instead, as OWASP recommends, so it stays text.
pub fn csv_field(text: &str) -> String {
    let text = if text.starts_with(['=', '+', '-', '@', '\t', '\r']) { format!("'{text}") } else { text.to_string() };
    if text.contains([',', '"', '\n', '\r']) { format!("\"{}\"", text.replace('"', "\"\"")) } else { text }
}

/// `grade --format csv`: one row a student, the same in every language.
pub fn csv(rows: &[&Grade]) -> String {
    let mut text = String::from("student,frame_wrong,depth_wrong,score,status,misconception\n");
    for grade in rows {
        let count = |c: Option<usize>| c.map_or_else(String::new, |c| c.to_string());
        text.push_str(&format!(
            "{},{},{},{},{},{}\n",
            csv_field(&grade.student),
            count(grade.frame_wrong),
            count(grade.depth_wrong),
            grade.percent(),
            csv_field(&grade.status.to_string()),
            grade.misconception.map_or("", |d| d.misconception.name())
        ));
    }
    text
}

/// `grade --format json`: the students and the common mistakes, each with
/// zsim's reason (`reasons`, in the order of `mistakes`).
pub fn json(
    lang: Lang,
    scene: &Path,
    after: &str,
    rows: &[&Grade],
    (mistakes, reasons, skipped): (&[CommonMistake], &[String], &[crate::teach::grade::class::Skipped]),
) -> String {
    let not_graded = skipped
        .iter()
        .map(|s| {
            let (student, buffer) =
                s.meant.as_ref().map(|(student, buffer)| (student.as_str(), buffer.name(lang))).unzip();
            NotGraded { buffer, file: &s.name, reason: s.text(lang), student }
        })
        .collect();
    let students = rows
        .iter()
        .map(|g| StudentRow {
            depth_wrong: g.depth_wrong,
            explained: g.misconception.map(|d| d.explained),
            frame_wrong: g.frame_wrong,
            misconception: g.misconception.map(|d| d.misconception.name()),
            // A number, written exactly as the table shows it (one decimal).
            score: g.percent().parse::<serde_json::Number>().expect("a decimal is a JSON number"),
            status: g.status.to_string(),
            student: &g.student,
            unanswered: g.unanswered,
        })
        .collect();
    let common_mistakes = mistakes
        .iter()
        .zip(reasons)
        .map(|(m, why)| MistakeRow {
            answers: m.answers.iter().map(|&(value, count)| AnswerCount { count, value }).collect(),
            buffer: m.buffer.name(lang),
            right: m.right,
            students: &m.students,
            why,
            x: m.x,
            y: m.y,
        })
        .collect();
    let object =
        ClassJson { after, common_mistakes, not_graded, scene: scene.to_string_lossy().into_owned(), students };
    format!("{}\n", serde_json::to_string_pretty(&object).expect("serializing plain data cannot fail"))
}

/// `grade --format json`, as zsim writes it (the fields of each object in
/// the order of their names, as the file has always been written).
#[derive(Debug, serde::Serialize)]
struct ClassJson<'a> {
    /// Which states were graded.
    after: &'a str,
    common_mistakes: Vec<MistakeRow<'a>>,
    /// The folder's files that were not graded, and why (a misnamed answer names its student).
    not_graded: Vec<NotGraded<'a>>,
    scene: String,
    students: Vec<StudentRow<'a>>,
}

/// A student's row of [`ClassJson`].
#[derive(Debug, serde::Serialize)]
struct StudentRow<'a> {
    depth_wrong: Option<usize>,
    explained: Option<usize>,
    frame_wrong: Option<usize>,
    misconception: Option<&'static str>,
    score: serde_json::Number,
    status: String,
    student: &'a str,
    unanswered: usize,
}

/// A mistake several students made, in [`ClassJson`].
#[derive(Debug, serde::Serialize)]
struct MistakeRow<'a> {
    answers: Vec<AnswerCount>,
    buffer: String,
    right: u32,
    students: &'a [String],
    why: &'a str,
    x: u32,
    y: u32,
}

/// How many students gave a value.
#[derive(Debug, serde::Serialize)]
struct AnswerCount {
    count: usize,
    value: u32,
}

/// A file of the folder that was not graded.
#[derive(Debug, serde::Serialize)]
struct NotGraded<'a> {
    buffer: Option<String>,
    file: &'a str,
    reason: String,
    student: Option<&'a str>,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `grade --format json`'s shape: a student, a common mistake, a file not graded.
    #[test]
    fn a_class_json_has_its_shape() {
        let students = vec!["ana".to_string(), "bo".to_string()];
        let class = ClassJson {
            after: "final",
            common_mistakes: vec![MistakeRow {
                answers: vec![AnswerCount { count: 2, value: 3 }],
                buffer: "framebuffer".into(),
                right: 1,
                students: &students,
                why: "polygon 2 is nearer",
                x: 4,
                y: 5,
            }],
            not_graded: vec![NotGraded {
                buffer: None,
                file: "notes.txt",
                reason: "not an answer".into(),
                student: None,
            }],
            scene: "rogers.json".into(),
            students: vec![StudentRow {
                depth_wrong: Some(0),
                explained: None,
                frame_wrong: Some(2),
                misconception: None,
                score: "87.5".parse().unwrap(),
                status: "wrong".into(),
                student: "ana",
                unanswered: 0,
            }],
        };
        crate::shape_snapshot("class_json", &class);
    }
}
