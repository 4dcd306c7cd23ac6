//! Parallel manipulators built from serial legs: their mechanism graph, Jacobians from
//! reciprocal screws (paper 000 §4–5), singularities, locking, and multioperation capacity.
//!
//! A [`Manipulator`] is read from a description ([`file::Description`], `mechanisms/*.json`):
//! each leg becomes a chain of primitive joints from the ground to the platform in a
//! [`Mechanism`], with intermediate bodies between consecutive primitives. The actuated joints
//! are the manipulator's inputs; locking an input holds its joint at its reference value
//! (paper 000 §5: `α̇ = 0` turns the 3-UPS into the 3-RPS).
//!
//! ```
//! use kinsyn::manipulator::Manipulator;
//! # std::env::set_current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).unwrap();
//! let text = std::fs::read_to_string("mechanisms/3-ups.json").unwrap();
//! let m = Manipulator::from_json(&text).unwrap();
//! assert_eq!((m.legs().len(), m.actuators().len()), (3, 6));
//! ```

mod body_tree;
pub mod build;
mod component_motion;
mod construction;
pub mod file;
mod jacobian;
pub mod leg;
pub mod lookup;
mod modes;
mod modes_cost;
mod operation_mode;
mod polynomial;
mod poses;
mod position;
mod request;
mod singularity;
pub mod stacking;
mod sub_mechanism;

pub use body_tree::{BodyBlock, BodyNode, Member};
pub use component_motion::{BlockPart, ComponentMotion, ComponentMotionError, MOVING_TOLERANCE};
pub use jacobian::{Jacobians, RowKind, WrenchRow};
pub use leg::{LegCheck, LegWarning, LegWarningKind};
pub use lookup::{CatalogueChain, ChainLookup, CommittedChains};
pub use modes::{MAX_INPUTS, Mode, Modes, PatternModes};
pub use modes_cost::ModesCost;
pub use operation_mode::{
    BlockModes, DecompositionMethod, LocalMotion, ModeComponent, OperationModeError,
    OperationModeSettings, OperationModes,
};
pub use polynomial::{
    FreeRevolute, InputValues, LegConstraint, LegKind, LegResidual, PositionSystem,
    PositionSystemError,
};
pub use poses::{NearestPoses, PRINTED_ROUNDING, PRINTED_STUDY_TOLERANCE, PoseChange};
pub use position::{CONTINUATION_TRIES, PlatformGoal, Position, PositionRequest};
pub use request::{ContinuationFailure, PositionError, RequestError};
pub use singularity::{
    Analysis, GenericRanks, Singularity, SingularityCause, SingularityKind, rank_text,
};
pub use sub_mechanism::{SubMechanismError, parse_leg_list};

use crate::chain::Displacement;
use crate::mechanism::{Mechanism, MechanismError};
use crate::notation::{Chain, Primitive};
use construction::{Fields, Layout, LegGeometry, MechanismBuilder};
pub(crate) use construction::{actuated_positions, check_joint_axes, leg_chain};
use file::{Description, DescriptionError, MultibodyDescription};
use nalgebra::{DMatrix, Point3, Rotation3, Vector3};
use std::ops::Range;

/// Why a manipulator could not be built or analysed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ManipulatorError {
    /// The description is unusable; the message names the field.
    #[error("{0}")]
    Description(#[from] DescriptionError),
    /// The mechanism could not be built or assembled.
    #[error("{0}")]
    Mechanism(#[from] MechanismError),
    /// A position that the manipulator cannot reach.
    #[error("{0}")]
    Position(#[from] PositionError),
    /// A request naming what the manipulator does not have, or a value that is not one.
    #[error("{0}")]
    Request(#[from] RequestError),
}

/// One leg of a manipulator.
#[derive(Debug, Clone, PartialEq)]
pub struct Leg {
    /// The chain as read (with its actuation marks).
    pub chain: Chain,
    /// The leg's primitive joints in the mechanism, base to platform (`from` to `to`).
    pub joints: Range<usize>,
    /// The body its first joint is on (a body of the mechanism; the ground is 0).
    pub from: usize,
    /// The body its last joint is on.
    pub to: usize,
}

/// A moving body of a manipulator, as its description names it.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// Its name (`platform` for the one platform of a `/1` description).
    pub name: String,
    /// The body in the mechanism.
    pub body: usize,
    /// Its frame at the reference configuration (ground frame).
    pub frame: Displacement,
    /// Its reference point at the reference configuration, in the ground frame.
    pub point: Vector3<f64>,
}

/// One input of a manipulator.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Actuator {
    /// 0-based leg.
    pub leg: usize,
    /// 0-based position of the primitive joint in the leg.
    pub position: usize,
    /// The joint in the mechanism.
    pub joint: usize,
    /// P or R.
    pub kind: Primitive,
}

impl Actuator {
    /// The actuator's label: its kind, leg and position, e.g. `P1.3` (leg 1, third joint).
    #[must_use]
    pub fn label(&self) -> String {
        format!(
            "{}{}.{}",
            self.kind.letter(),
            self.leg + 1,
            self.position + 1
        )
    }
}

/// A parallel manipulator: legs from the ground to one platform, or more generally between named
/// bodies (a `/2` description: stacked modules, platforms made of several bodies), with actuated
/// joints and one moving body, the end-effector, analysed by default.
#[derive(Debug, Clone)]
pub struct Manipulator {
    name: String,
    units: file::Units,
    mechanism: Mechanism,
    legs: Vec<Leg>,
    actuators: Vec<Actuator>,
    /// The ground's name.
    ground: String,
    /// The moving bodies, in description order.
    bodies: Vec<Body>,
    /// The end-effector: an index into `bodies`.
    end_effector: usize,
    /// The moving body the end-effector's motion patterns are taken relative to
    /// ([`Manipulator::relative_to`]): an index into `bodies`; `None`: relative to the ground.
    relative_to: Option<usize>,
    /// The end-effector's body in the mechanism (`platform()`).
    platform: usize,
    /// P at the reference configuration, in the ground frame.
    point: Vector3<f64>,
    /// The platform frame at the reference configuration.
    frame: Displacement,
}

/// The tolerance of the joint-axis checks on unit axes: a C's axes are parallel when
/// `|a₁ × a₂|` is below it, a U's are not when above, an S's are independent when
/// `|(a₁ × a₂)·a₃|` is above it.
const AXIS_TOLERANCE: f64 = 1e-6;

impl Manipulator {
    /// Reads and builds a manipulator from the JSON text of a description file of either
    /// format (`/1`: one platform; `/2`: named bodies).
    ///
    /// # Errors
    /// See [`file::AnyDescription::from_json`], [`Manipulator::new`] and
    /// [`Manipulator::from_bodies`].
    ///
    /// # Example
    /// The reconfigurable 3-UPS of paper 000 §5.1 has a platform of six dof; locking the first
    /// revolute α of each U (inputs `R1.1`, `R2.1`, `R3.1`) turns it into the 3-RPS of §5.2,
    /// whose platform keeps three.
    ///
    /// ```
    /// use kinsyn::manipulator::Manipulator;
    /// use kinsyn::mechanism::SampleSettings;
    ///
    /// # std::env::set_current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).unwrap();
    /// let text = std::fs::read_to_string("mechanisms/3-ups.json")?;
    /// let m = Manipulator::from_json(&text)?;
    /// let settings = SampleSettings::default();
    /// assert_eq!(m.analyse(&m.reference(), &[], &settings)?.platform_dof, 6);
    ///
    /// let alphas = m.parse_locks("R1.1,R2.1,R3.1")?;
    /// let rps = m.analyse(&m.reference(), &alphas, &settings)?;
    /// assert_eq!(rps.platform_dof, 3);
    /// assert!(rps.singularities.is_empty());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn from_json(text: &str) -> Result<Self, ManipulatorError> {
        match file::AnyDescription::from_json(text)? {
            file::AnyDescription::V1(d) => Self::new(&d),
            file::AnyDescription::V2(d) => Self::from_bodies(&d),
        }
    }

    /// Builds a manipulator from a description, resolving catalogue ids (and catalogue chains
    /// whose axes are left out) in the committed catalogue ([`CommittedChains`]).
    ///
    /// # Errors
    /// See [`Manipulator::new_with`].
    pub fn new(d: &Description) -> Result<Self, ManipulatorError> {
        Self::new_with(d, CommittedChains::get())
    }

    /// Builds a manipulator from a description, resolving catalogue ids (and catalogue chains
    /// whose axes are left out) through `lookup`. The description is built as its `/2` form
    /// ([`Description::to_multibody`]); errors name the fields of `/1`.
    ///
    /// # Errors
    /// A chain that does not parse or an unknown catalogue id, axes or points in the wrong
    /// number, axes of no length, joints whose axes break the joint's definition (a C whose
    /// revolute is not parallel to its slider, a U with parallel axes, an S with dependent
    /// axes), revolutes of one parallel group (`Ra…Ra`) whose axes are not parallel, a one-joint leg whose base and platform points differ, actuated positions out of
    /// range, or no leg at all. Each error names its field.
    pub fn new_with(d: &Description, lookup: &dyn ChainLookup) -> Result<Self, ManipulatorError> {
        Self::build(&d.to_multibody(), lookup, Fields::V1)
    }

    /// Builds a manipulator from a description with named bodies (format `/2`), resolving
    /// catalogue chains in the committed catalogue.
    ///
    /// # Errors
    /// See [`Manipulator::from_bodies_with`].
    pub fn from_bodies(d: &MultibodyDescription) -> Result<Self, ManipulatorError> {
        Self::from_bodies_with(d, CommittedChains::get())
    }

    /// Builds a manipulator from a description with named bodies (format `/2`), resolving
    /// catalogue chains through `lookup`.
    ///
    /// # Errors
    /// Besides the leg errors of [`Manipulator::new_with`]: no moving body, too many bodies,
    /// legs or joints (docs/limits.md), an empty or repeated body name, a leg naming a body
    /// that does not exist or the same body twice, a moving body joined to the ground by no
    /// chain of legs, an end-effector that is not a moving body (or left out when there are
    /// several). Each error names its field (`legs[3].to`).
    pub fn from_bodies_with(
        d: &MultibodyDescription,
        lookup: &dyn ChainLookup,
    ) -> Result<Self, ManipulatorError> {
        Self::build(d, lookup, Fields::V2)
    }

    /// The manipulator of a `/2` description, its errors named with the fields of the format
    /// it was read in.
    fn build(
        d: &MultibodyDescription,
        lookup: &dyn ChainLookup,
        fields: Fields,
    ) -> Result<Self, ManipulatorError> {
        let layout = Layout::new(d, fields)?;
        let mut builder = MechanismBuilder::new(&layout.names);
        let mut legs = Vec::new();
        let mut actuators = Vec::new();
        for (i, spec) in d.legs.iter().enumerate() {
            let (from, to) = layout.ends[i];
            let geometry = LegGeometry::new(
                i,
                spec,
                (&layout.frames[from], &layout.frames[to]),
                lookup,
                fields,
            )?;
            let joints = builder.add_serial_leg(from, to, i + 1, &geometry);
            actuators.extend(geometry.actuated.iter().map(|&p| Actuator {
                leg: i,
                position: p,
                joint: joints.start + p,
                kind: geometry.kinds[p],
            }));
            legs.push(Leg {
                chain: geometry.chain,
                joints,
                from,
                to,
            });
        }
        let joints = legs.last().map_or(0, |l| l.joints.end);
        if fields == Fields::V2 && joints > MAX_JOINTS {
            return Err(DescriptionError::new(
                "legs",
                format!(
                    "{joints} primitive joints in all: at most {MAX_JOINTS} (docs/limits.md; the analysis grows with the cube of the number of joints)"
                ),
            )
            .into());
        }
        let bodies: Vec<Body> = d
            .bodies
            .iter()
            .enumerate()
            .map(|(k, b)| {
                let frame = layout.frames[k + 1];
                Body {
                    name: b.name.clone(),
                    body: k + 1,
                    frame,
                    point: frame.transform_point(&Point3::from(b.point)).coords,
                }
            })
            .collect();
        let ee = &bodies[layout.end_effector];
        Ok(Manipulator {
            name: d.name.clone(),
            units: d.units.clone(),
            mechanism: builder.build()?,
            legs,
            actuators,
            ground: d.ground.clone(),
            platform: ee.body,
            point: ee.point,
            frame: ee.frame,
            end_effector: layout.end_effector,
            relative_to: None,
            bodies,
        })
    }

    /// The moving body `name` (an index into [`Manipulator::bodies`]), or the error that lists
    /// the bodies there are.
    fn moving_body(&self, name: &str) -> Result<usize, RequestError> {
        self.body_named(name)
            .ok_or_else(|| RequestError::UnknownBody {
                name: name.to_string(),
                manipulator: self.name.clone(),
                known: self.bodies.iter().map(|b| b.name.clone()).collect(),
            })
    }

    /// The same manipulator with another moving body as its end-effector (by name): every
    /// analysis of the copy (pose, `--pose`, twist space, dof, motion pattern, modes) is of
    /// that body.
    ///
    /// # Errors
    /// A name that is not a moving body; the message lists them.
    pub fn with_end_effector(&self, name: &str) -> Result<Self, RequestError> {
        let k = self.moving_body(name)?;
        let mut copy = self.clone();
        copy.end_effector = k;
        copy.relative_to = self.relative_to.filter(|&r| r != k);
        copy.platform = self.bodies[k].body;
        copy.point = self.bodies[k].point;
        copy.frame = self.bodies[k].frame;
        Ok(copy)
    }

    /// The same manipulator with the end-effector's motion taken relative to the moving body
    /// `name` (`--relative-to NAME`): its motion patterns ([`Manipulator::mode_from`],
    /// [`Manipulator::modes_from`]) are those of the displacements `g_name⁻¹ g_end-effector`,
    /// directions and points in the frame of `name` at its reference pose.
    ///
    /// # Errors
    /// A name that is not a moving body (the message lists them), or the end-effector itself.
    pub fn relative_to(&self, name: &str) -> Result<Self, RequestError> {
        let k = self.moving_body(name)?;
        if k == self.end_effector {
            return Err(RequestError::RelativeToItself {
                name: name.to_string(),
            });
        }
        let mut copy = self.clone();
        copy.relative_to = Some(k);
        Ok(copy)
    }

    /// The moving body the end-effector's motion is taken relative to (an index into
    /// [`Manipulator::bodies`]), if any ([`Manipulator::relative_to`]).
    #[must_use]
    pub fn relative_body(&self) -> Option<usize> {
        self.relative_to
    }

    /// The twist space of moving body `body` relative to moving body `base` (indices into
    /// [`Manipulator::bodies`]) at `q` with the `locked` inputs held: a basis of the twists
    /// `(ω; v)` of `g_base⁻¹ g_body` (columns, in the frame of `base` at its reference pose, v
    /// the velocity of the point at the ground origin) and the relative degrees of freedom
    /// ([`Mechanism::relative_twist_space`]).
    #[must_use]
    pub fn relative_twists(
        &self,
        body: usize,
        base: usize,
        q: &[f64],
        locked: &[usize],
    ) -> (DMatrix<f64>, usize) {
        self.mechanism.relative_twist_space(
            self.bodies[body].body,
            self.bodies[base].body,
            q,
            &self.lock_mask(locked),
        )
    }

    /// The reference point of moving body `body` at `q` as seen from moving body `base`
    /// (indices into [`Manipulator::bodies`]): carried by `g_base⁻¹ g_body`, in the frame of
    /// `base` at its reference pose (the ground frame where `base` has not moved).
    #[must_use]
    pub fn relative_point(&self, body: usize, base: usize, q: &[f64]) -> Vector3<f64> {
        let b = &self.bodies[body];
        self.mechanism
            .relative_pose(b.body, self.bodies[base].body, q)
            .transform_point(&Point3::from(b.point))
            .coords
    }

    /// The moving bodies, in description order (one, `platform`, for a `/1` description).
    #[must_use]
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    /// The end-effector: an index into [`Manipulator::bodies`].
    #[must_use]
    pub fn end_effector(&self) -> usize {
        self.end_effector
    }

    /// The ground's name (`ground` for a `/1` description).
    #[must_use]
    pub fn ground_name(&self) -> &str {
        &self.ground
    }

    /// The moving body with this name: an index into [`Manipulator::bodies`].
    #[must_use]
    pub fn body_named(&self, name: &str) -> Option<usize> {
        self.bodies.iter().position(|b| b.name == name)
    }

    /// Whether paper 000's leg-wrench Jacobians `J_D`, `J_I` ([`Manipulator::jacobians`]) are
    /// defined: every leg runs from the ground to the end-effector, so that each leg's wrenches
    /// act on the end-effector. Otherwise [`Manipulator::jacobians`] has no rows and
    /// [`Manipulator::analyse`] judges the end-effector from the loop-closure Jacobian
    /// (docs/manipulators.md, "Several moving bodies").
    #[must_use]
    pub fn has_leg_wrench_jacobians(&self) -> bool {
        self.legs
            .iter()
            .all(|l| l.from == MechanismBuilder::GROUND && l.to == self.platform)
    }

    /// The twist space of moving body `body` (an index into [`Manipulator::bodies`]) at `q` with
    /// the `locked` inputs held: a basis of its spatial twists `(ω; v)` (columns, velocity of
    /// the point at the ground origin) and its local degrees of freedom.
    #[must_use]
    pub fn body_twists(&self, body: usize, q: &[f64], locked: &[usize]) -> (DMatrix<f64>, usize) {
        self.mechanism
            .twist_space(self.bodies[body].body, q, &self.lock_mask(locked))
    }

    /// The frame of moving body `body` (an index into [`Manipulator::bodies`]) at `q`.
    #[must_use]
    pub fn body_frame(&self, body: usize, q: &[f64]) -> Displacement {
        let b = &self.bodies[body];
        crate::mechanism::compose(&self.mechanism.poses(q)[b.body], &b.frame)
    }

    /// The reference point of moving body `body` at `q`, in the ground frame.
    #[must_use]
    pub fn body_point(&self, body: usize, q: &[f64]) -> Vector3<f64> {
        let b = &self.bodies[body];
        self.mechanism.poses(q)[b.body]
            .transform_point(&Point3::from(b.point))
            .coords
    }

    /// The manipulator's name.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The units of its description.
    #[must_use]
    pub fn units(&self) -> &file::Units {
        &self.units
    }

    /// The mechanism graph.
    #[must_use]
    pub fn mechanism(&self) -> &Mechanism {
        &self.mechanism
    }

    /// The legs.
    #[must_use]
    pub fn legs(&self) -> &[Leg] {
        &self.legs
    }

    /// The inputs, leg by leg.
    #[must_use]
    pub fn actuators(&self) -> &[Actuator] {
        &self.actuators
    }

    /// The end-effector's body in the mechanism (the platform of a `/1` description).
    #[must_use]
    pub fn platform(&self) -> usize {
        self.platform
    }

    /// The reference configuration (all joint values zero: the geometry of the description).
    #[must_use]
    pub fn reference(&self) -> Vec<f64> {
        vec![0.0; self.mechanism.joints().len()]
    }

    /// The reference point P at joint values `q`, in the ground frame.
    #[must_use]
    pub fn point(&self, q: &[f64]) -> Vector3<f64> {
        let g = self.mechanism.poses(q)[self.platform];
        g.transform_point(&Point3::from(self.point)).coords
    }

    /// The platform frame (orientation, origin) at joint values `q`.
    #[must_use]
    pub fn platform_frame(&self, q: &[f64]) -> Displacement {
        let g = self.mechanism.poses(q)[self.platform];
        crate::mechanism::compose(&g, &self.frame)
    }

    /// The joint lock mask of a set of locked actuators (indices into [`Manipulator::actuators`]).
    #[must_use]
    pub fn lock_mask(&self, locked: &[usize]) -> Vec<bool> {
        let mut mask = vec![false; self.mechanism.joints().len()];
        for &a in locked {
            if let Some(act) = self.actuators.get(a) {
                mask[act.joint] = true;
            }
        }
        mask
    }

    /// Parses a set of actuator labels (`P1.3,R2.1`, or `-` for none) into actuator indices.
    ///
    /// # Errors
    /// A label that names no actuator.
    pub fn parse_locks(&self, text: &str) -> Result<Vec<usize>, RequestError> {
        let mut out = Vec::new();
        for label in text
            .split([',', ' '])
            .filter(|s| !s.is_empty() && *s != "-")
        {
            let a = self.actuator_named(label)?;
            if !out.contains(&a) {
                out.push(a);
            }
        }
        out.sort_unstable();
        Ok(out)
    }

    /// The actuator with this label (`P1.3`, any case).
    ///
    /// # Errors
    /// A label that names no actuator; the message lists the actuators.
    pub fn actuator_named(&self, label: &str) -> Result<usize, RequestError> {
        self.actuators
            .iter()
            .position(|a| a.label().eq_ignore_ascii_case(label))
            .ok_or_else(|| RequestError::UnknownActuator {
                label: label.to_string(),
                manipulator: self.name.clone(),
                known: self.actuators.iter().map(Actuator::label).collect(),
            })
    }

    /// Assembles the manipulator with its platform frame at `position` and `orientation`
    /// (rotation vector, radians), starting from the reference configuration, with the `locked`
    /// actuators held.
    ///
    /// # Errors
    /// [`ManipulatorError::Position`] when the loops cannot be closed at that pose.
    pub fn assemble_at(
        &self,
        position: Vector3<f64>,
        orientation: Vector3<f64>,
        locked: &[usize],
    ) -> Result<Vec<f64>, ManipulatorError> {
        let request = PositionRequest {
            platform: Some(PlatformGoal::Pose(crate::spatial::displacement(
                Rotation3::from_scaled_axis(orientation),
                position,
            ))),
            held: locked.to_vec(),
            ..PositionRequest::default()
        };
        Ok(self.solve_position(&self.reference(), &request)?.q)
    }
}

/// The most legs a `/1` description may have (docs/limits.md): twice the six of a Gough–Stewart
/// platform. Analysis time grows with the cube of the number of joints (one SVD of the
/// loop-closure Jacobian per Newton step).
pub const MAX_LEGS: usize = 12;

/// The largest coordinate magnitude accepted (docs/limits.md): far enough from overflow that
/// products and squares of lengths stay exact to round-off.
pub const LARGEST_COORDINATE: f64 = 1e12;

/// The smallest length `kinsyn build` accepts for a radius or height (docs/limits.md).
pub const SMALLEST_LENGTH: f64 = 1e-12;

/// The largest ratio between the lengths of a built geometry (docs/limits.md): beyond it the
/// legs' joint twists differ in size by more than the rank tolerances can tell from round-off.
pub const LARGEST_LENGTH_RATIO: f64 = 1e6;

/// The most moving bodies a `/2` description may have (docs/limits.md): enough for paper 001's
/// HEXA with reconfigurable platforms (19: two parallelogram bars per limb, two sub-platforms,
/// two end-effectors, a four-bar's cranks and coupler). The cost is bounded by [`MAX_JOINTS`].
pub const MAX_BODIES: usize = 24;

/// The most legs a `/2` description may have (docs/limits.md): legs there may be single joints
/// between bodies, so the cost is bounded by [`MAX_JOINTS`] rather than by the legs.
/// 48 leaves room for the HEXA of paper 001 (31 legs, most of them one or two joints).
pub const MAX_LEGS_BETWEEN_BODIES: usize = 48;

/// The most primitive joints a `/2` description may have in all (docs/limits.md): those of
/// [`MAX_LEGS`] legs of six joints, the largest `/1` description.
pub const MAX_JOINTS: usize = 72;
