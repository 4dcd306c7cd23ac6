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
//! - **planar legs**: every passive revolute parallel to one axis `n`, any passive slider across
//!   it (the motions of the leg's end lie in the planar group `G(n)`): the platform turns about
//!   `n` only, `R m = n` — two **linear** equations in `x` (`x m = n x`,
//!   [`crate::geometry::StudyVariables::vector_onto`]) — and its point `B` stays in the plane
//!   of `A` normal to `n`; two parallel revolutes (an RR dyad) add `|B − A| = l`; a slider
//!   along `n` frees the plane (`R m = n` only); one passive revolute fixes its axis
//!   (`B = A` and `R m = n`);
//! - **spherical RR dyads**: two passive revolutes meeting at `A`: `B = A` and the angle of the
//!   link, `n·(R m) = cos α`;
//! - **a passive slider between the end groups** (a leg whose slider input is free or not
//!   given): S–P–S and U–P–S constrain nothing; R–P–S with the slider across the R keeps only
//!   the plane condition, S–P–R with the slider across the platform R only the moving plane.
//!
//! Anything else (two revolutes at each end with inner axes not parallel, a skew RR dyad, a
//! passive slider in any other place, several passive joints between the end groups) is
//! refused with [`PositionSystemError::UnsupportedLeg`], as are descriptions with several
//! moving bodies or legs between bodies ([`PositionSystemError::Multibody`]).
//!
//! The system is the legs' constraints, the Study quadric and the chart's equation
//! ([`Chart`]); it is square exactly when the legs give six constraints. An over-constrained
//! manipulator (the 4-RUU: 4 × 2 leg equations) has a non-square one
//! ([`Manipulator::constraint_system`]).
//!
//! # Free inputs
//! With [`InputValues::Free`], a free input is a **passive joint** of its leg wherever the leg
//! is then of a kind recognised above: its value is eliminated with the leg's motion (a UPS
//! with its slider free constrains nothing, an RPS keeps its plane, a planar RRR its plane and
//! axis). Otherwise (an RUU, whose five passive revolutes form no kind above), an actuated
//! revolute fixed in the ground (the first joint of its leg) is an unknown
//! `t_k = tan(θ_k / 2)` of its **displacement `θ_k` from the reference** (variables
//! `t1, t2, …`, named by actuator number, after `x0 … y3`). The points and axes it carries
//! (its leg's ground-side data) turn about its axis `n` through its point `p` by the rational
//! Rodrigues form `(1 + t²) R(θ) v = (1 − t²) v + 2t (n × v) + 2t² n (n·v)`, and each of the
//! leg's equations is multiplied by `1 + t²`, which makes it a polynomial of degree 2 in `t`
//! (as paper 004's `g1 … g8`, there with the absolute angle's tangent).

use super::body_tree::BodyNode;
use super::{Manipulator, construction::MechanismBuilder};
use crate::geometry::{
    Chart, PolyVector, STUDY_NAMES, StudyPolys, StudyVariables, constant_vector, cross, dot,
    study_constant, study_inverse, study_product, study_slide, study_turn,
};
use crate::notation::Primitive;
use crate::poly::{Poly, System};
use crate::spatial::{Displacement, study};
use nalgebra::{Matrix3, Point3, Vector3};

/// Why a manipulator at given inputs has no square polynomial position system here.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PositionSystemError {
    /// Several moving bodies, or legs that do not run from the ground to the end-effector:
    /// not one system but one block per body ([`Manipulator::body_blocks`]); or a body that no
    /// leg reaches.
    #[error(
        "{manipulator}: several moving bodies, or a body no leg reaches: the constraints of a description with several bodies are one block per body of its body tree"
    )]
    Multibody {
        /// The manipulator's name.
        manipulator: String,
    },
    /// A leg that does not fit the body tree ([`Manipulator::body_tree`]): it closes a loop
    /// between moving bodies, ends on the ground, or joins a body to itself.
    #[error(
        "leg {leg} (from {from} to {to}) closes a loop between moving bodies: global analysis covers bodies that each hang from one other body (the ground or a moving body) by all their legs, such as stacked modules; loops between moving bodies are not supported yet"
    )]
    BodyLoop {
        /// 1-based leg number.
        leg: usize,
        /// The name of the body the leg starts on.
        from: String,
        /// The name of the body it ends on.
        to: String,
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
    /// Parallel passive revolutes (axis `n`), with any passive sliders across them, giving the
    /// leg's end three planar dof or more: the planar displacements `G(n)`. The platform turns
    /// about `n` only, `R m = n` (two linear equations in `x`: [`StudyVariables::vector_onto`]),
    /// and its point `B` stays in the plane through `A` normal to `n`: `n·(B − A) = 0`.
    Planar,
    /// Two parallel passive revolutes (a planar RR dyad: the first axis through `A`, the last
    /// through `B`, `B − A` normal to them): [`LegKind::Planar`] and `|B − A| = l`.
    PlanarDistance,
    /// Parallel passive revolutes with a passive slider along them (the Schoenflies motions
    /// `X(n)`, or a cylindrical leg with the plane of motion free): `R m = n` only.
    Parallel,
    /// Two passive revolutes whose axes meet at `A` (a spherical RR dyad; `B = A` on the
    /// platform): `B = A` (three equations) and the angle of the link between the fixed axis
    /// `n` and the moving axis `R m`, `n·(R m) = cos α`.
    SphericalAngle,
    /// One passive revolute (axis `n` through `A`; `m` and `B` on the platform): the axis is
    /// fixed, `B = A` and `R m = n`.
    Revolute,
    /// A passive slider between spherical groups of five revolutes or more (a UPS or SPS with
    /// its slider free): no constraint.
    Free,
    /// A revolute at the base, a passive slider across its axis and a spherical group at the
    /// platform (an RPS with its slider free): `n·(B − A) = 0` only.
    Plane,
    /// A spherical group at the base, a passive slider across the platform revolute's axis
    /// (an SPR with its slider free): `(R m)·(A − B) = 0` only.
    MovingPlane,
    /// A revolute at the base (axis `n` through `A`), a passive slider not across it
    /// (direction `d` at the reference, turning with the revolute) and a spherical group at
    /// the platform: `B` stays on the quadric of revolution swept by the slider's line,
    /// `|B − A|² = |b₀|² + 2 (b₀·d / c) h + (|d|² / c²) h²` with `h = n·(B − A)`,
    /// `c = n·d` and `b₀ = B − A` at the reference (a cone when the line meets the axis).
    Cone,
    /// A spherical group at the base, a passive slider not across the platform revolute's
    /// axis `m` and the revolute: the base point `A` stays on the platform's quadric of
    /// revolution about `(B, R m)`, `|A − B|² = k0 + k1 h + k2 h²` with `h = (R m)·(A − B)`
    /// ([`LegKind::Cone`] seen from the platform).
    MovingCone,
}

impl LegKind {
    /// What the leg imposes, in a few words (reports).
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            Self::Distance => "distance",
            Self::RevoluteSpherical => "R–S: distance and plane",
            Self::SphericalRevolute => "S–R: distance and moving plane",
            Self::Coincident => "coincident points",
            Self::CoplanarDistance => "U–U: distance and coplanar lines",
            Self::Planar => "planar: axis kept and plane",
            Self::PlanarDistance => "planar R–R: axis kept, plane and distance",
            Self::Parallel => "axis kept",
            Self::SphericalAngle => "spherical R–R: coincident points and axis angle",
            Self::Revolute => "revolute: coincident points and axis kept",
            Self::Free => "none (passive slider)",
            Self::Plane => "plane",
            Self::MovingPlane => "moving plane",
            Self::Cone => "quadric of revolution",
            Self::MovingCone => "moving quadric of revolution",
        }
    }
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
    /// The platform U's last axis `n` (platform frame) for [`LegKind::CoplanarDistance`]; the
    /// platform's axis `m` (platform frame) for [`LegKind::Planar`],
    /// [`LegKind::PlanarDistance`], [`LegKind::Parallel`], [`LegKind::SphericalAngle`] and
    /// [`LegKind::Revolute`] (whose `axis` is then the fixed axis `n`, ground frame).
    pub platform_axis: Option<Vector3<f64>>,
    /// `cos α`, the angle between the fixed and the moving axis, for
    /// [`LegKind::SphericalAngle`].
    pub cosine: Option<f64>,
    /// For [`LegKind::Cone`], the coefficients `[k0, k1, k2]` of the quadric of revolution
    /// `|B − A|² = k0 + k1 h + k2 h²`, `h = n·(B − A)`: `k0 = |b₀|²`, `k1 = 2 b₀·d / c`,
    /// `k2 = |d|² / c²` (module documentation of the kind).
    pub revolution: Option<[f64; 3]>,
    /// The free input that turns `base` and `axis` (ground frame), with
    /// [`InputValues::Free`]; they are given at its reference value.
    pub turned_by: Option<FreeRevolute>,
}

impl LegConstraint {
    /// The constraint with the free revolute `turn` (ground frame) turning its ground-side
    /// data.
    #[must_use]
    pub fn turned(mut self, turn: Option<FreeRevolute>) -> Self {
        self.turned_by = turn;
        self
    }

    /// The constraint with its ground-side data (the fixed point, the fixed axis of the kinds
    /// that have one, the free revolute that turns them) expressed in the frame `f` (given in
    /// the ground frame): the leg's constraint on the displacement of its end body relative
    /// to a body whose frame is `f`.
    #[must_use]
    pub fn in_frame(mut self, f: &Displacement) -> Self {
        let local = |p: &Vector3<f64>| f.inverse_transform_point(&Point3::from(*p)).coords;
        self.base = local(&self.base);
        if !matches!(
            self.kind,
            LegKind::SphericalRevolute | LegKind::MovingPlane | LegKind::MovingCone
        ) {
            self.axis = self.axis.map(|n| f.rotation.inverse() * n);
        }
        self.turned_by = self.turned_by.map(|t| FreeRevolute {
            point: local(&t.point),
            axis: f.rotation.inverse() * t.axis,
            ..t
        });
        self
    }

    /// The number of equations of the leg.
    #[must_use]
    pub fn equations(&self) -> usize {
        match self.kind {
            LegKind::Free => 0,
            LegKind::Distance
            | LegKind::Plane
            | LegKind::MovingPlane
            | LegKind::Cone
            | LegKind::MovingCone => 1,
            LegKind::RevoluteSpherical
            | LegKind::SphericalRevolute
            | LegKind::CoplanarDistance
            | LegKind::Parallel => 2,
            LegKind::Coincident | LegKind::Planar => 3,
            LegKind::PlanarDistance | LegKind::SphericalAngle => 4,
            LegKind::Revolute => 5,
        }
    }
}

/// How far a pose is from meeting one leg's constraints (lengths in the file's unit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LegResidual {
    /// 0-based leg.
    pub leg: usize,
    /// `|B − A| − l` (`|B − A|` for the kinds that make the points coincide); 0 for the
    /// kinds without a distance or coincidence condition.
    pub distance: f64,
    /// The plane condition's residual as a signed distance, `n·(B − A)` (R–S),
    /// `(R m)·(A − B)` (S–R), or the distance of `C` from the plane through `B` spanned by `u`
    /// and `R n`, `(C − B)·(u × R n) / |u × R n|` (U–U; 0 when they are parallel); `None` for
    /// the other kinds; `n·(B − A)` for the planar kinds too.
    pub plane: Option<f64>,
    /// The kinds that fix an axis: the angle (radians) between the moving axis `R m` and the
    /// fixed `n` ([`LegKind::Planar`], [`LegKind::PlanarDistance`], [`LegKind::Parallel`],
    /// [`LegKind::Revolute`]), or its difference from the link's `α`
    /// ([`LegKind::SphericalAngle`]); `None` for the other kinds.
    pub angle: Option<f64>,
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
    free: Vec<FreeRevolute>,
    /// The members of a block of the body tree, each with its Study parameters relative to the
    /// root as polynomials of the system's unknowns.
    members: Vec<(usize, StudyPolys)>,
    /// For each leg, the body it starts on (`None`: the block's parent; else an index into
    /// [`Manipulator::bodies`]) and the body it ends on.
    ends: Vec<(Option<usize>, usize)>,
    /// For a planar mechanism, the plane's normal `n` and two unit vectors `u`, `v` across it:
    /// the root's Study parameters are then `x = (s0, s1 n)`, `y = (0, s2 u + s3 v)` in the
    /// system's first four unknowns ([`Self::study`]).
    planar: Option<[Vector3<f64>; 3]>,
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

    /// The variable index of each free input's `t_k = tan(θ_k / 2)`, in actuator order: the
    /// revolutes fixed in the ground (empty when the inputs are given). The other free inputs
    /// are passive joints of their legs, with no variable.
    #[must_use]
    pub fn inputs(&self) -> &[usize] {
        &self.inputs
    }

    /// The variable of the free input `actuator` (an index into [`Manipulator::actuators`]),
    /// `None` when it has none (given inputs, or a free input that is a passive joint).
    #[must_use]
    pub fn input_variable(&self, actuator: usize) -> Option<usize> {
        self.free
            .iter()
            .find(|f| f.actuator == actuator)
            .map(|f| f.variable)
    }

    /// The platform frame's displacement of a real solution `x0 … y3` (the free inputs'
    /// tangents after them, if any, are ignored)
    /// ([`study::to_displacement`] with [`study::QUADRIC_TOLERANCE`]).
    ///
    /// # Errors
    /// Not eight numbers ([`study::StudyError::NotFinite`] stands for that too), or parameters
    /// that are no displacement ([`study::StudyError`]).
    pub fn displacement(&self, solution: &[f64]) -> Result<Displacement, study::StudyError> {
        let z: Vec<crate::poly::C64> = solution
            .iter()
            .map(|v| crate::poly::C64::new(*v, 0.0))
            .collect();
        let s = self.study(&z).ok_or(study::StudyError::NotFinite)?;
        study::to_displacement(&s.map(|c| c.re), study::QUADRIC_TOLERANCE)
    }

    /// The Study parameters `x0 … y3` of the root's frame at a point of the system (complex or
    /// real): its first eight unknowns, or for a planar mechanism the embedding of its first
    /// four (`x = (s0, s1 n)`, `y = (0, s2 u + s3 v)`); `None` for a point too short.
    #[must_use]
    pub fn study(&self, point: &[crate::poly::C64]) -> Option<[crate::poly::C64; 8]> {
        match &self.planar {
            None => point.get(..8)?.try_into().ok(),
            Some([n, u, v]) => {
                let s = point.get(..4)?;
                let xn = |k: usize| s[1] * n[k];
                let yv = |k: usize| s[2] * u[k] + s[3] * v[k];
                Some([
                    s[0],
                    xn(0),
                    xn(1),
                    xn(2),
                    crate::poly::C64::new(0.0, 0.0),
                    yv(0),
                    yv(1),
                    yv(2),
                ])
            }
        }
    }

    /// The Study parameters of the block's members relative to its root at a point of the
    /// system (complex or real): each member (an index into [`Manipulator::bodies`]) with its
    /// eight parameters; empty for a block of one body.
    #[must_use]
    pub fn member_study(&self, point: &[crate::poly::C64]) -> Vec<(usize, [crate::poly::C64; 8])> {
        self.members
            .iter()
            .map(|(b, g)| (*b, std::array::from_fn(|k| g[k].eval(point))))
            .collect()
    }

    /// Whether the point (complex or real) puts a body of the block — its root, or a member
    /// through its joints — on the null cone `x0² + x1² + x2² + x3² = 0` (to `1e-8` of
    /// `Σ |x_k|²`): the equations hold there without the point being a displacement (a joint's
    /// `tan(θ/2) = ±i`, say).
    #[must_use]
    pub fn on_null_cone(&self, point: &[crate::poly::C64]) -> bool {
        let null = |x: &[crate::poly::C64]| {
            let delta: crate::poly::C64 = x[..4].iter().map(|c| c * c).sum();
            let size: f64 = x[..4].iter().map(crate::poly::C64::norm_sqr).sum();
            delta.norm() <= 1e-8 * size
        };
        self.study(point).is_some_and(|x| null(&x))
            || self.members.iter().any(|(_, g)| {
                let x: Vec<crate::poly::C64> = g[..4].iter().map(|p| p.eval(point)).collect();
                null(&x)
            })
    }

    /// How many of the system's first unknowns are the root's Study parameters: eight, or
    /// four for a planar mechanism ([`Self::study`]).
    #[must_use]
    pub fn study_unknowns(&self) -> usize {
        if self.planar.is_some() { 4 } else { 8 }
    }

    /// The variable groupings whose multi-homogeneous start systems may track fewer paths than
    /// the total degree ([`crate::homotopy::fewest_paths_start`]): the root's Study parameters
    /// as one group, or `x` and `y` apart, with each other unknown (a joint's tangent, an
    /// input's) alone — a joint's unknown enters each equation in low degree.
    #[must_use]
    pub fn variable_groupings(&self) -> Vec<Vec<Vec<usize>>> {
        let (k, n) = (self.study_unknowns(), self.system.nvars());
        vec![
            study_groups(k, n),
            [(0..k / 2).collect(), (k / 2..k).collect()]
                .into_iter()
                .chain((k..n).map(|v| vec![v]))
                .collect(),
        ]
    }

    /// Whether the system is a block with members (bodies joined to its root by joints whose
    /// values are unknowns): [`Self::displacement`] is then its root body's frame.
    #[must_use]
    pub fn has_members(&self) -> bool {
        !self.members.is_empty()
    }

    /// The frames of the block's members (indices into [`Manipulator::bodies`]) relative to its
    /// root's at the real solution `solution` (the joints' unknowns read from it); empty for a
    /// block of one body.
    ///
    /// # Errors
    /// Values that are no displacement ([`study::StudyError`]).
    pub fn member_frames(
        &self,
        solution: &[f64],
    ) -> Result<Vec<(usize, Displacement)>, study::StudyError> {
        let z: Vec<crate::poly::C64> = solution
            .iter()
            .map(|v| crate::poly::C64::new(*v, 0.0))
            .collect();
        self.members
            .iter()
            .map(|(b, g)| {
                let s: [f64; 8] = std::array::from_fn(|k| g[k].eval(&z).re);
                study::to_displacement(&s, study::QUADRIC_TOLERANCE).map(|d| (*b, d))
            })
            .collect()
    }

    /// The solution vector of the platform pose `pose` on this system's chart, `None` when the
    /// chart misses it ([`Chart::representative`]).
    #[must_use]
    pub fn solution_of(&self, pose: &Displacement) -> Option<Vec<f64>> {
        let s = self.chart.representative(&study::from_displacement(pose))?;
        Some(match &self.planar {
            None => s.to_vec(),
            Some([n, u, v]) => {
                let xv = Vector3::new(s[1], s[2], s[3]);
                let yv = Vector3::new(s[5], s[6], s[7]);
                vec![s[0], xv.dot(n), yv.dot(u), yv.dot(v)]
            }
        })
    }

    /// Each leg's residuals at the platform pose `pose`: zero for every leg exactly when the
    /// pose is an assembly at the given inputs (free inputs at their reference values).
    #[must_use]
    pub fn leg_residuals(&self, pose: &Displacement) -> Vec<LegResidual> {
        self.legs.iter().map(|c| leg_residual(c, pose)).collect()
    }

    /// Each leg's residuals at the real solution `solution` of the system: every leg's at the
    /// displacement of its last body relative to its first (or to the block's parent), the
    /// block's members placed by their joints' values; `None` where the solution is no
    /// displacement.
    #[must_use]
    pub fn residuals_at(&self, solution: &[f64]) -> Option<Vec<LegResidual>> {
        let root = self.displacement(solution).ok()?;
        let members = self.member_frames(solution).ok()?;
        let of = |body: usize| {
            members
                .iter()
                .find(|(b, _)| *b == body)
                .map_or_else(crate::spatial::identity, |(_, g)| *g)
        };
        Some(
            self.legs
                .iter()
                .zip(&self.ends)
                .map(|(c, &(start, end))| {
                    let pose = match start {
                        None => root * of(end),
                        Some(s) => of(s).inverse() * of(end),
                    };
                    leg_residual(c, &pose)
                })
                .collect(),
        )
    }
}

/// One leg's residuals at the displacement `pose` of its last body relative to its first
/// ([`PositionSystem::leg_residuals`]).
fn leg_residual(c: &LegConstraint, pose: &Displacement) -> LegResidual {
    let b = pose.transform_point(&Point3::from(c.platform)).coords;
    let moving = c.platform_axis.map(|m| pose.rotation * m);
    let between = |n: Vector3<f64>, m: Vector3<f64>| n.dot(&m).clamp(-1.0, 1.0).acos();
    let angle = match c.kind {
        LegKind::Planar | LegKind::PlanarDistance | LegKind::Parallel | LegKind::Revolute => {
            c.axis.zip(moving).map(|(n, m)| between(n, m))
        }
        LegKind::SphericalAngle => c
            .axis
            .zip(moving)
            .zip(c.cosine)
            .map(|((n, m), cos)| between(n, m) - cos.clamp(-1.0, 1.0).acos()),
        _ => None,
    };
    let plane = match c.kind {
        LegKind::RevoluteSpherical | LegKind::Plane | LegKind::Planar | LegKind::PlanarDistance => {
            c.axis.map(|n| n.dot(&(b - c.base)))
        }
        LegKind::MovingPlane => c.axis.map(|m| (pose.rotation * m).dot(&(c.base - b))),
        LegKind::SphericalRevolute => c.axis.map(|m| (pose.rotation * m).dot(&(c.base - b))),
        LegKind::CoplanarDistance => c.axis.zip(c.platform_axis).map(|(u, n)| {
            let normal = u.cross(&(pose.rotation * n));
            let norm = normal.norm();
            if norm > super::AXIS_TOLERANCE {
                (b - c.base).dot(&normal) / norm
            } else {
                0.0
            }
        }),
        _ => None,
    };
    let distance = match c.kind {
        LegKind::Free | LegKind::Plane | LegKind::MovingPlane | LegKind::Parallel => 0.0,
        LegKind::Cone | LegKind::MovingCone => {
            // |B − A| against the quadric of revolution's radius at the height h.
            let n = c.axis.unwrap_or_default();
            let [k0, k1, k2] = c.revolution.unwrap_or_default();
            let h = if c.kind == LegKind::Cone {
                n.dot(&(b - c.base))
            } else {
                (pose.rotation * n).dot(&(c.base - b))
            };
            (b - c.base).norm() - (k0 + k1 * h + k2 * h * h).max(0.0).sqrt()
        }
        LegKind::PlanarDistance => {
            // The distance within the plane of motion (normal to the axis).
            let n = c.axis.unwrap_or_default();
            let d = b - c.base;
            (d - n * n.dot(&d)).norm() - c.length
        }
        _ => (b - c.base).norm() - c.length,
    };
    LegResidual {
        leg: c.leg,
        distance,
        plane,
        angle,
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
        let node = BodyNode {
            body: 0,
            parent: None,
            legs: (0..self.legs.len()).collect(),
            members: Vec::new(),
            internal: Vec::new(),
        };
        self.block_system(&node, inputs, chart)
    }

    /// The constraint system of one block of the body tree (`node`,
    /// [`Manipulator::body_tree`]): in the Study parameters of its root body's frame **relative
    /// to its parent's frame** (the ground-side data of the legs taken into the parent's frame
    /// at its reference pose), then the free inputs' tangents, then one unknown per joint that
    /// joins a member to the block (`h<leg>` the tangent of a revolute's half turn from the
    /// reference, `d<leg>` a slider's displacement). The legs to a member, and the legs that
    /// close loops inside the block, are the equations of their kinds in the Study parameters
    /// of the member relative to the parent (or to the leg's first body), written as
    /// polynomials of the block's unknowns by composing the joints' displacements
    /// ([`crate::geometry::study_product`]).
    pub(super) fn block_system(
        &self,
        node: &BodyNode,
        inputs: &InputValues,
        chart: &Chart,
    ) -> Result<PositionSystem, PositionSystemError> {
        let legs: Vec<usize> = node.legs.iter().chain(&node.internal).copied().collect();
        let (value, turned) = self.input_values(inputs, &legs)?;
        let tolerance = 1e-6 * self.mechanism.scale();
        let frame_of =
            |k: Option<usize>| k.map_or_else(crate::spatial::identity, |k| self.bodies[k].frame);
        let index = |body: usize| self.bodies.iter().position(|b| b.body == body);
        let parent_frame = frame_of(node.parent);
        let mut free: Vec<FreeRevolute> = turned.iter().flatten().copied().collect();
        free.sort_by_key(|f| f.variable);
        // The joints that join the members: an unknown each, unless given.
        let mut names: Vec<String> = STUDY_NAMES.iter().map(|n| (*n).to_string()).collect();
        names.extend(free.iter().map(|f| format!("t{}", f.actuator + 1)));
        let joint_variable = self.joint_variables(node, &value, &mut names);
        let nb = names.len();
        // A ring of the block's unknowns and eight more for the Study parameters of a leg's
        // end relative to its start, substituted away.
        let nr = nb + 8;
        let study = |g: &Displacement| study_constant(nr, &study::from_displacement(g));
        let root_study: StudyPolys = std::array::from_fn(|k| Poly::variable(nr, k));
        let member_study = self.member_studies(node, &value, &joint_variable, &root_study);
        // A body's Study parameters relative to the root (the identity for the root).
        let of_body = |k: usize| -> StudyPolys {
            member_study
                .iter()
                .find(|(b, _)| *b == k)
                .map_or_else(|| study(&crate::spatial::identity()), |(_, g)| g.clone())
        };
        let root = StudyVariables::new(nr, [0, 1, 2, 3, 4, 5, 6, 7]);
        let virtual_study = StudyVariables::new(nr, std::array::from_fn(|k| nb + k));
        let mut constraints = Vec::new();
        let mut ends = Vec::new();
        let mut equations = Vec::new();
        for &i in &legs {
            let leg = &self.legs[i];
            let external = node.legs.contains(&i);
            let start_frame = if external {
                parent_frame
            } else {
                frame_of(index(leg.from))
            };
            let c = self
                .leg_constraint(i, &value, tolerance)?
                .turned(turned[i])
                .in_frame(&start_frame);
            let to = index(leg.to).unwrap_or(node.body);
            // The Study parameters of the leg's end relative to its start.
            let end: Option<StudyPolys> = match (external, to == node.body) {
                (true, true) => None,
                (true, false) => Some(study_product(&root_study, &of_body(to))),
                (false, _) => {
                    let from = index(leg.from).unwrap_or(node.body);
                    Some(study_product(&study_inverse(&of_body(from)), &of_body(to)))
                }
            };
            let s = if end.is_some() { &virtual_study } else { &root };
            let leg_equations = match &c.turned_by {
                None => fixed_leg_equations(s, &c),
                Some(turn) => turned_leg_equations(s, &c, &Turn::new(nr, turn)),
            };
            for e in leg_equations {
                let e = match &end {
                    None => e,
                    Some(g) => (0..8).fold(e, |e, k| e.substitute(nb + k, &g[k])),
                };
                equations.push(e);
            }
            constraints.push(c);
            ends.push((
                (!external).then(|| index(leg.from).unwrap_or(node.body)),
                to,
            ));
        }
        equations.push(root.quadric());
        equations.push(root.chart(chart));
        let map: Vec<usize> = (0..nr).map(|k| if k < nb { k } else { 0 }).collect();
        let mut equations: Vec<Poly> = equations
            .into_iter()
            .map(|e| e.relabel(nb, &map))
            .filter(|e| !e.is_empty())
            .collect();
        let mut members: Vec<(usize, StudyPolys)> = member_study
            .into_iter()
            .map(|(b, g)| (b, g.map(|p| p.relabel(nb, &map))))
            .collect();
        // A planar mechanism: the root's displacement in the plane's group, four unknowns.
        let planar = self.planar_frame(node);
        if let Some(frame) = &planar {
            equations = planar_restriction(&equations, frame);
            members = planar_members(members, frame);
            names.splice(0..8, planar_names(frame));
            for f in &mut free {
                f.variable -= 4;
            }
        }
        Ok(PositionSystem {
            system: grouped_system(names, equations, planar.is_some()),
            chart: *chart,
            legs: constraints,
            inputs: free.iter().map(|f| f.variable).collect(),
            free,
            members,
            ends,
            planar,
        })
    }

    /// The plane of a planar block: when every joint of the mechanism is a revolute parallel to
    /// one `n` or a slider across it, and the root's frame at the reference is a planar
    /// displacement of its parent's, every displacement of the root relative to its parent lies
    /// in the planar group `G(n)`: `[n, u, v]` in the parent's frame (`u`, `v` across `n`).
    fn planar_frame(&self, node: &BodyNode) -> Option<[Vector3<f64>; 3]> {
        let joints = self.mechanism.joints();
        let n = joints
            .iter()
            .find(|j| j.kind == Primitive::R)?
            .axis
            .normalize();
        let planar = joints.iter().all(|j| {
            let a = j.axis.normalize();
            match j.kind {
                Primitive::R => a.cross(&n).norm() <= super::AXIS_TOLERANCE,
                Primitive::P => a.dot(&n).abs() <= super::AXIS_TOLERANCE,
            }
        });
        if !planar {
            return None;
        }
        let parent = node
            .parent
            .map_or_else(crate::spatial::identity, |p| self.bodies[p].frame);
        let n_local = parent.rotation.inverse() * n;
        let relative = parent.inverse() * self.bodies[node.body].frame;
        let turned = (relative.rotation * n_local - n_local).norm() > super::AXIS_TOLERANCE;
        let lifted =
            relative.translation.vector.dot(&n_local).abs() > 1e-9 * self.mechanism.scale();
        if turned || lifted {
            return None;
        }
        let u = if n_local.x.abs() < 0.9 {
            Vector3::x().cross(&n_local).cross(&n_local).normalize() * -1.0
        } else {
            Vector3::y().cross(&n_local).cross(&n_local).normalize() * -1.0
        };
        let v = n_local.cross(&u);
        Some([n_local, u, v])
    }

    /// One unknown per joint of the legs of the members' paths in `node` whose value is not
    /// given (`value`), named after `names`: `h<leg>` (a revolute) or `d<leg>` (a slider) for
    /// a one-joint leg, `h<leg>_<k>` for the `k`-th joint of a longer one — each joint (an
    /// index into the mechanism's joints) with its variable's index.
    fn joint_variables(
        &self,
        node: &BodyNode,
        value: &[Option<f64>],
        names: &mut Vec<String>,
    ) -> Vec<(usize, usize)> {
        let joints = self.mechanism.joints();
        let mut out: Vec<(usize, usize)> = Vec::new();
        for &(i, _) in node.members.iter().flat_map(|m| &m.path) {
            let range = self.legs[i].joints.clone();
            let single = range.len() == 1;
            for (k, j) in range.enumerate() {
                if value[j].is_some() || out.iter().any(|(l, _)| *l == j) {
                    continue;
                }
                let letter = if joints[j].kind == Primitive::R {
                    'h'
                } else {
                    'd'
                };
                out.push((j, names.len()));
                names.push(if single {
                    format!("{letter}{}", i + 1)
                } else {
                    format!("{letter}{}_{}", i + 1, k + 1)
                });
            }
        }
        out
    }

    /// The Study parameters of each member of the block `node` relative to its root, in a
    /// ring of `nr` variables whose first eight are the root's Study parameters relative to
    /// the parent (`root`): the displacements of the legs of its path composed, each joint's
    /// value an unknown (`joint_variable`: joint, variable) or given (`value`); a body held
    /// from the parent is the root's inverse composed with its leg's displacement.
    fn member_studies(
        &self,
        node: &BodyNode,
        value: &[Option<f64>],
        joint_variable: &[(usize, usize)],
        root: &StudyPolys,
    ) -> Vec<(usize, StudyPolys)> {
        let joints = self.mechanism.joints();
        let nr = root[0].nvars();
        let index = |body: usize| self.bodies.iter().position(|b| b.body == body);
        let frame_of =
            |k: Option<usize>| k.map_or_else(crate::spatial::identity, |k| self.bodies[k].frame);
        let study = |g: &Displacement| study_constant(nr, &study::from_displacement(g));
        // The frame of a leg's last body relative to its first, through its joints (each
        // turned about, or slid along, its axis at the reference configuration: the product
        // of exponentials).
        let relative = |i: usize| -> StudyPolys {
            let leg = &self.legs[i];
            let from = frame_of(index(leg.from));
            let to = frame_of(index(leg.to));
            let moved = leg.joints.clone().fold(study(&from.inverse()), |g, j| {
                let spec = &joints[j];
                let joint = match joint_variable.iter().find(|(l, _)| *l == j) {
                    None => study(&spec.primitive().displacement(value[j].unwrap_or(0.0))),
                    Some((_, v)) => match spec.kind {
                        Primitive::R => study_turn(nr, *v, &spec.axis.normalize(), &spec.point),
                        Primitive::P => study_slide(nr, *v, &spec.axis.normalize()),
                    },
                };
                study_product(&g, &joint)
            });
            study_product(&moved, &study(&to))
        };
        node.members
            .iter()
            .map(|m| {
                let start = if m.from_parent {
                    study_inverse(root)
                } else {
                    study(&crate::spatial::identity())
                };
                let g = m.path.iter().fold(start, |g, &(i, along)| {
                    let r = relative(i);
                    study_product(&g, &if along { r } else { study_inverse(&r) })
                });
                (m.body, g)
            })
            .collect()
    }

    /// The values of the given inputs by joint, and (free inputs) the leg each free revolute
    /// at the ground of one of `legs` turns, with its unknown's index (from 8): a free input is
    /// a passive joint of its leg wherever the leg is then of a kind recognised here.
    #[allow(clippy::type_complexity)]
    fn input_values(
        &self,
        inputs: &InputValues,
        legs: &[usize],
    ) -> Result<(Vec<Option<f64>>, Vec<Option<FreeRevolute>>), PositionSystemError> {
        let joints = self.mechanism.joints();
        let mut value: Vec<Option<f64>> = vec![None; joints.len()];
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
                let mut variable = 8;
                for (k, act) in self.actuators.iter().enumerate() {
                    if !legs.contains(&act.leg) {
                        continue;
                    }
                    let spec = &joints[act.joint];
                    let leg = self.legs.iter().position(|l| l.joints.start == act.joint);
                    // A free input is a passive joint of its leg, its value eliminated with
                    // the leg's motion, wherever the leg is then of a kind recognised here.
                    // Otherwise, a revolute fixed in the ground is locked at its reference
                    // value, the leg's ground side turned by the unknown `t`.
                    let eliminated = leg.is_none_or(|l| {
                        self.leg_constraint(l, &value, 1e-6 * self.mechanism.scale())
                            .is_ok()
                    });
                    if let (Primitive::R, Some(leg), false) = (spec.kind, leg, eliminated) {
                        value[act.joint] = Some(0.0);
                        turned[leg] = Some(FreeRevolute {
                            actuator: k,
                            variable,
                            point: spec.point,
                            axis: spec.axis.normalize(),
                        });
                        variable += 1;
                    }
                }
            }
        }
        Ok((value, turned))
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
        let frame = self
            .bodies
            .iter()
            .find(|b| b.body == leg.to)
            .map_or(self.frame, |b| b.frame);
        (passive, g * frame)
    }

    /// Leg `i`'s constraint with the joints of `value` locked there (the others at their
    /// reference values, where their axes are read): the kinds of [`LegKind`], tried in turn —
    /// parallel revolutes (planar legs), revolutes through one point (spherical legs), then
    /// groups of concurrent revolutes at the two ends with at most one passive slider between.
    fn leg_constraint(
        &self,
        i: usize,
        value: &[Option<f64>],
        tolerance: f64,
    ) -> Result<LegConstraint, PositionSystemError> {
        let (passive, frame) = self.passive_lines(i, value);
        let lines: Vec<&Line> = passive.iter().map(|(_, l)| l).collect();
        let to_platform = |v: &Vector3<f64>| frame.rotation.inverse() * v;
        let constraint = |kind, base, platform| constraint_of(i, &frame, kind, base, platform);
        if lines.is_empty() {
            return Err(self.unsupported(
                i,
                "no passive joint: the leg is rigid at these inputs".to_string(),
            ));
        }
        if let Some(kind) = planar_kind(&lines) {
            // The first revolute's axis through `A`; `B` the foot of `A` on the last one.
            let revolutes: Vec<&&Line> = lines.iter().filter(|l| l.kind == Primitive::R).collect();
            let n = revolutes[0].direction;
            let a = revolutes[0].point;
            let b = foot(revolutes[revolutes.len() - 1], &a);
            let mut c = constraint(kind, a, b);
            if kind == LegKind::Revolute {
                c.length = 0.0;
            }
            c.axis = Some(n);
            c.platform_axis = Some(to_platform(&n));
            return Ok(c);
        }
        if lines.len() == 2
            && let Some(o) = common_point(&lines, tolerance)
        {
            let (n, m) = (lines[0].direction, lines[1].direction);
            let mut c = constraint(LegKind::SphericalAngle, o, o);
            c.length = 0.0;
            c.axis = Some(n);
            c.platform_axis = Some(to_platform(&m));
            c.cosine = Some(n.dot(&m));
            return Ok(c);
        }
        self.end_groups_constraint(i, &passive, &frame, tolerance)
    }

    /// [`PositionSystemError::UnsupportedLeg`] for leg `i`, with `reason`.
    fn unsupported(&self, i: usize, reason: String) -> PositionSystemError {
        PositionSystemError::UnsupportedLeg {
            leg: i + 1,
            chain: self.legs[i].chain.to_string(),
            reason,
        }
    }

    /// Leg `i`'s constraint from its `passive` lines (with their positions in the leg; the
    /// platform `frame` its configuration carries) as groups of concurrent revolutes at its
    /// two ends, with at most one passive slider between.
    fn end_groups_constraint(
        &self,
        i: usize,
        passive: &[(usize, Line)],
        frame: &Displacement,
        tolerance: f64,
    ) -> Result<LegConstraint, PositionSystemError> {
        let leg = &self.legs[i];
        let unsupported = |reason: String| self.unsupported(i, reason);
        let lines: Vec<&Line> = passive.iter().map(|(_, l)| l).collect();
        let to_platform = |v: &Vector3<f64>| frame.rotation.inverse() * v;
        let constraint = |kind, base, platform| constraint_of(i, frame, kind, base, platform);
        let n = lines.len();
        let (kb, a) = end_group(&lines, &mut (0..n), tolerance);
        let (kp, b) = end_group(&lines, &mut (kb..n).rev(), tolerance);
        let slider_hint = |k: usize| {
            self.actuators
                .iter()
                .find(|a| a.joint == leg.joints.start + passive[k].0)
                .map_or(String::new(), |a| {
                    format!(" (its input {} is not given)", a.label())
                })
        };
        // At most one passive slider between the end groups, and nothing else.
        let slider = match n - kb - kp {
            0 => None,
            1 if lines[kb].kind == Primitive::P => Some(lines[kb].direction),
            1 => {
                return Err(unsupported(
                    "1 passive revolute between the joints at its base and at its platform"
                        .to_string(),
                ));
            }
            between => {
                let sliders = lines[kb..n - kp]
                    .iter()
                    .position(|l| l.kind == Primitive::P)
                    .map_or(String::new(), |k| slider_hint(kb + k));
                return Err(unsupported(format!(
                    "{between} passive joints between the joints at its base and at its platform{sliders}"
                )));
            }
        };
        let refuse_groups = |extra: &str| {
            unsupported(format!(
                "its passive joints form {} at the base and {} at the platform{extra}",
                describe(kb),
                describe(kp)
            ))
        };
        let mut c = match (kb, kp, a, b, slider) {
            (2 | 3, 2 | 3, Some(a), Some(_), Some(_)) if kb + kp > 4 => {
                constraint(LegKind::Free, a, a)
            }
            (1, 3, Some(_), Some(b), Some(d)) => revolute_slider(i, frame, lines[0], &b, &d),
            (3, 1, Some(a), Some(_), Some(d)) => slider_revolute(i, frame, lines[n - 1], &a, &d),
            (_, _, _, _, Some(_)) => {
                return Err(refuse_groups(&format!(
                    " with a passive slider between{}",
                    slider_hint(kb)
                )));
            }
            (2 | 3, 2 | 3, Some(a), Some(b), None) if kb + kp > 4 => {
                constraint(LegKind::Distance, a, b)
            }
            (2, 2, Some(a), Some(b), None) => {
                let [u, nn] = u_u_axes(&lines, &a, &b, tolerance).map_err(|p| {
                    unsupported(format!(
                        "its passive joints form a universal joint (2 revolutes) at the base and at the platform with the {p}"
                    ))
                })?;
                let mut c = constraint(LegKind::CoplanarDistance, a, b);
                c.axis = Some(u);
                c.platform_axis = Some(to_platform(&nn));
                c
            }
            (1, 3, Some(_), Some(b), None) => {
                let line = lines[0];
                let mut c = constraint(LegKind::RevoluteSpherical, foot(line, &b), b);
                c.axis = Some(line.direction);
                c
            }
            (3, 1, Some(a), Some(_), None) => {
                let line = lines[n - 1];
                let mut c = constraint(LegKind::SphericalRevolute, a, foot(line, &a));
                c.axis = Some(to_platform(&line.direction));
                c
            }
            (3, 0, Some(a), None, None) => constraint(LegKind::Coincident, a, a),
            _ => return Err(refuse_groups("")),
        };
        if c.kind == LegKind::Free {
            c.length = 0.0;
        }
        Ok(c)
    }
}

/// The members' Study parameters (polynomials in a ring of `nb` whose first eight unknowns,
/// the root's, they do not involve) in the ring of a planar block, four unknowns fewer.
/// The names of a planar block's four Study unknowns (`x = (x0, x3 n)`, `y = (0, y1 u + y2 v)`
/// along the frame `[n, u, v]`): `x0, x3, y1, y2` for `n = z` (`u = x`, `v = y`), where they are
/// the Study parameters themselves; `x0, xn, yu, yv` otherwise.
fn planar_names(frame: &[Vector3<f64>; 3]) -> Vec<String> {
    let [n, u, _] = frame;
    let names = if (n - Vector3::z()).norm() < 1e-12 && (u - Vector3::x()).norm() < 1e-12 {
        ["x0", "x3", "y1", "y2"]
    } else {
        ["x0", "xn", "yu", "yv"]
    };
    names.iter().map(|s| (*s).to_string()).collect()
}

/// A polynomial of the block's `nb` unknowns with the root's Study parameters (the first
/// eight) restricted to the planar group of `frame` (`x = (s0, s1 n)`, `y = (0, s2 u + s3 v)`):
/// the four `s` take the first places, the other unknowns keep their order after them.
fn planar_substitution(p: &Poly, frame: &[Vector3<f64>; 3]) -> Poly {
    let [n, u, v] = frame;
    let nb = p.nvars();
    let ring = nb + 4;
    let s = |k: usize| Poly::variable(ring, nb + k);
    let zero = Poly::zero(ring);
    let study: [Poly; 8] = [
        s(0),
        s(1) * n.x,
        s(1) * n.y,
        s(1) * n.z,
        zero,
        s(2) * u.x + s(3) * v.x,
        s(2) * u.y + s(3) * v.y,
        s(2) * u.z + s(3) * v.z,
    ];
    // Variables 0..8 leave; the four new ones take their place at the front.
    let map: Vec<usize> = (0..ring)
        .map(|k| match k {
            k if k < 8 => 0,
            k if k < nb => k - 4,
            k => k - nb,
        })
        .collect();
    let widened = p.relabel(ring, &(0..nb).collect::<Vec<_>>());
    (0..8)
        .fold(widened, |p, k| p.substitute(k, &study[k]))
        .relabel(nb - 4, &map)
}

/// The members' Study parameters with the root's restricted to the planar group of `frame`
/// ([`planar_substitution`]).
fn planar_members(
    members: Vec<(usize, StudyPolys)>,
    frame: &[Vector3<f64>; 3],
) -> Vec<(usize, StudyPolys)> {
    members
        .into_iter()
        .map(|(b, g)| (b, g.map(|p| planar_substitution(&p, frame))))
        .collect()
}

/// The equations with the root's Study parameters restricted to the planar group of `frame`
/// ([`planar_substitution`]): the equations that vanish on the group (the Study quadric, the
/// axis and plane conditions of planar legs) are dropped — those whose coefficients all fall
/// below `1e-12` of the largest before the restriction.
fn planar_restriction(equations: &[Poly], frame: &[Vector3<f64>; 3]) -> Vec<Poly> {
    let largest = |p: &Poly| p.terms().map(|(_, c)| c.norm()).fold(0.0, f64::max);
    equations
        .iter()
        .filter_map(|e| {
            let restricted = planar_substitution(e, frame);
            (largest(&restricted) > 1e-12 * largest(e)).then_some(restricted)
        })
        .collect()
}

/// Leg `i`'s constraint as an R–P–S: the revolute `line` at the base, a passive slider of
/// direction `d` after it, the spherical group's centre `b` (ground frame, at the
/// configuration that carries the platform frame `frame`): [`LegKind::Plane`] with the slider
/// across the axis, else [`LegKind::Cone`] with its quadric of revolution.
fn revolute_slider(
    i: usize,
    frame: &Displacement,
    line: &Line,
    b: &Vector3<f64>,
    d: &Vector3<f64>,
) -> LegConstraint {
    let (n, d) = (line.direction, d.normalize());
    let cn = n.dot(&d);
    let across = cn.abs() <= super::AXIS_TOLERANCE;
    let kind = if across {
        LegKind::Plane
    } else {
        LegKind::Cone
    };
    let a = foot(line, b);
    let mut c = constraint_of(i, frame, kind, a, *b);
    c.axis = Some(n);
    if !across {
        let b0 = b - a;
        c.revolution = Some([b0.norm_squared(), 2.0 * b0.dot(&d) / cn, 1.0 / (cn * cn)]);
    }
    c
}

/// Leg `i`'s constraint as an S–P–R: the spherical group's centre `a` at the base, a passive
/// slider of direction `d`, the platform's revolute `line` ([`revolute_slider`] seen from the
/// platform): [`LegKind::MovingPlane`] with the slider across its axis, else
/// [`LegKind::MovingCone`]; the axis in the platform frame.
fn slider_revolute(
    i: usize,
    frame: &Displacement,
    line: &Line,
    a: &Vector3<f64>,
    d: &Vector3<f64>,
) -> LegConstraint {
    let mut c = revolute_slider(i, frame, line, a, d);
    c.base = *a;
    c.platform = frame
        .inverse_transform_point(&Point3::from(foot(line, a)))
        .coords;
    c.kind = if c.kind == LegKind::Plane {
        LegKind::MovingPlane
    } else {
        LegKind::MovingCone
    };
    c.axis = Some(frame.rotation.inverse() * line.direction);
    c
}

/// The longest run of concurrent revolutes (at most three) among `lines` taken in the order of
/// `range`, from its start: how many, and their common point.
fn end_group(
    lines: &[&Line],
    range: &mut dyn Iterator<Item = usize>,
    tolerance: f64,
) -> (usize, Option<Vector3<f64>>) {
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
}

/// Leg `i`'s constraint of `kind` between the fixed point `base` and the point
/// `platform_ground` (ground frame, at the configuration where the leg carries the platform
/// frame `frame`), their distance its length; no axis yet.
fn constraint_of(
    i: usize,
    frame: &Displacement,
    kind: LegKind,
    base: Vector3<f64>,
    platform_ground: Vector3<f64>,
) -> LegConstraint {
    LegConstraint {
        leg: i,
        kind,
        base,
        platform: frame
            .inverse_transform_point(&Point3::from(platform_ground))
            .coords,
        length: (platform_ground - base).norm(),
        axis: None,
        platform_axis: None,
        cosine: None,
        revolution: None,
        turned_by: None,
    }
}

/// The planar kind of a leg's passive lines, if every revolute among them is parallel to the
/// first and every slider runs across or along them ([`LegKind::Planar`],
/// [`LegKind::PlanarDistance`], [`LegKind::Parallel`], [`LegKind::Revolute`]); `None` when they
/// are not, or form a planar chain of another kind (an RP dyad, a cylindrical pair).
fn planar_kind(lines: &[&Line]) -> Option<LegKind> {
    let n = lines.iter().find(|l| l.kind == Primitive::R)?.direction;
    let (mut revolutes, mut across, mut along) = (0, 0, 0);
    for l in lines {
        let c = l.direction.dot(&n);
        match l.kind {
            Primitive::R if l.direction.cross(&n).norm() <= super::AXIS_TOLERANCE => revolutes += 1,
            Primitive::P if c.abs() <= super::AXIS_TOLERANCE => across += 1,
            Primitive::P if l.direction.cross(&n).norm() <= super::AXIS_TOLERANCE => along += 1,
            _ => return None,
        }
    }
    match (revolutes, across, along) {
        (1, 0, 0) => Some(LegKind::Revolute),
        (2, 0, 0) => Some(LegKind::PlanarDistance),
        (r, a, 0) if r + a >= 3 => Some(LegKind::Planar),
        (r, a, _) if r + a >= 3 => Some(LegKind::Parallel),
        _ => None,
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
        LegKind::Planar | LegKind::PlanarDistance | LegKind::Parallel | LegKind::Revolute => {
            let m = c.platform_axis.unwrap_or_default();
            let mut e = s.vector_onto(&m, &axis).to_vec();
            match c.kind {
                LegKind::Planar => {
                    e.push(s.moving_point_on_fixed_plane(&c.platform, &c.base, &axis));
                }
                LegKind::PlanarDistance => {
                    e.push(s.moving_point_on_fixed_plane(&c.platform, &c.base, &axis));
                    e.push(s.distance(&c.base, &c.platform, c.length));
                }
                LegKind::Revolute => e.extend(s.moving_point_at(&c.platform, &c.base)),
                _ => {}
            }
            e
        }
        LegKind::SphericalAngle => {
            let mut e = s.moving_point_at(&c.platform, &c.base).to_vec();
            e.push(s.vectors_at_angle(
                &axis,
                &c.platform_axis.unwrap_or_default(),
                c.cosine.unwrap_or_default(),
            ));
            e
        }
        LegKind::Free => Vec::new(),
        LegKind::Plane => vec![s.moving_point_on_fixed_plane(&c.platform, &c.base, &axis)],
        LegKind::Cone => vec![revolution_equation(
            s,
            c,
            &s.moving_point_on_fixed_plane(&c.platform, &c.base, &axis),
        )],
        LegKind::MovingCone => vec![revolution_equation(
            s,
            c,
            &s.fixed_point_on_moving_plane(&c.base, &c.platform, &axis),
        )],
        LegKind::MovingPlane => vec![s.fixed_point_on_moving_plane(&c.base, &c.platform, &axis)],
    }
}

/// The equation of a [`LegKind::Cone`] or [`LegKind::MovingCone`] leg (degree 4): with
/// `D = Δ |B − A|²` (the distance quadric at length 0, [`StudyVariables::distance`], on the
/// Study quadric) and `h` the plane condition `H = Δ n·(B − A)` (or `Δ (R m)·(A − B)`),
/// `Δ D − k2 H² − k1 Δ H − k0 Δ² = 0`: the leg's
/// relation `|B − A|² = k0 + k1 h + k2 h²` times `Δ²`. (`B = A + R(θ)(b₀ + s d)`: `h = s c`,
/// `|B − A|² = |b₀|² + 2 s b₀·d + s² |d|²`, `s = h / c`.)
fn revolution_equation(s: &StudyVariables, c: &LegConstraint, h: &Poly) -> Poly {
    let [k0, k1, k2] = c.revolution.unwrap_or_default();
    let delta = s.delta();
    &delta * &s.distance(&c.base, &c.platform, 0.0)
        - h * h * k2
        - &delta * h * k1
        - &delta * &delta * k0
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
    // w (n'·(M_R b + M_T) − Δ n'·a'), n'·a' = (R n)·p + n·(a − p): the moving point on the
    // turned fixed plane.
    let plane = || {
        let wn = turn.direction(&axis);
        let wna =
            dot(&wn, &constant_vector(n, &turn.point)) + w.clone() * axis.dot(&(a - turn.point));
        dot(&wn, &s.point(b)) - &delta * &wna
    };
    // w (M_R b + M_T − Δ a'): the moving point at the turned fixed point.
    let coincident = || {
        let p = s.point(b);
        let wa = turn.point(a);
        (0..3)
            .map(|i| &w * &p[i] - &delta * &wa[i])
            .collect::<Vec<_>>()
    };
    // x m = n' x with the turned axis n' (four equations, bilinear in x and t); two linear
    // ones in x when the turn is about n itself, which leaves n' = n.
    let onto = || {
        let m = c.platform_axis.unwrap_or_default();
        if turn.axis.cross(&axis).norm() <= super::AXIS_TOLERANCE {
            s.vector_onto(&m, &axis).to_vec()
        } else {
            s.vector_onto_turned(&m, &turn.direction(&axis), &w)
                .to_vec()
        }
    };
    match c.kind {
        LegKind::Distance => vec![distance()],
        LegKind::RevoluteSpherical => vec![distance(), plane()],
        LegKind::Plane => vec![plane()],
        LegKind::Planar | LegKind::PlanarDistance | LegKind::Parallel | LegKind::Revolute => {
            let mut e = onto();
            match c.kind {
                LegKind::Planar => e.push(plane()),
                LegKind::PlanarDistance => e.extend([plane(), distance()]),
                LegKind::Revolute => e.extend(coincident()),
                _ => {}
            }
            e
        }
        LegKind::SphericalAngle => {
            // w n'·(M_R m) − w cos α Δ.
            let wn = turn.direction(&axis);
            let angle = dot(&wn, &s.vector(&c.platform_axis.unwrap_or_default()))
                - &w * &delta * c.cosine.unwrap_or_default();
            let mut e = coincident();
            e.push(angle);
            e
        }
        LegKind::Free => Vec::new(),
        LegKind::Cone => {
            // The relation times (w Δ)²: with D_w = w Δ |B − a'|² and H_w = w Δ n'·(B − a'),
            // Δ w D_w − k2 H_w² − k1 Δ w H_w − k0 w² Δ².
            let [k0, k1, k2] = c.revolution.unwrap_or_default();
            let d_w = &w * &s.distance(&zero, b, 0.0) + &delta * &turn.norm_squared(a)
                - dot(&turn.point(a), &s.point(b)) * 2.0;
            let h_w = plane();
            let dw = &delta * &w;
            vec![&dw * &d_w - &h_w * &h_w * k2 - &dw * &h_w * k1 - &dw * &dw * k0]
        }
        LegKind::MovingCone => {
            // As the cone, with the moving plane's condition affine in the turned fixed point.
            let [k0, k1, k2] = c.revolution.unwrap_or_default();
            let d_w = &w * &s.distance(&zero, b, 0.0) + &delta * &turn.norm_squared(a)
                - dot(&turn.point(a), &s.point(b)) * 2.0;
            let h_w = &w * &s.fixed_point_on_moving_plane(&zero, b, &axis)
                + dot(&s.vector(&axis), &turn.point(a));
            let dw = &delta * &w;
            vec![&dw * &d_w - &h_w * &h_w * k2 - &dw * &h_w * k1 - &dw * &dw * k0]
        }
        LegKind::SphericalRevolute | LegKind::MovingPlane => {
            // The plane condition is affine in the fixed point: F(a') = F(0) + (M_R m)·a'.
            let m = axis;
            let moving_plane = &w * &s.fixed_point_on_moving_plane(&zero, b, &m)
                + dot(&s.vector(&m), &turn.point(a));
            if c.kind == LegKind::MovingPlane {
                vec![moving_plane]
            } else {
                vec![distance(), moving_plane]
            }
        }
        LegKind::Coincident => coincident(),
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

/// The constraint system of `equations` in the unknowns `names`, the Study parameters of the
/// root first (four of them when `planar`), with its variable groups ([`study_groups`]).
fn grouped_system(names: Vec<String>, equations: Vec<Poly>, planar: bool) -> System {
    let groups = study_groups(if planar { 4 } else { 8 }, names.len());
    System::new(names, equations)
        .and_then(|s| s.with_groups(groups))
        .expect("distinct names, equations in their ring, a partition of them")
}

/// The variable groups of a constraint system of `n` unknowns whose first `study` are the
/// root's Study parameters: those together, each other unknown (an input's or a joint's
/// tangent, which enters each equation in low degree) alone. The system carries them
/// ([`PositionSystem::system`]), for the multi-homogeneous and linear-product starts.
fn study_groups(study: usize, n: usize) -> Vec<Vec<usize>> {
    std::iter::once((0..study).collect())
        .chain((study..n).map(|v| vec![v]))
        .collect()
}
