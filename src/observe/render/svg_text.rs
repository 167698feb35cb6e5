//! Text in the figures' SVG: escaped for XML, and measured the way the
//! figures lay it out.

/// Whether a character is one of Chinese's wide ones (from U+2E80 on),
/// which take about two columns and may be broken between.
pub(super) fn is_wide(c: char) -> bool {
    u32::from(c) >= 0x2E80
}

/// Text for SVG: markup's special characters as entities, and every
/// character XML does not allow (control characters but tab and line ends,
/// U+FFFE, U+FFFF) as U+FFFD, so that any name or title gives a valid file.
pub(crate) fn escape(text: &str) -> String {
    let allowed =
        |c: char| matches!(c, '\t' | '\n' | '\r' | '\u{20}'..='\u{D7FF}' | '\u{E000}'..='\u{FFFD}' | '\u{10000}'..);
    text.chars()
        .map(|c| if allowed(c) { c } else { char::REPLACEMENT_CHARACTER })
        .collect::<String>()
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
