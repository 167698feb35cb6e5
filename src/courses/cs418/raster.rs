//! The course's pipeline, written once over a number type ([`Scalar`]) and
//! run in `f64` (the course's arithmetic) or in exact rationals.

use std::collections::BTreeMap;

use num_rational::BigRational;

use super::clip::{Dda, clip, clockwise};
use super::compare::{Comparison, Primitive, SampleGrid, SampleSpan};
use super::image::{Image, byte, linear_texels, to_srgb};
use super::scalar::{Scalar, Vertex};
use super::{Cs418Error, Cs418Problem, FileCommand, RastFile, error};

/// The arithmetic the course's algorithm runs in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arithmetic {
    /// The course's own: every number read as the nearest `f64`, the viewport
    /// computed as `(x/w + 1)·W/2`, and each DDA started at `a + (⌈a_d⌉ − a_d)·s`
    /// and stepped by adding `s`, all in `f64`, as its reference images were made.
    DdaF64,
    /// The same algorithm on exact rationals: the numbers as written, every
    /// step exact, so each sample is inside or outside as the geometry says.
    Exact,
}

impl Arithmetic {
    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Arithmetic::DdaF64 => "dda-f64",
            Arithmetic::Exact => "exact",
        }
    }
}

/// How many image sizes away from the image a vertex may land (see
/// `within_reach`).
pub(super) const REACH: f64 = 1000.0;

/// Components of a vertex as the pipeline carries it. In clip space:
/// x, y, z, w, then the attributes r, g, b, a, s, t. On screen: x', y', z/w,
/// 1/w, then the attributes (divided by w under `hyp`, recovered by dividing
/// by the interpolated 1/w).
const COMPONENTS: usize = 4 + ATTRIBUTES;
/// Colour (r, g, b, a) and texture coordinates (s, t).
const ATTRIBUTES: usize = 6;
/// How many texels further on a negative texture coordinate's texel lies
/// than wrapping alone puts it: what the course's `textures` reference shows
/// (see the module docs).
const NEGATIVE_SHIFT: i64 = 5;

/// A fragment's colour and (s, t).
enum Attributes<S> {
    /// In the run's arithmetic.
    Values([S; ATTRIBUTES]),
    /// At a sample where the interpolated 1/w is exactly 0 (a triangle
    /// through infinity, drawn with `hyp` but without `frustum`): each value
    /// divided by 0 as the course's floats do it, giving infinities and NaN.
    AtInfinity([f64; ATTRIBUTES]),
}

/// Runs a case in an arithmetic.
pub fn render(case: &RastFile, arithmetic: Arithmetic) -> Result<Comparison, Cs418Error> {
    match arithmetic {
        Arithmetic::DdaF64 => Pipeline::<f64>::run(case, arithmetic),
        Arithmetic::Exact => Pipeline::<BigRational>::run(case, arithmetic),
    }
}

/// What a case draws, after clipping and culling, in exact arithmetic,
/// without sampling it: its primitives and their shapes (for `zsim cs418
/// import`, which leaves the sampling to zsim's rasterizer).
pub fn shapes(case: &RastFile) -> Result<(Vec<Primitive>, Vec<SampleGrid>), Cs418Error> {
    let pipeline = Pipeline::<BigRational>::new(case, false).draw()?;
    Ok((pipeline.primitives, pipeline.shapes))
}

struct Pipeline<'a, S> {
    case: &'a RastFile,
    /// Whether triangles and points are sampled, or only clipped, culled and
    /// kept as shapes.
    sample: bool,
    level: u32,
    width: usize,
    height: usize,
    colour: Vec<[f64; 4]>,
    depth: Vec<S>,
    owners: Vec<u32>,
    primitives: Vec<Primitive>,
    spans: BTreeMap<(u32, i64), Vec<SampleSpan>>,
    shapes: Vec<SampleGrid>,
    positions: Vec<[S; 4]>,
    colours: Vec<[S; 4]>,
    texcoords: Vec<[S; 2]>,
    /// Each of the case's textures as linear RGBA, row by row from the top.
    textures: Vec<Texels>,
    /// The texture bound (index into the case's textures).
    texture: Option<usize>,
    elements: Vec<usize>,
    sizes: Vec<S>,
    matrix: Option<Vec<S>>,
}

impl<'a, S: Scalar> Pipeline<'a, S> {
    fn run(case: &'a RastFile, arithmetic: Arithmetic) -> Result<Comparison, Cs418Error> {
        let pipeline = Pipeline::<S>::new(case, true).draw()?;
        Ok(Comparison {
            image: pipeline.resolve(),
            arithmetic,
            level: pipeline.level,
            primitives: pipeline.primitives,
            owners: pipeline.owners,
            spans: pipeline.spans,
            shapes: pipeline.shapes,
        })
    }

    /// A pipeline for `case`, its buffers allocated when it samples.
    fn new(case: &'a RastFile, sample: bool) -> Self {
        let level = case.features.fsaa.max(1);
        let (width, height) = ((case.width * level) as usize, (case.height * level) as usize);
        let samples = if sample { width * height } else { 0 };
        Pipeline {
            case,
            sample,
            level,
            width,
            height,
            colour: vec![[0.0; 4]; samples],
            depth: vec![S::int(1); if case.features.depth { samples } else { 0 }],
            owners: vec![0; samples],
            primitives: Vec::new(),
            spans: BTreeMap::new(),
            shapes: Vec::new(),
            positions: Vec::new(),
            colours: Vec::new(),
            texcoords: Vec::new(),
            textures: linear_once(&case.textures),
            texture: None,
            elements: Vec::new(),
            sizes: Vec::new(),
            matrix: None,
        }
    }

    /// Runs the case's commands.
    fn draw(mut self) -> Result<Self, Cs418Error> {
        for (line, command) in &self.case.commands {
            self.command(*line, command)?;
        }
        Ok(self)
    }

    fn command(&mut self, line: usize, command: &FileCommand) -> Result<(), Cs418Error> {
        match command {
            FileCommand::Position { size, numbers } => {
                self.positions = numbers
                    .chunks(*size)
                    .map(|c| {
                        let get = |i: usize, default: i64| c.get(i).map_or(S::int(default), S::number);
                        [get(0, 0), get(1, 0), get(2, 0), get(3, 1)]
                    })
                    .collect();
            }
            FileCommand::Color { size, numbers } => {
                self.colours = numbers
                    .chunks(*size)
                    .map(|c| {
                        let get = |i: usize| c.get(i).map_or(S::int(1), S::number);
                        [get(0), get(1), get(2), get(3)]
                    })
                    .collect();
            }
            FileCommand::TexCoord(numbers) => {
                self.texcoords = numbers.chunks(2).map(|c| [S::number(&c[0]), S::number(&c[1])]).collect();
            }
            FileCommand::Texture(index) => self.texture = Some(*index),
            FileCommand::Elements(indices) => self.elements.clone_from(indices),
            FileCommand::PointSize(numbers) => self.sizes = numbers.iter().map(S::number).collect(),
            FileCommand::Matrix(numbers) => self.matrix = Some(numbers.iter().map(S::number).collect()),
            FileCommand::DrawArrays { first, count } => {
                // Every index must name a vertex: checked before any is collected, so that a
                // huge count (or one that wraps past 2^64) is refused, not allocated.
                let positions = self.positions.len();
                if first.checked_add(*count).is_none_or(|end| end > positions) {
                    let index = (*first).max(positions);
                    return Err(error(line, Cs418Problem::VertexIndex { index, count: positions }));
                }
                let indices: Vec<usize> = (*first..first + count).collect();
                self.triangles(line, &indices)?;
            }
            FileCommand::DrawElements { count, offset } => {
                let range = offset.checked_add(*count).map(|end| *offset..end);
                let Some(indices) = range.and_then(|range| self.elements.get(range)).map(<[usize]>::to_vec) else {
                    let (count, offset, has) = (*count, *offset, self.elements.len());
                    return Err(error(line, Cs418Problem::ElementsRange { count, offset, has }));
                };
                self.triangles(line, &indices)?;
            }
            FileCommand::DrawPoints { first, count } => {
                for index in *first..first.saturating_add(*count) {
                    let size =
                        self.sizes.get(index).cloned().ok_or_else(|| {
                            error(line, Cs418Problem::PointSizeRange { index, has: self.sizes.len() })
                        })?;
                    let vertex = self.vertex(line, index, false)?;
                    self.primitives.push(Primitive { line, vertices: vec![index] });
                    self.point(vertex, size);
                }
            }
        }
        Ok(())
    }

    /// Vertex `index` in clip space: its position times the matrix, its
    /// colour and its texture coordinates (needed only by a triangle drawn
    /// with a texture; (0, 0) otherwise).
    fn vertex(&self, line: usize, index: usize, textured: bool) -> Result<Vertex<S>, Cs418Error> {
        let position = self
            .positions
            .get(index)
            .ok_or_else(|| error(line, Cs418Problem::VertexIndex { index, count: self.positions.len() }))?;
        // A texture without decals replaces the colour, so none need be given
        // (WebGL's default attribute, opaque black, stands in).
        let replaced = self.texture.is_some() && !self.case.features.decals;
        let colour = match self.colours.get(index) {
            Some(colour) => colour.clone(),
            None if replaced => [S::int(0), S::int(0), S::int(0), S::int(1)],
            None => {
                return Err(error(line, Cs418Problem::ColourRange { index, has: self.colours.len() }));
            }
        };
        let position: Vec<S> = match &self.matrix {
            // Column-major: entry (row, column) is matrix[column·4 + row].
            Some(m) => (0..4)
                .map(|row| {
                    (1..4).fold(m[row].mul(&position[0]), |sum, column| {
                        sum.add(&m[column * 4 + row].mul(&position[column]))
                    })
                })
                .collect(),
            None => position.to_vec(),
        };
        let texcoord = match self.texcoords.get(index) {
            Some(st) => st.clone(),
            None if textured => {
                return Err(error(line, Cs418Problem::TexcoordRange { index, has: self.texcoords.len() }));
            }
            None => [S::int(0), S::int(0)],
        };
        Ok(position.into_iter().chain(colour).chain(texcoord).collect())
    }

    fn triangles(&mut self, line: usize, indices: &[usize]) -> Result<(), Cs418Error> {
        let textured = self.texture.is_some();
        for corners in indices.chunks_exact(3) {
            let vertices = [
                self.vertex(line, corners[0], textured)?,
                self.vertex(line, corners[1], textured)?,
                self.vertex(line, corners[2], textured)?,
            ];
            self.primitives.push(Primitive { line, vertices: corners.to_vec() });
            let primitive = self.primitives.len() as u32;
            let pieces: Vec<Vec<Vertex<S>>> = if self.case.features.frustum {
                // The clipped polygon, as a fan from its first vertex.
                let polygon = clip(vertices.to_vec());
                (1..polygon.len().saturating_sub(1))
                    .map(|i| vec![polygon[0].clone(), polygon[i].clone(), polygon[i + 1].clone()])
                    .collect()
            } else {
                vec![vertices.to_vec()]
            };
            for piece in &pieces {
                let Some(screen) = piece.iter().map(|v| self.to_screen(v)).collect::<Option<Vec<_>>>() else {
                    continue;
                };
                self.within_reach(line, &screen)?;
                if self.case.features.cull && !clockwise(&screen) {
                    continue;
                }
                self.record_shape(
                    primitive,
                    screen.iter().map(|v| [v[0].clone(), v[1].clone(), v[2].clone()]).collect(),
                );
                if self.sample {
                    self.scanline(&screen, primitive);
                }
            }
        }
        Ok(())
    }

    /// Refuses a triangle whose vertices land so far outside the image (or
    /// at no number at all) that walking its rows and columns would take
    /// ages: the DDA visits every integer between a vertex and the image.
    fn within_reach(&self, line: usize, screen: &[Vertex<S>]) -> Result<(), Cs418Error> {
        let reach = REACH * (self.width.max(self.height) as f64);
        for v in screen {
            let (x, y) = (v[0].to_f64(), v[1].to_f64());
            if !(x.abs() <= reach && y.abs() <= reach) {
                return Err(error(line, Cs418Problem::TooFar { x, y }));
            }
        }
        Ok(())
    }

    /// Division by w and the viewport: `(x/w + 1)·W/2` in the course's order
    /// of operations. `None` for w = 0 (a vertex at infinity: not drawn).
    fn to_screen(&self, v: &[S]) -> Option<Vertex<S>> {
        let w = &v[3];
        if w.is_zero() {
            return None;
        }
        let one = S::int(1);
        let two = S::int(2);
        let x = v[0].div(w).add(&one).mul(&S::int(self.width as i64)).div(&two);
        let y = v[1].div(w).add(&one).mul(&S::int(self.height as i64)).div(&two);
        let inverse = one.div(w);
        let mut out = vec![x, y, v[2].div(w), inverse.clone()];
        for c in &v[4..COMPONENTS] {
            out.push(if self.case.features.hyp { c.div(w) } else { c.clone() });
        }
        Some(out)
    }

    /// The course's scanline algorithm: the vertices sorted by y, a DDA along
    /// the long edge and one along each short edge, and a DDA in x between
    /// them on every row.
    fn scanline(&mut self, vertices: &[Vertex<S>], primitive: u32) {
        let mut sorted: Vec<&Vertex<S>> = vertices.iter().collect();
        sorted.sort_by(|a, b| a[1].partial_cmp(&b[1]).unwrap_or(std::cmp::Ordering::Equal));
        let [top, middle, bottom] = [sorted[0], sorted[1], sorted[2]];
        let Some(mut long) = Dda::new(top, bottom, 1) else { return };
        for (from, to) in [(top, middle), (middle, bottom)] {
            let Some(mut short) = Dda::new(from, to, 1) else { continue };
            short.skip_before(0, Some(&mut long));
            while short.live() {
                if short.at() >= self.height as i64 {
                    return;
                }
                self.row(&short.p, &long.p, primitive);
                short.step();
                long.step();
            }
        }
    }

    /// One row of a triangle, on the image: its span, and the samples from
    /// the image's left edge to its right (the DDA's steps before the left
    /// edge are taken, but visit nothing).
    fn row(&mut self, a: &[S], b: &[S], primitive: u32) {
        let row = a[1].to_f64().round() as i64;
        let (left, right) = if a[0] <= b[0] { (a, b) } else { (b, a) };
        self.spans.entry((primitive, row)).or_default().push(SampleSpan {
            left: left[0].text(),
            right: right[0].text(),
            left_value: left[0].to_f64(),
            right_value: right[0].to_f64(),
        });
        let Some(mut dda) = Dda::new(a, b, 0) else { return };
        dda.skip_before(0, None);
        let hyp = self.case.features.hyp;
        while dda.live() {
            let x = dda.at();
            if x >= self.width as i64 {
                break;
            }
            let p = &dda.p;
            let attributes = || match (hyp, p[3].is_zero()) {
                (true, true) => Attributes::AtInfinity(std::array::from_fn(|k| p[4 + k].to_f64() / 0.0)),
                (true, false) => Attributes::Values(std::array::from_fn(|k| p[4 + k].div(&p[3]))),
                (false, _) => Attributes::Values(std::array::from_fn(|k| p[4 + k].clone())),
            };
            self.fragment(x, row, &p[2], attributes, primitive);
            dda.step();
        }
    }

    fn point(&mut self, vertex: Vertex<S>, size: S) {
        let primitive = self.primitives.len() as u32;
        let (w, z) = (&vertex[3], &vertex[2]);
        if self.case.features.frustum && (z.add(w) < S::int(0) || w.sub(z) < S::int(0)) {
            return;
        }
        let Some(screen) = self.to_screen(&vertex) else { return };
        let half = size.mul(&S::int(i64::from(self.level))).div(&S::int(2));
        let (x0, x1) = (screen[0].sub(&half), screen[0].add(&half));
        let (y0, y1) = (screen[1].sub(&half), screen[1].add(&half));
        let z = screen[2].clone();
        let (width, height) = (x1.sub(&x0), y1.sub(&y0));
        let corners = [(&x0, &y0), (&x1, &y0), (&x1, &y1), (&x0, &y1)];
        self.record_shape(primitive, corners.iter().map(|(x, y)| [(*x).clone(), (*y).clone(), z.clone()]).collect());
        if !self.sample {
            return;
        }
        // Only the image's samples: x and y step by exactly 1, so starting at
        // the image's edge visits the same samples a walk from far outside would.
        let (zero, right, bottom) = (S::int(0), S::int(self.width as i64), S::int(self.height as i64));
        let clamp_low = |v: S| if v < zero { zero.clone() } else { v };
        let (x_end, y_end) =
            (if x1 > right { right } else { x1.clone() }, if y1 > bottom { bottom } else { y1.clone() });
        let mut y = clamp_low(y0.ceil());
        while y < y_end {
            let mut x = clamp_low(x0.ceil());
            while x < x_end {
                let (xi, yi) = (x.to_f64() as i64, y.to_f64() as i64);
                // The vertex's colour; (s, t) across the square from its top-left corner.
                let attributes = || {
                    Attributes::Values(std::array::from_fn(|k| match k {
                        4 => x.sub(&x0).div(&width),
                        5 => y.sub(&y0).div(&height),
                        _ => vertex[4 + k].clone(),
                    }))
                };
                self.fragment(xi, yi, &z, attributes, primitive);
                x = x.add(&S::int(1));
            }
            y = y.add(&S::int(1));
        }
    }

    /// Keeps a drawn shape in zsim's coordinates (see [`SampleGrid`]).
    fn record_shape(&mut self, primitive: u32, corners: Vec<[S; 3]>) {
        let half = S::int(1).div(&S::int(2));
        let height = S::int(self.height as i64);
        let vertices =
            corners.iter().map(|[x, y, z]| [x.add(&half).text(), height.sub(y).sub(&half).text(), z.text()]).collect();
        self.shapes.push(SampleGrid { primitive, vertices });
    }

    /// One fragment: bounds, the depth test, the texture, then "over" onto
    /// the sample. `attributes` gives its colour and (s, t), already divided
    /// by the interpolated 1/w under `hyp`, computed only for a fragment that
    /// passes the depth test.
    fn fragment(&mut self, x: i64, y: i64, z: &S, attributes: impl FnOnce() -> Attributes<S>, primitive: u32) {
        if x < 0 || y < 0 || x >= self.width as i64 || y >= self.height as i64 {
            return;
        }
        let index = y as usize * self.width + x as usize;
        if self.case.features.depth {
            // Kept when z/w ≤ stored (a NaN depth, from a vertex at infinity, is not).
            if z.partial_cmp(&self.depth[index]).is_none_or(|o| o == std::cmp::Ordering::Greater) {
                return;
            }
            self.depth[index] = z.clone();
        }
        let (vertex, texel): ([f64; 4], _) = match attributes() {
            Attributes::Values(a) => {
                (std::array::from_fn(|k| a[k].to_f64()), self.texture.map(|t| self.texel(t, &a[4], &a[5])))
            }
            Attributes::AtInfinity(a) => {
                (std::array::from_fn(|k| a[k]), self.texture.map(|t| self.texel(t, &a[4], &a[5])))
            }
        };
        let colour = match texel {
            None => vertex,
            Some(texel) => {
                if self.case.features.decals {
                    let a = texel[3];
                    let mut out: [f64; 4] = std::array::from_fn(|k| texel[k] * a + vertex[k] * (1.0 - a));
                    out[3] = a + vertex[3] - a * vertex[3];
                    out
                } else {
                    texel
                }
            }
        };
        let below = self.colour[index];
        let alpha = colour[3] + below[3] * (1.0 - colour[3]);
        let mut out = [0.0, 0.0, 0.0, alpha];
        if alpha > 0.0 {
            for k in 0..3 {
                out[k] = (colour[k] * colour[3] + below[k] * below[3] * (1.0 - colour[3])) / alpha;
            }
        }
        self.colour[index] = out;
        self.owners[index] = primitive;
    }

    /// The nearest texel of the bound texture to (s, t), both wrapped into
    /// 0 … 1 first (repeat); linear RGBA.
    fn texel<T: Scalar>(&self, texture: usize, s: &T, t: &T) -> [f64; 4] {
        let image = &self.case.textures[texture].image;
        let at = |v: &T, size: u32| {
            // The texel whose centre is nearest: s·W rounded half up, wrapped
            // (repeat); a negative coordinate's texel lies NEGATIVE_SHIFT further on.
            let nearest = v.sub(&v.floor()).mul(&T::int(i64::from(size))).add(&T::int(1).div(&T::int(2))).floor();
            let shift = if *v < T::int(0) { NEGATIVE_SHIFT } else { 0 };
            (nearest.to_f64() as i64 + shift).rem_euclid(i64::from(size)) as usize
        };
        let (column, row) = (at(s, image.width), at(t, image.height));
        self.textures[texture][row * image.width as usize + column]
    }

    /// Averages each pixel's samples (colour weighted by alpha), converts to
    /// sRGB when asked, and rounds to 8 bits.
    fn resolve(&self) -> Image {
        let (width, height, level) = (self.case.width, self.case.height, self.level as usize);
        let mut rgba = Vec::with_capacity((width * height * 4) as usize);
        for y in 0..height as usize {
            for x in 0..width as usize {
                let mut sum = [0.0f64; 4];
                for sy in 0..level {
                    for sx in 0..level {
                        let c = self.colour[(y * level + sy) * self.width + x * level + sx];
                        for k in 0..3 {
                            sum[k] += c[k] * c[3];
                        }
                        sum[3] += c[3];
                    }
                }
                let samples = (level * level) as f64;
                let alpha = sum[3] / samples;
                for k in 0..3 {
                    let linear = if sum[3] > 0.0 { sum[k] / sum[3] } else { 0.0 };
                    let shown = if self.case.features.srgb { to_srgb(linear) } else { linear };
                    rgba.push(byte(shown));
                }
                rgba.push(byte(alpha));
            }
        }
        Image { width, height, rgba }
    }
}

/// A texture's texels in linear light, row by row from the top, shared.
type Texels = std::sync::Arc<Vec<[f64; 4]>>;

/// Each texture's texels in linear light, computed once for every image
/// however many of the case's names lead to it (the names share one image).
fn linear_once(textures: &[super::Texture]) -> Vec<Texels> {
    use std::sync::Arc;
    let mut made: Vec<(&Arc<Image>, Texels)> = Vec::new();
    textures
        .iter()
        .map(|texture| match made.iter().find(|(image, _)| Arc::ptr_eq(image, &texture.image)) {
            Some((_, texels)) => Arc::clone(texels),
            None => {
                let texels = Arc::new(linear_texels(texture));
                made.push((&texture.image, Arc::clone(&texels)));
                texels
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::words::Lang;
    use num_bigint::BigInt;

    #[test]
    fn numbers_keep_their_exact_value() {
        let case = super::super::RastFile::parse("png 1 1 a.png\npointsize 1 0.6934 -.5 1e-3 +4", &|_| {
            Err(super::super::TextureProblem::Missing)
        })
        .unwrap();
        let super::super::FileCommand::PointSize(numbers) = &case.commands[0].1 else { panic!("pointsize") };
        let exact: Vec<BigRational> = numbers.iter().map(BigRational::number).collect();
        let q = |n: i64, d: i64| BigRational::new(BigInt::from(n), BigInt::from(d));
        assert_eq!(exact, vec![q(3467, 5000), q(-1, 2), q(1, 1000), q(4, 1)]);
        assert_eq!(numbers[0].value, 0.6934);
    }

    #[test]
    fn dda_includes_the_first_integer_and_never_the_end() {
        let points = |a: f64, b: f64| {
            let mut dda = Dda::new(&[a], &[b], 0).unwrap();
            let mut out = Vec::new();
            while dda.live() {
                out.push(dda.p[0]);
                dda.step();
            }
            out
        };
        assert_eq!(points(2.0, 5.0), vec![2.0, 3.0, 4.0]);
        assert_eq!(points(1.5, 4.0), vec![2.0, 3.0]);
        assert_eq!(points(4.0, 1.5), vec![2.0, 3.0]);
    }

    /// A 2×2 texture: top row red, green; bottom row blue, and a grey whose
    /// sRGB byte is 188 (linear 0.5) at alpha 128.
    fn two_by_two() -> Image {
        let rgba = [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [188, 188, 188, 128]];
        Image { width: 2, height: 2, rgba: rgba.concat() }
    }

    fn textured(text: &str) -> Image {
        let case = super::super::RastFile::parse(text, &|_| Ok(std::sync::Arc::new(two_by_two()))).unwrap();
        render(&case, Arithmetic::DdaF64).unwrap().image
    }

    /// The whole image as one quad whose (s, t) run from 0 to 2: each sample
    /// (x, y) of a 4×4 image has s = x/2, t = y/2, so wrapping repeats the
    /// texture twice each way, nearest texel, t = 0 at the file's top row.
    #[test]
    fn texels_are_nearest_repeated_and_read_from_the_top_row() {
        let image = textured(
            "png 4 4 t.png\nsRGB\ntexture t.png\nposition 2 -1 -1 1 -1 -1 1 1 1\ntexcoord 2 0 0 2 0 0 2 2 2\nelements 0 1 2 2 1 3\ndrawElementsTriangles 6 0",
        );
        let texture = two_by_two();
        for y in 0..4 {
            for x in 0..4 {
                let [r, g, b, a] = texture.pixel(x % 2, y % 2);
                // Alpha is not sRGB: the grey texel's 128 goes over the empty
                // background and comes back as 128; its colour, linear 0.5
                // inside, is 188 again at output.
                assert_eq!(image.pixel(x, y), [r, g, b, a], "({x}, {y})");
            }
        }
    }

    /// A negative coordinate's texel lies 5 texels further on than wrapping
    /// alone puts it, as the course's `textures` reference shows. On an 8×1
    /// image, one quad: s runs over 0 … 1 (top row) or −1 … 0 (bottom row)
    /// across an 8-texel texture of 8 greys, so pixel x samples s = x/8 or
    /// x/8 − 1: texel x on the top row, texel (x + 5) mod 8 below.
    #[test]
    fn a_negative_coordinate_shows_the_texel_five_further_on() {
        let greys = Image { width: 8, height: 1, rgba: (0..8u8).flat_map(|k| [k * 30, k * 30, k * 30, 255]).collect() };
        for (s0, shift) in [(0, 0), (-1, 5)] {
            let text = format!(
                "png 8 1 n.png\nsRGB\ntexture g.png\nposition 2 -1 -1 1 -1 -1 1 1 1\ntexcoord 2 {s0} 0 {} 0 {s0} 0 {} 0\nelements 0 1 2 2 1 3\ndrawElementsTriangles 6 0",
                s0 + 1,
                s0 + 1
            );
            let case = super::super::RastFile::parse(&text, &|_| Ok(std::sync::Arc::new(greys.clone()))).unwrap();
            let image = render(&case, Arithmetic::DdaF64).unwrap().image;
            for x in 0..8u32 {
                let k = ((x + shift) % 8) as u8 * 30;
                assert_eq!(image.pixel(x, 0), [k, k, k, 255], "s from {s0}, pixel {x}");
            }
        }
    }

    /// `decals`: the texel goes over the vertex colour, in linear light.
    #[test]
    fn decals_put_the_texel_over_the_vertex_colour() {
        let image = textured(
            "png 2 2 d.png\ndecals\ntexture t.png\nposition 2 -1 -1 1 -1 -1 1 1 1\ncolor 3 0 0 1 0 0 1 0 0 1 0 0 1\ntexcoord 2 0 0 1 0 0 1 1 1\nelements 0 1 2 2 1 3\ndrawElementsTriangles 6 0",
        );
        // Opaque red over blue is red; the grey texel (linear 0.5 at
        // alpha 128/255) over opaque blue: rgb = 0.5·a + (0, 0, 1)·(1 − a).
        assert_eq!(image.pixel(0, 0), [255, 0, 0, 255]);
        let a = 128.0 / 255.0;
        let grey = ((188.0f64 / 255.0 + 0.055) / 1.055).powf(2.4);
        let expected = [byte(grey * a), byte(grey * a), byte(grey * a + (1.0 - a)), 255];
        assert_eq!(image.pixel(1, 1), expected);
    }

    /// A point drawn with a texture bound is a sprite: (0, 0) at its top-left.
    #[test]
    fn a_textured_point_shows_the_texture_from_its_top_left_corner() {
        let image = textured(
            "png 2 2 p.png\ntexture t.png\nposition 2 0 0\ncolor 3 1 1 1\npointsize 1 2\ndrawArraysPoints 0 1",
        );
        assert_eq!(image.pixel(0, 0), [255, 0, 0, 255]);
        assert_eq!(image.pixel(1, 0), [0, 255, 0, 255]);
        assert_eq!(image.pixel(0, 1), [0, 0, 255, 255]);
    }

    /// Found by a random file: with `hyp` and no `frustum`, a triangle whose
    /// w changes sign passes through infinity, and at a sample where the
    /// interpolated 1/w is exactly 0 exact arithmetic divided by zero. There
    /// both arithmetics now give the course's floats' answer (the colour
    /// divided by 0: NaN alpha, drawn as transparent black), and agree.
    #[test]
    fn a_sample_at_infinity_gets_the_floats_colour_in_both_arithmetics() {
        let case = super::super::RastFile::parse(
            "png 4 4 o.png\nhyp\nposition 4 2 1.0 0 -2 0 -1.0 0 2 2 -0.5 0 -1\ncolor 3 1 0 0 0 1 0 0 0 1\ndrawArraysTriangles 0 3",
            &|_| Err(super::super::TextureProblem::Missing),
        )
        .unwrap();
        let (course, exact) = (render(&case, Arithmetic::DdaF64).unwrap(), render(&case, Arithmetic::Exact).unwrap());
        assert_eq!(course.image, exact.image);
        let at_infinity: Vec<(u32, u32)> = (0..4)
            .flat_map(|y| (0..4).map(move |x| (x, y)))
            .filter(|&(x, y)| exact.owner(x, y) != 0 && exact.image.pixel(x, y) == [0, 0, 0, 0])
            .collect();
        assert!(!at_infinity.is_empty(), "some covered sample lies at infinity");
    }

    #[test]
    fn a_textured_triangle_needs_texture_coordinates() {
        let case = super::super::RastFile::parse(
            "png 2 2 a.png\ntexture t.png\nposition 2 -1 -1 1 -1 -1 1\ntexcoord 2 0 0 1 0\ndrawArraysTriangles 0 3",
            &|_| Ok(std::sync::Arc::new(two_by_two())),
        )
        .unwrap();
        let problem = render(&case, Arithmetic::DdaF64).unwrap_err().message(Lang::En);
        assert_eq!(problem, "line 5: vertex 2 is drawn with a texture, but \"texcoord\" has 2 vertices");
    }
}
