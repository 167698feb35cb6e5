//! Scan conversion: half-interval scanlines, edge crossings, spans and the
//! pixel-centre rule, all on a polygon's scaled integer coordinates (see
//! [`crate::plane`]).

use std::cmp::Ordering;
use std::ops::RangeInclusive;

use crate::exact::{Q, ceil_div, floor_div};
use crate::rules::{ColumnRule, RowRule};

/// An x position in scaled units as the fraction `numerator / denominator`
/// (`denominator > 0`), where a crossing falls on a scanline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Crossing {
    /// Numerator, in scaled units; at most `6R²` in magnitude.
    pub numerator: i128,
    /// Positive denominator, at most `2R`.
    pub denominator: i128,
}

impl Crossing {
    /// The position in pixel units, given the polygon's scale `2D`.
    pub fn x(self, scale: i128) -> Q {
        Q::new(self.numerator, self.denominator * scale)
    }

    fn cmp_position(&self, other: &Crossing) -> Ordering {
        // Both products are below 6R²·2R < 2^107.
        (self.numerator * other.denominator).cmp(&(other.numerator * self.denominator))
    }
}

/// A pair of crossings, left and right, and the pixel columns whose centres
/// lie between them (boundary included), clipped to the raster.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Span {
    /// The left crossing.
    pub left: Crossing,
    /// The right crossing.
    pub right: Crossing,
    /// The covered columns, or `None` when no centre lies within the pair or
    /// all of them lie outside the raster.
    pub columns: Option<(u32, u32)>,
}

/// Scaled height of scanline `row`: the pixel centres' `y = row + 1/2`,
/// i.e. `(2row + 1)·D` in scaled units.
pub fn scanline_y(row: u32, denominator: i128) -> i128 {
    (2 * i128::from(row) + 1) * denominator
}

/// The rows whose scanlines can meet the polygon, clipped to `limit`
/// (first and last row, inclusive):
/// those with `y_min ≤ row + 1/2 < y_max` (half-open), or
/// `y_min ≤ row + 1/2 ≤ y_max` (closed).
pub fn rows(points: &[[i128; 3]], denominator: i128, limit: (u32, u32), rule: RowRule) -> Option<RangeInclusive<u32>> {
    let y_min = points.iter().map(|p| p[1]).min()?;
    let y_max = points.iter().map(|p| p[1]).max()?;
    // (2r + 1)·D ≥ y_min  ⇔  r ≥ ⌈(y_min − D) / 2D⌉
    let first = ceil_div(y_min - denominator, 2 * denominator).max(i128::from(limit.0));
    let last = match rule {
        // (2r + 1)·D < y_max  ⇔  r < (y_max − D) / 2D  ⇔  r ≤ ⌈(y_max − D) / 2D⌉ − 1
        RowRule::HalfOpen => ceil_div(y_max - denominator, 2 * denominator) - 1,
        // (2r + 1)·D ≤ y_max  ⇔  r ≤ ⌊(y_max − D) / 2D⌋
        RowRule::Closed => floor_div(y_max - denominator, 2 * denominator).0,
    };
    let last = last.min(i128::from(limit.1));
    (first <= last).then_some(first as u32..=last as u32)
}

/// The crossings of the polygon's edges with the scanline at scaled height
/// `scan_y`, sorted left to right, written into `out`.
///
/// Rogers' half-interval convention ([`RowRule::HalfOpen`]): an edge crosses
/// when `min(y₁, y₂) ≤ y < max(y₁, y₂)`, so a vertex on the scanline counts
/// only for the edge whose lower end it is. With [`RowRule::Closed`] an edge
/// crosses when `min(y₁, y₂) ≤ y ≤ max(y₁, y₂)`. Horizontal edges never cross.
pub fn crossings(points: &[[i128; 3]], scan_y: i128, rule: RowRule, out: &mut Vec<Crossing>) {
    out.clear();
    let count = points.len();
    for i in 0..count {
        let [x1, y1, _] = points[i];
        let [x2, y2, _] = points[(i + 1) % count];
        let above = match rule {
            RowRule::HalfOpen => scan_y >= y1.max(y2),
            RowRule::Closed => scan_y > y1.max(y2),
        };
        if y1 == y2 || scan_y < y1.min(y2) || above {
            continue;
        }
        // x = x₁ + (x₂ − x₁)(y − y₁)/(y₂ − y₁), kept as one fraction.
        let (numerator, denominator) = (x1 * (y2 - y1) + (x2 - x1) * (scan_y - y1), y2 - y1);
        let (numerator, denominator) =
            if denominator < 0 { (-numerator, -denominator) } else { (numerator, denominator) };
        out.push(Crossing { numerator, denominator });
    }
    out.sort_unstable_by(Crossing::cmp_position);
}

/// One edge walked down the scanlines: its crossing numerator is stepped by a
/// constant per row (Bresenham-style), so no multiplication or division is
/// needed per row, and the result equals [`crossings`]' formula exactly.
#[derive(Debug, Clone, Copy)]
struct WalkedEdge {
    first_row: u32,
    last_row: u32,
    /// Crossing numerator at the next row to visit (over `denominator`).
    numerator: i128,
    /// Added per row: (x₂ − x₁)·2D.
    step: i128,
    denominator: i128,
}

/// The edges of one polygon, walked row by row in increasing order.
#[derive(Debug, Clone, Default)]
pub struct EdgeTable {
    edges: Vec<WalkedEdge>,
}

impl EdgeTable {
    /// Prepares the edges that cross any row of `rows` under `rule`.
    pub fn prepare(&mut self, points: &[[i128; 3]], denominator: i128, rows: &RangeInclusive<u32>, rule: RowRule) {
        self.edges.clear();
        let count = points.len();
        for i in 0..count {
            let (p, q) = (points[i], points[(i + 1) % count]);
            if p[1] == q[1] {
                continue;
            }
            let (low, high) = if p[1] < q[1] { (p, q) } else { (q, p) };
            // Rows whose scanline (2r + 1)·D lies in [y_low, y_high) (half-open) or [y_low, y_high] (closed).
            let first = ceil_div(low[1] - denominator, 2 * denominator).max(i128::from(*rows.start()));
            let last = match rule {
                RowRule::HalfOpen => ceil_div(high[1] - denominator, 2 * denominator) - 1,
                RowRule::Closed => floor_div(high[1] - denominator, 2 * denominator).0,
            }
            .min(i128::from(*rows.end()));
            if first > last {
                continue;
            }
            let den = high[1] - low[1];
            let scan_y = (2 * first + 1) * denominator;
            // x = x_low + (x_high − x_low)(y − y_low)/(y_high − y_low), as one fraction.
            let numerator = low[0] * den + (high[0] - low[0]) * (scan_y - low[1]);
            let step = (high[0] - low[0]) * 2 * denominator;
            self.edges.push(WalkedEdge {
                first_row: first as u32,
                last_row: last as u32,
                numerator,
                step,
                denominator: den,
            });
        }
    }

    /// The crossings on `row`, sorted; rows must be visited in increasing order.
    pub fn crossings(&mut self, row: u32, out: &mut Vec<Crossing>) {
        out.clear();
        for edge in &mut self.edges {
            if row < edge.first_row || row > edge.last_row {
                continue;
            }
            out.push(Crossing { numerator: edge.numerator, denominator: edge.denominator });
            edge.numerator += edge.step;
        }
        if out.len() == 2 {
            if out[0].cmp_position(&out[1]) == Ordering::Greater {
                out.swap(0, 1);
            }
        } else {
            out.sort_unstable_by(Crossing::cmp_position);
        }
    }
}

/// The columns a span covers, clipped to `limit` (first and last column, inclusive): with
/// [`ColumnRule::CentreInside`] those whose centres `x + 1/2` lie within
/// `[left, right]`, boundary included ("the pixel whose centre lies inside or
/// on the boundary"); with [`ColumnRule::CellHolds`] from `⌊left⌋` to `⌊right⌋`.
pub fn columns(
    left: Crossing,
    right: Crossing,
    denominator: i128,
    limit: (u32, u32),
    rule: ColumnRule,
) -> Option<(u32, u32)> {
    let (first, last) = match rule {
        ColumnRule::CentreInside => (
            // (2x + 1)·D ≥ n/d  ⇔  x ≥ ⌈(n − D·d) / 2D·d⌉
            ceil_div(left.numerator - denominator * left.denominator, 2 * denominator * left.denominator),
            // (2x + 1)·D ≤ n/d  ⇔  x ≤ ⌊(n − D·d) / 2D·d⌋
            floor_div(right.numerator - denominator * right.denominator, 2 * denominator * right.denominator).0,
        ),
        // x = n / (2D·d) in pixel units: the cell holding it is ⌊n / 2D·d⌋.
        ColumnRule::CellHolds => (
            floor_div(left.numerator, 2 * denominator * left.denominator).0,
            floor_div(right.numerator, 2 * denominator * right.denominator).0,
        ),
    };
    let first = first.max(i128::from(limit.0));
    let last = last.min(i128::from(limit.1));
    (first <= last).then_some((first as u32, last as u32))
}

/// Turns sorted crossings into spans: paired 1st–2nd, 3rd–4th, … with
/// [`RowRule::HalfOpen`] (an odd last crossing cannot happen for a closed
/// polygon and is ignored), or one span from the first to the last with
/// [`RowRule::Closed`].
pub fn spans(
    crossings: &[Crossing],
    denominator: i128,
    limit: (u32, u32),
    rules: (RowRule, ColumnRule),
    out: &mut Vec<Span>,
) {
    out.clear();
    let span = |left: Crossing, right: Crossing| Span {
        left,
        right,
        columns: columns(left, right, denominator, limit, rules.1),
    };
    match rules.0 {
        RowRule::HalfOpen => {
            let mut pairs = crossings.chunks_exact(2);
            for pair in &mut pairs {
                out.push(span(pair[0], pair[1]));
            }
        }
        RowRule::Closed => {
            if let (Some(first), Some(last)) = (crossings.first(), crossings.last()) {
                out.push(span(*first, *last));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Scaled points for integer vertices (D = 1, scale 2).
    fn scaled(points: &[[i128; 2]]) -> Vec<[i128; 3]> {
        points.iter().map(|p| [2 * p[0], 2 * p[1], 0]).collect()
    }

    fn crossing_xs(points: &[[i128; 3]], row: u32) -> Vec<Q> {
        let mut out = Vec::new();
        crossings(points, scanline_y(row, 1), RowRule::HalfOpen, &mut out);
        out.iter().map(|c| c.x(2)).collect()
    }

    #[test]
    fn vertex_on_scanline_counts_for_lower_edge_only() {
        // A diamond whose side vertices sit exactly on scanline y = 2.5.
        let points: Vec<[i128; 3]> = [[4, 1], [6, 5], [4, 9], [2, 5]].iter().map(|p| [p[0], p[1], 0]).collect();
        // In scaled units with D = 1 a point at y = 5 is y = 2.5.
        let mut out = Vec::new();
        crossings(&points, 5, RowRule::HalfOpen, &mut out);
        assert_eq!(out.len(), 2, "each side vertex counts once, for the edge it is the lower end of");
        assert_eq!(out.iter().map(|c| c.x(2)).collect::<Vec<_>>(), vec![Q::from_integer(1), Q::from_integer(3)]);
    }

    #[test]
    fn top_vertex_on_scanline_adds_no_crossing() {
        // Triangle with apex exactly at y = 2.5 (scaled 5): the apex is the upper end of both edges.
        let points: Vec<[i128; 3]> = [[0, 1], [8, 1], [4, 5]].iter().map(|p| [p[0], p[1], 0]).collect();
        let mut out = Vec::new();
        crossings(&points, 5, RowRule::HalfOpen, &mut out);
        assert!(out.is_empty());
        crossings(&points, 1, RowRule::HalfOpen, &mut out);
        assert_eq!(out.len(), 2, "the base's scanline counts the two edges whose lower end is on it");
    }

    #[test]
    fn horizontal_edges_never_cross() {
        let points = scaled(&[[0, 0], [4, 0], [4, 4], [0, 4]]);
        assert_eq!(crossing_xs(&points, 0), vec![Q::from_integer(0), Q::from_integer(4)]);
        assert!(crossing_xs(&points, 4).is_empty(), "row 4's scanline 4.5 is above the square");
    }

    #[test]
    fn centre_on_right_edge_is_covered() {
        // Span [0.5, 2.5] covers centres 0.5, 1.5 and 2.5: both boundaries included.
        let left = Crossing { numerator: 1, denominator: 1 };
        let right = Crossing { numerator: 5, denominator: 1 };
        assert_eq!(columns(left, right, 1, (0, 31), ColumnRule::CentreInside), Some((0, 2)));
    }

    #[test]
    fn span_between_centres_covers_nothing() {
        let left = Crossing { numerator: 6, denominator: 5 }; // 0.6
        let right = Crossing { numerator: 14, denominator: 5 }; // 1.4
        assert_eq!(columns(left, right, 1, (0, 31), ColumnRule::CentreInside), None);
    }

    #[test]
    fn span_shrinking_to_one_centre_covers_it() {
        let centre = Crossing { numerator: 3, denominator: 1 }; // 1.5
        assert_eq!(columns(centre, centre, 1, (0, 31), ColumnRule::CentreInside), Some((1, 1)));
    }

    #[test]
    fn spans_are_clipped_to_the_raster() {
        let left = Crossing { numerator: -20, denominator: 1 };
        let right = Crossing { numerator: 200, denominator: 1 };
        assert_eq!(columns(left, right, 1, (0, 31), ColumnRule::CentreInside), Some((0, 31)));
        let beyond = Crossing { numerator: 100, denominator: 1 };
        assert_eq!(columns(beyond, right, 1, (0, 31), ColumnRule::CentreInside), None);
    }

    #[test]
    fn walked_edges_give_the_formulas_crossings() {
        // A concave, self-crossing polygon with fractional vertices (scaled by 2D = 6).
        let points: Vec<[i128; 3]> =
            [[3, 1], [40, 7], [22, 25], [31, 45], [-4, 30], [9, 13]].iter().map(|p| [p[0], p[1], 0]).collect();
        for rule in [RowRule::HalfOpen, RowRule::Closed] {
            let rows = rows(&points, 3, (0, 31), rule).unwrap();
            let mut table = EdgeTable::default();
            table.prepare(&points, 3, &rows, rule);
            let (mut walked, mut direct) = (Vec::new(), Vec::new());
            for row in rows {
                table.crossings(row, &mut walked);
                crossings(&points, scanline_y(row, 3), rule, &mut direct);
                let as_q = |v: &[Crossing]| v.iter().map(|c| c.x(6)).collect::<Vec<_>>();
                assert_eq!(as_q(&walked), as_q(&direct), "row {row}, {rule:?}");
            }
        }
    }

    #[test]
    fn closed_rows_include_the_top_vertex_row() {
        // y from 5.5 to 6.5: the closed rule takes centres 5.5 and 6.5.
        let points: Vec<[i128; 3]> = [[0, 11], [4, 11], [4, 13]].iter().map(|p| [p[0], p[1], 0]).collect();
        assert_eq!(rows(&points, 1, (0, 31), RowRule::Closed), Some(5..=6));
        // The apex at y = 6.5 gives two equal crossings there.
        let mut out = Vec::new();
        crossings(&points, 13, RowRule::Closed, &mut out);
        assert_eq!(out.len(), 2);
        assert_eq!(out[0].x(2), out[1].x(2));
    }

    #[test]
    fn cell_rule_takes_the_cells_holding_the_crossings() {
        // Span 0.6 … 1.4: no centre inside, but the cells holding 0.6 and 1.4 are 0 and 1.
        let left = Crossing { numerator: 6, denominator: 5 };
        let right = Crossing { numerator: 14, denominator: 5 };
        assert_eq!(columns(left, right, 1, (0, 31), ColumnRule::CellHolds), Some((0, 1)));
        // A crossing exactly on a cell boundary (x = 2) belongs to the cell on its right.
        let on_line = Crossing { numerator: 4, denominator: 1 };
        assert_eq!(columns(on_line, on_line, 1, (0, 31), ColumnRule::CellHolds), Some((2, 2)));
    }

    #[test]
    fn rows_follow_the_half_open_rule() {
        // y from 5 to 25: centres 5.5 … 24.5, rows 5 … 24.
        let points = scaled(&[[10, 5], [10, 25], [25, 25], [25, 5]]);
        assert_eq!(rows(&points, 1, (0, 31), RowRule::HalfOpen), Some(5..=24));
        // y from 5.5 to 6.5: only the centre 5.5 lies in [5.5, 6.5).
        let points: Vec<[i128; 3]> = [[0, 11], [4, 11], [4, 13]].iter().map(|p| [p[0], p[1], 0]).collect();
        assert_eq!(rows(&points, 1, (0, 31), RowRule::HalfOpen), Some(5..=5));
        assert_eq!(rows(&points, 1, (0, 4), RowRule::HalfOpen), None);
    }
}
