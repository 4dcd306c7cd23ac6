//! **Operation modes** of a manipulator whose constraints are polynomial in the Study
//! parameters of its platform ([`Manipulator::constraint_system`]): the irreducible components
//! of its solution set, found by numerical irreducible decomposition
//! ([`crate::homotopy::regenerate`] or [`crate::homotopy::decompose`]), each with the motion
//! of the platform in it.
//!
//! At fixed inputs the components are the **assemblies** (dimension 0) and the **self-motions**
//! (positive dimension: the platform moves while every input is held). With the inputs free
//! (their half-angle tangents unknowns), the components are the **operation modes** over input
//! and pose space; a mode's dimension is its number of degrees of freedom.
//!
//! The motion of the platform in a component is classified with [`crate::motion::classify`]
//! from real points of it: the tangent space of the constraint variety there (the null space of
//! the constraint Jacobian, of the component's dimension at a smooth point) gives the platform's
//! twists, by central differences of the Study parameters' displacements; a short walk along the
//! component (steps corrected back onto it by minimum-norm Newton steps) gives further samples,
//! so that a displacement group is named only when the motion is seen to stay in it. An
//! assembly's **operation mode** is found the same way with the inputs released: the component of
//! the free-input variety through it, its local dimension and motion.

use super::Manipulator;
use super::polynomial::{InputValues, PositionSystem, PositionSystemError};
use crate::geometry::Chart;
use crate::homotopy::{
    C64, Component, DecomposeError, DecomposeSettings, Decomposition, RegenerationProgress,
    decompose, points_on_slice, regenerate_with_progress,
};
use crate::motion::{self, Classification};
use crate::poly::Program;
use crate::spatial::{Displacement, compose, inverse, log, study};
use nalgebra::{DMatrix, DVector};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rand_distr::StandardNormal;

/// Which decomposition algorithm.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DecompositionMethod {
    /// Equation-by-equation regeneration ([`crate::homotopy::regenerate`]): fewer paths on
    /// large systems, but it can lose components through singular intermediate endpoints at
    /// special inputs (docs/operation-modes.md).
    Regeneration,
    /// Witness supersets dimension by dimension ([`crate::homotopy::decompose`]): the default,
    /// robust on the small systems of a manipulator at fixed inputs.
    #[default]
    ByDimension,
}

/// How to find the operation modes.
#[derive(Debug, Clone, PartialEq)]
pub struct OperationModeSettings {
    /// The decomposition's settings (seed, tolerances).
    pub decompose: DecomposeSettings,
    /// The algorithm.
    pub method: DecompositionMethod,
    /// Samples of each motion: the real point and the ends of walks from it.
    pub samples: usize,
    /// The length of one walk step, in the units of the Study parameters (dimensionless).
    pub step: f64,
    /// The random real slices a positive-dimensional component is cut with for real points
    /// besides its real witness points.
    pub real_slices: usize,
}

impl Default for OperationModeSettings {
    fn default() -> Self {
        Self {
            decompose: DecomposeSettings::default(),
            method: DecompositionMethod::default(),
            samples: 4,
            step: 0.05,
            real_slices: 8,
        }
    }
}

/// Why the operation modes cannot be found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OperationModeError {
    /// The manipulator has no polynomial constraint system here.
    #[error(transparent)]
    System(#[from] PositionSystemError),
    /// The decomposition failed.
    #[error(transparent)]
    Decompose(#[from] DecomposeError),
}

/// The motion of the platform at a real point of a component.
#[derive(Debug, Clone, PartialEq)]
pub struct LocalMotion {
    /// The real point (the system's variables).
    pub point: Vec<f64>,
    /// The platform's pose there.
    pub pose: Displacement,
    /// The dimension of the component at the point (the null space of the constraint
    /// Jacobian): its degrees of freedom.
    pub dof: usize,
    /// The platform's motion, from the point and walks along the component.
    pub motion: Classification,
}

/// One irreducible component of the constraint variety.
#[derive(Debug, Clone, PartialEq)]
pub struct ModeComponent {
    /// Its dimension: degrees of freedom (free inputs) or of the self-motion (fixed inputs).
    pub dimension: usize,
    /// Its degree.
    pub degree: usize,
    /// Its multiplicity: 1 when reduced, at least 2 for a non-reduced component (found by
    /// deflation).
    pub multiplicity: usize,
    /// Whether the trace test confirmed it.
    pub trace_test_passed: bool,
    /// A (complex) witness point.
    pub sample: Vec<C64>,
    /// Whether a real witness point was found and its motion, else `None`.
    pub real: Option<LocalMotion>,
    /// The real points found: the real witness points (isolated assemblies have one), then
    /// for a positive dimension those on random real slices.
    pub real_points: Vec<Vec<f64>>,
    /// For a real assembly (dimension 0 at fixed inputs): the operation mode through it with
    /// the inputs released; `None` where that variety is singular, or where an input is half a
    /// turn from the reference (its `tan(δ/2)` is infinite).
    pub released: Option<LocalMotion>,
}

/// The operation modes of one block of a manipulator's body tree
/// ([`Manipulator::block_operation_modes_with_progress`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BlockModes {
    /// The body: an index into [`Manipulator::bodies`].
    pub body: usize,
    /// Its parent: an index into [`Manipulator::bodies`]; `None` for the ground.
    pub parent: Option<usize>,
    /// The components of its constraint variety, in the Study parameters of its frame
    /// relative to its parent's.
    pub modes: OperationModes,
}

/// The components of a manipulator's constraint variety.
#[derive(Debug, Clone, PartialEq)]
pub struct OperationModes {
    /// The system decomposed.
    pub system: PositionSystem,
    /// Whether the inputs were free.
    pub free_inputs: bool,
    /// The decomposition.
    pub decomposition: Decomposition,
    /// The components, by decreasing dimension.
    pub components: Vec<ModeComponent>,
}

/// A point is real when every imaginary part is below this fraction of `1 + |x|`.
const REAL: f64 = 1e-7;

impl Manipulator {
    /// The components of the constraint variety at the given inputs (assemblies and
    /// self-motions, each real assembly with its operation mode), or over input and pose space
    /// with [`InputValues::Free`] (module documentation). The Study parameters are normalised
    /// by `x0² + x1² + x2² + x3² = 1` ([`Chart::Unit`]), so each pose appears twice, as `±(x, y)`.
    ///
    /// # Errors
    /// [`OperationModeError`] when the legs have no polynomial form or the decomposition fails.
    pub fn operation_modes(
        &self,
        inputs: &InputValues,
        settings: &OperationModeSettings,
    ) -> Result<OperationModes, OperationModeError> {
        self.operation_modes_with_progress(inputs, settings, &mut |_| {})
    }

    /// [`Self::operation_modes`], reporting the regeneration's progress (after each equation;
    /// nothing with [`DecompositionMethod::ByDimension`]).
    ///
    /// # Errors
    /// As [`Self::operation_modes`].
    pub fn operation_modes_with_progress(
        &self,
        inputs: &InputValues,
        settings: &OperationModeSettings,
        progress: &mut dyn FnMut(RegenerationProgress),
    ) -> Result<OperationModes, OperationModeError> {
        let system = self.constraint_system(inputs, &Chart::Unit)?;
        let released = match inputs {
            InputValues::Free => None,
            InputValues::Given(_) => {
                Some(self.constraint_system(&InputValues::Free, &Chart::Unit)?)
            }
        };
        let centre = self.reference_point((None, self.end_effector, &system));
        self.modes_of(
            system,
            released.as_ref(),
            inputs,
            settings,
            centre.as_deref(),
            progress,
        )
    }

    /// The operation modes of each block of the body tree ([`Manipulator::body_blocks`];
    /// one block for a one-platform manipulator): each body's frame relative to its parent's,
    /// decomposed on its own ([`Self::operation_modes_with_progress`] for each). The
    /// components of the mechanism are the products of one component per block: their
    /// dimensions add, their degrees multiply.
    ///
    /// # Errors
    /// As [`Self::operation_modes`] and [`Manipulator::body_blocks`].
    pub fn block_operation_modes_with_progress(
        &self,
        inputs: &InputValues,
        settings: &OperationModeSettings,
        progress: &mut dyn FnMut(RegenerationProgress),
    ) -> Result<Vec<BlockModes>, OperationModeError> {
        let blocks = self.body_blocks(inputs, &Chart::Unit)?;
        let mut released = match inputs {
            InputValues::Free => None,
            InputValues::Given(_) => Some(
                self.body_blocks(&InputValues::Free, &Chart::Unit)?
                    .into_iter(),
            ),
        };
        blocks
            .into_iter()
            .map(|b| {
                let free = released.as_mut().and_then(Iterator::next).map(|r| r.system);
                let centre = self.reference_point((b.parent, b.body, &b.system));
                Ok(BlockModes {
                    body: b.body,
                    parent: b.parent,
                    modes: self.modes_of(
                        b.system,
                        free.as_ref(),
                        inputs,
                        settings,
                        centre.as_deref(),
                        progress,
                    )?,
                })
            })
            .collect()
    }

    /// The components of the constraint variety of `system` (`released`: the same with the
    /// inputs free, for the operation mode of each real assembly; `centre`: the reference
    /// configuration's point, through which real slices are cut first).
    fn modes_of(
        &self,
        system: PositionSystem,
        released: Option<&PositionSystem>,
        inputs: &InputValues,
        settings: &OperationModeSettings,
        centre: Option<&[f64]>,
        progress: &mut dyn FnMut(RegenerationProgress),
    ) -> Result<OperationModes, OperationModeError> {
        let free = matches!(inputs, InputValues::Free);
        let decomposition = match settings.method {
            DecompositionMethod::Regeneration => {
                regenerate_with_progress(system.system(), &settings.decompose, progress)?
            }
            DecompositionMethod::ByDimension => decompose(system.system(), &settings.decompose)?,
        };
        let mut rng = ChaCha8Rng::seed_from_u64(settings.decompose.seed);
        let given: Vec<(usize, f64)> = match inputs {
            InputValues::Given(g) => g.to_vec(),
            InputValues::Free => Vec::new(),
        };
        // Components on which a body of the block lies on the null cone (a member's joint at
        // tan(θ/2) = ±i) solve the equations without being configurations: dropped.
        let mut decomposition = decomposition;
        decomposition
            .components
            .retain(|c| !c.witness_points.iter().all(|x| system.on_null_cone(x)));
        let components = decomposition
            .components
            .iter()
            .map(|c| {
                let witness = c.witness_points.iter().filter_map(|x| real_point(x));
                let real_points: Vec<Vec<f64>> = if c.dimension > 0 {
                    let (near, far) =
                        real_slices(&system, &decomposition, c, settings, centre, &mut rng);
                    near.into_iter().chain(witness).chain(far).collect()
                } else {
                    witness.collect()
                };
                let real = real_points
                    .first()
                    .and_then(|p| self.local_motion(&system, p, settings, &mut rng));
                let released = match (released, real_points.first()) {
                    (Some(free_system), Some(p)) if c.dimension == 0 => {
                        let q =
                            released_point(&system, free_system, p, &given, self.actuators.len());
                        q.and_then(|q| self.local_motion(free_system, &q, settings, &mut rng))
                    }
                    _ => None,
                };
                ModeComponent {
                    dimension: c.dimension,
                    degree: c.degree,
                    trace_test_passed: c.trace_test_passed,
                    multiplicity: c.multiplicity,
                    sample: c.sample_point.clone(),
                    real,
                    real_points,
                    released,
                }
            })
            .collect();
        Ok(OperationModes {
            system,
            free_inputs: free,
            decomposition,
            components,
        })
    }

    /// The motion of the platform on the constraint variety of `system` near its real point
    /// `p`: the tangent space there, and walks along the variety (module documentation).
    fn local_motion(
        &self,
        system: &PositionSystem,
        p: &[f64],
        settings: &OperationModeSettings,
        rng: &mut ChaCha8Rng,
    ) -> Option<LocalMotion> {
        let program = system.system().program();
        let (twists, dof) = self.tangent_twists(system, &program, p)?;
        let pose = system.displacement(p).ok()?;
        let mut spans = vec![twists];
        let mut poses = vec![pose];
        if dof > 0 {
            for _ in 1..settings.samples {
                let Some(q) = walk(&program, p, settings.step, rng) else {
                    continue;
                };
                // A walk that ends where another did (with one dof there are two directions)
                // adds no sample: the samples' separation is between distinct poses.
                if let (Some((t, d)), Ok(g)) = (
                    self.tangent_twists(system, &program, &q),
                    system.displacement(&q),
                ) && d == dof
                    && poses
                        .iter()
                        .all(|o| (o.to_homogeneous() - g.to_homogeneous()).amax() > 1e-9)
                {
                    spans.push(t);
                    poses.push(g);
                }
            }
        }
        let mut separation = f64::INFINITY;
        for (i, a) in poses.iter().enumerate() {
            for b in &poses[i + 1..] {
                separation = separation.min(self.mechanism.pose_distance(a, b));
            }
        }
        let motion = motion::classify(&spans, separation, motion::SUBSPACE_TOLERANCE);
        Some(LocalMotion {
            point: p.to_vec(),
            pose,
            dof,
            motion,
        })
    }

    /// The platform's twists (dimensionless, [`crate::mechanism::Mechanism::unitless_twists`])
    /// along the tangent space of the constraint variety at `p`, and its dimension.
    fn tangent_twists(
        &self,
        system: &PositionSystem,
        program: &Program,
        p: &[f64],
    ) -> Option<(DMatrix<f64>, usize)> {
        let null = tangent_space(program, p)?;
        let dof = null.ncols();
        let h = 1e-6;
        let mut twists = DMatrix::zeros(6, dof);
        for k in 0..dof {
            let shifted = |sign: f64| -> Option<Displacement> {
                let q: Vec<f64> = p
                    .iter()
                    .enumerate()
                    .map(|(i, x)| x + sign * h * null[(i, k)])
                    .collect();
                let z: Vec<C64> = q.iter().map(|v| C64::new(*v, 0.0)).collect();
                let s = system.study(&z)?.map(|c| c.re);
                study::to_displacement(&study::normalise(&s).ok()?, 1e-6).ok()
            };
            let (plus, minus) = (shifted(1.0)?, shifted(-1.0)?);
            let twist = log(&compose(&plus, &inverse(&minus))).to_vector() / (2.0 * h);
            twists.set_column(k, &twist);
        }
        Some((self.mechanism.unitless_twists(&twists), dof))
    }
}

/// The real point of a complex one, if it is real.
fn real_point(x: &[C64]) -> Option<Vec<f64>> {
    let size: f64 = 1.0 + x.iter().map(C64::norm_sqr).sum::<f64>().sqrt();
    x.iter()
        .all(|v| v.im.abs() <= REAL * size)
        .then(|| x.iter().map(|v| v.re).collect())
}

/// Real points of a positive-dimensional component: its points on random **real** slices,
/// [`OperationModeSettings::real_slices`] of them — real linear spaces of complementary
/// dimension through the reference configuration's point `centre` or its antipode `−x` (half
/// of them; the component through the reference meets them there, and the others near the
/// mechanism's own scale), through the real part of a witness point, or through the origin (with the unit
/// chart the Study parameters' `x` lie on a sphere about it, which every real line through
/// the origin meets). The points of the slices through `centre`, then the others, each
/// nearest `centre` first. Not every
/// real point is a configuration: a leg may reach it only with complex joint values (its
/// reach, an inequality, is not among the equations), so the mechanism is placed on the first
/// the legs reach ([`Manipulator::component_motion`]).
fn real_slices(
    system: &PositionSystem,
    decomposition: &Decomposition,
    c: &Component,
    settings: &OperationModeSettings,
    centre: Option<&[f64]>,
    rng: &mut ChaCha8Rng,
) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let n = system.system().nvars();
    let origin = vec![C64::new(0.0, 0.0); n];
    // The reference, and its antipode: the same configuration (the unit chart's `−x`, the
    // joints' unknowns unchanged), on the other copy of its component.
    let k = system.study_unknowns();
    let reference: Option<[Vec<C64>; 2]> = centre.map(|x| {
        let plus: Vec<C64> = x.iter().map(|v| C64::new(*v, 0.0)).collect();
        let mut minus = plus.clone();
        for v in &mut minus[..k] {
            *v = -*v;
        }
        [plus, minus]
    });
    let (mut near, mut far) = (Vec::new(), Vec::new());
    for attempt in 0..settings.real_slices {
        let through = match (attempt % 4, &reference) {
            (0 | 1, Some(r)) => &r[attempt % 2],
            (2, _) | (0 | 1, None) => &c.witness_points[(attempt / 4) % c.witness_points.len()],
            _ => &origin,
        };
        let slice: Vec<Vec<C64>> = (0..c.dimension)
            .map(|_| {
                let a: Vec<f64> = (0..n)
                    .map(|_| rng.sample::<f64, _>(StandardNormal))
                    .collect();
                let b: f64 = -a.iter().zip(through).map(|(a, x)| a * x.re).sum::<f64>();
                a.into_iter().chain([b]).map(C64::from).collect()
            })
            .collect();
        let Ok(points) = points_on_slice(
            system.system(),
            decomposition,
            c,
            &slice,
            &settings.decompose,
        ) else {
            continue;
        };
        let real = points.iter().filter_map(|x| real_point(x));
        if attempt % 4 < 2 && reference.is_some() {
            near.extend(real);
        } else {
            far.extend(real);
        }
    }
    // Nearest the reference first: the reference itself on its own component, and elsewhere
    // the points most likely within the legs' reach.
    if let Some([plus, minus]) = &reference {
        let from = |x: &Vec<f64>, r: &Vec<C64>| -> f64 {
            x.iter().zip(r).map(|(a, b)| (a - b.re).powi(2)).sum()
        };
        let distance = |x: &Vec<f64>| from(x, plus).min(from(x, minus));
        near.sort_by(|a, b| distance(a).total_cmp(&distance(b)));
        far.sort_by(|a, b| distance(a).total_cmp(&distance(b)));
    }
    (near, far)
}

/// The point of the free-input variety of an assembly `p` at the given inputs: the Study
/// parameters, then `tan(δ/2)` of each input's displacement (0 for those not given).
fn released_point(
    fixed: &PositionSystem,
    free: &PositionSystem,
    p: &[f64],
    given: &[(usize, f64)],
    actuators: usize,
) -> Option<Vec<f64>> {
    // The unknowns both systems share (the Study parameters, the joints of a block's members)
    // by name; the free inputs' tangents below.
    let names = fixed.system().variables();
    let mut q: Vec<f64> = free
        .system()
        .variables()
        .iter()
        .map(|v| names.iter().position(|n| n == v).map_or(0.0, |k| p[k]))
        .collect();
    for a in 0..actuators {
        let delta = given.iter().find(|(i, _)| *i == a).map_or(0.0, |(_, v)| *v);
        // A free input that is a passive joint of its leg has no variable to set.
        let Some(variable) = free.input_variable(a) else {
            continue;
        };
        // An input half a turn from the reference has no finite tangent of its half angle.
        if (delta / 2.0).cos().abs() < 1e-6 {
            return None;
        }
        q[variable] = (delta / 2.0).tan();
    }
    Some(q)
}

/// The constraint values and Jacobian (rows: equations) of the compiled system at the real
/// point `p`.
fn jacobian(program: &Program, p: &[f64]) -> (DVector<f64>, DMatrix<f64>) {
    let (m, n) = (program.len(), program.nvars());
    let x: Vec<C64> = p.iter().map(|v| C64::from(*v)).collect();
    let mut values = vec![C64::from(0.0); m];
    let mut j = vec![C64::from(0.0); m * n];
    program.evaluate_with_jacobian(&x, &mut values, &mut j, &mut program.workspace());
    (
        DVector::from_iterator(m, values.iter().map(|v| v.re)),
        DMatrix::from_row_iterator(m, n, j.iter().map(|v| v.re)),
    )
}

/// An orthonormal basis of the null space of the constraint Jacobian at `p` (singular values
/// below `1e-8` of the largest dropped).
fn tangent_space(program: &Program, p: &[f64]) -> Option<DMatrix<f64>> {
    let (_, j) = jacobian(program, p);
    let n = j.ncols();
    // Zero rows added so that the SVD's Vᵀ is square: all n right singular vectors.
    let mut padded = DMatrix::zeros(j.nrows().max(n), n);
    padded.rows_mut(0, j.nrows()).copy_from(&j);
    let svd = padded.svd(false, true);
    let v_t = svd.v_t?;
    let largest = svd.singular_values.max();
    let kept: Vec<usize> = (0..n)
        .filter(|k| svd.singular_values[*k] <= 1e-8 * largest)
        .collect();
    let mut basis = DMatrix::zeros(n, kept.len());
    for (c, k) in kept.iter().enumerate() {
        basis.set_column(c, &v_t.row(*k).transpose());
    }
    Some(basis)
}

/// A point of the variety a step away from `p` in a random tangent direction, corrected back
/// onto it by minimum-norm Newton steps.
fn walk(program: &Program, p: &[f64], step: f64, rng: &mut ChaCha8Rng) -> Option<Vec<f64>> {
    let null = tangent_space(program, p)?;
    if null.ncols() == 0 {
        return None;
    }
    let c = DVector::from_fn(null.ncols(), |_, _| rng.sample::<f64, _>(StandardNormal));
    let d = &null * c;
    let mut q = DVector::from_column_slice(p) + d.normalize() * step;
    for _ in 0..30 {
        let (f, j) = jacobian(program, q.as_slice());
        if f.norm() < 1e-13 {
            return Some(q.iter().copied().collect());
        }
        let dq = j.svd(true, true).solve(&f, 1e-10).ok()?;
        q -= dq;
    }
    let (f, _) = jacobian(program, q.as_slice());
    (f.norm() < 1e-10).then(|| q.iter().copied().collect())
}
