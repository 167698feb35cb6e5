//! Gradebook imports: `grade --format moodle` and `--format canvas` write a
//! class's scores in the layout each platform imports. Moodle maps one
//! identity column (email address, ID number or username) to its users and
//! takes a grade column per item, refusing the whole file when a value lies
//! outside the item's range; Canvas takes its export's layout, `Student, ID,
//! SIS User ID, SIS Login ID, Section` then one column per assignment, and a
//! second row `Points Possible`. The identity is each student's file name
//! (`ana@uni.edu.frame.txt` gives `ana@uni.edu`); the grade is the share of
//! right cells times the points, with two decimals, always within 0 … points.

use zsim::grade::Grade;
use zsim::{Q, decimal};

use super::grade::csv_field;

/// Which column names the student in the import.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Identity {
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

impl Identity {
    /// The column's header as the platform writes it in its own exports.
    pub fn header(self) -> &'static str {
        match self {
            Identity::Email => "Email address",
            Identity::Idnumber => "ID number",
            Identity::Username => "Username",
            Identity::Id => "ID",
            Identity::SisUserId => "SIS User ID",
            Identity::SisLoginId => "SIS Login ID",
        }
    }

    /// Whether Moodle imports by this column (else Canvas does).
    pub fn is_moodle(self) -> bool {
        matches!(self, Identity::Email | Identity::Idnumber | Identity::Username)
    }
}

/// A student's grade out of `points`, with two decimals (rounded half up,
/// so never above `points`).
fn points_of(grade: &Grade, points: u32) -> String {
    decimal(grade.score * Q::from_integer(i128::from(points)), 2)
}

/// Moodle's gradebook import: the identity column, then the grade item.
pub fn moodle(rows: &[&Grade], identity: Identity, item: &str, points: u32) -> String {
    let mut text = format!("{},{}\n", identity.header(), csv_field(item));
    for grade in rows {
        text.push_str(&format!("{},{}\n", csv_field(&grade.student), points_of(grade, points)));
    }
    text
}

/// Canvas's gradebook import: its five identity columns, the assignment,
/// the `Points Possible` row; the student's name goes in `Student` and in
/// the identity column chosen.
pub fn canvas(rows: &[&Grade], identity: Identity, item: &str, points: u32) -> String {
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
