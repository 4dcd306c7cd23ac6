//! Binomial systems `x^{v_i} = β_i` (`v_i` integer rows, `β_i ≠ 0`): the start systems of the
//! polyhedral homotopy, one per mixed cell. With `V M = H` lower triangular for a unimodular
//! `M` (a Hermite form by integer column operations), the substitution `x = y^M`
//! (`x_j = Π_k y_k^{M_jk}`) turns the system into the triangular `Π_{k ≤ i} y_k^{H_ik} = β_i`,
//! solved row by row by `H_ii`-th roots: `|det V| = Π H_ii` solutions, all in the torus (Li's
//! survey, §4.2; Huber & Sturmfels 1995, §3).

use crate::poly::C64;

/// Why a binomial system could not be solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum BinomialError {
    /// The exponent rows are linearly dependent: no isolated solution.
    #[error("the exponent matrix is singular")]
    Singular,
    /// An integer operation overflowed 128 bits.
    #[error("the Hermite form overflowed 128-bit integers")]
    Overflow,
    /// More solutions than fit in memory here.
    #[error("{0} solutions are too many for one binomial system")]
    TooMany(u128),
}

/// The most solutions of one binomial system (one mixed cell's volume) that are enumerated.
pub const MAX_BINOMIAL_SOLUTIONS: u128 = 1 << 24;

/// An integer matrix, row by row.
pub type IntegerMatrix = Vec<Vec<i128>>;

/// `(H, M)` with `V M = H` lower triangular with a positive diagonal and `M` unimodular, by
/// extended-gcd column operations.
///
/// # Errors
/// [`BinomialError::Singular`] for a singular `V`, [`BinomialError::Overflow`] past 128 bits.
pub fn hermite_lower(v: &[Vec<i64>]) -> Result<(IntegerMatrix, IntegerMatrix), BinomialError> {
    let n = v.len();
    let mut h: Vec<Vec<i128>> = v
        .iter()
        .map(|r| r.iter().map(|x| i128::from(*x)).collect())
        .collect();
    let mut m: Vec<Vec<i128>> = (0..n)
        .map(|r| (0..n).map(|c| i128::from(r == c)).collect())
        .collect();
    for r in 0..n {
        for c in r + 1..n {
            if h[r][c] == 0 {
                continue;
            }
            let (a, b) = (h[r][r], h[r][c]);
            let (g, x, y) = extended_gcd(a, b);
            let (ag, bg) = (a / g, b / g);
            // Columns r, c ← (x·col_r + y·col_c, −(b/g)·col_r + (a/g)·col_c): determinant 1.
            for mat in [&mut h, &mut m] {
                for row in mat.iter_mut() {
                    let (cr, cc) = (row[r], row[c]);
                    row[r] = combine(x, cr, y, cc)?;
                    row[c] = combine(-bg, cr, ag, cc)?;
                }
            }
        }
        if h[r][r] == 0 {
            return Err(BinomialError::Singular);
        }
        if h[r][r] < 0 {
            for mat in [&mut h, &mut m] {
                for row in mat.iter_mut() {
                    row[r] = -row[r];
                }
            }
        }
    }
    Ok((h, m))
}

fn combine(a: i128, x: i128, b: i128, y: i128) -> Result<i128, BinomialError> {
    a.checked_mul(x)
        .and_then(|p| b.checked_mul(y).and_then(|q| p.checked_add(q)))
        .ok_or(BinomialError::Overflow)
}

/// `(g, x, y)` with `a x + b y = g = gcd(a, b) > 0` (for `(a, b) ≠ (0, 0)`).
fn extended_gcd(a: i128, b: i128) -> (i128, i128, i128) {
    let (mut r0, mut r1) = (a, b);
    let (mut s0, mut s1) = (1i128, 0i128);
    let (mut t0, mut t1) = (0i128, 1i128);
    while r1 != 0 {
        let q = r0 / r1;
        (r0, r1) = (r1, r0 - q * r1);
        (s0, s1) = (s1, s0 - q * s1);
        (t0, t1) = (t1, t0 - q * t1);
    }
    if r0 < 0 {
        (-r0, -s0, -t0)
    } else {
        (r0, s0, t0)
    }
}

/// Every solution of `x^{v_i} = β_i`, `i = 1 … n`: `|det V|` points of the torus.
///
/// # Errors
/// [`BinomialError`] for a singular or overflowing exponent matrix, or more than
/// [`MAX_BINOMIAL_SOLUTIONS`] solutions.
pub fn binomial_roots(v: &[Vec<i64>], beta: &[C64]) -> Result<Vec<Vec<C64>>, BinomialError> {
    let n = v.len();
    let (h, m) = hermite_lower(v)?;
    let count = h
        .iter()
        .enumerate()
        .try_fold(1u128, |acc, (i, row)| {
            acc.checked_mul(u128::try_from(row[i]).ok()?)
        })
        .ok_or(BinomialError::Overflow)?;
    if count > MAX_BINOMIAL_SOLUTIONS {
        return Err(BinomialError::TooMany(count));
    }
    // Logarithms of the y's, row by row: H_ii log y_i = log β_i − Σ_{k<i} H_ik log y_k + 2πi j.
    let mut partial: Vec<Vec<C64>> = vec![Vec::new()];
    for i in 0..n {
        let hii = h[i][i] as f64;
        let mut next = Vec::with_capacity(partial.len() * usize::try_from(h[i][i]).unwrap_or(0));
        for logs in &partial {
            let mut rhs = beta[i].ln();
            for (k, lk) in logs.iter().enumerate() {
                rhs -= lk * (h[i][k] as f64);
            }
            for j in 0..h[i][i] {
                let root = (rhs + C64::new(0.0, std::f64::consts::TAU * j as f64)) / hii;
                let mut extended = logs.clone();
                extended.push(root);
                next.push(extended);
            }
        }
        partial = next;
    }
    Ok(partial
        .iter()
        .map(|logs| {
            (0..n)
                .map(|j| {
                    let log: C64 = (0..n).map(|k| logs[k] * (m[j][k] as f64)).sum();
                    log.exp()
                })
                .collect()
        })
        .collect())
}
