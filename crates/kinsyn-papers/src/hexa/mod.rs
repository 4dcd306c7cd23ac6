//! The **6-RUU HEXA with reconfigurable platforms** of paper 001 (Wu & Dong, *Kinematics of a
//! 6-RUU parallel robot with reconfigurable platforms*, §2–3), by the paper's closed forms: the
//! limbs' geometry (eq. 6), the inverse geometry of one limb (eqs. 4–5), the Jacobians
//! `A χ̇ = B θ̇` (eqs. 9–11) and the transmission indices (eqs. 13, 15–17), with the
//! description file, the end-effector constraint of eqs. 7–8, the workspace and the maps; this
//! module is the paper's second method beside the general mechanism machinery.
//!
//! # Conventions (paper 001 §2–3; those the paper leaves implicit are stated here)
//! Limb `i = 1 … 6` has its actuated revolute at `a_i = R_z(μ_i)[(−1)^{i+1} a i + R j]`
//! (eq. 6a), about `u_i = R_z(μ_i) i` (the first two axes are parallel to x, §2). The active
//! link `A_i B_i` of length `b` has the direction
//! `v_i(θ_i) = cos θ_i R_z(μ_i) j + sin θ_i k`: `θ_i` is measured from the horizontal, outward
//! direction `R_z(μ_i) j` and turns `v_i` about `+u_i` (`dv_i/dθ_i = u_i × v_i`). Under it the
//! paper's equations hold together: eq. 5's `I_i = −2b m_iz`,
//! `J_i = 2b(m_ix sin μ_i − m_iy cos μ_i)`, `K_i = |m_i|² + b² − l²` are the coefficients of
//! `|c_i − b_i|² = l²` written as `J_i cos θ_i + I_i sin θ_i + K_i = 0`, and eq. 9 holds with
//! its printed sign, `A χ̇ = B θ̇` with `h_i = b w_iᵀ(u_i × v_i)`. Eq. 9's sign needs `θ` about
//! `+u_i`; of the conventions that give it (`θ` from `±k` or `±R_z(μ_i) j`), this one and `θ`
//! from `+k` (`v_i = cos θ k − sin θ R_z(μ_i) j`) bring eq. 5's printed root nearest to a
//! true one, and this one is the HEXA's customary arm angle, from the base plane
//! (`tests/suite/hexa.rs`, docs/deviations.md). The
//! parallelogram `B_i C_i` has length `l` and direction `w_i = (c_i − b_i)/l`. The working mode
//! (active links pointing away from the base centre) is `cos θ_i > 0`.
//!
//! # Eq. 5 as printed
//! The printed root `θ_i = 2 atan((−I_i ± √(I_i² + J_i² + K_i²))/(K_i − I_i))` does not solve
//! eq. 4 under any convention for `θ`: its square root is real even where the limb cannot reach
//! (`I² + J² < K²`). In this module's convention the roots are
//! `θ = 2 atan((−I ± √(I² + J² − K²))/(K − J))` ([`Hexa::inverse_limb`]): the printed numerator,
//! with `K − J` for the printed `K − I` and `−K²` for `+K²`. `tests/suite/hexa.rs` shows the printed
//! form leaving the limb open and this one closing it; `docs/deviations.md` records it.
//!
//! # Eq. 15
//! Eqs. 14–16 use `s_i` as a unit vector (`s1 = Q1 j`; eq. 14's rows carry `r1 w_iᵀ s_i`),
//! eq. 11 as `r1 Q1 j`: with eq. 14's `s_i`, eq. 15 holds as printed (`tests/suite/hexa.rs`).

use nalgebra::{Matrix3, Vector3};

/// Paper 001's 6-RUU (lengths in mm): base radius `R`, the actuated joints' offset `a` along
/// `±u_i`, the active link `b`, the parallelogram `l`, and the platform radii `r1 … r5`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hexa {
    /// `R`: the distance of the actuated joints' pairs from the base centre.
    pub big_r: f64,
    /// `a`: the offset of each actuated joint from its pair's centre, along `u_i`.
    pub a: f64,
    /// `b`: the length of the active link `A_i B_i`.
    pub b: f64,
    /// `l`: the length of the parallelogram `B_i C_i`.
    pub l: f64,
    /// `r1 … r5` of eqs. 6b–8.
    pub r: [f64; 5],
    /// `γ` of eq. 6b, the direction of the sub-platforms' arms `C2C3` and `C1C6`: unstated in
    /// the paper; [`Hexa::paper001`] takes `π/6` (module documentation).
    pub gamma: f64,
}

/// The directions `μ_i` of the six limbs (paper 001 §2): `0, 0, 2π/3, 2π/3, −2π/3, −2π/3`.
#[must_use]
pub fn mu(i: usize) -> f64 {
    use std::f64::consts::PI;
    [
        0.0,
        0.0,
        2.0 * PI / 3.0,
        2.0 * PI / 3.0,
        -2.0 * PI / 3.0,
        -2.0 * PI / 3.0,
    ][i]
}

/// `R_z(φ)`.
#[must_use]
pub fn rz(phi: f64) -> Matrix3<f64> {
    let (s, c) = phi.sin_cos();
    Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
}

/// One limb's state at an actuated angle: `b_i`, `v_i`, `w_i`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimbState {
    /// The actuated angle `θ_i`.
    pub theta: f64,
    /// `b_i`, the end of the active link.
    pub b: Vector3<f64>,
    /// `v_i`, the active link's direction.
    pub v: Vector3<f64>,
    /// `w_i = (c_i − b_i)/l`, the parallelogram's direction (unit when the limb closes).
    pub w: Vector3<f64>,
}

impl Hexa {
    /// Paper 001 §4: `R = 200, a = 60, b = 260, l = 550, r1 … r5 = 60` (mm).
    #[must_use]
    pub fn paper001() -> Self {
        Self {
            big_r: 200.0,
            a: 60.0,
            b: 260.0,
            l: 550.0,
            r: [60.0; 5],
            gamma: std::f64::consts::FRAC_PI_6,
        }
    }

    /// `a_i` of limb `i` (0-based; eq. 6a with `(−1)^{i+1}` for the 1-based index).
    #[must_use]
    pub fn base_joint(&self, i: usize) -> Vector3<f64> {
        let sign = if i.is_multiple_of(2) { 1.0 } else { -1.0 };
        rz(mu(i)) * Vector3::new(sign * self.a, self.big_r, 0.0)
    }

    /// `u_i = R_z(μ_i) i`, the actuated joint's axis.
    #[must_use]
    pub fn axis(&self, i: usize) -> Vector3<f64> {
        rz(mu(i)) * Vector3::x()
    }

    /// `v_i(θ) = cos θ R_z(μ_i) j + sin θ k`: `θ` from the horizontal, outward direction,
    /// about `+u_i` (module documentation).
    #[must_use]
    pub fn link_direction(&self, i: usize, theta: f64) -> Vector3<f64> {
        rz(mu(i)) * Vector3::y() * theta.cos() + Vector3::z() * theta.sin()
    }

    /// Eq. 5's coefficients `(I_i, J_i, K_i)` for the platform joint `c` of limb `i`: the limb
    /// closes (`|c − b_i| = l`, eq. 4) where `J cos θ + I sin θ + K = 0`.
    #[must_use]
    pub fn coefficients(&self, i: usize, c: &Vector3<f64>) -> (f64, f64, f64) {
        self.coefficients_of(&(c - self.base_joint(i)), mu(i).sin_cos())
    }

    /// Eq. 5's `(I, J, K)` for `m = c − a_i` and `(sin μ_i, cos μ_i)`.
    #[must_use]
    pub fn coefficients_of(&self, m: &Vector3<f64>, (s, c): (f64, f64)) -> (f64, f64, f64) {
        (
            -2.0 * self.b * m.z,
            2.0 * self.b * (m.x * s - m.y * c),
            m.norm_squared() + self.b * self.b - self.l * self.l,
        )
    }

    /// The two actuated angles that close limb `i` on the platform joint `c`,
    /// `θ = 2 atan((−I ± √(I² + J² − K²))/(K − J))` (eq. 5 with its denominator and the sign
    /// under its root corrected: module documentation), or `None` when `c` is out of the
    /// limb's reach (`I² + J² < K²`).
    #[must_use]
    pub fn inverse_limb(&self, i: usize, c: &Vector3<f64>) -> Option<[f64; 2]> {
        let (ii, jj, kk) = self.coefficients(i, c);
        let disc = ii * ii + jj * jj - kk * kk;
        if disc < 0.0 {
            return None;
        }
        let root = disc.sqrt();
        // t = tan(θ/2) in J cos θ + I sin θ + K = 0: (K − J) t² + 2 I t + (K + J) = 0.
        Some([-ii + root, -ii - root].map(|n| 2.0 * (n / (kk - jj)).atan()))
    }

    /// Eq. 5 **as printed**, `2 atan((−I ± √(I² + J² + K²))/(K − I))`: kept to show that it
    /// does not close the limb under any convention for `θ` (`tests/suite/hexa.rs`).
    #[must_use]
    pub fn inverse_limb_as_printed(&self, i: usize, c: &Vector3<f64>) -> [f64; 2] {
        let (ii, jj, kk) = self.coefficients(i, c);
        let root = (ii * ii + jj * jj + kk * kk).sqrt();
        [-ii + root, -ii - root].map(|n| 2.0 * (n / (kk - ii)).atan())
    }

    /// Limb `i` at the angle `theta` reaching for `c`.
    #[must_use]
    pub fn limb(&self, i: usize, theta: f64, c: &Vector3<f64>) -> LimbState {
        let v = self.link_direction(i, theta);
        let b = self.base_joint(i) + v * self.b;
        LimbState {
            theta,
            b,
            v,
            w: (c - b) / self.l,
        }
    }

    /// `h_i = b w_iᵀ(u_i × v_i)` (eq. 11): the rate of `w_i·c_i` that limb `i` needs per unit
    /// `θ̇_i` (`ḃ_i = b θ̇_i u_i × v_i`, module documentation).
    #[must_use]
    pub fn h(&self, i: usize, s: &LimbState) -> f64 {
        self.b * s.w.dot(&self.axis(i).cross(&s.v))
    }

    /// The input transmission index `λ_i = |w_iᵀ(u_i × v_i)|` (eq. 13).
    #[must_use]
    pub fn input_index(&self, i: usize, s: &LimbState) -> f64 {
        s.w.dot(&self.axis(i).cross(&s.v)).abs()
    }
}

/// A pose of both end-effectors, `χ = (x1, y1, z, φ1, x2, y2, φ2)` (eq. 10a): `P1 = (x1, y1, z)`
/// and `P2 = (x2, y2, z)` at one height (the platforms' vertical offsets are zero, §2), and
/// their turns `φ1`, `φ2` about `k`. Only poses whose `P2` lies on the four-bar's coupler curve
/// (eqs. 7–8, [`Hexa::four_bar_through`]) are assemblable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// `χ` in the order of eq. 10a (mm and radians).
    pub chi: [f64; 7],
}

impl Pose {
    /// `P1`.
    #[must_use]
    pub fn p1(&self) -> Vector3<f64> {
        Vector3::new(self.chi[0], self.chi[1], self.chi[2])
    }

    /// `P2`.
    #[must_use]
    pub fn p2(&self) -> Vector3<f64> {
        Vector3::new(self.chi[4], self.chi[5], self.chi[2])
    }

    /// `φ1`.
    #[must_use]
    pub fn phi1(&self) -> f64 {
        self.chi[3]
    }

    /// `φ2`.
    #[must_use]
    pub fn phi2(&self) -> f64 {
        self.chi[6]
    }

    /// End-effector 1 at `(p1, φ1)` and end-effector 2 at `(p2.x, p2.y, φ2)`, at `p1`'s height.
    #[must_use]
    pub fn new(p1: &Vector3<f64>, phi1: f64, p2: &Vector3<f64>, phi2: f64) -> Self {
        Self {
            chi: [p1.x, p1.y, p1.z, phi1, p2.x, p2.y, phi2],
        }
    }
}

/// The robot at a pose: both end-effectors, every limb in the working mode and the four-bar
/// ([`Hexa::inverse`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Configuration {
    /// The pose.
    pub pose: Pose,
    /// The platform joints `c_i` (eq. 6b).
    pub joints: [Vector3<f64>; 6],
    /// The limbs, in the working mode.
    pub limbs: [LimbState; 6],
    /// The four-bar's assembly through `P2` ([`Hexa::four_bar_assembly`]), `None` when `P2` is
    /// off its coupler curve.
    pub four_bar: Option<FourBarPose>,
}

impl Hexa {
    /// The platform joints `c_i` of eq. 6b at a pose: `c1, c2 = p1 ± r1 Q1 i` on end-effector 1;
    /// `c3 = c2 − r2 (cos γ, sin γ, 0)` and `c6 = c1 + r2 (cos γ, −sin γ, 0)` on the translating
    /// sub-platforms (not turned by `Q1`); `c4, c5 = p2 ∓ r5 Q2 i` on end-effector 2 (eq. 6b's
    /// `Q` read as `Q2`).
    #[must_use]
    pub fn platform_joints(&self, pose: &Pose) -> [Vector3<f64>; 6] {
        let (p1, p2) = (pose.p1(), pose.p2());
        let x1 = rz(pose.phi1()) * Vector3::x() * self.r[0];
        let x2 = rz(pose.phi2()) * Vector3::x() * self.r[4];
        let (s, c) = self.gamma.sin_cos();
        let arm = |sign: f64| Vector3::new(sign * c, -s, 0.0) * self.r[1];
        [
            p1 + x1,
            p1 - x1,
            p1 - x1 + arm(-1.0),
            p2 - x2,
            p2 + x2,
            p1 + x1 + arm(1.0),
        ]
    }

    /// The working mode's root of eq. 5 for limb `i` reaching `c`: the active link pointing
    /// away from the base centre (`b_i` the farther from the `z` axis, the HEXA's "elbow out"),
    /// or `None` out of reach.
    #[must_use]
    pub fn working_root(&self, i: usize, c: &Vector3<f64>) -> Option<f64> {
        let roots = self.inverse_limb(i, c)?;
        // The outward reach of the active link, `v_i · R_z(μ_i) j = cos θ`.
        let reach = f64::cos;
        Some(if reach(roots[0]) >= reach(roots[1]) {
            roots[0]
        } else {
            roots[1]
        })
    }

    /// The inverse geometry of the whole robot (eqs. 4–6): every limb's actuated angle in the
    /// working mode, and the four-bar's assembly through `P2` ([`Hexa::four_bar_assembly`]); `None`
    /// when a limb cannot reach its platform joint. A `P2` off the coupler curve leaves
    /// [`Configuration::four_bar`] empty (and end-effector 2's indices 0).
    #[must_use]
    pub fn inverse(&self, pose: &Pose) -> Option<Configuration> {
        let joints = self.platform_joints(pose);
        let mut limbs = [LimbState {
            theta: 0.0,
            b: Vector3::zeros(),
            v: Vector3::zeros(),
            w: Vector3::zeros(),
        }; 6];
        for (i, c) in joints.iter().enumerate() {
            limbs[i] = self.limb(i, self.working_root(i, c)?, c);
        }
        Some(Configuration {
            pose: *pose,
            joints,
            limbs,
            four_bar: self.four_bar_assembly(pose),
        })
    }
}

mod four_bar;
mod mechanism;
mod transmission;
mod workspace;

pub use four_bar::{FourBar, FourBarPose};
pub use mechanism::{FILE_TOLERANCE, GROUND, HexaFile, HexaFileError};
pub use transmission::{Indices, forward_jacobian, output_index};
pub use workspace::{
    Cylinder, Grid, IndexMap, IndexMapSettings, MAX_CELLS, Progress, Workspace, WorkspaceError,
    WorkspaceSettings,
};
