//! The text of `kinsyn modes`: the manipulator and the subsets sampled, then a summary of the
//! patterns by dof and the multioperation capacity, or one lock subset in detail (`--lock`).

use kinsyn::manipulator::{Manipulator, Mode, Modes, PatternModes};
use kinsyn::motion::MIN_SEPARATION;
use kinsyn_report::manipulator::{Selection, clean};
use std::fmt::Write as _;

/// The lock sets printed per pattern in text; `--json` lists them all.
const LOCK_SETS_SHOWN: usize = 6;

/// The patterns printed per dof and per list of the summary in text; `--json` lists them all.
const PATTERNS_SHOWN: usize = 12;

/// The text report of `kinsyn modes`: the `modes` of `m` sampled from the start `pose` (the
/// reference when `None`) for the subsets of `selection`.
pub(in crate::cli) fn text(
    m: &Manipulator,
    modes: &Modes,
    pose: Option<&str>,
    selection: &Selection,
) -> String {
    let mut s = modes_header(m, modes, pose, selection);
    if let Selection::Lock(_) = selection {
        s += &mode_detail(&modes.modes[0]);
    } else {
        s += &modes_by_dof(modes);
        s += &capacity_text(modes);
    }
    s
}

/// The moving bodies' names, comma separated, the end-effector marked.
fn body_names(m: &Manipulator) -> String {
    m.bodies()
        .iter()
        .enumerate()
        .map(|(k, b)| {
            if k == m.end_effector() {
                format!("{} (end-effector)", b.name)
            } else {
                b.name.clone()
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
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
