//! Parameter homotopies: a family of systems `F(x; p)` whose coefficients depend polynomially
//! on parameters `p` (the inputs of a manipulator, its leg lengths, its geometry), and the
//! solutions followed as `p` moves (Morgan & Sommese, *Coefficient-parameter polynomial
//! continuation*, Appl. Math. Comput. 29, 1989): a trajectory of inputs, or a solve at new
//! parameters from the solutions at generic ones — and **monodromy**, which fills the solution
//! set of a generic member of the family from a single solution by moving the parameters around
//! loops (Duff, Hill, Jensen, Lee, Leykin & Sommars, *Solving polynomial systems via homotopy
//! continuation and monodromy*, IMA J. Numer. Anal. 39, 2019).

use super::C64;
use super::tracker::{Homotopy, PathFailure, Tracker, TrackerSettings};
use crate::poly::{Poly, Program, System, Workspace};
use nalgebra::{DMatrix, DVector};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, StandardNormal};
use rayon::prelude::*;

/// Why a parametrised system cannot be formed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParameterError {
    /// The unknowns (variables less parameters) are not as many as the equations.
    #[error(
        "{equations} equations in {unknowns} unknowns (after {parameters} parameters): a square family is needed"
    )]
    NotSquare {
        /// Equations.
        equations: usize,
        /// Unknowns.
        unknowns: usize,
        /// Parameters.
        parameters: usize,
    },
    /// A parameter point of the wrong length.
    #[error("{found} parameter values given, the family has {expected}")]
    ParameterCount {
        /// The family's parameters.
        expected: usize,
        /// The values given.
        found: usize,
    },
    /// The start point does not solve the system at the start parameters.
    #[error("the start point is not a solution at the start parameters (residual {0:.3e})")]
    NotASolution(f64),
}

/// A square family of systems `F(x; p)`: a [`System`] whose last variables are the parameters.
#[derive(Debug, Clone)]
pub struct ParametrizedSystem {
    system: System,
    unknowns: usize,
    program: Program,
    /// The family with every coefficient replaced by its modulus (the scale of each
    /// equation's row in the endpoint condition).
    magnitudes: Program,
}

impl ParametrizedSystem {
    /// The family of `system` whose last `parameters` variables are parameters.
    ///
    /// # Errors
    /// [`ParameterError::NotSquare`] unless the remaining unknowns are as many as the equations.
    pub fn new(system: System, parameters: usize) -> Result<Self, ParameterError> {
        let unknowns = system.nvars().saturating_sub(parameters);
        if unknowns != system.len() || parameters > system.nvars() {
            return Err(ParameterError::NotSquare {
                equations: system.len(),
                unknowns,
                parameters,
            });
        }
        let program = system.program();
        let magnitudes = system.magnitudes_program();
        Ok(Self {
            system,
            unknowns,
            program,
            magnitudes,
        })
    }

    /// The number of unknowns.
    #[must_use]
    pub fn unknowns(&self) -> usize {
        self.unknowns
    }

    /// The number of parameters.
    #[must_use]
    pub fn parameters(&self) -> usize {
        self.system.nvars() - self.unknowns
    }

    /// The compiled family (values and Jacobian in unknowns and parameters).
    #[must_use]
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// The family's system (unknowns, then parameters).
    #[must_use]
    pub fn system(&self) -> &System {
        &self.system
    }

    /// The member of the family at the parameters `p`: a system in the unknowns alone.
    ///
    /// # Errors
    /// [`ParameterError::ParameterCount`] if `p` has the wrong length.
    ///
    /// # Panics
    /// Never: the member keeps the family's own (distinct) variable names.
    pub fn at(&self, p: &[C64]) -> Result<System, ParameterError> {
        self.check(p)?;
        let n = self.unknowns;
        let fix = |f: &Poly| {
            Poly::from_terms(
                n,
                f.terms().map(|(e, c)| {
                    let value = e[n..].iter().zip(p).fold(c, |acc, (k, v)| acc * v.powu(*k));
                    (e[..n].to_vec(), value)
                }),
            )
        };
        Ok(self
            .system
            .mapped(self.system.variables()[..n].to_vec(), fix)
            .expect("the family's own names"))
    }

    /// The largest `|f_i(x; p)|`.
    #[must_use]
    pub fn residual(&self, x: &[C64], p: &[C64]) -> f64 {
        let point: Vec<C64> = x.iter().chain(p).copied().collect();
        self.system
            .evaluate(&point)
            .iter()
            .map(|v| v.norm())
            .fold(0.0, f64::max)
    }

    fn check(&self, p: &[C64]) -> Result<(), ParameterError> {
        if p.len() == self.parameters() {
            Ok(())
        } else {
            Err(ParameterError::ParameterCount {
                expected: self.parameters(),
                found: p.len(),
            })
        }
    }
}

/// The straight segment from `from` (at `t = 1`) to `to` (at `t = 0`) in parameter space.
struct Segment<'a> {
    family: &'a ParametrizedSystem,
    from: &'a [C64],
    to: &'a [C64],
    /// Whether the endgame may find paths diverging in these affine coordinates (measured by
    /// `1 / (1 + |x|)`): the end member may have fewer solutions than the start.
    may_diverge: bool,
}

/// Scratch of a [`Segment`] evaluation.
struct SegmentWorkspace {
    program: Workspace<C64>,
    point: Vec<C64>,
    values: Vec<C64>,
    jacobian: Vec<C64>,
    magnitude_program: Workspace<C64>,
}

impl Homotopy for Segment<'_> {
    type Workspace = SegmentWorkspace;

    fn dim(&self) -> usize {
        self.family.unknowns
    }

    fn workspace(&self) -> SegmentWorkspace {
        let n = self.family.system.nvars();
        SegmentWorkspace {
            program: self.family.program.workspace(),
            point: vec![C64::from(0.0); n],
            values: vec![C64::from(0.0); self.family.unknowns],
            jacobian: vec![C64::from(0.0); self.family.unknowns * n],
            magnitude_program: self.family.magnitudes.workspace(),
        }
    }

    fn inverse_condition(&self, z: &DVector<C64>, ws: &mut SegmentWorkspace) -> f64 {
        let n = self.family.unknowns;
        let total = self.family.system.nvars();
        let mut hz = DMatrix::zeros(n, n);
        let (mut h, mut ht) = (DVector::zeros(n), DVector::zeros(n));
        self.evaluate(z, C64::from(0.0), ws, &mut h, &mut hz, &mut ht);
        let unit = ws.point.iter().map(|c| c.norm()).fold(1.0, f64::max);
        let moduli = super::floored_moduli(&ws.point, unit);
        let mut values = vec![C64::from(0.0); n];
        let mut jacobian = vec![C64::from(0.0); n * total];
        self.family.magnitudes.evaluate_with_jacobian(
            &moduli,
            &mut values,
            &mut jacobian,
            &mut ws.magnitude_program,
        );
        let scales: Vec<f64> = (0..n)
            .map(|i| {
                jacobian[i * total..i * total + n]
                    .iter()
                    .map(nalgebra::Complex::norm_sqr)
                    .sum::<f64>()
                    .sqrt()
            })
            .collect();
        super::scaled_inverse_condition(hz, &scales)
    }

    fn evaluate(
        &self,
        z: &DVector<C64>,
        t: C64,
        ws: &mut SegmentWorkspace,
        h: &mut DVector<C64>,
        hz: &mut DMatrix<C64>,
        ht: &mut DVector<C64>,
    ) {
        let n = self.family.unknowns;
        let total = self.family.system.nvars();
        for (slot, x) in ws.point.iter_mut().zip(z.iter()) {
            *slot = *x;
        }
        for (k, (a, b)) in self.from.iter().zip(self.to).enumerate() {
            ws.point[n + k] = t * a + (C64::from(1.0) - t) * b;
        }
        self.family.program.evaluate_with_jacobian(
            &ws.point,
            &mut ws.values,
            &mut ws.jacobian,
            &mut ws.program,
        );
        for i in 0..n {
            h[i] = ws.values[i];
            for j in 0..n {
                hz[(i, j)] = ws.jacobian[i * total + j];
            }
            ht[i] = (0..self.from.len())
                .map(|k| ws.jacobian[i * total + n + k] * (self.from[k] - self.to[k]))
                .sum();
        }
    }

    fn infinity_measure(&self, z: &DVector<C64>) -> Option<f64> {
        self.may_diverge.then(|| 1.0 / (1.0 + z.norm()))
    }
}

/// Follows each solution `x` of `F(x; from) = 0` to a solution of `F(x; to) = 0` along the
/// straight segment of parameters, in parallel; each result in the order given.
///
/// # Errors
/// [`ParameterError::ParameterCount`] for parameter points of the wrong length. A path that
/// fails (a singular system on the segment, a diverging solution) is an `Err` in its slot.
pub fn track_parameters(
    family: &ParametrizedSystem,
    from: &[C64],
    to: &[C64],
    solutions: &[Vec<C64>],
    settings: TrackerSettings,
) -> Result<Vec<Result<Vec<C64>, PathFailure>>, ParameterError> {
    family.check(from)?;
    family.check(to)?;
    let segment = Segment {
        family,
        from,
        to,
        may_diverge: false,
    };
    Ok(solutions
        .par_iter()
        .map(|x| follow(&segment, settings, x))
        .collect())
}

/// The limit of a path followed by [`track_parameters_to_end`].
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum FamilyEnd {
    /// A regular solution of the end member (refined).
    Regular(Vec<C64>),
    /// A singular solution (winding number above 1 or a rank-deficient Jacobian), to the
    /// endgame's accuracy.
    Singular(Vec<C64>),
    /// The path diverges: the end member has no solution there.
    Infinite,
}

/// Follows each solution of `F(x; from) = 0` along the straight segment of parameters to the
/// limit at `to`, with the endgame: for segments whose end member is special (fewer or
/// singular solutions), as in a regeneration homotopy. Each result in the order given.
///
/// # Errors
/// [`ParameterError::ParameterCount`] for parameter points of the wrong length; a path that
/// fails is an `Err` in its slot.
pub(crate) fn track_parameters_to_end(
    family: &ParametrizedSystem,
    from: &[C64],
    to: &[C64],
    solutions: &[Vec<C64>],
    settings: TrackerSettings,
) -> Result<Vec<Result<FamilyEnd, PathFailure>>, ParameterError> {
    family.check(from)?;
    family.check(to)?;
    let segment = Segment {
        family,
        from,
        to,
        may_diverge: true,
    };
    Ok(solutions
        .par_iter()
        .map(|x| {
            let mut tracker = Tracker::new(&segment, settings);
            let mut z = DVector::from_column_slice(x);
            let end = tracker.track_to_end(&mut z)?;
            if end.diverges {
                return Ok(FamilyEnd::Infinite);
            }
            let mut point = end.z;
            if !point.iter().all(|c| c.re.is_finite() && c.im.is_finite()) {
                return Err(PathFailure::NotFinite);
            }
            if end.winding == 1 && tracker.inverse_condition(&point) > super::SINGULAR_TOLERANCE {
                tracker.refine(&mut point, C64::from(0.0), 1e-14);
                Ok(FamilyEnd::Regular(point.iter().copied().collect()))
            } else if end.converged {
                Ok(FamilyEnd::Singular(point.iter().copied().collect()))
            } else {
                Err(PathFailure::Endgame)
            }
        })
        .collect())
}

fn follow(
    segment: &Segment<'_>,
    settings: TrackerSettings,
    x: &[C64],
) -> Result<Vec<C64>, PathFailure> {
    Tracker::new(segment, settings).track_refined(DVector::from_column_slice(x))
}

/// When to stop the monodromy loops.
#[derive(Debug, Clone, PartialEq)]
pub struct MonodromySettings {
    /// The seed of the random loop parameters.
    pub seed: u64,
    /// Stop when this many solutions are known (a known root count), if given.
    pub target: Option<usize>,
    /// Stop after this many consecutive loops that found nothing new.
    pub stall_loops: usize,
    /// Stop after this many loops in all.
    pub max_loops: usize,
    /// Step control of the paths.
    pub tracker: TrackerSettings,
}

impl Default for MonodromySettings {
    fn default() -> Self {
        Self {
            seed: 1,
            target: None,
            stall_loops: 5,
            max_loops: 100,
            tracker: TrackerSettings::default(),
        }
    }
}

/// The solutions monodromy found at the base parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct MonodromyReport {
    /// The distinct solutions at the base parameters.
    pub solutions: Vec<Vec<C64>>,
    /// The loops made.
    pub loops: usize,
    /// Paths tracked.
    pub paths: usize,
}

/// Fills the solutions of `F(x; base) = 0` from one solution `start` by monodromy: each loop
/// moves the parameters `base → p1 → p2 → base` through two random complex points and follows
/// every known solution; endpoints not yet known are new solutions. For generic `base`, the
/// loops' monodromy group acts transitively on the solutions of an irreducible family, so all
/// are found with probability one as loops accumulate; [`MonodromySettings`] says when to stop
/// (without a known count, the stall criterion is a heuristic).
///
/// # Errors
/// [`ParameterError`] if `base` has the wrong length or `start` does not solve the system at
/// `base` (relative residual above 1e-8).
pub fn monodromy_solve(
    family: &ParametrizedSystem,
    base: &[C64],
    start: &[C64],
    settings: &MonodromySettings,
) -> Result<MonodromyReport, ParameterError> {
    family.check(base)?;
    let residual = family.residual(start, base);
    let size = 1.0
        + start
            .iter()
            .chain(base)
            .map(|c| c.norm())
            .fold(0.0, f64::max);
    if residual > 1e-8 * size * size {
        return Err(ParameterError::NotASolution(residual));
    }
    let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
    let scale = base.iter().map(|c| c.norm()).fold(1.0, f64::max);
    let mut random_point = || -> Vec<C64> {
        (0..base.len())
            .map(|_| {
                let re: f64 = StandardNormal.sample(&mut rng);
                let im: f64 = StandardNormal.sample(&mut rng);
                C64::new(re, im) * scale
            })
            .collect()
    };
    let mut known = vec![start.to_vec()];
    let (mut loops, mut paths, mut stalled) = (0, 0, 0);
    while loops < settings.max_loops
        && stalled < settings.stall_loops
        && settings.target.is_none_or(|t| known.len() < t)
    {
        loops += 1;
        let (p1, p2) = (random_point(), random_point());
        paths += known.len();
        let ends = known.par_iter().map(|x| {
            let legs = [
                (base, p1.as_slice()),
                (p1.as_slice(), p2.as_slice()),
                (p2.as_slice(), base),
            ];
            legs.iter().try_fold(x.clone(), |x, (a, b)| {
                follow(
                    &Segment {
                        family,
                        from: a,
                        to: b,
                        may_diverge: false,
                    },
                    settings.tracker,
                    &x,
                )
            })
        });
        let ends: Vec<_> = ends.collect();
        let before = known.len();
        for e in ends.into_iter().flatten() {
            if family.residual(&e, base) <= 1e-8 * size * size
                && known.iter().all(|k| super::relative_distance(k, &e) > 1e-6)
            {
                known.push(e);
            }
        }
        stalled = if known.len() > before { 0 } else { stalled + 1 };
    }
    Ok(MonodromyReport {
        solutions: known,
        loops,
        paths,
    })
}
