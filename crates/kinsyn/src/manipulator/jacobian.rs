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
//! **Which wrench.** When a leg has structural constraints, a joint's wrench is defined only
//! modulo them: any wrench reciprocal to the other joints and *not* in the constraint span will
//! do, and the choice changes no rank (the constraint rows are in `J_D` too) and no `J_I` entry
//! (a constraint does no work on any joint of the leg). kinsyn first takes the direction of
//! that wrench system orthogonal to the constraint span in the dimensionless metric (forces, and
//! moments about the mechanism's centre over its characteristic length), so the wrench taken can
//! never be a constraint, whether the constraints are forces, couples or both. Within the coset
//! it then takes the representative with the **smallest force** and, among those, the
//! **smallest moment about P**: force orthogonal to the constraint forces, moment orthogonal to
//! the constraint couples. For the RPS leg this is the force along the leg through the S centre,
//! `(u_c; u_c × GP)`, eqs. 20–22; it does not depend on the length unit.
//!
//! Normalisation: a row has a unit force (a unit moment when it is a couple); an actuation row's
//! sign makes its `J_I` entry positive, a constraint row's sign makes its first non-zero entry
//! (dimensionless) positive.

use super::Manipulator;
use crate::linalg::{self, DEFAULT_RANK_TOLERANCE, Rank};
use crate::mechanism::Mechanism;
use crate::notation::Primitive;
use crate::screw::{self, Wrench};
use nalgebra::{DMatrix, DVector, Vector3};
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
    /// The same entry made dimensionless: the product of the row's wrench and the input's joint
    /// screw, each of unit size in the dimensionless metric (1 for a leg of six independent
    /// joints at a generic configuration; it tends to 0 at an inverse singularity).
    #[serde(skip)]
    pub unitless_input: f64,
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
    /// of its leg: an inverse singularity).
    pub without_wrench: Vec<usize>,
    /// The rank of each leg's joint twists (dimensionless, all joints of the leg).
    pub leg_ranks: Vec<usize>,
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

/// The force below which (relative to the dimensionless size of a unit wrench) a wrench counts
/// as a couple.
const COUPLE_TOLERANCE: f64 = 1e-8;

/// `Δ T`: the twists with their angular and linear halves swapped, so that a wrench `w` acts on
/// them by the plain product `wᵀ (Δ T)`.
fn swap_blocks(t: &DMatrix<f64>) -> DMatrix<f64> {
    let mut out = t.clone();
    out.rows_mut(0, 3).copy_from(&t.rows(3, 3));
    out.rows_mut(3, 3).copy_from(&t.rows(0, 3));
    out
}

/// A dimensionless wrench (moment about the centre) with its moment moved to the point whose
/// offset from the centre, over the length scale, is `offset`.
fn moment_at(w: &DVector<f64>, offset: &Vector3<f64>) -> DVector<f64> {
    let f = Vector3::new(w[0], w[1], w[2]);
    let m = Vector3::new(w[3], w[4], w[5]) - offset.cross(&f);
    DVector::from_column_slice(&[f.x, f.y, f.z, m.x, m.y, m.z])
}

/// The wrench of a joint in its leg, in the dimensionless form: `b` (columns) spans the
/// wrenches reciprocal to the leg's other joints, `s` (orthonormal columns) the leg's
/// constraints, a subspace of it. `None` when `b` adds nothing to `s` (the joint depends on the
/// others: an inverse singularity).
///
/// The direction of `b` orthogonal to `s` is never a constraint; of its coset modulo `s`, the
/// representative taken has the smallest force and then the smallest moment about P (`offset`:
/// P's offset from the centre over the length scale), see the module documentation.
fn joint_wrench(b: &DMatrix<f64>, s: &DMatrix<f64>, offset: &Vector3<f64>) -> Option<DVector<f64>> {
    // The part of b orthogonal to the constraints: its largest direction has unit size when the
    // joint is independent of the others, round-off when it is not.
    let projected = b - s * (s.transpose() * b);
    let d = linalg::svd(&projected);
    if d.singular_values.first().copied().unwrap_or(0.0) < 0.5 {
        return None;
    }
    let w0 = d.u.column(0).into_owned();
    if s.ncols() == 0 {
        return Some(w0);
    }
    // Smallest force: remove the constraint forces' share of the force. The basis is
    // orthonormal, so a constraint direction whose force is below the tolerance (relative to 1,
    // not to the other forces) is a couple.
    let forces = linalg::least_squares(
        &s.rows(0, 3).into_owned(),
        &w0.rows(0, 3).into_owned(),
        COUPLE_TOLERANCE,
    );
    let w1 = &w0 - s * &forces.x;
    // The constraint directions along which the force is round-off: the couples.
    let couples = forces.dropped;
    if couples.ncols() == 0 {
        return Some(w1);
    }
    // Then the smallest moment about P: remove the constraint couples' share of it.
    let sn = s * &couples;
    let moments = DMatrix::from_fn(3, sn.ncols(), |r, k| {
        moment_at(&sn.column(k).into_owned(), offset)[r + 3]
    });
    let z = linalg::least_squares(
        &moments,
        &moment_at(&w1, offset).rows(3, 3).into_owned(),
        COUPLE_TOLERANCE,
    );
    Some(w1 - sn * z.x)
}

/// A row of `J_D` from a dimensionless wrench `w` (about the centre, lengths over the scale):
/// the physical wrench and its row `(f; m_P)`, the moment about P (at `offset` from the centre,
/// in length-scale units), both scaled to a unit force, or to a unit moment for a couple.
fn physical_row(m: &Mechanism, w: &DVector<f64>, offset: &Vector3<f64>) -> (Wrench, [f64; 6]) {
    let at_p = moment_at(w, offset);
    let size = at_p.norm();
    let f = Vector3::new(at_p[0], at_p[1], at_p[2]);
    let mp = Vector3::new(at_p[3], at_p[4], at_p[5]) * m.scale();
    let norm = if f.norm() > COUPLE_TOLERANCE * size {
        f.norm()
    } else {
        mp.norm()
    };
    let wrench = m.physical_wrench(w.as_slice());
    let wrench = Wrench {
        f: wrench.f / norm,
        m: wrench.m / norm,
    };
    let (f, mp) = (f / norm, mp / norm);
    (wrench, [f.x, f.y, f.z, mp.x, mp.y, mp.z])
}

/// The wrenches of a leg with unitless joint twists `t` (one column per joint): for a leg of
/// six independent joints (certified by `rank6`), the wrenches of all its joints at once, the
/// rows of `(Δ T)⁻¹` (`w_j · $_k = δ_jk`), and no constraint wrench; otherwise no such inverse
/// (the joints' wrenches are then found as reciprocal complements, joint by joint) and the
/// leg's constraint wrenches, a basis of the wrenches reciprocal to all its joints.
fn leg_wrenches(t: &DMatrix<f64>) -> (Option<DMatrix<f64>>, DMatrix<f64>) {
    let dual = (t.ncols() == 6
        && linalg::rank6(
            &nalgebra::Matrix6xX::from_column_slice(t.as_slice()),
            DEFAULT_RANK_TOLERANCE,
        ) == 6)
        .then(|| swap_blocks(t).try_inverse())
        .flatten();
    let structural = if dual.is_some() {
        DMatrix::zeros(6, 0)
    } else {
        screw::reciprocal_complement(t, DEFAULT_RANK_TOLERANCE)
    };
    (dual, structural)
}

/// The constraint rows of leg `leg`: each wrench the leg's joints transmit whatever the inputs
/// (a column of `structural`, dimensionless) as a row of `J_D` ([`physical_row`]), its sign
/// chosen so that its first non-negligible component about P is positive.
fn constraint_rows(
    m: &Mechanism,
    structural: &DMatrix<f64>,
    offset: &Vector3<f64>,
    leg: usize,
) -> Vec<WrenchRow> {
    (0..structural.ncols())
        .map(|c| {
            let w = structural.column(c).into_owned();
            let (_, mut row) = physical_row(m, &w, offset);
            let unitless = moment_at(&w, offset);
            let first = unitless
                .iter()
                .copied()
                .find(|x| x.abs() > 1e-9 * unitless.norm());
            if first.is_some_and(|x| x < 0.0) {
                row = row.map(|x| -x);
            }
            WrenchRow {
                kind: RowKind::Constraint { leg },
                wrench: row,
                input: 0.0,
                unitless_input: 0.0,
            }
        })
        .collect()
}

impl Manipulator {
    /// The Jacobians `J_D`, `J_I` at joint values `q` with the `locked` inputs (indices into
    /// [`Manipulator::actuators`]) held.
    ///
    /// They are defined when every leg runs from the ground to the end-effector
    /// ([`Manipulator::has_leg_wrench_jacobians`]). Otherwise (legs between other bodies: a
    /// stack of modules, a platform of several bodies) a leg's wrenches do not act on the
    /// end-effector, and the result has **no rows** (`jd` 0 × 6, `ji` 0 × free inputs), only
    /// the free inputs, P and the legs' ranks; [`Manipulator::analyse`] then takes the
    /// end-effector's freedoms from the loop-closure Jacobian.
    #[must_use]
    pub fn jacobians(&self, q: &[f64], locked: &[usize]) -> Jacobians {
        if !self.has_leg_wrench_jacobians() {
            return self.without_leg_wrenches(q, locked);
        }
        let m = &self.mechanism;
        let scale = m.scale();
        let screws = m.joint_screws(q);
        let p = self.point(q);
        // P's offset from the centre, in length-scale units.
        let offset = (p - m.centre()) / scale;
        let mut actuation = Vec::new();
        let mut locked_rows = Vec::new();
        let mut constraints = Vec::new();
        let mut without_wrench = Vec::new();
        let mut leg_ranks = Vec::with_capacity(self.legs.len());
        for (i, leg) in self.legs.iter().enumerate() {
            let joints: Vec<usize> = leg.joints.clone().collect();
            let t = self.unitless_leg_twists(&screws, &joints);
            let (dual, structural) = leg_wrenches(&t);
            leg_ranks.push(6 - structural.ncols());
            for (a, act) in self
                .actuators
                .iter()
                .enumerate()
                .filter(|(_, a)| a.leg == i)
            {
                let wrench = if let Some(inverse) = &dual {
                    Some(inverse.row(act.position).transpose())
                } else {
                    let others = t.clone().remove_column(act.position);
                    let b = screw::reciprocal_complement(&others, DEFAULT_RANK_TOLERANCE);
                    joint_wrench(&b, &structural, &offset)
                };
                let Some(w) = wrench else {
                    without_wrench.push(a);
                    continue;
                };
                let (physical_wrench, mut row) = physical_row(m, &w, &offset);
                let mut input = screw::reciprocal_product(&physical_wrench, &screws[act.joint]);
                let screw_a = t.column(act.position);
                let mut unitless_input = (w.rows(0, 3).dot(&screw_a.rows(3, 3))
                    + w.rows(3, 3).dot(&screw_a.rows(0, 3)))
                    / (w.norm() * screw_a.norm());
                if input < 0.0 {
                    row = row.map(|x| -x);
                    input = -input;
                    unitless_input = -unitless_input;
                }
                if locked.contains(&a) {
                    locked_rows.push(WrenchRow {
                        kind: RowKind::Locked { actuator: a },
                        wrench: row,
                        input: 0.0,
                        unitless_input: 0.0,
                    });
                } else {
                    actuation.push(WrenchRow {
                        kind: RowKind::Actuation { actuator: a },
                        wrench: row,
                        input,
                        unitless_input,
                    });
                }
            }
            constraints.extend(constraint_rows(m, &structural, &offset, i));
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
            leg_ranks,
            jd,
            ji,
        }
    }

    /// The "Jacobians" of a manipulator whose legs do not all run from the ground to the
    /// end-effector: no rows, the free inputs, P and each leg's rank.
    fn without_leg_wrenches(&self, q: &[f64], locked: &[usize]) -> Jacobians {
        let screws = self.mechanism.joint_screws(q);
        let leg_ranks = self.leg_ranks(&screws).iter().map(|r| r.rank).collect();
        let free: Vec<usize> = (0..self.actuators.len())
            .filter(|a| !locked.contains(a))
            .collect();
        Jacobians {
            point: self.point(q),
            rows: Vec::new(),
            jd: DMatrix::zeros(0, 6),
            ji: DMatrix::zeros(0, free.len()),
            free,
            without_wrench: Vec::new(),
            leg_ranks,
        }
    }

    /// The end-effector's freedoms from the loop-closure Jacobian, for any manipulator: a basis
    /// of its twists `(v_P; ω)` (columns, physical units) with the `locked` inputs held, and the
    /// rank decision of the wrenches reciprocal to them (the dimensionless constraint wrench
    /// system on the end-effector: an orthonormal basis, so its rank is six minus the
    /// end-effector's dof, decided on its twist space).
    pub(super) fn closure_output(&self, q: &[f64], locked: &[usize]) -> (DMatrix<f64>, Rank) {
        let m = &self.mechanism;
        let screws = m.joint_screws(q);
        let (basis, _) = m.unitless_twist_space(self.platform, &screws, &self.lock_mask(locked));
        let wrenches = screw::reciprocal_complement(&basis, DEFAULT_RANK_TOLERANCE);
        let rank = linalg::rank(&wrenches, DEFAULT_RANK_TOLERANCE);
        let physical = m.physical_twists(&basis);
        let p = self.point(q);
        let out = DMatrix::from_fn(6, physical.ncols(), |r, c| {
            let w = Vector3::new(physical[(0, c)], physical[(1, c)], physical[(2, c)]);
            let v = Vector3::new(physical[(3, c)], physical[(4, c)], physical[(5, c)]);
            let vp = v + w.cross(&p);
            [vp.x, vp.y, vp.z, w.x, w.y, w.z][r]
        });
        (out, rank)
    }

    /// The ranks an analysis judges the end-effector by, at `q` with the `locked` inputs held:
    /// the rank of `J_D` and of its constraint rows. With leg-wrench Jacobians `j`, theirs
    /// (dimensionless); otherwise those of the wrench systems reciprocal to the end-effector's
    /// twists with every input held (the wrenches `J_D`'s rows would span) and with only the
    /// `locked` inputs held (its constraint rows), from the loop-closure Jacobian.
    pub(super) fn output_ranks(&self, q: &[f64], locked: &[usize], j: &Jacobians) -> (Rank, Rank) {
        if self.has_leg_wrench_jacobians() {
            let jd = self.wrench_rank(&j.jd, &j.point);
            let (_, constraint) = self.twists_of(j);
            return (jd, constraint);
        }
        let all: Vec<usize> = (0..self.actuators.len()).collect();
        let (_, jd) = self.closure_output(q, &all);
        let (_, constraint) = self.closure_output(q, locked);
        (jd, constraint)
    }

    /// The rank of each leg's joint twists (dimensionless) at the current joint `screws`.
    pub(super) fn leg_ranks(&self, screws: &[screw::Twist]) -> Vec<linalg::Rank> {
        self.legs
            .iter()
            .map(|leg| {
                let joints: Vec<usize> = leg.joints.clone().collect();
                linalg::rank(
                    &self.unitless_leg_twists(screws, &joints),
                    DEFAULT_RANK_TOLERANCE,
                )
            })
            .collect()
    }

    /// The current screws of a leg's joints in the dimensionless form (columns of unit size:
    /// at the centre, translations over the length scale, prismatic rates in length-scale units).
    pub(super) fn unitless_leg_twists(
        &self,
        screws: &[screw::Twist],
        joints: &[usize],
    ) -> DMatrix<f64> {
        let m = &self.mechanism;
        let t = DMatrix::from_fn(6, joints.len(), |r, c| screws[joints[c]].to_vector()[r]);
        let mut t = m.unitless_twists(&t);
        for (c, &j) in joints.iter().enumerate() {
            if m.joints()[j].kind == Primitive::P {
                t.column_mut(c).scale_mut(m.scale());
            }
        }
        t
    }

    /// Rows `(f; m_P)` of wrenches at P (at `point`) in the dimensionless form, as columns:
    /// moments about the mechanism's centre over its length scale, each of unit size.
    fn unitless_rows(&self, rows: &DMatrix<f64>, point: &Vector3<f64>) -> DMatrix<f64> {
        let m = &self.mechanism;
        let mut out = DMatrix::zeros(6, rows.nrows());
        for r in 0..rows.nrows() {
            let f = Vector3::new(rows[(r, 0)], rows[(r, 1)], rows[(r, 2)]);
            let mp = Vector3::new(rows[(r, 3)], rows[(r, 4)], rows[(r, 5)]);
            // The moment about the origin, then the dimensionless form at the centre.
            let w = m.unitless_wrench(&Wrench {
                f,
                m: mp + point.cross(&f),
            });
            out.column_mut(r)
                .copy_from(&(w / w.norm().max(f64::MIN_POSITIVE)));
        }
        out
    }

    /// The rank of rows `(f; m_P)` in the dimensionless form, with its singular values.
    pub(super) fn wrench_rank(&self, rows: &DMatrix<f64>, point: &Vector3<f64>) -> Rank {
        linalg::rank(&self.unitless_rows(rows, point), DEFAULT_RANK_TOLERANCE)
    }

    /// The twists `(v_P; ω)` the platform can have at `q` with the `locked` inputs held: the
    /// twists reciprocal to the constraint rows of `J_D` (a basis, columns; physical units), and
    /// the rank decision of those rows. Their number is the platform's local degrees of freedom,
    /// six minus the rank: one computation gives both.
    ///
    /// Without leg-wrench Jacobians ([`Manipulator::has_leg_wrench_jacobians`]) the twists are
    /// the end-effector's twist space from the loop-closure Jacobian, and the rank that of the
    /// wrenches reciprocal to them.
    #[must_use]
    pub fn platform_twists(&self, q: &[f64], locked: &[usize]) -> (DMatrix<f64>, Rank) {
        if !self.has_leg_wrench_jacobians() {
            return self.closure_output(q, locked);
        }
        let j = self.jacobians(q, locked);
        self.twists_of(&j)
    }

    pub(super) fn twists_of(&self, j: &Jacobians) -> (DMatrix<f64>, Rank) {
        let m = &self.mechanism;
        let rows = self.unitless_rows(&j.constraint_rows(), &j.point);
        // Twists reciprocal to every constraint wrench: the null space of the rows, whose
        // coefficients (of f, then of m̂) are a twist's (v̂; ω) since w·t = f·v̂ + m̂·ω.
        let (basis, rank) = if rows.ncols() == 0 {
            (
                DMatrix::identity(6, 6),
                linalg::rank(&rows, DEFAULT_RANK_TOLERANCE),
            )
        } else {
            linalg::nullspace(&rows.transpose(), DEFAULT_RANK_TOLERANCE)
        };
        let twists = swap_blocks(&basis);
        // Dimensionless (ω; v_c/L) to physical (v_P; ω).
        let physical = m.physical_twists(&twists);
        let out = DMatrix::from_fn(6, physical.ncols(), |r, c| {
            let w = Vector3::new(physical[(0, c)], physical[(1, c)], physical[(2, c)]);
            let v = Vector3::new(physical[(3, c)], physical[(4, c)], physical[(5, c)]);
            let vp = v + w.cross(&j.point);
            [vp.x, vp.y, vp.z, w.x, w.y, w.z][r]
        });
        (out, rank)
    }
}
