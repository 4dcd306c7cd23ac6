//! Replays the committed fuzz corpora (`fuzz/corpus/<target>/`) through the same checks the fuzz
//! targets run (`fuzz/checks.rs`), on the stable toolchain: every input found by fuzzing, and
//! every reproducer of a fixed panic, stays checked by `cargo test`. docs/fuzzing.md.

#[path = "../../../../fuzz/checks.rs"]
mod checks;

use std::panic;
use std::path::{Path, PathBuf};

/// Runs `check` on every file of `fuzz/corpus/<target>/` and fails with the names of the files
/// whose check panicked.
fn replay(target: &str, check: fn(&[u8])) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join("fuzz/corpus")
        .join(target);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    assert!(!files.is_empty(), "{}: no corpus", dir.display());
    let failed: Vec<String> = files
        .iter()
        .filter(|path| {
            let data = std::fs::read(path).expect("a corpus file");
            panic::catch_unwind(|| check(&data)).is_err()
        })
        .map(|p| p.display().to_string())
        .collect();
    assert!(
        failed.is_empty(),
        "{} of {} {target} inputs broke an invariant: {}",
        failed.len(),
        files.len(),
        failed.join(" ")
    );
}

#[test]
fn notation_corpus() {
    replay("notation", checks::check_notation);
}

#[test]
fn pattern_corpus() {
    replay("pattern", checks::check_pattern);
}

#[test]
fn locks_corpus() {
    replay("locks", checks::check_locks);
}

#[test]
fn description_corpus() {
    replay("description", checks::check_description);
}

#[test]
fn position_corpus() {
    replay("position", checks::check_position);
}

#[test]
fn bertini_corpus() {
    replay("bertini", checks::check_bertini);
}

#[test]
fn components_corpus() {
    replay("components", checks::check_components);
}

#[test]
fn assemblies_corpus() {
    replay("assemblies", checks::check_assemblies);
}

#[test]
fn checkpoint_corpus() {
    replay("checkpoint", checks::check_checkpoint);
}
