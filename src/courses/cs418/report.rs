//! A CS 418 run in words: a case read with its textures, the features it
//! uses, where the course's floats and exact arithmetic disagree and why,
//! and our image against a reference PNG.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::{
    Comparison, Cs418Problem, Image, Primitive, RastFile, Reason, TextureProblem, compare_images, differences,
};
use crate::door::{Folder, Identity};
use crate::error::Error;
use crate::words::Lang;

/// Whether a case's texture files are read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Textures {
    /// Read from beside the case: the image needs them.
    Read,
    /// Not read (each stands in as one transparent texel): what is drawn
    /// where does not depend on them.
    Ignored,
}

/// Reads the case at `path`, its textures from beside it where `textures`
/// says so; errors name the file and the line.
pub fn load(path: &Path, textures: Textures) -> Result<LoadedCase, Error> {
    let text = crate::door::read_text(path)?;
    let folder = Folder::beside(path)?;
    // Each file decoded once, and held once, however many names lead to it (`x.png`, `./x.png`).
    let read: RefCell<Vec<(PathBuf, Identity, Arc<Image>)>> = RefCell::new(Vec::new());
    let held = std::cell::Cell::new(0u64);
    let texture = |name: &str| {
        if textures == Textures::Ignored {
            return Ok(Arc::new(Image { width: 1, height: 1, rgba: vec![0; 4] }));
        }
        let (bytes, identity) = folder.read(name).map_err(|error| match error {
            Error::Read { source, .. } if source.kind() == std::io::ErrorKind::NotFound => TextureProblem::Missing,
            other => TextureProblem::Unread(Box::new(other)),
        })?;
        if let Some((_, _, image)) = read.borrow().iter().find(|(_, known, _)| *known == identity) {
            return Ok(image.clone());
        }
        // What the textures hold together, this one's share known from its header.
        let info = crate::door::png_reader(&bytes).map_err(TextureProblem::Image)?;
        let together = held.get() + u64::from(info.info().width) * u64::from(info.info().height);
        if together > super::MAX_CASE_TEXTURE_PIXELS {
            return Err(TextureProblem::TooLarge { pixels: together });
        }
        held.set(together);
        let image = Arc::new(Image::from_png(&bytes).map_err(TextureProblem::Image)?);
        read.borrow_mut().push((folder.path_of(name), identity, Arc::clone(&image)));
        Ok(image)
    };
    let case = RastFile::parse(&text, &texture).map_err(|e| e.in_file(path))?;
    let textures = read.into_inner().into_iter().map(|(path, identity, _)| (path, identity)).collect();
    Ok(LoadedCase { case, textures })
}

/// A case read, with the texture files it read: a run writes onto none of them.
pub struct LoadedCase {
    /// The case.
    pub case: RastFile,
    /// Each texture file read, once, by the name that first led to it.
    pub textures: Vec<(PathBuf, Identity)>,
}

/// A reference image refused.
fn refused(png: &Path, problem: Cs418Problem) -> Error {
    crate::courses::CaseError { line: None, problem }.in_file(png)
}

/// Reads a reference image for `--compare`, through the same door as every
/// input: a regular file within [`crate::door::MAX_INPUT_BYTES`], its declared
/// size checked before decoding; its identity comes with it.
pub fn reference(png: &Path) -> Result<(Image, Option<Identity>), Error> {
    let bytes = crate::door::read_bytes(png, crate::door::Links::Follow)?;
    let image = Image::from_png(&bytes).map_err(|problem| refused(png, Cs418Problem::Reference(problem)))?;
    Ok((image, Identity::of(png)))
}

/// `--compare`: our image against a reference `image` read from `png`,
/// within `tolerance` per channel, in words; and whether they differ. An
/// image of another size is an error about the reference.
pub fn compare_text(
    lang: Lang,
    png: &Path,
    image: &Image,
    ours: &Image,
    tolerance: u8,
) -> Result<(String, bool), Error> {
    let mut text = String::new();
    let Some(difference) = compare_images(ours, image, tolerance) else {
        return Err(refused(
            png,
            Cs418Problem::ImageSize { size: (image.width, image.height), case: (ours.width, ours.height) },
        ));
    };
    let (path, tolerance_text, largest) =
        (crate::words::shown_path(png), tolerance.to_string(), difference.largest.to_string());
    if difference.pixels.is_empty() {
        let line = words!(lang, "cs418-compare-same", path = path, tolerance = tolerance_text, largest = largest);
        text.push_str(&format!("{line}\n"));
        return Ok((text, false));
    }
    let count = difference.pixels.len();
    let line = words!(
        lang,
        "cs418-compare-differs",
        path = path,
        count = count,
        tolerance = tolerance_text,
        largest = largest
    );
    text.push_str(&format!("{line}\n"));
    for (x, y, ours, theirs) in difference.pixels.iter().take(20) {
        let line = words!(
            lang,
            "cs418-compare-pixel",
            x = x.to_string(),
            y = y.to_string(),
            ours = format!("{ours:?}"),
            theirs = format!("{theirs:?}")
        );
        text.push_str(&format!("  {line}\n"));
    }
    if count > 20 {
        text.push_str(&format!("  {}\n", words!(lang, "cs418-compare-more", count = (count - 20).to_string())));
    }
    Ok((text, true))
}

/// The case's features in use, after a comma: `, depth, sRGB, fsaa 4`.
pub fn features_text(case: &RastFile) -> String {
    let f = case.features;
    let mut on: Vec<String> =
        [(f.depth, "depth"), (f.srgb, "sRGB"), (f.hyp, "hyp"), (f.cull, "cull"), (f.frustum, "frustum")]
            .into_iter()
            .filter(|(on, _)| *on)
            .map(|(_, name)| name.to_string())
            .collect();
    if f.fsaa > 1 {
        on.push(format!("fsaa {}", f.fsaa));
    }
    if on.is_empty() { String::new() } else { format!(", {}", on.join(", ")) }
}

/// The samples where the course's floats and exact arithmetic disagree, each with why.
pub fn disagreements_text(lang: Lang, course: &Comparison, exact: &Comparison) -> String {
    let cells = differences(course, exact);
    if cells.is_empty() {
        return words!(lang, "cs418-arith-alike") + "\n";
    }
    let mut text = words!(lang, "cs418-arith-disagree", count = cells.len()) + "\n";
    for cell in &cells {
        let place = if course.level > 1 {
            words!(
                lang,
                "cs418-place-sample",
                x = cell.x.to_string(),
                y = cell.y.to_string(),
                px = cell.pixel.0.to_string(),
                py = cell.pixel.1.to_string()
            )
        } else {
            words!(lang, "cs418-place-pixel", x = cell.x.to_string(), y = cell.y.to_string())
        };
        let why = match &cell.reason {
            Reason::SampleSpan { primitive, course, exact, course_covers } => {
                let span = |s: &Option<(String, String)>| match s {
                    Some((l, r)) => format!("[{l}, {r})"),
                    None => words!(lang, "cs418-no-span"),
                };
                let (inside, outside) = (words!(lang, "cs418-inside"), words!(lang, "cs418-outside"));
                let (course_side, exact_side) = if *course_covers { (inside, outside) } else { (outside, inside) };
                words!(
                    lang,
                    "cs418-why-span",
                    primitive = primitive.message(lang),
                    row = cell.y.to_string(),
                    course = span(course),
                    exact = span(exact),
                    x = cell.x.to_string(),
                    course_side = course_side,
                    exact_side = exact_side
                )
            }
            Reason::Depth { course, exact } => {
                let who = |p: &Option<Primitive>| {
                    p.as_ref().map_or_else(|| words!(lang, "cs418-nothing"), |p| p.message(lang))
                };
                words!(lang, "cs418-why-depth", course = who(course), exact = who(exact))
            }
        };
        text.push_str(&format!("  {place}: {why}\n"));
    }
    text
}
