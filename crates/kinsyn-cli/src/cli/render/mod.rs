//! How the reports of `kinsyn-report` are printed: the text a terminal shows, one module per
//! command, each taking the command's typed report (and the manipulator, where the text names
//! what the report does not hold). The `--json` output is the report itself
//! ([`kinsyn_report::json`], [`kinsyn_report::sorted_json`]).

pub(super) mod analyze;
pub(super) mod assemblies;
pub(super) mod components;
pub(super) mod configurable;
pub(super) mod modes;
pub(super) mod solve;
pub(super) mod sweep;

use super::terminal;
use std::path::Path;

/// Prints each warning on stderr as one line `warning: FILE: …`. Called once the command has
/// succeeded, so that an error stays the only line on stderr.
pub(super) fn warn(path: &Path, warnings: &[String]) {
    for w in warnings {
        terminal::warning(&format!("{}: {w}", path.display()));
    }
}
