//! What a student sends the lesson (`Command`, the keys of one table) and
//! what the lesson answers (`Said`: a move, a verdict, a hint named by its
//! kind, the score), each worded here so that every front end says the same.

use crate::scene::Scene;
use crate::teach::check::diagnose::Misconception;
use crate::teach::step::{Moved, Verdict, skip_text};
use crate::words::{Lang, printable};

/// What a student can ask of the lesson: the same keys in every front end.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Command {
    /// `n` (or Enter on an empty line): the next scanline.
    Next,
    /// `b`: the scanline before.
    Back,
    /// `p`: the next polygon's first scanline.
    NextPolygon,
    /// `P`: the previous polygon's first scanline.
    PreviousPolygon,
    /// `g Y`: scanline Y + ½ of the current polygon.
    Go(u32),
    /// Scanline `row` + ½ of polygon `polygon` (0-based): where a page's address points.
    GoTo {
        /// 0-based polygon index.
        polygon: usize,
        /// The pixel row.
        row: u32,
    },
    /// `s`: skip the scanline's open questions (each counts as skipped).
    Skip,
    /// Anything else typed: an answer to the open question.
    Answer(String),
    /// `q`: the end of the lesson.
    Quit,
}

/// The keys that act alone, and what each does: one table for every front end.
pub const KEYS: [(char, &str); 6] = [
    ('n', "lesson-key-next"),
    ('b', "lesson-key-back"),
    ('p', "lesson-key-next-polygon"),
    ('P', "lesson-key-previous-polygon"),
    ('s', "lesson-key-skip"),
    ('q', "lesson-key-quit"),
];

impl Command {
    /// The command of a key that acts alone (see [`KEYS`]).
    pub fn from_key(key: char) -> Option<Command> {
        Some(match key {
            'n' => Command::Next,
            'b' => Command::Back,
            'p' => Command::NextPolygon,
            'P' => Command::PreviousPolygon,
            's' => Command::Skip,
            'q' => Command::Quit,
            _ => return None,
        })
    }

    /// A line as typed: empty is [`Command::Next`], a key of [`KEYS`] alone
    /// its command, `g Y` a row, anything else an answer.
    pub fn parse(line: &str) -> Command {
        let line = line.trim();
        let mut chars = line.chars();
        if let (Some(key), None) = (chars.next(), chars.next())
            && let Some(command) = Command::from_key(key)
        {
            return command;
        }
        if line.is_empty() {
            return Command::Next;
        }
        if let Some(row) = line.strip_prefix("g ").and_then(|row| row.trim().parse().ok()) {
            return Command::Go(row);
        }
        Command::Answer(line.to_string())
    }

    /// The keys in one line of the reader's language.
    pub fn keys_text(lang: Lang) -> String {
        let keys: Vec<String> = KEYS.iter().map(|(key, what)| format!("{key} {}", words!(lang, what))).collect();
        words!(lang, "lesson-keys", keys = keys.join(&words!(lang, "list-comma")))
    }
}

/// The kind of a wrong answer, named before its value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hint {
    /// A wrong rule students are known to follow gives exactly this answer.
    Misconception(Misconception),
    /// The pixel is written, and the answer says it is not (or keeps the old value).
    IsWritten,
    /// The pixel is not written, and the answer writes it.
    IsNotWritten,
    /// Only centres exactly on the polygon's boundary decided the other way.
    CentreOnBoundary,
    /// The columns of the row just below or above.
    NeighbouringRow,
    /// The depth rounded up where the nearest integer is below.
    RoundedUp,
    /// No known rule gives this answer: a plain "not yet".
    Other,
}

impl Hint {
    /// The hint in one line of the reader's language (no value in it).
    pub fn text(self, lang: Lang) -> String {
        match self {
            // The pixel's own numbers would give the answer away, and another's mislead: none.
            Hint::Misconception(Misconception::HalfDown) => words!(lang, "lesson-hint-half-down"),
            Hint::Misconception(what) => words!(lang, "lesson-hint-misconception", what = what.words(lang)),
            Hint::IsWritten => words!(lang, "lesson-hint-is-written"),
            Hint::IsNotWritten => words!(lang, "lesson-hint-is-not-written"),
            Hint::CentreOnBoundary => words!(lang, "lesson-hint-centre-on-boundary"),
            Hint::NeighbouringRow => words!(lang, "lesson-hint-neighbouring-row"),
            Hint::RoundedUp => words!(lang, "lesson-hint-rounded-up"),
            Hint::Other => String::new(),
        }
    }
}

/// What became of a command.
#[derive(Debug, Clone)]
pub enum Said {
    /// Moved to a stop or to the end, or refused (with why).
    Moved(Moved),
    /// Right, at the first try or the second.
    Right {
        /// The verdict, with the reason.
        verdict: Box<Verdict>,
        /// Whether it took a second try.
        second_try: bool,
    },
    /// Wrong at the first try: the kind of mistake; the question stays open.
    TryAgain {
        /// What the student typed, shown safely.
        said: String,
        /// The kind of mistake.
        hint: Hint,
    },
    /// Wrong at the second try: the answer and why; the next question follows.
    Revealed(Box<Verdict>),
    /// Not an answer to the question (why); nothing is counted.
    AskAgain(String),
    /// This many open questions skipped.
    Skipped(usize),
    /// An answer typed while nothing is asked.
    NothingAsked(String),
    /// The student asked to stop.
    Quit,
}

impl Said {
    /// What happened, in the reader's language, as every front end shows it
    /// (empty for a move that passed over nothing).
    pub fn text(&self, lang: Lang, scene: &Scene) -> String {
        match self {
            Said::Moved(Moved::To { at, skipped }) => {
                let mut lines: Vec<String> =
                    skipped.iter().map(|skip| format!("· {}", skip_text(lang, scene, skip))).collect();
                if at.is_none() {
                    lines.push(words!(lang, "step-end"));
                }
                lines.join("\n")
            }
            Said::Moved(Moved::Refused(refusal)) => refusal.text(lang, scene),
            Said::Right { verdict, second_try } => {
                let said = match verdict.meant {
                    Some(meant) => words!(lang, "lesson-said-meant", said = &verdict.said, meant = meant.text(lang)),
                    None => verdict.said.clone(),
                };
                let key = if *second_try { "lesson-right-second" } else { "lesson-right" };
                words!(lang, key, said = said, why = &verdict.why)
            }
            Said::TryAgain { said, hint: Hint::Other } => words!(lang, "lesson-try-again-plain", said = said),
            Said::TryAgain { said, hint } => words!(lang, "lesson-try-again", said = said, hint = hint.text(lang)),
            Said::Revealed(verdict) => {
                words!(lang, "lesson-revealed", said = &verdict.said, expected = &verdict.expected, why = &verdict.why)
            }
            Said::AskAgain(why) => why.clone(),
            Said::Skipped(0) => words!(lang, "lesson-nothing-to-skip"),
            Said::Skipped(count) => words!(lang, "lesson-skipped", count = count.to_string()),
            Said::NothingAsked(typed) => words!(
                lang,
                "step-unknown",
                text = printable(&crate::words::token(lang, typed)).into_owned(),
                help = Command::keys_text(lang)
            ),
            Said::Quit => String::new(),
        }
    }
}

/// The quiz's score: each question counted once, by how it ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Score {
    /// Right at the first try.
    pub first_try: usize,
    /// Right at the second try.
    pub second_try: usize,
    /// Wrong twice: the answer was shown.
    pub revealed: usize,
    /// Skipped on purpose.
    pub skipped: usize,
}

impl Score {
    /// Every question that ended.
    pub fn asked(&self) -> usize {
        self.first_try + self.second_try + self.revealed + self.skipped
    }

    /// The score in one line of the reader's language.
    pub fn text(&self, lang: Lang) -> String {
        words!(
            lang,
            "lesson-score",
            first = self.first_try,
            second = self.second_try,
            revealed = self.revealed,
            skipped = self.skipped,
            asked = self.asked()
        )
    }
}
