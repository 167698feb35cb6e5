//! Scan conversion: half-interval scanlines, edge crossings, spans and the
//! pixel-centre rule, all on a polygon's scaled integer coordinates (see
//! [`crate::geometry::plane`]).

use std::cmp::Ordering;
use std::hint::select_unpredictable;
use std::ops::RangeInclusive;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;

use crate::numbers::{Exact, Q, Word, ceil_div, cmp_fractions, floor_div};
use crate::rules::{ColumnRule, RowRule};

/// An x position in pixel units where a crossing falls on a scanline: what
/// every tier reports. As the fraction `numerator / denominator`
/// (`denominator > 0`, not necessarily reduced), both parts below 2^120 (the
/// word tiers: a numerator of at most `6R²` over `2R·2D`; the big-integer
/// tier: checked when the polygon is made, `crate::raster::big`), or a big rational
/// for an edge whose line outgrows those bounds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Crossing(CrossingValue);

#[derive(Debug, Clone, PartialEq, Eq)]
enum CrossingValue {
    Word { numerator: i128, denominator: i128 },
    Big(Box<BigRational>),
}

impl Crossing {
    /// The crossing at `numerator / denominator` (`denominator > 0`, both
    /// below 2^120).
    pub fn new(numerator: i128, denominator: i128) -> Crossing {
        debug_assert!(denominator > 0, "a crossing's denominator is positive");
        Crossing(CrossingValue::Word { numerator, denominator })
    }

    /// The crossing at `numerator / denominator` in big integers
    /// (`denominator > 0`), held in 128 bits when both fit the bounds
    /// above, else kept as it is (reduced only when reported: a gcd per
    /// crossing would cost more than the crossing).
    pub fn from_big(numerator: BigInt, denominator: BigInt) -> Crossing {
        let small = |v: &BigInt| v.to_i128().filter(|v| v.unsigned_abs() < 1 << 120);
        match (small(&numerator), small(&denominator)) {
            (Some(n), Some(d)) => Crossing::new(n, d),
            _ => Crossing(CrossingValue::Big(Box::new(BigRational::new_raw(numerator, denominator)))),
        }
    }

    /// The position in pixel units, reduced.
    pub fn x(&self) -> Exact {
        match &self.0 {
            CrossingValue::Word { numerator, denominator } => Exact::Word(Q::new(*numerator, *denominator)),
            CrossingValue::Big(big) => Exact::from(big.reduced()),
        }
    }

    /// The position as a big rational, not reduced.
    fn to_big(&self) -> BigRational {
        match &self.0 {
            CrossingValue::Word { numerator, denominator } => {
                BigRational::new_raw(BigInt::from(*numerator), BigInt::from(*denominator))
            }
            CrossingValue::Big(big) => (**big).clone(),
        }
    }

    /// Compares two positions without overflow.
    pub fn cmp_position(&self, other: &Crossing) -> Ordering {
        match (&self.0, &other.0) {
            (
                CrossingValue::Word { numerator, denominator },
                CrossingValue::Word { numerator: other_numerator, denominator: other_denominator },
            ) => cmp_fractions(*numerator, *denominator, *other_numerator, *other_denominator),
            _ => self.to_big().cmp(&other.to_big()),
        }
    }
}

/// A pair of crossings, left and right, and the pixel columns whose centres
/// lie between them (boundary included), clipped to the raster.
#[derive(Debug, Clone, PartialEq, Eq)]
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

/// The first row whose scanline an edge or polygon whose lower end is at
/// scaled height `y` reaches: `(2r + 1)·D ≥ y  ⇔  r ≥ ⌈(y − D) / 2D⌉`, or
/// strictly above it, `r ≥ ⌊(y − D) / 2D⌋ + 1` ([`RowRule::TopLeft`]).
#[cfg(test)]
#[inline]
fn first_row_from<W: Word>(y: W, denominator: W, rule: RowRule) -> W {
    match rule {
        RowRule::TopLeft => (y - denominator).floor_div(denominator + denominator).0 + W::ONE,
        RowRule::HalfOpen | RowRule::Closed => (y - denominator).ceil_div(denominator + denominator),
    }
}

/// The last row whose scanline an edge or polygon whose upper end is at
/// scaled height `y` reaches: `(2r + 1)·D < y` ([`RowRule::HalfOpen`]) or
/// `≤ y` ([`RowRule::Closed`], [`RowRule::TopLeft`]).
#[cfg(test)]
#[inline]
fn last_row_to<W: Word>(y: W, denominator: W, rule: RowRule) -> W {
    match rule {
        // r < (y − D) / 2D  ⇔  r ≤ ⌈(y − D) / 2D⌉ − 1
        RowRule::HalfOpen => (y - denominator).ceil_div(denominator + denominator) - W::ONE,
        // r ≤ ⌊(y − D) / 2D⌋
        RowRule::Closed | RowRule::TopLeft => (y - denominator).floor_div(denominator + denominator).0,
    }
}

/// The rows `first ..= last` clipped to `limit`, or `None` when empty.
#[inline]
fn clip_rows<W: Word>(first: W, last: W, limit: (u32, u32)) -> Option<RangeInclusive<u32>> {
    let first = first.max(W::narrow(i128::from(limit.0)));
    let last = last.min(W::narrow(i128::from(limit.1)));
    (first <= last).then(|| first.wide() as u32..=last.wide() as u32)
}

/// The rows whose scanlines can meet the polygon, clipped to `limit`
/// (first and last row, inclusive):
/// those with `y_min ≤ row + 1/2 < y_max` (half-open),
/// `y_min ≤ row + 1/2 ≤ y_max` (closed), or `y_min < row + 1/2 ≤ y_max` (top-left).
#[cfg(test)]
pub fn rows(points: &[[i128; 3]], denominator: i128, limit: (u32, u32), rule: RowRule) -> Option<RangeInclusive<u32>> {
    let y_min = points.iter().map(|p| p[1]).min()?;
    let y_max = points.iter().map(|p| p[1]).max()?;
    clip_rows(first_row_from(y_min, denominator, rule), last_row_to(y_max, denominator, rule), limit)
}

/// The crossings of the polygon's edges (scaled `points`, scale `2D`) with
/// the scanline at scaled height `scan_y`, sorted left to right, written into
/// `out`.
///
/// Rogers' half-interval convention ([`RowRule::HalfOpen`]): an edge crosses
/// when `min(y₁, y₂) ≤ y < max(y₁, y₂)`, so a vertex on the scanline counts
/// only for the edge whose lower end it is. With [`RowRule::Closed`] an edge
/// crosses when `min(y₁, y₂) ≤ y ≤ max(y₁, y₂)`, with [`RowRule::TopLeft`]
/// when `min(y₁, y₂) < y ≤ max(y₁, y₂)` (a vertex counts for the edge whose
/// upper end it is). Horizontal edges never cross.
///
/// Computed by the formula on the polygon's word-sized scaled coordinates
/// (within [`crate::geometry::plane::MAX_SCALED`]): the independent reference the edge
/// walker ([`EdgeTable`]) is tested against.
#[cfg(test)]
pub fn crossings(points: &[[i128; 3]], scan_y: i128, scale: i128, rule: RowRule, out: &mut Vec<Crossing>) {
    out.clear();
    let count = points.len();
    for i in 0..count {
        let [x1, y1, _] = points[i];
        let [x2, y2, _] = points[(i + 1) % count];
        let (below, above) = match rule {
            RowRule::HalfOpen => (scan_y < y1.min(y2), scan_y >= y1.max(y2)),
            RowRule::Closed => (scan_y < y1.min(y2), scan_y > y1.max(y2)),
            RowRule::TopLeft => (scan_y <= y1.min(y2), scan_y > y1.max(y2)),
        };
        if y1 == y2 || below || above {
            continue;
        }
        // x = x₁ + (x₂ − x₁)(y − y₁)/(y₂ − y₁), kept as one fraction.
        let (numerator, denominator) = (x1 * (y2 - y1) + (x2 - x1) * (scan_y - y1), y2 - y1);
        let (numerator, denominator) =
            if denominator < 0 { (-numerator, -denominator) } else { (numerator, denominator) };
        out.push(Crossing::new(numerator, denominator * scale));
    }
    out.sort_unstable_by(Crossing::cmp_position);
}

/// One edge walked down the scanlines. Its crossing `numerator / denominator`
/// and the column bound `(numerator − offset·denominator) / modulus`, kept as
/// whole part and remainder, are both stepped by a constant per row
/// (Bresenham-style): no multiplication or division per row, and the results
/// equal the formulas `crossings` (in the tests) and [`columns`] exactly.
#[derive(Debug, Clone, Copy)]
pub struct WalkedEdge<W> {
    first_row: u32,
    last_row: u32,
    /// Crossing numerator at the next row to visit (over `denominator`).
    numerator: W,
    /// Added per row: (x₂ − x₁)·2D.
    step: W,
    denominator: W,
    /// ⌊(numerator − offset·denominator) / modulus⌋ and its remainder, where
    /// `modulus = 2D·denominator` and `offset` is `D` for
    /// [`ColumnRule::CentreInside`] (centres sit at `(2x + 1)·D`), 0 for
    /// [`ColumnRule::CellHolds`].
    column: W,
    column_remainder: W,
    modulus: W,
    /// `step / modulus` as whole part and remainder.
    column_step: W,
    column_step_remainder: W,
}

/// A crossing found by the [`EdgeTable`] on one row, with the columns it
/// bounds: a span starting at this crossing covers from `first_column`, a
/// span ending at it covers up to `last_column`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RowCrossing<W> {
    /// Numerator of the crossing's x, in scaled units.
    pub numerator: W,
    /// Its positive denominator.
    pub denominator: W,
    /// The first column on or after the crossing ([`ColumnRule::CentreInside`]:
    /// the first centre at or right of it; [`ColumnRule::CellHolds`]: the cell holding it).
    pub first_column: W,
    /// The last column on or before it (the last centre at or left of it, or the cell holding it).
    pub last_column: W,
}

impl<W: Word> RowCrossing<W> {
    /// The crossing as reported to observers, in pixel units (the polygon's
    /// scale is `2D`): below `6R²` over `2R·2D`.
    pub fn crossing(&self, scale: i128) -> Crossing {
        Crossing::new(self.numerator.wide(), self.denominator.wide() * scale)
    }

    /// Compares the positions of two crossings on the same row.
    #[inline]
    pub fn cmp_position(&self, other: &Self) -> Ordering {
        // Below 6R²·2R < 2^107 in i128, below 2^61 in i64 (Geometry::fits_i64).
        (self.numerator * other.denominator).cmp(&(other.numerator * self.denominator))
    }
}

/// The edges of one polygon, walked row by row in increasing order, in the
/// machine integers `W` (see [`Word`]).
#[derive(Debug, Clone, Default)]
pub struct EdgeTable<W> {
    edges: Vec<WalkedEdge<W>>,
    points: Vec<ScaledVertex<W>>,
    /// Indices of the edges crossing the current row.
    active: Vec<usize>,
    /// The first row at which `active` must be rebuilt.
    next_change: u32,
}

/// A vertex's scaled x and y, and the rows an edge starting (`from`) or
/// ending (`to`) there reaches (as `first_row_from` and `last_row_to` do).
#[derive(Debug, Clone, Copy)]
struct ScaledVertex<W> {
    x: W,
    y: W,
    from: W,
    to: W,
}

impl<W: Word> EdgeTable<W> {
    /// Prepares the edges of the polygon with scaled `points` that cross any
    /// row of `limit` under `rules`; returns the rows to visit (as the formula `rows` in the tests).
    pub fn prepare(
        &mut self,
        points: &[[i128; 3]],
        denominator: i128,
        limit: (u32, u32),
        rules: (RowRule, ColumnRule),
    ) -> Option<RangeInclusive<u32>> {
        self.edges.clear();
        self.points.clear();
        self.next_change = 0;
        let d = W::narrow(denominator);
        let two_d = d + d;
        // Per vertex, once: the first row at or above it and the last row below
        // (or at) it, from one division (a shift when 2D is a power of two, as
        // for integer and binary-fraction vertices).
        let shift = denominator.trailing_zeros() + 1;
        let power_of_two = denominator == 1 << (shift - 1);
        self.points.extend(points.iter().map(|p| {
            let y = W::narrow(p[1]);
            let (whole, remainder) =
                if power_of_two { (y - d).floor_div_pow2(shift) } else { (y - d).floor_div(two_d) };
            let (from, to) = match rules.0 {
                RowRule::HalfOpen => {
                    let from = select_unpredictable(remainder == W::ZERO, whole, whole + W::ONE);
                    (from, from - W::ONE)
                }
                RowRule::Closed => (select_unpredictable(remainder == W::ZERO, whole, whole + W::ONE), whole),
                // A centre exactly at a vertex belongs to the edge below it, never above.
                RowRule::TopLeft => (whole + W::ONE, whole),
            };
            ScaledVertex { x: W::narrow(p[0]), y, from, to }
        }));
        let first_vertex = *self.points.first()?;
        let (mut first, mut last) = (first_vertex.from, first_vertex.to);
        for p in &self.points {
            (first, last) = (first.min(p.from), last.max(p.to));
        }
        let rows = clip_rows(first, last, limit)?;
        let (row_first, row_last) = (W::narrow(i128::from(*rows.start())), W::narrow(i128::from(*rows.end())));
        let offset = match rules.1 {
            ColumnRule::CentreInside | ColumnRule::HalfOpen => d,
            ColumnRule::CellHolds => W::ZERO,
        };
        let mut previous = self.points[self.points.len() - 1];
        for &vertex in &self.points {
            let (p, q) = (previous, vertex);
            previous = vertex;
            if p.y == q.y {
                continue;
            }
            let rising = p.y < q.y;
            let (low, high) = (select_unpredictable(rising, p, q), select_unpredictable(rising, q, p));
            let (first, last) = (low.from.max(row_first), high.to.min(row_last));
            if first > last {
                continue;
            }
            let den = high.y - low.y;
            let scan_y = (first + first + W::ONE) * d;
            // x = x_low + (x_high − x_low)(y − y_low)/(y_high − y_low), as one fraction.
            let numerator = low.x * den + (high.x - low.x) * (scan_y - low.y);
            let step = (high.x - low.x) * two_d;
            let modulus = two_d * den;
            let (column, column_remainder) = (numerator - offset * den).floor_div(modulus);
            // step / modulus = (x_high − x_low) / den.
            let (column_step, remainder) = (high.x - low.x).floor_div(den);
            self.edges.push(WalkedEdge {
                first_row: first.wide() as u32,
                last_row: last.wide() as u32,
                numerator,
                step,
                denominator: den,
                column,
                column_remainder,
                modulus,
                column_step,
                column_step_remainder: remainder * two_d,
            });
        }
        Some(rows)
    }

    /// The crossings on `row`, sorted left to right, with the columns they
    /// bound under `rule`; rows must be visited in increasing order, starting
    /// at or after the first row [`EdgeTable::prepare`] returned.
    #[inline]
    pub fn crossings(&mut self, row: u32, rule: ColumnRule, out: &mut Vec<RowCrossing<W>>) {
        if row >= self.next_change {
            self.activate(row);
        }
        out.clear();
        for &index in &self.active {
            let edge = &mut self.edges[index];
            out.push(edge.crossing(rule));
            edge.advance();
        }
        // The active edges were sorted when they became active, so this finds
        // them in order unless two of them cross between vertices.
        if out.len() == 2 {
            if out[0].cmp_position(&out[1]) == Ordering::Greater {
                out.swap(0, 1);
            }
        } else {
            out.sort_unstable_by(RowCrossing::cmp_position);
        }
    }

    /// Makes the edges that cross `row` the active ones, in order of their
    /// crossings there, and returns the last row before an edge starts or
    /// ends: rows up to it step only these edges, with no test per edge and
    /// row. [`EdgeTable::crossings`] calls it when needed.
    pub fn activate(&mut self, row: u32) -> u32 {
        // Without branches: which edges start or end where comes as it comes.
        self.active.clear();
        self.active.resize(self.edges.len(), 0);
        self.next_change = u32::MAX;
        let mut count = 0;
        for (index, edge) in self.edges.iter().enumerate() {
            let (ahead, crossing) = (row < edge.first_row, edge.first_row <= row && row <= edge.last_row);
            let change = select_unpredictable(ahead, edge.first_row, edge.last_row.saturating_add(1));
            self.next_change = self.next_change.min(select_unpredictable(ahead || crossing, change, u32::MAX));
            self.active[count] = index;
            count += usize::from(crossing);
        }
        self.active.truncate(count);
        // In order of their crossings on this row (numerator over denominator).
        let edges = &self.edges;
        let order = |i: &usize, j: &usize| edges[*i].position().cmp_position(&edges[*j].position());
        if let [first, second] = self.active[..] {
            // Which comes first is a toss-up per polygon: chosen without a branch.
            let swap = order(&first, &second) == Ordering::Greater;
            self.active[0] = select_unpredictable(swap, second, first);
            self.active[1] = select_unpredictable(swap, first, second);
        } else {
            self.active.sort_unstable_by(order);
        }
        self.next_change - 1
    }

    /// The active edges, left then right, when there are exactly two (every
    /// row of a triangle or a convex polygon), for the caller to walk row by
    /// row.
    #[inline]
    pub fn pair(&mut self) -> Option<[&mut WalkedEdge<W>; 2]> {
        match self.active[..] {
            [left, right] => self.edges.get_disjoint_mut([left, right]).ok(),
            _ => None,
        }
    }
}

impl<W: Word> WalkedEdge<W> {
    /// The crossing on the current row, with the columns it bounds under `rule`.
    #[inline]
    pub fn crossing(&self, rule: ColumnRule) -> RowCrossing<W> {
        let on_centre = self.column_remainder == W::ZERO;
        let on_centre_or_cell = match rule {
            ColumnRule::CentreInside | ColumnRule::HalfOpen => on_centre,
            ColumnRule::CellHolds => true,
        };
        // Half-open spans [x_l, x_r) leave out a centre exactly on their right end.
        let right_open = rule == ColumnRule::HalfOpen && on_centre;
        RowCrossing {
            numerator: self.numerator,
            denominator: self.denominator,
            first_column: select_unpredictable(on_centre_or_cell, self.column, self.column + W::ONE),
            last_column: select_unpredictable(right_open, self.column - W::ONE, self.column),
        }
    }

    /// The crossing's position alone, for ordering.
    fn position(&self) -> RowCrossing<W> {
        RowCrossing { numerator: self.numerator, denominator: self.denominator, ..RowCrossing::default() }
    }

    /// Steps to the next row: the crossing and the column bound by their
    /// constant increments.
    #[inline]
    pub fn advance(&mut self) {
        self.numerator += self.step;
        self.column += self.column_step;
        self.column_remainder += self.column_step_remainder;
        // The carry comes as often as not: chosen without a branch.
        let carry = self.column_remainder >= self.modulus;
        self.column_remainder -= select_unpredictable(carry, self.modulus, W::ZERO);
        self.column += select_unpredictable(carry, W::ONE, W::ZERO);
    }
}

/// Which sorted crossings pair into spans, as index pairs: 1st–2nd, 3rd–4th,
/// … with [`RowRule::HalfOpen`] and [`RowRule::TopLeft`] (an odd last
/// crossing cannot happen for a closed polygon and is ignored), or the first
/// with the last with [`RowRule::Closed`].
#[inline]
pub fn pairs(count: usize, rule: RowRule) -> impl Iterator<Item = (usize, usize)> + Clone {
    let pairs = match rule {
        RowRule::HalfOpen | RowRule::TopLeft => count / 2,
        RowRule::Closed => count.min(1),
    };
    (0..pairs).map(move |k| match rule {
        RowRule::HalfOpen | RowRule::TopLeft => (2 * k, 2 * k + 1),
        RowRule::Closed => (0, count - 1),
    })
}

/// The columns `first ..= last` clipped to `limit`, or `None` when empty.
#[inline]
pub fn clip_columns<W: Word>(first: W, last: W, limit: (u32, u32)) -> Option<(u32, u32)> {
    let first = first.max(W::narrow(i128::from(limit.0)));
    let last = last.min(W::narrow(i128::from(limit.1)));
    (first <= last).then(|| (first.wide() as u32, last.wide() as u32))
}

/// The columns a span covers, clipped to `limit` (first and last column, inclusive): with
/// [`ColumnRule::CentreInside`] those whose centres `x + 1/2` lie within
/// `[left, right]`, boundary included ("the pixel whose centre lies inside or
/// on the boundary"); with [`ColumnRule::HalfOpen`] those within
/// `[left, right)`; with [`ColumnRule::CellHolds`] from `⌊left⌋` to `⌊right⌋`.
pub fn columns(left: &Crossing, right: &Crossing, limit: (u32, u32), rule: ColumnRule) -> Option<(u32, u32)> {
    let (
        CrossingValue::Word { numerator: left_numerator, denominator: left_denominator },
        CrossingValue::Word { numerator: right_numerator, denominator: right_denominator },
    ) = (&left.0, &right.0)
    else {
        return big_columns(left.to_big(), right.to_big(), limit, rule);
    };
    let (left, right) = ((*left_numerator, *left_denominator), (*right_numerator, *right_denominator));
    // The centre x + 1/2 against n/d: 2x + 1 ≥ 2n/d  ⇔  x ≥ (2n − d)/2d (both below 2^122).
    let centred = |(n, d): (i128, i128)| (2 * n - d, 2 * d);
    let (first, last) = match rule {
        ColumnRule::CentreInside => (
            ceil_div(centred(left).0, centred(left).1),
            // 2x + 1 ≤ 2n/d  ⇔  x ≤ ⌊(2n − d)/2d⌋
            floor_div(centred(right).0, centred(right).1).0,
        ),
        ColumnRule::HalfOpen => (
            ceil_div(centred(left).0, centred(left).1),
            // 2x + 1 < 2n/d  ⇔  x ≤ ⌈(2n − d)/2d⌉ − 1
            ceil_div(centred(right).0, centred(right).1) - 1,
        ),
        // The cell holding x = n/d is ⌊n/d⌋.
        ColumnRule::CellHolds => (floor_div(left.0, left.1).0, floor_div(right.0, right.1).0),
    };
    clip_columns(first, last, limit)
}

/// [`columns`] for crossings beyond 128 bits, by the same rules in big
/// rationals; the bounds, clamped just outside the range of `u32`, are then
/// clipped as [`columns`] clips them.
fn big_columns(left: BigRational, right: BigRational, limit: (u32, u32), rule: ColumnRule) -> Option<(u32, u32)> {
    let half = BigRational::new(BigInt::from(1), BigInt::from(2));
    let (first, last) = match rule {
        ColumnRule::CentreInside => ((left - &half).ceil(), (right - &half).floor()),
        ColumnRule::HalfOpen => ((left - &half).ceil(), (right - &half).ceil() - BigInt::from(1)),
        ColumnRule::CellHolds => (left.floor(), right.floor()),
    };
    let clamp = |v: BigRational| {
        v.to_integer().clamp(BigInt::from(-1), BigInt::from(u64::from(u32::MAX) + 1)).to_i128().expect("clamped")
    };
    clip_columns(clamp(first), clamp(last), limit)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Scaled points for integer vertices (D = 1, scale 2).
    fn scaled(points: &[[i128; 2]]) -> Vec<[i128; 3]> {
        points.iter().map(|p| [2 * p[0], 2 * p[1], 0]).collect()
    }

    fn crossing_xs(points: &[[i128; 3]], row: u32) -> Vec<Exact> {
        let mut out = Vec::new();
        crossings(points, scanline_y(row, 1), 2, RowRule::HalfOpen, &mut out);
        out.iter().map(|c| c.x()).collect()
    }

    #[test]
    fn vertex_on_scanline_counts_for_lower_edge_only() {
        // A diamond whose side vertices sit exactly on scanline y = 2.5.
        let points: Vec<[i128; 3]> = [[4, 1], [6, 5], [4, 9], [2, 5]].iter().map(|p| [p[0], p[1], 0]).collect();
        // In scaled units with D = 1 a point at y = 5 is y = 2.5.
        let mut out = Vec::new();
        crossings(&points, 5, 2, RowRule::HalfOpen, &mut out);
        assert_eq!(out.len(), 2, "each side vertex counts once, for the edge it is the lower end of");
        assert_eq!(out.iter().map(|c| c.x()).collect::<Vec<_>>(), vec![Q::from_integer(1), Q::from_integer(3)]);
    }

    #[test]
    fn top_vertex_on_scanline_adds_no_crossing() {
        // Triangle with apex exactly at y = 2.5 (scaled 5): the apex is the upper end of both edges.
        let points: Vec<[i128; 3]> = [[0, 1], [8, 1], [4, 5]].iter().map(|p| [p[0], p[1], 0]).collect();
        let mut out = Vec::new();
        crossings(&points, 5, 2, RowRule::HalfOpen, &mut out);
        assert!(out.is_empty());
        crossings(&points, 1, 2, RowRule::HalfOpen, &mut out);
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
        let left = Crossing::new(1, 2);
        let right = Crossing::new(5, 2);
        assert_eq!(columns(&left, &right, (0, 31), ColumnRule::CentreInside), Some((0, 2)));
    }

    #[test]
    fn span_between_centres_covers_nothing() {
        let left = Crossing::new(6, 10); // 0.6
        let right = Crossing::new(14, 10); // 1.4
        assert_eq!(columns(&left, &right, (0, 31), ColumnRule::CentreInside), None);
    }

    #[test]
    fn span_shrinking_to_one_centre_covers_it() {
        let centre = Crossing::new(3, 2); // 1.5
        assert_eq!(columns(&centre, &centre, (0, 31), ColumnRule::CentreInside), Some((1, 1)));
    }

    #[test]
    fn spans_are_clipped_to_the_raster() {
        let left = Crossing::new(-20, 2);
        let right = Crossing::new(200, 2);
        assert_eq!(columns(&left, &right, (0, 31), ColumnRule::CentreInside), Some((0, 31)));
        let beyond = Crossing::new(100, 2);
        assert_eq!(columns(&beyond, &right, (0, 31), ColumnRule::CentreInside), None);
    }

    /// The walker's crossings and column bounds, in both machine words, equal
    /// the formulas ([`crossings`], [`columns`]) on every row and every rule.
    fn check_walker<W: Word>(points: &[[i128; 3]], denominator: i128, limit: (u32, u32)) {
        for row_rule in [RowRule::HalfOpen, RowRule::Closed, RowRule::TopLeft] {
            for column_rule in [ColumnRule::CentreInside, ColumnRule::CellHolds, ColumnRule::HalfOpen] {
                let mut table = EdgeTable::<W>::default();
                let prepared = table.prepare(points, denominator, limit, (row_rule, column_rule));
                assert_eq!(prepared, rows(points, denominator, limit, row_rule));
                let (mut walked, mut direct) = (Vec::new(), Vec::new());
                for row in prepared.into_iter().flatten() {
                    table.crossings(row, column_rule, &mut walked);
                    let scale = 2 * denominator;
                    crossings(points, scanline_y(row, denominator), scale, row_rule, &mut direct);
                    let as_q = |v: &[Crossing]| v.iter().map(|c| c.x()).collect::<Vec<_>>();
                    let walked_crossings: Vec<Crossing> = walked.iter().map(|c| c.crossing(scale)).collect();
                    assert_eq!(as_q(&walked_crossings), as_q(&direct), "row {row}, {row_rule:?}");
                    let by_walker: Vec<_> = pairs(walked.len(), row_rule)
                        .map(|(i, j)| clip_columns(walked[i].first_column, walked[j].last_column, (0, 31)))
                        .collect();
                    let by_formula: Vec<_> = pairs(direct.len(), row_rule)
                        .map(|(i, j)| columns(&direct[i], &direct[j], (0, 31), column_rule))
                        .collect();
                    assert_eq!(by_walker, by_formula, "row {row}, {row_rule:?}, {column_rule:?}");
                }
            }
        }
    }

    #[test]
    fn walked_edges_give_the_formulas_crossings_and_columns() {
        // A concave, self-crossing polygon with fractional vertices (scaled by 2D = 6).
        let points: Vec<[i128; 3]> =
            [[3, 1], [40, 7], [22, 25], [31, 45], [-4, 30], [9, 13]].iter().map(|p| [p[0], p[1], 0]).collect();
        for limit in [(0, 31), (3, 5)] {
            check_walker::<i64>(&points, 3, limit);
            check_walker::<i128>(&points, 3, limit);
        }
        // Vertices on centres and on half-pixel lines (D = 1): crossings land exactly on centres.
        let on_lines = scaled(&[[1, 0], [9, 4], [5, 12], [0, 7]]);
        check_walker::<i64>(&on_lines, 1, (0, 31));
        check_walker::<i128>(&on_lines, 1, (0, 31));
        let half: Vec<[i128; 3]> = [[1, 1], [19, 9], [3, 25]].iter().map(|p| [p[0], p[1], 0]).collect();
        check_walker::<i64>(&half, 1, (0, 31));
    }

    #[test]
    fn closed_rows_include_the_top_vertex_row() {
        // y from 5.5 to 6.5: the closed rule takes centres 5.5 and 6.5.
        let points: Vec<[i128; 3]> = [[0, 11], [4, 11], [4, 13]].iter().map(|p| [p[0], p[1], 0]).collect();
        assert_eq!(rows(&points, 1, (0, 31), RowRule::Closed), Some(5..=6));
        // The apex at y = 6.5 gives two equal crossings there.
        let mut out = Vec::new();
        crossings(&points, 13, 2, RowRule::Closed, &mut out);
        assert_eq!(out.len(), 2);
        assert_eq!(out[0].x(), out[1].x());
    }

    #[test]
    fn cell_rule_takes_the_cells_holding_the_crossings() {
        // Span 0.6 … 1.4: no centre inside, but the cells holding 0.6 and 1.4 are 0 and 1.
        let left = Crossing::new(6, 10);
        let right = Crossing::new(14, 10);
        assert_eq!(columns(&left, &right, (0, 31), ColumnRule::CellHolds), Some((0, 1)));
        // A crossing exactly on a cell boundary (x = 2) belongs to the cell on its right.
        let on_line = Crossing::new(4, 2);
        assert_eq!(columns(&on_line, &on_line, (0, 31), ColumnRule::CellHolds), Some((2, 2)));
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
