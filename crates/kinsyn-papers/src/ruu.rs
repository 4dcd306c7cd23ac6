//! The **4-RUU** parallel manipulator of paper 004 (Nurahmi, Caro, Wenger, Schadlbauer, Husty,
//! *Reconfiguration analysis of a 4-RUU parallel manipulator*, Mech. Mach. Theory 2016, §2–3)
//! and its constraint equations `g1 … g14` in Study parameters, derived from the geometry with
//! the primitives of [`kinsyn::geometry`].
//!
//! # Geometry (paper 004 §2)
//! A square base and a square platform joined by four legs `i = 1 … 4`. Leg `i`'s actuated R
//! joint sits at `A_i = a e_i` with `e_i = (cos (i−1)π/2, sin (i−1)π/2, 0)` and turns about the
//! base's `Z` axis by `θ1i`; the link of length `l` carries the first U joint's centre
//! `B_i = A_i + l (cos θ1i, sin θ1i, 0)` (eq. 2). The U joint's first axis is `Z` (`v_i`), its
//! second `s_i = (cos θ2i, sin θ2i, 0)` (eq. 1, `θ2i` an absolute angle in the base plane, a
//! passive joint). The link `B_i C_i` has length `r`; the platform U joint's centre is
//! `C_i = b e_i` in the platform frame (eq. 3), its last axis the platform's `z` axis (`n_i`).
//!
//! # Constraints (paper 004 §3)
//! With the half-angle tangents `t1i = tan(θ1i/2)`, `t2i = tan(θ2i/2)` (eq. 8) and the Study
//! parameters of the platform ([`kinsyn::spatial::study`]):
//! - `g1 … g4` (eq. 10): the link `B_i C_i` lies in the plane of `v_i = Z` and `n_i`: the fixed
//!   line through `B_i` along `Z` and the moving line through `C_i` along `z` are coplanar
//!   ([`StudyVariables::lines_coplanar`]), times `1 + t1i²`;
//! - `g5 … g8` (eq. 12): `|C_i − B_i| = r` ([`StudyVariables::distance`]), times `1 + t1i²`;
//! - `g9 … g12` (eq. 13): `(C_i − B_i)·s_i = 0`
//!   ([`StudyVariables::moving_point_on_fixed_plane`]), times `(1 + t1i²)(1 + t2i²)`;
//! - `g13`: the Study quadric; `g14`: the normalisation `x0² + x1² + x2² + x3² = 1`.
//!
//! Every `g` is a polynomial in the Study parameters and the tangents, of degree 2 in the Study
//! parameters; `g1 … g12` hold for the parameters of a displacement (on the Study quadric) exactly
//! when the leg closes. Where the base point `B_i` depends on `t1i`, the primitives (which take
//! fixed points) are used through their affine (coplanarity, plane) or quadratic (distance)
//! dependence on the fixed point: `f(p) = f(0) + Σ p_k (f(e_k) − f(0))` for an affine `f`.
//!
//! `tests/suite/ruu.rs` compares the derived equations with the printed ones
//! (`data/paper004-constraints.txt`) and evaluates them at poses assembled independently;
//! `docs/deviations.md` lists the printed equations that differ.

use kinsyn::geometry::{PolyVector, STUDY_NAMES, StudyVariables};
use kinsyn::poly::{Poly, System};
use nalgebra::Vector3;

/// A 4-RUU manipulator of paper 004's architecture (module documentation): base radius `a`
/// (`|O A_i|`), platform radius `b` (`|P C_i|`), crank length `l` (`|A_i B_i|`) and coupler
/// length `r` (`|B_i C_i|`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ruu {
    /// The distance of the actuated joints `A_i` from the base centre `O`.
    pub a: f64,
    /// The distance of the platform joints `C_i` from the platform centre `P`.
    pub b: f64,
    /// The length of the crank `A_i B_i`.
    pub l: f64,
    /// The length of the coupler `B_i C_i`.
    pub r: f64,
}

/// How the actuated joints enter [`Ruu::constraints`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InputMode {
    /// The tangents `t11 … t14` are unknowns (the input–pose space; the paper's ideals over
    /// `ℂ[t11, …, t14]` with the tangents treated as variables for dimension counts).
    Free,
    /// Given inputs: the values of `t1i = tan(θ1i / 2)`, `i = 1 … 4`.
    Given([f64; 4]),
    /// Given inputs as the angles `θ1i` in radians: the equations use `cos θ1i` and `sin θ1i`
    /// in place of `(1 − t1i², 2 t1i) / (1 + t1i²)`, so `θ1i = π` (where the tangent is
    /// infinite; paper 004 §5.2 computes that self-motion "with the trigonometric functions")
    /// is covered. The factors `1 + t1i²` of the module documentation are then 1.
    Angles([f64; 4]),
}

/// Why a 4-RUU or its inputs are not valid.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum RuuError {
    /// A design parameter is not a positive finite length.
    #[error("the 4-RUU's {name} = {value} is not a positive finite length")]
    Length {
        /// `a`, `b`, `l` or `r`.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// A given input tangent is NaN or infinite.
    #[error("the input t1{leg} = {value} is not finite")]
    Input {
        /// The leg, 1 … 4.
        leg: usize,
        /// The value given.
        value: f64,
    },
}

/// The unit vector `e_i` of leg `i` (0-based): `(cos iπ/2, sin iπ/2, 0)`, exact.
fn leg_direction(i: usize) -> Vector3<f64> {
    match i % 4 {
        0 => Vector3::new(1.0, 0.0, 0.0),
        1 => Vector3::new(0.0, 1.0, 0.0),
        2 => Vector3::new(-1.0, 0.0, 0.0),
        _ => Vector3::new(0.0, -1.0, 0.0),
    }
}

impl Ruu {
    /// A 4-RUU with the given lengths.
    ///
    /// # Errors
    /// [`RuuError::Length`] if a length is not positive and finite.
    pub fn new(a: f64, b: f64, l: f64, r: f64) -> Result<Self, RuuError> {
        for (name, value) in [("a", a), ("b", b), ("l", l), ("r", r)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(RuuError::Length { name, value });
            }
        }
        Ok(Self { a, b, l, r })
    }

    /// Paper 004's design (§4.1): `a = 2, b = 1, l = 1, r = 2`.
    #[must_use]
    pub fn paper004() -> Self {
        Self {
            a: 2.0,
            b: 1.0,
            l: 1.0,
            r: 2.0,
        }
    }

    /// The actuated joint `A_i` of leg `i` (0-based, `i < 4`) in the base frame (eq. 2).
    #[must_use]
    pub fn base_joint(&self, i: usize) -> Vector3<f64> {
        leg_direction(i) * self.a
    }

    /// The base U joint's centre `B_i` of leg `i` (0-based) at the input angle `θ1i` (eq. 2):
    /// `A_i + l (cos θ1i, sin θ1i, 0)`.
    #[must_use]
    pub fn crank_joint(&self, i: usize, theta: f64) -> Vector3<f64> {
        self.base_joint(i) + Vector3::new(theta.cos(), theta.sin(), 0.0) * self.l
    }

    /// The platform U joint's centre `C_i` of leg `i` (0-based) in the platform frame (eq. 3).
    #[must_use]
    pub fn platform_joint(&self, i: usize) -> Vector3<f64> {
        leg_direction(i) * self.b
    }

    /// The names of the unknowns of [`Self::constraints`]: `x0 … x3, y0 … y3`, then
    /// `t11 … t14` when the inputs are [`InputMode::Free`], then the passive `t21 … t24`.
    #[must_use]
    pub fn variable_names(inputs: &InputMode) -> Vec<String> {
        let mut names: Vec<String> = STUDY_NAMES.iter().map(|s| (*s).to_string()).collect();
        if matches!(inputs, InputMode::Free) {
            names.extend((1..=4).map(|i| format!("t1{i}")));
        }
        names.extend((1..=4).map(|i| format!("t2{i}")));
        names
    }

    /// Paper 004's constraint equations `g1 … g14` (§3, eqs. 10–13 and the Study quadric and
    /// normalisation), in this order, derived from the geometry (module documentation). The
    /// unknowns are [`Self::variable_names`]. `g1 … g12` are multiplied by `1 + t1i²` (and
    /// `g9 … g12` also by `1 + t2i²`) to clear the half-angle denominators, as in the paper.
    ///
    /// # Errors
    /// [`RuuError::Input`] if a given input tangent is not finite.
    ///
    /// # Panics
    /// Never: the names are distinct and every equation is in their ring.
    pub fn constraints(&self, inputs: InputMode) -> Result<System, RuuError> {
        if let InputMode::Given(t) | InputMode::Angles(t) = inputs
            && let Some((i, v)) = t.iter().enumerate().find(|(_, v)| !v.is_finite())
        {
            return Err(RuuError::Input {
                leg: i + 1,
                value: *v,
            });
        }
        let names = Self::variable_names(&inputs);
        let n = names.len();
        let s = StudyVariables::leading(n);
        let passive0 = n - 4;
        let one = Poly::real(n, 1.0);
        // (1 + t², (1 + t²) cos θ, (1 + t²) sin θ) = (1 + t², 1 − t², 2t) of the input angle.
        let crank = |i: usize| -> (Poly, Poly, Poly) {
            let t = match inputs {
                InputMode::Free => Poly::variable(n, 8 + i),
                InputMode::Given(t) => Poly::real(n, t[i]),
                InputMode::Angles(theta) => {
                    return (
                        one.clone(),
                        Poly::real(n, theta[i].cos()),
                        Poly::real(n, theta[i].sin()),
                    );
                }
            };
            (&one + &(&t * &t), &one - &(&t * &t), t * 2.0)
        };
        let z = Vector3::z();
        let zero = Vector3::zeros();
        let basis = [Vector3::x(), Vector3::y(), Vector3::z()];
        let mut coplanar = Vec::new();
        let mut length = Vec::new();
        let mut axis = Vec::new();
        for i in 0..4 {
            let (w1, cos1, sin1) = crank(i);
            let t2 = Poly::variable(n, passive0 + i);
            let cos2 = &one - &(&t2 * &t2);
            let sin2 = t2.clone() * 2.0;
            let ai = self.base_joint(i);
            let ci = self.platform_joint(i);
            // (1 + t1²) B_i.
            let wb: PolyVector = [
                w1.clone() * ai.x + cos1.clone() * self.l,
                w1.clone() * ai.y + sin1.clone() * self.l,
                w1.clone() * ai.z,
            ];
            // g1..g4: the line through B_i along Z and the moving line through C_i along z.
            let f0 = s.lines_coplanar(&zero, &z, &ci, &z);
            let mut g = &w1 * &f0;
            for k in 0..3 {
                g = g + &wb[k] * &(s.lines_coplanar(&basis[k], &z, &ci, &z) - f0.clone());
            }
            coplanar.push(g);
            // g5..g8: |C_i − B_i| = r; the distance is quadratic in B with Hessian 2Δ.
            let d0 = s.distance(&zero, &ci, self.r);
            let delta = s.delta();
            // (1 + t1²)|B_i|² = (1 + t1²)(|A_i|² + l²) + 2 l A_i·(1 − t1², 2 t1, 0).
            let w_b2 = w1.clone() * (ai.norm_squared() + self.l * self.l)
                + (cos1.clone() * ai.x + sin1.clone() * ai.y) * (2.0 * self.l);
            let mut g = &w1 * &d0 + &w_b2 * &delta;
            for k in 0..3 {
                let linear = s.distance(&basis[k], &ci, self.r) - d0.clone() - delta.clone();
                g = g + &wb[k] * &linear;
            }
            length.push(g);
            // g9..g12: (C_i − B_i)·s_i = 0, bilinear in the normal s_i and the point B_i.
            let ws: PolyVector = [cos2, sin2, Poly::zero(n)];
            let mut g = Poly::zero(n);
            for k in 0..3 {
                let p = s.moving_point_on_fixed_plane(&ci, &zero, &basis[k]);
                let q = s.moving_point_on_fixed_plane(&ci, &basis[k], &basis[k]) - p.clone();
                g = g + &ws[k] * &(&(&w1 * &p) + &(&wb[k] * &q));
            }
            axis.push(g);
        }
        let mut equations = coplanar;
        equations.extend(length);
        equations.extend(axis);
        equations.push(s.quadric());
        equations.push(s.unit_normalisation());
        Ok(System::new(names, equations).expect("distinct names, equations in their ring"))
    }
}
