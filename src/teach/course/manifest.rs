//! A class's manifest, `variants.json`: the settings every variant was made
//! with and, for each student, the identity, the printable variant code,
//! the seed it came from and **the scene itself**, with the hard cases it
//! holds and how far each wrong rule's answer lies from its key. Every
//! command that grades reads the scene stored here and recomputes the key
//! from it, so a later zsim, or a teacher's edit of a scene, regrades
//! exactly; the seed only says where the scene came from.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use serde_json::value::RawValue;

use crate::error::{Error, Refusal};
use crate::observe::explain::Buffer;
use crate::scene::Scene;
use crate::teach::grade::file_kind;
use crate::words::{Lang, printable};

/// What the manifest's `format` says: the layout this zsim reads and writes.
pub const FORMAT: &str = "zsim class variants 1";

/// The manifest.
#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Manifest {
    /// [`FORMAT`].
    pub format: String,
    /// The course's seed, which every student's seed comes from.
    pub course_seed: u64,
    /// Where the roster came from (`moodle`, `canvas`, `gradescope`, `prairielearn`, `plain`).
    pub roster: String,
    /// The roster's column that names the students (empty for a plain list).
    pub identity_column: String,
    /// The settings every variant was made with.
    pub settings: Settings,
    /// What each student hands in: `frame`, `depth` or both.
    pub hand_in: Vec<String>,
    /// The students, in the roster's order.
    pub students: Vec<Variant>,
}

/// The settings of a class's variants.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Settings {
    /// Raster width.
    pub width: u32,
    /// Raster height.
    pub height: u32,
    /// Polygons in each scene.
    pub polygons: usize,
    /// Framebuffer bits.
    pub frame_bits: u32,
    /// z-buffer bits.
    pub depth_bits: u32,
    /// The hard cases asked for, by name.
    pub hard: Vec<String>,
    /// How many times each asked case arises in every variant (polygons it
    /// arises in; pairs of polygons for `intersecting`).
    pub times: usize,
    /// The fewest cells each required wrong rule's answer differs from the key in.
    pub distinct: usize,
    /// The wrong rules every variant tells apart from the key, by name.
    pub rules: Vec<String>,
    /// `book` or `free`.
    pub style: String,
    /// With the book style: the fewest centres each polygon covers.
    pub min_pixels: u32,
}

/// One student's variant.
#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Variant {
    /// What names the student to the platform; their files are `IDENTITY.frame.txt`.
    pub identity: String,
    /// The name on their worksheet.
    pub name: String,
    /// Other identities of theirs the roster gave (an email beside an SID).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub aliases: Vec<String>,
    /// The printable variant code on their worksheet and answer files.
    pub code: String,
    /// The seed their scene came from.
    pub seed: u64,
    /// How many times they were given a new variant (`--reseed`).
    pub attempt: u32,
    /// The scene itself, as zsim's scene JSON.
    pub scene: Box<RawValue>,
    /// Each hard case and how many times it arises in the scene.
    pub cases: Vec<Count>,
    /// Each wrong rule and how many cells its answer differs from the key in.
    pub separations: Vec<Count>,
}

/// A name and a count.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Count {
    /// The hard case's or the wrong rule's name.
    pub name: String,
    /// How many.
    pub count: usize,
}

impl Manifest {
    /// The buffers each student hands in.
    pub fn buffers(&self) -> Vec<Buffer> {
        [Buffer::Frame, Buffer::Depth].into_iter().filter(|b| self.hand_in.iter().any(|h| h == file_kind(*b))).collect()
    }

    /// The student whose identity, or one of whose aliases, is `who`, compared without case.
    pub fn student(&self, who: &str) -> Option<usize> {
        let who = who.trim().to_lowercase();
        let by = |f: &dyn Fn(&Variant) -> bool| self.students.iter().position(f);
        by(&|v| v.identity.to_lowercase() == who).or_else(|| by(&|v| v.aliases.iter().any(|a| a.to_lowercase() == who)))
    }

    /// What every variant holds, in one sentence.
    pub fn summary(&self, lang: Lang) -> String {
        let settings = &self.settings;
        let hard =
            if settings.hard.is_empty() { words!(lang, "exercise-notes-no-case") } else { settings.hard.join(", ") };
        words!(
            lang,
            "class-summary",
            students = self.students.len(),
            seed = self.course_seed.to_string(),
            width = settings.width,
            height = settings.height,
            polygons = settings.polygons,
            hard = hard,
            times = settings.times,
            rules = settings.rules.join(", "),
            distinct = settings.distinct
        )
    }

    /// The pretty JSON written to `variants.json`.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a manifest is plain data") + "\n"
    }
}

/// A manifest that cannot be used.
#[derive(Debug)]
pub struct ManifestError {
    /// The manifest file.
    pub path: PathBuf,
    /// Where in it (`students[3].scene`), where known.
    pub place: String,
    /// What is wrong.
    pub problem: ManifestProblem,
}

/// What is wrong with a manifest.
#[derive(Debug)]
pub enum ManifestProblem {
    /// Not JSON of the manifest's layout.
    Layout(String),
    /// Another layout's `format`.
    Format(String),
    /// A `hand_in` that is neither `frame` nor `depth`, or none.
    HandIn,
    /// Two students with one identity (without case) or one code.
    Twice(String),
    /// An identity that cannot name a student's files.
    Unnameable(String),
    /// A student's scene that zsim cannot draw: the scene's own message.
    Scene(Box<Error>),
}

impl Refusal for ManifestError {
    fn message(&self, lang: Lang) -> String {
        let path = crate::words::shown_path(&self.path);
        let place = if self.place.is_empty() { path } else { format!("{path}: {}", self.place) };
        match &self.problem {
            ManifestProblem::Layout(why) => words!(lang, "manifest-layout", place = place, why = why.as_str()),
            ManifestProblem::Format(found) => {
                words!(lang, "manifest-format", place = place, found = printable(found).into_owned(), expected = FORMAT)
            }
            ManifestProblem::HandIn => words!(lang, "manifest-hand-in", place = place),
            ManifestProblem::Twice(what) => {
                words!(lang, "manifest-twice", place = place, what = printable(what).into_owned())
            }
            ManifestProblem::Unnameable(who) => {
                words!(lang, "manifest-unnameable", place = place, identity = printable(who).into_owned())
            }
            ManifestProblem::Scene(error) => {
                words!(lang, "manifest-scene", place = place, why = error.message(lang))
            }
        }
    }
}

/// A manifest read through the door, with every student's scene read and
/// checked: the scenes in the students' order.
#[derive(Debug)]
pub struct Loaded {
    /// The manifest.
    pub manifest: Manifest,
    /// Each student's scene, in the manifest's order.
    pub scenes: Vec<Scene>,
}

/// Reads and checks the manifest at `path`.
pub fn load(path: &Path) -> Result<Loaded, Error> {
    let text = crate::door::read_text(path)?;
    read(&text, path)
}

/// Reads and checks a manifest's text (see [`load`]); `path` names it in messages.
pub fn read(text: &str, path: &Path) -> Result<Loaded, Error> {
    let refuse = |place: String, problem| Error::from(ManifestError { path: path.to_owned(), place, problem });
    let mut deserializer = serde_json::Deserializer::from_str(text);
    let manifest: Manifest = serde_path_to_error::deserialize(&mut deserializer).map_err(|e| {
        let place = e.path().to_string();
        refuse(if place == "." { String::new() } else { place }, ManifestProblem::Layout(e.into_inner().to_string()))
    })?;
    if manifest.format != FORMAT {
        return Err(refuse("format".into(), ManifestProblem::Format(manifest.format.clone())));
    }
    if manifest.hand_in.is_empty() || manifest.hand_in.iter().any(|h| h != "frame" && h != "depth") {
        return Err(refuse("hand_in".into(), ManifestProblem::HandIn));
    }
    let mut seen = std::collections::HashMap::new();
    let mut scenes = Vec::with_capacity(manifest.students.len());
    for (k, variant) in manifest.students.iter().enumerate() {
        let place = format!("students[{k}]");
        if !super::roster::nameable(&variant.identity) || variant.identity.is_empty() {
            return Err(refuse(place, ManifestProblem::Unnameable(variant.identity.clone())));
        }
        for key in [variant.identity.to_lowercase(), format!("code {}", variant.code)] {
            if seen.insert(key.clone(), k).is_some() {
                return Err(refuse(place, ManifestProblem::Twice(key)));
            }
        }
        // The scene is named as the student knows it, their own scene.json.
        let shown = Path::new("scene.json");
        let scene = Scene::from_json(variant.scene.get(), shown).map_err(|e| {
            refuse(format!("{place}.scene ({})", variant.identity), ManifestProblem::Scene(Box::new(e)))
        })?;
        if scene.polygons.is_empty() || scene.clear_depth.level().is_none() {
            let why = Error::from(crate::teach::grade::class::GradeRefused::ExactDepths { path: shown.to_owned() });
            return Err(refuse(format!("{place}.scene"), ManifestProblem::Scene(Box::new(why))));
        }
        scenes.push(scene);
    }
    Ok(Loaded { manifest, scenes })
}

/// A printable variant code from a seed: six letters and digits of
/// Crockford's base 32 (no I, L, O or U, which read as 1, 0 or V), as
/// `7KQ-M3X`.
pub fn code_of(seed: u64) -> String {
    const ALPHABET: &[u8; 32] = b"0123456789ABCDEFGHJKMNPQRSTVWXYZ";
    let mut bits = seed ^ (seed >> 32);
    let mut code = String::with_capacity(7);
    for k in 0..6 {
        if k == 3 {
            code.push('-');
        }
        code.push(ALPHABET[(bits & 31) as usize] as char);
        bits >>= 5;
    }
    code
}

/// The variant code an answer file's comment line names (`# variant CODE`,
/// anywhere in a line starting with `#`), if any.
pub fn code_in(text: &str) -> Option<&str> {
    text.lines().filter(|line| line.trim_start().starts_with('#')).find_map(|line| {
        let (_, rest) = line.split_once("variant ")?;
        let code = rest.split_whitespace().next()?.trim_end_matches([',', ';', ':', ')', '.']);
        (code.len() == 7 && code.as_bytes()[3] == b'-').then_some(code)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_six_crockford_letters_read_back_from_an_answer_file() {
        assert_eq!(code_of(0), "000-000");
        let code = code_of(0x1234_5678_9abc_def0);
        assert!(code.chars().all(|c| c == '-' || "0123456789ABCDEFGHJKMNPQRSTVWXYZ".contains(c)), "{code}");
        let file = format!("# framebuffer, variant {code}, Ana Lima\n0 0\n");
        assert_eq!(code_in(&file), Some(code.as_str()));
        assert_eq!(code_in("0 0\n# a note\n"), None);
    }
}
