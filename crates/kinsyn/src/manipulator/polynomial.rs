//! A manipulator as a **polynomial system** in the Study parameters of its platform frame
//! ([`crate::geometry`]): at fixed inputs and square, the forward position problem in the
//! form whose solutions a homotopy finds all of ([`Manipulator::position_system`]); square or
//! not, and with the inputs as unknowns if asked, the constraint ideal whose components are the
//! operation modes ([`Manipulator::constraint_system`]).
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
//!   platform point `B` at the fixed point `A` (three equations);
//! - **U–U** with parallel inner axes (RUU with its R locked, paper 004 §2): a U at `B` (axes
//!   `u`, then `s`) and a U at the platform's `C` (axes `s' ∥ s`, then `n`), with `u` and `n`
//!   perpendicular to `s` and the link `BC` perpendicular to `s`: `|C − B| = l` and the line
//!   through `B` along `u` coplanar with the moving line through `C` along `R n` (paper 004
//!   eqs. 10, 12: `BC` lies in the plane of `u` and `R n`, the plane normal to `s`).
//!
//! Anything else (a passive P, two revolutes at each end with inner axes not parallel,
//! parallel revolutes as in planar legs, passive joints between the end groups) is refused with
//! [`PositionSystemError::UnsupportedLeg`], as are descriptions with several moving bodies or
//! legs between bodies ([`PositionSystemError::Multibody`]).
//!
//! The system is the legs' constraints, the Study quadric and the chart's equation
//! ([`Chart`]); it is square exactly when the legs give six constraints. An over-constrained
//! manipulator (the 4-RUU: 4 × 2 leg equations) has a non-square one
//! ([`Manipulator::constraint_system`]).
//!
//! # Free inputs
//! With [`InputValues::Free`], each actuated revolute fixed in the ground (the first joint of
//! its leg) is an unknown `t_k = tan(θ_k / 2)` of its **displacement `θ_k` from the reference**
//! (variables `t1, t2, …` after `x0 … y3`, by actuator index). The points and axes it carries
//! (its leg's ground-side data) turn about its axis `n` through its point `p` by the rational
//! Rodrigues form `(1 + t²) R(θ) v = (1 − t²) v + 2t (n × v) + 2t² n (n·v)`, and each of the
//! leg's equations is multiplied by `1 + t²`, which makes it a polynomial of degree 2 in `t`
//! (as paper 004's `g1 … g8`, there with the absolute angle's tangent).

use super::{Manipulator, construction::MechanismBuilder};
use crate::geometry::{
    Chart, PolyVector, STUDY_NAMES, StudyVariables, constant_vector, cross, dot,
};
use crate::notation::Primitive;
use crate::poly::{Poly, System};
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
        "leg {leg} ({chain}): {reason}; supported with its inputs locked: S–S (e.g. UPS), R–S (RPS), S–R (SPR), rigid–S, U–U with parallel inner axes (RUU)"
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
    /// A free input ([`InputValues::Free`]) that is not a revolute fixed in the ground.
    #[error(
        "input {label} cannot be a free unknown: {reason}; free inputs must be revolutes fixed in the ground (the first joint of a leg)"
    )]
    FreeInput {
        /// The actuator's label.
        label: String,
        /// What it is instead.
        reason: String,
    },
}

/// Which actuated joints are fixed in [`Manipulator::constraint_system`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InputValues<'a> {
    /// The given inputs (actuator index, joint value from the reference configuration: radians
    /// or a length) are locked; the actuators not given are passive joints.
    Given(&'a [(usize, f64)]),
    /// Every input is an unknown: `t_k = tan(θ_k / 2)` of its displacement from the reference
    /// (module documentation); every actuator must be a revolute fixed in the ground.
    Free,
}

/// A free input turning a leg's ground-side data (module documentation, [`InputValues::Free`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeRevolute {
    /// The actuator (index into [`Manipulator::actuators`]).
    pub actuator: usize,
    /// Its unknown `t = tan(θ / 2)`: the variable's index in the system.
    pub variable: usize,
    /// A point of its axis (ground frame).
    pub point: Vector3<f64>,
    /// Its unit axis `n` (ground frame; positive `θ` turns counter-clockwise about it).
    pub axis: Vector3<f64>,
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
    /// A U at `B` (ground side, first axis `u`) and a U at the platform's `C` (last axis `n`),
    /// inner axes parallel (RUU): `|C − B| = l` and `(C − B)·(u × R n) = 0`, the line
    /// `(B, u)` coplanar with the moving line `(C, R n)`.
    CoplanarDistance,
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
    /// `m` of the platform revolute (platform frame) for [`LegKind::SphericalRevolute`], the
    /// base U's first axis `u` (ground frame) for [`LegKind::CoplanarDistance`].
    pub axis: Option<Vector3<f64>>,
    /// The platform U's last axis `n` (platform frame) for [`LegKind::CoplanarDistance`].
    pub platform_axis: Option<Vector3<f64>>,
    /// The free input that turns `base` and `axis` (ground frame), with
    /// [`InputValues::Free`]; they are given at its reference value.
    pub turned_by: Option<FreeRevolute>,
}

impl LegConstraint {
    /// The number of equations of the leg.
    #[must_use]
    pub fn equations(&self) -> usize {
        match self.kind {
            LegKind::Distance => 1,
            LegKind::RevoluteSpherical | LegKind::SphericalRevolute | LegKind::CoplanarDistance => {
                2
            }
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
    /// The plane condition's residual as a signed distance, `n·(B − A)` (R–S),
    /// `(R m)·(A − B)` (S–R), or the distance of `C` from the plane through `B` spanned by `u`
    /// and `R n`, `(C − B)·(u × R n) / |u × R n|` (U–U; 0 when they are parallel); `None` for
    /// the other kinds.
    pub plane: Option<f64>,
}

/// A manipulator as a polynomial system in the Study parameters `x0 … y3` of its platform
/// frame, and the free inputs' tangents after them (module documentation): square at fixed
/// inputs from [`Manipulator::position_system`], square or not from
/// [`Manipulator::constraint_system`].
#[derive(Debug, Clone, PartialEq)]
pub struct PositionSystem {
    system: System,
    chart: Chart,
    legs: Vec<LegConstraint>,
    inputs: Vec<usize>,
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

    /// The variable index of each free input's `t_k = tan(θ_k / 2)`, in actuator order (empty
    /// when the inputs are given).
    #[must_use]
    pub fn inputs(&self) -> &[usize] {
        &self.inputs
    }

    /// The platform frame's displacement of a real solution `x0 … y3` (the free inputs'
    /// tangents after them, if any, are ignored)
    /// ([`study::to_displacement`] with [`study::QUADRIC_TOLERANCE`]).
    ///
    /// # Errors
    /// Not eight numbers ([`study::StudyError::NotFinite`] stands for that too), or parameters
    /// that are no displacement ([`study::StudyError`]).
    pub fn displacement(&self, solution: &[f64]) -> Result<Displacement, study::StudyError> {
        let s: [f64; 8] = solution
            .get(..8)
            .ok_or(study::StudyError::NotFinite)?
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
    /// pose is an assembly at the given inputs (free inputs at their reference values).
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
                    LegKind::CoplanarDistance => c.axis.zip(c.platform_axis).map(|(u, n)| {
                        let normal = u.cross(&(pose.rotation * n));
                        let norm = normal.norm();
                        if norm > super::AXIS_TOLERANCE {
                            (b - c.base).dot(&normal) / norm
                        } else {
                            0.0
                        }
                    }),
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
    /// use kinsyn::{geometry::Chart, poly::C64};
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
        let ps = self.constraint_system(&InputValues::Given(inputs), chart)?;
        let constraints: usize = ps.legs.iter().map(LegConstraint::equations).sum();
        if constraints < 6 {
            let given: Vec<usize> = inputs.iter().map(|(a, _)| *a).collect();
            return Err(PositionSystemError::Underdetermined {
                constraints,
                missing: (0..self.actuators.len())
                    .filter(|a| !given.contains(a))
                    .map(|a| self.actuators[a].label())
                    .collect(),
            });
        }
        if constraints > 6 {
            return Err(PositionSystemError::Overdetermined(constraints));
        }
        Ok(ps)
    }

    /// The manipulator's constraint system in its platform frame's Study parameters, with the
    /// chart `chart`: the legs' equations in leg order, the Study quadric and the chart's
    /// equation, **square or not** (an over-constrained manipulator such as paper 004's 4-RUU
    /// has more equations than unknowns; an under-constrained one fewer). With
    /// [`InputValues::Given`] the unknowns are `x0 … y3` and the system is
    /// [`Manipulator::position_system`]'s without its count check; with
    /// [`InputValues::Free`] the inputs' half-angle tangents `t1, t2, …` follow
    /// ([`PositionSystem::inputs`]; module documentation), and the system's zero set is the
    /// input–pose space whose components are the operation modes.
    ///
    /// # Example
    /// The 4-RUU of paper 004 with free inputs: 4 × 2 leg equations of degree 4 (2 in the
    /// Study parameters, 2 in the input's tangent), the quadric and the chart, in 12 unknowns;
    /// the reference configuration (`t = 0`) is a solution.
    ///
    /// ```
    /// use kinsyn::manipulator::{InputValues, Manipulator};
    /// use kinsyn::{geometry::Chart, poly::C64};
    /// # std::env::set_current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../..")).unwrap();
    /// let m = Manipulator::from_json(&std::fs::read_to_string("mechanisms/4-ruu.json")?)?;
    /// let ps = m.constraint_system(&InputValues::Free, &Chart::Unit)?;
    /// assert_eq!(ps.system().degrees(), [4, 4, 4, 4, 4, 4, 4, 4, 2, 2]);
    /// assert_eq!(ps.inputs(), [8, 9, 10, 11]);
    /// let s = ps.solution_of(&m.platform_frame(&m.reference())).unwrap();
    /// let mut z: Vec<C64> = s.iter().map(|r| C64::new(*r, 0.0)).collect();
    /// z.extend([C64::new(0.0, 0.0); 4]);
    /// assert!(ps.system().evaluate(&z).iter().all(|r| r.norm() < 1e-9));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`PositionSystemError`]: several moving bodies, an input that is unknown, repeated or
    /// not finite, a leg of an unsupported kind, or (free inputs) an actuator that is not a
    /// revolute fixed in the ground.
    ///
    /// # Panics
    /// Never: the variable names are distinct and every equation is in their ring.
    pub fn constraint_system(
        &self,
        inputs: &InputValues,
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
        // The free revolute of each leg, if any.
        let mut turned: Vec<Option<FreeRevolute>> = vec![None; self.legs.len()];
        match inputs {
            InputValues::Given(given) => {
                for &(a, v) in *given {
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
            }
            InputValues::Free => {
                for (k, act) in self.actuators.iter().enumerate() {
                    let refuse = |reason: &str| PositionSystemError::FreeInput {
                        label: act.label(),
                        reason: reason.to_string(),
                    };
                    let spec = &joints[act.joint];
                    if spec.kind != Primitive::R {
                        return Err(refuse("it is a prismatic joint"));
                    }
                    let leg = self
                        .legs
                        .iter()
                        .position(|l| l.joints.start == act.joint)
                        .ok_or_else(|| refuse("it is not the first joint of its leg"))?;
                    // Locked at its reference value; the leg's ground side turns with `t`.
                    value[act.joint] = Some(0.0);
                    turned[leg] = Some(FreeRevolute {
                        actuator: k,
                        variable: 8 + k,
                        point: spec.point,
                        axis: spec.axis.normalize(),
                    });
                }
            }
        }
        let tolerance = 1e-6 * self.mechanism.scale();
        let mut legs = Vec::new();
        for (i, turn) in turned.iter().enumerate() {
            let mut c = self.leg_constraint(i, &value, tolerance)?;
            c.turned_by = *turn;
            legs.push(c);
        }
        let free = matches!(inputs, InputValues::Free);
        let nvars = if free { 8 + self.actuators.len() } else { 8 };
        let s = StudyVariables::leading(nvars);
        let mut equations = Vec::with_capacity(legs.len() * 2 + 2);
        for c in &legs {
            match &c.turned_by {
                None => equations.extend(fixed_leg_equations(&s, c)),
                Some(turn) => {
                    equations.extend(turned_leg_equations(&s, c, &Turn::new(nvars, turn)));
                }
            }
        }
        equations.push(s.quadric());
        equations.push(s.chart(chart));
        let mut names: Vec<String> = STUDY_NAMES.iter().map(|n| (*n).to_string()).collect();
        let mut input_variables = Vec::new();
        if free {
            names.extend((1..=self.actuators.len()).map(|k| format!("t{k}")));
            input_variables.extend(8..nvars);
        }
        Ok(PositionSystem {
            system: System::new(names, equations).expect("distinct names, equations in their ring"),
            chart: *chart,
            legs,
            inputs: input_variables,
        })
    }

    /// Leg `i`'s serial chain with the joints of `value` locked there, the passive joints at
    /// their reference values: each passive joint's line (with its position in the leg), and
    /// the platform frame this configuration carries.
    fn passive_lines(&self, i: usize, value: &[Option<f64>]) -> (Vec<(usize, Line)>, Displacement) {
        let leg = &self.legs[i];
        let joints = self.mechanism.joints();
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
        (passive, g * self.frame)
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
        let unsupported = |reason: String| PositionSystemError::UnsupportedLeg {
            leg: i + 1,
            chain: leg.chain.to_string(),
            reason,
        };
        let (passive, frame) = self.passive_lines(i, value);
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
        let mut platform_axis = None;
        let (kind, base, platform_ground, axis) = match (kb, kp, a, b) {
            (2 | 3, 2 | 3, Some(a), Some(b)) if kb + kp > 4 => (LegKind::Distance, a, b, None),
            (2, 2, Some(a), Some(b)) => {
                let [u, n] = u_u_axes(&lines, &a, &b, tolerance).map_err(|p| {
                    unsupported(format!(
                        "its passive joints form a universal joint (2 revolutes) at the base and at the platform with the {p}"
                    ))
                })?;
                platform_axis = Some(frame.rotation.inverse() * n);
                (LegKind::CoplanarDistance, a, b, Some(u))
            }
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
            platform_axis,
            turned_by: None,
        })
    }
}

/// The outer axes `[u, n]` (ground frame) of a U–U leg's four passive lines meeting at `a`
/// (the first two) and `b` (the last two), or what keeps them from a
/// [`LegKind::CoplanarDistance`]: the inner axes must be parallel, the outer ones and the link
/// `a b` perpendicular to them.
fn u_u_axes(
    lines: &[&Line],
    a: &Vector3<f64>,
    b: &Vector3<f64>,
    tolerance: f64,
) -> Result<[Vector3<f64>; 2], &'static str> {
    let [u, s, s2, n] = [0, 1, 2, 3].map(|k| lines[k].direction);
    if s.cross(&s2).norm() > super::AXIS_TOLERANCE {
        Err("inner axes (joints 2 and 3 of its passive U–U) not parallel")
    } else if u.dot(&s).abs() > super::AXIS_TOLERANCE || n.dot(&s).abs() > super::AXIS_TOLERANCE {
        Err("outer axes of its U–U not perpendicular to the inner ones")
    } else if (b - a).dot(&s).abs() > tolerance {
        Err("link between its two U joints not perpendicular to their inner axes")
    } else {
        Ok([u, n])
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

/// A leg's equations with its ground-side data fixed (module documentation).
fn fixed_leg_equations(s: &StudyVariables, c: &LegConstraint) -> Vec<Poly> {
    let axis = c.axis.unwrap_or_default();
    match c.kind {
        LegKind::Distance => vec![s.distance(&c.base, &c.platform, c.length)],
        LegKind::RevoluteSpherical => vec![
            s.distance(&c.base, &c.platform, c.length),
            s.moving_point_on_fixed_plane(&c.platform, &c.base, &axis),
        ],
        LegKind::SphericalRevolute => vec![
            s.distance(&c.base, &c.platform, c.length),
            s.fixed_point_on_moving_plane(&c.base, &c.platform, &axis),
        ],
        LegKind::Coincident => s.moving_point_at(&c.platform, &c.base).to_vec(),
        LegKind::CoplanarDistance => vec![
            s.distance(&c.base, &c.platform, c.length),
            s.lines_coplanar(
                &c.base,
                &axis,
                &c.platform,
                &c.platform_axis.unwrap_or_default(),
            ),
        ],
    }
}

/// The turn of a free ground revolute (axis `n` through `p`, unknown `t = tan(θ/2)`) acting on
/// ground-frame data, every quantity multiplied by `w = 1 + t²` to stay polynomial.
struct Turn {
    nvars: usize,
    t: Poly,
    point: Vector3<f64>,
    axis: Vector3<f64>,
}

impl Turn {
    fn new(nvars: usize, turn: &FreeRevolute) -> Self {
        Self {
            nvars,
            t: Poly::variable(nvars, turn.variable),
            point: turn.point,
            axis: turn.axis,
        }
    }

    /// `w = 1 + t²`.
    fn weight(&self) -> Poly {
        Poly::real(self.nvars, 1.0) + &self.t * &self.t
    }

    /// `w R(θ) v = (1 − t²) v + 2t (n × v) + 2t² n (n·v)` (Rodrigues, rational form).
    fn direction(&self, v: &Vector3<f64>) -> PolyVector {
        let n = &self.axis;
        let t2 = &self.t * &self.t;
        let along = n * n.dot(v);
        let across = n.cross(v);
        std::array::from_fn(|i| {
            Poly::real(self.nvars, v[i]) - t2.clone() * v[i]
                + self.t.clone() * (2.0 * across[i])
                + t2.clone() * (2.0 * along[i])
        })
    }

    /// `w` times the turned point `p + R(θ)(a − p)`.
    fn point(&self, a: &Vector3<f64>) -> PolyVector {
        let r = self.direction(&(a - self.point));
        let w = self.weight();
        std::array::from_fn(|i| &r[i] + &(w.clone() * self.point[i]))
    }

    /// `w |p + R(θ)(a − p)|² = w (|p|² + |a − p|²) + 2 p·(w R(θ)(a − p))`.
    fn norm_squared(&self, a: &Vector3<f64>) -> Poly {
        let d = a - self.point;
        let r = self.direction(&d);
        self.weight() * (self.point.norm_squared() + d.norm_squared())
            + dot(&constant_vector(self.nvars, &self.point), &r) * 2.0
    }

    /// `w` times the moment `a' × u'` of the turned line through `a` along `u`:
    /// `p × (w R u) + w R ((a − p) × u)`.
    fn moment(&self, a: &Vector3<f64>, u: &Vector3<f64>) -> PolyVector {
        let ru = self.direction(u);
        let rm = self.direction(&(a - self.point).cross(u));
        let pc = cross(&constant_vector(self.nvars, &self.point), &ru);
        std::array::from_fn(|i| &pc[i] + &rm[i])
    }
}

/// A leg's equations with its ground-side data turned by a free input, each the fixed one
/// times `w = 1 + t²` (module documentation): the constraints of [`crate::geometry`]
/// written through their affine (or, for `|a|²`, quadratic) dependence on the fixed point and
/// their linear dependence on the fixed direction and the fixed line's moment.
fn turned_leg_equations(s: &StudyVariables, c: &LegConstraint, turn: &Turn) -> Vec<Poly> {
    let n = s.nvars();
    let zero = Vector3::zeros();
    let (a, b) = (&c.base, &c.platform);
    let w = turn.weight();
    let delta = s.delta();
    // w · |R b + t − a'|² − l²) Δ = w D(0) + Δ (w |a'|²) − 2 (w a')·(M_R b + M_T).
    let distance = || {
        &w * &s.distance(&zero, b, c.length) + &delta * &turn.norm_squared(a)
            - dot(&turn.point(a), &s.point(b)) * 2.0
    };
    let axis = c.axis.unwrap_or_default();
    match c.kind {
        LegKind::Distance => vec![distance()],
        LegKind::RevoluteSpherical => {
            // w (n'·(M_R b + M_T) − Δ n'·a'), n'·a' = (R n)·p + n·(a − p).
            let wn = turn.direction(&axis);
            let wna = dot(&wn, &constant_vector(n, &turn.point))
                + w.clone() * axis.dot(&(a - turn.point));
            vec![distance(), dot(&wn, &s.point(b)) - &delta * &wna]
        }
        LegKind::SphericalRevolute => {
            // The plane condition is affine in the fixed point: F(a') = F(0) + (M_R m)·a'.
            let m = axis;
            vec![
                distance(),
                &w * &s.fixed_point_on_moving_plane(&zero, b, &m)
                    + dot(&s.vector(&m), &turn.point(a)),
            ]
        }
        LegKind::Coincident => {
            let p = s.point(b);
            let wa = turn.point(a);
            (0..3).map(|i| &w * &p[i] - &delta * &wa[i]).collect()
        }
        LegKind::CoplanarDistance => {
            // Coplanarity is linear in the fixed line's Plücker coordinates (u', a' × u'):
            // u'·P − (M_R m)·(a' × u') with P_k = lines_coplanar(0, e_k, b, m).
            let m = c.platform_axis.unwrap_or_default();
            let p: PolyVector =
                std::array::from_fn(|k| s.lines_coplanar(&zero, &Vector3::ith(k, 1.0), b, &m));
            let coplanar =
                dot(&turn.direction(&axis), &p) - dot(&s.vector(&m), &turn.moment(a, &axis));
            vec![distance(), coplanar]
        }
    }
}
