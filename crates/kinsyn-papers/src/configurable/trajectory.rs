//! The trajectory of paper 003 §5: the inputs `q_i(t)` move periodically and the assembly of
//! Table 2 is followed as a real branch of the position equations of method 2 with the elbows
//! `B_i` as parameters ([`elbow_family`]), by the engine's general follower
//! ([`kinsyn::homotopy::follow_real`]: parameter homotopy between instants, rates by implicit
//! differentiation), the corner velocities from the unknowns' rates. Where the followed
//! assembly stops being real (a turning point: the Jacobian of the position equations
//! singular, two real assemblies meeting and leaving as a complex pair), the trajectory says so
//! and where — it never continues on another branch silently. What is the paper's here: the
//! equations, the inputs of §5 and the corners.

use super::{Configurable, CornerPose};
use kinsyn::geometry::sin_cos;
use kinsyn::homotopy::{BranchEnd, BranchPoint, ParametrizedSystem, follow_real, real_newton};
use kinsyn::poly::{Poly, System};
use nalgebra::Vector2;

/// The unknowns of method 2 (§3.2): `x4, y4, sin θ, cos θ, sin φ, cos φ`.
pub const UNKNOWNS: [&str; 6] = ["x4", "y4", "st", "ct", "sp", "cp"];

/// The inputs of §5 at time `t` (s): `q1 = 2.477 − 1.5 sin t cos t`, `q2 = 3.549 − 1.25 sin t
/// cos t`, `q3 = 5.895 − 2 sin t cos t`, `q4 = 5.331 + 1.5 sin t cos t` (radians).
#[must_use]
pub fn paper_inputs(t: f64) -> [f64; 4] {
    let s = t.sin() * t.cos();
    [
        2.477 - 1.5 * s,
        3.549 - 1.25 * s,
        5.895 - 2.0 * s,
        5.331 + 1.5 * s,
    ]
}

/// The input rates `dq_i/dt` of [`paper_inputs`] (`d(sin t cos t)/dt = cos 2t`), rad/s.
#[must_use]
pub fn paper_input_rates(t: f64) -> [f64; 4] {
    let d = (2.0 * t).cos();
    [-1.5 * d, -1.25 * d, -2.0 * d, 1.5 * d]
}

/// The instants of one period `[0, 2π]` s at which [`paper_inputs`] take a value they take on
/// `[0, turning]`, where `turning` is the first instant after `t = 0` at which the followed real
/// assembly is lost (a turning point). The inputs depend on `t` only through
/// `sin t cos t = ½ sin 2t`, which rises from 0 on `[0, π/4]`; so they repeat the values of
/// `[0, turning]` (`sin 2t ≤ sin 2·turning`, for `turning ≤ π/4`) exactly on
/// `[0, turning] ∪ [π/2 − turning, π + turning] ∪ [3π/2 − turning, 2π]`, returned in that order.
/// Whether the *whole* of those instants has real assemblies is a claim about the values of
/// `sin 2t` below 0 as well, which a caller checks (the trajectory test follows the branch back
/// in time from `2π` and counts assemblies on every interval).
///
/// `None` unless `turning` is in `(0, π/4]`.
#[must_use]
pub fn paper_recurring_intervals(turning: f64) -> Option<[(f64, f64); 3]> {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};
    (turning > 0.0 && turning <= FRAC_PI_4).then_some({
        [
            (0.0, turning),
            (FRAC_PI_2 - turning, PI + turning),
            (3.0 * FRAC_PI_2 - turning, TAU),
        ]
    })
}

/// Method 2's position equations (eqs. 6, 13–15) with the elbows as parameters: unknowns
/// [`UNKNOWNS`], then parameters `bx1, by1, …, bx4, by4`. The four equations
/// `|C_i − B_i|² − b²` are linear in the parameters, so the family is polynomial in them.
///
/// # Panics
/// Never: the names are distinct.
#[must_use]
pub fn elbow_family(m: &Configurable) -> ParametrizedSystem {
    let n = 14;
    let v = |i| Poly::variable(n, i);
    let k = |x: f64| Poly::real(n, x);
    let (x4, y4, st, ct, sp, cp) = (v(0), v(1), v(2), v(3), v(4), v(5));
    let c = m.c;
    let c1 = [&x4 + &(ct.clone() * c), &y4 + &(st.clone() * c)];
    let c3 = [&x4 + &(cp.clone() * c), &y4 + &(sp.clone() * c)];
    let c2 = [&(&c1[0] + &c3[0]) - &x4, &(&c1[1] + &c3[1]) - &y4];
    let c4 = [x4.clone(), y4.clone()];
    let corners = [c1, c2, c3, c4];
    let mut equations: Vec<Poly> = corners
        .iter()
        .enumerate()
        .map(|(i, ci)| {
            let dx = &ci[0] - &v(6 + 2 * i);
            let dy = &ci[1] - &v(7 + 2 * i);
            &dx * &dx + &dy * &dy - k(m.b * m.b)
        })
        .collect();
    equations.push(sin_cos(&st, &ct));
    equations.push(sin_cos(&sp, &cp));
    let mut names: Vec<String> = UNKNOWNS.iter().map(ToString::to_string).collect();
    for i in 1..=4 {
        names.push(format!("bx{i}"));
        names.push(format!("by{i}"));
    }
    let system = System::new(names, equations).expect("distinct names");
    ParametrizedSystem::new(system, 8).expect("six equations in six unknowns")
}

/// The elbows `B_i(q_i)` as the family's parameters `bx1, by1, …, bx4, by4`.
fn elbow_parameters(m: &Configurable, q: &[f64; 4]) -> Vec<f64> {
    (0..4)
        .flat_map(|i| {
            let b = m.elbow(i, q[i]);
            [b.x, b.y]
        })
        .collect()
}

/// The elbows' rates `Ḃ_i = a q̇_i (−sin q_i, cos q_i)` in the order of [`elbow_parameters`].
fn elbow_rates(m: &Configurable, q: &[f64; 4], dq: &[f64; 4]) -> Vec<f64> {
    (0..4)
        .flat_map(|i| [-m.a * q[i].sin() * dq[i], m.a * q[i].cos() * dq[i]])
        .collect()
}

/// The pose as the family's unknowns [`UNKNOWNS`].
fn pose_unknowns(p: &CornerPose) -> Vec<f64> {
    vec![
        p.c4.x,
        p.c4.y,
        p.theta.sin(),
        p.theta.cos(),
        p.phi.sin(),
        p.phi.cos(),
    ]
}

/// The pose of the unknowns [`UNKNOWNS`].
fn pose_of(x: &[f64]) -> CornerPose {
    CornerPose {
        c4: Vector2::new(x[0], x[1]),
        theta: x[2].atan2(x[3]),
        phi: x[4].atan2(x[5]),
    }
}

/// The assembly at inputs `q` nearest `guess` by Newton's method on the position equations
/// (method 2, [`kinsyn::homotopy::real_newton`]): `None` unless it converges (update below
/// 1e-12 of the size) in 50 steps.
#[must_use]
pub fn assemble(m: &Configurable, q: &[f64; 4], guess: &CornerPose) -> Option<CornerPose> {
    let family = elbow_family(m);
    real_newton(&family, &pose_unknowns(guess), &elbow_parameters(m, q)).map(|x| pose_of(&x))
}

/// One instant of the followed trajectory.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// Time (s).
    pub t: f64,
    /// The inputs (rad).
    pub q: [f64; 4],
    /// The platform (eq. 13's parametrisation).
    pub pose: CornerPose,
    /// The corners `C_1 … C_4`.
    pub corners: [Vector2<f64>; 4],
    /// The corner velocities `Ċ_1 … Ċ_4` (mm/s for lengths in mm).
    pub corner_velocities: [Vector2<f64>; 4],
    /// `σ_min / σ_max` of the position equations' Jacobian in the unknowns: zero at a turning
    /// point of the inputs (where assemblies meet).
    pub inverse_condition: f64,
}

/// How the following ended: the general [`BranchEnd`] of [`follow_real`], its reason worded
/// for assemblies ("assembly" where the solver says "solution").
pub type TrajectoryEnd = BranchEnd;

/// The followed trajectory.
#[derive(Debug, Clone, PartialEq)]
pub struct TrajectoryReport {
    /// The instants reached, in order.
    pub samples: Vec<Sample>,
    /// How it ended.
    pub end: TrajectoryEnd,
    /// The smallest inverse condition met.
    pub least_inverse_condition: f64,
}

/// The instant `point` of the followed branch as a sample of the trajectory: the pose, the
/// corners and their velocities (`Ċ_4 = ẋ4`, `Ċ_1 = Ċ_4 + c (ċos θ, ṡin θ)`, `Ċ_3` likewise with
/// `φ`, `Ċ_2 = Ċ_1 + Ċ_3 − Ċ_4`).
fn sample(m: &Configurable, q: [f64; 4], point: &BranchPoint) -> Sample {
    let (x, dx) = (&point.x, &point.rates);
    let pose = pose_of(x);
    let c = m.c;
    let d4 = Vector2::new(dx[0], dx[1]);
    let d1 = d4 + c * Vector2::new(dx[3], dx[2]);
    let d3 = d4 + c * Vector2::new(dx[5], dx[4]);
    Sample {
        t: point.t,
        q,
        pose,
        corners: pose.corners(c),
        corner_velocities: [d1, d1 + d3 - d4, d3, d4],
        inverse_condition: point.inverse_condition,
    }
}

/// Follows the assembly `start` (at the inputs `inputs(times[0])`) along the inputs
/// `inputs(t)`, `t` over `times` in order (increasing, or decreasing to follow it back in time),
/// as a real branch of [`elbow_family`] ([`follow_real`]). A step that fails, leaves the reals
/// or ends on a Jacobian with inverse condition below 1e-10 ends the trajectory with
/// [`TrajectoryEnd::Ceased`].
#[must_use]
pub fn follow(
    m: &Configurable,
    start: &CornerPose,
    inputs: impl Fn(f64) -> [f64; 4],
    input_rates: impl Fn(f64) -> [f64; 4],
    times: &[f64],
) -> TrajectoryReport {
    let family = elbow_family(m);
    let branch = follow_real(
        &family,
        &pose_unknowns(start),
        |t| elbow_parameters(m, &inputs(t)),
        |t| elbow_rates(m, &inputs(t), &input_rates(t)),
        times,
    );
    TrajectoryReport {
        samples: branch
            .points
            .iter()
            .map(|p| sample(m, inputs(p.t), p))
            .collect(),
        end: match branch.end {
            BranchEnd::Completed => BranchEnd::Completed,
            BranchEnd::Ceased { last, next, reason } => BranchEnd::Ceased {
                last,
                next,
                reason: reason
                    .replace("solutions", "assemblies")
                    .replace("solution", "assembly"),
            },
        },
        least_inverse_condition: branch.least_inverse_condition,
    }
}
