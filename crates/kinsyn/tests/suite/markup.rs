//! The escapers of text read from files (src/markup.rs): no hidden character and no markup of
//! the input left in terminal text, JSON, XML, HTML or Markdown, with the JSON's value unchanged.

use kinsyn::markup::{
    escape, is_hidden, json_in_html, json_visible, markdown, markdown_code, visible, visible_lines,
};
use std::borrow::Cow;

/// A hostile name: markup, a terminal colour, NUL, a right-to-left override, a line break.
const HOSTILE: &str = "T1-001\"><script>alert(1)</script>|*x*_`[l](j)`\u{1b}[31m\u{0}\u{202e}\n";

#[test]
fn hidden_characters_are_controls_and_invisible_formatting() {
    for c in ['\u{0}', '\n', '\t', '\u{1b}', '\u{7f}', '\u{85}', '\u{9f}'] {
        assert!(is_hidden(c), "{c:?}");
    }
    // The bidirectional controls of Unicode's UAX #9 (ALM, LRM, RLM, LRE…RLO, LRI…PDI).
    for c in [
        '\u{061c}', '\u{200e}', '\u{200f}', '\u{202a}', '\u{202b}', '\u{202c}', '\u{202d}',
        '\u{202e}', '\u{2066}', '\u{2067}', '\u{2068}', '\u{2069}',
    ] {
        assert!(is_hidden(c), "{c:?}");
    }
    for c in ['\u{200b}', '\u{feff}', '\u{2028}', '\u{e0041}', '\u{fffe}'] {
        assert!(is_hidden(c), "{c:?}");
    }
    for c in ['a', ' ', 'é', 'λ', '≤', '→', '—', '−', '\u{a0}', '文'] {
        assert!(!is_hidden(c), "{c:?}");
    }
}

#[test]
fn visible_text_has_no_hidden_character_and_keeps_the_rest() {
    let shown = visible(HOSTILE);
    assert!(!shown.chars().any(is_hidden), "{shown}");
    assert!(shown.ends_with(r"\u{1b}[31m\0\u{202e}\n"), "{shown}");
    assert!(matches!(visible("plain λ ≤ 3"), Cow::Borrowed(_)));
    let lines = visible_lines("a\tb\nc\r\u{1b}d");
    assert_eq!(lines, "a\tb\nc\\r\\u{1b}d");
}

#[test]
fn json_stays_json_with_the_same_value() {
    let value = serde_json::json!({ "name": HOSTILE, "wide": "\u{e0041}\u{85}" });
    let text = serde_json::to_string_pretty(&value).unwrap();
    let shown = json_visible(&text);
    assert!(!shown.chars().any(|c| is_hidden(c) && c != '\n'), "{shown}");
    assert!(shown.contains(r"\u202e") && shown.contains(r"\udb40\udc41"));
    let back: serde_json::Value = serde_json::from_str(&shown).unwrap();
    assert_eq!(back, value);
    let html = json_in_html(&text);
    assert!(!html.contains('<') && !html.contains('>') && !html.contains('&'));
    let back: serde_json::Value = serde_json::from_str(&html).unwrap();
    assert_eq!(back, value);
}

#[test]
fn xml_text_has_no_markup_and_no_character_xml_forbids() {
    let text = escape(HOSTILE);
    for raw in ['<', '>', '"', '\''] {
        assert!(!text.contains(raw), "{raw} in {text}");
    }
    // Every '&' starts one of the entities written.
    for (i, _) in text.match_indices('&') {
        let rest = &text[i..];
        assert!(
            ["&amp;", "&lt;", "&gt;", "&quot;", "&#39;"]
                .iter()
                .any(|e| rest.starts_with(e)),
            "{rest}"
        );
    }
    assert!(!text.chars().any(is_hidden), "{text}");
    // Names that differ only in hidden characters stay different.
    assert_ne!(escape("a\u{1}"), escape("a\u{2}"));
}

#[test]
fn markdown_text_has_no_markup_from_the_input() {
    let md = markdown(HOSTILE);
    assert!(!md.contains('<') && !md.contains('>'), "{md}");
    assert!(!md.chars().any(is_hidden), "{md}");
    // Each markup character is escaped: preceded by an odd number of backslashes.
    let chars: Vec<char> = md.chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        if matches!(c, '|' | '*' | '_' | '`' | '[' | ']') {
            let slashes = chars[..i].iter().rev().take_while(|&&b| b == '\\').count();
            assert_eq!(slashes % 2, 1, "{c} at {i} in {md}");
        }
    }
    assert_eq!(markdown(r"a\b"), r"a\\b");
    assert_eq!(markdown("\u{1b}"), r"\\u{1b}");
}

#[test]
fn a_code_span_cannot_be_left_from_inside() {
    let span = markdown_code(HOSTILE);
    assert!(!span.chars().any(is_hidden), "{span}");
    // The fence is longer than any run of backticks inside.
    assert!(span.starts_with("``") && !span.starts_with("```"), "{span}");
    assert!(!span.replace("\\|", "").contains('|'), "{span}");
    assert_eq!(markdown_code("`"), "`` ` ``");
    assert_eq!(markdown_code("a|b"), r"`a\|b`");
}
