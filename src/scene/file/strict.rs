//! A polygon's text of the common shape, read straight from its bytes.
//!
//! serde reads a polygon through its general machinery and, with
//! `arbitrary_precision`, hands over each number as a string it builds for
//! it: on a large scene that was most of the reading. A polygon of the common
//! shape is read here from its bytes, each number where it stands, by the
//! very rules serde follows ([`coordinate`]). The shape, in JSON's grammar
//! (white space allowed wherever JSON allows it):
//!
//! ```text
//! polygon  = "{" member ("," member)* "}"     each key at most once
//! member   = "\"name\"" ":" string            no escape, no control character
//!          | "\"value\"" ":" digits           fits u64
//!          | "\"vertices\"" ":" "[" (vertex ("," vertex)*)? "]"
//! vertex   = "[" number "," number "," number ("," number)? "]"
//! number   = "-"? integer ("." digits)?       no exponent
//! ```
//!
//! Anything else, valid or not (an escape, an exponent, `opacity`, `null`,
//! a key twice), gives `None`, and serde reads the polygon and names what is
//! wrong: this reader never accepts a text serde refuses, nor reads one
//! otherwise (a proptest holds it to serde's reading).

use super::{Coordinate, PolygonFile, ReadNumber, VerticesFile, after_space};
use crate::numbers::Exact;

/// The polygon of the common shape that `text` holds; `None` for any other
/// text, valid or not.
pub(super) fn polygon(text: &str) -> Option<PolygonFile> {
    let mut json = Cursor { bytes: text.as_bytes(), at: 0 };
    let (mut name, mut value, mut vertices) = (None, None, None);
    json.eat(b'{')?;
    loop {
        let key = json.string()?;
        json.eat(b':')?;
        match key {
            b"name" if name.is_none() => name = Some(std::str::from_utf8(json.string()?).ok()?.to_owned()),
            b"value" if value.is_none() => value = Some(unsigned(json.number()?)?),
            b"vertices" if vertices.is_none() => vertices = Some(vertex_list(&mut json)?),
            _ => return None,
        }
        if json.eat(b',').is_none() {
            break;
        }
    }
    json.eat(b'}')?;
    json.space();
    (json.at == json.bytes.len()).then_some(())?;
    Some(PolygonFile { name, value: value?, opacity: None, vertices: vertices? })
}

/// A place in a polygon's bytes.
struct Cursor<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Cursor<'a> {
    /// Past JSON's white space.
    fn space(&mut self) {
        self.at = after_space(self.bytes, self.at);
    }

    /// Past white space and `byte`, when `byte` is next.
    fn eat(&mut self, byte: u8) -> Option<()> {
        self.space();
        (self.bytes.get(self.at) == Some(&byte)).then(|| self.at += 1)
    }

    /// A string's bytes between its quotes, when it has no escape and no
    /// control character (which JSON refuses): then they are the string.
    fn string(&mut self) -> Option<&'a [u8]> {
        self.eat(b'"')?;
        let rest = &self.bytes[self.at..];
        let length = memchr::memchr2(b'"', b'\\', rest)?;
        let string = &rest[..length];
        if rest[length] != b'"' || string.iter().any(|&b| b < 0x20) {
            return None;
        }
        self.at += length + 1;
        Some(string)
    }

    /// A JSON number without an exponent, `-?integer(.digits)?`, the
    /// integer `0` or without a leading zero.
    fn number(&mut self) -> Option<Written<'a>> {
        self.space();
        let start = self.at;
        let negative = self.bytes.get(self.at) == Some(&b'-');
        self.at += usize::from(negative);
        let digits_start = self.at;
        // The integer's value as the digits go by: kept when there are at
        // most 18 (which fit `i64` whatever the sign), else unused.
        let mut integer = 0_i64;
        while let Some(&byte @ b'0'..=b'9') = self.bytes.get(self.at) {
            integer = integer.wrapping_mul(10).wrapping_add(i64::from(byte - b'0'));
            self.at += 1;
        }
        let digits = self.at - digits_start;
        if digits == 0 || (digits > 1 && self.bytes[digits_start] == b'0') {
            return None;
        }
        let fraction = self.bytes.get(self.at) == Some(&b'.');
        if fraction {
            self.at += 1;
            if self.digits() == 0 {
                return None;
            }
        }
        if matches!(self.bytes.get(self.at), Some(b'e' | b'E')) {
            return None;
        }
        let integer = (!fraction && digits <= 18).then(|| if negative { -integer } else { integer });
        Some(Written { text: &self.bytes[start..self.at], negative, fraction, integer })
    }

    /// Past a run of digits; how many.
    fn digits(&mut self) -> usize {
        let count = self.bytes[self.at..].iter().take_while(|b| b.is_ascii_digit()).count();
        self.at += count;
        count
    }
}

/// A number as written in a polygon's text.
struct Written<'a> {
    text: &'a [u8],
    negative: bool,
    /// Whether it has a `.` and digits after it.
    fraction: bool,
    /// Its value, when it is an integer of at most 18 digits.
    integer: Option<i64>,
}

/// An integer of digits only that fits 64 bits, as serde reads one for a
/// `u64` (a sign or a fraction does not parse).
fn unsigned(number: Written) -> Option<u64> {
    std::str::from_utf8(number.text).ok()?.parse().ok()
}

/// `[[x, y, z], …]` or `[[x, y, z, w], …]`, each vertex into its list.
fn vertex_list(json: &mut Cursor) -> Option<VerticesFile> {
    let mut vertices = VerticesFile::default();
    json.eat(b'[')?;
    if json.eat(b']').is_some() {
        return Some(vertices);
    }
    loop {
        json.eat(b'[')?;
        let x = coordinate(json.number()?)?;
        json.eat(b',')?;
        let y = coordinate(json.number()?)?;
        json.eat(b',')?;
        let z = coordinate(json.number()?)?;
        if json.eat(b',').is_some() {
            let w = coordinate(json.number()?)?;
            json.eat(b']')?;
            vertices.clip.push([x, y, z, w]);
        } else {
            json.eat(b']')?;
            // A triangle's three, not the four a first push would make room for.
            if vertices.xyz.capacity() == 0 {
                vertices.xyz.reserve_exact(3);
            }
            vertices.xyz.push([x, y, z]);
        }
        if json.eat(b',').is_none() {
            break;
        }
    }
    json.eat(b']')?;
    Some(vertices)
}

/// A number as [`Cursor::number`] finds it, read as serde with
/// `arbitrary_precision` reads it into a [`Coordinate`]: an integer that fits
/// `u64` or `i64` as that integer (serde reads `-0` from its text: 0 too),
/// any other from its text, which serde hands over as written; `None` when
/// that text does not parse (serde then names the error).
fn coordinate(number: Written) -> Option<Exact> {
    let Written { text, negative, fraction, integer } = number;
    let integer = match integer {
        // Most coordinates.
        Some(integer) => Some(i128::from(integer)),
        None if fraction => None,
        None => {
            let text = std::str::from_utf8(text).ok()?;
            if negative { text.parse::<i64>().ok().map(i128::from) } else { text.parse::<u64>().ok().map(i128::from) }
        }
    };
    match integer {
        Some(integer) => Some(Coordinate::integer(integer).0),
        None => Coordinate::parse(std::str::from_utf8(text).ok()?).ok().map(|coordinate| coordinate.0),
    }
}
