//! `kinsyn export`: a manipulator written out for a simulator (docs/export.md).

use super::CliError;
use std::path::Path;

/// Writes the MuJoCo model of the manipulator described in `file` to `out`. An unusable
/// description is an input error (exit 2); an output that cannot be written is an environment
/// error (exit 1), as for every file kinsyn writes.
pub fn mjcf(file: &Path, out: &Path) -> Result<String, CliError> {
    let m = super::manipulator::load(file)?;
    let xml = kinsyn::mjcf::to_mjcf(&m);
    std::fs::write(out, &xml)
        .map_err(|e| std::io::Error::new(e.kind(), format!("{}: {e}", out.display())))?;
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
