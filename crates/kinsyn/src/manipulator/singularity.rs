//! What a configuration of a manipulator is: its mobility, its platform dof, the ranks of its
//! Jacobians with their gaps, and its singularities, judged against the ranks at random
//! assemblies of the same mechanism (generic ranks).
//!
//! Kinds (Gosselin–Angeles, Zlatanov): **inverse** — a free input's joint depends on the other
//! joints of its leg (`J_I` loses rank); **leg** — a leg's joint twists lose rank; **constraint**
//! — the constraint wrenches lose rank and the platform gains a motion; **direct** — `J_D` loses
//! rank, or never reaches 6 (too few inputs, or an architecture singularity).

use super::Manipulator;
use super::jacobian::Jacobians;
use crate::linalg::Rank;
use crate::mechanism::{ImageRanks, SampleSettings};
use serde::Serialize;

/// Which kind of singularity (Gosselin–Angeles, and Zlatanov's constraint singularity).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SingularityKind {
    /// Inverse (serial): an input's rate has no effect on the platform (`J_I` loses rank).
    Inverse,
    /// Leg: a leg's joint twists lose rank; the platform loses a freedom it has at generic
    /// configurations.
    Leg,
    /// Direct (parallel): the platform moves with all inputs held (`J_D` loses rank).
    Direct,
    /// Constraint: the legs' constraint wrenches become dependent; the platform gains a motion
    /// it does not have elsewhere.
    Constraint,
}

/// A singularity found at a configuration: its kind and what dropped, with the numbers. In
/// JSON it is `{"kind", "detail"}`, the detail being the cause in words.
#[derive(Debug, Clone, PartialEq)]
pub struct Singularity {
    /// Which kind.
    pub kind: SingularityKind,
    /// What dropped, with the numbers.
    pub cause: SingularityCause,
}

impl Singularity {
    /// The cause in words (its [`Display`](std::fmt::Display)).
    #[must_use]
    pub fn detail(&self) -> String {
        self.cause.to_string()
    }
}

impl Serialize for Singularity {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct as _;
        let mut st = serializer.serialize_struct("Singularity", 2)?;
        st.serialize_field("kind", &self.kind)?;
        st.serialize_field("detail", &self.detail())?;
        st.end()
    }
}

/// What makes a configuration singular, with the ranks here and at generic configurations.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SingularityCause {
    /// With the end-effector held the free inputs keep more independent rates than at generic
    /// configurations (loop-closure Jacobian).
    #[error(
        "with the end-effector held, the free inputs keep {here} independent rate{s} here, {generic} at generic configurations (loop-closure Jacobian)",
        s = if *here == 1 { "" } else { "s" }
    )]
    InputsFreeWithEndEffectorHeld {
        /// Independent input rates here.
        here: usize,
        /// At generic configurations.
        generic: usize,
    },
    /// An input's joint depends on the other joints of its leg: it has no effect on the
    /// platform (an inverse singularity of the leg).
    #[error(
        "input {input} has no effect on the platform: its joint depends on the other joints of leg {leg} ({})",
        rank_text(leg_rank)
    )]
    InputWithoutEffect {
        /// The input's label.
        input: String,
        /// Its leg (1-based).
        leg: usize,
        /// The rank of the leg's joint twists here.
        leg_rank: Rank,
    },
    /// A leg's joint twists lose rank.
    #[error(
        "leg {leg} ({chain}) has joint twists of rank {} here, {generic} at generic configurations ({})",
        here.rank,
        rank_text(here)
    )]
    LegRank {
        /// The leg (1-based).
        leg: usize,
        /// Its chain.
        chain: String,
        /// The rank of its joint twists here.
        here: Rank,
        /// At generic configurations.
        generic: usize,
    },
    /// The legs' constraint wrenches become dependent: the platform gains a motion.
    #[error(
        "constraint wrenches of rank {} here, {generic} at generic configurations: the platform gains {} dof ({})",
        here.rank,
        generic - here.rank,
        rank_text(here)
    )]
    ConstraintRank {
        /// The rank of the constraint rows here.
        here: Rank,
        /// At generic configurations.
        generic: usize,
    },
    /// `J_D` (or, without leg-wrench Jacobians, the end-effector's freedom with every input
    /// held) is deficient at every generic configuration: too few inputs, or an architecture
    /// singularity.
    #[error("{}", if *leg_wrenches {
        format!("the held inputs and constraints never fix the platform: J_D of rank {generic} at every generic configuration (too few inputs, or an architecture singularity)")
    } else {
        format!("the held inputs never fix the end-effector: with every input held it keeps {} dof at every generic configuration (loop-closure Jacobian; too few inputs, or an architecture singularity)", 6 - generic)
    })]
    NeverFixed {
        /// The generic rank of `J_D` (six minus the end-effector's freedom).
        generic: usize,
        /// Whether `J_D` is the leg-wrench Jacobian of paper 000 (else the loop-closure form).
        leg_wrenches: bool,
    },
    /// `J_D` loses rank here: the platform moves with every input held.
    #[error("{}", if *leg_wrenches {
        format!("J_D of rank {} here, {generic} at generic configurations ({})", here.rank, rank_text(here))
    } else {
        format!("with every input held the end-effector keeps {} dof here, {} at generic configurations (loop-closure Jacobian)", 6 - here.rank, 6 - generic)
    })]
    JdRank {
        /// The rank of `J_D` here.
        here: Rank,
        /// At generic configurations.
        generic: usize,
        /// Whether `J_D` is the leg-wrench Jacobian of paper 000 (else the loop-closure form).
        leg_wrenches: bool,
    },
}

/// The ranks of a manipulator at generic configurations: at random assemblies of the same
/// mechanism around the configuration analysed ([`crate::mechanism::Mechanism::random_assemblies`]).
///
/// The assemblies are reached by continuation from the configuration, so they lie on its
/// component of the configuration space (another component has ranks of its own). A rank of a
/// matrix of fixed shape that depends analytically on the configuration can only drop at
/// special configurations of a component, so its generic value is its **largest** over the
/// random assemblies: one assembly that happens to lie near a singular set (an ill-conditioned
/// sample, whose smallest kept singular value falls under the tolerance) cannot lower it, and
/// no assembly can raise it. That is how `J_D`'s rank (leg-wrench Jacobians) and each leg's
/// rank are decided. A dimension of an image of the compatible rates (the end-effector's
/// freedom, the inputs' freedom with it held) is a difference of two such ranks
/// ([`crate::mechanism::ImageRanks`]) and moves either way at special configurations; its
/// generic value is the difference of the two ranks' largest values. `assemblies_below` counts
/// the assemblies at which some rank fell short of its generic value: the ones a minimum or a
/// majority would have let decide.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GenericRanks {
    /// Random assemblies that closed (the ranks below are over them).
    pub assemblies: usize,
    /// The rank of `J_D`: the largest over the assemblies (leg-wrench Jacobians), or six less
    /// the end-effector's generic freedom with every input held (loop-closure form).
    pub jd: usize,
    /// The rank of the constraint rows: six less the end-effector's generic freedom with the
    /// locked inputs held.
    pub constraint: usize,
    /// The largest rank of each leg's joint twists.
    pub legs: Vec<usize>,
    /// The independent rates the free inputs have with the end-effector held at generic
    /// configurations ([`Analysis::inputs_with_end_effector_held`]).
    pub inputs_with_end_effector_held: usize,
    /// The assemblies at which some rank fell short of its generic value (near a singular set,
    /// or at one): reported, not used.
    pub assemblies_below: usize,
}

/// The largest rank of each part of an image's rank decisions, over samples.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
struct MaxImage {
    equations: usize,
    stacked: usize,
}

impl MaxImage {
    fn add(&mut self, r: &ImageRanks) {
        self.equations = self.equations.max(r.equations.rank);
        self.stacked = self.stacked.max(r.stacked.rank);
    }

    fn below(&self, r: &ImageRanks) -> bool {
        r.equations.rank < self.equations || r.stacked.rank < self.stacked
    }

    fn dimension(&self) -> usize {
        self.stacked.saturating_sub(self.equations)
    }
}

/// Jacobians, mobility and singularities of a manipulator at one configuration.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The locked inputs.
    pub locked: Vec<usize>,
    /// The joint values.
    pub q: Vec<f64>,
    /// The Jacobians.
    pub jacobians: Jacobians,
    /// Dimension of the joint-rate null space of the loop closure (all free joints): the
    /// platform's degrees of freedom plus the legs' internal motions.
    pub mobility: usize,
    /// The rank decision of the (dimensionless) loop-closure Jacobian behind `mobility`.
    pub closure_rank: Rank,
    /// The platform's local degrees of freedom: six minus the rank of the constraint rows
    /// (the dimension of the twists reciprocal to them, [`Manipulator::platform_twists`]).
    pub platform_dof: usize,
    /// Rank of `J_D` (dimensionless), with its singular values and gap.
    pub jd_rank: Rank,
    /// Rank of the constraint rows (dimensionless), with its singular values and gap.
    pub constraint_rank: Rank,
    /// Rank of each leg's joint twists (dimensionless), with its singular values and gap.
    pub leg_ranks: Vec<Rank>,
    /// The ranks at generic configurations.
    pub generic: GenericRanks,
    /// Whether `J_D`, `J_I` are paper 000's leg-wrench Jacobians (every leg from the ground to
    /// the end-effector, [`Manipulator::has_leg_wrench_jacobians`]). When false, `jacobians`
    /// has no rows, and `jd_rank`, `constraint_rank` and `platform_dof` come from the
    /// loop-closure Jacobian ([`Manipulator::platform_twists`]): `jd_rank` is six minus the
    /// end-effector's dof with every input held, `constraint_rank` six minus its dof with the
    /// `locked` inputs held.
    pub leg_wrench_jacobians: bool,
    /// The independent rates the free inputs can have with the end-effector held still (from
    /// the loop-closure Jacobian): more than at generic configurations is an inverse
    /// singularity.
    pub inputs_with_end_effector_held: usize,
    /// Each moving body's local dof with the `locked` inputs held (the dimension of its twist
    /// space), in the order of [`Manipulator::bodies`].
    pub body_dof: Vec<usize>,
    /// Singularities found.
    pub singularities: Vec<Singularity>,
}

/// The number of random assemblies that decide the generic ranks, and their spread (radians;
/// prismatic values over the length scale).
pub(super) const GENERIC_ASSEMBLIES: usize = 4;
pub(super) const GENERIC_SPREAD: f64 = 0.3;

impl Manipulator {
    /// Jacobians, mobility and singularities at the assembled configuration `q` with the
    /// `locked` inputs held. Singularities are rank drops against the ranks at generic
    /// configurations: random assemblies of the same mechanism around `q`
    /// ([`crate::mechanism::Mechanism::random_assemblies`], seeded by `settings.seed`). A
    /// configuration that is singular along a whole neighbourhood of its own motion is still
    /// found, as long as the mechanism is generic elsewhere.
    ///
    /// # Errors
    /// When `q` is not assembled, or no random assembly around it closes.
    pub fn analyse(
        &self,
        q: &[f64],
        locked: &[usize],
        settings: &SampleSettings,
    ) -> Result<Analysis, super::ManipulatorError> {
        let mask = self.lock_mask(locked);
        let m = &self.mechanism;
        let q = m.assemble(q, &mask, None)?;
        let jacobians = self.jacobians(&q, locked);
        let closure = m.mobility(&q, &mask);
        let (mobility, closure_rank) = (closure.dof, closure.closure_rank);
        let (jd_rank, constraint_rank) = self.output_ranks(&q, locked, &jacobians);
        let platform_dof = 6 - constraint_rank.rank;
        let screws = m.joint_screws(&q);
        let leg_ranks: Vec<Rank> = self.leg_ranks(&screws);
        let generic = self.generic_ranks(&q, locked, settings)?;
        let inputs_with_end_effector_held = self.inputs_with_end_effector_held(&q, locked);
        let mut singularities =
            self.singularities(&jacobians, &leg_ranks, &jd_rank, &constraint_rank, &generic);
        if !self.has_leg_wrench_jacobians()
            && inputs_with_end_effector_held > generic.inputs_with_end_effector_held
        {
            // Without leg wrenches, an inverse singularity is seen on the loop closure: inputs
            // that move while the end-effector stays, more of them than generically.
            singularities.insert(
                0,
                Singularity {
                    kind: SingularityKind::Inverse,
                    cause: SingularityCause::InputsFreeWithEndEffectorHeld {
                        here: inputs_with_end_effector_held,
                        generic: generic.inputs_with_end_effector_held,
                    },
                },
            );
        }
        let body_dof = (0..self.bodies.len())
            .map(|b| self.body_twists(b, &q, locked).1)
            .collect();
        Ok(Analysis {
            leg_wrench_jacobians: self.has_leg_wrench_jacobians(),
            inputs_with_end_effector_held,
            body_dof,
            locked: locked.to_vec(),
            q,
            jacobians,
            mobility,
            closure_rank,
            platform_dof,
            jd_rank,
            constraint_rank,
            leg_ranks,
            generic,
            singularities,
        })
    }

    /// The ranks at random assemblies around `q` (every joint free, so that they can leave a
    /// singular set), with the `locked` inputs' rows as constraints.
    fn generic_ranks(
        &self,
        q: &[f64],
        locked: &[usize],
        settings: &SampleSettings,
    ) -> Result<GenericRanks, super::ManipulatorError> {
        let m = &self.mechanism;
        let assemblies = m.random_assemblies(
            q,
            &vec![false; m.joints().len()],
            GENERIC_ASSEMBLIES,
            GENERIC_SPREAD,
            settings.seed,
        );
        if assemblies.is_empty() {
            return Err(super::PositionError::NoGenericAssembly.into());
        }
        let all: Vec<usize> = (0..self.actuators.len()).collect();
        let leg_wrenches = self.has_leg_wrench_jacobians();
        let mut jd = 0;
        let mut legs = vec![0; self.legs.len()];
        let (mut held_all, mut held_locked, mut inputs) = (
            MaxImage::default(),
            MaxImage::default(),
            MaxImage::default(),
        );
        let mut per_sample = Vec::with_capacity(assemblies.len());
        for sample in &assemblies {
            let j = self.jacobians(sample, locked);
            let leg_ranks = j.leg_ranks.clone();
            let jd_here = if leg_wrenches {
                self.output_ranks(sample, locked, &j).0.rank
            } else {
                0
            };
            let ranks = (
                self.end_effector_freedom_ranks(sample, &all),
                self.end_effector_freedom_ranks(sample, locked),
                self.inputs_with_end_effector_held_ranks(sample, locked),
            );
            jd = jd.max(jd_here);
            for (g, &r) in legs.iter_mut().zip(&leg_ranks) {
                *g = (*g).max(r);
            }
            held_all.add(&ranks.0);
            held_locked.add(&ranks.1);
            inputs.add(&ranks.2);
            per_sample.push((jd_here, leg_ranks, ranks));
        }
        let assemblies_below = per_sample
            .iter()
            .filter(|(jd_here, leg_ranks, (a, l, i))| {
                (leg_wrenches && *jd_here < jd)
                    || leg_ranks.iter().zip(&legs).any(|(r, g)| r < g)
                    || held_all.below(a)
                    || held_locked.below(l)
                    || inputs.below(i)
            })
            .count();
        if !leg_wrenches {
            jd = 6usize.saturating_sub(held_all.dimension());
        }
        Ok(GenericRanks {
            assemblies: assemblies.len(),
            jd,
            constraint: 6usize.saturating_sub(held_locked.dimension()),
            legs,
            inputs_with_end_effector_held: inputs.dimension(),
            assemblies_below,
        })
    }

    /// The rank decisions behind the end-effector's freedom at `q` with the `locked` inputs
    /// held ([`crate::mechanism::Mechanism::twist_space_ranks`]).
    fn end_effector_freedom_ranks(&self, q: &[f64], locked: &[usize]) -> ImageRanks {
        self.mechanism
            .twist_space_ranks(self.platform, q, &self.lock_mask(locked))
    }

    /// The rank decisions behind [`Manipulator::inputs_with_end_effector_held`].
    fn inputs_with_end_effector_held_ranks(&self, q: &[f64], locked: &[usize]) -> ImageRanks {
        let joints: Vec<usize> = (0..self.actuators.len())
            .filter(|a| !locked.contains(a))
            .map(|a| self.actuators[a].joint)
            .collect();
        self.mechanism.joint_freedom_ranks_with_body_held(
            self.platform,
            q,
            &self.lock_mask(locked),
            &joints,
        )
    }

    /// How many independent rates the free inputs have at `q` with the `locked` inputs and the
    /// end-effector held ([`crate::mechanism::Mechanism::joint_freedom_with_body_held`]).
    fn inputs_with_end_effector_held(&self, q: &[f64], locked: &[usize]) -> usize {
        self.inputs_with_end_effector_held_ranks(q, locked)
            .dimension()
    }

    /// The singularities at a configuration, from its ranks against the generic ones.
    fn singularities(
        &self,
        j: &Jacobians,
        leg_ranks: &[Rank],
        jd_rank: &Rank,
        constraint_rank: &Rank,
        generic: &GenericRanks,
    ) -> Vec<Singularity> {
        let mut out = Vec::new();
        for &a in &j.free {
            let act = &self.actuators[a];
            if j.without_wrench.contains(&a) {
                out.push(Singularity {
                    kind: SingularityKind::Inverse,
                    cause: SingularityCause::InputWithoutEffect {
                        input: act.label(),
                        leg: act.leg + 1,
                        leg_rank: leg_ranks[act.leg].clone(),
                    },
                });
            }
        }
        for (i, (here, &elsewhere)) in leg_ranks.iter().zip(&generic.legs).enumerate() {
            if here.rank < elsewhere {
                out.push(Singularity {
                    kind: SingularityKind::Leg,
                    cause: SingularityCause::LegRank {
                        leg: i + 1,
                        chain: self.legs[i].chain.to_string(),
                        here: here.clone(),
                        generic: elsewhere,
                    },
                });
            }
        }
        if constraint_rank.rank < generic.constraint {
            out.push(Singularity {
                kind: SingularityKind::Constraint,
                cause: SingularityCause::ConstraintRank {
                    here: constraint_rank.clone(),
                    generic: generic.constraint,
                },
            });
        }
        let legs = self.has_leg_wrench_jacobians();
        if generic.jd < 6 {
            out.push(Singularity {
                kind: SingularityKind::Direct,
                cause: SingularityCause::NeverFixed {
                    generic: generic.jd,
                    leg_wrenches: legs,
                },
            });
        }
        if jd_rank.rank < generic.jd {
            out.push(Singularity {
                kind: SingularityKind::Direct,
                cause: SingularityCause::JdRank {
                    here: jd_rank.clone(),
                    generic: generic.jd,
                    leg_wrenches: legs,
                },
            });
        }
        out
    }
}

/// A rank decision in words: the rank, the gap (smallest kept and largest dropped singular
/// values over the largest) and the singular values.
#[must_use]
pub fn rank_text(r: &Rank) -> String {
    let (kept, dropped) = r.gap();
    format!(
        "rank {}, gap {kept:.3e} kept / {dropped:.3e} dropped, singular values {}",
        r.rank,
        r.singular_values
            .iter()
            .map(|x| format!("{x:.3e}"))
            .collect::<Vec<_>>()
            .join(" ")
    )
}
