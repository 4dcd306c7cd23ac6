//! From a description to a manipulator: the checks of a `/2` description (sizes, names, body
//! frames, legs between known bodies, every body joined to the ground), each leg's joint points
//! and axes with the C, U, S and parallel-group rules (paper 000 §2), its actuated joints, and
//! the mechanism built leg by leg ([`MechanismBuilder::add_serial_leg`]).

use super::file::{self, AxisSpec, DescriptionError, MultibodyDescription};
use super::lookup::ChainLookup;
use super::{
    AXIS_TOLERANCE, LARGEST_COORDINATE, MAX_BODIES, MAX_LEGS, MAX_LEGS_BETWEEN_BODIES,
    ManipulatorError, build, leg,
};
use crate::chain::Displacement;
use crate::mechanism::{JointSpec, Mechanism, MechanismError};
use crate::notation::{Chain, JointKind, Primitive};
use nalgebra::{Point3, Rotation3, Vector3};
use std::ops::Range;

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

/// Which format's field names an error uses: a `/1` description is built as its `/2` form, but
/// its errors name the fields the user wrote (`platform.position`, `legs[0].base`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Fields {
    V1,
    V2,
}

impl Fields {
    /// The field of moving body `k` (0-based in `bodies`).
    pub(super) fn body(self, k: usize, f: &str) -> String {
        match self {
            Fields::V1 => format!("platform.{f}"),
            Fields::V2 => format!("bodies[{k}].{f}"),
        }
    }

    /// The names of a leg's first and last points.
    pub(super) fn ends(self) -> (&'static str, &'static str) {
        match self {
            Fields::V1 => ("base", "platform"),
            Fields::V2 => ("first", "last"),
        }
    }
}

/// The bodies of a description, checked: their names (the ground first, then the moving bodies
/// in order: the mechanism's first bodies), reference frames (identity for the ground), each
/// leg's two bodies, and the end-effector (an index into the moving bodies).
pub(super) struct Layout {
    pub(super) names: Vec<String>,
    pub(super) frames: Vec<Displacement>,
    pub(super) ends: Vec<(usize, usize)>,
    pub(super) end_effector: usize,
}

impl Layout {
    pub(super) fn new(d: &MultibodyDescription, fields: Fields) -> Result<Self, ManipulatorError> {
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
pub(super) struct LegGeometry {
    pub(super) chain: Chain,
    pub(super) kinds: Vec<Primitive>,
    pub(super) points: Vec<Vector3<f64>>,
    pub(super) axes: Vec<Vector3<f64>>,
    pub(super) actuated: Vec<usize>,
}

impl LegGeometry {
    /// Leg `i` of a description, its first point placed by the frame of its `from` body and
    /// its last point by that of its `to` body (`frames`), catalogue chains resolved through
    /// `lookup`. Errors name the field (`legs[i].axes[2]`) as the format `fields` calls it.
    pub(super) fn new(
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
pub(super) struct MechanismBuilder {
    pub(super) bodies: Vec<String>,
    pub(super) joints: Vec<JointSpec>,
}

impl MechanismBuilder {
    /// The ground body.
    pub(super) const GROUND: usize = 0;

    /// The named bodies (the ground first), no joint yet.
    pub(super) fn new(names: &[String]) -> Self {
        MechanismBuilder {
            bodies: names.to_vec(),
            joints: Vec::new(),
        }
    }

    /// Adds a serial leg from body `from` to body `to`: its primitive joints in order, with a
    /// new intermediate body (`leg {number} link {k}`) between consecutive primitives, each
    /// joint at its letter's point. Gives the leg's joints in the mechanism.
    pub(super) fn add_serial_leg(
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
    pub(super) fn build(self) -> Result<Mechanism, MechanismError> {
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
