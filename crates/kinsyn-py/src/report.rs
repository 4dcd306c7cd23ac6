//! The reports of `kinsyn analyze --json`: the configuration, mobility, Jacobians, ranks and
//! singularities of a manipulator, field for field as the command line writes them.

use kinsyn::manipulator::{Analysis, Manipulator, RowKind};
use kinsyn::screw::{self, DEFAULT_RANK_TOLERANCE};
use nalgebra::DMatrix;

/// How the configuration analysed was reached.
pub struct Reached {
    /// "the reference configuration".
    pub start: String,
    /// Continuation steps from the start (0 when nothing was asked).
    pub steps: usize,
    /// Whether the configuration is the one continuous with the start.
    pub continuous: bool,
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

pub fn analysis_json(
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
        "series_parallel": series_json(m, a),
        // Beyond the command's report: the matrices themselves, row by row.
        "jd_matrix": matrix_rows(&a.jacobians.jd),
        "ji_matrix": matrix_rows(&a.jacobians.ji),
    })
}

/// A matrix as a list of its rows.
fn matrix_rows(m: &DMatrix<f64>) -> Vec<Vec<f64>> {
    m.row_iter().map(|r| r.iter().copied().collect()).collect()
}

/// The stack of three-legged modules the manipulator is, when it has two or more (paper 002):
/// `J_S-PM` (eqs. 7–8), its rank, the order of the twist system (eqs. 9–10) and each module's
/// forward Jacobian `A` (eqs. 2–3) with its rank and its input twists `A⁻¹B` (`null` in a parallel
/// singularity); `null` otherwise.
fn series_json(m: &Manipulator, a: &Analysis) -> serde_json::Value {
    let Some(spm) = m.series_stack(&a.q).filter(|s| s.modules().len() > 1) else {
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

/// The stack's constraint wrenches (columns `(f; m_{O_n})` of [`kinsyn::series::TwistSystem`])
/// with their moments taken about the ground origin: `m_O = m_{O_n} + O_n × f`.
fn stack_wrenches(
    spm: &kinsyn::series::SeriesParallel,
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
pub fn rank_json(r: &kinsyn::screw::Rank, generic: Option<usize>) -> serde_json::Value {
    let (kept, dropped) = r.gap();
    serde_json::json!({
        "rank": r.rank,
        "generic": generic,
        "tolerance": r.tolerance,
        "gap": {"smallest_kept": kept, "largest_dropped": dropped},
        "singular_values": r.singular_values,
    })
}
