//! Helpers shared by the command-line tests: running the `kinsyn` binary from the repository
//! root (where `mechanisms/` and `catalogue/` are), and its output as text.

pub mod browser;

/// Runs the `kinsyn` binary from the repository root.
#[allow(dead_code)]
pub fn kinsyn(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_kinsyn"))
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .args(args)
        .output()
        .expect("run kinsyn")
}

/// The standard output of a run, as text.
#[allow(dead_code)]
#[must_use]
pub fn stdout(o: &std::process::Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

/// The standard error of a run, as text.
#[allow(dead_code)]
#[must_use]
pub fn stderr(o: &std::process::Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

#[allow(dead_code)]
/// Asserts the contract for bad input: exit 2, nothing on stdout, one stderr line starting with
/// `kinsyn: error:` that holds no control or bidirectional-formatting character, containing
/// every needle.
pub fn assert_refused(o: &std::process::Output, what: &str, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{what}: {err}");
    assert!(stdout(o).is_empty(), "{what}: stdout {}", stdout(o));
    assert_eq!(err.lines().count(), 1, "{what}: {err:?}");
    assert!(err.starts_with("kinsyn: error: "), "{what}: {err}");
    let line = err.trim_end_matches('\n');
    assert!(
        !line
            .chars()
            .any(|c| c.is_control() || ('\u{2028}'..='\u{202e}').contains(&c)),
        "{what}: unsafe character in {line:?}"
    );
    for needle in needles {
        assert!(err.contains(needle), "{what}: {needle:?} not in {err}");
    }
}
