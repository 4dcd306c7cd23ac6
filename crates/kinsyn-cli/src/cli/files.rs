//! Reading input files: the checks every file kinsyn reads passes before it is parsed.

use super::CliError;
use std::io::Read as _;
use std::path::Path;

/// The largest input file kinsyn reads (1 MiB): descriptions and polynomial systems are a few
/// kilobytes; anything larger is not what it claims to be, or is more than kinsyn can use.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// The text of `path`. A path that is not a regular file, a file over [`MAX_FILE_BYTES`]
/// (checked on the metadata and again while reading) or bytes that are not UTF-8 are refused
/// as `FILE is NOT_WHAT (why)`, e.g. "not a kinsyn manipulator file"; a missing file is
/// `FILE: No such file or directory`.
///
/// # Errors
///
/// Those refusals, as [`CliError::Input`] (exit 2).
pub fn read_text(path: &Path, not_what: &str) -> Result<String, CliError> {
    let shown = path.display();
    let refuse = |why: String| CliError::Input(format!("{shown} is {not_what} ({why})"));
    let metadata = std::fs::metadata(path).map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
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
        .map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
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
