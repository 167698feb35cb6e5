//! The per-pixel stages between the exact depth and the buffers: the plain
//! depth test and store, or every effect a scene can ask for (depth range,
//! w-buffer, cross-section, opacity), chosen once per run; and the stages in
//! words, for reports.

use crate::depth::{Depth, DepthTest, Stored};
use crate::exact::{Q, fraction};
use crate::rules::{DepthStore, RowRule};
use crate::scene::{Polygon, Scene};
use crate::trace::Outcome;

/// What the per-pixel stages make of one covered centre.
#[derive(Debug, Clone, Copy)]
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

impl PixelStages for Plain {
    fn plain_levels(&self) -> Option<(DepthTest, u32)> {
        (self.store == DepthStore::Quantized).then_some((self.test, self.depth_max))
    }

    #[inline]
    fn decide(&self, polygon: &Polygon, depth: Depth, stored: Stored, frame: u32) -> Decision {
        if self.test.passes(depth, stored) {
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
            Some(perspective) if perspective.store_w => perspective.eye_depth(depth),
            _ => depth,
        };
        let unchanged = |outcome| Decision { outcome, compared, stored, frame };
        if scene.depth_range.is_some_and(|(front, rear)| compared.cmp_q(front).is_lt() || compared.cmp_q(rear).is_gt())
        {
            return unchanged(Outcome::OutsideDepthRange);
        }
        if !scene.depth_test.passes(compared, stored) {
            return unchanged(Outcome::Hidden);
        }
        if scene.effects.section.is_some_and(|z| !scene.depth_test.keeps_section(compared, z)) {
            return unchanged(Outcome::BeyondSection);
        }
        let frame = match polygon.opacity {
            Some(alpha) => blend(polygon.value, frame, alpha),
            None => polygon.value,
        };
        Decision {
            outcome: Outcome::Written,
            compared,
            stored: compared.stored(scene.rules.store, scene.depth_max()),
            frame,
        }
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
    /// per-pixel effects runs [`Plain`].
    #[default]
    AsAsked,
    /// [`WithEffects`] even when the scene asks for none (for benchmarks and
    /// for the test that both paths agree).
    AllCompiledIn,
}

/// The stages that run for this scene, in order, in words.
pub fn describe(scene: &Scene) -> Vec<String> {
    let mut stages = Vec::new();
    if let Some(winding) = scene.effects.cull {
        stages.push(format!("back-face culling ({} polygons skipped)", winding.name()));
    }
    if let Some(perspective) = scene.effects.perspective {
        stages.push(format!(
            "near-plane clipping (keep z ≤ {}) and perspective projection (eye at z = {})",
            fraction(perspective.near_plane()),
            fraction(perspective.distance)
        ));
    }
    if let Some(antialias) = scene.effects.antialias {
        stages.push(format!(
            "supersampling {0}×{0} (depth at each {1}), then averaging",
            antialias.samples,
            if antialias.depth_at_samples { "sample" } else { "pixel's centre" }
        ));
    }
    if let Some(window) = scene.window {
        stages.push(format!(
            "window {} … {} × {} … {} onto the raster",
            fraction(window.left),
            fraction(window.right),
            fraction(window.bottom),
            fraction(window.top)
        ));
    }
    stages.push(match scene.rules.rows {
        RowRule::HalfOpen => "scan conversion".to_string(),
        RowRule::Closed => "scan conversion (closed rows, cells holding the crossings)".to_string(),
        RowRule::TopLeft => "scan conversion (top-left rule)".to_string(),
    });
    if let Some((front, rear)) = scene.depth_range {
        stages.push(format!("depth range (discard z outside {} … {})", fraction(front), fraction(rear)));
    }
    if scene.effects.perspective.is_some_and(|p| p.store_w) {
        stages.push("w-buffer (eye-space depth z = d·z'/(d + z'))".to_string());
    }
    stages.push(format!("depth test ({})", scene.depth_test.rule_text()));
    if let Some(section) = scene.effects.section {
        stages.push(format!("cross-section (z {} {})", scene.depth_test.section_symbol(), fraction(section)));
    }
    if scene.effects.transparency {
        stages.push("blend by opacity (α·value + (1 − α)·under, rounded half up)".to_string());
    }
    stages.push(match scene.rules.store {
        DepthStore::Quantized => format!("store (rounded half up, saturated to 0…{})", scene.depth_max()),
        DepthStore::Exact => "store (exact depth)".to_string(),
    });
    stages
}
