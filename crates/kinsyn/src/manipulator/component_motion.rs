//! The **whole mechanism on a component** of its constraint variety: every body placed from a
//! real point of the component (one per block of the body tree; a block without one at its
//! reference), the joints of every leg found by assembling the mechanism at those frames
//! ([`Manipulator::solve_poses`]), and there the local analysis of any body — its motion with
//! the held inputs locked, sampled on the mechanism ([`Manipulator::mode_from`]) — and the
//! inputs whose rates are not zero on the loop closure's null space: the inputs that **move**
//! on the component. At a generic point of an operation mode the mechanism's local motion is
//! the component's, so this is the component's motion read by a second method (the loop
//! closure of the joint graph rather than the polynomial constraints), for a body of any
//! block and for the products of several blocks' components alike.
//!
//! A leg's inverse kinematics is solved here, leg by leg, rather than by the mechanism's own
//! assembly (`Mechanism::assemble_to`): that Newton's method closes every loop at once from
//! one start, and a point of another operation mode is rarely within its reach; one leg of
//! at most six joints, from 32 random starts, is cheap (its Jacobian by central differences
//! of the product of exponentials, which needs no joint screws of the whole mechanism).

use super::polynomial::PositionSystem;
use super::{Manipulator, ManipulatorError, Mode};
use crate::mechanism::SampleSettings;
use crate::notation::Primitive;
use crate::spatial::Displacement;

/// The part of a block a frame computation needs: its parent (an index into
/// [`Manipulator::bodies`], `None` for the ground), its root body and its system.
pub type BlockPart<'a> = (Option<usize>, usize, &'a PositionSystem);

/// The mechanism at a real point of a component (module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct ComponentMotion {
    /// The joint values of the mechanism there (from the reference).
    pub q: Vec<f64>,
    /// The end-effector's motion there with the held inputs locked.
    pub mode: Mode,
    /// For each actuator (in [`Manipulator::actuators`] order): whether its input moves on the
    /// component; held inputs do not.
    pub moving: Vec<bool>,
    /// The held inputs (indices into [`Manipulator::actuators`]).
    pub held: Vec<usize>,
}

/// Why the mechanism could not be placed on a component.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ComponentMotionError {
    /// A block's point is no displacement.
    #[error("a block's point is no displacement: {0}")]
    Study(#[from] crate::spatial::study::StudyError),
    /// A leg does not reach its bodies' frames with real joint values (the point is real, the
    /// leg's joints there complex).
    #[error("leg {leg} does not reach its bodies' frames with real joint values")]
    Unreached {
        /// The leg (1-based).
        leg: usize,
    },
    /// The loops could not be closed at the bodies' frames.
    #[error("the loops do not close at the bodies' frames: {0}")]
    Assembly(#[from] ManipulatorError),
}

/// The random starts of a leg's inverse kinematics ([`Manipulator::leg_joint_values`]).
const LEG_STARTS: usize = 32;

/// An input is at its value when within this of it (radians; lengths over the mechanism's
/// scale), a revolute's value taken modulo a turn.
const INPUT_TOLERANCE: f64 = 1e-7;

/// A rate below this (radians, or lengths over the mechanism's scale, per unit of an
/// orthonormal basis of dimensionless joint rates) is a joint that does not move.
pub const MOVING_TOLERANCE: f64 = 1e-6;

impl Manipulator {
    /// The point of a block's system at the reference configuration: its root's frame relative
    /// to its parent's, every joint unknown at zero (joint values are measured from the
    /// reference); `None` when the system's chart misses it.
    #[must_use]
    pub fn reference_point(&self, part: BlockPart<'_>) -> Option<Vec<f64>> {
        let (parent, body, system) = part;
        let parent = parent.map_or_else(crate::spatial::identity, |p| self.bodies[p].frame);
        let mut x = system.solution_of(&(parent.inverse() * self.bodies[body].frame))?;
        x.resize(system.system().nvars(), 0.0);
        Some(x)
    }

    /// The frame of every moving body (in [`Manipulator::bodies`] order, ground frame) from one
    /// real point per block (`parts` parents first, `points` in the same order): each root's
    /// frame is its parent's composed with the block's displacement, each member's the root's
    /// composed with its joints'.
    ///
    /// # Errors
    /// A point that is no displacement ([`crate::spatial::study::StudyError`]).
    pub fn frames_of_blocks(
        &self,
        parts: &[BlockPart<'_>],
        points: &[&[f64]],
    ) -> Result<Vec<Displacement>, crate::spatial::study::StudyError> {
        let mut frames = vec![crate::spatial::identity(); self.bodies.len()];
        for (&(parent, body, system), x) in parts.iter().zip(points) {
            let parent = parent.map_or_else(crate::spatial::identity, |p| frames[p]);
            let root = parent * system.displacement(x)?;
            frames[body] = root;
            for (member, g) in system.member_frames(x)? {
                frames[member] = root * g;
            }
        }
        Ok(frames)
    }

    /// The joint values that put every moving body at `frames` (in [`Manipulator::bodies`]
    /// order, ground frame) with the `inputs` (actuator index, value) at their values: by
    /// continuation from the reference when it reaches them with those inputs, else leg by
    /// leg — with every body placed, each leg's joints solve its own inverse kinematics with
    /// its inputs fixed ([`Manipulator::leg_joint_values`]) — and the loops closed by Newton's
    /// method from there, the inputs held. A leg's joints can reach its bodies' frames in
    /// several ways (an RUU's crank in two positions over one pose): the inputs choose the one
    /// the frames were found at.
    ///
    /// # Errors
    /// [`ComponentMotionError::Unreached`] when a leg cannot reach its bodies' frames,
    /// [`ComponentMotionError::Assembly`] when the loops do not close then.
    pub fn assemble_at_frames(
        &self,
        frames: &[Displacement],
        inputs: &[(usize, f64)],
    ) -> Result<Vec<f64>, ComponentMotionError> {
        let goal: Vec<(usize, Displacement)> = frames.iter().copied().enumerate().collect();
        let at_inputs = |q: &[f64]| {
            inputs.iter().all(|&(a, v)| {
                let joint = self.actuators[a].joint;
                match self.actuators[a].kind {
                    Primitive::R => {
                        let d = (q[joint] - v).rem_euclid(std::f64::consts::TAU);
                        d.min(std::f64::consts::TAU - d) < INPUT_TOLERANCE
                    }
                    Primitive::P => (q[joint] - v).abs() < INPUT_TOLERANCE * self.mechanism.scale(),
                }
            })
        };
        if let Ok(q) = self.solve_poses(&self.reference(), &goal)
            && at_inputs(&q)
        {
            return Ok(q);
        }
        let index = |body: usize| self.bodies.iter().position(|b| b.body == body);
        let frame = |body: usize| index(body).map_or_else(crate::spatial::identity, |k| frames[k]);
        let mut q = self.reference();
        for (i, leg) in self.legs.iter().enumerate() {
            let fixed: Vec<(usize, f64)> = inputs
                .iter()
                .filter(|&&(a, _)| self.actuators[a].leg == i)
                .map(|&(a, v)| (self.actuators[a].position, v))
                .collect();
            let values = self
                .leg_joint_values(i, &frame(leg.from), &frame(leg.to), &fixed)
                .ok_or(ComponentMotionError::Unreached { leg: i + 1 })?;
            q[leg.joints.clone()].copy_from_slice(&values);
        }
        let held: Vec<usize> = inputs.iter().map(|&(a, _)| a).collect();
        let all = self.poses_goal(&goal, &self.frames_at(&q, &goal), 1.0);
        self.mechanism
            .assemble_to(&q, &self.lock_mask(&held), Some(&all))
            .map_err(|e| ComponentMotionError::Assembly(e.into()))
    }

    /// The joint values of leg `i` (from the reference) that carry its last body to `to` when
    /// its first body is at `from` (ground frames), the joints `fixed` (position in the leg,
    /// value) at their values: damped Gauss–Newton on the product of the joints' exponentials
    /// about their reference axes over the other joints, from the reference and then from
    /// seeded random values, until one reaches the frame to `1e-12` (rotation in radians,
    /// lengths over the mechanism's scale). A leg with an idle joint (an S–S rod's spin) has
    /// many; one is returned. `None` when no start reaches it.
    #[must_use]
    pub fn leg_joint_values(
        &self,
        i: usize,
        from: &Displacement,
        to: &Displacement,
        fixed: &[(usize, f64)],
    ) -> Option<Vec<f64>> {
        use rand::{Rng, SeedableRng};
        let leg = &self.legs[i];
        let joints = &self.mechanism.joints()[leg.joints.clone()];
        let index = |body: usize| self.bodies.iter().position(|b| b.body == body);
        let reference = |body: usize| {
            index(body).map_or_else(crate::spatial::identity, |k| self.bodies[k].frame)
        };
        let scale = self.mechanism.scale();
        // The joints' product must equal (from · from_ref⁻¹)⁻¹ · to · to_ref⁻¹.
        let target =
            (from * reference(leg.from).inverse()).inverse() * (to * reference(leg.to).inverse());
        let residual = |q: &[f64]| -> nalgebra::DVector<f64> {
            let product = joints
                .iter()
                .zip(q)
                .fold(crate::spatial::identity(), |g, (j, v)| {
                    g * j.primitive().displacement(*v)
                });
            let t = crate::spatial::log(&(target.inverse() * product)).to_vector();
            nalgebra::DVector::from_fn(6, |k, _| if k < 3 { t[k] } else { t[k] / scale })
        };
        let moving: Vec<usize> = (0..joints.len())
            .filter(|k| fixed.iter().all(|&(f, _)| f != *k))
            .collect();
        let solve = |mut q: Vec<f64>| -> Option<Vec<f64>> {
            for &(k, v) in fixed {
                q[k] = v;
            }
            let h = 1e-7;
            for _ in 0..60 {
                let r = residual(&q);
                if r.amax() < 1e-12 {
                    return Some(q);
                }
                let jac = nalgebra::DMatrix::from_fn(6, moving.len(), |row, col| {
                    let mut plus = q.clone();
                    let mut minus = q.clone();
                    plus[moving[col]] += h;
                    minus[moving[col]] -= h;
                    (residual(&plus)[row] - residual(&minus)[row]) / (2.0 * h)
                });
                let jt = jac.transpose();
                let normal =
                    &jt * &jac + nalgebra::DMatrix::identity(moving.len(), moving.len()) * 1e-12;
                let step = normal.lu().solve(&(jt * r))?;
                for (&k, d) in moving.iter().zip(step.iter()) {
                    q[k] -= d;
                }
            }
            (residual(&q).amax() < 1e-10).then_some(q)
        };
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(i as u64);
        std::iter::once(vec![0.0; joints.len()])
            .chain((0..LEG_STARTS).map(|_| {
                joints
                    .iter()
                    .map(|j| match j.kind {
                        Primitive::R => {
                            rng.random_range(-std::f64::consts::PI..std::f64::consts::PI)
                        }
                        Primitive::P => rng.random_range(-2.0..2.0) * scale,
                    })
                    .collect()
            }))
            .find_map(solve)
    }

    /// The mechanism on a component (module documentation): the blocks `parts` (parents
    /// first), a real point of the component for some (`points`, `None`: the block at its
    /// reference), the inputs `held` (index into [`Manipulator::actuators`], the value the
    /// component was found at) locked at their values.
    ///
    /// # Errors
    /// A point that is no displacement, or frames the mechanism cannot be assembled at by
    /// continuation from its reference ([`ComponentMotionError`]).
    pub fn component_motion(
        &self,
        parts: &[BlockPart<'_>],
        points: &[Option<&[f64]>],
        held: &[(usize, f64)],
        settings: &SampleSettings,
    ) -> Result<ComponentMotion, ComponentMotionError> {
        let reference: Vec<Option<Vec<f64>>> = parts
            .iter()
            .zip(points)
            .map(|(&part, p)| match p {
                Some(_) => None,
                None => self.reference_point(part),
            })
            .collect();
        let chosen: Vec<&[f64]> = points
            .iter()
            .zip(&reference)
            .map(|(p, r)| p.or(r.as_deref()).unwrap_or(&[]))
            .collect();
        let frames = self.frames_of_blocks(parts, &chosen)?;
        let q = self.assemble_at_frames(&frames, held)?;
        let held: Vec<usize> = held.iter().map(|&(a, _)| a).collect();
        let mode = self.mode_from(&q, &held, settings);
        let mask = self.lock_mask(&held);
        let free: Vec<usize> = (0..mask.len()).filter(|&j| !mask[j]).collect();
        let rates = self.mechanism.mobility(&q, &mask).rates;
        let joints = self.mechanism.joints();
        let moving = self
            .actuators
            .iter()
            .map(|a| {
                free.iter().position(|&j| j == a.joint).is_some_and(|row| {
                    let unit = match joints[a.joint].kind {
                        Primitive::R => 1.0,
                        Primitive::P => self.mechanism.scale(),
                    };
                    rates.row(row).amax() > MOVING_TOLERANCE * unit
                })
            })
            .collect();
        Ok(ComponentMotion {
            q,
            mode,
            moving,
            held,
        })
    }
}
