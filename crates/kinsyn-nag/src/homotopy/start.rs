//! Start systems and the projective γ-trick homotopy
//! `H(z, t) = (1 − t) F̂(z) + γ t Ĝ(z)` with one random affine patch per variable group.
//!
//! `F̂` is the target system homogenised per group (one new coordinate `h_j` per group), so that
//! paths whose affine coordinates diverge stay bounded and end at points with `h_j = 0`: the
//! solutions at infinity. Each group's projective coordinates are fixed on the random
//! hyperplane `a_j · z_j = 1` (Morgan 1986, *A transformation to avoid solutions at infinity*).
//! For generic complex `γ` the paths from the start solutions at `t = 1` are non-singular for
//! `t ∈ (0, 1]` with probability one (the γ-trick: Morgan & Sommese 1987; Sommese & Wampler,
//! *The Numerical Solution of Systems of Polynomials*, 2005, §8.3).
//!
//! Start systems:
//! - **total degree**, one group: `Ĝ_i = z_i^{d_i} − h^{d_i}`, whose `Π d_i` solutions are the
//!   roots of unity;
//! - **multi-homogeneous** (linear products): `Ĝ_i = Π_j Π_{k ≤ d_ij} L_ijk(z_j)` with random
//!   linear forms `L`, `d_ij` the degree of equation `i` in group `j`; its solutions, one per
//!   choice of a factor in each equation that gives each group as many linear equations as it
//!   has variables, number the multi-homogeneous Bézout number (Morgan & Sommese 1987,
//!   *Coefficient-parameter polynomial continuation*; Wampler 1992).

use super::C64;
use super::tracker::Homotopy;
use crate::poly::linear_product::{SetStructure, SupportChoice};
use crate::poly::multihomogeneous::Assignments;
use crate::poly::{Program, System, Workspace};
use nalgebra::{DMatrix, DVector};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// Which start system to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StartSystem {
    /// `z_i^{d_i} − h^{d_i}`: Bézout's number of paths.
    #[default]
    TotalDegree,
    /// Products of random linear forms per variable group: the multi-homogeneous Bézout
    /// number of paths, for the system's variable groups.
    MultiHomogeneous,
    /// Products of random linear forms, one per slot of the system's set structure from its
    /// variable groups ([`crate::poly::linear_product`]): the same as the multi-homogeneous
    /// start for equations of one group per term, and far fewer paths when some equations
    /// are dense in several groups (a generic slice, a random combination of equations).
    LinearProduct,
    /// The polyhedral homotopy: a start system with the target's supports (and the origin)
    /// and random coefficients, solved by the mixed cells of a random lifting: the mixed
    /// volume's number of paths (the BKK bound), never more than Bézout's
    /// ([`crate::polyhedral`]).
    Polyhedral,
    /// Whichever of the others tracks the fewest paths ([`super::resolve_start`]): the total
    /// degree, the multi-homogeneous start for the system's variable groups (when it has more
    /// than one), or the polyhedral start when its mixed cells are found within
    /// [`super::AUTO_PROGRAMS_PER_PATH`] linear programs per path of the best of the other two.
    /// A report names the start chosen.
    Auto,
}

impl StartSystem {
    /// Every start system, in the order of the command line's choices.
    pub const ALL: [Self; 5] = [
        Self::Auto,
        Self::TotalDegree,
        Self::MultiHomogeneous,
        Self::LinearProduct,
        Self::Polyhedral,
    ];

    /// The name the command line and JSON give it: `auto`, `total-degree`,
    /// `multi-homogeneous`, `linear-product`, `polyhedral`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::TotalDegree => "total-degree",
            Self::MultiHomogeneous => "multi-homogeneous",
            Self::LinearProduct => "linear-product",
            Self::Polyhedral => "polyhedral",
            Self::Auto => "auto",
        }
    }

    /// The start system of a [`Self::name`].
    #[must_use]
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// The start system that tracks the fewest paths for the square `system`: the total degree,
/// the multi-homogeneous start of one of the variable groupings `candidates` (each a partition
/// of the variables into groups), whichever has the smallest Bézout number (ties keep the total
/// degree), or the polyhedral start when its mixed volume is smaller still and its mixed cells
/// (for the lifting of `seed`) are found within the budget of [`StartSystem::Auto`]. Returns the
/// system with the grouping chosen (its own when the total degree or the polyhedral start wins)
/// and the start. A grouping that is no partition, or whose states are too many to count, is
/// passed over.
#[must_use]
pub fn fewest_paths_start(
    system: &System,
    candidates: &[Vec<Vec<usize>>],
    seed: u64,
) -> (System, StartSystem) {
    let (chosen, start) = fewest_bezout_start(system, candidates);
    let paths = super::path_count(&chosen, start).unwrap_or(u128::MAX);
    if let Ok(cells) = super::polyhedral_subdivision(system, seed, super::auto_budget(paths))
        && cells.mixed_volume() < paths
    {
        return (system.clone(), StartSystem::Polyhedral);
    }
    (chosen, start)
}

/// [`fewest_paths_start`] among the total degree and the multi-homogeneous starts only.
fn fewest_bezout_start(system: &System, candidates: &[Vec<Vec<usize>>]) -> (System, StartSystem) {
    let total = system.bezout_number();
    let best = candidates
        .iter()
        .filter_map(|groups| {
            let grouped = system.clone().with_groups(groups.clone()).ok()?;
            let paths = grouped.multihomogeneous_bezout()?;
            (paths > 0).then_some((paths, grouped))
        })
        .min_by_key(|(paths, _)| *paths);
    match best {
        Some((paths, grouped)) if paths < total => (grouped, StartSystem::MultiHomogeneous),
        _ => (system.clone(), StartSystem::TotalDegree),
    }
}

fn random_complex(rng: &mut ChaCha8Rng) -> C64 {
    // A point uniform on the unit circle: generic, and of unit size.
    C64::from_polar(1.0, rng.random_range(0.0..std::f64::consts::TAU))
}

/// One equation's slot factors in a linear-product start: each support's variables (indices
/// into `z`, the homogenising coordinate last) and one row of coefficients over them per slot.
type SlotForms = Vec<(Vec<usize>, Vec<Vec<C64>>)>;

enum Start {
    TotalDegree(Vec<u32>),
    /// `[equation][group][factor]` → coefficients over the group's coordinates (its variables
    /// in group order, then its homogenising coordinate); and the assignments of equations to
    /// groups that complete, which the enumeration of the start solutions follows.
    MultiHomogeneous(Vec<Vec<Vec<Vec<C64>>>>, Assignments),
    /// `[equation][support]` → the support's variables (indices into `z`, the homogenising
    /// coordinate last) and one row of coefficients over them per slot; and the choices of
    /// supports with a finite root ([`crate::poly::linear_product`]).
    SetStructure(Vec<SlotForms>, Vec<SupportChoice>),
    /// A start system whose roots are found apart (the polyhedral homotopy's `G`,
    /// [`ProjectiveHomotopy::start_point`]): its homogenised program.
    Explicit(Program),
}

/// The γ-trick homotopy from a start system to a homogenised target, in projective coordinates
/// `z = (x_0 … x_{n−1}, h_0 … h_{m−1})` with one patch per group.
pub(crate) struct ProjectiveHomotopy {
    n: usize,
    /// Each group's coordinates in `z`: its variables then its homogenising coordinate.
    groups: Vec<Vec<usize>>,
    /// The random patches of the start solutions; each path then carries its own chart
    /// ([`ProjectiveWorkspace::patches`]).
    patches: Vec<Vec<C64>>,
    target: Program,
    /// The homogenised target with every coefficient replaced by its modulus: the size of each
    /// equation's terms, which scales its row in the endpoint condition.
    magnitudes: Program,
    start: Start,
    gamma: C64,
}

/// The scratch of one path of a [`ProjectiveHomotopy`]: the evaluation buffers and the path's
/// chart.
pub(crate) struct ProjectiveWorkspace {
    program: Workspace<C64>,
    values: Vec<C64>,
    jacobian: Vec<C64>,
    start: Vec<C64>,
    /// The path's patch per group (`patches[j] · z_j = 1`): the random one at the start, then
    /// the unit normal of the point ([`Homotopy::rechart`]).
    patches: Vec<Vec<C64>>,
    magnitude_program: Workspace<C64>,
    magnitude_values: Vec<C64>,
    magnitude_jacobian: Vec<C64>,
    /// The evaluation scratch of an explicit start system.
    start_program: Option<Workspace<C64>>,
    start_jacobian: Vec<C64>,
}

impl ProjectiveHomotopy {
    /// The homotopy for `system` (square) with the given start system, random data drawn from
    /// `rng`.
    pub(crate) fn new(system: &System, kind: StartSystem, rng: &mut ChaCha8Rng) -> Self {
        let n = system.nvars();
        let variable_groups: Vec<Vec<usize>> = match kind {
            StartSystem::TotalDegree
            | StartSystem::LinearProduct
            | StartSystem::Polyhedral
            | StartSystem::Auto => {
                vec![(0..n).collect()]
            }
            StartSystem::MultiHomogeneous => system.groups().to_vec(),
        };
        let homogenised = system.homogenized(&variable_groups);
        let target = homogenised.program();
        let magnitudes = homogenised.magnitudes_program();
        let groups: Vec<Vec<usize>> = variable_groups
            .iter()
            .enumerate()
            .map(|(j, g)| g.iter().copied().chain([n + j]).collect())
            .collect();
        let patches = groups
            .iter()
            .map(|g| g.iter().map(|_| random_complex(rng)).collect())
            .collect();
        let start = match kind {
            // The polyhedral start is given with its roots (`with_start_system`).
            StartSystem::TotalDegree | StartSystem::Polyhedral | StartSystem::Auto => {
                Start::TotalDegree(system.degrees())
            }
            StartSystem::LinearProduct => {
                let structure = SetStructure::of(system);
                let choices = structure
                    .choices()
                    .expect("solve counts the set structure before it builds the homotopy");
                let forms = structure
                    .equations()
                    .iter()
                    .map(|e| {
                        e.supports
                            .iter()
                            .map(|(vars, slots)| {
                                let vars: Vec<usize> = vars.iter().copied().chain([n]).collect();
                                let rows = (0..*slots)
                                    .map(|_| vars.iter().map(|_| random_complex(rng)).collect())
                                    .collect();
                                (vars, rows)
                            })
                            .collect()
                    })
                    .collect();
                Start::SetStructure(forms, choices)
            }
            StartSystem::MultiHomogeneous => {
                let d = system.multihomogeneous_degrees();
                let assignments = system
                    .assignments()
                    .expect("solve counts the assignments before it builds the homotopy");
                Start::MultiHomogeneous(
                    d.iter()
                        .map(|row| {
                            row.iter()
                                .zip(&groups)
                                .map(|(dij, g)| {
                                    (0..*dij)
                                        .map(|_| g.iter().map(|_| random_complex(rng)).collect())
                                        .collect()
                                })
                                .collect()
                        })
                        .collect(),
                    assignments,
                )
            }
        };
        let gamma = random_complex(rng);
        Self {
            n,
            groups,
            patches,
            target,
            magnitudes,
            start,
            gamma,
        }
    }

    /// The γ-trick homotopy from `start_system` (square, in the target's variables, each
    /// equation of the same degree as the target's) to `system`, in one projective group: the
    /// second stage of the polyhedral homotopy, whose start points are the start system's
    /// roots ([`Self::start_point`]).
    pub(crate) fn with_start_system(
        system: &System,
        start_system: &System,
        rng: &mut ChaCha8Rng,
    ) -> Self {
        let mut homotopy = Self::new(system, StartSystem::TotalDegree, rng);
        let everything = [(0..system.nvars()).collect::<Vec<_>>()];
        let homogenised: Vec<_> = start_system
            .equations()
            .iter()
            .zip(system.degrees())
            .map(|(p, d)| {
                debug_assert_eq!(
                    p.total_degree(),
                    d,
                    "a start equation of the target's degree"
                );
                p.homogenize(&everything)
            })
            .collect();
        homotopy.start = Start::Explicit(Program::new(&homogenised, system.nvars() + 1));
        homotopy
    }

    /// The start point of an explicit start system's affine root `x`: `(x, 1)` on the
    /// patches.
    pub(crate) fn start_point(&self, x: &[C64]) -> DVector<C64> {
        let z = DVector::from_iterator(self.n + 1, x.iter().copied().chain([C64::from(1.0)]));
        self.on_patches(z)
    }

    /// The start solutions, in a fixed order (the path numbers).
    pub(crate) fn start_solutions(&self) -> Vec<DVector<C64>> {
        match &self.start {
            Start::TotalDegree(degrees) => self.roots_of_unity(degrees),
            Start::MultiHomogeneous(forms, assignments) => {
                self.linear_product_solutions(forms, assignments)
            }
            Start::SetStructure(forms, choices) => self.set_structure_solutions(forms, choices),
            // An explicit start system's points come root by root ([`Self::start_point`]).
            Start::Explicit(_) => Vec::new(),
        }
    }

    fn roots_of_unity(&self, degrees: &[u32]) -> Vec<DVector<C64>> {
        let total: usize = degrees.iter().map(|d| *d as usize).product();
        let mut out = Vec::with_capacity(total);
        let mut digits = vec![0u32; degrees.len()];
        for _ in 0..total {
            let mut z = DVector::from_element(self.n + 1, C64::from(1.0));
            for (i, (k, d)) in digits.iter().zip(degrees).enumerate() {
                z[i] = C64::from_polar(1.0, std::f64::consts::TAU * f64::from(*k) / f64::from(*d));
            }
            out.push(self.on_patches(z));
            for (k, d) in digits.iter_mut().zip(degrees) {
                *k += 1;
                if *k < *d {
                    break;
                }
                *k = 0;
            }
        }
        out
    }

    /// Scales each group's coordinates onto its patch.
    fn on_patches(&self, mut z: DVector<C64>) -> DVector<C64> {
        for (g, a) in self.groups.iter().zip(&self.patches) {
            let dot: C64 = g.iter().zip(a).map(|(i, ai)| ai * z[*i]).sum();
            for i in g {
                z[*i] /= dot;
            }
        }
        z
    }

    fn linear_product_solutions(
        &self,
        forms: &[Vec<Vec<Vec<C64>>>],
        assignments: &Assignments,
    ) -> Vec<DVector<C64>> {
        let mut out = Vec::new();
        // Every assignment of equations to groups with group j receiving as many equations as
        // it has variables, and every choice of one factor per equation; only steps from
        // which the assignment completes are taken, so the walk costs the start solutions,
        // not the dead ends.
        let mut chosen = Vec::with_capacity(forms.len());
        self.assign(forms, assignments, 0, &mut chosen, &mut out);
        out
    }

    fn assign(
        &self,
        forms: &[Vec<Vec<Vec<C64>>>],
        assignments: &Assignments,
        state: usize,
        chosen: &mut Vec<(usize, usize)>,
        out: &mut Vec<DVector<C64>>,
    ) {
        let i = chosen.len();
        if i == forms.len() {
            if let Some(z) = self.solve_linear(forms, chosen) {
                out.push(z);
            }
            return;
        }
        for (j, factors) in forms[i].iter().enumerate() {
            let Some(next) = assignments.step(i, state, j) else {
                continue;
            };
            for k in 0..factors.len() {
                chosen.push((j, k));
                self.assign(forms, assignments, next, chosen, out);
                chosen.pop();
            }
        }
    }

    /// The roots of a linear-product start system: for each choice of supports, every
    /// choice of one slot per equation among the chosen support's, in mixed radix.
    fn set_structure_solutions(
        &self,
        forms: &[SlotForms],
        choices: &[SupportChoice],
    ) -> Vec<DVector<C64>> {
        let dim = self.n + 1;
        let mut out = Vec::new();
        for (supports, _) in choices {
            let chosen: Vec<&(Vec<usize>, Vec<Vec<C64>>)> =
                supports.iter().zip(forms).map(|(s, f)| &f[*s]).collect();
            let mut slot = vec![0usize; chosen.len()];
            loop {
                let mut a = DMatrix::zeros(dim, dim);
                let mut b = DVector::zeros(dim);
                for (i, ((vars, rows), k)) in chosen.iter().zip(&slot).enumerate() {
                    for (v, c) in vars.iter().zip(&rows[*k]) {
                        a[(i, *v)] = *c;
                    }
                }
                for (c, p) in self.patches[0].iter().enumerate() {
                    a[(self.n, c)] = *p;
                }
                b[self.n] = C64::from(1.0);
                if let Some(z) = a.lu().solve(&b) {
                    out.push(z);
                }
                // The next slot choice, the first equation's digit fastest.
                let mut i = 0;
                while i < slot.len() {
                    slot[i] += 1;
                    if slot[i] < chosen[i].1.len() {
                        break;
                    }
                    slot[i] = 0;
                    i += 1;
                }
                if i == slot.len() {
                    break;
                }
            }
        }
        out
    }

    /// The solution of the chosen linear factors and the patches, group by group.
    fn solve_linear(
        &self,
        forms: &[Vec<Vec<Vec<C64>>>],
        chosen: &[(usize, usize)],
    ) -> Option<DVector<C64>> {
        let mut z = DVector::zeros(self.n + self.groups.len());
        for (j, g) in self.groups.iter().enumerate() {
            let m = g.len();
            let mut a = DMatrix::zeros(m, m);
            let mut b = DVector::zeros(m);
            let mut row = 0;
            for (i, (jj, k)) in chosen.iter().enumerate() {
                if *jj == j {
                    for c in 0..m {
                        a[(row, c)] = forms[i][j][*k][c];
                    }
                    row += 1;
                }
            }
            for c in 0..m {
                a[(row, c)] = self.patches[j][c];
            }
            b[row] = C64::from(1.0);
            let x = a.lu().solve(&b)?;
            for (c, idx) in g.iter().enumerate() {
                z[*idx] = x[c];
            }
        }
        Some(z)
    }

    /// `Ĝ(z)` into `g` and its Jacobian into `gz`; `scratch` evaluates an explicit start
    /// system.
    fn start_values(
        &self,
        z: &DVector<C64>,
        g: &mut [C64],
        gz: &mut DMatrix<C64>,
        scratch: (&mut Option<Workspace<C64>>, &mut Vec<C64>),
    ) {
        match &self.start {
            Start::Explicit(program) => {
                let (ws, jacobian) = scratch;
                let ws = ws.get_or_insert_with(|| program.workspace());
                let dim = self.n + 1;
                jacobian.resize(self.n * dim, C64::from(0.0));
                program.evaluate_with_jacobian(z.as_slice(), g, jacobian, ws);
                for i in 0..self.n {
                    for c in 0..dim {
                        gz[(i, c)] = jacobian[i * dim + c];
                    }
                }
            }
            Start::TotalDegree(degrees) => {
                let h = z[self.n];
                for (i, d) in degrees.iter().enumerate() {
                    let d = i32::try_from(*d).unwrap_or(i32::MAX);
                    g[i] = z[i].powi(d) - h.powi(d);
                    gz[(i, i)] = z[i].powi(d - 1) * f64::from(d);
                    gz[(i, self.n)] = -h.powi(d - 1) * f64::from(d);
                }
            }
            Start::SetStructure(forms, _) => {
                for (i, row) in forms.iter().enumerate() {
                    let factors = row.iter().flat_map(|(vars, rows)| {
                        rows.iter().map(move |r| (vars.as_slice(), r.as_slice()))
                    });
                    g[i] = product_of_forms(factors, z, i, gz);
                }
            }
            Start::MultiHomogeneous(forms, _) => {
                for (i, row) in forms.iter().enumerate() {
                    let factors = row.iter().enumerate().flat_map(|(j, group_forms)| {
                        group_forms
                            .iter()
                            .map(move |f| (self.groups[j].as_slice(), f.as_slice()))
                    });
                    g[i] = product_of_forms(factors, z, i, gz);
                }
            }
        }
    }

    /// Each group's homogenising coordinate `h_j` over the size of the group's coordinates:
    /// near zero for a point at infinity.
    pub(crate) fn measure(&self, z: &DVector<C64>) -> f64 {
        self.groups
            .iter()
            .map(|g| {
                let h = z[*g.last().expect("a group has its homogenising coordinate")].norm();
                let size = g.iter().map(|i| z[*i].norm_sqr()).sum::<f64>().sqrt();
                h / size
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The affine point of a finite `z`: each variable over its group's homogenising coordinate.
    pub(crate) fn affine(&self, z: &DVector<C64>) -> Vec<C64> {
        let mut x = vec![C64::from(0.0); self.n];
        for g in &self.groups {
            let h = z[*g.last().expect("a group has its homogenising coordinate")];
            for i in &g[..g.len() - 1] {
                x[*i] = z[*i] / h;
            }
        }
        x
    }
}

impl Homotopy for ProjectiveHomotopy {
    type Workspace = ProjectiveWorkspace;

    fn at_infinity(&self, z: &DVector<C64>) -> bool {
        self.measure(z) < super::INFINITY_TOLERANCE * 1e-2
    }

    fn infinity_measure(&self, z: &DVector<C64>) -> Option<f64> {
        Some(self.measure(z))
    }

    fn dim(&self) -> usize {
        self.n + self.groups.len()
    }

    fn workspace(&self) -> ProjectiveWorkspace {
        let n = self.target.len();
        ProjectiveWorkspace {
            program: self.target.workspace(),
            values: vec![C64::from(0.0); n],
            jacobian: vec![C64::from(0.0); n * self.dim()],
            start: vec![C64::from(0.0); n],
            patches: self.patches.clone(),
            magnitude_program: self.magnitudes.workspace(),
            magnitude_values: vec![C64::from(0.0); n],
            magnitude_jacobian: vec![C64::from(0.0); n * self.dim()],
            start_program: None,
            start_jacobian: Vec::new(),
        }
    }

    fn rechart(&self, z: &mut DVector<C64>, ws: &mut ProjectiveWorkspace) {
        for (g, patch) in self.groups.iter().zip(&mut ws.patches) {
            let largest = g.iter().map(|i| z[*i].norm()).fold(0.0, f64::max);
            if !(largest > 0.0 && largest.is_finite()) {
                continue;
            }
            for i in g {
                z[*i] /= largest;
            }
            let size = g.iter().map(|i| z[*i].norm_sqr()).sum::<f64>();
            for (a, i) in patch.iter_mut().zip(g) {
                *a = z[*i].conj() / size;
            }
        }
    }

    fn inverse_condition(&self, z: &DVector<C64>, ws: &mut ProjectiveWorkspace) -> f64 {
        let dim = self.dim();
        // The same projective point with each group scaled to largest modulus 1: the
        // homogeneous rows only change by a factor, which the row scaling removes, and no
        // power of a coordinate overflows.
        let mut w = z.clone();
        for g in &self.groups {
            let largest = g.iter().map(|i| w[*i].norm()).fold(0.0, f64::max);
            if largest > 0.0 && largest.is_finite() {
                for i in g {
                    w[*i] /= largest;
                }
            }
        }
        self.target.evaluate_with_jacobian(
            w.as_slice(),
            &mut ws.values,
            &mut ws.jacobian,
            &mut ws.program,
        );
        let moduli = super::floored_moduli(w.as_slice(), 1.0);
        self.magnitudes.evaluate_with_jacobian(
            &moduli,
            &mut ws.magnitude_values,
            &mut ws.magnitude_jacobian,
            &mut ws.magnitude_program,
        );
        let mut m = DMatrix::zeros(dim, dim);
        let mut scales = vec![1.0; dim];
        for i in 0..self.n {
            for c in 0..dim {
                m[(i, c)] = ws.jacobian[i * dim + c];
            }
            scales[i] = ws.magnitude_jacobian[i * dim..(i + 1) * dim]
                .iter()
                .map(nalgebra::Complex::norm_sqr)
                .sum::<f64>()
                .sqrt();
        }
        for (j, g) in self.groups.iter().enumerate() {
            let size = g.iter().map(|i| w[*i].norm_sqr()).sum::<f64>().sqrt();
            for i in g {
                m[(self.n + j, *i)] = w[*i].conj() / size;
            }
        }
        super::scaled_inverse_condition(m, &scales)
    }

    fn evaluate(
        &self,
        z: &DVector<C64>,
        t: C64,
        ws: &mut ProjectiveWorkspace,
        h: &mut DVector<C64>,
        hz: &mut DMatrix<C64>,
        ht: &mut DVector<C64>,
    ) {
        let dim = self.dim();
        self.target.evaluate_with_jacobian(
            z.as_slice(),
            &mut ws.values,
            &mut ws.jacobian,
            &mut ws.program,
        );
        hz.fill(C64::from(0.0));
        self.start_values(
            z,
            &mut ws.start,
            hz,
            (&mut ws.start_program, &mut ws.start_jacobian),
        );
        let one_minus_t = C64::from(1.0) - t;
        let gt = self.gamma * t;
        for i in 0..self.n {
            h[i] = one_minus_t * ws.values[i] + gt * ws.start[i];
            ht[i] = self.gamma * ws.start[i] - ws.values[i];
            for c in 0..dim {
                hz[(i, c)] = one_minus_t * ws.jacobian[i * dim + c] + gt * hz[(i, c)];
            }
        }
        for (j, (grp, a)) in self.groups.iter().zip(&ws.patches).enumerate() {
            let row = self.n + j;
            h[row] = grp.iter().zip(a).map(|(i, ai)| ai * z[*i]).sum::<C64>() - C64::from(1.0);
            ht[row] = C64::from(0.0);
            for (i, ai) in grp.iter().zip(a) {
                hz[(row, *i)] = *ai;
            }
        }
    }
}

/// The product of the linear forms `factors` (each its coordinates' indices into `z` and its
/// coefficients) at `z`, its gradient added to row `i` of `gz` by the product rule: a start
/// equation of a multi-homogeneous or linear-product start system.
fn product_of_forms<'a>(
    factors: impl Iterator<Item = (&'a [usize], &'a [C64])>,
    z: &DVector<C64>,
    i: usize,
    gz: &mut DMatrix<C64>,
) -> C64 {
    let factors: Vec<(&[usize], &[C64], C64)> = factors
        .map(|(vars, c)| (vars, c, vars.iter().zip(c).map(|(v, a)| a * z[*v]).sum()))
        .collect();
    for (k, (vars, c, _)) in factors.iter().enumerate() {
        let others: C64 = factors
            .iter()
            .enumerate()
            .filter(|(l, _)| *l != k)
            .map(|(_, f)| f.2)
            .product();
        for (v, a) in vars.iter().zip(*c) {
            gz[(i, *v)] += a * others;
        }
    }
    factors.iter().map(|f| f.2).product()
}
