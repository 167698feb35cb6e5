//! The big-integer tier's scan conversion: the crossings, spans and depths
//! of a [`BigPolygon`] (built and checked in the geometry layer), by the
//! same rules and in the same order as the word-sized scan converter.

use crate::geometry::big::{BigPolygon, Words, big, rule_index, sum_of_products};
use crate::geometry::equation::PlaneEquation;
use crate::raster::depth::{Depth, DepthStepper};
use crate::raster::scan::{self, Crossing, Span};
use crate::raster::sink::{PixelRect, RasterSink};
use crate::rules::{RowRule, Rules};

impl BigPolygon {
    /// The exact depth at the centre of pixel `(column, row)`:
    /// `−(A(2x + 1) + B(2y + 1) + 2D) / 2C`, within 128 bits near the
    /// polygon when [`BigPolygon::new`] found it so.
    pub(crate) fn depth_at_centre(&self, column: u32, row: u32) -> Depth {
        let (x, y) = (2 * i128::from(column) + 1, 2 * i128::from(row) + 1);
        if let Some(Words { plane: [a, b, c, d], .. }) = self.words
            && let Some(numerator) = sum_of_products(&[(a, x), (b, y), (d, 2)])
        {
            return Depth::from_fraction(-numerator, 2 * c);
        }
        let PlaneEquation { a, b, c, d } = &self.plane;
        Depth::from_big(-(a * big(x) + b * big(y) + d * 2u32), c * 2u32)
    }

    /// The rows the polygon's scanlines reach under `rule`, clipped to `limit`.
    fn rows(&self, rule: RowRule, limit: (u32, u32)) -> Option<std::ops::RangeInclusive<u32>> {
        let ranges = self.edges.iter().map(|e| e.rows[rule_index(rule)]).filter(|[f, l]| f <= l);
        let (first, last) = ranges.fold((i128::MAX, i128::MIN), |(f, l), [a, b]| (f.min(a), l.max(b)));
        let (first, last) = (first.max(limit.0.into()), last.min(limit.1.into()));
        (first <= last).then_some(first as u32..=last as u32)
    }

    /// The crossings with the scanline of row `row`, sorted left to right (as
    /// the word tiers compute them from the vertices).
    fn crossings(&self, row: u32, rule: RowRule, out: &mut Vec<Crossing>) {
        out.clear();
        let r = i128::from(row);
        for (index, edge) in self.edges.iter().enumerate() {
            let [first, last] = edge.rows[rule_index(rule)];
            if first <= r && r <= last {
                // αx = −(βy + γ) at y = (2r + 1)/2.
                out.push(match &self.words {
                    // Below 2^120 by `BigPolygon::words`.
                    Some(words) => {
                        let [alpha, beta, gamma] = words.lines[index];
                        let numerator = sum_of_products(&[(beta, 2 * r + 1), (gamma, 2)]);
                        Crossing::new(-numerator.expect("checked by BigPolygon::words"), 2 * alpha)
                    }
                    None => {
                        let [alpha, beta, gamma] = &edge.line;
                        Crossing::from_big(-(beta * big(2 * r + 1) + gamma * 2u32), alpha * 2u32)
                    }
                });
            }
        }
        out.sort_unstable_by(Crossing::cmp_position);
    }

    /// Draws the polygon: the same events, in the same order, as the
    /// word-sized rasterizer ([`crate::raster::convert::rasterize`]).
    pub(crate) fn rasterize<S: RasterSink>(
        &self,
        rules: Rules,
        rect: PixelRect,
        (found, spans): (&mut Vec<Crossing>, &mut Vec<Span>),
        sink: &mut S,
    ) {
        let Some(rows) = self.rows(rules.rows, rect.rows) else { return };
        for row in rows {
            self.crossings(row, rules.rows, found);
            spans.clear();
            spans.extend(scan::pairs(found.len(), rules.rows).map(|(i, j)| Span {
                left: found[i].clone(),
                right: found[j].clone(),
                columns: scan::columns(&found[i], &found[j], rect.columns, rules.columns),
            }));
            if S::OBSERVES_SCANLINES {
                sink.scanline(row, found, spans);
            }
            for span in spans.iter() {
                if let Some((first, last)) = span.columns {
                    self.span(row, first, last, sink);
                }
            }
        }
    }

    /// The pixels `first ..= last` of `row`, the depth stepped by the coursework's
    /// `z₁ = z − A/C` per column.
    fn span<S: RasterSink>(&self, row: u32, first: u32, last: u32, sink: &mut S) {
        // The numerator over |2C| falls by 2A·sign(C) per column, below 2^125 as
        // the depths at two columns of `BigPolygon::words`' range are.
        let start = |Words { plane: [a, _, c, _], .. }: &Words| {
            DepthStepper::from_depth(&self.depth_at_centre(first, row), -2 * a * c.signum())
        };
        if let Some(mut depth) = self.words.as_ref().and_then(start) {
            for x in first..=last {
                sink.pixel(x, row, depth.current());
                depth.advance();
            }
            return;
        }
        let PlaneEquation { a, b, c, d } = &self.plane;
        let (two_a, denominator) = (a * 2u32, c * 2u32);
        let mut numerator = -(a * big(2 * i128::from(first) + 1) + b * big(2 * i128::from(row) + 1) + d * 2u32);
        for x in first..=last {
            sink.pixel(x, row, Depth::from_big(numerator.clone(), denominator.clone()));
            numerator -= &two_a;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::plane::Geometry;
    use crate::numbers::Exact;
    use crate::numbers::Q;
    use crate::raster::convert::{Scratch, rasterize as draw};
    use num_bigint::BigInt;
    use num_traits::Signed;

    /// Every event as values: scanlines' crossings and spans, pixels' depths.
    #[derive(Default)]
    struct Values(Vec<String>);

    impl RasterSink for Values {
        fn scanline(&mut self, row: u32, crossings: &[Crossing], spans: &[Span]) {
            let xs: Vec<Exact> = crossings.iter().map(|c| c.x()).collect();
            let columns: Vec<_> = spans.iter().map(|s| s.columns).collect();
            self.0.push(format!("row {row}: {xs:?} {columns:?}"));
        }

        fn pixel(&mut self, x: u32, y: u32, depth: Depth) {
            self.0.push(format!("({x}, {y}) {}", depth.value()));
        }
    }

    /// BUET CSE 410's 2018 assignment maps a window 0.7 wide onto 500 pixels
    /// from 7-decimal input: the common denominator reaches 10^7 and the
    /// scaled coordinates pass 2^34. Such a triangle is drawn (on this tier),
    /// and every covered centre lies inside it, by an independent test in
    /// big rationals, with the plane's depth there.
    #[test]
    fn seven_decimal_input_beyond_the_word_range_is_drawn_exactly() {
        let d = |text: &str| crate::numbers::parse_number(text).unwrap();
        // Pixel units of a 500-px raster over a 0.7-wide window: 7 decimals times 500/0.7.
        let window = |v: &str| (d(v) + Q::new(35, 100)) * Q::new(5000, 7);
        let vertices: Vec<[Q; 3]> = [
            ["-0.2480390", "-0.1234567", "1.2345678"],
            ["0.3012345", "-0.2999999", "2.7654321"],
            ["0.0123457", "0.3301234", "1.9876543"],
        ]
        .iter()
        .map(|[x, y, z]| [window(x), window(y), d(z)])
        .collect();
        let geometry = Geometry::new(&vertices).expect("drawn, not refused");
        assert!(geometry.is_big(), "the scaled coordinates pass 2^34");
        let rect = PixelRect { columns: (0, 499), rows: (0, 499) };
        let mut sink = Values::default();
        draw(&geometry, Rules::default(), rect, &mut Scratch::default(), &mut sink);
        let pixels: Vec<&String> = sink.0.iter().filter(|e| e.starts_with('(')).collect();
        assert!(pixels.len() > 10_000, "{}", pixels.len());
        // Independent check on a sample of pixels: the centre is inside (edge functions in big
        // rationals, all of one sign) and the depth is the plane's.
        use num_rational::BigRational;
        let r = |q: Q| BigRational::new(BigInt::from(*q.numer()), BigInt::from(*q.denom()));
        let v: Vec<[BigRational; 3]> = vertices.iter().map(|p| p.map(r)).collect();
        for event in pixels.iter().step_by(997) {
            let (x, rest) = event[1..].split_once(", ").unwrap();
            let y: u32 = rest.split_once(')').unwrap().0.parse().unwrap();
            let x: u32 = x.parse().unwrap();
            let (cx, cy) = (r(Q::new(2 * i128::from(x) + 1, 2)), r(Q::new(2 * i128::from(y) + 1, 2)));
            let side = |i: usize| {
                let (a, b) = (&v[i], &v[(i + 1) % 3]);
                (&b[0] - &a[0]) * (&cy - &a[1]) - (&b[1] - &a[1]) * (&cx - &a[0])
            };
            let signs: Vec<bool> = (0..3).map(|i| side(i).is_positive()).collect();
            assert!(signs.iter().all(|s| *s == signs[0]), "({x}, {y}) lies inside");
            // z by the plane through the three vertices (Cramer on the barycentric weights).
            let det = (&v[1][0] - &v[0][0]) * (&v[2][1] - &v[0][1]) - (&v[2][0] - &v[0][0]) * (&v[1][1] - &v[0][1]);
            let w1 = ((&cx - &v[0][0]) * (&v[2][1] - &v[0][1]) - (&v[2][0] - &v[0][0]) * (&cy - &v[0][1])) / &det;
            let w2 = ((&v[1][0] - &v[0][0]) * (&cy - &v[0][1]) - (&cx - &v[0][0]) * (&v[1][1] - &v[0][1])) / &det;
            let z = &v[0][2] + w1 * (&v[1][2] - &v[0][2]) + w2 * (&v[2][2] - &v[0][2]);
            let expected = Exact::from(z);
            assert!(event.ends_with(&format!(" {expected}")), "{event}: expected {expected}");
        }
    }
}
