//! Standard benchmark systems of polynomial system solving, with their published root counts:
//! the test problems every solver (Bertini, `PHCpack`, `HomotopyContinuation.jl`) is measured on.

use super::{Poly, System};

fn names(prefix: &str, n: usize) -> Vec<String> {
    (0..n).map(|i| format!("{prefix}{i}")).collect()
}

/// Katsura-n (S. Katsura, *Spin glass problem by the method of integral equation of the effective
/// field*, 1990; the `PoSSo` test suite): `n + 1` unknowns `u_0 … u_n`, with `u_{−m} = u_m` and
/// `u_m = 0` for `|m| > n`, equations `Σ_l u_l u_{m−l} = u_m` for `m = 0 … n − 1` and
/// `u_0 + 2 Σ_{l ≥ 1} u_l = 1`. Its Bézout number is `2^n` and it has `2^n` solutions, all
/// regular.
///
/// # Panics
/// If `n` exceeds `i64::MAX` (no such system fits in memory).
#[must_use]
pub fn katsura(n: usize) -> System {
    let nv = n + 1;
    let u = |m: i64| -> Poly {
        let m = usize::try_from(m.unsigned_abs()).unwrap_or(usize::MAX);
        if m > n {
            Poly::zero(nv)
        } else {
            Poly::variable(nv, m)
        }
    };
    let n = i64::try_from(n).expect("a small n");
    let mut equations = Vec::new();
    for m in 0..n {
        let mut sum = Poly::zero(nv);
        for l in -n..=n {
            sum = sum + u(l) * u(m - l);
        }
        equations.push(sum - u(m));
    }
    let mut last = u(0) - Poly::real(nv, 1.0);
    for l in 1..=n {
        last = last + u(l) * 2.0;
    }
    equations.push(last);
    System::new(names("u", nv), equations).expect("well formed")
}

/// Cyclic-n (G. Björck & R. Fröberg, *A faster way to count the solutions of inhomogeneous
/// systems of algebraic equations, with applications to cyclic n-roots*, J. Symbolic Comput.
/// 12, 1991): `Σ_i Π_{j<k} x_{(i+j) mod n} = 0` for `k = 1 … n − 1` and `x_0 ⋯ x_{n−1} = 1`.
/// Bézout number `n!`; cyclic-5 has 70 solutions, cyclic-6 has 156, all regular.
///
/// # Panics
/// Never for `n ≥ 1`; for `n = 0` the system has no variables and no equations.
#[must_use]
pub fn cyclic(n: usize) -> System {
    let x: Vec<Poly> = (0..n).map(|i| Poly::variable(n, i)).collect();
    let mut equations = Vec::new();
    for k in 1..n {
        let mut sum = Poly::zero(n);
        for i in 0..n {
            sum = sum + (0..k).fold(Poly::real(n, 1.0), |p, j| p * &x[(i + j) % n]);
        }
        equations.push(sum);
    }
    let product = x.iter().fold(Poly::real(n, 1.0), |a, b| a * b);
    equations.push(product - Poly::real(n, 1.0));
    System::new(names("x", n), equations).expect("well formed")
}

/// Noon-n (V. W. Noonburg, *A neural network modeled by an adaptive Lotka–Volterra system*, SIAM
/// J. Appl. Math. 49, 1989; the `PoSSo` and `PHCpack` test suites): `x_i Σ_{j≠i} x_j² − 1.1 x_i + 1 = 0`
/// for `i = 1 … n`. Bézout number `3ⁿ`; it has `3ⁿ − 2n` isolated roots (21, 73, 233 for
/// `n` = 3, 4, 5), all regular.
///
/// # Panics
/// Never: the system is well formed by construction.
#[must_use]
pub fn noon(n: usize) -> System {
    let x: Vec<Poly> = (0..n).map(|i| Poly::variable(n, i)).collect();
    let equations = (0..n)
        .map(|i| {
            let squares = (0..n)
                .filter(|j| *j != i)
                .fold(Poly::zero(n), |s, j| s + &x[j] * &x[j]);
            &x[i] * &squares - x[i].clone() * 1.1 + Poly::real(n, 1.0)
        })
        .collect();
    System::new(names("x", n), equations).expect("well formed")
}

/// Eco-n (A. Morgan, *Solving Polynomial Systems Using Continuation for Engineering and
/// Scientific Problems*, 1987, the economics modelling problem; the `PoSSo` and `PHCpack` test
/// suites): `(x_k + Σ_{i=1}^{n−k−1} x_i x_{i+k}) x_n − k = 0` for `k = 1 … n − 1` and
/// `Σ_{i=1}^{n−1} x_i + 1 = 0`. It has `2^{n−2}` isolated roots (8, 16, 32 for `n` = 5, 6,
/// 7), all regular.
///
/// # Panics
/// For `n < 2` (the system needs a last variable and one more).
#[must_use]
pub fn eco(n: usize) -> System {
    assert!(n >= 2, "eco-n takes n ≥ 2");
    let x: Vec<Poly> = (0..n).map(|i| Poly::variable(n, i)).collect();
    let mut equations = Vec::new();
    for k in 1..n {
        // x_k (1-based) is x[k − 1].
        let mut inner = x[k - 1].clone();
        for i in 1..n.saturating_sub(k) {
            inner = inner + &x[i - 1] * &x[i + k - 1];
        }
        equations.push(inner * &x[n - 1] - Poly::real(n, k as f64));
    }
    let sum = (0..n - 1).fold(Poly::real(n, 1.0), |s, i| s + &x[i]);
    equations.push(sum);
    System::new(names("x", n), equations).expect("well formed")
}
