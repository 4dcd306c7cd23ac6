//! Sparse multivariate polynomials with complex coefficients, and square systems of them: the
//! algebraic form of position problems (paper 003 §3.2, paper 004 §3), solved completely by
//! [`crate::homotopy`].
//!
//! A [`Poly`] is a finite sum of terms `c · x0^e0 · x1^e1 ⋯` over a fixed list of variables
//! (its ring, `nvars` of them); coefficients are [`C64`], with real polynomials simply having
//! zero imaginary parts ([`Poly::is_real`]). A [`System`] names its variables and may group them
//! for a multi-homogeneous structure; [`Program`] compiles its equations and their Jacobian into
//! a straight-line program evaluated without allocation, over complex numbers or over the
//! intervals of the certificates.
//!
//! ```
//! use kinsyn_nag::poly::{Poly, System, C64};
//! // The unit circle met by the line x = y.
//! let x = Poly::variable(2, 0);
//! let y = Poly::variable(2, 1);
//! let circle = &x * &x + &y * &y - Poly::real(2, 1.0);
//! let line = &x - &y;
//! let system = System::new(vec!["x".into(), "y".into()], vec![circle, line]).unwrap();
//! assert_eq!(system.bezout_number(), 2);
//! let h = std::f64::consts::FRAC_1_SQRT_2;
//! let residual = system.evaluate(&[C64::new(h, 0.0), C64::new(h, 0.0)]);
//! assert!(residual.iter().all(|r| r.norm() < 1e-15));
//! ```

pub mod bertini;
mod composition;
pub mod expansion;
pub mod families;
pub mod linear_product;
pub mod multihomogeneous;
pub mod phc;
mod program;

pub use composition::Composition;
pub use program::{Program, Scalar, Workspace};

use std::collections::BTreeMap;
use std::ops::{Add, Mul, Neg, Sub};

/// A complex number in double precision: the coefficients and values of polynomials.
pub type C64 = nalgebra::Complex<f64>;

/// The largest total degree of a polynomial the readers ([`bertini::parse`]) accept, for every
/// expression on the way (a product or power beyond it is refused where it is written): 2²⁰,
/// the degree of a univariate equation whose total-degree homotopy already has
/// [`crate::homotopy::MAX_PATHS`] paths. Degrees are computed in `u64` against it, so they
/// never wrap.
pub const MAX_DEGREE: u32 = 1 << 20;

/// The most variables a system read from text ([`bertini::parse`]) may declare. Every term of
/// a polynomial holds one exponent per variable, so the variables multiply the memory of
/// everything the reader expands; the solvers have tighter limits of their own
/// ([`crate::homotopy::MAX_UNKNOWNS`], [`crate::homotopy::MAX_DECOMPOSE_UNKNOWNS`]).
pub const MAX_VARIABLES: usize = 1000;

/// The most equations (functions) a system read from text may declare: the Jacobian of a
/// system has `equations × variables` entries.
pub const MAX_EQUATIONS: usize = 1000;

/// The largest [`System::program_size`] the solvers compile: 2²² factors, about 100 MB of
/// program and a few milliseconds per evaluation of the values and the Jacobian. Katsura-10's
/// is about 2 000, a manipulator's constraints with free inputs about 20 000.
pub const MAX_PROGRAM_SIZE: u128 = 1 << 22;

/// Why polynomials or a system cannot be formed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PolyError {
    /// An equation lives in a ring with another number of variables than the system names.
    #[error("equation {equation} has {found} variables, the system names {expected}")]
    VariableCount {
        /// The equation (0-based).
        equation: usize,
        /// The number of variables the system names.
        expected: usize,
        /// The number of variables of the equation's ring.
        found: usize,
    },
    /// Two variables share a name, or a name is empty.
    #[error("variable name {0:?} is empty or used twice")]
    VariableName(String),
    /// The variable groups do not partition the variables.
    #[error("the variable groups must list every variable exactly once: {0}")]
    Groups(String),
    /// A subsystem leaves out a variable that one of its equations involves, or names an
    /// equation or variable the system does not have.
    #[error("subsystem: {0}")]
    Subsystem(String),
}

/// A polynomial in `nvars` variables with complex coefficients, stored as its non-zero terms:
/// exponent vector → coefficient, in lexicographic order of the exponent vectors.
#[derive(Clone, Debug, PartialEq)]
pub struct Poly {
    nvars: usize,
    terms: BTreeMap<Vec<u32>, C64>,
}

impl Poly {
    /// The zero polynomial of the ring with `nvars` variables.
    #[must_use]
    pub fn zero(nvars: usize) -> Self {
        Self {
            nvars,
            terms: BTreeMap::new(),
        }
    }

    /// The constant `c`.
    #[must_use]
    pub fn constant(nvars: usize, c: C64) -> Self {
        Self::from_terms(nvars, [(vec![0; nvars], c)])
    }

    /// The real constant `c`.
    #[must_use]
    pub fn real(nvars: usize, c: f64) -> Self {
        Self::constant(nvars, C64::new(c, 0.0))
    }

    /// The variable `x_i`.
    ///
    /// # Panics
    /// If `i >= nvars` (a programming error: the ring has no such variable).
    #[must_use]
    pub fn variable(nvars: usize, i: usize) -> Self {
        assert!(i < nvars, "variable {i} of a ring with {nvars} variables");
        let mut e = vec![0; nvars];
        e[i] = 1;
        Self::from_terms(nvars, [(e, C64::new(1.0, 0.0))])
    }

    /// The sum of the given terms (like terms added, zero coefficients dropped).
    ///
    /// # Panics
    /// If an exponent vector's length is not `nvars`.
    #[must_use]
    pub fn from_terms(nvars: usize, terms: impl IntoIterator<Item = (Vec<u32>, C64)>) -> Self {
        let mut p = Self::zero(nvars);
        for (e, c) in terms {
            assert_eq!(e.len(), nvars, "exponent vector of the wrong length");
            p.add_term(e, c);
        }
        p
    }

    /// Adds the term `c · x^e`; returns the coefficient of `x^e` now (0 when it cancelled).
    fn add_term(&mut self, e: Vec<u32>, c: C64) -> C64 {
        use std::collections::btree_map::Entry;
        let zero = C64::new(0.0, 0.0);
        if c == zero {
            return self.terms.get(&e).copied().unwrap_or(zero);
        }
        match self.terms.entry(e) {
            Entry::Vacant(v) => *v.insert(c),
            Entry::Occupied(mut o) => {
                *o.get_mut() += c;
                let sum = *o.get();
                if sum == zero {
                    o.remove();
                }
                sum
            }
        }
    }

    /// Adds `rhs` in place; whether every coefficient it changed is finite afterwards
    /// (a sum of finite coefficients may overflow to infinity). The cost is `rhs`'s terms, not
    /// `self`'s: what a reader adding term after term needs.
    pub(crate) fn add_assign_finite(&mut self, rhs: Poly) -> bool {
        same_ring(self, &rhs);
        let mut finite = true;
        for (e, c) in rhs.terms {
            let sum = self.add_term(e, c);
            finite &= sum.re.is_finite() && sum.im.is_finite();
        }
        finite
    }

    /// Whether every coefficient is finite (neither infinite nor NaN).
    #[must_use]
    pub fn is_finite(&self) -> bool {
        self.terms
            .values()
            .all(|c| c.re.is_finite() && c.im.is_finite())
    }

    /// The number of variables of the ring.
    #[must_use]
    pub fn nvars(&self) -> usize {
        self.nvars
    }

    /// The non-zero terms: exponent vector (one exponent per variable) and coefficient.
    pub fn terms(&self) -> impl Iterator<Item = (&[u32], C64)> + '_ {
        self.terms.iter().map(|(e, c)| (e.as_slice(), *c))
    }

    /// The number of non-zero terms.
    #[must_use]
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether this is the zero polynomial.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// Whether every coefficient is real (zero imaginary part): the polynomial maps real
    /// points to real values, and its non-real roots come in conjugate pairs.
    #[must_use]
    pub fn is_real(&self) -> bool {
        self.terms.values().all(|c| c.im == 0.0)
    }

    /// The total degree (0 for constants and for the zero polynomial); saturates at
    /// `u32::MAX` (the readers of this module keep degrees within [`MAX_DEGREE`]).
    #[must_use]
    pub fn total_degree(&self) -> u32 {
        self.terms
            .keys()
            .map(|e| e.iter().fold(0u32, |d, k| d.saturating_add(*k)))
            .max()
            .unwrap_or(0)
    }

    /// The degree in the variables `vars` together (the others counted as constants): the
    /// degree of the polynomial in one group of a multi-homogeneous structure.
    #[must_use]
    pub fn degree_in(&self, vars: &[usize]) -> u32 {
        self.terms
            .keys()
            .map(|e| vars.iter().map(|i| e[*i]).sum::<u32>())
            .max()
            .unwrap_or(0)
    }

    /// The partial derivative `∂p/∂x_i`.
    #[must_use]
    pub fn derivative(&self, i: usize) -> Self {
        let terms = self.terms.iter().filter(|(e, _)| e[i] > 0).map(|(e, c)| {
            let mut d = e.clone();
            d[i] -= 1;
            (d, c * f64::from(e[i]))
        });
        Self::from_terms(self.nvars, terms)
    }

    /// The value at the point `x` (one coordinate per variable).
    ///
    /// # Panics
    /// If `x` has fewer than `nvars` coordinates.
    #[must_use]
    pub fn eval(&self, x: &[C64]) -> C64 {
        self.terms
            .iter()
            .map(|(e, c)| {
                e.iter().zip(x).fold(
                    *c,
                    |acc, (k, xi)| if *k == 0 { acc } else { acc * xi.powu(*k) },
                )
            })
            .sum()
    }

    /// The polynomial with `x_i` replaced by `q` (a polynomial of the same ring).
    #[must_use]
    pub fn substitute(&self, i: usize, q: &Self) -> Self {
        let mut out = Self::zero(self.nvars);
        let mut powers = vec![Self::real(self.nvars, 1.0)];
        for (e, c) in &self.terms {
            while powers.len() <= e[i] as usize {
                let next = &powers[powers.len() - 1] * q;
                powers.push(next);
            }
            let mut rest = e.clone();
            rest[i] = 0;
            let term = Self::from_terms(self.nvars, [(rest, *c)]);
            out = out + term * &powers[e[i] as usize];
        }
        out
    }

    /// `p^k` (`p^0 = 1`), by multiplying by `p` again and again: `k − 1` products, whose cost
    /// [`expansion::power`] bounds before any is done.
    #[must_use]
    pub fn pow(&self, k: u32) -> Self {
        if k == 0 {
            return Self::real(self.nvars, 1.0);
        }
        (1..k).fold(self.clone(), |acc, _| &acc * self)
    }

    /// The polynomial with every coefficient replaced by its modulus, `Σ |c_α| x^α`: at the
    /// moduli of a point, its value and gradient bound those of `p` term by term, and measure
    /// the size of the terms that cancel at a root (the scale of an equation's row in the
    /// endpoint condition of [`crate::homotopy`]).
    #[must_use]
    pub fn magnitudes(&self) -> Self {
        Self::from_terms(
            self.nvars,
            self.terms
                .iter()
                .map(|(e, c)| (e.clone(), C64::new(c.norm(), 0.0))),
        )
    }

    /// `c · p`.
    #[must_use]
    pub fn scale(&self, c: C64) -> Self {
        Self::from_terms(
            self.nvars,
            self.terms.iter().map(|(e, a)| (e.clone(), a * c)),
        )
    }

    /// The same polynomial in a ring of `nvars` variables, variable `i` becoming `map[i]`:
    /// how the equations of a part are placed in a larger system.
    ///
    /// # Panics
    /// If `map` does not have one entry per variable or names a variable beyond `nvars`.
    #[must_use]
    pub fn relabel(&self, nvars: usize, map: &[usize]) -> Self {
        assert_eq!(map.len(), self.nvars, "one new index per variable");
        let terms = self.terms.iter().map(|(e, c)| {
            let mut f = vec![0; nvars];
            for (k, m) in e.iter().zip(map) {
                f[*m] += k;
            }
            (f, *c)
        });
        Self::from_terms(nvars, terms)
    }

    /// The homogenisation with respect to the variable groups: each term of degree `d_j` in
    /// group `j` is multiplied by `h_j^(D_j − d_j)`, `D_j` the polynomial's degree in the group
    /// and `h_j` the new variable `nvars + j`. The result has `nvars + groups.len()` variables.
    #[must_use]
    pub fn homogenize(&self, groups: &[Vec<usize>]) -> Self {
        let n = self.nvars + groups.len();
        let degrees: Vec<u32> = groups.iter().map(|g| self.degree_in(g)).collect();
        let terms = self.terms.iter().map(|(e, c)| {
            let mut f = e.clone();
            f.resize(n, 0);
            for (j, g) in groups.iter().enumerate() {
                let d: u32 = g.iter().map(|i| e[*i]).sum();
                f[self.nvars + j] = degrees[j] - d;
            }
            (f, *c)
        });
        Self::from_terms(n, terms)
    }

    /// The polynomial written with the given variable names, e.g. `2*x^2 - y + 1`; complex
    /// coefficients as `(re+im*I)`, Bertini's imaginary unit.
    ///
    /// # Panics
    /// If fewer names than variables are given.
    #[must_use]
    pub fn display_with(&self, names: &[String]) -> String {
        assert!(names.len() >= self.nvars, "a name per variable");
        bertini::format_poly(self, names, "I")
    }
}

impl std::fmt::Display for Poly {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let names: Vec<String> = (0..self.nvars).map(|i| format!("x{i}")).collect();
        f.write_str(&self.display_with(&names))
    }
}

fn same_ring(a: &Poly, b: &Poly) {
    assert_eq!(a.nvars, b.nvars, "polynomials of different rings");
}

impl Add<&Poly> for &Poly {
    type Output = Poly;
    fn add(self, rhs: &Poly) -> Poly {
        same_ring(self, rhs);
        let mut out = self.clone();
        for (e, c) in &rhs.terms {
            out.add_term(e.clone(), *c);
        }
        out
    }
}

impl Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        self.scale(C64::new(-1.0, 0.0))
    }
}

impl Sub<&Poly> for &Poly {
    type Output = Poly;
    fn sub(self, rhs: &Poly) -> Poly {
        self + &(-rhs)
    }
}

impl Mul<&Poly> for &Poly {
    type Output = Poly;
    #[allow(
        clippy::suspicious_arithmetic_impl,
        reason = "exponents add when monomials multiply"
    )]
    fn mul(self, rhs: &Poly) -> Poly {
        same_ring(self, rhs);
        let mut out = Poly::zero(self.nvars);
        for (e, c) in &self.terms {
            for (f, d) in &rhs.terms {
                let sum = e.iter().zip(f).map(|(a, b)| {
                    a.checked_add(*b).expect(
                        "an exponent beyond u32::MAX (readers refuse degrees beyond MAX_DEGREE)",
                    )
                });
                out.add_term(sum.collect(), c * d);
            }
        }
        out
    }
}

// Sums and differences with an owned left operand add into it in place: a long sum costs the
// terms added, not the terms of the running total at every step (a sum of n monomials is then
// O(n log n) work, not O(n²)). (`+=` is not offered: written `p = p + q`, as everywhere in
// kinsyn, it costs the same.)
impl Add<Poly> for Poly {
    type Output = Poly;
    fn add(mut self, rhs: Poly) -> Poly {
        same_ring(&self, &rhs);
        for (e, c) in rhs.terms {
            self.add_term(e, c);
        }
        self
    }
}

impl Add<&Poly> for Poly {
    type Output = Poly;
    fn add(mut self, rhs: &Poly) -> Poly {
        same_ring(&self, rhs);
        for (e, c) in &rhs.terms {
            self.add_term(e.clone(), *c);
        }
        self
    }
}

impl Add<Poly> for &Poly {
    type Output = Poly;
    fn add(self, rhs: Poly) -> Poly {
        rhs + self
    }
}

impl Sub<Poly> for Poly {
    type Output = Poly;
    fn sub(self, rhs: Poly) -> Poly {
        self + (-rhs)
    }
}

impl Sub<&Poly> for Poly {
    type Output = Poly;
    fn sub(mut self, rhs: &Poly) -> Poly {
        same_ring(&self, rhs);
        for (e, c) in &rhs.terms {
            self.add_term(e.clone(), -*c);
        }
        self
    }
}

impl Sub<Poly> for &Poly {
    type Output = Poly;
    fn sub(self, rhs: Poly) -> Poly {
        -rhs + self
    }
}

impl Mul<Poly> for Poly {
    type Output = Poly;
    fn mul(self, rhs: Poly) -> Poly {
        &self * &rhs
    }
}

impl Mul<&Poly> for Poly {
    type Output = Poly;
    fn mul(self, rhs: &Poly) -> Poly {
        &self * rhs
    }
}

impl Mul<Poly> for &Poly {
    type Output = Poly;
    fn mul(self, rhs: Poly) -> Poly {
        self * &rhs
    }
}

impl Neg for Poly {
    type Output = Poly;
    /// Every coefficient negated in place (exact in floating point).
    fn neg(mut self) -> Poly {
        for c in self.terms.values_mut() {
            *c = -*c;
        }
        self
    }
}

impl Mul<C64> for Poly {
    type Output = Poly;
    fn mul(self, c: C64) -> Poly {
        self.scale(c)
    }
}

impl Mul<f64> for Poly {
    type Output = Poly;
    fn mul(self, c: f64) -> Poly {
        self.scale(C64::new(c, 0.0))
    }
}

/// A system of polynomial equations `f_1 = … = f_m = 0` in named variables, with an optional
/// grouping of the variables for a multi-homogeneous structure (one group of all by default).
#[derive(Clone, Debug, PartialEq)]
pub struct System {
    variables: Vec<String>,
    equations: Vec<Poly>,
    groups: Vec<Vec<usize>>,
    /// The equations as outer polynomials of inner ones, when they were given so
    /// ([`Self::composed`]): how they are evaluated.
    composition: Option<Composition>,
}

impl System {
    /// The system of `equations` in the named `variables` (in the order of the equations'
    /// rings), all variables in one group.
    ///
    /// # Errors
    /// [`PolyError::VariableCount`] if an equation's ring has another number of variables,
    /// [`PolyError::VariableName`] if a name is empty or repeated.
    pub fn new(variables: Vec<String>, equations: Vec<Poly>) -> Result<Self, PolyError> {
        let mut seen = std::collections::HashSet::with_capacity(variables.len());
        for name in &variables {
            if name.is_empty() || !seen.insert(name.as_str()) {
                return Err(PolyError::VariableName(name.clone()));
            }
        }
        for (equation, p) in equations.iter().enumerate() {
            if p.nvars != variables.len() {
                return Err(PolyError::VariableCount {
                    equation,
                    expected: variables.len(),
                    found: p.nvars,
                });
            }
        }
        let groups = vec![(0..variables.len()).collect()];
        Ok(Self {
            variables,
            equations,
            groups,
            composition: None,
        })
    }

    /// The system whose equations are `composition`'s, evaluated as composed
    /// ([`Composition`]: an eliminated equation stays a product of small pieces); its
    /// [`Self::equations`] are the expansions, for the degrees, supports and text.
    ///
    /// # Errors
    /// As [`Self::new`], for the inner polynomials' ring.
    pub fn composed(variables: Vec<String>, composition: Composition) -> Result<Self, PolyError> {
        if composition.nvars() != variables.len() && !composition.inner().is_empty() {
            return Err(PolyError::VariableCount {
                equation: 0,
                expected: variables.len(),
                found: composition.nvars(),
            });
        }
        let mut system = Self::new(variables, composition.expand())?;
        system.composition = Some(composition);
        Ok(system)
    }

    /// The same system with the composition `composition` of the same equations (trusted:
    /// the transformations of [`Composition`] keep the expansions equal).
    pub(crate) fn with_composition(mut self, composition: Option<Composition>) -> Self {
        self.composition = composition;
        self
    }

    /// The composition the equations are evaluated by, if they were given as one.
    #[must_use]
    pub fn composition(&self) -> Option<&Composition> {
        self.composition.as_ref()
    }

    /// The same system with the variables partitioned into `groups` (indices into the
    /// variables) for a multi-homogeneous start system.
    ///
    /// # Errors
    /// [`PolyError::Groups`] unless every variable is in exactly one non-empty group.
    pub fn with_groups(mut self, groups: Vec<Vec<usize>>) -> Result<Self, PolyError> {
        let mut seen = vec![0usize; self.variables.len()];
        for g in &groups {
            if g.is_empty() {
                return Err(PolyError::Groups("a group is empty".into()));
            }
            for i in g {
                match seen.get_mut(*i) {
                    Some(s) => *s += 1,
                    None => return Err(PolyError::Groups(format!("no variable {i}"))),
                }
            }
        }
        if let Some(i) = seen.iter().position(|s| *s != 1) {
            return Err(PolyError::Groups(format!(
                "variable {:?} is in {} groups",
                self.variables[i], seen[i]
            )));
        }
        self.groups = groups;
        Ok(self)
    }

    /// The variable names.
    #[must_use]
    pub fn variables(&self) -> &[String] {
        &self.variables
    }

    /// The equations (each a polynomial in all the variables).
    #[must_use]
    pub fn equations(&self) -> &[Poly] {
        &self.equations
    }

    /// The variable groups (indices into [`Self::variables`]).
    #[must_use]
    pub fn groups(&self) -> &[Vec<usize>] {
        &self.groups
    }

    /// The number of variables.
    #[must_use]
    pub fn nvars(&self) -> usize {
        self.variables.len()
    }

    /// The number of equations.
    #[must_use]
    pub fn len(&self) -> usize {
        self.equations.len()
    }

    /// Whether the system has no equations.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.equations.is_empty()
    }

    /// Whether there are as many equations as variables.
    #[must_use]
    pub fn is_square(&self) -> bool {
        self.len() == self.nvars()
    }

    /// Whether every coefficient is real.
    #[must_use]
    pub fn is_real(&self) -> bool {
        self.equations.iter().all(Poly::is_real)
    }

    /// The total degree of each equation.
    #[must_use]
    pub fn degrees(&self) -> Vec<u32> {
        self.equations.iter().map(Poly::total_degree).collect()
    }

    /// Bézout's number, the product of the degrees: for a square system, the number of paths
    /// of a total-degree homotopy and a bound on the isolated solutions in ℂⁿ. Saturates at
    /// `u128::MAX` (read: more than 10^38).
    #[must_use]
    pub fn bezout_number(&self) -> u128 {
        self.degrees()
            .iter()
            .fold(1, |n, d| n.saturating_mul(u128::from(*d)))
    }

    /// The degree of each equation in each variable group: `[equation][group]`.
    #[must_use]
    pub fn multihomogeneous_degrees(&self) -> Vec<Vec<u32>> {
        self.equations
            .iter()
            .map(|p| self.groups.iter().map(|g| p.degree_in(g)).collect())
            .collect()
    }

    /// The multi-homogeneous Bézout number of the grouping: the coefficient of
    /// `Π_j α_j^{n_j}` in `Π_i Σ_j d_ij α_j` (`n_j` the size of group `j`, `d_ij` the degree
    /// of equation `i` in it), the number of paths of the multi-homogeneous start system.
    /// Zero unless the system is square; saturates at `u128::MAX` (read: more than 10^38).
    /// `None` when the groups are too many to count ([`multihomogeneous::MAX_GROUP_STATES`]).
    #[must_use]
    pub fn multihomogeneous_bezout(&self) -> Option<u128> {
        if !self.is_square() {
            return Some(0);
        }
        self.assignments().map(|a| a.count())
    }

    /// The assignments of the equations to the variable groups behind
    /// [`Self::multihomogeneous_bezout`]; `None` when their states are too many.
    pub(crate) fn assignments(&self) -> Option<multihomogeneous::Assignments> {
        let sizes: Vec<usize> = self.groups.iter().map(Vec::len).collect();
        multihomogeneous::Assignments::new(&self.multihomogeneous_degrees(), &sizes)
    }

    /// The values of the equations at `x`.
    #[must_use]
    pub fn evaluate(&self, x: &[C64]) -> Vec<C64> {
        match &self.composition {
            Some(c) => c.evaluate(x),
            None => self.equations.iter().map(|p| p.eval(x)).collect(),
        }
    }

    /// The equations `equations` (indices) as a system in the variables `variables` alone
    /// (indices, in the order given): e.g. a mechanism's pose equations without the passive
    /// angles they do not involve. Variable groups are not kept.
    ///
    /// # Errors
    /// [`PolyError::Subsystem`] if an index is out of range or a kept equation involves a
    /// variable left out.
    pub fn subsystem(&self, equations: &[usize], variables: &[usize]) -> Result<Self, PolyError> {
        let n = variables.len();
        if let Some(v) = variables.iter().find(|v| **v >= self.nvars()) {
            return Err(PolyError::Subsystem(format!("no variable {v}")));
        }
        let kept = equations
            .iter()
            .map(|&k| {
                let f = self
                    .equations
                    .get(k)
                    .ok_or_else(|| PolyError::Subsystem(format!("no equation {k}")))?;
                let mut terms = Vec::with_capacity(f.len());
                for (e, c) in f.terms() {
                    if let Some(j) = (0..e.len()).find(|j| e[*j] > 0 && !variables.contains(j)) {
                        return Err(PolyError::Subsystem(format!(
                            "equation {k} involves {}, which is left out",
                            self.variables[j]
                        )));
                    }
                    terms.push((variables.iter().map(|&j| e[j]).collect(), c));
                }
                Ok(Poly::from_terms(n, terms))
            })
            .collect::<Result<Vec<Poly>, PolyError>>()?;
        Self::new(
            variables
                .iter()
                .map(|&j| self.variables[j].clone())
                .collect(),
            kept,
        )
    }

    /// An upper bound on the size of the straight-line program of the equations and their
    /// Jacobian, homogenised or not: `Σ (s + 1)(s + 2)` over the terms, `s` the number of
    /// variables a term involves (a term's monomial and those of its `s` partial derivatives
    /// list at most `s + 1` factors each, one more when homogenised). Known from the terms
    /// before anything is compiled; the solvers refuse beyond [`MAX_PROGRAM_SIZE`].
    /// A composed system's is its composition's ([`Composition::program_size`]).
    #[must_use]
    pub fn program_size(&self) -> u128 {
        match &self.composition {
            Some(c) => c.program_size(),
            None => terms_program_size(&self.equations),
        }
    }

    /// The straight-line program of the equations and their Jacobian.
    #[must_use]
    pub fn program(&self) -> Program {
        match &self.composition {
            Some(c) => Program::composed(c),
            None => Program::new(&self.equations, self.nvars()),
        }
    }

    /// The program of the equations with every coefficient replaced by its modulus
    /// ([`Poly::magnitudes`], [`Composition::magnitudes`]): the size of each equation's
    /// terms at the moduli of a point.
    #[must_use]
    pub fn magnitudes_program(&self) -> Program {
        match &self.composition {
            Some(c) => Program::composed(&c.magnitudes()),
            None => Program::new(
                &self
                    .equations
                    .iter()
                    .map(Poly::magnitudes)
                    .collect::<Vec<_>>(),
                self.nvars(),
            ),
        }
    }

    /// The equations homogenised with respect to `groups` ([`Poly::homogenize`]), as a
    /// system in the variables then one homogenising coordinate per group (named `h#j`),
    /// composed when this one is.
    ///
    /// # Panics
    /// Never: the new names are distinct from the old (`#` is not in a variable's name).
    #[must_use]
    pub fn homogenized(&self, groups: &[Vec<usize>]) -> Self {
        let equations: Vec<Poly> = self
            .equations
            .iter()
            .map(|p| p.homogenize(groups))
            .collect();
        let composition = self.composition.as_ref().map(|c| {
            let degrees: Vec<Vec<u32>> = self
                .equations
                .iter()
                .map(|p| groups.iter().map(|g| p.degree_in(g)).collect())
                .collect();
            c.homogenize(groups, &degrees, &self.equations)
        });
        let mut variables = self.variables.clone();
        variables.extend((0..groups.len()).map(|j| format!("h#{j}")));
        Self {
            groups: vec![(0..variables.len()).collect()],
            variables,
            equations,
            composition,
        }
    }

    /// The combinations `Σ_j rows[i][j] f_j` of the equations, one per row, composed when this
    /// system is.
    #[must_use]
    pub fn combinations(&self, rows: &[Vec<C64>]) -> Self {
        Self {
            variables: self.variables.clone(),
            equations: linear_combinations(&self.equations, rows, self.nvars()),
            groups: self.groups.clone(),
            composition: self.composition.as_ref().map(|c| c.combinations(rows)),
        }
    }

    /// The equations in a ring of more variables (`variables`, the first ones this system's),
    /// followed by `extra` (polynomials of the larger ring): how slices with parameters are
    /// added. Composed when this system is, each extra polynomial a leaf.
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn widened(&self, variables: Vec<String>, extra: Vec<Poly>) -> Result<Self, PolyError> {
        let total = variables.len();
        let identity: Vec<usize> = (0..self.nvars()).collect();
        let mut equations: Vec<Poly> = self
            .equations
            .iter()
            .map(|f| f.relabel(total, &identity))
            .collect();
        let composition = self.composition.as_ref().map(|c| {
            c.map_inner(|a| a.relabel(total, &identity))
                .with_leaves(&extra)
        });
        equations.extend(extra);
        Ok(Self::new(variables, equations)?.with_composition(composition))
    }

    /// The system with `f` applied to every polynomial (expanded and inner), into the ring of
    /// `variables`: `f` must commute with sums and products (a substitution of values for
    /// some variables, a relabelling).
    ///
    /// # Errors
    /// As [`Self::new`].
    pub fn mapped(
        &self,
        variables: Vec<String>,
        f: impl Fn(&Poly) -> Poly,
    ) -> Result<Self, PolyError> {
        let equations = self.equations.iter().map(&f).collect();
        let composition = self.composition.as_ref().map(|c| c.map_inner(&f));
        Ok(Self::new(variables, equations)?.with_composition(composition))
    }
}

/// `Σ_j rows[i][j] p_j` for each row (polynomials in `nvars` variables; zero coefficients
/// skipped).
fn linear_combinations(polys: &[Poly], rows: &[Vec<C64>], nvars: usize) -> Vec<Poly> {
    rows.iter()
        .map(|row| {
            row.iter()
                .zip(polys)
                .filter(|(c, _)| **c != C64::new(0.0, 0.0))
                .fold(Poly::zero(nvars), |acc, (c, p)| &acc + &p.scale(*c))
        })
        .collect()
}

/// [`System::program_size`] of plain equations: `Σ (s + 1)(s + 2)` over their terms.
fn terms_program_size(equations: &[Poly]) -> u128 {
    equations
        .iter()
        .flat_map(Poly::terms)
        .map(|(e, _)| {
            let s = e.iter().filter(|k| **k > 0).count() as u128;
            (s + 1) * (s + 2)
        })
        .fold(0, u128::saturating_add)
}
