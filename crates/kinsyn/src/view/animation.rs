//! The configurations a view animates, all computed by kinsyn before the page is written:
//! - an **input sweep**: one input moved from its start value to either side with the others
//!   held, each configuration reached by continuation from the last
//!   ([`Manipulator::solve_position`]);
//! - a **mode walk**: the finite motion left by a set of locked inputs, followed from the start
//!   along the direction of the joint rates that move the end-effector most, each step closed
//!   by Newton's method with the locks held ([`crate::mechanism::Mechanism::assemble`]).
//!
//! Either side stops early, and says why, where the continuation fails: the edge of the
//! workspace, a singularity, or (for a walk) a direction that no longer continues smoothly.

use crate::manipulator::{Manipulator, PositionRequest};
use crate::mechanism::Mechanism;
use nalgebra::{DMatrix, DVector};
use serde::Serialize;

/// The most steps to either side of a sweep or a walk (the page holds every configuration).
pub const MAX_STEPS: usize = 200;

/// A walk's step: the dimensionless joint rates (radians, prismatic values over the
/// characteristic length) advance by this length per step.
pub const WALK_STEP: f64 = 0.03;

/// A walk stops where the new rate space keeps less than this fraction of the last direction:
/// the motion turns sharply (a singularity or a branch point).
const SMOOTH_CONTINUATION: f64 = 0.5;

/// One side of a sweep or walk that stopped before its last step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Stop {
    /// `-1` (decreasing) or `+1`.
    pub side: i8,
    /// The steps taken on that side.
    pub steps: usize,
    /// Why it stopped.
    pub reason: String,
}

impl Stop {
    /// Side `side` stopped after `steps` steps, for `reason`.
    fn new(side: i8, steps: usize, reason: &dyn std::fmt::Display) -> Self {
        Self {
            side,
            steps,
            reason: reason.to_string(),
        }
    }
}

/// The configurations of both sides of a sweep or walk in one list, increasing: the first
/// side's reversed, the start, the second side's; and the start's index.
fn joined(sides: &[Vec<Vec<f64>>], start: &[f64]) -> (Vec<Vec<f64>>, usize) {
    let mut all: Vec<Vec<f64>> = sides[0].iter().rev().cloned().collect();
    let index = all.len();
    all.push(start.to_vec());
    all.extend(sides[1].iter().cloned());
    (all, index)
}

/// An input swept with the others held.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputSweep {
    /// The input's label (`R1.1`).
    pub input: String,
    /// The input's values, one per configuration, in the description's unit (degrees or
    /// radians for a revolute, the length unit for a slider): `unit`.
    pub values: Vec<f64>,
    /// The unit of `values`.
    pub unit: String,
    /// The configurations: every joint value (radians for revolutes, the length unit for
    /// sliders), increasing input.
    pub joint_values: Vec<Vec<f64>>,
    /// The index of the start configuration in `joint_values`.
    pub start: usize,
    /// The sides that stopped early.
    pub stops: Vec<Stop>,
}

/// The input `actuator` of `m` moved from its value at the assembled configuration `start` by
/// `span` (radians or length) to either side in `steps` equal steps, the other inputs held.
#[must_use]
pub fn input_sweep(
    m: &Manipulator,
    start: &[f64],
    actuator: usize,
    span: f64,
    steps: usize,
) -> InputSweep {
    let steps = steps.clamp(1, MAX_STEPS);
    let joint = m.actuators()[actuator].joint;
    let held: Vec<(usize, f64)> = m
        .actuators()
        .iter()
        .enumerate()
        .filter(|&(a, _)| a != actuator)
        .map(|(a, act)| (a, start[act.joint]))
        .collect();
    let mut sides: Vec<Vec<Vec<f64>>> = Vec::new();
    let mut stops = Vec::new();
    for side in [-1i8, 1] {
        let mut q = start.to_vec();
        let mut reached = Vec::new();
        for k in 1..=steps {
            let value = start[joint] + f64::from(side) * span * k as f64 / steps as f64;
            let mut inputs = held.clone();
            inputs.push((actuator, value));
            let request = PositionRequest {
                inputs,
                ..PositionRequest::default()
            };
            match m.solve_position(&q, &request) {
                Ok(p) if p.continuous => {
                    q = p.q;
                    reached.push(q.clone());
                }
                Ok(_) => {
                    stops.push(Stop::new(
                        side,
                        k - 1,
                        &"the continuation jumped to another assembly",
                    ));
                    break;
                }
                Err(e) => {
                    stops.push(Stop::new(side, k - 1, &e));
                    break;
                }
            }
        }
        sides.push(reached);
    }
    let (joint_values, start_index) = joined(&sides, start);
    let a = &m.actuators()[actuator];
    let (unit, values) = match a.kind {
        crate::notation::Primitive::R => {
            let angle = m.units().angle;
            (
                angle.symbol().to_string(),
                joint_values
                    .iter()
                    .map(|q| angle.from_radians(q[joint]))
                    .collect(),
            )
        }
        crate::notation::Primitive::P => (
            m.units().length.clone(),
            joint_values.iter().map(|q| q[joint]).collect(),
        ),
    };
    InputSweep {
        input: a.label(),
        values,
        unit,
        joint_values,
        start: start_index,
        stops,
    }
}

/// A mode's finite motion followed from a start.
#[derive(Debug, Clone, PartialEq)]
pub struct Walk {
    /// The configurations along it (every joint value), the start at index `start`.
    pub joint_values: Vec<Vec<f64>>,
    /// The index of the start.
    pub start: usize,
    /// The sides that stopped early.
    pub stops: Vec<Stop>,
}

/// The motion of `m` from the assembled configuration `start` with the inputs `locked` held,
/// `steps` steps of [`WALK_STEP`] to either side along the joint rates that move the
/// end-effector most ([`walk`] of its mechanism and platform).
#[must_use]
pub fn mode_walk(m: &Manipulator, start: &[f64], locked: &[usize], steps: usize) -> Walk {
    walk(
        m.mechanism(),
        m.platform(),
        start,
        &m.lock_mask(locked),
        steps,
        WALK_STEP,
    )
}

/// The motion of `mech` from the assembled configuration `start` with the joints in `mask`
/// held, `steps` steps of length `step` (dimensionless joint rates) to either side along the
/// joint rates that move the body `end` most (the leading right singular vector of its
/// dimensionless twists over the compatible rates), each step closed by Newton's method; one
/// configuration when the locks leave nothing to move. Without loops (a serial chain) every
/// rate of the free joints is compatible, and the walk is a straight line in joint space.
#[must_use]
pub fn walk(
    mech: &Mechanism,
    end: usize,
    start: &[f64],
    mask: &[bool],
    steps: usize,
    step: f64,
) -> Walk {
    let steps = steps.clamp(1, MAX_STEPS);
    let Some(direction) = leading_rates(mech, end, start, mask, None) else {
        return Walk {
            joint_values: vec![start.to_vec()],
            start: 0,
            stops: Vec::new(),
        };
    };
    let mut sides = Vec::new();
    let mut stops = Vec::new();
    for side in [-1i8, 1] {
        let mut q = start.to_vec();
        let mut d = &direction * f64::from(side);
        let mut reached = Vec::new();
        for k in 1..=steps {
            let trial: Vec<f64> = q
                .iter()
                .enumerate()
                .map(|(j, v)| v + step * d[j] * mech.unit(j))
                .collect();
            let next = match mech.assemble(&trial, mask, None) {
                Ok(next) => next,
                Err(e) => {
                    stops.push(Stop::new(side, k - 1, &e));
                    break;
                }
            };
            let Some(turned) = leading_rates(mech, end, &next, mask, Some(&d)) else {
                stops.push(Stop::new(
                    side,
                    k - 1,
                    &"the motion turns sharply here (a singularity or a branch)",
                ));
                break;
            };
            d = turned;
            q = next;
            reached.push(q.clone());
        }
        sides.push(reached);
    }
    let (joint_values, start_index) = joined(&sides, start);
    Walk {
        joint_values,
        start: start_index,
        stops,
    }
}

/// A unit vector of dimensionless joint rates (all joints, zero on the locked ones) compatible
/// with the loops at `q`: without `previous`, the one that moves body `end` most; with
/// it, its projection on the compatible rates, `None` when that keeps less than
/// [`SMOOTH_CONTINUATION`] of it. `None` also when nothing can move.
fn leading_rates(
    mech: &Mechanism,
    end: usize,
    q: &[f64],
    mask: &[bool],
    previous: Option<&DVector<f64>>,
) -> Option<DVector<f64>> {
    let n = mech.joints().len();
    let free: Vec<usize> = (0..n).filter(|&j| !mask[j]).collect();
    let mobility = mech.mobility(q, mask);
    if mobility.dof == 0 {
        return None;
    }
    // The basis over every joint, dimensionless (prismatic rates over the length scale).
    let basis = DMatrix::from_fn(n, mobility.dof, |j, c| {
        free.iter()
            .position(|&f| f == j)
            .map_or(0.0, |k| mobility.rates[(k, c)] / mech.unit(j))
    });
    let orthonormal = basis.qr().q();
    let chosen = if let Some(d) = previous {
        let projected = &orthonormal * (orthonormal.transpose() * d);
        if projected.norm() < SMOOTH_CONTINUATION * d.norm() {
            return None;
        }
        projected
    } else {
        let screws = mech.joint_screws(q);
        let physical = DMatrix::from_fn(n, mobility.dof, |j, c| orthonormal[(j, c)] * mech.unit(j));
        let twists = mech.unitless_twists(&(mech.body_jacobian(end, &screws) * physical));
        let svd = twists.svd(false, true);
        let v_t = svd.v_t?;
        let top = svd
            .singular_values
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map_or(0, |(i, _)| i);
        &orthonormal * v_t.row(top).transpose()
    };
    let norm = chosen.norm();
    (norm > 0.0).then(|| chosen / norm)
}
