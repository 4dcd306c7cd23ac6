//! The mixed cells of a random lifting, by depth-first search over lower edges with linear
//! programs (the module documentation of [`super`]).

use super::feasibility::{Row, feasible};
use crate::poly::System;
use nalgebra::{DMatrix, DVector};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// How to enumerate mixed cells.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MixedCellSettings {
    /// The seed of the random lifting.
    pub seed: u64,
    /// The most linear programs the enumeration may solve before it gives up
    /// ([`MixedCellError::Budget`]): the cost bound. A program of more than 256 row entries
    /// (rows × unknowns) counts in proportion; the lower edges' programs, one per pair of points
    /// of a support, are counted before any is solved.
    pub max_linear_programs: usize,
}

impl Default for MixedCellSettings {
    fn default() -> Self {
        Self {
            seed: 1,
            max_linear_programs: DEFAULT_MAX_LINEAR_PROGRAMS,
        }
    }
}

/// The default budget of linear programs: about a minute of one core at worst (measured:
/// 5–60 µs each on the systems of the tests).
pub const DEFAULT_MAX_LINEAR_PROGRAMS: usize = 2_000_000;

/// A mixed cell: one edge of each lifted support with a common inner normal.
#[derive(Debug, Clone, PartialEq)]
pub struct MixedCell {
    /// For each equation, the indices in its support of the edge's two points `(p_i, q_i)`.
    pub edges: Vec<(usize, usize)>,
    /// The inner normal `α` (the lifting coordinate's component, 1, left out): the exponents of
    /// the torus substitution `x = y · t^α` that turns the lifted system into the cell's
    /// binomial system at `t = 0`.
    pub normal: Vec<f64>,
    /// `|det(q_i − p_i)|`: the cell's volume, its number of start solutions.
    pub volume: u128,
}

/// The mixed cells of a lifting: a fine mixed subdivision's cells of type `(2, …, 2)`.
#[derive(Debug, Clone, PartialEq)]
pub struct MixedSubdivision {
    /// The supports, per equation its points (exponent vectors).
    pub supports: Vec<Vec<Vec<i64>>>,
    /// The lifting of each support's points.
    pub lifting: Vec<Vec<f64>>,
    /// The mixed cells.
    pub cells: Vec<MixedCell>,
    /// The linear programs solved to find them.
    pub linear_programs: usize,
    /// The wall time of the enumeration, in seconds.
    pub seconds: f64,
}

impl MixedSubdivision {
    /// The mixed volume: the sum of the cells' volumes.
    #[must_use]
    pub fn mixed_volume(&self) -> u128 {
        self.cells
            .iter()
            .fold(0u128, |sum, c| sum.saturating_add(c.volume))
    }
}

/// Why the mixed cells could not be enumerated.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MixedCellError {
    /// Not as many supports as the dimension, or a point of the wrong dimension.
    #[error(
        "{supports} supports of points in {dimension} coordinates: a mixed volume takes as many supports as coordinates"
    )]
    Shape {
        /// The number of supports.
        supports: usize,
        /// The points' dimension.
        dimension: usize,
    },
    /// A cell's volume (an integer determinant) overflowed 128 bits.
    #[error("a mixed cell's volume overflows 128-bit integers")]
    Overflow,
    /// The enumeration needed more linear programs than allowed.
    #[error("the mixed-cell enumeration needs more than {limit} linear programs")]
    Budget {
        /// The limit ([`MixedCellSettings::max_linear_programs`]).
        limit: usize,
    },
}

/// The supports of `system`'s equations (its exponent vectors, equation by equation), with the
/// origin added to those that lack it when `with_origin` (then the mixed volume bounds the
/// isolated roots in `ℂⁿ`, not only in the torus: Li & Wang, *The BKK root count in ℂⁿ*, Math.
/// Comp. 65, 1996).
#[must_use]
pub fn supports_of(system: &System, with_origin: bool) -> Vec<Vec<Vec<i64>>> {
    let n = system.nvars();
    system
        .equations()
        .iter()
        .map(|p| {
            let mut points: Vec<Vec<i64>> = p
                .terms()
                .map(|(e, _)| e.iter().map(|k| i64::from(*k)).collect())
                .collect();
            if with_origin && !points.iter().any(|a| a.iter().all(|k| *k == 0)) {
                points.push(vec![0; n]);
            }
            points
        })
        .collect()
}

/// The mixed volume of `supports` (the number of isolated roots in the torus of a system with
/// these supports and generic coefficients), from the mixed cells of a random lifting.
///
/// # Errors
/// As [`mixed_cells`].
pub fn mixed_volume(
    supports: &[Vec<Vec<i64>>],
    settings: &MixedCellSettings,
) -> Result<u128, MixedCellError> {
    Ok(mixed_cells(supports, settings)?.mixed_volume())
}

/// The mixed cells of `supports` under a random lifting drawn from `settings.seed`.
///
/// # Errors
/// [`MixedCellError::Shape`] unless there are as many supports as coordinates;
/// [`MixedCellError::Budget`] when more than `settings.max_linear_programs` linear programs
/// would be needed.
pub fn mixed_cells(
    supports: &[Vec<Vec<i64>>],
    settings: &MixedCellSettings,
) -> Result<MixedSubdivision, MixedCellError> {
    let n = supports.len();
    if supports.iter().flatten().any(|a| a.len() != n) {
        return Err(MixedCellError::Shape {
            supports: n,
            dimension: supports
                .iter()
                .flatten()
                .map(Vec::len)
                .find(|d| *d != n)
                .unwrap_or(n),
        });
    }
    let clock = std::time::Instant::now();
    let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
    let lifting: Vec<Vec<f64>> = supports
        .iter()
        .map(|s| s.iter().map(|_| rng.random_range(0.0..1.0)).collect())
        .collect();
    let search = Search {
        supports,
        lifting: &lifting,
        n,
        programs: AtomicUsize::new(0),
        limit: settings.max_linear_programs,
    };
    let cells = search.run()?;
    let linear_programs = search.programs.load(Ordering::Relaxed);
    Ok(MixedSubdivision {
        supports: supports.to_vec(),
        lifting,
        cells,
        linear_programs,
        seconds: clock.elapsed().as_secs_f64(),
    })
}

/// An edge of support `support`: its points `p`, `q` (indices).
type Edge = (usize, usize, usize);

struct Search<'a> {
    supports: &'a [Vec<Vec<i64>>],
    lifting: &'a [Vec<f64>],
    n: usize,
    programs: AtomicUsize,
    limit: usize,
}

impl Search<'_> {
    fn run(&self) -> Result<Vec<MixedCell>, MixedCellError> {
        if self.n == 0 {
            return Ok(Vec::new());
        }
        // The lower edges of each lifted support: one program per pair of points, counted
        // against the budget before any is solved.
        let first: usize = self
            .supports
            .iter()
            .map(|s| {
                let m = s.len();
                (m * m.saturating_sub(1) / 2).saturating_mul(program_weight(m, self.n))
            })
            .fold(0usize, usize::saturating_add);
        if first > self.limit {
            return Err(MixedCellError::Budget { limit: self.limit });
        }
        let lower: Vec<Vec<Edge>> = (0..self.n)
            .map(|i| {
                let pairs: Vec<Edge> = (0..self.supports[i].len())
                    .flat_map(|p| (p + 1..self.supports[i].len()).map(move |q| (i, p, q)))
                    .collect();
                let keep = pairs
                    .par_iter()
                    .map(|e| self.feasible(&[*e]))
                    .collect::<Result<Vec<bool>, _>>()?;
                Ok(pairs
                    .into_iter()
                    .zip(keep)
                    .filter_map(|(e, k)| k.then_some(e))
                    .collect())
            })
            .collect::<Result<_, MixedCellError>>()?;
        if lower.iter().any(Vec::is_empty) {
            return Ok(Vec::new());
        }
        let first = (0..self.n)
            .min_by_key(|i| (lower[*i].len(), *i))
            .expect("at least one support");
        let compatible = self.compatibility(&lower)?;
        let tables = Tables {
            lower: &lower,
            compatible: &compatible,
        };
        let found = lower[first]
            .par_iter()
            .enumerate()
            .map(|(k, e)| {
                let mut cells = Vec::new();
                let mut chosen = vec![(*e, k)];
                self.extend(&tables, &mut chosen, &mut cells)?;
                Ok(cells)
            })
            .collect::<Result<Vec<Vec<MixedCell>>, MixedCellError>>()?;
        Ok(found.into_iter().flatten().collect())
    }

    /// For each pair of supports `(i, k)`, `i < k`, and each lower
    /// edge of `i`: the lower edges of `k` compatible with it (their two-support program is
    /// feasible).
    fn compatibility(
        &self,
        lower: &[Vec<Edge>],
    ) -> Result<Vec<Vec<Vec<Vec<bool>>>>, MixedCellError> {
        (0..self.n)
            .map(|i| {
                (0..self.n)
                    .map(|k| {
                        if k <= i {
                            return Ok(Vec::new());
                        }
                        lower[i]
                            .par_iter()
                            .map(|e| {
                                lower[k]
                                    .iter()
                                    .map(|f| self.feasible(&[*e, *f]))
                                    .collect::<Result<Vec<bool>, _>>()
                            })
                            .collect()
                    })
                    .collect()
            })
            .collect()
    }

    /// Extends the partial choice `chosen` (edge, its index among its support's lower edges),
    /// feasible, by each compatible lower edge of the support with the fewest.
    fn extend(
        &self,
        tables: &Tables<'_>,
        chosen: &mut Vec<(Edge, usize)>,
        cells: &mut Vec<MixedCell>,
    ) -> Result<(), MixedCellError> {
        if chosen.len() == self.n {
            if let Some(cell) = self.cell(chosen)? {
                cells.push(cell);
            }
            return Ok(());
        }
        // The support to extend by: the one with the fewest lower edges compatible with every
        // edge chosen (fail first); none left for some support ends this branch.
        let mut best: Option<(usize, Vec<usize>)> = None;
        for next in 0..self.n {
            if chosen.iter().any(|((i, _, _), _)| *i == next) {
                continue;
            }
            let candidates: Vec<usize> = (0..tables.lower[next].len())
                .filter(|k| {
                    chosen
                        .iter()
                        .all(|((i, _, _), e)| tables.compatible_pair(*i, *e, next, *k))
                })
                .collect();
            if candidates.is_empty() {
                return Ok(());
            }
            if best
                .as_ref()
                .is_none_or(|(_, b)| candidates.len() < b.len())
            {
                best = Some((next, candidates));
            }
        }
        let (next, candidates) = best.expect("a support not chosen yet");
        for k in candidates {
            let f = &tables.lower[next][k];
            chosen.push((*f, k));
            // Two supports are settled by the table; a complete choice by its cell's own check.
            let open = chosen.len() > 2 && chosen.len() < self.n;
            if !open || self.feasible(&chosen.iter().map(|(e, _)| *e).collect::<Vec<_>>())? {
                self.extend(tables, chosen, cells)?;
            }
            chosen.pop();
        }
        Ok(())
    }

    /// The cell of a complete feasible choice: its inner normal and volume (`None` for a
    /// degenerate choice of zero volume, or a choice whose edges are not all least).
    fn cell(&self, chosen: &[(Edge, usize)]) -> Result<Option<MixedCell>, MixedCellError> {
        let mut sorted: Vec<Edge> = chosen.iter().map(|(e, _)| *e).collect();
        sorted.sort_by_key(|e| e.0);
        let n = self.n;
        let rows: Vec<Vec<i64>> = sorted
            .iter()
            .map(|(i, p, q)| {
                (0..n)
                    .map(|j| self.supports[*i][*q][j] - self.supports[*i][*p][j])
                    .collect()
            })
            .collect();
        let volume = integer_determinant(&rows)
            .ok_or(MixedCellError::Overflow)?
            .unsigned_abs();
        if volume == 0 {
            return Ok(None);
        }
        let a = DMatrix::from_fn(n, n, |r, c| rows[r][c] as f64);
        let b = DVector::from_fn(n, |r, _| {
            let (i, p, q) = sorted[r];
            self.lifting[i][p] - self.lifting[i][q]
        });
        let Some(normal) = a.lu().solve(&b) else {
            return Ok(None);
        };
        // The cell's test, decided here by the inequalities themselves (the linear programs
        // only prune): each edge's points least over their support, up to rounding.
        let least = sorted.iter().all(|(i, p, _)| {
            let support = &self.supports[*i];
            let lift = &self.lifting[*i];
            let value = |c: usize| -> f64 {
                support[c]
                    .iter()
                    .zip(normal.iter())
                    .map(|(a, x)| *a as f64 * x)
                    .sum::<f64>()
                    + lift[c]
            };
            let minimum = value(*p);
            let scale = 1.0 + normal.iter().map(|x| x.abs()).sum::<f64>();
            (0..support.len()).all(|c| value(c) >= minimum - 1e-9 * scale)
        });
        if !least {
            return Ok(None);
        }
        Ok(Some(MixedCell {
            edges: sorted.iter().map(|(_, p, q)| (*p, *q)).collect(),
            normal: normal.iter().copied().collect(),
            volume,
        }))
    }

    /// Whether some `α` puts each edge's two lifted points at the minimum of `⟨(a, ω(a)), (α, 1)⟩`
    /// over its support.
    fn feasible(&self, edges: &[Edge]) -> Result<bool, MixedCellError> {
        let rows: usize = edges.iter().map(|(i, _, _)| self.supports[*i].len()).sum();
        let weight = program_weight(rows, self.n);
        let used = self.programs.fetch_add(weight, Ordering::Relaxed);
        if used.saturating_add(weight) > self.limit {
            return Err(MixedCellError::Budget { limit: self.limit });
        }
        let mut rows = Vec::new();
        for (i, p, q) in edges {
            let support = &self.supports[*i];
            let lift = &self.lifting[*i];
            let base = &support[*p];
            let row = |to: &[i64]| -> Vec<f64> {
                base.iter().zip(to).map(|(a, b)| (b - a) as f64).collect()
            };
            // ⟨q − p, α⟩ = ω(p) − ω(q)
            rows.push(Row {
                a: row(&support[*q]),
                b: lift[*p] - lift[*q],
                equal: true,
            });
            for (c, point) in support.iter().enumerate() {
                if c != *p && c != *q {
                    // ⟨c − p, α⟩ ≥ ω(p) − ω(c)
                    rows.push(Row {
                        a: row(point),
                        b: lift[*p] - lift[c],
                        equal: false,
                    });
                }
            }
        }
        // Only a proof of infeasibility prunes: an undecided program counts as feasible, and
        // the complete choices below it are decided by their own test.
        Ok(feasible(self.n, &rows))
    }
}

/// How many programs a linear program of `rows` rows in `n` unknowns counts against the budget:
/// 1 up to 256 row entries (the enumeration's usual size, 5–30 µs), then in proportion, as
/// its steps cost.
fn program_weight(rows: usize, n: usize) -> usize {
    (rows.saturating_mul(n)).div_ceil(256).max(1)
}

/// The search's fixed data: the lower edges and the compatibility table.
struct Tables<'a> {
    lower: &'a [Vec<Edge>],
    compatible: &'a [Vec<Vec<Vec<bool>>>],
}

impl Tables<'_> {
    /// Whether lower edge `e` of support `i` and lower edge `f` of support `k` are compatible.
    fn compatible_pair(&self, i: usize, e: usize, k: usize, f: usize) -> bool {
        if i < k {
            self.compatible[i][k][e][f]
        } else {
            self.compatible[k][i][f][e]
        }
    }
}

/// The determinant of a square integer matrix, exactly (Bareiss' fraction-free elimination);
/// `None` on overflow of 128 bits (0 for a singular matrix).
pub(crate) fn integer_determinant(rows: &[Vec<i64>]) -> Option<i128> {
    let n = rows.len();
    let mut m: Vec<Vec<i128>> = rows
        .iter()
        .map(|r| r.iter().map(|v| i128::from(*v)).collect())
        .collect();
    let mut sign = 1i128;
    let mut previous = 1i128;
    for k in 0..n {
        if m[k][k] == 0 {
            let Some(swap) = (k + 1..n).find(|r| m[*r][k] != 0) else {
                return Some(0);
            };
            m.swap(k, swap);
            sign = -sign;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let v = m[i][j]
                    .checked_mul(m[k][k])?
                    .checked_sub(m[i][k].checked_mul(m[k][j])?)?;
                m[i][j] = v / previous;
            }
            m[i][k] = 0;
        }
        previous = m[k][k];
    }
    if n == 0 {
        return Some(1);
    }
    Some(sign * m[n - 1][n - 1])
}
