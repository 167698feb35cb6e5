//! A figure's SVG in the other formats a handout takes: a PNG picture, a
//! PDF page and a TikZ picture in a LaTeX document, chosen by the output's
//! extension.

use std::path::Path;

use crate::error::{Error, Refusal};
use crate::words::{Lang, shown_path};

/// A figure refused: each with the facts its message states.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum FigureRefused {
    /// A raster past the largest side a figure draws.
    TooLarge {
        /// The scene file.
        path: std::path::PathBuf,
        /// The raster's width.
        width: u32,
        /// The raster's height.
        height: u32,
        /// The largest side a figure draws.
        max: u32,
    },
    /// A scene without polygons: nothing to draw.
    NoPolygons {
        /// The scene file.
        path: std::path::PathBuf,
    },
    /// The PNG renderer failed.
    PngFailed {
        /// The PNG asked for.
        path: std::path::PathBuf,
        /// What failed.
        reason: String,
    },
}

impl Refusal for FigureRefused {
    fn message(&self, lang: Lang) -> String {
        match self {
            FigureRefused::TooLarge { path, width, height, max } => words!(
                lang,
                "usage-figure-too-large",
                path = shown_path(path),
                width = width.to_string(),
                height = height.to_string(),
                max = max.to_string()
            ),
            FigureRefused::NoPolygons { path } => words!(lang, "usage-no-polygons-draw", path = shown_path(path)),
            FigureRefused::PngFailed { path, reason } => {
                words!(lang, "usage-png-failed", path = shown_path(path), reason = reason)
            }
        }
    }
}

/// A format a figure is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// The SVG itself.
    Svg,
    /// A picture at twice the SVG's size.
    Png,
    /// A page (A4 or Letter) with the figure fitted on it.
    Pdf,
    /// A TikZ picture in a LaTeX document (with `whole`), or alone.
    Tex,
}

/// The paper a figure's PDF page is: A4 (the default) or US Letter, turned
/// to landscape when that fits the figure larger.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Paper {
    /// 210 × 297 mm.
    #[default]
    A4,
    /// 8.5 × 11 inches.
    Letter,
}

impl Paper {
    /// The papers' names, as `--paper` takes them.
    pub const NAMES: [&'static str; 2] = ["a4", "letter"];

    /// The paper named `name` (`a4`, `letter`, in any case).
    pub fn parse(name: &str) -> Option<Paper> {
        match name.to_ascii_lowercase().as_str() {
            "a4" => Some(Paper::A4),
            "letter" => Some(Paper::Letter),
            _ => None,
        }
    }

    /// Width and height in points (1/72 inch), portrait.
    pub fn points(self) -> (f32, f32) {
        match self {
            Paper::A4 => (595.2756, 841.8898),
            Paper::Letter => (612.0, 792.0),
        }
    }
}

/// The margin around a figure on its PDF page: half an inch, in points.
pub const PAGE_MARGIN: f32 = 36.0;

impl Format {
    /// Every format, in the order of [`Format::NAMES`].
    pub const ALL: [Format; 4] = [Format::Svg, Format::Png, Format::Pdf, Format::Tex];

    /// The formats' names, which are also their files' extensions.
    pub const NAMES: [&'static str; 4] = ["svg", "png", "pdf", "tex"];

    /// The format named `name` (an extension, in any case).
    pub fn parse(name: &str) -> Option<Format> {
        let name = name.to_ascii_lowercase();
        Format::NAMES.iter().position(|n| *n == name).map(|i| Format::ALL[i])
    }

    /// The format a file's extension asks for.
    pub fn of(path: &Path) -> Option<Format> {
        path.extension().and_then(|e| e.to_str()).and_then(Format::parse)
    }

    /// The extension of its files.
    pub fn extension(self) -> &'static str {
        Format::NAMES[Format::ALL.iter().position(|f| *f == self).expect("every format is named")]
    }

    /// `svg` in this format, for the file `path` (named in errors); a TeX
    /// file is a whole LaTeX document unless `tikz_only`.
    /// A PNG is drawn at `scale` pixels a unit (default: 2, or less to keep
    /// its longer side within [`PNG_SIDE`]); a PDF is a page of `paper`.
    pub fn encode(
        self,
        lang: Lang,
        svg: &str,
        path: &Path,
        tikz_only: bool,
        (scale, paper): (Option<f32>, Paper),
    ) -> Result<Vec<u8>, Error> {
        match self {
            Format::Svg => Ok(svg.as_bytes().to_vec()),
            Format::Png => png(lang, svg, path, scale),
            Format::Pdf => pdf(lang, svg, path, paper),
            Format::Tex => crate::observe::tikz::tikz(svg, !tikz_only)
                .map(String::into_bytes)
                .map_err(|reason| FigureRefused::PngFailed { path: path.to_path_buf(), reason }.into()),
        }
    }
}

/// The longest side of a figure's PNG unless `--scale` asks for more, in
/// pixels: the default scale, 2 pixels a unit, is lowered to keep within it.
pub const PNG_SIDE: f32 = 4096.0;

/// The most pixels a figure's PNG may have, whatever `--scale` asks: 8192 ×
/// 8192, 256 MiB as RGBA. Refused before the image is allocated.
pub const MAX_PNG_PIXELS: f64 = 8192.0 * 8192.0;

/// The SVG drawn as a PNG at `scale` pixels a unit (default: twice its size,
/// or less to keep the longer side within [`PNG_SIDE`]), text in the
/// system's sans-serif font; more than [`MAX_PNG_PIXELS`] is refused.
#[cfg(feature = "figures")]
pub fn png(lang: Lang, svg: &str, path: &Path, scale: Option<f32>) -> Result<Vec<u8>, Error> {
    let failed = |reason: String| Error::from(FigureRefused::PngFailed { path: path.to_path_buf(), reason });
    let tree = tree(lang, svg, path)?;
    let (width, height) = (tree.size().width(), tree.size().height());
    let scale = scale.unwrap_or_else(|| 2f32.min(PNG_SIDE / width.max(height).max(1.0)));
    let pixels = f64::from(width * scale).ceil() * f64::from(height * scale).ceil();
    if !(scale > 0.0 && pixels <= MAX_PNG_PIXELS) {
        return Err(failed(words!(lang, "png-figure-too-many-pixels", max = (MAX_PNG_PIXELS as u64).to_string())));
    }
    let size = tree.size().to_int_size().scale_by(scale).ok_or_else(|| failed(words!(lang, "png-figure-too-large")))?;
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| failed(words!(lang, "png-figure-too-large")))?;
    resvg::render(&tree, resvg::tiny_skia::Transform::from_scale(scale, scale), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| failed(e.to_string()))
}

/// The SVG on one page of `paper` (portrait or landscape, whichever shows
/// it larger), fitted within [`PAGE_MARGIN`] and centred across, its text
/// drawn as the outlines of the system's sans-serif font (the glyphs the PNG
/// shows; the PDF embeds no font, so needs none of svg2pdf's font crates).
#[cfg(feature = "figures")]
pub fn pdf(lang: Lang, svg: &str, path: &Path, paper: Paper) -> Result<Vec<u8>, Error> {
    let failed = |reason: String| Error::from(FigureRefused::PngFailed { path: path.to_path_buf(), reason });
    let tree = tree(lang, svg, path)?;
    // usvg writes text as paths (its glyphs' outlines) unless asked to keep it.
    let outlined = tree.to_string(&resvg::usvg::WriteOptions::default());
    let (width, height) = (tree.size().width(), tree.size().height());
    let (short, long) = paper.points();
    let fit = |(page_width, page_height): (f32, f32)| {
        ((page_width - 2.0 * PAGE_MARGIN) / width).min((page_height - 2.0 * PAGE_MARGIN) / height)
    };
    let (page_width, page_height) = if fit((long, short)) > fit((short, long)) { (long, short) } else { (short, long) };
    let scale = fit((page_width, page_height));
    let x = (page_width - width * scale) / 2.0;
    // The written SVG's content, inside its root element, placed on the page.
    let body = outlined.find('>').zip(outlined.rfind("</svg>")).map_or("", |(start, end)| &outlined[start + 1..end]);
    let page = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="{page_width}" height="{page_height}" viewBox="0 0 {page_width} {page_height}"><g transform="matrix({scale} 0 0 {scale} {x} {PAGE_MARGIN})">{body}</g></svg>"#
    );
    let page =
        resvg::usvg::Tree::from_str(&page, &resvg::usvg::Options::default()).map_err(|e| failed(e.to_string()))?;
    svg2pdf::to_pdf(&page, svg2pdf::ConversionOptions::default(), svg2pdf::PageOptions::default())
        .map_err(|e| failed(e.to_string()))
}

/// Without the `figures` feature: says so.
#[cfg(not(feature = "figures"))]
pub fn png(lang: Lang, _svg: &str, path: &Path, _scale: Option<f32>) -> Result<Vec<u8>, Error> {
    Err(not_built(lang, path, Format::Png))
}

/// Without the `figures` feature: says so.
#[cfg(not(feature = "figures"))]
pub fn pdf(lang: Lang, _svg: &str, path: &Path, _paper: Paper) -> Result<Vec<u8>, Error> {
    Err(not_built(lang, path, Format::Pdf))
}

/// A figure in `format` asked of a build without the `figures` feature.
#[cfg(not(feature = "figures"))]
fn not_built(lang: Lang, path: &Path, format: Format) -> Error {
    let reason = words!(lang, "figures-not-built", format = format.extension().to_ascii_uppercase());
    FigureRefused::PngFailed { path: path.to_path_buf(), reason }.into()
}

/// The SVG parsed with the system's fonts, "sans-serif" being the first of
/// the usual sans fonts the system has.
#[cfg(feature = "figures")]
fn tree(lang: Lang, svg: &str, path: &Path) -> Result<resvg::usvg::Tree, Error> {
    let failed = |reason: String| Error::from(FigureRefused::PngFailed { path: path.to_path_buf(), reason });
    let mut options = resvg::usvg::Options::default();
    let fonts = options.fontdb_mut();
    fonts.load_system_fonts();
    // The figure asks for "sans-serif"; take the first of the usual sans fonts the system has.
    let families: Vec<String> =
        fonts.faces().flat_map(|face| face.families.iter().map(|(name, _)| name.clone())).collect();
    let sans = ["DejaVu Sans", "Liberation Sans", "Arial", "Helvetica", "Noto Sans", "FreeSans"]
        .into_iter()
        .find(|wanted| families.iter().any(|f| f == wanted))
        .map(str::to_string)
        .or_else(|| families.first().cloned())
        .ok_or_else(|| failed(words!(lang, "png-no-fonts")))?;
    fonts.set_sans_serif_family(sans);
    resvg::usvg::Tree::from_str(svg, &options).map_err(|e| failed(e.to_string()))
}
