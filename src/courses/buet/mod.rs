//! BUET CSE 410 "Offline 2: Rasterization", end to end: the case files
//! (`config.txt`, `scene.txt`), the three transformation stages, and the
//! course's output formats (`stageN.txt`, `z_buffer.txt`, `out.bmp`).
//!
//! Stages 1–3 involve sin, cos, tan and sqrt, so they are computed in `f64`
//! as the course computes them and written with 7 decimals. Stage 4 reads the
//! triangles back from `stage3.txt` as exact decimals and runs the `buet`
//! rules (`crate::rules`) exactly on the one rasterizer.

pub mod check;

use crate::words::Lang;
use std::fmt::Write as _;

use std::path::Path;

use crate::error::Error;
use crate::numbers::{Exact, Q, parse_number, to_f64};
use crate::raster::depth::Stored;
use crate::simulate::buffer::Buffers;

use crate::error::Refusal;

/// A problem in a BUET case's file, with its line.
pub type BuetError = super::CaseError<BuetProblem>;

fn case_error(line: Option<usize>, problem: BuetProblem) -> BuetError {
    BuetError { line, problem }
}

/// What is wrong in a BUET case's file (`config.txt`, `scene.txt`, a stage
/// file) or in a student's `z_buffer.txt`.
#[derive(Debug, Clone, PartialEq)]
pub enum BuetProblem {
    /// A raster side that is not a whole number from 1 to the largest side.
    Size {
        /// The word written.
        word: String,
    },
    /// `config.txt` is empty.
    ConfigEmpty,
    /// Its first line is not two numbers.
    ConfigFirst,
    /// A line that should hold one number.
    OneNumber,
    /// The depth range's line is not two numbers.
    ZRange,
    /// The window's left or bottom edge is not negative.
    WindowNegative,
    /// The depth range's front lies behind its rear.
    ZOrder,
    /// `config.txt` has neither one line nor four.
    ConfigLines {
        /// Its lines with something on them.
        count: usize,
    },
    /// A word that is not a number.
    Number(crate::numbers::NumberError),
    /// The file ends where these values were due.
    Ends {
        /// The values due.
        what: BuetValues,
    },
    /// A line that is not `count` finite numbers.
    Numbers {
        /// The values due.
        what: BuetValues,
        /// How many.
        count: usize,
        /// The line written.
        found: String,
    },
    /// The camera looks at its own position.
    LookAtEye,
    /// The up direction lies along the direction of view.
    UpAlongView,
    /// A field of view, aspect ratio or near and far planes no projection has.
    Perspective,
    /// A rotation about the zero axis.
    RotationAxis,
    /// `pop` with nothing pushed.
    Pop,
    /// A command the course does not have.
    UnknownCommand {
        /// The word written.
        command: String,
    },
    /// A stage file's line that is not three coordinates.
    ThreeCoordinates {
        /// The line written.
        found: String,
    },
    /// A stage file's points that do not make whole triangles.
    Triangles {
        /// How many points.
        count: usize,
    },
    /// A value of a student's `z_buffer.txt` that is not a number.
    AnswerNotANumber {
        /// Its line (from 1).
        line: usize,
        /// Which value of the line (from 1).
        value: usize,
        /// What is written.
        text: String,
    },
    /// A student's `z_buffer.txt` with another count of rows than the raster's.
    AnswerRows {
        /// The rows written.
        rows: usize,
        /// The raster's height.
        height: u32,
    },
}

/// The values a line of `scene.txt` holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BuetValues {
    /// The eye position.
    Eye,
    /// The point looked at.
    Look,
    /// The up direction.
    Up,
    /// The projection's field of view, aspect ratio, near and far planes.
    Perspective,
    /// A triangle's vertex.
    Vertex,
    /// A translation.
    Translation,
    /// A scaling.
    Scale,
    /// A rotation's angle and axis.
    Rotation,
}

impl BuetValues {
    fn key(self) -> &'static str {
        match self {
            BuetValues::Eye => "buet-what-eye",
            BuetValues::Look => "buet-what-look",
            BuetValues::Up => "buet-what-up",
            BuetValues::Perspective => "buet-what-perspective",
            BuetValues::Vertex => "buet-what-vertex",
            BuetValues::Translation => "buet-what-translation",
            BuetValues::Scale => "buet-what-scale",
            BuetValues::Rotation => "buet-what-rotation",
        }
    }
}

impl Refusal for BuetProblem {
    fn message(&self, lang: Lang) -> String {
        use crate::words::token;
        match self {
            BuetProblem::Size { word } => {
                words!(lang, "buet-size", word = token(lang, word), max = crate::scene::MAX_SIDE.to_string())
            }
            BuetProblem::ConfigEmpty => words!(lang, "buet-config-empty"),
            BuetProblem::ConfigFirst => words!(lang, "buet-config-first"),
            BuetProblem::OneNumber => words!(lang, "buet-one-number"),
            BuetProblem::ZRange => words!(lang, "buet-z-range"),
            BuetProblem::WindowNegative => words!(lang, "buet-window-negative"),
            BuetProblem::ZOrder => words!(lang, "buet-z-order"),
            BuetProblem::ConfigLines { count } => words!(lang, "buet-config-lines", count = count.to_string()),
            BuetProblem::Number(problem) => problem.message(lang),
            BuetProblem::Ends { what } => words!(lang, "buet-ends", what = words!(lang, what.key())),
            BuetProblem::Numbers { what, count, found } => words!(
                lang,
                "buet-numbers",
                what = words!(lang, what.key()),
                count = count.to_string(),
                found = token(lang, found)
            ),
            BuetProblem::LookAtEye => words!(lang, "buet-look-at-eye"),
            BuetProblem::UpAlongView => words!(lang, "buet-up-along-view"),
            BuetProblem::Perspective => words!(lang, "buet-perspective"),
            BuetProblem::RotationAxis => words!(lang, "buet-rotation-axis"),
            BuetProblem::Pop => words!(lang, "buet-pop"),
            BuetProblem::UnknownCommand { command } => {
                words!(lang, "case-unknown-command", command = token(lang, command))
            }
            BuetProblem::ThreeCoordinates { found } => {
                words!(lang, "buet-three-coordinates", found = token(lang, found))
            }
            BuetProblem::Triangles { count } => words!(lang, "buet-triangles", count = count.to_string()),
            BuetProblem::AnswerNotANumber { line, value, text } => words!(
                lang,
                "buet-answer-not-a-number",
                line = line.to_string(),
                value = value.to_string(),
                text = token(lang, text)
            ),
            BuetProblem::AnswerRows { rows, height } => {
                words!(lang, "buet-answer-rows", rows = rows.to_string(), height = height.to_string())
            }
        }
    }
}

/// `config.txt`: the raster size, the window and the depth range.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Config {
    /// Raster width.
    pub width: u32,
    /// Raster height.
    pub height: u32,
    /// Left edge of the window; the right edge is `−left`.
    pub left: Q,
    /// Bottom edge of the window; the top edge is `−bottom`.
    pub bottom: Q,
    /// Front of the depth range.
    pub z_front: Q,
    /// Rear of the depth range.
    pub z_rear: Q,
    /// What the z-buffer is cleared to; only values below it are written out.
    pub z_max: Q,
}

impl Config {
    /// Reads either form: `W H` alone (window −1 … 1 in x and y, depth range
    /// −1 … 1, buffer cleared to 2), or `W H`, `left_x`, `bottom_y`,
    /// `z_front z_rear` on the following lines (window `left_x … −left_x` ×
    /// `bottom_y … −bottom_y`, buffer cleared to `z_rear`).
    pub fn parse(text: &str) -> Result<Config, BuetError> {
        let lines: Vec<(usize, Vec<&str>)> = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.split_whitespace().collect::<Vec<_>>()))
            .filter(|(_, words)| !words.is_empty())
            .collect();
        let number = |line: usize, word: &str| -> Result<Q, BuetError> {
            parse_number(word).map_err(|e| case_error(Some(line), BuetProblem::Number(e)))
        };
        let size = |line: usize, word: &str| -> Result<u32, BuetError> {
            word.parse::<u32>()
                .ok()
                .filter(|v| (1..=crate::scene::MAX_SIDE as u32).contains(v))
                .ok_or_else(|| case_error(Some(line), BuetProblem::Size { word: word.to_string() }))
        };
        let Some((first_line, first)) = lines.first() else {
            return Err(case_error(None, BuetProblem::ConfigEmpty));
        };
        let [w, h] = first.as_slice() else {
            return Err(case_error(Some(*first_line), BuetProblem::ConfigFirst));
        };
        let (width, height) = (size(*first_line, w)?, size(*first_line, h)?);
        let one = Q::from_integer(1);
        match lines.len() {
            1 => Ok(Config {
                width,
                height,
                left: -one,
                bottom: -one,
                z_front: -one,
                z_rear: one,
                z_max: Q::from_integer(2),
            }),
            4 => {
                let single = |index: usize| -> Result<Q, BuetError> {
                    let (line, words) = &lines[index];
                    match words.as_slice() {
                        [word] => number(*line, word),
                        _ => Err(case_error(Some(*line), BuetProblem::OneNumber)),
                    }
                };
                let left = single(1)?;
                let bottom = single(2)?;
                let (line, words) = &lines[3];
                let [front, rear] = words.as_slice() else {
                    return Err(case_error(Some(*line), BuetProblem::ZRange));
                };
                let (z_front, z_rear) = (number(*line, front)?, number(*line, rear)?);
                if left >= Q::from_integer(0) || bottom >= Q::from_integer(0) {
                    return Err(case_error(Some(lines[1].0), BuetProblem::WindowNegative));
                }
                if z_front > z_rear {
                    return Err(case_error(Some(*line), BuetProblem::ZOrder));
                }
                Ok(Config { width, height, left, bottom, z_front, z_rear, z_max: z_rear })
            }
            n => Err(case_error(None, BuetProblem::ConfigLines { count: n })),
        }
    }
}

/// A 4×4 matrix of `f64`, rows first.
pub type Matrix4 = [[f64; 4]; 4];

fn identity() -> Matrix4 {
    let mut m = [[0.0; 4]; 4];
    for (i, row) in m.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    m
}

/// `a · b`, each entry summed over k = 0 … 3 from 0.0.
pub fn multiply(a: &Matrix4, b: &Matrix4) -> Matrix4 {
    let mut c = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            let mut sum = 0.0;
            for k in 0..4 {
                sum += a[i][k] * b[k][j];
            }
            c[i][j] = sum;
        }
    }
    c
}

/// `m · (x, y, z, 1)`, divided by the resulting w.
pub fn transform(m: &Matrix4, p: [f64; 3]) -> [f64; 3] {
    let v = [p[0], p[1], p[2], 1.0];
    let mut out = [0.0; 4];
    for (i, row) in m.iter().enumerate() {
        let mut sum = 0.0;
        for k in 0..4 {
            sum += row[k] * v[k];
        }
        out[i] = sum;
    }
    [out[0] / out[3], out[1] / out[3], out[2] / out[3]]
}

fn translation(t: [f64; 3]) -> Matrix4 {
    let mut m = identity();
    m[0][3] = t[0];
    m[1][3] = t[1];
    m[2][3] = t[2];
    m
}

fn scaling(s: [f64; 3]) -> Matrix4 {
    let mut m = identity();
    m[0][0] = s[0];
    m[1][1] = s[1];
    m[2][2] = s[2];
    m
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn normalize(a: [f64; 3]) -> [f64; 3] {
    let length = dot(a, a).sqrt();
    [a[0] / length, a[1] / length, a[2] / length]
}

/// Rodrigues' formula: `R(x) = cos θ·x + (1 − cos θ)(a·x)·a + sin θ·(a × x)`.
fn rodrigues(x: [f64; 3], a: [f64; 3], theta: f64) -> [f64; 3] {
    let (c, s) = (theta.cos(), theta.sin());
    let d = dot(a, x);
    let ax = cross(a, x);
    [0, 1, 2].map(|i| c * x[i] + (1.0 - c) * d * a[i] + s * ax[i])
}

/// The rotation by `angle` degrees about `axis`: columns are the rotated unit vectors.
fn rotation(angle: f64, axis: [f64; 3]) -> Matrix4 {
    let a = normalize(axis);
    let theta = angle * std::f64::consts::PI / 180.0;
    let columns = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].map(|e| rodrigues(e, a, theta));
    let mut m = identity();
    for (j, column) in columns.iter().enumerate() {
        for i in 0..3 {
            m[i][j] = column[i];
        }
    }
    m
}

/// The non-empty lines of a file, read one at a time.
struct Lines<'a> {
    lines: &'a [(usize, &'a str)],
    next: usize,
}

impl<'a> Lines<'a> {
    fn next_line(&mut self) -> Option<(usize, &'a str)> {
        let line = self.lines.get(self.next).copied();
        self.next += 1;
        line
    }

    /// The number of the line read last.
    fn last_line(&self) -> Option<usize> {
        self.next.checked_sub(1).and_then(|i| self.lines.get(i)).map(|(line, _)| *line)
    }

    /// The next line as exactly `count` numbers, the values `what`.
    fn numbers(&mut self, count: usize, what: BuetValues) -> Result<Vec<f64>, BuetError> {
        let Some((line, text)) = self.next_line() else {
            return Err(case_error(None, BuetProblem::Ends { what }));
        };
        let values: Result<Vec<f64>, _> = text.split_whitespace().map(str::parse::<f64>).collect();
        match values {
            // `str::parse` reads "NaN" and "inf" too: the course's numbers are finite.
            Ok(values) if values.len() == count && values.iter().all(|v| v.is_finite()) => Ok(values),
            _ => Err(case_error(Some(line), BuetProblem::Numbers { what, count, found: text.to_string() })),
        }
    }
}

/// `scene.txt`: the camera and the triangles after the model transformations.
#[derive(Debug, Clone)]
pub struct CaseScene {
    /// The eye position.
    pub eye: [f64; 3],
    /// The point looked at.
    pub look: [f64; 3],
    /// The up direction.
    pub up: [f64; 3],
    /// Vertical field of view in degrees, aspect ratio, near and far planes.
    pub perspective: [f64; 4],
    /// The triangles after stage 1 (model transformations).
    pub stage1: Vec<[[f64; 3]; 3]>,
}

impl CaseScene {
    /// Reads `scene.txt` and applies the model transformations (stage 1):
    /// `triangle`, `translate`, `scale`, `rotate` (angle in degrees and an
    /// axis), `push`, `pop`, `end`; each transformation is `M = M·T`.
    pub fn parse(text: &str) -> Result<CaseScene, BuetError> {
        let lines: Vec<(usize, &str)> =
            text.lines().enumerate().map(|(i, l)| (i + 1, l.trim())).filter(|(_, l)| !l.is_empty()).collect();
        let mut reader = Lines { lines: &lines, next: 0 };
        let three = |v: Vec<f64>| [v[0], v[1], v[2]];
        // A camera or projection the formulas cannot build (they would divide by
        // zero and fill every stage with NaN) is refused at its line.
        let eye = three(reader.numbers(3, BuetValues::Eye)?);
        let look = three(reader.numbers(3, BuetValues::Look)?);
        if look == eye {
            return Err(case_error(reader.last_line(), BuetProblem::LookAtEye));
        }
        let up = three(reader.numbers(3, BuetValues::Up)?);
        let direction = [0, 1, 2].map(|i| look[i] - eye[i]);
        if cross(direction, up).iter().all(|v| *v == 0.0) {
            return Err(case_error(reader.last_line(), BuetProblem::UpAlongView));
        }
        let p = reader.numbers(4, BuetValues::Perspective)?;
        let perspective = [p[0], p[1], p[2], p[3]];
        let [fov_y, aspect, near, far] = perspective;
        let angle = |a: f64| a > 0.0 && a < 180.0;
        if !(angle(fov_y) && aspect > 0.0 && angle(fov_y * aspect) && near > 0.0 && far != near) {
            return Err(case_error(reader.last_line(), BuetProblem::Perspective));
        }
        let mut model = identity();
        let mut stack: Vec<Matrix4> = Vec::new();
        let mut stage1 = Vec::new();
        while let Some((line, command)) = reader.next_line() {
            match command {
                "triangle" => {
                    let mut triangle = [[0.0; 3]; 3];
                    for vertex in &mut triangle {
                        *vertex = transform(&model, three(reader.numbers(3, BuetValues::Vertex)?));
                    }
                    stage1.push(triangle);
                }
                "translate" => {
                    model = multiply(&model, &translation(three(reader.numbers(3, BuetValues::Translation)?)))
                }
                "scale" => model = multiply(&model, &scaling(three(reader.numbers(3, BuetValues::Scale)?))),
                "rotate" => {
                    let r = reader.numbers(4, BuetValues::Rotation)?;
                    if r[1..].iter().all(|v| *v == 0.0) {
                        return Err(case_error(reader.last_line(), BuetProblem::RotationAxis));
                    }
                    model = multiply(&model, &rotation(r[0], [r[1], r[2], r[3]]));
                }
                "push" => stack.push(model),
                "pop" => model = stack.pop().ok_or_else(|| case_error(Some(line), BuetProblem::Pop))?,
                "end" => break,
                other => {
                    return Err(case_error(Some(line), BuetProblem::UnknownCommand { command: other.to_string() }));
                }
            }
        }
        Ok(CaseScene { eye, look, up, perspective, stage1 })
    }

    /// The view matrix `V = R·T`: `l = look − eye`, `r = l × up`, `u = r × l`,
    /// all normalized; R has rows r, u, −l; T moves the eye to the origin.
    pub fn view(&self) -> Matrix4 {
        let l = normalize([0, 1, 2].map(|i| self.look[i] - self.eye[i]));
        let r = normalize(cross(l, self.up));
        let u = normalize(cross(r, l));
        let mut rotation = identity();
        rotation[0][..3].copy_from_slice(&r);
        rotation[1][..3].copy_from_slice(&u);
        rotation[2][..3].copy_from_slice(&l.map(|v| -v));
        multiply(&rotation, &translation(self.eye.map(|v| -v)))
    }

    /// The projection matrix: `t = near·tan(fovY/2)`, `r = near·tan(fovY·aspect/2)`.
    pub fn projection(&self) -> Matrix4 {
        let [fov_y, aspect, near, far] = self.perspective;
        let fov_x = fov_y * aspect;
        let t = near * (fov_y / 2.0 * std::f64::consts::PI / 180.0).tan();
        let r = near * (fov_x / 2.0 * std::f64::consts::PI / 180.0).tan();
        let mut m = [[0.0; 4]; 4];
        m[0][0] = near / r;
        m[1][1] = near / t;
        m[2][2] = -(far + near) / (far - near);
        m[2][3] = -(2.0 * far * near) / (far - near);
        m[3][2] = -1.0;
        m
    }

    /// The triangles after stages 1, 2 and 3.
    pub fn stages(&self) -> [Vec<[[f64; 3]; 3]>; 3] {
        let view = self.view();
        let projection = self.projection();
        let stage2: Vec<[[f64; 3]; 3]> = self.stage1.iter().map(|t| t.map(|p| transform(&view, p))).collect();
        let stage3 = stage2.iter().map(|t| t.map(|p| transform(&projection, p))).collect();
        [self.stage1.clone(), stage2, stage3]
    }
}

/// A stage file: `%.7f` coordinates separated by spaces, one point per line,
/// a blank line after each triangle.
pub fn stage_text(triangles: &[[[f64; 3]; 3]]) -> String {
    let mut out = String::new();
    for triangle in triangles {
        for p in triangle {
            let _ = writeln!(out, "{:.7} {:.7} {:.7}", p[0], p[1], p[2]);
        }
        out.push('\n');
    }
    out
}

/// Reads a stage file's triangles as the decimal texts written there, each
/// checked to be a number (stage 4 reads them exactly, not as `f64`s).
pub fn parse_stage(text: &str) -> Result<Vec<[[String; 3]; 3]>, BuetError> {
    let mut points = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let words: Vec<&str> = line.split_whitespace().collect();
        if words.is_empty() {
            continue;
        }
        let [x, y, z] = words.as_slice() else {
            return Err(case_error(Some(i + 1), BuetProblem::ThreeCoordinates { found: line.trim().to_string() }));
        };
        for word in [x, y, z] {
            parse_number(word).map_err(|e| case_error(Some(i + 1), BuetProblem::Number(e)))?;
        }
        points.push([x.to_string(), y.to_string(), z.to_string()]);
    }
    if points.len() % 3 != 0 {
        return Err(case_error(None, BuetProblem::Triangles { count: points.len() }));
    }
    Ok(points.chunks_exact(3).map(|c| [c[0].clone(), c[1].clone(), c[2].clone()]).collect())
}

/// The case as a zsim scene (JSON): the `buet` rules, the config's window,
/// depth range and clear value, and one polygon per stage-3 triangle with the
/// course's colour as its 24-bit value. Coordinates are copied as written.
pub fn scene_json(config: &Config, triangles: &[[[String; 3]; 3]]) -> String {
    let q = |v: Q| format!("\"{}\"", crate::numbers::fraction(v));
    let mut out = String::new();
    let _ = writeln!(out, "{{");
    let _ = writeln!(out, "  \"width\": {}, \"height\": {},", config.width, config.height);
    let _ = writeln!(out, "  \"frame_bits\": 24, \"background\": 0,");
    let _ = writeln!(out, "  \"rules\": \"buet\", \"depth_test\": \"less\",");
    let _ = writeln!(
        out,
        "  \"window\": {{\"left\": {}, \"right\": {}, \"bottom\": {}, \"top\": {}}},",
        q(config.left),
        q(-config.left),
        q(config.bottom),
        q(-config.bottom)
    );
    let _ = writeln!(
        out,
        "  \"depth_range\": [{}, {}], \"clear_depth\": {},",
        q(config.z_front),
        q(config.z_rear),
        q(config.z_max)
    );
    let _ = writeln!(out, "  \"polygons\": [");
    let colours = colours(triangles.len());
    for (i, (triangle, colour)) in triangles.iter().zip(&colours).enumerate() {
        // Copy each coordinate as written; quote it when it is not a JSON number (e.g. "+1.5").
        let number = |t: &String| {
            if serde_json::from_str::<serde_json::Number>(t).is_ok() { t.clone() } else { format!("\"{t}\"") }
        };
        let vertices: Vec<String> =
            triangle.iter().map(|p| format!("[{}, {}, {}]", number(&p[0]), number(&p[1]), number(&p[2]))).collect();
        let comma = if i + 1 < triangles.len() { "," } else { "" };
        let _ = writeln!(
            out,
            "    {{\"name\": \"triangle {}\", \"value\": {colour}, \"vertices\": [{}]}}{comma}",
            i + 1,
            vertices.join(", ")
        );
    }
    let _ = writeln!(out, "  ]");
    let _ = writeln!(out, "}}");
    out
}

/// Where stage 4's triangles come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Source {
    /// The case's own `stage3.txt`.
    Stage3,
    /// `scene.txt`, through stages 1–3 computed here.
    Scene,
}

/// A case read from its folder: the config, the stages computed (when from
/// `scene.txt`), stage 3's triangles as text, and the zsim scene built from them.
#[derive(Debug, Clone)]
pub struct Case {
    /// `config.txt`.
    pub config: Config,
    /// Stages 1–3 as computed here, when the source is `scene.txt`.
    pub stages: Option<[Vec<[[f64; 3]; 3]>; 3]>,
    /// The triangles stage 4 reads, as written in (or for) `stage3.txt`.
    pub stage3: Vec<[[String; 3]; 3]>,
    /// The scene stage 4 runs.
    pub scene: crate::scene::Scene,
    /// The same scene as zsim scene JSON.
    pub scene_json: String,
}

fn read(path: &Path) -> Result<String, Error> {
    crate::door::read_text(path)
}

impl Case {
    /// Reads a case folder. With no `source`, stage 3 is read from
    /// `stage3.txt` when the folder has one, and computed from `scene.txt`
    /// otherwise.
    pub fn load(dir: &Path, source: Option<Source>) -> Result<Case, Error> {
        let config_path = dir.join("config.txt");
        let config = Config::parse(&read(&config_path)?).map_err(|e| e.in_file(&config_path))?;
        let source = source.unwrap_or(if dir.join("stage3.txt").is_file() { Source::Stage3 } else { Source::Scene });
        let (stages, stage3_text, stage3_path) = match source {
            Source::Stage3 => {
                let path = dir.join("stage3.txt");
                (None, read(&path)?, path)
            }
            Source::Scene => {
                let path = dir.join("scene.txt");
                let scene = CaseScene::parse(&read(&path)?).map_err(|e| e.in_file(&path))?;
                let stages = scene.stages();
                let text = stage_text(&stages[2]);
                (Some(stages), text, path)
            }
        };
        let stage3 = parse_stage(&stage3_text).map_err(|e| e.in_file(&stage3_path))?;
        let scene_json = scene_json(&config, &stage3);
        let scene = crate::scene::Scene::from_json(&scene_json, &stage3_path)?;
        Ok(Case { config, stages, stage3, scene, scene_json })
    }
}

/// The course's triangle colours: a linear congruential generator
/// `g = 214013·g + 2531011` (mod 2^32) from `g = 1`, each channel
/// `((g >> 16) & 0x7FFF) % 256`, red, green, blue per triangle; packed as
/// `0xRRGGBB`.
pub fn colours(count: usize) -> Vec<u32> {
    let mut g: u32 = 1;
    let mut next = || {
        g = g.wrapping_mul(214_013).wrapping_add(2_531_011);
        ((g >> 16) & 0x7FFF) % 256
    };
    (0..count).map(|_| (next() << 16) | (next() << 8) | next()).collect()
}

/// `z_buffer.txt`: rows top to bottom; for each cell holding a value below
/// `z_max`, the nearest `f64` as `%.6f` followed by a tab; a newline after
/// every row.
pub fn z_buffer_text(buffers: &Buffers, z_max: Q) -> String {
    let mut out = String::new();
    for row in buffers.depth_rows() {
        for cell in row {
            let value = cell.value();
            if value < Exact::Word(z_max) {
                let _ = write!(out, "{:.6}\t", to_f64(value));
            }
        }
        out.push('\n');
    }
    out
}

/// The cells of `z_buffer.txt` row by row: for each row, the columns whose
/// value is written and the text written, for comparison with an answer.
pub fn z_buffer_cells(buffers: &Buffers, z_max: Q) -> Vec<Vec<(u32, String)>> {
    buffers
        .depth_rows()
        .into_iter()
        .map(|row| {
            row.into_iter()
                .enumerate()
                .filter(|(_, cell)| cell.value() < Exact::Word(z_max))
                .map(|(x, cell): (usize, Stored)| (x as u32, format!("{:.6}", to_f64(cell.value()))))
                .collect()
        })
        .collect()
}

/// `out.bmp`: a 24-bit BMP of the framebuffer (`0xRRGGBB` values), rows
/// stored bottom-up, blue-green-red, each row padded to 4 bytes. The header
/// copies the course's writer, whose file-size field is one more than the
/// file's length.
pub fn bmp(buffers: &Buffers) -> Vec<u8> {
    let (width, height) = (buffers.width(), buffers.height());
    let row_size = (width as usize * 3).div_ceil(4) * 4;
    let image_size = row_size * height as usize;
    let mut out = Vec::with_capacity(54 + image_size);
    out.extend_from_slice(b"BM");
    out.extend_from_slice(&((55 + image_size) as u32).to_le_bytes());
    out.extend_from_slice(&[0; 4]);
    out.extend_from_slice(&54u32.to_le_bytes());
    out.extend_from_slice(&40u32.to_le_bytes());
    out.extend_from_slice(&width.to_le_bytes());
    out.extend_from_slice(&height.to_le_bytes());
    out.extend_from_slice(&1u16.to_le_bytes());
    out.extend_from_slice(&24u16.to_le_bytes());
    out.extend_from_slice(&0u32.to_le_bytes());
    out.extend_from_slice(&(image_size as u32).to_le_bytes());
    out.extend_from_slice(&[0; 16]);
    for y in 0..height {
        let start = out.len();
        for x in 0..width {
            let colour = buffers.frame(x, y);
            out.extend_from_slice(&[(colour & 0xFF) as u8, ((colour >> 8) & 0xFF) as u8, (colour >> 16) as u8]);
        }
        out.resize(start + row_size, 0);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_config_forms_are_read() {
        let short = Config::parse("500 500").unwrap();
        assert_eq!((short.width, short.height, short.z_max), (500, 500, Q::from_integer(2)));
        assert_eq!(
            (short.left, short.z_front, short.z_rear),
            (Q::from_integer(-1), Q::from_integer(-1), Q::from_integer(1))
        );
        let long = Config::parse("640 480\n-2.5\n-1.5\n0.5 10\n").unwrap();
        assert_eq!((long.left, long.bottom), (Q::new(-5, 2), Q::new(-3, 2)));
        assert_eq!((long.z_front, long.z_rear, long.z_max), (Q::new(1, 2), Q::from_integer(10), Q::from_integer(10)));
        assert!(Config::parse("500").is_err());
        assert!(Config::parse("500 500\n-1\n").is_err());
        assert!(Config::parse("500 500\n1\n-1\n-1 1").is_err());
    }

    #[test]
    fn colours_follow_the_course_generator() {
        // The first outputs of g = 214013·g + 2531011 from g = 1 are 41, 18467, 6334, …;
        // modulo 256 that is red 41, green 35, blue 190: 0x2923BE; then 26500, 19169, 15724: 0x84E16C.
        assert_eq!(colours(2), vec![0x2923BE, 0x84E16C]);
    }

    #[test]
    fn rotation_by_90_degrees_about_z_maps_x_to_y() {
        let m = rotation(90.0, [0.0, 0.0, 1.0]);
        let p = transform(&m, [5.0, 0.0, 10.0]);
        assert_eq!(stage_text(&[[p, p, p]]).lines().next().unwrap(), "0.0000000 5.0000000 10.0000000");
    }
}
