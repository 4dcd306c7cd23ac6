//! `kinsyn analyze`: a configuration placed by pose, input values and start, and its mobility,
//! Jacobians, ranks and singularities as text or JSON.

use super::{clean, leg_warnings, load_with_body, warn};
use crate::{Error, json};
use kinsyn::manipulator::file::AngleUnit;
use kinsyn::manipulator::{
    Analysis, ContinuationFailure, Manipulator, ManipulatorError, PRINTED_STUDY_TOLERANCE,
    PositionError, PositionRequest, RowKind, rank_text,
};
use kinsyn::mechanism::SampleSettings;
use kinsyn::screw::{self, DEFAULT_RANK_TOLERANCE};
use nalgebra::DMatrix;
use std::fmt::Write as _;
use std::path::Path;

/// The platform pose of `--pose TEXT` (or another option named `option`) for `m`, assembled
/// from the reference configuration with the `locked` inputs held.
pub fn configuration_at_pose(
    m: &Manipulator,
    option: &str,
    text: &str,
    locked: &[usize],
) -> Result<Vec<f64>, Error> {
    let request = PositionRequest {
        platform: Some(
            m.parse_pose(text)
                .map_err(|e| Error::Input(format!("{option} {text:?}: {e}")))?,
        ),
        held: locked.to_vec(),
        ..PositionRequest::default()
    };
    m.solve_position(&m.reference(), &request)
        .map(|p| p.q)
        .map_err(|e| Error::Input(format!("{option} {text:?}: {}", position_error(&e))))
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
    /// `--study`: one set of Study parameters per moving body, in series order from the ground.
    pub study: &'a [String],
    /// `--nearest` with its `--rounding`: analyse the assembly nearest to the `--study` poses,
    /// refused when a body moves further than rounding each parameter by this explains.
    pub nearest: Option<f64>,
    /// `--relative-to`: a moving body from which the analysed body's motion is also reported.
    pub relative_to: Option<&'a str>,
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
///
/// # Errors
/// [`Error::Input`] for a file that is not a description, a pose or inputs that do not read or do not assemble, or options out of range.
pub fn analyze(
    path: &Path,
    placement: &Placement<'_>,
    lock: Option<&str>,
    settings: &SampleSettings,
    as_json: bool,
) -> Result<String, Error> {
    let m = load_with_body(path, placement.body, placement.relative_to, None)?;
    let analyzed = analyse_placed(&m, placement, lock, settings)?;
    let warnings = leg_warnings(&m);
    warn(path, &warnings);
    if as_json {
        return Ok(json(&analyzed.json(&m, &warnings)));
    }
    Ok(analyzed.study_lines.clone() + &analysis_text(&m, &analyzed.analysis, &analyzed.reached))
}

/// A configuration placed as `kinsyn analyze` places it, and its analysis.
pub struct Analyzed {
    /// Mobility, Jacobians, ranks and singularities at the configuration.
    pub analysis: Analysis,
    /// How the configuration was reached.
    reached: Reached,
    /// The text report's lines on `--study`.
    study_lines: String,
    /// The JSON report's `study` entries.
    study_json: Vec<serde_json::Value>,
}

impl Analyzed {
    /// The report of `kinsyn analyze --json` for the manipulator `m` analysed, with the leg
    /// `warnings` listed in it.
    #[must_use]
    pub fn json(&self, m: &Manipulator, warnings: &[String]) -> serde_json::Value {
        let mut v = analysis_json(m, &self.analysis, &self.reached, warnings);
        if !self.study_json.is_empty() {
            v["study"] = serde_json::Value::Array(self.study_json.clone());
        }
        v
    }
}

/// The configuration of `m` that `placement` asks for, with the inputs of `lock` (`--lock`,
/// labels) held, reached from the start, and its analysis sampled with `settings`.
///
/// # Errors
///
/// [`Error::Input`], naming the option: a malformed lock set, pose, input values or Study
/// parameters, a configuration that cannot be reached, or one that cannot be analysed.
pub fn analyse_placed(
    m: &Manipulator,
    placement: &Placement<'_>,
    lock: Option<&str>,
    settings: &SampleSettings,
) -> Result<Analyzed, Error> {
    let locked = match lock {
        Some(text) => m
            .parse_locks(text)
            .map_err(|e| Error::Input(format!("--lock {text:?}: {e}")))?,
        None => Vec::new(),
    };
    let (start, start_text) = match placement.from {
        Some(text) => (
            configuration_at_pose(m, "--from", text, &[])?,
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
            .map_err(|e| Error::Input(format!("--inputs {text:?}: {e}")))?;
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
                .map_err(|e| Error::Input(format!("--pose {text:?}: {e}")))?,
        );
    }
    let mut study_lines = String::new();
    let mut study_json = Vec::new();
    let (q, steps, continuous) = if !placement.study.is_empty() {
        let q = study_configuration(m, placement, &start, &mut study_lines, &mut study_json)?;
        (q, 0, true)
    } else if request.inputs.is_empty() && request.platform.is_none() {
        (start, 0, true)
    } else {
        let asked: Vec<String> = [("--inputs", placement.inputs), ("--pose", placement.pose)]
            .iter()
            .filter_map(|(o, t)| t.map(|t| format!("{o} {t:?}")))
            .collect();
        let p = m
            .solve_position(&start, &request)
            .map_err(|e| Error::Input(format!("{}: {}", asked.join(" "), position_error(&e))))?;
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
        .map_err(|e| Error::Input(e.to_string()))?;
    Ok(Analyzed {
        analysis: a,
        reached,
        study_lines,
        study_json,
    })
}

/// `--study` (with `--nearest`): the configuration of the Study poses reached from `start`,
/// with the report's lines and JSON entries.
fn study_configuration(
    m: &Manipulator,
    placement: &Placement<'_>,
    start: &[f64],
    study_lines: &mut String,
    study_json: &mut Vec<serde_json::Value>,
) -> Result<Vec<f64>, Error> {
    let sets = placement
        .study
        .iter()
        .map(|t| Manipulator::parse_study(t).map_err(|e| Error::Input(format!("--study: {e}"))))
        .collect::<Result<Vec<_>, _>>()?;
    for (body, s) in m.bodies().iter().zip(&sets) {
        let residual = kinsyn::spatial::study::relative_quadric_residual(s);
        let _ = writeln!(
            study_lines,
            "--study {:?}: relative Study quadric residual |x·y|/(|x| |y|) = {residual:.3e} (tolerance {:.0e}, values printed to two decimals)",
            body.name, PRINTED_STUDY_TOLERANCE
        );
        study_json.push(serde_json::json!({
            "body": body.name,
            "parameters": s,
            "relative_quadric_residual": residual,
            "tolerance": PRINTED_STUDY_TOLERANCE,
        }));
    }
    if let Some(rounding) = placement.nearest {
        nearest_study(m, start, &sets, rounding, study_lines, study_json)
    } else {
        let frames = m
            .frames_from_study(&sets, PRINTED_STUDY_TOLERANCE)
            .map_err(|e| Error::Input(format!("--study: {e}")))?;
        let q = m.solve_poses(start, &frames).map_err(|e| {
            Error::Input(format!(
                "--study: {e} (--nearest takes the nearest assembly of rounded values)"
            ))
        })?;
        Ok(q)
    }
}

/// `--study … --nearest`: the assembly nearest to the Study poses, with a line and a JSON
/// entry per body on how far it moved (the file's units) and how far the rounding explains;
/// refused in one line when a body moved further.
fn nearest_study(
    m: &Manipulator,
    start: &[f64],
    sets: &[kinsyn::spatial::study::StudyParameters],
    rounding: f64,
    lines: &mut String,
    entries: &mut [serde_json::Value],
) -> Result<Vec<f64>, Error> {
    if !(rounding.is_finite() && rounding > 0.0) {
        return Err(Error::Input(format!(
            "--rounding {rounding}: give a positive half unit of the last printed place, e.g. 0.005"
        )));
    }
    let units = m.units();
    let angle = units.angle;
    let angle_name = match angle {
        AngleUnit::Deg => "deg",
        AngleUnit::Rad => "rad",
    };
    let length = units.length.clone();
    let nearest = match m.nearest_study(start, sets, PRINTED_STUDY_TOLERANCE, rounding) {
        Ok(n) => n,
        Err(ManipulatorError::Position(PositionError::BeyondRounding {
            body,
            translation,
            rotation,
            translation_bound,
            rotation_bound,
            rounding,
        })) => {
            return Err(Error::Input(format!(
                "--study --nearest: the nearest assembly moves {body:?} by {translation:.4} {length} and {:.4} {angle_name}, more than rounding each parameter by {rounding} explains ({translation_bound:.4} {length}, {:.4} {angle_name}): no rounded configuration of this mechanism (--rounding to allow more)",
                angle.from_radians(rotation),
                angle.from_radians(rotation_bound),
            )));
        }
        Err(e) => return Err(Error::Input(format!("--study --nearest: {e}"))),
    };
    let mut moved = Vec::new();
    for c in &nearest.changes {
        let name = &m.bodies()[c.body].name;
        let _ = writeln!(
            lines,
            "--nearest {name:?}: moved {:.3e} {length} and {:.3e} {angle_name} from its --study pose (rounding each parameter by {rounding} explains up to {:.3e} {length} and {:.3e} {angle_name})",
            c.translation,
            angle.from_radians(c.rotation),
            c.translation_bound,
            angle.from_radians(c.rotation_bound),
        );
        moved.push(serde_json::json!({
            "body": name,
            "translation": c.translation,
            "rotation": angle.from_radians(c.rotation),
            "translation_bound": c.translation_bound,
            "rotation_bound": angle.from_radians(c.rotation_bound),
            "length_unit": length,
            "angle_unit": angle_name,
            "rounding": rounding,
        }));
    }
    for (entry, change) in entries.iter_mut().zip(moved) {
        entry["nearest"] = change;
    }
    Ok(nearest.q)
}

/// The analysed body's instantaneous motion relative to the body of `--relative-to`.
struct RelativeMotion {
    /// The name of the body it is seen from.
    base: String,
    /// Its relative degrees of freedom.
    dof: usize,
    /// How many independent relative angular velocities it has (0: every relative twist is a
    /// translation).
    rotations: usize,
    /// A basis of its relative twists `(v; ω)`, `v` the velocity of the analysed body's point,
    /// in the frame of the base body at its reference pose.
    twists: Vec<[f64; 6]>,
}

/// [`RelativeMotion`] at the configuration analysed, when `--relative-to` was given.
fn relative_motion(m: &Manipulator, a: &Analysis) -> Option<RelativeMotion> {
    let base = m.relative_body()?;
    let body = m.end_effector();
    let (twists, dof) = m.relative_twists(body, base, &a.q, &a.locked);
    // The rotation rank is decided on the dimensionless basis (orthonormal columns).
    let unitless = m.mechanism().unitless_twists(&twists);
    let w = unitless.rows(0, 3).into_owned();
    let rotations = if w.ncols() == 0 {
        0
    } else {
        w.singular_values()
            .iter()
            .filter(|&&s| s > kinsyn::screw::DEFAULT_RANK_TOLERANCE)
            .count()
    };
    let p = m.relative_point(body, base, &a.q);
    let twists = (0..twists.ncols())
        .map(|c| {
            let w = nalgebra::Vector3::new(twists[(0, c)], twists[(1, c)], twists[(2, c)]);
            let v = nalgebra::Vector3::new(twists[(3, c)], twists[(4, c)], twists[(5, c)]);
            let vp = v + w.cross(&p);
            [vp.x, vp.y, vp.z, w.x, w.y, w.z]
        })
        .collect();
    Some(RelativeMotion {
        base: m.bodies()[base].name.clone(),
        dof,
        rotations,
        twists,
    })
}

fn relative_json(m: &Manipulator, r: &RelativeMotion) -> serde_json::Value {
    serde_json::json!({
        "body": m.bodies()[m.end_effector()].name,
        "relative_to": r.base,
        "dof": r.dof,
        "rotations": r.rotations,
        "twists_at_point": r.twists,
    })
}

fn relative_text(m: &Manipulator, r: &RelativeMotion) -> String {
    let body = &m.bodies()[m.end_effector()].name;
    let what = match (r.dof, r.rotations) {
        (0, _) => "it does not move relative to it".to_string(),
        (_, 0) => format!(
            "every relative twist is a translation ({body:?} and {:?} have the same angular velocity)",
            r.base
        ),
        (_, 1) => "1 independent relative angular velocity".to_string(),
        (_, k) => format!("{k} independent relative angular velocities"),
    };
    let mut s = format!(
        "motion of {body:?} relative to {:?}: {} dof; {what}; twist basis (v of {body:?}'s point; ω), in the frame of {:?} at the reference:",
        r.base, r.dof, r.base
    );
    for t in &r.twists {
        let t: Vec<String> = t.iter().map(|x| format!("{:.6}", clean(*x))).collect();
        let _ = write!(s, " [{}]", t.join(", "));
    }
    s.push('\n');
    s
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
    let mut v = serde_json::json!({
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
        "generic_assemblies_below": a.generic.assemblies_below,
        "singularities": a.singularities,
        "warnings": warnings,
        "end_effector": m.bodies()[m.end_effector()].name,
        "bodies": bodies_json(m, a),
        "leg_wrench_jacobians": a.leg_wrench_jacobians,
        "inputs_with_end_effector_held": {
            "here": a.inputs_with_end_effector_held,
            "generic": a.generic.inputs_with_end_effector_held,
        },
        "series_parallel": series_json(m, a),
    });
    if let Some(r) = relative_motion(m, a) {
        v["relative_motion"] = relative_json(m, &r);
    }
    v
}

/// The stack of three-legged modules the manipulator is, when it has two or more (paper 002):
/// `J_S-PM` (eqs. 7–8), its rank, the order of the twist system (eqs. 9–10) and each module's
/// forward Jacobian `A` (eqs. 2–3) with its rank and its input twists `A⁻¹B` (`null` in a parallel
/// singularity); `null` otherwise.
fn series_json(m: &Manipulator, a: &Analysis) -> serde_json::Value {
    let Some(spm) = kinsyn_papers::series::stack(m, &a.q).filter(|s| s.modules().len() > 1) else {
        return serde_json::Value::Null;
    };
    let system = spm.twist_system(DEFAULT_RANK_TOLERANCE);
    let order = system.order.clone();
    let wrenches: Vec<[f64; 6]> = stack_wrenches(&spm, &system.constraint_wrenches)
        .iter()
        .map(|w| w.to_vector().into())
        .collect();
    let modules: Vec<serde_json::Value> = spm
        .modules()
        .iter()
        .map(|module| {
            let forward = DMatrix::from_column_slice(6, 6, module.forward_jacobian().as_slice());
            let rows = |m: &DMatrix<f64>| -> Vec<Vec<f64>> {
                m.row_iter().map(|r| r.iter().copied().collect()).collect()
            };
            let inputs = module.input_twists().ok().map(|t| {
                rows(&DMatrix::from_column_slice(6, 3, t.as_slice()))
            });
            serde_json::json!({
                "forward_jacobian": rows(&forward),
                "forward_jacobian_rank": rank_json(&screw::rank(&forward, DEFAULT_RANK_TOLERANCE), None),
                "input_twists": inputs,
            })
        })
        .collect();
    match spm.jacobian() {
        Ok(j) => serde_json::json!({
            "modules": modules,
            "jacobian": j.row_iter().map(|r| r.iter().copied().collect::<Vec<f64>>()).collect::<Vec<_>>(),
            "jacobian_rank": rank_json(&screw::rank(&j, DEFAULT_RANK_TOLERANCE), None),
            "twist_system_order": rank_json(&order, None),
            "constraint_wrenches_f_m_about_ground_origin": wrenches,
        }),
        Err(e) => serde_json::json!({
            "modules": modules,
            "jacobian": null,
            "jacobian_error": e.to_string(),
            "twist_system_order": rank_json(&order, None),
            "constraint_wrenches_f_m_about_ground_origin": wrenches,
        }),
    }
}

/// The stack's constraint wrenches (columns `(f; m_{O_n})` of [`kinsyn_papers::series::TwistSystem`])
/// with their moments taken about the ground origin: `m_O = m_{O_n} + O_n × f`.
fn stack_wrenches(
    spm: &kinsyn_papers::series::SeriesParallel,
    wrenches: &DMatrix<f64>,
) -> Vec<kinsyn::screw::Wrench> {
    let origin = spm
        .poses()
        .last()
        .map_or_else(nalgebra::Vector3::zeros, |p| p.translation.vector);
    wrenches
        .column_iter()
        .map(|c| {
            let f = nalgebra::Vector3::new(c[0], c[1], c[2]);
            let m = nalgebra::Vector3::new(c[3], c[4], c[5]) + origin.cross(&f);
            kinsyn::screw::Wrench { f, m }
        })
        .collect()
}

/// A wrench in words: a couple about a direction, a force along a line, or a wrench of some
/// pitch along a line (`length` the mechanism's characteristic length, for what counts as 0).
fn wrench_text(w: &kinsyn::screw::Wrench, length: f64) -> String {
    let ff = w.f.norm_squared();
    let size = (ff.sqrt() * length).max(w.m.norm());
    // Four decimals, round-off (below 5e-5 of the characteristic length) written as 0.
    let c = |x: f64| {
        if x.abs() < 5e-5 * length.max(1.0) {
            0.0
        } else {
            x
        }
    };
    let v = |x: nalgebra::Vector3<f64>| format!("[{:.4}, {:.4}, {:.4}]", c(x.x), c(x.y), c(x.z));
    if ff.sqrt() * length < 1e-9 * size {
        return format!("a couple about {}", v(w.m.normalize()));
    }
    let pitch = w.f.dot(&w.m) / ff;
    let point = w.f.cross(&w.m) / ff;
    let direction = w.f.normalize();
    if pitch.abs() < 1e-9 * length {
        format!("a force along {} through {}", v(direction), v(point))
    } else {
        format!(
            "a wrench of pitch {pitch:.4} along {} through {}",
            v(direction),
            v(point)
        )
    }
}

/// The paper 002 lines of the text report (see [`series_json`]); empty unless the
/// manipulator is a stack of two or more three-legged modules.
fn series_text(m: &Manipulator, a: &Analysis) -> String {
    let Some(spm) = kinsyn_papers::series::stack(m, &a.q).filter(|s| s.modules().len() > 1) else {
        return String::new();
    };
    let mut s = String::new();
    let system = spm.twist_system(DEFAULT_RANK_TOLERANCE);
    let _ = writeln!(
        s,
        "series-parallel stack of {} three-legged modules (paper 002): twist-system order {} (eqs. 9–10: {})",
        spm.modules().len(),
        system.order.rank,
        rank_text(&system.order)
    );
    match spm.jacobian() {
        Ok(j) => {
            let _ = writeln!(
                s,
                "  J_S-PM (eqs. 7–8, twist (ω; v) of the end-effector origin per input rate): {}",
                rank_text(&screw::rank(&j, DEFAULT_RANK_TOLERANCE))
            );
        }
        Err(e) => {
            let _ = writeln!(s, "  J_S-PM not defined here: {e}");
        }
    }
    if system.order.rank < 6 {
        let _ = writeln!(
            s,
            "  constraint wrench system of the stack (order {}, reciprocal to every end-effector twist; a basis, moments about the ground origin, {}):",
            6 - system.order.rank,
            m.units().length
        );
        for w in stack_wrenches(&spm, &system.constraint_wrenches) {
            let _ = writeln!(s, "    {}", wrench_text(&w, m.mechanism().scale()));
        }
    }
    for (i, module) in spm.modules().iter().enumerate() {
        let forward = DMatrix::from_column_slice(6, 6, module.forward_jacobian().as_slice());
        let _ = writeln!(
            s,
            "  module {} forward Jacobian A (eqs. 2–3, actuation and constraint wrenches): {}",
            i + 1,
            rank_text(&screw::rank(&forward, DEFAULT_RANK_TOLERANCE))
        );
    }
    s
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
    s += &series_text(m, a);
    if a.singularities.is_empty() {
        let _ = writeln!(s, "no singularity");
    }
    for sing in &a.singularities {
        let _ = writeln!(s, "singularity ({:?}): {}", sing.kind, sing.detail());
    }
    if let Some(r) = relative_motion(m, a) {
        s += &relative_text(m, &r);
    }
    s
}
