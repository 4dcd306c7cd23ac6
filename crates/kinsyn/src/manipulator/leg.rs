//! Checks of one leg on its own: parallel-group marks against the axes, and the rank of the
//! leg's joint twists at the reference configuration against its generic rank.
//!
//! A leg is a serial chain of primitive joints. Its joint twists at the reference configuration
//! (all joint values zero) span the twists the leg allows there. At generic joint values they
//! span a space of the chain's *generic rank*; at special values (two revolutes coaxial, three
//! revolute axes through collinear points in a plane, two guides parallel) the rank drops. Such
//! a reference is a **leg singularity**: every Jacobian of the manipulator computed there sees a
//! leg that lost a freedom, and its reciprocal wrenches are not those of the leg in general.
//! When the generic rank itself is below the number of joints, some joints are **dependent at
//! every configuration** (four parallel revolutes, a U whose second axis lies along the slider
//! of a UPS leg): the leg has a self-motion or a redundant joint.
//!
//! Rank decisions are unit-free. The twists are made dimensionless with the mechanism's
//! **characteristic point and length** `c`, `L` ([`crate::mechanism::Mechanism::scale`]; for a
//! leg checked on its own by `kinsyn build`, those of its revolute points: their centroid and
//! RMS distance from it; a prismatic joint has no point): a revolute of unit axis `ω` through
//! `p` becomes
//! `(ω; ((p − c)/L) × ω)`, a prismatic joint of unit direction `a` becomes `(0; a)` (its column
//! multiplied by `L`, translational rows divided by it), and slider values are drawn in units of
//! `L`. The rank is then [`screw::rank`](crate::screw::rank) with the relative tolerance
//! [`screw::DEFAULT_RANK_TOLERANCE`](crate::screw::DEFAULT_RANK_TOLERANCE); scaling every
//! length of a file, or moving it, changes nothing.

use super::{AXIS_TOLERANCE, Manipulator};
use crate::chain::SerialChain;
use crate::chain::random_configuration;
use crate::linalg::{self, Rank};
use crate::notation::{Chain, Primitive};
use nalgebra::{DMatrix, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::fmt;

/// Random configurations at which the generic rank of a leg is taken (the largest rank found).
const GENERIC_SAMPLES: usize = 4;

/// Seed of those configurations: the checks are reproducible.
const GENERIC_SEED: u64 = 2026;

/// A coefficient of a null vector (relative to its largest) below this is round-off: the joint
/// takes no part in the dependency.
const DEPENDENCY_TOLERANCE: f64 = 1e-6;

/// The rank check of one leg.
#[derive(Debug, Clone, PartialEq)]
pub struct LegCheck {
    /// 0-based leg.
    pub leg: usize,
    /// The leg's chain as read.
    pub chain: Chain,
    /// Number of primitive joints.
    pub joints: usize,
    /// The characteristic length `L` the twists were made dimensionless with.
    pub length: f64,
    /// The rank of the dimensionless joint twists at the reference configuration, with its
    /// singular values ([`Rank::gap`] gives the gap of the decision).
    pub reference: Rank,
    /// The largest rank at seeded random joint values (the generic rank), with its singular
    /// values.
    pub generic: Rank,
    /// The joints (1-based) of the first dependency among the joint twists at the reference,
    /// base to platform: the first joint whose twist lies in the span of those before it, and
    /// those before it that take part. Empty when the twists are independent there.
    pub dependent_at_reference: Vec<usize>,
    /// The same at the generic configuration: empty unless joints are dependent everywhere.
    pub dependent_everywhere: Vec<usize>,
}

impl LegCheck {
    /// Checks a leg given as its primitive joints `(kind, unit axis, point)` at the reference
    /// configuration (the point of a prismatic joint is ignored), made dimensionless about the
    /// characteristic point and length `(centre, length)`: the mechanism's
    /// ([`crate::mechanism::Mechanism::centre`], [`crate::mechanism::Mechanism::scale`]) for a
    /// leg of a manipulator, the leg's own revolute points' when there is no manipulator yet
    /// ([`LegCheck::standalone`]). `leg` and `chain` only name it.
    ///
    /// # Panics
    /// If an axis has no length or a point is not finite (a [`Manipulator`] never has either).
    #[must_use]
    pub fn new(
        leg: usize,
        chain: &Chain,
        joints: &[(Primitive, Vector3<f64>, Vector3<f64>)],
        (centre, length): (Vector3<f64>, f64),
    ) -> Self {
        let unitless = SerialChain::new(
            joints
                .iter()
                .map(|&(kind, axis, point)| {
                    let r = match kind {
                        Primitive::R => (point - centre) / length,
                        Primitive::P => Vector3::zeros(),
                    };
                    (kind, axis, r)
                })
                .collect(),
        )
        .expect("the joints of a leg have unit axes and finite points");
        let twists = |q: &[f64]| {
            let j = unitless.jacobian(q);
            DMatrix::from_column_slice(6, unitless.len(), j.as_slice())
        };
        let at_reference = twists(&vec![0.0; unitless.len()]);
        let reference = linalg::rank(&at_reference, linalg::DEFAULT_RANK_TOLERANCE);
        let mut rng = ChaCha8Rng::seed_from_u64(GENERIC_SEED);
        let mut generic: Option<(Rank, DMatrix<f64>)> = None;
        for _ in 0..GENERIC_SAMPLES {
            let m = twists(&random_configuration(&unitless, &mut rng));
            let r = linalg::rank(&m, linalg::DEFAULT_RANK_TOLERANCE);
            if generic.as_ref().is_none_or(|(g, _)| r.rank > g.rank) {
                generic = Some((r, m));
            }
        }
        let (generic, at_generic) =
            generic.unwrap_or_else(|| (reference.clone(), at_reference.clone()));
        let joints = unitless.len();
        LegCheck {
            leg,
            chain: chain.clone(),
            joints,
            length,
            dependent_at_reference: if reference.rank < joints {
                first_dependency(&at_reference)
            } else {
                Vec::new()
            },
            dependent_everywhere: if generic.rank < joints {
                first_dependency(&at_generic)
            } else {
                Vec::new()
            },
            reference,
            generic,
        }
    }

    /// [`LegCheck::new`] with the leg's own characteristic point and length (those of its
    /// revolute points, [`crate::mechanism::Mechanism::scale`]'s definition): for a leg checked
    /// before its manipulator exists (`kinsyn build`).
    #[must_use]
    pub fn standalone(
        leg: usize,
        chain: &Chain,
        joints: &[(Primitive, Vector3<f64>, Vector3<f64>)],
    ) -> Self {
        let revolutes: Vec<Vector3<f64>> = joints
            .iter()
            .filter(|j| j.0 == Primitive::R)
            .map(|j| j.2)
            .collect();
        Self::new(
            leg,
            chain,
            joints,
            crate::mechanism::characteristic_of(&revolutes),
        )
    }

    /// Whether the reference configuration is a leg singularity: the rank there is below the
    /// generic rank.
    #[must_use]
    pub fn is_singular(&self) -> bool {
        self.reference.rank < self.generic.rank
    }

    /// Whether some joints are dependent at every configuration: the generic rank is below the
    /// number of joints.
    #[must_use]
    pub fn has_dependent_joints(&self) -> bool {
        self.generic.rank < self.joints
    }

    /// The warnings of this leg: none for a leg whose joints are independent at generic values
    /// and whose reference is not singular.
    #[must_use]
    pub fn warnings(&self) -> Vec<LegWarning> {
        let mut out = Vec::new();
        let mut push = |kind| {
            out.push(LegWarning {
                kind,
                leg: self.leg,
                chain: self.chain.to_string(),
                joints: self.joints,
                reference_rank: self.reference.rank,
                generic_rank: self.generic.rank,
                dependent: match kind {
                    LegWarningKind::Singular => self.dependent_at_reference.clone(),
                    LegWarningKind::DependentJoints => self.dependent_everywhere.clone(),
                },
            });
        };
        if self.is_singular() {
            push(LegWarningKind::Singular);
        }
        if self.has_dependent_joints() {
            push(LegWarningKind::DependentJoints);
        }
        out
    }
}

/// What a [`LegWarning`] is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum LegWarningKind {
    /// The reference configuration is a leg singularity.
    Singular,
    /// Some joints are dependent at every configuration.
    DependentJoints,
}

/// A leg whose reference is singular or whose joints are dependent everywhere. Its `Display` is
/// one line naming the leg (1-based), its chain and the ranks.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct LegWarning {
    /// What is wrong.
    pub kind: LegWarningKind,
    /// 0-based leg.
    pub leg: usize,
    /// The leg's chain.
    pub chain: String,
    /// Number of primitive joints.
    pub joints: usize,
    /// Rank of the joint twists at the reference.
    pub reference_rank: usize,
    /// Rank at generic joint values.
    pub generic_rank: usize,
    /// The joints (1-based) of the dependency found (see [`LegCheck`]).
    pub dependent: Vec<usize>,
}

/// `1`, `1 and 2`, `1, 2 and 3`.
pub(crate) fn joint_list(joints: &[usize]) -> String {
    match joints {
        [] => String::new(),
        [one] => one.to_string(),
        [rest @ .., last] => format!(
            "{} and {last}",
            rest.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

impl LegWarning {
    /// The dependency in words, e.g. `joints 2 and 4 dependent` (empty when none was named).
    fn dependency(&self) -> String {
        if self.dependent.is_empty() {
            String::new()
        } else {
            format!("; joints {} dependent", joint_list(&self.dependent))
        }
    }
}

impl fmt::Display for LegWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let leg = self.leg + 1;
        match self.kind {
            LegWarningKind::Singular => write!(
                f,
                "leg {leg} ({}) is singular at the reference configuration: its {} joint twists have rank {} there, {} at generic joint values{}",
                self.chain,
                self.joints,
                self.reference_rank,
                self.generic_rank,
                self.dependency()
            ),
            LegWarningKind::DependentJoints => write!(
                f,
                "leg {leg} ({}) has joints dependent at every configuration: its {} joint twists have rank {} at generic joint values{}",
                self.chain,
                self.joints,
                self.generic_rank,
                self.dependency()
            ),
        }
    }
}

/// The first dependency among the columns of `m`: the first column in the span of those before
/// it, with those before it that take part (1-based). Empty when the columns are independent.
fn first_dependency(m: &DMatrix<f64>) -> Vec<usize> {
    for k in 1..=m.ncols() {
        let head = m.columns(0, k).into_owned();
        let r = linalg::rank(&head, linalg::DEFAULT_RANK_TOLERANCE);
        if r.rank < k {
            // Columns 0..k−1 are independent, so the null space of the first k is one vector:
            // the right singular vector of the smallest singular value.
            let v = linalg::svd(&head).v.column(k - 1).into_owned();
            let top = v.amax();
            return (0..k)
                .filter(|&i| v[i].abs() > DEPENDENCY_TOLERANCE * top)
                .map(|i| i + 1)
                .collect();
        }
    }
    Vec::new()
}

impl Manipulator {
    /// The rank check of every leg at the reference configuration (see the module
    /// documentation of `leg`).
    #[must_use]
    pub fn leg_checks(&self) -> Vec<LegCheck> {
        let joints = self.mechanism.joints();
        self.legs
            .iter()
            .enumerate()
            .map(|(i, leg)| {
                let primitives: Vec<(Primitive, Vector3<f64>, Vector3<f64>)> = joints
                    [leg.joints.clone()]
                .iter()
                .map(|j| (j.kind, j.axis, j.point))
                .collect();
                LegCheck::new(
                    i,
                    &leg.chain,
                    &primitives,
                    (self.mechanism.centre(), self.mechanism.scale()),
                )
            })
            .collect()
    }

    /// The warnings of every leg, leg by leg: empty for a manipulator whose legs are generic
    /// at the reference.
    #[must_use]
    pub fn leg_warnings(&self) -> Vec<LegWarning> {
        self.leg_checks()
            .iter()
            .flat_map(LegCheck::warnings)
            .collect()
    }
}

/// Two revolutes of one parallel group whose axes are not parallel.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ParallelFault {
    /// The group letter.
    pub group: char,
    /// The group's first revolute (0-based position in the leg).
    pub first: usize,
    /// The revolute at fault (0-based position in the leg).
    pub at: usize,
    /// The angle between the two axes, degrees (0 to 90).
    pub degrees: f64,
}

impl ParallelFault {
    /// The message of a description file's error at `axes[at]`, e.g. `marked 'a' in RaRaRa like
    /// axes[0], so the two must be parallel, but they are 90.000° apart`.
    pub(crate) fn message(&self, chain: &Chain) -> String {
        format!(
            "marked '{}' in {chain} like axes[{}], so the two must be parallel (a parallel group, docs/notation.md), but they are {:.3}° apart",
            self.group, self.first, self.degrees
        )
    }
}

/// Checks that the revolutes of each parallel group of `chain` (`Ra…Ra`, `U(-,a)U(a,-)`, see
/// docs/notation.md) have parallel axes (`|a₁ × a₂|` at most [`AXIS_TOLERANCE`] on unit axes;
/// opposite directions are parallel). The notation asserts nothing about revolutes that are
/// unmarked or in different groups, so they are not checked.
pub(crate) fn check_parallel_marks(
    chain: &Chain,
    axes: &[Vector3<f64>],
) -> Result<(), ParallelFault> {
    let mut first: [Option<usize>; 3] = [None; 3];
    for (k, (_, mark)) in chain.primitives().enumerate() {
        let Some(g) = mark.group else { continue };
        let Some(slot) = first.get_mut(usize::from(g)) else {
            continue;
        };
        let Some(f) = *slot else {
            *slot = Some(k);
            continue;
        };
        let (a, b) = (axes[f].normalize(), axes[k].normalize());
        let cross = a.cross(&b).norm();
        if cross > AXIS_TOLERANCE {
            return Err(ParallelFault {
                group: char::from(b'a' + g),
                first: f,
                at: k,
                degrees: cross.atan2(a.dot(&b).abs()).to_degrees(),
            });
        }
    }
    Ok(())
}
