//! A class's files, planned whole before any is written: the teacher's
//! folder holds the manifest, the fairness table, the keys and one printable
//! file of every worksheet; each student's folder under `students/` holds
//! only what that student may see: their scene, their worksheet with their
//! name and variant code, what to hand in and a blank answer file for each
//! buffer, and their playground link. Nothing in a student's folder gives a
//! cell of an answer away.

use std::path::{Path, PathBuf};

use crate::door::Plan;
use crate::error::Error;
use crate::observe::explain::Buffer;
use crate::observe::render::figure::{Annotations, Shading, svg_with};
use crate::observe::render::picture::{Format, Paper};
use crate::observe::render::report::matrix;
use crate::observe::render::svg_text::escape;
use crate::scene::Scene;
use crate::simulate::simulation::Simulation;
use crate::teach::check::diagnose::Misconception;
use crate::teach::exercise::HardCase;
use crate::teach::grade::file_kind;
use crate::teach::grade::gradebooks::csv_field;
use crate::words::{Lang, printable};

use super::fair::key_of;
use super::manifest::{Manifest, Variant};

/// A student's folder in the class's folder: `students/IDENTITY`.
pub fn student_folder(dir: &Path, variant: &Variant) -> PathBuf {
    dir.join("students").join(&variant.identity)
}

/// The name of a student's answer file for `buffer`: `IDENTITY.frame.txt`.
pub fn answer_name(identity: &str, buffer: Buffer) -> String {
    format!("{identity}.{}.txt", file_kind(buffer))
}

/// What the class's files are made with.
pub struct Handouts<'a> {
    /// The students' language.
    pub lang: Lang,
    /// The manifest.
    pub manifest: &'a Manifest,
    /// The worksheet's formats.
    pub formats: &'a [Format],
    /// The playground's address, for each student's link.
    pub site: Option<&'a str>,
}

/// Plans every file of the class into `dir`, each made when it is written;
/// returns the names listed for the teacher (the teacher's files, then the
/// students' folder).
pub fn plan<'a>(handouts: &'a Handouts<'a>, dir: &Path, fairness_text: String, plan: &mut Plan<'a>) -> Vec<String> {
    let Handouts { lang, manifest, .. } = *handouts;
    plan.file(dir.join("variants.json"), manifest.to_json());
    plan.file(dir.join("fairness.txt"), fairness_text);
    plan.file(dir.join("fairness.csv"), fairness_csv(manifest));
    let mut listed = vec!["variants.json".to_string(), "fairness.txt".into(), "fairness.csv".into()];
    for variant in &manifest.students {
        for buffer in manifest.buffers() {
            plan.file_made(dir.join("keys").join(answer_name(&variant.identity, buffer)), move || {
                let (frame, depth) = key_of(&scene_of(variant)?);
                let rows = if buffer == Buffer::Frame { frame } else { depth };
                Ok(format!("# variant {} (the key)\n{}", variant.code, matrix(&rows, false)).into_bytes())
            });
        }
    }
    listed.push("keys/".into());
    plan.file(dir.join("worksheets.html"), worksheets_html(handouts));
    listed.push("worksheets.html".into());
    for variant in &manifest.students {
        let folder = student_folder(dir, variant);
        plan.file(folder.join("scene.json"), variant.scene.get().to_string() + "\n");
        for format in handouts.formats {
            let name = format!("worksheet.{}", format.extension());
            let path = folder.join(&name);
            let format = *format;
            plan.file_made(folder.join(&name), move || {
                let worksheet = worksheet(lang, manifest, variant, &scene_of(variant)?);
                format.encode(lang, &worksheet, &path, false, (None, Paper::default()))
            });
        }
        for buffer in manifest.buffers() {
            plan.file_made(folder.join(answer_name(&variant.identity, buffer)), move || {
                Ok(template(lang, variant, &scene_of(variant)?, buffer).into_bytes())
            });
        }
        plan.file(folder.join("hand-in.txt"), hand_in(lang, manifest, variant, handouts.site));
    }
    listed.push("students/".into());
    listed
}

/// A student's worksheet: the blank raster with the polygons' vertices,
/// their name and variant code in the title, and what to hand in.
pub fn worksheet(lang: Lang, manifest: &Manifest, variant: &Variant, scene: &Scene) -> String {
    let title = words!(
        lang,
        "class-worksheet-title",
        name = printable(&variant.name).into_owned(),
        code = variant.code.as_str(),
        width = scene.width,
        height = scene.height,
        count = scene.polygons.len()
    );
    let files: Vec<String> = manifest.buffers().iter().map(|b| answer_name(&variant.identity, *b)).collect();
    let caption = vec![
        words!(lang, "exercise-task-draw", max = scene.depth_max()),
        words!(lang, "exercise-task-write"),
        words!(lang, "class-worksheet-hand-in", files = files.join(", "), code = variant.code.as_str()),
    ];
    let blank = Simulation::new(scene);
    let extras = Annotations { vertex_labels: true, caption, values: false };
    svg_with(lang, scene, blank.buffers(), scene.polygons.len() - 1, Shading::Frame, &title, &extras)
}

/// A student's scene, read from the manifest as their `scene.json` is.
fn scene_of(variant: &Variant) -> Result<Scene, Error> {
    Scene::from_json(variant.scene.get(), Path::new("scene.json"))
}

/// One printable page of every worksheet, in the roster's order: each
/// student's heading and their `worksheet.svg` from their folder, a page
/// each when printed (the pictures are read from the folders beside it, so
/// the page costs a line a student, whatever the class's size).
fn worksheets_html(handouts: &Handouts<'_>) -> String {
    let Handouts { lang, manifest, formats, .. } = *handouts;
    // A picture a browser shows and prints: the SVG, else the PNG; a PDF or TeX worksheet is linked.
    let shown = [Format::Svg, Format::Png].into_iter().find(|f| formats.contains(f));
    let linked = shown.or_else(|| formats.first().copied()).unwrap_or(Format::Svg);
    let title = escape(&words!(lang, "class-worksheets-title", count = manifest.students.len()));
    let mut html = format!(
        "<!doctype html>\n<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n<title>{title}</title>\n\
         <style>body{{font-family:sans-serif}} section{{break-after:page;page-break-after:always}} \
         img{{max-width:100%;height:auto}}</style>\n</head>\n<body>\n",
        lang.code()
    );
    for variant in &manifest.students {
        let heading = escape(&format!("{} · {}", printable(&variant.name), variant.code));
        let folder = url_escaped(&variant.identity);
        let file = format!("students/{folder}/worksheet.{}", linked.extension());
        let body = match shown {
            Some(_) => format!("<img src=\"{file}\" alt=\"{heading}\">"),
            None => format!("<a href=\"{file}\">{file}</a>"),
        };
        html.push_str(&format!("<section>\n<h2>{heading}</h2>\n{body}\n</section>\n"));
    }
    html.push_str("</body>\n</html>\n");
    html
}

/// A blank answer file: its comment lines (the buffer, the variant code, the
/// student) and a `?` for every cell.
pub fn template(lang: Lang, variant: &Variant, scene: &Scene, buffer: Buffer) -> String {
    let mut text = format!(
        "# {}\n# variant {}\n# {}\n",
        words!(lang, "class-template-what", buffer = buffer.name(lang), name = printable(&variant.name).into_owned()),
        variant.code,
        words!(lang, "class-template-how", width = scene.width)
    );
    let row = vec!["?"; scene.width as usize].join(" ");
    for _ in 0..scene.height {
        text.push_str(&row);
        text.push('\n');
    }
    text
}

/// What a student hands in, and how: `hand-in.txt` in their folder.
fn hand_in(lang: Lang, manifest: &Manifest, variant: &Variant, site: Option<&str>) -> String {
    let mut text = words!(
        lang,
        "class-hand-in-who",
        name = printable(&variant.name).into_owned(),
        identity = printable(&variant.identity).into_owned(),
        code = variant.code.as_str()
    ) + "\n";
    text.push_str(&(words!(lang, "class-hand-in-files", count = manifest.buffers().len()) + "\n"));
    for buffer in manifest.buffers() {
        let file = answer_name(&variant.identity, buffer);
        text.push_str(&format!("  {}\n", words!(lang, "class-hand-in-file", file = file, buffer = buffer.name(lang))));
    }
    let (width, height) = (manifest.settings.width, manifest.settings.height);
    text.push_str(
        &(words!(lang, "class-hand-in-format", width = width, height = height, code = variant.code.as_str()) + "\n"),
    );
    if let Some(site) = site {
        text.push_str(&(words!(lang, "class-hand-in-link", link = link(site, variant)) + "\n"));
    }
    text
}

/// A student's playground link: the site's address, their scene in the
/// fragment and the quiz on.
pub fn link(site: &str, variant: &Variant) -> String {
    let base = site.split('#').next().unwrap_or(site);
    let scene = crate::teach::playground::fragment_of(variant.scene.get());
    format!("{base}#{scene}&quiz=depth&student={}&variant={}", url_escaped(&variant.identity), variant.code)
}

/// A text in a URL: each byte outside RFC 3986's unreserved set percent-encoded.
fn url_escaped(text: &str) -> String {
    text.bytes()
        .map(|b| match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' => (b as char).to_string(),
            _ => format!("%{b:02X}"),
        })
        .collect()
}

/// The fairness table as CSV: a row a student, their code, how many times
/// each hard case arises, and how many cells each wrong rule's answer
/// differs from the key in.
pub fn fairness_csv(manifest: &Manifest) -> String {
    let mut text = String::from("identity,code");
    for case in HardCase::ALL {
        text.push_str(&format!(",{}", case.name()));
    }
    for rule in Misconception::ALL {
        text.push_str(&format!(",{}", rule.name()));
    }
    text.push('\n');
    for variant in &manifest.students {
        text.push_str(&format!("{},{}", csv_field(&variant.identity), variant.code));
        for count in variant.cases.iter().chain(&variant.separations) {
            text.push_str(&format!(",{}", count.count));
        }
        text.push('\n');
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_template_reads_back_as_an_answer_with_every_cell_unanswered() {
        let scene = Scene::from_json(
            r#"{"width": 4, "height": 3, "polygons": [{"value": 1, "vertices": [[0, 0, 5], [4, 0, 5], [0, 3, 5]]}]}"#,
            Path::new("s.json"),
        )
        .unwrap();
        let variant: Variant = serde_json::from_str(
            r#"{"identity": "ana", "name": "Ana\nLima", "code": "7KQ-M3X", "seed": 1, "attempt": 0,
                "scene": {}, "cases": [], "separations": []}"#,
        )
        .unwrap();
        let text = template(Lang::En, &variant, &scene, Buffer::Depth);
        assert_eq!(super::super::manifest::code_in(&text), Some("7KQ-M3X"));
        assert!(text.contains("Ana\\u{a}Lima"), "{text}");
        let answer = crate::teach::check::answer_from_text(&text, &scene, Buffer::Depth).unwrap();
        assert_eq!(answer.unanswered(), 12);
    }
}
