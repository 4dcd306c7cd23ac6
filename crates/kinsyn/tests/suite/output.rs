//! The output files (src/output.rs): written whole or not at all, an existing file refused or
//! replaced as asked, a symbolic link replaced and never followed, no folder created but the
//! one named.

use kinsyn::output::{OutputError, Overwrite, create_folder, write};
#[cfg(target_os = "linux")]
use std::path::Path;

#[test]
fn a_new_file_is_written_whole_and_no_temporary_file_is_left() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("a.txt");
    write(&path, b"hello", Overwrite::Refuse).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"hello");
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(names, ["a.txt"]);
}

#[test]
fn an_existing_file_is_refused_or_replaced_as_asked() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("a.txt");
    std::fs::write(&path, b"old").unwrap();
    let refused = write(&path, b"new", Overwrite::Refuse).unwrap_err();
    assert!(matches!(refused, OutputError::Exists { .. }), "{refused}");
    assert!(refused.is_path_choice());
    assert_eq!(std::fs::read(&path).unwrap(), b"old");
    write(&path, b"new", Overwrite::Replace).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"new");
}

#[cfg(unix)]
#[test]
fn a_symbolic_link_is_replaced_never_followed() {
    let dir = tempfile::tempdir().unwrap();
    let victim = dir.path().join("victim.txt");
    std::fs::write(&victim, b"keep").unwrap();
    let link = dir.path().join("link.txt");
    std::os::unix::fs::symlink(&victim, &link).unwrap();
    let refused = write(&link, b"new", Overwrite::Refuse).unwrap_err();
    assert!(matches!(refused, OutputError::Exists { .. }), "{refused}");
    write(&link, b"new", Overwrite::Replace).unwrap();
    assert_eq!(std::fs::read(&victim).unwrap(), b"keep");
    assert!(!std::fs::symlink_metadata(&link).unwrap().is_symlink());
    assert_eq!(std::fs::read(&link).unwrap(), b"new");
    // A dangling link is an existing entry too.
    let dangling = dir.path().join("dangling.txt");
    std::os::unix::fs::symlink(dir.path().join("nowhere"), &dangling).unwrap();
    assert!(matches!(
        write(&dangling, b"x", Overwrite::Refuse),
        Err(OutputError::Exists { .. })
    ));
    assert!(!dir.path().join("nowhere").exists());
}

#[cfg(target_os = "linux")]
#[test]
fn an_environment_failure_names_the_target_not_the_temporary_file() {
    // Not even root can add a file to /proc/self.
    let e = write(Path::new("/proc/self/x"), b"x", Overwrite::Refuse).unwrap_err();
    assert!(!e.is_path_choice());
    let message = e.to_string();
    assert!(message.starts_with("/proc/self/x: "), "{message}");
    assert!(!message.contains(".tmp"), "{message}");
}

#[test]
fn a_folder_is_never_replaced_by_a_file() {
    let dir = tempfile::tempdir().unwrap();
    for overwrite in [Overwrite::Refuse, Overwrite::Replace] {
        assert!(matches!(
            write(dir.path(), b"x", overwrite),
            Err(OutputError::IsFolder { .. })
        ));
    }
}

#[test]
fn only_the_folder_named_is_created() {
    let dir = tempfile::tempdir().unwrap();
    let chain = dir.path().join("a").join("b");
    let e = create_folder(&chain).unwrap_err();
    assert!(matches!(&e, OutputError::Missing { path } if *path == dir.path().join("a")));
    assert!(!dir.path().join("a").exists());
    create_folder(&dir.path().join("a")).unwrap();
    create_folder(&chain).unwrap();
    create_folder(&chain).unwrap();
    assert!(chain.is_dir());
    let file = dir.path().join("f");
    std::fs::write(&file, b"").unwrap();
    assert!(matches!(create_folder(&file), Err(OutputError::NotFolder { path }) if path == file));
    assert!(matches!(
        write(&file.join("x"), b"", Overwrite::Replace),
        Err(OutputError::NotFolder { path }) if path == file
    ));
    assert!(matches!(
        write(&chain.join("c").join("x"), b"", Overwrite::Replace),
        Err(OutputError::Missing { path }) if path == chain.join("c")
    ));
}
