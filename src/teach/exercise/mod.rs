//! New exercises in the book's style: a small scene of planar polygons with
//! vertices on half pixels, repeatable from a seed, that contains the hard
//! cases a teacher asks for. Which cases a scene contains is found from the
//! trace of its run ([`find_cases`]), never assumed from how it was made:
//! the generator keeps drawing candidates until the trace shows every case
//! asked for.

pub mod files;

use crate::words::Lang;
use std::collections::BTreeSet;
use std::fmt;

use crate::error::Refusal;
use crate::numbers::{Q, fraction, short_in_files};
use crate::scene::random::SplitMix64;
use crate::scene::{Scene, max_for_bits};
use crate::simulate::events::{Observer, Outcome, PixelEvent, ScanlineEvent};
use crate::simulate::simulation::Simulation;

/// A case that students get wrong, which an exercise can be asked to contain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum HardCase {
    /// A vertex lies on a scanline (y = row + 1/2) that its polygon is scanned on.
    VertexOnScanline,
    /// A pixel centre lies exactly on an edge (a crossing at x = column + 1/2).
    CentreOnEdge,
    /// A covered centre's depth is exactly k + 1/2, where rounding decides.
    HalfDepth,
    /// A written depth lies outside 0 … 2^depth_bits − 1 and is saturated.
    Saturation,
    /// A covered centre fails the depth test: hidden behind an earlier polygon.
    Hidden,
    /// Two polygons intersect: each is in front of the other somewhere.
    Intersecting,
    /// A scanline of a polygon has two spans or more (a concave polygon).
    Concave,
}

impl HardCase {
    /// Every case, in the order they are reported.
    pub const ALL: [HardCase; 7] = [
        HardCase::VertexOnScanline,
        HardCase::CentreOnEdge,
        HardCase::HalfDepth,
        HardCase::Saturation,
        HardCase::Hidden,
        HardCase::Intersecting,
        HardCase::Concave,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            HardCase::VertexOnScanline => "vertex-on-scanline",
            HardCase::CentreOnEdge => "centre-on-edge",
            HardCase::HalfDepth => "half-depth",
            HardCase::Saturation => "saturation",
            HardCase::Hidden => "hidden",
            HardCase::Intersecting => "intersecting",
            HardCase::Concave => "concave",
        }
    }

    /// Reads a comma-separated list of case names.
    pub fn parse_list(text: &str) -> Result<Vec<HardCase>, Unfit> {
        let mut cases = Vec::new();
        for name in text.split(',').map(str::trim).filter(|n| !n.is_empty()) {
            let case = HardCase::ALL.into_iter().find(|c| c.name() == name).ok_or_else(|| {
                let names = HardCase::ALL.iter().map(|c| c.name().to_string()).collect();
                Unfit::NotAHardCase { name: name.to_string(), names }
            })?;
            if !cases.contains(&case) {
                cases.push(case);
            }
        }
        cases.sort();
        Ok(cases)
    }
}

impl fmt::Display for HardCase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Where a scene contains a case: the first place its run meets it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Found {
    /// The case.
    pub case: HardCase,
    /// Where, in words: `pixel (20, 15), polygon 2: z = 21/2 rounds up to 11`.
    pub place: String,
}

/// The cases the run of `scene` meets, each at the first place it meets it,
/// in [`HardCase::ALL`] order.
pub fn find_cases(lang: Lang, scene: &Scene) -> Vec<Found> {
    census(lang, scene).found
}

/// Every case a scene's run meets, counted: where each is met first, in how
/// many places a teacher would count it (the polygons it arises in, or for
/// `intersecting` the pairs of polygons), and which cells of the raster it
/// touches, so that a class's wrong cells can be told by the kind of case
/// behind them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Census {
    /// The first place of each case met, in [`HardCase::ALL`] order.
    pub found: Vec<Found>,
    /// Per case of [`HardCase::ALL`]: the polygons it arises in (pairs, for
    /// `intersecting`).
    pub times: [usize; 7],
    /// Per case of [`HardCase::ALL`]: the cells it touches, each
    /// `y · width + x` (row 0 at the bottom), ascending.
    pub cells: [Vec<u32>; 7],
}

impl Census {
    /// How many times `case` arises (see [`Census::times`]).
    pub fn count(&self, case: HardCase) -> usize {
        self.times[case as usize]
    }

    /// Whether `case` touches the cell (x, y).
    pub fn touches(&self, case: HardCase, width: u32, x: u32, y: u32) -> bool {
        self.cells[case as usize].binary_search(&(y * width + x)).is_ok()
    }
}

/// The [`Census`] of `scene`'s run, its places worded in `lang`.
pub fn census(lang: Lang, scene: &Scene) -> Census {
    let mut finder = CaseFinder::new(lang, scene);
    Simulation::new(scene).finish(&mut finder);
    let mut found = finder.found;
    found.sort_by_key(|f| f.case);
    // A pair of polygons intersects where each won a cell from the other's ones: its cells both ways.
    let mut intersecting = BTreeSet::new();
    for pair in finder.won.intersection(&finder.lost) {
        intersecting.insert(*pair);
        finder.cells[HardCase::Intersecting as usize].extend(finder.pair_cells.get(pair).into_iter().flatten());
    }
    let mut times = [0; 7];
    for case in HardCase::ALL {
        times[case as usize] = match case {
            HardCase::Intersecting => intersecting.len(),
            _ => finder.polygons[case as usize].len(),
        };
    }
    let cells = finder.cells.map(|set| set.into_iter().collect());
    Census { found, times, cells }
}

/// Watches a run for the hard cases.
struct CaseFinder {
    lang: Lang,
    width: u32,
    depth_max: u32,
    quantized: bool,
    /// Which polygon wrote each cell last, row-major from the bottom.
    owner: Vec<Option<usize>>,
    /// Pairs `(earlier, later)` where the later polygon won a cell from the earlier, and where it lost one.
    won: BTreeSet<(usize, usize)>,
    lost: BTreeSet<(usize, usize)>,
    /// The cells each such pair won or lost.
    pair_cells: std::collections::BTreeMap<(usize, usize), Vec<u32>>,
    /// Per case: the polygons it arose in, and the cells it touched.
    polygons: [BTreeSet<usize>; 7],
    cells: [BTreeSet<u32>; 7],
    /// The rows of the polygon being drawn whose scanline meets a vertex, or has two spans or more.
    vertex_rows: BTreeSet<(usize, u32)>,
    concave_rows: BTreeSet<(usize, u32)>,
    found: Vec<Found>,
}

impl CaseFinder {
    fn new(lang: Lang, scene: &Scene) -> CaseFinder {
        CaseFinder {
            lang,
            width: scene.width,
            depth_max: scene.depth_max(),
            quantized: scene.clear_depth.level().is_some(),
            owner: vec![None; scene.width as usize * scene.height as usize],
            won: BTreeSet::new(),
            lost: BTreeSet::new(),
            pair_cells: std::collections::BTreeMap::new(),
            polygons: Default::default(),
            cells: Default::default(),
            vertex_rows: BTreeSet::new(),
            concave_rows: BTreeSet::new(),
            found: Vec::new(),
        }
    }

    /// `case` arises in polygon `index` (at the cell (x, y), where it touches one).
    fn note(&mut self, case: HardCase, index: usize, cell: Option<(u32, u32)>, place: impl FnOnce() -> String) {
        self.polygons[case as usize].insert(index);
        if let Some((x, y)) = cell {
            self.cells[case as usize].insert(y * self.width + x);
        }
        if !self.found.iter().any(|f| f.case == case) {
            self.found.push(Found { case, place: place() });
        }
    }
}

impl Observer for CaseFinder {
    fn scanline(&mut self, event: &ScanlineEvent<'_>) {
        let lang = self.lang;
        let (index, row) = (event.index, event.row);
        let scan_y = Q::new(2 * i128::from(row) + 1, 2);
        if let Some((k, v)) = event.polygon.vertices().iter().enumerate().find(|(_, v)| v[1] == scan_y) {
            self.vertex_rows.insert((index, row));
            self.note(HardCase::VertexOnScanline, index, None, || {
                words!(
                    lang,
                    "place-vertex-on-scanline",
                    polygon = (index + 1).to_string(),
                    vertex = (k + 1).to_string(),
                    x = short_in_files(&v[0]),
                    y = short_in_files(&v[1]),
                    row = row.to_string()
                )
            });
        }
        for crossing in event.crossings {
            // A centre x + 1/2 on the crossing: 2x an odd integer (x·2 fits: exercises are small).
            let doubled = crossing.x().to_big() * num_bigint::BigInt::from(2);
            let odd = doubled.is_integer() && doubled.to_integer().bit(0);
            if let (true, Some(doubled)) = (odd, num_traits::ToPrimitive::to_i128(&doubled.to_integer())) {
                let column = (doubled - 1) / 2;
                if (0..i128::from(self.width)).contains(&column) {
                    self.note(HardCase::CentreOnEdge, index, Some((column as u32, row)), || {
                        words!(
                            lang,
                            "place-centre-on-edge",
                            x = column.to_string(),
                            y = row.to_string(),
                            polygon = (index + 1).to_string()
                        )
                    });
                }
            }
        }
        if event.spans.len() >= 2 {
            self.concave_rows.insert((index, row));
            self.note(HardCase::Concave, index, None, || {
                words!(
                    lang,
                    "place-spans",
                    polygon = (index + 1).to_string(),
                    row = row.to_string(),
                    spans = event.spans.len().to_string()
                )
            });
        }
    }

    fn pixel(&mut self, event: &PixelEvent) {
        let lang = self.lang;
        let (index, x, y) = (event.index, event.x, event.y);
        for (case, rows) in [(HardCase::VertexOnScanline, &self.vertex_rows), (HardCase::Concave, &self.concave_rows)] {
            if rows.contains(&(index, y)) {
                self.cells[case as usize].insert(y * self.width + x);
            }
        }
        let z = event.compared.value();
        let half = z.to_big() * num_bigint::BigInt::from(2);
        if self.quantized && half.is_integer() && half.to_integer().bit(0) {
            self.note(HardCase::HalfDepth, index, Some((x, y)), || {
                words!(
                    lang,
                    "place-half-depth",
                    x = x.to_string(),
                    y = y.to_string(),
                    polygon = (index + 1).to_string(),
                    z = fraction(&z),
                    stored = event.compared.rounded().to_string()
                )
            });
        }
        let rounded = event.compared.rounded();
        let range = num_bigint::BigInt::from(0)..=num_bigint::BigInt::from(self.depth_max);
        if self.quantized && event.outcome == Outcome::Written && !range.contains(&rounded) {
            self.note(HardCase::Saturation, index, Some((x, y)), || {
                words!(
                    lang,
                    "place-saturation",
                    x = x.to_string(),
                    y = y.to_string(),
                    polygon = (index + 1).to_string(),
                    z = fraction(&z),
                    rounded = rounded.to_string(),
                    stored = event.stored_after.text(lang)
                )
            });
        }
        let cell = y as usize * self.width as usize + x as usize;
        let owner = self.owner[cell];
        // The pair (earlier, this) that this cell was won or lost against.
        let mut pair = None;
        match event.outcome {
            Outcome::Written => {
                if let Some(earlier) = owner.filter(|o| *o != index) {
                    self.won.insert((earlier, index));
                    pair = Some((earlier, index));
                }
                self.owner[cell] = Some(index);
            }
            Outcome::Hidden => {
                self.note(HardCase::Hidden, index, Some((x, y)), || {
                    words!(
                        lang,
                        "place-hidden",
                        x = x.to_string(),
                        y = y.to_string(),
                        polygon = (index + 1).to_string(),
                        z = fraction(&z),
                        stored = event.stored_before.text(lang)
                    )
                });
                if let Some(earlier) = owner.filter(|o| *o != index) {
                    self.lost.insert((earlier, index));
                    pair = Some((earlier, index));
                }
            }
            Outcome::BeyondSection | Outcome::OutsideDepthRange => {}
        }
        if let Some(pair) = pair {
            self.pair_cells.entry(pair).or_default().push(y * self.width + x);
        }
        // Only the pair this event touched can have become both won and lost.
        if let Some((a, b)) = pair.filter(|p| self.won.contains(p) && self.lost.contains(p)) {
            self.note(HardCase::Intersecting, b, None, || {
                words!(lang, "place-intersecting", first = (a + 1).to_string(), second = (b + 1).to_string())
            });
        }
    }
}

/// What `zsim exercise` is asked for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Spec {
    /// Seed of the generator: the same seed gives the same exercise.
    pub seed: u64,
    /// Raster width.
    pub width: u32,
    /// Raster height.
    pub height: u32,
    /// How many polygons.
    pub polygons: usize,
    /// Framebuffer bits.
    pub frame_bits: u32,
    /// z-buffer bits.
    pub depth_bits: u32,
    /// The cases the exercise must contain.
    pub hard: Vec<HardCase>,
    /// How the polygons may look.
    pub style: Style,
    /// With [`Style::Book`]: the fewest pixel centres each polygon covers.
    pub min_pixels: u32,
}

/// How an exercise's polygons may look.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// Like the book's example: every polygon covers at least the asked
    /// number of centres, and every depth lies within the z-buffer's range
    /// (unless saturation is asked for, which needs depths beyond it).
    Book,
    /// Any candidate that contains the asked cases: slivers and depths below
    /// zero included.
    Free,
}

/// How many candidates are drawn before giving up.
pub const TRIES: usize = 20_000;

/// A made exercise: its scene file, the scene, and the cases found in its trace.
#[derive(Debug, Clone)]
pub struct Exercise {
    /// The scene as zsim scene JSON (pretty, one vertex a line).
    pub json: String,
    /// The scene read back from that JSON.
    pub scene: Scene,
    /// Every case its run meets (at least those asked for).
    pub found: Vec<Found>,
    /// Which candidate (from 1) was kept.
    pub tries: usize,
}

/// An exercise that cannot be made as asked.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Unfit {
    /// A case name that is not a hard case.
    NotAHardCase {
        /// The name given.
        name: String,
        /// The names of the hard cases.
        names: Vec<String>,
    },
    /// A raster side outside 4 … 64.
    Size {
        /// The width given.
        width: u32,
        /// The height given.
        height: u32,
    },
    /// A polygon count outside 1 … 8.
    Polygons {
        /// The count given.
        count: usize,
    },
    /// Buffers too deep for work by hand.
    Bits,
    /// `hidden` or `intersecting` asked of one polygon.
    NeedsTwoPolygons,
    /// No candidate scene showed every case asked for.
    NotFound {
        /// Polygons asked for.
        polygons: usize,
        /// The raster's width.
        width: u32,
        /// The raster's height.
        height: u32,
        /// The cases asked for.
        cases: Vec<String>,
        /// Candidates tried.
        tries: usize,
    },
}

impl Refusal for Unfit {
    fn message(&self, lang: Lang) -> String {
        match self {
            Unfit::NotAHardCase { name, names } => {
                words!(lang, "usage-not-a-hard-case", name = name.as_str(), names = names.join(", "))
            }
            Unfit::Size { width, height } => {
                words!(lang, "usage-exercise-size", width = width.to_string(), height = height.to_string())
            }
            Unfit::Polygons { count } => words!(lang, "usage-exercise-polygons", count = count.to_string()),
            Unfit::Bits => words!(lang, "usage-exercise-bits"),
            Unfit::NeedsTwoPolygons => words!(lang, "usage-exercise-two-polygons"),
            Unfit::NotFound { polygons, width, height, cases, tries } => words!(
                lang,
                "usage-exercise-not-found",
                polygons = polygons.to_string(),
                width = width.to_string(),
                height = height.to_string(),
                cases = cases.join(", "),
                tries = tries.to_string()
            ),
        }
    }
}

/// Makes an exercise: candidates drawn from the seed's sequence, the first
/// whose trace shows every asked case kept.
pub fn make(lang: Lang, spec: &Spec) -> Result<Exercise, Unfit> {
    let asked = |census: &Census| spec.hard.iter().all(|case| census.count(*case) > 0);
    search(lang, spec, |_, census| asked(census).then_some(())).map(|(exercise, ())| exercise)
}

/// Draws candidates from the seed's sequence as [`make`] does and keeps the
/// first that `accept` takes (given its scene and its [`Census`]), with what
/// `accept` made of it.
pub fn search<T>(
    lang: Lang,
    spec: &Spec,
    mut accept: impl FnMut(&Scene, &Census) -> Option<T>,
) -> Result<(Exercise, T), Unfit> {
    if spec.width < 4 || spec.height < 4 || spec.width > 64 || spec.height > 64 {
        return Err(Unfit::Size { width: spec.width, height: spec.height });
    }
    if !(1..=8).contains(&spec.polygons) {
        return Err(Unfit::Polygons { count: spec.polygons });
    }
    if !(1..=8).contains(&spec.frame_bits) || !(1..=16).contains(&spec.depth_bits) {
        return Err(Unfit::Bits);
    }
    let two = spec.hard.iter().any(|c| matches!(c, HardCase::Hidden | HardCase::Intersecting));
    if two && spec.polygons < 2 {
        return Err(Unfit::NeedsTwoPolygons);
    }
    let mut rng = SplitMix64::new(spec.seed);
    for tries in 1..=TRIES {
        let json = candidate(spec, &mut rng);
        let Ok(scene) = Scene::from_json(&json, std::path::Path::new("exercise.json")) else { continue };
        if spec.style == Style::Book && !book_like(&scene, spec) {
            continue;
        }
        let census = census(lang, &scene);
        if let Some(made) = accept(&scene, &census) {
            return Ok((Exercise { json, scene, found: census.found, tries }, made));
        }
    }
    Err(Unfit::NotFound {
        polygons: spec.polygons,
        width: spec.width,
        height: spec.height,
        cases: spec.hard.iter().map(|c| c.name().to_string()).collect(),
        tries: TRIES,
    })
}

/// Whether a candidate looks like the book's: each polygon covers at least
/// `min_pixels` centres, and (unless saturation is asked for) every vertex's
/// depth, so every depth on the polygon, lies within the z-buffer's range.
fn book_like(scene: &Scene, spec: &Spec) -> bool {
    if !spec.hard.contains(&HardCase::Saturation) {
        let (low, high) = (Q::from_integer(0), Q::from_integer(i128::from(scene.depth_max())));
        let inside = |z: &crate::numbers::Exact| z.word().is_some_and(|z| (low..=high).contains(&z));
        if !scene.polygons.iter().all(|p| p.vertices().iter().all(|v| inside(&v[2]))) {
            return false;
        }
    }
    let mut covered = Coverage(vec![0; scene.polygons.len()]);
    Simulation::new(scene).finish(&mut covered);
    covered.0.iter().all(|&count| count >= spec.min_pixels)
}

/// How many centres each polygon covers.
struct Coverage(Vec<u32>);

impl Observer for Coverage {
    const OBSERVES_SCANLINES: bool = false;
    const OBSERVES_POLYGONS: bool = false;

    fn pixel(&mut self, event: &PixelEvent) {
        self.0[event.index] += 1;
    }
}

/// One candidate scene: polygons with vertices on half pixels over the
/// middle of the raster (so that they overlap), each on a plane with
/// quarter-level slopes (so that depths of k + 1/2 occur), some reaching
/// past the z-buffer's range, a concave one when asked for.
fn candidate(spec: &Spec, rng: &mut SplitMix64) -> String {
    let (w, h) = (i64::from(spec.width), i64::from(spec.height));
    let depth_max = i64::from(max_for_bits(spec.depth_bits));
    let value_max = i64::from(max_for_bits(spec.frame_bits));
    let concave_at = if spec.hard.contains(&HardCase::Concave) { rng.range(0, spec.polygons as i64 - 1) } else { -1 };
    // Slopes in quarter levels per pixel, scaled so a polygon spans a good part of the range.
    let unit = (depth_max / i64::from(spec.width.max(spec.height))).max(1);
    let mut polygons = Vec::new();
    for index in 0..spec.polygons {
        // Half-pixel vertices in the raster's middle, with a margin of a pixel.
        let half = |rng: &mut SplitMix64, size: i64| Q::new(i128::from(rng.range(2, 2 * size - 2)), 2);
        let points: Vec<(Q, Q)> = if index as i64 == concave_at {
            // An arrowhead pointing down: top left, the tip, top right, and the notch
            // between the two top corners, so the rows above the notch have two spans.
            let third = |rng: &mut SplitMix64, size: i64, k: i64| {
                Q::new(i128::from(rng.range(2 * size * k / 3 + 1, 2 * size * (k + 1) / 3 - 1)), 2)
            };
            let (x0, x1, y0, y1) = (third(rng, w, 0), third(rng, w, 2), third(rng, h, 0), third(rng, h, 2));
            let middle = |a: Q, b: Q| (a + b).round() / Q::from_integer(2);
            let (xm, yn) = (middle(x0, x1), middle(y0, y1));
            vec![(x0, y1), (xm, y0), (x1, y1), (xm, yn)]
        } else {
            (0..3).map(|_| (half(rng, w), half(rng, h))).collect()
        };
        let slope = |rng: &mut SplitMix64| Q::new(i128::from(rng.range(-4, 4) * unit), 4);
        let (p, q) = (slope(rng), slope(rng));
        // Through the first vertex at a level that may sit at either end of the range.
        let z0 = Q::new(i128::from(rng.range(-unit, 2 * (depth_max + unit))), 2);
        let vertices: Vec<String> = points
            .iter()
            .map(|&(x, y)| {
                let z = z0 + p * (x - points[0].0) + q * (y - points[0].1);
                format!("[{}, {}, {}]", number(x), number(y), number(z))
            })
            .collect();
        let value = 1 + (index as i64 % value_max);
        let name = (b'A' + index as u8) as char;
        polygons.push(format!(
            "    {{\"name\": \"{name}\", \"value\": {value}, \"vertices\": [\n      {}\n    ]}}",
            vertices.join(",\n      ")
        ));
    }
    format!(
        "{{\n  \"width\": {}, \"height\": {},\n  \"frame_bits\": {}, \"depth_bits\": {},\n  \"polygons\": [\n{}\n  ]\n}}\n",
        spec.width,
        spec.height,
        spec.frame_bits,
        spec.depth_bits,
        polygons.join(",\n")
    )
}

/// A number for the scene file: an integer or a decimal when exact, else a fraction in a string.
fn number(value: Q) -> String {
    let text = short_in_files(value);
    if text.contains('/') { format!("\"{text}\"") } else { text }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn case_lists_parse_and_refuse_unknown_names() {
        assert_eq!(
            HardCase::parse_list("hidden, half-depth,hidden").unwrap(),
            vec![HardCase::HalfDepth, HardCase::Hidden]
        );
        assert!(
            HardCase::parse_list("tricky")
                .unwrap_err()
                .message(Lang::En)
                .starts_with("\"tricky\" is not a hard case: vertex-on-scanline")
        );
    }

    #[test]
    fn the_books_example_has_its_known_cases() {
        let scene =
            Scene::load(std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/rogers.json"))).unwrap();
        let cases: Vec<HardCase> = find_cases(Lang::En, &scene).into_iter().map(|f| f.case).collect();
        // The triangle pierces the rectangle: hidden and intersecting; its depths step by
        // 3/4 and reach k + 1/2 (pixel (22, 14): z = 19/2).
        assert!(cases.contains(&HardCase::Hidden) && cases.contains(&HardCase::Intersecting), "{cases:?}");
        assert!(cases.contains(&HardCase::HalfDepth), "{cases:?}");
        assert!(!cases.contains(&HardCase::Concave), "{cases:?}");
    }
}
