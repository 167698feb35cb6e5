//! One pixel's whole history, gathered in one call ([`history`]) and worded
//! in one ([`PixelHistory::text`]): the polygons' depth tests at its centre,
//! and what the scene or the reader adds (point-in-polygon tests, the segment
//! holding it, antialiasing, another arithmetic). `zsim explain` prints it.

use crate::words::Lang;
use std::path::Path;

use crate::effects::antialias::{self, PixelModeNote};
use crate::effects::arith::{self, Arith};
use crate::effects::variants::{self, ArcDifference, Segments};
use crate::error::Error;
use crate::numbers::{Exact, Q, exact_and_decimal, fraction};
use crate::observe::explain::{depth_text, entry_text, polygon_name};
use crate::observe::trace::{PixelHistoryEntry, PixelWatcher};
use crate::raster::depth::Stored;
use crate::raster::sink::PixelRect;
use crate::scene::{Antialias, Scene};
use crate::simulate::events::{Fate, Outcome};
use crate::simulate::simulation::Simulation;

/// A pixel asked for outside the raster.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PixelOutside {
    /// Its column, as asked (a page's address may ask past 2^32).
    pub x: u64,
    /// Its row, as asked.
    pub y: u64,
    /// The raster's width.
    pub width: u32,
    /// The raster's height.
    pub height: u32,
}

impl crate::error::Refusal for PixelOutside {
    fn message(&self, lang: Lang) -> String {
        let PixelOutside { x, y, width, height } = *self;
        words!(
            lang,
            "usage-pixel-outside",
            x = x.to_string(),
            y = y.to_string(),
            width = width.to_string(),
            height = height.to_string(),
            last_x = width.saturating_sub(1).to_string(),
            last_y = height.saturating_sub(1).to_string()
        )
    }
}

/// What to add to a pixel's history besides the depth tests.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Extras {
    /// Each drawn polygon's point-in-polygon tests at the centre.
    pub inside: bool,
    /// What this arithmetic leaves in the pixel (nothing for `exact`).
    pub arith: Arith,
    /// The segment holding the pixel and the polygons it visits.
    pub segments: Option<Segments>,
}

impl Default for Extras {
    fn default() -> Extras {
        Extras { inside: false, arith: Arith::Exact, segments: None }
    }
}

/// The two point-in-polygon tests of one drawn polygon at the centre.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InsideTests {
    /// Ray casting: inside or not.
    pub ray: bool,
    /// Arc length: inside or not, and why it may differ from the scanlines.
    pub arc: (bool, ArcDifference),
}

/// One polygon's part of the history.
#[derive(Debug, Clone)]
pub struct PolygonStep {
    /// Its depth test at the centre (or why there was none).
    pub entry: PixelHistoryEntry,
    /// Its point-in-polygon tests, when asked for and it is drawn.
    pub inside: Option<InsideTests>,
}

/// The segment holding the pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SegmentFacts {
    /// How the raster is cut.
    pub segments: Segments,
    /// Which segment, 0-based, of how many.
    pub number: usize,
    /// How many segments there are.
    pub count: usize,
    /// Its pixels.
    pub rect: PixelRect,
    /// The polygons it visits, by index.
    pub visited: Vec<usize>,
}

/// One sample of an antialiased pixel (depth at the samples): its position,
/// its final cells, and the polygons that covered it.
#[derive(Debug, Clone)]
pub struct SampleFacts {
    /// Its place in the pixel, `(i, j)`.
    pub within: (u32, u32),
    /// Its pixel in the supersampled raster.
    pub sample: (u32, u32),
    /// Its position in pixel units.
    pub at: (Q, Q),
    /// The framebuffer value it ends with.
    pub frame: u32,
    /// The depth it ends with.
    pub depth: Stored,
    /// The polygons whose spans covered it, with their depth tests.
    pub entries: Vec<PixelHistoryEntry>,
}

/// What antialiasing did at the pixel.
#[derive(Debug, Clone)]
pub struct AntialiasFacts {
    /// Samples per side.
    pub samples: u32,
    /// Depth at the samples: each sample's history; depth at the pixel:
    /// each polygon's covered samples and centre-depth test.
    pub detail: AntialiasDetail,
    /// The mean framebuffer value and depth after the last polygon.
    pub mean: Option<(Q, Exact)>,
}

/// The two ways antialiasing decides depth.
#[derive(Debug, Clone)]
pub enum AntialiasDetail {
    /// Each sample's history in the supersampled scene.
    Samples(Box<Scene>, Vec<SampleFacts>),
    /// Each polygon's covered samples and its test at the centre.
    Pixel(Vec<PixelModeNote>),
}

/// Everything zsim knows about one pixel, for [`PixelHistory::text`].
#[derive(Debug, Clone)]
pub struct PixelHistory {
    /// The pixel.
    pub pixel: (u32, u32),
    /// The segment holding it, when asked for.
    pub segment: Option<SegmentFacts>,
    /// Each polygon's part, in drawing order.
    pub steps: Vec<PolygonStep>,
    /// The framebuffer value and depth it ends with.
    pub last: (u32, Stored),
    /// What antialiasing did, when the scene asks for it.
    pub antialias: Option<AntialiasFacts>,
    /// Another arithmetic's framebuffer value and depth, when asked for.
    pub arith: Option<(Arith, u32, Stored)>,
}

/// The history of pixel `(x, y)` through the whole scene, with `extras`.
/// The pixel must lie on the raster.
pub fn history(scene: &Scene, (x, y): (u32, u32), extras: Extras) -> Result<PixelHistory, Error> {
    if x >= scene.width || y >= scene.height {
        let (x, y, width, height) = (u64::from(x), u64::from(y), scene.width, scene.height);
        return Err(PixelOutside { x, y, width, height }.into());
    }
    let mut watcher = PixelWatcher::new([(x, y)]);
    let mut simulation = Simulation::new(scene);
    simulation.finish(&mut watcher);
    let steps = watcher
        .history(x, y)
        .iter()
        .map(|entry| {
            let polygon = &scene.polygons[entry.index];
            let inside = (extras.inside && entry.fate == Fate::Drawn).then(|| InsideTests {
                ray: variants::ray_inside(polygon, x, y),
                arc: variants::arc_inside(polygon, x, y),
            });
            PolygonStep { entry: entry.clone(), inside }
        })
        .collect();
    let buffers = simulation.buffers();
    let last = (buffers.frame(x, y), buffers.depth(x, y));
    let segment = extras.segments.and_then(|segments| {
        let rects = segments.rects(scene.width, scene.height);
        let (number, rect) = rects
            .iter()
            .enumerate()
            .find(|(_, r)| (r.columns.0..=r.columns.1).contains(&x) && (r.rows.0..=r.rows.1).contains(&y))?;
        let visited = variants::visited_in(scene, *rect);
        Some(SegmentFacts { segments, number, count: rects.len(), rect: *rect, visited })
    });
    let antialias = scene.effects.antialias.map(|settings| antialias_facts(scene, settings, (x, y))).transpose()?;
    let arith = if extras.arith == Arith::Exact {
        None
    } else {
        arith::check_supported(scene, extras.arith)?;
        let (mode, _) = arith::run(scene, extras.arith)?;
        Some((extras.arith, mode.frame(x, y), mode.depth(x, y)))
    };
    Ok(PixelHistory { pixel: (x, y), segment, steps, last, antialias, arith })
}

/// What antialiasing does at (x, y): each sample's history (depth at the
/// samples) or each polygon's covered samples and centre-depth test (depth at
/// the pixel), and the mean.
fn antialias_facts(scene: &Scene, settings: Antialias, (x, y): (u32, u32)) -> Result<AntialiasFacts, Error> {
    let k = settings.samples;
    let (pictures, notes) = antialias::run_watching(scene, settings, Some((x, y)))?;
    let detail = if settings.depth_at_samples {
        let big = antialias::supersampled(scene, k)?;
        let samples: Vec<(u32, u32)> = (0..k).flat_map(|j| (0..k).map(move |i| (x * k + i, y * k + j))).collect();
        let mut watcher = PixelWatcher::new(samples.iter().copied());
        let mut simulation = Simulation::new(&big);
        simulation.finish(&mut watcher);
        let at = |v: u32| Q::new(2 * i128::from(v) + 1, 2 * i128::from(k));
        let samples = samples
            .iter()
            .map(|&(sx, sy)| SampleFacts {
                within: (sx - x * k, sy - y * k),
                sample: (sx, sy),
                at: (at(sx), at(sy)),
                frame: simulation.buffers().frame(sx, sy),
                depth: simulation.buffers().depth(sx, sy),
                entries: watcher.history(sx, sy).iter().filter(|e| e.pixel.is_some()).cloned().collect(),
            })
            .collect();
        AntialiasDetail::Samples(Box::new(big), samples)
    } else {
        AntialiasDetail::Pixel(notes)
    };
    let row = crate::raster::printed_row(scene.height, y);
    let mean = pictures.last().map(|last| (last.frame[row][x as usize], last.depth[row][x as usize].clone()));
    Ok(AntialiasFacts { samples: k, detail, mean })
}

/// Up to how many polygons `explain` tells every one; in a larger scene only
/// those that reach the pixel's scanline.
pub const LISTED_ALL: usize = 50;

impl PixelHistory {
    /// The history in the reader's language, one fact a line, as `zsim
    /// explain` prints it; `file` names the scene in the heading.
    pub fn text(&self, lang: Lang, scene: &Scene, file: &Path) -> String {
        let (x, y) = self.pixel;
        let centre = |v: u32| exact_and_decimal(lang, Q::new(2 * i128::from(v) + 1, 2));
        let mut text = words!(
            lang,
            "explain-heading",
            x = x,
            y = y,
            file = crate::words::shown_path(file),
            cx = centre(x),
            cy = centre(y),
            test = scene.depth_test.local_name(lang),
            rule = scene.depth_test.rule_text(lang)
        ) + "\n";
        if let Some(section) = scene.effects.section {
            let line = words!(
                lang,
                "explain-section",
                op = scene.depth_test.section_symbol(),
                section = depth_text(lang, scene, section)
            );
            text.push_str(&format!("{line}\n"));
        }
        if scene.rules.sample == crate::rules::Sample::Corner {
            text.push_str(&words!(lang, "explain-corner-sample", x = x, y = y));
            text.push('\n');
        }
        text.push_str(&words!(lang, "explain-start", frame = scene.background, depth = scene.clear_depth.text(lang)));
        text.push('\n');
        if let Some(segment) = &self.segment {
            text.push_str(&segment_text(lang, scene, segment));
        }
        // A large scene (a model of thousands of faces): only the polygons that
        // reach the pixel's scanline are told, the others counted.
        let large = scene.polygons.len() > LISTED_ALL;
        let (mut not_drawn, mut off_row) = (0usize, 0usize);
        for step in &self.steps {
            let entry = &step.entry;
            if large && entry.scanline.is_none() {
                if entry.fate == crate::simulate::events::Fate::Drawn {
                    off_row += 1;
                } else {
                    not_drawn += 1;
                }
                continue;
            }
            let line = words!(
                lang,
                "polygon-line",
                polygon = polygon_name(lang, scene, entry.index),
                text = entry_text(lang, scene, x, y, entry)
            );
            text.push_str(&line);
            text.push('\n');
            if let Some(inside) = &step.inside {
                text.push_str(&format!("  {}\n", inside_text(lang, inside)));
            }
        }
        if not_drawn + off_row > 0 {
            text.push_str(&words!(
                lang,
                "explain-others",
                count = not_drawn + off_row,
                skipped = not_drawn,
                off = off_row
            ));
            text.push('\n');
        }
        let (frame, depth) = &self.last;
        text.push_str(&words!(lang, "explain-final", frame = *frame, depth = depth.text(lang)));
        text.push('\n');
        if let Some(antialias) = &self.antialias {
            text.push_str(&antialias_text(lang, scene, antialias));
        }
        if let Some((mode, frame, depth)) = &self.arith {
            let same = (*frame, depth) == (self.last.0, &self.last.1);
            let line = words!(
                lang,
                "explain-arith",
                arith = mode.to_string(),
                frame = frame.to_string(),
                depth = depth.text(lang),
                verdict = if same { words!(lang, "explain-arith-same") } else { words!(lang, "explain-arith-differs") }
            );
            text.push_str(&format!("{line}\n"));
        }
        text
    }
}

/// The two point-in-polygon tests at the centre, in words.
fn inside_text(lang: Lang, tests: &InsideTests) -> String {
    let side =
        |inside: bool| if inside { words!(lang, "explain-inside-in") } else { words!(lang, "explain-inside-out") };
    let arc = match tests.arc {
        (_, ArcDifference::OnBoundary) => words!(lang, "explain-arc-boundary"),
        (inside, ArcDifference::Winding(w)) => {
            words!(lang, "explain-arc-winding", winding = w.to_string(), inside = side(inside))
        }
    };
    words!(lang, "explain-inside", ray = side(tests.ray), arc = arc)
}

/// The segment holding the pixel and the polygons it visits, in words.
fn segment_text(lang: Lang, scene: &Scene, segment: &SegmentFacts) -> String {
    let SegmentFacts { segments, number, count, rect, visited } = segment;
    let visited: Vec<String> = visited.iter().map(|&i| polygon_name(lang, scene, i)).collect();
    let visited = if visited.is_empty() { words!(lang, "explain-segment-none") } else { visited.join(", ") };
    let cells = u64::from(rect.columns.1 - rect.columns.0 + 1) * u64::from(rect.rows.1 - rect.rows.0 + 1);
    words!(
        lang,
        "explain-segment",
        number = (number + 1).to_string(),
        count = count.to_string(),
        segments = segments.to_string(),
        first = rect.columns.0.to_string(),
        last = rect.columns.1.to_string(),
        bottom = rect.rows.0.to_string(),
        top = rect.rows.1.to_string(),
        cells = cells.to_string(),
        visited = visited
    ) + "\n"
}

/// What antialiasing did at the pixel, in words.
fn antialias_text(lang: Lang, scene: &Scene, facts: &AntialiasFacts) -> String {
    let k = facts.samples;
    let mut text = words!(lang, "explain-antialias", k = k.to_string()) + "\n";
    match &facts.detail {
        AntialiasDetail::Samples(big, samples) => {
            for sample in samples {
                let line = words!(
                    lang,
                    "explain-sample",
                    i = sample.within.0.to_string(),
                    j = sample.within.1.to_string(),
                    x = exact_and_decimal(lang, sample.at.0),
                    y = exact_and_decimal(lang, sample.at.1),
                    frame = sample.frame.to_string(),
                    depth = sample.depth.text(lang)
                );
                text.push_str(&format!("{line}\n"));
                let (sx, sy) = sample.sample;
                for entry in &sample.entries {
                    let line = words!(
                        lang,
                        "polygon-line",
                        polygon = polygon_name(lang, scene, entry.index),
                        text = entry_text(lang, big, sx, sy, entry)
                    );
                    text.push_str(&format!("  {line}\n"));
                }
            }
        }
        AntialiasDetail::Pixel(notes) => {
            for note in notes {
                let samples: Vec<String> = note.samples.iter().map(|(i, j)| format!("({i}, {j})")).collect();
                let d = &note.decision;
                let result = match d.outcome {
                    Outcome::Written => words!(lang, "explain-pixel-mode-written", stored = d.stored.text(lang)),
                    _ => words!(lang, "explain-pixel-mode-not-written"),
                };
                let line = words!(
                    lang,
                    "explain-pixel-mode",
                    polygon = polygon_name(lang, scene, note.index),
                    samples = samples.join(" "),
                    depth = depth_text(lang, scene, d.compared.value()),
                    result = result
                );
                text.push_str(&format!("{line}\n"));
            }
        }
    }
    if let Some((frame, depth)) = &facts.mean {
        let line = words!(lang, "explain-mean", frame = fraction(*frame), depth = fraction(depth));
        text.push_str(&format!("{line}\n"));
    }
    text
}
