//! What reaches the user: results on stdout that stop quietly when the reader goes away, and
//! errors and warnings on stderr that are always one line and never drive the terminal; the
//! progress bars and spinner of `kinsyn-report` beside them.

pub(super) use kinsyn_report::terminal::{one_line, progress, working};
use std::io::{self, Write};

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
pub(super) fn print(text: &str) -> io::Result<()> {
    let shown = kinsyn::markup::visible_lines(text);
    let mut out = io::stdout().lock();
    match out.write_all(shown.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        other => other,
    }
}

/// Prints `kinsyn: error: MESSAGE` as one line on stderr.
pub(super) fn error(message: &str) {
    line(&format!("kinsyn: error: {}", one_line(message)));
}

/// Prints `warning: MESSAGE` as one line on stderr.
pub(super) fn warning(message: &str) {
    line(&format!("warning: {}", one_line(message)));
}

/// One line on stderr; a closed stderr is ignored (there is nowhere left to report it).
fn line(text: &str) {
    let _ = writeln!(io::stderr().lock(), "{text}");
}
