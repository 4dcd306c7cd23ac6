//! `kinsyn view`: a manipulator's 3D page (docs/view.md).

use super::CliError;
use super::output::OutputFile;
use kinsyn_report::view::{ViewOptions, view_of};
use std::path::Path;

/// Writes the view of the manipulator described in `file` to `out` (replacing an existing
/// file only when `force`). The output is checked before any work; an unusable description or
/// inputs it cannot reach are input errors (exit 2). Returns the summary line, or with `json`
/// the page's data.
pub fn view(
    file: &Path,
    out: &Path,
    options: &ViewOptions,
    force: bool,
    json: bool,
) -> Result<String, CliError> {
    let target = OutputFile::check("--out", out, force)?;
    let m = super::manipulator::load(file)?;
    let view = view_of(&m, options)?;
    let page = kinsyn::view::page(&view);
    target.write(page.as_bytes())?;
    if json {
        return Ok(kinsyn_report::sorted_json(&view));
    }
    let frames: usize = view
        .sweeps
        .iter()
        .map(|s| s.joint_values.len())
        .sum::<usize>()
        + view
            .modes
            .iter()
            .map(|m| m.joint_values.len())
            .sum::<usize>()
        + view.assemblies.len();
    Ok(format!(
        "wrote {} ({}: {} bodies, {} joints; {} input sweeps, {} modes, {} assemblies; {} configurations, {} kB)\n",
        out.display(),
        m.name(),
        m.mechanism().body_count(),
        m.mechanism().joints().len(),
        view.sweeps.len(),
        view.modes.len(),
        view.assemblies.len(),
        frames,
        page.len().div_ceil(1024)
    ))
}
