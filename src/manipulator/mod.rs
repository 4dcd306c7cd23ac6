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
mod singularity;

pub use jacobian::{Jacobians, RowKind, WrenchRow};
pub use leg::{LegCheck, LegWarning, LegWarningKind};
pub use lookup::{CatalogueChain, ChainLookup, CommittedChains};
pub use modes::{MAX_INPUTS, Mode, Modes, PatternModes};
pub use position::{PlatformGoal, Position, PositionRequest};
pub use singularity::{Analysis, GenericRanks, Singularity, SingularityKind, rank_text};

use crate::chain::Displacement;
use crate::mechanism::{JointSpec, Mechanism, MechanismError};
use crate::notation::{Chain, JointKind, Primitive};
use file::{AxisSpec, Description, DescriptionError};
use nalgebra::{Point3, Rotation3, Vector3};
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
    /// A pose that the manipulator cannot reach.
    #[error("{0}")]
    Pose(String),
}

/// One leg of a manipulator.
#[derive(Debug, Clone, PartialEq)]
pub struct Leg {
    /// The chain as read (with its actuation marks).
    pub chain: Chain,
    /// The leg's primitive joints in the mechanism, base to platform.
    pub joints: Range<usize>,
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

/// A parallel manipulator: legs from the ground to one platform, with actuated joints.
#[derive(Debug, Clone)]
pub struct Manipulator {
    name: String,
    units: file::Units,
    mechanism: Mechanism,
    legs: Vec<Leg>,
    actuators: Vec<Actuator>,
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
    /// Reads and builds a manipulator from the JSON text of a description file.
    ///
    /// # Errors
    /// See [`Description::from_json`] and [`Manipulator::new`].
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
        Self::new(&Description::from_json(text)?)
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
    /// whose axes are left out) through `lookup`.
    ///
    /// # Errors
    /// A chain that does not parse or an unknown catalogue id, axes or points in the wrong
    /// number, axes of no length, joints whose axes break the joint's definition (a C whose
    /// revolute is not parallel to its slider, a U with parallel axes, an S with dependent
    /// axes), revolutes of one parallel group (`Ra…Ra`) whose axes are not parallel, a one-joint leg whose base and platform points differ, actuated positions out of
    /// range, or no leg at all. Each error names its field.
    pub fn new_with(d: &Description, lookup: &dyn ChainLookup) -> Result<Self, ManipulatorError> {
        let frame = platform_frame(d)?;
        let mut builder = MechanismBuilder::new();
        let mut legs = Vec::new();
        let mut actuators = Vec::new();
        for (i, spec) in d.legs.iter().enumerate() {
            let geometry = LegGeometry::new(i, spec, &frame, lookup)?;
            let joints =
                builder.add_serial_leg(MechanismBuilder::GROUND, PLATFORM, i + 1, &geometry);
            actuators.extend(geometry.actuated.iter().map(|&p| Actuator {
                leg: i,
                position: p,
                joint: joints.start + p,
                kind: geometry.kinds[p],
            }));
            legs.push(Leg {
                chain: geometry.chain,
                joints,
            });
        }
        Ok(Manipulator {
            name: d.name.clone(),
            units: d.units.clone(),
            mechanism: builder.build()?,
            legs,
            actuators,
            platform: PLATFORM,
            point: frame
                .transform_point(&Point3::from(d.platform.point))
                .coords,
            frame,
        })
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

    /// The platform body.
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
    pub fn parse_locks(&self, text: &str) -> Result<Vec<usize>, String> {
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
    pub fn actuator_named(&self, label: &str) -> Result<usize, String> {
        self.actuators
            .iter()
            .position(|a| a.label().eq_ignore_ascii_case(label))
            .ok_or_else(|| {
                let all: Vec<String> = self.actuators.iter().map(Actuator::label).collect();
                format!(
                    "{label:?} is not an actuator of {} (actuators: {})",
                    self.name,
                    all.join(" ")
                )
            })
    }

    /// Assembles the manipulator with its platform frame at `position` and `orientation`
    /// (rotation vector, radians), starting from the reference configuration, with the `locked`
    /// actuators held.
    ///
    /// # Errors
    /// [`ManipulatorError::Pose`] when the loops cannot be closed at that pose.
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

/// The most legs a description may have (docs/limits.md): twice the six of a Gough–Stewart
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

/// The platform body of a manipulator's mechanism (the ground is body 0).
const PLATFORM: usize = 1;

/// Checks the description's leg count and platform fields, and gives the platform frame at the
/// reference configuration (ground frame).
fn platform_frame(d: &Description) -> Result<Displacement, ManipulatorError> {
    if d.legs.is_empty() {
        return Err(
            DescriptionError::new("legs", "no leg: a manipulator needs at least one").into(),
        );
    }
    if d.legs.len() > MAX_LEGS {
        return Err(DescriptionError::new(
            "legs",
            format!(
                "{} legs: at most {MAX_LEGS} (docs/limits.md; the analysis grows with the cube of the number of joints)",
                d.legs.len()
            ),
        )
        .into());
    }
    let angle = d.units.angle;
    finite(&d.platform.position, "platform.position")?;
    finite(&d.platform.orientation, "platform.orientation")?;
    finite(&d.platform.point, "platform.point")?;
    let rotation = Rotation3::from_scaled_axis(
        Vector3::from(d.platform.orientation).map(|a| angle.to_radians(a)),
    );
    Ok(crate::spatial::displacement(
        rotation,
        Vector3::from(d.platform.position),
    ))
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
    /// Leg `i` of a description, its platform point placed by the platform `frame`, catalogue
    /// chains resolved through `lookup`. Errors name the field (`legs[i].axes[2]`).
    fn new(
        i: usize,
        spec: &file::LegSpec,
        frame: &Displacement,
        lookup: &dyn ChainLookup,
    ) -> Result<Self, ManipulatorError> {
        let field = |f: &str| format!("legs[{i}].{f}");
        finite(&spec.base, &field("base"))?;
        finite(&spec.platform, &field("platform"))?;
        let (chain, entry_axes) = leg_chain(&spec.chain, spec.axes.is_none(), lookup)
            .map_err(|m| DescriptionError::new(field("chain"), m))?;
        let kinds: Vec<Primitive> = chain.primitives().map(|(p, _)| p).collect();
        let base = Vector3::from(spec.base);
        let end = frame.transform_point(&Point3::from(spec.platform)).coords;
        let points = leg_points(&chain, spec, &base, &end, &field)?;
        let axes = leg_axes(&chain, spec, entry_axes, &base, &end, &field)?;
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

/// One point per joint letter of a leg from `base` to `end`: the description's points between
/// the first and the last, or points evenly spaced on the segment. A one-joint leg must have
/// its base and platform points at the same place.
fn leg_points(
    chain: &Chain,
    spec: &file::LegSpec,
    base: &Vector3<f64>,
    end: &Vector3<f64>,
    field: &dyn Fn(&str) -> String,
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
        return Err(DescriptionError::new(
            field("platform"),
            format!("the leg {chain} has one joint, so it does not reach the platform point unless base and platform are the same point"),
        )
        .into());
    }
    Ok(points)
}

/// One unit axis per primitive joint of a leg: the description's, or the catalogue's axis word
/// read in the leg frame from `base` to `end` ([`build::leg_frame`]).
fn leg_axes(
    chain: &Chain,
    spec: &file::LegSpec,
    entry_axes: Option<String>,
    base: &Vector3<f64>,
    end: &Vector3<f64>,
    field: &dyn Fn(&str) -> String,
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
                    axis_vector(a, &along)
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

    /// The ground and the platform, no joint yet.
    fn new() -> Self {
        MechanismBuilder {
            bodies: vec!["ground".into(), "platform".into()],
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

fn axis_vector(a: &AxisSpec, along: &Vector3<f64>) -> Result<Vector3<f64>, String> {
    let v = match a {
        AxisSpec::Vector(v) => Vector3::from(*v),
        AxisSpec::Named(name) if name == "leg" => {
            if along.norm() < 1e-12 {
                return Err("'leg' needs the base and platform points apart".into());
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
