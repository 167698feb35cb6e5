//! The words of the program: every sentence a person reads about the
//! algorithm is rendered here from facts, in the student's language.
//!
//! Each language is a Fluent catalogue (a folder `en/`, `ru/`, `uk/`, `zh/`,
//! built into the binary) of one resource per area ([`AREAS`]: reading a
//! scene, drawing it, stepping and the lesson, checking and grading, the
//! courses, requests that do not fit, a class of variants), with one message per sentence or
//! phrase, keyed by the fact it states (never by the front end that shows
//! it), and the facts as arguments; Fluent chooses plural forms by the
//! language's CLDR rules. Numbers arrive already written: exact values stay exact
//! (`43/4`), and the decimal beside them uses the language's separator
//! ([`Lang::decimal_separator`]: `10,75` in Russian and Ukrainian).
//!
//! The language is passed to every call that makes words ([`text`], the
//! `words!` macro); nothing holds it behind the caller's back. The command
//! line chooses it from `--lang` or the environment ([`Lang::from_env`]);
//! English is the default. JSON output never passes through here.

use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource, FluentValue};

/// A language zsim speaks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Lang {
    /// English (the default).
    #[default]
    En,
    /// Russian.
    Ru,
    /// Ukrainian.
    Uk,
    /// Simplified Chinese.
    Zh,
}

impl Lang {
    /// Every language, English first.
    pub const ALL: [Lang; 4] = [Lang::En, Lang::Ru, Lang::Uk, Lang::Zh];

    /// The language of a code or locale: `ru`, `ru_RU.UTF-8`, `uk-UA`,
    /// `zh_CN`, `en_US`; `None` for others (and for `C` and `POSIX`).
    pub fn parse(code: &str) -> Option<Lang> {
        let language = code.split(['_', '-', '.', '@']).next()?.to_ascii_lowercase();
        match language.as_str() {
            "en" => Some(Lang::En),
            "ru" => Some(Lang::Ru),
            "uk" => Some(Lang::Uk),
            "zh" => Some(Lang::Zh),
            _ => None,
        }
    }

    /// The language the environment asks for: the first of `LC_ALL`,
    /// `LC_MESSAGES` and `LANG` that is set and not empty decides (as
    /// gettext reads them); English when it names another language.
    pub fn from_env() -> Lang {
        Lang::from_vars(|name| std::env::var(name).ok())
    }

    /// [`Lang::from_env`] over any source of variables (for tests).
    pub fn from_vars(var: impl Fn(&str) -> Option<String>) -> Lang {
        ["LC_ALL", "LC_MESSAGES", "LANG"]
            .iter()
            .find_map(|name| var(name).filter(|v| !v.is_empty()))
            .and_then(|value| Lang::parse(&value))
            .unwrap_or_default()
    }

    /// The code: `en`, `ru`, `uk`, `zh`.
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Ru => "ru",
            Lang::Uk => "uk",
            Lang::Zh => "zh",
        }
    }

    /// The decimal separator: a comma in Russian and Ukrainian, a point otherwise.
    pub fn decimal_separator(self) -> char {
        match self {
            Lang::Ru | Lang::Uk => ',',
            Lang::En | Lang::Zh => '.',
        }
    }

    /// The catalogue's resources, one an area, in the order of [`AREAS`]:
    /// `src/words/LANG/AREA.ftl` as the build keeps them (build.rs leaves out
    /// the messages only a part this build lacks names: the command line's,
    /// the GPU's, the courses').
    fn catalogue(self) -> [&'static str; AREAS.len()] {
        macro_rules! areas {
            ($lang:literal) => {
                [
                    include_str!(concat!(env!("OUT_DIR"), "/words/", $lang, "/scene.ftl")),
                    include_str!(concat!(env!("OUT_DIR"), "/words/", $lang, "/draw.ftl")),
                    include_str!(concat!(env!("OUT_DIR"), "/words/", $lang, "/step.ftl")),
                    include_str!(concat!(env!("OUT_DIR"), "/words/", $lang, "/check.ftl")),
                    include_str!(concat!(env!("OUT_DIR"), "/words/", $lang, "/courses.ftl")),
                    include_str!(concat!(env!("OUT_DIR"), "/words/", $lang, "/usage.ftl")),
                    include_str!(concat!(env!("OUT_DIR"), "/words/", $lang, "/class.ftl")),
                ]
            };
        }
        match self {
            Lang::En => areas!("en"),
            Lang::Ru => areas!("ru"),
            Lang::Uk => areas!("uk"),
            Lang::Zh => areas!("zh"),
        }
    }
}

/// A language's catalogue, parsed the first time it is asked for and then
/// shared by every thread (the concurrent bundle's memoizer is `Sync`);
/// which language a sentence is made in is always passed by the caller.
fn catalogue(lang: Lang) -> &'static FluentBundle<FluentResource> {
    static BUNDLES: [std::sync::OnceLock<FluentBundle<FluentResource>>; 4] = [const { std::sync::OnceLock::new() }; 4];
    let index = Lang::ALL.iter().position(|l| *l == lang).expect("every language has a catalogue");
    BUNDLES[index].get_or_init(|| bundle(lang))
}

/// The areas a catalogue's messages are kept in, one resource each
/// (`src/words/LANG/AREA.ftl`).
const AREAS: [&str; 7] = ["scene", "draw", "step", "check", "courses", "usage", "class"];

fn bundle(lang: Lang) -> FluentBundle<FluentResource> {
    let id: unic_langid::LanguageIdentifier = lang.code().parse().expect("a language code");
    let mut bundle = FluentBundle::new_concurrent(vec![id]);
    // No Unicode isolation marks around arguments: terminals show them as gaps.
    bundle.set_use_isolating(false);
    for (area, text) in AREAS.iter().zip(lang.catalogue()) {
        let resource = FluentResource::try_new(text.to_string()).unwrap_or_else(|(_, errors)| {
            panic!("the {} catalogue's {area} does not parse: {errors:?}: please report this bug", lang.code())
        });
        bundle.add_resource(resource).unwrap_or_else(|errors| {
            panic!("the {} catalogue's {area} repeats a message: {errors:?}: please report this bug", lang.code())
        });
    }
    bundle
}

/// An argument of a message: text, or a number (for plural choices).
#[derive(Debug, Clone)]
pub enum Arg {
    /// Already written text.
    Text(String),
    /// A whole number.
    Number(i64),
}

impl From<&str> for Arg {
    fn from(text: &str) -> Arg {
        Arg::Text(text.to_string())
    }
}

impl From<String> for Arg {
    fn from(text: String) -> Arg {
        Arg::Text(text)
    }
}

impl From<&String> for Arg {
    fn from(text: &String) -> Arg {
        Arg::Text(text.clone())
    }
}

macro_rules! number_arg {
    ($($t:ty),*) => {$(
        impl From<$t> for Arg {
            fn from(value: $t) -> Arg {
                Arg::Number(value as i64)
            }
        }
    )*};
}
number_arg!(u32, usize, u64, i32, i64);

/// The message `key` in `lang` with `args`; a key missing from a catalogue
/// falls back to English (the key-coverage test keeps that from happening).
pub fn text(lang: Lang, key: &str, args: &[(&str, Arg)]) -> String {
    let bundle = match catalogue(lang).has_message(key) {
        true => catalogue(lang),
        false => catalogue(Lang::En),
    };
    let Some(pattern) = bundle.get_message(key).and_then(|m| m.value()) else {
        debug_assert!(false, "message {key} is missing: please report this bug");
        return key.to_string();
    };
    let mut fluent_args = FluentArgs::new();
    for (name, value) in args {
        match value {
            Arg::Text(t) => fluent_args.set(*name, FluentValue::from(t.as_str())),
            Arg::Number(n) => fluent_args.set(*name, FluentValue::from(*n)),
        }
    }
    let mut errors = Vec::new();
    let out = bundle.format_pattern(pattern, Some(&fluent_args), &mut errors).into_owned();
    debug_assert!(errors.is_empty(), "message {key}: {errors:?}: please report this bug");
    out
}

/// `words!(lang, "key", name = value, …)`: the message in `lang`.
#[macro_export]
macro_rules! words {
    ($lang:expr, $key:expr $(, $name:ident = $value:expr)* $(,)?) => {
        $crate::message($lang, $key, &[$((stringify!($name), $crate::Arg::from($value))),*])
    };
}

// After the macro: `words!` is in scope from here on.
mod shown;
mod system;

pub use shown::{name as shown_name, own_name, path as shown_path, printable};
pub use system::{fact, io_reason, json_reason};

/// How many characters of a token from a file a message quotes.
const TOKEN_SHOWN: usize = 32;

/// A token from an input file as a message quotes it: whole when short, else
/// its first characters, `…` and its length, so that no message repeats more
/// of a file than the token that failed (a 3 MB token prints 3 MB otherwise).
pub fn token(lang: Lang, text: &str) -> String {
    let count = text.chars().count();
    if count <= TOKEN_SHOWN + 8 {
        return text.to_string();
    }
    let shown: String = text.chars().take(TOKEN_SHOWN).collect();
    words!(lang, "token-cut", shown = shown, count = count.to_string())
}

/// A decimal written with a point, in `lang`'s convention.
pub fn localize_decimal(lang: Lang, text: String) -> String {
    match lang.decimal_separator() {
        '.' => text,
        separator => text.replace('.', &separator.to_string()),
    }
}

/// The message keys of each area of a catalogue, in order.
#[cfg(test)]
fn keys(lang: Lang) -> Vec<Vec<String>> {
    lang.catalogue()
        .iter()
        .map(|text| {
            let resource = FluentResource::try_new(text.to_string()).unwrap_or_else(|(r, _)| r);
            resource
                .entries()
                .filter_map(|entry| match entry {
                    fluent_syntax::ast::Entry::Message(m) => Some(m.id.name.to_string()),
                    _ => None,
                })
                .collect()
        })
        .collect()
}

/// The name of a polygon the file leaves unnamed: `polygon N`, numbered from 1.
pub fn default_name(index: usize) -> String {
    format!("polygon {}", index + 1)
}

/// Whether `name` is the one polygon `index` gets when the file names it
/// not: reports then call it by its number alone.
pub fn is_default_name(name: &str, index: usize) -> bool {
    name == default_name(index)
}

/// Polygon `index` named `name` as `message` (`polygon-name` or
/// `polygon-after`) words it: `polygon 2 "triangle"`, or `polygon 2` when
/// the name is the one an unnamed polygon gets (`is_default_name`),
/// which would only repeat the number (and in English).
pub fn polygon_label(lang: Lang, message: &str, index: usize, name: &str) -> String {
    let named = if is_default_name(name, index) { "no" } else { "yes" };
    words!(lang, message, number = index + 1, name = name, named = named)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every message of the English catalogue exists in every other, in the
    /// same area, and no catalogue has a message English lacks or a syntax
    /// error.
    #[test]
    fn every_message_key_exists_in_every_catalogue() {
        let english = keys(Lang::En);
        assert!(english.iter().all(|area| area.len() > 50), "{:?}", english.iter().map(Vec::len).collect::<Vec<_>>());
        for lang in Lang::ALL {
            for (area, text) in AREAS.iter().zip(lang.catalogue()) {
                FluentResource::try_new(text.to_string())
                    .unwrap_or_else(|(_, errors)| panic!("{} {area}: {errors:?}", lang.code()));
            }
            for ((area, ours), theirs) in AREAS.iter().zip(&english).zip(keys(lang)) {
                let missing: Vec<&String> = ours.iter().filter(|k| !theirs.contains(k)).collect();
                let extra: Vec<&String> = theirs.iter().filter(|k| !ours.contains(k)).collect();
                assert_eq!((missing, extra), (vec![], vec![]), "{} {area}", lang.code());
            }
        }
    }

    /// A message is keyed by the fact it states, so that every front end
    /// shows the same words for it: no key is named for the terminal app,
    /// the recorded page or the playground.
    #[test]
    fn no_message_is_keyed_by_a_front_end() {
        let keys: Vec<String> = keys(Lang::En).concat();
        let by_front_end: Vec<&String> = keys
            .iter()
            .filter(|k| ["tui-", "page-", "play-", "app-", "web-"].iter().any(|p| k.starts_with(p)))
            .collect();
        assert!(by_front_end.is_empty(), "{by_front_end:?}");
    }

    #[test]
    fn the_environment_chooses_the_language_as_gettext_does() {
        let env = |pairs: &'static [(&str, &str)]| {
            move |name: &str| pairs.iter().find(|(k, _)| *k == name).map(|(_, v)| v.to_string())
        };
        assert_eq!(Lang::from_vars(env(&[("LANG", "ru_RU.UTF-8")])), Lang::Ru);
        assert_eq!(Lang::from_vars(env(&[("LANG", "ru_RU.UTF-8"), ("LC_ALL", "uk_UA.UTF-8")])), Lang::Uk);
        assert_eq!(Lang::from_vars(env(&[("LANG", "zh_CN.UTF-8"), ("LC_MESSAGES", "")])), Lang::Zh);
        assert_eq!(Lang::from_vars(env(&[("LANG", "C.UTF-8")])), Lang::En);
        assert_eq!(Lang::from_vars(env(&[("LANG", "de_DE.UTF-8")])), Lang::En);
    }

    #[test]
    fn plurals_follow_each_language() {
        let differ = |lang: Lang, count: i64| {
            text(
                lang,
                "check-differ",
                &[
                    ("buffer", "b".into()),
                    ("file", "f".into()),
                    ("count", Arg::Number(count)),
                    ("cells", Arg::Number(1024)),
                    ("after", "p".into()),
                ],
            )
        };
        assert_eq!(differ(Lang::En, 1), "b f: 1 of 1024 cells differs from the b after p");
        assert_eq!(differ(Lang::En, 3), "b f: 3 of 1024 cells differ from the b after p");
        assert!(differ(Lang::Ru, 1).contains("отличается 1"), "{}", differ(Lang::Ru, 1));
        assert!(differ(Lang::Ru, 3).contains("отличаются 3"), "{}", differ(Lang::Ru, 3));
        assert!(differ(Lang::Ru, 5).contains("отличаются 5"), "{}", differ(Lang::Ru, 5));
    }
}
