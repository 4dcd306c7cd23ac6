//! The polyhedral homotopy's first stage (Huber & Sturmfels, *A polyhedral method for solving
//! sparse polynomial systems*, Math. Comp. 64, 1995; Verschelde, Verlinden & Cools, *Homotopies
//! exploiting Newton polytopes for solving sparse polynomial systems*, SIAM J. Numer. Anal. 31,
//! 1994): the roots of a start system `G` with the target's supports (and the origin) and random
//! coefficients, one path per unit of mixed volume.
//!
//! For a mixed cell with edges `{p_i, q_i}` and inner normal `α` of the lifting `ω`, the
//! substitution `x = y · t^α` and division of equation `i` by its least power of `t` give
//! `h_i(y, t) = Σ_{a ∈ A_i} c_a y^a t^{e_a}`, `e_a = ⟨a, α⟩ + ω(a) − min ≥ 0`, zero exactly at
//! `p_i` and `q_i`: at `t = 0` the binomial system `c_p y^p + c_q y^q = 0`, whose `|det(q − p)|`
//! roots ([`crate::polyhedral::binomial_roots`]) start the paths, and at `t = 1` the system `G`
//! itself (`x = y`). Paths are tracked in `s = log t` from `s_0` to 0 (with the exponents
//! scaled so that the least positive one is 1, and `e^{s_0}` = 10⁻¹² so that the start is the
//! binomial root to that accuracy, then refined by Newton's method).
//!
//! The second stage, from `G` to the target along the γ-trick homotopy, is
//! [`super::start::ProjectiveHomotopy::from_start_system`]: `G`'s coefficients are generic, so
//! for generic γ its `MV` roots continue to every isolated root of the target in `ℂⁿ`
//! (coefficient-parameter continuation: Morgan & Sommese 1989; Li's survey, §4.4).

use super::C64;
use super::tracker::{Homotopy, PathFailure, Tracker, TrackerSettings};
use crate::poly::{Poly, System};
use crate::polyhedral::{MixedCell, MixedSubdivision, binomial_roots};
use nalgebra::{DMatrix, DVector};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// `log t` at the start of every cell's path, with the least positive exponent scaled to 1:
/// the terms off the cell weigh `e^{S0}` ≈ 10⁻¹² there.
const S0: f64 = -27.631_021_115_928_547;

/// The start system of the second stage, and how to find its roots: each path's cell and
/// binomial root, followed along the cell's homotopy on demand ([`Self::root`]), so that a
/// shard of the solve follows only its own paths.
pub(crate) struct PolyhedralStart {
    /// `G`: the target's supports (with the origin) and random coefficients on the unit
    /// circle.
    pub system: System,
    cells: Vec<CellHomotopy>,
    /// Per path (one per unit of mixed volume, cell by cell): its cell and binomial root, or
    /// why it has none.
    starts: Vec<(usize, Result<Vec<C64>, PathFailure>)>,
    settings: TrackerSettings,
}

impl PolyhedralStart {
    /// The number of paths: the mixed volume.
    pub(crate) fn paths(&self) -> usize {
        self.starts.len()
    }

    /// `G`'s root of path `k`: its cell's homotopy followed from the binomial root, with
    /// stricter steps twice if need be; the failure of a path that could not be followed.
    pub(crate) fn root(&self, k: usize) -> Result<Vec<C64>, PathFailure> {
        let (cell, start) = &self.starts[k];
        let y = start.as_ref().map_err(|f| *f)?;
        let stricter = self.settings.stricter();
        let cell = &self.cells[*cell];
        cell.follow(y, self.settings)
            .or_else(|_| cell.follow(y, stricter))
            .or_else(|_| cell.follow(y, stricter.stricter()))
    }
}

/// The first stage: `G` for `subdivision` (the mixed cells of `system`'s supports with the
/// origin, [`crate::polyhedral::supports_of`]), its cells' homotopies and binomial roots in
/// cell order; the roots of `G` are followed path by path ([`PolyhedralStart::root`]).
pub(crate) fn polyhedral_start(
    system: &System,
    subdivision: &MixedSubdivision,
    rng: &mut ChaCha8Rng,
    settings: TrackerSettings,
) -> PolyhedralStart {
    let n = system.nvars();
    let coefficients: Vec<Vec<C64>> = subdivision
        .supports
        .iter()
        .map(|s| {
            s.iter()
                .map(|_| C64::from_polar(1.0, rng.random_range(0.0..std::f64::consts::TAU)))
                .collect()
        })
        .collect();
    let start_system = System::new(
        system.variables().to_vec(),
        subdivision
            .supports
            .iter()
            .zip(&coefficients)
            .map(|(support, c)| {
                Poly::from_terms(n, support.iter().zip(c).map(|(a, ci)| (exponents(a), *ci)))
            })
            .collect(),
    )
    .expect("the target's variables and as many equations");
    let cells: Vec<CellHomotopy> = subdivision
        .cells
        .iter()
        .map(|cell| CellHomotopy::new(subdivision, &coefficients, cell))
        .collect();
    let starts: Vec<(usize, Result<Vec<C64>, PathFailure>)> = cells
        .iter()
        .enumerate()
        .flat_map(|(k, h)| match h.binomial_start() {
            Ok(roots) => roots.into_iter().map(|r| (k, Ok(r))).collect::<Vec<_>>(),
            // Only a cell beyond the path limit has too many roots to list, and the path count
            // refuses such a system before this stage.
            Err(_) => (0..h.volume.min(crate::polyhedral::MAX_BINOMIAL_SOLUTIONS))
                .map(|_| (k, Err(PathFailure::NotFinite)))
                .collect(),
        })
        .collect();
    PolyhedralStart {
        system: start_system,
        cells,
        starts,
        settings,
    }
}

fn exponents(a: &[i64]) -> Vec<u32> {
    a.iter()
        .map(|k| u32::try_from(*k).expect("a polynomial's exponents"))
        .collect()
}

/// The homotopy of one mixed cell, in `τ ∈ [0, 1]` with `log t = S0 · τ`: `τ = 1` the binomial
/// start, `τ = 0` the start system `G` (the tracker's target).
struct CellHomotopy {
    n: usize,
    /// Per equation, its terms: exponent vector, coefficient, scaled exponent of `t`.
    equations: Vec<Vec<(Vec<u32>, C64, f64)>>,
    /// The binomial system: per equation the exponent row `q − p` and `−c_p / c_q`.
    binomial: (Vec<Vec<i64>>, Vec<C64>),
    volume: u128,
}

impl CellHomotopy {
    fn new(subdivision: &MixedSubdivision, coefficients: &[Vec<C64>], cell: &MixedCell) -> Self {
        let alpha = &cell.normal;
        let mut equations: Vec<Vec<(Vec<u32>, C64, f64)>> = Vec::new();
        let mut rows = Vec::new();
        let mut beta = Vec::new();
        for (i, (support, &(p, q))) in subdivision.supports.iter().zip(&cell.edges).enumerate() {
            let lift = &subdivision.lifting[i];
            let value = |c: usize| -> f64 {
                support[c]
                    .iter()
                    .zip(alpha)
                    .map(|(a, x)| *a as f64 * x)
                    .sum::<f64>()
                    + lift[c]
            };
            let least = value(p);
            equations.push(
                support
                    .iter()
                    .enumerate()
                    .map(|(c, a)| {
                        let e = if c == p || c == q {
                            0.0
                        } else {
                            (value(c) - least).max(0.0)
                        };
                        (exponents(a), coefficients[i][c], e)
                    })
                    .collect(),
            );
            rows.push(
                support[q]
                    .iter()
                    .zip(&support[p])
                    .map(|(b, a)| b - a)
                    .collect(),
            );
            beta.push(-coefficients[i][p] / coefficients[i][q]);
        }
        let smallest = equations
            .iter()
            .flatten()
            .map(|t| t.2)
            .filter(|e| *e > 0.0)
            .fold(f64::INFINITY, f64::min);
        if smallest.is_finite() {
            for t in equations.iter_mut().flatten() {
                t.2 /= smallest;
            }
        }
        Self {
            n: subdivision.supports.len(),
            equations,
            binomial: (rows, beta),
            volume: cell.volume,
        }
    }

    /// The binomial system's roots: the paths' starts at `τ = 1`.
    fn binomial_start(&self) -> Result<Vec<Vec<C64>>, crate::polyhedral::BinomialError> {
        binomial_roots(&self.binomial.0, &self.binomial.1)
    }

    /// From a binomial root to a root of `G`: Newton's method at `τ = 1`, the path to `τ = 0`,
    /// Newton's method there.
    fn follow(&self, y: &[C64], settings: TrackerSettings) -> Result<Vec<C64>, PathFailure> {
        let mut tracker = Tracker::new(self, settings);
        let mut z = DVector::from_column_slice(y);
        tracker.refine(&mut z, C64::from(1.0), 1e-12);
        tracker.track_refined(z)
    }
}

impl Homotopy for CellHomotopy {
    type Workspace = Vec<Vec<C64>>;

    fn dim(&self) -> usize {
        self.n
    }

    fn workspace(&self) -> Vec<Vec<C64>> {
        let mut highest = vec![0u32; self.n];
        for (a, _, _) in self.equations.iter().flatten() {
            for (h, k) in highest.iter_mut().zip(a) {
                *h = (*h).max(*k);
            }
        }
        highest
            .iter()
            .map(|h| vec![C64::from(1.0); *h as usize + 1])
            .collect()
    }

    fn evaluate(
        &self,
        z: &DVector<C64>,
        t: C64,
        powers: &mut Vec<Vec<C64>>,
        h: &mut DVector<C64>,
        hz: &mut DMatrix<C64>,
        ht: &mut DVector<C64>,
    ) {
        for (j, p) in powers.iter_mut().enumerate() {
            for k in 1..p.len() {
                p[k] = p[k - 1] * z[j];
            }
        }
        h.fill(C64::from(0.0));
        ht.fill(C64::from(0.0));
        hz.fill(C64::from(0.0));
        let s = t * S0;
        for (i, terms) in self.equations.iter().enumerate() {
            for (a, c, e) in terms {
                let w = if *e == 0.0 { *c } else { c * (s * *e).exp() };
                let m: C64 = a
                    .iter()
                    .enumerate()
                    .map(|(j, k)| powers[j][*k as usize])
                    .product();
                h[i] += w * m;
                ht[i] += w * m * (S0 * *e);
                for (j, k) in a.iter().enumerate() {
                    if *k == 0 {
                        continue;
                    }
                    // ∂(y^a)/∂y_j = a_j y^a / y_j on the torus, where the paths stay; the
                    // product without y_j's factor near a zero coordinate.
                    let partial = if z[j].norm() > 1e-100 {
                        m * f64::from(*k) / z[j]
                    } else {
                        a.iter()
                            .enumerate()
                            .map(|(l, kl)| {
                                if l == j {
                                    powers[l][*kl as usize - 1] * f64::from(*kl)
                                } else {
                                    powers[l][*kl as usize]
                                }
                            })
                            .product()
                    };
                    hz[(i, j)] += w * partial;
                }
            }
        }
    }

    fn inverse_condition(&self, z: &DVector<C64>, ws: &mut Vec<Vec<C64>>) -> f64 {
        let n = self.n;
        let mut h = DVector::zeros(n);
        let mut hz = DMatrix::zeros(n, n);
        let mut ht = DVector::zeros(n);
        self.evaluate(z, C64::from(0.0), ws, &mut h, &mut hz, &mut ht);
        super::scaled_inverse_condition(hz, &vec![1.0; n])
    }
}
