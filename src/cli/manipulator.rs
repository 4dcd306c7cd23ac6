//! `kinsyn build`, `kinsyn modes`, `kinsyn analyze`: manipulators from description files.

use super::{CliError, json};
use kinsyn::manipulator::build::{BuildSpec, build};
use kinsyn::manipulator::{Analysis, Manipulator, RowKind};
use kinsyn::mechanism::SampleSettings;
use nalgebra::Vector3;
use std::fmt::Write as _;
use std::path::Path;

/// Reads and builds a manipulator file; errors name the file and the field.
pub fn load(path: &Path) -> Result<Manipulator, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| std::io::Error::new(e.kind(), format!("{}: {e}", path.display())))?;
    Manipulator::from_json(&text).map_err(|e| CliError::Input(format!("{}: {e}", path.display())))
}

/// The leg warnings of `m` (docs/mechanism-format.md, "Leg checks").
fn leg_warnings(m: &Manipulator) -> Vec<String> {
    m.leg_warnings().iter().map(ToString::to_string).collect()
}

/// Prints each warning on stderr as one line `warning: FILE: …`. Called once the command has
/// succeeded, so that an error stays the only line on stderr.
fn warn(path: &Path, warnings: &[String]) {
    for w in warnings {
        eprintln!("warning: {}: {w}", path.display());
    }
}

/// `kinsyn build`: writes a description (to `output`, or returns it for stdout).
pub fn build_command(spec: &BuildSpec, output: Option<&Path>) -> Result<String, CliError> {
    let description = build(spec).map_err(CliError::Input)?;
    // Check that what is written can be read back and built.
    let m = Manipulator::new(&description).map_err(|e| CliError::Input(e.to_string()))?;
    // `build` refuses legs that are not generic; the file as read back must agree.
    if let Some(w) = m.leg_warnings().first() {
        return Err(CliError::Input(format!(
            "--chain '{}': {w}",
            spec.chain.trim()
        )));
    }
    let text = description.to_json();
    match output {
        Some(path) => {
            std::fs::write(path, &text)
                .map_err(|e| std::io::Error::new(e.kind(), format!("{}: {e}", path.display())))?;
            let mobility = m.mechanism().mobility(&m.reference(), &[]).dof;
            let (_, dof) = m.mechanism().twist_space(m.platform(), &m.reference(), &[]);
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

/// `kinsyn modes`.
pub fn modes(path: &Path, settings: &SampleSettings, as_json: bool) -> Result<String, CliError> {
    let m = load(path)?;
    let modes = m.modes(settings).map_err(CliError::Input)?;
    warn(path, &leg_warnings(&m));
    if as_json {
        return Ok(json(&modes));
    }
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{}: {} inputs ({}), {} lock subsets; finite motion sampled by loop closure ({} samples, seed {})",
        modes.manipulator,
        modes.actuators.len(),
        modes.actuators.join(" "),
        modes.modes.len(),
        settings.samples,
        settings.seed
    );
    let width = modes
        .modes
        .iter()
        .map(|m| m.lock_text.len())
        .max()
        .unwrap_or(1)
        .max(6);
    let _ = writeln!(s, "{:<width$}  dof  pattern", "locked");
    for mode in &modes.modes {
        let note = match (&mode.error, mode.group) {
            (Some(e), _) => format!("  ({e})"),
            (None, true) => "  group".into(),
            (None, false) => String::new(),
        };
        let _ = writeln!(
            s,
            "{:<width$}  {:>3}  {}{note}",
            mode.lock_text, mode.dof, mode.pattern
        );
    }
    let _ = writeln!(
        s,
        "\nmultioperation capacity: {} displacement subgroups reached, of {} of the 12 kinds ({}):",
        modes.groups.len(),
        modes.group_kinds.len(),
        if modes.group_kinds.is_empty() {
            "none".to_string()
        } else {
            modes.group_kinds.join(" ")
        }
    );
    for g in &modes.groups {
        let _ = writeln!(s, "  {:<8} lock {}", g.pattern, g.lock_sets.join(" | "));
    }
    if !modes.non_groups.is_empty() {
        let _ = writeln!(s, "non-group patterns:");
        for g in &modes.non_groups {
            let _ = writeln!(s, "  {:<8} lock {}", g.pattern, g.lock_sets.join(" | "));
        }
    }
    Ok(s)
}

/// Parses `x,y,z,rx,ry,rz`: the platform frame's position and rotation vector (angles in the
/// file's unit).
fn parse_pose(text: &str, m: &Manipulator) -> Result<(Vector3<f64>, Vector3<f64>), CliError> {
    let values: Result<Vec<f64>, _> = text.split(',').map(|v| v.trim().parse::<f64>()).collect();
    let values = values
        .ok()
        .filter(|v| v.len() == 6 && v.iter().all(|x| x.is_finite()))
        .ok_or_else(|| {
            CliError::Input(format!(
                "--pose '{text}': six numbers x,y,z,rx,ry,rz (platform frame position, then rotation vector in {})",
                match m.units().angle {
                    kinsyn::manipulator::file::AngleUnit::Deg => "degrees",
                    kinsyn::manipulator::file::AngleUnit::Rad => "radians",
                }
            ))
        })?;
    let a = |x: f64| m.units().angle.to_radians(x);
    Ok((
        Vector3::new(values[0], values[1], values[2]),
        Vector3::new(a(values[3]), a(values[4]), a(values[5])),
    ))
}

/// `kinsyn analyze`.
pub fn analyze(
    path: &Path,
    pose: Option<&str>,
    lock: Option<&str>,
    settings: &SampleSettings,
    as_json: bool,
) -> Result<String, CliError> {
    let m = load(path)?;
    let locked = match lock {
        Some(text) => m
            .parse_locks(text)
            .map_err(|e| CliError::Input(format!("--lock '{text}': {e}")))?,
        None => Vec::new(),
    };
    let q = match pose {
        Some(text) => {
            let (position, orientation) = parse_pose(text, &m)?;
            m.assemble_at(position, orientation, &locked)
                .map_err(|e| CliError::Input(format!("--pose '{text}': {e}")))?
        }
        None => m.reference(),
    };
    let a = m
        .analyse(&q, &locked, settings)
        .map_err(|e| CliError::Input(e.to_string()))?;
    let warnings = leg_warnings(&m);
    warn(path, &warnings);
    if as_json {
        return Ok(json(&analysis_json(&m, &a, &warnings)));
    }
    Ok(analysis_text(&m, &a))
}

fn row_label(m: &Manipulator, kind: RowKind) -> String {
    match kind {
        RowKind::Actuation { actuator } => format!("input {}", m.actuators()[actuator].label()),
        RowKind::Locked { actuator } => format!("locked {}", m.actuators()[actuator].label()),
        RowKind::Constraint { leg } => format!("constraint leg {}", leg + 1),
    }
}

fn analysis_json(m: &Manipulator, a: &Analysis, warnings: &[String]) -> serde_json::Value {
    let frame = m.platform_frame(&a.q);
    let rv = kinsyn::mechanism::rotation_log(&frame.0);
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
        "platform_position": [frame.1.x, frame.1.y, frame.1.z],
        "platform_rotation_vector_rad": [rv.x, rv.y, rv.z],
        "joint_values": a.q,
        "mobility": a.mobility,
        "platform_dof": a.platform_dof,
        "wrench_dof": a.wrench_dof,
        "inputs": a.jacobians.free.iter().map(|&i| m.actuators()[i].label()).collect::<Vec<_>>(),
        "rows": rows,
        "jd_rank": {"rank": a.jd_rank.rank, "generic": a.generic.0, "singular_values": a.jd_rank.singular_values},
        "constraint_rank": {"rank": a.constraint_rank.rank, "generic": a.generic.1, "singular_values": a.constraint_rank.singular_values},
        "singularities": a.singularities,
        "warnings": warnings,
    })
}

fn analysis_text(m: &Manipulator, a: &Analysis) -> String {
    let mut s = String::new();
    let frame = m.platform_frame(&a.q);
    let rv = kinsyn::mechanism::rotation_log(&frame.0);
    let p = a.jacobians.point;
    let _ = writeln!(
        s,
        "{}: P = [{:.6}, {:.6}, {:.6}] {}; platform rotation vector [{:.6}, {:.6}, {:.6}] rad; locked: {}",
        m.name(),
        clean(p.x),
        clean(p.y),
        clean(p.z),
        m.units().length,
        clean(rv.x),
        clean(rv.y),
        clean(rv.z),
        m.lock_text(&a.locked)
    );
    let _ = writeln!(
        s,
        "mobility {} (loop closure), platform dof {} (twist space) = {} (6 − rank of the constraint wrenches)",
        a.mobility, a.platform_dof, a.wrench_dof
    );
    let inputs: Vec<String> = a
        .jacobians
        .free
        .iter()
        .map(|&i| m.actuators()[i].label())
        .collect();
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
    let sv = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:.4e}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let _ = writeln!(
        s,
        "rank J_D {} (nearby {}), singular values {}",
        a.jd_rank.rank,
        a.generic.0,
        sv(&a.jd_rank.singular_values)
    );
    let _ = writeln!(
        s,
        "rank of the constraint rows {} (nearby {}), singular values {}",
        a.constraint_rank.rank,
        a.generic.1,
        sv(&a.constraint_rank.singular_values)
    );
    if a.singularities.is_empty() {
        let _ = writeln!(s, "no singularity");
    }
    for sing in &a.singularities {
        let _ = writeln!(s, "singularity ({:?}): {}", sing.kind, sing.detail);
    }
    s
}

/// A value printed with six decimals, without a "-0.000000" for round-off.
fn clean(x: f64) -> f64 {
    if x.abs() < 5e-7 { 0.0 } else { x }
}
