//! Singular (Debian package `singular`), the exact computer-algebra check of some tests.

use std::io::Write as _;

/// What Singular prints for `script` (run with `Singular -q`, the script on standard input),
/// or `None` with a note on stderr when Singular is not installed (`.ci/run` installs it when it
/// can), so that the calling test is skipped rather than failed.
///
/// # Panics
/// If Singular is installed but does not run the script.
#[allow(dead_code)]
#[must_use]
pub fn run(script: &str, check: &str) -> Option<String> {
    if std::process::Command::new("Singular")
        .arg("--version")
        .output()
        .is_err()
    {
        eprintln!("Singular is not installed: {check} is skipped");
        return None;
    }
    let mut child = std::process::Command::new("Singular")
        .arg("-q")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("run Singular");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(script.as_bytes())
        .expect("the script");
    let out = child.wait_with_output().expect("Singular's answer");
    assert!(out.status.success(), "Singular failed on {script}");
    Some(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// Singular declarations `poly gK = …;` of paper 004's printed equations `names` (e.g. "g1"),
/// as transcribed in `data/paper004-constraints.txt` (the design parameters and inputs are
/// declared by the caller as `number`s).
///
/// # Panics
/// If the data file is missing or lacks one of the equations.
#[allow(dead_code)]
#[must_use]
pub fn printed_paper004(names: &[&str]) -> String {
    let text = std::fs::read_to_string("../../data/paper004-constraints.txt")
        .expect("data/paper004-constraints.txt");
    let mut out = String::new();
    for g in names {
        let line = text
            .lines()
            .find(|l| l.starts_with(&format!("{g} = ")))
            .unwrap_or_else(|| panic!("{g} is not in data/paper004-constraints.txt"));
        out.push_str("poly ");
        out.push_str(line);
        out.push('\n');
    }
    out
}
