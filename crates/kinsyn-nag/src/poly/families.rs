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
