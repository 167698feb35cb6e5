//! The kind of a wrong answer, named before its value: which known wrong
//! rule gives exactly what the student typed, or which way coverage or the
//! depth test went wrong.

use crate::numbers::{Exact, Q, parse_number};
use crate::observe::tie::boundary_at;
use crate::raster::depth::{Depth, Stored};
use crate::rules::DepthStore;
use crate::scene::Scene;
use crate::simulate::events::{Outcome, PixelEvent};
use crate::teach::check::diagnose::Misconception;
use crate::teach::step::{Question, parse_columns};

use super::Hint;

/// The kind of a wrong answer (judged already): named only where a known
/// wrong rule gives exactly what was typed, else [`Hint::Other`] (a plain
/// "not yet"). `covered`, the columns the question's scanline covers;
/// `neighbours`, those the same polygon covers on the rows just below and above.
pub(super) fn hint(scene: &Scene, question: &Question, covered: &[u32], neighbours: &[Vec<u32>], typed: &str) -> Hint {
    match question {
        Question::Coverage { stop, row } => match parse_columns(typed) {
            Some(said) => coverage_hint(scene, stop.polygon, *row, (covered, neighbours), &said),
            None => Hint::Other,
        },
        Question::Depth { pixel, .. } => depth_hint(scene, pixel, typed),
        Question::Frame { pixel, .. } => frame_hint(scene, pixel, typed),
    }
}

/// A coverage answer's kind of mistake: only centres on the polygon's
/// boundary decided the other way (every differing column's centre lies on
/// it), or the columns of the row just below or above; else none.
fn coverage_hint(
    scene: &Scene,
    polygon: usize,
    row: u32,
    (covered, neighbours): (&[u32], &[Vec<u32>]),
    said: &[u32],
) -> Hint {
    let vertices = scene.polygons[polygon].vertices();
    let taken_in = said.iter().filter(|x| !covered.contains(x));
    let left_out = covered.iter().filter(|x| !said.contains(x));
    // Whether the centre lies on the boundary is a fact: asked of `boundary_at`, not worded.
    if taken_in.chain(left_out).all(|&x| boundary_at(&vertices, x, row).is_some()) {
        return Hint::CentreOnBoundary;
    }
    let mut said = said.to_vec();
    said.sort_unstable();
    if neighbours.iter().any(|columns| !columns.is_empty() && *columns == said) {
        return Hint::NeighbouringRow;
    }
    Hint::Other
}

/// A depth answer's kind of mistake: a known wrong rule that gives exactly
/// this value first, then whether the pixel is written.
pub(super) fn depth_hint(scene: &Scene, pixel: &PixelEvent, typed: &str) -> Hint {
    let written = pixel.outcome == Outcome::Written;
    if typed == "-" {
        return if written { written_hint(scene, pixel) } else { Hint::Other };
    }
    let Ok(value) = parse_number(typed) else { return Hint::Other };
    let said = Exact::Word(value);
    let z = pixel.compared.value();
    let rounded = Exact::integer(pixel.compared.rounded());
    if scene.rules.store == DepthStore::Quantized && written {
        let max = i128::from(scene.depth_max());
        let fits = value.is_integer() && *value.numer() >= 0 && *value.numer() <= max;
        if !fits && said == rounded {
            return Hint::Misconception(Misconception::NoSaturation);
        }
        let floor = Exact::integer(z.floor());
        if said == floor && floor != rounded {
            let half = z.minus(&floor) == Exact::Word(Q::new(1, 2));
            return Hint::Misconception(if half { Misconception::HalfDown } else { Misconception::Truncated });
        }
        // Rounded up where the nearest integer is below (z = 21/4 stored as 6).
        let ceiling = floor.plus(&Exact::integer(1.into()));
        if said == ceiling && ceiling != rounded && z != floor {
            return Hint::RoundedUp;
        }
    }
    match written {
        // The old value kept where the pixel is written.
        true if said == pixel.stored_before.value() => written_hint(scene, pixel),
        // The pixel's own depth stored where it is hidden.
        false if said == rounded || said == z => reversed_hint(scene, pixel),
        _ => Hint::Other,
    }
}

/// Why a student says a written pixel is not written: comparing the rounded
/// depth, a test not strict, or the test reversed.
fn written_hint(scene: &Scene, pixel: &PixelEvent) -> Hint {
    if scene.rules.store == DepthStore::Quantized
        && let Ok(rounded) = i128::try_from(pixel.compared.rounded())
        && !scene.depth_test.passes(&Depth::from_fraction(rounded, 1), &pixel.stored_before)
    {
        return Hint::Misconception(Misconception::RoundedCompared);
    }
    Hint::IsWritten
}

/// Why a student writes a hidden pixel: the test not strict where the depths
/// are equal, else reversed.
fn reversed_hint(scene: &Scene, pixel: &PixelEvent) -> Hint {
    let equal = match &pixel.stored_before {
        Stored::Level(level) => pixel.compared.cmp_integer(i128::from(*level)).is_eq(),
        Stored::Exact(value) => pixel.compared.cmp_exact(value).is_eq(),
    };
    if equal && scene.depth_test.compares() {
        return Hint::Misconception(Misconception::NotStrict);
    }
    Hint::IsNotWritten
}

/// A framebuffer answer's kind of mistake.
fn frame_hint(scene: &Scene, pixel: &PixelEvent, typed: &str) -> Hint {
    let written = pixel.outcome == Outcome::Written;
    let value = if typed == "-" { None } else { parse_number(typed).ok() };
    let said_kept = typed == "-" || value.is_some_and(|v| *v.numer() == i128::from(pixel.frame_before));
    let polygon_value = scene.polygons[pixel.index].value;
    let said_written = value.is_some_and(|v| *v.numer() == i128::from(polygon_value));
    match (written, said_kept, said_written) {
        (true, true, _) => written_hint(scene, pixel),
        (false, _, true) => reversed_hint(scene, pixel),
        _ => Hint::Other,
    }
}
