//! What a run leaves besides its image, for reports: the primitives drawn,
//! per sample the primitive that wrote it last, each triangle's spans, the
//! shapes as drawn; and the samples where two arithmetics disagree, with why.

use crate::words::Lang;
use std::collections::BTreeMap;

use super::{Arithmetic, Image};

/// One drawing command's primitive (a triangle or a point), for reports.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Primitive {
    /// The line of the draw command.
    pub line: usize,
    /// The vertex indices it reads.
    pub vertices: Vec<usize>,
}

impl Primitive {
    /// The message in `lang`, one line.
    pub fn message(&self, lang: Lang) -> String {
        let list: Vec<String> = self.vertices.iter().map(ToString::to_string).collect();
        let (vertices, line) = (list.join(", "), self.line.to_string());
        if self.vertices.len() == 1 {
            words!(lang, "cs418-primitive-point", vertices = vertices, line = line)
        } else {
            words!(lang, "cs418-primitive-triangle", vertices = vertices, line = line)
        }
    }
}

/// Where a triangle's span on one sample row begins and ends, `[left, right)`.
#[derive(Debug, Clone, PartialEq)]
pub struct SampleSpan {
    /// The left end, as computed.
    pub left: String,
    /// The right end, as computed.
    pub right: String,
    /// The left end as an `f64` (for comparisons).
    pub(super) left_value: f64,
    /// The right end as an `f64`.
    pub(super) right_value: f64,
}

impl SampleSpan {
    fn covers(&self, x: i64) -> bool {
        self.left_value.ceil() <= x as f64 && (x as f64) < self.right_value
    }
}

/// A finished run: the image and, per sample, which primitive wrote it last.
#[derive(Debug, Clone)]
pub struct Comparison {
    /// The image.
    pub image: Image,
    /// The arithmetic it ran in.
    pub arithmetic: Arithmetic,
    /// Samples per pixel side (`fsaa`).
    pub level: u32,
    /// The primitives drawn, in order; `owners` index them from 1.
    pub primitives: Vec<Primitive>,
    /// Per sample, row by row from the top: 0 for none, else 1 + the index
    /// in `primitives` of the last one written.
    pub(super) owners: Vec<u32>,
    /// Each triangle's spans by (primitive, sample row).
    pub(super) spans: BTreeMap<(u32, i64), Vec<SampleSpan>>,
    /// What was drawn, as polygons in zsim's coordinates (see `SampleGrid`).
    pub shapes: Vec<SampleGrid>,
}

/// A triangle (after clipping and culling) or a point's square as drawn, in
/// zsim's coordinates on the sample raster: x + 1/2 and height − y − 1/2, so
/// that the course's sample at integer (x, y) is zsim's centre of column x,
/// row height − 1 − y, and the picture is not flipped; depth z/w.
#[derive(Debug, Clone, PartialEq)]
pub struct SampleGrid {
    /// The primitive (1-based index into `primitives`).
    pub primitive: u32,
    /// Its corners as text (exact fractions in exact arithmetic).
    pub vertices: Vec<[String; 3]>,
}

impl Comparison {
    /// The primitive sample (x, y) shows last (1-based into `primitives`), 0
    /// for none; x and y on the sample raster, y from the top.
    pub fn owner(&self, x: u32, y: u32) -> u32 {
        self.owners[(y * self.image.width * self.level + x) as usize]
    }
}

/// Why a sample came out differently in the two arithmetics.
#[derive(Debug, Clone, PartialEq)]
pub enum Reason {
    /// A triangle covers the sample in one arithmetic and not the other,
    /// because its span on the sample's row ends on the other side of it.
    SampleSpan {
        /// The triangle.
        primitive: Primitive,
        /// Its span on the row in the course's floats (`None`: no span).
        course: Option<(String, String)>,
        /// Its span on the row exactly.
        exact: Option<(String, String)>,
        /// Whether the course's floats cover the sample (exact arithmetic
        /// then does not, and the other way round).
        course_covers: bool,
    },
    /// Both arithmetics cover the sample with the same primitives; the depth
    /// test chose differently (two depths equal or within rounding).
    Depth {
        /// What the course's floats kept.
        course: Option<Primitive>,
        /// What exact arithmetic kept.
        exact: Option<Primitive>,
    },
}

/// One sample whose last writer differs between the two arithmetics.
#[derive(Debug, Clone, PartialEq)]
pub struct CellDifference {
    /// Sample column (pixel column × fsaa level + sub-sample).
    pub x: u32,
    /// Sample row, from the top.
    pub y: u32,
    /// The pixel it belongs to.
    pub pixel: (u32, u32),
    /// Why.
    pub reason: Reason,
}

/// The samples whose last writer differs between a run in the course's
/// floats and one in exact arithmetic of the same case, each with its reason.
pub fn differences(course: &Comparison, exact: &Comparison) -> Vec<CellDifference> {
    let width = (course.image.width * course.level) as usize;
    let mut out = Vec::new();
    for (index, (&a, &b)) in course.owners.iter().zip(&exact.owners).enumerate() {
        if a == b {
            continue;
        }
        let (x, y) = ((index % width) as i64, (index / width) as i64);
        let covers =
            |run: &Comparison, p: u32| run.spans.get(&(p, y)).is_some_and(|spans| spans.iter().any(|s| s.covers(x)));
        let span = |run: &Comparison, p: u32| {
            run.spans
                .get(&(p, y))
                .and_then(|spans| spans.iter().find(|s| s.covers(x)).or(spans.first()))
                .map(|s| (s.left.clone(), s.right.clone()))
        };
        let disputed = [a, b].into_iter().filter(|&p| p != 0).find(|&p| covers(course, p) != covers(exact, p));
        let primitive = |run: &Comparison, p: u32| (p != 0).then(|| run.primitives[p as usize - 1].clone());
        let reason = match disputed {
            Some(p) => Reason::SampleSpan {
                primitive: primitive(course, p).expect("nonzero"),
                course: span(course, p),
                exact: span(exact, p),
                course_covers: covers(course, p),
            },
            None => Reason::Depth { course: primitive(course, a), exact: primitive(exact, b) },
        };
        let level = i64::from(course.level);
        out.push(CellDifference { x: x as u32, y: y as u32, pixel: ((x / level) as u32, (y / level) as u32), reason });
    }
    out
}
