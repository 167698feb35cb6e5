//! A variant for each student, fair by construction: each student's seed
//! comes from the course's seed and their identity by a stable hash, and
//! their scene is the first candidate of that seed's sequence in which
//! every asked hard case arises exactly the asked number of times, every
//! other case not at all (but `hidden` where `intersecting` is asked, which
//! brings it), and every
//! required wrong rule's answer differs from the key in at least the asked
//! number of cells, both counted from the run itself ([`census`],
//! [`Diagnoser::separations`]). No two students share a scene, a key or a
//! code: a clash moves the student later in identity order to their next
//! attempt, so nobody else's variant changes.

use rayon::prelude::*;
use serde_json::value::RawValue;

use crate::error::Error;
use crate::observe::explain::Buffer;
use crate::scene::Scene;
use crate::simulate::events::Unobserved;
use crate::simulate::simulation::Simulation;
use crate::teach::check::answer::Matrix;
use crate::teach::check::diagnose::{Diagnoser, Misconception};
use crate::teach::exercise::{Census, HardCase, Spec, Unfit, search};
use crate::teach::grade::file_kind;
use crate::words::Lang;

use super::manifest::{Count, FORMAT, Manifest, Settings, Variant, code_of};
use super::roster::Roster;

/// What a class's variants are asked for.
#[derive(Debug, Clone)]
pub struct ClassSpec {
    /// The exercise every variant is made like; its seed is the course's seed.
    pub exercise: Spec,
    /// How many times each asked hard case arises in every variant.
    pub times: usize,
    /// The fewest cells each of `rules` differs from the key in, in every variant.
    pub distinct: usize,
    /// The wrong rules every variant tells apart from its key.
    pub rules: Vec<Misconception>,
    /// What each student hands in.
    pub hand_in: Vec<Buffer>,
}

/// The hard cases every variant of a class holds once by default.
pub const CLASS_HARD: &str = "vertex-on-scanline,centre-on-edge,half-depth,hidden";

/// The wrong rules a class's variants tell apart by default: every rule the
/// diagnosis knows but the three that the book's style makes rare or
/// impossible to separate in a small scene (no saturation, which needs
/// depths beyond the z-buffer's range; the test not strict, which needs a
/// depth exactly equal to a stored level; the rounded depth compared, which
/// needs a rounded tie against an earlier polygon); asking for `saturation`
/// adds `no-saturation`.
pub fn default_rules(hard: &[HardCase]) -> Vec<Misconception> {
    Misconception::ALL
        .into_iter()
        .filter(|m| match m {
            Misconception::NoSaturation => hard.contains(&HardCase::Saturation),
            Misconception::NotStrict | Misconception::RoundedCompared => false,
            _ => true,
        })
        .collect()
}

/// FNV-1a, 64 bits: the same bytes give the same hash on every machine.
pub fn fnv(bytes: impl IntoIterator<Item = u8>) -> u64 {
    bytes.into_iter().fold(0xcbf2_9ce4_8422_2325u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3))
}

/// A student's seed: the course's seed, their identity without case and
/// their attempt, hashed (FNV-1a, 64 bits, then SplitMix64's finalizer), so
/// the same roster gives the same seeds on every machine and version.
pub fn student_seed(course_seed: u64, identity: &str, attempt: u32) -> u64 {
    let bytes =
        course_seed.to_le_bytes().into_iter().chain(identity.to_lowercase().into_bytes()).chain(attempt.to_le_bytes());
    let mut hash = fnv(bytes);
    hash = (hash ^ (hash >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    hash = (hash ^ (hash >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    hash ^ (hash >> 31)
}

/// One variant made: its scene's JSON and scene, its census, how far each
/// wrong rule lies from its key, and the key.
#[derive(Debug, Clone)]
pub struct Made {
    /// The scene as zsim scene JSON.
    pub json: String,
    /// The scene.
    pub scene: Scene,
    /// Its hard cases.
    pub census: Census,
    /// Every wrong rule and the cells its answer differs from the key in.
    pub separations: Vec<(Misconception, usize)>,
    /// The key: the framebuffer and the z-buffer after the last polygon, top row first.
    pub key: (Matrix, Matrix),
}

/// The variant of `seed`: the first candidate of its sequence that `spec` accepts.
pub fn make_variant(lang: Lang, spec: &ClassSpec, seed: u64) -> Result<Made, Unfit> {
    let exercise = Spec { seed, ..spec.exercise.clone() };
    let last = exercise.polygons - 1;
    let (made, separations) = search(lang, &exercise, |scene, census| {
        if !HardCase::ALL.iter().all(|case| holds(&exercise.hard, *case, census.count(*case), spec.times)) {
            return None;
        }
        let separations = Diagnoser::new(scene, last)?.separations();
        let apart = spec.rules.iter().all(|rule| separations.iter().any(|(m, n)| m == rule && *n >= spec.distinct));
        apart.then_some(separations)
    })?;
    let census = super::super::exercise::census(lang, &made.scene);
    let key = key_of(&made.scene);
    Ok(Made { json: made.json, scene: made.scene, census, separations, key })
}

/// Whether a variant holding `case` `count` times is fair: an asked case
/// arises exactly `times` times, a case not asked never, unless an asked
/// case brings it (two polygons intersect only where one hides the other).
fn holds(asked: &[HardCase], case: HardCase, count: usize, times: usize) -> bool {
    if asked.contains(&case) {
        count == times
    } else {
        count == 0 || (case == HardCase::Hidden && asked.contains(&HardCase::Intersecting))
    }
}

/// The wrong rules named in a comma-separated list.
pub fn parse_rules(list: &str) -> Result<Vec<Misconception>, Error> {
    let mut rules = Vec::new();
    for name in list.split(',').map(str::trim).filter(|n| !n.is_empty()) {
        let rule = Misconception::ALL.into_iter().find(|m| m.name() == name).ok_or_else(|| {
            Error::from(ClassUnfit::NotARule {
                name: name.to_string(),
                names: Misconception::ALL.iter().map(|m| m.name().to_string()).collect(),
            })
        })?;
        if !rules.contains(&rule) {
            rules.push(rule);
        }
    }
    Ok(rules)
}

/// The buffers named in a comma-separated list (`frame`, `depth`), the framebuffer first.
pub fn parse_hand_in(list: &str) -> Result<Vec<Buffer>, Error> {
    let mut buffers = Vec::new();
    for name in list.split(',').map(str::trim).filter(|n| !n.is_empty()) {
        let buffer = match name {
            "frame" => Buffer::Frame,
            "depth" => Buffer::Depth,
            _ => return Err(ClassUnfit::HandIn { name: name.to_string() }.into()),
        };
        if !buffers.contains(&buffer) {
            buffers.push(buffer);
        }
    }
    buffers.sort_by_key(|b| *b != Buffer::Frame);
    if buffers.is_empty() {
        return Err(ClassUnfit::HandIn { name: String::new() }.into());
    }
    Ok(buffers)
}

/// The key of a scene: its buffers after the last polygon, top row first.
pub fn key_of(scene: &Scene) -> (Matrix, Matrix) {
    let mut simulation = Simulation::new(scene);
    simulation.finish(&mut Unobserved);
    let buffers = simulation.buffers();
    (buffers.frame_rows(), buffers.depth_level_rows().expect("a class's scenes keep a quantized z-buffer"))
}

/// A class's variants that cannot be made.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ClassUnfit {
    /// One student's variant could not be made as asked.
    Student {
        /// The student.
        identity: String,
        /// Why.
        unfit: Unfit,
    },
    /// `--reseed` names someone not on the roster.
    NotOnRoster {
        /// The identity given.
        identity: String,
    },
    /// The asked times or distinct cells are out of range.
    Counts,
    /// A name in `--rules` that is no wrong rule.
    NotARule {
        /// The name given.
        name: String,
        /// The wrong rules' names.
        names: Vec<String>,
    },
    /// A name in `--hand-in` that is no buffer (or none given).
    HandIn {
        /// The name given.
        name: String,
    },
}

impl crate::error::Refusal for ClassUnfit {
    fn message(&self, lang: Lang) -> String {
        match self {
            ClassUnfit::Student { identity, unfit } => words!(
                lang,
                "class-student-unfit",
                identity = crate::words::printable(identity).into_owned(),
                why = crate::error::Refusal::message(unfit, lang)
            ),
            ClassUnfit::NotOnRoster { identity } => {
                words!(lang, "class-reseed-not-on-roster", identity = crate::words::printable(identity).into_owned())
            }
            ClassUnfit::Counts => words!(lang, "class-counts"),
            ClassUnfit::NotARule { name, names } => words!(
                lang,
                "class-not-a-rule",
                name = crate::words::printable(name).into_owned(),
                names = names.join(", ")
            ),
            ClassUnfit::HandIn { name } => {
                words!(lang, "class-hand-in-list", name = crate::words::printable(name).into_owned())
            }
        }
    }
}

/// Every student's variant, in the roster's order, with the manifest that
/// stores them. `reseed` names students (by identity, without case) to be
/// given their next variant, once for each time they are named.
pub fn make_class(lang: Lang, spec: &ClassSpec, roster: &Roster, reseed: &[String]) -> Result<Manifest, Error> {
    if !(1..=8).contains(&spec.times) || !(1..=1024).contains(&spec.distinct) {
        return Err(ClassUnfit::Counts.into());
    }
    let lower: Vec<String> = roster.students.iter().map(|s| s.identity.to_lowercase()).collect();
    if let Some(unknown) = reseed.iter().find(|r| !lower.contains(&r.trim().to_lowercase())) {
        return Err(ClassUnfit::NotOnRoster { identity: unknown.clone() }.into());
    }
    let mut attempts: Vec<u32> =
        lower.iter().map(|id| reseed.iter().filter(|r| r.trim().to_lowercase() == *id).count() as u32).collect();
    let course = spec.exercise.seed;
    let make = |k: usize, attempt: u32| {
        let seed = student_seed(course, &lower[k], attempt);
        make_variant(lang, spec, seed)
            .map(|made| (seed, Kept::of(made)))
            .map_err(|unfit| Error::from(ClassUnfit::Student { identity: roster.students[k].identity.clone(), unfit }))
    };
    // What each variant keeps once made: its scene's text, its counts and its key's hash, so that a
    // class of thousands holds its manifest, not every variant's drawing.
    let mut made: Vec<(u64, Kept)> =
        (0..lower.len()).into_par_iter().map(|k| make(k, attempts[k])).collect::<Result<_, _>>()?;
    // Clashes of scene, key or code: the later student in identity order moves on, again until none.
    loop {
        let clashing = clashes(&made, &lower);
        if clashing.is_empty() {
            break;
        }
        for k in clashing {
            attempts[k] += 1;
            made[k] = make(k, attempts[k])?;
        }
    }
    let students = roster
        .students
        .iter()
        .zip(&made)
        .zip(&attempts)
        .map(|((student, (seed, made)), attempt)| Variant {
            identity: student.identity.clone(),
            name: student.name.clone(),
            aliases: student.aliases.clone(),
            code: code_of(*seed),
            seed: *seed,
            attempt: *attempt,
            scene: RawValue::from_string(made.json.clone()).expect("an exercise's scene is JSON"),
            cases: HardCase::ALL
                .iter()
                .map(|c| Count { name: c.name().into(), count: made.cases[*c as usize] })
                .collect(),
            separations: made.separations.iter().map(|(m, n)| Count { name: m.name().into(), count: *n }).collect(),
        })
        .collect();
    let exercise = &spec.exercise;
    let manifest = Manifest {
        format: FORMAT.to_string(),
        course_seed: course,
        roster: roster.shape.name().to_string(),
        identity_column: roster.column.clone(),
        settings: Settings {
            width: exercise.width,
            height: exercise.height,
            polygons: exercise.polygons,
            frame_bits: exercise.frame_bits,
            depth_bits: exercise.depth_bits,
            hard: exercise.hard.iter().map(|c| c.name().to_string()).collect(),
            times: spec.times,
            distinct: spec.distinct,
            rules: spec.rules.iter().map(|m| m.name().to_string()).collect(),
            style: match exercise.style {
                crate::teach::exercise::Style::Book => "book".into(),
                crate::teach::exercise::Style::Free => "free".into(),
            },
            min_pixels: exercise.min_pixels,
        },
        hand_in: spec.hand_in.iter().map(|b| file_kind(*b).to_string()).collect(),
        students,
    };
    Ok(manifest)
}

/// A variant as a class keeps it: its scene's JSON, how many times each
/// hard case arises, each wrong rule's distance from the key, and a hash of
/// the key (to find two students with one key).
struct Kept {
    json: String,
    cases: [usize; 7],
    separations: Vec<(Misconception, usize)>,
    key: u64,
}

impl Kept {
    fn of(made: Made) -> Kept {
        let cases = HardCase::ALL.map(|case| made.census.count(case));
        let cells = made.key.0.iter().chain(&made.key.1).flatten().flat_map(|v| v.to_le_bytes());
        Kept { json: made.json, cases, separations: made.separations, key: fnv(cells) }
    }
}

/// The students whose scene, key or code another student (earlier in
/// identity order, without case) already has.
fn clashes(made: &[(u64, Kept)], lower: &[String]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..made.len()).collect();
    order.sort_by(|a, b| lower[*a].cmp(&lower[*b]));
    let (mut scenes, mut keys, mut codes) =
        (std::collections::HashSet::new(), std::collections::HashSet::new(), std::collections::HashSet::new());
    let mut clashing = Vec::new();
    for k in order {
        let (seed, made) = &made[k];
        let fresh = [scenes.insert(&made.json), keys.insert(&made.key), codes.insert(code_of(*seed))];
        if fresh.contains(&false) {
            clashing.push(k);
        }
    }
    clashing
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_students_seed_depends_on_the_course_their_identity_without_case_and_their_attempt() {
        let seed = student_seed(7, "Ana@Uni.edu", 0);
        assert_eq!(seed, student_seed(7, "ana@uni.edu", 0));
        assert_ne!(seed, student_seed(8, "ana@uni.edu", 0));
        assert_ne!(seed, student_seed(7, "ana@uni.edu", 1));
        assert_ne!(seed, student_seed(7, "bo@uni.edu", 0));
    }

    /// Why the default rules are these: of the first 400 candidates of the
    /// default settings, each default rule's answer differs from the key in
    /// 3 cells or more in most of them, and each rule left out in few
    /// (`cargo test --lib default_rules -- --nocapture` prints the shares).
    #[test]
    #[allow(clippy::print_stderr)]
    fn default_rules_are_those_most_candidates_tell_apart_in_three_cells() {
        let spec = Spec {
            seed: 1,
            width: 16,
            height: 16,
            polygons: 2,
            frame_bits: 2,
            depth_bits: 4,
            hard: vec![],
            style: crate::teach::exercise::Style::Book,
            min_pixels: 12,
        };
        let (mut apart, mut seen) = (std::collections::BTreeMap::<Misconception, usize>::new(), 0);
        let _ = search(Lang::En, &spec, |scene, _| {
            let diagnoser = Diagnoser::new(scene, 1)?;
            seen += 1;
            for (rule, cells) in diagnoser.separations() {
                *apart.entry(rule).or_default() += usize::from(cells >= 3);
            }
            (seen == 400).then_some(())
        });
        let defaults = default_rules(&[]);
        for rule in Misconception::ALL {
            let share = apart.get(&rule).copied().unwrap_or(0) as f64 / seen as f64;
            eprintln!("{:18} told apart in 3 cells or more: {:.2}", rule.name(), share);
            assert_eq!(defaults.contains(&rule), share >= 0.5, "{} at {share:.2}", rule.name());
        }
    }
}
