//! The invariants the fuzz targets check, shared with the stable replay test
//! (`tests/suite/fuzz_corpus.rs`). Each check takes the raw input; it returns quietly when the input is
//! rejected (an error is a fine answer) and panics when an invariant is broken. docs/fuzzing.md
//! says what each one asserts.

// Each fuzz target uses one of these, the replay test all of them.
#![allow(dead_code)]

use kinsyn::lockset::LockSet;
use kinsyn::manipulator::Manipulator;
use kinsyn::mechanism::SampleSettings;
use kinsyn::motion::PatternQuery;
use kinsyn::notation::Chain;
use std::sync::OnceLock;

/// A chain that parses prints a text that parses to the same chain, prints the same text, and
/// has the same primitive word, letters and parallel groups.
pub fn check_notation(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(chain) = text.parse::<Chain>() else {
        return;
    };
    let printed = chain.to_string();
    let again: Chain = printed
        .parse()
        .unwrap_or_else(|e| panic!("{text:?} parses but its text {printed:?} does not: {e}"));
    assert_eq!(
        again.to_string(),
        printed,
        "{text:?}: printing is not stable"
    );
    assert_eq!(
        again, chain,
        "{text:?}: the printed text {printed:?} reads differently"
    );
    assert_eq!(again.primitive_word(), chain.primitive_word(), "{text:?}");
    assert_eq!(again.letters(), chain.letters(), "{text:?}");
    assert_eq!(again.parallel_groups(), chain.parallel_groups(), "{text:?}");
    // The word has one letter per primitive, and a group holds at least two of its positions.
    let word = chain.primitive_word();
    assert_eq!(word.len(), chain.primitives().count(), "{text:?}");
    for group in chain.parallel_groups() {
        assert!(group.len() >= 2, "{text:?}: a group of one: {group:?}");
        for &p in &group {
            assert_eq!(
                word.as_bytes().get(p - 1),
                Some(&b'R'),
                "{text:?}: group position {p} is not a revolute of {word}"
            );
        }
    }
    // Without actuation marks the chain still round-trips.
    let plain = chain.without_actuation();
    assert_eq!(
        plain.to_string().parse::<Chain>().as_ref(),
        Ok(&plain),
        "{text:?}: the unactuated chain {plain} does not read back"
    );
}

/// A pattern query that parses prints a text that parses to the same query.
pub fn check_pattern(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(query) = text.parse::<PatternQuery>() else {
        return;
    };
    let printed = query.to_string();
    let again: PatternQuery = printed
        .parse()
        .unwrap_or_else(|e| panic!("{text:?} parses but its text {printed:?} does not: {e}"));
    assert_eq!(
        again, query,
        "{text:?}: the printed text {printed:?} reads differently"
    );
    assert_eq!(
        again.to_string(),
        printed,
        "{text:?}: printing is not stable"
    );
}

/// The 3-UPS of paper 000 §5.1, built once.
fn three_ups() -> &'static Manipulator {
    static M: OnceLock<Manipulator> = OnceLock::new();
    M.get_or_init(|| {
        Manipulator::from_json(include_str!("../mechanisms/3-ups.json"))
            .expect("mechanisms/3-ups.json is a valid description")
    })
}

/// The 3-RPS (mechanisms/3-rps.json): three dof with a parasitic motion, built once.
fn three_rps() -> &'static Manipulator {
    static M: OnceLock<Manipulator> = OnceLock::new();
    M.get_or_init(|| {
        Manipulator::from_json(include_str!("../mechanisms/3-rps.json"))
            .expect("mechanisms/3-rps.json is a valid description")
    })
}

/// Poses and input values as `analyze --pose` and `--inputs` read them, on the 3-RPS: the
/// input is split at the first `|` into a pose text and an inputs text. What parses and
/// assembles is a configuration whose loops close, whose inputs have the values asked for, and
/// whose platform has the coordinates asked for.
pub fn check_position(data: &[u8]) {
    use kinsyn::manipulator::{PlatformGoal, PositionRequest};
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let (pose, inputs) = text.split_once('|').unwrap_or((text, ""));
    let m = three_rps();
    let mut request = PositionRequest::default();
    if !pose.is_empty() {
        let Ok(goal) = m.parse_pose(pose) else {
            return;
        };
        request.platform = Some(goal);
    }
    if !inputs.is_empty() {
        let Ok(values) = m.parse_inputs(inputs) else {
            return;
        };
        request.inputs = values;
    }
    let Ok(reached) = m.solve_position(&m.reference(), &request) else {
        return;
    };
    let q = &reached.q;
    assert!(q.iter().all(|x| x.is_finite()), "{text:?}: {q:?}");
    let residual = m.mechanism().closure_residual(q).amax();
    assert!(residual < 1e-8, "{text:?}: loops open by {residual:e}");
    // `allow`, not `expect`: this file is also built by the fuzz crate, which does not enable
    // clippy::pedantic, so an expectation would go unfulfilled there.
    #[allow(
        clippy::float_cmp,
        reason = "an input is locked and set along the path, never moved by the solver: the check \
                  is that it ends exactly at the value asked for"
    )]
    for &(a, value) in &request.inputs {
        let joint = m.actuators()[a].joint;
        assert_eq!(q[joint], value, "{text:?}: input {a} not at its value");
    }
    let frame = m.platform_frame(q);
    match &request.platform {
        Some(PlatformGoal::Coordinates(values)) => {
            for &(c, v) in values {
                let got = c.of(&frame);
                // Rotation-vector components are compared as the rotation they give.
                let off = if c.is_angle() {
                    (got - v)
                        .abs()
                        .min((got.abs() + v.abs() - 2.0 * std::f64::consts::PI).abs())
                } else {
                    (got - v).abs() / (1.0 + v.abs())
                };
                assert!(off < 1e-7, "{text:?}: {} is {got}, asked {v}", c.name());
            }
        }
        Some(PlatformGoal::Pose(goal)) => {
            let off = (frame.translation.vector - goal.translation.vector).norm()
                / (1.0 + goal.translation.vector.norm())
                + kinsyn::mechanism::rotation_log(&(frame.rotation.inverse() * goal.rotation))
                    .norm();
            assert!(off < 1e-7, "{text:?}: pose off by {off:e}");
        }
        None => {}
    }
}

/// Lock sets of a chain of 1 to 12 joints (digits up to 9, numbers with commas beyond), and
/// actuator labels of the 3-UPS: an accepted set names joints that exist, and its text reads
/// back to the same set.
pub fn check_locks(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    for n in 1..=12usize {
        let Ok(set) = LockSet::parse_for(text, n) else {
            continue;
        };
        let mask = set.mask();
        assert_eq!(
            mask >> n,
            0,
            "{text:?}: joints beyond {n} in mask {mask:#b}"
        );
        let printed = set.to_string();
        let again = LockSet::parse_for(&printed, n)
            .unwrap_or_else(|e| panic!("{text:?} (n = {n}) reads but {printed:?} does not: {e}"));
        assert_eq!(
            again, set,
            "{text:?} (n = {n}): {printed:?} reads differently"
        );
    }
    let m = three_ups();
    let Ok(locked) = m.parse_locks(text) else {
        return;
    };
    assert!(
        locked.windows(2).all(|w| w[0] < w[1]),
        "{text:?}: {locked:?} not sorted and distinct"
    );
    assert!(
        locked.iter().all(|&a| a < m.actuators().len()),
        "{text:?}: {locked:?} names an input the manipulator does not have"
    );
    let printed = m.lock_text(&locked);
    let again = m
        .parse_locks(&printed)
        .unwrap_or_else(|e| panic!("{text:?} reads but {printed:?} does not: {e}"));
    assert_eq!(again, locked, "{text:?}: {printed:?} reads differently");
}

/// A description that builds: its JSON text reads back to the same description, its leg checks
/// run, and its analysis at the reference configuration (when it assembles) has consistent
/// degrees of freedom.
pub fn check_description(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(d) = kinsyn::manipulator::file::Description::from_json(text) {
        let json = d.to_json();
        let again = kinsyn::manipulator::file::Description::from_json(&json)
            .unwrap_or_else(|e| panic!("a description's own JSON does not read: {e}\n{json}"));
        assert_eq!(
            again, d,
            "a description's own JSON reads differently:\n{json}"
        );
    }
    // Either format in its /2 form (a /1 file converted): its /2 JSON reads back the same.
    if let Ok(d) = kinsyn::manipulator::file::MultibodyDescription::from_json(text) {
        let json = d.to_json();
        let again = kinsyn::manipulator::file::MultibodyDescription::from_json(&json)
            .unwrap_or_else(|e| panic!("a /2 description's own JSON does not read: {e}\n{json}"));
        assert_eq!(
            again, d,
            "a /2 description's own JSON reads differently:\n{json}"
        );
    }
    let Ok(m) = Manipulator::from_json(text) else {
        return;
    };
    assert!(m.end_effector() < m.bodies().len());
    let warnings = m.leg_warnings();
    assert!(warnings.iter().all(|w| w.leg < m.legs().len()));
    let settings = SampleSettings {
        samples: 2,
        ..Default::default()
    };
    let Ok(a) = m.analyse(&m.reference(), &[], &settings) else {
        return;
    };
    // Nothing locked: every input is free and has its column in J_I.
    assert!(a.locked.is_empty());
    assert_eq!(a.jacobians.free.len(), m.actuators().len());
    assert_eq!(a.jacobians.jd.ncols(), 6);
    assert_eq!(a.jacobians.jd.nrows(), a.jacobians.rows.len());
    assert_eq!(a.jacobians.ji.nrows(), a.jacobians.rows.len());
    assert_eq!(a.jacobians.ji.ncols(), a.jacobians.free.len());
    assert_eq!(a.leg_ranks.len(), m.legs().len());
    assert_eq!(a.generic.legs.len(), m.legs().len());
    assert!(a.generic.assemblies >= 1);
    // The platform's dof: six minus the rank of the constraint wrenches, one twist each.
    assert!(a.constraint_rank.rank <= 6);
    assert_eq!(a.platform_dof, 6 - a.constraint_rank.rank);
    let (twists, rank) = m.platform_twists(&a.q, &[]);
    assert_eq!(twists.nrows(), 6);
    assert_eq!(
        twists.ncols(),
        a.platform_dof,
        "platform twists {} but platform dof {}",
        twists.ncols(),
        a.platform_dof
    );
    assert_eq!(rank.rank, a.constraint_rank.rank);
    // Mobility counts the platform's dof plus the legs' internal motions.
    assert!(
        a.mobility >= a.platform_dof,
        "mobility {} below the platform dof {} ({})",
        a.mobility,
        a.platform_dof,
        m.name()
    );
    for (r, leg) in a.leg_ranks.iter().zip(m.legs()) {
        assert!(r.rank <= leg.joints.len().min(6));
    }
}

/// A Bertini input file that reads is a system whose coefficients are finite and whose degrees
/// are within `poly::MAX_DEGREE`; its own Bertini text (`bertini::write`) reads back to the
/// same system; and its compiled evaluation program gives, at a fixed complex point, the values
/// and Jacobian that the polynomials themselves give (`Poly::eval`, `Poly::derivative`), to
/// round-off relative to the size of the terms.
pub fn check_bertini(data: &[u8]) {
    use kinsyn::poly::{C64, MAX_DEGREE, bertini};
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(input) = bertini::parse(text) else {
        return;
    };
    let system = &input.system;
    assert_eq!(input.functions.len(), system.len());
    for p in system.equations() {
        assert_eq!(p.nvars(), system.nvars());
        assert!(
            p.total_degree() <= MAX_DEGREE,
            "{text:?}: degree beyond the limit"
        );
        for (_, c) in p.terms() {
            assert!(c.re.is_finite() && c.im.is_finite(), "{text:?}: {c}");
        }
    }
    let written = bertini::write(system);
    let again = bertini::parse(&written)
        .unwrap_or_else(|e| panic!("{text:?} reads but its own text does not: {e}\n{written}"));
    assert_eq!(
        again.system, *system,
        "{text:?}: its own text reads differently:\n{written}"
    );
    // Values and Jacobian of the program against the polynomials, at a point of modulus < 1
    // (so that powers up to the degree limit stay finite).
    let n = system.nvars();
    let x: Vec<C64> = (0..n)
        .map(|k| C64::new(0.3 + 0.05 * (k % 7) as f64, -0.2 + 0.03 * (k % 5) as f64))
        .collect();
    let size: Vec<C64> = x.iter().map(|c| C64::new(c.norm(), 0.0)).collect();
    let program = system.program();
    let mut ws = program.workspace::<C64>();
    let mut values = vec![C64::new(0.0, 0.0); system.len()];
    let mut jacobian = vec![C64::new(0.0, 0.0); system.len() * n];
    program.evaluate_with_jacobian(&x, &mut values, &mut jacobian, &mut ws);
    let close = |got: C64, want: C64, scale: f64, what: &str| {
        if want.re.is_finite() && want.im.is_finite() && scale.is_finite() {
            assert!(
                (got - want).norm() <= 1e-9 * scale.max(f64::MIN_POSITIVE),
                "{text:?}: {what}: program {got}, polynomial {want} (terms of size {scale})"
            );
        }
    };
    for (i, p) in system.equations().iter().enumerate() {
        close(
            values[i],
            p.eval(&x),
            p.magnitudes().eval(&size).re,
            "value",
        );
        for j in 0..n {
            let d = p.derivative(j);
            close(
                jacobian[i * n + j],
                d.eval(&x),
                d.magnitudes().eval(&size).re,
                "derivative",
            );
        }
    }
}

/// The most unknowns and start paths of the systems the components target decomposes: small
/// systems, so that one execution takes milliseconds (larger ones are refused or skipped).
const COMPONENTS_UNKNOWNS: usize = 3;
const COMPONENTS_PATHS: u128 = 48;

/// A small Bertini system's numerical irreducible decomposition (`kinsyn components`) either
/// is refused before any path is tracked or is a list of components whose dimensions are below
/// the number of unknowns, whose degrees count their witness points, whose witness points lie
/// on the system and on the slice of their dimension, and whose sample points lie on the
/// system; it tracks no more paths than its limit allows.
pub fn check_components(data: &[u8]) {
    use kinsyn::homotopy::{DecomposeSettings, check_system, decompose, decompose_paths};
    use kinsyn::poly::{C64, bertini};
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(input) = bertini::parse(text) else {
        return;
    };
    let system = &input.system;
    if check_system(system).is_err()
        || system.nvars() > COMPONENTS_UNKNOWNS
        || decompose_paths(system) > COMPONENTS_PATHS
    {
        return;
    }
    let settings = DecomposeSettings {
        max_paths: 4096,
        ..DecomposeSettings::default()
    };
    let Ok(d) = decompose(system, &settings) else {
        return;
    };
    assert!(d.estimated_paths <= COMPONENTS_PATHS);
    assert!(
        d.paths as u64 <= settings.max_paths,
        "{text:?}: {} paths tracked, limit {}",
        d.paths,
        settings.max_paths
    );
    let n = system.nvars();
    // On the system: each equation small beside the size of its terms (taken at least 1).
    let on_system = |x: &[C64], what: &str| {
        assert_eq!(x.len(), n, "{text:?}: {what} of {} coordinates", x.len());
        let size: Vec<C64> = x.iter().map(|c| C64::new(c.norm(), 0.0)).collect();
        for (i, p) in system.equations().iter().enumerate() {
            let scale = p.magnitudes().eval(&size).re.max(1.0);
            if !scale.is_finite() {
                continue;
            }
            let r = p.eval(x).norm();
            assert!(
                r <= 1e-6 * scale,
                "{text:?}: {what} {x:?}: equation {i} leaves {r:e} (terms {scale:e})"
            );
        }
    };
    for c in &d.components {
        assert!(
            c.dimension < n,
            "{text:?}: a component of dimension {}",
            c.dimension
        );
        assert_eq!(c.degree, c.witness_points.len(), "{text:?}");
        assert!(c.degree >= 1, "{text:?}: a component of degree 0");
        let slice = &d.slices[c.dimension];
        assert_eq!(slice.len(), c.dimension);
        for w in &c.witness_points {
            on_system(w, "a witness point");
            let size = 1.0 + w.iter().map(|c| c.norm()).fold(0.0, f64::max);
            for h in slice {
                let v: C64 = h[..n].iter().zip(w).map(|(a, x)| a * x).sum::<C64>() + h[n];
                let scale = h.iter().map(|a| a.norm()).fold(0.0, f64::max) * size;
                assert!(
                    v.norm() <= 1e-6 * scale,
                    "{text:?}: a witness point off its slice by {:e}",
                    v.norm()
                );
            }
        }
        on_system(&c.sample_point, "a sample point");
    }
}

/// The most start paths of a position system the assemblies target solves.
const ASSEMBLIES_PATHS: u64 = 64;

/// `analyze --all-assemblies` on a description (either format, read as `/2`): the polynomial
/// position system at the reference inputs, when the legs have one, vanishes at the assembly
/// that Newton continuation reaches from the reference (the polynomial form and the
/// description's geometry are two formulations of one mechanism); the solve either is refused
/// before tracking or gives real regular solutions that are displacements whose own chart
/// representative solves the system again.
pub fn check_assemblies(data: &[u8]) {
    use kinsyn::geometry::Chart;
    use kinsyn::homotopy::{SolveSettings, check_solvable, solve};
    use kinsyn::manipulator::PositionRequest;
    use kinsyn::poly::C64;
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(m) = Manipulator::from_json(text) else {
        return;
    };
    let inputs: Vec<(usize, f64)> = (0..m.actuators().len()).map(|a| (a, 0.0)).collect();
    let seed = 1;
    let Ok(ps) = m.position_system(&inputs, &Chart::random_linear(seed)) else {
        return;
    };
    let system = ps.system();
    // Each equation small beside the size of its terms at the point (taken at least 1).
    let residual = |x: &[f64]| -> f64 {
        let x: Vec<C64> = x.iter().map(|v| C64::new(*v, 0.0)).collect();
        let size: Vec<C64> = x.iter().map(|c| C64::new(c.norm(), 0.0)).collect();
        system
            .equations()
            .iter()
            .map(|p| p.eval(&x).norm() / p.magnitudes().eval(&size).re.max(1.0))
            .fold(0.0, f64::max)
    };
    let request = PositionRequest {
        inputs: inputs.clone(),
        ..PositionRequest::default()
    };
    if let Ok(p) = m.solve_position(&m.reference(), &request) {
        let pose = m.platform_frame(&p.q);
        if let Some(x) = ps.solution_of(&pose) {
            let r = residual(&x);
            assert!(
                r <= 1e-6,
                "{}: the assembly at the reference inputs leaves {r:e} in its position system",
                m.name()
            );
        }
    }
    let settings = SolveSettings {
        seed,
        max_paths: ASSEMBLIES_PATHS,
        ..SolveSettings::default()
    };
    if check_solvable(system, &settings).is_err() {
        return;
    }
    let Ok(report) = solve(system, &settings) else {
        return;
    };
    assert!(report.paths() as u64 <= ASSEMBLIES_PATHS);
    for s in report.solutions.iter().filter(|s| s.regular && s.real) {
        let x: Vec<f64> = s.x.iter().map(|c| c.re).collect();
        let Ok(pose) = ps.displacement(&x) else {
            continue;
        };
        let again = ps
            .solution_of(&pose)
            .unwrap_or_else(|| panic!("{}: a solution's pose misses the chart", m.name()));
        let r = residual(&again);
        assert!(
            r <= 1e-6,
            "{}: a real assembly's own representative leaves {r:e}",
            m.name()
        );
    }
}

/// The committed catalogue and the designs of the default sweep over it, built once.
fn sweep_designs() -> &'static (kinsyn::catalogue::Catalogue, Vec<kinsyn::sweep::Design>) {
    use kinsyn::catalogue::Catalogue;
    use kinsyn::sweep::{SweepSettings, designs};
    static D: OnceLock<(Catalogue, Vec<kinsyn::sweep::Design>)> = OnceLock::new();
    D.get_or_init(|| {
        let catalogue = Catalogue::committed().expect("the committed catalogue reads");
        let list = designs(&catalogue, &SweepSettings::default());
        (catalogue, list)
    })
}

/// The rows of a sweep's checkpoint or `designs.jsonl` as every reader reads them back
/// (`Known::parse_rows`), against the default sweep's designs and against any design over the
/// verified catalogue: accepted rows name each design once, pass the row check again, and
/// their own JSON lines read back to the same rows.
pub fn check_checkpoint(data: &[u8]) {
    use kinsyn::sweep::SweepSettings;
    use kinsyn::sweep::rows::Known;
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let (catalogue, designs) = sweep_designs();
    let legs = SweepSettings::default().legs;
    for known in [Known::sweep(designs, legs), Known::catalogue(catalogue)] {
        let Ok(rows) = known.parse_rows(text) else {
            continue;
        };
        let mut seen = std::collections::HashSet::new();
        let mut lines = String::new();
        for row in &rows {
            assert!(seen.insert(row.design), "design {} twice", row.design);
            assert_eq!(known.check(row), Ok(()), "an accepted row fails its check");
            assert!(row.dof <= 6 && row.inputs == row.legs * row.actuated.len());
            lines.push_str(&serde_json::to_string(row).expect("a row serialises"));
            lines.push('\n');
        }
        let again = known
            .parse_rows(&lines)
            .unwrap_or_else(|e| panic!("accepted rows written again do not read: {e}\n{lines}"));
        assert_eq!(again, rows, "accepted rows read back differently");
    }
}
