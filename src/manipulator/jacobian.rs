//! Forward and inverse Jacobians of a parallel manipulator from reciprocal screws, in the form of
//! paper 000 eqs. 11, 18–21: `J_D [v_P; ω] = J_I q̇_a`.
//!
//! Every row of `J_D` is a wrench `(f; m_P)` written at the reference point P, acting on the
//! platform twist `(v_P; ω)` by the virtual power `f·v_P + m_P·ω`:
//! - the **wrench of a joint** in its leg is reciprocal to every other joint of the leg and not to
//!   that joint. For an actuated joint it is the actuation wrench: `W·t = (W·$_a) q̇_a`, so its
//!   `J_I` entry is `W·$_a`. For the UPS leg's prismatic joint this is the force along the leg
//!   through the S centre, `(u_c; u_c × GP)` with entry 1 (eq. 10–11); for the U's first
//!   revolute α it is the force along `u_β` through the S centre, `(u_β; u_β × GP)` with entry
//!   `c (u_β × u_α)·u_c` (eqs. 16–19).
//! - a **locked** input's wrench stays in `J_D` with a zero row in `J_I`: a constraint equation
//!   (eqs. 20–22: locking α turns the 3-UPS into the 3-RPS, `u_β·v_P + (u_β × GP)·ω = 0`).
//! - a leg with fewer than six independent joints adds its **structural constraint wrenches**
//!   (the wrench system reciprocal to its twist system) as further zero-input rows.
//!
//! Normalisation: a row has a unit force (a unit moment when it is a couple); an actuation row's
//! sign makes its `J_I` entry positive, a constraint row's sign makes its first non-zero entry
//! positive. When a leg has structural constraints, a joint's wrench is only defined modulo them;
//! the representative taken has its force orthogonal to theirs (Euclidean in the six components
//! at P when their forces are dependent), which gives the paper's rows for the RPS leg.

use super::Manipulator;
use crate::mechanism::SampleSettings;
use crate::screw::{self, DEFAULT_RANK_TOLERANCE, Wrench};
use nalgebra::{DMatrix, Vector3};
use serde::Serialize;

/// What a row of `J_D` stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum RowKind {
    /// The actuation wrench of a free input (index into the manipulator's actuators).
    Actuation {
        /// The actuator.
        actuator: usize,
    },
    /// The wrench of a locked input: a constraint equation.
    Locked {
        /// The actuator.
        actuator: usize,
    },
    /// A structural constraint wrench of a leg (0-based).
    Constraint {
        /// The leg.
        leg: usize,
    },
}

/// One row of `J_D`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WrenchRow {
    /// What the row stands for.
    #[serde(flatten)]
    pub kind: RowKind,
    /// The wrench `(f; m_P)` at P: the row of `J_D`.
    pub wrench: [f64; 6],
    /// Its `J_I` entry (`W·$_a` for an actuation row, 0 otherwise).
    pub input: f64,
}

/// The Jacobians at one configuration with some inputs locked.
#[derive(Debug, Clone, PartialEq)]
pub struct Jacobians {
    /// P in the ground frame.
    pub point: Vector3<f64>,
    /// The rows: free inputs, locked inputs, structural constraints.
    pub rows: Vec<WrenchRow>,
    /// The free inputs (indices into the actuators), the columns of `J_I`.
    pub free: Vec<usize>,
    /// Inputs that have no wrench at this configuration (their joint is dependent on the others
    /// of its leg: a leg singularity).
    pub without_wrench: Vec<usize>,
    /// `J_D`: one row per wrench, columns `(v_P; ω)`.
    pub jd: DMatrix<f64>,
    /// `J_I`: one row per wrench, one column per free input.
    pub ji: DMatrix<f64>,
}

impl Jacobians {
    /// The rows that are constraint equations (locked inputs and structural constraints).
    #[must_use]
    pub fn constraint_rows(&self) -> DMatrix<f64> {
        let idx: Vec<usize> = (0..self.rows.len())
            .filter(|&r| !matches!(self.rows[r].kind, RowKind::Actuation { .. }))
            .collect();
        DMatrix::from_fn(idx.len(), 6, |r, c| self.jd[(idx[r], c)])
    }
}

/// Which kind of singularity (Gosselin–Angeles, and Zlatanov's constraint singularity).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SingularityKind {
    /// Inverse (serial): an input's rate has no effect on the platform (`J_I` loses rank).
    Inverse,
    /// Direct (parallel): the platform moves with all inputs held (`J_D` loses rank).
    Direct,
    /// Constraint: the legs' constraint wrenches become dependent; the platform gains a motion
    /// it does not have elsewhere.
    Constraint,
}

/// A singularity found at a configuration.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Singularity {
    /// Which kind.
    pub kind: SingularityKind,
    /// What dropped, with the numbers.
    pub detail: String,
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
    /// Dimension of the joint-rate null space of the loop closure (all free joints).
    pub mobility: usize,
    /// The platform's local degrees of freedom (dimension of its twist space).
    pub platform_dof: usize,
    /// The same from the wrenches: six minus the rank of the constraint rows.
    pub wrench_dof: usize,
    /// Rank of `J_D` (dimensionless: moments over the length scale).
    pub jd_rank: screw::Rank,
    /// Rank of the constraint rows.
    pub constraint_rank: screw::Rank,
    /// The ranks at nearby generic configurations (sampled), `(J_D, constraint rows)`.
    pub generic: (usize, usize),
    /// Singularities found.
    pub singularities: Vec<Singularity>,
}

/// A dimensionless copy of twists (translational rows over `scale`).
fn dimensionless(t: &DMatrix<f64>, scale: f64) -> DMatrix<f64> {
    let mut out = t.clone();
    for r in 3..6 {
        out.row_mut(r).scale_mut(1.0 / scale);
    }
    out
}

/// `Δ T`: the twists with their angular and linear halves swapped, so that a wrench `w` acts on
/// them by the plain product `wᵀ (Δ T)`.
fn swap_blocks(t: &DMatrix<f64>) -> DMatrix<f64> {
    let mut out = t.clone();
    out.rows_mut(0, 3).copy_from(&t.rows(3, 3));
    out.rows_mut(3, 3).copy_from(&t.rows(0, 3));
    out
}

/// The representative of the wrench system `b` (columns) modulo the system `s` (a subspace of
/// it) with the force part orthogonal to the forces of `s` (or the whole wrench orthogonal when
/// the forces of `s` are dependent); `None` when `b` adds nothing to `s`.
fn modulo(b: &DMatrix<f64>, s: &DMatrix<f64>) -> Option<nalgebra::DVector<f64>> {
    if b.ncols() <= s.ncols() {
        return None;
    }
    if s.ncols() == 0 {
        return Some(b.column(0).into_owned());
    }
    let fs = s.rows(0, 3).into_owned();
    let fb = b.rows(0, 3).into_owned();
    let force_rank = screw::rank(&fs, DEFAULT_RANK_TOLERANCE).rank;
    let m = if force_rank == s.ncols() {
        fs.transpose() * fb
    } else {
        s.transpose() * b
    };
    let (null, _) = screw::nullspace(&m, 1e-8);
    let c = null.column(0).into_owned();
    Some(b * c)
}

impl Manipulator {
    /// The Jacobians `J_D`, `J_I` at joint values `q` with the `locked` inputs (indices into
    /// [`Manipulator::actuators`]) held.
    #[must_use]
    pub fn jacobians(&self, q: &[f64], locked: &[usize]) -> Jacobians {
        let m = &self.mechanism;
        let s = m.scale();
        let screws = m.joint_screws(q);
        let p = self.point(q);
        let mut actuation = Vec::new();
        let mut locked_rows = Vec::new();
        let mut constraints = Vec::new();
        let mut without_wrench = Vec::new();
        // A wrench from its dimensionless form (f'; m') at the origin: physical (f'; s m'),
        // normalised, with its moment about P.
        let physical = |w: &nalgebra::DVector<f64>| -> ([f64; 6], Vector3<f64>, Vector3<f64>) {
            let f = Vector3::new(w[0], w[1], w[2]);
            let mo = Vector3::new(w[3], w[4], w[5]) * s;
            let mp = mo - p.cross(&f);
            let norm = if f.norm() > 1e-9 * mp.norm() / s {
                f.norm()
            } else {
                mp.norm()
            };
            let (f, mo, mp) = (f / norm, mo / norm, mp / norm);
            ([f.x, f.y, f.z, mp.x, mp.y, mp.z], f, mo)
        };
        for (i, leg) in self.legs.iter().enumerate() {
            let joints: Vec<usize> = leg.joints.clone().collect();
            let t = DMatrix::from_fn(6, joints.len(), |r, c| screws[joints[c]].to_vector()[r]);
            let t = dimensionless(&t, s);
            // A leg of six independent joints: the wrenches of all its joints at once, the rows
            // of (Δ T)⁻¹ (w_j · $_k = δ_jk). Otherwise reciprocal complements, joint by joint.
            let dual = (t.ncols() == 6
                && screw::rank6(
                    &nalgebra::Matrix6xX::from_column_slice(t.as_slice()),
                    DEFAULT_RANK_TOLERANCE,
                ) == 6)
                .then(|| swap_blocks(&t).try_inverse())
                .flatten();
            let structural = if dual.is_some() {
                DMatrix::zeros(6, 0)
            } else {
                screw::reciprocal_complement(&t, DEFAULT_RANK_TOLERANCE)
            };
            for (a, act) in self
                .actuators
                .iter()
                .enumerate()
                .filter(|(_, a)| a.leg == i)
            {
                let wrench = match &dual {
                    Some(inverse) => Some(inverse.row(act.position).transpose()),
                    None => {
                        let others = t.clone().remove_column(act.position);
                        let b = screw::reciprocal_complement(&others, DEFAULT_RANK_TOLERANCE);
                        modulo(&b, &structural)
                    }
                };
                let Some(w) = wrench else {
                    without_wrench.push(a);
                    continue;
                };
                let (mut row, f, mo) = physical(&w);
                let mut input = screw::reciprocal_product(&Wrench { f, m: mo }, &screws[act.joint]);
                if input < 0.0 {
                    row = row.map(|x| -x);
                    input = -input;
                }
                if locked.contains(&a) {
                    locked_rows.push(WrenchRow {
                        kind: RowKind::Locked { actuator: a },
                        wrench: row,
                        input: 0.0,
                    });
                } else {
                    actuation.push(WrenchRow {
                        kind: RowKind::Actuation { actuator: a },
                        wrench: row,
                        input,
                    });
                }
            }
            for c in 0..structural.ncols() {
                let (mut row, _, _) = physical(&structural.column(c).into_owned());
                if row
                    .iter()
                    .find(|x| x.abs() > 1e-9)
                    .is_some_and(|&x| x < 0.0)
                {
                    row = row.map(|x| -x);
                }
                constraints.push(WrenchRow {
                    kind: RowKind::Constraint { leg: i },
                    wrench: row,
                    input: 0.0,
                });
            }
        }
        let free: Vec<usize> = (0..self.actuators.len())
            .filter(|a| !locked.contains(a))
            .collect();
        let rows: Vec<WrenchRow> = actuation
            .into_iter()
            .chain(locked_rows)
            .chain(constraints)
            .collect();
        let jd = DMatrix::from_fn(rows.len(), 6, |r, c| rows[r].wrench[c]);
        let mut ji = DMatrix::zeros(rows.len(), free.len());
        for (r, row) in rows.iter().enumerate() {
            if let RowKind::Actuation { actuator } = row.kind
                && let Some(col) = free.iter().position(|&a| a == actuator)
            {
                ji[(r, col)] = row.input;
            }
        }
        Jacobians {
            point: p,
            rows,
            free,
            without_wrench,
            jd,
            ji,
        }
    }

    /// The rank of rows `(f; m_P)` made dimensionless (moments over the length scale).
    fn wrench_rank(&self, rows: &DMatrix<f64>) -> screw::Rank {
        let mut d = rows.transpose();
        for r in 3..6 {
            d.row_mut(r).scale_mut(1.0 / self.mechanism.scale());
        }
        screw::rank(&d, DEFAULT_RANK_TOLERANCE)
    }

    /// Jacobians, mobility and singularities at the assembled configuration `q` with the
    /// `locked` inputs held. Singularities are rank drops against the ranks at nearby
    /// configurations reached by finite motion (`settings`), and inputs whose `J_I` entry
    /// vanishes.
    ///
    /// # Errors
    /// When the nearby configurations cannot be reached (the configuration is not assembled).
    pub fn analyse(
        &self,
        q: &[f64],
        locked: &[usize],
        settings: &SampleSettings,
    ) -> Result<Analysis, super::ManipulatorError> {
        let mask = self.lock_mask(locked);
        let m = &self.mechanism;
        let jacobians = self.jacobians(q, locked);
        let mobility = m.mobility(q, &mask).dof;
        let (_, platform_dof) = m.twist_space(self.platform, q, &mask);
        let jd_rank = self.wrench_rank(&jacobians.jd);
        let constraint_rank = self.wrench_rank(&jacobians.constraint_rows());
        // Generic ranks: at configurations reached by the platform's finite motion with every
        // input free (so that the walk can leave the pose).
        let samples = m.sample_motion(self.platform, q, &vec![false; mask.len()], settings)?;
        let mut generic = (jd_rank.rank, constraint_rank.rank);
        for sample in &samples {
            let j = self.jacobians(&sample.q, locked);
            generic.0 = generic.0.max(self.wrench_rank(&j.jd).rank);
            generic.1 = generic.1.max(self.wrench_rank(&j.constraint_rows()).rank);
        }
        let mut singularities = Vec::new();
        let s = m.scale();
        for (col, &a) in jacobians.free.iter().enumerate() {
            let entry = jacobians.ji.column(col).amax();
            let act = &self.actuators[a];
            let dimensionless = if act.kind == crate::notation::Primitive::R {
                entry / s
            } else {
                entry
            };
            if jacobians.without_wrench.contains(&a) || dimensionless < 1e-9 {
                singularities.push(Singularity {
                    kind: SingularityKind::Inverse,
                    detail: format!(
                        "input {} has no effect on the platform (J_I entry {entry:.3e})",
                        act.label()
                    ),
                });
            }
        }
        if constraint_rank.rank < generic.1 {
            singularities.push(Singularity {
                kind: SingularityKind::Constraint,
                detail: format!(
                    "constraint wrenches of rank {} here, {} nearby (singular values {})",
                    constraint_rank.rank,
                    generic.1,
                    values(&constraint_rank.singular_values)
                ),
            });
        }
        if generic.0 < 6 {
            singularities.push(Singularity {
                kind: SingularityKind::Direct,
                detail: format!(
                    "the held inputs and constraints never fix the platform here or nearby: J_D of rank {} at every sampled configuration (too few inputs, or an architecture singularity)",
                    generic.0
                ),
            });
        }
        if jd_rank.rank < generic.0 {
            singularities.push(Singularity {
                kind: SingularityKind::Direct,
                detail: format!(
                    "J_D of rank {} here, {} nearby (singular values {})",
                    jd_rank.rank,
                    generic.0,
                    values(&jd_rank.singular_values)
                ),
            });
        }
        Ok(Analysis {
            locked: locked.to_vec(),
            q: q.to_vec(),
            wrench_dof: 6 - constraint_rank.rank,
            jacobians,
            mobility,
            platform_dof,
            jd_rank,
            constraint_rank,
            generic,
            singularities,
        })
    }
}

fn values(v: &[f64]) -> String {
    v.iter()
        .map(|x| format!("{x:.3e}"))
        .collect::<Vec<_>>()
        .join(" ")
}
