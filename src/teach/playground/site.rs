//! The playground's site as this zsim carries it: the files `web/build`
//! writes (the page, its script and style, the bindings' glue and the
//! WebAssembly module as a script), embedded where the build was given them
//! (`ZSIM_PLAYGROUND`, the folder `web/build` writes); the Debian package and
//! the release archives are built so. From them, the site for any static web
//! server ([`site_files`], `zsim playground`) and the one page that opens from
//! `file://` ([`one_file_page`], `zsim step --html`).

use std::path::Path;

use serde_json::Value;

use crate::effects::arith::Arith;
use crate::scene::Scene;
use crate::teach::page_limits::{PageLimit, check_reach, check_recorded, check_text};
use crate::teach::step::{QuizMode, Stepper};
use crate::words::Lang;

/// The site's files by name, as `web/build` wrote them; `None` when this
/// zsim was built without the playground.
fn embedded() -> Option<[(&'static str, &'static str); 5]> {
    #[cfg(playground)]
    {
        macro_rules! built {
            ($name:literal) => {
                ($name, include_str!(concat!(env!("OUT_DIR"), "/", $name)))
            };
        }
        Some([
            built!("index.html"),
            built!("playground.js"),
            built!("playground.css"),
            built!("zsim_web.js"),
            built!("zsim_module.js"),
        ])
    }
    #[cfg(not(playground))]
    {
        None
    }
}

/// The playground's site, every file by its name, for a static web server or
/// a folder opened from disk (`index.html` first); `None` when this zsim was
/// built without the playground.
pub fn site_files() -> Option<Vec<(String, Vec<u8>)>> {
    Some(embedded()?.iter().map(|(name, text)| (name.to_string(), text.as_bytes().to_vec())).collect())
}

/// Writes the site into `folder` as one plan, replacing an older site's
/// files: the names written; `None` when this zsim was built without the
/// playground.
pub fn write_site(folder: &Path) -> Option<Result<Vec<String>, crate::error::Error>> {
    let files = site_files()?;
    let mut plan = crate::door::Plan::new(&[], crate::door::Replace::Allowed);
    for (name, bytes) in &files {
        plan.file(folder.join(name), bytes.clone());
    }
    Some(plan.write().map(|_| files.into_iter().map(|(name, _)| name).collect()))
}

/// The playground as one self-contained page that opens from `file://`
/// (`zsim step --html`): its style, script and WebAssembly module inlined,
/// the scene in `text` to start with, in `lang` unless the address asks for
/// another (`?lang=`), its quiz on in `quiz`'s mode unless the address says
/// otherwise. `None` when this zsim was built without the playground.
pub fn one_file_page(lang: Lang, text: &str, quiz: Option<QuizMode>) -> Option<String> {
    let [index, script, style, glue, module] = embedded()?.map(|(_, text)| text);
    let quiz = match quiz {
        Some(QuizMode::Depth) => "depth",
        Some(QuizMode::Frame) => "frame",
        Some(QuizMode::Coverage) => "coverage",
        None => "",
    };
    let start = format!(
        "window.ZSIM_SCENE = {};\nwindow.ZSIM_LANG = \"{}\";\nwindow.ZSIM_QUIZ = \"{quiz}\";\n",
        crate::teach::step::page::embedded_json(&Value::String(text.to_string()).to_string()),
        lang.code()
    );
    let page = index
        .replace(r#"<link rel="stylesheet" href="playground.css">"#, &format!("<style>\n{style}</style>"))
        .replace(r#"<script src="zsim_web.js"></script>"#, &format!("<script>\n{glue}\n{start}</script>"))
        .replace(r#"<script src="zsim_module.js"></script>"#, &format!("<script>\n{module}</script>"))
        .replace(r#"<script src="playground.js"></script>"#, &format!("<script>\n{script}</script>"));
    Some(page)
}

/// The page `zsim step --html` writes for `scene` (read from `text`, the
/// file `path`): the playground where this zsim carries it and the
/// arithmetic is exact, its quiz on in `quiz`'s mode; the recorded stepper
/// otherwise. Refused past the page's limits before it is made.
pub fn step_page(
    lang: Lang,
    scene: &Scene,
    text: &str,
    path: &Path,
    arith: Arith,
    quiz: Option<QuizMode>,
) -> Result<String, PageLimit> {
    if arith == Arith::Exact && embedded().is_some() {
        check_text(text, Some(path))?;
        check_reach(scene, Some(path))?;
        return Ok(one_file_page(lang, text, quiz).unwrap_or_default());
    }
    check_recorded(scene, path)?;
    let name = path.file_name().map_or_else(|| crate::words::shown_path(path), |n| n.to_string_lossy().into());
    Ok(crate::teach::step::page::page(lang, &mut Stepper::new(scene, arith), &name))
}
