//! kinsyn's failures as Python exceptions: `KinsynError`, and `InputError` for bad input (what
//! the command line refuses with exit code 2), each with the command's one-line message.

use pyo3::PyErr;
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use std::fmt::Write as _;

create_exception!(
    kinsyn,
    KinsynError,
    PyException,
    "A kinsyn failure; str() is the one-line message the kinsyn command prints after `kinsyn: error: `."
);
create_exception!(
    kinsyn,
    InputError,
    KinsynError,
    "Bad input (a missing or malformed file, chain, pattern, pose, input value or option): what the kinsyn command refuses with exit code 2."
);

/// A failure as the command line classifies it.
#[derive(Debug)]
pub enum Error {
    /// Bad input (the command's exit code 2).
    Input(String),
    /// A fault of the build or the environment (exit code 1).
    Internal(String),
}

impl From<Error> for PyErr {
    fn from(e: Error) -> Self {
        match e {
            Error::Input(m) => InputError::new_err(one_line(&m)),
            Error::Internal(m) => KinsynError::new_err(one_line(&m)),
        }
    }
}

/// `message` made safe for one line, as the command line prints it: control characters and
/// invisible formatting characters written as Rust escapes (`\n`, `\u{1b}`, `\u{202e}`).
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

/// Invisible characters that change how the text around them is shown (bidirectional
/// controls, zero-width characters, the BOM, line and paragraph separators).
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
