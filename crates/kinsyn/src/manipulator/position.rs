//! Position analysis: the configuration of a manipulator from what an analyst gives, input
//! values (forward kinematics), platform coordinates (inverse kinematics, with the parasitic
//! coordinates of a low-dof platform solved), or both.
//!
//! A manipulator generally has several assemblies for the same values. The one returned is the
//! assembly **continuous with the start configuration**: the given values are approached from
//! their values at the start along a straight path, and the loops are closed at each step by
//! [`crate::mechanism::Mechanism::assemble_to`] from the previous step's configuration. A step
//! in which a joint moves by more than [`LARGEST_JOINT_STEP`] is taken again in halves, so the
//! path does not jump between assemblies, and the result keeps the start's assembly mode;
//! another start (e.g. `analyze --from POSE`) selects another assembly. When the path cannot be
//! followed (it leaves the workspace or meets a singularity), a configuration that damped Newton
//! steps reach straight from the start is returned and flagged as not continuous with it
//! ([`Position::continuous`]).

use super::{ContinuationFailure, Manipulator, ManipulatorError, PositionError, RequestError};
use crate::chain::Displacement;
use crate::mechanism::{Coordinate, Goal, MechanismError, compose, exp, inverse, log};
use crate::screw::Twist;
use nalgebra::{Rotation3, Vector3};

/// What the platform and the inputs are asked to be.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PositionRequest {
    /// Input values (actuator index, joint value: radians or length, from the reference).
    pub inputs: Vec<(usize, f64)>,
    /// Where the platform frame is asked to be, if anywhere.
    pub platform: Option<PlatformGoal>,
    /// Inputs held at their values at the start (actuator indices).
    pub held: Vec<usize>,
}

/// Where the platform frame is asked to be.
#[derive(Debug, Clone, PartialEq)]
pub enum PlatformGoal {
    /// The whole pose: (orientation, origin) in the ground frame.
    Pose(Displacement),
    /// Some coordinates (radians for angles); the others, the parasitic motion of a low-dof
    /// platform, are solved.
    Coordinates(Vec<(Coordinate, f64)>),
}

impl PlatformGoal {
    /// The goal for these coordinates: the whole pose when all six are given (each once).
    #[must_use]
    pub fn from_coordinates(mut values: Vec<(Coordinate, f64)>) -> Self {
        if values.len() != 6 {
            return PlatformGoal::Coordinates(values);
        }
        values.sort_by_key(|(c, _)| c.index());
        let v: Vec<f64> = values.iter().map(|&(_, x)| x).collect();
        PlatformGoal::Pose(crate::spatial::displacement(
            Rotation3::from_scaled_axis(Vector3::new(v[3], v[4], v[5])),
            Vector3::new(v[0], v[1], v[2]),
        ))
    }
}

/// A configuration reached by [`Manipulator::solve_position`].
#[derive(Debug, Clone, PartialEq)]
pub struct Position {
    /// The joint values.
    pub q: Vec<f64>,
    /// Continuation steps taken from the start.
    pub steps: usize,
    /// Whether the configuration was reached by continuation from the start (the start's
    /// assembly mode). When the path of the values from the start cannot be followed (it
    /// leaves the workspace or meets a singularity) but damped Newton steps straight from the
    /// start reach a configuration, that one is returned with `continuous` false: it may be
    /// another assembly mode.
    pub continuous: bool,
}

/// The most a joint may move in one continuation step (radians, or lengths over the
/// mechanism's characteristic length): small enough that a step stays on the branch it starts
/// from, since two assemblies for nearby values differ by finite joint motions.
pub(super) const LARGEST_JOINT_STEP: f64 = 0.5;

/// The most continuation steps tried (kept or halved) before the path is given up: values far
/// from the start (a slider extended a thousand lengths) would otherwise take thousands.
pub const CONTINUATION_TRIES: usize = 400;

/// The smallest continuation step (as a fraction of the path) before the path is given up.
const SMALLEST_STEP: f64 = 1.0 / 4096.0;

impl Manipulator {
    /// The configuration that meets `request`, continuous with `start` (module documentation).
    ///
    /// # Example
    /// Inverse kinematics of the 6-UPS: the platform raised by 0.1 m without turning. Leg 1
    /// runs from A = (1, 0, 0) on the base to B = (0.469846, 0.171010, 0) in the platform
    /// frame (`mechanisms/6-ups.json`), so its slider `P1.3` lengthens by |p′ + B − A| −
    /// |p + B − A| with p = (0, 0, 1) and p′ = (0, 0, 1.1).
    ///
    /// ```
    /// use kinsyn::manipulator::{Manipulator, PlatformGoal, PositionRequest};
    /// use nalgebra::{Rotation3, Vector3};
    ///
    /// # std::env::set_current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).unwrap();
    /// let m = Manipulator::from_json(&std::fs::read_to_string("mechanisms/6-ups.json")?)?;
    /// let raised = kinsyn::spatial::displacement(Rotation3::identity(), Vector3::new(0.0, 0.0, 1.1));
    /// let request = PositionRequest {
    ///     platform: Some(PlatformGoal::Pose(raised)),
    ///     ..PositionRequest::default()
    /// };
    /// let reached = m.solve_position(&m.reference(), &request)?;
    /// assert!(reached.continuous);
    ///
    /// let a = Vector3::new(1.0, 0.0, 0.0);
    /// let b = Vector3::new(0.469846310393, 0.171010071663, 0.0);
    /// let length = |z: f64| (Vector3::new(0.0, 0.0, z) + b - a).norm();
    /// let slider = m.actuators()[m.actuator_named("P1.3")?].joint;
    /// assert!((reached.q[slider] - (length(1.1) - length(1.0))).abs() < 1e-9);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`ManipulatorError::Position`] when the continuation cannot go on: the values asked for lie
    /// beyond the workspace, or a singularity lies on the way (the message gives how far it
    /// got and the residual), or when the request leaves the platform free to move (fewer
    /// values than degrees of freedom).
    pub fn solve_position(
        &self,
        start: &[f64],
        request: &PositionRequest,
    ) -> Result<Position, ManipulatorError> {
        let m = &self.mechanism;
        let mut mask = self.lock_mask(&request.held);
        for &(a, _) in &request.inputs {
            mask[self.actuators[a].joint] = true;
        }
        let start_frame = self.platform_frame(start);
        let at = |t: f64| self.path_point(start, &start_frame, request, t);
        let with_inputs = |t: f64, q: &[f64]| {
            let (values, goal) = at(t);
            let mut trial = q.to_vec();
            for (j, locked) in mask.iter().enumerate() {
                if *locked {
                    trial[j] = values[j];
                }
            }
            (trial, goal)
        };
        let (q, steps) = match self
            .continue_along(start, with_inputs, |q, goal| m.assemble_to(q, &mask, goal))
        {
            Ok(reached) => reached,
            Err((_, failure)) => {
                // The path cannot be followed: damped Newton steps straight from the start.
                let (direct, goal) = with_inputs(1.0, start);
                if let Ok(q) = m.assemble_to(&direct, &mask, goal.as_ref()) {
                    self.determined(&q, &mask, goal.as_ref())?;
                    return Ok(Position {
                        q,
                        steps: 0,
                        continuous: false,
                    });
                }
                return Err(PositionError::NotReached(failure).into());
            }
        };
        let (_, goal) = at(1.0);
        self.determined(&q, &mask, goal.as_ref())?;
        Ok(Position {
            q,
            steps,
            continuous: true,
        })
    }

    /// Follows a path of goals from `start` (`point(t, q)`: the joint values to start the
    /// loop closure from and the goal at fraction `t` of the path, `q` the configuration
    /// reached so far; `solve(q, goal)`: the configuration that closes the loops there, such as
    /// [`crate::mechanism::Mechanism::assemble_to`] or
    /// [`crate::mechanism::Mechanism::assemble_nearest`]) by continuation: steps
    /// that close the loops are kept and doubled, and a
    /// step that fails, or moves a joint by more than [`LARGEST_JOINT_STEP`] (a jump to another
    /// assembly), is taken again in halves. The configuration at `t = 1` with the steps kept,
    /// or the furthest configuration reached and why the path was given up.
    pub(super) fn continue_along(
        &self,
        start: &[f64],
        point: impl Fn(f64, &[f64]) -> (Vec<f64>, Option<Goal>),
        solve: impl Fn(&[f64], Option<&Goal>) -> Result<Vec<f64>, MechanismError>,
    ) -> Result<(Vec<f64>, usize), (Vec<f64>, ContinuationFailure)> {
        let m = &self.mechanism;
        let mut q = start.to_vec();
        let (mut t, mut dt, mut steps) = (0.0_f64, 1.0_f64, 0);
        for tries in 1.. {
            if t >= 1.0 {
                break;
            }
            let next = (t + dt).min(1.0);
            let (trial, goal) = point(next, &q);
            let solved = match solve(&trial, goal.as_ref()) {
                Err(e) => Err(e.to_string()),
                Ok(solved) => {
                    let change = (0..q.len())
                        .map(|j| (solved[j] - q[j]).abs() / m.unit(j))
                        .fold(0.0, f64::max);
                    if change > LARGEST_JOINT_STEP {
                        Err(format!(
                            "a joint moves by {change:.3} (dimensionless) within {dt:.1e} of the path, a jump between assemblies"
                        ))
                    } else {
                        Ok(solved)
                    }
                }
            };
            match solved {
                Ok(solved) => {
                    q = solved;
                    t = next;
                    steps += 1;
                    dt = (dt * 2.0).min(1.0);
                }
                Err(_) if tries >= CONTINUATION_TRIES => {
                    return Err((q, ContinuationFailure::TooManySteps { done: t }));
                }
                Err(e) => {
                    dt /= 2.0;
                    if dt < SMALLEST_STEP {
                        return Err((q, ContinuationFailure::Stopped { done: t, why: e }));
                    }
                }
            }
        }
        Ok((q, steps))
    }

    /// The point at fraction `t` (0 at `start`, 1 at the values asked for) of the straight path
    /// of the continuation: the joint values with each input moved linearly from its start
    /// value, and the platform's goal, its frame moved along the screw from the start pose to
    /// the pose asked for (or its coordinates moved linearly).
    fn path_point(
        &self,
        start: &[f64],
        start_frame: &Displacement,
        request: &PositionRequest,
        t: f64,
    ) -> (Vec<f64>, Option<Goal>) {
        let mut q0 = start.to_vec();
        for &(a, value) in &request.inputs {
            let j = self.actuators[a].joint;
            q0[j] = start[j] + t * (value - start[j]);
        }
        let goal = match &request.platform {
            None => None,
            Some(PlatformGoal::Pose(pose)) => {
                // The frame moves along the screw from its start pose to the goal.
                let screw = log(&compose(pose, &inverse(start_frame))).to_vector() * t;
                let frame = compose(&exp(&Twist::from_vector(&screw)), start_frame);
                Some(Goal::Pose {
                    body: self.platform,
                    displacement: compose(&frame, &inverse(&self.frame)),
                })
            }
            Some(PlatformGoal::Coordinates(values)) => Some(Goal::Coordinates {
                body: self.platform,
                frame: self.frame,
                values: values
                    .iter()
                    .map(|&(c, v)| {
                        let from = c.of(start_frame);
                        (c, from + t * (v - from))
                    })
                    .collect(),
            }),
        };
        (q0, goal)
    }

    /// Checks that the locks and the goal leave the platform no freedom at `q`.
    fn determined(
        &self,
        q: &[f64],
        mask: &[bool],
        goal: Option<&Goal>,
    ) -> Result<(), ManipulatorError> {
        if matches!(goal, Some(Goal::Pose { body, .. }) if *body == self.platform) {
            // The whole pose of the platform is asked for: nothing is left to it.
            return Ok(());
        }
        let undetermined = self.mechanism.freedom_left(self.platform, q, mask, goal);
        if undetermined > 0 {
            return Err(PositionError::Undetermined(undetermined).into());
        }
        Ok(())
    }
}

impl Manipulator {
    /// Parses input values `P1.3=1.05,R2.1=10`: joint values from the reference configuration,
    /// lengths in the file's length unit, angles in its angle unit (returned in radians).
    ///
    /// # Errors
    /// An item without `=`, a label that names no input, an input given twice, or a value that
    /// is not a finite number.
    pub fn parse_inputs(&self, text: &str) -> Result<Vec<(usize, f64)>, RequestError> {
        let mut out: Vec<(usize, f64)> = Vec::new();
        for item in text.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let Some((label, value)) = item.split_once('=') else {
                return Err(RequestError::NotLabelValue {
                    item: item.to_string(),
                    example: self
                        .actuators
                        .first()
                        .map_or_else(|| "P1.3".to_string(), super::Actuator::label),
                });
            };
            let a = self.actuator_named(label.trim())?;
            let value = finite_number(value)?;
            if out.iter().any(|&(b, _)| b == a) {
                return Err(RequestError::InputTwice(self.actuators[a].label()));
            }
            let value = match self.mechanism.joints()[self.actuators[a].joint].kind {
                crate::notation::Primitive::R => self.units.angle.to_radians(value),
                crate::notation::Primitive::P => value,
            };
            out.push((a, value));
        }
        if out.is_empty() {
            return Err(RequestError::NoInput);
        }
        Ok(out)
    }

    /// Parses a platform pose: six numbers `x,y,z,rx,ry,rz` (the platform frame's origin and
    /// rotation vector, angles in the file's unit), or some of them by name, `z=1.1,rx=5`,
    /// leaving the others to be solved.
    ///
    /// # Errors
    /// Not six numbers and not `name=value` items, an unknown or repeated name, or a value that
    /// is not a finite number.
    pub fn parse_pose(&self, text: &str) -> Result<PlatformGoal, RequestError> {
        let items: Vec<&str> = text.split(',').map(str::trim).collect();
        let angle = |c: Coordinate, v: f64| {
            if c.is_angle() {
                self.units.angle.to_radians(v)
            } else {
                v
            }
        };
        if !items.iter().any(|i| i.contains('=')) {
            let values = items
                .iter()
                .map(|v| finite_number(v))
                .collect::<Result<Vec<f64>, RequestError>>()?;
            if values.len() != 6 {
                return Err(RequestError::PoseCount(values.len()));
            }
            let named: Vec<(Coordinate, f64)> = Coordinate::ALL
                .iter()
                .zip(&values)
                .map(|(&c, &x)| (c, angle(c, x)))
                .collect();
            return Ok(PlatformGoal::from_coordinates(named));
        }
        let mut values: Vec<(Coordinate, f64)> = Vec::new();
        for item in items.iter().filter(|s| !s.is_empty()) {
            let Some((name, value)) = item.split_once('=') else {
                return Err(RequestError::UnnamedCoordinate((*item).to_string()));
            };
            let name = name.trim().to_ascii_lowercase();
            let c = Coordinate::ALL
                .into_iter()
                .find(|c| c.name() == name)
                .ok_or_else(|| RequestError::UnknownCoordinate(name.clone()))?;
            if values.iter().any(|&(d, _)| d == c) {
                return Err(RequestError::CoordinateTwice(c.name()));
            }
            values.push((c, angle(c, finite_number(value)?)));
        }
        Ok(PlatformGoal::from_coordinates(values))
    }
}

/// A finite number, or a one-line error naming the text.
fn finite_number(text: &str) -> Result<f64, RequestError> {
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x.abs() <= super::LARGEST_COORDINATE => Ok(x),
        Ok(x) if x.is_finite() => Err(RequestError::BeyondLimit(x)),
        _ => Err(RequestError::NotANumber(text.trim().to_string())),
    }
}
