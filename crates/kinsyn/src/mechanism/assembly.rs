//! Assembly: joint values that close every loop and, optionally, put one body where it is
//! asked to be: at a whole displacement, or at some coordinates of a frame fixed to it (the
//! position and rotation-vector components an analyst gives for a low-dof platform, whose other
//! coordinates, the parasitic motion, follow).
//!
//! The equations are solved by damped Newton steps (Levenberg–Marquardt) on their dimensionless
//! form (rotations in radians, lengths over [`Mechanism::scale`] about [`Mechanism::centre`]):
//! a step is kept only when it reduces the residual, and the damping grows until it does. Near a
//! regular solution the damping vanishes and the steps are Newton's, converging quadratically;
//! near a singular solution set (a configuration where the loop-closure Jacobian loses rank,
//! such as a mechanism built in a special pose) the damping keeps the steps from being thrown
//! along the nearly-null directions, where undamped least-squares steps wander off.

use super::{Mechanism, MechanismError, compose, inverse, log};
use crate::chain::Displacement;
use crate::linalg;
use crate::spatial::inverse_left_jacobian;
use nalgebra::{DMatrix, DVector};

/// The residual below which the loops count as closed and a goal as met: the largest
/// dimensionless component (radians, or lengths over the mechanism's characteristic length).
/// Coordinates of order 1 carry round-off of about 1e-16; 1e-10 leaves six orders for the
/// conditioning of the equations (docs/limits.md).
pub const ASSEMBLY_TOLERANCE: f64 = 1e-10;

/// The most damped Newton steps tried before an assembly is given up.
pub const ASSEMBLY_STEPS: usize = 100;

/// The steps taken after the tolerance is met, while they still reduce the residual.
const POLISHING_STEPS: usize = 2;

/// The settings of an assembly ([`Mechanism::assemble_with`]); the default is
/// [`ASSEMBLY_TOLERANCE`], [`ASSEMBLY_STEPS`] and two polishing steps, what
/// [`Mechanism::assemble_to`] uses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AssemblySettings {
    /// The largest dimensionless residual component (radians, or lengths over the mechanism's
    /// characteristic length) at which the loops count as closed and a goal as met.
    pub tolerance: f64,
    /// The most damped Newton steps tried before the assembly is given up.
    pub max_steps: usize,
    /// The steps taken after `tolerance` is met, each kept only while it reduces the residual
    /// (to round-off: derivatives by finite differences of assemblies need it).
    pub polishing_steps: usize,
}

impl Default for AssemblySettings {
    fn default() -> Self {
        AssemblySettings {
            tolerance: ASSEMBLY_TOLERANCE,
            max_steps: ASSEMBLY_STEPS,
            polishing_steps: POLISHING_STEPS,
        }
    }
}

/// A residual at the round-off of dimensionless coordinates of order one: no step can improve it.
const ROUND_OFF: f64 = 1e-14;

/// Limits a dimensionless Newton step so that no joint turns by more than half a radian (or
/// slides by half the length scale).
fn clamp_step(step: &mut DVector<f64>) {
    let largest = step.amax();
    if largest > 0.5 {
        *step *= 0.5 / largest;
    }
}

/// A coordinate of a frame's pose: its origin's position components, or its rotation vector's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Coordinate {
    /// Position along x.
    X,
    /// Position along y.
    Y,
    /// Position along z.
    Z,
    /// Rotation-vector component along x.
    Rx,
    /// Rotation-vector component along y.
    Ry,
    /// Rotation-vector component along z.
    Rz,
}

impl Coordinate {
    /// The six coordinates in the order x, y, z, rx, ry, rz.
    pub const ALL: [Coordinate; 6] = [
        Coordinate::X,
        Coordinate::Y,
        Coordinate::Z,
        Coordinate::Rx,
        Coordinate::Ry,
        Coordinate::Rz,
    ];

    /// The name used on the command line: `x`, `y`, `z`, `rx`, `ry`, `rz`.
    #[must_use]
    pub fn name(self) -> &'static str {
        ["x", "y", "z", "rx", "ry", "rz"][self.index()]
    }

    /// Position in [`Coordinate::ALL`].
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// Whether the coordinate is an angle (a rotation-vector component).
    #[must_use]
    pub fn is_angle(self) -> bool {
        self.index() >= 3
    }

    /// The coordinate's value for a frame at `g`: position, or rotation vector in radians.
    #[must_use]
    pub fn of(self, g: &Displacement) -> f64 {
        let i = self.index();
        if i < 3 {
            g.translation.vector[i]
        } else {
            super::rotation_log(&g.rotation)[i - 3]
        }
    }
}

/// Where a body of the mechanism is asked to be.
#[derive(Debug, Clone, PartialEq)]
pub enum Goal {
    /// The body at this displacement from its reference pose.
    Pose {
        /// The body.
        body: usize,
        /// Its displacement.
        displacement: Displacement,
    },
    /// A frame fixed to the body (at `frame` in the body's reference pose) with some of its
    /// coordinates at given values (radians for angles); the others are free.
    Coordinates {
        /// The body.
        body: usize,
        /// The frame's pose when the body is at its reference.
        frame: Displacement,
        /// The coordinates asked for and their values.
        values: Vec<(Coordinate, f64)>,
    },
    /// Several goals met at once, each on its own body: e.g. the poses of the coupler and the
    /// end-effector of a stack of modules, both given by Study parameters (paper 002 §5). The
    /// equations are the parts' equations stacked in order; a part may itself be `All`.
    All(Vec<Goal>),
}

impl Goal {
    /// The number of equations the goal adds.
    #[must_use]
    pub fn equations(&self) -> usize {
        match self {
            Goal::Pose { .. } => 6,
            Goal::Coordinates { values, .. } => values.len(),
            Goal::All(parts) => parts.iter().map(Goal::equations).sum(),
        }
    }

    /// The goal's body; for [`Goal::All`], its first part's (the ground, 0, when it has none).
    #[must_use]
    pub fn body(&self) -> usize {
        match self {
            Goal::Pose { body, .. } | Goal::Coordinates { body, .. } => *body,
            Goal::All(parts) => parts.first().map_or(0, Goal::body),
        }
    }

    /// The single-body goals the goal is made of, in order: itself, or the parts of
    /// [`Goal::All`] flattened.
    #[must_use]
    pub fn parts(&self) -> Vec<&Goal> {
        match self {
            Goal::All(parts) => parts.iter().flat_map(Goal::parts).collect(),
            single => vec![single],
        }
    }

    /// The goal's dimensionless equations at the body pose `g`: a matrix `C` that maps the
    /// body's dimensionless twist (ω; `v_c/L`) to the rates of the goal's quantities, and their
    /// errors `e` (goal met when `e = 0`; a step `Δ` of twist reduces them by `C Δ`).
    fn linearised(&self, m: &Mechanism, g: &Displacement) -> (DMatrix<f64>, DVector<f64>) {
        match self {
            Goal::Pose { displacement, .. } => {
                let error = log(&compose(g, &inverse(displacement))).to_vector();
                let unitless = m
                    .unitless_twists(&DMatrix::from_column_slice(6, 1, error.as_slice()))
                    .column(0)
                    .into_owned();
                (DMatrix::identity(6, 6), unitless)
            }
            Goal::Coordinates { frame, values, .. } => {
                let f = compose(g, frame);
                let (centre, length) = (m.centre(), m.scale());
                let arm = (f.translation.vector - centre) / length;
                let r = super::rotation_log(&f.rotation);
                let rotation_rates = inverse_left_jacobian(&r);
                let mut c = DMatrix::zeros(values.len(), 6);
                let mut e = DVector::zeros(values.len());
                for (row, &(coordinate, value)) in values.iter().enumerate() {
                    let i = coordinate.index();
                    if i < 3 {
                        // ṗ/L = v_c/L + ω × (p − c)/L.
                        let cross = -arm.cross_matrix();
                        for k in 0..3 {
                            c[(row, k)] = cross[(i, k)];
                        }
                        c[(row, 3 + i)] = 1.0;
                        e[row] = (f.translation.vector[i] - value) / length;
                    } else {
                        // ṙ = J_l⁻¹(r) ω for the spatial angular velocity ω.
                        for k in 0..3 {
                            c[(row, k)] = rotation_rates[(i - 3, k)];
                        }
                        e[row] = r[i - 3] - value;
                    }
                }
                (c, e)
            }
            // A composite goal adds no rows of its own: `equations` linearises its parts, one
            // body each (`Goal::parts`).
            Goal::All(_) => (DMatrix::zeros(0, 6), DVector::zeros(0)),
        }
    }
}

impl Mechanism {
    /// Closes the loops from `q` with the `locked` joints held, and meets `goal` when one is
    /// given, by damped Newton steps on the dimensionless equations (module documentation),
    /// with the default [`AssemblySettings`]. The solution found is the one the steps reach
    /// from `q`: for a mechanism with several assemblies, the one nearest `q` in this sense.
    ///
    /// # Errors
    /// [`MechanismError::NotAssembled`] when the largest dimensionless residual does not fall
    /// below [`ASSEMBLY_TOLERANCE`] within [`ASSEMBLY_STEPS`] steps, or a step stops reducing
    /// it (a configuration where the equations have no solution nearby).
    pub fn assemble_to(
        &self,
        q: &[f64],
        locked: &[bool],
        goal: Option<&Goal>,
    ) -> Result<Vec<f64>, MechanismError> {
        self.assemble_with(q, locked, goal, &AssemblySettings::default())
    }

    /// [`Mechanism::assemble_to`] with explicit settings: the tolerance, the most steps and the
    /// polishing steps.
    ///
    /// # Errors
    /// [`MechanismError::NotAssembled`] when the largest dimensionless residual does not fall
    /// below `settings.tolerance` within `settings.max_steps` steps, or a step stops reducing
    /// it (a configuration where the equations have no solution nearby).
    pub fn assemble_with(
        &self,
        q: &[f64],
        locked: &[bool],
        goal: Option<&Goal>,
        settings: &AssemblySettings,
    ) -> Result<Vec<f64>, MechanismError> {
        let free = self.free(locked);
        let mut q = q.to_vec();
        let (mut rows, mut residual) = self.equations(&q, goal);
        let mut norm = residual.norm();
        // Damping relative to the largest squared singular value of the step's matrix.
        let mut damping: f64 = 1e-12;
        // Once the tolerance is met, a few more steps polish the solution to round-off (each
        // is kept only if it helps): derivatives by finite differences of assemblies need it.
        let mut polish = 0;
        for iteration in 0..settings.max_steps {
            let polishing = residual.amax() < settings.tolerance;
            if polishing {
                polish += 1;
                if polish > settings.polishing_steps || residual.amax() < ROUND_OFF {
                    return Ok(q);
                }
            }
            let af = DMatrix::from_fn(rows.nrows(), free.len(), |r, k| rows[(r, free[k])]);
            // The Gauss–Newton step of least norm, by the Cholesky factor of the Gram matrix
            // when the equations are independent; kept when it reduces the residual, as the
            // least-damped step below would be. Otherwise (dependent equations, or no
            // decrease) the damped steps by SVD.
            if let Some(mut step) = linalg::min_norm_step(&af, &residual) {
                clamp_step(&mut step);
                let trial = self.stepped(&q, &free, &step);
                if trial.iter().all(|x| x.is_finite()) {
                    let (trial_rows, trial_residual) = self.equations(&trial, goal);
                    let trial_norm = trial_residual.norm();
                    if trial_norm < norm {
                        (q, rows, residual, norm) = (trial, trial_rows, trial_residual, trial_norm);
                        damping = (damping / 10.0).max(1e-20);
                        continue;
                    }
                }
            }
            let d = linalg::svd(&af);
            let top = d.singular_values.first().copied().unwrap_or(0.0);
            if top == 0.0 {
                break;
            }
            let projected = d.u.transpose() * &residual;
            let mut improved = false;
            while damping < 1e12 {
                let lambda = damping * top * top;
                let mut step = DVector::zeros(free.len());
                for (k, &s) in d.singular_values.iter().enumerate() {
                    if s > 1e-14 * top {
                        step += d.v.column(k) * (s / (s * s + lambda) * projected[k]);
                    }
                }
                clamp_step(&mut step);
                let trial = self.stepped(&q, &free, &step);
                if !trial.iter().all(|x| x.is_finite()) {
                    damping *= 10.0;
                    continue;
                }
                let (trial_rows, trial_residual) = self.equations(&trial, goal);
                let trial_norm = trial_residual.norm();
                if trial_norm < norm {
                    (q, rows, residual, norm) = (trial, trial_rows, trial_residual, trial_norm);
                    damping = (damping / 10.0).max(1e-20);
                    improved = true;
                    break;
                }
                if polishing {
                    // Polishing takes only steps that help at once.
                    break;
                }
                damping *= 10.0;
            }
            if !improved && residual.amax() < settings.tolerance {
                return Ok(q);
            }
            if !improved {
                return Err(MechanismError::NotAssembled {
                    residual: residual.amax(),
                    iterations: iteration + 1,
                });
            }
        }
        if residual.amax() < settings.tolerance {
            return Ok(q);
        }
        Err(MechanismError::NotAssembled {
            residual: residual.amax(),
            iterations: settings.max_steps,
        })
    }

    /// The assembly nearest to a goal that may lie off the constraint set: joint values that
    /// close every loop **exactly** (within `settings.tolerance`) and meet `goal` in the
    /// least-squares sense, the sum of squares of its dimensionless errors (radians, lengths
    /// over [`Mechanism::scale`]) smallest among the assemblies near `q`. This is the projection
    /// of rounded data (e.g. Study parameters printed to two decimals, paper 002 Table 1) onto
    /// the constraint set; when the goal can be met, the result is [`Mechanism::assemble_to`]'s.
    ///
    /// Gauss–Newton on the constrained problem: at each step the loops' linearised equations
    /// `C Δ = ε` are met by their least-norm solution `Δ₀ = C⁺ ε`, and the goal's `G Δ ≈ e` in
    /// least squares over the rest, `Δ = Δ₀ + N z`, `N` a basis of the null space of `C`
    /// (`z = (G N)⁺ (e − G Δ₀)`). It stops when a step is below `settings.tolerance`
    /// (dimensionless) and the loops are closed.
    ///
    /// # Errors
    /// [`MechanismError::NotAssembled`] when the loops are not closed within
    /// `settings.max_steps` steps or the steps do not settle.
    pub fn assemble_nearest(
        &self,
        q: &[f64],
        locked: &[bool],
        goal: &Goal,
        settings: &AssemblySettings,
    ) -> Result<Vec<f64>, MechanismError> {
        let free = self.free(locked);
        let mut q = q.to_vec();
        let goal_rows = goal.equations();
        let mut closure = f64::INFINITY;
        for _ in 0..settings.max_steps {
            let (rows, residual) = self.equations(&q, Some(goal));
            let loops = rows.nrows() - goal_rows;
            let a = DMatrix::from_fn(rows.nrows(), free.len(), |r, k| rows[(r, free[k])]);
            let c = a.rows(0, loops).into_owned();
            let g = a.rows(loops, goal_rows).into_owned();
            let ec = residual.rows(0, loops).into_owned();
            let eg = residual.rows(loops, goal_rows).into_owned();
            closure = ec.amax();
            let (base, null) = if loops == 0 {
                (
                    DVector::zeros(free.len()),
                    DMatrix::identity(free.len(), free.len()),
                )
            } else {
                let d = linalg::svd(&c);
                let top = d.singular_values.first().copied().unwrap_or(0.0);
                let cutoff = linalg::DEFAULT_RANK_TOLERANCE * top;
                let fit = linalg::least_squares(&c, &ec, cutoff);
                let (null, _) = linalg::nullspace(&c, linalg::DEFAULT_RANK_TOLERANCE);
                (fit.x, null)
            };
            let mut step = base.clone();
            if null.ncols() > 0 && goal_rows > 0 {
                let gn = &g * &null;
                let top = linalg::svd(&gn)
                    .singular_values
                    .first()
                    .copied()
                    .unwrap_or(0.0);
                let rest = linalg::least_squares(
                    &gn,
                    &(eg - &g * &base),
                    linalg::DEFAULT_RANK_TOLERANCE * top,
                );
                step += &null * rest.x;
            }
            clamp_step(&mut step);
            let size = step.amax();
            q = self.stepped(&q, &free, &step);
            if !q.iter().all(|x| x.is_finite()) {
                break;
            }
            if size < settings.tolerance && closure < settings.tolerance {
                return Ok(q);
            }
        }
        Err(MechanismError::NotAssembled {
            residual: closure,
            iterations: settings.max_steps,
        })
    }

    /// The joint values `q` moved by the dimensionless Newton `step` of the `free` joints (the
    /// step is subtracted: it is the change that cancels the residual's linear part).
    fn stepped(&self, q: &[f64], free: &[usize], step: &DVector<f64>) -> Vec<f64> {
        let mut trial = q.to_vec();
        for (k, &j) in free.iter().enumerate() {
            trial[j] -= step[k] * self.unit(j);
        }
        trial
    }

    /// The dimensionless equations at `q`: loop closure (6 rows per loop), then the goal's;
    /// their matrix over every joint (a joint step `Δ` changes the residual by `A Δ`) and the
    /// residual.
    pub(crate) fn equations(&self, q: &[f64], goal: Option<&Goal>) -> (DMatrix<f64>, DVector<f64>) {
        let poses = self.poses(q);
        let screws = self.screws_at(&poses);
        let closure = self.residual_at(q, &poses);
        let closure = self
            .unitless_twists(&DMatrix::from_column_slice(
                closure.len(),
                1,
                closure.as_slice(),
            ))
            .column(0)
            .into_owned();
        // The loop residual ε of a chord changes by −(V_b − V_a − ξ q̇) = −C q̇.
        let mut rows = -self.dimensionless(&self.closure_jacobian(&screws));
        let mut residual = closure;
        for part in goal.map(Goal::parts).unwrap_or_default() {
            let (c, e) = part.linearised(self, &poses[part.body()]);
            let body = c * self.dimensionless(&self.body_jacobian(part.body(), &screws));
            let n = rows.nrows();
            rows = rows.insert_rows(n, body.nrows(), 0.0);
            rows.view_mut((n, 0), body.shape()).copy_from(&body);
            residual = residual.insert_rows(n, e.len(), 0.0);
            residual.rows_mut(n, e.len()).copy_from(&e);
        }
        (rows, residual)
    }

    /// The degrees of freedom `body` keeps at `q` with the `locked` joints held and the
    /// `goal`'s quantities fixed: the rank of its twists over the joint rates that keep the
    /// loops closed and the goal met (dimensionless, default rank tolerance). Zero when the
    /// locks and the goal determine the body's pose.
    #[must_use]
    pub fn freedom_left(
        &self,
        body: usize,
        q: &[f64],
        locked: &[bool],
        goal: Option<&Goal>,
    ) -> usize {
        let free = self.free(locked);
        let (rows, _) = self.equations(q, goal);
        let a = DMatrix::from_fn(rows.nrows(), free.len(), |r, k| rows[(r, free[k])]);
        let (rates, _) = linalg::nullspace(&a, linalg::DEFAULT_RANK_TOLERANCE);
        let twists = self.dimensionless(&self.body_jacobian(body, &self.joint_screws(q)));
        let twists = DMatrix::from_fn(6, free.len(), |r, k| twists[(r, free[k])]);
        // Unit screws times an orthonormal basis: the scale is 1, whatever round-off is left.
        linalg::span_basis_scaled(&(twists * rates), linalg::DEFAULT_RANK_TOLERANCE, Some(1.0))
            .1
            .rank
    }
}

impl Mechanism {
    /// Closes the loops from `q` with the `locked` joints held, and when `target` is given also
    /// moves `body` to the displacement `target` from its reference pose
    /// ([`Mechanism::assemble_to`] with a [`Goal::Pose`]).
    ///
    /// # Errors
    /// [`MechanismError::NotAssembled`] when the residual does not fall below
    /// [`ASSEMBLY_TOLERANCE`] (rotation in radians, translation over the length scale).
    pub fn assemble(
        &self,
        q: &[f64],
        locked: &[bool],
        target: Option<(usize, &Displacement)>,
    ) -> Result<Vec<f64>, MechanismError> {
        let goal = target.map(|(body, g)| Goal::Pose {
            body,
            displacement: *g,
        });
        self.assemble_to(q, locked, goal.as_ref())
    }
}
