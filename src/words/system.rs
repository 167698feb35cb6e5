//! What the system and the JSON reader say, in the reader's language: an
//! operating-system error's reason by its kind, and serde_json's messages by
//! their fixed shapes (`invalid type: integer `3`, expected a sequence at
//! line 1 column 14`). The tokens a message quotes (a field's name, a value)
//! stay as they are; a shape not known here is passed on unchanged.

use std::io::ErrorKind;

/// Why reading or writing a file failed, from the error's kind; the system's
/// own sentence (English) only for kinds without a message here.
pub fn io_reason(lang: crate::words::Lang, error: &std::io::Error) -> String {
    let key = match error.kind() {
        ErrorKind::NotFound => "io-not-found",
        ErrorKind::PermissionDenied => "io-permission-denied",
        ErrorKind::AlreadyExists => "io-already-exists",
        ErrorKind::IsADirectory => "io-is-a-directory",
        ErrorKind::NotADirectory => "io-not-a-directory",
        ErrorKind::StorageFull => "io-storage-full",
        ErrorKind::ReadOnlyFilesystem => "io-read-only",
        ErrorKind::InvalidData => "io-not-utf8",
        _ => return error.to_string(),
    };
    words!(lang, key)
}

/// A serde_json message in the reader's language.
pub fn json_reason(lang: crate::words::Lang, message: &str) -> String {
    let (body, place) = match message.rsplit_once(" at line ") {
        Some((body, place)) => match place.split_once(" column ") {
            Some((line, column)) if line.parse::<u64>().is_ok() && column.parse::<u64>().is_ok() => {
                (body, Some((line, column)))
            }
            _ => (message, None),
        },
        None => (message, None),
    };
    let body = json_body(lang, body);
    match place {
        Some((line, column)) => words!(lang, "json-at", message = body, line = line, column = column),
        None => body,
    }
}

/// A fact a serde visitor reports (`number-found-object`, or a number that
/// does not read, with the text it quotes), as a message key and its
/// arguments in a form no JSON message takes: [`json_reason`] words it in
/// the reader's language where the error is turned into zsim's, as serde's
/// own messages are.
pub fn fact(key: &str, args: &[(&str, &str)]) -> String {
    let mut out = format!("{FACT}{key}");
    for (name, value) in args {
        out.push_str(&format!("{FACT}{name}{NAME_END}{value}"));
    }
    out
}

const FACT: char = '\u{1f}';
const NAME_END: char = '\u{1e}';

/// The message of a [`fact`]; a `text` argument (a token from the file) is
/// cut short as every message quotes one.
fn fact_body(lang: crate::words::Lang, fact: &str) -> String {
    let mut parts = fact.split(FACT);
    let key = parts.next().unwrap_or_default();
    let args: Vec<(&str, crate::words::Arg)> = parts
        .filter_map(|part| part.split_once(NAME_END))
        .map(|(name, value)| match name {
            "text" => (name, crate::words::token(lang, value).into()),
            _ => (name, value.into()),
        })
        .collect();
    crate::words::text(lang, key, &args)
}

fn json_body(lang: crate::words::Lang, body: &str) -> String {
    if let Some(fact) = body.strip_prefix(FACT) {
        return fact_body(lang, fact);
    }
    if let Some(rest) = body.strip_prefix("invalid type: ")
        && let Some((found, expected)) = rest.split_once(", expected ")
    {
        return words!(lang, "json-invalid-type", found = found_kind(lang, found), expected = wanted(lang, expected));
    }
    if let Some(rest) = body.strip_prefix("invalid value: ")
        && let Some((found, expected)) = rest.split_once(", expected ")
    {
        return words!(lang, "json-invalid-value", found = found_kind(lang, found), expected = wanted(lang, expected));
    }
    if let Some(rest) = body.strip_prefix("invalid length ")
        && let Some((length, expected)) = rest.split_once(", expected ")
    {
        return words!(lang, "json-invalid-length", length = length, expected = wanted(lang, expected));
    }
    if let Some(field) = body.strip_prefix("missing field ") {
        return words!(lang, "json-missing-field", field = field);
    }
    if let Some(rest) = body.strip_prefix("unknown field ") {
        return match rest.split_once(", expected one of ") {
            Some((field, known)) => words!(lang, "json-unknown-field", field = field, known = known),
            None => words!(lang, "json-unknown-field-none", field = rest.split(',').next().unwrap_or(rest)),
        };
    }
    if let Some(rest) = body.strip_prefix("unknown variant ")
        && let Some((variant, known)) = rest.split_once(", expected one of ").or_else(|| rest.split_once(", expected "))
    {
        return words!(lang, "json-unknown-variant", variant = variant, known = known);
    }
    if let Some(field) = body.strip_prefix("duplicate field ") {
        return words!(lang, "json-duplicate-field", field = field);
    }
    if body.starts_with("EOF while parsing") {
        return words!(lang, "json-eof");
    }
    if let Some(token) = body.strip_prefix("expected ")
        && token.starts_with('`')
    {
        return words!(lang, "json-expected-token", token = token);
    }
    let key = match body {
        "expected value" => "json-expected-value",
        "expected ident" => "json-expected-value",
        "trailing characters" => "json-trailing",
        "trailing comma" => "json-trailing-comma",
        "key must be a string" => "json-key-string",
        "invalid number" => "json-invalid-number",
        "number out of range" => "json-number-range",
        "invalid escape" => "json-invalid-escape",
        "recursion limit exceeded" => "json-too-deep",
        _ if body.starts_with("control character") => "json-control",
        _ => return body.to_string(),
    };
    words!(lang, key)
}

/// serde's name for what was found: `integer `3``, `string "x"`, `sequence`.
fn found_kind(lang: crate::words::Lang, found: &str) -> String {
    let (kind, value) = match found.split_once(' ') {
        Some((kind, value)) if matches!(kind, "integer" | "string" | "boolean" | "floating") => (kind, value),
        _ => (found, ""),
    };
    let value = value.trim_start_matches("point ").to_string();
    match kind {
        "integer" => words!(lang, "json-found-integer", value = value),
        "floating" => words!(lang, "json-found-decimal", value = value),
        "string" => words!(lang, "json-found-string", value = value),
        "boolean" => words!(lang, "json-found-bool", value = value),
        "null" | "unit value" => words!(lang, "json-found-null"),
        "sequence" => words!(lang, "json-found-list"),
        "map" => words!(lang, "json-found-object"),
        _ => found.to_string(),
    }
}

/// What was expected, as serde or zsim's readers name it.
fn wanted(lang: crate::words::Lang, expected: &str) -> String {
    match expected {
        "a sequence" => words!(lang, "json-want-list"),
        "a string" => words!(lang, "json-want-string"),
        "a boolean" => words!(lang, "json-want-bool"),
        "a number, or a string holding a fraction or a decimal" => words!(lang, "json-want-number"),
        "a vertex [x, y, z], or [x, y, z, w] in clip space" => words!(lang, "json-want-vertex"),
        _ if expected.starts_with("struct ") || expected == "a map" => words!(lang, "json-want-object"),
        _ if ["u8", "u16", "u32", "u64", "usize", "i32", "i64"].contains(&expected) => {
            words!(lang, "json-want-whole")
        }
        _ => expected.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::words::Lang;

    #[test]
    fn json_messages_are_rendered_in_each_language_with_their_tokens_kept() {
        let message = "invalid type: integer `3`, expected a sequence at line 1 column 14";
        assert_eq!(
            json_reason(Lang::En, message),
            "invalid type: found the integer `3` where a list was expected (line 1, column 14)"
        );
        assert_eq!(
            json_reason(Lang::Ru, message),
            "неверный тип: найдено целое число `3`, а ожидался список (строка 1, позиция 14)"
        );
        let unknown = json_reason(Lang::Uk, "unknown field `colour`, expected one of `name`, `value`");
        assert_eq!(unknown, "невідоме поле `colour`; можливі поля: `name`, `value`");
        // A shape not known here passes unchanged rather than being guessed at.
        assert_eq!(json_reason(Lang::Zh, "something new"), "something new");
    }

    #[test]
    fn io_reasons_are_named_by_kind() {
        let missing = std::io::Error::from(ErrorKind::NotFound);
        assert_eq!((io_reason(Lang::Ru, &missing)), "нет такого файла или папки");
        assert_eq!((io_reason(Lang::En, &missing)), "no such file or folder");
    }
}
