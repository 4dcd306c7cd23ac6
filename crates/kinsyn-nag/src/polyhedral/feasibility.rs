//! Whether a small system of linear inequalities `⟨a_r, α⟩ ≥ b_r` in `α ∈ ℝⁿ` has a solution:
//! the linear programs of the mixed-cell enumeration (a few to a few tens of unknowns, tens to
//! hundreds of rows, solved by the hundred thousand).
//!
//! The dual simplex method on the inequality form (Chvátal, *Linear Programming*, 1983, ch. 10;
//! the form of Li's mixed-cell enumeration, where a basis is `n` tight constraints): a basis `B`
//! of `n` independent rows gives the point `α_B = A_B⁻¹ b_B` and the multipliers `y_B` of an
//! objective `c = A_Bᵀ y_B`. With `c` chosen as the sum of the first basis' rows, `y_B = 1 ≥ 0`
//! is dual feasible from the start, so no first phase is needed. Each step brings in the most
//! violated row `r` (writing `a_r = A_Bᵀ w`) and takes out the basis row of least `y_l / w_l`
//! over `w_l > 0`, which keeps the multipliers non-negative and raises the dual objective by
//! `θ (b_r − ⟨a_r, α_B⟩) > 0`; no `w_l > 0` means the dual is unbounded, a proof (Farkas) that
//! the inequalities have no solution. A point violating no row beyond the tolerance is a
//! solution.
//!
//! Rows that do not span `ℝⁿ` leave `α` free along their null space: that freedom is removed by
//! the equalities `⟨v, α⟩ = 0` for a basis `v` of the null space (an SVD), which changes nothing
//! about feasibility. Equalities are written as two inequalities.
//!
//! Only a proof prunes: after eight steps per row (cycling under degeneracy, in
//! principle) the answer is "feasible", and the enumeration's cells are decided by their own
//! exact test.

use nalgebra::{DMatrix, DVector};

/// Violations below this (relative to the row's size and the point's) count as satisfied.
const TOLERANCE: f64 = 1e-9;

/// The steps allowed per row before the method gives up and answers "feasible".
const MAX_STEPS_PER_ROW: usize = 8;

/// A constraint `⟨a, α⟩ ≥ b` (`equal`: `=`).
#[derive(Debug, Clone)]
pub struct Row {
    /// The row's coefficients.
    pub a: Vec<f64>,
    /// The right-hand side.
    pub b: f64,
    /// Whether the row is an equality.
    pub equal: bool,
}

/// Whether the rows have a common solution `α ∈ ℝⁿ` (module documentation); "true" where the
/// method cannot decide.
#[must_use]
pub fn feasible(n: usize, rows: &[Row]) -> bool {
    let mut all: Vec<(Vec<f64>, f64)> = Vec::with_capacity(2 * rows.len() + n);
    // Equalities first: they are the rows the first basis prefers.
    for r in rows.iter().filter(|r| r.equal) {
        all.push((r.a.clone(), r.b));
        all.push((r.a.iter().map(|x| -x).collect(), -r.b));
    }
    for r in rows.iter().filter(|r| !r.equal) {
        all.push((r.a.clone(), r.b));
    }
    for v in null_space(n, &all) {
        all.push((v.clone(), 0.0));
        all.push((v.iter().map(|x| -x).collect(), 0.0));
    }
    let Some(mut basis) = first_basis(n, &all) else {
        return true;
    };
    let mut y = DVector::from_element(n, 1.0);
    let steps = MAX_STEPS_PER_ROW * all.len().max(n);
    for _ in 0..steps {
        let a_b = DMatrix::from_fn(n, n, |i, j| all[basis[i]].0[j]);
        let b_b = DVector::from_fn(n, |i, _| all[basis[i]].1);
        let lu = a_b.clone().lu();
        let Some(alpha) = lu.solve(&b_b) else {
            return true;
        };
        let size = 1.0 + alpha.amax();
        // The most violated row.
        let mut worst = (usize::MAX, 0.0);
        for (k, (a, b)) in all.iter().enumerate() {
            let value: f64 = a.iter().zip(alpha.iter()).map(|(x, y)| x * y).sum();
            let scale = 1.0 + a.iter().map(|x| x.abs()).sum::<f64>() * size + b.abs();
            let violation = (b - value) / scale;
            if violation > TOLERANCE && violation > worst.1 {
                worst = (k, violation);
            }
        }
        if worst.0 == usize::MAX {
            return true;
        }
        let r = worst.0;
        let Some(w) = a_b
            .transpose()
            .lu()
            .solve(&DVector::from_column_slice(&all[r].0))
        else {
            return true;
        };
        let leaving = (0..n)
            .filter(|l| w[*l] > TOLERANCE * (1.0 + w.amax()))
            .min_by(|&l, &m| (y[l] / w[l]).total_cmp(&(y[m] / w[m])));
        let Some(l) = leaving else {
            return false;
        };
        let theta = y[l] / w[l];
        for i in 0..n {
            y[i] = (y[i] - theta * w[i]).max(0.0);
        }
        y[l] = theta;
        basis[l] = r;
    }
    true
}

/// A basis of the null space of the rows (empty when they span `ℝⁿ`).
fn null_space(n: usize, rows: &[(Vec<f64>, f64)]) -> Vec<Vec<f64>> {
    if rows.is_empty() {
        return (0..n)
            .map(|j| (0..n).map(|i| f64::from(u8::from(i == j))).collect())
            .collect();
    }
    let m = DMatrix::from_fn(rows.len(), n, |i, j| rows[i].0[j]);
    // Rank by elimination first: the SVD only where the rows are deficient.
    if rank(&m) == n {
        return Vec::new();
    }
    let gram = m.transpose() * &m;
    let eigen = gram.symmetric_eigen();
    let largest = eigen.eigenvalues.amax().max(1.0);
    (0..n)
        .filter(|k| eigen.eigenvalues[*k] <= 1e-10 * largest)
        .map(|k| eigen.eigenvectors.column(k).iter().copied().collect())
        .collect()
}

/// The rank of `m` by Gaussian elimination with partial pivoting.
fn rank(m: &DMatrix<f64>) -> usize {
    let mut m = m.clone();
    let (rows, cols) = m.shape();
    let scale = m.amax().max(1.0);
    let mut r = 0;
    for c in 0..cols {
        if r == rows {
            break;
        }
        let (p, value) = (r..rows)
            .map(|i| (i, m[(i, c)].abs()))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .expect("rows left");
        if value <= 1e-10 * scale {
            continue;
        }
        m.swap_rows(r, p);
        for i in r + 1..rows {
            let f = m[(i, c)] / m[(r, c)];
            if f != 0.0 {
                for j in c..cols {
                    m[(i, j)] -= f * m[(r, j)];
                }
            }
        }
        r += 1;
    }
    r
}

/// `n` linearly independent rows, taken greedily in order (equalities first), or `None`.
fn first_basis(n: usize, rows: &[(Vec<f64>, f64)]) -> Option<Vec<usize>> {
    // Incremental Gram–Schmidt: a row joins when its component off the chosen ones is large.
    let mut chosen: Vec<usize> = Vec::with_capacity(n);
    let mut orthonormal: Vec<Vec<f64>> = Vec::with_capacity(n);
    for (k, (a, _)) in rows.iter().enumerate() {
        if chosen.len() == n {
            break;
        }
        let norm = a.iter().map(|x| x * x).sum::<f64>().sqrt();
        if norm == 0.0 {
            continue;
        }
        let mut v = a.clone();
        for q in &orthonormal {
            let dot: f64 = v.iter().zip(q).map(|(x, y)| x * y).sum();
            for (vi, qi) in v.iter_mut().zip(q) {
                *vi -= dot * qi;
            }
        }
        let rest = v.iter().map(|x| x * x).sum::<f64>().sqrt();
        if rest > 1e-8 * norm {
            orthonormal.push(v.iter().map(|x| x / rest).collect());
            chosen.push(k);
        }
    }
    (chosen.len() == n).then_some(chosen)
}
