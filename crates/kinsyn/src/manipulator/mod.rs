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

pub mod build;
pub mod file;
mod jacobian;
pub mod leg;
pub mod lookup;
mod modes;
mod position;
mod request;
mod singularity;

pub use jacobian::{Jacobians, RowKind, WrenchRow};
pub use leg::{LegCheck, LegWarning, LegWarningKind};
pub use lookup::{CatalogueChain, ChainLookup, CommittedChains};
pub use modes::{MAX_INPUTS, Mode, Modes, PatternModes};
pub use position::{CONTINUATION_TRIES, PlatformGoal, Position, PositionRequest};
pub use request::{ContinuationFailure, PositionError, RequestError};
pub use singularity::{
    Analysis, GenericRanks, Singularity, SingularityCause, SingularityKind, rank_text,
};

use crate::chain::Displacement;
use crate::mechanism::{JointSpec, Mechanism, MechanismError};
use crate::notation::{Chain, JointKind, Primitive};
use file::{AxisSpec, Description, DescriptionError, MultibodyDescription};
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
            bodies,
        })
    }

    /// The same manipulator with another moving body as its end-effector (by name): every
    /// analysis of the copy (pose, `--pose`, twist space, dof, motion pattern, modes) is of
    /// that body.
    ///
    /// # Errors
    /// A name that is not a moving body; the message lists them.
    pub fn with_end_effector(&self, name: &str) -> Result<Self, RequestError> {
        let k = self
            .body_named(name)
            .ok_or_else(|| RequestError::UnknownBody {
                name: name.to_string(),
                manipulator: self.name.clone(),
                known: self.bodies.iter().map(|b| b.name.clone()).collect(),
            })?;
        let mut copy = self.clone();
        copy.end_effector = k;
        copy.platform = self.bodies[k].body;
        copy.point = self.bodies[k].point;
        copy.frame = self.bodies[k].frame;
        Ok(copy)
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

fn finite(p: &[f64; 3], field: &str) -> Result<(), DescriptionError> {
    if !p.iter().all(|x| x.is_finite()) {
        Err(DescriptionError::new(field, "not a finite point"))
    } else if p.iter().any(|x| x.abs() > LARGEST_COORDINATE) {
        Err(DescriptionError::new(
            field,
            format!("a coordinate beyond ±{LARGEST_COORDINATE:e}: choose a larger length unit"),
        ))
    } else {
        Ok(())
    }
}

/// The most moving bodies a `/2` description may have (docs/limits.md).
pub const MAX_BODIES: usize = 12;

/// The most legs a `/2` description may have (docs/limits.md): legs there may be single joints
/// between bodies, so the cost is bounded by [`MAX_JOINTS`] rather than by the legs.
pub const MAX_LEGS_BETWEEN_BODIES: usize = 24;

/// The most primitive joints a `/2` description may have in all (docs/limits.md): those of
/// [`MAX_LEGS`] legs of six joints, the largest `/1` description.
pub const MAX_JOINTS: usize = 72;

/// Which format's field names an error uses: a `/1` description is built as its `/2` form, but
/// its errors name the fields the user wrote (`platform.position`, `legs[0].base`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Fields {
    V1,
    V2,
}

impl Fields {
    /// The field of moving body `k` (0-based in `bodies`).
    fn body(self, k: usize, f: &str) -> String {
        match self {
            Fields::V1 => format!("platform.{f}"),
            Fields::V2 => format!("bodies[{k}].{f}"),
        }
    }

    /// The names of a leg's first and last points.
    fn ends(self) -> (&'static str, &'static str) {
        match self {
            Fields::V1 => ("base", "platform"),
            Fields::V2 => ("first", "last"),
        }
    }
}

/// The bodies of a description, checked: their names (the ground first, then the moving bodies
/// in order: the mechanism's first bodies), reference frames (identity for the ground), each
/// leg's two bodies, and the end-effector (an index into the moving bodies).
struct Layout {
    names: Vec<String>,
    frames: Vec<Displacement>,
    ends: Vec<(usize, usize)>,
    end_effector: usize,
}

impl Layout {
    fn new(d: &MultibodyDescription, fields: Fields) -> Result<Self, ManipulatorError> {
        let err = field_error;
        check_sizes(d, fields)?;
        let (names, frames) = body_frames(d, fields)?;
        let ends = leg_ends(d, &names)?;
        check_grounded(d, &names, &ends)?;
        let moving = || names[1..].join(", ");
        let end_effector = match &d.end_effector {
            Some(name) if *name == d.ground => {
                return Err(err(
                    "end_effector".into(),
                    format!("{name:?} is the ground; name a moving body ({})", moving()),
                ));
            }
            Some(name) => d
                .bodies
                .iter()
                .position(|b| b.name == *name)
                .ok_or_else(|| {
                    err(
                        "end_effector".into(),
                        format!(
                            "{name:?} is not a moving body (moving bodies: {})",
                            moving()
                        ),
                    )
                })?,
            None if d.bodies.len() == 1 => 0,
            None => {
                return Err(err(
                    "end_effector".into(),
                    format!(
                        "missing: name the end-effector among the {} moving bodies ({})",
                        d.bodies.len(),
                        moving()
                    ),
                ));
            }
        };
        Ok(Layout {
            names,
            frames,
            ends,
            end_effector,
        })
    }
}

/// An error in the description's `field`.
fn field_error(field: String, message: String) -> ManipulatorError {
    DescriptionError::new(field, message).into()
}

/// Checks the sizes of a description against docs/limits.md: at least one leg, at most
/// [`MAX_LEGS`] legs in a `/1` description or [`MAX_LEGS_BETWEEN_BODIES`] in a `/2` one; at
/// least one moving body and at most [`MAX_BODIES`]; and a named ground.
fn check_sizes(d: &MultibodyDescription, fields: Fields) -> Result<(), ManipulatorError> {
    let err = field_error;
    if d.legs.is_empty() {
        return Err(err(
            "legs".into(),
            "no leg: a manipulator needs at least one".into(),
        ));
    }
    match fields {
        Fields::V1 if d.legs.len() > MAX_LEGS => {
            return Err(err(
                "legs".into(),
                format!(
                    "{} legs: at most {MAX_LEGS} (docs/limits.md; the analysis grows with the cube of the number of joints)",
                    d.legs.len()
                ),
            ));
        }
        Fields::V2 if d.legs.len() > MAX_LEGS_BETWEEN_BODIES => {
            return Err(err(
                "legs".into(),
                format!(
                    "{} legs: at most {MAX_LEGS_BETWEEN_BODIES} (docs/limits.md)",
                    d.legs.len()
                ),
            ));
        }
        _ => {}
    }
    if d.bodies.is_empty() {
        return Err(err(
            "bodies".into(),
            "no moving body: a manipulator needs at least one".into(),
        ));
    }
    if d.bodies.len() > MAX_BODIES {
        return Err(err(
            "bodies".into(),
            format!(
                "{} moving bodies: at most {MAX_BODIES} (docs/limits.md)",
                d.bodies.len()
            ),
        ));
    }
    if d.ground.trim().is_empty() {
        return Err(err("ground".into(), "an empty name".into()));
    }
    Ok(())
}

/// The bodies' names, each its own, and reference frames (the pose of each body's frame in the
/// ground's), the ground first with the identity.
fn body_frames(
    d: &MultibodyDescription,
    fields: Fields,
) -> Result<(Vec<String>, Vec<Displacement>), ManipulatorError> {
    let err = field_error;
    let mut names = vec![d.ground.clone()];
    let mut frames = vec![Displacement::identity()];
    let angle = d.units.angle;
    for (k, b) in d.bodies.iter().enumerate() {
        let field = |f: &str| fields.body(k, f);
        if b.name.trim().is_empty() {
            return Err(err(field("name"), "an empty name".into()));
        }
        if b.name == d.ground {
            return Err(err(
                field("name"),
                format!(
                    "{:?} is the ground's name; every body needs its own",
                    b.name
                ),
            ));
        }
        if let Some(j) = d.bodies[..k].iter().position(|o| o.name == b.name) {
            return Err(err(
                field("name"),
                format!(
                    "{:?} names bodies[{j}] too; every body needs its own name",
                    b.name
                ),
            ));
        }
        finite(&b.position, &field("position"))?;
        finite(&b.orientation, &field("orientation"))?;
        finite(&b.point, &field("point"))?;
        let rotation =
            Rotation3::from_scaled_axis(Vector3::from(b.orientation).map(|a| angle.to_radians(a)));
        names.push(b.name.clone());
        frames.push(crate::spatial::displacement(
            rotation,
            Vector3::from(b.position),
        ));
    }
    Ok((names, frames))
}

/// The two bodies each leg joins (indices into `names`, the ground 0), checked to be bodies
/// and distinct.
fn leg_ends(
    d: &MultibodyDescription,
    names: &[String],
) -> Result<Vec<(usize, usize)>, ManipulatorError> {
    let err = field_error;
    let all = || names.join(", ");
    let mut ends = Vec::with_capacity(d.legs.len());
    for (i, leg) in d.legs.iter().enumerate() {
        let find = |name: &str, f: &str| {
            names.iter().position(|n| n == name).ok_or_else(|| {
                err(
                    format!("legs[{i}].{f}"),
                    format!("{name:?} is not a body (bodies: {})", all()),
                )
            })
        };
        let (from, to) = (find(&leg.from, "from")?, find(&leg.to, "to")?);
        if from == to {
            return Err(err(
                format!("legs[{i}].to"),
                format!(
                    "{:?} again: a leg joins two distinct bodies, and its from is {:?} too",
                    leg.to, leg.from
                ),
            ));
        }
        ends.push((from, to));
    }
    Ok(ends)
}

/// Checks that every moving body is joined to the ground by a chain of legs (the legs' `ends`
/// connect it to body 0), so that nothing floats free of the mechanism.
fn check_grounded(
    d: &MultibodyDescription,
    names: &[String],
    ends: &[(usize, usize)],
) -> Result<(), ManipulatorError> {
    let mut reached = vec![false; names.len()];
    reached[0] = true;
    let mut grew = true;
    while grew {
        grew = false;
        for &(a, b) in ends {
            if reached[a] != reached[b] {
                reached[a] = true;
                reached[b] = true;
                grew = true;
            }
        }
    }
    if let Some(k) = reached.iter().position(|r| !r) {
        return Err(field_error(
            format!("bodies[{}]", k - 1),
            format!(
                "{:?} is joined to the ground {:?} by no chain of legs; every moving body needs one",
                names[k], d.ground
            ),
        ));
    }
    Ok(())
}

/// One leg's geometry at the reference configuration, checked: its chain, primitive joints,
/// one point per joint letter and one unit axis per primitive joint (ground frame), and its
/// actuated primitives.
struct LegGeometry {
    chain: Chain,
    kinds: Vec<Primitive>,
    points: Vec<Vector3<f64>>,
    axes: Vec<Vector3<f64>>,
    actuated: Vec<usize>,
}

impl LegGeometry {
    /// Leg `i` of a description, its first point placed by the frame of its `from` body and
    /// its last point by that of its `to` body (`frames`), catalogue chains resolved through
    /// `lookup`. Errors name the field (`legs[i].axes[2]`) as the format `fields` calls it.
    fn new(
        i: usize,
        spec: &file::LegBetween,
        frames: (&Displacement, &Displacement),
        lookup: &dyn ChainLookup,
        fields: Fields,
    ) -> Result<Self, ManipulatorError> {
        let field = |f: &str| format!("legs[{i}].{f}");
        let (first, last) = fields.ends();
        finite(&spec.first, &field(first))?;
        finite(&spec.last, &field(last))?;
        let (chain, entry_axes) = leg_chain(&spec.chain, spec.axes.is_none(), lookup)
            .map_err(|m| DescriptionError::new(field("chain"), m))?;
        let kinds: Vec<Primitive> = chain.primitives().map(|(p, _)| p).collect();
        let base = frames.0.transform_point(&Point3::from(spec.first)).coords;
        let end = frames.1.transform_point(&Point3::from(spec.last)).coords;
        let points = leg_points(&chain, spec, (&base, &end), &field, fields)?;
        let axes = leg_axes(&chain, spec, entry_axes, (&base, &end), &field, fields)?;
        check_joint_axes(&chain, &axes)
            .map_err(|f| DescriptionError::new(field(&format!("axes[{}]", f.at)), f.why))?;
        leg::check_parallel_marks(&chain, &axes).map_err(|f| {
            DescriptionError::new(field(&format!("axes[{}]", f.at)), f.message(&chain))
        })?;
        let actuated = actuated_positions(&chain, spec.actuated.as_deref())
            .map_err(|m| DescriptionError::new(field("actuated"), m))?;
        Ok(LegGeometry {
            chain,
            kinds,
            points,
            axes,
            actuated,
        })
    }
}

/// One point per joint letter of a leg from `base` to `end` (its first and last points in the
/// ground frame): the description's points between the first and the last, or points evenly
/// spaced on the segment. A one-joint leg must have its two points at the same place.
fn leg_points(
    chain: &Chain,
    spec: &file::LegBetween,
    (base, end): (&Vector3<f64>, &Vector3<f64>),
    field: &dyn Fn(&str) -> String,
    fields: Fields,
) -> Result<Vec<Vector3<f64>>, ManipulatorError> {
    let letters = chain.joints().len();
    let points: Vec<Vector3<f64>> = match &spec.points {
        Some(between) if letters == 1 && between.is_empty() => vec![*base],
        Some(_) if letters == 1 => {
            return Err(DescriptionError::new(
                field("points"),
                format!("{chain} has one joint, so no joint lies between the first and the last; leave points out"),
            )
            .into());
        }
        Some(between) => {
            if between.len() + 2 != letters {
                return Err(DescriptionError::new(
                    field("points"),
                    format!(
                        "{} points for the {} joints of {} between the first and the last (expected {})",
                        between.len(),
                        letters.saturating_sub(2),
                        chain,
                        letters.saturating_sub(2)
                    ),
                )
                .into());
            }
            for (k, p) in between.iter().enumerate() {
                finite(p, &field(&format!("points[{k}]")))?;
            }
            std::iter::once(*base)
                .chain(between.iter().map(|p| Vector3::from(*p)))
                .chain(std::iter::once(*end))
                .collect()
        }
        None if letters == 1 => vec![*base],
        None => (0..letters)
            .map(|k| base + (end - base) * (k as f64 / (letters - 1) as f64))
            .collect(),
    };
    if letters == 1 && (end - base).norm() > 1e-9 * (1.0 + base.norm()) {
        let message = match fields {
            Fields::V1 => format!(
                "the leg {chain} has one joint, so it does not reach the platform point unless base and platform are the same point"
            ),
            Fields::V2 => format!(
                "the leg {chain} has one joint, so its first point (in the frame of {:?}) and its last (in the frame of {:?}) must be the same point at the reference configuration; they are {:.3e} apart",
                spec.from,
                spec.to,
                (end - base).norm()
            ),
        };
        return Err(DescriptionError::new(field(fields.ends().1), message).into());
    }
    Ok(points)
}

/// One unit axis per primitive joint of a leg: the description's, or the catalogue's axis word
/// read in the leg frame from `base` to `end` ([`build::leg_frame`]).
fn leg_axes(
    chain: &Chain,
    spec: &file::LegBetween,
    entry_axes: Option<String>,
    (base, end): (&Vector3<f64>, &Vector3<f64>),
    field: &dyn Fn(&str) -> String,
    fields: Fields,
) -> Result<Vec<Vector3<f64>>, ManipulatorError> {
    let primitives = chain.primitives().count();
    let along = end - base;
    match (&spec.axes, entry_axes) {
        (Some(axes), _) => {
            if axes.len() != primitives {
                return Err(DescriptionError::new(
                    field("axes"),
                    format!(
                        "{} axes for the {} primitive joints of {chain}",
                        axes.len(),
                        primitives
                    ),
                )
                .into());
            }
            Ok(axes
                .iter()
                .enumerate()
                .map(|(k, a)| {
                    axis_vector(a, &along, fields)
                        .map_err(|m| DescriptionError::new(field(&format!("axes[{k}]")), m))
                })
                .collect::<Result<_, _>>()?)
        }
        (None, Some(word)) => {
            let frame = build::leg_frame(base, end);
            let word: crate::notation::AxisWord = word.parse().map_err(|e| {
                DescriptionError::new(field("chain"), format!("the catalogue's axis word {e}"))
            })?;
            Ok(word.axes().map(|a| frame[a.index()]).collect())
        }
        (None, None) => Err(DescriptionError::new(
            field("axes"),
            format!("missing, and {chain} is not a catalogue chain whose axes could be used; give one axis per primitive joint"),
        )
        .into()),
    }
}

/// Bodies and primitive joints gathered leg by leg, then made a [`Mechanism`] with body 0 as
/// the ground.
struct MechanismBuilder {
    bodies: Vec<String>,
    joints: Vec<JointSpec>,
}

impl MechanismBuilder {
    /// The ground body.
    const GROUND: usize = 0;

    /// The named bodies (the ground first), no joint yet.
    fn new(names: &[String]) -> Self {
        MechanismBuilder {
            bodies: names.to_vec(),
            joints: Vec::new(),
        }
    }

    /// Adds a serial leg from body `from` to body `to`: its primitive joints in order, with a
    /// new intermediate body (`leg {number} link {k}`) between consecutive primitives, each
    /// joint at its letter's point. Gives the leg's joints in the mechanism.
    fn add_serial_leg(
        &mut self,
        from: usize,
        to: usize,
        number: usize,
        leg: &LegGeometry,
    ) -> Range<usize> {
        let first = self.joints.len();
        let mut previous = from;
        let mut k = 0;
        for (letter, joint) in leg.chain.joints().iter().enumerate() {
            for _ in joint.kind.primitives() {
                let next = if k + 1 == leg.kinds.len() {
                    to
                } else {
                    self.bodies.push(format!("leg {number} link {}", k + 1));
                    self.bodies.len() - 1
                };
                self.joints.push(JointSpec::new(
                    leg.kinds[k],
                    leg.axes[k],
                    leg.points[letter],
                    previous,
                    next,
                ));
                previous = next;
                k += 1;
            }
        }
        first..self.joints.len()
    }

    /// The mechanism of the bodies and joints added.
    fn build(self) -> Result<Mechanism, MechanismError> {
        let names: Vec<&str> = self.bodies.iter().map(String::as_str).collect();
        Mechanism::new(&names, Self::GROUND, self.joints)
    }
}

/// The chain of a leg (notation or catalogue id), and the catalogue's axis word when the chain
/// is a catalogue chain. The lookup is asked only for an id, or for a notation whose axes are
/// missing (`need_axes`).
pub(crate) fn leg_chain(
    text: &str,
    need_axes: bool,
    lookup: &dyn ChainLookup,
) -> Result<(Chain, Option<String>), String> {
    let bytes = text.trim().as_bytes();
    let looks_like_id = bytes.len() > 3
        && bytes[0].eq_ignore_ascii_case(&b'T')
        && bytes[1].is_ascii_digit()
        && bytes.contains(&b'-');
    if looks_like_id {
        let entry = lookup
            .chain(text)
            .ok_or_else(|| format!("{text:?} is not a catalogue id (see kinsyn catalogue list)"))?;
        let chain: Chain = entry
            .notation
            .parse()
            .map_err(|e| format!("catalogue entry {}: {e}", entry.id))?;
        return Ok((chain, Some(entry.axes.to_owned())));
    }
    let chain: Chain = text.parse().map_err(|e| format!("{text:?}: {e}"))?;
    let axes = if need_axes {
        lookup.chain(text).map(|e| e.axes.to_owned())
    } else {
        None
    };
    Ok((chain, axes))
}

fn axis_vector(a: &AxisSpec, along: &Vector3<f64>, fields: Fields) -> Result<Vector3<f64>, String> {
    let v = match a {
        AxisSpec::Vector(v) => Vector3::from(*v),
        AxisSpec::Named(name) if name == "leg" => {
            if along.norm() < 1e-12 {
                return Err(match fields {
                    Fields::V1 => "'leg' needs the base and platform points apart".into(),
                    Fields::V2 => "'leg' needs the first and last points apart".into(),
                });
            }
            *along
        }
        AxisSpec::Named(name) => {
            return Err(format!(
                "{name:?} is not an axis (a vector [x, y, z] or \"leg\")"
            ));
        }
    };
    let n = v.norm();
    if !n.is_finite() || n < 1e-12 {
        return Err("the axis has no length".into());
    }
    Ok(v / n)
}

/// The actuated primitive joints of a leg (0-based, sorted): the `list` of 1-based positions
/// when given, else the chain's `!` marks. A list and marks must agree.
///
/// # Errors
/// A position outside the chain, a position named twice, or a list that contradicts the marks.
pub(crate) fn actuated_positions(
    chain: &Chain,
    list: Option<&[usize]>,
) -> Result<Vec<usize>, String> {
    let marked: Vec<usize> = chain
        .primitives()
        .enumerate()
        .filter(|(_, (_, m))| m.actuated)
        .map(|(k, _)| k)
        .collect();
    let Some(list) = list else {
        return Ok(marked);
    };
    let primitives = chain.primitives().count();
    let mut positions = Vec::with_capacity(list.len());
    for &p in list {
        if p == 0 || p > primitives {
            return Err(format!(
                "{p} is not a joint of {chain} (joints 1 to {primitives})"
            ));
        }
        if positions.contains(&(p - 1)) {
            return Err(format!("joint {p} named twice"));
        }
        positions.push(p - 1);
    }
    positions.sort_unstable();
    if !marked.is_empty() && marked != positions {
        return Err(format!(
            "disagrees with the '!' marks of {chain}; give one or the other"
        ));
    }
    Ok(positions)
}

/// A joint letter whose axes break its definition.
pub(crate) struct AxisFault {
    /// C, U or S.
    pub letter: char,
    /// The letter's primitive joints (0-based positions in the leg).
    pub primitives: Range<usize>,
    /// The primitive at fault.
    pub at: usize,
    /// What the joint needs.
    pub why: &'static str,
}

/// Checks that the axes of each C, U and S are what the joint means (paper 000 §2: a C's revolute
/// is parallel to its slider; a U's two axes cross; an S's three axes are independent).
pub(crate) fn check_joint_axes(chain: &Chain, axes: &[Vector3<f64>]) -> Result<(), AxisFault> {
    let mut k = 0;
    for joint in chain.joints() {
        let n = joint.kind.primitives().len();
        let a = &axes[k..k + n];
        let fault = match joint.kind {
            JointKind::C if a[0].cross(&a[1]).norm() > AXIS_TOLERANCE => {
                Some((k + 1, "a C joint's revolute must be parallel to its slider"))
            }
            JointKind::U if a[0].cross(&a[1]).norm() < AXIS_TOLERANCE => {
                Some((k + 1, "a U joint's two axes must not be parallel"))
            }
            JointKind::S if a[0].cross(&a[1]).dot(&a[2]).abs() < AXIS_TOLERANCE => {
                Some((k + 2, "an S joint's three axes must be independent"))
            }
            _ => None,
        };
        if let Some((at, why)) = fault {
            return Err(AxisFault {
                letter: joint.kind.letter(),
                primitives: k..k + n,
                at,
                why,
            });
        }
        k += n;
    }
    Ok(())
}
