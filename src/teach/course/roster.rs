//! A class's roster, read from the files teachers already have: Moodle's
//! grade or participants export, Canvas's gradebook export, Gradescope's
//! roster, PrairieLearn's, or a plain list of one identity a line. The shape
//! is known by the header row; the identity is the column that names a
//! student to the platform (its default per shape, or the one chosen). A
//! roster is untrusted input: it comes through the door's size limit, and an
//! empty, duplicate (without case, as gradebooks match them) or unusable
//! identity is refused naming its line.

use std::path::{Path, PathBuf};

use crate::error::{Error, Refusal};
use crate::words::{Lang, printable};

/// The most students a roster may list.
pub const MAX_STUDENTS: usize = 10_000;

/// The longest identity, in bytes: it names the student's files and folder.
pub const MAX_IDENTITY_BYTES: usize = 200;

/// Where a roster comes from, known by its header row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RosterKind {
    /// Moodle's grade or participants export (`Email address`, `ID number`, `Username`).
    Moodle,
    /// Canvas's gradebook export (`Student`, `ID`, `SIS User ID`, `SIS Login ID`, `Section`).
    Canvas,
    /// Gradescope's roster (`Name`, `Email`, `SID`).
    Gradescope,
    /// PrairieLearn's roster (`UID`, `UIN`, `Name`).
    PrairieLearn,
    /// One identity a line, no header.
    Plain,
}

impl RosterKind {
    /// Its name, as the manifest records it.
    pub fn name(self) -> &'static str {
        match self {
            RosterKind::Moodle => "moodle",
            RosterKind::Canvas => "canvas",
            RosterKind::Gradescope => "gradescope",
            RosterKind::PrairieLearn => "prairielearn",
            RosterKind::Plain => "plain",
        }
    }

    /// The columns that can name a student, the default first.
    pub fn identity_columns(self) -> &'static [&'static str] {
        match self {
            RosterKind::Moodle => &["Email address", "ID number", "Username"],
            RosterKind::Canvas => &["SIS Login ID", "SIS User ID", "ID"],
            RosterKind::Gradescope => &["Email", "SID"],
            RosterKind::PrairieLearn => &["UID", "UIN"],
            RosterKind::Plain => &[],
        }
    }

    /// The shape a header row shows, if any.
    fn of(headers: &[String]) -> Option<RosterKind> {
        let has = |name: &str| headers.iter().any(|h| h.eq_ignore_ascii_case(name));
        if has("Student") && (has("SIS Login ID") || has("SIS User ID")) {
            Some(RosterKind::Canvas)
        } else if has("UID") {
            Some(RosterKind::PrairieLearn)
        } else if has("SID") || (has("Email") && (has("Name") || has("First Name"))) {
            Some(RosterKind::Gradescope)
        } else if has("Email address") || has("ID number") || has("Username") {
            Some(RosterKind::Moodle)
        } else {
            None
        }
    }
}

/// One student of the roster.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Student {
    /// What names the student to the platform: their files are `IDENTITY.frame.txt`.
    pub identity: String,
    /// The name printed on their worksheet (the identity where the roster has none).
    pub name: String,
    /// Every other identity the row gives (an email beside an SID), which an
    /// autograder may be handed instead.
    pub aliases: Vec<String>,
    /// The roster's line the student's row starts on (from 1).
    pub line: usize,
}

/// A roster read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Roster {
    /// Where it comes from.
    pub shape: RosterKind,
    /// The header of the column that names the students (empty for a plain list).
    pub column: String,
    /// The students, in the roster's order.
    pub students: Vec<Student>,
}

/// What is wrong with a roster, at its line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Unusable {
    /// No row at all.
    Empty,
    /// A header row zsim does not know, with more than one column.
    UnknownHeader {
        /// The headers found.
        headers: Vec<String>,
    },
    /// `--identity` names no column of the roster.
    NoSuchColumn {
        /// The column asked for.
        column: String,
        /// The roster's columns.
        headers: Vec<String>,
    },
    /// A row without an identity.
    EmptyIdentity {
        /// Its line.
        line: usize,
        /// The identity column.
        column: String,
    },
    /// An identity already on the roster (without case).
    Duplicate {
        /// Its line.
        line: usize,
        /// The identity, as written there.
        identity: String,
        /// The line it is first on.
        first: usize,
    },
    /// An identity that cannot name a student's files.
    Unnameable {
        /// Its line.
        line: usize,
        /// The identity, as shown.
        identity: String,
    },
    /// More students than zsim makes exercises for at once.
    TooMany {
        /// The limit.
        max: usize,
    },
    /// A row the CSV reader could not read.
    Unreadable {
        /// Its line.
        line: usize,
        /// What the reader said.
        reason: String,
    },
}

/// A roster refused: the file and what is wrong in it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RosterError {
    /// The roster file.
    pub path: PathBuf,
    /// What is wrong.
    pub problem: Unusable,
}

impl Refusal for RosterError {
    fn message(&self, lang: Lang) -> String {
        let path = crate::words::shown_path(&self.path);
        let quoted =
            |items: &[String]| items.iter().map(|h| format!("\"{}\"", printable(h))).collect::<Vec<_>>().join(", ");
        match &self.problem {
            Unusable::Empty => words!(lang, "roster-empty", path = path),
            Unusable::UnknownHeader { headers } => {
                words!(lang, "roster-unknown-header", path = path, headers = quoted(headers))
            }
            Unusable::NoSuchColumn { column, headers } => words!(
                lang,
                "roster-no-such-column",
                path = path,
                column = printable(column).into_owned(),
                headers = quoted(headers)
            ),
            Unusable::EmptyIdentity { line, column } => {
                words!(lang, "roster-empty-identity", path = path, line = *line, column = column.as_str())
            }
            Unusable::Duplicate { line, identity, first } => words!(
                lang,
                "roster-duplicate",
                path = path,
                line = *line,
                identity = printable(identity).into_owned(),
                first = *first
            ),
            Unusable::Unnameable { line, identity } => {
                words!(lang, "roster-unnameable", path = path, line = *line, identity = identity.as_str())
            }
            Unusable::TooMany { max } => words!(lang, "roster-too-many", path = path, max = *max),
            Unusable::Unreadable { line, reason } => {
                words!(lang, "roster-unreadable", path = path, line = *line, reason = reason.as_str())
            }
        }
    }
}

/// Reads the roster at `path` through the door, its identities from
/// `identity` (a column's header, without case) or the shape's default.
pub fn load(path: &Path, identity: Option<&str>) -> Result<Roster, Error> {
    let text = crate::door::read_text(path)?;
    parse(&text, identity).map_err(|problem| RosterError { path: path.to_owned(), problem }.into())
}

/// Reads a roster's text (see [`load`]).
pub fn parse(text: &str, identity: Option<&str>) -> Result<Roster, Unusable> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut reader = csv::ReaderBuilder::new().has_headers(false).flexible(true).from_reader(text.as_bytes());
    let mut records = reader.records();
    let header = match records.next() {
        None => return Err(Unusable::Empty),
        Some(record) => record.map_err(|e| unreadable(&e))?,
    };
    let headers: Vec<String> = header.iter().map(|h| h.trim().to_string()).collect();
    let Some(shape) = RosterKind::of(&headers) else {
        // A first line of one column is a plain list's first identity.
        if headers.len() == 1 && !text.lines().next().unwrap_or("").contains(',') {
            return plain(text, identity);
        }
        return Err(Unusable::UnknownHeader { headers });
    };
    let position = |name: &str| headers.iter().position(|h| h.eq_ignore_ascii_case(name));
    let column = match identity {
        Some(asked) => position(asked.trim())
            .ok_or_else(|| Unusable::NoSuchColumn { column: asked.to_string(), headers: headers.clone() })?,
        None => shape.identity_columns().iter().find_map(|c| position(c)).expect("the shape was known by one of them"),
    };
    let others: Vec<usize> =
        shape.identity_columns().iter().filter_map(|c| position(c)).filter(|c| *c != column).collect();
    let name_of = |record: &csv::StringRecord| -> String {
        let cell = |name: &str| position(name).and_then(|i| record.get(i)).map(str::trim).unwrap_or("");
        match shape {
            RosterKind::Canvas => cell("Student").to_string(),
            _ if !cell("Name").is_empty() => cell("Name").to_string(),
            _ => {
                let last = if cell("Last name").is_empty() { cell("Surname") } else { cell("Last name") };
                format!("{} {}", cell("First name"), last).trim().to_string()
            }
        }
    };
    let mut students = Vec::new();
    let mut seen = std::collections::HashMap::new();
    for record in records {
        let record = record.map_err(|e| unreadable(&e))?;
        let line = record.position().map_or(0, |p| p.line() as usize);
        if record.iter().all(|cell| cell.trim().is_empty()) {
            continue;
        }
        // Canvas's second row gives each assignment's points, not a student.
        let first = record.get(0).unwrap_or("").trim();
        if shape == RosterKind::Canvas && (first == "Points Possible" || first == "Student, Test") {
            continue;
        }
        let id = record.get(column).unwrap_or("").trim().to_string();
        let aliases = others
            .iter()
            .filter_map(|i| record.get(*i).map(str::trim))
            .filter(|a| !a.is_empty() && !a.eq_ignore_ascii_case(&id))
            .map(str::to_string)
            .collect();
        let name = name_of(&record);
        add(&mut students, &mut seen, Student { identity: id, name, aliases, line }, &headers[column])?;
    }
    if students.is_empty() {
        return Err(Unusable::Empty);
    }
    Ok(Roster { shape, column: headers[column].clone(), students })
}

/// A plain list: one identity a line, blank lines skipped.
fn plain(text: &str, identity: Option<&str>) -> Result<Roster, Unusable> {
    if let Some(column) = identity {
        return Err(Unusable::NoSuchColumn { column: column.to_string(), headers: Vec::new() });
    }
    let mut students = Vec::new();
    let mut seen = std::collections::HashMap::new();
    for (n, line) in text.lines().enumerate() {
        let id = line.trim();
        if id.is_empty() {
            continue;
        }
        let student = Student { identity: id.to_string(), name: id.to_string(), aliases: Vec::new(), line: n + 1 };
        add(&mut students, &mut seen, student, "")?;
    }
    if students.is_empty() {
        return Err(Unusable::Empty);
    }
    Ok(Roster { shape: RosterKind::Plain, column: String::new(), students })
}

/// Adds a student after checking their identity: not empty, not on the
/// roster already (without case), usable as a file's name, within the count.
fn add(
    students: &mut Vec<Student>,
    seen: &mut std::collections::HashMap<String, usize>,
    mut student: Student,
    column: &str,
) -> Result<(), Unusable> {
    let line = student.line;
    if student.identity.is_empty() {
        return Err(Unusable::EmptyIdentity { line, column: column.to_string() });
    }
    if !nameable(&student.identity) {
        return Err(Unusable::Unnameable { line, identity: printable(&student.identity).into_owned() });
    }
    if let Some(first) = seen.get(&student.identity.to_lowercase()) {
        return Err(Unusable::Duplicate { line, identity: student.identity, first: *first });
    }
    if students.len() == MAX_STUDENTS {
        return Err(Unusable::TooMany { max: MAX_STUDENTS });
    }
    seen.insert(student.identity.to_lowercase(), line);
    if student.name.is_empty() {
        student.name = student.identity.clone();
    }
    students.push(student);
    Ok(())
}

/// Whether an identity can name a student's files and folder on every
/// system a class uses: no separator, no control character, no leading dot,
/// none of the characters Windows refuses, within [`MAX_IDENTITY_BYTES`].
pub fn nameable(identity: &str) -> bool {
    identity.len() <= MAX_IDENTITY_BYTES
        && !identity.starts_with('.')
        && !identity
            .chars()
            .any(|c| c.is_control() || matches!(c, '/' | '\\' | ':' | '*' | '?' | '"' | '<' | '>' | '|'))
}

fn unreadable(error: &csv::Error) -> Unusable {
    let line = error.position().map_or(0, |p| p.line() as usize);
    Unusable::Unreadable { line, reason: error.to_string() }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ids(roster: &Roster) -> Vec<&str> {
        roster.students.iter().map(|s| s.identity.as_str()).collect()
    }

    #[test]
    fn a_canvas_export_skips_its_points_possible_row_and_reads_quoted_names() {
        let text = "\u{feff}Student,ID,SIS User ID,SIS Login ID,Section,Homework 1 (12)\r\n\
            \"    Points Possible\",,,,,10\r\n\
            \"Lima, Ana\",101,A1,ana,Sec 1,\r\n\
            \"Østby, Bjørn\",102,B2,bjorn,Sec 1,\r\n";
        let roster = parse(text, None).unwrap();
        assert_eq!((roster.shape, roster.column.as_str()), (RosterKind::Canvas, "SIS Login ID"));
        assert_eq!(ids(&roster), ["ana", "bjorn"]);
        assert_eq!(roster.students[1].name, "Østby, Bjørn");
        assert_eq!(roster.students[0].aliases, ["A1", "101"]);
        assert_eq!(ids(&parse(text, Some("sis user id")).unwrap()), ["A1", "B2"]);
    }

    #[test]
    fn each_platforms_roster_is_known_by_its_header() {
        let moodle = "First name,Last name,ID number,Institution,Department,Email address\n\
            Ana,Lima,1001,,,ana@uni.edu\nBo,Chen,1002,,,bo@uni.edu\n";
        let roster = parse(moodle, None).unwrap();
        assert_eq!(
            (roster.shape, ids(&roster), roster.students[0].name.as_str()),
            (RosterKind::Moodle, vec!["ana@uni.edu", "bo@uni.edu"], "Ana Lima")
        );
        assert_eq!(ids(&parse(moodle, Some("ID number")).unwrap()), ["1001", "1002"]);
        let gradescope = "Name,Email,SID\nAna Lima,ana@uni.edu,s1\n";
        assert_eq!(parse(gradescope, None).unwrap().shape, RosterKind::Gradescope);
        let prairielearn = "UID,UIN,Name,Role\nana@uni.edu,1001,Ana Lima,Student\n";
        assert_eq!(ids(&parse(prairielearn, None).unwrap()), ["ana@uni.edu"]);
        let plain = "ana@uni.edu\r\n\r\nbo@uni.edu\r\n";
        let roster = parse(plain, None).unwrap();
        assert_eq!((roster.shape, ids(&roster)), (RosterKind::Plain, vec!["ana@uni.edu", "bo@uni.edu"]));
    }

    #[test]
    fn bad_identities_are_refused_naming_their_line() {
        let text = "Name,Email,SID\nAna,ana@uni.edu,1\nBo,,2\n";
        assert_eq!(parse(text, None), Err(Unusable::EmptyIdentity { line: 3, column: "Email".into() }));
        let text = "Name,Email,SID\nAna,ana@uni.edu,1\nAna L,ANA@uni.edu,2\n";
        assert_eq!(parse(text, None), Err(Unusable::Duplicate { line: 3, identity: "ANA@uni.edu".into(), first: 2 }));
        let text = "Name,Email,SID\nAna,../ana,1\n";
        assert_eq!(parse(text, None), Err(Unusable::Unnameable { line: 2, identity: "../ana".into() }));
        let text = "Given,Family\nAna,Lima\n";
        assert!(matches!(parse(text, None), Err(Unusable::UnknownHeader { .. })));
        assert!(matches!(parse("Name,Email,SID\n", None), Err(Unusable::Empty)));
        assert!(matches!(parse("Name,Email,SID\nA,a,1\n", Some("Login")), Err(Unusable::NoSuchColumn { .. })));
    }
}
