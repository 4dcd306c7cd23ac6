//! Series-parallel manipulators (S-PMs): parallel modules stacked in series, the moving platform
//! of each the base of the next, analysed by the kinematic Jacobian and the twist system of
//! paper 002 (Nayak, Caro, Wenger, *Local and full-cycle mobility analysis of a 3-RPS-3-SPR
//! series-parallel manipulator*, CK 2017), §3 eqs. 1–8 and §4 eqs. 9–10.
//!
//! This is a second method beside the general mechanism graph of [`kinsyn::mechanism`]: each
//! module is given by its geometry at one configuration ([`Module`]: the pose of its moving
//! platform and, per leg, the spherical-joint centre, the actuated prismatic direction and the
//! revolute axis), and the S-PM by the list of its modules ([`SeriesParallel`]).
//!
//! # Frames and twists (paper 002 §3)
//! Bodies are numbered 0 (the fixed base) to `n` (the end-effector); module `i` (1-based) joins
//! body `i − 1` to body `i`, and its geometry is expressed in the frame `F_{i−1}` of its lower
//! body. The paper's twists are `t = (ω; v_O)` with `O` the origin of a *moving* platform's
//! frame, not the origin of the frame the coordinates are taken in: the twist of module `i` is
//! `(ω; v_{O_i})` of body `i` relative to body `i − 1`, in `F_{i−1}` axes, and the S-PM's
//! Jacobian gives the end-effector twist `(ω; v_{O_n})` relative to the base in `F_0` axes. (The
//! twists of [`kinsyn::spatial`] take the velocity at the frame origin; [`reference_shift`]
//! converts.) Rows of the forward Jacobian `A` are wrenches written `(r × f; f)`, moment about
//! the moving origin first, so that a row times a twist is the virtual power `m·ω + f·v`.
//!
//! # Misprints (docs/deviations.md, "Paper 002 — 3-RPS-3-SPR")
//! - Eq. (5) prints the augmented rotation as `[[R, I], [I, R]]`; the change of frame of a
//!   twist is `[[R, 0], [0, R]]` ([`augmented_rotation`]). `tests/suite/series.rs` shows the
//!   block-diagonal form agrees with finite differences and the printed form does not; the
//!   printed form is kept as [`augmented_rotation_as_printed`] for that comparison.
//! - Eq. (8) indexes the modules from 0 in its Jacobian (`A_{M_0}`, …, `⁰R̄_n A_{M_n}`) but
//!   from 1 in the sum; the consistent reading, implemented here, is the block
//!   `⁰R̄_{i−1} ⁿAd_i A_{M_i}⁻¹ B_{M_i}` for module `i = 1 … n` (`⁰R̄_0 = I`, `ⁿAd_n = I`).
//!
//! ```
//! use kinsyn_papers::series::{Leg, Module, SeriesParallel};
//! use kinsyn::spatial::displacement;
//! use nalgebra::{Rotation3, Vector3};
//! // One 3-RPS module at its home pose: base circum-radius 2, platform circum-radius 1 at
//! // height 1.5, revolute axes tangent to the base circle.
//! let legs = [0.0_f64, 120.0, 240.0].map(|deg| {
//!     let (s, c) = deg.to_radians().sin_cos();
//!     let base = 2.0 * Vector3::new(c, s, 0.0);
//!     let centre = Vector3::new(c, s, 1.5);
//!     Leg { centre, actuation: (centre - base).normalize(), constraint: Vector3::new(-s, c, 0.0) }
//! });
//! let pose = displacement(Rotation3::identity(), Vector3::new(0.0, 0.0, 1.5));
//! let spm = SeriesParallel::new(vec![Module { pose, legs }]).unwrap();
//! let j = spm.jacobian().unwrap();
//! // A 3-RPS alone has three degrees of freedom: the rank of its 6×3 Jacobian.
//! let rank = kinsyn::screw::rank(&j, kinsyn::screw::DEFAULT_RANK_TOLERANCE);
//! assert_eq!(rank.rank, 3);
//! ```

mod stack;
pub use stack::stack;

use kinsyn::screw::{self, DEFAULT_RANK_TOLERANCE, Rank, adjoint, reciprocal_complement};
use kinsyn::spatial::{Displacement, identity};
use nalgebra::{DMatrix, Matrix3, Matrix6, Matrix6x3, Rotation3, Vector3};

/// One leg of a module with an actuated prismatic joint and one constraint force (a 3-RPS or
/// 3-SPR leg), at one configuration, in the frame of the module's lower body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Leg {
    /// The spherical-joint centre the leg's actuation and constraint forces pass through: the
    /// S centre on the moving platform for an RPS leg, on the lower platform for an SPR leg
    /// (paper 002 eqs. 2, 3, 9).
    pub centre: Vector3<f64>,
    /// The unit direction `p_i` (`q_i` for SPR) of the actuated prismatic joint: the line of
    /// the actuation force.
    pub actuation: Vector3<f64>,
    /// The unit revolute axis `u_i` (`v_i` for SPR): the direction of the leg's constraint force
    /// (paper 002 §4).
    pub constraint: Vector3<f64>,
}

/// A three-legged parallel module at one configuration: its moving platform's pose and its
/// legs, all in the frame of its lower body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Module {
    /// The pose of the moving platform's frame `F_i` in the lower body's frame `F_{i−1}`:
    /// its origin `O_i` is `pose.translation`, its axes the columns of `pose.rotation`.
    pub pose: Displacement,
    /// The three legs, inputs `ρ̇_1, ρ̇_2, ρ̇_3` in this order.
    pub legs: [Leg; 3],
}

/// Errors of the series-parallel analysis.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SeriesError {
    /// An S-PM needs at least one module.
    #[error("a series-parallel manipulator needs at least one module")]
    NoModules,
    /// The forward Jacobian `A` of a module has rank below six: the module is in a parallel
    /// singularity (paper 002 §3, footnote 1) and eq. (7) does not apply there. Move the
    /// configuration away from it, or analyse the twist system instead
    /// ([`SeriesParallel::twist_system`]).
    #[error(
        "module {module} is in a parallel singularity: rank A = {rank} (smallest singular value \
         {smallest:.3e} of largest {largest:.3e}, relative tolerance {tolerance:.1e})"
    )]
    ParallelSingularity {
        /// The module, 1-based as in the paper.
        module: usize,
        /// The rank of its forward Jacobian `A`.
        rank: usize,
        /// Its smallest singular value.
        smallest: f64,
        /// Its largest singular value.
        largest: f64,
        /// The relative tolerance the rank was judged with.
        tolerance: f64,
    },
}

/// Which augmented rotation `⁰R̄_{i−1}` carries a module's twist from its lower body's frame to
/// the base frame (paper 002 eq. 5).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AugmentedRotation {
    /// `[[R, 0], [0, R]]`: the change of frame of a twist ([`augmented_rotation`]).
    BlockDiagonal,
    /// `[[R, I], [I, R]]` as printed in eq. (5) — a misprint kept for the comparison in
    /// `tests/suite/series.rs` ([`augmented_rotation_as_printed`]).
    AsPrinted,
}

/// The augmented rotation `⁰R̄_1 = [[R, 0], [0, R]]` (paper 002 eq. 5, corrected): a twist
/// `(ω; v_P)` in `F_1` axes becomes the same twist in `F_0` axes, `R = ⁰R_1` the orientation of
/// `F_1` in `F_0`. It is the adjoint of the pure rotation.
#[must_use]
pub fn augmented_rotation(rotation: &Rotation3<f64>) -> Matrix6<f64> {
    adjoint(rotation, &Vector3::zeros())
}

/// The augmented rotation exactly as eq. (5) of paper 002 prints it, `[[R, I], [I, R]]`. It is
/// not a change of frame (it mixes angular and linear velocity); kept only to show, in
/// `tests/suite/series.rs`, that it disagrees with finite differences (docs/deviations.md).
#[must_use]
pub fn augmented_rotation_as_printed(rotation: &Rotation3<f64>) -> Matrix6<f64> {
    let mut m = Matrix6::identity();
    m.fixed_view_mut::<3, 3>(0, 0).copy_from(rotation.matrix());
    m.fixed_view_mut::<3, 3>(3, 3).copy_from(rotation.matrix());
    m.fixed_view_mut::<3, 3>(0, 3)
        .copy_from(&Matrix3::identity());
    m.fixed_view_mut::<3, 3>(3, 0)
        .copy_from(&Matrix3::identity());
    m
}

/// The screw transformation `ⁿAd_i = [[I, 0], [−[r_{O_i O_n}], I]]` (paper 002 eqs. 4, 8): the
/// twist `(ω; v_{O_i})` of a body becomes `(ω; v_{O_n})`, the velocity of its point at `O_n`,
/// in the same axes (`v_{O_n} = v_{O_i} + ω × r_{O_i O_n}`). It is [`adjoint`] of the
/// translation `O_i − O_n`.
#[must_use]
pub fn reference_shift(from: &Vector3<f64>, to: &Vector3<f64>) -> Matrix6<f64> {
    adjoint(&Rotation3::identity(), &(from - to))
}

impl Module {
    /// The forward Jacobian `A` (paper 002 eqs. 2, 3): rows 1–3 the actuation wrenches, forces
    /// along `p_i` through the S centres, rows 4–6 the constraint wrenches, forces along `u_i`
    /// through the S centres, each written `(r_{O_i S} × f; f)` with moments about the moving
    /// platform's origin `O_i`, in the lower body's axes. `A t = B ρ̇` for the twist
    /// `t = (ω; v_{O_i})` of the moving platform relative to the lower body.
    #[must_use]
    pub fn forward_jacobian(&self) -> Matrix6<f64> {
        let origin = self.pose.translation.vector;
        let mut a = Matrix6::zeros();
        for (i, leg) in self.legs.iter().enumerate() {
            let r = leg.centre - origin;
            for (row, f) in [(i, leg.actuation), (i + 3, leg.constraint)] {
                a.fixed_view_mut::<1, 3>(row, 0)
                    .copy_from(&r.cross(&f).transpose());
                a.fixed_view_mut::<1, 3>(row, 3).copy_from(&f.transpose());
            }
        }
        a
    }

    /// The inverse Jacobian `B = [I; 0]` (paper 002 eqs. 2, 3): the actuated rates drive the
    /// actuation wrenches' rows, the constraint rows are zero.
    #[must_use]
    pub fn inverse_jacobian() -> Matrix6x3<f64> {
        let mut b = Matrix6x3::zeros();
        b.fixed_view_mut::<3, 3>(0, 0)
            .copy_from(&Matrix3::identity());
        b
    }

    /// `A⁻¹ B`: the moving platform's twist `(ω; v_{O_i})` relative to the lower body, in the
    /// lower body's axes, per unit rate of each actuated joint (one column per leg).
    ///
    /// # Errors
    /// [`SeriesError::ParallelSingularity`] when rank `A` < 6 at [`DEFAULT_RANK_TOLERANCE`]
    /// (`module` is reported as 1; [`SeriesParallel::jacobian`] numbers the modules).
    pub fn input_twists(&self) -> Result<Matrix6x3<f64>, SeriesError> {
        let a = self.forward_jacobian();
        let dynamic = DMatrix::from_column_slice(6, 6, a.as_slice());
        let rank = screw::rank(&dynamic, DEFAULT_RANK_TOLERANCE);
        let singular = |rank: &Rank| SeriesError::ParallelSingularity {
            module: 1,
            rank: rank.rank,
            smallest: rank.singular_values.last().copied().unwrap_or(0.0),
            largest: rank.scale,
            tolerance: rank.tolerance,
        };
        if rank.rank < 6 {
            return Err(singular(&rank));
        }
        a.lu()
            .solve(&Self::inverse_jacobian())
            .ok_or_else(|| singular(&rank))
    }

    /// The constraint wrench system of the module (paper 002 eq. 9): one pure force per leg
    /// along its revolute axis through its S centre, as columns `(f; m)` (kinsyn's wrench
    /// order, ARCHITECTURE.md's conventions) with moments about `reference`, in the lower body's axes.
    #[must_use]
    pub fn constraint_wrenches(&self, reference: &Vector3<f64>) -> Matrix6x3<f64> {
        let mut w = Matrix6x3::zeros();
        for (j, leg) in self.legs.iter().enumerate() {
            let f = leg.constraint;
            let m = (leg.centre - reference).cross(&f);
            w.fixed_view_mut::<3, 1>(0, j).copy_from(&f);
            w.fixed_view_mut::<3, 1>(3, j).copy_from(&m);
        }
        w
    }
}

/// The twist system of an S-PM (paper 002 eq. 10): each module's twist system in the base
/// frame, their direct sum, and its order.
#[derive(Debug, Clone, PartialEq)]
pub struct TwistSystem {
    /// Per module, an orthonormal basis (columns `(ω; v_{O_n})`, `F_0` axes) of the twists of
    /// its moving platform relative to its lower body reciprocal to its constraint wrenches.
    pub modules: Vec<DMatrix<f64>>,
    /// All the modules' twists side by side (6 × the sum of their orders).
    pub twists: DMatrix<f64>,
    /// The order of the direct sum `⁰T_{S-PM}`: the rank of [`TwistSystem::twists`] with its
    /// singular values (the local mobility, paper 002 §4).
    pub order: Rank,
    /// A basis of the S-PM's constraint wrench system, the intersection of the modules'
    /// (columns `(f; m)`, moments about `O_n`, `F_0` axes): the wrenches reciprocal to every
    /// twist of [`TwistSystem::twists`].
    pub constraint_wrenches: DMatrix<f64>,
}

/// A series-parallel manipulator: modules in series from the base (module 1) to the
/// end-effector (module `n`).
#[derive(Debug, Clone, PartialEq)]
pub struct SeriesParallel {
    modules: Vec<Module>,
}

impl SeriesParallel {
    /// The S-PM of these modules, base first.
    ///
    /// # Errors
    /// [`SeriesError::NoModules`] for an empty list.
    pub fn new(modules: Vec<Module>) -> Result<Self, SeriesError> {
        if modules.is_empty() {
            return Err(SeriesError::NoModules);
        }
        Ok(SeriesParallel { modules })
    }

    /// The modules, base first.
    #[must_use]
    pub fn modules(&self) -> &[Module] {
        &self.modules
    }

    /// The pose of every body's frame in the base frame: `⁰g_0 = I, ⁰g_1, …, ⁰g_n`.
    #[must_use]
    pub fn poses(&self) -> Vec<Displacement> {
        let mut poses = vec![identity()];
        for m in &self.modules {
            let last = poses[poses.len() - 1];
            poses.push(last * m.pose);
        }
        poses
    }

    /// Per module `i`, the frame change `⁰R̄_{i−1}` (as chosen) times the reference shift
    /// `ⁿAd_i` (from `O_i` to `O_n`, in `F_{i−1}` axes): the map from the module's twist to its
    /// contribution to the end-effector twist, paper 002 eq. (8).
    fn to_end_effector(&self, reading: AugmentedRotation) -> Vec<Matrix6<f64>> {
        let poses = self.poses();
        let n = self.modules.len();
        (1..=n)
            .map(|i| {
                let lower = &poses[i - 1];
                // O_i and O_n in F_{i−1}.
                let relative = lower.inverse() * poses[n];
                let shift = reference_shift(
                    &self.modules[i - 1].pose.translation.vector,
                    &relative.translation.vector,
                );
                // Module 1's twist is in F_0 already: eqs. (7)–(8) have no R̄ on its block.
                let rotation = match reading {
                    _ if i == 1 => Matrix6::identity(),
                    AugmentedRotation::BlockDiagonal => augmented_rotation(&lower.rotation),
                    AugmentedRotation::AsPrinted => augmented_rotation_as_printed(&lower.rotation),
                };
                rotation * shift
            })
            .collect()
    }

    /// The kinematic Jacobian `J_{6×3n}` (paper 002 eq. 8, read with module `i`'s block
    /// `⁰R̄_{i−1} ⁿAd_i A_{M_i}⁻¹ B_{M_i}`; for two modules eq. 7's `J_S-PM`): the end-effector
    /// twist `(ω; v_{O_n})` relative to the base, in `F_0` axes, is `J ρ̇` with `ρ̇` the actuated
    /// rates, module by module. Its rank is the local mobility.
    ///
    /// # Errors
    /// [`SeriesError::ParallelSingularity`] when a module's `A` is singular.
    pub fn jacobian(&self) -> Result<DMatrix<f64>, SeriesError> {
        self.jacobian_with(AugmentedRotation::BlockDiagonal)
    }

    /// [`SeriesParallel::jacobian`] with the augmented rotation of choice: the block-diagonal
    /// one (correct) or the one printed in eq. (5) (for the comparison of docs/deviations.md).
    ///
    /// # Errors
    /// [`SeriesError::ParallelSingularity`] when a module's `A` is singular.
    pub fn jacobian_with(&self, reading: AugmentedRotation) -> Result<DMatrix<f64>, SeriesError> {
        let maps = self.to_end_effector(reading);
        let mut j = DMatrix::zeros(6, 3 * self.modules.len());
        for (i, (module, map)) in self.modules.iter().zip(&maps).enumerate() {
            let twists = module.input_twists().map_err(|e| match e {
                SeriesError::ParallelSingularity {
                    rank,
                    smallest,
                    largest,
                    tolerance,
                    ..
                } => SeriesError::ParallelSingularity {
                    module: i + 1,
                    rank,
                    smallest,
                    largest,
                    tolerance,
                },
                SeriesError::NoModules => SeriesError::NoModules,
            })?;
            j.fixed_view_mut::<6, 3>(0, 3 * i)
                .copy_from(&(map * twists));
        }
        Ok(j)
    }

    /// The twist system of the S-PM (paper 002 §4, eqs. 9–10): for each module, its
    /// constraint wrenches with moments about the end-effector origin `O_n` (eq. 9), their
    /// reciprocal complement (the module's twist system, [`reciprocal_complement`], which is
    /// symmetric in twists and wrenches), carried to `F_0` by the augmented rotation; then the
    /// order of their direct sum (rank at relative `tolerance`, with its singular values) and
    /// the S-PM's constraint wrench system. No module needs to be free of parallel
    /// singularities.
    #[must_use]
    pub fn twist_system(&self, tolerance: f64) -> TwistSystem {
        let poses = self.poses();
        let n = self.modules.len();
        let modules: Vec<DMatrix<f64>> = self
            .modules
            .iter()
            .enumerate()
            .map(|(i, module)| {
                let lower = &poses[i];
                let end = (lower.inverse() * poses[n]).translation.vector;
                let wrenches = module.constraint_wrenches(&end);
                let wrenches = DMatrix::from_column_slice(6, 3, wrenches.as_slice());
                let twists = reciprocal_complement(&wrenches, tolerance);
                let rotation = augmented_rotation(&lower.rotation);
                DMatrix::from_column_slice(6, 6, rotation.as_slice()) * twists
            })
            .collect();
        let total = modules.iter().map(DMatrix::ncols).sum();
        let mut twists = DMatrix::zeros(6, total);
        let mut next = 0;
        for m in &modules {
            twists.columns_mut(next, m.ncols()).copy_from(m);
            next += m.ncols();
        }
        let order = screw::rank(&twists, tolerance);
        let constraint_wrenches = reciprocal_complement(&twists, tolerance);
        TwistSystem {
            modules,
            twists,
            order,
            constraint_wrenches,
        }
    }
}
