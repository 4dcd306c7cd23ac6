//! `kinsyn analyze`: a configuration placed by pose, input values and start, and its mobility,
//! Jacobians, ranks and singularities as a typed report (printed by the front ends).

use super::{Loaded, leg_warnings, load_with_body};
use crate::Error;
use kinsyn::manipulator::file::Units;
use kinsyn::manipulator::{
    Analysis, ContinuationFailure, Manipulator, ManipulatorError, PRINTED_STUDY_TOLERANCE,
    PositionError, PositionRequest, RowKind, Singularity,
};
use kinsyn::mechanism::SampleSettings;
use kinsyn::screw::{self, DEFAULT_RANK_TOLERANCE};
use kinsyn::spatial::study::StudyParameters;
use nalgebra::DMatrix;
use serde::Serialize;
use std::collections::BTreeMap;
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

/// `kinsyn analyze`: the manipulator of the file at `path` (with `placement`'s end-effector
/// and reference body), the configuration `placement` asks for analysed, and the leg warnings.
///
/// # Errors
/// [`Error::Input`] for a file that is not a description, a pose or inputs that do not read or do not assemble, or options out of range.
pub fn analyze(
    path: &Path,
    placement: &Placement<'_>,
    lock: Option<&str>,
    settings: &SampleSettings,
) -> Result<Loaded<Analyzed>, Error> {
    let m = load_with_body(path, placement.body, placement.relative_to, None)?;
    let analyzed = analyse_placed(&m, placement, lock, settings)?;
    let warnings = leg_warnings(&m);
    Ok(Loaded {
        manipulator: m,
        result: analyzed,
        warnings,
    })
}

/// A configuration placed as `kinsyn analyze` places it, and its analysis.
pub struct Analyzed {
    /// Mobility, Jacobians, ranks and singularities at the configuration.
    pub analysis: Analysis,
    /// How the configuration was reached.
    reached: Reached,
    /// The report's `study` entries.
    study: Vec<StudyReport>,
}

impl Analyzed {
    /// The report of `kinsyn analyze --json` for the manipulator `m` analysed, with the leg
    /// `warnings` listed in it.
    #[must_use]
    pub fn report(&self, m: &Manipulator, warnings: &[String]) -> AnalyzeReport {
        AnalyzeReport::new(
            m,
            &self.analysis,
            &self.reached,
            warnings,
            self.study.clone(),
        )
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
    let mut study = Vec::new();
    let (q, steps, continuous) = if !placement.study.is_empty() {
        let q = study_configuration(m, placement, &start, &mut study)?;
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
        study,
    })
}

/// `--study` (with `--nearest`): the configuration of the Study poses reached from `start`,
/// with the report's entries.
fn study_configuration(
    m: &Manipulator,
    placement: &Placement<'_>,
    start: &[f64],
    study: &mut Vec<StudyReport>,
) -> Result<Vec<f64>, Error> {
    let sets = placement
        .study
        .iter()
        .map(|t| Manipulator::parse_study(t).map_err(|e| Error::Input(format!("--study: {e}"))))
        .collect::<Result<Vec<_>, _>>()?;
    for (body, s) in m.bodies().iter().zip(&sets) {
        let residual = kinsyn::spatial::study::relative_quadric_residual(s);
        study.push(StudyReport {
            body: body.name.clone(),
            parameters: *s,
            relative_quadric_residual: residual,
            tolerance: PRINTED_STUDY_TOLERANCE,
            nearest: None,
        });
    }
    if let Some(rounding) = placement.nearest {
        nearest_study(m, start, &sets, rounding, study)
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

/// `--study … --nearest`: the assembly nearest to the Study poses, with a report entry per
/// body on how far it moved (the file's units) and how far the rounding explains; refused in
/// one line when a body moved further.
fn nearest_study(
    m: &Manipulator,
    start: &[f64],
    sets: &[kinsyn::spatial::study::StudyParameters],
    rounding: f64,
    entries: &mut [StudyReport],
) -> Result<Vec<f64>, Error> {
    if !(rounding.is_finite() && rounding > 0.0) {
        return Err(Error::Input(format!(
            "--rounding {rounding}: give a positive half unit of the last printed place, e.g. 0.005"
        )));
    }
    let units = m.units();
    let angle = units.angle;
    let angle_name = angle.symbol();
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
        moved.push(NearestReport {
            body: name.clone(),
            translation: c.translation,
            rotation: angle.from_radians(c.rotation),
            translation_bound: c.translation_bound,
            rotation_bound: angle.from_radians(c.rotation_bound),
            length_unit: length.clone(),
            angle_unit: angle_name,
            rounding,
        });
    }
    for (entry, change) in entries.iter_mut().zip(moved) {
        entry.nearest = Some(change);
    }
    Ok(nearest.q)
}

/// [`RelativeMotionReport`] at the configuration analysed, when `--relative-to` was given.
fn relative_motion(m: &Manipulator, a: &Analysis) -> Option<RelativeMotionReport> {
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
    Some(RelativeMotionReport {
        body: m.bodies()[body].name.clone(),
        relative_to: m.bodies()[base].name.clone(),
        dof,
        rotations,
        twists_at_point: twists,
    })
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

/// The labels of the inputs left free in an analysis.
fn free_labels(m: &Manipulator, a: &Analysis) -> Vec<String> {
    a.jacobians
        .free
        .iter()
        .map(|&i| m.actuators()[i].label())
        .collect()
}

/// The report of `kinsyn analyze --json` (and of Python's `Manipulator.analyze`): the
/// configuration analysed, how it was reached, and its mobility, Jacobians, ranks and
/// singularities (paper 000). Lengths are in the description's length unit, angles in radians
/// unless a field's name says otherwise.
///
/// Printed through [`crate::sorted_value`]: its keys, and those of every value in it, come in
/// alphabetical order, as they did when the report was built with `serde_json::json!`, not in
/// the order of these fields.
#[derive(Debug, Clone, Serialize)]
pub struct AnalyzeReport {
    /// The manipulator's name (the description's `name`).
    pub manipulator: String,
    /// The description's units: the name of its length unit and its angle unit (of inputs and
    /// poses as given and printed).
    pub units: Units,
    /// The inputs locked (held at their values) in the analysis, by label, `-` for none.
    pub locked: String,
    /// The point P of the end-effector at which the rows' wrench moments and the velocity `v_P`
    /// of `J_D [v_P; ω]` are taken, in the ground frame (length unit).
    pub point: [f64; 3],
    /// The end-effector frame's origin in the ground frame (length unit).
    pub platform_position: [f64; 3],
    /// The end-effector frame's orientation as a rotation vector (axis × angle, radians).
    pub platform_rotation_vector_rad: [f64; 3],
    /// Every joint's value at the configuration, in the mechanism's joint order: radians for
    /// revolute joints, length unit for prismatic ones, measured from the reference.
    pub joint_values: Vec<f64>,
    /// Each input's value by label, from the reference: prismatic inputs in the length unit,
    /// revolute ones in the description's angle unit.
    pub input_values: BTreeMap<String, f64>,
    /// The start the configuration was reached from: `the reference configuration` or
    /// `--from POSE`.
    pub reached_from: String,
    /// The continuation steps from the start (0 when nothing was asked, or by `--study`).
    pub continuation_steps: usize,
    /// Whether the configuration is the assembly continuous with the start (false when damped
    /// Newton steps reached it after the continuation path left the workspace).
    pub continuous_with_start: bool,
    /// Whether the start was given (`--from`) rather than the reference (not in the JSON).
    #[serde(skip)]
    pub start_given: bool,
    /// The mobility: the dimension of the joint rates that keep every loop closed (the locked
    /// inputs held), the platform's dof plus the legs' internal motions.
    pub mobility: usize,
    /// The rank decision of the (dimensionless) loop-closure Jacobian behind `mobility`.
    pub closure_rank: RankReport,
    /// The end-effector's local dof with the locked inputs held: six minus the rank of the
    /// constraint wrenches.
    pub platform_dof: usize,
    /// The labels of the inputs left free: the columns of `J_I`.
    pub inputs: Vec<String>,
    /// The rows of `J_D [v_P; ω] = J_I q̇` (paper 000, eq. 11): actuation wrenches, locked
    /// inputs' wrenches and constraint wrenches; none when `leg_wrench_jacobians` is false.
    pub rows: Vec<JacobianRow>,
    /// The rank of `J_D`, with its generic value (6 when the inputs fix the end-effector).
    pub jd_rank: RankReport,
    /// The rank of the constraint wrenches, with its generic value.
    pub constraint_rank: RankReport,
    /// Each leg's rank of its joint twists, with its generic value, in leg order.
    pub leg_ranks: Vec<RankReport>,
    /// The random assemblies that closed, over which the generic ranks were taken.
    pub generic_assemblies: usize,
    /// Of those, the assemblies at which some rank fell short of its generic value (near or on
    /// a singular set): reported, not used.
    pub generic_assemblies_below: usize,
    /// The singularities found at the configuration: their kind and what dropped, in words.
    pub singularities: Vec<Singularity>,
    /// The leg warnings of the description (docs/mechanism-format.md, "Leg checks").
    pub warnings: Vec<String>,
    /// The name of the moving body analysed as the end-effector.
    pub end_effector: String,
    /// Each moving body at the configuration, in the description's order.
    pub bodies: Vec<BodyReport>,
    /// Whether `J_D` and `J_I` are paper 000's leg-wrench Jacobians: every leg runs from the
    /// ground to the end-effector. When false, `rows` is empty and `jd_rank`,
    /// `constraint_rank` and `platform_dof` come from the loop-closure Jacobian.
    pub leg_wrench_jacobians: bool,
    /// The independent rates the free inputs keep with the end-effector held still.
    pub inputs_with_end_effector_held: HeldInputs,
    /// The stack of three-legged modules the manipulator is, when it has two or more (paper
    /// 002); `null` otherwise.
    pub series_parallel: Option<SeriesParallelReport>,
    /// The end-effector's motion relative to the body of `--relative-to`; absent without it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub relative_motion: Option<RelativeMotionReport>,
    /// One entry per `--study` pose, in series order from the ground; absent without
    /// `--study`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub study: Vec<StudyReport>,
}

/// A rank decision: the rank of a matrix from its singular values, with the gap around the
/// cut-off and the generic rank it is compared with.
#[derive(Debug, Clone, Serialize)]
pub struct RankReport {
    /// The rank: the singular values above `tolerance` times the scale (the largest singular
    /// value, unless the decision was judged against another).
    pub rank: usize,
    /// The rank at generic configurations, where one is compared (`null` otherwise).
    pub generic: Option<usize>,
    /// The relative tolerance of the decision (dimensionless).
    pub tolerance: f64,
    /// The singular values on either side of the cut-off, relative to the scale.
    pub gap: RankGap,
    /// Every singular value, largest first (in the matrix's own units; dimensionless for the
    /// loop closure).
    pub singular_values: Vec<f64>,
}

/// The gap of a rank decision at its cut, each side relative to the scale the rank was judged
/// against (dimensionless; both 0 for an empty matrix).
#[derive(Debug, Clone, Serialize)]
pub struct RankGap {
    /// The smallest singular value kept over the scale: how far the rank is from dropping.
    pub smallest_kept: f64,
    /// The largest singular value dropped over the scale (0 when none is): how far the rank is
    /// from rising.
    pub largest_dropped: f64,
}

/// One row of `J_D [v_P; ω] = J_I q̇`: a wrench on the end-effector and its input coefficient.
#[derive(Debug, Clone, Serialize)]
pub struct JacobianRow {
    /// What the row is: `input LABEL` (an actuation wrench), `locked LABEL` (the wrench of a
    /// locked input) or `constraint leg N`.
    pub row: String,
    /// The row of `J_D`: the wrench `(f; m_P)`, its moment taken about the point P (the
    /// moment in the length unit times the force's).
    pub jd: [f64; 6],
    /// The row's entry of `J_I`: `W·$_a`, the product of the row's wrench and its input's
    /// joint screw, for an actuation row; 0 otherwise.
    pub ji: f64,
}

/// One moving body at the configuration analysed.
#[derive(Debug, Clone, Serialize)]
pub struct BodyReport {
    /// The body's name in the description.
    pub name: String,
    /// Whether it is the body analysed as the end-effector.
    pub end_effector: bool,
    /// Its local dof with the locked inputs held (the dimension of its twist space).
    pub dof: usize,
    /// Its frame's origin in the ground frame (length unit).
    pub position: [f64; 3],
    /// Its frame's orientation as a rotation vector (radians).
    pub rotation_vector_rad: [f64; 3],
    /// Its reference point in the ground frame (length unit).
    pub point: [f64; 3],
}

/// The independent rates the free inputs can have with the end-effector held still: more
/// here than at generic configurations is an inverse singularity.
#[derive(Debug, Clone, Serialize)]
pub struct HeldInputs {
    /// At the configuration analysed.
    pub here: usize,
    /// At generic configurations.
    pub generic: usize,
}

/// The manipulator as a stack of three-legged modules (paper 002).
#[derive(Debug, Clone, Serialize)]
pub struct SeriesParallelReport {
    /// Each module, from the ground.
    pub modules: Vec<ModuleReport>,
    /// `J_S-PM` (eqs. 7–8), row by row: the end-effector twist `(ω; v)` of its origin per input
    /// rate; `null` where it is not defined (`jacobian_error` says why).
    pub jacobian: Option<Vec<Vec<f64>>>,
    /// The rank of `J_S-PM`; absent where it is not defined.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub jacobian_rank: Option<RankReport>,
    /// Why `J_S-PM` is not defined here; absent where it is.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub jacobian_error: Option<String>,
    /// The order of the stack's twist system (eqs. 9–10): the end-effector's dof.
    pub twist_system_order: RankReport,
    /// A basis of the stack's constraint wrenches `(f; m)`, reciprocal to every end-effector
    /// twist, moments about the ground origin (force dimensionless, moment in the length unit).
    pub constraint_wrenches_f_m_about_ground_origin: Vec<[f64; 6]>,
}

/// One three-legged module of a stack (paper 002).
#[derive(Debug, Clone, Serialize)]
pub struct ModuleReport {
    /// The module's forward Jacobian `A` (eqs. 2–3), row by row: its actuation and constraint
    /// wrenches.
    pub forward_jacobian: Vec<Vec<f64>>,
    /// The rank of `A`.
    pub forward_jacobian_rank: RankReport,
    /// The module's input twists `A⁻¹B` (6 × 3), row by row; `null` in a parallel singularity
    /// (`A` singular).
    pub input_twists: Option<Vec<Vec<f64>>>,
}

/// The analysed body's instantaneous motion relative to the body of `--relative-to`.
#[derive(Debug, Clone, Serialize)]
pub struct RelativeMotionReport {
    /// The name of the body analysed.
    pub body: String,
    /// The name of the body it is seen from.
    pub relative_to: String,
    /// Its relative dof.
    pub dof: usize,
    /// How many independent relative angular velocities it has (0: every relative twist is a
    /// translation).
    pub rotations: usize,
    /// A basis of its relative twists `(v; ω)`, `v` the velocity of the analysed body's point
    /// (length unit per unit time) and `ω` its angular velocity (radians per unit time), in
    /// the frame of the base body at its reference pose.
    pub twists_at_point: Vec<[f64; 6]>,
}

/// One `--study` pose: a moving body's Study parameters as given, and how nearly they lie on
/// the Study quadric.
#[derive(Debug, Clone, Serialize)]
pub struct StudyReport {
    /// The moving body they place.
    pub body: String,
    /// The Study parameters as given (`x0…x3`, `y0…y3`; the `y` in the length unit).
    pub parameters: StudyParameters,
    /// The relative Study quadric residual `|x·y| / (|x| |y|)` (dimensionless).
    pub relative_quadric_residual: f64,
    /// The residual accepted for parameters printed to two decimals (dimensionless).
    pub tolerance: f64,
    /// With `--nearest`: how far the nearest assembly moved the body; absent without it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nearest: Option<NearestReport>,
}

/// `--nearest`: how far the nearest assembly moved a body from its `--study` pose, and how far
/// rounding each parameter explains.
#[derive(Debug, Clone, Serialize)]
pub struct NearestReport {
    /// The moving body.
    pub body: String,
    /// How far its reference point moved (`length_unit`).
    pub translation: f64,
    /// How far it turned (`angle_unit`).
    pub rotation: f64,
    /// The translation rounding each parameter by `rounding` explains (`length_unit`).
    pub translation_bound: f64,
    /// The rotation rounding each parameter by `rounding` explains (`angle_unit`).
    pub rotation_bound: f64,
    /// The description's length unit.
    pub length_unit: String,
    /// The description's angle unit: `deg` or `rad`.
    pub angle_unit: &'static str,
    /// `--rounding`: half a unit of the last printed place of each parameter.
    pub rounding: f64,
}

impl RankReport {
    /// The report of the rank decision `r`, compared with the `generic` rank when given.
    fn new(r: &kinsyn::screw::Rank, generic: Option<usize>) -> Self {
        let (smallest_kept, largest_dropped) = r.gap();
        Self {
            rank: r.rank,
            generic,
            tolerance: r.tolerance,
            gap: RankGap {
                smallest_kept,
                largest_dropped,
            },
            singular_values: r.singular_values.clone(),
        }
    }
}

impl AnalyzeReport {
    /// The report of the analysis `a` of `m`, reached as `reached` says, with the leg
    /// `warnings` and the `--study` entries.
    fn new(
        m: &Manipulator,
        a: &Analysis,
        reached: &Reached,
        warnings: &[String],
        study: Vec<StudyReport>,
    ) -> Self {
        let frame = m.platform_frame(&a.q);
        let rv = kinsyn::mechanism::rotation_log(&frame.rotation);
        let p = a.jacobians.point;
        Self {
            manipulator: m.name().to_string(),
            units: m.units().clone(),
            locked: m.lock_text(&a.locked),
            point: [p.x, p.y, p.z],
            platform_position: [
                frame.translation.x,
                frame.translation.y,
                frame.translation.z,
            ],
            platform_rotation_vector_rad: [rv.x, rv.y, rv.z],
            joint_values: a.q.clone(),
            input_values: input_values(m, &a.q).into_iter().collect(),
            reached_from: reached.start.clone(),
            continuation_steps: reached.steps,
            continuous_with_start: reached.continuous,
            start_given: reached.start_given,
            mobility: a.mobility,
            closure_rank: RankReport::new(&a.closure_rank, None),
            platform_dof: a.platform_dof,
            inputs: free_labels(m, a),
            rows: a
                .jacobians
                .rows
                .iter()
                .map(|r| JacobianRow {
                    row: row_label(m, r.kind),
                    jd: r.wrench,
                    ji: r.input,
                })
                .collect(),
            jd_rank: RankReport::new(&a.jd_rank, Some(a.generic.jd)),
            constraint_rank: RankReport::new(&a.constraint_rank, Some(a.generic.constraint)),
            leg_ranks: a
                .leg_ranks
                .iter()
                .zip(&a.generic.legs)
                .map(|(r, &g)| RankReport::new(r, Some(g)))
                .collect(),
            generic_assemblies: a.generic.assemblies,
            generic_assemblies_below: a.generic.assemblies_below,
            singularities: a.singularities.clone(),
            warnings: warnings.to_vec(),
            end_effector: m.bodies()[m.end_effector()].name.clone(),
            bodies: bodies(m, a),
            leg_wrench_jacobians: a.leg_wrench_jacobians,
            inputs_with_end_effector_held: HeldInputs {
                here: a.inputs_with_end_effector_held,
                generic: a.generic.inputs_with_end_effector_held,
            },
            series_parallel: series_parallel(m, a),
            relative_motion: relative_motion(m, a),
            study,
        }
    }
}

/// The stack of three-legged modules the manipulator is, when it has two or more (paper 002):
/// `J_S-PM` (eqs. 7–8), its rank, the order of the twist system (eqs. 9–10) and each module's
/// forward Jacobian `A` (eqs. 2–3) with its rank and its input twists `A⁻¹B` (`None` in a
/// parallel singularity); `None` otherwise.
fn series_parallel(m: &Manipulator, a: &Analysis) -> Option<SeriesParallelReport> {
    let spm = kinsyn_papers::series::stack(m, &a.q).filter(|s| s.modules().len() > 1)?;
    let system = spm.twist_system(DEFAULT_RANK_TOLERANCE);
    let rows = |m: &DMatrix<f64>| -> Vec<Vec<f64>> {
        m.row_iter().map(|r| r.iter().copied().collect()).collect()
    };
    let modules = spm
        .modules()
        .iter()
        .map(|module| {
            let forward = DMatrix::from_column_slice(6, 6, module.forward_jacobian().as_slice());
            ModuleReport {
                forward_jacobian: rows(&forward),
                forward_jacobian_rank: RankReport::new(
                    &screw::rank(&forward, DEFAULT_RANK_TOLERANCE),
                    None,
                ),
                input_twists: module
                    .input_twists()
                    .ok()
                    .map(|t| rows(&DMatrix::from_column_slice(6, 3, t.as_slice()))),
            }
        })
        .collect();
    let (jacobian, jacobian_rank, jacobian_error) = match spm.jacobian() {
        Ok(j) => (
            Some(rows(&j)),
            Some(RankReport::new(
                &screw::rank(&j, DEFAULT_RANK_TOLERANCE),
                None,
            )),
            None,
        ),
        Err(e) => (None, None, Some(e.to_string())),
    };
    Some(SeriesParallelReport {
        modules,
        jacobian,
        jacobian_rank,
        jacobian_error,
        twist_system_order: RankReport::new(&system.order, None),
        constraint_wrenches_f_m_about_ground_origin: stack_wrenches(
            &spm,
            &system.constraint_wrenches,
        )
        .iter()
        .map(|w| w.to_vector().into())
        .collect(),
    })
}

/// Each moving body at the configuration analysed: its name, dof with the locked inputs held,
/// frame origin, rotation vector (radians) and reference point.
fn bodies(m: &Manipulator, a: &Analysis) -> Vec<BodyReport> {
    m.bodies()
        .iter()
        .enumerate()
        .map(|(k, b)| {
            let frame = m.body_frame(k, &a.q);
            let rv = kinsyn::mechanism::rotation_log(&frame.rotation);
            let p = m.body_point(k, &a.q);
            BodyReport {
                name: b.name.clone(),
                end_effector: k == m.end_effector(),
                dof: a.body_dof[k],
                position: [
                    frame.translation.x,
                    frame.translation.y,
                    frame.translation.z,
                ],
                rotation_vector_rad: [rv.x, rv.y, rv.z],
                point: [p.x, p.y, p.z],
            }
        })
        .collect()
}
