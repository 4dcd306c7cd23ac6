//! What reaches the user: results on stdout that stop quietly when the reader goes away, and
//! errors and warnings on stderr that are always one line and never drive the terminal.

use std::fmt::Write as _;
use std::io::{self, Write};

/// `message` made safe for one line of a terminal: line breaks, escape sequences and every
/// other control or bidirectional-formatting character are written as Rust escapes (`\n`,
/// `\u{1b}`, `\u{202e}`), so that echoed input can neither add lines nor reorder or recolour
/// the text around it.
#[must_use]
pub fn one_line(message: &str) -> String {
    let mut s = String::with_capacity(message.len());
    for c in message.chars() {
        if c.is_control() {
            s.extend(c.escape_debug());
        } else if is_format(c) {
            let _ = write!(s, "\\u{{{:x}}}", u32::from(c));
        } else {
            s.push(c);
        }
    }
    s
}

/// Invisible characters that change how the text around them is shown: bidirectional
/// embeddings, overrides and isolates, zero-width characters, the BOM and the line and
/// paragraph separators.
fn is_format(c: char) -> bool {
    matches!(
        c,
        '\u{061c}'
            | '\u{200b}'..='\u{200f}'
            | '\u{2028}'..='\u{202e}'
            | '\u{2060}'..='\u{206f}'
            | '\u{feff}'
            | '\u{fff9}'..='\u{fffb}'
    )
}

/// Writes `text` to stdout. A reader that has gone away (`kinsyn … | head`) is not an error:
/// the command ends quietly, as the conventional SIGPIPE behaviour would.
pub fn print(text: &str) -> io::Result<()> {
    let mut out = io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

/// Runs `work` with a spinner and `message` on stderr, shown only when stderr is a terminal
/// (so that scripts and tests see nothing) and cleared when the work is done.
pub fn working<T>(message: &str, work: impl FnOnce() -> T) -> T {
    let spinner = indicatif::ProgressBar::new_spinner().with_message(message.to_string());
    spinner.enable_steady_tick(std::time::Duration::from_millis(120));
    let result = work();
    spinner.finish_and_clear();
    result
}

/// A progress bar over `count` items (`unit`: "paths", "lock subsets") on stderr, labelled
/// `message`. indicatif hides it (draws nothing) when stderr is not a terminal, so pipes, files
/// and tests see only the output and the errors.
pub fn progress(count: usize, unit: &str, message: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(count as u64);
    if let Ok(style) = indicatif::ProgressStyle::with_template(&format!(
        "{{msg}} [{{bar:30}}] {{pos}}/{{len}} {unit}, {{elapsed}} elapsed, about {{eta}} left"
    )) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message(message.to_string());
    bar
}

/// Prints `kinsyn: error: MESSAGE` as one line on stderr.
pub fn error(message: &str) {
    line(&format!("kinsyn: error: {}", one_line(message)));
}

/// Prints `warning: MESSAGE` as one line on stderr.
pub fn warning(message: &str) {
    line(&format!("warning: {}", one_line(message)));
}

/// One line on stderr; a closed stderr is ignored (there is nowhere left to report it).
fn line(text: &str) {
    let _ = writeln!(io::stderr().lock(), "{text}");
}
