//! `kinsyn build`, `kinsyn modes`, `kinsyn analyze`: manipulators from description files.

use super::{CliError, json};
use indicatif::{ProgressBar, ProgressStyle};
use kinsyn::manipulator::build::{BuildField, BuildSpec, build};
use kinsyn::manipulator::{
    Analysis, ContinuationFailure, Manipulator, ManipulatorError, Mode, Modes, PatternModes,
    PositionError, PositionRequest, RowKind, file, rank_text,
};
use kinsyn::mechanism::SampleSettings;
use kinsyn::motion::MIN_SEPARATION;
use std::fmt::Write as _;
use std::io::Read as _;
use std::path::Path;

/// The largest manipulator file read, in bytes: the largest description within the limits of
/// docs/limits.md (12 legs of 6 joints, written out with every optional field) is under
/// 64 KiB; anything much larger is not a description.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// Reads and builds a manipulator file; errors name the file and the field. A path that is
/// not a regular file, a file over [`MAX_FILE_BYTES`], or text that is not UTF-8 or not a
/// description is refused as "not a kinsyn manipulator file" before it is parsed further.
pub fn load(path: &Path) -> Result<Manipulator, CliError> {
    let shown = path.display();
    let refuse =
        |why: String| CliError::Input(format!("{shown} is {} ({why})", file::NOT_A_DESCRIPTION));
    let metadata = std::fs::metadata(path).map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
    if !metadata.is_file() {
        return Err(refuse(if metadata.is_dir() {
            "a directory".into()
        } else {
            "not a regular file".into()
        }));
    }
    if metadata.len() > MAX_FILE_BYTES {
        return Err(refuse(format!(
            "{} bytes; description files are at most {} bytes",
            metadata.len(),
            MAX_FILE_BYTES
        )));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_FILE_BYTES + 1).read_to_end(&mut bytes))
        .map_err(|e| CliError::Input(format!("{shown}: {e}")))?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(refuse(format!(
            "more than {MAX_FILE_BYTES} bytes; description files are at most that"
        )));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        refuse(format!(
            "not UTF-8 text: invalid byte at offset {}",
            e.utf8_error().valid_up_to()
        ))
    })?;
    Manipulator::from_json(&text).map_err(|e| match &e {
        ManipulatorError::Description(d) if d.is_not_a_description() => {
            CliError::Input(format!("{shown} is {}", d.message))
        }
        _ => CliError::Input(format!("{shown}: {e}")),
    })
}

/// [`load`], with the moving body `body` (`--body NAME`) as the end-effector when given.
fn load_with_body(path: &Path, body: Option<&str>) -> Result<Manipulator, CliError> {
    let m = load(path)?;
    match body {
        None => Ok(m),
        Some(name) => m
            .with_end_effector(name)
            .map_err(|e| CliError::Input(format!("--body {name:?}: {e}"))),
    }
}

/// The leg warnings of `m` (docs/mechanism-format.md, "Leg checks").
fn leg_warnings(m: &Manipulator) -> Vec<String> {
    m.leg_warnings().iter().map(ToString::to_string).collect()
}

/// Prints each warning on stderr as one line `warning: FILE: …`. Called once the command has
/// succeeded, so that an error stays the only line on stderr.
fn warn(path: &Path, warnings: &[String]) {
    for w in warnings {
        super::terminal::warning(&format!("{}: {w}", path.display()));
    }
}

/// The `kinsyn build` option that sets a [`BuildSpec`] field.
fn build_flag(field: BuildField) -> String {
    match field {
        BuildField::Legs => "--legs",
        BuildField::Chain => "--chain",
        BuildField::Axes => "--axes",
        BuildField::Actuated => "--actuated",
        BuildField::BaseRadius => "--base-radius",
        BuildField::PlatformRadius => "--platform-radius",
        BuildField::Height => "--height",
        BuildField::Twist => "--twist",
    }
    .to_string()
}

/// `kinsyn build`: writes a description (to `output`, or returns it for stdout).
pub fn build_command(spec: &BuildSpec, output: Option<&Path>) -> Result<String, CliError> {
    let description = build(spec).map_err(|e| CliError::Input(e.describe(build_flag)))?;
    // Check that what is written can be read back and built.
    let m = Manipulator::new(&description).map_err(|e| {
        CliError::Input(format!(
            "--chain {:?} in this geometry makes no usable manipulator: {e}",
            spec.chain.trim()
        ))
    })?;
    // `build` refuses legs that are not generic; the file as read back must agree.
    if let Some(w) = m.leg_warnings().first() {
        return Err(CliError::Input(format!(
            "--chain {:?}: {w}",
            spec.chain.trim()
        )));
    }
    let text = description.to_json();
    match output {
        Some(path) => {
            std::fs::write(path, &text)
                .map_err(|e| std::io::Error::new(e.kind(), format!("{}: {e}", path.display())))?;
            let mobility = m.mechanism().mobility(&m.reference(), &[]).dof;
            let (twists, _) = m.platform_twists(&m.reference(), &[]);
            let dof = twists.ncols();
            Ok(format!(
                "wrote {} ({}: {} legs, {} inputs; mobility {mobility}, platform dof {dof} at the reference pose)\n",
                path.display(),
                description.name,
                description.legs.len(),
                m.actuators().len()
            ))
        }
        None => Ok(text),
    }
}

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

/// The default of `modes --max-subsets`: 4096 sampled motions, about 16–20 s of CPU for legs
/// like the 6-UPS's (4–5 ms per subset measured, docs/limits-modes.md), and every subset of up
/// to 12 inputs.
pub const DEFAULT_MAX_SUBSETS: u32 = 4096;

/// The largest `--max-subsets`: 2^16, every subset of 16 inputs (the old limit of 16 inputs),
/// about 4–6 minutes of CPU at 4–5 ms per subset.
pub const MAX_SUBSETS_CEILING: u32 = 1 << 16;

/// The lock sets printed per pattern in text; `--json` lists them all.
const LOCK_SETS_SHOWN: usize = 6;

/// The patterns printed per dof and per list of the summary in text; `--json` lists them all.
const PATTERNS_SHOWN: usize = 12;

/// The configuration the modes are sampled from: the file's reference configuration, or the
/// assembly with the platform frame at `pose` (`x,y,z,rx,ry,rz` as for `analyze --pose`) with
/// every input free, so that each subset's locked inputs are held at their values there.
fn start_configuration(m: &Manipulator, pose: Option<&str>) -> Result<Vec<f64>, CliError> {
    match pose {
        None => Ok(m.reference()),
        Some(text) => configuration_at_pose(m, "--pose", text, &[]),
    }
}

/// The lock subsets a selection asks for, refused when they are more than `max_subsets`
/// (each is one sampled motion; the refusal says how to ask for fewer).
fn selected_subsets(
    path: &Path,
    m: &Manipulator,
    selection: &Selection,
    max_subsets: u32,
) -> Result<Vec<Vec<usize>>, CliError> {
    let n = m.actuators().len();
    let max_locks = match selection {
        Selection::Lock(text) => {
            let locked = m
                .parse_locks(text)
                .map_err(|e| CliError::Input(format!("--lock {text:?}: {e}")))?;
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
    Err(CliError::Input(format!(
        "{}: {n} inputs give {count} lock subsets {scope}, more than --max-subsets {max_subsets} (each is a sampled motion of about 1–5 ms of CPU, docs/limits.md); use --max-locks {fits} ({} subsets) or --lock SET, or raise --max-subsets (at most {MAX_SUBSETS_CEILING})",
        path.display(),
        m.lock_subset_count(fits)
    )))
}

/// A progress bar over `count` lock subsets on stderr. indicatif hides it (draws nothing) when
/// stderr is not a terminal, so pipes, files and tests see only the output and the errors.
fn subset_progress(count: usize) -> ProgressBar {
    let bar = ProgressBar::new(count as u64);
    if let Ok(style) = ProgressStyle::with_template(
        "{msg} [{bar:30}] {pos}/{len} lock subsets, {elapsed} elapsed, about {eta} left",
    ) {
        bar.set_style(style.progress_chars("=> "));
    }
    bar.set_message("modes");
    bar
}

/// `kinsyn modes`: the platform's motion for the selected lock subsets, with the locked inputs
/// held at their values at the start configuration (the reference, or `--pose`).
pub fn modes(
    path: &Path,
    (pose, body): (Option<&str>, Option<&str>),
    selection: &Selection,
    max_subsets: u32,
    settings: &SampleSettings,
    as_json: bool,
) -> Result<String, CliError> {
    let m = load_with_body(path, body)?;
    let subsets = selected_subsets(path, &m, selection, max_subsets)?;
    let start = start_configuration(&m, pose)?;
    let modes = if subsets.len() > 1 {
        let bar = subset_progress(subsets.len());
        let modes = m.modes_from(&start, &subsets, settings, &|| bar.inc(1));
        bar.finish_and_clear();
        modes
    } else {
        m.modes_from(&start, &subsets, settings, &|| {})
    };
    let warnings = leg_warnings(&m);
    warn(path, &warnings);
    if as_json {
        let mut value = modes_json(&modes, pose, selection, &warnings);
        if let Some(object) = value.as_object_mut() {
            object.insert(
                "end_effector".into(),
                serde_json::json!(m.bodies()[m.end_effector()].name),
            );
        }
        return Ok(json(&value));
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

/// `modes --json`: every sampled subset and pattern, with the request (start pose, subsets) and
/// the leg warnings.
fn modes_json(
    modes: &Modes,
    pose: Option<&str>,
    selection: &Selection,
    warnings: &[String],
) -> serde_json::Value {
    let mut value = serde_json::to_value(modes).unwrap_or_default();
    if let Some(object) = value.as_object_mut() {
        object.insert("pose".into(), serde_json::json!(pose));
        object.insert(
            "max_locks".into(),
            serde_json::json!(match selection {
                Selection::MaxLocks(k) => Some(k),
                _ => None,
            }),
        );
        object.insert(
            "lock".into(),
            serde_json::json!(match selection {
                Selection::Lock(_) => modes.modes.first().map(|m| m.lock_text.clone()),
                _ => None,
            }),
        );
        object.insert("warnings".into(), serde_json::json!(warnings));
    }
    value
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
    if m.bodies().len() > 1 {
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

/// The platform pose of `--pose TEXT` (or another option named `option`) for `m`, assembled
/// from the reference configuration with the `locked` inputs held.
pub fn configuration_at_pose(
    m: &Manipulator,
    option: &str,
    text: &str,
    locked: &[usize],
) -> Result<Vec<f64>, CliError> {
    let request = PositionRequest {
        platform: Some(
            m.parse_pose(text)
                .map_err(|e| CliError::Input(format!("{option} {text:?}: {e}")))?,
        ),
        held: locked.to_vec(),
        ..PositionRequest::default()
    };
    m.solve_position(&m.reference(), &request)
        .map(|p| p.q)
        .map_err(|e| CliError::Input(format!("{option} {text:?}: {}", position_error(&e))))
}

/// A position error in words, with the option that helps when the start is too far.
fn position_error(e: &ManipulatorError) -> String {
    match e {
        ManipulatorError::Position(PositionError::NotReached(
            ContinuationFailure::TooManySteps { .. },
        )) => format!("{e} (analyze --from)"),
        _ => e.to_string(),
    }
}

/// Where `kinsyn analyze` puts the manipulator: a start (the reference, or `--from`), then the
/// input values and platform coordinates asked for, reached by continuation from it.
#[derive(Debug, Default)]
pub struct Placement<'a> {
    /// `--pose`: a whole or partial platform pose.
    pub pose: Option<&'a str>,
    /// `--inputs`: input values.
    pub inputs: Option<&'a str>,
    /// `--from`: the pose of the start configuration.
    pub from: Option<&'a str>,
    /// `--body`: the moving body analysed instead of the description's end-effector.
    pub body: Option<&'a str>,
}

/// How the configuration analysed was reached, for the report.
struct Reached {
    /// "the reference configuration" or "--from …".
    start: String,
    /// Whether the start was given (`--from`) rather than the reference.
    start_given: bool,
    /// Continuation steps from the start (0 when nothing was asked).
    steps: usize,
    /// Whether the configuration is the one continuous with the start.
    continuous: bool,
}

/// `kinsyn analyze`.
pub fn analyze(
    path: &Path,
    placement: &Placement<'_>,
    lock: Option<&str>,
    settings: &SampleSettings,
    as_json: bool,
) -> Result<String, CliError> {
    let m = load_with_body(path, placement.body)?;
    let locked = match lock {
        Some(text) => m
            .parse_locks(text)
            .map_err(|e| CliError::Input(format!("--lock {text:?}: {e}")))?,
        None => Vec::new(),
    };
    let (start, start_text) = match placement.from {
        Some(text) => (
            configuration_at_pose(&m, "--from", text, &[])?,
            format!("--from {text}"),
        ),
        None => (m.reference(), "the reference configuration".to_string()),
    };
    let mut request = PositionRequest {
        held: locked.clone(),
        ..PositionRequest::default()
    };
    if let Some(text) = placement.inputs {
        request.inputs = m
            .parse_inputs(text)
            .map_err(|e| CliError::Input(format!("--inputs {text:?}: {e}")))?;
        // Without a pose, inputs not named keep their values at the start; with one, they
        // are free, and the pose and the named inputs are met together.
        if placement.pose.is_none() {
            request.held.extend(
                (0..m.actuators().len()).filter(|a| !request.inputs.iter().any(|&(b, _)| b == *a)),
            );
        }
    }
    if let Some(text) = placement.pose {
        request.platform = Some(
            m.parse_pose(text)
                .map_err(|e| CliError::Input(format!("--pose {text:?}: {e}")))?,
        );
    }
    let (q, steps, continuous) = if request.inputs.is_empty() && request.platform.is_none() {
        (start, 0, true)
    } else {
        let asked: Vec<String> = [("--inputs", placement.inputs), ("--pose", placement.pose)]
            .iter()
            .filter_map(|(o, t)| t.map(|t| format!("{o} {t:?}")))
            .collect();
        let p = m
            .solve_position(&start, &request)
            .map_err(|e| CliError::Input(format!("{}: {}", asked.join(" "), position_error(&e))))?;
        (p.q, p.steps, p.continuous)
    };
    let reached = Reached {
        start: start_text,
        start_given: placement.from.is_some(),
        steps,
        continuous,
    };
    let a = m
        .analyse(&q, &locked, settings)
        .map_err(|e| CliError::Input(e.to_string()))?;
    let warnings = leg_warnings(&m);
    warn(path, &warnings);
    if as_json {
        return Ok(json(&analysis_json(&m, &a, &reached, &warnings)));
    }
    Ok(analysis_text(&m, &a, &reached))
}

/// The input values at `q` in the file's units (lengths, or angles in its angle unit), with
/// their labels: `P1.3 = 0.050000`.
fn input_values(m: &Manipulator, q: &[f64]) -> Vec<(String, f64)> {
    m.actuators()
        .iter()
        .map(|a| {
            let value = q[a.joint];
            let shown = match a.kind {
                kinsyn::notation::Primitive::R => m.units().angle.from_radians(value),
                kinsyn::notation::Primitive::P => value,
            };
            (a.label(), shown)
        })
        .collect()
}

fn row_label(m: &Manipulator, kind: RowKind) -> String {
    match kind {
        RowKind::Actuation { actuator } => format!("input {}", m.actuators()[actuator].label()),
        RowKind::Locked { actuator } => format!("locked {}", m.actuators()[actuator].label()),
        RowKind::Constraint { leg } => format!("constraint leg {}", leg + 1),
    }
}

fn analysis_json(
    m: &Manipulator,
    a: &Analysis,
    reached: &Reached,
    warnings: &[String],
) -> serde_json::Value {
    let frame = m.platform_frame(&a.q);
    let rv = kinsyn::mechanism::rotation_log(&frame.rotation);
    let rows: Vec<serde_json::Value> = a
        .jacobians
        .rows
        .iter()
        .map(|r| serde_json::json!({"row": row_label(m, r.kind), "jd": r.wrench, "ji": r.input}))
        .collect();
    serde_json::json!({
        "manipulator": m.name(),
        "units": m.units(),
        "locked": m.lock_text(&a.locked),
        "point": [a.jacobians.point.x, a.jacobians.point.y, a.jacobians.point.z],
        "platform_position": [frame.translation.x, frame.translation.y, frame.translation.z],
        "platform_rotation_vector_rad": [rv.x, rv.y, rv.z],
        "joint_values": a.q,
        "input_values": input_values(m, &a.q).into_iter().map(|(k, v)| (k, serde_json::json!(v))).collect::<serde_json::Map<String, serde_json::Value>>(),
        "reached_from": reached.start,
        "continuation_steps": reached.steps,
        "continuous_with_start": reached.continuous,
        "mobility": a.mobility,
        "closure_rank": rank_json(&a.closure_rank, None),
        "platform_dof": a.platform_dof,
        "inputs": a.jacobians.free.iter().map(|&i| m.actuators()[i].label()).collect::<Vec<_>>(),
        "rows": rows,
        "jd_rank": rank_json(&a.jd_rank, Some(a.generic.jd)),
        "constraint_rank": rank_json(&a.constraint_rank, Some(a.generic.constraint)),
        "leg_ranks": a.leg_ranks.iter().zip(&a.generic.legs).map(|(r, &g)| rank_json(r, Some(g))).collect::<Vec<_>>(),
        "generic_assemblies": a.generic.assemblies,
        "singularities": a.singularities,
        "warnings": warnings,
        "end_effector": m.bodies()[m.end_effector()].name,
        "bodies": bodies_json(m, a),
        "leg_wrench_jacobians": a.leg_wrench_jacobians,
        "inputs_with_end_effector_held": {
            "here": a.inputs_with_end_effector_held,
            "generic": a.generic.inputs_with_end_effector_held,
        },
    })
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

/// Each moving body at the configuration analysed: its name, dof with the locked inputs held,
/// frame origin, rotation vector (radians) and reference point.
fn bodies_json(m: &Manipulator, a: &Analysis) -> serde_json::Value {
    let bodies: Vec<serde_json::Value> = m
        .bodies()
        .iter()
        .enumerate()
        .map(|(k, b)| {
            let frame = m.body_frame(k, &a.q);
            let rv = kinsyn::mechanism::rotation_log(&frame.rotation);
            let p = m.body_point(k, &a.q);
            serde_json::json!({
                "name": b.name,
                "end_effector": k == m.end_effector(),
                "dof": a.body_dof[k],
                "position": [frame.translation.x, frame.translation.y, frame.translation.z],
                "rotation_vector_rad": [rv.x, rv.y, rv.z],
                "point": [p.x, p.y, p.z],
            })
        })
        .collect();
    serde_json::Value::Array(bodies)
}

/// A rank decision with its gap and the generic rank it is compared with.
fn rank_json(r: &kinsyn::screw::Rank, generic: Option<usize>) -> serde_json::Value {
    let (kept, dropped) = r.gap();
    serde_json::json!({
        "rank": r.rank,
        "generic": generic,
        "tolerance": r.tolerance,
        "gap": {"smallest_kept": kept, "largest_dropped": dropped},
        "singular_values": r.singular_values,
    })
}

/// The labels of the inputs left free in an analysis.
fn free_labels(m: &Manipulator, a: &Analysis) -> Vec<String> {
    a.jacobians
        .free
        .iter()
        .map(|&i| m.actuators()[i].label())
        .collect()
}

fn jacobian_text(m: &Manipulator, a: &Analysis) -> String {
    let mut s = String::new();
    let inputs = free_labels(m, a);
    let _ = writeln!(
        s,
        "J_D [v_P; ω] = J_I [{}]   (rows: wrenches (f; m_P) at P; J_I column of the row's input)",
        inputs.join(" ")
    );
    for r in &a.jacobians.rows {
        let cells: Vec<String> = r
            .wrench
            .iter()
            .map(|&x| format!("{:>10.6}", clean(x)))
            .collect();
        let _ = writeln!(
            s,
            "  {:<20} [{}] | {:.6}",
            row_label(m, r.kind),
            cells.join(" "),
            r.input
        );
    }
    let _ = writeln!(
        s,
        "J_D: {} (generic {})",
        rank_text(&a.jd_rank),
        a.generic.jd
    );
    let _ = writeln!(
        s,
        "constraint rows: {} (generic {})",
        rank_text(&a.constraint_rank),
        a.generic.constraint
    );
    s
}

/// What replaces `J_D`, `J_I` when the legs do not all run from the ground to the end-effector:
/// why they are not defined, and the end-effector's input–output freedoms from the loop
/// closure (docs/manipulators.md, "Several moving bodies").
fn closure_io_text(m: &Manipulator, a: &Analysis) -> String {
    let mut s = String::new();
    let ee = m.platform();
    let off: Vec<String> = m
        .legs()
        .iter()
        .enumerate()
        .filter(|(_, l)| l.from != m.mechanism().ground() || l.to != ee)
        .map(|(i, l)| {
            format!(
                "leg {} {} → {}",
                i + 1,
                m.mechanism().body_name(l.from),
                m.mechanism().body_name(l.to)
            )
        })
        .collect();
    let _ = writeln!(
        s,
        "J_D, J_I: not defined: paper 000's leg wrenches act on the end-effector only when every leg runs from the ground to it, and {} do not; from the loop-closure Jacobian instead:",
        off.join(", ")
    );
    let plural = |n: usize| if n == 1 { "" } else { "s" };
    let held = 6 - a.jd_rank.rank;
    let generic_held = 6 - a.generic.jd;
    let _ = writeln!(
        s,
        "  with every input held, the end-effector keeps {held} dof (generic {generic_held}; 0 when the inputs fix it)"
    );
    let _ = writeln!(
        s,
        "  with the locked inputs held, the end-effector has {} dof: constraint wrenches of rank {} (generic {})",
        a.platform_dof, a.constraint_rank.rank, a.generic.constraint
    );
    let free = free_labels(m, a);
    let _ = writeln!(
        s,
        "  with the end-effector held, the free inputs [{}] keep {} independent rate{} (generic {})",
        free.join(" "),
        a.inputs_with_end_effector_held,
        plural(a.inputs_with_end_effector_held),
        a.generic.inputs_with_end_effector_held
    );
    s
}

/// The opening lines of `analyze`: the configuration analysed (the end-effector's point P and
/// rotation vector, the locked inputs), how it was reached from the start, and the input
/// values.
fn configuration_text(m: &Manipulator, a: &Analysis, reached: &Reached) -> String {
    let mut s = String::new();
    let frame = m.platform_frame(&a.q);
    let rv = kinsyn::mechanism::rotation_log(&frame.rotation);
    let p = a.jacobians.point;
    let several = m.bodies().len() > 1;
    let title = if several {
        format!(
            "{}, end-effector {:?}",
            m.name(),
            m.bodies()[m.end_effector()].name
        )
    } else {
        m.name().to_string()
    };
    let _ = writeln!(
        s,
        "{title}: P = [{:.6}, {:.6}, {:.6}] {}; platform rotation vector [{:.6}, {:.6}, {:.6}] rad; locked: {}",
        clean(p.x),
        clean(p.y),
        clean(p.z),
        m.units().length,
        clean(rv.x),
        clean(rv.y),
        clean(rv.z),
        m.lock_text(&a.locked)
    );
    if !reached.continuous {
        let _ = writeln!(
            s,
            "reached from {} by damped Newton steps, not by continuation: the path of the values from the start leaves the workspace or meets a singularity, so this may be another assembly mode than the start's",
            reached.start
        );
    } else if reached.steps > 0 || reached.start_given {
        let _ = writeln!(
            s,
            "reached from {} in {} continuation step{}: the assembly continuous with it (another start, --from POSE, may give another assembly)",
            reached.start,
            reached.steps,
            if reached.steps == 1 { "" } else { "s" }
        );
    }
    let values: Vec<String> = input_values(m, &a.q)
        .iter()
        .map(|(label, v)| format!("{label} = {:.6}", clean(*v)))
        .collect();
    let _ = writeln!(
        s,
        "input values (from the reference; {}, angles in {}): {}",
        m.units().length,
        m.units().angle.name(),
        values.join(", ")
    );
    s
}

fn analysis_text(m: &Manipulator, a: &Analysis, reached: &Reached) -> String {
    let mut s = configuration_text(m, a, reached);
    let several = m.bodies().len() > 1;
    if several {
        let dofs: Vec<String> = m
            .bodies()
            .iter()
            .zip(&a.body_dof)
            .map(|(b, d)| format!("{} {d}", b.name))
            .collect();
        let _ = writeln!(
            s,
            "mobility {} (joint rates closing the loops); moving bodies' dof (twist spaces on the loop closure): {}; end-effector {:?}",
            a.mobility,
            dofs.join(", "),
            m.bodies()[m.end_effector()].name
        );
    } else {
        let _ = writeln!(
            s,
            "mobility {} (joint rates closing the loops), platform dof {} (6 − rank of the constraint wrenches; {} internal)",
            a.mobility,
            a.platform_dof,
            a.mobility.saturating_sub(a.platform_dof)
        );
    }
    let (kept, dropped) = a.closure_rank.gap();
    let _ = writeln!(
        s,
        "loop closure: rank {} over {} free joint rates, gap {kept:.3e} kept / {dropped:.3e} dropped",
        a.closure_rank.rank,
        a.closure_rank.rank + a.mobility,
    );
    if a.leg_wrench_jacobians {
        s += &jacobian_text(m, a);
    } else {
        s += &closure_io_text(m, a);
    }
    for (i, (r, g)) in a.leg_ranks.iter().zip(&a.generic.legs).enumerate() {
        let _ = writeln!(
            s,
            "leg {} joint twists: {} (generic {g})",
            i + 1,
            rank_text(r)
        );
    }
    if a.generic.constraint == 6 && a.locked.is_empty() {
        let _ = writeln!(
            s,
            "note: the constraint wrenches have rank 6 at every generic configuration: with every input free the platform cannot move (a structure, not a manipulator)"
        );
    }
    if a.singularities.is_empty() {
        let _ = writeln!(s, "no singularity");
    }
    for sing in &a.singularities {
        let _ = writeln!(s, "singularity ({:?}): {}", sing.kind, sing.detail());
    }
    s
}

/// A value printed with six decimals, without a "-0.000000" for round-off.
fn clean(x: f64) -> f64 {
    if x.abs() < 5e-7 { 0.0 } else { x }
}
