//! Poses of several moving bodies at once: the joint values that put each body where it is asked
//! to be and close every loop, e.g. a stack of parallel modules given by the Study parameters of
//! each module's moving platform relative to the one below (paper 002 §5: `⁰X₁` of the coupler
//! from the base, `¹Y₂` of the end-effector from the coupler).
//!
//! The poses are reached by continuation from a start configuration, as
//! [`Manipulator::solve_position`]: every body's frame moves along the screw from its start pose
//! to the pose asked for, and the loops are closed at each step by damped Newton steps
//! ([`crate::mechanism::Mechanism::assemble_to`] with a [`Goal::All`] of [`Goal::Pose`]s). Poses
//! that no joint values realise — e.g. Study parameters printed to two decimals, which miss the
//! constraint manifold by about 1e-2 — are refused with
//! [`PositionError::PosesNotAssembled`], which carries the residual where the solver stopped.

use super::{Manipulator, ManipulatorError, PositionError, RequestError};
use crate::chain::Displacement;
use crate::mechanism::{
    ASSEMBLY_TOLERANCE, AssemblySettings, Goal, MechanismError, compose, exp, inverse, log,
    rotation_log,
};
use crate::screw::Twist;
use crate::spatial::study::{self, StudyParameters};

/// The tolerance on the relative Study quadric residual `|x·y| / (|x| |y|)`
/// ([`study::relative_quadric_residual`]) for Study parameters **printed to two decimals**, as in
/// paper 002 Table 1. Rounding each of the eight parameters by at most 0.005 changes `x·y` by at
/// most `0.005 (Σ|xᵢ| + Σ|yᵢ|) ≤ 0.01 (|x| + |y|)`, so the relative residual by at most
/// `0.01 (1/|y| + 1/|x|)`: below 2e-2 whenever `|x|, |y| ≥ 1`, the case of every row of the
/// table. Exact parameters pass [`study::QUADRIC_TOLERANCE`].
pub const PRINTED_STUDY_TOLERANCE: f64 = 2e-2;

/// The rounding of parameters printed to two decimals: each lies within half a unit of the
/// last printed place, 0.005, of the value printed (paper 002 Table 1). The default of
/// [`Manipulator::nearest_study`]'s bound.
pub const PRINTED_ROUNDING: f64 = 5e-3;

/// How far the nearest configuration puts one moving body from the pose asked for, and (for
/// rounded data) how far the rounding alone could have moved it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PoseChange {
    /// The body, an index into [`Manipulator::bodies`].
    pub body: usize,
    /// The distance between its frame's origin and the one asked for (the description's length
    /// unit).
    pub translation: f64,
    /// The angle of the rotation between its frame and the one asked for (radians).
    pub rotation: f64,
    /// The largest `translation` the rounding explains (first order, [`Manipulator::study_rounding_bounds`]);
    /// infinite when no bound applies.
    pub translation_bound: f64,
    /// The largest `rotation` the rounding explains (radians); infinite when no bound applies.
    pub rotation_bound: f64,
}

/// The assembled configuration nearest to poses that may lie off the constraint set
/// ([`Manipulator::nearest_poses`], [`Manipulator::nearest_study`]).
#[derive(Debug, Clone, PartialEq)]
pub struct NearestPoses {
    /// Its joint values: every loop closed.
    pub q: Vec<f64>,
    /// How far it puts each body asked for from its pose, in the order asked.
    pub changes: Vec<PoseChange>,
}

impl Manipulator {
    /// Parses Study parameters written `x0:x1:x2:x3:y0:y1:y2:y3` (paper 004 eqs. 4–7, any
    /// common non-zero scale); the quadric is checked by [`Manipulator::frames_from_study`].
    ///
    /// # Errors
    /// [`RequestError::StudyFormat`] when the text is not eight `:`-separated finite numbers.
    pub fn parse_study(text: &str) -> Result<StudyParameters, RequestError> {
        let values: Vec<f64> = text
            .split(':')
            .map(|v| v.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| RequestError::StudyFormat(text.to_string()))?;
        let s: StudyParameters = values
            .try_into()
            .map_err(|_| RequestError::StudyFormat(text.to_string()))?;
        if s.iter().all(|c| c.is_finite()) {
            Ok(s)
        } else {
            Err(RequestError::StudyFormat(text.to_string()))
        }
    }

    /// The frames of the moving bodies (index into [`Manipulator::bodies`], frame pose in the
    /// ground frame) from one set of Study parameters per moving body, **in series order from
    /// the ground**, i.e. in the order of the description's bodies: the first gives the first
    /// body's frame `F₁` from the ground frame `F₀`, each next one the next body's frame from the
    /// previous body's (paper 002 §5: `⁰X₁`, then `¹Y₂`), so body k's frame is
    /// `S₁ ∘ S₂ ∘ … ∘ S_k`. Each set may have any scale; it must lie on the Study quadric within
    /// `tolerance` (relative residual, [`study::relative_quadric_residual`]; use
    /// [`PRINTED_STUDY_TOLERANCE`] for values printed to two decimals).
    ///
    /// # Errors
    /// [`RequestError::StudyCount`] when not one set per moving body; [`RequestError::Study`]
    /// when a set is no displacement (off the quadric beyond `tolerance`, `x = 0`).
    pub fn frames_from_study(
        &self,
        sets: &[StudyParameters],
        tolerance: f64,
    ) -> Result<Vec<(usize, Displacement)>, RequestError> {
        if sets.len() != self.bodies.len() {
            return Err(RequestError::StudyCount {
                manipulator: self.name.clone(),
                given: sets.len(),
                bodies: self.bodies.len(),
            });
        }
        let mut frame = Displacement::identity();
        let mut frames = Vec::with_capacity(sets.len());
        for (k, s) in sets.iter().enumerate() {
            let relative =
                study::to_displacement(s, tolerance).map_err(|source| RequestError::Study {
                    body: self.bodies[k].name.clone(),
                    source,
                })?;
            frame = compose(&frame, &relative);
            frames.push((k, frame));
        }
        Ok(frames)
    }

    /// The joint values that put the frames of several moving bodies at the given poses (index
    /// into [`Manipulator::bodies`], frame pose in the ground frame) and close every loop,
    /// reached by continuation from `start` (module documentation). A body's pose in the
    /// mechanism is its displacement from its reference, `frame ∘ reference_frame⁻¹`.
    ///
    /// # Errors
    /// [`ManipulatorError::Position`] with [`PositionError::PosesNotAssembled`] when the poses
    /// cannot be assembled (or not reached from `start`): its `residual` is where damped Newton
    /// steps toward the poses stop, from the furthest configuration the continuation reached.
    pub fn solve_poses(
        &self,
        start: &[f64],
        frames: &[(usize, Displacement)],
    ) -> Result<Vec<f64>, ManipulatorError> {
        let m = &self.mechanism;
        let unlocked = vec![false; start.len()];
        let start_frames = self.frames_at(start, frames);
        let goal_at = |t: f64| self.poses_goal(frames, &start_frames, t);
        let (q, t) = match self.continue_along(
            start,
            |t, q| (q.to_vec(), Some(goal_at(t))),
            |q, goal| m.assemble_to(q, &unlocked, goal),
        ) {
            Ok((q, _)) => return Ok(q),
            Err((q, failure)) => (q, failure.done()),
        };
        // The path cannot be followed: Newton steps toward the poses from the furthest
        // configuration reached, whose residual says how far the poses are from an assembly.
        match m.assemble_to(&q, &unlocked, Some(&goal_at(1.0))) {
            Ok(solved) => Ok(solved),
            Err(MechanismError::NotAssembled { residual, .. }) => {
                Err(PositionError::PosesNotAssembled {
                    residual,
                    tolerance: ASSEMBLY_TOLERANCE,
                    done: t,
                }
                .into())
            }
            Err(e) => Err(e.into()),
        }
    }

    /// The frames at `q` of the bodies that `frames` names (their poses at the start of a path).
    pub(super) fn frames_at(
        &self,
        q: &[f64],
        frames: &[(usize, Displacement)],
    ) -> Vec<Displacement> {
        frames.iter().map(|&(k, _)| self.body_frame(k, q)).collect()
    }

    /// The goal of the bodies' frames a fraction `t` of the way from `from` to the `frames`
    /// asked for, each along the screw between the two poses; a body's pose in the mechanism is
    /// its displacement from its reference, `frame ∘ reference_frame⁻¹`.
    pub(super) fn poses_goal(
        &self,
        frames: &[(usize, Displacement)],
        from: &[Displacement],
        t: f64,
    ) -> Goal {
        Goal::All(
            frames
                .iter()
                .zip(from)
                .map(|(&(k, target), from)| {
                    let screw = log(&compose(&target, &inverse(from))).to_vector() * t;
                    let frame = compose(&exp(&Twist::from_vector(&screw)), from);
                    Goal::Pose {
                        body: self.bodies[k].body,
                        displacement: compose(&frame, &inverse(&self.bodies[k].frame)),
                    }
                })
                .collect(),
        )
    }

    /// The assembled configuration nearest to the frames asked for (index into
    /// [`Manipulator::bodies`], frame pose in the ground frame), which need not be assemblable:
    /// every loop closed, and the bodies' frames as near the poses as the loops allow (least
    /// squares of the dimensionless pose errors, rotations in radians and lengths over the
    /// mechanism's characteristic length; [`crate::mechanism::Mechanism::assemble_nearest`]).
    /// Reached by continuation from `start`: the frames asked for are approached along the
    /// screws from the start's, in steps that halve when one fails or jumps. Each
    /// [`PoseChange`] has infinite bounds (see [`Manipulator::nearest_study`] for rounded data).
    ///
    /// # Errors
    /// [`ManipulatorError::Position`] with [`PositionError::NotReached`] when the continuation
    /// stops (a step that cannot be made small enough, or too many steps).
    pub fn nearest_poses(
        &self,
        start: &[f64],
        frames: &[(usize, Displacement)],
    ) -> Result<NearestPoses, ManipulatorError> {
        let m = &self.mechanism;
        let unlocked = vec![false; start.len()];
        let start_frames = self.frames_at(start, frames);
        let settings = AssemblySettings::default();
        let goal_at = |t: f64| self.poses_goal(frames, &start_frames, t);
        let (q, _) = self
            .continue_along(
                start,
                |t, q| (q.to_vec(), Some(goal_at(t))),
                |q, goal| match goal {
                    Some(goal) => m.assemble_nearest(q, &unlocked, goal, &settings),
                    None => m.assemble_to(q, &unlocked, None),
                },
            )
            .map_err(|(_, failure)| PositionError::NotReached(failure))?;
        let changes = frames
            .iter()
            .map(|&(k, target)| {
                let reached = self.body_frame(k, &q);
                PoseChange {
                    body: k,
                    translation: (reached.translation.vector - target.translation.vector).norm(),
                    rotation: rotation_log(&(reached.rotation * target.rotation.inverse())).norm(),
                    translation_bound: f64::INFINITY,
                    rotation_bound: f64::INFINITY,
                }
            })
            .collect();
        Ok(NearestPoses { q, changes })
    }

    /// How far each moving body's frame can move when every Study parameter of `sets` (as
    /// [`Manipulator::frames_from_study`]) changes by at most `rounding`: to first order, the
    /// sum over the parameters of `|∂(origin)/∂s| · rounding` and `|∂(rotation)/∂s| · rounding`
    /// (central differences), the worst case of the rounding box. Returns (translation in the
    /// description's length unit, rotation in radians) per body, in body order. Body k's frame
    /// is the composition of sets 1 … k, so its bound gathers their parameters.
    ///
    /// # Errors
    /// As [`Manipulator::frames_from_study`] (the quadric is not checked here).
    pub fn study_rounding_bounds(
        &self,
        sets: &[StudyParameters],
        rounding: f64,
    ) -> Result<Vec<(f64, f64)>, RequestError> {
        // Any eight numbers with x ≠ 0 give a matrix; the relative residual is at most 1.
        let frames = |s: &[StudyParameters]| self.frames_from_study(s, 1.0);
        frames(sets)?;
        let h = 1e-6;
        let mut bounds = vec![(0.0, 0.0); sets.len()];
        for set in 0..sets.len() {
            for c in 0..8 {
                let (mut up, mut down) = (sets.to_vec(), sets.to_vec());
                up[set][c] += h;
                down[set][c] -= h;
                let (fu, fd) = (frames(&up)?, frames(&down)?);
                for (k, bound) in bounds.iter_mut().enumerate() {
                    let (a, b) = (fu[k].1, fd[k].1);
                    let dt = (a.translation.vector - b.translation.vector).norm() / (2.0 * h);
                    let dr = rotation_log(&(a.rotation * b.rotation.inverse())).norm() / (2.0 * h);
                    bound.0 += dt * rounding;
                    bound.1 += dr * rounding;
                }
            }
        }
        Ok(bounds)
    }

    /// The assembled configuration nearest to the poses of rounded Study parameters (as
    /// [`Manipulator::frames_from_study`], one set per moving body in series order, each on the
    /// quadric within `tolerance`), accepted only when no body moves further than rounding
    /// each parameter by `rounding` explains ([`Manipulator::study_rounding_bounds`];
    /// [`PRINTED_ROUNDING`] for values printed to two decimals). This is how a printed table
    /// such as paper 002's Table 1 is checked: a row within its rounding is a configuration of
    /// the mechanism, analysed at the nearest assembly; a row beyond it is not one.
    ///
    /// # Errors
    /// As [`Manipulator::frames_from_study`] and [`Manipulator::nearest_poses`], and
    /// [`PositionError::BeyondRounding`] for the first body moved further than the rounding
    /// explains.
    pub fn nearest_study(
        &self,
        start: &[f64],
        sets: &[StudyParameters],
        tolerance: f64,
        rounding: f64,
    ) -> Result<NearestPoses, ManipulatorError> {
        let frames = self.frames_from_study(sets, tolerance)?;
        let bounds = self.study_rounding_bounds(sets, rounding)?;
        let mut nearest = self.nearest_poses(start, &frames)?;
        for change in &mut nearest.changes {
            (change.translation_bound, change.rotation_bound) = bounds[change.body];
            if change.translation > change.translation_bound
                || change.rotation > change.rotation_bound
            {
                return Err(PositionError::BeyondRounding {
                    body: self.bodies[change.body].name.clone(),
                    translation: change.translation,
                    rotation: change.rotation,
                    translation_bound: change.translation_bound,
                    rotation_bound: change.rotation_bound,
                    rounding,
                }
                .into());
            }
        }
        Ok(nearest)
    }

    /// [`Manipulator::frames_from_study`] then [`Manipulator::solve_poses`]: the configuration
    /// with every moving body at the pose its Study parameters give (series order from the
    /// ground), reached from `start`.
    ///
    /// # Errors
    /// As the two: [`ManipulatorError::Request`] for the Study parameters,
    /// [`ManipulatorError::Position`] when the poses cannot be assembled.
    pub fn solve_study(
        &self,
        start: &[f64],
        sets: &[StudyParameters],
        tolerance: f64,
    ) -> Result<Vec<f64>, ManipulatorError> {
        let frames = self.frames_from_study(sets, tolerance)?;
        self.solve_poses(start, &frames)
    }
}
