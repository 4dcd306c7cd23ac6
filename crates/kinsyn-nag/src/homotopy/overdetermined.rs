//! **Over-determined systems** — more equations than unknowns, as the position system of an
//! over-constrained mechanism (the 4-RUU of paper 004: eight leg equations, the Study quadric
//! and a chart in the eight Study parameters) — solved by the standard randomisation to a
//! square system (Sommese & Wampler, *The Numerical Solution of Systems of Polynomials Arising
//! in Engineering and Science*, 2005; Wampler & Sommese, Acta Numerica 20, 2011):
//! with the `N` equations sorted by decreasing degree, the square system is
//! `g_i = f_i + Σ_{j > n} λ_ij f_j` (`i ≤ n`, the `n` unknowns), so its degrees are the `n`
//! highest of the system's and its Bézout number the smallest a randomisation can have. By
//! Bertini's theorem, for generic `λ` every isolated solution of `f = 0` is an isolated solution
//! of `g = 0` of the same multiplicity (non-singular ones stay non-singular), but `g = 0` has
//! other solutions too: every endpoint is therefore checked against the **original** equations,
//! and only those that satisfy them are solutions of the system.
//!
//! The `λ` are real (standard normal, from the solve's seed), so a real system stays real and
//! its real solutions are found and certified real as for a square one; real choices are
//! generic with probability one as complex ones are (the real points are Zariski-dense).

use super::{HomotopyError, SolveReport, SolveSettings, solve_with_progress, witness};
use crate::poly::{C64, System};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The solve of an over-determined (or square) system through a square randomisation.
#[derive(Debug, Clone)]
pub struct OverdeterminedReport {
    /// The square system solved: the `n` equations of highest degree, each plus a random real
    /// combination of the others (the system itself when it is square).
    pub square: System,
    /// The solve of [`Self::square`].
    pub report: SolveReport,
    /// For each solution of [`Self::report`] (same order), whether it satisfies every equation
    /// of the original system ([`satisfying`]).
    pub satisfies: Vec<bool>,
}

impl OverdeterminedReport {
    /// The solutions of the original system: the square system's that satisfy every original
    /// equation.
    pub fn solutions(&self) -> impl Iterator<Item = &super::Solution> {
        self.report
            .solutions
            .iter()
            .zip(&self.satisfies)
            .filter(|(_, ok)| **ok)
            .map(|(s, _)| s)
    }

    /// How many of the square system's solutions the original equations refuse (introduced by
    /// the randomisation).
    #[must_use]
    pub fn spurious(&self) -> usize {
        self.satisfies.iter().filter(|ok| !**ok).count()
    }
}

/// The square randomisation of `system` (module documentation), its random coefficients drawn
/// from `seed`: the system itself when it is square.
///
/// # Errors
/// [`HomotopyError::NotSquare`] when it has fewer equations than unknowns (an
/// under-determined system has no isolated solutions: its components are
/// [`super::decompose`]'s).
///
/// # Panics
/// Never: the combinations are in the system's own variables.
pub fn square_randomisation(system: &System, seed: u64) -> Result<System, HomotopyError> {
    let (big_n, n) = (system.len(), system.nvars());
    if big_n < n {
        return Err(HomotopyError::NotSquare {
            equations: big_n,
            variables: n,
        });
    }
    if big_n == n {
        return Ok(system.clone());
    }
    let mut order: Vec<usize> = (0..big_n).collect();
    let degrees = system.degrees();
    // Stable: equal degrees keep their order.
    order.sort_by_key(|&i| std::cmp::Reverse(degrees[i]));
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x0dd5_eed5);
    let rows: Vec<Vec<C64>> = order[..n]
        .iter()
        .map(|&i| {
            let mut row = vec![C64::new(0.0, 0.0); big_n];
            row[i] = C64::new(1.0, 0.0);
            for &j in &order[n..] {
                let lambda: f64 = rng.sample(rand_distr::StandardNormal);
                row[j] = C64::new(lambda, 0.0);
            }
            row
        })
        .collect();
    Ok(system.combinations(&rows))
}

/// Whether `x` satisfies every equation of `system` to the relative `tolerance`: each
/// `|f(x)|` at most `tolerance` times the sum of the magnitudes of `f`'s terms at `x` (taken
/// `≥ 1`), zero to the precision with which `f(x)` can be computed.
#[must_use]
pub fn satisfies_all(system: &System, x: &[C64], tolerance: f64) -> bool {
    witness::satisfies(system, x, tolerance)
}

/// For each solution of `report` — a solve of a randomisation of `system` — whether it
/// satisfies every equation of `system` ([`satisfies_all`]): a regular one to the relative
/// tolerance `1e-8`, a singular one (known to fewer digits) to `1e-4`.
#[must_use]
pub fn satisfying(system: &System, report: &SolveReport) -> Vec<bool> {
    report
        .solutions
        .iter()
        .map(|s| {
            let tolerance = if s.regular { 1e-8 } else { 1e-4 };
            satisfies_all(system, &s.x, tolerance)
        })
        .collect()
}

/// Every isolated solution of `system`, square or over-determined: [`square_randomisation`]
/// seeded by `settings.seed`, solved by [`super::solve`] with `settings`, each endpoint checked
/// against the original equations ([`OverdeterminedReport::satisfies`]).
///
/// # Errors
/// As [`square_randomisation`] and [`super::solve`] (on the square system: its paths are
/// counted and refused past `settings.max_paths` before any is tracked).
pub fn solve_overdetermined(
    system: &System,
    settings: &SolveSettings,
) -> Result<OverdeterminedReport, HomotopyError> {
    let square = square_randomisation(system, settings.seed)?;
    let report = solve_with_progress(&square, settings, &|| {})?;
    let satisfies = satisfying(system, &report);
    Ok(OverdeterminedReport {
        square,
        report,
        satisfies,
    })
}
