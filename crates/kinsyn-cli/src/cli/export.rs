//! `kinsyn export`: a manipulator written out for a simulator (docs/export.md).

use super::CliError;
use super::output::OutputFile;
use std::path::Path;

/// Writes the MuJoCo model of the manipulator described in `file` to `out` (replacing an
/// existing file only when `force`). An unusable description, or an output path that exists or
/// whose folder does not, is an input error (exit 2); an output that cannot be written is an
/// environment error (exit 1), as for every file kinsyn writes ([`super::output`]).
pub fn mjcf(file: &Path, out: &Path, force: bool) -> Result<String, CliError> {
    let target = OutputFile::check("--mjcf", out, force)?;
    let m = super::manipulator::load(file)?;
    let xml = kinsyn::mjcf::to_mjcf(&m);
    target.write(xml.as_bytes())?;
    Ok(format!(
        "wrote {} ({}: {} bodies, {} joints, {} loops, {} actuators)\n",
        out.display(),
        m.name(),
        m.mechanism().body_count(),
        m.mechanism().joints().len(),
        m.mechanism().loop_count(),
        m.actuators().len()
    ))
}
