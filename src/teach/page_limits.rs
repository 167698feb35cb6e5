//! What a page draws: the limits the browser playground and the recorded
//! page (`step --html`) hold a scene to, checked before any work, so that no
//! scene keeps a tab busy for more than a second or makes a page too large
//! to open; a scene past them is refused in one line that names the limit
//! and says what draws it instead. The command line's own limits (the
//! raster's side and cells, a polygon's vertices, a file's size) hold too.

use std::path::{Path, PathBuf};

use serde_json::Value;

use crate::error::Refusal;
use crate::scene::Scene;
use crate::words::{Lang, shown_path};

/// The largest raster the page shows cell by cell (each polygon's buffers,
/// every stop): 128 × 128. A larger scene is still drawn and its final
/// buffers shown.
pub const MAX_SHOWN_CELLS: u64 = 128 * 128;

/// The most polygons whose buffers the page shows one by one.
pub const MAX_SHOWN_POLYGONS: usize = 64;

/// The largest raster whose final buffers the page prints as text: 512 ×
/// 512 (a 1024 × 1024 raster's text kept a tab busy past a second). A larger
/// scene is drawn, and the page says why its buffers are not printed.
pub const MAX_PRINTED_CELLS: u64 = 512 * 512;

/// The longest scene text the page reads, typed or in its address: 1 MiB
/// (thousands of polygons; a longer one is for `zsim run`, and reading it
/// kept a tab busy for seconds). Refused in one line naming the limit.
pub const MAX_PAGE_SCENE_BYTES: usize = 1 << 20;

/// The largest raster the page draws at all: 2048 × 2048 (4,194,304
/// pixels); a larger one is for `zsim run`.
pub const MAX_PAGE_CELLS: u64 = 2048 * 2048;

/// The most polygons the page draws.
pub const MAX_PAGE_POLYGONS: usize = 20_000;

/// The most vertices of one polygon the page draws (a polygon of many
/// vertices can cross a scanline at each).
pub const MAX_PAGE_VERTICES: usize = 1_000;

/// A scene larger than a page draws.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum TooLarge {
    /// More pixels than [`MAX_PAGE_CELLS`].
    Cells {
        /// The scene file, where there is one.
        path: Option<PathBuf>,
        /// Its pixels.
        cells: u64,
    },
    /// More polygons than [`MAX_PAGE_POLYGONS`].
    Polygons {
        /// The scene file, where there is one.
        path: Option<PathBuf>,
        /// Its polygons.
        count: usize,
    },
    /// A polygon of more vertices than [`MAX_PAGE_VERTICES`].
    Vertices {
        /// The scene file, where there is one.
        path: Option<PathBuf>,
        /// The polygon, from 1.
        polygon: usize,
        /// Its vertices.
        count: usize,
    },
    /// More than the recorded page steps (a page without the playground):
    /// [`MAX_SHOWN_CELLS`] pixels, [`MAX_SHOWN_POLYGONS`] polygons.
    Recorded {
        /// The scene file.
        path: PathBuf,
        /// Its pixels.
        cells: u64,
        /// Its polygons.
        polygons: usize,
    },
}

impl Refusal for TooLarge {
    fn message(&self, lang: Lang) -> String {
        let (path, said) = match self {
            TooLarge::Cells { path, cells } => (
                path.as_deref(),
                words!(lang, "limit-page-cells", max = MAX_PAGE_CELLS.to_string(), cells = cells.to_string()),
            ),
            TooLarge::Polygons { path, count } => (
                path.as_deref(),
                words!(lang, "limit-page-polygons", max = MAX_PAGE_POLYGONS.to_string(), count = count.to_string()),
            ),
            TooLarge::Vertices { path, polygon, count } => (
                path.as_deref(),
                words!(
                    lang,
                    "limit-page-vertices",
                    max = MAX_PAGE_VERTICES.to_string(),
                    polygon = polygon.to_string(),
                    count = count.to_string()
                ),
            ),
            TooLarge::Recorded { path, cells, polygons } => (
                Some(path.as_path()),
                words!(
                    lang,
                    "limit-recorded-page",
                    cells = MAX_SHOWN_CELLS.to_string(),
                    polygons = MAX_SHOWN_POLYGONS.to_string(),
                    has_cells = cells.to_string(),
                    has_polygons = *polygons
                ),
            ),
        };
        match path {
            Some(path) => format!("{}: {said}", shown_path(path)),
            None => said,
        }
    }
}

/// The page's limits on a scene's text, read as plain JSON before the scene
/// is (whose validation is the work a limit spares): its raster, its
/// polygons, each polygon's vertices. Text that is not a scene's JSON passes,
/// for the scene's reader to say what is wrong with it.
pub fn check_text(text: &str, path: Option<&Path>) -> Result<(), TooLarge> {
    let Ok(Value::Object(scene)) = serde_json::from_str::<Value>(text) else { return Ok(()) };
    let side = |key: &str| scene.get(key).and_then(Value::as_u64).unwrap_or(32);
    let path = || path.map(Path::to_path_buf);
    let cells = side("width").saturating_mul(side("height"));
    if cells > MAX_PAGE_CELLS {
        return Err(TooLarge::Cells { path: path(), cells });
    }
    let Some(Value::Array(polygons)) = scene.get("polygons") else { return Ok(()) };
    if polygons.len() > MAX_PAGE_POLYGONS {
        return Err(TooLarge::Polygons { path: path(), count: polygons.len() });
    }
    for (index, polygon) in polygons.iter().enumerate() {
        if let Some(Value::Array(vertices)) = polygon.get("vertices")
            && vertices.len() > MAX_PAGE_VERTICES
        {
            return Err(TooLarge::Vertices { path: path(), polygon: index + 1, count: vertices.len() });
        }
    }
    Ok(())
}

/// The recorded page's limits (`step --html` without the playground): a
/// scene it steps pixel by pixel, at most [`MAX_SHOWN_CELLS`] pixels and
/// [`MAX_SHOWN_POLYGONS`] polygons, as the playground's stepper.
pub fn check_recorded(scene: &Scene, path: &Path) -> Result<(), TooLarge> {
    let cells = u64::from(scene.width) * u64::from(scene.height);
    if cells > MAX_SHOWN_CELLS || scene.polygons.len() > MAX_SHOWN_POLYGONS {
        return Err(TooLarge::Recorded { path: path.to_path_buf(), cells, polygons: scene.polygons.len() });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(width: u64, height: u64, polygons: usize, vertices: usize) -> String {
        let polygon = |n: usize| {
            let points: Vec<String> = (0..n)
                .map(|k| {
                    let angle = k as f64 / n as f64 * std::f64::consts::TAU;
                    format!("[{:.6}, {:.6}, 1]", 8.0 + 6.0 * angle.cos(), 8.0 + 6.0 * angle.sin())
                })
                .collect();
            format!(r#"{{"value": 1, "vertices": [{}]}}"#, points.join(", "))
        };
        let list: Vec<String> = (0..polygons).map(|k| polygon(if k == 0 { vertices } else { 3 })).collect();
        format!(r#"{{"width": {width}, "height": {height}, "polygons": [{}]}}"#, list.join(", "))
    }

    /// Each limit holds at its value and refuses one more, naming itself
    /// and what draws the scene instead; text that is not a scene passes, for
    /// the scene's reader to word.
    #[test]
    fn each_page_limit_holds_at_its_value_and_refuses_one_more() {
        assert_eq!(check_text(&scene(2048, 2048, 1, 3), None), Ok(()));
        let cells = check_text(&scene(2048, 2049, 1, 3), None).unwrap_err();
        assert_eq!(cells, TooLarge::Cells { path: None, cells: 2048 * 2049 });
        assert_eq!(
            cells.message(Lang::En),
            "the page draws rasters of up to 4194304 pixels; this one has 4196352: zsim run draws it"
        );
        assert_eq!(check_text(&scene(16, 16, MAX_PAGE_POLYGONS, 3), None), Ok(()));
        let polygons = check_text(&scene(16, 16, MAX_PAGE_POLYGONS + 1, 3), None).unwrap_err();
        assert_eq!(polygons, TooLarge::Polygons { path: None, count: 20_001 });
        assert_eq!(check_text(&scene(16, 16, 2, MAX_PAGE_VERTICES), None), Ok(()));
        let vertices = check_text(&scene(16, 16, 2, MAX_PAGE_VERTICES + 1), Some(Path::new("v.json"))).unwrap_err();
        assert_eq!(
            vertices.message(Lang::En),
            "v.json: the page draws polygons of up to 1000 vertices; polygon 1 has 1001: zsim run draws it"
        );
        assert!(vertices.message(Lang::Ru).contains("1001"), "{}", vertices.message(Lang::Ru));
        // The default raster is 32 × 32; what is not a scene's JSON is the reader's to word.
        assert_eq!(check_text(r#"{"polygons": []}"#, None), Ok(()));
        assert_eq!(check_text("{not json", None), Ok(()));
        assert_eq!(check_text(r#"{"width": "wide"}"#, None), Ok(()));
    }
}
