//! Reading input files: the checks every file kinsyn reads passes before it is parsed.

use crate::Error;
use std::io::Read as _;
use std::path::Path;

/// The largest input file kinsyn reads (1 MiB): descriptions and polynomial systems are a few
/// kilobytes; anything larger is not what it claims to be, or is more than kinsyn can use.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// How large a file of one kind may be, and the kind's name in the refusal
/// (`… 2881040 bytes; input files are at most 1048576 bytes`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SizeLimit {
    /// The most bytes read.
    pub bytes: u64,
    /// The files it applies to, plural, as the refusal names them.
    pub files: &'static str,
}

/// The limit of every input file but a sweep's rows: [`MAX_FILE_BYTES`].
pub const INPUT_FILES: SizeLimit = SizeLimit {
    bytes: MAX_FILE_BYTES,
    files: "input files",
};

/// The text of `path`, within [`INPUT_FILES`]: [`read_text_within`].
///
/// # Errors
///
/// As [`read_text_within`].
pub fn read_text(path: &Path, not_what: &str) -> Result<String, Error> {
    read_text_within(path, not_what, INPUT_FILES)
}

/// The text of `path`: [`read_bytes_within`], then bytes that are not UTF-8 are refused as
/// `FILE is NOT_WHAT (not UTF-8 text: invalid byte at offset N)`.
///
/// # Errors
///
/// Those refusals, as [`Error::Input`] (exit 2).
pub fn read_text_within(path: &Path, not_what: &str, limit: SizeLimit) -> Result<String, Error> {
    text_of(path, not_what, read_bytes_within(path, not_what, limit)?)
}

/// `bytes` read from `path` as text, or refused as `FILE is NOT_WHAT (not UTF-8 text: invalid
/// byte at offset N)`.
///
/// # Errors
///
/// That refusal, as [`Error::Input`] (exit 2).
pub fn text_of(path: &Path, not_what: &str, bytes: Vec<u8>) -> Result<String, Error> {
    String::from_utf8(bytes).map_err(|e| {
        Error::Input(format!(
            "{} is {not_what} (not UTF-8 text: invalid byte at offset {})",
            path.display(),
            e.utf8_error().valid_up_to()
        ))
    })
}

/// The checks every file kinsyn reads passes before it is opened: a path that is not a regular
/// file (a directory, a device such as `/dev/zero`, a named pipe) or a file over `limit` (on
/// its metadata) is refused as `FILE is NOT_WHAT (why)`, e.g. "not a kinsyn manipulator
/// file"; a missing file is `FILE: No such file or directory`. Returns the file's length.
///
/// # Errors
///
/// Those refusals, as [`Error::Input`] (exit 2).
pub fn check_file(path: &Path, not_what: &str, limit: SizeLimit) -> Result<u64, Error> {
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
    if metadata.len() > limit.bytes {
        return Err(refuse(format!(
            "{} bytes; {} are at most {} bytes",
            metadata.len(),
            limit.files,
            limit.bytes
        )));
    }
    Ok(metadata.len())
}

/// The bytes of `path`, once [`check_file`] passes, read up to `limit` again (so that a file
/// growing meanwhile is cut off and refused).
///
/// # Errors
///
/// As [`check_file`], and `FILE is NOT_WHAT (more than N bytes; …)` for a file that grew past
/// `limit`, as [`Error::Input`] (exit 2).
pub fn read_bytes_within(path: &Path, not_what: &str, limit: SizeLimit) -> Result<Vec<u8>, Error> {
    let len = check_file(path, not_what, limit)?;
    let max = limit.bytes;
    let mut bytes = Vec::with_capacity(usize::try_from(len).map_or(0, |n| n + 1));
    std::fs::File::open(path)
        .and_then(|f| f.take(max + 1).read_to_end(&mut bytes))
        .map_err(|e| Error::Input(format!("{}: {e}", path.display())))?;
    if bytes.len() as u64 > max {
        return Err(Error::Input(format!(
            "{} is {not_what} (more than {max} bytes; {} are at most that)",
            path.display(),
            limit.files
        )));
    }
    Ok(bytes)
}
