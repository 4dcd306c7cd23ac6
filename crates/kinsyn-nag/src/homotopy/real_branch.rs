//! One **real** solution of a parametrized system `F(x; p) = 0` followed along a real path of
//! parameters `p(t)`: a real branch, by parameter homotopy between successive instants
//! ([`track_parameters`]), with the rates of the unknowns by implicit differentiation
//! (`ẋ = −F_x⁻¹ F_p ṗ`). Where the followed solution stops being real (a turning point: `F_x`
//! singular, two real solutions meeting and leaving as a complex pair), the branch ends and says
//! where, between the last instant reached and the first not, narrowed by bisection; it never
//! continues on another branch silently.
//!
//! In kinematics `x` is an assembly, `p` the inputs (or a function of them) and `t` time: a
//! trajectory of a mechanism driven through its inputs.

use super::{ParametrizedSystem, REAL_TOLERANCE, TrackerSettings, track_parameters};
use crate::poly::C64;
use nalgebra::{DMatrix, DVector};

/// Below this `σ_min/σ_max` of `F_x` a point of the branch is a turning point.
pub const TURNING_INVERSE_CONDITION: f64 = 1e-10;

/// One instant of a followed branch.
#[derive(Debug, Clone, PartialEq)]
pub struct BranchPoint {
    /// The instant `t`.
    pub t: f64,
    /// The real solution `x(t)`.
    pub x: Vec<f64>,
    /// Its rates `ẋ(t) = −F_x⁻¹ F_p ṗ(t)`.
    pub rates: Vec<f64>,
    /// `σ_min / σ_max` of `F_x` at `(x(t), p(t))`: zero at a turning point.
    pub inverse_condition: f64,
}

/// How the following of a branch ended.
#[derive(Debug, Clone, PartialEq)]
pub enum BranchEnd {
    /// Every instant reached on the same real branch.
    Completed,
    /// The followed solution stopped being real (or regular) between two instants.
    Ceased {
        /// The last instant reached on the branch.
        last: f64,
        /// The first instant it was not found at.
        next: f64,
        /// Why, in words.
        reason: String,
    },
}

/// A followed real branch.
#[derive(Debug, Clone, PartialEq)]
pub struct RealBranch {
    /// The instants reached, in order.
    pub points: Vec<BranchPoint>,
    /// How it ended.
    pub end: BranchEnd,
    /// The smallest inverse condition met.
    pub least_inverse_condition: f64,
}

/// The values of `F` and its Jacobian (rows: equations; columns: unknowns then parameters) at
/// the real point `(x, p)`, real parts.
fn real_jacobian(
    family: &ParametrizedSystem,
    x: &[f64],
    p: &[f64],
) -> (DVector<f64>, DMatrix<f64>, DMatrix<f64>) {
    let (n, m) = (family.unknowns(), family.parameters());
    let point: Vec<C64> = x.iter().chain(p).map(|v| C64::from(*v)).collect();
    let program = family.program();
    let mut ws = program.workspace::<C64>();
    let mut values = vec![C64::from(0.0); n];
    let mut jac = vec![C64::from(0.0); n * (n + m)];
    program.evaluate_with_jacobian(&point, &mut values, &mut jac, &mut ws);
    let f = DVector::from_fn(n, |i, _| values[i].re);
    let fx = DMatrix::from_fn(n, n, |i, j| jac[i * (n + m) + j].re);
    let fp = DMatrix::from_fn(n, m, |i, j| jac[i * (n + m) + n + j].re);
    (f, fx, fp)
}

/// The real solution of `F(x; p) = 0` near `guess` by Newton's method: `None` unless the update
/// falls below `1e-12` of the size (`1 + max |x_i|`) within 50 steps.
///
/// # Panics
/// If `guess` or `p` has the wrong length.
#[must_use]
pub fn real_newton(family: &ParametrizedSystem, guess: &[f64], p: &[f64]) -> Option<Vec<f64>> {
    assert_eq!(guess.len(), family.unknowns(), "one value per unknown");
    assert_eq!(p.len(), family.parameters(), "one value per parameter");
    let mut x = guess.to_vec();
    for _ in 0..50 {
        let (f, fx, _) = real_jacobian(family, &x, p);
        let dx = fx.lu().solve(&(-f))?;
        for (xi, d) in x.iter_mut().zip(dx.iter()) {
            *xi += d;
        }
        if dx.norm() <= 1e-12 * (1.0 + x.iter().map(|v| v.abs()).fold(0.0, f64::max)) {
            return Some(x);
        }
    }
    None
}

/// The rates `ẋ = −F_x⁻¹ F_p ṗ` of the real solution `x` at the parameters `p` moving at `dp`,
/// with `σ_min/σ_max` of `F_x`; `None` where `F_x` is singular.
///
/// # Panics
/// If a slice has the wrong length.
#[must_use]
pub fn real_rates(
    family: &ParametrizedSystem,
    x: &[f64],
    p: &[f64],
    dp: &[f64],
) -> Option<(Vec<f64>, f64)> {
    assert_eq!(dp.len(), family.parameters(), "one rate per parameter");
    let (_, fx, fp) = real_jacobian(family, x, p);
    let sv = fx.clone().singular_values();
    let inverse_condition = sv.min() / sv.max();
    let rhs = -(fp * DVector::from_column_slice(dp));
    let dx = fx.lu().solve(&rhs)?;
    Some((dx.iter().copied().collect(), inverse_condition))
}

/// The solution `x` at `p0` tracked to `p1`, if it arrives real.
fn step(family: &ParametrizedSystem, x: &[C64], p0: &[f64], p1: &[f64]) -> Option<Vec<C64>> {
    let complex = |p: &[f64]| p.iter().map(|v| C64::from(*v)).collect::<Vec<_>>();
    let y = track_parameters(
        family,
        &complex(p0),
        &complex(p1),
        &[x.to_vec()],
        TrackerSettings::default(),
    )
    .ok()?
    .pop()?
    .ok()?;
    let size = 1.0 + y.iter().map(|c| c.norm()).fold(0.0, f64::max);
    y.iter()
        .all(|c| c.im.abs() <= REAL_TOLERANCE * size)
        .then_some(y)
}

/// Narrows `[t0, t1]` (the solution `x` real at `t0`, lost at `t1`; `t1 < t0` when followed
/// back in time) by bisection to the last instant reached and the first not, 1e-9 apart in `t`
/// (or 40 halvings).
fn bracket(
    family: &ParametrizedSystem,
    params: &impl Fn(f64) -> Vec<f64>,
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
        match step(family, &at, &params(lo), &params(mid)) {
            Some(y) => {
                lo = mid;
                at = y;
            }
            None => hi = mid,
        }
    }
    (lo, hi)
}

/// Follows the real solution `start` of `F(x; params(times[0])) = 0` along `params(t)`, `t`
/// over `times` in order (increasing, or decreasing to follow it back in time), by parameter
/// homotopy between successive instants; `param_rates(t)` is `ṗ(t)`. A step that fails or
/// leaves the reals (imaginary parts above [`REAL_TOLERANCE`] of the size) ends the branch,
/// bracketed by bisection, as does an instant where `F_x` is singular or its inverse condition
/// is below [`TURNING_INVERSE_CONDITION`] ([`BranchEnd::Ceased`]).
///
/// # Panics
/// If `start` or `params(t)` has the wrong length.
#[must_use]
pub fn follow_real(
    family: &ParametrizedSystem,
    start: &[f64],
    params: impl Fn(f64) -> Vec<f64>,
    param_rates: impl Fn(f64) -> Vec<f64>,
    times: &[f64],
) -> RealBranch {
    let mut x: Vec<C64> = start.iter().map(|v| C64::from(*v)).collect();
    let mut points = Vec::with_capacity(times.len());
    let mut least = f64::INFINITY;
    let mut previous: Option<f64> = None;
    let ceased = |points, last, next, reason: String, least| RealBranch {
        points,
        end: BranchEnd::Ceased { last, next, reason },
        least_inverse_condition: least,
    };
    for &t in times {
        let p = params(t);
        if let Some(t0) = previous {
            let Some(moved) = step(family, &x, &params(t0), &p) else {
                let (last, next) = bracket(family, &params, &x, t0, t);
                let reason = "the solution could not be followed as a real one: a turning point, where the Jacobian in the unknowns is singular and two real solutions meet and leave as a complex pair".to_string();
                return ceased(points, last, next, reason, least);
            };
            x = moved;
        }
        let real: Vec<f64> = x.iter().map(|c| c.re).collect();
        let Some((rates, inverse_condition)) = real_rates(family, &real, &p, &param_rates(t))
        else {
            let last = previous.unwrap_or(t);
            return ceased(points, last, t, "a singular Jacobian".into(), least);
        };
        least = least.min(inverse_condition);
        if inverse_condition < TURNING_INVERSE_CONDITION {
            let last = previous.unwrap_or(t);
            let reason = format!("a turning point: inverse condition {inverse_condition:.1e}");
            return ceased(points, last, t, reason, least);
        }
        points.push(BranchPoint {
            t,
            x: real,
            rates,
            inverse_condition,
        });
        previous = Some(t);
    }
    RealBranch {
        points,
        end: BranchEnd::Completed,
        least_inverse_condition: least,
    }
}
