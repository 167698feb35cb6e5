//! The per-pixel stages between the exact depth and the buffers: the plain
//! depth test and store, or every effect a scene can ask for (depth range,
//! w-buffer, cross-section, opacity), chosen once per run; and the stages in
//! words, for reports.

use crate::numbers::{Q, fraction};
use crate::raster::depth::{Depth, DepthTest, Stored};
use crate::rules::{Compare, DepthStore, RowRule};
use crate::scene::{Polygon, Scene};
use crate::simulate::events::{Observer, Outcome, PixelEvent};
use crate::simulate::setup::Stats;

/// What the per-pixel stages make of one covered centre.
#[derive(Debug, Clone)]
pub struct Decision {
    /// What happened.
    pub outcome: Outcome,
    /// The depth that was compared (and stored when written).
    pub compared: Depth,
    /// The z-buffer after.
    pub stored: Stored,
    /// The framebuffer after.
    pub frame: u32,
}

/// One covered pixel as every sink takes it, the one bookkeeping of the
/// reference's sink and the plain loop's: the stages' decision (`decide`)
/// on the cells found (`before`: the z-buffer's, the framebuffer's), the
/// pixel counted as tested and, when written, as written and its cells
/// stored (`store`), then the observer told. Pixel `at` of polygon `index`,
/// at exact depth `depth`.
#[inline(always)]
pub(super) fn take_pixel<O: Observer>(
    (index, at): (usize, (u32, u32)),
    depth: Depth,
    before: (Stored, u32),
    decide: impl FnOnce(Depth, Stored, u32) -> Decision,
    store: impl FnOnce(&Decision),
    stats: &mut Stats,
    observer: &mut O,
) {
    let decision = decide(depth.clone(), before.0.clone(), before.1);
    stats.tested += 1;
    if decision.outcome == Outcome::Written {
        stats.written += 1;
        store(&decision);
    }
    observer.pixel(&decision.event(index, at, depth, before));
}

impl Decision {
    /// What an observer is told of this decision: pixel (`x`, `y`) of
    /// polygon `index` at exact depth `depth`, over the cells it found.
    pub fn event(self, index: usize, (x, y): (u32, u32), depth: Depth, (stored, frame): (Stored, u32)) -> PixelEvent {
        PixelEvent {
            index,
            x,
            y,
            depth,
            compared: self.compared,
            stored_before: stored,
            frame_before: frame,
            outcome: self.outcome,
            stored_after: self.stored,
            frame_after: self.frame,
        }
    }
}

/// The per-pixel stages between the exact depth and the buffers, chosen once
/// per run from the scene, so a scene without effects runs a loop with no
/// effect code in it.
pub trait PixelStages {
    /// Decides one covered centre of `polygon` with exact depth `depth`.
    fn decide(&self, polygon: &Polygon, depth: Depth, stored: Stored, frame: u32) -> Decision;

    /// For the plain stages on a quantized z-buffer: the test and the largest
    /// level, so the loop can work on the buffers' cells directly.
    fn plain_levels(&self) -> Option<(DepthTest, u32)> {
        None
    }
}

/// The plain algorithm: the depth test and the store, nothing else.
#[derive(Debug, Clone, Copy)]
pub struct Plain {
    test: DepthTest,
    store: DepthStore,
    depth_max: u32,
}

impl Plain {
    /// The plain stages of a scene.
    pub fn new(scene: &Scene) -> Plain {
        Plain { test: scene.depth_test, store: scene.rules.store, depth_max: scene.depth_max() }
    }
}

impl Plain {
    /// The plain stages on a quantized z-buffer: `test`, then the level
    /// stored, at most `depth_max`.
    pub fn quantized(test: DepthTest, depth_max: u32) -> Plain {
        Plain { test, store: DepthStore::Quantized, depth_max }
    }
}

impl PixelStages for Plain {
    fn plain_levels(&self) -> Option<(DepthTest, u32)> {
        (self.store == DepthStore::Quantized).then_some((self.test, self.depth_max))
    }

    #[inline]
    fn decide(&self, polygon: &Polygon, depth: Depth, stored: Stored, frame: u32) -> Decision {
        if self.test.passes(&depth, &stored) {
            let stored = depth.stored(self.store, self.depth_max);
            Decision { outcome: Outcome::Written, compared: depth, stored, frame: polygon.value }
        } else {
            Decision { outcome: Outcome::Hidden, compared: depth, stored, frame }
        }
    }
}

/// Every per-pixel stage: the depth range, the w-buffer's depth, the depth
/// test, the cross-section, blending by opacity, and the store.
#[derive(Debug, Clone, Copy)]
pub struct WithEffects<'s> {
    scene: &'s Scene,
}

impl<'s> WithEffects<'s> {
    /// Every stage, as the scene sets them.
    pub fn new(scene: &'s Scene) -> WithEffects<'s> {
        WithEffects { scene }
    }
}

impl PixelStages for WithEffects<'_> {
    fn decide(&self, polygon: &Polygon, depth: Depth, stored: Stored, frame: u32) -> Decision {
        let scene = self.scene;
        let compared = match scene.effects.perspective {
            Some(perspective) if perspective.store_w => perspective.eye_depth(&depth),
            _ => depth,
        };
        if scene.depth_range.is_some_and(|range| !compared.within(range)) {
            return Decision { outcome: Outcome::OutsideDepthRange, compared, stored, frame };
        }
        // Compared as the level it would be stored as, when the rules say so.
        let tested = match scene.rules.compare {
            Compare::Exact => compared.clone(),
            Compare::Level => match compared.stored(scene.rules.store, scene.depth_max()) {
                Stored::Level(level) => Depth::from_fraction(i128::from(level), 1),
                Stored::Exact(_) => compared.clone(),
            },
        };
        if !scene.depth_test.passes(&tested, &stored) {
            return Decision { outcome: Outcome::Hidden, compared, stored, frame };
        }
        if scene.effects.section.is_some_and(|z| !scene.depth_test.keeps_section(&compared, z)) {
            return Decision { outcome: Outcome::BeyondSection, compared, stored, frame };
        }
        let frame = match polygon.opacity {
            Some(alpha) => blend(polygon.value, frame, alpha),
            None => polygon.value,
        };
        let stored = compared.stored(scene.rules.store, scene.depth_max());
        Decision { outcome: Outcome::Written, compared, stored, frame }
    }
}

/// `α·value + (1 − α)·under`, rounded half up to an integer (the framebuffer
/// holds integers).
pub fn blend(value: u32, under: u32, alpha: Q) -> u32 {
    let mixed =
        alpha * Q::from_integer(i128::from(value)) + (Q::from_integer(1) - alpha) * Q::from_integer(i128::from(under));
    (mixed + Q::new(1, 2)).floor().to_integer() as u32
}

/// Which per-pixel stages a simulation runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum StageSet {
    /// Only those the scene asks for (the default): a scene without
    /// per-pixel effects runs `Plain`.
    #[default]
    AsAsked,
    /// `WithEffects` even when the scene asks for none (for benchmarks and
    /// for the test that both paths agree).
    AllCompiledIn,
}

/// The stages that run for this scene, in order, in words.
pub fn describe(lang: crate::words::Lang, scene: &Scene) -> Vec<String> {
    let mut stages = Vec::new();
    if let Some(winding) = scene.effects.cull {
        stages.push(words!(lang, "stage-cull", winding = winding.name()));
    }
    if let Some(perspective) = scene.effects.perspective {
        stages.push(words!(
            lang,
            "stage-near-plane",
            near = fraction(perspective.near_plane()),
            eye = fraction(perspective.distance)
        ));
    }
    if let Some(antialias) = scene.effects.antialias {
        let key = if antialias.depth_at_samples { "stage-supersampling-sample" } else { "stage-supersampling-pixel" };
        stages.push(words!(lang, key, k = antialias.samples.to_string()));
    }
    if let Some(window) = scene.window {
        stages.push(words!(
            lang,
            "stage-window",
            left = fraction(window.left),
            right = fraction(window.right),
            bottom = fraction(window.bottom),
            top = fraction(window.top)
        ));
    }
    stages.push(match scene.rules.rows {
        RowRule::HalfOpen => words!(lang, "stage-scan"),
        RowRule::Closed => words!(lang, "stage-scan-closed"),
        RowRule::TopLeft => words!(lang, "stage-scan-top-left"),
    });
    if let Some((front, rear)) = scene.depth_range {
        stages.push(words!(lang, "stage-depth-range", front = fraction(front), rear = fraction(rear)));
    }
    if scene.effects.perspective.is_some_and(|p| p.store_w) {
        stages.push(words!(lang, "stage-w-buffer"));
    }
    stages.push(words!(lang, "stage-depth-test", rule = scene.depth_test.rule_text(lang)));
    if let Some(section) = scene.effects.section {
        stages.push(words!(lang, "stage-section", op = scene.depth_test.section_symbol(), section = fraction(section)));
    }
    if scene.effects.transparency {
        stages.push(words!(lang, "stage-blend"));
    }
    stages.push(match scene.rules.store {
        DepthStore::Quantized => words!(lang, "stage-store-quantized", max = scene.depth_max().to_string()),
        DepthStore::Truncated => words!(lang, "stage-store-truncated", max = scene.depth_max().to_string()),
        DepthStore::Exact => words!(lang, "stage-store-exact"),
    });
    stages
}
