//! Homotopy continuation: every isolated complex solution of a square polynomial system, with
//! each path's endpoint classified (finite or at infinity, regular or singular with its
//! multiplicity, real or not) — the numerical algebraic geometry of Sommese & Wampler, *The
//! Numerical Solution of Systems of Polynomials Arising in Engineering and Science* (2005), and
//! of the solvers Bertini, `PHCpack` and `HomotopyContinuation.jl`, written anew for kinsyn.
//!
//! [`solve`] deforms a start system with known solutions into the target along the γ-trick
//! homotopy in projective coordinates ([`StartSystem`]: total degree or multi-homogeneous),
//! tracks every path in parallel (rayon; results in path order whatever the thread count) with
//! an adaptive Runge–Kutta predictor and Newton corrector, and finishes each with the Cauchy
//! endgame, which converges to singular endpoints too and gives their winding numbers.
//! Endpoints that coincide although regular betray a path jump: those paths are tracked again
//! with stricter steps. Every random choice (γ, patches, start forms) comes from one seeded
//! generator: the same seed gives the same paths.
//!
//! An over-determined system (more equations than unknowns) is solved by
//! [`solve_overdetermined`]: randomised to a square one ([`square_randomisation`]), solved, and
//! every endpoint checked against the original equations.
//!
//! ```
//! use kinsyn_nag::homotopy::{solve, SolveSettings};
//! use kinsyn_nag::poly::{Poly, System};
//! // The unit circle met by the line x = y: two real points (±1/√2, ±1/√2).
//! let x = Poly::variable(2, 0);
//! let y = Poly::variable(2, 1);
//! let circle = &x * &x + &y * &y - Poly::real(2, 1.0);
//! let system = System::new(vec!["x".into(), "y".into()], vec![circle, &x - &y]).unwrap();
//! let report = solve(&system, &SolveSettings::default()).unwrap();
//! assert_eq!(report.nonsingular(), 2);
//! assert_eq!(report.real(), 2);
//! assert_eq!(report.at_infinity(), 0, "Bézout's 2 paths, both finite");
//! ```

// Public for the tests in tests/suite/; not part of the API.
#[doc(hidden)]
pub mod deflation;
pub mod nearby;
mod overdetermined;
mod parameter;
mod polyhedral;
mod real_branch;
mod regeneration;
mod shard;
mod start;
mod tracker;
mod witness;

pub use overdetermined::{
    OverdeterminedReport, satisfies_all, satisfying, solve_overdetermined, square_randomisation,
};
pub use parameter::{
    MonodromyReport, MonodromySettings, ParameterError, ParametrizedSystem, monodromy_solve,
    track_parameters,
};

pub use real_branch::{
    BranchEnd, BranchPoint, RealBranch, TURNING_INVERSE_CONDITION, follow_real, real_newton,
    real_rates,
};
pub use regeneration::{
    RegenerationProgress, regenerate, regenerate_with_progress, regeneration_paths,
};
pub use shard::{Shard, ShardEnds, merge_shards, solve_shard};
pub use start::{StartSystem, fewest_paths_start};
pub use tracker::{PathFailure, TrackerSettings};
pub use witness::{
    Component, DEFAULT_DECOMPOSE_PATHS, DecomposeError, DecomposeSettings, Decomposition,
    MAX_DECOMPOSE_EQUATIONS, MAX_DECOMPOSE_PATHS, MAX_DECOMPOSE_UNKNOWNS, check_system, decompose,
    decompose_paths, decompose_paths_by_dimension, points_on_slice,
};

use crate::certify::{Certificate, Reality, certify_roots};
pub use crate::poly::C64;
use crate::poly::System;
use crate::polyhedral::MixedSubdivision;
use nalgebra::{DMatrix, DVector};
use nearby::NearPoints;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use start::ProjectiveHomotopy;
use std::fmt::Write as _;
use tracker::Tracker;

/// The most paths [`solve`] tracks, whatever [`SolveSettings::max_paths`] says: every start
/// solution and every path's end are held together in memory (2²⁰ paths of a system in 20
/// unknowns take about a gigabyte), and beyond it the system is refused rather than left to
/// run for hours (a tighter start system or a parameter homotopy is the way).
pub const MAX_PATHS: u64 = 1 << 20;

/// The default of [`SolveSettings::max_paths`]: 2¹⁶ = 65 536 paths of up to
/// [`PATH_WEIGHT_UNKNOWNS`] unknowns ([`path_weight`]), about three minutes on two cores when
/// most paths diverge (docs/limits.md, "Measured cost").
pub const DEFAULT_MAX_PATHS: u64 = 1 << 16;

/// Up to this many unknowns a path counts once against a path limit; beyond, its cost grows as
/// the cube of the unknowns (each step factors the Jacobian), and it counts [`path_weight`]
/// times.
pub const PATH_WEIGHT_UNKNOWNS: usize = 12;

/// How many times a path in `unknowns` unknowns counts against a path limit
/// ([`SolveSettings::max_paths`], [`DecomposeSettings::max_paths`]): 1 up to
/// [`PATH_WEIGHT_UNKNOWNS`], then `⌈(n/12)³⌉` — 19 for 32 unknowns, 579 for 100. Measured
/// (docs/limits.md): a path costs about 1–5 ms of CPU up to 16 unknowns, 20–35 ms at 32–64 and
/// 0.6 s at 100.
#[must_use]
pub fn path_weight(unknowns: usize) -> u64 {
    let n = unknowns as u64;
    let reference = PATH_WEIGHT_UNKNOWNS as u64;
    (n * n * n)
        .div_ceil(reference * reference * reference)
        .max(1)
}

/// The most unknowns (and equations) [`solve`] takes: each step of a path factors the
/// `n × n` Jacobian, and the certificates take interval matrices of that size
/// (docs/limits.md, "Measured cost").
pub const MAX_UNKNOWNS: usize = 100;

/// An endpoint is at infinity when a homogenising coordinate is below this fraction of its
/// group's coordinates.
pub const INFINITY_TOLERANCE: f64 = 1e-8;

/// An endpoint is singular when its inverse condition ([`PathEnd::inverse_condition`]) is
/// below this (or its winding number exceeds 1).
///
/// The inverse condition is `σ_min / σ_max` of the system's Jacobian at the endpoint with each
/// equation's row divided by the size of its terms there (the gradient of `Σ |c_α| z^α` at
/// `|z|`, [`crate::poly::Poly::magnitudes`], coordinates below 1e-3 of the largest counted as
/// 1e-3 of it), in projective coordinates restricted to the
/// point's orthogonal complement (the patch row of each variable group is the unit normal
/// `z̄ / |z|` of the group's coordinates scaled to largest modulus 1). It therefore does not
/// depend on the scale of an equation, on the degree of a homogenised equation, on the
/// random patch, or on where the endpoint lies relative to the patch: `x^1024 − 1` has
/// inverse condition about 1 at each root of unity, and a double root has 0 up to the
/// endpoint's accuracy.
pub const SINGULAR_TOLERANCE: f64 = 1e-9;

/// A solution is real when each imaginary part is below this fraction of `1 + |x|`.
pub const REAL_TOLERANCE: f64 = 1e-8;

/// Why a system cannot be solved.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum HomotopyError {
    /// Not as many equations as variables.
    #[error(
        "the system has {equations} equations in {variables} variables: homotopy continuation here solves square systems"
    )]
    NotSquare {
        /// The number of equations.
        equations: usize,
        /// The number of variables.
        variables: usize,
    },
    /// An equation is a non-zero constant (no solution) or zero (not isolated).
    #[error("equation {0} is constant: the system has no isolated solutions")]
    ConstantEquation(usize),
    /// More unknowns than [`MAX_UNKNOWNS`].
    #[error("{unknowns} unknowns exceed the limit of {MAX_UNKNOWNS}")]
    TooManyUnknowns {
        /// The system's unknowns.
        unknowns: usize,
    },
    /// The system's program would exceed [`crate::poly::MAX_PROGRAM_SIZE`]
    /// ([`System::program_size`]).
    #[error(
        "the system's program of values and Jacobian would hold up to {size} factors, beyond the limit of {}",
        crate::poly::MAX_PROGRAM_SIZE
    )]
    ProgramSize {
        /// The bound on its size.
        size: u128,
    },
    /// The variable groups are too many to count the multi-homogeneous start solutions
    /// ([`crate::poly::multihomogeneous::MAX_GROUP_STATES`]).
    #[error(
        "{groups} variable groups are too many to count the multi-homogeneous start solutions (at most {} states)",
        crate::poly::multihomogeneous::MAX_GROUP_STATES
    )]
    TooManyGroups {
        /// The system's variable groups.
        groups: usize,
    },
    /// The set structure's choices of supports are too many to walk
    /// ([`crate::poly::linear_product::MAX_NODES`]).
    #[error(
        "the linear-product start system's set structure has too many choices to count (more than {} steps)",
        crate::poly::linear_product::MAX_NODES
    )]
    SetStructure,
    /// The mixed cells of the polyhedral start system could not be enumerated.
    #[error("the polyhedral start system: {0}")]
    MixedCells(#[from] crate::polyhedral::MixedCellError),
    /// More paths than the limit ([`SolveSettings::max_paths`], at most [`MAX_PATHS`]), each
    /// counting [`path_weight`] times.
    #[error("{paths} paths, each counting {weight} times, exceed the limit of {limit}")]
    TooManyPaths {
        /// The start system's paths (saturating at `u128::MAX`).
        paths: u128,
        /// How many times each counts ([`path_weight`] of the unknowns).
        weight: u64,
        /// The limit.
        limit: u64,
    },
    /// Shards that do not make one solve ([`merge_shards`]): a shard missing or given twice,
    /// shards of another count, start system or seed, a path missing or repeated.
    #[error("the shards do not make one solve: {0}")]
    Shards(String),
}

/// How to solve.
#[derive(Debug, Clone, PartialEq)]
pub struct SolveSettings {
    /// The seed of every random choice (γ, patches, start forms).
    pub seed: u64,
    /// The start system.
    pub start: StartSystem,
    /// Step control and endgame.
    pub tracker: TrackerSettings,
    /// Whether to certify the regular solutions (Krawczyk, [`crate::certify`]).
    pub certify: bool,
    /// How many times paths with suspect endpoints (coinciding regular endpoints: a path jump;
    /// failures) are tracked again, each round with stricter steps than the last
    /// ([`TrackerSettings::stricter`]).
    pub retrack_rounds: usize,
    /// The most paths to track, each counting [`path_weight`] times: a start system with more
    /// is refused before any is tracked ([`DEFAULT_MAX_PATHS`]; at most [`MAX_PATHS`] is
    /// honoured).
    pub max_paths: u64,
}

impl Default for SolveSettings {
    fn default() -> Self {
        Self {
            seed: 1,
            start: StartSystem::TotalDegree,
            tracker: TrackerSettings::default(),
            certify: true,
            retrack_rounds: 2,
            max_paths: DEFAULT_MAX_PATHS,
        }
    }
}

/// What one path ended at.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum EndpointKind {
    /// A finite, non-singular solution (winding number 1, Jacobian of full rank).
    Regular,
    /// A finite singular solution (or one reached with winding number above 1).
    Singular,
    /// A point at infinity of the projective closure: no affine solution.
    AtInfinity,
    /// The path was given up (see [`PathEnd::failure`]).
    Failed,
}

/// The end of one path.
#[derive(Debug, Clone, PartialEq)]
pub struct PathEnd {
    /// The path's number (the index of its start solution).
    pub path: usize,
    /// What it ended at.
    pub kind: EndpointKind,
    /// The affine endpoint (finite endpoints only).
    pub x: Option<Vec<C64>>,
    /// The winding number of the endgame (the cycle number of the path's Puiseux series).
    pub winding: usize,
    /// The endpoint's inverse condition: `σ_min / σ_max` of the system's Jacobian there, rows
    /// scaled by the size of each equation's terms, in projective coordinates restricted to
    /// the point's orthogonal complement ([`SINGULAR_TOLERANCE`]); 0 for paths at infinity
    /// and failed ones.
    pub inverse_condition: f64,
    /// Steps taken, accepted or not.
    pub steps: usize,
    /// Why it failed, for failed paths.
    pub failure: Option<PathFailure>,
    /// Whether this end comes from tracking the path again.
    pub retracked: bool,
}

/// A distinct finite solution, and the paths that reached it.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    /// The coordinates, in the system's variable order.
    pub x: Vec<C64>,
    /// Whether it is non-singular.
    pub regular: bool,
    /// The number of paths that ended here: the multiplicity of a singular isolated solution
    /// (1 for a regular one).
    pub multiplicity: usize,
    /// Whether every coordinate is real (to [`REAL_TOLERANCE`], for real systems).
    pub real: bool,
    /// The largest `|f_i(x)|`.
    pub residual: f64,
    /// The paths that ended here.
    pub paths: Vec<usize>,
    /// The Krawczyk certificate of a regular solution ([`crate::certify`]): a proof that a
    /// unique root lies in a small box around `x`, distinct from the other solutions' boxes, and
    /// real or non-real where that is proven. `None` for singular solutions (no certificate
    /// exists for them) and when certification was not asked for.
    pub certificate: Option<Certificate>,
}

impl Solution {
    /// Whether the solution is certified: a unique regular root proven in its box, and that
    /// box disjoint from every other solution's.
    #[must_use]
    pub fn is_certified(&self) -> bool {
        self.certificate
            .as_ref()
            .is_some_and(|c| c.is_certified() && c.distinct)
    }
}

/// All that [`solve`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct SolveReport {
    /// The start system used.
    pub start: StartSystem,
    /// The seed.
    pub seed: u64,
    /// One end per path, in path order.
    pub ends: Vec<PathEnd>,
    /// The distinct finite solutions, regular ones first.
    pub solutions: Vec<Solution>,
    /// Paths tracked again.
    pub retracked: usize,
    /// Wall time in seconds.
    pub seconds: f64,
}

impl SolveReport {
    /// The number of paths.
    #[must_use]
    pub fn paths(&self) -> usize {
        self.ends.len()
    }

    /// The number of distinct non-singular solutions.
    #[must_use]
    pub fn nonsingular(&self) -> usize {
        self.solutions.iter().filter(|s| s.regular).count()
    }

    /// The number of distinct real non-singular solutions.
    #[must_use]
    pub fn real(&self) -> usize {
        self.solutions
            .iter()
            .filter(|s| s.regular && s.real)
            .count()
    }

    /// The number of certified solutions ([`Solution::is_certified`]).
    #[must_use]
    pub fn certified(&self) -> usize {
        self.solutions.iter().filter(|s| s.is_certified()).count()
    }

    /// The number of solutions certified real.
    #[must_use]
    pub fn certified_real(&self) -> usize {
        self.solutions
            .iter()
            .filter(|s| {
                s.is_certified()
                    && s.certificate
                        .as_ref()
                        .is_some_and(|c| c.real == Reality::CertifiedReal)
            })
            .count()
    }

    /// The number of distinct singular solutions.
    #[must_use]
    pub fn singular(&self) -> usize {
        self.solutions.iter().filter(|s| !s.regular).count()
    }

    /// The number of paths that ended at infinity.
    #[must_use]
    pub fn at_infinity(&self) -> usize {
        self.ends
            .iter()
            .filter(|e| e.kind == EndpointKind::AtInfinity)
            .count()
    }

    /// The number of failed paths.
    #[must_use]
    pub fn failed(&self) -> usize {
        self.ends
            .iter()
            .filter(|e| e.kind == EndpointKind::Failed)
            .count()
    }

    /// Whether every path ended (none failed, after the re-tracking rounds): only then can the
    /// solutions be complete. A failed path may have been the only one to a root.
    #[must_use]
    pub fn complete(&self) -> bool {
        self.failed() == 0
    }

    /// One line: "12 non-singular solutions (2 real), 52 at infinity, 64 paths".
    #[must_use]
    pub fn summary(&self) -> String {
        let mut s = format!(
            "{} non-singular solutions ({} real)",
            self.nonsingular(),
            self.real()
        );
        if self.singular() > 0 {
            let _ = write!(s, ", {} singular", self.singular());
        }
        let _ = write!(s, ", {} at infinity", self.at_infinity());
        if self.failed() > 0 {
            let _ = write!(s, ", {} failed", self.failed());
        }
        s + &format!(", {} paths", self.paths())
    }
}

/// All isolated solutions of the square `system` (module documentation).
///
/// # Errors
/// [`HomotopyError`] if the system is not square, has more than [`MAX_UNKNOWNS`] unknowns or a
/// constant equation, or needs more paths than [`SolveSettings::max_paths`] ([`check_solvable`]).
pub fn solve(system: &System, settings: &SolveSettings) -> Result<SolveReport, HomotopyError> {
    solve_with_progress(system, settings, &|| {})
}

/// [`solve`], calling `progress` once per path tracked (from any thread).
///
/// # Errors
/// As [`solve`].
pub fn solve_with_progress(
    system: &System,
    settings: &SolveSettings,
    progress: &(dyn Fn() + Sync),
) -> Result<SolveReport, HomotopyError> {
    let clock = std::time::Instant::now();
    let (start, _) = check(system, settings, 1)?;
    // The time of the mixed cells is theirs whether found now or for an earlier count.
    let checked = clock.elapsed().as_secs_f64();
    let settings = &SolveSettings {
        start,
        ..settings.clone()
    };
    let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
    let (homotopy, starts, cells_seconds) = start_paths(system, settings, &mut rng)?;
    let ends = first_ends(&homotopy, &starts, settings, |_| true, progress);
    Ok(finish_solve(
        system,
        settings,
        (&homotopy, &starts),
        ends,
        clock.elapsed().as_secs_f64() - checked + cells_seconds,
    ))
}

/// The first tracking of the paths `k` for which `keep(k)` holds, in path order (a shard's,
/// or all of them).
fn first_ends(
    homotopy: &ProjectiveHomotopy,
    starts: &StartPoints,
    settings: &SolveSettings,
    keep: impl Fn(usize) -> bool + Sync,
    progress: &(dyn Fn() + Sync),
) -> Vec<PathEnd> {
    (0..starts.len())
        .into_par_iter()
        .filter(|k| keep(*k))
        .map(|k| {
            let end = match starts.point(homotopy, k) {
                Ok(z) => track_path(homotopy, settings.tracker, k, z),
                Err(failure) => failed_start(k, failure),
            };
            progress();
            end
        })
        .collect()
}

/// The rest of a solve once every path has been tracked once (`ends`, one per path in path
/// order): the suspect paths tracked again, round by round stricter; the distinct solutions;
/// their certificates. `seconds` is the time of the run so far.
fn finish_solve(
    system: &System,
    settings: &SolveSettings,
    (homotopy, starts): (&ProjectiveHomotopy, &StartPoints),
    mut ends: Vec<PathEnd>,
    seconds: f64,
) -> SolveReport {
    let clock = std::time::Instant::now();
    let mut retracked = 0;
    let mut stricter = settings.tracker;
    for _ in 0..settings.retrack_rounds {
        // Each round stricter than the last: a path that failed or jumped again gets smaller
        // steps still.
        stricter = stricter.stricter();
        // A path without a start point (its polyhedral first stage failed) has nothing to
        // track again.
        let suspects: Vec<(usize, DVector<C64>)> = suspect_paths(&ends)
            .into_par_iter()
            .filter(|k| ends[*k].steps > 0 || ends[*k].kind != EndpointKind::Failed)
            .filter_map(|k| starts.point(homotopy, k).ok().map(|z| (k, z)))
            .collect();
        if suspects.is_empty() {
            break;
        }
        retracked += suspects.len();
        let again: Vec<PathEnd> = suspects
            .into_par_iter()
            .map(|(k, z)| PathEnd {
                retracked: true,
                ..track_path(homotopy, stricter, k, z)
            })
            .collect();
        for e in again {
            let k = e.path;
            ends[k] = e;
        }
    }
    let mut solutions = distinct_solutions(system, &ends);
    if settings.certify {
        certify_solutions(system, &mut solutions);
    }
    SolveReport {
        start: settings.start,
        seed: settings.seed,
        ends,
        solutions,
        retracked,
        seconds: seconds + clock.elapsed().as_secs_f64(),
    }
}

/// The start points of a solve's paths, one per path in path order: listed (the total-degree
/// and multi-homogeneous starts), or the polyhedral start's, each found when its path is
/// tracked (its cell's homotopy followed to a root of `G`), so that a shard follows its own
/// paths only.
pub(crate) enum StartPoints {
    /// Every start point.
    Listed(Vec<DVector<C64>>),
    /// The polyhedral first stage.
    Polyhedral(Box<polyhedral::PolyhedralStart>),
}

impl StartPoints {
    /// The number of paths.
    pub(crate) fn len(&self) -> usize {
        match self {
            Self::Listed(points) => points.len(),
            Self::Polyhedral(first) => first.paths(),
        }
    }

    /// The start point of path `k` on `homotopy`'s patches, or why it has none (a polyhedral
    /// first-stage path that failed).
    fn point(&self, homotopy: &ProjectiveHomotopy, k: usize) -> Result<DVector<C64>, PathFailure> {
        match self {
            Self::Listed(points) => Ok(points[k].clone()),
            Self::Polyhedral(first) => first.root(k).map(|x| homotopy.start_point(&x)),
        }
    }
}

/// The homotopy of `settings.start` for `system` and its start points, and the seconds spent
/// on the mixed cells.
fn start_paths(
    system: &System,
    settings: &SolveSettings,
    rng: &mut ChaCha8Rng,
) -> Result<(ProjectiveHomotopy, StartPoints, f64), HomotopyError> {
    if settings.start != StartSystem::Polyhedral {
        let homotopy = ProjectiveHomotopy::new(system, settings.start, rng);
        let starts = StartPoints::Listed(homotopy.start_solutions());
        return Ok((homotopy, starts, 0.0));
    }
    let subdivision = polyhedral_subdivision(
        system,
        settings.seed,
        crate::polyhedral::DEFAULT_MAX_LINEAR_PROGRAMS,
    )?;
    let first = polyhedral::polyhedral_start(system, &subdivision, rng, settings.tracker);
    let homotopy = ProjectiveHomotopy::with_start_system(system, &first.system, rng);
    Ok((
        homotopy,
        StartPoints::Polyhedral(Box::new(first)),
        subdivision.seconds,
    ))
}

/// The end of a path whose start was not found.
fn failed_start(k: usize, failure: PathFailure) -> PathEnd {
    PathEnd {
        path: k,
        kind: EndpointKind::Failed,
        x: None,
        winding: 0,
        inverse_condition: 0.0,
        steps: 0,
        failure: Some(failure),
        retracked: false,
    }
}

/// The mixed cells of `system`'s supports with the origin ([`crate::polyhedral`]) for the
/// lifting of `seed`, within `max_linear_programs`. The last outcome is kept — the subdivision,
/// or the budget it exceeded — so that counting the paths ([`check_solvable`]) and solving pay
/// for it once, found or not.
///
/// # Errors
/// [`HomotopyError::MixedCells`] when the enumeration exceeds its budget.
pub fn polyhedral_subdivision(
    system: &System,
    seed: u64,
    max_linear_programs: usize,
) -> Result<std::sync::Arc<MixedSubdivision>, HomotopyError> {
    use crate::polyhedral::MixedCellError;
    type Outcome = Result<std::sync::Arc<MixedSubdivision>, MixedCellError>;
    /// The seed, the supports and what came of them.
    type Kept = Option<(u64, Vec<Vec<Vec<i64>>>, Outcome)>;
    static LAST: std::sync::Mutex<Kept> = std::sync::Mutex::new(None);
    let supports = crate::polyhedral::supports_of(system, true);
    if let Ok(last) = LAST.lock()
        && let Some((s, kept_supports, outcome)) = last.as_ref()
        && *s == seed
        && *kept_supports == supports
    {
        match outcome {
            Ok(kept) => return Ok(kept.clone()),
            // A budget no larger than one already exceeded is exceeded again.
            Err(MixedCellError::Budget { limit }) if max_linear_programs <= *limit => {
                return Err(MixedCellError::Budget {
                    limit: max_linear_programs,
                }
                .into());
            }
            Err(_) => {}
        }
    }
    let outcome = crate::polyhedral::mixed_cells(
        &supports,
        &crate::polyhedral::MixedCellSettings {
            seed,
            max_linear_programs,
        },
    )
    .map(std::sync::Arc::new);
    if let Ok(mut last) = LAST.lock() {
        *last = Some((seed, supports, outcome.clone()));
    }
    Ok(outcome?)
}

/// The number of paths of the start system `start` for `system`: its Bézout number, its
/// multi-homogeneous Bézout number for its variable groups (`None` when those are too many to
/// count, [`crate::poly::multihomogeneous::MAX_GROUP_STATES`]), or its mixed volume with the
/// origin (`None` when the mixed cells exceed their budget; the lifting of seed 1, the count
/// does not depend on it), or the fewest of these ([`StartSystem::Auto`]).
#[must_use]
pub fn path_count(system: &System, start: StartSystem) -> Option<u128> {
    resolve_start(system, start, 1).ok().map(|(_, paths)| paths)
}

/// How many linear programs per path of the best Bézout-type start [`StartSystem::Auto`] spends
/// looking for the mixed cells (at least [`AUTO_MIN_PROGRAMS`]) before it keeps that start: a
/// linear program costs about 10–30 µs of CPU, a path about 0.5–5 ms (more for one that
/// diverges), so a search that fails costs at most about a third of the paths (Katsura-7, whose
/// mixed volume is its Bézout number: 74 ms in all, 90 ms with 25 per path). The sparse systems of the tests need 5–13 per path (cyclic-5: 1 549
/// for 120 Bézout paths; cyclic-7: 26 914 for 5 040; noon-5: 2 466 for 243).
pub const AUTO_PROGRAMS_PER_PATH: u128 = 12;

/// The fewest linear programs [`StartSystem::Auto`] allows the mixed cells, whatever the paths.
pub const AUTO_MIN_PROGRAMS: u128 = 2000;

/// The linear programs [`StartSystem::Auto`] allows the mixed cells against a start of `paths`
/// paths ([`AUTO_PROGRAMS_PER_PATH`], [`AUTO_MIN_PROGRAMS`]).
pub(crate) fn auto_budget(paths: u128) -> usize {
    let budget = paths.saturating_mul(AUTO_PROGRAMS_PER_PATH).clamp(
        AUTO_MIN_PROGRAMS,
        crate::polyhedral::DEFAULT_MAX_LINEAR_PROGRAMS as u128,
    );
    usize::try_from(budget).unwrap_or(usize::MAX)
}

/// The start system `start` stands for and its number of paths: [`StartSystem::Auto`] resolved to
/// the one with the fewest paths (ties keep the total degree, then the multi-homogeneous start),
/// the others as they are; `seed` draws the polyhedral lifting.
///
/// # Errors
/// [`HomotopyError::TooManyGroups`] for a multi-homogeneous start whose groups are too many to
/// count; [`HomotopyError::MixedCells`] for a polyhedral start whose cells exceed their budget.
pub fn resolve_start(
    system: &System,
    start: StartSystem,
    seed: u64,
) -> Result<(StartSystem, u128), HomotopyError> {
    let too_many_groups = || HomotopyError::TooManyGroups {
        groups: system.groups().len(),
    };
    match start {
        StartSystem::TotalDegree => Ok((start, system.bezout_number())),
        StartSystem::MultiHomogeneous => Ok((
            start,
            system
                .multihomogeneous_bezout()
                .ok_or_else(too_many_groups)?,
        )),
        StartSystem::LinearProduct => Ok((
            start,
            crate::poly::linear_product::SetStructure::of(system)
                .count()
                .ok_or(HomotopyError::SetStructure)?,
        )),
        StartSystem::Polyhedral => Ok((
            start,
            polyhedral_subdivision(system, seed, crate::polyhedral::DEFAULT_MAX_LINEAR_PROGRAMS)?
                .mixed_volume(),
        )),
        StartSystem::Auto => {
            let mut best = (StartSystem::TotalDegree, system.bezout_number());
            if system.groups().len() > 1
                && let Some(m) = system.multihomogeneous_bezout()
                && m < best.1
            {
                best = (StartSystem::MultiHomogeneous, m);
            }
            if system.groups().len() > 1
                && let Some(m) = crate::poly::linear_product::SetStructure::of(system).count()
                && m < best.1
            {
                best = (StartSystem::LinearProduct, m);
            }
            if let Ok(cells) = polyhedral_subdivision(system, seed, auto_budget(best.1))
                && cells.mixed_volume() < best.1
            {
                best = (StartSystem::Polyhedral, cells.mixed_volume());
            }
            Ok(best)
        }
    }
}

/// What [`solve`] checks before it tracks any path, at a cost of the system's size alone: a
/// square system of at most [`MAX_UNKNOWNS`] unknowns and a program within
/// [`crate::poly::MAX_PROGRAM_SIZE`], without a constant equation, whose start system has at
/// most [`SolveSettings::max_paths`] (and [`MAX_PATHS`]) paths, each counting [`path_weight`]
/// times. Returns the paths.
///
/// # Errors
/// The [`HomotopyError`] [`solve`] would return before tracking.
pub fn check_solvable(system: &System, settings: &SolveSettings) -> Result<u128, HomotopyError> {
    check(system, settings, 1).map(|(_, paths)| paths)
}

/// [`check_solvable`], with the start system resolved ([`resolve_start`]); the paths' limit
/// applies to one `share` of them (a shard's, [`solve_shard`]).
fn check(
    system: &System,
    settings: &SolveSettings,
    share: u128,
) -> Result<(StartSystem, u128), HomotopyError> {
    if !system.is_square() {
        return Err(HomotopyError::NotSquare {
            equations: system.len(),
            variables: system.nvars(),
        });
    }
    if system.nvars() > MAX_UNKNOWNS {
        return Err(HomotopyError::TooManyUnknowns {
            unknowns: system.nvars(),
        });
    }
    let size = system.program_size();
    if size > crate::poly::MAX_PROGRAM_SIZE {
        return Err(HomotopyError::ProgramSize { size });
    }
    if let Some(i) = system.degrees().iter().position(|d| *d == 0) {
        return Err(HomotopyError::ConstantEquation(i));
    }
    let (start, count) = resolve_start(system, settings.start, settings.seed)?;
    let limit = settings.max_paths.min(MAX_PATHS);
    let weight = path_weight(system.nvars());
    if count
        .div_ceil(share.max(1))
        .saturating_mul(u128::from(weight))
        > u128::from(limit)
    {
        return Err(HomotopyError::TooManyPaths {
            paths: count.div_ceil(share.max(1)),
            weight,
            limit,
        });
    }
    Ok((start, count))
}

/// Independent solves of one system with different random choices (seeds `seed, seed + 1, …`):
/// the check that a solve found every root, since a path tracker can lose roots to path jumps
/// without a trace (HomotopyContinuation.jl issues #545, #574).
#[derive(Debug, Clone, PartialEq)]
pub struct RunsReport {
    /// Each run's report.
    pub runs: Vec<SolveReport>,
    /// The distinct non-singular solutions found by any run.
    pub union: Vec<Vec<C64>>,
    /// For each run, whether it found every solution of the union.
    pub complete: Vec<bool>,
}

impl RunsReport {
    /// The number of runs that found every solution any run found.
    #[must_use]
    pub fn complete_count(&self) -> usize {
        self.complete.iter().filter(|c| **c).count()
    }

    /// The fraction of runs that found every solution any run found.
    #[must_use]
    pub fn complete_fraction(&self) -> f64 {
        self.complete_count() as f64 / self.runs.len().max(1) as f64
    }
}

/// [`solve`] `runs` times with seeds `settings.seed + k`, and the union of what they found.
///
/// # Errors
/// As [`solve`].
pub fn solve_runs(
    system: &System,
    settings: &SolveSettings,
    runs: usize,
) -> Result<RunsReport, HomotopyError> {
    let reports: Vec<SolveReport> = (0..runs as u64)
        .map(|k| {
            solve(
                system,
                &SolveSettings {
                    seed: settings.seed.wrapping_add(k),
                    ..settings.clone()
                },
            )
        })
        .collect::<Result<_, _>>()?;
    Ok(combine_runs(reports))
}

/// The union of the non-singular solutions of independent runs of one system, and which runs
/// found all of it.
#[must_use]
pub fn combine_runs(runs: Vec<SolveReport>) -> RunsReport {
    let mut union: Vec<Vec<C64>> = Vec::new();
    let mut index = NearPoints::default();
    for s in runs
        .iter()
        .flat_map(|r| r.solutions.iter().filter(|s| s.regular))
    {
        let known = index
            .candidates(&s.x, 1e-6)
            .into_iter()
            .any(|k| close(&union[k], &s.x, 1e-6));
        if !known {
            index.insert(union.len(), &s.x);
            union.push(s.x.clone());
        }
    }
    let complete = runs
        .iter()
        .map(|r| {
            let mut found = NearPoints::default();
            for (k, s) in r.solutions.iter().enumerate().filter(|(_, s)| s.regular) {
                found.insert(k, &s.x);
            }
            union.iter().all(|u| {
                found
                    .candidates(u, 1e-6)
                    .into_iter()
                    .any(|k| close(u, &r.solutions[k].x, 1e-6))
            })
        })
        .collect();
    RunsReport {
        runs,
        union,
        complete,
    }
}

/// Tracks path `k` from its start solution `z` and classifies its end.
fn track_path(
    homotopy: &ProjectiveHomotopy,
    settings: TrackerSettings,
    k: usize,
    mut z: DVector<C64>,
) -> PathEnd {
    let mut tracker = Tracker::new(homotopy, settings);
    let failed = |failure, steps| PathEnd {
        path: k,
        kind: EndpointKind::Failed,
        x: None,
        winding: 0,
        inverse_condition: 0.0,
        steps,
        failure: Some(failure),
        retracked: false,
    };
    let end = match tracker.track_to_end(&mut z) {
        Ok(end) => end,
        Err(f) => return failed(f, tracker.steps),
    };
    let mut point = end.z;
    if end.diverges || homotopy.measure(&point) < INFINITY_TOLERANCE {
        return PathEnd {
            path: k,
            kind: EndpointKind::AtInfinity,
            x: None,
            winding: end.winding,
            inverse_condition: 0.0,
            steps: tracker.steps,
            failure: None,
            retracked: false,
        };
    }
    let inverse_condition = tracker.inverse_condition(&point);
    let regular = end.winding == 1 && inverse_condition > SINGULAR_TOLERANCE;
    if regular {
        tracker.refine(&mut point, C64::from(0.0), 1e-14);
    } else if !end.converged {
        return failed(PathFailure::Endgame, tracker.steps);
    }
    if homotopy.measure(&point) < INFINITY_TOLERANCE {
        return PathEnd {
            path: k,
            kind: EndpointKind::AtInfinity,
            x: None,
            winding: end.winding,
            inverse_condition,
            steps: tracker.steps,
            failure: None,
            retracked: false,
        };
    }
    PathEnd {
        path: k,
        kind: if regular {
            EndpointKind::Regular
        } else {
            EndpointKind::Singular
        },
        x: Some(homotopy.affine(&point)),
        winding: end.winding,
        inverse_condition,
        steps: tracker.steps,
        failure: None,
        retracked: false,
    }
}

/// In the size of an equation's terms (the row scale of [`SINGULAR_TOLERANCE`]), a coordinate
/// smaller than this fraction of the point's largest (1 for affine points) counts as this
/// fraction. A coordinate that small is not trusted to scale a row down: at an approximate
/// double root of `x² = 0` (`x` about 1e-13) the row `2x` stays small against the others and
/// the root singular, where the size `2|x|` of the row's one term would have made it look
/// regular.
pub(crate) const TERM_SIZE_FLOOR: f64 = 1e-3;

/// The moduli of the coordinates of `z`, each at least [`TERM_SIZE_FLOOR`] times `unit` (the
/// largest modulus of a projective group, or `max(1, |z|∞)` for an affine point), as complex
/// numbers: the point at which the magnitude polynomials ([`crate::poly::Poly::magnitudes`])
/// give the size of each equation's terms.
pub(crate) fn floored_moduli(z: &[C64], unit: f64) -> Vec<C64> {
    z.iter()
        .map(|c| C64::new(c.norm().max(TERM_SIZE_FLOOR * unit), 0.0))
        .collect()
}

/// `σ_min / σ_max` of `jacobian` with row `i` divided by `scales[i]` (the size of equation
/// `i`'s terms at the point; rows of zero or non-finite scale are left as they are): the
/// inverse condition of an endpoint ([`SINGULAR_TOLERANCE`]). 0 when the matrix is not finite.
pub(crate) fn scaled_inverse_condition(mut jacobian: DMatrix<C64>, scales: &[f64]) -> f64 {
    for (i, s) in scales.iter().enumerate() {
        if *s > 0.0 && s.is_finite() {
            jacobian.row_mut(i).unscale_mut(*s);
        }
    }
    if !jacobian
        .iter()
        .all(|c| c.re.is_finite() && c.im.is_finite())
    {
        return 0.0;
    }
    let sv = jacobian.singular_values();
    let largest = sv.max();
    if largest > 0.0 {
        sv.min() / largest
    } else {
        0.0
    }
}

/// `|a − b| / (1 + |a|)`: how far apart two points are, relative to the first one's size (so
/// not symmetric), for points with the same number of coordinates. The solvers tell endpoints
/// and witness points apart by it.
#[must_use]
pub fn relative_distance(a: &[C64], b: &[C64]) -> f64 {
    let d: f64 = a
        .iter()
        .zip(b)
        .map(|(p, q)| (p - q).norm_sqr())
        .sum::<f64>()
        .sqrt();
    let size: f64 = a
        .iter()
        .map(nalgebra::Complex::norm_sqr)
        .sum::<f64>()
        .sqrt();
    d / (1.0 + size)
}

fn close(a: &[C64], b: &[C64], tolerance: f64) -> bool {
    relative_distance(a, b) <= tolerance
}

/// Paths to track again: failed ones, and regular endpoints reached by more than one path (a
/// regular solution is the end of exactly one path of a γ-trick homotopy, so a second one
/// jumped).
fn suspect_paths(ends: &[PathEnd]) -> Vec<usize> {
    let regular = |e: &PathEnd| e.kind == EndpointKind::Regular;
    let mut index = NearPoints::default();
    for (k, e) in ends.iter().enumerate().filter(|(_, e)| regular(e)) {
        index.insert(k, e.x.as_deref().expect("finite"));
    }
    let mut suspects = Vec::new();
    for (k, e) in ends.iter().enumerate() {
        if e.kind == EndpointKind::Failed {
            suspects.push(k);
            continue;
        }
        if !regular(e) {
            continue;
        }
        let x = e.x.as_deref().expect("finite");
        let twin = index
            .candidates(x, 1e-6)
            .into_iter()
            .any(|l| l != k && close(x, ends[l].x.as_deref().expect("finite"), 1e-6));
        if twin {
            suspects.push(k);
        }
    }
    suspects
}

/// Certifies the regular solutions in place; a certified reality replaces the tolerance's.
fn certify_solutions(system: &System, solutions: &mut [Solution]) {
    let regular: Vec<usize> = (0..solutions.len())
        .filter(|k| solutions[*k].regular)
        .collect();
    let roots: Vec<Vec<C64>> = regular.iter().map(|k| solutions[*k].x.clone()).collect();
    let Ok(certificates) = certify_roots(&system.program(), &roots, system.is_real()) else {
        return;
    };
    for (k, c) in regular.into_iter().zip(certificates) {
        let s = &mut solutions[k];
        match c.real {
            Reality::CertifiedReal => s.real = true,
            Reality::CertifiedNonReal => s.real = false,
            Reality::Unknown => {}
        }
        if c.is_certified() {
            s.x.clone_from(&c.refined);
        }
        s.certificate = Some(c);
    }
}

/// The finite endpoints grouped into distinct solutions.
fn distinct_solutions(system: &System, ends: &[PathEnd]) -> Vec<Solution> {
    let real_system = system.is_real();
    let mut solutions: Vec<Solution> = Vec::new();
    let mut index = NearPoints::default();
    let mut finite: Vec<&PathEnd> = ends.iter().filter(|e| e.x.is_some()).collect();
    finite.sort_by_key(|e| e.kind != EndpointKind::Regular);
    for e in finite {
        let x = e.x.as_deref().expect("finite");
        let tolerance = if e.kind == EndpointKind::Regular {
            1e-6
        } else {
            1e-4
        };
        // The first solution (in the order found) within the tolerance, as a scan would give.
        let same = index
            .candidates(x, tolerance)
            .into_iter()
            .filter(|k| close(&solutions[*k].x, x, tolerance))
            .min();
        if let Some(s) = same.map(|k| &mut solutions[k]) {
            s.multiplicity += 1;
            s.paths.push(e.path);
            s.regular &= e.kind == EndpointKind::Regular;
            continue;
        }
        let size = x
            .iter()
            .map(nalgebra::Complex::norm_sqr)
            .sum::<f64>()
            .sqrt();
        let real = real_system
            && x.iter()
                .all(|c| c.im.abs() <= REAL_TOLERANCE * (1.0 + size));
        let residual = system
            .evaluate(x)
            .iter()
            .map(|v| v.norm())
            .fold(0.0, f64::max);
        index.insert(solutions.len(), x);
        solutions.push(Solution {
            x: x.to_vec(),
            regular: e.kind == EndpointKind::Regular,
            multiplicity: 1,
            real,
            residual,
            paths: vec![e.path],
            certificate: None,
        });
    }
    solutions
}
