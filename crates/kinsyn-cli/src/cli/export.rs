//! `kinsyn export`: a manipulator written out for a simulator or a kinematics library
//! (docs/export.md).

use super::CliError;
use super::output::OutputFile;
use std::fmt::Write as _;
use std::path::Path;

/// Writes the MuJoCo model (`mjcf`) and the URDF spanning tree (`urdf`) of the manipulator
/// described in `file`, whichever are asked for (replacing existing files only when `force`).
/// Both outputs are checked before the description is read and before either is written. An
/// unusable description, an output path that exists or whose folder does not, or the same
/// path given twice is an input error (exit 2); an output that cannot be written is an
/// environment error (exit 1), as for every file kinsyn writes ([`super::output`]).
pub fn models(
    file: &Path,
    mjcf: Option<&Path>,
    urdf: Option<&Path>,
    force: bool,
) -> Result<String, CliError> {
    if let (Some(a), Some(b)) = (mjcf, urdf)
        && a == b
    {
        return Err(CliError::Input(format!(
            "--mjcf and --urdf are both {}: give two files",
            a.display()
        )));
    }
    let mjcf = mjcf
        .map(|out| OutputFile::check("--mjcf", out, force))
        .transpose()?;
    let urdf = urdf
        .map(|out| OutputFile::check("--urdf", out, force))
        .transpose()?;
    let m = super::manipulator::load(file)?;
    let mut report = String::new();
    let summary = format!(
        "{}: {} bodies, {} joints, {} loops, {} actuators",
        m.name(),
        m.mechanism().body_count(),
        m.mechanism().joints().len(),
        m.mechanism().loop_count(),
        m.actuators().len()
    );
    if let Some(target) = mjcf {
        target.write(kinsyn::mjcf::to_mjcf(&m).as_bytes())?;
        let _ = writeln!(report, "wrote {} ({summary})", target.path().display());
    }
    if let Some(target) = urdf {
        let tree = kinsyn::export_tree::ExportTree::new(&m);
        target.write(kinsyn::urdf::to_urdf(&m).as_bytes())?;
        let _ = writeln!(
            report,
            "wrote {} ({summary}; the tree's {} joints, {} loop-closing joints listed in a comment)",
            target.path().display(),
            tree.joint_count(),
            tree.chords.len()
        );
    }
    Ok(report)
}
