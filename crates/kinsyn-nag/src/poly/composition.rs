//! Equations given as polynomials of polynomials: `f_i(x) = g_i(a_1(x), …, a_m(x))`, the
//! **inner** polynomials `a_k` in the system's variables and the **outer** ones `g_i` in `m`
//! leaf variables. An equation obtained by elimination is of this form: the resultant of two
//! quadratics in `t` is `(a₂b₀ − a₀b₂)² − (a₂b₁ − a₁b₂)(a₁b₀ − a₀b₁)` of their coefficients, a
//! dozen products of small polynomials, while expanded it may hold a thousand terms of degree
//! eight. A [`super::Program`] evaluates a composition stage by stage, the Jacobian by the
//! chain rule, so the work is that of the small pieces (as the straight-line programs of
//! Bertini and HomotopyContinuation.jl's `ModelKit`), and every transformation the solvers apply
//! to a system — random combinations, slices, homogenisation, fixing parameters — keeps the
//! form ([`super::System::composed`]).

use super::{C64, Poly};

/// Outer polynomials of inner ones (module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct Composition {
    inner: Vec<Poly>,
    outer: Vec<Poly>,
}

impl Composition {
    /// `outer` (each in `inner.len()` leaf variables) of `inner` (each in one ring of the
    /// system's variables). `None` if the rings do not match.
    #[must_use]
    pub fn new(inner: Vec<Poly>, outer: Vec<Poly>) -> Option<Self> {
        let nvars = inner.first().map(Poly::nvars)?;
        (inner.iter().all(|a| a.nvars() == nvars) && outer.iter().all(|g| g.nvars() == inner.len()))
            .then_some(Self { inner, outer })
    }

    /// The inner polynomials `a_k`.
    #[must_use]
    pub fn inner(&self) -> &[Poly] {
        &self.inner
    }

    /// The outer polynomials `g_i`, in the leaf variables.
    #[must_use]
    pub fn outer(&self) -> &[Poly] {
        &self.outer
    }

    /// The variables of the inner polynomials' ring.
    #[must_use]
    pub fn nvars(&self) -> usize {
        self.inner.first().map_or(0, Poly::nvars)
    }

    /// The equations expanded: each `g_i(a(x))` as one polynomial.
    #[must_use]
    pub fn expand(&self) -> Vec<Poly> {
        let n = self.nvars();
        let mut powers: Vec<Vec<Poly>> = self
            .inner
            .iter()
            .map(|a| vec![Poly::real(n, 1.0), a.clone()])
            .collect();
        self.outer
            .iter()
            .map(|g| {
                let mut out = Poly::zero(n);
                for (e, c) in g.terms() {
                    let mut term = Poly::constant(n, c);
                    for (k, &p) in e.iter().enumerate() {
                        if p == 0 {
                            continue;
                        }
                        while powers[k].len() <= p as usize {
                            let next = &powers[k][powers[k].len() - 1] * &self.inner[k];
                            powers[k].push(next);
                        }
                        term = &term * &powers[k][p as usize];
                    }
                    out = out + term;
                }
                out
            })
            .collect()
    }

    /// The values of the equations at `x`: the inner polynomials, then the outer ones at
    /// their values (nothing compiled, for a point now and then; [`super::Program::composed`]
    /// for many).
    #[must_use]
    pub fn evaluate(&self, x: &[C64]) -> Vec<C64> {
        let leaves: Vec<C64> = self.inner.iter().map(|a| a.eval(x)).collect();
        self.outer.iter().map(|g| g.eval(&leaves)).collect()
    }

    /// Every coefficient, inner and outer, replaced by its modulus: at the moduli of a point
    /// its value bounds the sum of the moduli of the expanded terms, the scale of an equation
    /// in the endpoint tests ([`Poly::magnitudes`]).
    #[must_use]
    pub fn magnitudes(&self) -> Self {
        Self {
            inner: self.inner.iter().map(Poly::magnitudes).collect(),
            outer: self.outer.iter().map(Poly::magnitudes).collect(),
        }
    }

    /// The same equations with `f` applied to every inner polynomial (a new ring, parameters
    /// fixed): valid for any `f` that commutes with sums and products, such as a
    /// substitution or a relabelling of the variables.
    #[must_use]
    pub fn map_inner(&self, f: impl Fn(&Poly) -> Poly) -> Self {
        Self {
            inner: self.inner.iter().map(f).collect(),
            outer: self.outer.clone(),
        }
    }

    /// The equations followed by `extra` (polynomials in the inner ring), each a leaf of its
    /// own.
    #[must_use]
    pub fn with_leaves(&self, extra: &[Poly]) -> Self {
        let m = self.inner.len() + extra.len();
        let identity: Vec<usize> = (0..self.inner.len()).collect();
        let mut outer: Vec<Poly> = self.outer.iter().map(|g| g.relabel(m, &identity)).collect();
        outer.extend((self.inner.len()..m).map(|k| Poly::variable(m, k)));
        let mut inner = self.inner.clone();
        inner.extend(extra.iter().cloned());
        Self { inner, outer }
    }

    /// The combinations `Σ_j rows[i][j] f_j` of the equations, one per row.
    #[must_use]
    pub fn combinations(&self, rows: &[Vec<C64>]) -> Self {
        Self {
            inner: self.inner.clone(),
            outer: super::linear_combinations(&self.outer, rows, self.inner.len()),
        }
    }

    /// The equations homogenised with respect to `groups` (one new variable `h_j` after the
    /// ring's per group), equation `i` to the degrees `degrees[i][j]` of its expansion
    /// ([`Poly::homogenize`]): each inner polynomial homogenised to its own degrees, a leaf per
    /// `h_j`, and each outer term padded with the powers of `h_j` its weighted degree leaves,
    /// so that the composition is the homogenised expansion term for term. An equation whose
    /// outer terms exceed its expansion's degree (the top terms cancel) becomes a leaf of its
    /// own, homogenised expanded (`expanded`).
    #[must_use]
    pub fn homogenize(
        &self,
        groups: &[Vec<usize>],
        degrees: &[Vec<u32>],
        expanded: &[Poly],
    ) -> Self {
        let n = self.nvars();
        let inner_degrees: Vec<Vec<u32>> = self
            .inner
            .iter()
            .map(|a| groups.iter().map(|g| a.degree_in(g)).collect())
            .collect();
        let mut inner: Vec<Poly> = self.inner.iter().map(|a| a.homogenize(groups)).collect();
        let m0 = inner.len();
        inner.extend((0..groups.len()).map(|j| Poly::variable(n + groups.len(), n + j)));
        // Outputs that need their expansion as a leaf.
        let fallback: Vec<usize> = (0..self.outer.len())
            .filter(|&i| {
                self.outer[i].terms().any(|(e, _)| {
                    (0..groups.len()).any(|j| {
                        let w: u32 = e.iter().zip(&inner_degrees).map(|(p, d)| p * d[j]).sum();
                        w > degrees[i][j]
                    })
                })
            })
            .collect();
        inner.extend(fallback.iter().map(|&i| expanded[i].homogenize(groups)));
        let m = inner.len();
        let outer = self
            .outer
            .iter()
            .enumerate()
            .map(|(i, g)| {
                if let Some(f) = fallback.iter().position(|&k| k == i) {
                    return Poly::variable(m, m0 + groups.len() + f);
                }
                Poly::from_terms(
                    m,
                    g.terms().map(|(e, c)| {
                        let mut f = vec![0u32; m];
                        f[..m0].copy_from_slice(e);
                        for j in 0..groups.len() {
                            let w: u32 = e.iter().zip(&inner_degrees).map(|(p, d)| p * d[j]).sum();
                            f[m0 + j] = degrees[i][j] - w;
                        }
                        (f, c)
                    }),
                )
            })
            .collect();
        Self { inner, outer }
    }

    /// An upper bound on the size of the program ([`super::System::program_size`]): that of
    /// the inner and of the outer polynomials as systems of their own.
    #[must_use]
    pub fn program_size(&self) -> u128 {
        super::terms_program_size(&self.inner) + super::terms_program_size(&self.outer)
    }
}
