//! Text made safe for where it is shown: one escaper per format, so that a name, an id or a
//! path read from a file can neither drive a terminal nor add markup to a document.
//!
//! | where the text goes | escaper |
//! | --- | --- |
//! | a terminal line (errors, warnings, stdout) | [`visible`], [`visible_lines`] |
//! | JSON printed on a terminal | [`json_visible`] |
//! | JSON inside an HTML `<script>` element | [`json_in_html`] |
//! | XML and HTML (pages, schematics, MJCF) | [`escape`] |
//! | SVG text written by a library that escapes markup itself (plotters) | [`visible`] |
//! | Markdown text (prose, table cells) | [`markdown`] |
//! | a Markdown code span | [`markdown_code`] |
//!
//! Every escaper writes the [hidden](is_hidden) characters — control characters (line breaks
//! and escape sequences included) and the invisible characters that reorder or hide text
//! (bidirectional overrides, zero-width characters) — as visible Rust escapes (`\n`,
//! `\u{1b}`, `\u{202e}`), or as `\uXXXX` in JSON, then the format's own markup characters.

use std::borrow::Cow;
use std::fmt::Write as _;

/// Whether `c` must not reach a reader raw: a control character (C0, DEL, C1), an invisible
/// character that changes how the text around it is shown (bidirectional embeddings,
/// overrides, isolates and marks, zero-width characters, the BOM, the line and paragraph
/// separators, the Mongolian vowel separator, interlinear annotations, the tag characters),
/// or one of the two non-characters XML 1.0 forbids (U+FFFE, U+FFFF).
#[must_use]
pub fn is_hidden(c: char) -> bool {
    c.is_control()
        || matches!(
            c,
            '\u{061c}'
                | '\u{180e}'
                | '\u{200b}'..='\u{200f}'
                | '\u{2028}'..='\u{202e}'
                | '\u{2060}'..='\u{206f}'
                | '\u{feff}'
                | '\u{fff9}'..='\u{fffb}'
                | '\u{fffe}'..='\u{ffff}'
                | '\u{e0000}'..='\u{e007f}'
        )
}

/// Writes the hidden character `c` as its Rust escape: `\n`, `\t`, `\0`, `\u{1b}`, `\u{202e}`.
fn push_escape(out: &mut String, c: char) {
    if c.is_control() {
        out.extend(c.escape_debug());
    } else {
        let _ = write!(out, "\\u{{{:x}}}", u32::from(c));
    }
}

/// `text` with every character for which `escaped` holds written by `escape`; borrowed when
/// there is none.
fn replace(
    text: &str,
    escaped: impl Fn(char) -> bool,
    escape: impl Fn(&mut String, char),
) -> Cow<'_, str> {
    let Some(first) = text.find(&escaped) else {
        return Cow::Borrowed(text);
    };
    let mut out = String::with_capacity(text.len() + 16);
    out.push_str(&text[..first]);
    for c in text[first..].chars() {
        if escaped(c) {
            escape(&mut out, c);
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

/// `text` as one line that cannot drive a terminal or reorder the text around it: every
/// [hidden](is_hidden) character, line breaks included, written as its Rust escape (`\n`,
/// `\u{1b}`, `\u{202e}`).
///
/// ```
/// assert_eq!(kinsyn::markup::visible("a\u{1b}[31mb\n\u{202e}"), r"a\u{1b}[31mb\n\u{202e}");
/// ```
#[must_use]
pub fn visible(text: &str) -> Cow<'_, str> {
    replace(text, is_hidden, push_escape)
}

/// `text` as lines for a terminal: as [`visible`], but the line breaks (`\n`) and tabs that
/// lay the text out are kept.
#[must_use]
pub fn visible_lines(text: &str) -> Cow<'_, str> {
    replace(
        text,
        |c| is_hidden(c) && c != '\n' && c != '\t',
        push_escape,
    )
}

/// Writes `c` as a JSON escape: `\uXXXX`, two of them (a surrogate pair) beyond the BMP.
fn push_json_escape(out: &mut String, c: char) {
    let mut units = [0u16; 2];
    for unit in c.encode_utf16(&mut units) {
        let _ = write!(out, "\\u{unit:04x}");
    }
}

/// JSON text that shows no hidden character raw: each one inside a string written as a
/// `\uXXXX` escape, which JSON reads back as the same character. The whitespace between
/// tokens (`\n`, `\t`, `\r`, as a pretty printer lays them out) is kept; every other hidden
/// character of JSON text is inside a string, so the text stays valid JSON with the same value.
#[must_use]
pub fn json_visible(json: &str) -> Cow<'_, str> {
    replace(
        json,
        |c| is_hidden(c) && !matches!(c, '\n' | '\t' | '\r'),
        push_json_escape,
    )
}

/// JSON text to put inside an HTML `<script>` element: as [`json_visible`], and `<`, `>` and
/// `&` (which occur only inside strings) as `\u003c`, `\u003e`, `\u0026`, so that no
/// `</script>` or `<!--` can end or change the element.
#[must_use]
pub fn json_in_html(json: &str) -> String {
    replace(
        json,
        |c| matches!(c, '<' | '>' | '&') || (is_hidden(c) && !matches!(c, '\n' | '\t' | '\r')),
        push_json_escape,
    )
    .into_owned()
}

/// `text` escaped for XML and HTML element content and quoted attributes: the five markup
/// characters as entities, and the [hidden](is_hidden) characters (which XML 1.0 mostly does
/// not allow) as visible Rust escapes (`\u{1b}`), so that two names differing in them stay
/// different.
///
/// ```
/// assert_eq!(kinsyn::markup::escape("<a b=\"c\">&\u{0}"), r"&lt;a b=&quot;c&quot;&gt;&amp;\0");
/// ```
#[must_use]
pub fn escape(text: &str) -> String {
    replace(
        text,
        |c| matches!(c, '&' | '<' | '>' | '"' | '\'') || is_hidden(c),
        |out, c| match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => push_escape(out, c),
        },
    )
    .into_owned()
}

/// Whether `c` means something to Markdown (the `CommonMark` syntax, and GitHub's tables,
/// strikethrough and math) where it may stand in a line of text: it is written with a
/// backslash.
fn is_markdown_punctuation(c: char) -> bool {
    matches!(
        c,
        '\\' | '`' | '*' | '_' | '[' | ']' | '|' | '~' | '$' | '#' | '!'
    )
}

/// `text` as Markdown text, in prose or a table cell: one line (the [hidden](is_hidden)
/// characters, line breaks included, as their Rust escapes, those escapes' backslashes
/// escaped in turn), `<`, `>` and `&` as HTML entities (no raw HTML, no entity made up of the
/// text), and `\`, `` ` ``, `*`, `_`, `[`, `]`, `|`, `~`, `$`, `#`, `!` behind a backslash
/// (no emphasis, code, link, image, table cell, strikethrough or math made up of the text).
///
/// ```
/// assert_eq!(kinsyn::markup::markdown("a|b <i>*c*</i>"), r"a\|b &lt;i&gt;\*c\*&lt;/i&gt;");
/// ```
#[must_use]
pub fn markdown(text: &str) -> String {
    let shown = visible(text);
    replace(
        &shown,
        |c| is_markdown_punctuation(c) || matches!(c, '<' | '>' | '&'),
        |out, c| match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            c => {
                out.push('\\');
                out.push(c);
            }
        },
    )
    .into_owned()
}

/// `text` as a whole Markdown code span (backticks included), shown as it is: one line (the
/// [hidden](is_hidden) characters as their Rust escapes), fenced by one backtick more than the
/// longest run of backticks in it (padded with a space when it starts or ends with one), and
/// each `|` written `\|`, which a GitHub table cell reads as `|` (a span outside a table shows
/// the backslash). Nothing in a code span is markup: no HTML, entity or emphasis.
///
/// ```
/// assert_eq!(kinsyn::markup::markdown_code("a`b"), "``a`b``");
/// assert_eq!(kinsyn::markup::markdown_code("X(z)"), "`X(z)`");
/// ```
#[must_use]
pub fn markdown_code(text: &str) -> String {
    let shown = visible(text);
    let shown = replace(&shown, |c| c == '|', |out, _| out.push_str("\\|"));
    let longest = shown.split(|c| c != '`').map(str::len).max().unwrap_or(0);
    let fence = "`".repeat(longest + 1);
    let pad = if shown.starts_with('`') || shown.ends_with('`') {
        " "
    } else {
        ""
    };
    format!("{fence}{pad}{shown}{pad}{fence}")
}
