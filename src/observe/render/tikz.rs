//! A figure as TikZ, for handouts written in LaTeX: the figure's SVG
//! ([`super::figure::svg_with`]) translated element by element, so the two
//! show the same cells, lines, outlines, names, axes and legend. Only what
//! the figure writes is translated: `rect`, `line`, `circle`, `polygon`,
//! `polyline` and `text`, with their fill, stroke, width, dashes, anchor,
//! size and weight, inherited through `g` as in SVG; `title` (a tooltip)
//! has no place on paper and is left out.
//!
//! Coordinates stay the SVG's units, one unit a quarter of a millimetre,
//! with y turned down as in SVG (`y=-0.25mm`). Text is escaped for LaTeX.

use std::fmt::Write;

/// The SVG's drawing attributes in force at an element.
#[derive(Debug, Clone, Default)]
struct Style {
    fill: Option<String>,
    stroke: Option<String>,
    width: Option<String>,
    dashes: Option<String>,
    anchor: Option<String>,
    size: Option<String>,
    bold: bool,
    halo: bool,
}

impl Style {
    /// The element's own attributes over the inherited ones.
    fn with(&self, node: roxmltree::Node<'_, '_>) -> Style {
        let mut style = self.clone();
        let get = |name: &str| node.attribute(name).map(str::to_string);
        style.fill = get("fill").or(style.fill);
        style.stroke = get("stroke").or(style.stroke);
        style.width = get("stroke-width").or(style.width);
        style.dashes = get("stroke-dasharray").or(style.dashes);
        style.anchor = get("text-anchor").or(style.anchor);
        style.size = get("font-size").or(style.size);
        style.bold |= node.attribute("font-weight") == Some("bold");
        style.halo |= node.attribute("paint-order") == Some("stroke");
        style
    }
}

/// The figure's SVG as a `tikzpicture`; with `standalone`, wrapped in a
/// LaTeX document that `pdflatex` compiles as it is.
pub fn tikz(svg: &str, standalone: bool) -> Result<String, String> {
    let document = roxmltree::Document::parse(svg).map_err(|e| e.to_string())?;
    let mut out = String::new();
    if standalone {
        out.push_str(PREAMBLE);
        // Scaled to the page's width, or to its height when that is what binds (A4 with 1 cm margins).
        let side = |name: &str| document.root_element().attribute(name).and_then(|v| v.parse::<f64>().ok());
        let tall = matches!((side("width"), side("height")), (Some(w), Some(h)) if h / w > 277.0 / 190.0);
        out.push_str(if tall {
            "\\noindent\\resizebox{!}{\\textheight}{%\n"
        } else {
            "\\noindent\\resizebox{\\linewidth}{!}{%\n"
        });
    }
    out.push_str("\\begin{tikzpicture}[x=0.25mm, y=-0.25mm, line cap=butt]\n");
    let root = document.root_element();
    let base = Style { fill: Some("black".into()), size: Some("11".into()), ..Style::default() }.with(root);
    for child in root.children().filter(roxmltree::Node::is_element) {
        element(&mut out, child, &base);
    }
    out.push_str("\\end{tikzpicture}\n");
    if standalone {
        out.push_str("}\n\\end{document}\n");
    }
    Ok(out)
}

/// A document for the picture: TikZ, UTF-8 text, and the few characters a
/// figure uses that pdflatex does not know by default.
const PREAMBLE: &str = "\\documentclass{article}\n\
\\usepackage[utf8]{inputenc}\n\
\\usepackage[T1]{fontenc}\n\
\\usepackage{tikz}\n\
\\usepackage[margin=1cm, a4paper]{geometry}\n\
\\DeclareUnicodeCharacter{00BD}{\\ensuremath{\\frac{1}{2}}}\n\
\\DeclareUnicodeCharacter{2248}{\\ensuremath{\\approx}}\n\
\\DeclareUnicodeCharacter{2212}{\\ensuremath{-}}\n\
\\DeclareUnicodeCharacter{00D7}{\\ensuremath{\\times}}\n\
\\DeclareUnicodeCharacter{2026}{\\ldots}\n\
\\pagestyle{empty}\n\
\\begin{document}\n";

fn element(out: &mut String, node: roxmltree::Node<'_, '_>, inherited: &Style) {
    let style = inherited.with(node);
    let number = |name: &str| node.attribute(name).and_then(|v| v.parse::<f64>().ok()).unwrap_or(0.0);
    match node.tag_name().name() {
        "g" => {
            for child in node.children().filter(roxmltree::Node::is_element) {
                element(out, child, &style);
            }
        }
        "rect" => {
            // The background (width="100%") is the page itself.
            if node.attribute("width").is_some_and(|w| w.ends_with('%')) {
                return;
            }
            let (x, y, w, h) = (number("x"), number("y"), number("width"), number("height"));
            let _ = writeln!(out, "\\path[{}] ({x},{y}) rectangle ({},{});", paint(&style, true), x + w, y + h);
        }
        "line" => {
            let (x1, y1, x2, y2) = (number("x1"), number("y1"), number("x2"), number("y2"));
            let _ =
                writeln!(out, "\\path[{}] ({x1},{y1}) -- ({x2},{y2});", paint(&Style { fill: None, ..style }, false));
        }
        "circle" => {
            let (x, y, r) = (number("cx"), number("cy"), number("r"));
            let _ = writeln!(out, "\\path[{}] ({x},{y}) circle[radius={r}];", paint(&style, true));
        }
        "polygon" | "polyline" => {
            let points: Vec<String> = node
                .attribute("points")
                .unwrap_or("")
                .split_whitespace()
                .map(|p| format!("({})", p.replace(' ', ",")))
                .collect();
            if points.is_empty() {
                return;
            }
            let close = if node.tag_name().name() == "polygon" { " -- cycle" } else { "" };
            let _ = writeln!(out, "\\path[{}] {}{close};", paint(&style, true), points.join(" -- "));
        }
        "text" => {
            let text: String = node.children().filter_map(|c| c.text()).collect();
            let anchor = match style.anchor.as_deref() {
                Some("middle") => "base",
                Some("end") => "base east",
                _ => "base west",
            };
            let size: f64 = style.size.as_deref().and_then(|s| s.parse().ok()).unwrap_or(11.0);
            // SVG units are quarter millimetres: a size of 11 is 2.75 mm, about 7.8 pt.
            let points = size * 0.25 / 25.4 * 72.27;
            let colour = style.fill.as_deref().map_or_else(|| "black".to_string(), colour);
            let weight = if style.bold { "\\bfseries" } else { "" };
            let halo = if style.halo { ", fill=white, fill opacity=0.8, text opacity=1" } else { "" };
            let _ = writeln!(
                out,
                "\\node[anchor={anchor}, inner sep=0pt, text={colour}{halo}, font=\\fontsize{{{points:.1}}}{{{:.1}}}\\selectfont{weight}] at ({},{}) {{{}}};",
                points * 1.2,
                number("x"),
                number("y"),
                escape(&text)
            );
        }
        _ => {}
    }
}

/// TikZ's drawing options for a style: fill (for closed shapes), stroke,
/// width and dashes.
fn paint(style: &Style, closed: bool) -> String {
    let mut options = Vec::new();
    if closed && let Some(fill) = style.fill.as_deref().filter(|f| *f != "none") {
        options.push(format!("fill={}", colour(fill)));
    }
    if let Some(stroke) = style.stroke.as_deref().filter(|s| *s != "none") {
        options.push(format!("draw={}", colour(stroke)));
        // SVG's stroke widths are in its units: a quarter millimetre each.
        let width: f64 = style.width.as_deref().and_then(|w| w.parse().ok()).unwrap_or(1.0);
        options.push(format!("line width={:.3}mm", width * 0.25));
        if let Some(dashes) = &style.dashes {
            let parts: Vec<f64> = dashes.split([' ', ',']).filter_map(|d| d.parse().ok()).collect();
            if let [on, off, ..] = parts[..] {
                options.push(format!("dash pattern=on {:.3}mm off {:.3}mm", on * 0.25, off * 0.25));
            }
        }
    }
    options.join(", ")
}

/// An SVG colour (`#rrggbb` or a name TikZ knows) in xcolor's words.
fn colour(svg: &str) -> String {
    match svg.strip_prefix('#').filter(|hex| hex.len() == 6) {
        Some(hex) => {
            let channel = |k: usize| u8::from_str_radix(&hex[2 * k..2 * k + 2], 16).unwrap_or(0);
            format!("{{rgb,255:red,{};green,{};blue,{}}}", channel(0), channel(1), channel(2))
        }
        None => svg.to_string(),
    }
}

/// Whether pdflatex typesets `c` with the document's preamble (UTF-8 input,
/// T1 fonts): printable ASCII, Latin-1 and Latin Extended-A but the eight
/// letters T1 lacks, the dashes, quotes and signs the figure uses. Found by
/// compiling each character alone (the guide's Safety chapter).
fn typesets(c: char) -> bool {
    const T1_LACKS: [char; 8] =
        ['\u{126}', '\u{127}', '\u{138}', '\u{13F}', '\u{140}', '\u{149}', '\u{166}', '\u{167}'];
    const SIGNS: [char; 14] = [
        '\u{2013}', '\u{2014}', '\u{2018}', '\u{2019}', '\u{201C}', '\u{201D}', '\u{2022}', '\u{2026}', '\u{2212}',
        '\u{2248}', '\u{20AC}', '\u{2190}', '\u{2192}', '\u{00BD}',
    ];
    matches!(c, ' '..='~') || (('\u{A0}'..='\u{17E}').contains(&c) && !T1_LACKS.contains(&c)) || SIGNS.contains(&c)
}

/// Text for LaTeX: its special characters written as LaTeX writes them, and
/// every character pdflatex would not typeset ([`typesets`]: a control
/// character, U+2028, U+200B, Cyrillic or Chinese with this preamble)
/// written as a visible `<U+2028>` in typewriter type, so that any name or
/// title gives a document pdflatex compiles.
fn escape(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars() {
        match c {
            '\\' => out.push_str("\\textbackslash{}"),
            '{' | '}' | '$' | '&' | '#' | '_' | '%' => {
                out.push('\\');
                out.push(c);
            }
            '^' => out.push_str("\\textasciicircum{}"),
            '~' => out.push_str("\\textasciitilde{}"),
            '"' => out.push_str("\\textquotedbl{}"),
            '<' => out.push_str("\\textless{}"),
            '>' => out.push_str("\\textgreater{}"),
            c if typesets(c) => out.push(c),
            c => {
                let _ = write!(out, "{{\\ttfamily\\textless{{}}U+{:04X}\\textgreater{{}}}}", u32::from(c));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Everything a file's text can hold reaches LaTeX as text: a scene
    /// named `\input{/etc/passwd}` is printed, not run.
    #[test]
    fn text_is_escaped_for_latex() {
        assert_eq!(
            escape(r"\input{x} 50% $a_b$ #1 & ~^"),
            r"\textbackslash{}input\{x\} 50\% \$a\_b\$ \#1 \& \textasciitilde{}\textasciicircum{}"
        );
    }

    /// Characters pdflatex rejected (a line separator, a zero-width space,
    /// a control character, the U+FFFD that an SVG holds for U+FFFE) are
    /// written as visible escapes it typesets.
    #[test]
    fn characters_pdflatex_cannot_typeset_are_shown_as_escapes() {
        assert_eq!(
            escape("a\u{2028}b\u{200B}c\u{1}d\u{FFFD}é"),
            "a{\\ttfamily\\textless{}U+2028\\textgreater{}}b{\\ttfamily\\textless{}U+200B\\textgreater{}}c\
             {\\ttfamily\\textless{}U+0001\\textgreater{}}d{\\ttfamily\\textless{}U+FFFD\\textgreater{}}é"
        );
    }

    #[test]
    fn each_kind_of_element_becomes_its_tikz_path() {
        let svg = r##"<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">
            <g stroke="#3a6ea5" stroke-width="0.6" stroke-dasharray="3 3"><line x1="0" y1="1" x2="8" y2="1"/></g>
            <rect x="1" y="2" width="3" height="4" fill="#ffffff"/>
            <g fill="none" stroke="black"><polygon points="0,0 4,0 4,4"/></g>
            <text x="5" y="6" text-anchor="middle">a_b</text></svg>"##;
        let tikz = tikz(svg, false).unwrap();
        let lines: Vec<&str> = tikz.lines().collect();
        assert_eq!(
            lines[1],
            "\\path[draw={rgb,255:red,58;green,110;blue,165}, line width=0.150mm, dash pattern=on 0.750mm off 0.750mm] (0,1) -- (8,1);"
        );
        assert_eq!(lines[2], "\\path[fill={rgb,255:red,255;green,255;blue,255}] (1,2) rectangle (4,6);");
        assert_eq!(lines[3], "\\path[draw=black, line width=0.250mm] (0,0) -- (4,0) -- (4,4) -- cycle;");
        assert!(lines[4].starts_with("\\node[anchor=base, inner sep=0pt, text=black, font=\\fontsize{7.8}{9.4}\\selectfont] at (5,6) {a\\_b};"), "{}", lines[4]);
    }
}
