//! `kinsyn modes`: the lock subsets chosen, sampled with a progress bar, and the patterns
//! reached — a summary per dof, one subset in detail, or JSON.

use super::analyze::configuration_at_pose;
use super::{body_names, clean, leg_warnings, load_with_body, warn};
use crate::{Error, sorted_json};
use kinsyn::manipulator::{Manipulator, Mode, Modes, ModesCost, PatternModes};
use kinsyn::mechanism::{ASSEMBLY_STEPS, SampleSettings};
use kinsyn::motion::MIN_SEPARATION;
use serde::Serialize;
use std::fmt::Write as _;
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

/// The lock sets printed per pattern in text; `--json` lists them all.
const LOCK_SETS_SHOWN: usize = 6;

/// The patterns printed per dof and per list of the summary in text; `--json` lists them all.
const PATTERNS_SHOWN: usize = 12;

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

/// `kinsyn modes`: the platform's motion for the selected lock subsets, with the locked inputs
/// held at their values at the start configuration (the reference, or `--pose`).
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
    as_json: bool,
) -> Result<String, Error> {
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
    warn(path, &warnings);
    if as_json {
        return Ok(sorted_json(&modes_report(
            &m, &modes, pose, selection, &warnings,
        )));
    }
    let mut s = modes_header(&m, &modes, pose, selection);
    if let Selection::Lock(_) = selection {
        s += &mode_detail(&modes.modes[0]);
    } else {
        s += &modes_by_dof(&modes);
        s += &capacity_text(&modes);
    }
    Ok(s)
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

/// The first lines of `modes`: the manipulator, its inputs, the subsets sampled and how, and
/// the start configuration where the locks hold.
fn modes_header(
    m: &Manipulator,
    modes: &Modes,
    pose: Option<&str>,
    selection: &Selection,
) -> String {
    let count = modes.modes.len();
    let scope = match selection {
        Selection::All => String::new(),
        Selection::MaxLocks(k) => format!(" with at most {k} locked"),
        Selection::Lock(_) => format!(" ({})", modes.modes[0].lock_text),
    };
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{}: {} inputs ({}), {count} lock subset{}{scope}; finite motion sampled by loop closure ({} samples, seed {})",
        modes.manipulator,
        modes.actuators.len(),
        modes.actuators.join(" "),
        if count == 1 { "" } else { "s" },
        modes.settings.samples,
        modes.settings.seed
    );
    let p = modes.start_position;
    let r = nalgebra::Vector3::from(modes.start_rotation_vector_rad);
    let (r, angle) = match m.units().angle {
        kinsyn::manipulator::file::AngleUnit::Deg => (r.map(f64::to_degrees), "deg"),
        kinsyn::manipulator::file::AngleUnit::Rad => (r, "rad"),
    };
    if let Some(base) = m.relative_body() {
        let _ = writeln!(
            s,
            "patterns of {:?} relative to {:?}: the displacements of {:?} seen from {:?}, in the frame of {:?} at the reference (moving bodies: {})",
            m.bodies()[m.end_effector()].name,
            m.bodies()[base].name,
            m.bodies()[m.end_effector()].name,
            m.bodies()[base].name,
            m.bodies()[base].name,
            body_names(m)
        );
    } else if m.bodies().len() > 1 {
        let _ = writeln!(
            s,
            "patterns of the end-effector {:?} (moving bodies: {}; --body NAME for another)",
            m.bodies()[m.end_effector()].name,
            body_names(m)
        );
    }
    let _ = writeln!(
        s,
        "start: {}: platform frame at [{:.6}, {:.6}, {:.6}] {}, rotation vector [{:.6}, {:.6}, {:.6}] {angle}; locked inputs held at their values there",
        pose.map_or_else(
            || "the reference configuration".to_string(),
            |t| format!("--pose {t}")
        ),
        clean(p[0]),
        clean(p[1]),
        clean(p[2]),
        m.units().length,
        clean(r.x),
        clean(r.y),
        clean(r.z),
    );
    s
}

/// At most [`LOCK_SETS_SHOWN`] lock sets, ` | ` between them, then how many more `--json` lists.
fn lock_sets_text(sets: &[String]) -> String {
    let mut text = sets
        .iter()
        .take(LOCK_SETS_SHOWN)
        .map(String::as_str)
        .collect::<Vec<_>>()
        .join(" | ");
    if sets.len() > LOCK_SETS_SHOWN {
        let _ = write!(
            text,
            " … and {} more (see --json)",
            sets.len() - LOCK_SETS_SHOWN
        );
    }
    text
}

/// One line per pattern, at most [`PATTERNS_SHOWN`], then how many more `--json` lists.
fn pattern_lines<T>(s: &mut String, patterns: &[T], line: impl Fn(&T) -> String) {
    for p in patterns.iter().take(PATTERNS_SHOWN) {
        let _ = writeln!(s, "  {}", line(p));
    }
    if patterns.len() > PATTERNS_SHOWN {
        let _ = writeln!(
            s,
            "  … and {} more patterns (see --json)",
            patterns.len() - PATTERNS_SHOWN
        );
    }
}

/// A pattern's parameters in parentheses, or nothing.
fn parameters_text(p: &PatternModes) -> String {
    p.parameters
        .as_ref()
        .map(|x| format!(" ({x})"))
        .unwrap_or_default()
}

/// The patterns reached, by platform dof from the most to none: for each, how many subsets give
/// it and its minimal lock sets; then the subsets whose motion could not be sampled.
fn modes_by_dof(modes: &Modes) -> String {
    let mut s = String::new();
    let mut dofs: Vec<usize> = modes
        .groups
        .iter()
        .chain(&modes.non_groups)
        .map(|p| p.dof)
        .collect();
    dofs.sort_unstable_by(|a, b| b.cmp(a));
    dofs.dedup();
    let plural = |k: usize| if k == 1 { "" } else { "s" };
    let kinds = [(&modes.groups, "group"), (&modes.non_groups, "")];
    for dof in dofs {
        // Groups first, then nTmR patterns, each with its kind.
        let here: Vec<(&PatternModes, &str)> = kinds
            .iter()
            .flat_map(|&(list, kind)| list.iter().filter(|p| p.dof == dof).map(move |p| (p, kind)))
            .collect();
        let subsets: usize = here.iter().map(|(p, _)| p.subsets).sum();
        let _ = writeln!(
            s,
            "\ndof {dof}: {subsets} subset{}, {} pattern{}",
            plural(subsets),
            here.len(),
            plural(here.len())
        );
        pattern_lines(&mut s, &here, |(p, kind)| {
            format!(
                "{:<8} {kind:<5} {:>5} subset{:<1}  lock {}{}",
                p.pattern,
                p.subsets,
                plural(p.subsets),
                lock_sets_text(&p.lock_sets),
                parameters_text(p)
            )
        });
    }
    let singular = modes.modes.iter().filter(|m| m.is_singular_start()).count();
    if singular > 0 {
        let _ = writeln!(
            s,
            "\n{singular} of {} subsets start at a singular configuration of the locked manipulator (more freedom there than along its motion: the branch the motion takes, hence its pattern, is not unique; not counted): lock {}",
            modes.modes.len(),
            lock_sets_text(&modes.singular_starts)
        );
    }
    let failed: Vec<&Mode> = modes.modes.iter().filter(|m| m.error.is_some()).collect();
    if let Some(first) = failed.first() {
        let _ = writeln!(
            s,
            "\n{} of {} subsets could not be sampled (pattern ?, listed in --json); the first, lock {}: {}",
            failed.len(),
            modes.modes.len(),
            first.lock_text,
            first.error.as_deref().unwrap_or_default()
        );
    }
    s
}

/// The multioperation capacity: the displacement subgroups reached with their parameters and
/// minimal lock sets, the kinds among the 12, and the non-group patterns.
fn capacity_text(modes: &Modes) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\nmultioperation capacity: {} displacement subgroup{} reached, of {} of the 12 kinds ({}):",
        modes.groups.len(),
        if modes.groups.len() == 1 { "" } else { "s" },
        modes.group_kinds.len(),
        if modes.group_kinds.is_empty() {
            "none".to_string()
        } else {
            modes.group_kinds.join(" ")
        }
    );
    let line = |g: &PatternModes| {
        format!(
            "{:<8} lock {}{}",
            g.pattern,
            lock_sets_text(&g.lock_sets),
            parameters_text(g)
        )
    };
    pattern_lines(&mut s, &modes.groups, line);
    if !modes.non_groups.is_empty() {
        let _ = writeln!(s, "non-group patterns:");
        pattern_lines(&mut s, &modes.non_groups, line);
    }
    s
}

/// One lock subset in detail (`modes --lock`): dof, pattern with its group parameters, the gap
/// of the rank decisions, the samples' smallest separation, or why it could not be sampled.
fn mode_detail(mode: &Mode) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "locked: {}", mode.lock_text);
    let Some(c) = &mode.classification else {
        let _ = writeln!(
            s,
            "pattern: ? (the motion could not be sampled: {})",
            mode.error.as_deref().unwrap_or_default()
        );
        return s;
    };
    let _ = writeln!(s, "dof: {}", mode.dof);
    let kind = if mode.group {
        "one of the 12 displacement groups"
    } else {
        "not a displacement group"
    };
    let _ = writeln!(
        s,
        "pattern: {} ({kind}{})",
        mode.pattern_text(),
        mode.parameters
            .as_ref()
            .map(|p| format!("; {p}"))
            .unwrap_or_default()
    );
    if let Some(start) = &c.singular_start {
        let _ = writeln!(
            s,
            "singular start: {} degrees of freedom here, {} along the sampled motion; the motion branches here, and the pattern above is that of the branches these walks took (another seed may take another)",
            start.start_dof, start.motion_dof
        );
    }
    let _ = writeln!(
        s,
        "rank gap: smallest kept singular value {}, largest dropped {:.3e} (each relative to its rank decision's scale, over the samples)",
        c.rank_gap
            .smallest_kept
            .map_or_else(|| "none (rank 0)".to_string(), |k| format!("{k:.3e}")),
        c.rank_gap.largest_dropped
    );
    let _ = writeln!(
        s,
        "min separation: {} (dimensionless pose distance between samples; a group is claimed only from samples at least {MIN_SEPARATION:e} apart)",
        c.min_separation
            .map_or_else(|| "none (one sample)".to_string(), |d| format!("{d:.3e}"))
    );
    s
}
