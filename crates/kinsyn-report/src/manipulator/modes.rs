//! `kinsyn modes`: the lock subsets chosen, sampled with a progress bar, and the patterns
//! reached, as typed values (the front ends print them: a summary per dof, one subset in
//! detail, or JSON).

use super::analyze::configuration_at_pose;
use super::{Loaded, leg_warnings, load_with_body};
use crate::Error;
use kinsyn::manipulator::{Manipulator, Modes, ModesCost};
use kinsyn::mechanism::{ASSEMBLY_STEPS, SampleSettings};
use serde::Serialize;
use std::path::Path;

/// Which lock subsets `kinsyn modes` samples.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Selection {
    /// Every subset of the n inputs: 2^n.
    All,
    /// The subsets with at most this many inputs locked (`--max-locks`).
    MaxLocks(usize),
    /// One subset, given by its labels (`--lock`), printed in detail.
    Lock(String),
}

/// The default of `modes --max-subsets`: 4096 sampled motions, every subset of up to 12 inputs.
/// A motion is ten loop closures from a regular start, one where the locks leave it rigid, and
/// more, each dearer, from a singular one ([`ModesCost`]): the 4096 of a 12-input 6-UPS, a
/// quarter of them singular, take about 4 s of CPU (docs/limits.md, "Measured cost").
pub const DEFAULT_MAX_SUBSETS: u32 = 4096;

/// The largest `--max-subsets`: 2^16, every subset of 16 inputs (the old limit of 16 inputs):
/// about a minute of CPU at the 1 ms of a regular subset of six UPS legs, several times that
/// when many starts are singular (docs/limits.md, "Measured cost").
pub const MAX_SUBSETS_CEILING: u32 = 1 << 16;

/// The most samples per motion (`--samples`): 64 walks, 193 loop closures a motion instead of
/// the default 10 ([`ModesCost::closures_per_motion`]), far more evidence than a group claim
/// needs (two samples 1e-3 apart, docs/verification.md).
pub const MAX_SAMPLES: u16 = 64;

/// The configuration the modes are sampled from: the file's reference configuration, or the
/// assembly with the platform frame at `pose` (`x,y,z,rx,ry,rz` as for `analyze --pose`) with
/// every input free, so that each subset's locked inputs are held at their values there.
fn start_configuration(m: &Manipulator, pose: Option<&str>) -> Result<Vec<f64>, Error> {
    match pose {
        None => Ok(m.reference()),
        Some(text) => configuration_at_pose(m, "--pose", text, &[]),
    }
}

/// The lock subsets a selection asks for, refused when they are more than `max_subsets`
/// (each is one sampled motion, whose loop closures with `settings` the refusal states; it says
/// how to ask for fewer).
fn selected_subsets(
    source: &str,
    m: &Manipulator,
    selection: &Selection,
    max_subsets: u32,
    settings: &SampleSettings,
) -> Result<Vec<Vec<usize>>, Error> {
    let n = m.actuators().len();
    let max_locks = match selection {
        Selection::Lock(text) => {
            let locked = m
                .parse_locks(text)
                .map_err(|e| Error::Input(format!("--lock {text:?}: {e}")))?;
            return Ok(vec![locked]);
        }
        Selection::All => n,
        Selection::MaxLocks(k) => *k,
    };
    let count = m.lock_subset_count(max_locks);
    let limit = u128::from(max_subsets);
    if count <= limit {
        return Ok(m.lock_subsets(max_locks));
    }
    let scope = match selection {
        Selection::MaxLocks(k) => format!("with at most {k} locked"),
        _ => format!("(all 2^{n})"),
    };
    // The most locks whose subsets stay within the limit (0 always does: one subset).
    let fits = (0..n)
        .take_while(|&k| m.lock_subset_count(k) <= limit)
        .last()
        .unwrap_or(0);
    Err(Error::Input(format!(
        "{}: {n} inputs give {count} lock subsets {scope}, more than --max-subsets {max_subsets} (each a sampled motion: 1 loop closure where the locks leave the start rigid, {} from a regular start (1 + {} samples × {} steps), up to {} of up to {ASSEMBLY_STEPS} Newton steps each from a singular one; their CPU in docs/limits.md); use --max-locks {fits} ({} subsets) or --lock SET, or raise --max-subsets (at most {MAX_SUBSETS_CEILING})",
        source,
        ModesCost::closures_per_motion(settings),
        settings.samples,
        settings.steps,
        ModesCost::most_closures_per_motion(settings),
        m.lock_subset_count(fits)
    )))
}

/// `kinsyn modes`: the manipulator of the file at `path` (cut to `legs`, with its end-effector
/// `body` and reference body `relative`), its motions for the selected lock subsets with the
/// locked inputs held at their values at the start configuration (the reference, or `pose`),
/// and the leg warnings.
///
/// # Errors
/// [`Error::Input`] for a file that is not a description, a pose or lock that does not read, or a sampling past its limits.
pub fn modes(
    path: &Path,
    (pose, body, relative): (Option<&str>, Option<&str>, Option<&str>),
    legs: Option<&str>,
    selection: &Selection,
    max_subsets: u32,
    settings: &SampleSettings,
) -> Result<Loaded<Modes>, Error> {
    let m = load_with_body(path, body, relative, legs)?;
    let modes = sample_modes(
        &m,
        &path.display().to_string(),
        pose,
        selection,
        max_subsets,
        settings,
    )?;
    let warnings = leg_warnings(&m);
    Ok(Loaded {
        manipulator: m,
        result: modes,
        warnings,
    })
}

/// The motions of `m` with the lock subsets of `selection` locked (refused beyond
/// `max_subsets`; `source` names the manipulator in that refusal), the locked inputs held at
/// their values at the start configuration (the reference, or the assembly at `pose`, every
/// input free), sampled with `settings`. A progress bar over the subsets is drawn on stderr
/// when it is a terminal.
///
/// # Errors
///
/// [`Error::Input`]: a malformed lock set or pose, a pose that cannot be reached, or more
/// subsets than `max_subsets`.
pub fn sample_modes(
    m: &Manipulator,
    source: &str,
    pose: Option<&str>,
    selection: &Selection,
    max_subsets: u32,
    settings: &SampleSettings,
) -> Result<Modes, Error> {
    let subsets = selected_subsets(source, m, selection, max_subsets, settings)?;
    let start = start_configuration(m, pose)?;
    Ok(if subsets.len() > 1 {
        let bar = crate::terminal::progress(subsets.len(), "lock subsets", "modes");
        let modes = m.modes_from(&start, &subsets, settings, &|| bar.inc(1));
        bar.finish_and_clear();
        modes
    } else {
        m.modes_from(&start, &subsets, settings, &|| {})
    })
}

/// The report of `kinsyn modes --json` (and of Python's `Manipulator.modes`): the sampled
/// motions of [`Modes`] (the manipulator, its inputs, the sampling settings, the start
/// configuration, every lock subset's motion and the patterns reached) with the request and
/// the end-effector.
///
/// Printed through [`crate::sorted_value`]: its keys, those of [`Modes`] among them, come in
/// alphabetical order, as they did when the report was built as a `serde_json` object, not in
/// the order of these fields.
#[derive(Debug, Clone, Serialize)]
pub struct ModesReport<'a> {
    /// The motions sampled, their fields at the top level of the report.
    #[serde(flatten)]
    pub modes: &'a Modes,
    /// `--pose`: the start pose as given (`x,y,z,rx,ry,rz`, the description's length and
    /// angle units), `null` for the reference configuration.
    pub pose: Option<String>,
    /// `--max-locks`: the most inputs locked in a subset sampled, `null` unless given.
    pub max_locks: Option<usize>,
    /// `--lock`: the one subset sampled, its labels space separated (`-` for none), `null`
    /// unless given.
    pub lock: Option<String>,
    /// The leg warnings of the description (docs/mechanism-format.md, "Leg checks").
    pub warnings: Vec<String>,
    /// The name of the moving body whose motion the patterns describe.
    pub end_effector: String,
}

/// The report of `kinsyn modes --json`: every sampled subset and pattern of `modes` (from
/// [`sample_modes`]), with the request (start `pose`, `selection`), the leg `warnings` and the
/// end-effector of `m`.
#[must_use]
pub fn modes_report<'a>(
    m: &Manipulator,
    modes: &'a Modes,
    pose: Option<&str>,
    selection: &Selection,
    warnings: &[String],
) -> ModesReport<'a> {
    ModesReport {
        modes,
        pose: pose.map(str::to_string),
        max_locks: match selection {
            Selection::MaxLocks(k) => Some(*k),
            _ => None,
        },
        lock: match selection {
            Selection::Lock(_) => modes.modes.first().map(|m| m.lock_text.clone()),
            _ => None,
        },
        warnings: warnings.to_vec(),
        end_effector: m.bodies()[m.end_effector()].name.clone(),
    }
}
