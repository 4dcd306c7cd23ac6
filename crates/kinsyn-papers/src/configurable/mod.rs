//! The planar 4-RRR manipulator with a configurable platform of paper 003 (Gallardo-Alvarado,
//! Tinajero-Campos, Sánchez-Rodríguez, *Cinemática de un manipulador configurable por medio de la
//! teoría de tornillos*, RIAI 18, 2021) by the paper's own formulas — the second method beside
//! the general mechanism graph (`mechanisms/4-rrr-configurable.json`).
//!
//! Four RRR legs join the ground at `A_i` (actuated revolutes, angles `q_i` from the x axis) to
//! the corners `C_i` of a rhombus of four links `m_1 … m_4` of length `c` (the configurable
//! platform, links `m_i` between `C_i` and `C_{i+1}`); each leg has an arm `A_i B_i` of length
//! `a` and a forearm `B_i C_i` of length `b` (§2, Fig. 6). All axes are normal to the plane.
//!
//! # Two parametrisations of the platform (§3.1)
//! - **Eqs. 1–5, 10, 11**: the centre `C = (w1, w2)`, the unit vector `û = (w3, w4)` from `C` to
//!   `C_1`, `v̂ = (−w4, w3)`, half-diagonals `w5 = |C C_1|`, `w6 = |C C_2|` with
//!   `w5² + w6² = c²`; the angles θ, φ of eq. 11: `π − φ − θ = 2 arccos w3 = 2 arcsin w4`,
//!   `φ − θ = 2 arcsin(w5/c)` ([`CentrePose`]).
//! - **Eqs. 12–14**: the corner `C_4 = (x4, y4)` and the directions θ of `C_4 C_1` and φ of
//!   `C_4 C_3`; `C_2 = C_1 + C_3 − C_4` ([`CornerPose`]).
//!
//! The two describe the same platform when `θ₁₃ = π − φ₁₁` and `φ₁₃ = π − θ₁₁`
//! ([`CentrePose::to_corner_pose`], proved in `tests/suite/configurable.rs`): the paper's inverse
//! example (θ = 75°, φ = 100° in eq. 11's sense, `C = (20, −30)`) is Table 1's converged pose
//! (θ = 80°, φ = 105° in eq. 13's sense), which is why the q of the one reproduce the other.

mod position;
pub use position::{
    Assembly, CENTRE_VARIABLES, CORNER_VARIABLES, ForwardMethod, ForwardPosition, InversePosition,
    LegInverse, MAX_RUNS, PositionError, angle_distance, centre_mirror, centre_system,
    corner_system, forward_position, forward_position_with, inverse_position, leg_inverse,
    solution_corners,
};
pub mod trajectory;
pub mod velocity;

use nalgebra::Vector2;

/// The geometry of the manipulator (§2, §5).
#[derive(Debug, Clone, PartialEq)]
pub struct Configurable {
    /// Arm length `|A_i B_i|`.
    pub a: f64,
    /// Forearm length `|B_i C_i|`.
    pub b: f64,
    /// Platform link length `|C_i C_{i+1}|`.
    pub c: f64,
    /// The base points `A_1 … A_4`.
    pub base: [Vector2<f64>; 4],
}

impl Configurable {
    /// The example of §5: `a = 80`, `b = 120`, `c = 120` mm, `A_1 = (200, 0)`, `A_2 = (0, 200)`,
    /// `A_3 = (−200, 0)`, `A_4 = (0, −200)` mm.
    #[must_use]
    pub fn paper003() -> Self {
        Self {
            a: 80.0,
            b: 120.0,
            c: 120.0,
            base: [
                Vector2::new(200.0, 0.0),
                Vector2::new(0.0, 200.0),
                Vector2::new(-200.0, 0.0),
                Vector2::new(0.0, -200.0),
            ],
        }
    }

    /// The elbow `B_i = A_i + a (cos q_i, sin q_i)` of leg `i` (0-based) at input angle `q`
    /// (eq. 7).
    #[must_use]
    pub fn elbow(&self, leg: usize, q: f64) -> Vector2<f64> {
        self.base[leg] + self.a * Vector2::new(q.cos(), q.sin())
    }
}

/// The platform by its corner `C_4` and the directions θ (of `C_4 → C_1`) and φ (of
/// `C_4 → C_3`), radians (eqs. 12–14).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CornerPose {
    /// The corner `C_4`.
    pub c4: Vector2<f64>,
    /// The direction of `C_4 → C_1`.
    pub theta: f64,
    /// The direction of `C_4 → C_3`.
    pub phi: f64,
}

impl CornerPose {
    /// The corners `C_1 … C_4` of a platform of link length `c` (eqs. 13, 14).
    #[must_use]
    pub fn corners(&self, c: f64) -> [Vector2<f64>; 4] {
        let c1 = self.c4 + c * Vector2::new(self.theta.cos(), self.theta.sin());
        let c3 = self.c4 + c * Vector2::new(self.phi.cos(), self.phi.sin());
        [c1, c1 + c3 - self.c4, c3, self.c4]
    }
}

/// The platform by its centre `C` and the angles θ, φ of eq. 11, radians (eqs. 1–5, 10, 11).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CentrePose {
    /// The centre `C = (w1, w2)`.
    pub centre: Vector2<f64>,
    /// θ of eq. 11.
    pub theta: f64,
    /// φ of eq. 11.
    pub phi: f64,
}

impl CentrePose {
    /// The corners `C_1 … C_4` (eq. 5) of a platform of link length `c`: `û` at angle
    /// `(π − φ − θ)/2` (eq. 11), `w5 = c sin((φ − θ)/2)` (eq. 11), `w6 = √(c² − w5²)` (eq. 10).
    #[must_use]
    pub fn corners(&self, c: f64) -> [Vector2<f64>; 4] {
        let alpha = (std::f64::consts::PI - self.phi - self.theta) / 2.0;
        let u = Vector2::new(alpha.cos(), alpha.sin());
        let v = Vector2::new(-u.y, u.x);
        let w5 = c * ((self.phi - self.theta) / 2.0).sin();
        let w6 = (c * c - w5 * w5).max(0.0).sqrt();
        [
            self.centre + w5 * u,
            self.centre + w6 * v,
            self.centre - w5 * u,
            self.centre - w6 * v,
        ]
    }

    /// The same platform in eq. 13's parametrisation: `C_4` from eq. 5, `θ₁₃ = π − φ`,
    /// `φ₁₃ = π − θ`.
    #[must_use]
    pub fn to_corner_pose(&self, c: f64) -> CornerPose {
        let corners = self.corners(c);
        CornerPose {
            c4: corners[3],
            theta: std::f64::consts::PI - self.phi,
            phi: std::f64::consts::PI - self.theta,
        }
    }
}
