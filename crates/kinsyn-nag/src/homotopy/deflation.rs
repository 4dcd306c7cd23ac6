//! Deflation of the singular witness points a decomposition could not place: the points of
//! **non-reduced components** (multiplicity above 1, where the Jacobian of `F` has rank below
//! the codimension at every point), which no path reaches as a regular endpoint, so that
//! monodromy and the trace test cannot move them.
//!
//! One step (Leykin, Verschelde & Zhao, *Newton's method with deflation for isolated
//! singularities of polynomial systems*, Theoret. Comput. Sci. 359, 2006; on components,
//! Hauenstein & Wampler, *Isosingular sets and deflation*, Found. Comput. Math. 13, 2013): at a
//! point `x` where the Jacobian `J(x)` of `F` (all its equations, `N` unknowns) has numerical
//! rank `R` (singular values above `RANK_TOLERANCE` of the largest, the gap reported), the
//! system
//!
//! `D(x, λ) = [F(x); J(x) B λ; h·λ − 1]`, `B` a random `N × (R + 1)` matrix, `h` a random row,
//!
//! has, over each point of the component where the rank is `R`, the one `λ` in the null space
//! of `J(x) B` with `h·λ = 1`: the component lifts to one of `D` of the same dimension and
//! degree (the slices cut `x` alone), of lower multiplicity. Steps repeat, up to
//! [`MAX_DEFLATIONS`], until Newton's method converges quadratically at the lifted points on
//! the sliced, randomised `D`. The lifted points are then an ordinary witness set, split by
//! monodromy and confirmed by the trace test like any other; the component is reported with
//! its multiplicity: the paths that ended at each of its witness points (by dimension: the
//! multiplicity of the witness points in the randomised, sliced system, at least the
//! component's in `F`), at least 2 (regeneration merges its endpoints, so its count is a
//! lower bound).

use super::witness::{
    Component, DecomposeError, DecomposeSettings, PathBudget, SAME_POINT, Witness, gaussian,
    hyperplane, irreducible_pieces, membership, randomized, sliced_family,
};
use super::{C64, relative_distance};
use crate::poly::{Poly, System};
use nalgebra::DMatrix;
use rand_chacha::ChaCha8Rng;

/// Deflation steps tried at a point before it is left unresolved.
pub const MAX_DEFLATIONS: usize = 3;

/// A singular value below this fraction of the largest counts as zero in the rank of the
/// Jacobian at a singular endpoint (endpoints of the Cauchy endgame at a double component are
/// accurate to about 1e-8).
pub const RANK_TOLERANCE: f64 = 1e-6;

/// The outcome of [`deflate`] at one dimension.
pub(super) struct Deflated {
    /// The components found, each with its multiplicity.
    pub components: Vec<Component>,
    /// Their witness sets (for the membership tests of lower dimensions).
    pub witnesses: Vec<Witness>,
    /// The points still singular after [`MAX_DEFLATIONS`] steps, with their dimension.
    pub unresolved: Vec<(usize, Vec<C64>)>,
    /// Paths tracked.
    pub paths: usize,
    /// Points found, once refined, on a larger component.
    pub junk: usize,
}

/// A point of a non-reduced component and the paths that ended there.
pub(super) struct Suspect {
    pub x: Vec<C64>,
    pub paths: usize,
}

/// The Jacobian of all the equations of `system` at `x`.
fn jacobian_at(system: &System, x: &[C64]) -> DMatrix<C64> {
    let program = system.program();
    let (m, n) = (system.len(), system.nvars());
    let mut values = vec![C64::new(0.0, 0.0); m];
    let mut j = vec![C64::new(0.0, 0.0); m * n];
    program.evaluate_with_jacobian(x, &mut values, &mut j, &mut program.workspace());
    DMatrix::from_row_slice(m, n, &j)
}

/// The numerical rank of `j`: its singular values above [`RANK_TOLERANCE`] of the largest.
fn rank(j: &DMatrix<C64>) -> usize {
    let sv = j.clone().svd(false, false).singular_values;
    let largest = sv.iter().copied().fold(0.0, f64::max);
    sv.iter().filter(|s| **s > RANK_TOLERANCE * largest).count()
}

/// One deflation step of `system` for rank `r`: `D(x, λ) = [F; J B λ; h·λ − 1]` in the
/// unknowns of `system` then `λ_0 … λ_r` (named after `step`), with its `B` and `h`.
fn deflation_step(
    system: &System,
    r: usize,
    step: usize,
    rng: &mut ChaCha8Rng,
) -> Result<(System, DMatrix<C64>, Vec<C64>), DecomposeError> {
    let n = system.nvars();
    let total = n + r + 1;
    let b = DMatrix::from_fn(n, r + 1, |_, _| gaussian(rng));
    let h: Vec<C64> = (0..=r).map(|_| gaussian(rng)).collect();
    let identity: Vec<usize> = (0..n).collect();
    let wide: Vec<Poly> = system
        .equations()
        .iter()
        .map(|f| f.relabel(total, &identity))
        .collect();
    let lambda = |k: usize| Poly::variable(total, n + k);
    let mut equations = wide.clone();
    for f in &wide {
        let gradient: Vec<Poly> = (0..n).map(|j| f.derivative(j)).collect();
        let mut row = Poly::zero(total);
        for k in 0..=r {
            let column = gradient
                .iter()
                .enumerate()
                .fold(Poly::zero(total), |acc, (j, g)| &acc + &g.scale(b[(j, k)]));
            row = &row + &(&column * &lambda(k));
        }
        equations.push(row);
    }
    let normalisation = (0..=r).fold(Poly::real(total, -1.0), |acc, k| {
        &acc + &lambda(k).scale(h[k])
    });
    equations.push(normalisation);
    let mut names = system.variables().to_vec();
    names.extend((0..=r).map(|k| format!("deflation#{step}#{k}")));
    let deflated =
        System::new(names, equations).map_err(|e| DecomposeError::Family(e.to_string()))?;
    Ok((deflated, b, h))
}

/// The `λ` of a deflation step at `x`: the null vector of `J(x) B` with `h·λ = 1`.
fn multipliers(system: &System, x: &[C64], b: &DMatrix<C64>, h: &[C64]) -> Option<Vec<C64>> {
    let jb = jacobian_at(system, x) * b;
    // The right singular vector of the smallest singular value (rows padded so that the SVD's
    // Vᵀ is square).
    let cols = jb.ncols();
    let padded = if jb.nrows() < cols {
        jb.clone()
            .insert_rows(jb.nrows(), cols - jb.nrows(), C64::new(0.0, 0.0))
    } else {
        jb
    };
    let svd = padded.svd(false, true);
    let v_t = svd.v_t?;
    let smallest = svd
        .singular_values
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(b.1))?
        .0;
    let v: Vec<C64> = v_t.row(smallest).iter().map(C64::conj).collect();
    let scale: C64 = h.iter().zip(&v).map(|(a, b)| a * b).sum();
    (scale.norm() > 1e-12).then(|| v.iter().map(|c| c / scale).collect())
}

/// The sliced square system of `deflated` at dimension `d`: its random combinations
/// `combined` and the `d` hyperplanes `slice` of the first `n` unknowns.
fn sliced_square(combined: &System, slice: &[Vec<C64>]) -> Vec<Poly> {
    let total = combined.nvars();
    let mut square = combined.equations().to_vec();
    square.extend(slice.iter().map(|row| hyperplane(row, total)));
    square
}

/// Deflates the singular points `suspects` of dimension `d` of `system`, which lie on the
/// slice `slice` (`d` rows `[a_0 … a_{N−1}, b]`) and on no larger component: groups of points
/// of one rank sequence share a deflated system; their lifted points are split into
/// irreducible pieces, each a component with its multiplicity (the paths per witness point,
/// when the piece's points agree). A point found, once refined, on a larger component
/// (`larger`, every witness set of a larger dimension; the homotopy membership test) is junk.
pub(super) fn deflate(
    system: &System,
    d: usize,
    slice: &[Vec<C64>],
    suspects: Vec<Suspect>,
    larger: &[&Witness],
    (settings, budget): (&DecomposeSettings, &PathBudget),
    rng: &mut ChaCha8Rng,
) -> Result<Deflated, DecomposeError> {
    let n = system.nvars();
    let mut out = Deflated {
        components: Vec::new(),
        witnesses: Vec::new(),
        unresolved: Vec::new(),
        paths: 0,
        junk: 0,
    };
    let mut left = suspects;
    // Groups: the points whose ranks along the deflation steps agree share one deflated
    // system, built at the group's first point.
    while let Some(first) = left.first() {
        let (steps, ranks, found) = deflation_steps(system, &first.x, d, slice, rng)?;
        let Some(combined) = found else {
            let s = left.remove(0);
            out.unresolved.push((d, s.x));
            continue;
        };
        // Every point of the same rank sequence, lifted through the same steps; the first
        // point is settled in this round whatever happens, so that the rounds end.
        let mut members: Vec<(Vec<C64>, usize)> = Vec::new();
        let mut rest = Vec::new();
        for (k, s) in left.drain(..).enumerate() {
            let mut y = s.x.clone();
            let mut current = system;
            let mut ok = true;
            for ((next, b, h), r) in steps.iter().zip(&ranks) {
                if rank(&jacobian_at(current, &y)) != *r {
                    ok = false;
                    break;
                }
                if let Some(lambda) = multipliers(current, &y, b, h) {
                    y.extend(lambda);
                } else {
                    ok = false;
                    break;
                }
                current = next;
            }
            let square = sliced_square(&combined, slice);
            let refined = ok
                .then(|| super::regeneration::regular_root(&square, &y))
                .flatten();
            let Some(y) = refined else {
                if k == 0 {
                    out.unresolved.push((d, s.x));
                } else {
                    rest.push(s);
                }
                continue;
            };
            if members
                .iter()
                .any(|(p, _)| relative_distance(p, &y) <= SAME_POINT)
            {
                continue;
            }
            // The membership test again, at the point refined to full accuracy: a singular
            // point where components meet is accurate to the endgame's few digits only, and
            // may have passed the first test for that reason.
            // A test whose path to the point failed decides nothing: the point stays
            // unresolved rather than become a component.
            let (inside, paths) = membership(larger.iter().copied(), &y[..n], settings, budget)?;
            out.paths += paths;
            match inside {
                Some(true) => out.junk += 1,
                Some(false) => members.push((y, s.paths)),
                None => out.unresolved.push((d, s.x)),
            }
        }
        left = rest;
        if members.is_empty() {
            continue;
        }
        let family = sliced_family(&combined, n, d)?;
        let witness = Witness {
            family,
            base: slice.concat(),
            points: members.iter().map(|(y, _)| y.clone()).collect(),
            sliced: n,
        };
        let (pieces, paths) = if d == 0 {
            (
                (0..witness.points.len()).map(|i| (vec![i], true)).collect(),
                0,
            )
        } else {
            irreducible_pieces(&witness, settings, rng, budget)?
        };
        out.paths += paths;
        for (piece, passed) in pieces {
            let multiplicities: Vec<usize> = piece.iter().map(|i| members[*i].1).collect();
            // The paths that ended at each witness point: all the same unless some were lost,
            // when the least is a lower bound; and at least 2, since the points are singular
            // on no larger component (regeneration merges its endpoints and counts fewer).
            let multiplicity = multiplicities.iter().copied().min().unwrap_or(1).max(2);
            let points: Vec<Vec<C64>> = piece.iter().map(|i| members[*i].0[..n].to_vec()).collect();
            out.components.push(Component {
                dimension: d,
                degree: points.len(),
                sample_point: points[0].clone(),
                witness_points: points,
                trace_test_passed: passed,
                multiplicity,
            });
        }
        out.witnesses.push(witness);
    }
    Ok(out)
}

/// The deflation steps of `system` at `x` (a singular point of dimension `d` on `slice`): each
/// step's system, `B` and `h`, the ranks met, and the randomised last system when its
/// sliced square has a regular root at the lifted point (`None` after [`MAX_DEFLATIONS`]).
type Steps = (
    Vec<(System, DMatrix<C64>, Vec<C64>)>,
    Vec<usize>,
    Option<System>,
);

fn deflation_steps(
    system: &System,
    x: &[C64],
    d: usize,
    slice: &[Vec<C64>],
    rng: &mut ChaCha8Rng,
) -> Result<Steps, DecomposeError> {
    let mut current = system.clone();
    let mut lifted_first = x.to_vec();
    // Each step's system, `B` and `h`.
    let mut steps: Vec<(System, DMatrix<C64>, Vec<C64>)> = Vec::new();
    let mut ranks = Vec::new();
    for step in 0..MAX_DEFLATIONS {
        let r = rank(&jacobian_at(&current, &lifted_first));
        ranks.push(r);
        let (deflated, b, h) = deflation_step(&current, r, step, rng)?;
        let Some(lambda) = multipliers(&current, &lifted_first, &b, &h) else {
            break;
        };
        lifted_first.extend(lambda);
        let combined = randomized(&deflated, deflated.nvars() - d, rng);
        let square = sliced_square(&combined, slice);
        steps.push((deflated.clone(), b, h));
        if super::regeneration::regular_root(&square, &lifted_first).is_some() {
            return Ok((steps, ranks, Some(combined)));
        }
        current = deflated;
    }
    Ok((steps, ranks, None))
}
