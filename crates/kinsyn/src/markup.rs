//! Text for XML and HTML documents (the catalogue site's pages and schematics, MuJoCo's MJCF).

/// `text` escaped for XML and HTML element content and quoted attributes: the five markup
/// characters as entities, and control characters (which XML 1.0 does not allow) as spaces.
#[must_use]
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c if c.is_control() => out.push(' '),
            c => out.push(c),
        }
    }
    out
}
