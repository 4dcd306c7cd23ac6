//! Numerical irreducible decomposition by **regeneration**: the equations are brought in one at
//! a time, and the witness sets of `V(f1, …, fm)` are carried from each to the next
//! (Hauenstein, Sommese & Wampler, *Regenerative cascade homotopies for solving polynomial
//! systems*, Appl. Math. Comput. 218, 2011; *Regeneration homotopies for solving systems of
//! polynomials*, Math. Comp. 80, 2011).
//!
//! All slices are taken from one flag of random complex hyperplanes `L1, …, LN`: a component
//! of dimension `d` is known by its points on `L1 ∩ … ∩ Ld`, so witness sets of the same
//! dimension found along different branches are directly comparable. Starting from `ℂᴺ` (one
//! point, `L1 ∩ … ∩ LN`), for each equation `f` of degree `e` and each witness set `W` of
//! dimension `k` (its points on `Z ∩ L1 … Lk`, `Z` a union of components of
//! `V(f1, …, fm−1)` cut out with multiplicity one by its **active** equations `A`, `N − k` of
//! them):
//! 1. the points where `f` vanishes lie on components of `Z` inside `V(f)`: they stay, with the
//!    same dimension and active equations;
//! 2. the others **regenerate**: the last hyperplane `Lk` is moved to each of `e` random
//!    hyperplanes `H1 … He` (the points of `Z ∩ L1 … Lk−1 ∩ Hj`), then the `e·deg W` points are
//!    followed by `(1 − s) f + s γ H1⋯He = 0` (with `A` and `L1 … Lk−1`) from `s = 1` to `0`.
//!    Every component of `Z ∩ V(f)` has dimension `k − 1`, and its points on `L1 … Lk−1` are
//!    the regular finite endpoints; they form a witness set of dimension `k − 1` with active
//!    equations `A ∪ {f}`. Singular endpoints lie on a component of `Z ∩ V(f)` inside another
//!    component of `V(A, f)` or on a non-reduced one: they are put to the homotopy membership
//!    test against the witness sets of larger dimension at that stage (junk when they pass;
//!    [`Decomposition::unresolved`] otherwise).
//!
//! At the end each witness set is split into irreducible components by monodromy and the
//! trace test ([`super::witness`]), and a component contained in a larger one (found through
//! another branch) is dropped by the membership test. The paths tracked are about
//! `Σ e · deg W` over the steps — the degrees of the intermediate solution sets, not the Bézout
//! number of the system: the 4-RUU's 12 unknowns and 10 quartic and quadratic equations take
//! a few thousand paths where a total-degree cascade would take hundreds of thousands.
//!
//! The equations are brought in by increasing degree, then number of terms (in the order given
//! among ties): short, low-degree equations first keep the intermediate sets small.

use super::deflation::{Suspect, deflate};
use super::nearby::PointList;
use super::parameter::{FamilyEnd, track_parameters, track_parameters_to_end};
use super::tracker::{PathFailure, TrackerSettings};
use super::witness::{
    Component, DecomposeError, DecomposeSettings, Decomposition, MEMBERSHIP_TOLERANCE, PathBudget,
    SAME_POINT, Witness, family, gaussian, hyperplane, irreducible_pieces, on_larger_component,
    random_combinations, satisfies, vanishes,
};
use super::{C64, relative_distance};
use crate::poly::{Poly, Program, System};
use nalgebra::{DMatrix, DVector};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// A witness set carried from one equation to the next: its points on `L1 ∩ … ∩ L_dim`, on a
/// union of components cut out by the active equations.
#[derive(Debug, Clone)]
struct Branch {
    dim: usize,
    active: Vec<Poly>,
    points: Vec<Vec<C64>>,
}

/// What a progress report of [`regenerate_with_progress`] says.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RegenerationProgress {
    /// The equations brought in so far.
    pub equations: usize,
    /// Of the system.
    pub of: usize,
    /// Paths tracked so far.
    pub paths: usize,
}

/// The irreducible decomposition of `V(system)` by regeneration (module documentation), with
/// the same settings and output as [`super::decompose`] — except that
/// [`Decomposition::unresolved`] holds the singular endpoints of every step that no set
/// contained and no rescue made regular, with the dimension they had at that step: points of a
/// non-reduced set of the first equations, which may satisfy only those (the components inside
/// such a set are not followed).
///
/// # Errors
/// [`DecomposeError`] for a system without equations or unknowns, too large, with a zero
/// equation, or needing more paths than [`DecomposeSettings::max_paths`]
/// ([`regeneration_paths`]; the limit is checked before any path is tracked, and again as
/// paths are tracked).
pub fn regenerate(
    system: &System,
    settings: &DecomposeSettings,
) -> Result<Decomposition, DecomposeError> {
    regenerate_with_progress(system, settings, &mut |_| {})
}

/// The paths of the regeneration steps of [`regenerate`], from the degrees alone. The
/// equations are brought in by increasing degree `e_1 ≤ e_2 ≤ …`; before step `m` the witness
/// points of all dimensions are points of distinct components of `V(f_1 … f_{m−1})`, at most
/// `Π_{i<m} e_i` of them (the refined Bézout theorem: the degrees of the components of `m − 1`
/// hypersurfaces sum to at most the product of theirs), and each is followed along `e_m` paths
/// twice (the moving hyperplane, then the homotopy to `f_m`). So at most
/// `Σ_m 2 Π_{i≤m} e_i` paths. Saturates at `u128::MAX`.
///
/// The 4-RUU at fixed inputs (ten quadrics): `2 (2 + 4 + … + 2¹⁰) = 4092`. Retried paths,
/// monodromy loops, trace and membership tests track more, in proportion to the witness points
/// found, within [`DecomposeSettings::max_paths`] in all.
#[must_use]
pub fn regeneration_paths(system: &System) -> u128 {
    let mut degrees = system.degrees();
    degrees.sort_unstable();
    let mut points: u128 = 1;
    let mut paths: u128 = 0;
    for e in degrees {
        points = points.saturating_mul(u128::from(e));
        paths = paths.saturating_add(points.saturating_mul(2));
    }
    paths
}

/// [`regenerate`], reporting after each equation.
///
/// # Errors
/// As [`regenerate`].
pub fn regenerate_with_progress(
    system: &System,
    settings: &DecomposeSettings,
    progress: &mut dyn FnMut(RegenerationProgress),
) -> Result<Decomposition, DecomposeError> {
    let clock = std::time::Instant::now();
    let estimated_paths = regeneration_paths(system);
    let budget = PathBudget::new(system, settings, estimated_paths)?;
    let (n, big_n) = (system.len(), system.nvars());
    let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
    let flag: Vec<Vec<C64>> = (0..big_n)
        .map(|_| (0..=big_n).map(|_| gaussian(&mut rng)).collect())
        .collect();
    let mut out = Decomposition {
        components: Vec::new(),
        slices: (0..=big_n).map(|d| flag[..d].to_vec()).collect(),
        unresolved: Vec::new(),
        junk: 0,
        paths: 0,
        estimated_paths,
        seconds: 0.0,
    };
    let mut branches = vec![Branch {
        dim: big_n,
        active: Vec::new(),
        points: vec![flag_point(&flag)?],
    }];
    // Lowest degree first, then fewest terms (stable): the intermediate sets stay small, and a
    // mechanism's Study quadric and normalisation (four terms each) cut before its legs, which
    // avoids singular endpoints on sets the normalisation excludes.
    let mut equations: Vec<Poly> = system.equations().to_vec();
    equations.sort_by_key(|f| (f.total_degree(), f.len()));
    let equations = &equations[..];
    for (m, f) in equations.iter().enumerate() {
        let mut next = Vec::new();
        let mut suspects = Vec::new();
        for branch in branches {
            let (on, off): (Vec<Vec<C64>>, Vec<Vec<C64>>) = branch
                .points
                .into_iter()
                .partition(|x| vanishes(f, x, settings.residual_tolerance));
            if !on.is_empty() {
                next.push(Branch {
                    dim: branch.dim,
                    active: branch.active.clone(),
                    points: on,
                });
            }
            if off.is_empty() || branch.dim == 0 || f.total_degree() == 0 {
                continue;
            }
            let step = Step {
                system,
                active: &branch.active,
                f,
                dim: branch.dim,
                flag: &flag,
                settings,
                budget: &budget,
            };
            let (regular, singular, paths) = step.regenerate(&off, &mut rng)?;
            out.paths += paths;
            let mut active = branch.active.clone();
            active.push(f.clone());
            suspects.extend(singular.into_iter().map(|x| (branch.dim - 1, x)));
            if !regular.is_empty() {
                next.push(Branch {
                    dim: branch.dim - 1,
                    active,
                    points: regular,
                });
            }
        }
        let (junk, unresolved, paths) =
            sort_suspects(system, &next, suspects, &flag, settings, &budget)?;
        out.junk += junk;
        out.paths += paths;
        let (rescued, unresolved) = rescue(system, &equations[..=m], unresolved, &flag, &mut rng);
        next.extend(rescued);
        out.unresolved.extend(unresolved);
        branches = without_repeats(next);
        progress(RegenerationProgress {
            equations: m + 1,
            of: n,
            paths: out.paths,
        });
    }
    finish(
        system,
        branches,
        &flag,
        (settings, &budget),
        &mut rng,
        &mut out,
    )?;
    deflate_unresolved(system, &flag, (settings, &budget), &mut rng, &mut out)?;
    out.components
        .sort_by_key(|c| (std::cmp::Reverse(c.dimension), std::cmp::Reverse(c.degree)));
    out.seconds = clock.elapsed().as_secs_f64();
    Ok(out)
}

/// The singular points left unresolved that satisfy every equation, deflated dimension by
/// dimension from the top ([`super::deflation`]): the non-reduced components of `V(F)`, each
/// with the number of paths that ended at its witness points as its multiplicity. Points of
/// an intermediate step that a later equation does not vanish on stay unresolved.
fn deflate_unresolved(
    system: &System,
    flag: &[Vec<C64>],
    (settings, budget): (&DecomposeSettings, &PathBudget),
    rng: &mut ChaCha8Rng,
    out: &mut Decomposition,
) -> Result<(), DecomposeError> {
    let unresolved = std::mem::take(&mut out.unresolved);
    let mut dims: Vec<usize> = unresolved.iter().map(|(d, _)| *d).collect();
    dims.sort_unstable_by(|a, b| b.cmp(a));
    dims.dedup();
    let mut deflated: Vec<Witness> = Vec::new();
    for d in dims {
        let mut suspects: Vec<Suspect> = Vec::new();
        for (_, x) in unresolved.iter().filter(|(e, _)| *e == d) {
            if !satisfies(system, x, settings.residual_tolerance.sqrt()) {
                out.unresolved.push((d, x.clone()));
            } else if let Some(s) = suspects
                .iter_mut()
                .find(|s| relative_distance(&s.x, x) <= MEMBERSHIP_TOLERANCE)
            {
                s.paths += 1;
            } else {
                suspects.push(Suspect {
                    x: x.clone(),
                    paths: 1,
                });
            }
        }
        if suspects.is_empty() {
            continue;
        }
        // The larger deflated components; the branches' own were the first membership test.
        let larger: Vec<&Witness> = deflated.iter().collect();
        let found = deflate(
            system,
            d,
            &flag[..d],
            suspects,
            &larger,
            (settings, budget),
            rng,
        )?;
        out.paths += found.paths;
        out.junk += found.junk;
        out.components.extend(found.components);
        out.unresolved.extend(found.unresolved);
        deflated.extend(found.witnesses);
    }
    Ok(())
}

/// The last stage: each branch split into irreducible pieces, and pieces inside a larger
/// component dropped (junk), into `out`.
fn finish(
    system: &System,
    mut branches: Vec<Branch>,
    flag: &[Vec<C64>],
    (settings, budget): (&DecomposeSettings, &PathBudget),
    rng: &mut ChaCha8Rng,
    out: &mut Decomposition,
) -> Result<(), DecomposeError> {
    branches.sort_by_key(|b| std::cmp::Reverse(b.dim));
    let witnesses: Vec<Witness> = branches
        .iter()
        .map(|b| witness_of(system, b, flag))
        .collect::<Result<_, _>>()?;
    for (i, branch) in branches.iter().enumerate() {
        let witness = &witnesses[i];
        let (pieces, paths) = if branch.dim == 0 {
            (
                (0..branch.points.len()).map(|k| (vec![k], true)).collect(),
                0,
            )
        } else {
            irreducible_pieces(witness, settings, rng, budget)?
        };
        out.paths += paths;
        for (members, passed) in pieces {
            let points: Vec<Vec<C64>> = members.iter().map(|k| branch.points[*k].clone()).collect();
            let larger = branches
                .iter()
                .zip(&witnesses)
                .filter(|(b, _)| b.dim > branch.dim)
                .map(|(_, w)| w);
            let (inside, paths) = on_larger_component(larger, &points[0], settings, budget)?;
            out.paths += paths;
            if inside {
                out.junk += 1;
                continue;
            }
            out.components.push(Component {
                dimension: branch.dim,
                degree: points.len(),
                sample_point: points[0].clone(),
                witness_points: points,
                trace_test_passed: passed,
                multiplicity: 1,
            });
        }
    }
    Ok(())
}

/// The point of `L1 ∩ … ∩ LN`.
fn flag_point(flag: &[Vec<C64>]) -> Result<Vec<C64>, DecomposeError> {
    let big_n = flag.len();
    let a = DMatrix::from_fn(big_n, big_n, |i, j| flag[i][j]);
    let b = DVector::from_fn(big_n, |i, _| -flag[i][big_n]);
    a.lu()
        .solve(&b)
        .map(|x| x.iter().copied().collect())
        .ok_or_else(|| DecomposeError::Family("the random slices are dependent".into()))
}

/// The witness set of a branch: its active equations and its slice `L1 … L_dim` as parameters.
fn witness_of(system: &System, b: &Branch, flag: &[Vec<C64>]) -> Result<Witness, DecomposeError> {
    Ok(Witness {
        family: family(system, b.active.clone(), &[], b.dim, 0)?,
        base: flag[..b.dim].concat(),
        points: b.points.clone(),
        sliced: system.nvars(),
    })
}

/// One regeneration step: a witness set of dimension `dim` with active equations `active`
/// meets `V(equations[f])`.
struct Step<'a> {
    system: &'a System,
    active: &'a [Poly],
    f: &'a Poly,
    dim: usize,
    flag: &'a [Vec<C64>],
    settings: &'a DecomposeSettings,
    budget: &'a PathBudget,
}

impl Step<'_> {
    /// The regular endpoints (distinct), the singular ones, and the paths tracked.
    #[allow(clippy::type_complexity)]
    fn regenerate(
        &self,
        points: &[Vec<C64>],
        rng: &mut ChaCha8Rng,
    ) -> Result<(Vec<Vec<C64>>, Vec<Vec<C64>>, usize), DecomposeError> {
        let big_n = self.flag.len();
        let k = self.dim;
        let system = self.system;
        let active = self.active.to_vec();
        let fixed = &self.flag[..k - 1];
        let f = self.f;
        let degree = f.total_degree() as usize;
        let tracker = self.settings.solve.tracker;
        let mut paths = 0;
        // 1. The points of Z ∩ L1 … Lk−1 ∩ Hj, for e random hyperplanes Hj.
        let moving = family(system, active.clone(), fixed, 1, 0)?;
        let targets: Vec<Vec<C64>> = (0..degree)
            .map(|_| (0..=big_n).map(|_| gaussian(rng)).collect())
            .collect();
        let mut starts = Vec::new();
        for h in &targets {
            let (ends, tracked) = with_retry(points, tracker, self.budget, |xs, t| {
                track_parameters(&moving, &self.flag[k - 1], h, xs, t)
            })?;
            paths += tracked;
            starts.extend(ends);
        }
        // 2. (1 − s) f + s γ H1⋯He from s = 1 to 0, on Z ∩ L1 … Lk−1.
        let total = big_n + 1;
        let s = Poly::variable(total, big_n);
        let widen: Vec<usize> = (0..big_n).collect();
        let product = targets.iter().fold(Poly::real(total, 1.0), |acc, h| {
            &acc * &hyperplane(h, total)
        });
        let fw = f.relabel(total, &widen);
        let blend = &fw + &(&s * &(&product.scale(gaussian(rng)) - &fw));
        let mut equations = active;
        equations.push(blend);
        let regeneration = family(system, equations, fixed, 0, 1)?;
        let (ends, tracked) = with_retry(&starts, tracker, self.budget, |xs, t| {
            track_parameters_to_end(&regeneration, &[C64::from(1.0)], &[C64::from(0.0)], xs, t)
        })?;
        paths += tracked;
        let mut regular = PointList::default();
        let mut singular = PointList::default();
        for end in ends {
            match end {
                FamilyEnd::Regular(x) => {
                    regular.insert_new(x, SAME_POINT);
                }
                FamilyEnd::Singular(x) => {
                    // A multiple endpoint is reached by as many paths as its multiplicity.
                    singular.insert_new(x, MEMBERSHIP_TOLERANCE);
                }
                FamilyEnd::Infinite => {}
            }
        }
        Ok((regular.into_points(), singular.into_points(), paths))
    }
}

/// The ends of the paths from `starts` tracked by `track`, those that failed tracked once more
/// with stricter steps (the ends of the paths that fail twice are left out), and the number of
/// paths tracked.
fn with_retry<T>(
    starts: &[Vec<C64>],
    tracker: TrackerSettings,
    budget: &PathBudget,
    track: impl Fn(
        &[Vec<C64>],
        TrackerSettings,
    ) -> Result<Vec<Result<T, PathFailure>>, super::ParameterError>,
) -> Result<(Vec<T>, usize), DecomposeError> {
    let family = |e: super::ParameterError| DecomposeError::Family(e.to_string());
    budget.spend(starts.len())?;
    let first = track(starts, tracker).map_err(family)?;
    let failed: Vec<Vec<C64>> = starts
        .iter()
        .zip(&first)
        .filter(|(_, e)| e.is_err())
        .map(|(x, _)| x.clone())
        .collect();
    let mut ends: Vec<T> = first.into_iter().flatten().collect();
    if !failed.is_empty() {
        budget.spend(failed.len())?;
        ends.extend(
            track(&failed, tracker.stricter())
                .map_err(family)?
                .into_iter()
                .flatten(),
        );
    }
    Ok((ends, starts.len() + failed.len()))
}

/// The branches with every point kept once per dimension (the same component reached along
/// two branches has the same points on the flag's slice), empty branches dropped.
fn without_repeats(branches: Vec<Branch>) -> Vec<Branch> {
    let mut kept: Vec<Branch> = Vec::new();
    let mut seen: std::collections::BTreeMap<usize, PointList> = std::collections::BTreeMap::new();
    for mut b in branches {
        let earlier = seen.entry(b.dim).or_default();
        b.points.retain(|x| !earlier.contains(x, SAME_POINT));
        for x in &b.points {
            earlier.push(x.clone());
        }
        if !b.points.is_empty() {
            kept.push(b);
        }
    }
    kept
}

/// The singular endpoints of a step, each put to the membership test against the branches of
/// at least its dimension: the number on them (junk), the others, and the paths tracked.
#[allow(clippy::type_complexity)]
fn sort_suspects(
    system: &System,
    branches: &[Branch],
    suspects: Vec<(usize, Vec<C64>)>,
    flag: &[Vec<C64>],
    settings: &DecomposeSettings,
    budget: &PathBudget,
) -> Result<(usize, Vec<(usize, Vec<C64>)>, usize), DecomposeError> {
    if suspects.is_empty() {
        return Ok((0, Vec::new(), 0));
    }
    let witnesses: Vec<(usize, Witness)> = branches
        .iter()
        .map(|b| witness_of(system, b, flag).map(|w| (b.dim, w)))
        .collect::<Result<_, _>>()?;
    let (mut junk, mut paths) = (0, 0);
    let mut unresolved = Vec::new();
    for (dim, x) in suspects {
        let candidates = witnesses.iter().filter(|(d, _)| *d >= dim).map(|(_, w)| w);
        let (inside, p) = on_larger_component(candidates, &x, settings, budget)?;
        paths += p;
        if inside {
            junk += 1;
        } else {
            unresolved.push((dim, x));
        }
    }
    Ok((junk, unresolved, paths))
}

/// Singular endpoints that no branch contains may still be regular points of a component of
/// `V(f1 … fm)` that the step's own equations (the branch's active ones and `fm`) do not cut out
/// alone — a component of `Z ∩ V(fm)` lying inside a larger component of `V(A, fm)` that an
/// earlier equation outside `A` cuts down. Against `N − d` random combinations of all the
/// equations so far (and `L1 … Ld`) such a point is regular (Bertini's theorem): Newton
/// converges there on a well-conditioned Jacobian, and the point starts a branch whose active
/// equations are those combinations. What stays singular is returned (a non-reduced component).
fn rescue(
    system: &System,
    equations: &[Poly],
    suspects: Vec<(usize, Vec<C64>)>,
    flag: &[Vec<C64>],
    rng: &mut ChaCha8Rng,
) -> (Vec<Branch>, Vec<(usize, Vec<C64>)>) {
    let big_n = system.nvars();
    let mut branches: Vec<Branch> = Vec::new();
    let mut left = Vec::new();
    for (dim, x) in suspects {
        let index = if let Some(i) = branches.iter().position(|b| b.dim == dim) {
            i
        } else {
            let active = random_combinations(equations, big_n - dim, rng);
            branches.push(Branch {
                dim,
                active,
                points: Vec::new(),
            });
            branches.len() - 1
        };
        let b = &mut branches[index];
        let mut square = b.active.clone();
        square.extend(flag[..dim].iter().map(|row| hyperplane(row, big_n)));
        match regular_root(&square, &x) {
            Some(y) if equations.iter().all(|f| vanishes(f, &y, 1e-8)) => {
                if !b
                    .points
                    .iter()
                    .any(|p| relative_distance(p, &y) <= SAME_POINT)
                {
                    b.points.push(y);
                }
            }
            _ => left.push((dim, x)),
        }
    }
    branches.retain(|b| !b.points.is_empty());
    (branches, left)
}

/// The root of the square system `equations` that Newton's method reaches from `x`, if it
/// converges there quadratically on a well-conditioned Jacobian.
pub(super) fn regular_root(equations: &[Poly], x: &[C64]) -> Option<Vec<C64>> {
    let n = x.len();
    let system = System::new(
        (0..n).map(|j| format!("x{j}")).collect(),
        equations.to_vec(),
    )
    .ok()?;
    let program = system.program();
    let magnitudes = Program::new(
        &equations.iter().map(Poly::magnitudes).collect::<Vec<_>>(),
        n,
    );
    let mut ws = program.workspace();
    let mut magnitude_ws = magnitudes.workspace();
    let (mut values, mut jacobian) = (vec![C64::from(0.0); n], vec![C64::from(0.0); n * n]);
    let (mut sizes, mut size_jacobian) = (vec![C64::from(0.0); n], vec![C64::from(0.0); n * n]);
    let mut z = DVector::from_column_slice(x);
    let mut last = f64::INFINITY;
    for _ in 0..8 {
        program.evaluate_with_jacobian(z.as_slice(), &mut values, &mut jacobian, &mut ws);
        let j = DMatrix::from_row_slice(n, n, &jacobian);
        // Well-conditioned with each equation's row scaled by the size of its terms, as the
        // endpoints of the tracker ([`super::SINGULAR_TOLERANCE`]).
        let unit = z.iter().map(|c| c.norm()).fold(1.0, f64::max);
        let moduli = super::floored_moduli(z.as_slice(), unit);
        magnitudes.evaluate_with_jacobian(
            &moduli,
            &mut sizes,
            &mut size_jacobian,
            &mut magnitude_ws,
        );
        let scales: Vec<f64> = size_jacobian
            .chunks(n)
            .map(|row| {
                row.iter()
                    .map(nalgebra::Complex::norm_sqr)
                    .sum::<f64>()
                    .sqrt()
            })
            .collect();
        if super::scaled_inverse_condition(j.clone(), &scales) <= 1e-8 {
            return None;
        }
        let dz = j.lu().solve(&DVector::from_column_slice(&values))?;
        z -= &dz;
        let size = dz.norm() / (1.0 + z.norm());
        if size < 1e-13 || (size < 1e-9 && size < last * last * 1e3) {
            return Some(z.iter().copied().collect());
        }
        last = size;
    }
    None
}
