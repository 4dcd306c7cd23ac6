//! Serial kinematic chains: joint screws, forward kinematics, the chain Jacobian, and the
//! generic 6P+6R chain of paper 000 §3 with its particularisations.
//!
//! A [`SerialChain`] is a list of primitive joints (P or R), each with its axis direction and a
//! point of its axis at the reference configuration (all joint values zero). Its motion is the
//! product of exponentials `g(q) = exp(ξ1 q1) ··· exp(ξn qn)`, and column `i` of its (spatial)
//! Jacobian is the twist of joint `i` carried to the current configuration by the joints before
//! it. A twist `(ω; v)` is referred to the base frame origin (ARCHITECTURE.md, Conventions).
//!
//! ```
//! use kinsyn::chain::SerialChain;
//! use kinsyn::notation::Primitive;
//! use nalgebra::Vector3;
//! // A planar RR arm: two revolutes about z through (0,0,0) and (1,0,0).
//! let arm = SerialChain::new(vec![
//!     (Primitive::R, Vector3::z(), Vector3::zeros()),
//!     (Primitive::R, Vector3::z(), Vector3::new(1.0, 0.0, 0.0)),
//! ]).unwrap();
//! let j = arm.jacobian(&[std::f64::consts::FRAC_PI_2, 0.0]);
//! // After a quarter turn of the first joint the second axis passes through (0, 1, 0):
//! // its twist is (z; p × z) with p = (0, 1, 0), i.e. v = (1, 0, 0).
//! assert!((j[(3, 1)] - 1.0).abs() < 1e-12 && j[(4, 1)].abs() < 1e-12);
//! ```

use crate::notation::{Axis, Primitive};
use crate::screw::{Twist, transform_twist};
pub use crate::spatial::{Displacement, compose};
use nalgebra::{Matrix6xX, Rotation3, Unit, Vector3};
use rand::Rng;

/// One primitive joint of a serial chain at the reference configuration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointAxis {
    /// P or R.
    pub kind: Primitive,
    /// Unit direction of the axis (rotation axis or sliding direction).
    pub axis: Vector3<f64>,
    /// A point of the axis (ignored for P).
    pub point: Vector3<f64>,
}

impl JointAxis {
    /// The unit joint screw at the reference configuration: `(u; p × u)` for R, `(0; u)` for P.
    #[must_use]
    pub fn screw(&self) -> Twist {
        match self.kind {
            Primitive::R => Twist::revolute(self.axis, self.point),
            Primitive::P => Twist::prismatic(self.axis),
        }
    }

    /// The displacement `exp(ξ q)` of this joint by `q` (radians or length units).
    #[must_use]
    pub fn displacement(&self, q: f64) -> Displacement {
        match self.kind {
            Primitive::P => crate::spatial::displacement(Rotation3::identity(), self.axis * q),
            Primitive::R => {
                let r = Rotation3::from_axis_angle(&Unit::new_unchecked(self.axis), q);
                let t = self.point - r * self.point;
                crate::spatial::displacement(r, t)
            }
        }
    }
}

/// Why a chain description was rejected.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ChainError {
    /// An axis direction of zero (or non-finite) length.
    #[error("joint {joint}: the axis direction has no length")]
    DegenerateAxis {
        /// 1-based joint index.
        joint: usize,
    },
    /// A point with a non-finite coordinate.
    #[error("joint {joint}: the axis point is not finite")]
    NonFinitePoint {
        /// 1-based joint index.
        joint: usize,
    },
    /// Layout data of different lengths.
    #[error("{0}")]
    Layout(String),
}

/// A serial chain of primitive joints, base to platform.
#[derive(Debug, Clone, PartialEq)]
pub struct SerialChain {
    joints: Vec<JointAxis>,
}

impl SerialChain {
    /// A chain from `(kind, axis direction, axis point)` per joint; directions are normalised.
    ///
    /// # Errors
    /// A zero or non-finite direction, or a non-finite point.
    pub fn new(joints: Vec<(Primitive, Vector3<f64>, Vector3<f64>)>) -> Result<Self, ChainError> {
        let mut out = Vec::with_capacity(joints.len());
        for (i, (kind, axis, point)) in joints.into_iter().enumerate() {
            let n = axis.norm();
            if !n.is_finite() || n < 1e-12 {
                return Err(ChainError::DegenerateAxis { joint: i + 1 });
            }
            if !point.iter().all(|c| c.is_finite()) {
                return Err(ChainError::NonFinitePoint { joint: i + 1 });
            }
            out.push(JointAxis {
                kind,
                axis: axis / n,
                point,
            });
        }
        Ok(SerialChain { joints: out })
    }

    /// The joints at the reference configuration.
    #[must_use]
    pub fn joints(&self) -> &[JointAxis] {
        &self.joints
    }

    /// Number of primitive joints.
    #[must_use]
    pub fn len(&self) -> usize {
        self.joints.len()
    }

    /// Whether the chain has no joint.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.joints.is_empty()
    }

    /// The platform displacement `g(q) = exp(ξ1 q1) ··· exp(ξn qn)` relative to the reference
    /// configuration.
    ///
    /// # Panics
    /// If `q` has fewer values than the chain has joints.
    #[must_use]
    pub fn forward(&self, q: &[f64]) -> Displacement {
        assert!(q.len() >= self.joints.len(), "one joint value per joint");
        self.joints
            .iter()
            .zip(q)
            .fold(crate::spatial::identity(), |g, (j, &qi)| {
                compose(&g, &j.displacement(qi))
            })
    }

    /// The spatial Jacobian at `q`: column `i` is the unit twist of joint `i` in the base frame,
    /// so that the platform twist is `J q̇`.
    ///
    /// # Panics
    /// If `q` has fewer values than the chain has joints.
    #[must_use]
    pub fn jacobian(&self, q: &[f64]) -> Matrix6xX<f64> {
        let mut j = Matrix6xX::zeros(self.joints.len());
        self.jacobian_into(q, &mut j);
        j
    }

    /// [`SerialChain::jacobian`] into a preallocated 6×n matrix.
    ///
    /// # Panics
    /// If `q` or `out` is shorter than the chain.
    pub fn jacobian_into(&self, q: &[f64], out: &mut Matrix6xX<f64>) {
        assert!(
            q.len() >= self.joints.len() && out.ncols() >= self.joints.len(),
            "one joint value and column per joint"
        );
        // The displacement of the joints before joint i carries its reference screw along.
        let mut g = crate::spatial::identity();
        for (i, (joint, &qi)) in self.joints.iter().zip(q).enumerate() {
            let t = transform_twist(&g.rotation, &g.translation.vector, &joint.screw());
            out.column_mut(i).copy_from(&t.to_vector());
            if qi != 0.0 {
                g = compose(&g, &joint.displacement(qi));
            }
        }
    }

    /// The chain seen from a displaced base frame: every axis moved by `(R, p)`.
    #[must_use]
    pub fn transformed(&self, rotation: &Rotation3<f64>, translation: &Vector3<f64>) -> Self {
        SerialChain {
            joints: self
                .joints
                .iter()
                .map(|j| JointAxis {
                    kind: j.kind,
                    axis: rotation * j.axis,
                    point: rotation * j.point + translation,
                })
                .collect(),
        }
    }

    /// The chain with only the joints for which `keep` is true (the others held at zero).
    #[must_use]
    pub fn subchain(&self, keep: impl Fn(usize) -> bool) -> Self {
        SerialChain {
            joints: self
                .joints
                .iter()
                .enumerate()
                .filter(|(i, _)| keep(*i))
                .map(|(_, j)| *j)
                .collect(),
        }
    }

    /// A concrete chain for a catalogue layout: primitive `word`, axis directions `axes`, and `blocks`, the number of primitives in each joint letter in
    /// order (a C, U or S block shares one point: coaxial or intersecting axes, rules 2–3).
    /// Consecutive blocks are offset by generic non-zero vectors drawn from `rng` (length 0.5 to
    /// 1.5 in a random direction), so no other coincidence holds.
    ///
    /// # Errors
    /// If the lengths of `word`, `axes` and `blocks` disagree.
    pub fn from_layout(
        word: &[Primitive],
        axes: &[Axis],
        blocks: &[usize],
        rng: &mut impl Rng,
    ) -> Result<Self, ChainError> {
        if word.len() != axes.len() || blocks.iter().sum::<usize>() != word.len() {
            return Err(ChainError::Layout(format!(
                "word of {} joints, {} axes, blocks {:?}",
                word.len(),
                axes.len(),
                blocks
            )));
        }
        let mut joints = Vec::with_capacity(word.len());
        let mut point = random_unit(rng) * rng.random_range(0.0..0.5);
        let mut at = 0;
        for &size in blocks {
            for k in at..at + size {
                joints.push(JointAxis {
                    kind: word[k],
                    axis: axes[k].unit(),
                    point,
                });
            }
            at += size;
            point += random_unit(rng) * rng.random_range(0.5..1.5);
        }
        Ok(SerialChain { joints })
    }
}

/// A uniformly random unit vector.
pub fn random_unit(rng: &mut impl Rng) -> Vector3<f64> {
    loop {
        let v = Vector3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let n = v.norm();
        if n > 0.1 && n <= 1.0 {
            return v / n;
        }
    }
}

/// A random configuration of a serial chain: revolutes in [−π, π), prismatics in [−1, 1)
/// (lengths in the chain's units), one value per joint in chain order.
pub fn random_configuration(chain: &SerialChain, rng: &mut impl Rng) -> Vec<f64> {
    chain
        .joints()
        .iter()
        .map(|j| match j.kind {
            Primitive::R => rng.random_range(-std::f64::consts::PI..std::f64::consts::PI),
            Primitive::P => rng.random_range(-1.0..1.0),
        })
        .collect()
}

/// The joints of the generic chain of paper 000 Fig. 1, in order from the base: prismatic
/// `a`, revolute `α`, prismatic `b`, revolute `β`, ... — six P and six R alternating.
pub const GENERIC_JOINTS: [&str; 12] = [
    "a", "alpha", "b", "beta", "c", "gamma", "d", "phi", "e", "theta", "f", "psi",
];

/// The generic 6P+6R kinematic chain of paper 000 §3 (Fig. 1, eqs. 1–4).
///
/// Its loop equation (eq. 2) is `r_P = r_A + a·u_a + b·u_b + c·u_c + d·u_d + e·u_e + f·u_f + GP`:
/// each prismatic joint's value is the length of the link it drives, and each revolute turns
/// every later link. Constant-length bars are prismatic joints held at a fixed length; absent
/// joints are held at zero (eq. 5).
#[derive(Debug, Clone, PartialEq)]
pub struct GenericChain {
    /// `r_A`, the base point.
    pub base: Vector3<f64>,
    /// Unit directions at the reference configuration, in [`GENERIC_JOINTS`] order:
    /// `u_a, u_α, u_b, u_β, u_c, u_γ, u_d, u_φ, u_e, u_θ, u_f, u_ψ`.
    pub directions: [Vector3<f64>; 12],
    /// `GP` at the reference configuration: from the last joint's point to the platform point.
    pub gp: Vector3<f64>,
}

/// The configuration of the generic chain: one value per joint, [`GENERIC_JOINTS`] order.
pub type GenericValues = [f64; 12];

impl GenericChain {
    /// The rotation every link after joint `k` has turned by, and the current directions.
    fn current(&self, q: &GenericValues) -> ([Vector3<f64>; 12], Rotation3<f64>) {
        let mut rot = Rotation3::identity();
        let mut dirs = [Vector3::zeros(); 12];
        for k in 0..12 {
            dirs[k] = rot * self.directions[k];
            if k % 2 == 1 {
                rot = Rotation3::from_axis_angle(&Unit::new_normalize(dirs[k]), q[k]) * rot;
            }
        }
        (dirs, rot)
    }

    /// The platform point `r_P` by the loop equation (eq. 2).
    #[must_use]
    pub fn platform_point(&self, q: &GenericValues) -> Vector3<f64> {
        let (dirs, rot) = self.current(q);
        let mut r = self.base;
        for k in (0..12).step_by(2) {
            r += dirs[k] * q[k];
        }
        r + rot * self.gp
    }

    /// The platform's angular velocity `ω` and the velocity `v_P` of the platform point by the
    /// velocity equation (eqs. 3–4): `v_P = Σ ḋ·u_d + Σ ω_link × link + ω × GP`, with
    /// `ω_b = α̇ u_α`, `ω_c = ω_b + β̇ u_β`, ..., `ω = ω_f + ψ̇ u_ψ`.
    #[must_use]
    pub fn velocity(
        &self,
        q: &GenericValues,
        rates: &GenericValues,
    ) -> (Vector3<f64>, Vector3<f64>) {
        let (dirs, rot) = self.current(q);
        let mut omega = Vector3::zeros();
        let mut v = Vector3::zeros();
        for k in 0..12 {
            if k % 2 == 0 {
                // Prismatic k drives link vector q[k]·u_k, which turns with the links before it.
                v += dirs[k] * rates[k] + omega.cross(&(dirs[k] * q[k]));
            } else {
                omega += dirs[k] * rates[k];
            }
        }
        (omega, v + omega.cross(&(rot * self.gp)))
    }

    /// The chain as a [`SerialChain`] of the joints not held, in order, at the configuration
    /// `held` (the values of held joints are fixed there, those of free joints are the
    /// reference). Paper 000 eq. 5: `a = b = d = e = f = 0, ψ = 0` leaves the UPS leg.
    ///
    /// Returns the chain and the platform point at that configuration; the chain's joint values
    /// are displacements from `held`.
    #[must_use]
    pub fn particularise(
        &self,
        held: &GenericValues,
        free: &[bool; 12],
    ) -> (SerialChain, Vector3<f64>) {
        let (dirs, rot) = self.current(held);
        let mut point = self.base;
        let mut joints = Vec::new();
        for k in 0..12 {
            if free[k] {
                let kind = if k % 2 == 0 {
                    Primitive::P
                } else {
                    Primitive::R
                };
                joints.push(JointAxis {
                    kind,
                    axis: dirs[k].normalize(),
                    point,
                });
            }
            if k % 2 == 0 {
                point += dirs[k] * held[k];
            }
        }
        (SerialChain { joints }, point + rot * self.gp)
    }
}
