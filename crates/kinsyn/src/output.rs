//! Output files: every file kinsyn writes is written whole or not at all, never through a
//! symbolic link, and never over a file that was not meant to be replaced.
//!
//! [`write()`] puts the bytes in a temporary file beside the target (same folder, so the same
//! file system), flushes and syncs it to the disk, then renames it to the target's name. A
//! reader, a full disk or an interruption therefore sees either the old file or the whole new
//! one: on any error the temporary file is removed and the target left as it was. The rename
//! replaces the folder's entry, so a symbolic link at the target is replaced by the new file,
//! never followed to the file it points to.
//!
//! Whether an existing entry may be replaced is the caller's [`Overwrite`]. A command that
//! writes several files checks them all first ([`check_file`] for each, [`check_folder`] for
//! their folder), so that it refuses before it writes the first; [`write()`] checks again, and
//! [`Overwrite::Refuse`] is kept by an atomic "rename unless the name exists", so a file that
//! appears in between is not replaced either. A folder is created by [`create_folder`], only the
//! one named: its parent must exist, so a mistyped path does not become a chain of folders.
//!
//! The errors ([`OutputError`]) tell the path concerned and whether the path itself was the
//! problem (it exists, it is a folder where a file is wanted or the other way round, its parent
//! is missing: [`OutputError::is_path_choice`]) or the environment failed (permission denied,
//! disk full).

use std::io::Write as _;
use std::path::{Path, PathBuf};

/// Whether an existing file may be replaced.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Overwrite {
    /// An existing file or symbolic link at the target is refused ([`OutputError::Exists`]).
    #[default]
    Refuse,
    /// An existing file or symbolic link is replaced (the link itself, not what it points to).
    Replace,
}

impl Overwrite {
    /// [`Overwrite::Replace`] when `force` is true, else [`Overwrite::Refuse`].
    #[must_use]
    pub fn from_force(force: bool) -> Self {
        if force { Self::Replace } else { Self::Refuse }
    }
}

/// Why an output could not be written, with the path concerned.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// Something exists at the target (a file, a symbolic link, anything but a folder) and
    /// [`Overwrite::Refuse`] was asked. Give another path, or allow replacing it.
    #[error("{} exists", .path.display())]
    Exists {
        /// The existing entry.
        path: PathBuf,
    },
    /// A folder is where a file is to be written (a folder is never replaced by a file).
    #[error("{} is a folder", .path.display())]
    IsFolder {
        /// The folder.
        path: PathBuf,
    },
    /// Something that is not a folder is where a folder is wanted.
    #[error("{} is not a folder", .path.display())]
    NotFolder {
        /// The entry that is not a folder.
        path: PathBuf,
    },
    /// The folder to write into, or the parent of the folder to create, does not exist.
    #[error("{} does not exist", .path.display())]
    Missing {
        /// The missing folder.
        path: PathBuf,
    },
    /// The environment failed: permission denied, a full disk, a read-only file system.
    #[error("{}: {source}", .path.display())]
    Io {
        /// The file or folder that could not be read, created or written.
        path: PathBuf,
        /// What the operating system said.
        source: std::io::Error,
    },
}

impl OutputError {
    /// The path the error concerns.
    #[must_use]
    pub fn path(&self) -> &Path {
        match self {
            Self::Exists { path }
            | Self::IsFolder { path }
            | Self::NotFolder { path }
            | Self::Missing { path }
            | Self::Io { path, .. } => path,
        }
    }

    /// Whether the path chosen is the problem (it exists, is a folder or not one, its parent is
    /// missing), rather than the environment ([`OutputError::Io`]).
    #[must_use]
    pub fn is_path_choice(&self) -> bool {
        !matches!(self, Self::Io { .. })
    }
}

/// An I/O failure on `path`. The operating system's message is kept without the temporary
/// file's name that `tempfile` appends to the errors of the files it creates (`… at path
/// "DIR/.NAME.XXXXXX.tmp"`; its error type is private, so the suffix is cut from the text): the
/// message names `path`, the file the user asked for.
fn io(path: &Path) -> impl FnOnce(std::io::Error) -> OutputError + '_ {
    move |source| {
        let text = source.to_string();
        let source = match text.rsplit_once(" at path \"") {
            Some((message, _)) => std::io::Error::new(source.kind(), message.to_string()),
            None => source,
        };
        OutputError::Io {
            path: path.to_path_buf(),
            source,
        }
    }
}

/// The folder `path` is written in: its parent, `.` for a bare name.
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// Checks that a file may be written at `path`: nothing there, or (with
/// [`Overwrite::Replace`]) a file or symbolic link to replace. A folder there is refused
/// either way. The folder `path` is in is not looked at ([`check_folder`] does that).
///
/// # Errors
/// [`OutputError::Exists`], [`OutputError::IsFolder`], or [`OutputError::Io`] when the entry
/// cannot be looked at.
pub fn check_file(path: &Path, overwrite: Overwrite) -> Result<(), OutputError> {
    if path.file_name().is_none() {
        // `.`, `..`, `/` or a path ending in one of them.
        return Err(OutputError::IsFolder {
            path: path.to_path_buf(),
        });
    }
    match std::fs::symlink_metadata(path) {
        // A folder on the way that is a file: the folder's check names it.
        Err(e) if is_missing(&e) => Ok(()),
        Err(e) => Err(io(path)(e)),
        Ok(m) if m.is_dir() => Err(OutputError::IsFolder {
            path: path.to_path_buf(),
        }),
        Ok(_) if overwrite == Overwrite::Refuse => Err(OutputError::Exists {
            path: path.to_path_buf(),
        }),
        Ok(_) => Ok(()),
    }
}

/// Checks that `dir` is a folder (a symbolic link to one counts: the user named it), or is
/// absent with a parent folder that exists, so that [`create_folder`] can make it.
///
/// # Errors
/// [`OutputError::NotFolder`] (for `dir` or its parent), [`OutputError::Missing`] (its
/// parent), or [`OutputError::Io`] when they cannot be looked at.
pub fn check_folder(dir: &Path) -> Result<(), OutputError> {
    match std::fs::metadata(dir) {
        Ok(m) if m.is_dir() => Ok(()),
        Ok(_) => Err(OutputError::NotFolder {
            path: dir.to_path_buf(),
        }),
        Err(e) if is_missing(&e) => existing_folder(folder_of(dir)),
        Err(e) => Err(io(dir)(e)),
    }
}

/// Whether `e` says a path does not exist (or a folder on its way is a file).
fn is_missing(e: &std::io::Error) -> bool {
    matches!(
        e.kind(),
        std::io::ErrorKind::NotFound | std::io::ErrorKind::NotADirectory
    )
}

/// Checks that the folder `dir` exists.
fn existing_folder(dir: &Path) -> Result<(), OutputError> {
    match std::fs::metadata(dir) {
        Ok(m) if m.is_dir() => Ok(()),
        Ok(_) => Err(OutputError::NotFolder {
            path: dir.to_path_buf(),
        }),
        Err(e) if is_missing(&e) => Err(OutputError::Missing {
            path: dir.to_path_buf(),
        }),
        Err(e) => Err(io(dir)(e)),
    }
}

/// Checks that [`write()`] may write `path`: [`check_file`], and the folder it is in exists.
///
/// # Errors
/// As [`check_file`]; [`OutputError::Missing`] or [`OutputError::NotFolder`] for its folder.
pub fn check_target(path: &Path, overwrite: Overwrite) -> Result<(), OutputError> {
    check_file(path, overwrite)?;
    existing_folder(folder_of(path))
}

/// Creates the folder `dir` if it does not exist: only it, never its parents ([`check_folder`]'s
/// conditions).
///
/// # Errors
/// As [`check_folder`], and [`OutputError::Io`] when the folder cannot be created.
pub fn create_folder(dir: &Path) -> Result<(), OutputError> {
    check_folder(dir)?;
    match std::fs::create_dir(dir) {
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => check_folder(dir),
        other => other.map_err(io(dir)),
    }
}

/// Writes `bytes` to the file `path` whole or not at all (the module's documentation): a
/// temporary file in the same folder, flushed and synced, then renamed to `path`. With
/// [`Overwrite::Refuse`] the rename fails if anything appeared at `path` meanwhile; with
/// [`Overwrite::Replace`] it replaces the file or symbolic link there. The folder must exist. A
/// new file gets the permissions `std::fs::write` gives (read and write for all, less the
/// umask).
///
/// # Errors
/// As [`check_target`]; [`OutputError::Io`] naming
/// `path` when the bytes cannot be written (the temporary file is then removed and `path` left
/// as it was).
pub fn write(path: &Path, bytes: &[u8], overwrite: Overwrite) -> Result<(), OutputError> {
    check_target(path, overwrite)?;
    let dir = folder_of(path);
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    // Dropping the temporary file on any error below removes it.
    let mut tmp = builder.tempfile_in(dir).map_err(io(path))?;
    let file = tmp.as_file_mut();
    file.write_all(bytes)
        .and_then(|()| file.flush())
        .and_then(|()| file.sync_all())
        .map_err(io(path))?;
    let persisted = match overwrite {
        Overwrite::Replace => tmp.persist(path),
        Overwrite::Refuse => tmp.persist_noclobber(path),
    };
    match persisted {
        Ok(_) => Ok(()),
        Err(e) if e.error.kind() == std::io::ErrorKind::AlreadyExists => Err(OutputError::Exists {
            path: path.to_path_buf(),
        }),
        Err(e) => match check_file(path, overwrite) {
            Err(refused) => Err(refused),
            Ok(()) => Err(io(path)(e.error)),
        },
    }
}
