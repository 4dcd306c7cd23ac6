//! The set structure of a square system for a linear-product start system
//! ([`crate::homotopy::StartSystem::LinearProduct`]), its number of finite start solutions and
//! their enumeration.
//!
//! Equation `i` of total degree `D_i` gets `D_i` **slots**, each a set of variables; the start
//! equation is a product of one random linear form per slot, in the slot's variables and the
//! homogenising coordinate. The structure fits `f_i` when every term of `f_i` is a product of
//! one variable (or `1`) from each slot; then every isolated root of the target is reached from
//! the start system's finite roots (the random product homotopy: Li, Sauer & Yorke 1987;
//! Verschelde & Cools 1993; Sommese & Wampler 2005, §8.4).
//!
//! **The slots, from the variable groups.** Each group `j` in which `f_i` has degree
//! `d_ij > 0` takes `d_ij` slots, the first ones free of every group that shares a term with
//! it; groups that never share a term share slots. A term then finds, for each of its groups,
//! that group's own slots, disjoint from its other groups', so the structure fits. When the
//! groups of a term need more than `D_i` slots (`x·t + x² + t²`), every slot holds every
//! variable: the equation counts as in the total degree.
//!
//! So a generic hyperplane (degree 1, every group, no two groups in one term) is one slot of
//! every variable, where the multi-homogeneous count would give it degree 1 in each group; and a
//! leg equation of degree 2 in the Study parameters and 2 in its input's tangent is
//! `{Study}{Study}{t}{t}`, where the total degree would count 4 of every variable.
//!
//! **The count.** A choice of one slot per equation gives a linear system with a unique finite
//! root exactly when its supports admit a perfect matching of equations to variables (for
//! generic coefficients, the determinant is a nonzero polynomial in them exactly then:
//! Edmonds 1967). The count is the sum over such choices of the number of distinct slot
//! factors chosen, walked depth-first with the matching grown by augmenting paths, and
//! bounded ([`MAX_NODES`]): a structure whose walk is longer is not counted.

use super::System;

/// The most nodes of the depth-first walk over slot choices (a choice of one slot support per
/// equation so far) the count and the enumeration visit: 2²⁰ nodes of at most 100 unknowns,
/// a fraction of a second.
pub const MAX_NODES: u64 = 1 << 20;

/// One equation's slots: its distinct slot supports (variable indices) and how many slots
/// have each.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EquationSlots {
    /// `(variables, slots)`: each distinct support and its number of slots.
    pub supports: Vec<(Vec<usize>, u32)>,
}

impl EquationSlots {
    /// The number of slots: the equation's total degree.
    #[must_use]
    pub fn degree(&self) -> u32 {
        self.supports.iter().map(|s| s.1).sum()
    }
}

/// The set structure of a square system (module documentation).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SetStructure {
    nvars: usize,
    equations: Vec<EquationSlots>,
}

/// A choice of one support per equation whose linear system has a finite root, and the
/// number of start roots it stands for (the product of the chosen supports' slot counts).
pub type SupportChoice = (Vec<usize>, u128);

impl SetStructure {
    /// The set structure of `system` from its variable groups (module documentation).
    #[must_use]
    pub fn of(system: &System) -> Self {
        let profiles: Vec<Profile> = system
            .equations()
            .iter()
            .map(|f| Profile::of(f, system.groups()))
            .collect();
        Self::from_profiles(system.nvars(), system.groups(), &profiles)
    }

    /// The set structure of equations with the given profiles ([`Profile`]) in `nvars`
    /// variables partitioned into `groups`.
    #[must_use]
    pub fn from_profiles(nvars: usize, groups: &[Vec<usize>], profiles: &[Profile]) -> Self {
        let equations = profiles
            .iter()
            .map(|p| {
                let slots = p.slots().unwrap_or_else(|| {
                    vec![(0..groups.len()).collect::<Vec<_>>(); p.degree as usize]
                });
                let mut supports: Vec<(Vec<usize>, u32)> = Vec::new();
                for slot in slots {
                    let mut vars: Vec<usize> = slot
                        .iter()
                        .flat_map(|j| groups[*j].iter().copied())
                        .collect();
                    vars.sort_unstable();
                    match supports.iter_mut().find(|s| s.0 == vars) {
                        Some(s) => s.1 += 1,
                        None => supports.push((vars, 1)),
                    }
                }
                EquationSlots { supports }
            })
            .collect();
        Self { nvars, equations }
    }

    /// Each equation's slots.
    #[must_use]
    pub fn equations(&self) -> &[EquationSlots] {
        &self.equations
    }

    /// The number of finite roots of the generic linear-product start system: the paths of a
    /// linear-product homotopy. `None` when the walk exceeds [`MAX_NODES`]; zero unless square.
    #[must_use]
    pub fn count(&self) -> Option<u128> {
        let mut total = 0u128;
        self.walk(&mut |(_, n)| total = total.saturating_add(n))?;
        Some(total)
    }

    /// Every choice of supports with a finite root, in a fixed order, with the number of start
    /// roots of each; `None` as for [`Self::count`].
    #[must_use]
    pub fn choices(&self) -> Option<Vec<SupportChoice>> {
        let mut out = Vec::new();
        self.walk(&mut |c| out.push(c))?;
        Some(out)
    }

    /// Visits each choice of supports whose supports admit a perfect matching; `None` when the
    /// walk exceeds [`MAX_NODES`]. The walk takes the equations of one support first (no
    /// branching), then those of several, and stops before the equations whose one support is
    /// every variable (generic hyperplanes): once the others are matched, these match the
    /// variables left in any order.
    fn walk(&self, visit: &mut dyn FnMut(SupportChoice)) -> Option<()> {
        let n = self.nvars;
        if self.equations.len() != n {
            return Some(());
        }
        let dense = |e: &EquationSlots| e.supports.len() == 1 && e.supports[0].0.len() == n;
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_by_key(|&i| {
            let e = &self.equations[i];
            match (dense(e), e.supports.len()) {
                (true, _) => 2,
                (false, 1) => 0,
                (false, _) => 1,
            }
        });
        let branching = order
            .iter()
            .position(|&i| dense(&self.equations[i]))
            .unwrap_or(n);
        let tail: u128 = order[branching..]
            .iter()
            .map(|&i| u128::from(self.equations[i].supports[0].1))
            .fold(1, u128::saturating_mul);
        let mut walk = Walk {
            structure: self,
            order: &order[..branching],
            chosen: vec![0; n],
            owner: vec![None; n],
            nodes: 0,
        };
        walk.descend(0, tail, visit)
    }
}

/// The depth-first walk of [`SetStructure::walk`]: the equations in the order walked, the
/// support chosen for each (by equation; zero for those not walked, whose one support it is)
/// and which equation each variable is matched to.
struct Walk<'a> {
    structure: &'a SetStructure,
    order: &'a [usize],
    chosen: Vec<usize>,
    owner: Vec<Option<usize>>,
    nodes: u64,
}

impl Walk<'_> {
    fn descend(
        &mut self,
        depth: usize,
        roots: u128,
        visit: &mut dyn FnMut(SupportChoice),
    ) -> Option<()> {
        if depth == self.order.len() {
            visit((self.chosen.clone(), roots));
            return Some(());
        }
        let i = self.order[depth];
        for (s, (_, slots)) in self.structure.equations[i].supports.iter().enumerate() {
            self.nodes += 1;
            if self.nodes > MAX_NODES {
                return None;
            }
            let saved = self.owner.clone();
            self.chosen[i] = s;
            let mut seen = vec![false; self.owner.len()];
            if self.augment(i, &mut seen) {
                self.descend(depth + 1, roots.saturating_mul(u128::from(*slots)), visit)?;
            }
            self.owner = saved;
        }
        self.chosen[i] = 0;
        Some(())
    }

    /// Kuhn's augmenting path from equation `i` (its chosen support), over the variables not
    /// yet `seen`.
    fn augment(&mut self, i: usize, seen: &mut [bool]) -> bool {
        let support = &self.structure.equations[i].supports[self.chosen[i]].0;
        for &v in support {
            if seen[v] {
                continue;
            }
            seen[v] = true;
            let free = match self.owner[v] {
                None => true,
                Some(k) => self.augment(k, seen),
            };
            if free {
                self.owner[v] = Some(i);
                return true;
            }
        }
        false
    }
}

/// What the slots of an equation depend on: its total degree, its degree in each variable
/// group and which groups share a term. A linear combination of equations has the largest
/// degrees and every pair that shares a term in one of them ([`Profile::sum`]), unless terms
/// cancel, which random coefficients exclude.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Profile {
    degree: u32,
    group_degrees: Vec<u32>,
    together: Vec<Vec<bool>>,
}

impl Profile {
    /// The profile of `f` for the variable groups `groups` (a partition of its variables).
    #[must_use]
    pub fn of(f: &super::Poly, groups: &[Vec<usize>]) -> Self {
        let m = groups.len();
        let mut group_of = vec![0; f.nvars()];
        for (j, g) in groups.iter().enumerate() {
            for v in g {
                group_of[*v] = j;
            }
        }
        let mut profile = Self {
            degree: f.total_degree(),
            group_degrees: vec![0; m],
            together: vec![vec![false; m]; m],
        };
        // Each term's groups and degrees in them: a few groups per term, whatever `m`.
        let mut in_term: Vec<(usize, u32)> = Vec::new();
        for (exponents, _) in f.terms() {
            in_term.clear();
            for (v, e) in exponents.iter().enumerate().filter(|(_, e)| **e > 0) {
                match in_term.iter_mut().find(|(j, _)| *j == group_of[v]) {
                    Some((_, d)) => *d += e,
                    None => in_term.push((group_of[v], *e)),
                }
            }
            for (a, (j, d)) in in_term.iter().enumerate() {
                profile.group_degrees[*j] = profile.group_degrees[*j].max(*d);
                for (k, _) in &in_term[a + 1..] {
                    profile.together[*j][*k] = true;
                    profile.together[*k][*j] = true;
                }
            }
        }
        profile
    }

    /// The profile of a generic affine hyperplane in `groups` groups: degree 1 in each, no two
    /// in one term.
    #[must_use]
    pub fn hyperplane(groups: usize) -> Self {
        Self {
            degree: 1,
            group_degrees: vec![1; groups],
            together: vec![vec![false; groups]; groups],
        }
    }

    /// The profile of a generic linear combination of equations of profiles `self` and
    /// `other`.
    #[must_use]
    pub fn sum(&self, other: &Self) -> Self {
        Self {
            degree: self.degree.max(other.degree),
            group_degrees: self
                .group_degrees
                .iter()
                .zip(&other.group_degrees)
                .map(|(a, b)| *a.max(b))
                .collect(),
            together: self
                .together
                .iter()
                .zip(&other.together)
                .map(|(a, b)| a.iter().zip(b).map(|(x, y)| *x || *y).collect())
                .collect(),
        }
    }

    /// The slots as sets of group indices: each group of positive degree in the first slots
    /// free of the groups it shares a term with, the groups of higher degree first; `None`
    /// when some group finds too few.
    fn slots(&self) -> Option<Vec<Vec<usize>>> {
        let m = self.group_degrees.len();
        let mut order: Vec<usize> = (0..m).filter(|j| self.group_degrees[*j] > 0).collect();
        order.sort_by_key(|j| std::cmp::Reverse(self.group_degrees[*j]));
        let mut slots: Vec<Vec<usize>> = vec![Vec::new(); self.degree as usize];
        for j in order {
            let wanted = self.group_degrees[j] as usize;
            let free: Vec<usize> = (0..slots.len())
                .filter(|s| slots[*s].iter().all(|k| !self.together[j][*k]))
                .take(wanted)
                .collect();
            if free.len() < wanted {
                return None;
            }
            for s in free {
                slots[s].push(j);
            }
        }
        // A slot no group took (a term of lower degree) holds the homogenising coordinate
        // alone in the start system; giving it every variable keeps the start equation generic.
        for slot in &mut slots {
            if slot.is_empty() {
                *slot = (0..m).collect();
            }
        }
        Some(slots)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::{C64, Poly};

    fn var(n: usize, i: usize) -> Poly {
        Poly::variable(n, i)
    }

    /// A generic hyperplane of `n` variables.
    fn plane(n: usize, seed: f64) -> Poly {
        (0..n).fold(Poly::constant(n, C64::new(seed, 0.3)), |h, j| {
            &h + &var(n, j).scale(C64::new(1.0 + j as f64 * seed, -0.5))
        })
    }

    /// The eigenvalue problem `A v = λ v`, `c·v = 1` in `(v, λ)`: `n` bilinear equations and
    /// one linear one. Its set structure `{v}{λ}` per equation has `n` roots, the number of
    /// eigenvalues (hand count: the `λ` slot can be chosen by one equation only, the other
    /// `n − 1` and the normalisation cover `v`), where the total degree is `2ⁿ`.
    #[test]
    fn eigenvalue_problem_counts_its_eigenvalues() {
        for n in 2..7 {
            let nv = n + 1;
            let lambda = var(nv, n);
            let mut eqs: Vec<Poly> = (0..n)
                .map(|i| {
                    let av = (0..n).fold(Poly::zero(nv), |s, j| {
                        &s + &var(nv, j).scale(C64::new(((i * 7 + j * 3) % 5) as f64 + 0.5, 0.0))
                    });
                    &av - &(&lambda * &var(nv, i))
                })
                .collect();
            eqs.push(&(0..n).fold(Poly::zero(nv), |s, j| &s + &var(nv, j)) - &Poly::real(nv, 1.0));
            let names = (0..nv).map(|k| format!("z{k}")).collect();
            let system = System::new(names, eqs)
                .unwrap()
                .with_groups(vec![(0..n).collect(), vec![n]])
                .unwrap();
            assert_eq!(
                SetStructure::of(&system).count(),
                Some(n as u128),
                "n = {n}"
            );
            assert_eq!(system.bezout_number(), 1 << n);
        }
    }

    /// Dense hyperplanes are one slot of every variable: `n` of them in `n` unknowns have one
    /// root (where the multi-homogeneous count of groups `{x0}…{x_{n−1}}` is `n!`).
    #[test]
    fn hyperplanes_are_one_slot() {
        let n = 5;
        let eqs: Vec<Poly> = (0..n).map(|k| plane(n, 0.1 * k as f64 + 0.2)).collect();
        let names = (0..n).map(|k| format!("z{k}")).collect();
        let system = System::new(names, eqs)
            .unwrap()
            .with_groups((0..n).map(|k| vec![k]).collect())
            .unwrap();
        let s = SetStructure::of(&system);
        assert!(
            s.equations()
                .iter()
                .all(|e| e.supports == vec![((0..n).collect(), 1)])
        );
        assert_eq!(s.count(), Some(1));
        assert_eq!(system.multihomogeneous_bezout(), Some(120));
    }

    /// Groups that share a term and together exceed the degree fall back to every variable in
    /// every slot: `x·t + x² + t² − 1` has degree 2 and two slots of `{x, t}`.
    #[test]
    fn shared_terms_beyond_the_degree_fall_back() {
        let (x, t) = (var(2, 0), var(2, 1));
        let f = &(&(&x * &t) + &(&x * &x)) + &(&(&t * &t) - &Poly::real(2, 1.0));
        let g = &x - &t;
        let system = System::new(vec!["x".into(), "t".into()], vec![f, g])
            .unwrap()
            .with_groups(vec![vec![0], vec![1]])
            .unwrap();
        let s = SetStructure::of(&system);
        assert_eq!(s.equations()[0].supports, vec![(vec![0, 1], 2)]);
        assert_eq!(s.count(), Some(2));
    }

    /// Groups that never share a term share slots: `x² + t² − 1` is `{x, t}{x, t}`.
    #[test]
    fn groups_apart_share_slots() {
        let (x, t) = (var(2, 0), var(2, 1));
        let f = &(&(&x * &x) + &(&t * &t)) - &Poly::real(2, 1.0);
        let system = System::new(vec!["x".into(), "t".into()], vec![f.clone(), f])
            .unwrap()
            .with_groups(vec![vec![0], vec![1]])
            .unwrap();
        let s = SetStructure::of(&system);
        assert_eq!(s.equations()[0].supports, vec![(vec![0, 1], 2)]);
        assert_eq!(s.count(), Some(4));
    }
}
