//! A manipulator at fixed inputs as a **square polynomial system** in the Study parameters of
//! its platform frame ([`crate::poly::geometry`]): the forward position problem in the form
//! whose solutions a homotopy finds all of.
//!
//! # Input values
//! An input value is what [`Manipulator::parse_inputs`] returns and
//! [`Manipulator::solve_position`] takes: the actuated **joint value from the reference
//! configuration** of the description (radians for an R, a length in the file's unit for a P).
//! A P input is therefore a **displacement of the slider from its reference**, not the leg's
//! length: a UPS leg whose points are `l₀` apart in the description has length `l₀ + value`
//! when its slider lies along the leg (the general case is computed: the distance between the
//! leg's joint centres with the slider moved by `value`). Inputs not given are **free**
//! (passive) joints.
//!
//! # Legs recognised
//! With the given inputs locked, each leg (from the ground to the platform) is reduced to its
//! passive joints. The passive revolutes at its base whose axes meet at one point form a
//! spherical group (a U: two, an S: three) at that point `A`; those at the platform end form one
//! at `B`. Everything between must be locked (rigid). Supported:
//! - **S–S**: spherical groups of at least two revolutes at both ends, not both of exactly two
//!   (UPS, SPS, UPU-with-a-spherical-end… with the P locked): one distance `|B − A| = l`;
//! - **R–S**: one revolute at the base (axis `n`) and a spherical group at the platform (3-RPS):
//!   the distance from `B` to the foot `A` of its perpendicular on the axis, and `B` in the
//!   plane through `A` perpendicular to `n`;
//! - **S–R**: a spherical group at the base and one revolute at the platform (axis `m`, SPR):
//!   the distance from `A` to the foot `B` on the platform axis, and `A` in the moving plane
//!   through `B` perpendicular to `m`;
//! - **rigid–S** or **S–rigid**: only a spherical group (three revolutes) at one end: the
//!   platform point `B` at the fixed point `A` (three equations).
//!
//! Anything else (a passive P, two revolutes at each end as in RUU, parallel revolutes as in
//! planar legs, passive joints between the end groups) is refused with
//! [`PositionSystemError::UnsupportedLeg`], as are descriptions with several moving bodies or
//! legs between bodies ([`PositionSystemError::Multibody`]).
//!
//! The system is the legs' constraints, the Study quadric and the chart's equation
//! ([`Chart`]); it is square exactly when the legs give six constraints.

use super::{Manipulator, construction::MechanismBuilder};
use crate::notation::Primitive;
use crate::poly::System;
use crate::poly::geometry::{Chart, StudyVariables, study_system};
use crate::spatial::{Displacement, study};
use nalgebra::{Matrix3, Point3, Vector3};

/// Why a manipulator at given inputs has no square polynomial position system here.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PositionSystemError {
    /// Several moving bodies, or legs that do not run from the ground to the end-effector.
    #[error(
        "{manipulator}: polynomial position systems cover legs from the ground to one platform; descriptions with several moving bodies or legs between bodies are not supported yet"
    )]
    Multibody {
        /// The manipulator's name.
        manipulator: String,
    },
    /// An input index that names no actuator.
    #[error("input {index} names no actuator ({count} actuators)")]
    UnknownInput {
        /// The index given.
        index: usize,
        /// The number of actuators.
        count: usize,
    },
    /// The same input given twice.
    #[error("input {0} given twice")]
    InputTwice(String),
    /// An input value that is not a finite number.
    #[error("input {label} = {value} is not a finite number")]
    NotFinite {
        /// The actuator's label.
        label: String,
        /// The value.
        value: f64,
    },
    /// A leg whose passive geometry at these inputs is not one of the supported kinds.
    #[error(
        "leg {leg} ({chain}): {reason}; supported with its inputs locked: S–S (e.g. UPS), R–S (RPS), S–R (SPR), rigid–S"
    )]
    UnsupportedLeg {
        /// 1-based leg number.
        leg: usize,
        /// The leg's chain as written.
        chain: String,
        /// What was found.
        reason: String,
    },
    /// Fewer than six constraints: the platform keeps degrees of freedom at these inputs.
    #[error(
        "the legs give {constraints} constraint{s} at these inputs: the manipulator has {dof} dof left{hint}",
        s = if *constraints == 1 { "" } else { "s" },
        dof = 6 - constraints,
        hint = if missing.is_empty() { String::new() } else { format!(" (inputs not given: {})", missing.join(" ")) }
    )]
    Underdetermined {
        /// The number of constraint equations of the legs.
        constraints: usize,
        /// The labels of the inputs not given.
        missing: Vec<String>,
    },
    /// More than six constraints (an over-constrained manipulator): the system is not square.
    #[error(
        "the legs give {0} constraints at these inputs, more than the platform's 6 dof: over-constrained systems are not supported yet"
    )]
    Overdetermined(usize),
}

/// What a leg imposes on the platform at the given inputs (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LegKind {
    /// Spherical groups at both ends: `|B − A| = l`.
    Distance,
    /// A revolute at the base, a spherical group at the platform: `|B − A| = l` and
    /// `n·(B − A) = 0`.
    RevoluteSpherical,
    /// A spherical group at the base, a revolute at the platform: `|B − A| = l` and
    /// `(R m)·(A − B) = 0`.
    SphericalRevolute,
    /// A spherical group at one end only: `B = A` (`l = 0`).
    Coincident,
}

/// The constraints of one leg: fixed point `A`, platform point `B`, length, axis.
#[derive(Debug, Clone, PartialEq)]
pub struct LegConstraint {
    /// 0-based leg.
    pub leg: usize,
    /// What the leg imposes.
    pub kind: LegKind,
    /// `A`, in the ground frame.
    pub base: Vector3<f64>,
    /// `B`, in the platform frame (the end-effector's frame of the description).
    pub platform: Vector3<f64>,
    /// `l = |B − A|` at the given inputs (0 for [`LegKind::Coincident`]).
    pub length: f64,
    /// The unit axis `n` of the base revolute (ground frame) for [`LegKind::RevoluteSpherical`],
    /// `m` of the platform revolute (platform frame) for [`LegKind::SphericalRevolute`].
    pub axis: Option<Vector3<f64>>,
}

impl LegConstraint {
    /// The number of equations of the leg.
    #[must_use]
    pub fn equations(&self) -> usize {
        match self.kind {
            LegKind::Distance => 1,
            LegKind::RevoluteSpherical | LegKind::SphericalRevolute => 2,
            LegKind::Coincident => 3,
        }
    }
}

/// How far a pose is from meeting one leg's constraints (lengths in the file's unit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LegResidual {
    /// 0-based leg.
    pub leg: usize,
    /// `|B − A| − l`.
    pub distance: f64,
    /// The plane condition's residual as a signed distance, `n·(B − A)` (R–S) or
    /// `(R m)·(A − B)` (S–R); `None` for the other kinds.
    pub plane: Option<f64>,
}

/// A manipulator at fixed inputs as a square polynomial system in the Study parameters
/// `x0 … y3` of its platform frame (module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct PositionSystem {
    system: System,
    chart: Chart,
    legs: Vec<LegConstraint>,
}

impl PositionSystem {
    /// The system: the legs' equations in leg order, then the Study quadric and the chart.
    #[must_use]
    pub fn system(&self) -> &System {
        &self.system
    }

    /// The chart of the Study parameters.
    #[must_use]
    pub fn chart(&self) -> &Chart {
        &self.chart
    }

    /// The legs' constraints, in leg order.
    #[must_use]
    pub fn legs(&self) -> &[LegConstraint] {
        &self.legs
    }

    /// The platform frame's displacement of a real solution `x0 … y3`
    /// ([`study::to_displacement`] with [`study::QUADRIC_TOLERANCE`]).
    ///
    /// # Errors
    /// Not eight numbers ([`study::StudyError::NotFinite`] stands for that too), or parameters
    /// that are no displacement ([`study::StudyError`]).
    pub fn displacement(&self, solution: &[f64]) -> Result<Displacement, study::StudyError> {
        let s: [f64; 8] = solution
            .try_into()
            .map_err(|_| study::StudyError::NotFinite)?;
        study::to_displacement(&s, study::QUADRIC_TOLERANCE)
    }

    /// The solution vector of the platform pose `pose` on this system's chart, `None` when the
    /// chart misses it ([`Chart::representative`]).
    #[must_use]
    pub fn solution_of(&self, pose: &Displacement) -> Option<[f64; 8]> {
        self.chart.representative(&study::from_displacement(pose))
    }

    /// Each leg's residuals at the platform pose `pose`: zero for every leg exactly when the
    /// pose is an assembly at the given inputs.
    #[must_use]
    pub fn leg_residuals(&self, pose: &Displacement) -> Vec<LegResidual> {
        self.legs
            .iter()
            .map(|c| {
                let b = pose.transform_point(&Point3::from(c.platform)).coords;
                let plane = match c.kind {
                    LegKind::RevoluteSpherical => c.axis.map(|n| n.dot(&(b - c.base))),
                    LegKind::SphericalRevolute => {
                        c.axis.map(|m| (pose.rotation * m).dot(&(c.base - b)))
                    }
                    LegKind::Distance | LegKind::Coincident => None,
                };
                LegResidual {
                    leg: c.leg,
                    distance: (b - c.base).norm() - c.length,
                    plane,
                }
            })
            .collect()
    }
}

/// A passive joint's line at the configuration of the given inputs (ground frame).
struct Line {
    kind: Primitive,
    direction: Vector3<f64>,
    point: Vector3<f64>,
}

/// The point where the lines meet (least squares), if they do within `tolerance` and their
/// directions are independent (two not parallel; three not coplanar).
fn common_point(lines: &[&Line], tolerance: f64) -> Option<Vector3<f64>> {
    if lines.iter().any(|l| l.kind != Primitive::R) {
        return None;
    }
    if lines.len() == 1 {
        return Some(lines[0].point);
    }
    let independent = match lines {
        [a, b] => a.direction.cross(&b.direction).norm() > super::AXIS_TOLERANCE,
        [a, b, c] => {
            a.direction.cross(&b.direction).dot(&c.direction).abs() > super::AXIS_TOLERANCE
        }
        _ => false,
    };
    if !independent {
        return None;
    }
    let mut m = Matrix3::zeros();
    let mut r = Vector3::zeros();
    for l in lines {
        let p = Matrix3::identity() - l.direction * l.direction.transpose();
        m += p;
        r += p * l.point;
    }
    let x = m.lu().solve(&r)?;
    lines
        .iter()
        .all(|l| (x - l.point).cross(&l.direction).norm() <= tolerance)
        .then_some(x)
}

/// The foot of the perpendicular from `p` on the line.
fn foot(line: &Line, p: &Vector3<f64>) -> Vector3<f64> {
    line.point + line.direction * line.direction.dot(&(p - line.point))
}

impl Manipulator {
    /// The manipulator with the `inputs` given (actuator index, joint value from the reference
    /// configuration: radians or a length — module documentation) as a square polynomial
    /// system in its platform frame's Study parameters, with the chart `chart` (e.g.
    /// [`Chart::random_linear`]).
    ///
    /// # Example
    /// The 6-UPS at its reference inputs: the reference pose is a solution.
    ///
    /// ```
    /// use kinsyn::manipulator::Manipulator;
    /// use kinsyn::poly::{C64, geometry::Chart};
    /// # std::env::set_current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).unwrap();
    /// let m = Manipulator::from_json(&std::fs::read_to_string("mechanisms/6-ups.json")?)?;
    /// let inputs = m.parse_inputs("P1.3=0,P2.3=0,P3.3=0,P4.3=0,P5.3=0,P6.3=0")?;
    /// let ps = m.position_system(&inputs, &Chart::random_linear(1))?;
    /// assert_eq!(ps.system().degrees(), [2, 2, 2, 2, 2, 2, 2, 1]);
    /// let s = ps.solution_of(&m.platform_frame(&m.reference())).unwrap();
    /// let z: Vec<C64> = s.iter().map(|r| C64::new(*r, 0.0)).collect();
    /// assert!(ps.system().evaluate(&z).iter().all(|r| r.norm() < 1e-9));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`PositionSystemError`]: several moving bodies, an input that is unknown, repeated or
    /// not finite, a leg of an unsupported kind, or legs giving other than six constraints.
    pub fn position_system(
        &self,
        inputs: &[(usize, f64)],
        chart: &Chart,
    ) -> Result<PositionSystem, PositionSystemError> {
        if self.bodies.len() != 1
            || !self
                .legs
                .iter()
                .all(|l| l.from == MechanismBuilder::GROUND && l.to == self.platform)
        {
            return Err(PositionSystemError::Multibody {
                manipulator: self.name.clone(),
            });
        }
        let joints = self.mechanism.joints();
        let mut value: Vec<Option<f64>> = vec![None; joints.len()];
        for &(a, v) in inputs {
            let act = self
                .actuators
                .get(a)
                .ok_or(PositionSystemError::UnknownInput {
                    index: a,
                    count: self.actuators.len(),
                })?;
            if !v.is_finite() {
                return Err(PositionSystemError::NotFinite {
                    label: act.label(),
                    value: v,
                });
            }
            if value[act.joint].replace(v).is_some() {
                return Err(PositionSystemError::InputTwice(act.label()));
            }
        }
        let tolerance = 1e-6 * self.mechanism.scale();
        let mut legs = Vec::new();
        for i in 0..self.legs.len() {
            legs.push(self.leg_constraint(i, &value, tolerance)?);
        }
        let constraints: usize = legs.iter().map(LegConstraint::equations).sum();
        if constraints < 6 {
            return Err(PositionSystemError::Underdetermined {
                constraints,
                missing: self
                    .actuators
                    .iter()
                    .filter(|a| value[a.joint].is_none())
                    .map(super::Actuator::label)
                    .collect(),
            });
        }
        if constraints > 6 {
            return Err(PositionSystemError::Overdetermined(constraints));
        }
        let s = StudyVariables::leading(8);
        let mut equations = Vec::with_capacity(8);
        for c in &legs {
            match c.kind {
                LegKind::Distance => equations.push(s.distance(&c.base, &c.platform, c.length)),
                LegKind::RevoluteSpherical => {
                    let n = c.axis.unwrap_or_default();
                    equations.push(s.distance(&c.base, &c.platform, c.length));
                    equations.push(s.moving_point_on_fixed_plane(&c.platform, &c.base, &n));
                }
                LegKind::SphericalRevolute => {
                    let m = c.axis.unwrap_or_default();
                    equations.push(s.distance(&c.base, &c.platform, c.length));
                    equations.push(s.fixed_point_on_moving_plane(&c.base, &c.platform, &m));
                }
                LegKind::Coincident => equations.extend(s.moving_point_at(&c.platform, &c.base)),
            }
        }
        equations.push(s.quadric());
        equations.push(s.chart(chart));
        Ok(PositionSystem {
            system: study_system(equations),
            chart: *chart,
            legs,
        })
    }

    /// Leg `i`'s constraint with the joints of `value` locked there (the others at their
    /// reference values, where their axes are read).
    fn leg_constraint(
        &self,
        i: usize,
        value: &[Option<f64>],
        tolerance: f64,
    ) -> Result<LegConstraint, PositionSystemError> {
        let leg = &self.legs[i];
        let joints = self.mechanism.joints();
        let unsupported = |reason: String| PositionSystemError::UnsupportedLeg {
            leg: i + 1,
            chain: leg.chain.to_string(),
            reason,
        };
        // The leg's serial chain at the given inputs, passive joints at their reference values:
        // each passive joint's line, and the platform frame this configuration carries.
        let mut g = crate::spatial::identity();
        let mut passive = Vec::new();
        for j in leg.joints.clone() {
            let spec = &joints[j];
            match value[j] {
                Some(q) => g *= spec.primitive().displacement(q),
                None => passive.push((
                    j - leg.joints.start,
                    Line {
                        kind: spec.kind,
                        direction: g.rotation * spec.axis,
                        point: g.transform_point(&Point3::from(spec.point)).coords,
                    },
                )),
            }
        }
        let frame = g * self.frame;
        if let Some((k, _)) = passive.iter().find(|(_, l)| l.kind == Primitive::P) {
            let hint = self
                .actuators
                .iter()
                .find(|a| a.joint == leg.joints.start + k)
                .map_or(String::new(), |a| {
                    format!(" (its input {} is not given)", a.label())
                });
            return Err(unsupported(format!(
                "its joint {} is a passive P{hint}",
                k + 1
            )));
        }
        let lines: Vec<&Line> = passive.iter().map(|(_, l)| l).collect();
        let n = lines.len();
        let group = |range: &mut dyn Iterator<Item = usize>| {
            let mut best = (0, None);
            let mut picked = Vec::new();
            for k in range.take(3) {
                picked.push(lines[k]);
                match common_point(&picked, tolerance) {
                    Some(p) => best = (picked.len(), Some(p)),
                    None => break,
                }
            }
            best
        };
        let (kb, a) = group(&mut (0..n));
        let (kp, b) = group(&mut (kb..n).rev());
        if kb + kp < n {
            return Err(unsupported(format!(
                "{} passive joints between the joints at its base and at its platform",
                n - kb - kp
            )));
        }
        let local = |p: &Vector3<f64>| frame.inverse_transform_point(&Point3::from(*p)).coords;
        let (kind, base, platform_ground, axis) = match (kb, kp, a, b) {
            (2 | 3, 2 | 3, Some(a), Some(b)) if kb + kp > 4 => (LegKind::Distance, a, b, None),
            (1, 3, Some(_), Some(b)) => {
                let line = lines[0];
                (
                    LegKind::RevoluteSpherical,
                    foot(line, &b),
                    b,
                    Some(line.direction),
                )
            }
            (3, 1, Some(a), Some(_)) => {
                let line = lines[n - 1];
                let m = frame.rotation.inverse() * line.direction;
                (LegKind::SphericalRevolute, a, foot(line, &a), Some(m))
            }
            (3, 0, Some(a), None) => (LegKind::Coincident, a, a, None),
            _ => {
                return Err(unsupported(format!(
                    "its passive joints form {} at the base and {} at the platform",
                    describe(kb),
                    describe(kp)
                )));
            }
        };
        Ok(LegConstraint {
            leg: i,
            kind,
            base,
            platform: local(&platform_ground),
            length: (platform_ground - base).norm(),
            axis,
        })
    }
}

/// A group of `k` concurrent revolutes, in words.
fn describe(k: usize) -> &'static str {
    match k {
        0 => "nothing (rigid)",
        1 => "one revolute",
        2 => "a universal joint (2 revolutes)",
        _ => "a spherical joint (3 revolutes)",
    }
}
