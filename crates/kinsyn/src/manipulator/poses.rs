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
use crate::mechanism::{ASSEMBLY_TOLERANCE, Goal, MechanismError, compose, exp, inverse, log};
use crate::screw::Twist;
use crate::spatial::study::{self, StudyParameters};

/// The tolerance on the relative Study quadric residual `|x·y| / (|x| |y|)`
/// ([`study::relative_quadric_residual`]) for Study parameters **printed to two decimals**, as in
/// paper 002 Table 1. Rounding each of the eight parameters by at most 0.005 changes `x·y` by at
/// most `0.005 (Σ|xᵢ| + Σ|yᵢ|) ≤ 0.01 (|x| + |y|)`, so the relative residual by at most
/// `0.01 (1/|y| + 1/|x|)`: below 2e-2 whenever `|x|, |y| ≥ 1`, the case of every row of the
/// table. Exact parameters pass [`study::QUADRIC_TOLERANCE`].
pub const PRINTED_STUDY_TOLERANCE: f64 = 2e-2;

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
        let start_frames: Vec<Displacement> = frames
            .iter()
            .map(|&(k, _)| self.body_frame(k, start))
            .collect();
        let goal_at = |t: f64| {
            Goal::All(
                frames
                    .iter()
                    .zip(&start_frames)
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
        };
        let (q, t) =
            match self.continue_along(start, &unlocked, |t, q| (q.to_vec(), Some(goal_at(t)))) {
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
