//! The four-bar that places end-effector 2 (paper 001 eqs. 7–8). With end-effector 1 held,
//! the sub-platforms' joints `C3` and `C6` are fixed: they are the four-bar's ground pivots,
//! `d = |c6 − c3|` apart. Two cranks of length `r3` turn about `k` at `C3` and `C6`; their ends
//! `D3`, `D6` carry the coupler, a bar of length `2 r4` whose middle is `P2` (eqs. 7b–c: `P2` is
//! `r4` along the coupler from `D3`, and `r4` back from `D6`). End-effector 2 turns about `k` at
//! `P2`, so the four-bar fixes `P2` and leaves `φ2` to limbs 4 and 5.
//!
//! Eq. 7a is Freudenstein's equation of this four-bar, the crank angles `α` (at `C3`) and `β`
//! (at `C6`) measured from the ground link `C3 → C6` in the frame `R_η` of eq. 8. `R_η` is a
//! reflection (determinant −1): its `x` is the direction `η` of `c6 − c3` and its `y` is that
//! direction turned by `−π/2`, so positive angles turn *away* from end-effector 1's side of the
//! ground link (the cranks hang towards limbs 4 and 5).

use super::{Hexa, rz};
use nalgebra::{Matrix3, Vector3};

/// The four-bar's ground link at a pose of end-effector 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FourBar {
    /// `C3`, the pivot of the crank `α`.
    pub c3: Vector3<f64>,
    /// `C6`, the pivot of the crank `β`.
    pub c6: Vector3<f64>,
    /// `η`, the direction of `c6 − c3` (eq. 8).
    pub eta: f64,
    /// `d = |c6 − c3|`.
    pub d: f64,
}

/// One assembly of the four-bar: the crank angles, the coupler's direction and the points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FourBarPose {
    /// `α` (eq. 7a), in the frame `R_η`.
    pub alpha: f64,
    /// `β` (eq. 7a).
    pub beta: f64,
    /// `ψ`, the coupler's direction `D3 → D6` in the frame `R_η` (eqs. 7b–c).
    pub psi: f64,
    /// `D3`, the end of the crank at `C3`.
    pub d3: Vector3<f64>,
    /// `D6`, the end of the crank at `C6`.
    pub d6: Vector3<f64>,
    /// `P2`, the middle of the coupler.
    pub p2: Vector3<f64>,
}

impl FourBar {
    /// `R_η` of eq. 8.
    #[must_use]
    pub fn frame(&self) -> Matrix3<f64> {
        let (s, c) = self.eta.sin_cos();
        Matrix3::new(c, s, 0.0, s, -c, 0.0, 0.0, 0.0, 1.0)
    }

    /// `R_η R_z(angle) i`: a direction given in the four-bar's frame, in the base frame.
    #[must_use]
    pub fn direction(&self, angle: f64) -> Vector3<f64> {
        self.frame() * rz(angle) * Vector3::x()
    }

    /// The angle in the four-bar's frame of a horizontal base-frame direction.
    #[must_use]
    pub fn angle_of(&self, direction: &Vector3<f64>) -> f64 {
        let local = self.frame() * direction; // R_η is its own inverse
        local.y.atan2(local.x)
    }
}

impl Hexa {
    /// The four-bar's ground link with end-effector 1 at `(p1, φ1)`: the sub-platform joints
    /// `C3`, `C6` of eq. 6b.
    #[must_use]
    pub fn four_bar(&self, p1: &Vector3<f64>, phi1: f64) -> FourBar {
        let joints = self.platform_joints(&super::Pose::new(p1, phi1, p1, 0.0));
        let (c3, c6) = (joints[2], joints[5]);
        let g = c6 - c3;
        FourBar {
            c3,
            c6,
            eta: g.y.atan2(g.x),
            d: g.norm(),
        }
    }

    /// Eq. 8's `k1` and `k2 = k3` for a ground link of length `d`.
    #[must_use]
    pub fn freudenstein(&self, d: f64) -> (f64, f64) {
        let (r3, r4) = (self.r[2], self.r[3]);
        (
            (d * d + 2.0 * r3 * r3 - 4.0 * r4 * r4) / (2.0 * r3 * r3),
            d / r3,
        )
    }

    /// The residual of eq. 7a, `k1 + k2 cos β − k3 cos α − cos α cos β − sin α sin β`.
    #[must_use]
    pub fn eq7a(&self, fb: &FourBar, alpha: f64, beta: f64) -> f64 {
        let (k1, k2) = self.freudenstein(fb.d);
        k1 + k2 * beta.cos() - k2 * alpha.cos() - (alpha - beta).cos()
    }

    /// The two crank angles `β` that eq. 7a pairs with `α`, or `None` where the coupler cannot
    /// reach the crank at `C6` (`α` outside the four-bar's range).
    #[must_use]
    pub fn rocker_angles(&self, fb: &FourBar, alpha: f64) -> Option<[f64; 2]> {
        let (k1, k2) = self.freudenstein(fb.d);
        // (k2 − cos α) cos β − sin α sin β = k2 cos α − k1.
        let (a, b, c) = (k2 - alpha.cos(), -alpha.sin(), k2 * alpha.cos() - k1);
        let size = a.hypot(b);
        if size == 0.0 || c.abs() > size {
            return None;
        }
        let (base, spread) = (b.atan2(a), (c / size).acos());
        Some([base + spread, base - spread])
    }

    /// The four-bar assembled at the crank angles `(α, β)`: the coupler's ends, its direction
    /// `ψ` and its middle `P2` (eqs. 7b–c). The coupler has length `2 r4` only where eq. 7a
    /// holds.
    #[must_use]
    pub fn four_bar_pose(&self, fb: &FourBar, alpha: f64, beta: f64) -> FourBarPose {
        let r3 = self.r[2];
        let d3 = fb.c3 + fb.direction(alpha) * r3;
        let d6 = fb.c6 + fb.direction(beta) * r3;
        FourBarPose {
            alpha,
            beta,
            psi: fb.angle_of(&(d6 - d3)),
            d3,
            d6,
            p2: (d3 + d6) / 2.0,
        }
    }

    /// The four-bar's assemblies that put the coupler's middle at `p2` (end-effector 1 at
    /// `(p1, φ1)`): none when `p2` is off the coupler curve by more than `tol` (mm), else one
    /// or two (`D3 = P2 − r4 e`, `D6 = P2 + r4 e` with `e` on both cranks' circles).
    #[must_use]
    pub fn four_bar_through(
        &self,
        p1: &Vector3<f64>,
        phi1: f64,
        p2: &Vector3<f64>,
        tol: f64,
    ) -> Vec<FourBarPose> {
        let fb = self.four_bar(p1, phi1);
        let (r3, r4) = (self.r[2], self.r[3]);
        // |P2 − r4 e − C3| = r3 with e = (cos t, sin t): a cos t + b sin t = c.
        let m = p2 - fb.c3;
        let (a, b) = (2.0 * r4 * m.x, 2.0 * r4 * m.y);
        let c = m.x * m.x + m.y * m.y + r4 * r4 - r3 * r3;
        let size = a.hypot(b);
        let mut found: Vec<FourBarPose> = Vec::new();
        if size == 0.0 {
            return found;
        }
        let (base, spread) = (b.atan2(a), (c / size).clamp(-1.0, 1.0).acos());
        for t in [base + spread, base - spread] {
            let e = Vector3::new(t.cos(), t.sin(), 0.0);
            let d3 = p2 - e * r4;
            let d6 = p2 + e * r4;
            let miss = ((d3 - fb.c3).xy().norm() - r3)
                .abs()
                .max(((d6 - fb.c6).xy().norm() - r3).abs());
            if miss <= tol && !found.iter().any(|f| (f.d3 - d3).norm() <= tol) {
                let pose =
                    self.four_bar_pose(&fb, fb.angle_of(&(d3 - fb.c3)), fb.angle_of(&(d6 - fb.c6)));
                found.push(FourBarPose { p2: *p2, ..pose });
            }
        }
        found
    }

    /// The four-bar's assembly at a pose: through `P2`, and where two pass through it (the
    /// coupler curve's double point) the one nearest the nominal assembly (by `D3`): a pose `χ`
    /// fixes `P2` but not always the four-bar. `None` when `P2` is off the coupler curve (by more
    /// than `1e-9 l`).
    #[must_use]
    pub fn four_bar_assembly(&self, pose: &super::Pose) -> Option<FourBarPose> {
        let (p1, phi1) = (pose.p1(), pose.phi1());
        let nominal = self.nominal_four_bar(&p1, phi1).map(|f| f.d3);
        let distance = |f: &FourBarPose| nominal.map_or(0.0, |n| (f.d3 - n).norm());
        self.four_bar_through(&p1, phi1, &pose.p2(), 1e-9 * self.l)
            .into_iter()
            .min_by(|x, y| distance(x).total_cmp(&distance(y)))
    }

    /// The nominal position of end-effector 2: the four-bar's symmetric assembly, cranks hanging
    /// away from end-effector 1 with `β = π − α` and the coupler parallel to the ground link
    /// (`cos α = (d − 2 r4)/(2 r3)`). At `φ1 = 0` it puts `P2` straight below `P1` in `y`
    /// (`r2 sin γ + r3 sin α` from it). `None` when the four-bar has no symmetric assembly.
    #[must_use]
    pub fn nominal_four_bar(&self, p1: &Vector3<f64>, phi1: f64) -> Option<FourBarPose> {
        let fb = self.four_bar(p1, phi1);
        let cos_alpha = (fb.d - 2.0 * self.r[3]) / (2.0 * self.r[2]);
        if cos_alpha.abs() > 1.0 {
            return None;
        }
        let alpha = cos_alpha.acos();
        Some(self.four_bar_pose(&fb, alpha, std::f64::consts::PI - alpha))
    }

    /// Fig. 3(a): the positions of `P2` relative to `P1` that the four-bar allows with
    /// end-effector 1 at `(p1, φ1)` — the coupler curve of the coupler's middle, sampled at
    /// `samples` crank angles `α` over a turn, both assemblies of each.
    #[must_use]
    pub fn end_effector2_curve(
        &self,
        p1: &Vector3<f64>,
        phi1: f64,
        samples: usize,
    ) -> Vec<[FourBarPose; 2]> {
        let fb = self.four_bar(p1, phi1);
        (0..samples)
            .filter_map(|k| {
                let alpha = std::f64::consts::TAU * k as f64 / samples as f64;
                let betas = self.rocker_angles(&fb, alpha)?;
                Some(betas.map(|beta| self.four_bar_pose(&fb, alpha, beta)))
            })
            .collect()
    }
}
