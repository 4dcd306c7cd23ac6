//! The cost of expanding products and powers of polynomials, known **before** they are
//! multiplied: an upper bound on the terms of the result and on the work of computing it.
//!
//! A product `a · b` has at most `|a| · |b|` terms (one per pair of terms) and at most as many
//! as there are monomials of its degree `d` in the `n` variables it involves, `C(n + d, n)`; it
//! costs `|a| · |b|` term products. [`Poly::pow`] multiplies by `p` again and again, so `p^k`
//! has at most `min(C(|p| + k − 1, k), C(n + k·deg p, n))` terms (a product of `k` of the
//! `|p|` terms, in any order, and a monomial of degree at most `k·deg p`) and costs the sum of
//! those bounds for `p^1 … p^(k−1)`, times `|p|`. `(x + y + z + 1)^50` has at most
//! `C(53, 3) = 23426` terms, exactly its count; `(x + 1)^65535` has 65536 and costs about
//! 2.1 · 10⁹ term products.
//!
//! The reader of Bertini files ([`super::bertini`]) refuses an expression whose terms would
//! exceed [`MAX_TERMS`], or whose work would exceed what is left of the file's
//! [`ExpansionBudget`], before it multiplies: no input expands without end.

use super::Poly;
use std::cell::Cell;

/// The most terms of a polynomial the readers form, at every step of an expression (sums
/// included). Every system of the repository has at most a few hundred terms per equation
/// (Katsura-10: 66, cyclic-7: 7, the 4-RUU's constraints with free inputs: under 300); a
/// polynomial of [`MAX_TERMS`] terms costs about a millisecond per evaluation of it and its
/// Jacobian (docs/limits.md, "Measured cost").
pub const MAX_TERMS: usize = 10_000;

/// The most memory, in 4-byte words, that the expansions of one file may write: each term
/// formed (a copy, a sum's term, a term product) costs its exponent vector (one word per
/// variable) and [`TERM_WORDS`] more for its coefficient and its place in the map. 2²⁶ words
/// are 256 MiB: about 3.9 million term products in a ring of one variable, 590 000 in one of
/// a hundred (docs/limits.md, "Measured cost").
pub const MAX_EXPANSION_WORDS: u64 = 1 << 26;

/// The words of a term beyond its exponents: the coefficient (4 words) and the bookkeeping of
/// the ordered map and the exponent vector's allocation (about 12).
pub const TERM_WORDS: u64 = 16;

/// Upper bounds on the result of a product or power and on the work of computing it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Estimate {
    /// At most this many terms (saturating at `u128::MAX`).
    pub terms: u128,
    /// At most this many term products (saturating at `u128::MAX`).
    pub work: u128,
}

/// The bounds of `a · b` (module documentation).
#[must_use]
pub fn product(a: &Poly, b: &Poly) -> Estimate {
    let pairs = (a.len() as u128).saturating_mul(b.len() as u128);
    let degree = u64::from(a.total_degree()) + u64::from(b.total_degree());
    let n = involved(&[a, b]);
    Estimate {
        terms: monomials_at_most(n, degree, pairs),
        work: pairs,
    }
}

/// The bounds of `p.pow(k)` (module documentation).
#[must_use]
pub fn power(p: &Poly, k: u32) -> Estimate {
    let m = p.len() as u128;
    if k == 0 {
        return Estimate { terms: 1, work: 0 };
    }
    if m == 0 {
        return Estimate { terms: 0, work: 0 };
    }
    let n = involved(&[p]);
    let d = u64::from(p.total_degree());
    // `multiset` is C(m + j − 1, j), the products of j of the m terms; `terms` the bound on
    // the terms of p^j. The first factor is a copy of p: m terms.
    let mut multiset = Some(m);
    let mut terms = m;
    let mut work = m;
    for j in 1..k {
        work = work.saturating_add(terms.saturating_mul(m));
        let j = u128::from(j);
        multiset = multiset
            .and_then(|c| c.checked_mul(m + j))
            .map(|c| c / (j + 1));
        let cap = multiset.unwrap_or(u128::MAX);
        terms = monomials_at_most(n, d * (u64::try_from(j).unwrap_or(u64::MAX) + 1), cap);
    }
    Estimate { terms, work }
}

/// `min(C(n + d, n), cap)`: the number of monomials of degree at most `d` in `n` variables, or
/// `cap` if that is fewer. The binomial is built as `C(N − r + i, i)` for `i = 1 … r`
/// (`N = n + d`, `r = min(n, d)`), which grows with `i`: it stops as soon as it passes `cap`,
/// so the cost is at most `min(n, d)` steps and usually one.
#[must_use]
pub fn monomials_at_most(n: u64, d: u64, cap: u128) -> u128 {
    let r = n.min(d);
    let big = u128::from(n) + u128::from(d);
    let mut c: u128 = 1;
    for i in 1..=u128::from(r) {
        // C(N − r + i, i) = C(N − r + i − 1, i − 1) · (N − r + i) / i, exactly.
        match c.checked_mul(big - u128::from(r) + i) {
            Some(x) => c = x / i,
            None => return cap,
        }
        if c >= cap {
            return cap;
        }
    }
    c.min(cap)
}

/// The number of variables that some term of the polynomials involves.
fn involved(polys: &[&Poly]) -> u64 {
    let nvars = polys.first().map_or(0, |p| p.nvars());
    let mut seen = vec![false; nvars];
    for p in polys {
        for (e, _) in p.terms() {
            for (s, k) in seen.iter_mut().zip(e) {
                *s |= *k > 0;
            }
        }
    }
    seen.iter().filter(|s| **s).count() as u64
}

/// What is left of the memory one file's expansions may write ([`MAX_EXPANSION_WORDS`]),
/// spent in term operations of a ring of `nvars` variables.
#[derive(Debug, Default)]
pub struct ExpansionBudget {
    spent: Cell<u64>,
}

impl ExpansionBudget {
    /// The words one term of a ring of `nvars` variables costs.
    #[must_use]
    pub fn words_per_term(nvars: usize) -> u64 {
        (nvars as u64).saturating_add(TERM_WORDS)
    }

    /// The term operations a whole file of `nvars` variables may take.
    #[must_use]
    pub fn total_terms(nvars: usize) -> u64 {
        MAX_EXPANSION_WORDS / Self::words_per_term(nvars)
    }

    /// The term operations still allowed in a ring of `nvars` variables.
    #[must_use]
    pub fn terms_left(&self, nvars: usize) -> u64 {
        MAX_EXPANSION_WORDS.saturating_sub(self.spent.get()) / Self::words_per_term(nvars)
    }

    /// Spends `work` term operations of a ring of `nvars` variables.
    ///
    /// # Errors
    /// The operations left, if `work` exceeds them (nothing is spent then).
    pub fn spend(&self, work: u128, nvars: usize) -> Result<(), u64> {
        let left = self.terms_left(nvars);
        if work > u128::from(left) {
            return Err(left);
        }
        let words = u64::try_from(work)
            .unwrap_or(u64::MAX)
            .saturating_mul(Self::words_per_term(nvars));
        self.spent.set(self.spent.get().saturating_add(words));
        Ok(())
    }
}
