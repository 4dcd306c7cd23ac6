//! From a leg chain to a manipulator: a symmetric geometry in which any catalogue chain can be
//! tried as a leg (`kinsyn build`).
//!
//! The legs stand on a base circle and reach a platform circle above it, one every `360°/n`,
//! so they lie in different planes as paper 000 §3 asks for rigidity. Each leg has its own
//! **leg frame**: `z` along the leg (base point to platform point), `y` horizontal and
//! perpendicular to it, `x = y × z`. The catalogue's axis letters x, y, z are read in that frame,
//! so the UPS entry (`xyzxyz`) gets its slider along the leg, its U's second axis horizontal
//! (the R of the 3-RPS when the first is locked) and its first in the leg's vertical plane.
//! Joints between the first and the last are spaced evenly along the leg and pushed off it by
//! 0.15 of its length, the m-th towards the angle m·ψ (ψ the golden angle) in the leg frame's
//! xy plane, so that the joint points of a leg are not coplanar and parallel revolutes are not
//! coaxial. Every leg is then checked as the file will hold it ([`super::leg::LegCheck`]):
//! when its joints are dependent at every configuration, `build` fails; when the reference is a
//! leg singularity (the rank of its joint twists there is below that at generic joint values,
//! e.g. two guides parallel), the directions are replaced by those after every revolute has
//! turned by a fixed angle, and kept only if they changed and the leg is then generic (the file's
//! `source` says so, with the ranks found); otherwise `build` fails, naming the leg, its ranks
//! and its dependent joints. Turning cannot help when every revolute turns about the direction
//! of the axes at fault: `--chain CRR --axes zzzz` puts the C's revolute (at the base point)
//! and the last R (at the platform point) on the leg line, coaxial, every axis stays z, and it
//! is refused.

use super::file::{AngleUnit, AxisSpec, Description, FORMAT, LegSpec, PlatformSpec, Units};
use super::leg::LegCheck;
use super::lookup::ChainLookup as _;
use crate::chain::SerialChain;
use crate::notation::{Chain, Primitive};
use nalgebra::Vector3;
use serde::Serialize;
use std::fmt::Write as _;

/// The geometry and legs asked for.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BuildSpec {
    /// Number of legs (3 to 6, paper 000 §3).
    pub legs: usize,
    /// The leg chain: notation (with `!` marks) or a catalogue id.
    pub chain: String,
    /// Axis letters x, y, z per primitive joint in the leg frame; default the catalogue's.
    pub axes: Option<String>,
    /// Actuated primitive joints (1-based) instead of `!` marks.
    pub actuated: Option<Vec<usize>>,
    /// Radius of the circle of base points.
    pub base_radius: f64,
    /// Radius of the circle of platform points.
    pub platform_radius: f64,
    /// Height of the platform above the base.
    pub height: f64,
    /// Angle (degrees) by which each leg's platform point is turned from its base point about
    /// the vertical.
    pub twist: f64,
    /// Turn the platform points of legs 2, 4, 6 the other way (−twist): with an even number of
    /// legs this pairs the platform points, as in the usual Gough–Stewart platform, whose
    /// regular-hexagon form is singular everywhere.
    pub alternate: bool,
    /// The manipulator's name (default `n-CHAIN`).
    pub name: Option<String>,
}

impl Default for BuildSpec {
    fn default() -> Self {
        BuildSpec {
            legs: 3,
            chain: String::new(),
            axes: None,
            actuated: None,
            base_radius: 1.0,
            platform_radius: 0.5,
            height: 1.0,
            twist: 0.0,
            alternate: false,
            name: None,
        }
    }
}

/// The leg frame `[x, y, z]` of a leg from `base` to `end` (see the module documentation).
#[must_use]
pub fn leg_frame(base: &Vector3<f64>, end: &Vector3<f64>) -> [Vector3<f64>; 3] {
    let z = (end - base).try_normalize(1e-12).unwrap_or_else(Vector3::z);
    let y = Vector3::z()
        .cross(&z)
        .try_normalize(1e-9)
        .unwrap_or_else(|| {
            // A vertical leg: the horizontal direction perpendicular to the base point's radius.
            Vector3::z()
                .cross(base)
                .try_normalize(1e-9)
                .unwrap_or_else(Vector3::y)
        });
    [y.cross(&z), y, z]
}

/// The joint directions of the leg after every revolute turned by `0.6 + 0.25 k` radians (k its
/// index), joint points kept: the same chain at a configuration where no two axes are aligned by
/// accident.
fn turned(chain: &Chain, axes: &[Vector3<f64>], points: &[Vector3<f64>]) -> Vec<Vector3<f64>> {
    let Some(leg) = leg_chain(chain, axes, points) else {
        return axes.to_vec();
    };
    let q: Vec<f64> = leg
        .joints()
        .iter()
        .enumerate()
        .map(|(k, j)| match j.kind {
            Primitive::R => 0.6 + 0.25 * k as f64,
            Primitive::P => 0.0,
        })
        .collect();
    let j = leg.jacobian(&q);
    leg.joints()
        .iter()
        .enumerate()
        .map(|(k, joint)| {
            let row = if joint.kind == Primitive::R { 0 } else { 3 };
            Vector3::new(j[(row, k)], j[(row + 1, k)], j[(row + 2, k)]).normalize()
        })
        .collect()
}

/// The leg as a serial chain: each primitive with its axis and its letter's point.
fn leg_chain(chain: &Chain, axes: &[Vector3<f64>], points: &[Vector3<f64>]) -> Option<SerialChain> {
    let mut joints = Vec::with_capacity(axes.len());
    let mut k = 0;
    for (letter, joint) in chain.joints().iter().enumerate() {
        for &kind in joint.kind.primitives() {
            joints.push((kind, *axes.get(k)?, *points.get(letter)?));
            k += 1;
        }
    }
    SerialChain::new(joints).ok()
}

/// The primitive joints `(kind, axis, point)` of a leg as the file will hold them (rounded by
/// [`tidy`]), each with its letter's point.
fn leg_primitives(
    chain: &Chain,
    axes: &[Vector3<f64>],
    points: &[Vector3<f64>],
) -> Vec<(Primitive, Vector3<f64>, Vector3<f64>)> {
    let mut out = Vec::with_capacity(axes.len());
    let mut k = 0;
    for (letter, joint) in chain.joints().iter().enumerate() {
        for &kind in joint.kind.primitives() {
            out.push((
                kind,
                Vector3::from(tidy(axes[k])).normalize(),
                Vector3::from(tidy(points[letter])),
            ));
            k += 1;
        }
    }
    out
}

/// The golden angle, 2π(1 − 1/φ): successive multiples never line up.
const GOLDEN_ANGLE: f64 = 2.399_963_229_728_653;

/// A field of [`BuildSpec`], as named in [`BuildError`] messages: the library says
/// `base_radius`, a front end names its own option (the CLI's `--base-radius`) through
/// [`BuildError::describe`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BuildField {
    /// [`BuildSpec::legs`].
    Legs,
    /// [`BuildSpec::chain`].
    Chain,
    /// [`BuildSpec::axes`].
    Axes,
    /// [`BuildSpec::actuated`].
    Actuated,
    /// [`BuildSpec::base_radius`].
    BaseRadius,
    /// [`BuildSpec::platform_radius`].
    PlatformRadius,
    /// [`BuildSpec::height`].
    Height,
    /// [`BuildSpec::twist`].
    Twist,
}

impl BuildField {
    /// The field's name in [`BuildSpec`].
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            BuildField::Legs => "legs",
            BuildField::Chain => "chain",
            BuildField::Axes => "axes",
            BuildField::Actuated => "actuated",
            BuildField::BaseRadius => "base_radius",
            BuildField::PlatformRadius => "platform_radius",
            BuildField::Height => "height",
            BuildField::Twist => "twist",
        }
    }
}

/// Why [`build`] made no description: the spec's fields, or a leg that the symmetric geometry
/// cannot make generic. Each variant names the fields at fault ([`BuildError::fields`]).
#[derive(Debug, Clone, PartialEq)]
pub enum BuildError {
    /// Not 3 to 6 legs (paper 000 §3).
    Legs(usize),
    /// A radius or the height is not a positive number.
    NotPositive(BuildField, f64),
    /// A radius or the height is outside the lengths kinsyn computes with (docs/limits.md).
    LengthOutOfRange(BuildField, f64),
    /// The largest of the radii and height is too many times the smallest (docs/limits.md).
    LengthRatio {
        /// [`BuildSpec::base_radius`].
        base_radius: f64,
        /// [`BuildSpec::platform_radius`].
        platform_radius: f64,
        /// [`BuildSpec::height`].
        height: f64,
        /// Largest over smallest.
        ratio: f64,
    },
    /// The twist is not an angle within ±360°.
    Twist(f64),
    /// The chain does not parse, or is an unknown catalogue id.
    Chain(String),
    /// The chain is not in the catalogue and no axes were given.
    AxesNeeded {
        /// The chain.
        chain: String,
    },
    /// The axis word has the wrong length or letters.
    AxesWord {
        /// The axis word given.
        axes: String,
        /// The chain.
        chain: String,
        /// Its number of primitive joints.
        primitives: usize,
    },
    /// The axis letters break a C, U or S (paper 000 §2).
    JointAxes {
        /// The axis word given.
        axes: String,
        /// C, U or S.
        letter: char,
        /// Its first primitive joint (1-based).
        first: usize,
        /// Its last primitive joint (1-based).
        last: usize,
        /// What the joint needs.
        why: &'static str,
    },
    /// Two joints of one parallel group get letters that are not parallel.
    ParallelGroup {
        /// The axis word given.
        axes: String,
        /// The chain.
        chain: String,
        /// The group's mark.
        group: char,
        /// The group's first joint (1-based).
        first: usize,
        /// The joint whose letter differs (1-based).
        at: usize,
    },
    /// The actuated list is not a set of joints of the chain consistent with its marks.
    Actuated(String),
    /// No joint is actuated.
    NoActuated {
        /// The chain's number of primitive joints.
        primitives: usize,
    },
    /// A leg is not generic in this geometry and turning its axes did not help.
    Refused {
        /// The chain as given.
        chain: String,
        /// The axis word.
        axes: String,
        /// What the leg check found.
        warning: String,
        /// Why turning the axes does not help.
        why: String,
    },
}

impl BuildError {
    /// The spec fields the error is about, in the order its message names them.
    #[must_use]
    pub fn fields(&self) -> Vec<BuildField> {
        use BuildField as F;
        match self {
            BuildError::Legs(_) => vec![F::Legs],
            BuildError::NotPositive(f, _) | BuildError::LengthOutOfRange(f, _) => vec![*f],
            BuildError::LengthRatio { .. } => vec![F::BaseRadius, F::PlatformRadius, F::Height],
            BuildError::Twist(_) => vec![F::Twist],
            BuildError::Chain(_) => vec![F::Chain],
            BuildError::AxesNeeded { .. }
            | BuildError::AxesWord { .. }
            | BuildError::JointAxes { .. }
            | BuildError::ParallelGroup { .. } => vec![F::Axes],
            BuildError::Actuated(_) | BuildError::NoActuated { .. } => vec![F::Actuated],
            BuildError::Refused { .. } => vec![F::Chain, F::Axes],
        }
    }

    /// The message with each field called `name(field)`: the [`Display`](std::fmt::Display)
    /// form uses the spec's field names, a front end its own option names.
    pub fn describe(&self, name: impl Fn(BuildField) -> String) -> String {
        use BuildField as F;
        match self {
            BuildError::Legs(n) => format!(
                "{} {n}: paper 000 §3 builds manipulators of three to six legs",
                name(F::Legs)
            ),
            BuildError::NotPositive(f, x) => format!("{} {x}: must be a positive length", name(*f)),
            BuildError::LengthOutOfRange(f, x) => format!(
                "{} {x:e}: lengths are between {:e} and {:e} (docs/limits.md); choose another length unit",
                name(*f),
                super::SMALLEST_LENGTH,
                super::LARGEST_COORDINATE
            ),
            BuildError::LengthRatio {
                base_radius,
                platform_radius,
                height,
                ratio,
            } => format!(
                "{} {base_radius}, {} {platform_radius}, {} {height}: the largest is {ratio:.1e} times the smallest; at most {:e} (docs/limits.md), beyond which the legs' ranks are round-off",
                name(F::BaseRadius),
                name(F::PlatformRadius),
                name(F::Height),
                super::LARGEST_LENGTH_RATIO
            ),
            BuildError::Twist(t) => {
                format!("{} {t}: degrees between -360 and 360", name(F::Twist))
            }
            BuildError::Chain(m) => m.clone(),
            BuildError::AxesNeeded { chain } => format!(
                "{chain} is not a catalogue chain; give its axes with {} (one of x, y, z per primitive joint, in the leg frame)",
                name(F::Axes)
            ),
            BuildError::AxesWord {
                axes,
                chain,
                primitives,
            } => format!(
                "{} {axes:?}: one letter x, y or z per primitive joint of {chain} ({primitives})",
                name(F::Axes)
            ),
            BuildError::JointAxes {
                axes,
                letter,
                first,
                last,
                why,
            } => format!(
                "{} {axes:?}: the {letter} at joints {first}–{last} ('{}'): {why}",
                name(F::Axes),
                axes.get(first - 1..*last).unwrap_or_default()
            ),
            BuildError::ParallelGroup {
                axes,
                chain,
                group,
                first,
                at,
            } => format!(
                "{} {axes:?}: joints {first} and {at} of {chain} are in parallel group '{group}' but get '{}' and '{}': the axes of a parallel group must be parallel",
                name(F::Axes),
                axes.get(first - 1..*first).unwrap_or_default(),
                axes.get(at - 1..*at).unwrap_or_default()
            ),
            BuildError::Actuated(m) => format!("{}: {m}", name(F::Actuated)),
            BuildError::NoActuated { primitives } => format!(
                "no actuated joint: mark them with '!' in the chain or give {} (1 to {primitives})",
                name(F::Actuated)
            ),
            BuildError::Refused {
                chain,
                axes,
                warning,
                why,
            } => format!(
                "{} {chain:?} {} {axes}: {warning}; {why}, so no file is written",
                name(F::Chain),
                name(F::Axes)
            ),
        }
    }
}

impl std::fmt::Display for BuildError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.describe(|field| field.name().to_string()))
    }
}

impl std::error::Error for BuildError {}

/// Rounds to 12 decimals so that written files do not carry round-off digits.
fn tidy(v: Vector3<f64>) -> [f64; 3] {
    v.map(|x| (x * 1e12).round() / 1e12 + 0.0).into()
}

/// A manipulator description with the symmetric geometry of the module documentation.
///
/// # Errors
/// A number of legs outside 3–6, a chain that does not parse or is not in the catalogue when
/// its axes are needed, an axis word of the wrong length or letters, no actuated joint, or
/// geometry numbers that are not positive.
pub fn build(spec: &BuildSpec) -> Result<Description, BuildError> {
    check_geometry(spec)?;
    let lookup = super::CommittedChains::get();
    let (chain, axes, actuated) = leg_chain_and_axes(spec, lookup)?;
    let plain: Chain = chain.without_actuation();
    let n = spec.legs;
    let mut legs = Vec::with_capacity(n);
    // The ranks and dependent joints of the first leg whose axes had to be turned.
    let mut turned_note: Option<TurnedNote> = None;
    for k in 0..n {
        let (leg, note) = symmetric_leg(spec, k, &plain, &axes, &actuated)?;
        legs.push(leg);
        if turned_note.is_none() {
            turned_note = note;
        }
    }
    let name = spec
        .name
        .clone()
        .unwrap_or_else(|| format!("{n}-{}", plain.letters()));
    let source = source_text(spec, lookup, &axes, &actuated, &name, turned_note.as_ref());
    Ok(Description {
        format: FORMAT.into(),
        name,
        source: Some(source),
        units: Units {
            length: "m".into(),
            angle: AngleUnit::Deg,
        },
        platform: PlatformSpec {
            position: [0.0, 0.0, spec.height],
            orientation: [0.0; 3],
            point: [0.0; 3],
        },
        legs,
    })
}

/// Checks the numbers of the symmetric geometry: 3 to 6 legs, lengths kinsyn computes with
/// (docs/limits.md), and a twist within ±360°.
fn check_geometry(spec: &BuildSpec) -> Result<(), BuildError> {
    if !(3..=6).contains(&spec.legs) {
        return Err(BuildError::Legs(spec.legs));
    }
    for (name, x) in [
        (BuildField::BaseRadius, spec.base_radius),
        (BuildField::PlatformRadius, spec.platform_radius),
        (BuildField::Height, spec.height),
    ] {
        if !(x.is_finite() && x > 0.0) {
            return Err(BuildError::NotPositive(name, x));
        }
        if !(super::SMALLEST_LENGTH..=super::LARGEST_COORDINATE).contains(&x) {
            return Err(BuildError::LengthOutOfRange(name, x));
        }
    }
    let lengths = [spec.base_radius, spec.platform_radius, spec.height];
    let ratio = lengths.iter().copied().fold(0.0, f64::max)
        / lengths.iter().copied().fold(f64::INFINITY, f64::min);
    if ratio > super::LARGEST_LENGTH_RATIO {
        return Err(BuildError::LengthRatio {
            base_radius: spec.base_radius,
            platform_radius: spec.platform_radius,
            height: spec.height,
            ratio,
        });
    }
    if !spec.twist.is_finite() || spec.twist.abs() > 360.0 {
        return Err(BuildError::Twist(spec.twist));
    }
    Ok(())
}

/// The leg chain, its axis word (given, or the catalogue's) checked against the chain's C, U, S
/// and parallel groups, and its actuated joints (1-based).
fn leg_chain_and_axes(
    spec: &BuildSpec,
    lookup: &super::CommittedChains,
) -> Result<(Chain, String, Vec<usize>), BuildError> {
    let (chain, entry_axes) =
        super::leg_chain(&spec.chain, spec.axes.is_none(), lookup).map_err(BuildError::Chain)?;
    let primitives = chain.primitives().count();
    let axes = match (&spec.axes, entry_axes) {
        (Some(word), _) => word.clone(),
        (None, Some(word)) => word,
        (None, None) => {
            return Err(BuildError::AxesNeeded {
                chain: chain.to_string(),
            });
        }
    };
    if axes.len() != primitives || !axes.bytes().all(|b| matches!(b, b'x' | b'y' | b'z')) {
        return Err(BuildError::AxesWord {
            axes,
            chain: chain.to_string(),
            primitives,
        });
    }
    // Each C, U and S must get directions that keep it that joint (paper 000 §2); the letters
    // are checked as the unit vectors they stand for.
    let letter_vectors: Vec<Vector3<f64>> = axes
        .chars()
        .filter_map(crate::notation::Axis::from_letter)
        .map(crate::notation::Axis::unit)
        .collect();
    super::check_joint_axes(&chain, &letter_vectors).map_err(|f| BuildError::JointAxes {
        axes: axes.clone(),
        letter: f.letter,
        first: f.primitives.start + 1,
        last: f.primitives.end,
        why: f.why,
    })?;
    super::leg::check_parallel_marks(&chain, &letter_vectors).map_err(|f| {
        BuildError::ParallelGroup {
            axes: axes.clone(),
            chain: chain.to_string(),
            group: f.group,
            first: f.first + 1,
            at: f.at + 1,
        }
    })?;
    let actuated: Vec<usize> = super::actuated_positions(&chain, spec.actuated.as_deref())
        .map_err(BuildError::Actuated)?
        .into_iter()
        .map(|p| p + 1)
        .collect();
    if actuated.is_empty() {
        return Err(BuildError::NoActuated { primitives });
    }
    Ok((chain, axes, actuated))
}

/// Why a leg's axes were turned: its joint-twist rank at the reference and at generic joint
/// values, and its joints dependent at the reference.
struct TurnedNote {
    rank: usize,
    generic: usize,
    dependent: Vec<usize>,
}

/// Leg `k` of the symmetric geometry (0-based): its joint points and axis directions in the
/// ground frame, checked generic as the file will hold it, with its axes turned when the aligned
/// directions are a singular configuration of the chain (and why).
fn symmetric_leg(
    spec: &BuildSpec,
    k: usize,
    plain: &Chain,
    axes: &str,
    actuated: &[usize],
) -> Result<(LegSpec, Option<TurnedNote>), BuildError> {
    let n = spec.legs;
    let letters = plain.joints().len();
    let theta = std::f64::consts::TAU * k as f64 / n as f64;
    let sense = if spec.alternate && k % 2 == 1 {
        -1.0
    } else {
        1.0
    };
    let phi = theta + sense * spec.twist.to_radians();
    let base = Vector3::new(theta.cos(), theta.sin(), 0.0) * spec.base_radius;
    let attach = Vector3::new(phi.cos(), phi.sin(), 0.0) * spec.platform_radius;
    let end = attach + Vector3::new(0.0, 0.0, spec.height);
    let frame = leg_frame(&base, &end);
    let length = (end - base).norm();
    // Letter m is pushed off the leg line by 0.15 of its length towards the angle m·ψ
    // (ψ the golden angle) in the leg frame's xy plane: the points do not lie in one plane.
    let off = |m: f64| {
        let a = m * GOLDEN_ANGLE;
        (frame[0] * a.cos() + frame[1] * a.sin()) * (0.15 * length)
    };
    let mut note = None;
    let mut axis_vectors: Vec<Vector3<f64>> = axes
        .chars()
        .filter_map(crate::notation::Axis::from_letter)
        .map(|a| frame[a.index()])
        .collect();
    let points: Vec<Vector3<f64>> = (0..letters)
        .map(|m| match m {
            0 => base,
            _ if m + 1 == letters => end,
            _ => base + (end - base) * (m as f64 / (letters - 1) as f64) + off(m as f64),
        })
        .collect();
    // The leg as it will be written (rounded as in the file) must be generic at the
    // reference: its joint twists of full generic rank, and that rank reached there.
    let check = |axis_vectors: &[Vector3<f64>]| {
        let joints = leg_primitives(plain, axis_vectors, &points);
        LegCheck::standalone(k, plain, &joints)
    };
    let sound = |c: &LegCheck| !c.is_singular() && !c.has_dependent_joints();
    let found = check(&axis_vectors);
    if !sound(&found) {
        let warning = found
            .warnings()
            .first()
            .map(ToString::to_string)
            .unwrap_or_default();
        let refused = |why: &str| BuildError::Refused {
            chain: spec.chain.trim().to_string(),
            axes: axes.to_string(),
            warning: warning.clone(),
            why: why.to_string(),
        };
        if found.has_dependent_joints() {
            return Err(refused(
                "turning the axes cannot remove a dependency that holds at every configuration",
            ));
        }
        // The aligned directions are a singular configuration of this chain (e.g. two
        // guides parallel there): take the directions the joints have after every revolute
        // turned by a fixed angle; parallel groups stay parallel (paper 000 §2). Kept only
        // when the directions changed and the leg is then generic.
        let turned_vectors = turned(plain, &axis_vectors, &points);
        let changed = turned_vectors
            .iter()
            .zip(&axis_vectors)
            .any(|(a, b)| a.cross(b).norm() > super::AXIS_TOLERANCE);
        if !changed {
            return Err(refused(
                "turning its revolutes leaves these axis directions unchanged",
            ));
        }
        let valid = super::check_joint_axes(plain, &turned_vectors).is_ok()
            && super::leg::check_parallel_marks(plain, &turned_vectors).is_ok();
        let after = check(&turned_vectors);
        if !valid || !sound(&after) {
            return Err(refused(&format!(
                "with its revolutes turned it is still not generic (rank {} of {} joints, {} at generic joint values)",
                after.reference.rank, after.joints, after.generic.rank
            )));
        }
        note = Some(TurnedNote {
            rank: found.reference.rank,
            generic: found.generic.rank,
            dependent: found.dependent_at_reference.clone(),
        });
        axis_vectors = turned_vectors;
    }

    let first = points[0];
    let points: Vec<[f64; 3]> = points[1..letters.saturating_sub(1).max(1)]
        .iter()
        .map(|p| tidy(*p))
        .collect();
    let leg = LegSpec {
        chain: plain.to_string(),
        base: tidy(first),
        platform: tidy(attach),
        points: (letters > 2).then_some(points),
        axes: Some(
            axis_vectors
                .iter()
                .map(|a| AxisSpec::Vector(tidy(*a)))
                .collect(),
        ),
        actuated: Some(actuated.to_vec()),
    };
    Ok((leg, note))
}

/// The file's `source`: the command that rebuilds it, the catalogue entry of its legs, and why
/// axes were turned.
fn source_text(
    spec: &BuildSpec,
    lookup: &super::CommittedChains,
    axes: &str,
    actuated: &[usize],
    name: &str,
    turned_note: Option<&TurnedNote>,
) -> String {
    let n = spec.legs;
    let from_catalogue = lookup
        .chain(&spec.chain)
        .filter(|e| e.id.eq_ignore_ascii_case(spec.chain.trim()))
        .map(|e| format!(" (legs: catalogue entry {} {})", e.id, e.notation));
    let mut source = format!(
        "kinsyn build --legs {n} --chain '{}' --axes {axes} --actuated {} --base-radius {} --platform-radius {} --height {} --twist {}{} --name '{name}'",
        spec.chain.trim(),
        actuated
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(","),
        spec.base_radius,
        spec.platform_radius,
        spec.height,
        spec.twist,
        if spec.alternate { " --alternate" } else { "" }
    );
    source += &from_catalogue.unwrap_or_default();
    if let Some(TurnedNote {
        rank,
        generic,
        dependent,
    }) = turned_note
    {
        let _ = write!(
            source,
            "; axes turned: with the directions of --axes the leg is singular at the reference (rank {rank} there, {generic} at generic joint values{}), so every revolute was turned by 0.6 + 0.25 k rad (k its 0-based position), joint points kept; the leg is then generic",
            if dependent.is_empty() {
                String::new()
            } else {
                format!("; joints {} dependent", super::leg::joint_list(dependent))
            }
        );
    }
    source
}
