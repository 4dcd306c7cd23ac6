//! Numerical irreducible decomposition: the solution set `V(F)` of a polynomial system of `n`
//! equations in `N` unknowns (any `n`), as a list of irreducible components, each known by its
//! dimension, its degree and a **witness set** — its points on a generic affine slice of
//! complementary dimension (Sommese, Verschelde & Wampler, *Numerical decomposition of the
//! solution sets of polynomial systems into irreducible components*, SIAM J. Numer. Anal. 38,
//! 2001; Sommese & Wampler 2005, ch. 13–15).
//!
//! For each dimension `d` from the top down, [`decompose`]:
//! 1. meets `V(F)` with `d` random complex affine hyperplanes `L_d` and randomises `F` to
//!    `N − d` random complex combinations of its equations, and solves that square system with
//!    [`solve`](super::solve); the finite endpoints that satisfy `F` itself (relative residual)
//!    form the witness superset `Ŵ_d`;
//! 2. keeps the **regular** endpoints as witness points: a point of `Ŵ_d` on a component of
//!    larger dimension `d' > d` lies on the positive-dimensional set (that component) ∩ `L_d`,
//!    so it is never a regular solution — junk is singular. Singular endpoints are put to the
//!    **homotopy membership test** against every larger witness set (its slice is translated
//!    to pass through the point; the point is on that component iff it is an endpoint); those
//!    that pass are junk and dropped, those that fail are witness points of non-reduced
//!    components (multiplicity > 1): they are **deflated** (`super::deflation`) into regular
//!    points of a lifted system and decomposed like the rest, each component with its
//!    multiplicity; points still singular after the deflation steps are reported in
//!    [`Decomposition::unresolved`];
//! 3. splits each witness set into irreducible pieces by **monodromy** (the slice moved
//!    around loops through random complex slices; points that permute lie on one component)
//!    and confirms each piece with the **linear trace test** (the sum of a linear function
//!    over a piece's points is affine in a parallel translation of the slice exactly when the
//!    piece is a union of whole components; tested with three translations). Pieces that fail
//!    after the loops stop are merged along sets whose traces' nonlinear parts cancel.
//!
//! All random choices come from one seed.

use super::deflation::{Suspect, deflate};
use super::nearby::NearPoints;
use super::parameter::{
    FamilyEnd, ParameterError, ParametrizedSystem, track_parameters, track_parameters_to_end,
};
use super::{C64, HomotopyError, SolveSettings, StartSystem, relative_distance, solve};
use crate::poly::linear_product::{Profile, SetStructure};
use crate::poly::{Poly, System};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use std::cell::Cell;

/// The default of [`DecomposeSettings::max_paths`]: 2¹⁶ = 65 536 paths of up to
/// [`super::PATH_WEIGHT_UNKNOWNS`] unknowns ([`super::path_weight`]), about three minutes on two
/// cores when most paths diverge (docs/limits.md, "Measured cost"). The 4-RUU at fixed inputs
/// estimates 510 (by dimension) and 4 092 (regeneration).
pub const DEFAULT_DECOMPOSE_PATHS: u64 = 1 << 16;

/// The most paths a decomposition tracks, whatever [`DecomposeSettings::max_paths`] says:
/// 2²² = 4 194 304, about two hours (the 4-RUU over its input space, `--free-inputs`, estimates
/// 699 052 paths by regeneration).
pub const MAX_DECOMPOSE_PATHS: u64 = 1 << 22;

/// The most unknowns a decomposition takes: the slice families of dimension `d` have
/// `N + d (N + 1)` variables (the slices' coefficients are their parameters), so the work and
/// memory grow as `N⁴` (docs/limits.md, "Measured cost").
pub const MAX_DECOMPOSE_UNKNOWNS: usize = 32;

/// The most equations a decomposition takes: an over-determined system is randomised to as
/// many combinations as unknowns, each a sum over every equation.
pub const MAX_DECOMPOSE_EQUATIONS: usize = 4 * MAX_DECOMPOSE_UNKNOWNS;

/// Why a system cannot be decomposed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DecomposeError {
    /// No unknowns or no equations.
    #[error("the system has {equations} equations in {variables} unknowns: nothing to decompose")]
    Empty {
        /// Equations.
        equations: usize,
        /// Unknowns.
        variables: usize,
    },
    /// An equation is identically zero: it constrains nothing.
    #[error("equation {0} is identically zero")]
    ZeroEquation(usize),
    /// A sliced system could not be solved.
    #[error("dimension {dimension}: {source}")]
    Solve {
        /// The dimension being sliced.
        dimension: usize,
        /// The solver's complaint.
        source: HomotopyError,
    },
    /// The sliced family could not be formed (a variable named like a slice parameter).
    #[error("the slice family: {0}")]
    Family(String),
    /// More unknowns than [`MAX_DECOMPOSE_UNKNOWNS`] or equations than
    /// [`MAX_DECOMPOSE_EQUATIONS`].
    #[error(
        "{equations} equations in {unknowns} unknowns: a decomposition takes at most {MAX_DECOMPOSE_EQUATIONS} equations in {MAX_DECOMPOSE_UNKNOWNS} unknowns"
    )]
    TooLarge {
        /// Equations.
        equations: usize,
        /// Unknowns.
        unknowns: usize,
    },
    /// The programs of the randomised system would exceed [`crate::poly::MAX_PROGRAM_SIZE`]:
    /// up to `N` combinations, each holding every equation's terms
    /// ([`System::program_size`] times `N`).
    #[error(
        "the randomised system's program would hold up to {size} factors, beyond the limit of {}",
        crate::poly::MAX_PROGRAM_SIZE
    )]
    ProgramSize {
        /// The bound on its size.
        size: u128,
    },
    /// The start systems (or regeneration steps) need more paths than the limit, known from
    /// the degrees before any path is tracked ([`decompose_paths`], [`super::regeneration_paths`]).
    #[error(
        "an estimated {estimate} paths, each counting {weight} times, exceed the limit of {limit}"
    )]
    TooManyPaths {
        /// The bound on the paths of the start systems (saturating at `u128::MAX`).
        estimate: u128,
        /// The unknowns of the system (the paths' weight).
        unknowns: usize,
        /// How many times each counts ([`super::path_weight`] of the unknowns).
        weight: u64,
        /// The limit ([`DecomposeSettings::max_paths`], at most [`MAX_DECOMPOSE_PATHS`]).
        limit: u64,
    },
    /// The paths tracked (start systems, monodromy loops, trace and membership tests) reached
    /// the limit: the decomposition stopped.
    #[error(
        "stopped after {tracked} paths, each counting {weight} times, at the limit of {limit} (the start systems were estimated at {estimate})"
    )]
    PathLimit {
        /// The paths tracked when it stopped.
        tracked: u64,
        /// The unknowns of the system (the paths' weight).
        unknowns: usize,
        /// How many times each counts ([`super::path_weight`] of the unknowns).
        weight: u64,
        /// The limit.
        limit: u64,
        /// The estimate the decomposition started from.
        estimate: u128,
    },
}

/// How to decompose.
#[derive(Debug, Clone, PartialEq)]
pub struct DecomposeSettings {
    /// The seed of every random choice (slices, randomisations, loops, the solver's γ).
    pub seed: u64,
    /// The solver of the sliced square systems (its seed is derived from `seed`).
    pub solve: SolveSettings,
    /// A point satisfies `F` when each `|f_i(x)|` is below this fraction of the sum of its
    /// terms' magnitudes at `x` (taken `≥ 1`).
    pub residual_tolerance: f64,
    /// The most monodromy loops per dimension.
    pub max_loops: usize,
    /// Stop the loops after this many in a row that merge nothing while some piece still fails
    /// the trace test.
    pub stall_loops: usize,
    /// A piece passes the trace test when the nonlinear part of its trace is below this
    /// fraction of the size of its points' traces.
    pub trace_tolerance: f64,
    /// The most paths to track in all (at most [`MAX_DECOMPOSE_PATHS`] is honoured): a system
    /// whose start systems alone are estimated at more is refused before any path is tracked
    /// ([`decompose_paths`], [`super::regeneration_paths`]); one whose monodromy loops and
    /// membership tests take the total beyond it stops with [`DecomposeError::PathLimit`].
    pub max_paths: u64,
}

impl Default for DecomposeSettings {
    fn default() -> Self {
        Self {
            seed: 1,
            solve: SolveSettings {
                certify: false,
                ..SolveSettings::default()
            },
            residual_tolerance: 1e-8,
            max_loops: 20,
            stall_loops: 5,
            trace_tolerance: 1e-6,
            max_paths: DEFAULT_DECOMPOSE_PATHS,
        }
    }
}

/// One irreducible component of `V(F)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Component {
    /// Its dimension.
    pub dimension: usize,
    /// Its degree: the number of points in which a generic affine slice of complementary
    /// dimension meets it.
    pub degree: usize,
    /// Those points, on the slice of its dimension ([`Decomposition::slices`]).
    pub witness_points: Vec<Vec<C64>>,
    /// A point on the component.
    pub sample_point: Vec<C64>,
    /// Whether the linear trace test confirmed the piece as a whole component (always true in
    /// dimension 0, where a point is a component).
    pub trace_test_passed: bool,
    /// Its multiplicity: 1 for a reduced component; at least 2 for a component found by
    /// deflation — by dimension, the paths that ended at each of its witness points;
    /// regeneration, which merges its endpoints, gives a lower bound ([`super::deflation`]).
    pub multiplicity: usize,
}

/// The irreducible decomposition of `V(F)`.
#[derive(Debug, Clone, PartialEq)]
pub struct Decomposition {
    /// The components, by decreasing dimension.
    pub components: Vec<Component>,
    /// The slice of each dimension `d` (index `d`): `d` rows `[a_0, …, a_{N−1}, b]`, the
    /// hyperplanes `Σ a_j x_j + b = 0`.
    pub slices: Vec<Vec<Vec<C64>>>,
    /// Singular points of the witness supersets that no larger component contains and that
    /// deflation did not make regular (`(dimension, point)`); with regeneration also the
    /// singular points of an intermediate step that a later equation cuts.
    pub unresolved: Vec<(usize, Vec<C64>)>,
    /// Singular points of the witness supersets found on larger components and dropped.
    pub junk: usize,
    /// Paths tracked (solves, loops, trace and membership tests).
    pub paths: usize,
    /// The paths of the start systems (or regeneration steps) as estimated from the degrees
    /// before any was tracked ([`decompose_paths`], [`super::regeneration_paths`]).
    pub estimated_paths: u128,
    /// Wall time.
    pub seconds: f64,
}

impl Decomposition {
    /// The `(dimension, degree)` of every component, by decreasing dimension then degree.
    #[must_use]
    pub fn signature(&self) -> Vec<(usize, usize)> {
        let mut s: Vec<(usize, usize)> = self
            .components
            .iter()
            .map(|c| (c.dimension, c.degree))
            .collect();
        s.sort_unstable_by(|a, b| b.cmp(a));
        s
    }
}

/// A witness set of one dimension: its slice family (the equations, then the slice's
/// hyperplanes with their coefficients as parameters), the slice and its points.
pub(super) struct Witness {
    pub(super) family: ParametrizedSystem,
    pub(super) base: Vec<C64>,
    pub(super) points: Vec<Vec<C64>>,
    /// The leading unknowns the slices cut, those of the system decomposed: all of the
    /// family's, or fewer for a deflated family (whose multipliers `λ` follow them).
    pub(super) sliced: usize,
}

/// The irreducible decomposition of `V(system)` (module documentation).
///
/// # Errors
/// [`DecomposeError`] for a system without equations or unknowns, too large, with a zero
/// equation, or needing more paths than [`DecomposeSettings::max_paths`] ([`decompose_paths`];
/// checked before any path is tracked, and again as paths are tracked) or than the solver
/// takes for one sliced system.
pub fn decompose(
    system: &System,
    settings: &DecomposeSettings,
) -> Result<Decomposition, DecomposeError> {
    let clock = std::time::Instant::now();
    let estimated_paths = check_system(system).map(|()| decompose_paths(system))?;
    let budget = PathBudget::new(system, settings, estimated_paths)?;
    let (n, big_n) = (system.len(), system.nvars());
    check_sliced_solves(system)?;
    let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
    let lowest = big_n.saturating_sub(n);
    let mut witnesses: Vec<Option<Witness>> = (0..big_n).map(|_| None).collect();
    // The witness sets of the components found by deflation, for the membership tests.
    let mut deflated: Vec<Witness> = Vec::new();
    let mut slices = vec![Vec::new(); big_n];
    let mut decomposition = Decomposition {
        components: Vec::new(),
        slices: Vec::new(),
        unresolved: Vec::new(),
        junk: 0,
        paths: 0,
        estimated_paths,
        seconds: 0.0,
    };
    for d in (lowest..big_n).rev() {
        let family = slice_family(system, d, &mut rng)?;
        let base: Vec<C64> = (0..d * (big_n + 1)).map(|_| gaussian(&mut rng)).collect();
        slices[d] = base.chunks(big_n + 1).map(<[C64]>::to_vec).collect();
        let sliced = family
            .at(&base)
            .map_err(|e| DecomposeError::Family(e.to_string()))?;
        let (sliced, start, start_paths) = sliced_start(sliced, system.groups());
        let solve_settings = SolveSettings {
            seed: settings.seed.wrapping_mul(1000).wrapping_add(d as u64),
            max_paths: super::MAX_PATHS,
            start,
            ..settings.solve.clone()
        };
        budget.spend_u128(start_paths)?;
        let report = solve(&sliced, &solve_settings).map_err(|source| DecomposeError::Solve {
            dimension: d,
            source,
        })?;
        budget.spend(report.retracked)?;
        decomposition.paths += report.paths();
        let mut points = Vec::new();
        let mut suspects = Vec::new();
        for s in &report.solutions {
            if s.regular && satisfies(system, &s.x, settings.residual_tolerance) {
                points.push(s.x.clone());
            } else if !s.regular && satisfies(system, &s.x, settings.residual_tolerance.sqrt()) {
                let (on_larger, paths) = on_larger_component(
                    witnesses.iter().flatten().chain(&deflated),
                    &s.x,
                    settings,
                    &budget,
                )?;
                decomposition.paths += paths;
                if on_larger {
                    decomposition.junk += 1;
                } else {
                    suspects.push(Suspect {
                        x: s.x.clone(),
                        paths: s.multiplicity,
                    });
                }
            }
        }
        if !points.is_empty() {
            let witness = Witness {
                family,
                base,
                points,
                sliced: big_n,
            };
            let (components, paths) = components_of(&witness, d, settings, &mut rng, &budget)?;
            decomposition.paths += paths;
            decomposition.components.extend(components);
            witnesses[d] = Some(witness);
        }
        // The singular points on no larger component: non-reduced components, deflated.
        if !suspects.is_empty() {
            let larger: Vec<&Witness> = witnesses[d + 1..]
                .iter()
                .flatten()
                .chain(&deflated)
                .collect();
            let found = deflate(
                system,
                d,
                &slices[d],
                suspects,
                &larger,
                (settings, &budget),
                &mut rng,
            )?;
            decomposition.paths += found.paths;
            decomposition.junk += found.junk;
            decomposition.components.extend(found.components);
            decomposition.unresolved.extend(found.unresolved);
            deflated.extend(found.witnesses);
        }
    }
    decomposition.slices = slices;
    decomposition.seconds = clock.elapsed().as_secs_f64();
    Ok(decomposition)
}

/// Each sliced system of [`decompose`] is a solve of its own, within the solver's ceiling
/// ([`super::MAX_PATHS`] weighted paths).
fn check_sliced_solves(system: &System) -> Result<(), DecomposeError> {
    let weight = super::path_weight(system.nvars());
    let ceiling = u128::from(super::MAX_PATHS);
    match sliced_paths(system).find(|(_, p)| p.saturating_mul(u128::from(weight)) > ceiling) {
        Some((dimension, paths)) => Err(DecomposeError::Solve {
            dimension,
            source: HomotopyError::TooManyPaths {
                paths,
                weight,
                limit: super::MAX_PATHS,
            },
        }),
        None => Ok(()),
    }
}

/// The components of the (reduced) witness set `witness` of dimension `d`: its irreducible
/// pieces (each point a component in dimension 0), and the paths tracked.
fn components_of(
    witness: &Witness,
    d: usize,
    settings: &DecomposeSettings,
    rng: &mut ChaCha8Rng,
    budget: &PathBudget,
) -> Result<(Vec<Component>, usize), DecomposeError> {
    let (pieces, paths) = if d == 0 {
        (
            (0..witness.points.len()).map(|i| (vec![i], true)).collect(),
            0,
        )
    } else {
        irreducible_pieces(witness, settings, rng, budget)?
    };
    let components = pieces
        .into_iter()
        .map(|(members, passed)| {
            let witness_points: Vec<Vec<C64>> =
                members.iter().map(|i| witness.points[*i].clone()).collect();
            Component {
                dimension: d,
                degree: witness_points.len(),
                sample_point: witness_points[0].clone(),
                witness_points,
                trace_test_passed: passed,
                multiplicity: 1,
            }
        })
        .collect();
    Ok((components, paths))
}

pub(super) fn gaussian(rng: &mut ChaCha8Rng) -> C64 {
    let re: f64 = StandardNormal.sample(rng);
    let im: f64 = StandardNormal.sample(rng);
    C64::new(re, im)
}

/// A system [`decompose`] and [`super::regenerate`] can work on: some equations, some
/// unknowns, at most [`MAX_DECOMPOSE_EQUATIONS`] and [`MAX_DECOMPOSE_UNKNOWNS`], programs
/// within [`crate::poly::MAX_PROGRAM_SIZE`], no equation identically zero.
///
/// # Errors
/// The [`DecomposeError`] the decomposition would return before any work.
pub fn check_system(system: &System) -> Result<(), DecomposeError> {
    let (n, big_n) = (system.len(), system.nvars());
    if n == 0 || big_n == 0 {
        return Err(DecomposeError::Empty {
            equations: n,
            variables: big_n,
        });
    }
    if n > MAX_DECOMPOSE_EQUATIONS || big_n > MAX_DECOMPOSE_UNKNOWNS {
        return Err(DecomposeError::TooLarge {
            equations: n,
            unknowns: big_n,
        });
    }
    // Each of the up to N random combinations holds every equation's terms.
    let size = system.program_size().saturating_mul(big_n as u128);
    if size > crate::poly::MAX_PROGRAM_SIZE {
        return Err(DecomposeError::ProgramSize { size });
    }
    if let Some(i) = system.equations().iter().position(Poly::is_empty) {
        return Err(DecomposeError::ZeroEquation(i));
    }
    Ok(())
}

/// The paths of the start systems of [`decompose`], from the equations' degrees and supports
/// alone: for each dimension `d` from `N − 1` down to `max(N − n, 0)` the paths of the sliced
/// system — the equations themselves when there are exactly `N − d` of them, else `N − d`
/// random combinations (`[I | A]`: the `N − d` of largest degree, each plus multiples of the
/// rest) — and `d` linear slices: its Bézout number, or for a system of several variable
/// groups its linear-product count when smaller ([`crate::poly::linear_product`]). Saturates
/// at `u128::MAX`.
///
/// 21 equations `x_i² − 1` in 21 unknowns: `2 + 4 + … + 2²¹ = 2²² − 2`. The monodromy loops,
/// trace and membership tests track more, in proportion to the witness points found, within
/// [`DecomposeSettings::max_paths`] in all.
#[must_use]
pub fn decompose_paths(system: &System) -> u128 {
    sliced_paths(system)
        .map(|(_, p)| p)
        .fold(0u128, u128::saturating_add)
}

/// [`decompose_paths`] dimension by dimension, from the highest: `(d, paths)` of the sliced
/// system of each dimension `d`.
#[must_use]
pub fn decompose_paths_by_dimension(system: &System) -> Vec<(usize, u128)> {
    let mut paths: Vec<(usize, u128)> = sliced_paths(system).collect();
    paths.reverse();
    paths
}

/// Each dimension of [`decompose`] with the paths of its sliced system's start
/// ([`sliced_start`]), from the equations' profiles alone ([`Profile`]: the randomisation's
/// combinations and the slices have the profiles of generic sums and hyperplanes, whatever
/// their random coefficients); the Bézout number for a system beyond the decomposition's
/// limits, which is refused anyway.
fn sliced_paths(system: &System) -> impl Iterator<Item = (usize, u128)> + '_ {
    let (n, big_n) = (system.len(), system.nvars());
    let groups = system.groups();
    let mut degrees = system.degrees();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by_key(|&i| std::cmp::Reverse(degrees[i]));
    degrees.sort_unstable_by(|a, b| b.cmp(a));
    let structured =
        groups.len() > 1 && big_n <= MAX_DECOMPOSE_UNKNOWNS && n <= MAX_DECOMPOSE_EQUATIONS;
    let profiles: Vec<Profile> = if structured {
        system
            .equations()
            .iter()
            .map(|f| Profile::of(f, groups))
            .collect()
    } else {
        Vec::new()
    };
    (big_n.saturating_sub(n)..big_n).map(move |d| {
        let count = big_n - d;
        let bezout = degrees[..count]
            .iter()
            .fold(1u128, |b, e| b.saturating_mul(u128::from(*e)));
        if !structured {
            return (d, bezout);
        }
        let rest = order[count..]
            .iter()
            .fold(None, |acc: Option<Profile>, &j| {
                Some(acc.map_or_else(|| profiles[j].clone(), |a| a.sum(&profiles[j])))
            });
        let mut sliced: Vec<Profile> = order[..count]
            .iter()
            .map(|&i| {
                rest.as_ref()
                    .map_or_else(|| profiles[i].clone(), |r| profiles[i].sum(r))
            })
            .collect();
        sliced.extend((0..d).map(|_| Profile::hyperplane(groups.len())));
        let paths = SetStructure::from_profiles(big_n, groups, &sliced)
            .count()
            .map_or(bezout, |p| p.min(bezout));
        (d, paths)
    })
}

/// The start system of a sliced system in the variable groups `groups` of the system sliced:
/// the linear-product start ([`crate::poly::linear_product`]) when the groups are several
/// and it has fewer paths than the total degree (slices and randomised equations are dense in
/// every group, which the multi-homogeneous count would charge in each), else the total
/// degree. Returns the system (with the groups), the start and its paths.
fn sliced_start(sliced: System, groups: &[Vec<usize>]) -> (System, StartSystem, u128) {
    let bezout = sliced.bezout_number();
    if groups.len() > 1
        && let Ok(grouped) = sliced.clone().with_groups(groups.to_vec())
        && let Some(paths) = SetStructure::of(&grouped).count()
        && paths < bezout
    {
        return (grouped, StartSystem::LinearProduct, paths);
    }
    (sliced, StartSystem::TotalDegree, bezout)
}

/// The paths a decomposition may still track: each tracking is charged before it starts
/// ([`DecomposeSettings::max_paths`]), each path [`super::path_weight`] times.
pub(super) struct PathBudget {
    limit: u64,
    unknowns: usize,
    weight: u64,
    estimate: u128,
    tracked: Cell<u64>,
}

impl PathBudget {
    /// The budget of a decomposition of `system` whose start systems need `estimate` paths:
    /// the system checked ([`check_system`]) and the estimate within the limit.
    pub(super) fn new(
        system: &System,
        settings: &DecomposeSettings,
        estimate: u128,
    ) -> Result<Self, DecomposeError> {
        check_system(system)?;
        let limit = settings.max_paths.min(MAX_DECOMPOSE_PATHS);
        let weight = super::path_weight(system.nvars());
        if estimate.saturating_mul(u128::from(weight)) > u128::from(limit) {
            return Err(DecomposeError::TooManyPaths {
                estimate,
                unknowns: system.nvars(),
                weight,
                limit,
            });
        }
        Ok(Self {
            limit,
            unknowns: system.nvars(),
            weight,
            estimate,
            tracked: Cell::new(0),
        })
    }

    /// Charges `paths` about to be tracked.
    pub(super) fn spend(&self, paths: usize) -> Result<(), DecomposeError> {
        self.spend_u128(paths as u128)
    }

    /// Charges `paths` about to be tracked.
    pub(super) fn spend_u128(&self, paths: u128) -> Result<(), DecomposeError> {
        let tracked = u128::from(self.tracked.get()).saturating_add(paths);
        if tracked.saturating_mul(u128::from(self.weight)) > u128::from(self.limit) {
            return Err(DecomposeError::PathLimit {
                tracked: self.tracked.get(),
                unknowns: self.unknowns,
                weight: self.weight,
                limit: self.limit,
                estimate: self.estimate,
            });
        }
        self.tracked.set(u64::try_from(tracked).unwrap_or(u64::MAX));
        Ok(())
    }
}

/// `count` random complex combinations of `equations` (the equations themselves when there
/// are exactly `count`): by Bertini's theorem their solution set has every component of the
/// equations' of codimension `count` as a component of multiplicity one.
pub(super) fn random_combinations(
    equations: &[Poly],
    count: usize,
    rng: &mut ChaCha8Rng,
) -> Vec<Poly> {
    if equations.len() == count {
        return equations.to_vec();
    }
    let nvars = equations.first().map_or(0, Poly::nvars);
    (0..count)
        .map(|_| {
            equations
                .iter()
                .fold(Poly::zero(nvars), |acc, f| &acc + &f.scale(gaussian(rng)))
        })
        .collect()
}

/// The affine form `Σ a_j x_j + b` of a hyperplane row `[a_0 … a_{N−1}, b]`, in `total`
/// variables of which the unknowns are the first `N`.
pub(super) fn hyperplane(row: &[C64], total: usize) -> Poly {
    let big_n = row.len() - 1;
    let mut h = Poly::constant(total, row[big_n]);
    for (j, a) in row[..big_n].iter().enumerate() {
        h = &h + &Poly::variable(total, j).scale(*a);
    }
    h
}

/// The square family of `equations` (polynomials in the `N` unknowns of `system`, or in those
/// and the `other_parameters` after them), then `other_parameters` parameters, the `fixed`
/// hyperplanes, and `sliced` hyperplanes whose coefficients are the last parameters
/// (`slice#k#j`).
pub(super) fn family(
    system: &System,
    equations: Vec<Poly>,
    fixed: &[Vec<C64>],
    sliced: usize,
    other_parameters: usize,
) -> Result<ParametrizedSystem, DecomposeError> {
    let (names, extra) = slices(system, fixed, sliced, other_parameters);
    let total = names.len();
    let mut equations: Vec<Poly> = equations
        .into_iter()
        .map(|f| f.relabel(total, &(0..f.nvars()).collect::<Vec<_>>()))
        .collect();
    equations.extend(extra);
    let family =
        System::new(names, equations).map_err(|e| DecomposeError::Family(e.to_string()))?;
    ParametrizedSystem::new(family, other_parameters + sliced * (system.nvars() + 1))
        .map_err(|e: ParameterError| DecomposeError::Family(e.to_string()))
}

/// The family of the equations of `combined` and `sliced` hyperplanes of its first `n`
/// unknowns whose coefficients are parameters after its unknowns (`slice#k#j`), composed when
/// `combined` is ([`System::widened`]): [`family`] for a randomised system (`n` all its
/// unknowns) or for a deflated one (`n` those of the system deflated, the multipliers after).
pub(super) fn sliced_family(
    combined: &System,
    n: usize,
    sliced: usize,
) -> Result<ParametrizedSystem, DecomposeError> {
    let unknowns = combined.nvars();
    let total = unknowns + sliced * (n + 1);
    let extra = (0..sliced)
        .map(|k| parameter_hyperplane(total, unknowns + k * (n + 1), n))
        .collect();
    let mut names = combined.variables().to_vec();
    for k in 0..sliced {
        names.extend((0..=n).map(|j| format!("slice#{k}#{j}")));
    }
    let family = combined
        .widened(names, extra)
        .map_err(|e| DecomposeError::Family(e.to_string()))?;
    ParametrizedSystem::new(family, sliced * (n + 1))
        .map_err(|e: ParameterError| DecomposeError::Family(e.to_string()))
}

/// The hyperplane `p_n + Σ_j p_j x_j` of the first `n` unknowns in a ring of `total`
/// variables, its coefficients `p_0 … p_n` the variables from `first` on.
fn parameter_hyperplane(total: usize, first: usize, n: usize) -> Poly {
    let p = |j: usize| Poly::variable(total, first + j);
    (0..n).fold(p(n), |h, j| &h + &(&p(j) * &Poly::variable(total, j)))
}

/// The names of a family's variables (the unknowns, `other_parameters`, then the
/// coefficients of `sliced` hyperplanes) and its hyperplanes: the `fixed` ones, then the
/// sliced ones with their coefficients as parameters.
fn slices(
    system: &System,
    fixed: &[Vec<C64>],
    sliced: usize,
    other_parameters: usize,
) -> (Vec<String>, Vec<Poly>) {
    let big_n = system.nvars();
    let total = big_n + other_parameters + sliced * (big_n + 1);
    let mut extra: Vec<Poly> = fixed.iter().map(|row| hyperplane(row, total)).collect();
    let first = big_n + other_parameters;
    extra.extend((0..sliced).map(|k| parameter_hyperplane(total, first + k * (big_n + 1), big_n)));
    let mut names = system.variables().to_vec();
    names.extend((0..other_parameters).map(|k| format!("regeneration#{k}")));
    for k in 0..sliced {
        names.extend((0..=big_n).map(|j| format!("slice#{k}#{j}")));
    }
    (names, extra)
}

/// `count` random combinations of the equations of `system` in the form `[I | A]`: the
/// equations by decreasing degree, each of the first `count` plus random multiples of the
/// rest (the equations themselves when there are exactly `count`). Any generic `count × n`
/// matrix is an invertible one times such a matrix, so by Bertini's theorem the solution set
/// keeps every component of codimension `count` as a component of multiplicity one; and the
/// combinations' degrees are the `count` largest, not `count` times the largest. Composed
/// when `system` is.
pub(super) fn randomized(system: &System, count: usize, rng: &mut ChaCha8Rng) -> System {
    if system.len() == count {
        return system.clone();
    }
    let degrees = system.degrees();
    let mut order: Vec<usize> = (0..system.len()).collect();
    order.sort_by_key(|&i| std::cmp::Reverse(degrees[i]));
    let rows: Vec<Vec<C64>> = (0..count)
        .map(|i| {
            let mut row = vec![C64::new(0.0, 0.0); system.len()];
            row[order[i]] = C64::new(1.0, 0.0);
            for &j in &order[count..] {
                row[j] = gaussian(rng);
            }
            row
        })
        .collect();
    system.combinations(&rows)
}

/// The family, in the unknowns then the slice parameters, of `N − d` random combinations of
/// `F` ([`randomized`]) and `d` affine hyperplanes whose coefficients are the parameters.
fn slice_family(
    system: &System,
    d: usize,
    rng: &mut ChaCha8Rng,
) -> Result<ParametrizedSystem, DecomposeError> {
    let combined = randomized(system, system.nvars() - d, rng);
    sliced_family(&combined, system.nvars(), d)
}

/// Whether `x` satisfies every equation of `system` to `tolerance` ([`vanishes`]).
pub(super) fn satisfies(system: &System, x: &[C64], tolerance: f64) -> bool {
    system.equations().iter().all(|f| vanishes(f, x, tolerance))
}

/// Whether `|f(x)|` is below `tolerance` times the sum of the magnitudes of `f`'s terms at `x`
/// (taken `≥ 1`): zero to the precision with which `f(x)` can be computed.
pub(super) fn vanishes(f: &Poly, x: &[C64], tolerance: f64) -> bool {
    let scale: f64 = f
        .terms()
        .map(|(e, c)| {
            e.iter().zip(x).fold(c.norm(), |acc, (k, v)| {
                acc * v.norm().powi(i32::try_from(*k).unwrap_or(i32::MAX))
            })
        })
        .sum::<f64>()
        .max(1.0);
    f.eval(x).norm() <= tolerance * scale
}

/// The homotopy membership test of `y` against every larger witness set: each set's slice is
/// translated to pass through `y` and its points followed; `y` lies on one of those
/// components iff it is among the endpoints. Returns the verdict and the paths tracked (a
/// test with failed paths counts as outside: [`membership`] tells it apart).
pub(super) fn on_larger_component<'a>(
    witnesses: impl IntoIterator<Item = &'a Witness>,
    y: &[C64],
    settings: &DecomposeSettings,
    budget: &PathBudget,
) -> Result<(bool, usize), DecomposeError> {
    membership(witnesses, y, settings, budget).map(|(inside, paths)| (inside == Some(true), paths))
}

/// [`on_larger_component`] with its doubt: `Some(true)` when `y` is an endpoint, `Some(false)`
/// when every path ended elsewhere, `None` when some path failed and none reached `y` (the
/// path to `y`, a singular point where components meet, may be the one that failed).
pub(super) fn membership<'a>(
    witnesses: impl IntoIterator<Item = &'a Witness>,
    y: &[C64],
    settings: &DecomposeSettings,
    budget: &PathBudget,
) -> Result<(Option<bool>, usize), DecomposeError> {
    let big_n = y.len();
    let mut paths = 0;
    let mut doubt = false;
    for w in witnesses {
        debug_assert_eq!(
            w.sliced, big_n,
            "a point of the system the witness set slices"
        );
        let mut target = w.base.clone();
        for row in target.chunks_mut(big_n + 1) {
            row[big_n] = -row[..big_n].iter().zip(y).map(|(a, v)| a * v).sum::<C64>();
        }
        budget.spend(w.points.len())?;
        paths += w.points.len();
        // The endgame, since `y` may be a singular point of the slice family (where the
        // component meets another one).
        let Ok(ends) = track_parameters_to_end(
            &w.family,
            &w.base,
            &target,
            &w.points,
            settings.solve.tracker,
        ) else {
            doubt = true;
            continue;
        };
        if ends.iter().flatten().any(|e| match e {
            FamilyEnd::Regular(x) | FamilyEnd::Singular(x) => {
                relative_distance(&x[..big_n], y) <= MEMBERSHIP_TOLERANCE
            }
            FamilyEnd::Infinite => false,
        }) {
            return Ok((Some(true), paths));
        }
        doubt |= ends.iter().any(Result::is_err);
    }
    Ok((if doubt { None } else { Some(false) }, paths))
}

/// A singular point and an endpoint of the membership test are the same point within this
/// relative distance (singular endpoints are accurate to about the square root of the
/// working precision).
pub(super) const MEMBERSHIP_TOLERANCE: f64 = 1e-5;

/// Same point within this relative distance (regular endpoints of the monodromy loops).
pub(super) const SAME_POINT: f64 = 1e-6;

/// The irreducible pieces of a positive-dimensional witness set (indices into its points, and
/// whether the trace test confirmed the piece), and the paths tracked.
#[allow(clippy::type_complexity)]
pub(super) fn irreducible_pieces(
    w: &Witness,
    settings: &DecomposeSettings,
    rng: &mut ChaCha8Rng,
    budget: &PathBudget,
) -> Result<(Vec<(Vec<usize>, bool)>, usize), DecomposeError> {
    let m = w.points.len();
    let mut paths = 0;
    budget.spend(2 * m)?;
    let (nonlinear, scale, traced) = trace_parts(w, settings, rng);
    paths += 2 * m;
    let mut parent: Vec<usize> = (0..m).collect();
    let mut index = NearPoints::default();
    for (j, x) in w.points.iter().enumerate() {
        index.insert(j, x);
    }
    let passes = |members: &[usize]| -> bool {
        members.iter().all(|i| traced[*i]) && {
            let s: C64 = members.iter().map(|i| nonlinear[*i]).sum();
            let size: f64 = members.iter().map(|i| scale[*i]).sum::<f64>().max(1.0);
            s.norm() <= settings.trace_tolerance * size
        }
    };
    let (mut loops, mut stalled) = (0, 0);
    loop {
        let groups = groups_of(&mut parent);
        if groups.iter().all(|g| passes(g))
            || loops >= settings.max_loops
            || stalled >= settings.stall_loops
        {
            break;
        }
        loops += 1;
        let p1: Vec<C64> = (0..w.base.len()).map(|_| gaussian(rng)).collect();
        let p2: Vec<C64> = (0..w.base.len()).map(|_| gaussian(rng)).collect();
        let mut current: Vec<Option<Vec<C64>>> = w.points.iter().cloned().map(Some).collect();
        for (a, b) in [(&w.base, &p1), (&p1, &p2), (&p2, &w.base)] {
            let live: Vec<usize> = (0..m).filter(|i| current[*i].is_some()).collect();
            let starts: Vec<Vec<C64>> = live
                .iter()
                .map(|i| current[*i].clone().expect("live"))
                .collect();
            budget.spend(starts.len())?;
            paths += starts.len();
            let Ok(ends) = track_parameters(&w.family, a, b, &starts, settings.solve.tracker)
            else {
                break;
            };
            for (i, e) in live.into_iter().zip(ends) {
                current[i] = e.ok();
            }
        }
        let mut merged = false;
        for (i, end) in current.iter().enumerate() {
            let Some(end) = end else { continue };
            // The first witness point the loop returned to, as a scan would find it.
            let back = index
                .candidates(end, SAME_POINT)
                .into_iter()
                .filter(|j| relative_distance(&w.points[*j], end) <= SAME_POINT)
                .min();
            if let Some(j) = back {
                merged |= union(&mut parent, i, j);
            }
        }
        stalled = if merged { 0 } else { stalled + 1 };
    }
    let groups = groups_of(&mut parent);
    let (mut done, failing): (Vec<Vec<usize>>, Vec<Vec<usize>>) =
        groups.into_iter().partition(|g| passes(g));
    let mut pieces: Vec<(Vec<usize>, bool)> = done.drain(..).map(|g| (g, true)).collect();
    pieces.extend(combine_failing(failing, &passes));
    pieces.sort_by_key(|(g, _)| std::cmp::Reverse(g.len()));
    Ok((pieces, paths))
}

/// The most failing monodromy groups whose unions are searched for passing combinations.
const MAX_COMBINED: usize = 12;

/// Unions of failing groups that pass the trace test, smallest first; what remains is one
/// piece per failing group, marked as failing.
fn combine_failing(
    mut failing: Vec<Vec<usize>>,
    passes: &dyn Fn(&[usize]) -> bool,
) -> Vec<(Vec<usize>, bool)> {
    let mut pieces = Vec::new();
    if failing.len() <= MAX_COMBINED {
        let mut size = 2;
        while size <= failing.len() {
            let k = failing.len();
            let found = (1u32..(1 << k)).find(|mask| {
                mask.count_ones() as usize == size && {
                    let union: Vec<usize> = (0..k)
                        .filter(|b| mask & (1 << b) != 0)
                        .flat_map(|b| failing[b].iter().copied())
                        .collect();
                    passes(&union)
                }
            });
            if let Some(mask) = found {
                let mut union = Vec::new();
                for b in (0..k).rev() {
                    if mask & (1 << b) != 0 {
                        union.extend(failing.remove(b));
                    }
                }
                union.sort_unstable();
                pieces.push((union, true));
            } else {
                size += 1;
            }
        }
    }
    pieces.extend(failing.into_iter().map(|g| (g, false)));
    pieces
}

/// For each witness point, the nonlinear part of its linear trace under a parallel translation
/// of the slice: with `ℓ` a random linear form and `x(t)` the point on the slice translated by
/// `t δ`, the second difference `(ℓ(x(t1)) − ℓ(x(0)))/t1 − (ℓ(x(t2)) − ℓ(x(0)))/t2`; its size
/// scale; and whether both translations were tracked.
fn trace_parts(
    w: &Witness,
    settings: &DecomposeSettings,
    rng: &mut ChaCha8Rng,
) -> (Vec<C64>, Vec<f64>, Vec<bool>) {
    // The form reads the sliced unknowns: a deflated point's multipliers are no linear
    // function on the component.
    let big_n = w.sliced;
    let form: Vec<C64> = (0..big_n).map(|_| gaussian(rng)).collect();
    let ell = |x: &[C64]| -> C64 { form.iter().zip(x).map(|(a, v)| a * v).sum() };
    let delta: Vec<C64> = (0..w.base.len() / (big_n + 1))
        .map(|_| gaussian(rng))
        .collect();
    let (t1, t2) = (C64::new(0.5, 0.2), C64::new(-0.4, 0.3));
    let moved = |t: C64| -> Vec<Option<Vec<C64>>> {
        let mut target = w.base.clone();
        for (row, dk) in target.chunks_mut(big_n + 1).zip(&delta) {
            row[big_n] += t * dk;
        }
        match track_parameters(
            &w.family,
            &w.base,
            &target,
            &w.points,
            settings.solve.tracker,
        ) {
            Ok(ends) => ends.into_iter().map(Result::ok).collect(),
            Err(_) => vec![None; w.points.len()],
        }
    };
    let (a, b) = (moved(t1), moved(t2));
    let mut nonlinear = Vec::new();
    let mut scale = Vec::new();
    let mut traced = Vec::new();
    for (x0, (x1, x2)) in w.points.iter().zip(a.iter().zip(&b)) {
        if let (Some(x1), Some(x2)) = (x1, x2) {
            let (l0, l1, l2) = (ell(x0), ell(x1), ell(x2));
            nonlinear.push((l1 - l0) / t1 - (l2 - l0) / t2);
            scale.push(l0.norm() + l1.norm() + l2.norm());
            traced.push(true);
        } else {
            nonlinear.push(C64::from(0.0));
            scale.push(0.0);
            traced.push(false);
        }
    }
    (nonlinear, scale, traced)
}

fn find(parent: &mut [usize], i: usize) -> usize {
    let mut r = i;
    while parent[r] != r {
        r = parent[r];
    }
    let mut k = i;
    while parent[k] != r {
        let next = parent[k];
        parent[k] = r;
        k = next;
    }
    r
}

fn union(parent: &mut [usize], i: usize, j: usize) -> bool {
    let (a, b) = (find(parent, i), find(parent, j));
    if a == b {
        false
    } else {
        parent[a.max(b)] = a.min(b);
        true
    }
}

fn groups_of(parent: &mut [usize]) -> Vec<Vec<usize>> {
    let mut groups: Vec<Vec<usize>> = Vec::new();
    let mut root_of_group: Vec<usize> = Vec::new();
    for i in 0..parent.len() {
        let r = find(parent, i);
        if let Some(k) = root_of_group.iter().position(|x| *x == r) {
            groups[k].push(i);
        } else {
            root_of_group.push(r);
            groups.push(vec![i]);
        }
    }
    groups
}

/// The points of a component of dimension `d ≥ 1` of `V(system)` on another slice of that
/// dimension (`d` rows `[a_0 … a_{N−1}, b]`): its witness points on the decomposition's slice
/// ([`Decomposition::slices`]) followed as the slice moves, with `N − d` random combinations
/// of the equations (the component is a reduced component of their solution set). A path that
/// fails leaves its point out. Used to find real points of a component on real slices.
///
/// # Errors
/// [`DecomposeError::Family`] if the slice does not have `d` rows of `N + 1` numbers, or the
/// component is of dimension 0 or has no slice in `decomposition`.
pub fn points_on_slice(
    system: &System,
    decomposition: &Decomposition,
    component: &Component,
    slice: &[Vec<C64>],
    settings: &DecomposeSettings,
) -> Result<Vec<Vec<C64>>, DecomposeError> {
    let (d, big_n) = (component.dimension, system.nvars());
    let base = decomposition
        .slices
        .get(d)
        .filter(|s| d > 0 && s.len() == d)
        .ok_or_else(|| DecomposeError::Family(format!("no slice of dimension {d}")))?;
    if slice.len() != d || slice.iter().any(|row| row.len() != big_n + 1) {
        return Err(DecomposeError::Family(format!(
            "a slice of dimension {d} has {d} rows of {} numbers",
            big_n + 1
        )));
    }
    let mut rng = ChaCha8Rng::seed_from_u64(settings.seed ^ 0x5eed);
    let family = slice_family(system, d, &mut rng)?;
    let ends = track_parameters(
        &family,
        &base.concat(),
        &slice.concat(),
        &component.witness_points,
        settings.solve.tracker,
    )
    .map_err(|e| DecomposeError::Family(e.to_string()))?;
    Ok(ends.into_iter().flatten().collect())
}
