//! Handouts: `figure -o F.tex` writes TikZ that pdflatex compiles, `-o
//! F.pdf` a PDF that renders, and `exercise --formats` writes its worksheet
//! and solution in each; both pictures are rendered here (pdftoppm, from
//! Debian's poppler-utils) and must show the figure's fill colours.

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::{missing, ran, zsim};

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("handouts").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The first line `NAME -v` prints (its version); a test that needs the tool
/// is `#[ignore = "needs …"]`.
fn tool(name: &str, package: &str) -> String {
    let Ok(output) = Command::new(name).arg("-v").output() else {
        missing(&format!("{name} ({package})"), "a handout")
    };
    let text = String::from_utf8_lossy(&output.stderr).to_string() + &String::from_utf8_lossy(&output.stdout);
    text.lines().next().unwrap_or(name).to_string()
}

/// pdflatex with TikZ.
const TEX: &str = "texlive-latex-base, texlive-pictures";

/// The page of a PDF as RGB pixels, rendered by pdftoppm at 40 dpi.
fn rendered(pdf: &Path) -> Vec<[u8; 3]> {
    let prefix = pdf.with_extension("page");
    let status =
        Command::new("pdftoppm").args(["-r", "40", "-png", "-singlefile"]).arg(pdf).arg(&prefix).status().unwrap();
    assert!(status.success(), "pdftoppm renders {}", pdf.display());
    let decoder =
        png::Decoder::new(std::io::BufReader::new(std::fs::File::open(format!("{}.png", prefix.display())).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buffer = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buffer).unwrap();
    let channels = info.color_type.samples();
    buffer[..info.buffer_size()].chunks(channels).map(|p| [p[0], p[1], p[2]]).collect()
}

/// Whether a rendered page shows a colour (within a few levels: anti-aliasing).
fn shows(pixels: &[[u8; 3]], colour: [u8; 3]) -> bool {
    pixels.iter().filter(|p| p.iter().zip(colour).all(|(a, b)| a.abs_diff(b) <= 6)).count() > 20
}

/// The fill colours of the figure's covered pixels, from its SVG.
fn fills(svg: &str) -> Vec<[u8; 3]> {
    let start = svg.find(r#"<g id="pixels""#).unwrap();
    let group = &svg[start..start + svg[start..].find("</g>").unwrap()];
    let mut colours: Vec<[u8; 3]> = group
        .split("fill=\"#")
        .skip(1)
        .map(|rest| {
            let hex = &rest[..6];
            [0, 1, 2].map(|k| u8::from_str_radix(&hex[2 * k..2 * k + 2], 16).unwrap())
        })
        .collect();
    colours.sort();
    colours.dedup();
    colours
}

/// The book's figure with its values, written as each of `names` (`NAME-only.tex`: TikZ
/// alone) into a scratch folder `folder`, which is returned.
fn figures(folder: &str, names: &[&str]) -> PathBuf {
    let dir = scratch(folder);
    for name in names {
        let path = dir.join(name).to_str().unwrap().to_string();
        let mut args = vec!["figure", "examples/rogers.json", "--values", "-o", &path];
        if name.ends_with("-only.tex") {
            args.push("--tikz-only");
        }
        let run = zsim(&args);
        assert_eq!((run.code, run.stderr.as_str()), (0, ""), "{name}");
    }
    dir
}

/// The figure's TikZ and SVG: one filled rectangle per run of cells, a node per value.
#[test]
fn figure_writes_tikz_cell_for_cell_as_its_svg() {
    let dir = figures("figure-tikz", &["rogers.svg", "rogers.tex", "rogers-only.tex"]);
    let svg = std::fs::read_to_string(dir.join("rogers.svg")).unwrap();
    assert_eq!(fills(&svg).len(), 2, "the rectangle's and the triangle's fill");
    let tex = std::fs::read_to_string(dir.join("rogers.tex")).unwrap();
    assert!(tex.starts_with("\\documentclass{article}") && tex.ends_with("\\end{document}\n"));
    let only = std::fs::read_to_string(dir.join("rogers-only.tex")).unwrap();
    assert!(only.starts_with("\\begin{tikzpicture}") && only.ends_with("\\end{tikzpicture}\n"));
    // The same cells: one filled rectangle in TikZ per run of cells in the SVG.
    let svg_cells = svg.matches("<rect x=").count() - 3;
    let tex_cells = only.matches(") rectangle (").count() - 3;
    assert_eq!(tex_cells, svg_cells);
    // The cell values, each a node.
    assert_eq!(only.matches("] at (").count(), svg.matches("<text ").count());
}

/// The figure's PDF (the figures feature) and its TikZ compiled by pdflatex,
/// both rendered by pdftoppm, show the figure's fill colours.
#[test]
#[ignore = "needs the figures feature, pdftoppm (poppler-utils) and pdflatex (texlive-latex-base, texlive-pictures)"]
fn figure_writes_tikz_that_compiles_and_a_pdf_that_renders() {
    let dir = figures("figure", &["rogers.svg", "rogers.pdf", "rogers.tex"]);
    let svg = std::fs::read_to_string(dir.join("rogers.svg")).unwrap();
    let colours = fills(&svg);
    assert_eq!(colours.len(), 2, "the rectangle's and the triangle's fill: {colours:?}");
    let pdf = std::fs::read(dir.join("rogers.pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF-"));
    let poppler = tool("pdftoppm", "poppler-utils");
    let page = rendered(&dir.join("rogers.pdf"));
    assert!(colours.iter().all(|c| shows(&page, *c)), "the PDF shows the fills {colours:?}");
    ran("the figure's PDF rendered", &poppler);
    let latex = tool("pdflatex", TEX);
    let compiled = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "rogers.tex"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let log = String::from_utf8_lossy(&compiled.stdout);
    assert!(compiled.status.success(), "pdflatex: {log}");
    assert!(log.contains("Output written on rogers.pdf (1 page"), "{log}");
    let page = rendered(&dir.join("rogers.pdf"));
    assert!(colours.iter().all(|c| shows(&page, *c)), "the TikZ page shows the fills {colours:?}");
    ran("the figure's TikZ compiled and rendered", &latex);
}

#[test]
#[ignore = "needs the figures feature and pdflatex (texlive-latex-base, texlive-pictures)"]
fn an_exercise_writes_its_worksheet_and_solution_in_each_format_asked() {
    let dir = scratch("exercise");
    let folder = dir.join("ex");
    let run = zsim(&["exercise", "--seed", "3", "--formats", "svg,pdf,tex", "-o", folder.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    // Beside zsim's PDF the TeX source is NAME-tikz.tex, so that pdflatex on it writes
    // NAME-tikz.pdf: `pdflatex worksheet.tex` once overwrote zsim's own worksheet.pdf.
    for name in ["worksheet", "solution"] {
        for file in [format!("{name}.svg"), format!("{name}.pdf"), format!("{name}-tikz.tex")] {
            assert!(folder.join(&file).is_file(), "{file}");
        }
        assert!(!folder.join(format!("{name}.tex")).exists());
        // The page is A4, turned to landscape when the figure fits larger so.
        let pdf = std::fs::read(folder.join(format!("{name}.pdf"))).unwrap();
        let media =
            String::from_utf8_lossy(&pdf).split("/MediaBox [").nth(1).unwrap().split(']').next().unwrap().to_string();
        assert!(["0 0 595.2756 841.8898", "0 0 841.8898 595.2756"].contains(&media.as_str()), "{name}: {media}");
    }
    {
        let latex = tool("pdflatex", TEX);
        let before = std::fs::read(folder.join("worksheet.pdf")).unwrap();
        let compiled = Command::new("pdflatex")
            .args(["-interaction=nonstopmode", "-halt-on-error", "worksheet-tikz.tex"])
            .current_dir(&folder)
            .output()
            .unwrap();
        assert!(compiled.status.success(), "{}", String::from_utf8_lossy(&compiled.stdout));
        assert!(folder.join("worksheet-tikz.pdf").is_file());
        assert_eq!(std::fs::read(folder.join("worksheet.pdf")).unwrap(), before, "zsim's PDF is left alone");
        ran("pdflatex on the exercise's TeX beside its PDF", &latex);
    }
    // `figure --paper letter`: a US Letter page.
    let letter = dir.join("letter.pdf");
    let run = zsim(&["figure", "examples/rogers.json", "--paper", "letter", "-o", letter.to_str().unwrap()]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let pdf = String::from_utf8_lossy(&std::fs::read(&letter).unwrap()).into_owned();
    assert!(pdf.contains("/MediaBox [0 0 792 612]") || pdf.contains("/MediaBox [0 0 612 792]"), "a Letter page");
    let run = zsim(&["exercise", "--seed", "3", "--formats", "svg,doc", "-o", dir.join("bad").to_str().unwrap()]);
    assert_eq!(run.code, 2);
    assert!(run.stderr.contains("doc"), "{}", run.stderr);
}

/// `.tex` handouts pdflatex rejected: names holding U+2028 or U+200B, a
/// title with a control character, a name with U+FFFE (which the SVG holds
/// as U+FFFD), a Russian figure, and zsim's own figure of a valid
/// perspective scene with a vertex near the eye ("Dimension too large").
#[test]
#[ignore = "needs pdflatex (texlive-latex-base, texlive-pictures)"]
fn every_handout_compiles_whatever_its_names_hold() {
    let latex = tool("pdflatex", TEX);
    let dir = scratch("odd-names");
    let names = "a\u{2028}b\u{200B}c\u{FFFE}d é ł Прямоугольник 三角形 \\\\input{x} $ % & #";
    std::fs::write(
        dir.join("names.json"),
        serde_json::json!({"width": 8, "height": 8, "polygons": [
            {"name": names, "value": 1, "vertices": [[0, 0, 1], [8, 0, 1], [0, 8, 1]]}]})
        .to_string(),
    )
    .unwrap();
    std::fs::write(
        dir.join("near.json"),
        r#"{"width": 32, "height": 32, "frame_bits": 2, "depth_bits": 5,
            "effects": {"perspective": {"distance": 40, "near": 1}},
            "polygons": [{"name": "close", "value": 1, "vertices": [[0, 0, 38.999], [32, 0, 38.999], [16, 32, 20]]}]}"#,
    )
    .unwrap();
    for (scene, title, lang) in
        [("names.json", "T\u{1}itle \u{2028}", "en"), ("near.json", "near", "en"), ("names.json", "заголовок", "ru")]
    {
        let tex = format!("{}-{lang}.tex", scene.trim_end_matches(".json"));
        let run = crate::zsim_in(Some(&dir), &["figure", scene, "-o", &tex, "--title", title, "--lang", lang]);
        assert_eq!(run.code, 0, "{}", run.stderr);
        let compiled = Command::new("pdflatex")
            .args(["-interaction=nonstopmode", "-halt-on-error", &tex])
            .current_dir(&dir)
            .output()
            .unwrap();
        let log = String::from_utf8_lossy(&compiled.stdout);
        assert!(compiled.status.success(), "{tex}: pdflatex: {log}");
    }
    ran("handouts with odd names compiled", &latex);
}

/// A text of a figure's SVG as a box: (left, top, right, bottom), its width
/// estimated as the figure lays it out (about 6 units a character at font size
/// 10, 7 at 11, 8 bold), its height the font's.
fn text_boxes(svg: &str, group: &str, per_char: f64, size: f64) -> Vec<(String, [f64; 4])> {
    let start = svg.find(&format!(r#"<g id="{group}""#)).unwrap_or_else(|| panic!("a group {group}"));
    let body = &svg[start..start + svg[start..].find("</g>").unwrap()];
    let attribute = |tag: &str, name: &str| {
        let at = tag.find(&format!(" {name}=\""))? + name.len() + 3;
        Some(tag[at..at + tag[at..].find('"')?].to_string())
    };
    body.split("<text")
        .skip(1)
        .map(|rest| {
            let (tag, rest) = rest.split_once('>').unwrap();
            let text = rest.split("</text>").next().unwrap().to_string();
            let x: f64 = attribute(tag, "x").unwrap().parse().unwrap();
            let y: f64 = attribute(tag, "y").unwrap().parse().unwrap();
            let width = text.chars().count() as f64 * per_char;
            let left = match attribute(tag, "text-anchor").as_deref() {
                Some("end") => x - width,
                Some("middle") => x - width / 2.0,
                _ => x,
            };
            (text, [left, y - size * 0.75, left + width, y + size * 0.2])
        })
        .collect()
}

fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// Found by a teacher: handouts' vertex labels sat on centre dots and
/// scanlines ("(10, 5, 10)" read "(10,.5, 10)") and covered cell values;
/// leader lines ran along edges. The labels stand in columns beside the
/// raster, where no cell, centre or value is, clear of each other, of the
/// row numbers and of the polygons' names, on the book's worksheet and on
/// a 3-polygon exercise's worksheet and answer key.
#[test]
fn vertex_labels_collide_with_no_centre_value_or_other_label() {
    let dir = scratch("labels");
    let book = dir.join("book.svg");
    let run = zsim(&["figure", "examples/rogers.json", "--after", "0", "-o", book.to_str().unwrap()]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    let exercise = dir.join("ex");
    let run =
        zsim(&["exercise", "--seed", "4", "--polygons", "3", "--formats", "svg", "-o", exercise.to_str().unwrap()]);
    assert_eq!(run.code, 0, "{}", run.stderr);
    for (figure, labels) in [(book, 7), (exercise.join("worksheet.svg"), 9), (exercise.join("solution.svg"), 9)] {
        let svg = std::fs::read_to_string(&figure).unwrap();
        let vertices = text_boxes(&svg, "vertices", 6.0, 10.0);
        assert_eq!(vertices.len(), labels, "{}", figure.display());
        // The raster: the grid's outer lines.
        let grid = &svg[svg.find(r#"<g id="grid""#).unwrap()..];
        let grid = &grid[..grid.find("</g>").unwrap()];
        let coordinates = |names: [&str; 2]| -> Vec<f64> {
            let mut found = Vec::new();
            for name in names {
                for rest in grid.split(&format!(" {name}=\"")).skip(1) {
                    found.push(rest.split('"').next().unwrap().parse().unwrap());
                }
            }
            found
        };
        let (xs, ys) = (coordinates(["x1", "x2"]), coordinates(["y1", "y2"]));
        let low = |v: &[f64]| v.iter().cloned().fold(f64::INFINITY, f64::min);
        let high = |v: &[f64]| v.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        let raster = [low(&xs), low(&ys), high(&xs), high(&ys)];
        let mut others = text_boxes(&svg, "names", 8.0, 11.0);
        others.extend(text_boxes(&svg, "axes", 7.0, 11.0));
        let width: f64 = svg.split("width=\"").nth(1).unwrap().split('"').next().unwrap().parse().unwrap();
        for (k, (text, area)) in vertices.iter().enumerate() {
            assert!(!overlap(area, &raster), "{}: {text} over the raster {area:?} {raster:?}", figure.display());
            assert!(area[0] >= 0.0 && area[2] <= width, "{}: {text} outside the figure", figure.display());
            for (other, other_area) in vertices[k + 1..].iter().chain(&others) {
                assert!(!overlap(area, other_area), "{}: {text} over {other}", figure.display());
            }
        }
    }
}
