//! Depth: the exact depth at a pixel centre, the depth tests, rounding and
//! saturation, and the exact incremental step along a scanline.

use crate::words::Lang;
use std::cmp::Ordering;

use serde::{Deserialize, Serialize};

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

use crate::geometry::equation::PlaneEquation;
use crate::geometry::plane::Geometry;
use crate::numbers::{Exact, Q, Word, cmp_fractions, exact_and_places, floor_div};
use crate::rules::DepthStore;

/// A value held by one z-buffer cell.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Stored {
    /// An integer level `0 … 2^depth_bits − 1` ([`DepthStore::Quantized`]).
    Level(u32),
    /// An exact depth ([`DepthStore::Exact`]).
    Exact(Exact),
}

impl Stored {
    /// The value as an exact number.
    pub fn value(&self) -> Exact {
        match self {
            Stored::Level(level) => Exact::Word(Q::from_integer(i128::from(*level))),
            Stored::Exact(value) => value.clone(),
        }
    }

    /// The integer level, when the z-buffer is quantized.
    pub fn level(&self) -> Option<u32> {
        match self {
            Stored::Level(level) => Some(*level),
            Stored::Exact(_) => None,
        }
    }
}

impl Stored {
    /// A level as an integer (`11`); an exact value with 6 decimals
    /// (`4876543/5000000 ≈ 0.975309`, the separator `lang`'s), as the exact
    /// store is used for depths in small ranges.
    pub fn text(&self, lang: Lang) -> String {
        match self {
            Stored::Level(level) => level.to_string(),
            Stored::Exact(value) => exact_and_places(lang, value, 6),
        }
    }
}

/// Which depth is nearer the viewer, and so which test a pixel must pass.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DepthTest {
    /// The book's: viewer at +∞ on z, larger z is nearer, buffer cleared to 0,
    /// written when `z > stored`.
    #[default]
    Greater,
    /// the Russian text on loop order and the Ukrainian Wikipedia: smaller z is nearer, buffer cleared to `2^depth_bits − 1`,
    /// written when `z < stored`.
    Less,
    /// As `greater`, but an equal depth passes too (GL's `GL_GEQUAL`): of two
    /// polygons at the same depth, the later one keeps the pixel.
    #[serde(rename = "greater-equal")]
    GreaterEqual,
    /// As `less`, but an equal depth passes too (GL's `GL_LEQUAL`, the usual
    /// choice for multi-pass drawing): the later polygon keeps the pixel.
    #[serde(rename = "less-equal")]
    LessEqual,
    /// Every fragment passes (GL's `GL_ALWAYS`): the z-buffer is written but
    /// never consulted, so the last polygon drawn wins, as with no z-buffer.
    /// Cleared as `greater`.
    Always,
    /// No fragment passes (GL's `GL_NEVER`): nothing is drawn.
    Never,
}

impl DepthTest {
    /// Whether a larger z is nearer the viewer (`greater`, `greater-equal`;
    /// `always` and `never`, which compare nothing, are cleared as `greater`).
    pub fn larger_is_nearer(self) -> bool {
        matches!(self, DepthTest::Greater | DepthTest::GreaterEqual | DepthTest::Always | DepthTest::Never)
    }

    /// Whether the test compares depths at all (not `always` or `never`).
    pub fn compares(self) -> bool {
        !matches!(self, DepthTest::Always | DepthTest::Never)
    }

    /// Whether an equal depth passes (`greater-equal`, `less-equal`).
    pub fn equal_passes(self) -> bool {
        matches!(self, DepthTest::GreaterEqual | DepthTest::LessEqual)
    }

    /// The value the z-buffer is cleared to: the farthest depth it can hold.
    pub fn clear_value(self, depth_max: u32) -> u32 {
        if self.larger_is_nearer() { 0 } else { depth_max }
    }

    /// Whether an incoming exact depth replaces the stored value. Equal
    /// depths never overwrite: the first polygon drawn keeps the pixel.
    #[inline]
    pub fn passes(self, incoming: &Depth, stored: &Stored) -> bool {
        let ord = match stored {
            Stored::Level(level) => incoming.cmp_integer(i128::from(*level)),
            Stored::Exact(value) => incoming.cmp_exact(value),
        };
        match self {
            DepthTest::Greater => ord == Ordering::Greater,
            DepthTest::Less => ord == Ordering::Less,
            DepthTest::GreaterEqual => ord != Ordering::Less,
            DepthTest::LessEqual => ord != Ordering::Greater,
            DepthTest::Always => true,
            DepthTest::Never => false,
        }
    }

    /// The comparison operator as printed: `>`, `<`, `≥` or `≤`; for
    /// `always` and `never`, which compare nothing, the word itself (use
    /// [`DepthTest::rule_text`] and [`DepthTest::outcome_text`] in sentences).
    pub fn symbol(self) -> &'static str {
        match self {
            DepthTest::Greater => ">",
            DepthTest::Less => "<",
            DepthTest::GreaterEqual => "≥",
            DepthTest::LessEqual => "≤",
            DepthTest::Always => "always",
            DepthTest::Never => "never",
        }
    }

    /// The rule in a heading's words: `z > stored`, or `every fragment
    /// passes`, `no fragment passes`.
    pub fn rule_text(self, lang: Lang) -> String {
        match self {
            DepthTest::Always => words!(lang, "rule-always"),
            DepthTest::Never => words!(lang, "rule-never"),
            other => words!(lang, "rule-compared", op = other.symbol()),
        }
    }

    /// A test's outcome in words, for `z` against `stored`: `43/4 > 10
    /// stored`, `43/4 is not > 10 stored`, or for the tests that compare
    /// nothing `43/4 (always passes; 10 stored)`.
    pub fn outcome_text(self, lang: Lang, z: &str, stored: &str, passed: bool) -> String {
        match (self, passed) {
            (DepthTest::Always | DepthTest::Never, _) => {
                words!(lang, "test-uncompared", z = z, test = self.symbol(), stored = stored)
            }
            (_, true) => words!(lang, "test-passed", z = z, op = self.symbol(), stored = stored),
            (_, false) => words!(lang, "test-failed", z = z, op = self.symbol(), stored = stored),
        }
    }

    /// The name used in scene files: `greater`, `less`, `greater-equal` or `less-equal`.
    pub fn name(self) -> &'static str {
        match self {
            DepthTest::Greater => "greater",
            DepthTest::Less => "less",
            DepthTest::GreaterEqual => "greater-equal",
            DepthTest::LessEqual => "less-equal",
            DepthTest::Always => "always",
            DepthTest::Never => "never",
        }
    }

    /// The test's name in the reader's language (the scene file's keyword
    /// is [`DepthTest::name`]).
    pub fn local_name(self, lang: Lang) -> String {
        crate::words::text(lang, &format!("depth-test-{}", self.name()), &[])
    }

    /// Whether a depth lies on the kept side of a cross-section at `section`
    /// (the Russian coursework: `z ≤ Zsection` when larger z is nearer; mirrored for `Less`).
    pub fn keeps_section(self, incoming: &Depth, section: Q) -> bool {
        let ord = incoming.cmp_exact(&Exact::Word(section));
        if self.larger_is_nearer() { ord != Ordering::Greater } else { ord != Ordering::Less }
    }

    /// The section comparison as printed: `≤` or `≥`.
    pub fn section_symbol(self) -> &'static str {
        if self.larger_is_nearer() { "≤" } else { "≥" }
    }
}

/// An exact depth: `whole + remainder/denominator` with `0 ≤ remainder <
/// denominator` (the floor and the fractional part of z) in 128 bits, as
/// every pixel of almost every polygon has it, or a big rational (not
/// reduced: reducing every pixel's depth would cost a gcd each) for a
/// polygon whose plane outgrows 128 bits (`crate::raster::big`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Depth(DepthValue);

#[derive(Debug, Clone, PartialEq, Eq)]
enum DepthValue {
    Word { whole: i128, remainder: i128, denominator: i128 },
    Big(Box<BigRational>),
}

impl Depth {
    /// The depth `numerator / denominator` (denominator non-zero, any sign).
    pub fn from_fraction(numerator: i128, denominator: i128) -> Depth {
        debug_assert!(denominator != 0, "depth with zero denominator: please report this bug");
        let (numerator, denominator) =
            if denominator < 0 { (-numerator, -denominator) } else { (numerator, denominator) };
        let (whole, remainder) = floor_div(numerator, denominator);
        Depth(DepthValue::Word { whole, remainder, denominator })
    }

    /// The depth `numerator / denominator` in big integers (denominator
    /// non-zero), held in 128 bits when both fit them.
    pub fn from_big(numerator: BigInt, denominator: BigInt) -> Depth {
        let (numerator, denominator) =
            if denominator.is_negative() { (-numerator, -denominator) } else { (numerator, denominator) };
        // Within the bounds every 128-bit depth keeps (see `rounded_word`).
        let words = numerator.to_i128().filter(|n| n.unsigned_abs() < 1 << 125);
        match (words, denominator.to_i128().filter(|d| *d < 1 << 124)) {
            (Some(n), Some(d)) => Depth::from_fraction(n, d),
            _ => Depth(DepthValue::Big(Box::new(BigRational::new_raw(numerator, denominator)))),
        }
    }

    /// The depth with an exact value.
    pub fn from_exact(value: Exact) -> Depth {
        match value {
            Exact::Word(q) => Depth::from_fraction(*q.numer(), *q.denom()),
            Exact::Big(big) => Depth(DepthValue::Big(big)),
        }
    }

    /// The value as `(numerator, denominator)`, denominator positive, not
    /// reduced, when it is held in 128 bits.
    pub fn fraction(&self) -> Option<(i128, i128)> {
        match self.0 {
            DepthValue::Word { whole, remainder, denominator } => Some((whole * denominator + remainder, denominator)),
            DepthValue::Big(_) => None,
        }
    }

    /// The exact value, reduced.
    pub fn value(&self) -> Exact {
        match &self.0 {
            DepthValue::Word { whole, remainder, denominator } => {
                Exact::Word(Q::new(whole * denominator + remainder, *denominator))
            }
            DepthValue::Big(big) => Exact::from(big.reduced()),
        }
    }

    /// Compares with an integer stored value.
    #[inline]
    pub fn cmp_integer(&self, stored: i128) -> Ordering {
        match &self.0 {
            DepthValue::Word { whole, remainder, .. } => {
                whole.cmp(&stored).then(if *remainder > 0 { Ordering::Greater } else { Ordering::Equal })
            }
            DepthValue::Big(big) => big.numer().cmp(&(big.denom() * stored)),
        }
    }

    /// Compares two exact depths without overflow.
    pub fn cmp_depth(&self, other: &Depth) -> Ordering {
        match (&self.0, &other.0) {
            (
                DepthValue::Word { whole, remainder, denominator },
                DepthValue::Word { whole: other_whole, remainder: other_remainder, denominator: other_denominator },
            ) => whole
                .cmp(other_whole)
                .then_with(|| cmp_fractions(*remainder, *denominator, *other_remainder, *other_denominator)),
            _ => self.to_big().cmp(&other.to_big()),
        }
    }

    /// The value as a big rational, not reduced.
    fn to_big(&self) -> BigRational {
        match &self.0 {
            DepthValue::Word { .. } => self.value().to_big(),
            DepthValue::Big(big) => (**big).clone(),
        }
    }

    /// Compares with an exact value without overflow.
    pub fn cmp_exact(&self, other: &Exact) -> Ordering {
        match (&self.0, other) {
            (DepthValue::Word { whole, remainder, denominator }, Exact::Word(other)) => {
                // Whole part and remainder by Euclid's division: `Ratio::floor`
                // overflows on a value near −2^127 (a CS 418 scene with w = 1e30 found it).
                let (numer, denom) = (*other.numer(), *other.denom());
                match whole.cmp(&numer.div_euclid(denom)) {
                    Ordering::Equal => cmp_fractions(*remainder, *denominator, numer.rem_euclid(denom), denom),
                    ord => ord,
                }
            }
            _ => self.to_big().cmp(&other.to_big()),
        }
    }

    /// Whether the depth lies in `front ..= rear` (a scene's depth range).
    pub fn within(&self, (front, rear): (Q, Q)) -> bool {
        !(self.cmp_exact(&Exact::Word(front)).is_lt() || self.cmp_exact(&Exact::Word(rear)).is_gt())
    }

    /// Rounded to the nearest integer, halves up (the book: "z is rounded to
    /// the nearest integer"; 10.5 becomes 11, −0.5 becomes 0).
    pub fn rounded(&self) -> BigInt {
        match &self.0 {
            DepthValue::Word { whole, remainder, denominator } => {
                BigInt::from(round_half_up(*whole, *remainder, *denominator))
            }
            // ⌊z + 1/2⌋ = ⌊(2n + d) / 2d⌋.
            DepthValue::Big(big) => (big.numer() * 2u32 + big.denom()).div_floor(&(big.denom() * 2u32)),
        }
    }

    /// [`Depth::rounded`] for a depth held in 128 bits.
    #[inline]
    fn rounded_word(&self) -> Option<i128> {
        match self.0 {
            DepthValue::Word { whole, remainder, denominator } => Some(round_half_up(whole, remainder, denominator)),
            DepthValue::Big(_) => None,
        }
    }

    /// What a quantized z-buffer stores: rounded half up, then saturated to
    /// `0 ..= depth_max`.
    #[inline]
    pub fn quantized(&self, depth_max: u32) -> u32 {
        match self.rounded_word() {
            Some(rounded) => rounded.clamp(0, i128::from(depth_max)) as u32,
            None => self.rounded().clamp(BigInt::zero(), BigInt::from(depth_max)).to_u32().expect("clamped"),
        }
    }

    /// Truncated (rounded down) to an integer, then saturated to
    /// `0 ..= depth_max` (tinyrenderer's `unsigned char` of a depth that is
    /// never negative).
    pub fn truncated(&self, depth_max: u32) -> u32 {
        let floor = match &self.0 {
            DepthValue::Word { whole, .. } => BigInt::from(*whole),
            DepthValue::Big(big) => big.floor().to_integer(),
        };
        floor.clamp(BigInt::zero(), BigInt::from(depth_max)).to_u32().expect("clamped")
    }

    /// What the z-buffer stores under `store`.
    pub fn stored(&self, store: DepthStore, depth_max: u32) -> Stored {
        match store {
            DepthStore::Quantized => Stored::Level(self.quantized(depth_max)),
            DepthStore::Truncated => Stored::Level(self.truncated(depth_max)),
            DepthStore::Exact => Stored::Exact(self.value()),
        }
    }
}

/// `whole + remainder/denominator` rounded half up.
/// `whole + remainder/denominator` (`0 ≤ remainder < denominator`) rounded
/// to the nearest integer, halves up: the one rounding rule of every path
/// (`depth_half_rounds_up`).
#[inline(always)]
pub(crate) fn round_half_up<T: Copy + std::ops::Add<Output = T> + PartialOrd + From<bool>>(
    whole: T,
    remainder: T,
    denominator: T,
) -> T {
    // remainder < denominator < 2^124 (plane::MAX_SCALED; Depth::from_big), so 2·remainder fits.
    whole + T::from(remainder + remainder >= denominator)
}

/// The depth test as the branch-free loops compare it, beside
/// [`DepthTest::passes`], which it equals (`branch_free_tests_are_the_tests`).
/// For `z = whole + remainder/denominator` (`0 ≤ remainder < denominator`)
/// and an integer stored `s`: `z > s ⇔ ⌈z⌉ > s`, `z ≥ s ⇔ ⌊z⌋ ≥ s`,
/// `z < s ⇔ ⌊z⌋ < s`, `z ≤ s ⇔ ⌈z⌉ ≤ s`; so each test is
/// `sign·(v − s) > threshold` with `v` the ceiling or the floor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BranchFreeTest {
    /// Whether `v` is the ceiling (else the floor).
    pub use_ceiling: bool,
    /// +1 when larger is nearer, −1 otherwise.
    pub sign: i64,
    /// 0 for a strict test, −1 for one that passes on equal depths.
    pub threshold: i64,
}

impl BranchFreeTest {
    /// `z > stored`, the book's test, as constants a loop is compiled with.
    pub const GREATER: BranchFreeTest = BranchFreeTest { use_ceiling: true, sign: 1, threshold: 0 };

    /// The constants of `test`.
    #[inline(always)]
    pub fn of(test: DepthTest) -> BranchFreeTest {
        let threshold = match test {
            // sign·(v − s) lies well inside ±2^62, so these decide alone.
            DepthTest::Always => i64::MIN,
            DepthTest::Never => i64::MAX,
            _ => -i64::from(test.equal_passes()),
        };
        BranchFreeTest {
            use_ceiling: matches!(test, DepthTest::Greater | DepthTest::LessEqual),
            sign: if test.larger_is_nearer() { 1 } else { -1 },
            threshold,
        }
    }

    /// Whether `whole + remainder/denominator` passes against `stored`.
    #[inline(always)]
    pub fn passes(self, whole: i64, remainder: i64, stored: u32) -> bool {
        let v = whole + i64::from(self.use_ceiling & (remainder != 0));
        self.sign * (v - i64::from(stored)) > self.threshold
    }
}

/// The exact depth along one scanline, stepped from pixel to pixel by the
/// seed's increment `z₁ = z − a/c` using a whole part and a remainder
/// (Bresenham-style), so no division happens per pixel and the result is
/// identical to evaluating the plane at every centre. `W` is the machine
/// integer the polygon runs on ([`Word`]).
#[derive(Debug, Clone, Copy)]
pub struct DepthStepper<W = i128> {
    whole: W,
    remainder: W,
    denominator: W,
    step_whole: W,
    step_remainder: W,
}

/// A [`DepthStepper`]'s state: the depth `whole + remainder/denominator`
/// (`0 ≤ remainder < denominator`) and the step per pixel
/// `step_whole + step_remainder/denominator`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StepperState<W> {
    /// The depth's whole part.
    pub whole: W,
    /// The depth's remainder.
    pub remainder: W,
    /// The denominator, positive.
    pub denominator: W,
    /// The step's whole part.
    pub step_whole: W,
    /// The step's remainder.
    pub step_remainder: W,
}

/// A polygon's plane prepared for stepping: the step per pixel split once
/// into whole part and remainder, and the depth numerator at any centre by
/// multiplication only, measured from vertex 1 so that the products stay as
/// small as the polygon (see [`Geometry::fits_i64`]).
#[derive(Debug, Clone, Copy)]
pub struct DepthPlane<W = i128> {
    /// −a, −b and `c·Z₁` of `N = c·Z₁ − a(X − X₁) − b(Y − Y₁)`, signs folded so the denominator `c·2D` is positive.
    minus_a: W,
    minus_b: W,
    at_first_vertex: W,
    /// `X₁` and `Y₁`, vertex 1's scaled x and y.
    x1: W,
    y1: W,
    denominator: W,
    half_unit: W,
    step_whole: W,
    step_remainder: W,
    /// The denominator's [`Word::reciprocal`], to find each span's start without a division.
    reciprocal: u64,
}

impl<W: Word> DepthPlane<W> {
    /// Prepares a polygon whose Newell `c` is non-zero (for `W = i64`, one
    /// that [`Geometry::fits_i64`]).
    #[inline(always)]
    pub fn new(geometry: &Geometry) -> DepthPlane<W> {
        debug_assert!(geometry.c() != 0, "depth of an edge-on polygon: please report this bug");
        // Every input and product here is within the bounds of Geometry::fits_i64
        // when W is i64, so the work is done in W.
        let [a, b, c] = geometry.normal;
        let [a, b, c] = [W::narrow(a), W::narrow(b), W::narrow(c)];
        let points: &[[i128; 3]] = &geometry.points;
        let [x1, y1, z1] = points[0];
        let [x1, y1, z1] = [W::narrow(x1), W::narrow(y1), W::narrow(z1)];
        let two_d = W::narrow(2 * geometry.denominator);
        // Signs folded so that the denominator c·2D is positive.
        let flip = c < W::ZERO;
        let signed = |v: W| if flip { W::ZERO - v } else { v };
        let denominator = signed(c) * two_d;
        let minus_a = signed(W::ZERO - a);
        let (step_whole, step_remainder) = (minus_a * two_d).floor_div(denominator);
        DepthPlane {
            minus_a,
            minus_b: signed(W::ZERO - b),
            at_first_vertex: signed(c) * z1,
            x1,
            y1,
            denominator,
            half_unit: W::narrow(geometry.denominator),
            step_whole,
            step_remainder,
            reciprocal: W::reciprocal(denominator),
        }
    }

    /// The part of the depth numerator that depends on the row: its value at
    /// `X = X₁` on the scanline at scaled height `scan_y`.
    #[inline]
    pub fn row_numerator(&self, scan_y: W) -> W {
        self.at_first_vertex + self.minus_b * (scan_y - self.y1)
    }

    /// What [`DepthPlane::row_numerator`] gains from one row to the next (2D in y).
    #[inline]
    pub fn row_step(&self) -> W {
        self.minus_b * (self.half_unit + self.half_unit)
    }

    /// A stepper at the centre of pixel `column` on the row whose
    /// [`DepthPlane::row_numerator`] is `row_numerator`.
    #[inline(always)]
    pub fn start_at(&self, row_numerator: W, column: u32) -> DepthStepper<W> {
        let column = W::narrow(i128::from(column));
        let centre_x = (column + column + W::ONE) * self.half_unit;
        let numerator = row_numerator + self.minus_a * (centre_x - self.x1);
        let (whole, remainder) = numerator.floor_div_by(self.denominator, self.reciprocal);
        DepthStepper {
            whole,
            remainder,
            denominator: self.denominator,
            step_whole: self.step_whole,
            step_remainder: self.step_remainder,
        }
    }
}

impl DepthStepper {
    /// Starts at `depth`, stepping by `step / denominator` per pixel (the
    /// depth's own positive denominator, [`Depth::fraction`]); every value
    /// reached must fit as the depth does. `None` for a depth beyond 128
    /// bits, which is stepped in big integers (`crate::raster::big`).
    pub fn from_depth(depth: &Depth, step: i128) -> Option<DepthStepper> {
        let DepthValue::Word { whole, remainder, denominator } = depth.0 else { return None };
        Some(DepthStepper::at(whole, remainder, denominator, step))
    }

    /// At `whole + remainder/denominator`, stepping by `step / denominator`.
    fn at(whole: i128, remainder: i128, denominator: i128, step: i128) -> DepthStepper {
        let (step_whole, step_remainder) = floor_div(step, denominator);
        DepthStepper { whole, remainder, denominator, step_whole, step_remainder }
    }

    /// Starts at the centre of pixel `column` on the scanline at scaled height
    /// `scan_y`, for a polygon whose Newell `c` is non-zero.
    ///
    /// In scaled units the depth at `(X, Y)` is
    /// `Z = Z₁ − (a(X − X₁) + b(Y − Y₁))/c` (the Russian coursework: `z = −(ax + by + d)/c`),
    /// and `z = Z / 2D`. Its numerator is bounded by `20nR³ < 2^123`.
    pub fn start(geometry: &Geometry, column: i128, scan_y: i128) -> DepthStepper {
        let [a, b, c] = geometry.normal;
        debug_assert!(c != 0, "depth of an edge-on polygon: please report this bug");
        let [x1, y1, z1] = geometry.points[0];
        let centre_x = (2 * column + 1) * geometry.denominator;
        let numerator = c * z1 - a * (centre_x - x1) - b * (scan_y - y1);
        // Signs folded so that the denominator c·2D is positive.
        let sign = c.signum();
        let (whole, remainder) = floor_div(sign * numerator, sign * c * geometry.scale());
        // One column is 2D scaled units: ΔZ = −a·2D/c, Δz = −a·2D/(c·2D).
        let step = -a * 2 * geometry.denominator;
        DepthStepper::at(whole, remainder, sign * c * geometry.scale(), sign * step)
    }
}

impl<W: Word> DepthStepper<W> {
    /// The state: the depth at the current centre as whole part and
    /// remainder over the denominator, and the step per pixel likewise.
    #[inline]
    pub fn state(&self) -> StepperState<W> {
        StepperState {
            whole: self.whole,
            remainder: self.remainder,
            denominator: self.denominator,
            step_whole: self.step_whole,
            step_remainder: self.step_remainder,
        }
    }

    /// The depth at the current pixel centre.
    #[inline]
    pub fn current(&self) -> Depth {
        Depth(DepthValue::Word {
            whole: self.whole.wide(),
            remainder: self.remainder.wide(),
            denominator: self.denominator.wide(),
        })
    }

    /// Moves one pixel to the right.
    #[inline]
    pub fn advance(&mut self) {
        self.whole += self.step_whole;
        self.remainder += self.step_remainder;
        if self.remainder >= self.denominator {
            self.remainder -= self.denominator;
            self.whole += W::ONE;
        }
    }
}

/// The exact depth at the centre of pixel `(column, row)` of a polygon whose
/// Newell `c` is non-zero, on any tier: as [`DepthStepper::start`] starts
/// there, or on the big-integer tier from the reduced plane,
/// `z = −(A(2x + 1) + B(2y + 1) + 2D) / 2C`, in big integers when that
/// outgrows 128 bits.
pub fn depth_at_centre(geometry: &Geometry, column: u32, row: u32) -> Depth {
    if let Some(polygon) = geometry.big() {
        return polygon.depth_at_centre(column, row);
    }
    DepthStepper::start(geometry, i128::from(column), crate::raster::scan::scanline_y(row, geometry.denominator))
        .current()
}

/// The exact depth of a polygon's plane at any point given in polygon units
/// (for reports: span ends, explanations), from the reduced plane
/// `z = −(Ax + By + D)/C` in big rationals. `None` when the plane has no z
/// term.
pub fn depth_at(geometry: &Geometry, x: &Exact, y: &Exact) -> Option<Exact> {
    let PlaneEquation { a, b, c, d } = geometry.plane();
    if c.is_zero() {
        return None;
    }
    let value = -(x.to_big() * a + y.to_big() * b + BigRational::from_integer(d)) / BigRational::from_integer(c);
    Some(Exact::from(value))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The constants the book's test is compiled with are its own.
    #[test]
    fn the_compiled_greater_test_is_the_greater_test() {
        assert_eq!(BranchFreeTest::GREATER, BranchFreeTest::of(DepthTest::Greater));
    }

    /// The branch-free form of every test decides as the test does, for
    /// depths around a stored level (whole parts and remainders over 4).
    #[cfg_attr(not(target_family = "wasm"), test)]
    #[cfg_attr(target_family = "wasm", wasm_bindgen_test::wasm_bindgen_test)]
    fn branch_free_tests_are_the_tests() {
        use num_rational::Ratio;
        let tests = [DepthTest::Greater, DepthTest::Less, DepthTest::GreaterEqual, DepthTest::LessEqual];
        for test in tests.into_iter().chain([DepthTest::Always, DepthTest::Never]) {
            for whole in 3..8i64 {
                for remainder in 0..4i64 {
                    let z = Ratio::new(i128::from(4 * whole + remainder), 4);
                    let incoming = Depth::from_fraction(*z.numer(), *z.denom());
                    let passes = test.passes(&incoming, &Stored::Level(5));
                    assert_eq!(BranchFreeTest::of(test).passes(whole, remainder, 5), passes, "{test:?} {z}");
                }
            }
        }
    }

    #[test]
    fn depth_half_rounds_up() {
        assert_eq!(Depth::from_fraction(21, 2).rounded(), BigInt::from(11));
        assert_eq!(Depth::from_fraction(-1, 2).rounded(), BigInt::from(0));
        assert_eq!(Depth::from_fraction(-3, 2).rounded(), BigInt::from(-1));
        assert_eq!(Depth::from_fraction(41, 4).rounded(), BigInt::from(10));
        assert_eq!(Depth::from_fraction(43, 4).rounded(), BigInt::from(11));
    }

    /// A stored exact value near −2^127 made `Ratio::floor` overflow (a
    /// panic with overflow checks, a wrong comparison without).
    #[test]
    fn exact_values_at_the_limit_compare_without_overflow() {
        let low = Exact::Word(Q::new(i128::MIN + 1, 3));
        assert_eq!(Depth::from_fraction(-1, 2).cmp_exact(&low), Ordering::Greater);
        assert_eq!(Depth::from_fraction(i128::MIN + 1, 3).cmp_exact(&low), Ordering::Equal);
        assert_eq!(Depth::from_fraction(i128::MIN + 2, 3).cmp_exact(&low), Ordering::Greater);
        let high = Exact::Word(Q::new(i128::MAX, 7));
        assert_eq!(Depth::from_fraction(i128::MAX - 1, 7).cmp_exact(&high), Ordering::Less);
        assert_eq!(Depth::from_fraction(-5, 2).cmp_exact(&Exact::Word(Q::new(-5, 2))), Ordering::Equal);
        assert_eq!(Depth::from_fraction(-5, 2).cmp_exact(&Exact::Word(Q::new(-7, 3))), Ordering::Less);
    }

    #[test]
    fn depth_saturates_at_both_ends() {
        assert_eq!(Depth::from_fraction(-7, 1).quantized(15), 0);
        assert_eq!(Depth::from_fraction(31, 2).quantized(15), 15);
        assert_eq!(Depth::from_fraction(99, 1).quantized(15), 15);
    }

    #[test]
    fn equal_depth_does_not_overwrite() {
        let ten = Depth::from_fraction(10, 1);
        let stored = Stored::Level(10);
        assert!(!DepthTest::Greater.passes(&ten, &stored));
        assert!(!DepthTest::Less.passes(&ten, &stored));
        assert!(DepthTest::Greater.passes(&Depth::from_fraction(41, 4), &stored));
        assert!(!DepthTest::Less.passes(&Depth::from_fraction(41, 4), &stored));
        assert!(DepthTest::Less.passes(&Depth::from_fraction(39, 4), &stored));
        // Exact stored values compare exactly too.
        let exact = Stored::Exact(Exact::Word(Q::new(41, 4)));
        assert!(!DepthTest::Less.passes(&Depth::from_fraction(82, 8), &exact));
        assert!(DepthTest::Less.passes(&Depth::from_fraction(81, 8), &exact));
    }

    #[test]
    fn equal_depth_overwrites_with_greater_equal_and_less_equal() {
        let stored = Stored::Level(10);
        for (z, greater_equal, less_equal) in [((10, 1), true, true), ((41, 4), true, false), ((39, 4), false, true)] {
            let z = Depth::from_fraction(z.0, z.1);
            assert_eq!(DepthTest::GreaterEqual.passes(&z, &stored), greater_equal, "{z:?} ≥ 10");
            assert_eq!(DepthTest::LessEqual.passes(&z, &stored), less_equal, "{z:?} ≤ 10");
        }
        // They clear and cut sections as their strict partners do.
        assert_eq!((DepthTest::GreaterEqual.clear_value(15), DepthTest::LessEqual.clear_value(15)), (0, 15));
        assert_eq!((DepthTest::GreaterEqual.section_symbol(), DepthTest::LessEqual.section_symbol()), ("≤", "≥"));
        assert_eq!((DepthTest::GreaterEqual.symbol(), DepthTest::LessEqual.symbol()), ("≥", "≤"));
    }

    #[test]
    fn exact_depth_beats_rounded_depth() {
        // The book's pixel (20, 17): z = 41/4 rounds to 10 but is still nearer than 10.
        let z = Depth::from_fraction(41, 4);
        assert!(DepthTest::Greater.passes(&z, &Stored::Level(10)));
        assert_eq!(z.quantized(15), 10);
    }

    #[test]
    fn section_keeps_the_far_side_including_the_plane() {
        let section = Q::from_integer(12);
        assert!(DepthTest::Greater.keeps_section(&Depth::from_fraction(12, 1), section));
        assert!(!DepthTest::Greater.keeps_section(&Depth::from_fraction(49, 4), section));
        assert!(DepthTest::Less.keeps_section(&Depth::from_fraction(49, 4), section));
        assert!(!DepthTest::Less.keeps_section(&Depth::from_fraction(47, 4), section));
    }

    #[test]
    fn stepping_matches_evaluation_at_every_centre() {
        let vertices: Vec<[Q; 3]> =
            [[1, 2, 7], [29, 5, -3], [11, 27, 13]].iter().map(|v| v.map(|c: i128| Q::from_integer(c))).collect();
        let geometry = Geometry::new(&vertices).unwrap();
        for row in 0..32i128 {
            let scan_y = (2 * row + 1) * geometry.denominator;
            let mut stepper = DepthStepper::start(&geometry, 0, scan_y);
            let plane = DepthPlane::<i128>::new(&geometry);
            let narrow = DepthPlane::<i64>::new(&geometry);
            for column in 0..32i128 {
                assert_eq!(
                    narrow.start_at(narrow.row_numerator(scan_y as i64), column as u32).current(),
                    plane.start_at(plane.row_numerator(scan_y), column as u32).current()
                );
                assert_eq!(plane.start_at(plane.row_numerator(scan_y), column as u32).current(), {
                    let mut fresh = DepthStepper::start(&geometry, column, scan_y);
                    let depth = fresh.current();
                    fresh.advance();
                    depth
                });
                let centre = |v: i128| Exact::Word(Q::new(2 * v + 1, 2));
                let expected = depth_at(&geometry, &centre(column), &centre(row)).unwrap();
                assert_eq!(stepper.current().value(), expected, "depth at (x={column}, y={row})");
                stepper.advance();
            }
        }
    }

    #[test]
    fn always_passes_and_never_does_not_whatever_is_stored() {
        for (z, stored) in
            [(Depth::from_fraction(41, 4), Stored::Level(10)), (Depth::from_fraction(1, 1), Stored::Level(15))]
        {
            assert!(DepthTest::Always.passes(&z, &stored));
            assert!(!DepthTest::Never.passes(&z, &stored));
        }
        assert_eq!(DepthTest::Always.outcome_text(Lang::En, "43/4", "10", true), "43/4 (always passes; 10 stored)");
        assert_eq!(DepthTest::Greater.outcome_text(Lang::En, "43/4", "11", false), "43/4 is not > 11 stored");
        assert_eq!(DepthTest::Never.rule_text(Lang::En), "no fragment passes");
    }
}
