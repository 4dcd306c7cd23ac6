//! A straight-line program for a polynomial system and its Jacobian: the monomials of the
//! equations and of their partial derivatives listed once, each a product of powers of the
//! variables, and every output a sum of coefficient × monomial. Evaluation walks these flat
//! lists into a reusable [`Workspace`] — no allocation per evaluation — over any [`Scalar`]:
//! complex numbers for path tracking, complex intervals for the certificates.

use super::{C64, Composition, Poly};
use std::collections::HashMap;
use std::ops::{Add, Mul, Neg, Sub};

/// The numbers a [`Program`] evaluates over: a commutative ring holding the complex
/// coefficients (exactly, or enclosing them).
pub trait Scalar:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Neg<Output = Self>
    + Send
    + Sync
{
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// A coefficient of the polynomials (an interval type returns an enclosure of it).
    fn coefficient(c: C64) -> Self;
}

impl Scalar for C64 {
    fn zero() -> Self {
        C64::new(0.0, 0.0)
    }
    fn one() -> Self {
        C64::new(1.0, 0.0)
    }
    fn coefficient(c: C64) -> Self {
        c
    }
}

/// The compiled form of a list of polynomials in one ring and of their Jacobian: flat, or
/// in two stages for a [`Composition`] (the inner polynomials and their Jacobian, then the
/// outer ones at those values, the Jacobian by the chain rule).
#[derive(Clone, Debug)]
pub struct Program {
    /// The polynomials (the inner ones of a composition).
    flat: Flat,
    /// A composition's outer stage.
    outer: Option<Box<Outer>>,
}

/// The outer stage of a composed [`Program`]: the outer polynomials in the leaf variables, and
/// for each the leaves it involves (the chain rule sums over those only).
#[derive(Clone, Debug)]
struct Outer {
    flat: Flat,
    leaves: Vec<Vec<usize>>,
}

/// A list of polynomials compiled flat.
#[derive(Clone, Debug)]
struct Flat {
    nvars: usize,
    len: usize,
    /// Offset of each variable's powers `x^0 … x^max` in the power table.
    power_offset: Vec<usize>,
    power_len: usize,
    /// Each monomial as a range of `factors` (indices into the power table).
    monomials: Vec<(usize, usize)>,
    factors: Vec<usize>,
    /// Coefficient and monomial of every term of every output.
    terms: Vec<(C64, usize)>,
    /// The outputs, each a range of `terms`: the equations, then the Jacobian row by row.
    outputs: Vec<(usize, usize)>,
}

/// The monomials of a [`Program`] by their non-zero exponents `(variable, exponent)`, in
/// increasing variable order.
#[derive(Default)]
struct MonomialIndex {
    index: HashMap<Vec<(u32, u32)>, usize>,
}

impl MonomialIndex {
    fn get_or_insert(&mut self, support: &[(u32, u32)], insert: impl FnOnce() -> usize) -> usize {
        if let Some(m) = self.index.get(support) {
            return *m;
        }
        let m = insert();
        self.index.insert(support.to_vec(), m);
        m
    }
}

/// Scratch space of a [`Program`] over one scalar type: the power table, the monomials and the
/// coefficients converted once (and a composition's intermediate values). Make one per thread
/// with [`Program::workspace`].
#[derive(Clone, Debug)]
pub struct Workspace<S> {
    flat: FlatWorkspace<S>,
    outer: Option<Box<OuterWorkspace<S>>>,
}

#[derive(Clone, Debug)]
struct OuterWorkspace<S> {
    flat: FlatWorkspace<S>,
    leaves: Vec<S>,
    leaf_jacobian: Vec<S>,
    outer_jacobian: Vec<S>,
}

#[derive(Clone, Debug)]
struct FlatWorkspace<S> {
    powers: Vec<S>,
    monomials: Vec<S>,
    coefficients: Vec<S>,
}

impl Program {
    /// Compiles `equations` (each a polynomial in `nvars` variables), flat: the monomials of
    /// the equations and of their partial derivatives listed once, each derivative taken term
    /// by term from the variables the term involves.
    ///
    /// # Panics
    /// If an equation's ring does not have `nvars` variables.
    #[must_use]
    pub fn new(equations: &[Poly], nvars: usize) -> Self {
        Self {
            flat: Flat::new(equations, nvars),
            outer: None,
        }
    }

    /// Compiles a composition in two stages: its inner polynomials, then its outer ones in the
    /// leaf variables.
    #[must_use]
    pub fn composed(composition: &Composition) -> Self {
        let m = composition.inner().len();
        let leaves = composition
            .outer()
            .iter()
            .map(|g| {
                (0..m)
                    .filter(|k| g.terms().any(|(e, _)| e[*k] > 0))
                    .collect()
            })
            .collect();
        Self {
            flat: Flat::new(composition.inner(), composition.nvars()),
            outer: Some(Box::new(Outer {
                flat: Flat::new(composition.outer(), m),
                leaves,
            })),
        }
    }

    /// The number of variables.
    #[must_use]
    pub fn nvars(&self) -> usize {
        self.flat.nvars
    }

    /// The number of equations.
    #[must_use]
    pub fn len(&self) -> usize {
        self.outer.as_ref().map_or(self.flat.len, |o| o.flat.len)
    }

    /// Whether there are no equations.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The number of distinct monomials, those of the equations and of their derivatives
    /// (both stages of a composition).
    // Public for the tests in tests/suite/; not part of the API.
    #[doc(hidden)]
    #[must_use]
    pub fn monomial_count(&self) -> usize {
        self.flat.monomials.len() + self.outer.as_ref().map_or(0, |o| o.flat.monomials.len())
    }

    /// The number of factors (powers of variables) of all the monomials together.
    // Public for the tests in tests/suite/; not part of the API.
    #[doc(hidden)]
    #[must_use]
    pub fn factor_count(&self) -> usize {
        self.flat.factors.len() + self.outer.as_ref().map_or(0, |o| o.flat.factors.len())
    }

    /// A workspace for evaluations over `S`.
    #[must_use]
    pub fn workspace<S: Scalar>(&self) -> Workspace<S> {
        Workspace {
            flat: self.flat.workspace(),
            outer: self.outer.as_ref().map(|o| {
                let m = o.flat.nvars;
                Box::new(OuterWorkspace {
                    flat: o.flat.workspace(),
                    leaves: vec![S::zero(); m],
                    leaf_jacobian: vec![S::zero(); m * self.flat.nvars],
                    outer_jacobian: vec![S::zero(); o.flat.len * m],
                })
            }),
        }
    }

    /// The values of the equations at `x`, into `values` (one per equation).
    ///
    /// # Panics
    /// If `x` or `values` has the wrong length, or `ws` is another program's.
    pub fn evaluate<S: Scalar>(&self, x: &[S], values: &mut [S], ws: &mut Workspace<S>) {
        match (&self.outer, &mut ws.outer) {
            (None, _) => self.flat.evaluate(x, values, &mut ws.flat),
            (Some(o), Some(ow)) => {
                self.flat.evaluate(x, &mut ow.leaves, &mut ws.flat);
                o.flat.evaluate(&ow.leaves, values, &mut ow.flat);
            }
            (Some(_), None) => panic!("a workspace of another program"),
        }
    }

    /// The values at `x` and the Jacobian `∂f_i/∂x_j`, row-major into `jacobian`
    /// (`len() × nvars()` entries).
    ///
    /// # Panics
    /// If a slice has the wrong length, or `ws` is another program's.
    pub fn evaluate_with_jacobian<S: Scalar>(
        &self,
        x: &[S],
        values: &mut [S],
        jacobian: &mut [S],
        ws: &mut Workspace<S>,
    ) {
        match (&self.outer, &mut ws.outer) {
            (None, _) => self
                .flat
                .evaluate_with_jacobian(x, values, jacobian, &mut ws.flat),
            (Some(o), Some(ow)) => {
                let n = self.flat.nvars;
                let m = o.flat.nvars;
                assert_eq!(
                    jacobian.len(),
                    o.flat.len * n,
                    "a Jacobian of len × nvars entries"
                );
                self.flat.evaluate_with_jacobian(
                    x,
                    &mut ow.leaves,
                    &mut ow.leaf_jacobian,
                    &mut ws.flat,
                );
                o.flat.evaluate_with_jacobian(
                    &ow.leaves,
                    values,
                    &mut ow.outer_jacobian,
                    &mut ow.flat,
                );
                // ∂f_i/∂x_j = Σ_k ∂g_i/∂a_k · ∂a_k/∂x_j over the leaves g_i involves.
                for (i, row) in jacobian.chunks_mut(n).enumerate() {
                    row.fill(S::zero());
                    for &k in &o.leaves[i] {
                        let dg = ow.outer_jacobian[i * m + k];
                        for (r, da) in row.iter_mut().zip(&ow.leaf_jacobian[k * n..(k + 1) * n]) {
                            *r = *r + dg * *da;
                        }
                    }
                }
            }
            (Some(_), None) => panic!("a workspace of another program"),
        }
    }
}

impl Flat {
    /// Compiles `equations` (each a polynomial in `nvars` variables).
    ///
    /// The partial derivatives are taken term by term from the variables each term involves,
    /// never as whole polynomials per variable, and monomials are indexed by their non-zero
    /// exponents only: the work and memory are those of the terms and their supports, not of
    /// `equations × nvars` polynomials of `nvars`-long exponent vectors (1 000 linear equations
    /// in 1 000 unknowns once took gigabytes here).
    ///
    /// # Panics
    /// If an equation's ring does not have `nvars` variables.
    fn new(equations: &[Poly], nvars: usize) -> Self {
        let mut max_power = vec![0u32; nvars];
        for p in equations {
            assert_eq!(p.nvars(), nvars, "an equation of another ring");
            for (e, _) in p.terms() {
                for (m, k) in max_power.iter_mut().zip(e) {
                    *m = (*m).max(*k);
                }
            }
        }
        let mut power_offset = Vec::with_capacity(nvars);
        let mut power_len = 1; // entry 0 is the constant 1
        for m in &max_power {
            power_offset.push(power_len);
            power_len += *m as usize;
        }
        let mut index = MonomialIndex::default();
        let mut monomials = Vec::new();
        let mut factors = Vec::new();
        let mut terms = Vec::new();
        let mut outputs = Vec::with_capacity(equations.len() * (nvars + 1));
        let mut monomial = |support: &[(u32, u32)], factors: &mut Vec<usize>| {
            index.get_or_insert(support, || {
                let first = factors.len();
                for (i, k) in support {
                    factors.push(power_offset[*i as usize] + *k as usize - 1);
                }
                monomials.push((first, factors.len()));
                monomials.len() - 1
            })
        };
        // The derivative terms of each equation, `(variable, coefficient, monomial)`, in the
        // order of the equation's terms.
        let mut derivatives: Vec<Vec<(u32, C64, usize)>> = Vec::with_capacity(equations.len());
        let mut support: Vec<(u32, u32)> = Vec::new();
        for p in equations {
            let start = terms.len();
            let mut dp = Vec::new();
            for (e, c) in p.terms() {
                support.clear();
                support.extend(
                    e.iter()
                        .enumerate()
                        .filter(|(_, k)| **k > 0)
                        .map(|(i, k)| (u32::try_from(i).expect("fewer than 2^32 variables"), *k)),
                );
                terms.push((c, monomial(&support, &mut factors)));
                for s in 0..support.len() {
                    let (i, k) = support[s];
                    support[s].1 = k - 1;
                    let reduced: Vec<(u32, u32)> =
                        support.iter().copied().filter(|(_, k)| *k > 0).collect();
                    support[s].1 = k;
                    dp.push((i, c * f64::from(k), monomial(&reduced, &mut factors)));
                }
            }
            outputs.push((start, terms.len()));
            derivatives.push(dp);
        }
        for mut dp in derivatives {
            // By variable; within one, in the order of the equation's terms (a stable sort):
            // the order in which `Poly::derivative` lists them, since removing one power of
            // `x_i` keeps the lexicographic order of the exponent vectors.
            dp.sort_by_key(|(i, _, _)| *i);
            let mut at = 0;
            for i in 0..nvars {
                let start = terms.len();
                while at < dp.len() && dp[at].0 as usize == i {
                    terms.push((dp[at].1, dp[at].2));
                    at += 1;
                }
                outputs.push((start, terms.len()));
            }
        }
        Self {
            nvars,
            len: equations.len(),
            power_offset,
            power_len,
            monomials,
            factors,
            terms,
            outputs,
        }
    }

    fn workspace<S: Scalar>(&self) -> FlatWorkspace<S> {
        FlatWorkspace {
            powers: vec![S::one(); self.power_len],
            monomials: vec![S::one(); self.monomials.len()],
            coefficients: self.terms.iter().map(|(c, _)| S::coefficient(*c)).collect(),
        }
    }

    fn fill_monomials<S: Scalar>(&self, x: &[S], ws: &mut FlatWorkspace<S>) {
        assert_eq!(
            x.len(),
            self.nvars,
            "a point with one coordinate per variable"
        );
        ws.powers[0] = S::one();
        for (i, xi) in x.iter().enumerate() {
            let start = self.power_offset[i];
            let end = self
                .power_offset
                .get(i + 1)
                .copied()
                .unwrap_or(self.power_len);
            // x^k = x^⌊k/2⌋ · x^⌈k/2⌉: a product tree of depth log₂ k rather than a chain of k
            // products. Over intervals this matters: each complex rectangle product widens its
            // operands' relative radius by up to √2 (the wrapping effect), geometrically along
            // a chain (x^62 of a root of unity: enclosures 2^31 times too wide, and no
            // certificate) but only polynomially, by about k^1.5, along the tree.
            for k in 1..=end - start {
                ws.powers[start + k - 1] = if k == 1 {
                    *xi
                } else {
                    ws.powers[start + k / 2 - 1] * ws.powers[start + (k - k / 2) - 1]
                };
            }
        }
        for (slot, (a, b)) in ws.monomials.iter_mut().zip(&self.monomials) {
            *slot = self.factors[*a..*b]
                .iter()
                .fold(S::one(), |acc, f| acc * ws.powers[*f]);
        }
    }

    fn output<S: Scalar>(&self, k: usize, ws: &FlatWorkspace<S>) -> S {
        let (a, b) = self.outputs[k];
        (a..b).fold(S::zero(), |acc, t| {
            acc + ws.coefficients[t] * ws.monomials[self.terms[t].1]
        })
    }

    fn evaluate<S: Scalar>(&self, x: &[S], values: &mut [S], ws: &mut FlatWorkspace<S>) {
        self.fill_monomials(x, ws);
        for (k, v) in values[..self.len].iter_mut().enumerate() {
            *v = self.output(k, ws);
        }
    }

    fn evaluate_with_jacobian<S: Scalar>(
        &self,
        x: &[S],
        values: &mut [S],
        jacobian: &mut [S],
        ws: &mut FlatWorkspace<S>,
    ) {
        self.evaluate(x, values, ws);
        assert_eq!(
            jacobian.len(),
            self.len * self.nvars,
            "a Jacobian of len × nvars entries"
        );
        for (k, v) in jacobian.iter_mut().enumerate() {
            *v = self.output(self.len + k, ws);
        }
    }
}
