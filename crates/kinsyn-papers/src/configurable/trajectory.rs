//! The trajectory of paper 003 §5: the inputs `q_i(t)` move periodically and the assembly of
//! Table 2 is followed by a **parameter homotopy** (the position equations of method 2 with the
//! elbows `B_i` as parameters, [`elbow_family`]), with the corner velocities by implicit
//! differentiation of the same equations. Where the followed assembly stops being real (a
//! turning point: the Jacobian of the position equations singular, two real assemblies meeting
//! and leaving as a complex pair), the trajectory says so and where — it never continues on
//! another branch silently.

use super::{Configurable, CornerPose};
use kinsyn::geometry::sin_cos;
use kinsyn::homotopy::{ParametrizedSystem, TrackerSettings, track_parameters};
use kinsyn::poly::{C64, Poly, System};
use nalgebra::{DMatrix, DVector, Vector2};

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

fn elbow_parameters(m: &Configurable, q: &[f64; 4]) -> Vec<C64> {
    (0..4)
        .flat_map(|i| {
            let b = m.elbow(i, q[i]);
            [C64::from(b.x), C64::from(b.y)]
        })
        .collect()
}

fn pose_unknowns(p: &CornerPose) -> Vec<C64> {
    [
        p.c4.x,
        p.c4.y,
        p.theta.sin(),
        p.theta.cos(),
        p.phi.sin(),
        p.phi.cos(),
    ]
    .map(C64::from)
    .to_vec()
}

/// The assembly at inputs `q` nearest `guess` by Newton's method on the position equations
/// (method 2): `None` unless it converges (update below 1e-12 of the size) in 50 steps.
#[must_use]
pub fn assemble(m: &Configurable, q: &[f64; 4], guess: &CornerPose) -> Option<CornerPose> {
    let family = elbow_family(m);
    let program = family.program();
    let mut ws = program.workspace::<C64>();
    let p = elbow_parameters(m, q);
    let mut x: Vec<f64> = pose_unknowns(guess).iter().map(|c| c.re).collect();
    let mut values = vec![C64::from(0.0); 6];
    let mut jac = vec![C64::from(0.0); 6 * 14];
    for _ in 0..50 {
        let point: Vec<C64> = x
            .iter()
            .map(|v| C64::from(*v))
            .chain(p.iter().copied())
            .collect();
        program.evaluate_with_jacobian(&point, &mut values, &mut jac, &mut ws);
        let fx = DMatrix::from_fn(6, 6, |i, j| jac[i * 14 + j].re);
        let f = DVector::from_fn(6, |i, _| -values[i].re);
        let dx = fx.lu().solve(&f)?;
        for (xi, d) in x.iter_mut().zip(dx.iter()) {
            *xi += d;
        }
        if dx.norm() <= 1e-12 * (1.0 + x.iter().map(|v| v.abs()).fold(0.0, f64::max)) {
            return Some(CornerPose {
                c4: Vector2::new(x[0], x[1]),
                theta: x[2].atan2(x[3]),
                phi: x[4].atan2(x[5]),
            });
        }
    }
    None
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

/// How the following ended.
#[derive(Debug, Clone, PartialEq)]
pub enum TrajectoryEnd {
    /// Every instant reached on the same real branch.
    Completed,
    /// The followed assembly stopped being real (or regular) between two instants.
    Ceased {
        /// The last instant reached on the branch.
        last: f64,
        /// The first instant it was not found at.
        next: f64,
        /// Why.
        reason: String,
    },
}

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

/// The unknowns' rates `ẋ = −F_x⁻¹ F_p ṗ` and the Jacobian's inverse condition at `(x, p)`.
fn rates(family: &ParametrizedSystem, x: &[f64], p: &[f64], dp: &[f64]) -> Option<(Vec<f64>, f64)> {
    let point: Vec<C64> = x.iter().chain(p).map(|v| C64::from(*v)).collect();
    let program = family.program();
    let mut ws = program.workspace::<C64>();
    let mut values = vec![C64::from(0.0); 6];
    let mut jac = vec![C64::from(0.0); 6 * 14];
    program.evaluate_with_jacobian(&point, &mut values, &mut jac, &mut ws);
    let fx = DMatrix::from_fn(6, 6, |i, j| jac[i * 14 + j].re);
    let fp = DMatrix::from_fn(6, 8, |i, j| jac[i * 14 + 6 + j].re);
    let sv = fx.clone().singular_values();
    let inverse_condition = sv.min() / sv.max();
    let rhs = -(fp * DVector::from_column_slice(dp));
    let dx = fx.lu().solve(&rhs)?;
    Some((dx.iter().copied().collect(), inverse_condition))
}

fn sample(
    m: &Configurable,
    family: &ParametrizedSystem,
    t: f64,
    q: [f64; 4],
    dq: [f64; 4],
    x: &[f64],
) -> Option<Sample> {
    let p: Vec<f64> = elbow_parameters(m, &q).iter().map(|c| c.re).collect();
    let dp: Vec<f64> = (0..4)
        .flat_map(|i| [-m.a * q[i].sin() * dq[i], m.a * q[i].cos() * dq[i]])
        .collect();
    let (dx, inverse_condition) = rates(family, x, &p, &dp)?;
    let pose = CornerPose {
        c4: Vector2::new(x[0], x[1]),
        theta: x[2].atan2(x[3]),
        phi: x[4].atan2(x[5]),
    };
    let c = m.c;
    let d4 = Vector2::new(dx[0], dx[1]);
    let d1 = d4 + c * Vector2::new(dx[3], dx[2]);
    let d3 = d4 + c * Vector2::new(dx[5], dx[4]);
    Some(Sample {
        t,
        q,
        pose,
        corners: pose.corners(c),
        corner_velocities: [d1, d1 + d3 - d4, d3, d4],
        inverse_condition,
    })
}

/// Whether the real assembly `x` at `inputs(t0)` is followed to a real one at `inputs(t1)`.
fn step(
    family: &ParametrizedSystem,
    m: &Configurable,
    inputs: &impl Fn(f64) -> [f64; 4],
    x: &[C64],
    t0: f64,
    t1: f64,
) -> Option<Vec<C64>> {
    let (p0, p1) = (
        elbow_parameters(m, &inputs(t0)),
        elbow_parameters(m, &inputs(t1)),
    );
    let y = track_parameters(family, &p0, &p1, &[x.to_vec()], TrackerSettings::default())
        .ok()?
        .pop()?
        .ok()?;
    let size = 1.0 + y.iter().map(|c| c.norm()).fold(0.0, f64::max);
    y.iter().all(|c| c.im.abs() <= 1e-8 * size).then_some(y)
}

/// Narrows `[t0, t1]` (the assembly `x` real at `t0`, lost at `t1`; `t1 < t0` when followed
/// back in time) by bisection to the last instant reached and the first not, 1e-9 apart in `t`
/// (or 40 halvings).
fn bracket(
    family: &ParametrizedSystem,
    m: &Configurable,
    inputs: &impl Fn(f64) -> [f64; 4],
    x: &[C64],
    t0: f64,
    t1: f64,
) -> (f64, f64) {
    let (mut lo, mut hi, mut at) = (t0, t1, x.to_vec());
    for _ in 0..40 {
        if (hi - lo).abs() < 1e-9 {
            break;
        }
        let mid = 0.5 * (lo + hi);
        match step(family, m, inputs, &at, lo, mid) {
            Some(y) => {
                lo = mid;
                at = y;
            }
            None => hi = mid,
        }
    }
    (lo, hi)
}

/// Follows the assembly `start` (at the inputs `inputs(times[0])`) along the inputs
/// `inputs(t)`, `t` over `times` in order (increasing, or decreasing to follow it back in time),
/// by parameter homotopy between successive instants.
/// A step that fails, leaves the reals (imaginary parts above 1e-8 of the size) or ends on a
/// Jacobian with inverse condition below 1e-10 ends the trajectory with
/// [`TrajectoryEnd::Ceased`].
///
/// # Panics
/// If `times` is empty.
#[must_use]
pub fn follow(
    m: &Configurable,
    start: &CornerPose,
    inputs: impl Fn(f64) -> [f64; 4],
    input_rates: impl Fn(f64) -> [f64; 4],
    times: &[f64],
) -> TrajectoryReport {
    let family = elbow_family(m);
    let mut x: Vec<C64> = pose_unknowns(start);
    let mut samples = Vec::with_capacity(times.len());
    let mut least = f64::INFINITY;
    let mut previous: Option<(f64, Vec<C64>)> = None;
    for &t in times {
        let q = inputs(t);
        let p = elbow_parameters(m, &q);
        if let Some((t0, _)) = &previous {
            let Some(moved) = step(&family, m, &inputs, &x, *t0, t) else {
                let (last, next) = bracket(&family, m, &inputs, &x, *t0, t);
                let reason = "the assembly could not be followed as a real one: a turning point, where the position Jacobian is singular and two real assemblies meet and leave as a complex pair".to_string();
                return TrajectoryReport {
                    samples,
                    end: TrajectoryEnd::Ceased { last, next, reason },
                    least_inverse_condition: least,
                };
            };
            x = moved;
        }
        let real: Vec<f64> = x.iter().map(|c| c.re).collect();
        let Some(s) = sample(m, &family, t, q, input_rates(t), &real) else {
            return TrajectoryReport {
                samples,
                end: TrajectoryEnd::Ceased {
                    last: previous.map_or(t, |p| p.0),
                    next: t,
                    reason: "singular position Jacobian".into(),
                },
                least_inverse_condition: least,
            };
        };
        least = least.min(s.inverse_condition);
        if s.inverse_condition < 1e-10 {
            return TrajectoryReport {
                samples,
                end: TrajectoryEnd::Ceased {
                    last: previous.map_or(t, |p| p.0),
                    next: t,
                    reason: format!(
                        "a turning point: inverse condition {:.1e}",
                        s.inverse_condition
                    ),
                },
                least_inverse_condition: least,
            };
        }
        samples.push(s);
        previous = Some((t, p));
    }
    TrajectoryReport {
        samples,
        end: TrajectoryEnd::Completed,
        least_inverse_condition: least,
    }
}
