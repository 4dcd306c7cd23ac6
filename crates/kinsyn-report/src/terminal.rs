//! What reaches the user: results on stdout that stop quietly when the reader goes away, and
//! errors and warnings on stderr that are always one line and never drive the terminal.

use std::io::{self, Write};

/// `message` made safe for one line of a terminal: line breaks, escape sequences and every
/// other control or bidirectional-formatting character are written as Rust escapes (`\n`,
/// `\u{1b}`, `\u{202e}`), so that echoed input can neither add lines nor reorder or recolour
/// the text around it ([`kinsyn::markup::visible`]).
#[must_use]
pub fn one_line(message: &str) -> String {
    kinsyn::markup::visible(message).into_owned()
}

/// Writes `text` to stdout, every line made safe for a terminal: the line breaks and tabs
/// that lay it out kept, every other control or bidirectional-formatting character written as
/// its Rust escape ([`kinsyn::markup::visible_lines`]), so that a name, id or path read from a
/// file cannot drive the terminal. JSON reaches here already escaped
/// ([`kinsyn::markup::json_visible`]) and passes unchanged. A reader that has gone away
/// (`kinsyn … | head`) is not an error: the command ends quietly, as the conventional SIGPIPE
/// behaviour would.
///
/// # Errors
/// The write's error when stdout is closed other than by the reader going away.
pub fn print(text: &str) -> io::Result<()> {
    let shown = kinsyn::markup::visible_lines(text);
    let mut out = io::stdout().lock();
    match out.write_all(shown.as_bytes()).and_then(|()| out.flush()) {
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
#[must_use]
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
