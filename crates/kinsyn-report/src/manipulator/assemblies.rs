//! `kinsyn analyze FILE --inputs … --all-assemblies`: every assembly of a manipulator at given
//! inputs, from its constraint polynomials in Study parameters solved by homotopy continuation
//! (through their square randomisation when the manipulator is over-constrained).

use super::{Loaded, clean, input_texts, inputs_or_reference, leg_warnings, load_with_body};
use crate::Error;
use crate::solve::{PathOption, solve_with_bar};
use itertools::Itertools;
use kinsyn::geometry::Chart;
use kinsyn::homotopy::{
    SolveReport, SolveSettings, StartSystem, fewest_paths_start, satisfying, square_randomisation,
};
use kinsyn::manipulator::{
    BodyBlock, InputValues, LegConstraint, Manipulator, PositionRequest, PositionSystemError,
};
use kinsyn::mechanism::rotation_log;
use kinsyn::poly::System;
use kinsyn::spatial::Displacement;
use serde::Serialize;
use std::path::Path;

/// One real assembly: the frame of every moving body, the largest leg residual, and whether it
/// is certified and the one continued from the reference.
pub struct Assembly {
    /// The end-effector's frame (of a block: the body's frame relative to its parent's).
    pub pose: Displacement,
    /// Every moving body's frame, in the description's order (ground frame); of a block, its
    /// body's relative frame alone.
    pub frames: Vec<Displacement>,
    /// The largest residual of the legs' constraints (length unit).
    pub residual: f64,
    /// Whether the solution is certified (Krawczyk): of a combination, every block's.
    pub certified: bool,
    /// Whether it is the assembly reached by continuation from the reference configuration.
    pub current: bool,
    /// Of a block: the solution (the block's unknowns) it is read from; empty for a
    /// combination.
    pub point: Vec<f64>,
}

/// The pose as `--pose` takes it: `x,y,z,rx,ry,rz`, lengths in the file's unit and the rotation
/// vector in its angle unit, each number in full (the shortest text that reads back to the same
/// double): a platform of fewer than six dof meets its constraints only at the exact pose, and
/// six rounded decimals leave it off them by more than the assembly tolerance.
#[must_use]
pub fn pose_text(m: &Manipulator, g: &Displacement) -> String {
    let t = g.translation.vector;
    let r = rotation_log(&g.rotation).map(|a| m.units().angle.from_radians(a));
    [t.x, t.y, t.z, r.x, r.y, r.z]
        .iter()
        .map(|v| format!("{}", clean(*v)))
        .collect::<Vec<_>>()
        .join(",")
}

/// `kinsyn analyze FILE [--inputs …] --all-assemblies`: the manipulator of the file at `path`
/// (its end-effector `body` when given), every assembly at the inputs of `inputs_text` (the
/// others at their reference values) solved with `seed`, and the leg warnings.
///
/// # Errors
/// [`Error::Input`] for a file that is not a description, inputs that do not read, a system past the path limit, or a mechanism whose assemblies cannot be posed as a system.
pub fn all_assemblies(
    path: &Path,
    inputs_text: Option<&str>,
    body: Option<&str>,
    seed: u64,
) -> Result<Loaded<AllAssemblies>, Error> {
    let m = load_with_body(path, body, None, None)?;
    let all = all_assemblies_of(&m, inputs_text, seed)?;
    let warnings = leg_warnings(&m);
    Ok(Loaded {
        manipulator: m,
        result: all,
        warnings,
    })
}

/// The most real assemblies of a mechanism of several bodies listed (combinations of one real
/// assembly per block of its body tree); the count is reported in full.
pub const MAX_COMBINATIONS: usize = 4096;

/// Every assembly of a manipulator at given inputs: one solve per block of its body tree (one
/// block for a one-platform manipulator), and the real assemblies of the mechanism.
pub struct AllAssemblies {
    /// The inputs, every one, by actuator index and value (radians or length unit; as text
    /// by [`input_texts`]).
    pub inputs: Vec<(usize, f64)>,
    /// The seed of the charts and of the solves.
    pub seed: u64,
    /// Each block's solve, parents first.
    pub blocks: Vec<BlockAssemblies>,
    /// The real assemblies of the mechanism: combinations of one real assembly per block (at
    /// most [`MAX_COMBINATIONS`]).
    pub assemblies: Vec<Assembly>,
    /// How many real combinations there are (the product of the blocks' real counts).
    pub combinations: u128,
}

/// The solve of one block of the body tree: a moving body's frame relative to its parent's.
pub struct BlockAssemblies {
    /// The body's name (the block's root).
    pub body: String,
    /// The names of the block's bodies: the root, then the members joined to it.
    pub bodies: Vec<String>,
    /// Its parent's name (the ground's for a body the ground holds).
    pub parent: String,
    /// The variables, equations and degrees of its position system.
    pub system: kinsyn::poly::System,
    /// The system solved: [`Self::system`] itself when it is square; for an over-constrained
    /// block (more equations than unknowns) its square randomisation
    /// ([`kinsyn::homotopy::square_randomisation`]).
    pub solved: kinsyn::poly::System,
    /// The endpoints that are no assembly, not in [`Self::report`]'s solutions: those of the
    /// square randomisation that the original equations refuse (0 for a square system), and
    /// the regular ones that put a member body on the null cone.
    pub spurious: usize,
    /// What each of its legs contributes to the position system.
    pub kinds: Vec<&'static str>,
    /// The solve.
    pub report: SolveReport,
    /// Its real assemblies (the body's frame relative to its parent's).
    pub real: Vec<Assembly>,
    /// How many singular endpoints lie on the null cone.
    pub null_cone: usize,
}

/// Every assembly of `m` at the inputs of `inputs_text` (`--inputs`; the inputs not named at
/// their reference values), by homotopy continuation on the constraint polynomials in the
/// Study parameters of each moving body relative to its parent in the body tree
/// ([`Manipulator::body_blocks`]; random linear charts and the solves seeded by `seed`). A
/// progress bar over the paths is drawn on stderr when it is a terminal.
///
/// # Errors
///
/// [`Error::Input`]: malformed input values, a manipulator without a position system, or
/// a system the solver refuses.
pub fn all_assemblies_of(
    m: &Manipulator,
    inputs_text: Option<&str>,
    seed: u64,
) -> Result<AllAssemblies, Error> {
    let inputs = inputs_or_reference(m, inputs_text)?;
    let chart = Chart::random_linear(seed);
    let refuse = |e: &dyn std::fmt::Display| Error::Input(format!("--all-assemblies: {e}"));
    let blocks = m
        .body_blocks(&InputValues::Given(&inputs), &chart)
        .map_err(|e| refuse(&e))?;
    // The configuration Newton continuation reaches from the reference, to mark its assembly.
    let request = PositionRequest {
        inputs: inputs.clone(),
        ..PositionRequest::default()
    };
    let current: Option<Vec<Displacement>> =
        m.solve_position(&m.reference(), &request).ok().map(|p| {
            (0..m.bodies().len())
                .map(|k| m.body_frame(k, &p.q))
                .collect()
        });
    let mut solved = Vec::with_capacity(blocks.len());
    for b in &blocks {
        // The reference's frame of the body relative to its parent.
        let reference = current.as_ref().map(|f| {
            let parent = b.parent.map_or_else(kinsyn::spatial::identity, |p| f[p]);
            parent.inverse() * f[b.body]
        });
        solved.push(solve_block(m, b, seed, reference.as_ref())?);
    }
    let combinations = solved
        .iter()
        .map(|b| b.real.len() as u128)
        .product::<u128>();
    let assemblies = combine(m, &blocks, &solved);
    Ok(AllAssemblies {
        inputs,
        seed,
        blocks: solved,
        assemblies,
        combinations,
    })
}

/// The solve of one block: its square randomisation when over-constrained, the endpoints the
/// original equations refuse removed, its real assemblies (`reference`: the body's relative
/// frame reached by continuation from the reference configuration, to mark its assembly).
fn solve_block(
    m: &Manipulator,
    block: &BodyBlock,
    seed: u64,
    reference: Option<&Displacement>,
) -> Result<BlockAssemblies, Error> {
    let ps = &block.system;
    check_isolated(m, block)?;
    let square = square_randomisation(ps.system(), seed)
        .map_err(|e| Error::Input(format!("--all-assemblies: {e}")))?;
    // The start that tracks the fewest paths: the configurable 4-RRR's 5 760 total-degree
    // paths are 512 multi-homogeneous ones.
    let (solved, start) = fewest_paths_start(&square, &ps.variable_groupings(), seed);
    let settings = SolveSettings {
        seed,
        start,
        ..SolveSettings::default()
    };
    // One run: its report is the only one.
    let mut report = solve_with_bar(
        "--all-assemblies",
        &solved,
        &settings,
        1,
        PathOption::Default,
    )?
    .runs
    .swap_remove(0);
    // Of the randomisation's endpoints, only those that satisfy every original equation.
    let mut spurious = 0;
    if solved.len() < ps.system().len() {
        let keep = satisfying(ps.system(), &report);
        spurious = keep.iter().filter(|ok| !**ok).count();
        let mut keep = keep.into_iter();
        report.solutions.retain(|_| keep.next().unwrap_or(false));
    }
    // Regular endpoints with a member body on the null cone (a joint's tan(θ/2) = ±i): they
    // solve the equations without being an assembly.
    if ps.has_members() {
        let before = report.solutions.len();
        report
            .solutions
            .retain(|s| !(s.regular && ps.on_null_cone(&s.x)));
        spurious += before - report.solutions.len();
    }
    let real: Vec<Assembly> = report
        .solutions
        .iter()
        .filter(|s| s.regular && s.real)
        .filter_map(|s| {
            let x: Vec<f64> = s.x.iter().map(|c| c.re).collect();
            let pose = ps.displacement(&x).ok()?;
            let residual = ps
                .residuals_at(&x)?
                .iter()
                .map(|r| {
                    r.distance
                        .abs()
                        .max(r.plane.map_or(0.0, f64::abs))
                        .max(r.angle.map_or(0.0, f64::abs))
                })
                .fold(0.0, f64::max);
            let current = reference.is_some_and(|c| {
                (c.to_homogeneous() - pose.to_homogeneous()).amax()
                    < 1e-6 * (1.0 + c.translation.vector.norm())
            });
            let mut frames = vec![pose];
            frames.extend(
                ps.member_frames(&x)
                    .ok()?
                    .into_iter()
                    .map(|(_, g)| pose * g),
            );
            Some(Assembly {
                pose,
                frames,
                residual,
                certified: s.is_certified(),
                current,
                point: x,
            })
        })
        .collect();
    let null_cone = null_cone_endpoints(ps, &report);
    let name = |k: Option<usize>| {
        k.map_or_else(
            || m.ground_name().to_string(),
            |k| m.bodies()[k].name.clone(),
        )
    };
    Ok(BlockAssemblies {
        body: name(Some(block.body)),
        bodies: std::iter::once(block.body)
            .chain(block.members.iter().copied())
            .map(|k| name(Some(k)))
            .collect(),
        parent: name(block.parent),
        system: ps.system().clone(),
        solved,
        spurious,
        kinds: ps.legs().iter().map(|l| l.kind.describe()).collect(),
        report,
        real,
        null_cone,
    })
}

/// Refuses a block whose legs leave its bodies degrees of freedom at the inputs (fewer
/// equations than unknowns): it has no isolated assemblies, and the message says so.
fn check_isolated(m: &Manipulator, block: &BodyBlock) -> Result<(), Error> {
    let ps = &block.system;
    let constraints: usize = ps.legs().iter().map(LegConstraint::equations).sum();
    if block.members.is_empty() && constraints < 6 {
        let e = PositionSystemError::Underdetermined {
            constraints,
            missing: Vec::new(),
        };
        return Err(Error::Input(format!("--all-assemblies: {e}")));
    }
    let (equations, unknowns) = (ps.system().len(), ps.system().nvars());
    if equations < unknowns {
        return Err(Error::Input(format!(
            "--all-assemblies: the block of {} has {equations} equations in {unknowns} unknowns: at these inputs the mechanism keeps at least {} dof, a self-motion rather than isolated assemblies; `kinsyn components FILE --inputs …` decomposes it",
            m.bodies()[block.body].name,
            unknowns - equations
        )));
    }
    Ok(())
}

/// The singular endpoints where `x0² + x1² + x2² + x3² = 0`: the constraints were multiplied
/// by this `Δ` (or vanish with it), so the null cone solves them without being a displacement.
fn null_cone_endpoints(ps: &kinsyn::manipulator::PositionSystem, report: &SolveReport) -> usize {
    report
        .solutions
        .iter()
        .filter(|s| !s.regular && ps.on_null_cone(&s.x))
        .count()
}

/// The real assemblies of the mechanism: each combination of one real assembly per block (at
/// most [`MAX_COMBINATIONS`]), every body's frame composed along the body tree.
fn combine(m: &Manipulator, blocks: &[BodyBlock], solved: &[BlockAssemblies]) -> Vec<Assembly> {
    solved
        .iter()
        .map(|b| b.real.iter())
        .multi_cartesian_product()
        .take(MAX_COMBINATIONS)
        .filter_map(|chosen| {
            let points: Vec<&[f64]> = chosen.iter().map(|a| a.point.as_slice()).collect();
            let frames = m.body_frames(blocks, &points).ok()?;
            Some(Assembly {
                pose: frames[m.end_effector()],
                residual: chosen.iter().map(|a| a.residual).fold(0.0, f64::max),
                certified: chosen.iter().all(|a| a.certified),
                current: chosen.iter().all(|a| a.current),
                frames,
                point: Vec::new(),
            })
        })
        .collect()
}

impl AllAssemblies {
    /// The report of `kinsyn analyze --all-assemblies --json` for `m`, with the leg `warnings`.
    #[must_use]
    pub fn report(&self, m: &Manipulator, warnings: &[String]) -> AssembliesReport {
        let blocks: Vec<BlockReport> = self.blocks.iter().map(|b| b.block_report(m)).collect();
        let sum = |f: &dyn Fn(&BlockReport) -> usize| blocks.iter().map(f).sum::<usize>();
        let product = |f: &dyn Fn(&BlockReport) -> usize| {
            blocks
                .iter()
                .fold(1_usize, |acc, b| acc.saturating_mul(f(b)))
        };
        let one = blocks.len() == 1;
        let mut warnings = warnings.to_vec();
        if self.combinations > self.assemblies.len() as u128 {
            warnings.push(format!(
                "{} real assemblies (combinations of the blocks' real assemblies): the first {} listed",
                self.combinations,
                self.assemblies.len()
            ));
        }
        let names: Vec<String> = m.bodies().iter().map(|b| b.name.clone()).collect();
        AssembliesReport {
            manipulator: m.name().to_string(),
            inputs: input_texts(m, &self.inputs),
            formulation: if one {
                blocks[0].formulation.clone()
            } else {
                Formulation::of_blocks(&self.blocks, &blocks)
            },
            summary: if one {
                self.blocks[0].report.summary()
            } else {
                format!(
                    "{} blocks, one per moving body: {} paths in all; the mechanism's assemblies are the combinations of one per block",
                    blocks.len(),
                    sum(&|b| b.counts.paths)
                )
            },
            counts: AssemblyCounts {
                paths: sum(&|b| b.counts.paths),
                nonsingular: product(&|b| b.counts.nonsingular),
                real: product(&|b| b.counts.real),
                singular: sum(&|b| b.counts.singular),
                singular_on_null_cone: sum(&|b| b.counts.singular_on_null_cone),
                at_infinity: sum(&|b| b.counts.at_infinity),
                spurious: sum(&|b| b.counts.spurious),
                certified: product(&|b| b.counts.certified),
                certified_real: product(&|b| b.counts.certified_real),
                seconds: blocks.iter().map(|b| b.counts.seconds).sum(),
            },
            seed: self.seed,
            real_assemblies: self
                .assemblies
                .iter()
                .map(|a| real_assembly(m, a, &names))
                .collect(),
            complex_assemblies: if one {
                blocks[0].complex_assemblies.clone()
            } else {
                Vec::new()
            },
            blocks: if one { Vec::new() } else { blocks },
            warnings,
        }
    }
}

impl BlockAssemblies {
    /// This block's part of the report.
    fn block_report(&self, m: &Manipulator) -> BlockReport {
        let (report, system, solved) = (&self.report, &self.system, &self.solved);
        BlockReport {
            body: self.body.clone(),
            parent: self.parent.clone(),
            formulation: Formulation {
                variables: system.variables().to_vec(),
                equations: system.len(),
                degrees: system.degrees(),
                bezout_number: solved.bezout_number().to_string(),
                randomised: solved.len() < system.len(),
                legs: self.kinds.clone(),
                start: report.start.name().to_string(),
                groups: start_groups(solved, report.start),
            },
            counts: AssemblyCounts {
                paths: report.paths(),
                nonsingular: report.nonsingular(),
                real: report.real(),
                singular: report.singular(),
                singular_on_null_cone: self.null_cone,
                at_infinity: report.at_infinity(),
                spurious: self.spurious,
                certified: report.certified(),
                certified_real: report.certified_real(),
                seconds: report.seconds,
            },
            real_assemblies: self
                .real
                .iter()
                .map(|a| real_assembly(m, a, &self.bodies))
                .collect(),
            complex_assemblies: report
                .solutions
                .iter()
                .filter(|s| s.regular && !s.real)
                .map(|s| s.x.iter().map(|c| [c.re, c.im]).collect())
                .collect(),
        }
    }
}

/// One real assembly as reported: the end-effector's pose, every body's (`names`, in the
/// order of [`Assembly::frames`]).
fn real_assembly(m: &Manipulator, a: &Assembly, names: &[String]) -> RealAssembly {
    let t = a.pose.translation.vector;
    let r = rotation_log(&a.pose.rotation);
    RealAssembly {
        pose: pose_text(m, &a.pose),
        position: [t.x, t.y, t.z],
        rotation_vector_rad: [r.x, r.y, r.z],
        bodies: names
            .iter()
            .zip(&a.frames)
            .map(|(name, g)| BodyPose {
                body: name.clone(),
                pose: pose_text(m, g),
            })
            .collect(),
        largest_leg_residual: a.residual,
        certified: a.certified,
        continued_from_reference: a.current,
    }
}

impl Formulation {
    /// The formulation of a mechanism of several blocks: their variables (each named after
    /// its body), equations and degrees side by side, the paths tracked in all (the sum of
    /// the blocks' Bézout numbers: each block is solved on its own), and every leg's kind.
    fn of_blocks(blocks: &[BlockAssemblies], reports: &[BlockReport]) -> Self {
        Self {
            variables: blocks
                .iter()
                .flat_map(|b| {
                    b.system
                        .variables()
                        .iter()
                        .map(move |v| format!("{}.{v}", b.body))
                })
                .collect(),
            equations: blocks.iter().map(|b| b.system.len()).sum(),
            degrees: blocks.iter().flat_map(|b| b.system.degrees()).collect(),
            bezout_number: blocks
                .iter()
                .map(|b| b.solved.bezout_number())
                .sum::<u128>()
                .to_string(),
            randomised: reports.iter().any(|r| r.formulation.randomised),
            legs: blocks.iter().flat_map(|b| b.kinds.clone()).collect(),
            start: if reports
                .iter()
                .all(|r| r.formulation.start == "total-degree")
            {
                "total-degree".to_string()
            } else {
                "per block".to_string()
            },
            groups: Vec::new(),
        }
    }
}

/// The report of `kinsyn analyze --all-assemblies --json` (and of Python's
/// `Manipulator.all_assemblies`): the position system in the Study parameters of the platform,
/// its solve by homotopy continuation, and the assemblies found. Lengths are in the
/// description's length unit. For a description of several moving bodies, one system per body
/// of its body tree (the body relative to its parent, [`BlockReport`]): the counts of
/// assemblies (`nonsingular`, `real`, `certified`, `certified_real`) are then the products of
/// the blocks' (the mechanism's assemblies are the combinations of one per block), the counts
/// of endpoints and paths their sums.
///
/// Printed through [`crate::sorted_value`]: its keys come in alphabetical order, as they did
/// when the report was built with `serde_json::json!`, not in the order of these fields.
#[derive(Debug, Clone, Serialize)]
pub struct AssembliesReport {
    /// The manipulator's name (the description's `name`).
    pub manipulator: String,
    /// Every input's value, `LABEL = value` (angles in the description's angle unit, rounded
    /// to 1e-9): those of `--inputs`, the others at their reference values (0).
    pub inputs: Vec<String>,
    /// The position system solved (of several blocks: their systems side by side).
    pub formulation: Formulation,
    /// The solve's counts in words.
    pub summary: String,
    /// The paths, endpoints and assemblies counted, at the top level of the report: of several
    /// blocks, the assemblies the products of the blocks' and the paths and endpoints their
    /// sums.
    #[serde(flatten)]
    pub counts: AssemblyCounts,
    /// The seed of the random chart and of the solve.
    pub seed: u64,
    /// The real assemblies.
    pub real_assemblies: Vec<RealAssembly>,
    /// The complex (non-real) assemblies: each the position system's variables (the Study
    /// parameters in the chart) as `[re, im]` pairs; of several blocks, in each block.
    pub complex_assemblies: Vec<Vec<[f64; 2]>>,
    /// Of several moving bodies: each block's system, solve and assemblies, parents first
    /// (empty for one platform).
    pub blocks: Vec<BlockReport>,
    /// The leg warnings of the description (docs/mechanism-format.md, "Leg checks").
    pub warnings: Vec<String>,
}

/// One block of [`AssembliesReport::blocks`]: a moving body's frame relative to its parent's,
/// its position system and solve, and its real and complex assemblies.
#[derive(Debug, Clone, Serialize)]
pub struct BlockReport {
    /// The body's name.
    pub body: String,
    /// Its parent's name (the ground's for a body the ground holds).
    pub parent: String,
    /// Its position system.
    pub formulation: Formulation,
    /// Its paths, endpoints and assemblies, at the top level of the entry.
    #[serde(flatten)]
    pub counts: AssemblyCounts,
    /// Its real assemblies: the body's frame relative to its parent's.
    pub real_assemblies: Vec<RealAssembly>,
    /// Its complex assemblies, as the variables' `[re, im]` pairs.
    pub complex_assemblies: Vec<Vec<[f64; 2]>>,
}

/// The counts of an `--all-assemblies` solve ([`AssembliesReport`], [`BlockReport`]).
#[derive(Debug, Clone, Serialize)]
pub struct AssemblyCounts {
    /// The paths tracked.
    pub paths: usize,
    /// The non-singular endpoints: the isolated assemblies, real and complex.
    pub nonsingular: usize,
    /// Of those, the real ones.
    pub real: usize,
    /// The singular endpoints.
    pub singular: usize,
    /// Of those, the ones on the null cone `x0² + x1² + x2² + x3² = 0` (of the root or of a
    /// body merged into it), which solve the constraints without being a displacement.
    pub singular_on_null_cone: usize,
    /// The paths that went to infinity.
    pub at_infinity: usize,
    /// The endpoints that are no assembly, counted nowhere else: those of the square
    /// randomisation of an over-determined system that the original equations refuse (0 for
    /// a square system), and the regular ones that put a merged body on the null cone.
    pub spurious: usize,
    /// The non-singular endpoints certified (each proved, by the Krawczyk operator in interval
    /// arithmetic, to approximate exactly one root).
    pub certified: usize,
    /// Of those, the ones certified real.
    pub certified_real: usize,
    /// The solve's wall-clock time (seconds).
    pub seconds: f64,
}

/// One body's frame in a real assembly.
#[derive(Debug, Clone, Serialize)]
pub struct BodyPose {
    /// The body's name.
    pub body: String,
    /// Its frame as `--pose` takes it (`x,y,z,rx,ry,rz`; of a block's assembly, relative to
    /// the parent's frame).
    pub pose: String,
}

/// The position system of `analyze --all-assemblies`: the legs' constraints on the Study
/// parameters `x0…y3` of the platform frame, the Study quadric, and a random linear chart
/// (more equations than unknowns for an over-constrained manipulator).
#[derive(Debug, Clone, Serialize)]
pub struct Formulation {
    /// The unknowns' names.
    pub variables: Vec<String>,
    /// How many equations.
    pub equations: usize,
    /// Each equation's degree.
    pub degrees: Vec<u32>,
    /// The total-degree Bézout number of the system solved (the product of its degrees: of the
    /// square randomisation when [`Self::randomised`]), as decimal text.
    pub bezout_number: String,
    /// Whether the system has more equations than unknowns (an over-constrained manipulator,
    /// e.g. the 4-RUU) and was solved through its square randomisation: the equations of
    /// highest degree, as many as the unknowns, each plus a random real combination of the
    /// others, every endpoint then checked against all the equations.
    pub randomised: bool,
    /// What each leg contributes (`distance`, `R–S: distance and plane`, …), in leg order.
    pub legs: Vec<&'static str>,
    /// The start system, whichever tracks fewer paths: `total-degree`, or `multi-homogeneous`
    /// over [`Self::groups`] (`per block` for several blocks that differ: see `blocks`).
    pub start: String,
    /// The variable groups of a multi-homogeneous or linear-product start (the Study parameters, or `x` and `y`,
    /// and each joint's unknown alone); empty for the total degree.
    pub groups: Vec<Vec<String>>,
}

/// The variable groups of `solved` named, for a multi-homogeneous or linear-product start;
/// empty otherwise.
#[must_use]
pub fn start_groups(solved: &System, start: StartSystem) -> Vec<Vec<String>> {
    match start {
        StartSystem::TotalDegree | StartSystem::Polyhedral | StartSystem::Auto => Vec::new(),
        StartSystem::MultiHomogeneous | StartSystem::LinearProduct => solved
            .groups()
            .iter()
            .map(|g| g.iter().map(|&v| solved.variables()[v].clone()).collect())
            .collect(),
    }
}

/// One real assembly: the platform frame where every leg closes.
#[derive(Debug, Clone, Serialize)]
pub struct RealAssembly {
    /// The pose as `--pose` takes it: `x,y,z,rx,ry,rz` (length unit, the rotation vector in
    /// the description's angle unit), each number in full.
    pub pose: String,
    /// The platform frame's origin in the ground frame (length unit).
    pub position: [f64; 3],
    /// The platform frame's orientation as a rotation vector (radians).
    pub rotation_vector_rad: [f64; 3],
    /// Every moving body's frame (one entry for a one-platform manipulator).
    pub bodies: Vec<BodyPose>,
    /// The largest residual of the legs' constraints there (their distances and planes missed,
    /// length unit).
    pub largest_leg_residual: f64,
    /// Whether the solution is certified (proved by the Krawczyk operator to approximate
    /// exactly one root).
    pub certified: bool,
    /// Whether it is the assembly reached by continuation from the reference configuration.
    pub continued_from_reference: bool,
}
