//! A real GPU implementation as a reference: the machine's OpenGL (Mesa's
//! llvmpipe, the standard software OpenGL, headless through EGL), loaded at
//! run time, so that zsim builds and runs without it and says so in one line
//! when it is absent.
//!
//! Triangles are drawn into a framebuffer object of the raster's size with
//! OpenGL's lower-left origin, which is zsim's y-up raster: pixel (x, y) is
//! zsim's pixel (x, y). A vertex at pixel units (x, y) is sent as
//! `2x/W − 1, 2y/H − 1` in `f32`, exact for the coordinates the tests use (a
//! power-of-two raster, vertices on a 1/256 grid, as llvmpipe's 8-bit subpixel
//! precision snaps them). Each triangle's colour is its number, so what is
//! read back is which triangle shows at each pixel, and its 24-bit depth.

use crate::words::Lang;

mod gl;
pub mod race;
mod vulkan;

pub use gl::{Gl, GlDrawing};
pub use vulkan::Vulkan;

/// What went wrong reaching the machine's OpenGL.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GpuError {
    /// No `libEGL.so.1`, or one without EGL 1.5.
    NoLibrary(String),
    /// No Vulkan device (no `libvulkan.so.1`, or no driver such as lavapipe).
    NoVulkan(String),
    /// This zsim was built without the cargo feature that API needs.
    NotBuilt(&'static str),
    /// A scene with per-pixel effects or antialiasing: the GPU is compared
    /// on the plain algorithm only.
    PlainOnly,
    /// EGL, OpenGL or Vulkan refused a step.
    Refused {
        /// The step.
        step: &'static str,
        /// What was said.
        reason: String,
    },
}

impl crate::error::Refusal for GpuError {
    fn message(&self, lang: Lang) -> String {
        GpuError::message(self, lang)
    }
}

impl GpuError {
    /// The message in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        match self {
            GpuError::NoLibrary(reason) => words!(lang, "gpu-no-library", reason = reason.as_str()),
            GpuError::NoVulkan(reason) => words!(lang, "gpu-no-vulkan", reason = reason.as_str()),
            GpuError::NotBuilt(feature) => words!(lang, "gpu-not-built", feature = *feature),
            GpuError::PlainOnly => words!(lang, "usage-compare-gpu-plain"),
            GpuError::Refused { step, reason } => words!(lang, "gpu-refused", step = *step, reason = reason.as_str()),
        }
    }
}

/// One triangle to draw: three vertices in pixel units `(x, y, z)` and the
/// number it is drawn with (1 … 2^24 − 1; 0 is the background).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GpuTriangle {
    /// The vertices, in pixel units; z in depth levels.
    pub vertices: [[f64; 3]; 3],
    /// Its number, read back where it shows.
    pub id: u32,
}

/// What the GPU drew.
#[derive(Debug, Clone, PartialEq)]
pub struct GpuPicture {
    /// Raster width.
    pub width: u32,
    /// Raster height.
    pub height: u32,
    /// The number of the triangle showing at each pixel, 0 where none does;
    /// row 0 (the bottom) first, as zsim counts rows.
    pub shown: Vec<u32>,
    /// The depth the GPU stored at each pixel, in depth levels
    /// (`window depth × depth_max`), row 0 first.
    pub depth: Vec<f64>,
}

impl GpuPicture {
    /// The number of the triangle showing at pixel (x, y), 0 for none.
    pub fn at(&self, x: u32, y: u32) -> u32 {
        self.shown[(y * self.width + x) as usize]
    }
}

/// One cell where the GPU shows another polygon than zsim.
#[derive(Debug, Clone, PartialEq)]
pub struct GpuDifference {
    /// The pixel.
    pub x: u32,
    /// The pixel's row.
    pub y: u32,
    /// The polygon (0-based) the GPU shows, if any.
    pub gpu: Option<usize>,
    /// The polygon zsim shows under the scene's own rules.
    pub book: Option<usize>,
    /// The polygon zsim shows under the API's preset.
    pub preset: Option<usize>,
    /// Why, in words: the edge a centre lies on and the rule that decides
    /// it, or the depths that decided it.
    pub why: String,
}

/// The scene drawn by the GPU beside zsim: every cell that differs.
#[derive(Debug, Clone, PartialEq)]
pub struct GpuComparison {
    /// The implementation, as it names itself.
    pub renderer: String,
    /// The preset of the API drawn with.
    pub preset: crate::rules::Preset,
    /// The cells that differ, bottom row first.
    pub differences: Vec<GpuDifference>,
    /// Polygons drawn as a fan of triangles though not convex (their
    /// picture on the GPU is not the polygon's).
    pub not_convex: Vec<usize>,
}

/// A GPU API `compare` draws with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GpuApi {
    /// OpenGL through EGL; compared with the `gl` preset.
    Gl,
    /// Vulkan (needs zsim built with its `vulkan` feature); compared with
    /// the `vulkan` preset.
    Vulkan,
}

/// A scene as the GPU draws it: each drawn polygon a fan of triangles
/// numbered as the polygon (from 1), moved by `margin` pixels on both axes.
pub struct Triangles {
    /// The triangles, in scene order.
    pub triangles: Vec<GpuTriangle>,
    /// How far the raster is moved into the GPU's larger one: 256 pixels when
    /// every vertex lies within 256 pixels of the raster, so that none is
    /// clipped by the view volume (with [`Margin::AsNeeded`], only when one
    /// lies off it); 0 otherwise.
    pub margin: u32,
    /// Polygons drawn as a fan though not convex.
    pub not_convex: Vec<usize>,
}

/// The scene's drawn polygons as triangles for the GPU (see [`Triangles`]),
/// moved into a larger framebuffer when every vertex lies within 256 pixels
/// of the raster, as the comparisons draw them.
pub fn triangles(scene: &crate::scene::Scene) -> Triangles {
    triangles_within(scene, Margin::Guard)
}

/// Whether the GPU's framebuffer is larger than the raster.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Margin {
    /// 256 pixels on every side when every vertex lies within them (so that
    /// vertices just off the raster are not clipped), as the comparisons draw.
    Guard,
    /// None when every vertex lies on the raster, where nothing is clipped;
    /// else as `Guard`. The speed race draws so: a larger framebuffer is more
    /// for the GPU to clear than zsim's buffers.
    AsNeeded,
}

/// The scene's drawn polygons as triangles for the GPU, its framebuffer's
/// margin chosen by `margin`.
pub fn triangles_within(scene: &crate::scene::Scene, margin: Margin) -> Triangles {
    use crate::numbers::to_f64;
    let (width, height) = (scene.width, scene.height);
    // A margin keeps vertices near the raster inside the GPU's view volume, unclipped.
    let within = |reach: f64| {
        let inside = |v: f64, side: u32| (-reach..=f64::from(side) + reach).contains(&v);
        scene
            .polygons
            .iter()
            .all(|p| p.vertices().iter().all(|v| inside(to_f64(&v[0]), width) && inside(to_f64(&v[1]), height)))
    };
    let margin = match margin {
        Margin::AsNeeded if within(0.0) => 0,
        _ if within(256.0) => 256,
        _ => 0,
    };
    let mut triangles = Vec::new();
    let mut not_convex = Vec::new();
    for (index, polygon) in scene.polygons.iter().enumerate() {
        if crate::simulate::setup::fate(scene, index) != crate::simulate::events::Fate::Drawn {
            continue;
        }
        let points: Vec<[f64; 3]> = polygon
            .vertices()
            .iter()
            .map(|v| [to_f64(&v[0]) + f64::from(margin), to_f64(&v[1]) + f64::from(margin), to_f64(&v[2])])
            .collect();
        if !convex(&points) {
            not_convex.push(index);
        }
        for i in 1..points.len() - 1 {
            triangles.push(GpuTriangle { vertices: [points[0], points[i], points[i + 1]], id: index as u32 + 1 });
        }
    }
    Triangles { triangles, margin, not_convex }
}

/// Draws `scene` with the machine's GPU through `api` and compares what
/// shows at every pixel with zsim under the scene's own rules and under the
/// API's preset. Only the plain algorithm is compared (no per-pixel effects,
/// no antialiasing).
pub fn compare(lang: Lang, scene: &crate::scene::Scene, api: GpuApi) -> Result<GpuComparison, crate::error::Error> {
    use crate::rules::{Preset, Rules};
    if scene.has_pixel_effects() || scene.effects.antialias.is_some() {
        return Err(GpuError::PlainOnly.into());
    }
    let preset = match api {
        GpuApi::Gl => Preset::Gl,
        GpuApi::Vulkan => Preset::Vulkan,
    };
    let shows = |rules: Rules| {
        // Each polygon writes its number, so the framebuffer says which polygon shows.
        let mut numbered = scene.clone();
        numbered.frame_bits = 32;
        numbered.background = 0;
        numbered.rules = rules;
        for (index, polygon) in numbered.polygons.iter_mut().enumerate() {
            polygon.value = index as u32 + 1;
        }
        let mut simulation = crate::simulate::simulation::Simulation::new(&numbered);
        simulation.finish(&mut crate::simulate::events::Unobserved);
        simulation.into_buffers()
    };
    let api_rules = Rules { store: scene.rules.store, ..Rules::preset(preset) };
    let (book, in_api) = (shows(scene.rules), shows(api_rules));
    let (width, height) = (scene.width, scene.height);
    let Triangles { triangles, margin, not_convex } = triangles(scene);
    let no_gpu = crate::error::Error::from;
    let (renderer, picture) = match api {
        GpuApi::Gl => {
            let gl = Gl::open().map_err(no_gpu)?;
            let depth = Some((scene.depth_test, scene.depth_max()));
            let picture = gl.draw((width + 2 * margin, height + 2 * margin), &triangles, depth).map_err(no_gpu)?;
            (gl.renderer().to_string(), picture)
        }
        GpuApi::Vulkan => vulkan_picture(scene, &triangles, margin).map_err(no_gpu)?,
    };
    let polygon = |id: u32| (id > 0).then(|| id as usize - 1);
    let mut differences = Vec::new();
    for y in 0..height {
        for x in 0..width {
            let gpu = polygon(picture.at(x + margin, y + margin));
            let (in_book, in_preset) = (polygon(book.frame(x, y)), polygon(in_api.frame(x, y)));
            if gpu == in_book && gpu == in_preset {
                continue;
            }
            let involved = [gpu, in_book, in_preset];
            let tie = involved
                .iter()
                .flatten()
                .find_map(|&i| crate::observe::tie::tie_text(lang, api_rules, &scene.polygons[i].vertices(), x, y));
            let why = tie.unwrap_or_else(|| {
                let exact = |i: Option<usize>| {
                    i.map_or_else(
                        || words!(lang, "gpu-background"),
                        |i| {
                            let depth = crate::raster::depth::depth_at_centre(scene.polygons[i].geometry(), x, y);
                            words!(
                                lang,
                                "gpu-exact-depth",
                                polygon = crate::observe::explain::polygon_name(lang, scene, i),
                                depth = crate::numbers::exact_and_decimal(lang, depth.value())
                            )
                        },
                    )
                };
                match picture.depth.get(((y + margin) * picture.width + x + margin) as usize) {
                    Some(stored) => {
                        words!(
                            lang,
                            "gpu-why-depth",
                            gpu = format!("{stored:.3}"),
                            shown = exact(gpu),
                            book = exact(in_book)
                        )
                    }
                    None => words!(lang, "gpu-why-depth-unread", shown = exact(gpu), book = exact(in_book)),
                }
            });
            differences.push(GpuDifference { x, y, gpu, book: in_book, preset: in_preset, why });
        }
    }
    Ok(GpuComparison { renderer, preset, differences, not_convex })
}

/// The scene's triangles drawn by Vulkan, as a picture of `width + 2·margin`
/// on each side (its depths are not read back).
fn vulkan_picture(
    scene: &crate::scene::Scene,
    triangles: &[GpuTriangle],
    margin: u32,
) -> Result<(String, GpuPicture), GpuError> {
    use crate::raster::depth::DepthTest;
    let vulkan = Vulkan::open()?;
    let side = scene.width.max(scene.height) + 2 * margin;
    let max = f64::from(scene.depth_max().max(1));
    // Vulkan's pipeline here tests `greater`; `less` is the same order on 1 − z.
    let depth = |z: f64| match scene.depth_test {
        DepthTest::Greater => Ok(z / max),
        DepthTest::Less => Ok(1.0 - z / max),
        other => Err(GpuError::Refused { step: "depth test", reason: other.name().to_string() }),
    };
    let mut drawn = Vec::with_capacity(triangles.len());
    for triangle in triangles {
        let [a, b, c] = triangle.vertices;
        let vertex = |[x, y, z]: [f64; 3]| depth(z).map(|z| [x, y, z]);
        drawn.push(([vertex(a)?, vertex(b)?, vertex(c)?], triangle.id));
    }
    let shown = vulkan.draw(side, &drawn, true)?;
    Ok((vulkan.renderer().to_string(), GpuPicture { width: side, height: side, shown, depth: Vec::new() }))
}

/// Whether a polygon's vertices (x, y) turn one way only.
fn convex(points: &[[f64; 3]]) -> bool {
    let n = points.len();
    let turns: Vec<f64> = (0..n)
        .map(|i| {
            let (a, b, c) = (points[i], points[(i + 1) % n], points[(i + 2) % n]);
            (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
        })
        .filter(|t| *t != 0.0)
        .collect();
    turns.iter().all(|t| *t > 0.0) || turns.iter().all(|t| *t < 0.0)
}

impl GpuComparison {
    /// The comparison in the reader's language, as `zsim run --compare-gpu`
    /// prints it.
    pub fn text(&self, lang: Lang, scene: &crate::scene::Scene, path: &str) -> String {
        let name = |i: Option<usize>| {
            i.map_or_else(|| words!(lang, "gpu-background"), |i| crate::observe::explain::polygon_name(lang, scene, i))
        };
        let preset = match self.preset {
            crate::rules::Preset::Vulkan => "vulkan",
            _ => "gl",
        };
        let mut text =
            words!(lang, "gpu-heading", path = path, renderer = self.renderer.as_str(), preset = preset) + "\n";
        for &index in &self.not_convex {
            text.push_str(&format!("  {}\n", words!(lang, "gpu-not-convex", polygon = name(Some(index)))));
        }
        if self.differences.is_empty() {
            text.push_str(&format!("{}\n", words!(lang, "gpu-same")));
            return text;
        }
        text.push_str(&format!("{}\n", words!(lang, "gpu-differ", count = self.differences.len())));
        for d in &self.differences {
            let line = words!(
                lang,
                "gpu-cell",
                x = d.x.to_string(),
                y = d.y.to_string(),
                gpu = name(d.gpu),
                book = name(d.book),
                covered = name(d.preset),
                preset = preset
            );
            text.push_str(&format!("  {line}\n      {}\n", d.why));
        }
        text
    }
}
