//! Position analysis of paper 003's configurable 4-RRR (§3.2): the inverse problem leg by leg,
//! and the forward problem by both of the paper's polynomial formulations, solved by homotopy
//! continuation ([`kinsyn::homotopy`]) with every solution certified.
//!
//! # Inverse position (§3.2, steps 1–6)
//! Given the platform (its corners `C_i`, from either parametrisation: eq. 5 for
//! [`CentrePose`], eqs. 13–14 for [`CornerPose`]), the elbow `B_i` of leg `i` lies on the circle
//! `|B − A_i| = a` (eq. 8) and on the circle `|C_i − B| = b` (eq. 6): their two intersections
//! give two input angles `q_i` (eq. 7), so a pose has up to `2⁴ = 16` sets of inputs
//! ([`InversePosition::sets`]). A corner farther than `a + b` from its base point, or nearer
//! than `|a − b|`, cannot be reached ([`PositionError::Unreachable`]).
//!
//! # Forward position (§3.2, methods 1 and 2)
//! Given the four inputs `q_i`, the elbows `B_i` follow (eq. 7) and the platform must put each
//! corner `C_i` on the circle `|C_i − B_i| = b` (eq. 6).
//! - **Method 2** ([`corner_system`], [`ForwardMethod::Corner`]): unknowns
//!   `(x4, y4, sin θ, cos θ, sin φ, cos φ)`, corners by eqs. 12–14
//!   (`C_1 = C_4 + c(cos θ, sin θ)`, `C_3 = C_4 + c(cos φ, sin φ)`, `C_2 = C_1 + C_3 − C_4`),
//!   `f_1 … f_4` = eq. 6 for corners 1–4, `f_5, f_6` = eq. 15. Six quadrics: 64 paths. The map
//!   from solutions to corner sets is one-to-one.
//! - **Method 1** ([`centre_system`], [`ForwardMethod::Centre`]): unknowns `w_1 … w_6`,
//!   corners by eq. 5 with `û = (w3, w4)` (eq. 2) and `v̂ = (−w4, w3)` (eq. 4; the `v̂ = w4 î +
//!   w3 ĵ` of §3.2 method 1 step 2 is a misprint: it is not orthogonal to `û`),
//!   `f_1 … f_4` = eq. 6, `f_5` = eq. 3, `f_6` = eq. 10. Eq. 6 with corners `C ± w5 û` is of
//!   degree **4** (the term `w5² w3²`), not quadratic as the paper says: `4⁴·2·2 = 1024`
//!   paths. The map from solutions to corner sets is **two-to-one**: `(û, w5, w6)` and
//!   `(−û, −w5, −w6)` give the same corners, so method 1 has exactly twice method 2's
//!   solutions, real and complex.
//!
//! [`forward_position`] solves either system and returns the real assemblies (distinct corner
//! sets) with θ, φ in eq. 13's sense, each flagged certified when every solution behind it is a
//! Krawczyk-certified real root, and the counts of the solve.
//!
//! # Counts and speed at §5's published inputs
//! Method 2: 12 complex solutions of 64 paths, 2 real (Fig. 10's two assemblies); method 1:
//! 24 and 4, the same two corner sets; `PHCpack` agrees on both (`tests/suite/configurable_position.rs`,
//! `docs/deviations.md`). `cargo bench -p kinsyn-bench --bench configurable` (2 shared cores): method 2 in
//! about 53 ms, method 1 in about 2–6 s (three runs of 1024 paths, 0.7–1 s each); `phc -b`
//! takes about 1.0 s and 1.7 s.

use super::{CentrePose, Configurable, CornerPose};
use kinsyn::certify::Reality;
use kinsyn::geometry::{PolyVector, distance_condition, sin_cos};
use kinsyn::homotopy::{self, HomotopyError, Solution, SolveReport, SolveSettings};
use kinsyn::poly::{C64, Poly, PolyError, System};
use nalgebra::{Vector2, Vector3};
use std::f64::consts::TAU;

/// Why a position problem has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PositionError {
    /// A corner is out of reach of its leg (inverse position).
    #[error(
        "leg {leg} cannot reach its corner: |C{leg} − A{leg}| = {distance} mm is outside [{min}, {max}] mm"
    )]
    Unreachable {
        /// The leg, 1 to 4.
        leg: usize,
        /// The distance from the base point `A_i` to the corner `C_i`.
        distance: f64,
        /// The least reachable distance `|a − b|`.
        min: f64,
        /// The greatest reachable distance `a + b`.
        max: f64,
    },
    /// An input or a coordinate is not a finite number.
    #[error("{0} is not finite")]
    NotFinite(&'static str),
    /// The geometry is not a mechanism (a non-positive length).
    #[error("the lengths a = {a}, b = {b}, c = {c} must be positive")]
    Lengths {
        /// Arm length.
        a: f64,
        /// Forearm length.
        b: f64,
        /// Platform link length.
        c: f64,
    },
    /// The polynomial system could not be built.
    #[error("building the closure equations: {0}")]
    Poly(#[from] PolyError),
    /// The homotopy solver refused the system.
    #[error("solving the closure equations: {0}")]
    Homotopy(#[from] HomotopyError),
}

/// The two solutions of one leg's inverse position: the elbows `B_i` at the intersections of
/// the circles `|B − A_i| = a` and `|C_i − B| = b`, and their input angles `q_i ∈ [0, 2π)`.
/// Solution 0 has the elbow to the left of the ray `A_i → C_i`, solution 1 to its right; at a
/// boundary of the leg's workspace (`|C_i − A_i| = a ± b`) the two coincide.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LegInverse {
    /// The input angles (eq. 7), radians in `[0, 2π)`.
    pub q: [f64; 2],
    /// The elbows `B_i`.
    pub elbows: [Vector2<f64>; 2],
}

/// The inverse position of a platform pose: both solutions of each leg (§3.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InversePosition {
    /// The corners `C_1 … C_4` the legs reach.
    pub corners: [Vector2<f64>; 4],
    /// Leg `i` (0-based).
    pub legs: [LegInverse; 4],
}

impl InversePosition {
    /// The `2⁴ = 16` sets of inputs `(q_1, q_2, q_3, q_4)`, every combination of the legs'
    /// solutions; set `k` takes solution `(k >> (3 − i)) & 1` of leg `i` (0-based).
    #[must_use]
    pub fn sets(&self) -> Vec<[f64; 4]> {
        (0..16usize)
            .map(|k| std::array::from_fn(|i| self.legs[i].q[(k >> (3 - i)) & 1]))
            .collect()
    }

    /// Whether `q` is one of the 16 sets, each angle within `tolerance` radians (modulo 2π).
    #[must_use]
    pub fn contains(&self, q: &[f64; 4], tolerance: f64) -> bool {
        (0..4).all(|i| {
            self.legs[i]
                .q
                .iter()
                .any(|s| angle_distance(*s, q[i]) <= tolerance)
        })
    }
}

/// The distance between two angles on the circle, in `[0, π]`.
#[must_use]
pub fn angle_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

fn check_geometry(m: &Configurable) -> Result<(), PositionError> {
    if ![m.a, m.b, m.c].iter().all(|l| l.is_finite() && *l > 0.0) {
        return Err(PositionError::Lengths {
            a: m.a,
            b: m.b,
            c: m.c,
        });
    }
    if m.base.iter().any(|p| !(p.x.is_finite() && p.y.is_finite())) {
        return Err(PositionError::NotFinite("a base point A_i"));
    }
    Ok(())
}

/// The two elbows of leg `leg` (0-based) that put its forearm's end at `corner`: the
/// intersections of the circles `|B − A_i| = a` (eq. 8) and `|C_i − B| = b` (eq. 6), with
/// their input angles (eq. 7).
///
/// # Errors
/// [`PositionError::Unreachable`] if the circles do not meet (`|C_i − A_i|` outside
/// `[|a − b|, a + b]`, or `C_i = A_i` with `a ≠ b`); [`PositionError::NotFinite`] for a
/// non-finite corner; [`PositionError::Lengths`] for non-positive lengths.
///
/// # Panics
/// If `leg > 3`.
pub fn leg_inverse(
    m: &Configurable,
    leg: usize,
    corner: Vector2<f64>,
) -> Result<LegInverse, PositionError> {
    check_geometry(m)?;
    if !(corner.x.is_finite() && corner.y.is_finite()) {
        return Err(PositionError::NotFinite("a corner C_i"));
    }
    let base = m.base[leg];
    let d_vec = corner - base;
    let d = d_vec.norm();
    let (min, max) = ((m.a - m.b).abs(), m.a + m.b);
    // Rounding slack: a corner on the boundary of the annulus is reachable (one double elbow).
    let slack = 1e-12 * max;
    if d > max + slack || d < min - slack || d == 0.0 {
        return Err(PositionError::Unreachable {
            leg: leg + 1,
            distance: d,
            min,
            max,
        });
    }
    let e = d_vec / d;
    let n = Vector2::new(-e.y, e.x);
    let along = (m.a * m.a - m.b * m.b + d * d) / (2.0 * d);
    let h = (m.a * m.a - along * along).max(0.0).sqrt();
    let elbows = [base + along * e + h * n, base + along * e - h * n];
    let q = elbows.map(|b| {
        let r = b - base;
        r.y.atan2(r.x).rem_euclid(TAU)
    });
    Ok(LegInverse { q, elbows })
}

/// The inverse position of the platform with corners `corners` (§3.2): both solutions of each
/// leg.
///
/// # Errors
/// As [`leg_inverse`], for the first leg that fails.
pub fn inverse_position(
    m: &Configurable,
    corners: &[Vector2<f64>; 4],
) -> Result<InversePosition, PositionError> {
    let legs = [
        leg_inverse(m, 0, corners[0])?,
        leg_inverse(m, 1, corners[1])?,
        leg_inverse(m, 2, corners[2])?,
        leg_inverse(m, 3, corners[3])?,
    ];
    Ok(InversePosition {
        corners: *corners,
        legs,
    })
}

impl Configurable {
    /// The inverse position at a pose given by the corner `C_4` and θ, φ of eq. 13 (§3.2).
    ///
    /// # Errors
    /// As [`inverse_position`]; [`PositionError::NotFinite`] for a non-finite pose.
    pub fn inverse_corner_pose(&self, pose: &CornerPose) -> Result<InversePosition, PositionError> {
        if !(pose.c4.x.is_finite()
            && pose.c4.y.is_finite()
            && pose.theta.is_finite()
            && pose.phi.is_finite())
        {
            return Err(PositionError::NotFinite("the pose"));
        }
        inverse_position(self, &pose.corners(self.c))
    }

    /// The inverse position at a pose given by the centre `C` and θ, φ of eq. 11 (§3.2, steps
    /// 1–6, the paper's own route).
    ///
    /// # Errors
    /// As [`inverse_position`]; [`PositionError::NotFinite`] for a non-finite pose.
    pub fn inverse_centre_pose(&self, pose: &CentrePose) -> Result<InversePosition, PositionError> {
        if !(pose.centre.x.is_finite()
            && pose.centre.y.is_finite()
            && pose.theta.is_finite()
            && pose.phi.is_finite())
        {
            return Err(PositionError::NotFinite("the pose"));
        }
        inverse_position(self, &pose.corners(self.c))
    }

    /// The elbows `B_1 … B_4` at inputs `q` (eq. 7).
    #[must_use]
    pub fn elbows(&self, q: &[f64; 4]) -> [Vector2<f64>; 4] {
        std::array::from_fn(|i| self.elbow(i, q[i]))
    }
}

/// Which of §3.2's formulations of the forward position.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ForwardMethod {
    /// Method 1: the centre `C = (w1, w2)`, `û = (w3, w4)`, half-diagonals `w5, w6` (eqs. 1–6,
    /// 3, 10); [`centre_system`].
    Centre,
    /// Method 2: the corner `C_4 = (x4, y4)` and the sines and cosines of θ, φ (eqs. 6,
    /// 12–15); [`corner_system`].
    Corner,
}

impl ForwardMethod {
    /// The method's number in the paper (1 or 2).
    #[must_use]
    pub fn number(self) -> u8 {
        match self {
            ForwardMethod::Centre => 1,
            ForwardMethod::Corner => 2,
        }
    }
}

fn constant_point(nvars: usize, p: Vector2<f64>) -> PolyVector {
    kinsyn::geometry::constant_vector(nvars, &Vector3::new(p.x, p.y, 0.0))
}

fn planar(nvars: usize, x: Poly, y: Poly) -> PolyVector {
    [x, y, Poly::zero(nvars)]
}

fn add(p: &PolyVector, q: &PolyVector) -> PolyVector {
    [&p[0] + &q[0], &p[1] + &q[1], &p[2] + &q[2]]
}

fn sub(p: &PolyVector, q: &PolyVector) -> PolyVector {
    [&p[0] - &q[0], &p[1] - &q[1], &p[2] - &q[2]]
}

fn check_inputs(m: &Configurable, q: &[f64; 4]) -> Result<(), PositionError> {
    check_geometry(m)?;
    if q.iter().any(|x| !x.is_finite()) {
        return Err(PositionError::NotFinite("an input angle q_i"));
    }
    Ok(())
}

/// The names of [`corner_system`]'s unknowns, in order.
pub const CORNER_VARIABLES: [&str; 6] = ["x4", "y4", "s_theta", "c_theta", "s_phi", "c_phi"];

/// The names of [`centre_system`]'s unknowns, in order.
pub const CENTRE_VARIABLES: [&str; 6] = ["w1", "w2", "w3", "w4", "w5", "w6"];

/// Method 2's closure equations at inputs `q` (§3.2 method 2, §5 steps 1–4): in the unknowns
/// `(x4, y4, sin θ, cos θ, sin φ, cos φ)`, `f_i = |C_i − B_i|² − b²` (eq. 6) for `i = 1 … 4`
/// with `B_i` from eq. 7 and `C_i` from eqs. 12–14, then `f_5 = sin²θ + cos²θ − 1`,
/// `f_6 = sin²φ + cos²φ − 1` (eq. 15). Every equation is quadratic.
///
/// # Errors
/// [`PositionError::NotFinite`] for a non-finite input, [`PositionError::Lengths`] for
/// non-positive lengths.
pub fn corner_system(m: &Configurable, q: &[f64; 4]) -> Result<System, PositionError> {
    check_inputs(m, q)?;
    let n = 6;
    let v = |i| Poly::variable(n, i);
    let c4 = planar(n, v(0), v(1));
    let c1 = add(&c4, &planar(n, v(3) * m.c, v(2) * m.c));
    let c3 = add(&c4, &planar(n, v(5) * m.c, v(4) * m.c));
    let c2 = sub(&add(&c1, &c3), &c4);
    let corners = [c1, c2, c3, c4];
    let elbows = m.elbows(q);
    let mut equations: Vec<Poly> = (0..4)
        .map(|i| distance_condition(&corners[i], &constant_point(n, elbows[i]), m.b))
        .collect();
    equations.push(sin_cos(&v(2), &v(3)));
    equations.push(sin_cos(&v(4), &v(5)));
    Ok(System::new(
        CORNER_VARIABLES.iter().map(|s| (*s).to_string()).collect(),
        equations,
    )?)
}

/// Method 1's closure equations at inputs `q` (§3.2 method 1): in the unknowns `w_1 … w_6`,
/// `f_i = |C_i − B_i|² − b²` (eq. 6) for `i = 1 … 4` with `B_i` from eq. 7 and the corners of
/// eq. 5, `C_{1,3} = C ± w5 û`, `C_{2,4} = C ± w6 v̂`, `C = (w1, w2)` (eq. 1), `û = (w3, w4)`
/// (eq. 2), `v̂ = (−w4, w3)` (eq. 4); then `f_5 = w3² + w4² − 1` (eq. 3) and
/// `f_6 = w5² + w6² − c²` (eq. 10). `f_1 … f_4` are quartic (not quadratic as §3.2 says).
///
/// # Errors
/// As [`corner_system`].
pub fn centre_system(m: &Configurable, q: &[f64; 4]) -> Result<System, PositionError> {
    check_inputs(m, q)?;
    let n = 6;
    let v = |i| Poly::variable(n, i);
    let centre = planar(n, v(0), v(1));
    let u = planar(n, v(2), v(3));
    let vhat = planar(n, -v(3), v(2));
    let scale = |p: &PolyVector, s: &Poly| -> PolyVector { [&p[0] * s, &p[1] * s, &p[2] * s] };
    let (w5u, w6v) = (scale(&u, &v(4)), scale(&vhat, &v(5)));
    let corners = [
        add(&centre, &w5u),
        add(&centre, &w6v),
        sub(&centre, &w5u),
        sub(&centre, &w6v),
    ];
    let elbows = m.elbows(q);
    let mut equations: Vec<Poly> = (0..4)
        .map(|i| distance_condition(&corners[i], &constant_point(n, elbows[i]), m.b))
        .collect();
    equations.push(sin_cos(&v(3), &v(2)));
    equations.push(&v(4) * &v(4) + &v(5) * &v(5) - Poly::real(n, m.c * m.c));
    Ok(System::new(
        CENTRE_VARIABLES.iter().map(|s| (*s).to_string()).collect(),
        equations,
    )?)
}

/// The corners `C_1 … C_4` of a (complex) solution of the method's system: eqs. 12–14 for
/// method 2, eq. 5 for method 1.
///
/// # Panics
/// If `x` has fewer than 6 coordinates.
#[must_use]
pub fn solution_corners(m: &Configurable, method: ForwardMethod, x: &[C64]) -> [[C64; 2]; 4] {
    match method {
        ForwardMethod::Corner => {
            let c4 = [x[0], x[1]];
            let c1 = [c4[0] + x[3] * m.c, c4[1] + x[2] * m.c];
            let c3 = [c4[0] + x[5] * m.c, c4[1] + x[4] * m.c];
            let c2 = [c1[0] + c3[0] - c4[0], c1[1] + c3[1] - c4[1]];
            [c1, c2, c3, c4]
        }
        ForwardMethod::Centre => {
            let (cx, cy, w3, w4, w5, w6) = (x[0], x[1], x[2], x[3], x[4], x[5]);
            [
                [cx + w5 * w3, cy + w5 * w4],
                [cx - w6 * w4, cy + w6 * w3],
                [cx - w5 * w3, cy - w5 * w4],
                [cx + w6 * w4, cy - w6 * w3],
            ]
        }
    }
}

/// One real assembly of the forward position: a set of corners of the platform.
#[derive(Debug, Clone, PartialEq)]
pub struct Assembly {
    /// The corners `C_1 … C_4`.
    pub corners: [Vector2<f64>; 4],
    /// The pose in eq. 13's sense: `C_4`, θ the direction of `C_4 → C_1`, φ that of
    /// `C_4 → C_3`, both in `[0, 2π)`.
    pub pose: CornerPose,
    /// The centre `C = (C_1 + C_3)/2` (eq. 14).
    pub centre: Vector2<f64>,
    /// The elbows `B_1 … B_4` (eq. 7, from the inputs).
    pub elbows: [Vector2<f64>; 4],
    /// How many solutions of the method's system give these corners (1 for method 2, 2 for
    /// method 1: `(û, w5, w6)` and `(−û, −w5, −w6)`).
    pub solutions: usize,
    /// Whether every one of those solutions is a Krawczyk-certified, distinct, real root.
    pub certified: bool,
    /// The largest loop-closure error `| |C_i − B_i| − b |`, mm.
    pub closure_error: f64,
}

/// The forward position at one set of inputs: the real assemblies and the counts of the solve.
#[derive(Debug, Clone, PartialEq)]
pub struct ForwardPosition {
    /// The formulation solved.
    pub method: ForwardMethod,
    /// The inputs.
    pub q: [f64; 4],
    /// The real assemblies, distinct corner sets, sorted by θ then φ.
    pub assemblies: Vec<Assembly>,
    /// The distinct non-singular complex solutions of the system found by all runs.
    pub solutions: Vec<Solution>,
    /// The number of distinct non-singular complex solutions ([`Self::solutions`]).
    pub complex: usize,
    /// The number of those that are real.
    pub real: usize,
    /// The number of distinct complex corner sets among the non-singular solutions.
    pub complex_assemblies: usize,
    /// Whether the last run had no failed path and (method 1) every solution's mirror
    /// `(w1, w2, −w3, −w4, −w5, −w6)` was found too.
    pub complete: bool,
    /// The solver's report of each run (seeds `settings.seed + k`): paths, endpoints at
    /// infinity, failures, certificates, time.
    pub reports: Vec<SolveReport>,
}

/// The most runs [`forward_position_with`] makes before it gives up on completeness.
pub const MAX_RUNS: usize = 4;

/// The solution of method 1 that gives the same corners as `x`: `(û, w5, w6) → (−û, −w5, −w6)`.
#[must_use]
pub fn centre_mirror(x: &[C64]) -> Vec<C64> {
    x.iter()
        .enumerate()
        .map(|(i, v)| if i < 2 { *v } else { -*v })
        .collect()
}

fn close(a: &[C64], b: &[C64]) -> bool {
    a.iter()
        .zip(b)
        .all(|(x, y)| (x - y).norm() <= 1e-6 * (1.0 + x.norm()))
}

/// Tolerance for two corner sets being one assembly, relative to the platform's size.
const SAME_ASSEMBLY: f64 = 1e-7;

fn same_corners(a: &[[C64; 2]; 4], b: &[[C64; 2]; 4], scale: f64) -> bool {
    a.iter()
        .zip(b)
        .all(|(p, q)| (p[0] - q[0]).norm() + (p[1] - q[1]).norm() <= SAME_ASSEMBLY * scale)
}

/// The forward position by `method` at inputs `q` with the default solver settings (seed 1,
/// total-degree start, certification on): see [`forward_position_with`].
///
/// # Errors
/// As [`forward_position_with`].
pub fn forward_position(
    m: &Configurable,
    q: [f64; 4],
    method: ForwardMethod,
) -> Result<ForwardPosition, PositionError> {
    forward_position_with(m, q, method, &SolveSettings::default())
}

/// The forward position at inputs `q` (§3.2): every isolated complex solution of the method's
/// closure equations by homotopy continuation, grouped into corner sets; the real ones are the
/// assemblies of the manipulator. Solves with `settings`, and again with seeds
/// `settings.seed + 1, …` (at most [`MAX_RUNS`] runs in all) while a run loses paths or, for
/// method 1, a solution's mirror ([`centre_mirror`]) is missing; the union is kept.
///
/// # Errors
/// [`PositionError::NotFinite`] / [`PositionError::Lengths`] for bad input,
/// [`PositionError::Homotopy`] if the solver refuses the system.
pub fn forward_position_with(
    m: &Configurable,
    q: [f64; 4],
    method: ForwardMethod,
    settings: &SolveSettings,
) -> Result<ForwardPosition, PositionError> {
    let system = match method {
        ForwardMethod::Corner => corner_system(m, &q)?,
        ForwardMethod::Centre => centre_system(m, &q)?,
    };
    // Paths can fail on these systems (method 1 has 1024 paths, ~1000 of them diverging to a
    // singular set at infinity): runs with further seeds until the last run loses no path and
    // the solutions are closed under method 1's mirror symmetry.
    let mut reports: Vec<SolveReport> = Vec::new();
    let mut found: Vec<Solution> = Vec::new();
    let mut complete = false;
    for run in 0..MAX_RUNS {
        let report = homotopy::solve(
            &system,
            &SolveSettings {
                seed: settings.seed.wrapping_add(run as u64),
                ..settings.clone()
            },
        )?;
        for s in report.solutions.iter().filter(|s| s.regular) {
            if !found.iter().any(|f| close(&f.x, &s.x)) {
                found.push(s.clone());
            }
        }
        let failed = report.failed();
        reports.push(report);
        let closed = method == ForwardMethod::Corner
            || found
                .iter()
                .all(|s| found.iter().any(|t| close(&centre_mirror(&s.x), &t.x)));
        if closed && failed == 0 {
            complete = true;
            break;
        }
    }
    let scale = m.a + m.b + m.c + m.base.iter().map(Vector2::norm).fold(0.0, f64::max);
    let elbows = m.elbows(&q);
    let regular: Vec<&Solution> = found.iter().collect();
    // Distinct complex corner sets, and which solutions give each.
    let mut groups: Vec<([[C64; 2]; 4], Vec<usize>)> = Vec::new();
    for (k, s) in regular.iter().enumerate() {
        let corners = solution_corners(m, method, &s.x);
        match groups
            .iter_mut()
            .find(|(c, _)| same_corners(c, &corners, scale))
        {
            Some((_, members)) => members.push(k),
            None => groups.push((corners, vec![k])),
        }
    }
    let mut assemblies: Vec<Assembly> = groups
        .iter()
        .filter(|(_, members)| members.iter().all(|&k| regular[k].real))
        .map(|(corners, members)| {
            let corners: [Vector2<f64>; 4] =
                std::array::from_fn(|i| Vector2::new(corners[i][0].re, corners[i][1].re));
            let direction = |v: Vector2<f64>| v.y.atan2(v.x).rem_euclid(TAU);
            let pose = CornerPose {
                c4: corners[3],
                theta: direction(corners[0] - corners[3]),
                phi: direction(corners[2] - corners[3]),
            };
            let certified = members.iter().all(|&k| {
                regular[k].is_certified()
                    && regular[k]
                        .certificate
                        .as_ref()
                        .is_some_and(|c| c.real == Reality::CertifiedReal)
            });
            let closure_error = (0..4)
                .map(|i| ((corners[i] - elbows[i]).norm() - m.b).abs())
                .fold(0.0, f64::max);
            Assembly {
                corners,
                pose,
                centre: (corners[0] + corners[2]) / 2.0,
                elbows,
                solutions: members.len(),
                certified,
                closure_error,
            }
        })
        .collect();
    assemblies.sort_by(|a, b| {
        a.pose
            .theta
            .total_cmp(&b.pose.theta)
            .then(a.pose.phi.total_cmp(&b.pose.phi))
    });
    Ok(ForwardPosition {
        method,
        q,
        complex: found.len(),
        real: found.iter().filter(|s| s.real).count(),
        complex_assemblies: groups.len(),
        assemblies,
        solutions: found,
        complete,
        reports,
    })
}
