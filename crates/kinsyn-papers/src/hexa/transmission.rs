//! Jacobians and transmission indices (paper 001 §3.2): the forward and inverse Jacobians
//! `A`, `B` (eqs. 9–11), the input index `λ_i` of each limb (eq. 13), the output index `σ` of
//! end-effector 1 (eq. 16) and the output index `ξ_k` of limbs 4 and 5 (eq. 17, defined as
//! below: the printed screws cannot be used as they stand).
//!
//! # `ξ_k` (eq. 17)
//! End-effector 2 is driven by limbs 4 and 5 once end-effector 1 is held: it keeps two freedoms,
//! the four-bar's motion (which moves `P2` along the coupler curve) and its turn `φ2` about `k`
//! at `P2`. With limb `k`'s actuator driving and the other one locked, end-effector 2 makes one
//! motion, its *output twist*; the *transmission wrench* of limb `k` is the force its
//! parallelogram can carry, along `w_k` through `C_k`. Their reciprocal product is the power
//! `w_k · ċ_k`, and its largest value over force directions is `|ċ_k|`; so
//! `ξ_k = |w_k · ċ_k| / |ċ_k|`, the cosine of the pressure angle at `C_k`, in `[0, 1]`, and
//! 0 exactly where end-effector 2's 2 × 2 Jacobian is singular (both limbs' rates vanish on a
//! motion: a parallel singularity). The printed `ŝ_O = (k; r5 Q2 i)`, `ŝ_T = (w_k; b v_k × w_k)`
//! refer their moments to different points (`ŝ_T`'s is about `A_k`) and leave `|·|_max`
//! undefined; `tests/suite/hexa.rs` shows their product does not vanish at that singularity
//! (docs/deviations.md).

use super::{Configuration, Hexa, LimbState, rz};
use nalgebra::{DMatrix, DVector, Matrix2, Vector3};

/// The transmission indices at a configuration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Indices {
    /// `λ_1 … λ_6` (eq. 13).
    pub lambda: [f64; 6],
    /// `σ` of end-effector 1 (eq. 16).
    pub sigma: f64,
    /// `ξ_4`, `ξ_5` of end-effector 2 (eq. 17, module documentation).
    pub xi: [f64; 2],
}

impl Indices {
    /// The smallest input index, the robot's input transmission.
    #[must_use]
    pub fn lambda_min(&self) -> f64 {
        self.lambda.iter().copied().fold(f64::INFINITY, f64::min)
    }

    /// The smaller of `ξ_4`, `ξ_5`.
    #[must_use]
    pub fn xi_min(&self) -> f64 {
        self.xi[0].min(self.xi[1])
    }
}

/// The forward Jacobian `A` of eqs. 10a–11 (rows `e_i`, columns `ẋ1, ẏ1, ż, φ̇1, ẋ2, ẏ2, φ̇2`;
/// the printed `ż2` of eq. 10a is `ẋ2`, since `e_4`, `e_5` put `w_ix` there) from the limbs'
/// `w_i` and the vectors `s_i` (`s1 = s6 = −s2 = −s3 = r1 Q1 j`, `s5 = −s4 = r5 Q2 j`).
#[must_use]
pub fn forward_jacobian(w: &[Vector3<f64>; 6], s: &[Vector3<f64>; 6]) -> DMatrix<f64> {
    let mut a = DMatrix::zeros(6, 7);
    for i in 0..6 {
        let ws = w[i].dot(&s[i]);
        if i == 3 || i == 4 {
            a[(i, 2)] = w[i].z;
            a[(i, 4)] = w[i].x;
            a[(i, 5)] = w[i].y;
            a[(i, 6)] = ws;
        } else {
            a[(i, 0)] = w[i].x;
            a[(i, 1)] = w[i].y;
            a[(i, 2)] = w[i].z;
            a[(i, 3)] = ws;
        }
    }
    a
}

/// The output transmission index `σ` of end-effector 1 (eq. 16):
/// `|((w1 × w6) × (w2 × w3))·s1| / ‖(w1 × w6) × (w2 × w3)‖`, with `s1` a unit vector
/// (`Q1 j`: the index is `|cos ω|`, in `[0, 1]`).
#[must_use]
pub fn output_index(w: &[Vector3<f64>; 6], s1_unit: &Vector3<f64>) -> f64 {
    let n = w[0].cross(&w[5]).cross(&w[1].cross(&w[2]));
    let size = n.norm();
    if size == 0.0 {
        0.0
    } else {
        n.dot(s1_unit).abs() / size
    }
}

impl Hexa {
    /// `s_i` of eq. 11 at a pose: `s1 = s6 = −s2 = −s3 = r1 Q1 j`, `s5 = −s4 = r5 Q2 j`.
    #[must_use]
    pub fn s_vectors(&self, phi1: f64, phi2: f64) -> [Vector3<f64>; 6] {
        let s1 = rz(phi1) * Vector3::y() * self.r[0];
        let s5 = rz(phi2) * Vector3::y() * self.r[4];
        [s1, -s1, -s1, -s5, s5, s1]
    }

    /// `A` and `B = diag(h_i)` of eqs. 9–11 at a configuration: `A χ̇ = B θ̇` as printed, with
    /// `θ` about `+u_i` (the module [`super`]'s convention).
    #[must_use]
    pub fn jacobians(&self, conf: &Configuration) -> (DMatrix<f64>, DMatrix<f64>) {
        let w: [Vector3<f64>; 6] = std::array::from_fn(|i| conf.limbs[i].w);
        let s = self.s_vectors(conf.pose.phi1(), conf.pose.phi2());
        let b = DMatrix::from_diagonal(&DVector::from_fn(6, |i, _| self.h(i, &conf.limbs[i])));
        (forward_jacobian(&w, &s), b)
    }

    /// The velocity of `P2` along the coupler curve with end-effector 1 held, for a unit rate
    /// of the four-bar's motion (normalised crank rates) in the configuration's assembly, or
    /// `None` when `P2` is off the four-bar or the four-bar is at a change point.
    fn coupler_rate(&self, conf: &Configuration) -> Option<Vector3<f64>> {
        let ground = self.four_bar(&conf.pose.p1(), conf.pose.phi1());
        let fb = conf.four_bar?;
        // Crank tips move at k × (D − C) per unit crank rate; the coupler keeps its length:
        // g · (ω6 t6 − ω3 t3) = 0, so (ω3, ω6) ∝ (g · t6, g · t3).
        let t3 = Vector3::z().cross(&(fb.d3 - ground.c3));
        let t6 = Vector3::z().cross(&(fb.d6 - ground.c6));
        let g = fb.d6 - fb.d3;
        let (w3, w6) = (g.dot(&t6), g.dot(&t3));
        let size = w3.hypot(w6);
        (size > 0.0).then(|| (t3 * w3 + t6 * w6) / (2.0 * size))
    }

    /// End-effector 2's Jacobian with end-effector 1 held: rows limbs 4 and 5 (`w_k · ċ_k`),
    /// columns the four-bar's motion (`coupler_rate`) and `φ̇2`. Singular at end-effector 2's
    /// parallel singularities. `None` when `P2` is off the four-bar
    /// ([`Configuration::four_bar`]).
    #[must_use]
    pub fn end_effector2_jacobian(&self, conf: &Configuration) -> Option<Matrix2<f64>> {
        Some(end_effector2_rows(conf, &self.coupler_rate(conf)?))
    }

    /// `ξ_4`, `ξ_5` (eq. 17 as defined in the module documentation): the cosine of the pressure
    /// angle at `C_k` when limb `k` drives end-effector 2 with the other limb locked and
    /// end-effector 1 held. `[0, 0]` when `P2` is off the four-bar.
    #[must_use]
    pub fn end_effector2_indices(&self, conf: &Configuration) -> [f64; 2] {
        let Some(p2_rate) = self.coupler_rate(conf) else {
            return [0.0, 0.0];
        };
        let m = end_effector2_rows(conf, &p2_rate);
        [(3usize, 1usize), (4, 0)].map(|(k, other)| {
            // The motion the other limb allows: orthogonal to its row.
            let motion = (m[(other, 1)], -m[(other, 0)]);
            transmission_cosine(&conf.limbs[k], &joint_velocity(conf, &p2_rate, k, motion))
        })
    }

    /// Every index at a configuration.
    #[must_use]
    pub fn indices(&self, conf: &Configuration) -> Indices {
        let w: [Vector3<f64>; 6] = std::array::from_fn(|i| conf.limbs[i].w);
        Indices {
            lambda: std::array::from_fn(|i| self.input_index(i, &conf.limbs[i])),
            sigma: output_index(&w, &(rz(conf.pose.phi1()) * Vector3::y())),
            xi: self.end_effector2_indices(conf),
        }
    }
}

/// The velocity of the platform joint `C_k` of end-effector 2 (end-effector 1 held) when the
/// four-bar moves at `four_bar` units of `p2_rate` and end-effector 2 turns at `φ̇2` about `k`.
fn joint_velocity(
    conf: &Configuration,
    p2_rate: &Vector3<f64>,
    k: usize,
    (four_bar, phi2_rate): (f64, f64),
) -> Vector3<f64> {
    p2_rate * four_bar + Vector3::z().cross(&(conf.joints[k] - conf.pose.p2())) * phi2_rate
}

/// End-effector 2's Jacobian: rows limbs 4 and 5 (`w_k · ċ_k`), columns the four-bar's motion
/// and `φ̇2`.
fn end_effector2_rows(conf: &Configuration, p2_rate: &Vector3<f64>) -> Matrix2<f64> {
    let entry = |k: usize, motion| {
        conf.limbs[k]
            .w
            .dot(&joint_velocity(conf, p2_rate, k, motion))
    };
    Matrix2::new(
        entry(3, (1.0, 0.0)),
        entry(3, (0.0, 1.0)),
        entry(4, (1.0, 0.0)),
        entry(4, (0.0, 1.0)),
    )
}

/// `|w · v| / (|w| |v|)`: the share of the limb's force that does work on the velocity `v` of its
/// platform joint; 0 for a joint that does not move.
fn transmission_cosine(limb: &LimbState, velocity: &Vector3<f64>) -> f64 {
    let size = limb.w.norm() * velocity.norm();
    if size == 0.0 {
        0.0
    } else {
        (limb.w.dot(velocity) / size).abs().min(1.0)
    }
}
