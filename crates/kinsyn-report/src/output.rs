//! The files the commands write, by the one writer of the library ([`kinsyn::output`]: whole or
//! not at all, never through a symbolic link), with the command line's policy and messages
//! (docs/limits.md, "Output files"):
//!
//! - a file given by an option (`build -o`, `stack -o`, `export --mjcf`) that exists is refused
//!   unless `--force`; its folder must exist;
//! - a folder given by `--out` may exist, or is created (only it: its parent must exist); the
//!   files the command writes into it are checked, all of them, before any is written, and one
//!   that exists refuses the command unless `--force`;
//! - the path chosen being wrong (it exists, it is a file where a folder is wanted or a folder
//!   where a file is, its parent is missing) is bad input (exit 2); the environment failing
//!   (permission denied, a full disk) is exit 1. Either message names the path.

use crate::Error;
use kinsyn::output::{self, OutputError, Overwrite};
use std::path::{Path, PathBuf};

/// `error` met on the output `given` with `option` (e.g. `--out figures`) as the command's
/// error: one line naming the option, the path and, for an existing file, `--force`.
#[must_use]
pub fn error(option: &str, given: &Path, error: OutputError) -> Error {
    let shown = given.display();
    let this = error.path() == given;
    match error {
        OutputError::Exists { .. } if this => Error::Input(format!(
            "{option} {shown}: exists; give --force to replace it"
        )),
        OutputError::Exists { path } => Error::Input(format!(
            "{option} {shown}: {} exists; give --force to replace it",
            path.display()
        )),
        OutputError::IsFolder { .. } if this => {
            Error::Input(format!("{option} {shown}: is a folder, give a file"))
        }
        OutputError::IsFolder { path } => Error::Input(format!(
            "{option} {shown}: {} is a folder, where kinsyn writes a file",
            path.display()
        )),
        OutputError::NotFolder { .. } if this => {
            Error::Input(format!("{option} {shown}: is a file, give a folder"))
        }
        OutputError::NotFolder { path } => Error::Input(format!(
            "{option} {shown}: {} is not a folder",
            path.display()
        )),
        OutputError::Missing { path } => Error::Input(format!(
            "{option} {shown}: {} does not exist",
            path.display()
        )),
        OutputError::Io { path, source } => Error::Io(std::io::Error::new(
            source.kind(),
            format!("cannot write {}: {source}", path.display()),
        )),
    }
}

/// A file given by `option` (`-o FILE`, `--mjcf FILE`), checked before the command's work.
#[derive(Debug)]
pub struct OutputFile<'a> {
    option: &'static str,
    path: &'a Path,
    overwrite: Overwrite,
}

impl<'a> OutputFile<'a> {
    /// `path` as the file `option` names: its folder exists, and nothing is there unless
    /// `force` (a folder never is accepted).
    ///
    /// # Errors
    /// [`Error::Input`] for a path that exists (without `force`), is a folder or has no parent folder.
    pub fn check(option: &'static str, path: &'a Path, force: bool) -> Result<Self, Error> {
        let overwrite = Overwrite::from_force(force);
        output::check_target(path, overwrite).map_err(|e| error(option, path, e))?;
        Ok(OutputFile {
            option,
            path,
            overwrite,
        })
    }

    /// The file's path.
    #[must_use]
    pub fn path(&self) -> &Path {
        self.path
    }

    /// Writes `bytes` to the file, whole or not at all.
    ///
    /// # Errors
    /// [`Error::Io`] when the file cannot be written (nothing is left behind).
    pub fn write(&self, bytes: &[u8]) -> Result<(), Error> {
        output::write(self.path, bytes, self.overwrite)
            .map_err(|e| error(self.option, self.path, e))
    }
}

/// The folder given by `option` (`--out DIR`) and the files a command writes into it.
#[derive(Debug)]
pub struct OutputFolder {
    option: &'static str,
    dir: PathBuf,
    overwrite: Overwrite,
}

impl OutputFolder {
    /// `dir` as the folder `option` names, for the files `names` (paths relative to it, a
    /// subfolder allowed: `entry/T1-001.html`): a folder, or absent with a parent folder that
    /// exists; every one of the files absent unless `force` (counted in the refusal). Nothing
    /// is created or written.
    ///
    /// # Errors
    /// [`Error::Input`] for a path that is not a folder, has no parent folder, or holds one of the files (without `force`).
    pub fn check<I, S>(
        option: &'static str,
        dir: &Path,
        names: I,
        force: bool,
    ) -> Result<Self, Error>
    where
        I: IntoIterator<Item = S>,
        S: AsRef<Path>,
    {
        let folder = OutputFolder {
            option,
            dir: dir.to_path_buf(),
            overwrite: Overwrite::from_force(force),
        };
        output::check_folder(dir).map_err(|e| folder.error(e))?;
        let mut existing: Vec<PathBuf> = Vec::new();
        for name in names {
            let path = dir.join(name);
            if let Some(sub) = path.parent().filter(|p| *p != dir) {
                match std::fs::metadata(sub) {
                    Ok(m) if !m.is_dir() => {
                        return Err(folder.error(OutputError::NotFolder {
                            path: sub.to_path_buf(),
                        }));
                    }
                    _ => {}
                }
            }
            match output::check_file(&path, folder.overwrite) {
                Ok(()) => {}
                Err(OutputError::Exists { path }) => existing.push(path),
                Err(e) => return Err(folder.error(e)),
            }
        }
        if let Some(first) = existing.first() {
            let more = match existing.len() {
                1 => String::new(),
                n => format!(" (and {} more of the files it writes)", n - 1),
            };
            return Err(Error::Input(format!(
                "{option} {}: {} exists{more}; give --force to replace {}",
                dir.display(),
                first.display(),
                if existing.len() == 1 { "it" } else { "them" }
            )));
        }
        Ok(folder)
    }

    /// Creates the folder if missing (only it), and its subfolders `subfolders`.
    ///
    /// # Errors
    /// [`Error::Io`] when a folder cannot be created.
    pub fn create(&self, subfolders: &[&str]) -> Result<(), Error> {
        output::create_folder(&self.dir).map_err(|e| self.error(e))?;
        for sub in subfolders {
            output::create_folder(&self.dir.join(sub)).map_err(|e| self.error(e))?;
        }
        Ok(())
    }

    /// Writes `bytes` to the file `name` in the folder, whole or not at all; its path.
    ///
    /// # Errors
    /// [`Error::Io`] when the file cannot be written (nothing is left behind).
    pub fn write(&self, name: impl AsRef<Path>, bytes: &[u8]) -> Result<PathBuf, Error> {
        let path = self.dir.join(name);
        output::write(&path, bytes, self.overwrite).map_err(|e| self.error(e))?;
        Ok(path)
    }

    /// `e` as the command's error, naming the option and the folder.
    fn error(&self, e: OutputError) -> Error {
        error(self.option, &self.dir, e)
    }
}
