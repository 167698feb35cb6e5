//! Numbers as a scene file writes them: exact, from a JSON number's digits
//! or from a string holding a fraction or a decimal.

use serde::Deserialize;
use serde::de::Error as _;

use crate::numbers::{Exact, Q, parse_number};

/// An exact number as written in a scene file (a setting: a 128-bit
/// fraction, at most 30 significant digits).
#[derive(Debug, Clone, Copy)]
pub(super) struct Number(pub(super) Q);

/// A vertex coordinate as written: exact, of any size up to
/// [`crate::numbers::MAX_BIG_DIGITS`] digits.
#[derive(Debug, Clone)]
pub(super) struct Coordinate(pub(super) Exact);

/// How a number of each kind is read from its text or a JSON integer.
pub(super) trait ReadNumber: Sized {
    fn parse(text: &str) -> Result<Self, crate::numbers::NumberError>;
    fn integer(value: i128) -> Self;
}

impl ReadNumber for Number {
    fn parse(text: &str) -> Result<Number, crate::numbers::NumberError> {
        parse_number(text).map(Number)
    }

    fn integer(value: i128) -> Number {
        Number(Q::from_integer(value))
    }
}

impl ReadNumber for Coordinate {
    fn parse(text: &str) -> Result<Coordinate, crate::numbers::NumberError> {
        crate::numbers::parse_exact(text).map(Coordinate)
    }

    fn integer(value: i128) -> Coordinate {
        Coordinate(Exact::Word(Q::from_integer(value)))
    }
}

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Number, D::Error> {
        deserializer.deserialize_any(NumberVisitor(std::marker::PhantomData))
    }
}

impl<'de> Deserialize<'de> for Coordinate {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Coordinate, D::Error> {
        deserializer.deserialize_any(NumberVisitor(std::marker::PhantomData))
    }
}

/// The key under which serde_json's `arbitrary_precision` hands over a JSON
/// number's digits (its private number token).
const NUMBER_TOKEN: &str = "$serde_json::private::Number";

/// Reads a number straight from the parser, without building a JSON value:
/// a JSON number's digits, or a string holding a fraction or a decimal.
struct NumberVisitor<T>(std::marker::PhantomData<T>);

impl<'de, T: ReadNumber> serde::de::Visitor<'de> for NumberVisitor<T> {
    type Value = T;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a number, or a string holding a fraction or a decimal")
    }

    fn visit_str<E: serde::de::Error>(self, text: &str) -> Result<T, E> {
        T::parse(text).map_err(|e| E::custom(e.fact()))
    }

    fn visit_i64<E: serde::de::Error>(self, value: i64) -> Result<T, E> {
        Ok(T::integer(i128::from(value)))
    }

    fn visit_u64<E: serde::de::Error>(self, value: u64) -> Result<T, E> {
        Ok(T::integer(i128::from(value)))
    }

    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<T, A::Error> {
        // The key and the digits are looked at where the parser holds them: a
        // large scene is nearly all numbers, and no string is built for either.
        match map.next_key_seed(IsNumberToken)? {
            Some(true) => map.next_value_seed(DigitsSeed(std::marker::PhantomData)),
            _ => Err(A::Error::custom(crate::words::fact("number-found-object", &[]))),
        }
    }

    fn visit_bool<E: serde::de::Error>(self, _: bool) -> Result<T, E> {
        Err(E::custom(crate::words::fact("number-found-bool", &[])))
    }

    fn visit_unit<E: serde::de::Error>(self) -> Result<T, E> {
        Err(E::custom(crate::words::fact("number-found-null", &[])))
    }

    fn visit_seq<A: serde::de::SeqAccess<'de>>(self, _: A) -> Result<T, A::Error> {
        Err(A::Error::custom(crate::words::fact("number-found-list", &[])))
    }
}

/// Whether a map's key is serde_json's number token, without copying it.
struct IsNumberToken;

impl<'de> serde::de::DeserializeSeed<'de> for IsNumberToken {
    type Value = bool;

    fn deserialize<D: serde::Deserializer<'de>>(self, deserializer: D) -> Result<bool, D::Error> {
        deserializer.deserialize_str(self)
    }
}

impl serde::de::Visitor<'_> for IsNumberToken {
    type Value = bool;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a key")
    }

    fn visit_str<E: serde::de::Error>(self, key: &str) -> Result<bool, E> {
        Ok(key == NUMBER_TOKEN)
    }
}

/// A number token's digits, parsed where the parser holds them.
struct DigitsSeed<T>(std::marker::PhantomData<T>);

impl<'de, T: ReadNumber> serde::de::DeserializeSeed<'de> for DigitsSeed<T> {
    type Value = T;

    fn deserialize<D: serde::Deserializer<'de>>(self, deserializer: D) -> Result<T, D::Error> {
        deserializer.deserialize_str(self)
    }
}

impl<T: ReadNumber> serde::de::Visitor<'_> for DigitsSeed<T> {
    type Value = T;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a number's digits")
    }

    fn visit_str<E: serde::de::Error>(self, digits: &str) -> Result<T, E> {
        T::parse(digits).map_err(|e| E::custom(e.fact()))
    }
}
