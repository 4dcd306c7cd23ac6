//! Helpers shared by the command-line tests: running the `kinsyn` binary from the repository
//! root (where `mechanisms/` and `catalogue/` are), and its output as text.

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
