//! Gradescope: `check --format gradescope` writes an autograder's
//! `results.json` (Gradescope's autograder specification: `score`,
//! `visibility`, `tests[]` with `name`, `score`, `max_score`, `status`,
//! `output`, `visibility`), and `exercise --gradescope DIR` writes the
//! autograder itself (`setup.sh`, `run_autograder`, the scene), which calls
//! zsim.

use std::path::Path;

use crate::door::Links;
use crate::effects::arith::Arith;
use crate::error::Error;
use crate::numbers::Q;
use crate::observe::explain::Buffer;
use crate::scene::Scene;
use crate::teach::check::{CheckReport, Expect, Expected, as_the_student_sees, check, read_answer};
use crate::words::Lang;
use crate::words::printable;

/// How an autograder's results are given: who sees them, and what the whole
/// submission is worth.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Autograde {
    /// Who sees the results.
    pub visibility: Visibility,
    /// The points the submission is worth, shared equally by its tests.
    pub points: u32,
}

/// Who sees a result, as Gradescope names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Visibility {
    /// Students see it at once.
    Visible,
    /// Students never see it.
    Hidden,
    /// After the due date.
    AfterDueDate,
    /// Once the grades are published.
    AfterPublished,
}

impl Visibility {
    /// Every visibility, in the order of [`Visibility::NAMES`].
    pub const ALL: [Visibility; 4] =
        [Visibility::Visible, Visibility::Hidden, Visibility::AfterDueDate, Visibility::AfterPublished];

    /// Gradescope's names, which a user chooses them by.
    pub const NAMES: [&'static str; 4] = ["visible", "hidden", "after_due_date", "after_published"];

    /// The visibility named `name` (one of [`Visibility::NAMES`]).
    pub fn parse(name: &str) -> Option<Visibility> {
        Visibility::NAMES.iter().position(|n| *n == name).map(|i| Visibility::ALL[i])
    }

    /// Gradescope's name.
    pub fn name(self) -> &'static str {
        match self {
            Visibility::Visible => "visible",
            Visibility::Hidden => "hidden",
            Visibility::AfterDueDate => "after_due_date",
            Visibility::AfterPublished => "after_published",
        }
    }
}

/// The most points a submission may be worth (`--points`): a bound that
/// keeps every share and sum exact in hundredths of a point.
pub const MAX_POINTS: u32 = 100_000;

/// The submission's `results.json`: one test per buffer of each state the
/// teacher expects ([`Expected`], from [`crate::teach::check::expected_answers`]),
/// worth an equal share of `points` (1 to [`MAX_POINTS`]), scored by its
/// share of right cells and passed only when every cell is right. A test no
/// file answers, or several do, or whose file is malformed, fails with 0 and
/// says why in its output; files that answer nothing asked (`unused`) earn
/// nothing and are named in the results' output. Each test's output is the
/// check's report as `render` writes it. Text in the reader's language.
pub fn results(
    lang: Lang,
    (scene, scene_path): (&Scene, &Path),
    (expected, unused): (&[Expected], &[String]),
    arith: Arith,
    Autograde { visibility, points }: Autograde,
    render: &dyn Fn(&CheckReport) -> String,
) -> Result<String, Error> {
    let points = points.clamp(1, MAX_POINTS);
    let count = expected.len().max(1) as u64;
    // Shares in hundredths of a point that add up to `points` exactly.
    let hundredths = u64::from(points) * 100;
    let share = |k: u64| hundredths / count + u64::from(k < hundredths % count);
    let mut tests = Vec::new();
    let mut total = 0;
    for (k, test) in expected.iter().enumerate() {
        let name = words!(
            lang,
            "gradescope-test",
            buffer = test.buffer.name(lang),
            after = crate::observe::explain::polygon_after(lang, scene, test.after)
        );
        let max_score = share(k as u64);
        let (score, passed, output) = match test.files.as_slice() {
            [] => {
                let file = expected_name(scene, test.after, test.buffer);
                (0, false, words!(lang, "gradescope-missing", file = file) + "\n")
            }
            [path] => match read_answer(path, scene, test.buffer, Links::Refuse) {
                Ok(answer) => {
                    // The student sees the file's name, not where the autograder keeps it.
                    let shown = Path::new(path.file_name().unwrap_or(path.as_os_str()));
                    let report = check(lang, scene, scene_path, test.after, vec![(test.buffer, shown, answer)], arith)?;
                    let passed = report.wrong() == 0 && report.answers.iter().all(|a| a.unanswered == 0);
                    let earned: Vec<_> = report.answers.iter().map(|a| a.earned).collect();
                    // The score's rule, rounded down to a hundredth: only a right answer scores in full.
                    let share = crate::teach::grade::score(&earned) * Q::from_integer(i128::from(max_score));
                    let score = if passed { max_score } else { share.floor().to_integer().clamp(0, 10_000) as u64 };
                    let rule = earned.iter().map(|e| {
                        let (changed, right, stray) = (e.changed, e.right, e.stray);
                        words!(lang, "gradescope-score-rule", changed = changed, right = right, stray = stray)
                    });
                    let rule: String = rule.map(|line| line + "\n").collect();
                    (score, passed, render(&report) + &rule)
                }
                Err(error) => (0, false, format!("{}\n", as_the_student_sees(lang, &error, path))),
            },
            several => {
                let names: Vec<String> =
                    several.iter().map(|p| format!("\"{}\"", crate::words::shown_name(p))).collect();
                (0, false, words!(lang, "gradescope-ambiguous", files = names.join(", ")) + "\n")
            }
        };
        total += score;
        tests.push(TestResult {
            max_score: max_score as f64 / 100.0,
            name,
            output,
            score: score as f64 / 100.0,
            status: if passed { "passed" } else { "failed" },
            visibility: visibility.name(),
        });
    }
    let output = (!unused.is_empty()).then(|| {
        let names: Vec<String> = unused.iter().map(|n| format!("\"{}\"", printable(n))).collect();
        words!(lang, "gradescope-unused", files = names.join(", "))
    });
    Ok(Results { output, score: total as f64 / 100.0, tests, visibility: visibility.name() }.written())
}

/// Gradescope's `results.json` (its autograder specification), as zsim
/// writes it: the fields in the order of their names, as the file has
/// always been written.
#[derive(Debug, serde::Serialize)]
struct Results {
    /// Said to the student above the tests, where there is something to say.
    #[serde(skip_serializing_if = "Option::is_none")]
    output: Option<String>,
    score: f64,
    tests: Vec<TestResult>,
    visibility: &'static str,
}

/// One test of a [`Results`].
#[derive(Debug, serde::Serialize)]
struct TestResult {
    max_score: f64,
    name: String,
    output: String,
    score: f64,
    /// `passed` or `failed`.
    status: &'static str,
    visibility: &'static str,
}

impl Results {
    /// The file's text, pretty, ending in a newline.
    fn written(&self) -> String {
        format!("{}\n", serde_json::to_string_pretty(self).expect("plain data"))
    }
}

/// The file that answers for `buffer` after polygon `after` (0-based), as a
/// student names it.
pub fn expected_name(scene: &Scene, after: usize, buffer: Buffer) -> String {
    let kind = match buffer {
        Buffer::Frame => "frame.txt",
        Buffer::Depth => "depth.txt",
    };
    if after + 1 == scene.polygons.len() { kind.to_string() } else { format!("after-{}.{kind}", after + 1) }
}

/// The `results.json` of a submission with nothing to grade: score 0, why in
/// its output.
pub fn nothing_to_grade(why: &str, visibility: Visibility) -> String {
    let output = Some(printable(why).into_owned());
    Results { output, score: 0.0, tests: Vec::new(), visibility: visibility.name() }.written()
}

/// `setup.sh`: zsim installed from the Debian package put beside it.
pub fn setup_script() -> String {
    "#!/usr/bin/env bash\n\
        # Gradescope runs this once, as root, when it builds the autograder's image.\n\
        # Put zsim's Debian package (zsim_*.deb: `packaging/deb` on a clone of zsim\n\
        # writes it into target/debian/, or a release's) beside\n\
        # this script before zipping the folder's files.\n\
        set -euo pipefail\n\
        cd \"$(dirname \"$0\")\"\n\
        if ! ls zsim_*.deb >/dev/null 2>&1; then\n\
        \x20 echo \"setup.sh: no zsim_*.deb beside this script: build it with packaging/deb on a clone of zsim (it writes target/debian/zsim_*.deb) and copy it here\" >&2\n\
        \x20 exit 1\n\
        fi\n\
        apt-get install -y ./zsim_*.deb\n"
        .to_string()
}

/// The autograder's files for an exercise: `setup.sh` installs zsim from
/// the Debian package put beside it; `run_autograder` checks the submission
/// folder (`frame.txt`, `depth.txt`, `after-N.*.txt`) against the scene and
/// writes `results/results.json`. `AUTOGRADER_ROOT` stands for `/autograder`
/// (for trying it elsewhere). The states graded are `expect`'s.
pub fn autograder(
    scene_json: &str,
    expect: &Expect,
    Autograde { visibility, points }: Autograde,
    lang: Lang,
) -> Vec<(String, Vec<u8>)> {
    let setup = setup_script();
    let run = format!(
        "#!/usr/bin/env bash\n\
        # Gradescope runs this for each submission: the student's frame.txt and/or\n\
        # depth.txt (and after-N.frame.txt, after-N.depth.txt for earlier polygons)\n\
        # are checked against the exercise's scene; zsim writes results.json.\n\
        set -uo pipefail\n\
        root=\"${{AUTOGRADER_ROOT:-/autograder}}\"\n\
        mkdir -p \"$root/results\"\n\
        zsim check \"$root/source/scene.json\" --submission \"$root/submission\" --format gradescope \\\n\
        \x20 --expect {} --visibility {} --points {points} --lang {} >\"$root/results/results.json\"\n",
        expect.text(),
        visibility.name(),
        lang.code()
    );
    vec![
        ("setup.sh".to_string(), setup.into_bytes()),
        ("run_autograder".to_string(), run.into_bytes()),
        ("scene.json".to_string(), scene_json.as_bytes().to_vec()),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `results.json`'s shape: a test, and the results' output.
    #[test]
    fn results_have_gradescopes_shape() {
        let test = TestResult {
            max_score: 0.5,
            name: "framebuffer after triangle".into(),
            output: "right\n".into(),
            score: 0.5,
            status: "passed",
            visibility: Visibility::Visible.name(),
        };
        let results =
            Results { output: Some("unused: \"x.txt\"".into()), score: 0.5, tests: vec![test], visibility: "visible" };
        crate::shape_snapshot("gradescope_results", &results);
        assert!(nothing_to_grade("why", Visibility::Hidden).contains("\"tests\": []"));
    }
}
