//! Operation modes of paper 004's 4-RUU from its description file (`mechanisms/4-ruu.json`):
//! `Manipulator::operation_modes` decomposes the constraint equations of the general polynomial
//! layer (U–U legs) at fixed inputs and names, for each real assembly, the operation mode
//! through it with the inputs released — its dof and the platform's motion pattern — and the
//! motion of each self-motion.
//!
//! Expected values: paper 004 §4 (K1 and K2 are 4-dof Schönflies modes, X(z), eqs. 16–17),
//! §5.2 (equal inputs: a 1-dof self-motion in K2, Fig. 9), and the count of 32 isolated
//! solutions at generic inputs — each pose twice as ±(x, y) — which Singular's `vdim` confirms
//! in `tests/suite/ruu_self_motions.rs`. The file's reference crank angles are θ1i = (−90°, 0°, 90°,
//! 0°), so an input `δ_i` is the absolute angle θ1i minus that.

use kinsyn::geometry::Chart;
use kinsyn::homotopy::{DecomposeSettings, SolveSettings, solve_overdetermined};
use kinsyn::manipulator::{
    DecompositionMethod, InputValues, Manipulator, ModeComponent, OperationModeSettings,
    OperationModes,
};
use kinsyn::motion::{Direction, GroupKind, Pattern};
use kinsyn::notation::Axis;
use std::f64::consts::FRAC_PI_2;

fn ruu() -> Manipulator {
    Manipulator::from_json(&std::fs::read_to_string("../../mechanisms/4-ruu.json").unwrap())
        .unwrap()
}

/// The inputs δ for absolute crank angles `theta` (radians).
fn inputs(theta: [f64; 4]) -> Vec<(usize, f64)> {
    let reference = [-FRAC_PI_2, 0.0, FRAC_PI_2, 0.0];
    (0..4).map(|i| (i, theta[i] - reference[i])).collect()
}

fn modes(theta: [f64; 4], seed: u64, method: DecompositionMethod) -> OperationModes {
    let given = inputs(theta);
    ruu()
        .operation_modes(
            &InputValues::Given(&given),
            &OperationModeSettings {
                decompose: DecomposeSettings {
                    seed,
                    ..DecomposeSettings::default()
                },
                method,
                ..OperationModeSettings::default()
            },
        )
        .unwrap()
}

fn is_schoenflies_z(c: &ModeComponent) -> bool {
    c.released.as_ref().is_some_and(|r| {
        r.dof == 4
            && matches!(&r.motion.pattern, Pattern::Group(g) if g.kind == GroupKind::X
                && g.direction.is_some_and(|d| Direction::of(&d) == Direction::Along(Axis::Z)))
    })
}

fn in_k1(c: &ModeComponent) -> bool {
    c.sample[0].norm() < 1e-8 && c.sample[3].norm() < 1e-8
}

fn in_k2(c: &ModeComponent) -> bool {
    c.sample[1].norm() < 1e-8 && c.sample[2].norm() < 1e-8
}

#[test]
fn generic_inputs_give_32_isolated_solutions_each_real_one_in_a_schoenflies_mode() {
    // Absolute angles of tangents (0.3, −0.7, 1.1, 0.45), the generic inputs of the other
    // paper 004 tests: 32 isolated solutions (Singular: vdim 32), 16 in K1 and 16 in K2.
    let theta = [0.3f64, -0.7, 1.1, 0.45].map(|t| 2.0 * t.atan());
    for (seed, method) in [
        (1, DecompositionMethod::Regeneration),
        (2, DecompositionMethod::Regeneration),
        (1, DecompositionMethod::ByDimension),
    ] {
        let m = modes(theta, seed, method);
        let sig = m.decomposition.signature();
        assert_eq!(sig, vec![(0, 1); 32], "seed {seed}, {method:?}");
        let k1 = m.components.iter().filter(|c| in_k1(c)).count();
        let k2 = m.components.iter().filter(|c| in_k2(c)).count();
        assert_eq!((k1, k2), (16, 16), "seed {seed}, {method:?}");
        let real: Vec<&ModeComponent> = m
            .components
            .iter()
            .filter(|c| !c.real_points.is_empty())
            .collect();
        assert!(!real.is_empty());
        for c in real {
            // Paper 004 §4.1.1–4.1.2: both modes are 4-dof Schönflies motions X(z).
            assert!(is_schoenflies_z(c), "{:?}", c.released);
        }
    }
}

/// The same count by a second method on the same equations: at fixed generic inputs the position
/// system is over-determined (eight leg equations, the Study quadric and the normalisation
/// `x0² + x1² + x2² + x3² = 1`, in the eight Study parameters). Randomised to a square system
/// (`solve_overdetermined`: the eight equations of highest degree, each plus a random real
/// combination of the other two; 2⁸ = 256 paths), the endpoints that satisfy all ten equations
/// are the 32 isolated solutions of the decomposition above and of Singular's `vdim`, 16 in K1
/// and 16 in K2, each regular and certified; two seeds.
#[test]
fn randomised_to_a_square_system_generic_inputs_give_the_same_32() {
    let theta = [0.3f64, -0.7, 1.1, 0.45].map(|t| 2.0 * t.atan());
    let given = inputs(theta);
    let ps = ruu()
        .constraint_system(&InputValues::Given(&given), &Chart::Unit)
        .unwrap();
    assert_eq!((ps.system().len(), ps.system().nvars()), (10, 8));
    for seed in [1, 2] {
        let settings = SolveSettings {
            seed,
            ..SolveSettings::default()
        };
        let o = solve_overdetermined(ps.system(), &settings).unwrap();
        assert_eq!(o.report.paths(), 256);
        let found: Vec<_> = o.solutions().collect();
        assert_eq!(found.len(), 32, "seed {seed}: {}", o.report.summary());
        assert!(
            found.iter().all(|s| s.regular && s.is_certified()),
            "seed {seed}"
        );
        let zero = |s: &&kinsyn::homotopy::Solution, a: usize, b: usize| {
            s.x[a].norm() < 1e-8 && s.x[b].norm() < 1e-8
        };
        let k1 = found.iter().filter(|s| zero(s, 0, 3)).count();
        let k2 = found.iter().filter(|s| zero(s, 1, 2)).count();
        assert_eq!((k1, k2), (16, 16), "seed {seed}");
    }
}

#[test]
fn an_upside_down_assembly_is_in_the_first_schoenflies_mode() {
    // A K1 assembly built by hand in tests/suite/ruu_mechanism.rs: cranks at 180°, −atan(3/4), 0°,
    // 90°, the platform turned by π about (1, 1, 0)/√2 at height √2.
    let m = modes(
        [std::f64::consts::PI, -(0.75f64).atan(), 0.0, FRAC_PI_2],
        1,
        DecompositionMethod::Regeneration,
    );
    let k1: Vec<&ModeComponent> = m
        .components
        .iter()
        .filter(|c| c.dimension == 0 && in_k1(c) && !c.real_points.is_empty())
        .collect();
    assert!(!k1.is_empty(), "{:?}", m.decomposition.signature());
    let expected = nalgebra::Vector3::new(0.0, 0.0, 2f64.sqrt());
    assert!(
        k1.iter().any(|c| c
            .real
            .as_ref()
            .is_some_and(|l| (l.pose.translation.vector - expected).norm() < 1e-9)),
        "the hand-built pose is among the real K1 assemblies"
    );
    for c in k1 {
        assert!(is_schoenflies_z(c), "{:?}", c.released);
        let pose = &c.real.as_ref().unwrap().pose;
        // Upside down: the platform's z axis points down (paper 004 §4.1.1, eq. 16).
        assert!((pose.rotation * nalgebra::Vector3::z()).z < -1.0 + 1e-9);
    }
}

#[test]
fn equal_inputs_give_a_one_dof_self_motion_in_the_second_mode() {
    // Paper 004 §5.2, Fig. 9: all actuated angles equal — the platform gains a 1-dof
    // self-motion in K2 (rotating about a vertical axis while its height changes:
    // h² = r² − a² − b² + 2ab cos φ, tests/suite/ruu_singularities.rs), with every input held.
    // Besides it, complex curves counted twice (no real point, found by deflation: before it,
    // their singular witness points were left unresolved): no configuration, no motion.
    for theta in [0.0, 0.3] {
        let m = modes([theta; 4], 1, DecompositionMethod::Regeneration);
        let (positive, doubled): (Vec<&ModeComponent>, Vec<&ModeComponent>) = m
            .components
            .iter()
            .filter(|c| c.dimension > 0)
            .partition(|c| c.multiplicity == 1);
        assert!(
            doubled
                .iter()
                .all(|c| c.multiplicity >= 2 && c.real_points.is_empty()),
            "θ = {theta}: {:?}",
            m.decomposition.signature()
        );
        assert_eq!(
            positive.len(),
            1,
            "θ = {theta}: {:?}",
            m.decomposition.signature()
        );
        let c = positive[0];
        assert_eq!((c.dimension, c.degree), (1, 8));
        assert!(in_k2(c));
        let motion = c.real.as_ref().expect("real points of the self-motion");
        assert_eq!(motion.dof, 1);
        // Not a displacement group: the rotation is coupled to a vertical translation.
        assert_eq!(motion.motion.pattern.dof(), 1);
        assert!(
            !motion.motion.pattern.is_group(),
            "{:?}",
            motion.motion.pattern
        );
        let z = (motion.pose.rotation * nalgebra::Vector3::z()).z;
        assert!((z - 1.0).abs() < 1e-9, "upright in K2");
    }
}
