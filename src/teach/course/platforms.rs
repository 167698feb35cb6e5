//! A class's variants on the platforms that run graders: Gradescope's
//! autograder and PrairieLearn's external grader each carry the manifest,
//! find the student's variant (Gradescope: by the submitters in
//! `submission_metadata.json`; PrairieLearn: by the variant the question
//! gave, in `data.json`'s `params`) and grade the files handed in against
//! that variant's key. An unknown student, or a group whose members have
//! different variants, gets a message they can see, never a crash or a
//! silent zero. The gradebooks (Moodle, Canvas) are `grade::gradebooks`;
//! Gradescope's single-scene autograder is `grade::gradescope`.

use serde::Deserialize;

use crate::error::Refusal;
use crate::words::{Lang, printable};

use super::manifest::Manifest;

/// Why no variant could be chosen for a submission.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Unmatched {
    /// The platform's file could not be read as its layout.
    Unreadable {
        /// The file, as the platform names it.
        file: String,
        /// What is wrong.
        why: String,
    },
    /// No submitter is on the roster.
    Unknown {
        /// The identities the platform gave.
        given: Vec<String>,
    },
    /// The group's members have different variants.
    Group {
        /// The students, by identity.
        students: Vec<String>,
    },
    /// The question's variant code is in no student's row.
    UnknownCode {
        /// The code.
        code: String,
    },
    /// The platform's file that names the submission was not given.
    NoFile,
}

impl Refusal for Unmatched {
    fn message(&self, lang: Lang) -> String {
        let list = |items: &[String]| items.iter().map(|i| printable(i).into_owned()).collect::<Vec<_>>().join(", ");
        match self {
            Unmatched::Unreadable { file, why } => {
                words!(lang, "platform-unreadable", file = file.as_str(), why = why.as_str())
            }
            Unmatched::Unknown { given } => words!(lang, "platform-unknown-student", given = list(given)),
            Unmatched::Group { students } => words!(lang, "platform-group", students = list(students)),
            Unmatched::UnknownCode { code } => {
                words!(lang, "platform-unknown-code", code = printable(code).into_owned())
            }
            Unmatched::NoFile => words!(lang, "platform-needs-file"),
        }
    }
}

/// The platform a grader runs on, with its file that names the submission.
pub enum Platform<'a> {
    /// Gradescope: `submission_metadata.json`, and how the results are given.
    Gradescope {
        /// The metadata file.
        metadata: Option<&'a std::path::Path>,
        /// Who sees the results and the points.
        grading: crate::teach::grade::gradescope::Autograde,
    },
    /// PrairieLearn: the grading job's `data.json`.
    PrairieLearn {
        /// The data file.
        data: Option<&'a std::path::Path>,
    },
}

/// How a platform's file picks the student of a manifest.
type Pick = fn(&Manifest, &str) -> Result<usize, Unmatched>;

/// One submission graded against its student's variant: the manifest at
/// `variants`, the student found by the platform's file, their files in
/// `submission`; the platform's `results.json` (its words in `lang`), or why
/// it could not be made.
pub fn autograde(
    lang: Lang,
    platform: &Platform<'_>,
    variants: &std::path::Path,
    submission: &std::path::Path,
    render: &dyn Fn(&crate::teach::check::CheckReport) -> String,
) -> Result<String, crate::error::Error> {
    let loaded = super::manifest::load(variants)?;
    let manifest = &loaded.manifest;
    let (file, pick): (_, Pick) = match platform {
        Platform::Gradescope { metadata, .. } => (metadata, gradescope_student),
        Platform::PrairieLearn { data } => (data, prairielearn_student),
    };
    let file = file.ok_or(Unmatched::NoFile)?;
    let text = crate::door::read_text(file)?;
    let k = pick(manifest, &text)?;
    let scene = &loaded.scenes[k];
    let (expected, unused) = submitted(submission, scene, &manifest.buffers())?;
    match platform {
        Platform::Gradescope { grading, .. } => {
            let shown = std::path::Path::new("scene.json");
            let arith = crate::effects::arith::Arith::Exact;
            crate::teach::grade::gradescope::results(
                lang,
                (scene, shown),
                (&expected, &unused),
                arith,
                *grading,
                render,
            )
        }
        Platform::PrairieLearn { .. } => prairielearn_results(lang, scene, &expected, render),
    }
}

/// The `results.json` of a submission that could not be graded, `why` in
/// words the student sees: Gradescope's score 0 with its output visible,
/// PrairieLearn's not gradable (no attempt lost).
pub fn unusable(why: &str, platform: &Platform<'_>) -> String {
    match platform {
        Platform::Gradescope { .. } => {
            crate::teach::grade::gradescope::nothing_to_grade(why, crate::teach::grade::gradescope::Visibility::Visible)
        }
        Platform::PrairieLearn { .. } => PrairieLearnResults::not_gradable(vec![printable(why).into_owned()]),
    }
}

/// Gradescope's `submission_metadata.json`, as much of it as names the submitters.
#[derive(Debug, Deserialize)]
struct Metadata {
    users: Vec<User>,
}

/// One submitter.
#[derive(Debug, Deserialize)]
struct User {
    #[serde(default)]
    email: Option<String>,
    #[serde(default)]
    sid: Option<String>,
}

/// The student of `manifest` a Gradescope submission is from: each
/// submitter found by their `sid`, else their `email`, without case, among
/// the identities and aliases; every submitter found must have one variant.
pub fn gradescope_student(manifest: &Manifest, metadata: &str) -> Result<usize, Unmatched> {
    let metadata: Metadata = serde_json::from_str(metadata)
        .map_err(|e| Unmatched::Unreadable { file: "submission_metadata.json".into(), why: e.to_string() })?;
    let mut found: Vec<usize> = Vec::new();
    let mut given = Vec::new();
    for user in &metadata.users {
        let ids = [user.sid.as_deref(), user.email.as_deref()];
        given.extend(ids.iter().flatten().map(|s| s.to_string()));
        if let Some(k) = ids.iter().flatten().find_map(|id| manifest.student(id)) {
            found.push(k);
        }
    }
    found.sort_unstable();
    found.dedup();
    match found.as_slice() {
        [] => Err(Unmatched::Unknown { given }),
        [k] => Ok(*k),
        several => {
            let mut students: Vec<String> = several.iter().map(|k| manifest.students[*k].identity.clone()).collect();
            students.sort();
            Err(Unmatched::Group { students })
        }
    }
}

/// PrairieLearn's `data.json`, as much of it as names the variant.
#[derive(Debug, Deserialize)]
struct Data {
    params: Params,
}

#[derive(Debug, Deserialize)]
struct Params {
    variant: String,
}

/// The student of `manifest` whose variant a PrairieLearn question gave:
/// `params.variant` of the grading job's `data.json` is their code.
pub fn prairielearn_student(manifest: &Manifest, data: &str) -> Result<usize, Unmatched> {
    let data: Data = serde_json::from_str(data)
        .map_err(|e| Unmatched::Unreadable { file: "data.json".into(), why: e.to_string() })?;
    manifest
        .students
        .iter()
        .position(|v| v.code == data.params.variant)
        .ok_or(Unmatched::UnknownCode { code: data.params.variant })
}

/// A Gradescope autograder for a class: `setup.sh` (zsim from its Debian
/// package beside it), `run_autograder` (zsim's autograde on the student's
/// files) and the manifest. `AUTOGRADER_ROOT` stands for `/autograder`.
pub fn gradescope_autograder(manifest_json: &str, visibility: &str, points: u32, lang: Lang) -> Vec<(String, Vec<u8>)> {
    let setup = crate::teach::grade::gradescope::setup_script();
    let run = format!(
        "#!/usr/bin/env bash\n\
        # Gradescope runs this for each submission: the student is found in\n\
        # submission_metadata.json, their variant in variants.json, and their\n\
        # IDENTITY.frame.txt and IDENTITY.depth.txt (or frame.txt, depth.txt)\n\
        # are graded against it; zsim writes results.json.\n\
        set -uo pipefail\n\
        root=\"${{AUTOGRADER_ROOT:-/autograder}}\"\n\
        mkdir -p \"$root/results\"\n\
        zsim autograde gradescope --variants \"$root/source/variants.json\" \\\n\
        \x20 --metadata \"$root/submission_metadata.json\" --submission \"$root/submission\" \\\n\
        \x20 --visibility {visibility} --points {points} --lang {} >\"$root/results/results.json\"\n",
        lang.code()
    );
    vec![
        ("setup.sh".to_string(), setup.into_bytes()),
        ("run_autograder".to_string(), run.into_bytes()),
        ("variants.json".to_string(), manifest_json.as_bytes().to_vec()),
    ]
}

/// A PrairieLearn question for a class (its folder under the course's
/// `questions/`): `info.json` with external grading on, `server.py` giving
/// each variant of the question one of the manifest's scenes (its code in
/// `params.variant`), `question.html` showing the scene and taking the two
/// files, and `tests/` with the manifest and `run.sh`, the grader's
/// entrypoint, which calls zsim's autograde on `/grade` (`GRADE_ROOT`
/// stands for it). `image` is the grading image, which must have zsim on
/// its path or a `zsim_*.deb` in `tests/` to unpack.
pub fn prairielearn_question(
    manifest: &Manifest,
    manifest_json: &str,
    image: &str,
    lang: Lang,
) -> Vec<(String, Vec<u8>)> {
    let title = words!(lang, "platform-question-title");
    let info = QuestionInfo {
        external_grading_options: ExternalGrading {
            enabled: true,
            entrypoint: "/grade/tests/run.sh",
            image: image.to_string(),
            timeout: 30,
        },
        grading_method: "External",
        single_variant: false,
        tags: ["zsim"],
        title,
        topic: "z-buffer",
        kind: "v3",
        uuid: uuid_of(manifest_json),
    };
    let files: Vec<String> =
        manifest.buffers().iter().map(|b| format!("{}.txt", crate::teach::grade::file_kind(*b))).collect();
    let server = "# Each variant of this question is one of the class's scenes (tests/variants.json),\n\
        # chosen by the variant's seed; the grader finds it again by its code.\n\
        import json, os\n\n\
        def generate(data):\n\
        \x20   here = os.path.dirname(os.path.abspath(__file__))\n\
        \x20   with open(os.path.join(here, \"tests\", \"variants.json\"), encoding=\"utf-8\") as f:\n\
        \x20       students = json.load(f)[\"students\"]\n\
        \x20   chosen = students[data[\"variant_seed\"] % len(students)]\n\
        \x20   data[\"params\"][\"variant\"] = chosen[\"code\"]\n\
        \x20   data[\"params\"][\"scene\"] = json.dumps(chosen[\"scene\"], indent=1)\n"
        .to_string();
    let question = format!(
        "<pl-question-panel>\n<p>{}</p>\n<p>{} <code>{{{{params.variant}}}}</code></p>\n<pre>{{{{params.scene}}}}</pre>\n</pl-question-panel>\n\
        <pl-file-upload file-names=\"{}\"></pl-file-upload>\n<pl-submission-panel>\n<pl-external-grader-results></pl-external-grader-results>\n\
        <pl-file-preview></pl-file-preview>\n</pl-submission-panel>\n",
        crate::observe::render::svg_text::escape(&words!(lang, "exercise-task-write")),
        crate::observe::render::svg_text::escape(&words!(lang, "platform-question-variant")),
        files.join(", ")
    );
    let run = format!(
        "#!/usr/bin/env bash\n\
        # PrairieLearn's external grader: the variant is in /grade/data/data.json,\n\
        # the files in /grade/student; zsim writes /grade/results/results.json.\n\
        set -uo pipefail\n\
        root=\"${{GRADE_ROOT:-/grade}}\"\n\
        mkdir -p \"$root/results\"\n\
        if ! command -v zsim >/dev/null 2>&1; then\n\
        \x20 deb=$(ls \"$root\"/tests/zsim_*.deb 2>/dev/null | head -n 1)\n\
        \x20 if [ -n \"$deb\" ]; then dpkg-deb -x \"$deb\" /tmp/zsim && PATH=\"/tmp/zsim/usr/bin:$PATH\"; fi\n\
        fi\n\
        zsim autograde prairielearn --variants \"$root/tests/variants.json\" --data \"$root/data/data.json\" \\\n\
        \x20 --submission \"$root/student\" --lang {} >\"$root/results/results.json\"\n",
        lang.code()
    );
    vec![
        ("info.json".to_string(), (serde_json::to_string_pretty(&info).expect("plain data") + "\n").into_bytes()),
        ("server.py".to_string(), server.into_bytes()),
        ("question.html".to_string(), question.into_bytes()),
        ("tests/run.sh".to_string(), run.into_bytes()),
        ("tests/variants.json".to_string(), manifest_json.as_bytes().to_vec()),
    ]
}

/// The tests of a platform's submission folder for a student's variant:
/// one per buffer the manifest asks for, answered by `frame.txt` or any
/// `NAME.frame.txt` (likewise `depth`), and the names of the files that
/// answer nothing asked.
pub fn submitted(
    folder: &std::path::Path,
    scene: &crate::scene::Scene,
    buffers: &[crate::observe::explain::Buffer],
) -> Result<(Vec<crate::teach::check::Expected>, Vec<String>), crate::error::Error> {
    let last = scene.polygons.len() - 1;
    let mut expected: Vec<crate::teach::check::Expected> =
        buffers.iter().map(|b| crate::teach::check::Expected { after: last, buffer: *b, files: Vec::new() }).collect();
    let read_error = |source| crate::error::Error::Read { path: folder.to_owned(), source };
    let mut names: Vec<(String, std::path::PathBuf)> = std::fs::read_dir(folder)
        .map_err(read_error)?
        .filter_map(|e| e.ok())
        .map(|e| (crate::words::shown_name(std::path::Path::new(&e.file_name())), e.path()))
        .collect();
    names.sort();
    let mut unused = Vec::new();
    for (name, path) in names {
        let kind = |b: crate::observe::explain::Buffer| format!("{}.txt", crate::teach::grade::file_kind(b));
        let test =
            expected.iter_mut().find(|e| name == kind(e.buffer) || name.ends_with(&format!(".{}", kind(e.buffer))));
        match test {
            Some(test) => test.files.push(path),
            None => unused.push(name),
        }
    }
    Ok((expected, unused))
}

/// PrairieLearn's `results.json` for a student's files against their
/// variant: `score` from 0 to 1 by the score's rule over every buffer asked
/// for, a test per buffer (its points its share of right cells), the check's
/// report as `render` writes it in each test's output; a file that is not a
/// matrix of the raster's shape makes the submission not gradable
/// (`gradable: false`, its problems in `format_errors`), so the student
/// loses no attempt.
pub fn prairielearn_results(
    lang: Lang,
    scene: &crate::scene::Scene,
    expected: &[crate::teach::check::Expected],
    render: &dyn Fn(&crate::teach::check::CheckReport) -> String,
) -> Result<String, crate::error::Error> {
    use crate::teach::check::{check, read_answer};
    let shown = std::path::Path::new("scene.json");
    let mut format_errors = Vec::new();
    let (mut tests, mut earned) = (Vec::new(), Vec::new());
    for test in expected {
        let name = words!(
            lang,
            "gradescope-test",
            buffer = test.buffer.name(lang),
            after = crate::observe::explain::polygon_after(lang, scene, test.after)
        );
        let (points, output) = match test.files.as_slice() {
            [path] => match read_answer(path, scene, test.buffer, crate::door::Links::Refuse) {
                Ok(answer) => {
                    let file = std::path::Path::new(path.file_name().unwrap_or(path.as_os_str()));
                    let report = check(
                        lang,
                        scene,
                        shown,
                        test.after,
                        vec![(test.buffer, file, answer)],
                        crate::effects::arith::Arith::Exact,
                    )?;
                    let mine: Vec<_> = report.answers.iter().map(|a| a.earned).collect();
                    earned.extend(mine.iter().copied());
                    (crate::teach::grade::score(&mine), render(&report))
                }
                Err(error) => {
                    format_errors.push(crate::teach::check::as_the_student_sees(lang, &error, path));
                    continue;
                }
            },
            [] => {
                let file = format!("{}.txt", crate::teach::grade::file_kind(test.buffer));
                earned.push(crate::teach::grade::Earned::of(
                    None,
                    &answer_key(scene, test.buffer),
                    crate::teach::grade::cleared(scene, test.buffer),
                ));
                (crate::numbers::Q::from_integer(0), words!(lang, "gradescope-missing", file = file) + "\n")
            }
            several => {
                let names: Vec<String> =
                    several.iter().map(|p| format!("\"{}\"", crate::words::shown_name(p))).collect();
                format_errors.push(words!(lang, "gradescope-ambiguous", files = names.join(", ")));
                continue;
            }
        };
        tests.push(PrairieLearnTest { max_points: 1, name, output, points: crate::numbers::to_f64(points) });
    }
    if !format_errors.is_empty() {
        return Ok(PrairieLearnResults::not_gradable(format_errors));
    }
    let score = Some(crate::numbers::to_f64(crate::teach::grade::score(&earned)));
    Ok(PrairieLearnResults { format_errors: None, gradable: true, score, tests: Some(tests) }.written())
}

/// PrairieLearn's `results.json` from an external grader, as zsim writes
/// it: gradable with a score and its tests, or not gradable with the
/// format's errors. (The fields of these files are written in the order of
/// their names, as they have always been.)
#[derive(Debug, serde::Serialize)]
struct PrairieLearnResults {
    #[serde(skip_serializing_if = "Option::is_none")]
    format_errors: Option<Vec<String>>,
    gradable: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    score: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tests: Option<Vec<PrairieLearnTest>>,
}

/// One test of [`PrairieLearnResults`].
#[derive(Debug, serde::Serialize)]
struct PrairieLearnTest {
    max_points: u32,
    name: String,
    output: String,
    points: f64,
}

impl PrairieLearnResults {
    /// A submission PrairieLearn counts no attempt for, and why.
    fn not_gradable(format_errors: Vec<String>) -> String {
        PrairieLearnResults { format_errors: Some(format_errors), gradable: false, score: None, tests: None }.written()
    }

    /// The file's text, pretty, ending in a newline.
    fn written(&self) -> String {
        serde_json::to_string_pretty(self).expect("plain data") + "\n"
    }
}

/// A PrairieLearn question's `info.json`.
#[derive(Debug, serde::Serialize)]
#[serde(rename_all = "camelCase")]
struct QuestionInfo {
    external_grading_options: ExternalGrading,
    grading_method: &'static str,
    single_variant: bool,
    tags: [&'static str; 1],
    title: String,
    topic: &'static str,
    #[serde(rename = "type")]
    kind: &'static str,
    uuid: String,
}

/// [`QuestionInfo`]'s external grader.
#[derive(Debug, serde::Serialize)]
struct ExternalGrading {
    enabled: bool,
    entrypoint: &'static str,
    image: String,
    timeout: u32,
}

/// The key of one buffer of a scene, top row first.
fn answer_key(scene: &crate::scene::Scene, buffer: crate::observe::explain::Buffer) -> crate::teach::check::Matrix {
    let (frame, depth) = super::fair::key_of(scene);
    if buffer == crate::observe::explain::Buffer::Frame { frame } else { depth }
}

/// A stable UUID (version 4's layout) from the manifest's bytes, so the same
/// class writes the same question.
fn uuid_of(text: &str) -> String {
    let a = super::fair::fnv(text.bytes());
    let b = super::fair::fnv(text.bytes().rev());
    let hex = format!("{a:016x}{b:016x}");
    format!("{}-{}-4{}-8{}-{}", &hex[0..8], &hex[8..12], &hex[13..16], &hex[17..20], &hex[20..32])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn manifest() -> Manifest {
        let text = r#"{"format": "zsim class variants 1", "course_seed": 1, "roster": "gradescope", "identity_column": "Email",
            "settings": {"width": 4, "height": 4, "polygons": 1, "frame_bits": 2, "depth_bits": 4, "hard": [], "times": 1,
                "distinct": 3, "rules": [], "style": "book", "min_pixels": 1},
            "hand_in": ["frame", "depth"],
            "students": [
              {"identity": "ana@uni.edu", "name": "Ana", "aliases": ["s1"], "code": "AAA-AAA", "seed": 1, "attempt": 0,
               "scene": {}, "cases": [], "separations": []},
              {"identity": "bo@uni.edu", "name": "Bo", "aliases": ["s2"], "code": "BBB-BBB", "seed": 2, "attempt": 0,
               "scene": {}, "cases": [], "separations": []}]}"#;
        serde_json::from_str(text).unwrap()
    }

    #[test]
    fn gradescope_submitters_are_found_by_sid_then_email_without_case() {
        let m = manifest();
        let by_sid = r#"{"users": [{"email": "other@x.org", "sid": "S2", "name": "Bo"}], "assignment": {}}"#;
        assert_eq!(gradescope_student(&m, by_sid), Ok(1));
        let by_email = r#"{"users": [{"email": "ANA@uni.edu", "sid": null}]}"#;
        assert_eq!(gradescope_student(&m, by_email), Ok(0));
        let unknown = r#"{"users": [{"email": "eve@uni.edu", "sid": "s9"}]}"#;
        assert_eq!(
            gradescope_student(&m, unknown),
            Err(Unmatched::Unknown { given: vec!["s9".into(), "eve@uni.edu".into()] })
        );
        let group = r#"{"users": [{"email": "ana@uni.edu"}, {"email": "bo@uni.edu"}]}"#;
        assert_eq!(
            gradescope_student(&m, group),
            Err(Unmatched::Group { students: vec!["ana@uni.edu".into(), "bo@uni.edu".into()] })
        );
        assert!(matches!(gradescope_student(&m, "not json"), Err(Unmatched::Unreadable { .. })));
    }

    #[test]
    fn a_prairielearn_job_names_its_variant_by_code() {
        let m = manifest();
        assert_eq!(prairielearn_student(&m, r#"{"params": {"variant": "BBB-BBB"}, "submitted_answers": {}}"#), Ok(1));
        assert_eq!(
            prairielearn_student(&m, r#"{"params": {"variant": "ZZZ-ZZZ"}}"#),
            Err(Unmatched::UnknownCode { code: "ZZZ-ZZZ".into() })
        );
    }

    /// PrairieLearn's files, each its type's shape: a question's
    /// `info.json`, a graded `results.json` and one not gradable.
    #[test]
    fn prairielearns_files_have_their_shapes() {
        let m = manifest();
        let files = prairielearn_question(&m, "{}", "zsim/grader", Lang::En);
        let info = &files.iter().find(|(name, _)| name == "info.json").expect("info.json").1;
        let info: serde_json::Value = serde_json::from_slice(info).unwrap();
        crate::shape_snapshot("prairielearn_info", &info);
        let test =
            PrairieLearnTest { max_points: 1, name: "framebuffer".into(), output: "right\n".into(), points: 1.0 };
        let graded =
            PrairieLearnResults { format_errors: None, gradable: true, score: Some(1.0), tests: Some(vec![test]) };
        crate::shape_snapshot("prairielearn_results", &graded);
        let refused: serde_json::Value =
            serde_json::from_str(&PrairieLearnResults::not_gradable(vec!["why".into()])).unwrap();
        crate::shape_snapshot("prairielearn_not_gradable", &refused);
    }
}
