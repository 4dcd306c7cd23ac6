//! Input files: the checks every file passes before it is parsed, with the command line's
//! messages.

use crate::error::Error;
use std::io::Read as _;
use std::path::Path;

/// The largest input file kinsyn reads (1 MiB), as on the command line.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// The text of `path`; a missing file is `FILE: <the system's reason>`, a directory, a file
/// over [`MAX_FILE_BYTES`] or bytes that are not UTF-8 are `FILE is NOT_WHAT (why)`.
pub fn read_text(path: &Path, not_what: &str) -> Result<String, Error> {
    let shown = path.display();
    let refuse = |why: String| Error::Input(format!("{shown} is {not_what} ({why})"));
    let metadata = std::fs::metadata(path).map_err(|e| Error::Input(format!("{shown}: {e}")))?;
    if !metadata.is_file() {
        return Err(refuse(if metadata.is_dir() {
            "a directory".into()
        } else {
            "not a regular file".into()
        }));
    }
    if metadata.len() > MAX_FILE_BYTES {
        return Err(refuse(format!(
            "{} bytes; input files are at most {MAX_FILE_BYTES} bytes",
            metadata.len()
        )));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| Error::Input(format!("{shown}: {e}")))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(refuse(format!(
            "more than {MAX_FILE_BYTES} bytes; input files are at most that"
        )));
    }
    String::from_utf8(bytes).map_err(|e| {
        refuse(format!(
            "not UTF-8 text: invalid byte at offset {}",
            e.utf8_error().valid_up_to()
        ))
    })
}
