//! Velocity analysis of paper 003's configurable 4-RRR by screw theory (§4, eqs. 16–29).
//!
//! # Screws and kinsyn's twists
//! The paper writes a screw as `$ = (s; s0)`, primal (direction / angular) part first, dual
//! part second, and a velocity state `⁰V_O = (ω; v_O)` with `v_O` the velocity of the body
//! point at the origin `O`. That is kinsyn's [`Twist`] `(ω; v)` exactly, and the joint screw of a
//! revolute with unit axis `u` through `p` is `(u; p × u)` in both. A Plücker line through `r`
//! along the unit `s` is `(s; r × s)`, kinsyn's [`kinsyn::screw::Line`]. Every screw here — joint
//! screws, lines, and their combinations such as `s4 − k4 s3 / k2` — is therefore held in a
//! [`Twist`] with `w = s`, `v = s0`, and the Klein form (eq. 16) is
//! `{$1; $2} = s1 · s02 + s2 · s01 = w1 · v2 + w2 · v1`; for a line and a twist it is the virtual
//! power [`kinsyn::screw::reciprocal_product`] of the line read as a unit force.
//!
//! # The manipulator's screws (Fig. 8)
//! All axes are along `ẑ` through the joint points (plane `z = 0`): `⁰$_i¹` at `A_i` (the
//! actuated joint, rate `q̇_i`), `¹$_i²` at `B_i`, the forearm–platform joint at `C_i`, and the
//! platform loop's joints `m1$m2` at `C2`, `m2$m3` at `C3`, `m3$m4` at `C4`, `m4$m1` at `C1`
//! (link `m_i` joins `C_i` to `C_{i+1}`). The Klein form of a line with such a revolute is the
//! signed distance of the axis from the line, zero exactly when the line passes through it —
//! the *reciprocity* that cancels passive rates.
//!
//! # Which link turns with which angle
//! In eq. 13's parametrisation ([`CornerPose`]) θ is the direction of `C4 → C1` (link `m4`) and
//! φ that of `C4 → C3` (link `m3`, reversed). The platform is a rhombus, so opposite links stay
//! parallel: `ω_{m1} = ω_{m3} = φ̇`, `ω_{m2} = ω_{m4} = θ̇`, and the loop rate
//! `m1ωm2 = θ̇ − φ̇`.

use super::{Configurable, CornerPose};
use kinsyn::screw::{Line, Twist};
use nalgebra::{Matrix3, Matrix3x4, Vector2, Vector3, Vector4};

/// Errors of the velocity analysis.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum VelocityError {
    /// An input (a joint point or a rate) is NaN or infinite.
    #[error("{what} is not finite")]
    NonFinite {
        /// Which input.
        what: &'static str,
    },
    /// Two points that should span a Plücker line coincide.
    #[error("the line {line} is undefined: its two points coincide")]
    DegenerateLine {
        /// The line, by the paper's name.
        line: &'static str,
    },
    /// A denominator of the method vanishes: the configuration is singular for it (a
    /// forearm is aligned with the platform link the method divides by, the rhombus is
    /// flat, or the Jacobian `J1` of eq. 26 is singular).
    #[error("singular configuration: {quantity} = {value:.3e} vanishes (eq. {equation})")]
    Singular {
        /// The vanishing quantity.
        quantity: &'static str,
        /// Its value.
        value: f64,
        /// The equation that divides by it.
        equation: &'static str,
    },
}

/// Relative size below which a denominator counts as zero.
const SINGULAR: f64 = 1e-10;

/// The joint points of the manipulator at one configuration, in the plane `z = 0` (Table 2's
/// columns): the base points `A_i`, elbows `B_i`, and platform corners `C_i`, legs in order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Configuration {
    /// The actuated joints `A_1 … A_4`.
    pub base: [Vector2<f64>; 4],
    /// The elbows `B_1 … B_4`.
    pub elbows: [Vector2<f64>; 4],
    /// The platform corners `C_1 … C_4`.
    pub corners: [Vector2<f64>; 4],
}

impl Configuration {
    /// The configuration of manipulator `m` at inputs `q` (radians) with the platform at
    /// `pose`: elbows by eq. 7, corners by eqs. 13–14. The closure equations (6) are not
    /// checked; `pose` should solve them for `q` (a forward position solution).
    #[must_use]
    pub fn new(m: &Configurable, q: [f64; 4], pose: &CornerPose) -> Self {
        Self {
            base: m.base,
            elbows: std::array::from_fn(|i| m.elbow(i, q[i])),
            corners: pose.corners(m.c),
        }
    }

    /// The unit screw of the actuated revolute `⁰$_i¹` at `A_i` (leg `i`, 0-based).
    #[must_use]
    pub fn actuated_screw(&self, leg: usize) -> Twist {
        revolute(self.base[leg])
    }

    /// The unit screw of the platform loop's joint `m_k $ m_{k+1}` (0-based `k`, so `k = 0` is
    /// `m1$m2`): the revolute at corner `C_{k+2}` where link `m_{k+1}` meets the next link.
    #[must_use]
    pub fn loop_screw(&self, k: usize) -> Twist {
        revolute(self.corners[(k + 1) % 4])
    }

    /// The Plücker line `s_i` from `B_i` to `C_i` (leg `i`, 0-based): the forearm, reciprocal to
    /// the two passive joints of the leg (§4, before eq. 21).
    ///
    /// # Errors
    /// [`VelocityError::DegenerateLine`] if `B_i = C_i`.
    pub fn forearm_line(&self, leg: usize) -> Result<Twist, VelocityError> {
        const NAMES: [&str; 4] = ["s1", "s2", "s3", "s4"];
        plucker_line(self.elbows[leg], self.corners[leg])
            .ok_or(VelocityError::DegenerateLine { line: NAMES[leg] })
    }

    fn check_finite(&self) -> Result<(), VelocityError> {
        let all = self.base.iter().chain(&self.elbows).chain(&self.corners);
        for p in all {
            if !(p.x.is_finite() && p.y.is_finite()) {
                return Err(VelocityError::NonFinite {
                    what: "a joint point of the configuration",
                });
            }
        }
        Ok(())
    }

    /// A length scale of the configuration (the platform's diameter), for relative tests.
    fn scale(&self) -> f64 {
        let c = &self.corners;
        (c[0] - c[2]).norm().max((c[1] - c[3]).norm()).max(1e-300)
    }
}

/// The unit screw of a revolute along `ẑ` through the point `p` of the plane: `(ẑ; p × ẑ)`.
#[must_use]
pub fn revolute(p: Vector2<f64>) -> Twist {
    Twist::revolute(Vector3::z(), Vector3::new(p.x, p.y, 0.0))
}

/// The Plücker line from `from` to `to` in the plane as a screw `(s; r × s)` with `s` the unit
/// direction (held in a [`Twist`], `w = s`, `v = r × s`); `None` when the points coincide.
#[must_use]
pub fn plucker_line(from: Vector2<f64>, to: Vector2<f64>) -> Option<Twist> {
    let d = to - from;
    if d.norm() == 0.0 || !d.norm().is_finite() {
        return None;
    }
    let l = Line::through(
        Vector3::new(from.x, from.y, 0.0),
        Vector3::new(d.x, d.y, 0.0),
    );
    Some(Twist {
        w: l.direction,
        v: l.moment,
    })
}

/// The Klein form of two screws (eq. 16): `{$1; $2} = s1 · s02 + s2 · s01`, a symmetric
/// bilinear form on se(3); zero for a line and a twist exactly when a force along the line does
/// no work on the twist (reciprocity), in particular when the line meets a revolute's axis.
#[must_use]
pub fn klein_form(a: &Twist, b: &Twist) -> f64 {
    a.w.dot(&b.v) + b.w.dot(&a.v)
}

fn scaled(t: &Twist, k: f64) -> Twist {
    Twist {
        w: t.w * k,
        v: t.v * k,
    }
}

fn sum(a: &Twist, b: &Twist) -> Twist {
    Twist {
        w: a.w + b.w,
        v: a.v + b.v,
    }
}

fn nonzero(
    value: f64,
    size: f64,
    quantity: &'static str,
    equation: &'static str,
) -> Result<f64, VelocityError> {
    if value.abs() <= SINGULAR * size || !value.is_finite() {
        Err(VelocityError::Singular {
            quantity,
            value,
            equation,
        })
    } else {
        Ok(value)
    }
}

/// The first-order coefficients of the platform loop (eqs. 17–19): the loop's relative joint
/// rates in terms of the one passive rate `m1ωm2`,
/// `m2ωm3 = g23 · m1ωm2`, `m3ωm4 = g34 · m1ωm2`, `m4ωm1 = g41 · m1ωm2` (eq. 18).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopCoefficients {
    /// `g23 = −{s41; m1$m2} / {s41; m2$m3}`.
    pub g23: f64,
    /// `g34 = −{s13; m1$m2} / {s13; m3$m4}`.
    pub g34: f64,
    /// `g41 = −{s43; m1$m2} / {s43; m4$m1}`.
    pub g41: f64,
}

/// The loop coefficients of eq. 19 at `cfg`.
///
/// The loop equation (17) `ω12 $12 + ω23 $23 + ω34 $34 + ω41 $41 = 0` (joints at `C2, C3, C4,
/// C1`) is taken in the Klein form with a line through the axes of the two joints *not* solved
/// for, so that their terms vanish by reciprocity and one unknown rate remains: `s41` is the
/// line through `C4` and `C1` (kills `$34`, `$41`; gives `g23`), `s13` the diagonal through `C1`
/// and `C3` (kills `$23`, `$41`; gives `g34`), `s43` the line through `C4` and `C3` (kills `$23`,
/// `$34`; gives `g41`) — `s_ij` passes through `C_i` and `C_j`. The lines' orientations
/// (Fig. 8) cancel in each ratio. For a rhombus (indeed any parallelogram) the values are
/// `g23 = −1`, `g34 = 1`, `g41 = −1`.
///
/// # Errors
/// [`VelocityError::DegenerateLine`] for coincident corners, [`VelocityError::Singular`] for a
/// flat platform (a corner on the line of the others), [`VelocityError::NonFinite`].
pub fn loop_coefficients(cfg: &Configuration) -> Result<LoopCoefficients, VelocityError> {
    cfg.check_finite()?;
    let c = &cfg.corners;
    let size = cfg.scale();
    let line = |i: usize, j: usize, name| {
        plucker_line(c[i], c[j]).ok_or(VelocityError::DegenerateLine { line: name })
    };
    let (s41, s13, s43) = (line(3, 0, "s41")?, line(0, 2, "s13")?, line(3, 2, "s43")?);
    let j: [Twist; 4] = std::array::from_fn(|k| cfg.loop_screw(k));
    let g23 =
        -klein_form(&s41, &j[0]) / nonzero(klein_form(&s41, &j[1]), size, "{s41; m2$m3}", "19")?;
    let g34 =
        -klein_form(&s13, &j[0]) / nonzero(klein_form(&s13, &j[2]), size, "{s13; m3$m4}", "19")?;
    let g41 =
        -klein_form(&s43, &j[0]) / nonzero(klein_form(&s43, &j[3]), size, "{s43; m4$m1}", "19")?;
    Ok(LoopCoefficients { g23, g34, g41 })
}

/// The polarity operator Δ of eq. 26 on planar screws reduced to their three generally
/// non-zero coordinates in the order `(s; s0)`: a line in the plane is `(s_x, s_y; s0_z)`, a
/// planar twist `(ω_z; v_x, v_y)`, and `lineᵀ Δ twist` is their Klein form. As printed:
/// rows `(0 1 0), (0 0 1), (1 0 0)`.
#[must_use]
pub fn polarity() -> Matrix3<f64> {
    Matrix3::new(0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0)
}

/// A line (or any zero-`ω_z`, zero-`v_z` screw) of the plane by its coordinates
/// `(s_x, s_y; s0_z)`.
#[must_use]
pub fn planar_line(s: &Twist) -> Vector3<f64> {
    Vector3::new(s.w.x, s.w.y, s.v.z)
}

/// A planar twist by its coordinates `(ω_z; v_x, v_y)`.
#[must_use]
pub fn planar_twist(t: &Twist) -> Vector3<f64> {
    Vector3::new(t.w.z, t.v.x, t.v.y)
}

/// The planar twist `(ω_z; v_x, v_y)` as a kinsyn [`Twist`].
#[must_use]
pub fn twist_from_planar(x: &Vector3<f64>) -> Twist {
    Twist {
        w: Vector3::new(0.0, 0.0, x[0]),
        v: Vector3::new(x[1], x[2], 0.0),
    }
}

/// The input–output equation of link `m1` (eqs. 20–26), `J1ᵀ Δ ⁰V^{m1} = J̄1 q̇`, with the
/// scalars of eqs. 23–24 it is built from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InputOutput {
    /// The loop coefficients of eq. 19.
    pub loop_coefficients: LoopCoefficients,
    /// `k1 = {s3; ⁰$_3¹}` (eq. 23).
    pub k1: f64,
    /// `k2 = {s3; g34 m3$m4 + g41 m4$m1}` (eq. 23), the joints at `C4` and `C1`.
    pub k2: f64,
    /// `k3 = {s4; ⁰$_4¹}` (eq. 24).
    pub k3: f64,
    /// `k4 = {s4; g41 m4$m1}` (eq. 24), the joint at `C1`.
    pub k4: f64,
    /// The forearm lines `s1 … s4` (from `B_i` to `C_i`) as screws.
    pub forearms: [Twist; 4],
    /// The direct Jacobian `J1 = [s1  s2  s4 − k4 s3 / k2]`, columns in planar line
    /// coordinates `(s_x, s_y; s0_z)`.
    pub j1: Matrix3<f64>,
    /// The inverse Jacobian `J̄1` (3 × 4): `diag({s1; ⁰$_1¹}, {s2; ⁰$_2¹})` and the row
    /// `(0, 0, −k1 k4 / k2, k3)`.
    pub j1_bar: Matrix3x4<f64>,
}

/// The input–output equation of link `m1` at `cfg` (eqs. 20–26).
///
/// Legs 1 and 2 carry `m1` (eq. 20); the Klein form with the forearm line `s_i` kills the
/// elbow and corner terms (eq. 21): `{s_i; V} = q̇_i {s_i; ⁰$_i¹}`, `i = 1, 2`. The third
/// equation comes from `m1` as the end of the serial chain leg 3 → `m3` → `m4` → `m1` (eq. 22):
/// with `s3`, `{s3; V} = k1 q̇3 + k2 m1ωm2` (eq. 23), and from leg 4 → `m4` → `m1` with `s4`,
/// `{s4; V} = k3 q̇4 + k4 m1ωm2` (eq. 24); eliminating the loop rate gives eq. 25,
/// `{s4 − k4 s3 / k2; V} = −k1 k4 / k2 q̇3 + k3 q̇4`.
///
/// # Errors
/// [`VelocityError::Singular`] when `k2` or `k4` vanishes (forearm 3 or 4 parallel to `m4`)
/// or `J1` is singular; the errors of [`loop_coefficients`].
pub fn input_output(cfg: &Configuration) -> Result<InputOutput, VelocityError> {
    let g = loop_coefficients(cfg)?;
    let size = cfg.scale();
    let s: [Twist; 4] = [
        cfg.forearm_line(0)?,
        cfg.forearm_line(1)?,
        cfg.forearm_line(2)?,
        cfg.forearm_line(3)?,
    ];
    let act: [Twist; 4] = std::array::from_fn(|i| cfg.actuated_screw(i));
    let (j34, j41) = (cfg.loop_screw(2), cfg.loop_screw(3));
    let k1 = klein_form(&s[2], &act[2]);
    let k2 = klein_form(&s[2], &sum(&scaled(&j34, g.g34), &scaled(&j41, g.g41)));
    let k3 = klein_form(&s[3], &act[3]);
    let k4 = klein_form(&s[3], &scaled(&j41, g.g41));
    let k2 = nonzero(k2, size, "k2", "23")?;
    nonzero(k4, size, "k4", "24")?;
    let third = sum(&s[3], &scaled(&s[2], -k4 / k2));
    let j1 = Matrix3::from_columns(&[planar_line(&s[0]), planar_line(&s[1]), planar_line(&third)]);
    let mut j1_bar = Matrix3x4::zeros();
    j1_bar[(0, 0)] = klein_form(&s[0], &act[0]);
    j1_bar[(1, 1)] = klein_form(&s[1], &act[1]);
    j1_bar[(2, 2)] = -k1 * k4 / k2;
    j1_bar[(2, 3)] = k3;
    let norms: f64 = j1.column_iter().map(|c| c.norm()).product();
    nonzero(j1.determinant(), norms, "det J1", "26")?;
    Ok(InputOutput {
        loop_coefficients: g,
        k1,
        k2,
        k3,
        k4,
        forearms: s,
        j1,
        j1_bar,
    })
}

impl InputOutput {
    /// The twist `⁰V^{m1}` of link `m1` (about the origin) for input rates `q̇`: the solution
    /// of eq. 26.
    #[must_use]
    pub fn twist_m1(&self, qdot: &Vector4<f64>) -> Twist {
        let lhs = self.j1.transpose() * polarity();
        let rhs = self.j1_bar * qdot;
        // `input_output` refused a singular J1, so the solve succeeds.
        let x = lhs.lu().solve(&rhs).unwrap_or_else(Vector3::zeros);
        twist_from_planar(&x)
    }

    /// The loop rate `m1ωm2` from eq. 24 once `⁰V^{m1}` is known:
    /// `({s4; V} − k3 q̇4) / k4` (`= θ̇ − φ̇`).
    #[must_use]
    pub fn loop_rate(&self, v_m1: &Twist, qdot: &Vector4<f64>) -> f64 {
        (klein_form(&self.forearms[3], v_m1) - self.k3 * qdot[3]) / self.k4
    }
}

/// The twist `⁰V^{m3}` of link `m3` (eqs. 27–28): its angular velocity is that of `m1`
/// (opposite links of a rhombus stay parallel; eq. 27), and its dual part solves
/// `{s_i; ⁰V^{m3}} = q̇_i {s_i; ⁰$_i¹}`, `i = 3, 4` (eq. 28: legs 3 and 4 carry `m3`).
///
/// # Errors
/// [`VelocityError::Singular`] when forearms 3 and 4 are parallel; the errors of
/// [`Configuration::forearm_line`].
pub fn twist_m3(
    cfg: &Configuration,
    omega: f64,
    qdot: &Vector4<f64>,
) -> Result<Twist, VelocityError> {
    let (s3, s4) = (cfg.forearm_line(2)?, cfg.forearm_line(3)?);
    let rhs = |s: &Twist, i: usize| qdot[i] * klein_form(s, &cfg.actuated_screw(i)) - omega * s.v.z;
    let m = nalgebra::Matrix2::new(s3.w.x, s3.w.y, s4.w.x, s4.w.y);
    nonzero(m.determinant(), 1.0, "s3 × s4", "28")?;
    let v = m
        .lu()
        .solve(&Vector2::new(rhs(&s3, 2), rhs(&s4, 3)))
        .unwrap_or_else(Vector2::zeros);
    Ok(Twist {
        w: Vector3::new(0.0, 0.0, omega),
        v: Vector3::new(v.x, v.y, 0.0),
    })
}

/// The velocity of the point `p` of a body with twist `t` (eq. 29): the dual part of the
/// velocity state moved to `P`, `d(⁰V_O) + p(⁰V_O) × r_{P/O}`.
#[must_use]
pub fn point_velocity(t: &Twist, p: Vector2<f64>) -> Vector2<f64> {
    let v = t.velocity_at(&Vector3::new(p.x, p.y, 0.0));
    Vector2::new(v.x, v.y)
}

/// The velocity state of the configurable platform for input rates `q̇`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Velocities {
    /// The twist `⁰V^{m1}` of link `m1` (`C1 C2`) about the origin (eq. 26).
    pub m1: Twist,
    /// The twist `⁰V^{m3}` of link `m3` (`C3 C4`) about the origin (eqs. 27–28).
    pub m3: Twist,
    /// The passive loop rate `m1ωm2` (eq. 24), `θ̇ − φ̇`.
    pub loop_rate: f64,
    /// The corner velocities `Ċ1 … Ċ4` (eq. 29): `C1, C2` on `m1`, `C3, C4` on `m3`.
    pub corners: [Vector2<f64>; 4],
}

/// The twists of `m1` and `m3`, the loop rate and the corner velocities at `cfg` for input
/// rates `qdot = (q̇1, q̇2, q̇3, q̇4)` (rad/s): paper 003 §4 end to end.
///
/// # Errors
/// [`VelocityError::NonFinite`] for a non-finite rate; the errors of [`input_output`] and
/// [`twist_m3`] at a configuration singular for the method.
pub fn velocities(cfg: &Configuration, qdot: &Vector4<f64>) -> Result<Velocities, VelocityError> {
    if qdot.iter().any(|x| !x.is_finite()) {
        return Err(VelocityError::NonFinite {
            what: "an input rate",
        });
    }
    let io = input_output(cfg)?;
    let m1 = io.twist_m1(qdot);
    let m3 = twist_m3(cfg, m1.w.z, qdot)?;
    let c = &cfg.corners;
    Ok(Velocities {
        m1,
        m3,
        loop_rate: io.loop_rate(&m1, qdot),
        corners: [
            point_velocity(&m1, c[0]),
            point_velocity(&m1, c[1]),
            point_velocity(&m3, c[2]),
            point_velocity(&m3, c[3]),
        ],
    })
}
