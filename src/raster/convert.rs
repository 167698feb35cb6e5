//! The one scan converter: a polygon's rows by half-interval scanlines, the
//! spans between paired crossings, and the exact depth at each covered centre,
//! handed to a [`RasterSink`]. Everything else (the depth test, effects,
//! stepping, explaining, supersampling) observes it.

use std::cmp::Ordering;

use crate::geometry::plane::Geometry;
use crate::numbers::Word;
use crate::raster::depth::DepthPlane;
use crate::raster::scan::{self, Crossing, RowCrossing, Span};
use crate::raster::sink::{PixelRect, RasterSink};
use crate::rules::Rules;

/// Reusable space for the edges, crossings and spans of one polygon, so the
/// rasterizer allocates nothing per row.
#[derive(Debug, Clone, Default)]
pub struct Scratch {
    narrow: Walk<i64>,
    wide: Walk<i128>,
    crossings: Vec<Crossing>,
    spans: Vec<Span>,
}

/// The edge table and one row's crossings, in one machine word.
#[derive(Debug, Clone, Default)]
struct Walk<W> {
    edges: scan::EdgeTable<W>,
    row: Vec<RowCrossing<W>>,
}

/// Scan-converts one polygon with the scene's rules: for each row inside
/// `rect` and the polygon's y range, the sink gets the crossings and spans;
/// for each covered pixel centre, left to right, (x, y) and the exact depth
/// there. This is the one rasterizer; everything else (the depth test,
/// effects, stepping, explaining, supersampling) observes it.
///
/// It runs on 64-bit integers when the polygon's values fit them
/// (`Geometry::fits_i64`) and on 128-bit integers otherwise; the same code
/// either way (`Word`), with the same results.
pub fn rasterize<S: RasterSink>(
    geometry: &Geometry,
    rules: Rules,
    rect: PixelRect,
    scratch: &mut Scratch,
    sink: &mut S,
) {
    let Scratch { narrow, wide, crossings, spans } = scratch;
    if let Some(polygon) = geometry.big() {
        polygon.rasterize(rules, rect, (crossings, spans), sink);
    } else if geometry.fits_i64() {
        rasterize_in(geometry, rules, rect, narrow, (crossings, spans), sink);
    } else {
        rasterize_in(geometry, rules, rect, wide, (crossings, spans), sink);
    }
}

fn rasterize_in<W: Word, S: RasterSink>(
    geometry: &Geometry,
    rules: Rules,
    rect: PixelRect,
    walk: &mut Walk<W>,
    events: (&mut Vec<Crossing>, &mut Vec<Span>),
    sink: &mut S,
) {
    let Some(rows) = walk.edges.prepare(&geometry.points, geometry.denominator, rect.rows, (rules.rows, rules.columns))
    else {
        return;
    };
    let plane = DepthPlane::<W>::new(geometry);
    let (first_row, last_row) = (*rows.start(), *rows.end());
    let mut row_numerator = plane.row_numerator(W::narrow(scan::scanline_y(first_row, geometry.denominator)));
    let row_step = plane.row_step();
    // Rows in bands over which the same edges cross them.
    let mut row = first_row;
    while row <= last_row {
        let band_last = walk.edges.activate(row).min(last_row);
        match walk.edges.pair() {
            // Two edges and nobody to tell the crossings: walk them here, one span per row.
            Some([one, other]) if !S::OBSERVES_SCANLINES => {
                for row in row..=band_last {
                    let (a, b) = (one.crossing(rules.columns), other.crossing(rules.columns));
                    one.advance();
                    other.advance();
                    // In order unless the two edges cross between vertices.
                    let (left, right) = if a.cmp_position(&b) == Ordering::Greater { (b, a) } else { (a, b) };
                    span(sink, &plane, rect.columns, row, (&left, &right), row_numerator);
                    row_numerator += row_step;
                }
            }
            _ => {
                for row in row..=band_last {
                    walk.edges.crossings(row, rules.columns, &mut walk.row);
                    let found = &walk.row;
                    let pairs = scan::pairs(found.len(), rules.rows);
                    if S::OBSERVES_SCANLINES {
                        let (crossings, spans) = (&mut *events.0, &mut *events.1);
                        crossings.clear();
                        crossings.extend(found.iter().map(|c| c.crossing(geometry.scale())));
                        spans.clear();
                        spans.extend(pairs.clone().map(|(i, j)| Span {
                            left: crossings[i].clone(),
                            right: crossings[j].clone(),
                            columns: scan::clip_columns(found[i].first_column, found[j].last_column, rect.columns),
                        }));
                        sink.scanline(row, crossings, spans);
                    }
                    for (i, j) in pairs {
                        span(sink, &plane, rect.columns, row, (&found[i], &found[j]), row_numerator);
                    }
                    row_numerator += row_step;
                }
            }
        }
        row = band_last + 1;
    }
}

/// A span between two crossings: its columns within `limit`, and the depth
/// at the first of them.
#[inline]
fn span<W: Word, S: RasterSink>(
    sink: &mut S,
    plane: &DepthPlane<W>,
    limit: (u32, u32),
    row: u32,
    (left, right): (&RowCrossing<W>, &RowCrossing<W>),
    row_numerator: W,
) {
    if let Some((first, last)) = scan::clip_columns(left.first_column, right.last_column, limit) {
        sink.span(row, first, last, plane.start_at(row_numerator, first));
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::numbers::Q;
    use crate::raster::depth::Depth;
    use crate::rules::{ColumnRule, RowRule};

    /// Everything a sink is told, in order.
    #[derive(Default)]
    struct Collect(Vec<String>);

    impl RasterSink for Collect {
        fn scanline(&mut self, row: u32, crossings: &[Crossing], spans: &[Span]) {
            // Values: crossings at the same x may come in either order, over different denominators.
            let x = |c: &Crossing| c.x();
            let crossings: Vec<crate::numbers::Exact> = crossings.iter().map(x).collect();
            let spans: Vec<_> = spans.iter().map(|s| (x(&s.left), x(&s.right), s.columns)).collect();
            self.0.push(format!("row {row}: {crossings:?} {spans:?}"));
        }

        fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
            // The value: the tiers may keep a depth over different denominators.
            self.0.push(format!("({x}, {y}) {:?}", depth.value()));
        }
    }

    /// The events of the big-integer tier for the same polygon: with its
    /// crossings and depths in 128 bits, or (`huge`) in big integers.
    fn run_big(geometry: &Geometry, rules: Rules, rect: PixelRect, huge: bool) -> Vec<String> {
        let mut sink = Collect::default();
        let big = if huge { geometry.on_huge_tier() } else { geometry.on_big_tier() };
        rasterize(&big, rules, rect, &mut Scratch::default(), &mut sink);
        sink.0
    }

    fn run<W: Word>(geometry: &Geometry, rules: Rules, rect: PixelRect) -> Vec<String> {
        let (mut walk, mut crossings, mut spans, mut sink) =
            (Walk::<W>::default(), Vec::new(), Vec::new(), Collect::default());
        rasterize_in(geometry, rules, rect, &mut walk, (&mut crossings, &mut spans), &mut sink);
        sink.0
    }

    /// A steep triangle as large as the 64-bit bound allows: it runs on `i64`
    /// without overflow (the test profile checks) and draws as on `i128`;
    /// one pixel larger no longer fits.
    #[test]
    fn the_largest_steep_polygon_that_fits_64_bits_draws_as_on_128() {
        let triangle = |size: i128| {
            let q = |v: i128| Q::from_integer(v);
            let rise = 1 << 30;
            Geometry::new(&[[q(0), q(0), q(7)], [q(size), q(1), q(7 + rise)], [q(2), q(size), q(7 - rise)]]).unwrap()
        };
        // The largest size that fits, by bisection.
        let (mut fits, mut fails) = (16i128, 1i128 << 32);
        assert!(triangle(fits).fits_i64() && !triangle(fails).fits_i64());
        while fails - fits > 1 {
            let middle = (fits + fails) / 2;
            if triangle(middle).fits_i64() { fits = middle } else { fails = middle }
        }
        let rect = PixelRect { columns: (0, 15), rows: (0, 15) };
        for rules in
            [Rules::default(), Rules { rows: RowRule::Closed, columns: ColumnRule::CellHolds, ..Rules::default() }]
        {
            let drawn = run::<i64>(&triangle(fits), rules, rect);
            assert!(drawn.iter().filter(|line| line.starts_with('(')).count() > 20, "{drawn:?}");
            assert_eq!(drawn, run::<i128>(&triangle(fits), rules, rect));
        }
        assert!(!triangle(fits + 1).fits_i64());
    }

    proptest! {
        /// The 64-bit and the 128-bit words, and the big-integer tier with its
        /// reports in 128 bits and in big integers, give the same crossings,
        /// spans, pixels and depths, under every rule and in any clipping
        /// rectangle.
        #[test]
        fn both_words_rasterize_alike(
            vertices in prop::collection::vec((-40i64..80, -40i64..80, 1i64..5), 3..7),
            plane in (-9i64..10, -9i64..10, -60i64..60, 1i64..8),
            row_rule in 0usize..3,
            column_rule in 0usize..3,
            rect in (0u32..20, 0u32..20, 0u32..20, 0u32..20),
        ) {
            // A planar polygon: z = (a·x + b·y + c) / e, vertices over denominators 1 … 4,
            // depths of both signs and with every remainder.
            let (a, b, c, e) = plane;
            let q = |n: i64, d: i64| Q::new(n.into(), d.into());
            let vertices: Vec<[Q; 3]> = vertices
                .iter()
                .map(|&(x, y, d)| {
                    let (x, y) = (q(x, d), q(y, d));
                    [x, y, (x * q(a, 1) + y * q(b, 1) + q(c, 1)) / q(e, 1)]
                })
                .collect();
            let geometry = Geometry::new(&vertices);
            prop_assume!(geometry.is_ok(), "not a polygon");
            let geometry = geometry.expect("assumed above");
            prop_assume!(geometry.c() != 0 && geometry.fits_i64());
            let rules = Rules {
                rows: [RowRule::HalfOpen, RowRule::Closed, RowRule::TopLeft][row_rule],
                columns: [ColumnRule::CentreInside, ColumnRule::CellHolds, ColumnRule::HalfOpen][column_rule],
                ..Rules::default()
            };
            let rect = PixelRect {
                columns: (rect.0.min(rect.1), rect.0.max(rect.1) + 10),
                rows: (rect.2.min(rect.3), rect.2.max(rect.3) + 10),
            };
            let words = run::<i128>(&geometry, rules, rect);
            prop_assert_eq!(&run::<i64>(&geometry, rules, rect), &words);
            prop_assert_eq!(&run_big(&geometry, rules, rect, false), &words);
            prop_assert_eq!(&run_big(&geometry, rules, rect, true), &words);
        }
    }

    /// The pixels a polygon covers under `rules`, as (x, y).
    fn covered(vertices: &[[i64; 2]], rules: Rules, size: u32) -> Vec<(u32, u32)> {
        let q = |v: i64| Q::new(v.into(), 2);
        let points: Vec<[Q; 3]> = vertices.iter().map(|p| [q(p[0]), q(p[1]), Q::from_integer(5)]).collect();
        let geometry = Geometry::new(&points).unwrap();
        let drawn = run::<i128>(&geometry, rules, PixelRect { columns: (0, size - 1), rows: (0, size - 1) });
        let mut cells: Vec<(u32, u32)> = drawn
            .iter()
            .filter_map(|line| {
                let (x, rest) = line.strip_prefix('(')?.split_once(", ")?;
                Some((x.parse().ok()?, rest.split_once(')')?.0.parse().ok()?))
            })
            .collect();
        cells.sort_unstable();
        cells
    }

    /// The Direct3D 11 rule itself, written independently with edge
    /// functions: a centre is covered when strictly inside every edge, or on
    /// an edge that is a top or left edge (and strictly inside the others).
    /// "Top" is as displayed, and zsim displays row 0 at the bottom, so a top
    /// edge is the horizontal edge with the largest y. Vertices in half units.
    fn direct3d(vertices: &[[i64; 2]], size: u32) -> Vec<(u32, u32)> {
        let n = vertices.len();
        let area: i64 =
            (0..n).map(|i| vertices[i][0] * vertices[(i + 1) % n][1] - vertices[(i + 1) % n][0] * vertices[i][1]).sum();
        let mut cells = Vec::new();
        for y in 0..size {
            for x in 0..size {
                let (px, py) = (2 * i64::from(x) + 1, 2 * i64::from(y) + 1);
                let inside = (0..n).all(|i| {
                    let ([ax, ay], [bx, by]) = (vertices[i], vertices[(i + 1) % n]);
                    // Positive inside, for either winding.
                    let e = ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) * area.signum();
                    // Interior on the edge's left when walking counter-clockwise: a left edge
                    // runs downwards (as displayed, y up: by < ay), a top edge runs right to left.
                    let (dx, dy) = ((bx - ax) * area.signum(), (by - ay) * area.signum());
                    let top = dy == 0 && dx < 0;
                    let left = dy < 0;
                    e > 0 || (e == 0 && (top || left))
                });
                if inside {
                    cells.push((x, y));
                }
            }
        }
        cells.sort_unstable();
        cells
    }

    fn gpu() -> Rules {
        Rules::preset(crate::rules::Preset::Vulkan)
    }

    /// Each case of the top-left rule, with a centre exactly on the edge or
    /// vertex named (vertices in half units: 2·x, so odd numbers are centres).
    #[test]
    fn top_left_rule_matches_direct3d_on_every_kind_of_edge() {
        let cases: [(&str, &[[i64; 2]]); 8] = [
            ("a centre on a left (slanted) edge is covered", &[[3, 1], [13, 1], [13, 11]]),
            ("a centre on a right (slanted) edge is not", &[[1, 1], [11, 1], [1, 11]]),
            ("a centre on a top (horizontal, largest y) edge is covered", &[[1, 1], [9, 9], [1, 9]]),
            ("a centre on a bottom (horizontal, smallest y) edge is not", &[[1, 1], [9, 1], [1, 9]]),
            ("a centre at a top vertex is not (left and right edges meet)", &[[0, 2], [10, 2], [5, 9]]),
            ("a centre at a bottom vertex is not", &[[5, 1], [10, 8], [0, 8]]),
            ("a centre at a left vertex is covered (two left edges)", &[[1, 5], [10, 0], [10, 10]]),
            ("a centre at a right vertex is not (two right edges)", &[[0, 0], [9, 5], [0, 10]]),
        ];
        for (case, vertices) in cases {
            let expected = direct3d(vertices, 8);
            assert!(!expected.is_empty(), "{case}: the case covers something");
            assert_eq!(covered(vertices, gpu(), 8), expected, "{case}");
            let reversed: Vec<[i64; 2]> = vertices.iter().rev().copied().collect();
            assert_eq!(covered(&reversed, gpu(), 8), expected, "{case}, vertices in the other order");
        }
    }

    /// Two triangles sharing an edge through centres: the book's rule draws
    /// the shared centres twice, the top-left rule once, and together they
    /// cover the square exactly.
    #[test]
    fn shared_edges_are_drawn_once_under_the_top_left_rule() {
        let (lower, upper): (&[[i64; 2]], &[[i64; 2]]) = (&[[1, 1], [13, 1], [13, 13]], &[[1, 1], [13, 13], [1, 13]]);
        let (a, b) = (covered(lower, gpu(), 8), covered(upper, gpu(), 8));
        assert!(a.iter().all(|cell| !b.contains(cell)), "no centre drawn twice");
        let mut both: Vec<(u32, u32)> = a.iter().chain(&b).copied().collect();
        both.sort_unstable();
        assert_eq!(both, direct3d(&[[1, 1], [13, 1], [13, 13], [1, 13]], 8));
        let (a, b) = (covered(lower, Rules::default(), 8), covered(upper, Rules::default(), 8));
        let twice: Vec<&(u32, u32)> = a.iter().filter(|cell| b.contains(cell)).collect();
        assert_eq!(
            twice,
            vec![&(0, 0), &(1, 1), &(2, 2), &(3, 3), &(4, 4), &(5, 5)],
            "the book draws the diagonal twice"
        );
    }
}
