//! Ties: pixel centres exactly on a polygon's edge or vertex, where the
//! rule sets differ, and the cells where two rule sets draw a scene
//! differently, each with the tie that decided it.

use crate::words::Lang;
use std::cmp::Ordering;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::numbers::{Exact, Q};
use crate::raster::convert::{Scratch, rasterize};
use crate::raster::sink::{CoveredCentres, PixelRect};
use crate::rules::{Preset, Rules, Sample};
use crate::scene::Scene;
use crate::simulate::events::Unobserved;
use crate::simulate::simulation::Simulation;

/// Which kind of boundary a centre lies on, as drawn (y up, row 0 at the bottom).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Boundary {
    /// A horizontal edge with the polygon below it.
    TopEdge,
    /// A horizontal edge with the polygon above it.
    BottomEdge,
    /// A slanted or vertical edge with the polygon to its right.
    LeftEdge,
    /// A slanted or vertical edge with the polygon to its left.
    RightEdge,
    /// A vertex.
    Vertex,
}

impl Boundary {
    /// The words for it: "left edge", "vertex", ….
    pub fn words(self, lang: Lang) -> String {
        match self {
            Boundary::TopEdge => words!(lang, "boundary-top"),
            Boundary::BottomEdge => words!(lang, "boundary-bottom"),
            Boundary::LeftEdge => words!(lang, "boundary-left"),
            Boundary::RightEdge => words!(lang, "boundary-right"),
            Boundary::Vertex => words!(lang, "boundary-vertex"),
        }
    }
}

/// The columns of row `y` whose centres can lie on the polygon's boundary:
/// where an edge meets the scanline y + ½ exactly at a centre, and every
/// centre along an edge that lies on the scanline. A superset of the
/// columns [`boundary_at`] finds on that row (held to it by
/// `boundary_columns_hold_every_centre_on_a_boundary`), so a caller asks
/// [`boundary_at`] a few columns instead of every one.
pub fn boundary_columns(vertices: &[[Exact; 3]], y: u32) -> Vec<u32> {
    let scan_y = Exact::Word(Q::new(2 * i128::from(y) + 1, 2)).to_big();
    let half = BigRational::new(1.into(), 2.into());
    let n = vertices.len();
    let mut columns = Vec::new();
    // The column whose centre is at `x`, if `x` is a centre.
    let centre_column = |x: &BigRational| {
        let column = x - &half;
        (column.is_integer() && !column.is_negative()).then(|| column.to_integer()).and_then(|c| u32::try_from(c).ok())
    };
    for i in 0..n {
        let (a, b) = (&vertices[i], &vertices[(i + 1) % n]);
        let (ax, ay, bx, by) = (a[0].to_big(), a[1].to_big(), b[0].to_big(), b[1].to_big());
        if ay == by {
            if ay == scan_y {
                // A horizontal edge on the scanline: every centre along it.
                let (low, high) = if ax <= bx { (ax, bx) } else { (bx, ax) };
                let first = (&low - &half).ceil().to_integer().max(0.into());
                let last = (&high - &half).floor().to_integer();
                let mut c = first;
                while c <= last {
                    columns.extend(u32::try_from(&c).ok());
                    c += 1;
                }
            }
            continue;
        }
        if scan_y < ay.clone().min(by.clone()) || scan_y > ay.clone().max(by.clone()) {
            continue;
        }
        let x = &ax + (&scan_y - &ay) * (&bx - &ax) / (&by - &ay);
        columns.extend(centre_column(&x));
    }
    columns.sort_unstable();
    columns.dedup();
    columns
}

/// Where pixel (x, y)'s centre lies on a polygon's boundary, if it does:
/// the boundary's kind and the edge (its two vertices) or vertex.
pub fn boundary_at(vertices: &[[Exact; 3]], x: u32, y: u32) -> Option<(Boundary, [Exact; 2], [Exact; 2])> {
    // In big rationals: a clipped polygon's vertices are fractions whose
    // products outgrow 128 bits.
    let centre = [Q::new(2 * i128::from(x) + 1, 2), Q::new(2 * i128::from(y) + 1, 2)];
    let n = vertices.len();
    for v in vertices {
        if v[0] == centre[0] && v[1] == centre[1] {
            let point = [v[0].clone(), v[1].clone()];
            return Some((Boundary::Vertex, point.clone(), point));
        }
    }
    let points: Vec<[BigRational; 2]> = vertices.iter().map(|v| [v[0].to_big(), v[1].to_big()]).collect();
    let centre_big = centre.map(|q| Exact::Word(q).to_big());
    // Twice the signed area: positive when the vertices run counter-clockwise.
    let area: BigRational =
        (0..n).map(|i| &points[i][0] * &points[(i + 1) % n][1] - &points[(i + 1) % n][0] * &points[i][1]).sum();
    let orientation = area.cmp(&BigRational::zero());
    for i in 0..n {
        let (a, b) = (&points[i], &points[(i + 1) % n]);
        let cross = (&b[0] - &a[0]) * (&centre_big[1] - &a[1]) - (&b[1] - &a[1]) * (&centre_big[0] - &a[0]);
        let within = |k: usize| {
            a[k].clone().min(b[k].clone()) <= centre_big[k] && centre_big[k] <= a[k].clone().max(b[k].clone())
        };
        if !cross.is_zero() || !within(0) || !within(1) {
            continue;
        }
        // Walking counter-clockwise the interior is on the left of each edge:
        // an edge running down has it to the east (a left edge), one running
        // right to left along a horizontal has it below (a top edge).
        let flip = if orientation == Ordering::Less { -1 } else { 1 };
        let dy = b[1].cmp(&a[1]) as i32 * flip;
        let dx = b[0].cmp(&a[0]) as i32 * flip;
        let (a, b) = (&vertices[i], &vertices[(i + 1) % n]);
        let kind = match (dy, dx) {
            (0, d) if d < 0 => Boundary::TopEdge,
            (0, _) => Boundary::BottomEdge,
            (d, _) if d < 0 => Boundary::LeftEdge,
            _ => Boundary::RightEdge,
        };
        return Some((kind, [a[0].clone(), a[1].clone()], [b[0].clone(), b[1].clone()]));
    }
    None
}

/// Whether a rule set covers a centre on a boundary of this kind (for a
/// vertex, the answer depends on the edges meeting there: `None`).
pub fn rule_covers(rules: Rules, boundary: Boundary) -> Option<bool> {
    use crate::rules::{ColumnRule, RowRule};
    match boundary {
        Boundary::Vertex => None,
        Boundary::TopEdge => Some(rules.rows != RowRule::HalfOpen),
        Boundary::BottomEdge => Some(rules.rows != RowRule::TopLeft),
        Boundary::LeftEdge => Some(true),
        Boundary::RightEdge => Some(rules.columns != ColumnRule::HalfOpen),
    }
}

/// A cell the two rule sets draw differently.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RuleDifference {
    /// Column.
    pub x: u32,
    /// Row (from the bottom).
    pub y: u32,
    /// The framebuffer value under the scene's rules and under the other.
    pub values: (u32, u32),
    /// The polygons covering the centre under each, by index, in drawing order.
    pub covering: (Vec<usize>, Vec<usize>),
    /// For each polygon covered under one rule set and not the other: its
    /// index, where the centre lies on it, and that edge's ends.
    pub ties: Vec<(usize, Boundary, [Exact; 2], [Exact; 2])>,
}

/// For each pixel (row by row from the bottom), the polygons of `scene` that
/// cover its centre under its rules, in scene order (none for a polygon
/// those rules do not draw: edge-on, culled, below the area bound).
fn coverage(scene: &Scene) -> Vec<Vec<usize>> {
    let rect = PixelRect { columns: (0, scene.width - 1), rows: (0, scene.height - 1) };
    let mut scratch = Scratch::default();
    let mut covering = vec![Vec::new(); scene.width as usize * scene.height as usize];
    for index in 0..scene.polygons.len() {
        if crate::simulate::setup::fate(scene, index) != crate::simulate::events::Fate::Drawn {
            continue;
        }
        let mut cells = CoveredCentres::default();
        rasterize(scene.polygons[index].geometry(), scene.rules, rect, &mut scratch, &mut cells);
        for (x, y) in cells.0 {
            covering[y as usize * scene.width as usize + x as usize].push(index);
        }
    }
    covering
}

/// The cells whose final framebuffer value differs between the scene's own
/// rules and `other` (the same scene otherwise), bottom row last, each with
/// the polygons covering it under each and the ties that made the difference.
pub fn compare_rules(scene: &Scene, other: Rules) -> Vec<RuleDifference> {
    let mut changed = scene.clone();
    changed.rules = other;
    // Samples at corners are drawn shifted by 1/2: the other rules see the polygons where they sample.
    let shift = match (scene.rules.sample, other.sample) {
        (Sample::Corner, Sample::Centre) => Some(Q::new(-1, 2)),
        (Sample::Centre, Sample::Corner) => Some(Q::new(1, 2)),
        _ => None,
    };
    if let Some(shift) = shift {
        for polygon in &mut changed.polygons {
            if let Ok(shifted) = polygon.shifted(shift) {
                *polygon = shifted;
            }
        }
    }
    let frames = [scene, &changed].map(|s| {
        let mut simulation = Simulation::new(s);
        simulation.finish(&mut Unobserved);
        simulation.buffers().frame_rows()
    });
    let (ours, theirs) = (coverage(scene), coverage(&changed));
    let mut out = Vec::new();
    for (printed_row, (a, b)) in frames[0].iter().zip(&frames[1]).enumerate() {
        let y = crate::raster::row_y(scene.height, printed_row);
        for (x, (&va, &vb)) in a.iter().zip(b).enumerate() {
            let x = x as u32;
            let cell = y as usize * scene.width as usize + x as usize;
            let covering = (ours[cell].clone(), theirs[cell].clone());
            if va == vb && covering.0 == covering.1 {
                continue;
            }
            // Only the polygons covering it under one rule set and not the other (both lists are in scene order).
            let mut changed: Vec<usize> = covering.0.iter().chain(&covering.1).copied().collect();
            changed.sort_unstable();
            changed.dedup();
            let ties = changed
                .into_iter()
                .filter(|i| covering.0.contains(i) != covering.1.contains(i))
                .filter_map(|i| boundary_at(&scene.polygons[i].vertices(), x, y).map(|(kind, a, b)| (i, kind, a, b)))
                .collect();
            out.push(RuleDifference { x, y, values: (va, vb), covering, ties });
        }
    }
    out
}

/// Which of a rule set's choices decides a centre on this kind of boundary,
/// in words: "the book's column rule (centres in [x_l, x_r], ends included)", ….
fn deciding_rule(lang: Lang, rules: Rules, boundary: Boundary) -> String {
    use crate::rules::{ColumnRule, RowRule};
    match boundary {
        Boundary::LeftEdge | Boundary::RightEdge => match rules.columns {
            ColumnRule::CentreInside => words!(lang, "rule-columns-centre"),
            ColumnRule::CellHolds => words!(lang, "rule-columns-cell"),
            ColumnRule::HalfOpen => words!(lang, "rule-columns-half-open"),
        },
        Boundary::TopEdge | Boundary::BottomEdge | Boundary::Vertex => match rules.rows {
            RowRule::HalfOpen => words!(lang, "rule-rows-half-open"),
            RowRule::Closed => words!(lang, "rule-rows-closed"),
            RowRule::TopLeft => words!(lang, "rule-rows-top-left"),
        },
    }
}

/// One sentence on a centre exactly on a polygon's boundary and the rule
/// that decides it, or `None` when pixel (x, y)'s centre is not on it.
pub fn tie_text(lang: Lang, rules: Rules, vertices: &[[Exact; 3]], x: u32, y: u32) -> Option<String> {
    let (boundary, a, b) = boundary_at(vertices, x, y)?;
    let point = |[x, y]: [Exact; 2]| format!("({}, {})", crate::numbers::fraction(x), crate::numbers::fraction(y));
    let place = boundary.words(lang);
    Some(match rule_covers(rules, boundary) {
        None => words!(lang, "tie-vertex", point = point(a), rule = deciding_rule(lang, rules, boundary)),
        Some(covers) => words!(
            lang,
            if covers { "tie-edge-in" } else { "tie-edge-out" },
            boundary = place,
            a = point(a),
            b = point(b),
            rule = deciding_rule(lang, rules, boundary)
        ),
    })
}

/// `--compare-rules` in words: the cells two rule sets draw differently,
/// each with the polygons covering it and the edge its centre lies on.
pub fn compare_rules_text(lang: Lang, scene: &Scene, path: &str, preset: Preset) -> String {
    use std::fmt::Write as _;
    // An exact z-buffer stays exact (BUET's); otherwise the preset's whole rules, depth included.
    let other = match scene.rules.store {
        crate::rules::DepthStore::Exact => Rules { store: crate::rules::DepthStore::Exact, ..Rules::preset(preset) },
        _ => Rules::preset(preset),
    };
    let differences = compare_rules(scene, other);
    let mut text = format!(
        "{path}\n  {}\n  {}\n",
        words!(lang, "compare-rules-this", rules = scene.rules.describe(lang)),
        words!(lang, "compare-rules-other", rules = other.describe(lang))
    );
    if differences.is_empty() {
        text.push_str(&format!("{}\n", words!(lang, "compare-rules-same")));
        return text;
    }
    let _ = writeln!(text, "{}", words!(lang, "compare-rules-differ", count = differences.len()));
    let names = |list: &[usize]| -> String {
        if list.is_empty() {
            return words!(lang, "compare-rules-nothing");
        }
        let names: Vec<String> = list.iter().map(|&i| format!("\"{}\"", scene.polygons[i].name)).collect();
        names.join(&words!(lang, "list-and"))
    };
    let point = |[x, y]: &[Exact; 2]| format!("({}, {})", crate::numbers::fraction(x), crate::numbers::fraction(y));
    for d in &differences {
        let line = words!(
            lang,
            "compare-rules-cell",
            x = d.x.to_string(),
            y = d.y.to_string(),
            before = d.values.0.to_string(),
            after = d.values.1.to_string(),
            covering = names(&d.covering.0),
            rules = scene.rules.preset.name(lang),
            other_covering = names(&d.covering.1),
            other_rules = preset.name(lang)
        );
        let _ = writeln!(text, "  {line}");
        for (polygon, boundary, a, b) in &d.ties {
            let name = &scene.polygons[*polygon].name;
            if *boundary == Boundary::Vertex {
                let line = words!(
                    lang,
                    "compare-rules-vertex",
                    x = d.x.to_string(),
                    y = d.y.to_string(),
                    vertex = point(a),
                    name = name.as_str()
                );
                let _ = writeln!(text, "      {line}");
                continue;
            }
            let verdict = |rules: Rules| match rule_covers(rules, *boundary) {
                Some(true) => words!(lang, "compare-rules-covered"),
                _ => words!(lang, "compare-rules-left-out"),
            };
            let line = words!(
                lang,
                "compare-rules-edge",
                x = d.x.to_string(),
                y = d.y.to_string(),
                boundary = boundary.words(lang),
                name = name.as_str(),
                from = point(a),
                to = point(b),
                verdict = verdict(scene.rules),
                rules = scene.rules.preset.name(lang),
                other_verdict = verdict(other),
                other_rules = preset.name(lang)
            );
            let _ = writeln!(text, "      {line}");
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rules::Preset;

    fn triangle() -> Vec<[Exact; 3]> {
        // (1/2, 1/2), (13/2, 1/2), (13/2, 13/2): centres on its right and bottom edges.
        let q = |n: i128| Exact::Word(Q::new(n, 2));
        vec![[q(1), q(1), q(10)], [q(13), q(1), q(10)], [q(13), q(13), q(10)]]
    }

    /// The columns `boundary_columns` offers hold every centre `boundary_at`
    /// finds, row by row, on every example scene's polygons (a filter that
    /// left one out would leave out its tie's note).
    #[test]
    fn boundary_columns_hold_every_centre_on_a_boundary() {
        let mut found = 0;
        let folder = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/examples"));
        let mut scenes: Vec<_> = std::fs::read_dir(folder).unwrap().map(|e| e.unwrap().path()).collect();
        scenes.retain(|p| p.extension().is_some_and(|e| e == "json"));
        scenes.sort();
        let mut polygons: Vec<(Vec<[Exact; 3]>, u32, u32)> = scenes
            .iter()
            .flat_map(|path| {
                let scene = Scene::load(path).unwrap();
                let (w, h) = (scene.width, scene.height);
                scene.polygons.iter().map(move |p| (p.vertices().into_owned(), w, h)).collect::<Vec<_>>()
            })
            .collect();
        polygons.push((triangle(), 8, 8));
        for (vertices, width, height) in polygons {
            for y in 0..height {
                let every: Vec<u32> = (0..width).filter(|&x| boundary_at(&vertices, x, y).is_some()).collect();
                let offered = boundary_columns(&vertices, y);
                let kept: Vec<u32> =
                    offered.into_iter().filter(|&x| x < width && boundary_at(&vertices, x, y).is_some()).collect();
                assert_eq!(kept, every, "row {y} of {vertices:?}");
                found += every.len();
            }
        }
        assert!(found > 20, "{found} centres on a boundary: the examples should have some");
    }

    #[test]
    fn ties_are_named_with_the_rule_that_decides_them() {
        let gpu = Rules::preset(Preset::Vulkan);
        assert_eq!(
            tie_text(Lang::En, gpu, &triangle(), 6, 3).unwrap(),
            "the centre lies exactly on the right edge from (13/2, 1/2) to (13/2, 13/2), which the half-open column rule (centres in [x_l, x_r): left edges in, right edges out) leaves out"
        );
        assert_eq!(
            tie_text(Lang::En, Rules::default(), &triangle(), 3, 0).unwrap(),
            "the centre lies exactly on the bottom edge from (1/2, 1/2) to (13/2, 1/2), which the book's half-interval rule (an edge counts for min ≤ y < max) includes"
        );
        assert!(tie_text(Lang::En, gpu, &triangle(), 4, 2).is_none(), "an inside centre is no tie");
        assert!(
            tie_text(Lang::En, gpu, &triangle(), 0, 0)
                .unwrap()
                .starts_with("the centre is exactly the vertex (1/2, 1/2)")
        );
    }
}
