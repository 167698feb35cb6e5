//! A class folder graded against the manifest: each student's files found
//! by their identity (or an alias, without case), each graded against the
//! key recomputed from the scene the manifest stores for them, with the
//! diagnosis on their own scene. Every student of the manifest gets a row,
//! with nothing handed in scoring 0; what each must hand in is the
//! manifest's, never inferred from the folder. A file is named out loud
//! when its identity is not on the roster, when it is misnamed
//! (`ana_frame.txt`), when it carries another student's variant code (swapped
//! sheets), or when two files answer one buffer of one student. Wrong cells
//! are also counted by the kind of case behind them, which means something
//! across different scenes where a cell does not.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use rayon::prelude::*;

use crate::door::{Links, read_text_with};
use crate::error::Error;
use crate::observe::explain::Buffer;
use crate::teach::check::answer_from_text;
use crate::teach::check::diagnose::{Diagnoser, Misconception};
use crate::teach::exercise::{HardCase, census};
use crate::teach::grade::{Grade, Handed, Key, Submission, cleared, file_kind, grade};
use crate::words::{Lang, shown_name};

use super::fair::{fnv, key_of};
use super::manifest::{Loaded, code_in};

/// A file of the class folder graded for a student, or named for them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct HandedFile {
    /// The buffer it answers for.
    pub buffer: Buffer,
    /// Its name, as shown.
    pub name: String,
    /// Where it is (never shown to the student).
    pub path: PathBuf,
}

/// Something about a student's files the teacher and the student are told.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Note {
    /// A file that looks like theirs but is misnamed: not graded.
    Misnamed {
        /// The file, as shown.
        file: String,
        /// The name it should have.
        expected: String,
    },
    /// A file that carries another student's variant code.
    Swapped {
        /// The file, as shown.
        file: String,
        /// The code it carries.
        code: String,
        /// The student whose code it is.
        owner: String,
    },
    /// Two files or more answer one buffer: none of them graded.
    TwoFiles {
        /// The buffer.
        buffer: Buffer,
        /// The files, as shown.
        files: Vec<String>,
    },
}

impl Note {
    /// One line in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match self {
            Note::Misnamed { file, expected } => {
                words!(lang, "course-misnamed", file = file.as_str(), expected = expected.as_str())
            }
            Note::Swapped { file, code, owner } => {
                words!(lang, "course-swapped", file = file.as_str(), code = code.as_str(), owner = owner.as_str())
            }
            Note::TwoFiles { buffer, files } => {
                words!(lang, "course-two-files", buffer = buffer.name(lang), files = files.join(", "))
            }
        }
    }
}

/// A file of the class folder that is nobody's on the roster.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Stray {
    /// An answer file whose identity is not on the roster.
    NotOnRoster {
        /// The file, as shown.
        file: String,
        /// The identity its name gives.
        identity: String,
    },
    /// Not an answer file, nor near one.
    NotAnAnswer {
        /// The file, as shown.
        file: String,
    },
}

impl Stray {
    /// One line in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match self {
            Stray::NotOnRoster { file, identity } => {
                words!(lang, "course-not-on-roster", file = file.as_str(), identity = identity.as_str())
            }
            Stray::NotAnAnswer { file } => words!(lang, "grade-skipped", file = file.as_str()),
        }
    }
}

/// One student's row.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Row {
    /// The student's index in the manifest.
    pub index: usize,
    /// Their grade (its `student` is their identity).
    pub grade: Grade,
    /// Their variant code.
    pub code: String,
    /// The files graded.
    pub files: Vec<HandedFile>,
    /// What they and the teacher are told about their files.
    pub notes: Vec<Note>,
    /// Per hard case of [`HardCase::ALL`]: whether their scene holds it, and
    /// how many of their wrong cells it touches.
    pub kinds: [(bool, usize); 7],
    /// Hashes of what the score came from: the scene, the key, the files read.
    pub fingerprint: Fingerprint,
}

/// What a score came from, hashed, so that a regrade can say why a score changed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Fingerprint {
    /// The scene's JSON.
    pub scene: u64,
    /// The key.
    pub key: u64,
    /// The files' bytes, in buffer order.
    pub files: u64,
}

/// A class graded against its manifest.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CourseGrades {
    /// A row per student of the manifest, in its order.
    pub rows: Vec<Row>,
    /// The folder's files that are nobody's on the roster.
    pub strays: Vec<Stray>,
}

impl CourseGrades {
    /// The grades, in the rows' order.
    pub fn grades(&self) -> Vec<&Grade> {
        self.rows.iter().map(|row| &row.grade).collect()
    }

    /// The wrong rules named for the students, each with how many, most first.
    pub fn causes(&self) -> Vec<(Misconception, usize)> {
        crate::teach::grade::causes(&self.grades())
    }

    /// Per hard case: the students whose scene holds it, how many of them got
    /// a cell it touches wrong, and how many such cells in all.
    pub fn by_kind(&self) -> Vec<(HardCase, usize, usize, usize)> {
        HardCase::ALL
            .into_iter()
            .map(|case| {
                let k = case as usize;
                let holding = self.rows.iter().filter(|r| r.kinds[k].0).count();
                let wrong = self.rows.iter().filter(|r| r.kinds[k].1 > 0).count();
                let cells = self.rows.iter().map(|r| r.kinds[k].1).sum();
                (case, holding, wrong, cells)
            })
            .collect()
    }
}

/// Grades the class folder `class` against the manifest `loaded`, messages in `lang`.
pub fn grade_course(lang: Lang, loaded: &Loaded, class: &Path) -> Result<CourseGrades, Error> {
    let manifest = &loaded.manifest;
    let buffers = manifest.buffers();
    let entries = std::fs::read_dir(class).map_err(|source| Error::Read { path: class.to_owned(), source })?;
    let mut names = Vec::new();
    for entry in entries {
        let entry = entry.map_err(|source| Error::Read { path: class.to_owned(), source })?;
        names.push((shown_name(Path::new(&entry.file_name())), entry.path()));
    }
    names.sort();
    let mut handed: Vec<Vec<HandedFile>> = vec![Vec::new(); manifest.students.len()];
    let mut notes: Vec<Vec<Note>> = vec![Vec::new(); manifest.students.len()];
    let mut strays = Vec::new();
    let lower: HashMap<String, usize> = manifest
        .students
        .iter()
        .enumerate()
        .flat_map(|(k, v)| {
            std::iter::once(v.identity.to_lowercase())
                .chain(v.aliases.iter().map(|a| a.to_lowercase()))
                .map(move |id| (id, k))
        })
        .collect();
    for (name, path) in names {
        let zsims_own = name.ends_with(".feedback.txt") || name == "common-mistakes.txt";
        if zsims_own {
            continue;
        }
        let answer = [Buffer::Frame, Buffer::Depth].into_iter().find_map(|buffer| {
            let stem = name.strip_suffix(&format!(".{}.txt", file_kind(buffer)))?;
            (!stem.is_empty()).then(|| (stem.to_string(), buffer))
        });
        match answer {
            Some((stem, buffer)) => match lower.get(&stem.to_lowercase()) {
                Some(&k) if buffers.contains(&buffer) => handed[k].push(HandedFile { buffer, name, path }),
                Some(_) => strays.push(Stray::NotAnAnswer { file: name }),
                None => strays.push(Stray::NotOnRoster { file: name, identity: stem }),
            },
            None => match misnamed(&name, &lower) {
                Some((k, buffer)) => {
                    let expected = format!("{}.{}.txt", manifest.students[k].identity, file_kind(buffer));
                    notes[k].push(Note::Misnamed { file: name, expected });
                }
                None => strays.push(Stray::NotAnAnswer { file: name }),
            },
        }
    }
    let codes: HashMap<&str, &str> = manifest.students.iter().map(|v| (v.code.as_str(), v.identity.as_str())).collect();
    let rows = manifest
        .students
        .par_iter()
        .zip(&loaded.scenes)
        .zip(handed.into_par_iter().zip(notes))
        .enumerate()
        .map(|(index, ((variant, scene), (files, mut notes)))| {
            let last = scene.polygons.len() - 1;
            let (frame, depth) = key_of(scene);
            let keys: Vec<Key> = buffers
                .iter()
                .map(|b| Key {
                    buffer: *b,
                    matrix: if *b == Buffer::Frame { frame.clone() } else { depth.clone() },
                    cleared: cleared(scene, *b),
                })
                .collect();
            let mut answers = Vec::new();
            let mut graded = Vec::new();
            let mut file_bytes = Vec::new();
            for buffer in &buffers {
                let mine: Vec<&HandedFile> = files.iter().filter(|f| f.buffer == *buffer).collect();
                let handed = match mine.as_slice() {
                    [] => Handed::Missing,
                    [file] => {
                        graded.push((*file).clone());
                        match read_text_with(&file.path, Links::Refuse) {
                            Err(error) => {
                                Handed::Malformed(crate::teach::check::as_the_student_sees(lang, &error, &file.path))
                            }
                            Ok(text) => {
                                file_bytes.extend(text.bytes());
                                if let Some(code) = code_in(&text).filter(|c| *c != variant.code)
                                    && let Some(owner) = codes.get(code)
                                {
                                    notes.push(Note::Swapped {
                                        file: file.name.clone(),
                                        code: code.into(),
                                        owner: owner.to_string(),
                                    });
                                }
                                match answer_from_text(&text, scene, *buffer) {
                                    Ok(answer) => Handed::Matrix(answer),
                                    Err(why) => Handed::Malformed(format!("{}: {}", file.name, why.message(lang))),
                                }
                            }
                        }
                    }
                    several => {
                        let names = several.iter().map(|f| f.name.clone()).collect();
                        notes.push(Note::TwoFiles { buffer: *buffer, files: names });
                        Handed::Missing
                    }
                };
                answers.push((*buffer, handed));
            }
            let submission = Submission { student: variant.identity.clone(), answers };
            let diagnoser = Diagnoser::new(scene, last);
            let (grade, wrong) = grade(&[submission], &keys, diagnoser.as_ref()).remove(0);
            let found = census(lang, scene);
            let mut kinds = [(false, 0); 7];
            for case in HardCase::ALL {
                let touched = wrong
                    .iter()
                    .flat_map(|w| &w.cells)
                    .filter(|cell| found.touches(case, scene.width, cell.x, cell.y))
                    .count();
                kinds[case as usize] = (found.count(case) > 0, touched);
            }
            let key_bytes = frame.iter().chain(&depth).flatten().flat_map(|v| v.to_le_bytes());
            // The scene as data, not as laid out: a manifest saved again by an editor keeps its hash.
            let scene = fnv(canonical(variant.scene.get()).into_bytes());
            let fingerprint = Fingerprint { scene, key: fnv(key_bytes), files: fnv(file_bytes) };
            Row { index, grade, code: variant.code.clone(), files: graded, notes, kinds, fingerprint }
        })
        .collect();
    Ok(CourseGrades { rows, strays })
}

/// A JSON text as data: its objects' keys sorted, no white space, so that
/// the same scene laid out otherwise (an editor's save) reads the same.
fn canonical(text: &str) -> String {
    fn write(value: &serde_json::Value, out: &mut String) {
        match value {
            serde_json::Value::Object(map) => {
                let mut keys: Vec<&String> = map.keys().collect();
                keys.sort();
                out.push('{');
                for (k, key) in keys.into_iter().enumerate() {
                    if k > 0 {
                        out.push(',');
                    }
                    out.push_str(&serde_json::Value::from(key.as_str()).to_string());
                    out.push(':');
                    write(&map[key], out);
                }
                out.push('}');
            }
            serde_json::Value::Array(items) => {
                out.push('[');
                for (k, item) in items.iter().enumerate() {
                    if k > 0 {
                        out.push(',');
                    }
                    write(item, out);
                }
                out.push(']');
            }
            other => out.push_str(&other.to_string()),
        }
    }
    match serde_json::from_str::<serde_json::Value>(text) {
        Ok(value) => {
            let mut out = String::new();
            write(&value, &mut out);
            out
        }
        Err(_) => text.to_string(),
    }
}

/// The student and buffer a misnamed file was meant for: a roster identity
/// (or alias), then a separator (`.`, `_`, `-` or a space), then `frame` or
/// `depth` but for letter case or one letter, then `.txt` or nothing (or
/// `.txt.txt`, as Windows hides the first).
fn misnamed(name: &str, identities: &HashMap<String, usize>) -> Option<(usize, Buffer)> {
    let lower = name.to_lowercase();
    let cuts = lower.char_indices().filter(|(_, c)| matches!(c, '.' | '_' | '-' | ' ')).map(|(i, _)| i);
    cuts.filter_map(|i| {
        let k = *identities.get(&lower[..i])?;
        let mut rest = &lower[i + 1..];
        while let Some(shorter) = rest.strip_suffix(".txt") {
            rest = shorter;
        }
        let buffer = [Buffer::Frame, Buffer::Depth]
            .into_iter()
            .find(|b| crate::teach::grade::class::one_edit(rest, file_kind(*b)))?;
        Some((i, k, buffer))
    })
    .max_by_key(|(i, ..)| *i)
    .map(|(_, k, buffer)| (k, buffer))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn misnamed_files_are_known_by_the_identity_before_them() {
        let ids: HashMap<String, usize> = [("eve".to_string(), 0), ("eve.li".to_string(), 1)].into_iter().collect();
        assert_eq!(misnamed("eve_frame.txt", &ids), Some((0, Buffer::Frame)));
        assert_eq!(misnamed("Eve-Depth.txt", &ids), Some((0, Buffer::Depth)));
        assert_eq!(misnamed("eve.frame", &ids), Some((0, Buffer::Frame)));
        assert_eq!(misnamed("eve.li.frme.txt", &ids), Some((1, Buffer::Frame)));
        assert_eq!(misnamed("eve.frame.txt.txt", &ids), Some((0, Buffer::Frame)));
        assert_eq!(misnamed("eve_notes.txt", &ids), None);
        assert_eq!(misnamed("bob_frame.txt", &ids), None);
    }
}
